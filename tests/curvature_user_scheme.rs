//! A user scheme file whose weights are tuned for bounded curvature, its
//! negative control, and the `subdlab curvature` command line.
//!
//! The file is a Loop variant on the primal triangle host. At the
//! extraordinary vertex (valence n ≠ 6) the edge rule is given by its Fourier
//! coefficients (as in schemes/loop-fourier-edge.toml): the new point on the
//! edge to e_0 is 3/8 v + Σ_j s_j e_j with s_j = (1/n) Σ_m μ(m) cos(2πjm/n), so
//! block m ≥ 1 of the 1-ring has the eigenvalue μ(m); with d = min(m, n − m):
//!   μ = 5/8 (d = 0), 3/5 (d = 1), 9/25 (d = 2), 1/8 (d ≥ 3).
//! Block 0 on (v, mean e) is [[c, 1 − c], [3/8, 5/8]] (the edge weights sum to
//! μ(0) = 5/8): eigenvalues 1 and c − 3/8. With c = 147/200 this is
//! 72/200 = 9/25 = (3/5)². At valence 6 the rules are Loop's, so ring 2 adds
//! 1/8 and 1/16 in every block (tests/curvature_loop.rs). Hence λ = 3/5
//! (blocks 1, n − 1), μ = 9/25 = λ² in blocks 0, 2, n − 2: bounded, and
//! F(μ) ⊇ {0, 2, n − 2}.
//!
//! Negative control: c = 31/40 gives block 0 the eigenvalue 31/40 − 3/8 = 2/5 >
//! 9/25, so μ = 2/5 from block 0 alone: unbounded, F(μ) = {0}, and
//! p* = 2 ln(3/5) / (2 ln(3/5) − ln(2/5)).

use std::path::PathBuf;
use std::process::Command;

use subdlab::curvature::{curvature_of, CurvatureClass, CurvatureOptions};
use subdlab::schemes;

