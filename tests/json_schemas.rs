//! The JSON and CSV outputs every command documents as stable (README:
//! "JSON (stable API)", the charmap, curvature, curve, sweep and verify
//! sections): each documented field is present with the documented kind of
//! value. A renamed field, a changed type or a dropped column fails here, so
//! users' scripts and notebooks do not break silently.
//!
//! Kinds: `s` string, `i` integer, `f` number, `b` boolean, `a` array, `o`
//! object; a trailing `?` allows null (fields the README says may be null:
//! numbers of a map that does not exist, an exact value not proven, ...).

use crate::common;
use common::subdlab;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{args:?}: not JSON: {e}"))
}

fn kind_ok(v: &Value, kind: &str) -> bool {
    let (kind, nullable) = kind.strip_suffix('?').map_or((kind, false), |k| (k, true));
    if v.is_null() {
        return nullable;
    }
    match kind {
        "s" => v.is_string(),
        "i" => v.is_u64() || v.is_i64(),
        "f" => v.is_number(),
        "b" => v.is_boolean(),
        "a" => v.is_array(),
        "o" => v.is_object(),
        _ => panic!("unknown kind {kind}"),
    }
}

fn check(what: &str, v: &Value, fields: &[(&str, &str)]) {
    let obj = v.as_object().unwrap_or_else(|| panic!("{what}: not an object: {v}"));
    for (name, kind) in fields {
        let x = obj.get(*name).unwrap_or_else(|| panic!("{what}: field '{name}' missing ({:?})", obj.keys()));
        assert!(kind_ok(x, kind), "{what}.{name}: expected kind {kind}, got {x}");
    }
}

/// An eigenvalue entry of `spectrum` and `curve` (one per distinct value).
const EIGENVALUE: &[(&str, &str)] = &[
    ("re", "f"),
    ("im", "f"),
    ("modulus", "f"),
    ("algebraic_multiplicity", "i"),
    ("geometric_multiplicity", "i"),
    ("defective", "b"),
    ("exact", "s?"),
    ("recognised", "s?"),
];

/// Every JSON output carries the tool version and a schema version.
const VERSIONED: &[(&str, &str)] = &[("subdlab_version", "s"), ("schema_version", "i")];

#[test]
fn spectrum_json() {
    let v = json(&["spectrum", "loop", "-n", "5", "--json"]);
    check("spectrum", &v, VERSIONED);
    check(
        "spectrum",
        &v,
        &[
            ("scheme", "s"),
            ("valence", "i"),
            ("params", "o"),
            ("faces", "s"),
            ("centre", "s"),
            ("neighbourhood", "s"),
            ("matrix_size", "i"),
            ("minimal_size", "i"),
            ("analysis_size", "i"),
            ("method", "s"),
            ("blocks", "a"),
            ("eigenvalues", "a"),
            ("verdict", "o"),
            ("exact_analysis", "o?"),
        ],
    );
    check("spectrum.blocks[0]", &v["blocks"][0], &[("index", "i"), ("size", "i")]);
    for e in v["eigenvalues"].as_array().unwrap() {
        check("spectrum.eigenvalues[]", e, EIGENVALUE);
        check("spectrum.eigenvalues[]", e, &[("block", "i"), ("blocks", "a")]);
    }
    check(
        "spectrum.verdict",
        &v["verdict"],
        &[
            ("c1_spectral", "b"),
            ("convergent", "b"),
            ("reasons", "a"),
            ("failures", "a"),
            ("subdominant", "f?"),
            ("subdominant_blocks", "a"),
            ("sub_subdominant", "f?"),
            ("lambda3_over_lambda1_squared", "f?"),
        ],
    );
    // with the exact path (Loop at n = 6 is rational)
    let v = json(&["spectrum", "loop", "-n", "6", "--json"]);
    check(
        "spectrum.exact_analysis",
        &v["exact_analysis"],
        &[
            ("method", "s"),
            ("polynomial_degree", "i"),
            ("rational_roots", "a"),
            ("remaining_degree", "i"),
            ("agrees_with_float", "b"),
        ],
    );
}

