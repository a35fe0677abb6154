//! # brdf
//!
//! BRDF math for renderers, physics checks and shader reference: pure functions, one generic
//! source for `f32`, `f64` and SIMD lanes (`f32x8`, `f64x4`), `#![no_std]`, every formula
//! cited and every property (normalization, reciprocity, energy) checked by numerical
//! integration in the test suite.
//!
//! ## Tour
//! ```
//! # #[cfg(all(feature = "ggx", feature = "fresnel"))] {
//! use brdf::glam::Vec3;
//! use brdf::wide::f32x8;
//! use brdf::{Real, fresnel, ggx, microfacet::alpha_from_perceptual};
//!
//! // A GGX specular lobe D V F, written once for every float type (Filament's shader form).
//! fn specular<T: Real>(n_dot_h: T, n_dot_v: T, n_dot_l: T, v_dot_h: T, roughness: T) -> T {
//!     let alpha = alpha_from_perceptual(roughness); // glTF's roughness is perceptual: alpha = r^2
//!     let f = fresnel::schlick(T::splat(0.04), v_dot_h);
//!     ggx::d(n_dot_h, alpha) * ggx::v_correlated(n_dot_v, n_dot_l, alpha) * f
//! }
//! // World-space glam vectors become the dot products the kernels take...
//! let (n, v, l) = (Vec3::Z, Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.6, 0.0, 0.8));
//! let h = (v + l).normalize();
//! let one = specular(n.dot(h), n.dot(v), n.dot(l), v.dot(h), 0.5_f32);
//! // ...and eight pixels at a time run the same source on lanes, bit for bit.
//! let x8 = |x: f32| f32x8::splat(x);
//! let eight = specular(x8(n.dot(h)), x8(n.dot(v)), x8(n.dot(l)), x8(v.dot(h)), x8(0.5));
//! assert_eq!(eight.to_array()[5], one);
//! // Bad input surfaces instead of hiding: a NaN in gives a NaN out.
//! assert!(specular(f32::NAN, 1.0, 1.0, 1.0, 0.5).is_nan());
//! # }
//! ```
//! All features are on by default (`default-features = false` keeps only what you list). For a
//! whole glTF 2.0 material rather than its terms, `material::MetallicRoughness` evaluates and
//! samples base colour, metallic and roughness from local-frame directions, or from world space
//! through a [`ShadingPoint`] built once per pixel (the repository's `examples/sphere.rs` shades
//! a sphere with it in about 60 lines). Every full BRDF takes a shading point's cosines as one
//! [`Cosines`] value, in the crate's one order n.v, n.l, n.h, v.h ([`shading`]). Lanes equal scalars bit for
//! bit on a given target wherever a kernel uses only arithmetic, `sqrt` and `mul_add`; where it
//! calls `exp`, `ln`, `sin`, `cos`, `atan`, `acos` or `asin`, the lanes use polynomial forms 1 to
//! 3 ULP from the scalar `libm` ones (the table in [`real`]), and the kernel's lanes can differ
//! from its scalars by a few ULP more (the repository's reference CLI tests bound every such
//! kernel). `Real::mul_add` is fused only where the target has FMA, so results can differ
//! between targets in the last bit.
//!
//! In generic code `T::splat(x)` (from [`Real`]) takes an `f64`; on a concrete `f32x8`,
//! `f32x8::splat` is `wide`'s and takes an `f32`, and `f32x8::from_f64(x)` takes an `f64`
//! (the [`real`] module's "two splats" table). [`V3`] carries directions and colours on any
//! lane type and converts from and to glam's `Vec3`, `Vec3A` and `DVec3`.
//!
//! ## Modules
//! | module | what it owns | feature |
//! |---|---|---|
//! | [`real`] | [`Real`]: the float/lane trait, its [`Mask`], lane accuracy bounds | always |
//! | [`vec3`] | [`V3`]: 3-vector of scalars or lanes (structure of arrays), glam conversions | always |
//! | [`frame`] | orthonormal basis from a normal, local-frame `cos_theta`/`tan2_theta`/`cos_phi` | always |
//! | [`shading`] | a shading point's [`Cosines`] (n.v, n.l, n.h, v.h) and world-to-local [`ShadingPoint`]; the crate's one argument order | always |
//! | [`error`] | [`ParamError`], returned by parameter constructors | always |
//! | `wgsl` | the WGSL twins of the kernels as source text: `COMMON`, one constant per family, `ALL` | `wgsl` |
//! | [`batch`] | any kernel over structure-of-arrays slices, 8 `f32` / 4 `f64` at a time; over all cores with `par_run` | always; `par_run` with `rayon` (needs `std`) |
//! | `fresnel` | Schlick (+F90, SG), exact dielectric and polarized, conductor, F82 tint | `fresnel` |
//! | `microfacet` | the `Microfacet` trait (D, Lambda, G1, G2) shared by the NDFs | `microfacet` |
//! | `ggx` | GGX / Trowbridge-Reitz, isotropic and anisotropic, real-time V approximations | `ggx` |
//! | `beckmann` | Beckmann, exact and rational Lambda, Blinn-Phong exponent conversion | `beckmann` |
//! | `cook_torrance` | D G F / (4 NoL NoV) evaluated through V | `cook-torrance` |
//! | `diffuse` | Lambert, Oren-Nayar (qualitative, full, Fujii, EON), Burley, diffuse-Fresnel couplings | `diffuse` |
//! | `phong` | classic, modified and normalized Phong, Blinn-Phong | `phong` |
//! | `engine` | three.js, Filament, bevy, Unreal Engine 4 and glTF-viewer conventions (roughness floor, Fresnel and F90, visibility guard, diffuse weight) as data, evaluated with the crate's kernels | `engine` |
//! | `material` | the glTF / Filament metallic-roughness BRDF, its parameters and lobe sampling | `material` |
//! | `lights` | punctual light radiance, distance attenuation, spot cones | `lights` |
//! | `rough_dielectric` | the rough dielectric BSDF (reflection and refraction, both sides, radiance or importance) and its visible-normal sampler | `transmission` |
//! | `transmission` | glTF `KHR_materials_transmission` (thin-walled and volumetric BTDF in the glTF dielectric) and `KHR_materials_volume` (thickness, Beer-Lambert attenuation) | `transmission` |
//! | `iridescence` | thin-film interference (Belcour and Barla 2017) over dielectric and conductor bases, integrated in CIE XYZ | `iridescence` |
//! | `sampling` | cosine hemisphere, D cos sampling, visible normals, pdfs | `sampling` |
//! | `tonemap` | tonemapping operators, exposure | `tonemap` |
//! | `color` | sRGB / Rec.709 transfer, luminance, colour matrices | `tonemap` |
//! | `integrate` | hemisphere integrators: albedo, NDF area, weak furnace, reciprocity | `integrate` |
//! | `layers` | the glTF extension lobes (sheen, clearcoat, specular and IOR, anisotropy) and the layered material composing them | `sheen`, `clearcoat`, `specular`, `anisotropy`, `layered` |
//! | `ibl` | split-sum DFG table and fits, prefilter samples, irradiance (quadrature, SH9), multiple-scattering energy compensation | `ibl` |
//!
//! ## Bad input: one rule for every function
//! Every public kernel keeps the same rule, on `f32`, `f64`, `f32x8` and `f64x4` alike
//! (`tests/kernels/bad_input.rs` lists every kernel and checks each clause on every lane type):
//!
//! 1. **NaN in, NaN out.** A NaN in any input (a cosine, a direction component, a parameter,
//!    a uniform sample) gives NaN, never a plausible finite value: a CPU reference must surface
//!    the bug, not hide it. Samplers return a NaN direction and a NaN pdf. One NaN lane does
//!    not touch the other lanes.
//! 2. **An invalid parameter gives NaN.** A free function does not validate its parameters
//!    beyond this: alpha < 0, eta <= 0, k < 0, an albedo outside [0, 1] give NaN, never the
//!    value of some other parameter (a negative alpha is not quietly a mirror). Parameter
//!    types (`ggx::Ggx`, `beckmann::Beckmann`, the diffuse and material parameters)
//!    validate in their constructors, return a [`ParamError`], and keep their fields private so
//!    the check cannot be skipped.
//! 3. **Inputs are clamped to their meaning.** Cosines live in [-1, 1]; one just above 1 (an
//!    unnormalized vector) counts as 1; a finite direction at or below the horizon reflects
//!    nothing (0); uniform samples are clamped into [0, 1).
//! 4. **The whole documented domain is safe.** Finite in-domain input gives finite output,
//!    never inf: physically meaningless extremes are clamped by documented constants
//!    (`microfacet::ALPHA_MIN` and `ALPHA_MAX`), poles (Lambda at the horizon) and products
//!    that would overflow are capped at the largest finite value. The domain a doc states is
//!    the domain the tests sweep, up to the largest finite float.
//! 5. **Infinities.** Every documented domain ends at the largest finite float, so an infinity
//!    is never in-domain input. An infinite *cosine or uniform sample* is clamped like any
//!    other out-of-range one (rule 3): +inf counts as 1 and -inf as -1 (a sample: as its
//!    clamped ends), so the result equals the result at +-1 bit for bit. The tonemap
//!    operators' inputs are clamped the same way by their own documented clamp
//!    (`tonemap::sanitize`: -inf counts as 0, +inf as `tonemap::MAX_INPUT`). *Every other
//!    infinite input* (a direction or normal component, a parameter, a colour or radiance, an
//!    angle, a distance, a pdf) gives NaN in every output that a NaN in that input would
//!    reach: a direction (inf, 0, 1) has no one meaning, and an infinite radiance is an
//!    overflow upstream that a reference must surface. Samplers return a NaN direction and a
//!    NaN pdf; the integrators return a NaN estimate and error (`integrate`, "Bad input").
//!    Exempt: the vector-arithmetic helpers of [`V3`] (`dot`, `cross`, `length`,
//!    `length_squared`, `normalize_or`, `min_element`, `max_element`, `mirror`, the operators),
//!    `Frame::to_local` and `Frame::to_world` (for the vector they transform), and the linear
//!    colour helpers `color::mul` and `color::luminance`: they follow IEEE arithmetic like the
//!    operators they are. A zero-length finite direction is finite input: it gives finite
//!    output, and every sampler and pdf returns pdf 0 for it.
//!
//! ## Accuracy
//! The exact functions (NDFs, Smith terms, Fresnel, the transfer functions, the tonemapping
//! operators, the exact diffuse and Phong lobes) are held to ULP bounds against a correctly rounded reference (MPFR at 256
//! bits, evaluating each paper's own definition) by the `brdf-oracle` workspace member of the
//! repository; the measured table is in the README ("Accuracy promises") and `docs/accuracy.md`,
//! and the repository's report (`cargo run --release -p brdf-report`) prints it beside the
//! error and run time of every approximation.
//!
#![no_std]
#![deny(missing_docs)]
#![forbid(unsafe_code)]
// `batch::par_run` (feature `rayon`) runs on rayon's thread pool, which needs std.
#[cfg(feature = "rayon")]
extern crate std;

