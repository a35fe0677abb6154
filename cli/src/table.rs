//! The kernel table: one [`Kernel`] per public scalar kernel of `brdf`, by its documented path.
//!
//! # How a Rust signature becomes a row of arguments
//! The arguments of a kernel are the Rust function's parameters, in order, after these rules
//! (`cli/tests/cli/drift.rs` parses `brdf`'s source with `syn` and holds every entry to them):
//!
//! - a scalar parameter `x: T` is one argument `x`;
//! - a vector `w: V3<T>` is three arguments `w_x`, `w_y`, `w_z`, or `w_r`, `w_g`, `w_b` where
//!   it is a colour (RGB albedo, F0, eta and k per channel, a radiance);
//! - a validated parameter type (`&Ggx<T>`, `&Beckmann<T>`, `&HableParams`, the receiver
//!   `&self` of `Ggx::d`, `Eon::eval`, `MetallicRoughness::sample`, ...) is the arguments of
//!   its constructor ([`CONSTRUCTORS`]), flattened the same way and built inside the kernel;
//!   if construction fails (only for input the CLI's domain check would reject) every output
//!   is NaN. Where a constructor argument's name clashes with another argument, all of that
//!   parameter's constructor arguments are prefixed with the parameter's name (`hable`'s
//!   `c` and `p_c`);
//! - a type with optional extensions ([`BUILDERS`]: `layers::layered::Layered`) is its
//!   constructor's arguments followed by the parameters of each of its listed builders
//!   (`with_sheen`, `with_clearcoat`, ...), in the order they are applied, flattened the same
//!   way and named after the builder: prefixed with its name less `with_` unless already so
//!   named (`with_sheen(color, roughness)` is `sheen_color_r`, ..., `sheen_roughness`;
//!   `with_clearcoat(clearcoat, roughness)` is `clearcoat`, `clearcoat_roughness`;
//!   `with_volume(volume)` is `volume_thickness`, ...). Every builder is applied: an extension
//!   is off at its glTF default, the value that leaves the material bit for bit as without it
//!   (sheen colour 0, clearcoat 0, anisotropy strength 0, iridescence factor 0, transmission 0,
//!   volume thickness 0: thin-walled);
//! - a parameter generic over `Microfacet` (`cook_torrance::eval`'s `m`, `sampling::d_cos_pdf`'s
//!   `dist`) is `model` ([`MODEL`]: 0 = `ggx::Ggx`, 1 = `beckmann::Beckmann`) followed by the
//!   shared constructor arguments `alpha_x`, `alpha_y`;
//! - an enumerated parameter (an AgX look, a diffuse coupling, the receiver of
//!   `tonemap::Operator::apply`) is one integer argument whose domain lists the choices;
//! - a `Cosines<T>` parameter `c` is four arguments `n_dot_v`, `n_dot_l`, `n_dot_h`, `v_dot_h`
//!   (its fields, in the crate's one cosine order);
//! - the receiver of `engine::Convention`'s methods is one integer argument `convention`, an
//!   index into `engine::ALL` ([`CONVENTION`]), like the other enumerated parameters;
//! - a colour matrix `m: &Mat3` is nine arguments `m_0_0`, `m_0_1`, ..., `m_2_2` (row-major);
//! - a Fresnel closure `fresnel: impl Fn(T) -> T` (or `-> V3<T>`) is the constant it returns,
//!   `fresnel` (or `fresnel_r`, `fresnel_g`, `fresnel_b`);
//! - `V3`'s own methods name their receiver `self` (`self_x`, `self_y`, `self_z`).
//!
//! Vector results are flattened the same way; samplers return the direction's components and
//! then the pdf (and the weight where the function returns one). Output names never repeat an
//! argument's name, so one CSV header holds both.
//!
//! # Domains
//! Each argument's [`Domain`] is the one its documentation states. Relations between arguments
//! are [`Constraint`]s: every run of three arguments `w_x`, `w_y`, `w_z` with the domain
//! [`Domain::DIR`] must be a unit vector (within [`UNIT_TOLERANCE`]), and a few kernels add
//! orderings (`spot_cone`'s cos_outer <= cos_inner, ...).
//!
//! Functions computed in `f64` only (`fresnel::average_dielectric`,
//! `ibl::energy::fresnel_avg_conductor`, `tonemap::ev100_from_camera`) and kernels whose
//! parameters are `f64` structs (Hable, Lottes, Uchimura, AgX looks, colour matrices) are
//! evaluated lane by lane on `f32x8` and `f64x4` (each lane's arguments splat, so the lane
//! type's own code runs); in `f32` the `f64` functions' results are rounded once.

use brdf::fresnel::ComplexIor;
use brdf::ibl::energy::{Albedo, AverageAlbedo, Reflectance};
use brdf::microfacet::Alpha;
use brdf::microfacet::{ALPHA_MAX, ALPHA_MIN};
use brdf::wide::{f32x8, f64x4};
use brdf::{Cosines, Mask, ParamError, Real, V3};

/// Where a scalar argument may lie, or where an output is guaranteed to lie.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// Whether `lo` itself is excluded.
    pub lo_open: bool,
    /// Whether `hi` itself is excluded.
    pub hi_open: bool,
    /// Whether only integers are allowed (choices of an enumerated parameter).
    pub integer: bool,
    /// The domain as the crate's docs state it, for `--list` and error messages.
    pub text: &'static str,
}

/// A float type a kernel runs on, with the constants its extremes and checks need.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Float {
    /// `f32` (and `f32x8` lanes).
    F32,
    /// `f64` (and `f64x4` lanes).
    F64,
}

impl Float {
    /// Machine epsilon.
    #[must_use]
    pub fn eps(self) -> f64 {
        match self {
            Self::F32 => f64::from(f32::EPSILON),
            Self::F64 => f64::EPSILON,
        }
    }
    /// Smallest positive normal value.
    #[must_use]
    pub fn tiny(self) -> f64 {
        match self {
            Self::F32 => f64::from(f32::MIN_POSITIVE),
            Self::F64 => f64::MIN_POSITIVE,
        }
    }
    /// Largest finite value.
    #[must_use]
    pub fn max(self) -> f64 {
        match self {
            Self::F32 => f64::from(f32::MAX),
            Self::F64 => f64::MAX,
        }
    }
    /// Smallest positive subnormal value.
    #[must_use]
    pub fn min_subnormal(self) -> f64 {
        match self {
            Self::F32 => f64::from(f32::from_bits(1)),
            Self::F64 => f64::from_bits(1),
        }
    }
    /// `x` rounded to this type (to nearest), as an `f64`.
    #[must_use]
    pub fn round(self, x: f64) -> f64 {
        match self {
            #[allow(clippy::cast_possible_truncation)]
            Self::F32 => f64::from(x as f32),
            Self::F64 => x,
        }
    }
    /// The type's name as Rust writes it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::F32 => "f32",
            Self::F64 => "f64",
        }
    }
}

impl Domain {
    /// The closed interval [lo, hi] (either end may be infinite: an infinite end is allowed
    /// as a value only when it is written as an end of a closed interval).
    #[must_use]
    pub const fn closed(lo: f64, hi: f64, text: &'static str) -> Self {
        Self {
            lo,
            hi,
            lo_open: false,
            hi_open: false,
            integer: false,
            text,
        }
    }
    /// A half-open or open interval.
    #[must_use]
    pub const fn new(lo: f64, lo_open: bool, hi: f64, hi_open: bool, text: &'static str) -> Self {
        Self {
            lo,
            hi,
            lo_open,
            hi_open,
            integer: false,
            text,
        }
    }
    /// Integers 0 ..= n - 1, each naming one choice.
    #[must_use]
    pub const fn choice(n: u32, text: &'static str) -> Self {
        Self {
            lo: 0.0,
            hi: (n - 1) as f64,
            lo_open: false,
            hi_open: false,
            integer: true,
            text,
        }
    }
    /// Cosines: [-1, 1].
    pub const COS: Self = Self::closed(-1.0, 1.0, "[-1, 1]");
    /// Clamped cosines and other unit-interval quantities: [0, 1].
    pub const UNIT: Self = Self::closed(0.0, 1.0, "[0, 1]");
    /// Any finite value >= 0.
    pub const NONNEG: Self = Self::new(0.0, false, f64::INFINITY, true, "[0, +inf), finite");
    /// Any value >= 0, +inf included.
    pub const NONNEG_INF: Self = Self::closed(0.0, f64::INFINITY, "[0, +inf]");
    /// Any finite value > 0.
    pub const POSITIVE: Self = Self::new(0.0, true, f64::INFINITY, true, "(0, +inf), finite");
    /// Any finite value.
    pub const FINITE: Self = Self::new(f64::NEG_INFINITY, true, f64::INFINITY, true, "finite");
    /// Any value but NaN, both infinities included (inputs the kernel clamps itself, outputs
    /// that may overflow).
    pub const ANY: Self = Self::closed(
        f64::NEG_INFINITY,
        f64::INFINITY,
        "any value, +-inf included (not NaN)",
    );
    /// A component of a unit direction: [-1, 1], and the three components of the vector must
    /// have length 1 (within [`UNIT_TOLERANCE`]).
    pub const DIR: Self = Self::closed(-1.0, 1.0, "[-1, 1], component of a unit vector");
    /// A component of a unit vector the kernel returns: [-1, 1] up to a rounding.
    pub const DIR_OUT: Self = Self::closed(
        -1.0 - 1e-6,
        1.0 + 1e-6,
        "component of a unit vector, [-1, 1] to rounding",
    );
    /// A uniform sample: [0, 1], 1 being clamped to the largest float below 1.
    pub const SAMPLE: Self = Self::closed(0.0, 1.0, "[0, 1] (1 is clamped below 1)");

    /// Whether `x` lies in the domain (NaN never does).
    #[must_use]
    pub fn contains(&self, x: f64) -> bool {
        let above = if self.lo_open {
            x > self.lo
        } else {
            x >= self.lo
        };
        let below = if self.hi_open {
            x < self.hi
        } else {
            x <= self.hi
        };
        above && below && (!self.integer || x.fract() == 0.0)
    }

    /// Whether `x` (a value of type `ty`) lies in the domain with both ends rounded to `ty`,
    /// as the kernel compares them (pi as an `f32` lies above pi, and so does the `f32` a
    /// shader passes for it).
    #[must_use]
    pub fn contains_as(&self, x: f64, ty: Float) -> bool {
        Self {
            lo: ty.round(self.lo),
            hi: ty.round(self.hi),
            ..*self
        }
        .contains(x)
    }

    /// The extreme inputs of this domain for a float type with machine epsilon `eps`,
    /// smallest normal `tiny` and largest finite value `max`: both ends (or the nearest
    /// representable values inside an open end), the values one rounding inside each end,
    /// 0, +-1 and 1 - eps/2 where inside, 1 +- 1e-6 (an IOR near 1), the smallest subnormal
    /// and normal, the microfacet width's clamps `ALPHA_MIN` and `ALPHA_MAX` with a rounding
    /// on either side, and the largest finite value where the domain reaches it. Every value
    /// returned lies in the domain.
    #[must_use]
    pub fn extremes(&self, eps: f64, tiny: f64, max: f64, min_subnormal: f64) -> Vec<f64> {
        let mut v = Vec::new();
        if self.integer {
            let mut i = self.lo;
            while i <= self.hi {
                v.push(i);
                i += 1.0;
            }
            return v;
        }
        let clamp_inf = |x: f64| x.clamp(-max, max);
        let lo = clamp_inf(self.lo);
        let hi = clamp_inf(self.hi);
        for x in [
            self.lo,
            self.hi,
            lo,
            hi,
            lo + lo.abs().max(tiny) * eps,
            hi - hi.abs().max(tiny) * eps,
            lo * (1.0 + eps),
            hi * (1.0 - eps / 2.0),
            0.0,
            -0.0,
            min_subnormal,
            -min_subnormal,
            tiny,
            -tiny,
            1.0,
            -1.0,
            1.0 - eps / 2.0,
            -(1.0 - eps / 2.0),
            1.0 + eps,
            1e-6,
            1.0 - 1e-6,
            1.0 + 1e-6,
            ALPHA_MIN,
            ALPHA_MIN * (1.0 - eps),
            ALPHA_MIN * (1.0 + eps),
            ALPHA_MAX,
            ALPHA_MAX * (1.0 - eps),
            ALPHA_MAX * (1.0 + eps),
            max,
            -max,
        ] {
            if (x.is_finite() || (x.is_infinite() && self.contains(x)))
                && self.contains(x)
                && !v.contains(&x)
            {
                v.push(x);
            }
        }
        v
    }

    /// [`Domain::extremes`] for the float type `ty`, each rounded to it and kept where it
    /// still lies in the domain (as [`Domain::contains_as`] decides).
    #[must_use]
    pub fn extremes_for(&self, ty: Float) -> Vec<f64> {
        let mut out: Vec<f64> = Vec::new();
        for x in self.extremes(ty.eps(), ty.tiny(), ty.max(), ty.min_subnormal()) {
            let r = ty.round(x);
            if self.contains_as(r, ty) && !out.iter().any(|o| o.to_bits() == r.to_bits()) {
                out.push(r);
            }
        }
        out
    }
}

/// How far from 1 the length of a vector whose components have the domain [`Domain::DIR`]
/// may be: 1e-3, loose enough for any shader's `normalize` (f16 included), tight enough to
/// catch an unnormalized or garbage vector.
pub const UNIT_TOLERANCE: f64 = 1e-3;

/// One named argument.
#[derive(Clone, Copy, Debug)]
pub struct Arg {
    /// The Rust parameter's name (flattened `_x`/`_y`/`_z` or `_r`/`_g`/`_b` for vectors).
    pub name: &'static str,
    /// Its documented domain.
    pub domain: Domain,
}

/// One named output.
#[derive(Clone, Copy, Debug)]
pub struct Output {
    /// Its name (the quantity, `d`, `f`, `v`, or a component `r`, `g`, `b`).
    pub name: &'static str,
    /// Where every output lies for in-domain inputs (the stability check).
    pub range: Domain,
}

/// The arguments of one row, by name, for a [`Constraint`]'s check.
#[derive(Clone, Copy, Debug)]
pub struct Values<'a> {
    args: &'a [Arg],
    values: &'a [f64],
    /// Machine epsilon of the float type the row is evaluated in.
    pub eps: f64,
    /// Largest finite value of that type.
    pub max: f64,
}

impl Values<'_> {
    /// The value of the argument `name`.
    ///
    /// # Panics
    /// If the kernel has no argument `name` (a typo in the table, which the tests catch).
    #[must_use]
    pub fn get(&self, name: &str) -> f64 {
        let i = self
            .args
            .iter()
            .position(|a| a.name == name)
            .unwrap_or_else(|| panic!("constraint names an unknown argument `{name}`"));
        self.values[i]
    }
}

/// A relation between a kernel's arguments that its documentation requires, beyond each
/// argument's own domain.
#[derive(Clone, Copy)]
pub enum Constraint {
    /// The three named arguments are the components of a unit vector (length within
    /// [`UNIT_TOLERANCE`] of 1). Runs `w_x`, `w_y`, `w_z` of [`Domain::DIR`] need no entry:
    /// [`Kernel::unit_vectors`] finds them.
    UnitVector([&'static str; 3]),
    /// Any other relation: its text (as the docs state it) and its check.
    Holds {
        /// The relation in words, for `--list` and error messages.
        text: &'static str,
        /// The arguments it relates (for error messages naming the columns).
        args: &'static [&'static str],
        /// True where the row satisfies it.
        check: fn(&Values<'_>) -> bool,
    },
}

impl core::fmt::Debug for Constraint {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.text())
    }
}

impl Constraint {
    /// The relation in words.
    #[must_use]
    pub fn text(&self) -> String {
        match self {
            Self::UnitVector([x, y, z]) => format!("({x}, {y}, {z}) is a unit vector"),
            Self::Holds { text, .. } => (*text).to_string(),
        }
    }
}

/// A relation between arguments that a row breaks ([`Kernel::broken_constraint`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Broken {
    /// The indices of the arguments involved.
    pub args: Vec<usize>,
    /// What is wrong, in words.
    pub text: String,
}

/// A kernel evaluated on one element: the inputs in the table's argument order, the outputs
/// written in the table's output order.
pub type Eval<T> = fn(&[T], &mut [T]);

/// A kernel over whole arrays, `n` elements: `ins[i]` holds argument `i` (length `n`, or 1 for
/// one value broadcast to every element), `outs[j]` receives output `j` (length `n`). Returns
/// `false`, writing nothing, when the counts or lengths do not fit.
pub type Arrays<S> = fn(&[&[S]], &mut [&mut [S]], usize) -> bool;

/// One public scalar kernel of `brdf`.
#[derive(Clone, Copy)]
pub struct Kernel {
    /// Its documented path in the crate (`ggx::d`, `fresnel::dielectric`, ...).
    pub path: &'static str,
    /// Its arguments, in the Rust function's order.
    pub args: &'static [Arg],
    /// Its outputs.
    pub outputs: &'static [Output],
    /// One line: what it computes and its source.
    pub summary: &'static str,
    /// Relations between arguments beyond the unit vectors found from the names (see
    /// [`Kernel::constraints_all`] for every one).
    pub constraints: &'static [Constraint],
    /// The kernel on `f32`.
    pub f32: Eval<f32>,
    /// The kernel on `f64`.
    pub f64: Eval<f64>,
    /// The kernel on eight `f32` lanes.
    pub f32x8: Eval<f32x8>,
    /// The kernel on four `f64` lanes.
    pub f64x4: Eval<f64x4>,
    /// The kernel over whole `f32` arrays, eight elements at a time on `f32x8` with the row's
    /// formula inlined in the loop: each element gets the `f32x8` entry's result on its row
    /// splat to every lane (lanes that come out NaN are evaluated again alone, so an invalid
    /// element never makes its neighbours NaN).
    pub f32_arrays: Arrays<f32>,
    /// The kernel over whole `f64` arrays, four elements at a time on `f64x4`.
    pub f64_arrays: Arrays<f64>,
}

impl core::fmt::Debug for Kernel {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Kernel")
            .field("path", &self.path)
            .finish_non_exhaustive()
    }
}

/// The kernel with this path, if the table has it.
#[must_use]
pub fn find(path: &str) -> Option<&'static Kernel> {
    KERNELS.iter().find(|k| k.path == path)
}

/// The constructor whose arguments stand for a validated parameter type (the type by its
/// path, the constructor's name; `{fields}` where the type is built from its public fields).
pub const CONSTRUCTORS: &[(&str, &str)] = &[
    ("ggx::Ggx", "new"),
    ("beckmann::Beckmann", "new"),
    ("transmission::Transmission", "new"),
    ("transmission::Volume", "new"),
    ("iridescence::ThinFilm", "new"),
    ("frame::Frame", "from_normal"),
    ("lights::SpotCone", "new"),
    ("material::MetallicRoughness", "new"),
    ("layers::layered::Layered", "new"),
    ("diffuse::Lambert", "new"),
    ("diffuse::OrenNayar", "new"),
    ("diffuse::OrenNayarFull", "new"),
    ("diffuse::OrenNayarFujii", "new"),
    ("diffuse::Eon", "new"),
    ("diffuse::Burley", "new"),
    ("diffuse::BurleyRenormalized", "new"),
    ("diffuse::ShirleyCoupled", "new"),
    ("diffuse::AshikhminShirley", "new"),
    ("phong::ClassicPhong", "new"),
    ("phong::ModifiedPhong", "new"),
    ("phong::NormalizedPhong", "new"),
    ("phong::BlinnPhong", "new"),
    ("phong::NormalizedBlinnPhong", "new"),
    ("phong::ApproxNormalizedBlinnPhong", "new"),
    ("phong::PhongDiffuseSpecular", "new"),
    ("ibl::irradiance::Sh9", "from_coeffs"),
    ("tonemap::HableParams", "new"),
    ("tonemap::LottesParams", "new"),
    ("tonemap::UchimuraParams", "{fields}"),
];

/// The builders of a type with optional extensions, in the order the kernels apply them:
/// where such a type stands for a parameter, its constructor's arguments ([`CONSTRUCTORS`])
/// are followed by each builder's parameters, prefixed with the builder's name less `with_`
/// unless already so named (module docs). The type's other builders (a layer's geometry such
/// as the coat normal, the energy compensation switch) are listed with their reason in
/// `cli/tests/cli/drift.rs`.
pub const BUILDERS: &[(&str, &[&str])] = &[(
    "layers::layered::Layered",
    &[
        "with_sheen",
        "with_clearcoat",
        "with_anisotropy",
        "with_iridescence",
        "with_transmission",
        "with_volume",
    ],
)];

/// The `model` argument of kernels generic over `Microfacet`.
pub const MODEL: Domain = Domain::choice(2, "0 = ggx::Ggx, 1 = beckmann::Beckmann");
/// The `transport` argument of the rough dielectric (`rough_dielectric::Transport`).
pub const TRANSPORT: Domain = Domain::choice(2, "0 = Radiance, 1 = Importance");
/// The `coupling` argument of `material::metallic_roughness` (`material::DiffuseCoupling`).
pub const COUPLING: Domain = Domain::choice(3, "0 = Gltf, 1 = OneMinusF, 2 = Additive");
/// The `convention` argument of `engine::Convention`'s methods: an index into `engine::ALL`.
pub const CONVENTION: Domain = Domain::choice(
    5,
    "index into engine::ALL: 0 = THREE_JS, 1 = FILAMENT, 2 = BEVY, 3 = UNREAL_4, \
     4 = KHRONOS_SAMPLE_VIEWER",
);
/// The `look` argument of the AgX operators (`tonemap::AgxLook`'s constants).
pub const LOOK: Domain = Domain::choice(4, "0 = BASE, 1 = PUNCHY, 2 = GOLDEN, 3 = GOLDEN_FILAMENT");
/// The `operator` argument of `tonemap::Operator::apply`: an index into `Operator::all()`.
pub const OPERATOR: Domain = Domain::choice(
    19,
    "index into Operator::all(): 0 = ExposureCurve(1), 1 = Reinhard, 2 = ReinhardLuminance, \
     3 = ReinhardExtended(4), 4 = ReinhardExtendedLuminance(4), 5 = ReinhardJodie, \
     6 = AcesNarkowicz, 7 = AcesHill, 8 = Hable(UNCHARTED2), 9 = Lottes(default_curve), \
     10 = Uchimura(GRAN_TURISMO), 11 = PbrNeutral, 12 = AgxMinimal(BASE), \
     13 = AgxMinimal(PUNCHY), 14 = AgxMinimal(GOLDEN), 15 = AgxThreejs, \
     16 = AgxFilament(BASE), 17 = AgxFilament(PUNCHY), 18 = AgxFilament(GOLDEN_FILAMENT)",
);

