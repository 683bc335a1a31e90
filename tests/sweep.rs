//! `subdlab sweep`: every point is the single-point analysis, and the
//! admissible intervals of non-box's a reproduce the G^1 bound
//! a_k > 1/4 − cos(2π/k)/4 derived in the paper (and in tests/non_box.rs)
//! to within the grid step.

use crate::common;
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
    // a sweep's cost is about the sum of its valences: 3..5000 (12.5 million)
    // is refused before any work, while a few high valences are a cheap sweep
    let e = fails(&["sweep", "non-box", "--valences", "3..5000"]);
    assert!(e.contains("sums to 12502497") && e.contains("limit 500497"), "{e}");
    let out = subdlab(&["sweep", "non-box", "--valences", "4999..5000", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
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
    // no swept parameter (without --curvature), --bound without --plot, bad bound, bad extension, unwritable path
    fails(&["sweep", "loop", "--valences", "3..5", "--plot", svg]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--bound", "1/4"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", svg, "--bound", "1/("]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", svg, "--bound", "q + 1"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", svg, "--bound", "sqrt(n - 4)"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", "s.eps"]);
    fails(&["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/2", "--plot", "/no/such/dir/s.svg"]);
    assert!(!std::path::Path::new(svg).exists(), "failed runs write no figure");
}

/// A Loop variant whose extraordinary vertices move by nβ = w (regular
/// vertices keep Loop's 1/16): its local spectrum is known in closed form,
/// so both kinds of interval can be predicted. On the minimal neighbourhood
/// (centre and ring) block 0 has {1, 5/8 − w} and block m ≥ 1 has
/// 3/8 + cos(2πm/n)/4 (the ring's circulant edge rule); the outer rings of
/// the analysis neighbourhood add regular-rule eigenvalues 1/8 and below.
/// Hence: convergent iff |5/8 − w| < 1, i.e. w < 13/8; spectral C¹ iff
/// |5/8 − w| < λ1 = 3/8 + cos(2π/n)/4, i.e. 1/4 − c/4 < w < 1 + c/4 with
/// c = cos(2π/n). At n = 6 the kronecker term makes every w regular Loop.
#[test]
fn convergent_and_admissible_intervals_match_the_closed_form() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("loop-w.toml");
    std::fs::write(
        &file,
        "name = \"loop-w\"\ntopology = \"primal-triangle\"\n\
         [params.w]\ndefault = \"3/8\"\nmin = 0\nmax = 2\n\
         [vertex]\ncentre = \"1 - w + kronecker(n - 6) (w - 3/8)\"\nedge = \"(w - kronecker(n - 6) (w - 3/8)) / n\"\n\
         [edge]\nends = \"3/8\"\nopposite = \"1/8\"\n",
    )
    .unwrap();
    let v = json(&["sweep", file.to_str().unwrap(), "--valences", "3..6", "--param", "w=0:2:1/8", "--json"]);
    let q = |s: &str| subdlab::numeric::ParamValue::parse(s).unwrap().value;
    let step = 0.125;
    for n in 3..=6usize {
        let of = |key: &str| -> Vec<(f64, f64)> {
            v[key]
                .as_array()
                .unwrap()
                .iter()
                .filter(|i| i["valence"].as_u64() == Some(n as u64))
                .map(|i| (q(i["from"].as_str().unwrap()), q(i["to"].as_str().unwrap())))
                .collect()
        };
        let (conv, adm) = (of("convergent"), of("admissible"));
        let c = (2.0 * std::f64::consts::PI / n as f64).cos();
        // the exact open intervals, clipped to the parameter range [0, 2]
        let (conv_lo, conv_hi, adm_lo, adm_hi) =
            if n == 6 { (-1.0, 3.0, -1.0, 3.0) } else { (-3.0 / 8.0, 13.0 / 8.0, 0.25 - c / 4.0, 1.0 + c / 4.0) };
        // the grid points strictly inside
        let inside = |lo: f64, hi: f64| {
            let pts: Vec<f64> =
                (0..=16).map(|k| k as f64 * step).filter(|&w| w > lo + 1e-12 && w < hi - 1e-12).collect();
            (pts[0], *pts.last().unwrap())
        };
        assert_eq!(conv, vec![inside(conv_lo, conv_hi)], "convergent, n = {n}");
        assert_eq!(adm, vec![inside(adm_lo, adm_hi)], "admissible, n = {n}");
    }
    // the text names the runs as grid points, never as closed intervals: at
    // n = 3 (c = −1/2) the admissible set is the open (3/8, 7/8), whose grid
    // points are 1/2..3/4; the convergent one (−3/8, 13/8) has 0..3/2
    let out = subdlab(&["sweep", file.to_str().unwrap(), "--valences", "3..3", "--param", "w=0:2:1/8"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("valence    3: grid points 1/2..3/4 (step 1/8)"), "{text}");
    assert!(text.contains("valence    3: grid points 0..3/2 (step 1/8)"), "{text}");
    assert!(!text.contains(": [1/2, 3/4]"), "{text}");
}

/// The points do not depend on how many worker threads compute them.
#[test]
fn thread_count_does_not_change_the_points() {
    let args = ["sweep", "non-box", "--valences", "3..9", "--param", "a=0:1:1/8", "--csv"];
    let one = subdlab(&[&args[..], &["--threads", "1"]].concat());
    let three = subdlab(&[&args[..], &["--threads", "3"]].concat());
    let all = subdlab(&args);
    assert!(one.status.success() && three.status.success() && all.status.success());
    assert_eq!(one.stdout, three.stdout);
    assert_eq!(one.stdout, all.stdout);
    fails(&[&args[..], &["--threads", "5000"]].concat());
    fails(&[&args[..], &["--threads", "-1"]].concat());
}

/// Mixed-mesh schemes sweep one face sequence; each point is the single-point
/// `spectrum --faces` run.
#[test]
fn face_sequences_sweep_like_single_points() {
    let v = json(&[
        "sweep",
        "four-three",
        "--valences",
        "5..5",
        "--faces",
        "QQTQT",
        "--param",
        "centre_weight=1/4:3/4:1/4",
        "--json",
    ]);
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 3);
    for p in points {
        let w = p["param"].as_str().unwrap();
        let single = json(&[
            "spectrum",
            "four-three",
            "--valence",
            "5",
            "--faces",
            "QQTQT",
            "-p",
            &format!("centre_weight={w}"),
            "--json",
            "--no-exact",
        ]);
        assert_eq!(single["faces"], "QQTQT");
        let expanded: Vec<f64> = single["eigenvalues"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|e| {
                std::iter::repeat_n(
                    e["modulus"].as_f64().unwrap(),
                    e["algebraic_multiplicity"].as_u64().unwrap() as usize,
                )
            })
            .take(4)
            .collect();
        let lambda: Vec<f64> = p["lambda"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        assert_eq!(lambda, expanded, "centre_weight = {w}");
        assert_eq!(p["c1_spectral"], single["verdict"]["c1_spectral"]);
    }
    fails(&["sweep", "four-three", "--valences", "5..6", "--faces", "QQTQT"]);
    fails(&["sweep", "four-three", "--valences", "5..5", "--faces", "QQXQT"]);
}

/// With --charmap a point's map verdict is the single-point `charmap` run's
/// (same levels and resolution: the command's defaults unless given).
#[test]
fn charmap_points_equal_single_point_runs() {
    for extra in [&[][..], &["--levels", "3", "--resolution", "128"][..]] {
        let args =
            [&["sweep", "non-box", "--valences", "3..5", "--param", "a=1/4:3/4:1/4", "--charmap", "--json"][..], extra]
                .concat();
        let v = json(&args);
        for p in v["points"].as_array().unwrap() {
            let (n, a) = (p["valence"].as_u64().unwrap().to_string(), p["param"].as_str().unwrap());
            let single = json(
                &[&["charmap", "non-box", "--valence", &n, "-p", &format!("a={a}"), "--json"][..], extra].concat(),
            );
            let expected = single["c1_spectral"] == true && single["regular"] == true && single["injective"] == true;
            assert_eq!(p["charmap"].as_bool(), Some(expected), "n = {n}, a = {a}, {extra:?}");
        }
    }
    let base = ["sweep", "non-box", "--valences", "3..5", "--param", "a=1/4:3/4:1/4"];
    fails(&[&base[..], &["--levels", "3"]].concat());
    fails(&[&base[..], &["--charmap", "--levels", "0"]].concat());
    fails(&[&base[..], &["--charmap", "--resolution", "5"]].concat());
}

/// The default characteristic-map levels follow the host's growth: a level
/// is one analysis step, 4 faces per face on the binary hosts (4 levels) and
/// 9 on the ternary host and sqrt(3)'s two steps (3 levels: 3³ = 27 subdivisions
/// of an edge against 2⁴ = 16, the nearest resolution). A ternary sweep
/// without `--levels` is the sweep at 3 levels, point for point.
#[test]
fn default_levels_follow_the_hosts_growth() {
    for (scheme, levels) in [("catmull-clark", 4), ("loop", 4), ("doo-sabin", 4), ("tps", 3), ("sqrt3", 3)] {
        let v = json(&["charmap", scheme, "-n", "5", "--json"]);
        assert_eq!(v["levels"].as_u64(), Some(levels), "{scheme}");
    }
    let base = ["sweep", "tps", "--valences", "3..5", "--param", "e=1/4:2/5:3/20", "--charmap", "--json"];
    let default = json(&base);
    let three = json(&[&base[..], &["--levels", "3"]].concat());
    assert_eq!(default["points"], three["points"]);
    assert_eq!(default["admissible"], three["admissible"]);
}

/// Under a pipe the progress bar draws nothing; plain progress lines say the
/// sweep is alive (every SUBDLAB_PROGRESS_SECONDS, 10 by default).
#[test]
fn a_piped_sweep_prints_plain_progress_lines() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab"))
        .args(["sweep", "loop", "--valences", "3..6"])
        .env("SUBDLAB_PROGRESS_SECONDS", "0")
        .output()
        .expect("binary runs");
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err.lines().filter(|l| l.starts_with("sweep: ")).collect();
    assert!(!lines.is_empty(), "no progress line on a piped stderr: {err:?}");
    assert!(lines.iter().all(|l| l.contains("/4 points")), "{lines:?}");
}

