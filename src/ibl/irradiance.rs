//! Diffuse image-based lighting: the irradiance E(n) = integral over the hemisphere around n
//! of L(l) (n.l) dl, by deterministic quadrature ([`irradiance`]) and through 9-coefficient
//! spherical harmonics ([`Sh9`]; Ramamoorthi and Hanrahan 2001, "An Efficient Representation
//! for Irradiance Environment Maps", SIGGRAPH).
//!
//! A Lambertian surface of albedo rho reflects L_o = rho E / pi.
//!
//! Directions are unit world-space vectors; radiance is RGB in a [`V3`] (x = red, y = green,
//! z = blue). The quadratures are `f64` table builders; the per-pixel kernels
//! ([`Sh9::eval`], [`Sh9::irradiance`], [`sh9_basis`]) are generic over [`Real`].
//!
//! Accuracy of SH9 irradiance (max relative error over 2 000 normals; `cargo test --test ibl
//! irradiance_sh9_error:: -- --nocapture`): 1.7% for a gradient sky (horizon colour mixing
//! linearly with elevation to zenith blue above and to a dark ground below), against the
//! quadrature; 123% for a 3-degree sun disc of radiance 300 on that sky dimmed to a tenth,
//! against the disc's closed form (SH9 spreads the disc over the sphere, so normals facing
//! away from the sun get far too much light). SH9 is exact only for band <= 2 environments:
//! light a sun analytically and keep SH9 for the rest.
//!
//! ```
//! use brdf::V3;
//! use brdf::ibl::irradiance::{irradiance, project};
//! let sky = |d: V3<f64>| V3::splat(1.0 + 0.5 * d.z);
//! let n = V3::new(0.0, 0.6, 0.8);
//! let e = irradiance(n, sky, 32);
//! let sh = project(sky, 8);
//! // L = 1 + 0.5 z is band 1: SH9 is exact, E = pi + (pi / 3) n.z.
//! let exact = core::f64::consts::PI * (1.0 + 0.8 / 3.0);
//! assert!((e.x - exact).abs() < 1e-12 && (sh.irradiance(n).x - exact).abs() < 1e-12);
//! ```

use core::f64::consts::PI;

use crate::domain::nan_where;
use crate::frame::Frame;
use crate::real::Real;
use crate::vec3::V3;
use crate::vec3::any_nonfinite3;

/// Node `k` (descending: k = 0 is the largest) and weight of the `order`-point Gauss-Legendre
/// rule on [-1, 1], which integrates polynomials of degree <= 2 order - 1 exactly.
///
/// Newton's method on the Legendre polynomial P_order (three-term recurrence), started at
/// Tricomi's estimate cos(pi (k + 3/4) / (order + 1/2)); weight 2 / ((1 - x^2) P'(x)^2)
/// (Abramowitz and Stegun 1964, 25.4.29; Golub and Welsch 1969). Nodes come in exact pairs
/// x, -x (the upper half is computed and mirrored), so odd integrands cancel exactly.
/// Accuracy: the weights sum to 2 within a few ULP for order <= 1024.
/// Returns NaN for order = 0 or k >= order.
#[must_use]
pub fn gauss_legendre(order: u32, k: u32) -> (f64, f64) {
    if k >= order {
        return (f64::NAN, f64::NAN);
    }
    let mirrored = k >= order.div_ceil(2);
    let k = if mirrored { order - 1 - k } else { k };
    let q = f64::from(order);
    // (P_q(x), P_q'(x)) by the recurrence (j + 1) P_{j+1} = (2j + 1) x P_j - j P_{j-1}.
    let legendre = |x: f64| {
        let (mut p0, mut p1) = (1.0, x);
        for j in 1..order {
            let j = f64::from(j);
            let p2 = ((2.0 * j + 1.0) * x * p1 - j * p0) / (j + 1.0);
            p0 = p1;
            p1 = p2;
        }
        // P' from P_q and P_{q-1}; 1 - x^2 as (1 - x)(1 + x), exact near the ends.
        let one_minus_x2 = (1.0 - x) * (1.0 + x);
        (p1, q * (p0 - x * p1) / one_minus_x2)
    };
    let mut x = Real::cos(PI * (f64::from(k) + 0.75) / (q + 0.5));
    // Quadratic convergence from Tricomi's start: 4 steps reach rounding for every order
    // tried (1 to 4096); the cap only bounds the loop.
    for _ in 0..32 {
        let (p, dp) = legendre(x);
        let dx = p / dp;
        x -= dx;
        if dx.abs() <= 1e-16 * x.abs().max(1e-300) {
            break;
        }
    }
    // Odd orders have the node 0 exactly.
    if order % 2 == 1 && k == order / 2 {
        x = 0.0;
    }
    let (_, dp) = legendre(x);
    let w = 2.0 / ((1.0 - x) * (1.0 + x) * dp * dp);
    (if mirrored { -x } else { x }, w)
}

