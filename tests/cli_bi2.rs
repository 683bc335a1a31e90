//! The command line on the bi-2 schemes of Karčiauskas–Peters (pgs,
//! polar-bi2, tps): listing, analysis commands, refinement, one-line errors.

use crate::common;
use common::{fails, subdlab};

fn json(args: &[&str]) -> serde_json::Value {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

#[test]
fn schemes_lists_the_bi2_schemes_with_their_parameters() {
    let v = json(&["schemes", "--json"]);
    let find = |name: &str| v.as_array().unwrap().iter().find(|e| e["name"] == name).cloned().unwrap();
    let tps = find("tps");
    assert_eq!(tps["params"][0]["name"], "e");
    assert_eq!(tps["params"][0]["default"], "1/3");
    let pgs = find("pgs");
    let names: Vec<&str> = pgs["params"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["mu", "lambda_sub"]);
    assert_eq!(find("polar-bi2")["params"][0]["name"], "alpha");
}

#[test]
fn spectrum_stencils_and_matrix_cover_the_bi2_schemes() {
    // (scheme, centre kind, analysis size at valence 5: 6n+1, 4n+1, 3n+1)
    for (scheme, centre, size) in [("tps", "vertex", 31), ("pgs", "augmented-face", 21), ("polar-bi2", "polar", 16)] {
        let v = json(&["spectrum", scheme, "--valence", "5", "--json"]);
        assert_eq!(v["centre"], centre, "{scheme}");
        assert_eq!(v["matrix_size"], size, "{scheme}");
        assert_eq!(v["verdict"]["c1_spectral"], true, "{scheme}");
        let s = json(&["stencils", scheme, "--valence", "5", "--json"]);
        assert!(s.is_object(), "{scheme}");
        let out = subdlab(&["matrix", scheme, "--valence", "5", "--format", "mtx"]);
        assert!(out.status.success(), "{scheme}");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.starts_with("%%MatrixMarket"), "{scheme}");
        // the size line: rows, columns, non-zeros
        let dims: Vec<usize> = text
            .lines()
            .find(|l| !l.starts_with('%'))
            .unwrap()
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect();
        assert_eq!(dims[..2], [size, size], "{scheme}");
    }
    let v = json(&["spectrum", "tps", "--valence", "5", "--param", "e=1/5", "--json"]);
    assert_eq!(v["params"]["e"], "1/5");
}

#[test]
fn refine_runs_on_real_meshes_and_rejects_unsuitable_ones() {
    // a folder of its own: every test of the suite binary runs in this process
    let dir = tempfile::tempdir().unwrap();
    let out = |name: &str| dir.path().join(name).to_string_lossy().into_owned();
    let ok = |args: &[&str]| {
        let o = subdlab(args);
        assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    };
    ok(&["refine", "meshes/cube.obj", "--scheme", "tps", "--levels", "1", "-o", &out("cube-tps.obj")]);
    let text = std::fs::read_to_string(out("cube-tps.obj")).unwrap();
    assert_eq!(text.lines().filter(|l| l.starts_with("f ")).count(), 54);
    ok(&[
        "refine",
        "meshes/mixed-quads.obj",
        "--scheme",
        "tps",
        "--levels",
        "2",
        "--param",
        "e=1/5",
        "-o",
        &out("mq.obj"),
    ]);
    ok(&["refine", "meshes/cube.obj", "--scheme", "doo-sabin", "--levels", "1", "-o", &out("ds.obj")]);
    ok(&["refine", &out("ds.obj"), "--scheme", "pgs", "--levels", "2", "-o", &out("pgs.obj")]);
    let err = fails(&["refine", "meshes/cube.obj", "--scheme", "pgs", "--levels", "1", "-o", &out("x.obj")]);
    assert!(err.contains("valence 4"), "{err}");
    let err = fails(&["refine", "meshes/octahedron.obj", "--scheme", "tps", "--levels", "1", "-o", &out("x.obj")]);
    assert!(err.contains("quad mesh"), "{err}");
    let err = fails(&["refine", "meshes/cube.obj", "--scheme", "polar-bi2", "--levels", "1", "-o", &out("x.obj")]);
    assert!(err.contains("polar net"), "{err}");
}

#[test]
fn bad_parameters_are_one_line_errors() {
    assert!(fails(&["spectrum", "tps", "--valence", "5", "--param", "e=0.6"]).contains("out of range"));
    assert!(fails(&["spectrum", "pgs", "--valence", "5", "--param", "nu=1"]).contains("no parameter"));
    assert!(fails(&["spectrum", "polar-bi2", "--valence", "2"]).contains("valence"));
}
