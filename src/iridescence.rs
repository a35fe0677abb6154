//! Thin-film iridescence: the Fresnel reflectance of a base (dielectric or conductor) under a
//! thin dielectric film, interference included, integrated over the visible spectrum
//! analytically in CIE XYZ. After Belcour and Barla 2017, "A Practical Extension to Microfacet
//! Theory for the Modeling of Varying Iridescence" (ACM TOG 36(4), SIGGRAPH), as glTF's
//! `KHR_materials_iridescence` and the Khronos glTF-Sample-Viewer use it.
//!
//! # The model
//! Light from the outside medium (index n1) meets a film (index n2, thickness d) on a base
//! (index n3 + i k3). With c1 = cos(theta_1), Snell's law gives c2 in the film; for each
//! polarization (s, p) the interfaces have reflectances R12, R23 and phase shifts phi21, phi23
//! (the conductor's phi23 is that of its complex Fresnel coefficient: the phase shift a metal
//! gives the reflected wave), and T121 = 1 - R12. The Airy summation of the film's multiple
//! reflections, R = |r12 + t12 t21 r23 e^{i Delta} / (1 - r21 r23 e^{i Delta})|^2 with the
//! optical phase Delta = 2 pi OPD / lambda and OPD = 2 n2 d c2, is the series (Belcour and
//! Barla 2017, eq. 10)
//!
//! ```text
//! R = C0 + 2 sum_{m >= 1} C_m cos(m (Delta + phi21 + phi23)),
//! C0 = R12 + Rs, Rs = T121^2 R23 / (1 - R12 R23), C_m = (Rs - T121) (R12 R23)^{m/2}.
//! ```
//!
//! Integrated against the CIE 1931 colour-matching functions over wavelength, each cosine
//! becomes the Fourier transform of the sensitivity at m OPD, which the paper fits with
//! Gaussians (its supplemental code, `evalSensitivity`: one Gaussian each for Y and Z, two for
//! X, normalized by the integral of y-bar, 1.0685e-7 m). The result is the film's XYZ
//! reflectance under an equal-energy illuminant, normalized so that a reflectance of 1 at every
//! wavelength has Y = 1 (and X, Z = 1 within the CIE tables' 4e-4); the sum runs to m = 3
//! (the paper's code), whose neglected terms are below (R12 R23)^2. s and p are averaged.
//!
//! As in the paper and the sample viewer, the film's index is blended to the outside index as
//! the thickness goes to 0 (n2' = n1 + (n2 - n1) smoothstep(0, 30 nm, d)), so that a
//! vanishing film gives the base's own Fresnel reflectance: for d = 0 and for n2 = n1 the
//! result is exactly the two-interface-free Fresnel reflectance of the base seen from the
//! outside (R12 = 0, every C_m = 0).
//!
//! The Khronos glTF-Sample-Viewer's `evalIridescence` (`iridescence.glsl` at commit
//! 14c393ecf0292030945fcebdf658b143329b8897, base (n, k) from F0 by Gulbrandsen's
//! `artisticIor`) computes the same polarized series and differs in four ways: it stops at
//! m = 2; it adds C0 as white in linear Rec.709 (the crate adds it as white in XYZ, which the
//! matrix below maps to C0 times its row sums 1.205, 0.948, 0.909); its conductor phase
//! formula expects the base index as n (1 + i kappa) but is handed the extinction k itself
//! (kappa = k / n), which shifts a metal's phase; and it writes the index blend as
//! smoothstep(0, 0.03, d) with d in nanometres (a step at 0.03 nm, the paper's 0.03
//! micrometres read in the wrong unit). With those four read the crate's way its result equals
//! the crate's to 2.6e-5 in linear Rec.709; as shipped it differs by up to 0.16 on dielectric
//! and 0.29 on metal bases (`cargo test --test iridescence viewer:: -- --nocapture`). Older
//! viewer versions (commit 60f616a5209e43d1359ee106b747376065180095) used Schlick's
//! approximation for both interfaces, unpolarized.
//!
//! Convert the XYZ result to linear Rec.709 / sRGB with [`XYZ_TO_REC709`] (the paper's and the
//! viewer's matrix), clamping negatives (out-of-gamut colours).

use crate::domain::nan_unless;
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

/// The largest film thickness [`ThinFilm::new`] accepts, in nanometres. Why 10 um: the m-th
/// interference term is damped by exp(-var (2 pi m OPD)^2) with the fits' smallest variance
/// 4.3e9 m^-2; at OPD = 2 n2 d c2 >= 2 x 10 um x c2 that is below e^-60 for c2 above 0.2, so
/// thicker films add only their incoherent reflectance C0 and are outside what the Gaussian
/// fits were made for (`KHR_materials_iridescence` uses 100 to 400 nm by default).
pub const MAX_THICKNESS_NM: f64 = 10_000.0;

