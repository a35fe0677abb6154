//! WGSL twins of the kernels, as source text for shaders.
//!
//! Each constant is one family's WGSL source (the files under `wgsl/` in the repository): the
//! functions are named by the Rust kernel's path with `::` written `_` (`ggx::d` is `ggx_d`,
//! `fresnel::schlick_f90` is `fresnel_schlick_f90`), take the Rust kernel's arguments in the
//! same order (a `V3` argument as its three components `w_x, w_y, w_z`, as the reference CLI
//! `brdf-ref --list` prints them; an argument whose name WGSL reserves takes a trailing
//! underscore: `tonemap_Operator_apply(operator_, ...)`), and use the same numerically stable forms (GGX D's
//! cancellation-free denominator (1 - c)(1 + c) + c^2 alpha^2, the alpha clamps
//! `ALPHA_MIN`/`ALPHA_MAX`, the caps at the largest finite value). Multi-channel results are
//! `vec3<f32>` (`vec2<f32>` for two, `array<f32, N>` beyond four: a sampler's direction, pdf
//! and weights); an enumerated parameter (the material's diffuse coupling) is a `u32`. Helpers
//! are prefixed `brdf_`; those shared by the families live in [`COMMON`].
//!
//! # Composing
//! [`COMMON`] must come first, then each family after the families it calls into
//! ([`Family::needs`]: [`COOK_TORRANCE`] needs [`GGX`], [`FRESNEL`] and [`BECKMANN`],
//! [`DIFFUSE`] needs [`FRESNEL`], [`MATERIAL`] needs [`GGX`], [`FRESNEL`], [`BECKMANN`],
//! [`COOK_TORRANCE`] and [`SAMPLING`], [`SAMPLING`] needs [`GGX`] and [`BECKMANN`], [`LAYERS`]
//! needs [`GGX`] and [`FRESNEL`], [`ROUGH_DIELECTRIC`] needs [`GGX`], [`FRESNEL`], [`BECKMANN`]
//! and [`SAMPLING`], [`TRANSMISSION`] needs those and [`ROUGH_DIELECTRIC`]; [`IRIDESCENCE`]
//! needs only [`COMMON`]; [`ENGINE`] needs [`GGX`], [`FRESNEL`] and [`DIFFUSE`]; [`LAYERED`]
//! needs [`TRANSMISSION`] and what it needs, [`LAYERS`] and [`IRIDESCENCE`]). No family defines
//! a name another family defines, so any such subset concatenated after [`COMMON`] is one valid
//! WGSL module:
//!
//! ```
//! let source = [brdf::wgsl::COMMON, brdf::wgsl::GGX, brdf::wgsl::FRESNEL].concat();
//! assert!(source.contains("fn ggx_d(n_dot_h: f32, alpha: f32) -> f32"));
//! ```
//!
//! [`ALL`] is every family in that order. With `wgpu`, pass the concatenation followed by
//! your own entry points to `device.create_shader_module` as `ShaderSource::Wgsl` (the
//! repository's README shows it, compiled by the `brdf-gpu` tests). The sources carry no
//! `#define_import_path` or import lines: for naga_oil or WESL, register the concatenation as
//! one module of your own.
//!
//! # What differs from the Rust kernels
//! The twins compute in `f32`, rounding every operation: the Rust kernels that round once
//! through double words (`ggx::d`, `ggx::lambda`, `fresnel::f0_from_ior`, ...) carry error-free
//! transformations that a WGSL implementation may undo, since it may reassociate and contract
//! floating-point operations (W3C, "WebGPU Shading Language", section "Floating Point
//! Evaluation"). WGSL also promises nothing for infinities and NaN, so the Rust kernels' rule
//! "NaN in, NaN out" has no twin: a NaN or infinite argument gives an unspecified value. The
//! repository's `brdf-gpu` workspace member runs every twin on a GPU API and holds it, input
//! by input, to an error bound derived from the accuracy table of that same section.

/// Constants and helpers every family uses (pi, the largest finite `f32`, the alpha clamps,
/// 1 - c^2 without cancellation, the samplers' clamp of u and azimuth), and the twins of `brdf::microfacet`'s roughness conversions.
/// Include it once, first.
pub const COMMON: &str = include_str!("../wgsl/common.wgsl");

/// The twins of `brdf::frame`'s local-frame trigonometry (cos, sin and tan of theta, cos and
/// sin of phi, from a direction's components; the direction of spherical angles).
pub const FRAME: &str = include_str!("../wgsl/frame.wgsl");