#[test]
fn stencils_json() {
    let v = json(&["stencils", "loop", "-n", "5", "--json"]);
    check("stencils", &v, VERSIONED);
    check(
        "stencils",
        &v,
        &[("scheme", "s"), ("valence", "i"), ("faces", "s"), ("neighbourhood", "s"), ("limit", "a"), ("tangent", "a")],
    );
    check("stencils.limit[0]", &v["limit"][0], &[("vertex", "s"), ("weight", "f"), ("recognised", "s?")]);
}

#[test]
fn charmap_json() {
    let fields = [
        ("scheme", "s"),
        ("valence", "i"),
        ("params", "o"),
        ("lambda1", "f?"),
        ("subdominant_blocks", "a"),
        ("spectral_status", "s"),
        ("explanation", "s"),
        ("c1_spectral", "b"),
        ("levels", "i"),
        ("refinements", "i?"),
        ("resolution", "i"),
        ("regular", "b"),
        ("injective", "b"),
        ("winding_number", "i?"),
        ("inner_winding_number", "i?"),
        ("overlap_pixels", "i?"),
        ("copy_overlap_pixels", "i?"),
        ("ring_pixels", "i?"),
        ("min_jacobian_ratio", "f?"),
        ("min_jacobian_at", "a?"),
        ("folded_facets", "i?"),
        ("ring_facets", "i?"),
        ("ring_area", "f?"),
        ("inner_area", "f?"),
        ("reasons", "a"),
    ];
    let v = json(&["charmap", "catmull-clark", "-n", "5", "--json"]);
    check("charmap", &v, VERSIONED);
    check("charmap", &v, &fields);
    assert_eq!(v["spectral_status"], "ok");
    // a scheme whose subdominant eigenvalue is complex: no map, numbers null
    let v = json(&["charmap", "unified-sqrt3", "-n", "3", "--param", "alpha=1", "--json"]);
    check("charmap (no map)", &v, &fields);
    assert_eq!(v["spectral_status"], "not-real-positive");
    assert!(v["winding_number"].is_null() && v["ring_area"].is_null());
    // --certify: the same fields and the certificate
    let v = json(&["charmap", "loop", "-n", "5", "--certify", "--json"]);
    check("charmap --certify", &v, VERSIONED);
    check("charmap --certify", &v, &fields);
    let c = &v["certificate"];
    check(
        "charmap.certificate",
        c,
        &[
            ("scheme", "s"),
            ("valence", "i"),
            ("spectrum", "o"),
            ("regularity", "o"),
            ("injectivity", "o"),
            ("c1", "o"),
            ("conditional", "b"),
            ("geometry_conditional", "b"),
            ("regular_part", "s?"),
            ("rules_checked", "i"),
            ("levels", "i?"),
            ("ring_faces", "i"),
            ("positive_faces", "i"),
            ("negative_faces", "i"),
            ("undecided_faces", "i"),
            ("min_jacobian_lower_bound", "f?"),
            ("min_jacobian_ratio", "f?"),
            ("eigenvector_radius", "f?"),
            ("max_point_width", "f?"),
            ("winding_number", "i?"),
            ("fold_witness", "o?"),
            ("reasons", "a"),
        ],
    );
    for part in ["regularity", "injectivity", "c1"] {
        check(&format!("charmap.certificate.{part}"), &c[part], &[("verdict", "s")]);
    }
}

#[test]
fn curvature_json() {
    let v = json(&["curvature", "loop", "-n", "7", "--json"]);
    check("curvature", &v, VERSIONED);
    check(
        "curvature",
        &v,
        &[
            ("scheme", "s"),
            ("valence", "i"),
            ("params", "o"),
            ("faces", "s"),
            ("class", "s"),
            ("evidence", "s"),
            ("tolerance", "f"),
            ("c1_spectral", "b"),
            ("charmap_injective", "b?"),
            ("lambda", "f?"),
            ("lambda_squared", "f?"),
            ("mu", "o?"),
            ("examined", "a"),
            ("mu_over_lambda_squared", "f?"),
            ("lp_limit", "f?"),
            ("curvature_converges", "b?"),
            ("shapes", "o?"),
            ("c2", "o?"),
            ("levels", "i"),
            ("ring_vertices", "i"),
            ("reasons", "a"),
        ],
    );
    assert!(["zero", "bounded", "unbounded", "not-applicable"].contains(&v["class"].as_str().unwrap()));
    assert!(["exact", "floating-point", "none"].contains(&v["evidence"].as_str().unwrap()));
    check(
        "curvature.examined[0]",
        &v["examined"][0],
        &[
            ("re", "f"),
            ("im", "f"),
            ("modulus", "f"),
            ("over_lambda_squared", "f"),
            ("algebraic_multiplicity", "i"),
            ("geometric_multiplicity", "i"),
            ("defective", "b"),
            ("blocks", "a"),
            ("ring_blocks", "a"),
            ("exact", "s?"),
            ("ring_size", "f"),
            ("vanishes", "b"),
            ("jordan_visible", "b?"),
        ],
    );
    check(
        "curvature.shapes",
        &v["shapes"],
        &[
            ("fourier_index", "a"),
            ("group_order", "i"),
            ("necessary_condition", "b"),
            ("elliptic_possible", "b"),
            ("saddle_possible", "b"),
            ("explanation", "s"),
        ],
    );
    check(
        "curvature.c2",
        &v["c2"],
        &[
            ("holds", "b"),
            ("quadratic", "b"),
            ("spans_quadratics", "b"),
            ("tolerance", "f"),
            ("max_residual", "f?"),
            ("fits", "a"),
            ("reasons", "a"),
        ],
    );
}

