//! The certified sector characteristic map at a Loop boundary vertex
//! (`charmap loop --tag boundary --certify`, `certify::tagged_charmap` with
//! the triangle host; lemma B3 for the triangle host in ARCHITECTURE.md)
//! and its independent re-check by `scripts/check_cert.py`.
//!
//! Expected verdicts are derived by hand, never read off the program:
//!
//! - the boundary curve's rows are the cubic B-spline's (3/4, 1/8, 1/8 and
//!   the midpoint), spectrum {1, 1/2, 1/4, 1/8, 0}, 1/2 the tangent, odd
//!   under the reflection r ↦ k − r;
//! - Loop's one-ring at a boundary vertex of k triangles is invariant; on
//!   a sine mode v_j = sin(jφ) of the interior ring points (centre and
//!   boundary neighbours 0), the new edge point on v0–v_j is 3/8·0 +
//!   3/8 v_j + 1/8 (v_{j−1} + v_{j+1}) = v_j (3/8 + cos φ/4) with Hoppe's
//!   rules: μ_m = 3/8 + cos(mπ/k)/4, m = 1..k − 1, of parity (−1)^(m+1).
//!   With BLZ's γ = 1/2 − cos(π/k)/4 on the edge (3/4 − γ) v0 + γ v_j +
//!   1/8 (c + d): μ_m = γ + cos(mπ/k)/4, so μ_1 = 1/2 exactly (even) and
//!   μ_m < 1/2 for m ≥ 2;
//! - Hoppe k = 2: λ1 = 1/2 (tangent, odd), λ2 = μ_1 = 3/8 (even, not a
//!   curve eigenvalue: its eigenvector vanishes on the rays);
//!   k = 3: μ_1 = 1/2 (even) beside the tangent 1/2 — the regular
//!   boundary, the box-spline half-plane; k = 4: λ1 = 3/8 + √2/8, k = 5:
//!   λ1 = 3/8 + cos(π/5)/4 = 3/8 + (1 + √5)/16, both even and irrational
//!   (they vanish on the rays), λ2 = 1/2 the tangent;
//! - Hoppe k = 6: μ_2 = 3/8 + cos(π/3)/4 = 1/2 in the odd block with the
//!   tangent: a Jordan block, the spectral part DISPROVED, the map not
//!   attempted; k ≥ 7: μ_1 > μ_2 > 1/2 (2π/k < π/3), neither a curve
//!   eigenvalue: both eigenvectors vanish on the rays, which collapse to
//!   the centre, DISPROVED by the map;
//! - k = 1 (Hoppe and BLZ: one triangle, no interior edge at the centre):
//!   the pair is the curve's 1/2 and 1/4, neither vanishes on the rays, so
//!   the rays' images are not known to lie on a line: NOT PROVED (lemmas
//!   B5/B6 need the line).
//!
//! Negative controls: Hoppe k = 6 (spectral) and k = 7..9 (the map), and
//! `tests/data/certify/loop-boundary-wide-curve.toml` (a Loop with the
//! boundary vertex rule 3/16, 5/8, 3/16: spectral part PROVED, float map
//! passes, certificate NOT PROVED at B3), each with the checker's verdict.

use crate::common;
use common::{
    assert_rejected, check_certificate, check_tampered_certificate, checker_can_run, subdlab, write_sector_certificate,
};
use subdlab::certify::tagged_charmap::{certify_tagged_charmap, TaggedCharMapCertificate};
use subdlab::certify::Verdict;
use subdlab::charmap::{check_map, CharMapOptions};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind, Tagging};
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Options};

struct Outcome {
    cert: TaggedCharMapCertificate,
    float_passes: bool,
}

fn certify(params: &[(&str, &str)], k: usize) -> Outcome {
    let params: Vec<(String, String)> = params.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
    let scheme: Box<dyn Scheme> = schemes::build("loop", &params).unwrap();
    let config = Configuration::tagged(scheme.as_ref(), k, None, Tagging::parse("boundary").unwrap()).unwrap();
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &opts).unwrap();
    let map = check_map(scheme.as_ref(), &analysis, &CharMapOptions::default()).unwrap();
    let cert = certify_tagged_charmap(scheme.as_ref(), &analysis, 5).unwrap();
    Outcome { cert, float_passes: analysis.spectrum.verdict.c1_spectral && map.regular && map.injective }
}

