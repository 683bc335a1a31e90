//! The local subdivision matrix of a curve scheme around a vertex, and its
//! spectrum (exact where every weight is rational), by the one driver that
//! every domain uses (`spectrum::driver`).
//!
//! Windows are found by following dependencies through the mask, never typed
//! in. Refined point k depends on the old points of `mask.stencil(k)`; a set
//! of indices W is invariant when every refined point in W depends only on
//! old points in W, and then S (rows: refined points of W, columns: old points
//! of W) is the local subdivision matrix. Two windows, as for surfaces:
//!
//! - minimal: the dependency closure of the vertex and its two neighbours
//!   (the vertex alone is invariant for an interpolatory scheme, which says
//!   nothing about tangents, so the one-ring is the seed);
//! - analysis: the closure of every old point that influences the limit curve
//!   over the two segments next to the vertex, i.e. the level-0 dependencies of
//!   the level-L points over [−1, 1] (indices |k| ≤ 2^L), collected over L
//!   until they stop growing.

use crate::error::Error;
use std::collections::{BTreeMap, BTreeSet};

use faer::c64;
use serde::Serialize;

use super::{CurveMask, CurveScheme, CurveWeight};
use crate::engine::closure::{self, assemble, invariant_closure, ClosureError, Levels, Refinement};
use crate::engine::LocalMatrix;
use crate::neighbourhood::{NeighbourhoodKind, VertexKind, VertexLabel};
use crate::numeric::recognise::recognise;
use crate::numeric::{Rational, Weight};
use crate::sdc::CentreKind;
use crate::spectrum::driver::{solve, Assembled, Identity, Problem};
use crate::spectrum::exact::Candidates;

/// Guard against masks whose dependency closure does not stay local.
const MAX_WINDOW: usize = 1000;
/// Most levels followed when collecting the limit influence set.
const MAX_INFLUENCE_LEVELS: u32 = 16;

/// The mask as the engine sees it: refined point k depends on the old points
/// of `mask.stencil(k)`.
struct Deps<'a, W>(&'a CurveMask<W>);

impl<W: Weight> Refinement for Deps<'_, W> {
    type Point = i64;
    fn dependencies(&self, k: &i64) -> Result<Vec<i64>, Error> {
        Ok(self.0.stencil(*k).into_iter().map(|t| t.0).collect())
    }
}

/// Largest |offset| of a rule accepted. The invariant window grows with the
/// reach (about twice it, plus the one-ring) and the exact stage's
/// characteristic polynomial over Q grows steeply with the window and the
/// mask's density: a dense mask of reach 8 takes 2 s, of reach 16 over 100 s
/// (a sparse one of reach 32, 12 s). Every built-in scheme reaches 2.
pub const MAX_CURVE_REACH: i64 = 8;

/// Every window is found by [`close`] and [`influence_set`], so every curve
/// analysis refuses a mask past [`MAX_CURVE_REACH`] there, before any work.
fn check_reach<W: Weight>(mask: &CurveMask<W>) -> Result<(), Error> {
    if mask.reach() > MAX_CURVE_REACH {
        return Err(Error::Input(format!(
            "the curve rules reach offset {}, beyond the supported {MAX_CURVE_REACH} (the invariant window grows with \
             the reach and its exact analysis steeply with the window)",
            mask.reach()
        )));
    }
    Ok(())
}

fn close<W: Weight>(mask: &CurveMask<W>, seed: BTreeSet<i64>) -> Result<BTreeSet<i64>, Error> {
    check_reach(mask)?;
    Ok(invariant_closure(&Deps(mask), seed, MAX_WINDOW)?)
}

/// The minimal invariant window: closure of the one-ring {−1, 0, 1}.
pub fn minimal_window<W: Weight>(mask: &CurveMask<W>) -> Result<Vec<i64>, Error> {
    Ok(close(mask, [-1, 0, 1].into_iter().collect())?.into_iter().collect())
}

/// The old points that influence the limit curve over [−1, 1] (see module doc).
pub fn influence_set<W: Weight>(mask: &CurveMask<W>) -> Result<BTreeSet<i64>, Error> {
    check_reach(mask)?;
    // the influence of level-L points lies within the mask's reach of [−1, 1];
    // once 2^L well exceeds that reach, further levels only repeat the pattern
    let levels = Levels::past_reach(mask.reach(), 1, MAX_INFLUENCE_LEVELS);
    Ok(closure::influence_set(&Deps(mask), |l| (-(1i64 << l)..=1i64 << l).collect(), levels)?)
}

/// The analysis window: closure of the influence set and the minimal window.
pub fn analysis_window<W: Weight>(mask: &CurveMask<W>) -> Result<Vec<i64>, Error> {
    let mut seed = influence_set(mask)?;
    seed.extend(minimal_window(mask)?);
    Ok(close(mask, seed)?.into_iter().collect())
}

/// The local subdivision matrix on an invariant window of old point indices
/// (the window is the matrix's labels).
pub fn local_matrix<W: Weight>(mask: &CurveMask<W>, window: &[i64]) -> Result<LocalMatrix<i64, W>, Error> {
    assemble(&Deps(mask), window, |&k| Ok(mask.stencil(k))).map_err(|e| match e {
        ClosureError::NotInvariant { fine, needs } => {
            Error::Input(format!("window is not invariant: point {fine} depends on {needs}"))
        }
        e => e.into(),
    })
}

