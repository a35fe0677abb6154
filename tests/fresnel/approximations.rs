//! The Fresnel approximations against the exact equations: maximum absolute error printed and
//! bounded by the figure the docs state. Run with `-- --nocapture` to see the table.
#![cfg(feature = "fresnel")]

use brdf::fresnel::{
    self, average_dielectric, average_dielectric_fit, dielectric, schlick, schlick_sg,
};

fn max_abs(f: impl Fn(f64) -> f64, g: impl Fn(f64) -> f64) -> (f64, f64) {
    let mut worst = (0.0, 0.0);
    for i in 0..=10_000 {
        let c = i as f64 / 10_000.0;
        let e = (f(c) - g(c)).abs();
        if e > worst.0 {
            worst = (e, c);
        }
    }
    worst
}

#[test]
fn schlick_error_against_exact_dielectric() {
    println!(
        "| eta | F0 | max abs error of Schlick | at cos | max abs error of Schlick SG vs Schlick |"
    );
    // Bounds: measured maxima rounded up; Schlick's error grows with eta (it has no Brewster
    // dip), the SG fit's is a property of the exp2 curve alone.
    for (eta, bound) in [
        (1.33, 0.061),
        (1.5, 0.037),
        (2.0, 0.045),
        (2.4, 0.075),
        (3.0, 0.126),
    ] {
        let f0 = fresnel::f0_from_ior(eta);
        let (e, at) = max_abs(|c| schlick(f0, c), |c| dielectric(c, eta));
        let (e_sg, _) = max_abs(|c| schlick_sg(f0, c), |c| schlick(f0, c));
        println!("| {eta} | {f0:.4} | {e:.4} | {at:.3} | {e_sg:.5} |");
        assert!(e <= bound, "eta {eta}: {e} at {at}");
        assert!(e_sg <= 0.0037, "SG eta {eta}: {e_sg}");
    }
}

#[test]
fn average_fit_error_against_quadrature() {
    let mut worst: (f64, f64) = (0.0, 0.0);
    for i in 0..=250 {
        let eta = 0.5 + i as f64 / 100.0;
        let e = (average_dielectric_fit(eta) - average_dielectric(eta)).abs();
        if e > worst.0 {
            worst = (e, eta);
        }
    }
    println!(
        "Kulla-Conty average fit: max abs error {:.5} at eta {}",
        worst.0, worst.1
    );
    assert!(worst.0 <= 0.01, "{worst:?}");
}
