//! Rasterising the characteristic ring: coverage count per pixel.
//!
//! A pixel is covered by a triangle when its centre is inside. Centres exactly
//! on an edge follow the top-left rule, and edge functions are evaluated with
//! the edge's endpoints in a canonical order, so two facets sharing an edge
//! never both cover (or both miss) a centre on it: a pixel counted twice is an
//! overlap of the map, not an artefact of rounding.

use super::ring::{signed_area, Tri};
use crate::error::Error;

/// Largest resolution accepted (pixels per side): 2 · 8192² coverage counters
/// are 256 MiB.
pub const MAX_RESOLUTION: usize = 8192;

#[derive(Clone, Debug)]
pub struct Grid {
    pub resolution: usize,
    /// lower-left corner and pixel size of the square window
    pub origin: [f64; 2],
    pub pixel: f64,
}

impl Grid {
    /// A square window around the given triangles (with a one-pixel margin).
    pub fn around(tris: &[Tri], resolution: usize) -> Result<Grid, Error> {
        if resolution == 0 || resolution > MAX_RESOLUTION {
            return Err(Error::Input(format!(
                "resolution must be between 1 and {MAX_RESOLUTION} pixels, got {resolution}"
            )));
        }
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in tris.iter().flatten() {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let side = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        if !side.is_finite() || side <= 0.0 {
            return Err(Error::Numeric("the characteristic ring is degenerate (no extent to rasterise)".into()));
        }
        let pixel = side / (resolution as f64 - 2.0).max(1.0);
        let centre = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
        let half = pixel * resolution as f64 / 2.0;
        Ok(Grid { resolution, origin: [centre[0] - half, centre[1] - half], pixel })
    }
}

/// Add one to every pixel whose centre lies in a triangle (either orientation).
///
/// Row by row, the covered pixels form one run, found by scanning from the
/// left end of the bounding box to the first covered pixel and stopping at
/// the first uncovered one after it. The run is exactly the set of pixels
/// [`inside`] accepts: along a row, the centre's x grows with i (a rounded
/// product and sum are monotone in their argument), so each edge function,
/// evaluated as [`EdgeFunction`] does — the same operations as
/// [`edge_function`], the row's term computed once — is monotone in i, and
/// each edge's test is a threshold on it: a prefix or a suffix of the row,
/// and the three together an interval (the unit test compares with
/// [`inside`] pixel by pixel).
pub fn rasterise(grid: &Grid, tris: &[Tri], coverage: &mut [u16]) {
    let r = grid.resolution;
    for t in tris {
        let a = signed_area(t);
        if a == 0.0 || !a.is_finite() {
            continue; // covers no area
        }
        let t = if a > 0.0 { *t } else { [t[0], t[2], t[1]] };
        let to_px = |x: f64, o: f64| (x - o) / grid.pixel - 0.5;
        let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for p in &t {
            x0 = x0.min(to_px(p[0], grid.origin[0]));
            x1 = x1.max(to_px(p[0], grid.origin[0]));
            y0 = y0.min(to_px(p[1], grid.origin[1]));
            y1 = y1.max(to_px(p[1], grid.origin[1]));
        }
        let clamp = |v: f64| v.clamp(0.0, r as f64 - 1.0) as usize;
        let (i0, i1, j0, j1) = (clamp(x0.ceil()), clamp(x1.floor()), clamp(y0.ceil()), clamp(y1.floor()));
        if x1 < 0.0 || y1 < 0.0 || x0 > r as f64 - 1.0 || y0 > r as f64 - 1.0 {
            continue;
        }
        let edges = [0, 1, 2].map(|k| EdgeFunction::new(t[k], t[(k + 1) % 3]));
        for j in j0..=j1 {
            let py = grid.origin[1] + (j as f64 + 0.5) * grid.pixel;
            let rows = edges.map(|e| e.row_term(py));
            let covers = |i: usize| {
                let px = grid.origin[0] + (i as f64 + 0.5) * grid.pixel;
                (0..3).all(|k| edges[k].accepts(rows[k], px))
            };
            let Some(mut i) = (i0..=i1).find(|&i| covers(i)) else { continue };
            while i <= i1 && covers(i) {
                let c = &mut coverage[j * r + i];
                *c = c.saturating_add(1);
                i += 1;
            }
        }
    }
}

/// [`edge_function`] of one edge with the part that depends only on the
/// row computed once: the same floating-point operations in the same order,
/// so the same value bit for bit.
#[derive(Clone, Copy)]
struct EdgeFunction {
    /// the edge's first end point in the canonical order
    from: [f64; 2],
    /// the second end point minus the first
    delta: [f64; 2],
    /// whether the canonical order reverses the edge
    reversed: bool,
    top_left: bool,
}

impl EdgeFunction {
    fn new(a: [f64; 2], b: [f64; 2]) -> Self {
        let (from, to, reversed) = if (a[0], a[1]) <= (b[0], b[1]) { (a, b, false) } else { (b, a, true) };
        EdgeFunction { from, delta: [to[0] - from[0], to[1] - from[1]], reversed, top_left: top_left(a, b) }
    }

    fn row_term(&self, py: f64) -> f64 {
        self.delta[0] * (py - self.from[1])
    }

    /// The centre (px, row) on the inner side of the edge, or on the edge
    /// and the edge top-left.
    fn accepts(&self, row_term: f64, px: f64) -> bool {
        let f = row_term - self.delta[1] * (px - self.from[0]);
        let e = if self.reversed { -f } else { f };
        e > 0.0 || (e == 0.0 && self.top_left)
    }
}

/// Point in a counter-clockwise triangle, with the top-left rule on edges
/// (the definition [`rasterise`] follows, pixel by pixel).
#[cfg(test)]
fn inside(t: &Tri, p: [f64; 2]) -> bool {
    (0..3).all(|k| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        let e = edge_function(a, b, p);
        e > 0.0 || (e == 0.0 && top_left(a, b))
    })
}

