//! The four-point interpolatory scheme of Dyn, Levin and Gregory with tension
//! w = 1/16 (the value that reproduces cubics):
//! P_{2i} = P_i, P_{2i+1} = (1/2 + w)(P_i + P_{i+1}) − w (P_{i-1} + P_{i+2}).

use crate::curves::{CurveDomain, CurveMask, CurveScheme};
use crate::numeric::{Inexact, Weight};
use crate::schemes::entry::CurveEntry;
use crate::sdc::Params;
use crate::sdc::Rules;

pub struct FourPoint {
    params: Params,
}

pub fn entry() -> CurveEntry {
    CurveEntry {
        name: "four-point",
        description: "Dyn–Levin–Gregory four-point interpolatory curve subdivision, w = 1/16",
        params: Vec::new,
        build: |params| Box::new(FourPoint { params }),
    }
}

impl<W: Weight> Rules<CurveDomain, W> for FourPoint {
    fn rule(&self, _: &(), _: ()) -> Result<CurveMask<W>, Inexact> {
        let w = W::ratio(1, 16);
        let near = W::ratio(1, 2) + w.clone();
        Ok(CurveMask { even: vec![(0, W::one())], odd: vec![(-1, -w.clone()), (0, near.clone()), (1, near), (2, -w)] })
    }
}

impl CurveScheme for FourPoint {
    fn name(&self) -> &'static str {
        "four-point"
    }
    fn description(&self) -> &'static str {
        entry().description
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
