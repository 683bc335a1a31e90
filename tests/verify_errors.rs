//! A CI path that cannot pass by accident (issue 24 §3): a claim that cannot
//! be read as written (a missing or misspelt scheme file, an unknown
//! parameter, a malformed or non-real value, an out-of-range option) is an
//! ERROR, and so is a claim that asserts nothing; no recorded `expected`
//! verdict lets either pass. Genuine "could not decide" stays INCONCLUSIVE.
//! Every command that prints a certified verdict exits 0 (proved), 1 (not
//! proved) or 2 (error), as `verify` does.

use crate::common;
use common::subdlab;
use subdlab::claims::{builtin_files, evaluate, parse_file, Outcome, Verdict};

/// The outcomes of a claim file given as text.
fn outcomes(text: &str) -> Vec<Outcome> {
    evaluate(&parse_file("test.toml", text).unwrap())
}

/// One claim (the TOML lines after `[[claim]]`, without id and statement).
fn claim(body: &str) -> String {
    format!("paper = \"t\"\ntitle = \"t\"\n[[claim]]\nid = \"c\"\nlocation = \"here\"\nstatement = \"s\"\n{body}\n")
}

fn verdict_of(body: &str) -> Outcome {
    let mut o = outcomes(&claim(body));
    assert_eq!(o.len(), 1);
    o.remove(0)
}

fn assert_error(body: &str, needle: &str) {
    let o = verdict_of(body);
    assert_eq!(o.verdict, Verdict::Error, "{body}: {} ({})", o.verdict, o.detail);
    assert!(o.detail.contains(needle), "{body}: '{}' lacks '{needle}'", o.detail);
}

/// Catmull–Clark's analysis neighbourhood at valence n is its two-ring:
/// the centre and, per sector, the (r + 1) × r lattice points i = 0..r,
/// j = 1..r of rings r ≤ 2, so 1 + n·2·3 = 6n + 1 vertices.
const CC_SIZE: &str = "check = \"size\"\nscheme = \"catmull-clark\"\nvalences = [3, 5]\nvalue = \"6 n + 1\"";

#[test]
fn the_controls_hold() {
    // the claims below are these, broken one way each: as written they hold
    assert_eq!(verdict_of(CC_SIZE).verdict, Verdict::Holds);
}

#[test]
fn a_missing_or_misspelt_scheme_or_an_unknown_parameter_is_an_error() {
    assert_error(&CC_SIZE.replace("\"catmull-clark\"", "\"catmul-clark\""), "catmul-clark");
    assert_error(&CC_SIZE.replace("\"catmull-clark\"", "\"/nonexistent/my-scheme.toml\""), "my-scheme.toml");
    assert_error(&format!("{CC_SIZE}\nparams = {{ no_such_parameter = \"1\" }}"), "no_such_parameter");
}

