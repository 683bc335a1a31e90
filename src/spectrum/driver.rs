//! The one analysis driver, shared by every domain: a mesh neighbourhood of
//! an extraordinary point (`spectrum::analyse`), a window of the regular
//! lattice Z² (`lattice::analysis::analyse`) and a window of the line Z
//! (`curves::local::curve_spectrum`).
//!
//! A domain finds its neighbourhood (discovery on a patch, the invariant
//! closure of a window) and then hands the driver a [`Problem`]: who the
//! spectrum belongs to, the labels of the points, the rotation symmetry, and a
//! [`RowSource`] that assembles rows of S in floating point and, where every
//! weight is rational, exactly. From there every domain takes the same route:
//!
//! 1. the method: Fourier blocks when the configuration has rotation
//!    symmetry (only the orbit representatives' rows are assembled), else the
//!    whole matrix, refused up front above [`MAX_FULL_SIZE`];
//! 2. the floating-point eigen-stage (`decompose`/`decompose_dft`) and the
//!    canonical order;
//! 3. the exact confirmation (`exact::confirm`: the whole S when small or
//!    without symmetry, else Fourier block 0);
//! 4. Reif's spectral C¹ verdict.

use super::decomposition::{decompose, decompose_dft, Decomposition};
use super::eigenvalue::sort_eigenvalues;
use super::exact::{self, ExactSummary};
use super::spectrum_result::{Method, Spectrum};
use super::verdict;
use crate::dft::{lazy_full_by_rotation, Orbits};
use crate::error::Error;
use crate::matrix::{FullMatrix, LocalMatrix};
use crate::neighbourhood::{NeighbourhoodKind, VertexLabel};
use crate::numeric::Rational;
use crate::sdc::CentreKind;

/// Largest matrix analysed whole (`Method::Full`): a dense eigenproblem of
/// this size takes seconds; beyond, the request is refused up front.
pub const MAX_FULL_SIZE: usize = 1500;

/// Rows of S by label index, each over every column.
pub type Rows<W> = Vec<Vec<(usize, W)>>;

/// Where the rows of S come from: the one thing a domain supplies besides
/// its labels.
pub trait RowSource {
    /// The rows `which` in floating point.
    fn float_rows(&self, which: &[usize]) -> Result<Rows<f64>, Error>;
    /// All of S in floating point (it may be assembled on first use).
    fn float_matrix(&self) -> Result<FullMatrix<f64>, Error>;
    /// The rows `which` exactly; None when a weight is not rational.
    fn exact_rows(&self, which: &[usize]) -> Option<Rows<Rational>>;
    /// All of S exactly; None when a weight is not rational.
    fn exact_matrix(&self) -> Option<LocalMatrix<Rational>>;
}

/// A domain whose matrices are already assembled (a lattice or curve window:
/// a few dozen points).
pub struct Assembled {
    pub float: LocalMatrix<f64>,
    pub exact: Option<LocalMatrix<Rational>>,
}

impl RowSource for Assembled {
    fn float_rows(&self, which: &[usize]) -> Result<Rows<f64>, Error> {
        Ok(which.iter().map(|&k| self.float.rows[k].clone()).collect())
    }
    fn float_matrix(&self) -> Result<FullMatrix<f64>, Error> {
        Ok(FullMatrix::ready(self.float.clone()))
    }
    fn exact_rows(&self, which: &[usize]) -> Option<Rows<Rational>> {
        let m = self.exact.as_ref()?;
        Some(which.iter().map(|&k| m.rows[k].clone()).collect())
    }
    fn exact_matrix(&self) -> Option<LocalMatrix<Rational>> {
        self.exact.clone()
    }
}

/// Who a spectrum belongs to: the identifying fields of [`Spectrum`].
#[derive(Clone, Debug)]
pub struct Identity {
    pub scheme: String,
    pub valence: usize,
    pub params: std::collections::BTreeMap<String, String>,
    pub faces: String,
    pub centre: CentreKind,
    pub neighbourhood: NeighbourhoodKind,
    pub minimal_size: usize,
    pub analysis_size: usize,
    /// the tagging of a tagged vertex (`neighbourhood::Tagging::name`),
    /// whose spectral criterion is the sector one (`verdict::sector`)
    pub tagging: Option<String>,
}

/// One local eigenproblem, whatever its domain.
pub struct Problem<'a> {
    pub identity: Identity,
    pub labels: Vec<VertexLabel>,
    /// the rotation period of the configuration, in sectors, and the number
    /// of sectors: `period == sectors` means no rotation symmetry (the
    /// lattice and curve windows: period = sectors = 1)
    pub period: usize,
    pub sectors: usize,
    /// the method asked for; None chooses Fourier blocks when there is symmetry
    pub method: Option<Method>,
    /// confirm eigenvalues exactly where S is rational
    pub exact: bool,
    /// which rationals the exact stage tries as eigenvalues
    pub candidates: exact::Candidates,
    pub rows: &'a dyn RowSource,
}

