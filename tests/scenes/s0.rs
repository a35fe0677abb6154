//! The scene of the image-based-lighting comparison (a procedural sky with a sun, four
//! surfaces, the reflectance integral, the split-sum path and the single-sample bug), shared
//! by `tests/ibl/seed_s0.rs` and the report's IBL section.
#![allow(dead_code)]

use brdf::frame::Frame;
use brdf::ibl::{dfg, irradiance, prefilter};
use brdf::material::{DiffuseCoupling, metallic_roughness};
use brdf::microfacet::alpha_from_perceptual;
use brdf::{Cosines, V3};

pub type C = V3<f64>;

pub fn normalize(v: C) -> C {
    v * (1.0 / v.dot(v).sqrt())
}

/// The sun's direction and its angular radius (a smooth disc of about 2.5 degrees).
pub fn sun_dir() -> C {
    normalize(V3::new(0.45, 0.2, 0.85))
}

/// A procedural environment, z up: a blue sky brightening toward the zenith, a warm sun
/// (peak radiance 2000, a Gaussian of 2.5 degrees), and a dim ground.
pub fn env(d: C) -> C {
    let d = normalize(d);
    let sky = if d.z > 0.0 {
        V3::new(0.25, 0.45, 0.9) * (0.6 + 0.8 * d.z)
    } else {
        V3::new(0.08, 0.07, 0.06)
    };
    let c = d.dot(sun_dir()).min(1.0);
    // 1 - cos(2.5 deg) = 9.5e-4.
    let sun = (-(1.0 - c) / 9.5e-4).exp() * 2000.0;
    sky + V3::new(1.0, 0.9, 0.75) * sun
}

/// A constant white environment (the furnace).
pub fn white(_: C) -> C {
    V3::splat(1.0)
}

pub struct Surface {
    pub name: &'static str,
    /// Bounds on the split-sum path's relative error against the reflectance integral, with
    /// quadrature and with SH9 irradiance (measured figures in the test's docs).
    pub bounds: (f64, f64),
    pub n: C,
    pub v: C,
    pub base: C,
    pub metallic: f64,
    pub roughness: f64,
}

pub fn surfaces() -> [Surface; 4] {
    let n = normalize(V3::new(0.15, -0.1, 1.0));
    let v = |x: f64, y: f64, z: f64| normalize(V3::new(x, y, z));
    [
        Surface {
            name: "rough dielectric (r 0.7)",
            bounds: (0.02, 0.05),
            n,
            v: v(-0.5, -0.1, 0.85),
            base: V3::new(0.8, 0.3, 0.2),
            metallic: 0.0,
            roughness: 0.7,
        },
        Surface {
            name: "glossy dielectric (r 0.3)",
            bounds: (0.015, 0.03),
            n,
            v: v(-0.45, -0.2, 0.85),
            base: V3::new(0.2, 0.5, 0.8),
            metallic: 0.0,
            roughness: 0.3,
        },
        Surface {
            name: "rough gold (r 0.6)",
            bounds: (0.16, 0.16),
            n,
            v: v(-0.3, -0.2, 0.9),
            base: V3::new(1.0, 0.78, 0.34),
            metallic: 1.0,
            roughness: 0.6,
        },
        Surface {
            name: "matte white (r 1)",
            bounds: (0.035, 0.065),
            n,
            v: v(0.1, 0.3, 0.95),
            base: V3::splat(0.9),
            metallic: 0.0,
            roughness: 1.0,
        },
    ]
}

/// L_o(v) = integral over the hemisphere of n of f(v, l) L(l) n.l dl, midpoint rule in
/// (n.l, phi) on an `nt` x `2 nt` grid (dl = d(n.l) dphi).
pub fn reference(s: &Surface, l_env: fn(C) -> C, nt: usize) -> C {
    let frame = Frame::from_normal(s.n);
    let np = 2 * nt;
    let n_dot_v = s.n.dot(s.v);
    let mut sum = V3::splat(0.0);
    for i in 0..nt {
        let mu = (i as f64 + 0.5) / nt as f64;
        let sin = (1.0 - mu * mu).sqrt();
        for j in 0..np {
            let phi = (j as f64 + 0.5) / np as f64 * core::f64::consts::TAU;
            let l = frame.to_world(V3::new(sin * phi.cos(), sin * phi.sin(), mu));
            let h = normalize(s.v + l);
            let cosines = Cosines {
                n_dot_v,
                n_dot_l: mu,
                n_dot_h: s.n.dot(h),
                v_dot_h: s.v.dot(h),
            };
            let f = metallic_roughness(
                cosines,
                s.base,
                s.metallic,
                s.roughness,
                0.04,
                DiffuseCoupling::OneMinusF,
            );
            sum += f * l_env(l) * mu;
        }
    }
    sum * (core::f64::consts::TAU / (nt * np) as f64)
}

/// The GGX-prefiltered radiance along r (n = v = r): Karis's n.l-weighted mean over the
/// crate's prefilter samples.
pub fn prefiltered(r: C, alpha: f64, l_env: fn(C) -> C, n: u32) -> C {
    let frame = Frame::from_normal(r);
    let (mut sum, mut w) = (V3::splat(0.0), 0.0);
    for smp in prefilter::samples::<f64>(n, alpha) {
        sum += l_env(frame.to_world(smp.dir)) * smp.weight;
        w += smp.weight;
    }
    sum * (1.0 / w)
}

pub struct Paths {
    /// Split-sum specular plus kD-weighted diffuse with quadrature irradiance.
    pub fixed: C,
    /// The same with SH9 irradiance.
    pub fixed_sh9: C,
    /// The bug: base L(n) + F0 lerp(L(r), L(n), roughness), no energy split.
    pub bug: C,
}

pub fn paths(s: &Surface, l_env: fn(C) -> C) -> Paths {
    let alpha = alpha_from_perceptual(s.roughness);
    let n_dot_v = s.n.dot(s.v);
    let r = s.n * (2.0 * n_dot_v) - s.v;
    let f0 = V3::splat(0.04) * (1.0 - s.metallic) + s.base * s.metallic;
    let [a, b, _] = dfg::dfg(n_dot_v, alpha, dfg::DEFAULT_SAMPLES);
    let spec = dfg::specular(prefiltered(r, alpha, l_env, 16384), f0, 1.0, a, b);
    // kD = (1 - F)(1 - metallic), F the specular lobe's directional albedo F0 A + B: what the
    // specular term takes, the diffuse term does not get again.
    let k_d = (V3::splat(1.0) - (f0 * a + V3::splat(b))) * (1.0 - s.metallic);
    let lambert = s.base * k_d * core::f64::consts::FRAC_1_PI;
    let e_quad = irradiance::irradiance(s.n, l_env, 256);
    let sh = irradiance::project(l_env, 256);
    let e_sh = sh.irradiance(s.n);
    let mirror = l_env(r);
    let normal = l_env(s.n);
    let lerp = mirror * (1.0 - s.roughness) + normal * s.roughness;
    Paths {
        fixed: spec + lambert * e_quad,
        fixed_sh9: spec + lambert * e_sh,
        bug: s.base * normal + f0 * lerp,
    }
}

/// max over RGB of |a - b| / max(b).
pub fn rel(a: C, b: C) -> f64 {
    ((a - b).abs().max_element()) / b.max_element()
}
