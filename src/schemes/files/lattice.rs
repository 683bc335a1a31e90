//! Regular-lattice scheme files: the four parity masks of a binary scheme on
//! Z², p_{2i+α, 2j+β} = Σ_{(r,s)} w_{α,β}(r, s) · p_{i+r, j+s}, with explicit
//! offsets, as `crate::lattice` analyses them.
//!
//! ```toml
//! domain = "lattice"
//! name = "my-lattice-scheme"
//! [mask-00]            # (α, β) = (0, 0): p_{2i,2j}
//! scale = "1/144"      # optional common factor of the section's weights
//! "0,0" = 80           # weight of p_{i,j}
//! "-1,0" = 32          # weight of p_{i-1,j}
//! # ...
//! [mask-10]            # p_{2i+1,2j}
//! [mask-01]            # p_{2i,2j+1}
//! [mask-11]            # p_{2i+1,2j+1}
//! ```
//!
//! The lattice analysis is exact (windows from exact dependencies, the
//! characteristic polynomial in rationals), so every weight must have an exact
//! rational value at the parameter values used; a file whose weight does not
//! is refused with the field named.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

use crate::error::Error;
use crate::lattice::{LatticeDomain, LatticeScheme, Parity, Point};
use crate::numeric::{Rational, Weight};
use crate::schemes::files::shared_format::MAX_FILE_BYTES;
use crate::schemes::files::shared_format::{
    evaluate, field_error, intern, line_of, not_affine, offset_key, rule_terms, toml_error, Head, ParamDoc, Section,
    Term,
};
use crate::sdc::Params;
use crate::sdc::Rules;

/// The section names of the masks, indexed [α][β].
const SECTIONS: [[&str; 2]; 2] = [["mask-00", "mask-01"], ["mask-10", "mask-11"]];

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LatticeDoc {
    #[allow(dead_code)] // read by the router (`files::family_of_text`)
    domain: String,
    name: Spanned<String>,
    description: Option<Spanned<String>>,
    affine: Option<bool>,
    #[serde(default)]
    params: BTreeMap<String, Spanned<ParamDoc>>,
    #[serde(rename = "mask-00")]
    m00: Option<Section>,
    #[serde(rename = "mask-01")]
    m01: Option<Section>,
    #[serde(rename = "mask-10")]
    m10: Option<Section>,
    #[serde(rename = "mask-11")]
    m11: Option<Section>,
}

/// One mask as written: its terms, its optional common factor and the line of
/// its section header.
#[derive(Clone, Debug)]
struct MaskDef {
    section: &'static str,
    line: usize,
    terms: Vec<Term<Point>>,
    scale: Option<Term<()>>,
}

/// A parsed lattice scheme file, before parameter values are fixed.
#[derive(Clone, Debug)]
pub struct LatticeFileDef {
    pub head: Head,
    /// indexed [α][β]
    masks: [[MaskDef; 2]; 2],
}

/// A lattice scheme file with its parameter values fixed: the four masks
/// evaluated once, in f64 and exactly.
pub struct LatticeFileScheme {
    name: &'static str,
    description: &'static str,
    params: Params,
    float: [[Vec<(Point, f64)>; 2]; 2],
    exact: [[Vec<(Point, Rational)>; 2]; 2],
}

impl LatticeFileDef {
    /// Parse a lattice scheme file's text; `file` names it in error messages.
    pub fn parse(text: &str, file: &str) -> Result<LatticeFileDef, Error> {
        if text.len() > MAX_FILE_BYTES {
            return Err(Error::File(format!("{file}: larger than {MAX_FILE_BYTES} bytes; scheme files are short")));
        }
        let doc: LatticeDoc = toml::from_str(text).map_err(|e| toml_error(e, text, file))?;
        let head = Head::parse(text, file, &doc.name, &doc.description, doc.affine, &doc.params)?;
        let tables = [[&doc.m00, &doc.m01], [&doc.m10, &doc.m11]];
        let mask = |a: usize, b: usize| -> Result<MaskDef, Error> {
            let section = SECTIONS[a][b];
            let table = tables[a][b].as_ref().ok_or_else(|| {
                Error::File(format!("{file}: missing section [{section}] (a lattice scheme has four masks)"))
            })?;
            let (terms, scale) = rule_terms(&head, text, section, table, |k| offset_key(k, 2).map(|v| (v[0], v[1])))?;
            Ok(MaskDef { section, line: line_of(text, table.span().start), terms, scale })
        };
        let masks = [[mask(0, 0)?, mask(0, 1)?], [mask(1, 0)?, mask(1, 1)?]];
        let def = LatticeFileDef { head, masks };
        // evaluate at the defaults now, so that a file that cannot work fails at load
        def.build(&[])?;
        Ok(def)
    }

    /// Each mask's terms and common factor, offsets dropped (`weight_sites`).
    pub(crate) fn terms(&self) -> Vec<(Vec<Term<()>>, Option<Term<()>>)> {
        self.masks.iter().flatten().map(|m| (m.terms.iter().map(Term::unplaced).collect(), m.scale.clone())).collect()
    }

    /// The scheme with `name=value` parameter overrides: every weight a finite
    /// rational, each mask summing to 1 unless `affine = false`.
    pub fn build(&self, overrides: &[(String, String)]) -> Result<LatticeFileScheme, Error> {
        let (env, params) = self.head.values(overrides)?;
        let mut float: [[Vec<(Point, f64)>; 2]; 2] = Default::default();
        let mut exact: [[Vec<(Point, Rational)>; 2]; 2] = Default::default();
        for (a, row) in self.masks.iter().enumerate() {
            for (b, m) in row.iter().enumerate() {
                let mut sum = <Rational as Weight>::zero();
                for t in &m.terms {
                    let v = evaluate(&self.head, t, m.scale.as_ref(), &env)?;
                    let q = v.exact.ok_or_else(|| {
                        field_error(
                            &self.head.file,
                            t.line,
                            &t.field,
                            "the weight has no exact rational value here; lattice schemes are analysed exactly",
                        )
                    })?;
                    sum += q.clone();
                    float[a][b].push((t.offset, v.float));
                    exact[a][b].push((t.offset, q));
                }
                if self.head.affine && sum != <Rational as Weight>::one() {
                    return Err(not_affine(&self.head, m.line, m.section, "mask", sum));
                }
            }
        }
        Ok(LatticeFileScheme {
            name: intern(&self.head.name),
            description: intern(&self.head.description),
            params,
            float,
            exact,
        })
    }
}

impl Rules<LatticeDomain, f64> for LatticeFileScheme {
    fn rule(&self, _: &(), (alpha, beta): Parity) -> Vec<(Point, f64)> {
        self.float[alpha as usize & 1][beta as usize & 1].clone()
    }
}

impl Rules<LatticeDomain, Rational> for LatticeFileScheme {
    fn rule(&self, _: &(), (alpha, beta): Parity) -> Vec<(Point, Rational)> {
        self.exact[alpha as usize & 1][beta as usize & 1].clone()
    }
}

impl LatticeScheme for LatticeFileScheme {
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
