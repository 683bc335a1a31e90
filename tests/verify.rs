//! `subdlab verify`: the built-in registry's verdicts are regression-tested
//! against the verdicts each claim file records (each of them derived and
//! tested independently elsewhere: tests/non_box*.rs, khan_mustafa.rs,
//! lin_luo_statements.rs, curves.rs, four_three.rs, pgs.rs, tps.rs,
//! polar_bi2.rs, registry_independent.rs; the identity claims carry their
//! own derivation), and
//! users' own claim files drive the exit status.

use crate::common;
use common::{fails, subdlab};
use subdlab::claims::{builtin_files, evaluate, Verdict};

#[test]
fn builtin_verdicts_are_the_recorded_ones() {
    let files = builtin_files().unwrap();
    let mut papers: Vec<&str> = files.iter().map(|f| f.paper.as_str()).collect();
    papers.sort_unstable();
    // one claim file per source paper, and the classical theorems re-proved
    assert_eq!(
        papers,
        ["huang-nonbox", "karciauskas-peters", "khan-mustafa", "known-results", "lin-luo", "peters-shiue"],
        "the built-in registry's files"
    );
    for f in &files {
        for o in evaluate(f) {
            let expected = o.expected.unwrap_or_else(|| panic!("{} records no expected verdict", o.id));
            // an undecidable statement is registered INCONCLUSIVE with its reason
            if o.verdict == Verdict::Inconclusive {
                assert_eq!(expected, Verdict::Inconclusive, "{}: {}", o.id, o.detail);
            }
            assert_eq!(o.verdict, expected, "{}: stated {} / computed {} / {}", o.id, o.stated, o.computed, o.detail);
        }
    }
}

const USER_FILE: &str = r#"
paper = "my-scheme"
title = "Catmull–Clark facts my paper relies on"

[[claim]]
id = "cc.subdominant"
location = "Lemma 1"
statement = "λ1 = (5 + c + sqrt((c + 1)(c + 9)))/16, c = cos(2π/n)"
check = "subdominant"
scheme = "catmull-clark"
valences = "3..12"
vars = { c = "cos(2 pi / n)" }
value = "(5 + c + sqrt((c + 1) (c + 9)))/16"
"#;

#[test]
fn user_claims_pass_and_fail_with_the_exit_status() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.toml");
    std::fs::write(&good, USER_FILE).unwrap();
    let junit = dir.path().join("report.xml");
    let out = subdlab(&["verify", "--claims", good.to_str().unwrap(), "--junit", junit.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains("1 HOLDS"));
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("<testcase") && !xml.contains("<failure"));
    // the same claim with a wrong formula (the minus root) must fail the run
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, USER_FILE.replace("+ sqrt", "- sqrt")).unwrap();
    let err = fails(&["verify", "--claims", bad.to_str().unwrap(), "--junit", junit.to_str().unwrap()]);
    assert!(err.contains("1 claim(s) did not hold"), "{err}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("<failure message=\"REFUTED\""));
}

#[test]
fn malformed_claim_files_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    for (name, text, needle) in [
        ("syntax.toml", "paper = \"x\"\ntitle = \n", "TOML"),
        ("dup.toml", &format!("{USER_FILE}\n{}", &USER_FILE[USER_FILE.find("[[claim]]").unwrap()..]), "appears twice"),
    ] {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        let err = fails(&["verify", "--claims", p.to_str().unwrap()]);
        assert!(err.contains(needle), "{err}");
    }
    let err = fails(&["verify", "--paper", "nobody-2020"]);
    assert!(err.contains("built-in papers") && err.contains("huang-nonbox"), "{err}");
    fails(&["verify", "--claims", "/nonexistent/claims.toml"]);
}

#[test]
fn a_claim_naming_an_unknown_scheme_is_an_error_with_the_reason() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("x.toml");
    std::fs::write(&p, USER_FILE.replace("\"catmull-clark\"", "\"no-such-scheme\"")).unwrap();
    let out = subdlab(&["verify", "--claims", p.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(2));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v[0]["claims"][0]["verdict"], "ERROR");
    assert!(v[0]["claims"][0]["detail"].as_str().unwrap().contains("unknown scheme"));
}

