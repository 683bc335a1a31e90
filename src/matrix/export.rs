//! Matrix exports: Matrix Market coordinate format (MATLAB, SciPy) and JSON.

use serde::Serialize;

use super::LocalMatrix;
use crate::neighbourhood::VertexLabel;

/// Matrix Market "coordinate real general", 1-based indices; labels as comments.
pub fn to_matrix_market(m: &LocalMatrix<f64>, header: &str) -> String {
    let nnz = m.entries().count();
    let mut s = String::from("%%MatrixMarket matrix coordinate real general\n");
    for line in header.lines() {
        s.push_str(&format!("% {line}\n"));
    }
    for (k, l) in m.labels.iter().enumerate() {
        s.push_str(&format!("% row/col {}: {}\n", k + 1, l.name));
    }
    s.push_str(&format!("{} {} {}\n", m.size(), m.size(), nnz));
    for (i, j, w) in m.entries() {
        s.push_str(&format!("{} {} {:.17e}\n", i + 1, j + 1, w));
    }
    s
}

#[derive(Serialize)]
pub struct MatrixJson<'a> {
    pub scheme: &'a str,
    pub valence: usize,
    pub neighbourhood: crate::neighbourhood::NeighbourhoodKind,
    pub size: usize,
    pub labels: Vec<&'a str>,
    pub vertices: &'a [VertexLabel],
    /// dense rows
    pub matrix: Vec<Vec<f64>>,
    /// exact entries as strings ("3/32") when every weight is rational
    pub exact: Option<Vec<Vec<String>>>,
}
