//! The `curvature` claim kind: every field, a true statement that HOLDS and a
//! false one that is REFUTED naming the disagreement.
//!
//! Expected values, derived independently of the code:
//! - Loop: λ = 3/8 + cos(2π/n)/4 (block 1); Loop's β makes the block-0
//!   eigenvalue 5/8 − nβ equal to λ² by construction; block 2 carries
//!   3/8 + cos(4π/n)/4. So μ = max(λ², block 2): n = 4: λ² = 9/64 > 1/8;
//!   n = 5: λ² = 0.2045 > 0.1727; n = 6: λ² = 1/4 = 3/8 − 1/8 (equal, blocks
//!   0, 2, 4); n = 7: block 2 = 0.3194 > λ² = 0.2819. Bounded for n = 4..6,
//!   unbounded from 7 on, F(μ) = {2, n − 2} there and {0, 2, 4} at n = 6.
//! - Catmull–Clark at n = 5: the block-2 eigenvalue 0.3401 exceeds
//!   λ² = 0.3025, so the class is unbounded and the C² test fails; at n = 4
//!   (bicubic B-splines) the λ²-eigenfunctions are x², xy, y² of the linear
//!   characteristic map: the C² test passes.
//! - 4-3 at an all-quad eon of valence 6: rule 4b makes block m ≥ 2 of the
//!   (v, e, f) ring [[1/4, 0], [(1 + ω)/4, 1/4]], a Jordan block for ω ≠ −1
//!   (m = 2, 4 at n = 6: two chains), and every weight is rational at n = 6,
//!   so the exact nullities of S − I/4 and its square differ by two.

use subdlab::claims::{evaluate, parse_file, Outcome, Verdict};

fn run(body: &str) -> Outcome {
    let text = format!("paper = \"t\"\ntitle = \"t\"\n\n[[claim]]\nid = \"c\"\nlocation = \"-\"\nstatement = \"-\"\ncheck = \"curvature\"\n{body}");
    let f = parse_file("t.toml", &text).unwrap();
    evaluate(&f).pop().unwrap()
}

fn holds(body: &str) -> Outcome {
    let o = run(body);
    assert_eq!(o.verdict, Verdict::Holds, "{body}: {} / {} / {}", o.stated, o.computed, o.detail);
    o
}

fn refuted(body: &str, needle: &str) -> Outcome {
    let o = run(body);
    assert_eq!(o.verdict, Verdict::Refuted, "{body}: {}", o.detail);
    assert!(o.detail.contains(needle), "{body}: '{needle}' not in {}", o.detail);
    o
}

#[test]
fn class_holds_and_is_refuted_with_stated_and_computed() {
    holds("scheme = \"loop\"\nvalences = \"4..6\"\nclass = \"bounded\"");
    holds("scheme = \"loop\"\nvalences = \"7..9\"\nclass = \"unbounded\"");
    // a list: any of them
    holds("scheme = \"loop\"\nvalences = \"4..9\"\nclass = [\"bounded\", \"unbounded\"]");
    let o = refuted(
        "scheme = \"loop\"\nvalences = \"4..8\"\nclass = \"bounded\"",
        "class: stated bounded, computed unbounded",
    );
    assert!(o.detail.starts_with("first disagreement at n = 7"), "{}", o.detail);
    assert!(o.computed.contains("n=7: class unbounded"), "{}", o.computed);
    refuted("scheme = \"loop\"\nvalences = [5]\nclass = \"zero\"", "stated zero, computed bounded");
}

#[test]
fn c2_holds_and_is_refuted() {
    holds("scheme = \"catmull-clark\"\nvalences = [4]\nclass = \"bounded\"\nc2 = true");
    holds("scheme = \"loop\"\nvalences = [6]\nclass = \"bounded\"\nc2 = true");
    holds("scheme = \"four-three\"\nfaces = [\"QQQQ\", \"TTTTTT\"]\nclass = \"bounded\"\nc2 = true");
    holds("scheme = \"catmull-clark\"\nvalences = [5]\nclass = \"unbounded\"\nc2 = false");
    refuted(
        "scheme = \"catmull-clark\"\nvalences = [5]\nclass = \"unbounded\"\nc2 = true",
        "C² test: stated passes, computed fails",
    );
    refuted(
        "scheme = \"catmull-clark\"\nvalences = [4]\nclass = \"bounded\"\nc2 = false",
        "C² test: stated fails, computed passes",
    );
}

#[test]
fn fourier_holds_and_is_refuted() {
    holds("scheme = \"loop\"\nvalences = [6]\nclass = \"bounded\"\nfourier = [0, 2, \"n - 2\"]");
    holds("scheme = \"loop\"\nvalences = \"7..9\"\nclass = \"unbounded\"\nfourier = [2, \"n - 2\"]");
    refuted(
        "scheme = \"loop\"\nvalences = [7]\nclass = \"unbounded\"\nfourier = [0, 2, \"n-2\"]",
        "F(μ): stated [0, 2, 5], computed [2, 5]",
    );
    refuted(
        "scheme = \"catmull-clark\"\nvalences = [5]\nclass = \"unbounded\"\nfourier = [0, 2, 3]",
        "computed [2, 3]",
    );
}

#[test]
fn a_jordan_block_names_both_routes_and_the_exact_nullities() {
    let o = holds("scheme = \"four-three\"\nvalences = [6]\nclass = \"unbounded\"");
    for needle in [
        "(a) floating-point multiplicities",
        "(b) growth test",
        "linear growth",
        "(c) exact",
        "nullity 7, its square 9",
    ] {
        assert!(o.detail.contains(needle), "'{needle}' not in {}", o.detail);
    }
    let o = refuted(
        "scheme = \"four-three\"\nvalences = [4, 5]\nclass = [\"zero\", \"bounded\"]",
        "stated zero or bounded, computed unbounded",
    );
    assert!(o.detail.contains("n = 5") && o.detail.contains("(b) growth test"), "{}", o.detail);
    // no Jordan block: the growth test agrees, and exactly at n = 4
    let o = holds("scheme = \"four-three\"\nvalences = [4]\nclass = \"bounded\"");
    assert!(o.detail.contains("bounded: no Jordan block") && o.detail.contains("no Jordan block)"), "{}", o.detail);
}

#[test]
fn malformed_curvature_claims_are_errors_or_inconclusive() {
    let o = run("scheme = \"loop\"\nvalences = [5]\nclass = \"flat\"");
    assert_eq!(o.verdict, Verdict::Error, "{}", o.detail);
    assert!(o.detail.contains("the classes are"), "{}", o.detail);
    let o = run("scheme = \"loop\"\nvalences = [5]\nclass = \"bounded\"\nfourrier = [0]");
    assert_eq!(o.verdict, Verdict::Error, "{}", o.detail);
    assert!(o.detail.contains("unknown key 'fourrier'"), "{}", o.detail);
    // F(μ) of a configuration without rotation symmetry is not computed
    let o = run("scheme = \"four-three\"\nfaces = [\"QQTTT\"]\nclass = \"bounded\"\nfourier = [0, 2, \"n-2\"]");
    assert_eq!(o.verdict, Verdict::Inconclusive, "{}", o.detail);
    assert!(o.detail.contains("rotation-symmetric"), "{}", o.detail);
}