/// The twins of `brdf::ggx`'s free functions (D, the fast D, anisotropic D, Lambda, G1, the
/// height-correlated V and its Hammon and Filament fast forms, Schlick's G1, k and V) and of
/// `ggx::Ggx`'s methods on local directions (`ggx_Ggx_d`, `ggx_Ggx_lambda`, ...,
/// `ggx_Ggx_d_visible`, taking the constructor's `alpha_x, alpha_y` first).
pub const GGX: &str = include_str!("../wgsl/ggx.wgsl");

/// The twins of `brdf::fresnel`'s Schlick family (plain, F90, spherical Gaussian, F82 tint,
/// RGB forms), the exact dielectric reflectance (polarized and not, and
/// `fresnel_dielectric_fast`, the twin of its working-precision form), the exact conductor
/// reflectance of a complex IOR (and its RGB form), F0 and IOR conversions and the dielectric
/// average's fit.
pub const FRESNEL: &str = include_str!("../wgsl/fresnel.wgsl");

/// The twins of `brdf::beckmann`'s D, fast D, Smith's a, the exact Smith Lambda and G1 (WGSL
/// has no `erf`: written as the Rust kernels write them, without erfc's cancellation, with a
/// polynomial and a continued fraction for the erfc ratio), Walter's rational Lambda, the
/// Blinn-Phong exponent conversions, and `beckmann::Beckmann`'s methods on local directions
/// (`beckmann_Beckmann_d`, ..., `beckmann_Beckmann_d_visible`).
pub const BECKMANN: &str = include_str!("../wgsl/beckmann.wgsl");

/// The twins of `brdf::cook_torrance`: the half vector and its cosines, the forms over a
/// microfacet model on local directions (`cook_torrance_eval`, ..., the model a `u32`:
/// 0 = GGX, 1 = Beckmann), and the isotropic GGX and Beckmann lobes from dot products
/// (constant F, Schlick RGB, exact dielectric, exact conductor). Needs [`GGX`], [`FRESNEL`]
/// and [`BECKMANN`] before it.
pub const COOK_TORRANCE: &str = include_str!("../wgsl/cook_torrance.wgsl");

/// The twins of `brdf::diffuse`'s Lambert, qualitative and Fujii Oren-Nayar (with its A and
/// B), EON (exact and fitted, with its directional and average albedos, its CLTC and mixture
/// samplers and their pdfs), Burley and
/// renormalized Burley lobes, the diffuse-Fresnel couplings, and the parameter types' `eval`
/// on local directions (`diffuse_Burley_eval`, `diffuse_Eon_albedo`, ...). Needs [`FRESNEL`]
/// before it.
pub const DIFFUSE: &str = include_str!("../wgsl/diffuse.wgsl");

/// The twins of `brdf::phong`: classic, modified and normalized Phong, Lambert plus Phong,
/// Blinn-Phong with exact and approximate normalization, the Blinn-Phong NDF, and the
/// parameter types' `eval` on local directions (`phong_BlinnPhong_eval`, ...).
pub const PHONG: &str = include_str!("../wgsl/phong.wgsl");

/// The twins of `brdf::lights`: reflected radiance (radiometric and pi c_light), irradiance,
/// inverse-square, windowed and polynomial falloffs, spot cones (from cosines, and
/// `lights::SpotCone` from its angles).
pub const LIGHTS: &str = include_str!("../wgsl/lights.wgsl");

/// The twins of `brdf::tonemap`'s sanitize, exposure, Reinhard (plain, extended, on
/// luminance, extended on luminance, Jodie), Narkowicz's and Hill's ACES, Khronos PBR Neutral,
/// Hable's, Lottes' and Uchimura's curves (from their parameters), AgX (minimal, three.js's,
/// Filament's, the looks a `u32`) and `Operator::apply` (the operator a `u32` index into
/// `Operator::all()`), and of `brdf::color`'s sRGB and Rec.709 transfer, gamma, luminance
/// and matrix product.
pub const TONEMAP: &str = include_str!("../wgsl/tonemap.wgsl");

/// The twins of `brdf::material`'s F0 from reflectance, the metallic-roughness BRDF from dot
/// products (its three diffuse couplings, and glTF's composition; precise and fast tiers), and
/// `material::MetallicRoughness`'s `eval`, `eval_fast`, `specular_probability`, `sample`,
/// `sample_weighted` and `pdf` on local directions. Needs [`GGX`], [`FRESNEL`], [`BECKMANN`],
/// [`COOK_TORRANCE`] and [`SAMPLING`] before it.
pub const MATERIAL: &str = include_str!("../wgsl/material.wgsl");

