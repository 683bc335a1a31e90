//! A Jordan block at λ² that shows on the ring: Peters–Shiue's 4-3 scheme at
//! an all-quad extraordinary vertex (eon) of valence n.
//!
//! Derivation on the 1-ring (v; edge neighbours e_j; face neighbours f_j):
//! - eon rule: v' = α v + (1 − α)/n Σ e_j;
//! - edge point next to the eon (rule 4b): (2v + e_i + Σ_j β_{i−j} e_j)/4 with
//!   β_k = (1 + 2cos(2πk/n))/n, whose Fourier transform is 1 in blocks 0, ±1
//!   and 0 in every other block;
//! - face point: (v + e_i + f_i + e_{i+1})/4.
//!
//! Block m ≥ 2 (ω = e^{2πim/n}, v drops out): e' = e/4, f' = (1 + ω)/4 e + f/4,
//! i.e. [[1/4, 0], [(1 + ω)/4, 1/4]]: the eigenvalue 1/4 with a Jordan block
//! whenever ω ≠ −1, whose top eigenvector is the pure f-direction. Block 1:
//! e' = (1 + 1)/4 e = e/2, so λ = 1/2 and λ² = 1/4. The face neighbours are
//! corners of the first-ring quads, so their basis functions do not vanish on
//! the ring: S^m carries m (1/4)^(m−1) on a visible eigenfunction and the
//! curvature grows like m (unbounded, yet in L_p for every finite p).
//!
//! At n = 4 block 2 has ω = −1: diag(1/4, 1/4), no Jordan block there (and
//! blocks 1 and 3 are non-defective): the class is bounded.

use subdlab::curvature::{curvature_of, CurvatureClass, CurvatureOptions};
use subdlab::schemes;

#[test]
fn four_three_eon_jordan_block_shows_on_the_ring() {
    let s = schemes::build("four-three", &[]).unwrap();
    for n in [5, 6, 7] {
        let c = curvature_of(s.as_ref(), n, &CurvatureOptions::default()).unwrap();
        assert!((c.lambda.unwrap() - 0.5).abs() < 1e-12, "n = {n}");
        assert_eq!(c.class, CurvatureClass::Unbounded, "n = {n}: {:?}", c.reasons);
        assert!(c.lp_limit.is_none(), "a Jordan block at λ² leaves every finite p");
        let e = c.examined.iter().find(|e| (e.modulus - 0.25).abs() < 1e-9).unwrap();
        assert!(e.defective && e.jordan_visible == Some(true), "n = {n}");
        // the chains sit in blocks 2..n−2
        for m in 2..=n - 2 {
            assert!(e.ring_blocks.contains(&m), "n = {n}: block {m}");
        }
        assert!(!c.c2.unwrap().holds);
    }
    // negative control: no Jordan block at n = 4
    let c = curvature_of(s.as_ref(), 4, &CurvatureOptions::default()).unwrap();
    assert_eq!(c.class, CurvatureClass::Bounded, "{:?}", c.reasons);
    assert!(c.examined.iter().all(|e| e.jordan_visible.is_none()));
}

#[test]
fn four_three_regular_box_spline_configurations_pass_the_c2_test() {
    // The regular quad (valence 4, all quads) and triangle (valence 6, all
    // triangles) configurations of 4-3 are box-spline subdivision (A_4 and
    // A_3 of Peters–Shiue): the characteristic map is linear, λ = 1/2, and the
    // eigenfunctions of λ² = 1/4 are exactly x², xy, y² of it.
    use subdlab::curvature::curvature;
    use subdlab::neighbourhood::Configuration;
    let s = schemes::build("four-three", &[]).unwrap();
    for (n, faces) in [(4, "QQQQ"), (6, "TTTTTT")] {
        let config = Configuration::with_faces(s.as_ref(), n, faces).unwrap();
        let c = curvature(s.as_ref(), &config, &CurvatureOptions::default()).unwrap();
        assert!((c.lambda.unwrap() - 0.5).abs() < 1e-12, "{faces}");
        assert_eq!(c.class, CurvatureClass::Bounded, "{faces}");
        let t = c.c2.unwrap();
        assert!(t.holds && t.spans_quadratics && t.max_residual.unwrap() < 1e-9, "{faces}: {:?}", t.reasons);
    }
    // negative control: the eon of valence 5 (Jordan block above) fails
    let c = curvature(
        s.as_ref(),
        &Configuration::with_faces(s.as_ref(), 5, "QQQQQ").unwrap(),
        &CurvatureOptions::default(),
    )
    .unwrap();
    assert!(!c.c2.unwrap().holds);
}
