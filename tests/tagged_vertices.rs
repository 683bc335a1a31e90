//! Tagged vertices (issue 26): the local subdivision matrix at a boundary,
//! corner or crease vertex, assembled from the schemes' crease rules
//! (Hoppe et al. 1994; OpenSubdiv's Sdc rules with infinite sharpness), no
//! rotation symmetry, analysed whole.
//!
//! Expected values come from the literature, not from the program:
//! - Along a sharp ray the crease rules are the cubic B-spline curve's
//!   ((1, 6, 1)/8 at a vertex, (1, 1)/2 at an edge) and read no vertex off
//!   the ray, so the rows of the ray vertices are the curve's subdivision
//!   matrix exactly, and S is block triangular: the curve's spectrum
//!   (1, 1/2, 1/4, then 1/8 on a 5-point window) is part of S's.
//! - A corner keeps its place (row = identity), and each ray is then an
//!   end-interpolating cubic B-spline: 1/2 once per ray (the two tangents).
//! - At the regular boundary (2 quads for Catmull–Clark, 3 triangles for
//!   Loop) the linear functions x along the boundary and y across it are
//!   reproduced by the smooth interior rules and the curve rule alike, so
//!   1/2 is double, and everything else is at most 1/4 (products of the
//!   curve's and the half-line's eigenvalues).

use approx::assert_relative_eq;
use subdlab::neighbourhood::{Configuration, Tagging};
use subdlab::numeric::exact::q;
use subdlab::numeric::Rational;
use subdlab::schemes;
use subdlab::spectrum::{analyse, Analysis, Options};

fn tagged(scheme: &str, k: usize, tagging: Tagging) -> Analysis {
    let s = schemes::build(scheme, &[]).unwrap();
    let config = Configuration::tagged(s.as_ref(), k, None, tagging).unwrap();
    analyse(s.as_ref(), &config, &Options::default()).unwrap()
}

/// Signed position along the sharp curve through the centre of an open
/// fan of k sectors (sector 0's ray positive, the ray after the last
/// sector negative), or None off the curve.
fn curve_position(sector: usize, i: i64, j: i64, k: usize) -> Option<i64> {
    match (sector, i, j) {
        (_, 0, 0) => Some(0),
        (0, i, 0) => Some(i),
        (s, i, 0) if s == k => Some(-i),
        _ => None,
    }
}

/// Weight of old curve point `from` in new curve point `to` under the cubic
/// B-spline rules (vertex (1, 6, 1)/8, edge (1, 1)/2), with position 0 held
/// fixed at a corner.
fn curve_weight(to: i64, from: i64, corner: bool) -> Rational {
    if corner && to == 0 {
        return if from == 0 { q(1, 1) } else { q(0, 1) };
    }
    if to % 2 == 0 {
        match (from - to / 2).abs() {
            0 => q(6, 8),
            1 => q(1, 8),
            _ => q(0, 1),
        }
    } else {
        let (a, b) = ((to - 1) / 2, (to + 1) / 2);
        if from == a || from == b {
            q(1, 2)
        } else {
            q(0, 1)
        }
    }
}

/// The rows of the curve's vertices are the cubic B-spline curve rules
/// exactly, and read nothing off the curve (S is block triangular), at
/// boundary and corner vertices of 1..6 sectors of Catmull–Clark and Loop.
#[test]
fn the_boundary_rows_are_the_cubic_b_spline_curve_alone() {
    for scheme in ["catmull-clark", "loop"] {
        for tagging in [Tagging::Boundary, Tagging::Corner] {
            for k in 1..=6 {
                let a = tagged(scheme, k, tagging);
                let s = a.exact_matrix.as_ref().expect("rational rules");
                let pos: Vec<Option<i64>> = s.labels.iter().map(|l| curve_position(l.sector, l.i, l.j, k)).collect();
                let on_curve = pos.iter().filter(|p| p.is_some()).count();
                assert!(
                    on_curve >= 3,
                    "{scheme} {k} {tagging:?}: the curve has {on_curve} points in the neighbourhood"
                );
                for (r, pr) in pos.iter().enumerate() {
                    let Some(to) = *pr else { continue };
                    for (c, pc) in pos.iter().enumerate() {
                        let want = match *pc {
                            Some(from) => curve_weight(to, from, tagging == Tagging::Corner),
                            None => q(0, 1),
                        };
                        assert_eq!(
                            s.get(r, c),
                            want,
                            "{scheme} {tagging:?} k = {k}: S[{}][{}]",
                            s.labels[r].name,
                            s.labels[c].name
                        );
                    }
                }
            }
        }
    }
}

fn has_eigenvalue(a: &Analysis, value: f64, at_least: usize) -> bool {
    a.spectrum
        .eigenvalues
        .iter()
        .any(|e| e.is_real() && (e.re - value).abs() < 1e-9 && e.algebraic_multiplicity >= at_least)
}

/// The curve's eigenvalues are S's: 1, 1/2 and 1/4 at every boundary
/// vertex; at a corner 1/2 twice (one tangent per ray) and 1 simple.
#[test]
fn the_curve_spectrum_is_part_of_the_tagged_spectrum() {
    for scheme in ["catmull-clark", "loop"] {
        for k in 1..=6 {
            let b = tagged(scheme, k, Tagging::Boundary);
            for v in [1.0, 0.5, 0.25] {
                assert!(has_eigenvalue(&b, v, 1), "{scheme} boundary k = {k}: no eigenvalue {v}");
            }
            assert_eq!(b.spectrum.eigenvalues[0].algebraic_multiplicity, 1, "{scheme} boundary k = {k}");
            let c = tagged(scheme, k, Tagging::Corner);
            assert!(has_eigenvalue(&c, 0.5, 2), "{scheme} corner k = {k}: 1/2 is not double");
            assert_relative_eq!(c.spectrum.eigenvalues[0].re, 1.0, epsilon = 1e-12);
            assert_eq!(c.spectrum.eigenvalues[0].algebraic_multiplicity, 1, "{scheme} corner k = {k}");
        }
    }
}

/// The regular boundary (CC: 2 quads, Loop: 3 triangles): λ1 = λ2 = 1/2,
/// |λ3| = 1/4, and the sector criterion's spectral part passes.
#[test]
fn the_regular_boundary_has_a_double_half() {
    for (scheme, k) in [("catmull-clark", 2), ("loop", 3)] {
        let a = tagged(scheme, k, Tagging::Boundary);
        let e = &a.spectrum.eigenvalues;
        assert_relative_eq!(e[0].re, 1.0, epsilon = 1e-12);
        assert_relative_eq!(e[1].re, 0.5, epsilon = 1e-12);
        assert_eq!(e[1].algebraic_multiplicity, 2, "{scheme}: {e:?}");
        assert_relative_eq!(e[2].modulus, 0.25, epsilon = 1e-12);
        let v = &a.spectrum.verdict;
        assert_eq!(v.criterion, "sector");
        assert!(v.c1_spectral, "{scheme}: {:?}", v.reasons);
    }
}
