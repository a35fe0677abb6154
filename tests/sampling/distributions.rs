//! Every sampler draws from the pdf it returns: the pdfs integrate to 1 (by the public
//! integrator), sampled directions pass a chi-square test against the pdf, the returned pdf is
//! the pdf function at the sample, and lanes reproduce scalars.
#![cfg(all(
    feature = "sampling",
    feature = "ggx",
    feature = "beckmann",
    feature = "integrate"
))]

use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::integrate::{Config, hemisphere};
use brdf::sampling::{self, erf_inv};
use brdf::wide::f32x8;
use brdf::{Real, V3};
use glam::DVec3;

use crate::common;
use common::{Rng, assert_fits, chi_square, dot, normalize};

fn v(w: DVec3) -> V3<f64> {
    V3::from(w)
}

fn wo_at(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin() * 0.6, t.sin() * 0.8, t.cos())
}

#[test]
fn cosine_hemisphere_matches_its_pdf() {
    let s = chi_square(
        |a, b| {
            let (w, p) = sampling::cosine_hemisphere(a, b);
            (w.into(), p)
        },
        |w| sampling::cosine_hemisphere_pdf(v(w)),
    );
    assert_fits("cosine", s);
}

#[test]
fn d_cos_samplers_match_their_pdf() {
    let g = Ggx::new(0.3, 0.6).unwrap();
    let b = Beckmann::new(0.5, 0.25).unwrap();
    assert_fits(
        "ggx D cos",
        chi_square(
            |x, y| {
                let (m, p) = sampling::ggx_d_cos(&g, x, y);
                (m.into(), p)
            },
            |m| sampling::d_cos_pdf(&g, v(m)),
        ),
    );
    assert_fits(
        "beckmann D cos",
        chi_square(
            |x, y| {
                let (m, p) = sampling::beckmann_d_cos(&b, x, y);
                (m.into(), p)
            },
            |m| sampling::d_cos_pdf(&b, v(m)),
        ),
    );
}

#[test]
fn ggx_visible_normal_samplers_match_their_pdf() {
    for (ax, ay, theta) in [
        (0.5, 0.5, 0.0),
        (0.5, 0.2, 60.0),
        (0.3, 0.8, 85.0),
        (1.0, 1.0, 45.0),
    ] {
        let g = Ggx::new(ax, ay).unwrap();
        let wo = wo_at(theta);
        assert_fits(
            &format!("ggx vndf Heitz 2018, alpha {ax}x{ay}, {theta} deg"),
            chi_square(
                |x, y| {
                    let (m, p) = sampling::ggx_vndf(&g, wo, x, y);
                    (m.into(), p)
                },
                |m| sampling::visible_normal_pdf(&g, wo, v(m)),
            ),
        );
        assert_fits(
            &format!("ggx vndf spherical cap, alpha {ax}x{ay}, {theta} deg"),
            chi_square(
                |x, y| {
                    let (m, p) = sampling::ggx_vndf_spherical_cap(&g, wo, x, y);
                    (m.into(), p)
                },
                |m| sampling::visible_normal_pdf(&g, wo, v(m)),
            ),
        );
    }
}

#[test]
fn beckmann_visible_normal_sampler_matches_its_pdf() {
    for (ax, ay, theta) in [
        (0.5, 0.5, 0.0),
        (0.3, 0.5, 30.0),
        (0.6, 0.3, 75.0),
        (0.4, 0.4, 88.0),
    ] {
        let b = Beckmann::new(ax, ay).unwrap();
        let wo = wo_at(theta);
        assert_fits(
            &format!("beckmann vndf, alpha {ax}x{ay}, {theta} deg"),
            chi_square(
                |x, y| {
                    let (m, p) = sampling::beckmann_vndf(&b, wo, x, y);
                    (m.into(), p)
                },
                |m| sampling::visible_normal_pdf(&b, wo, v(m)),
            ),
        );
    }
}

#[test]
fn a_wrong_pdf_is_rejected() {
    // The test has teeth: GGX D cos samples judged against the pdf D alone (the cosine left
    // out, a classic bug) fail by a wide margin.
    let g = Ggx::isotropic(0.5).unwrap();
    let wrong = |m: DVec3| {
        use brdf::microfacet::Microfacet;
        g.d(v(m)) / 1.26 // D integrates to ~1.26 over the hemisphere at alpha = 0.5
    };
    let (stat, dof) = chi_square(
        |x, y| {
            let (m, _) = sampling::ggx_d_cos(&g, x, y);
            (m.into(), wrong(m.into()))
        },
        wrong,
    );
    assert!(stat > 10.0 * dof as f64, "chi^2 {stat} (dof {dof})");
}

