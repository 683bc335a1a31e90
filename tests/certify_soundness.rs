//! Negative controls for the certificates' soundness (issue 23 §1): each
//! file under `tests/data/certify/` is built so that a proof taking any
//! floating-point decision, or speaking about the wrong neighbourhood, would
//! print PROVED where the statement is false. What each must give comes from
//! the files' own construction (their comments derive the spectra as
//! discrete Fourier transforms of the corner weights), never from output.
//!
//! - `toggle-cc.toml`: the reproducer. Exactly, block 1 holds
//!   31/32 and 11/20 and the λ1 = 31/32 map folds; a float reading that
//!   calls cos(2π/5)/10¹³ zero sees Catmull–Clark. Never PROVED.
//! - `toggle-block2.toml`: exactly, block 2 holds 1/2 above block 1's 2/5;
//!   floats see Doo–Sabin. DISPROVED by the spectrum; no map attempted.
//! - `tie-blocks.toml`: 1/2 in blocks 1, 2, n−2, n−1 (a tie no enclosure
//!   separates). NOT PROVED, or DISPROVED by lemma S7 (multiplicity 4)
//!   where S is rational; never PROVED.
//! - `polar-radial-tie.toml`: polar bi-2 with the radial rule (1 − w, w);
//!   every block m ∉ {0, ±1} is lower triangular with eigenvalues w, 0, 0
//!   (0 defective). At w = 5/8 that w is λ1 (block 1's leading eigenvalue)
//!   and lemma S6 (‖B^k‖^(1/k)) must not separate it: NOT PROVED, naming S6.
//!   At w = 1/2 λ1's own block holds a defective cluster: NOT PROVED. At
//!   n = 6 (S rational) lemma S7 DISPROVES both: λ1 = w is dominant with
//!   multiplicity ≥ n.
//! - `analysis-gap.toml`: Catmull–Clark on the minimal set, an eigenvalue of
//!   modulus 3/4 > λ1 among the analysis neighbourhood's outer points.
//!   Certificates refuse the minimal set; on the analysis set DISPROVED.

use crate::common;

use subdlab::certify::{certify_analysis, certify_charmap, Verdict};
use subdlab::charmap::{check_map, CharMapOptions};
use subdlab::claims::{evaluate, parse_file, Verdict as ClaimVerdict};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Analysis, Options};

