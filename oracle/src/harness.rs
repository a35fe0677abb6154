//! The ULP harness: evaluate a kernel on f32, f64, f32x8 and f64x4 over a point set, compare
//! each result with the high-precision reference, and keep the worst error in ULPs.
//!
//! Error of a result y against the exact value x (before any rounding):
//! |y - x| / ulp(round(x)), with ulp of the target type's binade. A correctly rounded result
//! scores at most 0.5; one more rounding adds up to about 0.5.
//!
//! Classes of points:
//! - measured: |x| >= [`Ty::threshold`] (1e-30 in f32, 1e-300 in f64) and round(x) finite;
//!   a NaN or infinite result there is a failure;
//! - tiny: |x| below the threshold: passes when y is finite and |y - x| <= threshold;
//! - overflow: round(x) is infinite: passes when y is +-inf or +-MAX with x's sign (the crate
//!   caps poles at the largest finite value).
//!
//! Conditioning. Where a function's own condition number makes a few ULPs impossible for any
//! kernel that receives rounded inputs (Fresnel at the critical angle, where dF/dcos is
//! infinite; Rp at its double zero at Brewster's angle), the case is split in two by
//! [`condition`], computed with MPFR at each point: kappa = max over cos +- 1 ulp (the
//! first argument, moved to its neighbouring float in the point's own type) of
//! |f(cos +- 1 ulp) - f(cos)| / ulp(f). The main row keeps the points with
//! kappa <= [`KAPPA_MAX`]; a second case named `<name> (ill-conditioned)` (suffix
//! [`ILL_CONDITIONED`]) takes the rest and is scored as error / kappa, in units of "the
//! change one rounding of the cosine causes": a score <= 1 means the kernel is no worse than
//! one rounding of its input. Only the first argument (the cosine, which reaches a kernel
//! already rounded from a dot product) is perturbed: material parameters such as eta are
//! used exactly by the kernels (eta - 1 is exact near 1), so their sensitivity, huge for
//! eta within a few ulps of 1, excuses nothing and those points stay in the main row. The
//! tightness check of `tests/harness.rs` perturbs an ill-conditioned row's results by kappa
//! roundings, i.e. by one unit of its score.

use brdf::Real;
use brdf::wide::{f32x8, f64x4};
use rug::Float;

use crate::PREC;

/// The scalar type a measurement is made in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Ty {
    /// `f32` (and `f32x8` lanes).
    F32,
    /// `f64` (and `f64x4` lanes).
    F64,
}

impl Ty {
    /// `x` rounded to this type (to nearest), back in an `f64`.
    #[must_use]
    pub fn round(self, x: f64) -> f64 {
        match self {
            Ty::F32 => f64::from(x as f32),
            Ty::F64 => x,
        }
    }

    /// Significand bits (24, 53).
    #[must_use]
    pub fn bits(self) -> i32 {
        match self {
            Ty::F32 => 24,
            Ty::F64 => 53,
        }
    }

    /// Smallest result magnitude that is measured in ULPs: 1e-30 (f32), 1e-300 (f64).
    #[must_use]
    pub fn threshold(self) -> f64 {
        match self {
            Ty::F32 => 1e-30,
            Ty::F64 => 1e-300,
        }
    }

    /// The largest finite value.
    #[must_use]
    pub fn max(self) -> f64 {
        match self {
            Ty::F32 => f64::from(f32::MAX),
            Ty::F64 => f64::MAX,
        }
    }

    /// The next representable value above `x` in this type (`x` finite, representable).
    #[must_use]
    pub fn next_up(self, x: f64) -> f64 {
        match self {
            Ty::F32 => f64::from((x as f32).next_up()),
            Ty::F64 => x.next_up(),
        }
    }

    /// The next representable value below `x` in this type.
    #[must_use]
    pub fn next_down(self, x: f64) -> f64 {
        match self {
            Ty::F32 => f64::from((x as f32).next_down()),
            Ty::F64 => x.next_down(),
        }
    }
}

