//! PNG charts for the report, drawn with `plotters` on its bitmap backend.
//!
//! Every chart function writes one PNG at the path it is given and returns an error instead of
//! panicking. Each one calls [`register_fonts`] itself, so a caller never has to: the text is set
//! in the DejaVu Sans bundled by the `dejavu` crate, and no system font is needed.
//!
//! The charts lay out their axes, ticks and legends in pixel space themselves (rather than
//! through `plotters`' chart builder), so logarithmic axes get decade ticks labelled `1e-6` or
//! `100`, lines are clipped to the plot area, and legends sit in a side panel beside the plot
//! instead of on top of the data.

use std::error::Error;
use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontDesc, FontFamily, FontStyle, FontTransform, register_font};

type Res<T = ()> = Result<T, Box<dyn Error>>;
type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

/// Draws a `w` x `h` picture with `draw` into an RGB buffer and writes it as an 8-bit RGB PNG
/// at `path` with the `png` crate (plotters' own encoder pulls in the whole `image` crate).
fn save(path: &Path, (w, h): (u32, u32), draw: impl FnOnce(&Area) -> Res) -> Res {
    let mut buf = vec![0u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        draw(&root)?;
        root.present()?;
    }
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut enc = png::Encoder::new(file, w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header()?;
    writer.write_image_data(&buf)?;
    writer.finish()?;
    Ok(())
}

/// The family name the bundled fonts are registered under, distinct from the generic
/// `sans-serif` so that nothing else registered in `plotters` collides with it.
const FAMILY: &str = "DejaVu Sans (report)";

/// Outcome of the one registration, kept so that every chart can report a failure.
static FONTS: OnceLock<Result<(), String>> = OnceLock::new();

/// Registers the bundled DejaVu Sans regular and bold faces with `plotters`.
///
/// Idempotent and cheap after the first call: the registration runs once per process. Every
/// chart function of this module calls it before drawing, so callers need not; calling it
/// early does no harm. A failure (which would mean the bundled font bytes are corrupt) is
/// remembered and returned as an error by every chart function.
pub fn register_fonts() {
    FONTS.get_or_init(|| {
        register_font(FAMILY, FontStyle::Normal, dejavu::sans::regular())
            .map_err(|_| "plotters rejected the bundled DejaVu Sans regular font".to_string())?;
        register_font(FAMILY, FontStyle::Bold, dejavu::sans::bold())
            .map_err(|_| "plotters rejected the bundled DejaVu Sans bold font".to_string())?;
        Ok(())
    });
}

/// Registers the fonts and reports whether that worked.
fn fonts_ready() -> Res {
    register_fonts();
    match FONTS.get() {
        Some(Ok(())) => Ok(()),
        Some(Err(e)) => Err(e.clone().into()),
        None => Err("font registration did not run".into()),
    }
}

// ---------------------------------------------------------------------------------------------
// Colours and markers
// ---------------------------------------------------------------------------------------------

/// 22 colours that stay distinguishable on white: Tableau 10 first, then darker and lighter
/// hues from the Tableau 20b/20c sets.
const PALETTE: [(u8, u8, u8); 22] = [
    (0x1f, 0x77, 0xb4), // blue
    (0xff, 0x7f, 0x0e), // orange
    (0x2c, 0xa0, 0x2c), // green
    (0xd6, 0x27, 0x28), // red
    (0x94, 0x67, 0xbd), // purple
    (0x8c, 0x56, 0x4b), // brown
    (0xe3, 0x77, 0xc2), // pink
    (0x7f, 0x7f, 0x7f), // grey
    (0xbc, 0xbd, 0x22), // olive
    (0x17, 0xbe, 0xcf), // cyan
    (0x00, 0x00, 0x00), // black
    (0x39, 0x3b, 0x79), // indigo
    (0xe7, 0xba, 0x52), // mustard
    (0x63, 0x79, 0x39), // moss
    (0x84, 0x3c, 0x39), // maroon
    (0x6b, 0x6e, 0xcf), // periwinkle
    (0x7b, 0x41, 0x73), // plum
    (0xff, 0x98, 0x96), // salmon
    (0x98, 0xdf, 0x8a), // light green
    (0xae, 0xc7, 0xe8), // light blue
    (0xc5, 0xb0, 0xd5), // lavender
    (0xb1, 0x59, 0x28), // rust
];

fn palette(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}

/// `c` moved towards black by the fraction `t`.
fn darken(c: RGBColor, t: f64) -> RGBColor {
    let f = |v: u8| (f64::from(v) * (1.0 - t)).round() as u8;
    RGBColor(f(c.0), f(c.1), f(c.2))
}

const GRID_MAJOR: RGBColor = RGBColor(214, 214, 214);
const GRID_MINOR: RGBColor = RGBColor(238, 238, 238);
const TEXT: RGBColor = RGBColor(20, 20, 20);
const NOTE: RGBColor = RGBColor(90, 90, 90);

/// Number of marker shapes; 7 is coprime with the palette length, so colour and shape together
/// repeat only after 154 entries.
const SHAPES: usize = 7;

fn style(c: RGBColor, width: u32, filled: bool) -> ShapeStyle {
    ShapeStyle {
        color: c.to_rgba(),
        filled,
        stroke_width: width,
    }
}

/// Draws marker `shape` (taken modulo [`SHAPES`]) of radius `r` centred at `(x, y)`.
fn marker(area: &Area, shape: usize, (x, y): (i32, i32), r: i32, c: RGBColor) -> Res {
    let fill = style(c, 1, true);
    let edge = style(darken(c, 0.45), 1, false);
    let rf = f64::from(r);
    let poly = |pts: &[(f64, f64)]| -> Vec<(i32, i32)> {
        pts.iter()
            .map(|&(dx, dy)| (x + (dx * rf).round() as i32, y + (dy * rf).round() as i32))
            .collect()
    };
    match shape % SHAPES {
        0 => {
            area.draw(&Circle::new((x, y), r, fill))?;
            area.draw(&Circle::new((x, y), r, edge))?;
        }
        1 => {
            let s = (rf * 0.85).round() as i32;
            area.draw(&Rectangle::new([(x - s, y - s), (x + s, y + s)], fill))?;
            area.draw(&Rectangle::new([(x - s, y - s), (x + s, y + s)], edge))?;
        }
        2..=4 => {
            let pts = match shape % SHAPES {
                2 => poly(&[(0.0, -1.2), (1.1, 0.75), (-1.1, 0.75)]),
                3 => poly(&[(0.0, -1.25), (1.0, 0.0), (0.0, 1.25), (-1.0, 0.0)]),
                _ => poly(&[(0.0, 1.2), (1.1, -0.75), (-1.1, -0.75)]),
            };
            area.draw(&Polygon::new(pts.clone(), fill))?;
            let mut closed = pts.clone();
            closed.extend(pts.first().copied());
            area.draw(&PathElement::new(closed, edge))?;
        }
        5 => {
            let s = (rf * 0.9).round() as i32;
            let st = style(c, 3, false);
            area.draw(&PathElement::new(vec![(x - s, y - s), (x + s, y + s)], st))?;
            area.draw(&PathElement::new(vec![(x - s, y + s), (x + s, y - s)], st))?;
        }
        _ => {
            let s = (rf * 1.15).round() as i32;
            let st = style(c, 3, false);
            area.draw(&PathElement::new(vec![(x - s, y), (x + s, y)], st))?;
            area.draw(&PathElement::new(vec![(x, y - s), (x, y + s)], st))?;
        }
    }
    Ok(())
}

/// 11 samples of matplotlib's viridis, evenly spaced over [0, 1].
const VIRIDIS: [(u8, u8, u8); 11] = [
    (0x44, 0x01, 0x54),
    (0x48, 0x24, 0x75),
    (0x41, 0x44, 0x87),
    (0x35, 0x5f, 0x8d),
    (0x2a, 0x78, 0x8e),
    (0x21, 0x91, 0x8c),
    (0x22, 0xa8, 0x84),
    (0x44, 0xbf, 0x70),
    (0x7a, 0xd1, 0x51),
    (0xbd, 0xdf, 0x26),
    (0xfd, 0xe7, 0x25),
];

/// Viridis at `t` in [0, 1] (clamped), linearly interpolated between the table's samples.
fn viridis(t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let pos = t * (VIRIDIS.len() - 1) as f64;
    let i = (pos.floor() as usize).min(VIRIDIS.len() - 2);
    let f = pos - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let lerp = |p: u8, q: u8| (f64::from(p) + (f64::from(q) - f64::from(p)) * f).round() as u8;
    RGBColor(lerp(a.0, b.0), lerp(a.1, b.1), lerp(a.2, b.2))
}

/// Black or white, whichever reads better on `c`.
fn contrast(c: RGBColor) -> RGBColor {
    let lum = 0.2126 * f64::from(c.0) + 0.7152 * f64::from(c.1) + 0.0722 * f64::from(c.2);
    if lum > 135.0 {
        RGBColor(0, 0, 0)
    } else {
        RGBColor(255, 255, 255)
    }
}

// ---------------------------------------------------------------------------------------------
// Text
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy)]
enum Ha {
    Left,
    Center,
    Right,
}

