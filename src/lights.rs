//! Punctual lights: the radiance they reflect off a BRDF, their distance attenuation and the
//! cone falloff of a spot light.
//!
//! # Two conventions for a light's strength
//! A punctual light seen from a surface point is a direction `l` and a perpendicular irradiance
//! E_perp (W/m^2 on a surface facing the light). The reflected radiance is the reflectance
//! equation with the light as a delta:
//!
//! L_o = f(v, l) E_perp max(0, n.l)                                  ([`radiance`])
//!
//! Real-time renderers often quote the light instead by its *colour* c_light, the radiance of a
//! white Lambertian surface (f = 1/pi) lit head-on: c_light = E_perp / pi. Then
//!
//! L_o = pi f(v, l) c_light max(0, n.l)                              ([`radiance_pi`])
//!
//! so that a white diffuse surface facing a light of colour 1 shows exactly 1 (Hoffman 2013,
//! "Background: Physics and Math of Shading", SIGGRAPH course "Physically Based Shading in
//! Theory and Practice"; Akenine-Moller, Haines, Hoffman, "Real-Time Rendering", 3rd ed.,
//! section 7.5). The two agree when c_light = E_perp / pi; mixing them up makes every light pi
//! times too bright or too dim.
//!
//! For a point light of intensity I (W/sr) at distance d, E_perp = I / d^2 (the inverse square
//! law); engines replace 1/d^2 by falloffs that reach zero at a finite radius
//! ([`windowed`], [`windowed_inverse_square`]) or by the fixed-function polynomial
//! ([`polynomial`]). A spot light multiplies by its cone falloff ([`spot_cone`]).
//!
//! # Bad input
//! Kernels validate nothing and never panic. A NaN input gives NaN. A parameter outside its
//! documented domain gives NaN. The documented edges (distance 0, radius 0) give the values
//! stated on each function, never NaN. Every domain ends at the largest finite float (crate
//! docs, "Bad input", rule 5): an infinite distance, radius, BRDF value, irradiance or light
//! colour gives NaN (an infinite radiance is an overflow upstream, which a reference must
//! surface); an infinite cosine counts as +-1. A light with no window is one of radius
//! `T::MAX`. [`Attenuation`] and [`SpotCone`] validate their parameters once, at construction.

use crate::domain::{nan_unless, unit_if_inf};
use crate::error::{ParamError, require};
use crate::real::Real;
use crate::vec3::V3;

/// NaN where `x` is NaN, else 0: carries an input's NaN into a branch whose value is a
/// constant, so a `select` on a comparison cannot turn NaN into a plausible number.
#[inline]
fn nan_of<T: Real>(x: T) -> T {
    T::select(x.is_nan(), x, T::ZERO)
}

/// Reflected radiance from a punctual light in radiometric units:
/// L_o = f E_perp max(0, n.l), with `f` the BRDF value for (v, l) and `e_perp` the irradiance on
/// a surface facing the light (for a point light, I / d^2 times an attenuation window).
///
/// Domain: f >= 0 and e_perp >= 0, both finite; n.l in [-1, 1]. n.l <= 0 (light behind the
/// surface) gives 0; NaN in any input, or an input outside its domain (f or e_perp infinite
/// included), gives NaN; n.l = +-inf counts as +-1 (rules 3 and 5). A product
/// too large for the float type is capped at the largest finite value instead of +inf.
///
/// Source: the reflectance equation with a delta light (Pharr, Jakob, Humphreys, "Physically
/// Based Rendering", 4th ed., section 12.1).
#[inline]
#[must_use]
pub fn radiance<T: Real>(f: T, e_perp: T, n_dot_l: T) -> T {
    reflected(f, e_perp, n_dot_l, T::ONE)
}

