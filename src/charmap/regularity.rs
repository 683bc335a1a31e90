//! Regularity of the characteristic ring: the Jacobian of the piecewise
//! linear map over the refined net is the signed area of each facet, so the
//! map is regular (at this level) when every facet has the same orientation.

use serde::Serialize;

use super::ring::{signed_area, Tri};

#[derive(Clone, Debug, Serialize)]
pub struct Regularity {
    /// every facet has strictly positive orientation (after normalising the
    /// map's orientation to counter-clockwise)
    pub regular: bool,
    /// smallest signed facet area over the largest: the margin (negative when
    /// some facet is folded over)
    pub min_jacobian_ratio: f64,
    /// centroid of the facet with the smallest signed area
    pub min_jacobian_at: [f64; 2],
    /// facets with non-positive signed area
    pub folded_facets: usize,
    pub facets: usize,
}

/// Regularity of a set of facets whose intended orientation is counter-clockwise.
pub fn regularity(facets: &[Tri]) -> Regularity {
    let mut min = f64::INFINITY;
    let mut max = f64::NEG_INFINITY;
    let mut at = [f64::NAN; 2];
    let mut folded = 0;
    for t in facets {
        let a = signed_area(t);
        if a <= 0.0 {
            folded += 1;
        }
        if a < min {
            min = a;
            at = [(t[0][0] + t[1][0] + t[2][0]) / 3.0, (t[0][1] + t[1][1] + t[2][1]) / 3.0];
        }
        max = max.max(a);
    }
    let ratio = if facets.is_empty() || max <= 0.0 { f64::NAN } else { min / max };
    Regularity {
        regular: !facets.is_empty() && folded == 0,
        min_jacobian_ratio: ratio,
        min_jacobian_at: at,
        folded_facets: folded,
        facets: facets.len(),
    }
}

/// The orientation of a set of facets: the sign of its total signed area.
pub fn total_signed_area(facets: &[Tri]) -> f64 {
    facets.iter().map(signed_area).sum()
}
