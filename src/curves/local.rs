//! The local subdivision matrix of a curve scheme around a vertex, and its
//! spectrum (exact where every weight is rational).
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

use std::collections::{BTreeMap, BTreeSet};

use faer::{c64, Mat};
use serde::Serialize;

use super::{CurveMask, CurveScheme, CurveWeight};
use crate::neighbourhood::NeighbourhoodKind;
use crate::numeric::exact::{rational_roots, QMatrix};
use crate::numeric::recognise::{convergents, recognise};
use crate::numeric::{Rational, Weight};

/// Guard against masks whose dependency closure does not stay local.
const MAX_WINDOW: usize = 1000;
/// Most levels followed when collecting the limit influence set.
const MAX_INFLUENCE_LEVELS: u32 = 16;

fn close<W: Weight>(mask: &CurveMask<W>, seed: BTreeSet<i64>) -> Result<BTreeSet<i64>, String> {
    let mut set = seed;
    let mut todo: Vec<i64> = set.iter().copied().collect();
    while let Some(k) = todo.pop() {
        for (i, _) in mask.stencil(k) {
            if set.insert(i) {
                todo.push(i);
                if set.len() > MAX_WINDOW {
                    return Err(format!("no invariant window of at most {MAX_WINDOW} points: the mask is not local"));
                }
            }
        }
    }
    Ok(set)
}

/// The minimal invariant window: closure of the one-ring {−1, 0, 1}.
pub fn minimal_window<W: Weight>(mask: &CurveMask<W>) -> Result<Vec<i64>, String> {
    Ok(close(mask, [-1, 0, 1].into_iter().collect())?.into_iter().collect())
}

/// The old points that influence the limit curve over [−1, 1] (see module doc).
pub fn influence_set<W: Weight>(mask: &CurveMask<W>) -> Result<BTreeSet<i64>, String> {
    let mut union: BTreeSet<i64> = BTreeSet::new();
    let mut unchanged = 0;
    for level in 1..=MAX_INFLUENCE_LEVELS {
        let r = 1i64 << level;
        let mut set: BTreeSet<i64> = (-r..=r).collect();
        for _ in 0..level {
            set = set.iter().flat_map(|&k| mask.stencil(k).into_iter().map(|t| t.0)).collect();
        }
        let before = union.len();
        union.extend(set);
        unchanged = if union.len() == before { unchanged + 1 } else { 0 };
        // the influence of level-L points lies within the mask's reach of [−1, 1];
        // once 2^L well exceeds that reach, further levels only repeat the pattern
        if unchanged >= 2 && r > 4 * (mask.reach() + 1) {
            return Ok(union);
        }
    }
    Err("the set of points influencing the limit curve did not settle".into())
}

/// The analysis window: closure of the influence set and the minimal window.
pub fn analysis_window<W: Weight>(mask: &CurveMask<W>) -> Result<Vec<i64>, String> {
    let mut seed = influence_set(mask)?;
    seed.extend(minimal_window(mask)?);
    Ok(close(mask, seed)?.into_iter().collect())
}

/// Local subdivision matrix on an invariant window: sparse rows (column, weight).
#[derive(Clone, Debug)]
pub struct CurveMatrix<W> {
    pub window: Vec<i64>,
    pub rows: Vec<Vec<(usize, W)>>,
}

impl<W: Weight> CurveMatrix<W> {
    pub fn size(&self) -> usize {
        self.window.len()
    }
    pub fn dense(&self) -> Vec<Vec<W>> {
        let n = self.size();
        let mut d = vec![vec![W::zero(); n]; n];
        for (i, row) in self.rows.iter().enumerate() {
            for (j, w) in row {
                d[i][*j] = w.clone();
            }
        }
        d
    }
}

