//! Unit tests of the analysis driver on matrices whose spectra are known in
//! closed form: a block-diagonal S (eigenvalues and Jordan structure read off
//! its blocks) through the whole-matrix path, and a rotation-symmetric S
//! (circulant ring around a fixed centre) through the Fourier path, whose
//! eigenvalues are a + 2b·cos(2πk/n) by the discrete Fourier transform.

use std::collections::BTreeMap;

use super::{solve, Assembled, Identity, Problem};
use crate::matrix::LocalMatrix;
use crate::neighbourhood::{NeighbourhoodKind, VertexKind, VertexLabel};
use crate::numeric::Rational;
use crate::sdc::CentreKind;
use crate::spectrum::driver::MAX_FULL_SIZE;
use crate::spectrum::exact::Candidates;
use crate::spectrum::spectrum_result::Method;

fn q(p: i64, d: i64) -> Rational {
    Rational::new(p.into(), d.into())
}

fn label(sector: usize, i: i64, j: i64) -> VertexLabel {
    let centre = i == 0 && j == 0;
    VertexLabel {
        name: format!("v[{sector},{i},{j}]"),
        ring: usize::from(!centre),
        sector,
        index: 0,
        kind: if centre { VertexKind::Centre } else { VertexKind::Edge },
        i,
        j,
    }
}

fn identity(size: usize) -> Identity {
    Identity {
        tagging: None,
        scheme: "test".into(),
        valence: 1,
        params: BTreeMap::new(),
        faces: String::new(),
        centre: CentreKind::Vertex,
        neighbourhood: NeighbourhoodKind::Analysis,
        minimal_size: size,
        analysis_size: size,
    }
}

/// The same rational matrix in floating point and exactly (rows sparse,
/// columns ascending, no zeros).
fn assembled(labels: Vec<VertexLabel>, rows: Vec<Vec<(usize, Rational)>>) -> Assembled {
    let to_f64 = |w: &Rational| {
        use num_traits::ToPrimitive;
        w.to_f64().unwrap()
    };
    let float = rows.iter().map(|r| r.iter().map(|(c, w)| (*c, to_f64(w))).collect()).collect();
    Assembled {
        float: LocalMatrix { kind: NeighbourhoodKind::Analysis, labels: labels.clone(), rows: float },
        exact: Some(LocalMatrix { kind: NeighbourhoodKind::Analysis, labels, rows }),
    }
}

#[test]
fn block_diagonal_matrix_gives_its_blocks_eigenvalues_and_jordan_structure() {
    // S = diag(B0, B1, B2) on 5 points:
    // B0 = [1]                     eigenvalue 1 (simple, dominant)
    // B1 = [[1/2, 1/4], [1/4, 1/2]] eigenvalues 1/2 ± 1/4 = 3/4, 1/4
    // B2 = [[1/8, 1], [0, 1/8]]    a Jordan block: 1/8 with algebraic
    //                               multiplicity 2 and geometric 1
    let rows = vec![
        vec![(0, q(1, 1))],
        vec![(1, q(1, 2)), (2, q(1, 4))],
        vec![(1, q(1, 4)), (2, q(1, 2))],
        vec![(3, q(1, 8)), (4, q(1, 1))],
        vec![(4, q(1, 8))],
    ];
    let labels = (0..5).map(|k| label(0, k, 1)).collect();
    let source = assembled(labels, rows);
    let solved = solve(Problem::window(identity(5), &source, true, Candidates::Recognised)).unwrap();
    let s = &solved.spectrum;
    assert_eq!(s.method, Method::Full, "a window has no rotation symmetry");
    assert_eq!(s.matrix_size, 5);
    // (value, algebraic, geometric), by decreasing modulus
    let want = [(1.0, 1, 1), (0.75, 1, 1), (0.25, 1, 1), (0.125, 2, 1)];
    assert_eq!(s.eigenvalues.len(), want.len(), "{:?}", s.eigenvalues.iter().map(|e| e.re).collect::<Vec<_>>());
    for (e, &(value, alg, geo)) in s.eigenvalues.iter().zip(&want) {
        assert!((e.re - value).abs() < 1e-9 && e.im.abs() < 1e-9, "{} against {value}", e.re);
        assert_eq!((e.algebraic_multiplicity, e.geometric_multiplicity), (alg, geo), "at {value}");
        assert_eq!(e.defective, alg != geo, "at {value}");
    }
    // the exact path confirms every eigenvalue as a rational root
    let exact = s.exact_analysis.as_ref().expect("a rational S is confirmed exactly");
    assert!(exact.agrees_with_float);
    assert_eq!(exact.polynomial_degree, 5);
    assert_eq!(exact.remaining_degree, 0, "every root is rational");
    // Reif: λ0 = 1 simple, λ1 = 3/4 simple and real, but not a double
    // subdominant pair, so no spectral C¹ verdict; convergent since |λ1| < 1
    assert!(s.verdict.convergent);
    assert_eq!(s.verdict.subdominant, Some(s.eigenvalues[1].re));
    assert!(!s.verdict.c1_spectral, "{:?}", s.verdict.reasons);
}

