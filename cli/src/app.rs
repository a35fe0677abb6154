//! The `brdf-ref` command line: argument parsing (lexopt), `--list`, `eval`, `diff` and the
//! help text, writing to the given streams so tests can run it in process as well.

use std::ffi::OsString;
use std::fmt::Write as _;
use std::io::{self, Read, Write};
use std::path::PathBuf;

use crate::table::{Float, KERNELS, Kernel, find};
use crate::ulp::{BUCKETS, Compare, Stats, bucket_label};

/// Exit status: every row evaluated (and, with `--max-ulp`, every difference within it).
pub const EXIT_OK: i32 = 0;
/// Exit status of `diff --max-ulp K` when a difference exceeds K or a NaN / infinity does
/// not match.
pub const EXIT_DIFFERENCE: i32 = 1;
/// Exit status when a row, an option or the header could not be used.
pub const EXIT_BAD_INPUT: i32 = 2;

/// The help text: a walk-through for shader authors.
pub const HELP: &str = "\
brdf-ref: the brdf crate's kernels as a reference for shader code.

USAGE
    brdf-ref --list [FILTER]               every kernel: arguments, domains, outputs
    brdf-ref eval [KERNEL] [OPTIONS]       evaluate a kernel on CSV rows or a grid
    brdf-ref diff [KERNEL] [OPTIONS]       compare a shader's outputs with the crate's
    brdf-ref help                          this text

CHECKING A SHADER AGAINST THE CRATE, STEP BY STEP
 1. Pick the kernel your shader function implements. `brdf-ref --list ggx` prints every
    kernel whose path contains `ggx`, for example

        ggx::d  GGX (Trowbridge-Reitz) NDF D(m), Walter et al. 2007 eq. 33
          args:    n_dot_h: [-1, 1]; alpha: [0, +inf) finite, clamped to [ALPHA_MIN, ...]
          outputs: d: [0, +inf), finite

    Mind the argument order and meaning: the crate's `alpha` is the GGX width (perceptual
    roughness squared); Filament's D_GGX(roughness, NoH) takes the same alpha but roughness
    first, Unreal's D_GGX(a2, NoH) takes alpha^2.

 2. Dump your shader's inputs and outputs as CSV, one row per evaluation: the arguments in
    the order `--list` prints them, then each output. From a compute shader, write them
    into a storage buffer (one float per column) and read it back; from a fragment shader,
    render the inputs you generated into a float render target (RGBA32F) and read the
    pixels back. Print every float with enough digits to round-trip (9 significant digits
    for f32, 17 for f64; `{}` in Rust, `%.9g` in C). A header row of the column names is
    optional; if present it must match the kernel's names exactly. Vectors are flattened:
    wo becomes wo_x,wo_y,wo_z, a colour c becomes c_r,c_g,c_b.

        n_dot_h,alpha,d
        0.5,0.25,0.033938915
        0.99,0.04,1.1050482

    Or let the crate produce the inputs (and its values) for you:

        brdf-ref eval ggx::d --grid n_dot_h=0:1:101 --grid alpha=0.25 > points.csv

 3. Diff the shader's values against the crate's:

        brdf-ref diff ggx::d --f32 --input shader.csv --worst 5

    Every row is re-evaluated in the chosen precision (--f32, the default, or --f64) and
    each output compared in ULPs: the distance between the two floats in the type's ordered
    integer representation (adjacent floats are 1 apart; two NaNs are equal; a NaN or an
    infinity that does not match is counted separately as a mismatch).

 4. Read the report: per output the max and median ULP and relative difference, the
    mismatches, a histogram of ULP differences (0, 1, 2, 3-4, 5-8, ..., > 2^20) and the
    worst rows with their inputs. A few ULP is rounding (a different operation order, a
    fused multiply-add); hundreds or more at a few inputs point at cancellation (1 - c^2
    near c = 1, for example) or a different clamp; a large error everywhere usually means
    swapped arguments or a different roughness convention. Add --max-ulp K in CI to fail
    (exit status 1) when any difference exceeds K.

EVAL
    brdf-ref eval KERNEL [--f32 | --f64] [--input FILE] [--unchecked]
    brdf-ref eval KERNEL --grid NAME=LO:HI:N ... [--grid NAME=VALUE ...]
    brdf-ref eval [--input FILE]           rows start with the kernel's path
    Reads rows of comma-separated arguments (stdin without --input) and prints CSV: a
    header (arguments, then outputs) and each row's arguments and outputs, every value the
    shortest text that parses back to the same float. --grid evaluates the cartesian product
    of N evenly spaced values from LO to HI per argument (one --grid per argument; NAME=VALUE
    fixes one). Without KERNEL every row starts with a kernel path (a column `kernel`), so
    one file can hold many kernels; a row starting with `kernel` is a header for the rows
    after it.

