//! Every kernel through the binary: `brdf-ref eval` (the mode with a leading kernel column,
//! one process per float type) on each kernel's extreme and random in-domain points prints
//! values that parse back to exactly what a direct call of the crate's function returns.

use crate::direct::{direct, direct_paths};
use crate::{points, run, same};
use brdf_ref::app::{fmt, parse};
use brdf_ref::{Float, KERNELS};
use std::collections::BTreeSet;

/// Extreme rows per kernel and type: enough to reach every extreme of every argument of
/// most kernels, few enough that two processes evaluate all of them in well under a second.
const CAP: usize = 96;
/// Random rows per kernel and type.
const RANDOM: usize = 16;

fn through_the_binary(ty: Float) {
    let mut input = String::new();
    let mut expected: Vec<(&str, Vec<f64>, Vec<f64>)> = Vec::new();
    for k in KERNELS {
        for row in points(k, ty, CAP, RANDOM) {
            let y: Vec<f64> = match ty {
                Float::F32 => {
                    #[allow(clippy::cast_possible_truncation)]
                    let a: Vec<f32> = row.iter().map(|&x| x as f32).collect();
                    direct(k.path, &a)
                        .unwrap_or_else(|| panic!("direct() does not handle {}", k.path))
                        .into_iter()
                        .map(f64::from)
                        .collect()
                }
                Float::F64 => direct(k.path, &row)
                    .unwrap_or_else(|| panic!("direct() does not handle {}", k.path)),
            };
            assert_eq!(
                y.len(),
                k.outputs.len(),
                "{}: direct() returns the table's outputs",
                k.path
            );
            let fields: Vec<String> = row.iter().map(|&x| fmt(x, ty)).collect();
            input.push_str(&format!("{},{}\n", k.path, fields.join(",")));
            expected.push((k.path, row, y));
        }
    }
    let flag = format!("--{}", ty.name());
    let (code, out, err) = run(&["eval", &flag], &input);
    assert_eq!(code, 0, "every in-domain row is accepted; stderr:\n{err}");
    let rows: Vec<&str> = out.lines().filter(|l| !l.starts_with("kernel,")).collect();
    assert_eq!(rows.len(), expected.len(), "one output row per input row");
    for (line, (path, args, y)) in rows.iter().zip(&expected) {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields[0], *path, "rows come back in order");
        let values: Vec<f64> = fields[1..]
            .iter()
            .map(|f| parse(f, ty).unwrap_or_else(|| panic!("`{f}` parses as {}", ty.name())))
            .collect();
        assert_eq!(
            values.len(),
            args.len() + y.len(),
            "{path}: arguments then outputs"
        );
        for (i, (got, want)) in values.iter().zip(args.iter().chain(y)).enumerate() {
            assert!(
                same(*got, *want),
                "{path} ({}) column {}: the binary printed {got}, the direct call gives {want}; row {line}",
                ty.name(),
                i + 2
            );
        }
    }
}

#[test]
fn every_kernel_through_the_binary_equals_a_direct_call_in_f32() {
    through_the_binary(Float::F32);
}

#[test]
fn every_kernel_through_the_binary_equals_a_direct_call_in_f64() {
    through_the_binary(Float::F64);
}

#[test]
fn direct_calls_cover_exactly_the_table() {
    let table: BTreeSet<String> = KERNELS.iter().map(|k| k.path.to_string()).collect();
    let direct: BTreeSet<String> = direct_paths().into_iter().collect();
    let only_table: Vec<_> = table.difference(&direct).collect();
    let only_direct: Vec<_> = direct.difference(&table).collect();
    assert!(
        only_table.is_empty() && only_direct.is_empty(),
        "in the table but not in direct(): {only_table:?}; in direct() but not in the table: {only_direct:?}"
    );
    assert_eq!(
        table.len(),
        KERNELS.len(),
        "every path appears once in the table"
    );
}