/// Irradiance E(n) = integral over the hemisphere n.l > 0 of L(l) (n.l) dl, by a product rule
/// in the frame of n: `order` Gauss-Legendre nodes in mu = n.l over [0, 1] (exact for
/// integrands polynomial in mu, the cosine included) times 2 `order` equally spaced azimuths
/// (the trapezoidal rule, spectrally accurate for periodic integrands): 2 order^2 calls of
/// `radiance`.
///
/// A constant environment L gives pi L to rounding (the mu weights integrate mu exactly), and
/// any environment polynomial of degree <= 2 order - 2 in l is exact. Smooth environments
/// converge fast; a discontinuity (a sun disc, a hard horizon) converges like the rule's node
/// spacing, about pi / (2 order) radians. `radiance` receives unit world-space directions
/// and returns RGB radiance.
///
/// `n` is normalised here. NaN in a component of n, a zero n, or order = 0 gives NaN (all
/// three channels) without calling `radiance`.
#[must_use]
pub fn irradiance(n: V3<f64>, mut radiance: impl FnMut(V3<f64>) -> V3<f64>, order: u32) -> V3<f64> {
    let len = n.length();
    // `len > 0` is false for NaN too.
    if order == 0 || len.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) || !len.is_finite()
    {
        return V3::splat(f64::NAN);
    }
    let frame = Frame::from_normal(n / len);
    let azimuths = 2 * order;
    let mut sum = V3::splat(0.0);
    for k in 0..order {
        let (x, w) = gauss_legendre(order, k);
        let mu = 0.5 * (1.0 + x);
        let sin = Real::sqrt((1.0 - mu) * (1.0 + mu));
        let mut ring = V3::splat(0.0);
        for j in 0..azimuths {
            let phi = 2.0 * PI * (f64::from(j) + 0.5) / f64::from(azimuths);
            let local = V3::new(sin * Real::cos(phi), sin * Real::sin(phi), mu);
            ring += radiance(frame.to_world(local));
        }
        // Weight of mu on [0, 1] is w / 2; the cosine factor is mu.
        sum += ring * (0.5 * w * mu);
    }
    sum * (2.0 * PI / f64::from(azimuths))
}

/// Solid angle of texel (i, j) of a cube face with `face_size` x `face_size` texels: the face
/// is the square [-1, 1]^2 at distance 1, texel (i, j) spans u in [2i / w - 1, 2(i+1) / w - 1]
/// and v likewise with j, and
/// Omega = A(u0, v0) - A(u0, v1) - A(u1, v0) + A(u1, v1), A(u, v) = atan2(u v, sqrt(u^2 + v^2 + 1)),
/// the antiderivative of the area element du dv / (1 + u^2 + v^2)^(3/2). Exact (to rounding):
/// the 6 w^2 texels sum to 4 pi. For [`Sh9::add`] with a renderer's own cube texels (the
/// face orientation is the renderer's). NaN for i or j >= face_size (face_size = 0 included).
#[must_use]
pub fn cube_texel_solid_angle(face_size: u32, i: u32, j: u32) -> f64 {
    if i >= face_size || j >= face_size {
        return f64::NAN;
    }
    let w = f64::from(face_size);
    let edge = |t: u32| 2.0 * f64::from(t) / w - 1.0;
    let (u0, u1, v0, v1) = (edge(i), edge(i + 1), edge(j), edge(j + 1));
    let a = |u: f64, v: f64| Real::atan2(u * v, Real::sqrt(u * u + v * v + 1.0));
    a(u0, v0) - a(u0, v1) - a(u1, v0) + a(u1, v1)
}

