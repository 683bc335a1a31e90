//! Architecture test: the crate's layers (see `src/lib.rs` and ARCHITECTURE.md)
//! only import downwards. Every `crate::<module>` path in the code of a
//! top-level module is checked against the layer order; an import of a module
//! in the same or a higher layer fails the test, naming file and line.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Top-level modules from the bottom layer up. A module may use modules of
/// strictly lower rank only (siblings of one layer are ranked too, so the
/// order inside a layer is fixed as well).
const LAYERS: &[(&str, u32)] = &[
    // foundation
    ("error", 0),
    // io reports failed writes as the typed error
    ("io", 1),
    ("numeric", 1),
    ("mesh", 2),
    // scheme description (rules, stencils, host names, parameters)
    ("sdc", 3),
    // refinement hosts
    ("topology", 4),
    // the engine
    ("refine", 5),
    ("engine", 5),
    ("neighbourhood", 6),
    ("matrix", 7),
    ("dft", 8),
    ("spectrum", 9),
    // analyses on top of a spectrum, and the Z² / Z domains
    ("charmap", 10),
    ("lattice", 10),
    ("curves", 10),
    // second-order analysis: on top of the characteristic map
    ("curvature", 11),
    // certified verdicts: interval enclosures on top of the spectrum's driver
    ("certify", 11),
    // the scheme catalogue: nothing below may import it
    ("schemes", 12),
    // the shape chart: second-order projections on top of the curvature pipeline
    ("shape_chart", 12),
    ("sweep", 13),
    // claims of kind parameter-range read the exact sweep's sets
    ("claims", 14),
    ("plot", 14),
    // spectral proofs over all valences: per-valence certificates and the
    // exact sweep's subresultants and Sturm sequences
    ("every_valence", 14),
    ("report", 15),
    ("cli", 16),
];

fn rank(module: &str) -> Option<u32> {
    LAYERS.iter().find(|(m, _)| *m == module).map(|(_, r)| *r)
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src is readable") {
        let path = entry.expect("directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The top-level module a source file belongs to (`src/charmap/net.rs` →
/// `charmap`, `src/io.rs` → `io`); `None` for the crate roots.
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).ok()?;
    let first = rel.components().next()?.as_os_str().to_str()?.to_string();
    let name = first.strip_suffix(".rs").unwrap_or(&first).to_string();
    (name != "lib" && name != "main").then_some(name)
}

/// Every module named after `crate::` on a line of code (comments removed),
/// including the members of a grouped `use crate::{a, b::c}`.
fn crate_paths(line: &str) -> Vec<String> {
    let code = match line.find("//") {
        Some(k) => &line[..k],
        None => line,
    };
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(k) = rest.find("crate::") {
        rest = &rest[k + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let name: String = item.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                if !name.is_empty() {
                    out.push(name);
                }
            }
        } else {
            let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            if !name.is_empty() {
                out.push(name);
            }
        }
    }
    out
}

/// (file:line, importing module, imported module) of every upward or sideways import.
fn violations(src: &Path) -> Vec<String> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    files.sort();
    let mut out = Vec::new();
    for file in &files {
        let Some(module) = module_of(src, file) else { continue };
        let own = rank(&module).unwrap_or_else(|| panic!("module '{module}' has no layer in tests/layers.rs"));
        let text = std::fs::read_to_string(file).expect("source is readable");
        for (k, line) in text.lines().enumerate() {
            for used in crate_paths(line) {
                if used == module {
                    continue;
                }
                match rank(&used) {
                    Some(r) if r < own => {}
                    Some(_) => out.push(format!("{}:{}: {module} imports {used}", file.display(), k + 1)),
                    // a root item (`crate::prelude` is only in lib.rs) or a macro path
                    None => out.push(format!("{}:{}: {module} uses unknown crate::{used}", file.display(), k + 1)),
                }
            }
        }
    }
    out
}

#[test]
fn every_import_points_down_the_layers() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let bad = violations(&src);
    assert!(bad.is_empty(), "imports against the layer order:\n{}", bad.join("\n"));
}