/// The twins of `brdf::ibl::dfg`'s per-pixel terms: the analytic split-sum fits (Karis mobile,
/// Lazarov, Narkowicz's two), the split-sum specular, the roughness-mip mappings; and of
/// `brdf::ibl::irradiance::Sh9`'s radiance and irradiance from nine RGB spherical-harmonic
/// coefficients (`ibl_irradiance_Sh9_eval`, taking the 27 coefficients first); and of
/// `brdf::ibl::energy`'s per-pixel multiple-scattering terms (Kulla and Conty's lobe and
/// Fresnel, the average Schlick Fresnel, Turquin's scale, Fdez-Aguera's split-sum terms;
/// the E and E_avg tables they read are textures in a shader).
pub const IBL: &str = include_str!("../wgsl/ibl.wgsl");

/// The twins of `brdf::sampling`'s cosine-hemisphere sampler and pdf, reflection Jacobian,
/// GGX and Beckmann D cos and visible-normal samplers (GGX: Heitz's and by spherical caps;
/// Beckmann: Heitz and d'Eon's inversion), D cos and visible-normal pdfs, GGX and Beckmann
/// reflection samplers with their weights (a constant F, scalar or RGB) and pdfs, and erf^-1
/// (with the f32 erf and erfc of the `libm` crate it is polished with). Needs [`GGX`] and
/// [`BECKMANN`] before it.
pub const SAMPLING: &str = include_str!("../wgsl/sampling.wgsl");

/// The twins of `brdf::layers`' glTF extension lobes: the Charlie sheen's D, fitted Lambda
/// and V, Neubelt's and Ashikhmin's cloth terms, the sheen lobe, the sheen albedo read from
/// the built-in 16 x 16 table (a constant array, `layers_sheen_albedo`), the two analytic sheen
/// albedo fits and the albedo scaling; the clearcoat's Fresnel, Kelemen's V, the coat lobes and the
/// layering; F0 from IOR and the specular extension's dielectric F0; the anisotropy's tangent
/// width, direction and bent reflection vector. Needs [`GGX`] and [`FRESNEL`] before it.
pub const LAYERS: &str = include_str!("../wgsl/layers.wgsl");

/// The twins of `brdf::rough_dielectric`'s generalized half vector, BSDF
/// (`rough_dielectric_eval`, the model a `u32`: 0 = GGX, 1 = Beckmann; the transport a `u32`:
/// 0 = radiance, 1 = importance), pdf of both lobes and GGX and Beckmann samplers
/// (`rough_dielectric_ggx_sample`, `rough_dielectric_beckmann_sample`).
/// Needs [`GGX`], [`FRESNEL`], [`BECKMANN`] and [`SAMPLING`] before it.
pub const ROUGH_DIELECTRIC: &str = include_str!("../wgsl/rough_dielectric.wgsl");

/// The twins of `brdf::transmission::Volume`'s Beer-Lambert transmittance and attenuation
/// coefficient (`transmission_Volume_transmittance`, taking the constructor's thickness,
/// attenuation colour and distance first), and of `transmission::thin_walled_btdf` and
/// `transmission::dielectric_bsdf`. Needs [`GGX`], [`FRESNEL`], [`BECKMANN`], [`SAMPLING`] and
/// [`ROUGH_DIELECTRIC`] before it.
pub const TRANSMISSION: &str = include_str!("../wgsl/transmission.wgsl");

/// The twins of `brdf::iridescence`'s thin-film reflectance over a dielectric and over a
/// conductor base (`iridescence_dielectric`, `iridescence_conductor`, taking the film's
/// thickness and index, `ThinFilm::new`'s arguments, first). The Airy sum's phases reach
/// thousands of radians, where WGSL states no accuracy for `cos`: the twins carry them in half
/// turns and reduce them exactly (u = n + s, n = round(u), s in [-1/2, 1/2] by Sterbenz's
/// lemma) before `cos` and `sin` of pi s, and rotate by the interfaces' complex Fresnel
/// coefficients instead of adding `atan2` phases.
pub const IRIDESCENCE: &str = include_str!("../wgsl/iridescence.wgsl");

/// The twins of `brdf::engine::Convention`'s methods (`engine_Convention_alpha`, `_f90`,
/// `_fresnel`, `_specular`, `_diffuse`, `_brdf`), the receiver a `u32` index into
/// `engine::ALL` (0 = three.js, 1 = Filament, 2 = bevy, 3 = Unreal Engine 4, 4 = the Khronos
/// glTF sample viewer): each engine's floors, guards, Fresnel weight, F90 rule and diffuse
/// lobe over the crate's stable kernels, to run beside that engine's own shader code. Needs
/// [`GGX`], [`FRESNEL`] and [`DIFFUSE`] before it.
pub const ENGINE: &str = include_str!("../wgsl/engine.wgsl");

