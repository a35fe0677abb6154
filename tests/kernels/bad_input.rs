//! The crate's one rule for bad input (crate docs, "Bad input"), checked on every public kernel
//! and on every lane type (`f32`, `f64`, `f32x8`, `f64x4`) from one table:
//!
//! - (a) in-domain input gives finite output (no NaN, no inf), above and below the horizon;
//! - (b) a NaN in each input, one at a time, gives NaN in every output that depends on it
//!   (for samplers: all three direction components and the pdf);
//! - (c) each parameter outside its documented domain gives NaN (also below the horizon);
//! - (e) an infinite cosine or uniform sample (and a tonemap operator's input, which the
//!   operators clamp to `MAX_INPUT`) gives bit for bit its value at the end it lies beyond
//!   (rule 3); any other infinite input gives NaN wherever a NaN would (rule 5), except in
//!   the IEEE-arithmetic helpers of `INFINITY_EXEMPT`;
//! - (d) on `f32x8` and `f64x4`, a NaN or an invalid parameter in one lane leaves the other
//!   lanes bit for bit as they were, and those equal the scalar results within 16 ulps
//!   (256 for the material's weighted samplers, whose BRDF at the drawn direction amplifies
//!   the lanes' last-ulp `sin` and `cos`; `tests/lanes/vs_scalar.rs` holds the per-function
//!   lane bounds; this only shows no lane leaks into another).
//!
//! A zero-length direction is finite input: another test sets each kernel's `wo`, `wi` or
//! `dir` to (0, 0, 0) on every lane type and requires finite output and, from every sampler
//! and pdf, pdf 0; a last one holds the microfacet verbs at the zero vector to their horizon
//! values.
//!
//! A second test scans `src/` for `pub fn` and fails when one is neither in the table nor in
//! the list of non-kernels (constructors, getters, integrators) below, so a new kernel cannot
//! skip the rule.
//!
//! `cargo test --test kernels bad_input:: -- --nocapture` prints the kernels x checks table and
//! every failure as (kernel, lane type, input, value, what came out).
#![allow(clippy::type_complexity)]
// Rows, constants and the source scan are used by feature-gated sections.
#![cfg_attr(
    not(all(
        feature = "fresnel",
        feature = "ggx",
        feature = "beckmann",
        feature = "cook-torrance",
        feature = "sampling",
        feature = "tonemap",
        feature = "diffuse",
        feature = "phong",
        feature = "material",
        feature = "lights",
        feature = "engine"
    )),
    allow(dead_code, unused_imports)
)]

use brdf::Cosines;
#[cfg(feature = "cook-torrance")]
use brdf::fresnel::ComplexIor;
#[cfg(feature = "ibl")]
use brdf::ibl::energy::{Albedo, AverageAlbedo, Reflectance};
#[cfg(feature = "cook-torrance")]
use brdf::microfacet::Alpha;
use brdf::wide::{f32x8, f64x4};
use brdf::{Real, V3};

const INF: f64 = f64::INFINITY;
/// `tonemap::MAX_INPUT`, where an operator's input clamp ends (`tonemap_max_input_matches`
/// holds the two equal).
const TONEMAP_MAX_INPUT: f64 = 1e9;
const NAN: f64 = f64::NAN;

/// One scalar input of a kernel (a cosine, a direction component, a parameter, a sample).
#[derive(Clone, Debug)]
struct Arg {
    name: String,
    /// A value inside the documented domain.
    valid: f64,
    /// Values outside the parameter's documented domain (empty for inputs that are clamped).
    invalid: Vec<f64>,
}

/// A kernel of the table: its flattened inputs and a closure mapping them to its flattened
/// outputs (a `V3` is three values, a sampler's (direction, pdf) four).
struct Kernel<T> {
    name: String,
    args: Vec<Arg>,
    f: Box<dyn Fn(&[T]) -> Vec<T>>,
    /// Inputs whose NaN reaches only some outputs (a component accessor, a per-channel
    /// colour function): (input, outputs that must be NaN). Every other input: all outputs.
    deps: Vec<(&'static str, Vec<usize>)>,
    /// How far (in ulps of the larger) a lane may sit from the scalar result in check (d):
    /// 16, unless the kernel feeds a lane function's documented last-ulp difference (the
    /// lanes' `sin` and `cos`) through a steep step.
    lane_ulps: f64,
}

impl<T> Kernel<T> {
    fn dep(mut self, input: &'static str, outputs: &[usize]) -> Self {
        self.deps.push((input, outputs.to_vec()));
        self
    }
    fn lane_ulps(mut self, ulps: f64) -> Self {
        self.lane_ulps = ulps;
        self
    }

    fn outputs_of(&self, input: &str, n_out: usize) -> Vec<usize> {
        self.deps
            .iter()
            .find(|(i, _)| *i == input)
            .map_or_else(|| (0..n_out).collect(), |(_, o)| o.clone())
    }
}

fn k<T>(name: &str, args: Vec<Vec<Arg>>, f: impl Fn(&[T]) -> Vec<T> + 'static) -> Kernel<T> {
    Kernel {
        name: name.to_string(),
        args: args.concat(),
        f: Box::new(f),
        deps: Vec::new(),
        lane_ulps: 16.0,
    }
}

/// An input without invalid values (cosines, samples, direction components are clamped).
fn c(name: &str, valid: f64) -> Vec<Arg> {
    vec![Arg {
        name: name.to_string(),
        valid,
        invalid: vec![],
    }]
}

/// A parameter with values outside its documented domain.
fn p(name: &str, valid: f64, invalid: &[f64]) -> Vec<Arg> {
    vec![Arg {
        name: name.to_string(),
        valid,
        invalid: invalid.to_vec(),
    }]
}

/// A direction (three inputs `name.x`, `name.y`, `name.z`).
fn v(name: &str, w: [f64; 3]) -> Vec<Arg> {
    ["x", "y", "z"]
        .iter()
        .zip(w)
        .map(|(a, x)| Arg {
            name: format!("{name}.{a}"),
            valid: x,
            invalid: vec![],
        })
        .collect()
}

/// An RGB parameter: three inputs, each with the same invalid values.
fn rgb(name: &str, w: [f64; 3], invalid: &[f64]) -> Vec<Arg> {
    ["x", "y", "z"]
        .iter()
        .zip(w)
        .map(|(a, x)| Arg {
            name: format!("{name}.{a}"),
            valid: x,
            invalid: invalid.to_vec(),
        })
        .collect()
}

fn v3<T: Real>(x: &[T], i: usize) -> V3<T> {
    V3::new(x[i], x[i + 1], x[i + 2])
}

fn o3<T: Real>(w: V3<T>) -> Vec<T> {
    vec![w.x, w.y, w.z]
}

fn o4<T: Real>((w, pdf): (V3<T>, T)) -> Vec<T> {
    vec![w.x, w.y, w.z, pdf]
}

/// An f64-only function applied lane by lane.
#[allow(dead_code)]
fn per_lane<T: Real>(x: &[T], f: impl Fn(&[f64]) -> f64) -> T {
    T::from_fn(|i| {
        let a: Vec<f64> = x.iter().map(|v| v.lane(i).into()).collect();
        T::Scalar::splat(f(&a))
    })
}

// Valid inputs shared by the rows: unit directions above the horizon and cosines consistent
// with them.
const WO: [f64; 3] = [0.36, 0.48, 0.8];
const WI: [f64; 3] = [-0.6, 0.0, 0.8];
const M: [f64; 3] = [0.0, 0.28, 0.96];
const NV: f64 = 0.8;
const NL: f64 = 0.7;
const NH: f64 = 0.9;
const VH: f64 = 0.85;
const VL: f64 = 0.3;
const UNIT_BAD: [f64; 4] = [-0.1, 1.1, INF, -INF];
const ALPHA_BAD: [f64; 3] = [-0.1, -INF, INF];
const ETA_BAD: [f64; 3] = [0.0, -1.0, -INF];
const NONNEG_BAD: [f64; 2] = [-0.1, -INF];

fn table<T: Real>() -> Vec<Kernel<T>> {
    let mut t = Vec::new();
    frame_rows(&mut t);
    #[cfg(feature = "fresnel")]
    fresnel_rows(&mut t);
    #[cfg(feature = "microfacet")]
    microfacet_rows(&mut t);
    #[cfg(feature = "ggx")]
    ggx_rows(&mut t);
    #[cfg(feature = "beckmann")]
    beckmann_rows(&mut t);
    #[cfg(feature = "cook-torrance")]
    cook_torrance_rows(&mut t);
    #[cfg(feature = "sampling")]
    sampling_rows(&mut t);
    #[cfg(all(feature = "transmission", feature = "ggx", feature = "beckmann"))]
    rough_dielectric_rows(&mut t);
    #[cfg(all(feature = "transmission", feature = "ggx"))]
    gltf_transmission_rows(&mut t);
    #[cfg(feature = "iridescence")]
    iridescence_rows(&mut t);
    #[cfg(feature = "tonemap")]
    tonemap_rows(&mut t);
    #[cfg(feature = "diffuse")]
    diffuse_rows(&mut t);
    #[cfg(feature = "phong")]
    phong_rows(&mut t);
    #[cfg(feature = "material")]
    material_rows(&mut t);
    #[cfg(feature = "lights")]
    lights_rows(&mut t);
    #[cfg(feature = "ibl")]
    ibl_rows(&mut t);
    #[cfg(feature = "engine")]
    engine_rows(&mut t);
    #[cfg(feature = "sheen")]
    sheen_rows(&mut t);
    #[cfg(feature = "clearcoat")]
    clearcoat_rows(&mut t);
    #[cfg(feature = "specular")]
    specular_rows(&mut t);
    #[cfg(feature = "anisotropy")]
    anisotropy_rows(&mut t);
    #[cfg(feature = "layered")]
    layered_rows(&mut t);
    t
}

/// `layers::layered::Layered`: a plain base, and every layer at once.
#[cfg(feature = "layered")]
fn layered_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::layers::layered::Layered;
    let s = T::splat;
    let plain = Layered::new(V3::new(s(0.9), s(0.6), s(0.3)), s(0.5), s(0.5)).unwrap();
    let all = plain
        .with_sheen(V3::new(s(0.8), s(0.4), s(0.2)), s(0.5))
        .and_then(|m| m.with_clearcoat(s(0.8), s(0.2)))
        .and_then(|m| m.with_clearcoat_normal(V3::new(s(0.0), s(0.6), s(0.8))))
        .and_then(|m| m.with_anisotropy(s(0.7), s(0.4)))
        .unwrap()
        .with_compensation(true);
    #[allow(unused_mut)]
    let mut variants = vec![("plain", plain), ("all layers", all)];
    #[cfg(feature = "iridescence")]
    variants.push((
        "iridescent",
        all.with_iridescence(
            s(0.9),
            brdf::iridescence::ThinFilm::new(s(400.0), s(1.3)).unwrap(),
        )
        .unwrap(),
    ));
    #[cfg(feature = "transmission")]
    {
        let thin = all.with_transmission(s(0.8)).unwrap();
        let volume =
            brdf::transmission::Volume::new(s(0.01), V3::new(s(0.9), s(0.8), s(0.7)), s(1.0));
        variants.push(("thin-walled transmission", thin));
        variants.push(("volumetric transmission", thin.with_volume(volume.unwrap())));
    }
    for (label, m) in variants {
        let dirs = || [v("wo", WO), v("wi", WI)].concat();
        t.push(k(
            &format!("Layered::eval({label})"),
            vec![dirs()],
            move |x| o3(m.eval(v3(x, 0), v3(x, 3))),
        ));
        t.push(k(
            &format!("Layered::lobe_probabilities({label})"),
            vec![v("wo", WO)],
            move |x| o3(m.lobe_probabilities(v3(x, 0))),
        ));
        t.push(k(
            &format!("Layered::pdf({label})"),
            vec![dirs()],
            move |x| vec![m.pdf(v3(x, 0), v3(x, 3))],
        ));
        t.push(k(
            &format!("Layered::sample({label})"),
            vec![v("wo", WO), c("u1", 0.3), c("u2", 0.6)],
            move |x| o4(m.sample(v3(x, 0), x[3], x[4])),
        ));
        // Prepared per shading point: a bad view reaches every light.
        t.push(k(
            &format!("Prepared::eval({label})"),
            vec![dirs()],
            move |x| o3(m.at_view(v3(x, 0)).eval(v3(x, 3))),
        ));
        t.push(k(
            &format!("Prepared::eval_view_only({label})"),
            vec![dirs()],
            move |x| o3(m.at_view(v3(x, 0)).eval_view_only(v3(x, 3))),
        ));
        // World space: a shading point of normal n and view v.
        let n_v = || [v("n", [0.0, 0.6, 0.8]), v("v", WO)].concat();
        let sp = |x: &[T]| brdf::ShadingPoint::new(v3(x, 0), v3(x, 3));
        t.push(k(
            &format!("Layered::eval_world({label})"),
            vec![n_v(), v("l", WI)],
            move |x| o3(m.eval_world(&sp(x), v3(x, 6))),
        ));
        t.push(k(
            &format!("Layered::pdf_world({label})"),
            vec![n_v(), v("l", WI)],
            move |x| vec![m.pdf_world(&sp(x), v3(x, 6))],
        ));
        t.push(k(
            &format!("Layered::sample_world({label})"),
            vec![n_v(), c("u1", 0.3), c("u2", 0.6)],
            move |x| o4(m.sample_world(&sp(x), x[6], x[7])),
        ));
    }
}

/// `layers::clearcoat`.
#[cfg(feature = "clearcoat")]
fn clearcoat_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::layers::clearcoat::*;
    let cos = || {
        vec![
            c("n_dot_v", NV),
            c("n_dot_l", NL),
            c("n_dot_h", NH),
            c("v_dot_h", VH),
        ]
    };
    let cs = |x: &[T]| Cosines {
        n_dot_v: x[0],
        n_dot_l: x[1],
        n_dot_h: x[2],
        v_dot_h: x[3],
    };
    t.push(k(
        "layers::clearcoat::fresnel",
        vec![c("cos_theta", VH)],
        |x| vec![fresnel(x[0])],
    ));
    t.push(k(
        "layers::clearcoat::v_kelemen",
        vec![c("v_dot_h", VH)],
        |x| vec![v_kelemen(x[0])],
    ));
    t.push(k(
        "layers::clearcoat::coat",
        [cos(), vec![p("alpha", 0.1, &ALPHA_BAD)]].concat(),
        move |x| vec![coat(cs(x), x[4])],
    ));
    t.push(k(
        "layers::clearcoat::coat_kelemen",
        [cos(), vec![p("alpha", 0.1, &ALPHA_BAD)]].concat(),
        move |x| vec![coat_kelemen(cs(x), x[4])],
    ));
    t.push(
        k(
            "layers::clearcoat::layer",
            vec![
                rgb("base", [0.3, 0.2, 0.1], &[]),
                c("coat", 0.5),
                p("clearcoat", 0.7, &UNIT_BAD),
                p("f_coat", 0.1, &UNIT_BAD),
            ],
            |x| o3(layer(v3(x, 0), x[3], x[4], x[5])),
        )
        .dep("base.x", &[0])
        .dep("base.y", &[1])
        .dep("base.z", &[2]),
    );
}

/// `layers::specular`.
#[cfg(feature = "specular")]
fn specular_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::layers::specular::*;
    t.push(k(
        "layers::specular::f0_from_ior",
        vec![p("ior", 1.5, &[0.5, -1.0, INF, -INF])],
        |x| vec![f0_from_ior(x[0])],
    ));
    t.push(
        k(
            "layers::specular::dielectric_f0",
            vec![
                p("f0_ior", 0.04, &UNIT_BAD),
                p("specular", 0.7, &UNIT_BAD),
                rgb("specular_color", [2.0, 1.0, 0.5], &NONNEG_BAD),
            ],
            |x| o3(dielectric_f0(x[0], x[1], v3(x, 2))),
        )
        .dep("specular_color.x", &[0])
        .dep("specular_color.y", &[1])
        .dep("specular_color.z", &[2]),
    );
}

/// `layers::anisotropy`.
#[cfg(feature = "anisotropy")]
fn anisotropy_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::layers::anisotropy::*;
    t.push(k(
        "layers::anisotropy::alpha_t",
        vec![p("alpha", 0.2, &UNIT_BAD), p("strength", 0.5, &UNIT_BAD)],
        |x| vec![alpha_t(x[0], x[1])],
    ));
    t.push(k(
        "layers::anisotropy::direction",
        vec![
            p("x", 0.6, &[INF, -INF]),
            p("y", 0.8, &[INF, -INF]),
            p("rotation", 0.3, &[INF, -INF]),
        ],
        |x| o3(direction(x[0], x[1], x[2])),
    ));
    t.push(k(
        "layers::anisotropy::bent_reflection",
        vec![
            v("n", [0.0, 0.0, 1.0]),
            v("v", WO),
            v("b", [0.0, 1.0, 0.0]),
            p("strength", 0.5, &UNIT_BAD),
            p("roughness", 0.4, &UNIT_BAD),
        ],
        |x| o3(bent_reflection(v3(x, 0), v3(x, 3), v3(x, 6), x[9], x[10])),
    ));
}

