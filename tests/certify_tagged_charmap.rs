//! The certified sector characteristic map at a boundary vertex
//! (`charmap --tag boundary --certify`, `certify::tagged_charmap`; lemmas
//! B1–B6 of ARCHITECTURE.md).
//!
//! Expected verdicts are derived by hand (the mode analysis of
//! `tests/certify_tagged.rs`' module doc), never read off the program:
//!
//! - the boundary curve's rows are the cubic B-spline's, with eigenvalues
//!   1, 1/2 (the tangent, odd under the reflection r ↦ k − r), 1/4, 1/8, …
//!   and no others: its local matrix is the curve's, whose spectrum is
//!   {1, 1/2, 1/4, 1/8, 0} for any number of points along the rays;
//! - an interior sine mode m of Hoppe's Catmull–Clark boundary fan of k
//!   faces has μ(φ) = (t + √(t² − 1/4))/2, t = 5/8 + cos φ/8, φ = mπ/k, of
//!   parity (−1)^(m+1); μ(π/2) = 1/2 and μ is decreasing in φ on (0, π);
//! - k = 3: λ1 = μ(π/3) = (11 + √57)/32 ≈ 0.5797 (mode 1, even), λ2 = 1/2
//!   (the curve's tangent, odd; mode 2's μ(2π/3) = (9 + √17)/32 ≈ 0.41 is
//!   below). 0.5797 is no eigenvalue of the curve, so the λ1 eigenvector
//!   vanishes on both rays and the λ2 one is the tangent: the rays' images
//!   lie on one line, 180° apart (the floating-point `charmap --tag`
//!   reports 180° too);
//! - k = 2 is the regular boundary (the bicubic half-plane): λ1 = λ2 = 1/2,
//!   mode 1 (even) and the tangent (odd); the map is a linear image of the
//!   half-plane, so regular and injective;
//! - k ≥ 5: modes 1 and 2 have φ = π/k, 2π/k < π/2, so both μ > 1/2, above
//!   the tangent, and neither is an eigenvalue of the curve: both
//!   eigenvectors vanish on the rays, the map sends them to the centre and
//!   is neither regular nor injective — while the spectral part holds
//!   (μ(π/k) > μ(2π/k) > 1/2 > every other): the map, not the spectrum,
//!   fails;
//! - k = 4 (μ(π/2) = 1/2 in the odd block with the tangent: defective) and
//!   k = 1 fail the spectral part, so the map is not attempted;
//! - BLZ's rules (`-p blz=1`) put mode 1 at 1/2 exactly (even): λ1 = λ2 =
//!   1/2, the even one vanishing on the curve (the curve's even spectrum is
//!   1, 1/4, …), the odd one the tangent; the sector map is then the map of
//!   a regular half-plane-like sector, PROVED for every k tried.
//!
//! Every PROVED here has its negative control in the same file (k = 1, 4
//! spectral; k = 5..8 geometric), and every verdict is compared with the
//! floating-point route, a third, independent one.

use crate::common;
use common::subdlab;
use subdlab::certify::tagged_charmap::certify_tagged_charmap;
use subdlab::certify::Verdict;
use subdlab::charmap::{check_map, CharMapOptions};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind, Tagging};
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Options};

struct Outcome {
    cert: subdlab::certify::tagged_charmap::TaggedCharMapCertificate,
    float_passes: bool,
}

fn certify(name: &str, params: &[(&str, &str)], k: usize) -> Outcome {
    let params: Vec<(String, String)> = params.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
    let scheme: Box<dyn Scheme> = schemes::build(name, &params).unwrap();
    let config = Configuration::tagged(scheme.as_ref(), k, None, Tagging::parse("boundary").unwrap()).unwrap();
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &opts).unwrap();
    let map = check_map(scheme.as_ref(), &analysis, &CharMapOptions::default()).unwrap();
    let cert = certify_tagged_charmap(scheme.as_ref(), &analysis, 5).unwrap();
    Outcome { cert, float_passes: analysis.spectrum.verdict.c1_spectral && map.regular && map.injective }
}

fn proved(o: &Outcome) {
    let c = &o.cert;
    assert_eq!(c.sector_criterion, Verdict::Proved, "{c:?}");
    assert!(!c.conditional);
    assert_eq!(c.regularity, Verdict::Proved);
    assert_eq!(c.injectivity, Verdict::Proved);
    // one Jacobian sign on every ring face, and the doubled chain winds
    // once in that orientation
    assert!(c.undecided_faces == 0 && (c.positive_faces == 0) != (c.negative_faces == 0), "{c:?}");
    let sign = if c.positive_faces > 0 { 1 } else { -1 };
    assert_eq!(c.winding_number, Some(sign));
    // faces on both rays were checked with ghost windows
    assert!(c.boundary_faces >= 2);
    assert!(o.float_passes, "the floating-point route must pass what is proved");
}

