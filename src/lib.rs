//! subdlab: eigenanalysis and smoothness verification of subdivision surfaces.
//!
//! Pipeline (one module per stage, see DESIGN.md):
//! `schemes` (rules) + `neighbourhood` (configuration, discovery) → `topology` +
//! `refine` (one step) → `matrix` (local S) → `dft` (Fourier blocks) →
//! `spectrum` (eigenvalues, stencils, verdicts) → `cli`.

pub mod charmap;
pub mod claims;
pub mod cli;
pub mod curves;
pub mod dft;
// regular-lattice schemes with explicit (i, j) coordinates (Khan–Mustafa)
pub mod lattice;
pub mod matrix;
pub mod mesh;
pub mod neighbourhood;
pub mod numeric;
// figures (SVG / PNG)
pub mod plot;
pub mod refine;
pub mod report;
pub mod schemes;
pub mod sdc;
pub mod spectrum;
pub mod sweep;
pub mod topology;