/// `layers::sheen`: alpha and the colours in [0, 1].
#[cfg(feature = "sheen")]
fn sheen_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::layers::sheen::*;
    let a = || p("alpha", 0.3, &UNIT_BAD);
    t.push(k(
        "layers::sheen::d_charlie",
        vec![c("n_dot_h", NH), a()],
        |x| vec![d_charlie(x[0], x[1])],
    ));
    t.push(k(
        "layers::sheen::lambda_charlie",
        vec![c("n_dot_v", NV), a()],
        |x| vec![lambda_charlie(x[0], x[1])],
    ));
    t.push(k(
        "layers::sheen::v_charlie",
        vec![c("n_dot_v", NV), c("n_dot_l", NL), a()],
        |x| vec![v_charlie(x[0], x[1], x[2])],
    ));
    t.push(k(
        "layers::sheen::v_neubelt",
        vec![c("n_dot_v", NV), c("n_dot_l", NL)],
        |x| vec![v_neubelt(x[0], x[1])],
    ));
    t.push(k(
        "layers::sheen::d_ashikhmin",
        vec![c("n_dot_h", NH), a()],
        |x| vec![d_ashikhmin(x[0], x[1])],
    ));
    t.push(
        k(
            "layers::sheen::charlie",
            vec![
                c("n_dot_v", NV),
                c("n_dot_l", NL),
                c("n_dot_h", NH),
                c("v_dot_h", VH),
                rgb("sheen_color", [0.9, 0.5, 0.2], &UNIT_BAD),
                a(),
            ],
            |x| {
                o3(charlie(
                    Cosines {
                        n_dot_v: x[0],
                        n_dot_l: x[1],
                        n_dot_h: x[2],
                        v_dot_h: x[3],
                    },
                    v3(x, 4),
                    x[7],
                ))
            },
        )
        .dep("sheen_color.x", &[0])
        .dep("sheen_color.y", &[1])
        .dep("sheen_color.z", &[2]),
    );
    t.push(k(
        "layers::sheen::albedo",
        vec![c("n_dot_v", NV), a()],
        |x| vec![albedo(x[0], x[1])],
    ));
    t.push(k(
        "layers::sheen::albedo_fit_materialx",
        vec![c("n_dot_v", NV), a()],
        |x| vec![albedo_fit_materialx(x[0], x[1])],
    ));
    t.push(k(
        "layers::sheen::albedo_fit_threejs",
        vec![c("n_dot_v", NV), p("roughness", 0.4, &UNIT_BAD)],
        |x| vec![albedo_fit_threejs(x[0], x[1])],
    ));
    t.push(k(
        "layers::sheen::albedo_scaling",
        vec![
            rgb("sheen_color", [0.9, 0.5, 0.2], &UNIT_BAD),
            p("e_v", 0.3, &UNIT_BAD),
            p("e_l", 0.4, &UNIT_BAD),
        ],
        |x| vec![albedo_scaling(v3(x, 0), x[3], x[4])],
    ));
}

/// `engine::Convention`'s methods, for each of the five conventions.
#[cfg(feature = "engine")]
fn engine_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::Cosines;
    let cosines = || {
        vec![
            c("n_dot_v", NV),
            c("n_dot_l", NL),
            c("n_dot_h", NH),
            c("v_dot_h", VH),
        ]
    };
    let cs = |x: &[T]| Cosines {
        n_dot_v: x[0],
        n_dot_l: x[1],
        n_dot_h: x[2],
        v_dot_h: x[3],
    };
    for e in brdf::engine::ALL {
        let n = e.name;
        t.push(k(
            &format!("Convention::alpha({n})"),
            vec![p("perceptual_roughness", 0.5, &UNIT_BAD)],
            move |x| vec![e.alpha(x[0])],
        ));
        t.push(k(
            &format!("Convention::f90({n})"),
            vec![rgb("f0", [0.04, 0.5, 0.9], &UNIT_BAD)],
            move |x| vec![e.f90(v3(x, 0))],
        ));
        t.push(k(
            &format!("Convention::fresnel({n})"),
            vec![
                rgb("f0", [0.04, 0.5, 0.9], &UNIT_BAD),
                p("f90", 1.0, &UNIT_BAD),
                c("v_dot_h", VH),
            ],
            move |x| o3(e.fresnel(v3(x, 0), x[3], x[4])),
        ));
        let mut a = cosines();
        a.extend([
            p("roughness", 0.5, &UNIT_BAD),
            rgb("f0", [0.04, 0.5, 0.9], &UNIT_BAD),
            p("f90", 1.0, &UNIT_BAD),
        ]);
        t.push(k(&format!("Convention::specular({n})"), a, move |x| {
            o3(e.specular(cs(x), x[4], v3(x, 5), x[8]))
        }));
        let mut a = cosines();
        a.extend([
            p("roughness", 0.5, &UNIT_BAD),
            rgb("diffuse_color", [0.9, 0.6, 0.3], &UNIT_BAD),
        ]);
        t.push(k(&format!("Convention::diffuse({n})"), a, move |x| {
            o3(e.diffuse(cs(x), x[4], v3(x, 5)))
        }));
        let mut a = cosines();
        a.extend([
            rgb("base_color", [0.9, 0.6, 0.3], &UNIT_BAD),
            p("metallic", 0.5, &UNIT_BAD),
            p("roughness", 0.5, &UNIT_BAD),
        ]);
        t.push(k(&format!("Convention::brdf({n})"), a, move |x| {
            o3(e.brdf(cs(x), v3(x, 4), x[7], x[8]))
        }));
    }
}

/// `ibl::dfg` and `ibl::energy` (`ibl::irradiance` and `ibl::prefilter` below them).
#[cfg(feature = "ibl")]
fn ibl_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::ibl::{dfg, energy, irradiance, prefilter};
    let fit_args = || vec![c("n_dot_v", 0.8), p("roughness", 0.3, &UNIT_BAD)];
    type Fit2<T> = fn(T, T) -> [T; 2];
    for (name, f) in [
        ("ibl::dfg::karis_mobile", dfg::karis_mobile::<T> as Fit2<T>),
        ("ibl::dfg::lazarov", dfg::lazarov::<T>),
        ("ibl::dfg::narkowicz_lazarov", dfg::narkowicz_lazarov::<T>),
        (
            "ibl::dfg::narkowicz_polynomial",
            dfg::narkowicz_polynomial::<T>,
        ),
    ] {
        t.push(k(name, fit_args(), move |x| f(x[0], x[1]).to_vec()));
    }
    t.push(k("ibl::dfg::karis_mobile_nonmetal", fit_args(), |x| {
        vec![dfg::karis_mobile_nonmetal(x[0], x[1])]
    }));
    t.push(
        k(
            "ibl::dfg::specular",
            vec![
                rgb("prefiltered", [0.5, 1.0, 2.0], &[-1.0, -INF]),
                rgb("f0", [0.04, 0.5, 0.9], &UNIT_BAD),
                p("f90", 1.0, &UNIT_BAD),
                c("a", 0.8),
                c("b", 0.1),
            ],
            |x| o3(dfg::specular(v3(x, 0), v3(x, 3), x[6], x[7], x[8])),
        )
        .dep("prefiltered.x", &[0])
        .dep("prefiltered.y", &[1])
        .dep("prefiltered.z", &[2])
        .dep("f0.x", &[0])
        .dep("f0.y", &[1])
        .dep("f0.z", &[2]),
    );
    t.push(
        k(
            "ibl::dfg::specular_filament",
            vec![
                rgb("prefiltered", [0.5, 1.0, 2.0], &[-1.0, -INF]),
                rgb("f0", [0.04, 0.5, 0.9], &UNIT_BAD),
                c("dfg_x", 0.1),
                c("dfg_y", 0.9),
            ],
            |x| o3(dfg::specular_filament(v3(x, 0), v3(x, 3), x[6], x[7])),
        )
        .dep("prefiltered.x", &[0])
        .dep("prefiltered.y", &[1])
        .dep("prefiltered.z", &[2])
        .dep("f0.x", &[0])
        .dep("f0.y", &[1])
        .dep("f0.z", &[2]),
    );
    type Map2<T> = fn(T, T) -> T;
    let maps: [(&str, Map2<T>, Vec<Vec<Arg>>); 6] = [
        (
            "ibl::dfg::mip_from_roughness_linear",
            dfg::mip_from_roughness_linear::<T>,
            vec![
                p("roughness", 0.5, &UNIT_BAD),
                p("n_mips", 5.0, &[0.5, INF, -INF]),
            ],
        ),
        (
            "ibl::dfg::roughness_from_mip_linear",
            dfg::roughness_from_mip_linear::<T>,
            vec![
                p("mip", 2.0, &[-1.0, 9.0, INF]),
                p("n_mips", 5.0, &[1.0, INF, -INF]),
            ],
        ),
        (
            "ibl::dfg::lod_from_roughness_filament",
            dfg::lod_from_roughness_filament::<T>,
            vec![
                p("roughness", 0.5, &UNIT_BAD),
                p("roughness_one_level", 4.0, &[-1.0, INF]),
            ],
        ),
        (
            "ibl::dfg::roughness_from_lod_filament",
            dfg::roughness_from_lod_filament::<T>,
            vec![
                p("lod", 2.0, &[-1.0, 6.0, INF]),
                p("roughness_one_level", 4.0, &[0.0, -1.0, INF]),
            ],
        ),
        (
            "ibl::dfg::mip_from_roughness_ue4",
            dfg::mip_from_roughness_ue4::<T>,
            vec![
                p("roughness", 0.5, &UNIT_BAD),
                p("cubemap_max_mip", 7.0, &[INF, -INF]),
            ],
        ),
        (
            "ibl::dfg::roughness_from_mip_ue4",
            dfg::roughness_from_mip_ue4::<T>,
            vec![
                p("mip", 2.0, &[INF, -INF]),
                p("cubemap_max_mip", 7.0, &[INF, -INF]),
            ],
        ),
    ];
    for (name, f, args) in maps {
        t.push(k(name, args, move |x| vec![f(x[0], x[1])]));
    }

    t.push(k(
        "ibl::energy::e_ggx",
        vec![c("mu", 0.5), p("alpha", 0.3, &ALPHA_BAD)],
        |x| vec![energy::e_ggx(x[0], x[1])],
    ));
    t.push(k(
        "ibl::energy::e_avg_ggx",
        vec![p("alpha", 0.3, &ALPHA_BAD)],
        |x| vec![energy::e_avg_ggx(x[0])],
    ));
    t.push(k(
        "ibl::energy::kulla_conty_lobe",
        vec![
            p("e_o", 0.8, &UNIT_BAD),
            p("e_i", 0.7, &UNIT_BAD),
            p("e_avg", 0.6, &UNIT_BAD),
        ],
        |x| {
            vec![energy::kulla_conty_lobe(
                Albedo(x[0]),
                Albedo(x[1]),
                AverageAlbedo(x[2]),
            )]
        },
    ));
    t.push(k(
        "ibl::energy::kulla_conty_fresnel",
        vec![p("f_avg", 0.5, &UNIT_BAD), p("e_avg", 0.6, &UNIT_BAD)],
        |x| {
            vec![energy::kulla_conty_fresnel(
                Reflectance(x[0]),
                AverageAlbedo(x[1]),
            )]
        },
    ));
    t.push(k(
        "ibl::energy::fresnel_avg_schlick",
        vec![p("f0", 0.04, &UNIT_BAD), p("f90", 1.0, &UNIT_BAD)],
        |x| vec![energy::fresnel_avg_schlick(x[0], x[1])],
    ));
    t.push(k(
        "ibl::energy::kulla_conty_ggx",
        vec![
            c("n_dot_v", 0.8),
            c("n_dot_l", 0.6),
            p("alpha", 0.3, &ALPHA_BAD),
            p("f_avg", 0.5, &UNIT_BAD),
        ],
        |x| vec![energy::kulla_conty_ggx(x[0], x[1], x[2], x[3])],
    ));
    t.push(
        k(
            "ibl::energy::kulla_conty_ggx_rgb",
            vec![
                c("n_dot_v", 0.8),
                c("n_dot_l", 0.6),
                p("alpha", 0.3, &ALPHA_BAD),
                rgb("f_avg", [0.9, 0.6, 0.3], &UNIT_BAD),
            ],
            |x| o3(energy::kulla_conty_ggx_rgb(x[0], x[1], x[2], v3(x, 3))),
        )
        .dep("f_avg.x", &[0])
        .dep("f_avg.y", &[1])
        .dep("f_avg.z", &[2]),
    );
    t.push(k(
        "ibl::energy::turquin_scale",
        vec![
            p("e", 0.8, &[0.0, -0.1, 1.1, INF, -INF]),
            p("f", 0.5, &UNIT_BAD),
        ],
        |x| vec![energy::turquin_scale(Albedo(x[0]), Reflectance(x[1]))],
    ));
    t.push(k(
        "ibl::energy::fdez_aguera_ms",
        vec![
            p("fss_ess", 0.5, &UNIT_BAD),
            p("e_ss", 0.8, &UNIT_BAD),
            p("f_avg", 0.5, &UNIT_BAD),
        ],
        |x| {
            vec![energy::fdez_aguera_ms(
                x[0],
                Albedo(x[1]),
                Reflectance(x[2]),
            )]
        },
    ));
    t.push(k(
        "ibl::energy::fdez_aguera",
        vec![
            p("a", 0.6, &[-0.1, 0.9, INF, -INF]),
            p("b", 0.2, &[-0.1, 0.5, INF, -INF]),
            p("f0", 0.04, &UNIT_BAD),
        ],
        |x| {
            let (a, b) = energy::fdez_aguera(x[0], x[1], x[2]);
            vec![a, b]
        },
    ));

    t.push(k(
        "ibl::prefilter::sample_from",
        vec![c("u1", 0.3), c("u2", 0.7), p("alpha", 0.3, &ALPHA_BAD)],
        |x| {
            let s = prefilter::sample_from(x[0], x[1], x[2]);
            vec![s.dir.x, s.dir.y, s.dir.z, s.weight, s.pdf]
        },
    ));
    t.push(k(
        "ibl::prefilter::sample",
        vec![p("alpha", 0.3, &ALPHA_BAD)],
        |x| {
            let s = prefilter::sample(3, 16, x[0]);
            vec![s.dir.x, s.dir.y, s.dir.z, s.weight, s.pdf]
        },
    ));
    t.push(k(
        "ibl::prefilter::pdf",
        vec![v("dir", [0.3, 0.2, 0.9]), p("alpha", 0.3, &ALPHA_BAD)],
        |x| vec![prefilter::pdf(v3(x, 0), x[3])],
    ));
    t.push(k(
        "ibl::prefilter::mip_level",
        vec![
            p("pdf", 1.0, &[-0.1, -INF]),
            p("sample_count", 1024.0, &[0.5, INF, -INF]),
            p("face_size", 256.0, &[0.5, INF, -INF]),
        ],
        |x| vec![prefilter::mip_level(x[0], x[1], x[2])],
    ));
    t.push(k(
        "ibl::irradiance::sh9_basis",
        vec![v("d", [0.3, 0.2, 0.9])],
        |x| irradiance::sh9_basis(v3(x, 0)).to_vec(),
    ));
    t.push(k("Sh9::eval", vec![v("dir", [0.3, 0.2, 0.9])], |x| {
        o3(sh_sky::<T>().eval(v3(x, 0)))
    }));
    t.push(k("Sh9::irradiance", vec![v("n", [0.3, 0.2, 0.9])], |x| {
        o3(sh_sky::<T>().irradiance(v3(x, 0)))
    }));
}

/// A fixed SH9 environment (a bright sky over a dim ground) on the lane type.
#[cfg(feature = "ibl")]
fn sh_sky<T: Real>() -> brdf::ibl::irradiance::Sh9<T> {
    let sh =
        brdf::ibl::irradiance::project(|d| V3::splat(if d.z > 0.0 { 1.0 + d.z } else { 0.2 }), 16);
    brdf::ibl::irradiance::Sh9::splat_from(&sh)
}

