//! Second-order analysis of Loop subdivision against closed forms.
//!
//! Derivation (the expected values below come from here, not from the
//! program). On the 1-ring (n + 1 points) Loop's rules are circulant:
//! - edge point next to the centre v: 3/8 v + 3/8 e_j + 1/8 (e_{j−1} + e_{j+1}),
//!   so Fourier block m ≥ 1 has the eigenvalue b(m) = 3/8 + cos(2πm/n)/4;
//!   λ = b(1) (blocks 1 and n − 1);
//! - block 0 on (v, mean e): [[1 − nβ, nβ], [3/8, 5/8]] has eigenvalues 1 and
//!   5/8 − nβ, and Loop's β = (5/8 − λ²)/n makes that exactly λ².
//!
//! The analysis neighbourhood (3n + 1 points) adds ring 2: a_j opposite the
//! edge e_j e_{j+1} and b_j beyond e_j on the spoke. After one step the new
//! a_j is the edge point of e_j e_{j+1}, 3/8 (e_j + e_{j+1}) + 1/8 (v + a_j),
//! and the new b_j the vertex point of the regular e_j, 5/8 e_j + 1/16 (its
//! six neighbours v, e_{j±1}, a_{j−1}, a_j, b_j). So the ring-2 part of S is
//! lower triangular: a_j → 1/8 a_j, b_j → 1/16 b_j + (a terms): eigenvalues
//! 1/8 and 1/16 in every block. Their eigenvectors are zero on rings 0 and 1
//! but carry a_j, b_j, whose box-spline basis functions reach over the first
//! ring of triangles, so they do not vanish on the characteristic ring.
//!
//! Hence, for n ≥ 4: μ = max(λ², b(2), 1/8) (b(m) decreases in min(m, n − m));
//! for n = 3 blocks 1 and 2 both carry λ, and μ = max(λ², 1/8) = 1/8 since
//! λ = 3/8 − 1/8 = 1/4, λ² = 1/16.

use crate::common;

use std::f64::consts::PI;

use subdlab::curvature::{curvature_of, Curvature, CurvatureClass, CurvatureOptions, Evidence};
use subdlab::schemes;

fn lam(n: usize) -> f64 {
    b(1, n)
}
fn b(m: usize, n: usize) -> f64 {
    3.0 / 8.0 + (2.0 * PI * m as f64 / n as f64).cos() / 4.0
}

fn run(n: usize) -> Curvature {
    let s = schemes::build("loop", &[]).unwrap();
    curvature_of(s.as_ref(), n, &CurvatureOptions::default()).unwrap()
}

/// The expected μ and F(μ) from the closed forms.
fn expected(n: usize) -> (f64, Vec<usize>) {
    let l2 = lam(n) * lam(n);
    let eighth = 1.0 / 8.0;
    if n == 3 {
        return (eighth, vec![0, 1, 2]);
    }
    let mu = l2.max(b(2, n)).max(eighth);
    let eq = |x: f64| (x - mu).abs() < 1e-12;
    let mut f = Vec::new();
    if eq(l2) {
        f.push(0);
    }
    for m in 1..n {
        if eq(b(m, n)) && m != 1 && m != n - 1 {
            f.push(m);
        }
    }
    if eq(eighth) {
        f = (0..n).collect();
    }
    f.sort_unstable();
    f.dedup();
    (mu, f)
}

