//! The rough conductor from the directions (`ggx_conductor_local` and its working-precision
//! tier): on f64 within its documented bound of the generic assembly `conductor` with `Ggx`
//! (an independent route); on f32 within 1 ULP of the f64 tier on the same (f32) directions;
//! the fast tier within its stated relative bound of the exact tier; lanes equal to scalars bit
//! for bit.
#![cfg(all(feature = "ggx", feature = "cook-torrance"))]

use brdf::cook_torrance;
use brdf::ggx::Ggx;
use brdf::microfacet::Alpha;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

use crate::common::Rng;

/// Random unit directions above the horizon (cosines down to 1e-6 half the time), alpha
/// log-uniform over [1e-3, 1], and (eta, k): a measured metal channel half the time,
/// log-uniform over [1e-3, 1e3] otherwise, kept where k >= 0.1 or eta >= 1 (no critical
/// angle, where one rounding of v.h moves F by more than any tier's error).
fn inputs(n: usize) -> Vec<([f64; 6], [f64; 3])> {
    // Seed from BRDF_TEST_SEED, else fixed.
    let seed = std::env::var("BRDF_TEST_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x10ca_1c0d);
    let mut rng = Rng(seed);
    let dir = |rng: &mut Rng| {
        let d = crate::common::random_dir(rng);
        [d.x, d.y, d.z]
    };
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (v, l) = (dir(&mut rng), dir(&mut rng));
        let alpha = libm::pow(10.0, -3.0 * rng.next_f64());
        let (eta, k) = if rng.next_f64() < 0.5 {
            [(0.18, 3.42), (2.76, 3.84), (0.52, 4.84)][(rng.next_f64() * 3.0) as usize % 3]
        } else {
            (
                libm::pow(10.0, 6.0 * rng.next_f64() - 3.0),
                libm::pow(10.0, 6.0 * rng.next_f64() - 3.0),
            )
        };
        if k >= 0.1 || eta >= 1.0 {
            // The directions as f32 values, so that both precisions read the same numbers.
            let d = [v[0], v[1], v[2], l[0], l[1], l[2]].map(|x| f64::from(x as f32));
            out.push((d, [alpha, eta, k].map(|x| f64::from(x as f32))));
        }
    }
    out
}

fn eval<T: Real>(d: [f64; 6], p: [f64; 3], fast: bool) -> T {
    let s = |x: f64| T::splat(x);
    let (wo, wi) = (
        V3::new(s(d[0]), s(d[1]), s(d[2])),
        V3::new(s(d[3]), s(d[4]), s(d[5])),
    );
    if fast {
        cook_torrance::ggx_conductor_local_fast(wo, wi, Alpha(s(p[0])), s(p[1]), s(p[2]))
    } else {
        cook_torrance::ggx_conductor_local(wo, wi, Alpha(s(p[0])), s(p[1]), s(p[2]))
    }
}

/// f32 ULP distance, with the spacing of f32 at |r| (subnormal spacing below 2^-126).
fn ulp32(x: f32, r: f64) -> f64 {
    let e = libm::floor(libm::log2(r.abs().max(f64::from(f32::MIN_POSITIVE))));
    (f64::from(x) - r).abs() / libm::exp2(e - 23.0)
}

