//! The characteristic-map certificate for Huang's non-box S_3^1 scheme
//! (`RegularPart::NonBoxS31`, lemma C3′ of ARCHITECTURE.md).
//!
//! - The refinement mask `certify::s31` derives from the spline's definition
//!   is tested by identities it must satisfy, computed here by other routes:
//!   the refinement equation itself, B(x) = Σ w B(2(x − p')), at points where
//!   both sides are integrated exactly from the hats (no mask involved on the
//!   left); partition of unity and reproduction of linear functions; and the
//!   four rules as the paper's text states them (section 3.2.2, a_4 = 1/2).
//! - With the paper's a_k the map is PROVED at several valences (and at the
//!   regular valence 4), with λ1 = 1/2 + cos(2π/k)/4 (the paper's closed form
//!   for the leading eigenvalue of B(1)) inside the certified enclosure.
//! - Negative controls: a = 0 puts 3/4 − a = 3/4 in block 0 above every λ1 <
//!   3/4 (spectrum DISPROVED); an E-vertex rule changed to the edge midpoint
//!   folds the map (the floating-point raster sees it) and is not the spline
//!   (NOT PROVED); an NFCV rule moved by 1/1000 is rejected by the rule check.

use std::collections::HashMap;

use subdlab::certify::s31::{self, Kind};
use subdlab::certify::{certify_charmap, charmap::RegularPart, Verdict};
use subdlab::charmap::{check_map, CharMapOptions};
use subdlab::neighbourhood::Configuration;
use subdlab::numeric::{Rational, Weight};
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Analysis, Options};

fn r(p: i64, q: i64) -> Rational {
    Rational::ratio(p, q)
}

fn analysis(scheme: &dyn Scheme, n: usize) -> Analysis {
    let config = Configuration::regular(scheme, n).unwrap();
    analyse(scheme, &config, &Options::default()).unwrap()
}

/// The hats of the definition at a point given in sixteenths of the coarse
/// lattice: the square hat of a V-vertex, 1 − 2 max(|x|, |y|), and the
/// diamond hat of an FCV, 1 − |x| − |y|, clipped at 0 (written out here, not
/// taken from `s31`).
fn hat16(kind: Kind, x: i64, y: i64) -> Rational {
    let v = match kind {
        Kind::Vertex => r(16 - 2 * x.abs().max(y.abs()), 16),
        Kind::Fcv => r(16 - x.abs() - y.abs(), 16),
    };
    if v > Rational::zero() {
        v
    } else {
        Rational::zero()
    }
}

/// B = φ * χ at the point (x, y) in eighths: the integral of the hat over the
/// unit square centred there, cut into cells of side 1/8 and each cell into
/// four triangles by its diagonals. Every kink line of both hats (the axes,
/// x = ±1/2, y = ±1/2, x = ±y, |x| + |y| = 1) runs along cell edges or
/// diagonals, so the hat is linear on each triangle and the integral is the
/// exact sum of area × the mean of the three vertex values.
fn basis(kind: Kind, x8: i64, y8: i64, memo: &mut HashMap<(bool, i64, i64), Rational>) -> Rational {
    let key = (kind == Kind::Vertex, x8, y8);
    if let Some(v) = memo.get(&key) {
        return v.clone();
    }
    // sixteenths: the square runs from 2x8 − 8 to 2x8 + 8
    let mut sum = Rational::zero();
    for i in 0..8 {
        for j in 0..8 {
            let (x0, y0) = (2 * x8 - 8 + 2 * i, 2 * y8 - 8 + 2 * j);
            let corners = [(x0, y0), (x0 + 2, y0), (x0 + 2, y0 + 2), (x0, y0 + 2)];
            let centre = hat16(kind, x0 + 1, y0 + 1);
            for k in 0..4 {
                let (a, b) = (corners[k], corners[(k + 1) % 4]);
                // area 1/256 of each triangle (a quarter of a 1/64 cell)
                sum += (hat16(kind, a.0, a.1) + hat16(kind, b.0, b.1) + centre.clone()) * r(1, 3 * 256);
            }
        }
    }
    memo.insert(key, sum.clone());
    sum
}