fn data(name: &str) -> String {
    format!("{}/tests/data/certify/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn scheme(name: &str) -> Box<dyn Scheme> {
    schemes::resolve(&data(name), &[]).unwrap()
}

fn analysis(scheme: &dyn Scheme, n: usize) -> Analysis {
    let config = Configuration::regular(scheme, n).unwrap();
    analyse(scheme, &config, &Options::default()).unwrap()
}

/// Catmull–Clark's subdominant eigenvalue (Doo–Sabin 1978; Ball–Storry):
/// λ1 = (5 + cos(2π/n) + cos(π/n)·√(2(9 + cos(2π/n)))) / 16.
fn catmull_clark_lambda1(n: usize) -> f64 {
    let c = (2.0 * std::f64::consts::PI / n as f64).cos();
    let h = (std::f64::consts::PI / n as f64).cos();
    (5.0 + c + h * (2.0 * (9.0 + c)).sqrt()) / 16.0
}

#[test]
fn the_toggle_reproducer_is_never_proved_and_its_fold_is_disproved() {
    let s = scheme("toggle-cc.toml");
    for n in [3, 5, 7, 8, 10] {
        let a = analysis(s.as_ref(), n);
        let c = certify_charmap(s.as_ref(), &a, 5).unwrap();
        assert_ne!(c.c1, Verdict::Proved, "n = {n}: a false proof");
        // the spectral certificate is about the exact rules: λ1 = 31/32
        assert_eq!(c.spectrum.verdict, Verdict::Proved, "n = {n}");
        let l1 = c.spectrum.margins.lambda1.expect("λ1 enclosed");
        assert!(l1.lo <= 31.0 / 32.0 && 31.0 / 32.0 <= l1.hi, "n = {n}: λ1 in [{}, {}]", l1.lo, l1.hi);
        if [3, 5, 7].contains(&n) {
            assert!(matches!(&c.regularity, Verdict::Disproved(w) if w.contains("changes sign")), "n = {n}");
            let w = c.fold_witness.as_ref().expect("a fold witness");
            assert!(w.negative_upper_bound < 0.0 && w.positive_lower_bound > 0.0);
            // a second, independent route: the floating-point raster of the
            // same map (the file's float reading is its exact one rounded)
            // finds folded facets too
            let raster = check_map(s.as_ref(), &a, &CharMapOptions::checked(4, 512).unwrap()).unwrap();
            assert!(!raster.regular, "n = {n}: the raster should see the fold");
        }
    }
}

#[test]
fn the_proof_takes_nothing_from_the_floating_point_spectrum() {
    // tamper with the float spectrum the analysis carries: put its λ1 at
    // block 1's other exact eigenvalue 11/20 (where the old certificate
    // looked for its eigenvector) and in other blocks; the certificate must
    // not change
    let s = scheme("toggle-cc.toml");
    let mut tampered = analysis(s.as_ref(), 5);
    let honest = certify_charmap(s.as_ref(), &tampered, 5).unwrap();
    for (value, blocks) in [(11.0 / 20.0, vec![1, 4]), (0.3, vec![2, 3]), (0.99, vec![0])] {
        let e = &mut tampered.spectrum.eigenvalues[1];
        (e.re, e.im, e.modulus, e.blocks) = (value, 0.0, value, blocks.clone());
        let c = certify_charmap(s.as_ref(), &tampered, 5).unwrap();
        assert_eq!(c.c1, honest.c1, "λ1 ≈ {value} in blocks {blocks:?}");
        assert_eq!(c.regularity, honest.regularity);
        assert_eq!(c.eigenvector_radius, honest.eigenvector_radius);
        assert_eq!((c.positive_faces, c.negative_faces), (honest.positive_faces, honest.negative_faces));
    }
    // and a proof stays a proof: Catmull–Clark with its float λ1 moved
    let cc = schemes::build("catmull-clark", &[]).unwrap();
    let mut tampered = analysis(cc.as_ref(), 5);
    tampered.spectrum.eigenvalues[1].blocks = vec![2, 3];
    let c = certify_charmap(cc.as_ref(), &tampered, 4).unwrap();
    assert_eq!(c.c1, Verdict::Proved, "{:?}", c.c1);
    assert_eq!(c.winding_number, Some(1));
}

#[test]
fn a_toggle_that_moves_the_dominant_block_is_disproved_by_the_spectrum() {
    let s = scheme("toggle-block2.toml");
    for n in [5, 6, 7, 9] {
        let a = analysis(s.as_ref(), n);
        let c = certify_charmap(s.as_ref(), &a, 4).unwrap();
        let Verdict::Disproved(why) = &c.spectrum.verdict else {
            panic!("n = {n}: expected DISPROVED, got {:?}", c.spectrum.verdict)
        };
        let w = c.spectrum.witness.as_ref().expect("a witness");
        // the witness is 1/2, from block 2 or n − 2, above block 1's 2/5
        assert!([2, n - 2].contains(&w.block), "n = {n}: {why}");
        assert!(w.component.min_modulus() > 2.0 / 5.0 && w.component.may_hold(faer::c64::new(0.5, 0.0)), "n = {n}");
        assert!(!c.conditional, "n = {n}: every premise is exact");
        assert!(matches!(&c.regularity, Verdict::NotProved(r) if r.contains("not attempted")), "n = {n}");
        assert!(matches!(&c.c1, Verdict::Disproved(_)), "n = {n}");
    }
}

#[test]
fn a_tie_across_blocks_is_never_proved() {
    let s = scheme("tie-blocks.toml");
    for n in [5, 6, 7, 8] {
        let a = analysis(s.as_ref(), n);
        let c = certify_analysis(s.as_ref(), &a).unwrap();
        match (&c.verdict, &c.exact_route) {
            // the enclosures cannot separate block 1 from block 2
            (Verdict::NotProved(w), _) => assert!(w.contains("cannot separate"), "n = {n}: {w}"),
            // where S is rational, lemma S7 counts the multiplicity of 1/2
            // exactly: 4 (the file's derivation), so "λ1 double" is false
            (Verdict::Disproved(_), Some(route)) => {
                assert_eq!(route.lambda1.as_deref(), Some("1/2"), "n = {n}");
                assert_eq!((route.algebraic, route.geometric), (4, 4), "n = {n}")
            }
            (v, _) => panic!("n = {n}: a tie must never be PROVED, got {v:?}"),
        }
        let m = certify_charmap(s.as_ref(), &a, 4).unwrap();
        assert!(!matches!(m.c1, Verdict::Proved), "n = {n}: {:?}", m.c1);
    }
}

#[test]
fn certificates_speak_about_the_analysis_neighbourhood_only() {
    let s = scheme("analysis-gap.toml");
    for n in [5, 7] {
        // the minimal invariant set alone passes Reif's test (floating point):
        // a proof there would hide the outer eigenvalue
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let opts = Options { neighbourhood: NeighbourhoodKind::Minimal, ..Options::default() };
        let minimal = analyse(s.as_ref(), &config, &opts).unwrap();
        assert!(minimal.spectrum.verdict.c1_spectral, "n = {n}");
        let refused = certify_analysis(s.as_ref(), &minimal).unwrap_err().to_string();
        assert!(refused.contains("analysis neighbourhood"), "{refused}");
        // the analysis neighbourhood: disproved, with a witness of modulus
        // at least 3/4, above Catmull–Clark's λ1
        let a = analysis(s.as_ref(), n);
        let c = certify_analysis(s.as_ref(), &a).unwrap();
        assert!(matches!(&c.verdict, Verdict::Disproved(_)), "n = {n}: {:?}", c.verdict);
        let w = c.witness.as_ref().expect("a witness");
        assert!(w.component.min_modulus() > catmull_clark_lambda1(n), "n = {n}: {:?}", w.component);
    }
    let out =
        common::fails(&["spectrum", &data("analysis-gap.toml"), "-n", "5", "--certify", "--neighbourhood", "minimal"]);
    assert!(out.contains("analysis neighbourhood"), "{out}");
    // a certified claim on the minimal set is malformed: ERROR, not a verdict
    let text = "paper = \"t\"\ntitle = \"t\"\n\n[[claim]]\nid = \"c\"\nlocation = \"-\"\nstatement = \"-\"\n\
                check = \"spectral-c1\"\nscheme = \"catmull-clark\"\nvalences = \"5..6\"\nneighbourhood = \"minimal\"\n\
                certified = true\n";
    let o = evaluate(&parse_file("t.toml", text).unwrap()).pop().unwrap();
    assert_eq!(o.verdict, ClaimVerdict::Error, "{}", o.detail);
    assert!(o.detail.contains("analysis neighbourhood"), "{}", o.detail);
}

#[test]
fn a_certified_map_claim_needs_the_spectrum_too() {
    // the twisted edge rule at t = 1/8 (n = 7) has its subdominant pair in
    // blocks 3 and 4: the map of that pair is regular, but there is no
    // characteristic map of a proved λ1, so a certified claim is REFUTED by
    // the spectrum, never HOLDS on regularity and injectivity alone
    let file = format!("{}/schemes/catmull-clark-twisted-edge.toml", env!("CARGO_MANIFEST_DIR"));
    let text = format!(
        "paper = \"t\"\ntitle = \"t\"\n\n[[claim]]\nid = \"c\"\nlocation = \"-\"\nstatement = \"-\"\n\
         check = \"characteristic-map\"\nscheme = \"{file}\"\nparams = {{ t = \"1/8\" }}\nvalences = [7]\ncertified = true\n"
    );
    let o = evaluate(&parse_file("t.toml", &text).unwrap()).pop().unwrap();
    assert_eq!(o.verdict, ClaimVerdict::Refuted, "{} / {} / {}", o.stated, o.computed, o.detail);
    assert!(o.computed.contains("spectrum DISPROVED"), "{}", o.computed);
}

#[test]
fn a_defective_block_at_lambda1_is_never_proved() {
    let file = data("polar-radial-tie.toml");
    for (w, lambda1) in [("5/8", 0.625), ("1/2", 0.5)] {
        let s = schemes::resolve(&file, &[("w".to_string(), w.to_string())]).unwrap();
        for n in [5, 6, 8] {
            let a = analysis(s.as_ref(), n);
            // the independent route (floating point, per the file's
            // derivation): the radial eigenvalue w lies in every Fourier
            // block, so S has λ1 = w with multiplicity at least n, and the
            // statement (λ1 double, every other eigenvalue below it) is false
            let at_lambda1: usize = a
                .spectrum
                .eigenvalues
                .iter()
                .filter(|e| (e.re - lambda1).abs() < 1e-9 && e.im.abs() < 1e-9)
                .map(|e| e.algebraic_multiplicity)
                .sum();
            assert!(at_lambda1 >= n, "w = {w}, n = {n}: {at_lambda1} eigenvalues at {lambda1}");
            let c = certify_analysis(s.as_ref(), &a).unwrap();
            if n == 6 {
                // cos(2π/6) = 1/2: S is rational, and lemma S7 decides exactly:
                // λ1 = w dominant with multiplicity ≥ n, not a double
                // semisimple eigenvalue: DISPROVED, unconditionally
                let Verdict::Disproved(why) = &c.verdict else {
                    panic!("w = {w}, n = 6: expected DISPROVED by lemma S7, got {:?}", c.verdict)
                };
                let route = c.exact_route.as_ref().expect("decided by the exact route");
                assert_eq!(route.lambda1.as_deref(), Some(w), "{why}");
                assert!(route.algebraic >= n, "{route:?}");
                assert!(!c.conditional);
                continue;
            }
            let Verdict::NotProved(why) = &c.verdict else {
                panic!("w = {w}, n = {n}: expected NOT PROVED, got {:?}", c.verdict)
            };
            if w == "5/8" {
                // a block other than 0, 1, n − 1 reaches λ1, and lemma S6 says
                // it cannot bound it below
                assert!(why.contains("lemma S6") && why.contains("may reach λ1"), "n = {n}: {why}");
            } else {
                // λ1's own block: its leading enclosure holds the cluster
                assert!(why.contains("block 1"), "n = {n}: {why}");
            }
        }
    }
}