/// One kernel instantiated on the four lane types; arguments in a slice, in the order of the
/// case's point coordinates.
#[derive(Clone, Copy)]
pub struct Kernels {
    /// On `f32`.
    pub f32: fn(&[f32]) -> f32,
    /// On `f64`.
    pub f64: fn(&[f64]) -> f64,
    /// On `f32x8`.
    pub f32x8: fn(&[f32x8]) -> f32x8,
    /// On `f64x4`.
    pub f64x4: fn(&[f64x4]) -> f64x4,
}

/// `kernel!(|x| expr)`: a [`Kernels`] from one expression generic over `T: Real`, with `x`
/// the argument slice `&[T]`.
#[macro_export]
macro_rules! kernel {
    (|$x:ident| $body:expr) => {{
        fn k<T: brdf::Real>($x: &[T]) -> T {
            $body
        }
        $crate::harness::Kernels {
            f32: k::<f32>,
            f64: k::<f64>,
            f32x8: k::<brdf::wide::f32x8>,
            f64x4: k::<brdf::wide::f64x4>,
        }
    }};
}

/// The function families, one test file each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// GGX and Beckmann: D, Lambda, G1, G2, V.
    Microfacet,
    /// Dielectric, conductor, Schlick, F0.
    Fresnel,
    /// Display transfer functions.
    Color,
    /// Diffuse and Phong lobes.
    Lobes,
    /// Tonemapping operators.
    Tonemap,
}

/// The coordinates a condition number perturbs ([`condition`]): the first (a cosine).
pub const FIRST: &[usize] = &[0];

/// The coordinates a condition number perturbs for an RGB operator: each colour channel
/// (coordinates 0, 1, 2), one at a time.
pub const RGB: &[usize] = &[0, 1, 2];

/// One exact function under test.
pub struct Case {
    /// The brdf path, e.g. `ggx::d`; the key of [`crate::bounds::BOUNDS`].
    pub name: &'static str,
    /// Its family.
    pub family: Family,
    /// The definition the reference implements (paper and equation).
    pub source: &'static str,
    /// The reference on exact inputs at the inputs' precision.
    pub reference: fn(&[Float]) -> Float,
    /// The kernel on each lane type.
    pub kernels: Kernels,
    /// The points (each a vector of arguments) for a type; coordinates are rounded to the
    /// type by the harness.
    pub points: fn(Ty) -> Vec<Vec<f64>>,
    /// The coordinates [`condition`] perturbs: [`FIRST`] (the cosine) for most functions,
    /// [`RGB`] for operators on a colour.
    pub perturbed: &'static [usize],
}

/// Worst-case figures of one kernel on one lane type.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Largest error in ULPs over measured points (inf when a result was NaN or inf).
    pub max_ulp: f64,
    /// The arguments where `max_ulp` was reached.
    pub worst: Vec<f64>,
    /// Points evaluated.
    pub points: usize,
    /// Points whose exact result is below the threshold (checked absolutely, not in ULPs).
    pub tiny: usize,
    /// Points whose exact result overflows the type.
    pub overflow: usize,
    /// Points that failed outright: NaN or inf for a finite reference, a tiny result off by
    /// more than the threshold, an overflowing one not capped.
    pub failures: usize,
    /// The first failing point, if any: arguments, computed value, exact value.
    pub first_failure: Option<(Vec<f64>, f64, f64)>,
    /// Ill-conditioned rows: the largest raw error in ULPs (not reduced by kappa)...
    pub max_raw: f64,
    /// ... the condition number at the point where it was reached ...
    pub kappa_at_raw: f64,
    /// ... and that point (recorded among the hardest inputs beside the top scores).
    pub worst_raw: Vec<f64>,
    /// The [`TOP`] highest-scoring points, highest first: (score, arguments). Recorded as
    /// the hardest inputs (`crate::hardest`).
    pub top: Vec<(f64, Vec<f64>)>,
}

/// How many of the highest-scoring points [`Stats::top`] keeps.
pub const TOP: usize = 32;

