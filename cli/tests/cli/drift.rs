//! The table cannot drift from the functions: `brdf`'s `src/**/*.rs` is parsed with `syn`,
//! each table path's function (free function, inherent or trait method, trait default, or a
//! method of a type a `macro_rules!` defines) is found, and its parameters, flattened by the
//! rules of `brdf_ref::table`'s module docs, must be the table's argument names in order.
//! Renaming or reordering a parameter in the crate fails this test.

use brdf_ref::KERNELS;
use brdf_ref::table::{BUILDERS, CONSTRUCTORS};
use quote::ToTokens;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use syn::{FnArg, GenericParam, ImplItem, Item, Pat, Signature, TraitItem, Type};

/// Types whose values are one integer argument naming a choice (an enum or a set of
/// constants), by type name.
const CHOICE_TYPES: &[&str] = &[
    "AgxLook",
    "Convention",
    "DiffuseCoupling",
    "Operator",
    "Transport",
];

/// One parsed source file and the module path its public items have.
struct Source {
    module: String,
    /// Whether the file's items are reachable from outside the crate (not `mod domain;`).
    public: bool,
    file: syn::File,
}

/// Every function and method of the crate, by path.
#[derive(Default)]
struct Index {
    /// `module::fn`, `module::Type::method`.
    fns: HashMap<String, Signature>,
    /// Trait default methods: `Trait::method`.
    trait_fns: HashMap<String, Signature>,
    /// The traits each type implements: `module::Type` -> trait names.
    impls: HashMap<String, Vec<String>>,
    /// Public named fields of structs: `module::Type`.
    fields: HashMap<String, Vec<String>>,
    /// Type name -> its path (`Ggx` -> `ggx::Ggx`).
    types: HashMap<String, String>,
    /// Every public function and method a user can call, by path (trait methods under each
    /// implementing type of the crate).
    public: Vec<String>,
}

/// The `.rs` files under `dir`, recursively, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).expect("src is readable") {
        let p = e.expect("a directory entry").path();
        if p.is_dir() {
            out.extend(rust_files(&p));
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
    out.sort();
    out
}

/// The crate's sources: (path relative to `src`, text).
fn crate_sources() -> Vec<(PathBuf, String)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../src");
    rust_files(&src)
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("a readable source");
            (p.strip_prefix(&src).expect("under src").to_path_buf(), text)
        })
        .collect()
}

/// Whether `file` (a `mod.rs`) makes its submodule `name` public as a module (`pub mod
/// name`) rather than re-exporting its items (`mod name; pub use name::*`).
fn is_pub_mod(file: &syn::File, name: &str) -> bool {
    let public = |m: &syn::ItemMod| matches!(m.vis, syn::Visibility::Public(_));
    file.items
        .iter()
        .any(|i| matches!(i, Item::Mod(m) if m.ident == name && public(m)))
}

/// Parses the sources and gives each its module path.
fn parse(sources: &[(PathBuf, String)]) -> Vec<Source> {
    let parsed: Vec<(PathBuf, syn::File)> = sources
        .iter()
        .map(|(p, t)| {
            (
                p.clone(),
                syn::parse_file(t).unwrap_or_else(|e| panic!("{}: {e}", p.display())),
            )
        })
        .collect();
    let mods: HashMap<PathBuf, &syn::File> = parsed
        .iter()
        .filter(|(p, _)| p.file_name().is_some_and(|f| f == "mod.rs"))
        .map(|(p, f)| (p.parent().expect("a folder").to_path_buf(), f))
        .collect();
    let lib = parsed
        .iter()
        .find(|(p, _)| p == Path::new("lib.rs"))
        .map(|(_, f)| f);
    parsed
        .iter()
        .map(|(p, f)| {
            let mut parts: Vec<String> = p
                .parent()
                .map(|d| d.iter().map(|s| s.to_string_lossy().into_owned()).collect())
                .unwrap_or_default();
            let stem = p
                .file_stem()
                .expect("a file name")
                .to_string_lossy()
                .into_owned();
            let mut reachable = true;
            if stem != "mod" && stem != "lib" {
                let folder = p.parent().expect("a folder").to_path_buf();
                let public = match mods.get(&folder) {
                    Some(m) => is_pub_mod(m, &stem),
                    None => {
                        // A top-level file: public where lib.rs says `pub mod`.
                        reachable = lib.is_some_and(|l| is_pub_mod(l, &stem));
                        true
                    }
                };
                if public {
                    parts.push(stem);
                }
            }
            Source {
                module: parts.join("::"),
                public: reachable,
                file: f.clone(),
            }
        })
        .collect()
}