/// Vertical anchor: `Top` puts the top of the capitals at `y`, `Center` their middle, `Baseline`
/// the baseline.
#[derive(Clone, Copy)]
enum Va {
    Top,
    Center,
    Baseline,
}

/// A text face: size in pixels (ab_glyph's scale: ascent plus descent), weight and colour.
#[derive(Clone, Copy)]
struct Tf {
    size: f64,
    bold: bool,
    color: RGBColor,
}

impl Tf {
    fn new(size: f64, color: RGBColor) -> Self {
        Self {
            size,
            bold: false,
            color,
        }
    }

    fn bold(self) -> Self {
        Self { bold: true, ..self }
    }

    fn font(&self) -> FontDesc<'static> {
        let st = if self.bold {
            FontStyle::Bold
        } else {
            FontStyle::Normal
        };
        FontDesc::new(FontFamily::Name(FAMILY), self.size, st)
    }

    /// Height of a line of text from capital top to descender bottom.
    fn height(&self) -> i32 {
        (self.size * 0.85).ceil() as i32
    }

    /// Distance between the baselines of consecutive lines.
    fn line(&self) -> i32 {
        (self.size * 1.15).ceil() as i32
    }
}

/// Width in pixels of `s` set in `tf`.
fn width(area: &Area, s: &str, tf: &Tf) -> Res<i32> {
    if s.is_empty() {
        return Ok(0);
    }
    let (w, _) = area.estimate_text_size(s, &TextStyle::from(tf.font()))?;
    Ok(w as i32)
}

/// Width in pixels of `s` set in `tf`, to 1/64 pixel (measured at 64 times the size, since
/// `plotters` truncates widths to whole pixels).
fn fine_width(area: &Area, s: &str, tf: &Tf) -> Res<f64> {
    let big = Tf {
        size: tf.size * 64.0,
        ..*tf
    };
    Ok(f64::from(width(area, s, &big)?) / 64.0)
}

/// Draws `s` anchored at `(x, y)`.
///
/// `plotters`' ab_glyph renderer puts the baseline half a font size below the anchor of a
/// top-anchored text, so the vertical anchor is computed here from DejaVu's proportions (capital
/// height 0.63 of the size, descent 0.2).
fn put(area: &Area, s: &str, (x, y): (i32, i32), tf: &Tf, ha: Ha, va: Va) -> Res {
    if s.is_empty() {
        return Ok(());
    }
    let w = width(area, s, tf)?;
    let x0 = match ha {
        Ha::Left => x,
        Ha::Center => x - w / 2,
        Ha::Right => x - w,
    };
    let dy = match va {
        Va::Top => 0.13 * tf.size,
        Va::Center => -0.185 * tf.size,
        Va::Baseline => -0.5 * tf.size,
    };
    glyphs(area, s, (x0, y + dy.round() as i32), tf, false)
}

/// Draws `s` reading upwards, its centre at `(x, y)`.
fn put_vertical(area: &Area, s: &str, (x, y): (i32, i32), tf: &Tf) -> Res {
    if s.is_empty() {
        return Ok(());
    }
    let w = width(area, s, tf)?;
    let dx = (0.185 * tf.size).round() as i32;
    glyphs(area, s, (x - dx, y + w / 2), tf, true)
}

/// Draws `s` one glyph at a time from `(x, y)` (a top-anchored text origin), rightwards or,
/// when `vertical`, upwards.
///
/// `plotters` 0.3.7's ab_glyph renderer drops each glyph's left side bearing (it places the
/// glyph's ink box, not its origin, at the pen position), which spaces narrow glyphs such as
/// `1` visibly unevenly. Placing every glyph at its pen position (the width of the text before
/// it, kerning included) plus its own bearing, read from the font's `hmtx` table, undoes that.
fn glyphs(area: &Area, s: &str, (x, y): (i32, i32), tf: &Tf, vertical: bool) -> Res {
    let bytes = if tf.bold {
        dejavu::sans::bold()
    } else {
        dejavu::sans::regular()
    };
    let base = TextStyle::from(tf.font())
        .color(&tf.color)
        .pos(Pos::new(HPos::Left, VPos::Top));
    let st = if vertical {
        base.transform(FontTransform::Rotate270)
    } else {
        base
    };
    for (k, ch) in s.char_indices() {
        if ch.is_whitespace() {
            continue;
        }
        let mut buf = [0u8; 4];
        let one: &str = ch.encode_utf8(&mut buf);
        let pen = fine_width(area, &s[..k + ch.len_utf8()], tf)? - fine_width(area, one, tf)?;
        let bearing = left_bearing(bytes, ch).map_or(0.0, |b| b * tf.size);
        let d = pen.round() as i32 + bearing.floor() as i32;
        let pos = if vertical { (x, y - d) } else { (x + d, y) };
        area.draw(&Text::new(one.to_string(), pos, st.clone()))?;
    }
    Ok(())
}

fn be16(d: &[u8], o: usize) -> Option<u16> {
    Some(u16::from_be_bytes([*d.get(o)?, *d.get(o + 1)?]))
}

fn be32(d: &[u8], o: usize) -> Option<u32> {
    Some(u32::from_be_bytes([
        *d.get(o)?,
        *d.get(o + 1)?,
        *d.get(o + 2)?,
        *d.get(o + 3)?,
    ]))
}

/// The TrueType table `tag` of the font `d`.
fn ttf_table<'a>(d: &'a [u8], tag: &[u8; 4]) -> Option<&'a [u8]> {
    let n = usize::from(be16(d, 4)?);
    (0..n).find_map(|i| {
        let rec = 12 + 16 * i;
        if d.get(rec..rec + 4)? != tag {
            return None;
        }
        let off = be32(d, rec + 8)? as usize;
        let len = be32(d, rec + 12)? as usize;
        d.get(off..off.checked_add(len)?)
    })
}

/// Glyph index of `c` in the font `d`, through its Windows Unicode BMP (format 4) `cmap`.
fn ttf_glyph(d: &[u8], c: char) -> Option<u16> {
    let cp = u16::try_from(u32::from(c)).ok()?;
    let cmap = ttf_table(d, b"cmap")?;
    let sub = (0..usize::from(be16(cmap, 2)?)).find_map(|i| {
        let rec = 4 + 8 * i;
        let off = be32(cmap, rec + 4)? as usize;
        let sub = cmap.get(off..)?;
        let ok = be16(cmap, rec)? == 3 && be16(cmap, rec + 2)? == 1 && be16(sub, 0)? == 4;
        ok.then_some(sub)
    })?;
    let seg2 = usize::from(be16(sub, 6)?);
    let (ends, starts, deltas, ranges) = (14, 16 + seg2, 16 + 2 * seg2, 16 + 3 * seg2);
    for s in (0..seg2).step_by(2) {
        if cp > be16(sub, ends + s)? {
            continue;
        }
        let start = be16(sub, starts + s)?;
        if cp < start {
            return Some(0);
        }
        let delta = be16(sub, deltas + s)?;
        let ro = usize::from(be16(sub, ranges + s)?);
        if ro == 0 {
            return Some(cp.wrapping_add(delta));
        }
        let g = be16(sub, ranges + s + ro + 2 * usize::from(cp - start))?;
        return Some(if g == 0 { 0 } else { g.wrapping_add(delta) });
    }
    None
}

/// Left side bearing of `c` in the font `d`, as a fraction of the font size in ab_glyph's
/// sense (ascent minus descent from `hhea`).
fn left_bearing(d: &[u8], c: char) -> Option<f64> {
    let gid = usize::from(ttf_glyph(d, c)?);
    let hhea = ttf_table(d, b"hhea")?;
    let ascent = f64::from(be16(hhea, 4)? as i16);
    let descent = f64::from(be16(hhea, 6)? as i16);
    let metrics = usize::from(be16(hhea, 34)?);
    let hmtx = ttf_table(d, b"hmtx")?;
    let lsb = if gid < metrics {
        be16(hmtx, 4 * gid + 2)?
    } else {
        be16(hmtx, 4 * metrics + 2 * (gid - metrics))?
    } as i16;
    let height = ascent - descent;
    (height > 0.0).then(|| f64::from(lsb) / height)
}

