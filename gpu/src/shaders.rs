//! The WGSL twins: which kernel of the reference table each function stands for, their
//! signatures held to the table's rows, the compute shader that runs one, and its
//! translations.
//!
//! One table drives both sides: a WGSL function `ggx_d` is the twin of the table's kernel
//! `ggx::d` (the path with `::` written `_`), its parameters must be the kernel's argument
//! names in the kernel's order, each `f32` (`u32` for an enumerated choice), and its result
//! `f32` for one output, `vecN<f32>` for N outputs up to four, `array<f32, N>` for more.
//! Functions prefixed `brdf_` are helpers.

use brdf_ref::{KERNELS, Kernel};
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use naga::{ArraySize, Module, ScalarKind, TypeInner};

/// The WGSL name of a kernel's twin: its path with `::` written `_`.
#[must_use]
pub fn wgsl_name(path: &str) -> String {
    path.replace("::", "_")
}

/// Argument names of the table that WGSL reserves (W3C WGSL, "Reserved Words"): their twins'
/// parameters take a trailing underscore.
pub const WGSL_RESERVED: &[&str] = &["operator", "smooth", "filter", "sample", "module"];

/// The WGSL parameter name of a kernel's argument: the name itself, or with a trailing
/// underscore where WGSL reserves it (`operator_`).
#[must_use]
pub fn wgsl_param(name: &str) -> String {
    if WGSL_RESERVED.contains(&name) {
        format!("{name}_")
    } else {
        name.to_string()
    }
}

/// One family's WGSL, parsed and validated after `COMMON` and the families it needs.
pub struct Family {
    /// The family's name (`ggx`, `fresnel`, ...).
    pub name: &'static str,
    /// `COMMON`, the families it needs, then the family's own source.
    pub source: String,
    /// The parsed module.
    pub module: Module,
}

/// Parses and validates `source`.
///
/// # Errors
/// naga's parse or validation error, rendered against the source.
pub fn parse(source: &str, what: &str) -> Result<(Module, ModuleInfo), String> {
    let module = naga::front::wgsl::parse_str(source)
        .map_err(|e| format!("{what}: {}", e.emit_to_string(source)))?;
    let info = Validator::new(ValidationFlags::all(), Capabilities::empty())
        .validate(&module)
        .map_err(|e| format!("{what}: {}", e.emit_to_string(source)))?;
    Ok((module, info))
}

/// Every family of `brdf::wgsl`, each parsed after `COMMON`.
///
/// # Panics
/// If a family does not parse or validate (the tests report which and why).
#[must_use]
pub fn families() -> Vec<Family> {
    brdf::wgsl::FAMILIES
        .iter()
        .map(|fam| {
            let name = fam.name;
            let mut source = brdf::wgsl::COMMON.to_string();
            for need in fam.needs {
                let dep = brdf::wgsl::FAMILIES
                    .iter()
                    .find(|f| f.name == *need)
                    .unwrap_or_else(|| panic!("{name} needs an unknown family {need}"));
                source += dep.source;
            }
            source += fam.source;
            let (module, _) = parse(&source, name).unwrap_or_else(|e| panic!("{e}"));
            Family {
                name,
                source,
                module,
            }
        })
        .collect()
}

/// A kernel of the table with its WGSL twin.
pub struct Twin {
    /// The table's row.
    pub kernel: &'static Kernel,
    /// The WGSL function's name.
    pub name: String,
    /// Index into [`families`] of the family defining it.
    pub family: usize,
}

/// The kernels of the table that have a twin, and those that do not (by path).
#[must_use]
pub fn twins(families: &[Family]) -> (Vec<Twin>, Vec<&'static str>) {
    let mut with = Vec::new();
    let mut without = Vec::new();
    for k in KERNELS {
        let name = wgsl_name(k.path);
        let family = families.iter().position(|f| {
            f.module
                .functions
                .iter()
                .any(|(_, g)| g.name.as_deref() == Some(&*name))
        });
        match family {
            Some(family) => with.push(Twin {
                kernel: k,
                name,
                family,
            }),
            None => without.push(k.path),
        }
    }
    (with, without)
}

