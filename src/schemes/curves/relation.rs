//! Relation (3) of Lin–Luo: one four-point step obtained from one cubic
//! B-spline step. With P^1_i the point the B-spline inserts between P_i and
//! P_{i+1}, P^2_i the B-spline's new position of P_i and Δ(P_i) = P^2_i − P_i,
//!
//! P^3_i = P^1_i − (Δ(P_i) + Δ(P_{i+1})) / 2                          (3)
//!
//! is the point the four-point scheme inserts. This module computes the right
//! side from the B-spline's own rules (no weight is restated), so comparing it
//! with a four-point step tests the paper's claim.

use crate::curves::{refine_closed, CurveWeight};
use crate::numeric::Inexact;
use crate::schemes::curves::cubic_bspline;

/// A refined closed polygon built by relation (3): old points kept at even
/// positions, P^3_i at odd positions. Compare with a four-point step.
pub fn four_point_by_relation3<W: CurveWeight>(points: &[W]) -> Result<Vec<W>, Inexact> {
    let bspline = cubic_bspline::entry();
    let mask = W::mask((bspline.build)(Default::default()).as_ref())?;
    let step = refine_closed(&mask, points);
    let n = points.len();
    let delta: Vec<W> = (0..n).map(|i| step[2 * i].clone() - points[i].clone()).collect();
    let half = W::ratio(1, 2);
    let mut out = Vec::with_capacity(2 * n);
    for i in 0..n {
        let inserted = step[2 * i + 1].clone();
        out.push(points[i].clone());
        out.push(inserted - half.clone() * (delta[i].clone() + delta[(i + 1) % n].clone()));
    }
    Ok(out)
}
