//! Doo–Sabin against closed forms (Doo & Sabin 1978):
//! - the central n-gon's matrix is circulant with eigenvalues
//!   Σ_j α_j ω^{jm} = 1 (m = 0), 1/2 (m = ±1), 1/4 otherwise;
//! - the limit point of the central face is its centroid (left eigenvector of
//!   a circulant is a Fourier mode);
//! - valence 4 is the biquadratic tensor product of Chaikin's local spectrum
//!   {1, 1/2, 1/4, 1/4}.

use crate::common;
use approx::assert_abs_diff_eq;
use common::*;
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::spectrum::stencils::{limit_stencil, tangent_stencils};

#[test]
fn central_face_spectrum_for_valences_3_to_50() {
    for n in 3..=50 {
        let a = run("doo-sabin", n, NeighbourhoodKind::Minimal, None, false);
        assert_eq!(a.spectrum.matrix_size, n);
        let mut want = vec![1.0, 0.5, 0.5];
        want.extend(std::iter::repeat_n(0.25, n - 3));
        assert_same_multiset(real_spectrum(&a), want, 1e-11, &format!("DS n={n}"));
        assert!(a.spectrum.verdict.c1_spectral);
    }
}

#[test]
fn analysis_neighbourhood_is_the_one_ring_of_faces() {
    for n in 3..=50 {
        let a = run("doo-sabin", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.spectrum.matrix_size, 4 * n, "4n at n = {n}");
        assert_abs_diff_eq!(a.spectrum.eigenvalues[1].re, 0.5, epsilon = 1e-11);
        assert_eq!(a.spectrum.eigenvalues[1].algebraic_multiplicity, 2);
    }
}

#[test]
fn limit_point_is_the_centroid_and_tangents_are_fourier_modes() {
    for n in 3..=50 {
        let a = run("doo-sabin", n, NeighbourhoodKind::Analysis, None, false);
        let l = limit_stencil(&a.spectrum).unwrap();
        let mut cos_form = vec![0.0; l.len()];
        let mut sin_form = vec![0.0; l.len()];
        for (k, lab) in a.spectrum.labels.iter().enumerate() {
            let want = if lab.ring == 0 { 1.0 / n as f64 } else { 0.0 };
            assert!((l[k] - want).abs() < 1e-12, "{} at n = {n}", lab.name);
            if lab.ring == 0 {
                cos_form[k] = cos2pi(lab.sector, n);
                sin_form[k] = sin2pi(lab.sector, n);
            }
        }
        for v in tangent_stencils(&a.spectrum).unwrap() {
            assert!(in_span(&[cos_form.clone(), sin_form.clone()], &v), "n = {n}");
        }
    }
}

#[test]
fn regular_valence_is_the_biquadratic_tensor_product() {
    let a = run("doo-sabin", 4, NeighbourhoodKind::Analysis, None, true);
    let chaikin = [1.0, 0.5, 0.25, 0.25];
    assert_same_multiset(real_spectrum(&a), products(&chaikin, &chaikin), 1e-12, "DS n=4");
    assert_eq!(a.spectrum.exact_analysis.as_ref().unwrap().remaining_degree, 0);
}
