//! The registry: every exact function under test, its reference, its kernel on the four lane
//! types and its point set.

use brdf::beckmann::Beckmann;
use brdf::ggx::Ggx;
use brdf::microfacet::Microfacet;
use brdf::{V3, beckmann, color, diffuse, fresnel, ggx, phong};

use crate::harness::{self, Case, Family, Ty};
use crate::kernel;
use crate::points::{self, Rng, alphas, around, cosines, direction, etas, grid, random};
use crate::reference as r;
use rug::Float;

/// The unit vector at (args[i], args[i + 1], args[i + 2]).
fn v3<T: brdf::Real>(x: &[T], i: usize) -> V3<T> {
    V3::new(x[i], x[i + 1], x[i + 2])
}

/// Stiff directions: each stiff cosine at azimuths 0, pi/4, pi/2 and 1 radian, and the
/// directions a hair off the normal (x = 1e-150 or the type's smallest normal, z = 1), where
/// the Beckmann a = 1 / (alpha tan) reaches 1e150.
fn directions(ty: Ty) -> Vec<[f64; 3]> {
    let mut v = Vec::new();
    for z in cosines(ty) {
        for phi in [
            0.0,
            core::f64::consts::FRAC_PI_4,
            core::f64::consts::FRAC_PI_2,
            1.0,
        ] {
            v.push(direction(z, phi));
        }
    }
    let tiny = match ty {
        Ty::F32 => [1e-30, 1e-20, 1e-10],
        Ty::F64 => [1e-150, 1e-100, 1e-20],
    };
    v.extend(tiny.map(|t| [t, 0.0, 1.0]));
    v
}

/// Anisotropic (alpha_x, alpha_y) pairs.
fn alpha_pairs() -> Vec<[f64; 2]> {
    let lo = points::ALPHA_LO;
    let hi = points::ALPHA_HI;
    vec![
        [lo, lo],
        [lo, 1.0],
        [0.5, 0.01],
        [0.5, 0.5],
        [1.0, 2.0],
        [hi, 0.1],
        [hi, hi],
    ]
}

/// (cos, alpha) on the stiff grid and at random: the cosine from [`Rng::cosine`], over its
/// whole range down to the smallest subnormal ([`points::cosine_full`], 0 excluded), or in
/// the band where Beckmann's a = 1 / (alpha tan(theta)) is 0.05 .. 30 (where its Lambda
/// changes form).
fn cos_alpha(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = grid(&[cosines(ty), alphas()]);
    v.extend(random("cos_alpha", |g| {
        let alpha = g.alpha();
        let c = match (g.uniform() * 3.0) as u32 {
            0 => g.cosine(),
            1 => points::cosine_full(g, ty),
            _ => {
                let t = 1.0 / (alpha * g.log_range(0.05, 30.0));
                1.0 / t.hypot(1.0)
            }
        };
        let tiny = points::full_range(ty).0;
        vec![c.max(tiny), alpha]
    }));
    v
}

/// (cos, alpha) plus the Beckmann stiff set: cosines where a = 1 / (alpha tan) is 0.1 .. 1e6.
fn cos_alpha_beckmann(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = cos_alpha(ty);
    for alpha in [points::ALPHA_LO, 0.01, 0.5, 1.0] {
        for a in [0.1, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 26.0, 40.0, 1e3, 1e6] {
            let t: f64 = 1.0 / (alpha * a);
            v.push(vec![1.0 / t.hypot(1.0), alpha]);
        }
    }
    v
}

/// (cos_v, cos_l, alpha).
fn two_cos_alpha(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = grid(&[cosines(ty), cosines(ty), alphas()]);
    v.extend(random("two_cos_alpha", |g| {
        vec![g.cosine(), g.cosine(), g.alpha()]
    }));
    v
}

/// (x, y, z, alpha_x, alpha_y).
fn dir_alphas(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = Vec::new();
    for d in directions(ty) {
        for [ax, ay] in alpha_pairs() {
            v.push(vec![d[0], d[1], d[2], ax, ay]);
        }
    }
    v.extend(random("dir_alphas", |g| {
        let d = g.direction();
        vec![d[0], d[1], d[2], g.alpha(), g.alpha()]
    }));
    v
}

/// (n.h, t.h, b.h, alpha_x, alpha_y): [`dir_alphas`] with z first.
fn nh_th_bh_alphas(ty: Ty) -> Vec<Vec<f64>> {
    dir_alphas(ty)
        .into_iter()
        .map(|p| vec![p[2], p[0], p[1], p[3], p[4]])
        .collect()
}