#[test]
fn the_derived_mask_satisfies_the_refinement_equation() {
    // B_t(x − o) = Σ_{p'} w(p', o) B_{kind p'}(2(x − p')) for the coarse point
    // o of either kind, at every x on the grid of eighths of a face around it
    let mut memo = HashMap::new();
    for (o, kind) in [((0i64, 0i64), Kind::Vertex), ((2, 2), Kind::Fcv)] {
        for x8 in -12..=12i64 {
            for y8 in -12..=12i64 {
                // o in quarters = 2 o in eighths
                let left = basis(kind, x8 - 2 * o.0, y8 - 2 * o.1, &mut memo);
                let mut right = Rational::zero();
                for px in -12..=12i64 {
                    for py in -12..=12i64 {
                        let Some(fine) = s31::fine_kind((px, py)) else { continue };
                        let w = s31::refinement_weight((px, py), o).unwrap();
                        if Weight::is_zero(&w) {
                            continue;
                        }
                        // 2(x − p') in eighths: 2·x8 − 4·p'(quarters)
                        let (u, v) = (2 * x8 - 4 * px, 2 * y8 - 4 * py);
                        if u.abs() >= 12 || v.abs() >= 12 {
                            continue; // outside every support (|·|∞ < 3/2)
                        }
                        right += w * basis(fine, u, v, &mut memo);
                    }
                }
                assert_eq!(left, right, "{kind:?} at ({x8}/8, {y8}/8)");
            }
        }
    }
    // the integral is right where it is known: B_V(0) = the pyramid's volume
    // over its unit square, 1/3
    assert_eq!(basis(Kind::Vertex, 0, 0, &mut memo), r(1, 3));
}

#[test]
fn the_derived_mask_reproduces_constants_and_linear_functions() {
    // one period of the new points: V-vertices at even, FCVs at odd quarters
    for new in [(0, 0), (2, 0), (0, 2), (2, 2), (1, 1), (3, 1), (1, 3), (3, 3), (-1, 5)] {
        let m = s31::mask(new).unwrap();
        let total = m.iter().fold(Rational::zero(), |s, (_, w)| s + w.clone());
        assert_eq!(total, Rational::one(), "{new:?}");
        // λ_p = p (in quarters) refines to μ_{p'} = p': the centred basis
        // reproduces the identity map
        let x = m.iter().fold(Rational::zero(), |s, (p, w)| s + w.clone() * Rational::int(p.0));
        let y = m.iter().fold(Rational::zero(), |s, (p, w)| s + w.clone() * Rational::int(p.1));
        assert_eq!((x, y), (Rational::int(new.0), Rational::int(new.1)), "{new:?}");
        assert!(m.iter().all(|(_, w)| *w > Rational::zero()), "{new:?}: the weights are positive");
    }
}

#[test]
fn the_derived_mask_is_the_rules_of_section_3_2_2() {
    // weights keyed by coarse position (quarters: V at 4Z², FCVs at 4Z² + 2)
    let mask = |p: (i64, i64)| -> Vec<((i64, i64), Rational)> {
        let mut m = s31::mask(p).unwrap();
        m.sort_by_key(|(q, _)| *q);
        m
    };
    let fcvs = [(-2, -2), (-2, 2), (2, -2), (2, 2)];
    // V-vertex: (1 − a_4) V + (a_4/4) Σ FCVs, a_4 = 1/2
    let mut want = vec![((0, 0), r(1, 2))];
    want.extend(fcvs.iter().map(|&p| (p, r(1, 8))));
    want.sort_by_key(|(q, _)| *q);
    assert_eq!(mask((0, 0)), want);
    // E-vertex: the two ends and the two faces' FCVs, 1/4 each
    assert_eq!(mask((2, 0)), vec![((0, 0), r(1, 4)), ((2, -2), r(1, 4)), ((2, 2), r(1, 4)), ((4, 0), r(1, 4))]);
    // the old FCV's new position: (1 − a_4) FCV + (a_4/4) Σ corners
    assert_eq!(
        mask((2, 2)),
        vec![((0, 0), r(1, 8)), ((0, 4), r(1, 8)), ((2, 2), r(1, 2)), ((4, 0), r(1, 8)), ((4, 4), r(1, 8))]
    );
    // NFCV at corner V_0 = (0,0) of the face F_0 centred at (2,2):
    // V_0/4 + FCV_0/2 + FCV_{±1}/8 (the faces beside F_0 at V_0)
    assert_eq!(mask((1, 1)), vec![((-2, 2), r(1, 8)), ((0, 0), r(1, 4)), ((2, -2), r(1, 8)), ((2, 2), r(1, 2))]);
}

