//! Curve schemes of Lin–Luo section 3. Every expected spectrum below is
//! derived by hand in the comments (symmetric/antisymmetric split of the
//! local matrix), never copied from program output.

use crate::common;
#[allow(unused_imports)]
use common::{fails, subdlab};

use num_bigint::BigInt;
use subdlab::curves::local::{curve_spectrum, CurveSpectrum};
use subdlab::curves::{refine_closed, CurveMask, CurveWeight};
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::numeric::Rational;
use subdlab::schemes::curves::{self, relation::four_point_by_relation3};

fn q(p: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(p), BigInt::from(d))
}

fn parse_q(s: &str) -> Rational {
    let (p, d) = s.split_once('/').unwrap_or((s, "1"));
    Rational::new(p.parse().unwrap(), d.parse().unwrap())
}

fn spectrum(name: &str, alpha: Option<&str>, kind: NeighbourhoodKind) -> CurveSpectrum {
    let params: Vec<(String, String)> = alpha.map(|a| vec![("alpha".to_string(), a.to_string())]).unwrap_or_default();
    curve_spectrum(curves::build(name, &params).unwrap().as_ref(), kind).unwrap()
}

/// Exact eigenvalues repeated by algebraic multiplicity, sorted; requires the
/// spectrum to have been proven exactly.
fn exact_multiset(s: &CurveSpectrum) -> Vec<Rational> {
    assert!(s.exact, "{}: spectrum not proven exactly", s.scheme);
    let mut v: Vec<Rational> = s
        .eigenvalues
        .iter()
        .flat_map(|e| std::iter::repeat_n(parse_q(e.exact.as_deref().unwrap()), e.algebraic_multiplicity))
        .collect();
    v.sort();
    v
}

fn sorted(mut v: Vec<Rational>) -> Vec<Rational> {
    v.sort();
    v
}

fn geometric(s: &CurveSpectrum, value: &Rational) -> usize {
    s.eigenvalues.iter().find(|e| parse_q(e.exact.as_deref().unwrap()) == *value).unwrap().geometric_multiplicity
}

fn mask<W: CurveWeight>(name: &str, alpha: Option<&str>) -> CurveMask<W> {
    let params: Vec<(String, String)> = alpha.map(|a| vec![("alpha".to_string(), a.to_string())]).unwrap_or_default();
    W::mask(curves::build(name, &params).unwrap().as_ref()).unwrap()
}

/// Cubic B-spline. Minimal window {−1,0,1} (the rules of points −1, 0, 1 only
/// reach old −1..1). Symmetric modes (c0, c1 = x±1): c0' = 3/4 c0 + 1/4 c1,
/// c1' = 1/2 c0 + 1/2 c1, eigenvalues 1 and 1/4; antisymmetric (d1):
/// d1' = 1/2 d1. So {1, 1/2, 1/4}.
/// Analysis window −2..2 (the cubic pieces on [−1,0] and [0,1] use P−2..P2):
/// symmetric c2' = 1/8 c0 + 3/4 c1 + 1/8 c2 adds 1/8 (triangular block);
/// antisymmetric d1' = 1/2 d1, d2' = 3/4 d1 + 1/8 d2 adds 1/8. So
/// {1, 1/2, 1/4, 1/8, 1/8}, 1/8 with two independent eigenvectors.
#[test]
fn cubic_bspline_spectra() {
    let m = spectrum("cubic-bspline", None, NeighbourhoodKind::Minimal);
    assert_eq!((m.matrix_size, m.minimal_size, m.analysis_size), (3, 3, 5));
    assert_eq!(m.window, vec![-1, 0, 1]);
    assert_eq!(exact_multiset(&m), sorted(vec![q(1, 1), q(1, 2), q(1, 4)]));
    let a = spectrum("cubic-bspline", None, NeighbourhoodKind::Analysis);
    assert_eq!(a.window, vec![-2, -1, 0, 1, 2]);
    assert_eq!(exact_multiset(&a), sorted(vec![q(1, 1), q(1, 2), q(1, 4), q(1, 8), q(1, 8)]));
    assert_eq!(geometric(&a, &q(1, 8)), 2);
    assert!(a.eigenvalues.iter().all(|e| !e.defective));
}