/// A fixed centre and a ring of n points, one per sector: the centre stays,
/// ring point s moves to a·v_s + b·(v_{s−1} + v_{s+1}) + c·centre.
fn circulant_ring(n: usize, a: Rational, b: Rational) -> Assembled {
    let c = q(1, 1) - a.clone() - b.clone() - b.clone();
    let mut labels = vec![label(0, 0, 0)];
    labels.extend((0..n).map(|s| label(s, 1, 0)));
    let ring = |s: usize| 1 + s % n;
    let mut rows = vec![vec![(0, q(1, 1))]];
    for s in 0..n {
        let mut row: BTreeMap<usize, Rational> = BTreeMap::new();
        row.insert(0, c.clone());
        *row.entry(ring(s)).or_insert_with(|| q(0, 1)) += a.clone();
        *row.entry(ring(s + n - 1)).or_insert_with(|| q(0, 1)) += b.clone();
        *row.entry(ring(s + 1)).or_insert_with(|| q(0, 1)) += b.clone();
        rows.push(row.into_iter().collect());
    }
    assembled(labels, rows)
}

#[test]
fn rotation_symmetric_matrix_through_fourier_blocks_and_whole_matrix_alike() {
    // with a = 1/2, b = 1/8: block 0 holds 1 (the centre) and a + 2b = 3/4;
    // block k ≠ 0 holds a + 2b·cos(2πk/n) = 1/2 + cos(2πk/n)/4
    let n = 5;
    let source = circulant_ring(n, q(1, 2), q(1, 8));
    let mut want: Vec<f64> = vec![1.0, 0.75];
    want.extend((1..n).map(|k| 0.5 + (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos() / 4.0));
    want.sort_by(|x, y| y.total_cmp(x));
    for method in [Method::Dft, Method::Full] {
        let problem = Problem {
            identity: identity(n + 1),
            labels: source.float.labels.clone(),
            period: 1,
            sectors: n,
            method: Some(method),
            exact: false,
            candidates: Candidates::Recognised,
            rows: &source,
        };
        let s = solve(problem).unwrap().spectrum;
        assert_eq!(s.method, method);
        let got: Vec<f64> = s
            .eigenvalues
            .iter()
            .flat_map(|e| {
                assert!(e.im.abs() < 1e-9, "{method:?}: a symmetric S has real eigenvalues");
                std::iter::repeat_n(e.re, e.algebraic_multiplicity)
            })
            .collect();
        assert_eq!(got.len(), want.len(), "{method:?}: {got:?}");
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() < 1e-9, "{method:?}: {got:?} against {want:?}");
        }
        // λ1 = 3/4 (block 0) lies above the pair 1/2 + cos(2π/5)/4 ≈ 0.577 of
        // blocks 1 and n − 1: a simple subdominant eigenvalue, so no C¹ verdict
        assert!((s.verdict.subdominant.unwrap() - 0.75).abs() < 1e-9, "{method:?}");
        assert!(!s.verdict.c1_spectral, "{method:?}");
    }
    // no method asked: the driver takes the Fourier blocks for a symmetric S
    let problem = Problem {
        identity: identity(n + 1),
        labels: source.float.labels.clone(),
        period: 1,
        sectors: n,
        method: None,
        exact: false,
        candidates: Candidates::Recognised,
        rows: &source,
    };
    assert_eq!(solve(problem).unwrap().spectrum.method, Method::Dft);
}

#[test]
fn whole_matrix_above_the_limit_is_refused_before_any_work() {
    // rows are never read: the refusal comes from the size alone (an empty
    // row would make S singular, not an error)
    let size = MAX_FULL_SIZE + 1;
    let labels: Vec<VertexLabel> = (0..size).map(|k| label(0, k as i64 + 1, 0)).collect();
    let empty = Assembled {
        float: LocalMatrix { kind: NeighbourhoodKind::Analysis, labels: labels.clone(), rows: vec![Vec::new(); size] },
        exact: None,
    };
    let err = solve(Problem::window(identity(size), &empty, false, Candidates::Recognised)).err().expect("refused");
    let text = err.to_string();
    assert!(text.contains(&format!("{size}×{size}")) && text.contains("no rotation symmetry"), "{text}");
}