#[test]
fn claim_values_may_use_bounded_sums() {
    // Σ_{m=0}^{5} cos(2π m/6) = 0 (the sixth roots of unity sum to 0), exactly;
    // Σ_{m=1}^{4} m² = 30, so 31 is refuted; a sum over the valence's Fourier
    // modes in an eigenvalue claim: Catmull–Clark's λ1 at n = 4 is 1/2 =
    // (1/n) Σ_m (1/2) (the mean of n equal terms)
    let text = r#"
paper = "sums"
title = "sums in claim values"

[[claim]]
id = "roots-of-unity"
location = "-"
statement = "the sixth roots of unity sum to 0"
check = "identity"
lhs = "sum(m, 0, 5, cos(2 pi m / 6))"
rhs = "0"

[[claim]]
id = "squares"
location = "-"
statement = "1 + 4 + 9 + 16 = 31"
check = "identity"
lhs = "sum(m, 1, 4, m^2)"
rhs = "31"

[[claim]]
id = "cc.lambda1"
location = "-"
statement = "λ1 = 1/2 at n = 4"
check = "subdominant"
scheme = "catmull-clark"
valences = "4..4"
value = "sum(t, 1, n, 1/2) / n"
"#;
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("sums.toml");
    std::fs::write(&p, text).unwrap();
    let out = subdlab(&["verify", "--claims", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let verdicts: Vec<(&str, &str)> = v[0]["claims"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| (c["id"].as_str().unwrap(), c["verdict"].as_str().unwrap()))
        .collect();
    assert_eq!(verdicts, [("roots-of-unity", "HOLDS"), ("squares", "REFUTED"), ("cc.lambda1", "HOLDS")], "{v}");
    assert!(v[0]["claims"][0]["detail"].as_str().unwrap().contains("exact"), "{v}");
}

/// A claim about rules built from the statement itself is marked, in the
/// table, the JSON (per claim and in the summary) and the JUnit report, so it
/// is never read as an independent confirmation; the registry marks the
/// three claims whose rules were built from the checked statement (TPS's
/// adjustable rules rebuilt from eq. (22), PGS's w1 set from eq. (9)).
#[test]
fn verdicts_by_construction_are_marked_everywhere() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("built.toml");
    let note = "the weights were chosen to give this λ1";
    std::fs::write(&p, USER_FILE.replace("value = ", &format!("by_construction = \"{note}\"\nvalue = "))).unwrap();
    let out = subdlab(&["verify", "--claims", p.to_str().unwrap(), "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v[0]["claims"][0]["verdict"], "HOLDS");
    assert_eq!(v[0]["claims"][0]["by_construction"], note);
    assert_eq!(v[0]["summary"]["by_construction"], 1);
    let text = String::from_utf8(subdlab(&["verify", "--claims", p.to_str().unwrap()]).stdout).unwrap();
    assert!(text.contains("HOLDS (by construction)") && text.contains(note), "{text}");
    assert!(text.contains("1 HOLDS, 0 REFUTED, 0 INCONCLUSIVE; 1 of them by construction"), "{text}");
    let junit = dir.path().join("j.xml");
    subdlab(&["verify", "--claims", p.to_str().unwrap(), "--junit", junit.to_str().unwrap()]);
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("HOLDS (by construction) as recorded") && xml.contains(note), "{xml}");
    // without the note: a plain HOLDS, no summary field
    let plain = dir.path().join("plain.toml");
    std::fs::write(&plain, USER_FILE).unwrap();
    let v: serde_json::Value =
        serde_json::from_slice(&subdlab(&["verify", "--claims", plain.to_str().unwrap(), "--json"]).stdout).unwrap();
    assert!(v[0]["claims"][0]["by_construction"].is_null() && v[0]["summary"].get("by_construction").is_none());
    // the registry's marked claims
    let mut marked: Vec<String> = builtin_files()
        .unwrap()
        .iter()
        .flat_map(|f| f.claims.iter().filter(|c| c.by_construction.is_some()).map(|c| c.id.clone()))
        .collect();
    marked.sort();
    assert_eq!(marked, ["pgs.subdominant", "tps.adjustable-c1", "tps.adjustable-subdominant"]);
}

/// Two face sequences of one length are two configurations: a claim about
/// eons of quads only must fail at TTT even though QQQ (listed first) passes
/// (an earlier version checked only the first sequence of each length).
#[test]
fn face_sequences_of_one_length_are_each_checked() {
    let text = r#"
paper = "configurations"
title = "every face sequence is a configuration"

[[claim]]
id = "all-quads"
location = "-"
statement = "every face around the eon is a quad"
check = "inequality"
scheme = "four-three"
faces = ["QQQ", "TTT", "QQQQQ"]
lhs = "quads"
op = ">="
rhs = "n"
"#;
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("configurations.toml");
    std::fs::write(&path, text).unwrap();
    let out = subdlab(&["verify", "--claims", path.to_str().unwrap(), "--json"]);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let claim = &doc[0]["claims"][0];
    assert_eq!(claim["verdict"], "REFUTED", "{claim}");
    let detail = claim["detail"].as_str().unwrap();
    assert!(detail.contains("n = 3 (TTT)") && detail.contains("3 checked"), "{detail}");
    // the quads-only sequences alone hold
    std::fs::write(&path, text.replace("\"TTT\", ", "")).unwrap();
    let out = subdlab(&["verify", "--claims", path.to_str().unwrap(), "--json"]);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc[0]["claims"][0]["verdict"], "HOLDS", "{}", doc[0]["claims"][0]);
}

/// Per-claim timings: `--json` gives each claim's wall-clock `seconds`, and
/// `--slowest K` lists K claims, slowest first, after the table. The claim
/// ids listed must be the file's own and the times must be those the JSON
/// orders (non-increasing), so the summary cannot invent or reorder claims.
#[test]
fn per_claim_timings_and_the_slowest_claims() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/claims/eigenvalues.toml");
    let out = subdlab(&["verify", "--claims", file, "--json"]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let claims = json[0]["claims"].as_array().unwrap();
    let ids: Vec<&str> = claims.iter().map(|c| c["id"].as_str().unwrap()).collect();
    assert_eq!(ids.len(), 3);
    for c in claims {
        let s = c["seconds"].as_f64().unwrap();
        assert!(s.is_finite() && s >= 0.0, "{c}");
    }
    let out = subdlab(&["verify", "--claims", file, "--slowest", "2"]);
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let tail = &text[text.find("slowest 2 of 3 claims").expect(&text)..];
    let rows: Vec<(f64, &str)> = tail
        .lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            (f[0].parse().unwrap(), *f.last().unwrap())
        })
        .collect();
    assert_eq!(rows.len(), 2, "{tail}");
    assert!(rows.iter().all(|(_, id)| ids.contains(id)), "{tail}");
    assert!(rows[0].0 >= rows[1].0, "slowest first: {tail}");
}
