//! The Cook-Torrance reflection samplers (`sampling::ggx_reflection`,
//! `sampling::beckmann_reflection` and their `_rgb` forms): their directions follow the pdf
//! function (chi-square on the folded sphere), the pdf they return is the pdf function bit
//! for bit, the weight is f cos / pdf from `cook_torrance::eval`, the mean weight is the
//! directional albedo of `brdf::integrate`, and bad input follows the crate's NaN rule.
//!
//! `cargo test --test sampling reflection:: -- --nocapture` prints the figures.
#![cfg(all(
    feature = "sampling",
    feature = "ggx",
    feature = "beckmann",
    feature = "cook-torrance",
    feature = "fresnel",
    feature = "integrate"
))]

use crate::common;

use brdf::beckmann::Beckmann;
use brdf::cook_torrance;
use brdf::fresnel;
use brdf::ggx::Ggx;
use brdf::integrate::directional_albedo;
use brdf::microfacet::Microfacet;
use brdf::sampling as sm;
use brdf::{Real, V3};
use common::{Rng, assert_fits, chi_square};

fn dir(theta_deg: f64, phi_deg: f64) -> V3<f64> {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    V3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

/// One model's sampler and pdf function on f64 with a scalar Fresnel closure.
type Sampler = Box<dyn Fn(V3<f64>, f64, f64, &dyn Fn(f64) -> f64) -> (V3<f64>, f64, f64)>;
type Pdf = Box<dyn Fn(V3<f64>, V3<f64>) -> f64>;

fn ggx_model(alpha: f64) -> (Sampler, Pdf, Box<dyn Microfacet<f64>>) {
    let g = Ggx::isotropic(alpha).unwrap();
    (
        Box::new(move |wo, u1, u2, f| sm::ggx_reflection(&g, wo, u1, u2, f)),
        Box::new(move |wo, wi| sm::ggx_reflection_pdf(&g, wo, wi)),
        Box::new(g),
    )
}

fn beckmann_model(alpha: f64) -> (Sampler, Pdf, Box<dyn Microfacet<f64>>) {
    let b = Beckmann::isotropic(alpha).unwrap();
    (
        Box::new(move |wo, u1, u2, f| sm::beckmann_reflection(&b, wo, u1, u2, f)),
        Box::new(move |wo, wi| sm::beckmann_reflection_pdf(&b, wo, wi)),
        Box::new(b),
    )
}

type Model = fn(f64) -> (Sampler, Pdf, Box<dyn Microfacet<f64>>);
const MODELS: [(&str, Model); 2] = [("GGX", ggx_model), ("Beckmann", beckmann_model)];

/// The samples reflected below the horizon are part of the distribution (their weight is 0),
/// and the shared chi-square bins the upper hemisphere only: fold the sphere onto it,
/// w -> (x, y, |z|), with the folded pdf q(w) = p(w) + p(x, y, -z). A sampler drawing the
/// wrong shape below the horizon, or the wrong fraction there, fails as surely as one wrong
/// above it.
#[test]
fn reflection_samples_follow_the_pdf_function() {
    for (name, model) in MODELS {
        // A smooth and a rough lobe; normal, oblique and grazing views (the last reflects a
        // part of its samples below the horizon).
        for (alpha, theta) in [(0.3, 0.0), (0.3, 80.0), (1.0, 45.0)] {
            {
                let (sample, pdf, _) = model(alpha);
                let wo = dir(theta, 30.0);
                let fold = |w: V3<f64>| V3::new(w.x, w.y, w.z.abs());
                let folded = |w: V3<f64>| pdf(wo, w) + pdf(wo, V3::new(w.x, w.y, -w.z));
                let fit = chi_square(
                    |u1, u2| {
                        let (wi, _, _) = sample(wo, u1, u2, &|_| 1.0);
                        (fold(wi).into(), folded(fold(wi)))
                    },
                    |w| folded(w.into()),
                );
                assert_fits(&format!("{name} alpha {alpha} theta_o {theta}"), fit);
            }
        }
    }
}

/// The pdf function integrates to 1 over the sphere of wi (upper hemisphere plus the
/// reflected-below part, by the integrator on each half): the density the sampler draws is
/// normalized, so the chi-square above compares shapes of equal mass.
#[test]
fn reflection_pdf_integrates_to_one_over_the_sphere() {
    println!(
        "{:>9} {:>6} {:>8} {:>12} {:>12} {:>12}",
        "model", "alpha", "theta_o", "upper", "total - 1", "quad. error"
    );
    for (name, model) in MODELS {
        for alpha in [0.2, 1.0] {
            for theta in [0.0, 85.0] {
                let (_, pdf, _) = model(alpha);
                let wo = dir(theta, 0.0);
                let cfg = brdf::integrate::Config::default();
                // The lobe's peak, the mirror direction, as a hint to the integrator.
                let mirror = V3::new(-wo.x, -wo.y, wo.z);
                let up = brdf::integrate::hemisphere(|w| pdf(wo, w), &[mirror], &cfg);
                // Below: the lobe's continuation past the horizon and wi = -wo (where the
                // half vector leaves the hemisphere of visible normals), mirrored up.
                let down = brdf::integrate::hemisphere(
                    |w| pdf(wo, V3::new(w.x, w.y, -w.z)),
                    &[V3::new(-wo.x, -wo.y, wo.z), mirror],
                    &cfg,
                );
                let total = up.value + down.value;
                println!(
                    "{name:>9} {alpha:>6} {theta:>8} {:>12.8} {:>12.2e} {:>12.2e}",
                    up.value,
                    total - 1.0,
                    up.error + down.error
                );
                // The integrator's reported error (about 1e-7) is the slack; measured totals
                // are within 4e-9 of 1.
                assert!(
                    (total - 1.0).abs() < 1e-9 + up.error + down.error,
                    "{name} alpha {alpha} theta {theta}: {total}"
                );
            }
        }
    }
}

/// The returned pdf is the pdf function at the returned direction, bit for bit, on every
/// lane type; and the weight is f(wo, wi) wi.z / pdf computed from `cook_torrance::eval`
/// (with h = normalize(wo + wi), not the sampled m) within a printed relative bound.
fn parts_check<T: Real>(label: &str) -> (f64, u64) {
    let mut rng = Rng(17);
    let mut worst_rel = 0.0f64;
    let mut checked = 0u64;
    let f0 = 0.3;
    for alpha in [0.05, 0.3, 0.8] {
        let g = Ggx::isotropic(T::splat(alpha)).unwrap();
        let b = Beckmann::isotropic(T::splat(alpha)).unwrap();
        for _ in 0..4000 {
            let wo = dir(rng.next_f64() * 89.0, rng.next_f64() * 360.0);
            let wo = V3::new(T::splat(wo.x), T::splat(wo.y), T::splat(wo.z));
            let (u1, u2) = (T::splat(rng.next_f64()), T::splat(rng.next_f64()));
            let fr = |c: T| fresnel::schlick(T::splat(f0), c);
            let samples = [
                (sm::ggx_reflection(&g, wo, u1, u2, fr), true),
                (sm::beckmann_reflection(&b, wo, u1, u2, fr), false),
            ];
            for ((wi, pdf, w), is_ggx) in samples {
                let (p_fn, f) = if is_ggx {
                    (
                        sm::ggx_reflection_pdf(&g, wo, wi),
                        cook_torrance::eval(&g, wo, wi, fr),
                    )
                } else {
                    (
                        sm::beckmann_reflection_pdf(&b, wo, wi),
                        cook_torrance::eval(&b, wo, wi, fr),
                    )
                };
                for l in 0..T::LANES {
                    let (p, q): (f64, f64) = (pdf.lane(l).into(), p_fn.lane(l).into());
                    assert_eq!(p.to_bits(), q.to_bits(), "{label}: pdf {p} vs function {q}");
                }
                let (p, w, f, z): (f64, f64, f64, f64) = (
                    pdf.lane(0).into(),
                    w.lane(0).into(),
                    f.lane(0).into(),
                    wi.z.lane(0).into(),
                );
                if z <= 0.0 {
                    assert_eq!(w, 0.0, "{label}: weight below the horizon");
                    continue;
                }
                let want = f * z / p;
                let rel = (w - want).abs() / want;
                worst_rel = worst_rel.max(rel);
                checked += 1;
            }
        }
    }
    (worst_rel, checked)
}

/// The weight F G2 / G1 and f cos / pdf are equal algebraically; numerically the second
/// reads D at h = normalize(wo + wi) and F at wo.h where the first uses the sampled m (equal
/// to rounding), and D's conditioning near a sharp peak (alpha = 0.05: 1 / alpha^2 = 400)
/// amplifies that rounding. Measured 5.2e-15 (f64) and 2.3e-6 (f32); bounds 1e-13 and 2e-5.
#[test]
fn returned_pdf_is_the_pdf_function_and_weight_is_f_cos_over_pdf() {
    let (r64, n64) = parts_check::<f64>("f64");
    let (r32, n32) = parts_check::<f32>("f32");
    parts_check::<brdf::wide::f64x4>("f64x4");
    parts_check::<brdf::wide::f32x8>("f32x8");
    println!("weight vs f cos / pdf: f64 max rel {r64:.2e} ({n64} samples), f32 {r32:.2e} ({n32})");
    assert!(r64 < 1e-13, "f64: {r64}");
    assert!(r32 < 2e-5, "f32: {r32}");
}

/// Mean weight over N samples with F = 1 against the integrator's directional albedo of
/// `cook_torrance::eval`: the estimator is unbiased, so they agree within 5 standard errors
/// (measured from the weights) plus the integrator's error. A missing 1 / G1, a wrong
/// Jacobian or the separable G2 each move the mean by far more.
#[test]
fn mean_weight_is_the_directional_albedo() {
    const N: usize = 100_000;
    println!(
        "{:>9} {:>6} {:>8} {:>10} {:>10} {:>10} {:>9}",
        "model", "alpha", "theta_o", "MC", "integral", "diff", "sigma"
    );
    for (name, model) in MODELS {
        for alpha in [0.1, 0.3, 1.0] {
            for theta in [0.0, 40.0, 70.0, 85.0] {
                let (sample, _, dist) = model(alpha);
                let wo = dir(theta, 0.0);
                let mut rng = Rng(99);
                let (mut s, mut s2) = (0.0, 0.0);
                for _ in 0..N {
                    let (_, _, w) = sample(wo, rng.next_f64(), rng.next_f64(), &|_| 1.0);
                    s += w;
                    s2 += w * w;
                }
                let mean = s / N as f64;
                let sigma = ((s2 / N as f64 - mean * mean).max(0.0) / N as f64).sqrt();
                let e = directional_albedo(wo, |o, i| {
                    cook_torrance::eval(dist.as_ref(), o, i, |_| 1.0)
                });
                let diff = mean - e.value;
                println!(
                    "{name:>9} {alpha:>6} {theta:>8} {mean:>10.6} {:>10.6} {diff:>10.2e} {sigma:>9.1e}",
                    e.value
                );
                assert!(
                    diff.abs() <= 5.0 * sigma + e.error + 1e-9,
                    "{name} alpha {alpha} theta {theta}: MC {mean} vs {} (sigma {sigma})",
                    e.value
                );
            }
        }
    }
}

/// NaN in any component of wo or in u1, u2: NaN direction (all three), pdf and weight; NaN
/// or negative F: NaN weight; wo below the horizon: pdf 0 and weight 0; the pdf function NaN
/// for NaN in wo or wi. On f32 and f64 (`tests/kernels/bad_input.rs` adds the lane types).
fn nan_rule<T: Real<Mask = bool> + PartialEq>() {
    let nan = T::splat(f64::NAN);
    let g = Ggx::isotropic(T::splat(0.3)).unwrap();
    let b = Beckmann::isotropic(T::splat(0.3)).unwrap();
    let wo = V3::new(T::splat(0.36), T::splat(0.48), T::splat(0.8));
    let u = T::splat(0.4);
    let all_nan = |(wi, p, w): (V3<T>, T, T)| {
        wi.x.is_nan() && wi.y.is_nan() && wi.z.is_nan() && p.is_nan() && w.is_nan()
    };
    let one = |_: T| T::ONE;
    for bad in [
        V3::new(nan, wo.y, wo.z),
        V3::new(wo.x, nan, wo.z),
        V3::new(wo.x, wo.y, nan),
    ] {
        assert!(all_nan(sm::ggx_reflection(&g, bad, u, u, one)));
        assert!(all_nan(sm::beckmann_reflection(&b, bad, u, u, one)));
        assert!(sm::ggx_reflection_pdf(&g, bad, wo).is_nan());
        assert!(sm::ggx_reflection_pdf(&g, wo, bad).is_nan());
        assert!(sm::beckmann_reflection_pdf(&b, wo, bad).is_nan());
    }
    for (u1, u2) in [(nan, u), (u, nan)] {
        assert!(all_nan(sm::ggx_reflection(&g, wo, u1, u2, one)));
        assert!(all_nan(sm::beckmann_reflection(&b, wo, u1, u2, one)));
        let (wi, p, w) = sm::ggx_reflection_rgb(&g, wo, u1, u2, |_| V3::splat(T::ONE));
        assert!(all_nan((wi, p, w.x)) && w.y.is_nan() && w.z.is_nan());
    }
    for f in [nan, T::splat(-0.1)] {
        let (wi, p, w) = sm::ggx_reflection(&g, wo, u, u, |_| f);
        assert!(wi.z.is_finite() && p.is_finite() && w.is_nan());
        let (_, _, w) = sm::beckmann_reflection_rgb(&b, wo, u, u, |_| V3::new(T::ONE, f, T::ONE));
        assert!(!w.x.is_nan() && w.y.is_nan() && !w.z.is_nan());
    }
    let below = V3::new(wo.x, wo.y, -wo.z);
    for (wi, p, w) in [
        sm::ggx_reflection(&g, below, u, u, one),
        sm::beckmann_reflection(&b, below, u, u, one),
    ] {
        let len: f64 = wi.dot(wi).lane(0).into();
        assert!((len - 1.0).abs() < 1e-5, "{len}");
        assert!(p == T::ZERO && w == T::ZERO);
    }
}

#[test]
fn bad_input_gives_nan_and_below_the_horizon_gives_zero() {
    nan_rule::<f32>();
    nan_rule::<f64>();
}