DIFF
    brdf-ref diff KERNEL [--input FILE] [--f32 | --f64] [--worst N] [--max-ulp K] [--unchecked]
    brdf-ref diff [--input FILE] ...       rows start with the kernel's path
    Rows hold the arguments, then the shader's value of each output. --worst N lists the N
    rows with the largest differences (default 10).

BAD INPUT
    A row with the wrong number of values, a value that is not a number, an unknown kernel,
    a value outside its argument's documented domain (NaN is outside every domain) or
    arguments that break a documented relation (unit vectors, orderings) is reported on
    stderr with its row (the line number in the input) and column (index and name), and
    skipped; the other rows still print, and the exit status is 2. --unchecked evaluates
    out-of-domain rows anyway (the crate returns NaN or clamps, as documented).

EXIT STATUS
    0 all rows used; 1 diff --max-ulp exceeded; 2 a row, option or header was rejected.
";

/// Parsed options of `eval` and `diff`.
#[derive(Debug)]
struct Opts {
    kernel: Option<String>,
    ty: Float,
    input: Option<PathBuf>,
    grids: Vec<String>,
    unchecked: bool,
    worst: usize,
    max_ulp: Option<u128>,
}

/// Runs the command line `args` (without the program name) with the given streams and
/// returns the exit status.
pub fn run(
    args: Vec<OsString>,
    stdin: &mut dyn Read,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> i32 {
    match run_inner(args, stdin, out, err) {
        Ok(code) => code,
        Err(e) if e == CLOSED_PIPE => 0,
        Err(e) => {
            let _ = writeln!(err, "error: {e}");
            EXIT_BAD_INPUT
        }
    }
}

fn run_inner(
    args: Vec<OsString>,
    stdin: &mut dyn Read,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, String> {
    use lexopt::prelude::*;
    let mut p = lexopt::Parser::from_args(args);
    let first = p.next().map_err(|e| e.to_string())?;
    let cmd = match first {
        None => {
            write_str(
                err,
                "usage: brdf-ref --list | eval KERNEL | diff KERNEL (brdf-ref help for the walk-through)\n",
            )?;
            return Ok(EXIT_BAD_INPUT);
        }
        Some(Long("help") | Short('h')) => {
            write_str(out, HELP)?;
            return Ok(EXIT_OK);
        }
        Some(Long("list")) => "list".to_string(),
        Some(Value(v)) => v.string().map_err(|e| e.to_string())?,
        Some(a) => return Err(a.unexpected().to_string()),
    };
    match cmd.as_str() {
        "help" => {
            write_str(out, HELP)?;
            Ok(EXIT_OK)
        }
        "list" => {
            let mut filter = None;
            while let Some(a) = p.next().map_err(|e| e.to_string())? {
                match a {
                    Value(v) if filter.is_none() => {
                        filter = Some(v.string().map_err(|e| e.to_string())?);
                    }
                    a => return Err(a.unexpected().to_string()),
                }
            }
            write_str(out, &list(filter.as_deref()))?;
            Ok(EXIT_OK)
        }
        "eval" | "diff" => {
            let mut o = Opts {
                kernel: None,
                ty: Float::F32,
                input: None,
                grids: Vec::new(),
                unchecked: false,
                worst: 10,
                max_ulp: None,
            };
            while let Some(a) = p.next().map_err(|e| e.to_string())? {
                match a {
                    Long("f32") => o.ty = Float::F32,
                    Long("f64") => o.ty = Float::F64,
                    Long("input") | Short('i') => {
                        o.input = Some(p.value().map_err(|e| e.to_string())?.into());
                    }
                    Long("grid") if cmd == "eval" => {
                        o.grids.push(
                            p.value()
                                .map_err(|e| e.to_string())?
                                .string()
                                .map_err(|e| e.to_string())?,
                        );
                    }
                    Long("unchecked") => o.unchecked = true,
                    Long("worst") if cmd == "diff" => {
                        let v: String = p
                            .value()
                            .map_err(|e| e.to_string())?
                            .string()
                            .map_err(|e| e.to_string())?;
                        o.worst = v
                            .parse()
                            .map_err(|_| format!("--worst takes a count, not `{v}`"))?;
                    }
                    Long("max-ulp") if cmd == "diff" => {
                        let v: String = p
                            .value()
                            .map_err(|e| e.to_string())?
                            .string()
                            .map_err(|e| e.to_string())?;
                        o.max_ulp = Some(
                            v.parse()
                                .map_err(|_| format!("--max-ulp takes a count, not `{v}`"))?,
                        );
                    }
                    Long("help") | Short('h') => {
                        write_str(out, HELP)?;
                        return Ok(EXIT_OK);
                    }
                    Value(v) if o.kernel.is_none() => {
                        o.kernel = Some(v.string().map_err(|e| e.to_string())?);
                    }
                    a => return Err(a.unexpected().to_string()),
                }
            }
            let kernel = match &o.kernel {
                Some(name) => Some(find(name).ok_or_else(|| unknown_kernel(name))?),
                None => None,
            };
            if cmd == "eval" && !o.grids.is_empty() {
                let k = kernel.ok_or("--grid needs a KERNEL")?;
                if o.input.is_some() {
                    return Err("--grid and --input exclude each other".into());
                }
                return eval_grid(k, &o, out, err);
            }
            let text = read_input(o.input.as_ref(), stdin)?;
            if cmd == "eval" {
                eval_rows(kernel, &text, &o, out, err)
            } else {
                diff_rows(kernel, &text, &o, out, err)
            }
        }
        other => Err(format!(
            "unknown command `{other}` (brdf-ref --list, eval, diff or help)"
        )),
    }
}

/// The error text of a write to a closed pipe (`brdf-ref --list | head`): not a failure of
/// the command, so [`run`] ends quietly with exit code 0.
const CLOSED_PIPE: &str = "output closed";

fn io_error(e: &std::io::Error) -> String {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        CLOSED_PIPE.to_string()
    } else {
        e.to_string()
    }
}

fn write_str(w: &mut dyn Write, s: &str) -> Result<(), String> {
    w.write_all(s.as_bytes()).map_err(|e| io_error(&e))
}

fn read_input(path: Option<&PathBuf>, stdin: &mut dyn Read) -> Result<String, String> {
    let mut s = String::new();
    match path {
        Some(p) if p.as_os_str() != "-" => {
            s = std::fs::read_to_string(p)
                .map_err(|e| format!("cannot read {}: {e}", p.display()))?;
        }
        _ => {
            stdin
                .read_to_string(&mut s)
                .map_err(|e| format!("cannot read stdin: {e}"))?;
        }
    }
    Ok(s)
}

/// `brdf-ref --list [FILTER]`: every kernel whose path contains FILTER.
#[must_use]
pub fn list(filter: Option<&str>) -> String {
    let mut s = String::new();
    let kernels: Vec<&Kernel> = KERNELS
        .iter()
        .filter(|k| filter.is_none_or(|f| k.path.contains(f)))
        .collect();
    for k in &kernels {
        let _ = writeln!(s, "{}  {}", k.path, k.summary);
        let args: Vec<String> = k
            .args
            .iter()
            .map(|a| format!("{}: {}", a.name, a.domain.text))
            .collect();
        let _ = writeln!(s, "  args:    {}", args.join("; "));
        let outs: Vec<String> = k
            .outputs
            .iter()
            .map(|o| format!("{}: {}", o.name, o.range.text))
            .collect();
        let _ = writeln!(s, "  outputs: {}", outs.join("; "));
        let c = k.constraints_all();
        if !c.is_empty() {
            let _ = writeln!(s, "  where:   {}", c.join("; "));
        }
    }
    let _ = writeln!(s, "{} kernels", kernels.len());
    s
}

/// The error for an unknown kernel path, with the closest known paths.
fn unknown_kernel(name: &str) -> String {
    let close = suggestions(name);
    if close.is_empty() {
        format!("unknown kernel `{name}` (brdf-ref --list prints every kernel)")
    } else {
        format!(
            "unknown kernel `{name}`; did you mean {}? (brdf-ref --list prints every kernel)",
            close.join(", ")
        )
    }
}

/// Up to five known paths close to `name`: containing it, or within a small edit distance
/// of it (whole path or last segment).
#[must_use]
pub fn suggestions(name: &str) -> Vec<&'static str> {
    let last = |p: &str| p.rsplit("::").next().unwrap_or(p).to_string();
    let mut scored: Vec<(usize, &'static str)> = KERNELS
        .iter()
        .filter_map(|k| {
            let d = levenshtein(name, k.path).min(levenshtein(&last(name), &last(k.path)) + 1);
            let contains = !name.is_empty() && k.path.contains(name);
            let limit = (name.len() / 3).max(2);
            (contains || d <= limit).then_some((if contains { 0 } else { d }, k.path))
        })
        .collect();
    scored.sort();
    scored.into_iter().take(5).map(|(_, p)| p).collect()
}

fn levenshtein(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            cur[j + 1] = (prev[j] + usize::from(ca != *cb))
                .min(prev[j + 1] + 1)
                .min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// `x` (a value of type `ty`) as the shortest text that parses back to it.
#[must_use]
pub fn fmt(x: f64, ty: Float) -> String {
    match ty {
        #[allow(clippy::cast_possible_truncation)]
        Float::F32 => format!("{}", x as f32),
        Float::F64 => format!("{x}"),
    }
}

/// `s` parsed as a number of type `ty` (correctly rounded from the decimal text), widened to
/// `f64`.
#[must_use]
pub fn parse(s: &str, ty: Float) -> Option<f64> {
    match ty {
        Float::F32 => s.parse::<f32>().ok().map(f64::from),
        Float::F64 => s.parse::<f64>().ok(),
    }
}

/// One line of input: its 1-based line number and its fields, trimmed.
struct Line<'a> {
    row: usize,
    fields: Vec<&'a str>,
}

/// The lines holding data or a header (blank lines and lines starting with `#` skipped).
fn lines(text: &str) -> impl Iterator<Item = Line<'_>> {
    text.lines().enumerate().filter_map(|(i, l)| {
        let t = l.trim();
        (!t.is_empty() && !t.starts_with('#')).then(|| Line {
            row: i + 1,
            fields: t.split(',').map(str::trim).collect(),
        })
    })
}

