//! The references: each function written from its published definition on MPFR floats, with
//! no rearrangement for floating-point stability (the working precision makes the textbook
//! cancellations harmless; `tests/harness.rs` checks that by evaluating every point again at
//! twice the precision).
//!
//! Arguments are MPFR floats holding the exact value of the `f32` or `f64` input; every result
//! is computed at the arguments' precision (see [`crate::PREC`]).
//!
//! Vector arguments (x, y, z) in the local shading frame map to the papers' angles as
//! cos(theta) = z, tan(theta) cos(phi) = x / z, tan(theta) sin(phi) = y / z, so
//! tan^2(theta) = (x^2 + y^2) / z^2: the definition is then a function of the three components
//! as given, and a direction that rounding left off the unit sphere is not charged to the
//! kernel.

use rug::Float;
use rug::float::Constant;
use rug::ops::Pow;

/// A float of precision `prec` holding `v` exactly.
#[must_use]
pub fn num(prec: u32, v: f64) -> Float {
    Float::with_val(prec, v)
}

/// A float of precision `prec` holding the decimal constant `s` rounded once (a standard's
/// constant such as 0.0031308 is a decimal, not its nearest `f64`).
///
/// # Panics
/// If `s` is not a number (a typo in this crate's constants).
#[must_use]
pub fn dec(prec: u32, s: &str) -> Float {
    Float::with_val(prec, Float::parse(s).expect("a decimal constant"))
}

/// pi at precision `prec`.
#[must_use]
pub fn pi(prec: u32) -> Float {
    Float::with_val(prec, Constant::Pi)
}

/// `a / b` for integers at precision `prec` (exponents such as 1/2.4 = 5/12).
#[must_use]
pub fn ratio(prec: u32, a: i32, b: i32) -> Float {
    Float::with_val(prec, a) / b
}

/// x^2.
fn sq(x: &Float) -> Float {
    x.clone().square()
}

/// tan^2(theta) = (1 - cos^2) / cos^2 for a cosine alone.
fn tan2_of_cos(c: &Float) -> Float {
    (1i32 - sq(c)) / sq(c)
}

/// alpha(phi)^2 = cos^2(phi) ax^2 + sin^2(phi) ay^2 with cos(phi) = x / sqrt(x^2 + y^2)
/// (Heitz 2014, section 5.3); ax^2 when x = y = 0, where it multiplies tan = 0 anyway.
fn alpha_phi2(x: &Float, y: &Float, ax: &Float, ay: &Float) -> Float {
    let s2 = sq(x) + sq(y);
    if s2.is_zero() {
        return sq(ax);
    }
    (sq(ax) * sq(x) + sq(ay) * sq(y)) / s2
}

/// GGX NDF, Walter et al. 2007 eq. 33:
/// D = alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2) for cos > 0, else 0.
#[must_use]
pub fn ggx_d(c: &Float, alpha: &Float) -> Float {
    let p = c.prec();
    if *c <= 0 {
        return num(p, 0.0);
    }
    let t = sq(alpha) + tan2_of_cos(c);
    sq(alpha) / (pi(p) * sq(&sq(c)) * sq(&t))
}

/// Anisotropic GGX NDF, Heitz 2014 eq. 85:
/// D = 1 / (pi ax ay cos^4 (1 + tan^2 (cos^2 phi / ax^2 + sin^2 phi / ay^2))^2) for z > 0.
#[must_use]
pub fn ggx_d_aniso(x: &Float, y: &Float, z: &Float, ax: &Float, ay: &Float) -> Float {
    let p = z.prec();
    if *z <= 0 {
        return num(p, 0.0);
    }
    let z2 = sq(z);
    let e = 1i32 + sq(x) / (sq(ax) * &z2) + sq(y) / (sq(ay) * &z2);
    let den = pi(p) * ax * ay * sq(&z2) * sq(&e);
    den.recip()
}

/// GGX Smith Lambda from a = 1 / (alpha tan), Heitz 2014 eq. 86:
/// Lambda = (-1 + sqrt(1 + 1 / a^2)) / 2.
fn ggx_lambda_of(alpha2: &Float, tan2: &Float) -> Float {
    let inv_a2 = Float::with_val(tan2.prec(), alpha2 * tan2);
    ((1i32 + inv_a2).sqrt() - 1i32) / 2i32
}

