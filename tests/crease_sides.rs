//! The per-side verdict at a crease vertex (`spectrum::crease_sides`,
//! `certify::tagged`'s crease part, `scripts/check_cert.py`'s sides).
//!
//! Expected values, derived by hand (not read off the program):
//!
//! - With crease rules that read only the curve on the curve, the rows of
//!   side A's points read only side A's and the curve's points, so S in the
//!   order (curve C, A only, B only) is block lower triangular and
//!   det(x − S)·det(x − S_CC) = det(x − S_AA)·det(x − S_BB), checked here
//!   exactly over Q (the same identity without the curve's factor must
//!   fail: the curve's eigenvalues would be missing once).
//! - Side A of `crease:K` holds the points of sectors 0..K−1 and of the two
//!   sharp rays: a fan of K faces with a boundary curve, i.e. the boundary
//!   fan of K faces (`--tag boundary -n K`), so the two characteristic
//!   polynomials are equal.
//! - The regular side (Catmull–Clark K = 2, Loop K = 3): the boundary
//!   curve's cubic B-spline eigenvalues 1, 1/2, 1/4; the interior sine mode
//!   m = 1 of the boundary fan (tests/tagged_verdicts.rs) with Hoppe's
//!   γ = 3/8: Catmull–Clark μ(φ) = (t + √(t² − 1/4))/2, t = 5/8 + cos φ/8,
//!   at φ = π/2: t = 5/8, √(25/64 − 16/64) = 3/8, μ = 1/2, and its partner
//!   (t − 3/8)/2 = 1/8; Loop 3/8 + cos(π/3)/4 = 1/2. So each side has
//!   λ1 = λ2 = 1/2 exactly twice (tangent and mode 1, one odd, one even), the
//!   rest smaller: each side PASSES, while S whole has 1/2 three times.
//! - A side of K = 4 Catmull–Clark faces is the boundary fan k = 4, whose
//!   mode m = 2 reaches the curve's 1/2 (γ = 3/8 = 3/8 − cos(2π/4)/4) and
//!   shares the odd block with the tangent: a Jordan block. That side fails,
//!   and the crease with it, naming that side.

use crate::common;
use common::{check_certificate, check_tampered_certificate, checker_can_run, write_spectrum_certificate};
use subdlab::certify::tagged::{certify_tagged, TaggedCertificate};
use subdlab::certify::Verdict;
use subdlab::neighbourhood::{Configuration, Tagging};
use subdlab::numeric::exact::{q, Poly, QMatrix};
use subdlab::numeric::Rational;
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::crease_sides::{
    decouple, dependency_closure, first_weight_outside, principal, CreaseSides, Decoupling,
};
use subdlab::spectrum::{analyse, Analysis, Options};

fn analysis(name: &str, params: &[(&str, &str)], n: usize, tag: &str) -> (Box<dyn Scheme>, Analysis) {
    let params: Vec<(String, String)> = params.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
    let scheme: Box<dyn Scheme> = schemes::build(name, &params).unwrap();
    let config = Configuration::tagged(scheme.as_ref(), n, None, Tagging::parse(tag).unwrap()).unwrap();
    let a = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
    (scheme, a)
}

fn certify(name: &str, n: usize, tag: &str) -> TaggedCertificate {
    let (scheme, a) = analysis(name, &[], n, tag);
    certify_tagged(scheme.as_ref(), &a).unwrap()
}

/// The sides, from the exact rows' reads (every weight exact here).
fn sides(a: &Analysis) -> CreaseSides {
    let exact = a.exact_matrix.as_ref().expect("rational rules");
    let reads = |r: usize| exact.rows[r].iter().map(|(c, _)| *c).collect::<Vec<_>>();
    match decouple(&a.discovered.config, &exact.labels, &reads) {
        Some(Decoupling::Sides(s)) => s,
        other => panic!("the crease rules decouple the sides: {other:?}"),
    }
}

/// The characteristic polynomial of an invariant set's principal submatrix
/// (the invariance asserted).
fn charpoly_on(a: &Analysis, set: &[usize]) -> Poly {
    let exact = a.exact_matrix.as_ref().unwrap();
    assert_eq!(first_weight_outside(&exact.rows, set, |w: &Rational| *w == q(0, 1)), None, "invariant set");
    principal_charpoly(a, set)
}

