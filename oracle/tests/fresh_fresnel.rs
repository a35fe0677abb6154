//! The exact Fresnel forms on fresh random points over their whole documented domain, beside
//! the fixed point sets of `tests/fresnel.rs`: eta and k log-uniform from the smallest
//! positive float to the largest finite one, with points on both sides of every internal
//! branch switch (the dielectric's ratio form beyond 1/256 and 256, the conductor's scalings
//! at max(eta, k) = 2^16 and EPSILON^2), eta near 1 and cosines near the critical angle; then
//! a hill-climb (neighbouring floats and coordinate steps) from the worst points. Errors are
//! in ULPs of the correctly rounded MPFR reference (`brdf_oracle::reference`), scored as in
//! `brdf_oracle::harness`: points whose condition number in the cosine exceeds
//! `harness::KAPPA_MAX` are reported apart, with their raw ULPs, kappa and ULPs / kappa.
//!
//! The default run (a few thousand points per function and type) holds the well-conditioned
//! points to the crate's 4-ULP target. The full run:
//! `FRESH_POINTS=100000 cargo test -p brdf-oracle --release --test fresh_fresnel -- --nocapture`.

use brdf::fresnel;
use brdf::wide::{f32x8, f64x4};
use brdf_oracle::harness::{self, Kernels, Ty};
use brdf_oracle::points::Rng;
use brdf_oracle::reference as r;
use brdf_oracle::{PREC, kernel};
use rug::Float;

/// One function under test: its reference, kernels, a point generator and the coordinates
/// its condition number perturbs (the cosine; none for F0, whose eta is used exactly).
struct Fun {
    name: &'static str,
    reference: fn(&[Float]) -> Float,
    kernels: Kernels,
    draw: fn(&mut Rng, Ty) -> Vec<f64>,
    perturbed: &'static [usize],
}

/// Smallest positive (subnormal) and largest finite value of `ty`.
fn range(ty: Ty) -> (f64, f64) {
    match ty {
        Ty::F32 => (f64::from(f32::from_bits(1)), f64::from(f32::MAX)),
        Ty::F64 => (f64::from_bits(1), f64::MAX),
    }
}

/// Log-uniform over (0, MAX] of `ty`, in the exponent (the natural log would overflow
/// nothing, but spans 2^-1074 .. 2^1024 in f64).
fn log_all(g: &mut Rng, ty: Ty) -> f64 {
    let (lo, hi) = range(ty);
    let (a, b) = (lo.log2(), hi.log2());
    let x = (a + (b - a) * g.uniform()).exp2();
    x.clamp(lo, hi)
}

/// A value within a few ulps or a few percent of `x`, either side.
fn near(g: &mut Rng, ty: Ty, x: f64) -> f64 {
    if g.uniform() < 0.5 {
        let mut y = ty.round(x);
        let steps = (g.uniform() * 4.0) as u32;
        for _ in 0..steps {
            y = if g.uniform() < 0.5 {
                ty.next_up(y)
            } else {
                ty.next_down(y)
            };
        }
        y
    } else {
        x * g.log_range(0.9, 1.0 / 0.9)
    }
}

/// A cosine in [0, 1]: uniform, log-uniform down to the smallest subnormal, near 1, or an end.
fn cosine(g: &mut Rng, ty: Ty) -> f64 {
    match (g.uniform() * 10.0) as u32 {
        0..=3 => g.uniform(),
        4 | 5 => log_all(g, ty).min(1.0),
        6 | 7 => 1.0 - g.log_range(1e-17, 1.0),
        8 => g.log_range(1e-8, 1.0),
        _ => [0.0, 1.0][(g.uniform() * 2.0) as usize],
    }
}

