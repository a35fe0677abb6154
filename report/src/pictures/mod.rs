//! Every picture of the report, rendered on the CPU through the crate's public API only.
//!
//! - `env.rs`: the environment (procedural sky, sun glow and ground, or a Radiance `.hdr`
//!   file), its prefiltered levels and SH9 irradiance, the key light.
//! - `hdr.rs`: the `.hdr` reader.
//! - `render.rs`: orthographic sphere grids and the display transform.
//! - `scenes.rs`: the sphere charts (material chart, multiple scattering, the single-sample
//!   image-light bug, Oren-Nayar, Phong, the white furnace) and the tonemap scene.
//! - `figures.rs`: the plots (D, G1, Fresnel, albedo against roughness).
//! - `iridescence.rs`: the thin film's colour strips over thickness.
//!
//! [`write_all`] writes them into the report folder and the report's markdown section;
//! [`docs_material_chart`] and [`docs_pareto`] render the small copies under `docs/` that
//! the README shows, which `report/tests/docs_images.rs` re-renders and compares.

mod env;
mod figures;
pub mod hdr;
mod iridescence;
mod render;
mod scenes;

use std::error::Error;
use std::path::{Path, PathBuf};

use brdf::tonemap::Operator;

use crate::plot::{self, ParetoPoint};
pub use env::Env;
use scenes::{Chart, Dfg};

type Res<T = ()> = Result<T, Box<dyn Error>>;

/// Tolerances of the pictures' albedo integrals: 1e-5, far below what an 8-bit pixel
/// (1/255) or a plotted line shows, and about 50 times faster than the integrator's default.
const ALBEDO_TOL: brdf::integrate::Config = brdf::integrate::Config {
    abs_tol: 1e-5,
    rel_tol: 1e-5,
    max_evals: 200_000,
};

/// Where the pictures' environment comes from.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// A Radiance `.hdr` equirectangular file instead of the procedural sky.
    pub env: Option<PathBuf>,
    /// Fewer integration points in the plots (the `--quick` report).
    pub quick: bool,
}

fn save_chart(dir: &Path, name: &str, c: &Chart) -> Res<String> {
    plot::labelled_grid(
        &dir.join(name),
        &c.title,
        &c.rgb,
        c.w,
        c.h,
        c.cols.len(),
        c.rows.len(),
        &c.cols,
        &c.rows,
    )?;
    Ok(name.into())
}

/// The name of an operator as the strip captions it.
pub fn operator_name(op: &Operator) -> String {
    crate::sections::checks::op_name(op)
}

