//! Exact cyclotomic weights (`numeric::Cyclotomic`) and the certificate's
//! exact premises in Q(ζ_N).
//!
//! The field identities are derived by hand, not from program output:
//! - Σ_{k=0}^{n−1} cos(2πk/n) = Re Σ_k ζ^k = 0 for n ≥ 2 (the n-th roots of
//!   unity sum to zero);
//! - 2cos(2π/5) = (√5 − 1)/2, the positive root of x² + x − 1;
//! - cos(2π/8) = √2/2, so its square is 1/2;
//! - cos(2π/7) is a root of 8x³ + 4x² − 4x − 1 (the minimal polynomial of
//!   2cos(2π/7) is x³ + x² − 2x − 1).
//!
//! The premise controls are scheme files whose defect is far below the
//! enclosures' width (1e-18·cos(2π/n), irrational): the interval check would
//! confirm the identity to overlap, the exact check refutes it.

use crate::common;
use common::{subdlab, Rng};
use subdlab::certify::matrix::Check;
use subdlab::certify::{certify_analysis, SpectrumCertificate, Verdict};
use subdlab::matrix::assemble_rows;
use subdlab::mesh::{PolyMesh, SectorKind};
use subdlab::neighbourhood::Configuration;
use subdlab::numeric::cyclotomic::cyclotomic_polynomial;
use subdlab::numeric::{Cyclotomic, Interval, Weight};
use subdlab::refine::{Origin, RuleResult, Stencil};
use subdlab::schemes::{self, Caps, CentreKind, MeshDomain, Params, Rules, Scheme, SchemeInfo, SchemeWeight};
use subdlab::sdc::Topology;
use subdlab::spectrum::{analyse, Options};

use std::f64::consts::PI;

fn cos(k: i64, n: i64) -> Cyclotomic {
    Cyclotomic::cos_2pi(k, n).unwrap()
}
fn q(p: i64, d: i64) -> Cyclotomic {
    Cyclotomic::ratio(p, d)
}

#[test]
fn the_cosines_of_a_full_turn_sum_to_zero() {
    for n in 2..=60 {
        let sum = (0..n).fold(Cyclotomic::zero(), |s, k| s + cos(k, n));
        assert!(sum.is_zero(), "n = {n}: {sum}");
        // and each is real, with the value of the C library's cosine
        for k in 0..n {
            let c = cos(k, n);
            assert!(c.is_real());
            assert!((c.to_f64() - (2.0 * PI * k as f64 / n as f64).cos()).abs() < 1e-13, "k = {k}, n = {n}");
        }
    }
}

#[test]
fn closed_forms_of_small_cosines_hold_exactly() {
    // x = 2cos(2π/5) = (√5 − 1)/2: x² + x − 1 = 0, and x is the inverse of x + 1
    let x = q(2, 1) * cos(1, 5);
    assert!((x.clone() * x.clone() + x.clone() - q(1, 1)).is_zero());
    assert_eq!(x.clone() * (x + q(1, 1)), q(1, 1));
    // cos(2π/8)² = 1/2 (cos 45° = √2/2)
    assert_eq!(cos(1, 8) * cos(1, 8), q(1, 2));
    // 8c³ + 4c² − 4c − 1 = 0 at c = cos(2π/7)
    let c = cos(1, 7);
    let p = q(8, 1) * c.clone() * c.clone() * c.clone() + q(4, 1) * c.clone() * c.clone() - q(4, 1) * c - q(1, 1);
    assert!(p.is_zero(), "{p}");
    // rational cosines are rationals (cos 60° = 1/2, cos 90° = 0, cos 120° = −1/2)
    assert_eq!(cos(1, 6).to_rational(), Some(subdlab::numeric::Rational::new(1.into(), 2.into())));
    assert!(cos(1, 4).is_zero());
    assert_eq!(cos(1, 3), q(-1, 2));
    // Φ_n has degree φ(n): 4 at n = 5, 20 at n = 50 (φ(50) = 50 · (1/2) · (4/5))
    assert_eq!(cyclotomic_polynomial(5).len() - 1, 4);
    assert_eq!(cyclotomic_polynomial(50).len() - 1, 20);
}