#[test]
fn non_box_is_proved_with_the_papers_weights() {
    let s = schemes::build("non-box", &[]).unwrap();
    for n in [3, 4, 5, 7, 10] {
        let a = analysis(s.as_ref(), n);
        let c = certify_charmap(s.as_ref(), &a, 5).unwrap();
        assert_eq!(c.c1, Verdict::Proved, "n = {n}: {:?}", c.c1);
        assert_eq!(c.regularity, Verdict::Proved, "n = {n}");
        assert_eq!(c.injectivity, Verdict::Proved, "n = {n}");
        assert_eq!(c.regular_part, Some(RegularPart::NonBoxS31), "n = {n}");
        assert!(c.rules_checked > 0, "n = {n}");
        assert_eq!(c.winding_number, Some(1), "n = {n}");
        // λ1 = 1/2 + cos(2π/n)/4 (section 4) inside the certified enclosure
        let l1 = c.spectrum.margins.lambda1.expect("λ1 enclosed");
        let want = 0.5 + (2.0 * std::f64::consts::PI / n as f64).cos() / 4.0;
        assert!(l1.lo <= want + 1e-12 && want - 1e-12 <= l1.hi, "n = {n}: λ1 in [{}, {}]", l1.lo, l1.hi);
    }
}

#[test]
fn a_dominant_block_0_eigenvalue_is_disproved() {
    // a = 0: block 0 holds 3/4 − a = 3/4 (section 4), above λ1 = 1/2 +
    // cos(2π/n)/4 < 3/4 at every valence k ≠ 4
    let s = schemes::build("non-box", &[("a".to_string(), "0".to_string())]).unwrap();
    for n in [3, 5, 8] {
        let a = analysis(s.as_ref(), n);
        let c = certify_charmap(s.as_ref(), &a, 5).unwrap();
        assert!(matches!(c.spectrum.verdict, Verdict::Disproved(_)), "n = {n}: {:?}", c.spectrum.verdict);
        assert!(matches!(c.c1, Verdict::Disproved(_)), "n = {n}: {:?}", c.c1);
    }
}

#[test]
fn a_folded_variant_is_never_proved() {
    let file = format!("{}/tests/data/certify/nonbox-midpoint-edge.toml", env!("CARGO_MANIFEST_DIR"));
    let s = schemes::resolve(&file, &[]).unwrap();
    for n in [5, 6, 7] {
        let a = analysis(s.as_ref(), n);
        // the independent route: the floating-point raster folds
        let raster = check_map(s.as_ref(), &a, &CharMapOptions::checked(4, 512).unwrap()).unwrap();
        assert!(!raster.regular, "n = {n}: the raster should see the fold");
        let c = certify_charmap(s.as_ref(), &a, 5).unwrap();
        assert_ne!(c.c1, Verdict::Proved, "n = {n}: a false proof");
        assert_ne!(c.regularity, Verdict::Proved, "n = {n}");
        assert!(matches!(&c.regularity, Verdict::NotProved(w) if w.contains("S_3^1")), "n = {n}: {:?}", c.regularity);
    }
}

#[test]
fn a_rule_moved_by_a_small_rational_amount_is_rejected() {
    // the NFCV rule's weights moved by 1/1000 (still summing to 1), in a copy
    // of the scheme file that reproduces the built-in
    let text = std::fs::read_to_string(format!("{}/schemes/non-box.toml", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let text = text
        .replace("name = \"non-box-file\"", "name = \"non-box-nudged\"")
        .replace("vertex = \"1/4\"", "vertex = \"1/4 + 1/1000\"")
        .replace("fcv = \"1/2\"", "fcv = \"1/2 - 1/1000\"");
    assert!(text.contains("1/4 + 1/1000") && text.contains("1/2 - 1/1000"));
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("non-box-nudged.toml");
    std::fs::write(&path, text).unwrap();
    let s = schemes::resolve(path.to_str().unwrap(), &[]).unwrap();
    let a = analysis(s.as_ref(), 5);
    let c = certify_charmap(s.as_ref(), &a, 5).unwrap();
    assert!(
        matches!(&c.regularity, Verdict::NotProved(w) if w.contains("Corner") && w.contains("S_3^1")),
        "{:?}",
        c.regularity
    );
    assert_ne!(c.c1, Verdict::Proved);
    // the unchanged file is the built-in, and is proved
    let s = schemes::resolve(&format!("{}/schemes/non-box.toml", env!("CARGO_MANIFEST_DIR")), &[]).unwrap();
    let c = certify_charmap(s.as_ref(), &analysis(s.as_ref(), 5), 5).unwrap();
    assert_eq!(c.c1, Verdict::Proved);
}
