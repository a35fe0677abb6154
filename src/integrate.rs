//! Deterministic hemisphere integrators, for checking any BRDF the way this crate checks its own.
//!
//! | function | integral | expected for a physical model |
//! |---|---|---|
//! | [`hemisphere`] | integral of f(w) dw over the upper hemisphere | |
//! | [`directional_albedo`] | rho(wo) = integral f(wo, wi) cos(theta_i) dwi | <= 1 (energy) |
//! | [`ndf_projected_area`] | integral D(m) cos(theta_m) dm | = 1 (normalization) |
//! | [`smith_weak_furnace`] | integral G1(wo, m) D(m) max(0, wo.m) dm / cos(theta_o) | = 1 (Smith) |
//! | [`reciprocity`] | max relative \|f(a, b) - f(b, a)\| over direction pairs | = 0 |
//! | [`sphere`] | integral of f(w) dw over the whole sphere | |
//! | [`directional_albedo_sphere`] | integral f(wo, wi) \|cos(theta_i)\| dwi over the sphere (a BSDF with transmission) | <= 1 (energy) |
//!
//! All directions are unit vectors in the local shading frame (normal = +z). Each integrator
//! comes in two forms computed by one implementation:
//!
//! | form | closure | directions |
//! |---|---|---|
//! | [`directional_albedo`], [`hemisphere`], ... | `f64` kernel | [`V3<f64>`](crate::V3) |
//! | [`directional_albedo_f32`], [`hemisphere_f32`], ... | `f32` kernel | [`V3<f32>`](crate::V3) |
//!
//! The `_f32` form hands the kernel each direction rounded to `f32` and widens its result
//! to `f64`; the integration itself (abscissae, weights, sums, error estimate) is the `f64`
//! one, so an `f32` kernel's estimate differs from its `f64` twin's by the kernel's own
//! rounding only (`tests/integrate/generic.rs`). The directions are the crate's own
//! [`V3`], so a kernel of this crate takes them as they come; a kernel written on
//! glam's vectors converts each one with `into()` (`V3<f64>` into `DVec3`, `V3<f32>` into
//! `Vec3`):
//!
//! ```
//! use brdf::integrate::{directional_albedo, directional_albedo_f32};
//! use brdf::glam::DVec3;
//! use brdf::{Real, V3};
//!
//! // A Lambertian lobe of albedo 0.5, written once over `V3<T>`.
//! fn lambert<T: Real>(_wo: V3<T>, wi: V3<T>) -> T {
//!     T::splat(0.5) * T::FRAC_1_PI * T::select(wi.z.simd_gt(T::ZERO), T::ONE, T::ZERO)
//! }
//! let a64 = directional_albedo(V3::unit_z(), lambert);
//! let a32 = directional_albedo_f32(V3::unit_z(), lambert);
//! assert!((a64.value - 0.5).abs() < 1e-6);
//! assert!((a32.value - 0.5).abs() < 1e-6);
//!
//! // The same lobe written on glam's DVec3.
//! let glam_lambert = |_wo: DVec3, wi: DVec3| if wi.z > 0.0 { 0.5 / core::f64::consts::PI } else { 0.0 };
//! let g = directional_albedo(V3::unit_z(), |wo, wi| glam_lambert(wo.into(), wi.into()));
//! assert_eq!(g.value.to_bits(), a64.value.to_bits());
//! ```
//!
//! # Method
//! Globally adaptive cubature in spherical coordinates (theta in [0, pi/2], phi in [0, 2 pi],
//! integrand f(w) sin(theta)) with the degree-7 Genz-Malik rule and its embedded degree-5 rule:
//! 17 evaluations per rectangle, |I7 - I5| as the rectangle's error estimate, and the
//! rectangle with the largest error bisected next, along the axis whose fourth difference is
//! largest (Genz and Malik 1980, "An adaptive algorithm for numerical integration over an
//! N-dimensional rectangular region"; the axis rule is theirs, as used by Berntsen, Espelid and
//! Genz 1991 and S. G. Johnson's `cubature`).
//!
//! A purely adaptive rule never sees a lobe narrower than its sample spacing: a Beckmann lobe
//! with alpha = 0.01 is exactly zero 0.05 rad from its peak, so the first 17 samples of a coarse
//! rectangle can all miss it and report zero error. The initial partition is therefore graded
//! geometrically (offsets 0.001 to 0.256 rad) around the normal, around each `peaks` direction,
//! and around the tangent axes phi = 0, pi/2, pi, 3 pi/2 (where anisotropic NDFs put their
//! ridges). Every peak of a lobe of width >= 0.001 rad then falls within a few sample spacings
//! of a rectangle edge, and adaptivity does the rest.
//!
//! The error estimate |I7 - I5| is that of the degree-5 rule, so it is pessimistic for the
//! degree-7 value returned: the tests in `tests/integrate/accuracy.rs` show actual errors
//! below the reported ones on every known integral, and those in
//! `tests/integrate/error_estimates.rs` on anisotropic GGX and Beckmann lobes down to
//! alpha_x / alpha_y = 1/100 (normalization and signed projected area: estimate at least 10
//! times the actual error).
//!
//! Known flaw: a kink or jump that does not lie on a rectangle edge (a horizon cut, the
//! critical angle of total internal reflection) converges slowly and the estimate can miss it.
//! The hemispherical average of dielectric Fresnel at eta = 0.9 (a square-root kink on the
//! ring theta = 64 degrees) comes out 1.2e-4 too high. Where a kink lies just past a rectangle
//! edge, the sliver between the edge and the kink can hold none of the rectangle's 17 sample
//! points and is missed outright: the integral of max(0, cos(theta + 1.3)), whose kink is the
//! ring theta = 0.271 rad (edge at 0.256), comes out 1.8e-4 (0.9%) too low with an estimate
//! of 1.0e-9 (`tests/integrate/error_estimates.rs`).
//! [`smith_weak_furnace`], whose kink is known, scales its estimate by [`KINK_SAFETY`], which
//! the crate's tests show to be a bound on every closed form they try; for others, put a
//! `peaks` direction on the kink (on a ring this makes the estimate a bound again, in the same
//! tests) or integrate that dimension in closed range yourself.
//!
//! # Resources
//! No allocation: the rectangles live in a fixed array of [`CAPACITY`] entries on the stack
//! (about 230 KB). Refinement stops when the error meets the tolerance, when the evaluation
//! budget is spent, or when the array is full; the returned [`Estimate::error`] says how well
//! it went in every case.
//!
//! # Bad input
//! The integrators keep the crate's rule for bad input (crate docs, "Bad input") for every
//! argument, their [`Config`] included: a direction (`wo`, a `peaks` entry) with a NaN or
//! infinite component, or a tolerance that is NaN or negative, gives [`Estimate::NAN`] (value
//! and error NaN, no evaluation) instead of a plausible estimate of some other integral. A
//! tolerance of +inf is meaningful (stop after the initial partition) and 0 refines until
//! the budget is spent. What the integrand returns is summed as it is: a NaN from `f` makes
//! the value NaN.

