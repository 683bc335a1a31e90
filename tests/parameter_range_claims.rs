//! Claims of kind `parameter-range` (issue 27): a paper's statement about a
//! parameter range decided from the exact sets of `sweep --exact`. The
//! expected verdicts are derived here by hand, never read off the program:
//!
//! Huang's non-box scheme at valence k ≠ 4 has (section 4, and the true
//! blocks checked by nonbox.B0-/Bm-distinct-eigenvalues) block-0
//! eigenvalues 1, 3/4 − a, 1/4, 1/8, 1/8, 0, ... and block-m eigenvalues
//! 1/2 + cos(2πm/k)/4, 1/4, 1/8, 1/8, 0, .... So λ1 = 1/2 + cos(2π/k)/4
//! (m = 1, k − 1) and the scheme is spectrally C¹ exactly when
//! |3/4 − a| < 1/2 + cos(2π/k)/4. For a in [0, 1], |3/4 − a| ≤ 3/4 and
//! 3/4 − a < λ1 ⟺ a > 1/4 − cos(2π/k)/4, while a − 3/4 ≤ 1/4 < λ1 (λ1 ≥
//! 3/8 at k = 3). Hence the C¹ set in [0, 1] is (1/4 − cos(2π/k)/4, 1]: at
//! k = 3 it is (3/8, 1], at k = 5 ((5 − √5)/16, 1]. Convergence: every
//! eigenvalue but 1 has modulus < 1 for a in [0, 1], so the set is [0, 1].

use subdlab::claims::{evaluate, parse_file, Outcome, Verdict};

fn verdict_of(body: &str) -> Outcome {
    let text = format!(
        "paper = \"t\"\ntitle = \"t\"\n[[claim]]\nid = \"c\"\nlocation = \"here\"\nstatement = \"s\"\n{body}\n"
    );
    let mut o = evaluate(&parse_file("test.toml", &text).unwrap());
    assert_eq!(o.len(), 1);
    o.remove(0)
}

const NONBOX: &str = "check = \"parameter-range\"\nscheme = \"non-box\"\nvalences = [3, 5]\nparameter = \"a\"";

fn nonbox(rest: &str) -> Outcome {
    verdict_of(&format!("{NONBOX}\n{rest}"))
}

#[test]
fn huangs_sufficient_range_holds_and_a_wider_one_is_refuted() {
    // (1/4 − cos(2π/k)/4, 3/4] lies inside (1/4 − cos(2π/k)/4, 1]
    let o = nonbox("window = [\"0\", \"1\"]\nrange = \"(1/4 - cos(2 pi / k)/4, 3/4]\"\nasserts = \"inside\"");
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
    // negative control: closing the lower end adds a = 1/4 − cos(2π/k)/4,
    // where 3/4 − a = λ1 (a double subdominant modulus from blocks 0 and 1);
    // at k = 3 that end is the rational 3/8, a rational witness
    let o = nonbox("window = [\"0\", \"1\"]\nrange = \"[1/4 - cos(2 pi / k)/4, 3/4]\"\nasserts = \"inside\"");
    assert_eq!(o.verdict, Verdict::Refuted, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("second route"), "{}", o.computed);
    // negative control: extending it below the bound by 1/100 adds a failing
    // piece (3/4 − a > λ1 there)
    let o = nonbox("window = [\"0\", \"1\"]\nrange = \"(1/4 - cos(2 pi / k)/4 - 1/100, 3/4]\"\nasserts = \"inside\"");
    assert_eq!(o.verdict, Verdict::Refuted, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("disproves"), "{}", o.computed);
}

#[test]
fn the_exact_reading_depends_on_the_window_as_derived() {
    // in [0, 3/4] the C¹ set is (1/4 − cos(2π/k)/4, 3/4]: the bound is sharp
    let o = nonbox("window = [\"0\", \"3/4\"]\nrange = \"(1/4 - cos(2 pi / k)/4, 3/4]\"\nasserts = \"exactly\"");
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
    // in [0, 1] it is (…, 1]: (…, 3/4] is not all of it; the witness, a
    // point of (3/4, 1], is proved C¹ by the certificate
    let o = nonbox("window = [\"0\", \"1\"]\nrange = \"(1/4 - cos(2 pi / k)/4, 3/4]\"\nasserts = \"exactly\"");
    assert_eq!(o.verdict, Verdict::Refuted, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("proves"), "{}", o.computed);
    // a lower end off by 1/1000 is not the set's end; the disagreement
    // (lb, lb + 1/1000] holds none of the sweep's decided points, so the
    // witness is searched in the gap between the two ends and proved C¹
    // there by the certificate (it was INCONCLUSIVE before that search)
    let o =
        nonbox("window = [\"0\", \"3/4\"]\nrange = \"(1/4 - cos(2 pi / k)/4 + 1/1000, 3/4]\"\nasserts = \"exactly\"");
    assert_eq!(o.verdict, Verdict::Refuted, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("proves"), "{}", o.computed);
}

#[test]
fn convergence_ranges_are_read_from_the_convergent_set() {
    // the convergent set in [0, 1] is [0, 1]
    let o = nonbox("window = [\"0\", \"1\"]\nrange = \"[0, 3/4]\"\ncondition = \"convergent\"\nasserts = \"inside\"");
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
    let o = nonbox("range = \"[0, 1]\"\ncondition = \"convergent\"\nasserts = \"exactly\"");
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
}

