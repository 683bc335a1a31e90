//! `limit-stencil`: the limit stencil's weights against the stated ones, by
//! vertex selector or whole label.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::{selector, Cache};
use crate::claims::common::values::{env_for, eval_real};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::spectrum::fmt_f;
use crate::spectrum::stencils::limit_stencil;

/// Limit stencil weights by vertex selector ("centre", "kind.ring", e.g.
/// "fcv.1", "edge.1"); every other vertex must have weight 0.
#[derive(Clone, Debug, Deserialize)]
pub struct LimitStencil {
    #[serde(flatten)]
    pub subject: Subject,
    pub weights: BTreeMap<String, String>,
}

impl CheckKind for LimitStencil {
    const KEYS: &'static [&'static str] = &["weights"];

    fn validate(&self) -> Result<(), Error> {
        if self.weights.is_empty() {
            return vacuous("weights");
        }
        Ok(())
    }

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let LimitStencil { subject, weights } = self;
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            let env = env_for(subject, n)?;
            let l = limit_stencil(&spec)?;
            let mut worst = (0.0f64, String::new());
            for (k, lab) in spec.labels.iter().enumerate() {
                // a whole label name (`edge[r1,s2,0]`) before its kind and ring
                let want = match weights.get(&lab.name).or_else(|| weights.get(&selector(lab.kind, lab.ring))) {
                    Some(e) => eval_real(e, &env)?,
                    None => 0.0,
                };
                let d = (l[k] - want).abs();
                if d > worst.0 {
                    worst = (d, format!("{}: computed {}, stated {}", lab.name, fmt_f(l[k]), fmt_f(want)));
                }
            }
            if let Some(key) = weights.keys().find(|k| k.contains('[') && !spec.labels.iter().any(|l| &l.name == *k)) {
                return Err(Error::Claim(format!("'{key}' names no vertex of the neighbourhood at n = {n}")));
            }
            let stated = weights.iter().map(|(k, v)| format!("{k} = {v}")).collect::<Vec<_>>().join(", ");
            let ok = worst.0 < 1e-9;
            Ok((ok, stated, if ok { "every weight as stated".into() } else { worst.1 }))
        })
    }
}