/// A relative index over the whole domain, with extra weight near 1, in [0.05, 20] and on
/// both sides of the dielectric's switch to the ratio form (1/256 and 256).
fn eta(g: &mut Rng, ty: Ty) -> f64 {
    match (g.uniform() * 10.0) as u32 {
        0..=2 => log_all(g, ty),
        3 if g.uniform() < 0.5 => near(g, ty, 1.0),
        3 => 1.0 + g.log_range(1e-9, 0.1) * if g.uniform() < 0.5 { 1.0 } else { -1.0 },
        4..=6 => g.log_range(0.05, 20.0),
        7 => near(g, ty, 256.0),
        8 => near(g, ty, 1.0 / 256.0),
        _ => g.log_range(1e-6, 1e6),
    }
}

fn dielectric_point(g: &mut Rng, ty: Ty) -> Vec<f64> {
    let e = eta(g, ty);
    let mut c = cosine(g, ty);
    // A tenth near the critical cosine sqrt(1 - eta^2) (eta < 1) or sqrt(1 - 1/eta^2) from
    // the other side (eta > 1).
    if g.uniform() < 0.1 {
        let m = e.min(1.0 / e);
        let crit = ((1.0 - m) * (1.0 + m)).sqrt();
        c = (crit * (1.0 + g.range(-1.0, 1.0) * g.log_range(1e-9, 1e-2))).clamp(0.0, 1.0);
        let from_inside = e > 1.0;
        return vec![if from_inside { -c } else { c }, e];
    }
    vec![if g.uniform() < 0.5 { -c } else { c }, e]
}

/// k over the whole range, k = 0, moderate k, and both sides of the conductor's scaling
/// thresholds 2^16 and EPSILON^2.
fn kappa_k(g: &mut Rng, ty: Ty) -> f64 {
    let eps2 = match ty {
        Ty::F32 => 2f64.powi(-46),
        Ty::F64 => 2f64.powi(-104),
    };
    match (g.uniform() * 10.0) as u32 {
        0 => 0.0,
        1..=3 => log_all(g, ty),
        4..=6 => g.log_range(1e-3, 10.0),
        7 => near(g, ty, 65536.0),
        8 => near(g, ty, eps2),
        _ => g.log_range(1e-8, 1e8),
    }
}

fn conductor_point(g: &mut Rng, ty: Ty) -> Vec<f64> {
    let eps2 = match ty {
        Ty::F32 => 2f64.powi(-46),
        Ty::F64 => 2f64.powi(-104),
    };
    // A quarter of the points are metals (eta in [0.05, 3], k in [1, 8]).
    if g.uniform() < 0.25 {
        return vec![cosine(g, ty), g.log_range(0.05, 3.0), g.log_range(1.0, 8.0)];
    }
    let e = match (g.uniform() * 10.0) as u32 {
        0 => near(g, ty, 65536.0),
        1 => near(g, ty, eps2),
        _ => eta(g, ty),
    };
    vec![cosine(g, ty), e, kappa_k(g, ty)]
}

fn eta_point(g: &mut Rng, ty: Ty) -> Vec<f64> {
    vec![eta(g, ty)]
}

fn funs() -> Vec<Fun> {
    vec![
        Fun {
            name: "dielectric",
            reference: |x| r::fresnel_dielectric(&x[0], &x[1]),
            kernels: kernel!(|x| fresnel::dielectric(x[0], x[1])),
            draw: dielectric_point,
            perturbed: harness::FIRST,
        },
        Fun {
            name: "dielectric_polarized Rs",
            reference: |x| r::fresnel_dielectric_polarized(&x[0], &x[1]).0,
            kernels: kernel!(|x| fresnel::dielectric_polarized(x[0], x[1]).0),
            draw: dielectric_point,
            perturbed: harness::FIRST,
        },
        Fun {
            name: "dielectric_polarized Rp",
            reference: |x| r::fresnel_dielectric_polarized(&x[0], &x[1]).1,
            kernels: kernel!(|x| fresnel::dielectric_polarized(x[0], x[1]).1),
            draw: dielectric_point,
            perturbed: harness::FIRST,
        },
        Fun {
            name: "conductor",
            reference: |x| r::fresnel_conductor(&x[0], &x[1], &x[2]),
            kernels: kernel!(|x| fresnel::conductor(x[0], x[1], x[2])),
            draw: conductor_point,
            perturbed: harness::FIRST,
        },
        Fun {
            name: "f0_from_ior",
            reference: |x| r::f0_from_ior(&x[0]),
            kernels: kernel!(|x| fresnel::f0_from_ior(x[0])),
            draw: eta_point,
            perturbed: &[],
        },
    ]
}