/// Twice the signed area of (a, b, p), computed from the endpoints in a fixed
/// order so that the reversed edge gives exactly the negated value.
#[cfg(test)]
fn edge_function(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    let f = |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    if (a[0], a[1]) <= (b[0], b[1]) {
        f(a, b)
    } else {
        -f(b, a)
    }
}

/// Of an edge and its reverse exactly one is "top-left", so a centre on a
/// shared edge belongs to exactly one of the two facets.
fn top_left(a: [f64; 2], b: [f64; 2]) -> bool {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    dy < 0.0 || (dy == 0.0 && dx > 0.0)
}

/// Coverage statistics of the ring and of the region inside it.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Coverage {
    pub resolution: usize,
    /// pixels covered by the ring at least once
    pub ring_pixels: usize,
    /// pixels the ring covers more than once (the ring overlaps itself)
    pub overlap_pixels: usize,
    /// pixels covered both by the ring and by its scaled copies inside it
    pub copy_overlap_pixels: usize,
    /// largest coverage count of a pixel by the ring
    pub max_coverage: u16,
    /// side of a pixel in map units
    pub pixel_size: f64,
}

pub struct Rasters {
    pub grid: Grid,
    pub ring: Vec<u16>,
    pub inner: Vec<u16>,
}

pub fn rasterise_ring(ring: &[Tri], inner: &[Tri], resolution: usize) -> Result<(Coverage, Rasters), Error> {
    let all: Vec<Tri> = ring.iter().chain(inner).copied().collect();
    let grid = Grid::around(&all, resolution)?;
    let mut ring_cov = vec![0u16; resolution * resolution];
    let mut inner_cov = vec![0u16; resolution * resolution];
    rasterise(&grid, ring, &mut ring_cov);
    rasterise(&grid, inner, &mut inner_cov);
    let cov = Coverage {
        resolution,
        ring_pixels: ring_cov.iter().filter(|&&c| c >= 1).count(),
        overlap_pixels: ring_cov.iter().filter(|&&c| c > 1).count(),
        copy_overlap_pixels: ring_cov.iter().zip(&inner_cov).filter(|(a, b)| **a >= 1 && **b >= 1).count(),
        max_coverage: ring_cov.iter().copied().max().unwrap_or(0),
        pixel_size: grid.pixel,
    };
    Ok((cov, Rasters { grid, ring: ring_cov, inner: inner_cov }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pixel-by-pixel definition: every pixel of the window whose centre
    /// [`inside`] accepts for the triangle in counter-clockwise order.
    fn by_pixel(grid: &Grid, tris: &[Tri]) -> Vec<u16> {
        let r = grid.resolution;
        let mut cov = vec![0u16; r * r];
        for t in tris {
            let a = signed_area(t);
            if a == 0.0 || !a.is_finite() {
                continue;
            }
            let t = if a > 0.0 { *t } else { [t[0], t[2], t[1]] };
            for j in 0..r {
                for i in 0..r {
                    let p = [
                        grid.origin[0] + (i as f64 + 0.5) * grid.pixel,
                        grid.origin[1] + (j as f64 + 0.5) * grid.pixel,
                    ];
                    if inside(&t, p) {
                        cov[j * r + i] += 1;
                    }
                }
            }
        }
        cov
    }

    #[test]
    fn runs_per_row_cover_exactly_the_pixels_whose_centres_are_inside() {
        // pseudo-random fans of triangles around shared vertices (shared
        // edges, slivers, both orientations), some vertices on pixel centres;
        // consecutive rim points less than half a turn apart, so the fan
        // does not overlap itself
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for round in 0..60 {
            let centre = [next() - 0.5, next() - 0.5];
            let k = 3 + round % 7;
            let mut rim: Vec<[f64; 2]> = (0..k)
                .map(|s| {
                    let angle = std::f64::consts::TAU * (s as f64 + 0.4 * next()) / k as f64;
                    let radius = 0.2 + next();
                    [centre[0] + radius * angle.cos(), centre[1] + radius * angle.sin()]
                })
                .collect();
            if round % 5 == 0 && k >= 6 {
                // a sliver: two rim points almost on one line with the centre
                // (the second turned a little counter-clockwise, so the fan
                // stays free of overlaps)
                let d = [rim[0][0] - centre[0], rim[0][1] - centre[1]];
                rim[1] = [centre[0] + 2.0 * d[0] - 1e-9 * d[1], centre[1] + 2.0 * d[1] + 1e-9 * d[0]];
            }
            let mut tris: Vec<Tri> = (0..k).map(|s| [centre, rim[s], rim[(s + 1) % k]]).collect();
            if round % 3 == 0 {
                tris.reverse();
                tris.iter_mut().for_each(|t| t.swap(1, 2));
            }
            let resolution = [17, 64, 101][round % 3];
            let mut grid = Grid::around(&tris, resolution).unwrap();
            if round % 4 == 1 {
                // put the centre on a pixel centre: edges through it meet
                // pixel centres exactly
                grid.origin = [centre[0] - 8.5 * grid.pixel, centre[1] - 8.5 * grid.pixel];
            }
            let mut cov = vec![0u16; resolution * resolution];
            rasterise(&grid, &tris, &mut cov);
            assert_eq!(cov, by_pixel(&grid, &tris), "round {round}");
            // a fan around an interior point covers each pixel at most once
            assert!(cov.iter().all(|&c| c <= 1), "round {round}");
        }
    }
}