#[test]
fn curve_json() {
    let v = json(&["curve", "four-point", "--json"]);
    check("curve", &v, VERSIONED);
    check(
        "curve",
        &v,
        &[
            ("scheme", "s"),
            ("params", "o"),
            ("neighbourhood", "s"),
            ("matrix_size", "i"),
            ("minimal_size", "i"),
            ("analysis_size", "i"),
            ("window", "a"),
            ("matrix", "a"),
            ("exact_matrix", "a?"),
            ("charpoly", "s?"),
            ("exact", "b"),
            ("eigenvalues", "a"),
        ],
    );
    check("curve.eigenvalues[0]", &v["eigenvalues"][0], EIGENVALUE);
}

#[test]
fn sweep_json_and_csv() {
    let v = json(&["sweep", "loop", "--valences", "3..4", "--json"]);
    check("sweep", &v, VERSIONED);
    check("sweep", &v, &[("scheme", "s"), ("points", "a"), ("convergent", "a"), ("admissible", "a")]);
    for p in v["points"].as_array().unwrap() {
        check(
            "sweep.points[]",
            p,
            &[
                ("valence", "i"),
                ("lambda", "a"),
                ("convergent", "b"),
                ("c1_spectral", "b"),
                ("charmap", "b?"),
                ("error", "s?"),
                ("curvature_class", "s?"),
                ("lp_limit", "f?"),
                ("failing", "a"),
            ],
        );
    }
    let out = subdlab(&["sweep", "loop", "--valences", "3..4", "--csv"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    // valence, the swept parameter (empty name when none), λ moduli, then the verdicts
    assert_eq!(header[0], "valence");
    let tail = &header[header.len() - 8..];
    assert_eq!(
        tail,
        ["convergent", "c1_spectral", "charmap", "error", "curvature_class", "lp_limit", "verdict", "failing"]
    );
    assert!(header.iter().filter(|h| h.starts_with("lambda")).count() >= 2);
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 2, "one row per point");
    assert!(rows.iter().all(|r| r.split(',').count() == header.len()));
}

#[test]
fn verify_json() {
    let v = json(&["verify", "--paper", "khan-mustafa", "--check-expected", "--json"]);
    let papers = v.as_array().expect("a list of papers");
    for p in papers {
        check("verify[]", p, &[("paper", "s"), ("title", "s"), ("summary", "o"), ("claims", "a")]);
        check("verify[].summary", &p["summary"], &[("holds", "i"), ("refuted", "i"), ("inconclusive", "i")]);
        for c in p["claims"].as_array().unwrap() {
            check(
                "verify[].claims[]",
                c,
                &[
                    ("id", "s"),
                    ("paper", "s"),
                    ("location", "s"),
                    ("statement", "s"),
                    ("convention", "s?"),
                    ("verdict", "s"),
                    ("expected", "s?"),
                    ("by_construction", "s?"),
                    ("stated", "s"),
                    ("computed", "s"),
                    ("detail", "s"),
                    ("seconds", "f"),
                ],
            );
            assert!(["HOLDS", "REFUTED", "INCONCLUSIVE", "ERROR"].contains(&c["verdict"].as_str().unwrap()));
        }
    }
}