/// Four-point (w = 1/16): the even rule keeps P_i, the odd rule reaches
/// P_{i−1}..P_{i+2}. Minimal window: closure of {−1,0,1}: point 1 needs
/// old −1..2, point 2 (= old 1) adds nothing, so −2..2.
/// Symmetric modes (c0, c1, c2): c0' = c0, c1' = 9/16 c0 + (9/16 − 1/16) c1
/// − 1/16 c2, c2' = c1; besides 1 the block [[1/2, −1/16],[1, 0]] has
/// λ² − λ/2 + 1/16 = (λ − 1/4)², and [[1/4, −1/16],[1, −1/4]] has rank 1:
/// 1/4 is a double eigenvalue with a single eigenvector (a Jordan block).
/// Antisymmetric modes (d1, d2): d1' = (9/16 + 1/16) d1 − 1/16 d2, d2' = d1;
/// λ² − 5/8 λ + 1/16 = 0 gives 1/2 and 1/8.
/// Analysis window −3..3 (the four-point basis function has support [−3,3],
/// so P_i matters on (−1,1) iff |i| < 4): the extra points ±3 are odd points
/// whose own weight is −1/16, one symmetric and one antisymmetric mode:
/// −1/16 twice, semisimple.
#[test]
fn four_point_spectra_derived_by_hand() {
    let m = spectrum("four-point", None, NeighbourhoodKind::Minimal);
    assert_eq!(m.window, vec![-2, -1, 0, 1, 2]);
    assert_eq!(exact_multiset(&m), sorted(vec![q(1, 1), q(1, 2), q(1, 4), q(1, 4), q(1, 8)]));
    assert_eq!(geometric(&m, &q(1, 4)), 1, "1/4 is defective");
    let a = spectrum("four-point", None, NeighbourhoodKind::Analysis);
    assert_eq!(a.window, (-3..=3).collect::<Vec<i64>>());
    assert_eq!(exact_multiset(&a), sorted(vec![q(1, 1), q(1, 2), q(1, 4), q(1, 4), q(1, 8), q(-1, 16), q(-1, 16)]));
    assert_eq!(geometric(&a, &q(1, 4)), 1);
    assert_eq!(geometric(&a, &q(-1, 16)), 2);
    assert!(a.eigenvalues.iter().find(|e| e.exact.as_deref() == Some("1/4")).unwrap().defective);
}

/// Unified scheme, analysis window −3..3 for α ∉ {1} (α = 1 kills the outer
/// odd weights). Symmetric modes (c0..c3):
///   c0' = (4−α)/4 c0 + α/4 c1,
///   c1' = (9−α)/16 c0 + 1/2 c1 + (α−1)/16 c2,
///   c2' = α/8 c0 + (4−α)/4 c1 + α/8 c2,
///   c3' = ... + (α−1)/16 c3  → eigenvalue (α−1)/16.
/// The 3×3 block has rows summing to 1 (eigenvalue 1), trace 3/2 − α/8 and
/// determinant (2−α)/32, so the other two have sum (4−α)/8 and product
/// (2−α)/32: discriminant α²/64, roots 1/4 and (2−α)/8.
/// Antisymmetric (d1, d2, d3): [[(5−α)/8, (α−1)/16], [(4−α)/4, α/8]] has
/// trace 5/8 and determinant 1/16 for every α: roots 1/2 and 1/8; d3 gives
/// (α−1)/16 again. Minimal window −2..2 drops the two (α−1)/16.
#[test]
fn unified_scheme_spectrum_matches_the_closed_form_for_rational_alpha() {
    for (p, d) in [(0, 1), (1, 3), (1, 2), (7, 10), (3, 2), (2, 1), (5, 3), (123, 1000)] {
        let alpha = q(p, d);
        let text = format!("{p}/{d}");
        let a = spectrum("unified-curve", Some(&text), NeighbourhoodKind::Analysis);
        assert_eq!(a.window, (-3..=3).collect::<Vec<i64>>(), "alpha {text}");
        let two_minus = (q(2, 1) - alpha.clone()) / q(8, 1);
        let outer = (alpha.clone() - q(1, 1)) / q(16, 1);
        let want = vec![q(1, 1), q(1, 2), q(1, 4), two_minus.clone(), q(1, 8), outer.clone(), outer.clone()];
        assert_eq!(exact_multiset(&a), sorted(want), "alpha {text}");
        let m = spectrum("unified-curve", Some(&text), NeighbourhoodKind::Minimal);
        assert_eq!(m.window, vec![-2, -1, 0, 1, 2], "alpha {text}");
        assert_eq!(exact_multiset(&m), sorted(vec![q(1, 1), q(1, 2), q(1, 4), two_minus, q(1, 8)]), "alpha {text}");
    }
    // α = 1: zero outer weights are no dependency, so the windows are the B-spline's
    let one = spectrum("unified-curve", Some("1"), NeighbourhoodKind::Analysis);
    assert_eq!(one.window, vec![-2, -1, 0, 1, 2]);
    assert_eq!(exact_multiset(&one), sorted(vec![q(1, 1), q(1, 2), q(1, 4), q(1, 8), q(1, 8)]));
}

