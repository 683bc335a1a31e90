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
    ("claims", 13),
    ("sweep", 13),
    ("plot", 14),
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
