//! Certified verdicts at tagged vertices (`spectrum --tag T --certify`,
//! `certify::tagged`): the spectral part of the sector criterion proved,
//! disproved or left open, by the enclosures of the reflection's even and
//! odd blocks (lemma T4) and, where S is rational, exactly (lemma T7).
//!
//! Expected values are derived by hand, never read off the program:
//!
//! - the boundary curve's rows are the cubic B-spline's: 1 (even, the
//!   constant), its tangent 1/2 (odd: the tangent changes sign under the
//!   reflection r ↦ k − r that swaps the two boundary rays) and 1/4;
//! - the interior of a boundary fan of k faces carries the sine modes
//!   sin(jmπ/k) of a closed fan of 2k sectors (`tests/tagged_verdicts.rs`
//!   derives them); mode m has parity (−1)^(m+1) under the reflection (m = 1
//!   even, m = 2 odd). Loop's mode m has the eigenvalue γ + cos(mπ/k)/4;
//!   Catmull–Clark's is the larger eigenvalue of the 2 × 2 mode matrix
//!   M(φ) = [[γ + cos φ/8, cos(φ/2)/8], [cos(φ/2)/2, 1/4]], φ = mπ/k. With
//!   Hoppe's γ = 3/8 its determinant is 3/32 + cos φ/32 − (1 + cos φ)/32 =
//!   1/16 for every φ, so the mode's eigenvalue is
//!   μ(φ) = (t + √(t² − 1/4))/2 with t = 5/8 + cos φ/8;
//!   e.g. μ(π/3) = (11 + √57)/32 and μ(π/2) = (5/8 + 3/8)/2 = 1/2 exactly;
//! - BLZ's γ (`-p blz=1`) puts mode 1 at 1/2 exactly (even), beside the
//!   tangent's 1/2 (odd): λ1 = λ2 = 1/2, one per block, non-defective;
//! - Hoppe's Catmull–Clark at k = 4 has mode 2 at μ(π/2) = 1/2 in the odd
//!   block with the tangent: a Jordan block (`tests/tagged_verdicts.rs`
//!   shows it by exact ranks), under mode 1's μ(π/4) > 1/2, so λ2 = λ3 =
//!   1/2: the statement is false; Loop k = 6 likewise (mode 2:
//!   3/8 + cos(π/3)/4 = 1/2); Catmull–Clark k = 1 has the curve's 1/4 and
//!   the interior's 1/4 in one Jordan block under the tangent's 1/2;
//! - a crease:K vertex of n faces: the sine modes of each side vanish on
//!   both sharp rays and see only their own side, so each side of k faces
//!   contributes a boundary fan's modes; the crease curve's tangent 1/2;
//! - a dart at valence 4 (Catmull–Clark) or 6 (Loop) is a regular vertex
//!   whose rules (the smooth ones, and the midpoint on the sharp ray)
//!   reproduce linear functions on the regular grid: the coordinates x and
//!   y are eigenvectors of 1/2, so 1/2 is (at least) double with two
//!   eigenvectors.
//!
//! The floating-point `sector` verdict is a third, independent route: every
//! PROVED must be its PASSES, every DISPROVED its FAILS.

use crate::common;
use common::{check_certificate, check_tampered_certificate, checker_can_run, subdlab, write_spectrum_certificate};
use subdlab::certify::tagged::{certify_tagged, TaggedCertificate};
use subdlab::certify::Verdict;
use subdlab::neighbourhood::{Configuration, Tagging};
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Options};

use std::f64::consts::PI;

fn certify(name: &str, params: &[(&str, &str)], n: usize, tag: &str) -> (TaggedCertificate, bool) {
    let params: Vec<(String, String)> = params.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
    let scheme: Box<dyn Scheme> = schemes::build(name, &params).unwrap();
    let config = Configuration::tagged(scheme.as_ref(), n, None, Tagging::parse(tag).unwrap()).unwrap();
    let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
    let cert = certify_tagged(scheme.as_ref(), &analysis).unwrap();
    (cert, analysis.spectrum.verdict.c1_spectral)
}

/// Catmull–Clark's mode eigenvalue with Hoppe's γ (see the module doc).
fn mu(phi: f64) -> f64 {
    let t = 5.0 / 8.0 + phi.cos() / 8.0;
    (t + (t * t - 0.25).sqrt()) / 2.0
}