/// A row rejected with its message; the caller prints it and moves on.
type RowResult<T> = Result<T, String>;

/// The column names of `k` as a header: its arguments, then (for `diff` input and every
/// output) its outputs.
fn header(k: &Kernel, with_outputs: bool) -> Vec<&'static str> {
    let mut h: Vec<&'static str> = k.args.iter().map(|a| a.name).collect();
    if with_outputs {
        h.extend(k.outputs.iter().map(|o| o.name));
    }
    h
}

/// The arguments of one row: `fields` (the row without its kernel column, `offset` columns
/// before it) parsed as `ty`, checked against the domains and relations unless `unchecked`.
/// `extra` more values (the shader's outputs for `diff`) follow the arguments and are parsed
/// but not checked.
fn parse_row(
    k: &Kernel,
    line: usize,
    fields: &[&str],
    offset: usize,
    extra: usize,
    ty: Float,
    unchecked: bool,
) -> RowResult<Vec<f64>> {
    let names = header(k, extra > 0);
    let want = k.args.len() + extra;
    if fields.len() != want {
        let what = if fields.len() < want {
            let i = fields.len();
            format!(
                "column {} ({}) is missing: {} values, expected {want} ({})",
                i + 1 + offset,
                names[i],
                fields.len(),
                names.join(", ")
            )
        } else {
            format!(
                "column {} is one too many: {} values, expected {want} ({})",
                want + 1 + offset,
                fields.len(),
                names.join(", ")
            )
        };
        return Err(format!("row {line}: {what}"));
    }
    let mut values = Vec::with_capacity(want);
    for (i, f) in fields.iter().enumerate() {
        let col = format!("row {line}, column {} ({})", i + 1 + offset, names[i]);
        let x = parse(f, ty).ok_or_else(|| format!("{col}: `{f}` is not a number"))?;
        if i < k.args.len() && !unchecked {
            let d = &k.args[i].domain;
            if x.is_nan() {
                return Err(format!(
                    "{col}: NaN is outside every domain (the domain of {} is {})",
                    names[i], d.text
                ));
            }
            if !d.contains_as(x, ty) {
                return Err(format!(
                    "{col}: {} is outside the domain of {}: {} (--unchecked evaluates it anyway)",
                    fmt(x, ty),
                    names[i],
                    d.text
                ));
            }
        }
        values.push(x);
    }
    if !unchecked && let Some(b) = k.broken_constraint(&values[..k.args.len()], ty) {
        let cols: Vec<String> = b
            .args
            .iter()
            .map(|&i| format!("{} ({})", i + 1 + offset, names[i]))
            .collect();
        return Err(format!(
            "row {line}, columns {}: {} (--unchecked evaluates it anyway)",
            cols.join(", "),
            b.text
        ));
    }
    Ok(values)
}

