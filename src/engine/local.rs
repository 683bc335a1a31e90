//! The one local-matrix type of every scheme family.
//!
//! A local subdivision matrix is a square sparse matrix whose rows and
//! columns are indexed by the same ordered points: the labelled vertices of a
//! mesh neighbourhood (`crate::matrix::LocalMatrix`), the lattice points
//! (i, j) of a Z² window (`crate::lattice`), the indices i of a Z window
//! (`crate::curves`), the planar positions of a strip window
//! (`crate::spectrum::strip`). Only the point type differs, so the matrix and
//! what is done with it (entry look-up, dense copies, the exact matrix) are
//! written once here, generic over the point type `P`.
//!
//! `K` says which window of its domain the matrix is on. The mesh pipeline
//! keeps its minimal/analysis choice there (`NeighbourhoodKind`, a type of a
//! sibling layer that this module must not name); callers that only need the
//! points use the default `()`.

use crate::numeric::exact::QMatrix;
use crate::numeric::{Rational, Weight};

/// Sparse rows of a local matrix: (column, weight), columns ascending.
pub type Rows<W> = Vec<Vec<(usize, W)>>;

/// A local subdivision matrix: row k is the stencil, over one analysis step,
/// of the refined point that plays the role of point `labels[k]`, written
/// over the points `labels` (column j is `labels[j]`).
#[derive(Clone, Debug, PartialEq)]
pub struct LocalMatrix<P, W, K = ()> {
    /// which window of the domain this is (see the module doc)
    pub kind: K,
    /// the points of the window, in matrix order
    pub labels: Vec<P>,
    /// sparse rows: (column, weight), columns ascending, no zero weights
    pub rows: Rows<W>,
}

impl<P, W> LocalMatrix<P, W> {
    /// The matrix with rows `rows` over the points `labels` (one row per point).
    pub fn new(labels: Vec<P>, rows: Rows<W>) -> Self {
        assert_eq!(labels.len(), rows.len(), "a local matrix has one row per point of its window");
        LocalMatrix { kind: (), labels, rows }
    }
}

impl<P, W, K> LocalMatrix<P, W, K> {
    /// The number of points (rows, and columns).
    pub fn size(&self) -> usize {
        self.rows.len()
    }

    /// The non-zero entries (row, column, weight), row by row, columns ascending.
    pub fn entries(&self) -> impl Iterator<Item = (usize, usize, &W)> + '_ {
        self.rows.iter().enumerate().flat_map(|(i, row)| row.iter().map(move |(j, w)| (i, *j, w)))
    }

    /// The same matrix on other labels of the same points (the k-th label
    /// from `f(k, old label)`), e.g. lattice points named for the tables.
    pub fn relabel<Q>(self, f: impl FnMut(usize, &P) -> Q) -> LocalMatrix<Q, W, K> {
        let mut f = f;
        let labels = self.labels.iter().enumerate().map(|(k, p)| f(k, p)).collect();
        LocalMatrix { kind: self.kind, labels, rows: self.rows }
    }

    /// The same matrix, marked as the window `kind` of its domain.
    pub fn with_kind<L>(self, kind: L) -> LocalMatrix<P, W, L> {
        LocalMatrix { kind, labels: self.labels, rows: self.rows }
    }
}

impl<P, K> LocalMatrix<P, f64, K> {
    /// S applied to points of dimension D (one per column): the control
    /// points one subdivision step later, e.g. a net of 3-D points taken
    /// ring by ring towards the centre.
    pub fn apply_points<const D: usize>(&self, data: &[[f64; D]]) -> Vec<[f64; D]> {
        self.rows
            .iter()
            .map(|row| {
                let mut p = [0.0; D];
                for (j, w) in row {
                    for (c, x) in p.iter_mut().enumerate() {
                        *x += w * data[*j][c];
                    }
                }
                p
            })
            .collect()
    }
}

impl<P: PartialEq, W, K> LocalMatrix<P, W, K> {
    /// The row (and column) of point `p`.
    pub fn position(&self, p: &P) -> Option<usize> {
        self.labels.iter().position(|x| x == p)
    }
}

