//! Fresh-point search for the microfacet Smith terms: random points from the documented domain
//! (cosines log-uniform down to the smallest subnormal, uniform, and near 1; the Beckmann
//! a = 1 / (alpha tan) band 0.05 .. 30; alpha log-uniform over [ALPHA_MIN, ALPHA_MAX]), then a
//! hill-climb from the worst points (neighbouring floats and relative steps of each
//! coordinate), against the MPFR references of `oracle/src/cases.rs`. Prints the max ULP per
//! function and lane type. Ignored by default (minutes of MPFR work):
//! `FRESH_N=100000 cargo test -p brdf-oracle --release --test fresh_microfacet -- --ignored --nocapture`.

use brdf::Real;
use brdf::wide::{f32x8, f64x4};
use brdf_oracle::cases;
use brdf_oracle::harness::{Case, Ty, precision_for};
use brdf_oracle::points::{ALPHA_HI, ALPHA_LO, Rng, direction};
use rug::Float;

const NAMES: &[&str] = &[
    "ggx::lambda",
    "ggx::g1",
    "ggx::v_correlated",
    "Ggx::lambda",
    "Ggx::g2_correlated",
    "Ggx::v_correlated",
    "beckmann::lambda",
    "beckmann::g1",
    "Beckmann::lambda",
    "Beckmann::v_correlated",
];

fn cosine(g: &mut Rng, ty: Ty, alpha: f64) -> f64 {
    let tiny = match ty {
        Ty::F32 => f64::from(f32::from_bits(1)),
        Ty::F64 => f64::from_bits(1),
    };
    let c = match (g.uniform() * 4.0) as u32 {
        0 => g.log_range(tiny, 1.0),
        1 => g.uniform(),
        2 => 1.0 - g.log_range(1e-17, 1.0),
        _ => {
            let a = g.log_range(0.05, 30.0);
            let t: f64 = 1.0 / (alpha * a);
            1.0 / t.hypot(1.0)
        }
    };
    ty.round(c.clamp(tiny, 1.0))
}

fn point(name: &str, g: &mut Rng, ty: Ty) -> Vec<f64> {
    let a1 = g.log_range(ALPHA_LO, ALPHA_HI);
    let a2 = if g.uniform() < 0.3 {
        a1
    } else {
        g.log_range(ALPHA_LO, ALPHA_HI)
    };
    let dir = |g: &mut Rng| {
        let z = cosine(g, ty, a1.min(a2));
        direction(z, g.range(0.0, core::f64::consts::TAU))
    };
    let p = match name {
        "ggx::lambda" | "ggx::g1" | "beckmann::lambda" | "beckmann::g1" => {
            vec![cosine(g, ty, a1), a1]
        }
        "ggx::v_correlated" => vec![cosine(g, ty, a1), cosine(g, ty, a1), a1],
        "Ggx::lambda" | "Beckmann::lambda" => {
            let d = dir(g);
            vec![d[0], d[1], d[2], a1, a2]
        }
        _ => {
            let (o, l) = (dir(g), dir(g));
            vec![o[0], o[1], o[2], l[0], l[1], l[2], a1, a2]
        }
    };
    p.into_iter().map(|v| ty.round(v)).collect()
}