/// On f64 against the generic assembly `conductor` with `Ggx` (D of the normalized h in double
/// words, V from the vectors' components, h from `half_vector`): an independent route that
/// agrees where the directions are unit vectors to f64's precision, within the documented
/// 1e-14 relative where |wo + wi| >= 1/8 (the plain f64 D V carries about twenty roundings of
/// 2^-53; F is the same kernel). Nearer opposite directions both routes round the sum
/// wo + wi of f64 components, h moves by up to about 2^-52 / |wo + wi| radians and D by up
/// to 2 / alpha relative per radian: there the bound is 1e-14 + 4e-16 (1 + 2 / alpha) /
/// |wo + wi|.
#[test]
fn local_f64_agrees_with_the_generic_assembly() {
    let (mut worst, mut worst_near) = (0.0f64, 0.0f64);
    for (d, p) in inputs(50_000) {
        // Exactly unit (to f64 rounding) versions of the f32 directions.
        let unit = |w: [f64; 3]| {
            let n = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
            V3::new(w[0] / n, w[1] / n, w[2] / n)
        };
        let (wo, wi) = (unit([d[0], d[1], d[2]]), unit([d[3], d[4], d[5]]));
        let m = Ggx::isotropic(p[0]).unwrap();
        let want = cook_torrance::conductor(&m, wo, wi, p[1], p[2]);
        let got = cook_torrance::ggx_conductor_local(wo, wi, Alpha(p[0]), p[1], p[2]);
        if want.is_normal() && want < 1e300 {
            let rel = (got / want - 1.0).abs();
            let sum = (wo + wi).length();
            if sum >= 0.125 {
                worst = worst.max(rel);
            } else {
                let bound = 1e-14 + 4e-16 * (1.0 + 2.0 / p[0]) / sum;
                assert!(rel <= bound, "{rel:e} at |wo + wi| = {sum:e}: {d:?} {p:?}");
                worst_near = worst_near.max(rel * sum);
            }
        }
    }
    println!(
        "ggx_conductor_local f64 against the generic assembly: max relative {worst:.3e} \
         (|wo + wi| >= 1/8), max relative times |wo + wi| {worst_near:.3e} elsewhere"
    );
    assert!(worst <= 1e-14, "{worst:e}");
}

/// The f32 result (the formulas evaluated in f64 and rounded once) against the f64 tier on the
/// same directions, whose own error is below 1e-14 relative: 1 ULP, as documented (0.5 for the
/// rounding, the rest for the f64 tier's error).
#[test]
fn local_f32_within_one_ulp_of_the_f64_tier() {
    let mut worst = 0.0f64;
    for (d, p) in inputs(200_000) {
        let got = eval::<f32>(d, p, false);
        let want = eval::<f64>(d, p, false);
        if want > f64::from(f32::MAX) {
            assert_eq!(got, f32::MAX, "{d:?} {p:?}");
            continue;
        }
        let u = ulp32(got, want);
        assert!(u <= 1.0, "{u} ULP at {d:?} {p:?}: {got:e} vs {want:e}");
        worst = worst.max(u);
    }
    println!("ggx_conductor_local f32 against f64: max {worst:.3} ULP");
}

/// The working-precision tier's relative error against the exact tier in f32 and f64 where the
/// exact value is a normal number, D V below the cap, and both cosines at least 1e-3 (the
/// documented bounds: 3e-6 in f32, 4e-15 in f64; the largest found over 30 seeds,
/// `BRDF_TEST_SEED=1` to `30`, 1.8e-6 and 2.3e-15).
#[test]
fn local_fast_within_its_bound_of_the_exact_tier() {
    let mut worst = [0.0f64; 2];
    for (d, p) in inputs(200_000) {
        if d[2].min(d[5]) < 1e-3 {
            continue;
        }
        let (f, e) = (eval::<f32>(d, p, true), eval::<f32>(d, p, false));
        if e.is_normal() && e < 1e30 {
            worst[0] = worst[0].max((f64::from(f) / f64::from(e) - 1.0).abs());
        }
        let (f, e) = (eval::<f64>(d, p, true), eval::<f64>(d, p, false));
        if e.is_normal() && e < 1e300 {
            worst[1] = worst[1].max((f / e - 1.0).abs());
        }
    }
    println!(
        "ggx_conductor_local_fast: max relative error {:.3e} (f32), {:.3e} (f64)",
        worst[0], worst[1]
    );
    assert!(worst[0] <= 3e-6 && worst[1] <= 4e-15, "{worst:?}");
}