fn reference(f: &Fun, p: &[f64]) -> Float {
    let prec = harness::precision_for(p, PREC);
    let args: Vec<Float> = p.iter().map(|&v| Float::with_val(prec, v)).collect();
    (f.reference)(&args)
}

/// The kernel on the scalar type and on one lane (all lanes the same point) of the SIMD type.
fn evaluate(f: &Fun, ty: Ty, p: &[f64]) -> [f64; 2] {
    match ty {
        Ty::F32 => {
            let a: Vec<f32> = p.iter().map(|&v| v as f32).collect();
            let l: Vec<f32x8> = a.iter().map(|&v| f32x8::splat(v)).collect();
            let lane = (f.kernels.f32x8)(&l).to_array()[3];
            [f64::from((f.kernels.f32)(&a)), f64::from(lane)]
        }
        Ty::F64 => {
            let l: Vec<f64x4> = p.iter().map(|&v| f64x4::splat(v)).collect();
            [(f.kernels.f64)(p), (f.kernels.f64x4)(&l).to_array()[2]]
        }
    }
}

/// Error in ULPs of the correctly rounded result; None where that result is below the
/// type's threshold or overflows (not scored in ULPs). A non-finite result scores inf.
fn ulps(y: f64, exact: &Float, ty: Ty) -> Option<f64> {
    let ex = exact.to_f64();
    let rounded = match ty {
        Ty::F32 => f64::from(exact.to_f32()),
        Ty::F64 => ex,
    };
    if rounded.is_infinite() || ex.abs() < ty.threshold() {
        return None;
    }
    if !y.is_finite() {
        return Some(f64::INFINITY);
    }
    let e = Float::with_val(64, rounded).get_exp().unwrap_or(0);
    let d = Float::with_val(exact.prec(), exact - y).abs();
    Some((d >> (e - ty.bits())).to_f64())
}

/// The worst point of one class on one type.
#[derive(Clone, Debug, Default)]
struct Worst {
    ulp: f64,
    kappa: f64,
    at: Vec<f64>,
}

/// Scored results of one function on one type: [scalar, lanes] for the well-conditioned
/// points, and for the ill-conditioned ones the worst raw ULPs and the worst ULPs / kappa.
#[derive(Clone, Debug, Default)]
struct Score {
    well: [Worst; 2],
    ill_raw: [Worst; 2],
    ill_rel: [Worst; 2],
    points: usize,
    ill_points: usize,
    lanes_differ: usize,
    failures: usize,
}

/// Error (max over scalar and lanes) below which a point cannot matter to the 4-ULP verdict
/// nor to the reported worst: its condition number is not computed.
const BORING: f64 = 1.0;

struct Eval {
    err: [f64; 2],
    kappa: f64,
}

fn eval_point(f: &Fun, ty: Ty, p: &[f64]) -> Option<Eval> {
    // Grazing light on no interface (c = 0, eta = 1, k = 0): the kernels document 0 (no
    // interface), the textbook ratios are 0 / 0 there and the reference says 1.
    if p.len() >= 2 && p[0] == 0.0 && p[1] == 1.0 && p.get(2).is_none_or(|&k| k == 0.0) {
        return None;
    }
    let ex = reference(f, p);
    if ex.is_nan() {
        return None;
    }
    let y = evaluate(f, ty, p);
    let e0 = ulps(y[0], &ex, ty)?;
    let e1 = ulps(y[1], &ex, ty)?;
    let kappa = if e0.max(e1) > BORING && !f.perturbed.is_empty() {
        harness::condition(f.reference, ty, p, f.perturbed)
    } else {
        0.0
    };
    Some(Eval {
        err: [e0, e1],
        kappa,
    })
}

