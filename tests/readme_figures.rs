//! The README's figures (`docs/figures/`, one of each figure type) are what
//! this build draws: every line of `docs/figures/figures.txt` is run again
//! and its output compared byte for byte with the committed file (figures are
//! deterministic); regenerate them with `scripts/readme-figures.sh`.

use std::path::Path;

/// Splits an argument list at spaces, double quotes grouping (the reading
/// `scripts/readme-figures.sh` gives the same line).
fn split_args(s: &str) -> Vec<String> {
    let (mut out, mut cur, mut quoted, mut any) = (Vec::new(), String::new(), false, false);
    for c in s.chars() {
        match c {
            '"' => {
                quoted = !quoted;
                any = true;
            }
            ' ' | '\t' if !quoted => {
                if any {
                    out.push(std::mem::take(&mut cur));
                    any = false;
                }
            }
            c => {
                cur.push(c);
                any = true;
            }
        }
    }
    assert!(!quoted, "unbalanced quote in {s}");
    if any {
        out.push(cur);
    }
    out
}

#[test]
fn readme_figures_are_current_and_shown() {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = repo.join("docs/figures");
    let list = std::fs::read_to_string(dir.join("figures.txt")).unwrap();
    let readme = std::fs::read_to_string(repo.join("README.md")).unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let mut listed = Vec::new();
    let mut stale = Vec::new();
    let mut commands = Vec::new();
    for line in list.lines().filter(|l| !l.trim().is_empty() && !l.starts_with('#')) {
        let (file, args) = line.split_once(':').expect("FILE: ARGS");
        let args = split_args(args);
        let out = tmp.path().join(file);
        let mut all: Vec<&str> = args.iter().map(String::as_str).collect();
        all.extend(["-o", out.to_str().unwrap()]);
        let run = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab")).args(&all).output().unwrap();
        assert!(run.status.success(), "{line}: {}", String::from_utf8_lossy(&run.stderr));
        let drawn = std::fs::read(&out).unwrap();
        match std::fs::read(dir.join(file)) {
            Ok(committed) if committed == drawn => {}
            Ok(_) => stale.push(format!("{file} differs")),
            Err(_) => stale.push(format!("{file} is missing")),
        }
        assert!(readme.contains(&format!("](docs/figures/{file})")), "README shows no docs/figures/{file}");
        listed.push(file.to_string());
        commands.push(args.join(" "));
    }
    // one of each figure type
    for (kind, marker) in [
        ("ring", "charmap"),
        ("wedge", "--wedge"),
        ("spectrum", "plot spectrum"),
        ("sweep", "sweep "),
        ("central ring", "--figure central-ring"),
        ("limit surface", "--figure surface"),
        ("comparison", "plot compare"),
    ] {
        assert!(commands.iter().any(|c| c.contains(marker)), "no {kind} figure in figures.txt");
    }
    // no figure left over that the list no longer draws
    for e in std::fs::read_dir(&dir).unwrap().flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if name != "figures.txt" && !listed.contains(&name) {
            stale.push(format!("{name} is not in figures.txt"));
        }
    }
    assert!(stale.is_empty(), "docs/figures is stale (run scripts/readme-figures.sh): {stale:?}");
}

#[test]
fn arguments_split_like_the_shell() {
    assert_eq!(
        split_args(r#"plot spectrum --reference "3/8 + x" -n 5"#),
        ["plot", "spectrum", "--reference", "3/8 + x", "-n", "5"]
    );
    assert_eq!(split_args(r#"a "" b"#), ["a", "", "b"]);
}