#[test]
fn four_three_centre_weight_range_at_mixed_eons() {
    // Peters–Shiue, Lemma 3.5 / Theorem 3.7: the eon block has eigenvalues
    // 1, 1/2, 1/2, 1/4 (n − 3 times) and c − 1/2 (α_M = 1 − c), the rest of
    // the spectrum 1/4, 1/8, ...; |c − 1/2| ≤ 1/4 < 1/2 on [1/4, 3/4], so the
    // C¹ set in the scheme's range [1/4, 3/4] is all of it, closed
    let o = verdict_of(
        "check = \"parameter-range\"\nscheme = \"four-three\"\nfaces = [\"QQTQT\", \"QTQT\", \"QQQQQ\"]\n\
         parameter = \"centre_weight\"\nrange = \"[1/4, 3/4]\"\nasserts = \"exactly\"",
    );
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
}

#[test]
fn malformed_parameter_range_claims_are_errors() {
    let err = |rest: &str, needle: &str| {
        let o = nonbox(rest);
        assert_eq!(o.verdict, Verdict::Error, "{rest}: {} ({})", o.verdict, o.detail);
        assert!(o.detail.contains(needle), "{rest}: '{}' lacks '{needle}'", o.detail);
    };
    err("range = \"1/4, 3/4\"\nasserts = \"inside\"", "is not of the form");
    err("range = \"(0, 1]\"\nasserts = \"sometimes\"", "asserts");
    err("range = \"(0, 1]\"\nasserts = \"inside\"\ncondition = \"c2\"", "condition");
    err("range = \"(1/4 - cos(2 pi / k)/4, 3/4]\"\nasserts = \"inside\"", "not an exact rational");
    err("window = [\"0\", \"1/2\"]\nrange = \"(0, 3/4]\"\nasserts = \"inside\"", "outside the window");
    err("range = \"(0, 1]\"\nasserts = \"inside\"\nparams = { a = \"1/2\" }", "cannot also be fixed");
    err("window = [\"1\", \"0\"]\nrange = \"(0, 1]\"\nasserts = \"inside\"", "empty");
}

/// Whether the rational p/q is below (5 − √5)/16, the C¹ bound at k = 5
/// (exactly: 16t < 5 − √5 ⟺ 5 − 16t > 0 and (5 − 16t)² > 5).
fn below_bound_k5(p: i64, q: i64) -> bool {
    let d = 5 * q - 16 * p; // (5 − 16t)·q
    d > 0 && (d as i128) * (d as i128) > 5 * (q as i128) * (q as i128)
}

/// The rational witness "a = p/q" named in a REFUTED's computed text.
fn witness_of(computed: &str) -> (i64, i64) {
    let at = computed.split("confirmed at a = ").nth(1).unwrap_or_else(|| panic!("no witness: {computed}"));
    let w = at.split(':').next().unwrap();
    let (p, q) = w.split_once('/').unwrap_or((w, "1"));
    (p.trim().parse().unwrap(), q.trim().parse().unwrap())
}

/// A range that misses the sharp bound by 10⁻⁶ disagrees with the set only
/// on an interval of that width, where the sweep decides no point (its
/// pieces' points are the simplest rationals between candidates): the
/// witness is searched in the gap between the stated end and the computed
/// one and confirmed by the interval certificate. At k = 5 the set in
/// [0, 1] is ((5 − √5)/16, 1] (derivation at the top of this file).
#[test]
fn a_disagreement_on_a_tiny_gap_is_decided_by_a_witness_inside_it() {
    let one =
        "check = \"parameter-range\"\nscheme = \"non-box\"\nvalences = [5]\nparameter = \"a\"\nwindow = [\"0\", \"1\"]";
    // (bound − 10⁻⁶, 3/4]: (bound − 10⁻⁶, bound] is outside the set
    let o = verdict_of(&format!("{one}\nrange = \"(1/4 - cos(2 pi / k)/4 - 1/1000000, 3/4]\"\nasserts = \"inside\""));
    assert_eq!(o.verdict, Verdict::Refuted, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("disproves"), "{}", o.computed);
    let (p, q) = witness_of(&o.computed);
    // the witness lies in the gap: below or at the bound, above bound − 10⁻⁶
    assert!(below_bound_k5(p, q), "{p}/{q}");
    assert!(!below_bound_k5(p * 1_000_000 + q, q * 1_000_000), "{p}/{q} is not within 10⁻⁶ of the bound");
    // negative control: 10⁻⁶ above the bound the range is inside the set
    let o = verdict_of(&format!("{one}\nrange = \"[1/4 - cos(2 pi / k)/4 + 1/1000000, 3/4]\"\nasserts = \"inside\""));
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
    // "exactly" with the lower end 10⁻⁶ too high: the witness is a point of
    // (bound, bound + 10⁻⁶], proved C¹
    let o = verdict_of(&format!("{one}\nrange = \"(1/4 - cos(2 pi / k)/4 + 1/1000000, 1]\"\nasserts = \"exactly\""));
    assert_eq!(o.verdict, Verdict::Refuted, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("proves"), "{}", o.computed);
    let (p, q) = witness_of(&o.computed);
    assert!(!below_bound_k5(p, q), "{p}/{q}");
    assert!(below_bound_k5(p * 1_000_000 - q, q * 1_000_000), "{p}/{q} is not within 10⁻⁶ above the bound");
}
