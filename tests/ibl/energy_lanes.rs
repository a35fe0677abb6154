//! Bad input and lanes for every generic kernel of `ibl::energy`: a NaN in any input gives NaN
//! (in every output it reaches) on f32, f64, f32x8 and f64x4; a parameter outside its domain
//! gives NaN; in-domain input, including the domain's edges, gives finite output; and every
//! lane equals the scalar result bit for bit (the lookups run in f64 per lane and round once;
//! the rest is the same arithmetic), with a NaN in one lane leaving the others untouched.
#![cfg(feature = "ibl")]

use brdf::ibl::energy::{Albedo, AverageAlbedo, Reflectance};
use brdf::ibl::energy::{
    e_avg_ggx, e_ggx, fdez_aguera, fdez_aguera_ms, fresnel_avg_schlick, kulla_conty_fresnel,
    kulla_conty_ggx, kulla_conty_ggx_rgb, kulla_conty_lobe, turquin_scale,
};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

type Kernel<T> = fn(&[T]) -> Vec<T>;

struct Row<T> {
    name: &'static str,
    /// (input name, a valid value, values outside the domain, which outputs a NaN reaches
    /// (empty: all)).
    args: Vec<(&'static str, f64, Vec<f64>, Vec<usize>)>,
    f: Kernel<T>,
}

fn rows<T: Real>() -> Vec<Row<T>> {
    let all = Vec::new;
    vec![
        Row {
            name: "e_ggx",
            args: vec![
                ("mu", 0.5, vec![], all()),
                ("alpha", 0.3, vec![-0.1, f64::INFINITY], all()),
            ],
            f: |a| vec![e_ggx(a[0], a[1])],
        },
        Row {
            name: "e_avg_ggx",
            args: vec![("alpha", 0.3, vec![-0.1, f64::INFINITY], all())],
            f: |a| vec![e_avg_ggx(a[0])],
        },
        Row {
            name: "kulla_conty_lobe",
            args: vec![
                ("e_o", 0.8, vec![-0.1, 1.1], all()),
                ("e_i", 0.7, vec![-0.1, 1.1], all()),
                ("e_avg", 0.75, vec![-0.1, 1.1], all()),
            ],
            f: |a| {
                vec![kulla_conty_lobe(
                    Albedo(a[0]),
                    Albedo(a[1]),
                    AverageAlbedo(a[2]),
                )]
            },
        },
        Row {
            name: "kulla_conty_fresnel",
            args: vec![
                ("f_avg", 0.6, vec![-0.1, 1.1], all()),
                ("e_avg", 0.7, vec![-0.1, 1.1], all()),
            ],
            f: |a| vec![kulla_conty_fresnel(Reflectance(a[0]), AverageAlbedo(a[1]))],
        },
        Row {
            name: "fresnel_avg_schlick",
            args: vec![
                ("f0", 0.04, vec![-0.1, 1.1], all()),
                ("f90", 1.0, vec![-0.1, 1.1], all()),
            ],
            f: |a| vec![fresnel_avg_schlick(a[0], a[1])],
        },
        Row {
            name: "kulla_conty_ggx",
            args: vec![
                ("n_dot_v", 0.6, vec![], all()),
                ("n_dot_l", 0.3, vec![], all()),
                ("alpha", 0.5, vec![-0.1, f64::INFINITY], all()),
                ("f_avg", 0.9, vec![-0.1, 1.1], all()),
            ],
            f: |a| vec![kulla_conty_ggx(a[0], a[1], a[2], a[3])],
        },
        Row {
            name: "kulla_conty_ggx_rgb",
            args: vec![
                ("n_dot_v", 0.6, vec![], all()),
                ("n_dot_l", 0.3, vec![], all()),
                ("alpha", 0.5, vec![-0.1, f64::INFINITY], all()),
                ("f_avg.r", 0.9, vec![-0.1, 1.1], vec![0]),
                ("f_avg.g", 0.7, vec![-0.1, 1.1], vec![1]),
                ("f_avg.b", 0.4, vec![-0.1, 1.1], vec![2]),
            ],
            f: |a| {
                let v = kulla_conty_ggx_rgb(a[0], a[1], a[2], V3::new(a[3], a[4], a[5]));
                vec![v.x, v.y, v.z]
            },
        },
        Row {
            name: "turquin_scale",
            args: vec![
                ("e", 0.6, vec![0.0, -0.1, 1.1], all()),
                ("f", 0.5, vec![-0.1, 1.1], all()),
            ],
            f: |a| vec![turquin_scale(Albedo(a[0]), Reflectance(a[1]))],
        },
        Row {
            name: "fdez_aguera_ms",
            args: vec![
                ("fss_ess", 0.5, vec![-0.1, 1.1], all()),
                ("e_ss", 0.7, vec![-0.1, 1.1], all()),
                ("f_avg", 0.6, vec![-0.1, 1.1], all()),
            ],
            f: |a| vec![fdez_aguera_ms(a[0], Albedo(a[1]), Reflectance(a[2]))],
        },
        Row {
            name: "fdez_aguera",
            args: vec![
                ("a", 0.5, vec![-0.1], all()),
                ("b", 0.2, vec![-0.1], all()),
                ("f0", 0.6, vec![-0.1, 1.1], all()),
            ],
            f: |a| {
                let (s, m) = fdez_aguera(a[0], a[1], a[2]);
                vec![s, m]
            },
        },
    ]
}

/// T with every lane set to `v` (rounded to the lane type).
fn splat<T: Real>(v: f64) -> T {
    T::splat(v)
}

fn check_bad_input<T: Real>(ty: &str) -> usize {
    let mut checks = 0;
    for row in rows::<T>() {
        let valid: Vec<T> = row.args.iter().map(|a| splat(a.1)).collect();
        let out = (row.f)(&valid);
        for o in &out {
            for l in 0..T::LANES {
                let x: f64 = o.lane(l).into();
                assert!(x.is_finite(), "{ty} {}: valid input gave {x}", row.name);
            }
        }
        for (k, (name, _, invalid, reach)) in row.args.iter().enumerate() {
            let mut bad_values = vec![f64::NAN];
            bad_values.extend(invalid);
            for bad in bad_values {
                let mut args = valid.clone();
                args[k] = splat(bad);
                let out = (row.f)(&args);
                let outs: Vec<usize> = if reach.is_empty() {
                    (0..out.len()).collect()
                } else {
                    reach.clone()
                };
                for &o in &outs {
                    for l in 0..T::LANES {
                        let x: f64 = out[o].lane(l).into();
                        assert!(
                            x.is_nan(),
                            "{ty} {}: {name} = {bad} gave {x} in output {o}",
                            row.name
                        );
                    }
                }
                checks += 1;
            }
        }
        // Edges of the in-domain inputs stay finite: cosines -1, 0, 1, 1 + eps; alpha 0,
        // 1e4 and the largest finite float; unit-interval values 0 and 1.
        for (k, (name, _, _, _)) in row.args.iter().enumerate() {
            let edges: &[f64] = match *name {
                "mu" | "n_dot_v" | "n_dot_l" => &[-1.0, 0.0, 1e-30, 1.0, 1.0 + 1e-6],
                "alpha" => &[0.0, 1e-6, 1.0, 1e4, f64::MAX],
                "e" => &[1e-30, 1.0],
                // a + b <= 1 with the other at its valid value.
                "a" | "b" => &[0.0, 0.5],
                _ => &[0.0, 1.0],
            };
            for &edge in edges {
                let mut args = valid.clone();
                // The largest finite value of the lane type (f64::MAX would round to inf in f32).
                args[k] = if edge == f64::MAX {
                    T::MAX
                } else {
                    splat(edge)
                };
                for o in (row.f)(&args) {
                    for l in 0..T::LANES {
                        let x: f64 = o.lane(l).into();
                        assert!(
                            x.is_finite() && x >= 0.0,
                            "{ty} {}: {name} = {edge} gave {x}",
                            row.name
                        );
                    }
                }
                checks += 1;
            }
        }
    }
    checks
}

#[test]
fn nan_and_invalid_parameters_give_nan_on_every_lane_type() {
    let n = check_bad_input::<f32>("f32")
        + check_bad_input::<f64>("f64")
        + check_bad_input::<f32x8>("f32x8")
        + check_bad_input::<f64x4>("f64x4");
    println!(
        "{n} bad-input and edge checks over {} kernels x 4 lane types",
        rows::<f64>().len()
    );
}

/// A deterministic in-domain value for argument `k` of lane `l`, case `c`.
fn sample(c: usize, k: usize, l: usize) -> f64 {
    let x = ((c * 131 + k * 37 + l * 17) % 97) as f64 / 96.0;
    0.02 + 0.96 * x
}

fn check_lanes<T: Real>(ty: &str) -> usize
where
    T::Scalar: Real<Scalar = T::Scalar>,
{
    let lane_rows = rows::<T>();
    let scalar_rows = rows::<T::Scalar>();
    let mut checks = 0;
    for (row, srow) in lane_rows.iter().zip(&scalar_rows) {
        for c in 0..64 {
            let n_args = row.args.len();
            // Lane 3 of case 0 carries a NaN in its first input: the other lanes must not see it.
            let value = |k: usize, l: usize| {
                if c == 0 && k == 0 && l == 3 {
                    f64::NAN
                } else {
                    sample(c, k, l)
                }
            };
            let args: Vec<T> = (0..n_args)
                .map(|k| T::from_fn(|l| <T::Scalar as Real>::splat(value(k, l))))
                .collect();
            let out = (row.f)(&args);
            for l in 0..T::LANES {
                let sargs: Vec<T::Scalar> = (0..n_args)
                    .map(|k| <T::Scalar as Real>::splat(value(k, l)))
                    .collect();
                let sout = (srow.f)(&sargs);
                for (o, s) in out.iter().zip(&sout) {
                    let (a, b): (f64, f64) = (o.lane(l).into(), (*s).into());
                    assert!(
                        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                        "{ty} {} lane {l} case {c}: {a} vs scalar {b}",
                        row.name
                    );
                    checks += 1;
                }
            }
        }
    }
    checks
}

#[test]
fn lanes_equal_scalar_bit_for_bit() {
    let n = check_lanes::<f32x8>("f32x8") + check_lanes::<f64x4>("f64x4");
    println!("{n} lane outputs equal their scalar twins bit for bit");
}
