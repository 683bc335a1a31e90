//! Exact confirmation of floating-point eigenvalues against the exact rational
//! matrix: the characteristic polynomial det(xI − S), which candidate
//! rationals are roots of it and with what algebraic multiplicity, and the
//! exact geometric multiplicity n − rank(S − λI) of each. The floats only
//! propose candidates; every reported value is proven on the exact matrix.
//!
//! This is the one exact confirmation: the curve analysis calls it, and the
//! mesh and lattice pipelines (`crate::spectrum::exact`) call it on the whole
//! S; for large rotation-symmetric S they test Fourier block 0 instead, whose
//! rational roots (without ranks) are all a block can prove.

use crate::numeric::exact::{rational_roots, Poly, QMatrix};
use crate::numeric::recognise::convergents;
use crate::numeric::Rational;

/// Largest denominator tried when turning a float eigenvalue into candidates.
const MAX_DENOMINATOR: i64 = 1_000_000_000;

/// A rational eigenvalue proven on the exact matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactEigenvalue {
    pub value: Rational,
    /// multiplicity as a root of det(xI − S)
    pub algebraic: usize,
    /// dim ker(S − λI), from an exact rank
    pub geometric: usize,
}

/// What the exact matrix proves about its spectrum.
#[derive(Clone, Debug)]
pub struct Confirmation {
    pub charpoly: Poly,
    /// the candidates that are roots, in the order `rational_roots` finds them
    pub eigenvalues: Vec<ExactEigenvalue>,
    /// degree of det(xI − S) with the proven rational roots divided out:
    /// 0 when every eigenvalue is rational and proven
    pub remaining_degree: usize,
}

impl Confirmation {
    /// Every eigenvalue is one of the proven rationals.
    pub fn complete(&self) -> bool {
        self.remaining_degree == 0
    }
}

/// Candidate rationals for real float eigenvalues: the continued-fraction
/// convergents of each (a true rational eigenvalue p/q with moderate q is
/// among them, since the float is within rounding of it).
pub fn candidates(reals: impl IntoIterator<Item = f64>) -> Vec<Rational> {
    reals
        .into_iter()
        .flat_map(|x| convergents(x, MAX_DENOMINATOR).into_iter().map(|(p, q)| Rational::new(p.into(), q.into())))
        .collect()
}

/// Test the candidates exactly as eigenvalues of `q`.
pub fn confirm(q: &QMatrix, candidates: &[Rational]) -> Confirmation {
    let poly = q.charpoly();
    let (roots, rest) = rational_roots(&poly, candidates);
    let dim = poly.degree();
    let eigenvalues = roots
        .into_iter()
        .map(|(value, algebraic)| {
            let geometric = dim - q.shifted(&value).rank();
            ExactEigenvalue { value, algebraic, geometric }
        })
        .collect();
    Confirmation { charpoly: poly, eigenvalues, remaining_degree: rest.degree() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::local::{LocalMatrix, Rows};
    use crate::numeric::exact::q;

    fn to_qmatrix(rows: Rows<Rational>) -> QMatrix {
        LocalMatrix::new((0..rows.len()).collect(), rows).to_qmatrix()
    }

    #[test]
    fn a_jordan_block_and_a_repeated_diagonal_value() {
        // S = [[1/2, 1, 0], [0, 1/2, 0], [0, 0, 1/4]]: det(xI − S) =
        // (x − 1/2)²(x − 1/4); 1/2 has one eigenvector (a Jordan block),
        // 1/4 one as well
        let rows = vec![vec![(0, q(1, 2)), (1, q(1, 1))], vec![(1, q(1, 2))], vec![(2, q(1, 4))]];
        let c = confirm(&to_qmatrix(rows), &candidates([0.5, 0.25]));
        assert!(c.complete());
        let half = c.eigenvalues.iter().find(|e| e.value == q(1, 2)).unwrap();
        assert_eq!((half.algebraic, half.geometric), (2, 1));
        let quarter = c.eigenvalues.iter().find(|e| e.value == q(1, 4)).unwrap();
        assert_eq!((quarter.algebraic, quarter.geometric), (1, 1));
    }

    #[test]
    fn irrational_roots_stay_unproven() {
        // [[0, 2], [1, 0]] has eigenvalues ±√2: no candidate is a root
        let rows = vec![vec![(1, q(2, 1))], vec![(0, q(1, 1))]];
        let c = confirm(&to_qmatrix(rows), &candidates([std::f64::consts::SQRT_2, -std::f64::consts::SQRT_2]));
        assert!(c.eigenvalues.is_empty());
        assert_eq!(c.remaining_degree, 2);
        assert!(!c.complete());
    }
}