/// With the rules printed in section 3, α = 0 gives P_{2i} = P_i and the odd
/// weights −1/16, 9/16, 9/16, −1/16 (the four-point scheme); α = 1 gives
/// 1/8, 3/4, 1/8 and 0, 1/2, 1/2, 0 (the cubic B-spline). The opposite
/// assignment (α = 0 the B-spline), as section 5 uses for the surface scheme,
/// does not hold for the printed curve rules.
#[test]
fn alpha_zero_is_the_four_point_scheme_and_alpha_one_the_cubic_bspline() {
    let bspline: CurveMask<Rational> = mask("cubic-bspline", None);
    let four: CurveMask<Rational> = mask("four-point", None);
    assert_eq!(mask::<Rational>("unified-curve", Some("0")), four);
    assert_eq!(mask::<Rational>("unified-curve", Some("1")), bspline);
    assert_ne!(mask::<Rational>("unified-curve", Some("0")), bspline);
    assert_ne!(mask::<Rational>("unified-curve", Some("1")), four);
    // the float masks agree too (the weights are dyadic)
    assert_eq!(mask::<f64>("unified-curve", Some("1")), mask::<f64>("cubic-bspline", None));
}

/// The unified mask is the affine blend α·B-spline + (1−α)·four-point,
/// offset by offset, for every α (checked exactly at several rationals).
#[test]
fn unified_mask_is_the_blend_of_bspline_and_four_point() {
    let b: CurveMask<Rational> = mask("cubic-bspline", None);
    let f: CurveMask<Rational> = mask("four-point", None);
    let weight =
        |rule: &[(i64, Rational)], o: i64| rule.iter().find(|t| t.0 == o).map(|t| t.1.clone()).unwrap_or(q(0, 1));
    for (text, alpha) in [("1/3", q(1, 3)), ("2/7", q(2, 7)), ("3/2", q(3, 2)), ("0.45", q(9, 20)), ("2", q(2, 1))] {
        let u: CurveMask<Rational> = mask("unified-curve", Some(text));
        for o in -3..=3 {
            for (ur, br, fr) in [(&u.even, &b.even, &f.even), (&u.odd, &b.odd, &f.odd)] {
                let want = alpha.clone() * weight(br, o) + (q(1, 1) - alpha.clone()) * weight(fr, o);
                assert_eq!(weight(ur, o), want, "alpha {text} offset {o}");
            }
        }
    }
}

/// The Laurent-polynomial C¹ test (`curves::smoothness`), against symbols
/// factored by hand. Four-point: a(z) = (1 + z)^4 (−1 + 4z − z²)/16 (expand:
/// −1, 0, 9, 16, 9, 0, −1 over 16), so b = 2a/(1 + z)² = (−1, 2, 6, 2, −1)/8,
/// whose one-step norm max(1 + 6 + 1, 2 + 2)/8 = 1 is not below 1. Cubic
/// B-spline: b = (1, 2, 1)/4, norm 1/2. The blend at α = 1/2 (section 3's
/// rules): b = (1 + z)² ((z/8) + (−1 + 4z − z²)/16) = (−1, 4, 10, 4, −1)/16,
/// norm max(12, 8)/16 = 3/4.
#[test]
fn c1_by_laurent_polynomials() {
    use subdlab::curves::smoothness::{c1_test, power_norm, symbol};
    let four: CurveMask<Rational> = mask("four-point", None);
    assert_eq!(symbol(&four), [-1, 0, 9, 16, 9, 0, -1].iter().map(|&k| q(k, 16)).collect::<Vec<_>>());
    let b4: Vec<Rational> = [-1, 2, 6, 2, -1].iter().map(|&k| q(k, 8)).collect();
    assert_eq!(power_norm(&b4, 1), q(1, 1));
    let (steps, norms) = c1_test(&four, 8).unwrap();
    assert_eq!(norms[0], q(1, 1));
    assert!(steps.is_some_and(|l| l >= 2), "the four-point scheme is C¹, with more than one step");
    let (steps, norms) = c1_test(&mask("cubic-bspline", None), 8).unwrap();
    assert_eq!((steps, norms), (Some(1), vec![q(1, 2)]));
    let (steps, norms) = c1_test(&mask("unified-curve", Some("1/2")), 8).unwrap();
    assert_eq!((steps, norms), (Some(1), vec![q(3, 4)]));
    // a mask that does not reproduce linear functions is reported, not tested
    let skewed = CurveMask { even: vec![(0, q(1, 1))], odd: vec![(0, q(1, 4)), (1, q(3, 4))] };
    assert!(c1_test(&skewed, 4).is_err());
}