fn join(module: &str, name: &str) -> String {
    if module.is_empty() {
        name.to_string()
    } else {
        format!("{module}::{name}")
    }
}

/// The name of the type an `impl` block is for (`Ggx` of `Ggx<T>`).
fn type_name(ty: &Type) -> Option<String> {
    match ty {
        Type::Path(p) => p.path.segments.last().map(|s| s.ident.to_string()),
        Type::Reference(r) => type_name(&r.elem),
        _ => None,
    }
}

/// The text of a `macro_rules!` transcriber with its metavariables replaced and its
/// repetitions (the doc attributes) removed.
fn expand(transcriber: &str, vars: &HashMap<String, String>) -> String {
    let mut out = String::new();
    let mut rest = transcriber;
    while let Some(i) = rest.find('$') {
        out.push_str(&rest[..i]);
        let after = rest[i + 1..].trim_start();
        if let Some(group) = after.strip_prefix('(') {
            // A repetition `$( ... ) *`: skip to its matching parenthesis and the `*`.
            let mut depth = 1;
            let mut end = 0;
            for (j, c) in group.char_indices() {
                depth += match c {
                    '(' => 1,
                    ')' => -1,
                    _ => 0,
                };
                if depth == 0 {
                    end = j + 1;
                    break;
                }
            }
            rest = group[end..].trim_start().trim_start_matches('*');
        } else {
            let name: String = after
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            out.push_str(vars.get(&name).map_or("__unknown", String::as_str));
            rest = &after[name.len()..];
        }
    }
    out.push_str(rest);
    out
}

/// The items `macro_rules!` definitions generate at their invocations in `file`.
fn macro_items(file: &syn::File) -> Vec<Item> {
    let mut rules: HashMap<String, (Vec<String>, String)> = HashMap::new();
    for item in &file.items {
        if let Item::Macro(m) = item
            && m.mac.path.is_ident("macro_rules")
            && let Some(ident) = &m.ident
        {
            let text = m.mac.tokens.to_string();
            let (matcher, transcriber) = text.split_once("=>").expect("one macro rule");
            // Top-level `$name : ident` metavariables of the matcher, in order.
            let mut depth = 0;
            let mut vars = Vec::new();
            let m_chars: Vec<char> = matcher.chars().collect();
            for (i, c) in m_chars.iter().enumerate() {
                match c {
                    '(' | '[' | '{' => depth += 1,
                    ')' | ']' | '}' => depth -= 1,
                    '$' if depth == 1 => {
                        let name: String = m_chars[i + 1..]
                            .iter()
                            .skip_while(|c| c.is_whitespace())
                            .take_while(|c| c.is_alphanumeric() || **c == '_')
                            .collect();
                        if !name.is_empty() {
                            vars.push(name);
                        }
                    }
                    _ => {}
                }
            }
            let body = transcriber.trim().trim_end_matches(';').trim();
            let body = body
                .strip_prefix('{')
                .and_then(|b| b.strip_suffix('}'))
                .unwrap_or(body);
            rules.insert(ident.to_string(), (vars, body.to_string()));
        }
    }
    let mut out = Vec::new();
    for item in &file.items {
        if let Item::Macro(m) = item
            && m.ident.is_none()
            && let Some(name) = m.mac.path.get_ident()
            && let Some((vars, body)) = rules.get(&name.to_string())
        {
            // Arguments: the last identifier of each comma-separated part.
            let text = m.mac.tokens.to_string();
            let mut depth = 0;
            let mut parts = vec![String::new()];
            for c in text.chars() {
                match c {
                    '(' | '[' | '{' => depth += 1,
                    ')' | ']' | '}' => depth -= 1,
                    _ => {}
                }
                if c == ',' && depth == 0 {
                    parts.push(String::new());
                } else {
                    parts.last_mut().expect("a part").push(c);
                }
            }
            let values: Vec<String> = parts
                .iter()
                .filter(|p| !p.trim().is_empty())
                .map(|p| {
                    p.split_whitespace()
                        .last()
                        .expect("an identifier")
                        .to_string()
                })
                .collect();
            let map: HashMap<String, String> = vars.iter().cloned().zip(values).collect();
            let expanded = expand(body, &map);
            let f = syn::parse_file(&expanded).unwrap_or_else(|e| panic!("expanding {name}!: {e}"));
            out.extend(f.items);
        }
    }
    out
}

