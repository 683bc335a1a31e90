//! Spectrum of the local subdivision matrix: via Fourier blocks when the
//! configuration is rotation-symmetric, via the full matrix otherwise; merged
//! into distinct eigenvalues with multiplicities, eigenvectors mapped back to
//! labelled vertices, exact confirmation where S is rational.

pub mod analysis;
pub mod crease_sides;
pub mod decomposition;
pub mod driver;
pub mod eigen;
pub mod eigenvalue;
pub mod exact;
pub mod reflection;
pub mod spectrum_result;
pub mod stencils;
pub mod strip;
pub mod verdict;

pub use analysis::{analyse, analyse_shared, spectrum_of, Analysis, Options};
pub use decomposition::{decompose, decompose_dft, Decomposition};
pub use driver::MAX_FULL_SIZE;
pub use eigenvalue::{eigenvalue_order, fmt_f, sort_eigenvalues, EigenVectors, Eigenvalue};
pub use exact::ExactSummary;
pub use spectrum_result::{BlockInfo, Method, Spectrum, Synthesis};
pub use verdict::Verdict;