/// The enclosure of λ1 or λ2 holds x (the closed form, from the C library's
/// cos and sqrt, widened by 1e-13 for their rounding).
fn holds(cert: &TaggedCertificate, which: usize, x: f64) -> bool {
    let r = &cert.enclosure_route;
    let named = if which == 1 { &r.lambda1 } else { &r.lambda2 };
    let e = named.as_ref().expect("a proved enclosure route names λ1 and λ2").enclosure;
    e.lo <= x + 1e-13 && x - 1e-13 <= e.hi
}

fn block_of(cert: &TaggedCertificate, which: usize) -> &'static str {
    let r = &cert.enclosure_route;
    let named = if which == 1 { &r.lambda1 } else { &r.lambda2 };
    named.as_ref().unwrap().block
}

fn assert_proved(cert: &TaggedCertificate, what: &str) {
    assert_eq!(cert.verdict, Verdict::Proved, "{what}: {:?}", cert.verdict);
    assert!(!cert.conditional, "{what}: the premises are exact");
}

#[test]
fn regular_boundaries_are_proved_by_both_routes() {
    // Catmull–Clark k = 2: the tangent's 1/2 (odd) and mode 1's μ(π/2) = 1/2 (even)
    let (c, passes) = certify("catmull-clark", &[], 2, "boundary");
    assert_proved(&c, "CC k = 2");
    assert!(passes);
    assert_eq!(c.decided_by, Some("both"));
    assert!(holds(&c, 1, 0.5) && holds(&c, 2, 0.5));
    let mut blocks = [block_of(&c, 1), block_of(&c, 2)];
    blocks.sort();
    assert_eq!(blocks, ["even", "odd"]);
    let exact = c.exact_route.as_ref().unwrap();
    assert_eq!((exact.r.as_deref(), exact.algebraic, exact.geometric, exact.above), (Some("1/2"), 2, 2, 0));
    // Catmull–Clark k = 3: λ1 = μ(π/3) = (11 + √57)/32 even, λ2 = 1/2 odd;
    // the exact route from r = 1/2: simple, one eigenvalue above it
    let (c, passes) = certify("catmull-clark", &[], 3, "boundary");
    assert_proved(&c, "CC k = 3");
    assert!(passes);
    assert_eq!(c.decided_by, Some("both"));
    assert!((mu(PI / 3.0) - (11.0 + 57f64.sqrt()) / 32.0).abs() < 1e-15);
    assert!(holds(&c, 1, (11.0 + 57f64.sqrt()) / 32.0) && block_of(&c, 1) == "even");
    assert!(holds(&c, 2, 0.5) && block_of(&c, 2) == "odd");
    let exact = c.exact_route.as_ref().unwrap();
    assert_eq!((exact.r.as_deref(), exact.algebraic, exact.above), (Some("1/2"), 1, 1));
    // Loop k = 3 (regular) and 4: mode 1 = 3/8 + cos(π/k)/4 even, 1/2 odd
    for k in [3usize, 4, 5] {
        let (c, passes) = certify("loop", &[], k, "boundary");
        assert_proved(&c, &format!("Loop k = {k}"));
        assert!(passes);
        let mode1 = 3.0 / 8.0 + (PI / k as f64).cos() / 4.0;
        assert!(holds(&c, 1, mode1.max(0.5)) && holds(&c, 2, mode1.min(0.5)), "Loop k = {k}");
    }
    // Catmull–Clark k = 5..8 (Hoppe): modes 1 and 2 above the curve's 1/2
    // (the spectral part passes; the map collapses, `charmap --tag`)
    for k in 5usize..=8 {
        let (c, passes) = certify("catmull-clark", &[], k, "boundary");
        assert_proved(&c, &format!("CC k = {k}"));
        assert!(passes);
        let kf = k as f64;
        assert!(holds(&c, 1, mu(PI / kf)) && block_of(&c, 1) == "even", "CC k = {k}");
        assert!(holds(&c, 2, mu(2.0 * PI / kf)) && block_of(&c, 2) == "odd", "CC k = {k}");
    }
}

#[test]
fn blz_rules_are_proved_with_irrational_weights() {
    // γ = 3/8 − cos(π/k)/4 (Catmull–Clark), 1/2 − cos(π/k)/4 (Loop): in
    // Q(ζ_2k) for k ≥ 4, enclosed; the exact route does not apply
    for name in ["catmull-clark", "loop"] {
        for k in [4usize, 5, 6, 7, 8, 12] {
            let (c, passes) = certify(name, &[("blz", "1")], k, "boundary");
            let what = format!("{name} blz k = {k}");
            assert_proved(&c, &what);
            assert!(passes, "{what}");
            assert_eq!(c.decided_by, Some("enclosures"), "{what}");
            assert!(c.exact_route.is_none() && c.exact_route_skipped.as_deref().unwrap().contains("irrational"));
            assert!(c.premises.field.as_deref().unwrap().starts_with("Q(ζ_"), "{what}");
            assert!(holds(&c, 1, 0.5) && holds(&c, 2, 0.5), "{what}");
            let mut blocks = [block_of(&c, 1), block_of(&c, 2)];
            blocks.sort();
            assert_eq!(blocks, ["even", "odd"], "{what}");
        }
    }
}