/// Every difference between the WGSL functions of `families` and the table's rows: a
/// function without a kernel, a parameter list or result that is not the kernel's.
#[must_use]
pub fn signature_mismatches(families: &[Family]) -> Vec<String> {
    let mut out = Vec::new();
    for fam in families {
        let m = &fam.module;
        for (_, f) in m.functions.iter() {
            let name = f.name.clone().unwrap_or_default();
            if name.starts_with("brdf_") {
                continue;
            }
            let Some(k) = KERNELS.iter().find(|k| wgsl_name(k.path) == name) else {
                out.push(format!(
                    "{}: WGSL function {name} has no kernel in brdf_ref::table::KERNELS",
                    fam.name
                ));
                continue;
            };
            let params: Vec<&str> = f
                .arguments
                .iter()
                .map(|a| a.name.as_deref().unwrap_or("?"))
                .collect();
            let want: Vec<String> = k.args.iter().map(|a| wgsl_param(a.name)).collect();
            if params != want {
                out.push(format!(
                    "{name}: parameters ({}) but {} takes ({})",
                    params.join(", "),
                    k.path,
                    want.join(", ")
                ));
            }
            for (a, arg) in f.arguments.iter().zip(k.args) {
                let t = &m.types[a.ty].inner;
                // An enumerated parameter (a choice among integers) is u32, any other f32.
                let ok = if arg.domain.integer {
                    matches!(t, TypeInner::Scalar(s) if s.kind == ScalarKind::Uint && s.width == 4)
                } else {
                    is_f32(t)
                };
                if !ok {
                    out.push(format!(
                        "{name}: parameter {:?} is not {}",
                        a.name.as_deref(),
                        if arg.domain.integer { "u32" } else { "f32" }
                    ));
                }
            }
            let n = match f.result.as_ref().map(|r| &m.types[r.ty].inner) {
                Some(t) if is_f32(t) => 1,
                Some(TypeInner::Vector { size, scalar })
                    if scalar.kind == ScalarKind::Float && scalar.width == 4 =>
                {
                    *size as usize
                }
                // More than four outputs (a sampler's direction, pdf and weights; the nine
                // spherical harmonics) are an array<f32, N>: a WGSL vector holds four.
                Some(TypeInner::Array {
                    base,
                    size: ArraySize::Constant(n),
                    ..
                }) if is_f32(&m.types[*base].inner) && n.get() > 4 => n.get() as usize,
                other => {
                    out.push(format!(
                        "{name}: result {other:?} is neither f32, vecN<f32> nor array<f32, N> \
                         (N > 4)"
                    ));
                    continue;
                }
            };
            if n != k.outputs.len() {
                out.push(format!(
                    "{name}: {n} results but {} has {} outputs",
                    k.path,
                    k.outputs.len()
                ));
            }
        }
    }
    out
}

fn is_f32(t: &TypeInner) -> bool {
    matches!(t, TypeInner::Scalar(s) if s.kind == ScalarKind::Float && s.width == 4)
}

/// Threads per workgroup of the kernels' compute shaders.
pub const WORKGROUP: u32 = 64;

/// A compute shader running `twin` on every row of `brdf_in` (the arguments, row after row)
/// into `brdf_out` (the outputs, row after row): the family's source and an entry point
/// `main`.
#[must_use]
pub fn compute_shader(twin: &Twin, families: &[Family]) -> String {
    let k = twin.kernel;
    let (na, no) = (k.args.len(), k.outputs.len());
    let args: Vec<String> = k
        .args
        .iter()
        .enumerate()
        .map(|(j, a)| {
            let x = format!("brdf_in[i * {na}u + {j}u]");
            if a.domain.integer {
                format!("u32({x})")
            } else {
                x
            }
        })
        .collect();
    let stores: String = if no == 1 {
        "    brdf_out[i] = r;\n".to_string()
    } else {
        (0..no)
            .map(|j| format!("    brdf_out[i * {no}u + {j}u] = r[{j}];\n"))
            .collect()
    };
    format!(
        "{src}
@group(0) @binding(0) var<storage, read> brdf_in: array<f32>;
@group(0) @binding(1) var<storage, read_write> brdf_out: array<f32>;

@compute @workgroup_size({WORKGROUP})
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {{
    let i = gid.x;
    if i >= arrayLength(&brdf_out) / {no}u {{
        return;
    }}
    let r = {name}({args});
{stores}}}
",
        src = families[twin.family].source,
        name = twin.name,
        args = args.join(", "),
    )
}

/// The translations of one validated compute shader.
pub struct Translations {
    /// SPIR-V words.
    pub spirv: Vec<u32>,
    /// GLSL 4.50 (compute).
    pub glsl: String,
    /// HLSL (shader model 5.1).
    pub hlsl: String,
    /// Metal Shading Language.
    pub msl: String,
}

