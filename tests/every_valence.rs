//! `spectrum --certify --valences`: spectral C¹ at every valence (issue 27).
//! Expected values come from the literature and hand derivations, never
//! from the program: Catmull–Clark and Loop are spectrally C¹ at every
//! n ≥ 3 (Doo–Sabin 1978, Ball–Storry 1988 for Catmull–Clark; Loop 1987,
//! Schweitzer 1996 for Loop); the defect file's first bad valence 40 is
//! derived in its comments. Doo–Sabin (face-centred) is spectrally C¹ at
//! every n ≥ 3 (Doo–Sabin 1978: eigenvalues 1, 1/2, 1/2, 1/4, ..., 1/8,
//! 1/16); its block-2 variant's first bad valence 45 is derived in
//! `tests/data/doo-sabin-block2-dominant.toml`.

use crate::common::subdlab;
use num_rational::BigRational;
use subdlab::certify::Verdict;
use subdlab::every_valence::centre::Variable;
use subdlab::every_valence::{block_polynomial, composite_block0_polynomial, run, Parametric, Report, Request};

fn request(scheme: &str, from: usize, to: Option<usize>) -> Request {
    Request { scheme: scheme.into(), params: Vec::new(), from, to }
}

fn q(p: i64, d: i64) -> BigRational {
    BigRational::new(p.into(), d.into())
}

/// P(x, c) at a rational c: coefficients lowest first.
fn poly_at(scheme: &str, c: &BigRational) -> Vec<BigRational> {
    let p = block_polynomial(&request(scheme, 3, None)).expect("P(x, c) computed");
    p.iter().map(|t| t.eval(c).to_rational().expect("rational")).collect()
}

/// A report PROVED for every n ≥ 3: the per-valence part exactly 3..N−1,
/// every certificate PROVED unconditionally, and the parametric part PROVED
/// (returned).
fn proved_from_three(r: &Report) -> &Parametric {
    assert_eq!(r.verdict, Verdict::Proved, "{r:?}");
    let n = r.threshold.expect("a threshold N");
    assert_eq!(r.per_valence.iter().map(|a| a.valence).collect::<Vec<_>>(), (3..n).collect::<Vec<_>>());
    assert!(r.per_valence.iter().all(|a| a.verdict == Verdict::Proved && !a.conditional));
    let p = r.parametric.as_ref().unwrap();
    assert_eq!(p.verdict, Verdict::Proved);
    p
}

/// p(x) at a rational x.
fn eval(p: &[BigRational], x: &BigRational) -> BigRational {
    p.iter().rev().fold(q(0, 1), |acc, a| acc * x + a)
}

#[test]
fn catmull_clark_file_is_spectrally_c1_at_every_valence() {
    let r = run(&request("schemes/catmull-clark.toml", 3, None)).unwrap();
    let p = proved_from_three(&r);
    assert!(p.block0.is_some() && p.blocks.is_some());
    assert!(r.scope.contains("spectral conditions only"));
}

#[test]
fn loop_file_is_spectrally_c1_at_every_valence() {
    let r = run(&request("schemes/loop.toml", 3, None)).unwrap();
    assert_eq!(r.verdict, Verdict::Proved, "{r:?}");
    assert!(r.threshold.is_some());
    // an open range starting above the threshold needs no per-valence part
    let r = run(&request("schemes/loop.toml", 100, None)).unwrap();
    assert_eq!(r.verdict, Verdict::Proved);
    assert!(r.per_valence.is_empty());
}

/// p(x + b): coefficients lowest first (repeated synthetic division).
fn shifted(p: &[BigRational], b: &BigRational) -> Vec<BigRational> {
    let mut a = p.to_vec();
    let n = a.len();
    for i in 0..n {
        for j in (i..n - 1).rev() {
            let t = &a[j + 1] * b;
            a[j] = &a[j] + t;
        }
    }
    a
}

/// Descartes' rule of signs: p has no root in (0, ∞) when its nonzero
/// coefficients never change sign; with p(0) > 0 and all coefficients
/// ≥ 0, p > 0 on [0, ∞).
fn positive_on_half_line(p: &[BigRational]) -> bool {
    p[0] > q(0, 1) && p.iter().all(|x| *x >= q(0, 1))
}

