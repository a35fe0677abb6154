//! Energy and reciprocity of the Cook-Torrance assembly, measured by the public integrators:
//! with F = 1 the directional albedo is <= 1 on an (alpha, theta_o) grid (the loss to
//! single scattering is printed, for the energy-compensation work to correct), and
//! f(wo, wi) = f(wi, wo) within 1e-5 relative.
#![cfg(all(
    feature = "integrate",
    feature = "cook-torrance",
    feature = "ggx",
    feature = "beckmann"
))]

use brdf::Cosines;
use brdf::V3;
use brdf::beckmann::Beckmann;
use brdf::cook_torrance;
use brdf::ggx::Ggx;
use brdf::integrate::{directional_albedo, reciprocity};
use brdf::microfacet::Alpha;
use brdf::microfacet::Microfacet;

const ALPHAS: [f64; 7] = [0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 1.0];
const THETAS_DEG: [f64; 6] = [0.0, 30.0, 60.0, 75.0, 85.0, 89.0];

fn albedo(m: &(impl Microfacet<f64> + ?Sized), theta_deg: f64) -> (f64, f64) {
    let t = theta_deg.to_radians();
    let wo = V3::new(t.sin(), 0.0, t.cos());
    let e = directional_albedo(wo, |o, i| cook_torrance::eval(m, o, i, |_| 1.0));
    (e.value, e.error)
}

fn loss_table(name: &str, make: impl Fn(f64) -> Box<dyn Microfacet<f64>>) {
    println!("\n{name}: energy loss 1 - rho(theta_o) with F = 1");
    print!("{:>7}", "alpha");
    for t in THETAS_DEG {
        print!(" {:>8}", format!("{t}deg"));
    }
    println!();
    for a in ALPHAS {
        let m = make(a);
        print!("{a:>7}");
        for t in THETAS_DEG {
            let (rho, err) = albedo(m.as_ref(), t);
            print!(" {:>8.5}", 1.0 - rho);
            // Energy conservation; the integrator's own error is the only slack allowed.
            assert!(
                rho <= 1.0 + err.max(1e-9),
                "{name} alpha {a} at {t} deg: albedo {rho} (+- {err:e})"
            );
            assert!(rho > 0.0);
        }
        println!();
    }
}

#[test]
fn cook_torrance_conserves_energy_and_prints_its_loss() {
    loss_table("GGX", |a| Box::new(Ggx::isotropic(a).unwrap()));
    loss_table("Beckmann", |a| Box::new(Beckmann::isotropic(a).unwrap()));
}

/// A smooth surface with F = 1 is a mirror: nothing is lost at normal incidence.
#[test]
fn smooth_surface_reflects_everything_at_normal_incidence() {
    let (rho, _) = albedo(&Ggx::isotropic(0.01).unwrap(), 0.0);
    assert!((rho - 1.0).abs() < 1e-3, "{rho}");
    // GGX at alpha = 1 has D = 1/pi and G2 = 2 mu / (1 + mu) at normal incidence, so
    // f = 1 / (2 pi (1 + mu)) and rho = integral of mu / (1 + mu) dmu over [0, 1] = 1 - ln 2:
    // a closed form the whole assembly must hit.
    let (rough, _) = albedo(&Ggx::isotropic(1.0).unwrap(), 0.0);
    assert!(
        (rough - (1.0 - core::f64::consts::LN_2)).abs() < 1e-7,
        "{rough}"
    );
}

#[test]
fn cook_torrance_is_reciprocal() {
    // 1e-5 relative: issue 3's bound. The symmetric formula gives ~1e-15.
    let ggx = Ggx::new(0.3, 0.1).unwrap();
    let beck = Beckmann::isotropic(0.2).unwrap();
    for (name, r) in [
        (
            "ggx dielectric",
            reciprocity(|o, i| cook_torrance::dielectric(&ggx, o, i, 1.5)),
        ),
        (
            "ggx conductor",
            reciprocity(|o, i| cook_torrance::conductor(&ggx, o, i, 0.2, 3.0)),
        ),
        (
            "beckmann dielectric",
            reciprocity(|o, i| cook_torrance::dielectric(&beck, o, i, 1.33)),
        ),
    ] {
        println!(
            "{name}: max relative asymmetry {:.1e} over {} pairs",
            r.max_rel, r.pairs
        );
        assert!(r.max_rel <= 1e-5, "{name}: {r:?}");
    }
}

#[test]
fn below_the_horizon_is_black() {
    let g = Ggx::isotropic(0.5).unwrap();
    let up = V3::new(0.0, 0.6, 0.8);
    let down = V3::new(0.0, 0.6, -0.8);
    assert_eq!(cook_torrance::dielectric(&g, up, down, 1.5), 0.0);
    assert_eq!(cook_torrance::dielectric(&g, down, up, 1.5), 0.0);
}

#[test]
fn dot_product_entry_points_equal_the_vector_ones() {
    let alpha = 0.35;
    let (g, b) = (
        Ggx::isotropic(alpha).unwrap(),
        Beckmann::isotropic(alpha).unwrap(),
    );
    for (to, po, ti, pi) in [
        (0.3, 0.0, 0.9, 2.0),
        (1.2, 1.0, 0.4, 4.0),
        (0.01, 0.0, 1.5, 3.1),
    ] {
        let (wo, wi) = (
            V3::new(
                f64::sin(to) * f64::cos(po),
                f64::sin(to) * f64::sin(po),
                f64::cos(to),
            ),
            V3::new(
                f64::sin(ti) * f64::cos(pi),
                f64::sin(ti) * f64::sin(pi),
                f64::cos(ti),
            ),
        );
        let (h, v_dot_h) = cook_torrance::half_vector(wo, wi);
        let f = brdf::fresnel::schlick(0.04, v_dot_h);
        let vec_g = cook_torrance::eval(&g, wo, wi, |c| brdf::fresnel::schlick(0.04, c));
        let dot_g = cook_torrance::ggx(
            Cosines {
                n_dot_v: wo.z,
                n_dot_l: wi.z,
                n_dot_h: h.z,
                v_dot_h,
            },
            Alpha(alpha),
            f,
        );
        let vec_b = cook_torrance::eval(&b, wo, wi, |c| brdf::fresnel::schlick(0.04, c));
        let dot_b = cook_torrance::beckmann(
            Cosines {
                n_dot_v: wo.z,
                n_dot_l: wi.z,
                n_dot_h: h.z,
                v_dot_h,
            },
            Alpha(alpha),
            f,
        );
        assert!((vec_g - dot_g).abs() <= 1e-12 * vec_g, "{vec_g} vs {dot_g}");
        assert!((vec_b - dot_b).abs() <= 1e-10 * vec_b, "{vec_b} vs {dot_b}");
    }
}