/// Y_0^0 = 1 / (2 sqrt(pi)) (Ramamoorthi and Hanrahan 2001 eq. 3 print 0.282095).
const C0: f64 = 0.282_094_791_773_878_14;
/// Band 1: sqrt(3 / (4 pi)) (printed 0.488603).
const C1: f64 = 0.488_602_511_902_919_9;
/// Band 2, xy, yz, xz: sqrt(15 / pi) / 2 (printed 1.092548).
const C2: f64 = 1.092_548_430_592_079_2;
/// Band 2, 3 z^2 - 1: sqrt(5 / pi) / 4 (printed 0.315392).
const C3: f64 = 0.315_391_565_252_520_05;
/// Band 2, x^2 - y^2: sqrt(15 / pi) / 4 (printed 0.546274).
const C4: f64 = 0.546_274_215_296_039_6;

/// The clamped-cosine lobe's SH coefficients per band, A_l (Ramamoorthi and Hanrahan 2001,
/// eq. 9): A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4. Irradiance coefficients are
/// E_lm = A_l L_lm (their eq. 7, the Funk-Hecke theorem).
pub const COSINE_BANDS: [f64; 3] = [PI, 2.0 * PI / 3.0, PI / 4.0];

/// The band of each of the 9 coefficients, in [`Sh9`]'s order.
const BAND: [usize; 9] = [0, 1, 1, 1, 2, 2, 2, 2, 2];

/// The nine real spherical harmonics of bands 0..2 at the unit direction `d` = (x, y, z), in
/// the order k = l (l + 1) + m:
///
/// | k | (l, m) | Y |
/// |---|---|---|
/// | 0 | (0, 0) | 0.282095 |
/// | 1 | (1, -1) | 0.488603 y |
/// | 2 | (1, 0) | 0.488603 z |
/// | 3 | (1, 1) | 0.488603 x |
/// | 4 | (2, -2) | 1.092548 x y |
/// | 5 | (2, -1) | 1.092548 y z |
/// | 6 | (2, 0) | 0.315392 (3 z^2 - 1) |
/// | 7 | (2, 1) | 1.092548 x z |
/// | 8 | (2, 2) | 0.546274 (x^2 - y^2) |
///
/// Ramamoorthi and Hanrahan 2001, eq. 3 (constants to 6 digits there, exact here:
/// 1 / (2 sqrt(pi)), sqrt(3 / (4 pi)), sqrt(15 / pi) / 2, sqrt(5 / pi) / 4, sqrt(15 / pi) / 4).
/// Orthonormal over the sphere. Their sign convention: no Condon-Shortley phase, so every
/// constant is positive; bases with the phase (Sloan 2008, "Stupid Spherical Harmonics
/// Tricks") negate k = 1, 3, 5, 7. z is the axis of the zonal harmonics (Y_1^0, Y_2^0): with
/// a y-up renderer, pass (x, y, z) permuted or accept that "up" is z here.
///
/// Domain: a unit d (not normalised here). A NaN or infinite component gives NaN in all nine.
#[inline]
#[must_use]
pub fn sh9_basis<T: Real>(d: V3<T>) -> [T; 9] {
    let (x, y, z) = (d.x, d.y, d.z);
    let c = |v: f64| T::splat(v);
    let y = [
        c(C0),
        c(C1) * y,
        c(C1) * z,
        c(C1) * x,
        c(C2) * x * y,
        c(C2) * y * z,
        c(C3) * (T::splat(3.0) * z * z - T::ONE),
        c(C2) * x * z,
        c(C4) * (x * x - y * y),
    ];
    let bad = any_nonfinite3(d);
    y.map(|v| nan_where(bad, v))
}

/// Nine RGB spherical-harmonic coefficients (bands 0..2) of a radiance environment, in the
/// order of [`sh9_basis`]: L_k = integral over the sphere of L(l) Y_k(l) dl.
///
/// Build one with [`project`] (a closure of direction) or by [`Sh9::add`]ing a renderer's
/// own texels; read radiance back with [`Sh9::eval`] and irradiance with [`Sh9::irradiance`]
/// (or [`Sh9::irradiance_matrix`], Ramamoorthi and Hanrahan's eq. 12 form). Generic over
/// [`Real`]: project in `f64`, then [`Sh9::splat_from`] into `f32` or lanes for shading.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sh9<T> {
    coeffs: [V3<T>; 9],
}

impl<T: Real> Default for Sh9<T> {
    fn default() -> Self {
        Self::zero()
    }
}