/// p divided by x − r (r a root of p).
fn deflate(p: &[BigRational], r: &BigRational) -> Vec<BigRational> {
    let d = p.len() - 1;
    let mut out = vec![q(0, 1); d];
    let mut carry = q(0, 1);
    for k in (1..=d).rev() {
        carry = &p[k] + &carry * r;
        out[k - 1] = carry.clone();
    }
    out
}

/// Second route: the top root of Catmull–Clark's block polynomial is the
/// closed form of the subdominant eigenvalue (Doo–Sabin 1978; Ball–Storry):
/// μ(c) = (5 + c + sqrt((c + 9)(c + 1)))/16, a root of the quadratic
/// Q = 256 x² − 32 (5 + c) x + (5 + c)² − (c + 9)(c + 1). Q divides P(x, c)
/// exactly, and the quotient R has no root at or above b = (5 + c + s)/16 for
/// a rational s ≤ sqrt((c+9)(c+1)) (so b ≤ μ): R(x + b) has positive
/// coefficients (Descartes). So μ is P's largest root, and simple.
#[test]
fn catmull_clark_top_root_is_the_closed_form() {
    for c in [q(-9, 10), q(-1, 3), q(0, 1), q(1, 2), q(7, 9), q(1, 1)] {
        let p = poly_at("schemes/catmull-clark.toml", &c);
        let s = q(5, 1) + &c;
        let disc = (&c + q(9, 1)) * (&c + q(1, 1));
        let quad = vec![&s * &s - &disc, q(-32, 1) * &s, q(256, 1)];
        let (quotient, rem) = divide(&p, &quad);
        assert!(rem.iter().all(|x| *x == q(0, 1)), "c = {c}: the quadratic divides P");
        // s_hi ≥ sqrt(disc) by Newton from above; s_lo = disc/s_hi ≤ sqrt(disc)
        let mut s_hi = &disc + q(1, 1);
        for _ in 0..8 {
            s_hi = (&s_hi + &disc / &s_hi) / q(2, 1);
        }
        let b = (&s + &disc / &s_hi) / q(16, 1);
        assert!(positive_on_half_line(&shifted(&quotient, &b)), "c = {c}: a root of P besides μ reaches μ");
        // the quadratic's other root (5 + c − sqrt)/16 is below b: Q(x + b)
        // has one sign change only (μ), checked by its value at b < 0 ... Q(b) < 0
        assert!(eval(&quad, &b) < q(0, 1), "c = {c}: b lies between the quadratic's roots");
    }
}

/// p = quotient · d + remainder.
fn divide(p: &[BigRational], d: &[BigRational]) -> (Vec<BigRational>, Vec<BigRational>) {
    let mut r = p.to_vec();
    let lead = d.last().unwrap().clone();
    let mut quotient = vec![q(0, 1); p.len() + 1 - d.len()];
    while r.len() >= d.len() {
        let f = r.last().unwrap().clone() / &lead;
        let shift = r.len() - d.len();
        quotient[shift] = f.clone();
        for (i, x) in d.iter().enumerate() {
            r[shift + i] = &r[shift + i] - &f * x;
        }
        r.pop();
    }
    (quotient, r)
}

/// Second route for Loop: λ1 = 3/8 + cos(2π/n)/4 (Loop 1987), i.e. x = 3/8 +
/// c/4 is a root of P(x, c), and the rest of P, P/(x − μ), is positive on
/// [μ, ∞) (Descartes on its shift by μ): μ is the largest root, simple.
#[test]
fn loop_top_root_is_three_eighths_plus_cos_over_four() {
    for c in [q(-1, 2), q(0, 1), q(1, 3), q(9, 10), q(1, 1)] {
        let p = poly_at("schemes/loop.toml", &c);
        let mu = q(3, 8) + &c / q(4, 1);
        assert_eq!(eval(&p, &mu), q(0, 1), "c = {c}");
        assert!(positive_on_half_line(&shifted(&deflate(&p, &mu), &mu)), "c = {c}");
    }
}

