//! Certified characteristic maps (`charmap --certify`, `certify::charmap`).
//!
//! What the certificate must prove comes from the literature, never from
//! program output:
//! - Catmull–Clark, Doo–Sabin and Loop are C¹ at every valence (Peters & Reif
//!   1998 and 1997, Zorin 2000; Umlauf 2000): their characteristic maps are
//!   regular and injective, with winding number 1;
//! - at the regular valence (4 for quads, 6 for triangles) a box-spline
//!   scheme's characteristic map is linear (linear precision), so the
//!   Jacobian is constant and its smallest lower bound over the ring equals
//!   its largest upper bound, up to the enclosures' widths;
//! - the regular rules of Kobbelt's sqrt(3) are no box spline's: no
//!   box-spline proof applies, and lemma C9 proves its map instead
//!   (tests/certify_difference.rs; non-box's S_3^1 spline, which reproduces
//!   linear functions too, is in tests/certify_nonbox.rs; its regular map is
//!   checked for linearity here);
//! - 4-3 subdivision's quad rules are the four-direction box spline A_4's and
//!   its triangle rules Loop's (Peters–Shiue; tests/four_three.rs derives
//!   both masks from the direction matrices), so its eons surrounded by quads
//!   only or by triangles only are box-spline rings; Peters–Shiue prove them
//!   C¹ (section 3); a ring whose faces meet transition vertices is not a box
//!   spline of one kind;
//! - `schemes/loop-block2-dominant.toml` is built (its comment says how) so
//!   that at valence 4 the subdominant 1/2 sits in block 2.

use crate::common;
use common::subdlab;
use rayon::prelude::*;
use subdlab::certify::charmap::{own_window_signs, RegularPart, DEFAULT_MAX_LEVELS};
use subdlab::certify::matrix::Check;
use subdlab::certify::{certify_charmap, CharMapCertificate, Verdict};
use subdlab::neighbourhood::Configuration;
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Options};

fn certificate(scheme: &dyn Scheme, n: usize) -> CharMapCertificate {
    let config = Configuration::regular(scheme, n).unwrap();
    let analysis = analyse(scheme, &config, &Options::default()).unwrap();
    certify_charmap(scheme, &analysis, 4).unwrap()
}

fn builtin(name: &str, n: usize) -> CharMapCertificate {
    certificate(schemes::build(name, &[]).unwrap().as_ref(), n)
}

fn assert_proved(c: &CharMapCertificate, part: RegularPart) {
    let who = format!("{} n = {}", c.scheme, c.valence);
    assert_eq!(c.regularity, Verdict::Proved, "{who}: {:?}", c.regularity);
    assert_eq!(c.injectivity, Verdict::Proved, "{who}: {:?}", c.injectivity);
    assert_eq!(c.regular_part, Some(part), "{who}");
    assert_eq!(c.winding_number, Some(1), "{who}");
    assert_eq!((c.negative_faces, c.undecided_faces), (0, 0), "{who}");
    assert!(c.positive_faces == c.ring_faces && c.ring_faces > 0, "{who}");
    assert!(c.min_jacobian_lower_bound.unwrap() > 0.0, "{who}");
    assert!(c.rules_checked > 0, "{who}");
    // the eigenvector and net enclosures are tight: far below the margins
    assert!(c.eigenvector_radius.unwrap() < 1e-10 && c.max_point_width.unwrap() < 1e-9, "{who}");
    // every premise is exact (in Q or Q(ζ_n)) for these rules at these
    // valences, so nothing rests on interval overlap
    let rotation = &c.spectrum.premises.as_ref().expect("premises checked").rotation_symmetry;
    assert_eq!(*rotation, Check::Exact, "{who}");
    assert!(!c.geometry_conditional && !c.conditional, "{who}");
}

#[test]
fn catmull_clark_loop_and_doo_sabin_are_proved_for_every_valence_3_to_50() {
    let cases: Vec<(&str, RegularPart, usize)> = [
        ("catmull-clark", RegularPart::BicubicBSpline),
        ("loop", RegularPart::ThreeDirectionQuarticBoxSpline),
        ("doo-sabin", RegularPart::BiquadraticBSpline),
    ]
    .into_iter()
    .flat_map(|(s, p)| (3..=50).map(move |n| (s, p, n)))
    .collect();
    cases.par_iter().for_each(|&(s, part, n)| {
        let c = builtin(s, n);
        assert_proved(&c, part);
        // the spectral half is proved too, unconditionally; so Reif's
        // criterion as a whole
        assert_eq!(c.spectrum.verdict, Verdict::Proved, "{s} n = {n}");
        assert!(!c.spectrum.conditional, "{s} n = {n}");
        assert_eq!(c.c1, Verdict::Proved, "{s} n = {n}");
    });
}