/// Writes every render and plot into `dir` and their section into the report's markdown;
/// returns the file names. The Pareto plot is not here: the report draws it from its own
/// measurements.
///
/// # Errors
/// An unreadable `.hdr` file, or a picture that cannot be written.
pub fn write_all(dir: &Path, opt: &Options) -> Res<Vec<String>> {
    let t = std::time::Instant::now();
    let lap = |what: &str| eprintln!("           {what}: {:.2} s", t.elapsed().as_secs_f64());
    let env = match &opt.env {
        Some(p) => Env::from_hdr(&p.display().to_string(), &hdr::read(p)?),
        None => Env::procedural(),
    };
    lap("environment");
    let dfg = Dfg::new();
    lap("DFG table");
    // Quick mode (CI) only checks that every picture is written: smaller cells.
    let cell = if opt.quick { 80 } else { 104 };
    let mut files = Vec::new();
    outln!("\n## Pictures\n");
    outln!(
        "Rendered on the CPU by `report/src/pictures/` through the crate's public API only: \
         spheres seen orthographically, shaded per pixel, in an environment ({}) with a key \
         light. Image light: split-sum specular (prefiltered radiance from \
         `brdf::ibl::prefilter` samples, each read at its filtered-importance-sampling mip, \
         and a `brdf::ibl::dfg::table`), diffuse from SH9 irradiance \
         (`brdf::ibl::irradiance::Sh9`). Display: exposure, then `Operator::PbrNeutral` and \
         the sRGB transfer function (the furnace: no operator). `-- --env FILE.hdr` renders \
         them in a Radiance file's environment instead.\n",
        env.name
    );
    type Job<'a> = Box<dyn FnOnce() -> Chart + Send + 'a>;
    let (env, dfg) = (&env, &dfg);
    let charts: [(&str, &str, Job); 6] = [
        (
            "spheres.png",
            "The material chart: roughness across, metallic down, with multiple-scattering \
             compensation.",
            Box::new(move || scenes::material_chart(env, dfg, cell)),
        ),
        (
            "multiscatter.png",
            "Single scattering against compensation: rough metals go dark without it (single-scattering \
             GGX at roughness 1 reflects about a third of the light arriving head-on: the energy \
             section's tables); dielectrics, whose diffuse layer takes what the specular layer \
             leaves, barely change.",
            Box::new(move || scenes::multiscatter_chart(env, dfg, cell)),
        ),
        (
            "ibl_single_sample.png",
            "The single-sample image-light bug beside the fix: one radiance read along the \
             normal for diffuse, and the mirror read lerped towards it for rough specular, keep \
             the environment's sharp horizon and checks on spheres that should be smooth; \
             SH9 irradiance and the prefiltered levels blur them as the lobes do.",
            Box::new(move || scenes::ibl_bug_chart(env, dfg, cell)),
        ),
        (
            "oren_nayar.png",
            "Lambert against the Oren-Nayar family: with the light near the view, rough \
             diffuse surfaces stay bright to the rim (back-scattering); EON also keeps the \
             energy Fujii's and the qualitative models lose.",
            Box::new(move || scenes::oren_nayar_chart(cell)),
        ),
        (
            "phong.png",
            "Classic Phong's peak stays near ks however tight the lobe, so a tight lobe reflects \
             almost nothing; normalized Phong scales it by (n + 2) / (2 pi) and keeps its \
             energy, so a tight lobe is small and bright.",
            Box::new(move || scenes::phong_chart(cell)),
        ),
        (
            "furnace.png",
            "White furnace (radiance 1 everywhere, shown at half exposure, no tonemapping): \
             darker than the background is energy lost, brighter is energy created. The \
             compensated GGX and EON all but vanish; the glTF metal loses what GGX loses. \
             The layered white metal under a full clearcoat (coat as rough as the base) loses \
             GGX's share and more without compensation; with it the sphere vanishes facing the \
             view (albedo 0.97 to 1.00 at n.v = 1) but keeps a dark rim (0.17 to 0.68 at n.v = \
             0.02): the extension's coat takes 1 - F_coat(n.v) away from the base and nothing \
             returns it, a loss of the layering that compensation does not touch. The rough \
             glass integrates reflection and transmission over the whole sphere, the \
             environment behind seen through the surface; inside a clear body in a furnace the \
             radiance is eta^2 (radiance / n^2 is what travels unchanged), so each pixel is the \
             BSDF's importance albedo and a correct sphere vanishes. It nearly does: 0.93 to 1.00 \
             at roughness 0.2 (lowest at the rim), 0.70 to 0.89 at roughness 1, the light lost between microfacets \
             by single scattering (no compensation for glass here); lit by radiance 1 inside \
             instead of eta^2 it would show about R + T / 2.25, a dark sphere.",
            Box::new(move || scenes::furnace_chart(cell)),
        ),
    ];
    // One thread a chart: they share nothing but the environment, read-only.
    let done: Vec<(&str, &str, Result<String, String>)> = std::thread::scope(|sc| {
        let handles: Vec<_> = charts
            .into_iter()
            .map(|(name, text, job)| {
                let h = sc.spawn(move || {
                    let c = job();
                    save_chart(dir, name, &c)
                        .map(|_| c.title)
                        .map_err(|e| e.to_string())
                });
                (name, text, h)
            })
            .collect();
        handles
            .into_iter()
            .map(|(name, text, h)| {
                let r = h
                    .join()
                    .unwrap_or_else(|_| Err(format!("{name}: the render panicked")));
                (name, text, r)
            })
            .collect()
    });
    lap("sphere charts");
    for (name, text, title) in done {
        let title = title?;
        outln!("{text}\n\n![{title}]({name})\n");
        files.push(name.to_string());
    }

    let scene = scenes::tonemap_scene(env, dfg, (240, 135));
    let cells: Vec<(Vec<u8>, String)> = Operator::all()
        .iter()
        .map(|op| (render::display(&scene, 1.0, Some(op)), operator_name(op)))
        .chain(std::iter::once((
            render::display(&scene, 1.0, None),
            "none (clipped at 1)".to_string(),
        )))
        .collect();
    let name = "tonemap_strip.png";
    plot::captioned_cells(
        &dir.join(name),
        "One HDR scene through every tonemapping operator (exposure 1, sRGB)",
        &cells,
        (scene.w, scene.h),
        4,
    )?;
    outln!(
        "The same HDR scene (the environment towards the sun's glow, a polished metal and a \
         rough red plastic sphere) through each operator of `brdf::tonemap::Operator::all()`.\n\n\
         ![Tonemap strip]({name})\n"
    );
    files.push(name.into());

    lap("tonemap strip");
    outln!("### Plots\n");
    let quick = opt.quick;
    type Plot<'a> = Box<dyn FnOnce() -> Res<String> + Send + 'a>;
    let plots: [(&str, Plot); 5] = [
        (
            "GGX's long tail against Beckmann's fast fall-off, at equal alpha.",
            Box::new(|| figures::ndf(dir)),
        ),
        (
            "Smith masking of the two distributions.",
            Box::new(|| figures::g1(dir)),
        ),
        (
            "Exact dielectric Fresnel over eta, Schlick's approximation for eta = 1.5, and \
             three metals from their complex indices at 650, 550 and 450 nm.",
            Box::new(|| figures::fresnel_curves(dir)),
        ),
        (
            "Directional albedo (`brdf::integrate::directional_albedo`) against roughness: \
             what each lobe loses or creates.",
            Box::new(move || figures::albedo_vs_roughness(dir, quick)),
        ),
        (
            "Thin-film iridescence over film thickness (0 to 1200 nm) from air: \
             `iridescence::dielectric` (film n = 1.33 on glass, n = 1.5) and `iridescence::conductor` (film n = 2.0 on \
             1.1 + 6.8i) at 0, 45 and 70 degrees, CIE XYZ to linear Rec.709 by \
             `XYZ_TO_REC709`, each row scaled so its brightest channel is 1 (the factor in its \
             caption), sRGB-encoded. Thickness 0 is the bare base; the fringes \
             shift to thinner films as the view tilts.",
            Box::new(|| iridescence::strip(dir)),
        ),
    ];
    let drawn: Vec<(&str, Result<String, String>)> = std::thread::scope(|sc| {
        let handles: Vec<_> = plots
            .into_iter()
            .map(|(text, job)| (text, sc.spawn(move || job().map_err(|e| e.to_string()))))
            .collect();
        handles
            .into_iter()
            .map(|(text, h)| {
                (
                    text,
                    h.join().unwrap_or_else(|_| Err("a plot panicked".into())),
                )
            })
            .collect()
    });
    for (text, f) in drawn {
        let f = f?;
        outln!("{text}\n\n![{f}]({f})\n");
        files.push(f);
    }
    lap("plots");
    Ok(files)
}