/// Splits `s` at spaces into lines at most `max_w` pixels wide (a single longer word keeps its
/// own line).
fn wrap(area: &Area, s: &str, tf: &Tf, max_w: i32) -> Res<Vec<String>> {
    let mut lines: Vec<String> = Vec::new();
    let mut cur = String::new();
    for word in s.split_whitespace() {
        let candidate = if cur.is_empty() {
            word.to_string()
        } else {
            format!("{cur} {word}")
        };
        if cur.is_empty() || width(area, &candidate, tf)? <= max_w {
            cur = candidate;
        } else {
            lines.push(std::mem::replace(&mut cur, word.to_string()));
        }
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    Ok(lines)
}

/// `s`, cut and ended with an ellipsis if it is wider than `max_w` pixels.
fn ellipsize(area: &Area, s: &str, tf: &Tf, max_w: i32) -> Res<String> {
    if width(area, s, tf)? <= max_w {
        return Ok(s.to_string());
    }
    let chars: Vec<char> = s.chars().collect();
    let mut n = chars.len();
    while n > 0 {
        n -= 1;
        let t: String = chars[..n].iter().collect::<String>() + "…";
        if width(area, &t, tf)? <= max_w {
            return Ok(t);
        }
    }
    Ok("…".to_string())
}

/// Draws the chart title centred at the top.
fn title_text(area: &Area, title: &str, w: i32) -> Res {
    let tf = Tf::new(24.0, TEXT).bold();
    let t = ellipsize(area, title, &tf, w - 40)?;
    put(area, &t, (w / 2, 30), &tf, Ha::Center, Va::Center)
}

// ---------------------------------------------------------------------------------------------
// Number formatting
// ---------------------------------------------------------------------------------------------

/// Removes trailing zeros (and a trailing point) from a decimal mantissa.
fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// `v` with about `sig` significant digits: plain for 1e-3 <= |v| < 1e5, else `1.5e-7` style.
fn fmt_sig(v: f64, sig: usize) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    if !v.is_finite() {
        return format!("{v}");
    }
    let sig = sig.max(1);
    let e = v.abs().log10().floor() as i32;
    if !(-3..5).contains(&e) {
        let s = format!("{:.*e}", sig - 1, v);
        match s.split_once('e') {
            Some((m, x)) => format!("{}e{}", trim_zeros(m), x),
            None => s,
        }
    } else {
        let dec = (sig as i32 - 1 - e).max(0) as usize;
        let s = trim_zeros(&format!("{v:.dec$}"));
        if s == "-0" { "0".to_string() } else { s }
    }
}

// ---------------------------------------------------------------------------------------------
// Axes
// ---------------------------------------------------------------------------------------------

/// One axis: a value range, linear or base-10 logarithmic.
#[derive(Clone, Copy)]
struct Axis {
    lo: f64,
    hi: f64,
    log: bool,
}

impl Axis {
    /// An axis over `[lo, hi]`, repaired if the range is empty, reversed, non-finite or (for a
    /// log axis) not positive.
    fn new(lo: f64, hi: f64, log: bool) -> Self {
        let (mut lo, mut hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        if log {
            if !(lo.is_finite() && lo > 0.0) {
                lo = if hi.is_finite() && hi > 0.0 {
                    hi / 100.0
                } else {
                    1.0
                };
            }
            if !(hi.is_finite() && hi > lo) {
                hi = lo * 10.0;
            }
        } else {
            if !lo.is_finite() {
                lo = if hi.is_finite() { hi - 1.0 } else { 0.0 };
            }
            if !(hi.is_finite() && hi > lo) {
                let d = if lo == 0.0 { 1.0 } else { lo.abs() * 0.1 };
                lo -= d;
                hi = lo + 2.0 * d;
            }
        }
        Self { lo, hi, log }
    }

    /// Position of `v` along the axis, 0 at `lo` and 1 at `hi`.
    fn frac(&self, v: f64) -> f64 {
        if self.log {
            (v.log10() - self.lo.log10()) / (self.hi.log10() - self.lo.log10())
        } else {
            (v - self.lo) / (self.hi - self.lo)
        }
    }

    /// Whether `v` can be placed on this axis at all.
    fn accepts(&self, v: f64) -> bool {
        v.is_finite() && (!self.log || v > 0.0)
    }

    /// Labelled ticks and unlabelled minor ticks.
    fn ticks(&self) -> (Vec<(f64, String)>, Vec<f64>) {
        if self.log {
            log_ticks(self.lo, self.hi)
        } else {
            (linear_ticks(self.lo, self.hi, 8.0), Vec::new())
        }
    }
}

/// Ticks at 1, 2 or 5 times a power of ten, about `target` of them.
fn linear_ticks(lo: f64, hi: f64, target: f64) -> Vec<(f64, String)> {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) {
        return Vec::new();
    }
    let raw = span / target;
    let mag = 10f64.powf(raw.log10().floor());
    let n = raw / mag;
    let step = mag
        * if n < 1.5 {
            1.0
        } else if n < 3.5 {
            2.0
        } else if n < 7.5 {
            5.0
        } else {
            10.0
        };
    let first = (lo / step - 1e-9).ceil();
    let last = (hi / step + 1e-9).floor();
    let big = lo.abs().max(hi.abs());
    let exp_style = !(1e-3..1e5).contains(&big);
    let dec = (-step.log10().floor()).max(0.0) as usize;
    let mut out = Vec::new();
    let mut k = first;
    while k <= last && out.len() < 100 {
        let v = k * step;
        let label = if v.abs() < step * 1e-9 {
            "0".to_string()
        } else if exp_style {
            fmt_sig(v, 3)
        } else {
            format!("{v:.dec$}")
        };
        out.push((v, label));
        k += 1.0;
    }
    out
}

/// Decade ticks (thinned to at most about 10 labels), with 2..9 multiples as minor ticks when
/// there are at most 6 decades; labels at 2 and 5 too when under 3 decades; evenly stepped
/// linear ticks when the range is under a decade.
fn log_ticks(lo: f64, hi: f64) -> (Vec<(f64, String)>, Vec<f64>) {
    let (l0, l1) = (lo.log10(), hi.log10());
    if l1 - l0 < 1.0 {
        // Under a decade, evenly stepped values read better than 1..9 multiples.
        return (linear_ticks(lo, hi, 6.0), Vec::new());
    }
    let d0 = (l0 - 1e-9).ceil() as i32;
    let d1 = (l1 + 1e-9).floor() as i32;
    let inside = |v: f64| v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9);
    let decades = (d1 - d0 + 1).max(0);
    let label_mult: &[i32] = if decades >= 3 { &[1] } else { &[1, 2, 5] };
    let every = ((decades + 9) / 10).max(1);
    let mut major = Vec::new();
    let mut minor = Vec::new();
    let lo_dec = l0.floor() as i32;
    let hi_dec = l1.ceil() as i32;
    let mut exps = Vec::new();
    for d in lo_dec..=hi_dec {
        for m in 1..=9 {
            let v = f64::from(m) * 10f64.powi(d);
            if !inside(v) {
                continue;
            }
            let labelled = if m == 1 {
                (d - d0).rem_euclid(every) == 0
            } else {
                label_mult.contains(&m)
            };
            if labelled {
                major.push((v, m, d));
                exps.push(d);
            } else if decades <= 6 {
                minor.push(v);
            }
        }
    }
    let plain = exps.iter().all(|&d| (-2..=4).contains(&d));
    let major = major
        .into_iter()
        .map(|(v, m, d)| {
            let label = if plain {
                let dec = (-d).max(0) as usize;
                format!("{v:.dec$}")
            } else {
                format!("{m}e{d}")
            };
            (v, label)
        })
        .collect();
    (major, minor)
}

/// A plot rectangle in pixels together with the axes mapped onto it.
#[derive(Clone, Copy)]
struct Frame {
    x0: i32,
    y0: i32,
    x1: i32,
    y1: i32,
    xa: Axis,
    ya: Axis,
}

impl Frame {
    fn px(&self, x: f64) -> f64 {
        f64::from(self.x0) + self.xa.frac(x) * f64::from(self.x1 - self.x0)
    }

    fn py(&self, y: f64) -> f64 {
        f64::from(self.y1) - self.ya.frac(y) * f64::from(self.y1 - self.y0)
    }

    fn contains(&self, (x, y): (f64, f64)) -> bool {
        x >= f64::from(self.x0) - 0.5
            && x <= f64::from(self.x1) + 0.5
            && y >= f64::from(self.y0) - 0.5
            && y <= f64::from(self.y1) + 0.5
    }
}

const TICK_FONT: f64 = 15.0;
const LABEL_FONT: f64 = 18.0;

/// Left margin the y tick labels and the y axis title of `ya` need.
fn left_margin(area: &Area, ya: &Axis) -> Res<i32> {
    let tf = Tf::new(TICK_FONT, TEXT);
    let mut w = 0;
    for (_, l) in ya.ticks().0 {
        w = w.max(width(area, &l, &tf)?);
    }
    Ok(16 + LABEL_FONT as i32 + 14 + w + 10)
}