/// (wo, wi, alpha_x, alpha_y).
fn two_dirs_alphas(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = Vec::new();
    let dirs = directions(ty);
    for (i, o) in dirs.iter().enumerate().step_by(3) {
        for (j, l) in dirs.iter().enumerate().step_by(5) {
            let [ax, ay] = alpha_pairs()[(i + j) % 7];
            v.push(vec![o[0], o[1], o[2], l[0], l[1], l[2], ax, ay]);
        }
    }
    v.extend(random("two_dirs_alphas", |g| {
        let (o, l) = (g.direction(), g.direction());
        vec![o[0], o[1], o[2], l[0], l[1], l[2], g.alpha(), g.alpha()]
    }));
    v
}

/// A relative index: half the time over the whole documented domain (0, MAX] of `ty`
/// ([`points::eta_full`], both sides of every internal switch), otherwise near 1 on either
/// side or log-uniform in [0.2, 10].
fn random_eta(g: &mut Rng, ty: Ty) -> f64 {
    if g.uniform() < 0.5 {
        return points::eta_full(g, ty);
    }
    match (g.uniform() * 3.0) as u32 {
        0 => 1.0 + g.log_range(1e-8, 0.1),
        1 => 1.0 - g.log_range(1e-8, 0.1),
        _ => g.log_range(0.2, 10.0),
    }
}

/// (cos_i, eta), cos_i of both signs: the stiff grid, random points ([`random_eta`], the
/// cosine over its whole range half the time), and the neighbourhood of the critical angle from outside
/// (eta < 1) and inside (eta > 1): the critical cosine and its 3 neighbouring floats each
/// side, and random relative offsets up to 2^-12. Split by conditioning per function
/// ([`conditioned`]).
fn cos_eta(ty: Ty) -> Vec<Vec<f64>> {
    let signed: Vec<f64> = cosines(ty).into_iter().flat_map(|c| [c, -c]).collect();
    let mut v = grid(&[signed, etas(ty)]);
    v.extend(random("cos_eta", |g| {
        let c = if g.uniform() < 0.5 {
            g.cosine()
        } else {
            points::cosine_full(g, ty)
        };
        let c = if g.uniform() < 0.5 { -c } else { c };
        vec![c, random_eta(g, ty)]
    }));
    let crit = |e: f64| ((1.0 - e) * (1.0 + e)).sqrt();
    for eta in [0.5_f64, 1.0 / 1.5, 1.0 - 1e-3, 1.0 - 1e-6] {
        v.extend(around(ty, crit(eta), 3).into_iter().map(|c| vec![c, eta]));
        v.extend(
            around(ty, crit(eta), 3)
                .into_iter()
                .map(|c| vec![-c, 1.0 / eta]),
        );
    }
    v.extend(random("cos_eta_critical", |g| {
        let e = g.log_range(0.2, 1.0 - 1e-6);
        let c = crit(e) * (1.0 + g.range(-1.0, 1.0) * 2f64.powi(-12));
        if g.uniform() < 0.5 {
            vec![c, e]
        } else {
            vec![-c, 1.0 / e]
        }
    }));
    v
}

/// The points of `all` (rounded to `ty`) whose condition number in the cosine for
/// `reference` ([`harness::condition`]) is at most [`harness::KAPPA_MAX`] (`ill` false: the
/// main row) or above it (`ill` true: the `(ill-conditioned)` row).
fn conditioned(
    ty: Ty,
    all: fn(Ty) -> Vec<Vec<f64>>,
    reference: fn(&[Float]) -> Float,
    ill: bool,
) -> Vec<Vec<f64>> {
    harness::conditioned_in(ty, all, reference, harness::FIRST, ill)
}

fn ref_dielectric(x: &[Float]) -> Float {
    r::fresnel_dielectric(&x[0], &x[1])
}

fn ref_rs(x: &[Float]) -> Float {
    r::fresnel_dielectric_polarized(&x[0], &x[1]).0
}

fn ref_rp(x: &[Float]) -> Float {
    r::fresnel_dielectric_polarized(&x[0], &x[1]).1
}

fn ref_conductor(x: &[Float]) -> Float {
    r::fresnel_conductor(&x[0], &x[1], &x[2])
}

fn dielectric_main(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta, ref_dielectric, false)
}

fn dielectric_ill(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta, ref_dielectric, true)
}

fn rs_main(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta, ref_rs, false)
}

fn rs_ill(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta, ref_rs, true)
}

fn rp_main(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta, ref_rp, false)
}

fn rp_ill(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta, ref_rp, true)
}

fn conductor_main(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta_k, ref_conductor, false)
}

fn conductor_ill(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, cos_eta_k, ref_conductor, true)
}

