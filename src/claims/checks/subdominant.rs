//! `subdominant`: the subdominant eigenvalue λ1 equals the stated value.

use num_complex::Complex64;
use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::{close, env_for, eval, show};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;

/// The subdominant eigenvalue λ1 equals the expression.
#[derive(Clone, Debug, Deserialize)]
pub struct Subdominant {
    #[serde(flatten)]
    pub subject: Subject,
    pub value: String,
}

impl CheckKind for Subdominant {
    const KEYS: &'static [&'static str] = &["value"];

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let Subdominant { subject, value } = self;
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            let stated = eval(value, &env_for(subject, n)?)?;
            let l1 = spec
                .eigenvalues
                .get(1)
                .map(|e| Complex64::new(e.re, e.im))
                .ok_or_else(|| Error::Undecided("no subdominant eigenvalue".into()))?;
            let double = spec.eigenvalues[1].algebraic_multiplicity;
            Ok((close(stated, l1), show(stated), format!("{} (multiplicity {double})", show(l1))))
        })
    }
}
