//! The layered material with KHR_materials_transmission, thin-walled and volumetric
//! (KHR_materials_volume): transmission 0 is the
//! material without it bit for bit (eval, pdf, sample, every lane type), the white furnace
//! over the whole sphere stays at most 1, the sampler draws the density its pdf gives over the
//! whole sphere (chi-square on (cos theta in [-1, 1], phi) bins, as tests/transmission's), a
//! wrong pdf is rejected, and a NaN in any argument gives NaN on every lane.
#![cfg(all(feature = "layered", feature = "transmission", feature = "integrate"))]

use brdf::integrate::directional_albedo_sphere;
use brdf::layers::layered::Layered;
use brdf::material::MetallicRoughness;
use brdf::transmission::Volume;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};
use core::f64::consts::TAU;

use crate::common::{Rng, critical, sphere};

fn sphere_dir(rng: &mut Rng) -> V3<f64> {
    let z = 2.0 * rng.next_f64() - 1.0;
    let phi = rng.next_f64() * TAU;
    let r = (1.0 - z * z).max(0.0).sqrt();
    V3::new(r * phi.cos(), r * phi.sin(), z)
}

fn wo_at(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin() * 0.6, t.sin() * 0.8, t.cos())
}

fn bits<T: Real>(a: T, b: T, what: &str) {
    for l in 0..T::LANES {
        let (g, w): (f64, f64) = (a.lane(l).into(), b.lane(l).into());
        assert_eq!(g.to_bits(), w.to_bits(), "{what}: {g} vs {w}");
    }
}

#[test]
fn transmission_zero_is_the_material_without_it_bit_for_bit() {
    fn check<T: Real>(x: impl Fn(f64) -> T) {
        let mut rng = Rng(11);
        for _ in 0..100 {
            let mut r = || x(rng.next_f64());
            let without = Layered::new(V3::new(r(), r(), r()), r(), r())
                .and_then(|m| m.with_sheen(V3::new(r(), r(), r()), r()))
                .and_then(|m| m.with_clearcoat(r(), r()))
                .and_then(|m| m.with_anisotropy(r(), r()))
                .unwrap();
            let thick = Volume::new(x(0.5), V3::splat(x(0.5)), x(2.0)).unwrap();
            for with in [
                without.with_transmission(T::ZERO).unwrap(),
                without
                    .with_transmission(T::ZERO)
                    .unwrap()
                    .with_volume(thick),
            ] {
                for _ in 0..10 {
                    let (o, i) = (sphere_dir(&mut rng), sphere_dir(&mut rng));
                    let wo = V3::new(x(o.x), x(o.y), x(o.z.abs()));
                    let wi = V3::new(x(i.x), x(i.y), x(i.z));
                    let (a, b) = (with.eval(wo, wi), without.eval(wo, wi));
                    bits(a.x, b.x, "eval.x");
                    bits(a.y, b.y, "eval.y");
                    bits(a.z, b.z, "eval.z");
                    bits(with.pdf(wo, wi), without.pdf(wo, wi), "pdf");
                    let (u1, u2) = (x(rng.next_f64()), x(rng.next_f64()));
                    let ((a, pa), (b, pb)) = (with.sample(wo, u1, u2), without.sample(wo, u1, u2));
                    bits(a.x, b.x, "sample.x");
                    bits(a.z, b.z, "sample.z");
                    bits(pa, pb, "sample pdf");
                }
            }
        }
    }
    check(|v| v as f32);
    check(|v| v);
    check(|v| f32x8::splat(v as f32));
    check(f64x4::splat);
}