/// `frame` and `vec3`: always compiled.
fn frame_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::frame::{self, Frame};
    let n = [0.36, 0.48, 0.8];
    t.push(k("Frame::from_normal", vec![v("n", n)], |x| {
        let f = Frame::from_normal(v3(x, 0));
        [o3(f.t), o3(f.b), o3(f.n)].concat()
    }));
    t.push(k("Frame::to_local", vec![v("n", n), v("v", WI)], |x| {
        o3(Frame::from_normal(v3(x, 0)).to_local(v3(x, 3)))
    }));
    t.push(k("Frame::to_world", vec![v("n", n), v("v", WI)], |x| {
        o3(Frame::from_normal(v3(x, 0)).to_world(v3(x, 3)))
    }));
    // The shading point's geometry (brdf::shading).
    {
        use brdf::{Cosines, ShadingPoint};
        let c4 = |c: Cosines<T>| vec![c.n_dot_v, c.n_dot_l, c.n_dot_h, c.v_dot_h];
        // Which cosines each component reaches: n.v and n.h read the view (and n.l the
        // light) in every component, v.h reads both directions.
        t.push(
            k(
                "Cosines::from_world",
                vec![v("n", n), v("v", WO), v("l", WI)],
                move |x| c4(Cosines::from_world(v3(x, 0), v3(x, 3), v3(x, 6))),
            )
            .dep("n.x", &[0, 1, 2])
            .dep("n.y", &[0, 1, 2])
            .dep("n.z", &[0, 1, 2])
            .dep("v.x", &[0, 2, 3])
            .dep("v.y", &[0, 2, 3])
            .dep("v.z", &[0, 2, 3])
            .dep("l.x", &[1, 2, 3])
            .dep("l.y", &[1, 2, 3])
            .dep("l.z", &[1, 2, 3]),
        );
        // Locally n.v = wo.z and n.l = wi.z.
        t.push(
            k(
                "Cosines::from_local",
                vec![v("wo", WO), v("wi", WI)],
                move |x| c4(Cosines::from_local(v3(x, 0), v3(x, 3))),
            )
            .dep("wo.x", &[2, 3])
            .dep("wo.y", &[2, 3])
            .dep("wo.z", &[0, 2, 3])
            .dep("wi.x", &[2, 3])
            .dep("wi.y", &[2, 3])
            .dep("wi.z", &[1, 2, 3]),
        );
        let sp = |x: &[T]| ShadingPoint::new(v3(x, 0), v3(x, 3));
        t.push(
            k(
                "ShadingPoint::local",
                vec![v("n", n), v("v", WO), v("l", WI)],
                move |x| o3(sp(x).local(v3(x, 6))),
            )
            // The frame is the normal's alone: the view direction cannot reach it.
            .dep("v.x", &[])
            .dep("v.y", &[])
            .dep("v.z", &[]),
        );
        t.push(
            k(
                "ShadingPoint::world",
                vec![v("n", n), v("v", WO), v("w", WI)],
                move |x| o3(sp(x).world(v3(x, 6))),
            )
            // The frame is the normal's alone: the view direction cannot reach it.
            .dep("v.x", &[])
            .dep("v.y", &[])
            .dep("v.z", &[]),
        );
        t.push(
            k(
                "ShadingPoint::cosines",
                vec![v("n", n), v("v", WO), v("l", WI)],
                move |x| c4(sp(x).cosines(v3(x, 6))),
            )
            .dep("v.x", &[0, 2, 3])
            .dep("v.y", &[0, 2, 3])
            .dep("v.z", &[0, 2, 3])
            .dep("l.x", &[1, 2, 3])
            .dep("l.y", &[1, 2, 3])
            .dep("l.z", &[1, 2, 3]),
        );
    }
    // The accessors read the components their formula names; the others cannot reach them.
    t.push(
        k("frame::cos_theta", vec![v("w", WO)], |x| {
            vec![frame::cos_theta(v3(x, 0))]
        })
        .dep("w.x", &[])
        .dep("w.y", &[]),
    );
    t.push(
        k("frame::cos2_theta", vec![v("w", WO)], |x| {
            vec![frame::cos2_theta(v3(x, 0))]
        })
        .dep("w.x", &[])
        .dep("w.y", &[]),
    );
    t.push(
        k("frame::abs_cos_theta", vec![v("w", WO)], |x| {
            vec![frame::abs_cos_theta(v3(x, 0))]
        })
        .dep("w.x", &[])
        .dep("w.y", &[]),
    );
    t.push(
        k("frame::sin2_theta", vec![v("w", WO)], |x| {
            vec![frame::sin2_theta(v3(x, 0))]
        })
        .dep("w.z", &[]),
    );
    t.push(
        k("frame::sin_theta", vec![v("w", WO)], |x| {
            vec![frame::sin_theta(v3(x, 0))]
        })
        .dep("w.z", &[]),
    );
    t.push(k("frame::tan2_theta", vec![v("w", WO)], |x| {
        vec![frame::tan2_theta(v3(x, 0))]
    }));
    t.push(
        k("frame::cos_phi", vec![v("w", WO)], |x| {
            vec![frame::cos_phi(v3(x, 0))]
        })
        .dep("w.z", &[]),
    );
    t.push(
        k("frame::sin_phi", vec![v("w", WO)], |x| {
            vec![frame::sin_phi(v3(x, 0))]
        })
        .dep("w.z", &[]),
    );
    t.push(
        k(
            "frame::spherical_direction",
            vec![c("theta", 0.7), c("phi", 2.0)],
            |x| o3(frame::spherical_direction(x[0], x[1])),
        )
        .dep("phi", &[0, 1]),
    );
    t.push(k("V3::dot", vec![v("a", WO), v("b", WI)], |x| {
        vec![v3(x, 0).dot(v3(x, 3))]
    }));
    t.push(
        k("V3::cross", vec![v("a", WO), v("b", WI)], |x| {
            o3(v3(x, 0).cross(v3(x, 3)))
        })
        .dep("a.x", &[1, 2])
        .dep("a.y", &[0, 2])
        .dep("a.z", &[0, 1])
        .dep("b.x", &[1, 2])
        .dep("b.y", &[0, 2])
        .dep("b.z", &[0, 1]),
    );
    t.push(k("V3::length_squared", vec![v("a", WO)], |x| {
        vec![v3(x, 0).length_squared()]
    }));
    t.push(k("V3::length", vec![v("a", WO)], |x| {
        vec![v3(x, 0).length()]
    }));
    t.push(k("V3::normalize_or", vec![v("a", [0.3, -1.2, 2.0])], |x| {
        o3(v3(x, 0).normalize_or(V3::unit_z()))
    }));
    t.push(k("V3::normalize", vec![v("a", [0.3, -1.2, 2.0])], |x| {
        o3(v3(x, 0).normalize())
    }));
    t.push(k("V3::mirror", vec![v("a", WO), v("n", M)], |x| {
        o3(v3(x, 0).mirror(v3(x, 3)))
    }));
    t.push(k("V3::min_element", vec![v("a", WO)], |x| {
        vec![v3(x, 0).min_element()]
    }));
    t.push(k("V3::max_element", vec![v("a", WO)], |x| {
        vec![v3(x, 0).max_element()]
    }));
}

#[cfg(feature = "fresnel")]
fn fresnel_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::fresnel as fr;
    t.push(k(
        "fresnel::f0_from_ior",
        vec![p("eta", 1.5, &ETA_BAD)],
        |x| vec![fr::f0_from_ior(x[0])],
    ));
    t.push(k(
        "fresnel::ior_from_f0",
        vec![p("f0", 0.04, &[-0.1, 1.5, INF])],
        |x| vec![fr::ior_from_f0(x[0])],
    ));
    t.push(k(
        "fresnel::schlick",
        vec![p("f0", 0.04, &UNIT_BAD), c("v_dot_h", VH)],
        |x| vec![fr::schlick(x[0], x[1])],
    ));
    t.push(k(
        "fresnel::schlick_f90",
        vec![
            // Any finite F0 and F90 (Burley's F90 reaches 2.5).
            p("f0", 0.04, &[INF, -INF]),
            p("f90", 0.9, &[INF, -INF]),
            c("v_dot_h", VH),
        ],
        |x| vec![fr::schlick_f90(x[0], x[1], x[2])],
    ));
    t.push(
        k(
            "fresnel::schlick_rgb",
            vec![rgb("f0", [0.9, 0.6, 0.3], &UNIT_BAD), c("v_dot_h", VH)],
            |x| o3(fr::schlick_rgb(v3(x, 0), x[3])),
        )
        .dep("f0.x", &[0])
        .dep("f0.y", &[1])
        .dep("f0.z", &[2]),
    );
    t.push(
        k(
            "fresnel::schlick_f90_rgb",
            vec![
                rgb("f0", [0.9, 0.6, 0.3], &[INF, -INF]),
                rgb("f90", [1.0, 0.9, 0.8], &[INF, -INF]),
                c("v_dot_h", VH),
            ],
            |x| o3(fr::schlick_f90_rgb(v3(x, 0), v3(x, 3), x[6])),
        )
        .dep("f0.x", &[0])
        .dep("f0.y", &[1])
        .dep("f0.z", &[2])
        .dep("f90.x", &[0])
        .dep("f90.y", &[1])
        .dep("f90.z", &[2]),
    );
    t.push(k(
        "fresnel::schlick_sg",
        vec![p("f0", 0.04, &UNIT_BAD), c("v_dot_h", VH)],
        |x| vec![fr::schlick_sg(x[0], x[1])],
    ));
    t.push(k(
        "fresnel::dielectric_polarized",
        vec![c("cos_theta_i", VH), p("eta", 1.5, &ETA_BAD)],
        |x| {
            let (s, pp) = fr::dielectric_polarized(x[0], x[1]);
            vec![s, pp]
        },
    ));
    t.push(k(
        "fresnel::dielectric",
        vec![c("cos_theta_i", VH), p("eta", 1.5, &ETA_BAD)],
        |x| vec![fr::dielectric(x[0], x[1])],
    ));
    t.push(k(
        "fresnel::dielectric_fast",
        vec![c("cos_theta_i", VH), p("eta", 1.5, &ETA_BAD)],
        |x| vec![fr::dielectric_fast(x[0], x[1])],
    ));
    t.push(k(
        "fresnel::conductor",
        vec![
            c("cos_theta_i", VH),
            p("eta", 0.2, &ETA_BAD),
            p("k", 3.0, &NONNEG_BAD),
        ],
        |x| vec![fr::conductor(x[0], x[1], x[2])],
    ));
    t.push(k(
        "fresnel::conductor_fast",
        vec![
            c("cos_theta_i", VH),
            p("eta", 0.2, &ETA_BAD),
            p("k", 3.0, &NONNEG_BAD),
        ],
        |x| vec![fr::conductor_fast(x[0], x[1], x[2])],
    ));
    t.push(
        k(
            "fresnel::conductor_rgb",
            vec![
                c("cos_theta_i", VH),
                rgb("eta", [0.2, 0.9, 1.1], &ETA_BAD),
                rgb("k", [3.0, 2.4, 2.2], &NONNEG_BAD),
            ],
            |x| o3(fr::conductor_rgb(x[0], v3(x, 1), v3(x, 4))),
        )
        .dep("eta.x", &[0])
        .dep("eta.y", &[1])
        .dep("eta.z", &[2])
        .dep("k.x", &[0])
        .dep("k.y", &[1])
        .dep("k.z", &[2]),
    );
    t.push(k(
        "fresnel::schlick_f82",
        vec![
            p("f0", 0.9, &UNIT_BAD),
            p("f82_tint", 0.8, &UNIT_BAD),
            c("cos_theta", VH),
        ],
        |x| vec![fr::schlick_f82(x[0], x[1], x[2])],
    ));
    t.push(
        k(
            "fresnel::schlick_f82_rgb",
            vec![
                rgb("f0", [0.9, 0.6, 0.3], &UNIT_BAD),
                rgb("f82_tint", [0.8, 0.9, 1.0], &UNIT_BAD),
                c("cos_theta", VH),
            ],
            |x| o3(fr::schlick_f82_rgb(v3(x, 0), v3(x, 3), x[6])),
        )
        .dep("f0.x", &[0])
        .dep("f0.y", &[1])
        .dep("f0.z", &[2])
        .dep("f82_tint.x", &[0])
        .dep("f82_tint.y", &[1])
        .dep("f82_tint.z", &[2]),
    );
    t.push(k(
        "fresnel::average_dielectric",
        vec![p("eta", 1.5, &ETA_BAD)],
        |x| vec![per_lane(x, |a| fr::average_dielectric(a[0]))],
    ));
    t.push(k(
        "fresnel::average_dielectric_fit",
        vec![p("eta", 1.5, &ETA_BAD)],
        |x| vec![fr::average_dielectric_fit(x[0])],
    ));
}

#[cfg(feature = "microfacet")]
fn microfacet_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::microfacet as mf;
    t.push(k(
        "microfacet::alpha_from_perceptual",
        vec![p("roughness", 0.5, &[-0.1, -INF])],
        |x| vec![mf::alpha_from_perceptual(x[0])],
    ));
    t.push(k(
        "microfacet::perceptual_from_alpha",
        vec![p("alpha", 0.25, &[-0.1, -INF])],
        |x| vec![mf::perceptual_from_alpha(x[0])],
    ));
}

/// The `Microfacet` trait's methods on one distribution, directions as inputs.
#[cfg(feature = "microfacet")]
fn trait_rows<T: Real, M: brdf::microfacet::Microfacet<T> + Copy + 'static>(
    t: &mut Vec<Kernel<T>>,
    ty: &str,
    dist: M,
) {
    t.push(k(&format!("{ty}::d"), vec![v("m", M)], move |x| {
        vec![dist.d(v3(x, 0))]
    }));
    t.push(k(&format!("{ty}::lambda"), vec![v("w", WO)], move |x| {
        vec![dist.lambda(v3(x, 0))]
    }));
    t.push(k(
        &format!("{ty}::cos_lambda"),
        vec![v("w", WO)],
        move |x| vec![dist.cos_lambda(v3(x, 0))],
    ));
    t.push(k(&format!("{ty}::g1"), vec![v("w", WO)], move |x| {
        vec![dist.g1(v3(x, 0))]
    }));
    t.push(k(
        &format!("{ty}::g2_correlated"),
        vec![v("wo", WO), v("wi", WI)],
        move |x| vec![dist.g2_correlated(v3(x, 0), v3(x, 3))],
    ));
    t.push(k(
        &format!("{ty}::g2_separable"),
        vec![v("wo", WO), v("wi", WI)],
        move |x| vec![dist.g2_separable(v3(x, 0), v3(x, 3))],
    ));
    t.push(k(
        &format!("{ty}::v_correlated"),
        vec![v("wo", WO), v("wi", WI)],
        move |x| vec![dist.v_correlated(v3(x, 0), v3(x, 3))],
    ));
    t.push(k(
        &format!("{ty}::d_visible"),
        vec![v("wo", WO), v("m", M)],
        move |x| vec![dist.d_visible(v3(x, 0), v3(x, 3))],
    ));
}

#[cfg(feature = "ggx")]
fn ggx_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::ggx;
    let a = || p("alpha", 0.3, &ALPHA_BAD);
    t.push(k("ggx::d", vec![c("n_dot_h", NH), a()], |x| {
        vec![ggx::d(x[0], x[1])]
    }));
    t.push(k("ggx::d_fast", vec![c("n_dot_h", NH), a()], |x| {
        vec![ggx::d_fast(x[0], x[1])]
    }));
    t.push(k(
        "ggx::d_aniso",
        vec![
            c("n_dot_h", NH),
            c("t_dot_h", 0.3),
            c("b_dot_h", 0.2),
            p("alpha_x", 0.3, &ALPHA_BAD),
            p("alpha_y", 0.5, &ALPHA_BAD),
        ],
        |x| vec![ggx::d_aniso(x[0], x[1], x[2], x[3], x[4])],
    ));
    t.push(k("ggx::lambda", vec![c("n_dot_v", NV), a()], |x| {
        vec![ggx::lambda(x[0], x[1])]
    }));
    t.push(k("ggx::g1", vec![c("n_dot_v", NV), a()], |x| {
        vec![ggx::g1(x[0], x[1])]
    }));
    t.push(k(
        "ggx::v_correlated",
        vec![c("n_dot_v", NV), c("n_dot_l", NL), a()],
        |x| vec![ggx::v_correlated(x[0], x[1], x[2])],
    ));
    t.push(k(
        "ggx::v_correlated_hammon",
        vec![c("n_dot_v", NV), c("n_dot_l", NL), a()],
        |x| vec![ggx::v_correlated_hammon(x[0], x[1], x[2])],
    ));
    t.push(k(
        "ggx::v_correlated_fast",
        vec![c("n_dot_v", NV), c("n_dot_l", NL), a()],
        |x| vec![ggx::v_correlated_fast(x[0], x[1], x[2])],
    ));
    let kk = || p("k", 0.2, &[-0.1, 0.0, INF]);
    t.push(k("ggx::g1_schlick", vec![c("n_dot_v", NV), kk()], |x| {
        vec![ggx::g1_schlick(x[0], x[1])]
    }));
    t.push(k("ggx::schlick_k_ibl", vec![a()], |x| {
        vec![ggx::schlick_k_ibl(x[0])]
    }));
    t.push(k(
        "ggx::schlick_k_analytic",
        vec![p("perceptual_roughness", 0.5, &[-0.1, -INF])],
        |x| vec![ggx::schlick_k_analytic(x[0])],
    ));
    t.push(k(
        "ggx::v_schlick",
        vec![c("n_dot_v", NV), c("n_dot_l", NL), kk()],
        |x| vec![ggx::v_schlick(x[0], x[1], x[2])],
    ));
    trait_rows(
        t,
        "Ggx",
        ggx::Ggx::new(T::splat(0.3), T::splat(0.5)).unwrap(),
    );
}