/// Alpha as the microfacet kernels take it: finite and >= 0 (clamped to
/// [ALPHA_MIN, ALPHA_MAX] inside).
const ALPHA: Domain = Domain::new(
    0.0,
    false,
    f64::INFINITY,
    true,
    "[0, +inf) finite, clamped to [ALPHA_MIN, ALPHA_MAX]",
);
/// An index of refraction (or the real part of a complex one): (0, MAX].
const ETA: Domain = Domain::new(0.0, true, f64::INFINITY, true, "(0, MAX], finite");
/// A thin film's thickness in nanometres (`iridescence::ThinFilm::new`).
const FILM_THICKNESS: Domain = Domain::closed(0.0, 10_000.0, "[0, MAX_THICKNESS_NM = 10000] nm");
/// A thin film's index of refraction (`iridescence::ThinFilm::new`).
const FILM_IOR: Domain = Domain::closed(1.0, 10.0, "[1, MAX_FILM_IOR = 10]");
/// An extinction coefficient: [0, MAX].
const KAPPA: Domain = Domain::new(0.0, false, f64::INFINITY, true, "[0, MAX], finite");
/// A Phong or Blinn-Phong exponent: finite and >= 0.
const EXPONENT: Domain = Domain::new(0.0, false, f64::INFINITY, true, "finite and >= 0");
/// A tonemapper's or transfer function's input: every value (clamped inside), NaN excluded.
const HDR: Domain = Domain::closed(
    f64::NEG_INFINITY,
    f64::INFINITY,
    "every value (negative -> 0, above MAX_INPUT -> MAX_INPUT)",
);
/// An input of the colour transfer functions: every finite value (negative clamped to 0;
/// +-inf give NaN, the crate's rule 5).
const SIGNAL: Domain = Domain::new(
    f64::NEG_INFINITY,
    true,
    f64::INFINITY,
    true,
    "every finite value (negative -> 0)",
);
/// A distance or a light's radius: >= 0 and finite (+inf gives NaN, the crate's rule 5).
const DISTANCE: Domain = Domain::new(0.0, false, f64::INFINITY, true, ">= 0, finite");
/// A strictly positive finite parameter.
const POS: Domain = Domain::POSITIVE;
/// A tonemapper's display-referred output.
const DISPLAY: Domain = Domain::closed(0.0, 1.0, "[0, 1] (clamped)");
/// A colour or direction component for `V3`'s own methods.
const COMPONENT: Domain = Domain::FINITE;

impl Kernel {
    /// Index of the argument `name`.
    #[must_use]
    pub fn arg_index(&self, name: &str) -> Option<usize> {
        self.args.iter().position(|a| a.name == name)
    }

    /// The unit vectors among the arguments: every run `w_x`, `w_y`, `w_z` of
    /// [`Domain::DIR`], and the explicit [`Constraint::UnitVector`]s, as argument indices.
    #[must_use]
    pub fn unit_vectors(&self) -> Vec<[usize; 3]> {
        let mut out = Vec::new();
        for (i, w) in self.args.windows(3).enumerate() {
            let base = w[0].name.strip_suffix("_x");
            if let Some(base) = base
                && w.iter().all(|a| a.domain == Domain::DIR)
                && w[1].name.strip_suffix("_y") == Some(base)
                && w[2].name.strip_suffix("_z") == Some(base)
            {
                out.push([i, i + 1, i + 2]);
            }
        }
        for c in self.constraints {
            if let Constraint::UnitVector(names) = c {
                let idx = names.map(|n| self.arg_index(n).unwrap_or(usize::MAX));
                out.push(idx);
            }
        }
        out
    }

    /// Every relation the arguments must satisfy, in words: the unit vectors, then
    /// [`Kernel::constraints`]' other entries.
    #[must_use]
    pub fn constraints_all(&self) -> Vec<String> {
        let mut out: Vec<String> = self
            .unit_vectors()
            .iter()
            .map(|[x, y, z]| {
                format!(
                    "({}, {}, {}) is a unit vector (length within {UNIT_TOLERANCE} of 1)",
                    self.args[*x].name, self.args[*y].name, self.args[*z].name
                )
            })
            .collect();
        out.extend(
            self.constraints
                .iter()
                .filter(|c| matches!(c, Constraint::Holds { .. }))
                .map(Constraint::text),
        );
        out
    }

    /// The first relation between arguments that `row` (values of type `ty`, one per
    /// argument, each already in its domain) breaks: the arguments it involves and what is
    /// wrong, in words.
    #[must_use]
    pub fn broken_constraint(&self, row: &[f64], ty: Float) -> Option<Broken> {
        for [x, y, z] in self.unit_vectors() {
            let len = (row[x] * row[x] + row[y] * row[y] + row[z] * row[z]).sqrt();
            if len.is_nan() || (len - 1.0).abs() > UNIT_TOLERANCE {
                return Some(Broken {
                    args: vec![x, y, z],
                    text: format!(
                        "({}, {}, {}) = ({}, {}, {}) has length {len}, not 1 (tolerance \
                         {UNIT_TOLERANCE})",
                        self.args[x].name,
                        self.args[y].name,
                        self.args[z].name,
                        row[x],
                        row[y],
                        row[z]
                    ),
                });
            }
        }
        let values = Values {
            args: self.args,
            values: row,
            eps: ty.eps(),
            max: ty.max(),
        };
        self.constraints.iter().find_map(|c| match c {
            Constraint::Holds { text, args, check } if !check(&values) => Some(Broken {
                args: args.iter().filter_map(|a| self.arg_index(a)).collect(),
                text: format!("{text} does not hold"),
            }),
            _ => None,
        })
    }

    /// The kernel on one `f64` row: the outputs in table order.
    #[must_use]
    pub fn eval_f64(&self, row: &[f64]) -> Vec<f64> {
        let mut out = vec![f64::NAN; self.outputs.len()];
        (self.f64)(row, &mut out);
        out
    }

    /// The kernel on one `f32` row: the outputs in table order.
    #[must_use]
    pub fn eval_f32(&self, row: &[f32]) -> Vec<f32> {
        let mut out = vec![f32::NAN; self.outputs.len()];
        (self.f32)(row, &mut out);
        out
    }

    /// The kernel on one row of type `ty` given as `f64`s (each value exactly representable
    /// in `ty`), its outputs widened to `f64`.
    #[must_use]
    pub fn eval_as(&self, row: &[f64], ty: Float) -> Vec<f64> {
        match ty {
            Float::F64 => self.eval_f64(row),
            Float::F32 => {
                #[allow(clippy::cast_possible_truncation)]
                let r: Vec<f32> = row.iter().map(|&x| x as f32).collect();
                self.eval_f32(&r).into_iter().map(f64::from).collect()
            }
        }
    }
}

/// Evaluates `body` lane by lane: for lane i every argument is splat from its lane i (so the
/// lane type's own code runs) and lane i of every output is kept. For kernels with `f64`
/// parameters, which are one value per call, not per lane.
fn lanewise<T: Real>(x: &[T], y: &mut [T], body: fn(&[T], &mut [T])) {
    if T::LANES == 1 {
        body(x, y);
        return;
    }
    let mut lanes: Vec<Vec<T>> = Vec::with_capacity(T::LANES);
    for i in 0..T::LANES {
        let xi: Vec<T> = x.iter().map(|v| T::from_scalar(v.lane(i))).collect();
        let mut yi = vec![T::ZERO; y.len()];
        body(&xi, &mut yi);
        lanes.push(yi);
    }
    for (k, o) in y.iter_mut().enumerate() {
        *o = T::from_fn(|i| lanes[i][k].lane(0));
    }
}

/// Lane types loaded from and stored to slices of their scalars, for [`over_arrays`].
trait Lanes: Real {
    /// The lanes from `s` (`s.len() == LANES`; NaN in lanes `s` lacks).
    fn load(s: &[Self::Scalar]) -> Self;
    /// The first `s.len()` lanes into `s` (`s.len() <= LANES`).
    fn store(self, s: &mut [Self::Scalar]);
}

macro_rules! lanes {
    ($t:ty, $s:ty, $n:literal) => {
        impl Lanes for $t {
            #[inline(always)]
            fn load(s: &[$s]) -> Self {
                <[$s; $n]>::try_from(s).map_or_else(
                    |_| Self::from_fn(|i| s.get(i).copied().unwrap_or(<$s>::NAN)),
                    Self::new,
                )
            }
            #[inline(always)]
            fn store(self, s: &mut [$s]) {
                let a = self.to_array();
                // A full group as one fixed-size copy (a copy of unknown length is a call to
                // memmove, a fifth of the time of a cheap kernel).
                match <&mut [$s; $n]>::try_from(&mut *s) {
                    Ok(full) => *full = a,
                    Err(_) => {
                        for (o, v) in s.iter_mut().zip(a) {
                            *o = v;
                        }
                    }
                }
            }
        }
    };
}
lanes!(f32x8, f32, 8);
lanes!(f64x4, f64, 4);

/// NaN test on a scalar (NaN is the one value unequal to itself).
#[allow(clippy::eq_op)]
fn scalar_nan<S: PartialOrd + Copy>(v: S) -> bool {
    v != v
}

/// The loop behind every [`Kernel::f32_arrays`] and [`Kernel::f64_arrays`]: `f` (the kernel's
/// body, inlined here by each row's `kernel!`, so a group costs no call and no argument
/// marshalling) on `L::LANES` elements at a time, arguments as [`Arrays`] describes.
///
/// Each element gets what the lane entry `slow` gives on its row splat to every lane. A
/// partial last group repeats its last element in the missing lanes (a value the caller
/// gave, as `brdf::batch` does) and stores only its real elements. A lane holding NaN may owe
/// it to its neighbours: a kernel that builds a validated parameter type (`Ggx::new`,
/// `PhongDiffuseSpecular::new`) gets NaN in every lane when one lane's parameters are invalid
/// (the constructor checks all lanes), so such lanes are evaluated again alone through `slow`,
/// and each element's result depends on its own inputs only.
#[inline(always)]
fn over_arrays<L: Lanes, const NA: usize, const NO: usize>(
    ins: &[&[L::Scalar]],
    outs: &mut [&mut [L::Scalar]],
    n: usize,
    f: impl Fn([L; NA]) -> [L; NO],
    slow: Eval<L>,
) -> bool {
    if ins.len() != NA
        || outs.len() != NO
        || ins.iter().any(|s| s.len() != n && s.len() != 1)
        || outs.iter().any(|o| o.len() != n)
    {
        return false;
    }
    let w = L::LANES;
    let mut s0 = 0;
    while s0 < n {
        let len = w.min(n - s0);
        // A plain loop, not `core::array::from_fn`: that one is a call per argument even at
        // opt-level 3, three times the cost of Schlick's formula.
        let mut x = [L::ZERO; NA];
        for (xi, s) in x.iter_mut().zip(ins) {
            *xi = if s.len() == 1 {
                L::from_scalar(s[0])
            } else if len == w {
                L::load(&s[s0..s0 + w])
            } else {
                L::from_fn(|j| s[s0 + j.min(len - 1)])
            };
        }
        let y = f(x);
        for (o, v) in outs.iter_mut().zip(y) {
            v.store(&mut o[s0..s0 + len]);
        }
        if y.iter().any(|v| v.is_nan().any()) {
            for i in 0..len {
                if y.iter().any(|v| scalar_nan(v.lane(i))) {
                    let xi = x.map(|v| L::from_scalar(v.lane(i)));
                    let mut yi = [L::ZERO; NO];
                    slow(&xi, &mut yi);
                    for (o, v) in outs.iter_mut().zip(yi) {
                        o[s0 + i] = v.lane(0);
                    }
                }
            }
        }
        s0 += len;
    }
    true
}

/// Lane 0 of `x` as an `f64` (exact): the value of an argument that is one `f64` per call.
fn f64_of<T: Real>(x: T) -> f64 {
    x.lane(0).into()
}

/// `N` NaNs.
fn nan<T: Real, const N: usize>() -> [T; N] {
    [T::splat(f64::NAN); N]
}

/// The outputs of `f` on the constructed parameter, or NaN in every output if construction
/// failed.
fn built<P, T: Real, const N: usize>(
    p: Result<P, ParamError>,
    f: impl FnOnce(P) -> [T; N],
) -> [T; N] {
    p.map_or_else(|_| nan(), f)
}

/// The layered material of the rows' 22 material arguments (the base, then every extension of
/// [`BUILDERS`] in its order; each is off at its glTF default).
fn layered<T: Real>(a: [T; 22]) -> Result<Layered<T>, ParamError> {
    Ok(Layered::new(v3(a[0], a[1], a[2]), a[3], a[4])?
        .with_sheen(v3(a[5], a[6], a[7]), a[8])?
        .with_clearcoat(a[9], a[10])?
        .with_anisotropy(a[11], a[12])?
        .with_iridescence(a[13], ThinFilm::new(a[14], a[15])?)?
        .with_transmission(a[16])?
        .with_volume(Volume::new(a[17], v3(a[18], a[19], a[20]), a[21])?))
}

/// The outputs of choice `k` in the lanes where `x` equals `k`, for each of `n` choices; NaN
/// in lanes holding no valid choice. On lanes each choice is evaluated on all lanes and
/// selected, so every lane runs the lane type's own code.
fn pick<T: Real, const N: usize>(x: T, n: usize, f: impl Fn(usize) -> [T; N]) -> [T; N] {
    let mut acc = nan::<T, N>();
    for k in 0..n {
        #[allow(clippy::cast_precision_loss)]
        let m = x.simd_eq(T::splat(k as f64));
        if m.any() {
            let r = f(k);
            for (a, v) in acc.iter_mut().zip(r) {
                *a = T::select(m, v, *a);
            }
        }
    }
    acc
}

fn v3<T: Real>(x: T, y: T, z: T) -> V3<T> {
    V3::new(x, y, z)
}

fn o3<T: Real>(v: V3<T>) -> [T; 3] {
    [v.x, v.y, v.z]
}

fn o4<T: Real>((w, p): (V3<T>, T)) -> [T; 4] {
    [w.x, w.y, w.z, p]
}

/// One table entry: `kernel!("path", "summary", [arg: DOMAIN, ...] -> [out: RANGE, ...],
/// where [constraints], |args...| [outputs...])`, where the body is generic over `T: Real`
/// and names the arguments as declared; `where [...]` is optional, and a leading `lanewise`
/// evaluates lanes one at a time (kernels with `f64` parameters).
macro_rules! kernel {
    (lanewise $($rest:tt)*) => { kernel!(@go true, $($rest)*) };
    (@go $lw:literal, $path:literal, $summary:literal,
     [$($arg:ident : $dom:expr),* $(,)?] -> [$($out:ident : $range:expr),* $(,)?],
     $(where [$($c:expr),* $(,)?],)?
     $body:expr) => {{
        const NA: usize = <[&str]>::len(&[$(stringify!($arg)),*]);
        const NO: usize = <[&str]>::len(&[$(stringify!($out)),*]);
        #[allow(
            unused_variables,
            unused_mut,
            clippy::too_many_arguments,
            clippy::many_single_char_names
        )]
        #[inline]
        fn arr<T: Real>(a: [T; NA]) -> [T; NO] {
            let [$($arg),*] = a;
            $body
        }
        fn body<T: Real>(x: &[T], y: &mut [T]) {
            let mut a = [T::splat(f64::NAN); NA];
            for (ai, v) in a.iter_mut().zip(x) {
                *ai = *v;
            }
            let r = arr(a);
            for (o, v) in y.iter_mut().zip(r) {
                *o = v;
            }
        }
        #[inline]
        fn group<T: Real>(a: [T; NA]) -> [T; NO] {
            if $lw {
                let mut y = [T::ZERO; NO];
                lanewise(&a, &mut y, body::<T>);
                y
            } else {
                arr(a)
            }
        }
        fn arrays<L: Lanes>(ins: &[&[L::Scalar]], outs: &mut [&mut [L::Scalar]], n: usize) -> bool {
            over_arrays(ins, outs, n, group::<L>, eval::<L>)
        }
        fn eval<T: Real>(x: &[T], y: &mut [T]) {
            if $lw {
                lanewise(x, y, body::<T>);
            } else {
                body(x, y);
            }
        }
        Kernel {
            path: $path,
            args: &[$(Arg { name: stringify!($arg), domain: $dom }),*],
            outputs: &[$(Output { name: stringify!($out), range: $range }),*],
            summary: $summary,
            constraints: &[$($($c),*)?],
            f32: eval::<f32>,
            f64: eval::<f64>,
            f32x8: eval::<f32x8>,
            f64x4: eval::<f64x4>,
            f32_arrays: arrays::<f32x8>,
            f64_arrays: arrays::<f64x4>,
        }
    }};
    ($path:literal, $($rest:tt)*) => { kernel!(@go false, $path, $($rest)*) };
}

/// `a <= b` between two named arguments.
macro_rules! le {
    ($a:literal, $b:literal, $text:literal) => {
        Constraint::Holds {
            text: $text,
            args: &[$a, $b],
            check: |v| v.get($a) <= v.get($b),
        }
    };
}

use brdf::beckmann::{self, Beckmann};
use brdf::diffuse;
use brdf::engine;
use brdf::frame::{self, Frame};
use brdf::ggx::{self, Ggx};
use brdf::ibl::{dfg, energy, irradiance, prefilter};
use brdf::iridescence::{self, ThinFilm};
use brdf::layers::layered::Layered;
use brdf::layers::{anisotropy, clearcoat, sheen, specular};
use brdf::material::{self, DiffuseCoupling, MetallicRoughness};
use brdf::microfacet::{self, Microfacet};
use brdf::rough_dielectric::{self, Transport};
use brdf::tonemap::{self, AgxLook, HableParams, LottesParams, Operator, UchimuraParams};
use brdf::transmission::{self, Transmission, Volume};
use brdf::{color, cook_torrance, fresnel, lights, phong, sampling};

/// The [`Cosines`] of four flattened arguments.
fn cosines<T: Real>(n_dot_v: T, n_dot_l: T, n_dot_h: T, v_dot_h: T) -> Cosines<T> {
    Cosines {
        n_dot_v,
        n_dot_l,
        n_dot_h,
        v_dot_h,
    }
}

/// Both distributions on the same alphas, for kernels generic over `Microfacet`: choice
/// `model` of [`MODEL`] evaluated through `f`, NaN if the alphas are out of their domain.
fn with_model<T: Real, const N: usize>(
    model: T,
    alpha_x: T,
    alpha_y: T,
    f: impl Fn(&dyn Microfacet<T>) -> [T; N],
) -> [T; N] {
    pick(model, 2, |k| {
        if k == 0 {
            built(Ggx::new(alpha_x, alpha_y), |g| f(&g))
        } else {
            built(Beckmann::new(alpha_x, alpha_y), |b| f(&b))
        }
    })
}

/// The transport of choice `k` of [`TRANSPORT`].
fn transport_of(k: usize) -> Transport {
    [Transport::Radiance, Transport::Importance][k]
}

/// The AgX look of choice `k` of [`LOOK`].
fn look(k: usize) -> AgxLook {
    [
        AgxLook::BASE,
        AgxLook::PUNCHY,
        AgxLook::GOLDEN,
        AgxLook::GOLDEN_FILAMENT,
    ][k]
}

/// The diffuse coupling of choice `k` of [`COUPLING`].
fn coupling(k: usize) -> DiffuseCoupling {
    [
        DiffuseCoupling::Gltf,
        DiffuseCoupling::OneMinusF,
        DiffuseCoupling::Additive,
    ][k]
}

/// A `Sh9` from 27 coefficient arguments (nine RGB triples in [`irradiance::sh9_basis`]'s
/// order).
fn sh9<T: Real>(c: &[T]) -> irradiance::Sh9<T> {
    irradiance::Sh9::from_coeffs(core::array::from_fn(|k| {
        V3::new(c[3 * k], c[3 * k + 1], c[3 * k + 2])
    }))
}

