//! A small reader of Radiance `.hdr` (RGBE) files: the header, the `-Y H +X W` orientation
//! (the one every equirectangular environment on the web uses), flat scanlines and the
//! run-length encoded scanlines of Ward's format ("Real Pixels", Graphics Gems II, 1991; the
//! file layout of Radiance's `color.c`, `freadcolrs`).
//!
//! Ours rather than the `image` crate's, which would compile a dozen codecs into the report
//! for one format. Old-style (pre-1991) run-length scanlines and other orientations are
//! refused with an error, never guessed.

/// A decoded image: linear RGB, row by row from the top.
pub struct Hdr {
    /// Width in pixels.
    pub w: usize,
    /// Height in pixels.
    pub h: usize,
    /// `w * h` linear RGB triples.
    pub px: Vec<[f32; 3]>,
}

/// RGBE to linear RGB: each mantissa byte times 2^(e - 136), the pixel centre convention of
/// Radiance's `colr_color` (mantissa + 0.5); e = 0 is black.
fn rgbe(p: [u8; 4]) -> [f32; 3] {
    if p[3] == 0 {
        return [0.0; 3];
    }
    let f = 2f32.powi(i32::from(p[3]) - 136);
    [0, 1, 2].map(|k| (f32::from(p[k]) + 0.5) * f)
}

/// Decodes the bytes of a `.hdr` file.
///
/// # Errors
/// A missing `#?` magic line, a `FORMAT` other than `32-bit_rle_rgbe`, a resolution line
/// other than `-Y H +X W`, a size over 2^15 x 2^15, or data that ends early or contradicts the
/// scanline width.
pub fn decode(d: &[u8]) -> Result<Hdr, String> {
    let mut pos = 0;
    let mut line = || -> Result<String, String> {
        let end = d[pos..]
            .iter()
            .position(|&b| b == b'\n')
            .ok_or("hdr: the header ends before the resolution line")?;
        let l = String::from_utf8_lossy(&d[pos..pos + end])
            .trim_end()
            .to_string();
        pos += end + 1;
        Ok(l)
    };
    if !line()?.starts_with("#?") {
        return Err("hdr: not a Radiance file (no #? magic line)".into());
    }
    loop {
        let l = line()?;
        if l.is_empty() {
            break;
        }
        if let Some(f) = l.strip_prefix("FORMAT=")
            && f != "32-bit_rle_rgbe"
        {
            return Err(format!(
                "hdr: FORMAT={f} is not supported (32-bit_rle_rgbe is)"
            ));
        }
    }
    let res = line()?;
    let t: Vec<&str> = res.split_whitespace().collect();
    let (h, w) = match t.as_slice() {
        ["-Y", h, "+X", w] => (
            h.parse::<usize>()
                .map_err(|e| format!("hdr: height: {e}"))?,
            w.parse::<usize>().map_err(|e| format!("hdr: width: {e}"))?,
        ),
        _ => {
            return Err(format!(
                "hdr: orientation `{res}` is not supported (-Y H +X W is)"
            ));
        }
    };
    if w == 0 || h == 0 || w > 1 << 15 || h > 1 << 15 {
        return Err(format!("hdr: size {w} x {h} outside 1..32768"));
    }
    let mut px = Vec::with_capacity(w * h);
    let byte = |p: &mut usize| -> Result<u8, String> {
        let b = *d.get(*p).ok_or("hdr: the pixel data ends early")?;
        *p += 1;
        Ok(b)
    };
    let mut scan = vec![[0u8; 4]; w];
    for _ in 0..h {
        let head: [Option<u8>; 4] = core::array::from_fn(|k| d.get(pos + k).copied());
        let rle = (8..0x8000).contains(&w)
            && head[0] == Some(2)
            && head[1] == Some(2)
            && head[2].is_some_and(|b| b & 0x80 == 0);
        if rle {
            let n = usize::from(head[2].unwrap_or(0)) << 8 | usize::from(head[3].unwrap_or(0));
            if n != w {
                return Err(format!("hdr: a scanline says width {n}, the header {w}"));
            }
            pos += 4;
            // Four planes (R, G, B, E), each a sequence of runs (count > 128: one byte repeated
            // count - 128 times) and literals (count <= 128 bytes).
            for c in 0..4 {
                let mut x = 0;
                while x < w {
                    let count = usize::from(byte(&mut pos)?);
                    if count > 128 {
                        let n = count - 128;
                        let v = byte(&mut pos)?;
                        if x + n > w {
                            return Err("hdr: a run crosses the scanline's end".into());
                        }
                        scan[x..x + n].iter_mut().for_each(|p| p[c] = v);
                        x += n;
                    } else {
                        if count == 0 || x + count > w {
                            return Err(
                                "hdr: a literal is empty or crosses the scanline's end".into()
                            );
                        }
                        for p in &mut scan[x..x + count] {
                            p[c] = byte(&mut pos)?;
                        }
                        x += count;
                    }
                }
            }
        } else {
            for p in &mut scan {
                for b in p.iter_mut() {
                    *b = byte(&mut pos)?;
                }
                if p[0] == 1 && p[1] == 1 && p[2] == 1 {
                    return Err("hdr: old-style run-length scanlines are not supported".into());
                }
            }
        }
        px.extend(scan.iter().map(|&p| rgbe(p)));
    }
    Ok(Hdr { w, h, px })
}