fn proved(o: &Outcome, k: usize) {
    let c = &o.cert;
    assert_eq!(c.sector_criterion, Verdict::Proved, "k = {k}: {c:?}");
    assert!(!c.conditional);
    assert_eq!((&c.regularity, &c.injectivity), (&Verdict::Proved, &Verdict::Proved));
    assert_eq!(c.regular_part.map(|r| r.describe()), Some("three-direction quartic box spline"), "k = {k}");
    assert!(c.undecided_faces == 0 && (c.positive_faces == 0) != (c.negative_faces == 0), "{c:?}");
    let sign = if c.positive_faces > 0 { 1 } else { -1 };
    assert_eq!(c.winding_number, Some(sign), "k = {k}");
    assert!(c.boundary_faces >= 2, "k = {k}: faces on both rays with ghost windows");
    assert!(o.float_passes, "k = {k}: the floating-point route must pass what is proved");
}

/// λ (the closed form) inside the named eigenvalue's enclosure, of that parity.
fn named(c: &TaggedCharMapCertificate, which: usize, lambda: f64, block: &str, k: usize) {
    let route = &c.spectrum.enclosure_route;
    let n = [route.lambda1.as_ref(), route.lambda2.as_ref()][which].unwrap();
    assert!(n.enclosure.lo <= lambda && lambda <= n.enclosure.hi, "k = {k}: λ{} = {lambda}: {:?}", which + 1, n);
    assert_eq!(n.block, block, "k = {k}: λ{}", which + 1);
}

/// Lemma B3 for the triangle host, recomputed here on a strip of the
/// three-direction lattice (d1 = (1, 0), d2 = (0, 1), d3 = (−1, 1)) with
/// integer data and the quartic box spline's rules written out (vertex
/// 10/16, 1/16; edge 3/8, 3/8, 1/8, 1/8), everything times 16 so the
/// arithmetic is exact in integers: the ghosts a + b − p make the rules at
/// the boundary row Loop's, and the refined ghost row is again the ghost
/// rule of the refined net; the point reflection 2b − p does neither.
#[test]
fn quartic_box_ghosts_reproduce_loops_boundary_rules() {
    use std::collections::HashMap;
    const D: [(i64, i64); 6] = [(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)];
    // data on rows 0..4 (a fixed pseudo-random pattern)
    let mut real: HashMap<(i64, i64), i64> = HashMap::new();
    for x in -14..=14i64 {
        for y in 0..5i64 {
            real.insert((x, y), (x * 37 + y * 101 + x * x * y * 7 + 13 * y * y) % 97 - 48);
        }
    }
    // ghost at (x, −1): edge (x − 1, 0)–(x, 0), apex across (x − 1, 1)
    let parallelogram = |p: &HashMap<(i64, i64), i64>, x: i64| p[&(x - 1, 0)] + p[&(x, 0)] - p[&(x - 1, 1)];
    let point_reflection = |p: &HashMap<(i64, i64), i64>, x: i64| 2 * p[&(x, 0)] - p[&(x, 1)];
    // one box-spline step, values times `scale`·16 (level-1 position (2x + a, 2y + b))
    let refine = |q: &HashMap<(i64, i64), i64>| {
        let mut n: HashMap<(i64, i64), i64> = HashMap::new();
        for (&(x, y), &v) in q {
            let nb: Vec<(i64, i64)> = D.iter().map(|d| (x + d.0, y + d.1)).collect();
            if nb.iter().all(|c| q.contains_key(c)) {
                n.insert((2 * x, 2 * y), 10 * v + nb.iter().map(|c| q[c]).sum::<i64>());
            }
            for k in 0..3 {
                let e = (x + D[k].0, y + D[k].1);
                let c1 = (x + D[(k + 1) % 6].0, y + D[(k + 1) % 6].1);
                let c2 = (x + D[(k + 5) % 6].0, y + D[(k + 5) % 6].1);
                if q.contains_key(&e) && q.contains_key(&c1) && q.contains_key(&c2) {
                    n.insert((2 * x + D[k].0, 2 * y + D[k].1), 6 * (v + q[&e]) + 2 * (q[&c1] + q[&c2]));
                }
            }
        }
        n
    };
    for (name, ghost) in
        [("a + b − p", &parallelogram as &dyn Fn(&HashMap<(i64, i64), i64>, i64) -> i64), ("2b − p", &point_reflection)]
    {
        let mut q = real.clone();
        for x in -13..=14 {
            q.insert((x, -1), ghost(&real, x));
        }
        let n = refine(&q);
        let v = |x: i64| real[&(x, 0)];
        // Loop's boundary rules: (1, 6, 1)/8 and the midpoint (times 16)
        let vertex = (-6..=6).all(|x| n[&(2 * x, 0)] == 12 * v(x) + 2 * (v(x - 1) + v(x + 1)));
        let edge = (-6..=6).all(|x| n[&(2 * x + 1, 0)] == 8 * (v(x) + v(x + 1)));
        // the new ghost row is the ghost rule of the new rows 0 and 1
        let stays = (-8..=8).all(|x| n.get(&(x, -1)) == Some(&ghost(&n, x)));
        if name == "a + b − p" {
            assert!(vertex && edge && stays, "{name}: vertex {vertex}, edge {edge}, ghost row {stays}");
        } else {
            assert!(!vertex && !edge, "{name} must not give Loop's boundary rules");
        }
    }
}