#[test]
fn local_lanes_equal_scalars_bit_for_bit() {
    let all = inputs(4_000);
    for fast in [false, true] {
        for chunk in all.chunks_exact(8) {
            let d8 = |j: usize| f32x8::new(core::array::from_fn(|i| chunk[i].0[j] as f32));
            let p8 = |j: usize| f32x8::new(core::array::from_fn(|i| chunk[i].1[j] as f32));
            let (wo, wi) = (V3::new(d8(0), d8(1), d8(2)), V3::new(d8(3), d8(4), d8(5)));
            let out = if fast {
                cook_torrance::ggx_conductor_local_fast(wo, wi, Alpha(p8(0)), p8(1), p8(2))
            } else {
                cook_torrance::ggx_conductor_local(wo, wi, Alpha(p8(0)), p8(1), p8(2))
            };
            for (i, (d, p)) in chunk.iter().enumerate() {
                assert_eq!(
                    out.to_array()[i].to_bits(),
                    eval::<f32>(*d, *p, fast).to_bits()
                );
            }
        }
        for chunk in all.chunks_exact(4) {
            let d4 = |j: usize| f64x4::new(core::array::from_fn(|i| chunk[i].0[j]));
            let p4 = |j: usize| f64x4::new(core::array::from_fn(|i| chunk[i].1[j]));
            let (wo, wi) = (V3::new(d4(0), d4(1), d4(2)), V3::new(d4(3), d4(4), d4(5)));
            let out = if fast {
                cook_torrance::ggx_conductor_local_fast(wo, wi, Alpha(p4(0)), p4(1), p4(2))
            } else {
                cook_torrance::ggx_conductor_local(wo, wi, Alpha(p4(0)), p4(1), p4(2))
            };
            for (i, (d, p)) in chunk.iter().enumerate() {
                assert_eq!(
                    out.to_array()[i].to_bits(),
                    eval::<f64>(*d, *p, fast).to_bits()
                );
            }
        }
    }
}

/// The f32 tier against the f64 tier at the edges of the domain: grazing directions (cosines
/// down to 2^-120), nearly opposite directions (|wo + wi| down to about 2^-60), wo = wi
/// (c = 1), alpha near both clamps, eta and k from the smallest normal f32 to f32::MAX with eta
/// within 2^-20 of 1: within 1 ULP where F is well conditioned (k >= 0.1 or eta >= 1, as
/// `inputs`), and finite and non-negative everywhere (the largest ULP distance found is
/// printed).
#[test]
fn local_f32_within_one_ulp_of_the_f64_tier_at_the_extremes() {
    let etas = [
        f64::from(f32::MIN_POSITIVE),
        1e-10,
        1e-4,
        0.05,
        0.2,
        1.0 - libm::exp2(-20.0),
        1.0,
        1.0 + libm::exp2(-20.0),
        1.5,
        10.0,
        1e4,
        1e10,
        1e30,
        f64::from(f32::MAX),
    ];
    let ks = [
        0.0,
        f64::from(f32::MIN_POSITIVE),
        1e-10,
        1e-3,
        0.1,
        1.0,
        3.0,
        1e4,
        1e10,
        1e30,
        f64::from(f32::MAX),
    ];
    // Just above ALPHA_MIN: 1e-4 itself rounds below it in f32, which the f32 tier clamps
    // to f32(1e-4) and the f64 tier to 1e-4 (D V moves by 7.6e-8 between the two).
    let alphas = [1.001e-4, 1e-3, 0.3, 1.0, 1e4];
    // Direction pairs: (z of wo, z of wi, azimuth between them).
    let mut pairs = Vec::new();
    for zo in [
        libm::exp2(-120.0),
        libm::exp2(-60.0),
        1e-6,
        0.01,
        0.3,
        0.9,
        1.0,
    ] {
        for zi in [libm::exp2(-120.0), libm::exp2(-30.0), 1e-6, 0.2, 0.7, 1.0] {
            for phi in [
                0.0,
                1e-7,
                0.5,
                2.0,
                core::f64::consts::PI - 1e-7,
                core::f64::consts::PI,
            ] {
                pairs.push((zo, zi, phi));
            }
        }
    }
    let dir = |z: f64, phi: f64| {
        let s = libm::sqrt((1.0 - z) * (1.0 + z));
        [s * libm::cos(phi), s * libm::sin(phi), z].map(|x| f64::from(x as f32))
    };
    let (mut worst, mut checked) = (0.0f64, 0usize);
    for &(zo, zi, phi) in &pairs {
        let (o, i) = (dir(zo, 0.4), dir(zi, 0.4 + phi));
        let d = [o[0], o[1], o[2], i[0], i[1], i[2]];
        for &alpha in &alphas {
            for &eta in &etas {
                for &k in &ks {
                    let p = [alpha, eta, k].map(|x| f64::from(x as f32));
                    let got = eval::<f32>(d, p, false);
                    assert!(got.is_finite() && got >= 0.0, "{got} at {d:?} {p:?}");
                    if !(k >= 0.1 || eta >= 1.0) {
                        continue;
                    }
                    let want = eval::<f64>(d, p, false);
                    if want > f64::from(f32::MAX) {
                        assert_eq!(got, f32::MAX, "{d:?} {p:?}");
                        continue;
                    }
                    let u = ulp32(got, want);
                    assert!(u <= 1.0, "{u} ULP at {d:?} {p:?}: {got:e} vs {want:e}");
                    worst = worst.max(u);
                    checked += 1;
                }
            }
        }
    }
    println!(
        "ggx_conductor_local f32 against f64 at the extremes: max {worst:.4} ULP over {checked}"
    );
}

