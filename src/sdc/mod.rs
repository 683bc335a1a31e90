//! The scheme description layer: what a mask may know of a refinement host.
pub mod slots;