/// The defect file (tests/data/loop-large-valence-defect.toml): block 0's
/// eigenvalue 5/8 − K/n² dominates λ1 exactly from n = 40 on (derived in
/// the file). The parametric part must not prove it; the scan finds 40.
#[test]
fn large_valence_defect_is_disproved_at_forty() {
    let file = "tests/data/loop-large-valence-defect.toml";
    let r = run(&request(file, 3, None)).unwrap();
    match &r.verdict {
        Verdict::Disproved(why) => assert!(why.contains("n = 40"), "{why}"),
        v => panic!("expected DISPROVED at 40, got {v:?}"),
    }
    let last = r.per_valence.last().unwrap();
    assert_eq!(last.valence, 40);
    assert!(r.per_valence[..r.per_valence.len() - 1].iter().all(|a| a.verdict == Verdict::Proved));
    assert!(matches!(r.parametric.as_ref().unwrap().verdict, Verdict::NotProved(_)));
    // finite ranges: proved below 40, disproved across it
    assert_eq!(run(&request(file, 36, Some(39))).unwrap().verdict, Verdict::Proved);
    let r = run(&request(file, 38, Some(45))).unwrap();
    assert!(matches!(&r.verdict, Verdict::Disproved(w) if w.contains("n = 40")), "{:?}", r.verdict);
}

/// A scheme whose rows away from the centre read an expression in n and j
/// at the centre's valence (an extraordinary edge rule): the parametric part
/// must refuse, and the scan finds the failure (bad at every valence).
#[test]
fn an_edge_rule_in_n_is_not_taken_as_independent_of_n() {
    let r = run(&request("schemes/loop-block2-dominant.toml", 3, None)).unwrap();
    let p = r.parametric.as_ref().unwrap();
    match &p.verdict {
        Verdict::NotProved(why) => assert!(why.contains("edge-extraordinary"), "{why}"),
        v => panic!("the parametric part must not prove it: {v:?}"),
    }
    assert!(matches!(r.verdict, Verdict::Disproved(_)), "{:?}", r.verdict);
}

/// Built-in rules are compiled code: no all-valence proof, and the output
/// says why (the per-valence certificates still run up to the scan limit).
#[test]
fn built_ins_are_not_proved_beyond_their_certificates() {
    let r = run(&request("loop", 3, None)).unwrap();
    match &r.verdict {
        Verdict::NotProved(why) => assert!(why.contains("compiled code"), "{why}"),
        v => panic!("{v:?}"),
    }
}

#[test]
fn cli_exit_codes_and_json() {
    let ok = subdlab(&["spectrum", "schemes/loop.toml", "--certify", "--valences", "3.."]);
    assert_eq!(ok.status.code(), Some(0));
    let text = String::from_utf8_lossy(&ok.stdout);
    assert!(text.contains("PROVED") && text.contains("spectral conditions only"), "{text}");
    // a parameter by the shared flag (blz weighs only crease rules: the
    // interior proof is the same)
    let with_param = subdlab(&["spectrum", "schemes/loop.toml", "--certify", "--valences", "3..", "-p", "blz=0"]);
    assert_eq!(with_param.status.code(), Some(0), "{}", String::from_utf8_lossy(&with_param.stderr));
    let bad =
        subdlab(&["spectrum", "tests/data/loop-large-valence-defect.toml", "--certify", "--valences", "3..", "--json"]);
    assert_eq!(bad.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&bad.stdout).unwrap();
    assert_eq!(v["verdict"], "disproved");
    assert!(v["reason"].as_str().unwrap().contains("n = 40"));
    assert!(v["parametric"]["evidence"].as_str().unwrap().contains("exact"));
    assert_eq!(v["per_valence"].as_array().unwrap().len(), 38);
    for args in [
        vec!["spectrum", "loop", "--certify", "--valences", "2.."],
        vec!["spectrum", "loop", "--certify", "--valences", "five"],
        vec!["spectrum", "loop", "--certify", "--valences", "9..4"],
        vec!["spectrum", "loop", "--valences", "3..5"],
        vec!["spectrum", "no-such-scheme", "--certify", "--valences", "3.."],
        // 100 000 certificates: refused up front (it ran for minutes before)
        vec!["spectrum", "loop", "--certify", "--valences", "3..100000"],
        // just past the limit Σ n ≤ Σ_{3..200} n: 3..201
        vec!["spectrum", "loop", "--certify", "--valences", "3..201"],
        // the shared configuration flags are taken, and refused where a
        // range of valences gives them no meaning
        vec!["spectrum", "four-three", "--certify", "--valences", "3..5", "--faces", "QQT"],
        vec!["spectrum", "loop", "--certify", "--valences", "3..5", "--tag", "boundary"],
        vec!["spectrum", "loop", "--certify", "--valences", "3..5", "-p", "no_such=1"],
    ] {
        let out = subdlab(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("error: ") && !err.contains("panicked"), "{err}");
    }
}