impl Stats {
    /// Records one result. Main rows score the error in ULPs; ill-conditioned rows (`ill`)
    /// score it minus `kappa / 2`, the error one rounding of the input explains (module docs).
    /// The result is multiplied by (1 + `perturb`) first (one rounding, to prove bounds tight).
    #[allow(clippy::too_many_arguments)]
    fn record(
        &mut self,
        args: &[f64],
        y: f64,
        exact: &Float,
        ty: Ty,
        perturb: f64,
        kappa: f64,
        ill: bool,
    ) {
        self.points += 1;
        let ex = exact.to_f64();
        let fail = |s: &mut Stats| {
            s.failures += 1;
            if s.first_failure.is_none() {
                s.first_failure = Some((args.to_vec(), y, ex));
            }
        };
        let raw = match classify(y, exact, ty, perturb) {
            Scored::Overflow(ok) => {
                self.overflow += 1;
                if !ok {
                    fail(self);
                }
                return;
            }
            Scored::Tiny(ok) => {
                self.tiny += 1;
                if !ok {
                    fail(self);
                }
                return;
            }
            Scored::Ulps(raw) => raw,
        };
        if raw.is_infinite() {
            fail(self);
        }
        let score = if ill { raw - kappa / 2.0 } else { raw };
        if score > self.max_ulp || self.worst.is_empty() {
            self.max_ulp = score;
            self.worst = args.to_vec();
        }
        if raw > self.max_raw {
            self.max_raw = raw;
            self.kappa_at_raw = kappa;
            self.worst_raw = args.to_vec();
        }
        if self.top.len() < TOP || score > self.top[TOP - 1].0 {
            if self.top.len() == TOP {
                self.top.pop();
            }
            let at = self.top.partition_point(|(s, _)| *s >= score);
            self.top.insert(at, (score, args.to_vec()));
        }
    }
}

/// How a result is scored ([`classify`]).
enum Scored {
    /// round(exact) overflows the type: whether the result is capped correctly.
    Overflow(bool),
    /// |exact| is below [`Ty::threshold`]: whether the result is within it.
    Tiny(bool),
    /// The error in ULPs (inf for a NaN or infinite result).
    Ulps(f64),
}

/// Classifies and scores the result `y` (multiplied by 1 + `perturb`) against `exact`.
fn classify(y: f64, exact: &Float, ty: Ty, perturb: f64) -> Scored {
    let ex = exact.to_f64();
    let rounded = match ty {
        Ty::F32 => f64::from(exact.to_f32()),
        Ty::F64 => ex,
    };
    if rounded.is_infinite() {
        return Scored::Overflow(y.abs() >= ty.max() && y.signum() == ex.signum());
    }
    if ex.abs() < ty.threshold() {
        return Scored::Tiny(y.is_finite() && (y - ex).abs() <= ty.threshold());
    }
    if !y.is_finite() {
        return Scored::Ulps(f64::INFINITY);
    }
    Scored::Ulps(ulp_error(y, exact, rounded, ty, perturb))
}

/// |y (1 + perturb) - exact| / ulp(rounded), computed in MPFR so that neither the difference
/// nor the perturbation is rounded to the target type.
fn ulp_error(y: f64, exact: &Float, rounded: f64, ty: Ty, perturb: f64) -> f64 {
    let p = exact.prec();
    let yp = Float::with_val(p, y) * (1 + Float::with_val(p, perturb));
    in_ulps(yp - exact, rounded, ty)
}

/// |diff| in ULPs of `rounded`'s binade in `ty`.
fn in_ulps(diff: Float, rounded: f64, ty: Ty) -> f64 {
    // rounded = m 2^e with m in [0.5, 1): its binade's ulp is 2^(e - bits).
    let e = Float::with_val(64, rounded).get_exp().unwrap_or(0);
    (diff.abs() >> (e - ty.bits())).to_f64()
}

/// Name suffix of a case scored relative to its conditioning (module docs, "Conditioning").
pub const ILL_CONDITIONED: &str = " (ill-conditioned)";

/// Condition number above which a point leaves a function's main row for its
/// [`ILL_CONDITIONED`] row: a 1-ulp change of the cosine moves the exact result by more than
/// 8 ulps. Below it the kernels' own few roundings dominate and the 4-ULP target applies.
pub const KAPPA_MAX: f64 = 8.0;