fn index(sources: &[Source]) -> Index {
    let mut ix = Index::default();
    // Trait methods are public through every type of the crate that implements the trait.
    let add_trait_methods = |ix: &mut Index| {
        let mut extra = Vec::new();
        for (ty, traits) in &ix.impls {
            for tr in traits {
                for key in ix.trait_fns.keys() {
                    if let Some(m) = key.strip_prefix(&format!("{tr}::")) {
                        extra.push(format!("{ty}::{m}"));
                    }
                }
            }
        }
        extra.sort();
        ix.public.extend(extra);
    };
    for s in sources {
        let mut items = s.file.items.clone();
        items.extend(macro_items(&s.file));
        for item in &items {
            match item {
                Item::Fn(f) => {
                    let path = join(&s.module, &f.sig.ident.to_string());
                    if s.public && matches!(f.vis, syn::Visibility::Public(_)) {
                        ix.public.push(path.clone());
                    }
                    ix.fns.insert(path, f.sig.clone());
                }
                Item::Struct(st) => {
                    let path = join(&s.module, &st.ident.to_string());
                    ix.types.insert(st.ident.to_string(), path.clone());
                    let fields = st
                        .fields
                        .iter()
                        .filter(|f| matches!(f.vis, syn::Visibility::Public(_)))
                        .filter_map(|f| f.ident.as_ref().map(ToString::to_string))
                        .collect();
                    ix.fields.insert(path, fields);
                }
                Item::Enum(e) => {
                    ix.types
                        .insert(e.ident.to_string(), join(&s.module, &e.ident.to_string()));
                }
                Item::Trait(t) => {
                    for ti in &t.items {
                        if let TraitItem::Fn(f) = ti {
                            ix.trait_fns
                                .insert(format!("{}::{}", t.ident, f.sig.ident), f.sig.clone());
                        }
                    }
                }
                Item::Impl(im) => {
                    let Some(ty) = type_name(&im.self_ty) else {
                        continue;
                    };
                    let ty_path = join(&s.module, &ty);
                    if let Some((_, tr, _)) = &im.trait_ {
                        let tr = tr.segments.last().expect("a trait").ident.to_string();
                        ix.impls.entry(ty_path.clone()).or_default().push(tr);
                    }
                    for ii in &im.items {
                        if let ImplItem::Fn(f) = ii {
                            let path = format!("{ty_path}::{}", f.sig.ident);
                            if s.public
                                && im.trait_.is_none()
                                && matches!(f.vis, syn::Visibility::Public(_))
                            {
                                ix.public.push(path.clone());
                            }
                            ix.fns.insert(path, f.sig.clone());
                        }
                    }
                }
                _ => {}
            }
        }
    }
    ix.impls.retain(|ty, _| ix.types.values().any(|p| p == ty));
    add_trait_methods(&mut ix);
    ix.public.sort();
    ix.public.dedup();
    ix
}

impl Index {
    /// The signature of a table path: a function, a method of the type (its own, from an
    /// implemented trait, or the trait's default).
    fn signature(&self, path: &str) -> Option<&Signature> {
        if let Some(s) = self.fns.get(path) {
            return Some(s);
        }
        let (ty, method) = path.rsplit_once("::")?;
        self.impls
            .get(ty)?
            .iter()
            .find_map(|tr| self.trait_fns.get(&format!("{tr}::{method}")))
    }
}

/// One parameter's arguments: alternatives (`_x/_y/_z` or `_r/_g/_b`), and the parameter
/// name when they come from a constructor (for the collision prefix).
struct Group {
    alternatives: Vec<Vec<String>>,
    constructor_of: Option<String>,
}

fn plain(names: Vec<String>) -> Group {
    Group {
        alternatives: vec![names],
        constructor_of: None,
    }
}

fn vector(name: &str) -> Group {
    Group {
        alternatives: vec![
            ["x", "y", "z"]
                .iter()
                .map(|c| format!("{name}_{c}"))
                .collect(),
            ["r", "g", "b"]
                .iter()
                .map(|c| format!("{name}_{c}"))
                .collect(),
        ],
        constructor_of: None,
    }
}

fn snake(ty: &str) -> String {
    let mut s = String::new();
    for (i, c) in ty.chars().enumerate() {
        if c.is_uppercase() && i > 0 {
            s.push('_');
        }
        s.extend(c.to_lowercase());
    }
    s
}

/// The argument groups of a validated parameter type (its constructor's parameters).
fn constructor(ix: &Index, ty_path: &str, param: &str) -> Result<Vec<Group>, String> {
    let (_, ctor) = CONSTRUCTORS
        .iter()
        .find(|(t, _)| *t == ty_path)
        .ok_or_else(|| format!("no constructor listed for {ty_path} (table::CONSTRUCTORS)"))?;
    let groups = if *ctor == "{fields}" {
        vec![plain(
            ix.fields
                .get(ty_path)
                .cloned()
                .ok_or_else(|| format!("no struct {ty_path}"))?,
        )]
    } else {
        let sig = ix
            .fns
            .get(&format!("{ty_path}::{ctor}"))
            .ok_or_else(|| format!("no constructor {ty_path}::{ctor}"))?;
        params(ix, sig, None)?
    };
    let mut out: Vec<Group> = groups
        .into_iter()
        .map(|g| Group {
            constructor_of: Some(param.to_string()),
            ..g
        })
        .collect();
    out.extend(builders(ix, ty_path)?);
    Ok(out)
}

