//! Assembly of S: row k of S is the stencil of the refined vertex that plays the
//! role of neighbourhood vertex k, restricted to the (invariant) neighbourhood.

use crate::neighbourhood::{Discovered, NeighbourhoodKind, VertexLabel};
use crate::numeric::{Inexact, Weight};
use crate::refine::{Combine, SparseRow};
use crate::sdc::{Scheme, SchemeWeight};

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

/// Assemble S on the chosen neighbourhood: row k is the stencil, over one
/// analysis step, of the refined vertex that plays the role of vertex k.
/// `Err(Inexact)` when some weight is not representable in W (exact path with
/// irrational cosines).
pub fn assemble<W: SchemeWeight>(
    scheme: &dyn Scheme,
    d: &Discovered,
    kind: NeighbourhoodKind,
) -> Result<LocalMatrix<W>, AssembleError> {
    let set = d.set(kind);
    let position: std::collections::HashMap<usize, usize> = set.iter().enumerate().map(|(k, &v)| (v, k)).collect();
    let targets: Vec<usize> =
        set.iter().map(|&v| d.successor(v).ok_or(AssembleError::Missing)).collect::<Result<_, _>>()?;
    let rows_w = step_rows::<W>(scheme, d, &targets)?;
    let mut rows = Vec::with_capacity(set.len());
    for row_w in rows_w {
        let mut row: Vec<(usize, W)> = Vec::new();
        for (u, wt) in row_w {
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

/// Stencils over a whole analysis step (in W) of the given last-level
/// vertices, in terms of level-0 vertices. Only the vertices the targets need
/// are evaluated at the intermediate levels (found from the float stencils).
fn step_rows<W: SchemeWeight>(
    scheme: &dyn Scheme,
    d: &Discovered,
    targets: &[usize],
) -> Result<Vec<Vec<(usize, W)>>, AssembleError> {
    let steps = d.refinements.len();
    // needed[k]: vertices after refinement k+1 whose stencils are needed
    let mut needed: Vec<Vec<usize>> = vec![Vec::new(); steps];
    needed[steps - 1] = targets.to_vec();
    for k in (1..steps).rev() {
        let mut mark = vec![false; d.refinements[k - 1].mesh.num_vertices()];
        for &v in &needed[k] {
            let st = d.stencils[k][v].as_ref().ok_or(AssembleError::Missing)?;
            st.support().for_each(|u| mark[u] = true);
        }
        needed[k - 1] = (0..mark.len()).filter(|&u| mark[u]).collect();
    }
    // rows[v] at the current level, over level-0 vertices
    let mut rows: std::collections::HashMap<usize, SparseRow<W>> = Default::default();
    for k in 0..steps {
        let mesh = d.mesh_before(k);
        let mut next = std::collections::HashMap::new();
        for &v in &needed[k] {
            let st = W::stencil(scheme, mesh, d.refinements[k].vertex_origins[v])
                .map_err(|Inexact| AssembleError::Inexact)?
                .ok_or(AssembleError::Missing)?;
            let row = if k == 0 {
                SparseRow { entries: st.terms }
            } else {
                let terms: Vec<(W, &SparseRow<W>)> = st
                    .terms
                    .iter()
                    .map(|(u, w)| rows.get(u).map(|r| (w.clone(), r)))
                    .collect::<Option<_>>()
                    .ok_or(AssembleError::Missing)?;
                SparseRow::combine(&terms)
            };
            next.insert(v, row);
        }
        rows = next;
    }
    Ok(targets.iter().map(|t| rows.remove(t).map(|r| r.entries).unwrap_or_default()).collect())
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
