//! What every check plug-in may use: the stated values and their
//! environment (`values`), the file's shared analyses (`spectra`), the
//! verdict over a claim's configurations (`configurations`) and the
//! second-order analysis with its Jordan routes (`curvature`). These files
//! import no plug-in, so the plug-ins import them without a cycle.

pub mod configurations;
pub mod curvature;
pub mod spectra;
pub mod values;