use glam::DVec3;

use crate::V3;

/// Most rectangles an integration keeps at once (its stack use is `CAPACITY` x 56 bytes).
pub const CAPACITY: usize = 4096;

/// An integral's estimate and an estimate of its absolute error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The integral (degree-7 rule summed over the final partition).
    pub value: f64,
    /// Estimated absolute error: the sum over rectangles of |I7 - I5|, times [`KINK_SAFETY`]
    /// for [`smith_weak_furnace`]. Conservative on smooth integrands; a kink off the
    /// rectangle edges can hide from it (module docs).
    pub error: f64,
    /// Integrand evaluations spent.
    pub evaluations: u64,
}

impl Estimate {
    /// The estimate of bad input (module docs, "Bad input"): value and error NaN, no
    /// evaluation spent.
    pub const NAN: Self = Self {
        value: f64::NAN,
        error: f64::NAN,
        evaluations: 0,
    };
}

/// Stopping rule of the adaptive integrators. Both tolerances must be >= 0 (+inf allowed:
/// stop after the initial partition); a NaN or negative one makes every integrator return
/// [`Estimate::NAN`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// Stop once `error <= abs_tol`...
    pub abs_tol: f64,
    /// ...or once `error <= rel_tol * |value|`.
    pub rel_tol: f64,
    /// Stop before spending more than this many evaluations.
    pub max_evals: u64,
}

impl Default for Config {
    /// `abs_tol = 1e-10`, `rel_tol = 1e-7`, `max_evals = 2_000_000` (about 20 ms for a cheap
    /// integrand). Tolerances sit two orders below the accuracy the tests demand (1e-5 on
    /// smooth integrands, 1e-3 on peaked lobes) because the error estimate is conservative
    /// and refinement stops as soon as it is met.
    fn default() -> Self {
        Self {
            abs_tol: 1e-10,
            rel_tol: 1e-7,
            max_evals: 2_000_000,
        }
    }
}

impl Config {
    /// True where both tolerances are >= 0 (false for NaN).
    fn is_valid(&self) -> bool {
        self.abs_tol >= 0.0 && self.rel_tol >= 0.0
    }
}

/// True where every component of `w` is finite (false for NaN and +-inf).
fn finite_dir(w: DVec3) -> bool {
    w.x.is_finite() && w.y.is_finite() && w.z.is_finite()
}

/// `w` widened to `f64` (exact).
fn widen(w: V3<f32>) -> V3<f64> {
    w.map(f64::from)
}

/// `w` rounded to `f32` (to nearest).
fn narrow(w: DVec3) -> V3<f32> {
    V3::new(w.x as f32, w.y as f32, w.z as f32)
}

/// Genz-Malik abscissae for two dimensions (fractions of the half-width).
const LAMBDA2: f64 = 0.358_568_582_800_318_1; // sqrt(9/70)
const LAMBDA4: f64 = 0.948_683_298_050_513_8; // sqrt(9/10)
const LAMBDA5: f64 = 0.688_247_201_611_685_3; // sqrt(9/19)
/// Degree-7 weights for n = 2 (they sum to 1 over the 17 points; see the module docs).
const W7: [f64; 5] = [
    -3816.0 / 19683.0,
    980.0 / 6561.0,
    1020.0 / 19683.0,
    200.0 / 19683.0,
    6859.0 / 19683.0 / 4.0,
];
/// Embedded degree-5 weights for n = 2 (no lambda5 points).
const W5: [f64; 4] = [-971.0 / 729.0, 245.0 / 486.0, 65.0 / 1458.0, 25.0 / 729.0];