/// f e max(0, n.l) k for a constant k > 0, capped at `T::MAX`, with the domain checks of
/// [`radiance`]. k multiplies last, so a finite f e n.l k is never lost to an intermediate
/// overflow (f k first would overflow for f near `T::MAX`, and its cap would change the
/// product).
#[inline]
fn reflected<T: Real>(f: T, e_perp: T, n_dot_l: T, k: T) -> T {
    // An infinite cosine counts as +-1 before the range check below rejects it.
    let n_dot_l = unit_if_inf(n_dot_l);
    let finite_non_negative = |x: T| x.simd_ge(T::ZERO) & x.is_finite();
    let ok = finite_non_negative(f)
        & finite_non_negative(e_perp)
        & n_dot_l.simd_ge(-T::ONE)
        & n_dot_l.simd_le(T::ONE);
    // e n.l <= e cannot overflow, so f (e n.l) overflows only where the true product does.
    let lit = (f * (e_perp * n_dot_l) * k).min(T::MAX);
    nan_unless(
        ok,
        T::select(n_dot_l.simd_gt(T::ZERO), lit, nan_of(n_dot_l)),
    )
}

/// Reflected radiance in the real-time convention: L_o = pi f c_light max(0, n.l), where
/// `c_light` is the radiance a white Lambertian surface facing the light would show
/// (c_light = E_perp / pi). A white Lambert (f = 1/pi) lit head-on returns exactly `c_light`.
///
/// Domain and edges as [`radiance`]. Source: Hoffman 2013, "Background: Physics and Math of
/// Shading" (SIGGRAPH course); Akenine-Moller, Haines, Hoffman, "Real-Time Rendering", 3rd ed.,
/// eq. 7.26 and section 7.5.
#[inline]
#[must_use]
pub fn radiance_pi<T: Real>(f: T, c_light: T, n_dot_l: T) -> T {
    reflected(f, c_light, n_dot_l, T::PI)
}

/// [`radiance_pi`] per colour channel: an RGB BRDF value times an RGB light colour.
#[inline]
#[must_use]
pub fn radiance_pi_rgb<T: Real>(f: V3<T>, c_light: V3<T>, n_dot_l: T) -> V3<T> {
    V3::new(
        radiance_pi(f.x, c_light.x, n_dot_l),
        radiance_pi(f.y, c_light.y, n_dot_l),
        radiance_pi(f.z, c_light.z, n_dot_l),
    )
}

/// Irradiance on the surface from a punctual light: E = E_perp max(0, n.l) (Lambert's cosine
/// law). Domain and edges as [`radiance`]: 0 for n.l <= 0, NaN for NaN.
#[inline]
#[must_use]
pub fn irradiance<T: Real>(e_perp: T, n_dot_l: T) -> T {
    radiance(T::ONE, e_perp, n_dot_l)
}

/// The inverse square law with a minimum distance: 1 / max(d, d_min)^2.
///
/// A punctual light has no size, so 1/d^2 grows without bound as d -> 0; clamping the distance
/// at the size of a real bulb (Lagarde and de Rousiers use 1 cm) keeps it finite.
///
/// Domain: d >= 0 finite, d_min > 0 finite (NaN otherwise, d = +inf included: an infinite
/// distance is an overflow upstream). Edges: d = 0 gives 1 / d_min^2; d = `T::MAX` gives 0.
/// Where d_min^2 underflows (d_min below about 1e-19 in f32)
/// the result is capped at the largest finite value instead of +inf.
///
/// Source: Lagarde and de Rousiers 2014, "Moving Frostbite to Physically Based Rendering 3.0",
/// SIGGRAPH course, section 4.3.3 (listing 24).
#[inline]
#[must_use]
pub fn inverse_square<T: Real>(distance: T, min_distance: T) -> T {
    let ok = distance.simd_ge(T::ZERO)
        & distance.is_finite()
        & min_distance.simd_gt(T::ZERO)
        & min_distance.is_finite();
    let d = distance.max(min_distance);
    nan_unless(ok, (d * d).recip().min(T::MAX))
}