/// Resolves the kernel of a row in the mode with a leading `kernel` column.
fn row_kernel(line: usize, name: &str) -> RowResult<&'static Kernel> {
    find(name).ok_or_else(|| format!("row {line}, column 1 (kernel): {}", unknown_kernel(name)))
}

/// Whether `fields` is a header row: its first field is not a number.
fn is_header(fields: &[&str], ty: Float) -> bool {
    fields.first().is_some_and(|f| parse(f, ty).is_none())
}

/// Checks a single-kernel header against the expected names.
fn check_header(
    k: &Kernel,
    line: usize,
    fields: &[&str],
    with_outputs: bool,
) -> Result<(), String> {
    let want = header(k, with_outputs);
    if fields == want.as_slice() {
        Ok(())
    } else {
        Err(format!(
            "row {line}: the header `{}` does not match {}'s columns `{}`",
            fields.join(","),
            k.path,
            want.join(",")
        ))
    }
}

fn write_row(
    out: &mut dyn Write,
    kernel: Option<&str>,
    values: &[f64],
    outputs: &[f64],
    ty: Float,
) -> Result<(), String> {
    let mut s = String::new();
    if let Some(p) = kernel {
        s.push_str(p);
        s.push(',');
    }
    let all: Vec<String> = values.iter().chain(outputs).map(|&x| fmt(x, ty)).collect();
    s.push_str(&all.join(","));
    s.push('\n');
    write_str(out, &s)
}