#[test]
fn hoppe_k2_to_k5_are_proved_with_the_closed_form_pair() {
    let sqrt2 = 2f64.sqrt();
    let cos_pi_5 = (1.0 + 5f64.sqrt()) / 4.0;
    for k in 2..=5 {
        let o = certify(&[], k);
        proved(&o, k);
        let c = &o.cert;
        match k {
            2 => {
                named(c, 0, 0.5, "odd", k);
                named(c, 1, 3.0 / 8.0, "even", k);
                assert_eq!(c.normal_coordinate, Some("lambda2"));
            }
            3 => {
                // 1/2 twice, one per block; the even one vanishes on the rays
                let route = &c.spectrum.enclosure_route;
                for n in [route.lambda1.as_ref().unwrap(), route.lambda2.as_ref().unwrap()] {
                    assert!(n.enclosure.lo <= 0.5 && 0.5 <= n.enclosure.hi);
                }
                let normal = if c.normal_coordinate == Some("lambda1") { &route.lambda1 } else { &route.lambda2 };
                assert_eq!(normal.as_ref().unwrap().block, "even");
            }
            _ => {
                let mu1 = 3.0 / 8.0 + if k == 4 { sqrt2 / 2.0 } else { cos_pi_5 } / 4.0;
                named(c, 0, mu1, "even", k);
                named(c, 1, 0.5, "odd", k);
                assert_eq!(c.normal_coordinate, Some("lambda1"), "k = {k}");
            }
        }
    }
}

#[test]
fn hoppe_k6_is_disproved_by_the_spectrum_and_k7_to_9_by_the_map() {
    let c = certify(&[], 6).cert;
    assert!(matches!(c.spectrum.verdict, Verdict::Disproved(_)), "{c:?}");
    assert!(matches!(&c.regularity, Verdict::NotProved(w) if w.contains("not attempted")));
    assert!(matches!(c.sector_criterion, Verdict::Disproved(_)));
    for k in 7..=9 {
        let o = certify(&[], k);
        let c = &o.cert;
        assert_eq!(c.spectrum.verdict, Verdict::Proved, "k = {k}");
        // μ_1 = 3/8 + cos(π/k)/4 and μ_2 = 3/8 + cos(2π/k)/4, both above 1/2
        named(c, 0, 3.0 / 8.0 + (std::f64::consts::PI / k as f64).cos() / 4.0, "even", k);
        named(c, 1, 3.0 / 8.0 + (2.0 * std::f64::consts::PI / k as f64).cos() / 4.0, "odd", k);
        assert!(matches!(&c.regularity, Verdict::Disproved(w) if w.contains("vanish on the sharp rays")), "k = {k}");
        assert!(matches!(&c.sector_criterion, Verdict::Disproved(_)), "k = {k}");
        assert!(!o.float_passes, "k = {k}: the floating-point route must fail too");
    }
}

