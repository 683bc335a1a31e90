//! Limits on the cost of a request: what is refused up front (with the
//! estimate, in one line) and what runs now that the limit follows the
//! estimated memory instead of a fixed valence. Refusals and acceptances
//! are asserted, never durations. Also the thread-count independence of the
//! outputs.

use crate::common;
use common::*;

fn stdout_of(args: &[&str]) -> String {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

/// Polar schemes are made for high valence: the old fixed cap (1000) refused
/// n = 5000, whose analysis is linear in n (a few tens of MB). The closed
/// forms of tests/polar_bi2.rs (Karčiauskas–Peters eqs. 13–15): 3n + 1
/// distinct points, λ1 = γ̂_1 = 1/2 double (blocks 1 and n − 1).
#[test]
fn polar_bi2_runs_at_valence_5000_with_the_closed_form_subdominant_eigenvalue() {
    let n = 5000;
    let out = stdout_of(&["spectrum", "polar-bi2", "-n", "5000", "--no-exact", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["matrix_size"], 3 * n + 1);
    let lambda1 = v["verdict"]["subdominant"].as_f64().unwrap();
    assert!((lambda1 - 0.5).abs() < 1e-12, "λ1 = {lambda1}");
    assert_eq!(v["eigenvalues"][1]["algebraic_multiplicity"], 2);
    assert_eq!(v["verdict"]["c1_spectral"], true);
}

/// A valence whose estimate exceeds the memory budget is refused before any
/// work, in one line naming the estimate; every command that builds a
/// configuration goes through the same check.
#[test]
fn a_valence_beyond_the_memory_budget_is_refused_with_the_estimate() {
    for args in [
        &["spectrum", "unified-sqrt3", "-n", "5000000", "--no-exact"][..],
        &["charmap", "unified-sqrt3", "-n", "5000000"],
        &["curvature", "unified-sqrt3", "-n", "5000000"],
        &["matrix", "unified-sqrt3", "-n", "5000000"],
    ] {
        let e = fails(args);
        assert!(e.contains("valence 5000000 would need about") && e.contains("iB of memory"), "{args:?}: {e}");
        assert!(e.contains("the largest valence that fits is about"), "{args:?}: {e}");
    }
    // absurd numbers are not even estimated (nor allocated)
    let e = fails(&["spectrum", "polar-bi2", "-n", "1000000000", "--no-exact"]);
    assert!(e.contains("valence 1000000000 is above the supported maximum"), "{e}");
    let e = fails(&["sweep", "polar-bi2", "--valences", "3..1000000000"]);
    assert!(e.contains("above the supported maximum"), "{e}");
}

/// The largest valence the refusal names is itself accepted by the check
/// (the estimate is linear in n): one past it is refused.
#[test]
fn the_named_largest_valence_is_the_boundary_of_the_estimate() {
    let e = fails(&["spectrum", "unified-sqrt3", "-n", "5000000", "--no-exact"]);
    let fits: usize = e
        .split("the largest valence that fits is about ")
        .nth(1)
        .and_then(|s| s.split(|c: char| !c.is_ascii_digit()).next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no largest valence in {e}"));
    assert!(fits > 1000, "{e}");
    let past = (fits + 2).to_string();
    let e = fails(&["spectrum", "unified-sqrt3", "-n", &past, "--no-exact"]);
    assert!(e.contains("iB of memory"), "{e}");
}

/// Whole-matrix eigenvalues must not depend on the number of threads: faer's
/// parallel kernels split reductions by thread count (the last digits of the
/// JSON differed between 1 and 2 threads at this size).
#[test]
fn whole_matrix_output_is_byte_identical_for_any_thread_count() {
    let args = ["spectrum", "catmull-clark", "-n", "60", "--method", "full", "--no-exact", "--json"];
    let run = |threads: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab"))
            .args(args)
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .expect("binary runs");
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        out.stdout
    };
    let one = run("1");
    assert!(one == run("2"), "RAYON_NUM_THREADS=1 and =2 give different bytes");
    assert!(one == run("3"), "RAYON_NUM_THREADS=1 and =3 give different bytes");
}

/// `report --out DIR` checks DIR before the analyses (tens of seconds): a
/// path under a regular file is refused naming that file, and nothing is
/// created.
#[test]
fn report_refuses_an_unwritable_destination_before_the_work() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("plain-file");
    std::fs::write(&file, "not a directory").unwrap();
    let out = file.join("reports");
    let e = fails(&["report", "--out", out.to_str().unwrap()]);
    assert!(e.contains("is not a directory") && e.contains("plain-file"), "{e}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "not a directory");
}

/// The curvature sampler's weight rows grow as n² (rows of O(n) entries near
/// the centre): sqrt(3) at n = 1000 with three levels would need about 6 GB
/// and was aborted by the allocator after a minute; it is refused with the
/// estimate. Small valences still run.
#[test]
fn curvature_refuses_a_sampler_beyond_the_memory_budget() {
    let e = fails(&["curvature", "sqrt3", "-n", "1000", "--no-exact"]);
    assert!(e.contains("sampling the characteristic ring 3 levels deep would need about"), "{e}");
    assert!(e.contains("use fewer --levels"), "{e}");
    let out = stdout_of(&["curvature", "sqrt3", "-n", "7", "--no-exact", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["valence"], 7);
}

fn curve_file(dir: &std::path::Path, far: i64) -> std::path::PathBuf {
    // even rule (P_i + P_{i+far}) / 2: a local (if useless) scheme whose
    // invariant window grows with `far`
    let path = dir.join(format!("far{far}.toml"));
    std::fs::write(
        &path,
        format!(
            "domain = \"curve\"\nname = \"far\"\ndescription = \"reach {far}\"\n[even]\n\"0\" = \"1/2\"\n\"{far}\" = \
             \"1/2\"\n[odd]\n\"0\" = \"1/2\"\n\"1\" = \"1/2\"\n"
        ),
    )
    .unwrap();
    path
}

fn lattice_file(dir: &std::path::Path, far: i64) -> std::path::PathBuf {
    let path = dir.join(format!("lattice{far}.toml"));
    std::fs::write(
        &path,
        format!(
            "domain = \"lattice\"\nname = \"far\"\ndescription = \"reach {far}\"\n[mask-00]\n\"0,0\" = \"1/2\"\n\
             \"{far},{far}\" = \"1/2\"\n[mask-10]\n\"0,0\" = \"1/2\"\n\"1,0\" = \"1/2\"\n[mask-01]\n\"0,0\" = \"1/2\"\n\
             \"0,1\" = \"1/2\"\n[mask-11]\n\"0,0\" = \"1/4\"\n\"1,0\" = \"1/4\"\n\"0,1\" = \"1/4\"\n\"1,1\" = \"1/4\"\n"
        ),
    )
    .unwrap();
    path
}

/// A curve rule reaching offset 32 ran for tens of seconds to minutes (the
/// exact characteristic polynomial of a 66-point window): refused, naming
/// the reach and the supported one; reach 8 (the limit) runs.
#[test]
fn curve_rules_beyond_the_supported_reach_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let far = curve_file(dir.path(), 32);
    let e = fails(&["curve", far.to_str().unwrap()]);
    assert!(e.contains("reach offset 32, beyond the supported 8"), "{e}");
    let near = curve_file(dir.path(), 8);
    let out = stdout_of(&["curve", near.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // the window is invariant and holds the one-ring, so it holds what the
    // new P_0 depends on: P_0 and P_8
    assert!(v["window"].as_array().unwrap().iter().any(|x| x == 8), "{out}");
}

/// Lattice masks out to ±32 ran for minutes; refused past the supported
/// reach, accepted within it.
#[test]
fn lattice_masks_beyond_the_supported_reach_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let far = lattice_file(dir.path(), 32);
    let e = fails(&["spectrum", far.to_str().unwrap(), "-n", "4"]);
    assert!(e.contains("the masks reach offset 32, beyond the supported"), "{e}");
    let near = lattice_file(dir.path(), 2);
    stdout_of(&["spectrum", near.to_str().unwrap(), "-n", "4"]);
}
