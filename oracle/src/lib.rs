//! A correctly rounded oracle for `brdf`'s exact functions.
//!
//! For each function, [`reference`](mod@reference) evaluates the published definition (the paper's equation,
//! not `brdf`'s rearrangement of it) with MPFR at [`PREC`] bits; [`harness`] runs `brdf`'s
//! kernel on `f32`, `f64`, `f32x8` and `f64x4` over the [`points`] of the function's
//! [`cases`] entry and measures the error in ULPs of the correctly rounded result;
//! [`bounds`] holds the bound each test asserts; [`table`] renders the measured table that
//! `docs/accuracy.md` publishes.
//!
//! Every run measures fresh random points (seeded from `BRDF_ORACLE_SEED` or the clock, and
//! printed), the committed [`hardest`] inputs and a short hill-climb from the worst points.
//!
//! Run: `cargo test -p brdf-oracle --release -- --nocapture` (needs GMP and MPFR: Debian's
//! `libgmp-dev` and `libmpfr-dev`). Deep search (10^5 fresh points per function
//! and type, a longer climb; tens of minutes) recording the hardest inputs:
//! `BRDF_ORACLE_DEEP=1 BRDF_ORACLE_RECORD=1 cargo test -p brdf-oracle --release --test accuracy_table -- --nocapture`.
//! Regenerate `docs/accuracy.md` from them:
//! `BLESS=1 cargo test -p brdf-oracle --release --test accuracy_table`.

pub mod bounds;
pub mod cases;
pub mod hardest;
pub mod harness;
pub mod points;
pub mod reference;
pub mod table;
pub mod tonemap_cases;
pub mod tonemap_ref;

/// Base working precision of the references, in bits; each point adds twice the largest binary
/// exponent of its arguments ([`harness::precision_for`]). Every reference is also evaluated
/// at twice that precision in `tests/harness.rs`; the two agree to far below one f64 ULP.
pub const PREC: u32 = 256;

/// Measures the case `name` on every lane type, prints its row (run with `--nocapture`), and
/// asserts its bounds from [`bounds::BOUNDS`] and that no point failed outright.
///
/// # Panics
/// When a bound is exceeded or a point fails: that is the test failing.
pub fn check(name: &str) {
    let case = cases::by_name(name);
    let m = harness::measure(
        &case,
        harness::Options {
            split: table::is_split(name),
            ..harness::Options::default()
        },
    );
    let b = bounds::bound(name);
    println!("{}", table::detail_header());
    println!("{}", table::detail_row(&case, &m, &b));
    let mut errors = Vec::new();
    for (ty, s, bound) in [
        ("f32", &m.f32, b.f32),
        ("f64", &m.f64, b.f64),
        ("f32x8", &m.f32x8, b.f32x8),
        ("f64x4", &m.f64x4, b.f64x4),
    ] {
        // NaN never occurs (a NaN result is recorded as inf), so `>` is the negation of `<=`.
        if s.max_ulp > bound {
            errors.push(format!(
                "{ty}: max {:.3} ulp > bound {bound} at {:?}",
                s.max_ulp, s.worst
            ));
        }
        if let Some((args, y, exact)) = &s.first_failure {
            errors.push(format!(
                "{ty}: {} failing points, first at {args:?}: got {y:e}, exact {exact:e}",
                s.failures
            ));
        }
    }
    assert!(
        errors.is_empty(),
        "{name} (fresh points from BRDF_ORACLE_SEED={}, {} build):\n{}",
        points::seed(),
        hardest::build(),
        errors.join("\n")
    );
}
