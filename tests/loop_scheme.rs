//! Loop subdivision against closed forms (Loop 1987; Schweitzer 1996):
//! - the one-ring matrix has eigenvalues 1, (3/8 + cos(2π/n)/4)^2 = 5/8 − nβ
//!   (block 0) and 3/8 + cos(2πm/n)/4 for m = 1..n−1;
//! - limit stencil: centre 1 − nχ, each neighbour χ = 1/(n + 3/(8β));
//! - tangent stencils: cos(2πi/n), sin(2πi/n) on the one-ring.

use crate::common;
use approx::assert_abs_diff_eq;
use common::*;
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::spectrum::stencils::{limit_stencil, tangent_stencils};

fn beta(n: usize) -> f64 {
    let t = 0.375 + 0.25 * cos2pi(1, n);
    (0.625 - t * t) / n as f64
}

#[test]
fn one_ring_spectrum_matches_closed_form_for_valences_3_to_50() {
    for n in 3..=50 {
        let a = run("loop", n, NeighbourhoodKind::Minimal, None, false);
        assert_eq!(a.spectrum.matrix_size, n + 1);
        let b = beta(n);
        let mut want = vec![1.0, 0.625 - n as f64 * b];
        want.extend((1..n).map(|m| 0.375 + 0.25 * cos2pi(m, n)));
        assert_same_multiset(real_spectrum(&a), want, 1e-11, &format!("Loop n={n}"));
        let l1 = 0.375 + 0.25 * cos2pi(1, n);
        assert_abs_diff_eq!(a.spectrum.verdict.subdominant.unwrap(), l1, epsilon = 1e-12);
        assert!(a.spectrum.verdict.c1_spectral);
    }
}

#[test]
fn analysis_neighbourhood_is_the_two_ring() {
    for n in 3..=50 {
        let a = run("loop", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.spectrum.matrix_size, 3 * n + 1, "3n+1 at n = {n}");
        let l1 = 0.375 + 0.25 * cos2pi(1, n);
        assert_abs_diff_eq!(a.spectrum.eigenvalues[1].re, l1, epsilon = 1e-11);
    }
}

#[test]
fn limit_and_tangent_stencils() {
    for n in 3..=50 {
        let a = run("loop", n, NeighbourhoodKind::Analysis, None, false);
        let chi = 1.0 / (n as f64 + 3.0 / (8.0 * beta(n)));
        let l = limit_stencil(&a.spectrum).unwrap();
        let mut cos_form = vec![0.0; l.len()];
        let mut sin_form = vec![0.0; l.len()];
        for (k, lab) in a.spectrum.labels.iter().enumerate() {
            let want = match lab.ring {
                0 => 1.0 - n as f64 * chi,
                1 => chi,
                _ => 0.0,
            };
            assert!((l[k] - want).abs() < 1e-12, "limit weight {} at n = {n}", lab.name);
            if lab.ring == 1 {
                cos_form[k] = cos2pi(lab.sector, n);
                sin_form[k] = sin2pi(lab.sector, n);
            }
        }
        let t = tangent_stencils(&a.spectrum).unwrap();
        assert_eq!(t.len(), 2);
        for v in &t {
            assert!(in_span(&[cos_form.clone(), sin_form.clone()], v), "n = {n}");
        }
    }
}

#[test]
fn exact_path_at_valence_6_proves_the_regular_spectrum() {
    // n = 6: cos(π/3) = 1/2 is rational, so every weight is (β = 1/16)
    let a = run("loop", 6, NeighbourhoodKind::Minimal, None, true);
    let x = a.spectrum.exact_analysis.as_ref().expect("rational at n = 6");
    // 3/8 + cos(2πm/6)/4 for m = 1..5: 1/2, 1/4, 1/8, 1/4, 1/2 ; block 0: 1 and (1/2)^2
    let mult = |v: &str| x.rational_roots.iter().find(|r| r.value == v).map(|r| r.algebraic_multiplicity);
    assert_eq!(mult("1"), Some(1));
    assert_eq!(mult("1/2"), Some(2));
    assert_eq!(mult("1/4"), Some(3));
    assert_eq!(mult("1/8"), Some(1));
    assert_eq!(x.remaining_degree, 0);
}
