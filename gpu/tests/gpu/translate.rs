//! Every twin's compute shader parses and validates with naga, translates to SPIR-V, GLSL,
//! HLSL and MSL, and the SPIR-V passes `spirv-val` and the GLSL `glslangValidator` (Debian's
//! `spirv-tools` and `glslang-tools`; `.ci/run` installs them).

use brdf_gpu::shaders::{compute_shader, families, parse, translate, twins};
use std::path::Path;
use std::process::Command;

/// Runs a validator on `file`, failing with its output; a missing tool fails with the
/// package that provides it.
fn validate(tool: &str, package: &str, args: &[&str], file: &Path, what: &str) {
    let out = Command::new(tool)
        .args(args)
        .arg(file)
        .output()
        .unwrap_or_else(|e| {
            panic!("{tool} not found ({e}): install Debian's {package} (.ci/run does)")
        });
    assert!(
        out.status.success(),
        "{tool} rejects {what}:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn every_twin_translates_and_the_validators_accept_spirv_and_glsl() {
    let fams = families();
    let (with, _) = twins(&fams);
    assert!(!with.is_empty(), "no twin found");
    let dir = std::env::temp_dir().join(format!("brdf-gpu-translate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    for t in &with {
        let src = compute_shader(t, &fams);
        let (module, info) = parse(&src, &t.name).unwrap_or_else(|e| panic!("{e}"));
        let tr = translate(&module, &info).unwrap_or_else(|e| panic!("{}: {e}", t.name));
        assert!(
            tr.hlsl.contains(&t.name),
            "{}: HLSL lacks the function",
            t.name
        );
        assert!(
            tr.msl.contains(&t.name),
            "{}: MSL lacks the function",
            t.name
        );
        let spv = dir.join(format!("{}.spv", t.name));
        let bytes: Vec<u8> = tr.spirv.iter().flat_map(|w| w.to_le_bytes()).collect();
        std::fs::write(&spv, bytes).expect("write SPIR-V");
        validate("spirv-val", "spirv-tools", &[], &spv, &t.name);
        let comp = dir.join(format!("{}.comp", t.name));
        std::fs::write(&comp, &tr.glsl).expect("write GLSL");
        validate("glslangValidator", "glslang-tools", &[], &comp, &t.name);
    }
    std::fs::remove_dir_all(&dir).ok();
    println!("{} twins translated and validated", with.len());
}

#[test]
fn all_families_compose_into_one_module() {
    // COMMON first, then every family: no name is defined twice.
    parse(brdf::wgsl::ALL, "brdf::wgsl::ALL").unwrap_or_else(|e| panic!("{e}"));
    let joined: String = std::iter::once(brdf::wgsl::COMMON)
        .chain(brdf::wgsl::FAMILIES.iter().map(|f| f.source))
        .collect();
    assert_eq!(
        joined,
        brdf::wgsl::ALL,
        "ALL is COMMON and every family, in order"
    );
}
