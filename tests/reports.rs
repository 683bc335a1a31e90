//! The committed reports/ folder must be what `subdlab report` writes now
//! (every byte but the index's one date line); regenerate it with
//! `cargo run --release -- report` after changing claims or the engine. Each
//! page shows each figure once, and every figure it shows is in the report.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::sync::OnceLock;

/// The report, built once for the tests of this file (about 15 s).
fn report() -> &'static BTreeMap<String, Vec<u8>> {
    static FILES: OnceLock<BTreeMap<String, Vec<u8>>> = OnceLock::new();
    FILES.get_or_init(|| subdlab::report::build().unwrap())
}

/// The index without its date line (the one line that is not reproducible),
/// which must be there once, as a date.
fn without_date(name: &str, bytes: &[u8]) -> Vec<u8> {
    if name != "index.md" {
        return bytes.to_vec();
    }
    let text = String::from_utf8(bytes.to_vec()).unwrap();
    let dated: Vec<&str> = text.lines().filter(|l| l.starts_with(subdlab::report::GENERATED_ON)).collect();
    assert_eq!(dated.len(), 1, "one date line in index.md");
    let date = &dated[0][subdlab::report::GENERATED_ON.len()..];
    let ymd: Vec<&str> = date.trim_end_matches(" (UTC).").split('-').collect();
    assert!(ymd.len() == 3 && ymd.iter().all(|p| p.parse::<u32>().is_ok()), "a YYYY-MM-DD date: {date}");
    text.lines().filter(|l| !l.starts_with(subdlab::report::GENERATED_ON)).collect::<Vec<_>>().join("\n").into_bytes()
}

#[test]
fn committed_reports_are_up_to_date() {
    let files = report();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    let mut stale = Vec::new();
    for (name, bytes) in files {
        match std::fs::read(root.join(name)) {
            Ok(old) if without_date(name, &old) == without_date(name, bytes) => {}
            Ok(_) => stale.push(format!("{name} differs")),
            Err(_) => stale.push(format!("{name} is missing")),
        }
    }
    // no leftover files from an earlier report
    let mut on_disk = BTreeSet::new();
    for dir in [root.clone(), root.join("figures")] {
        for e in std::fs::read_dir(&dir).unwrap().flatten() {
            if e.path().is_file() {
                on_disk.insert(e.path().strip_prefix(&root).unwrap().to_string_lossy().replace('\\', "/"));
            }
        }
    }
    for name in on_disk {
        if !files.contains_key(&name) {
            stale.push(format!("{name} is not produced any more"));
        }
    }
    assert!(stale.is_empty(), "reports/ is stale (run `cargo run --release -- report`): {stale:?}");
}

#[test]
fn no_figure_twice_on_a_page() {
    let files = report();
    let mut pages = Vec::new();
    for (name, bytes) in files.iter().filter(|(n, _)| n.ends_with(".md")) {
        let text = std::str::from_utf8(bytes).unwrap();
        // Markdown images: ![alt](path)
        let images: Vec<&str> = text
            .split("![")
            .skip(1)
            .filter_map(|rest| {
                let open = rest.find("](")?;
                let path = &rest[open + 2..];
                Some(&path[..path.find(')')?])
            })
            .collect();
        let unique: BTreeSet<&str> = images.iter().copied().collect();
        assert_eq!(unique.len(), images.len(), "{name} shows a figure twice: {images:?}");
        for path in &images {
            assert!(files.contains_key(*path), "{name} shows {path}, which the report does not write");
        }
        if !images.is_empty() {
            pages.push(name.trim_end_matches(".md").to_string());
        }
    }
    // not vacuous: every paper whose claim file asks for figures shows some
    let asking: Vec<String> = subdlab::claims::builtin_files()
        .unwrap()
        .into_iter()
        .filter(|f| !f.figures.is_empty() || !f.sweeps.is_empty())
        .map(|f| f.paper)
        .collect();
    assert!(!asking.is_empty());
    for paper in &asking {
        assert!(pages.contains(paper), "{paper}.md shows no figure although its claim file asks for some");
    }
}

#[test]
fn report_dates_are_utc_calendar_dates() {
    use subdlab::report::date_of;
    // dates of the Unix epoch, a century leap day, a leap day, a non-leap
    // century year, and a day before the epoch (from `date -u -d @SECONDS`)
    for (seconds, date) in [
        (0, "1970-01-01"),
        (951_782_400, "2000-02-29"),
        (1_709_164_800, "2024-02-29"),
        (4_102_444_800, "2100-01-01"),
        (-86_400, "1969-12-31"),
        (86_399, "1970-01-01"),
    ] {
        assert_eq!(date_of(seconds), date, "{seconds} s");
    }
}
