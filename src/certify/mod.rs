//! Certified verdicts: statements about the true local subdivision matrix
//! proved with rigorous enclosures, next to the floating-point analysis that
//! only observes them.
//!
//! - [`complex`]: complex intervals (rectangles) and interval matrices; the
//!   real interval with outward rounding is `numeric::Interval`, a weight
//!   type, so the rules themselves evaluate in it;
//! - [`matrix`]: interval rows of S from the rules, their Fourier blocks, and
//!   the structural identities the proof uses (row sums 1, rotation and
//!   mirror symmetry), checked exactly on the rows in Q or in a cyclotomic
//!   field Q(ζ_N) (`numeric::cyclotomic`);
//! - [`discs`]: eigenvalue enclosures of an interval matrix (Gershgorin discs
//!   after a verified approximate diagonalisation), with counts per component;
//! - [`power`]: lemma S6, a bound of an interval block's spectral radius by
//!   ‖B^k‖∞^{1/k} (interval squarings), for blocks whose eigenvectors are
//!   defective or ill-conditioned and that need only be bounded above;
//! - [`spectrum`]: the spectral verdict (λ0 = 1 simple, λ1 real positive from
//!   blocks 1 and g − 1, a proven gap to every other eigenvalue):
//!   PROVED / DISPROVED / NOT PROVED with the reason and the margins.
//! - [`exact_spectrum`]: the spectral verdict of a rational matrix from its
//!   exact characteristic polynomial (λ1 a double semisimple rational root,
//!   Schur–Cohn for the rest), where no rotation splits λ1's pair;
//! - [`export`]: the certificate document (JSON) that an independent
//!   checker, `scripts/check_cert.py`, re-verifies from the exact rows;
//! - [`charmap`]: the geometric verdict (the characteristic map regular and
//!   injective) from enclosed eigenvectors, an interval net refined with the
//!   rules, box-spline (or non-box S_3^1) Jacobian bounds per ring face and a
//!   certified winding number; with the spectral verdict, Reif's criterion
//!   as a whole;
//! - [`tagged`]: the spectral part of the sector criterion at a tagged
//!   vertex (boundary, corner, crease, dart), proved on the reflection's even
//!   and odd blocks by enclosures and, where S is rational, exactly over Q
//!   (counting Schur–Cohn, ranks);
//! - [`s31`]: the refinement mask of the four-directional S_3^1 spline
//!   (non-box subdivision's regular part), derived from its two generators'
//!   definition, which `charmap` compares the rules with.

pub mod charmap;
pub mod complex;
pub mod difference;
pub mod discs;
pub mod exact_spectrum;
pub mod export;
pub mod matrix;
pub mod midrad;
pub mod power;
pub mod s31;
pub mod spectrum;
pub mod step_rotation;
pub mod tagged;
pub mod tagged_charmap;
pub mod window_orbits;

pub use charmap::{certify_charmap, CharMapCertificate};
pub use spectrum::{certify_analysis, certify_spectrum, SpectrumCertificate, Verdict};