#[test]
fn one_triangle_is_not_proved_and_says_why() {
    for params in [&[][..], &[("blz", "1")][..]] {
        let c = certify(params, 1).cert;
        assert_eq!(c.spectrum.verdict, Verdict::Proved);
        assert!(
            matches!(&c.sector_criterion, Verdict::NotProved(w) if w.contains("neither eigenvector")),
            "{params:?}: {c:?}"
        );
    }
}

#[test]
fn blz_k2_to_k12_are_proved_at_one_half() {
    for k in 2..=12 {
        let o = certify(&[("blz", "1")], k);
        proved(&o, k);
        let route = &o.cert.spectrum.enclosure_route;
        for n in [route.lambda1.as_ref().unwrap(), route.lambda2.as_ref().unwrap()] {
            assert!(n.enclosure.lo <= 0.5 && 0.5 <= n.enclosure.hi, "k = {k}: λ = 1/2");
        }
        let normal = if o.cert.normal_coordinate == Some("lambda1") { &route.lambda1 } else { &route.lambda2 };
        assert_eq!(normal.as_ref().unwrap().block, "even", "k = {k}: mode 1 vanishes on the rays");
    }
}

const WIDE_CURVE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/certify/loop-boundary-wide-curve.toml");

#[test]
fn a_loop_boundary_rule_outside_lemma_b3_is_not_proved() {
    for k in ["2", "3", "5"] {
        let out = subdlab(&["charmap", WIDE_CURVE, "-n", k, "--tag", "boundary", "--certify", "--json"]);
        assert_eq!(out.status.code(), Some(1), "k = {k}");
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let c = &v["certificate"];
        assert_eq!(c["spectrum"]["verdict"], "proved", "k = {k}: the spectral part holds, {c}");
        assert_eq!(c["sector_criterion"]["verdict"], "not_proved", "k = {k}: {c}");
        let why = c["regularity"]["reason"].as_str().unwrap();
        assert!(why.contains("numerical only") && why.contains("quartic box spline"), "{why}");
    }
}