#[test]
fn every_element_times_its_inverse_is_one() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for n in [5i64, 7, 9, 12, 16, 25, 50] {
        for _ in 0..6 {
            // a random element Σ a_k cos(2πk/n) + b ζ_n, a_k and b small integers over a small denominator
            let mut x = Cyclotomic::zero();
            for k in 0..4 {
                x = x + q(rng.below(11) as i64 - 5, 1) * cos(k, n);
            }
            x = (x + q(rng.below(5) as i64 - 2, 1) * Cyclotomic::root_of_unity(1, n).unwrap())
                / q(rng.below(6) as i64 + 1, 1);
            if x.is_zero() {
                continue;
            }
            assert_eq!(x.clone() * x.inverse(), q(1, 1), "n = {n}: {x}");
            assert_eq!(q(1, 1) / x.clone() * x.clone(), q(1, 1));
        }
    }
    // division by zero is the undefined element, not a panic, and it equals nothing
    let u = cos(1, 5) / Cyclotomic::zero();
    assert!(!u.is_defined() && u != u && !u.is_zero());
}

#[test]
fn embedding_into_a_larger_field_keeps_the_value() {
    for n in [5i64, 7, 9, 12, 25] {
        for k in 1..n {
            // ζ_n^k = ζ_{2n}^{2k}: the same element, written in Q(ζ_n) and in Q(ζ_2n)
            let small = Cyclotomic::root_of_unity(k, n).unwrap();
            let large = Cyclotomic::root_of_unity(2 * k, 2 * n).unwrap();
            assert_eq!(small, large);
            // an element of Q(ζ_2n) proper: mixing embeds ζ_n into Q(ζ_2n)
            let mixed = cos(k, n) + cos(1, 2 * n) - cos(1, 2 * n);
            assert_eq!(mixed, cos(k, n));
            let sum = cos(k, n) + cos(1, 2 * n);
            let want = (2.0 * PI * k as f64 / n as f64).cos() + (PI / n as f64).cos();
            approx::assert_abs_diff_eq!(sum.to_f64(), want, epsilon = 1e-13);
            approx::assert_abs_diff_eq!(mixed.to_f64(), cos(k, n).to_f64(), epsilon = 1e-14);
        }
    }
}

#[test]
fn cyclotomic_rows_of_the_builtins_are_the_float_rows() {
    // the same rule code, exact: every weight equals the float weight to
    // rounding, and the interval enclosure holds the exact value
    for name in ["loop", "doo-sabin", "sqrt3", "non-box", "four-three", "pgs"] {
        let scheme = schemes::build(name, &[]).unwrap();
        for n in [5, 7] {
            let config = Configuration::regular(scheme.as_ref(), n).unwrap();
            let a = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
            let all: Vec<usize> = (0..a.spectrum.labels.len()).collect();
            let (d, kind) = (&a.discovered, a.spectrum.neighbourhood);
            let exact = assemble_rows::<Cyclotomic>(scheme.as_ref(), d, kind, &all).unwrap();
            let float = assemble_rows::<f64>(scheme.as_ref(), d, kind, &all).unwrap();
            let enclosed = assemble_rows::<Interval>(scheme.as_ref(), d, kind, &all).unwrap();
            for ((e, f), i) in exact.iter().zip(&float).zip(&enclosed) {
                assert_eq!(e.len(), f.len(), "{name} n = {n}");
                for (((ce, we), (cf, wf)), (ci, wi)) in e.iter().zip(f).zip(i) {
                    assert_eq!(ce, cf);
                    assert_eq!(ce, ci);
                    assert!((we.to_f64() - wf).abs() < 1e-14, "{name} n = {n}: {we} vs {wf}");
                    assert!(wi.overlaps(&Interval::from_cyclotomic(we).unwrap()), "{name} n = {n}: {we} vs {wi:?}");
                }
            }
        }
    }
}

