//! The environment the renders are lit by: an equirectangular radiance map (procedural, or a
//! Radiance `.hdr` file), its box-filtered mips, GGX-prefiltered copies for the split-sum
//! specular (samples from [`brdf::ibl::prefilter`], each read at the mip of filtered importance
//! sampling), its SH9 irradiance ([`brdf::ibl::irradiance::Sh9`]), and a key light.
//!
//! Directions are world space with +y up and the camera looking along -z (v = +z on the
//! spheres). Texel (i, j) of a W x H map looks along phi = 2 pi ((i + 0.5) / W - 0.5),
//! theta = pi (j + 0.5) / H: (sin theta sin phi, cos theta, -sin theta cos phi), so the centre
//! column of a `.hdr` file lies straight ahead, behind the spheres.

use brdf::V3;
use brdf::frame::Frame;
use brdf::ibl::irradiance::Sh9;
use brdf::ibl::prefilter;
use brdf::microfacet::alpha_from_perceptual;
use core::f32::consts::PI;

use super::hdr::Hdr;

/// An equirectangular map of linear RGB.
#[derive(Clone)]
pub struct Map {
    w: usize,
    h: usize,
    px: Vec<V3<f32>>,
}

/// The map direction of texel centre (x, y) in texel units.
fn texel_dir(x: f32, y: f32, w: usize, h: usize) -> V3<f32> {
    let phi = 2.0 * PI * (x / w as f32 - 0.5);
    let theta = PI * y / h as f32;
    V3::new(
        theta.sin() * phi.sin(),
        theta.cos(),
        -theta.sin() * phi.cos(),
    )
}

impl Map {
    fn from_fn(w: usize, h: usize, f: impl Fn(V3<f32>) -> V3<f32>) -> Self {
        let px = (0..w * h)
            .map(|k| f(texel_dir((k % w) as f32 + 0.5, (k / w) as f32 + 0.5, w, h)))
            .collect();
        Self { w, h, px }
    }

    /// Half the size, each texel the mean of four (latitude weights ignored: the mips only
    /// feed filtered importance sampling, which tolerates that blur at the poles).
    fn half(&self) -> Self {
        let (w, h) = ((self.w / 2).max(1), (self.h / 2).max(1));
        let at = |x: usize, y: usize| self.px[y.min(self.h - 1) * self.w + x.min(self.w - 1)];
        let px = (0..w * h)
            .map(|k| {
                let (x, y) = (2 * (k % w), 2 * (k / w));
                (at(x, y) + at(x + 1, y) + at(x, y + 1) + at(x + 1, y + 1)) * 0.25
            })
            .collect();
        Self { w, h, px }
    }

    /// Bilinear read along `d` (unit), wrapping in longitude and clamping in latitude.
    fn read(&self, d: V3<f32>) -> V3<f32> {
        let u = d.x.atan2(-d.z) / (2.0 * PI) + 0.5;
        let v = d.y.clamp(-1.0, 1.0).acos() / PI;
        let x = u * self.w as f32 - 0.5;
        let y = (v * self.h as f32 - 0.5).clamp(0.0, (self.h - 1) as f32);
        let (x0, y0) = (x.floor(), y.floor());
        let (tx, ty) = (x - x0, y - y0);
        let xi = |k: f32| (k as i64).rem_euclid(self.w as i64) as usize;
        let (xa, xb) = (xi(x0), xi(x0 + 1.0));
        let (ya, yb) = (y0 as usize, (y0 as usize + 1).min(self.h - 1));
        let p = |x: usize, y: usize| self.px[y * self.w + x];
        let top = p(xa, ya) * (1.0 - tx) + p(xb, ya) * tx;
        let bottom = p(xa, yb) * (1.0 - tx) + p(xb, yb) * tx;
        top * (1.0 - ty) + bottom * ty
    }
}

