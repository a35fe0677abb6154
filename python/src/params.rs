//! The validated parameter types: each constructor of `brdf` that returns
//! `Result<_, ParamError>`, callable on plain values so the Python classes (`brdf.ggx.Ggx`,
//! `brdf.diffuse.Eon`, ...) validate at construction with the crate's own rules and name the
//! offending parameter in a `ValueError`.

use brdf::beckmann::Beckmann;
use brdf::diffuse::{
    AshikhminShirley, Burley, BurleyRenormalized, Eon, Lambert, OrenNayar, OrenNayarFujii,
    OrenNayarFull, ShirleyCoupled,
};
use brdf::ggx::Ggx;
use brdf::lights::SpotCone;
use brdf::material::MetallicRoughness;
use brdf::phong::{
    ApproxNormalizedBlinnPhong, BlinnPhong, ClassicPhong, ModifiedPhong, NormalizedBlinnPhong,
    NormalizedPhong, PhongDiffuseSpecular,
};
use brdf::tonemap::{HableParams, LottesParams};
use brdf::{ParamError, Real, V3};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;

/// A constructor on `f32` or `f64` values (`f64` only for the tonemap curves, whose
/// parameters are `f64` in the crate).
type Check = fn(&[f64], bool) -> Result<(), ParamError>;

/// `new` of a type generic over `T: Real`, on `f32` (rounded) or `f64` values.
macro_rules! generic {
    (|$a:ident| $build:expr) => {{
        fn run<T: Real>($a: &[T]) -> Result<(), ParamError> {
            $build.map(|_| ())
        }
        |v: &[f64], f32: bool| {
            if f32 {
                #[allow(clippy::cast_possible_truncation)]
                let x: Vec<f32> = v.iter().map(|&x| x as f32).collect();
                run(&x)
            } else {
                run(v)
            }
        }
    }};
}

/// Type path, its constructor's arguments (flattened as the kernel table flattens them),
/// the check.
static TYPES: &[(&str, &[&str], Check)] = &[
    (
        "ggx::Ggx",
        &["alpha_x", "alpha_y"],
        generic!(|a| Ggx::new(a[0], a[1])),
    ),
    (
        "beckmann::Beckmann",
        &["alpha_x", "alpha_y"],
        generic!(|a| Beckmann::new(a[0], a[1])),
    ),
    (
        "lights::SpotCone",
        &["inner", "outer"],
        generic!(|a| SpotCone::new(a[0], a[1])),
    ),
    (
        "material::MetallicRoughness",
        &[
            "base_color_r",
            "base_color_g",
            "base_color_b",
            "metallic",
            "roughness",
        ],
        generic!(|a| MetallicRoughness::new(V3::new(a[0], a[1], a[2]), a[3], a[4])),
    ),
    (
        "diffuse::Lambert",
        &["rho"],
        generic!(|a| Lambert::new(a[0])),
    ),
    (
        "diffuse::OrenNayar",
        &["rho", "sigma"],
        generic!(|a| OrenNayar::new(a[0], a[1])),
    ),
    (
        "diffuse::OrenNayarFull",
        &["rho", "sigma"],
        generic!(|a| OrenNayarFull::new(a[0], a[1])),
    ),
    (
        "diffuse::OrenNayarFujii",
        &["rho", "sigma"],
        generic!(|a| OrenNayarFujii::new(a[0], a[1])),
    ),
    (
        "diffuse::Eon",
        &["rho", "sigma"],
        generic!(|a| Eon::new(a[0], a[1])),
    ),
    (
        "diffuse::Burley",
        &["rho", "roughness"],
        generic!(|a| Burley::new(a[0], a[1])),
    ),
    (
        "diffuse::BurleyRenormalized",
        &["rho", "roughness"],
        generic!(|a| BurleyRenormalized::new(a[0], a[1])),
    ),
    (
        "diffuse::ShirleyCoupled",
        &["rho", "f0"],
        generic!(|a| ShirleyCoupled::new(a[0], a[1])),
    ),
    (
        "diffuse::AshikhminShirley",
        &["rho", "rs"],
        generic!(|a| AshikhminShirley::new(a[0], a[1])),
    ),
    (
        "phong::ClassicPhong",
        &["ks", "exponent"],
        generic!(|a| ClassicPhong::new(a[0], a[1])),
    ),
    (
        "phong::ModifiedPhong",
        &["ks", "exponent"],
        generic!(|a| ModifiedPhong::new(a[0], a[1])),
    ),
    (
        "phong::NormalizedPhong",
        &["ks", "exponent"],
        generic!(|a| NormalizedPhong::new(a[0], a[1])),
    ),
    (
        "phong::BlinnPhong",
        &["ks", "exponent"],
        generic!(|a| BlinnPhong::new(a[0], a[1])),
    ),
    (
        "phong::NormalizedBlinnPhong",
        &["ks", "exponent"],
        generic!(|a| NormalizedBlinnPhong::new(a[0], a[1])),
    ),
    (
        "phong::ApproxNormalizedBlinnPhong",
        &["ks", "exponent"],
        generic!(|a| ApproxNormalizedBlinnPhong::new(a[0], a[1])),
    ),
    (
        "phong::PhongDiffuseSpecular",
        &["kd", "ks", "exponent"],
        generic!(|a| PhongDiffuseSpecular::new(a[0], a[1], a[2])),
    ),
    (
        "tonemap::HableParams",
        &["a", "b", "c", "d", "e", "f", "white", "exposure_bias"],
        |a, _| HableParams::new(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]).map(|_| ()),
    ),
    (
        "tonemap::LottesParams",
        &["contrast", "shoulder", "hdr_max", "mid_in", "mid_out"],
        |a, _| LottesParams::new(a[0], a[1], a[2], a[3], a[4]).map(|_| ()),
    ),
];

/// The validated parameter types: (type path, constructor argument names).
#[pyfunction]
pub fn param_types() -> Vec<(&'static str, Vec<&'static str>)> {
    TYPES.iter().map(|(p, a, _)| (*p, a.to_vec())).collect()
}

/// Runs the constructor of `type_path` on `values` (rounded to `f32` first where `f32`):
/// `ValueError("invalid parameter `alpha_x`: expected ...")` where the crate rejects one.
#[pyfunction]
pub fn validate(type_path: &str, values: Vec<f64>, f32: bool) -> PyResult<()> {
    let (_, names, check) = TYPES
        .iter()
        .find(|(p, _, _)| *p == type_path)
        .ok_or_else(|| PyKeyError::new_err(type_path.to_string()))?;
    if values.len() != names.len() {
        return Err(PyValueError::new_err(format!(
            "{type_path} takes {} parameters ({}), got {}",
            names.len(),
            names.join(", "),
            values.len()
        )));
    }
    check(&values, f32).map_err(|e| PyValueError::new_err(e.to_string()))
}