/// The smooth window saturate(1 - (d/r)^4)^2 that takes a falloff to exactly 0 at the light's
/// radius r with zero slope. d >= r gives 0; r = 0 gives 0 (a light that reaches nothing);
/// r = `T::MAX` gives 1 for every d below about 1e-2 `T::MAX`. NaN for an infinite or
/// NaN d or r (rules 1 and 5).
#[inline]
fn window<T: Real>(distance: T, radius: T) -> T {
    let q = distance / radius;
    let q2 = q * q;
    let w = (T::ONE - q2 * q2).saturate();
    // d / r is NaN for d = r = 0: at r = 0 nothing is lit.
    let empty = radius.simd_eq(T::ZERO);
    nan_unless(
        distance.is_finite() & radius.is_finite(),
        T::select(empty, T::ZERO, w * w),
    )
}

/// Unreal Engine 4's windowed falloff: saturate(1 - (d/r)^4)^2 / (d^2 + 1).
///
/// The window brings the light to exactly 0, with zero slope, at its radius r, so lights can be
/// culled; the "+1" keeps the value finite at d = 0 (it acts as a 1-unit bulb, so d and r are
/// in the units for which that is right: metres in Karis's notes).
///
/// Domain: d >= 0 and r >= 0, both finite (NaN for negative, infinite or NaN input). Edges:
/// d = 0 gives 1 (for r > 0); d >= r gives 0; r = 0 gives 0; r = `T::MAX` gives
/// 1 / (d^2 + 1) (no window) for every d up to about 1e-2 `T::MAX`.
///
/// Source: Karis 2013, "Real Shading in Unreal Engine 4", SIGGRAPH course "Physically Based
/// Shading in Theory and Practice", eq. 9.
#[inline]
#[must_use]
pub fn windowed<T: Real>(distance: T, radius: T) -> T {
    let ok = distance.simd_ge(T::ZERO) & radius.simd_ge(T::ZERO);
    let falloff = window(distance, radius) / distance.mul_add(distance, T::ONE);
    // (d^2 + 1) is +inf for huge finite d, and w / inf = 0.
    nan_unless(ok, falloff)
}

/// Frostbite's windowed inverse square: saturate(1 - (d/r)^4)^2 / max(d, d_min)^2, the
/// physical 1/d^2 law with the same smooth window as [`windowed`].
///
/// Domain: d >= 0, r >= 0, d_min > 0, all finite; NaN otherwise. Edges: d = 0 gives
/// 1 / d_min^2 (for r > 0); d >= r or r = 0 gives 0; r = `T::MAX` gives [`inverse_square`]
/// for every d up to about 1e-2 `T::MAX`.
///
/// Source: Lagarde and de Rousiers 2014, "Moving Frostbite to Physically Based Rendering 3.0",
/// SIGGRAPH course, section 4.3.3 (listing 24, `smoothDistanceAtt`).
#[inline]
#[must_use]
pub fn windowed_inverse_square<T: Real>(distance: T, radius: T, min_distance: T) -> T {
    let ok = radius.simd_ge(T::ZERO);
    nan_unless(
        ok,
        window(distance, radius) * inverse_square(distance, min_distance),
    )
}