#[cfg(feature = "beckmann")]
fn beckmann_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::beckmann as bk;
    let a = || p("alpha", 0.3, &ALPHA_BAD);
    t.push(k("beckmann::d", vec![c("n_dot_h", NH), a()], |x| {
        vec![bk::d(x[0], x[1])]
    }));
    t.push(k("beckmann::d_fast", vec![c("n_dot_h", NH), a()], |x| {
        vec![bk::d_fast(x[0], x[1])]
    }));
    t.push(k("beckmann::a_of", vec![c("n_dot_v", NV), a()], |x| {
        vec![bk::a_of(x[0], x[1])]
    }));
    t.push(k("beckmann::lambda", vec![c("n_dot_v", NV), a()], |x| {
        vec![bk::lambda(x[0], x[1])]
    }));
    t.push(k("beckmann::g1", vec![c("n_dot_v", NV), a()], |x| {
        vec![bk::g1(x[0], x[1])]
    }));
    t.push(k(
        "beckmann::lambda_walter",
        vec![c("n_dot_v", NV), a()],
        |x| vec![bk::lambda_walter(x[0], x[1])],
    ));
    t.push(k(
        "beckmann::alpha_from_blinn_phong",
        vec![p("exponent", 50.0, &[-1.0, -INF])],
        |x| vec![bk::alpha_from_blinn_phong(x[0])],
    ));
    t.push(k(
        "beckmann::blinn_phong_from_alpha",
        vec![p("alpha", 0.3, &[-0.1, -INF])],
        |x| vec![bk::blinn_phong_from_alpha(x[0])],
    ));
    trait_rows(
        t,
        "Beckmann",
        bk::Beckmann::new(T::splat(0.3), T::splat(0.5)).unwrap(),
    );
}

#[cfg(feature = "cook-torrance")]
fn cook_torrance_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::cook_torrance as ct;
    use brdf::fresnel as fr;
    t.push(k(
        "cook_torrance::half_vector",
        vec![v("wo", WO), v("wi", WI)],
        |x| o4(ct::half_vector(v3(x, 0), v3(x, 3))),
    ));
    t.push(k(
        "cook_torrance::half_cosines",
        vec![v("wo", WO), v("wi", WI)],
        |x| {
            let (nh, vh) = ct::half_cosines(v3(x, 0), v3(x, 3));
            vec![nh, vh]
        },
    ));
    #[cfg(feature = "ggx")]
    {
        let g = brdf::ggx::Ggx::new(T::splat(0.3), T::splat(0.5)).unwrap();
        t.push(k(
            "cook_torrance::eval",
            vec![v("wo", WO), v("wi", WI), p("f0", 0.04, &UNIT_BAD)],
            move |x| vec![ct::eval(&g, v3(x, 0), v3(x, 3), |c| fr::schlick(x[6], c))],
        ));
        t.push(k(
            "cook_torrance::dielectric",
            vec![v("wo", WO), v("wi", WI), p("eta", 1.5, &ETA_BAD)],
            move |x| vec![ct::dielectric(&g, v3(x, 0), v3(x, 3), x[6])],
        ));
        t.push(k(
            "cook_torrance::conductor",
            vec![
                v("wo", WO),
                v("wi", WI),
                p("eta", 0.2, &ETA_BAD),
                p("k", 3.0, &NONNEG_BAD),
            ],
            move |x| vec![ct::conductor(&g, v3(x, 0), v3(x, 3), x[6], x[7])],
        ));
        t.push(
            k(
                "cook_torrance::eval_rgb",
                vec![
                    v("wo", WO),
                    v("wi", WI),
                    rgb("f0", [0.9, 0.6, 0.3], &UNIT_BAD),
                ],
                move |x| {
                    o3(ct::eval_rgb(&g, v3(x, 0), v3(x, 3), |c| {
                        fr::schlick_rgb(v3(x, 6), c)
                    }))
                },
            )
            .dep("f0.x", &[0])
            .dep("f0.y", &[1])
            .dep("f0.z", &[2]),
        );
        t.push(k(
            "cook_torrance::ggx",
            vec![
                c("n_dot_h", NH),
                c("n_dot_v", NV),
                c("n_dot_l", NL),
                c("v_dot_h", VH),
                p("alpha", 0.3, &ALPHA_BAD),
                // F >= 0: a coloured F90 or a layered F may exceed 1.
                p("fresnel", 0.1, &[-0.1, -INF]),
            ],
            |x| {
                vec![ct::ggx(
                    Cosines {
                        n_dot_v: x[1],
                        n_dot_l: x[2],
                        n_dot_h: x[0],
                        v_dot_h: x[3],
                    },
                    Alpha(x[4]),
                    x[5],
                )]
            },
        ));
        t.push(k(
            "cook_torrance::ggx_conductor_local",
            vec![
                v("wo", WO),
                v("wi", WI),
                p("alpha", 0.3, &ALPHA_BAD),
                p("eta", 0.2, &ETA_BAD),
                p("k", 3.0, &NONNEG_BAD),
            ],
            |x| {
                vec![ct::ggx_conductor_local(
                    v3(x, 0),
                    v3(x, 3),
                    Alpha(x[6]),
                    x[7],
                    x[8],
                )]
            },
        ));
        t.push(k(
            "cook_torrance::ggx_conductor_local_fast",
            vec![
                v("wo", WO),
                v("wi", WI),
                p("alpha", 0.3, &ALPHA_BAD),
                p("eta", 0.2, &ETA_BAD),
                p("k", 3.0, &NONNEG_BAD),
            ],
            |x| {
                vec![ct::ggx_conductor_local_fast(
                    v3(x, 0),
                    v3(x, 3),
                    Alpha(x[6]),
                    x[7],
                    x[8],
                )]
            },
        ));
        t.push(
            k(
                "cook_torrance::ggx_conductor_rgb_fast",
                vec![
                    c("n_dot_h", NH),
                    c("n_dot_v", NV),
                    c("n_dot_l", NL),
                    c("v_dot_h", VH),
                    p("alpha", 0.3, &ALPHA_BAD),
                    rgb("eta", [0.18, 0.42, 1.37], &ETA_BAD),
                    rgb("k", [3.42, 2.35, 1.77], &NONNEG_BAD),
                ],
                |x| {
                    o3(ct::ggx_conductor_rgb_fast(
                        Cosines {
                            n_dot_v: x[1],
                            n_dot_l: x[2],
                            n_dot_h: x[0],
                            v_dot_h: x[3],
                        },
                        Alpha(x[4]),
                        ComplexIor {
                            eta: v3(x, 5),
                            k: v3(x, 8),
                        },
                    ))
                },
            )
            .dep("eta.x", &[0])
            .dep("eta.y", &[1])
            .dep("eta.z", &[2])
            .dep("k.x", &[0])
            .dep("k.y", &[1])
            .dep("k.z", &[2]),
        );
        t.push(
            k(
                "cook_torrance::ggx_conductor_rgb",
                vec![
                    c("n_dot_h", NH),
                    c("n_dot_v", NV),
                    c("n_dot_l", NL),
                    c("v_dot_h", VH),
                    p("alpha", 0.3, &ALPHA_BAD),
                    rgb("eta", [0.18, 0.42, 1.37], &ETA_BAD),
                    rgb("k", [3.42, 2.35, 1.77], &NONNEG_BAD),
                ],
                |x| {
                    o3(ct::ggx_conductor_rgb(
                        Cosines {
                            n_dot_v: x[1],
                            n_dot_l: x[2],
                            n_dot_h: x[0],
                            v_dot_h: x[3],
                        },
                        Alpha(x[4]),
                        ComplexIor {
                            eta: v3(x, 5),
                            k: v3(x, 8),
                        },
                    ))
                },
            )
            .dep("eta.x", &[0])
            .dep("eta.y", &[1])
            .dep("eta.z", &[2])
            .dep("k.x", &[0])
            .dep("k.y", &[1])
            .dep("k.z", &[2]),
        );
        t.push(
            k(
                "cook_torrance::ggx_schlick_rgb",
                vec![
                    c("n_dot_h", NH),
                    c("n_dot_v", NV),
                    c("n_dot_l", NL),
                    c("v_dot_h", VH),
                    p("alpha", 0.3, &ALPHA_BAD),
                    rgb("f0", [0.9, 0.6, 0.3], &UNIT_BAD),
                ],
                |x| {
                    o3(ct::ggx_schlick_rgb(
                        Cosines {
                            n_dot_v: x[1],
                            n_dot_l: x[2],
                            n_dot_h: x[0],
                            v_dot_h: x[3],
                        },
                        Alpha(x[4]),
                        v3(x, 5),
                    ))
                },
            )
            .dep("f0.x", &[0])
            .dep("f0.y", &[1])
            .dep("f0.z", &[2]),
        );
        t.push(k(
            "cook_torrance::ggx_dielectric",
            vec![
                c("n_dot_h", NH),
                c("n_dot_v", NV),
                c("n_dot_l", NL),
                c("v_dot_h", VH),
                p("alpha", 0.3, &ALPHA_BAD),
                p("eta", 1.5, &ETA_BAD),
            ],
            |x| {
                vec![ct::ggx_dielectric(
                    Cosines {
                        n_dot_v: x[1],
                        n_dot_l: x[2],
                        n_dot_h: x[0],
                        v_dot_h: x[3],
                    },
                    Alpha(x[4]),
                    x[5],
                )]
            },
        ));
        t.push(k(
            "cook_torrance::ggx_dielectric_fast",
            vec![
                c("n_dot_h", NH),
                c("n_dot_v", NV),
                c("n_dot_l", NL),
                c("v_dot_h", VH),
                p("alpha", 0.3, &ALPHA_BAD),
                p("eta", 1.5, &ETA_BAD),
            ],
            |x| {
                vec![ct::ggx_dielectric_fast(
                    Cosines {
                        n_dot_v: x[1],
                        n_dot_l: x[2],
                        n_dot_h: x[0],
                        v_dot_h: x[3],
                    },
                    Alpha(x[4]),
                    x[5],
                )]
            },
        ));
    }
    #[cfg(feature = "beckmann")]
    t.push(k(
        "cook_torrance::beckmann",
        vec![
            c("n_dot_h", NH),
            c("n_dot_v", NV),
            c("n_dot_l", NL),
            c("v_dot_h", VH),
            p("alpha", 0.3, &ALPHA_BAD),
            // F >= 0: a coloured F90 or a layered F may exceed 1.
            p("fresnel", 0.1, &[-0.1, -INF]),
        ],
        |x| {
            vec![ct::beckmann(
                Cosines {
                    n_dot_v: x[1],
                    n_dot_l: x[2],
                    n_dot_h: x[0],
                    v_dot_h: x[3],
                },
                Alpha(x[4]),
                x[5],
            )]
        },
    ));
    #[cfg(feature = "beckmann")]
    {
        t.push(
            k(
                "cook_torrance::beckmann_conductor_rgb",
                vec![
                    c("n_dot_h", NH),
                    c("n_dot_v", NV),
                    c("n_dot_l", NL),
                    c("v_dot_h", VH),
                    p("alpha", 0.3, &ALPHA_BAD),
                    rgb("eta", [0.18, 0.42, 1.37], &ETA_BAD),
                    rgb("k", [3.42, 2.35, 1.77], &NONNEG_BAD),
                ],
                |x| {
                    o3(ct::beckmann_conductor_rgb(
                        Cosines {
                            n_dot_v: x[1],
                            n_dot_l: x[2],
                            n_dot_h: x[0],
                            v_dot_h: x[3],
                        },
                        Alpha(x[4]),
                        ComplexIor {
                            eta: v3(x, 5),
                            k: v3(x, 8),
                        },
                    ))
                },
            )
            .dep("eta.x", &[0])
            .dep("eta.y", &[1])
            .dep("eta.z", &[2])
            .dep("k.x", &[0])
            .dep("k.y", &[1])
            .dep("k.z", &[2]),
        );
        t.push(
            k(
                "cook_torrance::beckmann_schlick_rgb",
                vec![
                    c("n_dot_h", NH),
                    c("n_dot_v", NV),
                    c("n_dot_l", NL),
                    c("v_dot_h", VH),
                    p("alpha", 0.3, &ALPHA_BAD),
                    rgb("f0", [0.9, 0.6, 0.3], &UNIT_BAD),
                ],
                |x| {
                    o3(ct::beckmann_schlick_rgb(
                        Cosines {
                            n_dot_v: x[1],
                            n_dot_l: x[2],
                            n_dot_h: x[0],
                            v_dot_h: x[3],
                        },
                        Alpha(x[4]),
                        v3(x, 5),
                    ))
                },
            )
            .dep("f0.x", &[0])
            .dep("f0.y", &[1])
            .dep("f0.z", &[2]),
        );
        t.push(k(
            "cook_torrance::beckmann_dielectric",
            vec![
                c("n_dot_h", NH),
                c("n_dot_v", NV),
                c("n_dot_l", NL),
                c("v_dot_h", VH),
                p("alpha", 0.3, &ALPHA_BAD),
                p("eta", 1.5, &ETA_BAD),
            ],
            |x| {
                vec![ct::beckmann_dielectric(
                    Cosines {
                        n_dot_v: x[1],
                        n_dot_l: x[2],
                        n_dot_h: x[0],
                        v_dot_h: x[3],
                    },
                    Alpha(x[4]),
                    x[5],
                )]
            },
        ));
    }
}

#[cfg(all(feature = "transmission", feature = "ggx", feature = "beckmann"))]
fn rough_dielectric_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::rough_dielectric::{self as rd, Transport};
    // A refracted pair (wi inside), so the transmission lobe is the one checked.
    const WT: [f64; 3] = [-0.3, 0.0, -0.953_939_201_416_945_6];
    let g = brdf::ggx::Ggx::new(T::splat(0.3), T::splat(0.5)).unwrap();
    let b = brdf::beckmann::Beckmann::new(T::splat(0.3), T::splat(0.5)).unwrap();
    t.push(k(
        "rough_dielectric::half_vector",
        vec![v("wo", WO), v("wi", WT), p("eta", 1.5, &ETA_BAD)],
        |x| o3(rd::half_vector(v3(x, 0), v3(x, 3), x[6])),
    ));
    for (tr, name) in [
        (Transport::Radiance, "Radiance"),
        (Transport::Importance, "Importance"),
    ] {
        for wi in [WI, WT] {
            t.push(k(
                &format!("rough_dielectric::eval(Ggx, {name}, wi.z {})", wi[2]),
                vec![v("wo", WO), v("wi", wi), p("eta", 1.5, &ETA_BAD)],
                move |x| vec![rd::eval(&g, v3(x, 0), v3(x, 3), x[6], tr)],
            ));
            t.push(k(
                &format!("rough_dielectric::eval(Beckmann, {name}, wi.z {})", wi[2]),
                vec![v("wo", WO), v("wi", wi), p("eta", 1.5, &ETA_BAD)],
                move |x| vec![rd::eval(&b, v3(x, 0), v3(x, 3), x[6], tr)],
            ));
        }
        let u = || [c("u0", 0.9), c("u1", 0.3), c("u2", 0.6)].concat();
        t.push(k(
            &format!("rough_dielectric::ggx_sample({name})"),
            vec![v("wo", WO), p("eta", 1.5, &ETA_BAD), u()],
            move |x| {
                let (wi, pdf, w) = rd::ggx_sample(&g, v3(x, 0), x[3], x[4], x[5], x[6], tr);
                vec![wi.x, wi.y, wi.z, pdf, w]
            },
        ));
        t.push(k(
            &format!("rough_dielectric::beckmann_sample({name})"),
            vec![v("wo", WO), p("eta", 1.5, &ETA_BAD), u()],
            move |x| {
                let (wi, pdf, w) = rd::beckmann_sample(&b, v3(x, 0), x[3], x[4], x[5], x[6], tr);
                vec![wi.x, wi.y, wi.z, pdf, w]
            },
        ));
    }
    for wi in [WI, WT] {
        t.push(k(
            &format!("rough_dielectric::pdf(Ggx, wi.z {})", wi[2]),
            vec![v("wo", WO), v("wi", wi), p("eta", 1.5, &ETA_BAD)],
            move |x| vec![rd::pdf(&g, v3(x, 0), v3(x, 3), x[6])],
        ));
        t.push(k(
            &format!("rough_dielectric::pdf(Beckmann, wi.z {})", wi[2]),
            vec![v("wo", WO), v("wi", wi), p("eta", 1.5, &ETA_BAD)],
            move |x| vec![rd::pdf(&b, v3(x, 0), v3(x, 3), x[6])],
        ));
    }
}

