//! The tonemapping operators' cases: per-channel curves take (x) or (x, parameter); operators
//! on a colour take (r, g, b, k) or (r, g, b, w, k), where k in {0, 1, 2} names the output
//! channel measured, and their condition numbers perturb each colour channel
//! ([`harness::RGB`]).

use brdf::tonemap::{self, AgxLook, HableParams, LottesParams, UchimuraParams};
use brdf::{Real, V3};
use rug::Float;

use crate::harness::{self, Case, Family, Ty, conditioned_in};
use crate::kernel;
use crate::points::{Rng, around, random};
use crate::reference::num;
use crate::tonemap_ref as t;

/// Output channel `k` (0, 1 or 2 in every lane) of `c`.
fn pick<T: Real>(c: V3<T>, k: T) -> T {
    T::select(
        k.simd_eq(T::ZERO),
        c.x,
        T::select(k.simd_eq(T::ONE), c.y, c.z),
    )
}

/// The colour (args[0], args[1], args[2]).
fn rgb<T: Real>(x: &[T]) -> V3<T> {
    V3::new(x[0], x[1], x[2])
}

/// A reference's channel `k` (the last argument).
fn channel(c: [Float; 3], k: &Float) -> Float {
    let i = k.to_f64() as usize;
    c.into_iter().nth(i).expect("channel 0, 1 or 2")
}

/// Stiff channel values in [0, 1e4]: 0, 1e-30, the smallest normal and a subnormal of the
/// type, 1e-7, 1e-4, the operators' knees, mid grey, 1 and powers of ten up to 1e4.
fn values(ty: Ty) -> Vec<f64> {
    let mut v = vec![
        0.0, 1e-30, 1e-7, 1e-4, 1e-3, 0.01, 0.05, 0.08, 0.1, 0.18, 0.22, 0.25, 0.5, 0.532, 0.62,
        0.76, 0.8, 1.0, 2.0, 4.0, 5.6, 8.0, 11.2, 16.0, 100.0, 1e3, 1e4,
    ];
    match ty {
        Ty::F32 => v.extend([f64::from(f32::MIN_POSITIVE), 1e-40]),
        Ty::F64 => v.extend([f64::MIN_POSITIVE, 1e-310]),
    }
    v
}

/// A random channel value: log-uniform in [1e-30, 1e4] a third of the time, log-uniform in
/// [1e-4, 1e2] a third, uniform in [0, 2] a third.
fn random_value(g: &mut Rng) -> f64 {
    match (g.uniform() * 3.0) as u32 {
        0 => g.log_range(1e-30, 1e4),
        1 => g.log_range(1e-4, 1e2),
        _ => g.range(0.0, 2.0),
    }
}

/// One channel: [`values`], each knee with its 4 neighbouring floats either side, and the
/// random sample.
fn scalar(ty: Ty, name: &str, knees: &[f64]) -> Vec<Vec<f64>> {
    let mut v = values(ty);
    v.extend(knees.iter().flat_map(|&k| around(ty, k, 4)));
    let mut v: Vec<Vec<f64>> = v.into_iter().map(|x| vec![x]).collect();
    v.extend(random(name, |g| vec![random_value(g)]));
    v
}

/// Colours: greys at every stiff value, saturated colours (one or two channels 0), a grid of
/// mixed colours, PBR Neutral's knees (the darkest channel around 0.08, the peak around
/// 0.8 = 0.76 + the offset 0.04), and random colours (a channel 0 a tenth of the time); each
/// colour measured on every channel (the last coordinate).
fn colours(ty: Ty, name: &str) -> Vec<[f64; 3]> {
    let mut c = Vec::new();
    for v in values(ty) {
        c.extend([
            [v, v, v],
            [v, 0.0, 0.0],
            [0.0, v, 0.0],
            [0.0, 0.0, v],
            [v, v, 0.0],
        ]);
    }
    let s = [0.0, 1e-30, 1e-7, 1e-4, 0.08, 0.18, 0.76, 1.0, 4.0, 1e4];
    for r in s {
        for g in s {
            for b in s {
                c.push([r, g, b]);
            }
        }
    }
    for x in around(ty, 0.08, 4) {
        c.extend([[x, 0.5, 0.9], [0.9, x, 2.0], [x, x, x]]);
    }
    for x in around(ty, 0.8, 4) {
        c.extend([[x, x, x], [x, 0.3, 0.1], [0.04, 0.5, x]]);
    }
    let mut g = Rng::fresh(name);
    for _ in 0..crate::points::random_points() / 3 {
        c.push([0, 1, 2].map(|_| {
            if g.uniform() < 0.1 {
                0.0
            } else {
                random_value(&mut g)
            }
        }));
    }
    c
}

