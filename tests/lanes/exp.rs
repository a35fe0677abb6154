//! The f32x8 lane exp (`Real::exp`) is `wide::f32x8::exp`'s algorithm without its
//! data-dependent branches: bit-identical to it on every f32 input. Checked here on every
//! 127th bit pattern (33.8 million values, both signs, NaN, infinities, subnormals), with
//! lanes mixing ordinary and far-negative arguments as a Beckmann D's tail does (the case
//! the branches were slow on). `cargo test --test lanes exp:: -- --nocapture` prints the count.
//!
//! `Real::exp_ftz` is `exp` with results below the smallest normal flushed to 0: checked
//! against exactly that definition on the same patterns, on f32x8 (against the lane exp), f32
//! and f64x4 / f64 (against their exp), so the flush moves no normal result by a single bit.

use brdf::Real;
use brdf::wide::f32x8;

fn same(a: f32, b: f32) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[test]
fn lane_exp_is_bit_identical_to_wides_on_every_127th_bit_pattern() {
    let mut checked = 0u64;
    let mut bits: u64 = 0;
    while bits <= u64::from(u32::MAX) {
        // Eight patterns per vector, the last lane a far-negative argument so that vectors
        // mix a subnormal or zero result with the others.
        let mut lanes = [0.0f32; 8];
        for (l, v) in lanes.iter_mut().enumerate().take(7) {
            *v = f32::from_bits(((bits + 127 * l as u64) & 0xFFFF_FFFF) as u32);
        }
        lanes[7] = -95.0 - (bits % 13) as f32;
        let x = f32x8::new(lanes);
        let ours = Real::exp(x).to_array();
        let theirs = x.exp().to_array();
        for l in 0..8 {
            assert!(
                same(ours[l], theirs[l]),
                "exp({:e}) = {:e}, wide {:e}",
                lanes[l],
                ours[l],
                theirs[l]
            );
        }
        checked += 8;
        bits += 127 * 7;
    }
    println!("{checked} values checked");
    assert!(checked > 30_000_000);
}

#[test]
fn exp_ftz_is_exp_with_subnormal_results_flushed_on_every_127th_bit_pattern() {
    use brdf::wide::f64x4;
    let flush32 = |e: f32| if e < f32::MIN_POSITIVE { 0.0 } else { e };
    let flush64 = |e: f64| if e < f64::MIN_POSITIVE { 0.0 } else { e };
    let mut checked = 0u64;
    let mut bits: u64 = 0;
    while bits <= u64::from(u32::MAX) {
        let mut lanes = [0.0f32; 8];
        for (l, v) in lanes.iter_mut().enumerate().take(7) {
            *v = f32::from_bits(((bits + 127 * l as u64) & 0xFFFF_FFFF) as u32);
        }
        // The last lane sweeps the band where e^x crosses the smallest normal.
        lanes[7] = -87.0 - (bits % 1031) as f32 * (1.0 / 1024.0);
        let x = f32x8::new(lanes);
        let ftz = Real::exp_ftz(x).to_array();
        let exp = Real::exp(x).to_array();
        for l in 0..8 {
            let scalar = Real::exp_ftz(lanes[l]);
            assert!(
                same(ftz[l], flush32(exp[l])) && same(scalar, flush32(libm::expf(lanes[l]))),
                "exp_ftz({:e}) = {:e} (f32x8), {:e} (f32); exp {:e}",
                lanes[l],
                ftz[l],
                scalar,
                exp[l]
            );
        }
        if bits.is_multiple_of(127 * 7 * 8) {
            // f64 lanes on the same values widened and spread over f64's range.
            let wide: [f64; 4] = core::array::from_fn(|l| f64::from(lanes[l]) * 8.0);
            let v = f64x4::new(wide);
            let (ftz, exp) = (Real::exp_ftz(v).to_array(), Real::exp(v).to_array());
            for l in 0..4 {
                let scalar = Real::exp_ftz(wide[l]);
                assert!(
                    (ftz[l].to_bits() == flush64(exp[l]).to_bits()
                        || ftz[l].is_nan() && exp[l].is_nan())
                        && (scalar.to_bits() == flush64(libm::exp(wide[l])).to_bits()
                            || scalar.is_nan() && wide[l].is_nan()),
                    "f64 exp_ftz({:e}) = {:e} (f64x4), {:e} (f64)",
                    wide[l],
                    ftz[l],
                    scalar
                );
            }
        }
        checked += 8;
        bits += 127 * 7;
    }
    println!("{checked} values checked against exp with the flush");
    assert!(checked > 30_000_000);
}