/// Isotropic GGX Lambda of a cosine (Heitz 2014 eq. 86), of |cos|.
#[must_use]
pub fn ggx_lambda(c: &Float, alpha: &Float) -> Float {
    ggx_lambda_of(&sq(alpha), &tan2_of_cos(&c.clone().abs()))
}

/// GGX Lambda of a direction with anisotropic alpha(phi) (Heitz 2014 eq. 86 with section 5.3).
#[must_use]
pub fn ggx_lambda_vec(w: [&Float; 3], ax: &Float, ay: &Float) -> Float {
    let [x, y, z] = w;
    let tan2 = (sq(x) + sq(y)) / sq(z);
    ggx_lambda_of(&alpha_phi2(x, y, ax, ay), &tan2)
}

/// Smith masking G1 = 1 / (1 + Lambda) (Heitz 2014 eq. 43).
#[must_use]
pub fn g1(lambda: Float) -> Float {
    (1i32 + lambda).recip()
}

/// Height-correlated G2 = 1 / (1 + Lambda_o + Lambda_i) (Heitz 2014 eq. 99).
#[must_use]
pub fn g2_correlated(lo: Float, li: &Float) -> Float {
    (1i32 + lo + li).recip()
}

/// Separable G2 = G1_o G1_i (Heitz 2014 eq. 98).
#[must_use]
pub fn g2_separable(lo: Float, li: Float) -> Float {
    g1(lo) * g1(li)
}

/// Visibility V = G2 / (4 |cos_o| |cos_i|).
#[must_use]
pub fn visibility(g2: Float, co: &Float, ci: &Float) -> Float {
    g2 / (4i32 * Float::with_val(co.prec(), co * ci).abs())
}

/// Beckmann NDF, Walter et al. 2007 eq. 25:
/// D = exp(-tan^2 / alpha^2) / (pi alpha^2 cos^4) for cos > 0, else 0.
#[must_use]
pub fn beckmann_d(c: &Float, alpha: &Float) -> Float {
    let p = c.prec();
    if *c <= 0 {
        return num(p, 0.0);
    }
    let e = (-tan2_of_cos(c) / sq(alpha)).exp();
    e / (pi(p) * sq(alpha) * sq(&sq(c)))
}

/// Anisotropic Beckmann NDF (Heitz 2014 eq. 80's anisotropic form):
/// D = exp(-tan^2 (cos^2 phi / ax^2 + sin^2 phi / ay^2)) / (pi ax ay cos^4) for z > 0.
#[must_use]
pub fn beckmann_d_aniso(x: &Float, y: &Float, z: &Float, ax: &Float, ay: &Float) -> Float {
    let p = z.prec();
    if *z <= 0 {
        return num(p, 0.0);
    }
    let z2 = sq(z);
    let e = (-(sq(x) / sq(ax) + sq(y) / sq(ay)) / &z2).exp();
    e / (pi(p) * ax * ay * sq(&z2))
}

/// Beckmann Smith Lambda from a = 1 / (alpha tan), Heitz 2014 eq. 83 with erf(a) - 1 written
/// as -erfc(a): Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2; 0 at a = inf.
///
/// The two terms agree to about 1 / (2 a^2) of their size, so the difference loses
/// log2(2 a^2) bits: 21 bits at a = 1000, out of [`crate::PREC`]. Results below 1e-300
/// (a > 26) are not measured, only checked to be tiny. For a > 27000, exp(-a^2) is below
/// MPFR's smallest exponent (2^-1073741823) and both terms flush to 0: the reference is then
/// 0 (or that exponent's smallest number), and the true Lambda rounds to 0 in every float.
fn beckmann_lambda_of(alpha2: &Float, tan2: &Float) -> Float {
    let p = tan2.prec();
    if tan2.is_zero() {
        return num(p, 0.0);
    }
    let a = Float::with_val(p, alpha2 * tan2).sqrt().recip();
    let t1 = (-sq(&a)).exp() / (a.clone() * pi(p).sqrt());
    (t1 - a.erfc()) / 2i32
}

/// Isotropic Beckmann Lambda of a cosine (Heitz 2014 eq. 83), of |cos|.
#[must_use]
pub fn beckmann_lambda(c: &Float, alpha: &Float) -> Float {
    beckmann_lambda_of(&sq(alpha), &tan2_of_cos(&c.clone().abs()))
}

