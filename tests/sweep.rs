//! `subdlab sweep`: every point is the single-point analysis, and the
//! admissible intervals of non-box's a reproduce the G^1 bound
//! a_k > 1/4 − cos(2π/k)/4 derived in the paper (and in tests/non_box.rs)
//! to within the grid step.

mod common;
use common::{fails, subdlab};

fn json(args: &[&str]) -> serde_json::Value {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn points_equal_single_point_runs() {
    let v = json(&["sweep", "loop", "--valences", "3..7", "--json"]);
    for p in v["points"].as_array().unwrap() {
        let n = p["valence"].as_u64().unwrap().to_string();
        let single = json(&["spectrum", "loop", "--valence", &n, "--json", "--no-exact"]);
        let l1 = single["eigenvalues"][1]["modulus"].as_f64().unwrap();
        assert_eq!(p["lambda"][1].as_f64().unwrap(), l1, "n = {n}");
        assert_eq!(p["c1_spectral"], single["verdict"]["c1_spectral"]);
    }
}

#[test]
fn admissible_intervals_follow_the_g1_bound() {
    let step = 0.01;
    let v = json(&["sweep", "non-box", "--valences", "3..8", "--param", "a=0:0.75:0.01", "--json"]);
    let intervals = v["admissible"].as_array().unwrap();
    for k in [3usize, 5, 6, 7, 8] {
        let bound = 0.25 - 0.25 * (2.0 * std::f64::consts::PI / k as f64).cos();
        let i: Vec<_> = intervals.iter().filter(|i| i["valence"].as_u64() == Some(k as u64)).collect();
        assert_eq!(i.len(), 1, "one interval at k = {k}");
        let from = subdlab::numeric::ParamValue::parse(i[0]["from"].as_str().unwrap()).unwrap().value;
        assert!(from > bound && from <= bound + step + 1e-12, "k = {k}: interval starts at {from}, bound {bound}");
    }
}

#[test]
fn bad_sweeps_are_one_line_errors() {
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:0.1", "--param", "a=0:1:0.5"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=1:0:0.1"]);
    fails(&["sweep", "non-box", "--valences", "5..3"]);
    fails(&["sweep", "non-box", "--valences", "3..5000"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--json", "--csv"]);
    fails(&["sweep", "no-such-scheme", "--valences", "3..5"]);
    fails(&["sweep", "loop", "--valences", "3..5", "--param", "q=0:1:0.5"]);
}

/// The figure draws one cell per grid point in the colour of its status (plus
/// one legend swatch per status that occurs): the counts must equal those of
/// the JSON points of the same sweep.
#[test]
fn plot_cells_match_the_points() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("sweep.svg");
    let svg_arg = svg.to_str().unwrap();
    let args = ["sweep", "non-box", "--valences", "3..6", "--param", "a=0:1/2:1/20"];
    let bound = "1/4 - cos(2 pi / n)/4";
    let out = subdlab(&[&args[..], &["--plot", svg_arg, "--bound", bound, "--json"]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty(), "no progress bar when standard error is not a terminal");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 4 * 11);
    let passing = points.iter().filter(|p| p["c1_spectral"] == true).count();
    let failing = points.len() - passing;
    assert!(passing > 0 && failing > 0, "this grid straddles the bound");
    let text = std::fs::read_to_string(&svg).unwrap();
    // rect elements whose attributes carry the fill
    let count =
        |fill: &str| text.split("<rect").skip(1).filter(|r| r.split('>').next().unwrap().contains(fill)).count();
    assert_eq!(count("fill=\"#66B266\""), passing + 1, "admissible cells + legend swatch");
    assert_eq!(count("fill=\"#F4BEBA\""), failing + 1, "failing cells + legend swatch");
    assert!(text.contains("admissible a per valence") && text.contains("parameter a") && text.contains("valence n"));
    assert!(text.contains(&format!("bound {bound}")));
    // PNG quick look of the same sweep
    let png = dir.path().join("sweep.png");
    let out = subdlab(&[&args[..], &["--plot", png.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(&std::fs::read(&png).unwrap()[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn bad_plots_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("s.svg");
    let svg = svg.to_str().unwrap();
    // no swept parameter, --bound without --plot, bad bound, bad extension, unwritable path
    fails(&["sweep", "loop", "--valences", "3..5", "--plot", svg]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--bound", "1/4"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", svg, "--bound", "1/("]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", svg, "--bound", "q + 1"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", svg, "--bound", "sqrt(n - 4)"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", "s.pdf"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", "/no/such/dir/s.svg"]);
    assert!(!std::path::Path::new(svg).exists(), "failed runs write no figure");
}