/// (cos_i, eta, k): moderate eta and k on a grid and at random, large ones on a grid, and
/// half the random points over the whole documented domain (eta in (0, MAX], k in [0, MAX],
/// both sides of the scaling thresholds 2^16 and EPSILON^2, [`points::k_full`]).
fn cos_eta_k(ty: Ty) -> Vec<Vec<f64>> {
    let eta = vec![0.2, 0.5, 1.0 - 1e-6, 1.0, 1.0 + 1e-6, 1.5, 10.0];
    let k = vec![0.0, 1e-3, 1.0, 3.0, 1e3];
    let mut v = grid(&[cosines(ty), eta, k]);
    // The scaled path of max(eta, k) > 2^16, where F is within 1e-4 of 1 at grazing cosines.
    v.extend(grid(&[
        cosines(ty),
        vec![0.5, 3.0, 7e4],
        vec![0.0, 7e4, 1e10],
    ]));
    v.extend(random("cos_eta_k", |g| {
        if g.uniform() < 0.5 {
            let e = match (g.uniform() * 10.0) as u32 {
                0 => points::near(g, ty, 65536.0),
                1 => points::near(g, ty, points::eps2(ty)),
                _ => points::eta_full(g, ty),
            };
            return vec![points::cosine_full(g, ty), e, points::k_full(g, ty)];
        }
        let k = if g.uniform() < 0.2 {
            0.0
        } else {
            g.log_range(1e-3, 1e3)
        };
        vec![g.cosine(), g.log_range(0.05, 10.0), k]
    }));
    v
}

/// (F0, cos).
fn f0_cos(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = grid(&[vec![0.0, 1e-6, 0.04, 0.5, 0.95, 1.0], cosines(ty)]);
    v.extend(random("f0_cos", |g| vec![g.uniform(), g.cosine()]));
    v
}

/// eta alone.
fn eta_only(ty: Ty) -> Vec<Vec<f64>> {
    let mut v: Vec<Vec<f64>> = etas(ty).into_iter().map(|e| vec![e]).collect();
    v.push(vec![1.0]);
    v.extend(random("eta_only", |g| vec![random_eta(g, ty)]));
    v
}

/// A transfer function's input in [0, 1]: its breakpoints with 4 floats either side, the
/// floats between the `extra` pair (a breakpoint and its image, 17 evenly spaced), the ends,
/// and the random sample.
fn transfer(ty: Ty, breaks: &[f64], between: Option<(f64, f64)>) -> Vec<Vec<f64>> {
    let mut v: Vec<f64> = breaks.iter().flat_map(|&b| around(ty, b, 4)).collect();
    if let Some((a, b)) = between {
        v.extend((0..=16).map(|i| a + (b - a) * f64::from(i) / 16.0));
    }
    v.extend([0.0, 1e-30, 1e-10, 1.0, ty.next_down(1.0), 0.5]);
    let mut v: Vec<Vec<f64>> = v.into_iter().map(|x| vec![x]).collect();
    v.extend(random("transfer", |g| vec![g.unit()]));
    v
}

fn srgb_oetf_points(ty: Ty) -> Vec<Vec<f64>> {
    transfer(ty, &[0.003_130_8], None)
}

fn srgb_eotf_points(ty: Ty) -> Vec<Vec<f64>> {
    let image = color::SRGB_EOTF_BREAK;
    transfer(ty, &[0.040_45, image], Some((image, 0.040_45)))
}

fn rec709_points(ty: Ty) -> Vec<Vec<f64>> {
    transfer(ty, &[0.018], None)
}

/// (cos_v, cos_l, rho).
fn lambert_points(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = grid(&[cosines(ty), vec![0.5, 1e-3], vec![0.0, 0.18, 1.0]]);
    v.extend(random("lambert", |g| {
        vec![g.cosine(), g.cosine(), g.uniform()]
    }));
    v
}

/// (cos_v, cos_l, v.l, rho, sigma) from two random directions.
fn oren_nayar_points(ty: Ty) -> Vec<Vec<f64>> {
    direction_pairs(ty, "oren_nayar", &[0.0, 0.1, 0.5, 1.0, 10.0], 1.5)
}

/// Oren-Nayar's full model: sigma up to the largest finite value (its documented domain).
fn oren_nayar_full_points(ty: Ty) -> Vec<Vec<f64>> {
    let sigmas = [0.0, 1e-3, 0.1, 0.5, 1.0, 10.0, 1e20, ty.max()];
    direction_pairs(ty, "oren_nayar_full", &sigmas, 1.5)
}