/// Beckmann Lambda of a direction with anisotropic alpha(phi) (Heitz 2014 eq. 83, section 5.3).
#[must_use]
pub fn beckmann_lambda_vec(w: [&Float; 3], ax: &Float, ay: &Float) -> Float {
    let [x, y, z] = w;
    let tan2 = (sq(x) + sq(y)) / sq(z);
    beckmann_lambda_of(&alpha_phi2(x, y, ax, ay), &tan2)
}

/// Dielectric Fresnel reflectances (Rs, Rp) by the textbook ratios (Born and Wolf, section
/// 1.5.2), with cos_t from Snell's law: r_s = (cos_i - eta cos_t) / (cos_i + eta cos_t),
/// r_p = (eta cos_i - cos_t) / (eta cos_i + cos_t), eta = n_t / n_i. A negative cosine means
/// the light arrives from the other side: eta becomes 1 / eta. sin_t >= 1 is total internal
/// reflection: (1, 1).
#[must_use]
pub fn fresnel_dielectric_polarized(cos_i: &Float, eta: &Float) -> (Float, Float) {
    let p = cos_i.prec();
    let (c, eta) = if *cos_i < 0 {
        (cos_i.clone().abs(), eta.clone().recip())
    } else {
        (cos_i.clone(), eta.clone())
    };
    // eta = 1 is no interface: 0 at every cosine, grazing included (where the limit along
    // cos -> 0 at any other eta is 1, and sin^2(theta_t) = 1 below would call it total
    // internal reflection).
    if eta == 1 {
        return (num(p, 0.0), num(p, 0.0));
    }
    let sin2_t = (1i32 - sq(&c)) / sq(&eta);
    if sin2_t >= 1 {
        return (num(p, 1.0), num(p, 1.0));
    }
    let cos_t = (1i32 - sin2_t).sqrt();
    let et = Float::with_val(p, &eta * &cos_t);
    let ec = Float::with_val(p, &eta * &c);
    let rs = Float::with_val(p, &c - &et) / Float::with_val(p, &c + &et);
    let rp = Float::with_val(p, &ec - &cos_t) / (ec + &cos_t);
    (sq(&rs), sq(&rp))
}

/// Unpolarized dielectric Fresnel reflectance (Rs + Rp) / 2.
#[must_use]
pub fn fresnel_dielectric(cos_i: &Float, eta: &Float) -> Float {
    let (rs, rp) = fresnel_dielectric_polarized(cos_i, eta);
    (rs + rp) / 2i32
}

/// A complex number as (re, im).
type Complex = (Float, Float);

fn c_mul(a: &Complex, b: &Complex) -> Complex {
    let p = a.0.prec();
    let re = Float::with_val(p, &a.0 * &b.0) - Float::with_val(p, &a.1 * &b.1);
    let im = Float::with_val(p, &a.0 * &b.1) + Float::with_val(p, &a.1 * &b.0);
    (re, im)
}

fn c_add(a: &Complex, b: &Complex) -> Complex {
    let p = a.0.prec();
    (
        Float::with_val(p, &a.0 + &b.0),
        Float::with_val(p, &a.1 + &b.1),
    )
}

fn c_sub(a: &Complex, b: &Complex) -> Complex {
    let p = a.0.prec();
    (
        Float::with_val(p, &a.0 - &b.0),
        Float::with_val(p, &a.1 - &b.1),
    )
}

fn c_norm2(a: &Complex) -> Float {
    sq(&a.0) + sq(&a.1)
}

fn c_recip(a: &Complex) -> Complex {
    let n = c_norm2(a);
    (a.0.clone() / &n, -a.1.clone() / n)
}

/// Principal square root of a complex number (re >= 0, im with the sign of the argument's
/// im), written so that nothing cancels: the larger part from sqrt((|a| + |Re a|) / 2), the
/// other as |Im a| / (2 larger). Forming both parts from |a| +- Re a cancels in one of them
/// where |Im a| is far below |Re a| (|N| near 2^-126, where Im(N^2) is 2^-251 beside a sin^2
/// near 1).
fn c_sqrt(a: &Complex) -> Complex {
    let p = a.0.prec();
    if a.0.is_zero() && a.1.is_zero() {
        return (num(p, 0.0), num(p, 0.0));
    }
    let m = c_norm2(a).sqrt();
    let big = ((m + a.0.clone().abs()) / 2i32).sqrt();
    let small = Float::with_val(p, a.1.abs_ref()) / (2i32 * big.clone());
    let (re, im) = if a.0 >= 0 { (big, small) } else { (small, big) };
    let im = if a.1 < 0 { -im } else { im };
    (re, im)
}