#[test]
fn every_top_level_module_has_a_layer() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let lib = std::fs::read_to_string(src.join("lib.rs")).unwrap();
    let mods: BTreeMap<&str, bool> = lib
        .lines()
        .filter_map(|l| l.trim().strip_prefix("pub mod ")?.strip_suffix(';'))
        .map(|m| (m, rank(m).is_some()))
        .collect();
    assert!(!mods.is_empty());
    let missing: Vec<_> = mods.iter().filter(|(_, ok)| !**ok).map(|(m, _)| *m).collect();
    assert!(missing.is_empty(), "modules without a layer: {missing:?}");
}

/// Negative control: the checker itself must catch an upward import, a
/// grouped one and ignore one in a comment.
#[test]
fn the_checker_sees_upward_imports() {
    assert_eq!(crate_paths("use crate::schemes::Scheme;"), vec!["schemes"]);
    assert_eq!(crate_paths("use crate::{cli, sdc::Origin};"), vec!["cli", "sdc"]);
    assert!(crate_paths("// see crate::schemes").is_empty());
    // a folder of its own: every test of the suite binary runs in this process
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir_all(dir.path().join("matrix")).unwrap();
    std::fs::write(dir.path().join("matrix/local.rs"), "use crate::schemes::Scheme;\nuse crate::numeric::Weight;\n")
        .unwrap();
    let bad = violations(dir.path());
    assert_eq!(bad.len(), 1, "{bad:?}");
    assert!(bad[0].contains("matrix imports schemes"), "{bad:?}");
}

// ------------------------------------------------------------ file-level import cycles

/// The code of a Rust file as tokens (identifiers, `::` and single
/// punctuation characters) with their 1-based lines; comments, string,
/// byte-string, raw-string and character literals removed (a `{` inside a
/// format string is no brace), lifetimes kept as identifiers.
fn tokens(text: &str) -> Vec<(String, usize)> {
    let c: Vec<char> = text.chars().collect();
    let (mut out, mut line, mut k) = (Vec::new(), 1usize, 0usize);
    let newlines = |s: &[char]| s.iter().filter(|&&x| x == '\n').count();
    while k < c.len() {
        let ch = c[k];
        let next = c.get(k + 1).copied();
        if ch == '\n' {
            line += 1;
            k += 1;
        } else if ch.is_whitespace() {
            k += 1;
        } else if ch == '/' && next == Some('/') {
            while k < c.len() && c[k] != '\n' {
                k += 1;
            }
        } else if ch == '/' && next == Some('*') {
            // block comments nest in Rust
            let (mut depth, start) = (0usize, k);
            while k < c.len() {
                if c[k] == '/' && c.get(k + 1) == Some(&'*') {
                    depth += 1;
                    k += 2;
                } else if c[k] == '*' && c.get(k + 1) == Some(&'/') {
                    depth -= 1;
                    k += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    k += 1;
                }
            }
            line += newlines(&c[start..k.min(c.len())]);
        } else if let Some(hashes) = raw_string_at(&c, k) {
            // a raw string r#"..."# (or br"...")
            let start = k;
            k += (if ch == 'b' { 2 } else { 1 }) + hashes + 1;
            while k < c.len()
                && !(c[k] == '"' && c[k + 1..].iter().take(hashes).filter(|&&x| x == '#').count() == hashes)
            {
                k += 1;
            }
            k = (k + 1 + hashes).min(c.len());
            line += newlines(&c[start..k]);
        } else if ch == '"' || (ch == 'b' && next == Some('"')) {
            let start = k;
            k += if ch == 'b' { 2 } else { 1 };
            while k < c.len() && c[k] != '"' {
                k += if c[k] == '\\' { 2 } else { 1 };
            }
            k = (k + 1).min(c.len());
            line += newlines(&c[start..k]);
        } else if ch == '\'' {
            // a character literal ('x', '\n', '\u{7f}', '{') or a lifetime ('a)
            if next == Some('\\') {
                k += 2;
                while k < c.len() && c[k] != '\'' {
                    k += 1;
                }
                k += 1;
            } else if c.get(k + 2) == Some(&'\'') {
                k += 3;
            } else {
                k += 1;
            }
        } else if ch.is_alphanumeric() || ch == '_' {
            let start = k;
            while k < c.len() && (c[k].is_alphanumeric() || c[k] == '_') {
                k += 1;
            }
            out.push((c[start..k].iter().collect(), line));
        } else if ch == ':' && next == Some(':') {
            out.push(("::".to_string(), line));
            k += 2;
        } else {
            out.push((ch.to_string(), line));
            k += 1;
        }
    }
    out
}