fn eval_rows(
    kernel: Option<&'static Kernel>,
    text: &str,
    o: &Opts,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, String> {
    let mut out = io::BufWriter::new(out);
    let mut bad = 0usize;
    let mut first = true;
    // Multi-kernel mode: the kernel whose columns the last header named, and the kernel of
    // the last row printed (a header is printed whenever it changes).
    let mut expected: Option<&'static Kernel> = None;
    let mut printed: Option<&'static Kernel> = None;
    if let Some(k) = kernel {
        write_str(&mut out, &format!("{}\n", header(k, true).join(",")))?;
    }
    for line in lines(text) {
        let is_first = std::mem::take(&mut first);
        let result = match read_line(kernel, &line, is_first, false, &mut expected, o, err) {
            Step::Next => continue,
            Step::BadRow => {
                bad += 1;
                continue;
            }
            Step::BadHeader => return Ok(EXIT_BAD_INPUT),
            Step::Row(r) => r,
        };
        match result {
            Ok((k, v)) => {
                let y = k.eval_as(&v, o.ty);
                if kernel.is_none() {
                    if printed.is_none_or(|p| p.path != k.path) {
                        write_str(&mut out, &format!("kernel,{}\n", header(k, true).join(",")))?;
                        printed = Some(k);
                    }
                    write_row(&mut out, Some(k.path), &v, &y, o.ty)?;
                } else {
                    write_row(&mut out, None, &v, &y, o.ty)?;
                }
            }
            Err(e) => {
                bad += 1;
                let _ = writeln!(err, "error: {e}");
            }
        }
    }
    out.flush().map_err(|e| io_error(&e))?;
    Ok(finish_bad(bad, err))
}

/// What one input line of `eval` or `diff` turned out to be.
enum Step {
    /// A header, checked and consumed.
    Next,
    /// A multi-kernel header that names no kernel (reported; the rows after it fail).
    BadRow,
    /// A single-kernel header that does not match the kernel (reported; nothing is read).
    BadHeader,
    /// A row: its kernel and values (`with_outputs`: the arguments, then the shader's
    /// outputs), or the error naming its row and column.
    Row(RowResult<(&'static Kernel, Vec<f64>)>),
}

/// Reads one line of `eval` input (`with_outputs` false) or `diff` input (true), for a
/// given kernel or, without one, with a leading `kernel` column; `expected` carries the
/// kernel the last multi-kernel header named.
fn read_line(
    kernel: Option<&'static Kernel>,
    line: &Line<'_>,
    is_first: bool,
    with_outputs: bool,
    expected: &mut Option<&'static Kernel>,
    o: &Opts,
    err: &mut dyn Write,
) -> Step {
    let extra = |k: &Kernel| if with_outputs { k.outputs.len() } else { 0 };
    match kernel {
        Some(k) => {
            if is_first && is_header(&line.fields, o.ty) {
                if let Err(e) = check_header(k, line.row, &line.fields, with_outputs) {
                    let _ = writeln!(err, "error: {e}");
                    return Step::BadHeader;
                }
                return Step::Next;
            }
            Step::Row(
                parse_row(k, line.row, &line.fields, 0, extra(k), o.ty, o.unchecked)
                    .map(|v| (k, v)),
            )
        }
        None => {
            if line.fields[0] == "kernel" {
                *expected = multi_header(line, with_outputs, err);
                return if expected.is_none() {
                    Step::BadRow
                } else {
                    Step::Next
                };
            }
            Step::Row(
                row_kernel(line.row, line.fields[0])
                    .and_then(|k| header_agrees(*expected, k, line.row).map(|()| k))
                    .and_then(|k| {
                        parse_row(
                            k,
                            line.row,
                            &line.fields[1..],
                            1,
                            extra(k),
                            o.ty,
                            o.unchecked,
                        )
                        .map(|v| (k, v))
                    }),
            )
        }
    }
}

/// A header row `kernel,<names>` of the multi-kernel mode: the kernel whose columns it names
/// (arguments, or arguments and outputs for `diff`), or `None` after reporting it.
fn multi_header(
    line: &Line<'_>,
    with_outputs: bool,
    err: &mut dyn Write,
) -> Option<&'static Kernel> {
    let names = &line.fields[1..];
    let found = KERNELS.iter().find(|k| header(k, with_outputs) == names);
    if found.is_none() {
        let _ = writeln!(
            err,
            "error: row {}: the header `{}` names the columns of no kernel",
            line.row,
            line.fields.join(",")
        );
    }
    found
}

/// In the multi-kernel mode, a row after a header must be of a kernel with the header's
/// columns.
fn header_agrees(expected: Option<&'static Kernel>, k: &Kernel, line: usize) -> RowResult<()> {
    match expected {
        Some(e)
            if e.args
                .iter()
                .map(|a| a.name)
                .ne(k.args.iter().map(|a| a.name)) =>
        {
            Err(format!(
                "row {line}, column 1 (kernel): {} does not have the columns of the header above it ({})",
                k.path,
                header(e, false).join(",")
            ))
        }
        _ => Ok(()),
    }
}

fn finish_bad(bad: usize, err: &mut dyn Write) -> i32 {
    if bad > 0 {
        let _ = writeln!(
            err,
            "{bad} row{} rejected (see above); the other rows were evaluated",
            if bad == 1 { "" } else { "s" }
        );
        EXIT_BAD_INPUT
    } else {
        EXIT_OK
    }
}

/// The values of one `--grid` axis, or the error naming the bad spec.
fn grid_axis(spec: &str, ty: Float) -> Result<(String, Vec<f64>), String> {
    let (name, range) = spec
        .split_once('=')
        .ok_or_else(|| format!("--grid `{spec}`: expected NAME=LO:HI:N or NAME=VALUE"))?;
    let num = |s: &str| {
        parse(s.trim(), ty).ok_or_else(|| format!("--grid `{spec}`: `{s}` is not a number"))
    };
    let parts: Vec<&str> = range.split(':').collect();
    let values = match parts.as_slice() {
        [v] => vec![num(v)?],
        [lo, hi, n] => {
            let (lo, hi) = (num(lo)?, num(hi)?);
            let n: usize = n
                .trim()
                .parse()
                .map_err(|_| format!("--grid `{spec}`: `{n}` is not a count"))?;
            if n == 0 {
                return Err(format!("--grid `{spec}`: the count must be at least 1"));
            }
            #[allow(clippy::cast_precision_loss)]
            let v: Vec<f64> = (0..n)
                .map(|i| {
                    if n == 1 {
                        lo
                    } else if i == n - 1 {
                        hi
                    } else {
                        ty.round(lo + (hi - lo) * (i as f64) / ((n - 1) as f64))
                    }
                })
                .collect();
            v
        }
        _ => {
            return Err(format!(
                "--grid `{spec}`: expected NAME=LO:HI:N or NAME=VALUE"
            ));
        }
    };
    Ok((name.trim().to_string(), values))
}

fn eval_grid(
    k: &Kernel,
    o: &Opts,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, String> {
    let mut axes: Vec<Option<Vec<f64>>> = vec![None; k.args.len()];
    for spec in &o.grids {
        let (name, values) = grid_axis(spec, o.ty)?;
        let i = k.arg_index(&name).ok_or_else(|| {
            format!(
                "--grid `{spec}`: {} has no argument `{name}` (its arguments: {})",
                k.path,
                header(k, false).join(", ")
            )
        })?;
        if axes[i].replace(values).is_some() {
            return Err(format!("--grid: `{name}` is given twice"));
        }
    }
    let missing: Vec<&str> = k
        .args
        .iter()
        .zip(&axes)
        .filter(|(_, a)| a.is_none())
        .map(|(a, _)| a.name)
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "--grid: no values for {} (give each argument a --grid NAME=LO:HI:N or NAME=VALUE)",
            missing.join(", ")
        ));
    }
    let axes: Vec<Vec<f64>> = axes.into_iter().flatten().collect();
    let total = axes
        .iter()
        .try_fold(1usize, |acc, a| acc.checked_mul(a.len()))
        .filter(|&n| n <= 100_000_000)
        .ok_or("--grid: more than 10^8 points")?;
    let mut out = io::BufWriter::new(out);
    write_str(&mut out, &format!("{}\n", header(k, true).join(",")))?;
    let mut bad = 0;
    let mut row = vec![0.0; k.args.len()];
    for n in 0..total {
        // The last argument varies fastest.
        let mut idx = n;
        for (i, a) in axes.iter().enumerate().rev() {
            row[i] = a[idx % a.len()];
            idx /= a.len();
        }
        let fields: Vec<String> = row.iter().map(|&x| fmt(x, o.ty)).collect();
        let fields: Vec<&str> = fields.iter().map(String::as_str).collect();
        match parse_row(k, n + 1, &fields, 0, 0, o.ty, o.unchecked) {
            Ok(v) => write_row(&mut out, None, &v, &k.eval_as(&v, o.ty), o.ty)?,
            Err(e) => {
                bad += 1;
                let _ = writeln!(err, "error: grid point {}", e.trim_start_matches("row "));
            }
        }
    }
    out.flush().map_err(|e| io_error(&e))?;
    Ok(finish_bad(bad, err))
}

