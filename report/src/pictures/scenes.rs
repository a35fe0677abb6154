//! The sphere charts: what each row and column holds, and the shading of each, through the
//! crate's public functions only.

use brdf::diffuse;
use brdf::ggx::Ggx;
use brdf::ibl::{dfg, energy};
use brdf::integrate::{directional_albedo_sphere, directional_albedo_with};
use brdf::layers::layered::Layered;
use brdf::material::MetallicRoughness;
use brdf::microfacet::alpha_from_perceptual;
use brdf::rough_dielectric::{self, Transport};
use brdf::tonemap::Operator;
use brdf::{ShadingPoint, V3, cook_torrance, fresnel, phong};
use core::f32::consts::PI;

use super::env::Env;
use super::render::{self, Px};

/// A rendered chart: RGB8 pixels and the captions of its rows and columns.
pub struct Chart {
    /// Title above the grid.
    pub title: String,
    /// RGB8, row by row.
    pub rgb: Vec<u8>,
    /// Width in pixels.
    pub w: usize,
    /// Height in pixels.
    pub h: usize,
    /// One caption per row.
    pub rows: Vec<String>,
    /// One caption per column.
    pub cols: Vec<String>,
}

/// The split-sum DFG table (32 x 32, 512 GGX samples a cell: [`dfg::table`]).
pub struct Dfg(Vec<[f32; 3]>);

const DFG_N: usize = 32;

impl Dfg {
    /// Builds the table.
    pub fn new() -> Self {
        let mut t = vec![[0f32; 3]; DFG_N * DFG_N];
        // Dimensions and sample count are valid constants: the table cannot refuse them.
        let _ = dfg::table(&mut t, DFG_N, DFG_N, 512);
        Self(t)
    }

    /// (A, B) at (n.v, perceptual roughness), with A + B kept at or below 1 (quadrature
    /// rounding can put it a hair above, where [`energy::fdez_aguera`] gives NaN).
    fn ab(&self, n_dot_v: f32, roughness: f32) -> (f32, f32) {
        let [a, b, _] = dfg::lookup(&self.0, DFG_N, DFG_N, n_dot_v, roughness);
        let s = (a + b).max(1.0);
        (a / s, b / s)
    }
}

/// Background radiance of the lit charts (a neutral grey a little darker than the sky).
const BACKDROP: f32 = 0.12;

/// Exposure and operator of the lit charts.
const EXPOSURE: f32 = 0.6;
const OPERATOR: Operator = Operator::PbrNeutral;

fn reflect(v: V3<f32>, n: V3<f32>) -> V3<f32> {
    n * (2.0 * n.dot(v)) - v
}

/// The glTF material lit by the key light and the environment: direct light through
/// [`MetallicRoughness::eval_world`]; specular IBL by the split sum (prefiltered radiance and
/// [`dfg::specular`]); diffuse IBL from SH9 irradiance, weighted by 1 - F0 A - B. With `ms`,
/// Fdez-Aguera's multiple-scattering term for the image light ([`energy::fdez_aguera`]) and
/// Kulla-Conty's lobe for the key light ([`energy::kulla_conty_ggx_rgb`]).
fn gltf(
    env: &Env,
    t: &Dfg,
    p: &Px,
    base: V3<f32>,
    metallic: f32,
    roughness: f32,
    ms: bool,
) -> V3<f32> {
    let Ok(m) = MetallicRoughness::new(base, metallic, roughness) else {
        return V3::splat(f32::NAN);
    };
    let sp = ShadingPoint::new(p.n, p.v);
    let n_dot_v = p.n.dot(p.v).max(1e-4);
    let n_dot_l = p.n.dot(env.light_dir);
    let f0 = m.dielectric_f0() * (1.0 - metallic) + base * metallic;
    let c_diff = base * (1.0 - metallic);
    let mut direct = m.eval_world(&sp, env.light_dir) * env.light * n_dot_l.max(0.0);
    if ms && n_dot_l > 0.0 {
        let f_avg = f0.map(|f| energy::fresnel_avg_schlick(f, 1.0));
        direct +=
            energy::kulla_conty_ggx_rgb(n_dot_v, n_dot_l, m.alpha(), f_avg) * env.light * n_dot_l;
    }
    let (a, b) = t.ab(n_dot_v, roughness);
    let pre = env.prefiltered(reflect(p.v, p.n), roughness);
    let e = env.irradiance(p.n) * (1.0 / PI);
    let (spec, kd) = if ms {
        let fss = f0.map(|f| energy::fdez_aguera(a, b, f).0);
        let fms = f0.map(|f| energy::fdez_aguera(a, b, f).1);
        (pre * fss + e * fms, V3::splat(1.0) - fss - fms)
    } else {
        (
            dfg::specular(pre, f0, 1.0, a, b),
            V3::splat(1.0) - f0 * a - V3::splat(b),
        )
    };
    direct + spec + c_diff * kd * e
}