/// Grid lines, frame, ticks, tick labels and axis titles.
fn draw_axes(area: &Area, f: &Frame, x_label: &str, y_label: &str) -> Res {
    let tick_tf = Tf::new(TICK_FONT, TEXT);
    let label_tf = Tf::new(LABEL_FONT, TEXT);
    let (xt, xm) = f.xa.ticks();
    let (yt, ym) = f.ya.ticks();
    let xpix = |v: f64| f.px(v).round() as i32;
    let ypix = |v: f64| f.py(v).round() as i32;
    for &v in &xm {
        let x = xpix(v);
        area.draw(&PathElement::new(
            vec![(x, f.y0), (x, f.y1)],
            style(GRID_MINOR, 1, false),
        ))?;
    }
    for &v in &ym {
        let y = ypix(v);
        area.draw(&PathElement::new(
            vec![(f.x0, y), (f.x1, y)],
            style(GRID_MINOR, 1, false),
        ))?;
    }
    for (v, _) in &xt {
        let x = xpix(*v);
        area.draw(&PathElement::new(
            vec![(x, f.y0), (x, f.y1)],
            style(GRID_MAJOR, 1, false),
        ))?;
    }
    for (v, _) in &yt {
        let y = ypix(*v);
        area.draw(&PathElement::new(
            vec![(f.x0, y), (f.x1, y)],
            style(GRID_MAJOR, 1, false),
        ))?;
    }
    area.draw(&Rectangle::new(
        [(f.x0, f.y0), (f.x1, f.y1)],
        style(TEXT, 1, false),
    ))?;
    for &v in &xm {
        let x = xpix(v);
        area.draw(&PathElement::new(
            vec![(x, f.y1), (x, f.y1 + 3)],
            style(TEXT, 1, false),
        ))?;
    }
    for &v in &ym {
        let y = ypix(v);
        area.draw(&PathElement::new(
            vec![(f.x0 - 3, y), (f.x0, y)],
            style(TEXT, 1, false),
        ))?;
    }
    for (v, l) in &xt {
        let x = xpix(*v);
        area.draw(&PathElement::new(
            vec![(x, f.y1), (x, f.y1 + 6)],
            style(TEXT, 1, false),
        ))?;
        put(area, l, (x, f.y1 + 11), &tick_tf, Ha::Center, Va::Top)?;
    }
    let mut max_w = 0;
    for (v, l) in &yt {
        let y = ypix(*v);
        area.draw(&PathElement::new(
            vec![(f.x0 - 6, y), (f.x0, y)],
            style(TEXT, 1, false),
        ))?;
        put(area, l, (f.x0 - 10, y), &tick_tf, Ha::Right, Va::Center)?;
        max_w = max_w.max(width(area, l, &tick_tf)?);
    }
    let xmid = (f.x0 + f.x1) / 2;
    let ymid = (f.y0 + f.y1) / 2;
    put(
        area,
        x_label,
        (xmid, f.y1 + 11 + tick_tf.height() + 16),
        &label_tf,
        Ha::Center,
        Va::Top,
    )?;
    let yl = ellipsize(area, y_label, &label_tf, f.y1 - f.y0)?;
    put_vertical(
        area,
        &yl,
        (f.x0 - 10 - max_w - 14 - label_tf.height() / 2, ymid),
        &label_tf,
    )?;
    Ok(())
}

/// A segment clipped to the frame: its ends, and whether each is an original (unclipped) end.
struct Clipped {
    a: (f64, f64),
    b: (f64, f64),
    a_orig: bool,
    b_orig: bool,
}

/// Clips the segment `a`-`b` to the frame's rectangle (Liang-Barsky).
fn clip(a: (f64, f64), b: (f64, f64), f: &Frame) -> Option<Clipped> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let mut t0 = 0.0f64;
    let mut t1 = 1.0f64;
    let checks = [
        (-dx, a.0 - f64::from(f.x0)),
        (dx, f64::from(f.x1) - a.0),
        (-dy, a.1 - f64::from(f.y0)),
        (dy, f64::from(f.y1) - a.1),
    ];
    for (p, q) in checks {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| (a.0 + t * dx, a.1 + t * dy);
    Some(Clipped {
        a: at(t0),
        b: at(t1),
        a_orig: t0 == 0.0,
        b_orig: t1 == 1.0,
    })
}

fn round_pt(p: (f64, f64)) -> (i32, i32) {
    (p.0.round() as i32, p.1.round() as i32)
}

/// Draws the data polyline `pts`, clipped to the frame and broken at points the axes cannot
/// show; dashed when `dash` is given (dash and gap lengths in pixels).
fn polyline(
    area: &Area,
    f: &Frame,
    pts: &[(f64, f64)],
    st: ShapeStyle,
    dash: Option<(u32, u32)>,
) -> Res {
    let flush = |run: &mut Vec<(i32, i32)>| -> Res {
        if run.len() >= 2 {
            match dash {
                Some((on, off)) => {
                    area.draw(&DashedPathElement::new(std::mem::take(run), on, off, st))?
                }
                None => area.draw(&PathElement::new(std::mem::take(run), st))?,
            }
        }
        run.clear();
        Ok(())
    };
    let mut run: Vec<(i32, i32)> = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for &(x, y) in pts {
        if !(f.xa.accepts(x) && f.ya.accepts(y)) {
            flush(&mut run)?;
            prev = None;
            continue;
        }
        let p = (f.px(x), f.py(y));
        if let Some(q) = prev {
            match clip(q, p, f) {
                Some(c) => {
                    if run.is_empty() || !c.a_orig {
                        flush(&mut run)?;
                        run.push(round_pt(c.a));
                    }
                    run.push(round_pt(c.b));
                    if !c.b_orig {
                        flush(&mut run)?;
                    }
                }
                None => flush(&mut run)?,
            }
        }
        prev = Some(p);
    }
    flush(&mut run)
}

/// A pixel-space box: left, top, right, bottom.
#[derive(Clone, Copy)]
struct Bx {
    l: f64,
    t: f64,
    r: f64,
    b: f64,
}

impl Bx {
    fn overlap(&self, o: &Bx) -> f64 {
        let w = (self.r.min(o.r) - self.l.max(o.l)).max(0.0);
        let h = (self.b.min(o.b) - self.t.max(o.t)).max(0.0);
        w * h
    }

    fn area(&self) -> f64 {
        (self.r - self.l) * (self.b - self.t)
    }
}

// ---------------------------------------------------------------------------------------------
// Pareto scatter
// ---------------------------------------------------------------------------------------------

/// One point of a [`pareto`] chart: one form (implementation) of a function.
#[derive(Debug, Clone, PartialEq)]
pub struct ParetoPoint {
    /// The group the form belongs to; each family gets its own colour and marker shape, a
    /// legend entry and a Pareto front.
    pub family: String,
    /// Short label drawn next to the marker.
    pub form: String,
    /// Cost, e.g. nanoseconds per element; must be positive and finite to be drawn.
    pub x: f64,
    /// Error, e.g. maximum relative error; values of 0 or below are drawn at a floor line.
    pub y: f64,
}

