//! subdlab: eigenanalysis and smoothness verification of subdivision surfaces.
//!
//! The crate is layered; each layer imports only the layers listed before it
//! (`tests/layers.rs` fails the build's tests when an import points upwards):
//!
//! 1. foundation: [`numeric`] (weights: f64 and exact rationals, expressions),
//!    [`mesh`] (polygon meshes, charts, OBJ), [`io`] (atomic file writing),
//!    [`error`] (the typed error);
//! 2. scheme description, [`sdc`]: the rule interface `Rules<W>` / `Scheme`,
//!    origins and stencils, the host a scheme runs on, typed parameters;
//! 3. refinement hosts, [`topology`]: connectivity of one step, no weights;
//! 4. the engine: [`refine`] (one step over any averaged data),
//!    [`engine`] (the invariant closure of every domain; assembly and exact
//!    confirmation for the Z² and Z domains),
//!    [`neighbourhood`] (configurations, discovery of invariant sets),
//!    [`matrix`] (the local subdivision matrix), [`dft`] (Fourier blocks);
//! 5. [`spectrum`]: eigenvalues with multiplicities, stencils, verdicts;
//! 6. analyses on top of a spectrum: [`charmap`] (characteristic maps), and
//!    the other domains, [`lattice`] (Z² masks) and [`curves`] (Z masks);
//!    on top of the characteristic map, [`curvature`] (second order: the
//!    curvature class, F(μ), Reif's C² test); [`certify`] (rigorous
//!    eigenvalue enclosures and the certified spectral verdict);
//! 7. the scheme catalogue, [`schemes`]: one file per built-in scheme and the
//!    scheme-file loader; nothing below imports it;
//! 8. [`claims`] (paper statements as data) and [`sweep`];
//! 9. [`plot`] and [`report`];
//! 10. [`cli`], the `subdlab` command line.
//!
//! The [`prelude`] exports what a library user needs for the common calls.

// Output goes through `io::out`, which reports a failed write (a full disk)
// as the one-line error: `print!` panics instead.
#![deny(clippy::print_stdout)]

pub mod error;
pub mod io;
pub mod mesh;
pub mod numeric;

pub mod sdc;

pub mod topology;

pub mod dft;
// the invariant closure of every domain; Z² and Z assembly and exact confirmation
pub mod engine;
pub mod matrix;
pub mod neighbourhood;
pub mod refine;

pub mod spectrum;

pub mod charmap;
pub mod curves;
// second order: curvature class, F(μ), Reif's C² test (uses charmap)
pub mod curvature;
// regular-lattice schemes with explicit (i, j) coordinates (Khan–Mustafa)
pub mod lattice;
// certified verdicts: interval enclosures of the spectrum
pub mod certify;

pub mod schemes;
pub mod shape_chart;

pub mod claims;
pub mod sweep;
// spectral C¹ at every valence: per-valence certificates and one parametric proof
pub mod every_valence;

// figures (SVG / PNG)
pub mod plot;
pub mod report;

pub mod cli;

/// The common calls: build a scheme, analyse a configuration, read its
/// spectrum and characteristic map.
///
/// ```
/// use subdlab::prelude::*;
/// let scheme = schemes::build("loop", &[]).unwrap();
/// let spectrum = spectrum_of(scheme.as_ref(), 5).unwrap();
/// assert!((spectrum.eigenvalues[0].re - 1.0).abs() < 1e-12);
/// ```
pub mod prelude {
    pub use crate::charmap::{characteristic_map, characteristic_map_of, CharMap, CharMapOptions};
    pub use crate::error::Error;
    pub use crate::neighbourhood::{Configuration, NeighbourhoodKind};
    pub use crate::numeric::{Rational, Weight};
    pub use crate::schemes;
    pub use crate::sdc::{CentreKind, Origin, Params, Rules, Scheme, SchemeWeight, Stencil, Topology};
    pub use crate::spectrum::{analyse, spectrum_of, Analysis, Method, Options, Spectrum};
}