/// Conductor Fresnel reflectance with complex relative index eta_c = eta + i k (Born and Wolf,
/// section 14.2): cos_t = sqrt(1 - sin_i^2 / eta_c^2) (principal root), r_s = (cos_i -
/// eta_c cos_t) / (cos_i + eta_c cos_t), r_p = (eta_c cos_i - cos_t) / (eta_c cos_i + cos_t),
/// F = (|r_s|^2 + |r_p|^2) / 2. With Im(eta_c^2 - sin^2) >= 0 the principal cos_t makes
/// eta_c cos_t the decaying root (its argument stays in [0, pi/2]).
#[must_use]
pub fn fresnel_conductor(cos_i: &Float, eta: &Float, k: &Float) -> Float {
    let p = cos_i.prec();
    let zero = num(p, 0.0);
    // eta = 1, k = 0 is no interface: 0 at every cosine (grazing, where the formula is 0 / 0,
    // included).
    if *eta == 1 && k.is_zero() {
        return zero;
    }
    let eta_c: Complex = (eta.clone(), k.clone());
    let sin2 = 1i32 - sq(cos_i);
    let inv_e2 = c_recip(&c_mul(&eta_c, &eta_c));
    let z = (1i32 - sin2.clone() * &inv_e2.0, -sin2 * &inv_e2.1);
    let cos_t = c_sqrt(&z);
    let ci: Complex = (cos_i.clone(), zero);
    let et = c_mul(&eta_c, &cos_t);
    let rs_num = c_norm2(&c_sub(&ci, &et));
    let rs_den = c_norm2(&c_add(&ci, &et));
    let ec = c_mul(&eta_c, &ci);
    let rp_num = c_norm2(&c_sub(&ec, &cos_t));
    let rp_den = c_norm2(&c_add(&ec, &cos_t));
    (rs_num / rs_den + rp_num / rp_den) / 2i32
}

/// Schlick 1994 eq. 15: F = F0 + (1 - F0)(1 - cos)^5.
#[must_use]
pub fn schlick(f0: &Float, c: &Float) -> Float {
    let w = (1i32 - c.clone()).pow(5u32);
    (1i32 - f0.clone()) * w + f0
}

/// Normal-incidence reflectance F0 = ((eta - 1) / (eta + 1))^2.
#[must_use]
pub fn f0_from_ior(eta: &Float) -> Float {
    sq(&((eta.clone() - 1i32) / (eta.clone() + 1i32)))
}

/// sRGB OETF of IEC 61966-2-1: 12.92 x for x <= 0.0031308, else 1.055 x^(1/2.4) - 0.055
/// (exact decimal constants, exponent 5/12).
#[must_use]
pub fn srgb_oetf(x: &Float) -> Float {
    let p = x.prec();
    if *x <= dec(p, "0.0031308") {
        return dec(p, "12.92") * x;
    }
    dec(p, "1.055") * x.clone().pow(&ratio(p, 5, 12)) - dec(p, "0.055")
}

/// sRGB EOTF of IEC 61966-2-1: x / 12.92 for x <= 0.04045, else ((x + 0.055) / 1.055)^2.4.
#[must_use]
pub fn srgb_eotf(x: &Float) -> Float {
    let p = x.prec();
    if *x <= dec(p, "0.04045") {
        return x.clone() / dec(p, "12.92");
    }
    ((x.clone() + dec(p, "0.055")) / dec(p, "1.055")).pow(&ratio(p, 12, 5))
}

/// Rec.709 OETF of ITU-R BT.709-6: 4.5 L for L < 0.018, else 1.099 L^0.45 - 0.099.
#[must_use]
pub fn rec709_oetf(l: &Float) -> Float {
    let p = l.prec();
    if *l < dec(p, "0.018") {
        return dec(p, "4.5") * l;
    }
    dec(p, "1.099") * l.clone().pow(&ratio(p, 9, 20)) - dec(p, "0.099")
}

