//! The engine core shared by the scheme families that live on a fixed grid
//! with binary dilation: the regular lattice Z² (`crate::lattice`) and the
//! line Z (`crate::curves`). What they have in common is written once here,
//! generic over the point type:
//!
//! - `closure`: the smallest invariant window around a seed, the invariance
//!   test, the set of control points that influence the limit over a region,
//!   and the assembly of the local matrix's rows on an invariant window;
//! - `exact`: the exact confirmation of floating-point eigenvalues against the
//!   exact rational matrix (characteristic polynomial, rational roots,
//!   algebraic and geometric multiplicities).
//!
//! The mesh pipeline (`crate::neighbourhood::discovery`) calls the same
//! closure on a different point type (vertex ids of an analysis patch); see
//! `closure`'s module doc.

pub mod closure;
pub mod exact;