#[test]
fn the_bi2_schemes_are_proved_for_valences_3_to_24() {
    let cases: Vec<(&str, RegularPart, usize)> =
        [("pgs", RegularPart::BiquadraticBSpline), ("tps", RegularPart::BiquadraticBSplineTernary)]
            .into_iter()
            .flat_map(|(s, p)| (3..=24).map(move |n| (s, p, n)))
            .collect();
    cases.par_iter().for_each(|&(s, part, n)| assert_proved(&builtin(s, n), part));
}

#[test]
fn at_the_regular_valence_the_jacobian_is_constant() {
    for (s, n) in [("catmull-clark", 4), ("doo-sabin", 4), ("loop", 6), ("tps", 4), ("four-three", 4), ("non-box", 4)] {
        let c = builtin(s, n);
        let ratio = c.min_jacobian_ratio.unwrap();
        assert!((ratio - 1.0).abs() < 1e-9, "{s}: smallest lower bound over largest upper bound {ratio}");
    }
}

#[test]
fn a_block_2_dominant_variant_is_disproved_by_its_spectrum() {
    let scheme =
        schemes::resolve(&format!("{}/schemes/loop-block2-dominant.toml", env!("CARGO_MANIFEST_DIR")), &[]).unwrap();
    let c = certificate(scheme.as_ref(), 4);
    assert!(matches!(c.spectrum.verdict, Verdict::Disproved(_)), "{:?}", c.spectrum.verdict);
    match &c.c1 {
        Verdict::Disproved(why) => assert!(why.starts_with("spectrum: block 2"), "{why}"),
        other => panic!("expected DISPROVED, got {other:?}"),
    }
    // no certified λ1, so no map whose regularity a proof could speak about
    assert!(matches!(&c.regularity, Verdict::NotProved(r) if r.contains("not attempted")), "{:?}", c.regularity);
    assert!(matches!(&c.injectivity, Verdict::NotProved(r) if r.contains("not attempted")));
}

fn twisted_scheme(t: &str) -> Box<dyn Scheme> {
    schemes::resolve(
        &format!("{}/schemes/catmull-clark-twisted-edge.toml", env!("CARGO_MANIFEST_DIR")),
        &[("t".to_string(), t.to_string())],
    )
    .unwrap()
}

fn twisted(t: &str, n: usize, levels: usize) -> CharMapCertificate {
    let scheme = twisted_scheme(t);
    let config = Configuration::regular(scheme.as_ref(), n).unwrap();
    let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
    certify_charmap(scheme.as_ref(), &analysis, levels).unwrap()
}

#[test]
fn a_wrong_block_pair_is_disproved_by_the_spectrum_and_its_map_is_not_attempted() {
    // at t = 1/8 the subdominant pair of the twisted edge rule sits in blocks
    // 3 and 4 (n = 7), above block 1: the spectral certificate disproves the
    // criterion with block 4's enclosure as witness, and no map is built from
    // a floating-point choice of block (the map of that pair would wind 3
    // times, but it is not the characteristic map of a proved λ1)
    let c = twisted("1/8", 7, 4);
    assert!(matches!(&c.spectrum.verdict, Verdict::Disproved(w) if w.contains("block 4")), "{:?}", c.spectrum.verdict);
    assert!(matches!(&c.regularity, Verdict::NotProved(r) if r.contains("not attempted")), "{:?}", c.regularity);
    assert_eq!(c.winding_number, None);
    assert!(matches!(&c.c1, Verdict::Disproved(w) if w.starts_with("spectrum:")), "{:?}", c.c1);
}