/// Loop's curvature class in closed form (derived in tests/curvature_loop.rs
/// and rechecked here): λ = b(1), b(m) = 3/8 + cos(2πm/n)/4 the eigenvalue of
/// Fourier block m on the 1-ring, λ² the second eigenvalue of block 0 (Loop's
/// β), and 1/8 from ring 2. μ = max(b(2), 1/8, λ²) for n ≥ 4, μ = 1/8 for
/// n = 3 (blocks 1 and 2 both carry λ = 1/4). So the class is bounded exactly
/// when b(2) ≤ λ² and 1/8 ≤ λ², i.e. n = 4, 5, 6, and unbounded otherwise;
/// the L_p limit is 2 ln λ / (2 ln λ − ln μ).
fn loop_closed_form(n: usize) -> (&'static str, Option<f64>) {
    let b = |m: usize| 3.0 / 8.0 + (2.0 * std::f64::consts::PI * m as f64 / n as f64).cos() / 4.0;
    let lam = b(1);
    let l2 = lam * lam;
    let mu = if n == 3 { 0.125 } else { b(2).max(0.125).max(l2) };
    if mu > l2 * (1.0 + 1e-9) {
        ("unbounded", Some(2.0 * lam.ln() / (2.0 * lam.ln() - mu.ln())))
    } else {
        ("bounded", None)
    }
}

