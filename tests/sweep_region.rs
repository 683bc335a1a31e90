//! Two swept parameters (`sweep --param w=… --param e=…`): the (w, e)
//! plane at one valence, with the exact ends in w at each e, checked
//! against a closed form derived here, and the figure in its three formats.
//!
//! tests/data/loop-two-weights.toml is Loop with a free vertex weight w
//! (v' = (1 − w) v + (w/n) Σ e_j) and a free edge weight e (edge point
//! (1/2 − e)(both ends) + e (both opposite vertices)). As in
//! tests/sweep_exact.rs (Loop's derivation in tests/curvature_loop.rs):
//! block 0 on (v, mean of the ring) is [[1 − w, w], [1/2 − e, 1/2 + e]],
//! eigenvalues 1 and 1/2 + e − w; block m ≥ 1 of the ring's circulant has
//! 1/2 − e + 2e cos(2πm/n), largest at m = 1: λ1 = 1/2 − e + 2ec,
//! c = cos(2π/n); ring 2 adds e (the new a_j is e a_j + ring-1 terms) and
//! 1/16. At n = 5 with e in [1/16, 3/16]: the other ring-1 blocks are below
//! λ1 in modulus (m = 2: 1/2 − e − 2e·0.809… > 0.19 > 0) and e < λ1. So
//! - convergent iff |1/2 + e − w| < 1: w < 3/2 + e (from w ≥ 0 on);
//! - spectrally C¹ iff |1/2 + e − w| < λ1: 2e(1 − c) < w < 1 + 2ec.

use crate::common;
use common::{fails, subdlab};

const FILE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/loop-two-weights.toml");

/// The decimals of the exact ends printed for `set` in the row of e.
fn ends_in_row(text: &str, e: &str, set: &str) -> Vec<(String, f64)> {
    let mut out = Vec::new();
    let mut inside = false;
    for line in text.lines() {
        if line.starts_with("e = ") {
            inside = line.starts_with(&format!("e = {e}:"));
            continue;
        }
        let key = format!("exact end of the {set} set: w = ");
        if inside {
            if let Some(rest) = line.trim().strip_prefix(&key) {
                let (exact, dec) = rest.rsplit_once('≈').unwrap();
                out.push((exact.trim().to_string(), dec.trim().parse().unwrap()));
            }
        }
    }
    out
}

#[test]
fn two_parameter_sweep_draws_the_plane_with_the_hand_derived_ends() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("region.svg");
    let out = subdlab(&[
        "sweep",
        FILE,
        "--valences",
        "5..5",
        "--param",
        "w=0:2:1/8",
        "--param",
        "e=1/16:3/16:1/16",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    // the evidence of both layers is stated
    assert!(text.contains("grid points floating point") && text.contains("ends exact"), "{text}");
    let c = (2.0 * std::f64::consts::PI / 5.0).cos();
    for (e_text, e, conv_end) in [("1/16", 1.0 / 16.0, "25/16"), ("1/8", 0.125, "13/8"), ("3/16", 3.0 / 16.0, "27/16")]
    {
        let c1 = ends_in_row(&text, e_text, "C1 spectral");
        assert_eq!(c1.len(), 2, "e = {e_text}: {text}");
        assert!((c1[0].1 - 2.0 * e * (1.0 - c)).abs() < 1e-11, "e = {e_text}: lower end {c1:?}");
        assert!((c1[1].1 - (1.0 + 2.0 * e * c)).abs() < 1e-11, "e = {e_text}: upper end {c1:?}");
        // irrational ends are named by their polynomial
        assert!(c1.iter().all(|(x, _)| x.starts_with("the root of")), "{c1:?}");
        // 3/2 + e, exactly
        let conv = ends_in_row(&text, e_text, "convergent");
        assert_eq!(conv.len(), 1, "e = {e_text}: {conv:?}");
        assert_eq!(conv[0].0, conv_end, "e = {e_text}");
    }
    // the figure: well-formed SVG with the exact ends drawn, a PNG, a PDF
    let doc = std::fs::read_to_string(&svg).unwrap();
    roxmltree::Document::parse(&doc).expect("well-formed SVG");
    for ext in ["png", "pdf"] {
        let path = dir.path().join(format!("region.{ext}"));
        let out = subdlab(&[
            "sweep",
            FILE,
            "--valences",
            "5..5",
            "--param",
            "w=0:2:1/4",
            "--param",
            "e=1/16:3/16:1/16",
            "--plot",
            path.to_str().unwrap(),
        ]);
        assert!(out.status.success(), "{ext}: {}", String::from_utf8_lossy(&out.stderr));
        let bytes = std::fs::read(&path).unwrap();
        match ext {
            "png" => {
                let reader = png::Decoder::new(std::io::Cursor::new(&bytes)).read_info().unwrap();
                let info = reader.info();
                assert!(info.width > 500 && info.height > 400, "{}×{}", info.width, info.height);
            }
            _ => assert!(bytes.starts_with(b"%PDF"), "not a PDF"),
        }
    }
}

#[test]
fn two_parameter_sweep_refuses_what_it_cannot_draw() {
    let args = ["sweep", FILE, "--param", "w=0:2:1/4", "--param", "e=1/16:3/16:1/16"];
    let err = fails(&[&args[..], &["--valences", "3..5"]].concat());
    assert!(err.contains("one valence"), "{err}");
    let err = fails(&[&args[..], &["--valences", "5..5", "--json"]].concat());
    assert!(err.contains("--json"), "{err}");
    let err = fails(&[&args[..], &["--valences", "5..5", "--exact"]].concat());
    assert!(err.contains("one parameter"), "{err}");
    // each range under the one-parameter limit, their product far over it
    // (20 001 × 6 251 points: this ran without end before the check)
    let big = ["sweep", FILE, "--valences", "5..5", "--param", "w=0:2:1/10000", "--param", "e=1/16:3/16:1/50000"];
    let err = fails(&big);
    assert!(err.contains("grid points") || err.contains("rows"), "{err}");
    // many rows, few columns: each row is an exact sweep
    let rows = ["sweep", FILE, "--valences", "5..5", "--param", "w=0:2:1", "--param", "e=0:1:1/5000"];
    let err = fails(&rows);
    assert!(err.contains("rows"), "{err}");
}
