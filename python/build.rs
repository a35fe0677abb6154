//! Carries the crate's doc comments into the Python docstrings: parses `brdf`'s `src/**/*.rs`
//! with `syn` (as `cli/tests/cli/drift.rs` does to hold the kernel table to the functions) and
//! writes `$OUT_DIR/docs.rs`, two sorted tables:
//!
//! - `FN_DOCS`: every function and method by path (`ggx::d`, `ggx::Ggx::d`, and trait
//!   methods both as `Trait::method` and under each implementing type), with its doc text;
//! - `MOD_DOCS`: every module's inner doc (`//!`) by module path (`ggx`, `ibl::dfg`).
//!
//! Items a `macro_rules!` generates are not expanded here: a kernel whose doc lives only in a
//! macro invocation falls back, at import, to its type's or its trait's doc and the table's
//! summary (`python/tests/test_docs.py` keeps the count of those in check).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use syn::{Attribute, ImplItem, Item, TraitItem, Type};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The doc comment of `attrs`: each `#[doc = "..."]` line with the one space rustdoc strips.
fn doc(attrs: &[Attribute]) -> String {
    let mut lines = Vec::new();
    for a in attrs {
        if !a.path().is_ident("doc") {
            continue;
        }
        if let syn::Meta::NameValue(nv) = &a.meta
            && let syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(s),
                ..
            }) = &nv.value
        {
            let v = s.value();
            lines.push(v.strip_prefix(' ').unwrap_or(&v).to_string());
        }
    }
    lines.join("\n").trim().to_string()
}

fn join(module: &str, name: &str) -> String {
    if module.is_empty() {
        name.to_string()
    } else {
        format!("{module}::{name}")
    }
}

fn type_name(ty: &Type) -> Option<String> {
    match ty {
        Type::Path(p) => p.path.segments.last().map(|s| s.ident.to_string()),
        Type::Reference(r) => type_name(&r.elem),
        _ => None,
    }
}