fn labels(prefix: &str, xs: &[f32]) -> Vec<String> {
    xs.iter().map(|x| format!("{prefix} {x}")).collect()
}

/// The classic chart: perceptual roughness across, metallic down, one base colour, key light
/// plus image light with multiple-scattering compensation.
pub fn material_chart(env: &Env, t: &Dfg, cell: usize) -> Chart {
    let rough = [0.0f32, 0.2, 0.4, 0.6, 0.8, 1.0];
    let metal = [0.0f32, 0.25, 0.5, 0.75, 1.0];
    let base = V3::new(0.9f32, 0.55, 0.18);
    let img = render::spheres(metal.len(), rough.len(), cell, V3::splat(BACKDROP), |p| {
        gltf(env, t, p, base, metal[p.row], rough[p.col], true)
    });
    Chart {
        title: "glTF metallic-roughness material, base colour (0.9, 0.55, 0.18)".into(),
        rgb: render::display(&img, EXPOSURE, Some(&OPERATOR)),
        w: img.w,
        h: img.h,
        rows: labels("metallic", &metal),
        cols: labels("roughness", &rough),
    }
}

/// Single scattering against the compensated material, for a white dielectric, a gold-like
/// metal and a white metal (F0 = 1, where the missing energy is all the darkening).
pub fn multiscatter_chart(env: &Env, t: &Dfg, cell: usize) -> Chart {
    let rough = [0.2f32, 0.4, 0.6, 0.8, 1.0];
    let rows: [(&str, V3<f32>, f32, bool); 6] = [
        ("white metal, single scattering", V3::splat(1.0), 1.0, false),
        ("white metal, compensated", V3::splat(1.0), 1.0, true),
        (
            "gold-coloured metal, single scattering",
            V3::new(1.0, 0.78, 0.34),
            1.0,
            false,
        ),
        (
            "gold-coloured metal, compensated",
            V3::new(1.0, 0.78, 0.34),
            1.0,
            true,
        ),
        (
            "white dielectric, single scattering",
            V3::splat(0.9),
            0.0,
            false,
        ),
        ("white dielectric, compensated", V3::splat(0.9), 0.0, true),
    ];
    let img = render::spheres(rows.len(), rough.len(), cell, V3::splat(BACKDROP), |p| {
        let (_, base, m, ms) = rows[p.row];
        gltf(env, t, p, base, m, rough[p.col], ms)
    });
    Chart {
        title: "Multiple scattering: single-scattering GGX against Fdez-Aguera (image light) + Kulla-Conty (key light)".into(),
        rgb: render::display(&img, EXPOSURE, Some(&OPERATOR)),
        w: img.w,
        h: img.h,
        rows: rows.iter().map(|r| r.0.to_string()).collect(),
        cols: labels("roughness", &rough),
    }
}

