//! The report's text: every section appends Markdown to one buffer (`out!` / `outln!`, in
//! place of `print!` / `println!`); at the end the buffer becomes `report.md`, and every
//! Markdown table in it is also written as a CSV file beside it, named after its section,
//! with a link under the table.

use std::fmt::Write as _;
use std::path::Path;
use std::sync::Mutex;

static BUFFER: Mutex<String> = Mutex::new(String::new());

/// Appends formatted text to the report.
pub fn append(args: std::fmt::Arguments<'_>) {
    let mut b = BUFFER
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    // Writing into a String cannot fail.
    let _ = b.write_fmt(args);
}

/// Appends to the report, like `print!`.
#[macro_export]
macro_rules! out {
    ($($t:tt)*) => { $crate::md::append(format_args!($($t)*)) };
}

/// Appends a line to the report, like `println!`.
#[macro_export]
macro_rules! outln {
    () => { $crate::md::append(format_args!("\n")) };
    ($($t:tt)*) => {{ $crate::md::append(format_args!($($t)*)); $crate::md::append(format_args!("\n")) }};
}

/// Takes the text written so far.
pub fn take() -> String {
    let mut b = BUFFER
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    std::mem::take(&mut *b)
}

/// A file-name slug of a heading: lower case, alphanumerics joined by '-', at most 48 chars.
fn slug(heading: &str) -> String {
    let mut s = String::new();
    for c in heading.trim_start_matches('#').trim().chars() {
        if c.is_ascii_alphanumeric() {
            s.push(c.to_ascii_lowercase());
        } else if !s.ends_with('-') && !s.is_empty() {
            s.push('-');
        }
        if s.len() >= 48 {
            break;
        }
    }
    s.trim_end_matches('-').to_string()
}

/// One Markdown table row's cells, without the outer pipes, with code ticks and emphasis
/// removed.
fn cells(line: &str) -> Vec<String> {
    let t = line.trim();
    let t = t.strip_prefix('|').unwrap_or(t);
    let t = t.strip_suffix('|').unwrap_or(t);
    t.split('|')
        .map(|c| {
            c.trim()
                .replace('`', "")
                .replace("**", "")
                .trim_matches('*')
                .to_string()
        })
        .collect()
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Writes `md` to `dir/report.md`, every table in it to `dir/<section>.csv` (numbered when
/// a section has several), and returns the CSV file names written.
pub fn write_folder(md: &str, dir: &Path) -> std::io::Result<Vec<String>> {
    let mut doc = String::new();
    let mut csvs = Vec::new();
    let mut heading = String::from("report");
    let mut table: Vec<Vec<String>> = Vec::new();
    let mut used: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    let mut flush =
        |table: &mut Vec<Vec<String>>, heading: &str, doc: &mut String| -> std::io::Result<()> {
            if table.is_empty() {
                return Ok(());
            }
            let base = slug(heading);
            let n = used.entry(base.clone()).or_insert(0);
            *n += 1;
            let name = if *n == 1 {
                format!("{base}.csv")
            } else {
                format!("{base}-{n}.csv")
            };
            let mut text = String::new();
            for row in table.iter() {
                let line: Vec<String> = row.iter().map(|c| csv_field(c)).collect();
                text.push_str(&line.join(","));
                text.push('\n');
            }
            std::fs::write(dir.join(&name), text)?;
            let _ = writeln!(doc, "\n[CSV: {name}]({name})");
            csvs.push(name);
            table.clear();
            Ok(())
        };
    for line in md.lines() {
        let is_row = line.trim_start().starts_with('|');
        if !is_row {
            flush(&mut table, &heading, &mut doc)?;
        }
        if line.starts_with('#') {
            heading = line.to_string();
        }
        if is_row {
            let c = cells(line);
            // The |---|---| separator row is Markdown, not data.
            if !c
                .iter()
                .all(|x| !x.is_empty() && x.chars().all(|ch| ch == '-' || ch == ':'))
            {
                table.push(c);
            }
        }
        doc.push_str(line);
        doc.push('\n');
    }
    flush(&mut table, &heading, &mut doc)?;
    std::fs::write(dir.join("report.md"), doc)?;
    Ok(csvs)
}