/// Reads and decodes a `.hdr` file.
///
/// # Errors
/// The file cannot be read, or [`decode`] refuses it.
pub fn read(path: &std::path::Path) -> Result<Hdr, String> {
    let d = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    decode(&d).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header(w: usize, h: usize) -> Vec<u8> {
        format!("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1\n\n-Y {h} +X {w}\n").into_bytes()
    }

    #[test]
    fn flat_scanlines_decode_to_mantissa_times_power_of_two() {
        let mut d = header(2, 1);
        // (128, 64, 0) at e = 129: (m + 0.5) 2^-7 = 1.00390625, 0.50390625, 0.00390625.
        d.extend([128, 64, 0, 129, 0, 0, 0, 0]);
        let img = decode(&d).unwrap();
        assert_eq!((img.w, img.h), (2, 1));
        assert_eq!(img.px[0], [128.5 / 128.0, 64.5 / 128.0, 0.5 / 128.0]);
        assert_eq!(img.px[1], [0.0; 3], "e = 0 is black");
    }

    #[test]
    fn run_length_scanlines_decode_runs_and_literals() {
        let w = 8;
        let mut d = header(w, 1);
        d.extend([2, 2, 0, w as u8]);
        // R: a run of 5 x 10 then a literal 1, 2, 3.
        d.extend([128 + 5, 10, 3, 1, 2, 3]);
        // G: a literal of 8.
        d.extend([8, 0, 1, 2, 3, 4, 5, 6, 7]);
        // B: a run of 8 zeros. E: a run of 8 x 128 (scale 2^-8).
        d.extend([128 + 8, 0, 128 + 8, 128]);
        let img = decode(&d).unwrap();
        let r: Vec<f32> = img.px.iter().map(|p| p[0] * 256.0 - 0.5).collect();
        let g: Vec<f32> = img.px.iter().map(|p| p[1] * 256.0 - 0.5).collect();
        assert_eq!(r, [10.0, 10.0, 10.0, 10.0, 10.0, 1.0, 2.0, 3.0]);
        assert_eq!(g, [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
    }

    #[test]
    fn truncated_or_foreign_files_are_errors_not_panics() {
        let mut d = header(8, 2);
        d.extend([2, 2, 0, 8, 128 + 8]);
        assert!(decode(&d).is_err(), "data ends inside a run");
        assert!(decode(b"P6\n1 1\n255\n").is_err(), "no magic");
        let mut d = b"#?RADIANCE\n\n+Y 1 +X 1\n".to_vec();
        d.extend([0, 0, 0, 0]);
        assert!(decode(&d).is_err(), "orientation");
        let mut d = header(8, 1);
        d.extend([2, 2, 0, 9]);
        assert!(decode(&d).is_err(), "scanline width");
    }
}
