//! The floating-point multiplicities (clustering + null spaces) must agree
//! with the exact ones (characteristic polynomial over Q, exact ranks) wherever
//! S is rational; both paths are independent computations.

mod common;
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
