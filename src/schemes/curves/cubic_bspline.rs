//! Uniform cubic B-spline subdivision (Lane–Riesenfeld / Chaikin of degree 3):
//! P_{2i} = (P_{i-1} + 6 P_i + P_{i+1}) / 8, P_{2i+1} = (P_i + P_{i+1}) / 2.

use crate::curves::{CurveDomain, CurveMask, CurveScheme};
use crate::numeric::{Inexact, Weight};
use crate::schemes::entry::CurveEntry;
use crate::sdc::Params;
use crate::sdc::Rules;

pub struct CubicBSpline {
    params: Params,
}

pub fn entry() -> CurveEntry {
    CurveEntry {
        name: "cubic-bspline",
        description: "uniform cubic B-spline curve subdivision (approximating, C2)",
        params: Vec::new,
        build: |params| Box::new(CubicBSpline { params }),
    }
}

impl<W: Weight> Rules<CurveDomain, W> for CubicBSpline {
    fn rule(&self, _: &(), _: ()) -> Result<CurveMask<W>, Inexact> {
        Ok(CurveMask {
            even: vec![(-1, W::ratio(1, 8)), (0, W::ratio(3, 4)), (1, W::ratio(1, 8))],
            odd: vec![(0, W::ratio(1, 2)), (1, W::ratio(1, 2))],
        })
    }
}

impl CurveScheme for CubicBSpline {
    fn name(&self) -> &'static str {
        "cubic-bspline"
    }
    fn description(&self) -> &'static str {
        entry().description
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
