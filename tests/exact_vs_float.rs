//! The floating-point multiplicities (clustering + null spaces) must agree
//! with the exact ones (characteristic polynomial over Q, exact ranks) wherever
//! S is rational; both paths are independent computations.

use crate::common;
use common::*;
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::spectrum::Method;

#[test]
fn float_and_exact_multiplicities_agree() {
    for (scheme, valences) in
        [("catmull-clark", vec![3, 4, 5, 6, 7, 8]), ("loop", vec![3, 4, 6]), ("doo-sabin", vec![3, 4, 6])]
    {
        for n in valences {
            for method in [Method::Dft, Method::Full] {
                let a = run(scheme, n, NeighbourhoodKind::Analysis, Some(method), true);
                let x = a.spectrum.exact_analysis.as_ref().expect("rational weights");
                assert!(x.agrees_with_float, "{scheme} n={n} {method:?}: {:?}", x.rational_roots);
                // every proven root is in the float spectrum with the same multiplicities
                for r in &x.rational_roots {
                    let e = a.spectrum.eigenvalues.iter().find(|e| e.exact.as_deref() == Some(r.value.as_str()));
                    let e = e.unwrap_or_else(|| panic!("{scheme} n={n}: root {} not matched", r.value));
                    assert_eq!(e.algebraic_multiplicity, r.algebraic_multiplicity);
                    assert_eq!(Some(e.geometric_multiplicity), r.geometric_multiplicity);
                }
            }
        }
    }
}

#[test]
fn doo_sabin_quarter_is_defective_at_valence_6() {
    // found by the exact rank: 1/4 has algebraic multiplicity 9 but only a
    // 7-dimensional eigenspace on the 4n neighbourhood; the float path must say so
    let a = run("doo-sabin", 6, NeighbourhoodKind::Analysis, None, true);
    let x = a.spectrum.exact_analysis.as_ref().unwrap();
    let q = x.rational_roots.iter().find(|r| r.value == "1/4").unwrap();
    assert!(q.geometric_multiplicity.unwrap() < q.algebraic_multiplicity);
    let e = a.spectrum.eigenvalues.iter().find(|e| e.exact.as_deref() == Some("1/4")).unwrap();
    assert!(e.defective);
}

/// Above the whole-matrix limit (80 rows) a rotation-symmetric S is confirmed
/// on Fourier block 0 only. Catmull–Clark's analysis neighbourhood has
/// 6n + 1 rows: 79 at n = 13 (whole S), 85 at n = 14 and 97 at n = 16
/// (block 0). Affine invariance puts the eigenvalue 1, simple, in block 0
/// (constant data is the block-0 pattern), so block 0's exact polynomial has
/// the root 1 once, and the float analysis must agree that 1 lies in block 0.
/// Every rational root of block 0 must be a float eigenvalue listed in block
/// 0 with at least that multiplicity (the check is not vacuous in this mode).
#[test]
fn block_zero_confirmation_above_the_whole_matrix_limit() {
    let a = run("catmull-clark", 13, NeighbourhoodKind::Analysis, Some(Method::Dft), true);
    assert_eq!(a.spectrum.exact_analysis.as_ref().unwrap().method, "full");
    for n in [14, 16] {
        let a = run("catmull-clark", n, NeighbourhoodKind::Analysis, Some(Method::Dft), true);
        let x = a.spectrum.exact_analysis.as_ref().unwrap();
        assert_eq!(x.method, "block0", "n = {n}");
        // block 0 has one orbit per vertex class of a sector: (6n + 1 − 1)/n + 1 = 7 rows
        assert_eq!(x.polynomial_degree, 7, "n = {n}");
        assert!(x.agrees_with_float, "n = {n}: {:?}", x.rational_roots);
        let one = x.rational_roots.iter().find(|r| r.value == "1").expect("1 is a root of block 0");
        assert_eq!(one.algebraic_multiplicity, 1);
        for r in &x.rational_roots {
            let e = a.spectrum.eigenvalues.iter().find(|e| e.exact.as_deref() == Some(r.value.as_str())).unwrap();
            assert!(
                e.blocks.contains(&0) && e.algebraic_multiplicity >= r.algebraic_multiplicity,
                "n = {n}: {}",
                r.value
            );
        }
    }
}