/// One (row, output) difference kept for the worst-rows list.
struct Worst {
    line: usize,
    output: usize,
    compare: Compare,
    args: Vec<f64>,
    ours: f64,
    theirs: f64,
}

impl Worst {
    /// Larger is worse: mismatches first, then by ULP.
    fn key(&self) -> (u128, std::cmp::Reverse<usize>) {
        let severity = match self.compare {
            Compare::Ulp(u) => u,
            Compare::NanMismatch | Compare::InfMismatch => u128::MAX,
        };
        (severity, std::cmp::Reverse(self.line))
    }
}

/// The comparison of one kernel's rows.
struct KernelDiff {
    kernel: &'static Kernel,
    rows: usize,
    outputs: Vec<Stats>,
    worst: Vec<Worst>,
}

impl KernelDiff {
    fn new(kernel: &'static Kernel) -> Self {
        Self {
            kernel,
            rows: 0,
            outputs: vec![Stats::default(); kernel.outputs.len()],
            worst: Vec::new(),
        }
    }

    fn add(&mut self, line: usize, args: &[f64], theirs: &[f64], ty: Float, keep: usize) {
        self.rows += 1;
        let ours = self.kernel.eval_as(args, ty);
        for (i, (&a, &b)) in ours.iter().zip(theirs).enumerate() {
            let c = self.outputs[i].add(a, b, ty);
            if keep > 0 && c != Compare::Ulp(0) {
                self.worst.push(Worst {
                    line,
                    output: i,
                    compare: c,
                    args: args.to_vec(),
                    ours: a,
                    theirs: b,
                });
                if self.worst.len() > 4 * keep + 64 {
                    self.prune(keep);
                }
            }
        }
    }