/// Every public scalar kernel of `brdf`, by path.
pub static KERNELS: &[Kernel] = &[
    // ---------------------------------------------------------------- frame
    kernel!(
        "frame::Frame::from_normal",
        "Orthonormal basis (t, b, n) from a unit normal, Duff et al. 2017 (JCGT 6(1))",
        [n_x: Domain::DIR, n_y: Domain::DIR, n_z: Domain::DIR]
            -> [tangent_x: Domain::DIR_OUT, tangent_y: Domain::DIR_OUT, tangent_z: Domain::DIR_OUT,
                bitangent_x: Domain::DIR_OUT, bitangent_y: Domain::DIR_OUT,
                bitangent_z: Domain::DIR_OUT,
                normal_x: Domain::DIR_OUT, normal_y: Domain::DIR_OUT, normal_z: Domain::DIR_OUT],
        {
            let f = Frame::from_normal(v3(n_x, n_y, n_z));
            [f.t.x, f.t.y, f.t.z, f.b.x, f.b.y, f.b.z, f.n.x, f.n.y, f.n.z]
        }
    ),
    kernel!(
        "frame::Frame::to_local",
        "World direction v in the frame of the normal n, (v.t, v.b, v.n), Duff et al. 2017",
        [n_x: Domain::DIR, n_y: Domain::DIR, n_z: Domain::DIR,
         v_x: Domain::DIR, v_y: Domain::DIR, v_z: Domain::DIR]
            -> [local_x: Domain::DIR_OUT, local_y: Domain::DIR_OUT, local_z: Domain::DIR_OUT],
        o3(Frame::from_normal(v3(n_x, n_y, n_z)).to_local(v3(v_x, v_y, v_z)))
    ),
    kernel!(
        "frame::Frame::to_world",
        "Local direction v back to world space, v.x t + v.y b + v.z n, Duff et al. 2017",
        [n_x: Domain::DIR, n_y: Domain::DIR, n_z: Domain::DIR,
         v_x: Domain::DIR, v_y: Domain::DIR, v_z: Domain::DIR]
            -> [world_x: Domain::DIR_OUT, world_y: Domain::DIR_OUT, world_z: Domain::DIR_OUT],
        o3(Frame::from_normal(v3(n_x, n_y, n_z)).to_world(v3(v_x, v_y, v_z)))
    ),
    kernel!(
        "frame::cos_theta",
        "cos(theta) = w.z of a local direction, pbrt-v4 (Pharr et al. 2023) CosTheta",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [cos_theta: Domain::COS],
        [frame::cos_theta(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::cos2_theta",
        "cos^2(theta) = w.z^2 of a local direction, pbrt-v4 (Pharr et al. 2023) Cos2Theta",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [cos2_theta: Domain::UNIT],
        [frame::cos2_theta(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::abs_cos_theta",
        "|cos(theta)| of a local direction, pbrt-v4 (Pharr et al. 2023) AbsCosTheta",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [abs_cos_theta: Domain::UNIT],
        [frame::abs_cos_theta(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::sin2_theta",
        "sin^2(theta) = x^2 + y^2 of a unit local direction, pbrt-v4 (Pharr et al. 2023) Sin2Theta",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [sin2_theta: Domain::NONNEG],
        [frame::sin2_theta(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::sin_theta",
        "sin(theta) = sqrt(x^2 + y^2) of a unit local direction, pbrt-v4 (Pharr et al. 2023) \
         SinTheta",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [sin_theta: Domain::NONNEG],
        [frame::sin_theta(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::tan2_theta",
        "tan^2(theta) of a unit local direction, +inf at the horizon, pbrt-v4 (Pharr et al. \
         2023) Tan2Theta",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [tan2_theta: Domain::NONNEG_INF],
        [frame::tan2_theta(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::cos_phi",
        "cos(phi) = x / sin(theta), clamped, 1 at the pole, pbrt-v4 (Pharr et al. 2023) CosPhi",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [cos_phi: Domain::COS],
        [frame::cos_phi(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::sin_phi",
        "sin(phi) = y / sin(theta), clamped, 0 at the pole, pbrt-v4 (Pharr et al. 2023) SinPhi",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [sin_phi: Domain::COS],
        [frame::sin_phi(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "frame::spherical_direction",
        "Unit direction (sin t cos p, sin t sin p, cos t) from spherical angles, pbrt-v4 \
         SphericalDirection",
        [theta: Domain::FINITE, phi: Domain::FINITE]
            -> [w_x: Domain::DIR_OUT, w_y: Domain::DIR_OUT, w_z: Domain::DIR_OUT],
        o3(frame::spherical_direction(theta, phi))
    ),
    // ---------------------------------------------------------------- vec3
    kernel!(
        "vec3::V3::dot",
        "Dot product x1 x2 + y1 y2 + z1 z2 (fused where the target has FMA)",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT,
         o_x: COMPONENT, o_y: COMPONENT, o_z: COMPONENT] -> [dot: Domain::FINITE],
        [v3(self_x, self_y, self_z).dot(v3(o_x, o_y, o_z))]
    ),
    kernel!(
        "vec3::V3::cross",
        "Cross product of two vectors",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT,
         o_x: COMPONENT, o_y: COMPONENT, o_z: COMPONENT]
            -> [cross_x: Domain::FINITE, cross_y: Domain::FINITE, cross_z: Domain::FINITE],
        o3(v3(self_x, self_y, self_z).cross(v3(o_x, o_y, o_z)))
    ),
    kernel!(
        "vec3::V3::length_squared",
        "Squared Euclidean length x^2 + y^2 + z^2",
        [self_x: COMPONENT, self_y: COMPONENT,
         self_z: COMPONENT] -> [length_squared: Domain::NONNEG],
        [v3(self_x, self_y, self_z).length_squared()]
    ),
    kernel!(
        "vec3::V3::length",
        "Euclidean length sqrt(x^2 + y^2 + z^2)",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT] -> [length: Domain::NONNEG],
        [v3(self_x, self_y, self_z).length()]
    ),
    kernel!(
        "vec3::V3::normalize_or",
        "v / |v|, or the fallback where |v| is 0 or infinite",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT,
         fallback_x: COMPONENT, fallback_y: COMPONENT, fallback_z: COMPONENT]
            -> [out_x: Domain::FINITE, out_y: Domain::FINITE, out_z: Domain::FINITE],
        o3(v3(self_x, self_y, self_z).normalize_or(v3(fallback_x, fallback_y, fallback_z)))
    ),
    kernel!(
        "vec3::V3::normalize",
        "v / |v| through v / max|v_i| (no overflow or underflow); the zero vector for v = 0",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT]
            -> [out_x: Domain::DIR, out_y: Domain::DIR, out_z: Domain::DIR],
        o3(v3(self_x, self_y, self_z).normalize())
    ),
    kernel!(
        "vec3::V3::mirror",
        "Mirror 2 (v.n) n - v of v about the unit normal n (pbrt-v4 Reflect, not GLSL reflect)",
        [self_x: Domain::DIR, self_y: Domain::DIR, self_z: Domain::DIR,
         n_x: Domain::DIR, n_y: Domain::DIR, n_z: Domain::DIR]
            -> [out_x: Domain::DIR_OUT, out_y: Domain::DIR_OUT, out_z: Domain::DIR_OUT],
        o3(v3(self_x, self_y, self_z).mirror(v3(n_x, n_y, n_z)))
    ),
    kernel!(
        "vec3::V3::min",
        "Component-wise minimum (a NaN in self propagates, in o is ignored)",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT,
         o_x: COMPONENT, o_y: COMPONENT, o_z: COMPONENT]
            -> [out_x: Domain::FINITE, out_y: Domain::FINITE, out_z: Domain::FINITE],
        o3(v3(self_x, self_y, self_z).min(v3(o_x, o_y, o_z)))
    ),
    kernel!(
        "vec3::V3::max",
        "Component-wise maximum (a NaN in self propagates, in o is ignored)",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT,
         o_x: COMPONENT, o_y: COMPONENT, o_z: COMPONENT]
            -> [out_x: Domain::FINITE, out_y: Domain::FINITE, out_z: Domain::FINITE],
        o3(v3(self_x, self_y, self_z).max(v3(o_x, o_y, o_z)))
    ),
    kernel!(
        "vec3::V3::abs",
        "Component-wise absolute value",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT]
            -> [out_x: Domain::NONNEG, out_y: Domain::NONNEG, out_z: Domain::NONNEG],
        o3(v3(self_x, self_y, self_z).abs())
    ),
    kernel!(
        "vec3::V3::min_element",
        "Smallest component (NaN if any is NaN)",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT] -> [min: Domain::FINITE],
        [v3(self_x, self_y, self_z).min_element()]
    ),
    kernel!(
        "vec3::V3::max_element",
        "Largest component, the peak of a colour (NaN if any is NaN)",
        [self_x: COMPONENT, self_y: COMPONENT, self_z: COMPONENT] -> [max: Domain::FINITE],
        [v3(self_x, self_y, self_z).max_element()]
    ),
    // ---------------------------------------------------------------- fresnel
    kernel!(
        "fresnel::f0_from_ior",
        "Normal-incidence reflectance ((eta - 1) / (eta + 1))^2, Fresnel's equations at theta = 0",
        [eta: ETA] -> [f0: Domain::UNIT],
        [fresnel::f0_from_ior(eta)]
    ),
    kernel!(
        "fresnel::ior_from_f0",
        "IOR (1 + sqrt(F0)) / (1 - sqrt(F0)) of a normal-incidence reflectance, capped at MAX",
        [f0: Domain::UNIT] -> [eta: Domain::new(1.0, false, f64::INFINITY, true, "[1, MAX]")],
        [fresnel::ior_from_f0(f0)]
    ),
    kernel!(
        "fresnel::schlick",
        "Schlick's Fresnel F0 + (1 - F0)(1 - c)^5, Schlick 1994 eq. 15",
        [f0: Domain::UNIT, v_dot_h: Domain::COS] -> [f: Domain::UNIT],
        [fresnel::schlick(f0, v_dot_h)]
    ),
    kernel!(
        "fresnel::schlick_f90",
        "Schlick's Fresnel with a grazing value, F0 + (F90 - F0)(1 - c)^5, Schlick 1994; Burley \
         2012",
        [f0: Domain::FINITE, f90: Domain::FINITE, v_dot_h: Domain::COS] -> [f: Domain::FINITE],
        [fresnel::schlick_f90(f0, f90, v_dot_h)]
    ),
    kernel!(
        "fresnel::schlick_rgb",
        "Schlick's Fresnel for an RGB F0, Schlick 1994 eq. 15",
        [f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT, v_dot_h: Domain::COS]
            -> [f_r: Domain::UNIT, f_g: Domain::UNIT, f_b: Domain::UNIT],
        o3(fresnel::schlick_rgb(v3(f0_r, f0_g, f0_b), v_dot_h))
    ),
    kernel!(
        "fresnel::schlick_f90_rgb",
        "Schlick's Fresnel for RGB F0 and F90, Schlick 1994; Burley 2012",
        [f0_r: Domain::FINITE, f0_g: Domain::FINITE, f0_b: Domain::FINITE,
         f90_r: Domain::FINITE, f90_g: Domain::FINITE, f90_b: Domain::FINITE, v_dot_h: Domain::COS]
            -> [f_r: Domain::FINITE, f_g: Domain::FINITE, f_b: Domain::FINITE],
        o3(fresnel::schlick_f90_rgb(v3(f0_r, f0_g, f0_b), v3(f90_r, f90_g, f90_b), v_dot_h))
    ),
    kernel!(
        "fresnel::schlick_sg",
        "Schlick's Fresnel with the spherical-Gaussian exp2 power fit, Karis 2013",
        [f0: Domain::UNIT, v_dot_h: Domain::COS] -> [f: Domain::UNIT],
        [fresnel::schlick_sg(f0, v_dot_h)]
    ),
    kernel!(
        "fresnel::dielectric_polarized",
        "s- and p-polarized dielectric reflectances (Rs, Rp), Fresnel 1823; Born and Wolf 1.5",
        [cos_theta_i: Domain::COS, eta: ETA] -> [rs: Domain::UNIT, rp: Domain::UNIT],
        {
            let (rs, rp) = fresnel::dielectric_polarized(cos_theta_i, eta);
            [rs, rp]
        }
    ),
    kernel!(
        "fresnel::dielectric",
        "Exact unpolarized dielectric Fresnel reflectance, Born and Wolf 1.5.2",
        [cos_theta_i: Domain::COS, eta: ETA] -> [f: Domain::UNIT],
        [fresnel::dielectric(cos_theta_i, eta)]
    ),
    kernel!(
        "fresnel::dielectric_fast",
        "Dielectric Fresnel in working precision, Born and Wolf 1.5.2",
        [cos_theta_i: Domain::COS, eta: ETA] -> [f: Domain::UNIT],
        [fresnel::dielectric_fast(cos_theta_i, eta)]
    ),
    kernel!(
        "fresnel::conductor",
        "Exact unpolarized conductor Fresnel reflectance of eta + i k, Born and Wolf 14.2",
        [cos_theta_i: Domain::COS, eta: ETA, k: KAPPA] -> [f: Domain::UNIT],
        [fresnel::conductor(cos_theta_i, eta, k)]
    ),
    kernel!(
        "fresnel::conductor_fast",
        "Conductor Fresnel in working precision, Born and Wolf 14.2; Lagarde 2013",
        [cos_theta_i: Domain::COS, eta: ETA, k: KAPPA] -> [f: Domain::UNIT],
        [fresnel::conductor_fast(cos_theta_i, eta, k)]
    ),
    kernel!(
        "fresnel::conductor_rgb",
        "Exact conductor Fresnel per channel for RGB eta and k, Born and Wolf 14.2",
        [cos_theta_i: Domain::COS, eta_r: ETA, eta_g: ETA, eta_b: ETA,
         k_r: KAPPA, k_g: KAPPA, k_b: KAPPA]
            -> [f_r: Domain::UNIT, f_g: Domain::UNIT, f_b: Domain::UNIT],
        o3(fresnel::conductor_rgb(cos_theta_i, v3(eta_r, eta_g, eta_b), v3(k_r, k_g, k_b)))
    ),
    kernel!(
        "fresnel::schlick_f82",
        "Generalized Schlick with an F82 tint for metals, Hoffman 2019; Kutz et al. 2021",
        [f0: Domain::UNIT, f82_tint: Domain::UNIT, cos_theta: Domain::COS] -> [f: Domain::UNIT],
        [fresnel::schlick_f82(f0, f82_tint, cos_theta)]
    ),
    kernel!(
        "fresnel::schlick_f82_rgb",
        "Schlick with an F82 tint per channel for RGB F0 and tint, Hoffman 2019; Kutz et al. 2021",
        [f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT,
         f82_tint_r: Domain::UNIT, f82_tint_g: Domain::UNIT, f82_tint_b: Domain::UNIT,
         cos_theta: Domain::COS]
            -> [f_r: Domain::UNIT, f_g: Domain::UNIT, f_b: Domain::UNIT],
        o3(fresnel::schlick_f82_rgb(
            v3(f0_r, f0_g, f0_b),
            v3(f82_tint_r, f82_tint_g, f82_tint_b),
            cos_theta,
        ))
    ),
    kernel!(
        lanewise "fresnel::average_dielectric",
        "Hemispherical average of the dielectric Fresnel term by quadrature (f64), Kulla and \
         Conty 2017",
        [eta: ETA] -> [f_avg: Domain::UNIT],
        [T::splat(fresnel::average_dielectric(f64_of(eta)))]
    ),
    kernel!(
        "fresnel::average_dielectric_fit",
        "Rational fit of the dielectric Fresnel average, Kulla and Conty 2017",
        [eta: ETA] -> [f_avg: Domain::UNIT],
        [fresnel::average_dielectric_fit(eta)]
    ),
    // ---------------------------------------------------------------- microfacet
    kernel!(
        "microfacet::alpha_from_perceptual",
        "alpha = r^2 from perceptual roughness, clamped to [ALPHA_MIN, ALPHA_MAX], Burley 2012; \
         Karis 2013",
        [roughness: Domain::NONNEG]
            -> [alpha: Domain::closed(microfacet::ALPHA_MIN, microfacet::ALPHA_MAX, "[ALPHA_MIN,
                ALPHA_MAX]")],
        [microfacet::alpha_from_perceptual(roughness)]
    ),
    kernel!(
        "microfacet::perceptual_from_alpha",
        "Perceptual roughness r = sqrt(alpha), Burley 2012; Karis 2013",
        [alpha: Domain::NONNEG] -> [roughness: Domain::NONNEG],
        [microfacet::perceptual_from_alpha(alpha)]
    ),
    // ---------------------------------------------------------------- ggx
    kernel!(
        "ggx::d",
        "GGX (Trowbridge-Reitz) NDF D(m), Walter et al. 2007 eq. 33",
        [n_dot_h: Domain::COS, alpha: ALPHA] -> [d: Domain::NONNEG],
        [ggx::d(n_dot_h, alpha)]
    ),
    kernel!(
        "ggx::d_fast",
        "GGX NDF in working precision (within 7 ULP of ggx::d, f32), Walter et al. 2007 eq. 33",
        [n_dot_h: Domain::COS, alpha: ALPHA] -> [d: Domain::NONNEG],
        [ggx::d_fast(n_dot_h, alpha)]
    ),
    kernel!(
        "ggx::d_aniso",
        "Anisotropic GGX NDF from the half vector's frame components, Heitz 2014 eq. 85; Burley \
         2012",
        [n_dot_h: Domain::DIR, t_dot_h: Domain::DIR, b_dot_h: Domain::DIR, alpha_x: ALPHA,
         alpha_y: ALPHA]
            -> [d: Domain::NONNEG],
        where [Constraint::UnitVector(["t_dot_h", "b_dot_h", "n_dot_h"])],
        [ggx::d_aniso(n_dot_h, t_dot_h, b_dot_h, alpha_x, alpha_y)]
    ),
    kernel!(
        "ggx::lambda",
        "GGX Smith Lambda (sqrt(1 + alpha^2 tan^2) - 1) / 2, Heitz 2014 eq. 86",
        [n_dot_v: Domain::COS, alpha: ALPHA] -> [lambda: Domain::NONNEG],
        [ggx::lambda(n_dot_v, alpha)]
    ),
    kernel!(
        "ggx::g1",
        "GGX Smith masking G1 = 1 / (1 + Lambda), Walter et al. 2007 eq. 34",
        [n_dot_v: Domain::COS, alpha: ALPHA] -> [g1: Domain::UNIT],
        [ggx::g1(n_dot_v, alpha)]
    ),
    kernel!(
        "ggx::v_correlated",
        "GGX height-correlated Smith visibility G2 / (4 NoL NoV), Heitz 2014 eq. 99; Lagarde and \
         de Rousiers 2014",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, alpha: ALPHA] -> [v: Domain::NONNEG],
        [ggx::v_correlated(n_dot_v, n_dot_l, alpha)]
    ),
    kernel!(
        "ggx::v_correlated_hammon",
        "Hammon's approximation of the GGX correlated visibility, Hammon 2017",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, alpha: ALPHA] -> [v: Domain::NONNEG],
        [ggx::v_correlated_hammon(n_dot_v, n_dot_l, alpha)]
    ),
    kernel!(
        "ggx::v_correlated_fast",
        "Filament's fast GGX correlated visibility (V_SmithGGXCorrelated_Fast), Guy and Agopian \
         2018",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, alpha: ALPHA] -> [v: Domain::NONNEG],
        [ggx::v_correlated_fast(n_dot_v, n_dot_l, alpha)]
    ),
    kernel!(
        "ggx::g1_schlick",
        "Schlick's G1 approximation c / (c (1 - k) + k), Schlick 1994; Karis 2013",
        [n_dot_v: Domain::COS, k: Domain::POSITIVE] -> [g1: Domain::UNIT],
        [ggx::g1_schlick(n_dot_v, k)]
    ),
    kernel!(
        "ggx::schlick_k_ibl",
        "Schlick-GGX k = alpha / 2 for image-based lighting, Karis 2013",
        [alpha: ALPHA] -> [k: Domain::closed(5e-5, 5e3, "[5e-5, 5e3]")],
        [ggx::schlick_k_ibl(alpha)]
    ),
    kernel!(
        "ggx::schlick_k_analytic",
        "Schlick-GGX k = (r + 1)^2 / 8 for analytic lights, Karis 2013",
        [perceptual_roughness: Domain::new(0.0, false, f64::INFINITY, true, "[0, +inf) finite,
         clamped to 100")]
            -> [k: Domain::closed(0.125, 1275.125, "[1/8, 101^2/8]")],
        [ggx::schlick_k_analytic(perceptual_roughness)]
    ),
    kernel!(
        "ggx::v_schlick",
        "Separable Schlick-GGX visibility 1 / (4 (NoV (1 - k) + k)(NoL (1 - k) + k)), Schlick \
         1994; Karis 2013",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, k: Domain::POSITIVE] -> [v: Domain::NONNEG],
        [ggx::v_schlick(n_dot_v, n_dot_l, k)]
    ),
    kernel!(
        "ggx::Ggx::d",
        "Anisotropic GGX NDF D(m) on a local-frame normal, Walter et al. 2007 eq. 33; Heitz 2014 \
         eq. 85",
        [alpha_x: ALPHA, alpha_y: ALPHA, m_x: Domain::DIR, m_y: Domain::DIR, m_z: Domain::DIR]
            -> [d: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| [g.d(v3(m_x, m_y, m_z))])
    ),
    kernel!(
        "ggx::Ggx::lambda",
        "Anisotropic GGX Smith Lambda(w), Heitz 2014 eq. 86",
        [alpha_x: ALPHA, alpha_y: ALPHA, w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR]
            -> [lambda: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| [g.lambda(v3(w_x, w_y, w_z))])
    ),
    kernel!(
        "ggx::Ggx::cos_lambda",
        "|w.z| Lambda(w) of anisotropic GGX, finite at the horizon, Heitz 2014 eq. 86",
        [alpha_x: ALPHA, alpha_y: ALPHA, w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR]
            -> [cos_lambda: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| [g.cos_lambda(v3(w_x, w_y, w_z))])
    ),
    kernel!(
        "ggx::Ggx::g1",
        "Anisotropic GGX Smith masking G1(w), Walter et al. 2007 eq. 34; Heitz 2014 eq. 43",
        [alpha_x: ALPHA, alpha_y: ALPHA, w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR]
            -> [g1: Domain::UNIT],
        built(Ggx::new(alpha_x, alpha_y), |g| [g.g1(v3(w_x, w_y, w_z))])
    ),
    kernel!(
        "ggx::Ggx::g2_correlated",
        "GGX height-correlated masking-shadowing 1 / (1 + Lo + Li), Heitz 2014 eq. 99",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [g2: Domain::UNIT],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            [g.g2_correlated(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "ggx::Ggx::g2_separable",
        "GGX separable masking-shadowing G1(wo) G1(wi), Heitz 2014 eq. 98",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [g2: Domain::UNIT],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            [g.g2_separable(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "ggx::Ggx::v_correlated",
        "GGX height-correlated visibility G2 / (4 |wo.z| |wi.z|) on vectors, Heitz 2014 eq. 99",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [v: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            [g.v_correlated(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "ggx::Ggx::d_visible",
        "GGX distribution of visible normals G1(wo) max(0, wo.m) D(m) / |wo.z|, Heitz 2014 eq. 38",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         m_x: Domain::DIR, m_y: Domain::DIR, m_z: Domain::DIR] -> [d_visible: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            [g.d_visible(v3(wo_x, wo_y, wo_z), v3(m_x, m_y, m_z))]
        })
    ),
    // ---------------------------------------------------------------- beckmann
    kernel!(
        "beckmann::d",
        "Beckmann NDF exp(-tan^2 / alpha^2) / (pi alpha^2 c^4), Walter et al. 2007 eq. 25",
        [n_dot_h: Domain::COS, alpha: ALPHA] -> [d: Domain::NONNEG],
        [beckmann::d(n_dot_h, alpha)]
    ),
    kernel!(
        "beckmann::d_fast",
        "Beckmann NDF in working precision, no subnormal intermediate, Walter et al. 2007 eq. 25",
        [n_dot_h: Domain::COS, alpha: ALPHA] -> [d: Domain::NONNEG],
        [beckmann::d_fast(n_dot_h, alpha)]
    ),
    kernel!(
        "beckmann::a_of",
        "Beckmann Smith argument a = 1 / (alpha tan(theta)), Walter et al. 2007 eq. 27",
        [n_dot_v: Domain::COS, alpha: ALPHA] -> [a: Domain::NONNEG],
        [beckmann::a_of(n_dot_v, alpha)]
    ),
    kernel!(
        "beckmann::lambda",
        "Exact Beckmann Smith Lambda (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, Heitz 2014 eq. 83",
        [n_dot_v: Domain::COS, alpha: ALPHA] -> [lambda: Domain::NONNEG],
        [beckmann::lambda(n_dot_v, alpha)]
    ),
    kernel!(
        "beckmann::g1",
        "Beckmann Smith masking G1 = 1 / (1 + Lambda), Walter et al. 2007 eq. 27",
        [n_dot_v: Domain::COS, alpha: ALPHA] -> [g1: Domain::UNIT],
        [beckmann::g1(n_dot_v, alpha)]
    ),
    kernel!(
        "beckmann::lambda_walter",
        "Walter et al.'s rational approximation of the Beckmann Lambda, Walter et al. 2007 eq. 27",
        [n_dot_v: Domain::COS, alpha: ALPHA] -> [lambda: Domain::NONNEG],
        [beckmann::lambda_walter(n_dot_v, alpha)]
    ),
    kernel!(
        "beckmann::alpha_from_blinn_phong",
        "Beckmann alpha = sqrt(2 / (n + 2)) of a Blinn-Phong exponent, Walter et al. 2007 \
         section 5.2",
        [exponent: EXPONENT] -> [alpha: Domain::UNIT],
        [beckmann::alpha_from_blinn_phong(exponent)]
    ),
    kernel!(
        "beckmann::blinn_phong_from_alpha",
        "Blinn-Phong exponent n = 2 / alpha^2 - 2 of a Beckmann alpha, clamped at 0, Walter et \
         al. 2007",
        [alpha: ALPHA] -> [exponent: Domain::NONNEG],
        [beckmann::blinn_phong_from_alpha(alpha)]
    ),
    kernel!(
        "beckmann::Beckmann::d",
        "Anisotropic Beckmann NDF D(m) on a local-frame normal, Walter et al. 2007 eq. 25; Heitz \
         2014 eq. 80",
        [alpha_x: ALPHA, alpha_y: ALPHA, m_x: Domain::DIR, m_y: Domain::DIR, m_z: Domain::DIR]
            -> [d: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |g| [g.d(v3(m_x, m_y, m_z))])
    ),
    kernel!(
        "beckmann::Beckmann::lambda",
        "Anisotropic Beckmann exact Smith Lambda(w), Heitz 2014 eq. 83",
        [alpha_x: ALPHA, alpha_y: ALPHA, w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR]
            -> [lambda: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |g| [g.lambda(v3(w_x, w_y, w_z))])
    ),
    kernel!(
        "beckmann::Beckmann::cos_lambda",
        "|w.z| Lambda(w) of anisotropic Beckmann, finite at the horizon, Heitz 2014 eq. 83",
        [alpha_x: ALPHA, alpha_y: ALPHA, w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR]
            -> [cos_lambda: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |g| [g.cos_lambda(v3(w_x, w_y, w_z))])
    ),
    kernel!(
        "beckmann::Beckmann::g1",
        "Anisotropic Beckmann Smith masking G1(w), Heitz 2014 eqs. 43 and 83",
        [alpha_x: ALPHA, alpha_y: ALPHA, w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR]
            -> [g1: Domain::UNIT],
        built(Beckmann::new(alpha_x, alpha_y), |g| [g.g1(v3(w_x, w_y, w_z))])
    ),
    kernel!(
        "beckmann::Beckmann::g2_correlated",
        "Beckmann height-correlated masking-shadowing 1 / (1 + Lo + Li), Heitz 2014 eq. 99",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [g2: Domain::UNIT],
        built(Beckmann::new(alpha_x, alpha_y), |g| {
            [g.g2_correlated(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "beckmann::Beckmann::g2_separable",
        "Beckmann separable masking-shadowing G1(wo) G1(wi), Heitz 2014 eq. 98",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [g2: Domain::UNIT],
        built(Beckmann::new(alpha_x, alpha_y), |g| {
            [g.g2_separable(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "beckmann::Beckmann::v_correlated",
        "Beckmann height-correlated visibility G2 / (4 |wo.z| |wi.z|), Heitz 2014 eq. 99",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [v: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |g| {
            [g.v_correlated(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "beckmann::Beckmann::d_visible",
        "Beckmann distribution of visible normals G1(wo) max(0, wo.m) D(m) / |wo.z|, Heitz 2014 \
         eq. 38",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         m_x: Domain::DIR, m_y: Domain::DIR, m_z: Domain::DIR] -> [d_visible: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |g| {
            [g.d_visible(v3(wo_x, wo_y, wo_z), v3(m_x, m_y, m_z))]
        })
    ),
    // ---------------------------------------------------------------- cook_torrance
    kernel!(
        "cook_torrance::half_vector",
        "Half vector normalize(wo + wi) and v.h (normal where wo = -wi), Walter et al. 2007",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR]
            -> [h_x: Domain::DIR_OUT, h_y: Domain::DIR_OUT, h_z: Domain::DIR_OUT,
                v_dot_h: Domain::COS],
        {
            let (h, c) = cook_torrance::half_vector(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z));
            [h.x, h.y, h.z, c]
        }
    ),
    kernel!(
        "cook_torrance::half_cosines",
        "n.h = s.z / |s| and v.h = |s| / 2 for s = wo + wi without forming h, Walter et al. 2007",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR]
            -> [n_dot_h: Domain::COS, v_dot_h: Domain::UNIT],
        {
            let (nh, vh) = cook_torrance::half_cosines(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z));
            [nh, vh]
        }
    ),
    kernel!(
        "cook_torrance::eval",
        "Cook-Torrance D(h) V(wo, wi) F with a constant F, Cook and Torrance 1982; Heitz 2014 \
         eq. 99",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR,
         fresnel: Domain::new(0.0, false, f64::INFINITY, true, "F >= 0,
         finite (the closure's constant)")]
            -> [f: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |m| {
            [cook_torrance::eval(m, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), |_| fresnel)]
        })
    ),
    kernel!(
        "cook_torrance::dielectric",
        "Cook-Torrance with the exact dielectric Fresnel, Cook and Torrance 1982; Born and Wolf \
         1.5",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, eta: ETA]
            -> [f: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |m| {
            [cook_torrance::dielectric(m, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), eta)]
        })
    ),
    kernel!(
        "cook_torrance::conductor",
        "Cook-Torrance with the exact conductor Fresnel, Cook and Torrance 1982; Born and Wolf \
         14.2",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, eta: ETA, k: KAPPA]
            -> [f: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |m| {
            [cook_torrance::conductor(m, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), eta, k)]
        })
    ),
    kernel!(
        "cook_torrance::eval_rgb",
        "Cook-Torrance D V F with a constant RGB F, Cook and Torrance 1982; Heitz 2014 eq. 99",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR,
         fresnel_r: Domain::NONNEG, fresnel_g: Domain::NONNEG, fresnel_b: Domain::NONNEG]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |m| {
            o3(cook_torrance::eval_rgb(m, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), |_| {
                v3(fresnel_r, fresnel_g, fresnel_b)
            }))
        })
    ),
    kernel!(
        "cook_torrance::ggx",
        "GGX Cook-Torrance D V F from dot products and a given F, Walter et al. 2007; Heitz 2014",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA,
         fresnel: Domain::new(0.0, false, f64::INFINITY, true, "F >= 0, finite")]
            -> [f: Domain::NONNEG],
        [cook_torrance::ggx(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), fresnel)]
    ),
    kernel!(
        "cook_torrance::beckmann",
        "Beckmann Cook-Torrance D G2 F / (4 NoL NoV) from dot products, Walter et al. 2007; \
         Heitz 2014",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA,
         fresnel: Domain::new(0.0, false, f64::INFINITY, true, "F >= 0, finite")]
            -> [f: Domain::NONNEG],
        [cook_torrance::beckmann(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), fresnel)]
    ),
    kernel!(
        "cook_torrance::ggx_conductor_rgb",
        "Rough conductor, GGX, RGB exact conductor Fresnel, Cook and Torrance 1982; Born and \
         Wolf 14.2",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, eta_r: ETA, eta_g: ETA, eta_b: ETA, k_r: KAPPA, k_g: KAPPA, k_b: KAPPA]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(cook_torrance::ggx_conductor_rgb(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), ComplexIor { eta: v3(eta_r, eta_g, eta_b), k: v3(k_r, k_g, k_b) }))
    ),
    kernel!(
        "cook_torrance::ggx_conductor_rgb_fast",
        "Rough conductor, GGX, RGB, working precision (D_GGX, conductor_fast), Cook and Torrance \
         1982; Guy and Agopian 2018",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, eta_r: ETA, eta_g: ETA, eta_b: ETA, k_r: KAPPA, k_g: KAPPA, k_b: KAPPA]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(cook_torrance::ggx_conductor_rgb_fast(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), ComplexIor { eta: v3(eta_r, eta_g, eta_b), k: v3(k_r, k_g, k_b) }))
    ),
    kernel!(
        "cook_torrance::ggx_conductor_local",
        "Rough conductor, GGX, one channel, from the directions (D from h's components), Walter \
         et al. 2007; Born and Wolf 14.2",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, alpha: ALPHA, eta: ETA, k: KAPPA]
            -> [f: Domain::NONNEG],
        [cook_torrance::ggx_conductor_local(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), Alpha(alpha), eta, k)]
    ),
    kernel!(
        "cook_torrance::ggx_conductor_local_fast",
        "Rough conductor, GGX, one channel, from the directions, working precision, Walter et \
         al. 2007; Born and Wolf 14.2",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, alpha: ALPHA, eta: ETA, k: KAPPA]
            -> [f: Domain::NONNEG],
        [cook_torrance::ggx_conductor_local_fast(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), Alpha(alpha), eta, k)]
    ),
    kernel!(
        "cook_torrance::ggx_schlick_rgb",
        "GGX with Schlick's Fresnel of an RGB F0 (glTF, Filament, UE4), Schlick 1994; Walter et \
         al. 2007",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(cook_torrance::ggx_schlick_rgb(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), v3(f0_r, f0_g, f0_b)))
    ),
    kernel!(
        "cook_torrance::ggx_dielectric",
        "Rough dielectric reflection, GGX with the exact dielectric Fresnel, Walter et al. 2007; \
         Born and Wolf 1.5",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, eta: ETA] -> [f: Domain::NONNEG],
        [cook_torrance::ggx_dielectric(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), eta)]
    ),
    kernel!(
        "cook_torrance::ggx_dielectric_fast",
        "Rough dielectric reflection in working precision, GGX with the dielectric Fresnel, \
         Walter et al. 2007; Born and Wolf 1.5",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, eta: ETA] -> [f: Domain::NONNEG],
        [cook_torrance::ggx_dielectric_fast(
            cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
            Alpha(alpha),
            eta
        )]
    ),
    kernel!(
        "cook_torrance::beckmann_conductor_rgb",
        "Rough conductor, Beckmann, RGB exact conductor Fresnel, Walter et al. 2007; Born and \
         Wolf 14.2",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, eta_r: ETA, eta_g: ETA, eta_b: ETA, k_r: KAPPA, k_g: KAPPA, k_b: KAPPA]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(cook_torrance::beckmann_conductor_rgb(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), ComplexIor { eta: v3(eta_r, eta_g, eta_b), k: v3(k_r, k_g, k_b) }))
    ),
    kernel!(
        "cook_torrance::beckmann_schlick_rgb",
        "Beckmann with Schlick's Fresnel of an RGB F0, Schlick 1994; Walter et al. 2007",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(cook_torrance::beckmann_schlick_rgb(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), v3(f0_r, f0_g, f0_b)))
    ),
    kernel!(
        "cook_torrance::beckmann_dielectric",
        "Rough dielectric reflection, Beckmann with the exact dielectric Fresnel, Walter et al. \
         2007",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA, eta: ETA] -> [f: Domain::NONNEG],
        [cook_torrance::beckmann_dielectric(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), Alpha(alpha), eta)]
    ),
    // ---------------------------------------------------------------- sampling
    kernel!(
        "sampling::cosine_hemisphere",
        "Cosine-weighted hemisphere direction and pdf cos / pi (Malley), Pharr et al. 2023 A.5.3",
        [u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        o4(sampling::cosine_hemisphere(u1, u2))
    ),
    kernel!(
        "sampling::cosine_hemisphere_pdf",
        "pdf max(0, w.z) / pi of cosine hemisphere sampling, Pharr et al. 2023 A.5.3",
        [w_x: Domain::DIR, w_y: Domain::DIR, w_z: Domain::DIR] -> [pdf: Domain::NONNEG],
        [sampling::cosine_hemisphere_pdf(v3(w_x, w_y, w_z))]
    ),
    kernel!(
        "sampling::reflect_pdf",
        "pdf of a reflected direction pdf_m / (4 |v.h|), Walter et al. 2007 eq. 14",
        [pdf_m: Domain::NONNEG, v_dot_h: Domain::COS] -> [pdf: Domain::NONNEG],
        [sampling::reflect_pdf(pdf_m, v_dot_h)]
    ),
    kernel!(
        "sampling::ggx_d_cos",
        "GGX microfacet normal with pdf D(m) cos(theta_m), Walter et al. 2007 eqs. 35-36; Heitz \
         2014",
        [alpha_x: ALPHA, alpha_y: ALPHA, u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [m_x: Domain::DIR_OUT, m_y: Domain::DIR_OUT, m_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| o4(sampling::ggx_d_cos(&g, u1, u2)))
    ),
    kernel!(
        "sampling::beckmann_d_cos",
        "Beckmann microfacet normal with pdf D(m) cos(theta_m), Walter et al. 2007 eqs. 28-29",
        [alpha_x: ALPHA, alpha_y: ALPHA, u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [m_x: Domain::DIR_OUT, m_y: Domain::DIR_OUT, m_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |b| o4(sampling::beckmann_d_cos(&b, u1, u2)))
    ),
    kernel!(
        "sampling::d_cos_pdf",
        "pdf D(m) max(0, m.z) of NDF sampling, Walter et al. 2007",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA, m_x: Domain::DIR, m_y: Domain::DIR,
         m_z: Domain::DIR]
            -> [pdf: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |d| [sampling::d_cos_pdf(d, v3(m_x, m_y, m_z))])
    ),
    kernel!(
        "sampling::visible_normal_pdf",
        "pdf D_wo(m) of visible-normal sampling, Heitz 2014 eq. 38",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         m_x: Domain::DIR, m_y: Domain::DIR, m_z: Domain::DIR] -> [pdf: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |d| {
            [sampling::visible_normal_pdf(d, v3(wo_x, wo_y, wo_z), v3(m_x, m_y, m_z))]
        })
    ),
    kernel!(
        "sampling::ggx_vndf",
        "GGX visible normal and its pdf, Heitz 2018 (JCGT 7(4))",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [m_x: Domain::DIR_OUT, m_y: Domain::DIR_OUT, m_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            o4(sampling::ggx_vndf(&g, v3(wo_x, wo_y, wo_z), u1, u2))
        })
    ),
    kernel!(
        "sampling::ggx_vndf_spherical_cap",
        "GGX visible normal by spherical caps and its pdf, Dupuy and Benyoub 2023",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [m_x: Domain::DIR_OUT, m_y: Domain::DIR_OUT, m_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            o4(sampling::ggx_vndf_spherical_cap(&g, v3(wo_x, wo_y, wo_z), u1, u2))
        })
    ),
    kernel!(
        "sampling::erf_inv",
        "Inverse error function, Giles 2010 polynomial with two Newton steps",
        [y: Domain::closed(-1.0, 1.0, "[-1, 1] (+-inf at +-1)")]
            -> [x: Domain::closed(f64::NEG_INFINITY, f64::INFINITY, "finite in (-1, 1),
                +-inf at +-1")],
        [sampling::erf_inv(y)]
    ),
    kernel!(
        "sampling::beckmann_vndf",
        "Beckmann visible normal and its pdf, Heitz and d'Eon 2014 with Jakob's improvements",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [m_x: Domain::DIR_OUT, m_y: Domain::DIR_OUT, m_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |b| {
            o4(sampling::beckmann_vndf(&b, v3(wo_x, wo_y, wo_z), u1, u2))
        })
    ),
    kernel!(
        "sampling::ggx_reflection",
        "GGX reflection lobe sample (wi, pdf, weight F G2 / G1) for a constant F, Heitz 2018",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE,
         fresnel: Domain::new(0.0, false, f64::INFINITY, true, "F >= 0,
         finite (the closure's constant)")]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG, weight: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            let wo = v3(wo_x, wo_y, wo_z);
            let (w, p, wt) = sampling::ggx_reflection(&g, wo, u1, u2, |_| fresnel);
            [w.x, w.y, w.z, p, wt]
        })
    ),
    kernel!(
        "sampling::ggx_reflection_rgb",
        "GGX reflection lobe sample with a constant RGB F, weight F_c G2 / G1, Heitz 2018",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE,
         fresnel_r: Domain::NONNEG, fresnel_g: Domain::NONNEG, fresnel_b: Domain::NONNEG]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG,
                weight_r: Domain::NONNEG, weight_g: Domain::NONNEG, weight_b: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            let f = v3(fresnel_r, fresnel_g, fresnel_b);
            let (w, p, wt) = sampling::ggx_reflection_rgb(&g, v3(wo_x, wo_y, wo_z), u1, u2, |_| f);
            [w.x, w.y, w.z, p, wt.x, wt.y, wt.z]
        })
    ),
    kernel!(
        "sampling::ggx_reflection_pdf",
        "pdf G1(wo) D(h) / (4 wo.z) of the GGX reflection sampler, Walter et al. 2007 eq. 14; \
         Heitz 2018 eq. 17",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [pdf: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            [sampling::ggx_reflection_pdf(&g, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "sampling::beckmann_reflection",
        "Beckmann reflection lobe sample (wi, pdf, weight) for a constant F, Heitz and d'Eon 2014",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE,
         fresnel: Domain::new(0.0, false, f64::INFINITY, true, "F >= 0,
         finite (the closure's constant)")]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG, weight: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |b| {
            let wo = v3(wo_x, wo_y, wo_z);
            let (w, p, wt) = sampling::beckmann_reflection(&b, wo, u1, u2, |_| fresnel);
            [w.x, w.y, w.z, p, wt]
        })
    ),
    kernel!(
        "sampling::beckmann_reflection_rgb",
        "Beckmann reflection lobe sample with a constant RGB F, Heitz and d'Eon 2014",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE,
         fresnel_r: Domain::NONNEG, fresnel_g: Domain::NONNEG, fresnel_b: Domain::NONNEG]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG,
                weight_r: Domain::NONNEG, weight_g: Domain::NONNEG, weight_b: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |b| {
            let f = v3(fresnel_r, fresnel_g, fresnel_b);
            let wo = v3(wo_x, wo_y, wo_z);
            let (w, p, wt) = sampling::beckmann_reflection_rgb(&b, wo, u1, u2, |_| f);
            [w.x, w.y, w.z, p, wt.x, wt.y, wt.z]
        })
    ),
    kernel!(
        "sampling::beckmann_reflection_pdf",
        "pdf G1(wo) D(h) / (4 wo.z) of the Beckmann reflection sampler, Walter et al. 2007 eq. 14",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [pdf: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |b| {
            [sampling::beckmann_reflection_pdf(&b, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    // ---------------------------------------------------------------- rough dielectric
    kernel!(
        "rough_dielectric::half_vector",
        "Generalized half vector +-normalize(wo + eta' wi), Walter et al. 2007 eq. 16",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, eta: ETA]
            -> [h_x: Domain::DIR_OUT, h_y: Domain::DIR_OUT, h_z: Domain::DIR_OUT],
        o3(rough_dielectric::half_vector(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), eta))
    ),
    kernel!(
        "rough_dielectric::eval",
        "Rough dielectric BSDF, reflection and transmission, Walter et al. 2007 eqs. 20-21",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, eta: ETA,
         transport: TRANSPORT]
            -> [f: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |m| {
            pick(transport, 2, |k| {
                let (wo, wi) = (v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z));
                [rough_dielectric::eval(m, wo, wi, eta, transport_of(k))]
            })
        })
    ),
    kernel!(
        "rough_dielectric::pdf",
        "pdf of the rough dielectric samplers, both lobes, Walter et al. 2007 eqs. 14, 17",
        [model: MODEL, alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, eta: ETA]
            -> [pdf: Domain::NONNEG],
        with_model(model, alpha_x, alpha_y, |m| {
            [rough_dielectric::pdf(m, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), eta)]
        })
    ),
    kernel!(
        "rough_dielectric::ggx_sample",
        "GGX rough dielectric sample (wi, pdf, weight G2 / G1), Walter et al. 2007; Heitz 2018",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         eta: ETA, u0: Domain::SAMPLE, u1: Domain::SAMPLE, u2: Domain::SAMPLE,
         transport: TRANSPORT]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG, weight: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            pick(transport, 2, |k| {
                let wo = v3(wo_x, wo_y, wo_z);
                let t = transport_of(k);
                let (w, p, wt) = rough_dielectric::ggx_sample(&g, wo, eta, u0, u1, u2, t);
                [w.x, w.y, w.z, p, wt]
            })
        })
    ),
    kernel!(
        "rough_dielectric::beckmann_sample",
        "Beckmann rough dielectric sample (wi, pdf, weight G2 / G1), Walter et al. 2007; Heitz \
         and d'Eon 2014",
        [alpha_x: ALPHA, alpha_y: ALPHA, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         eta: ETA, u0: Domain::SAMPLE, u1: Domain::SAMPLE, u2: Domain::SAMPLE,
         transport: TRANSPORT]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG, weight: Domain::NONNEG],
        built(Beckmann::new(alpha_x, alpha_y), |b| {
            pick(transport, 2, |k| {
                let wo = v3(wo_x, wo_y, wo_z);
                let t = transport_of(k);
                let (w, p, wt) = rough_dielectric::beckmann_sample(&b, wo, eta, u0, u1, u2, t);
                [w.x, w.y, w.z, p, wt]
            })
        })
    ),
    // ---------------------------------------------------------------- glTF transmission
    kernel!(
        "transmission::Volume::transmittance",
        "Beer-Lambert transmittance c^(x / d), KHR_materials_volume",
        [thickness: Domain::NONNEG, attenuation_color_r: Domain::UNIT,
         attenuation_color_g: Domain::UNIT, attenuation_color_b: Domain::UNIT,
         attenuation_distance: ETA, path_length: Domain::NONNEG]
            -> [t_r: Domain::UNIT, t_g: Domain::UNIT, t_b: Domain::UNIT],
        built(
            Volume::new(
                thickness,
                v3(attenuation_color_r, attenuation_color_g, attenuation_color_b),
                attenuation_distance,
            ),
            |v| o3(v.transmittance(path_length)),
        )
    ),
    kernel!(
        "transmission::Volume::attenuation_coefficient",
        "Attenuation coefficient -ln(c) / d, KHR_materials_volume",
        [thickness: Domain::NONNEG, attenuation_color_r: Domain::UNIT,
         attenuation_color_g: Domain::UNIT, attenuation_color_b: Domain::UNIT,
         attenuation_distance: ETA]
            -> [sigma_r: Domain::NONNEG, sigma_g: Domain::NONNEG, sigma_b: Domain::NONNEG],
        built(
            Volume::new(
                thickness,
                v3(attenuation_color_r, attenuation_color_g, attenuation_color_b),
                attenuation_distance,
            ),
            |v| o3(v.attenuation_coefficient()),
        )
    ),
    kernel!(
        "transmission::thin_walled_btdf",
        "Thin-walled GGX BTDF V_T D_T with the mirrored half vector, KHR_materials_transmission",
        [alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR]
            -> [f: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            [transmission::thin_walled_btdf(&g, v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "transmission::dielectric_bsdf",
        "glTF dielectric BSDF with KHR_materials_transmission, thin-walled or volumetric (Walter \
         et al. 2007)",
        [alpha_x: ALPHA, alpha_y: ALPHA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR,
         base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         ior: ETA, factor: Domain::UNIT, thickness: Domain::NONNEG,
         attenuation_color_r: Domain::UNIT, attenuation_color_g: Domain::UNIT,
         attenuation_color_b: Domain::UNIT, attenuation_distance: ETA]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        built(Ggx::new(alpha_x, alpha_y), |g| {
            built(Transmission::new(factor), |t| {
                built(
                    Volume::new(
                        thickness,
                        v3(attenuation_color_r, attenuation_color_g, attenuation_color_b),
                        attenuation_distance,
                    ),
                    |vol| {
                        o3(transmission::dielectric_bsdf(
                            &g,
                            v3(wo_x, wo_y, wo_z),
                            v3(wi_x, wi_y, wi_z),
                            v3(base_color_r, base_color_g, base_color_b),
                            ior,
                            &t,
                            &vol,
                        ))
                    },
                )
            })
        })
    ),
    // ---------------------------------------------------------------- iridescence
    kernel!(
        "iridescence::dielectric",
        "Thin-film XYZ reflectance over a dielectric base, Belcour and Barla 2017",
        [thickness: FILM_THICKNESS, ior: FILM_IOR, outside_ior: ETA, base_ior: ETA,
         cos_theta: Domain::UNIT]
            -> [cie_x: Domain::UNIT, cie_y: Domain::UNIT, cie_z: Domain::UNIT],
        built(ThinFilm::new(thickness, ior), |f| {
            o3(iridescence::dielectric(&f, outside_ior, base_ior, cos_theta))
        })
    ),
    kernel!(
        "iridescence::conductor",
        "Thin-film XYZ reflectance over a conductor base (its phase shift), Belcour and Barla \
         2017",
        [thickness: FILM_THICKNESS, ior: FILM_IOR, outside_ior: ETA, base_eta: ETA,
         base_k: KAPPA, cos_theta: Domain::UNIT]
            -> [cie_x: Domain::UNIT, cie_y: Domain::UNIT, cie_z: Domain::UNIT],
        built(ThinFilm::new(thickness, ior), |f| {
            o3(iridescence::conductor(&f, outside_ior, base_eta, base_k, cos_theta))
        })
    ),
    // ---------------------------------------------------------------- diffuse
    kernel!(
        "diffuse::lambert",
        "Lambert's diffuse BRDF rho / pi, Lambert 1760",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, rho: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::lambert(n_dot_v, n_dot_l, rho)]
    ),
    kernel!(
        "diffuse::Lambert::eval",
        "Lambert's diffuse BRDF on local-frame directions, Lambert 1760",
        [rho: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::Lambert::new(rho), |l| [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))])
    ),
    kernel!(
        "diffuse::oren_nayar_a",
        "Oren-Nayar qualitative A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33), Oren and Nayar 1994",
        [sigma: Domain::NONNEG] -> [a: Domain::closed(0.5, 1.0, "[0.5, 1]")],
        [diffuse::oren_nayar_a(sigma)]
    ),
    kernel!(
        "diffuse::oren_nayar_b",
        "Oren-Nayar qualitative B = 0.45 sigma^2 / (sigma^2 + 0.09), Oren and Nayar 1994",
        [sigma: Domain::NONNEG] -> [b: Domain::closed(0.0, 0.45, "[0, 0.45]")],
        [diffuse::oren_nayar_b(sigma)]
    ),
    kernel!(
        "diffuse::oren_nayar",
        "Oren-Nayar qualitative model from dot products, Oren and Nayar 1994 eq. 30",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, v_dot_l: Domain::COS, rho: Domain::UNIT,
         sigma: Domain::new(0.0, false, f64::INFINITY, true, ">= 0 and finite (radians)")]
            -> [f: Domain::NONNEG],
        [diffuse::oren_nayar(n_dot_v, n_dot_l, v_dot_l, rho, sigma)]
    ),
    kernel!(
        "diffuse::OrenNayar::eval",
        "Oren-Nayar qualitative model on local-frame directions, Oren and Nayar 1994 eq. 30",
        [rho: Domain::UNIT, sigma: Domain::new(0.0, false, f64::INFINITY, true,
         ">= 0 and finite (radians)"),
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::OrenNayar::new(rho, sigma), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::oren_nayar_full",
        "Oren-Nayar full model (L1 with C1, C2, C3 plus interreflection L2), Oren and Nayar 1994 \
         section 4",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, v_dot_l: Domain::COS, rho: Domain::UNIT,
         sigma: Domain::new(0.0, false, f64::INFINITY, true, ">= 0 and finite (radians)")]
            -> [f: Domain::NONNEG],
        [diffuse::oren_nayar_full(n_dot_v, n_dot_l, v_dot_l, rho, sigma)]
    ),
    kernel!(
        "diffuse::OrenNayarFull::eval",
        "Oren-Nayar full model on local-frame directions, Oren and Nayar 1994 section 4",
        [rho: Domain::UNIT, sigma: Domain::new(0.0, false, f64::INFINITY, true,
         ">= 0 and finite (radians)"),
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::OrenNayarFull::new(rho, sigma), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::oren_nayar_fujii",
        "Fujii's improved Oren-Nayar (FON), Fujii 2012; Portsmouth, Kutz and Hill 2025",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, v_dot_l: Domain::COS, rho: Domain::UNIT,
         sigma: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::oren_nayar_fujii(n_dot_v, n_dot_l, v_dot_l, rho, sigma)]
    ),
    kernel!(
        "diffuse::OrenNayarFujii::eval",
        "Fujii's improved Oren-Nayar on local-frame directions, Fujii 2012",
        [rho: Domain::UNIT, sigma: Domain::UNIT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::OrenNayarFujii::new(rho, sigma), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::eon",
        "EON energy-preserving Oren-Nayar with the exact FON albedo, Portsmouth, Kutz and Hill \
         2025",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, v_dot_l: Domain::COS, rho: Domain::UNIT,
         sigma: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::eon(n_dot_v, n_dot_l, v_dot_l, rho, sigma)]
    ),
    kernel!(
        "diffuse::eon_approx",
        "EON with the fitted FON albedo (no acos), Portsmouth, Kutz and Hill 2025",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, v_dot_l: Domain::COS, rho: Domain::UNIT,
         sigma: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::eon_approx(n_dot_v, n_dot_l, v_dot_l, rho, sigma)]
    ),
    kernel!(
        "diffuse::eon_fon_albedo",
        "Exact FON directional albedo at rho = 1, Portsmouth, Kutz and Hill 2025 (E_FON_exact)",
        [n_dot_v: Domain::COS, sigma: Domain::UNIT] -> [e: Domain::UNIT],
        [diffuse::eon_fon_albedo(n_dot_v, sigma)]
    ),
    kernel!(
        "diffuse::eon_fon_albedo_approx",
        "Fitted FON directional albedo at rho = 1, capped at 1, Portsmouth, Kutz and Hill 2025 \
         (E_FON_approx)",
        [n_dot_v: Domain::COS, sigma: Domain::UNIT] -> [e: Domain::UNIT],
        [diffuse::eon_fon_albedo_approx(n_dot_v, sigma)]
    ),
    kernel!(
        "diffuse::eon_fon_average_albedo",
        "Cosine-weighted average FON albedo (1 + c2 sigma) / (1 + c1 sigma), Portsmouth, Kutz \
         and Hill 2025",
        [sigma: Domain::UNIT] -> [e_avg: Domain::UNIT],
        [diffuse::eon_fon_average_albedo(sigma)]
    ),
    kernel!(
        "diffuse::eon_multiscatter_albedo",
        "EON multiple-scattering albedo rho^2 E_avg / (1 - rho (1 - E_avg)), Portsmouth, Kutz \
         and Hill 2025",
        [rho: Domain::UNIT, sigma: Domain::UNIT] -> [rho_ms: Domain::UNIT],
        [diffuse::eon_multiscatter_albedo(rho, sigma)]
    ),
    kernel!(
        "diffuse::eon_albedo",
        "EON directional albedo in closed form, exact E, Portsmouth, Kutz and Hill 2025 (E_EON)",
        [n_dot_v: Domain::COS, rho: Domain::UNIT, sigma: Domain::UNIT] -> [albedo: Domain::UNIT],
        [diffuse::eon_albedo(n_dot_v, rho, sigma)]
    ),
    kernel!(
        "diffuse::eon_albedo_approx",
        "EON directional albedo with the fitted E, Portsmouth, Kutz and Hill 2025 (E_EON approx)",
        [n_dot_v: Domain::COS, rho: Domain::UNIT, sigma: Domain::UNIT] -> [albedo: Domain::UNIT],
        [diffuse::eon_albedo_approx(n_dot_v, rho, sigma)]
    ),
    kernel!(
        "diffuse::eon_cltc_sample",
        "EON's clipped linearly transformed cosine sample and pdf, Portsmouth, Kutz and Hill \
         2025; Heitz et al. 2016",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR, sigma: Domain::UNIT,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        o4(diffuse::eon_cltc_sample(v3(wo_x, wo_y, wo_z), sigma, u1, u2))
    ),
    kernel!(
        "diffuse::eon_cltc_pdf",
        "pdf of EON's CLTC sampler, Portsmouth, Kutz and Hill 2025 (cltc_pdf)",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, sigma: Domain::UNIT]
            -> [pdf: Domain::NONNEG],
        [diffuse::eon_cltc_pdf(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), sigma)]
    ),
    kernel!(
        "diffuse::eon_sample",
        "EON importance sample (uniform and CLTC mixture) and pdf, Portsmouth, Kutz and Hill 2025",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR, sigma: Domain::UNIT,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        o4(diffuse::eon_sample(v3(wo_x, wo_y, wo_z), sigma, u1, u2))
    ),
    kernel!(
        "diffuse::eon_pdf",
        "pdf of EON's mixture sampler, Portsmouth, Kutz and Hill 2025 (pdf_EON)",
        [wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR, sigma: Domain::UNIT]
            -> [pdf: Domain::NONNEG],
        [diffuse::eon_pdf(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z), sigma)]
    ),
    kernel!(
        "diffuse::Eon::eval",
        "EON with the exact FON albedo on local-frame directions, Portsmouth, Kutz and Hill 2025",
        [rho: Domain::UNIT, sigma: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::Eon::new(rho, sigma), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::Eon::eval_approx",
        "EON with the fitted FON albedo on local-frame directions, Portsmouth, Kutz and Hill 2025",
        [rho: Domain::UNIT, sigma: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::Eon::new(rho, sigma), |l| {
            [l.eval_approx(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::Eon::albedo",
        "EON directional albedo at wo, exact E, Portsmouth, Kutz and Hill 2025",
        [rho: Domain::UNIT, sigma: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR]
            -> [albedo: Domain::UNIT],
        built(diffuse::Eon::new(rho, sigma), |l| [l.albedo(v3(wo_x, wo_y, wo_z))])
    ),
    kernel!(
        "diffuse::Eon::albedo_approx",
        "EON directional albedo at wo, fitted E, Portsmouth, Kutz and Hill 2025",
        [rho: Domain::UNIT, sigma: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR]
            -> [albedo: Domain::UNIT],
        built(diffuse::Eon::new(rho, sigma), |l| [l.albedo_approx(v3(wo_x, wo_y, wo_z))])
    ),
    kernel!(
        "diffuse::Eon::sample",
        "EON importance sample and pdf for view wo, Portsmouth, Kutz and Hill 2025",
        [rho: Domain::UNIT, sigma: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         u1: Domain::SAMPLE, u2: Domain::SAMPLE]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(diffuse::Eon::new(rho, sigma), |l| o4(l.sample(v3(wo_x, wo_y, wo_z), u1, u2)))
    ),
    kernel!(
        "diffuse::Eon::pdf",
        "pdf of EON's sampler, Portsmouth, Kutz and Hill 2025",
        [rho: Domain::UNIT, sigma: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [pdf: Domain::NONNEG],
        built(diffuse::Eon::new(rho, sigma), |l| {
            [l.pdf(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::burley",
        "Burley's (Disney) diffuse with the F_D90 retro-reflection, Burley 2012 section 5.3",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, l_dot_h: Domain::COS, rho: Domain::UNIT,
         roughness: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::burley(n_dot_v, n_dot_l, l_dot_h, rho, roughness)]
    ),
    kernel!(
        "diffuse::burley_renormalized",
        "Burley's diffuse renormalized (Fr_DisneyDiffuse / pi), Lagarde and de Rousiers 2014",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, l_dot_h: Domain::COS, rho: Domain::UNIT,
         roughness: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::burley_renormalized(n_dot_v, n_dot_l, l_dot_h, rho, roughness)]
    ),
    kernel!(
        "diffuse::Burley::eval",
        "Burley's diffuse on local-frame directions, Burley 2012",
        [rho: Domain::UNIT, roughness: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::Burley::new(rho, roughness), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::BurleyRenormalized::eval",
        "Renormalized Burley diffuse on local-frame directions, Lagarde and de Rousiers 2014",
        [rho: Domain::UNIT, roughness: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::BurleyRenormalized::new(rho, roughness), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::fresnel_weight_normalized",
        "One-sided diffuse weight (1 - F(wi)) / (1 - F0)",
        [fresnel_l: Domain::UNIT, f0: Domain::new(0.0, false, 1.0, true, "[0,
         1)")] -> [w: Domain::NONNEG],
        [diffuse::fresnel_weight_normalized(fresnel_l, f0)]
    ),
    kernel!(
        "diffuse::fresnel_weight_symmetric",
        "Symmetric diffuse weight (1 - F(wi))(1 - F(wo)), Shirley, Hu, Smits and Lafortune 1997",
        [fresnel_v: Domain::UNIT, fresnel_l: Domain::UNIT] -> [w: Domain::UNIT],
        [diffuse::fresnel_weight_symmetric(fresnel_v, fresnel_l)]
    ),
    kernel!(
        "diffuse::fresnel_mix",
        "Fresnel mix (1 - F) f_diffuse + F f_specular (glTF 2.0 Appendix B fresnel_mix)",
        [f_diffuse: Domain::NONNEG, f_specular: Domain::NONNEG,
         fresnel: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::fresnel_mix(f_diffuse, f_specular, fresnel)]
    ),
    kernel!(
        "diffuse::fresnel_mix_schlick",
        "Fresnel mix with Schlick's F at cos_theta, Schlick 1994",
        [f_diffuse: Domain::NONNEG, f_specular: Domain::NONNEG, f0: Domain::UNIT,
         cos_theta: Domain::COS]
            -> [f: Domain::NONNEG],
        [diffuse::fresnel_mix_schlick(f_diffuse, f_specular, f0, cos_theta)]
    ),
    kernel!(
        "diffuse::shirley_coupled",
        "Coupled diffuse under a smooth Schlick interface, Shirley, Hu, Smits and Lafortune 1997",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, rho: Domain::UNIT,
         f0: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::shirley_coupled(n_dot_v, n_dot_l, rho, f0)]
    ),
    kernel!(
        "diffuse::ashikhmin_shirley",
        "Ashikhmin and Shirley's coupled diffuse term, Ashikhmin and Shirley 2000 eq. 5",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, rho: Domain::UNIT,
         rs: Domain::UNIT] -> [f: Domain::NONNEG],
        [diffuse::ashikhmin_shirley(n_dot_v, n_dot_l, rho, rs)]
    ),
    kernel!(
        "diffuse::ShirleyCoupled::eval",
        "Shirley et al.'s coupled diffuse on local-frame directions, Shirley et al. 1997",
        [rho: Domain::UNIT, f0: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::ShirleyCoupled::new(rho, f0), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "diffuse::AshikhminShirley::eval",
        "Ashikhmin and Shirley's coupled diffuse on local-frame directions, Ashikhmin and \
         Shirley 2000",
        [rho: Domain::UNIT, rs: Domain::UNIT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(diffuse::AshikhminShirley::new(rho, rs), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    // ---------------------------------------------------------------- phong
    kernel!(
        "phong::phong_normalization",
        "Phong lobe normalization (n + 2) / (2 pi), Lafortune and Willems 1994",
        [exponent: EXPONENT] -> [c: Domain::NONNEG],
        [phong::phong_normalization(exponent)]
    ),
    kernel!(
        "phong::blinn_phong_normalization_exact",
        "Exact Blinn-Phong BRDF normalization (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)), Giesen 2009",
        [exponent: EXPONENT] -> [c: Domain::NONNEG],
        [phong::blinn_phong_normalization_exact(exponent)]
    ),
    kernel!(
        "phong::blinn_phong_normalization_approx",
        "Approximate Blinn-Phong normalization (n + 8) / (8 pi), Akenine-Moller et al. 2008",
        [exponent: EXPONENT] -> [c: Domain::NONNEG],
        [phong::blinn_phong_normalization_approx(exponent)]
    ),
    kernel!(
        "phong::classic",
        "Classic Phong as a BRDF ks (r.l)^n / (n.l), Phong 1975; Lewis 1994",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, r_dot_l: Domain::COS, ks: Domain::UNIT,
         exponent: EXPONENT]
            -> [f: Domain::NONNEG],
        [phong::classic(n_dot_v, n_dot_l, r_dot_l, ks, exponent)]
    ),
    kernel!(
        "phong::modified",
        "Modified Phong ks (r.l)^n, Lewis 1994",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, r_dot_l: Domain::COS, ks: Domain::UNIT,
         exponent: EXPONENT]
            -> [f: Domain::UNIT],
        [phong::modified(n_dot_v, n_dot_l, r_dot_l, ks, exponent)]
    ),
    kernel!(
        "phong::normalized",
        "Normalized modified Phong ks (n + 2) / (2 pi) (r.l)^n, Lewis 1994; Lafortune and \
         Willems 1994",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, r_dot_l: Domain::COS, ks: Domain::UNIT,
         exponent: EXPONENT]
            -> [f: Domain::NONNEG],
        [phong::normalized(n_dot_v, n_dot_l, r_dot_l, ks, exponent)]
    ),
    kernel!(
        "phong::diffuse_specular",
        "Diffuse plus normalized Phong kd / pi + ks (n + 2) / (2 pi) (r.l)^n, Lafortune and \
         Willems 1994",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, r_dot_l: Domain::COS, kd: Domain::UNIT,
         ks: Domain::UNIT,
         exponent: EXPONENT] -> [f: Domain::NONNEG],
        where [Constraint::Holds {
            text: "kd + ks <= 1 + epsilon",
            args: &["kd", "ks"],
            check: |v| v.get("kd") + v.get("ks") <= 1.0 + v.eps,
        }],
        [phong::diffuse_specular(n_dot_v, n_dot_l, r_dot_l, kd, ks, exponent)]
    ),
    kernel!(
        "phong::blinn_phong",
        "Unnormalized Blinn-Phong ks (n.h)^n, Blinn 1977",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, ks: Domain::UNIT,
         exponent: EXPONENT]
            -> [f: Domain::UNIT],
        [phong::blinn_phong(n_dot_v, n_dot_l, n_dot_h, ks, exponent)]
    ),
    kernel!(
        "phong::blinn_phong_normalized",
        "Blinn-Phong with its exact BRDF normalization ks c(n) (n.h)^n, Blinn 1977; Giesen 2009",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, ks: Domain::UNIT,
         exponent: EXPONENT]
            -> [f: Domain::NONNEG],
        [phong::blinn_phong_normalized(n_dot_v, n_dot_l, n_dot_h, ks, exponent)]
    ),
    kernel!(
        "phong::blinn_phong_normalized_approx",
        "Blinn-Phong with the (n + 8) / (8 pi) normalization, Akenine-Moller et al. 2008",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, ks: Domain::UNIT,
         exponent: EXPONENT]
            -> [f: Domain::NONNEG],
        [phong::blinn_phong_normalized_approx(n_dot_v, n_dot_l, n_dot_h, ks, exponent)]
    ),
    kernel!(
        "phong::blinn_phong_ndf",
        "Blinn-Phong microfacet NDF (n + 2) / (2 pi) (n.m)^n, Walter et al. 2007 eq. 30",
        [n_dot_h: Domain::COS, exponent: EXPONENT] -> [d: Domain::NONNEG],
        [phong::blinn_phong_ndf(n_dot_h, exponent)]
    ),
    kernel!(
        "phong::ClassicPhong::eval",
        "Classic Phong BRDF on local-frame directions, Phong 1975",
        [ks: Domain::UNIT, exponent: EXPONENT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(phong::ClassicPhong::new(ks, exponent), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "phong::ModifiedPhong::eval",
        "Modified Phong on local-frame directions, Lewis 1994",
        [ks: Domain::UNIT, exponent: EXPONENT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::UNIT],
        built(phong::ModifiedPhong::new(ks, exponent), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "phong::NormalizedPhong::eval",
        "Normalized modified Phong on local-frame directions, Lafortune and Willems 1994",
        [ks: Domain::UNIT, exponent: EXPONENT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(phong::NormalizedPhong::new(ks, exponent), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "phong::BlinnPhong::eval",
        "Unnormalized Blinn-Phong on local-frame directions, Blinn 1977",
        [ks: Domain::UNIT, exponent: EXPONENT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::UNIT],
        built(phong::BlinnPhong::new(ks, exponent), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "phong::NormalizedBlinnPhong::eval",
        "Blinn-Phong with the exact normalization on local-frame directions, Giesen 2009",
        [ks: Domain::UNIT, exponent: EXPONENT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(phong::NormalizedBlinnPhong::new(ks, exponent), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "phong::ApproxNormalizedBlinnPhong::eval",
        "Blinn-Phong with the (n + 8) / (8 pi) normalization on local-frame directions, \
         Akenine-Moller et al. 2008",
        [ks: Domain::UNIT, exponent: EXPONENT, wo_x: Domain::DIR, wo_y: Domain::DIR,
         wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        built(phong::ApproxNormalizedBlinnPhong::new(ks, exponent), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    kernel!(
        "phong::PhongDiffuseSpecular::eval",
        "Diffuse plus normalized Phong on local-frame directions, Lafortune and Willems 1994",
        [kd: Domain::UNIT, ks: Domain::UNIT, exponent: EXPONENT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [f: Domain::NONNEG],
        where [Constraint::Holds {
            text: "kd + ks <= 1 + epsilon",
            args: &["kd", "ks"],
            check: |v| v.get("kd") + v.get("ks") <= 1.0 + v.eps,
        }],
        built(phong::PhongDiffuseSpecular::new(kd, ks, exponent), |l| {
            [l.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))]
        })
    ),
    // ---------------------------------------------------------------- material
    kernel!(
        "material::f0_from_reflectance",
        "F0 = 0.16 reflectance^2 from Filament's reflectance, Guy and Agopian 2018 section 4.8.3.2",
        [reflectance: Domain::UNIT] -> [f0: Domain::closed(0.0, 0.16, "[0, 0.16]")],
        [material::f0_from_reflectance(reflectance)]
    ),
    kernel!(
        "material::metallic_roughness",
        "Metallic-roughness BRDF from dot products, RGB, glTF 2.0 Appendix B; Karis 2013; Guy \
         and Agopian 2018",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT, dielectric_f0: Domain::UNIT,
         coupling: COUPLING]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        pick(coupling, 3, |k| {
            o3(material::metallic_roughness(
                cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
                dielectric_f0,
                self::coupling(k),
            ))
        })
    ),
    kernel!(
        "material::gltf",
        "glTF 2.0 metallic-roughness BRDF as Appendix B composes it, RGB, Khronos glTF 2.0 \
         Appendix B",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(material::gltf(
            cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
            v3(base_color_r, base_color_g, base_color_b),
            metallic,
            roughness,
        ))
    ),
    kernel!(
        "material::MetallicRoughness::eval",
        "glTF metallic-roughness BRDF on local-frame directions, RGB, glTF 2.0 Appendix B",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        built(
            MetallicRoughness::new(
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
            ),
            |m| o3(m.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))),
        )
    ),
    kernel!(
        "material::metallic_roughness_fast",
        "Metallic-roughness BRDF in working precision (Filament's D_GGX), RGB, glTF 2.0 \
         Appendix B; Guy and Agopian 2018",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT, dielectric_f0: Domain::UNIT,
         coupling: COUPLING]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        pick(coupling, 3, |k| {
            o3(material::metallic_roughness_fast(
                cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
                dielectric_f0,
                self::coupling(k),
            ))
        })
    ),
    kernel!(
        "material::gltf_fast",
        "glTF 2.0 metallic-roughness BRDF in working precision, RGB, Khronos glTF 2.0 Appendix B",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(material::gltf_fast(
            cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
            v3(base_color_r, base_color_g, base_color_b),
            metallic,
            roughness,
        ))
    ),
    kernel!(
        "material::MetallicRoughness::eval_fast",
        "glTF metallic-roughness BRDF on local-frame directions in working precision, RGB, \
         glTF 2.0 Appendix B",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        built(
            MetallicRoughness::new(
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
            ),
            |m| o3(m.eval_fast(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))),
        )
    ),
    kernel!(
        "material::MetallicRoughness::specular_probability",
        "Probability of sampling the specular lobe, S / (S + D) kept in [1/16, 15/16] \
         (one-sample MIS)",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR] -> [p: Domain::UNIT],
        built(
            MetallicRoughness::new(
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
            ),
            |m| [m.specular_probability(v3(wo_x, wo_y, wo_z))],
        )
    ),
    kernel!(
        "material::MetallicRoughness::pdf",
        "One-sample MIS pdf of the material's sampler, Heitz 2018; Walter et al. 2007 eq. 14",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR] -> [pdf: Domain::NONNEG],
        built(
            MetallicRoughness::new(
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
            ),
            |m| [m.pdf(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))],
        )
    ),
    kernel!(
        "material::MetallicRoughness::sample",
        "Material sample by one-sample lobe selection (GGX visible normals or cosine), with its \
         pdf, Heitz 2018",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR, u1: Domain::SAMPLE,
         u2: Domain::SAMPLE]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(
            MetallicRoughness::new(
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
            ),
            |m| o4(m.sample(v3(wo_x, wo_y, wo_z), u1, u2)),
        )
    ),
    kernel!(
        "material::MetallicRoughness::sample_weighted",
        "Material sample with pdf and RGB Monte Carlo weight f cos / pdf, Heitz 2018",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR, u1: Domain::SAMPLE,
         u2: Domain::SAMPLE]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG,
                weight_r: Domain::NONNEG, weight_g: Domain::NONNEG, weight_b: Domain::NONNEG],
        built(
            MetallicRoughness::new(
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
            ),
            |m| {
                let (w, p, wt) = m.sample_weighted(v3(wo_x, wo_y, wo_z), u1, u2);
                [w.x, w.y, w.z, p, wt.x, wt.y, wt.z]
            },
        )
    ),
    // ---------------------------------------------------------------- engine
    kernel!(
        "engine::Convention::alpha",
        "An engine's alpha = clamp(r, floor, 1)^2 (three.js, Filament, bevy, Karis 2013, glTF \
         sample viewer)",
        [convention: CONVENTION, perceptual_roughness: Domain::UNIT]
            -> [alpha: Domain::closed(ALPHA_MIN, 1.0, "[ALPHA_MIN, 1]")],
        pick(convention, 5, |k| [engine::ALL[k].alpha(perceptual_roughness)])
    ),
    kernel!(
        "engine::Convention::f90",
        "An engine's F90 of F0: 1, or saturate(16.5 (f0.r + f0.g + f0.b)) (Filament, bevy)",
        [convention: CONVENTION, f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT]
            -> [f90: Domain::UNIT],
        pick(convention, 5, |k| [engine::ALL[k].f90(v3(f0_r, f0_g, f0_b))])
    ),
    kernel!(
        "engine::Convention::fresnel",
        "An engine's Schlick Fresnel F0 (1 - w) + F90 w, w = (1 - v.h)^5 or Karis 2013's exp2 fit",
        [convention: CONVENTION, f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT,
         f90: Domain::UNIT, v_dot_h: Domain::COS]
            -> [f_r: Domain::UNIT, f_g: Domain::UNIT, f_b: Domain::UNIT],
        pick(convention, 5, |k| o3(engine::ALL[k].fresnel(v3(f0_r, f0_g, f0_b), f90, v_dot_h)))
    ),
    kernel!(
        "engine::Convention::specular",
        "An engine's specular lobe D V F under its floors and guards, RGB, without n.l",
        [convention: CONVENTION, n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS,
         v_dot_h: Domain::COS, roughness: Domain::UNIT,
         f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT, f90: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        pick(convention, 5, |k| {
            o3(engine::ALL[k].specular(
                cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
                roughness,
                v3(f0_r, f0_g, f0_b),
                f90,
            ))
        })
    ),
    kernel!(
        "engine::Convention::diffuse",
        "An engine's diffuse lobe (Lambert, or bevy's Burley of alpha), RGB, without n.l",
        [convention: CONVENTION, n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS,
         v_dot_h: Domain::COS, roughness: Domain::UNIT,
         diffuse_color_r: Domain::UNIT, diffuse_color_g: Domain::UNIT,
         diffuse_color_b: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        pick(convention, 5, |k| {
            o3(engine::ALL[k].diffuse(
                cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
                roughness,
                v3(diffuse_color_r, diffuse_color_g, diffuse_color_b),
            ))
        })
    ),
    kernel!(
        "engine::Convention::brdf",
        "An engine's metallic-roughness BRDF for a punctual light, RGB, without n.l (three.js, \
         Filament, bevy, Karis 2013, glTF sample viewer)",
        [convention: CONVENTION, n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS,
         v_dot_h: Domain::COS,
         base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        pick(convention, 5, |k| {
            o3(engine::ALL[k].brdf(
                cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
                v3(base_color_r, base_color_g, base_color_b),
                metallic,
                roughness,
            ))
        })
    ),
    // ---------------------------------------------------------------- lights
    kernel!(
        "lights::radiance",
        "Reflected radiance of a punctual light f E_perp max(0, n.l), Pharr et al. 2023 section \
         12.1",
        [f: Domain::NONNEG, e_perp: Domain::NONNEG, n_dot_l: Domain::COS] -> [l_o: Domain::NONNEG],
        [lights::radiance(f, e_perp, n_dot_l)]
    ),
    kernel!(
        "lights::radiance_pi",
        "Reflected radiance in the real-time convention pi f c_light max(0, n.l), Hoffman 2013",
        [f: Domain::NONNEG, c_light: Domain::NONNEG, n_dot_l: Domain::COS] -> [l_o: Domain::NONNEG],
        [lights::radiance_pi(f, c_light, n_dot_l)]
    ),
    kernel!(
        "lights::radiance_pi_rgb",
        "Real-time reflected radiance per channel, Hoffman 2013",
        [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG,
         c_light_r: Domain::NONNEG, c_light_g: Domain::NONNEG, c_light_b: Domain::NONNEG,
         n_dot_l: Domain::COS]
            -> [l_o_r: Domain::NONNEG, l_o_g: Domain::NONNEG, l_o_b: Domain::NONNEG],
        o3(lights::radiance_pi_rgb(v3(f_r, f_g, f_b), v3(c_light_r, c_light_g, c_light_b), n_dot_l))
    ),
    kernel!(
        "lights::irradiance",
        "Irradiance from a punctual light E_perp max(0, n.l), Lambert's cosine law",
        [e_perp: Domain::NONNEG, n_dot_l: Domain::COS] -> [e: Domain::NONNEG],
        [lights::irradiance(e_perp, n_dot_l)]
    ),
    kernel!(
        "lights::inverse_square",
        "Inverse square law with a minimum distance 1 / max(d, d_min)^2, Lagarde and de Rousiers \
         2014",
        [distance: DISTANCE, min_distance: POS] -> [attenuation: Domain::NONNEG],
        [lights::inverse_square(distance, min_distance)]
    ),
    kernel!(
        "lights::windowed",
        "UE4's windowed falloff saturate(1 - (d/r)^4)^2 / (d^2 + 1), Karis 2013 eq. 9",
        [distance: DISTANCE, radius: DISTANCE] -> [attenuation: Domain::UNIT],
        [lights::windowed(distance, radius)]
    ),
    kernel!(
        "lights::windowed_inverse_square",
        "Frostbite's windowed inverse square law, Lagarde and de Rousiers 2014 (smoothDistanceAtt)",
        [distance: DISTANCE, radius: DISTANCE, min_distance: POS] -> [attenuation: Domain::NONNEG],
        [lights::windowed_inverse_square(distance, radius, min_distance)]
    ),
    kernel!(
        "lights::polynomial",
        "Fixed-function attenuation 1 / (k_c + k_l d + k_q d^2), OpenGL 1.5 section 2.14.1",
        [distance: DISTANCE, constant: POS, linear: Domain::NONNEG, quadratic: Domain::NONNEG]
            -> [attenuation: Domain::NONNEG],
        [lights::polynomial(distance, constant, linear, quadratic)]
    ),
    kernel!(
        "lights::spot_cone",
        "Spot light cone falloff t^2, t = saturate((cos a - cos_outer) / (cos_inner - \
         cos_outer)), Lagarde and de Rousiers 2014",
        [cos_angle: Domain::COS, cos_outer: Domain::COS,
         cos_inner: Domain::COS] -> [attenuation: Domain::UNIT],
        where [le!("cos_outer", "cos_inner", "cos_outer <= cos_inner")],
        [lights::spot_cone(cos_angle, cos_outer, cos_inner)]
    ),
    kernel!(
        "lights::SpotCone::eval",
        "Spot cone falloff from inner and outer angles in radians, Lagarde and de Rousiers 2014",
        [inner: Domain::closed(0.0, core::f64::consts::PI, "[0, outer]"),
         outer: Domain::closed(0.0, core::f64::consts::PI, "[0, pi]"), cos_angle: Domain::COS]
            -> [attenuation: Domain::UNIT],
        where [le!("inner", "outer", "inner <= outer")],
        built(lights::SpotCone::new(inner, outer), |s| [s.eval(cos_angle)])
    ),
    // ---------------------------------------------------------------- ibl::dfg
    kernel!(
        "ibl::dfg::karis_mobile",
        "Analytic split-sum DFG fit [A, B] (UE4 EnvBRDFApprox), Karis 2014",
        [n_dot_v: Domain::COS, roughness: Domain::UNIT] -> [a: Domain::FINITE, b: Domain::FINITE],
        dfg::karis_mobile(n_dot_v, roughness)
    ),
    kernel!(
        "ibl::dfg::karis_mobile_nonmetal",
        "Non-metal split-sum shortcut 0.04 A + B (UE4 EnvBRDFApproxNonmetal), Karis 2014",
        [n_dot_v: Domain::COS, roughness: Domain::UNIT] -> [albedo: Domain::FINITE],
        [dfg::karis_mobile_nonmetal(n_dot_v, roughness)]
    ),
    kernel!(
        "ibl::dfg::lazarov",
        "Environment BRDF fit [A, B] for normalized Blinn-Phong, Lazarov 2013",
        [n_dot_v: Domain::COS, roughness: Domain::UNIT] -> [a: Domain::FINITE, b: Domain::FINITE],
        dfg::lazarov(n_dot_v, roughness)
    ),
    kernel!(
        "ibl::dfg::narkowicz_lazarov",
        "Refit of Lazarov's DFG form to GGX [A, B] (EnvDFGLazarov), Narkowicz 2014",
        [n_dot_v: Domain::COS, roughness: Domain::UNIT] -> [a: Domain::FINITE, b: Domain::UNIT],
        dfg::narkowicz_lazarov(n_dot_v, roughness)
    ),
    kernel!(
        "ibl::dfg::narkowicz_polynomial",
        "Polynomial DFG fit for GGX [A, B] (EnvDFGPolynomial), Narkowicz 2014",
        [n_dot_v: Domain::COS, roughness: Domain::UNIT] -> [a: Domain::FINITE, b: Domain::UNIT],
        dfg::narkowicz_polynomial(n_dot_v, roughness)
    ),
    kernel!(
        "ibl::dfg::specular_filament",
        "Split-sum specular radiance from Filament's DFG channels, prefiltered mix(x, y, F0), \
         Guy and Agopian, Filament 5.3.4.3",
        [prefiltered_r: Domain::NONNEG, prefiltered_g: Domain::NONNEG,
         prefiltered_b: Domain::NONNEG,
         f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT,
         dfg_x: Domain::FINITE, dfg_y: Domain::FINITE]
            -> [radiance_r: Domain::FINITE, radiance_g: Domain::FINITE, radiance_b: Domain::FINITE],
        o3(dfg::specular_filament(
            v3(prefiltered_r, prefiltered_g, prefiltered_b),
            v3(f0_r, f0_g, f0_b),
            dfg_x,
            dfg_y
        ))
    ),
    kernel!(
        "ibl::dfg::specular",
        "Split-sum specular radiance prefiltered (F0 A + F90 B) per channel, Karis 2013; Lagarde \
         and de Rousiers 2014",
        [prefiltered_r: Domain::NONNEG, prefiltered_g: Domain::NONNEG,
         prefiltered_b: Domain::NONNEG,
         f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT, f90: Domain::UNIT,
         a: Domain::FINITE, b: Domain::FINITE]
            -> [radiance_r: Domain::FINITE, radiance_g: Domain::FINITE, radiance_b: Domain::FINITE],
        o3(dfg::specular(
            v3(prefiltered_r, prefiltered_g, prefiltered_b),
            v3(f0_r, f0_g, f0_b),
            f90,
            a,
            b,
        ))
    ),
    kernel!(
        "ibl::dfg::mip_from_roughness_linear",
        "Linear roughness-to-mip mapping r (n_mips - 1), Karis 2013 (LearnOpenGL, bevy)",
        [roughness: Domain::UNIT, n_mips: Domain::new(1.0, false, f64::INFINITY, true,
         ">= 1 and finite")]
            -> [mip: Domain::NONNEG],
        [dfg::mip_from_roughness_linear(roughness, n_mips)]
    ),
    kernel!(
        "ibl::dfg::roughness_from_mip_linear",
        "Roughness mip / (n_mips - 1) of a linearly mapped mip, Karis 2013",
        [mip: Domain::new(0.0, false, f64::INFINITY, true, "[0, n_mips - 1]"),
         n_mips: Domain::new(1.0, true, f64::INFINITY, true, "> 1 and finite")]
            -> [roughness: Domain::UNIT],
        where [Constraint::Holds {
            text: "mip <= n_mips - 1",
            args: &["mip", "n_mips"],
            check: |v| v.get("mip") <= v.get("n_mips") - 1.0,
        }],
        [dfg::roughness_from_mip_linear(mip, n_mips)]
    ),
    kernel!(
        "ibl::dfg::lod_from_roughness_filament",
        "Filament's roughness-to-lod mapping L r (2 - r) (perceptualRoughnessToLod), Guy and \
         Agopian 2018",
        [roughness: Domain::UNIT, roughness_one_level: Domain::NONNEG] -> [lod: Domain::NONNEG],
        [dfg::lod_from_roughness_filament(roughness, roughness_one_level)]
    ),
    kernel!(
        "ibl::dfg::roughness_from_lod_filament",
        "Filament's lod-to-roughness mapping 1 - sqrt(1 - lod / L) (lodToPerceptualRoughness), \
         Guy and Agopian 2018",
        [lod: Domain::new(0.0, false, f64::INFINITY, true, "[0, roughness_one_level]"),
         roughness_one_level: Domain::POSITIVE] -> [roughness: Domain::UNIT],
        where [le!("lod", "roughness_one_level", "lod <= roughness_one_level")],
        [dfg::roughness_from_lod_filament(lod, roughness_one_level)]
    ),
    kernel!(
        "ibl::dfg::mip_from_roughness_ue4",
        "UE4's roughness-to-mip mapping (ComputeReflectionCaptureMipFromRoughness), Karis 2013",
        [roughness: Domain::UNIT, cubemap_max_mip: Domain::FINITE] -> [mip: Domain::FINITE],
        [dfg::mip_from_roughness_ue4(roughness, cubemap_max_mip)]
    ),
    kernel!(
        "ibl::dfg::roughness_from_mip_ue4",
        "UE4's mip-to-roughness mapping 2^((1 - (M - 1 - mip)) / 1.2), Karis 2013",
        [mip: Domain::FINITE, cubemap_max_mip: Domain::FINITE] -> [roughness: Domain::NONNEG],
        [dfg::roughness_from_mip_ue4(mip, cubemap_max_mip)]
    ),
    // ---------------------------------------------------------------- ibl::prefilter
    kernel!(
        "ibl::prefilter::pdf",
        "Solid-angle pdf D(h) / 4 of a GGX prefilter direction, Walter et al. 2007 eq. 14",
        [dir_x: Domain::DIR, dir_y: Domain::DIR, dir_z: Domain::DIR,
         alpha: ALPHA] -> [pdf: Domain::NONNEG],
        [prefilter::pdf(v3(dir_x, dir_y, dir_z), alpha)]
    ),
    kernel!(
        "ibl::prefilter::sample_from",
        "GGX prefilter sample (direction, weight n.l, pdf) from a uniform pair, Karis 2013",
        [u1: Domain::SAMPLE, u2: Domain::SAMPLE, alpha: ALPHA]
            -> [dir_x: Domain::DIR_OUT, dir_y: Domain::DIR_OUT, dir_z: Domain::DIR_OUT,
                weight: Domain::UNIT, pdf: Domain::NONNEG],
        {
            let s = prefilter::sample_from(u1, u2, alpha);
            [s.dir.x, s.dir.y, s.dir.z, s.weight, s.pdf]
        }
    ),
    kernel!(
        "ibl::prefilter::mip_level",
        "Filtered importance sampling mip level, Krivanek and Colbert 2008",
        [pdf: Domain::NONNEG,
         sample_count: Domain::new(1.0, false, f64::INFINITY, true, ">= 1 and finite"),
         face_size: Domain::new(1.0, false, f64::INFINITY, true, ">= 1 and finite (texels)")]
            -> [lod: Domain::NONNEG],
        [prefilter::mip_level(pdf, sample_count, face_size)]
    ),
    // ---------------------------------------------------------------- ibl::energy
    kernel!(
        "ibl::energy::e_ggx",
        "GGX directional albedo E(mu, alpha) from the built-in table, Kulla and Conty 2017",
        [mu: Domain::COS, alpha: ALPHA] -> [e: Domain::closed(0.3, 1.0, "[0.3, 1]")],
        [energy::e_ggx(mu, alpha)]
    ),
    kernel!(
        "ibl::energy::e_avg_ggx",
        "GGX average albedo E_avg(alpha) from the built-in table, Kulla and Conty 2017",
        [alpha: ALPHA] -> [e_avg: Domain::closed(0.4, 1.0, "[0.40, 1]")],
        [energy::e_avg_ggx(alpha)]
    ),
    kernel!(
        "ibl::energy::kulla_conty_lobe",
        "Multiple-scattering lobe (1 - E_o)(1 - E_i) / (pi (1 - E_avg)), Kulla and Conty 2017; \
         Kelemen and Szirmay-Kalos 2001",
        [e_o: Domain::UNIT, e_i: Domain::UNIT, e_avg: Domain::UNIT] -> [f_ms: Domain::NONNEG],
        [energy::kulla_conty_lobe(Albedo(e_o), Albedo(e_i), AverageAlbedo(e_avg))]
    ),
    kernel!(
        "ibl::energy::kulla_conty_fresnel",
        "Multiple-scattering Fresnel F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), Kulla and Conty 2017",
        [f_avg: Domain::UNIT, e_avg: Domain::UNIT] -> [f_ms: Domain::UNIT],
        [energy::kulla_conty_fresnel(Reflectance(f_avg), AverageAlbedo(e_avg))]
    ),
    kernel!(
        "ibl::energy::fresnel_avg_schlick",
        "Hemispherical average of Schlick's Fresnel F0 + (F90 - F0) / 21, Fdez-Aguera 2019",
        [f0: Domain::UNIT, f90: Domain::UNIT] -> [f_avg: Domain::UNIT],
        [energy::fresnel_avg_schlick(f0, f90)]
    ),
    kernel!(
        lanewise "ibl::energy::fresnel_avg_conductor",
        "Hemispherical average of the conductor Fresnel by 32-point quadrature (f64), Kulla and \
         Conty 2017",
        [eta: ETA, k: KAPPA] -> [f_avg: Domain::UNIT],
        [T::splat(energy::fresnel_avg_conductor(f64_of(eta), f64_of(k)))]
    ),
    kernel!(
        "ibl::energy::kulla_conty_ggx",
        "Kulla-Conty multiple-scattering term of GGX from the built-in tables, Kulla and Conty \
         2017",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, alpha: ALPHA,
         f_avg: Domain::UNIT] -> [f_ms: Domain::NONNEG],
        [energy::kulla_conty_ggx(n_dot_v, n_dot_l, alpha, f_avg)]
    ),
    kernel!(
        "ibl::energy::kulla_conty_ggx_rgb",
        "Kulla-Conty multiple-scattering term of GGX for an RGB F_avg, Kulla and Conty 2017",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, alpha: ALPHA,
         f_avg_r: Domain::UNIT, f_avg_g: Domain::UNIT, f_avg_b: Domain::UNIT]
            -> [f_ms_r: Domain::NONNEG, f_ms_g: Domain::NONNEG, f_ms_b: Domain::NONNEG],
        o3(energy::kulla_conty_ggx_rgb(n_dot_v, n_dot_l, alpha, v3(f_avg_r, f_avg_g, f_avg_b)))
    ),
    kernel!(
        "ibl::energy::turquin_scale",
        "Energy-compensation factor 1 + F (1 - E) / E, Turquin 2019 eqs. 14 and 16",
        [e: Domain::new(0.0, true, 1.0, false, "(0, 1]"), f: Domain::UNIT]
            -> [scale: Domain::new(1.0, false, f64::INFINITY, true, "[1, 1 / e]")],
        [energy::turquin_scale(Albedo(e), Reflectance(f))]
    ),
    kernel!(
        "ibl::energy::fdez_aguera_ms",
        "Split-sum multiple-scattering term Fms Ems, Fdez-Aguera 2019 (JCGT 8(1)) Listing 1",
        [fss_ess: Domain::UNIT, e_ss: Domain::UNIT,
         f_avg: Domain::UNIT] -> [fms_ems: Domain::NONNEG],
        [energy::fdez_aguera_ms(fss_ess, Albedo(e_ss), Reflectance(f_avg))]
    ),
    kernel!(
        "ibl::energy::fdez_aguera",
        "Split-sum specular (FssEss, Fms Ems) from a DFG pair and F0, Fdez-Aguera 2019 Listing 1",
        [a: Domain::NONNEG, b: Domain::NONNEG, f0: Domain::UNIT]
            -> [fss_ess: Domain::UNIT, fms_ems: Domain::NONNEG],
        where [Constraint::Holds {
            text: "a + b <= 1",
            args: &["a", "b"],
            check: |v| v.get("a") + v.get("b") <= 1.0,
        }],
        {
            let (s, m) = energy::fdez_aguera(a, b, f0);
            [s, m]
        }
    ),
    // ---------------------------------------------------------------- ibl::irradiance
    kernel!(
        "ibl::irradiance::sh9_basis",
        "The nine real spherical harmonics of bands 0..2 at a unit direction, Ramamoorthi and \
         Hanrahan 2001 eq. 3",
        [d_x: Domain::DIR, d_y: Domain::DIR, d_z: Domain::DIR]
            -> [y0: Domain::FINITE, y1: Domain::FINITE, y2: Domain::FINITE, y3: Domain::FINITE,
                y4: Domain::FINITE, y5: Domain::FINITE, y6: Domain::FINITE, y7: Domain::FINITE,
                y8: Domain::FINITE],
        irradiance::sh9_basis(v3(d_x, d_y, d_z))
    ),
    kernel!(
        "ibl::irradiance::Sh9::eval",
        "Band-limited radiance sum_k L_k Y_k(dir) of nine RGB SH coefficients, Ramamoorthi and \
         Hanrahan 2001",
        [coeffs_0_r: Domain::FINITE, coeffs_0_g: Domain::FINITE, coeffs_0_b: Domain::FINITE,
         coeffs_1_r: Domain::FINITE, coeffs_1_g: Domain::FINITE, coeffs_1_b: Domain::FINITE,
         coeffs_2_r: Domain::FINITE, coeffs_2_g: Domain::FINITE, coeffs_2_b: Domain::FINITE,
         coeffs_3_r: Domain::FINITE, coeffs_3_g: Domain::FINITE, coeffs_3_b: Domain::FINITE,
         coeffs_4_r: Domain::FINITE, coeffs_4_g: Domain::FINITE, coeffs_4_b: Domain::FINITE,
         coeffs_5_r: Domain::FINITE, coeffs_5_g: Domain::FINITE, coeffs_5_b: Domain::FINITE,
         coeffs_6_r: Domain::FINITE, coeffs_6_g: Domain::FINITE, coeffs_6_b: Domain::FINITE,
         coeffs_7_r: Domain::FINITE, coeffs_7_g: Domain::FINITE, coeffs_7_b: Domain::FINITE,
         coeffs_8_r: Domain::FINITE, coeffs_8_g: Domain::FINITE, coeffs_8_b: Domain::FINITE,
         dir_x: Domain::DIR, dir_y: Domain::DIR, dir_z: Domain::DIR]
            -> [radiance_r: Domain::FINITE, radiance_g: Domain::FINITE, radiance_b: Domain::FINITE],
        o3(sh9(&[
            coeffs_0_r, coeffs_0_g, coeffs_0_b,
            coeffs_1_r, coeffs_1_g, coeffs_1_b,
            coeffs_2_r, coeffs_2_g, coeffs_2_b,
            coeffs_3_r, coeffs_3_g, coeffs_3_b,
            coeffs_4_r, coeffs_4_g, coeffs_4_b,
            coeffs_5_r, coeffs_5_g, coeffs_5_b,
            coeffs_6_r, coeffs_6_g, coeffs_6_b,
            coeffs_7_r, coeffs_7_g, coeffs_7_b,
            coeffs_8_r, coeffs_8_g, coeffs_8_b,
        ])
        .eval(v3(dir_x, dir_y, dir_z)))
    ),
    kernel!(
        "ibl::irradiance::Sh9::irradiance",
        "Irradiance at a unit normal from nine RGB SH coefficients, Ramamoorthi and Hanrahan \
         2001 eq. 13",
        [coeffs_0_r: Domain::FINITE, coeffs_0_g: Domain::FINITE, coeffs_0_b: Domain::FINITE,
         coeffs_1_r: Domain::FINITE, coeffs_1_g: Domain::FINITE, coeffs_1_b: Domain::FINITE,
         coeffs_2_r: Domain::FINITE, coeffs_2_g: Domain::FINITE, coeffs_2_b: Domain::FINITE,
         coeffs_3_r: Domain::FINITE, coeffs_3_g: Domain::FINITE, coeffs_3_b: Domain::FINITE,
         coeffs_4_r: Domain::FINITE, coeffs_4_g: Domain::FINITE, coeffs_4_b: Domain::FINITE,
         coeffs_5_r: Domain::FINITE, coeffs_5_g: Domain::FINITE, coeffs_5_b: Domain::FINITE,
         coeffs_6_r: Domain::FINITE, coeffs_6_g: Domain::FINITE, coeffs_6_b: Domain::FINITE,
         coeffs_7_r: Domain::FINITE, coeffs_7_g: Domain::FINITE, coeffs_7_b: Domain::FINITE,
         coeffs_8_r: Domain::FINITE, coeffs_8_g: Domain::FINITE, coeffs_8_b: Domain::FINITE,
         n_x: Domain::DIR, n_y: Domain::DIR, n_z: Domain::DIR]
            -> [irradiance_r: Domain::FINITE, irradiance_g: Domain::FINITE,
                irradiance_b: Domain::FINITE],
        o3(sh9(&[
            coeffs_0_r, coeffs_0_g, coeffs_0_b,
            coeffs_1_r, coeffs_1_g, coeffs_1_b,
            coeffs_2_r, coeffs_2_g, coeffs_2_b,
            coeffs_3_r, coeffs_3_g, coeffs_3_b,
            coeffs_4_r, coeffs_4_g, coeffs_4_b,
            coeffs_5_r, coeffs_5_g, coeffs_5_b,
            coeffs_6_r, coeffs_6_g, coeffs_6_b,
            coeffs_7_r, coeffs_7_g, coeffs_7_b,
            coeffs_8_r, coeffs_8_g, coeffs_8_b,
        ])
        .irradiance(v3(n_x, n_y, n_z)))
    ),
    // ---------------------------------------------------------------- tonemap
    kernel!(
        "tonemap::sanitize",
        "The operators' input clamp: negative -> 0, above MAX_INPUT (1e9) -> MAX_INPUT",
        [x: Domain::ANY] -> [out: Domain::closed(0.0, tonemap::MAX_INPUT, "[0, MAX_INPUT]")],
        [tonemap::sanitize(x)]
    ),
    kernel!(
        "tonemap::exposure_curve",
        "Exponential exposure curve 1 - exp(-c exposure) per channel",
        [c: HDR, exposure: Domain::new(0.0, true, f64::INFINITY, true, "(0,
         MAX]")] -> [out: DISPLAY],
        [tonemap::exposure_curve(c, exposure)]
    ),
    kernel!(
        "tonemap::reinhard",
        "Reinhard c / (1 + c) per channel, Reinhard et al. 2002 eq. 3",
        [c: HDR] -> [out: DISPLAY],
        [tonemap::reinhard(c)]
    ),
    kernel!(
        "tonemap::reinhard_extended",
        "Extended Reinhard c (1 + c / w^2) / (1 + c) per channel, Reinhard et al. 2002 eq. 4",
        [c: HDR, white: Domain::new(0.0, true, f64::INFINITY, true, "(0, MAX]")] -> [out: DISPLAY],
        [tonemap::reinhard_extended(c, white)]
    ),
    kernel!(
        "tonemap::reinhard_luminance",
        "Reinhard on luminance c / (1 + L), Reinhard et al. 2002",
        [c_r: HDR, c_g: HDR, c_b: HDR] -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        o3(tonemap::reinhard_luminance(v3(c_r, c_g, c_b)))
    ),
    kernel!(
        "tonemap::reinhard_extended_luminance",
        "Extended Reinhard on luminance, Reinhard et al. 2002 eq. 4",
        [c_r: HDR, c_g: HDR, c_b: HDR, white: Domain::new(0.0, true, f64::INFINITY, true, "(0,
         MAX]")]
            -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        o3(tonemap::reinhard_extended_luminance(v3(c_r, c_g, c_b), white))
    ),
    kernel!(
        "tonemap::reinhard_jodie",
        "Reinhard-Jodie: per-channel Reinhard blended toward luminance Reinhard (Shadertoy 2019; \
         Reinhard et al. 2002)",
        [c_r: HDR, c_g: HDR, c_b: HDR] -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        o3(tonemap::reinhard_jodie(v3(c_r, c_g, c_b)))
    ),
    kernel!(
        "tonemap::aces_narkowicz",
        "Narkowicz's ACES filmic curve fit per channel, Narkowicz 2015",
        [c: HDR] -> [out: DISPLAY],
        [tonemap::aces_narkowicz(c)]
    ),
    kernel!(
        "tonemap::aces_hill",
        "ACES RRT + sRGB ODT fitted by Stephen Hill (ACESFitted.hlsl), Hill 2016",
        [c_r: HDR, c_g: HDR, c_b: HDR] -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        o3(tonemap::aces_hill(v3(c_r, c_g, c_b)))
    ),
    kernel!(
        lanewise "tonemap::hable",
        "Hable's filmic curve (Uncharted 2) per channel, Hable 2010",
        [c: HDR, p_a: POS, p_b: POS, p_c: POS, p_d: POS, p_e: POS, p_f: POS, p_white: POS,
         p_exposure_bias: POS] -> [out: DISPLAY],
        where [Constraint::Holds {
            text: "HableParams::new accepts the parameters: the curve reaches white, \
                   F(W) = ((F - E) A W + B (F C - E)) / ... > 0, and its coefficients are finite",
            args: &["p_a", "p_b", "p_c", "p_d", "p_e", "p_f", "p_white", "p_exposure_bias"],
            check: |v| {
                HableParams::new(
                    v.get("p_a"),
                    v.get("p_b"),
                    v.get("p_c"),
                    v.get("p_d"),
                    v.get("p_e"),
                    v.get("p_f"),
                    v.get("p_white"),
                    v.get("p_exposure_bias"),
                )
                .is_ok()
            },
        }],
        built(
            HableParams::new(
                f64_of(p_a),
                f64_of(p_b),
                f64_of(p_c),
                f64_of(p_d),
                f64_of(p_e),
                f64_of(p_f),
                f64_of(p_white),
                f64_of(p_exposure_bias),
            ),
            |p| [tonemap::hable(c, &p)],
        )
    ),
    kernel!(
        lanewise "tonemap::lottes",
        "Lottes' curve x^a / (x^(a d) b + c) per channel, Lottes 2016",
        [c: HDR, contrast: POS, shoulder: POS, hdr_max: POS, mid_in: POS,
         mid_out: Domain::new(0.0, true, 1.0, true, "(0, 1)")] -> [out: DISPLAY],
        where [Constraint::Holds {
            text: "mid_in < hdr_max, contrast <= LOTTES_CONTRAST_MAX, and the derived b, c \
                   finite with c != 0 (LottesParams::new accepts the parameters)",
            args: &["contrast", "shoulder", "hdr_max", "mid_in", "mid_out"],
            check: |v| {
                v.get("mid_in") < v.get("hdr_max")
                    && LottesParams::new(
                        v.get("contrast"),
                        v.get("shoulder"),
                        v.get("hdr_max"),
                        v.get("mid_in"),
                        v.get("mid_out"),
                    )
                    .is_ok()
            },
        }],
        built(
            LottesParams::new(
                f64_of(contrast),
                f64_of(shoulder),
                f64_of(hdr_max),
                f64_of(mid_in),
                f64_of(mid_out),
            ),
            |p| [tonemap::lottes(c, &p)],
        )
    ),
    kernel!(
        lanewise "tonemap::uchimura",
        "Uchimura's GT curve (toe, linear section, shoulder) per channel, Uchimura 2017",
        [c: HDR, max_brightness: POS, contrast: POS, linear_start: POS,
         linear_length: Domain::NONNEG,
         black: POS, pedestal: Domain::FINITE] -> [out: DISPLAY],
        where [Constraint::Holds {
            text: "linear_start + contrast l0 < max_brightness, \
                   l0 = (max_brightness - linear_start) linear_length / contrast, with \
                   S0 = linear_start + l0, S1 = linear_start + contrast l0 and \
                   max_brightness - S1 finite",
            args: &["max_brightness", "contrast", "linear_start", "linear_length"],
            check: |v| {
                let (pm, a) = (v.get("max_brightness"), v.get("contrast"));
                let (m, l) = (v.get("linear_start"), v.get("linear_length"));
                let l0 = (pm - m) * l / a;
                let (s0, s1) = (m + l0, m + a * l0);
                s1 < pm && s0.is_finite() && s1.is_finite() && (pm - s1).is_finite()
            },
        }],
        {
            let p = UchimuraParams {
                max_brightness: f64_of(max_brightness),
                contrast: f64_of(contrast),
                linear_start: f64_of(linear_start),
                linear_length: f64_of(linear_length),
                black: f64_of(black),
                pedestal: f64_of(pedestal),
            };
            [tonemap::uchimura(c, &p)]
        }
    ),
    kernel!(
        "tonemap::pbr_neutral",
        "Khronos PBR Neutral tone mapper, Khronos Group 2024",
        [c_r: HDR, c_g: HDR, c_b: HDR] -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        o3(tonemap::pbr_neutral(v3(c_r, c_g, c_b)))
    ),
    kernel!(
        "tonemap::agx_minimal",
        "Minimal AgX on Rec.709 with a look, Wrensch 2023; Sobotka 2022",
        [c_r: HDR, c_g: HDR, c_b: HDR, look: LOOK]
            -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        pick(look, 4, |k| o3(tonemap::agx_minimal(v3(c_r, c_g, c_b), &self::look(k))))
    ),
    kernel!(
        "tonemap::agx_threejs",
        "three.js's AgXToneMapping (Rec.2020, Wrensch's curve), three.js r162; Sobotka 2022",
        [c_r: HDR, c_g: HDR, c_b: HDR] -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        o3(tonemap::agx_threejs(v3(c_r, c_g, c_b)))
    ),
    kernel!(
        "tonemap::agx_filament",
        "Filament's AgxToneMapper on Rec.2020 with a look, Filament ToneMapper.cpp; Sobotka 2022",
        [c_r: HDR, c_g: HDR, c_b: HDR, look: LOOK]
            -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        pick(look, 4, |k| o3(tonemap::agx_filament(v3(c_r, c_g, c_b), &self::look(k))))
    ),
    kernel!(
        "tonemap::Operator::apply",
        "Any tonemapping operator with its default parameters, by index into Operator::all()",
        [operator: OPERATOR, c_r: HDR, c_g: HDR, c_b: HDR]
            -> [out_r: DISPLAY, out_g: DISPLAY, out_b: DISPLAY],
        pick(operator, 19, |k| o3(Operator::all()[k].apply(v3(c_r, c_g, c_b))))
    ),
    kernel!(
        lanewise "tonemap::ev100_from_camera",
        "EV100 = log2(N^2 / t * 100 / S) from aperture, shutter time and ISO (f64), Lagarde and \
         de Rousiers 2014 eq. 12",
        [aperture: POS, shutter_s: POS, iso: POS] -> [ev100: Domain::FINITE],
        [T::splat(tonemap::ev100_from_camera(f64_of(aperture), f64_of(shutter_s), f64_of(iso)))]
    ),
    // ---------------------------------------------------------------- color
    kernel!(
        "color::luminance",
        "Relative luminance of linear Rec.709 with weights (0.2126, 0.7152, 0.0722), ITU-R BT.709",
        [c_r: Domain::FINITE, c_g: Domain::FINITE,
         c_b: Domain::FINITE] -> [luminance: Domain::FINITE],
        [color::luminance(v3(c_r, c_g, c_b))]
    ),
    kernel!(
        lanewise "color::mul",
        "Colour matrix times colour m c (a 3 x 3 matrix given row-major)",
        [m_0_0: Domain::FINITE, m_0_1: Domain::FINITE, m_0_2: Domain::FINITE,
         m_1_0: Domain::FINITE, m_1_1: Domain::FINITE, m_1_2: Domain::FINITE,
         m_2_0: Domain::FINITE, m_2_1: Domain::FINITE, m_2_2: Domain::FINITE,
         c_r: Domain::FINITE, c_g: Domain::FINITE, c_b: Domain::FINITE]
            -> [out_r: Domain::FINITE, out_g: Domain::FINITE, out_b: Domain::FINITE],
        where [Constraint::Holds {
            text: "each row's sum |m_i0 c_r| + |m_i1 c_g| + |m_i2 c_b| stays below MAX",
            args: &[
                "m_0_0", "m_0_1", "m_0_2", "m_1_0", "m_1_1", "m_1_2", "m_2_0", "m_2_1", "m_2_2",
                "c_r", "c_g", "c_b",
            ],
            check: |v| {
                let c = [v.get("c_r"), v.get("c_g"), v.get("c_b")];
                let m = |i: usize, j: usize| v.get(&format!("m_{i}_{j}"));
                (0..3).all(|i| (0..3).map(|j| (m(i, j) * c[j]).abs()).sum::<f64>() < v.max)
            },
        }],
        {
            let m = [
                [f64_of(m_0_0), f64_of(m_0_1), f64_of(m_0_2)],
                [f64_of(m_1_0), f64_of(m_1_1), f64_of(m_1_2)],
                [f64_of(m_2_0), f64_of(m_2_1), f64_of(m_2_2)],
            ];
            o3(color::mul(&m, v3(c_r, c_g, c_b)))
        }
    ),
    kernel!(
        "color::srgb_oetf",
        "sRGB inverse EOTF (linear to encoded), IEC 61966-2-1:1999 section 5.2",
        [x: SIGNAL] -> [encoded: Domain::NONNEG_INF],
        [color::srgb_oetf(x)]
    ),
    kernel!(
        "color::srgb_oetf_fast",
        "sRGB inverse EOTF in the input's precision (one pow), IEC 61966-2-1:1999",
        [x: SIGNAL] -> [encoded: Domain::NONNEG_INF],
        [color::srgb_oetf_fast(x)]
    ),
    kernel!(
        "color::srgb_eotf",
        "sRGB EOTF (encoded to linear), IEC 61966-2-1:1999 section 5.2",
        [x: SIGNAL] -> [linear: Domain::NONNEG_INF],
        [color::srgb_eotf(x)]
    ),
    kernel!(
        "color::rec709_oetf",
        "Rec.709 OETF 4.5 L or 1.099 L^0.45 - 0.099, ITU-R BT.709-6 item 1.2",
        [l: SIGNAL] -> [encoded: Domain::NONNEG_INF],
        [color::rec709_oetf(l)]
    ),
    kernel!(
        "color::gamma_encode",
        "Plain gamma encoding x^(1 / gamma) (display gamma correction)",
        [x: SIGNAL, gamma: Domain::new(0.0, true, f64::INFINITY, true, "(0,
         MAX]")] -> [encoded: Domain::NONNEG_INF],
        [color::gamma_encode(x, gamma)]
    ),
    kernel!(
        "color::gamma_decode",
        "Plain gamma decoding x^gamma, the inverse of gamma_encode",
        [x: SIGNAL, gamma: Domain::new(0.0, true, f64::INFINITY, true, "(0,
         MAX]")] -> [linear: Domain::NONNEG_INF],
        [color::gamma_decode(x, gamma)]
    ),
    kernel!(
        "color::srgb_oetf_rgb",
        "sRGB inverse EOTF per channel, IEC 61966-2-1:1999",
        [c_r: SIGNAL, c_g: SIGNAL, c_b: SIGNAL]
            -> [encoded_r: Domain::NONNEG_INF, encoded_g: Domain::NONNEG_INF,
                encoded_b: Domain::NONNEG_INF],
        o3(color::srgb_oetf_rgb(v3(c_r, c_g, c_b)))
    ),
    kernel!(
        "color::srgb_eotf_rgb",
        "sRGB EOTF per channel, IEC 61966-2-1:1999",
        [c_r: SIGNAL, c_g: SIGNAL, c_b: SIGNAL]
            -> [linear_r: Domain::NONNEG_INF, linear_g: Domain::NONNEG_INF,
                linear_b: Domain::NONNEG_INF],
        o3(color::srgb_eotf_rgb(v3(c_r, c_g, c_b)))
    ),
    // ---------------------------------------------------------------- layers::sheen
    kernel!(
        "layers::sheen::d_charlie",
        "Charlie sheen NDF (2 + 1/alpha) sin^(1/alpha) / (2 pi), Estevez and Kulla 2017 eq. 2",
        [n_dot_h: Domain::COS, alpha: Domain::UNIT] -> [d: Domain::NONNEG],
        [sheen::d_charlie(n_dot_h, alpha)]
    ),
    kernel!(
        "layers::sheen::lambda_charlie",
        "Charlie sheen's fitted Smith Lambda, Estevez and Kulla 2017 section 3",
        [n_dot_v: Domain::COS, alpha: Domain::UNIT] -> [lambda: Domain::NONNEG],
        [sheen::lambda_charlie(n_dot_v, alpha)]
    ),
    kernel!(
        "layers::sheen::v_charlie",
        "Charlie sheen visibility 1 / ((1 + Lambda_v + Lambda_l) 4 NoV NoL), Estevez and Kulla \
         2017",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, alpha: Domain::UNIT] -> [v: Domain::NONNEG],
        [sheen::v_charlie(n_dot_v, n_dot_l, alpha)]
    ),
    kernel!(
        "layers::sheen::v_neubelt",
        "Cloth visibility 1 / (4 (NoL + NoV - NoL NoV)), Neubelt and Pettineo 2013",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS] -> [v: Domain::NONNEG],
        [sheen::v_neubelt(n_dot_v, n_dot_l)]
    ),
    kernel!(
        "layers::sheen::d_ashikhmin",
        "Ashikhmin's velvet NDF, Ashikhmin and Premoze 2007",
        [n_dot_h: Domain::COS, alpha: Domain::UNIT] -> [d: Domain::NONNEG],
        [sheen::d_ashikhmin(n_dot_h, alpha)]
    ),
    kernel!(
        "layers::sheen::charlie",
        "glTF sheen lobe sheenColor D_charlie V_charlie, RGB, KHR_materials_sheen",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         sheen_color_r: Domain::UNIT, sheen_color_g: Domain::UNIT, sheen_color_b: Domain::UNIT,
         alpha: Domain::UNIT]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        o3(sheen::charlie(
            cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h),
            v3(sheen_color_r, sheen_color_g, sheen_color_b),
            alpha,
        ))
    ),
    kernel!(
        "layers::sheen::albedo",
        "Sheen directional albedo from the built-in table, KHR_materials_sheen",
        [n_dot_v: Domain::COS, alpha: Domain::UNIT] -> [e: Domain::UNIT],
        [sheen::albedo(n_dot_v, alpha)]
    ),
    kernel!(
        "layers::sheen::albedo_fit_materialx",
        "MaterialX's rational fit of the Imageworks sheen albedo (Neubelt visibility)",
        [n_dot_v: Domain::COS, alpha: Domain::UNIT] -> [e: Domain::UNIT],
        [sheen::albedo_fit_materialx(n_dot_v, alpha)]
    ),
    kernel!(
        "layers::sheen::albedo_fit_threejs",
        "three.js's exponential fit of the sheen albedo (IBLSheenBRDF's DG)",
        [n_dot_v: Domain::COS, roughness: Domain::UNIT] -> [e: Domain::UNIT],
        [sheen::albedo_fit_threejs(n_dot_v, roughness)]
    ),
    kernel!(
        "layers::sheen::albedo_scaling",
        "Albedo scaling min(1 - max(c) E_v, 1 - max(c) E_l) of the layer below, \
         KHR_materials_sheen",
        [sheen_color_r: Domain::UNIT, sheen_color_g: Domain::UNIT, sheen_color_b: Domain::UNIT,
         e_v: Domain::UNIT, e_l: Domain::UNIT] -> [s: Domain::UNIT],
        [sheen::albedo_scaling(v3(sheen_color_r, sheen_color_g, sheen_color_b), e_v, e_l)]
    ),
    // ---------------------------------------------------------------- layers::clearcoat
    kernel!(
        "layers::clearcoat::fresnel",
        "Clearcoat Schlick Fresnel 0.04 + 0.96 (1 - c)^5, KHR_materials_clearcoat",
        [cos_theta: Domain::COS] -> [f: Domain::UNIT],
        [clearcoat::fresnel(cos_theta)]
    ),
    kernel!(
        "layers::clearcoat::v_kelemen",
        "Kelemen's visibility 1 / (4 VoH^2), Kelemen and Szirmay-Kalos 2001",
        [v_dot_h: Domain::COS] -> [v: Domain::NONNEG],
        [clearcoat::v_kelemen(v_dot_h)]
    ),
    kernel!(
        "layers::clearcoat::coat",
        "Clearcoat lobe F(VoH) D V (exact Smith), F0 0.04, KHR_materials_clearcoat",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA] -> [f: Domain::NONNEG],
        [clearcoat::coat(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), alpha)]
    ),
    kernel!(
        "layers::clearcoat::coat_kelemen",
        "Clearcoat lobe F(VoH) D V_kelemen, Filament section 4.9",
        [n_dot_v: Domain::COS, n_dot_l: Domain::COS, n_dot_h: Domain::COS, v_dot_h: Domain::COS,
         alpha: ALPHA] -> [f: Domain::NONNEG],
        [clearcoat::coat_kelemen(cosines(n_dot_v, n_dot_l, n_dot_h, v_dot_h), alpha)]
    ),
    kernel!(
        "layers::clearcoat::layer",
        "Coat over base: clearcoat coat + (1 - clearcoat F) base, RGB, KHR_materials_clearcoat",
        [base_r: Domain::NONNEG, base_g: Domain::NONNEG, base_b: Domain::NONNEG,
         coat: Domain::NONNEG, clearcoat: Domain::UNIT, f_coat: Domain::UNIT]
            -> [f_r: Domain::NONNEG_INF, f_g: Domain::NONNEG_INF, f_b: Domain::NONNEG_INF],
        o3(clearcoat::layer(v3(base_r, base_g, base_b), coat, clearcoat, f_coat))
    ),
    // ---------------------------------------------------------------- layers::specular
    kernel!(
        "layers::specular::f0_from_ior",
        "F0 ((ior - 1) / (ior + 1))^2, 1 for the special ior 0, KHR_materials_ior",
        [ior: Domain::closed(0.0, f64::INFINITY, "0 or [1, MAX]")] -> [f0: Domain::UNIT],
        where [Constraint::Holds {
            text: "ior = 0 or ior >= 1",
            args: &["ior"],
            check: |v| {
                let x = v.get("ior");
                (x == 0.0 || x >= 1.0) && x <= v.max
            },
        }],
        [specular::f0_from_ior(ior)]
    ),
    kernel!(
        "layers::specular::dielectric_f0",
        "Dielectric F0 min(F0_ior color, 1) specular, RGB, KHR_materials_specular",
        [f0_ior: Domain::UNIT, specular: Domain::UNIT, specular_color_r: Domain::NONNEG,
         specular_color_g: Domain::NONNEG, specular_color_b: Domain::NONNEG]
            -> [f0_r: Domain::UNIT, f0_g: Domain::UNIT, f0_b: Domain::UNIT],
        o3(specular::dielectric_f0(
            f0_ior,
            specular,
            v3(specular_color_r, specular_color_g, specular_color_b),
        ))
    ),
    // ---------------------------------------------------------------- layers::anisotropy
    kernel!(
        "layers::anisotropy::alpha_t",
        "Tangent alpha mix(alpha, 1, strength^2), KHR_materials_anisotropy",
        [alpha: Domain::UNIT, strength: Domain::UNIT] -> [alpha_t: Domain::UNIT],
        [anisotropy::alpha_t(alpha, strength)]
    ),
    kernel!(
        "layers::anisotropy::direction",
        "Anisotropy direction: normalized (x, y) rotated by rotation, KHR_materials_anisotropy",
        [x: Domain::FINITE, y: Domain::FINITE, rotation: Domain::FINITE]
            -> [out_x: Domain::DIR_OUT, out_y: Domain::DIR_OUT, out_z: Domain::DIR_OUT],
        o3(anisotropy::direction(x, y, rotation))
    ),
    kernel!(
        "layers::anisotropy::bent_reflection",
        "Bent reflection vector for anisotropic IBL, Khronos sample viewer; Filament 5.3.9",
        [n_x: Domain::DIR, n_y: Domain::DIR, n_z: Domain::DIR,
         v_x: Domain::DIR, v_y: Domain::DIR, v_z: Domain::DIR,
         b_x: Domain::DIR, b_y: Domain::DIR, b_z: Domain::DIR,
         strength: Domain::UNIT, roughness: Domain::UNIT]
            -> [r_x: Domain::DIR_OUT, r_y: Domain::DIR_OUT, r_z: Domain::DIR_OUT],
        o3(anisotropy::bent_reflection(
            v3(n_x, n_y, n_z),
            v3(v_x, v_y, v_z),
            v3(b_x, b_y, b_z),
            strength,
            roughness,
        ))
    ),
    // ---------------------------------------------------------------- layers::layered
    kernel!(
        "layers::layered::Layered::eval",
        "Layered glTF material (sheen, clearcoat, anisotropy, iridescence, transmission, volume over \
         metallic-roughness), RGB",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         sheen_color_r: Domain::UNIT, sheen_color_g: Domain::UNIT, sheen_color_b: Domain::UNIT,
         sheen_roughness: Domain::UNIT, clearcoat: Domain::UNIT,
         clearcoat_roughness: Domain::UNIT, anisotropy_strength: Domain::UNIT,
         anisotropy_rotation: Domain::FINITE, iridescence_factor: Domain::UNIT,
         iridescence_thickness: FILM_THICKNESS, iridescence_ior: FILM_IOR,
         transmission: Domain::UNIT, volume_thickness: Domain::NONNEG,
         volume_attenuation_color_r: Domain::UNIT, volume_attenuation_color_g: Domain::UNIT,
         volume_attenuation_color_b: Domain::UNIT, volume_attenuation_distance: ETA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR]
            -> [f_r: Domain::NONNEG, f_g: Domain::NONNEG, f_b: Domain::NONNEG],
        built(
            layered([
                base_color_r,
                base_color_g,
                base_color_b,
                metallic,
                roughness,
                sheen_color_r,
                sheen_color_g,
                sheen_color_b,
                sheen_roughness,
                clearcoat,
                clearcoat_roughness,
                anisotropy_strength,
                anisotropy_rotation,
                iridescence_factor,
                iridescence_thickness,
                iridescence_ior,
                transmission,
                volume_thickness,
                volume_attenuation_color_r,
                volume_attenuation_color_g,
                volume_attenuation_color_b,
                volume_attenuation_distance,
            ]),
            |m| o3(m.eval(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))),
        )
    ),
    kernel!(
        "layers::layered::Layered::lobe_probabilities",
        "Lobe-selection probabilities (coat, specular, cosine) of the layered material",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         sheen_color_r: Domain::UNIT, sheen_color_g: Domain::UNIT, sheen_color_b: Domain::UNIT,
         sheen_roughness: Domain::UNIT, clearcoat: Domain::UNIT,
         clearcoat_roughness: Domain::UNIT, anisotropy_strength: Domain::UNIT,
         anisotropy_rotation: Domain::FINITE, iridescence_factor: Domain::UNIT,
         iridescence_thickness: FILM_THICKNESS, iridescence_ior: FILM_IOR,
         transmission: Domain::UNIT, volume_thickness: Domain::NONNEG,
         volume_attenuation_color_r: Domain::UNIT, volume_attenuation_color_g: Domain::UNIT,
         volume_attenuation_color_b: Domain::UNIT, volume_attenuation_distance: ETA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR]
            -> [p_coat: Domain::UNIT, p_spec: Domain::UNIT, p_cos: Domain::UNIT],
        built(
            layered([
                base_color_r,
                base_color_g,
                base_color_b,
                metallic,
                roughness,
                sheen_color_r,
                sheen_color_g,
                sheen_color_b,
                sheen_roughness,
                clearcoat,
                clearcoat_roughness,
                anisotropy_strength,
                anisotropy_rotation,
                iridescence_factor,
                iridescence_thickness,
                iridescence_ior,
                transmission,
                volume_thickness,
                volume_attenuation_color_r,
                volume_attenuation_color_g,
                volume_attenuation_color_b,
                volume_attenuation_distance,
            ]),
            |m| o3(m.lobe_probabilities(v3(wo_x, wo_y, wo_z))),
        )
    ),
    kernel!(
        "layers::layered::Layered::pdf",
        "One-sample mixture pdf of the layered material, Heitz 2018",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         sheen_color_r: Domain::UNIT, sheen_color_g: Domain::UNIT, sheen_color_b: Domain::UNIT,
         sheen_roughness: Domain::UNIT, clearcoat: Domain::UNIT,
         clearcoat_roughness: Domain::UNIT, anisotropy_strength: Domain::UNIT,
         anisotropy_rotation: Domain::FINITE, iridescence_factor: Domain::UNIT,
         iridescence_thickness: FILM_THICKNESS, iridescence_ior: FILM_IOR,
         transmission: Domain::UNIT, volume_thickness: Domain::NONNEG,
         volume_attenuation_color_r: Domain::UNIT, volume_attenuation_color_g: Domain::UNIT,
         volume_attenuation_color_b: Domain::UNIT, volume_attenuation_distance: ETA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR,
         wi_x: Domain::DIR, wi_y: Domain::DIR, wi_z: Domain::DIR]
            -> [pdf: Domain::NONNEG],
        built(
            layered([
                base_color_r,
                base_color_g,
                base_color_b,
                metallic,
                roughness,
                sheen_color_r,
                sheen_color_g,
                sheen_color_b,
                sheen_roughness,
                clearcoat,
                clearcoat_roughness,
                anisotropy_strength,
                anisotropy_rotation,
                iridescence_factor,
                iridescence_thickness,
                iridescence_ior,
                transmission,
                volume_thickness,
                volume_attenuation_color_r,
                volume_attenuation_color_g,
                volume_attenuation_color_b,
                volume_attenuation_distance,
            ]),
            |m| [m.pdf(v3(wo_x, wo_y, wo_z), v3(wi_x, wi_y, wi_z))],
        )
    ),
    kernel!(
        "layers::layered::Layered::sample",
        "Layered material sample by lobe selection, with its pdf, Heitz 2018",
        [base_color_r: Domain::UNIT, base_color_g: Domain::UNIT, base_color_b: Domain::UNIT,
         metallic: Domain::UNIT, roughness: Domain::UNIT,
         sheen_color_r: Domain::UNIT, sheen_color_g: Domain::UNIT, sheen_color_b: Domain::UNIT,
         sheen_roughness: Domain::UNIT, clearcoat: Domain::UNIT,
         clearcoat_roughness: Domain::UNIT, anisotropy_strength: Domain::UNIT,
         anisotropy_rotation: Domain::FINITE, iridescence_factor: Domain::UNIT,
         iridescence_thickness: FILM_THICKNESS, iridescence_ior: FILM_IOR,
         transmission: Domain::UNIT, volume_thickness: Domain::NONNEG,
         volume_attenuation_color_r: Domain::UNIT, volume_attenuation_color_g: Domain::UNIT,
         volume_attenuation_color_b: Domain::UNIT, volume_attenuation_distance: ETA,
         wo_x: Domain::DIR, wo_y: Domain::DIR, wo_z: Domain::DIR, u1: Domain::SAMPLE,
         u2: Domain::SAMPLE]
            -> [wi_x: Domain::DIR_OUT, wi_y: Domain::DIR_OUT, wi_z: Domain::DIR_OUT,
                pdf: Domain::NONNEG],
        built(
            layered([
                base_color_r,
                base_color_g,
                base_color_b,
                metallic,
                roughness,
                sheen_color_r,
                sheen_color_g,
                sheen_color_b,
                sheen_roughness,
                clearcoat,
                clearcoat_roughness,
                anisotropy_strength,
                anisotropy_rotation,
                iridescence_factor,
                iridescence_thickness,
                iridescence_ior,
                transmission,
                volume_thickness,
                volume_attenuation_color_r,
                volume_attenuation_color_g,
                volume_attenuation_color_b,
                volume_attenuation_distance,
            ]),
            |m| o4(m.sample(v3(wo_x, wo_y, wo_z), u1, u2)),
        )
    ),
];