/// The argument groups of a type's optional extensions (`table::BUILDERS`): each builder's
/// parameters after its receiver, flattened, prefixed with the builder's name less `with_`
/// unless already so named.
fn builders(ix: &Index, ty_path: &str) -> Result<Vec<Group>, String> {
    let Some((_, methods)) = BUILDERS.iter().find(|(t, _)| *t == ty_path) else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    for m in *methods {
        let sig = ix
            .fns
            .get(&format!("{ty_path}::{m}"))
            .ok_or_else(|| format!("no builder {ty_path}::{m}"))?;
        let prefix = m
            .strip_prefix("with_")
            .ok_or_else(|| format!("builder {ty_path}::{m} is not named with_*"))?;
        for input in &sig.inputs {
            let FnArg::Typed(pt) = input else { continue };
            let Pat::Ident(id) = &*pt.pat else {
                return Err(format!(
                    "{ty_path}::{m}: a parameter pattern that is not a name"
                ));
            };
            for g in param(ix, sig, Some(ty_path), &id.ident.to_string(), &pt.ty)? {
                let alternatives = g
                    .alternatives
                    .into_iter()
                    .map(|alt| {
                        alt.into_iter()
                            .map(|n| {
                                if n == prefix || n.starts_with(&format!("{prefix}_")) {
                                    n
                                } else {
                                    format!("{prefix}_{n}")
                                }
                            })
                            .collect()
                    })
                    .collect();
                out.push(Group {
                    alternatives,
                    constructor_of: None,
                });
            }
        }
    }
    Ok(out)
}

/// The argument groups of one parameter `name: ty` of `sig` (a method of `self_ty`).
fn param(
    ix: &Index,
    sig: &Signature,
    self_ty: Option<&str>,
    name: &str,
    ty: &Type,
) -> Result<Vec<Group>, String> {
    let mut text = ty.to_token_stream().to_string().replace(' ', "");
    if text.trim_start_matches('&') == "Self" && self_ty.is_some_and(|t| t.ends_with("::V3")) {
        text = "V3<T>".to_string();
    }
    let generic_bound = |ident: &str| {
        sig.generics.params.iter().find_map(|g| match g {
            GenericParam::Type(t) if t.ident == ident => {
                Some(t.bounds.to_token_stream().to_string().replace(' ', ""))
            }
            _ => None,
        })
    };
    let inner = text.trim_start_matches('&');
    Ok(match inner {
        "T" | "f64" | "f32" => vec![plain(vec![name.to_string()])],
        "V3<T>" => vec![vector(name)],
        // The four cosines of a shading point, by field, in the crate's one order.
        "Cosines<T>" => vec![plain(
            ["n_dot_v", "n_dot_l", "n_dot_h", "v_dot_h"]
                .iter()
                .map(ToString::to_string)
                .collect(),
        )],
        "Mat3" => vec![plain(
            (0..3)
                .flat_map(|i| (0..3).map(move |j| format!("{name}_{i}_{j}")))
                .collect(),
        )],
        "[V3<T>;9]" => vec![plain(
            (0..9)
                .flat_map(|k| ["r", "g", "b"].map(|c| format!("{name}_{k}_{c}")))
                .collect(),
        )],
        "implFn(T)->T" => vec![plain(vec![name.to_string()])],
        // A complex IOR with named parts: its eta, then its k.
        "ComplexIor<V3<T>>" => vec![vector("eta"), vector("k")],
        // The energy terms' named wrappers: one argument each.
        "Albedo<T>" | "AverageAlbedo<T>" | "Reflectance<T>" | "Alpha<T>" => {
            vec![plain(vec![name.to_string()])]
        }
        "implFn(T)->V3<T>" => vec![vector(name)],
        _ => {
            let ty_name = type_name(ty).ok_or_else(|| format!("parameter {name}: type {text}"))?;
            if let Some(bound) = generic_bound(&ty_name) {
                if !bound.contains("Microfacet") {
                    return Err(format!("parameter {name}: generic {ty_name}: {bound}"));
                }
                let g = constructor(ix, "ggx::Ggx", name)?;
                let b = constructor(ix, "beckmann::Beckmann", name)?;
                let names = |gs: &[Group]| {
                    gs.iter()
                        .map(|g| g.alternatives[0].clone())
                        .collect::<Vec<_>>()
                };
                if names(&g) != names(&b) {
                    return Err("Ggx::new and Beckmann::new take different parameters".into());
                }
                let mut out = vec![plain(vec!["model".to_string()])];
                out.extend(g.into_iter().map(|g| Group {
                    constructor_of: None,
                    ..g
                }));
                out
            } else if CHOICE_TYPES.contains(&ty_name.as_str()) {
                vec![plain(vec![name.to_string()])]
            } else {
                let path = ix
                    .types
                    .get(&ty_name)
                    .ok_or_else(|| format!("unknown type {ty_name}"))?;
                constructor(ix, path, name)?
            }
        }
    })
}