/// The single-sample image-light bug (diffuse: the environment read once along the normal;
/// specular: the mirror read lerped towards it by roughness, times Schlick's F at n.v) beside
/// the fix (SH9 irradiance; prefiltered radiance and the DFG terms).
pub fn ibl_bug_chart(env: &Env, t: &Dfg, cell: usize) -> Chart {
    let rough = [0.0f32, 0.25, 0.5, 0.75, 1.0];
    let rows: [(&str, V3<f32>, f32, bool); 4] = [
        (
            "plastic: one sample along n, lerp by roughness",
            V3::new(0.8, 0.2, 0.15),
            0.0,
            true,
        ),
        (
            "plastic: SH9 irradiance + split-sum specular",
            V3::new(0.8, 0.2, 0.15),
            0.0,
            false,
        ),
        (
            "metal: one sample, lerp by roughness",
            V3::new(0.95, 0.93, 0.88),
            1.0,
            true,
        ),
        (
            "metal: split-sum specular",
            V3::new(0.95, 0.93, 0.88),
            1.0,
            false,
        ),
    ];
    let img = render::spheres(rows.len(), rough.len(), cell, V3::splat(BACKDROP), |p| {
        let (_, base, m, bug) = rows[p.row];
        let r = rough[p.col];
        if !bug {
            return gltf(env, t, p, base, m, r, false);
        }
        let n_dot_v = p.n.dot(p.v).max(1e-4);
        let f0 = V3::splat(0.04) * (1.0 - m) + base * m;
        let mirror = env.radiance(reflect(p.v, p.n));
        let along_n = env.radiance(p.n);
        let spec = (mirror * (1.0 - r) + along_n * r) * fresnel::schlick_rgb(f0, n_dot_v);
        let diffuse = base * (1.0 - m) * along_n;
        let Ok(mat) = MetallicRoughness::new(base, m, r) else {
            return V3::splat(f32::NAN);
        };
        let n_dot_l = p.n.dot(env.light_dir).max(0.0);
        mat.eval_world(&ShadingPoint::new(p.n, p.v), env.light_dir) * env.light * n_dot_l
            + spec
            + diffuse
    });
    Chart {
        title: "Image light: one radiance sample along the normal (a common bug) against irradiance and prefiltered specular".into(),
        rgb: render::display(&img, EXPOSURE, Some(&OPERATOR)),
        w: img.w,
        h: img.h,
        rows: rows.iter().map(|r| r.0.to_string()).collect(),
        cols: labels("roughness", &rough),
    }
}

/// A light almost behind the camera (30 degrees off the view, raised 20): where rough diffuse
/// surfaces look flat (the back-scattering Oren and Nayar explain) and Lambert darkens to the
/// rim.
fn front_light() -> V3<f32> {
    let (a, e) = (30f32.to_radians(), 20f32.to_radians());
    V3::new(a.sin() * e.cos(), e.sin(), a.cos() * e.cos())
}

/// Lambert against the Oren-Nayar family over sigma.
pub fn oren_nayar_chart(cell: usize) -> Chart {
    let sigma = [0.0f32, 0.25, 0.5, 0.75, 1.0];
    type Lobe = fn(f32, f32, f32, f32, f32) -> f32;
    let rows: [(&str, Lobe); 5] = [
        ("Lambert", |nv, nl, _, rho, _| diffuse::lambert(nv, nl, rho)),
        (
            "Oren-Nayar qualitative (sigma in radians)",
            diffuse::oren_nayar,
        ),
        (
            "Oren-Nayar full, with interreflection (radians)",
            diffuse::oren_nayar_full,
        ),
        (
            "Fujii's Oren-Nayar (sigma in [0, 1])",
            diffuse::oren_nayar_fujii,
        ),
        ("EON, energy-preserving (sigma in [0, 1])", diffuse::eon),
    ];
    let rho = V3::new(0.85f32, 0.5, 0.35);
    let l = front_light();
    let img = render::spheres(rows.len(), sigma.len(), cell, V3::splat(BACKDROP), |p| {
        let (nv, nl, vl) = (p.n.dot(p.v), p.n.dot(l), p.v.dot(l));
        let f = rho.map(|r| rows[p.row].1(nv, nl, vl, r, sigma[p.col]));
        f * (3.0 * nl.max(0.0)) + rho * 0.04
    });
    Chart {
        title: "Diffuse lobes over sigma, one light 30 degrees off the view".into(),
        rgb: render::display(&img, 1.0, Some(&OPERATOR)),
        w: img.w,
        h: img.h,
        rows: rows.iter().map(|r| r.0.to_string()).collect(),
        cols: labels("sigma", &sigma),
    }
}