/// Lambert: f = rho / pi where both cosines are positive, else 0.
#[must_use]
pub fn lambert(cv: &Float, cl: &Float, rho: &Float) -> Float {
    let p = rho.prec();
    if *cv <= 0 || *cl <= 0 {
        return num(p, 0.0);
    }
    rho.clone() / pi(p)
}

/// Oren-Nayar qualitative model in its angle form (Oren and Nayar 1994, eq. 30):
/// f = rho / pi (A + B max(0, cos(phi_i - phi_r)) sin(alpha) tan(beta)) with
/// alpha = max(theta_i, theta_r), beta = min, A = 1 - 0.5 s^2 / (s^2 + 0.33),
/// B = 0.45 s^2 / (s^2 + 0.09), the angles from acos of the cosines and cos(phi_i - phi_r) =
/// (v.l - cos_v cos_l) / (sin_v sin_l).
#[must_use]
pub fn oren_nayar(cv: &Float, cl: &Float, vl: &Float, rho: &Float, sigma: &Float) -> Float {
    let p = rho.prec();
    if *cv <= 0 || *cl <= 0 {
        return num(p, 0.0);
    }
    let s2 = sq(sigma);
    let a = 1i32 - (s2.clone() / 2i32) / (s2.clone() + dec(p, "0.33"));
    let b = dec(p, "0.45") * &s2 / (s2 + dec(p, "0.09"));
    let (tv, tl) = (cv.clone().acos(), cl.clone().acos());
    let (alpha, beta) = if tv >= tl { (tv, tl) } else { (tl, tv) };
    let sin_prod = Float::with_val(p, cv.clone().acos().sin() * cl.clone().acos().sin());
    let cos_phi = if sin_prod.is_zero() {
        num(p, 0.0)
    } else {
        (vl.clone() - Float::with_val(p, cv * cl)) / sin_prod
    };
    let lobe = cos_phi.max(&num(p, 0.0)) * alpha.sin() * beta.tan();
    rho.clone() / pi(p) * (a + b * lobe)
}

/// Burley 2012 diffuse (section 5.3): f = rho / pi (1 + (FD90 - 1)(1 - cos_l)^5)
/// (1 + (FD90 - 1)(1 - cos_v)^5), FD90 = 1/2 + 2 r (l.h)^2.
#[must_use]
pub fn burley(cv: &Float, cl: &Float, lh: &Float, rho: &Float, r: &Float) -> Float {
    let p = rho.prec();
    if *cv <= 0 || *cl <= 0 {
        return num(p, 0.0);
    }
    let fd90 = num(p, 0.5) + 2i32 * r.clone() * sq(lh);
    let fl = 1i32 + (fd90.clone() - 1i32) * (1i32 - cl.clone()).pow(5u32);
    let fv = 1i32 + (fd90 - 1i32) * (1i32 - cv.clone()).pow(5u32);
    rho.clone() / pi(p) * fl * fv
}

/// Normalized modified Phong (Lewis 1994; Lafortune and Willems 1994):
/// f = ks (n + 2) / (2 pi) max(0, r.l)^n where both cosines are positive.
#[must_use]
pub fn phong_normalized(cv: &Float, cl: &Float, rl: &Float, ks: &Float, n: &Float) -> Float {
    let p = ks.prec();
    if *cv <= 0 || *cl <= 0 || *rl <= 0 {
        return num(p, 0.0);
    }
    ks.clone() * (n.clone() + 2i32) / (2i32 * pi(p)) * rl.clone().pow(n)
}

/// Blinn-Phong with the exact BRDF normalization (the crate's derivation, as Giesen 2009):
/// f = ks (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) (n.h)^n where both cosines are positive.
#[must_use]
pub fn blinn_phong_normalized(cv: &Float, cl: &Float, nh: &Float, ks: &Float, n: &Float) -> Float {
    let p = ks.prec();
    if *cv <= 0 || *cl <= 0 || *nh <= 0 {
        return num(p, 0.0);
    }
    let two_pow = (-n.clone() / 2i32).exp2();
    let c = (n.clone() + 2i32) * (n.clone() + 4i32) / (8i32 * pi(p) * (two_pow + n));
    ks.clone() * c * nh.clone().pow(n)
}