/// (r, g, b, k) for every colour of [`colours`] and channel k.
fn colour_points(ty: Ty, name: &str) -> Vec<Vec<f64>> {
    colours(ty, name)
        .into_iter()
        .flat_map(|c| (0..3).map(move |k| vec![c[0], c[1], c[2], f64::from(k)]))
        .collect()
}

const EXPOSURES: [f64; 7] = [1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3];
const WHITES: [f64; 6] = [0.5, 1.0, 4.0, 11.2, 100.0, 1e4];

fn exposure_points(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = Vec::new();
    for x in values(ty) {
        for e in EXPOSURES {
            v.push(vec![x, e]);
        }
    }
    v.extend(random("tonemap::exposure_curve", |g| {
        vec![random_value(g), g.log_range(1e-3, 1e3)]
    }));
    v
}

fn white_points(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = Vec::new();
    for w in WHITES {
        for x in values(ty).into_iter().chain(around(ty, w, 4)) {
            v.push(vec![x, w]);
        }
    }
    v.extend(random("tonemap::reinhard_extended", |g| {
        vec![random_value(g), g.log_range(0.5, 1e4)]
    }));
    v
}

fn colour_white_points(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = Vec::new();
    for (i, c) in colours(ty, "tonemap::reinhard_extended_luminance")
        .into_iter()
        .enumerate()
    {
        let w = WHITES[i % WHITES.len()];
        for k in 0..3 {
            v.push(vec![c[0], c[1], c[2], w, f64::from(k)]);
        }
    }
    // Luminance at the white point: greys at w and their neighbours.
    for w in WHITES {
        for x in around(ty, w, 4) {
            for k in 0..3 {
                v.push(vec![x, x, x, w, f64::from(k)]);
            }
        }
    }
    v
}

fn reinhard_lum_points(ty: Ty) -> Vec<Vec<f64>> {
    colour_points(ty, "tonemap::reinhard_luminance")
}

fn jodie_points(ty: Ty) -> Vec<Vec<f64>> {
    colour_points(ty, "tonemap::reinhard_jodie")
}

fn hill_points(ty: Ty) -> Vec<Vec<f64>> {
    colour_points(ty, "tonemap::aces_hill")
}

fn pbr_points(ty: Ty) -> Vec<Vec<f64>> {
    colour_points(ty, "tonemap::pbr_neutral")
}

fn ref_hill(x: &[Float]) -> Float {
    channel(t::aces_hill([&x[0], &x[1], &x[2]]), &x[3])
}

fn ref_pbr(x: &[Float]) -> Float {
    channel(t::pbr_neutral([&x[0], &x[1], &x[2]]), &x[3])
}

fn hill_main(ty: Ty) -> Vec<Vec<f64>> {
    conditioned_in(ty, hill_points, ref_hill, harness::RGB, false)
}

fn hill_ill(ty: Ty) -> Vec<Vec<f64>> {
    conditioned_in(ty, hill_points, ref_hill, harness::RGB, true)
}

fn pbr_main(ty: Ty) -> Vec<Vec<f64>> {
    conditioned_in(ty, pbr_points, ref_pbr, harness::RGB, false)
}

fn pbr_ill(ty: Ty) -> Vec<Vec<f64>> {
    conditioned_in(ty, pbr_points, ref_pbr, harness::RGB, true)
}

fn hable_ref_params(p: u32) -> ([Float; 6], Float, Float) {
    let h = HableParams::UNCHARTED2;
    (
        [h.a, h.b, h.c, h.d, h.e, h.f].map(|v| num(p, v)),
        num(p, h.white),
        num(p, h.exposure_bias),
    )
}

fn hable_points(ty: Ty) -> Vec<Vec<f64>> {
    let h = HableParams::UNCHARTED2;
    scalar(ty, "tonemap::hable", &[h.white / h.exposure_bias])
}

fn ref_hable(x: &[Float]) -> Float {
    let (k, w, b) = hable_ref_params(x[0].prec());
    t::hable(&x[0], &k, &w, &b)
}

fn ref_lottes(x: &[Float]) -> Float {
    let l = LottesParams::default_curve();
    let p = x[0].prec();
    t::lottes(
        &x[0],
        &num(p, l.contrast),
        &num(p, l.shoulder),
        &num(p, l.hdr_max),
        &num(p, l.mid_in),
        &num(p, l.mid_out),
    )
}