/// The characteristic polynomial of the principal submatrix on `set`.
fn principal_charpoly(a: &Analysis, set: &[usize]) -> Poly {
    let exact = a.exact_matrix.as_ref().unwrap();
    let rows = principal(&exact.rows, set);
    let mut m = QMatrix::zeros(set.len());
    for (i, row) in rows.iter().enumerate() {
        for (j, w) in row {
            m.set(i, *j, w.clone());
        }
    }
    m.charpoly()
}

fn times(a: &Poly, b: &Poly) -> Poly {
    let mut c = vec![q(0, 1); a.coeffs.len() + b.coeffs.len() - 1];
    for (i, x) in a.coeffs.iter().enumerate() {
        for (j, y) in b.coeffs.iter().enumerate() {
            c[i + j] = &c[i + j] + x * y;
        }
    }
    Poly { coeffs: c }
}

#[test]
fn the_spectrum_of_s_is_the_sides_less_the_curve_exactly() {
    for (name, n, tag) in [
        ("catmull-clark", 4, "crease:2"),
        ("catmull-clark", 6, "crease:4"),
        ("catmull-clark", 7, "crease:3"),
        ("loop", 6, "crease:3"),
        ("loop", 9, "crease:4"),
    ] {
        let (_, a) = analysis(name, &[], n, tag);
        let s = sides(&a);
        let all: Vec<usize> = (0..a.spectrum.labels.len()).collect();
        // the rest R: curve points further out on the sharp rays that no
        // side's inside point reads (Loop's second ring on the rays; none
        // for Catmull–Clark). Their rows are the curve rule's, so R ∪ C is
        // invariant and, in the order (C, R, A only, B only), S is block
        // lower triangular: det(x − S) det(x − C) = det(x − A) det(x − B) det(x − R)
        let rest: Vec<usize> =
            all.iter().copied().filter(|p| !s.sides[0].contains(p) && !s.sides[1].contains(p)).collect();
        let mut curve_and_rest: Vec<usize> = s.curve.iter().chain(&rest).copied().collect();
        curve_and_rest.sort();
        assert_eq!(
            first_weight_outside(&a.exact_matrix.as_ref().unwrap().rows, &curve_and_rest, |w: &Rational| *w == q(0, 1)),
            None
        );
        let (ps, pa, pb, pc) = (
            charpoly_on(&a, &all),
            charpoly_on(&a, &s.sides[0]),
            charpoly_on(&a, &s.sides[1]),
            charpoly_on(&a, &s.curve),
        );
        let pr = principal_charpoly(&a, &rest);
        assert_eq!(
            times(&ps, &pc),
            times(&times(&pa, &pb), &pr),
            "{name} {tag}: det(x − S) det(x − C) = det(x − A) det(x − B) det(x − R)"
        );
        assert_eq!(rest.is_empty(), name == "catmull-clark", "{name}: rest {rest:?}");
        // negative control: without the curve's factor the identity fails
        assert_ne!(times(&ps, &Poly::one()), times(&times(&pa, &pb), &pr), "{name} {tag}");
        // each side is the boundary fan of its faces: the same closure of
        // the fan's inside points (off its two boundary rays), whose
        // characteristic polynomial divides the fan's whole one (the fan's
        // other points are on its boundary rays, further out)
        for (side, k) in [(0, s.at), (1, n - s.at)] {
            let (_, fan) = analysis(name, &[], k, "boundary");
            let exact = fan.exact_matrix.as_ref().unwrap();
            let inside: Vec<usize> = (0..exact.labels.len())
                .filter(|&p| {
                    let l = &exact.labels[p];
                    !(l.i == 0 && l.j == 0) && !(l.j == 0 && (l.sector == 0 || l.sector == k))
                })
                .collect();
            let reads = |r: usize| exact.rows[r].iter().map(|(c, _)| *c).collect::<Vec<_>>();
            let fan_side = dependency_closure(&inside, &reads);
            let pside = if side == 0 { &pa } else { &pb };
            assert_eq!(pside, &charpoly_on(&fan, &fan_side), "{name} {tag} side {side} = boundary k = {k}");
            let all_fan: Vec<usize> = (0..exact.labels.len()).collect();
            let fan_rest: Vec<usize> = all_fan.iter().copied().filter(|p| !fan_side.contains(p)).collect();
            assert_eq!(
                charpoly_on(&fan, &all_fan),
                times(pside, &principal_charpoly(&fan, &fan_rest)),
                "{name} k = {k}"
            );
        }
    }
}