/// Errors in ULPs of (scalar, lanes) at `p`; None where not measured (tiny, overflow, NaN
/// reference, alpha outside the domain).
fn errors(case: &Case, ty: Ty, p: &[f64]) -> Option<(f64, f64)> {
    let n = p.len();
    if p[n - 1] < ALPHA_LO || p[n - 1] > ALPHA_HI || p[n - 2] < ALPHA_LO && n > 3 {
        return None;
    }
    let prec = precision_for(p, brdf_oracle::PREC);
    let args: Vec<Float> = p.iter().map(|&v| Float::with_val(prec, v)).collect();
    let exact = (case.reference)(&args);
    if exact.is_nan() {
        return None;
    }
    let ex = exact.to_f64();
    let rounded = match ty {
        Ty::F32 => f64::from(exact.to_f32()),
        Ty::F64 => ex,
    };
    if rounded.is_infinite() || ex.abs() < ty.threshold() {
        return None;
    }
    let (ys, yl) = match ty {
        Ty::F32 => {
            let a: Vec<f32> = p.iter().map(|&v| v as f32).collect();
            let l: Vec<f32x8> = a.iter().map(|&v| f32x8::splat(v)).collect();
            (
                f64::from((case.kernels.f32)(&a)),
                f64::from((case.kernels.f32x8)(&l).lane(3)),
            )
        }
        Ty::F64 => {
            let l: Vec<f64x4> = p.iter().map(|&v| f64x4::splat(v)).collect();
            ((case.kernels.f64)(p), (case.kernels.f64x4)(&l).lane(2))
        }
    };
    let e = Float::with_val(64, rounded).get_exp().unwrap_or(0);
    let err = |y: f64| {
        if !y.is_finite() {
            return f64::INFINITY;
        }
        let d = Float::with_val(exact.prec(), y) - &exact;
        (d.abs() >> (e - ty.bits())).to_f64()
    };
    Some((err(ys), err(yl)))
}

fn step(ty: Ty, x: f64, k: i32) -> f64 {
    let mut v = x;
    for _ in 0..k.abs() {
        v = if k > 0 {
            ty.next_up(v)
        } else {
            ty.next_down(v)
        };
    }
    v
}

/// Hill-climb on the scalar error (lanes follow) from `p`.
fn climb(case: &Case, ty: Ty, mut p: Vec<f64>, mut best: f64) -> (Vec<f64>, f64, f64) {
    let mut g = Rng::for_case(case.name);
    let mut lane_best = errors(case, ty, &p).map_or(0.0, |e| e.1);
    for _ in 0..300 {
        let i = (g.uniform() * p.len() as f64) as usize;
        let mut q = p.clone();
        // Vector components move by a few floats only (a unit vector stays unit to rounding);
        // cosines and alphas also by relative steps; every cosine stays in [0, 1].
        let alpha = i >= p.len() - if p.len() > 3 { 2 } else { 1 };
        let vector = p.len() > 3 && !alpha;
        q[i] = match (g.uniform() * 3.0) as u32 {
            _ if vector => step(ty, p[i], (g.uniform() * 9.0) as i32 - 4),
            0 => step(ty, p[i], (g.uniform() * 9.0) as i32 - 4),
            1 => ty.round(p[i] * (1.0 + g.range(-1e-3, 1e-3))),
            _ => ty.round(p[i] * (1.0 + g.range(-1e-6, 1e-6))),
        };
        if !alpha {
            q[i] = q[i].clamp(-1.0, 1.0);
        }
        if let Some((e, l)) = errors(case, ty, &q)
            && e.max(l) > best.max(lane_best)
        {
            p = q;
            best = e;
            lane_best = l;
        }
    }
    (p, best, lane_best)
}

