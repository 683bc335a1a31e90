//! `size`: the size of the analysed neighbourhood equals the stated value.

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::{env_for, eval_real};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;

/// The neighbourhood size equals the expression.
#[derive(Clone, Debug, Deserialize)]
pub struct Size {
    #[serde(flatten)]
    pub subject: Subject,
    pub value: String,
}

impl CheckKind for Size {
    const KEYS: &'static [&'static str] = &["value"];

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let Size { subject, value } = self;
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            let stated = eval_real(value, &env_for(subject, n)?)?;
            let size = spec.matrix_size as f64;
            Ok((
                (stated - size).abs() < 0.5,
                format!("{stated}"),
                format!("{} (minimal {}, analysis {})", spec.matrix_size, spec.minimal_size, spec.analysis_size),
            ))
        })
    }
}