/// The number of `#` of a raw string literal starting at `k` (`r"`, `r#"`,
/// `br"`), or `None` when none starts there.
fn raw_string_at(c: &[char], k: usize) -> Option<usize> {
    if k > 0 && (c[k - 1].is_alphanumeric() || c[k - 1] == '_') {
        return None;
    }
    let j = match (c.get(k), c.get(k + 1)) {
        (Some('r'), _) => k + 1,
        (Some('b'), Some('r')) => k + 2,
        _ => return None,
    };
    let hashes = c[j..].iter().take_while(|&&x| x == '#').count();
    (c.get(j + hashes) == Some(&'"')).then_some(hashes)
}

/// The module path of a source file under `src` (`claims/checks/size.rs` →
/// [claims, checks, size], `claims/mod.rs` → [claims], `lib.rs` → []).
fn module_path(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).expect("a file under src");
    let mut parts: Vec<String> = rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
    let last = parts.pop().expect("a file name");
    let stem = last.strip_suffix(".rs").unwrap_or(&last).to_string();
    if !(stem == "mod" || (parts.is_empty() && (stem == "lib" || stem == "main"))) {
        parts.push(stem);
    }
    parts
}

/// The paths of a `use` tree (`a::{b, c::{d, e}}` → a::b, a::c::d, a::c::e),
/// `self` inside a group standing for the group's own path; `*` and renames
/// (`as x`) dropped.
fn expand_use(toks: &[String]) -> Vec<Vec<String>> {
    fn tree(toks: &[String], k: &mut usize, prefix: &[String], out: &mut Vec<Vec<String>>) {
        let mut path = prefix.to_vec();
        while let Some(t) = toks.get(*k) {
            match t.as_str() {
                "{" => {
                    *k += 1;
                    while *k < toks.len() && toks[*k] != "}" {
                        tree(toks, k, &path, out);
                        if toks.get(*k).map(String::as_str) == Some(",") {
                            *k += 1;
                        }
                    }
                    *k += 1;
                    return;
                }
                "*" => {
                    *k += 1;
                    out.push(path);
                    return;
                }
                "::" => *k += 1,
                "as" => *k += 2,
                "," | "}" => break,
                // `a::{self, b}`: the group's own path
                "self" if !path.is_empty() => *k += 1,
                _ => {
                    path.push(t.clone());
                    *k += 1;
                }
            }
        }
        out.push(path);
    }
    let mut out = Vec::new();
    let mut k = 0;
    while k < toks.len() {
        tree(toks, &mut k, &[], &mut out);
        k += 1;
    }
    out
}