#[derive(Clone, Copy, Debug, Default)]
struct Rect {
    center: [f64; 2],
    half: [f64; 2],
    value: f64,
    error: f64,
    split_axis: usize,
}

/// The integrand in (theta, phi), including the sin(theta) Jacobian.
#[inline]
fn eval_polar(f: &mut impl FnMut(DVec3) -> f64, theta: f64, phi: f64) -> f64 {
    let (st, ct) = libm::sincos(theta);
    let (sp, cp) = libm::sincos(phi);
    f(DVec3::new(st * cp, st * sp, ct)) * st
}

/// Applies the Genz-Malik rule to a rectangle (17 evaluations).
fn rule(f: &mut impl FnMut(DVec3) -> f64, center: [f64; 2], half: [f64; 2]) -> Rect {
    let mut g = |a: f64, b: f64| eval_polar(f, center[0] + a * half[0], center[1] + b * half[1]);
    let f0 = g(0.0, 0.0);
    let mut d2 = [0.0; 2];
    let mut d4 = [0.0; 2];
    d2[0] = g(LAMBDA2, 0.0) + g(-LAMBDA2, 0.0);
    d2[1] = g(0.0, LAMBDA2) + g(0.0, -LAMBDA2);
    d4[0] = g(LAMBDA4, 0.0) + g(-LAMBDA4, 0.0);
    d4[1] = g(0.0, LAMBDA4) + g(0.0, -LAMBDA4);
    let s4 =
        g(LAMBDA4, LAMBDA4) + g(LAMBDA4, -LAMBDA4) + g(-LAMBDA4, LAMBDA4) + g(-LAMBDA4, -LAMBDA4);
    let s5 =
        g(LAMBDA5, LAMBDA5) + g(LAMBDA5, -LAMBDA5) + g(-LAMBDA5, LAMBDA5) + g(-LAMBDA5, -LAMBDA5);
    let (s2, s3) = (d2[0] + d2[1], d4[0] + d4[1]);
    let volume = 4.0 * half[0] * half[1];
    let i7 = volume * (W7[0] * f0 + W7[1] * s2 + W7[2] * s3 + W7[3] * s4 + W7[4] * s5);
    let i5 = volume * (W5[0] * f0 + W5[1] * s2 + W5[2] * s3 + W5[3] * s4);
    // Fourth divided difference along each axis: large where the integrand is far from a cubic
    // along that axis. The ratio lambda2^2 / lambda4^2 = 1/7 cancels the quadratic term.
    let diff = |i: usize| ((d2[i] - 2.0 * f0) - (d4[i] - 2.0 * f0) / 7.0).abs();
    let (dx, dy) = (diff(0), diff(1));
    // Ties (common for integrands smooth along both axes) go to the longer side.
    let split_axis = if dx > dy || (dx == dy && half[0] >= half[1]) {
        0
    } else {
        1
    };
    // A NaN anywhere makes the error NaN; keep it at the top of the heap so it is visible.
    let error = (i7 - i5).abs();
    Rect {
        center,
        half,
        value: i7,
        error: if error.is_nan() { f64::INFINITY } else { error },
        split_axis,
    }
}

/// A binary max-heap of rectangles by error, in a fixed array.
struct Heap {
    items: [Rect; CAPACITY],
    len: usize,
}

impl Heap {
    fn push(&mut self, r: Rect) -> bool {
        if self.len == CAPACITY {
            return false;
        }
        let mut i = self.len;
        self.items[i] = r;
        self.len += 1;
        while i > 0 {
            let parent = (i - 1) / 2;
            if self.items[parent].error >= self.items[i].error {
                break;
            }
            self.items.swap(parent, i);
            i = parent;
        }
        true
    }

    /// Removes and returns the rectangle with the largest error (callers check `len > 0`).
    fn pop(&mut self) -> Rect {
        let top = self.items[0];
        self.len -= 1;
        self.items[0] = self.items[self.len];
        let mut i = 0;
        loop {
            let (l, r) = (2 * i + 1, 2 * i + 2);
            let mut largest = i;
            if l < self.len && self.items[l].error > self.items[largest].error {
                largest = l;
            }
            if r < self.len && self.items[r].error > self.items[largest].error {
                largest = r;
            }
            if largest == i {
                break;
            }
            self.items.swap(i, largest);
            i = largest;
        }
        top
    }
}

/// Geometric grading offsets (radians) placed on both sides of every special direction.
const GRADING: [f64; 5] = [0.001, 0.004, 0.016, 0.064, 0.256];
/// At most this many `peaks` shape the initial partition (more would not fit [`CAPACITY`]).
pub const MAX_PEAKS: usize = 4;
const MAX_BREAKS: usize = 64;

/// Sorted, deduplicated breakpoints in [lo, hi].
struct Breaks {
    v: [f64; MAX_BREAKS],
    len: usize,
}

