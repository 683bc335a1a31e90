//! What an analysis finds (`Spectrum`): whose spectrum it is, the method and
//! blocks, the distinct eigenvalues, Reif's verdict and the exact summary,
//! and the synthesis that maps block vectors to the labelled neighbourhood;
//! at a crease vertex, the per-side verdicts (`CreaseVerdict`).

use faer::c64;
use faer::Mat;
use serde::Serialize;

use super::eigen;
use super::eigenvalue::Eigenvalue;
use super::exact::ExactSummary;
use super::verdict::Verdict;
use crate::dft::{omega_pow, Orbits};
use crate::neighbourhood::{NeighbourhoodKind, VertexLabel};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Fourier blocks of the rotation-symmetric matrix
    Dft,
    /// the full matrix (no rotation symmetry, or forced)
    Full,
}

#[derive(Clone, Debug, Serialize)]
pub struct BlockInfo {
    pub index: usize,
    pub size: usize,
}

/// The blocks that were decomposed, and how block coordinates map to
/// neighbourhood vertices.
#[derive(Clone, Debug)]
pub enum Synthesis {
    /// block m's coordinate k is orbit `block_orbits[m][k]`
    Dft { orbits: Orbits, block_orbits: Vec<Vec<usize>>, blocks: Vec<Mat<c64>> },
    /// the single block is the whole matrix
    Full { matrix: Mat<c64> },
}

impl Synthesis {
    /// Fourier block `m`, or the whole matrix when there is no symmetry.
    pub fn block(&self, m: usize) -> &Mat<c64> {
        match self {
            Synthesis::Dft { blocks, .. } => &blocks[m],
            Synthesis::Full { matrix } => matrix,
        }
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Spectrum {
    pub scheme: String,
    pub valence: usize,
    pub params: std::collections::BTreeMap<String, String>,
    pub faces: String,
    pub centre: crate::sdc::CentreKind,
    pub neighbourhood: NeighbourhoodKind,
    pub matrix_size: usize,
    pub minimal_size: usize,
    pub analysis_size: usize,
    /// the tagging of a tagged vertex (`--tag`); absent for interior points
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tagging: Option<String>,
    pub method: Method,
    pub blocks: Vec<BlockInfo>,
    pub eigenvalues: Vec<Eigenvalue>,
    /// the verdict: at a crease vertex whose sides decouple, the per-side
    /// one (`crease`); S whole's is then `crease.whole`
    pub verdict: Verdict,
    pub exact_analysis: Option<ExactSummary>,
    /// at a `crease:K` vertex: each side's spectrum and verdict, and S
    /// whole's verdict (`spectrum::crease_sides`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crease: Option<CreaseVerdict>,
    #[serde(skip)]
    pub labels: Vec<VertexLabel>,
    #[serde(skip)]
    pub synthesis: Synthesis,
}

impl Spectrum {
    /// Right eigenvectors of `e` over the neighbourhood (S x = λ x).
    pub fn right_vectors(&self, e: &Eigenvalue) -> Vec<Vec<c64>> {
        self.map_vectors(e, false)
    }
    /// Left eigenvectors of `e` over the neighbourhood, as rows l with l S = λ l.
    pub fn left_vectors(&self, e: &Eigenvalue) -> Vec<Vec<c64>> {
        self.map_vectors(e, true)
    }
    fn map_vectors(&self, e: &Eigenvalue, left: bool) -> Vec<Vec<c64>> {
        let mut out = Vec::new();
        for vs in &e.vectors {
            let list = if left {
                let lambda = c64::new(e.re, e.im);
                eigen::left_eigenvectors(self.synthesis.block(vs.block), lambda, vs.right.len()).unwrap_or_default()
            } else {
                vs.right.clone()
            };
            for x in &list {
                out.push(match &self.synthesis {
                    Synthesis::Full { .. } => {
                        if left {
                            x.iter().map(|z| z.conj()).collect()
                        } else {
                            x.clone()
                        }
                    }
                    Synthesis::Dft { orbits, block_orbits, .. } => {
                        synthesise(x, vs.block, &block_orbits[vs.block], orbits, self.matrix_size, left)
                    }
                });
            }
        }
        out
    }
}

/// Map one block vector to the whole neighbourhood: right vectors by
/// X[(t,a)] = ω^{mt} x_a, left rows by l[(t,a)] = conj(y_a) ω^{-mt} / g (the
/// dual basis of u_a^m); fixed points (the centre) carry their value as is.
fn synthesise(x: &[c64], m: usize, block_orbits: &[usize], orbits: &Orbits, size: usize, left: bool) -> Vec<c64> {
    let g = orbits.group_order;
    let mut pos = vec![usize::MAX; orbits.num_orbits()];
    for (k, &o) in block_orbits.iter().enumerate() {
        pos[o] = k;
    }
    (0..size)
        .map(|k| {
            let (o, t) = orbits.member[k];
            if pos[o] == usize::MAX {
                return c64::new(0.0, 0.0);
            }
            let v = if left { x[pos[o]].conj() } else { x[pos[o]] };
            if orbits.fixed[o] {
                v
            } else if left {
                v * omega_pow(m, t, g).conj() / g as f64
            } else {
                v * omega_pow(m, t, g)
            }
        })
        .collect()
}

// What the per-side analysis of a crease vertex finds (`spectrum::crease_sides`
// makes it; a `Spectrum` carries it, and each side's own `Spectrum` is kept
// in it: one file for the two types that hold each other).

/// One side's spectrum and verdict (the sector criterion on its own matrix).
#[derive(Clone, Debug, Serialize)]
pub struct SideSpectrum {
    /// "side A (sectors 0..1, 2 faces, 15 points)"
    pub name: String,
    pub faces: usize,
    /// its points (the principal submatrix's size)
    pub size: usize,
    pub eigenvalues: Vec<Eigenvalue>,
    pub verdict: Verdict,
    pub exact_analysis: Option<ExactSummary>,
    /// its points: indices of S (ascending), the principal submatrix's rows
    #[serde(skip)]
    pub points: Vec<usize>,
    /// the side's whole spectrum with its eigenvectors over `points` (the
    /// per-side characteristic map is built from them, `charmap`)
    #[serde(skip)]
    pub spectrum: Box<Spectrum>,
}

/// The crease's verdict per side, beside S whole's.
#[derive(Clone, Debug, Serialize)]
pub struct CreaseVerdict {
    /// how each side's invariance was checked: "exact, in Q" or "floating
    /// point (weights up to 1e-12 relative taken as zero)"; null when the
    /// sides do not decouple
    pub invariance: Option<String>,
    /// points of the crease curve (both sides read them)
    pub curve_size: usize,
    pub sides: Vec<SideSpectrum>,
    /// why there is no per-side verdict, when there is none (the verdict
    /// is then S whole's)
    pub coupled: Option<String>,
    /// the sector criterion applied to S whole (both sides at once): not the
    /// crease's criterion where the sides decouple, kept for comparison
    pub whole: Verdict,
}
