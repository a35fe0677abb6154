//! Every f32 input of the one-argument functions: the display transfer functions of
//! `brdf::color`, `fresnel::f0_from_ior`, and the tone curves on one channel (or on a grey,
//! for the operators on a colour), on `f32` and on each lane of `f32x8`.
//!
//! # Reference
//! MPFR at 256 bits costs microseconds a point, too slow for 2^31 inputs on two cores. Each
//! function's published formula is written again here in f64 with std's math (glibc's `pow`,
//! `exp`, `expm1`, which are within 1 f64 ulp), arranged so that no step cancels: a few f64
//! roundings, each 2^-53 relative, are 2^-29 of an f32 ulp, and the worst amplification
//! (a `pow` whose exponent, rounded to f64, meets |ln x| up to 89, and sRGB's subtraction of
//! 0.055, which loses 1.3 bits near its breakpoint) keeps the reference within about 3e-7 f32
//! ulp of the exact value. [`f64_references_agree_with_mpfr`] checks that bound against the
//! MPFR references of `brdf_oracle` on a few thousand points per function (log-uniform over
//! the domain, the breakpoints and their neighbours): agreement to 1e-6 f32 ulp, so the
//! measured errors below are exact to that.
//!
//! # Scoring
//! As in `brdf_oracle::harness`: |y - ref| in ulps of the binade of ref rounded to f32; a
//! result below 1e-30 is checked absolutely (|y - ref| <= 1e-30); a result that overflows
//! f32 passes when y is +inf or f32::MAX (the crate caps poles and overflows at MAX).
//!
//! # Domain
//! Each function's documented domain: every non-negative f32 up to the largest finite one for
//! the transfer functions (+-inf give NaN there, the crate's rule 5, checked apart) and up to
//! +inf for the tone curves (their inputs above `tonemap::MAX_INPUT` = 1e9 are clamped
//! to it, and the reference applies that documented clamp), (0, MAX] for `f0_from_ior`.
//! Negative inputs are a documented clamp to 0 (their result is f(0)): the full sweep checks
//! every 1024th negative f32 (and -0, -inf, the smallest negative), not all 2^31.
//!
//! The full sweep (#[ignore], both cores):
//! `cargo test -p brdf-oracle --release --test exhaustive_f32 -- --ignored --nocapture`.
//! The default run checks every 4096th f32 bit pattern, the domain ends and every power of
//! two with its neighbouring floats, in a few seconds.

use brdf::tonemap::{self, HableParams, LottesParams, UchimuraParams};
use brdf::wide::f32x8;
use brdf::{Real, V3, color, fresnel};
use brdf_oracle::reference as r;
use brdf_oracle::reference::num;
use brdf_oracle::tonemap_ref as t;
use rug::Float;

/// The crate's promise for every exact function.
const BOUND: f64 = 4.0;

/// The documented bound of `color::srgb_oetf_fast` on [0, 1] (a single `pow` in the input's
/// precision, whose exponent 1/2.4 is rounded to f32).
const FAST_BOUND: f64 = 5.0;

/// Its documented bound above 1, where the exponent's rounding is multiplied by ln x (up to
/// 88.7 at f32::MAX).
const FAST_BOUND_ABOVE_1: f64 = 17.0;

/// One function under test.
struct Fun {
    name: &'static str,
    /// The f32 kernel.
    f32: fn(f32) -> f32,
    /// The f32x8 kernel.
    f32x8: fn(f32x8) -> f32x8,
    /// The independent f64 reference of the published formula, on the input as given
    /// (negative and large inputs included: it applies the documented clamps).
    reference: fn(f64) -> f64,
    /// The MPFR reference (within the formula's domain, before any input clamp).
    mpfr: fn(&Float) -> Float,
    /// Smallest and largest bit pattern of the non-negative domain.
    bits: (u32, u32),
    /// Whether negative inputs are in the documented domain (clamped to 0).
    negatives: bool,
    /// The bound asserted.
    bound: f64,
    /// The documented input clamp above which the result is f(clamp) (`MAX_INPUT` for the
    /// tone curves, +inf otherwise): the reference there is evaluated once.
    clamp: f64,
    /// Whether +-inf are clamped inputs (the tone curves clamp them like any other input,
    /// `tonemap::sanitize`); elsewhere an infinity is outside the domain and gives NaN (the
    /// crate's rule 5), checked by [`infinities_outside_the_domain_give_nan`].
    infinities_clamped: bool,
}