fn ref_oren_nayar_full(x: &[Float]) -> Float {
    realizable(x, r::oren_nayar_full)
}

/// Whether (n.v, n.l, v.l) is a triple some pair of unit vectors has, up to rounding:
/// (v.l - n.v n.l)^2 <= (1 - n.v^2)(1 - n.l^2)(1 + 2^-10), i.e. |cos(phi)| <= 1 + 2^-11,
/// decided exactly (products of f64 values are exact at 256 bits). [`direction_pairs`]
/// keeps its points to it. The slack keeps a cosine's neighbouring floats inside where a
/// triple sits on the boundary (directions opposite in azimuth), so its condition number can
/// be measured; the references and the kernels both extend the lobes there by the same
/// formula in s = v.l - n.v n.l.
fn is_realizable(cv: f64, cl: f64, vl: f64) -> bool {
    let f = |v: f64| Float::with_val(256, v);
    let (cv, cl, vl) = (f(cv), f(cl), f(vl));
    let s = Float::with_val(256, &vl - Float::with_val(256, &cv * &cl));
    let lhs = Float::with_val(256, s.square_ref());
    let a = Float::with_val(256, 1 - Float::with_val(256, cv.square_ref()));
    let b = Float::with_val(256, 1 - Float::with_val(256, cl.square_ref()));
    let slack = Float::with_val(256, 1) + Float::with_val(256, -10).exp2();
    lhs <= Float::with_val(256, &a * &b) * slack
}

/// `f` at (n.v, n.l, v.l, rho, sigma) where the triple is realizable ([`is_realizable`]),
/// NaN elsewhere: the hill-climb of the harness skips points whose reference is NaN, so it
/// cannot wander onto direction triples no pair of unit vectors has.
fn realizable(x: &[Float], f: fn(&Float, &Float, &Float, &Float, &Float) -> Float) -> Float {
    if is_realizable(x[0].to_f64(), x[1].to_f64(), x[2].to_f64()) {
        f(&x[0], &x[1], &x[2], &x[3], &x[4])
    } else {
        Float::with_val(x[0].prec(), rug::float::Special::Nan)
    }
}

/// Oren-Nayar full, split by conditioning in n.v ([`conditioned`]): both directions near
/// grazing on opposite sides, L1's terms (each about 1) cancel to a few hundredths.
fn oren_nayar_full_main(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, oren_nayar_full_points, ref_oren_nayar_full, false)
}

fn oren_nayar_full_ill(ty: Ty) -> Vec<Vec<f64>> {
    conditioned(ty, oren_nayar_full_points, ref_oren_nayar_full, true)
}

/// Fujii's form and EON: sigma in [0, 1].
fn fujii_points(ty: Ty) -> Vec<Vec<f64>> {
    direction_pairs(ty, "oren_nayar_fujii", &[0.0, 1e-3, 0.1, 0.5, 1.0], 1.0)
}

/// (cos_v, cos_l, v.l, rho, sigma): the stiff directions paired, each pair with one of
/// `sigmas` in turn (rho 0.8), then random pairs with rho uniform and sigma uniform in
/// [0, `sigma_hi`].
fn direction_pairs(ty: Ty, name: &str, sigmas: &[f64], sigma_hi: f64) -> Vec<Vec<f64>> {
    let mut v = Vec::new();
    let dirs = directions(ty);
    for (i, o) in dirs.iter().enumerate().step_by(2) {
        for l in dirs.iter().step_by(7) {
            let vl = o[0] * l[0] + o[1] * l[1] + o[2] * l[2];
            let sigma = sigmas[i % sigmas.len()];
            v.push(vec![o[2], l[2], vl, 0.8, sigma]);
        }
    }
    v.extend(random(name, |g| {
        let (o, l) = (g.direction(), g.direction());
        let vl = o[0] * l[0] + o[1] * l[1] + o[2] * l[2];
        vec![o[2], l[2], vl, g.uniform(), g.range(0.0, sigma_hi)]
    }));
    // The lobe clamps max(n.v, n.l) up to the smallest normal float on purpose (to keep
    // tan(beta) finite): where both cosines are subnormal it is not the paper's.
    let tiny = match ty {
        Ty::F32 => f64::from(f32::MIN_POSITIVE),
        Ty::F64 => f64::MIN_POSITIVE,
    };
    v.retain(|p| ty.round(p[0]).max(ty.round(p[1])) >= tiny);
    // Rounding the directions' cosines to f32 can leave a triple no pair of unit vectors has
    // (n.l rounded to 1 while v.l != n.v): cos(phi) = (v.l - n.v n.l) / (sin_v sin_l) is then
    // undefined or far outside [-1, 1]. Such a triple is replaced by the nearest realizable
    // one with the same rounded cosines (v.l moved into its feasible interval), so near-normal
    // inputs keep their share of the points instead of being dropped.
    let realizable = is_realizable;
    v.into_iter()
        .filter_map(|mut p| {
            let [cv, cl, vl] = [0, 1, 2].map(|i| ty.round(p[i]));
            if realizable(cv, cl, vl) {
                return Some(p);
            }
            let half = ((1.0 - cv * cv) * (1.0 - cl * cl)).max(0.0).sqrt();
            let centre = cv * cl;
            // The clamped value, then up to 4 floats further toward the centre, then the
            // centre itself (rounded).
            let mut x = ty.round(vl.clamp(centre - half, centre + half));
            let mut tries = vec![x];
            for _ in 0..4 {
                x = if x > centre {
                    ty.next_down(x)
                } else {
                    ty.next_up(x)
                };
                tries.push(x);
            }
            tries.push(ty.round(centre));
            p[2] = tries.into_iter().find(|&x| realizable(cv, cl, x))?;
            Some(p)
        })
        .collect()
}

