//! The engine core shared by the scheme families, written once here, generic
//! over the point type:
//!
//! - `local`: the one local-matrix type (sparse rows over labelled points) of
//!   every family: mesh neighbourhoods (`crate::matrix`), the regular lattice
//!   Z² (`crate::lattice`), the line Z (`crate::curves`) and strip windows;
//! - `closure`: for grids with binary dilation (Z², Z, strip windows), the
//!   smallest invariant window around a seed, the invariance test, the set of
//!   control points that influence the limit over a region, and the assembly
//!   of the local matrix on an invariant window;
//! - `exact`: the exact confirmation of floating-point eigenvalues against the
//!   exact rational matrix (characteristic polynomial, rational roots,
//!   algebraic and geometric multiplicities).
//!
//! The mesh pipeline (`crate::neighbourhood::discovery`) calls the same
//! closure on a different point type (vertex ids of an analysis patch); see
//! `closure`'s module doc.

pub mod closure;
pub mod exact;
pub mod local;
// results shared across callers (one discovery per scheme and configuration)
pub mod memo;

pub use local::LocalMatrix;