#[test]
fn negative_controls_are_disproved_exactly() {
    // Hoppe's Catmull–Clark k = 4 and Loop k = 6: mode 2 at 1/2 in the odd
    // block with the tangent (a Jordan block), mode 1 above: λ2 = λ3 = 1/2
    for (name, k) in [("catmull-clark", 4usize), ("loop", 6)] {
        let (c, passes) = certify(name, &[], k, "boundary");
        assert!(matches!(&c.verdict, Verdict::Disproved(w) if w.contains("defective")), "{name} {k}: {:?}", c.verdict);
        assert!(!passes);
        assert_eq!(c.decided_by, Some("exact"));
        // the enclosures cannot separate a Jordan block: NOT PROVED there
        assert!(matches!(c.enclosure_route.verdict, Verdict::NotProved(_)));
        let e = c.exact_route.as_ref().unwrap();
        assert_eq!((e.r.as_deref(), e.algebraic, e.geometric, e.above), (Some("1/2"), 2, 1, 1), "{name} {k}");
    }
    // Catmull–Clark k = 1: 1/4 twice in one Jordan block under the tangent's 1/2
    let (c, passes) = certify("catmull-clark", &[], 1, "boundary");
    assert!(matches!(c.verdict, Verdict::Disproved(_)), "{:?}", c.verdict);
    assert!(!passes);
    let e = c.exact_route.as_ref().unwrap();
    assert_eq!((e.r.as_deref(), e.algebraic, e.geometric, e.above), (Some("1/4"), 2, 1, 1));
    // the regular crease (Catmull–Clark n = 4, crease:2): the tangent and
    // each side's mode 1 (k = 2: μ(π/2) = 1/2): 1/2 three times in S whole,
    // |λ3| = λ2 — S whole's verdict, kept beside the crease's per-side one
    // (PROVED: tests/crease_sides.rs)
    let (c, passes) = certify("catmull-clark", &[], 4, "crease:2");
    let whole = &c.crease.as_ref().unwrap().whole_verdict;
    assert!(matches!(whole, Verdict::Disproved(_)), "{whole:?}");
    assert!(passes, "per side");
    assert_eq!(c.exact_route.as_ref().unwrap().algebraic, 3);
}

#[test]
fn creases_and_darts_are_proved() {
    // crease:3 at n = 7 (sides of 3 and 4 faces): λ1 = μ(π/4) (side 4's
    // mode 1), λ2 = μ(π/3) (side 3's), the tangent's 1/2 and side 4's mode
    // 2 (μ(π/2) = 1/2) below
    // below. That is S whole's verdict; per side, side B is the boundary fan
    // of 4 faces, whose mode 2 and tangent make a Jordan block at 1/2: the
    // crease's verdict is DISPROVED, naming side B (tests/crease_sides.rs)
    let (c, passes) = certify("catmull-clark", &[], 7, "crease:3");
    assert_eq!(c.crease.as_ref().unwrap().whole_verdict, Verdict::Proved);
    assert!(matches!(&c.verdict, Verdict::Disproved(w) if w.starts_with("side B")), "{:?}", c.verdict);
    assert!(!passes);
    assert!(holds(&c, 1, mu(PI / 4.0)) && holds(&c, 2, mu(PI / 3.0)));
    // Loop crease:4 at n = 9 (sides 4 and 5): 3/8 + cos(π/5)/4 and 3/8 + cos(π/4)/4
    let (c, passes) = certify("loop", &[], 9, "crease:4");
    assert_proved(&c, "Loop crease:4 n = 9");
    assert!(passes);
    assert!(holds(&c, 1, 3.0 / 8.0 + (PI / 5.0).cos() / 4.0) && holds(&c, 2, 3.0 / 8.0 + (PI / 4.0).cos() / 4.0));
    // darts at the regular valence: x and y are eigenvectors of 1/2
    for (name, n) in [("catmull-clark", 4usize), ("loop", 6)] {
        let (c, passes) = certify(name, &[], n, "dart");
        assert_proved(&c, &format!("{name} dart n = {n}"));
        assert!(passes);
        assert_eq!(c.decided_by, Some("both"));
        assert!(holds(&c, 1, 0.5) && holds(&c, 2, 0.5));
    }
}

