//! `identity`: an algebraic identity between two expressions, exactly where
//! both sides are rational, at every listed valence when it is a statement
//! in n.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::{define, env_for, finite, real_variables, show};
use crate::claims::subject::{Subject, Valences};
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::numeric::expr::{Env, Expr};

/// An algebraic identity between two expressions, exact where possible.
/// `vars` are expressions in each other; with `valences` (a statement in
/// n) the identity must hold at every listed valence, with `n` (alias
/// `k`) defined and `vars` expressions in n as well.
#[derive(Clone, Debug, Deserialize)]
pub struct Identity {
    pub lhs: String,
    pub rhs: String,
    #[serde(default)]
    pub vars: BTreeMap<String, String>,
    #[serde(default)]
    pub valences: Option<Valences>,
}

impl CheckKind for Identity {
    const KEYS: &'static [&'static str] = &["lhs", "rhs", "vars", "valences"];
    const TAKES_SUBJECT: bool = false;

    fn validate(&self) -> Result<(), Error> {
        if matches!(&self.valences, Some(Valences::List(l)) if l.is_empty()) {
            return vacuous("valences");
        }
        Ok(())
    }

    fn evaluate(&self, _cache: &mut Cache) -> Result<Finding, Error> {
        let Identity { lhs, rhs, vars, valences } = self;
        let (l, r) = (Expr::parse(lhs)?, Expr::parse(rhs)?);
        let Some(valences) = valences else {
            let env = define(Env::new(), vars.iter().collect())?;
            let (ok, computed, exact) = identity_at(&l, &r, lhs, rhs, &env)?;
            return Ok(Finding::new(
                ok,
                format!("{lhs} = {rhs}"),
                computed,
                if exact { "exact rational arithmetic" } else { "floating point (relative 1e-12)" }.into(),
            ));
        };
        // a statement in n: the identity at every listed valence, with
        // n (alias k) defined and the vars expressions in n
        let subject = Subject::valences_only(valences, vars);
        let mut modes = (0, 0);
        let mut p = over_valences(&subject, |subject, n| {
            let (ok, computed, exact) = identity_at(&l, &r, lhs, rhs, &env_for(subject, n)?)?;
            if exact {
                modes.0 += 1;
            } else {
                modes.1 += 1;
            }
            Ok((ok, format!("{lhs} = {rhs}"), computed))
        })?;
        p.detail = format!(
            "{}; {} valences in exact rational arithmetic, {} in floating point (relative 1e-12)",
            p.detail, modes.0, modes.1
        );
        Ok(p)
    }
}

/// `lhs = rhs` in `env`: exactly where both sides are rational, else in
/// floating point (relative 1e-12); the two values as shown, and whether the
/// comparison was exact.
fn identity_at(l: &Expr, r: &Expr, lhs: &str, rhs: &str, env: &Env) -> Result<(bool, String, bool), Error> {
    real_variables(l, env)?;
    real_variables(r, env)?;
    if let (Some(a), Some(b)) = (l.exact(env), r.exact(env)) {
        return Ok((a == b, format!("{a} vs {b}"), true));
    }
    let (a, b) = (finite(l.eval(env)?, lhs)?, finite(r.eval(env)?, rhs)?);
    let ok = (a - b).norm() <= 1e-12 * a.norm().max(b.norm()).max(1.0);
    Ok((ok, format!("{} vs {}", show(a), show(b)), false))
}