/// (cos_v, cos_l, l.h, rho, roughness).
fn burley_points(ty: Ty) -> Vec<Vec<f64>> {
    let mut v = grid(&[
        cosines(ty),
        vec![1.0, 0.5, 1e-3],
        vec![0.0, 0.5, 1.0],
        vec![0.5, 1.0],
        vec![0.0, 1e-3, 0.25, 1.0],
    ]);
    // F_D90 = 1 (l.h^2 = 1 / (4 r)), where F_D90 - 1 cancels, and both cosines stiff.
    v.extend(grid(&[
        cosines(ty),
        cosines(ty),
        vec![0.5, core::f64::consts::FRAC_1_SQRT_2],
        vec![1.0],
        vec![1.0, 0.5],
    ]));
    v.extend(random("burley", |g| {
        vec![
            g.cosine(),
            g.cosine(),
            g.uniform(),
            g.uniform(),
            g.uniform(),
        ]
    }));
    v
}

/// (cos_v, cos_l, lobe cosine, ks, exponent).
fn phong_points(ty: Ty) -> Vec<Vec<f64>> {
    let exps = vec![0.0, 1.0, 5.0, 50.0, 1e3, 1e4, 1e6, 1e30, ty.max()];
    let mut v = grid(&[vec![0.5], vec![0.8], cosines(ty), vec![0.7], exps]);
    v.extend(random("phong", |g| {
        vec![
            g.cosine(),
            g.cosine(),
            1.0 - g.log_range(1e-8, 1.0),
            g.uniform(),
            g.log_range(0.1, 1e4),
        ]
    }));
    v
}

/// The exponent n alone: 0, 1, the neighbourhood of 2 and 4, 10^4, large, the largest
/// finite value, and log-uniform random in [1e-3, 1e6].
fn exponent_points(ty: Ty) -> Vec<Vec<f64>> {
    let mut v: Vec<f64> = vec![0.0, 1e-30, 1e-3, 0.5, 1.0, 2.0, 4.0, 8.76, 10.0, 100.0, 1e4];
    v.extend([1e6, 1e10, 1e20, 1e30, 1e37, ty.max()]);
    if ty == Ty::F64 {
        v.extend([1e100, 1e300]);
    }
    let mut v: Vec<Vec<f64>> = v.into_iter().map(|x| vec![x]).collect();
    v.extend(random("exponent", |g| vec![g.log_range(1e-3, 1e6)]));
    v
}