/// Width of a sphere cell in the README's material chart, in pixels.
pub const DOCS_CELL: usize = 64;

/// The README's material chart (cells of [`DOCS_CELL`] pixels, procedural environment) at
/// `path`.
///
/// # Errors
/// The PNG cannot be written.
pub fn docs_material_chart(path: &Path) -> Res {
    let env = Env::procedural();
    let dfg = Dfg::new();
    let mut c = scenes::material_chart(&env, &dfg, DOCS_CELL);
    c.title = "glTF material, perceptual roughness r across".into();
    c.cols = c
        .cols
        .iter()
        .map(|s| s.replace("roughness ", "r = "))
        .collect();
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or("chart.png");
    save_chart(path.parent().unwrap_or(Path::new(".")), name, &c)?;
    Ok(())
}

/// The Pareto points as the CSV `docs/pareto.csv` keeps them: `family,form,ns,max_rel`, the
/// form in double quotes when it holds a comma or a quote (RFC 4180).
pub fn pareto_csv(points: &[ParetoPoint]) -> String {
    let mut s = String::from("family,form,ns_per_element,max_rel_error\n");
    for p in points {
        let form = if p.form.contains([',', '"']) {
            format!("\"{}\"", p.form.replace('"', "\"\""))
        } else {
            p.form.clone()
        };
        s.push_str(&format!("{},{form},{:e},{:e}\n", p.family, p.x, p.y));
    }
    s
}

/// Parses [`pareto_csv`]'s text.
///
/// # Errors
/// A line without four fields or with a number that does not parse.
pub fn parse_pareto_csv(s: &str) -> Res<Vec<ParetoPoint>> {
    s.lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            // family (no commas), form (quoted when it holds a comma), two numbers.
            let bad = || format!("pareto csv: `{l}` is not family,form,ns,error");
            let (family, rest) = l.split_once(',').ok_or_else(bad)?;
            let mut tail = rest.rsplitn(3, ',');
            let (y, x, form) = (tail.next(), tail.next(), tail.next());
            let (Some(y), Some(x), Some(form)) = (y, x, form) else {
                return Err(bad().into());
            };
            let form = match form.strip_prefix('"').and_then(|f| f.strip_suffix('"')) {
                Some(q) => q.replace("\"\"", "\""),
                None => form.to_string(),
            };
            Ok(ParetoPoint {
                family: family.into(),
                form,
                x: x.parse()?,
                y: y.parse()?,
            })
        })
        .collect()
}

