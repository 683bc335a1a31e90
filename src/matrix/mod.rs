//! The local subdivision matrix S, assembled from the scheme's own rules, and
//! its exports (Matrix Market, JSON).

pub mod export;
pub mod local;

pub use local::{assemble, assemble_rows, FullMatrix, LocalMatrix};
