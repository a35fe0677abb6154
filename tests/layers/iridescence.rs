//! KHR_materials_iridescence in the layered material: factor 0 and thickness 0 are the
//! material without it bit for bit (every lane type), a vanishing film is the exact Fresnel
//! reflectance of the base's index (dielectric and metal), the compensated white metal passes
//! the furnace and the layered albedo stays at most 1, reciprocity, the sampler against its
//! pdf by chi-square, lanes against scalars.
#![cfg(all(feature = "layered", feature = "iridescence", feature = "integrate"))]

use brdf::integrate::{directional_albedo, reciprocity};
use brdf::iridescence::ThinFilm;
use brdf::layers::layered::Layered;
use brdf::material::MetallicRoughness;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

use crate::common::{Rng, assert_fits, chi_square, normalize};

fn wo_at(theta_deg: f64) -> V3<f64> {
    let t = theta_deg.to_radians();
    V3::new(t.sin() * 0.6, t.sin() * 0.8, t.cos())
}

fn random_dir(rng: &mut Rng) -> V3<f64> {
    let z = rng.next_f64();
    let phi = rng.next_f64() * core::f64::consts::TAU;
    let r = (1.0 - z * z).sqrt();
    V3::new(r * phi.cos(), r * phi.sin(), z)
}

fn soap() -> ThinFilm<f64> {
    ThinFilm::new(400.0, 1.3).unwrap()
}

#[test]
fn factor_zero_and_thickness_zero_are_the_material_without_it_bit_for_bit() {
    fn check<T: Real>(x: impl Fn(f64) -> T) {
        let mut rng = Rng(17);
        let film = ThinFilm::new(x(400.0), x(1.3)).unwrap();
        let flat = ThinFilm::new(x(0.0), x(1.8)).unwrap();
        for _ in 0..100 {
            let base = MetallicRoughness::new(
                V3::new(x(rng.next_f64()), x(rng.next_f64()), x(rng.next_f64())),
                x(rng.next_f64()),
                x(rng.next_f64()),
            )
            .unwrap();
            let r = x(rng.next_f64());
            let layered = Layered::from_base(base)
                .with_sheen(V3::splat(x(0.5)), r)
                .and_then(|m| m.with_clearcoat(x(0.6), r))
                .unwrap();
            for m in [
                Layered::from_base(base),
                layered,
                layered.with_compensation(true),
            ] {
                let variants = [
                    m.with_iridescence(T::ZERO, film).unwrap(),
                    m.with_iridescence(T::ONE, flat).unwrap(),
                ];
                for _ in 0..5 {
                    let (o, i) = (random_dir(&mut rng), random_dir(&mut rng));
                    let wo = V3::new(x(o.x), x(o.y), x(o.z));
                    let wi = V3::new(x(i.x), x(i.y), x(i.z));
                    let (fw, pw) = (m.eval(wo, wi), m.pdf(wo, wi));
                    for (k, v) in variants.iter().enumerate() {
                        let (fg, pg) = (v.eval(wo, wi), v.pdf(wo, wi));
                        let pairs = [(fg.x, fw.x), (fg.y, fw.y), (fg.z, fw.z), (pg, pw)];
                        for (g, w) in pairs {
                            for l in 0..T::LANES {
                                let (g, w): (f64, f64) = (g.lane(l).into(), w.lane(l).into());
                                assert_eq!(g.to_bits(), w.to_bits(), "variant {k}: {g} vs {w}");
                            }
                        }
                    }
                }
            }
        }
    }
    check(|v| v as f32);
    check(|v| v);
    check(|v| f32x8::splat(v as f32));
    check(f64x4::splat);
}

