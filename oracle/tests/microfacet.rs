//! GGX and Beckmann D, Lambda, G1, G2 and V stay within their ULP bounds of the correctly rounded
//! result (`oracle/src/bounds.rs`) on f32, f64, f32x8 and f64x4. Print the measured figures
//! with `cargo test -p brdf-oracle --release --test microfacet -- --nocapture`.

/// `ggx::d` against its reference.
#[test]
fn ggx_d_within_bound() {
    brdf_oracle::check("ggx::d");
}

/// `ggx::d_aniso` against its reference.
#[test]
fn ggx_d_aniso_within_bound() {
    brdf_oracle::check("ggx::d_aniso");
}

/// `ggx::lambda` against its reference.
#[test]
fn ggx_lambda_within_bound() {
    brdf_oracle::check("ggx::lambda");
}

/// `ggx::g1` against its reference.
#[test]
fn ggx_g1_within_bound() {
    brdf_oracle::check("ggx::g1");
}

/// `ggx::v_correlated` against its reference.
#[test]
fn ggx_v_correlated_within_bound() {
    brdf_oracle::check("ggx::v_correlated");
}

/// `Ggx::lambda` against its reference.
#[test]
fn ggx_type_lambda_within_bound() {
    brdf_oracle::check("Ggx::lambda");
}

/// `Ggx::g2_correlated` against its reference.
#[test]
fn ggx_type_g2_correlated_within_bound() {
    brdf_oracle::check("Ggx::g2_correlated");
}

/// `Ggx::g2_separable` against its reference.
#[test]
fn ggx_type_g2_separable_within_bound() {
    brdf_oracle::check("Ggx::g2_separable");
}

/// `Ggx::v_correlated` against its reference.
#[test]
fn ggx_type_v_correlated_within_bound() {
    brdf_oracle::check("Ggx::v_correlated");
}

/// `beckmann::d` against its reference.
#[test]
fn beckmann_d_within_bound() {
    brdf_oracle::check("beckmann::d");
}

/// `Beckmann::d` against its reference.
#[test]
fn beckmann_type_d_within_bound() {
    brdf_oracle::check("Beckmann::d");
}

/// `beckmann::lambda` against its reference.
#[test]
fn beckmann_lambda_within_bound() {
    brdf_oracle::check("beckmann::lambda");
}

/// `beckmann::g1` against its reference.
#[test]
fn beckmann_g1_within_bound() {
    brdf_oracle::check("beckmann::g1");
}

/// `Beckmann::lambda` against its reference.
#[test]
fn beckmann_type_lambda_within_bound() {
    brdf_oracle::check("Beckmann::lambda");
}

/// `Beckmann::v_correlated` against its reference.
#[test]
fn beckmann_type_v_correlated_within_bound() {
    brdf_oracle::check("Beckmann::v_correlated");
}