fn record(s: &mut Score, p: &[f64], e: &Eval) {
    s.points += 1;
    if e.err[0].to_bits() != e.err[1].to_bits() {
        s.lanes_differ += 1;
    }
    if !e.err[0].is_finite() || !e.err[1].is_finite() {
        s.failures += 1;
    }
    let ill = e.kappa > harness::KAPPA_MAX;
    if ill {
        s.ill_points += 1;
    }
    for i in 0..2 {
        let w = Worst {
            ulp: e.err[i],
            kappa: e.kappa,
            at: p.to_vec(),
        };
        if ill {
            if e.err[i] > s.ill_raw[i].ulp {
                s.ill_raw[i] = w.clone();
            }
            if e.err[i] / e.kappa > s.ill_rel[i].ulp / s.ill_rel[i].kappa.max(1.0) {
                s.ill_rel[i] = w;
            }
        } else if e.err[i] > s.well[i].ulp {
            s.well[i] = w;
        }
    }
}

/// Neighbours of `p` for the hill-climb: each coordinate moved by 1, 2, 4 ... 2^20 floats and
/// by relative steps of 2^-k, both directions, within the domain.
fn neighbours(f: &Fun, ty: Ty, p: &[f64], g: &mut Rng) -> Vec<Vec<f64>> {
    let (_, max) = range(ty);
    let mut out = Vec::new();
    for i in 0..p.len() {
        for _ in 0..4 {
            let mut q = p.to_vec();
            let n = 1u32 << (g.uniform() * 21.0) as u32;
            let up = g.uniform() < 0.5;
            for _ in 0..n.min(64) {
                q[i] = if up {
                    ty.next_up(q[i])
                } else {
                    ty.next_down(q[i])
                };
            }
            if n > 64 {
                let rel = f64::from(n) * 2f64.powi(-ty.bits());
                q[i] = ty.round(q[i] * if up { 1.0 + rel } else { 1.0 - rel });
            }
            out.push(q);
        }
        let mut q = p.to_vec();
        q[i] = ty.round(q[i] * g.log_range(0.5, 2.0));
        out.push(q);
    }
    // Keep the domain: |cos| <= 1 (cos >= 0 for the conductor), eta in (0, MAX], k in [0, MAX].
    let signed_cos = f.name.starts_with("dielectric");
    out.retain(|q| {
        q.iter().all(|v| v.is_finite() && v.abs() <= max)
            && match q.len() {
                1 => q[0] > 0.0,
                2 => q[0].abs() <= 1.0 && q[1] > 0.0 && (signed_cos || q[0] >= 0.0),
                _ => (0.0..=1.0).contains(&q[0]) && q[1] > 0.0 && q[2] >= 0.0,
            }
    });
    out
}

/// Climbs from `start` (well-conditioned: stays in kappa <= KAPPA_MAX; ill: maximizes the
/// raw error) for `steps` rounds, recording every point it evaluates.
fn climb(f: &Fun, ty: Ty, start: &[f64], ill: bool, steps: usize, s: &mut Score, g: &mut Rng) {
    let kappa_ok = |k: f64| (k > harness::KAPPA_MAX) == ill;
    let mut cur = start.to_vec();
    let mut best = match eval_point(f, ty, &cur) {
        Some(e) => e.err[0].max(e.err[1]),
        None => return,
    };
    for _ in 0..steps {
        let mut moved = false;
        for q in neighbours(f, ty, &cur, g) {
            let Some(e) = eval_point(f, ty, &q) else {
                continue;
            };
            record(s, &q, &e);
            let err = e.err[0].max(e.err[1]);
            if err > best && err.is_finite() && (err <= BORING || kappa_ok(e.kappa)) {
                best = err;
                cur = q;
                moved = true;
            }
        }
        if !moved && g.uniform() < 0.5 {
            break;
        }
    }
}