/// The largest film index [`ThinFilm::new`] accepts. The densest transparent solids have
/// indices near 4 (germanium in the infrared); 10 leaves room and keeps (n1 / n2)^2 sin^2 and
/// every product of the film formulas far inside f32's range.
pub const MAX_FILM_IOR: f64 = 10.0;

/// The base's relative index (n3 and k3 over the film's index) is clamped to this: its
/// Fresnel reflectance is then within 4e-6 of 1, and the complex square root of
/// N3^2 - sin^2 stays finite in f32 (the clamp changes F by less than 4e-6).
const MAX_BASE_RATIO: f64 = 1e6;

/// CIE XYZ to linear Rec.709 (sRGB primaries, D65 white), row-major: the matrix of Belcour
/// and Barla 2017's supplemental code and of the Khronos glTF-Sample-Viewer (IEC 61966-2-1).
pub const XYZ_TO_REC709: [[f64; 3]; 3] = [
    [3.240_454_2, -1.537_138_5, -0.498_531_4],
    [-0.969_266_0, 1.876_010_8, 0.041_556_0],
    [0.055_643_4, -0.204_025_9, 1.057_225_2],
];

/// A thin dielectric film: thickness d in nanometres and index of refraction n2
/// (`KHR_materials_iridescence`'s `iridescenceThickness...` and `iridescenceIor`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThinFilm<T> {
    thickness: T,
    ior: T,
}

impl<T: Real> ThinFilm<T> {
    /// A film of `thickness` in [0, [`MAX_THICKNESS_NM`]] nanometres and index `ior` in
    /// [1, [`MAX_FILM_IOR`]] (glTF's `iridescenceIor` has minimum 1 and default 1.3), in every
    /// lane, else [`ParamError`].
    pub fn new(thickness: T, ior: T) -> Result<Self, ParamError> {
        require::<T>(
            thickness.simd_ge(T::ZERO) & thickness.simd_le(T::splat(MAX_THICKNESS_NM)),
            "thickness",
            "in [0, MAX_THICKNESS_NM] nanometres",
        )?;
        require::<T>(
            ior.simd_ge(T::ONE) & ior.simd_le(T::splat(MAX_FILM_IOR)),
            "ior",
            "in [1, MAX_FILM_IOR]",
        )?;
        Ok(Self { thickness, ior })
    }

    /// The thickness in nanometres, as given.
    #[inline]
    #[must_use]
    pub fn thickness(&self) -> T {
        self.thickness
    }

    /// The film's index of refraction, as given.
    #[inline]
    #[must_use]
    pub fn ior(&self) -> T {
        self.ior
    }
}

/// A complex number of lanes, for the Fresnel coefficients.
#[derive(Clone, Copy)]
struct C<T> {
    re: T,
    im: T,
}

impl<T: Real> C<T> {
    fn real(re: T) -> Self {
        Self { re, im: T::ZERO }
    }
    fn add(self, o: Self) -> Self {
        Self {
            re: self.re + o.re,
            im: self.im + o.im,
        }
    }
    fn sub(self, o: Self) -> Self {
        Self {
            re: self.re - o.re,
            im: self.im - o.im,
        }
    }
    fn mul(self, o: Self) -> Self {
        Self {
            re: self.re * o.re - self.im * o.im,
            im: self.re * o.im + self.im * o.re,
        }
    }
    fn norm2(self) -> T {
        self.re * self.re + self.im * self.im
    }
    /// Principal square root (Re >= 0; Im >= 0 for a negative real), without the cancellation
    /// of sqrt((|z| - x) / 2).
    fn sqrt(self) -> Self {
        let m = self.norm2().sqrt();
        let t = (T::HALF * (m + self.re.abs())).sqrt();
        let safe = T::select(t.simd_gt(T::ZERO), t, T::ONE);
        let other = self.im.abs() / (T::TWO * safe);
        let pos = self.re.simd_ge(T::ZERO);
        let re = T::select(pos, t, other);
        let im = T::select(pos, self.im / (T::TWO * safe), t.copysign(self.im));
        let zero = t.simd_eq(T::ZERO);
        Self {
            re: T::select(zero, T::ZERO, re),
            im: T::select(zero, T::ZERO, im),
        }
    }
}