/// A white material (base colour 1) with transmission 1 reflects and transmits at most the
/// light it receives: the albedo over the whole sphere, (1 / pi) integral f |wi.z| times pi,
/// is <= 1 + 2e-3 (the sphere integrator's stated error, a few 1e-4 on these lobes, with a
/// margin), for views from normal to 85 degrees, rough and smooth, with and without layers.
#[test]
fn white_furnace_over_the_sphere_is_at_most_one() {
    let mut worst: f64 = 0.0;
    let thick = Volume::new(1.0, V3::splat(1.0), f64::MAX).unwrap();
    for rough in [0.2, 0.5, 1.0] {
        for (layers, volume) in [(false, false), (true, false), (false, true), (true, true)] {
            let mut m = Layered::new(V3::splat(1.0), 0.0, rough)
                .and_then(|m| m.with_transmission(1.0))
                .unwrap();
            if volume {
                m = m.with_volume(thick);
            }
            if layers {
                m = m
                    .with_sheen(V3::splat(1.0), 0.5)
                    .and_then(|m| m.with_clearcoat(1.0, 0.3))
                    .unwrap();
            }
            for theta in [0.0, 30.0, 60.0, 85.0] {
                let wo = wo_at(theta);
                let through = V3::new(-wo.x, -wo.y, -wo.z);
                let mirrored = V3::new(wo.x, wo.y, -wo.z);
                let e = directional_albedo_sphere(wo, |o, i| m.eval(o, i).y, &[through, mirrored]);
                println!(
                    "rough {rough} layers {layers} volume {volume} theta {theta}: albedo {:.5}",
                    e.value
                );
                worst = worst.max(e.value);
            }
        }
    }
    println!("worst sphere albedo {worst:.5}");
    assert!(worst <= 1.0 + 2e-3, "{worst}");
}

/// (statistic, degrees of freedom, stray samples) of the sampler's directions against the
/// pdf over the whole sphere ([`sphere::chi_square`]); each live sample's returned pdf is the
/// material's pdf function's (`pdf` may be another, to test the test).
fn chi_square(m: &Layered<f64>, pdf: &dyn Fn(V3<f64>) -> f64, wo: V3<f64>) -> (f64, usize, f64) {
    let fit = sphere::chi_square(
        |rng| {
            let (w, p) = m.sample(wo, rng.next_f64(), rng.next_f64());
            if p > 0.0 {
                assert_eq!(p, m.pdf(wo, w), "returned pdf vs pdf function at {w:?}");
            }
            (w, p)
        },
        pdf,
    );
    (fit.stat, fit.dof, fit.stray)
}

fn transmissive() -> [(Layered<f64>, f64); 6] {
    let thick = Volume::new(0.2, V3::new(0.9, 0.5, 0.2), 1.0).unwrap();
    let diamond = MetallicRoughness::new(V3::new(0.5, 0.6, 0.9), 0.1, 0.8)
        .and_then(|b| b.with_ior(2.4))
        .unwrap();
    [
        (
            Layered::new(V3::new(0.9, 0.8, 0.7), 0.0, 0.4)
                .and_then(|m| m.with_transmission(1.0))
                .unwrap()
                .with_volume(thick),
            0.0,
        ),
        (
            Layered::new(V3::new(0.8, 0.6, 0.3), 0.0, 0.5)
                .and_then(|m| m.with_transmission(0.9))
                .and_then(|m| m.with_clearcoat(1.0, 0.2))
                .and_then(|m| m.with_anisotropy(0.6, 1.0))
                .unwrap()
                .with_volume(thick),
            70.0,
        ),
        (
            Layered::from_base(diamond)
                .with_transmission(1.0)
                .unwrap()
                .with_volume(thick),
            40.0,
        ),
        (
            Layered::new(V3::new(0.9, 0.8, 0.7), 0.0, 0.4)
                .and_then(|m| m.with_transmission(1.0))
                .unwrap(),
            0.0,
        ),
        (
            Layered::new(V3::new(0.8, 0.6, 0.3), 0.2, 0.6)
                .and_then(|m| m.with_transmission(0.6))
                .and_then(|m| m.with_clearcoat(1.0, 0.5))
                .unwrap(),
            50.0,
        ),
        (
            Layered::new(V3::new(0.3, 0.6, 0.9), 0.0, 0.7)
                .and_then(|m| m.with_transmission(0.8))
                .and_then(|m| m.with_sheen(V3::splat(0.5), 0.3))
                .and_then(|m| m.with_anisotropy(0.5, 0.4))
                .unwrap(),
            80.0,
        ),
    ]
}