#[cfg(all(feature = "transmission", feature = "ggx"))]
fn gltf_transmission_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::transmission::{self as tr, Transmission, Volume};
    const WT: [f64; 3] = [-0.3, 0.0, -0.953_939_201_416_945_6];
    let g = brdf::ggx::Ggx::new(T::splat(0.3), T::splat(0.5)).unwrap();
    let vol = |th: f64| {
        Volume::new(
            T::splat(th),
            V3::new(T::splat(0.9), T::splat(0.5), T::splat(0.2)),
            T::splat(2.0),
        )
        .unwrap()
    };
    let (thin, thick) = (vol(0.0), vol(1.0));
    t.push(k(
        "Volume::transmittance",
        vec![p("path_length", 1.5, &NONNEG_BAD)],
        move |x| o3(thick.transmittance(x[0])),
    ));
    t.push(k(
        "transmission::thin_walled_btdf",
        vec![v("wo", WO), v("wi", WT)],
        move |x| vec![tr::thin_walled_btdf(&g, v3(x, 0), v3(x, 3))],
    ));
    for (name, volume) in [("thin", thin), ("volumetric", thick)] {
        for wi in [WI, WT] {
            let tf = Transmission::new(T::splat(0.7)).unwrap();
            t.push(
                k(
                    &format!("transmission::dielectric_bsdf({name}, wi.z {})", wi[2]),
                    vec![
                        v("wo", WO),
                        v("wi", wi),
                        rgb("base_color", [0.9, 0.6, 0.3], &UNIT_BAD),
                        p("ior", 1.5, &ETA_BAD),
                    ],
                    move |x| {
                        o3(tr::dielectric_bsdf(
                            &g,
                            v3(x, 0),
                            v3(x, 3),
                            v3(x, 6),
                            x[9],
                            &tf,
                            &volume,
                        ))
                    },
                )
                .dep("base_color.x", &[0])
                .dep("base_color.y", &[1])
                .dep("base_color.z", &[2]),
            );
        }
    }
}

#[cfg(feature = "iridescence")]
fn iridescence_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::iridescence::{self as ir, ThinFilm};
    for d in [0.0, 300.0] {
        let film = ThinFilm::new(T::splat(d), T::splat(1.33)).unwrap();
        t.push(k(
            &format!("iridescence::dielectric(d {d})"),
            vec![
                p("outside_ior", 1.0, &ETA_BAD),
                p("base_ior", 1.5, &ETA_BAD),
                c("cos_theta", VH),
            ],
            move |x| o3(ir::dielectric(&film, x[0], x[1], x[2])),
        ));
        t.push(k(
            &format!("iridescence::conductor(d {d})"),
            vec![
                p("outside_ior", 1.0, &ETA_BAD),
                p("base_eta", 0.2, &ETA_BAD),
                p("base_k", 3.9, &NONNEG_BAD),
                c("cos_theta", VH),
            ],
            move |x| o3(ir::conductor(&film, x[0], x[1], x[2], x[3])),
        ));
    }
}

#[cfg(feature = "sampling")]
fn sampling_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::sampling as sm;
    let u = || [c("u1", 0.3), c("u2", 0.6)].concat();
    t.push(k("sampling::cosine_hemisphere", vec![u()], |x| {
        o4(sm::cosine_hemisphere(x[0], x[1]))
    }));
    t.push(k(
        "sampling::cosine_hemisphere_pdf",
        vec![v("wi", WI)],
        |x| vec![sm::cosine_hemisphere_pdf(v3(x, 0))],
    ));
    t.push(k(
        "sampling::reflect_pdf",
        vec![p("pdf_m", 1.5, &[-1.0, -INF]), c("v_dot_h", VH)],
        |x| vec![sm::reflect_pdf(x[0], x[1])],
    ));
    #[cfg(feature = "ggx")]
    {
        let g = brdf::ggx::Ggx::new(T::splat(0.3), T::splat(0.5)).unwrap();
        t.push(k("sampling::ggx_d_cos", vec![u()], move |x| {
            o4(sm::ggx_d_cos(&g, x[0], x[1]))
        }));
        t.push(k("sampling::d_cos_pdf(Ggx)", vec![v("m", M)], move |x| {
            vec![sm::d_cos_pdf(&g, v3(x, 0))]
        }));
        t.push(k(
            "sampling::visible_normal_pdf(Ggx)",
            vec![v("wo", WO), v("m", M)],
            move |x| vec![sm::visible_normal_pdf(&g, v3(x, 0), v3(x, 3))],
        ));
        t.push(k("sampling::ggx_vndf", vec![v("wo", WO), u()], move |x| {
            o4(sm::ggx_vndf(&g, v3(x, 0), x[3], x[4]))
        }));
        t.push(k(
            "sampling::ggx_vndf_spherical_cap",
            vec![v("wo", WO), u()],
            move |x| o4(sm::ggx_vndf_spherical_cap(&g, v3(x, 0), x[3], x[4])),
        ));
        // The Fresnel closure returns a constant F >= 0: its NaN reaches the weight only.
        t.push(
            k(
                "sampling::ggx_reflection",
                vec![v("wo", WO), u(), p("fresnel", 0.5, &[-0.1, -INF])],
                move |x| {
                    let (wi, pdf, w) = sm::ggx_reflection(&g, v3(x, 0), x[3], x[4], |_| x[5]);
                    vec![wi.x, wi.y, wi.z, pdf, w]
                },
            )
            .dep("fresnel", &[4]),
        );
        t.push(
            k(
                "sampling::ggx_reflection_rgb",
                vec![v("wo", WO), u(), rgb("f", [0.9, 0.6, 0.3], &[-0.1, -INF])],
                move |x| {
                    let f = v3(x, 5);
                    let (wi, pdf, w) = sm::ggx_reflection_rgb(&g, v3(x, 0), x[3], x[4], |_| f);
                    vec![wi.x, wi.y, wi.z, pdf, w.x, w.y, w.z]
                },
            )
            .dep("f.x", &[4])
            .dep("f.y", &[5])
            .dep("f.z", &[6]),
        );
        t.push(k(
            "sampling::ggx_reflection_pdf",
            vec![v("wo", WO), v("wi", WI)],
            move |x| vec![sm::ggx_reflection_pdf(&g, v3(x, 0), v3(x, 3))],
        ));
    }
    #[cfg(feature = "beckmann")]
    {
        let b = brdf::beckmann::Beckmann::new(T::splat(0.3), T::splat(0.5)).unwrap();
        t.push(k("sampling::beckmann_d_cos", vec![u()], move |x| {
            o4(sm::beckmann_d_cos(&b, x[0], x[1]))
        }));
        t.push(k(
            "sampling::d_cos_pdf(Beckmann)",
            vec![v("m", M)],
            move |x| vec![sm::d_cos_pdf(&b, v3(x, 0))],
        ));
        t.push(k(
            "sampling::visible_normal_pdf(Beckmann)",
            vec![v("wo", WO), v("m", M)],
            move |x| vec![sm::visible_normal_pdf(&b, v3(x, 0), v3(x, 3))],
        ));
        t.push(k(
            "sampling::erf_inv",
            vec![p("y", 0.3, &[1.5, -1.5, INF])],
            |x| vec![sm::erf_inv(x[0])],
        ));
        t.push(k(
            "sampling::beckmann_vndf",
            vec![v("wo", WO), u()],
            move |x| o4(sm::beckmann_vndf(&b, v3(x, 0), x[3], x[4])),
        ));
        t.push(
            k(
                "sampling::beckmann_reflection",
                vec![v("wo", WO), u(), p("fresnel", 0.5, &[-0.1, -INF])],
                move |x| {
                    let (wi, pdf, w) = sm::beckmann_reflection(&b, v3(x, 0), x[3], x[4], |_| x[5]);
                    vec![wi.x, wi.y, wi.z, pdf, w]
                },
            )
            .dep("fresnel", &[4]),
        );
        t.push(
            k(
                "sampling::beckmann_reflection_rgb",
                vec![v("wo", WO), u(), rgb("f", [0.9, 0.6, 0.3], &[-0.1, -INF])],
                move |x| {
                    let f = v3(x, 5);
                    let (wi, pdf, w) = sm::beckmann_reflection_rgb(&b, v3(x, 0), x[3], x[4], |_| f);
                    vec![wi.x, wi.y, wi.z, pdf, w.x, w.y, w.z]
                },
            )
            .dep("f.x", &[4])
            .dep("f.y", &[5])
            .dep("f.z", &[6]),
        );
        t.push(k(
            "sampling::beckmann_reflection_pdf",
            vec![v("wo", WO), v("wi", WI)],
            move |x| vec![sm::beckmann_reflection_pdf(&b, v3(x, 0), v3(x, 3))],
        ));
    }
}

#[cfg(feature = "tonemap")]
fn tonemap_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::color;
    use brdf::tonemap::{self as tm, AgxLook, HableParams, LottesParams, Operator, UchimuraParams};
    let per_channel = |kern: Kernel<T>| kern.dep("c.x", &[0]).dep("c.y", &[1]).dep("c.z", &[2]);
    let col = [0.5, 2.0, 0.05];
    t.push(k("color::luminance", vec![v("c", col)], |x| {
        vec![color::luminance(v3(x, 0))]
    }));
    t.push(k("color::mul", vec![v("c", col)], |x| {
        o3(color::mul(&color::AGX_INSET, v3(x, 0)))
    }));
    for (name, f) in [
        ("color::srgb_oetf", color::srgb_oetf::<T> as fn(T) -> T),
        ("color::srgb_oetf_fast", color::srgb_oetf_fast::<T>),
        ("color::srgb_eotf", color::srgb_eotf::<T>),
        ("color::rec709_oetf", color::rec709_oetf::<T>),
        ("tonemap::sanitize", tm::sanitize::<T>),
        ("tonemap::reinhard", tm::reinhard::<T>),
        ("tonemap::aces_narkowicz", tm::aces_narkowicz::<T>),
    ] {
        t.push(k(name, vec![c("x", 0.4)], move |x| vec![f(x[0])]));
    }
    t.push(k(
        "color::gamma_encode",
        vec![c("x", 0.4), p("gamma", 2.2, &[0.0, -1.0, -INF])],
        |x| vec![color::gamma_encode(x[0], x[1])],
    ));
    t.push(k(
        "color::gamma_decode",
        vec![c("x", 0.4), p("gamma", 2.2, &[0.0, -1.0, -INF])],
        |x| vec![color::gamma_decode(x[0], x[1])],
    ));
    t.push(per_channel(k(
        "color::srgb_oetf_rgb",
        vec![v("c", col)],
        |x| o3(color::srgb_oetf_rgb(v3(x, 0))),
    )));
    t.push(per_channel(k(
        "color::srgb_eotf_rgb",
        vec![v("c", col)],
        |x| o3(color::srgb_eotf_rgb(v3(x, 0))),
    )));
    t.push(k(
        "tonemap::ev100_from_camera",
        vec![
            p("aperture", 16.0, &[0.0, -1.0, INF]),
            p("shutter_s", 0.01, &[0.0, -1.0, INF]),
            p("iso", 100.0, &[0.0, -1.0, INF]),
        ],
        |x| vec![per_lane(x, |a| tm::ev100_from_camera(a[0], a[1], a[2]))],
    ));
    t.push(k(
        "tonemap::exposure_curve",
        vec![c("c", 0.4), p("exposure", 1.5, &[-1.0, -INF])],
        |x| vec![tm::exposure_curve(x[0], x[1])],
    ));
    t.push(k(
        "tonemap::reinhard_extended",
        vec![c("c", 0.4), p("white", 4.0, &[0.0, -1.0, -INF])],
        |x| vec![tm::reinhard_extended(x[0], x[1])],
    ));
    t.push(k(
        "tonemap::reinhard_extended_luminance",
        vec![v("c", col), p("white", 4.0, &[0.0, -1.0, -INF])],
        |x| o3(tm::reinhard_extended_luminance(v3(x, 0), x[3])),
    ));
    for (name, f) in [
        (
            "tonemap::reinhard_luminance",
            tm::reinhard_luminance::<T> as fn(V3<T>) -> V3<T>,
        ),
        ("tonemap::reinhard_jodie", tm::reinhard_jodie::<T>),
        ("tonemap::aces_hill", tm::aces_hill::<T>),
        ("tonemap::pbr_neutral", tm::pbr_neutral::<T>),
    ] {
        t.push(k(name, vec![v("c", col)], move |x| o3(f(v3(x, 0)))));
    }
    t.push(k("tonemap::hable", vec![c("c", 0.4)], |x| {
        vec![tm::hable(x[0], &HableParams::UNCHARTED2)]
    }));
    t.push(k("tonemap::lottes", vec![c("c", 0.4)], |x| {
        vec![tm::lottes(x[0], &LottesParams::default_curve())]
    }));
    t.push(k("tonemap::uchimura", vec![c("c", 0.4)], |x| {
        vec![tm::uchimura(x[0], &UchimuraParams::GRAN_TURISMO)]
    }));
    t.push(k("tonemap::agx_minimal", vec![v("c", col)], |x| {
        o3(tm::agx_minimal(v3(x, 0), &AgxLook::PUNCHY))
    }));
    t.push(k("tonemap::agx_threejs", vec![v("c", col)], |x| {
        o3(tm::agx_threejs(v3(x, 0)))
    }));
    t.push(k("tonemap::agx_filament", vec![v("c", col)], |x| {
        o3(tm::agx_filament(v3(x, 0), &AgxLook::GOLDEN_FILAMENT))
    }));
    for (i, op) in Operator::all().into_iter().enumerate() {
        let variant: String = format!("{op:?}")
            .chars()
            .take_while(|c| c.is_alphanumeric())
            .collect();
        let row = k(
            &format!("Operator::apply({i}: {variant})"),
            vec![v("c", col)],
            move |x| o3(op.apply(v3(x, 0))),
        );
        let separable = matches!(
            op,
            Operator::ExposureCurve(_)
                | Operator::Reinhard
                | Operator::ReinhardExtended(_)
                | Operator::AcesNarkowicz
                | Operator::Hable(_)
                | Operator::Lottes(_)
                | Operator::Uchimura(_)
        );
        t.push(if separable { per_channel(row) } else { row });
    }
}