pub fn local_matrix<W: Weight>(mask: &CurveMask<W>, window: &[i64]) -> Result<CurveMatrix<W>, String> {
    let pos: BTreeMap<i64, usize> = window.iter().enumerate().map(|(p, &k)| (k, p)).collect();
    let mut rows = Vec::with_capacity(window.len());
    for &k in window {
        let mut row = Vec::new();
        for (i, w) in mask.stencil(k) {
            let col = *pos.get(&i).ok_or_else(|| format!("window is not invariant: point {k} depends on {i}"))?;
            row.push((col, w));
        }
        row.sort_by_key(|e| e.0);
        rows.push(row);
    }
    Ok(CurveMatrix { window: window.to_vec(), rows })
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

/// Window, local matrix and spectrum of a curve scheme at a vertex.
pub fn curve_spectrum(scheme: &dyn CurveScheme, kind: NeighbourhoodKind) -> Result<CurveSpectrum, String> {
    let mask = <f64 as CurveWeight>::mask(scheme).map_err(|_| "a weight is not representable".to_string())?;
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
    let m = local_matrix(&mask, &window)?;
    let n = m.size();
    let dense = m.dense();
    let block = Mat::<c64>::from_fn(n, n, |i, j| c64::new(dense[i][j], 0.0));
    let floats = crate::spectrum::eigen::block_eigen(&block)?;
    let mut eigenvalues: Vec<CurveEigenvalue> = floats
        .iter()
        .map(|e| {
            let im = if e.value.im.abs() < 1e-12 * e.value.norm().max(1.0) { 0.0 } else { e.value.im };
            CurveEigenvalue {
                re: e.value.re,
                im,
                modulus: e.value.norm(),
                algebraic_multiplicity: e.algebraic,
                geometric_multiplicity: e.geometric,
                defective: e.geometric < e.algebraic,
                exact: None,
                recognised: if im == 0.0 { recognise(e.value.re) } else { None },
            }
        })
        .collect();
    let mut exact_matrix = None;
    let mut charpoly = None;
    let mut exact = false;
    if let Some(em) = &exact_mask {
        let qm = local_matrix(em, &window)?;
        let mut q = QMatrix::zeros(n);
        for (i, row) in qm.rows.iter().enumerate() {
            for (j, w) in row {
                q.set(i, *j, w.clone());
            }
        }
        let poly = q.charpoly();
        let candidates: Vec<Rational> = eigenvalues
            .iter()
            .filter(|e| e.im == 0.0)
            .flat_map(|e| convergents(e.re, 1_000_000_000).into_iter().map(|(p, q)| Rational::ratio(p, q)))
            .collect();
        let (roots, rest) = rational_roots(&poly, &candidates);
        charpoly = Some(poly.pretty());
        exact_matrix = Some(qm.dense().iter().map(|r| r.iter().map(|x| x.to_string()).collect()).collect());
        if rest.degree() == 0 {
            // every eigenvalue is rational and proven: multiplicities from the
            // polynomial, eigenspace dimensions from exact ranks
            exact = true;
            eigenvalues = roots
                .iter()
                .map(|(r, alg)| {
                    let geo = n - q.shifted(r).rank();
                    let re = Weight::to_f64(r);
                    CurveEigenvalue {
                        re,
                        im: 0.0,
                        modulus: re.abs(),
                        algebraic_multiplicity: *alg,
                        geometric_multiplicity: geo,
                        defective: geo < *alg,
                        exact: Some(r.to_string()),
                        recognised: recognise(re),
                    }
                })
                .collect();
        } else {
            for (r, _) in &roots {
                let v = Weight::to_f64(r);
                if let Some(e) = eigenvalues
                    .iter_mut()
                    .find(|e| e.im == 0.0 && (e.re - v).abs() <= 1e-7 * v.abs().max(1.0) && e.exact.is_none())
                {
                    e.exact = Some(r.to_string());
                }
            }
        }
    }
    eigenvalues.sort_by(|a, b| crate::spectrum::eigenvalue_order(c64::new(a.re, a.im), c64::new(b.re, b.im)));
    Ok(CurveSpectrum {
        scheme: scheme.name().to_string(),
        params: scheme.params().values.iter().map(|(k, v)| (k.clone(), v.text.clone())).collect(),
        neighbourhood: kind,
        matrix_size: n,
        minimal_size: minimal.len(),
        analysis_size: analysis.len(),
        window,
        matrix: dense,
        exact_matrix,
        charpoly,
        exact,
        eigenvalues,
    })
}
