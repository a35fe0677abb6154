//! The geometry of one shading point, built once and handed to every full BRDF: the four
//! cosines a dot-product BRDF reads ([`Cosines`]) and the world-to-local frame a direction
//! BRDF and a sampler read ([`ShadingPoint`]).
//!
//! # One argument order, and a type so it cannot be swapped
//! Every kernel of the crate that takes cosines of a shading point takes them in the order
//! **n.v, n.l, n.h, v.h** (view before light, normal cosines before the half-vector one), and
//! every full BRDF (the Cook-Torrance assemblies, the metallic-roughness material) takes them
//! as one [`Cosines`] value instead of four loose floats. Its fields are public and named, so a
//! struct literal states each cosine by name, and the constructors compute them from world-space
//! or local-frame directions:
//!
//! ```
//! use brdf::glam::Vec3;
//! use brdf::shading::{Cosines, ShadingPoint};
//! use brdf::V3;
//!
//! // From world-space unit vectors: n the normal, v towards the viewer, l towards the light.
//! let (n, v, l) = (Vec3::Z, Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.6, 0.0, 0.8));
//! let c = Cosines::from_world(V3::from(n), V3::from(v), V3::from(l));
//! assert!((c.n_dot_v - 0.8).abs() < 1e-6 && (c.n_dot_l - 0.8).abs() < 1e-6);
//!
//! // The same from a frame built once per shading point (one per pixel, any number of lights).
//! let sp = ShadingPoint::new(V3::from(n), V3::from(v));
//! let c2 = sp.cosines(V3::from(l));
//! assert!((c2.n_dot_h - c.n_dot_h).abs() < 1e-6 && (c2.v_dot_h - c.v_dot_h).abs() < 1e-6);
//!
//! // A shader's dot products, each named: a swap is visible at the call site.
//! let c3 = Cosines { n_dot_v: 0.8_f32, n_dot_l: 0.8, n_dot_h: 0.9487, v_dot_h: 0.9487 };
//! # let _ = c3;
//! ```
//!
//! The plain-float kernels below the full BRDFs (an NDF `d(n_dot_h, alpha)`, a visibility
//! `v_correlated(n_dot_v, n_dot_l, alpha)`, a Fresnel term of v.h) keep loose floats, in the
//! same order: they are what a shader calls, and the crate's WGSL twins and reference CLI map
//! onto them one to one.

use crate::domain::{finite_or_nan, nan_where};
use crate::frame::Frame;
use crate::real::Real;
use crate::vec3::{V3, any_nonfinite3};

/// The four cosines of a shading point: n.v, n.l, n.h and v.h, with v the unit direction
/// towards the viewer, l the unit direction towards the light, n the unit normal and
/// h = normalize(v + l) the half vector.
///
/// Every full BRDF of the crate takes this instead of four floats, so the cosines cannot be
/// passed in the wrong order. Build it with a struct literal (each field named), from
/// world-space vectors ([`Cosines::from_world`]), from local-frame directions
/// ([`Cosines::from_local`]) or from a [`ShadingPoint`] ([`ShadingPoint::cosines`]).
///
/// Values are used as given: the kernels clamp each cosine to [-1, 1] (and read a negative n.v
/// or n.l as "below the horizon"). The constructors never produce NaN from finite directions:
/// where v = -l exactly (h undefined) n.h = 1 and v.h = 0, which only happens with one of the
/// two below the horizon, where every BRDF is 0 anyway.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cosines<T> {
    /// n.v: the cosine of the view direction with the normal.
    pub n_dot_v: T,
    /// n.l: the cosine of the light direction with the normal.
    pub n_dot_l: T,
    /// n.h: the cosine of the half vector with the normal (the NDF's argument).
    pub n_dot_h: T,
    /// v.h = l.h: the cosine of the view (or light) direction with the half vector (the Fresnel
    /// term's argument).
    pub v_dot_h: T,
}

impl<T: Real> Cosines<T> {
    /// The cosines of world-space unit vectors `n` (normal), `v` (towards the viewer) and `l`
    /// (towards the light): n.v and n.l are dot products, n.h and v.h come from s = v + l
    /// without normalizing h (v.h = |s| / 2, n.h = n.s / |s|, as
    /// `cook_torrance::half_cosines`), symmetric in v and l bit for bit.
    ///
    /// Domain: unit vectors (the results carry their length errors). v = -l gives n.h = 1 and
    /// v.h = 0; a NaN or infinite component gives NaN in every cosine that reads its vector
    /// (the crate's rules 1 and 5).
    #[inline]
    #[must_use]
    pub fn from_world(n: V3<T>, v: V3<T>, l: V3<T>) -> Self {
        let (n_dot_h, v_dot_h) = half_cosines_about(n, v, l);
        // Rule 5: an infinite component is no direction; NaN wherever a NaN would reach.
        let (bad_n, bad_v, bad_l) = (any_nonfinite3(n), any_nonfinite3(v), any_nonfinite3(l));
        Self {
            n_dot_v: nan_where(bad_n | bad_v, n.dot(v)),
            n_dot_l: nan_where(bad_n | bad_l, n.dot(l)),
            n_dot_h: nan_where(bad_n | bad_v | bad_l, n_dot_h),
            v_dot_h: nan_where(bad_v | bad_l, v_dot_h),
        }
    }