#[derive(Clone, Debug, Serialize)]
pub struct CurveEigenvalue {
    pub re: f64,
    pub im: f64,
    pub modulus: f64,
    pub algebraic_multiplicity: usize,
    pub geometric_multiplicity: usize,
    pub defective: bool,
    /// exact rational value, a proven root of the exact characteristic polynomial
    pub exact: Option<String>,
    /// a small rational close to the value (a reading aid only)
    pub recognised: Option<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct CurveSpectrum {
    pub scheme: String,
    pub params: BTreeMap<String, String>,
    pub neighbourhood: NeighbourhoodKind,
    pub matrix_size: usize,
    pub minimal_size: usize,
    pub analysis_size: usize,
    /// old point indices of the window, relative to the centre vertex 0
    pub window: Vec<i64>,
    pub matrix: Vec<Vec<f64>>,
    /// the matrix in exact rationals, when every weight is rational
    pub exact_matrix: Option<Vec<Vec<String>>>,
    /// det(xI − S) when exact
    pub charpoly: Option<String>,
    /// true when every eigenvalue and multiplicity was proven exactly
    pub exact: bool,
    pub eigenvalues: Vec<CurveEigenvalue>,
}

/// The labels of a window's points for the shared spectrum types: point i
/// of the line as "P_i", its distance from the centre as its ring.
fn label(k: usize, &i: &i64) -> VertexLabel {
    VertexLabel {
        name: format!("P_{i}"),
        ring: i.unsigned_abs() as usize,
        sector: 0,
        index: k,
        kind: if i == 0 { VertexKind::Centre } else { VertexKind::Vertex },
        i,
        j: 0,
    }
}

/// Window, local matrix and spectrum of a curve scheme at a vertex. The
/// spectrum comes from the one driver (`spectrum::driver::solve`) that the
/// mesh and lattice domains use; when every weight is rational and every
/// eigenvalue is a proven rational root, the eigenvalues reported are the
/// exact ones, with multiplicities from the polynomial and exact ranks.
pub fn curve_spectrum(scheme: &dyn CurveScheme, kind: NeighbourhoodKind) -> Result<CurveSpectrum, Error> {
    let mask =
        <f64 as CurveWeight>::mask(scheme).map_err(|_| Error::Numeric("a weight is not representable".into()))?;
    let exact_mask = <Rational as CurveWeight>::mask(scheme).ok();
    // windows from the exact mask when there is one, so that a weight that is
    // zero only up to rounding is not mistaken for a dependency (or vice versa)
    let (minimal, analysis) = match &exact_mask {
        Some(m) => (minimal_window(m)?, analysis_window(m)?),
        None => (minimal_window(&mask)?, analysis_window(&mask)?),
    };
    let window = match kind {
        NeighbourhoodKind::Minimal => minimal.clone(),
        NeighbourhoodKind::Analysis => analysis.clone(),
    };
    let float = local_matrix(&mask, &window)?.relabel(label).with_kind(kind);
    let exact_matrix = match &exact_mask {
        Some(m) => Some(local_matrix(m, &window)?.relabel(label).with_kind(kind)),
        None => None,
    };
    let rows = Assembled { float, exact: exact_matrix };
    let params: BTreeMap<String, String> =
        scheme.params().values.iter().map(|(k, v)| (k.clone(), v.text.clone())).collect();
    let identity = Identity {
        tagging: None,
        scheme: scheme.name().to_string(),
        valence: 2,
        params: params.clone(),
        faces: String::new(),
        centre: CentreKind::Vertex,
        neighbourhood: kind,
        minimal_size: minimal.len(),
        analysis_size: analysis.len(),
    };
    // a window is a handful of points: every convergent is worth a try
    let problem = Problem::window(identity, &rows, true, Candidates::Convergents);
    let spectrum = solve(problem)?.spectrum;
    let summary = spectrum.exact_analysis.as_ref();
    let exact = summary.is_some_and(|s| s.complete());
    let mut eigenvalues: Vec<CurveEigenvalue> = match summary {
        // every eigenvalue is rational and proven: multiplicities from the
        // polynomial, eigenspace dimensions from exact ranks
        Some(s) if exact => s
            .rational_roots
            .iter()
            .map(|r| {
                let re = Weight::to_f64(&r.rational);
                let geometric = r.geometric_multiplicity.expect("the full method gives exact ranks");
                CurveEigenvalue {
                    re,
                    im: 0.0,
                    modulus: re.abs(),
                    algebraic_multiplicity: r.algebraic_multiplicity,
                    geometric_multiplicity: geometric,
                    defective: geometric < r.algebraic_multiplicity,
                    exact: Some(r.value.clone()),
                    recognised: recognise(re),
                }
            })
            .collect(),
        _ => spectrum
            .eigenvalues
            .iter()
            .map(|e| CurveEigenvalue {
                re: e.re,
                im: e.im,
                modulus: e.modulus,
                algebraic_multiplicity: e.algebraic_multiplicity,
                geometric_multiplicity: e.geometric_multiplicity,
                defective: e.defective,
                exact: e.exact.clone(),
                recognised: e.recognised.clone(),
            })
            .collect(),
    };
    eigenvalues.sort_by(|a, b| crate::spectrum::eigenvalue_order(c64::new(a.re, a.im), c64::new(b.re, b.im)));
    Ok(CurveSpectrum {
        scheme: scheme.name().to_string(),
        params,
        neighbourhood: kind,
        matrix_size: window.len(),
        minimal_size: minimal.len(),
        analysis_size: analysis.len(),
        matrix: rows.float.dense(),
        exact_matrix: rows
            .exact
            .as_ref()
            .map(|m| m.dense().iter().map(|r| r.iter().map(|x| x.to_string()).collect()).collect()),
        charpoly: summary.map(|s| s.poly.pretty()),
        window,
        exact,
        eigenvalues,
    })
}
