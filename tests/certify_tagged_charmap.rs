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
//! floating-point route, a third, independent one. Loop's boundary (the
//! triangle host) is `tests/certify_loop_sector.rs`.

use crate::common;
use common::{
    assert_rejected, check_certificate, check_tampered_certificate, checker_can_run, subdlab, write_sector_certificate,
};
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
    for args in [
        &["charmap", "catmull-clark", "-n", "4", "--tag", "crease:2", "--certify"][..],
        &["charmap", "catmull-clark", "-n", "3", "--tag", "corner", "--certify"][..],
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

#[test]
fn the_independent_checker_re_derives_proved_sector_maps() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // the PROVED cases of the module doc (Hoppe k = 2, 3; BLZ k = 2, 5, 12):
    // the checker rebuilds the eigenvectors (Krawczyk), the curve's
    // vanishing (Sturm), the net, every Jacobian sign and the winding
    for (file, args) in [
        ("hoppe2.json", &["-n", "2"][..]),
        ("hoppe3.json", &["-n", "3"][..]),
        ("blz2.json", &["-n", "2", "-p", "blz=1"][..]),
        ("blz5.json", &["-n", "5", "-p", "blz=1"][..]),
        ("blz12.json", &["-n", "12", "-p", "blz=1"][..]),
    ] {
        let (code, text) = check_certificate(&write_sector_certificate(dir.path(), file, "catmull-clark", args));
        assert_eq!(code, 0, "{file}: {text}");
        assert!(text.contains("CERTIFICATE ACCEPTED (tagged PROVED, sector criterion PROVED)"), "{file}: {text}");
        for lemma in ["B1:", "B2:", "B3/B4:", "B5:", "B6:"] {
            assert!(text.contains(lemma), "{file}: {lemma} not re-checked: {text}");
        }
    }
    // Hoppe k = 3: λ1 = (11 + √57)/32 (even) is the normal coordinate, the
    // doubled chain winds once (the module doc's derivation)
    let text = check_certificate(&dir.path().join("hoppe3.json")).1;
    assert!(text.contains("no eigenvalue in λ1's enclosure"), "{text}");
}

#[test]
fn a_disproved_sector_map_writes_no_sector_part() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // Hoppe k = 5: the spectral part holds, the map does not (both
    // eigenvectors vanish on the rays): the document holds the tagged part
    // only, and the checker re-checks that, never the map
    let path = write_sector_certificate(dir.path(), "hoppe5.json", "catmull-clark", &["-n", "5"]);
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert!(doc["parts"].get("sector").is_none());
    assert_eq!(doc["sector_claimed"], "DISPROVED");
    let (code, text) = check_certificate(&path);
    assert_eq!(code, 0, "{text}");
    assert!(text.contains("ACCEPTED (tagged PROVED; sector criterion not re-checked (claimed DISPROVED))"), "{text}");
    assert!(!text.contains("sector criterion PROVED"), "{text}");
    // Hoppe k = 3's sector part grafted onto it: rejected (its eigenvectors
    // are not k = 5's: the blocks rebuilt from k = 5's rows differ)
    let donor = write_sector_certificate(dir.path(), "hoppe3.json", "catmull-clark", &["-n", "3"]);
    let donor: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&donor).unwrap()).unwrap();
    let (code, text) = check_tampered_certificate(dir.path(), "hoppe5.json", &|d| {
        d["parts"]["sector"] = donor["parts"]["sector"].clone();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("REJECTED"), "{text}");
}

