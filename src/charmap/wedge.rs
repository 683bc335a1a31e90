//! Normalised characteristic wedges: for large valences the ring's sectors
//! become thin slivers; mapping one sector of angle 2π/n onto a quarter plane
//! by z ↦ |z| · exp(i·arg(z)·n/4) (angles stretched by n/4, radii kept) shows
//! its shape at the size of the regular case, as the papers draw it.

use super::ring::Tri;

/// The facets of `facets` whose centroid lies in the sector [0, 2π/n) of
/// angles, mapped to the quarter plane. The map has been rotated so that a
/// sector spoke lies on the positive x-axis (see `charmap::normalise`).
pub fn normalised_wedge(facets: &[Tri], n: usize) -> Vec<Tri> {
    let polys: Vec<Vec<[f64; 2]>> = facets.iter().map(|t| t.to_vec()).collect();
    normalised_wedge_polygons(&polys, n).into_iter().map(|p| [p[0], p[1], p[2]]).collect()
}

/// The same for polygons (faces of the net, for figures).
pub fn normalised_wedge_polygons(polys: &[Vec<[f64; 2]>], n: usize) -> Vec<Vec<[f64; 2]>> {
    let width = 2.0 * std::f64::consts::PI / n as f64;
    let stretch = n as f64 / 4.0;
    let angle = |p: &[f64; 2]| p[1].atan2(p[0]);
    polys
        .iter()
        .filter(|t| {
            let k = t.len() as f64;
            let c = [t.iter().map(|p| p[0]).sum::<f64>() / k, t.iter().map(|p| p[1]).sum::<f64>() / k];
            let a = angle(&c);
            // half a facet's angular size of slack below 0 is not needed: the
            // centroid rule assigns every facet to exactly one sector
            (0.0..width).contains(&a)
        })
        .map(|t| {
            t.iter()
                .map(|p| {
                    let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
                    // vertices of a facet straddling the spoke keep their side
                    let mut a = angle(p);
                    if a < -width / 2.0 {
                        a += 2.0 * std::f64::consts::PI;
                    }
                    let b = a * stretch;
                    [r * b.cos(), r * b.sin()]
                })
                .collect()
        })
        .collect()
}
