//! `nonnegative-spectrum`: whether every real eigenvalue is non-negative.

use num_complex::Complex64;
use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::show_list;
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;

/// Every real eigenvalue is non-negative (`expect = true`, the default) or not.
#[derive(Clone, Debug, Deserialize)]
pub struct NonnegativeSpectrum {
    #[serde(flatten)]
    pub subject: Subject,
    #[serde(default = "yes")]
    pub expect: bool,
}

fn yes() -> bool {
    true
}

impl CheckKind for NonnegativeSpectrum {
    const KEYS: &'static [&'static str] = &["expect"];

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let NonnegativeSpectrum { subject, expect } = self;
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            let negative: Vec<Complex64> = spec
                .eigenvalues
                .iter()
                .filter(|e| e.is_real() && e.re < -1e-12)
                .map(|e| Complex64::new(e.re, 0.0))
                .collect();
            let got = negative.is_empty();
            Ok((
                got == *expect,
                if *expect { "no negative eigenvalue".into() } else { "a negative eigenvalue".into() },
                if got { "no negative eigenvalue".into() } else { format!("negative: {}", show_list(&negative)) },
            ))
        })
    }
}