/// The procedural sky: a zenith-to-horizon gradient, a glow around the sun, a soft horizon
/// and a checkered ground (so that reflections show how much a lobe blurs).
fn sky(d: V3<f32>, sun: V3<f32>) -> V3<f32> {
    let up = d.y;
    if up >= 0.0 {
        let t = (1.0 - up).powi(4);
        let zenith = V3::new(0.18, 0.34, 0.85);
        let horizon = V3::new(0.85, 0.9, 1.0);
        let glow = (-(1.0 - d.dot(sun).min(1.0)) / 0.015).exp() * 14.0
            + (-(1.0 - d.dot(sun).min(1.0)) / 0.25).exp() * 0.6;
        (zenith * (1.0 - t) + horizon * t) * 1.1 + V3::new(1.0, 0.85, 0.6) * glow
    } else {
        // The ground plane one unit below the eye, in checks of one unit, fading to a haze
        // towards the horizon (where the checks would alias).
        let t = -1.0 / up;
        let (gx, gz) = (d.x * t, d.z * t);
        let check = ((gx.floor() + gz.floor()) as i64).rem_euclid(2) == 0;
        let base = if check {
            V3::new(0.32, 0.3, 0.27)
        } else {
            V3::new(0.12, 0.11, 0.1)
        };
        let haze = (-(-up) * 12.0).exp();
        base * (1.0 - haze) + V3::new(0.5, 0.5, 0.52) * haze
    }
}

/// Perceptual roughness of each prefiltered level: level k holds r = k / (LEVELS - 1).
pub const LEVELS: usize = 6;

/// An environment ready to shade with.
pub struct Env {
    /// Where it comes from, for captions.
    pub name: String,
    mips: Vec<Map>,
    levels: Vec<Map>,
    /// Its SH9 projection (irradiance by [`Sh9::irradiance`]).
    pub sh: Sh9<f32>,
    /// Direction to the key light (unit).
    pub light_dir: V3<f32>,
    /// The key light's irradiance on a surface facing it, RGB.
    pub light: V3<f32>,
    /// Constant radiance everywhere (a white furnace) instead of a map.
    uniform: Option<V3<f32>>,
}

/// Base map size (texels of 1.4 degrees) and GGX samples per prefiltered texel.
const BASE_W: usize = 256;
const SAMPLES: u32 = 96;

impl Env {
    /// The procedural sky, sun and ground.
    pub fn procedural() -> Self {
        let sun = V3::new(-0.55f32, 0.5, 0.67).normalize();
        let base = Map::from_fn(BASE_W, BASE_W / 2, |d| sky(d, sun));
        Self::from_base(
            "procedural sky, sun glow and checkered ground".into(),
            base,
            sun,
            V3::new(3.0, 2.8, 2.5),
        )
    }

    /// A Radiance `.hdr` file (equirectangular), halved until at most twice the base width
    /// and resampled to the base map; the key light keeps the procedural sun's direction.
    pub fn from_hdr(name: &str, img: &Hdr) -> Self {
        let mut m = Map {
            w: img.w,
            h: img.h,
            px: img.px.iter().map(|&[r, g, b]| V3::new(r, g, b)).collect(),
        };
        while m.w > 2 * BASE_W && m.h > 1 {
            m = m.half();
        }
        let base = Map::from_fn(BASE_W, BASE_W / 2, |d| m.read(d));
        let sun = V3::new(-0.55f32, 0.5, 0.67).normalize();
        Self::from_base(name.into(), base, sun, V3::new(3.0, 2.8, 2.5))
    }

    /// A white furnace: radiance `l` from every direction, no key light.
    pub fn uniform(l: f32) -> Self {
        let base = Map::from_fn(8, 4, |_| V3::splat(l));
        let mut e = Self::from_base("uniform".into(), base, V3::unit_z(), V3::splat(0.0));
        e.uniform = Some(V3::splat(l));
        e
    }