#[test]
fn tampered_sector_certificates_are_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    write_sector_certificate(dir.path(), "hoppe3.json", "catmull-clark", &["-n", "3"]);
    let tamper = |edit: &dyn Fn(&mut serde_json::Value)| check_tampered_certificate(dir.path(), "hoppe3.json", edit);
    let rejected = assert_rejected;
    // an eigenvector enclosure shifted: x̃ moved by 10⁻³ in one entry, far
    // outside Y, so Krawczyk's operator leaves the box
    rejected(
        tamper(&|d| {
            let e = &mut d["parts"]["sector"]["eigenvectors"][0];
            let s = e["s"].as_u64().unwrap() as usize;
            let j = if s == 0 { 1 } else { 0 };
            let x = e["x"][j].as_f64().unwrap();
            e["x"][j] = (x + 1e-3).into();
        }),
        "Krawczyk",
        "eigenvector shifted",
    );
    // the eigenvalue claimed in another block's component
    rejected(
        tamper(&|d| d["parts"]["sector"]["eigenvectors"][0]["component"] = 0.into()),
        "the spectral part names",
        "eigenvector of another component",
    );
    // a net point moved: a sharp row's point (normal coordinate exactly 0)
    // made the level-0 face point face[r1,s0,1], strictly inside sector 0,
    // where the normal coordinate (mode 1: sin(π/3) > 0) is not 0
    rejected(
        tamper(&|d| {
            let sector = &mut d["parts"]["sector"];
            let n0 = sector["points"]["level0"].as_u64().unwrap() as usize;
            let face = sector["faces"].as_array().unwrap().iter().find(|f| !f["rows"].as_array().unwrap().is_empty());
            let face = face.unwrap().clone();
            let at = face["rows"][0][1].clone();
            let entry = face["layout"].as_array().unwrap().iter().find(|e| e[0] == at[0] && e[1] == at[1]).unwrap();
            let point = entry[2].as_u64().unwrap() as usize;
            assert!(point >= n0, "the row's point is a refined one");
            let labels = d["parts"]["tagged"]["labels"].as_array().unwrap();
            let inside = labels.iter().position(|l| l == "face[r1,s0,1]").unwrap();
            d["parts"]["sector"]["points"]["stencils"][point - n0] = serde_json::json!([[inside, "1/1"]]);
        }),
        "line",
        "net point moved",
    );
    // a face's Jacobian sign flipped (k = 3 is proved negative)
    rejected(tamper(&|d| d["parts"]["sector"]["faces"][5]["sign"] = "+".into()), "claimed +", "sign flipped");
    // a face dropped from the ring: the chain's windows no longer line up
    rejected(
        tamper(&|d| {
            let arcs = d["parts"]["sector"]["chain"]["arcs"].clone();
            let first = arcs[0].as_u64().unwrap() as usize;
            d["parts"]["sector"]["faces"].as_array_mut().unwrap().remove(first);
        }),
        "chain vertex",
        "face dropped",
    );
    // a ghost point made the mirror of a point off the line
    rejected(
        tamper(&|d| {
            for f in d["parts"]["sector"]["faces"].as_array_mut().unwrap() {
                for e in f["layout"].as_array_mut().unwrap() {
                    if e.as_array().unwrap().len() == 4 {
                        let (b, p) = (e[2].clone(), e[3].clone());
                        e[2] = p;
                        e[3] = b;
                        return;
                    }
                }
            }
        }),
        "ghost",
        "ghost rule altered",
    );
    // a ghost's p made its b (2b − b = b: the window's missing row would be
    // the ray's copy), which is not the point two steps beside it
    rejected(
        tamper(&|d| {
            for f in d["parts"]["sector"]["faces"].as_array_mut().unwrap() {
                for e in f["layout"].as_array_mut().unwrap() {
                    if e.as_array().unwrap().len() == 4 {
                        e[3] = e[2].clone();
                        return;
                    }
                }
            }
        }),
        "is not 2b − p",
        "ghost's p replaced",
    );
    // the winding data altered: the number, and one polygon point mirrored
    rejected(tamper(&|d| d["parts"]["sector"]["chain"]["number"] = 1.into()), "winds", "winding number");
    rejected(
        tamper(&|d| {
            let w = &mut d["parts"]["sector"]["chain"]["polygon"][3];
            let (x, y) = (w[0].as_f64().unwrap(), w[1].as_f64().unwrap());
            *w = serde_json::json!([-x, -y]);
        }),
        "half-plane",
        "polygon point moved",
    );
    // the scheme's rules altered: a wrong weight in S's rows (the boundary
    // vertex rule 3/4, 1/8, 1/8 made 5/8) and in a refinement stencil
    rejected(tamper(&|d| d["parts"]["tagged"]["rows"][0][0][1] = "5/8".into()), "sum to 1", "a row weight");
    rejected(
        tamper(&|d| {
            let st = &mut d["parts"]["sector"]["points"]["stencils"][0][0][1];
            *st = "1/3".into();
        }),
        "do not sum to 1",
        "a stencil weight",
    );
    // the normal coordinate swapped: λ2 = 1/2 is the curve's tangent
    // eigenvalue (odd), so its eigenvector is not shown to vanish
    rejected(tamper(&|d| d["parts"]["sector"]["normal"] = "lambda2".into()), "not shown to vanish", "normal swapped");
    // a verdict word other than PROVED in a sector part
    rejected(
        tamper(&|d| d["parts"]["sector"]["injectivity"] = "NOT PROVED".into()),
        "PROVED sector map only",
        "verdict word",
    );
}

#[test]
fn the_example_registry_writes_sector_documents_the_checker_accepts() {
    if !checker_can_run() {
        return;
    }
    // examples/claims/boundary-blz.toml's certified sector maps, written by
    // one run of the file: Catmull–Clark Hoppe k = 2, 3 and BLZ k = 2..8
    // PROVED (re-derived), Hoppe k = 5..8 DISPROVED (the tagged part only,
    // never a PROVED sector map); Loop Hoppe k = 2..5 and BLZ k = 2..12
    // PROVED (re-derived), Hoppe k = 6 (spectral part DISPROVED) and
    // k = 7..9 (the map DISPROVED) without a sector part
    let dir = tempfile::tempdir().unwrap();
    let claims = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/claims/boundary-blz.toml");
    let out = subdlab(&["verify", "--claims", claims, "--certificates", dir.path().to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let cases = [
        ("cc.boundary.regular.map.certified", 2..=3, "(tagged PROVED, sector criterion PROVED)"),
        ("cc.boundary.blz-map.certified", 2..=8, "(tagged PROVED, sector criterion PROVED)"),
        (
            "cc.boundary.hoppe-collapse.certified",
            5..=8,
            "(tagged PROVED; sector criterion not re-checked (claimed DISPROVED))",
        ),
        ("loop.boundary.hoppe-map.certified", 2..=5, "(tagged PROVED, sector criterion PROVED)"),
        ("loop.boundary.blz-map.certified", 2..=12, "(tagged PROVED, sector criterion PROVED)"),
        (
            "loop.boundary.hoppe-defective.map.certified",
            6..=6,
            "(tagged DISPROVED; sector criterion not re-checked (claimed DISPROVED))",
        ),
        (
            "loop.boundary.hoppe-collapse.certified",
            7..=9,
            "(tagged PROVED; sector criterion not re-checked (claimed DISPROVED))",
        ),
    ];
    for (id, ks, want) in cases {
        for k in ks {
            let (code, text) = check_certificate(&dir.path().join(format!("{id}-n{k}.json")));
            assert_eq!(code, 0, "{id} k = {k}: {text}");
            assert!(text.contains(&format!("CERTIFICATE ACCEPTED {want}")), "{id} k = {k}: {text}");
        }
    }
}