#[cfg(feature = "diffuse")]
fn diffuse_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::diffuse::*;
    let rho = || p("rho", 0.8, &UNIT_BAD);
    let sigma_rad = || p("sigma", 0.5, &[-0.1, INF, -INF]);
    let sigma = || p("sigma", 0.5, &UNIT_BAD);
    let cos3 = |third: &str, val: f64| [c("n_dot_v", NV), c("n_dot_l", NL), c(third, val)].concat();
    let s = T::splat;
    t.push(k(
        "diffuse::lambert",
        vec![c("n_dot_v", NV), c("n_dot_l", NL), rho()],
        |x| vec![lambert(x[0], x[1], x[2])],
    ));
    t.push(k("diffuse::oren_nayar_a", vec![sigma_rad()], |x| {
        vec![oren_nayar_a(x[0])]
    }));
    t.push(k("diffuse::oren_nayar_b", vec![sigma_rad()], |x| {
        vec![oren_nayar_b(x[0])]
    }));
    type K5<T> = fn(T, T, T, T, T) -> T;
    for (name, f, sg) in [
        ("diffuse::oren_nayar", oren_nayar::<T> as K5<T>, true),
        ("diffuse::oren_nayar_full", oren_nayar_full::<T>, true),
        ("diffuse::oren_nayar_fujii", oren_nayar_fujii::<T>, false),
        ("diffuse::eon", eon::<T>, false),
        ("diffuse::eon_approx", eon_approx::<T>, false),
    ] {
        let sig = if sg { sigma_rad() } else { sigma() };
        t.push(k(name, vec![cos3("v_dot_l", VL), rho(), sig], move |x| {
            vec![f(x[0], x[1], x[2], x[3], x[4])]
        }));
    }
    for (name, f) in [
        ("diffuse::burley", burley::<T> as K5<T>),
        ("diffuse::burley_renormalized", burley_renormalized::<T>),
    ] {
        t.push(k(
            name,
            vec![cos3("l_dot_h", VH), rho(), p("roughness", 0.5, &UNIT_BAD)],
            move |x| vec![f(x[0], x[1], x[2], x[3], x[4])],
        ));
    }
    t.push(k(
        "diffuse::eon_fon_albedo",
        vec![c("n_dot_v", NV), sigma()],
        |x| vec![eon_fon_albedo(x[0], x[1])],
    ));
    t.push(k(
        "diffuse::eon_fon_albedo_approx",
        vec![c("n_dot_v", NV), sigma()],
        |x| vec![eon_fon_albedo_approx(x[0], x[1])],
    ));
    t.push(k("diffuse::eon_fon_average_albedo", vec![sigma()], |x| {
        vec![eon_fon_average_albedo(x[0])]
    }));
    t.push(k(
        "diffuse::eon_multiscatter_albedo",
        vec![rho(), sigma()],
        |x| vec![eon_multiscatter_albedo(x[0], x[1])],
    ));
    t.push(k(
        "diffuse::eon_albedo",
        vec![c("n_dot_v", NV), rho(), sigma()],
        |x| vec![eon_albedo(x[0], x[1], x[2])],
    ));
    t.push(k(
        "diffuse::eon_albedo_approx",
        vec![c("n_dot_v", NV), rho(), sigma()],
        |x| vec![eon_albedo_approx(x[0], x[1], x[2])],
    ));
    let u = || [c("u1", 0.3), c("u2", 0.6)].concat();
    t.push(k(
        "diffuse::eon_cltc_sample",
        vec![v("wo", WO), sigma(), u()],
        |x| o4(eon_cltc_sample(v3(x, 0), x[3], x[4], x[5])),
    ));
    t.push(k(
        "diffuse::eon_sample",
        vec![v("wo", WO), sigma(), u()],
        |x| o4(eon_sample(v3(x, 0), x[3], x[4], x[5])),
    ));
    t.push(k(
        "diffuse::eon_cltc_pdf",
        vec![v("wo", WO), v("wi", WI), sigma()],
        |x| vec![eon_cltc_pdf(v3(x, 0), v3(x, 3), x[6])],
    ));
    t.push(k(
        "diffuse::eon_pdf",
        vec![v("wo", WO), v("wi", WI), sigma()],
        |x| vec![eon_pdf(v3(x, 0), v3(x, 3), x[6])],
    ));
    t.push(k(
        "diffuse::fresnel_weight_normalized",
        vec![
            p("fresnel_l", 0.3, &UNIT_BAD),
            p("f0", 0.04, &[-0.1, 1.0, 1.1, INF]),
        ],
        |x| vec![fresnel_weight_normalized(x[0], x[1])],
    ));
    t.push(k(
        "diffuse::fresnel_weight_symmetric",
        vec![
            p("fresnel_v", 0.3, &UNIT_BAD),
            p("fresnel_l", 0.1, &UNIT_BAD),
        ],
        |x| vec![fresnel_weight_symmetric(x[0], x[1])],
    ));
    let brdf_value = |n: &str, val: f64| p(n, val, &[-0.1, INF, -INF]);
    t.push(k(
        "diffuse::fresnel_mix",
        vec![
            brdf_value("f_diffuse", 0.2),
            brdf_value("f_specular", 0.7),
            p("fresnel", 0.3, &UNIT_BAD),
        ],
        |x| vec![fresnel_mix(x[0], x[1], x[2])],
    ));
    t.push(k(
        "diffuse::fresnel_mix_schlick",
        vec![
            brdf_value("f_diffuse", 0.2),
            brdf_value("f_specular", 0.7),
            p("f0", 0.04, &UNIT_BAD),
            c("cos_theta", VH),
        ],
        |x| vec![fresnel_mix_schlick(x[0], x[1], x[2], x[3])],
    ));
    t.push(k(
        "diffuse::shirley_coupled",
        vec![
            c("n_dot_v", NV),
            c("n_dot_l", NL),
            rho(),
            p("f0", 0.04, &UNIT_BAD),
        ],
        |x| vec![shirley_coupled(x[0], x[1], x[2], x[3])],
    ));
    t.push(k(
        "diffuse::ashikhmin_shirley",
        vec![
            c("n_dot_v", NV),
            c("n_dot_l", NL),
            rho(),
            p("rs", 0.04, &UNIT_BAD),
        ],
        |x| vec![ashikhmin_shirley(x[0], x[1], x[2], x[3])],
    ));
    // The parameter types: parameters validated by their constructors, directions as inputs.
    let dirs = || [v("wo", WO), v("wi", WI)].concat();
    let l = Lambert::new(s(0.8)).unwrap();
    t.push(k("Lambert::eval", vec![dirs()], move |x| {
        vec![l.eval(v3(x, 0), v3(x, 3))]
    }));
    let on = OrenNayar::new(s(0.8), s(0.5)).unwrap();
    t.push(k("OrenNayar::eval", vec![dirs()], move |x| {
        vec![on.eval(v3(x, 0), v3(x, 3))]
    }));
    let onf = OrenNayarFull::new(s(0.8), s(0.5)).unwrap();
    t.push(k("OrenNayarFull::eval", vec![dirs()], move |x| {
        vec![onf.eval(v3(x, 0), v3(x, 3))]
    }));
    let fj = OrenNayarFujii::new(s(0.8), s(0.5)).unwrap();
    t.push(k("OrenNayarFujii::eval", vec![dirs()], move |x| {
        vec![fj.eval(v3(x, 0), v3(x, 3))]
    }));
    let b = Burley::new(s(0.8), s(0.5)).unwrap();
    t.push(k("Burley::eval", vec![dirs()], move |x| {
        vec![b.eval(v3(x, 0), v3(x, 3))]
    }));
    let br = BurleyRenormalized::new(s(0.8), s(0.5)).unwrap();
    t.push(k("BurleyRenormalized::eval", vec![dirs()], move |x| {
        vec![br.eval(v3(x, 0), v3(x, 3))]
    }));
    let sc = ShirleyCoupled::new(s(0.8), s(0.04)).unwrap();
    t.push(k("ShirleyCoupled::eval", vec![dirs()], move |x| {
        vec![sc.eval(v3(x, 0), v3(x, 3))]
    }));
    let ash = AshikhminShirley::new(s(0.8), s(0.04)).unwrap();
    t.push(k("AshikhminShirley::eval", vec![dirs()], move |x| {
        vec![ash.eval(v3(x, 0), v3(x, 3))]
    }));
    let e = Eon::new(s(0.8), s(0.5)).unwrap();
    t.push(k("Eon::eval", vec![dirs()], move |x| {
        vec![e.eval(v3(x, 0), v3(x, 3))]
    }));
    t.push(k("Eon::eval_approx", vec![dirs()], move |x| {
        vec![e.eval_approx(v3(x, 0), v3(x, 3))]
    }));
    t.push(k("Eon::albedo", vec![v("wo", WO)], move |x| {
        vec![e.albedo(v3(x, 0))]
    }));
    t.push(k("Eon::albedo_approx", vec![v("wo", WO)], move |x| {
        vec![e.albedo_approx(v3(x, 0))]
    }));
    t.push(k("Eon::sample", vec![v("wo", WO), u()], move |x| {
        o4(e.sample(v3(x, 0), x[3], x[4]))
    }));
    t.push(k("Eon::pdf", vec![dirs()], move |x| {
        vec![e.pdf(v3(x, 0), v3(x, 3))]
    }));
}

#[cfg(feature = "phong")]
fn phong_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::phong::*;
    let n = || p("exponent", 30.0, &[-1.0, INF, -INF]);
    let ks = || p("ks", 0.6, &UNIT_BAD);
    let s = T::splat;
    type K1<T> = fn(T) -> T;
    for (name, f) in [
        (
            "phong::phong_normalization",
            phong_normalization::<T> as K1<T>,
        ),
        (
            "phong::blinn_phong_normalization_exact",
            blinn_phong_normalization_exact::<T>,
        ),
        (
            "phong::blinn_phong_normalization_approx",
            blinn_phong_normalization_approx::<T>,
        ),
    ] {
        t.push(k(name, vec![n()], move |x| vec![f(x[0])]));
    }
    type K5<T> = fn(T, T, T, T, T) -> T;
    for (name, f, third) in [
        ("phong::classic", classic::<T> as K5<T>, "r_dot_l"),
        ("phong::modified", modified::<T>, "r_dot_l"),
        ("phong::normalized", normalized::<T>, "r_dot_l"),
        ("phong::blinn_phong", blinn_phong::<T>, "n_dot_h"),
        (
            "phong::blinn_phong_normalized",
            blinn_phong_normalized::<T>,
            "n_dot_h",
        ),
        (
            "phong::blinn_phong_normalized_approx",
            blinn_phong_normalized_approx::<T>,
            "n_dot_h",
        ),
    ] {
        t.push(k(
            name,
            vec![
                c("n_dot_v", NV),
                c("n_dot_l", NL),
                c(third, 0.95),
                ks(),
                n(),
            ],
            move |x| vec![f(x[0], x[1], x[2], x[3], x[4])],
        ));
    }
    t.push(k(
        "phong::diffuse_specular",
        vec![
            c("n_dot_v", NV),
            c("n_dot_l", NL),
            c("r_dot_l", 0.95),
            p("kd", 0.3, &[-0.1, 0.5, 1.1, INF]),
            p("ks", 0.6, &UNIT_BAD),
            n(),
        ],
        |x| vec![diffuse_specular(x[0], x[1], x[2], x[3], x[4], x[5])],
    ));
    t.push(k(
        "phong::blinn_phong_ndf",
        vec![c("n_dot_h", NH), n()],
        |x| vec![blinn_phong_ndf(x[0], x[1])],
    ));
    let dirs = || [v("wo", WO), v("wi", WI)].concat();
    // The mirror of WO is (-0.36, -0.48, 0.8): WI at 0.53 rad from it, inside a wide lobe.
    let (ks0, n0) = (s(0.6), s(8.0));
    macro_rules! eval_row {
        ($ty:ident) => {
            let lobe = $ty::new(ks0, n0).unwrap();
            t.push(k(
                concat!(stringify!($ty), "::eval"),
                vec![dirs()],
                move |x| vec![lobe.eval(v3(x, 0), v3(x, 3))],
            ));
        };
    }
    eval_row!(ClassicPhong);
    eval_row!(ModifiedPhong);
    eval_row!(NormalizedPhong);
    eval_row!(BlinnPhong);
    eval_row!(NormalizedBlinnPhong);
    eval_row!(ApproxNormalizedBlinnPhong);
    let ds = PhongDiffuseSpecular::new(s(0.3), ks0, n0).unwrap();
    t.push(k("PhongDiffuseSpecular::eval", vec![dirs()], move |x| {
        vec![ds.eval(v3(x, 0), v3(x, 3))]
    }));
}

#[cfg(feature = "material")]
fn material_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::ShadingPoint;
    use brdf::material::*;
    let s = T::splat;
    t.push(k(
        "material::f0_from_reflectance",
        vec![p("reflectance", 0.5, &UNIT_BAD)],
        |x| vec![f0_from_reflectance(x[0])],
    ));
    let args = || {
        vec![
            c("n_dot_v", NV),
            c("n_dot_l", NL),
            c("n_dot_h", NH),
            c("v_dot_h", VH),
            rgb("base_color", [0.9, 0.6, 0.3], &UNIT_BAD),
            p("metallic", 0.5, &UNIT_BAD),
            p("roughness", 0.5, &UNIT_BAD),
        ]
    };
    for coupling in [
        DiffuseCoupling::Gltf,
        DiffuseCoupling::OneMinusF,
        DiffuseCoupling::Additive,
    ] {
        let mut a = args();
        a.push(p("dielectric_f0", 0.04, &UNIT_BAD));
        t.push(k(
            &format!("material::metallic_roughness_fast({coupling:?})"),
            a.clone(),
            move |x| {
                o3(metallic_roughness_fast(
                    Cosines {
                        n_dot_v: x[0],
                        n_dot_l: x[1],
                        n_dot_h: x[2],
                        v_dot_h: x[3],
                    },
                    v3(x, 4),
                    x[7],
                    x[8],
                    x[9],
                    coupling,
                ))
            },
        ));
        t.push(k(
            &format!("material::metallic_roughness({coupling:?})"),
            a,
            move |x| {
                o3(metallic_roughness(
                    Cosines {
                        n_dot_v: x[0],
                        n_dot_l: x[1],
                        n_dot_h: x[2],
                        v_dot_h: x[3],
                    },
                    v3(x, 4),
                    x[7],
                    x[8],
                    x[9],
                    coupling,
                ))
            },
        ));
    }
    t.push(k("material::gltf_fast", args(), |x| {
        o3(gltf_fast(
            Cosines {
                n_dot_v: x[0],
                n_dot_l: x[1],
                n_dot_h: x[2],
                v_dot_h: x[3],
            },
            v3(x, 4),
            x[7],
            x[8],
        ))
    }));
    t.push(k("material::gltf", args(), |x| {
        o3(gltf(
            Cosines {
                n_dot_v: x[0],
                n_dot_l: x[1],
                n_dot_h: x[2],
                v_dot_h: x[3],
            },
            v3(x, 4),
            x[7],
            x[8],
        ))
    }));
    let mats = [
        (
            "glTF",
            MetallicRoughness::new(V3::new(s(0.9), s(0.6), s(0.3)), s(0.5), s(0.5)).unwrap(),
        ),
        (
            "specular",
            MetallicRoughness::new(V3::new(s(0.9), s(0.6), s(0.3)), s(0.2), s(0.3))
                .and_then(|m| m.with_specular(s(0.7), V3::new(s(2.0), s(1.0), s(0.5))))
                .unwrap()
                .with_coupling(DiffuseCoupling::OneMinusF),
        ),
    ];
    for (label, m) in mats {
        let dirs = || [v("wo", WO), v("wi", WI)].concat();
        let u = || [c("u1", 0.3), c("u2", 0.6)].concat();
        t.push(k(
            &format!("MetallicRoughness::eval({label})"),
            vec![dirs()],
            move |x| o3(m.eval(v3(x, 0), v3(x, 3))),
        ));
        t.push(k(
            &format!("MetallicRoughness::eval_fast({label})"),
            vec![dirs()],
            move |x| o3(m.eval_fast(v3(x, 0), v3(x, 3))),
        ));
        t.push(k(
            &format!("MetallicRoughness::specular_probability({label})"),
            vec![v("wo", WO)],
            move |x| vec![m.specular_probability(v3(x, 0))],
        ));
        t.push(k(
            &format!("MetallicRoughness::pdf({label})"),
            vec![dirs()],
            move |x| vec![m.pdf(v3(x, 0), v3(x, 3))],
        ));
        t.push(k(
            &format!("MetallicRoughness::sample({label})"),
            vec![v("wo", WO), u()],
            move |x| o4(m.sample(v3(x, 0), x[3], x[4])),
        ));
        // The weights evaluate the BRDF at the drawn direction, whose cosine-lobe azimuth
        // comes from the lanes' `sin` and `cos` (within 1 ulp of the scalar's): the specular
        // lobe (alpha 0.09) moves by up to 7.3e-6 relative per ulp there (found on the
        // `-C target-cpu=native` build, `specular` at u = (0.3, 0.6)).
        t.push(
            k(
                &format!("MetallicRoughness::sample_weighted({label})"),
                vec![v("wo", WO), u()],
                move |x| {
                    let (wi, pdf, w) = m.sample_weighted(v3(x, 0), x[3], x[4]);
                    [o4((wi, pdf)), o3(w)].concat()
                },
            )
            .lane_ulps(256.0),
        );
        // World space: a shading point of normal n and view v (both world-space unit vectors).
        let n_v = || [v("n", [0.0, 0.6, 0.8]), v("v", WO)].concat();
        let sp = |x: &[T]| ShadingPoint::new(v3(x, 0), v3(x, 3));
        t.push(k(
            &format!("MetallicRoughness::eval_world({label})"),
            vec![n_v(), v("l", WI)],
            move |x| o3(m.eval_world(&sp(x), v3(x, 6))),
        ));
        t.push(k(
            &format!("MetallicRoughness::pdf_world({label})"),
            vec![n_v(), v("l", WI)],
            move |x| vec![m.pdf_world(&sp(x), v3(x, 6))],
        ));
        t.push(k(
            &format!("MetallicRoughness::sample_world({label})"),
            vec![n_v(), u()],
            move |x| o4(m.sample_world(&sp(x), x[6], x[7])),
        ));
        t.push(
            k(
                &format!("MetallicRoughness::sample_weighted_world({label})"),
                vec![n_v(), u()],
                move |x| {
                    let (l, pdf, w) = m.sample_weighted_world(&sp(x), x[6], x[7]);
                    [o4((l, pdf)), o3(w)].concat()
                },
            )
            .lane_ulps(256.0),
        );
    }
}

#[cfg(feature = "lights")]
fn lights_rows<T: Real>(t: &mut Vec<Kernel<T>>) {
    use brdf::lights::*;
    let s = T::splat;
    let pos = |n: &str, val: f64| p(n, val, &[-1.0, INF, -INF]);
    t.push(k(
        "lights::radiance",
        vec![pos("f", 0.3), pos("e_perp", 2.0), c("n_dot_l", NL)],
        |x| vec![radiance(x[0], x[1], x[2])],
    ));
    t.push(k(
        "lights::radiance_pi",
        vec![pos("f", 0.3), pos("c_light", 2.0), c("n_dot_l", NL)],
        |x| vec![radiance_pi(x[0], x[1], x[2])],
    ));
    t.push(
        k(
            "lights::radiance_pi_rgb",
            vec![
                rgb("f", [0.3, 0.2, 0.1], &[-1.0, INF, -INF]),
                rgb("c_light", [2.0, 1.0, 0.5], &[-1.0, INF, -INF]),
                c("n_dot_l", NL),
            ],
            |x| o3(radiance_pi_rgb(v3(x, 0), v3(x, 3), x[6])),
        )
        .dep("f.x", &[0])
        .dep("f.y", &[1])
        .dep("f.z", &[2])
        .dep("c_light.x", &[0])
        .dep("c_light.y", &[1])
        .dep("c_light.z", &[2]),
    );
    t.push(k(
        "lights::irradiance",
        vec![pos("e_perp", 2.0), c("n_dot_l", NL)],
        |x| vec![irradiance(x[0], x[1])],
    ));
    let d = || p("distance", 3.0, &[-1.0, -INF]);
    let d_min = || p("min_distance", 0.01, &[0.0, -1.0, INF]);
    let r = || p("radius", 10.0, &[-1.0, -INF]);
    t.push(k("lights::inverse_square", vec![d(), d_min()], |x| {
        vec![inverse_square(x[0], x[1])]
    }));
    t.push(k("lights::windowed", vec![d(), r()], |x| {
        vec![windowed(x[0], x[1])]
    }));
    t.push(k(
        "lights::windowed_inverse_square",
        vec![d(), r(), d_min()],
        |x| vec![windowed_inverse_square(x[0], x[1], x[2])],
    ));
    t.push(k(
        "lights::polynomial",
        vec![
            d(),
            p("constant", 1.0, &[0.0, -1.0, INF]),
            p("linear", 0.1, &[-1.0, INF]),
            p("quadratic", 0.01, &[-1.0, INF]),
        ],
        |x| vec![polynomial(x[0], x[1], x[2], x[3])],
    ));
    t.push(k(
        "lights::spot_cone",
        vec![
            c("cos_angle", 0.7),
            p("cos_outer", 0.5, &[0.95, 1.5, -1.5]),
            p("cos_inner", 0.9, &[0.3, 1.5]),
        ],
        |x| vec![spot_cone(x[0], x[1], x[2])],
    ));
    for (label, a) in [
        ("inverse_square", Attenuation::inverse_square(s(0.01))),
        ("windowed", Attenuation::windowed(s(10.0))),
        (
            "windowed_inverse_square",
            Attenuation::windowed_inverse_square(s(10.0), s(0.01)),
        ),
        (
            "polynomial",
            Attenuation::polynomial(s(1.0), s(0.1), s(0.01)),
        ),
    ] {
        let a = a.unwrap();
        t.push(k(
            &format!("Attenuation::eval({label})"),
            vec![c("distance", 3.0)],
            move |x| vec![a.eval(x[0])],
        ));
    }
    let cone = SpotCone::new(s(0.3), s(0.6)).unwrap();
    t.push(k("SpotCone::eval", vec![c("cos_angle", 0.9)], move |x| {
        vec![cone.eval(x[0])]
    }));
}

