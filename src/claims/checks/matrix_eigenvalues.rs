//! `matrix-eigenvalues`: the eigenvalues of a matrix printed in the paper
//! against the eigenvalues the paper states for it (the paper's own
//! consistency).

use std::collections::BTreeMap;

use num_complex::Complex64;
use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::{env_for, eval, show_list, stated_values, unmatched};
use crate::claims::subject::{Subject, Valences};
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::spectrum::{eigen, eigenvalue_order};

/// The eigenvalues of a matrix printed in the paper (entries are
/// expressions in n and `vars`) against the eigenvalues the paper states
/// for it: checks the paper's own consistency.
#[derive(Clone, Debug, Deserialize)]
pub struct MatrixEigenvalues {
    pub valences: Valences,
    #[serde(default)]
    pub vars: BTreeMap<String, String>,
    pub rows: Vec<Vec<String>>,
    pub values: Vec<String>,
}

impl CheckKind for MatrixEigenvalues {
    const KEYS: &'static [&'static str] = &["valences", "vars", "rows", "values"];
    const TAKES_SUBJECT: bool = false;

    fn validate(&self) -> Result<(), Error> {
        if self.rows.is_empty() {
            return vacuous("rows");
        }
        if self.values.is_empty() {
            return vacuous("values");
        }
        Ok(())
    }

    fn evaluate(&self, _cache: &mut Cache) -> Result<Finding, Error> {
        let MatrixEigenvalues { valences, vars, rows, values } = self;
        let subject = Subject::valences_only(valences, vars);
        over_valences(&subject, |subject, n| {
            let env = env_for(subject, n)?;
            let cols = rows.first().map(|r| r.len()).unwrap_or(0);
            if rows.iter().any(|r| r.len() != cols) || rows.len() != cols {
                return Ok((
                    false,
                    format!("{} stated eigenvalues", values.len()),
                    format!(
                        "the printed matrix is not square ({} rows, column counts {:?})",
                        rows.len(),
                        rows.iter().map(|r| r.len()).collect::<Vec<_>>()
                    ),
                ));
            }
            let mut m = faer::Mat::<Complex64>::zeros(cols, cols);
            for (i, r) in rows.iter().enumerate() {
                for (j, e) in r.iter().enumerate() {
                    m[(i, j)] = eval(e, &env)?;
                }
            }
            let mut computed: Vec<Complex64> =
                eigen::block_eigen(&m)?.into_iter().flat_map(|e| std::iter::repeat_n(e.value, e.algebraic)).collect();
            computed.sort_by(|a, b| eigenvalue_order(*a, *b));
            let mut stated = stated_values(values, &env)?;
            stated.sort_by(|a, b| eigenvalue_order(*a, *b));
            let (missing, extra) = unmatched(&stated, &computed);
            let ok = missing.is_empty() && extra.is_empty();
            let why = if ok {
                String::new()
            } else {
                format!(" (stated but not found: {}; found but not stated: {})", show_list(&missing), show_list(&extra))
            };
            Ok((ok, show_list(&stated), format!("{}{why}", show_list(&computed))))
        })
    }
}