/// The constant-linear-quadratic attenuation of fixed-function pipelines:
/// 1 / (k_c + k_l d + k_q d^2).
///
/// Domain: k_c > 0, k_l >= 0, k_q >= 0, d >= 0, all finite; NaN otherwise (d = +inf
/// included). Edges: d = 0 gives 1 / k_c; a term with a zero coefficient contributes 0 at
/// every d (k_l = k_q = 0 gives 1 / k_c), not 0 x an overflowed d^2. k_c = 1, k_l = 0, k_q = 1 is the
/// inverse square law softened at d < 1. A general numerator c_0 / (...) is a scale of this.
/// Where 1 / k_c overflows (a subnormal k_c) the result is capped at the largest finite value.
///
/// Source: the OpenGL 1.x fixed-function lighting equation (Segal and Akeley, "The OpenGL
/// Graphics System: A Specification", version 1.5, section 2.14.1), also Direct3D 9's
/// attenuation.
#[inline]
#[must_use]
pub fn polynomial<T: Real>(distance: T, constant: T, linear: T, quadratic: T) -> T {
    let ok = constant.simd_gt(T::ZERO)
        & constant.is_finite()
        & linear.simd_ge(T::ZERO)
        & linear.is_finite()
        & quadratic.simd_ge(T::ZERO)
        & quadratic.is_finite()
        & distance.simd_ge(T::ZERO)
        & distance.is_finite();
    // A zero coefficient drops its term even where d^2 overflows.
    let lin = T::select(linear.simd_gt(T::ZERO), linear * distance, T::ZERO);
    let quad = T::select(
        quadratic.simd_gt(T::ZERO),
        quadratic * distance * distance,
        T::ZERO,
    );
    // 1 / k_c overflows for a subnormal k_c: capped at the largest finite value.
    nan_unless(ok, (constant + lin + quad).recip().min(T::MAX))
}

/// The cone falloff of a spot light: t^2 with t = saturate((cos a - cos_outer) / (cos_inner -
/// cos_outer)), where a is the angle between the spot's axis and the direction from the light
/// to the point. 1 inside the inner cone, 0 outside the outer one, a smooth ramp between.
///
/// Domain: all three cosines in [-1, 1] with cos_outer <= cos_inner (NaN otherwise; cos a =
/// +-inf counts as +-1, rules 3 and 5, while the cone's two cosines are parameters). Edge:
/// cos_inner = cos_outer is a hard-edged cone: 1 for cos a >= cos_outer, 0 below (instead of
/// 0 / 0).
///
/// Source: Lagarde and de Rousiers 2014, "Moving Frostbite to Physically Based Rendering 3.0",
/// SIGGRAPH course (`getAngleAtt`: the linear ramp in cos a, squared for a smoother edge);
/// Google Filament, "Physically Based Rendering in Filament" (spot light attenuation).
#[inline]
#[must_use]
pub fn spot_cone<T: Real>(cos_angle: T, cos_outer: T, cos_inner: T) -> T {
    let cos_angle = unit_if_inf(cos_angle);
    let in_range = |c: T| c.simd_ge(-T::ONE) & c.simd_le(T::ONE);
    let ok = in_range(cos_angle)
        & in_range(cos_outer)
        & in_range(cos_inner)
        & cos_outer.simd_le(cos_inner);
    let width = cos_inner - cos_outer;
    let hard = width.simd_eq(T::ZERO);
    let t = ((cos_angle - cos_outer) / T::select(hard, T::ONE, width)).saturate();
    let step = T::select(cos_angle.simd_ge(cos_outer), T::ONE, nan_of(cos_angle));
    nan_unless(ok, T::select(hard, step, t * t))
}

/// Which distance falloff an [`Attenuation`] applies.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind<T> {
    InverseSquare {
        min_distance: T,
    },
    Windowed {
        radius: T,
    },
    WindowedInverseSquare {
        radius: T,
        min_distance: T,
    },
    Polynomial {
        constant: T,
        linear: T,
        quadratic: T,
    },
}

/// A validated distance falloff: the kernels above with parameters checked once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attenuation<T> {
    kind: Kind<T>,
}

/// True where `x` is finite and >= 0.
fn finite_non_negative<T: Real>(x: T) -> T::Mask {
    x.simd_ge(T::ZERO) & x.is_finite()
}

/// `Ok` when `x` is finite and > 0 in every lane.
fn require_positive<T: Real>(x: T, param: &'static str) -> Result<(), ParamError> {
    require::<T>(x.simd_gt(T::ZERO) & x.is_finite(), param, "finite and > 0")
}

impl<T: Real> Attenuation<T> {
    /// [`inverse_square`] with `min_distance` finite and > 0.
    pub fn inverse_square(min_distance: T) -> Result<Self, ParamError> {
        require_positive(min_distance, "min_distance")?;
        Ok(Self {
            kind: Kind::InverseSquare { min_distance },
        })
    }

