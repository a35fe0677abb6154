//! A constant environment L has irradiance pi L exactly (to rounding), by the hemisphere
//! quadrature and through SH9, for every normal; the quadrature's parts are exact: the
//! Gauss-Legendre weights sum to 2 and the cube texel solid angles to 4 pi.
#![cfg(feature = "ibl")]

use brdf::V3;
use brdf::ibl::irradiance::{self, Sh9, cube_texel_solid_angle, gauss_legendre, project};
use core::f64::consts::PI;

fn normals() -> impl Iterator<Item = V3<f64>> {
    // A Fibonacci spiral: 200 near-uniform unit normals, poles included.
    (0..200).map(|i| {
        let z = 1.0 - 2.0 * f64::from(i) / 199.0;
        let r = (1.0 - z * z).max(0.0).sqrt();
        let phi = f64::from(i) * 2.399_963_229_728_653;
        V3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

fn rel(a: V3<f64>, b: V3<f64>) -> f64 {
    ((a - b).abs() / b.abs()).max_element()
}

#[test]
fn constant_environment_gives_pi_l_by_quadrature_and_sh9() {
    let l = V3::new(1.0, 0.37, 12.5);
    let want = l * PI;
    let mut worst = (0.0_f64, 0.0_f64, 0.0_f64);
    for order in [1, 2, 5, 16, 64] {
        // project is exact for environments of degree <= 2 order - 3: a constant needs 2.
        let sh = project(|_| l, order.max(2));
        let sh32 = Sh9::<f32>::splat_from(&sh);
        for n in normals() {
            worst.0 = worst
                .0
                .max(rel(irradiance::irradiance(n, |_| l, order), want));
            worst.1 = worst.1.max(rel(sh.irradiance(n), want));
            let n32 = V3::new(n.x as f32, n.y as f32, n.z as f32);
            let e32 = sh32.irradiance(n32);
            worst.2 = worst
                .2
                .max(rel(V3::new(e32.x.into(), e32.y.into(), e32.z.into()), want));
        }
    }
    println!(
        "constant L: max relative error, quadrature {:.2e}, SH9 f64 {:.2e}, SH9 f32 {:.2e}",
        worst.0, worst.1, worst.2
    );
    // Quadrature: ring sums of up to 128 equal terms and 64 weighted rings, a few ULP each.
    // SH9: the band-1 and band-2 coefficients of a constant are rounding residues of sums
    // over 8192 nodes, and they enter E with weights near 1: measured 6e-14. f32 rounds
    // the coefficients and the normal.
    assert!(worst.0 < 1e-14 && worst.1 < 1e-13, "{worst:?}");
    assert!(worst.2 < 1e-5, "{worst:?}");
}

#[test]
fn quadrature_weights_and_texel_solid_angles_are_exact() {
    let mut worst = 0.0_f64;
    // x^2 needs order >= 2 (exact for degree <= 2 order - 1).
    for order in [2, 3, 8, 33, 128, 1024] {
        let (mut sum, mut moment) = (0.0, 0.0);
        for k in 0..order {
            let (x, w) = gauss_legendre(order, k);
            assert!(w > 0.0 && x.abs() < 1.0, "order {order} node {k}: {x} {w}");
            sum += w;
            moment += w * x * x;
        }
        worst = worst.max((sum - 2.0).abs()).max((moment - 2.0 / 3.0).abs());
    }
    println!("Gauss-Legendre: max |sum w - 2|, |sum w x^2 - 2/3| = {worst:.2e}");
    // 1024 additions of weights each within a few ULP.
    assert!(worst < 1e-13);
    for w in [1, 2, 7, 64] {
        let mut total = 0.0;
        for i in 0..w {
            for j in 0..w {
                total += cube_texel_solid_angle(w, i, j);
            }
        }
        let err = (6.0 * total - 4.0 * PI).abs();
        println!("cube {w}x{w}: 6 * sum of texel solid angles - 4 pi = {err:.2e}");
        assert!(err < 1e-12, "{w}: {err}");
    }
    assert!(cube_texel_solid_angle(4, 4, 0).is_nan());
}