#[test]
fn every_kernel_has_distinct_column_names_and_a_summary() {
    for k in KERNELS {
        let mut names = BTreeSet::new();
        for n in k
            .args
            .iter()
            .map(|a| a.name)
            .chain(k.outputs.iter().map(|o| o.name))
        {
            assert!(
                names.insert(n),
                "{}: the column `{n}` appears twice",
                k.path
            );
            assert_ne!(n, "kernel", "{}: `kernel` names the path column", k.path);
        }
        assert!(
            !k.summary.is_empty() && !k.summary.contains('\n'),
            "{}: a one-line summary",
            k.path
        );
        assert!(!k.outputs.is_empty(), "{}: at least one output", k.path);
    }
}

/// The layered rows' 22 material arguments: a dielectric base with every extension off at
/// its glTF default but transmission `t` and volume thickness `thickness`.
fn layered_args(t: f64, thickness: f64) -> Vec<f64> {
    let mut a = vec![0.9, 0.6, 0.3, 0.0, 0.5]; // base colour, metallic, roughness
    a.extend([0.0, 0.0, 0.0, 0.5]); // sheen colour (black: off), roughness
    a.extend([0.0, 0.2, 0.0, 0.0]); // clearcoat (off), roughness, anisotropy strength, rotation
    a.extend([0.0, 400.0, 1.3]); // iridescence factor (off), film thickness, index
    a.push(t);
    a.extend([thickness, 1.0, 1.0, 1.0, 1.0]); // volume thickness, attenuation colour, distance
    a
}

#[test]
fn layered_rows_with_transmission_are_the_crates_value_and_differ_from_opaque() {
    use brdf::V3;
    use brdf::layers::layered::Layered;
    use brdf::transmission::Volume;
    // wi below the surface: only the transmission lobe reaches it.
    let (wo, wi) = (V3::new(0.0, 0.6, 0.8), V3::new(0.28, -0.48, -0.832));
    let crate_eval = |t: f64, thickness: f64| {
        let m = Layered::new(V3::new(0.9, 0.6, 0.3), 0.0, 0.5)
            .and_then(|m| m.with_transmission(t))
            .expect("in-domain material")
            .with_volume(Volume::new(thickness, V3::splat(1.0), 1.0).expect("in-domain volume"));
        let f = m.eval(wo, wi);
        vec![f.x, f.y, f.z]
    };
    let cases = [(0.0, 0.0), (1.0, 0.0), (0.7, 0.0), (1.0, 2.0)];
    let mut input = String::new();
    for &(t, thickness) in &cases {
        let mut row = layered_args(t, thickness);
        row.extend([wo.x, wo.y, wo.z, wi.x, wi.y, wi.z]);
        let fields: Vec<String> = row.iter().map(|&x| fmt(x, Float::F64)).collect();
        input.push_str(&format!(
            "layers::layered::Layered::eval,{}\n",
            fields.join(",")
        ));
    }
    let (code, out, err) = run(&["eval", "--f64"], &input);
    assert_eq!(code, 0, "in-domain rows; stderr:\n{err}");
    let rows: Vec<Vec<f64>> = out
        .lines()
        .filter(|l| !l.starts_with("kernel,"))
        .map(|l| {
            let fields: Vec<&str> = l.split(',').collect();
            fields[fields.len() - 3..]
                .iter()
                .map(|f| parse(f, Float::F64).expect("a number"))
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), cases.len(), "one output row per input row");
    for (got, &(t, thickness)) in rows.iter().zip(&cases) {
        let want = crate_eval(t, thickness);
        assert!(
            got.iter().zip(&want).all(|(g, w)| same(*g, *w)),
            "transmission {t}, thickness {thickness}: the row gives {got:?}, the crate {want:?}"
        );
    }
    let opaque = &rows[0];
    assert!(opaque.iter().all(|&f| f == 0.0), "opaque: {opaque:?}");
    for (got, &(t, thickness)) in rows.iter().zip(&cases).skip(1) {
        assert!(
            got.iter().all(|&f| f > 0.0),
            "transmission {t}, thickness {thickness} transmits: {got:?}"
        );
    }
    assert_ne!(rows[1], rows[3], "the volume's thickness changes the lobe");
}
