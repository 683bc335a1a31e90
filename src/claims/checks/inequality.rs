//! `inequality`: `lhs op rhs` at every valence, with the computed λ1, |λ3|
//! and neighbourhood size available to the expressions.

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::{env_for, finite, real_variables};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::numeric::expr::Expr;
use crate::numeric::ParamValue;
use crate::spectrum::fmt_f;

/// An inequality `lhs op rhs` (op one of <, <=, >, >=) at every valence;
/// besides `n`, parameters and `vars`, the expressions may use the computed
/// `lambda1` (subdominant eigenvalue), `lambda3` (modulus of the next one)
/// and `size` (the neighbourhood size).
#[derive(Clone, Debug, Deserialize)]
pub struct Inequality {
    #[serde(flatten)]
    pub subject: Subject,
    pub lhs: String,
    pub op: String,
    pub rhs: String,
}

impl CheckKind for Inequality {
    const KEYS: &'static [&'static str] = &["lhs", "op", "rhs"];

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let Inequality { subject, lhs, op, rhs } = self;
        over_valences(subject, |subject, n| {
            let mut env = env_for(subject, n)?;
            let (l, r) = (Expr::parse(lhs)?, Expr::parse(rhs)?);
            let uses_spectrum = l
                .variables()
                .iter()
                .chain(r.variables().iter())
                .any(|v| ["lambda1", "lambda3", "size"].contains(&v.as_str()));
            if uses_spectrum && !subject.scheme.is_empty() {
                let spec = cache.spectrum(subject, n)?;
                let l1 = spec
                    .eigenvalues
                    .get(1)
                    .map(|e| e.re)
                    .ok_or_else(|| Error::Undecided("no subdominant eigenvalue".into()))?;
                let l3 = spec.eigenvalues.get(2).map(|e| e.modulus).unwrap_or(0.0);
                env.insert("lambda1".into(), ParamValue::from_f64(l1));
                env.insert("lambda3".into(), ParamValue::from_f64(l3));
                env.insert("size".into(), ParamValue::from_ratio(spec.matrix_size as i64, 1));
            }
            real_variables(&l, &env)?;
            real_variables(&r, &env)?;
            let (a, b) = (finite(l.eval(&env)?, lhs)?, finite(r.eval(&env)?, rhs)?);
            if a.im.abs() > 1e-12 || b.im.abs() > 1e-12 {
                return Err(Error::Claim(format!("'{lhs}' or '{rhs}' is not real at n = {n}")));
            }
            let (a, b) = (a.re, b.re);
            let ok = match op.as_str() {
                "<" => a < b,
                "<=" => a <= b,
                ">" => a > b,
                ">=" => a >= b,
                other => return Err(Error::Claim(format!("unknown comparison '{other}' (<, <=, >, >=)"))),
            };
            Ok((ok, format!("{lhs} {op} {rhs}"), format!("{} {op} {}: {ok}", fmt_f(a), fmt_f(b))))
        })
    }
}
