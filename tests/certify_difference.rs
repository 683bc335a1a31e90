//! Lemma C9 (`certify::difference`): characteristic maps of schemes whose
//! regular part is no box spline, proved from the contraction of the
//! scheme's own difference scheme.
//!
//! Expected values come from the rules' definitions, never from output:
//! - Kobbelt's √3 (Kobbelt 2000): an old vertex becomes (2/3)p + (1/18)Σ of
//!   its six neighbours at valence 6 (a_6 = (4 − 2 cos(π/3))/9 = 1/3), a new
//!   vertex is its triangle's centroid. Two steps (one analysis step, the
//!   lattice scaled by 1/3): the old vertex's weight on itself is
//!   (2/3)(2/3) + 6·(1/18)(1/3) = 5/9 (itself, then the six centroids that
//!   hold it), on each old neighbour (2/3)(1/18) + 2·(1/18)(1/3) = 2/27 (the
//!   neighbour's smoothing weight, then the two centroids that hold both);
//! - Loop at valence 6 is the three-direction quartic box spline: vertex
//!   5/8 and 1/16 on each neighbour, edge 3/8 on its ends and 1/8 on the two
//!   opposite vertices;
//! - Kobbelt √3 and Loop are C¹ at every valence (Kobbelt 2000, Zorin 2000 /
//!   Loop 1987 with Umlauf's and Zorin's analyses), their characteristic
//!   maps regular and injective with winding number 1;
//! - a rule whose limit is not C¹ cannot have a contractive scaled
//!   second-difference scheme (that contraction proves the regular part C¹),
//!   so the lattice bound must fail for it.

use crate::common;
use common::subdlab;
use num_rational::BigRational;
use subdlab::certify::charmap::RegularPart;
use subdlab::certify::difference::{lattice_bound, regular_mask};
use subdlab::certify::{certify_charmap, Verdict};
use subdlab::neighbourhood::Configuration;
use subdlab::schemes;
use subdlab::spectrum::{analyse, Options};

fn q(p: i64, d: i64) -> BigRational {
    BigRational::new(p.into(), d.into())
}

fn weights_of(mask: &subdlab::certify::difference::RegularMask, class: (i64, i64)) -> Vec<((i64, i64), BigRational)> {
    let mut w = mask.classes[&class].clone();
    w.sort_by(|a, b| a.0.cmp(&b.0));
    w
}

#[test]
fn kobbelts_two_step_vertex_mask_is_the_closed_form() {
    let scheme = schemes::build("sqrt3", &[]).unwrap();
    let mask = regular_mask(scheme.as_ref()).unwrap();
    assert_eq!((mask.dilation, mask.steps), (3, 2));
    assert_eq!(mask.classes.len(), 9, "one class per point of the 1/3 lattice modulo Z²");
    // offsets D·x − y in 1/3 units: the vertex itself and its six neighbours
    let mut expected = vec![((0, 0), q(5, 9))];
    for o in [(3, 0), (-3, 0), (0, 3), (0, -3), (-3, 3), (3, -3)] {
        expected.push((o, q(2, 27)));
    }
    expected.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(weights_of(&mask, (0, 0)), expected);
    // every class's weights sum to 1 (the rules are affine combinations)
    for (class, list) in &mask.classes {
        let sum: BigRational = list.iter().map(|(_, w)| w.clone()).sum();
        assert_eq!(sum, q(1, 1), "class {class:?}");
    }
}

#[test]
fn loops_mask_is_the_box_spline_mask() {
    let scheme = schemes::build("loop", &[]).unwrap();
    let mask = regular_mask(scheme.as_ref()).unwrap();
    assert_eq!((mask.dilation, mask.steps), (2, 1));
    let mut vertex = vec![((0, 0), q(5, 8))];
    for o in [(2, 0), (-2, 0), (0, 2), (0, -2), (-2, 2), (2, -2)] {
        vertex.push((o, q(1, 16)));
    }
    vertex.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(weights_of(&mask, (0, 0)), vertex);
    // the midpoint (1, 0)/2 of the edge (0,0)–(1,0): ends at offsets ∓(1, 0),
    // opposite vertices (0, 1) and (1, −1) at (0, 2) − (1, 0), (2, −2) − (1, 0)
    let mut edge = vec![((-1, 0), q(3, 8)), ((1, 0), q(3, 8)), ((-1, 2), q(1, 8)), ((1, -2), q(1, 8))];
    edge.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(weights_of(&mask, (1, 0)), edge);
}

#[test]
fn c1_regular_rules_have_a_contractive_difference_scheme() {
    for name in ["sqrt3", "loop"] {
        let scheme = schemes::build(name, &[]).unwrap();
        let b = lattice_bound(scheme.as_ref()).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(b.word_norms[b.word] < 1.0, "{name}: q = {}", b.word_norms[b.word]);
        assert!(b.edge_constant.is_finite() && b.position_constant.is_finite(), "{name}");
        // the windows hold the triangle's corners and are closed under refinement
        assert!(b.windows[0].contains(&(0, 0)) && b.windows[0].contains(&(1, 0)) && b.windows[0].contains(&(0, 1)));
    }
}

#[test]
fn a_c0_rule_is_never_proved_contractive() {
    let path = format!("{}/tests/data/certify/sqrt3-centroids-only.toml", env!("CARGO_MANIFEST_DIR"));
    let scheme = schemes::resolve(&path, &[]).unwrap();
    match lattice_bound(scheme.as_ref()) {
        Err(why) => assert!(why.contains("not proved contractive"), "{why}"),
        Ok(b) => panic!("a C⁰ rule was proved contractive: q = {}", b.word_norms[b.word]),
    }
}

#[test]
fn kobbelts_characteristic_map_is_proved_by_lemma_c9() {
    let scheme = schemes::build("sqrt3", &[]).unwrap();
    for n in [4, 5] {
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
        let c = certify_charmap(scheme.as_ref(), &analysis, 5).unwrap();
        let who = format!("sqrt3 n = {n}");
        assert_eq!(c.c1, Verdict::Proved, "{who}: {:?}", c.c1);
        assert_eq!(c.regular_part, Some(RegularPart::DifferenceScheme), "{who}");
        assert_eq!(c.winding_number, Some(1), "{who}");
        assert_eq!((c.negative_faces, c.undecided_faces), (0, 0), "{who}");
        assert!(c.rules_checked > 0 && c.min_jacobian_lower_bound.unwrap() > 0.0, "{who}");
    }
}

#[test]
fn a_lemma_c9_proof_is_exported_with_its_lattice_data() {
    // the document carries what the checker re-derives lemma C9 from: the
    // regular mask, the windows and bases, and each face's window layout
    // a folder of its own: every test of the suite binary runs in this process
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("sqrt3-5.json");
    let out = subdlab(&["charmap", "sqrt3", "-n", "5", "--certify", "--certificate", file.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let doc: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    let part = &doc["parts"]["charmap"];
    assert_eq!(part["regular_part"], "difference-scheme");
    let d = &part["difference"];
    assert_eq!((d["dilation"].as_i64(), d["steps"].as_i64()), (Some(3), Some(2)));
    assert_eq!(d["mask"].as_array().unwrap().len(), 9);
    let up = d["windows"]["up"].as_array().unwrap().len();
    assert_eq!(d["basis"]["up"].as_array().unwrap().len() + 3, up, "a basis of second differences");
    for face in part["faces"].as_array().unwrap() {
        assert_eq!(face["window"].as_array().unwrap().len(), up);
    }
}