#[test]
fn the_regular_crease_passes_per_side() {
    // Catmull–Clark n = 4 crease:2 (sides of 2 quads), Loop n = 6 crease:3
    // (sides of 3 triangles): the curve is the centre and its two sharp rays
    for (name, n, tag, curve) in [("catmull-clark", 4, "crease:2", 5), ("loop", 6, "crease:3", 3)] {
        let (_, a) = analysis(name, &[], n, tag);
        let v = &a.spectrum.verdict;
        assert_eq!(v.criterion, "sector per side");
        assert!(v.c1_spectral, "{name}: {:?}", v.reasons);
        let c = a.spectrum.crease.as_ref().unwrap();
        assert!(!c.whole.c1_spectral, "S whole has 1/2 three times");
        assert_eq!(c.curve_size, curve);
        assert_eq!(c.invariance.as_deref(), Some("exact, in Q"));
        // each side: 1 simple, 1/2 exactly twice and non-defective, the
        // curve's 1/4 among the rest (the derivation in the module doc)
        let s = sides(&a);
        for side in 0..2 {
            let p = charpoly_on(&a, &s.sides[side]);
            assert_eq!(p.root_multiplicity(&q(1, 1)).0, 1);
            assert_eq!(p.root_multiplicity(&q(1, 2)).0, 2);
            assert!(p.root_multiplicity(&q(1, 4)).0 >= 1);
            let e = &c.sides[side].eigenvalues;
            assert_eq!(
                (e[1].exact.as_deref(), e[1].algebraic_multiplicity, e[1].geometric_multiplicity),
                (Some("1/2"), 2, 2)
            );
        }
        let cert = certify(name, n, tag);
        assert_eq!(cert.verdict, Verdict::Proved, "{name}: {:?}", cert.verdict);
        assert_eq!(cert.decided_by, Some("sides"));
        let crease = cert.crease.as_ref().unwrap();
        assert!(matches!(crease.whole_verdict, Verdict::Disproved(_)), "{:?}", crease.whole_verdict);
        for side in &crease.sides {
            let x = side.certificate.exact_route.as_ref().unwrap();
            assert_eq!((x.r.as_deref(), x.algebraic, x.geometric, x.above), (Some("1/2"), 2, 2, 0), "{}", side.name);
        }
    }
}

#[test]
fn a_side_with_a_defective_boundary_fails_naming_that_side() {
    // Catmull–Clark n = 6 crease:4: side A has 4 faces (the defective
    // boundary k = 4), side B 2 (the regular one)
    let (_, a) = analysis("catmull-clark", &[], 6, "crease:4");
    let v = &a.spectrum.verdict;
    assert!(!v.c1_spectral);
    assert!(v.failures.iter().all(|f| f.starts_with("side A (sectors 0..3, 4 faces")), "{:?}", v.failures);
    assert!(v.failures.iter().any(|f| f.contains("defective")), "{:?}", v.failures);
    let c = a.spectrum.crease.as_ref().unwrap();
    assert!(!c.sides[0].verdict.c1_spectral && c.sides[1].verdict.c1_spectral);
    let cert = certify("catmull-clark", 6, "crease:4");
    assert!(matches!(&cert.verdict, Verdict::Disproved(w) if w.starts_with("side A")), "{:?}", cert.verdict);
    let crease = cert.crease.as_ref().unwrap();
    assert_eq!(crease.sides[1].certificate.verdict, Verdict::Proved);
    let x = crease.sides[0].certificate.exact_route.as_ref().unwrap();
    assert_eq!((x.r.as_deref(), x.algebraic, x.geometric), (Some("1/2"), 2, 1), "a Jordan block at 1/2");
    // with BLZ's rules the same crease passes on both sides (their γ puts
    // mode 1 at 1/2, odd, beside the even tangent... one per block)
    let (_, b) = analysis("catmull-clark", &[("blz", "1")], 6, "crease:4");
    assert!(b.spectrum.verdict.c1_spectral, "{:?}", b.spectrum.verdict.reasons);
}

#[test]
fn sides_that_read_across_the_crease_do_not_decouple() {
    let (_, a) = analysis("catmull-clark", &[], 4, "crease:2");
    let exact = a.exact_matrix.as_ref().unwrap();
    let s = sides(&a);
    // a point strictly inside side B, and a row of side A made to read it
    let b_only = *s.sides[1].iter().find(|p| !s.curve.contains(p)).unwrap();
    let a_only = *s.sides[0].iter().find(|p| !s.curve.contains(p)).unwrap();
    let reads = |r: usize| {
        let mut v: Vec<usize> = exact.rows[r].iter().map(|(c, _)| *c).collect();
        if r == a_only {
            v.push(b_only);
        }
        v
    };
    assert!(matches!(decouple(&a.discovered.config, &exact.labels, &reads), Some(Decoupling::Coupled(_))));
    // a side's set without its curve points is not invariant
    let no_curve: Vec<usize> = s.sides[0].iter().copied().filter(|p| !s.curve.contains(p)).collect();
    assert!(first_weight_outside(&exact.rows, &no_curve, |w: &Rational| *w == q(0, 1)).is_some());
    // a boundary vertex is not a crease: no per-side verdict
    let (_, boundary) = analysis("catmull-clark", &[], 3, "boundary");
    assert!(boundary.spectrum.crease.is_none());
    assert_eq!(boundary.spectrum.verdict.criterion, "sector");
}