/// On x86-64 the MXCSR flags record, per thread, whether any SSE/AVX instruction met a
/// subnormal operand (DE) or produced a tiny result (UE): each such instruction costs a
/// microcode assist. `exp_ftz` on f32x8 lanes, `beckmann::d_fast` on every lane type and
/// `beckmann::d` and `fresnel::conductor` on `f32` and `f32x8` (evaluated in f64, their
/// subnormal results made from normal ones) raise neither for normal inputs (and 0), across every 127th f32 bit pattern
/// and a (cosine, alpha) grid with cosines from 2^-149 to 1 (for `beckmann::d` also the
/// cosines where D crosses 2^-126 and 2^-149), as does
/// `cook_torrance::ggx_conductor_local` on `f32` and `f32x8` (with the `ggx` feature) for
/// directions at those cosines. This is the only `unsafe` in the crate's tests: reading
/// and clearing the flag register.
#[cfg(all(target_arch = "x86_64", feature = "beckmann", feature = "fresnel"))]
#[test]
#[allow(deprecated)]
fn normal_inputs_meet_no_subnormal_number() {
    use brdf::beckmann;
    use brdf::wide::f64x4;
    use core::arch::x86_64::{_mm_getcsr, _mm_setcsr};
    const DE_UE: u32 = 0x2 | 0x10;
    // SAFETY: reading and writing the status flags of MXCSR (its low six bits) changes no
    // rounding or exception mode.
    let clear = || unsafe { _mm_setcsr(_mm_getcsr() & !0x3f) };
    let flagged = || unsafe { _mm_getcsr() } & DE_UE != 0;
    let mut bits: u64 = 0;
    let mut checked = 0u64;
    while bits <= u64::from(u32::MAX) {
        let lanes: [f32; 8] = core::array::from_fn(|l| {
            let x = f32::from_bits(((bits + 127 * l as u64) & 0xFFFF_FFFF) as u32);
            if x.is_normal() { x } else { 0.0 }
        });
        // black_box orders the evaluation between clearing and reading the flags.
        clear();
        let x = std::hint::black_box(f32x8::new(lanes));
        std::hint::black_box(Real::exp_ftz(x));
        assert!(!flagged(), "exp_ftz({lanes:?}) met a subnormal");
        checked += 8;
        bits += 127 * 8;
    }
    let mut cosines: Vec<f64> = (0..=149).map(|k| 2f64.powi(-k)).collect();
    cosines.extend((1..2000).map(|k| f64::from(k) / 2000.0));
    cosines.extend((1..200).map(|k| 1.0 - 2f64.powi(-k / 8)));
    let alphas: Vec<f64> = (0..=80)
        .map(|k| 10f64.powf(-4.0 + f64::from(k) * 0.1))
        .collect();
    for &a in &alphas {
        for c in cosines.chunks(8) {
            let c32: [f32; 8] = core::array::from_fn(|l| c.get(l).map_or(0.0, |&v| v as f32));
            let c32 = c32.map(|v| if v.is_normal() { v } else { 0.0 });
            clear();
            let (cv, av) = std::hint::black_box((f32x8::new(c32), f32x8::splat(a as f32)));
            std::hint::black_box(beckmann::d_fast(cv, av));
            assert!(!flagged(), "f32x8 d_fast({c32:?}, {a}) met a subnormal");
            clear();
            std::hint::black_box(beckmann::d(cv, av));
            assert!(!flagged(), "f32x8 d({c32:?}, {a}) met a subnormal");
            for &v in &c32 {
                clear();
                let (cs, as_) = std::hint::black_box((v, a as f32));
                std::hint::black_box(beckmann::d(cs, as_));
                assert!(!flagged(), "f32 d({v:e}, {a}) met a subnormal");
            }
            for q in c.chunks(4) {
                let c64: [f64; 4] = core::array::from_fn(|l| q.get(l).copied().unwrap_or(0.0));
                clear();
                let (cv, av) = std::hint::black_box((f64x4::new(c64), <f64x4 as Real>::splat(a)));
                std::hint::black_box(beckmann::d_fast(cv, av));
                assert!(!flagged(), "f64x4 d_fast({c64:?}, {a}) met a subnormal");
            }
            checked += 8;
        }
    }
    // beckmann::d on f32 and f32x8 at the cosines where D crosses 2^-126 (its rounding
    // switches from the converted part to the multiply-add's bits) and 2^-149 (where it
    // rounds to 0), 32 floats on each side, every alpha above.
    for &a in &alphas {
        let d64 = |c: f64| {
            let (c2, a2) = (c * c, a * a);
            (-(1.0 - c2) / (c2 * a2)).exp() / (std::f64::consts::PI * a2 * c2 * c2)
        };
        let peak = (1.0 / (std::f64::consts::SQRT_2 * a)).min(1.0);
        for target in [f64::from(f32::MIN_POSITIVE), 1.401_298_464_324_817e-45] {
            let (mut lo, mut hi) = (1e-30f64, peak);
            for _ in 0..200 {
                let m = 0.5 * (lo + hi);
                if d64(m) < target {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            let c0 = (lo as f32).to_bits();
            for k in (0..64u32).step_by(8) {
                let c32: [f32; 8] =
                    core::array::from_fn(|l| f32::from_bits(c0 + k + l as u32 - 32));
                clear();
                let (cv, av) = std::hint::black_box((f32x8::new(c32), f32x8::splat(a as f32)));
                std::hint::black_box(beckmann::d(cv, av));
                assert!(!flagged(), "f32x8 d({c32:?}, {a}) met a subnormal");
                for &v in &c32 {
                    clear();
                    let (cs, as_) = std::hint::black_box((v, a as f32));
                    std::hint::black_box(beckmann::d(cs, as_));
                    assert!(!flagged(), "f32 d({v:e}, {a}) met a subnormal");
                }
                checked += 8;
            }
        }
    }
    // The exact conductor on f32 and f32x8 (evaluated in f64) where F falls into f32's
    // subnormal range: N within a few ulps of 1, k down to the smallest normal f32.
    let iors: [(f32, f32); 6] = [
        (1.0, 1e-20),
        (1.0, 1e-30),
        (1.0, f32::MIN_POSITIVE),
        (1.000_000_1, 0.0),
        (0.999_999_94, 1e-25),
        (0.2, 3.0),
    ];
    for (eta, k) in iors {
        for c in cosines.chunks(8) {
            let c32: [f32; 8] = core::array::from_fn(|l| c.get(l).map_or(0.0, |&v| v as f32));
            let c32 = c32.map(|v| if v.is_normal() { v } else { 0.0 });
            clear();
            let (cv, ev, kv) =
                std::hint::black_box((f32x8::new(c32), f32x8::splat(eta), f32x8::splat(k)));
            std::hint::black_box(brdf::fresnel::conductor(cv, ev, kv));
            assert!(
                !flagged(),
                "f32x8 conductor({c32:?}, {eta}, {k}) met a subnormal"
            );
            for &v in &c32 {
                clear();
                let (cs, es, ks) = std::hint::black_box((v, eta, k));
                std::hint::black_box(brdf::fresnel::conductor(cs, es, ks));
                assert!(
                    !flagged(),
                    "f32 conductor({v:e}, {eta}, {k}) met a subnormal"
                );
            }
            checked += 8;
        }
    }
    // The rough conductor from directions at those cosines (the view at the cosine, the light
    // at its mirror image about a tilted normal), F near 0 included.
    #[cfg(feature = "ggx")]
    for (eta, k) in iors {
        use brdf::V3;
        use brdf::cook_torrance::ggx_conductor_local;
        use brdf::microfacet::Alpha;
        for c in cosines.chunks(8) {
            let dir = |l: usize, turn: f64| {
                let z = c.get(l).copied().unwrap_or(0.5).max(2f64.powi(-120));
                let s = ((1.0 - z) * (1.0 + z)).sqrt();
                [(s * turn.cos()) as f32, (s * turn.sin()) as f32, z as f32]
            };
            let wo: [[f32; 3]; 8] = core::array::from_fn(|l| dir(l, 0.3));
            let wi: [[f32; 3]; 8] = core::array::from_fn(|l| dir(7 - l, 2.9));
            let v8 = |w: &[[f32; 3]; 8]| {
                V3::new(
                    f32x8::new(w.map(|d| d[0])),
                    f32x8::new(w.map(|d| d[1])),
                    f32x8::new(w.map(|d| d[2])),
                )
            };
            clear();
            let (o, i) = std::hint::black_box((v8(&wo), v8(&wi)));
            let a = Alpha(f32x8::splat(0.3));
            std::hint::black_box(ggx_conductor_local(
                o,
                i,
                a,
                f32x8::splat(eta),
                f32x8::splat(k),
            ));
            assert!(
                !flagged(),
                "f32x8 ggx_conductor_local({eta}, {k}) met a subnormal"
            );
            for l in 0..8 {
                let v3 = |d: [f32; 3]| V3::new(d[0], d[1], d[2]);
                clear();
                let (o, i) = std::hint::black_box((v3(wo[l]), v3(wi[l])));
                std::hint::black_box(ggx_conductor_local(o, i, Alpha(0.3), eta, k));
                assert!(
                    !flagged(),
                    "f32 ggx_conductor_local({o:?}, {i:?}, {eta}, {k}) met a subnormal"
                );
            }
            checked += 8;
        }
    }
    println!("{checked} lane values checked for subnormal operands and results");
}
