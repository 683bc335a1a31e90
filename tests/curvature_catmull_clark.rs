//! Second-order analysis of Catmull–Clark against the closed forms of its
//! Fourier blocks on the 2n + 1 points v, e_j (edge neighbours), f_j (face
//! neighbours).
//!
//! Block m ≥ 1 (θ = 2πm/n, ω = e^{iθ}, v drops out): the face point
//! F_j = (v + e_j + f_j + e_{j+1})/4 = ω^j (e(1 + ω) + f)/4 and the edge point
//! E_j = (v + e_j + F_{j−1} + F_j)/4 give
//!   e' = (3 + cos θ)/8 e + (1 + ω̄)/16 f,   f' = (1 + ω)/4 e + 1/4 f,
//! with trace (5 + cos θ)/8 and determinant (3 + cos θ)/32 − (2 + 2cos θ)/64 = 1/16:
//!   p±(m) = (5 + cos θ ± sqrt((1 + cos θ)(9 + cos θ)))/16,
//! and λ = p+(1) = (5 + cos(2π/n) + cos(π/n) sqrt(18 + 2cos(2π/n)))/16.
//!
//! Block 0 (v, e, f): v' = (Q + 2R + (n − 3)v)/n with Q = (v + 2e + f)/4,
//! R = (v + e)/2, so v' = ((n − 7/4)v + 3/2 e + 1/4 f)/n; e' = (3v + 4e + f)/8;
//! f' = (v + 2e + f)/4. Besides 1 its eigenvalues have sum 3/4 − 7/(4n) and
//! product det = (n − 3)/(16n):
//!   r± = (3n − 7 ± sqrt(5n² − 30n + 49))/(8n)   (n = 4: 1/4 and 1/16).
//!
//! The analysis neighbourhood (6n + 1) adds the outer points; their
//! eigenvalues are not derived here. The test asserts that the computed μ is
//! the largest of the closed forms above (other than λ), which fails if an
//! outer eigenvalue were larger.

use crate::common;

use std::f64::consts::PI;

use subdlab::curvature::{curvature_of, Curvature, CurvatureClass, CurvatureOptions};
use subdlab::schemes;

fn p(m: usize, n: usize, sign: f64) -> f64 {
    let c = (2.0 * PI * m as f64 / n as f64).cos();
    (5.0 + c + sign * ((1.0 + c) * (9.0 + c)).sqrt()) / 16.0
}
fn lam(n: usize) -> f64 {
    let (c, h) = ((2.0 * PI / n as f64).cos(), (PI / n as f64).cos());
    (5.0 + c + h * (18.0 + 2.0 * c).sqrt()) / 16.0
}
fn r0(n: usize) -> f64 {
    let n = n as f64;
    (3.0 * n - 7.0 + (5.0 * n * n - 30.0 * n + 49.0).sqrt()) / (8.0 * n)
}

/// μ and F(μ) from the closed forms: every block eigenvalue but λ itself.
fn expected(n: usize) -> (f64, Vec<usize>) {
    let mut cands: Vec<(f64, usize)> = vec![(r0(n), 0)];
    for m in 1..n {
        if m != 1 && m != n - 1 {
            cands.push((p(m, n, 1.0), m));
        }
        cands.push((p(m, n, -1.0), m));
    }
    let mu = cands.iter().map(|c| c.0).fold(0.0, f64::max);
    let mut f: Vec<usize> = cands.iter().filter(|c| (c.0 - mu).abs() < 1e-12).map(|c| c.1).collect();
    f.sort_unstable();
    f.dedup();
    (mu, f)
}

fn run(n: usize) -> Curvature {
    let s = schemes::build("catmull-clark", &[]).unwrap();
    curvature_of(s.as_ref(), n, &CurvatureOptions::default()).unwrap()
}

#[test]
fn classes_three_to_twenty_follow_the_block_closed_forms() {
    assert!((lam(7) - p(1, 7, 1.0)).abs() < 1e-15);
    for n in 3..=20 {
        let c = run(n);
        let (mu, f) = expected(n);
        let l2 = lam(n) * lam(n);
        assert!((c.lambda.unwrap() - lam(n)).abs() < 1e-12, "n = {n}");
        let m = c.mu.as_ref().unwrap();
        assert!((m.modulus - mu).abs() < 1e-10, "n = {n}: μ = {} against {mu}", m.modulus);
        let want = common::class_from_closed_forms(mu, l2);
        assert_eq!(c.class, want, "n = {n}");
        assert_eq!(c.shapes.as_ref().unwrap().fourier_index, f, "n = {n}");
        if want == CurvatureClass::Unbounded {
            let p_star = 2.0 * lam(n).ln() / (2.0 * lam(n).ln() - mu.ln());
            assert!((c.lp_limit.unwrap() - p_star).abs() < 1e-8, "n = {n}");
        } else {
            assert!(c.lp_limit.is_none());
        }
    }
}

#[test]
fn known_classes_with_their_margins() {
    // n = 3: r+ = (2 + 2)/24 = 1/6 < λ² = ((4.5 + sqrt 17 / 2)/16)² ≈ 0.16818:
    // a flat spot (a wrong comparison by under 1 % would call it bounded)
    let c3 = run(3);
    assert!(1.0 / 6.0 < lam(3) * lam(3) && lam(3) * lam(3) < 1.0 / 6.0 * 1.01);
    assert_eq!(c3.class, CurvatureClass::Zero);
    assert_eq!(c3.shapes.unwrap().fourier_index, vec![0]);
    // n = 4: bicubic; 1/4 from block 0 and (double) block 2
    let c4 = run(4);
    assert_eq!(c4.class, CurvatureClass::Bounded);
    assert!(c4.shapes.unwrap().necessary_condition);
    // n ≥ 5: μ = p+(2) from blocks 2 and n − 2 only: no block 0, so only
    // saddle-like central shapes (elliptic input turns hyperbolic, KPR 2004)
    for n in [5, 6, 9, 16] {
        let c = run(n);
        assert_eq!(c.class, CurvatureClass::Unbounded, "n = {n}");
        let s = c.shapes.unwrap();
        assert_eq!(s.fourier_index, vec![2, n - 2]);
        assert!(!s.elliptic_possible && s.saddle_possible && !s.necessary_condition);
    }
}

#[test]
fn regular_valence_passes_the_c2_test_and_five_does_not() {
    let t = run(4).c2.unwrap();
    assert!(t.holds && t.quadratic && t.spans_quadratics, "{:?}", t.reasons);
    assert!(t.max_residual.unwrap() < 1e-9);
    // n = 5: unbounded, and λ² is not an eigenvalue at all
    let t5 = run(5).c2.unwrap();
    assert!(!t5.holds && t5.fits.is_empty() && !t5.spans_quadratics);
}

#[test]
fn cost_at_valence_twenty_is_well_under_a_second() {
    let s = schemes::build("catmull-clark", &[]).unwrap();
    let t = std::time::Instant::now();
    let c = curvature_of(s.as_ref(), 20, &CurvatureOptions::default()).unwrap();
    let secs = t.elapsed().as_secs_f64();
    assert_eq!(c.class, CurvatureClass::Unbounded);
    // generous for a loaded 2-core machine; measured 0.06 s in release
    assert!(secs < 2.0, "{secs} s");
}