/// A worst-case search for the isotropic `beckmann::d` on `f32` and `f32x8` (evaluated in f64
/// and rounded once, its documented bound 0.7 ULP): fresh random points (seed printed) plus
/// the regions where its roundings are hardest to hide, and a hill-climb from the worst of
/// them, every point scored against MPFR at 256 bits in ULPs of the correctly rounded f32
/// (2^-149 below f32's smallest normal number, so the border of the subnormal range is scored
/// as strictly as the normal range):
///
/// - cosines within 64 ULP of 1 (E near 0, where 1 - c^2 cancels), alpha from ALPHA_MIN up;
/// - for each alpha, the cosines where D crosses 2^-126 (the border of the subnormal results,
///   where the rounding switches parts) and 2^-149 (where D rounds to 0), and where E is near
///   the f32 floor of the cosine (E = 200) and near the ends of the polynomial's interval
///   (E log2(e) within 2^-20 of an integer);
/// - alpha at ALPHA_MIN and ALPHA_MAX (and their neighbouring floats inside the domain);
/// - random cosines (uniform and log-uniform down to 1e-7) and log-uniform alphas.
///
/// `BRDF_ORACLE_POINTS` sets the number of random points (default 200 000); run with
/// `cargo test -p brdf-oracle --release --test microfacet beckmann_d_f32_worst_case -- --nocapture`.
#[test]
fn beckmann_d_f32_worst_case_search() {
    use brdf::beckmann;
    use brdf::wide::f32x8;
    use brdf_oracle::points::Rng;
    use rug::Float;

    let exact = |c: f32, a: f32| -> f64 {
        let r =
            brdf_oracle::reference::beckmann_d(&Float::with_val(256, c), &Float::with_val(256, a));
        r.to_f64()
    };
    // Error in ULPs of the correctly rounded f32 (2^-149 in the subnormal range).
    let score = |y: f32, want: f64| -> f64 {
        let w = want.abs();
        let ulp = if w < f64::from(f32::MIN_POSITIVE) {
            (-149.0f64).exp2()
        } else {
            (w.log2().floor() - 23.0).exp2()
        };
        (f64::from(y) - want).abs() / ulp
    };
    let lo = 1e-4f32.max(brdf::microfacet::ALPHA_MIN as f32);
    let hi = 1e4f32.min(brdf::microfacet::ALPHA_MAX as f32);
    let mut rng = Rng::fresh("beckmann::d worst case");
    let n: usize = std::env::var("BRDF_ORACLE_POINTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(200_000);
    let mut pts: Vec<(f32, f32)> = Vec::new();
    let mut alphas = vec![
        lo,
        f32::from_bits(lo.to_bits() + 1),
        hi,
        f32::from_bits(hi.to_bits() - 1),
    ];
    for _ in 0..60 {
        alphas.push(rng.log_range(1e-4, 1e4) as f32);
    }
    alphas.retain(|a| (lo..=hi).contains(a));
    for &a in &alphas {
        for k in 0..64u32 {
            pts.push((f32::from_bits(1f32.to_bits() - k), a));
        }
        // D(c) = target solved for c by bisection on the exact D (in f64), then the floats
        // around it. D increases with c below the peak c = 1 / (sqrt(2) alpha) (or 1).
        let peak = (1.0 / (std::f64::consts::SQRT_2 * f64::from(a))).min(1.0);
        let d64 = |c: f64| {
            let (c2, a2) = (c * c, f64::from(a) * f64::from(a));
            (-(1.0 - c2) / (c2 * a2)).exp() / (std::f64::consts::PI * a2 * c2 * c2)
        };
        for target in [
            1.175_494_350_822_287_5e-38,
            1.401_298_464_324_817e-45,
            7e-46,
        ] {
            let (mut l, mut h) = (1e-30f64, peak);
            for _ in 0..200 {
                let m = 0.5 * (l + h);
                if d64(m) < target { l = m } else { h = m }
            }
            let c = l as f32;
            for k in -40i32..=40 {
                pts.push((f32::from_bits(c.to_bits().wrapping_add_signed(k)), a));
            }
        }
        // E log2(e) near an integer j (the ends of the reduced interval), and E = 200.
        let a2 = f64::from(a) * f64::from(a);
        for j in [
            1.0f64,
            2.0,
            5.0,
            17.0,
            100.0,
            200.0 * std::f64::consts::LOG2_E,
            288.0,
        ] {
            let e = j / std::f64::consts::LOG2_E;
            let c = (1.0 / (1.0 + e * a2)).sqrt() as f32;
            for k in -8i32..=8 {
                pts.push((f32::from_bits(c.to_bits().wrapping_add_signed(k)), a));
            }
        }
    }
    for i in 0..n {
        let c = if i % 2 == 0 {
            rng.uniform()
        } else {
            rng.log_range(1e-7, 1.0)
        } as f32;
        pts.push((c, rng.log_range(1e-4, 1e4) as f32));
    }
    pts.retain(|&(c, a)| c > 0.0 && c <= 1.0 && (lo..=hi).contains(&a));

    let eval = |&(c, a): &(f32, f32)| -> f64 {
        let y = beckmann::d(c, a);
        let lanes = beckmann::d(f32x8::splat(c), f32x8::splat(a)).to_array();
        assert!(
            lanes.iter().all(|l| l.to_bits() == y.to_bits()),
            "f32x8 lanes differ from f32 at c = {c:e}, alpha = {a:e}"
        );
        score(y, exact(c, a))
    };
    let mut scored: Vec<(f64, (f32, f32))> = pts.iter().map(|p| (eval(p), *p)).collect();
    scored.sort_by(|x, y| y.0.total_cmp(&x.0));
    // Hill-climb: from each of the 200 worst, steps of 1 to 64 ULP in c and alpha while the
    // error grows.
    let mut worst = scored[0];
    let mut climbed = Vec::new();
    for &(mut best, (mut c, mut a)) in scored.iter().take(200) {
        for _ in 0..400 {
            let dc = (rng.uniform() * 129.0) as i32 - 64;
            let da = (rng.uniform() * 9.0) as i32 - 4;
            let cand = (
                f32::from_bits(c.to_bits().wrapping_add_signed(dc)),
                f32::from_bits(a.to_bits().wrapping_add_signed(da)),
            );
            if !(cand.0 > 0.0 && cand.0 <= 1.0 && (lo..=hi).contains(&cand.1)) {
                continue;
            }
            let s = eval(&cand);
            if s > best {
                (best, c, a) = (s, cand.0, cand.1);
            }
        }
        if best > worst.0 {
            worst = (best, (c, a));
        }
        climbed.push((best, (c, a)));
    }
    // The three worst in distinct regions (c or alpha apart by more than 1e-3 relative), in
    // `oracle/hardest.txt`'s form.
    climbed.sort_by(|x, y| y.0.total_cmp(&x.0));
    let mut kept: Vec<(f64, (f32, f32))> = Vec::new();
    for &(e, (c, a)) in &climbed {
        let near = |&(_, (c2, a2)): &(f64, (f32, f32))| {
            ((c - c2) / c).abs() < 1e-3 && ((a - a2) / a).abs() < 1e-3
        };
        if kept.len() < 3 && !kept.iter().any(near) {
            kept.push((e, (c, a)));
            eprintln!(
                "{e:.4} ULP:\tbeckmann::d\tf32\t{:e} {:e}",
                f64::from(c),
                f64::from(a)
            );
        }
    }
    let (e, (c, a)) = worst;
    eprintln!(
        "beckmann::d f32/f32x8: max {e:.4} ULP at c = {c:e} ({:#x}), alpha = {a:e} ({:#x}), \
         over {} points and the climb",
        c.to_bits(),
        a.to_bits(),
        pts.len()
    );
    assert!(e <= 0.7, "beckmann::d {e} ULP at c = {c:e}, alpha = {a:e}");
}
