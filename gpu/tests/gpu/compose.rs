//! The families compose without duplicate definitions: no two of `COMMON` and the families
//! define the same name, and each registers with naga_oil (bevy's shader composer) as a module
//! of its own, `brdf::<family>`, importing what it calls from `brdf::common` and the families
//! it needs; a shader importing every twin from those modules composes into one valid module.

use naga_oil::compose::{
    ComposableModuleDescriptor, Composer, NagaModuleDescriptor, ShaderLanguage, ShaderType,
};
use std::collections::BTreeMap;

/// The names a WGSL source defines at module scope (`fn` and `const` items).
fn defined(source: &str) -> Vec<String> {
    source
        .lines()
        .filter_map(|l| l.strip_prefix("fn ").or_else(|| l.strip_prefix("const ")))
        .filter_map(|rest| {
            rest.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                .next()
                .map(str::to_string)
        })
        .collect()
}

/// (module name, source) for `COMMON` and every family, in the order of `ALL`.
fn modules() -> Vec<(&'static str, &'static str)> {
    std::iter::once(("common", brdf::wgsl::COMMON))
        .chain(brdf::wgsl::FAMILIES.iter().map(|f| (f.name, f.source)))
        .collect()
}

#[test]
fn no_name_is_defined_by_two_families() {
    let mut owner: BTreeMap<String, &str> = BTreeMap::new();
    let mut twice = Vec::new();
    for (module, source) in modules() {
        for name in defined(source) {
            if let Some(first) = owner.insert(name.clone(), module) {
                twice.push(format!("{name}: {first} and {module}"));
            }
        }
    }
    assert!(twice.is_empty(), "defined twice: {twice:?}");
    // The scan saw every item: as many names as naga finds functions and constants in ALL.
    let (all, _) = brdf_gpu::shaders::parse(brdf::wgsl::ALL, "ALL").expect("ALL parses");
    let named_constants = all
        .constants
        .iter()
        .filter(|(_, c)| c.name.is_some())
        .count();
    assert_eq!(owner.len(), all.functions.len() + named_constants);
}

/// `#import brdf::<module>::{...}` of everything `module` defines.
fn import_all(module: &str, source: &str) -> String {
    format!(
        "#import brdf::{module}::{{{}}}\n",
        defined(source).join(", ")
    )
}

#[test]
fn the_families_compose_as_naga_oil_modules() {
    let mut composer = Composer::default();
    let mut add = |name: &str, source: String| {
        let added = composer.add_composable_module(ComposableModuleDescriptor {
            source: &source,
            file_path: &format!("wgsl/{name}.wgsl"),
            language: ShaderLanguage::Wgsl,
            as_name: Some(format!("brdf::{name}")),
            ..ComposableModuleDescriptor::default()
        });
        if let Err(e) = added {
            panic!("brdf::{name}: {}", e.emit_to_string(&composer));
        }
    };
    add("common", brdf::wgsl::COMMON.to_string());
    for fam in brdf::wgsl::FAMILIES {
        let mut source = import_all("common", brdf::wgsl::COMMON);
        for need in fam.needs {
            let dep = brdf::wgsl::FAMILIES
                .iter()
                .find(|f| f.name == *need)
                .expect("known family");
            source += &import_all(need, dep.source);
        }
        source += fam.source;
        add(fam.name, source);
    }
    // A shader importing every twin (not the helpers) of every family, and calling a few.
    let mut shader = String::new();
    for fam in brdf::wgsl::FAMILIES {
        let twins: Vec<String> = defined(fam.source)
            .into_iter()
            .filter(|n| !n.starts_with("brdf_") && !n.starts_with("BRDF_"))
            .collect();
        if !twins.is_empty() {
            shader += &format!("#import brdf::{}::{{{}}}\n", fam.name, twins.join(", "));
        }
    }
    shader += "
@group(0) @binding(0) var<storage, read_write> out: array<f32>;

@compute @workgroup_size(1)
fn main() {
    out[0] = ggx_d(0.5, 0.25);
    out[1] = beckmann_lambda(0.5, 0.25);
    out[2] = fresnel_conductor(0.5, 0.2, 3.0);
    out[3] = diffuse_eon(0.5, 0.5, 0.2, 0.8, 0.5);
    out[4] = material_gltf(0.5, 0.5, 0.9, 0.8, 0.5, 0.5, 0.5, 0.0, 0.5).x;
    out[5] = tonemap_agx_minimal(1.0, 0.5, 0.25, 1u).y;
    out[6] = cook_torrance_beckmann(0.5, 0.5, 0.9, 0.8, 0.3, 0.04);
}
";
    let module = composer
        .make_naga_module(NagaModuleDescriptor {
            source: &shader,
            file_path: "user.wgsl",
            shader_type: ShaderType::Wgsl,
            ..NagaModuleDescriptor::default()
        })
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(&composer)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .expect("the composed module validates");
    assert!(module.entry_points.iter().any(|e| e.name == "main"));
}