/// Reflectance |r|^2 and phase arg(r) of r = (a - b) / (a + b).
fn coefficient<T: Real>(a: C<T>, b: C<T>) -> (T, T) {
    // Both scaled by their largest component: the ratio is unchanged and |a + b|^2 can no
    // longer overflow (an outside index of 1e30 over a film of 1 in f32).
    let big = a.re.abs().max(a.im.abs()).max(b.re.abs()).max(b.im.abs());
    let inv = T::select(big.simd_gt(T::ZERO), big.recip().min(T::MAX), T::ONE);
    let (a, b) = (a.mul(C::real(inv)), b.mul(C::real(inv)));
    let (n, d) = (a.sub(b), a.add(b));
    let d2 = d.norm2();
    let r = T::select(d2.simd_gt(T::ZERO), n.norm2() / d2, T::ONE);
    // r = n conj(d) / |d|^2: its argument is that of n conj(d).
    let re = n.re * d.re + n.im * d.im;
    let im = n.im * d.re - n.re * d.im;
    (r.min(T::ONE), im.atan2(re))
}

/// The fits' Fourier transform of the XYZ sensitivities at an optical path difference `opd`
/// (nanometres) with phase `shift` (Belcour and Barla 2017, supplemental `evalSensitivity`),
/// normalized by the integral of y-bar (1.0685e-7 m).
fn sensitivity<T: Real>(opd: T, shift: T) -> V3<T> {
    // (amplitude val sqrt(2 pi var) / 1.0685e-7, position (1/m), variance (1/m^2)).
    const NORM: f64 = 1.0685e-7;
    let lobe = |val: f64, pos: f64, var: f64, phase: T| {
        let amp = val * libm::sqrt(2.0 * core::f64::consts::PI * var) / NORM;
        T::splat(amp)
            * (T::splat(pos) * phase + shift).cos()
            * (-T::splat(var) * phase * phase).exp()
    };
    let phase = T::splat(2.0 * core::f64::consts::PI * 1e-9) * opd;
    V3::new(
        lobe(5.4856e-13, 1.6810e+06, 4.3278e+09, phase)
            + lobe(9.7470e-14, 2.2399e+06, 4.5282e+09, phase),
        lobe(4.4201e-13, 1.7953e+06, 9.3046e+09, phase),
        lobe(5.2481e-13, 2.2084e+06, 6.6121e+09, phase),
    )
}

/// The film's XYZ reflectance over a base of complex index n3 + i k3 (module docs).
fn film_xyz<T: Real>(film: &ThinFilm<T>, n1: T, n3: T, k3: T, cos_theta: T) -> V3<T> {
    let c1 = cos_theta.clamp(T::ZERO, T::ONE);
    let d = film.thickness;
    // smoothstep(0, 30 nm, d): the film's index tends to the outside's as d -> 0.
    let x = (d / T::splat(30.0)).saturate();
    let blend = x * x * (T::splat(3.0) - T::TWO * x);
    // Written as a mix, not n1 + (n2 - n1) t: that form cancels to 0 for an n1 near MAX.
    let n2 = n1 * (T::ONE - blend) + film.ior * blend;
    // Indices relative to the film (n2 in [1, 10] once blended with an n1 in that range; an
    // extreme n1 only makes the top interface totally reflecting).
    let e1 = n1 / n2;
    let cap = T::splat(MAX_BASE_RATIO);
    let (e3, k) = ((n3 / n2).min(cap), (k3 / n2).min(cap));
    let sin1 = (T::ONE - c1) * (T::ONE + c1);
    let sin2 = (e1 * e1).min(T::MAX) * sin1;
    let tir = sin2.simd_ge(T::ONE) & sin1.simd_gt(T::ZERO);
    let c2 = (T::ONE - sin2.min(T::ONE)).sqrt_nonneg();
    // First interface, outside -> film (real coefficients): s and p.
    let (r12s, phi12s) = coefficient(C::real(e1 * c1), C::real(c2));
    let (r12p, phi12p) = coefficient(C::real(c1), C::real(e1 * c2));
    // Second interface, film -> base: w = N3 cos(theta_3) = sqrt(N3^2 - sin^2 theta_2).
    let n3c = C { re: e3, im: k };
    let n3sq = n3c.mul(n3c);
    let w = n3sq.sub(C::real(sin2.min(T::ONE))).sqrt();
    let (r23s, phi23s) = coefficient(C::real(c2), w);
    let (r23p, phi23p) = coefficient(n3sq.mul(C::real(c2)), w);
    // n2 d is capped at 1e7 nm: beyond it every interference term is below e^-1e7 (module
    // docs), and an n2 near MAX (a film blended to a huge outside index) would overflow.
    let opd = (n2 * d).min(T::splat(1e7)) * c2 * T::TWO;
    let pol = |r12: T, phi12: T, r23: T, phi23: T| {
        let t121 = T::ONE - r12;
        let r123 = (r12 * r23).min(T::ONE);
        // R12 R23 < 1 unless both interfaces reflect totally (then C0 = 1 below).
        let den = T::select(r123.simd_lt(T::ONE), T::ONE - r123, T::ONE);
        let rs = t121 * t121 * r23 / den;
        let c0 = r12 + rs;
        // phi21 = phi12 + pi: r21 = -r12 at a dielectric interface.
        let phi = phi12 + T::PI + phi23;
        let root = r123.sqrt();
        let mut cm = rs - t121;
        let mut xyz = V3::splat(c0);
        for m in 1..=3 {
            cm *= root;
            let mf = T::splat(f64::from(m));
            xyz += sensitivity(mf * opd, mf * phi) * (T::TWO * cm);
        }
        xyz
    };
    let s = pol(r12s, phi12s, r23s, phi23s);
    let p = pol(r12p, phi12p, r23p, phi23p);
    let xyz = (s + p) * T::HALF;
    xyz.map(|v| T::select(tir, T::ONE, v.saturate()))
}

