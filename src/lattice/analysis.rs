//! Spectra of lattice schemes, reported with the same types (and so the same
//! stable JSON fields) as the mesh-based schemes: the window's matrix (the
//! one local-matrix type, on lattice points) is relabelled with vertex
//! labels and handed to the one driver (`spectrum::driver::solve`), which
//! every domain uses for the eigen-stage, the exact confirmation and the
//! verdict.

use super::{analysis_window, minimal_invariant_window, point_name, window_matrix, LatticeScheme, Window};
use crate::error::Error;
use crate::matrix::LocalMatrix;
use crate::neighbourhood::{NeighbourhoodKind, VertexKind, VertexLabel};
use crate::numeric::exact::{Poly, QMatrix};
use crate::numeric::Rational;
use crate::sdc::CentreKind;
use crate::spectrum::driver::{solve, Assembled, Identity, Problem};
use crate::spectrum::exact::Candidates;
use crate::spectrum::Spectrum;

/// The control points of the limit surface over the cells touching the origin
/// define the analysis window (radius 1 in level-0 lattice units).
pub const ANALYSIS_RADIUS: i64 = 1;

pub struct LatticeAnalysis {
    pub window: Window,
    pub minimal: Window,
    pub analysis: Window,
    pub matrix: LocalMatrix<f64>,
    pub exact_matrix: LocalMatrix<Rational>,
    pub spectrum: Spectrum,
}

fn label(k: usize, p: (i64, i64)) -> VertexLabel {
    VertexLabel {
        name: point_name(p),
        ring: p.0.unsigned_abs().max(p.1.unsigned_abs()) as usize,
        sector: 0,
        index: k,
        kind: if p == (0, 0) { VertexKind::Centre } else { VertexKind::Vertex },
        i: p.0,
        j: p.1,
    }
}

/// The matrix on a window with the labels of the mesh tables and JSON (the
/// paper's point names, lattice coordinates as i, j).
pub fn to_local<W: super::LatticeWeight>(
    scheme: &dyn LatticeScheme,
    w: &Window,
    kind: NeighbourhoodKind,
) -> Result<LocalMatrix<W>, Error> {
    Ok(window_matrix::<W>(scheme, w)?.relabel(|k, &p| label(k, p)).with_kind(kind))
}

/// Exact characteristic polynomial det(xI − S) of the matrix on a window.
pub fn charpoly(scheme: &dyn LatticeScheme, w: &Window) -> Result<Poly, Error> {
    Ok(window_matrix::<Rational>(scheme, w)?.to_qmatrix().charpoly())
}

/// The exact matrix of dense rows (as `local_matrix` gives them).
pub fn to_qmatrix(dense: &[Vec<Rational>]) -> QMatrix {
    let mut q = QMatrix::zeros(dense.len());
    for (i, row) in dense.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            q.set(i, j, x.clone());
        }
    }
    q
}

/// Spectrum of the scheme on its minimal or analysis window, by the one
/// driver (`spectrum::driver`): the window has no rotation symmetry to use
/// (asymmetric masks), so the whole matrix is analysed. Lattice weights are
/// rational, so the exact confirmation always runs (full characteristic
/// polynomial, exact ranks) unless `exact` is false.
pub fn analyse(scheme: &dyn LatticeScheme, kind: NeighbourhoodKind, exact: bool) -> Result<LatticeAnalysis, Error> {
    let minimal = minimal_invariant_window(scheme, &[(0, 0)])?;
    let analysis = analysis_window(scheme, ANALYSIS_RADIUS)?;
    let window = match kind {
        NeighbourhoodKind::Minimal => minimal.clone(),
        NeighbourhoodKind::Analysis => analysis.clone(),
    };
    let rows = Assembled {
        float: to_local::<f64>(scheme, &window, kind)?,
        exact: Some(to_local::<Rational>(scheme, &window, kind)?),
    };
    let identity = Identity {
        tagging: None,
        scheme: scheme.name().to_string(),
        valence: 4,
        params: scheme.params().values.iter().map(|(k, v)| (k.clone(), v.text.clone())).collect(),
        faces: "QQQQ".into(),
        centre: CentreKind::Vertex,
        neighbourhood: kind,
        minimal_size: minimal.len(),
        analysis_size: analysis.len(),
    };
    let problem = Problem::window(identity, &rows, exact, Candidates::Recognised);
    let spectrum = solve(problem)?.spectrum;
    let Assembled { float: matrix, exact: exact_matrix } = rows;
    let exact_matrix = exact_matrix.expect("assembled above");
    Ok(LatticeAnalysis { window, minimal, analysis, matrix, exact_matrix, spectrum })
}
