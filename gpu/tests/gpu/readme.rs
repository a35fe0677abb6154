//! The README's example of the WGSL in a wgpu renderer is this file's code, and it builds.

// README begin
/// A compute pipeline whose shader calls the crate's GGX D: the WGSL twins are plain
/// source, concatenated before your own (COMMON first, then the families you use).
fn ggx_pipeline(device: &wgpu::Device) -> wgpu::ComputePipeline {
    let source = [brdf::wgsl::COMMON, brdf::wgsl::GGX, USER_SHADER].concat();
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("brdf ggx"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("ggx_d over n.h"),
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: wgpu::PipelineCompilationOptions::default(),
        cache: None,
    })
}

const USER_SHADER: &str = "
@group(0) @binding(0) var<storage, read_write> d: array<f32>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let n_dot_h = f32(id.x) / 63.0;
    d[id.x] = ggx_d(n_dot_h, 0.25); // same name, same argument order as brdf::ggx::d
}
";
// README end

#[test]
fn the_readme_example_validates_and_builds_a_pipeline() {
    let source = [brdf::wgsl::COMMON, brdf::wgsl::GGX, USER_SHADER].concat();
    brdf_gpu::shaders::parse(&source, "README example").unwrap_or_else(|e| panic!("{e}"));
    // With an adapter, wgpu compiles it too (the equivalence test reports a missing one).
    if let Some(gpu) = brdf_gpu::device::Gpu::new() {
        let _ = ggx_pipeline(gpu.device());
    }
}

#[test]
fn the_readme_shows_this_example() {
    let this = include_str!("readme.rs");
    let code = this
        .split("// README begin\n")
        .nth(1)
        .and_then(|s| s.split("// README end").next())
        .expect("markers");
    let readme = include_str!("../../../README.md");
    assert!(
        readme.contains(code.trim_end()),
        "README.md's wgpu example differs from gpu/tests/gpu/readme.rs"
    );
}