#[test]
fn a_thin_ring_that_the_raster_rejects_at_the_defaults_is_proved_injective() {
    use subdlab::charmap::{check_map, CharMapOptions};
    let scheme = twisted_scheme("-1/4");
    let config = Configuration::regular(scheme.as_ref(), 7).unwrap();
    let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
    // undecided faces at 4 levels: NOT PROVED, never a guess
    let c = certify_charmap(scheme.as_ref(), &analysis, 4).unwrap();
    assert!(matches!(&c.regularity, Verdict::NotProved(w) if w.contains("undecided")), "{:?}", c.regularity);
    // 6 levels decide every face
    let c = certify_charmap(scheme.as_ref(), &analysis, 6).unwrap();
    assert_proved(&c, RegularPart::BicubicBSpline);
    assert_eq!(c.c1, Verdict::Proved);
    // the numerical check at its defaults reports an overlap with the scaled
    // copy (the piecewise-linear ring at level 4 is off by more than the
    // ring's width allows); refined, it agrees with the proof
    let coarse = check_map(scheme.as_ref(), &analysis, &CharMapOptions::checked(4, 512).unwrap()).unwrap();
    assert!(coarse.regular && !coarse.injective && coarse.copy_overlap_pixels.unwrap() > 0);
    let fine = check_map(scheme.as_ref(), &analysis, &CharMapOptions::checked(6, 1024).unwrap()).unwrap();
    assert!(fine.regular && fine.injective, "{:?}", fine.reasons);
}

#[test]
fn a_folded_map_with_a_valid_spectrum_is_disproved_with_a_witness() {
    // schemes/catmull-clark-folded-ring.toml: λ1 = 31/32 from blocks 1 and
    // n − 1 by design (its comment derives it), control quads around the
    // centre that are darts, and a limit Jacobian of both signs
    // (tests/registry_independent.rs evaluates it exactly)
    let scheme =
        schemes::resolve(&format!("{}/schemes/catmull-clark-folded-ring.toml", env!("CARGO_MANIFEST_DIR")), &[])
            .unwrap();
    for n in [3, 5, 6] {
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
        let c = certify_charmap(scheme.as_ref(), &analysis, 5).unwrap();
        assert_eq!(c.spectrum.verdict, Verdict::Proved, "n = {n}: the spectrum is valid");
        assert!(
            matches!(&c.regularity, Verdict::Disproved(w) if w.contains("changes sign")),
            "n = {n}: {:?}",
            c.regularity
        );
        assert!(matches!(c.injectivity, Verdict::Disproved(_)) && matches!(c.c1, Verdict::Disproved(_)), "n = {n}");
        let w = c.fold_witness.as_ref().expect("a witness");
        assert!(w.negative_upper_bound < 0.0 && w.positive_lower_bound > 0.0, "n = {n}: {w:?}");
        assert!(c.negative_faces > 0 && c.positive_faces > 0, "n = {n}");
    }
}