// ---------------------------------------------------------------------------------------
// The checks.

/// The valid points of a kernel: its valid inputs, and where it has a second direction
/// (`n_dot_l` or `wi`) the same with that direction below the horizon, so a NaN or a bad
/// parameter cannot hide behind the horizon's 0.
fn points(args: &[Arg]) -> Vec<Vec<f64>> {
    let above: Vec<f64> = args.iter().map(|a| a.valid).collect();
    let mut below = above.clone();
    let mut has = false;
    for (i, a) in args.iter().enumerate() {
        if a.name == "n_dot_l" || a.name == "wi.z" {
            below[i] = -a.valid;
            has = true;
        }
    }
    if has { vec![above, below] } else { vec![above] }
}

fn splat_all<T: Real>(x: &[f64]) -> Vec<T> {
    x.iter().map(|&v| T::splat(v)).collect()
}

/// One lane `bad_lane` set to `bad`, the others to `good`.
fn one_lane<T: Real>(good: f64, bad: f64, bad_lane: usize) -> T {
    T::from_fn(|i| T::Scalar::splat(if i == bad_lane { bad } else { good }))
}

fn lanes<T: Real>(x: T) -> Vec<f64> {
    (0..T::LANES).map(|i| x.lane(i).into()).collect()
}

/// Checks a, b, c, d of one kernel (index `ki` of the table) on lane type T; returns the
/// failures per check.
#[derive(Default, Clone)]
struct Outcome {
    fails: [Vec<String>; 5],
    counts: [usize; 5],
}

/// Inputs that rule 3 clamps (cosines and uniform samples): an infinity among them counts as
/// the end it lies beyond, so f(+-inf) = f(+-1) (a sample's -1 is clamped to 0 as -inf is).
/// Returns the finite inputs that -inf and +inf must equal, or None for an input that rule 5
/// sends to NaN (directions, colours, parameters, angles, distances, the DFG terms a and b).
fn clamped(kernel: &str, name: &str) -> Option<[f64; 2]> {
    if name.contains("_dot_")
        || name.starts_with("cos_")
        || matches!(name, "mu" | "u0" | "u1" | "u2")
    {
        return Some([-1.0, 1.0]);
    }
    // The tonemap operators document their own input clamp (`tonemap::sanitize`, the module's
    // "Bad input"): negative and -inf count as 0, above `MAX_INPUT` and +inf as `MAX_INPUT`, so
    // an operator's f(+inf) is its value at `MAX_INPUT`. Their inputs are the scene colour's
    // channels (`c`, `x`, `c.x`, ...).
    let tonemap = kernel.starts_with("tonemap::") || kernel.starts_with("Operator::apply");
    if tonemap && (name == "x" || name == "c" || name.starts_with("c.")) {
        return Some([-1.0, TONEMAP_MAX_INPUT]);
    }
    None
}

/// Kernels (and the inputs, by name prefix) that rule 5 exempts: they follow IEEE arithmetic
/// like the operators they are, so an infinite component gives what the arithmetic gives.
const INFINITY_EXEMPT: &[(&str, &str, &str)] = &[
    ("V3::dot", "", "vector arithmetic: the sum of products"),
    ("V3::cross", "", "vector arithmetic"),
    (
        "V3::length_squared",
        "",
        "vector arithmetic: +inf is the length of an infinite vector",
    ),
    ("V3::length", "", "vector arithmetic"),
    (
        "V3::normalize",
        "",
        "vector arithmetic: inf / inf is NaN, as IEEE has it",
    ),
    (
        "V3::normalize_or",
        "",
        "vector arithmetic: the fallback covers only a zero length",
    ),
    ("V3::mirror", "", "vector arithmetic: 2 (a.n) n - a"),
    (
        "V3::min_element",
        "",
        "a component comparison, like f32::min",
    ),
    (
        "V3::max_element",
        "",
        "a component comparison, like f32::max",
    ),
    (
        "Frame::to_local",
        "v.",
        "three dot products with the frame's axes (the normal is not exempt)",
    ),
    (
        "Frame::to_world",
        "v.",
        "a linear combination of the axes (the normal is not exempt)",
    ),
    (
        "ShadingPoint::local",
        "l.",
        "Frame::to_local of the point's frame (the normal is not exempt)",
    ),
    (
        "ShadingPoint::world",
        "w.",
        "Frame::to_world of the point's frame (the normal is not exempt)",
    ),
    (
        "color::mul",
        "",
        "a linear colour helper: one product per channel",
    ),
    (
        "color::luminance",
        "",
        "a linear colour helper: a weighted sum of the channels",
    ),
];

fn infinity_exempt(kernel: &str, name: &str) -> bool {
    INFINITY_EXEMPT
        .iter()
        .any(|(k, prefix, _)| *k == kernel && name.starts_with(prefix))
}

fn fmt_out(v: &[f64]) -> String {
    let s: Vec<String> = v.iter().map(|x| format!("{x:.4e}")).collect();
    format!("[{}]", s.join(", "))
}

fn check<T: Real>(kern: &Kernel<T>, scalar: &Kernel<T::Scalar>, ty: &str) -> Outcome {
    let mut o = Outcome::default();
    let eps: f64 = T::EPSILON.lane(0).into();
    let pts = points(&kern.args);
    let n_pts = pts.len();
    for (pi, pt) in pts.into_iter().enumerate() {
        let at = match (n_pts, pi) {
            (1, _) => "",
            (_, 0) => " (above the horizon)",
            _ => " (below the horizon)",
        };
        let x = splat_all::<T>(&pt);
        let out = (kern.f)(&x);
        let n_out = out.len();
        // (a) finite.
        o.counts[0] += 1;
        let flat: Vec<f64> = out.iter().flat_map(|&y| lanes(y)).collect();
        if !flat.iter().all(|y| y.is_finite()) {
            o.fails[0].push(format!("{ty} at {pt:?} gave {}", fmt_out(&flat)));
        }
        // (b) NaN in each input, (c) each invalid parameter value: every lane.
        for (j, a) in kern.args.iter().enumerate() {
            let deps = kern.outputs_of(&a.name, n_out);
            let probe = |bad: f64, check: usize, o: &mut Outcome| {
                let mut y = x.clone();
                y[j] = T::splat(bad);
                let got = (kern.f)(&y);
                o.counts[check] += 1;
                let flat: Vec<f64> = got.iter().flat_map(|&v| lanes(v)).collect();
                if !deps
                    .iter()
                    .all(|&d| lanes(got[d]).iter().all(|v| v.is_nan()))
                {
                    let what = if check == 1 {
                        "NaN".to_string()
                    } else {
                        format!("{bad}")
                    };
                    o.fails[check].push(format!(
                        "{ty} {} = {what}{at} gave {}",
                        a.name,
                        fmt_out(&flat)
                    ));
                }
            };
            probe(NAN, 1, &mut o);
            for &bad in &a.invalid {
                probe(bad, 2, &mut o);
            }
            // (e) infinities: a clamped input at +-inf equals it at +-1 bit for bit; any other
            // input at +-inf gives NaN where a NaN would.
            for (end, sign) in [1.0, -1.0].into_iter().enumerate() {
                if infinity_exempt(&kern.name, &a.name) {
                    continue;
                }
                // A parameter that rejects out-of-range values (a spot cone's cos_outer) is not
                // clamped, whatever its name: its infinities give NaN like its other bad values.
                let ends = if a.invalid.is_empty() {
                    clamped(&kern.name, &a.name)
                } else {
                    None
                };
                if let Some(ends) = ends {
                    let at_inf = |v: f64| {
                        let mut y = x.clone();
                        y[j] = T::splat(v);
                        (kern.f)(&y)
                            .iter()
                            .flat_map(|&v| lanes(v))
                            .collect::<Vec<f64>>()
                    };
                    let finite = ends[1 - end];
                    let (got, want) = (at_inf(sign * INF), at_inf(finite));
                    o.counts[4] += 1;
                    let same = got
                        .iter()
                        .zip(&want)
                        .all(|(g, w)| g.to_bits() == w.to_bits() || (g.is_nan() && w.is_nan()));
                    if !same {
                        o.fails[4].push(format!(
                            "{ty} {} = {}{at} gave {}, at {} {}",
                            a.name,
                            sign * INF,
                            fmt_out(&got),
                            finite,
                            fmt_out(&want)
                        ));
                    }
                } else {
                    probe(sign * INF, 4, &mut o);
                }
            }
        }
        // (d) lanes: one bad lane leaves the others as they were; those equal the scalars.
        if T::LANES > 1 {
            let sx: Vec<T::Scalar> = pt.iter().map(|&v| T::Scalar::splat(v)).collect();
            let sout = (scalar.f)(&sx);
            for (oi, (&lane_v, &sc)) in out.iter().zip(&sout).enumerate() {
                let sc: f64 = sc.into();
                for (l, y) in lanes(lane_v).into_iter().enumerate() {
                    let ok = y == sc
                        || (y.is_nan() && sc.is_nan())
                        || (y - sc).abs() <= kern.lane_ulps * eps * y.abs().max(sc.abs());
                    o.counts[3] += 1;
                    if !ok {
                        o.fails[3].push(format!(
                            "{ty} output {oi} lane {l} = {y:e}, scalar {sc:e} (at {pt:?})"
                        ));
                    }
                }
            }
            for (j, a) in kern.args.iter().enumerate() {
                let bads: Vec<f64> = core::iter::once(NAN)
                    .chain(a.invalid.iter().copied())
                    .collect();
                for bad in bads {
                    for bl in 0..T::LANES {
                        let mut y = x.clone();
                        y[j] = one_lane::<T>(pt[j], bad, bl);
                        let got = (kern.f)(&y);
                        o.counts[3] += 1;
                        let mut bad_msg = None;
                        for (oi, (&g, &ref_v)) in got.iter().zip(&out).enumerate() {
                            for l in (0..T::LANES).filter(|&l| l != bl) {
                                let (gv, rv): (f64, f64) = (g.lane(l).into(), ref_v.lane(l).into());
                                if gv.to_bits() != rv.to_bits() && !(gv.is_nan() && rv.is_nan()) {
                                    bad_msg = Some(format!(
                                        "{ty} {} = {bad} in lane {bl}: output {oi} lane {l} {rv:e} -> {gv:e}",
                                        a.name
                                    ));
                                }
                            }
                        }
                        if let Some(m) = bad_msg {
                            o.fails[3].push(m);
                        }
                    }
                }
            }
        }
    }
    o
}

fn run<T: Real>(ty: &str) -> Vec<(String, usize, Outcome)> {
    let lane_table = table::<T>();
    let scalar_table = table::<T::Scalar>();
    lane_table
        .iter()
        .zip(&scalar_table)
        .map(|(kl, ks)| (kl.name.clone(), kl.args.len(), check(kl, ks, ty)))
        .collect()
}

#[test]
fn every_kernel_keeps_the_bad_input_rule_on_every_lane_type() {
    let results = [
        run::<f32>("f32"),
        run::<f64>("f64"),
        run::<f32x8>("f32x8"),
        run::<f64x4>("f64x4"),
    ];
    let names = ["a finite", "b NaN", "c invalid", "d lanes", "e infinity"];
    println!(
        "{:<48} {:>4}  {:>12} {:>12} {:>12} {:>12} {:>12}",
        "kernel", "args", names[0], names[1], names[2], names[3], names[4]
    );
    let mut failures = Vec::new();
    let mut totals = [0usize; 5];
    let mut failed_kernels = [0usize; 5];
    for (i, (name, n_args, _)) in results[0].iter().enumerate() {
        let mut cells = Vec::new();
        for chk in 0..5 {
            let (mut n, mut f) = (0, 0);
            for r in &results {
                n += r[i].2.counts[chk];
                f += r[i].2.fails[chk].len();
                for m in &r[i].2.fails[chk] {
                    failures.push(format!("{name} ({}): {m}", names[chk]));
                }
            }
            totals[chk] += n;
            if f > 0 {
                failed_kernels[chk] += 1;
            }
            cells.push(if n == 0 {
                "-".to_string()
            } else if f == 0 {
                format!("ok {n}")
            } else {
                format!("FAIL {f}/{n}")
            });
        }
        println!(
            "{name:<48} {n_args:>4}  {:>12} {:>12} {:>12} {:>12} {:>12}",
            cells[0], cells[1], cells[2], cells[3], cells[4]
        );
    }
    println!(
        "{} kernels; probes per check {:?}; kernels failing per check {:?}",
        results[0].len(),
        totals,
        failed_kernels
    );
    for f in &failures {
        println!("FAIL {f}");
    }
    assert!(
        failures.is_empty(),
        "{} probes break the bad-input rule (run with --nocapture for the list)",
        failures.len()
    );
}

// ---------------------------------------------------------------------------------------
// Every `pub fn` in src/ is in the table or named below as a non-kernel.