fn lottes_points(ty: Ty) -> Vec<Vec<f64>> {
    let l = LottesParams::default_curve();
    scalar(ty, "tonemap::lottes", &[l.hdr_max, l.mid_in])
}

/// The reference of `tonemap::uchimura` with the Gran Turismo parameters at `x[0]`.
#[must_use]
pub fn ref_uchimura(x: &[Float]) -> Float {
    let u = UchimuraParams::GRAN_TURISMO;
    let p = x[0].prec();
    let k = [
        u.max_brightness,
        u.contrast,
        u.linear_start,
        u.linear_length,
        u.black,
        u.pedestal,
    ]
    .map(|v| num(p, v));
    t::uchimura(&x[0], &k)
}

fn uchimura_points(ty: Ty) -> Vec<Vec<f64>> {
    let u = UchimuraParams::GRAN_TURISMO;
    let m = u.linear_start;
    let s0 = m + (u.max_brightness - m) * u.linear_length / u.contrast;
    scalar(ty, "tonemap::uchimura", &[m, s0, m + u.linear_length])
}

fn narkowicz_points(ty: Ty) -> Vec<Vec<f64>> {
    scalar(ty, "tonemap::aces_narkowicz", &[1.0])
}

fn reinhard_points(ty: Ty) -> Vec<Vec<f64>> {
    scalar(ty, "tonemap::reinhard", &[1.0])
}

/// Every tonemapping case, in table order.
#[must_use]
pub fn all() -> Vec<Case> {
    let tm = Family::Tonemap;
    let one = harness::FIRST;
    let rgb3 = harness::RGB;
    vec![
        Case {
            name: "tonemap::exposure_curve",
            family: tm,
            source: "1 - exp(-x e)",
            reference: |x| t::exposure_curve(&x[0], &x[1]),
            kernels: kernel!(|x| tonemap::exposure_curve(x[0], x[1])),
            points: exposure_points,
            perturbed: one,
        },
        Case {
            name: "tonemap::reinhard",
            family: tm,
            source: "Reinhard et al. 2002 eq. 3",
            reference: |x| t::reinhard(&x[0]),
            kernels: kernel!(|x| tonemap::reinhard(x[0])),
            points: reinhard_points,
            perturbed: one,
        },
        Case {
            name: "tonemap::reinhard_extended",
            family: tm,
            source: "Reinhard et al. 2002 eq. 4",
            reference: |x| t::reinhard_extended(&x[0], &x[1]),
            kernels: kernel!(|x| tonemap::reinhard_extended(x[0], x[1])),
            points: white_points,
            perturbed: one,
        },
        Case {
            name: "tonemap::reinhard_luminance",
            family: tm,
            source: "Reinhard et al. 2002 eq. 3 on BT.709 luminance",
            reference: |x| channel(t::reinhard_luminance([&x[0], &x[1], &x[2]]), &x[3]),
            kernels: kernel!(|x| pick(tonemap::reinhard_luminance(rgb(x)), x[3])),
            points: reinhard_lum_points,
            perturbed: rgb3,
        },
        Case {
            name: "tonemap::reinhard_extended_luminance",
            family: tm,
            source: "Reinhard et al. 2002 eq. 4 on BT.709 luminance",
            reference: |x| {
                channel(
                    t::reinhard_extended_luminance([&x[0], &x[1], &x[2]], &x[3]),
                    &x[4],
                )
            },
            kernels: kernel!(|x| pick(tonemap::reinhard_extended_luminance(rgb(x), x[3]), x[4])),
            points: colour_white_points,
            perturbed: rgb3,
        },
        Case {
            name: "tonemap::reinhard_jodie",
            family: tm,
            source: "Jodie 2019 (Shadertoy), BT.709 luminance",
            reference: |x| channel(t::reinhard_jodie([&x[0], &x[1], &x[2]]), &x[3]),
            kernels: kernel!(|x| pick(tonemap::reinhard_jodie(rgb(x)), x[3])),
            points: jodie_points,
            perturbed: rgb3,
        },
        Case {
            name: "tonemap::aces_narkowicz",
            family: tm,
            source: "Narkowicz 2015",
            reference: |x| t::aces_narkowicz(&x[0]),
            kernels: kernel!(|x| tonemap::aces_narkowicz(x[0])),
            points: narkowicz_points,
            perturbed: one,
        },
        Case {
            name: "tonemap::aces_hill",
            family: tm,
            source: "Hill 2016, ACESFitted.hlsl",
            reference: ref_hill,
            kernels: kernel!(|x| pick(tonemap::aces_hill(rgb(x)), x[3])),
            points: hill_main,
            perturbed: rgb3,
        },
        Case {
            name: "tonemap::aces_hill (ill-conditioned)",
            family: tm,
            source: "Hill 2016, ACESFitted.hlsl",
            reference: ref_hill,
            kernels: kernel!(|x| pick(tonemap::aces_hill(rgb(x)), x[3])),
            points: hill_ill,
            perturbed: rgb3,
        },
        Case {
            name: "tonemap::hable",
            family: tm,
            source: "Hable 2010, Uncharted 2 values",
            reference: ref_hable,
            kernels: kernel!(|x| tonemap::hable(x[0], &HableParams::UNCHARTED2)),
            points: hable_points,
            perturbed: one,
        },
        Case {
            name: "tonemap::lottes",
            family: tm,
            source: "Lottes 2016, default curve",
            reference: ref_lottes,
            kernels: kernel!(|x| tonemap::lottes(x[0], &LottesParams::default_curve())),
            points: lottes_points,
            perturbed: one,
        },
        Case {
            name: "tonemap::uchimura",
            family: tm,
            source: "Uchimura 2017, Gran Turismo values",
            reference: ref_uchimura,
            kernels: kernel!(|x| tonemap::uchimura(x[0], &UchimuraParams::GRAN_TURISMO)),
            points: uchimura_points,
            perturbed: one,
        },
        Case {
            name: "tonemap::pbr_neutral",
            family: tm,
            source: "Khronos PBR Neutral 2024",
            reference: ref_pbr,
            kernels: kernel!(|x| pick(tonemap::pbr_neutral(rgb(x)), x[3])),
            points: pbr_main,
            perturbed: rgb3,
        },
        Case {
            name: "tonemap::pbr_neutral (ill-conditioned)",
            family: tm,
            source: "Khronos PBR Neutral 2024",
            reference: ref_pbr,
            kernels: kernel!(|x| pick(tonemap::pbr_neutral(rgb(x)), x[3])),
            points: pbr_ill,
            perturbed: rgb3,
        },
    ]
}

