//! The prefilter kernels keep the crate's bad-input rule on f32, f64, f32x8 and f64x4: NaN in
//! any input (or alpha < 0 or +inf) gives a NaN direction, weight and pdf. Lanes equal
//! scalars within 6 ULP for directions and weights (measured 4) and 16 for pdfs (measured
//! 5.5): the lanes' sin and cos are within 1 ULP of libm's (src/real.rs), and D amplifies
//! the difference. Every finite alpha, up to the largest float, gives unit directions with
//! finite weights and pdfs.
#![cfg(feature = "ibl")]

use brdf::ibl::prefilter::{self, PrefilterSample};
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

fn all_nan<T: Real>(s: PrefilterSample<T>) -> bool {
    (0..T::LANES).all(|i| {
        let d = s.dir.lane(i);
        let nan = |x: T::Scalar| x.is_nan();
        nan(d.x) && nan(d.y) && nan(d.z) && nan(s.weight.lane(i)) && nan(s.pdf.lane(i))
    })
}

fn check_nan<T: Real>(name: &str) {
    let nan = T::splat(f64::NAN);
    let (u, a) = (T::splat(0.3), T::splat(0.4));
    for (what, s) in [
        ("u1", prefilter::sample_from(nan, u, a)),
        ("u2", prefilter::sample_from(u, nan, a)),
        ("alpha", prefilter::sample_from(u, u, nan)),
        ("alpha < 0", prefilter::sample_from(u, u, T::splat(-0.1))),
        ("alpha = inf", prefilter::sample_from(u, u, T::INFINITY)),
        ("i >= n", prefilter::sample(9, 9, a)),
    ] {
        assert!(all_nan(s), "{name}: NaN {what} gave {s:?}");
    }
    let d = V3::new(T::ZERO, T::ZERO, T::ONE);
    let p = prefilter::pdf(V3::new(nan, T::ZERO, T::ONE), a);
    let q = prefilter::pdf(d, T::splat(-1.0));
    for i in 0..T::LANES {
        assert!(p.lane(i).is_nan() && q.lane(i).is_nan(), "{name} pdf");
    }
}

#[test]
fn prefilter_nan_in_gives_nan_out_on_every_type() {
    check_nan::<f32>("f32");
    check_nan::<f64>("f64");
    check_nan::<f32x8>("f32x8");
    check_nan::<f64x4>("f64x4");
}

/// |a - b| within `ulps` units of the larger magnitude (1 for directions, whose components
/// are at most 1 in magnitude).
fn close(a: f64, b: f64, eps: f64, ulps: f64) -> bool {
    (a - b).abs() <= ulps * eps * a.abs().max(b.abs()).max(1e-300) || (a - b).abs() <= ulps * eps
}

/// The pdf D(h) / 4 amplifies a 1-ULP difference in h.z: d ln D / d ln h.z = -4 h.z^2
/// (alpha^2 - 1) / (1 + h.z^2 (alpha^2 - 1)), which reaches about 4 alpha^2 h.z^2 / (1 + ...)
/// and so up to ~4 for large alpha, times the few ULP of h itself.
const PDF_ULPS: f64 = 16.0;

#[test]
fn prefilter_lanes_equal_scalars() {
    let alphas = [0.0, 1e-4, 0.05, 0.25, 0.5, 1.0, 3.0, 1e6];
    let a8 = f32x8::from_fn(|i| alphas[i] as f32);
    let a4 = f64x4::from_fn(|i| alphas[i + 2]);
    let (e32, e64) = (f64::from(f32::EPSILON), f64::EPSILON);
    let mut worst = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    for i in 0..256 {
        let s8 = prefilter::sample(i, 256, a8);
        let s4 = prefilter::sample(i, 256, a4);
        for (k, &alpha) in alphas.iter().enumerate() {
            let s = prefilter::sample(i, 256, alpha as f32);
            let l = s8.dir.lane(k);
            for (a, b) in [
                (l.x, s.dir.x),
                (l.y, s.dir.y),
                (l.z, s.dir.z),
                (s8.weight.lane(k), s.weight),
            ] {
                let (a, b) = (f64::from(a), f64::from(b));
                worst.0 = worst
                    .0
                    .max((a - b).abs() / (e32 * a.abs().max(b.abs()).max(1.0)));
                assert!(
                    close(a, b, e32, 6.0),
                    "f32x8 sample {i} lane {k}: {a} vs {b}"
                );
            }
            let (a, b) = (f64::from(s8.pdf.lane(k)), f64::from(s.pdf));
            worst.2 = worst.2.max((a - b).abs() / (e32 * a.abs().max(b.abs())));
            assert!(
                close(a, b, e32, PDF_ULPS),
                "f32x8 pdf {i} lane {k}: {a} vs {b}"
            );
        }
        for k in 0..4 {
            let s = prefilter::sample(i, 256, alphas[k + 2]);
            let l = s4.dir.lane(k);
            for (a, b) in [
                (l.x, s.dir.x),
                (l.y, s.dir.y),
                (l.z, s.dir.z),
                (s4.weight.lane(k), s.weight),
            ] {
                worst.1 = worst
                    .1
                    .max((a - b).abs() / (e64 * a.abs().max(b.abs()).max(1.0)));
                assert!(
                    close(a, b, e64, 6.0),
                    "f64x4 sample {i} lane {k}: {a} vs {b}"
                );
            }
            let (a, b) = (s4.pdf.lane(k), s.pdf);
            worst.3 = worst.3.max((a - b).abs() / (e64 * a.abs().max(b.abs())));
            assert!(
                close(a, b, e64, PDF_ULPS),
                "f64x4 pdf {i} lane {k}: {a} vs {b}"
            );
        }
    }
    println!(
        "lanes vs scalar, direction and weight: f32x8 {:.2} ULP, f64x4 {:.2} ULP; pdf: f32x8 {:.2} ULP, f64x4 {:.2} ULP",
        worst.0, worst.1, worst.2, worst.3
    );
}

#[test]
fn prefilter_samples_are_finite_for_every_finite_alpha() {
    let alphas = [0.0, 1e-30, 1e-4, 0.01, 0.5, 1.0, 100.0, 1e30, f64::MAX];
    for &alpha in &alphas {
        for u1 in [0.0, 1e-12, 0.3, 0.999_999, 1.0, 2.0] {
            for u2 in [0.0, 0.7, 1.0] {
                let s = prefilter::sample_from(u1, u2, alpha);
                assert!(
                    (s.dir.length() - 1.0).abs() < 1e-12,
                    "f64 {alpha} {u1}: {s:?}"
                );
                assert!(s.weight.is_finite() && s.pdf.is_finite() && s.pdf >= 0.0);
                let a32 = (alpha as f32).min(f32::MAX);
                let t = prefilter::sample_from(u1 as f32, u2 as f32, a32);
                assert!(
                    (t.dir.length() - 1.0).abs() < 1e-5,
                    "f32 {alpha} {u1}: {t:?}"
                );
                assert!(t.weight.is_finite() && t.pdf.is_finite() && t.pdf >= 0.0);
            }
        }
    }
}