fn scheme_file(dir: &std::path::Path, name: &str, centre: &str) -> PathBuf {
    let text = format!(
        r#"name = "{name}"
description = "Loop variant tuned at the extraordinary vertex"
topology = "primal-triangle"

[vertex]
centre = "5/8 + ({centre} - 5/8) (1 - kronecker(n - 6))"
edge = "(1 - (5/8 + ({centre} - 5/8) (1 - kronecker(n - 6)))) / n"

[edge]
ends = "3/8"
opposite = "1/8"

[edge-extraordinary]
centre = "3/8"
edge = "sum(m, 0, n-1, (1/8 + kronecker(n - abs(n-2m))/2 + (3/5 - 1/8) kronecker(n - abs(n-2m) - 2) + (9/25 - 1/8) kronecker(n - abs(n-2m) - 4)) cos(2 pi j m / n)) / n"
"#
    );
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

fn tmp() -> tempfile::TempDir {
    tempfile::tempdir().unwrap()
}

#[test]
fn tuned_file_is_bounded_with_all_three_blocks() {
    let dir = tmp();
    let path = scheme_file(dir.path(), "tuned", "147/200");
    let s = schemes::resolve(path.to_str().unwrap(), &[]).unwrap();
    for n in [5, 7, 8] {
        let c = curvature_of(s.as_ref(), n, &CurvatureOptions::default()).unwrap();
        assert!((c.lambda.unwrap() - 0.6).abs() < 1e-12, "n = {n}: λ = {:?}", c.lambda);
        let m = c.mu.as_ref().unwrap();
        assert!((m.modulus - 9.0 / 25.0).abs() < 1e-12, "n = {n}");
        assert_eq!(c.class, CurvatureClass::Bounded, "n = {n}: {:?}", c.reasons);
        assert!(c.lp_limit.is_none());
        let f = c.shapes.unwrap();
        assert_eq!(f.fourier_index, vec![0, 2, n - 2], "n = {n}");
        assert!(f.necessary_condition);
    }
}

#[test]
fn negative_control_block_zero_too_large_is_unbounded() {
    let dir = tmp();
    let path = scheme_file(dir.path(), "untuned", "31/40");
    let s = schemes::resolve(path.to_str().unwrap(), &[]).unwrap();
    let c = curvature_of(s.as_ref(), 5, &CurvatureOptions::default()).unwrap();
    assert_eq!(c.class, CurvatureClass::Unbounded);
    assert!((c.mu.as_ref().unwrap().modulus - 0.4).abs() < 1e-12);
    assert_eq!(c.shapes.as_ref().unwrap().fourier_index, vec![0]);
    let want = 2.0 * 0.6f64.ln() / (2.0 * 0.6f64.ln() - 0.4f64.ln());
    assert!((c.lp_limit.unwrap() - want).abs() < 1e-9);
}

fn subdlab(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_subdlab")).args(args).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into(), String::from_utf8_lossy(&out.stderr).into())
}

#[test]
fn cli_json_fields_and_figures() {
    let (ok, out, err) = subdlab(&["curvature", "loop", "--valence", "7", "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["class"], "unbounded");
    assert_eq!(v["evidence"], "floating-point");
    assert_eq!(v["shapes"]["fourier_index"], serde_json::json!([2, 5]));
    assert_eq!(v["shapes"]["necessary_condition"], false);
    assert_eq!(v["c2"]["holds"], false);
    for key in ["lambda", "lambda_squared", "mu", "mu_over_lambda_squared", "lp_limit", "examined", "charmap_injective"]
    {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    // p* from λ = 3/8 + cos(2π/7)/4 and μ = 3/8 + cos(4π/7)/4
    let c = |k: f64| (2.0 * std::f64::consts::PI * k / 7.0).cos();
    let (l, m) = (0.375 + c(1.0) / 4.0, 0.375 + c(2.0) / 4.0);
    let want = 2.0 * l.ln() / (2.0 * l.ln() - m.ln());
    assert!((v["lp_limit"].as_f64().unwrap() - want).abs() < 1e-9);

    let dir = tmp();
    for (file, figure) in [("ring.svg", "central-ring"), ("ring.png", "central-ring"), ("surface.svg", "surface")] {
        let path = dir.path().join(file);
        let (ok, _, err) =
            subdlab(&["curvature", "catmull-clark", "-n", "5", "--figure", figure, "-o", path.to_str().unwrap()]);
        assert!(ok, "{file}: {err}");
        let bytes = std::fs::read(&path).unwrap();
        if file.ends_with(".png") {
            assert_eq!(&bytes[..4], b"\x89PNG");
        } else {
            let text = String::from_utf8(bytes).unwrap();
            // the title names the scheme and the moduli; the class (a verdict)
            // is in the table and the JSON, not drawn
            assert!(text.contains("<svg") && text.contains("catmull-clark n = 5") && text.contains("|μ|"), "{file}");
            assert!(!text.contains("unbounded"), "{file}");
        }
    }
}

#[test]
fn cli_bad_input_is_one_line() {
    for args in [
        vec!["curvature", "loop", "--valence", "2"],
        vec!["curvature", "no-such-scheme", "--valence", "5"],
        vec!["curvature", "loop", "--valence", "5", "--levels", "0"],
        vec!["curvature", "loop", "--valence", "5", "--figure", "chart", "-o", "x.svg"],
        vec!["curvature", "loop", "--valence", "5", "-o", "x.eps"],
        vec!["curvature", "loop", "--valence", "5", "-o", "/no/such/dir/x.svg"],
        // --input: T outside [−1, 1], not finite, not a pair
        vec!["curvature", "loop", "--valence", "5", "--input", "1.5,0"],
        vec!["curvature", "loop", "--valence", "5", "--input", "-0.5,inf"],
        vec!["curvature", "loop", "--valence", "5", "--input", "NaN,10"],
        vec!["curvature", "loop", "--valence", "5", "--input", "0.5"],
        vec!["curvature", "loop", "--valence", "5", "--input", "a,b"],
    ] {
        let (ok, _, err) = subdlab(&args);
        assert!(!ok, "{args:?} succeeded");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// `--input T,THETA` picks one surface row, labelled with its t and θ; the
/// default draws two (t = ±1/2 at θ = 23°).
#[test]
fn cli_surface_input() {
    let dir = tmp();
    let one = dir.path().join("one.svg");
    let (ok, _, err) = subdlab(&[
        "curvature",
        "catmull-clark",
        "-n",
        "5",
        "--figure",
        "surface",
        "--input",
        "-0.25,40",
        "-o",
        one.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let text = std::fs::read_to_string(&one).unwrap();
    assert!(text.contains("t = -0.25") && text.contains("θ = 40°") && text.contains("hyperbolic"));
    assert!(!text.contains("t = 0.5"));
    let two = dir.path().join("two.svg");
    let (ok, _, err) =
        subdlab(&["curvature", "catmull-clark", "-n", "5", "--figure", "surface", "-o", two.to_str().unwrap()]);
    assert!(ok, "{err}");
    let text = std::fs::read_to_string(&two).unwrap();
    assert!(text.contains("t = 0.5") && text.contains("t = -0.5") && text.contains("θ = 23°"));
}

/// 4-3's centre_weight is the eon rule's; a QQQQ centre is a regular quad
/// vertex (four quads: rule 1a, `sdc::slots::classify`) and ignores it, which
/// the table says. Catmull–Clark n = 3 (|μ| < λ², the flat-spot class)
/// prints its C² test as flat, and its JSON keeps `holds`.
#[test]
fn cli_curvature_notes() {
    let (ok, out, err) =
        subdlab(&["curvature", "four-three", "-n", "4", "--faces", "QQQQ", "--param", "centre_weight=0.3"]);
    assert!(ok, "{err}");
    assert!(out.contains("centre_weight has no effect") && out.contains("regular quad vertex"), "{out}");
    let (ok, out, err) =
        subdlab(&["curvature", "four-three", "-n", "5", "--faces", "QQQQQ", "--param", "centre_weight=0.3"]);
    assert!(ok, "{err}");
    assert!(!out.contains("no effect"), "an eon uses centre_weight: {out}");
    // the note's premise: the QQQQ spectrum does not move with centre_weight
    // (it does at the QQQQQ eon)
    let eigs = |faces: &str, w: &str| -> Vec<f64> {
        let n = faces.len().to_string();
        let param = format!("centre_weight={w}");
        let (ok, out, err) =
            subdlab(&["spectrum", "four-three", "-n", &n, "--faces", faces, "--param", &param, "--json"]);
        assert!(ok, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        v["eigenvalues"].as_array().unwrap().iter().map(|e| e["modulus"].as_f64().unwrap()).collect()
    };
    assert_eq!(eigs("QQQQ", "0.3"), eigs("QQQQ", "0.7"));
    assert_ne!(eigs("QQQQQ", "0.3"), eigs("QQQQQ", "0.7"));
    let (ok, out, err) = subdlab(&["curvature", "catmull-clark", "-n", "3"]);
    assert!(ok, "{err}");
    assert!(out.contains("C² (flat: curvature → 0)"), "{out}");
    let (ok, out, _) = subdlab(&["curvature", "catmull-clark", "-n", "3", "--json"]);
    assert!(ok);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["class"], "zero");
    assert_eq!(v["c2"]["holds"], true);
}
