//! The thin film's colour over its thickness as a picture: one strip per base and view angle,
//! thickness along a labelled axis in nm.

use std::error::Error;
use std::path::Path;

use brdf::V3;
use brdf::iridescence::{self, ThinFilm, XYZ_TO_REC709};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontDesc, FontFamily, FontStyle};

type Res<T = ()> = Result<T, Box<dyn Error>>;

/// The thickest film drawn: past about 1 micron the film's colours wash out to the base's
/// white-ish average (the fringes get finer than the eye's colour matching functions).
pub const MAX_NM: f64 = 1200.0;

/// The family `plot::register_fonts` registers the bundled DejaVu Sans under.
const FAMILY: &str = "DejaVu Sans (report)";

/// One strip: its caption and the film's XYZ at a thickness.
struct Row {
    caption: String,
    xyz: Box<dyn Fn(f64) -> V3<f64>>,
}

/// The strips: a soap-like film (n 1.33) on glass (n 1.5) and an oxide-like film (n 2.0) on
/// an aluminium-like conductor (1.1 + 6.8i), each from air at 0, 45 and 70 degrees.
fn rows() -> Vec<Row> {
    let mut r = Vec::new();
    for deg in [0.0_f64, 45.0, 70.0] {
        let c = deg.to_radians().cos();
        r.push(Row {
            caption: format!("soap film on glass, {deg} deg"),
            xyz: Box::new(move |d| {
                ThinFilm::new(d, 1.33)
                    .map(|f| iridescence::dielectric(&f, 1.0, 1.5, c))
                    .unwrap_or(V3::new(f64::NAN, f64::NAN, f64::NAN))
            }),
        });
    }
    for deg in [0.0_f64, 45.0, 70.0] {
        let c = deg.to_radians().cos();
        r.push(Row {
            caption: format!("oxide on metal, {deg} deg"),
            xyz: Box::new(move |d| {
                ThinFilm::new(d, 2.0)
                    .map(|f| iridescence::conductor(&f, 1.0, 1.1, 6.8, c))
                    .unwrap_or(V3::new(f64::NAN, f64::NAN, f64::NAN))
            }),
        });
    }
    r
}

/// sRGB-encoded 8-bit value of a linear channel, clamped to [0, 1]; NaN shows as 0.
fn srgb8(x: f64) -> u8 {
    let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
    let e = if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    };
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let v = (e * 255.0).round() as u8;
    v
}

/// XYZ (equal-energy white) to linear Rec.709 through `XYZ_TO_REC709`.
fn rec709(xyz: V3<f64>) -> [f64; 3] {
    let m = XYZ_TO_REC709;
    [0, 1, 2].map(|r| m[r][0] * xyz.x + m[r][1] * xyz.y + m[r][2] * xyz.z)
}

/// Writes `iridescence_strip.png` into `dir` and returns its name.
///
/// # Errors
/// The fonts do not register, or the PNG cannot be drawn or written.
pub fn strip(dir: &Path) -> Res<String> {
    crate::plot::register_fonts();
    let name = "iridescence_strip.png";
    let rows = rows();
    // Layout in pixels: captions on the left, one pixel column per nm step.
    let (left, right, top, strip_h, gap) = (300_i32, 30_i32, 60_i32, 44_i32, 10_i32);
    let plot_w = 1000_i32;
    let n = i32::try_from(rows.len())?;
    let axis_top = top + n * (strip_h + gap);
    let (w, h) = (left + plot_w + right, axis_top + 80);
    let (wu, hu) = (u32::try_from(w)?, u32::try_from(h)?);
    let mut buf = vec![0u8; 3 * wu as usize * hu as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (wu, hu)).into_drawing_area();
        root.fill(&WHITE)?;
        let text = RGBColor(20, 20, 20);
        let font = |size: f64, style| FontDesc::new(FontFamily::Name(FAMILY), size, style);
        let at = |h, v| {
            TextStyle::from(font(17.0, FontStyle::Normal))
                .color(&text)
                .pos(Pos::new(h, v))
        };
        root.draw_text(
            "Thin-film iridescence over film thickness (Belcour and Barla 2017), sRGB",
            &TextStyle::from(font(22.0, FontStyle::Bold))
                .color(&text)
                .pos(Pos::new(HPos::Center, VPos::Top)),
            (w / 2, 16),
        )?;
        for (i, row) in rows.iter().enumerate() {
            let y0 = top + i32::try_from(i)? * (strip_h + gap);
            let rgb: Vec<[f64; 3]> = (0..plot_w)
                .map(|px| {
                    rec709((row.xyz)(
                        MAX_NM * (f64::from(px) + 0.5) / f64::from(plot_w),
                    ))
                })
                .collect();
            // Each row at its own exposure, its brightest channel at 1: a dielectric reflects
            // a few percent head-on and a quarter at grazing, which one exposure cannot show.
            let peak = rgb.iter().flatten().fold(0.0_f64, |m, &v| m.max(v));
            let exposure = if peak > 0.0 { 1.0 / peak } else { 1.0 };
            for (px, c) in (0..plot_w).zip(&rgb) {
                let [r, g, b] = c.map(|v| srgb8(v * exposure));
                let c = RGBColor(r, g, b);
                root.draw(&Rectangle::new(
                    [(left + px, y0), (left + px + 1, y0 + strip_h)],
                    c.filled(),
                ))?;
            }
            root.draw_text(
                &format!("{} (x{exposure:.2})", row.caption),
                &at(HPos::Right, VPos::Center),
                (left - 12, y0 + strip_h / 2),
            )?;
        }
        // The thickness axis under the strips, ticks every 100 nm.
        root.draw(&PathElement::new(
            [(left, axis_top), (left + plot_w, axis_top)],
            text.stroke_width(1),
        ))?;
        for k in 0..=12 {
            let x = left + plot_w * k / 12;
            root.draw(&PathElement::new(
                [(x, axis_top), (x, axis_top + 6)],
                text.stroke_width(1),
            ))?;
            root.draw_text(
                &format!("{}", 100 * k),
                &at(HPos::Center, VPos::Top),
                (x, axis_top + 9),
            )?;
        }
        root.draw_text(
            "film thickness (nm)",
            &at(HPos::Center, VPos::Top),
            (left + plot_w / 2, axis_top + 40),
        )?;
        root.present()?;
    }
    let file = std::io::BufWriter::new(std::fs::File::create(dir.join(name))?);
    let mut enc = png::Encoder::new(file, wu, hu);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header()?;
    writer.write_image_data(&buf)?;
    writer.finish()?;
    Ok(name.into())
}
