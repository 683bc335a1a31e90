//! Certified spectral verdicts (`spectrum --certify`, `certify::spectrum`).
//!
//! Expected values come from the literature and from the schemes' designs,
//! never from program output:
//! - Catmull–Clark: λ1 = (5 + c + cos(π/n)·√(18 + 2c))/16, c = cos(2π/n)
//!   (the largest eigenvalue of Fourier block 1; Doo & Sabin 1978, Ball &
//!   Storry 1988); every weight is rational, so the premises are exact;
//! - Loop: λ1 = 3/8 + cos(2π/n)/4 (block 1 of the edge rule; Loop 1987); the
//!   rows off the centre are rational at every valence (3/8, 1/8 and the
//!   regular vertex's β(6) = 1/16), the centre's only at n ∈ {3, 4, 6}, and
//!   elsewhere in Q(ζ_n), where cos(2π/n) = (ζ_n + ζ_n^{−1})/2 is exact: the
//!   premises are exact at every valence;
//! - Doo–Sabin: λ1 = 1/2 at every valence (Doo & Sabin 1978); its ring-0
//!   weights (3 + 2cos(2πj/n))/(4n) lie in Q(ζ_n) (in Q at n ∈ {3, 4, 6});
//! - `schemes/loop-block2-dominant.toml`: by design block 2 carries 1/2 and
//!   block 1 at most 1/4 at valence 4.
//!
//! The closed forms are enclosed from the C library's cos and sqrt, widened
//! by a few ulps (a route independent of the certificate's own Taylor
//! enclosures of cos(2πk/n)).

use crate::common;
use common::subdlab;
use subdlab::certify::matrix::Check;
use subdlab::certify::{certify_spectrum, SpectrumCertificate, Verdict};
use subdlab::neighbourhood::Configuration;
use subdlab::numeric::Interval;
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Options};

use std::f64::consts::PI;

fn certificate_of(scheme: &dyn Scheme, n: usize) -> SpectrumCertificate {
    let config = Configuration::regular(scheme, n).unwrap();
    let analysis = analyse(scheme, &config, &Options::default()).unwrap();
    certify_spectrum(scheme, &analysis, config.symmetry_period()).unwrap()
}

fn builtin(name: &str, n: usize) -> SpectrumCertificate {
    certificate_of(schemes::build(name, &[]).unwrap().as_ref(), n)
}

fn file(rel: &str, n: usize) -> SpectrumCertificate {
    let path = format!("{}/{rel}", env!("CARGO_MANIFEST_DIR"));
    certificate_of(schemes::resolve(&path, &[]).unwrap().as_ref(), n)
}

/// A value from the C library (cos, sqrt: within an ulp or two), widened by 4 ulps.
fn libm(x: f64) -> Interval {
    let (mut lo, mut hi) = (x, x);
    for _ in 0..4 {
        lo = lo.next_down();
        hi = hi.next_up();
    }
    Interval::new(lo, hi)
}

fn lambda1(c: &SpectrumCertificate) -> Interval {
    let l = c.margins.lambda1.expect("a proved certificate encloses λ1");
    Interval::new(l.lo, l.hi)
}

fn assert_proved(c: &SpectrumCertificate, what: &str) {
    assert_eq!(c.verdict, Verdict::Proved, "{what}: {:?}", c.verdict);
    let gap = c.margins.gap_lower_bound.unwrap();
    assert!(gap > 0.0, "{what}: gap {gap}");
    let l0 = c.margins.lambda0.unwrap();
    assert!(l0.lo <= 1.0 && 1.0 <= l0.hi, "{what}: λ0 enclosure misses 1");
    assert!(lambda1(c).hi < l0.lo, "{what}: λ1 not below λ0");
}

#[test]
fn catmull_clark_is_proved_for_valences_3_to_50_with_the_closed_form_enclosed() {
    for n in 3..=50 {
        let c = builtin("catmull-clark", n);
        let what = format!("catmull-clark n = {n}");
        assert_proved(&c, &what);
        let cos2 = libm((2.0 * PI / n as f64).cos());
        let cos1 = libm((PI / n as f64).cos());
        let root = Interval::point(18.0) + Interval::point(2.0) * cos2;
        let root = libm(root.mid()).hull(&root.sqrt());
        let closed = (Interval::point(5.0) + cos2 + cos1 * root) / Interval::point(16.0);
        assert!(lambda1(&c).overlaps(&closed), "{what}: λ1 ∈ {:?}, closed form {:?}", lambda1(&c), closed);
        assert!(lambda1(&c).width() < 1e-12, "{what}: λ1 enclosure too wide");
        // every weight is rational: both premises hold exactly
        let p = c.premises.as_ref().unwrap();
        assert!(p.exact && !c.conditional, "{what}: {p:?}");
    }
}

