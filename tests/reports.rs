//! The committed reports/ folder must be what `subdlab report` writes now;
//! regenerate it with `cargo run --release -- report` after changing claims
//! or the engine.

use std::collections::BTreeSet;
use std::path::Path;

#[test]
fn committed_reports_are_up_to_date() {
    let files = subdlab::report::build().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    let mut stale = Vec::new();
    for (name, bytes) in &files {
        match std::fs::read(root.join(name)) {
            Ok(old) if &old == bytes => {}
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