impl Breaks {
    fn new(lo: f64, hi: f64) -> Self {
        let mut b = Self {
            v: [0.0; MAX_BREAKS],
            len: 0,
        };
        b.add(lo, lo, hi);
        b.add(hi, lo, hi);
        b
    }
    fn add(&mut self, x: f64, lo: f64, hi: f64) {
        if self.len < MAX_BREAKS && x >= lo && x <= hi && x.is_finite() {
            self.v[self.len] = x;
            self.len += 1;
        }
    }
    fn graded_around(&mut self, x: f64, scale: f64, lo: f64, hi: f64) {
        self.add(x, lo, hi);
        for d in GRADING {
            self.add(x - d * scale, lo, hi);
            self.add(x + d * scale, lo, hi);
        }
    }
    fn finish(&mut self) -> &[f64] {
        let s = &mut self.v[..self.len];
        s.sort_unstable_by(f64::total_cmp);
        // Drop breakpoints closer than 1e-9 rad: zero-width rectangles add evaluations, not
        // accuracy.
        let mut n = 0;
        for i in 0..s.len() {
            if n == 0 || s[i] - s[n - 1] > 1e-9 {
                s[n] = s[i];
                n += 1;
            }
        }
        self.len = n;
        &self.v[..n]
    }
}

/// Integral of `f(w)` over the upper unit hemisphere (w.z >= 0) with respect to solid angle.
///
/// `peaks`: directions where `f` may be sharply peaked (a mirror direction, a light); the first
/// [`MAX_PEAKS`] shape the initial partition, the normal always does. `f` is called only with
/// unit vectors with z >= 0 (z = 0 never occurs: the rule's points are interior).
///
/// Accuracy (tests/integrate/accuracy.rs): 1e-5 absolute or better on smooth integrands and
/// 1e-3 relative on lobes as narrow as alpha = 0.01 or cos^10000, with [`Config::default`].
///
/// Bad input: a peak with a NaN or infinite component (among the first [`MAX_PEAKS`]) or an
/// invalid `cfg` (a NaN or negative tolerance) gives [`Estimate::NAN`] without calling `f`.
#[must_use]
pub fn hemisphere(mut f: impl FnMut(V3<f64>) -> f64, peaks: &[V3<f64>], cfg: &Config) -> Estimate {
    let mut p = [DVec3::ZERO; MAX_PEAKS];
    let n = peaks.len().min(MAX_PEAKS);
    for (w, q) in p.iter_mut().zip(peaks) {
        *w = DVec3::from(*q);
    }
    hemisphere_glam(|w| f(w.into()), &p[..n], cfg)
}

/// [`hemisphere`] on glam's vectors, which the integration's own arithmetic uses.
fn hemisphere_glam(mut f: impl FnMut(DVec3) -> f64, peaks: &[DVec3], cfg: &Config) -> Estimate {
    use core::f64::consts::{FRAC_PI_2, PI, TAU};
    // Without these, a NaN tolerance stops refinement at once (every comparison is false) and
    // a NaN peak poisons the partition, both with a plausible finite estimate.
    if !cfg.is_valid() || !peaks.iter().take(MAX_PEAKS).all(|&p| finite_dir(p)) {
        return Estimate::NAN;
    }
    let mut thetas = Breaks::new(0.0, FRAC_PI_2);
    let mut phis = Breaks::new(0.0, TAU);
    thetas.graded_around(0.0, 1.0, 0.0, FRAC_PI_2);
    for axis in [FRAC_PI_2, PI, 3.0 * FRAC_PI_2] {
        phis.add(axis, 0.0, TAU);
    }
    for axis in [0.0, FRAC_PI_2, PI, 3.0 * FRAC_PI_2, TAU] {
        for d in &GRADING[1..] {
            phis.add(axis - d, 0.0, TAU);
            phis.add(axis + d, 0.0, TAU);
        }
    }
    for p in peaks.iter().take(MAX_PEAKS) {
        let p = p.normalize_or_zero();
        if p.z <= 0.0 {
            continue;
        }
        let sin_t = libm::hypot(p.x, p.y);
        let theta = libm::atan2(sin_t, p.z);
        thetas.graded_around(theta, 1.0, 0.0, FRAC_PI_2);
        if sin_t > 1e-6 {
            let phi = libm::atan2(p.y, p.x);
            let phi = if phi < 0.0 { phi + TAU } else { phi };
            // An offset d on the sphere is d / sin(theta) in phi; cap the scale so the grading
            // does not wrap the whole circle near the pole.
            phis.graded_around(phi, (1.0 / sin_t).min(8.0), 0.0, TAU);
        }
    }

    let mut heap = Heap {
        items: [Rect::default(); CAPACITY],
        len: 0,
    };
    let (mut value, mut error, mut evals) = (0.0, 0.0, 0u64);
    let ts = thetas.finish();
    let ps = phis.finish();
    for t in ts.windows(2) {
        for p in ps.windows(2) {
            let r = rule(
                &mut f,
                [0.5 * (t[0] + t[1]), 0.5 * (p[0] + p[1])],
                [0.5 * (t[1] - t[0]), 0.5 * (p[1] - p[0])],
            );
            evals += 17;
            value += r.value;
            error += r.error;
            // The partition is sized to fit; a rectangle that does not fit still counts in
            // `value` and `error`, it just cannot be refined.
            let _ = heap.push(r);
        }
    }

    while heap.len > 0
        && error > cfg.abs_tol
        && error > cfg.rel_tol * value.abs()
        && evals + 34 <= cfg.max_evals
        && heap.len < CAPACITY
    {
        let r = heap.pop();
        let mut half = r.half;
        half[r.split_axis] *= 0.5;
        let mut c_lo = r.center;
        let mut c_hi = r.center;
        c_lo[r.split_axis] -= half[r.split_axis];
        c_hi[r.split_axis] += half[r.split_axis];
        let a = rule(&mut f, c_lo, half);
        let b = rule(&mut f, c_hi, half);
        evals += 34;
        value += a.value + b.value - r.value;
        error += a.error + b.error - r.error;
        let _ = heap.push(a);
        let _ = heap.push(b);
    }
    // Re-sum: the running sums above accumulate rounding over thousands of updates.
    let (mut v, mut e) = (0.0, 0.0);
    for r in &heap.items[..heap.len] {
        v += r.value;
        e += r.error;
    }
    Estimate {
        value: v,
        error: e.max(0.0),
        evaluations: evals,
    }
}