/// Writes a log-log scatter of error against cost as a 1400 x 900 PNG at `path`.
///
/// One marker per point, coloured and shaped by `family` and labelled with `form`; labels are
/// placed greedily to avoid markers and each other (with a thin leader line when pushed away).
/// Each family's Pareto front (its points that no other point of the family beats in both `x`
/// and `y`) is joined by a light dashed line. Both axes are logarithmic over the data's range
/// widened by a factor 2 each way. Points with `y <= 0` are drawn on a dashed floor line at
/// `1e-9` (or a decade below the smallest positive `y`, if that is lower), which a note in the
/// legend panel explains; points with a non-finite or non-positive `x` or a NaN or infinite `y`
/// are left out and counted in a note. The legend panel on the right lists the families in
/// order of first appearance. Calls [`register_fonts`] itself.
pub fn pareto(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    points: &[ParetoPoint],
) -> Result<(), Box<dyn Error>> {
    fonts_ready()?;
    const W: i32 = 1400;
    const H: i32 = 900;
    save(path, (W as u32, H as u32), |root| {
        root.fill(&WHITE)?;

        let mut families: Vec<&str> = Vec::new();
        for p in points {
            if !families.contains(&p.family.as_str()) {
                families.push(&p.family);
            }
        }
        let fam_index = |name: &str| families.iter().position(|f| *f == name).unwrap_or(0);

        let shown: Vec<&ParetoPoint> = points
            .iter()
            .filter(|p| p.x.is_finite() && p.x > 0.0 && p.y < f64::INFINITY)
            .collect();
        let skipped = points.len() - shown.len();
        let min_pos = shown
            .iter()
            .map(|p| p.y)
            .filter(|&y| y > 0.0)
            .fold(f64::INFINITY, f64::min);
        let n_floor = shown.iter().filter(|p| p.y <= 0.0).count();
        let floor = if min_pos.is_finite() {
            1e-9f64.min(10f64.powf(min_pos.log10().floor() - 1.0))
        } else {
            1e-9
        };
        let yv = |p: &ParetoPoint| if p.y > 0.0 { p.y } else { floor };

        let (mut xlo, mut xhi, mut ylo, mut yhi) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for p in &shown {
            xlo = xlo.min(p.x);
            xhi = xhi.max(p.x);
            ylo = ylo.min(yv(p));
            yhi = yhi.max(yv(p));
        }
        // Pad by a factor 2 each way, less (down to 1.25) when the data spans under 3 decades.
        let pad = |lo: f64, hi: f64| 10f64.powf(0.1 * (hi / lo).log10()).clamp(1.25, 2.0);
        let xa = if shown.is_empty() {
            Axis::new(1.0, 100.0, true)
        } else {
            let f = pad(xlo, xhi);
            Axis::new(xlo / f, xhi * f, true)
        };
        let ya = if shown.is_empty() {
            Axis::new(1e-9, 1.0, true)
        } else {
            let f = pad(ylo, yhi);
            Axis::new(ylo / f, yhi * f, true)
        };

        // Legend panel: families, then notes.
        let leg_tf = Tf::new(15.0, TEXT);
        let note_tf = Tf::new(13.0, NOTE);
        let mut panel_w = 250;
        for f in &families {
            panel_w = panel_w.max(width(root, f, &leg_tf)? + 50);
        }
        let panel_w = panel_w.min(380);
        let left = left_margin(root, &ya)?;
        let frame = Frame {
            x0: left,
            y0: 62,
            x1: W - panel_w - 30,
            y1: H - 80,
            xa,
            ya,
        };

        title_text(root, title, W)?;
        draw_axes(root, &frame, x_label, y_label)?;

        let marker_r = 6;
        let pix: Vec<(f64, f64)> = shown
            .iter()
            .map(|p| (frame.px(p.x), frame.py(yv(p))))
            .collect();

        // Floor line for exact (y <= 0) points.
        if n_floor > 0 {
            let y = frame.py(floor).round() as i32;
            area_dashed_hline(root, &frame, y)?;
            put(
                root,
                &format!("y ≤ 0 drawn at {}", fmt_sig(floor, 2)),
                (frame.x1 - 6, y - 4),
                &Tf::new(12.0, NOTE),
                Ha::Right,
                Va::Baseline,
            )?;
        }

        // Pareto fronts.
        for (fi, fam) in families.iter().enumerate() {
            let mut pts: Vec<(f64, f64)> = shown
                .iter()
                .filter(|p| p.family == *fam)
                .map(|p| (p.x, yv(p)))
                .collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
            let mut front = Vec::new();
            let mut best = f64::INFINITY;
            for (x, y) in pts {
                if y < best {
                    best = y;
                    front.push((x, y));
                }
            }
            if front.len() >= 2 {
                let c = palette(fi);
                let st = ShapeStyle {
                    color: c.mix(0.45),
                    filled: false,
                    stroke_width: 2,
                };
                polyline(root, &frame, &front, st, Some((7, 5)))?;
            }
        }

        // Markers.
        for (p, &(x, y)) in shown.iter().zip(&pix) {
            let fi = fam_index(&p.family);
            marker(root, fi, round_pt((x, y)), marker_r, palette(fi))?;
        }

        // Labels, most crowded points first.
        let lab_tf = Tf::new(12.0, TEXT);
        let bounds = Bx {
            l: f64::from(frame.x0 + 2),
            t: f64::from(frame.y0 + 2),
            r: f64::from(frame.x1 - 2),
            b: f64::from(frame.y1 - 2),
        };
        let mr = f64::from(marker_r) + 1.0;
        let mut obstacles: Vec<Bx> = pix
            .iter()
            .map(|&(x, y)| Bx {
                l: x - mr,
                t: y - mr,
                r: x + mr,
                b: y + mr,
            })
            .collect();
        let mut order: Vec<usize> = (0..shown.len()).collect();
        let crowd = |i: usize| {
            pix.iter()
                .filter(|q| (q.0 - pix[i].0).hypot(q.1 - pix[i].1) < 70.0)
                .count()
        };
        order.sort_by_key(|&i| std::cmp::Reverse(crowd(i)));
        let dirs: [f64; 12] = [
            0.0, 180.0, -35.0, 35.0, -145.0, 145.0, -90.0, 90.0, -60.0, 60.0, -120.0, 120.0,
        ];
        let mut placed: Vec<(usize, Bx, f64)> = Vec::new();
        for i in order {
            let label = &shown[i].form;
            if label.is_empty() {
                continue;
            }
            let w = f64::from(width(root, label, &lab_tf)?) + 4.0;
            let h = f64::from(lab_tf.height()) + 2.0;
            let (px, py) = pix[i];
            let mut best: Option<(f64, Bx, f64)> = None;
            for (ri, r) in [mr + 3.0, mr + 14.0, mr + 28.0, mr + 46.0]
                .into_iter()
                .enumerate()
            {
                for (di, deg) in dirs.iter().enumerate() {
                    let (s, c) = deg.to_radians().sin_cos();
                    let (ax, ay) = (px + r * c, py + r * s);
                    let l = if c > 0.3 {
                        ax
                    } else if c < -0.3 {
                        ax - w
                    } else {
                        ax - w / 2.0
                    };
                    let t = if s > 0.3 {
                        ay
                    } else if s < -0.3 {
                        ay - h
                    } else {
                        ay - h / 2.0
                    };
                    let bx = Bx {
                        l,
                        t,
                        r: l + w,
                        b: t + h,
                    };
                    let hit: f64 = obstacles.iter().map(|o| bx.overlap(o)).sum();
                    let outside = bx.area() - bx.overlap(&bounds);
                    let cost = hit + 10.0 * outside + ri as f64 * 30.0 + di as f64 * 0.5;
                    if best.is_none_or(|b| cost < b.0) {
                        best = Some((cost, bx, r));
                    }
                }
            }
            if let Some((_, bx, r)) = best {
                obstacles.push(bx);
                placed.push((i, bx, r));
            }
        }
        for (i, bx, r) in placed {
            let (px, py) = pix[i];
            let fi = fam_index(&shown[i].family);
            let c = darken(palette(fi), 0.3);
            if r > mr + 4.0 {
                // Leader from the marker's edge to the nearest point of the label box.
                let nx = px.clamp(bx.l, bx.r);
                let ny = py.clamp(bx.t, bx.b);
                let d = (nx - px).hypot(ny - py);
                if d > mr {
                    let sx = px + (nx - px) / d * mr;
                    let sy = py + (ny - py) / d * mr;
                    root.draw(&PathElement::new(
                        vec![round_pt((sx, sy)), round_pt((nx, ny))],
                        style(RGBColor(150, 150, 150), 1, false),
                    ))?;
                }
            }
            root.draw(&Rectangle::new(
                [round_pt((bx.l, bx.t)), round_pt((bx.r - 1.0, bx.b - 1.0))],
                ShapeStyle {
                    color: WHITE.mix(0.75),
                    filled: true,
                    stroke_width: 0,
                },
            ))?;
            put(
                root,
                &shown[i].form,
                round_pt((bx.l + 2.0, bx.t + 2.0)),
                &Tf { color: c, ..lab_tf },
                Ha::Left,
                Va::Top,
            )?;
        }

        // Legend panel: the notes are laid out first so that the family list can be fitted above.
        let px0 = frame.x1 + 24;
        let mut notes = vec![(
        "Pareto front of a family: its forms that no other form of the family beats in both time \
         and error"
            .to_string(),
        true,
    )];
        if n_floor > 0 {
            notes.push((
                format!(
                    "{n_floor} point{} with error ≤ 0 (exact) drawn at {} on the dashed floor line",
                    if n_floor == 1 { "" } else { "s" },
                    fmt_sig(floor, 2)
                ),
                false,
            ));
        }
        if skipped > 0 {
            notes.push((
                format!(
                    "{skipped} point{} not drawn: a value is not finite or x is not positive",
                    if skipped == 1 { "" } else { "s" }
                ),
                false,
            ));
        }
        if shown.is_empty() {
            notes.push(("no data".to_string(), false));
        }
        let mut note_lines = Vec::new();
        for (note, indented) in &notes {
            let x = if *indented { px0 + 28 } else { px0 };
            note_lines.push((x, wrap(root, note, &note_tf, panel_w - (x - px0) - 8)?));
        }
        let notes_h: i32 = note_lines
            .iter()
            .map(|(_, l)| l.len() as i32 * note_tf.line() + 12)
            .sum();

        let mut y = frame.y0 + 6;
        put(
            root,
            "Families",
            (px0, y),
            &Tf::new(16.0, TEXT).bold(),
            Ha::Left,
            Va::Top,
        )?;
        y += 28;
        let avail = (H - 16 - notes_h - 8 - y).max(14);
        let nf = families.len().max(1) as i32;
        let row_h = (avail / nf).clamp(14, 24);
        let fit = (avail / row_h).max(1) as usize;
        let listed = if families.len() > fit {
            fit - 1
        } else {
            families.len()
        };
        let fam_tf = Tf::new((f64::from(row_h) * 0.64).clamp(10.0, 15.0), TEXT);
        let leg_r = (row_h / 3).clamp(4, marker_r);
        for (fi, f) in families.iter().enumerate().take(listed) {
            marker(root, fi, (px0 + 10, y), leg_r, palette(fi))?;
            let name = ellipsize(root, f, &fam_tf, panel_w - 36)?;
            put(root, &name, (px0 + 26, y), &fam_tf, Ha::Left, Va::Center)?;
            y += row_h;
        }
        if listed < families.len() {
            let more = format!("… and {} more", families.len() - listed);
            put(root, &more, (px0 + 26, y), &fam_tf, Ha::Left, Va::Center)?;
            y += row_h;
        }
        y += 8;
        root.draw(&DashedPathElement::new(
            vec![(px0, y), (px0 + 20, y)],
            7,
            5,
            ShapeStyle {
                color: RGBColor(110, 110, 110).mix(0.8),
                filled: false,
                stroke_width: 2,
            },
        ))?;
        for (k, (x, lines)) in note_lines.iter().enumerate() {
            if k > 0 {
                y += 6;
            }
            for (j, l) in lines.iter().enumerate() {
                let yy = y + j as i32 * note_tf.line();
                put(root, l, (*x, yy), &note_tf, Ha::Left, Va::Center)?;
            }
            y += lines.len() as i32 * note_tf.line() + 6;
        }
        Ok(())
    })
}