/// The argument groups of `sig`, with the receiver of type `self_ty` (a method) first.
fn params(ix: &Index, sig: &Signature, self_ty: Option<&str>) -> Result<Vec<Group>, String> {
    let mut out = Vec::new();
    for input in &sig.inputs {
        match input {
            FnArg::Receiver(_) => {
                let ty = self_ty.ok_or("a receiver outside a method")?;
                let name = ty.rsplit("::").next().unwrap_or(ty);
                if name == "V3" {
                    out.push(vector("self"));
                } else if CHOICE_TYPES.contains(&name) {
                    out.push(plain(vec![snake(name)]));
                } else {
                    out.extend(constructor(ix, ty, "self")?);
                }
            }
            FnArg::Typed(pt) => {
                let Pat::Ident(id) = &*pt.pat else {
                    return Err("a parameter pattern that is not a name".into());
                };
                out.extend(param(ix, sig, self_ty, &id.ident.to_string(), &pt.ty)?);
            }
        }
    }
    // A constructor's names that clash with another argument's are all prefixed with the
    // parameter's name.
    let all: Vec<String> = out.iter().flat_map(|g| g.alternatives[0].clone()).collect();
    let clashing: Vec<String> = out
        .iter()
        .filter(|g| {
            g.alternatives[0]
                .iter()
                .any(|n| all.iter().filter(|m| *m == n).count() > 1)
        })
        .filter_map(|g| g.constructor_of.clone())
        .collect();
    for g in &mut out {
        if let Some(p) = g.constructor_of.as_ref().filter(|p| clashing.contains(p)) {
            for alt in &mut g.alternatives {
                for n in alt.iter_mut() {
                    *n = format!("{p}_{n}");
                }
            }
        }
    }
    Ok(out)
}

/// Whether the table's `names` are exactly the groups' arguments in order.
fn matches(groups: &[Group], names: &[&str]) -> bool {
    let mut pos = 0;
    for g in groups {
        let len = g.alternatives[0].len();
        let Some(slice) = names.get(pos..pos + len) else {
            return false;
        };
        if !g
            .alternatives
            .iter()
            .any(|alt| alt.iter().zip(slice).all(|(a, b)| a == b))
        {
            return false;
        }
        pos += len;
    }
    pos == names.len()
}

/// Every table entry whose argument names are not its function's parameters, as messages.
fn drift(sources: &[(PathBuf, String)]) -> Vec<String> {
    let parsed = parse(sources);
    let ix = index(&parsed);
    let mut problems = Vec::new();
    for k in KERNELS {
        let Some(sig) = ix.signature(k.path) else {
            problems.push(format!("{}: no such function in brdf's source", k.path));
            continue;
        };
        let self_ty = k.path.rsplit_once("::").map(|(t, _)| t).filter(|t| {
            t.rsplit("::")
                .next()
                .is_some_and(|s| s.starts_with(char::is_uppercase))
        });
        let names: Vec<&str> = k.args.iter().map(|a| a.name).collect();
        match params(&ix, sig, self_ty) {
            Ok(groups) if matches(&groups, &names) => {}
            Ok(groups) => {
                let want: Vec<String> = groups
                    .iter()
                    .flat_map(|g| g.alternatives[0].clone())
                    .collect();
                problems.push(format!(
                    "{}: the table's arguments ({}) are not the function's ({})",
                    k.path,
                    names.join(", "),
                    want.join(", ")
                ));
            }
            Err(e) => problems.push(format!("{}: {e}", k.path)),
        }
    }
    problems
}

#[test]
fn table_arguments_are_the_functions_parameters() {
    let problems = drift(&crate_sources());
    assert!(
        problems.is_empty(),
        "the table drifted from brdf's source:\n{}",
        problems.join("\n")
    );
}

/// Replaces the first occurrence of `from` in the source file `file` (which must contain it).
fn edited(file: &str, from: &str, to: &str) -> Vec<(PathBuf, String)> {
    let mut sources = crate_sources();
    let (_, text) = sources
        .iter_mut()
        .find(|(p, _)| p == Path::new(file))
        .unwrap_or_else(|| panic!("no source {file}"));
    assert!(text.contains(from), "{file} no longer contains `{from}`");
    *text = text.replacen(from, to, 1);
    sources
}

