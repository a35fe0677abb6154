//! Bad input: every malformed row (wrong arity, not a number, unknown kernel, a value outside
//! its domain, NaN, a broken relation between arguments) is reported on stderr naming its
//! row and column, skipped, the other rows still printed, and the exit status is 2.

use crate::run;

#[test]
fn malformed_rows_are_reported_by_row_and_column_and_skipped() {
    let input = "\
n_dot_h,alpha
0.5,0.25
0.5
0.5,0.25,1
0.5,abc
1.5,0.25
0.5,-1
NaN,0.25

0.9,0.5
";
    let (code, out, err) = run(&["eval", "ggx::d"], input);
    assert_eq!(
        code, 2,
        "a rejected row makes the exit status 2; stderr:\n{err}"
    );
    let rows: Vec<&str> = out.lines().collect();
    assert_eq!(
        rows,
        [
            "n_dot_h,alpha,d",
            "0.5,0.25,0.033938915",
            "0.9,0.5,0.5165481"
        ],
        "the good rows still print"
    );
    for expected in [
        "row 3: column 2 (alpha) is missing",
        "row 4: column 3 is one too many",
        "row 5, column 2 (alpha): `abc` is not a number",
        "row 6, column 1 (n_dot_h): 1.5 is outside the domain of n_dot_h: [-1, 1]",
        "row 7, column 2 (alpha): -1 is outside the domain of alpha: [0, +inf) finite",
        "row 8, column 1 (n_dot_h): NaN is outside every domain",
        "6 rows rejected",
    ] {
        assert!(err.contains(expected), "stderr names `{expected}`:\n{err}");
    }
}

#[test]
fn a_broken_unit_vector_names_its_columns() {
    let (code, out, err) = run(&["eval", "frame::cos_theta"], "0,0,1\n0.5,0.5,0.5\n");
    assert_eq!(code, 2);
    assert_eq!(
        out.lines().count(),
        2,
        "header and the unit vector's row:\n{out}"
    );
    assert!(
        err.contains(
            "row 2, columns 1 (w_x), 2 (w_y), 3 (w_z): (w_x, w_y, w_z) = (0.5, 0.5, 0.5) has length"
        ),
        "{err}"
    );
}

#[test]
fn a_broken_ordering_names_its_columns() {
    let (code, _, err) = run(&["eval", "lights::spot_cone"], "0.5,0.9,0.8\n");
    assert_eq!(code, 2);
    assert!(
        err.contains(
            "row 1, columns 2 (cos_outer), 3 (cos_inner): cos_outer <= cos_inner does not hold"
        ),
        "{err}"
    );
}

#[test]
fn unknown_kernels_are_reported_with_suggestions() {
    let input = "ggx::d,0.5,0.25\nggx::dd,0.5,0.25\ndiffuse::lambert,0.5,0.5,0.5\n";
    let (code, out, err) = run(&["eval"], input);
    assert_eq!(code, 2);
    assert!(
        err.contains("row 2, column 1 (kernel): unknown kernel `ggx::dd`; did you mean ggx::d"),
        "{err}"
    );
    assert_eq!(
        out.lines().filter(|l| !l.starts_with("kernel,")).count(),
        2,
        "the other rows print:\n{out}"
    );
    let (code, _, err) = run(&["eval", "fresnel::schlik"], "");
    assert_eq!(code, 2);
    assert!(
        err.contains("unknown kernel `fresnel::schlik`; did you mean fresnel::schlick"),
        "{err}"
    );
}

#[test]
fn unchecked_evaluates_out_of_domain_rows() {
    let (code, out, err) = run(&["eval", "ggx::d", "--unchecked"], "0.5,-1\n1.5,0.25\n");
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        out.lines().collect::<Vec<_>>(),
        ["n_dot_h,alpha,d", "0.5,-1,NaN", "1.5,0.25,5.092958"]
    );
}

#[test]
fn a_header_must_match_the_kernel() {
    let (code, _, err) = run(&["eval", "ggx::d"], "alpha,n_dot_h\n0.25,0.5\n");
    assert_eq!(code, 2);
    assert!(
        err.contains(
            "row 1: the header `alpha,n_dot_h` does not match ggx::d's columns `n_dot_h,alpha`"
        ),
        "{err}"
    );
    let (code, _, err) = run(&["diff", "ggx::d"], "n_dot_h,alpha\n0.5,0.25,0.1\n");
    assert_eq!(code, 2, "diff's header holds the outputs too");
    assert!(
        err.contains("does not match ggx::d's columns `n_dot_h,alpha,d`"),
        "{err}"
    );
}

#[test]
fn diff_reports_bad_rows_and_compares_the_others() {
    let (code, out, err) = run(
        &["diff", "ggx::d"],
        "0.5,0.25,0.033938915\n0.5,0.25\n0.5,0.25,x\n",
    );
    assert_eq!(code, 2);
    assert!(out.contains("ggx::d (f32): 1 rows compared"), "{out}");
    assert!(err.contains("row 2: column 3 (d) is missing"), "{err}");
    assert!(
        err.contains("row 3, column 3 (d): `x` is not a number"),
        "{err}"
    );
}

#[test]
fn grids_cover_every_argument() {
    let (code, out, err) = run(
        &[
            "eval",
            "ggx::d",
            "--grid",
            "n_dot_h=0:1:3",
            "--grid",
            "alpha=0.25",
        ],
        "",
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        out.lines().collect::<Vec<_>>(),
        [
            "n_dot_h,alpha,d",
            "0,0.25,0",
            "0.5,0.25,0.033938915",
            "1,0.25,5.092958"
        ]
    );
    let (code, _, err) = run(&["eval", "ggx::d", "--grid", "n_dot_h=0:1:3"], "");
    assert_eq!(code, 2);
    assert!(err.contains("no values for alpha"), "{err}");
}
