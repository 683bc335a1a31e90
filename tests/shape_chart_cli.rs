//! `subdlab shape-chart` on the command line: bad input is a one-line error
//! with a non-zero exit, before any computation; the rows come out as CSV
//! and JSON with one row per (t, θ, m); figures are written.

use crate::common::{fails, subdlab};

#[test]
fn bad_input_is_a_one_line_error() {
    let cases: &[(&[&str], &str)] = &[
        (&["shape-chart", "no-such-scheme"], "unknown scheme"),
        (&["shape-chart", "catmull-clark", "--valences", "5..3"], "valence range"),
        (&["shape-chart", "catmull-clark", "--valences", "3-5"], "A..B"),
        (&["shape-chart", "catmull-clark", "--valences", "3..41"], "limit 40"),
        (&["shape-chart", "catmull-clark", "--valences", "1..3"], "valence"),
        (&["shape-chart", "four-three", "--faces", "QQQQQ", "--valences", "3..5"], "fixes the valence"),
        (&["shape-chart", "catmull-clark", "--t-samples", "1"], "--t-samples"),
        (&["shape-chart", "catmull-clark", "--thetas", "0"], "--thetas"),
        (&["shape-chart", "catmull-clark", "--steps", "0,x"], "--steps"),
        (&["shape-chart", "catmull-clark", "--steps", "61"], "at most 60"),
        (&["shape-chart", "catmull-clark", "--levels", "0"], "levels"),
        (&["shape-chart", "catmull-clark", "--json", "--csv"], "one of --json and --csv"),
        (&["shape-chart", "catmull-clark", "-o", "chart.txt"], "extension"),
        (&["shape-chart", "catmull-clark", "--theta-valence", "5"], "--theta-out"),
        (&["shape-chart", "catmull-clark", "--width", "400"], "style flags"),
        (&["shape-chart", "catmull-clark", "--param", "nonsense"], "NAME=VALUE"),
        (&["shape-chart", "four-point"], "curve scheme"),
    ];
    for (args, want) in cases {
        let err = fails(args);
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

/// CSV: the header names the columns the issue asks for, and a chart of one
/// valence with 3 values of t, 2 angles and the steps 0 and ∞ has 3·2·2 rows.
/// At the regular Catmull–Clark vertex every input is reproduced (bicubic
/// B-splines have quadratic precision).
#[test]
fn csv_rows_cover_the_grid() {
    let out = subdlab(&[
        "shape-chart",
        "catmull-clark",
        "--valences",
        "4..4",
        "--t-samples",
        "3",
        "--thetas",
        "2",
        "--steps",
        "0",
        "--csv",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    for col in ["n", "t", "theta_degrees", "m", "nu", "g", "sign_fraction", "residual", "category"] {
        assert!(header.contains(&col), "{col} missing from {header:?}");
    }
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 3 * 2 * 2);
    let cat = header.iter().position(|c| *c == "category").unwrap();
    assert!(rows.iter().all(|r| r[cat] == "correct"), "{text}");
}

#[test]
fn json_and_figures() {
    let dir = std::env::temp_dir().join(format!("subdlab-shape-chart-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (svg, png) = (dir.join("chart.svg"), dir.join("theta.png"));
    let out = subdlab(&[
        "shape-chart",
        "loop",
        "--valences",
        "5..6",
        "--t-samples",
        "5",
        "--thetas",
        "1",
        "--steps",
        "0",
        "-o",
        svg.to_str().unwrap(),
        "--theta-out",
        png.to_str().unwrap(),
        "--theta-valence",
        "5",
        "--theta-samples",
        "2",
        "--json",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["valences"].as_array().unwrap().len(), 2);
    assert_eq!(v["valences"][0]["rows"].as_array().unwrap().len(), 5 * 2);
    assert_eq!(v["theta_chart"]["n"], 5);
    assert_eq!(v["theta_chart"]["thetas"].as_array().unwrap().len(), 2);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains("shape chart"));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    std::fs::remove_dir_all(&dir).ok();
}