const INF_BITS: u32 = 0x7f80_0000;

/// min(max(x, 0), 1e9): the tone curves' documented input clamp (`tonemap::sanitize`).
fn sanitize(x: f64) -> f64 {
    x.clamp(0.0, tonemap::MAX_INPUT)
}

fn saturate(x: f64) -> f64 {
    x.clamp(0.0, 1.0)
}

// ---- f64 references, each the published formula -------------------------------------------

/// IEC 61966-2-1 sRGB OETF: 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055.
/// The f64 nearest 0.0031308 lies below it with no f64 between, so `<=` on f64 decides
/// every f32 as the real threshold does.
fn srgb_oetf_ref(x: f64) -> f64 {
    let x = x.max(0.0);
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// `srgb_oetf_fast`'s documented definition: the same pieces, the threshold compared in
/// f32 (the f32 nearest 0.0031308 lies above it and takes the linear piece).
fn srgb_oetf_fast_ref(x: f64) -> f64 {
    let x = x.max(0.0);
    if x as f32 <= 0.003_130_8_f32 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// IEC 61966-2-1 sRGB EOTF: x / 12.92 for x <= 0.04045, else ((x + 0.055) / 1.055)^2.4.
fn srgb_eotf_ref(x: f64) -> f64 {
    let x = x.max(0.0);
    if x <= 0.040_45 {
        x / 12.92
    } else {
        ((x + 0.055) / 1.055).powf(2.4)
    }
}

/// ITU-R BT.709-6 OETF: 4.5 L for L < 0.018, else 1.099 L^0.45 - 0.099.
fn rec709_oetf_ref(l: f64) -> f64 {
    let l = l.max(0.0);
    if l < 0.018 {
        4.5 * l
    } else {
        1.099 * l.powf(0.45) - 0.099
    }
}

/// F0 = ((eta - 1) / (eta + 1))^2.
fn f0_ref(eta: f64) -> f64 {
    let q = (eta - 1.0) / (eta + 1.0);
    q * q
}

/// 1 - exp(-x e) with e = 1, as -expm1(-x) (no cancellation for small x).
fn exposure_ref(x: f64) -> f64 {
    saturate(-(-sanitize(x)).exp_m1())
}

/// Reinhard et al. 2002 eq. 3: x / (1 + x).
fn reinhard_ref(x: f64) -> f64 {
    let x = sanitize(x);
    saturate(x / (1.0 + x))
}

/// The white point of the fixed-parameter extended Reinhard curves (`Operator::all`'s).
const WHITE: f64 = 4.0;

/// Reinhard et al. 2002 eq. 4: x (1 + x / w^2) / (1 + x), w = 4.
fn reinhard_extended_ref(x: f64) -> f64 {
    let x = sanitize(x);
    saturate(x * (1.0 + x / (WHITE * WHITE)) / (1.0 + x))
}

/// Narkowicz 2015: x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14) (every term positive).
fn narkowicz_ref(x: f64) -> f64 {
    let x = sanitize(x);
    saturate(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14))
}

/// Hable 2010's F(x) = (x (A x + C B) + D E) / (x (A x + B) + D F) - E / F over one
/// denominator, x ((F - E) A x + B (F C - E)) / (F (x (A x + B) + D F)), an identity that
/// removes the cancellation of its two terms for small x.
fn hable_f(x: f64) -> f64 {
    let h = HableParams::UNCHARTED2;
    let (a, b, c, d, e, f) = (h.a, h.b, h.c, h.d, h.e, h.f);
    x * ((f - e) * a * x + b * (f * c - e)) / (f * (x * (a * x + b) + d * f))
}

/// Hable 2010, Uncharted 2 values: F(2 x) / F(11.2).
fn hable_ref(x: f64) -> f64 {
    let h = HableParams::UNCHARTED2;
    saturate(hable_f(h.exposure_bias * sanitize(x)) / hable_f(h.white))
}

/// Lottes 2016's x^a / (x^(a d) b + c), b and c solving f(mid_in) = mid_out and
/// f(hdr_max) = 1 (the talk's derivation), default curve.
fn lottes_ref(x: f64) -> f64 {
    let l = LottesParams::default_curve();
    let (a, d, hm, mi, mo) = (l.contrast, l.shoulder, l.hdr_max, l.mid_in, l.mid_out);
    let ad = a * d;
    let den = (hm.powf(ad) - mi.powf(ad)) * mo;
    let b = (-mi.powf(a) + hm.powf(a) * mo) / den;
    let c = (hm.powf(ad) * mi.powf(a) - hm.powf(a) * mi.powf(ad) * mo) / den;
    let x = sanitize(x);
    if x == 0.0 {
        return 0.0;
    }
    saturate(x.powf(a) / (x.powf(ad) * b + c))
}

/// Uchimura 2017's GT curve, Gran Turismo values (the talk's listing).
fn uchimura_ref(x: f64) -> f64 {
    let u = UchimuraParams::GRAN_TURISMO;
    let (pm, a, m, l, c, b) = (
        u.max_brightness,
        u.contrast,
        u.linear_start,
        u.linear_length,
        u.black,
        u.pedestal,
    );
    let x = sanitize(x);
    let l0 = (pm - m) * l / a;
    let s0 = m + l0;
    let s1 = m + a * l0;
    let c2 = a * pm / (pm - s1);
    let cp = -c2 / pm;
    let tt = (x / m).clamp(0.0, 1.0);
    let smooth = tt * tt * (3.0 - 2.0 * tt);
    let w0 = 1.0 - smooth;
    let w2 = if x >= s0 { 1.0 } else { 0.0 };
    // 1 - w0 - w2 as smooth - w2 (equal; no cancellation of 1 - (1 - smooth)).
    let w1 = smooth - w2;
    let toe = m * (x.min(m) / m).powf(c) + b;
    let shoulder = pm - (pm - s1) * (cp * (x - s0)).exp();
    let linear = m + a * (x - m);
    saturate(toe * w0 + linear * w1 + shoulder * w2)
}

/// Khronos PBR Neutral on a grey (x, x, x): offset x - 6.25 x^2 below 0.08, else 0.04; the
/// grey minus it, p (6.25 x^2 below 0.08, exactly, since x - (x - 6.25 x^2) is that); below
/// 0.76 p itself, else every channel is p_n = 1 - 0.0576 / (p - 0.52) (the mix of
/// c p_n / p = p_n and p_n).
fn pbr_neutral_ref(x: f64) -> f64 {
    let x = sanitize(x);
    let p = if x < 0.08 { 6.25 * x * x } else { x - 0.04 };
    if p < 0.76 {
        p
    } else {
        saturate(1.0 - 0.0576 / (p - 0.52))
    }
}

/// Reinhard-Jodie on a grey: L = (0.2126 + 0.7152 + 0.0722) x = x, so
/// lerp(x / (1 + L), t, t) = t = x / (1 + x).
fn jodie_grey_ref(x: f64) -> f64 {
    reinhard_ref(x)
}

// ---- MPFR references -------------------------------------------------------------------

fn hable_mpfr(x: &Float) -> Float {
    let h = HableParams::UNCHARTED2;
    let p = x.prec();
    let k = [h.a, h.b, h.c, h.d, h.e, h.f].map(|v| num(p, v));
    t::hable(x, &k, &num(p, h.white), &num(p, h.exposure_bias))
}

fn lottes_mpfr(x: &Float) -> Float {
    let l = LottesParams::default_curve();
    let p = x.prec();
    t::lottes(
        x,
        &num(p, l.contrast),
        &num(p, l.shoulder),
        &num(p, l.hdr_max),
        &num(p, l.mid_in),
        &num(p, l.mid_out),
    )
}

fn uchimura_mpfr(x: &Float) -> Float {
    brdf_oracle::tonemap_cases::ref_uchimura(std::slice::from_ref(x))
}

fn grey<T: Real>(x: T) -> V3<T> {
    V3::new(x, x, x)
}

/// A function on every f32 (negatives clamped to 0) with the 4-ULP bound.
fn tm(
    name: &'static str,
    f32: fn(f32) -> f32,
    f32x8: fn(f32x8) -> f32x8,
    reference: fn(f64) -> f64,
    mpfr: fn(&Float) -> Float,
) -> Fun {
    let tone = name.starts_with("tonemap");
    Fun {
        name,
        f32,
        f32x8,
        reference,
        mpfr,
        bits: (0, if tone { INF_BITS } else { INF_BITS - 1 }),
        negatives: true,
        bound: BOUND,
        clamp: if tone {
            tonemap::MAX_INPUT
        } else {
            f64::INFINITY
        },
        infinities_clamped: tone,
    }
}

fn all() -> Vec<Fun> {
    vec![
        tm(
            "color::srgb_oetf",
            color::srgb_oetf,
            color::srgb_oetf,
            srgb_oetf_ref,
            r::srgb_oetf,
        ),
        Fun {
            bound: FAST_BOUND,
            bits: (0, 1f32.to_bits()),
            ..tm(
                "color::srgb_oetf_fast",
                color::srgb_oetf_fast,
                color::srgb_oetf_fast,
                srgb_oetf_fast_ref,
                r::srgb_oetf,
            )
        },
        Fun {
            bound: FAST_BOUND_ABOVE_1,
            bits: (1f32.to_bits() + 1, INF_BITS - 1),
            negatives: false,
            ..tm(
                "color::srgb_oetf_fast (above 1)",
                color::srgb_oetf_fast,
                color::srgb_oetf_fast,
                srgb_oetf_fast_ref,
                r::srgb_oetf,
            )
        },
        tm(
            "color::srgb_eotf",
            color::srgb_eotf,
            color::srgb_eotf,
            srgb_eotf_ref,
            r::srgb_eotf,
        ),
        tm(
            "color::rec709_oetf",
            color::rec709_oetf,
            color::rec709_oetf,
            rec709_oetf_ref,
            r::rec709_oetf,
        ),
        Fun {
            bits: (1, f32::MAX.to_bits()),
            negatives: false,
            ..tm(
                "fresnel::f0_from_ior",
                fresnel::f0_from_ior,
                fresnel::f0_from_ior,
                f0_ref,
                r::f0_from_ior,
            )
        },
        tm(
            "tonemap::exposure_curve (e = 1)",
            |x| tonemap::exposure_curve(x, 1.0),
            |x| tonemap::exposure_curve(x, f32x8::splat(1.0)),
            exposure_ref,
            |x| t::exposure_curve(x, &num(x.prec(), 1.0)),
        ),
        tm(
            "tonemap::reinhard",
            tonemap::reinhard,
            tonemap::reinhard,
            reinhard_ref,
            t::reinhard,
        ),
        tm(
            "tonemap::reinhard_extended (w = 4)",
            |x| tonemap::reinhard_extended(x, 4.0),
            |x| tonemap::reinhard_extended(x, f32x8::splat(4.0)),
            reinhard_extended_ref,
            |x| t::reinhard_extended(x, &num(x.prec(), WHITE)),
        ),
        tm(
            "tonemap::aces_narkowicz",
            tonemap::aces_narkowicz,
            tonemap::aces_narkowicz,
            narkowicz_ref,
            t::aces_narkowicz,
        ),
        tm(
            "tonemap::hable",
            |x| tonemap::hable(x, &HableParams::UNCHARTED2),
            |x| tonemap::hable(x, &HableParams::UNCHARTED2),
            hable_ref,
            hable_mpfr,
        ),
        tm(
            "tonemap::lottes",
            |x| tonemap::lottes(x, &LottesParams::default_curve()),
            |x| tonemap::lottes(x, &LottesParams::default_curve()),
            lottes_ref,
            lottes_mpfr,
        ),
        tm(
            "tonemap::uchimura",
            |x| tonemap::uchimura(x, &UchimuraParams::GRAN_TURISMO),
            |x| tonemap::uchimura(x, &UchimuraParams::GRAN_TURISMO),
            uchimura_ref,
            uchimura_mpfr,
        ),
        tm(
            "tonemap::pbr_neutral (grey)",
            |x| tonemap::pbr_neutral(grey(x)).x,
            |x| tonemap::pbr_neutral(grey(x)).x,
            pbr_neutral_ref,
            |x| t::pbr_neutral([x, x, x])[0].clone(),
        ),
        tm(
            "tonemap::reinhard_jodie (grey)",
            |x| tonemap::reinhard_jodie(grey(x)).x,
            |x| tonemap::reinhard_jodie(grey(x)).x,
            jodie_grey_ref,
            |x| t::reinhard_jodie([x, x, x])[0].clone(),
        ),
        tm(
            "tonemap::reinhard_luminance (grey)",
            |x| tonemap::reinhard_luminance(grey(x)).x,
            |x| tonemap::reinhard_luminance(grey(x)).x,
            reinhard_ref,
            |x| t::reinhard_luminance([x, x, x])[0].clone(),
        ),
        tm(
            "tonemap::reinhard_extended_luminance (grey, w = 4)",
            |x| tonemap::reinhard_extended_luminance(grey(x), 4.0).x,
            |x| tonemap::reinhard_extended_luminance(grey(x), f32x8::splat(4.0)).x,
            reinhard_extended_ref,
            |x| t::reinhard_extended_luminance([x, x, x], &num(x.prec(), WHITE))[0].clone(),
        ),
    ]
}

/// The error of `y` against `exact` in f32 ulps of the binade of `exact` rounded to f32, as
/// `brdf_oracle::harness` scores it: 0 for a tiny result within 1e-30 and for an overflowing
/// one capped at MAX or inf, +inf for any other failure.
fn ulp_error(y: f32, exact: f64) -> f64 {
    let rounded = exact as f32;
    let y64 = f64::from(y);
    if rounded.is_infinite() {
        let capped = y.abs() >= f32::MAX && y.signum() as f64 == exact.signum();
        return if capped { 0.0 } else { f64::INFINITY };
    }
    if exact.abs() < 1e-30 {
        let ok = y.is_finite() && (y64 - exact).abs() <= 1e-30;
        return if ok { 0.0 } else { f64::INFINITY };
    }
    if !y.is_finite() {
        return f64::INFINITY;
    }
    // rounded = m 2^e with m in [1, 2): its binade's ulp is 2^(e - 23).
    let e = ((rounded.abs().to_bits() >> 23) & 0xff) as i32 - 127;
    (y64 - exact).abs() / 2f64.powi(e - 23)
}

/// Worst figures of one function.
#[derive(Clone, Copy, Default, Debug)]
struct Worst {
    scalar: f64,
    scalar_at: f32,
    lanes: f64,
    lanes_at: f32,
    points: u64,
}

impl Worst {
    fn merge(&mut self, o: &Worst) {
        if o.scalar > self.scalar || self.scalar.is_nan() {
            self.scalar = o.scalar;
            self.scalar_at = o.scalar_at;
        }
        if o.lanes > self.lanes || self.lanes.is_nan() {
            self.lanes = o.lanes;
            self.lanes_at = o.lanes_at;
        }
        self.points += o.points;
    }
}

/// Evaluates `f` on `xs` (scalar on each, lanes in groups of 8 with the last padded).
fn eval(f: &Fun, xs: &[f32], w: &mut Worst) {
    let top = (f.reference)(f.clamp);
    for chunk in xs.chunks(8) {
        let lanes = (f.f32x8)(f32x8::from_fn(|i| chunk[i.min(chunk.len() - 1)]));
        for (i, &x) in chunk.iter().enumerate() {
            let x64 = f64::from(x);
            let exact = if x64 >= f.clamp {
                top
            } else {
                (f.reference)(x64)
            };
            let es = ulp_error((f.f32)(x), exact);
            let el = ulp_error(lanes.lane(i), exact);
            // Never NaN: `ulp_error` scores a failure as +inf.
            if es > w.scalar {
                w.scalar = es;
                w.scalar_at = x;
            }
            if el > w.lanes {
                w.lanes = el;
                w.lanes_at = x;
            }
            w.points += 1;
        }
    }
}

/// The inputs of `f` among the bit patterns lo, lo + stride, ... up to hi, then the domain
/// ends and every power of two with its two neighbours either side (those in the domain),
/// and the negatives -0, -smallest, -1, -MAX, -inf where they are in the domain.
fn slice(f: &Fun, stride: u32) -> Vec<f32> {
    let (lo, hi) = f.bits;
    let mut v: Vec<f32> = (lo..=hi)
        .step_by(stride as usize)
        .map(f32::from_bits)
        .collect();
    v.extend([f32::from_bits(lo), f32::from_bits(hi)]);
    for e in -149..=127 {
        let p = 2f32.powi(e);
        let b = p.to_bits();
        for d in [-2i64, -1, 0, 1, 2] {
            let q = i64::from(b) + d;
            if q >= i64::from(lo) && q <= i64::from(hi) {
                v.push(f32::from_bits(q as u32));
            }
        }
    }
    if f.negatives {
        v.extend([-0.0, -f32::from_bits(1), -1.0, -f32::MAX]);
        if f.infinities_clamped {
            v.push(f32::NEG_INFINITY);
        }
    }
    v
}

/// Rule 5 of the crate's bad-input rule: where an infinity is not a clamped input (the
/// transfer functions, `f0_from_ior`), +-inf give NaN, on `f32` and on every lane.
#[test]
fn infinities_outside_the_domain_give_nan() {
    let mut checked = 0;
    for f in all().into_iter().filter(|f| !f.infinities_clamped) {
        for x in [f32::INFINITY, f32::NEG_INFINITY] {
            let y = (f.f32)(x);
            let lanes = (f.f32x8)(f32x8::splat(x)).to_array();
            assert!(
                y.is_nan() && lanes.iter().all(|l| l.is_nan()),
                "{}({x}) = {y}, lanes {lanes:?}: want NaN",
                f.name
            );
            checked += 1;
        }
    }
    assert!(checked >= 10, "{checked}");
}

fn report(name: &str, w: &Worst, bound: f64) -> Option<String> {
    println!(
        "{name:50} f32 {:8.4} at {:e} ({:#010x})   f32x8 {:8.4} at {:e}   {} inputs",
        w.scalar,
        w.scalar_at,
        w.scalar_at.to_bits(),
        w.lanes,
        w.lanes_at,
        w.points
    );
    // `!(e <= bound)` also catches a NaN.
    (!(w.scalar <= bound && w.lanes <= bound)).then(|| {
        format!(
            "{name}: f32 {:.4} at {:e}, f32x8 {:.4} at {:e} > {bound}",
            w.scalar, w.scalar_at, w.lanes, w.lanes_at
        )
    })
}

/// The CI slice: every 4096th bit pattern of each domain, its ends, the powers of two with
/// their neighbours and a few negatives, within each function's bound.
#[test]
fn every_4096th_f32_within_bound() {
    let mut failures = Vec::new();
    for f in all() {
        let mut w = Worst::default();
        eval(&f, &slice(&f, 4096), &mut w);
        failures.extend(report(f.name, &w, f.bound));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Every f32 of each domain (the negatives on a stride of 1024), on two threads.
#[test]
#[ignore = "minutes: every f32 input of 17 functions; run on demand"]
fn every_f32_within_bound() {
    let only = std::env::var("EXHAUSTIVE_ONLY").ok();
    let start = std::time::Instant::now();
    let mut failures = Vec::new();
    for f in all() {
        if only
            .as_deref()
            .is_some_and(|o| !o.split(',').any(|x| f.name.starts_with(x)))
        {
            continue;
        }
        let t0 = std::time::Instant::now();
        let (lo, hi) = f.bits;
        let blocks: u32 = 256;
        let next = std::sync::atomic::AtomicU32::new(0);
        let span = (u64::from(hi) - u64::from(lo) + 1).div_ceil(u64::from(blocks));
        let mut w = std::thread::scope(|s| {
            let hs: Vec<_> = (0..2)
                .map(|_| {
                    s.spawn(|| {
                        let mut w = Worst::default();
                        let mut buf = Vec::with_capacity(1 << 16);
                        loop {
                            let b = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                            if b >= blocks {
                                break;
                            }
                            let a = u64::from(lo) + u64::from(b) * span;
                            let z = (a + span).min(u64::from(hi) + 1);
                            let mut i = a;
                            while i < z {
                                let e = (i + (1 << 16)).min(z);
                                buf.clear();
                                buf.extend((i..e).map(|k| f32::from_bits(k as u32)));
                                eval(&f, &buf, &mut w);
                                i = e;
                            }
                        }
                        w
                    })
                })
                .collect();
            let mut w = Worst::default();
            for h in hs {
                w.merge(&h.join().expect("worker"));
            }
            w
        });
        if f.negatives {
            let last = if f.infinities_clamped {
                0xff80_0000u32
            } else {
                0xff7f_ffff
            };
            let neg: Vec<f32> = (0x8000_0000u32..=last)
                .step_by(1024)
                .chain([0x8000_0001, last])
                .map(f32::from_bits)
                .collect();
            eval(&f, &neg, &mut w);
        }
        failures.extend(report(f.name, &w, f.bound));
        println!("{:50} {:.1} s", "", t0.elapsed().as_secs_f64());
    }
    println!("total {:.1} s", start.elapsed().as_secs_f64());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The f64 references against MPFR's (256 bits) on a few thousand points per function:
/// log-uniform over each domain (below 1e9 for the tone curves, whose reference clamps
/// there), uniform on [0, 2], the breakpoints and their neighbouring f32s. Agreement to 1e-6
/// f32 ulp (tiny results to 1e-40 absolutely), so the sweep's figures are exact to that.
#[test]
fn f64_references_agree_with_mpfr() {
    let mut g = brdf_oracle::points::Rng::for_case("exhaustive_f32");
    let mut worst_all: f64 = 0.0;
    for f in all() {
        // The fast OETF's reference is `srgb_oetf_ref`'s pieces with its own threshold (where
        // it differs from the standard on purpose, at one f32): the pieces are checked there.
        if f.name.starts_with("color::srgb_oetf_fast") {
            continue;
        }
        let (lo, hi) = f.bits;
        let top = if f.name.starts_with("tonemap") {
            1e9
        } else {
            f64::from(f32::from_bits(hi.min(f32::MAX.to_bits())))
        };
        let bottom = f64::from(f32::from_bits(lo.max(1)));
        let mut xs: Vec<f32> = (0..3000)
            .map(|i| {
                if i % 3 == 0 {
                    g.range(0.0, 2.0) as f32
                } else {
                    g.log_range(bottom, top) as f32
                }
            })
            .collect();
        for k in [
            0.003_130_8,
            0.040_45,
            0.018,
            0.08,
            0.8,
            0.22,
            0.62,
            1.0,
            5.6,
            8.0,
            1e9,
        ] {
            let mut x = k as f32;
            for _ in 0..8 {
                x = x.next_down();
            }
            for _ in 0..17 {
                xs.push(x);
                x = x.next_up();
            }
        }
        let mut worst: (f64, f32) = (0.0, 0.0);
        for x in xs {
            let x64 = f64::from(x);
            if !(x64 >= bottom && x64 <= top) {
                continue;
            }
            let exact = (f.mpfr)(&Float::with_val(256, x64));
            let e = exact.to_f64();
            let mine = (f.reference)(x64);
            let rounded = e as f32;
            let d = if rounded.is_infinite() {
                0.0
            } else if e.abs() < 1e-30 {
                let diff = Float::with_val(256, mine) - &exact;
                if diff.to_f64().abs() <= 1e-40 {
                    0.0
                } else {
                    f64::INFINITY
                }
            } else {
                let diff = (Float::with_val(256, mine) - &exact).to_f64();
                let ex = ((rounded.abs().to_bits() >> 23) & 0xff) as i32 - 127;
                diff.abs() / 2f64.powi(ex - 23)
            };
            if d > worst.0 {
                worst = (d, x);
            }
        }
        println!(
            "{:50} f64 reference within {:.2e} f32 ulp of MPFR (worst at {:e})",
            f.name, worst.0, worst.1
        );
        worst_all = worst_all.max(worst.0);
        assert!(
            worst.0 < 1e-6,
            "{}: f64 reference {:e} f32 ulp from MPFR at {:e}",
            f.name,
            worst.0,
            worst.1
        );
    }
    println!("largest: {worst_all:.2e} f32 ulp");
}