/// [`hemisphere`] for an `f32` integrand over [`V3<f32>`]: `f` sees each direction rounded
/// to `f32`, its result is widened to `f64`, and everything else is [`hemisphere`]'s.
///
/// ```
/// use brdf::integrate::{hemisphere_f32, Config};
/// use brdf::V3;
/// // Integral of cos(theta) over the hemisphere: pi.
/// let e = hemisphere_f32(|w: V3<f32>| w.z, &[], &Config::default());
/// assert!((e.value - core::f64::consts::PI).abs() < 1e-6);
/// ```
#[must_use]
pub fn hemisphere_f32(
    mut f: impl FnMut(V3<f32>) -> f32,
    peaks: &[V3<f32>],
    cfg: &Config,
) -> Estimate {
    let mut p = [DVec3::ZERO; MAX_PEAKS];
    let n = peaks.len().min(MAX_PEAKS);
    for (w, q) in p.iter_mut().zip(peaks) {
        *w = widen(*q).into();
    }
    hemisphere_glam(|w| f64::from(f(narrow(w))), &p[..n], cfg)
}

/// Mirror direction of a local-frame `wo` about the normal: `(-wo.x, -wo.y, wo.z)`.
#[inline]
fn mirror(wo: DVec3) -> DVec3 {
    DVec3::new(-wo.x, -wo.y, wo.z)
}

/// Directional albedo rho(wo) = integral over the upper hemisphere of f(wo, wi) cos(theta_i) dwi,
/// with [`Config::default`].
///
/// `f(wo, wi)` is the BRDF with both directions pointing away from the surface. A physical
/// BRDF has rho(wo) <= 1 for every wo (white furnace); a Lambertian surface of albedo a has
/// rho = a. The normal and the mirror direction of `wo` are treated as peaks. A NaN or
/// infinite component of `wo` gives [`Estimate::NAN`] (module docs, "Bad input").
#[must_use]
pub fn directional_albedo(wo: V3<f64>, f: impl FnMut(V3<f64>, V3<f64>) -> f64) -> Estimate {
    directional_albedo_with(wo, f, &Config::default())
}

/// [`directional_albedo`] with an explicit [`Config`]; an invalid `cfg` or a non-finite `wo`
/// gives [`Estimate::NAN`].
#[must_use]
pub fn directional_albedo_with(
    wo: V3<f64>,
    mut f: impl FnMut(V3<f64>, V3<f64>) -> f64,
    cfg: &Config,
) -> Estimate {
    let wo_g = DVec3::from(wo);
    // `f` may ignore wo (a Lambertian lobe): a NaN view must still give NaN.
    if !finite_dir(wo_g) {
        return Estimate::NAN;
    }
    hemisphere_glam(|wi| f(wo, wi.into()) * wi.z, &[mirror(wo_g)], cfg)
}

/// [`directional_albedo`] for an `f32` BRDF over [`V3<f32>`] (see [`hemisphere_f32`]).
///
/// ```
/// use brdf::integrate::directional_albedo_f32;
/// use brdf::V3;
/// let rho = directional_albedo_f32(V3::unit_z(), |_wo, _wi| 0.8 / core::f32::consts::PI);
/// assert!((rho.value - 0.8).abs() < 1e-6);
/// ```
#[must_use]
pub fn directional_albedo_f32(wo: V3<f32>, f: impl FnMut(V3<f32>, V3<f32>) -> f32) -> Estimate {
    directional_albedo_with_f32(wo, f, &Config::default())
}

/// [`directional_albedo_with`] for an `f32` BRDF over [`V3<f32>`] (see [`hemisphere_f32`]).
#[must_use]
pub fn directional_albedo_with_f32(
    wo: V3<f32>,
    mut f: impl FnMut(V3<f32>, V3<f32>) -> f32,
    cfg: &Config,
) -> Estimate {
    directional_albedo_with(widen(wo), |_, i| f64::from(f(wo, narrow(i.into()))), cfg)
}

