//! The command line as a user runs it: output formats and one-line errors.

use crate::common;
#[allow(unused_imports)]
use common::{fails, subdlab};

fn json(args: &[&str]) -> serde_json::Value {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

#[test]
fn spectrum_json_carries_the_stable_fields() {
    let v = json(&["spectrum", "catmull-clark", "--valence", "5", "--json"]);
    assert_eq!(v["scheme"], "catmull-clark");
    assert_eq!(v["valence"], 5);
    assert!(v["params"].is_object());
    assert_eq!(v["matrix_size"], 31);
    let blocks = v["blocks"].as_array().unwrap();
    assert_eq!(blocks.len(), 5);
    assert!(blocks.iter().all(|b| b["index"].is_u64() && b["size"].is_u64()));
    let eig = v["eigenvalues"].as_array().unwrap();
    for e in eig {
        for f in ["re", "im", "modulus", "algebraic_multiplicity", "geometric_multiplicity", "block"] {
            assert!(!e[f].is_null(), "field {f}");
        }
        assert!(e.get("exact").is_some());
    }
    let moduli: Vec<f64> = eig.iter().map(|e| e["modulus"].as_f64().unwrap()).collect();
    assert!(moduli.windows(2).all(|w| w[0] >= w[1]), "sorted by modulus");
    let c = (2.0 * std::f64::consts::PI / 5.0).cos();
    let l1 = (5.0 + c + ((c + 1.0) * (c + 9.0)).sqrt()) / 16.0;
    assert!((eig[1]["re"].as_f64().unwrap() - l1).abs() < 1e-10);
    assert_eq!(eig[1]["algebraic_multiplicity"], 2);
    assert_eq!(eig[0]["exact"], "1");
    assert_eq!(v["verdict"]["c1_spectral"], true);
    assert!(!v["verdict"]["reasons"].as_array().unwrap().is_empty());
}

#[test]
fn readable_table_names_the_subdominant_eigenvalue() {
    let out = subdlab(&["spectrum", "catmull-clark", "--valence", "4"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    assert!(text.contains("0.5 (= 1/2)"), "{text}");
    assert!(text.contains("PASSES"));
}

#[test]
fn minimal_neighbourhood_option() {
    let v = json(&["spectrum", "loop", "-n", "7", "--neighbourhood", "minimal", "--json"]);
    assert_eq!(v["matrix_size"], 8);
    assert_eq!(v["neighbourhood"], "minimal");
}

#[test]
fn stencils_json_limit_sums_to_one() {
    let v = json(&["stencils", "doo-sabin", "-n", "6", "--json"]);
    let sum: f64 = v["limit"].as_array().unwrap().iter().map(|w| w["weight"].as_f64().unwrap()).sum();
    assert!((sum - 1.0).abs() < 1e-12);
    assert_eq!(v["tangent"].as_array().unwrap().len(), 2);
}

#[test]
fn matrix_market_export_is_well_formed() {
    let out = subdlab(&["matrix", "catmull-clark", "--valence", "3", "--format", "mtx"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("%%MatrixMarket matrix coordinate real general"));
    let mut lines = text.lines().filter(|l| !l.starts_with('%'));
    let header: Vec<usize> = lines.next().unwrap().split_whitespace().map(|x| x.parse().unwrap()).collect();
    assert_eq!(&header[..2], &[19, 19]);
    let mut row_sum = [0.0; 19];
    let mut count = 0;
    for l in lines {
        let p: Vec<&str> = l.split_whitespace().collect();
        let i: usize = p[0].parse().unwrap();
        row_sum[i - 1] += p[2].parse::<f64>().unwrap();
        count += 1;
    }
    assert_eq!(count, header[2]);
    assert!(row_sum.iter().all(|s| (s - 1.0).abs() < 1e-14), "affine invariance: rows sum to 1");
}

#[test]
fn matrix_json_has_exact_entries_and_file_output_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cc4.json");
    let out = subdlab(&[
        "matrix",
        "catmull-clark",
        "-n",
        "4",
        "--neighbourhood",
        "minimal",
        "--format",
        "json",
        "-o",
        path.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    assert_eq!(v["size"], 9);
    // the centre row of Catmull–Clark at n = 4: (n-7/4)/n = 9/16 on the centre
    assert_eq!(v["labels"][0], "centre");
    assert_eq!(v["exact"][0][0], "9/16");
}

#[test]
fn schemes_lists_the_baseline_schemes() {
    let out = subdlab(&["schemes"]);
    let text = String::from_utf8_lossy(&out.stdout);
    // every built-in name of the registry (all three families) starts a line
    for s in subdlab::schemes::registry::known_names() {
        assert!(text.lines().any(|l| l.split_whitespace().next() == Some(s)), "{s} not listed:\n{text}");
    }
}

#[test]
fn unknown_scheme_lists_the_known_ones() {
    let err = fails(&["spectrum", "butterfly", "--valence", "5"]);
    assert!(err.contains("unknown scheme 'butterfly'") && err.contains("catmull-clark"), "{err}");
}

#[test]
fn valence_below_three_is_rejected() {
    let err = fails(&["spectrum", "catmull-clark", "--valence", "2"]);
    assert!(err.contains("below 3"), "{err}");
}

#[test]
fn valence_above_the_cap_is_rejected() {
    // the cap is the estimated memory (tests/limits.rs); absurd numbers are
    // refused outright
    let err = fails(&["spectrum", "loop", "--valence", "1000000000"]);
    assert!(err.contains("above the supported maximum"), "{err}");
}

#[test]
fn non_numeric_valence_is_rejected() {
    fails(&["spectrum", "loop", "--valence", "five"]);
    fails(&["spectrum", "loop", "--valence", "-4"]);
}

#[test]
fn unknown_and_malformed_parameters_are_rejected() {
    let err = fails(&["spectrum", "doo-sabin", "-n", "5", "--param", "a=1/2"]);
    assert!(err.contains("no parameters"), "{err}");
    let err = fails(&["spectrum", "catmull-clark", "-n", "5", "--param", "a=1/2"]);
    assert!(err.contains("no parameter 'a'; its parameters: blz"), "{err}");
    let err = fails(&["spectrum", "catmull-clark", "-n", "5", "--param", "a"]);
    assert!(err.contains("NAME=VALUE"), "{err}");
}

#[test]
fn bad_options_are_rejected() {
    let err = fails(&["spectrum", "catmull-clark", "-n", "5", "--neighbourhood", "huge"]);
    assert!(err.contains("minimal or analysis"), "{err}");
    let err = fails(&["matrix", "catmull-clark", "-n", "5", "--format", "csv"]);
    assert!(err.contains("mtx or json"), "{err}");
    let err = fails(&["spectrum", "catmull-clark", "-n", "5", "--method", "qr"]);
    assert!(err.contains("dft or full"), "{err}");
    fails(&["frobnicate"]);
    fails(&["spectrum"]);
}

#[test]
fn unwritable_output_is_an_error_not_a_panic() {
    let err = fails(&["matrix", "loop", "-n", "5", "-o", "/nonexistent-dir/x.mtx"]);
    assert!(err.contains("cannot"), "{err}");
}

#[test]
fn schemes_describes_scheme_files() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("w.toml");
    std::fs::write(
        &file,
        "name = \"loop-w\"\ndescription = \"Loop with a free edge weight\"\ntopology = \"primal-triangle\"\n\
         [params.w]\ndefault = \"3/8\"\nmin = 0\nmax = 0.5\ndescription = \"edge end weight\"\n\
         [vertex]\ncentre = \"5/8\"\nedge = \"3/(8 n)\"\n[edge]\nends = \"w\"\nopposite = \"1/2 - w\"\n",
    )
    .unwrap();
    let out = subdlab(&["schemes", file.to_str().unwrap(), "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v[0]["name"], "loop-w");
    assert_eq!(v[0]["file"], file.to_str().unwrap());
    assert_eq!(v[0]["params"][0]["name"], "w");
    assert_eq!(v[0]["params"][0]["default"], "3/8");
    assert_eq!(v[0]["params"][0]["max"], 0.5);
    fails(&["schemes", "no-such-file.toml"]);
}

/// `spectrum --certify` on a regular-lattice scheme proves the window's
/// spectrum exactly (lemma S7: the masks are rational). Khan–Mustafa's
/// scheme reproduces the linear functions x and y, which the dilation halves:
/// λ1 = 1/2, double, with a two-dimensional eigenspace, and 1 simple (the
/// constants). The negative control is the piecewise-constant scheme (every
/// parity copies p_{i,j}): the four points of {-1, 0}² are their own
/// parents, so 1 is an eigenvalue four times and the conditions are
/// DISPROVED, with exit status 1.
#[test]
fn lattice_spectrum_certify_proves_exactly_and_disproves_the_control() {
    let out = subdlab(&["spectrum", "khan-mustafa", "-n", "4", "--certify", "--json"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let c = &v["certificate"];
    assert_eq!(c["verdict"], "proved", "{c}");
    let e = &c["exact_route"];
    assert_eq!((e["one_multiplicity"].as_u64(), e["lambda1"].as_str()), (Some(1), Some("1/2")), "{e}");
    assert_eq!((e["algebraic"].as_u64(), e["geometric"].as_u64()), (Some(2), Some(2)), "{e}");

    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("constant.toml");
    let masks: String =
        ["00", "10", "01", "11"].iter().map(|p| format!("[mask-{p}]\n\"0,0\" = 1\n")).collect::<Vec<_>>().concat();
    std::fs::write(&file, format!("domain = \"lattice\"\nname = \"piecewise-constant\"\n{masks}")).unwrap();
    let out = subdlab(&["spectrum", file.to_str().unwrap(), "-n", "4", "--certify"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.contains("certified spectral C1 conditions: DISPROVED"), "{text}");
    assert!(text.contains("1 of multiplicity 4"), "{text}");
    // the certificate document describes mesh configurations: refused in one line
    let e = fails(&["spectrum", "khan-mustafa", "-n", "4", "--certify", "--certificate", "x.json"]);
    assert!(e.contains("lattice scheme"), "{e}");
}

/// A curve's λ1 is simple, so the surface statement `--certify` proves does
/// not apply: a one-line refusal naming the domain.
#[test]
fn curve_spectrum_certify_is_refused_naming_the_domain() {
    let e = fails(&["spectrum", "four-point", "-n", "2", "--certify"]);
    assert!(e.contains("curve scheme") && e.contains("the line Z") && e.contains("λ1 is simple"), "{e}");
}