#[test]
fn loop_is_proved_for_valences_3_to_50_with_the_closed_form_enclosed() {
    for n in 3..=50 {
        let c = builtin("loop", n);
        let what = format!("loop n = {n}");
        assert_proved(&c, &what);
        let closed = Interval::ratio(3, 8) + libm((2.0 * PI / n as f64).cos()) / Interval::point(4.0);
        assert!(lambda1(&c).overlaps(&closed), "{what}: λ1 ∈ {:?}, closed form {:?}", lambda1(&c), closed);
        assert_exact_in_the_cyclotomic_field(&c, n, &what);
    }
}

/// Every premise exact and the proof unconditional, in Q where cos(2π/n) is
/// rational (n ∈ {3, 4, 6}), else in Q(ζ_n).
fn assert_exact_in_the_cyclotomic_field(c: &SpectrumCertificate, n: usize, what: &str) {
    let p = c.premises.as_ref().unwrap();
    for check in [&p.row_sums_one, &p.mirror_symmetry, &p.rotation_symmetry] {
        assert_eq!(*check, Check::Exact, "{what}: {p:?}");
    }
    assert!(p.exact && !c.conditional, "{what}");
    let field = if matches!(n, 3 | 4 | 6) { "Q".to_string() } else { format!("Q(ζ_{n})") };
    assert_eq!(p.field.as_deref(), Some(field.as_str()), "{what}");
}

#[test]
fn doo_sabin_is_proved_for_valences_3_to_50_with_one_half_enclosed() {
    for n in 3..=50 {
        let c = builtin("doo-sabin", n);
        let what = format!("doo-sabin n = {n}");
        assert_proved(&c, &what);
        assert!(lambda1(&c).contains(0.5), "{what}: λ1 ∈ {:?}", lambda1(&c));
        // the ring-0 weights (3 + 2cos(2πj/n))/(4n) are exact in Q(ζ_n)
        assert_exact_in_the_cyclotomic_field(&c, n, &what);
    }
}

#[test]
fn the_block_2_dominant_loop_variant_is_disproved_with_its_witness() {
    let c = file("schemes/loop-block2-dominant.toml", 4);
    assert!(matches!(c.verdict, Verdict::Disproved(_)), "{:?}", c.verdict);
    let w = c.witness.as_ref().expect("a disproof names its witness");
    assert_eq!(w.block, 2);
    // the witness encloses the designed 1/2, and beats everything in block 1 (≤ 1/4 by design)
    assert!(w.component.may_hold(faer::c64::new(0.5, 0.0)));
    assert!(w.component.min_modulus() > 0.25);
    let block1 = c.blocks.iter().find(|b| b.block == 1).unwrap();
    let block1_max = block1.components.iter().map(|k| k.max_modulus()).fold(0.0, f64::max);
    assert!(block1_max < w.component.min_modulus());
    assert!(block1.components.iter().any(|k| k.may_hold(faer::c64::new(0.25, 0.0))));
}

