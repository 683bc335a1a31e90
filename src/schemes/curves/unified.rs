//! The unified curve scheme of Lin–Luo section 3 with a uniform parameter α,
//! exactly as printed there:
//!
//! P_{2i}   = α/8 P_{i-1} + (4 − α)/4 P_i + α/8 P_{i+1}
//! P_{2i+1} = (α − 1)/16 (P_{i-1} + P_{i+2}) + (9 − α)/16 (P_i + P_{i+1})
//!
//! Convention, checked exactly in tests/curves.rs: with these printed rules
//! α = 1 is the cubic B-spline and α = 0 the four-point scheme (the mask is
//! α·B-spline + (1 − α)·four-point). Section 5 of the same paper uses the
//! opposite convention for its surface scheme (α = 0 approximating, α = 1
//! interpolatory); the section-3 α here corresponds to 1 − α there.

use crate::curves::{CurveDomain, CurveMask, CurveScheme};
use crate::numeric::{Inexact, Weight};
use crate::schemes::entry::CurveEntry;
use crate::sdc::Rules;
use crate::sdc::{ParamSpec, Params};

pub struct UnifiedCurve {
    params: Params,
}

pub fn entry() -> CurveEntry {
    CurveEntry {
        name: "unified-curve",
        description:
            "Lin–Luo unified curve scheme, section 3 rules as printed (alpha=1: cubic B-spline, alpha=0: four-point)",
        params: || {
            vec![ParamSpec {
                name: "alpha",
                default: "1/2",
                min: 0.0,
                max: 2.0,
                description: "blend parameter of the section-3 rules (the paper analyses [0, 2])",
            }]
        },
        build: |params| Box::new(UnifiedCurve { params }),
    }
}

impl<W: Weight> Rules<CurveDomain, W> for UnifiedCurve {
    fn rule(&self, _: &(), _: ()) -> Result<CurveMask<W>, Inexact> {
        let a: W = W::param(self.params.get("alpha").expect("alpha has a default"))?;
        let side = a.clone() / W::int(8);
        let centre = (W::int(4) - a.clone()) / W::int(4);
        let far = (a.clone() - W::one()) / W::int(16);
        let near = (W::int(9) - a) / W::int(16);
        Ok(CurveMask {
            even: vec![(-1, side.clone()), (0, centre), (1, side)],
            odd: vec![(-1, far.clone()), (0, near.clone()), (1, near), (2, far)],
        })
    }
}

impl CurveScheme for UnifiedCurve {
    fn name(&self) -> &'static str {
        "unified-curve"
    }
    fn description(&self) -> &'static str {
        entry().description
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
