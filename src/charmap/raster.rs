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
        for j in j0..=j1 {
            let py = grid.origin[1] + (j as f64 + 0.5) * grid.pixel;
            for i in i0..=i1 {
                let px = grid.origin[0] + (i as f64 + 0.5) * grid.pixel;
                if inside(&t, [px, py]) {
                    let c = &mut coverage[j * r + i];
                    *c = c.saturating_add(1);
                }
            }
        }
    }
}

/// Point in a counter-clockwise triangle, with the top-left rule on edges.
fn inside(t: &Tri, p: [f64; 2]) -> bool {
    (0..3).all(|k| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        let e = edge_function(a, b, p);
        e > 0.0 || (e == 0.0 && top_left(a, b))
    })
}

/// Twice the signed area of (a, b, p), computed from the endpoints in a fixed
/// order so that the reversed edge gives exactly the negated value.
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
