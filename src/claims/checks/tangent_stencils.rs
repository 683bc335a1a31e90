//! `tangent-stencils`: the tangent stencils span the plane of the stated
//! cos/sin patterns.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::{selector, Cache};
use crate::claims::common::values::{env_for, eval_real};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::numeric::ParamValue;
use crate::spectrum::stencils::tangent_stencils;

/// The tangent stencils span the same plane as the stated cos/sin
/// patterns (expressions in the vertex's sector `s`).
#[derive(Clone, Debug, Deserialize)]
pub struct TangentStencils {
    #[serde(flatten)]
    pub subject: Subject,
    pub cos: BTreeMap<String, String>,
    pub sin: BTreeMap<String, String>,
}

impl CheckKind for TangentStencils {
    const KEYS: &'static [&'static str] = &["cos", "sin"];

    fn validate(&self) -> Result<(), Error> {
        if self.cos.is_empty() {
            return vacuous("cos");
        }
        if self.sin.is_empty() {
            return vacuous("sin");
        }
        Ok(())
    }

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let TangentStencils { subject, cos, sin } = self;
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            let t = tangent_stencils(&spec)?;
            let mut basis = vec![vec![0.0; spec.labels.len()]; 2];
            for (k, lab) in spec.labels.iter().enumerate() {
                let mut env = env_for(subject, n)?;
                env.insert("s".into(), ParamValue::from_ratio(lab.sector as i64, 1));
                for (b, map) in [cos, sin].iter().enumerate() {
                    if let Some(e) = map.get(&selector(lab.kind, lab.ring)) {
                        basis[b][k] = eval_real(e, &env)?;
                    }
                }
            }
            let ok = t.len() == 2 && t.iter().all(|v| in_span(&basis, v)) && basis.iter().all(|v| in_span(&t, v));
            Ok((
                ok,
                "span of the stated cos/sin stencils".into(),
                format!("{} tangent stencils, {}", t.len(), if ok { "same span" } else { "different span" }),
            ))
        })
    }
}

fn in_span(basis: &[Vec<f64>], v: &[f64]) -> bool {
    v.iter().any(|x| *x != 0.0) && crate::spectrum::stencils::span_residual(basis, v) < 1e-8
}