/// Projected area of a microfacet distribution: integral of D(m) cos(theta_m) dm over the upper
/// hemisphere, which is 1 for a normalized NDF (Torrance and Sparrow 1967; Walter et al. 2007,
/// "Microfacet Models for Refraction through Rough Surfaces", eq. 4).
#[must_use]
pub fn ndf_projected_area(mut d: impl FnMut(V3<f64>) -> f64) -> Estimate {
    hemisphere_glam(|m| d(m.into()) * m.z, &[], &Config::default())
}

/// [`ndf_projected_area`] for an `f32` NDF over [`V3<f32>`] (see [`hemisphere_f32`]).
///
/// ```
/// use brdf::integrate::ndf_projected_area_f32;
/// // The cosine-lobe "NDF" D(m) = 1 / pi is normalized: integral of cos / pi = 1.
/// let e = ndf_projected_area_f32(|_m| core::f32::consts::FRAC_1_PI);
/// assert!((e.value - 1.0).abs() < 1e-6);
/// ```
#[must_use]
pub fn ndf_projected_area_f32(mut d: impl FnMut(V3<f32>) -> f32) -> Estimate {
    hemisphere_glam(|m| f64::from(d(narrow(m))) * m.z, &[], &Config::default())
}

/// Smith's weak white furnace: integral of G1(wo, m) D(m) max(0, wo.m) dm / cos(theta_o), which
/// is 1 for every wo when G1 is the Smith masking function of D (Heitz 2014, "Understanding the
/// Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 18 and section 5).
///
/// `wo` must have `wo.z > 0`; for `wo.z <= 0` the result is [`Estimate::NAN`] (the integral
/// is undefined), and so it is for a NaN or infinite component of `wo` (module docs, "Bad
/// input"; the tangent components set the kink, so a NaN there is not a plausible 1).
/// The normal and `wo` itself are treated as peaks (for grazing `wo` the visible normals
/// concentrate towards it).
///
/// The integrand has a kink along the great circle wo.m = 0, where the embedded-rule estimate
/// |I7 - I5| can under-report: by 44x on the GGX cases of `tests/integrate/accuracy.rs`
/// (alpha 0.2, theta_o = 80 degrees: actual 4.4e-6, raw estimate 1.0e-7) and by up to 1.1e3x
/// on Beckmann (alpha 1, theta_o = 89.8 degrees: actual 1.1e-4, raw estimate 1.0e-7). The
/// returned error is therefore [`KINK_SAFETY`] times the raw estimate: about 1e-3 of the
/// value once refinement has met its tolerance, an honest bound but a loose one, as the
/// actual error is usually below 1e-7.
#[must_use]
pub fn smith_weak_furnace(
    wo: V3<f64>,
    mut d: impl FnMut(V3<f64>) -> f64,
    mut g1: impl FnMut(V3<f64>, V3<f64>) -> f64,
) -> Estimate {
    let wo_g = DVec3::from(wo);
    if wo.z <= 0.0 || !finite_dir(wo_g) {
        return Estimate::NAN;
    }
    let e = hemisphere_glam(
        |m| {
            let wo_dot_m = wo_g.dot(m);
            if wo_dot_m > 0.0 {
                g1(wo, m.into()) * d(m.into()) * wo_dot_m
            } else {
                0.0
            }
        },
        &[wo_g],
        &Config::default(),
    );
    Estimate {
        value: e.value / wo.z,
        error: KINK_SAFETY * e.error / wo.z,
        evaluations: e.evaluations,
    }
}

/// [`smith_weak_furnace`] for an `f32` NDF and masking function over [`V3<f32>`] (see
/// [`hemisphere_f32`]). `wo` is widened to `f64` for the integration, and `g1` receives it
/// as given.
///
/// ```
/// use brdf::integrate::smith_weak_furnace_f32;
/// use brdf::V3;
/// // D = 1 / pi on the upper hemisphere with G1 = 1 at normal incidence: 1.
/// let e = smith_weak_furnace_f32(V3::unit_z(), |_m| core::f32::consts::FRAC_1_PI, |_wo, _m| 1.0);
/// assert!((e.value - 1.0).abs() < 1e-5);
/// ```
#[must_use]
pub fn smith_weak_furnace_f32(
    wo: V3<f32>,
    mut d: impl FnMut(V3<f32>) -> f32,
    mut g1: impl FnMut(V3<f32>, V3<f32>) -> f32,
) -> Estimate {
    smith_weak_furnace(
        widen(wo),
        |m| f64::from(d(narrow(m.into()))),
        |_, m| f64::from(g1(wo, narrow(m.into()))),
    )
}

