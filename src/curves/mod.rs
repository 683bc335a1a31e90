//! The Z domain: binary curve subdivision (the schemes themselves, Lin–Luo
//! section 3, are in `crate::schemes::curves`).
//!
//! A binary curve scheme is two rules over the old points: the new point
//! P_{2i} (the "even" rule, at an old vertex) and P_{2i+1} (the "odd" rule,
//! between P_i and P_{i+1}). Each scheme writes its two rules once, generic
//! over the weight scalar, as offsets relative to i; refinement of a polygon
//! (`refine_closed`), the local subdivision matrix (`local`) and relation (3)
//! of the paper (`schemes::curves::relation`) all evaluate those same masks.

pub mod local;
pub mod smoothness;

use crate::numeric::{Inexact, Rational, Weight};
use crate::sdc::{Domain, Params, RuleWeight, Rules};

/// The two rules of a binary curve scheme: new P_{2i} = Σ w·P_{i+o} over
/// `even`, new P_{2i+1} = Σ w·P_{i+o} over `odd`, as (o, w) pairs.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveMask<W> {
    pub even: Vec<(i64, W)>,
    pub odd: Vec<(i64, W)>,
}

impl<W: Weight> CurveMask<W> {
    /// Sum duplicate offsets, drop zero weights (a zero weight is no
    /// dependency: this is what makes α = 1 structurally the B-spline), sort.
    pub fn merged(self) -> Self {
        fn merge<W: Weight>(mut v: Vec<(i64, W)>) -> Vec<(i64, W)> {
            v.sort_by_key(|t| t.0);
            let mut out: Vec<(i64, W)> = Vec::with_capacity(v.len());
            for (o, w) in v {
                match out.last_mut() {
                    Some(last) if last.0 == o => last.1 = last.1.clone() + w,
                    _ => out.push((o, w)),
                }
            }
            out.retain(|t| !t.1.is_zero());
            out
        }
        CurveMask { even: merge(self.even), odd: merge(self.odd) }
    }

    /// The stencil of refined point k over old indices: (old index, weight).
    pub fn stencil(&self, k: i64) -> Vec<(i64, W)> {
        let base = k.div_euclid(2);
        let rule = if k.rem_euclid(2) == 0 { &self.even } else { &self.odd };
        rule.iter().map(|(o, w)| (base + o, w.clone())).collect()
    }

    /// Largest |offset| of either rule.
    pub fn reach(&self) -> i64 {
        self.even.iter().chain(&self.odd).map(|t| t.0.abs()).max().unwrap_or(0)
    }
}

/// The line Z with binary dilation: one rule gives both masks (even and
/// odd), or why the weights are not representable in `W` (the scheme's rules
/// are `sdc::Rules<CurveDomain, W>`, written once generic over `W`).
pub enum CurveDomain {}

impl Domain for CurveDomain {
    type Host = ();
    type Position = ();
    type Rule<W: Weight> = Result<CurveMask<W>, Inexact>;
    type Scheme<'a> = dyn CurveScheme + 'a;
}

crate::sdc::rule_weights!(CurveDomain: f64, Rational);

/// A curve scheme: its masks in f64 and exact rationals.
pub trait CurveScheme: Rules<CurveDomain, f64> + Rules<CurveDomain, Rational> + Send + Sync {
    fn name(&self) -> &'static str;
    fn description(&self) -> &'static str;
    fn params(&self) -> &Params;
}

/// Weight types every curve scheme has rules for ([`RuleWeight`] on the
/// curve domain); `mask` is the one entry point to the curve rules (results
/// come back merged).
pub trait CurveWeight: RuleWeight<CurveDomain> {
    fn mask(scheme: &dyn CurveScheme) -> Result<CurveMask<Self>, Inexact> {
        Ok(Self::rule_of(scheme, &(), ())?.merged())
    }
}

impl<W: RuleWeight<CurveDomain>> CurveWeight for W {}

/// One subdivision step of a closed polygon of scalars (apply it per
/// coordinate for points): the refined polygon has twice as many points,
/// new point k from `mask.stencil(k)` with indices taken cyclically.
pub fn refine_closed<W: Weight>(mask: &CurveMask<W>, values: &[W]) -> Vec<W> {
    let n = values.len() as i64;
    if n == 0 {
        return Vec::new();
    }
    (0..2 * n)
        .map(|k| {
            mask.stencil(k)
                .into_iter()
                .fold(W::zero(), |acc, (i, w)| acc + w * values[i.rem_euclid(n) as usize].clone())
        })
        .collect()
}