    fn prune(&mut self, keep: usize) {
        self.worst.sort_by_key(|w| std::cmp::Reverse(w.key()));
        self.worst.truncate(keep);
    }

    fn exceeds(&self, k: u128) -> bool {
        self.outputs
            .iter()
            .any(|s| s.max_ulp() > k || s.nan_mismatches > 0 || s.inf_mismatches > 0)
    }

    fn report(&mut self, ty: Float, keep: usize) -> String {
        let mut s = String::new();
        let k = self.kernel;
        let _ = writeln!(s, "{} ({}): {} rows compared", k.path, ty.name(), self.rows);
        for (o, st) in k.outputs.iter().zip(&mut self.outputs) {
            st.finish();
            let _ = writeln!(
                s,
                "  output {}: max ULP {}, median ULP {}, max relative {:.3e}, median relative {:.3e}",
                o.name,
                st.max_ulp(),
                st.median_ulp(),
                st.max_rel(),
                st.median_rel()
            );
            let _ = writeln!(
                s,
                "    non-finite mismatches: {} (NaN against a number {}, infinity against another value {})",
                st.nan_mismatches + st.inf_mismatches,
                st.nan_mismatches,
                st.inf_mismatches
            );
            let last = st.histogram.iter().rposition(|&n| n > 0).unwrap_or(0);
            let _ = writeln!(s, "    histogram (ULP: rows):");
            let compared: usize = st.histogram.iter().sum();
            for (b, &n) in st.histogram.iter().enumerate().take(last.max(2) + 1) {
                let bar = if compared == 0 {
                    0
                } else {
                    (n * 40).div_ceil(compared)
                };
                let _ = writeln!(
                    s,
                    "      {:>17} {:>9}  {}",
                    bucket_label(b),
                    n,
                    "#".repeat(bar)
                );
            }
            if last < BUCKETS - 1 && st.histogram[BUCKETS - 1] > 0 {
                let _ = writeln!(
                    s,
                    "      {:>17} {:>9}",
                    bucket_label(BUCKETS - 1),
                    st.histogram[BUCKETS - 1]
                );
            }
        }
        self.prune(keep);
        if keep > 0 {
            if self.worst.is_empty() {
                let _ = writeln!(s, "  worst rows: none (every value matches bit for bit)");
            } else {
                let _ = writeln!(s, "  worst {} rows:", self.worst.len());
                for w in &self.worst {
                    let args: Vec<String> = k
                        .args
                        .iter()
                        .zip(&w.args)
                        .map(|(a, &x)| format!("{}={}", a.name, fmt(x, ty)))
                        .collect();
                    let diff = match w.compare {
                        Compare::Ulp(u) => format!("{u} ULP"),
                        Compare::NanMismatch => "NaN mismatch".to_string(),
                        Compare::InfMismatch => "infinity mismatch".to_string(),
                    };
                    let _ = writeln!(
                        s,
                        "    row {}: {}: crate {}, shader {}, {} ({})",
                        w.line,
                        k.outputs[w.output].name,
                        fmt(w.ours, ty),
                        fmt(w.theirs, ty),
                        diff,
                        args.join(", ")
                    );
                }
            }
        }
        s
    }
}