/// Doo–Sabin's centre face: α_j = δ_j/4 + (3 + 2 cos(2πj/n))/(4n). By hand,
/// with Σ_j ω^{jk} = n[k ≡ 0] and Σ_j cos(2πj/n) ω^{jk} = (n/2)([k ≡ 1] +
/// [k ≡ −1]) (ω = e^{2πi/n}):
///   σ(k) = Σ_j α_j ω^{jk} = 1/4 + (3/4)[k ≡ 0] + (1/4)([k ≡ 1] + [k ≡ −1]),
/// i.e. σ(0) = 1, σ(±1) = 1/2, σ(k) = 1/4 for 2 ≤ k ≤ n − 2: generic value
/// 1/4, corrections e_0 = 3/4 and e_1 = 1/4, frequency M = 1. (The new
/// vertices of the n-gon are 1/4 of their corner plus the centroid's 3/4
/// and a first harmonic of weight 1/2: the classical 1, 1/2, 1/4.)
#[test]
fn doo_sabin_centre_symbol_is_the_closed_form() {
    use subdlab::every_valence::symbol::trig_in_j;
    use subdlab::numeric::expr::{Env, Expr};
    let e = Expr::parse("kronecker(j)/4 + (3 + 2 cos(2 pi j / n)) / (4 n)").unwrap();
    let sym = trig_in_j(&e, &Env::new()).unwrap();
    assert_eq!(sym.degree(), 1);
    for n in [3i64, 4, 7, 24, 101] {
        for k in 0..n {
            let expected = if k == 0 {
                q(1, 1)
            } else if k == 1 || k == n - 1 {
                q(1, 2)
            } else {
                q(1, 4)
            };
            let got = sym.symbol_at(n, k).unwrap().to_rational().unwrap();
            assert_eq!(got, expected, "n = {n}, k = {k}");
        }
    }
    // products of cosines expand (cos² a = (1 + cos 2a)/2): frequency 2, and
    // σ(k) of cos²(2πj/n) is n/2 at k = 0 and n/4 at k = ±2 (n ≥ 5)
    let e = Expr::parse("cos(2 pi j / n)^2").unwrap();
    let sym = trig_in_j(&e, &Env::new()).unwrap();
    assert_eq!(sym.degree(), 2);
    let at = |k| sym.symbol_at(9, k).unwrap().to_rational().unwrap();
    assert_eq!((at(0), at(1), at(2), at(7), at(3)), (q(9, 2), q(0, 1), q(9, 4), q(9, 4), q(0, 1)));
    // what is not a cosine polynomial in j is refused, not guessed
    for bad in ["sin(2 pi j / n) / n", "cos(2 pi j^2 / n) / n", "j / n", "cos(2 pi j / n + 1) / n", "kronecker(j - 1)"]
    {
        assert!(trig_in_j(&Expr::parse(bad).unwrap(), &Env::new()).is_err(), "{bad}");
    }
}

/// Expands Π (x − r) (coefficients lowest first).
fn from_roots(roots: &[BigRational]) -> Vec<BigRational> {
    let mut p = vec![q(1, 1)];
    for r in roots {
        let mut next = vec![q(0, 1); p.len() + 1];
        for (i, a) in p.iter().enumerate() {
            next[i + 1] = &next[i + 1] + a;
            next[i] = &next[i] - a * r;
        }
        p = next;
    }
    p
}

