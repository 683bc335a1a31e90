//! Assembly of S: row k of S is the stencil of the refined vertex that plays the
//! role of neighbourhood vertex k, restricted to the (invariant) neighbourhood.

use crate::neighbourhood::{Discovered, NeighbourhoodKind, VertexLabel};
use crate::numeric::{Inexact, Rational, SmallRational, Weight};
use crate::refine::{Combine, SparseRow};
use crate::sdc::{Scheme, SchemeWeight, Stencil};

/// S on a mesh neighbourhood: the one local-matrix type of every family
/// (`engine::LocalMatrix`) on the neighbourhood's labelled vertices, marked
/// with the neighbourhood (minimal or analysis) it is on.
pub type LocalMatrix<W> = crate::engine::LocalMatrix<VertexLabel, W, NeighbourhoodKind>;

impl<W> LocalMatrix<W> {
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
    let all: Vec<usize> = (0..d.set(kind).len()).collect();
    let rows = assemble_rows::<W>(scheme, d, kind, &all)?;
    Ok(LocalMatrix { kind, labels: set_labels(d, kind), rows })
}

/// The labels of the neighbourhood's vertices, in matrix order.
pub fn set_labels(d: &Discovered, kind: NeighbourhoodKind) -> Vec<VertexLabel> {
    d.set(kind).iter().map(|&v| d.labels[v].clone()).collect()
}

/// Rows `which` (matrix indices) of S, each over all columns, sorted by
/// column: the same rows [`assemble`] gives, without composing the others.
/// The Fourier blocks need only the rows of one representative per rotation
/// orbit, O(1) rows instead of O(n).
pub fn assemble_rows<W: SchemeWeight>(
    scheme: &dyn Scheme,
    d: &Discovered,
    kind: NeighbourhoodKind,
    which: &[usize],
) -> Result<Vec<Vec<(usize, W)>>, AssembleError> {
    let set = d.set(kind);
    let targets: Vec<usize> =
        which.iter().map(|&k| d.successor(set[k]).ok_or(AssembleError::Missing)).collect::<Result<_, _>>()?;
    let raw = step_rows::<W>(d.refinements().len(), &targets, |k, v| {
        crate::refine::new_stencil::<W>(scheme, d.mesh_before(k), &d.refinements()[k], v)
            .map_err(|Inexact| AssembleError::Inexact)?
            .map_err(|_| AssembleError::Missing)
    })?;
    restrict(set, raw)
}

/// [`assemble_rows`] in exact rationals, computed in machine-integer
/// rationals first ([`SmallRational`]: most schemes' weights are small
/// fractions, and big rationals allocate and reduce at every product); when
/// a weight leaves the machine integers the rows are assembled again in big
/// rationals. `Err(Inexact)` exactly where big rationals would give it (an
/// irrational weight).
pub fn assemble_rows_rational(
    scheme: &dyn Scheme,
    d: &Discovered,
    kind: NeighbourhoodKind,
    which: &[usize],
) -> Result<Vec<Vec<(usize, Rational)>>, AssembleError> {
    let small = assemble_rows::<SmallRational>(scheme, d, kind, which)?;
    let exact: Option<Vec<Vec<(usize, Rational)>>> =
        small.iter().map(|row| row.iter().map(|(c, w)| w.to_rational().map(|w| (*c, w))).collect()).collect();
    match exact {
        Some(rows) => Ok(rows),
        None => assemble_rows::<Rational>(scheme, d, kind, which),
    }
}

/// The rows over one analysis step of the successors of the level-0
/// vertices `vertices` (any vertices of the patch, not only a discovered
/// neighbourhood's), over level-0 vertex ids and not restricted to any set:
/// for checking whether a stated vertex set is invariant (its rows then
/// depend on it alone) and for S on such a set. `Err(Missing)` when a rule
/// cannot be evaluated on the patch (it is too small for the set).
pub fn step_rows_of<W: SchemeWeight>(
    scheme: &dyn Scheme,
    d: &Discovered,
    vertices: &[usize],
) -> Result<Vec<Vec<(usize, W)>>, AssembleError> {
    let targets: Vec<usize> =
        vertices.iter().map(|&v| d.successor(v).ok_or(AssembleError::Missing)).collect::<Result<_, _>>()?;
    step_rows::<W>(d.refinements().len(), &targets, |k, v| {
        crate::refine::new_stencil::<W>(scheme, d.mesh_before(k), &d.refinements()[k], v)
            .map_err(|Inexact| AssembleError::Inexact)?
            .map_err(|_| AssembleError::Missing)
    })
}