/// A grey dashed horizontal line across the frame at pixel row `y`.
fn area_dashed_hline(area: &Area, f: &Frame, y: i32) -> Res {
    area.draw(&DashedPathElement::new(
        vec![(f.x0, y), (f.x1, y)],
        4,
        4,
        style(RGBColor(140, 140, 140), 1, false),
    ))?;
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Heatmap
// ---------------------------------------------------------------------------------------------

/// Writes a heatmap of `values[iy][ix]` over the categorical grid `xs` x `ys` as a PNG at `path`.
///
/// Column `ix` is labelled with `xs[ix]`, row `iy` with `ys[iy]`; `ys[0]` is the bottom row, as on
/// a plot. Colours follow viridis over `range` (values outside it take the end colours; an empty,
/// reversed or non-finite range falls back to the data's own range); NaN cells are grey. A colour
/// bar with ticks and `colorbar_label` sits on the right. When the grid is at most 12 x 12 each
/// cell also shows its value (3 significant digits) in black or white, whichever contrasts. The
/// image size follows the grid (cells of at most 125 x 125 px inside about 1000 x 760 px, so
/// about 1290 x 920 for 8 x 8). When tick labels are wider than the cells only every k-th is
/// written. Errors if `xs` or `ys` is empty or longer than 4000, or `values` is not `ys.len()`
/// rows of `xs.len()` values. Calls [`register_fonts`] itself.
#[allow(clippy::too_many_arguments)]
pub fn heatmap(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    xs: &[f64],
    ys: &[f64],
    values: &[Vec<f64>],
    colorbar_label: &str,
    range: (f64, f64),
) -> Result<(), Box<dyn Error>> {
    fonts_ready()?;
    let (nx, ny) = (xs.len(), ys.len());
    if nx == 0 || ny == 0 {
        return Err("heatmap: xs and ys must not be empty".into());
    }
    if nx > 4000 || ny > 4000 {
        return Err(format!("heatmap: a {nx} x {ny} grid is too large to draw").into());
    }
    if values.len() != ny || values.iter().any(|r| r.len() != nx) {
        return Err(format!(
            "heatmap: values must be {ny} rows (ys) of {nx} values (xs), got {} rows",
            values.len()
        )
        .into());
    }
    let (mut lo, mut hi) = range;
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        lo = f64::INFINITY;
        hi = f64::NEG_INFINITY;
        for v in values.iter().flatten().filter(|v| v.is_finite()) {
            lo = lo.min(*v);
            hi = hi.max(*v);
        }
        let a = Axis::new(lo, hi, false);
        lo = a.lo;
        hi = a.hi;
    }
    let t_of = |v: f64| (v - lo) / (hi - lo);
    let any_nan = values.iter().flatten().any(|v| v.is_nan());
    let any_out = values
        .iter()
        .flatten()
        .any(|v| !v.is_nan() && (*v < lo || *v > hi));

    // Layout, measured with a scratch area (text widths do not depend on the canvas).
    let xl: Vec<String> = xs.iter().map(|&v| fmt_sig(v, 4)).collect();
    let yl: Vec<String> = ys.iter().map(|&v| fmt_sig(v, 4)).collect();
    let base = (1000.0 / nx as f64).min(760.0 / ny as f64).min(125.0);
    let cw = (1000.0 / nx as f64)
        .min(2.0 * base)
        .min(125.0)
        .floor()
        .max(4.0) as i32;
    let ch = (760.0 / ny as f64)
        .min(2.0 * base)
        .min(125.0)
        .floor()
        .max(4.0) as i32;
    let (gw, gh) = (cw * nx as i32, ch * ny as i32);

    let mut measure_buf = vec![0u8; 3 * 4 * 4];
    let scratch = BitMapBackend::with_buffer(&mut measure_buf, (4, 4)).into_drawing_area();
    let tick_tf = Tf::new(TICK_FONT, TEXT);
    let label_tf = Tf::new(LABEL_FONT, TEXT);
    let mut ytw = 0;
    for l in &yl {
        ytw = ytw.max(width(&scratch, l, &tick_tf)?);
    }
    let mut xtw = 0;
    for l in &xl {
        xtw = xtw.max(width(&scratch, l, &tick_tf)?);
    }
    let bar_ticks = linear_ticks(lo, hi, 6.0);
    let mut btw = 0;
    for (_, l) in &bar_ticks {
        btw = btw.max(width(&scratch, l, &tick_tf)?);
    }
    let title_w = width(&scratch, title, &Tf::new(24.0, TEXT).bold())?;
    let note_tf = Tf::new(13.0, NOTE);
    drop(scratch);

    let left = 16 + label_tf.height() + 14 + ytw + 10;
    let top = 64;
    let right = 30 + 26 + 10 + btw + 14 + label_tf.height() + 24;
    let right = right.max(190);
    let bottom = 11 + tick_tf.height() + 16 + label_tf.height() + 24;
    let w = (left + gw + right).max(title_w + 40).max(500);
    let h = top + gh + bottom;

    save(path, (w as u32, h as u32), |root| {
        root.fill(&WHITE)?;
        title_text(root, title, w)?;
        let (gx0, gy0) = (left, top);
        let (gx1, gy1) = (gx0 + gw, gy0 + gh);

        let show_values = nx <= 12 && ny <= 12;
        let mut vsize = (f64::from(cw) / 4.5).clamp(9.0, 18.0);
        if show_values {
            // Shrink the value font until the widest value fits its cell.
            let mut widest = String::new();
            let mut ww = 0;
            for v in values.iter().flatten() {
                let s = fmt_sig(*v, 3);
                let sw = width(root, &s, &Tf::new(vsize, TEXT))?;
                if sw > ww {
                    ww = sw;
                    widest = s;
                }
            }
            while vsize > 8.0 && width(root, &widest, &Tf::new(vsize, TEXT))? > cw - 6 {
                vsize -= 1.0;
            }
        }
        for (iy, row) in values.iter().enumerate() {
            for (ix, &v) in row.iter().enumerate() {
                let x0 = gx0 + ix as i32 * cw;
                let y1 = gy1 - iy as i32 * ch;
                let c = if v.is_nan() {
                    RGBColor(190, 190, 190)
                } else {
                    viridis(t_of(v))
                };
                root.draw(&Rectangle::new(
                    [(x0, y1 - ch), (x0 + cw, y1)],
                    style(c, 1, true),
                ))?;
                if show_values {
                    let s = fmt_sig(v, 3);
                    let tf = Tf::new(vsize, contrast(c));
                    if width(root, &s, &tf)? <= cw - 4 && tf.height() <= ch - 2 {
                        put(
                            root,
                            &s,
                            (x0 + cw / 2, y1 - ch / 2),
                            &tf,
                            Ha::Center,
                            Va::Center,
                        )?;
                    }
                }
            }
        }
        root.draw(&Rectangle::new(
            [(gx0, gy0), (gx1, gy1)],
            style(TEXT, 1, false),
        ))?;

        // Column ticks: every k-th when the labels are wider than the cells.
        let kx = ((xtw + 8) as f64 / f64::from(cw)).ceil().max(1.0) as usize;
        for (ix, l) in xl.iter().enumerate() {
            let x = gx0 + ix as i32 * cw + cw / 2;
            root.draw(&PathElement::new(
                vec![(x, gy1), (x, gy1 + 5)],
                style(TEXT, 1, false),
            ))?;
            if ix % kx == 0 {
                put(root, l, (x, gy1 + 11), &tick_tf, Ha::Center, Va::Top)?;
            }
        }
        let ky = ((tick_tf.height() + 4) as f64 / f64::from(ch))
            .ceil()
            .max(1.0) as usize;
        for (iy, l) in yl.iter().enumerate() {
            let y = gy1 - iy as i32 * ch - ch / 2;
            root.draw(&PathElement::new(
                vec![(gx0 - 5, y), (gx0, y)],
                style(TEXT, 1, false),
            ))?;
            if iy % ky == 0 {
                put(root, l, (gx0 - 10, y), &tick_tf, Ha::Right, Va::Center)?;
            }
        }
        put(
            root,
            x_label,
            ((gx0 + gx1) / 2, gy1 + 11 + tick_tf.height() + 16),
            &label_tf,
            Ha::Center,
            Va::Top,
        )?;
        let ylab = ellipsize(root, y_label, &label_tf, gh.max(200))?;
        put_vertical(
            root,
            &ylab,
            (gx0 - 10 - ytw - 14 - label_tf.height() / 2, (gy0 + gy1) / 2),
            &label_tf,
        )?;

        // Colour bar.
        let bx0 = gx1 + 30;
        let bx1 = bx0 + 26;
        for y in gy0..=gy1 {
            let t = f64::from(gy1 - y) / f64::from(gh.max(1));
            root.draw(&PathElement::new(
                vec![(bx0, y), (bx1, y)],
                style(viridis(t), 1, false),
            ))?;
        }
        root.draw(&Rectangle::new(
            [(bx0, gy0), (bx1, gy1)],
            style(TEXT, 1, false),
        ))?;
        for (v, l) in &bar_ticks {
            let y = (f64::from(gy1) - t_of(*v) * f64::from(gh)).round() as i32;
            root.draw(&PathElement::new(
                vec![(bx1, y), (bx1 + 5, y)],
                style(TEXT, 1, false),
            ))?;
            put(root, l, (bx1 + 10, y), &tick_tf, Ha::Left, Va::Center)?;
        }
        let cbl = ellipsize(root, colorbar_label, &label_tf, gh.max(200))?;
        put_vertical(
            root,
            &cbl,
            (bx1 + 10 + btw + 14 + label_tf.height() / 2, (gy0 + gy1) / 2),
            &label_tf,
        )?;
        let mut notes = Vec::new();
        if any_nan {
            notes.push("grey: no value (NaN)");
        }
        if any_out {
            notes.push("values outside the bar's range take its end colours");
        }
        let mut y = gy1 + 14;
        for n in notes {
            for l in wrap(root, n, &note_tf, w - bx0 - 10)? {
                put(root, &l, (bx0, y), &note_tf, Ha::Left, Va::Top)?;
                y += note_tf.line();
            }
        }
        Ok(())
    })
}