#[test]
#[ignore = "minutes of MPFR work; run on demand"]
fn fresh_microfacet_max_ulp() {
    let n: usize = std::env::var("FRESH_N")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_000);
    let only = std::env::var("FRESH_ONLY").ok();
    for &name in NAMES {
        if only
            .as_deref()
            .is_some_and(|o| !o.split(',').any(|x| x == name))
        {
            continue;
        }
        let case = cases::by_name(name);
        for ty in [Ty::F32, Ty::F64] {
            let threads = 2;
            let results: Vec<Vec<(f64, f64, Vec<f64>)>> = std::thread::scope(|s| {
                let hs: Vec<_> = (0..threads)
                    .map(|t| {
                        let case = &case;
                        s.spawn(move || {
                            let mut g = Rng::for_case(&format!("{name}{t}{ty:?}fresh"));
                            let mut v = Vec::new();
                            for _ in 0..n / threads {
                                let p = point(name, &mut g, ty);
                                if let Some((e, l)) = errors(case, ty, &p) {
                                    v.push((e, l, p));
                                }
                            }
                            v.sort_by(|a, b| b.0.max(b.1).total_cmp(&a.0.max(a.1)));
                            v.truncate(8);
                            v
                        })
                    })
                    .collect();
                hs.into_iter().map(|h| h.join().unwrap()).collect()
            });
            let mut top: Vec<_> = results.into_iter().flatten().collect();
            top.sort_by(|a, b| b.0.max(b.1).total_cmp(&a.0.max(a.1)));
            let (mut ms, mut ml) = (0.0f64, 0.0f64);
            let (mut ws, mut wl) = (Vec::new(), Vec::new());
            for (e, l, p) in &top {
                if *e > ms {
                    ms = *e;
                    ws = p.clone();
                }
                if *l > ml {
                    ml = *l;
                    wl = p.clone();
                }
            }
            let random = (ms, ml);
            for (e, _, p) in top.into_iter().take(6) {
                let (q, e2, l2) = climb(&case, ty, p, e);
                if e2 > ms {
                    ms = e2;
                    ws = q.clone();
                }
                if l2 > ml {
                    ml = l2;
                    wl = q;
                }
            }
            let (s, l) = match ty {
                Ty::F32 => ("f32", "f32x8"),
                Ty::F64 => ("f64", "f64x4"),
            };
            println!(
                "{name:24} {s:5} {ms:6.3} (random {:.3}) at {ws:?}\n{name:24} {l:5} {ml:6.3} (random {:.3}) at {wl:?}",
                random.0, random.1
            );
        }
    }
}

/// The points the report and the review found, and `ggx::g1_schlick` at a huge k.
#[test]
fn fresh_microfacet_reported_points() {
    let pts: [(&str, Ty, Vec<f64>); 4] = [
        (
            "beckmann::lambda",
            Ty::F32,
            vec![8.346_115_238_964_558e-3, 2.594_486_111_775_040_6e-3],
        ),
        (
            "ggx::v_correlated",
            Ty::F32,
            vec![2.674_225_9e-6, 0.966_159_58, 2.568_341_4e-4],
        ),
        (
            "ggx::v_correlated",
            Ty::F64,
            vec![2.674_225_9e-6, 0.966_159_58, 2.568_341_4e-4],
        ),
        (
            "beckmann::lambda",
            Ty::F64,
            vec![8.346_115_238_964_558e-3, 2.594_486_111_775_040_6e-3],
        ),
    ];
    for (name, ty, p) in pts {
        let p: Vec<f64> = p.into_iter().map(|v| ty.round(v)).collect();
        let e = errors(&cases::by_name(name), ty, &p).expect("a measured point");
        println!("{name} {ty:?} {p:?}: {:.3} / lanes {:.3} ulp", e.0, e.1);
        assert!(e.0.max(e.1) <= 4.0);
    }
    for k in [1e8f32, 3e38] {
        let g = brdf::ggx::g1_schlick(1.0f32, k);
        println!("g1_schlick(1, {k:e}) = {g}");
        assert_eq!(g, 1.0);
    }
    assert_eq!(brdf::ggx::g1_schlick(1.0f64, 1e300), 1.0);
    assert_eq!(brdf::ggx::v_schlick(1.0f64, 1.0, 1e300), 0.25);
}

/// The oracle's own point sets, its max ULP printed to six decimals (for the bound rows of
/// `oracle/src/bounds.rs`).
#[test]
#[ignore = "prints figures; run on demand"]
fn fresh_microfacet_oracle_points_precise() {
    for &name in NAMES {
        let m = brdf_oracle::harness::measure(
            &cases::by_name(name),
            brdf_oracle::harness::Options::default(),
        );
        println!(
            "{name:24} {:.9} {:.9} {:.9} {:.9}",
            m.f32.max_ulp, m.f64.max_ulp, m.f32x8.max_ulp, m.f64x4.max_ulp
        );
    }
}
