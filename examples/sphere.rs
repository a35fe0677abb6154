//! `cargo run --release --example sphere`: a sphere shaded with the glTF metallic-roughness
//! material from world-space n, v and l, per pixel in `f32` and 8 pixels at a time in `f32x8`
//! (one generic `shade`). Each pixel builds its `ShadingPoint` (frame of n, view v) once and
//! evaluates the material on the world-space light direction through it.
//! Writes out/sphere_{scalar,lanes}.png; fails unless they agree bitwise.
use brdf::material::MetallicRoughness;
use brdf::{Real, ShadingPoint, V3, color::srgb_oetf, wide::f32x8};
use std::{error::Error, fs::File, io::BufWriter};
const S: usize = 256; // image width and height in pixels

/// Linear RGB radiance of the `T::LANES` pixels starting at (px, py).
fn shade<T: Real<Scalar = f32>>(m: &MetallicRoughness<T>, px: usize, py: usize) -> V3<T> {
    let x = T::from_fn(|i| (px + i) as f32 + 0.5) * T::splat(2.0 / S as f64) - T::ONE;
    let y = T::ONE - T::splat((py as f64 + 0.5) * 2.0 / S as f64);
    // Off the sphere z = 0, so n.v = 0 and the material returns 0: a black background.
    let n = V3::new(x, y, (T::ONE - x * x - y * y).sqrt_nonneg());
    let v = V3::unit_z(); // orthographic camera looking down -z; light from the upper left
    let l = V3::new(T::splat(-0.3), T::splat(0.4), T::splat(0.87)).normalize_or(v);
    let sp = ShadingPoint::new(n, v); // once per pixel, shared by every light
    m.eval_world(&sp, l) * (T::splat(3.0) * n.dot(l).max(T::ZERO)) // f E n.l, irradiance E = 3
}

fn render<T: Real<Scalar = f32>>() -> Result<Vec<f32>, brdf::ParamError> {
    // Red plastic (linear base colour), metallic 0, perceptual roughness 0.4 (alpha = 0.16).
    let base = V3::new(T::splat(0.8), T::splat(0.05), T::splat(0.04));
    let m = MetallicRoughness::new(base, T::ZERO, T::splat(0.4))?;
    let mut img = Vec::with_capacity(3 * S * S);
    for i in (0..S * S).step_by(T::LANES) {
        let c = shade(&m, i % S, i / S);
        img.extend((0..T::LANES).flat_map(|k| [c.x.lane(k), c.y.lane(k), c.z.lane(k)]));
    }
    Ok(img)
}

fn save(path: &str, img: &[f32]) -> Result<(), Box<dyn Error>> {
    let encode = |c: &f32| (srgb_oetf(c.min(1.0)) * 255.0).round() as u8; // clip, then sRGB
    let mut png = png::Encoder::new(BufWriter::new(File::create(path)?), S as u32, S as u32);
    png.set_color(png::ColorType::Rgb); // 8 bits per channel by default
    let bytes: Vec<u8> = img.iter().map(encode).collect();
    Ok(png.write_header()?.write_image_data(&bytes)?)
}

fn main() -> Result<(), Box<dyn Error>> {
    let (scalar, lanes) = (render::<f32>()?, render::<f32x8>()?);
    std::fs::create_dir_all("out")?;
    save("out/sphere_scalar.png", &scalar)?;
    save("out/sphere_lanes.png", &lanes)?;
    let (mut differ, mut bad, mut lit) = (0, 0, 0);
    for (a, b) in scalar.iter().zip(&lanes) {
        differ += usize::from(a.to_bits() != b.to_bits());
        bad += usize::from(!(a.is_finite() && *a >= 0.0));
        lit += usize::from(*a > 0.0);
    }
    println!("sphere: {lit} values > 0, {bad} NaN/inf/negative (want 0) in RGB of {S}x{S} px");
    println!("sphere: f32 vs f32x8: {differ} differ; wrote out/sphere_scalar.png, _lanes.png");
    let ok = differ + bad == 0 && lit > 0;
    assert!(
        ok,
        "sphere: f32x8 must equal f32 bit for bit, every value finite"
    );
    Ok(())
}
