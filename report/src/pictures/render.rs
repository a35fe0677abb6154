//! Orthographic sphere grids: one sphere per cell, shaded per pixel by a closure, with
//! analytic edge coverage (the disc's signed distance over a pixel's width) instead of
//! supersampling; then exposure, a tonemapping operator on `f32x8` lanes and the sRGB
//! transfer function.

use brdf::Real;
use brdf::V3;
use brdf::color;
use brdf::tonemap::Operator;
use brdf::wide::f32x8;

/// A linear-radiance picture.
pub struct Hdr {
    /// Width in pixels.
    pub w: usize,
    /// Height in pixels.
    pub h: usize,
    /// Radiance, row by row.
    pub px: Vec<V3<f32>>,
}

/// Sphere radius as a fraction of half the cell.
const RADIUS: f32 = 0.88;

/// What a shader sees at one pixel: the world normal, the direction to the camera (+z) and
/// the sphere's cell.
pub struct Px {
    /// Unit surface normal.
    pub n: V3<f32>,
    /// Unit direction to the camera.
    pub v: V3<f32>,
    /// Row of the cell.
    pub row: usize,
    /// Column of the cell.
    pub col: usize,
}

/// Renders `rows` x `cols` cells of `cell` pixels: `background` outside the spheres, `shade`
/// inside, blended by coverage at the rim.
pub fn spheres(
    rows: usize,
    cols: usize,
    cell: usize,
    background: V3<f32>,
    shade: impl Fn(&Px) -> V3<f32>,
) -> Hdr {
    let (w, h) = (cols * cell, rows * cell);
    let mut px = vec![background; w * h];
    let pixel = 2.0 / cell as f32;
    for row in 0..rows {
        for col in 0..cols {
            for y in 0..cell {
                for x in 0..cell {
                    let sx = (x as f32 + 0.5) * pixel - 1.0;
                    let sy = 1.0 - (y as f32 + 0.5) * pixel;
                    let r = (sx * sx + sy * sy).sqrt();
                    let coverage = ((RADIUS - r) / pixel + 0.5).clamp(0.0, 1.0);
                    if coverage <= 0.0 {
                        continue;
                    }
                    // Rim pixels are shaded just inside the rim, where the normal is defined.
                    let k = if r > 0.999 * RADIUS {
                        0.999 * RADIUS / r
                    } else {
                        1.0
                    };
                    let (nx, ny) = (sx * k / RADIUS, sy * k / RADIUS);
                    let nz = (1.0 - nx * nx - ny * ny).max(0.0).sqrt();
                    let c = shade(&Px {
                        n: V3::new(nx, ny, nz),
                        v: V3::unit_z(),
                        row,
                        col,
                    });
                    let i = (row * cell + y) * w + col * cell + x;
                    px[i] = c * coverage + background * (1.0 - coverage);
                }
            }
        }
    }
    Hdr { w, h, px }
}

/// Exposure, then `op` (`None`: none, values clipped to [0, 1]) on `f32x8` lanes, then the
/// sRGB OETF, quantized to RGB8.
pub fn display(img: &Hdr, exposure: f32, op: Option<&Operator>) -> Vec<u8> {
    let mut out = Vec::with_capacity(img.px.len() * 3);
    for chunk in img.px.chunks(8) {
        let lane =
            |f: fn(&V3<f32>) -> f32| f32x8::from_fn(|i| chunk.get(i).map_or(0.0, f) * exposure);
        let c = V3::new(lane(|p| p.x), lane(|p| p.y), lane(|p| p.z));
        let mapped = match op {
            Some(op) => op.apply(c),
            None => c,
        };
        let enc = color::srgb_oetf_rgb(mapped.map(|x| x.clamp(f32x8::ZERO, f32x8::ONE)));
        for i in 0..chunk.len() {
            let p = enc.lane(i);
            out.extend([p.x, p.y, p.z].map(|x| (x.clamp(0.0, 1.0) * 255.0).round() as u8));
        }
    }
    out
}
