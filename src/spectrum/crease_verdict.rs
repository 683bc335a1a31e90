//! What the per-side analysis of a crease vertex finds
//! (`spectrum::crease_sides` makes it; a `Spectrum` carries it). A file of
//! its own, below the driver, so that the spectrum's type does not import
//! the analysis that uses the driver.

use serde::Serialize;

use super::eigenvalue::Eigenvalue;
use super::exact::ExactSummary;
use super::spectrum_result::Spectrum;
use super::verdict::Verdict;

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