/// Every case, in table order.
#[must_use]
pub fn all() -> Vec<Case> {
    use Family::{Color, Fresnel, Lobes, Microfacet as Mf};
    let mut all = vec![
        Case {
            name: "ggx::d",
            family: Mf,
            source: "Walter et al. 2007 eq. 33",
            reference: |x| r::ggx_d(&x[0], &x[1]),
            kernels: kernel!(|x| ggx::d(x[0], x[1])),
            points: cos_alpha,
            perturbed: harness::FIRST,
        },
        Case {
            name: "ggx::d_aniso",
            family: Mf,
            source: "Heitz 2014 eq. 85",
            reference: |x| r::ggx_d_aniso(&x[1], &x[2], &x[0], &x[3], &x[4]),
            kernels: kernel!(|x| ggx::d_aniso(x[0], x[1], x[2], x[3], x[4])),
            points: nh_th_bh_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "ggx::lambda",
            family: Mf,
            source: "Heitz 2014 eq. 86",
            reference: |x| r::ggx_lambda(&x[0], &x[1]),
            kernels: kernel!(|x| ggx::lambda(x[0], x[1])),
            points: cos_alpha,
            perturbed: harness::FIRST,
        },
        Case {
            name: "ggx::g1",
            family: Mf,
            source: "Heitz 2014 eqs. 43, 86",
            reference: |x| r::g1(r::ggx_lambda(&x[0], &x[1])),
            kernels: kernel!(|x| ggx::g1(x[0], x[1])),
            points: cos_alpha,
            perturbed: harness::FIRST,
        },
        Case {
            name: "ggx::v_correlated",
            family: Mf,
            source: "Heitz 2014 eqs. 86, 99",
            reference: |x| {
                let g2 =
                    r::g2_correlated(r::ggx_lambda(&x[0], &x[2]), &r::ggx_lambda(&x[1], &x[2]));
                r::visibility(g2, &x[0], &x[1])
            },
            kernels: kernel!(|x| ggx::v_correlated(x[0], x[1], x[2])),
            points: two_cos_alpha,
            perturbed: harness::FIRST,
        },
        Case {
            name: "Ggx::lambda",
            family: Mf,
            source: "Heitz 2014 eq. 86, anisotropic",
            reference: |x| r::ggx_lambda_vec([&x[0], &x[1], &x[2]], &x[3], &x[4]),
            kernels: kernel!(|x| Ggx::new(x[3], x[4]).unwrap().lambda(v3(x, 0))),
            points: dir_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "Ggx::g2_correlated",
            family: Mf,
            source: "Heitz 2014 eqs. 86, 99",
            reference: |x| {
                let lo = r::ggx_lambda_vec([&x[0], &x[1], &x[2]], &x[6], &x[7]);
                let li = r::ggx_lambda_vec([&x[3], &x[4], &x[5]], &x[6], &x[7]);
                r::g2_correlated(lo, &li)
            },
            kernels: kernel!(|x| Ggx::new(x[6], x[7])
                .unwrap()
                .g2_correlated(v3(x, 0), v3(x, 3))),
            points: two_dirs_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "Ggx::g2_separable",
            family: Mf,
            source: "Heitz 2014 eqs. 86, 98",
            reference: |x| {
                let lo = r::ggx_lambda_vec([&x[0], &x[1], &x[2]], &x[6], &x[7]);
                let li = r::ggx_lambda_vec([&x[3], &x[4], &x[5]], &x[6], &x[7]);
                r::g2_separable(lo, li)
            },
            kernels: kernel!(|x| Ggx::new(x[6], x[7])
                .unwrap()
                .g2_separable(v3(x, 0), v3(x, 3))),
            points: two_dirs_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "Ggx::v_correlated",
            family: Mf,
            source: "Heitz 2014 eqs. 86, 99",
            reference: |x| {
                let lo = r::ggx_lambda_vec([&x[0], &x[1], &x[2]], &x[6], &x[7]);
                let li = r::ggx_lambda_vec([&x[3], &x[4], &x[5]], &x[6], &x[7]);
                r::visibility(r::g2_correlated(lo, &li), &x[2], &x[5])
            },
            kernels: kernel!(|x| Ggx::new(x[6], x[7])
                .unwrap()
                .v_correlated(v3(x, 0), v3(x, 3))),
            points: two_dirs_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "beckmann::d",
            family: Mf,
            source: "Walter et al. 2007 eq. 25",
            reference: |x| r::beckmann_d(&x[0], &x[1]),
            kernels: kernel!(|x| beckmann::d(x[0], x[1])),
            points: cos_alpha,
            perturbed: harness::FIRST,
        },
        Case {
            name: "Beckmann::d",
            family: Mf,
            source: "Heitz 2014 eq. 80, anisotropic",
            reference: |x| r::beckmann_d_aniso(&x[0], &x[1], &x[2], &x[3], &x[4]),
            kernels: kernel!(|x| Beckmann::new(x[3], x[4]).unwrap().d(v3(x, 0))),
            points: dir_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "beckmann::lambda",
            family: Mf,
            source: "Heitz 2014 eq. 83 (MPFR erfc)",
            reference: |x| r::beckmann_lambda(&x[0], &x[1]),
            kernels: kernel!(|x| beckmann::lambda(x[0], x[1])),
            points: cos_alpha_beckmann,
            perturbed: harness::FIRST,
        },
        Case {
            name: "beckmann::g1",
            family: Mf,
            source: "Heitz 2014 eqs. 43, 83",
            reference: |x| r::g1(r::beckmann_lambda(&x[0], &x[1])),
            kernels: kernel!(|x| beckmann::g1(x[0], x[1])),
            points: cos_alpha_beckmann,
            perturbed: harness::FIRST,
        },
        Case {
            name: "Beckmann::lambda",
            family: Mf,
            source: "Heitz 2014 eq. 83, anisotropic",
            reference: |x| r::beckmann_lambda_vec([&x[0], &x[1], &x[2]], &x[3], &x[4]),
            kernels: kernel!(|x| Beckmann::new(x[3], x[4]).unwrap().lambda(v3(x, 0))),
            points: dir_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "Beckmann::v_correlated",
            family: Mf,
            source: "Heitz 2014 eqs. 83, 99",
            reference: |x| {
                let lo = r::beckmann_lambda_vec([&x[0], &x[1], &x[2]], &x[6], &x[7]);
                let li = r::beckmann_lambda_vec([&x[3], &x[4], &x[5]], &x[6], &x[7]);
                r::visibility(r::g2_correlated(lo, &li), &x[2], &x[5])
            },
            kernels: kernel!(|x| Beckmann::new(x[6], x[7])
                .unwrap()
                .v_correlated(v3(x, 0), v3(x, 3))),
            points: two_dirs_alphas,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::dielectric",
            family: Fresnel,
            source: "Born and Wolf 1.5.2, Snell",
            reference: ref_dielectric,
            kernels: kernel!(|x| fresnel::dielectric(x[0], x[1])),
            points: dielectric_main,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::dielectric (ill-conditioned)",
            family: Fresnel,
            source: "Born and Wolf 1.5.2, Snell",
            reference: ref_dielectric,
            kernels: kernel!(|x| fresnel::dielectric(x[0], x[1])),
            points: dielectric_ill,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::dielectric_polarized (Rs)",
            family: Fresnel,
            source: "Born and Wolf 1.5.2, Snell",
            reference: ref_rs,
            kernels: kernel!(|x| fresnel::dielectric_polarized(x[0], x[1]).0),
            points: rs_main,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::dielectric_polarized (Rs) (ill-conditioned)",
            family: Fresnel,
            source: "Born and Wolf 1.5.2, Snell",
            reference: ref_rs,
            kernels: kernel!(|x| fresnel::dielectric_polarized(x[0], x[1]).0),
            points: rs_ill,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::dielectric_polarized (Rp)",
            family: Fresnel,
            source: "Born and Wolf 1.5.2, Snell",
            reference: ref_rp,
            kernels: kernel!(|x| fresnel::dielectric_polarized(x[0], x[1]).1),
            points: rp_main,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::dielectric_polarized (Rp) (ill-conditioned)",
            family: Fresnel,
            source: "Born and Wolf 1.5.2, Snell",
            reference: ref_rp,
            kernels: kernel!(|x| fresnel::dielectric_polarized(x[0], x[1]).1),
            points: rp_ill,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::conductor",
            family: Fresnel,
            source: "Born and Wolf 14.2, complex Snell",
            reference: ref_conductor,
            kernels: kernel!(|x| fresnel::conductor(x[0], x[1], x[2])),
            points: conductor_main,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::conductor (ill-conditioned)",
            family: Fresnel,
            source: "Born and Wolf 14.2, complex Snell",
            reference: ref_conductor,
            kernels: kernel!(|x| fresnel::conductor(x[0], x[1], x[2])),
            points: conductor_ill,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::schlick",
            family: Fresnel,
            source: "Schlick 1994 eq. 15",
            reference: |x| r::schlick(&x[0], &x[1]),
            kernels: kernel!(|x| fresnel::schlick(x[0], x[1])),
            points: f0_cos,
            perturbed: harness::FIRST,
        },
        Case {
            name: "fresnel::f0_from_ior",
            family: Fresnel,
            source: "Fresnel at normal incidence",
            reference: |x| r::f0_from_ior(&x[0]),
            kernels: kernel!(|x| fresnel::f0_from_ior(x[0])),
            points: eta_only,
            perturbed: harness::FIRST,
        },
        Case {
            name: "color::srgb_oetf",
            family: Color,
            source: "IEC 61966-2-1",
            reference: |x| r::srgb_oetf(&x[0]),
            kernels: kernel!(|x| color::srgb_oetf(x[0])),
            points: srgb_oetf_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "color::srgb_eotf",
            family: Color,
            source: "IEC 61966-2-1",
            reference: |x| r::srgb_eotf(&x[0]),
            kernels: kernel!(|x| color::srgb_eotf(x[0])),
            points: srgb_eotf_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "color::rec709_oetf",
            family: Color,
            source: "ITU-R BT.709-6",
            reference: |x| r::rec709_oetf(&x[0]),
            kernels: kernel!(|x| color::rec709_oetf(x[0])),
            points: rec709_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::lambert",
            family: Lobes,
            source: "Lambert 1760",
            reference: |x| r::lambert(&x[0], &x[1], &x[2]),
            kernels: kernel!(|x| diffuse::lambert(x[0], x[1], x[2])),
            points: lambert_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::oren_nayar",
            family: Lobes,
            source: "Oren and Nayar 1994 eq. 30",
            reference: |x| realizable(x, r::oren_nayar),
            kernels: kernel!(|x| diffuse::oren_nayar(x[0], x[1], x[2], x[3], x[4])),
            points: oren_nayar_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::burley",
            family: Lobes,
            source: "Burley 2012 sec. 5.3",
            reference: |x| r::burley(&x[0], &x[1], &x[2], &x[3], &x[4]),
            kernels: kernel!(|x| diffuse::burley(x[0], x[1], x[2], x[3], x[4])),
            points: burley_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::burley_renormalized",
            family: Lobes,
            source: "Lagarde and de Rousiers 2014 sec. 3.1",
            reference: |x| r::burley_renormalized(&x[0], &x[1], &x[2], &x[3], &x[4]),
            kernels: kernel!(|x| diffuse::burley_renormalized(x[0], x[1], x[2], x[3], x[4])),
            points: burley_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::oren_nayar_full",
            family: Lobes,
            source: "Oren and Nayar 1994 sec. 4",
            reference: ref_oren_nayar_full,
            kernels: kernel!(|x| diffuse::oren_nayar_full(x[0], x[1], x[2], x[3], x[4])),
            points: oren_nayar_full_main,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::oren_nayar_full (ill-conditioned)",
            family: Lobes,
            source: "Oren and Nayar 1994 sec. 4",
            reference: ref_oren_nayar_full,
            kernels: kernel!(|x| diffuse::oren_nayar_full(x[0], x[1], x[2], x[3], x[4])),
            points: oren_nayar_full_ill,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::oren_nayar_fujii",
            family: Lobes,
            source: "Fujii 2012",
            reference: |x| realizable(x, r::oren_nayar_fujii),
            kernels: kernel!(|x| diffuse::oren_nayar_fujii(x[0], x[1], x[2], x[3], x[4])),
            points: fujii_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "diffuse::eon",
            family: Lobes,
            source: "Portsmouth et al. 2025, f_EON exact",
            reference: |x| realizable(x, r::eon),
            kernels: kernel!(|x| diffuse::eon(x[0], x[1], x[2], x[3], x[4])),
            points: fujii_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "phong::normalized",
            family: Lobes,
            source: "Lafortune and Willems 1994",
            reference: |x| r::phong_normalized(&x[0], &x[1], &x[2], &x[3], &x[4]),
            kernels: kernel!(|x| phong::normalized(x[0], x[1], x[2], x[3], x[4])),
            points: phong_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "phong::modified",
            family: Lobes,
            source: "Lewis 1994",
            reference: |x| r::phong_modified(&x[0], &x[1], &x[2], &x[3], &x[4]),
            kernels: kernel!(|x| phong::modified(x[0], x[1], x[2], x[3], x[4])),
            points: phong_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "phong::blinn_phong",
            family: Lobes,
            source: "Blinn 1977",
            reference: |x| r::blinn_phong(&x[0], &x[1], &x[2], &x[3], &x[4]),
            kernels: kernel!(|x| phong::blinn_phong(x[0], x[1], x[2], x[3], x[4])),
            points: phong_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "phong::blinn_phong_normalization_exact",
            family: Lobes,
            source: "exact c(n), as Giesen 2009",
            reference: |x| r::blinn_phong_normalization(&x[0]),
            kernels: kernel!(|x| phong::blinn_phong_normalization_exact(x[0])),
            points: exponent_points,
            perturbed: harness::FIRST,
        },
        Case {
            name: "phong::blinn_phong_normalized",
            family: Lobes,
            source: "exact c(n), as Giesen 2009",
            reference: |x| r::blinn_phong_normalized(&x[0], &x[1], &x[2], &x[3], &x[4]),
            kernels: kernel!(|x| phong::blinn_phong_normalized(x[0], x[1], x[2], x[3], x[4])),
            points: phong_points,
            perturbed: harness::FIRST,
        },
    ];
    all.extend(crate::tonemap_cases::all());
    all.extend(crate::tonemap_cases::agx());
    all
}

/// The case named `name`.
///
/// # Panics
/// If there is none (a typo in a test).
#[must_use]
pub fn by_name(name: &str) -> Case {
    all()
        .into_iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no case named {name}"))
}