/// A small deterministic generator (64-bit LCG) for random rational data.
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> i64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 33) as i64
    }
    fn rational(&mut self) -> Rational {
        q(self.next() % 2001 - 1000, 1 + self.next() % 97)
    }
}

/// Relation (3): P^3_i = P^1_i − (Δ(P_i) + Δ(P_{i+1}))/2, checked exactly on
/// random closed polygons of rational numbers (one coordinate suffices: the
/// rules are linear and act per coordinate).
#[test]
fn relation_3_turns_a_bspline_step_into_a_four_point_step_exactly() {
    let four: CurveMask<Rational> = mask("four-point", None);
    let mut rng = Lcg(0x5eed);
    for n in 4..=12 {
        for _ in 0..5 {
            let pts: Vec<Rational> = (0..n).map(|_| rng.rational()).collect();
            let by_relation = four_point_by_relation3(&pts).unwrap();
            assert_eq!(by_relation, refine_closed(&four, &pts), "n = {n}");
        }
    }
    // and the relation is not vacuous: a B-spline step is not a four-point step
    let b: CurveMask<Rational> = mask("cubic-bspline", None);
    let pts: Vec<Rational> = (0..6).map(|_| rng.rational()).collect();
    assert_ne!(refine_closed(&b, &pts), refine_closed(&four, &pts));
}

#[test]
fn cli_curve_json_and_table() {
    let out = subdlab(&["curve", "unified-curve", "--param", "alpha=1/3", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["scheme"], "unified-curve");
    assert_eq!(v["params"]["alpha"], "1/3");
    assert_eq!(v["neighbourhood"], "analysis");
    assert_eq!(v["matrix_size"], 7);
    assert_eq!(v["minimal_size"], 5);
    assert_eq!(v["exact"], true);
    let eig = v["eigenvalues"].as_array().unwrap();
    // (2 − 1/3)/8 = 5/24 and (1/3 − 1)/16 = −1/24 (twice)
    assert!(eig.iter().any(|e| e["exact"] == "5/24" && e["algebraic_multiplicity"] == 1));
    assert!(eig.iter().any(|e| e["exact"] == "-1/24" && e["algebraic_multiplicity"] == 2));
    let moduli: Vec<f64> = eig.iter().map(|e| e["modulus"].as_f64().unwrap()).collect();
    assert!(moduli.windows(2).all(|w| w[0] >= w[1]), "sorted by modulus");
    let out = subdlab(&["curve", "four-point", "--neighbourhood", "minimal"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && text.contains("DEFECTIVE") && text.contains("(= 1/4)"), "{text}");
}

#[test]
fn cli_curve_errors_are_one_line() {
    assert!(fails(&["curve", "nope"]).contains("unknown curve scheme"));
    assert!(fails(&["curve", "unified-curve", "--param", "alpha=3"]).contains("out of range"));
    fails(&["curve", "unified-curve", "--param", "alpha=nan"]);
    fails(&["curve", "unified-curve", "--param", "alpha"]);
    fails(&["curve", "unified-curve", "--param", "beta=1"]);
    fails(&["curve", "cubic-bspline", "--param", "alpha=1"]);
    fails(&["curve", "four-point", "--neighbourhood", "huge"]);
    fails(&["curve"]);
}