#[test]
fn loop_closed_form_switches_at_seven() {
    let classes: Vec<&str> = (3..=12).map(|n| loop_closed_form(n).0).collect();
    assert_eq!(classes[..5], ["unbounded", "bounded", "bounded", "bounded", "unbounded"]);
    assert!(classes[4..].iter().all(|c| *c == "unbounded"));
    // p* = 4 at n = 3: 2 ln(1/4) / (2 ln(1/4) − ln(1/8)) = −4 ln 2 / (−ln 2)
    assert!((loop_closed_form(3).1.unwrap() - 4.0).abs() < 1e-12);
}

/// `--curvature` adds `curvature_class` and `lp_limit` to every point (JSON,
/// and as the last CSV columns, after `error`): equal to the library's
/// `curvature()` (with its exact stage) and to the closed form.
#[test]
fn curvature_columns_equal_single_point_runs_and_the_closed_form() {
    use subdlab::curvature::{curvature_of, CurvatureOptions};
    let v = json(&["sweep", "loop", "--valences", "3..10", "--curvature", "--json"]);
    let out = subdlab(&["sweep", "loop", "--valences", "3..10", "--curvature", "--csv"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = String::from_utf8(out.stdout).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        head,
        [
            "valence",
            "",
            "lambda0",
            "lambda1",
            "lambda2",
            "lambda3",
            "convergent",
            "c1_spectral",
            "charmap",
            "error",
            "curvature_class",
            "lp_limit",
            "verdict",
            "failing"
        ]
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let scheme = subdlab::schemes::build("loop", &[]).unwrap();
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 8);
    for (p, row) in points.iter().zip(&rows) {
        let n = p["valence"].as_u64().unwrap() as usize;
        let single = curvature_of(scheme.as_ref(), n, &CurvatureOptions::default()).unwrap();
        let (class, lp) = loop_closed_form(n);
        assert_eq!(p["curvature_class"].as_str().unwrap(), single.class.name(), "n = {n}");
        assert_eq!(p["curvature_class"].as_str().unwrap(), class, "n = {n}");
        assert_eq!(row[10], class, "CSV, n = {n}");
        match lp {
            Some(x) => {
                let json_lp = p["lp_limit"].as_f64().unwrap();
                let csv_lp: f64 = row[11].parse().unwrap();
                assert!((json_lp - x).abs() < 1e-6 * x, "n = {n}: {json_lp} against {x}");
                // (serde_json's default float parser may be one ulp off)
                assert!((csv_lp - json_lp).abs() <= 1e-14 * x, "n = {n}");
                assert!((json_lp - single.lp_limit.unwrap()).abs() < 1e-9 * x, "n = {n}");
            }
            None => {
                assert!(p["lp_limit"].is_null() && single.lp_limit.is_none(), "n = {n}");
                assert_eq!(row[11], "", "n = {n}");
            }
        }
    }
    // Catmull–Clark too: zero at 3, bounded at 4, unbounded from 5 (README),
    // each equal to the library's single-point analysis
    let v = json(&["sweep", "catmull-clark", "--valences", "3..8", "--curvature", "--json"]);
    let scheme = subdlab::schemes::build("catmull-clark", &[]).unwrap();
    for p in v["points"].as_array().unwrap() {
        let n = p["valence"].as_u64().unwrap() as usize;
        let single = curvature_of(scheme.as_ref(), n, &CurvatureOptions::default()).unwrap();
        assert_eq!(p["curvature_class"].as_str().unwrap(), single.class.name(), "n = {n}");
    }
    let classes: Vec<&str> =
        v["points"].as_array().unwrap().iter().map(|p| p["curvature_class"].as_str().unwrap()).collect();
    assert_eq!(classes, ["zero", "bounded", "unbounded", "unbounded", "unbounded", "unbounded"]);
    // without --curvature the new fields are null / empty and the old ones unchanged
    let plain = json(&["sweep", "loop", "--valences", "3..4", "--json"]);
    for p in plain["points"].as_array().unwrap() {
        assert!(p["curvature_class"].is_null() && p["lp_limit"].is_null());
    }
    let out = subdlab(&["sweep", "loop", "--valences", "3..4", "--csv"]);
    let csv = String::from_utf8(out.stdout).unwrap();
    // error, curvature_class and lp_limit empty; then the verdict and (passing) no failing condition
    assert!(csv.lines().skip(1).all(|l| l.ends_with(",,,PASSES,") && l.split(',').count() == 14), "{csv}");
}

/// The figure colours every C¹ cell by its curvature class, with one legend
/// swatch per class present; a sweep over valences alone draws one cell per
/// valence.
#[test]
fn plot_cells_are_coloured_by_curvature_class() {
    const ZERO: &str = "fill=\"#6BAED6\"";
    const BOUNDED: &str = "fill=\"#238B45\"";
    const UNBOUNDED: &str = "fill=\"#8064B4\"";
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("sweep.svg");
    let count = |text: &str, fill: &str| {
        text.split("<rect").skip(1).filter(|r| r.split('>').next().unwrap().contains(fill)).count()
    };
    // Loop over valences: bounded at 4, 5, 6, unbounded at 3 and 7..10 (closed form)
    let out = subdlab(&["sweep", "loop", "--valences", "3..10", "--curvature", "--plot", svg.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    let bounded = (3..=10).filter(|&n| loop_closed_form(n).0 == "bounded").count();
    assert_eq!(bounded, 3);
    assert_eq!(count(&text, BOUNDED), bounded + 1, "bounded cells + legend swatch");
    assert_eq!(count(&text, UNBOUNDED), 8 - bounded + 1, "unbounded cells + legend swatch");
    assert_eq!(count(&text, ZERO), 0, "no zero class, no swatch");
    assert!(text.contains("loop: curvature class per valence"));
    assert!(text.contains("curvature class bounded") && text.contains("curvature class unbounded"));
    assert!(!text.contains("curvature class zero"));
    // a swept parameter: every cell's colour follows its JSON point
    let out = subdlab(&[
        "sweep",
        "non-box",
        "--valences",
        "3..5",
        "--param",
        "a=0:1/2:1/10",
        "--curvature",
        "--json",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let text = std::fs::read_to_string(&svg).unwrap();
    let points = v["points"].as_array().unwrap();
    for (class, fill) in [("zero", ZERO), ("bounded", BOUNDED), ("unbounded", UNBOUNDED)] {
        let cells = points.iter().filter(|p| p["c1_spectral"] == true && p["curvature_class"] == class).count();
        assert_eq!(count(&text, fill), if cells > 0 { cells + 1 } else { 0 }, "{class}");
    }
    let failing = points.iter().filter(|p| p["c1_spectral"] == false && p["convergent"] == true).count();
    assert!(failing > 0);
    assert_eq!(count(&text, "fill=\"#F4BEBA\""), failing + 1, "failing cells keep their colour");
    assert!(points.iter().all(|p| p["c1_spectral"] == true || p["curvature_class"] == "not-applicable"));
}
