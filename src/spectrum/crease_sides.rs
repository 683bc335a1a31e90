//! The per-side verdict at a crease vertex (issue 26).
//!
//! A crease vertex (`--tag crease:K`) has two smooth sides: side A, the K
//! sectors 0..K−1 between the sharp rays 0 and K, and side B, the n − K
//! sectors K..n−1. The piecewise-smooth theory analyses such a vertex sector
//! by sector (Zorin 2000, "A method for analysis of C¹-continuity of
//! subdivision surfaces"; Biermann, Levin and Zorin 2000, "Piecewise smooth
//! subdivision surfaces with normal control"): each side must satisfy the
//! boundary-vertex criterion with its own eigen-data, the crease curve's
//! eigenvalues shared. Applied to S whole, the criterion sees both sides'
//! cross modes at once (the regular crease: 1/2 three times) and fails where
//! each side is a spline patch.
//!
//! Why a side has its own matrix. With crease rules that read only the
//! curve on the curve (Hoppe et al. 1994, OpenSubdiv, BLZ), a point of side A
//! is made from side A's and the curve's points alone. Then the set X of
//! side A's points with the curve's is closed under "row a of S reads
//! column b": S[a][b] = 0 for a ∈ X, b ∉ X. So the coordinates on X evolve
//! by themselves, (S x)_X = S_XX x_X, and S_XX (the principal submatrix) is
//! the subdivision matrix of a fan of K faces with a boundary curve — the
//! boundary fan of K faces. In the order (curve C, side A only, side B only)
//! S is block lower triangular, [[S_CC, 0, 0], [*, S_A'A', 0], [*, 0, S_B'B']],
//! so spec S = spec S_AA ∪ spec S_BB less one copy of spec S_CC
//! (`tests/crease_sides.rs` checks this exactly over Q).
//!
//! Nothing here is hard-coded per scheme: the side's set is the dependency
//! closure, through S's own non-zero entries, of the points strictly inside
//! that side (by their labels); the sides decouple when neither closure
//! reaches a point strictly inside the other side. The invariance is then
//! re-checked on the exact rows where there are some (a weight the float
//! rows round to almost zero must be exactly zero).

use super::driver::{self, Assembled, Identity, Problem};
use super::exact::Candidates;
use super::spectrum_result::{CreaseVerdict, SideSpectrum};
use super::verdict::Verdict;
use crate::error::Error;
use crate::matrix::local::FullMatrix;
use crate::matrix::LocalMatrix;
use crate::neighbourhood::{Configuration, Tagging, VertexKind, VertexLabel};
use crate::numeric::Rational;

/// Float weights at most this much (relative to the largest) do not count
/// as reads when the closure is formed (rows composed from stencils may
/// carry rounding where exact weights cancel); the exact rows decide.
pub const READ_TOLERANCE: f64 = 1e-12;

/// The side a labelled point lies strictly inside (0: side A, sectors
/// 0..K−1; 1: side B), or `None` on the crease curve (the centre and the
/// points of the sharp rays 0 and K). A point of sector s has chart
/// coordinates (i, j) along rays s and s + 1; j = 0 puts it on ray s.
pub fn side_of(label: &VertexLabel, at: usize) -> Option<usize> {
    let on_sharp_ray = label.j == 0 && (label.sector == 0 || label.sector == at);
    if label.kind == VertexKind::Centre || on_sharp_ray {
        None
    } else {
        Some(usize::from(label.sector >= at))
    }
}

/// The smallest set holding `seed` and every column a row of the set reads
/// (`reads(a)`: the columns of row a's non-zero weights), ascending.
pub fn dependency_closure(seed: &[usize], reads: &dyn Fn(usize) -> Vec<usize>) -> Vec<usize> {
    let mut inside: std::collections::BTreeSet<usize> = seed.iter().copied().collect();
    let mut frontier: Vec<usize> = seed.to_vec();
    while let Some(a) = frontier.pop() {
        for b in reads(a) {
            if inside.insert(b) {
                frontier.push(b);
            }
        }
    }
    inside.into_iter().collect()
}

/// The two sides of a crease vertex whose rules decouple them.
#[derive(Clone, Debug, serde::Serialize)]
pub struct CreaseSides {
    /// K: side A is sectors 0..K−1, side B sectors K..n−1
    pub at: usize,
    pub valence: usize,
    /// each side's points (matrix indices, ascending): the dependency
    /// closure of the points strictly inside it, the curve's it reads
    /// included
    pub sides: [Vec<usize>; 2],
    /// the points both sides read (the crease curve's)
    pub curve: Vec<usize>,
}