impl<T: Real> Sh9<T> {
    /// All nine coefficients 0 (the start of an accumulation).
    #[must_use]
    pub fn zero() -> Self {
        Self {
            coeffs: [V3::splat(T::ZERO); 9],
        }
    }

    /// The coefficients as given (order of [`sh9_basis`]; no convention change is applied).
    #[must_use]
    pub const fn from_coeffs(coeffs: [V3<T>; 9]) -> Self {
        Self { coeffs }
    }

    /// The nine RGB coefficients, in the order of [`sh9_basis`].
    #[must_use]
    pub const fn coeffs(&self) -> &[V3<T>; 9] {
        &self.coeffs
    }

    /// The `f64` coefficients rounded to T, the same in every lane.
    #[must_use]
    pub fn splat_from(sh: &Sh9<f64>) -> Self {
        Self {
            coeffs: sh
                .coeffs
                .map(|c| V3::new(T::splat(c.x), T::splat(c.y), T::splat(c.z))),
        }
    }

    /// Accumulates one sample of the projection integral: L_k += L Y_k(dir) solid_angle. With
    /// `dir` the (unit) centre of a cube texel and `solid_angle` its
    /// [`cube_texel_solid_angle`], a loop over the 6 w^2 texels projects a cube map (the
    /// midpoint rule per texel). `radiance` is RGB. NaN in any input makes every coefficient
    /// NaN from then on.
    #[inline]
    pub fn add(&mut self, dir: V3<T>, radiance: V3<T>, solid_angle: T) {
        let y = sh9_basis(dir);
        let l = radiance * solid_angle;
        for (c, yk) in self.coeffs.iter_mut().zip(y) {
            *c += l * yk;
        }
    }

    /// The band-limited radiance sum_k L_k Y_k(dir) at a unit `dir`: the environment seen
    /// through SH9 (it rings, and can go negative, near sharp features). NaN for NaN in a
    /// component of dir or in a coefficient.
    #[inline]
    #[must_use]
    pub fn eval(&self, dir: V3<T>) -> V3<T> {
        let y = sh9_basis(dir);
        let mut sum = V3::splat(T::ZERO);
        for (c, yk) in self.coeffs.iter().zip(y) {
            sum += *c * yk;
        }
        sum
    }

    /// The coefficients of the irradiance E = L convolved with the clamped cosine:
    /// E_lm = A_l L_lm ([`COSINE_BANDS`]), so that `convolved().eval(n)` = `irradiance(n)`
    /// (store these to shade with a plain SH evaluation; divide by pi for Lambert's
    /// outgoing radiance per unit albedo).
    #[must_use]
    pub fn cosine_convolved(&self) -> Self {
        let mut out = *self;
        for (c, band) in out.coeffs.iter_mut().zip(BAND) {
            *c *= T::splat(COSINE_BANDS[band]);
        }
        out
    }

    /// Irradiance at the unit normal `n` = (x, y, z) from the projected environment,
    /// E(n) = sum_lm A_l L_lm Y_lm(n), evaluated as Ramamoorthi and Hanrahan 2001's eq. 13:
    ///
    /// ```text
    /// E = c1 L22 (x^2 - y^2) + c3 L20 z^2 + c4 L00 - c5 L20
    ///   + 2 c1 (L2-2 xy + L21 xz + L2-1 yz) + 2 c2 (L11 x + L1-1 y + L10 z)
    /// c1 = A2 sqrt(15 / pi) / 4    = 0.429043     c2 = A1 sqrt(3 / (4 pi)) / 2 = 0.511664
    /// c3 = 3 A2 sqrt(5 / pi) / 4   = 0.743125     c4 = A0 / (2 sqrt(pi))        = 0.886227
    /// c5 = A2 sqrt(5 / pi) / 4     = 0.247708
    /// ```
    ///
    /// (the constants exact here, to 6 digits in the paper).
    ///
    /// Exact for environments of band <= 2; otherwise the error of dropping bands >= 3, whose
    /// cosine-lobe coefficients are small (A_3 = 0, A_4 = pi / 24): 1.7% for a gradient sky,
    /// 123% for a sun disc (module docs). Not clamped: SH9 of a sharp light can give
    /// E < 0 on the side facing away from it (clamp with max(0) if a shader needs it). A
    /// constant environment L gives E = pi L to rounding. Domain: unit n (not normalised
    /// here); NaN in a component of n gives NaN in all three channels.
    #[inline]
    #[must_use]
    pub fn irradiance(&self, n: V3<T>) -> V3<T> {
        let [l00, l1m1, l10, l11, l2m2, l2m1, l20, l21, l22] = self.coeffs;
        let (x, y, z) = (n.x, n.y, n.z);
        let k = irradiance_constants::<T>();
        let linear = (l11 * x + l1m1 * y + l10 * z) * (T::TWO * k[1]);
        let cross = (l2m2 * (x * y) + l21 * (x * z) + l2m1 * (y * z)) * (T::TWO * k[0]);
        let e = l22 * (k[0] * (x * x - y * y)) + l20 * (k[2] * z * z) + l00 * k[3] - l20 * k[4]
            + cross
            + linear;
        let bad = any_nonfinite3(n);
        V3::new(
            nan_where(bad, e.x),
            nan_where(bad, e.y),
            nan_where(bad, e.z),
        )
    }

