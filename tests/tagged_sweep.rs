//! `subdlab sweep --tag`: sweeps over tagged configurations (issue 26).
//! Every expected value is derived by hand below (the derivation of
//! tests/tagged_verdicts.rs, restated where used), none is a number the
//! program printed.
//!
//! A boundary vertex of k sectors. Its local matrix is block triangular
//! over the boundary curve's rows (c, v_0, v_k), whose eigenvalues are the
//! cubic B-spline curve's 1, 1/2, 1/4. The interior's sine modes
//! v_j = a sin(jφ), f_j = b sin((j + 1/2)φ), φ = mπ/k, m = 1 .. k − 1,
//! with the edge weight γ on the centre's neighbour (Hoppe: γ = 3/8) have
//! the eigenvalues
//!
//! - Loop: γ + cos(φ)/4;
//! - Catmull–Clark: those of M(φ) = [[γ + cos φ/8, cos(φ/2)/8],
//!   [cos(φ/2)/2, 1/4]], the larger μ(φ) = tr/2 + sqrt((a − d)²/4 + bc).
//!
//! det(M(φ) − 1/2) = −γ/4 − cos φ/16 + 3/32 (with cos²(φ/2) = (1 + cos φ)/2),
//! and tr M < 1 for γ ≤ 3/8, so μ(φ) > 1/2 iff γ > 3/8 − cos(φ)/4 and
//! μ(φ) = 1/2 iff equality. Hence with Hoppe's γ = 3/8 (Catmull–Clark):
//! mode m sits above 1/2 iff cos(mπ/k) > 0, i.e. 2m < k; at 2m = k it is
//! 1/2, a Jordan block with the curve's tangent for even m (k = 4), and
//! k = 1 has 1/4 twice, defective. An eigenvector whose eigenvalue is not
//! the curve's vanishes on the curve, so when the two leading modes lie
//! above 1/2 (k ≥ 5) the characteristic map sends the boundary rays to the
//! centre.
//!
//! `blz = t` blends γ linearly from Hoppe's 3/8 (t = 0) to
//! Biermann–Levin–Zorin's 3/8 − cos(π/k)/4 (t = 1): γ(t) = 3/8 −
//! t cos(π/k)/4. Mode m is above 1/2 iff γ(t) > 3/8 − cos(mπ/k)/4, i.e.
//! t < cos(mπ/k)/cos(π/k). At k = 5, m = 2: t* = cos(2π/5)/cos(π/5) =
//! ((√5 − 1)/4)/((√5 + 1)/4) = (3 − √5)/2 ≈ 0.382: below t* the two leading
//! modes are above 1/2 (rays collapse), above t* only mode 1 is, λ2 is the
//! curve's 1/2 (its eigenvector the tangent (0, 1, −1), not zero on the
//! rays), and at t = 1 mode 1 is 1/2 exactly: λ1 = λ2 = 1/2, the BLZ rules.

use crate::common;
use common::{fails, subdlab};

fn json(args: &[&str]) -> serde_json::Value {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The larger eigenvalue of Catmull–Clark's mode matrix M(φ) at edge weight γ.
fn cc_mode(gamma: f64, phi: f64) -> f64 {
    let (a, b, c, d) = (gamma + phi.cos() / 8.0, (phi / 2.0).cos() / 8.0, (phi / 2.0).cos() / 2.0, 0.25);
    (a + d) / 2.0 + ((a - d) * (a - d) / 4.0 + b * c).sqrt()
}

fn failing(p: &serde_json::Value) -> Vec<String> {
    p["failing"].as_array().unwrap().iter().map(|s| s.as_str().unwrap().to_string()).collect()
}

fn lambda(p: &serde_json::Value, i: usize) -> f64 {
    p["lambda"][i].as_f64().unwrap()
}

const COLLAPSE: &str = "vanish on the sharp rays";

/// Catmull–Clark boundary, Hoppe's rules, k = 1..8: the leading moduli are
/// the hand modes, and every verdict is the derived one with its reason.
#[test]
fn catmull_clark_boundary_sweep_follows_the_mode_derivation() {
    let v = json(&["sweep", "catmull-clark", "--tag", "boundary", "--sectors", "1..8", "--charmap", "--json"]);
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 8);
    let pi = std::f64::consts::PI;
    for p in points {
        let k = p["valence"].as_u64().unwrap() as usize;
        let f = failing(p);
        let admissible = p["c1_spectral"].as_bool().unwrap() && p["charmap"].as_bool().unwrap();
        assert_eq!(admissible, f.is_empty(), "k = {k}: failing is empty exactly when the point passes: {f:?}");
        assert!((lambda(p, 0) - 1.0).abs() < 1e-12, "k = {k}");
        // the modes m = 1, 2 (where they exist) and the curve's 1/2, largest first
        let mut leading: Vec<f64> = (1..k.min(3)).map(|m| cc_mode(0.375, m as f64 * pi / k as f64)).collect();
        leading.push(0.5);
        if k == 1 {
            leading = vec![0.5, 0.25];
        }
        leading.sort_by(|a, b| b.total_cmp(a));
        for (i, want) in leading.iter().take(2).enumerate() {
            assert!(
                (lambda(p, i + 1) - want).abs() < 1e-9,
                "k = {k}: |λ{}| = {} against {want}",
                i + 1,
                lambda(p, i + 1)
            );
        }
        match k {
            // 1/4 twice from the curve and the one face, a Jordan block
            1 => assert!(f[0].contains("defective") && f[0].contains("0.25"), "{f:?}"),
            2 | 3 => assert!(admissible, "k = {k}: {f:?}"),
            // mode 2 at 1/2 couples to the curve's tangent
            4 => assert!(f[0].contains("defective") && f[0].contains("0.5"), "{f:?}"),
            _ => {
                assert!(p["c1_spectral"].as_bool().unwrap(), "k = {k}: two simple modes above 1/2: {f:?}");
                assert!(f.len() == 1 && f[0].contains(COLLAPSE), "k = {k}: {f:?}");
            }
        }
    }
}