/// Every path a file names (in `use` trees and in code): `crate::`,
/// `super::` and `self::` paths, and paths starting with a child module of
/// the file's module, made absolute (from the crate root) with the inline
/// `mod name { ... }` blocks they stand in taken into account.
fn named_paths(module: &[String], children: &[String], text: &str) -> Vec<(Vec<String>, usize)> {
    let toks = tokens(text);
    let words: Vec<String> = toks.iter().map(|(t, _)| t.clone()).collect();
    let (mut out, mut inline, mut depth) = (Vec::new(), Vec::<(String, usize)>::new(), 0usize);
    let absolute = |here: &[String], path: &[String]| -> Option<Vec<String>> {
        let mut base: Vec<String> = here.to_vec();
        let mut rest = path;
        match rest.first().map(String::as_str) {
            Some("crate") => {
                base.clear();
                rest = &rest[1..];
            }
            Some("self") => rest = &rest[1..],
            Some("super") => {
                while rest.first().map(String::as_str) == Some("super") {
                    base.pop()?;
                    rest = &rest[1..];
                }
            }
            Some(first) if here.len() == module.len() && children.iter().any(|c| c == first) => {}
            _ => return None,
        }
        base.extend(rest.iter().cloned());
        Some(base)
    };
    let mut k = 0;
    while k < words.len() {
        let here: Vec<String> = module.iter().cloned().chain(inline.iter().map(|(m, _)| m.clone())).collect();
        match words[k].as_str() {
            "{" => depth += 1,
            "}" => {
                depth = depth.saturating_sub(1);
                if inline.last().is_some_and(|(_, d)| *d == depth) {
                    inline.pop();
                }
            }
            "mod" if words.get(k + 2).map(String::as_str) == Some("{") => {
                inline.push((words[k + 1].clone(), depth));
                depth += 1;
                k += 3;
                continue;
            }
            "use" => {
                let end = (k..words.len()).find(|&j| words[j] == ";").unwrap_or(words.len());
                for p in expand_use(&words[k + 1..end]) {
                    if let Some(a) = absolute(&here, &p) {
                        out.push((a, toks[k].1));
                    }
                }
                k = end + 1;
                continue;
            }
            w if (["crate", "super", "self"].contains(&w) || children.iter().any(|c| c == w))
                && words.get(k + 1).map(String::as_str) == Some("::")
                && (k == 0 || (words[k - 1] != "::" && words[k - 1] != "in")) =>
            {
                let mut path = vec![w.to_string()];
                let mut j = k + 1;
                while words.get(j).map(String::as_str) == Some("::")
                    && words.get(j + 1).is_some_and(|x| x.chars().all(|c| c.is_alphanumeric() || c == '_'))
                {
                    path.push(words[j + 1].clone());
                    j += 2;
                }
                if let Some(a) = absolute(&here, &path) {
                    out.push((a, toks[k].1));
                }
                k = j;
                continue;
            }
            _ => {}
        }
        k += 1;
    }
    out
}

/// The file graph of the crate under `src`: for each file (relative path),
/// the files it names a path into (the file of the longest prefix of the
/// path that is a module), without itself.
fn file_graph(src: &Path) -> BTreeMap<String, std::collections::BTreeSet<String>> {
    let mut files = Vec::new();
    rust_files(src, &mut files);
    files.sort();
    let rel = |f: &Path| f.strip_prefix(src).unwrap().to_string_lossy().replace('\\', "/");
    let modules: BTreeMap<Vec<String>, String> = files.iter().map(|f| (module_path(src, f), rel(f))).collect();
    let mut graph = BTreeMap::new();
    for file in &files {
        let module = module_path(src, file);
        let children: Vec<String> = modules
            .keys()
            .filter(|m| m.len() == module.len() + 1 && m.starts_with(&module))
            .map(|m| m.last().unwrap().clone())
            .collect();
        let text = std::fs::read_to_string(file).expect("source is readable");
        let mut uses = std::collections::BTreeSet::new();
        for (path, _) in named_paths(&module, &children, &text) {
            let target = (0..=path.len()).rev().find_map(|n| modules.get(&path[..n]));
            if let Some(t) = target.filter(|t| **t != rel(file)) {
                uses.insert(t.clone());
            }
        }
        graph.insert(rel(file), uses);
    }
    graph
}

/// The import cycles among the files of each top-level folder of `src`
/// (folder → cycles, each as the files around it, the first repeated at the
/// end): one cycle per strongly connected set of files. Cycles through
/// several top-level modules are the layer test's (`every_import_points_down_the_layers`).
fn folder_cycles(src: &Path) -> BTreeMap<String, Vec<Vec<String>>> {
    let graph = file_graph(src);
    let folder = |f: &str| f.split_once('/').map(|(d, _)| d.to_string());
    let mut out: BTreeMap<String, Vec<Vec<String>>> = BTreeMap::new();
    let mut seen = std::collections::BTreeSet::new();
    for start in graph.keys() {
        let Some(dir) = folder(start) else { continue };
        if seen.contains(start) {
            continue;
        }
        let inside = |f: &String| folder(f).as_deref() == Some(dir.as_str());
        // the files reachable from `start` inside the folder, with a parent each
        let reach = |from: &String| {
            let mut parent: BTreeMap<String, String> = BTreeMap::new();
            let mut queue = std::collections::VecDeque::from([from.clone()]);
            while let Some(f) = queue.pop_front() {
                for g in graph[&f].iter().filter(|g| inside(g)) {
                    if !parent.contains_key(g) {
                        parent.insert(g.clone(), f.clone());
                        queue.push_back(g.clone());
                    }
                }
            }
            parent
        };
        let from_start = reach(start);
        if !from_start.contains_key(start) {
            continue;
        }
        // the strongly connected set: reachable from start and reaching it
        let component: Vec<String> =
            from_start.keys().filter(|f| *f == start || reach(f).contains_key(start)).cloned().collect();
        seen.extend(component.iter().cloned());
        // one cycle through start: from start back along the parents to
        // start, then read forwards
        let mut cycle = vec![start.clone()];
        let mut f = from_start[start].clone();
        while f != *start {
            cycle.push(f.clone());
            f = from_start[&f].clone();
        }
        cycle.push(start.clone());
        cycle.reverse();
        let mut shown = cycle.clone();
        if component.len() > cycle.len() - 1 {
            shown.push(format!("(and {} more files in this cycle set)", component.len() + 1 - cycle.len()));
        }
        out.entry(dir).or_default().push(shown);
    }
    out
}