impl CreaseSides {
    /// The faces (sectors) of side 0 (A) or 1 (B).
    pub fn faces(&self, side: usize) -> usize {
        if side == 0 {
            self.at
        } else {
            self.valence - self.at
        }
    }
    /// "side A (sectors 0..1, 2 faces, 15 points)".
    pub fn name(&self, side: usize) -> String {
        let (first, last) = if side == 0 { (0, self.at - 1) } else { (self.at, self.valence - 1) };
        format!(
            "side {} (sectors {first}..{last}, {} face{}, {} points)",
            ["A", "B"][side],
            self.faces(side),
            if self.faces(side) == 1 { "" } else { "s" },
            self.sides[side].len()
        )
    }
}

/// Whether the sides of a crease decouple, found from the reads of S's rows.
#[derive(Clone, Debug)]
pub enum Decoupling {
    Sides(CreaseSides),
    /// why not (the verdict then is S whole's)
    Coupled(String),
}

/// The sides of a `crease:K` configuration from the reads of S's rows;
/// `None` when the configuration is not a crease.
pub fn decouple(
    config: &Configuration,
    labels: &[VertexLabel],
    reads: &dyn Fn(usize) -> Vec<usize>,
) -> Option<Decoupling> {
    let Some(Tagging::Crease { at }) = config.tagging else { return None };
    let inside =
        |side: usize| -> Vec<usize> { (0..labels.len()).filter(|&p| side_of(&labels[p], at) == Some(side)).collect() };
    let seeds = [inside(0), inside(1)];
    if seeds.iter().any(Vec::is_empty) {
        return Some(Decoupling::Coupled(
            "a side has no point strictly inside it in this neighbourhood (use the analysis neighbourhood)".into(),
        ));
    }
    let sides = [dependency_closure(&seeds[0], reads), dependency_closure(&seeds[1], reads)];
    for (s, set) in sides.iter().enumerate() {
        if let Some(&p) = set.iter().find(|&&p| side_of(&labels[p], at) == Some(1 - s)) {
            return Some(Decoupling::Coupled(format!(
                "the rows of side {}'s points read, through their closure, {} strictly inside side {}",
                ["A", "B"][s],
                labels[p].name,
                ["B", "A"][s]
            )));
        }
    }
    let curve: Vec<usize> = sides[0].iter().copied().filter(|p| sides[1].binary_search(p).is_ok()).collect();
    Some(Decoupling::Sides(CreaseSides { at, valence: config.valence(), sides, curve }))
}

/// The invariance of `set` on sparse rows of S: `None` when every row of
/// the set has zero weight (by `is_zero`) outside it, else the first
/// (row, column) that has one.
pub fn first_weight_outside<W>(
    rows: &[Vec<(usize, W)>],
    set: &[usize],
    is_zero: impl Fn(&W) -> bool,
) -> Option<(usize, usize)> {
    set.iter().find_map(|&a| weight_outside(&rows[a], set, &is_zero).map(|b| (a, b)))
}

/// The first column of `row` outside `set` (ascending) with a weight that is
/// not zero.
pub fn weight_outside<W>(row: &[(usize, W)], set: &[usize], is_zero: impl Fn(&W) -> bool) -> Option<usize> {
    row.iter().find(|(b, w)| set.binary_search(b).is_err() && !is_zero(w)).map(|(b, _)| *b)
}

/// The principal submatrix of sparse rows on `set` (ascending), re-indexed
/// 0..set.len(); weights outside the set are dropped (check
/// [`first_weight_outside`] first).
pub fn principal<W: Clone>(rows: &[Vec<(usize, W)>], set: &[usize]) -> Vec<Vec<(usize, W)>> {
    set.iter().map(|&a| principal_row(&rows[a], set)).collect()
}

/// One row of [`principal`]: its entries on `set`, re-indexed.
pub fn principal_row<W: Clone>(row: &[(usize, W)], set: &[usize]) -> Vec<(usize, W)> {
    row.iter().filter_map(|(b, w)| set.binary_search(b).ok().map(|k| (k, w.clone()))).collect()
}

/// [`principal`] of a local matrix, with the set's labels.
fn principal_matrix<W: Clone>(m: &LocalMatrix<W>, set: &[usize]) -> LocalMatrix<W> {
    LocalMatrix {
        kind: m.kind,
        labels: set.iter().map(|&k| m.labels[k].clone()).collect(),
        rows: principal(&m.rows, set),
    }
}

/// [`decouple`] on the float rows of S (a weight below [`READ_TOLERANCE`]
/// relative to the largest counts as no read): `None` for a configuration
/// that is not a crease, decided before S is read, so the lazy S of every
/// other configuration stays unassembled (the Fourier path never needs it).
pub fn decoupling(config: &Configuration, float: &FullMatrix<f64>) -> Option<Decoupling> {
    if !matches!(config.tagging, Some(Tagging::Crease { .. })) {
        return None;
    }
    let float: &LocalMatrix<f64> = float;
    let scale = float.rows.iter().flatten().fold(0.0f64, |m, (_, w)| m.max(w.abs())).max(1.0);
    let reads = |a: usize| -> Vec<usize> {
        float.rows[a].iter().filter(|(_, w)| w.abs() > READ_TOLERANCE * scale).map(|(b, _)| *b).collect()
    };
    decouple(config, &float.labels, &reads)
}