#[test]
fn drift_is_caught_when_a_parameter_is_renamed_or_reordered() {
    let renamed = drift(&edited(
        "ggx.rs",
        "pub fn d<T: Real>(n_dot_h: T, alpha: T)",
        "pub fn d<T: Real>(cos_h: T, alpha: T)",
    ));
    assert!(
        renamed.iter().any(|p| p.starts_with("ggx::d:")),
        "a renamed parameter: {renamed:?}"
    );
    let reordered = drift(&edited(
        "lights.rs",
        "pub fn spot_cone<T: Real>(cos_angle: T, cos_outer: T, cos_inner: T)",
        "pub fn spot_cone<T: Real>(cos_angle: T, cos_inner: T, cos_outer: T)",
    ));
    assert!(
        reordered
            .iter()
            .any(|p| p.starts_with("lights::spot_cone:")),
        "reordered parameters: {reordered:?}"
    );
    let ctor = drift(&edited(
        "ggx.rs",
        "pub fn new(alpha_x: T, alpha_y: T)",
        "pub fn new(alpha_y: T, alpha_x: T)",
    ));
    assert!(
        ctor.iter().any(|p| p.starts_with("ggx::Ggx::d:")),
        "a constructor's parameters: {ctor:?}"
    );
    let macro_type = drift(&edited(
        "phong.rs",
        "pub fn new(ks: T, exponent: T) -> Result<Self, ParamError> {\n                validate",
        "pub fn new(exponent: T, ks: T) -> Result<Self, ParamError> {\n                validate",
    ));
    assert!(
        macro_type
            .iter()
            .any(|p| p.starts_with("phong::BlinnPhong::eval:")),
        "a macro-defined type's constructor: {macro_type:?}"
    );
    let builder = drift(&edited(
        "layers/layered.rs",
        "pub fn with_transmission(self, transmission: T)",
        "pub fn with_transmission(self, factor: T)",
    ));
    assert!(
        builder
            .iter()
            .any(|p| p.starts_with("layers::layered::Layered::eval:")),
        "a builder's parameters: {builder:?}"
    );
}

/// Builders of the types in `table::BUILDERS` that are not extensions the rows take, with
/// the reason.
const BUILDERS_LEFT_OUT: &[(&str, &str)] = &[
    (
        "layers::layered::Layered::with_clearcoat_normal",
        "the coat's normal is geometry (a normal map's texel), not a parameter of the extension's \
         factors; the rows keep the shading normal",
    ),
    (
        "layers::layered::Layered::with_clearcoat_normal_world",
        "world-space form of with_clearcoat_normal",
    ),
    (
        "layers::layered::Layered::with_compensation",
        "a switch of the crate's energy compensation, not a glTF extension (off, as in the \
         extensions)",
    ),
];

#[test]
fn every_builder_of_a_type_with_extensions_is_in_its_rows_or_left_out_with_a_reason() {
    let ix = index(&parse(&crate_sources()));
    for (ty, methods) in BUILDERS {
        for p in ix
            .public
            .iter()
            .filter(|p| p.starts_with(&format!("{ty}::with_")))
        {
            let listed = methods.iter().any(|m| *p == format!("{ty}::{m}"));
            let left_out = BUILDERS_LEFT_OUT.iter().any(|(e, _)| e == p);
            assert!(
                listed != left_out,
                "{p}: a builder is either in table::BUILDERS or in BUILDERS_LEFT_OUT, once"
            );
        }
    }
    for (e, _) in BUILDERS_LEFT_OUT {
        assert!(ix.public.iter().any(|p| p == e), "{e} is no longer public");
    }
}

/// Why a public method is not a kernel by its signature alone: a constructor (no receiver,
/// or a builder's `self` by value, returning the type) or a getter (the receiver alone,
/// returning a stored or derived parameter).
fn by_rule(sig: &Signature) -> Option<&'static str> {
    let receiver = sig.inputs.iter().any(|i| matches!(i, FnArg::Receiver(_)));
    // A builder takes the value itself (`self`, not `&self`) and returns a new one.
    let by_value = sig
        .inputs
        .iter()
        .any(|i| matches!(i, FnArg::Receiver(r) if r.reference.is_none()));
    let out = match &sig.output {
        syn::ReturnType::Default => String::new(),
        syn::ReturnType::Type(_, t) => t.to_token_stream().to_string().replace(' ', ""),
    };
    if (!receiver || by_value)
        && (out.contains("Self") || out.starts_with("V3<"))
        && sig.ident != "all"
    {
        return Some("constructor");
    }
    let getter_types = [
        "T",
        "f64",
        "V3<T>",
        "[f64;3]",
        "DiffuseCoupling",
        "&[V3<T>;9]",
    ];
    (receiver && sig.inputs.len() == 1 && getter_types.contains(&out.as_str()))
        .then_some("getter of a parameter")
}

