//! no_std link probe for `brdf` (see Cargo.toml).
#![no_std]
#![no_main]

use brdf::{Real, V3, frame::Frame};

// The C library provides `memcpy`/`memset` and the start-up code that calls `main`; a no_std
// binary does not link it by default.
#[link(name = "c")]
unsafe extern "C" {}

/// The prebuilt `core` is compiled for unwinding and still names this symbol; with
/// `panic = "abort"` it is never called.
// SAFETY: nothing calls it (panics abort), and no other definition exists in a no_std program.
#[unsafe(no_mangle)]
pub extern "C" fn rust_eh_personality() {}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}

/// The C runtime's entry point: the probe links against the platform's C start-up files, not
/// against Rust's `std`.
// SAFETY: `main` is the one symbol of that name in the program and has the C signature the
// start-up code expects.
#[unsafe(no_mangle)]
pub extern "C" fn main(_argc: i32, _argv: *const *const u8) -> i32 {
    // Touch the foundation and the integrators so they are linked, not just compiled.
    let n = V3::new(0.0_f32, 0.6, 0.8);
    let f = Frame::from_normal(n);
    let z = f.to_local(n).z.exp().ln();
    let albedo = brdf::integrate::directional_albedo(V3::unit_z(), |_, _| core::f64::consts::FRAC_1_PI);
    if (z - 1.0).abs() < 1e-5 && (albedo.value - 1.0).abs() < 1e-6 { 0 } else { 1 }
}