/// The condition number of `reference` at `p` (coordinates already rounded to `ty`) in the
/// coordinates `perturbed` (one at a time): max over `p[i]` +- 1 ulp of `ty`, i in
/// `perturbed`, of |f(p') - f(p)| / ulp(f(p)), in MPFR. 0 where f(p) is below
/// [`Ty::threshold`] or overflows `ty` (those points are scored absolutely); a neighbour
/// where the reference is NaN (outside its domain) is skipped, and so is the neighbour below
/// a coordinate that is 0 (a colour channel's domain starts there).
#[must_use]
pub fn condition(reference: fn(&[Float]) -> Float, ty: Ty, p: &[f64], perturbed: &[usize]) -> f64 {
    let eval = |q: &[f64]| {
        let prec = precision_for(q, PREC);
        let args: Vec<Float> = q.iter().map(|&v| Float::with_val(prec, v)).collect();
        reference(&args)
    };
    let f = eval(p);
    let ex = f.to_f64();
    let rounded = ty.round(ex);
    if f.is_nan() || rounded.is_infinite() || ex.abs() < ty.threshold() {
        return 0.0;
    }
    let mut kappa: f64 = 0.0;
    for &i in perturbed {
        for x in [ty.next_up(p[i]), ty.next_down(p[i])] {
            if p[i] == 0.0 && x < 0.0 {
                continue;
            }
            let mut q = p.to_vec();
            q[i] = x;
            let g = eval(&q);
            if !g.is_nan() {
                let prec = g.prec().max(f.prec());
                kappa = kappa.max(in_ulps(Float::with_val(prec, &g - &f), rounded, ty));
            }
        }
    }
    kappa
}

/// The four measurements of one case.
#[derive(Clone, Debug, Default)]
pub struct Measurement {
    /// On `f32`.
    pub f32: Stats,
    /// On `f64`.
    pub f64: Stats,
    /// On `f32x8` (against the f32 references).
    pub f32x8: Stats,
    /// On `f64x4` (against the f64 references).
    pub f64x4: Stats,
    /// Largest difference, in f64 ULPs of the result, between the reference at the working
    /// precision and with [`PREC`] more bits, over the measured points (0 unless checked).
    pub reference_drift: f64,
}

/// Options of [`measure`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// Multiply each computed result by (1 + perturb) before comparing (in MPFR): a relative
    /// error of one rounding is 2^-24 (f32) or 2^-53 (f64). Used to prove the bounds tight.
    /// The f32 entry applies to f32 and f32x8, the f64 one to f64 and f64x4.
    pub perturb: (f64, f64),
    /// Evaluate the references again with [`PREC`] more bits and record the drift.
    pub check_reference: bool,
    /// Skip the lane types.
    pub scalars_only: bool,
    /// The case is one half of a function split by conditioning (it or its twin carries the
    /// [`ILL_CONDITIONED`] suffix): the hill-climb keeps to the half's side of
    /// [`KAPPA_MAX`]. Set by `table::measure_all` and `check`.
    pub split: bool,
    /// Measure only the committed hardest inputs (`crate::hardest`): no fresh points, no
    /// climb, so the figures are the same on every run (the published table).
    pub hardest_only: bool,
}

/// What one (case, type) costs to prepare, kept for the process: the points (the case's
/// stiff and fresh points, the committed hardest inputs and every point the hill-climb
/// visited), their references at [`PREC`], and the ill-conditioned rows' condition numbers.
/// A test that measures every case more than once (the perturbation proof measures them
/// three times) pays for the MPFR work once and measures the same points each time.
#[derive(Clone)]
struct Prepared {
    points: Vec<Vec<f64>>,
    refs: Vec<Float>,
    kappas: Vec<f64>,
}

type Key = (&'static str, Ty, bool);
type Slot = std::sync::Arc<std::sync::OnceLock<Prepared>>;
type Cache = std::sync::Mutex<std::collections::HashMap<Key, Slot>>;

fn cache() -> &'static Cache {
    static CACHE: std::sync::OnceLock<Cache> = std::sync::OnceLock::new();
    CACHE.get_or_init(Default::default)
}