/// Public functions that are not kernels of float or `V3` input, with the reason.
const NOT_KERNELS: &[(&str, &str)] = &[
    (
        "batch::run",
        "applies a kernel over slices (the kernel keeps the rule)",
    ),
    (
        "batch::run_f32",
        "applies a kernel over slices (the kernel keeps the rule)",
    ),
    (
        "batch::run_f64",
        "applies a kernel over slices (the kernel keeps the rule)",
    ),
    (
        "batch::par_run",
        "applies a kernel over slices on all cores (the kernel keeps the rule)",
    ),
    (
        "batch::par_run_f32",
        "applies a kernel over slices on all cores (the kernel keeps the rule)",
    ),
    (
        "batch::par_run_f64",
        "applies a kernel over slices on all cores (the kernel keeps the rule)",
    ),
    ("ibl::dfg::dfg", "f64 quadrature of one table entry"),
    ("ibl::dfg::table", "table builder into a caller's buffer"),
    (
        "ibl::dfg::table_filament",
        "table builder into a caller's buffer",
    ),
    (
        "ibl::dfg::lookup",
        "table lookup (its inputs are clamped texture coordinates)",
    ),
    (
        "ibl::energy::e_ggx_estimate",
        "f64 quadrature of one table entry",
    ),
    (
        "ibl::energy::e_avg_ggx_estimate",
        "f64 quadrature of one table entry",
    ),
    (
        "ibl::energy::e_table",
        "table builder into a caller's buffer",
    ),
    (
        "ibl::energy::e_avg_table",
        "table builder into a caller's buffer",
    ),
    ("ibl::energy::fresnel_avg_conductor", "f64 quadrature"),
    (
        "ibl::prefilter::hammersley",
        "f64 point set (indices, not values)",
    ),
    (
        "ibl::prefilter::samples",
        "iterator over sample (integer indices)",
    ),
    (
        "ibl::prefilter::fill",
        "fills a caller's buffer through sample",
    ),
    ("ibl::irradiance::gauss_legendre", "f64 quadrature nodes"),
    ("ibl::irradiance::irradiance", "f64 quadrature of a closure"),
    (
        "ibl::irradiance::cube_texel_solid_angle",
        "f64 of integer texel indices",
    ),
    ("ibl::irradiance::project", "f64 quadrature of a closure"),
    ("Sh9::zero", "constructor"),
    ("Sh9::splat_from", "constructor"),
    ("Sh9::add", "accumulator of a renderer's own samples"),
    ("Sh9::cosine_convolved", "coefficient scaling (constants)"),
    ("Sh9::irradiance_matrix", "coefficient rearrangement"),
    ("error::require", "validation helper of the constructors"),
    ("V3::splat", "constructor"),
    ("V3::broadcast", "constructor: one vector in every lane"),
    ("V3::to_array", "accessor"),
    ("V3::map", "applies the caller's function per component"),
    (
        "V3::zip_map",
        "applies the caller's function per component pair",
    ),
    (
        "V3::min",
        "component-wise Real::min: its NaN rule, per component",
    ),
    (
        "V3::max",
        "component-wise Real::max: its NaN rule, per component",
    ),
    (
        "V3::abs",
        "component-wise |x|: NaN stays in its own component",
    ),
    ("V3::unit_z", "constructor"),
    ("V3::select", "lane select, no arithmetic"),
    ("V3::lane", "lane accessor"),
    ("V3::from_lanes", "transpose, no arithmetic"),
    ("V3::to_lanes", "transpose, no arithmetic"),
    (
        "frame::same_hemisphere",
        "a mask (NaN compares false by IEEE 754)",
    ),
    ("Ggx::new", "validating constructor (ParamError)"),
    ("Ggx::isotropic", "validating constructor"),
    ("Ggx::alpha_x", "getter"),
    ("Ggx::alpha_y", "getter"),
    ("Beckmann::new", "validating constructor"),
    ("Beckmann::isotropic", "validating constructor"),
    ("Beckmann::alpha_x", "getter"),
    ("Beckmann::alpha_y", "getter"),
    ("Exposure::from_ev100", "validating constructor"),
    ("Exposure::from_camera", "validating constructor"),
    ("HableParams::new", "validating constructor"),
    ("LottesParams::default_curve", "constructor"),
    ("LottesParams::new", "validating constructor"),
    ("AgxLook::new", "validating constructor"),
    ("AgxLook::slope", "getter"),
    ("AgxLook::power", "getter"),
    ("AgxLook::saturation", "getter"),
    ("Exposure::new", "validating constructor"),
    ("Exposure::value", "getter"),
    ("Operator::apply_vec3", "glam wrapper of Operator::apply"),
    ("Operator::apply_vec3a", "glam wrapper of Operator::apply"),
    ("Operator::all", "list of operators"),
    ("Attenuation::inverse_square", "validating constructor"),
    ("Attenuation::windowed", "validating constructor"),
    (
        "Attenuation::windowed_inverse_square",
        "validating constructor",
    ),
    ("Attenuation::polynomial", "validating constructor"),
    ("SpotCone::new", "validating constructor"),
    ("SpotCone::cos_outer", "getter"),
    ("SpotCone::cos_inner", "getter"),
    ("MetallicRoughness::new", "validating constructor"),
    ("MetallicRoughness::with_ior", "validating constructor"),
    (
        "MetallicRoughness::with_dielectric_f0",
        "validating constructor",
    ),
    (
        "MetallicRoughness::with_reflectance",
        "validating constructor",
    ),
    ("MetallicRoughness::with_specular", "validating constructor"),
    ("MetallicRoughness::with_coupling", "constructor"),
    ("MetallicRoughness::base_color", "getter"),
    ("MetallicRoughness::metallic", "getter"),
    ("MetallicRoughness::roughness", "getter"),
    ("MetallicRoughness::alpha", "getter"),
    (
        "MetallicRoughness::dielectric_f0",
        "getter (validated parameters only)",
    ),
    ("MetallicRoughness::dielectric_f90", "getter"),
    ("MetallicRoughness::coupling", "getter"),
    ("PhongDiffuseSpecular::new", "validating constructor"),
    ("PhongDiffuseSpecular::kd", "getter"),
    ("PhongDiffuseSpecular::ks", "getter"),
    ("PhongDiffuseSpecular::exponent", "getter"),
    (
        "layers::sheen::albedo_estimate",
        "f64 cubature of one table entry",
    ),
    (
        "layers::sheen::albedo_table",
        "table builder into a caller's buffer",
    ),
    ("Ior::value", "getter"),
    ("Specular::factor", "getter"),
    ("Specular::color", "getter"),
    (
        "Specular::dielectric_f0",
        "validated form of layers::specular::dielectric_f0 (a row)",
    ),
    ("Specular::dielectric_f90", "getter"),
    ("Layered::from_base", "constructor"),
    ("Layered::with_sheen", "validating constructor"),
    ("Layered::with_clearcoat", "validating constructor"),
    ("Layered::with_clearcoat_normal", "validating constructor"),
    ("Layered::with_anisotropy", "validating constructor"),
    ("Layered::with_transmission", "validating constructor"),
    ("Layered::with_volume", "constructor"),
    ("Layered::with_compensation", "constructor"),
    ("Layered::with_iridescence", "validating constructor"),
    (
        "Layered::with_clearcoat_normal_world",
        "validating constructor",
    ),
    ("Transmission::factor", "getter"),
    ("Volume::thickness", "getter"),
    ("ThinFilm::thickness", "getter"),
    ("ThinFilm::ior", "getter"),
    (
        "Volume::attenuation_coefficient",
        "getter of a derived parameter (validated parameters only)",
    ),
    (
        "Layered::at_view",
        "prepares the material at a view; its Prepared::eval rows check the view",
    ),
];

/// Methods every parameter type of these modules has: constructor and getters.
const NOT_KERNEL_METHODS: &[&str] = &[
    "new",
    // microfacet::Alpha's constructor: microfacet::alpha_from_perceptual, which is a row.
    "from_perceptual",
    "from_frame",
    "frame",
    "wo",
    "rho",
    "sigma",
    "roughness",
    "rs",
    "f0",
    "ks",
    "exponent",
];

/// Files scanned, with the module path their free functions have.
const SOURCES: &[(&str, &str)] = &[
    ("batch", include_str!("../../src/batch.rs")),
    ("ibl::dfg", include_str!("../../src/ibl/dfg.rs")),
    ("ibl::energy", include_str!("../../src/ibl/energy.rs")),
    (
        "ibl::irradiance",
        include_str!("../../src/ibl/irradiance.rs"),
    ),
    ("ibl::prefilter", include_str!("../../src/ibl/prefilter.rs")),
    ("beckmann", include_str!("../../src/beckmann.rs")),
    ("color", include_str!("../../src/color.rs")),
    ("cook_torrance", include_str!("../../src/cook_torrance.rs")),
    ("diffuse", include_str!("../../src/diffuse/mod.rs")),
    ("diffuse", include_str!("../../src/diffuse/burley.rs")),
    ("diffuse", include_str!("../../src/diffuse/coupling.rs")),
    ("diffuse", include_str!("../../src/diffuse/eon.rs")),
    ("diffuse", include_str!("../../src/diffuse/oren_nayar.rs")),
    ("error", include_str!("../../src/error.rs")),
    ("frame", include_str!("../../src/frame.rs")),
    ("fresnel", include_str!("../../src/fresnel.rs")),
    ("ggx", include_str!("../../src/ggx.rs")),
    ("lights", include_str!("../../src/lights.rs")),
    ("material", include_str!("../../src/material.rs")),
    ("engine", include_str!("../../src/engine.rs")),
    ("microfacet", include_str!("../../src/microfacet.rs")),
    ("phong", include_str!("../../src/phong.rs")),
    ("sampling", include_str!("../../src/sampling.rs")),
    (
        "rough_dielectric",
        include_str!("../../src/rough_dielectric.rs"),
    ),
    ("transmission", include_str!("../../src/transmission.rs")),
    ("iridescence", include_str!("../../src/iridescence.rs")),
    ("shading", include_str!("../../src/shading.rs")),
    ("tonemap", include_str!("../../src/tonemap/mod.rs")),
    ("tonemap", include_str!("../../src/tonemap/curves.rs")),
    ("tonemap", include_str!("../../src/tonemap/agx.rs")),
    ("vec3", include_str!("../../src/vec3.rs")),
    ("layers::sheen", include_str!("../../src/layers/sheen.rs")),
    (
        "layers::clearcoat",
        include_str!("../../src/layers/clearcoat.rs"),
    ),
    (
        "layers::specular",
        include_str!("../../src/layers/specular.rs"),
    ),
    (
        "layers::anisotropy",
        include_str!("../../src/layers/anisotropy.rs"),
    ),
];

/// Every public function of the sources, as `module::name` (free) or `Type::name` (method;
/// `Microfacet::name` for the trait's methods, the Phong macro's types expanded).
fn public_functions() -> Vec<String> {
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == '$')
            .collect()
    };
    let mut out = Vec::new();
    for (module, src) in SOURCES {
        // The types the Phong macro defines: the identifier line after each `phong_type!(`.
        let mut macro_types = Vec::new();
        let lines: Vec<&str> = src.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            if l.trim_start().starts_with("phong_type!(")
                && let Some(ty) = lines[i + 1..]
                    .iter()
                    .map(|l| l.trim())
                    .find(|l| !l.starts_with("///") && l.ends_with(','))
            {
                macro_types.push(ty.trim_end_matches(',').to_string());
            }
        }
        let mut self_ty = String::new();
        let mut in_trait = None;
        for l in &lines {
            let tl = l.trim_start();
            let indented = tl.len() != l.len();
            if let Some(rest) = l.strip_prefix("pub trait ") {
                in_trait = Some(ident(rest));
                continue;
            }
            if *l == "}" {
                in_trait = None;
            }
            if let Some(rest) = tl.strip_prefix("impl") {
                // `impl<...> Type<..> {` or `impl<...> Trait<..> for Type<..> {`.
                let mut rest = rest.trim_start();
                if rest.starts_with('<') {
                    let mut depth = 0;
                    let end = rest
                        .char_indices()
                        .find(|&(_, ch)| {
                            depth += match ch {
                                '<' => 1,
                                '>' => -1,
                                _ => 0,
                            };
                            depth == 0
                        })
                        .map_or(0, |(i, _)| i + 1);
                    rest = rest[end..].trim_start();
                }
                self_ty = match rest.find(" for ") {
                    Some(f) => format!("!{}", ident(&rest[f + 5..])),
                    None => ident(rest),
                };
                continue;
            }
            if let Some(tr) = &in_trait {
                if let Some(rest) = tl.strip_prefix("fn ") {
                    out.push(format!("{tr}::{}", ident(rest)));
                }
                continue;
            }
            let Some(rest) = tl.strip_prefix("pub fn ") else {
                continue;
            };
            let name = ident(rest);
            if !indented {
                out.push(format!("{module}::{name}"));
            } else if self_ty == "$name" {
                for ty in &macro_types {
                    out.push(format!("{ty}::{name}"));
                }
            } else if !self_ty.starts_with('!') {
                out.push(format!("{self_ty}::{name}"));
            }
        }
    }
    out
}

#[cfg(all(
    feature = "fresnel",
    feature = "ggx",
    feature = "beckmann",
    feature = "cook-torrance",
    feature = "sampling",
    feature = "tonemap",
    feature = "diffuse",
    feature = "phong",
    feature = "material",
    feature = "lights",
    feature = "engine"
))]
#[test]
fn every_public_function_is_in_the_table_or_named_as_not_a_kernel() {
    let listed: Vec<String> = table::<f64>()
        .iter()
        .map(|k| k.name.split('(').next().unwrap_or("").to_string())
        .collect();
    let found = public_functions();
    let mut missing = Vec::new();
    for f in &found {
        let (ty, method) = f.rsplit_once("::").unwrap_or(("", f));
        let covered = listed.contains(f)
            || NOT_KERNELS.iter().any(|(n, _)| n == f)
            || (ty.chars().next().is_some_and(char::is_uppercase)
                && NOT_KERNEL_METHODS.contains(&method))
            || (ty == "Microfacet"
                && listed.contains(&format!("Ggx::{method}"))
                && listed.contains(&format!("Beckmann::{method}")));
        if !covered {
            missing.push(f.clone());
        }
    }
    println!(
        "{} public functions in src/ (less integrate.rs and real.rs); table rows {}; listed as not kernels {}",
        found.len(),
        listed.len(),
        NOT_KERNELS.len()
    );
    assert!(
        found.len() > 150,
        "the scan found only {} functions: is it still reading the sources?",
        found.len()
    );
    assert!(
        missing.is_empty(),
        "public functions neither in the table nor exempt: {missing:?}"
    );
}

#[cfg(feature = "tonemap")]
#[test]
fn tonemap_max_input_matches() {
    assert_eq!(TONEMAP_MAX_INPUT, brdf::tonemap::MAX_INPUT);
}

// ---------------------------------------------------------------------------------------
// Degenerate directions: a zero-length wo or wi is finite input, so it gives finite output
// (never NaN), and every sampler and pdf documents its pdf there: 0.

/// Kernels that return a pdf, and which output holds it.
fn pdf_output(name: &str) -> Option<usize> {
    let sampler = name.contains("sample")
        || name.contains("vndf")
        || name.contains("_reflection")
        || name.contains("d_cos(");
    if name.contains("pdf") {
        Some(0)
    } else if sampler && !name.contains("sample_from") && !name.contains("prefilter::sample") {
        Some(3)
    } else {
        None
    }
}

fn zero_direction_sweep<T: Real>(ty: &str, failures: &mut Vec<String>, probes: &mut usize) {
    for kern in table::<T>() {
        for dir in ["wo", "wi", "dir"] {
            let idx: Vec<usize> = (0..kern.args.len())
                .filter(|&i| kern.args[i].name.starts_with(&format!("{dir}.")))
                .collect();
            if idx.len() != 3 {
                continue;
            }
            let mut x: Vec<f64> = kern.args.iter().map(|a| a.valid).collect();
            for &i in &idx {
                x[i] = 0.0;
            }
            let out = (kern.f)(&splat_all::<T>(&x));
            *probes += 1;
            let flat: Vec<f64> = out.iter().flat_map(|&y| lanes(y)).collect();
            let pdf_ok =
                pdf_output(&kern.name).is_none_or(|p| lanes(out[p]).iter().all(|&v| v == 0.0));
            if !flat.iter().all(|y| y.is_finite()) || !pdf_ok {
                failures.push(format!(
                    "{} {ty} {dir} = (0, 0, 0) gave {}",
                    kern.name,
                    fmt_out(&flat)
                ));
            }
        }
    }
}

#[test]
fn a_zero_length_direction_gives_finite_output_and_a_zero_pdf() {
    let (mut failures, mut probes) = (Vec::new(), 0);
    zero_direction_sweep::<f32>("f32", &mut failures, &mut probes);
    zero_direction_sweep::<f64>("f64", &mut failures, &mut probes);
    zero_direction_sweep::<f32x8>("f32x8", &mut failures, &mut probes);
    zero_direction_sweep::<f64x4>("f64x4", &mut failures, &mut probes);
    println!("{probes} zero-direction probes");
    for f in &failures {
        println!("FAIL {f}");
    }
    assert!(
        failures.is_empty(),
        "{} of {probes} zero-direction probes break the rule",
        failures.len()
    );
}

/// The microfacet verbs of one distribution at the zero vector: the horizon's values.
#[cfg(all(feature = "ggx", feature = "beckmann"))]
fn zero_vector_is_the_horizon_for<T: Real, M: brdf::microfacet::Microfacet<T>>(dist: &M) {
    let zero = V3::splat(T::ZERO);
    let horizon = V3::new(T::ONE, T::ZERO, T::ZERO);
    let up = V3::new(T::ZERO, T::splat(0.6), T::splat(0.8));
    let same = |a: T, b: T, what: &str| {
        for i in 0..T::LANES {
            let (a, b): (f64, f64) = (a.lane(i).into(), b.lane(i).into());
            assert!(
                a.is_finite() && a.to_bits() == b.to_bits(),
                "{what}: {a} vs {b}"
            );
        }
    };
    same(dist.g1(zero), dist.g1(horizon), "g1");
    same(dist.lambda(zero), dist.lambda(horizon), "lambda");
    same(
        dist.cos_lambda(zero),
        dist.cos_lambda(horizon),
        "cos_lambda",
    );
    same(
        dist.g2_correlated(zero, up),
        dist.g2_correlated(horizon, up),
        "g2_correlated",
    );
    same(
        dist.g2_separable(zero, up),
        dist.g2_separable(horizon, up),
        "g2_separable",
    );
    same(
        dist.g2_correlated(up, zero),
        dist.g2_correlated(up, horizon),
        "g2_correlated wi",
    );
    same(
        dist.v_correlated(zero, up),
        dist.v_correlated(horizon, up),
        "v_correlated",
    );
    same(
        dist.v_correlated(up, zero),
        dist.v_correlated(up, horizon),
        "v_correlated wi",
    );
    same(dist.d_visible(zero, up), T::ZERO, "d_visible");
}

#[cfg(all(feature = "ggx", feature = "beckmann"))]
#[test]
fn a_zero_vector_takes_the_horizon_values_of_every_microfacet_verb() {
    fn all<T: Real>() {
        let a = T::splat(0.3);
        zero_vector_is_the_horizon_for(&brdf::ggx::Ggx::new(a, a).unwrap());
        zero_vector_is_the_horizon_for(&brdf::beckmann::Beckmann::new(a, a).unwrap());
    }
    all::<f32>();
    all::<f64>();
    all::<f32x8>();
    all::<f64x4>();
}
