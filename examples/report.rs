//! The main job: prints the crate's report (the integrators on known integrals, the lane paths
//! against scalar, NDF normalization, Smith's weak furnace, the Cook-Torrance energy loss, the
//! approximations' errors, the tonemapping operators, the diffuse lobes' albedo, the Phong
//! comparison, the metallic-roughness white furnace, the light falloffs, image-based lighting
//! and multiple-scattering compensation) and writes its images to `out/`:
//!
//! - `out/spheres.png`: Cook-Torrance GGX spheres, roughness 0.05 to 1, a dielectric (eta 1.5
//!   over a red Lambertian base) and gold, rendered eight pixels at a time on `f32x8` lanes,
//!   tonemapped with ACES (Hill) and sRGB-encoded;
//! - `out/energy_loss.png`: 1 - albedo of GGX Cook-Torrance with F = 1 over (alpha, theta_o);
//! - `out/tonemap_curves.png`: every tonemapping operator on a grey ramp, log input axis.
//!
//! Run: `cargo run --release --example report`.

#[path = "report_sections/ibl.rs"]
mod ibl_section;
#[path = "report_sections/lobes.rs"]
mod lobes;
#[path = "report_sections/tonemap.rs"]
mod tonemap_section;

use brdf::cook_torrance;
use brdf::frame::Frame;
use brdf::ggx::{self, Ggx};
use brdf::integrate::{self, Config, Estimate};
use brdf::microfacet::Microfacet;
use brdf::tonemap::{AgxLook, Operator};
use brdf::wide::f32x8;
use brdf::{Real, V3, beckmann, color, fresnel};
use core::f64::consts::PI;
use glam::DVec3;
use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

fn row(name: &str, e: Estimate, exact: f64) {
    println!(
        "| {name:<34} | {:>15.12} | {:>15.12} | {:>9.2e} | {:>9.2e} | {:>7} |",
        e.value,
        exact,
        (e.value - exact).abs(),
        e.error,
        e.evaluations
    );
}

fn integrator_checks() {
    println!("## Integrators on known integrals (default budget)\n");
    println!("| integrand | estimate | exact | actual err | reported | evals |");
    println!("|---|---|---|---|---|---|");
    let cfg = Config::default();
    row("cos(theta)", integrate::hemisphere(|w| w.z, &[], &cfg), PI);
    for n in [1.0, 10.0, 100.0, 1000.0, 10000.0] {
        row(
            &format!("cos^{n}(theta)"),
            integrate::hemisphere(|w| w.z.powf(n), &[], &cfg),
            2.0 * PI / (n + 1.0),
        );
    }
    for rho in [0.18, 1.0] {
        let wo = DVec3::new(0.6, 0.0, 0.8);
        row(
            &format!("Lambert albedo, rho = {rho}"),
            integrate::directional_albedo(wo, |_, _| rho / PI),
            rho,
        );
    }
    let n = 10_000.0;
    let wo = DVec3::new(0.6, 0.0, 0.8);
    let r = DVec3::new(-wo.x, -wo.y, wo.z);
    row(
        "Phong n=1e4 about mirror, 37 deg",
        integrate::directional_albedo(wo, |_, wi| {
            (n + 2.0) / (2.0 * PI) * r.dot(wi).max(0.0).powf(n)
        }),
        wo.z,
    );
    let classic = integrate::reciprocity(|a, b| {
        let r = DVec3::new(-a.x, -a.y, a.z);
        r.dot(b).max(0.0).powi(4) / b.z
    });
    println!(
        "\nreciprocity of classic Phong (1 / n.l factor): max relative asymmetry {:.3} over {} pairs",
        classic.max_rel, classic.pairs
    );
}

