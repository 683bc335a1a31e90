//! What every check plug-in may use: the stated values and their
//! environment (`values`), the file's shared analyses (`spectra`) and the
//! verdict over a claim's configurations (`configurations`). These files
//! import no plug-in, so the plug-ins import them without a cycle.

pub mod configurations;
pub mod spectra;
pub mod values;