fn certificate(scheme: &dyn Scheme, n: usize) -> SpectrumCertificate {
    let config = Configuration::regular(scheme, n).unwrap();
    let analysis = analyse(scheme, &config, &Options::default()).unwrap();
    certify_analysis(scheme, &analysis).unwrap()
}

/// A Loop scheme file with `extra` appended to the vertex rule's centre
/// weight and `edge_extra` to the extraordinary edge rule's e_j weights (the
/// edge rule written at the extraordinary vertex as Loop's: 3/8 on the centre
/// and on e_0, 1/8 on the apexes e_1 and e_{n−1}).
fn loop_file(dir: &std::path::Path, name: &str, extra: &str, edge_extra: &str) -> Box<dyn Scheme> {
    let text = format!(
        "name = \"{name}\"\ntopology = \"primal-triangle\"\n\n[vertex]\n\
         centre = \"3/8 + (3/8 + cos(2 pi / n) / 4)^2{extra}\"\n\
         edge = \"(5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n\"\n\n\
         [edge]\nends = \"3/8\"\nopposite = \"1/8\"\n\n\
         [edge-extraordinary]\ncentre = \"3/8\"\n\
         edge = \"3 kronecker(j) / 8 + (kronecker(j - 1) + kronecker(j - n + 1)) / 8{edge_extra}\"\n"
    );
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    schemes::resolve(path.to_str().unwrap(), &[]).unwrap()
}

#[test]
fn scheme_files_with_cosines_are_proved_exactly_and_tiny_irrational_defects_are_caught() {
    let dir = tempfile::tempdir().unwrap();
    // the control: Loop as a file, with its edge rule written out at the
    // extraordinary vertex: PROVED, every premise exact in Q(ζ_n)
    let good = loop_file(dir.path(), "loop-exact", "", "");
    for n in [5, 7] {
        let c = certificate(good.as_ref(), n);
        assert_eq!(c.verdict, Verdict::Proved, "n = {n}");
        let p = c.premises.as_ref().unwrap();
        assert!(p.exact && !c.conditional, "n = {n}: {p:?}");
        assert_eq!(p.field.as_deref(), Some(format!("Q(ζ_{n})").as_str()));
    }
    // the centre's row sums to 1 + 1e-18·cos(2π/n) ≠ 1: within every
    // enclosure's width, refuted exactly
    let drift = loop_file(dir.path(), "loop-drift", " + 1e-18 cos(2 pi / n)", "");
    for n in [5, 7] {
        // the enclosure of the centre's row sum holds 1: intervals alone would pass it
        let config = Configuration::regular(drift.as_ref(), n).unwrap();
        let a = analyse(drift.as_ref(), &config, &Options::default()).unwrap();
        let centre = a.spectrum.labels.iter().position(|l| l.name == "centre").unwrap();
        let rows =
            assemble_rows::<Interval>(drift.as_ref(), &a.discovered, a.spectrum.neighbourhood, &[centre]).unwrap();
        let sum = rows[0].iter().fold(Interval::point(0.0), |s, (_, w)| s + *w);
        assert!(sum.contains(1.0), "n = {n}: {sum:?}");
        let c = certificate(drift.as_ref(), n);
        let p = c.premises.as_ref().unwrap();
        match &p.row_sums_one {
            Check::Fails(why) => assert!(why.contains("the row of centre sums to"), "{why}"),
            other => panic!("n = {n}: {other:?}"),
        }
        match &c.verdict {
            Verdict::NotProved(why) => assert!(why.contains("1 is not known to be an eigenvalue"), "{why}"),
            v => panic!("n = {n}: {v:?}"),
        }
        assert!(!c.conditional);
    }
    // a chiral term ±1e-18·cos(2π/n) on e_1 and e_{n−1} of the edge rule:
    // rotation-symmetric, rows still summing to 1, but not mirror-symmetric
    let chiral = loop_file(
        dir.path(),
        "loop-chiral-tiny",
        "",
        " + (kronecker(j - 1) - kronecker(j - n + 1)) 1e-18 cos(2 pi / n)",
    );
    for n in [5, 7] {
        let c = certificate(chiral.as_ref(), n);
        let p = c.premises.as_ref().unwrap();
        assert_eq!(p.row_sums_one, Check::Exact, "n = {n}");
        assert_eq!(p.rotation_symmetry, Check::Exact, "n = {n}");
        assert!(matches!(p.mirror_symmetry, Check::Fails(_)), "n = {n}: {:?}", p.mirror_symmetry);
        match &c.verdict {
            Verdict::NotProved(why) => assert!(why.contains("mirror symmetry"), "{why}"),
            v => panic!("n = {n}: {v:?}"),
        }
    }
}