#[test]
fn every_public_function_is_in_the_table_or_excluded_with_a_reason() {
    let ix = index(&parse(&crate_sources()));
    let table: Vec<&str> = KERNELS.iter().map(|k| k.path).collect();
    let mut rule = 0;
    let mut missing = Vec::new();
    for p in &ix.public {
        if table.contains(&p.as_str()) || EXCLUDED.iter().any(|(e, _)| e == p) {
            continue;
        }
        let is_method = p
            .rsplit("::")
            .nth(1)
            .is_some_and(|t| t.starts_with(char::is_uppercase));
        if is_method && ix.fns.get(p).and_then(by_rule).is_some() {
            rule += 1;
        } else {
            missing.push(p);
        }
    }
    println!(
        "{} public functions: {} kernels in the table, {} constructors and getters, {} excluded by name",
        ix.public.len(),
        table.len(),
        rule,
        EXCLUDED.len()
    );
    for (e, why) in EXCLUDED {
        assert!(
            ix.public.iter().any(|p| p == e),
            "excluded {e} is no longer a public function"
        );
        assert!(
            !table.contains(e),
            "{e} is both in the table and excluded ({why})"
        );
    }
    assert!(
        missing.is_empty(),
        "public functions neither in the table nor excluded: {missing:?}"
    );
}