/// The points of `all` (rounded to `ty`) whose condition number for `reference` in the
/// coordinates `perturbed` ([`condition`]) is at most [`KAPPA_MAX`] (`ill` false: a case's main
/// row) or above it (`ill` true: its `(ill-conditioned)` row). Shared by `cases` and
/// `tonemap_cases`, which both depend on this module and not on each other.
pub fn conditioned_in(
    ty: Ty,
    all: fn(Ty) -> Vec<Vec<f64>>,
    reference: fn(&[Float]) -> Float,
    perturbed: &[usize],
    ill: bool,
) -> Vec<Vec<f64>> {
    all(ty)
        .into_iter()
        .map(|p| p.into_iter().map(|x| ty.round(x)).collect::<Vec<f64>>())
        .filter(|p| (condition(reference, ty, p, perturbed) > KAPPA_MAX) == ill)
        .collect()
}

/// The points, references and condition numbers of (case, ty), from the cache or computed
/// and cached. Each (case, type) is computed once: a second thread asking for it waits for
/// the first, while other cases are prepared beside it.
fn prepared(case: &Case, ty: Ty, opts: Options) -> Prepared {
    let slot: Slot = {
        let mut guard = cache()
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        guard
            .entry((case.name, ty, opts.hardest_only))
            .or_default()
            .clone()
    };
    slot.get_or_init(|| prepare(case, ty, opts)).clone()
}

fn prepare(case: &Case, ty: Ty, opts: Options) -> Prepared {
    let round = |p: Vec<f64>| p.into_iter().map(|v| ty.round(v)).collect::<Vec<f64>>();
    let ill = case.name.ends_with(ILL_CONDITIONED);
    // A committed point of a split function counts in the half its condition number puts it
    // in (a reported point may be listed under both); one outside the function's domain (its
    // reference NaN: the domain was narrowed since it was recorded) is dropped.
    let hardest: Vec<Vec<f64>> = crate::hardest::points(case.name, ty)
        .into_iter()
        .map(round)
        .filter(|p| {
            let prec = precision_for(p, PREC);
            let args: Vec<Float> = p.iter().map(|&v| Float::with_val(prec, v)).collect();
            !(case.reference)(&args).is_nan()
                && (!opts.split
                    || (condition(case.reference, ty, p, case.perturbed) > KAPPA_MAX) == ill)
        })
        .collect();
    let points: Vec<Vec<f64>> = if opts.hardest_only {
        hardest.into_iter().map(round).collect()
    } else {
        (case.points)(ty)
            .into_iter()
            .chain(hardest)
            .map(round)
            .collect()
    };
    let refs = references(case, &points, PREC);
    let kappas = points
        .iter()
        .zip(&refs)
        .map(|(p, r)| {
            if ill && !r.is_nan() {
                condition(case.reference, ty, p, case.perturbed).max(1.0)
            } else {
                1.0
            }
        })
        .collect();
    let mut prep = Prepared {
        points,
        refs,
        kappas,
    };
    if !opts.hardest_only {
        climb(case, ty, opts, &mut prep);
    }
    prep
}

/// Hill-climb starting points and evaluations per start: (starts, evaluations) in an
/// ordinary run and in a deep one (`points::deep`).
pub const CLIMB: [(usize, usize); 2] = [(4, 40), (16, 400)];

/// The score of the point `p` (exact value `exact`, condition number `kappa`): the larger of
/// the scalar and the lane kernel's, as [`Stats::record`] scores them; `None` where the point
/// is scored absolutely (tiny or overflowing results).
fn point_score(
    case: &Case,
    ty: Ty,
    p: &[f64],
    exact: &Float,
    kappa: f64,
    ill: bool,
) -> Option<f64> {
    let (y, lane) = match ty {
        Ty::F32 => {
            let a: Vec<f32> = p.iter().map(|&v| v as f32).collect();
            let pts = [p.to_vec()];
            (
                f64::from((case.kernels.f32)(&a)),
                eval_lanes::<f32x8>(&pts, |v| v as f32, f64::from, case.kernels.f32x8)[0],
            )
        }
        Ty::F64 => {
            let pts = [p.to_vec()];
            (
                (case.kernels.f64)(p),
                eval_lanes::<f64x4>(&pts, |v| v, |v| v, case.kernels.f64x4)[0],
            )
        }
    };
    let mut best = None::<f64>;
    for v in [y, lane] {
        if let Scored::Ulps(raw) = classify(v, exact, ty, 0.0) {
            let s = if ill { raw - kappa / 2.0 } else { raw };
            best = Some(best.map_or(s, |b| b.max(s)));
        }
    }
    best
}

