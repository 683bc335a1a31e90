//! Neighbourhoods of an extraordinary point: configurations, generous patches
//! with lattice charts, stable vertex labels, and the automatic discovery of
//! the minimal invariant and analysis neighbourhoods.

pub mod builder;
pub mod configuration;
pub mod discovery;
pub mod labels;
pub mod valence_limit;

pub use builder::build_patch;
pub use configuration::{Configuration, Tagging};
pub use discovery::{discover, discover_shared, discover_with_rings, Discovered, NeighbourhoodKind};
pub use labels::{VertexKind, VertexLabel};