// ---------------------------------------------------------------------------------------------
// Curves
// ---------------------------------------------------------------------------------------------

/// One curve of a [`lines`] chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend label.
    pub name: String,
    /// The points, drawn in the given order.
    pub pts: Vec<(f64, f64)>,
    /// RGB colour; `None` takes the series' place in the 22-colour palette.
    pub color: Option<(u8, u8, u8)>,
    /// Dashed instead of solid.
    pub dashed: bool,
}

impl Series {
    /// A solid series in its palette colour.
    pub fn new(name: impl Into<String>, pts: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.into(),
            pts,
            color: None,
            dashed: false,
        }
    }

    /// The same series in `color`, dashed or solid.
    #[must_use]
    pub fn styled(self, color: (u8, u8, u8), dashed: bool) -> Self {
        Self {
            color: Some(color),
            dashed,
            ..self
        }
    }
}

/// The frame of a [`lines`] chart: texts and axis kinds.
#[derive(Debug, Clone, Copy)]
pub struct LinePlot<'a> {
    /// Title above the plot.
    pub title: &'a str,
    /// x axis title, with its unit.
    pub x_label: &'a str,
    /// y axis title, with its unit.
    pub y_label: &'a str,
    /// Base-10 logarithmic x axis (points with x <= 0 skipped).
    pub log_x: bool,
    /// Base-10 logarithmic y axis (points with y <= 0 skipped).
    pub log_y: bool,
    /// The y range; an empty, reversed or non-finite range falls back to the data's range
    /// (plus 5 % on a linear axis).
    pub y_range: (f64, f64),
}

/// Writes a line chart of `series` (each a legend label and its `(x, y)` points, drawn in the
/// given order) as a 1400 x 900 PNG at `path`: [`lines`] with palette colours, a linear y axis
/// over `y_range` and an x axis logarithmic when `log_x`.
pub fn curves(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    log_x: bool,
    y_range: (f64, f64),
    series: &[(String, Vec<(f64, f64)>)],
) -> Result<(), Box<dyn Error>> {
    let series: Vec<Series> = series
        .iter()
        .map(|(n, p)| Series::new(n.clone(), p.clone()))
        .collect();
    lines(
        path,
        &LinePlot {
            title,
            x_label,
            y_label,
            log_x,
            log_y: false,
            y_range,
        },
        &series,
    )
}

/// Writes a line chart of `series` as a 1400 x 900 PNG at `path`.
///
/// The x axis spans the data (base-10 logarithmic with decade ticks when `plot.log_x`, in which
/// case points with `x <= 0` are skipped); the y axis spans `plot.y_range` (logarithmic when
/// `plot.log_y`; an empty, reversed or non-finite range falls back to the data's range). Lines
/// are clipped to the plot and broken at non-finite points. A series without a colour takes
/// colour `i` of a 22-colour palette; palette series past the 22nd are dashed. When there are
/// more than 10 series every series also carries markers (a shape per series, about 8 per
/// curve, staggered), so each one stays distinguishable. A single-point series is drawn as a
/// marker. The legend is a side panel right of the plot. Calls [`register_fonts`] itself.
pub fn lines(path: &Path, plot: &LinePlot, series: &[Series]) -> Result<(), Box<dyn Error>> {
    let LinePlot {
        title,
        x_label,
        y_label,
        log_x,
        log_y,
        y_range,
    } = *plot;
    fonts_ready()?;
    const W: i32 = 1400;
    const H: i32 = 900;
    save(path, (W as u32, H as u32), |root| {
        root.fill(&WHITE)?;

        let (mut xlo, mut xhi) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut ylo, mut yhi) = (f64::INFINITY, f64::NEG_INFINITY);
        for s in series {
            for &(x, y) in &s.pts {
                if x.is_finite() && (!log_x || x > 0.0) && y.is_finite() && (!log_y || y > 0.0) {
                    xlo = xlo.min(x);
                    xhi = xhi.max(x);
                    ylo = ylo.min(y);
                    yhi = yhi.max(y);
                }
            }
        }
        let xa = if xlo <= xhi {
            Axis::new(xlo, xhi, log_x)
        } else {
            Axis::new(1.0, 10.0, log_x)
        };
        let ya = if y_range.0.is_finite()
            && y_range.1.is_finite()
            && y_range.0 < y_range.1
            && (!log_y || y_range.0 > 0.0)
        {
            Axis::new(y_range.0, y_range.1, log_y)
        } else if ylo <= yhi && log_y {
            Axis::new(ylo, yhi, true)
        } else if ylo <= yhi {
            let pad = 0.05 * (yhi - ylo);
            Axis::new(ylo - pad, yhi + pad, false)
        } else {
            Axis::new(0.0, 1.0, log_y)
        };

        // Legend panel geometry.
        let n = series.len();
        let top = 62;
        let bottom = H - 80;
        let avail = bottom - top - 40;
        let row_h = if n == 0 {
            24
        } else {
            (avail / n as i32).clamp(10, 24)
        };
        let leg_tf = Tf::new((f64::from(row_h) * 0.64).clamp(9.0, 15.0), TEXT);
        let sample_w = 34;
        let mut lw = 0;
        for s in series {
            lw = lw.max(width(root, &s.name, &leg_tf)?);
        }
        let panel_w = (sample_w + 10 + lw + 24).clamp(160, 420);
        let label_max = panel_w - sample_w - 10 - 24;
        let left = left_margin(root, &ya)?;
        let frame = Frame {
            x0: left,
            y0: top,
            x1: W - panel_w - 36,
            y1: bottom,
            xa,
            ya,
        };
        title_text(root, title, W)?;
        draw_axes(root, &frame, x_label, y_label)?;

        let with_markers = n > 10;
        let dashed = |i: usize| match series[i].color {
            Some(_) => series[i].dashed,
            None => series[i].dashed || (i / PALETTE.len()) % 2 == 1,
        };
        let colour = |i: usize| {
            series[i]
                .color
                .map_or_else(|| palette(i), |(r, g, b)| RGBColor(r, g, b))
        };
        for (i, s) in series.iter().enumerate() {
            let pts = &s.pts;
            let c = colour(i);
            let st = style(c, 2, false);
            polyline(
                root,
                &frame,
                pts,
                st,
                if dashed(i) { Some((9, 5)) } else { None },
            )?;
            let valid: Vec<(f64, f64)> = pts
                .iter()
                .copied()
                .filter(|&(x, y)| xa.accepts(x) && ya.accepts(y))
                .collect();
            if with_markers || valid.len() == 1 {
                let every = (valid.len() / 8).max(1);
                let offset = (i * every).checked_div(n).unwrap_or(0);
                for (j, &(x, y)) in valid.iter().enumerate() {
                    if !(j + offset).is_multiple_of(every) && valid.len() > 1 {
                        continue;
                    }
                    let p = (frame.px(x), frame.py(y));
                    if frame.contains(p) {
                        marker(root, i, round_pt(p), 4, c)?;
                    }
                }
            }
        }

        // Legend.
        let lx0 = frame.x1 + 20;
        let ly0 = frame.y0;
        // Entries that fit the panel; the rest are summed up in a last line.
        let fit = ((bottom - ly0 - 12) / row_h).max(1) as usize;
        let listed = if n > fit { fit - 1 } else { n };
        let rows_drawn = if n > fit { fit } else { n };
        if n > 0 {
            let box_h = row_h * rows_drawn as i32 + 12;
            root.draw(&Rectangle::new(
                [(lx0, ly0), (lx0 + panel_w, ly0 + box_h)],
                style(GRID_MAJOR, 1, false),
            ))?;
        }
        if listed < n {
            let y = ly0 + 6 + listed as i32 * row_h + row_h / 2;
            let more = format!("… and {} more", n - listed);
            put(root, &more, (lx0 + 8, y), &leg_tf, Ha::Left, Va::Center)?;
        }
        for (i, s) in series.iter().enumerate().take(listed) {
            let name = &s.name;
            let y = ly0 + 6 + i as i32 * row_h + row_h / 2;
            let c = colour(i);
            let (sx0, sx1) = (lx0 + 8, lx0 + 8 + sample_w);
            if dashed(i) {
                root.draw(&DashedPathElement::new(
                    vec![(sx0, y), (sx1, y)],
                    9,
                    5,
                    style(c, 2, false),
                ))?;
            } else {
                root.draw(&PathElement::new(
                    vec![(sx0, y), (sx1, y)],
                    style(c, 2, false),
                ))?;
            }
            if with_markers {
                marker(root, i, ((sx0 + sx1) / 2, y), 4, c)?;
            }
            let label = ellipsize(root, name, &leg_tf, label_max)?;
            put(root, &label, (sx1 + 10, y), &leg_tf, Ha::Left, Va::Center)?;
        }
        if n == 0 {
            put(
                root,
                "no data",
                (lx0, ly0 + 10),
                &Tf::new(13.0, NOTE),
                Ha::Left,
                Va::Top,
            )?;
        }
        Ok(())
    })
}