/// `x` moved by `n` floats of `ty` (up for n > 0).
fn step(ty: Ty, mut x: f64, n: i32) -> f64 {
    for _ in 0..n.unsigned_abs() {
        x = if n > 0 {
            ty.next_up(x)
        } else {
            ty.next_down(x)
        };
    }
    x
}

/// Hill-climbs from the highest-scoring points of `prep`: each step moves one coordinate by
/// 1 to 1024 floats either way and keeps the move when the score rises (a coordinate that
/// only takes a few integer values, such as an output channel's index, is not moved). A
/// candidate must stay
/// inside the box the case's own points span in every coordinate (the sampled domain), have
/// a reference that is not NaN, and, for a function split by conditioning, stay on its half's
/// side of [`KAPPA_MAX`]. Every candidate evaluated joins the point set.
fn climb(case: &Case, ty: Ty, opts: Options, prep: &mut Prepared) {
    let ill = case.name.ends_with(ILL_CONDITIONED);
    let Some(first) = prep.points.first() else {
        return;
    };
    let dims = first.len();
    let lo: Vec<f64> = (0..dims)
        .map(|i| {
            prep.points
                .iter()
                .map(|p| p[i])
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    let hi: Vec<f64> = (0..dims)
        .map(|i| {
            prep.points
                .iter()
                .map(|p| p[i])
                .fold(f64::NEG_INFINITY, f64::max)
        })
        .collect();
    // A coordinate whose values are all among a few integers selects (an output channel,
    // say) rather than measures: the climb leaves it alone.
    let movable: Vec<usize> = (0..dims)
        .filter(|&i| {
            let mut seen: Vec<f64> = Vec::new();
            for p in &prep.points {
                if p[i].fract() != 0.0 || p[i].abs() > 16.0 {
                    return true;
                }
                if !seen.contains(&p[i]) {
                    seen.push(p[i]);
                }
            }
            seen.len() > 8
        })
        .collect();
    if movable.is_empty() {
        return;
    }
    let mut scored: Vec<(f64, usize)> = (0..prep.points.len())
        .filter_map(|i| {
            point_score(
                case,
                ty,
                &prep.points[i],
                &prep.refs[i],
                prep.kappas[i],
                ill,
            )
            .filter(|s| s.is_finite())
            .map(|s| (s, i))
        })
        .collect();
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    let (starts, budget) = CLIMB[usize::from(crate::points::deep())];
    let mut g = crate::points::Rng::fresh(&format!("{} climb {ty:?}", case.name));
    let starts: Vec<(f64, Vec<f64>)> = scored
        .iter()
        .take(starts)
        .map(|&(s, i)| (s, prep.points[i].clone()))
        .collect();
    for (mut best, mut cur) in starts {
        for _ in 0..budget {
            let i = movable[((g.uniform() * movable.len() as f64) as usize).min(movable.len() - 1)];
            let n = 1 << (g.uniform() * 11.0) as i32;
            let n = if g.uniform() < 0.5 { -n } else { n };
            let mut q = cur.clone();
            q[i] = step(ty, q[i], n);
            if !(q[i] >= lo[i] && q[i] <= hi[i]) {
                continue;
            }
            let prec = precision_for(&q, PREC);
            let args: Vec<Float> = q.iter().map(|&v| Float::with_val(prec, v)).collect();
            let r = (case.reference)(&args);
            if r.is_nan() {
                continue;
            }
            let kappa = if opts.split || ill {
                let k = condition(case.reference, ty, &q, case.perturbed);
                if (k > KAPPA_MAX) != ill {
                    continue;
                }
                if ill { k.max(1.0) } else { 1.0 }
            } else {
                1.0
            };
            let s = point_score(case, ty, &q, &r, kappa, ill);
            prep.points.push(q.clone());
            prep.refs.push(r);
            prep.kappas.push(kappa);
            if let Some(s) = s
                && s > best
            {
                best = s;
                cur = q;
            }
        }
    }
}

/// The working precision for the point `p`: `base` plus twice the largest binary exponent of
/// its arguments, so that sums such as 1 - c^2 are exact even for c = 1e-310 (where 256 bits
/// would round 1 - c^2 to 1 and turn sqrt(1 - sin^2) into 0).
#[must_use]
pub fn precision_for(p: &[f64], base: u32) -> u32 {
    let span = p
        .iter()
        .filter(|v| **v != 0.0)
        .map(|&v| Float::with_val(64, v).get_exp().unwrap_or(0).unsigned_abs())
        .max()
        .unwrap_or(0);
    base + 2 * span
}

fn references(case: &Case, pts: &[Vec<f64>], base: u32) -> Vec<Float> {
    pts.iter()
        .map(|p| {
            let prec = precision_for(p, base);
            let args: Vec<Float> = p.iter().map(|&v| Float::with_val(prec, v)).collect();
            (case.reference)(&args)
        })
        .collect()
}

/// Evaluates `lanes` (an `f32x8` or `f64x4` kernel) on `pts` in groups of `T::LANES`,
/// padding the last group with its last point, and returns one `f64` per point.
fn eval_lanes<T: Real>(
    pts: &[Vec<f64>],
    to_scalar: fn(f64) -> T::Scalar,
    from_scalar: fn(T::Scalar) -> f64,
    k: fn(&[T]) -> T,
) -> Vec<f64> {
    let mut out = Vec::with_capacity(pts.len());
    for chunk in pts.chunks(T::LANES) {
        let n_args = chunk[0].len();
        let args: Vec<T> = (0..n_args)
            .map(|a| T::from_fn(|i| to_scalar(chunk[i.min(chunk.len() - 1)][a])))
            .collect();
        let r = k(&args);
        out.extend((0..chunk.len()).map(|i| from_scalar(r.lane(i))));
    }
    out
}

/// Measures `case` on every lane type.
///
/// # Panics
/// If the reference is NaN at some point: the point set left the function's domain.
#[must_use]
pub fn measure(case: &Case, opts: Options) -> Measurement {
    let mut m = Measurement::default();
    let ill = case.name.ends_with(ILL_CONDITIONED);
    for ty in [Ty::F32, Ty::F64] {
        let Prepared {
            points: pts,
            refs,
            kappas,
        } = prepared(case, ty, opts);
        if let Some(i) = refs.iter().position(Float::is_nan) {
            panic!("{}: reference is NaN at {:?}", case.name, pts[i]);
        }
        if opts.check_reference {
            let fine = references(case, &pts, 2 * PREC);
            for (a, b) in refs.iter().zip(&fine) {
                let r = b.to_f64();
                if r.is_finite() && r.abs() >= Ty::F64.threshold() {
                    let d = in_ulps(Float::with_val(b.prec(), a - b), r, Ty::F64);
                    m.reference_drift = m.reference_drift.max(d);
                }
            }
        }
        let (scalar, lanes): (Vec<f64>, Option<Vec<f64>>) = match ty {
            Ty::F32 => (
                pts.iter()
                    .map(|p| {
                        let a: Vec<f32> = p.iter().map(|&v| v as f32).collect();
                        f64::from((case.kernels.f32)(&a))
                    })
                    .collect(),
                (!opts.scalars_only).then(|| {
                    eval_lanes::<f32x8>(&pts, |v| v as f32, f64::from, case.kernels.f32x8)
                }),
            ),
            Ty::F64 => (
                pts.iter().map(|p| (case.kernels.f64)(p)).collect(),
                (!opts.scalars_only)
                    .then(|| eval_lanes::<f64x4>(&pts, |v| v, |v| v, case.kernels.f64x4)),
            ),
        };
        let perturb = match ty {
            Ty::F32 => opts.perturb.0,
            Ty::F64 => opts.perturb.1,
        };
        let (s_stats, l_stats) = match ty {
            Ty::F32 => (&mut m.f32, &mut m.f32x8),
            Ty::F64 => (&mut m.f64, &mut m.f64x4),
        };
        for (i, p) in pts.iter().enumerate() {
            let kappa = kappas[i];
            s_stats.record(p, scalar[i], &refs[i], ty, perturb, kappa, ill);
            if let Some(l) = &lanes {
                l_stats.record(p, l[i], &refs[i], ty, perturb, kappa, ill);
            }
        }
    }
    m
}