fn diff_rows(
    kernel: Option<&'static Kernel>,
    text: &str,
    o: &Opts,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<i32, String> {
    let mut diffs: Vec<KernelDiff> = Vec::new();
    let mut bad = 0usize;
    let mut first = true;
    let mut expected: Option<&'static Kernel> = None;
    for line in lines(text) {
        let is_first = std::mem::take(&mut first);
        let parsed = match read_line(kernel, &line, is_first, true, &mut expected, o, err) {
            Step::Next => continue,
            Step::BadRow => {
                bad += 1;
                continue;
            }
            Step::BadHeader => return Ok(EXIT_BAD_INPUT),
            Step::Row(r) => r,
        };
        match parsed {
            Ok((k, v)) => {
                let i = match diffs.iter().position(|d| d.kernel.path == k.path) {
                    Some(i) => i,
                    None => {
                        diffs.push(KernelDiff::new(k));
                        diffs.len() - 1
                    }
                };
                let n = k.args.len();
                diffs[i].add(line.row, &v[..n], &v[n..], o.ty, o.worst);
            }
            Err(e) => {
                bad += 1;
                let _ = writeln!(err, "error: {e}");
            }
        }
    }
    let mut report = String::new();
    if diffs.is_empty() {
        report.push_str("no rows compared\n");
    }
    let mut exceeded = Vec::new();
    for d in &mut diffs {
        report.push_str(&d.report(o.ty, o.worst));
        if let Some(k) = o.max_ulp
            && d.exceeds(k)
        {
            exceeded.push(d.kernel.path);
        }
    }
    write_str(out, &report)?;
    let code = finish_bad(bad, err);
    if code != EXIT_OK {
        return Ok(code);
    }
    if let Some(k) = o.max_ulp
        && !exceeded.is_empty()
    {
        let _ = writeln!(
            err,
            "FAIL: differences above --max-ulp {k} (or NaN / infinity mismatches) in {}",
            exceeded.join(", ")
        );
        return Ok(EXIT_DIFFERENCE);
    }
    Ok(EXIT_OK)
}
