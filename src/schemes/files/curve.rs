//! Curve scheme files: the two rules of a binary scheme on Z, new
//! P_{2i} = Σ_o w(o) P_{i+o} (`[even]`) and new P_{2i+1} = Σ_o w(o) P_{i+o}
//! (`[odd]`), as `crate::curves` analyses them.
//!
//! ```toml
//! domain = "curve"
//! name = "my-curve-scheme"
//! [params.alpha]
//! default = "1/2"
//! min = 0
//! max = 2
//! [even]             # P_{2i}
//! "-1" = "alpha/8"   # weight of P_{i-1}
//! "0" = "(4 - alpha)/4"
//! "1" = "alpha/8"
//! [odd]              # P_{2i+1}
//! "0" = "1/2"
//! "1" = "1/2"
//! ```
//!
//! Weights may be irrational (then the analysis is in floating point only);
//! a weight that is exactly zero at the chosen parameters is no dependency.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

use crate::curves::{CurveDomain, CurveMask, CurveScheme};
use crate::error::Error;
use crate::numeric::{Inexact, Rational};
use crate::schemes::files::shared_format::MAX_FILE_BYTES;
use crate::schemes::files::shared_format::{
    evaluate, intern, line_of, not_affine, offset_key, rule_terms, toml_error, Head, ParamDoc, Section, Term,
};
use crate::sdc::Params;
use crate::sdc::Rules;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CurveDoc {
    #[allow(dead_code)] // read by the router (`files::family_of_text`)
    domain: String,
    name: Spanned<String>,
    description: Option<Spanned<String>>,
    affine: Option<bool>,
    #[serde(default)]
    params: BTreeMap<String, Spanned<ParamDoc>>,
    even: Option<Section>,
    odd: Option<Section>,
}

#[derive(Clone, Debug)]
struct RuleDef {
    section: &'static str,
    line: usize,
    terms: Vec<Term<i64>>,
    scale: Option<Term<()>>,
}

/// A parsed curve scheme file, before parameter values are fixed.
#[derive(Clone, Debug)]
pub struct CurveFileDef {
    pub head: Head,
    even: RuleDef,
    odd: RuleDef,
}

/// A curve scheme file with its parameter values fixed: both rules evaluated
/// once, in f64 and (when every weight is rational) exactly.
pub struct CurveFileScheme {
    name: &'static str,
    description: &'static str,
    params: Params,
    float: CurveMask<f64>,
    exact: Option<CurveMask<Rational>>,
}

impl CurveFileDef {
    /// Parse a curve scheme file's text; `file` names it in error messages.
    pub fn parse(text: &str, file: &str) -> Result<CurveFileDef, Error> {
        if text.len() > MAX_FILE_BYTES {
            return Err(Error::File(format!("{file}: larger than {MAX_FILE_BYTES} bytes; scheme files are short")));
        }
        let doc: CurveDoc = toml::from_str(text).map_err(|e| toml_error(e, text, file))?;
        let head = Head::parse(text, file, &doc.name, &doc.description, doc.affine, &doc.params)?;
        let rule = |section: &'static str, table: &Option<Section>| -> Result<RuleDef, Error> {
            let table = table.as_ref().ok_or_else(|| {
                Error::File(format!("{file}: missing section [{section}] (a curve scheme has an even and an odd rule)"))
            })?;
            let (terms, scale) = rule_terms(&head, text, section, table, |k| offset_key(k, 1).map(|v| v[0]))?;
            Ok(RuleDef { section, line: line_of(text, table.span().start), terms, scale })
        };
        let def = CurveFileDef { even: rule("even", &doc.even)?, odd: rule("odd", &doc.odd)?, head };
        // evaluate at the defaults now, so that a file that cannot work fails at load
        def.build(&[])?;
        Ok(def)
    }

    /// Each rule's terms and common factor, offsets dropped (`weight_sites`).
    pub(crate) fn terms(&self) -> Vec<(Vec<Term<()>>, Option<Term<()>>)> {
        [&self.even, &self.odd]
            .iter()
            .map(|r| (r.terms.iter().map(Term::unplaced).collect(), r.scale.clone()))
            .collect()
    }

    /// The scheme with `name=value` parameter overrides: every weight finite
    /// and real, each rule summing to 1 unless `affine = false`.
    pub fn build(&self, overrides: &[(String, String)]) -> Result<CurveFileScheme, Error> {
        let (env, params) = self.head.values(overrides)?;
        let mut float = CurveMask { even: Vec::new(), odd: Vec::new() };
        let mut exact = Some(CurveMask { even: Vec::new(), odd: Vec::new() });
        for rule in [&self.even, &self.odd] {
            let mut sum = 0.0;
            let mut exact_sum = Some(Rational::from_integer(0.into()));
            for t in &rule.terms {
                let v = evaluate(&self.head, t, rule.scale.as_ref(), &env)?;
                sum += v.float;
                let (f, e) = if rule.section == "even" {
                    (&mut float.even, exact.as_mut().map(|m| &mut m.even))
                } else {
                    (&mut float.odd, exact.as_mut().map(|m| &mut m.odd))
                };
                f.push((t.offset, v.float));
                match (v.exact, e) {
                    (Some(q), Some(e)) => {
                        exact_sum = exact_sum.map(|s| s + q.clone());
                        e.push((t.offset, q));
                    }
                    // one irrational weight: no exact mask at all
                    _ => {
                        exact = None;
                        exact_sum = None;
                    }
                }
            }
            let is_one = match &exact_sum {
                Some(s) => *s == Rational::from_integer(1.into()),
                None => (sum - 1.0).abs() <= 1e-12,
            };
            if self.head.affine && !is_one {
                let shown = exact_sum.map(|s| s.to_string()).unwrap_or_else(|| sum.to_string());
                return Err(not_affine(&self.head, rule.line, rule.section, "rule", shown));
            }
        }
        Ok(CurveFileScheme {
            name: intern(&self.head.name),
            description: intern(&self.head.description),
            params,
            float,
            exact,
        })
    }
}

impl Rules<CurveDomain, f64> for CurveFileScheme {
    fn rule(&self, _: &(), _: ()) -> Result<CurveMask<f64>, Inexact> {
        Ok(self.float.clone())
    }
}

impl Rules<CurveDomain, Rational> for CurveFileScheme {
    fn rule(&self, _: &(), _: ()) -> Result<CurveMask<Rational>, Inexact> {
        self.exact.clone().ok_or(Inexact)
    }
}

impl CurveScheme for CurveFileScheme {
    fn name(&self) -> &'static str {
        self.name
    }
    fn description(&self) -> &'static str {
        self.description
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