fn run(f: &Fun, ty: Ty, n: usize) -> Score {
    let mut s = Score::default();
    let mut g = Rng::for_case(&format!("fresh {} {:?}", f.name, ty));
    let mut pts: Vec<(f64, f64, Vec<f64>)> = Vec::new();
    for _ in 0..n {
        let p: Vec<f64> = (f.draw)(&mut g, ty)
            .into_iter()
            .map(|v| ty.round(v))
            .collect();
        if let Some(e) = eval_point(f, ty, &p) {
            record(&mut s, &p, &e);
            pts.push((e.err[0].max(e.err[1]), e.kappa, p));
        }
    }
    // Hill-climb from the 16 worst well-conditioned and the 4 worst ill-conditioned points.
    let mut starts: Vec<(bool, Vec<f64>)> = Vec::new();
    for ill in [false, true] {
        let mut c: Vec<&(f64, f64, Vec<f64>)> = pts
            .iter()
            .filter(|(_, k, _)| (*k > harness::KAPPA_MAX) == ill)
            .collect();
        c.sort_by(|a, b| b.0.total_cmp(&a.0));
        starts.extend(
            c.iter()
                .take(if ill { 4 } else { 32 })
                .map(|(_, _, p)| (ill, p.clone())),
        );
    }
    let steps = if n >= 20_000 { 100 } else { 8 };
    for (ill, p) in starts {
        climb(f, ty, &p, ill, steps, &mut s, &mut g);
    }
    s
}

fn points_per_function() -> usize {
    std::env::var("FRESH_POINTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3000)
}

/// Every exact Fresnel form is within 4 ULP of the correctly rounded result on fresh random
/// points over the whole domain (where a 1-ulp change of the cosine moves the result by at
/// most `KAPPA_MAX` ulps), scalar and lanes alike, with no NaN or infinite result.
#[test]
fn fresnel_exact_forms_within_4_ulp_on_fresh_points() {
    let n = points_per_function();
    let jobs: Vec<(usize, Ty)> = (0..funs().len())
        .flat_map(|i| [(i, Ty::F32), (i, Ty::F64)])
        .collect();
    let threads = std::thread::available_parallelism().map_or(2, |v| v.get());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|sc| {
        for _ in 0..threads {
            sc.spawn(|| {
                let fs = funs();
                loop {
                    let j = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(&(i, ty)) = jobs.get(j) else { break };
                    let s = run(&fs[i], ty, n);
                    results.lock().unwrap().push((i, ty, s));
                }
            });
        }
    });
    let mut results = results.into_inner().unwrap();
    results.sort_by_key(|(i, ty, _)| (*i, *ty == Ty::F64));
    let fs = funs();
    let lane = |ty: Ty| if ty == Ty::F32 { "f32x8" } else { "f64x4" };
    let mut errors = Vec::new();
    println!("{n} random points per function and type, then a hill-climb from the worst");
    for (i, ty, s) in &results {
        let name = fs[*i].name;
        for (l, tname) in [(0, format!("{ty:?}").to_lowercase()), (1, lane(*ty).into())] {
            let w = &s.well[l];
            println!(
                "{name:<24} {tname:<6} well max {:>7.3} ulp at {:?}",
                w.ulp, w.at
            );
            if s.ill_points > 0 {
                let (a, b) = (&s.ill_raw[l], &s.ill_rel[l]);
                println!(
                    "{:<31} ill  max {:>9.3} ulp (kappa {:.3e}) at {:?}; max ulp/kappa {:.3} \
                     ({:.3} ulp, kappa {:.3e}) at {:?}",
                    "",
                    a.ulp,
                    a.kappa,
                    a.at,
                    b.ulp / b.kappa.max(1.0),
                    b.ulp,
                    b.kappa,
                    b.at
                );
            }
            if w.ulp > 4.0 {
                errors.push(format!("{name} {tname}: {:.3} ulp at {:?}", w.ulp, w.at));
            }
        }
        println!(
            "{:<31} {} points ({} ill-conditioned with error > 1 ulp), lanes differ at {}, non-finite at {}",
            "", s.points, s.ill_points, s.lanes_differ, s.failures
        );
        if s.failures > 0 {
            errors.push(format!("{name} {ty:?}: {} non-finite results", s.failures));
        }
    }
    assert!(errors.is_empty(), "{}", errors.join("\n"));
}
