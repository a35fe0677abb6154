//! One table drives both sides: every WGSL function (but the `brdf_` helpers) is the twin of
//! a kernel of `brdf_ref::table::KERNELS`, with its argument names in its order, `f32`
//! parameters and one `f32` per output.

use brdf_gpu::shaders::{families, signature_mismatches, twins};

#[test]
fn every_wgsl_function_has_its_rust_twins_name_and_parameters() {
    let fams = families();
    let bad = signature_mismatches(&fams);
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    let (with, without) = twins(&fams);
    // Coverage, visible in the test log (--nocapture): the kernels still without a twin.
    println!(
        "{} kernels have a WGSL twin; {} do not:",
        with.len(),
        without.len()
    );
    for p in &without {
        println!("  {p}");
    }
}

#[test]
fn a_renamed_parameter_is_caught() {
    // The check itself, on a twin with a swapped argument order.
    let mut fams = families();
    let src = format!(
        "{}fn ggx_d(alpha: f32, n_dot_h: f32) -> f32 {{ return alpha * n_dot_h; }}",
        brdf::wgsl::COMMON
    );
    fams[0].module = naga::front::wgsl::parse_str(&src).expect("parses");
    let bad = signature_mismatches(&fams[..1]);
    assert!(
        bad.iter()
            .any(|b| b.contains("ggx_d: parameters (alpha, n_dot_h)")),
        "{bad:?}"
    );
}