/// Folders of `src` whose files still import each other in a cycle (a
/// `mod.rs` that uses a child which uses an item of the `mod.rs`). The list
/// only shrinks: a folder not listed must have no cycle, and a listed
/// folder that has none any more fails the test until it is taken off.
const FOLDERS_WITH_CYCLES: &[&str] = &[];

/// No file of a folder of `src` imports itself through a chain of others,
/// except in the folders still listed in [`FOLDERS_WITH_CYCLES`] (whose
/// cycles are printed with `--nocapture`). In `src/claims` the check kinds
/// and the paper files import the shared helpers, which import none of them.
#[test]
fn no_import_cycle_among_the_files_of_a_folder() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let cycles = folder_cycles(&src);
    for (dir, list) in &cycles {
        for c in list {
            eprintln!("import cycle in src/{dir}: {}", c.join(" -> "));
        }
    }
    let new: Vec<String> = cycles
        .iter()
        .filter(|(dir, _)| !FOLDERS_WITH_CYCLES.contains(&dir.as_str()))
        .flat_map(|(dir, list)| list.iter().map(move |c| format!("src/{dir}: {}", c.join(" -> "))))
        .collect();
    assert!(new.is_empty(), "import cycles among the files of a folder:\n{}", new.join("\n"));
    let gone: Vec<&&str> = FOLDERS_WITH_CYCLES.iter().filter(|d| !cycles.contains_key(**d)).collect();
    assert!(
        gone.is_empty(),
        "these folders have no import cycle any more; take them off FOLDERS_WITH_CYCLES: {gone:?}"
    );
}

