//! Every NDF is normalized: the integral of D(m) cos(theta_m) dm over the hemisphere is 1
//! (Walter et al. 2007 eq. 4), for alpha in [0.01, 1], isotropic and anisotropic up to
//! alpha_x / alpha_y = 100, and the isotropic dot-product form equals the vector form.
#![cfg(all(feature = "integrate", feature = "ggx", feature = "beckmann"))]

use brdf::V3;
use brdf::beckmann::{self, Beckmann};
use brdf::ggx::{self, Ggx};
use brdf::integrate::ndf_projected_area;
use brdf::microfacet::Microfacet;

/// Issue 3's bound; the integrator itself is good to 1e-9 on these lobes
/// (tests/integrate/accuracy.rs), so any excess is the model's.
const TOL: f64 = 1e-3;

const ALPHAS: [(f64, f64); 12] = [
    (0.01, 0.01),
    (0.03, 0.03),
    (0.1, 0.1),
    (0.3, 0.3),
    (0.6, 0.6),
    (1.0, 1.0),
    (1.0, 0.01),
    (0.01, 1.0),
    (0.5, 0.05),
    (0.2, 0.02),
    (0.05, 0.5),
    (0.8, 0.3),
];

fn check(name: &str, m: &impl Microfacet<f64>, ax: f64, ay: f64) {
    let e = ndf_projected_area(|h| m.d(h));
    println!(
        "{name} {ax}x{ay}: {:.9} (+- {:.1e}, {} evals)",
        e.value, e.error, e.evaluations
    );
    assert!(
        (e.value - 1.0).abs() <= TOL,
        "{name} {ax}x{ay}: projected area {}",
        e.value
    );
}

#[test]
fn ggx_projected_area_is_one() {
    for (ax, ay) in ALPHAS {
        check("ggx", &Ggx::new(ax, ay).unwrap(), ax, ay);
    }
}

#[test]
fn beckmann_projected_area_is_one() {
    for (ax, ay) in ALPHAS {
        check("beckmann", &Beckmann::new(ax, ay).unwrap(), ax, ay);
    }
}

#[test]
fn isotropic_dot_product_forms_equal_the_vector_forms() {
    for alpha in [0.01, 0.1, 0.5, 1.0] {
        let g = Ggx::isotropic(alpha).unwrap();
        let b = Beckmann::isotropic(alpha).unwrap();
        for i in 1..=100 {
            let theta = 1.5 * i as f64 / 100.0;
            let m = V3::new(theta.sin() * 0.6, theta.sin() * 0.8, theta.cos());
            let c = m.z;
            for (got, want) in [
                (ggx::d(c, alpha), g.d(m)),
                (beckmann::d(c, alpha), b.d(m)),
                (ggx::lambda(c, alpha), g.lambda(m)),
                (beckmann::lambda(c, alpha), b.lambda(m)),
            ] {
                // The dot-product forms take sin^2 from (1 - c)(1 + c), the vector forms from
                // x^2 + y^2: they differ by the rounding of c, amplified by Beckmann's exponent
                // tan^2 / alpha^2 (up to ~60 here): 1e-10 relative covers it.
                assert!(
                    (got - want).abs() <= 1e-10 * want.abs().max(1e-300),
                    "{got} vs {want} at alpha {alpha}, theta {theta}"
                );
            }
            let d_aniso = ggx::d_aniso(m.z, m.x, m.y, alpha, alpha);
            assert!((d_aniso - g.d(m)).abs() <= 1e-12 * d_aniso);
        }
    }
}

#[test]
fn anisotropic_lobes_stretch_along_the_rougher_axis() {
    let g = Ggx::new(0.5, 0.05).unwrap();
    let t = 0.2_f64;
    let along_x = V3::new(t.sin(), 0.0, t.cos());
    let along_y = V3::new(0.0, t.sin(), t.cos());
    assert!(g.d(along_x) > 10.0 * g.d(along_y));
    assert!(g.lambda(along_y) < g.lambda(along_x));
}