    /// [`windowed`] with `radius` finite and >= 0 (`T::MAX`: no window).
    pub fn windowed(radius: T) -> Result<Self, ParamError> {
        require::<T>(finite_non_negative(radius), "radius", "finite and >= 0")?;
        Ok(Self {
            kind: Kind::Windowed { radius },
        })
    }

    /// [`windowed_inverse_square`] with `radius` finite and >= 0 (`T::MAX`: no window) and
    /// `min_distance` finite and > 0.
    pub fn windowed_inverse_square(radius: T, min_distance: T) -> Result<Self, ParamError> {
        require::<T>(finite_non_negative(radius), "radius", "finite and >= 0")?;
        require_positive(min_distance, "min_distance")?;
        Ok(Self {
            kind: Kind::WindowedInverseSquare {
                radius,
                min_distance,
            },
        })
    }

    /// [`polynomial`] with `constant` finite and > 0, `linear` and `quadratic` finite and
    /// >= 0.
    pub fn polynomial(constant: T, linear: T, quadratic: T) -> Result<Self, ParamError> {
        require_positive(constant, "constant")?;
        let non_negative = |x: T| x.simd_ge(T::ZERO) & x.is_finite();
        require::<T>(non_negative(linear), "linear", "finite and >= 0")?;
        require::<T>(non_negative(quadratic), "quadratic", "finite and >= 0")?;
        Ok(Self {
            kind: Kind::Polynomial {
                constant,
                linear,
                quadratic,
            },
        })
    }

    /// The falloff at a finite `distance` >= 0; NaN for a negative, infinite or NaN distance.
    #[inline]
    #[must_use]
    pub fn eval(&self, distance: T) -> T {
        match self.kind {
            Kind::InverseSquare { min_distance } => inverse_square(distance, min_distance),
            Kind::Windowed { radius } => windowed(distance, radius),
            Kind::WindowedInverseSquare {
                radius,
                min_distance,
            } => windowed_inverse_square(distance, radius, min_distance),
            Kind::Polynomial {
                constant,
                linear,
                quadratic,
            } => polynomial(distance, constant, linear, quadratic),
        }
    }
}

/// A validated spot cone: [`spot_cone`] with angles given in radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotCone<T> {
    cos_outer: T,
    cos_inner: T,
}

impl<T: Real> SpotCone<T> {
    /// A cone with full intensity up to `inner` radians from the axis, falling to 0 at `outer`.
    /// Requires 0 <= inner <= outer <= pi (every lane), else [`ParamError`].
    pub fn new(inner: T, outer: T) -> Result<Self, ParamError> {
        require::<T>(
            outer.simd_ge(T::ZERO) & outer.simd_le(T::PI),
            "outer",
            "in [0, pi]",
        )?;
        require::<T>(
            inner.simd_ge(T::ZERO) & inner.simd_le(outer),
            "inner",
            "in [0, outer]",
        )?;
        // cos is decreasing on [0, pi], but rounding could still order two nearly equal
        // angles the wrong way; the min keeps cos_outer <= cos_inner.
        let cos_inner = inner.cos();
        Ok(Self {
            cos_outer: outer.cos().min(cos_inner),
            cos_inner,
        })
    }

    /// The cosine of the outer angle.
    #[inline]
    #[must_use]
    pub fn cos_outer(&self) -> T {
        self.cos_outer
    }

    /// The cosine of the inner angle.
    #[inline]
    #[must_use]
    pub fn cos_inner(&self) -> T {
        self.cos_inner
    }

    /// The falloff for a point at angle a from the axis, given cos a ([`spot_cone`]).
    #[inline]
    #[must_use]
    pub fn eval(&self, cos_angle: T) -> T {
        spot_cone(cos_angle, self.cos_outer, self.cos_inner)
    }
}