/// [`assemble_rows`] in f64 from what discovery computed: the rows it composed
/// for the orbit representatives; any other row is composed from the float
/// stencils (the same values the rules give, as discovery evaluated them with
/// the same code).
pub fn assemble_rows_f64(
    scheme: &dyn Scheme,
    d: &Discovered,
    kind: NeighbourhoodKind,
    which: &[usize],
) -> Result<Vec<Vec<(usize, f64)>>, AssembleError> {
    let set = d.set(kind);
    let mut raw: Vec<Option<Vec<(usize, f64)>>> =
        which.iter().map(|&k| d.composite_row(set[k]).map(|r| r.entries.clone())).collect();
    let missing: Vec<usize> = (0..which.len()).filter(|&i| raw[i].is_none()).collect();
    if !missing.is_empty() {
        let targets: Vec<usize> = missing
            .iter()
            .map(|&i| d.successor(set[which[i]]).ok_or(AssembleError::Missing))
            .collect::<Result<_, _>>()?;
        let stencils = d.float_stencils(scheme);
        let rows = step_rows::<f64>(d.refinements().len(), &targets, |k, v| {
            stencils[k][v].clone().ok_or(AssembleError::Missing)
        })?;
        for (i, row) in missing.into_iter().zip(rows) {
            raw[i] = Some(row);
        }
    }
    restrict(set, raw.into_iter().map(|r| r.expect("filled above")).collect())
}