/// A film far thinner than a wavelength (1e-6 nm: its index is blended to the outside's)
/// reflects as the bare base: the specular lobe becomes F D V with F the exact unpolarized
/// Fresnel reflectance `fresnel::dielectric(v.h, n)` of the base index n read from F0,
/// n = (1 + sqrt(F0)) / (1 - sqrt(F0)), where the material without the film has Schlick's F.
/// Black base colour for the dielectric, so the lobe is alone.
#[cfg(feature = "fresnel")]
#[test]
fn a_vanishing_film_is_the_exact_fresnel_of_the_base_index() {
    use brdf::fresnel;
    let thin = ThinFilm::new(1e-6, 1.3).unwrap();
    let ior = |f0: f64| (1.0 + f0.sqrt()) / (1.0 - f0.sqrt());
    let mut worst: f64 = 0.0;
    let mut schlick_gap: f64 = 0.0;
    for (color, metallic) in [(V3::splat(0.0), 0.0), (V3::new(0.9, 0.6, 0.3), 1.0)] {
        let plain = Layered::new(color, metallic, 0.5).unwrap();
        let film = plain.with_iridescence(1.0, thin).unwrap();
        let f0 = if metallic == 0.0 {
            V3::splat(0.04)
        } else {
            color
        };
        let mut rng = Rng(3);
        for _ in 0..200 {
            let (wo, wi) = (random_dir(&mut rng), random_dir(&mut rng));
            let h = normalize(wo + wi);
            let c = wo.dot(h);
            let w = (1.0 - c).powi(5);
            let (got, base) = (film.eval(wo, wi), plain.eval(wo, wi));
            for (g, b, f0) in [
                (got.x, base.x, f0.x),
                (got.y, base.y, f0.y),
                (got.z, base.z, f0.z),
            ] {
                let schlick = f0 + (1.0 - f0) * w;
                let dv = b / schlick;
                let exact = fresnel::dielectric(c, ior(f0));
                let err = (g - exact * dv).abs() / (exact * dv);
                worst = worst.max(err);
                schlick_gap = schlick_gap.max((schlick - exact).abs() / exact);
            }
        }
    }
    println!(
        "vanishing film vs exact Fresnel: max rel {worst:.2e} (Schlick's gap {schlick_gap:.2e})"
    );
    // 1e-12: with the film's index blended to air the Airy sum is the flat C0 = R23 in X, Y
    // and Z, and the white balance returns it per channel to a few roundings (measured
    // 1.6e-15). Schlick's F is 0.42 away at worst.
    assert!(worst < 1e-12, "{worst}");
    assert!(
        schlick_gap > 10.0 * worst,
        "the test can tell the two Fresnels apart"
    );
}

fn albedo(m: &Layered<f64>, theta: f64, channel: usize) -> f64 {
    directional_albedo(wo_at(theta), |o, i| {
        let f = m.eval(o, i);
        [f.x, f.y, f.z][channel]
    })
    .value
}

#[test]
fn white_furnace_and_layered_albedo_at_most_one() {
    // A white metal reflects 1 under any film (a base of reflectance 1 under a lossless
    // film): compensated, the furnace holds.
    let mut worst: f64 = 0.0;
    for r in [0.3, 1.0] {
        let m = Layered::new(V3::splat(1.0), 1.0, r)
            .and_then(|m| m.with_iridescence(1.0, soap()))
            .unwrap()
            .with_compensation(true);
        for theta in [0.0, 45.0, 80.0] {
            for ch in 0..3 {
                let e = albedo(&m, theta, ch);
                worst = worst.max((e - 1.0).abs());
                assert!((e - 1.0).abs() < 5e-3, "r {r} theta {theta} ch {ch}: {e}");
            }
        }
    }
    println!("iridescent white metal: max |albedo - 1| = {worst:.2e}");
    // Coloured metals and dielectrics with every layer: at most 1 (the dielectric at angles
    // where the glTF coupling itself stays below 1, module docs of `material`).
    let mut top: f64 = 0.0;
    for comp in [false, true] {
        for (metallic, base, angles) in [
            (1.0, V3::new(0.9, 0.6, 0.3), &[0.0, 40.0, 70.0][..]),
            (0.0, V3::splat(0.05), &[0.0, 40.0, 70.0][..]),
            (0.0, V3::splat(1.0), &[0.0, 30.0][..]),
        ] {
            let m = Layered::new(base, metallic, 0.4)
                .and_then(|m| m.with_sheen(V3::splat(0.8), 0.5))
                .and_then(|m| m.with_clearcoat(1.0, 0.3))
                .and_then(|m| m.with_iridescence(1.0, ThinFilm::new(300.0, 1.8).unwrap()))
                .unwrap()
                .with_compensation(comp);
            for &theta in angles {
                for ch in 0..3 {
                    let e = albedo(&m, theta, ch);
                    top = top.max(e);
                    // 2e-3 as in `layered::layered_albedo_is_at_most_one`.
                    assert!(
                        e <= 1.0 + 2e-3,
                        "comp {comp} m {metallic} {theta} {ch}: {e}"
                    );
                }
            }
        }
    }
    println!("iridescent layered albedo: max {top:.5}");
}

#[test]
fn iridescent_material_is_reciprocal() {
    let m = Layered::new(V3::new(0.8, 0.4, 0.2), 0.5, 0.5)
        .and_then(|m| m.with_sheen(V3::splat(0.6), 0.5))
        .and_then(|m| m.with_iridescence(0.8, soap()))
        .unwrap()
        .with_compensation(true);
    for ch in 0..3 {
        let r = reciprocity(|o, i| {
            let f = m.eval(o, i);
            [f.x, f.y, f.z][ch]
        });
        // The film is read at v.h = l.h (the Sample Viewer's n.v would not be reciprocal).
        assert!(r.max_rel < 1e-9, "channel {ch}: {r:?}");
    }
}