/// Loop boundary, Hoppe's rules: mode m is 3/8 + cos(mπ/k)/4, at 1/2 when
/// k = 3m; k = 6 (m = 2) is defective, k ≥ 7 has two modes above 1/2.
#[test]
fn loop_boundary_sweep_follows_the_mode_derivation() {
    let v = json(&["sweep", "loop", "--tag", "boundary", "--sectors", "2..8", "--charmap", "--json"]);
    let pi = std::f64::consts::PI;
    for p in v["points"].as_array().unwrap() {
        let k = p["valence"].as_u64().unwrap() as usize;
        let mut leading: Vec<f64> = (1..k.min(3)).map(|m| 0.375 + (m as f64 * pi / k as f64).cos() / 4.0).collect();
        leading.push(0.5);
        leading.sort_by(|a, b| b.total_cmp(a));
        assert!((lambda(p, 1) - leading[0]).abs() < 1e-9, "k = {k}");
        let f = failing(p);
        match k {
            2..=5 => assert!(f.is_empty(), "k = {k}: {f:?}"),
            6 => assert!(f[0].contains("defective") && f[0].contains("0.5"), "{f:?}"),
            _ => assert!(f.len() == 1 && f[0].contains(COLLAPSE), "k = {k}: {f:?}"),
        }
    }
}

/// A sweep point is the single-point run `spectrum --tag --no-exact`.
#[test]
fn tagged_points_equal_single_point_runs() {
    let v = json(&["sweep", "catmull-clark", "--tag", "crease:2", "--valences", "3..6", "--json"]);
    for p in v["points"].as_array().unwrap() {
        let n = p["valence"].as_u64().unwrap().to_string();
        let single = json(&["spectrum", "catmull-clark", "-n", &n, "--tag", "crease:2", "--json", "--no-exact"]);
        assert_eq!(p["lambda"][1].as_f64().unwrap(), single["eigenvalues"][1]["modulus"].as_f64().unwrap(), "n = {n}");
        assert_eq!(p["c1_spectral"], single["verdict"]["c1_spectral"], "n = {n}");
        assert_eq!(p["failing"], single["verdict"]["failures"], "n = {n}");
    }
}

/// The BLZ blend at k = 5: the map collapses below t* = (3 − √5)/2 and not
/// above; λ1 is mode 1 at γ(t) (above 1/2 until t = 1); t = 1 passes with
/// λ1 = λ2 = 1/2, t = 0 (Hoppe) fails.
#[test]
fn blz_blend_at_five_quads_changes_verdict_at_the_derived_threshold() {
    let v = json(&[
        "sweep",
        "catmull-clark",
        "--tag",
        "boundary",
        "--sectors",
        "5..5",
        "-p",
        "blz=0:1:1/8",
        "--charmap",
        "--json",
    ]);
    let pi = std::f64::consts::PI;
    let threshold = (3.0 - 5f64.sqrt()) / 2.0;
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 9);
    for (i, p) in points.iter().enumerate() {
        let t = i as f64 / 8.0;
        let gamma = 0.375 - t * (pi / 5.0).cos() / 4.0;
        let mode1 = cc_mode(gamma, pi / 5.0);
        assert!((lambda(p, 1) - mode1.max(0.5)).abs() < 1e-9, "t = {t}: {} against {mode1}", lambda(p, 1));
        let f = failing(p);
        let collapsed = f.iter().any(|r| r.contains(COLLAPSE));
        assert_eq!(collapsed, t < threshold, "t = {t}: {f:?}");
        if t < threshold {
            // mode 2 is λ2, above 1/2
            assert!((lambda(p, 2) - cc_mode(gamma, 2.0 * pi / 5.0)).abs() < 1e-9, "t = {t}");
        } else {
            assert!((lambda(p, 2) - 0.5).abs() < 1e-9, "t = {t}: λ2 is the curve's 1/2");
        }
    }
    assert!(!failing(&points[0]).is_empty(), "Hoppe's rules at 5 quads");
    assert!(failing(&points[8]).is_empty(), "BLZ's rules at 5 quads: {:?}", failing(&points[8]));
    assert!((lambda(&points[8], 1) - 0.5).abs() < 1e-12 && (lambda(&points[8], 2) - 0.5).abs() < 1e-12);
    let admissible = v["admissible"].as_array().unwrap();
    assert_eq!(admissible.len(), 1);
    assert_eq!((admissible[0]["from"].as_str(), admissible[0]["to"].as_str()), (Some("1/2"), Some("1")));
}