/// Classic Phong against normalized Phong over the exponent, over a Lambert base.
pub fn phong_chart(cell: usize) -> Chart {
    let n = [1.0f32, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0];
    let l = V3::new(-0.5f32, 0.6, 0.62).normalize();
    let kd = V3::new(0.25f32, 0.35, 0.6);
    let img = render::spheres(2, n.len(), cell, V3::splat(BACKDROP), |p| {
        let (nv, nl) = (p.n.dot(p.v), p.n.dot(l));
        let r_dot_l = 2.0 * nv * nl - p.v.dot(l);
        let ks = 0.5;
        let s = if p.row == 0 {
            phong::classic(nv, nl, r_dot_l, ks, n[p.col])
        } else {
            phong::normalized(nv, nl, r_dot_l, ks, n[p.col])
        };
        let f = kd * (1.0 / PI) + V3::splat(s);
        f * (3.0 * nl.max(0.0)) + kd * 0.05
    });
    Chart {
        title: "Phong over the exponent n: classic (ks r.l^n / n.l) against normalized (ks (n + 2) / (2 pi) r.l^n), ks = 0.5".into(),
        rgb: render::display(&img, 1.0, Some(&OPERATOR)),
        w: img.w,
        h: img.h,
        rows: vec!["classic Phong".into(), "normalized Phong".into()],
        cols: labels("n =", &n),
    }
}

/// The directional albedo of a furnace material at a view direction (local frame), f64.
type Albedo = Box<dyn Fn(V3<f64>) -> f64>;

/// The albedo of a furnace row at a perceptual roughness; `None` for an invalid one.
type MakeAlbedo = fn(f64) -> Option<Albedo>;

/// The albedo of a BRDF: its integral over the upper hemisphere
/// ([`directional_albedo_with`]).
fn hemisphere(f: impl Fn(V3<f64>, V3<f64>) -> f64 + 'static) -> Option<Albedo> {
    Some(Box::new(move |wo| {
        directional_albedo_with(wo, &f, &super::ALBEDO_TOL).value
    }))
}

/// Index of refraction of the glass row.
const GLASS_ETA: f64 = 1.5;

/// The layered white material of the furnace: a white metal under a full clearcoat as rough
/// as the base.
fn layered_white(r: f64, compensate: bool) -> Option<Albedo> {
    let m = Layered::new(V3::splat(1.0), 1.0, r)
        .ok()?
        .with_clearcoat(1.0, r)
        .ok()?
        .with_compensation(compensate);
    hemisphere(move |o, i| m.eval(o, i).y)
}

/// Rows of the white furnace: a name and, per roughness column, the albedo at a view
/// direction.
fn furnace_rows() -> Vec<(&'static str, MakeAlbedo)> {
    vec![
        ("GGX conductor, F = 1, single scattering", |r| {
            let g = Ggx::isotropic(alpha_from_perceptual(r)).ok()?;
            hemisphere(move |o, i| cook_torrance::eval(&g, o, i, |_| 1.0))
        }),
        ("GGX conductor, F = 1, + Kulla-Conty", |r| {
            let a = alpha_from_perceptual(r);
            let g = Ggx::isotropic(a).ok()?;
            hemisphere(move |o, i| {
                cook_torrance::eval(&g, o, i, |_| 1.0) + energy::kulla_conty_ggx(o.z, i.z, a, 1.0)
            })
        }),
        ("glTF material, white metal", |r| {
            let m = MetallicRoughness::new(V3::splat(1.0), 1.0, r).ok()?;
            hemisphere(move |o, i| m.eval(o, i).y)
        }),
        ("layered: white metal + clearcoat 1", |r| {
            layered_white(r, false)
        }),
        ("layered: the same + per-lobe compensation", |r| {
            layered_white(r, true)
        }),
        (
            "rough glass (GGX, eta 1.5): reflection + transmission, whole sphere",
            |r| {
                // The view outside, the glass below: the integral over the whole sphere, the
                // environment behind seen through the interface. Inside a non-absorbing body in a
                // furnace the radiance is eta^2 (radiance / n^2 is what travels unchanged), which
                // turns the radiance BTDF's 1 / eta^2 into the importance form: the pixel is the
                // importance albedo, 1 for a surface that keeps all the light.
                let g = Ggx::isotropic(alpha_from_perceptual(r)).ok()?;
                Some(Box::new(move |wo: V3<f64>| {
                    let s2 = (wo.x * wo.x + wo.y * wo.y) / (GLASS_ETA * GLASS_ETA);
                    let refracted = V3::new(
                        -wo.x / GLASS_ETA,
                        -wo.y / GLASS_ETA,
                        -(1.0 - s2).max(0.0).sqrt(),
                    );
                    let f =
                        |o, i| rough_dielectric::eval(&g, o, i, GLASS_ETA, Transport::Importance);
                    directional_albedo_sphere(wo, f, &[refracted]).value
                }))
            },
        ),
        ("EON diffuse, rho = 1 (sigma = roughness)", |r| {
            let e = diffuse::Eon::new(1.0, r).ok()?;
            hemisphere(move |o, i| e.eval(o, i))
        }),
    ]
}