/// A conductor with |N| below 2^-27 (Re(N^2) - 1 rounds to -1 in f64) at and near normal
/// incidence, where F = |(1 - N) / (1 + N)|^2 is close to 1 and well conditioned in the
/// direction: the f32 tier within 1 ULP of the f64 tier, whose F comes from the cosine by
/// another route (`fresnel::conductor`). The projection form once lost Re(N^2) there, found
/// y z = 0 at normal incidence and returned 0 / 0 (which its rounding to f32 turned into the
/// smallest normal number).
#[test]
fn local_f32_tiny_n_at_normal_incidence() {
    let tilts = [0.0, 1e-7, 1e-4, 0.01, 0.1];
    let mut worst = 0.0f64;
    for eta in [f64::from(f32::MIN_POSITIVE), 1e-30, 1e-10, 3e-9, 1e-8] {
        for k in [0.0, f64::from(f32::MIN_POSITIVE), 1e-12, 1e-9] {
            for &to in &tilts {
                for &ti in &tilts {
                    let dir = |t: f64, phi: f64| {
                        let z = libm::cos(t);
                        let s = libm::sin(t);
                        [s * libm::cos(phi), s * libm::sin(phi), z].map(|x| f64::from(x as f32))
                    };
                    let (o, i) = (dir(to, 0.3), dir(ti, 2.1));
                    let d = [o[0], o[1], o[2], i[0], i[1], i[2]];
                    for alpha in [1e-3, 0.3, 1.0] {
                        let p = [alpha, eta, k].map(|x| f64::from(x as f32));
                        let got = eval::<f32>(d, p, false);
                        let want = eval::<f64>(d, p, false);
                        assert!(want.is_finite() && want > 0.0, "{want} at {d:?} {p:?}");
                        let u = ulp32(got, want);
                        assert!(u <= 1.0, "{u} ULP at {d:?} {p:?}: {got:e} vs {want:e}");
                        worst = worst.max(u);
                    }
                }
            }
        }
    }
    println!(
        "ggx_conductor_local f32 against f64, |N| < 2^-26 near normal incidence: max {worst:.4} ULP"
    );
}