/// The generic blocks of Doo–Sabin (2 ≤ k ≤ n − 2): the centre face's
/// symbol 1/4 and the rest, whose eigenvalues are those of the regular
/// tensor-product quadratic B-spline's products 1/4, 1/8, 1/16 (Doo–Sabin
/// 1978: the spectrum 1, 1/2, 1/2, 1/4, ..., 1/8, ..., 1/16, ...): P(x, c) =
/// (x − 1/4)²(x − 1/8)(x − 1/16), independent of c.
#[test]
fn doo_sabin_generic_blocks_are_the_classical_eigenvalues() {
    let expected = from_roots(&[q(1, 4), q(1, 4), q(1, 8), q(1, 16)]);
    for c in [q(-1, 1), q(0, 1), q(1, 3), q(1, 1)] {
        assert_eq!(poly_at("schemes/doo-sabin.toml", &c), expected, "c = {c}");
    }
}

#[test]
fn doo_sabin_file_is_spectrally_c1_at_every_valence() {
    let r = run(&request("schemes/doo-sabin.toml", 3, None)).unwrap();
    let p = proved_from_three(&r);
    let f = p.special.as_ref().expect("the face-centred part");
    // M = 1 (σ has frequencies 0 and 1 only), λ1 = σ(±1) = 1/2 exactly
    assert_eq!(f.frequencies, 1);
    assert!(f.lambda1.ends_with("∈ 1/2"), "{}", f.lambda1);
    // the built-in's compiled rules stay NOT PROVED (as Catmull–Clark's, Loop's)
    let r = run(&request("doo-sabin", 3, None)).unwrap();
    assert!(matches!(&r.verdict, Verdict::NotProved(w) if w.contains("compiled code")), "{:?}", r.verdict);
}

/// The negative control: Doo–Sabin with a second harmonic 2bc·cos(4πj/n)/(4n)
/// in the centre face's rule, b = 101/100, c = cos(2π/n): block 2's centre
/// eigenvalue 1/4 + bc/4 exceeds λ1 = 1/2 exactly when cos(2π/n) > 100/101,
/// first at n = 45 (derived in the file). The parametric part must not prove
/// it (block 2 reaches λ1 as n → ∞); the scan proves 3..44 and disproves 45.
#[test]
fn doo_sabin_block2_variant_is_disproved_at_forty_five() {
    let file = "tests/data/doo-sabin-block2-dominant.toml";
    let r = run(&request(file, 3, None)).unwrap();
    match &r.verdict {
        Verdict::Disproved(why) => assert!(why.contains("n = 45"), "{why}"),
        v => panic!("expected DISPROVED at 45, got {v:?}"),
    }
    assert_eq!(r.per_valence.last().unwrap().valence, 45);
    assert!(r.per_valence[..r.per_valence.len() - 1].iter().all(|a| a.verdict == Verdict::Proved && !a.conditional));
    match &r.parametric.as_ref().unwrap().verdict {
        Verdict::NotProved(why) => assert!(why.starts_with("block 2:"), "{why}"),
        v => panic!("the parametric part must not prove it: {v:?}"),
    }
    assert_eq!(run(&request(file, 40, Some(44))).unwrap().verdict, Verdict::Proved);
}

// √3 (Kobbelt 2000), a composite scheme: S is two refinement steps. The
// closed forms below are derived by hand in tests/data/sqrt3-large-valence-
// defect.toml: blocks k ≠ 0 never see the centre, so λ1 = |1 + ω|²/9 =
// (2 + 2c)/9, c = cos(2π/n); block 0 keeps the centre and its ring's average
// together, one step acting there as [[1 − a, a], [1/3, 2/3]] (eigenvalues
// 1 and 2/3 − a), so two steps give (2/3 − a)², with Kobbelt's
// a = (4 − 2c)/9 exactly λ1².

fn sqrt3_lambda1(c: &BigRational) -> BigRational {
    (q(2, 1) + q(2, 1) * c) / q(9, 1)
}

#[test]
fn sqrt3_file_is_spectrally_c1_at_every_valence() {
    let r = run(&request("schemes/sqrt3.toml", 3, None)).unwrap();
    let p = proved_from_three(&r);
    assert!(p.rows.contains("2 refinement steps"), "{}", p.rows);
    let b0 = p.block0.as_ref().expect("block 0 decided");
    assert_eq!(b0.variable, Variable::Cosine);
}