#[test]
fn the_checker_rechecks_each_side_and_rejects_tampering() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let check = check_certificate;
    let write = |file: &str, args: &[&str]| write_spectrum_certificate(dir.path(), file, args);
    for (file, args, want) in [
        ("regular.json", &["catmull-clark", "-n", "4", "--tag", "crease:2"][..], "ACCEPTED (PROVED)"),
        ("loop.json", &["loop", "-n", "6", "--tag", "crease:3"][..], "ACCEPTED (PROVED)"),
        ("k4.json", &["catmull-clark", "-n", "6", "--tag", "crease:4"][..], "ACCEPTED (DISPROVED)"),
    ] {
        let (code, text) = check(&write(file, args));
        assert_eq!(code, 0, "{file}: {text}");
        assert!(text.contains(want) && text.contains("crease per side"), "{file}: {text}");
    }
    let tamper = |file: &str, edit: &dyn Fn(&mut serde_json::Value)| check_tampered_certificate(dir.path(), file, edit);
    // the failing side claimed PROVED, and the crease with it: the side's
    // exact route recomputed says DISPROVED
    let (code, text) = tamper("k4.json", &|d| {
        let t = &mut d["parts"]["tagged"];
        t["verdict"] = "PROVED".into();
        let side = &mut t["crease"]["sides"][0];
        side["verdict"] = "PROVED".into();
        side["claims"]["exact_route"]["verdict"] = "PROVED".into();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("REJECTED"), "{text}");
    // the crease's verdict changed alone: the sides' verdicts disagree with it
    let (code, text) = tamper("k4.json", &|d| d["parts"]["tagged"]["verdict"] = "PROVED".into());
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("make the crease DISPROVED"), "{text}");
    // a side's set without the centre: rows of it read the centre
    let (code, text) = tamper("regular.json", &|d| {
        let side = &mut d["parts"]["tagged"]["crease"]["sides"][0];
        let idx: Vec<serde_json::Value> = side["indices"].as_array().unwrap().iter().skip(1).cloned().collect();
        side["indices"] = idx.into();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("not invariant"), "{text}");
    // a side claimed to be S whole (it holds the other side's points)
    let (code, text) = tamper("regular.json", &|d| {
        let n = d["parts"]["tagged"]["size"].as_u64().unwrap();
        d["parts"]["tagged"]["crease"]["sides"][0]["indices"] = (0..n).collect::<Vec<u64>>().into();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("strictly inside the other side"), "{text}");
    // the document says whose verdict it gives: the sides' here
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("regular.json")).unwrap()).unwrap();
    assert_eq!(doc["parts"]["tagged"]["crease"]["verdict_of"], "sides");
    // ... and a document that claims it does not: rejected
    let (code, text) = tamper("regular.json", &|d| d["parts"]["tagged"]["crease"]["verdict_of"] = "S whole".into());
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("the crease's verdict is of 'S whole'"), "{text}");
    // S whole's verdict given as the fallback where the sides do decouple
    // (the regular crease: S whole DISPROVED, the sides PROVED): the checker
    // re-derives the closures from the exact rows and rejects the fallback
    let (code, text) = tamper("regular.json", &|d| {
        let t = &mut d["parts"]["tagged"];
        t["crease"]["decoupled"] = false.into();
        t["crease"]["verdict_of"] = "S whole".into();
        t["crease"]["coupled"] = "claimed without reason".into();
        t["verdict"] = t["crease"]["whole_verdict"].clone();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("but the sides decouple"), "{text}");
    // a fallback without its reason
    let (code, text) = tamper("regular.json", &|d| {
        let t = &mut d["parts"]["tagged"];
        t["crease"]["decoupled"] = false.into();
        t["crease"]["verdict_of"] = "S whole".into();
        t["crease"]["coupled"] = serde_json::Value::Null;
        t["verdict"] = t["crease"]["whole_verdict"].clone();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("gives no reason"), "{text}");
}
