//! The Jupyter notebooks in `notebooks/`, executed as a researcher runs them:
//! `scripts/notebooks.sh` with this build's `subdlab` (it makes the Python
//! environment of `notebooks/requirements.txt` the first time, which needs
//! python3 and network access to PyPI). Then every executed copy must have run
//! every code cell, contain no error output, and end with its summary line
//! `notebook NAME: N checks passed` with N > 0; the committed notebooks must
//! carry no outputs. What a reader browsing the repository sees instead is
//! `reports/notebooks/`: each notebook rendered as Markdown with its outputs
//! and figures, which must be byte for byte what this run rendered
//! (`scripts/notebooks.sh --publish` rewrites it).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use serde_json::Value;

fn notebooks(repo: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(repo.join("notebooks"))
        .expect("notebooks/ exists")
        .map(|e| e.expect("readable notebooks/ entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "ipynb"))
        .collect();
    v.sort();
    v
}

fn read_notebook(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: not JSON: {e}", path.display()))
}

fn code_cells(nb: &Value) -> Vec<&Value> {
    nb["cells"].as_array().expect("cells").iter().filter(|c| c["cell_type"] == "code").collect()
}

/// The text of a cell's stream outputs (`text` is a string or a list of lines).
fn stream_text(cell: &Value) -> String {
    let mut s = String::new();
    for o in cell["outputs"].as_array().into_iter().flatten() {
        if o["output_type"] == "stream" {
            match &o["text"] {
                Value::String(t) => s.push_str(t),
                Value::Array(lines) => lines.iter().filter_map(Value::as_str).for_each(|l| s.push_str(l)),
                _ => {}
            }
        }
    }
    s
}

/// N of the line `notebook NAME: N checks passed`, if the text has it.
fn checks_passed(text: &str, name: &str) -> Option<u64> {
    let prefix = format!("notebook {name}: ");
    text.lines().find_map(|l| l.strip_prefix(&prefix)?.strip_suffix(" checks passed")?.parse().ok())
}

#[test]
fn committed_notebooks_carry_no_outputs() {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    let all = notebooks(repo);
    let names: Vec<_> = all.iter().map(|p| p.file_stem().unwrap().to_string_lossy().into_owned()).collect();
    for want in ["validate-new-weights", "paper-figures", "assert-spectral-claims"] {
        assert!(names.iter().any(|n| n == want), "notebooks/{want}.ipynb missing (found {names:?})");
    }
    for path in &all {
        let nb = read_notebook(path);
        assert_eq!(nb["nbformat"], 4, "{}: nbformat 4", path.display());
        for cell in code_cells(&nb) {
            assert!(
                cell["outputs"].as_array().is_some_and(|o| o.is_empty()) && cell["execution_count"].is_null(),
                "{}: committed with outputs (clear them before committing)",
                path.display()
            );
        }
    }
}

#[test]
fn notebooks_execute_and_pass_their_checks() {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    // CARGO_TARGET_TMPDIR is <target dir>/tmp: the environment, the executed
    // notebooks and the figures go to the target dir cargo uses.
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).parent().expect("target dir").to_path_buf();

    match Command::new("python3").arg("--version").output() {
        Ok(out) if out.status.success() => {}
        Ok(out) => panic!(
            "`python3 --version` failed ({}): the notebook test needs Python 3 (3.11 tested) with its venv module",
            String::from_utf8_lossy(&out.stderr)
        ),
        Err(e) => panic!(
            "python3 not found ({e}): the notebook test (tests/notebooks.rs) needs Python 3 (3.11 tested) with its \
             venv module, and network access to PyPI the first time (scripts/notebooks.sh)"
        ),
    }

    let executed_dir = target.join("notebooks-executed");
    let all = notebooks(repo);
    for nb in &all {
        let _ = std::fs::remove_file(executed_dir.join(nb.file_name().unwrap()));
    }
    let _ = std::fs::remove_dir_all(target.join("notebooks-rendered"));

    let start = Instant::now();
    let out = Command::new("bash")
        .arg(repo.join("scripts/notebooks.sh"))
        .current_dir(repo)
        .env("SUBDLAB", env!("CARGO_BIN_EXE_subdlab"))
        .env("SUBDLAB_TARGET_DIR", &target)
        .env_remove("SUBDLAB_NOTEBOOKS_RENDERED")
        .output()
        .expect("bash runs scripts/notebooks.sh");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "scripts/notebooks.sh failed ({}):\n--- stdout\n{stdout}\n--- stderr\n{stderr}",
        out.status
    );
    println!("{stdout}(scripts/notebooks.sh: {:.1} s)", start.elapsed().as_secs_f64());

    for path in &all {
        let name = path.file_stem().unwrap().to_string_lossy();
        let executed = executed_dir.join(path.file_name().unwrap());
        assert!(executed.is_file(), "no executed copy {} of {}\n{stdout}", executed.display(), path.display());
        let raw = std::fs::read_to_string(&executed).unwrap();
        let nb: Value = serde_json::from_str(&raw).unwrap_or_else(|e| panic!("{}: not JSON: {e}", executed.display()));
        let cells = code_cells(&nb);
        assert!(!cells.is_empty(), "{name}: no code cells");
        for (i, cell) in cells.iter().enumerate() {
            assert!(cell["execution_count"].is_u64(), "{name}: code cell {} was not executed", i + 1);
            for o in cell["outputs"].as_array().expect("outputs") {
                assert_ne!(o["output_type"], "error", "{name}: code cell {} raised: {}", i + 1, o["evalue"]);
            }
        }
        assert!(!raw.contains("\"output_type\": \"error\""), "{name}: an error output in {}", executed.display());
        let last = cells.last().unwrap();
        let n = checks_passed(&stream_text(last), &name).unwrap_or_else(|| {
            panic!("{name}: the last cell does not print `notebook {name}: N checks passed`:\n{}", stream_text(last))
        });
        assert!(n > 0, "{name}: no checks ran");
    }

    // the published rendering is what this run rendered
    let rendered = target.join("notebooks-rendered");
    let published = repo.join("reports/notebooks");
    let (now, committed) = (tree(&rendered), tree(&published));
    let mut stale = Vec::new();
    for (name, bytes) in &now {
        match committed.get(name) {
            Some(old) if old == bytes => {}
            Some(_) => stale.push(format!("{name} differs")),
            None => stale.push(format!("{name} is missing")),
        }
    }
    stale.extend(committed.keys().filter(|k| !now.contains_key(*k)).map(|k| format!("{k} is not rendered any more")));
    for path in &all {
        let name = format!("{}.md", path.file_stem().unwrap().to_string_lossy());
        assert!(now.contains_key(&name), "{name} was not rendered");
    }
    assert!(stale.is_empty(), "reports/notebooks is stale (run scripts/notebooks.sh --publish): {stale:?}");
}

/// Every file under `dir` (relative path → bytes), sorted.
fn tree(dir: &Path) -> std::collections::BTreeMap<String, Vec<u8>> {
    let mut out = std::collections::BTreeMap::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                todo.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().to_string_lossy().replace('\\', "/");
                out.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    out
}