/// Negative control: the cycle checker finds a cycle through a parent
/// module and a chain of siblings, reads grouped, nested and relative
/// imports and inline paths, and ignores paths in comments, strings and an
/// inline test module's `use super::*`.
#[test]
fn the_cycle_checker_sees_cycles() {
    let dir = std::env::temp_dir().join(format!("subdlab-cycles-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("a/deep")).unwrap();
    std::fs::create_dir_all(dir.join("b")).unwrap();
    let write = |p: &str, t: &str| std::fs::write(dir.join(p), t).unwrap();
    write("lib.rs", "pub mod a;\npub mod b;\n");
    // a: mod.rs -> x (relative), x -> y (inline path), y -> mod.rs (grouped super)
    write("a/mod.rs", "pub mod x;\npub mod y;\npub mod deep;\nuse x::run;\npub struct Shared;\n");
    write("a/x.rs", "pub fn run() { crate::a::y::go(); }\n// use crate::a::deep::z;\n");
    write("a/y.rs", "use super::{Shared, deep::{z::{self}}};\npub fn go() { let _ = \"crate::b::q\"; }\n");
    write("a/deep/mod.rs", "pub mod z;\n");
    write("a/deep/z.rs", "pub fn f() {}\n#[cfg(test)]\nmod tests {\n    use super::*;\n}\n");
    // b: no cycle; q uses r, r uses a sibling folder's file only
    write("b/mod.rs", "pub mod q;\npub mod r;\n");
    write("b/q.rs", "use crate::b::r::R;\n");
    write("b/r.rs", "pub struct R;\nfn g() { let _c = '{'; crate::a::x::run(); }\n");
    let graph = file_graph(&dir);
    let cycles = folder_cycles(&dir);
    std::fs::remove_dir_all(&dir).unwrap();
    let set = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<std::collections::BTreeSet<_>>();
    assert_eq!(graph["a/mod.rs"], set(&["a/x.rs"]));
    assert_eq!(graph["a/x.rs"], set(&["a/y.rs"]));
    assert_eq!(graph["a/y.rs"], set(&["a/mod.rs", "a/deep/z.rs"]));
    assert!(graph["a/deep/z.rs"].is_empty(), "{:?}", graph["a/deep/z.rs"]);
    assert_eq!(graph["b/r.rs"], set(&["a/x.rs"]));
    assert_eq!(cycles.len(), 1, "{cycles:?}");
    let a = &cycles["a"];
    assert_eq!(a.len(), 1, "{a:?}");
    assert_eq!(a[0].first(), a[0].last());
    assert_eq!(a[0][..3].iter().collect::<std::collections::BTreeSet<_>>().len(), 3, "{a:?}");
    for f in ["a/mod.rs", "a/x.rs", "a/y.rs"] {
        assert!(a[0].iter().any(|x| x == f), "{f} in {a:?}");
    }
}

// ------------------------------------------------------------ function length

/// Longest function allowed in `src/claims`, in lines from `fn` to its
/// closing brace: a longer one mixes steps that deserve names.
const MAX_FUNCTION_LINES: usize = 150;

/// Every function of a file with its first line and length in lines (from
/// the line of `fn` to the line of its closing brace; a declaration without
/// a body is not counted). Braces in strings and comments are not code.
fn function_lengths(text: &str) -> Vec<(String, usize, usize)> {
    let toks = tokens(text);
    let mut out = Vec::new();
    for k in 0..toks.len() {
        if toks[k].0 != "fn" || !toks.get(k + 1).is_some_and(|t| t.0.chars().all(|c| c.is_alphanumeric() || c == '_')) {
            continue;
        }
        // the body opens at the first `{` outside parentheses and generics
        // before any `;` (a trait method without a body)
        let mut parens = 0i64;
        let mut j = k + 2;
        let open = loop {
            match toks.get(j).map(|t| t.0.as_str()) {
                None | Some(";") if parens == 0 => break None,
                None => break None,
                Some("(") | Some("[") => parens += 1,
                Some(")") | Some("]") => parens -= 1,
                Some("{") if parens == 0 => break Some(j),
                _ => {}
            }
            j += 1;
        };
        let Some(open) = open else { continue };
        let mut depth = 0usize;
        for (t, line) in &toks[open..] {
            match t.as_str() {
                "{" => depth += 1,
                "}" => {
                    depth -= 1;
                    if depth == 0 {
                        out.push((toks[k + 1].0.clone(), toks[k].1, line - toks[k].1 + 1));
                        break;
                    }
                }
                _ => {}
            }
        }
    }
    out
}

#[test]
fn no_function_in_claims_is_over_150_lines() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/claims");
    let mut files = Vec::new();
    rust_files(&dir, &mut files);
    files.sort();
    assert!(files.len() > 10, "{files:?}");
    let mut long = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        for (name, line, lines) in function_lengths(&text) {
            if lines > MAX_FUNCTION_LINES {
                long.push(format!("{}:{line}: fn {name} has {lines} lines", f.display()));
            }
        }
    }
    assert!(long.is_empty(), "functions over {MAX_FUNCTION_LINES} lines:\n{}", long.join("\n"));
}

/// Negative control: lengths are counted from `fn` to the closing brace,
/// with braces in strings, characters and comments ignored, and a trait
/// method without a body skipped.
#[test]
fn function_lengths_are_counted_to_the_closing_brace() {
    let text = "trait T {\n    fn decl(&self) -> u8;\n}\nfn a(x: [u8; 2]) -> u8 {\n    let _ = \"}}\";\n    let _ = '}';\n    // }\n    if x[0] > 0 {\n        1\n    } else {\n        2\n    }\n}\nfn b() {}\n";
    let got = function_lengths(text);
    assert_eq!(got, vec![("a".to_string(), 4, 10), ("b".to_string(), 14, 1)]);
}