/// The float verdict as an independent route: over the boundary fans and
/// parameters the registered claims speak about, a PROVED is a PASSES and
/// a DISPROVED a FAILS, and nothing is left undecided.
#[test]
fn every_boundary_verdict_agrees_with_the_floating_point_route() {
    for name in ["catmull-clark", "loop"] {
        for blz in [false, true] {
            for k in 1usize..=8 {
                let params: &[(&str, &str)] = if blz { &[("blz", "1")] } else { &[] };
                let (c, passes) = certify(name, params, k, "boundary");
                let what = format!("{name} blz={blz} k = {k}: {:?}", c.verdict);
                match c.verdict {
                    Verdict::Proved => assert!(passes, "{what}"),
                    Verdict::Disproved(_) => assert!(!passes, "{what}"),
                    Verdict::NotProved(_) => panic!("undecided: {what}"),
                }
            }
        }
    }
}

#[test]
fn the_command_line_exits_and_speaks_json_like_the_interior_certificate() {
    let out = subdlab(&["spectrum", "catmull-clark", "-n", "3", "--tag", "boundary", "--certify", "--json"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let cert = &v["certificate"];
    assert_eq!(cert["verdict"], "proved");
    assert_eq!(cert["decided_by"], "both");
    assert_eq!(cert["premises"]["field"], "Q");
    assert_eq!(cert["blocks"].as_array().unwrap().len(), 2);
    assert!(v["eigenvalues"].is_array(), "the spectrum is flattened beside the certificate");
    // a disproof exits 1 and says why
    let out = subdlab(&["spectrum", "catmull-clark", "-n", "4", "--tag", "boundary", "--certify"]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("certified sector criterion, spectral part: DISPROVED"), "{text}");
    assert!(text.contains("exact route (lemma T7)"));
    // bad input: one line, exit 2
    for args in [
        &["spectrum", "catmull-clark", "-n", "4", "--tag", "crease:9", "--certify"][..],
        &["spectrum", "catmull-clark", "-n", "3", "--tag", "boundary", "--certify", "--neighbourhood", "minimal"],
    ] {
        let out = subdlab(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("error:"), "{err}");
    }
}

/// The certificate document (`--certificate FILE`) re-checked by the
/// independent `scripts/check_cert.py` (its own exact rows, reflection
/// blocks, ball arithmetic, characteristic polynomials by interpolation and
/// counting Schur–Cohn): accepted as written, rejected when tampered with.
#[test]
fn the_independent_checker_accepts_tagged_certificates_and_rejects_tampered_ones() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let check = check_certificate;
    let write = |file: &str, args: &[&str]| write_spectrum_certificate(dir.path(), file, args);
    let cases = [
        ("cc3.json", &["catmull-clark", "-n", "3", "--tag", "boundary"][..], "ACCEPTED (PROVED)"),
        ("cc4.json", &["catmull-clark", "-n", "4", "--tag", "boundary"][..], "ACCEPTED (DISPROVED)"),
        ("loop6.json", &["loop", "-n", "6", "--tag", "boundary"][..], "ACCEPTED (DISPROVED)"),
        ("blz5.json", &["catmull-clark", "-n", "5", "--tag", "boundary", "-p", "blz=1"][..], "ACCEPTED (PROVED)"),
        ("crease.json", &["catmull-clark", "-n", "7", "--tag", "crease:3"][..], "ACCEPTED (DISPROVED)"),
        ("dart.json", &["loop", "-n", "6", "--tag", "dart"][..], "ACCEPTED (PROVED)"),
    ];
    for (name, args, want) in cases {
        let path = write(name, args);
        let (code, text) = check(&path);
        assert_eq!(code, 0, "{name}: {text}");
        assert!(text.contains(want), "{name}: {text}");
    }
    let tamper = |file: &str, edit: &dyn Fn(&mut serde_json::Value)| check_tampered_certificate(dir.path(), file, edit);
    // the disproof claimed as a proof: the checker's own exact route says DISPROVED
    let (code, text) = tamper("cc4.json", &|d| {
        let t = &mut d["parts"]["tagged"];
        t["verdict"] = "PROVED".into();
        t["claims"]["exact_route"]["verdict"] = "PROVED".into();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("REJECTED"), "{text}");
    // λ2's disc shrunk below its Gershgorin bound
    let (code, text) = tamper("blz5.json", &|d| {
        let t = &mut d["parts"]["tagged"];
        let (b, c) =
            (t["claims"]["lambda2"]["block"].as_u64().unwrap(), t["claims"]["lambda2"]["component"].as_u64().unwrap());
        let disc = t["blocks"][b as usize]["components"][c as usize]["discs"][0].as_u64().unwrap();
        let r = t["blocks"][b as usize]["discs"][disc as usize][2].as_f64().unwrap();
        t["blocks"][b as usize]["discs"][disc as usize][2] = (r / 1e6).into();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("Gershgorin"), "{text}");
    // a weight of S changed: the rows no longer sum to 1
    let (code, text) = tamper("cc3.json", &|d| {
        d["parts"]["tagged"]["rows"][0][0][1] = "1/3".into();
    });
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("REJECTED"), "{text}");
}

/// Lemma T4's two disproofs, made by the enclosures alone and re-derived by
/// the independent checker from its own discs. Loop's file with the
/// boundary vertex rule (a, 1 − 2a, a) along the boundary: the boundary
/// curve is refined by its own rules (the vertex rule and the midpoint), so
/// on (v₋₁, v₀, v₁) the matrix [[1/2, 1/2, 0], [a, 1 − 2a, a], [0, 1/2, 1/2]]
/// gives eigenvalues of S: 1, 1/2 (odd) and its trace minus both,
/// 2 − 2a − 3/2 = 1/2 − 2a (even). a = 1: −3/2, outside the unit disc.
/// a = 9/16: −5/8, above every other eigenvalue in modulus — the interior's
/// sine modes at k = 25 are 3/8 + cos(mπ/25)/4 ≤ 3/8 + cos(π/25)/4 < 0.6231
/// (they vanish on the boundary rays, so the changed vertex rule does not
/// reach them) and the tangent 1/2 — so λ1 is negative. At k = 25 S has 78
/// points, above the 64 the exact route re-decides once the enclosures have
/// decided, so the document carries the enclosures' disproof alone; at
/// k = 3 the exact route (lemma T7) runs and disproves the same rules, a
/// second route.
#[test]
fn enclosure_disproofs_are_rechecked_by_the_independent_checker() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let loop_file = std::fs::read_to_string(format!("{}/schemes/loop.toml", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let cases =
        [("outside", "1", "-1", "outside the closed unit disc"), ("negative", "9/16", "-1/8", "real and negative")];
    for (name, a, centre, why) in cases {
        let rules = loop_file.replace(
            "[vertex-crease]\ncentre = \"3/4\"\ncrease = \"1/8\"",
            &format!("[vertex-crease]\ncentre = \"{centre}\"\ncrease = \"{a}\""),
        );
        assert_ne!(rules, loop_file, "the boundary vertex rule of schemes/loop.toml moved");
        let scheme = dir.path().join(format!("{name}.toml"));
        std::fs::write(&scheme, rules).unwrap();
        let scheme = scheme.to_str().unwrap();
        let path =
            write_spectrum_certificate(dir.path(), &format!("{name}.json"), &[scheme, "-n", "25", "--tag", "boundary"]);
        let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let t = &doc["parts"]["tagged"];
        assert_eq!(t["verdict"], "DISPROVED", "{name}: {t}");
        assert_eq!(t["decided_by"], "enclosures", "{name}: the exact route should not have run");
        assert_eq!(t["claims"]["enclosures"], "DISPROVED", "{name}");
        let (code, text) = check_certificate(&path);
        assert_eq!(code, 0, "{name}: {text}");
        assert!(text.contains("ACCEPTED (DISPROVED)") && text.contains(why), "{name}: {text}");
        // the second route: the same rules at k = 3, disproved exactly
        let small = write_spectrum_certificate(
            dir.path(),
            &format!("{name}-3.json"),
            &[scheme, "-n", "3", "--tag", "boundary"],
        );
        let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&small).unwrap()).unwrap();
        assert_eq!(doc["parts"]["tagged"]["claims"]["exact_route"]["verdict"], "DISPROVED", "{name} at k = 3");
    }
    // negative control: a proved boundary (Loop's own rules) presented as an
    // enclosure disproof; the checker finds none on the discs
    write_spectrum_certificate(dir.path(), "proved.json", &["loop", "-n", "25", "--tag", "boundary"]);
    let (code, text) = check_certificate(&dir.path().join("proved.json"));
    assert!(code == 0 && text.contains("ACCEPTED (PROVED)"), "{text}");
    common::assert_rejected(
        check_tampered_certificate(dir.path(), "proved.json", &|d| {
            let t = &mut d["parts"]["tagged"];
            t["verdict"] = "DISPROVED".into();
            t["claims"]["enclosures"] = "DISPROVED".into();
        }),
        "no disproof of lemma T4",
        "a proof relabelled as an enclosure disproof",
    );
}