#[test]
fn an_error_fails_check_expected_whatever_the_file_records() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("c.toml");
    let text = claim(&format!("{}\nexpected = \"INCONCLUSIVE\"", CC_SIZE.replace("catmull-clark", "catmul-clark")));
    std::fs::write(&p, text).unwrap();
    let out = subdlab(&["verify", "--check-expected", "--claims", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    let out = subdlab(&["verify", "--claims", p.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(2));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v[0]["claims"][0]["verdict"], "ERROR");
}

#[test]
fn a_claim_that_asserts_nothing_is_an_error() {
    let cc = "scheme = \"catmull-clark\"\nvalences = [5]";
    for compare in ["all", "contains", "leading", "count"] {
        assert_error(
            &format!("check = \"eigenvalues\"\n{cc}\nvalues = []\ncompare = \"{compare}\""),
            "values is empty",
        );
    }
    assert_error("check = \"matrix-eigenvalues\"\nvalences = [3]\nrows = []\nvalues = []", "rows is empty");
    assert_error("check = \"matrix-eigenvalues\"\nvalences = [3]\nrows = [[\"1\"]]\nvalues = []", "values is empty");
    assert_error(&format!("check = \"limit-stencil\"\n{cc}\nweights = {{}}"), "weights is empty");
    assert_error(&format!("check = \"tangent-stencils\"\n{cc}\ncos = {{}}\nsin = {{}}"), "is empty");
    assert_error("check = \"identity\"\nlhs = \"n\"\nrhs = \"n\"\nvalences = []", "valences is empty");
    assert_error(
        &format!("check = \"invariant-set\"\n{cc}\nrings = \"2\"\nkinds = []\nvalue = \"31\""),
        "kinds is empty",
    );
    // no configuration at all
    assert_error("check = \"size\"\nscheme = \"catmull-clark\"\nvalue = \"6 n + 1\"", "asserts nothing");
}

#[test]
fn a_non_real_value_where_a_real_one_is_required_is_an_error() {
    // the real part alone would hold (6n + 1, see CC_SIZE)
    assert_error(&CC_SIZE.replace("\"6 n + 1\"", "\"6 n + 1 + 3 i\""), "not a real number");
    let cc = "scheme = \"catmull-clark\"\nvalences = [5]";
    // Catmull–Clark's limit position: centre n/(n + 5), per edge and face
    // neighbour 4/(n(n + 5)) and 1/(n(n + 5)); at n = 5 that is 1/2, 2/25, 1/50
    let stencil = "weights = { centre = \"1/2\", \"edge.1\" = \"2/25\", \"face.1\" = \"1/50\" }";
    assert_eq!(verdict_of(&format!("check = \"limit-stencil\"\n{cc}\n{stencil}")).verdict, Verdict::Holds);
    assert_error(&format!("check = \"limit-stencil\"\n{cc}\n{}", stencil.replace("1/50", "1/50 + i")), "not a real");
    // a repeat count and a block index
    assert_error(
        &format!("check = \"eigenvalues\"\n{cc}\nvalues = [\"1 ; 1 + i\"]\ncompare = \"contains\""),
        "not a real",
    );
    assert_error(
        &format!("check = \"eigenvalues\"\n{cc}\nvalues = [\"1\"]\ncompare = \"contains\"\nblock = \"1 + i\""),
        "not a real",
    );
    // rings of an invariant set, and a variable the stated values use
    assert_error(&format!("check = \"invariant-set\"\n{cc}\nrings = \"2 + i\"\nvalue = \"31\""), "not a real");
    // (x − x is 0 whatever x is: with the imaginary part of x dropped the
    // claim held; a variable is real, and a non-real one is an error where used)
    let with_x = CC_SIZE.replace("\"6 n + 1\"", "\"6 n + 1 + x - x\"");
    assert_error(&format!("{with_x}\nvars = {{ x = \"sqrt(-1)\" }}"), "is not a real number");
    assert_error(&format!("{with_x}\nvars = {{ x = \"2 y\", y = \"1 + i\" }}"), "is not a real number");
    assert_eq!(verdict_of(&format!("{with_x}\nvars = {{ x = \"sqrt(2)\" }}")).verdict, Verdict::Holds);
}

#[test]
fn certified_levels_share_the_command_lines_range_check() {
    for levels in [0, 1, 7] {
        let body = format!(
            "check = \"characteristic-map\"\nscheme = \"catmull-clark\"\nvalences = [5]\ncertified = true\nlevels = {levels}"
        );
        assert_error(&body, &format!("levels must be between 2 and 6, got {levels}"));
    }
    let body = "check = \"characteristic-map\"\nscheme = \"catmull-clark\"\nvalences = [5]\nlevels = 0";
    assert_error(body, "levels must be between 1 and");
    let err = common::fails(&["charmap", "catmull-clark", "-n", "5", "--certify", "--certify-levels", "0"]);
    assert!(err.contains("--certify-levels must be between 2 and 6, got 0"), "{err}");
}

/// An invariant set larger than the matrices analysed whole: its spectrum is
/// not computed, so the claim is not decided (it was REFUTED). Every vertex
/// of ring ≤ r of Catmull–Clark at valence n: 1 + n·r(r + 1) (see CC_SIZE);
/// n = 36, r = 6 gives 1513 > 1500 (an invariant set containing the
/// analysis neighbourhood, so nothing refutes it).
#[test]
fn an_invariant_set_too_large_to_analyse_is_inconclusive_with_the_reason() {
    let o = verdict_of(
        "check = \"invariant-set\"\nscheme = \"catmull-clark\"\nvalences = [36]\nrings = \"6\"\nvalue = \"1 + 36 * 6 * 7\"",
    );
    assert_eq!(o.verdict, Verdict::Inconclusive, "{}", o.detail);
    assert!(o.detail.contains("spectrum not computed") && o.detail.contains("1513"), "{}", o.detail);
}

#[test]
fn location_is_optional_in_a_users_file_and_present_in_the_registry() {
    let text = format!("paper = \"t\"\ntitle = \"t\"\n[[claim]]\nid = \"c\"\nstatement = \"s\"\n{CC_SIZE}\n");
    let o = outcomes(&text);
    assert_eq!(o[0].verdict, Verdict::Holds, "{}", o[0].detail);
    for f in builtin_files().unwrap() {
        for c in &f.claims {
            assert!(!c.location.trim().is_empty(), "{}: registry claim {} has no location", f.paper, c.id);
        }
    }
}

/// The exit status of a command printing a certified verdict: 0 proved,
/// 1 not proved (disproved or undecided), 2 error.
#[test]
fn certified_commands_exit_with_the_meaning_of_verify() {
    let code = |args: &[&str]| subdlab(args).status.code();
    // Catmull–Clark is C¹ at every valence (Reif; Peters–Reif)
    assert_eq!(code(&["spectrum", "catmull-clark", "-n", "5", "--certify"]), Some(0));
    assert_eq!(code(&["charmap", "catmull-clark", "-n", "7", "--certify"]), Some(0));
    // Lin–Luo's unified √3 at α = 1 has a complex subdominant pair at n = 3
    // (tests/registry_independent.rs derives it from the typed rules)
    let out = subdlab(&["spectrum", "unified-sqrt3", "-n", "3", "-p", "alpha=1", "--certify"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("DISPROVED"));
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(code(&["charmap", "unified-sqrt3", "-n", "3", "-p", "alpha=1", "--certify"]), Some(1));
    // an error is 2, as before
    assert_eq!(code(&["spectrum", "catmull-clark", "-n", "2", "--certify"]), Some(2));
    // and the exit statuses are in each command's help
    for cmd in ["verify", "spectrum", "charmap", "curvature", "sweep"] {
        let help = String::from_utf8_lossy(&subdlab(&[cmd, "--help"]).stdout).to_string();
        assert!(help.contains("Exit status: "), "{cmd} --help: {help}");
    }
}