#[test]
fn hoppe_k2_and_k3_are_proved() {
    let k2 = certify("catmull-clark", &[], 2);
    proved(&k2);
    let k3 = certify("catmull-clark", &[], 3);
    proved(&k3);
    // λ1 = (11 + √57)/32 is off the curve's spectrum: the λ1 eigenvector
    // vanishes on the rays
    assert_eq!(k3.cert.normal_coordinate, Some("lambda1"));
    let lambda1 = (11.0 + 57f64.sqrt()) / 32.0;
    let l1 = k3.cert.spectrum.enclosure_route.lambda1.as_ref().unwrap();
    assert!(l1.enclosure.lo <= lambda1 && lambda1 <= l1.enclosure.hi);
    assert_eq!(l1.block, "even");
}

#[test]
fn hoppe_k5_to_8_pass_the_spectrum_and_fail_the_map() {
    for k in 5..=8 {
        let o = certify("catmull-clark", &[], k);
        let c = &o.cert;
        assert_eq!(c.spectrum.verdict, Verdict::Proved, "k = {k}");
        assert!(matches!(&c.regularity, Verdict::Disproved(w) if w.contains("vanish on the sharp rays")), "k = {k}");
        assert!(matches!(&c.injectivity, Verdict::Disproved(_)), "k = {k}");
        assert!(matches!(&c.sector_criterion, Verdict::Disproved(_)), "k = {k}");
        assert!(!o.float_passes, "k = {k}: the floating-point route must fail too");
    }
}

#[test]
fn hoppe_k1_and_k4_fail_the_spectral_part_and_the_map_is_not_attempted() {
    for k in [1, 4] {
        let c = certify("catmull-clark", &[], k).cert;
        assert!(matches!(c.spectrum.verdict, Verdict::Disproved(_)), "k = {k}");
        assert!(matches!(&c.regularity, Verdict::NotProved(w) if w.contains("not attempted")), "k = {k}");
        assert!(matches!(c.sector_criterion, Verdict::Disproved(_)), "k = {k}");
        assert!(c.levels.is_none());
    }
}

#[test]
fn blz_boundaries_are_proved() {
    for k in [2, 3, 4, 5, 6, 8, 12] {
        let o = certify("catmull-clark", &[("blz", "1")], k);
        proved(&o);
        // the vanishing eigenvector is the even one (mode 1 at 1/2)
        let route = &o.cert.spectrum.enclosure_route;
        let named = match o.cert.normal_coordinate {
            Some("lambda1") => route.lambda1.as_ref(),
            Some("lambda2") => route.lambda2.as_ref(),
            _ => None,
        };
        assert_eq!(named.map(|n| n.block), Some("even"), "k = {k}");
        for n in [route.lambda1.as_ref(), route.lambda2.as_ref()] {
            let e = &n.unwrap().enclosure;
            assert!(e.lo <= 0.5 && 0.5 <= e.hi, "k = {k}: λ = 1/2");
        }
    }
}

#[test]
fn loop_is_not_proved_but_never_disproved() {
    // the ghost construction 2b − p is the bicubic B-spline's; Loop's
    // boundary is not covered, and must say so rather than decide
    let c = certify("loop", &[], 3).cert;
    assert_eq!(c.spectrum.verdict, Verdict::Proved);
    assert!(matches!(&c.sector_criterion, Verdict::NotProved(w) if w.contains("numerical only")), "{c:?}");
}

#[test]
fn cli_exit_codes_json_and_refusals() {
    let out = subdlab(&["charmap", "catmull-clark", "-n", "3", "--tag", "boundary", "--certify"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("certified sector criterion") && text.contains(": PROVED"), "{text}");
    let out = subdlab(&["charmap", "catmull-clark", "-n", "6", "--tag", "boundary", "--certify", "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["certificate"]["sector_criterion"]["verdict"], "disproved");
    assert_eq!(v["certificate"]["spectrum"]["verdict"], "proved");
    let out = subdlab(&["charmap", "loop", "-n", "3", "--tag", "boundary", "--certify"]);
    assert_eq!(out.status.code(), Some(1));
    for args in [
        &["charmap", "catmull-clark", "-n", "4", "--tag", "crease:2", "--certify"][..],
        &["charmap", "catmull-clark", "-n", "3", "--tag", "corner", "--certify"][..],
        &["charmap", "catmull-clark", "-n", "3", "--tag", "boundary", "--certify", "--certificate", "/tmp/never.json"]
            [..],
    ] {
        let line = common::fails(args);
        assert!(line.contains("--certify"), "{line}");
    }
}

#[test]
fn a_boundary_rule_outside_lemma_b3_is_not_proved() {
    // tests/data/certify/cc-boundary-wide-curve.toml: the boundary vertex
    // rule (3/16, 5/8, 3/16) is not the ghost-extended bicubic B-spline's
    // (1/8, 3/4, 1/8) (derivation in the file): the certificate must refuse
    // to prove, and say why
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/certify/cc-boundary-wide-curve.toml");
    for k in ["2", "3"] {
        let out = subdlab(&["charmap", file, "-n", k, "--tag", "boundary", "--certify", "--json"]);
        assert_eq!(out.status.code(), Some(1), "k = {k}");
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let c = &v["certificate"];
        assert_eq!(c["sector_criterion"]["verdict"], "not_proved", "k = {k}: {c}");
        let why = c["regularity"]["reason"].as_str().unwrap();
        assert!(why.contains("numerical only") && why.contains("ghost-extended"), "{why}");
    }
}