/// Whether `file` declares `pub mod name` (a module reachable by its own path) rather than
/// `mod name; pub use name::*` (items re-exported into the parent).
fn is_pub_mod(file: &syn::File, name: &str) -> bool {
    file.items.iter().any(|i| {
        matches!(i, Item::Mod(m) if m.ident == name && matches!(m.vis, syn::Visibility::Public(_)))
    })
}

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default());
    let src = manifest.join("../src");
    println!("cargo:rerun-if-changed={}", src.display());
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    for f in &files {
        println!("cargo:rerun-if-changed={}", f.display());
    }
    let parsed: Vec<(PathBuf, syn::File)> = files
        .iter()
        .filter_map(|p| {
            let text = std::fs::read_to_string(p).ok()?;
            let file = syn::parse_file(&text).ok()?;
            Some((p.strip_prefix(&src).ok()?.to_path_buf(), file))
        })
        .collect();
    let folder_mods: BTreeMap<PathBuf, &syn::File> = parsed
        .iter()
        .filter(|(p, _)| p.file_name().is_some_and(|f| f == "mod.rs"))
        .map(|(p, f)| (p.parent().map(Path::to_path_buf).unwrap_or_default(), f))
        .collect();
    let lib = parsed
        .iter()
        .find(|(p, _)| p == Path::new("lib.rs"))
        .map(|(_, f)| f);

    let mut fn_docs: BTreeMap<String, String> = BTreeMap::new();
    let mut mod_docs: BTreeMap<String, String> = BTreeMap::new();
    let mut type_docs: BTreeMap<String, String> = BTreeMap::new();
    // Trait default and declared methods: `Trait::method` -> doc.
    let mut trait_docs: BTreeMap<String, String> = BTreeMap::new();
    // (type path, trait name, methods the impl defines without a doc of their own).
    let mut trait_impls: Vec<(String, String, Vec<String>)> = Vec::new();

    for (p, file) in &parsed {
        let mut parts: Vec<String> = p
            .parent()
            .map(|d| d.iter().map(|s| s.to_string_lossy().into_owned()).collect())
            .unwrap_or_default();
        let stem = p
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        if stem != "mod" && stem != "lib" {
            let folder = p.parent().map(Path::to_path_buf).unwrap_or_default();
            let public = match folder_mods.get(&folder) {
                Some(m) => is_pub_mod(m, &stem),
                None => lib.is_some_and(|l| is_pub_mod(l, &stem)),
            };
            if public {
                parts.push(stem);
            }
        }
        let module = parts.join("::");
        let inner = doc(&file.attrs);
        if !inner.is_empty() {
            mod_docs.entry(module.clone()).or_insert(inner);
        }
        for item in &file.items {
            match item {
                Item::Fn(f) => {
                    fn_docs.insert(join(&module, &f.sig.ident.to_string()), doc(&f.attrs));
                }
                Item::Struct(s) => {
                    type_docs.insert(join(&module, &s.ident.to_string()), doc(&s.attrs));
                }
                Item::Enum(e) => {
                    type_docs.insert(join(&module, &e.ident.to_string()), doc(&e.attrs));
                }
                Item::Trait(t) => {
                    for ti in &t.items {
                        if let TraitItem::Fn(f) = ti {
                            trait_docs
                                .insert(format!("{}::{}", t.ident, f.sig.ident), doc(&f.attrs));
                        }
                    }
                }
                Item::Impl(im) => {
                    let Some(ty) = type_name(&im.self_ty) else {
                        continue;
                    };
                    let ty_path = join(&module, &ty);
                    let mut undocumented = Vec::new();
                    for ii in &im.items {
                        if let ImplItem::Fn(f) = ii {
                            let d = doc(&f.attrs);
                            let path = format!("{ty_path}::{}", f.sig.ident);
                            if d.is_empty() {
                                undocumented.push(f.sig.ident.to_string());
                            } else {
                                fn_docs.insert(path, d);
                            }
                        }
                    }
                    if let Some((_, tr, _)) = &im.trait_
                        && let Some(last) = tr.segments.last()
                    {
                        trait_impls.push((ty_path, last.ident.to_string(), undocumented));
                    }
                }
                _ => {}
            }
        }
    }
    // A trait method implemented without a doc of its own reads the trait's.
    for (ty_path, tr, methods) in &trait_impls {
        for m in methods {
            if let Some(d) = trait_docs.get(&format!("{tr}::{m}")) {
                fn_docs
                    .entry(format!("{ty_path}::{m}"))
                    .or_insert_with(|| d.clone());
            }
        }
    }
    for (k, v) in &trait_docs {
        fn_docs.entry(k.clone()).or_insert_with(|| v.clone());
    }
    for (k, v) in type_docs {
        fn_docs.entry(format!("{k}::")).or_insert(v);
    }
    fn_docs.retain(|_, v| !v.is_empty());

    let mut out = String::new();
    let table = |out: &mut String, name: &str, what: &str, map: &BTreeMap<String, String>| {
        let _ = writeln!(out, "/// {what}, sorted by path.");
        let _ = writeln!(out, "pub static {name}: &[(&str, &str)] = &[");
        for (k, v) in map {
            let _ = writeln!(out, "    ({k:?}, {v:?}),");
        }
        let _ = writeln!(out, "];");
    };
    table(
        &mut out,
        "FN_DOCS",
        "Doc comments of functions and methods (a type's own doc under `path::`)",
        &fn_docs,
    );
    table(
        &mut out,
        "MOD_DOCS",
        "Inner doc comments of modules",
        &mod_docs,
    );
    let dest = PathBuf::from(std::env::var("OUT_DIR").unwrap_or_default()).join("docs.rs");
    if let Err(e) = std::fs::write(&dest, out) {
        println!("cargo:warning=cannot write {}: {e}", dest.display());
    }
}