/// A Loop scheme file whose β uses √2 in place of cos(2π/n): a weight known
/// in floating point only (neither rational nor in a cyclotomic field as the
/// expression evaluator sees it).
fn float_only_loop(dir: &std::path::Path) -> String {
    let path = dir.join("loop-root-two.toml");
    std::fs::write(
        &path,
        "name = \"loop-root-two\"\ntopology = \"primal-triangle\"\n\n[vertex]\n\
         centre = \"3/8 + (3/8 + sqrt(2) / 8)^2\"\nedge = \"(5/8 - (3/8 + sqrt(2) / 8)^2) / n\"\n\n\
         [edge]\nends = \"3/8\"\nopposite = \"1/8\"\n",
    )
    .unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn float_only_weights_are_not_proved_and_say_why() {
    let dir = tempfile::tempdir().unwrap();
    let path = float_only_loop(dir.path());
    let c = certificate_of(schemes::resolve(&path, &[]).unwrap().as_ref(), 5);
    match &c.verdict {
        Verdict::NotProved(why) => assert!(why.starts_with("numerical only"), "{why}"),
        v => panic!("{v:?}"),
    }
}

#[test]
fn fourier_designed_files_are_decided_where_their_weights_hold_irrational_cosines() {
    // at valence 5 the designed edge weights Σ_m μ(m) cos(2πjm/5)/5 are
    // elements of Q(ζ_5): enclosed, and the premises exact
    let c = file("schemes/loop-fourier-edge.toml", 5);
    assert_proved(&c, "loop-fourier-edge n = 5");
    // μ(1) = 1/2 by design
    assert!(lambda1(&c).contains(0.5), "{:?}", lambda1(&c));
    assert_exact_in_the_cyclotomic_field(&c, 5, "loop-fourier-edge n = 5");
    // block 2 (and its conjugate block 3) carries 1/2 by design, block 1 1/4
    let c = file("schemes/loop-block2-dominant.toml", 5);
    assert!(matches!(c.verdict, Verdict::Disproved(_)), "{:?}", c.verdict);
    let w = c.witness.as_ref().unwrap();
    assert!(w.block == 2 || w.block == 3, "{}", w.block);
    assert!(w.component.may_hold(faer::c64::new(0.5, 0.0)));
    assert!(c.premises.as_ref().unwrap().exact);
}

/// Without a rotation of order ≥ 3 the blocks cannot split λ1's pair. With
/// rational weights (the transition node QQTTT) lemma S7 proves it from the
/// exact characteristic polynomial, with λ1 = 1/2 (Peters–Shiue's S_43:
/// leading eigenvalues 1, 1/2, 1/2, 1/4); with cos(2π/5) in the eon rules
/// (QQTQT) neither route applies, and the reason says so.
#[test]
fn a_configuration_without_rotation_symmetry_is_proved_exactly_or_not_proved_with_the_reason() {
    let certificate = |faces: &str| {
        let out = subdlab(&["spectrum", "four-three", "-n", "5", "--faces", faces, "--certify", "--json"]);
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        // the exit status follows the verdict: 0 proved, 1 not proved
        let proved = v["certificate"]["verdict"] == "proved";
        assert_eq!(out.status.code(), Some(if proved { 0 } else { 1 }), "{faces}");
        v["certificate"].clone()
    };
    let node = certificate("QQTTT");
    assert_eq!(node["verdict"], "proved", "{node}");
    assert_eq!(node["exact_route"]["lambda1"], "1/2", "{node}");
    let eon = certificate("QQTQT");
    assert_eq!(eon["verdict"], "not_proved");
    let reason = eon["reason"].as_str().unwrap();
    assert!(reason.contains("no rotation symmetry") && reason.contains("irrational"), "{reason}");
}

#[test]
fn json_carries_the_verdict_and_margins() {
    let out = subdlab(&["spectrum", "catmull-clark", "-n", "5", "--certify", "--json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    // the usual spectrum fields stay, the certificate comes beside them
    assert_eq!(v["scheme"], "catmull-clark");
    let cert = &v["certificate"];
    assert_eq!(cert["verdict"], "proved");
    assert_eq!(cert["conditional"], false);
    assert_eq!(cert["premises"]["row_sums_one"]["status"], "exact");
    let m = &cert["margins"];
    let (lo, hi) = (m["lambda1"]["lo"].as_f64().unwrap(), m["lambda1"]["hi"].as_f64().unwrap());
    // Catmull–Clark at n = 5: (5 + cos 72° + cos 36° √(18 + 2 cos 72°))/16 = 0.5499883545...
    assert!(lo <= 0.549_988_354_52 && 0.549_988_354_51 <= hi);
    assert!(m["gap_lower_bound"].as_f64().unwrap() > 0.0);
    assert_eq!(cert["blocks"].as_array().unwrap().len(), 5);
}

#[test]
fn certify_refuses_curve_schemes_in_one_line() {
    // lattice schemes are certified by the exact route (tests/cli.rs)
    for args in [&["spectrum", "four-point", "-n", "2", "--certify"][..]] {
        let out = subdlab(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains("--certify covers mesh schemes only"), "{err}");
    }
}

#[test]
fn the_chiral_loop_variant_is_disproved_and_its_mirror_premise_fails() {
    // by design block 1 carries 1/2 + i/8 at valence 4 (schemes/loop-chiral-edge.toml)
    let c = file("schemes/loop-chiral-edge.toml", 4);
    match &c.verdict {
        Verdict::Disproved(why) => assert!(why.contains("not real"), "{why}"),
        v => panic!("{v:?}"),
    }
    let w = c.witness.as_ref().unwrap();
    assert_eq!(w.block, 1);
    assert!(w.component.may_hold(faer::c64::new(0.5, 0.125)));
    assert!(!w.component.meets_real_axis());
    // the negative control of the mirror check: this S has no mirror symmetry
    let p = c.premises.as_ref().unwrap();
    assert!(matches!(p.mirror_symmetry, Check::Fails(_)), "{:?}", p.mirror_symmetry);
    assert_eq!(p.rotation_symmetry, Check::Exact);
    assert_eq!(p.row_sums_one, Check::Exact);
}

/// `certified = true` on a `spectral-c1` claim: the claim asks for a proof.
/// Catmull–Clark's rows are rational (its weights need no cosine), so the
/// premises are exact and the certificate proves Reif's conditions (its
/// blocks' closed forms, above): HOLDS. Loop's rows at n = 5 hold cos(2π/5),
/// exact in Q(ζ_5): HOLDS too, as at n = 3, 4, 6 where they are rational. A
/// Loop file whose β holds √2 has a weight known in floating point only: no
/// proof, INCONCLUSIVE with the certificate's reason. The block-2-dominant
/// Loop variant is disproved: a claim that it is C¹ is REFUTED, and the
/// opposite claim (`expect = false`) HOLDS.
#[test]
fn claims_can_demand_a_certified_verdict() {
    use subdlab::claims::{evaluate, parse_file, Verdict};
    let run = |body: &str| {
        let text = format!(
            "paper = \"t\"\ntitle = \"t\"\n\n[[claim]]\nid = \"c\"\nlocation = \"-\"\nstatement = \"-\"\ncheck = \"spectral-c1\"\ncertified = true\n{body}"
        );
        evaluate(&parse_file("t.toml", &text).unwrap()).pop().unwrap()
    };
    let o = run("scheme = \"catmull-clark\"\nvalences = \"3..8\"");
    assert_eq!(o.verdict, Verdict::Holds, "{}", o.detail);
    assert!(o.computed.contains("certified PROVED"), "{}", o.computed);
    assert_eq!(run("scheme = \"loop\"\nvalences = [3, 4, 6]").verdict, Verdict::Holds);
    let o = run("scheme = \"loop\"\nvalences = [5, 7]");
    assert_eq!(o.verdict, Verdict::Holds, "{}", o.detail);
    let dir = tempfile::tempdir().unwrap();
    let o = run(&format!("scheme = \"{}\"\nvalences = [5]", float_only_loop(dir.path())));
    assert_eq!(o.verdict, Verdict::Inconclusive, "{}", o.detail);
    assert!(o.detail.contains("NOT PROVED (numerical only"), "{}", o.detail);
    let wrong = format!("{}/schemes/loop-block2-dominant.toml", env!("CARGO_MANIFEST_DIR"));
    let o = run(&format!("scheme = \"{wrong}\"\nvalences = [4]"));
    assert_eq!(o.verdict, Verdict::Refuted, "{}", o.detail);
    assert!(o.computed.contains("DISPROVED"), "{}", o.computed);
    assert_eq!(run(&format!("scheme = \"{wrong}\"\nvalences = [4]\nexpect = false")).verdict, Verdict::Holds);
}

#[test]
fn polar_bi2_is_proved_for_valences_3_to_24_with_its_defective_blocks_bounded_by_powers() {
    // Karčiauskas–Peters eq. (14): D_k(λ) = (λ − 1/4) λ² (λ − γ̂_k) with
    // γ̂_k = 0 for k ∉ {0, ±1}: those blocks have spectral radius 1/4 and a
    // defective 0, and λ1 = γ̂_1 = 1/2. Lemma S6 may bound them by anything
    // in [1/4, 1/2), never below their spectral radius 1/4.
    for n in 3..=24 {
        let c = builtin("polar-bi2", n);
        assert_proved(&c, &format!("polar-bi2 n = {n}"));
        assert!(lambda1(&c).contains(0.5), "n = {n}");
        for b in &c.blocks {
            let bounded = c.margins.power_bounded.contains(&b.block);
            assert!(!bounded || ![0, 1, n - 1].contains(&b.block), "n = {n}: block {} by S6", b.block);
            // a block without discs must have been bounded by S6
            assert!(b.failure.is_none() || bounded, "n = {n}: block {} has neither", b.block);
            if bounded {
                let p = b.power_bound.expect("S6 evidence");
                assert!(p.radius >= 0.25 && p.radius < 0.5, "n = {n}: block {}: {p:?}", b.block);
                assert!(p.k.is_power_of_two());
            }
        }
        // from n = 4 on some block needs S6 (n = 3 has only blocks 0, 1, 2)
        assert_eq!(c.margins.power_bounded.is_empty(), n == 3, "n = {n}: {:?}", c.margins.power_bounded);
    }
}
