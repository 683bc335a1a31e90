//! `builtin`: a named computation for a statement that needs bespoke work
//! (the paper-specific checks of `claims::builtin`, one file per paper).

use serde::Deserialize;

use crate::claims::builtin;
use crate::claims::check_kind::CheckKind;
use crate::claims::common::spectra::Cache;
use crate::claims::verdict::Finding;
use crate::error::Error;

/// A named computation implemented in `claims::builtin` for statements
/// that need bespoke work; `data` carries the printed values it needs.
#[derive(Clone, Debug, Deserialize)]
pub struct Builtin {
    pub name: String,
    #[serde(default)]
    pub data: Option<toml::Value>,
}

impl CheckKind for Builtin {
    const KEYS: &'static [&'static str] = &["name", "data"];
    const TAKES_SUBJECT: bool = false;

    fn evaluate(&self, _cache: &mut Cache) -> Result<Finding, Error> {
        builtin::run(&self.name, self.data.as_ref())
    }
}