    fn from_base(name: String, base: Map, light_dir: V3<f32>, light: V3<f32>) -> Self {
        let mut mips = vec![base];
        while mips.last().is_some_and(|m| m.h > 1) {
            let next = mips.last().map(Map::half);
            mips.extend(next);
        }
        let b = &mips[0];
        // SH9 by the midpoint rule per texel: a texel of row j subtends
        // (2 pi / W) (cos theta_j - cos theta_j+1).
        let mut sh = Sh9::<f64>::zero();
        for (k, l) in b.px.iter().enumerate() {
            let (x, y) = (k % b.w, k / b.w);
            let t0 = core::f64::consts::PI * y as f64 / b.h as f64;
            let t1 = core::f64::consts::PI * (y + 1) as f64 / b.h as f64;
            let omega = 2.0 * core::f64::consts::PI / b.w as f64 * (t0.cos() - t1.cos());
            let d = texel_dir(x as f32 + 0.5, y as f32 + 0.5, b.w, b.h);
            sh.add(
                V3::new(f64::from(d.x), f64::from(d.y), f64::from(d.z)),
                V3::new(f64::from(l.x), f64::from(l.y), f64::from(l.z)),
                omega,
            );
        }
        let mut env = Self {
            name,
            mips,
            levels: Vec::new(),
            sh: Sh9::splat_from(&sh),
            light_dir,
            light,
            uniform: None,
        };
        env.levels = (0..LEVELS).map(|k| env.prefilter(k)).collect();
        env
    }

    /// Trilinear read of the mip pyramid at fractional `lod`.
    fn read_lod(&self, d: V3<f32>, lod: f32) -> V3<f32> {
        let top = (self.mips.len() - 1) as f32;
        let lod = lod.clamp(0.0, top);
        let i = lod.floor() as usize;
        let t = lod - i as f32;
        let a = self.mips[i].read(d);
        if t == 0.0 || i + 1 >= self.mips.len() {
            a
        } else {
            a * (1.0 - t) + self.mips[i + 1].read(d) * t
        }
    }

    /// Level k: Karis's n = v = r prefilter at perceptual roughness k / (LEVELS - 1), each
    /// sample read at its filtered-importance-sampling mip. Level 0 is the base map itself.
    fn prefilter(&self, k: usize) -> Map {
        if k == 0 {
            return self.mips[0].clone();
        }
        let r = k as f32 / (LEVELS - 1) as f32;
        let alpha = alpha_from_perceptual(r);
        let mut samples = vec![prefilter::PrefilterSample::<f32>::default(); SAMPLES as usize];
        let total = prefilter::fill(&mut samples, alpha);
        // The cube face of the same mean texel solid angle as the W x H base map:
        // 6 w^2 = W H, and W = 2 H.
        let b = &self.mips[0];
        let face = (b.w as f32 * b.h as f32 / 6.0).sqrt();
        let lods: Vec<f32> = samples
            .iter()
            .map(|s| prefilter::mip_level(s.pdf, SAMPLES as f32, face))
            .collect();
        let w = if k == 1 { 128 } else { 64 };
        Map::from_fn(w, w / 2, |rdir| {
            let fr = Frame::from_normal(rdir);
            let mut acc = V3::splat(0.0);
            for (s, &lod) in samples.iter().zip(&lods) {
                if s.weight > 0.0 {
                    acc += self.read_lod(fr.to_world(s.dir), lod) * s.weight;
                }
            }
            acc * total.recip()
        })
    }

    /// The environment's radiance along `d` (unit), unfiltered.
    pub fn radiance(&self, d: V3<f32>) -> V3<f32> {
        self.uniform.unwrap_or_else(|| self.mips[0].read(d))
    }

    /// Prefiltered radiance along the reflection direction `r` (unit) for perceptual
    /// `roughness` in [0, 1], linear between the two nearest levels.
    pub fn prefiltered(&self, r: V3<f32>, roughness: f32) -> V3<f32> {
        if let Some(l) = self.uniform {
            return l;
        }
        let t = roughness.clamp(0.0, 1.0) * (LEVELS - 1) as f32;
        let i = (t.floor() as usize).min(LEVELS - 2);
        let f = t - i as f32;
        self.levels[i].read(r) * (1.0 - f) + self.levels[i + 1].read(r) * f
    }

    /// Irradiance E(n) from SH9, clamped at 0 (SH9 rings below 0 opposite a bright region).
    pub fn irradiance(&self, n: V3<f32>) -> V3<f32> {
        self.sh.irradiance(n).max(V3::splat(0.0))
    }
}