fn lane_checks() {
    println!("\n## Lanes against scalar (f32x8 vs f32, 100 000 points in [-10, 10])\n");
    println!("| function | max ULP |");
    println!("|---|---|");
    type Pair = (&'static str, fn(f32) -> f32, fn(f32x8) -> f32x8);
    let fns: [Pair; 6] = [
        ("exp", Real::exp, Real::exp),
        ("ln", Real::ln, Real::ln),
        ("sin", Real::sin, Real::sin),
        ("atan", Real::atan, Real::atan),
        ("erf", Real::erf, Real::erf),
        ("sqrt", Real::sqrt, Real::sqrt),
    ];
    for (name, s, l) in fns {
        let mut worst = 0u32;
        for k in 0..100_000 / 8 {
            let v = f32x8::from_fn(|i| -10.0 + 20.0 * (8 * k + i) as f32 / 100_000.0);
            for i in 0..8 {
                let (a, b) = (l(v).lane(i), s(v.lane(i)));
                if !(a.is_nan() && b.is_nan()) {
                    worst =
                        worst.max((a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs() as u32);
                }
            }
        }
        println!("| {name} | {worst} |");
    }
}

fn microfacet_checks() {
    println!("\n## NDF normalization: integral of D(m) cos(theta_m) dm (should be 1)\n");
    println!("| alpha_x x alpha_y | GGX | Beckmann |");
    println!("|---|---|---|");
    for (ax, ay) in [
        (0.01, 0.01),
        (0.1, 0.1),
        (0.5, 0.5),
        (1.0, 1.0),
        (1.0, 0.01),
        (0.5, 0.05),
    ] {
        let g = Ggx::new(ax, ay).expect("valid alpha");
        let b = beckmann::Beckmann::new(ax, ay).expect("valid alpha");
        let eg = integrate::ndf_projected_area(|m| g.d(V3::from(m)));
        let eb = integrate::ndf_projected_area(|m| b.d(V3::from(m)));
        println!("| {ax} x {ay} | {:.9} | {:.9} |", eg.value, eb.value);
    }
    println!("\n## Smith weak white furnace (should be 1)\n");
    println!("| alpha | theta_o | GGX | Beckmann |");
    println!("|---|---|---|---|");
    for alpha in [0.01, 0.2, 1.0] {
        let g = Ggx::new(alpha, alpha).expect("valid alpha");
        let b = beckmann::Beckmann::new(alpha, alpha).expect("valid alpha");
        for deg in [0.0f64, 60.0, 89.0, 89.9] {
            let t = deg.to_radians();
            let wo = DVec3::new(t.sin(), 0.0, t.cos());
            let (g1g, g1b) = (g.g1(V3::from(wo)), b.g1(V3::from(wo)));
            let eg = integrate::smith_weak_furnace(wo, |m| g.d(V3::from(m)), |_, _| g1g);
            let eb = integrate::smith_weak_furnace(wo, |m| b.d(V3::from(m)), |_, _| g1b);
            println!("| {alpha} | {deg} | {:.7} | {:.7} |", eg.value, eb.value);
        }
    }
}

const LOSS_ALPHAS: [f64; 8] = [0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0];
const LOSS_THETAS: [f64; 8] = [0.0, 20.0, 40.0, 60.0, 70.0, 80.0, 85.0, 89.0];

/// 1 - albedo of GGX Cook-Torrance with F = 1, over (alpha, theta_o); printed and returned.
fn energy_loss() -> Vec<Vec<f64>> {
    println!(
        "\n## Energy: 1 - directional albedo of GGX Cook-Torrance with F = 1 (the single-scattering loss)\n"
    );
    print!("| alpha \\ theta_o |");
    for t in LOSS_THETAS {
        print!(" {t} |");
    }
    println!();
    println!("|---|{}", "---|".repeat(LOSS_THETAS.len()));
    let mut table = Vec::new();
    for a in LOSS_ALPHAS {
        let g = Ggx::new(a, a).expect("valid alpha");
        print!("| {a} |");
        let mut row = Vec::new();
        for t in LOSS_THETAS {
            let t = t.to_radians();
            let wo = DVec3::new(t.sin(), 0.0, t.cos());
            let rho = integrate::directional_albedo(wo, |o, i| {
                cook_torrance::eval(&g, V3::from(o), V3::from(i), |_| 1.0)
            })
            .value;
            print!(" {:.4} |", 1.0 - rho);
            row.push(1.0 - rho);
        }
        println!();
        table.push(row);
    }
    table
}

fn approximation_errors() {
    println!("\n## Approximations against exact forms (max over the grid)\n");
    let mut hammon: f64 = 0.0;
    let mut schlick_v: f64 = 0.0;
    for ia in 1..=50 {
        let a = ia as f64 / 50.0;
        for iv in 1..=50 {
            for il in 1..=50 {
                let (v, l) = (iv as f64 / 50.0, il as f64 / 50.0);
                let exact = ggx::v_correlated(v, l, a);
                hammon = hammon.max((ggx::v_correlated_hammon(v, l, a) - exact).abs() / exact);
                schlick_v = schlick_v
                    .max((ggx::v_schlick(v, l, ggx::schlick_k_ibl(a)) - exact).abs() / exact);
            }
        }
    }
    let mut schlick_f: f64 = 0.0;
    let mut walter: f64 = 0.0;
    for i in 0..=1000 {
        let c = i as f64 / 1000.0;
        schlick_f = schlick_f.max(
            (fresnel::schlick(fresnel::f0_from_ior(1.5), c) - fresnel::dielectric(c, 1.5)).abs(),
        );
        if c > 0.0 {
            for ia in 1..=20 {
                let a = ia as f64 / 20.0;
                let e = beckmann::g1(c, a);
                walter = walter.max((1.0 / (1.0 + beckmann::lambda_walter(c, a)) - e).abs() / e);
            }
        }
    }
    println!("| approximation | of | max error |");
    println!("|---|---|---|");
    println!("| Hammon 2017 (= Filament fast) | GGX height-correlated V | {hammon:.3} relative |");
    println!(
        "| Schlick-GGX k = alpha/2, separable | GGX height-correlated V | {schlick_v:.3} relative |"
    );
    println!("| Walter 2007 rational Lambda | Beckmann G1 | {walter:.5} relative |");
    println!("| Schlick | dielectric Fresnel, eta 1.5 | {schlick_f:.4} absolute |");
    println!("\nRun time of each against its exact form: `cargo bench --bench approximations`.");
}

fn tonemap_table() {
    println!("\n## Tonemapping operators on grey input (display-linear output)\n");
    let inputs = [0.0, 0.18, 1.0, 4.0, 16.0, 1e3, f64::INFINITY];
    print!("| operator |");
    for x in inputs {
        print!(" {x} |");
    }
    println!();
    println!("|---|{}", "---|".repeat(inputs.len()));
    for op in Operator::all() {
        print!("| {} |", op_name(&op));
        for x in inputs {
            print!(" {:.4} |", op.apply(V3::splat(x)).y);
        }
        println!();
    }
}

fn op_name(op: &Operator) -> String {
    match op {
        Operator::AgxMinimal(look) | Operator::AgxFilament(look) if *look != AgxLook::BASE => {
            let which = if matches!(op, Operator::AgxMinimal(_)) {
                "AgxMinimal"
            } else {
                "AgxFilament"
            };
            let name = if *look == AgxLook::PUNCHY {
                "punchy"
            } else {
                "golden"
            };
            format!("{which} {name}")
        }
        _ => format!("{op:?}")
            .split('(')
            .next()
            .unwrap_or("?")
            .to_string(),
    }
}

/// An 8-bit RGB image.
struct Image {
    w: usize,
    h: usize,
    px: Vec<u8>,
}

impl Image {
    fn new(w: usize, h: usize, bg: [u8; 3]) -> Self {
        Self {
            w,
            h,
            px: bg.iter().copied().cycle().take(w * h * 3).collect(),
        }
    }
    fn set(&mut self, x: usize, y: usize, c: [u8; 3]) {
        if x < self.w && y < self.h {
            let i = 3 * (y * self.w + x);
            self.px[i..i + 3].copy_from_slice(&c);
        }
    }
    fn save(&self, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
        let mut enc = png::Encoder::new(
            BufWriter::new(File::create(path)?),
            self.w as u32,
            self.h as u32,
        );
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.write_header()?.write_image_data(&self.px)?;
        Ok(())
    }
}

fn quantize(x: f32) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// Cook-Torrance spheres on f32x8 lanes: 8 pixels per evaluation.
fn render_spheres() -> Image {
    const S: usize = 128;
    let roughness = [0.05f32, 0.2, 0.4, 0.6, 0.8, 1.0];
    let mut img = Image::new(S * roughness.len(), 2 * S, [24, 24, 28]);
    let light = V3::new(-0.45f32, 0.55, 0.7);
    let light = light * light.length().recip();
    let view = V3::new(0.0f32, 0.0, 1.0);
    let splat = |v: V3<f32>| V3::new(f32x8::splat(v.x), f32x8::splat(v.y), f32x8::splat(v.z));
    let (l_w, v_w) = (splat(light), splat(view));
    let base = V3::new(f32x8::splat(0.6), f32x8::splat(0.08), f32x8::splat(0.05));
    let gold_eta = V3::new(
        f32x8::splat(0.143),
        f32x8::splat(0.374),
        f32x8::splat(1.442),
    );
    let gold_k = V3::new(
        f32x8::splat(3.983),
        f32x8::splat(2.385),
        f32x8::splat(1.603),
    );
    let tonemap = Operator::AcesHill;
    for (col, &r) in roughness.iter().enumerate() {
        let alpha = brdf::microfacet::alpha_from_perceptual(f32x8::splat(r));
        let Ok(dist) = Ggx::isotropic(alpha) else {
            continue;
        };
        for row in 0..2 {
            for py in 0..S {
                for px0 in (0..S).step_by(8) {
                    // Sphere normal at each of 8 pixels.
                    let x = f32x8::from_fn(|i| ((px0 + i) as f32 + 0.5) / S as f32 * 2.0 - 1.0);
                    let y = f32x8::splat(1.0 - (py as f32 + 0.5) / S as f32 * 2.0);
                    let r2 = x * x + y * y;
                    let inside = r2.simd_lt(f32x8::splat(0.92 * 0.92));
                    let z = (f32x8::splat(0.92 * 0.92) - r2).sqrt_nonneg();
                    let n = V3::new(x, y, z).normalize_or(V3::unit_z());
                    let frame = Frame::from_normal(n);
                    let (wo, wi) = (frame.to_local(v_w), frame.to_local(l_w));
                    let n_dot_l = wi.z.max(f32x8::ZERO);
                    let radiance = if row == 0 {
                        // Dielectric coat over a red Lambertian base, diffuse weighted by 1 - F.
                        let spec = cook_torrance::dielectric(&dist, wo, wi, f32x8::splat(1.5));
                        let kd = f32x8::ONE - fresnel::dielectric(wo.z, f32x8::splat(1.5));
                        let diffuse = base * (kd * f32x8::FRAC_1_PI);
                        let f = diffuse + V3::splat(spec);
                        f * (f32x8::splat(3.0) * n_dot_l) + base * f32x8::splat(0.03)
                    } else {
                        let f = cook_torrance::eval_rgb(&dist, wo, wi, |c| {
                            fresnel::conductor_rgb(c, gold_eta, gold_k)
                        });
                        let ambient =
                            fresnel::conductor_rgb(wo.z, gold_eta, gold_k) * f32x8::splat(0.05);
                        f * (f32x8::splat(3.0) * n_dot_l) + ambient
                    };
                    let display = color::srgb_oetf_rgb(tonemap.apply(radiance));
                    for i in 0..8 {
                        if inside.lane(i) != 0.0 {
                            let c = display.lane(i);
                            img.set(
                                col * S + px0 + i,
                                row * S + py,
                                [quantize(c.x), quantize(c.y), quantize(c.z)],
                            );
                        }
                    }
                }
            }
        }
    }
    img
}

/// The energy-loss table as a heat map: cells 40 px, black = 0, white = 0.75.
fn loss_image(table: &[Vec<f64>]) -> Image {
    const C: usize = 40;
    let mut img = Image::new(C * LOSS_THETAS.len(), C * LOSS_ALPHAS.len(), [0, 0, 0]);
    for (ia, row) in table.iter().enumerate() {
        for (it, &loss) in row.iter().enumerate() {
            let v = (loss / 0.75).clamp(0.0, 1.0) as f32;
            // A simple perceptual-ish ramp: black -> orange -> white.
            let c = [
                quantize(color::srgb_oetf(v.min(1.0) * 1.6)),
                quantize(color::srgb_oetf(v * v)),
                quantize(color::srgb_oetf(v * v * v)),
            ];
            for y in 0..C {
                for x in 0..C {
                    img.set(it * C + x, ia * C + y, c);
                }
            }
        }
    }
    img
}

fn curves_image() -> Image {
    let (w, h) = (640usize, 400usize);
    let mut img = Image::new(w, h, [250, 250, 250]);
    // Axes: log10 input from -3 to 2, encoded output 0..1.
    for x in 0..w {
        img.set(x, h - 1, [0, 0, 0]);
    }
    for d in 0..=5 {
        let x = d * (w - 1) / 5;
        for y in 0..h {
            img.set(x, y, [200, 200, 200]);
        }
    }
    // One colour per operator (cycled if the list grows past it).
    let palette: [[u8; 3]; 19] = [
        [31, 119, 180],
        [255, 127, 14],
        [44, 160, 44],
        [214, 39, 40],
        [148, 103, 189],
        [140, 86, 75],
        [227, 119, 194],
        [127, 127, 127],
        [188, 189, 34],
        [23, 190, 207],
        [0, 0, 0],
        [90, 60, 0],
        [200, 0, 90],
        [0, 90, 200],
        [255, 187, 120],
        [152, 223, 138],
        [255, 152, 150],
        [197, 176, 213],
        [196, 156, 148],
    ];
    for (k, op) in Operator::all().iter().enumerate() {
        let mut prev: Option<usize> = None;
        for x in 0..w {
            let input = 10f32.powf(-3.0 + 5.0 * x as f32 / (w - 1) as f32);
            let out = color::srgb_oetf(op.apply(V3::splat(input)).y);
            let y = ((1.0 - out) * (h - 1) as f32).round() as usize;
            let (lo, hi) = match prev {
                Some(p) => (p.min(y), p.max(y)),
                None => (y, y),
            };
            for yy in lo..=hi {
                img.set(x, yy, palette[k % palette.len()]);
            }
            prev = Some(y);
        }
    }
    img
}

/// The per-function ULP table against the correctly rounded MPFR oracle. Measuring it needs
/// GMP and MPFR (the `brdf-oracle` workspace member); `.ci/run` re-measures it on every run
/// and fails if this committed copy differs, so what the report prints is current.
fn accuracy_table() {
    println!("\n## Exact functions against the correctly rounded oracle (max ULP)\n");
    print!("{}", include_str!("../docs/accuracy.md"));
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("# brdf report\n");
    integrator_checks();
    lane_checks();
    accuracy_table();
    microfacet_checks();
    let loss = energy_loss();
    approximation_errors();
    tonemap_table();
    tonemap_section::peers_table();
    lobes::diffuse_albedo()?;
    lobes::phong_comparison()?;
    lobes::material_furnace()?;
    lobes::light_falloffs();
    ibl_section::dfg_section();
    ibl_section::irradiance_section();
    ibl_section::energy_section();
    let out = Path::new("out");
    std::fs::create_dir_all(out)?;
    render_spheres().save(&out.join("spheres.png"))?;
    loss_image(&loss).save(&out.join("energy_loss.png"))?;
    curves_image().save(&out.join("tonemap_curves.png"))?;
    println!("\nImages: out/spheres.png, out/energy_loss.png, out/tonemap_curves.png");
    Ok(())
}