#[cfg(test)]
mod arrays_tests {
    use super::{KERNELS, find};
    use brdf::Real;
    use brdf::wide::f32x8;

    #[test]
    #[allow(clippy::cast_precision_loss)]
    fn arrays_equal_the_lane_entry_per_element_and_refuse_wrong_lengths() {
        // Eleven elements: one full group of eight and a partial one, an argument broadcast,
        // and an invalid alpha in element 3, which must not turn its group's other lanes NaN.
        let k = find("ggx::Ggx::d").expect("row");
        let n = 11;
        let ax: Vec<f32> = (0..n)
            .map(|i| if i == 3 { -1.0 } else { 0.05 * (i + 1) as f32 })
            .collect();
        let mz: Vec<f32> = (0..n).map(|i| 1.0 - 0.08 * i as f32).collect();
        let ins: [&[f32]; 5] = [&ax, &[0.3], &[0.0], &[0.0], &mz];
        let mut d = vec![0.0f32; n];
        assert!((k.f32_arrays)(&ins, &mut [&mut d], n));
        for i in 0..n {
            let row = [ax[i], 0.3, 0.0, 0.0, mz[i]].map(f32x8::splat);
            let mut y = [f32x8::splat(0.0)];
            (k.f32x8)(&row, &mut y);
            let (got, want) = (d[i], y[0].lane(0));
            assert!(
                got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                "{i}"
            );
            assert_eq!(got.is_nan(), i == 3, "{i}");
        }
        // Wrong counts or lengths: false, nothing written.
        let mut d = vec![7.0f32; n];
        assert!(!(k.f32_arrays)(&ins[..4], &mut [&mut d], n));
        assert!(!(k.f32_arrays)(&ins, &mut [&mut d], n + 1));
        let short = [&ax[..5], &[0.3][..], &[0.0][..], &[0.0][..], &mz[..]];
        assert!(!(k.f32_arrays)(&short, &mut [&mut d], n));
        assert!(d.iter().all(|&v| v == 7.0));
        assert!(KERNELS.iter().all(|k| !(k.f64_arrays)(&[], &mut [], 0)));
    }
}