/// True where an index is in (0, MAX] (false for NaN and +inf).
#[inline]
fn ior_ok<T: Real>(n: T) -> T::Mask {
    n.simd_gt(T::ZERO) & n.simd_le(T::MAX)
}

/// XYZ reflectance (equal-energy illuminant, Y of a perfect reflector = 1) of a dielectric base
/// of index `base_ior` under a thin film, seen from a medium of index `outside_ior` at angle
/// theta (cos_theta = n.v, or v.h on a microfacet): the Airy summation of Belcour and Barla 2017
/// (eq. 10) with the spectral integration done in XYZ by the paper's Gaussian fits (module
/// docs). Each component clamped to [0, 1] (the fits can overshoot 1 by about 1e-3).
///
/// Domain: outside_ior and base_ior in (0, MAX], finite; cos_theta in [0, 1] (clamped into
/// it). Edges: thickness 0 or a film index equal to outside_ior gives exactly the base's
/// Fresnel reflectance `fresnel::dielectric(cos_theta, base_ior / outside_ior)` in all three
/// components (to rounding); total internal reflection at the film's top (outside_ior above
/// the film's) gives (1, 1, 1); at the base, the complex reflection coefficient's phase.
/// NaN in any input and an index outside its domain give NaN.
///
/// ```
/// use brdf::iridescence::{ThinFilm, dielectric};
/// let soap = ThinFilm::new(300.0_f64, 1.33).unwrap();
/// let xyz = dielectric(&soap, 1.0, 1.33, 1.0);
/// assert!(xyz.x >= 0.0 && xyz.y <= 1.0);
/// let none = dielectric(&ThinFilm::new(0.0_f64, 1.33).unwrap(), 1.0, 1.5, 1.0);
/// assert!((none.y - 0.04).abs() < 1e-12); // the bare base: ((1.5 - 1) / (1.5 + 1))^2
/// ```
#[inline]
#[must_use]
pub fn dielectric<T: Real>(film: &ThinFilm<T>, outside_ior: T, base_ior: T, cos_theta: T) -> V3<T> {
    let xyz = film_xyz(film, outside_ior, base_ior, T::ZERO, cos_theta);
    let ok = ior_ok(outside_ior) & ior_ok(base_ior) & !cos_theta.is_nan();
    xyz.map(|v| nan_unless(ok, v))
}

/// [`dielectric`] over a conductor base of complex index `base_eta` + i `base_k` (a metal's
/// refractive index and extinction coefficient, or the per-channel values a renderer keeps):
/// the film -> base interface's reflectances and phase shifts are those of the complex Fresnel
/// coefficients (Born and Wolf, section 14.2), the phase shift that gives tarnished and
/// heat-tinted metals their colours (Belcour and Barla 2017, section 4).
///
/// Domain: outside_ior and base_eta in (0, MAX], base_k in [0, MAX], all finite; cos_theta in
/// [0, 1]. Edges: base_k = 0 equals [`dielectric`]; thickness 0 gives exactly
/// `fresnel::conductor(cos_theta, base_eta / outside_ior, base_k / outside_ior)` (to rounding);
/// NaN in any input, an index outside its domain and a negative k give NaN.
#[inline]
#[must_use]
pub fn conductor<T: Real>(
    film: &ThinFilm<T>,
    outside_ior: T,
    base_eta: T,
    base_k: T,
    cos_theta: T,
) -> V3<T> {
    let xyz = film_xyz(film, outside_ior, base_eta, base_k, cos_theta);
    let k_ok = base_k.simd_ge(T::ZERO) & base_k.simd_le(T::MAX);
    let ok = ior_ok(outside_ior) & ior_ok(base_eta) & k_ok & !cos_theta.is_nan();
    xyz.map(|v| nan_unless(ok, v))
}
