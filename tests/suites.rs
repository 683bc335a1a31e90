//! The integration tests are a few binaries by theme: Cargo.toml sets
//! `autotests = false` and has one `[[test]]` per root file
//! `tests/suite_*.rs`, which declares the test files of its theme as modules
//! (`mod NAME;` for `tests/NAME.rs`). A test file that no suite declares would
//! silently never be compiled or run, and one declared by two suites would run
//! twice; these tests catch both, and a suite root Cargo.toml does not build.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn tests_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests")
}

/// A suite root is a file `tests/suite_*.rs`; its stem is the binary's name.
fn is_suite_root(stem: &str) -> bool {
    stem.starts_with("suite_")
}

/// The test modules a suite root declares: its `mod NAME;` lines, without the
/// shared helper module `common` (tests/common/, not a test file).
fn declared_modules(root_text: &str) -> Vec<String> {
    root_text
        .lines()
        .filter_map(|l| l.trim().strip_prefix("mod ")?.strip_suffix(';'))
        .filter(|m| *m != "common")
        .map(str::to_string)
        .collect()
}

/// The stems of the `.rs` files directly under `tests/` (sorted).
fn test_file_stems() -> Vec<String> {
    let mut stems: Vec<String> = std::fs::read_dir(tests_dir())
        .expect("tests/ is readable")
        .map(|e| e.expect("readable tests/ entry").path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "rs"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    stems.sort();
    stems
}

#[test]
fn every_test_file_belongs_to_exactly_one_suite() {
    let stems = test_file_stems();
    let roots: Vec<&String> = stems.iter().filter(|s| is_suite_root(s)).collect();
    assert!(roots.len() >= 3, "expected a few suite roots tests/suite_*.rs, found {roots:?}");
    // module -> the suites that declare it
    let mut owners: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for root in &roots {
        let text = std::fs::read_to_string(tests_dir().join(format!("{root}.rs"))).unwrap();
        let modules = declared_modules(&text);
        assert!(!modules.is_empty(), "tests/{root}.rs declares no test files");
        for m in modules {
            assert!(
                tests_dir().join(format!("{m}.rs")).is_file(),
                "tests/{root}.rs declares `mod {m};` but there is no tests/{m}.rs"
            );
            owners.entry(m).or_default().push(root.to_string());
        }
    }
    for stem in stems.iter().filter(|s| !is_suite_root(s)) {
        match owners.get(stem).map(Vec::as_slice) {
            Some([_]) => {}
            None | Some([]) => panic!(
                "tests/{stem}.rs is in no suite, so it is never compiled: add `mod {stem};` to the \
                 tests/suite_*.rs of its theme"
            ),
            Some(many) => panic!("tests/{stem}.rs is declared by {many:?}: its tests would run more than once"),
        }
    }
}

#[test]
fn cargo_toml_builds_every_suite_and_nothing_else() {
    let manifest = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml")).unwrap();
    let manifest: toml::Table = manifest.parse().expect("Cargo.toml is TOML");
    assert_eq!(
        manifest["package"].get("autotests").and_then(toml::Value::as_bool),
        Some(false),
        "Cargo.toml must set autotests = false, or every test file becomes a binary of its own again"
    );
    let mut targets: Vec<(String, String)> = manifest["test"]
        .as_array()
        .expect("[[test]] entries")
        .iter()
        .map(|t| (t["name"].as_str().unwrap().to_string(), t["path"].as_str().unwrap().to_string()))
        .collect();
    targets.sort();
    let want: Vec<(String, String)> = test_file_stems()
        .into_iter()
        .filter(|s| is_suite_root(s))
        .map(|s| (s.clone(), format!("tests/{s}.rs")))
        .collect();
    assert_eq!(targets, want, "Cargo.toml's [[test]] entries must be exactly the suite roots tests/suite_*.rs");
}

/// Negative control for the reader of suite roots: comments, the shared
/// `common` module and inline modules are no test files.
#[test]
fn declared_modules_reads_only_module_declarations() {
    let root =
        "//! mod commented;\nmod common;\nmod alpha;\n// mod beta;\n  mod gamma;\nmod inline {}\nuse crate::common;\n";
    assert_eq!(declared_modules(root), vec!["alpha", "gamma"]);
}