/// Public functions that are not pointwise scalar kernels (besides constructors and getters,
/// which [`by_rule`] recognises), with the reason.
const EXCLUDED: &[(&str, &str)] = &[
    ("batch::run", "runs a caller's kernel over slices"),
    ("batch::run_f32", "runs a caller's kernel over slices"),
    ("batch::run_f64", "runs a caller's kernel over slices"),
    (
        "batch::par_run",
        "runs a caller's kernel over slices on all cores",
    ),
    (
        "batch::par_run_f32",
        "runs a caller's kernel over slices on all cores",
    ),
    (
        "batch::par_run_f64",
        "runs a caller's kernel over slices on all cores",
    ),
    ("error::require", "validation helper of the constructors"),
    ("frame::same_hemisphere", "returns a lane mask, not a value"),
    (
        "ibl::dfg::dfg",
        "Monte Carlo estimate whose cost grows with its sample count (u32)",
    ),
    ("ibl::dfg::table", "writes a table into a caller's buffer"),
    (
        "ibl::dfg::table_filament",
        "writes a table into a caller's buffer",
    ),
    (
        "ibl::dfg::lookup",
        "reads a caller's table (a slice argument)",
    ),
    (
        "ibl::energy::e_ggx_estimate",
        "Monte Carlo estimate whose cost grows with its sample count (u32)",
    ),
    (
        "ibl::energy::e_avg_ggx_estimate",
        "Monte Carlo estimate whose cost grows with its sample count (u32)",
    ),
    (
        "ibl::energy::e_table",
        "writes a table into a caller's buffer",
    ),
    (
        "ibl::energy::e_avg_table",
        "writes a table into a caller's buffer",
    ),
    (
        "ibl::prefilter::hammersley",
        "integer (u32) index and count: no float lanes to carry them",
    ),
    (
        "ibl::prefilter::sample",
        "integer (u32) index and count; prefilter::sample_from is the kernel",
    ),
    ("ibl::prefilter::samples", "an iterator over samples"),
    (
        "ibl::prefilter::fill",
        "writes samples into a caller's buffer",
    ),
    (
        "ibl::irradiance::gauss_legendre",
        "integer (u32) order and node index",
    ),
    (
        "ibl::irradiance::irradiance",
        "quadrature of a caller's closure",
    ),
    (
        "ibl::irradiance::cube_texel_solid_angle",
        "integer (u32) face size and texel indices",
    ),
    (
        "ibl::irradiance::project",
        "quadrature of a caller's closure",
    ),
    (
        "ibl::irradiance::Sh9::add",
        "accumulates into the coefficients (mutates)",
    ),
    (
        "ibl::irradiance::Sh9::cosine_convolved",
        "rescales the 27 coefficients, not a value at a point",
    ),
    (
        "ibl::irradiance::Sh9::irradiance_matrix",
        "rearranges the 27 coefficients, not a value at a point",
    ),
    ("integrate::hemisphere", "integrator of a caller's closure"),
    ("integrate::sphere", "integrator of a caller's closure"),
    ("integrate::sphere_f32", "integrator of a caller's closure"),
    (
        "integrate::directional_albedo_sphere",
        "integrator of a caller's closure",
    ),
    (
        "integrate::hemisphere_f32",
        "integrator of a caller's closure",
    ),
    (
        "integrate::directional_albedo",
        "integrator of a caller's closure",
    ),
    (
        "integrate::directional_albedo_f32",
        "integrator of a caller's closure",
    ),
    (
        "integrate::directional_albedo_with",
        "integrator of a caller's closure",
    ),
    (
        "integrate::directional_albedo_with_f32",
        "integrator of a caller's closure",
    ),
    (
        "integrate::ndf_projected_area",
        "integrator of a caller's closure",
    ),
    (
        "integrate::ndf_projected_area_f32",
        "integrator of a caller's closure",
    ),
    (
        "integrate::smith_weak_furnace",
        "integrator of a caller's closure",
    ),
    (
        "integrate::smith_weak_furnace_f32",
        "integrator of a caller's closure",
    ),
    ("integrate::reciprocity", "integrator of a caller's closure"),
    (
        "integrate::reciprocity_f32",
        "integrator of a caller's closure",
    ),
    (
        "lights::Attenuation::eval",
        "dispatches to lights::inverse_square, windowed, windowed_inverse_square or polynomial (same bits), which are in the table",
    ),
    (
        "tonemap::Operator::all",
        "the list of operators (tonemap::Operator::apply takes an index into it)",
    ),
    (
        "tonemap::Operator::apply_vec3",
        "glam wrapper of tonemap::Operator::apply",
    ),
    (
        "tonemap::Operator::apply_vec3a",
        "glam wrapper of tonemap::Operator::apply",
    ),
    (
        "material::MetallicRoughness::eval_world",
        "world-space wrapper: MetallicRoughness::eval(sp.wo(), sp.local(l)), which is in the table",
    ),
    (
        "material::MetallicRoughness::pdf_world",
        "world-space wrapper: MetallicRoughness::pdf(sp.wo(), sp.local(l)), which is in the table",
    ),
    (
        "material::MetallicRoughness::sample_world",
        "world-space wrapper: sp.world of MetallicRoughness::sample(sp.wo(), u1, u2), which is in the table",
    ),
    (
        "material::MetallicRoughness::sample_weighted_world",
        "world-space wrapper: sp.world of MetallicRoughness::sample_weighted(sp.wo(), u1, u2), which is in the table",
    ),
    (
        "shading::ShadingPoint::local",
        "frame::Frame::to_local of the point's frame, which is in the table",
    ),
    (
        "shading::ShadingPoint::world",
        "frame::Frame::to_world of the point's frame, which is in the table",
    ),
    (
        "shading::ShadingPoint::cosines",
        "shading::Cosines::from_local of the point's view and the local light direction",
    ),
    (
        "shading::ShadingPoint::frame",
        "getter of the point's frame",
    ),
    ("vec3::V3::map", "applies a caller's closure per component"),
    (
        "vec3::V3::zip_map",
        "applies a caller's closure per component pair",
    ),
    ("vec3::V3::select", "lane select by a mask"),
    ("vec3::V3::lane", "lane accessor"),
    ("vec3::V3::to_array", "accessor"),
    ("vec3::V3::to_lanes", "transpose to glam vectors"),
    (
        "layers::sheen::albedo_estimate",
        "f64 cubature of one table entry",
    ),
    (
        "layers::sheen::albedo_table",
        "writes a table into a caller's buffer",
    ),
    (
        "layers::specular::Specular::dielectric_f0",
        "validated-parameter form of layers::specular::dielectric_f0, which is in the table",
    ),
    (
        "layers::layered::Layered::eval_world",
        "world-space wrapper: Layered::eval(sp.wo(), sp.local(l)), which is in the table",
    ),
    (
        "layers::layered::Layered::pdf_world",
        "world-space wrapper: Layered::pdf(sp.wo(), sp.local(l)), which is in the table",
    ),
    (
        "layers::layered::Layered::at_view",
        "prepares the material at a view for Prepared::eval, not a kernel",
    ),
    (
        "layers::layered::Prepared::eval",
        "prepared form of Layered::eval (bit for bit), which is in the table",
    ),
    (
        "layers::layered::Prepared::eval_view_only",
        "Layered::eval with the view-only albedo scaling, prepared per shading point: \
         Layered::at_view(wo).eval_view_only(wi)",
    ),
    (
        "layers::layered::Layered::sample_world",
        "world-space wrapper: sp.world of Layered::sample(sp.wo(), u1, u2), which is in the table",
    ),
];