/// Lagarde and de Rousiers 2014 (Frostbite's `Fr_DisneyDiffuse`, divided by pi):
/// f = rho / pi k (1 + (FD90 - 1)(1 - cos_l)^5)(1 + (FD90 - 1)(1 - cos_v)^5),
/// FD90 = r / 2 + 2 r (l.h)^2 (energyBias = lerp(0, 1/2, r)), k = lerp(1, 1/1.51, r).
#[must_use]
pub fn burley_renormalized(cv: &Float, cl: &Float, lh: &Float, rho: &Float, r: &Float) -> Float {
    let p = rho.prec();
    if *cv <= 0 || *cl <= 0 {
        return num(p, 0.0);
    }
    let fd90 = r.clone() / 2i32 + 2i32 * r.clone() * sq(lh);
    let k = 1i32 + r.clone() * (1i32 / dec(p, "1.51") - 1i32);
    let fl = 1i32 + (fd90.clone() - 1i32) * (1i32 - cl.clone()).pow(5u32);
    let fv = 1i32 + (fd90 - 1i32) * (1i32 - cv.clone()).pow(5u32);
    rho.clone() / pi(p) * k * fl * fv
}

/// cos(phi_i - phi_r) = (v.l - cos_v cos_l) / (sin_v sin_l) with the sines from acos of the
/// cosines; 0 at a pole (sin_v sin_l = 0), where every term it multiplies vanishes with beta.
/// Clamped into [-1, 1]: cosines rounded to f32 can leave a triple that no pair of unit
/// vectors has, and the kernels document the same clamp for such input.
fn cos_phi(cv: &Float, cl: &Float, vl: &Float) -> Float {
    let p = cv.prec();
    let sin_prod = Float::with_val(p, cv.clone().acos().sin() * cl.clone().acos().sin());
    if sin_prod.is_zero() {
        return num(p, 0.0);
    }
    let c = (vl.clone() - Float::with_val(p, cv * cl)) / sin_prod;
    c.clamp(&num(p, -1.0), &num(p, 1.0))
}

/// Oren-Nayar full model (Oren and Nayar 1994, section 4: eqs. for C1, C2, C3, L1 and the
/// interreflection term L2): f = rho / pi (max(0, L1) + L2),
/// L1 = C1 + cos(phi) C2 tan(beta) + (1 - |cos(phi)|) C3 tan((alpha + beta) / 2),
/// L2 = 0.17 rho s^2 / (s^2 + 0.13) (1 - cos(phi) (2 beta / pi)^2), C1 = 1 - 0.5 s^2 / (s^2 +
/// 0.33), C2 = 0.45 s^2 / (s^2 + 0.09) (sin(alpha) or sin(alpha) - (2 beta / pi)^3 for
/// cos(phi) < 0), C3 = 0.125 s^2 / (s^2 + 0.09) (4 alpha beta / pi^2)^2; the angles from acos.
/// The clamp of L1 at 0 is `brdf`'s documented deviation (the fit goes negative at grazing).
#[must_use]
pub fn oren_nayar_full(cv: &Float, cl: &Float, vl: &Float, rho: &Float, sigma: &Float) -> Float {
    let p = rho.prec();
    if *cv <= 0 || *cl <= 0 {
        return num(p, 0.0);
    }
    let s2 = sq(sigma);
    let c1 = 1i32 - (s2.clone() / 2i32) / (s2.clone() + dec(p, "0.33"));
    let k09 = s2.clone() / (s2.clone() + dec(p, "0.09"));
    let (tv, tl) = (cv.clone().acos(), cl.clone().acos());
    let (alpha, beta) = if tv >= tl { (tv, tl) } else { (tl, tv) };
    let cphi = cos_phi(cv, cl, vl);
    let b2pi = 2i32 * beta.clone() / pi(p);
    let c2 = if cphi >= 0 {
        dec(p, "0.45") * k09.clone() * alpha.clone().sin()
    } else {
        dec(p, "0.45") * k09.clone() * (alpha.clone().sin() - b2pi.clone().pow(3u32))
    };
    let c3 = dec(p, "0.125") * k09 * sq(&(4i32 * alpha.clone() * &beta / sq(&pi(p))));
    let tan_half = ((alpha + &beta) / 2i32).tan();
    let l1 = c1 + cphi.clone() * c2 * beta.tan() + (1i32 - cphi.clone().abs()) * c3 * tan_half;
    let l1 = l1.max(&num(p, 0.0));
    let l2 = dec(p, "0.17") * rho.clone() * s2.clone() / (s2 + dec(p, "0.13"))
        * (1i32 - cphi * sq(&b2pi));
    rho.clone() / pi(p) * (l1 + l2)
}