impl<'a> Problem<'a> {
    /// A window of a lattice or a line: no rotation symmetry to use (the
    /// masks may be asymmetric), so the whole matrix, labelled as assembled.
    pub fn window(identity: Identity, rows: &'a Assembled, exact: bool, candidates: exact::Candidates) -> Self {
        Problem {
            identity,
            labels: rows.float.labels.clone(),
            period: 1,
            sectors: 1,
            method: Some(Method::Full),
            exact,
            candidates,
            rows,
        }
    }
}

/// What the driver computed.
pub struct Solved {
    /// S over the whole neighbourhood; with Fourier blocks only the
    /// representative rows were needed, and the rest is their rotation,
    /// assembled on first access
    pub matrix: FullMatrix<f64>,
    pub exact_matrix: Option<FullMatrix<Rational>>,
    pub spectrum: Spectrum,
}

/// The driver: method, float eigen-stage, exact confirmation, verdict.
pub fn solve(p: Problem) -> Result<Solved, Error> {
    let size = p.labels.len();
    let (period, n) = (p.period, p.sectors);
    let symmetric = period < n;
    let method = p.method.unwrap_or(if symmetric { Method::Dft } else { Method::Full });
    if method == Method::Full && size > MAX_FULL_SIZE {
        // refused before the O(size³) work, with the estimate
        let minutes = (size as f64 / 1800.0).powi(3);
        return Err(Error::Input(format!(
            "the whole-matrix method needs a dense {size}×{size} eigenproblem, above the supported {MAX_FULL_SIZE}×{MAX_FULL_SIZE} \
             (its cost grows as the cube of the size: about {minutes:.1} min here){}",
            if symmetric { "; use --method dft" } else { "; this configuration has no rotation symmetry: use a smaller valence" }
        )));
    }
    let kind = p.identity.neighbourhood;
    let orbits = Orbits::from_labels(&p.labels, period, n);
    let (matrix, Decomposition { blocks, mut eigenvalues, synthesis }) = match method {
        Method::Dft => {
            // the representative rows are all the blocks need; the rest of S,
            // if anyone asks, is their rotation
            let rows = p.rows.float_rows(&orbits.representative)?;
            let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
            let decomposition = decompose_dft(&refs, orbits.clone())?;
            (lazy_full_by_rotation(p.labels.clone(), kind, &orbits, rows), decomposition)
        }
        Method::Full => {
            let matrix = p.rows.float_matrix()?;
            let decomposition = decompose(&matrix, period, n, Method::Full)?;
            (matrix, decomposition)
        }
    };
    sort_eigenvalues(&mut eigenvalues);
    let (exact_matrix, exact_analysis): (Option<FullMatrix<Rational>>, Option<ExactSummary>) = if !p.exact {
        (None, None)
    } else if exact::needs_full(size, period, n) {
        match p.rows.exact_matrix() {
            Some(m) => {
                let summary = exact::confirm(&m, &mut eigenvalues, period, n, p.candidates);
                (Some(FullMatrix::ready(m)), Some(summary))
            }
            None => (None, None),
        }
    } else {
        // block 0 needs the representative rows only; the rest of the exact
        // S, if anyone asks, is their rotation
        match p.rows.exact_rows(&orbits.representative) {
            Some(rows) => {
                let refs: Vec<&[(usize, Rational)]> = rows.iter().map(Vec::as_slice).collect();
                let summary = exact::confirm_block0(&refs, &orbits, &mut eigenvalues, p.candidates);
                (Some(lazy_full_by_rotation(p.labels.clone(), kind, &orbits, rows)), Some(summary))
            }
            None => (None, None),
        }
    };
    let id = p.identity;
    let verdict = match id.tagging {
        None => verdict::reif(&eigenvalues),
        Some(_) => verdict::sector(&eigenvalues),
    };
    let spectrum = Spectrum {
        scheme: id.scheme,
        valence: id.valence,
        params: id.params,
        faces: id.faces,
        centre: id.centre,
        neighbourhood: id.neighbourhood,
        matrix_size: size,
        minimal_size: id.minimal_size,
        analysis_size: id.analysis_size,
        tagging: id.tagging,
        method,
        blocks,
        eigenvalues,
        verdict,
        exact_analysis,
        crease: None,
        labels: p.labels,
        synthesis,
    };
    Ok(Solved { matrix, exact_matrix, spectrum })
}

#[cfg(test)]
mod tests;