#[test]
fn block_two_overtakes_lambda_squared_at_seven() {
    // b(2) = λ² at n = 6: cos(2π/3) = −1/2 gives b(2) = 1/4 = (1/2)²; the
    // first valence where b(2) > λ² is therefore computed, not assumed
    let threshold = (4..=40).find(|&n| b(2, n) > lam(n) * lam(n) + 1e-12).unwrap();
    assert_eq!(threshold, 7);
    for n in 3..=20 {
        let c = run(n);
        let l2 = lam(n) * lam(n);
        let (mu, f) = expected(n);
        let m = c.mu.as_ref().unwrap_or_else(|| panic!("n = {n}: no μ"));
        assert!((c.lambda.unwrap() - lam(n)).abs() < 1e-12, "n = {n}");
        assert!((m.modulus - mu).abs() < 1e-10, "n = {n}: μ {} against {mu}", m.modulus);
        let want = common::class_from_closed_forms(mu, l2);
        assert_eq!(c.class, want, "n = {n}");
        // the class changes exactly at the threshold (n = 3 is the ring-2 case)
        if n >= 4 {
            assert_eq!(c.class == CurvatureClass::Unbounded, n >= threshold, "n = {n}");
        }
        assert_eq!(c.shapes.as_ref().unwrap().fourier_index, f, "n = {n}");
        match c.lp_limit {
            Some(p) => {
                let want = 2.0 * lam(n).ln() / (2.0 * lam(n).ln() - mu.ln());
                assert!((p - want).abs() < 1e-8, "n = {n}: p* {p} against {want}");
            }
            None => assert_ne!(c.class, CurvatureClass::Unbounded, "n = {n}"),
        }
    }
}

#[test]
fn valence_three_is_unbounded_through_ring_two() {
    // λ = 1/4, μ = 1/8 > λ² = 1/16: p* = 2 ln(1/4) / (2 ln(1/4) − ln(1/8))
    // = −4 ln 2 / (−4 ln 2 + 3 ln 2) = 4; all three blocks carry 1/8
    let c = run(3);
    assert_eq!(c.class, CurvatureClass::Unbounded);
    assert!((c.lp_limit.unwrap() - 4.0).abs() < 1e-9);
    // both rational and confirmed by the exact path (3n + 1 = 10 points)
    assert_eq!(c.evidence, Evidence::Exact);
    let m = c.mu.unwrap();
    assert_eq!(m.exact.as_deref(), Some("1/8"));
    // negative control for the vanishing test: the ring-2 eigenvectors are
    // zero on rings 0 and 1 and must still count
    assert!(!m.vanishes && m.ring_size > 1e-3, "ring size {}", m.ring_size);
    assert!(c.shapes.unwrap().necessary_condition);
}

#[test]
fn valences_four_and_five_are_bounded_but_only_elliptic() {
    // n = 4: λ = 3/8, λ² = 9/64 > 1/8 = b(2); n = 5: λ² = 0.2045 > b(2) = 0.1727 > 1/8
    for n in [4, 5] {
        let c = run(n);
        assert_eq!(c.class, CurvatureClass::Bounded, "n = {n}");
        assert_eq!(c.curvature_converges, Some(true));
        let s = c.shapes.unwrap();
        assert_eq!(s.fourier_index, vec![0]);
        assert!(s.elliptic_possible && !s.saddle_possible && !s.necessary_condition);
        // Loop is not C² off the regular valence: the block-0 eigenfunction is
        // not a quadratic in the characteristic map (negative control: a fit
        // that accepted everything would pass here)
        let t = c.c2.unwrap();
        assert!(!t.holds && !t.quadratic, "n = {n}");
        assert!(t.max_residual.unwrap() > 1e-4, "n = {n}: residual {:?}", t.max_residual);
    }
}

#[test]
fn regular_valence_passes_the_c2_test() {
    // n = 6 is the quartic box spline: λ = 1/2, and 1/4 = λ² in blocks 0, 2, 4
    // with the eigenfunctions x² + y², Re/Im (x + iy)²
    let c = run(6);
    assert_eq!(c.class, CurvatureClass::Bounded);
    let t = c.c2.unwrap();
    assert!(t.holds && t.quadratic && t.spans_quadratics, "{:?}", t.reasons);
    assert!(t.max_residual.unwrap() < 1e-9);
    // one real function from block 0, real and imaginary parts from 2 and 4
    let mut blocks: Vec<usize> = t.fits.iter().map(|f| f.block).collect();
    blocks.dedup();
    assert_eq!(blocks, vec![0, 2, 4]);
}