/// Factor applied to the error estimate of integrands with a known kink (see
/// [`smith_weak_furnace`]): the largest under-report measured, 1.1e3, rounded up to the next
/// power of ten.
///
/// Where the kink circle cuts a rectangle just inside its edge, the part of the integrand
/// between the edge and the first row of sample points is never seen and the rectangle
/// reports almost no error for it, so the raw |I7 - I5| can fall three orders of magnitude
/// short. The factor is read off a sweep of 34 020 GGX and Beckmann weak furnaces (theta_o in
/// 0.02 degree steps over 73 to 76.5, 85.5 to 87 and 88.6 to 89.9 degrees, six azimuths,
/// alpha 0.15 to 1), whose worst raw under-reports are 1.1e3x (Beckmann alpha 1 at 89.8
/// degrees) and 990x (alpha 0.25 at 74.66 degrees, the kink's top 0.012 rad past an edge).
///
/// Evidence, from the crate's tests (`tests/integrate/error_estimates.rs`, which also hold
/// the sweep as an ignored test): on closed forms not used to choose it (the Beckmann weak
/// furnace for alpha from ALPHA_MIN = 1e-4 to 1 and theta_o up to 89 degrees, the clamped
/// cosine max(0, wo.m) as a furnace with D = 1 / pi and G1 = 1 up to 89.8 degrees, and
/// anisotropic GGX and Beckmann furnaces with alpha_x / alpha_y from 1/100 to 100) the
/// returned error is at least 139 times the actual error (the clamped cosine at 74.66
/// degrees), and on the sweep's two worst cases at least 9.0 times. With the former factor,
/// 100, those two cases under-reported by 10x and 11x.
pub const KINK_SAFETY: f64 = 1e4;

/// Result of [`reciprocity`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reciprocity {
    /// Largest |f(a, b) - f(b, a)| / max(|f(a, b)|, |f(b, a)|) over the pairs (pairs where both
    /// are zero count as 0; a non-finite value counts as +inf).
    pub max_rel: f64,
    /// The pair (a, b) where `max_rel` occurred.
    pub worst: (V3<f64>, V3<f64>),
    /// Number of ordered pairs checked.
    pub pairs: u64,
}

/// Directions of the reciprocity set: a Fibonacci spiral over the hemisphere (even coverage in
/// solid angle) plus near-normal and near-grazing directions, where asymmetric terms hide.
fn reciprocity_direction(i: usize) -> DVec3 {
    const SPIRAL: usize = 56;
    // Golden angle, so consecutive points never line up.
    const GOLDEN: f64 = 2.399_963_229_728_653;
    if i < SPIRAL {
        let z = 1.0 - (i as f64 + 0.5) / SPIRAL as f64;
        let r = libm::sqrt((1.0 - z * z).max(0.0));
        let (s, c) = libm::sincos(GOLDEN * i as f64);
        DVec3::new(r * c, r * s, z)
    } else {
        let j = i - SPIRAL;
        let z: f64 = [1.0, 0.999_999, 0.9999, 1e-3, 1e-5, 0.05, 0.5, 0.95][j % 8];
        let r = libm::sqrt((1.0 - z * z).max(0.0));
        let (s, c) = libm::sincos(0.7 + 1.3 * j as f64);
        DVec3::new(r * c, r * s, z)
    }
}

/// Number of directions in the reciprocity set (so `pairs = N * (N - 1)`).
pub const RECIPROCITY_DIRECTIONS: usize = 64;

/// Reciprocity check: the largest relative |f(a, b) - f(b, a)| over every ordered pair of
/// distinct directions of a fixed set of [`RECIPROCITY_DIRECTIONS`] upper-hemisphere
/// directions (Helmholtz reciprocity: a physical BRDF has f(a, b) = f(b, a)).
///
/// A maximum over a finite set, not an integral: it has no error estimate, and a zero result
/// shows symmetry on these pairs only.
#[must_use]
pub fn reciprocity(mut f: impl FnMut(V3<f64>, V3<f64>) -> f64) -> Reciprocity {
    let mut out = Reciprocity {
        max_rel: 0.0,
        worst: (V3::unit_z(), V3::unit_z()),
        pairs: 0,
    };
    for i in 0..RECIPROCITY_DIRECTIONS {
        for j in 0..RECIPROCITY_DIRECTIONS {
            if i == j {
                continue;
            }
            let (a, b) = (
                V3::from(reciprocity_direction(i)),
                V3::from(reciprocity_direction(j)),
            );
            let (ab, ba) = (f(a, b), f(b, a));
            out.pairs += 1;
            let rel = if !ab.is_finite() || !ba.is_finite() {
                f64::INFINITY
            } else {
                let scale = ab.abs().max(ba.abs());
                if scale == 0.0 {
                    0.0
                } else {
                    (ab - ba).abs() / scale
                }
            };
            if rel > out.max_rel {
                out.max_rel = rel;
                out.worst = (a, b);
            }
        }
    }
    out
}

/// [`reciprocity`] for an `f32` BRDF over [`V3<f32>`]: `f` sees the same direction set
/// rounded to `f32` (both orders of a pair see the same two vectors), and
/// [`Reciprocity::worst`] reports the `f64` directions they were rounded from.
///
/// ```
/// use brdf::integrate::reciprocity_f32;
/// use brdf::V3;
/// // Phong-like, symmetric in its arguments: reciprocal to the last bit.
/// let r = reciprocity_f32(|a: V3<f32>, b: V3<f32>| (a.z * b.z).max(0.0).powi(8));
/// assert_eq!(r.max_rel, 0.0);
/// ```
#[must_use]
pub fn reciprocity_f32(mut f: impl FnMut(V3<f32>, V3<f32>) -> f32) -> Reciprocity {
    reciprocity(|a, b| f64::from(f(narrow(a.into()), narrow(b.into()))))
}