/// The table names the configuration, the criterion and the evidence, and
/// each row its verdict; the CSV has the verdict and the failing conditions
/// as its last two columns.
#[test]
fn table_and_csv_carry_the_verdict() {
    let out = subdlab(&["sweep", "catmull-clark", "--tag", "boundary", "--sectors", "3..4"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("boundary vertex") && text.contains("sector criterion") && text.contains("floating point"));
    let rows: Vec<&str> = text.lines().filter(|l| l.trim_start().starts_with(['3', '4'])).collect();
    assert_eq!(rows.len(), 2, "{text}");
    assert!(rows[0].ends_with("PASSES"), "{text}");
    assert!(rows[1].contains("FAILS: ") && rows[1].contains("defective"), "{text}");
    let out = subdlab(&["sweep", "catmull-clark", "--tag", "boundary", "--sectors", "3..4", "--csv"]);
    let csv = String::from_utf8(out.stdout).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(&head[head.len() - 2..], ["verdict", "failing"]);
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert!(rows.iter().all(|r| r.len() == head.len()), "{csv}");
    assert_eq!(rows[0][head.len() - 2], "PASSES");
    assert_eq!(rows[1][head.len() - 2], "FAILS");
    assert!(rows[1][head.len() - 1].contains("defective"), "{csv}");
}

/// A parameter sweep at a tagged vertex draws its figure like any sweep.
#[test]
fn tagged_parameter_sweep_plots() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("blz.svg");
    let f = path.to_str().unwrap();
    let out = subdlab(&["sweep", "loop", "--tag", "boundary", "--sectors", "6..8", "-p", "blz=0:1:1/4", "--plot", f]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.contains("<svg") && svg.contains("blz"));
}

#[test]
fn tagged_sweep_errors_are_one_line() {
    let e = fails(&["sweep", "catmull-clark", "--tag", "boundary", "--sectors", "0..3"]);
    assert!(e.contains("at least 1 sector"), "{e}");
    let e = fails(&["sweep", "catmull-clark", "--tag", "crease:3", "--valences", "3..5"]);
    assert!(e.contains("crease:3"), "{e}");
    let e = fails(&["sweep", "catmull-clark", "--tag", "edge", "--valences", "3..5"]);
    assert!(e.contains("--tag 'edge'"), "{e}");
    let e = fails(&["sweep", "catmull-clark", "--tag", "boundary", "--sectors", "2..4", "--curvature"]);
    assert!(e.contains("curvature"), "{e}");
    let e =
        fails(&["sweep", "catmull-clark", "--tag", "boundary", "--sectors", "2..4", "-p", "blz=0:1:1/2", "--exact"]);
    assert!(e.contains("--exact"), "{e}");
    // a scheme without crease rules refuses the tagged configuration
    let e = fails(&["sweep", "doo-sabin", "--tag", "boundary", "--sectors", "2..4"]);
    assert!(!e.is_empty());
}

/// `spectrum --tag` prints the spectrum per reflection block: at a
/// Catmull–Clark boundary vertex of 4 quads the tangent (0, 1, −1) and the
/// sine mode m = 2 are both odd under j ↦ k − j, so the Jordan block at 1/2
/// is in the odd block (tests/reflection_split.rs derives it exactly).
#[test]
fn spectrum_prints_the_reflection_blocks() {
    let out = subdlab(&["spectrum", "catmull-clark", "-n", "4", "--tag", "boundary", "--no-exact"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("reflection r -> 4 - r"), "{text}");
    let odd = text.lines().find(|l| l.trim_start().starts_with("odd")).unwrap();
    assert!(odd.contains("0.5 (x2, defective"), "{text}");
    let v = json(&["spectrum", "catmull-clark", "-n", "4", "--tag", "boundary", "--no-exact", "--json"]);
    let first = &v["reflection"]["odd"][0];
    assert_eq!(
        (first["algebraic_multiplicity"].as_u64(), first["geometric_multiplicity"].as_u64()),
        (Some(2), Some(1))
    );
    assert!((first["re"].as_f64().unwrap() - 0.5).abs() < 1e-9);
    let interior = json(&["spectrum", "catmull-clark", "-n", "5", "--no-exact", "--json"]);
    assert!(interior.get("reflection").is_none());
}