/// Translates a module with the compute entry point `main` to SPIR-V, GLSL, HLSL and MSL.
///
/// # Errors
/// The first back end's error.
pub fn translate(module: &Module, info: &ModuleInfo) -> Result<Translations, String> {
    use naga::back::{glsl, hlsl, msl, spv};
    let stage = naga::ShaderStage::Compute;
    let spirv = spv::write_vec(module, info, &spv::Options::default(), None)
        .map_err(|e| format!("SPIR-V: {e}"))?;
    let mut glsl_src = String::new();
    let options = glsl::Options {
        version: glsl::Version::Desktop(450),
        ..glsl::Options::default()
    };
    let pipeline = glsl::PipelineOptions {
        shader_stage: stage,
        entry_point: "main".into(),
        multiview: None,
    };
    glsl::Writer::new(
        &mut glsl_src,
        module,
        info,
        &options,
        &pipeline,
        naga::proc::BoundsCheckPolicies::default(),
    )
    .and_then(|mut w| w.write())
    .map_err(|e| format!("GLSL: {e}"))?;
    let mut hlsl_src = String::new();
    let hlsl_pipeline = hlsl::PipelineOptions {
        entry_point: Some((stage, "main".into())),
    };
    hlsl::Writer::new(&mut hlsl_src, &hlsl::Options::default(), &hlsl_pipeline)
        .write(module, info, None)
        .map_err(|e| format!("HLSL: {e}"))?;
    let msl_pipeline = msl::PipelineOptions {
        entry_point: Some((stage, "main".into())),
        ..msl::PipelineOptions::default()
    };
    let (msl_src, _) = msl::write_string(module, info, &msl::Options::default(), &msl_pipeline)
        .map_err(|e| format!("MSL: {e}"))?;
    Ok(Translations {
        spirv,
        glsl: glsl_src,
        hlsl: hlsl_src,
        msl: msl_src,
    })
}

/// The modules of the kernels a shader calls, whose every kernel must have a WGSL twin or a
/// reason in [`NO_TWIN`]: Fresnel, GGX and Beckmann, Cook-Torrance, the diffuse lobes, the
/// Phong family, the metallic-roughness material, the punctual lights, the tonemappers and
/// the colour transfer functions, the glTF extension lobes, the rough dielectric, glTF
/// transmission and volume, the thin film, and the engines' conventions.
pub const TWINNED_MODULES: &[&str] = &[
    "fresnel",
    "ggx",
    "beckmann",
    "cook_torrance",
    "diffuse",
    "phong",
    "material",
    "lights",
    "tonemap",
    "color",
    "microfacet",
    "layers",
    "rough_dielectric",
    "transmission",
    "iridescence",
    "engine",
];

/// Kernels without a WGSL twin, each with the reason: an exact path, or a path prefix ending
/// in `::` for a whole module.
pub const NO_TWIN: &[(&str, &str)] = &[
    (
        "cook_torrance::ggx_conductor_local",
        "its f32 form is evaluated in f64 and rounded once, which WGSL (no f64) cannot \
         follow; cook_torrance_conductor is the shader form of the same lobe",
    ),
    (
        "vec3::",
        "vector algebra WGSL has built in (dot, cross, length, normalize, min, max, abs)",
    ),
    (
        "frame::Frame::",
        "a tangent frame of its normal: shaders build theirs from the mesh's tangents",
    ),
    (
        "fresnel::average_dielectric",
        "a numerical integral evaluated in f64 only; fresnel_average_dielectric_fit is its \
         shader form",
    ),
    (
        "tonemap::ev100_from_camera",
        "camera exposure from f64 settings, computed once on the CPU, not per pixel",
    ),
    (
        "ibl::prefilter::",
        "precomputation of prefiltered environment maps, run once per map, not per pixel",
    ),
    (
        "ibl::energy::e_ggx",
        "a bilinear lookup of the built-in E table: a shader samples E_GGX_TABLE as a texture",
    ),
    (
        "ibl::energy::e_avg_ggx",
        "a linear lookup of the built-in E_avg table: a shader samples E_AVG_GGX_TABLE as a \
         texture",
    ),
    (
        "ibl::energy::kulla_conty_ggx",
        "reads the built-in E and E_avg tables (a shader samples them as textures and calls \
         ibl_energy_kulla_conty_lobe and ibl_energy_kulla_conty_fresnel)",
    ),
    (
        "ibl::energy::kulla_conty_ggx_rgb",
        "reads the built-in E and E_avg tables, as kulla_conty_ggx does, per colour channel (a \
         shader samples them as textures and calls ibl_energy_kulla_conty_lobe and \
         ibl_energy_kulla_conty_fresnel)",
    ),
    (
        "ibl::energy::fresnel_avg_conductor",
        "a 32-point quadrature in f64, computed once per material on the CPU, not per pixel",
    ),
];

/// Why `path` has no WGSL twin, from [`NO_TWIN`].
#[must_use]
pub fn no_twin_reason(path: &str) -> Option<&'static str> {
    NO_TWIN
        .iter()
        .find(|(p, _)| {
            if p.ends_with("::") {
                path.starts_with(p)
            } else {
                path == *p
            }
        })
        .map(|(_, why)| *why)
}

/// The module of a kernel's path (`ggx` for `ggx::Ggx::d`, `ibl` for `ibl::dfg::karis`).
#[must_use]
pub fn module_of(path: &str) -> &str {
    path.split("::").next().unwrap_or(path)
}