/// Fujii 2012's improved Oren-Nayar: f = rho (A' + B' s / t), A' = 1 / (pi + (pi/2 - 2/3)
/// sigma), B' = sigma A', s = v.l - cos_v cos_l, t = max(cos_v, cos_l) where s > 0, else 1.
/// s is clamped into [-1, 1], its range for unit vectors, as `brdf` documents (cosines
/// rounded to f32 can leave a triple that no pair of unit vectors has).
#[must_use]
pub fn oren_nayar_fujii(cv: &Float, cl: &Float, vl: &Float, rho: &Float, sigma: &Float) -> Float {
    let p = rho.prec();
    if *cv <= 0 || *cl <= 0 {
        return num(p, 0.0);
    }
    let a = (pi(p) + (pi(p) / 2i32 - ratio(p, 2, 3)) * sigma).recip();
    let b = sigma.clone() * &a;
    let s = (vl.clone() - Float::with_val(p, cv * cl)).clamp(&num(p, -1.0), &num(p, 1.0));
    let t = if s > 0 {
        cv.clone().max(cl)
    } else {
        num(p, 1.0)
    };
    rho.clone() * (a + b * s / t)
}

/// EON (Portsmouth, Kutz, Hill 2025, `f_EON` with the exact FON albedo): f = f_FON + f_ms,
/// f_FON = Fujii's lobe ([`oren_nayar_fujii`] with s clamped into [-1, 1]),
/// f_ms = rho_ms / pi (1 - E(cos_v))(1 - E(cos_l)) / (1 - E_avg), E(mu) = A (1 + sigma G(mu) /
/// pi), G(mu) = S (acos(mu) - S mu) + (2/3)((S / mu)(1 - S^3) - S), S = sqrt(1 - mu^2),
/// A = 1 / (1 + (1/2 - 2/(3 pi)) sigma), E_avg = A (1 + (2/3 - 28/(15 pi)) sigma),
/// rho_ms = rho^2 E_avg / (1 - rho (1 - E_avg)); f_ms = 0 at sigma = 0 (its limit: the
/// numerator is of order sigma^2, the denominator of order sigma).
#[must_use]
pub fn eon(cv: &Float, cl: &Float, vl: &Float, rho: &Float, sigma: &Float) -> Float {
    let p = rho.prec();
    if *cv <= 0 || *cl <= 0 {
        return num(p, 0.0);
    }
    let c1 = num(p, 0.5) - ratio(p, 2, 3) / pi(p);
    let c2 = ratio(p, 2, 3) - ratio(p, 28, 15) / pi(p);
    let a = (1i32 + c1 * sigma).recip();
    let s = (vl.clone() - Float::with_val(p, cv * cl)).clamp(&num(p, -1.0), &num(p, 1.0));
    let s_over_t = if s > 0 { s / cv.clone().max(cl) } else { s };
    let single = rho.clone() / pi(p) * &a * (1i32 + sigma.clone() * s_over_t);
    if sigma.is_zero() {
        return single;
    }
    let e = |mu: &Float| {
        let si = (1i32 - sq(mu)).sqrt();
        let g = si.clone() * (mu.clone().acos() - si.clone() * mu)
            + ratio(p, 2, 3) * ((si.clone() / mu) * (1i32 - si.clone().pow(3u32)) - &si);
        a.clone() * (1i32 + sigma.clone() * g / pi(p))
    };
    let e_avg = a.clone() * (1i32 + c2 * sigma);
    let rho_ms = sq(rho) * &e_avg / (1i32 - rho.clone() * (1i32 - e_avg.clone()));
    let multi = rho_ms / pi(p) * (1i32 - e(cv)) * (1i32 - e(cl)) / (1i32 - e_avg);
    single + multi
}

/// Modified Phong (Lewis 1994): f = ks max(0, r.l)^n where both cosines are positive; 0 where
/// r.l <= 0 (also at n = 0: the limit n -> 0+).
#[must_use]
pub fn phong_modified(cv: &Float, cl: &Float, rl: &Float, ks: &Float, n: &Float) -> Float {
    let p = ks.prec();
    if *cv <= 0 || *cl <= 0 || *rl <= 0 {
        return num(p, 0.0);
    }
    ks.clone() * rl.clone().pow(n)
}