    /// The symmetric 4 x 4 matrix M of Ramamoorthi and Hanrahan 2001, eq. 12, per RGB channel,
    /// with E(n) = (x, y, z, 1) M (x, y, z, 1)^T for a unit n (the form a shader evaluates
    /// with three matrix-vector products):
    ///
    /// ```text
    /// | c1 L22   c1 L2-2  c1 L21   c2 L11          |
    /// | c1 L2-2  -c1 L22  c1 L2-1  c2 L1-1         |
    /// | c1 L21   c1 L2-1  c3 L20   c2 L10          |
    /// | c2 L11   c2 L1-1  c2 L10   c4 L00 - c5 L20 |
    /// ```
    ///
    /// c1..c5 as in [`Sh9::irradiance`]; the same polynomial, so the same values to rounding.
    #[must_use]
    pub fn irradiance_matrix(&self) -> [[V3<T>; 4]; 4] {
        let [l00, l1m1, l10, l11, l2m2, l2m1, l20, l21, l22] = self.coeffs;
        let k = irradiance_constants::<T>();
        let (c1, c2, c3, c4, c5) = (k[0], k[1], k[2], k[3], k[4]);
        [
            [l22 * c1, l2m2 * c1, l21 * c1, l11 * c2],
            [l2m2 * c1, -(l22 * c1), l2m1 * c1, l1m1 * c2],
            [l21 * c1, l2m1 * c1, l20 * c3, l10 * c2],
            [l11 * c2, l1m1 * c2, l10 * c2, l00 * c4 - l20 * c5],
        ]
    }
}

/// Ramamoorthi and Hanrahan's c1..c5 from the basis constants and the A_l.
#[inline]
fn irradiance_constants<T: Real>() -> [T; 5] {
    let [a0, a1, a2] = COSINE_BANDS;
    [
        T::splat(a2 * C4),
        T::splat(a1 * C1 / 2.0),
        T::splat(3.0 * a2 * C3),
        T::splat(a0 * C0),
        T::splat(a2 * C3),
    ]
}

/// Projects an environment onto [`Sh9`]: L_k = integral over the sphere of L(l) Y_k(l) dl by a
/// product rule, `order` Gauss-Legendre nodes in z = cos(theta) over [-1, 1] times 2 `order`
/// equally spaced azimuths (2 order^2 calls of `radiance`, with unit world-space
/// directions). Exact (to rounding) for environments polynomial of degree <= 2 order - 3
/// in l, so band <= 2 environments need only order >= 3; order 64 to 256 suits a measured
/// sky; a discontinuity converges like the node spacing pi / order. Deterministic.
/// order = 0 gives NaN coefficients.
#[must_use]
pub fn project(mut radiance: impl FnMut(V3<f64>) -> V3<f64>, order: u32) -> Sh9<f64> {
    if order == 0 {
        return Sh9::from_coeffs([V3::splat(f64::NAN); 9]);
    }
    let azimuths = 2 * order;
    let d_phi = 2.0 * PI / f64::from(azimuths);
    let mut sh = Sh9::zero();
    for k in 0..order {
        let (z, w) = gauss_legendre(order, k);
        let sin = Real::sqrt((1.0 - z) * (1.0 + z));
        for j in 0..azimuths {
            let phi = d_phi * (f64::from(j) + 0.5);
            let dir = V3::new(sin * Real::cos(phi), sin * Real::sin(phi), z);
            sh.add(dir, radiance(dir), w * d_phi);
        }
    }
    sh
}