/// The twins of `brdf::layers::layered::Layered`'s `eval`, `lobe_probabilities`, `pdf` and
/// `sample` (`layers_layered_Layered_eval`, ...), taking the material as the 22 arguments of its
/// constructor and builders (base, sheen, clearcoat, anisotropy, iridescence, transmission,
/// volume; each off at its glTF default) before the local-frame directions; the coat normal
/// is the shading normal and the multiple-scattering compensation is off. Composed from the
/// lobes' twins in the Rust order: needs [`GGX`], [`FRESNEL`], [`BECKMANN`], [`SAMPLING`],
/// [`ROUGH_DIELECTRIC`], [`TRANSMISSION`], [`LAYERS`] and [`IRIDESCENCE`] before it.
pub const LAYERED: &str = include_str!("../wgsl/layered.wgsl");

/// [`COMMON`] followed by every family, each after the families it needs: one module defining
/// every twin.
pub const ALL: &str = concat!(
    include_str!("../wgsl/common.wgsl"),
    include_str!("../wgsl/frame.wgsl"),
    include_str!("../wgsl/ggx.wgsl"),
    include_str!("../wgsl/fresnel.wgsl"),
    include_str!("../wgsl/beckmann.wgsl"),
    include_str!("../wgsl/cook_torrance.wgsl"),
    include_str!("../wgsl/diffuse.wgsl"),
    include_str!("../wgsl/phong.wgsl"),
    include_str!("../wgsl/lights.wgsl"),
    include_str!("../wgsl/tonemap.wgsl"),
    include_str!("../wgsl/ibl.wgsl"),
    include_str!("../wgsl/sampling.wgsl"),
    include_str!("../wgsl/material.wgsl"),
    include_str!("../wgsl/layers.wgsl"),
    include_str!("../wgsl/rough_dielectric.wgsl"),
    include_str!("../wgsl/transmission.wgsl"),
    include_str!("../wgsl/iridescence.wgsl"),
    include_str!("../wgsl/engine.wgsl"),
    include_str!("../wgsl/layered.wgsl"),
);

/// One family's WGSL, with the families it calls into.
#[derive(Clone, Copy, Debug)]
pub struct Family {
    /// The Rust module it twins (`ggx`, `cook_torrance`, ...).
    pub name: &'static str,
    /// Its source.
    pub source: &'static str,
    /// The families whose functions it calls, in the order to include them (after
    /// [`COMMON`], before this one).
    pub needs: &'static [&'static str],
}

/// Every family, in the order of [`ALL`].
pub const FAMILIES: &[Family] = &[
    Family {
        name: "frame",
        source: FRAME,
        needs: &[],
    },
    Family {
        name: "ggx",
        source: GGX,
        needs: &[],
    },
    Family {
        name: "fresnel",
        source: FRESNEL,
        needs: &[],
    },
    Family {
        name: "beckmann",
        source: BECKMANN,
        needs: &[],
    },
    Family {
        name: "cook_torrance",
        source: COOK_TORRANCE,
        needs: &["ggx", "fresnel", "beckmann"],
    },
    Family {
        name: "diffuse",
        source: DIFFUSE,
        needs: &["fresnel"],
    },
    Family {
        name: "phong",
        source: PHONG,
        needs: &[],
    },
    Family {
        name: "lights",
        source: LIGHTS,
        needs: &[],
    },
    Family {
        name: "tonemap",
        source: TONEMAP,
        needs: &[],
    },
    Family {
        name: "ibl",
        source: IBL,
        needs: &[],
    },
    Family {
        name: "sampling",
        source: SAMPLING,
        needs: &["ggx", "beckmann"],
    },
    Family {
        name: "material",
        source: MATERIAL,
        needs: &["ggx", "fresnel", "beckmann", "cook_torrance", "sampling"],
    },
    Family {
        name: "layers",
        source: LAYERS,
        needs: &["ggx", "fresnel"],
    },
    Family {
        name: "rough_dielectric",
        source: ROUGH_DIELECTRIC,
        needs: &["ggx", "fresnel", "beckmann", "sampling"],
    },
    Family {
        name: "transmission",
        source: TRANSMISSION,
        needs: &["ggx", "fresnel", "beckmann", "sampling", "rough_dielectric"],
    },
    Family {
        name: "iridescence",
        source: IRIDESCENCE,
        needs: &[],
    },
    Family {
        name: "engine",
        source: ENGINE,
        needs: &["ggx", "fresnel", "diffuse"],
    },
    Family {
        name: "layered",
        source: LAYERED,
        needs: &[
            "ggx",
            "fresnel",
            "beckmann",
            "sampling",
            "rough_dielectric",
            "transmission",
            "layers",
            "iridescence",
        ],
    },
];