/// Loop with the centre's vertex weights passed through √(w²) = w (they are
/// positive): the same numbers, but a square root of an irrational square
/// is beyond the exact cyclotomic arithmetic, while the interval encloses it.
struct RootLoop {
    base: Box<dyn Scheme>,
    params: Params,
}

impl<W: SchemeWeight> Rules<MeshDomain, W> for RootLoop {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        let stencil = W::rule(self.base.as_ref(), mesh, origin)?;
        match (origin, stencil) {
            (Origin::Vertex(v), Ok(s)) if mesh.valence(v) != Some(6) => {
                let terms =
                    s.terms.into_iter().map(|(u, w)| Ok((u, (w.clone() * w).sqrt()?))).collect::<Result<_, _>>()?;
                Ok(Ok(Stencil { terms }))
            }
            (_, s) => Ok(s),
        }
    }
}

const ROOT_LOOP: SchemeInfo = SchemeInfo {
    name: "root-loop",
    description: "Loop with its extraordinary vertex weights written as square roots of their squares (test only)",
    topology: Topology::PrimalTriangle,
    centre: CentreKind::Vertex,
    sector: SectorKind::Tri,
    caps: Caps::NONE,
};

impl Scheme for RootLoop {
    fn info(&self) -> &SchemeInfo {
        &ROOT_LOOP
    }
    fn params(&self) -> &Params {
        &self.params
    }
}

#[test]
fn a_weight_beyond_the_exact_arithmetic_keeps_the_proof_conditional() {
    let s = RootLoop { base: schemes::build("loop", &[]).unwrap(), params: Params::default() };
    let c = certificate(&s, 5);
    assert_eq!(c.verdict, Verdict::Proved);
    let p = c.premises.as_ref().unwrap();
    // the centre's row is enclosed but not exact: its sum and its rotation
    // invariance are confirmed to overlap; the mirror check uses the other
    // rows, all rational
    assert_eq!(p.row_sums_one, Check::Overlap);
    assert_eq!(p.rotation_symmetry, Check::Overlap);
    assert_eq!(p.mirror_symmetry, Check::Exact);
    assert!(!p.exact && c.conditional);
    assert_eq!(p.field.as_deref(), Some("Q"));
    // at n = 4 the square roots are of rational squares: exact again
    let c = certificate(&s, 4);
    assert!(c.premises.as_ref().unwrap().exact && !c.conditional);
}

/// Doo–Sabin with ±1e-18·cos(2π/n) moved between two weights of the new
/// vertex at corner 2 of the extraordinary face only: rows still summing to
/// 1, but S no longer commutes with the rotation (by far less than the
/// enclosures' width).
struct TwistedDooSabin {
    base: Box<dyn Scheme>,
    params: Params,
}

impl<W: SchemeWeight> Rules<MeshDomain, W> for TwistedDooSabin {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        let stencil = W::rule(self.base.as_ref(), mesh, origin)?;
        match (origin, stencil) {
            (Origin::Corner { face, corner: 2 }, Ok(mut s)) if mesh.face(face).len() != 4 => {
                let n = mesh.face(face).len() as i64;
                let tiny =
                    W::ratio(1, 1_000_000_000_000_000_000) * W::cos_2pi(1, n).map_err(|_| subdlab::numeric::Inexact)?;
                let (a, b) = (mesh.face(face)[2], mesh.face(face)[3]);
                s.terms.push((a, tiny.clone()));
                s.terms.push((b, -tiny));
                Ok(Ok(s.merged()))
            }
            (_, s) => Ok(s),
        }
    }
}