/// Blinn-Phong (Blinn 1977): f = ks (n.h)^n where both cosines are positive.
#[must_use]
pub fn blinn_phong(cv: &Float, cl: &Float, nh: &Float, ks: &Float, n: &Float) -> Float {
    let p = ks.prec();
    if *cv <= 0 || *cl <= 0 || *nh <= 0 {
        return num(p, 0.0);
    }
    ks.clone() * nh.clone().pow(n)
}

/// The exact Blinn-Phong BRDF normalization c(n) = (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)).
#[must_use]
pub fn blinn_phong_normalization(n: &Float) -> Float {
    let p = n.prec();
    let two_pow = (-n.clone() / 2i32).exp2();
    (n.clone() + 2i32) * (n.clone() + 4i32) / (8i32 * pi(p) * (two_pow + n))
}

/// The rough conductor of `brdf::cook_torrance::ggx_conductor_local` from the references of
/// its published parts, one channel, on two local-frame directions taken as given (not
/// renormalized): f = D(h) V(wo, wi) F(v.h) with s = wo + wi and h = s / |s|:
/// [`ggx_d`] at n.h = s_z / |s| (Walter et al. 2007 eq. 33), [`visibility`] of the
/// height-correlated [`g2_correlated`] (Heitz 2014 eq. 99 with eq. 86) at n.v = wo.z and
/// n.l = wi.z saturated to [0, 1], and [`fresnel_conductor`] (Born and Wolf, section 14.2) at
/// c = wo.s / |s| saturated to [0, 1].
///
/// 0 where wo.z <= 0 or wi.z <= 0. `alpha` is taken as given (the caller applies the
/// kernel's clamp). Every argument should hold its `f32` value exactly at a precision such
/// as [`crate::harness::precision_for`]'s, which keeps s, |s|^2 and wo.s exact.
#[must_use]
pub fn ggx_conductor_local(
    wo: [&Float; 3],
    wi: [&Float; 3],
    alpha: &Float,
    eta: &Float,
    k: &Float,
) -> Float {
    let zero = num(alpha.prec(), 0.0);
    ggx_conductor_local_moved(wo, wi, alpha, eta, k, &zero)
}

/// [`ggx_conductor_local`] with F taken at c^2 (1 + `rel`) (saturated to [0, 1]) in place of
/// c^2, D and V unchanged: the change that a relative error `rel` in the kernel's c^2 alone
/// would make, which measures how F's conditioning amplifies the kernel's own roundings of c
/// (near the critical cosine of eta < 1 with small k, dF/dc grows without bound).
#[must_use]
pub fn ggx_conductor_local_moved(
    wo: [&Float; 3],
    wi: [&Float; 3],
    alpha: &Float,
    eta: &Float,
    k: &Float,
    rel: &Float,
) -> Float {
    let p = alpha.prec();
    let zero = num(p, 0.0);
    if *wo[2] <= 0 || *wi[2] <= 0 {
        return zero;
    }
    let s: [Float; 3] = core::array::from_fn(|i| Float::with_val(p, wo[i] + wi[i]));
    let ss = Float::with_val(p, sq(&s[0]) + sq(&s[1])) + sq(&s[2]);
    // D at n.h = s_z / |s| (s_z > 0 above both horizons), V from the two cosines.
    let d = ggx_d(&(Float::with_val(p, &s[2]) / ss.clone().sqrt()), alpha);
    let sat = |c: &Float| c.clone().clamp(&0i32, &1i32);
    let (cv, cl) = (sat(wo[2]), sat(wi[2]));
    let g2 = g2_correlated(ggx_lambda(&cv, alpha), &ggx_lambda(&cl, alpha));
    let v = visibility(g2, &cv, &cl);
    // F at c = wo.s / |s|, saturated (x >= 0, c <= 1), c^2 moved by the factor 1 + rel.
    let x = (Float::with_val(p, wo[0] * &s[0])
        + Float::with_val(p, wo[1] * &s[1])
        + Float::with_val(p, wo[2] * &s[2]))
    .max(&zero);
    let c2 = Float::with_val(p, sq(&x) / &ss) * (1i32 + rel.clone());
    let c = c2.min(&num(p, 1.0)).sqrt();
    d * v * fresnel_conductor(&c, eta, k)
}