#[test]
fn the_cli_prints_the_certificate_in_json_and_text() {
    let out = subdlab(&["charmap", "catmull-clark", "-n", "7", "--certify", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let c = &v["certificate"];
    assert_eq!(c["c1"]["verdict"], "proved");
    assert_eq!(c["regularity"]["verdict"], "proved");
    assert_eq!(c["injectivity"]["verdict"], "proved");
    assert_eq!(c["regular_part"], "bicubic-b-spline");
    assert_eq!(c["winding_number"], 1);
    assert!(c["min_jacobian_lower_bound"].as_f64().unwrap() > 0.0);
    assert!(c["spectrum"]["margins"]["gap_lower_bound"].as_f64().unwrap() > 0.0);
    // the numerical verdicts stay beside the certificate
    assert_eq!(v["regular"], true);
    let text = subdlab(&["charmap", "doo-sabin", "-n", "5", "--certify"]);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(text.contains("certified C1 (Reif's criterion): PROVED"), "{text}");
    assert!(text.contains("regular part: biquadratic B-spline"), "{text}");
    let bad = common::fails(&["charmap", "loop", "-n", "5", "--certify", "--certify-levels", "9"]);
    assert!(bad.contains("--certify-levels must be between 2 and 6"), "{bad}");
}

#[test]
fn four_three_eons_of_quads_or_of_triangles_are_proved() {
    use subdlab::neighbourhood::Configuration;
    let scheme = schemes::build("four-three", &[]).unwrap();
    let cases: Vec<(String, RegularPart)> = (3..=10)
        .filter(|&n| n != 4)
        .map(|n| ("Q".repeat(n), RegularPart::FourDirectionBoxSpline))
        .chain((3..=9).filter(|&n| n != 6).map(|n| ("T".repeat(n), RegularPart::ThreeDirectionQuarticBoxSpline)))
        .collect();
    let results: Vec<(String, CharMapCertificate)> = cases
        .par_iter()
        .map(|(faces, _)| {
            let config = Configuration::with_faces(scheme.as_ref(), faces.len(), faces).unwrap();
            let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
            (faces.clone(), certify_charmap(scheme.as_ref(), &analysis, 4).unwrap())
        })
        .collect();
    for ((faces, c), (_, part)) in results.iter().zip(&cases) {
        assert_eq!(c.c1, Verdict::Proved, "{faces}: {:?}", c.c1);
        assert_proved(c, *part);
    }
    // alternating quads and triangles: the spectrum is proved (a reflection
    // through a sector's bisector gives the realness), but the ring's faces
    // meet transition vertices, whose rules mix the two box splines
    let config = Configuration::with_faces(scheme.as_ref(), 6, "QTQTQT").unwrap();
    let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
    let c = certify_charmap(scheme.as_ref(), &analysis, 4).unwrap();
    assert_eq!(c.spectrum.verdict, Verdict::Proved, "{:?}", c.spectrum.verdict);
    assert!(matches!(&c.regularity, Verdict::NotProved(r) if r.contains("not regular")), "{:?}", c.regularity);
    // the CLI takes the face sequence
    let out = common::subdlab(&["charmap", "four-three", "-n", "5", "--faces", "TTTTT", "--certify"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("certified C1 (Reif's criterion): PROVED"), "{text}");
    assert!(text.contains("regular part: three-direction quartic box spline"), "{text}");
}

/// The rule check's control: Catmull–Clark with the vertex rule moved off
/// the bicubic B-spline's at every valence (centre 1 − 7/(4n) − 1/(8n), each
/// edge neighbour 1/(8n²) more: at n = 4 the centre weight is 17/32, neither
/// the bicubic mask's 9/16 nor A_4's 1/2). Every regular vertex of the ring's
/// windows then fails both masks, in the windows the check keeps (one per
/// rotation orbit, `certify::window_orbits`) as in every other: NOT PROVED,
/// numerically only, at every valence.
#[test]
fn a_vertex_rule_that_is_no_box_splines_is_not_proved() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cc-off-vertex.toml");
    std::fs::write(
        &path,
        "name = \"cc-off-vertex\"\ntopology = \"primal-quad\"\n[vertex]\ncentre = \"1 - 7 / (4 n) - 1 / (8 n)\"\n\
         edge = \"3 / (2 n^2) + 1 / (8 n^2)\"\nface = \"1 / (4 n^2)\"\n[edge]\nends = \"3/8\"\nside = \"1/16\"\n\
         [face]\ncorner = \"1 / n\"\n",
    )
    .unwrap();
    let scheme = schemes::resolve(path.to_str().unwrap(), &[]).unwrap();
    for n in [3, 5, 8] {
        let c = certificate(scheme.as_ref(), n);
        assert_eq!(c.spectrum.verdict, Verdict::Proved, "n = {n}: the spectrum is not what fails");
        assert!(
            matches!(&c.regularity, Verdict::NotProved(w) if w.starts_with("numerical only") && w.contains("not one box spline")),
            "n = {n}: {:?}",
            c.regularity
        );
        assert!(matches!(c.c1, Verdict::NotProved(_)), "n = {n}");
    }
}

/// The net of a certificate's first try (two analysis steps; the points are
/// placeholders, the faces and flags do not depend on them), its ring
/// (outer, not inner) and the rotation period.
fn ring_net(name: &str, n: usize) -> (subdlab::charmap::net::Net<[f64; 2]>, Vec<usize>, usize) {
    ring_net_of(name, n, None)
}

/// [`ring_net`] of a face sequence around the centre (mixed meshes).
fn ring_net_of(name: &str, n: usize, faces: Option<&str>) -> (subdlab::charmap::net::Net<[f64; 2]>, Vec<usize>, usize) {
    let scheme = schemes::resolve(name, &[]).unwrap();
    let config = match faces {
        Some(f) => Configuration::with_faces(scheme.as_ref(), n, f).unwrap(),
        None => Configuration::regular(scheme.as_ref(), n).unwrap(),
    };
    let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
    let d = &analysis.discovered;
    let level0 = vec![Some([0.0, 0.0]); d.patch.num_vertices()];
    let net = subdlab::charmap::net::refine_net_exactly_as::<f64, [f64; 2]>(scheme.as_ref(), d, level0, 2).unwrap();
    let ring: Vec<usize> = (0..net.mesh.num_faces()).filter(|&f| net.outer[f] && !net.inner[f]).collect();
    (net, ring, config.rotation_period(scheme.as_ref()))
}

/// The image of face f under the rotation by `period` sectors, rebuilt here
/// from the net's lattice chart (sector s + period, same coordinates) and
/// the half-edge of its first two turned corners.
fn turned_face(net: &subdlab::charmap::net::Net<[f64; 2]>, period: usize, f: usize) -> usize {
    let chart = net.mesh.chart.as_ref().expect("the net keeps its chart");
    let n = chart.sectors();
    let turn = |v: usize| {
        let c = chart.vertex_coords[v];
        let to = subdlab::mesh::LatticeCoord { sector: (c.sector + period) % n, ..c };
        chart.vertex_coords.iter().position(|&x| x == to).expect("the turned point is in the net")
    };
    let face = net.mesh.face(f);
    net.mesh.half_edge(turn(face[0]), turn(face[1])).expect("the turned edge is in the net").0
}

/// `certify::window_orbits`: the ring's faces fall into orbits of g = n /
/// period faces (every sector of a regular configuration is alike), and
/// each orbit holds exactly one face whose window the rule check keeps.
#[test]
fn every_orbit_of_ring_faces_has_exactly_one_checked_window() {
    use subdlab::certify::window_orbits::representatives;
    for (name, n) in [("catmull-clark", 5), ("loop", 7), ("doo-sabin", 6), ("tps", 4), ("catmull-clark", 3)] {
        let (net, ring, period) = ring_net(name, n);
        let reps = representatives(&net, &ring, period);
        let g = n / period;
        assert_eq!(reps.len() * g, ring.len(), "{name} n = {n}: {} of {} faces", reps.len(), ring.len());
        let kept: std::collections::HashSet<usize> = reps.iter().map(|&i| ring[i]).collect();
        for &f in &ring {
            let mut orbit = vec![f];
            while orbit.len() < g {
                orbit.push(turned_face(&net, period, *orbit.last().unwrap()));
            }
            assert_eq!(turned_face(&net, period, orbit[g - 1]), f, "{name} n = {n}: g turns close the orbit");
            let met = orbit.iter().filter(|h| kept.contains(h)).count();
            assert_eq!(met, 1, "{name} n = {n}: the orbit of face {f} holds {met} checked windows");
        }
    }
}

/// Data the rotation does not carry turn the reduction off: every window is
/// checked.
#[test]
fn data_the_rotation_does_not_keep_turn_the_one_orbit_check_off() {
    use subdlab::certify::window_orbits::representatives;
    let (mut net, ring, period) = ring_net("catmull-clark", 5);
    assert!(representatives(&net, &ring, period).len() < ring.len());
    // one vertex's parameter differs from its images'
    let mut params = vec![0.5; net.mesh.num_vertices()];
    params[net.mesh.face(ring[0])[0]] = 0.25;
    net.mesh.vertex_params = Some(params);
    assert_eq!(representatives(&net, &ring, period).len(), ring.len(), "an asymmetric per-vertex parameter");
    // the same parameter everywhere keeps the symmetry
    net.mesh.vertex_params = Some(vec![0.5; net.mesh.num_vertices()]);
    assert!(representatives(&net, &ring, period).len() < ring.len());
    // lattice directions are not carried by the rotation
    net.mesh.vertex_params = None;
    net.mesh.lattice_dirs = Some(vec![0; net.mesh.num_faces()]);
    assert_eq!(representatives(&net, &ring, period).len(), ring.len(), "lattice directions");
    // a ring flag that does not turn: the ring itself is not invariant
    net.mesh.lattice_dirs = None;
    net.inner[ring[0]] = true;
    assert_eq!(representatives(&net, &ring, period).len(), ring.len(), "a ring that does not turn");
}

/// `window_orbits::representative_of` (lemma C5′: one Jacobian bound per
/// orbit): on a 4-3 eon with a half-turn (QQTQQT, period 3) every ring
/// face's representative is the face itself or its image under the turn
/// rebuilt here from the chart, and each orbit has two faces; the eon QQQQT
/// has no rotation (its period is its valence), so every face is its own
/// representative, as are all faces of a net whose data the rotation does
/// not keep.
#[test]
fn orbits_of_a_half_turn_eon_have_two_faces_and_an_asymmetric_eon_none() {
    use subdlab::certify::window_orbits::representative_of;
    let itself = |n: usize| (0..n).collect::<Vec<_>>();
    let (net, ring, period) = ring_net_of("four-three", 6, Some("QQTQQT"));
    assert_eq!(period, 3);
    let rep = representative_of(&net, &ring, period);
    let mut moved = 0;
    for (i, &f) in ring.iter().enumerate() {
        assert_eq!(rep.iter().filter(|&&x| x == rep[i]).count(), 2, "face {f}: an orbit of the half-turn");
        let r = ring[rep[i]];
        if r != f {
            moved += 1;
            assert_eq!(r, turned_face(&net, period, f), "face {f}: representative {r} is not its image");
        }
    }
    assert_eq!(2 * moved, ring.len());
    let (net, ring, period) = ring_net_of("four-three", 5, Some("QQQQT"));
    assert_eq!(representative_of(&net, &ring, period), itself(ring.len()), "no rotation");
    let (mut net, ring, period) = ring_net("catmull-clark", 5);
    net.mesh.lattice_dirs = Some(vec![0; net.mesh.num_faces()]);
    assert_eq!(representative_of(&net, &ring, period), itself(ring.len()), "lattice directions");
}

/// Lemma C5′ against the route it replaced: at every level the
/// certificate tries, every ring face's own window proves the sign its
/// representative's does (so the route that bounded every face decided
/// the same at every level), each orbit has g members, and the counts
/// and the document's per-face signs are the all-faces ones. The signs
/// are a second computation (each face's own enclosures), not the
/// certificate's.
#[test]
fn one_jacobian_bound_per_orbit_decides_as_every_face_does() {
    for (name, n) in [("catmull-clark", 5), ("loop", 7), ("doo-sabin", 5), ("catmull-clark", 3), ("loop", 4)] {
        let scheme = subdlab::schemes::build(name, &[]).unwrap();
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
        let cert = certify_charmap(scheme.as_ref(), &analysis, DEFAULT_MAX_LEVELS).unwrap();
        let who = format!("{name} n = {n}");
        assert_eq!(cert.regularity, Verdict::Proved, "{who}");
        let decisive = cert.levels.expect("decided");
        let g = n / config.rotation_period(scheme.as_ref());
        // the decisive level must be compared (a test that found no
        // windows there would compare nothing)
        let mut compared_decisive = false;
        for levels in 2..=decisive {
            let Some((own, rep)) = own_window_signs(scheme.as_ref(), &analysis, levels) else { continue };
            for i in 0..own.len() {
                assert_eq!(own[i], own[rep[i]], "{who} at {levels} levels: face {i} and its representative");
            }
            // every orbit has g faces
            let reps: Vec<usize> = (0..rep.len()).filter(|&i| rep[i] == i).collect();
            assert_eq!(reps.len() * g, own.len(), "{who}");
            for &r in &reps {
                assert_eq!(rep.iter().filter(|&&x| x == r).count(), g, "{who}: the orbit of face {r}");
            }
            if levels == decisive {
                let count = |s: i8| own.iter().filter(|&&x| x == s).count();
                assert_eq!(cert.ring_faces, own.len(), "{who}");
                assert_eq!(
                    (cert.positive_faces, cert.negative_faces, cert.undecided_faces),
                    (count(1), count(-1), count(0)),
                    "{who}"
                );
                let evidence = cert.evidence.as_ref().expect("evidence of a decided map");
                let claimed: Vec<i8> = evidence.faces.iter().map(|f| f.sign).collect();
                assert_eq!(claimed, own, "{who}: the document's signs are every face's own");
                compared_decisive = true;
            }
        }
        assert!(compared_decisive, "{who}: no windows at the decisive level {decisive}");
    }
}