#[test]
fn cli_proves_loop_k3_and_disproves_k7() {
    let out = subdlab(&["charmap", "loop", "-n", "3", "--tag", "boundary", "--certify"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("certified sector criterion") && text.contains(": PROVED"), "{text}");
    assert!(text.contains("ghost-extended three-direction quartic box spline rules"), "{text}");
    let out = subdlab(&["charmap", "loop", "-n", "7", "--tag", "boundary", "--certify", "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["certificate"]["sector_criterion"]["verdict"], "disproved");
}

#[test]
fn the_checker_re_derives_loops_proved_sector_maps_and_agrees_on_the_controls() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (file, args) in [
        ("hoppe2.json", &["-n", "2"][..]),
        ("hoppe3.json", &["-n", "3"][..]),
        ("hoppe4.json", &["-n", "4"][..]),
        ("hoppe5.json", &["-n", "5"][..]),
        ("blz6.json", &["-n", "6", "-p", "blz=1"][..]),
        ("blz12.json", &["-n", "12", "-p", "blz=1"][..]),
    ] {
        let (code, text) = check_certificate(&write_sector_certificate(dir.path(), file, "loop", args));
        assert_eq!(code, 0, "{file}: {text}");
        assert!(text.contains("CERTIFICATE ACCEPTED (tagged PROVED, sector criterion PROVED)"), "{file}: {text}");
        assert!(text.contains("three-direction quartic box spline with"), "{file}: {text}");
        assert!(text.contains("a + b − p computed here"), "{file}: {text}");
        for lemma in ["B1:", "B2:", "B3/B4:", "B5:", "B6:"] {
            assert!(text.contains(lemma), "{file}: {lemma} not re-checked: {text}");
        }
    }
    // the controls: no sector part, and the checker never accepts a PROVED map
    for (file, scheme, args, claimed) in [
        ("hoppe6.json", "loop", &["-n", "6"][..], "DISPROVED"),
        ("hoppe7.json", "loop", &["-n", "7"][..], "DISPROVED"),
        ("wide3.json", WIDE_CURVE, &["-n", "3"][..], "NOT PROVED"),
    ] {
        let path = write_sector_certificate(dir.path(), file, scheme, args);
        let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        assert!(doc["parts"].get("sector").is_none(), "{file}");
        assert_eq!(doc["sector_claimed"], claimed, "{file}");
        let (code, text) = check_certificate(&path);
        assert!(!text.contains("sector criterion PROVED"), "{file}: {text}");
        if file == "hoppe6.json" {
            // the tagged part is DISPROVED exactly, and re-checked so
            assert_eq!(code, 0, "{file}: {text}");
            assert!(text.contains("DISPROVED"), "{file}: {text}");
        } else {
            assert_eq!(code, 0, "{file}: {text}");
            assert!(text.contains(&format!("sector criterion not re-checked (claimed {claimed})")), "{file}: {text}");
        }
    }
}

#[test]
fn tampered_loop_sector_certificates_are_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    write_sector_certificate(dir.path(), "hoppe4.json", "loop", &["-n", "4"]);
    let tamper = |edit: &dyn Fn(&mut serde_json::Value)| check_tampered_certificate(dir.path(), "hoppe4.json", edit);
    let rejected = assert_rejected;
    // the first ghost [x, y, a, b, p] of any face, edited
    fn first_ghost(d: &mut serde_json::Value, edit: &dyn Fn(&mut Vec<serde_json::Value>, &[serde_json::Value])) {
        for f in d["parts"]["sector"]["faces"].as_array_mut().unwrap() {
            let layout = f["layout"].as_array().unwrap().clone();
            for e in f["layout"].as_array_mut().unwrap() {
                if e.as_array().unwrap().len() == 5 {
                    edit(e.as_array_mut().unwrap(), &layout);
                    return;
                }
            }
        }
        panic!("no quartic-box ghost in the document");
    }
    // a ghost moved: its apex p replaced by another net point of the window
    rejected(
        tamper(&|d| {
            first_ghost(d, &|e, layout| {
                let other = layout.iter().find(|o| o.as_array().unwrap().len() == 3 && o[2] != e[4]).unwrap();
                e[4] = other[2].clone();
            })
        }),
        "is not a + b − p",
        "ghost apex moved",
    );
    // a ghost moved to another position of the window (its own one given twice or left out)
    rejected(
        tamper(&|d| {
            first_ghost(d, &|e, _| {
                e[0] = (e[0].as_i64().unwrap() + 5).into();
            })
        }),
        "window",
        "ghost position moved",
    );
    // the bicubic host's ghost 2b − p written into the triangle host's window
    rejected(
        tamper(&|d| {
            first_ghost(d, &|e, _| {
                e.remove(2);
            })
        }),
        "ghost rule",
        "a 2b − p ghost in a Loop window",
    );
    // the host renamed: the bicubic B-spline's 4 × 4 window is not this one
    rejected(tamper(&|d| d["parts"]["sector"]["host"] = "bicubic B-spline".into()), "ghost rule", "host renamed");
    // a face's Jacobian sign flipped (k = 4 is proved negative: the
    // document says so for every face)
    rejected(
        tamper(&|d| {
            let faces = d["parts"]["sector"]["faces"].as_array_mut().unwrap();
            let s = faces[3]["sign"].as_str().unwrap().to_string();
            faces[3]["sign"] = if s == "+" { "-" } else { "+" }.into();
        }),
        "the Jacobian is claimed",
        "determinant sign flipped",
    );
    // the winding number negated
    rejected(
        tamper(&|d| {
            let n = d["parts"]["sector"]["chain"]["number"].as_i64().unwrap();
            d["parts"]["sector"]["chain"]["number"] = (-n).into();
        }),
        "winds",
        "winding number negated",
    );
}