/// The (family, form) pairs the report's Pareto plot draws today, in order.
pub fn pareto_forms() -> Vec<(String, String)> {
    crate::tradeoff::families()
        .iter()
        .filter(|f| f.plot)
        .flat_map(|f| {
            f.forms
                .iter()
                .map(|m| (f.name.to_string(), m.name.to_string()))
        })
        .collect()
}

/// Width of the README's Pareto plot: the report's 1400 x 900 drawing, area-averaged down.
pub const DOCS_PARETO_W: usize = 840;

/// The README's Pareto plot at `path` from `points`.
///
/// # Errors
/// The PNG cannot be drawn, read back or written.
pub fn docs_pareto(points: &[ParetoPoint], path: &Path) -> Res {
    let tmp = path.with_extension("full.png");
    plot::pareto(
        &tmp,
        "Error against run time (f32, one run)",
        "ns per element (f32x8 through batch; f32 where there is no lane path)",
        "max relative error of the f32 result",
        points,
    )?;
    let (w, h, rgb) = read_png(&tmp)?;
    std::fs::remove_file(&tmp)?;
    let (w2, h2) = (DOCS_PARETO_W, (h * DOCS_PARETO_W).div_ceil(w));
    write_png(path, w2, h2, &downsample(&rgb, (w, h), (w2, h2)))
}

/// Area-average resampling of RGB8 from `w x h` to `w2 x h2` (each output pixel the mean of
/// the input pixels it covers, partial pixels weighted), in sRGB values (text stays crisp
/// enough, and lines keep their apparent weight).
fn downsample(rgb: &[u8], (w, h): (usize, usize), (w2, h2): (usize, usize)) -> Vec<u8> {
    let (sx, sy) = (w as f64 / w2 as f64, h as f64 / h2 as f64);
    let mut out = vec![0u8; w2 * h2 * 3];
    for y2 in 0..h2 {
        let (ya, yb) = (y2 as f64 * sy, (y2 + 1) as f64 * sy);
        for x2 in 0..w2 {
            let (xa, xb) = (x2 as f64 * sx, (x2 + 1) as f64 * sx);
            let mut acc = [0f64; 3];
            let mut wsum = 0.0;
            for y in ya.floor() as usize..(yb.ceil() as usize).min(h) {
                let wy = (yb.min(y as f64 + 1.0) - ya.max(y as f64)).max(0.0);
                for x in xa.floor() as usize..(xb.ceil() as usize).min(w) {
                    let wx = (xb.min(x as f64 + 1.0) - xa.max(x as f64)).max(0.0);
                    let i = 3 * (y * w + x);
                    for k in 0..3 {
                        acc[k] += wx * wy * f64::from(rgb[i + k]);
                    }
                    wsum += wx * wy;
                }
            }
            let o = 3 * (y2 * w2 + x2);
            for k in 0..3 {
                out[o + k] = (acc[k] / wsum).round().clamp(0.0, 255.0) as u8;
            }
        }
    }
    out
}

/// Reads an 8-bit RGB PNG: (width, height, pixels).
///
/// # Errors
/// The file cannot be read or is not 8-bit RGB.
pub fn read_png(path: &Path) -> Res<(usize, usize, Vec<u8>)> {
    let dec = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path)?));
    let mut r = dec.read_info()?;
    let mut buf = vec![0; r.output_buffer_size().ok_or("png: image too large")?];
    let info = r.next_frame(&mut buf)?;
    if info.color_type != png::ColorType::Rgb || info.bit_depth != png::BitDepth::Eight {
        return Err(format!("{}: not 8-bit RGB", path.display()).into());
    }
    buf.truncate(info.buffer_size());
    Ok((info.width as usize, info.height as usize, buf))
}

/// Writes an 8-bit RGB PNG.
///
/// # Errors
/// The file cannot be written.
pub fn write_png(path: &Path, w: usize, h: usize, rgb: &[u8]) -> Res {
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut enc = png::Encoder::new(file, u32::try_from(w)?, u32::try_from(h)?);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut wr = enc.write_header()?;
    wr.write_image_data(rgb)?;
    wr.finish()?;
    Ok(())
}
