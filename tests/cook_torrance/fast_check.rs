//! Shared by the working-precision tiers' tests (`fast_tier`, `fast_dielectric`): the random
//! directions their inputs are drawn from and the relative-error sweep against the exact tier.
#![cfg(all(feature = "ggx", feature = "cook-torrance"))]

pub use crate::common::random_dir;

/// |x - r| / |r|, 0 where x equals r (both 0 included).
fn rel(x: f64, r: f64) -> f64 {
    if x == r { 0.0 } else { (x - r).abs() / r.abs() }
}

/// The largest relative errors seen, in f32 and f64.
#[derive(Default)]
pub struct Worst {
    w32: f64,
    w64: f64,
}

impl Worst {
    /// One f32 result `fast` against the exact tier's `exact`. Results below f32's smallest
    /// normal carry an absolute, not relative, error: skipped.
    pub fn f32(&mut self, fast: f32, exact: f32) {
        if exact.abs() >= f32::MIN_POSITIVE {
            self.w32 = self.w32.max(rel(f64::from(fast), f64::from(exact)));
        }
    }

    /// One f64 result `fast` against the exact tier's `exact`.
    pub fn f64(&mut self, fast: f64, exact: f64) {
        self.w64 = self.w64.max(rel(fast, exact));
    }
}

/// The fast tier within its documented relative bounds (`bound`: f32, f64) of the exact tier
/// over `inputs(n)`, n = 400 000 points or `BRDF_FAST_TIER_POINTS`: `compare` feeds each
/// point's (fast, exact) pairs to [`Worst`]. Prints "`what`, fast tier against the exact tier
/// over n points`note`: relative ... (f32), ... (f64)".
pub fn within_bound<X>(
    what: &str,
    note: &str,
    bound: [f64; 2],
    inputs: impl Fn(usize) -> Vec<X>,
    compare: impl Fn(&X, &mut Worst),
) {
    let n = std::env::var("BRDF_FAST_TIER_POINTS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(400_000);
    let mut worst = Worst::default();
    for x in inputs(n) {
        compare(&x, &mut worst);
    }
    let Worst { w32, w64 } = worst;
    println!(
        "{what}, fast tier against the exact tier over {n} points{note}: relative {w32:.2e} (f32), {w64:.2e} (f64)"
    );
    assert!(w32 <= bound[0], "f32 {w32:e}");
    assert!(w64 <= bound[1], "f64 {w64:e}");
}