/// λ1 = (2 + 2c)/9 is a root of P(x, c) and its largest (the rest of P,
/// P/(x − λ1), positive on [λ1, ∞) by Descartes on its shift).
#[test]
fn sqrt3_top_root_is_two_plus_two_cos_over_nine() {
    for c in [q(-1, 2), q(0, 1), q(1, 3), q(9, 10), q(1, 1)] {
        let p = poly_at("schemes/sqrt3.toml", &c);
        let mu = sqrt3_lambda1(&c);
        assert_eq!(eval(&p, &mu), q(0, 1), "c = {c}");
        assert!(positive_on_half_line(&shifted(&deflate(&p, &mu), &mu)), "c = {c}");
    }
}

/// Block 0 without λ0 = 1 has the root (2/3 − a)² in c: λ1² for √3,
/// ((16 + 16c)/45)² for the defect file (a = (14 − 16c)/45).
#[test]
fn sqrt3_block0_has_the_centre_ring_eigenvalue() {
    let gamma_sqrt3 = |c: &BigRational| sqrt3_lambda1(c);
    let gamma_defect = |c: &BigRational| (q(16, 1) + q(16, 1) * c) / q(45, 1);
    let cases: [(&str, &dyn Fn(&BigRational) -> BigRational); 2] =
        [("schemes/sqrt3.toml", &gamma_sqrt3), ("tests/data/sqrt3-large-valence-defect.toml", &gamma_defect)];
    for (file, gamma) in cases {
        let (variable, qp) = composite_block0_polynomial(&request(file, 3, None)).expect("block 0 of a composite");
        assert_eq!(variable, Variable::Cosine);
        for c in [q(-1, 2), q(0, 1), q(1, 3), q(9, 10), q(1, 1)] {
            let at_c: Vec<BigRational> = qp.iter().map(|t| t.eval(&c).to_rational().expect("rational")).collect();
            let g = gamma(&c);
            assert_eq!(eval(&at_c, &(&g * &g)), q(0, 1), "{file}, c = {c}");
        }
    }
}

/// The defect file: γ² > λ1 exactly when c > 97/128, first at n = 9 (derived
/// in the file). Checked here without the program: cos(2π/8)² = 1/2 <
/// (97/128)², and cos(2π/9) ≥ T(x) for x = 2(355/113)/9 ≥ 2π/9 (cos
/// decreasing on [0, π/2]) with T the Taylor polynomial 1 − x²/2 + x⁴/24 −
/// x⁶/720 ≤ cos x there (the remainder cos ξ · x⁸/8! ≥ 0). The parametric
/// part must not prove it; the scan finds 9.
#[test]
fn sqrt3_large_valence_defect_is_disproved_at_nine() {
    let threshold = q(97, 128);
    assert!(q(1, 2) < &threshold * &threshold);
    let x = q(2 * 355, 113 * 9);
    let x2 = &x * &x;
    let taylor = q(1, 1) - &x2 / q(2, 1) + &x2 * &x2 / q(24, 1) - &x2 * &x2 * &x2 / q(720, 1);
    assert!(taylor > threshold);

    let file = "tests/data/sqrt3-large-valence-defect.toml";
    let r = run(&request(file, 3, None)).unwrap();
    match &r.verdict {
        Verdict::Disproved(why) => assert!(why.contains("n = 9"), "{why}"),
        v => panic!("expected DISPROVED at 9, got {v:?}"),
    }
    assert_eq!(r.per_valence.last().unwrap().valence, 9);
    assert!(r.per_valence[..r.per_valence.len() - 1].iter().all(|a| a.verdict == Verdict::Proved));
    assert!(matches!(r.parametric.as_ref().unwrap().verdict, Verdict::NotProved(_)));
    assert_eq!(run(&request(file, 3, Some(8))).unwrap().verdict, Verdict::Proved);
}

/// The built-in √3 is compiled code: refused as before.
#[test]
fn sqrt3_built_in_is_not_proved_beyond_its_certificates() {
    let r = run(&request("sqrt3", 3, None)).unwrap();
    match &r.verdict {
        Verdict::NotProved(why) => assert!(why.contains("compiled code"), "{why}"),
        v => panic!("{v:?}"),
    }
}