#[test]
fn pdfs_integrate_to_one() {
    let cfg = Config::default();
    let g = Ggx::new(0.2, 0.5).unwrap();
    let b = Beckmann::isotropic(0.3).unwrap();
    let wo = wo_at(70.0);
    type Pdf<'a> = Box<dyn Fn(V3<f64>) -> f64 + 'a>;
    let cases: [(&str, Pdf); 5] = [
        ("cosine", Box::new(sampling::cosine_hemisphere_pdf::<f64>)),
        ("ggx D cos", Box::new(|m| sampling::d_cos_pdf(&g, m))),
        ("beckmann D cos", Box::new(|m| sampling::d_cos_pdf(&b, m))),
        (
            "ggx visible",
            Box::new(|m| sampling::visible_normal_pdf(&g, wo, m)),
        ),
        (
            "beckmann visible",
            Box::new(|m| sampling::visible_normal_pdf(&b, wo, m)),
        ),
    ];
    for (name, pdf) in cases {
        let e = hemisphere(pdf, &[wo], &cfg);
        assert!((e.value - 1.0).abs() < 1e-3, "{name}: {}", e.value);
    }
    // The reflected-direction pdf integrates to 1 over the whole sphere (directions reflected
    // below the horizon included): upper half plus the mirrored lower half.
    let refl = |wi: V3<f64>| {
        let h = normalize(wo + wi);
        let h = if h.z < 0.0 { -h } else { h };
        sampling::reflect_pdf(sampling::visible_normal_pdf(&g, wo, h), dot(wo, h))
    };
    let r = wo - 2.0 * wo.z * V3::unit_z(); // mirror: the peak of the reflected lobe
    let upper = hemisphere(refl, &[V3::new(-wo.x, -wo.y, wo.z)], &cfg).value;
    let lower = hemisphere(
        |w| refl(V3::new(w.x, w.y, -w.z)),
        &[V3::new(r.x, r.y, -r.z)],
        &cfg,
    )
    .value;
    assert!(
        (upper + lower - 1.0).abs() < 1e-3,
        "reflected pdf: {upper} + {lower}"
    );
}

#[test]
fn erf_inv_inverts_erf() {
    for i in -999..=999 {
        let y = i as f64 / 1000.0;
        let x = erf_inv(y);
        assert!(
            (libm::erf(x) - y).abs() <= 4.0 * f64::EPSILON,
            "y {y}: erf({x}) = {}",
            libm::erf(x)
        );
        let x32 = erf_inv(y as f32);
        assert!((libm::erff(x32) - y as f32).abs() <= 4.0 * f32::EPSILON);
    }
    assert_eq!(erf_inv(1.0), f64::INFINITY);
    assert_eq!(erf_inv(-1.0), f64::NEG_INFINITY);
}

#[test]
fn lanes_reproduce_scalar_samples() {
    let g = Ggx::new(0.4f32, 0.2).unwrap();
    let gl = Ggx::new(f32x8::splat(0.4), f32x8::splat(0.2)).unwrap();
    let b = Beckmann::new(0.4f32, 0.2).unwrap();
    let bl = Beckmann::new(f32x8::splat(0.4), f32x8::splat(0.2)).unwrap();
    let wo = V3::new(0.5f32, 0.3, 0.812);
    let wol = V3::new(f32x8::splat(0.5), f32x8::splat(0.3), f32x8::splat(0.812));
    let mut rng = Rng(7);
    for _ in 0..200 {
        let u1: [f32; 8] = core::array::from_fn(|_| rng.next_f64() as f32);
        let u2: [f32; 8] = core::array::from_fn(|_| rng.next_f64() as f32);
        let (a, b2) = (f32x8::new(u1), f32x8::new(u2));
        let lanes = [
            sampling::ggx_vndf(&gl, wol, a, b2),
            sampling::ggx_vndf_spherical_cap(&gl, wol, a, b2),
            sampling::beckmann_vndf(&bl, wol, a, b2),
            sampling::cosine_hemisphere(a, b2),
        ];
        for i in 0..8 {
            let scalars = [
                sampling::ggx_vndf(&g, wo, u1[i], u2[i]),
                sampling::ggx_vndf_spherical_cap(&g, wo, u1[i], u2[i]),
                sampling::beckmann_vndf(&b, wo, u1[i], u2[i]),
                sampling::cosine_hemisphere(u1[i], u2[i]),
            ];
            for ((ml, pl), (ms, ps)) in lanes.iter().zip(&scalars) {
                // Lane sin/cos/exp/ln are within 1-3 ulps of libm (src/real.rs); a few
                // roundings later, 1e-5 relative bounds the difference.
                let (m, p) = (ml.lane(i), pl.lane(i));
                assert!((m - *ms).length() <= 1e-5, "{m:?} vs {ms:?}");
                assert!((p - ps).abs() <= 1e-4 * ps.max(1.0), "{p} vs {ps}");
            }
        }
    }
}

#[test]
fn u_equal_to_one_stays_finite() {
    let g = Ggx::isotropic(0.3f64).unwrap();
    let b = Beckmann::isotropic(0.3f64).unwrap();
    let wo = V3::new(0.6, 0.0, 0.8);
    for (u1, u2) in [(1.0, 1.0), (0.0, 0.0), (1.0, 0.0), (0.0, 1.0)] {
        for (m, p) in [
            sampling::ggx_d_cos(&g, u1, u2),
            sampling::beckmann_d_cos(&b, u1, u2),
            sampling::ggx_vndf(&g, wo, u1, u2),
            sampling::ggx_vndf_spherical_cap(&g, wo, u1, u2),
            sampling::beckmann_vndf(&b, wo, u1, u2),
            sampling::cosine_hemisphere(u1, u2),
        ] {
            assert!(
                m.x.is_finite() && m.y.is_finite() && m.z.is_finite() && p.is_finite(),
                "u = ({u1}, {u2}): {m:?} {p}"
            );
        }
    }
}
