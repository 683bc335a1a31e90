//! Two swept parameters (`sweep --param a=A:B:S --param b=C:D:E`): the
//! verdicts on a grid of the (a, b) plane at one valence, and, where the
//! exact sweep applies, the exact ends in a of the convergent, C¹ and
//! curvature-class sets at each grid value of b.
//!
//! Evidence: each grid point is the single-point analysis of `sweep` (the
//! floating-point spectrum, and with `--curvature` the second-order
//! analysis), so the coloured grid is floating point; the ends are those of
//! `sweep --exact` (exact algebraic numbers, pieces decided in floating
//! point), drawn as ticks at their exact positions.

use super::exact::{run as exact_run, ExactInterval, ExactSweep};
use super::{parse_range, run_on, Grid, Point};
use crate::error::Error;
use crate::numeric::ParamValue;

/// The most values of the vertical parameter (rows of the plane).
pub const MAX_ROWS: usize = 1000;

/// What the two-parameter sweep is asked.
#[derive(Clone, Debug)]
pub struct RegionSweep {
    pub scheme: String,
    pub valence: usize,
    pub faces: Option<String>,
    /// the horizontal parameter and its range text "A:B:S"
    pub x: (String, String),
    /// the vertical parameter and its range text
    pub y: (String, String),
    /// the other (fixed) parameters
    pub fixed: Vec<(String, String)>,
    pub curvature: bool,
    pub charmap: bool,
    pub threads: usize,
}

/// One exact end in x at one grid value of y.
#[derive(Clone, Debug)]
pub struct ExactEnd {
    pub y: f64,
    pub x: f64,
    /// "convergent", "C1 spectral", or a curvature class name
    pub set: String,
    /// the end as text (exact)
    pub text: String,
}

/// The grid and the exact ends.
#[derive(Clone, Debug)]
pub struct Region {
    /// one row per y value: (y as text, the points along x)
    pub rows: Vec<(String, Vec<Point>)>,
    pub ends: Vec<ExactEnd>,
    /// why no exact ends were drawn (the exact sweep refused), else None
    pub exact_missing: Option<String>,
}

/// Run the grid, then the exact sweep in x at every y of the grid.
pub fn run(r: &RegionSweep) -> Result<Region, Error> {
    let ys = parse_range(&r.y.1)?;
    // each range is bounded on its own; the plane is their product, and
    // every row of y also runs an exact sweep: refused up front, not run
    // for hours
    let xs = parse_range(&r.x.1)?.len();
    if ys.len() > MAX_ROWS {
        return Err(Error::Input(format!(
            "{} = {}: {} rows, more than the {MAX_ROWS} a two-parameter sweep takes (each row is an exact sweep in {})",
            r.y.0,
            r.y.1,
            ys.len(),
            r.x.0
        )));
    }
    if xs.saturating_mul(ys.len()) > super::MAX_POINTS {
        return Err(Error::Input(format!(
            "{} × {} = {} grid points, more than the {} a sweep takes: coarsen a step",
            xs,
            ys.len(),
            xs.saturating_mul(ys.len()),
            super::MAX_POINTS
        )));
    }
    let valences = format!("{0}..{0}", r.valence);
    let mut rows = Vec::with_capacity(ys.len());
    for y in &ys {
        let mut params = r.fixed.clone();
        params.push((r.x.0.clone(), r.x.1.clone()));
        params.push((r.y.0.clone(), y.clone()));
        let mut grid = Grid::parse(&r.scheme, &valences, r.faces.as_deref(), &params, r.charmap)?;
        grid.curvature = r.curvature;
        rows.push((y.clone(), run_on(&grid, r.threads, &|_, _| {})?));
    }
    // the exact ends: the x range's own ends are the window
    let parts: Vec<&str> = r.x.1.split(':').collect();
    let exact = |t: &str| ParamValue::parse(t).ok().and_then(|p| p.exact);
    let (Some(lo), Some(hi)) = (exact(parts[0]), exact(parts[1])) else {
        return Ok(Region { rows, ends: Vec::new(), exact_missing: Some("the range of x is not exact".into()) });
    };
    let mut ends = Vec::new();
    let mut exact_missing = None;
    if lo < hi {
        for y in &ys {
            let mut fixed = r.fixed.clone();
            fixed.push((r.y.0.clone(), y.clone()));
            let sweep = ExactSweep {
                scheme: r.scheme.clone(),
                valences: vec![r.valence],
                param: r.x.0.clone(),
                lo: lo.clone(),
                hi: hi.clone(),
                fixed,
                faces: r.faces.clone(),
                certify: false,
                curvature: r.curvature,
            };
            let sets = match exact_run(&sweep) {
                Ok(mut s) => s.pop().ok_or_else(|| Error::Message("no valence swept".into()))?,
                Err(e) => {
                    // the grid stands on its own; the figure says why no ends
                    exact_missing = Some(e.to_string());
                    ends.clear();
                    break;
                }
            };
            if !sets.exact {
                exact_missing = Some(format!("at {} = {y}: {}", r.y.0, sets.not_exact_because.join("; ")));
            }
            let yv = ParamValue::parse(y)?.value;
            let mut push = |set: &str, list: &[ExactInterval]| {
                for i in list {
                    for (e, is_range_end) in [
                        (&i.from, i.from.rational.as_ref() == Some(&lo.to_string())),
                        (&i.to, i.to.rational.as_ref() == Some(&hi.to_string())),
                    ] {
                        // the window's own ends are not boundaries
                        if !is_range_end {
                            ends.push(ExactEnd { y: yv, x: e.decimal, set: set.to_string(), text: e.text.clone() });
                        }
                    }
                }
            };
            push("convergent", &sets.convergent);
            push("C1 spectral", &sets.c1_spectral);
            if let Some(c) = &sets.curvature {
                push("curvature zero", &c.zero);
                push("curvature bounded", &c.bounded);
                push("curvature unbounded", &c.unbounded);
            }
        }
    }
    Ok(Region { rows, ends, exact_missing })
}