/// AgX's colours, fewer than [`colours`] (each reference takes a log2 and two powers per
/// channel): greys and single-channel colours at every stiff value, a coarser grid of mixed
/// colours, and 300 random colours (more in a deep run); each measured on every channel.
fn agx_points(ty: Ty) -> Vec<Vec<f64>> {
    let mut c = Vec::new();
    for v in values(ty) {
        c.extend([[v, v, v], [v, 0.0, 0.0], [0.0, v, 0.0], [0.0, 0.0, v]]);
    }
    let s = [0.0, 1e-7, 0.01, 0.18, 1.0, 4.0, 1e4];
    for r in s {
        for g in s {
            for b in s {
                c.push([r, g, b]);
            }
        }
    }
    let mut g = Rng::fresh("tonemap::agx");
    // 300 random colours in an ordinary run; a deep one (10^5 points) draws 3333.
    for _ in 0..(crate::points::random_points() / 30).max(300) {
        c.push([0, 1, 2].map(|_| {
            if g.uniform() < 0.1 {
                0.0
            } else {
                random_value(&mut g)
            }
        }));
    }
    c.into_iter()
        .flat_map(|c| (0..3).map(move |k| vec![c[0], c[1], c[2], f64::from(k)]))
        .collect()
}

fn look_of(l: &AgxLook) -> t::Look {
    t::Look {
        slope: l.slope(),
        power: l.power(),
        saturation: l.saturation(),
    }
}

fn agx_ref(x: &[Float], src: &t::AgxSource, l: &AgxLook) -> Float {
    channel(t::agx([&x[0], &x[1], &x[2]], src, &look_of(l)), &x[3])
}

fn ref_agx_min(x: &[Float]) -> Float {
    agx_ref(x, &t::AgxSource::Wrensch, &AgxLook::BASE)
}
fn ref_agx_min_golden(x: &[Float]) -> Float {
    agx_ref(x, &t::AgxSource::Wrensch, &AgxLook::GOLDEN)
}
fn ref_agx_min_punchy(x: &[Float]) -> Float {
    agx_ref(x, &t::AgxSource::Wrensch, &AgxLook::PUNCHY)
}
fn ref_agx_threejs(x: &[Float]) -> Float {
    agx_ref(x, &t::AgxSource::Threejs, &AgxLook::BASE)
}
fn ref_agx_fil(x: &[Float]) -> Float {
    agx_ref(x, &t::AgxSource::Filament, &AgxLook::BASE)
}
fn ref_agx_fil_golden(x: &[Float]) -> Float {
    agx_ref(x, &t::AgxSource::Filament, &AgxLook::GOLDEN_FILAMENT)
}
fn ref_agx_fil_punchy(x: &[Float]) -> Float {
    agx_ref(x, &t::AgxSource::Filament, &AgxLook::PUNCHY)
}