const TWISTED: SchemeInfo = SchemeInfo {
    name: "twisted-doo-sabin",
    description: "Doo–Sabin with one corner of the extraordinary face perturbed (test only)",
    topology: Topology::Dual,
    centre: CentreKind::Face,
    sector: SectorKind::Quad,
    caps: Caps::NONE,
};

impl Scheme for TwistedDooSabin {
    fn info(&self) -> &SchemeInfo {
        &TWISTED
    }
    fn params(&self) -> &Params {
        &self.params
    }
}

#[test]
fn a_rotation_defect_below_the_enclosures_width_is_refuted_exactly() {
    let s = TwistedDooSabin { base: schemes::build("doo-sabin", &[]).unwrap(), params: Params::default() };
    for n in [5, 7] {
        let c = certificate(&s, n);
        match &c.verdict {
            Verdict::NotProved(why) => assert!(why.contains("commute with the rotation"), "n = {n}: {why}"),
            v => panic!("n = {n}: {v:?}"),
        }
        assert!(!c.conditional);
    }
}

#[test]
fn doo_sabin_rotation_is_exact_within_the_work_bound_and_enclosed_beyond() {
    // ring 0 of Doo–Sabin is one orbit of n dense rows: (n − 1)·n·n coefficient
    // operations; at n = 130 its rows come in three chunks, at n = 210 they
    // exceed the bound and are compared on their enclosures
    let ds = schemes::build("doo-sabin", &[]).unwrap();
    const { assert!(129 * 130 * 130 <= subdlab::certify::spectrum::MAX_EXACT_ORBIT_WORK) };
    const { assert!(209 * 210 * 210 > subdlab::certify::spectrum::MAX_EXACT_ORBIT_WORK) };
    let c = certificate(ds.as_ref(), 130);
    assert_eq!(c.verdict, Verdict::Proved);
    assert!(c.premises.as_ref().unwrap().exact && !c.conditional);
    let c = certificate(ds.as_ref(), 210);
    assert_eq!(c.verdict, Verdict::Proved);
    let p = c.premises.as_ref().unwrap();
    assert_eq!(p.rotation_symmetry, Check::Overlap);
    assert_eq!((&p.row_sums_one, &p.mirror_symmetry), (&Check::Exact, &Check::Exact));
    assert!(c.conditional);
}

#[test]
fn loop_and_doo_sabin_are_proved_unconditionally_through_the_cli() {
    for name in ["loop", "doo-sabin"] {
        for n in ["5", "7", "12", "50"] {
            let out = subdlab(&["spectrum", name, "-n", n, "--certify", "--json"]);
            assert!(out.status.success(), "{name} {n}: {}", String::from_utf8_lossy(&out.stderr));
            let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
            let cert = &v["certificate"];
            assert_eq!(cert["verdict"], "proved", "{name} n = {n}: {cert}");
            assert_eq!(cert["conditional"], false, "{name} n = {n}");
            let p = &cert["premises"];
            for premise in ["row_sums_one", "mirror_symmetry", "rotation_symmetry"] {
                assert_eq!(p[premise]["status"], "exact", "{name} n = {n}: {premise}");
            }
            assert_eq!(p["exact"], true);
            assert_eq!(p["field"], format!("Q(ζ_{n})"), "{name} n = {n}");
        }
    }
    // the text names the field
    let out = subdlab(&["spectrum", "loop", "-n", "7", "--certify"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("certified spectral C1 conditions: PROVED\n"), "{text}");
    assert!(text.contains("premise row sums = 1: exact, in Q(ζ_7)"), "{text}");
}
