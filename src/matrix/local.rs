//! Assembly of S: row k of S is the stencil of the refined vertex that plays the
//! role of neighbourhood vertex k, restricted to the (invariant) neighbourhood.

use crate::neighbourhood::{Discovered, NeighbourhoodKind, VertexLabel};
use crate::numeric::{Inexact, Weight};
use crate::schemes::{Scheme, SchemeWeight};

#[derive(Clone, Debug)]
pub struct LocalMatrix<W> {
    pub kind: NeighbourhoodKind,
    pub labels: Vec<VertexLabel>,
    /// sparse rows: (column, weight)
    pub rows: Vec<Vec<(usize, W)>>,
}

impl<W: Weight> LocalMatrix<W> {
    pub fn size(&self) -> usize {
        self.rows.len()
    }
    pub fn get(&self, i: usize, j: usize) -> W {
        self.rows[i].iter().find(|e| e.0 == j).map(|e| e.1.clone()).unwrap_or_else(W::zero)
    }
    pub fn to_dense_f64(&self) -> Vec<Vec<f64>> {
        let n = self.size();
        let mut d = vec![vec![0.0; n]; n];
        for (i, row) in self.rows.iter().enumerate() {
            for (j, w) in row {
                d[i][j.to_owned()] = w.to_f64();
            }
        }
        d
    }
    /// Position of the vertex obtained by rotating vertex k by `period` sectors.
    pub fn rotation(&self, period: usize, sectors: usize) -> Vec<usize> {
        let key = |l: &VertexLabel| (l.sector, l.i, l.j);
        let pos: std::collections::HashMap<_, _> = self.labels.iter().enumerate().map(|(k, l)| (key(l), k)).collect();
        self.labels
            .iter()
            .map(|l| {
                if l.i == 0 && l.j == 0 {
                    return pos[&(l.sector, 0, 0)];
                }
                pos[&((l.sector + period) % sectors, l.i, l.j)]
            })
            .collect()
    }
}

/// Assemble S on the chosen neighbourhood. `Err(Inexact)` when some weight is
/// not representable in W (exact path with irrational cosines).
pub fn assemble<W: SchemeWeight>(
    scheme: &dyn Scheme,
    d: &Discovered,
    kind: NeighbourhoodKind,
) -> Result<LocalMatrix<W>, AssembleError> {
    let set = d.set(kind);
    let position: std::collections::HashMap<usize, usize> = set.iter().enumerate().map(|(k, &v)| (v, k)).collect();
    let mut rows = Vec::with_capacity(set.len());
    for &v in set {
        let w = d.successor(v).ok_or(AssembleError::Missing)?;
        let st = W::stencil(scheme, &d.patch, d.level1.vertex_origins[w])
            .map_err(|Inexact| AssembleError::Inexact)?
            .ok_or(AssembleError::Missing)?;
        let mut row: Vec<(usize, W)> = Vec::new();
        for (u, wt) in st.terms {
            if wt.is_zero() {
                continue;
            }
            let col = *position.get(&u).ok_or(AssembleError::NotInvariant)?;
            row.push((col, wt));
        }
        row.sort_by_key(|e| e.0);
        rows.push(row);
    }
    Ok(LocalMatrix { kind, labels: set.iter().map(|&v| d.labels[v].clone()).collect(), rows })
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AssembleError {
    Inexact,
    Missing,
    NotInvariant,
}

impl std::fmt::Display for AssembleError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            AssembleError::Inexact => "a weight is irrational; no exact matrix",
            AssembleError::Missing => "a rule could not be evaluated on the neighbourhood",
            AssembleError::NotInvariant => "the neighbourhood is not invariant under the rules",
        })
    }
}