#[test]
fn sampler_matches_its_pdf_over_the_sphere() {
    for (k, (m, theta)) in transmissive().iter().enumerate() {
        let wo = wo_at(*theta);
        let (stat, dof, stray) = chi_square(m, &|w| m.pdf(wo, w), wo);
        let c = critical(dof);
        println!("case {k}: chi^2 = {stat:.1}, dof = {dof}, critical = {c:.1}, stray {stray}");
        // Pooled bins that expect almost nothing must receive almost nothing.
        assert!(
            stray < 20.0,
            "case {k}: {stray} samples where the pdf expects < 5"
        );
        assert!(dof > 30, "case {k}: too few populated bins ({dof})");
        assert!(stat < c, "case {k}: chi^2 = {stat} >= {c} (dof {dof})");
    }
}

/// The chi-square has teeth: the samples judged against the pdf of the same material without
/// transmission (no density below the surface) fail by a wide margin.
#[test]
fn a_pdf_without_the_transmission_lobe_is_rejected() {
    let (m, theta) = transmissive()[4];
    let wo = wo_at(theta);
    let opaque = m.with_transmission(0.0).unwrap();
    let (stat, dof, stray) = chi_square(&m, &|w| opaque.pdf(wo, w), wo);
    println!("wrong pdf: chi^2 = {stat:.1}, dof = {dof}, stray {stray}");
    assert!(
        stat > 4.0 * critical(dof) || stray >= 20.0,
        "{stat} vs {}, stray {stray}",
        critical(dof)
    );
}

/// NaN in any component of wo or wi (or in u1, u2) gives NaN in eval, pdf and sample, on
/// every lane type, with transmission on, thin-walled and volumetric; an invalid factor is
/// refused.
#[test]
fn nan_rule_on_every_lane() {
    fn check<T: Real>(x: impl Fn(f64) -> T, thickness: f64) {
        let m = Layered::new(V3::splat(x(0.8)), x(0.1), x(0.5))
            .and_then(|m| m.with_transmission(x(0.7)))
            .and_then(|m| m.with_clearcoat(x(0.5), x(0.3)))
            .unwrap()
            .with_volume(Volume::new(x(thickness), V3::splat(x(1.0)), x(1.0)).unwrap());
        let nan = x(f64::NAN);
        let wo = V3::new(x(0.3), x(0.0), x(0.9539392014169456));
        let wi = V3::new(x(0.1), x(0.2), x(-0.9746794344808963));
        let all_nan = |v: T| (0..T::LANES).all(|l| Into::<f64>::into(v.lane(l)).is_nan());
        for c in 0..3 {
            let put = |w: V3<T>| match c {
                0 => V3::new(nan, w.y, w.z),
                1 => V3::new(w.x, nan, w.z),
                _ => V3::new(w.x, w.y, nan),
            };
            for (o, i) in [(put(wo), wi), (wo, put(wi))] {
                let f = m.eval(o, i);
                assert!(all_nan(f.x) && all_nan(f.y) && all_nan(f.z), "eval");
                assert!(all_nan(m.pdf(o, i)), "pdf");
            }
            let (s, p) = m.sample(put(wo), x(0.3), x(0.6));
            assert!(all_nan(s.z) && all_nan(p), "sample");
        }
        for (u1, u2) in [(nan, x(0.5)), (x(0.5), nan)] {
            let (s, p) = m.sample(wo, u1, u2);
            assert!(all_nan(s.x) && all_nan(p), "sample u");
        }
        // Finite below the surface, where the transmission lobe lives.
        let f = m.eval(wo, wi);
        assert!(!all_nan(f.x) && f.x.lane(0).into() > 0.0);
        for bad in [-0.1, 1.1, f64::NAN, f64::INFINITY] {
            assert!(m.with_transmission(x(bad)).is_err(), "{bad}");
        }
    }
    for thickness in [0.0, 1.0] {
        check(|v| v as f32, thickness);
        check(|v| v, thickness);
        check(|v| f32x8::splat(v as f32), thickness);
        check(f64x4::splat, thickness);
    }
}