    /// The cosines of local-frame unit directions (the normal is +z): `wo` towards the viewer,
    /// `wi` towards the light. For finite directions equal to `from_world(V3::unit_z(), wo, wi)`
    /// bit for bit. n.v is wo.z and n.l is wi.z; a NaN or infinite component of either
    /// direction makes n.h and v.h NaN, and one in wo.z (wi.z) makes n.v (n.l) NaN.
    #[inline]
    #[must_use]
    pub fn from_local(wo: V3<T>, wi: V3<T>) -> Self {
        let s = wo + wi;
        let len = s.length();
        let n_dot_h = T::select(len.simd_eq(T::ZERO), T::ONE, s.z / len);
        let bad = any_nonfinite3(wo) | any_nonfinite3(wi);
        Self {
            n_dot_v: finite_or_nan(wo.z),
            n_dot_l: finite_or_nan(wi.z),
            n_dot_h: nan_where(bad, n_dot_h),
            v_dot_h: nan_where(bad, (T::HALF * len).min(T::ONE)),
        }
    }
}

/// n.h and v.h from s = v + l: v.h = |s| / 2 (clamped to 1), n.h = n.s / |s|; s = 0 gives
/// (1, 0). A NaN or infinite component gives NaN in both.
#[inline]
fn half_cosines_about<T: Real>(n: V3<T>, v: V3<T>, l: V3<T>) -> (T, T) {
    let s = v + l;
    let len = s.length();
    let n_dot_h = T::select(len.simd_eq(T::ZERO), T::ONE, n.dot(s) / len);
    // s = 0 selects 1 without reading n: a NaN normal must still give NaN.
    let n_dot_h = crate::domain::nan_where(crate::vec3::any_nonfinite3(n), n_dot_h);
    (n_dot_h, (T::HALF * len).min(T::ONE))
}

/// A shading point: the local frame of the normal and the view direction in it, built once
/// per pixel (or per path vertex) so that any number of lights, BRDF evaluations and samples
/// reuse it.
///
/// `n` is the unit shading normal and `v` the unit direction towards the viewer, both in world
/// space. [`ShadingPoint::local`] turns a world-space light direction into the local frame every
/// direction kernel of the crate takes (`brdf.eval(sp.wo(), sp.local(l))`),
/// [`ShadingPoint::world`] turns a sampled local direction back, and [`ShadingPoint::cosines`]
/// gives the dot products a [`Cosines`] BRDF takes. The frame is Duff et al.'s
/// ([`Frame::from_normal`]); for an anisotropic material build the frame from its own tangent
/// with [`ShadingPoint::from_frame`].
///
/// ```
/// use brdf::V3;
/// use brdf::shading::ShadingPoint;
///
/// let n = V3::new(0.0, 0.6, 0.8);
/// let v = V3::new(0.0, 0.0, 1.0);
/// let sp = ShadingPoint::new(n, v);
/// assert!((sp.wo().z - 0.8_f64).abs() < 1e-15); // n.v
/// let l = V3::new(0.0, 0.96, 0.28); // v mirrored about n
/// let wi = sp.local(l);
/// assert!((wi.z - 0.8).abs() < 1e-15);
/// assert!((sp.world(wi) - l).length() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadingPoint<T> {
    frame: Frame<T>,
    wo: V3<T>,
}

impl<T: Real> ShadingPoint<T> {
    /// The shading point of unit normal `n` and unit view direction `v` (world space, `v`
    /// pointing away from the surface towards the viewer). A NaN or infinite component of `n` gives an
    /// all-NaN frame; a NaN in `v` a NaN `wo`.
    #[inline]
    #[must_use]
    pub fn new(n: V3<T>, v: V3<T>) -> Self {
        Self::from_frame(Frame::from_normal(n), v)
    }

    /// The shading point of a given orthonormal frame (an anisotropic material's tangent,
    /// bitangent and normal) and unit view direction `v` in world space.
    #[inline]
    #[must_use]
    pub fn from_frame(frame: Frame<T>, v: V3<T>) -> Self {
        Self {
            frame,
            wo: frame.to_local(v),
        }
    }

    /// The frame (tangent, bitangent, normal).
    #[inline]
    #[must_use]
    pub fn frame(&self) -> &Frame<T> {
        &self.frame
    }

    /// The view direction in the local frame (its z is n.v).
    #[inline]
    #[must_use]
    pub fn wo(&self) -> V3<T> {
        self.wo
    }

    /// A world-space direction in the local frame: `(l.t, l.b, l.n)`.
    #[inline]
    #[must_use]
    pub fn local(&self, l: V3<T>) -> V3<T> {
        self.frame.to_local(l)
    }

    /// A local-frame direction (a sampled one) back in world space.
    #[inline]
    #[must_use]
    pub fn world(&self, w: V3<T>) -> V3<T> {
        self.frame.to_world(w)
    }

    /// The [`Cosines`] of the world-space unit light direction `l` at this point: equal to
    /// `Cosines::from_local(self.wo(), self.local(l))`.
    #[inline]
    #[must_use]
    pub fn cosines(&self, l: V3<T>) -> Cosines<T> {
        Cosines::from_local(self.wo, self.local(l))
    }
}