pub mod batch;
pub mod error;
pub mod frame;
pub mod real;
pub mod shading;
pub mod vec3;
#[cfg(feature = "wgsl")]
pub mod wgsl;

#[cfg(feature = "beckmann")]
pub mod beckmann;
#[cfg(feature = "tonemap")]
pub mod color;
#[cfg(feature = "cook-torrance")]
pub mod cook_torrance;
#[cfg(feature = "diffuse")]
pub mod diffuse;
#[allow(dead_code)] // each feature uses a subset of the guards
mod domain;
#[allow(dead_code)] // each feature uses a subset of the double-word arithmetic
mod dw;
#[cfg(feature = "engine")]
pub mod engine;
#[cfg(feature = "fresnel")]
pub mod fresnel;
#[cfg(feature = "ggx")]
pub mod ggx;
#[cfg(feature = "ibl")]
pub mod ibl;
#[cfg(feature = "integrate")]
pub mod integrate;
#[cfg(feature = "iridescence")]
pub mod iridescence;
#[cfg(any(
    feature = "sheen",
    feature = "clearcoat",
    feature = "specular",
    feature = "anisotropy",
    feature = "layered"
))]
pub mod layers;
#[cfg(feature = "lights")]
pub mod lights;
#[cfg(feature = "material")]
pub mod material;
#[cfg(feature = "microfacet")]
pub mod microfacet;
#[cfg(feature = "phong")]
pub mod phong;
#[cfg(feature = "transmission")]
pub mod rough_dielectric;
#[cfg(feature = "sampling")]
pub mod sampling;
#[cfg(feature = "tonemap")]
pub mod tonemap;
#[cfg(feature = "transmission")]
pub mod transmission;
#[allow(dead_code)] // each feature uses a subset of the f64 evaluation of f32 kernels
mod widen;

pub use error::ParamError;

/// The vector math crate whose `Vec3`/`DVec3` convert to [`V3`].
pub use glam;
pub use real::{Mask, Real};
pub use shading::{Cosines, ShadingPoint};
pub use vec3::V3;
/// The SIMD crate whose `f32x8` and `f64x4` implement [`Real`].
pub use wide;

/// The README's snippets, compiled and run as doc tests (they use every default feature).
#[doc = include_str!("../README.md")]
#[cfg(all(
    doctest,
    feature = "integrate",
    feature = "engine",
    feature = "material",
    feature = "tonemap",
    feature = "ibl",
    feature = "beckmann",
    feature = "phong",
    feature = "lights"
))]
pub struct ReadmeDoctests;