/// Integral of `f(w)` over the whole unit sphere with respect to solid angle: the upper
/// hemisphere and the lower one (w.z <= 0), each by [`hemisphere`]'s method and `cfg`, the
/// lower one through the mirror w -> (w.x, w.y, -w.z). For BSDFs that transmit (a rough
/// dielectric), whose lobes lie on both sides.
///
/// `peaks`: directions where `f` may be peaked, on either side; each shapes the partition of
/// its own hemisphere (the first [`MAX_PEAKS`] of each side count). `f` is called only with
/// unit vectors off the horizon. The value is the sum of the halves' values and the error the
/// sum of their errors, so the accuracy is [`hemisphere`]'s on each half, and its known flaw
/// (a kink off the partition's edges, such as the critical angle of total internal
/// reflection) applies: put a peak on such a ring.
///
/// Bad input: a peak with a NaN or infinite component or an invalid `cfg` gives
/// [`Estimate::NAN`] without calling `f`.
///
/// ```
/// use brdf::integrate::{Config, sphere};
/// use brdf::V3;
/// // The sphere's area, and the integral of |cos(theta)| over it: 4 pi and 2 pi.
/// let area = sphere(|_w: V3<f64>| 1.0, &[], &Config::default());
/// let cos = sphere(|w: V3<f64>| w.z.abs(), &[], &Config::default());
/// assert!((area.value - 4.0 * core::f64::consts::PI).abs() < 1e-9);
/// assert!((cos.value - 2.0 * core::f64::consts::PI).abs() < 1e-9);
/// ```
#[must_use]
pub fn sphere(mut f: impl FnMut(V3<f64>) -> f64, peaks: &[V3<f64>], cfg: &Config) -> Estimate {
    let (mut up, mut down) = ([DVec3::ZERO; MAX_PEAKS], [DVec3::ZERO; MAX_PEAKS]);
    let (mut nu, mut nd) = (0, 0);
    for q in peaks {
        let q = DVec3::from(*q);
        if !finite_dir(q) {
            return Estimate::NAN;
        }
        if q.z >= 0.0 && nu < MAX_PEAKS {
            up[nu] = q;
            nu += 1;
        } else if q.z < 0.0 && nd < MAX_PEAKS {
            down[nd] = DVec3::new(q.x, q.y, -q.z);
            nd += 1;
        }
    }
    let a = hemisphere_glam(|w| f(w.into()), &up[..nu], cfg);
    let b = hemisphere_glam(|w| f(DVec3::new(w.x, w.y, -w.z).into()), &down[..nd], cfg);
    Estimate {
        value: a.value + b.value,
        error: a.error + b.error,
        evaluations: a.evaluations + b.evaluations,
    }
}

/// [`sphere`] for an `f32` integrand over [`V3<f32>`] (see [`hemisphere_f32`]).
#[must_use]
pub fn sphere_f32(mut f: impl FnMut(V3<f32>) -> f32, peaks: &[V3<f32>], cfg: &Config) -> Estimate {
    let mut p = [V3::new(0.0, 0.0, 0.0); 2 * MAX_PEAKS];
    let n = peaks.len().min(2 * MAX_PEAKS);
    for (w, q) in p.iter_mut().zip(peaks) {
        *w = widen(*q);
    }
    sphere(|w| f64::from(f(narrow(w.into()))), &p[..n], cfg)
}

/// The scattering albedo of a BSDF with transmission: integral over the whole sphere of
/// f(wo, wi) |cos(theta_i)| dwi ([`sphere`] with [`Config::default`]), at most 1 for a
/// physical BSDF in the direction the energy flows (for a refracting BSDF, the importance form
/// whose first argument is the light's direction: `rough_dielectric::Transport`). The mirror
/// direction of `wo` and the `peaks` given (a refracted direction, a critical-angle ring's
/// point) shape the partition. A NaN or infinite component of `wo` or of a peak gives
/// [`Estimate::NAN`].
///
/// ```
/// use brdf::integrate::directional_albedo_sphere;
/// use brdf::V3;
/// // A "Lambertian" BSDF that scatters half of the light to each side: albedo 1.
/// let e = directional_albedo_sphere(V3::unit_z(), |_wo, _wi| 0.5 / core::f64::consts::PI, &[]);
/// assert!((e.value - 1.0).abs() < 1e-9);
/// ```
#[must_use]
pub fn directional_albedo_sphere(
    wo: V3<f64>,
    mut f: impl FnMut(V3<f64>, V3<f64>) -> f64,
    peaks: &[V3<f64>],
) -> Estimate {
    let wo_g = DVec3::from(wo);
    if !finite_dir(wo_g) {
        return Estimate::NAN;
    }
    let mut p = [V3::new(0.0, 0.0, 0.0); 2 * MAX_PEAKS];
    p[0] = mirror(wo_g).into();
    let n = 1 + peaks.len().min(2 * MAX_PEAKS - 1);
    for (w, q) in p[1..].iter_mut().zip(peaks) {
        *w = *q;
    }
    sphere(|wi| f(wo, wi) * wi.z.abs(), &p[..n], &Config::default())
}