/// Rows over level-0 vertices to rows over the neighbourhood's positions.
fn restrict<W: Weight>(set: &[usize], raw: Vec<Vec<(usize, W)>>) -> Result<Vec<Vec<(usize, W)>>, AssembleError> {
    let position: crate::mesh::IdMap<usize, usize> = set.iter().enumerate().map(|(k, &v)| (v, k)).collect();
    let mut rows = Vec::with_capacity(raw.len());
    for row_w in raw {
        let mut row: Vec<(usize, W)> = Vec::with_capacity(row_w.len());
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
    Ok(rows)
}

/// Stencils over a whole analysis step of `levels` refinements (in W) of the
/// given last-level vertices, in terms of level-0 vertices; `stencil(k, v)`
/// gives the stencil of vertex v of refinement k+1. Only the vertices the
/// targets need are evaluated: stencils are taken top-down (each level's
/// supports are the next level's needs), then composed bottom-up, each
/// stencil's terms in their own order, so f64 rows come out the same
/// whichever way they were asked for.
fn step_rows<W: Weight>(
    levels: usize,
    targets: &[usize],
    mut stencil: impl FnMut(usize, usize) -> Result<Stencil<W>, AssembleError>,
) -> Result<Vec<Vec<(usize, W)>>, AssembleError> {
    // needed[k]: the stencils of the vertices after refinement k+1 that are needed
    let mut needed: Vec<crate::mesh::IdMap<usize, Stencil<W>>> = vec![Default::default(); levels];
    let mut wanted: Vec<usize> = targets.to_vec();
    for k in (0..levels).rev() {
        let mut below = Vec::new();
        for v in wanted {
            if needed[k].contains_key(&v) {
                continue; // listed twice, or reached through two stencils
            }
            let st = stencil(k, v)?;
            below.extend(st.support());
            needed[k].insert(v, st);
        }
        wanted = below;
    }
    // rows[v] at the current level, over level-0 vertices
    let mut rows: crate::mesh::IdMap<usize, SparseRow<W>> = Default::default();
    for (k, level) in needed.into_iter().enumerate() {
        let mut next = crate::mesh::IdMap::default();
        for (v, st) in level {
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
    Ok(targets.iter().map(|t| rows.get(t).map(|r| r.entries.clone()).unwrap_or_default()).collect())
}

/// S over the whole neighbourhood, assembled on first use. The spectrum of a
/// rotation-symmetric configuration needs only the representative rows, but
/// exports, `--method full` and callers of [`crate::spectrum::Analysis`] may
/// read all of S; they get it, through `Deref`, as if it had been assembled
/// up front.
pub struct FullMatrix<W: Weight> {
    cell: std::sync::OnceLock<LocalMatrix<W>>,
    build: std::sync::Mutex<Option<Builder<W>>>,
}

type Builder<W> = Box<dyn FnOnce() -> LocalMatrix<W> + Send>;

impl<W: Weight> FullMatrix<W> {
    /// Already assembled.
    pub fn ready(m: LocalMatrix<W>) -> Self {
        FullMatrix { cell: std::sync::OnceLock::from(m), build: std::sync::Mutex::new(None) }
    }
    /// Assembled by `build` on first access.
    pub fn lazy(build: impl FnOnce() -> LocalMatrix<W> + Send + 'static) -> Self {
        FullMatrix { cell: std::sync::OnceLock::new(), build: std::sync::Mutex::new(Some(Box::new(build))) }
    }
    /// Whether S has been assembled (for tests and benchmarks of the lazy path).
    pub fn is_assembled(&self) -> bool {
        self.cell.get().is_some()
    }
}

impl<W: Weight> std::ops::Deref for FullMatrix<W> {
    type Target = LocalMatrix<W>;
    fn deref(&self) -> &LocalMatrix<W> {
        self.cell.get_or_init(|| {
            let build = self.build.lock().unwrap_or_else(|e| e.into_inner()).take();
            build.expect("a lazy matrix has its builder until first use")()
        })
    }
}

impl<W: Weight> std::fmt::Debug for FullMatrix<W> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.cell.get() {
            Some(m) => m.fmt(f),
            None => f.write_str("FullMatrix(not assembled yet)"),
        }
    }
}

/// The whole f64 matrix from discovery's float stencils, assembled on first
/// use: row for row what [`assemble`] gives in f64 (discovery evaluated the
/// same rules with the same code). Completes the float stencils now (see
/// [`Discovered::float_stencils`]); they are shared, not copied.
pub fn lazy_full_f64(
    scheme: &dyn Scheme,
    d: &Discovered,
    kind: NeighbourhoodKind,
) -> Result<FullMatrix<f64>, AssembleError> {
    let set = d.set(kind).to_vec();
    let targets: Vec<usize> =
        set.iter().map(|&v| d.successor(v).ok_or(AssembleError::Missing)).collect::<Result<_, _>>()?;
    let labels = set_labels(d, kind);
    let stencils = std::sync::Arc::clone(d.float_stencils(scheme));
    let levels = d.refinements().len();
    Ok(FullMatrix::lazy(move || {
        let rows = step_rows(levels, &targets, |k, v| stencils[k][v].clone().ok_or(AssembleError::Missing))
            .and_then(|raw| restrict(&set, raw))
            // the representative rows assembled, and S commutes with the
            // rotation, so every other row is a rotated copy of an assembled one
            .expect("every row of a rotation-symmetric S assembles when its representatives do");
        LocalMatrix { kind, labels, rows }
    }))
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AssembleError {
    Inexact,
    Missing,
    NotInvariant,
}

/// An irrational weight is a numeric limit of the exact path; a rule that
/// cannot be evaluated, or a set that is not invariant, means the
/// neighbourhood does not determine the rows.
impl From<AssembleError> for crate::error::Error {
    fn from(e: AssembleError) -> Self {
        match e {
            AssembleError::Inexact => crate::error::Error::Numeric(e.to_string()),
            AssembleError::Missing | AssembleError::NotInvariant => crate::error::Error::NotDetermined(e.to_string()),
        }
    }
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
