//! What the analysis neighbourhood of a sqrt(3) scheme is, and why the verdicts
//! do not depend on taking a larger one.
//!
//! sqrt(3) refinement flips the old edges, so the faces that descend from the
//! first ring (the faces touching the centre) cover less than the first ring:
//! after one analysis step (two refinements) the descendants of a first-ring
//! triangle are the small triangles built from its own vertices and face
//! points, and the region they converge to is a smaller neighbourhood D of the
//! centre. The analysis neighbourhood is the invariant closure of the control
//! points that determine the limit over D: 3n + 1 points (rings 0..2) for
//! Kobbelt's rules, while the limit over the whole first ring of faces also
//! involves ring 3 (6n + 1 points in all).
//!
//! Why either set gives the same verdicts: let the small set A (the analysis
//! neighbourhood) be invariant inside a larger invariant set B. Ordering B as
//! (A, B \ A), the rows of A only use columns of A, so
//!     S_B = [[S_A, 0], [X, C]],
//! spec(S_B) = spec(S_A) ∪ spec(C), and a right eigenvector (x, y) of S_B has
//! S_A x = λ x. When every eigenvalue of C is smaller in modulus than the
//! subdominant λ1, the dominant and subdominant eigenvectors of S_B restrict
//! to those of S_A, the spectral test sees the same leading eigenvalues, and
//! the characteristic ring over D (determined by A alone) is the same map.
//! The test builds B = rings 0..3, checks that it is invariant (assembly on B
//! fails otherwise), that it has 6n + 1 points, that spec(S_A) ⊂ spec(S_B), and
//! that every further eigenvalue is below λ1 in modulus.

use subdlab::matrix::assemble;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::schemes;
use subdlab::spectrum::{decompose, Method};

fn moduli(m: &subdlab::matrix::LocalMatrix<f64>, n: usize) -> Vec<f64> {
    let d = decompose(m, n, n, Method::Full).unwrap();
    let mut m: Vec<f64> =
        d.eigenvalues.iter().flat_map(|e| std::iter::repeat_n(e.modulus, e.algebraic_multiplicity)).collect();
    m.sort_by(|a, b| b.total_cmp(a)); // descending: m[0] = 1, m[1] = λ1
    m
}

/// Checks the claim for the set B of rings 0..=r_max + 1, r_max the outermost
/// ring of the analysis set A; returns |B|.
fn check(name: &str, params: &[(String, String)], n: usize) -> usize {
    let s = schemes::build(name, params).unwrap();
    let config = Configuration::regular(s.as_ref(), n).unwrap();
    let mut d = discover(s.as_ref(), &config).unwrap();
    let small = assemble::<f64>(s.as_ref(), &d, NeighbourhoodKind::Analysis).unwrap();
    let r_max = d.analysis.iter().map(|&v| d.labels[v].ring).max().unwrap();
    let mut big: Vec<usize> = (0..d.patch.num_vertices()).filter(|&v| d.labels[v].ring <= r_max + 1).collect();
    assert!(d.analysis.iter().all(|v| big.contains(v)));
    // the block structure holds in any vertex order
    big.sort_by_key(|&v| (d.labels[v].ring, d.labels[v].sector, d.labels[v].index));
    let size = big.len();
    let added = size - d.analysis.len();
    d.analysis = big;
    let large = assemble::<f64>(s.as_ref(), &d, NeighbourhoodKind::Analysis)
        .unwrap_or_else(|e| panic!("{name} n={n}: rings 0..={} are not invariant: {e}", r_max + 1));
    let (ms, mut ml) = (moduli(&small, n), moduli(&large, n));
    let l1 = ms[1];
    // spec(S_A) ⊂ spec(S_B): remove each eigenvalue of S_A from the list of S_B
    for x in &ms {
        let k = ml
            .iter()
            .position(|y| (y - x).abs() < 1e-9)
            .unwrap_or_else(|| panic!("{name} n={n}: |λ| = {x} of S_A missing from S_B"));
        ml.remove(k);
    }
    assert_eq!(ml.len(), added, "{name} n={n}: one eigenvalue per added point");
    for y in ml {
        assert!(y < l1 - 1e-9, "{name} n={n}: an eigenvalue of the added ring, |λ| = {y}, reaches λ1 = {l1}");
    }
    size
}

#[test]
fn kobbelt_verdicts_do_not_depend_on_the_third_ring() {
    for n in 3..=12 {
        // Kobbelt: A is rings 0..2 (3n + 1 points), B rings 0..3
        assert_eq!(check("sqrt3", &[], n), 6 * n + 1, "n={n}: rings 0..3");
    }
}

#[test]
fn unified_sqrt3_verdicts_do_not_depend_on_one_more_ring() {
    for alpha in ["0", "1/2", "1"] {
        for n in 3..=8 {
            check("unified-sqrt3", &[("alpha".into(), alpha.into())], n);
        }
    }
}

/// Negative control: the test's invariance check can fail. Rings 0..2 less
/// one point of ring 2 are not invariant (the successors of that point's
/// ring-2 neighbours depend on it), so assembly on them must be refused.
#[test]
fn a_non_invariant_set_is_refused() {
    let s = schemes::build("sqrt3", &[]).unwrap();
    let config = Configuration::regular(s.as_ref(), 5).unwrap();
    let mut d = discover(s.as_ref(), &config).unwrap();
    let dropped = d.analysis.iter().position(|&v| d.labels[v].ring == 2).unwrap();
    d.analysis.remove(dropped);
    assert!(assemble::<f64>(s.as_ref(), &d, NeighbourhoodKind::Analysis).is_err());
}