/// One AgX variant: name, source, reference, kernels, main and ill-conditioned points.
type AgxRow = (
    &'static str,
    &'static str,
    fn(&[Float]) -> Float,
    harness::Kernels,
    fn(Ty) -> Vec<Vec<f64>>,
    fn(Ty) -> Vec<Vec<f64>>,
);

/// The AgX cases, each split by conditioning in the colour.
#[must_use]
pub fn agx() -> Vec<Case> {
    let tm = Family::Tonemap;
    let rows: [AgxRow; 7] = [
        (
            "tonemap::agx_minimal",
            "Wrensch 2023, Minimal AgX",
            ref_agx_min,
            kernel!(|x| pick(tonemap::agx_minimal(rgb(x), &AgxLook::BASE), x[3])),
            |ty| conditioned_in(ty, agx_points, ref_agx_min, harness::RGB, false),
            |ty| conditioned_in(ty, agx_points, ref_agx_min, harness::RGB, true),
        ),
        (
            "tonemap::agx_minimal golden",
            "Wrensch 2023, golden look",
            ref_agx_min_golden,
            kernel!(|x| pick(tonemap::agx_minimal(rgb(x), &AgxLook::GOLDEN), x[3])),
            |ty| conditioned_in(ty, agx_points, ref_agx_min_golden, harness::RGB, false),
            |ty| conditioned_in(ty, agx_points, ref_agx_min_golden, harness::RGB, true),
        ),
        (
            "tonemap::agx_minimal punchy",
            "Wrensch 2023, punchy look",
            ref_agx_min_punchy,
            kernel!(|x| pick(tonemap::agx_minimal(rgb(x), &AgxLook::PUNCHY), x[3])),
            |ty| conditioned_in(ty, agx_points, ref_agx_min_punchy, harness::RGB, false),
            |ty| conditioned_in(ty, agx_points, ref_agx_min_punchy, harness::RGB, true),
        ),
        (
            "tonemap::agx_threejs",
            "three.js AgXToneMapping (r162)",
            ref_agx_threejs,
            kernel!(|x| pick(tonemap::agx_threejs(rgb(x)), x[3])),
            |ty| conditioned_in(ty, agx_points, ref_agx_threejs, harness::RGB, false),
            |ty| conditioned_in(ty, agx_points, ref_agx_threejs, harness::RGB, true),
        ),
        (
            "tonemap::agx_filament",
            "Filament AgxToneMapper",
            ref_agx_fil,
            kernel!(|x| pick(tonemap::agx_filament(rgb(x), &AgxLook::BASE), x[3])),
            |ty| conditioned_in(ty, agx_points, ref_agx_fil, harness::RGB, false),
            |ty| conditioned_in(ty, agx_points, ref_agx_fil, harness::RGB, true),
        ),
        (
            "tonemap::agx_filament golden",
            "Filament AgxToneMapper, golden look",
            ref_agx_fil_golden,
            kernel!(|x| pick(
                tonemap::agx_filament(rgb(x), &AgxLook::GOLDEN_FILAMENT),
                x[3]
            )),
            |ty| conditioned_in(ty, agx_points, ref_agx_fil_golden, harness::RGB, false),
            |ty| conditioned_in(ty, agx_points, ref_agx_fil_golden, harness::RGB, true),
        ),
        (
            "tonemap::agx_filament punchy",
            "Filament AgxToneMapper, punchy look",
            ref_agx_fil_punchy,
            kernel!(|x| pick(tonemap::agx_filament(rgb(x), &AgxLook::PUNCHY), x[3])),
            |ty| conditioned_in(ty, agx_points, ref_agx_fil_punchy, harness::RGB, false),
            |ty| conditioned_in(ty, agx_points, ref_agx_fil_punchy, harness::RGB, true),
        ),
    ];
    let mut v = Vec::new();
    for (name, source, reference, kernels, main, ill) in rows {
        v.push(Case {
            name,
            family: tm,
            source,
            reference,
            kernels,
            points: main,
            perturbed: harness::RGB,
        });
        let ill_name: &'static str =
            Box::leak(format!("{name}{}", harness::ILL_CONDITIONED).into_boxed_str());
        v.push(Case {
            name: ill_name,
            family: tm,
            source,
            reference,
            kernels,
            points: ill,
            perturbed: harness::RGB,
        });
    }
    v
}