// ---------------------------------------------------------------------------------------------
// Labelled image grid
// ---------------------------------------------------------------------------------------------

/// Writes the RGB8 image `rgb` (`w` x `h` pixels, row-major, 3 bytes a pixel), which is a grid
/// of `rows` x `cols` equal cells, as a PNG at `path` with `title` above it, `col_labels[c]`
/// centred above column `c` and `row_labels[r]` right-aligned left of row `r`.
///
/// The image is copied unscaled. Labels wrap at spaces to fit their column (row labels to about
/// 260 px); missing labels are left blank and extra ones ignored. Errors if `rgb.len()` is not
/// `w * h * 3`, a dimension is zero, or there are more cells than pixels. Calls
/// [`register_fonts`] itself.
#[allow(clippy::too_many_arguments)]
pub fn labelled_grid(
    path: &Path,
    title: &str,
    rgb: &[u8],
    w: usize,
    h: usize,
    cols: usize,
    rows: usize,
    col_labels: &[String],
    row_labels: &[String],
) -> Result<(), Box<dyn Error>> {
    fonts_ready()?;
    if w == 0 || h == 0 || cols == 0 || rows == 0 {
        return Err("labelled_grid: width, height, cols and rows must be positive".into());
    }
    let (wi, hi) = (i32::try_from(w)?, i32::try_from(h)?);
    let bytes = w.checked_mul(h).and_then(|n| n.checked_mul(3));
    if bytes != Some(rgb.len()) {
        return Err(format!(
            "labelled_grid: rgb has {} bytes, a {w} x {h} RGB8 image needs 3 per pixel",
            rgb.len()
        )
        .into());
    }
    if cols > w || rows > h {
        return Err(
            format!("labelled_grid: {cols} x {rows} cells do not fit {w} x {h} pixels").into(),
        );
    }
    let cell_w = f64::from(wi) / cols as f64;
    let cell_h = f64::from(hi) / rows as f64;
    let lab_tf = Tf::new(16.0, TEXT);
    let title_tf = Tf::new(24.0, TEXT).bold();

    let mut measure_buf = vec![0u8; 3 * 4 * 4];
    let scratch = BitMapBackend::with_buffer(&mut measure_buf, (4, 4)).into_drawing_area();
    let col_w = (cell_w as i32 - 8).max(60);
    let mut col_lines: Vec<Vec<String>> = Vec::new();
    for c in 0..cols {
        let l = col_labels.get(c).map(String::as_str).unwrap_or("");
        col_lines.push(wrap(&scratch, l, &lab_tf, col_w)?);
    }
    // When some column labels wrap, break the one-line ones at their last space too, so that
    // every column reads the same way ("roughness" above its value).
    if col_lines.iter().any(|l| l.len() > 1) {
        for lines in &mut col_lines {
            if let [one] = lines.as_slice()
                && let Some((a, b)) = one.rsplit_once(' ')
            {
                *lines = vec![a.to_string(), b.to_string()];
            }
        }
    }
    let mut row_lines: Vec<Vec<String>> = Vec::new();
    let mut row_w = 0;
    for r in 0..rows {
        let l = row_labels.get(r).map(String::as_str).unwrap_or("");
        let lines = wrap(&scratch, l, &lab_tf, 260)?;
        for s in &lines {
            row_w = row_w.max(width(&scratch, s, &lab_tf)?);
        }
        row_lines.push(lines);
    }
    let title_w = width(&scratch, title, &title_tf)?;
    drop(scratch);

    let max_col_lines = col_lines.iter().map(Vec::len).max().unwrap_or(0) as i32;
    let margin = 20;
    let title_h = if title.is_empty() { margin } else { 56 };
    let col_band = if max_col_lines == 0 {
        0
    } else {
        max_col_lines * lab_tf.line() + 10
    };
    let row_band = if row_w == 0 { 0 } else { row_w + 14 };
    let content_w = margin + row_band + wi + margin;
    let cw = content_w.max(title_w + 40);
    // Centred when the title is wider than the labelled image.
    let ix0 = (cw - content_w) / 2 + margin + row_band;
    let iy0 = title_h + col_band;
    let ch = iy0 + hi + margin;

    save(path, (cw as u32, ch as u32), |root| {
        root.fill(&WHITE)?;
        if !title.is_empty() {
            title_text(root, title, cw)?;
        }
        let img = BitMapElement::<(i32, i32)>::with_ref((ix0, iy0), (w as u32, h as u32), rgb)
            .ok_or("labelled_grid: image buffer too small")?;
        root.draw(&img)?;

        for (c, lines) in col_lines.iter().enumerate() {
            let x = ix0 + (cell_w * (c as f64 + 0.5)).round() as i32;
            let n = lines.len() as i32;
            for (j, l) in lines.iter().enumerate() {
                // Bottom-aligned: the last line sits just above the image.
                let y = iy0 - 8 - (n - 1 - j as i32) * lab_tf.line();
                put(root, l, (x, y), &lab_tf, Ha::Center, Va::Baseline)?;
            }
        }
        for (r, lines) in row_lines.iter().enumerate() {
            let yc = iy0 + (cell_h * (r as f64 + 0.5)).round() as i32;
            let n = lines.len() as i32;
            for (j, l) in lines.iter().enumerate() {
                let y = yc + ((2 * j as i32 - (n - 1)) * lab_tf.line()) / 2;
                put(root, l, (ix0 - 12, y), &lab_tf, Ha::Right, Va::Center)?;
            }
        }
        Ok(())
    })
}

// ---------------------------------------------------------------------------------------------
// Captioned cells
// ---------------------------------------------------------------------------------------------

/// Writes equal-sized RGB8 images (`cell_w` x `cell_h` pixels each, row-major, 3 bytes a pixel)
/// as a grid of `cols` columns at `path`, each with its caption centred below it, under
/// `title`.
///
/// Captions wrap at spaces to the cell's width. Errors if there are no cells, `cols` is 0, a
/// dimension is zero or a cell's buffer is not `cell_w * cell_h * 3` bytes. Calls
/// [`register_fonts`] itself.
pub fn captioned_cells(
    path: &Path,
    title: &str,
    cells: &[(Vec<u8>, String)],
    (cell_w, cell_h): (usize, usize),
    cols: usize,
) -> Result<(), Box<dyn Error>> {
    fonts_ready()?;
    if cells.is_empty() || cols == 0 || cell_w == 0 || cell_h == 0 {
        return Err("captioned_cells: no cells, or a zero dimension".into());
    }
    if let Some((c, _)) = cells.iter().find(|(c, _)| c.len() != cell_w * cell_h * 3) {
        return Err(format!(
            "captioned_cells: a cell has {} bytes, {cell_w} x {cell_h} RGB8 needs {}",
            c.len(),
            cell_w * cell_h * 3
        )
        .into());
    }
    let (cw, chh) = (i32::try_from(cell_w)?, i32::try_from(cell_h)?);
    let rows = cells.len().div_ceil(cols);
    let lab_tf = Tf::new(16.0, TEXT);
    let mut measure_buf = vec![0u8; 3 * 4 * 4];
    let scratch = BitMapBackend::with_buffer(&mut measure_buf, (4, 4)).into_drawing_area();
    let mut captions = Vec::new();
    for (_, c) in cells {
        captions.push(wrap(&scratch, c, &lab_tf, cw)?);
    }
    drop(scratch);
    let cap_lines = captions.iter().map(Vec::len).max().unwrap_or(1) as i32;
    let (margin, gap) = (20, 12);
    let title_h = if title.is_empty() { margin } else { 56 };
    let row_h = chh + 6 + cap_lines * lab_tf.line() + gap;
    let w = 2 * margin + cols as i32 * cw + (cols as i32 - 1) * gap;
    let h = title_h + rows as i32 * row_h + margin - gap;
    save(path, (w as u32, h as u32), |root| {
        root.fill(&WHITE)?;
        if !title.is_empty() {
            title_text(root, title, w)?;
        }
        for (k, ((rgb, _), lines)) in cells.iter().zip(&captions).enumerate() {
            let (r, c) = ((k / cols) as i32, (k % cols) as i32);
            let (x0, y0) = (margin + c * (cw + gap), title_h + r * row_h);
            let img = BitMapElement::<(i32, i32)>::with_ref(
                (x0, y0),
                (cell_w as u32, cell_h as u32),
                rgb.as_slice(),
            )
            .ok_or("captioned_cells: image buffer too small")?;
            root.draw(&img)?;
            for (j, l) in lines.iter().enumerate() {
                let y = y0 + chh + 6 + j as i32 * lab_tf.line();
                put(root, l, (x0 + cw / 2, y), &lab_tf, Ha::Center, Va::Top)?;
            }
        }
        Ok(())
    })
}
