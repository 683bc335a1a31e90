//! Characteristic-ring figures: the ring and its copies scaled by λ1, λ1², …
//! nested around the centre, over the control net of the subdominant
//! eigenvectors (the way papers draw characteristic rings), or the normalised
//! wedge of one sector for large valences.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{err, Figure, FONT};
use crate::charmap::{wedge, CharMap};
use crate::error::Error;

pub struct RingFigure<'a> {
    pub map: &'a CharMap,
    /// how many rings to draw (the ring and copies scaled by λ1^k)
    pub copies: usize,
    /// draw the normalised wedge of one sector instead of the rings
    pub wedge: bool,
}

/// A polygon to paint: corners, colour index, whether to outline it.
type Painted = (Vec<(f64, f64)>, usize, bool);

const FILLS: [RGBColor; 2] = [RGBColor(158, 202, 225), RGBColor(253, 208, 162)];
const LINES: [RGBColor; 2] = [RGBColor(33, 113, 181), RGBColor(217, 72, 1)];

impl Figure for RingFigure<'_> {
    fn size(&self) -> (u32, u32) {
        (900, 900)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        let m = self.map;
        let ring = m
            .display
            .as_ref()
            .or(m.ring.as_ref())
            .ok_or_else(|| Error::Input("no characteristic ring to draw".into()))?;
        root.fill(&WHITE).map_err(err)?;
        let verdict = format!(
            "{}  ·  {}",
            if m.regular { "regular" } else { "NOT regular" },
            if m.injective { "injective" } else { "NOT injective" }
        );
        let title = format!(
            "{} n = {}: characteristic {}, λ1 = {:.6}",
            m.scheme,
            m.valence,
            if self.wedge { "wedge (normalised)" } else { "rings" },
            m.lambda1
        );
        let (top, rest) = root.split_vertically(70);
        top.draw(&Text::new(title, (20, 12), (FONT, 24).into_font())).map_err(err)?;
        top.draw(&Text::new(verdict, (20, 42), (FONT, 18).into_font())).map_err(err)?;

        // (polygon, colour, outlined). Copies are painted from the largest
        // down, each with the faces inside it: the next copy covers them, so
        // what shows of copy k is λ1^k times (the refined first ring minus its
        // copy scaled by λ1) at one level, without the sliver that separates
        // the ring's inner boundary (one level coarser) from the copy's outer
        // boundary in dual and sqrt(3) schemes.
        let xy = |p: &[f64; 2], s: f64| (p[0] * s, p[1] * s);
        let polys: Vec<Painted> = if self.wedge {
            wedge::normalised_wedge_polygons(&ring.ring_polys, m.valence)
                .into_iter()
                .map(|t| (t.iter().map(|p| xy(p, 1.0)).collect(), 0, true))
                .collect()
        } else {
            let mut out = Vec::new();
            let mut scale = 1.0;
            let copies = self.copies.max(1);
            for k in 0..copies {
                if k + 1 < copies {
                    for poly in &ring.inner_polys {
                        out.push((poly.iter().map(|p| xy(p, scale)).collect(), k % 2, false));
                    }
                }
                for poly in &ring.ring_polys {
                    out.push((poly.iter().map(|p| xy(p, scale)).collect(), k % 2, true));
                }
                scale *= m.lambda1;
            }
            out
        };
        let net: Vec<Vec<(f64, f64)>> = if self.wedge {
            Vec::new()
        } else {
            m.control_net.iter().map(|f| f.iter().map(|p| (p[0], p[1])).collect()).collect()
        };
        // equal scales on both axes: a square window around everything drawn
        let (mut lo, mut hi) = ((f64::INFINITY, f64::INFINITY), (f64::NEG_INFINITY, f64::NEG_INFINITY));
        for p in polys.iter().flat_map(|(p, _, _)| p.iter()).chain(net.iter().flatten()) {
            lo = (lo.0.min(p.0), lo.1.min(p.1));
            hi = (hi.0.max(p.0), hi.1.max(p.1));
        }
        if !(lo.0.is_finite() && hi.0.is_finite()) {
            return Err(Error::Input("nothing to draw".into()));
        }
        let half = 0.52 * (hi.0 - lo.0).max(hi.1 - lo.1);
        let c = ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0);
        let mut chart = ChartBuilder::on(&rest)
            .margin(20)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(c.0 - half..c.0 + half, c.1 - half..c.1 + half)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x")
            .y_desc("y")
            .label_style((FONT, 16))
            .axis_desc_style((FONT, 18))
            .draw()
            .map_err(err)?;
        let grey = RGBColor(150, 150, 150);
        for f in &net {
            let mut closed = f.clone();
            closed.push(f[0]);
            chart.draw_series(std::iter::once(PathElement::new(closed, grey.stroke_width(1)))).map_err(err)?;
        }
        for (p, k, outline) in &polys {
            chart.draw_series(std::iter::once(Polygon::new(p.clone(), FILLS[*k].filled()))).map_err(err)?;
            if *outline {
                let mut closed = p.clone();
                closed.push(p[0]);
                chart.draw_series(std::iter::once(PathElement::new(closed, LINES[*k].stroke_width(1)))).map_err(err)?;
            }
        }
        if !self.wedge {
            let dots: Vec<(f64, f64)> = net.iter().flatten().copied().collect();
            chart.draw_series(dots.into_iter().map(|p| Circle::new(p, 3, BLACK.filled()))).map_err(err)?;
        }
        Ok(())
    }
}