fn flip(w: V3<f64>) -> V3<f64> {
    V3::new(w.x, w.y, -w.z)
}

#[test]
fn sampler_matches_its_pdf() {
    // One case (each pdf reads the film twelve times): part metal, so both films count, a
    // coat and a diffuse lobe, so every lobe of the mixture is drawn.
    let cases: [(Layered<f64>, f64); 1] = [(
        Layered::new(V3::new(0.3, 0.6, 0.9), 0.3, 0.7)
            .and_then(|m| m.with_clearcoat(0.6, 0.5))
            .and_then(|m| m.with_iridescence(0.7, ThinFilm::new(250.0, 2.0).unwrap()))
            .unwrap(),
        30.0,
    )];
    for (k, (m, theta)) in cases.iter().enumerate() {
        let wo = wo_at(*theta);
        let folded = |w: V3<f64>| m.pdf(wo, w) + m.pdf(wo, flip(w));
        let stat = chi_square(
            |u1, u2| {
                let (wi, p) = m.sample(wo, u1, u2);
                assert_eq!(p, m.pdf(wo, wi), "returned pdf is pdf(wo, wi)");
                let w = if wi.z < 0.0 { flip(wi) } else { wi };
                (w.into(), folded(w))
            },
            |w| folded(w.into()),
        );
        assert_fits(&format!("iridescent case {k}"), stat);
    }
}

#[test]
fn lanes_follow_scalars() {
    let film64 = soap();
    let m64 = Layered::new(V3::new(0.9, 0.6, 0.3), 0.5, 0.4)
        .and_then(|m| m.with_iridescence(1.0, film64))
        .unwrap()
        .with_compensation(true);
    let m4 = Layered::new(
        V3::new(0.9, 0.6, 0.3).map(f64x4::splat),
        f64x4::splat(0.5),
        f64x4::splat(0.4),
    )
    .and_then(|m| {
        m.with_iridescence(
            f64x4::splat(1.0),
            ThinFilm::new(f64x4::splat(400.0), f64x4::splat(1.3)).unwrap(),
        )
    })
    .unwrap()
    .with_compensation(true);
    let m1 = Layered::new(V3::new(0.9f32, 0.6, 0.3), 0.5, 0.4)
        .and_then(|m| m.with_iridescence(1.0, ThinFilm::new(400.0, 1.3).unwrap()))
        .unwrap()
        .with_compensation(true);
    let m8 = Layered::new(
        V3::new(0.9f32, 0.6, 0.3).map(f32x8::splat),
        f32x8::splat(0.5),
        f32x8::splat(0.4),
    )
    .and_then(|m| {
        m.with_iridescence(
            f32x8::splat(1.0),
            ThinFilm::new(f32x8::splat(400.0), f32x8::splat(1.3)).unwrap(),
        )
    })
    .unwrap()
    .with_compensation(true);
    let mut rng = Rng(9);
    let (mut w64, mut w32): (f64, f64) = (0.0, 0.0);
    for _ in 0..200 {
        let (wo, wi) = (random_dir(&mut rng), random_dir(&mut rng));
        let one = m64.eval(wo, wi);
        let four = m4.eval(wo.map(f64x4::splat), wi.map(f64x4::splat));
        let n = |v: V3<f64>| v.map(|c| c as f32);
        let s = m1.eval(n(wo), n(wi));
        let e = m8.eval(n(wo).map(f32x8::splat), n(wi).map(f32x8::splat));
        for (a, b, c, d) in [
            (one.x, four.x, s.x, e.x),
            (one.y, four.y, s.y, e.y),
            (one.z, four.z, s.z, e.z),
        ] {
            let rel = |p: f64, q: f64| {
                if p == q {
                    0.0
                } else {
                    (p - q).abs() / p.abs().max(q.abs())
                }
            };
            w64 = w64.max(rel(a, b.to_array()[2]));
            w32 = w32.max(rel(f64::from(c), f64::from(d.to_array()[5])));
        }
    }
    println!("iridescent eval: f64x4 vs f64 {w64:.2e}, f32x8 vs f32 {w32:.2e}");
    // The lanes' cos, exp and atan2 are a few ULP from libm's.
    assert!(w64 < 1e-12 && w32 < 1e-4, "{w64} {w32}");
}