impl<P, W: Weight, K> LocalMatrix<P, W, K> {
    /// Entry (i, j); zero where the row has no entry.
    pub fn get(&self, i: usize, j: usize) -> W {
        self.rows[i].iter().find(|e| e.0 == j).map(|e| e.1.clone()).unwrap_or_else(W::zero)
    }

    /// Dense rows in the weight type.
    pub fn dense(&self) -> Vec<Vec<W>> {
        let n = self.size();
        let mut d = vec![vec![W::zero(); n]; n];
        for (i, j, w) in self.entries() {
            d[i][j] = w.clone();
        }
        d
    }

    /// Dense rows in floating point.
    pub fn to_dense_f64(&self) -> Vec<Vec<f64>> {
        let n = self.size();
        let mut d = vec![vec![0.0; n]; n];
        for (i, j, w) in self.entries() {
            d[i][j] = w.to_f64();
        }
        d
    }
}

impl<P, K> LocalMatrix<P, Rational, K> {
    /// The dense exact matrix, for characteristic polynomials and exact ranks.
    pub fn to_qmatrix(&self) -> QMatrix {
        let mut q = QMatrix::zeros(self.size());
        for (i, j, w) in self.entries() {
            q.set(i, j, w.clone());
        }
        q
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::exact::q;

    /// The 3×3 matrix of the cubic B-spline on the one-ring, rows
    /// (4, 4, 0)/8, (1, 6, 1)/8, (0, 4, 4)/8, as sparse rows.
    fn rows() -> Rows<Rational> {
        vec![
            vec![(0, q(1, 2)), (1, q(1, 2))],
            vec![(0, q(1, 8)), (1, q(3, 4)), (2, q(1, 8))],
            vec![(1, q(1, 2)), (2, q(1, 2))],
        ]
    }

    #[test]
    fn the_label_type_does_not_change_the_matrix() {
        let on_z = LocalMatrix::new(vec![-1i64, 0, 1], rows());
        let on_z2 = LocalMatrix::new(vec![(-1i64, 0i64), (0, 0), (1, 0)], rows());
        let named = LocalMatrix::new(vec!["p[i-1]".to_string(), "p[i]".into(), "p[i+1]".into()], rows());
        assert_eq!(on_z.dense(), on_z2.dense());
        assert_eq!(on_z.dense(), named.dense());
        assert_eq!(on_z.to_dense_f64(), named.to_dense_f64());
        for i in 0..3 {
            for j in 0..3 {
                assert_eq!(on_z.get(i, j), on_z2.get(i, j));
                assert_eq!(on_z.get(i, j), named.get(i, j));
            }
        }
        assert_eq!(on_z.get(0, 2), q(0, 1));
        assert_eq!(on_z.to_dense_f64()[1], vec![0.125, 0.75, 0.125]);
        assert_eq!(on_z2.position(&(1, 0)), Some(2));
        assert_eq!(named.position(&"p[i]".to_string()), Some(1));
    }

    #[test]
    fn relabelling_keeps_rows_and_kind() {
        let m = LocalMatrix::new(vec![-1i64, 0, 1], rows()).with_kind("minimal");
        let r = m.clone().relabel(|k, &i| format!("{k}:{i}"));
        assert_eq!(r.labels, vec!["0:-1", "1:0", "2:1"]);
        assert_eq!((r.kind, &r.rows), (m.kind, &m.rows));
        let entries: Vec<(usize, usize)> = m.entries().map(|(i, j, _)| (i, j)).collect();
        assert_eq!(entries, vec![(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (2, 1), (2, 2)]);
    }

    #[test]
    fn the_exact_matrix_has_the_b_spline_spectrum() {
        // eigenvalues of the cubic B-spline's one-ring matrix: 1, 1/2, 1/4
        let p = LocalMatrix::new(vec![-1i64, 0, 1], rows()).to_qmatrix().charpoly();
        for (lambda, root) in [(q(1, 1), true), (q(1, 2), true), (q(1, 4), true), (q(1, 8), false)] {
            assert_eq!(p.eval(&lambda) == q(0, 1), root, "λ = {lambda}");
        }
    }

    #[test]
    #[should_panic(expected = "one row per point")]
    fn a_row_per_point() {
        LocalMatrix::new(vec![0i64, 1], rows());
    }
}