/// White furnace: every sphere lit by radiance 1 from everywhere, so each pixel shows the
/// directional albedo at its n.v (tabulated at 16 values of n.v and read linearly): over the
/// hemisphere for the opaque rows, over the whole sphere for the glass
/// ([`directional_albedo_sphere`]). A sphere that neither loses nor creates energy vanishes.
pub fn furnace_chart(cell: usize) -> Chart {
    let rough = [0.2f64, 0.4, 0.6, 0.8, 1.0];
    let rows = furnace_rows();
    const NODES: usize = 16;
    let mu = |j: usize| (j as f64 / (NODES - 1) as f64).max(0.02);
    let albedo: Vec<Vec<[f64; NODES]>> = rows
        .iter()
        .map(|(_, make)| {
            rough
                .iter()
                .map(|&r| {
                    let Some(e) = make(r) else {
                        return [f64::NAN; NODES];
                    };
                    core::array::from_fn(|j| {
                        let m = mu(j);
                        e(V3::new((1.0 - m * m).sqrt(), 0.0, m))
                    })
                })
                .collect()
        })
        .collect();
    let img = render::spheres(rows.len(), rough.len(), cell, V3::splat(1.0), |p| {
        let m = f64::from(p.n.dot(p.v).clamp(0.0, 1.0)) * (NODES - 1) as f64;
        let j = (m.floor() as usize).min(NODES - 2);
        let t = m - j as f64;
        let a = &albedo[p.row][p.col];
        V3::splat((a[j] * (1.0 - t) + a[j + 1] * t) as f32)
    });
    Chart {
        title:
            "White furnace: radiance 1 from every direction; a sphere that keeps energy vanishes"
                .into(),
        rgb: render::display(&img, 0.5, None),
        w: img.w,
        h: img.h,
        rows: rows.iter().map(|r| r.0.to_string()).collect(),
        cols: rough.iter().map(|r| format!("roughness {r}")).collect(),
    }
}

/// The HDR scene of the tonemap strip: the environment through a pinhole camera looking
/// towards the sun's glow, with a glossy and a rough sphere in front (the key light's
/// highlight is the brightest thing in it).
pub fn tonemap_scene(env: &Env, t: &Dfg, (w, h): (usize, usize)) -> render::Hdr {
    let fwd = V3::new(env.light_dir.x, 0.12, env.light_dir.z).normalize();
    let right = fwd.cross(V3::new(0.0, 1.0, 0.0)).normalize();
    let up = right.cross(fwd);
    let focal = 0.5 * w as f32 / (50f32.to_radians()).tan();
    let mut px = Vec::with_capacity(w * h);
    let spheres = [
        (0.3f32, 0.05f32, V3::new(0.95f32, 0.93, 0.88), 1.0f32),
        (0.7, 0.5, V3::new(0.8, 0.2, 0.15), 0.0),
    ];
    let rad = 0.19 * h as f32;
    for y in 0..h {
        for x in 0..w {
            let (fx, fy) = (x as f32 + 0.5, y as f32 + 0.5);
            let mut c = None;
            for &(cx, rough, base, metal) in &spheres {
                let (dx, dy) = ((fx - cx * w as f32) / rad, -(fy - 0.62 * h as f32) / rad);
                let r2 = dx * dx + dy * dy;
                if r2 < 1.0 {
                    // The sphere seen orthographically from the camera: its normal in
                    // camera space, turned into the world.
                    let nz = (1.0 - r2).sqrt();
                    let n = right * dx + up * dy - fwd * nz;
                    let p = Px {
                        n,
                        v: -fwd,
                        row: 0,
                        col: 0,
                    };
                    c = Some(gltf(env, t, &p, base, metal, rough, true));
                }
            }
            px.push(c.unwrap_or_else(|| {
                let d = (fwd * focal + right * (fx - 0.5 * w as f32) - up * (fy - 0.5 * h as f32))
                    .normalize();
                env.radiance(d)
            }));
        }
    }
    render::Hdr { w, h, px }
}
