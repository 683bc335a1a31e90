//! The curve schemes of Lin–Luo section 3 (the cubic B-spline, the
//! four-point scheme and the unified α-scheme that blends them), one file
//! each, plus relation (3) of the paper. The Z-domain machinery they run on
//! (masks, refinement, local matrices) is `crate::curves`.

pub mod cubic_bspline;
pub mod four_point;
pub mod relation;
pub mod unified;

use crate::curves::CurveScheme;
use crate::error::Error;
use crate::schemes::registry::{self, Built, Family};

/// The built-in curve schemes' names (listed with every other family in
/// `schemes::registry`).
pub fn known_names() -> Vec<&'static str> {
    registry::names_of(Family::Curve)
}

/// Build a curve scheme from a built-in name or a curve scheme file
/// (`domain = "curve"`) with `name=value` parameter overrides.
pub fn build(name_or_path: &str, overrides: &[(String, String)]) -> Result<Box<dyn CurveScheme>, Error> {
    let unknown = || {
        Error::Input(format!(
            "unknown curve scheme '{name_or_path}'; known curve schemes: {}",
            known_names().join(", ")
        ))
    };
    if !registry::is_file_argument(name_or_path) && registry::find(name_or_path).is_none() {
        return Err(unknown());
    }
    match registry::resolve(name_or_path, overrides)? {
        Built::Curve(c) => Ok(c),
        other => Err(Error::Input(format!(
            "'{name_or_path}' is a {} scheme, not a curve scheme; known curve schemes: {}",
            other.family().name(),
            known_names().join(", ")
        ))),
    }
}
