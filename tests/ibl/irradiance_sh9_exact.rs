//! SH9 is exact where it should be: projecting a band <= 2 environment and evaluating gives
//! it back; its irradiance equals the Funk-Hecke closed form and the hemisphere quadrature;
//! R&H's matrix form equals the polynomial form; rotating the environment rotates the
//! irradiance.
#![cfg(feature = "ibl")]

use brdf::V3;
use brdf::ibl::irradiance::{self, Sh9, project, sh9_basis};
use core::f64::consts::PI;

fn normals() -> impl Iterator<Item = V3<f64>> {
    (0..300).map(|i| {
        let z = 1.0 - 2.0 * (f64::from(i) + 0.5) / 300.0;
        let r = (1.0 - z * z).max(0.0).sqrt();
        let phi = f64::from(i) * 2.399_963_229_728_653;
        V3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

/// A band <= 2 environment (every quadratic in x, y, z is), RGB.
fn quadratic(d: V3<f64>) -> V3<f64> {
    V3::new(
        1.0 + 0.3 * d.x - 0.2 * d.y + 0.5 * d.z * d.z + 0.4 * d.x * d.y,
        0.7 + 0.1 * d.z + 0.3 * d.x * d.z - 0.2 * d.y * d.z,
        2.0 + 0.6 * (d.x * d.x - d.y * d.y),
    )
}

/// Its irradiance by hand (Funk-Hecke: the hemisphere integral of P_l(a.l) (n.l) is
/// A_l P_l(a.n)): a constant c gives pi c, a linear b.l gives (2 pi / 3) b.n, a traceless
/// quadratic q(l) gives (pi / 4) q(n); z^2 is split as 1/3 + (z^2 - 1/3).
fn quadratic_irradiance(n: V3<f64>) -> V3<f64> {
    // Red: 1 + 0.3 x - 0.2 y + 0.5 z^2 + 0.4 xy; z^2 = 1/3 + (z^2 - 1/3).
    let r = PI * (1.0 + 0.5 / 3.0)
        + 2.0 * PI / 3.0 * (0.3 * n.x - 0.2 * n.y)
        + PI / 4.0 * (0.5 * (n.z * n.z - 1.0 / 3.0) + 0.4 * n.x * n.y);
    let g =
        PI * 0.7 + 2.0 * PI / 3.0 * (0.1 * n.z) + PI / 4.0 * (0.3 * n.x * n.z - 0.2 * n.y * n.z);
    let b = PI * 2.0 + PI / 4.0 * 0.6 * (n.x * n.x - n.y * n.y);
    V3::new(r, g, b)
}

fn rel(a: V3<f64>, b: V3<f64>) -> f64 {
    ((a - b).abs() / b.abs().max(V3::splat(1e-300))).max_element()
}

#[test]
fn band_two_environments_round_trip_and_have_exact_irradiance() {
    let sh = project(quadratic, 3);
    let (mut eval_err, mut sh_err, mut quad_err, mut matrix_err) =
        (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    for n in normals() {
        eval_err = eval_err.max(rel(sh.eval(n), quadratic(n)));
        let want = quadratic_irradiance(n);
        sh_err = sh_err.max(rel(sh.irradiance(n), want));
        quad_err = quad_err.max(rel(irradiance::irradiance(n, quadratic, 3), want));
        // R&H eq. 12: (n, 1) M (n, 1)^T.
        let m = sh.irradiance_matrix();
        let v = [n.x, n.y, n.z, 1.0];
        let mut e = V3::splat(0.0);
        for i in 0..4 {
            for j in 0..4 {
                e += m[i][j] * (v[i] * v[j]);
            }
        }
        matrix_err = matrix_err.max(rel(e, sh.irradiance(n)));
        matrix_err = matrix_err.max(rel(sh.cosine_convolved().eval(n), sh.irradiance(n)));
    }
    println!(
        "band <= 2: eval {eval_err:.2e}, SH9 irradiance {sh_err:.2e}, quadrature {quad_err:.2e}, matrix/convolved vs polynomial {matrix_err:.2e}"
    );
    // All exact; rounding of sums of about ten terms of size 1 (and 2 order^2 = 18 nodes).
    for e in [eval_err, sh_err, quad_err, matrix_err] {
        assert!(e < 1e-13, "{e}");
    }
}

#[test]
fn basis_is_orthonormal_under_the_projection_rule() {
    let mut worst = 0.0_f64;
    for a in 0..9 {
        // Project Y_a (in red): coefficient b must be delta_ab.
        let sh = project(|d| V3::new(sh9_basis(d)[a], 0.0, 0.0), 4);
        for b in 0..9 {
            let want = if a == b { 1.0 } else { 0.0 };
            worst = worst.max((sh.coeffs()[b].x - want).abs());
        }
    }
    println!("orthonormality: max |<Y_a, Y_b> - delta_ab| = {worst:.2e}");
    assert!(worst < 1e-14);
}

#[test]
fn irradiance_of_a_rotated_environment_is_the_rotated_irradiance() {
    // Rotation by 90 degrees about x: (x, y, z) -> (x, -z, y).
    let rot = |d: V3<f64>| V3::new(d.x, -d.z, d.y);
    let inv = |d: V3<f64>| V3::new(d.x, d.z, -d.y);
    let env = |d: V3<f64>| V3::splat(1.0 + (3.0 * d.x + d.z).max(0.0).powi(3));
    let sh = project(env, 48);
    let sh_rot = project(|d| env(inv(d)), 48);
    let mut worst = 0.0_f64;
    for n in normals() {
        worst = worst.max(rel(sh_rot.irradiance(rot(n)), sh.irradiance(n)));
    }
    println!("rotation: max relative difference {worst:.2e}");
    // Both projections integrate the same smooth function on differently placed nodes.
    assert!(worst < 1e-6, "{worst}");
    let _ = Sh9::<f32>::splat_from(&sh);
}