/// The per-side analysis of a crease configuration from S (float, and exact
/// where rational): `None` for other configurations. `identity` names the
/// whole analysis (each side's is derived from it); `exact` asks for the
/// exact confirmation of each side's spectrum.
pub fn crease_verdict(
    config: &Configuration,
    identity: &Identity,
    float: &FullMatrix<f64>,
    exact_matrix: Option<&FullMatrix<Rational>>,
    whole: &Verdict,
    exact: bool,
) -> Result<Option<CreaseVerdict>, Error> {
    let Some(decoupling) = decoupling(config, float) else { return Ok(None) };
    let exact_matrix: Option<&LocalMatrix<Rational>> = exact_matrix.map(|q| &**q);
    let coupled = |why: String| CreaseVerdict {
        invariance: None,
        curve_size: 0,
        sides: Vec::new(),
        coupled: Some(why),
        whole: whole.clone(),
    };
    let sides = match decoupling {
        Decoupling::Coupled(why) => return Ok(Some(coupled(why))),
        Decoupling::Sides(s) => s,
    };
    // the invariance re-checked: exactly on the exact rows, else on the
    // float rows to the tolerance the closure used
    let invariance = match exact_matrix {
        Some(q) => {
            for set in &sides.sides {
                if let Some((a, b)) = first_weight_outside(&q.rows, set, |w| *w == Rational::from_integer(0.into())) {
                    return Ok(Some(coupled(format!(
                        "row {} has the exact weight {} on {} outside its side (the float rows round it to almost zero)",
                        float.labels[a].name,
                        q.get(a, b),
                        float.labels[b].name
                    ))));
                }
            }
            "exact, in Q".to_string()
        }
        None => format!("floating point (weights up to {READ_TOLERANCE:e} relative taken as zero)"),
    };
    let mut out = Vec::new();
    for (s, set) in sides.sides.iter().enumerate() {
        let rows =
            Assembled { float: principal_matrix(float, set), exact: exact_matrix.map(|q| principal_matrix(q, set)) };
        let side_identity = Identity {
            tagging: Some(format!("{} side {}", config.tagging.map(|t| t.name()).unwrap_or_default(), ["A", "B"][s])),
            analysis_size: set.len(),
            ..identity.clone()
        };
        // the same driver as every matrix: float spectrum, exact
        // confirmation of the whole (small) side, the sector verdict
        let solved = driver::solve(Problem::window(side_identity, &rows, exact, Candidates::Recognised))?;
        out.push(SideSpectrum {
            name: sides.name(s),
            faces: sides.faces(s),
            size: set.len(),
            eigenvalues: solved.spectrum.eigenvalues.clone(),
            verdict: solved.spectrum.verdict.clone(),
            exact_analysis: solved.spectrum.exact_analysis.clone(),
            points: set.clone(),
            spectrum: Box::new(solved.spectrum),
        });
    }
    Ok(Some(CreaseVerdict {
        invariance: Some(invariance),
        curve_size: sides.curve.len(),
        sides: out,
        coupled: None,
        whole: whole.clone(),
    }))
}

/// The crease's verdict as one [`Verdict`] (criterion "sector per side"):
/// PASSES iff both sides pass; each failing condition names its side. When
/// the sides do not decouple, S whole's verdict with that reason first.
pub fn combined(c: &CreaseVerdict) -> Verdict {
    let mut v = c.whole.clone();
    if let Some(why) = &c.coupled {
        let note = format!("no per-side verdict: {why}; the criterion is applied to S whole");
        v.reasons.insert(0, note);
        return v;
    }
    v.criterion = "sector per side";
    v.reasons = vec![format!(
        "the sides decouple: each side's points with the crease curve's ({} points) are invariant under S (checked {})",
        c.curve_size,
        c.invariance.as_deref().unwrap_or("-")
    )];
    v.failures = Vec::new();
    for side in &c.sides {
        let word = if side.verdict.c1_spectral { "PASSES" } else { "FAILS" };
        let said: Vec<&str> =
            side.verdict.reasons.iter().filter(|r| !r.starts_with("not decided here")).map(String::as_str).collect();
        v.reasons.push(format!("{}: {word}: {}", side.name, said.join("; ")));
        v.failures.extend(side.verdict.failures.iter().map(|f| format!("{}: {f}", side.name)));
    }
    v.reasons.push("not decided here: the characteristic map's regularity and injectivity on the sectors".into());
    v.c1_spectral = c.sides.iter().all(|s| s.verdict.c1_spectral);
    v
}
