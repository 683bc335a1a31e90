//! Characteristic-ring figures: the ring and its copies scaled by λ1, λ1², …
//! nested around the centre, over the control net of the subdominant
//! eigenvectors (the way papers draw characteristic rings), or the normalised
//! wedge of one sector for large valences. With `sectors` the ring's faces
//! are coloured by the sector [2πk/n, 2π(k+1)/n) their centroid lies in (the
//! map is normalised so that sector 0 starts on the positive x-axis).

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::MARGIN;
use super::layout::{
    block_height, draw_lines, em, fit, plan_with_legend, region_area, title_lines, Axis, Legend, LegendPosition,
    Swatch, Ticks,
};
use super::{err, square_window, tick_label, Figure, Style};
use crate::charmap::{wedge, CharMap};
use crate::error::Error;
use plotters::style::text_anchor::HPos;

pub struct RingFigure<'a> {
    pub map: &'a CharMap,
    /// how many rings to draw (the ring and copies scaled by λ1^k)
    pub copies: usize,
    /// draw the normalised wedge of one sector instead of the rings
    pub wedge: bool,
    /// colour faces by the sector they lie in (rings only: the wedge is one sector)
    pub sectors: bool,
    pub style: Style,
}

/// Colours of the sectors, in turn around the centre.
pub const SECTOR_COLOURS: [RGBColor; 5] = [
    RGBColor(141, 211, 199),
    RGBColor(255, 255, 179),
    RGBColor(190, 186, 218),
    RGBColor(251, 128, 114),
    RGBColor(128, 177, 211),
];

/// The colour (index into [`SECTOR_COLOURS`]) of sector k of n: the
/// colours in turn, and where the last sector would take the colour of
/// sector 0, its neighbour across the positive x-axis, one of neither of its
/// neighbours, so neighbouring sectors always differ.
pub fn sector_colour(k: usize, n: usize) -> usize {
    let m = SECTOR_COLOURS.len();
    if k + 1 == n && n > m && k.is_multiple_of(m) {
        2
    } else {
        k % m
    }
}

/// The sector [2πk/n, 2π(k+1)/n) of a polygon's vertex centroid.
pub fn sector_of(poly: &[(f64, f64)], n: usize) -> usize {
    let k = poly.len() as f64;
    let (x, y) = poly.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0 / k, a.1 + p.1 / k));
    let turn = y.atan2(x).rem_euclid(2.0 * std::f64::consts::PI) / (2.0 * std::f64::consts::PI);
    ((turn * n as f64).floor() as usize).min(n - 1)
}

/// Base font size of the figure (tick labels), which `Style::font_size` replaces.
const BASE_FONT: u32 = 16;

/// A polygon to paint: corners, colour index, whether to outline it.
type Painted = (Vec<(f64, f64)>, usize, bool);

const FILLS: [RGBColor; 2] = [RGBColor(158, 202, 225), RGBColor(253, 208, 162)];
const LINES: [RGBColor; 2] = [RGBColor(33, 113, 181), RGBColor(217, 72, 1)];

impl Figure for RingFigure<'_> {
    fn size(&self) -> (u32, u32) {
        self.style.size((900, 900))
    }
    fn dpi(&self) -> Option<f64> {
        self.style.dpi
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        let m = self.map;
        let (polys, net) = self.shapes()?;
        root.fill(&WHITE).map_err(err)?;
        // the verdict is not drawn: it belongs to the caption of the paper
        // and to the command's table and JSON
        let title = self.style.title(format!(
            "{} n = {}: characteristic {}, λ₁ = {:.6}",
            m.scheme,
            m.valence,
            if self.wedge { "wedge (normalised)" } else { "rings" },
            m.lambda1
        ));
        // equal scales on both axes: a square window around everything drawn
        let (c, half) =
            square_window(polys.iter().flat_map(|(p, _, _)| p.iter()).chain(net.iter().flatten()).map(|p| [p.0, p.1]))
                .ok_or_else(|| Error::Input("nothing to draw".into()))?;
        let (xr, yr) =
            (self.style.xlim.unwrap_or((c.0 - half, c.0 + half)), self.style.ylim.unwrap_or((c.1 - half, c.1 + half)));
        let span = (xr.1 - xr.0).max(yr.1 - yr.0);
        let fmt = |v: f64| tick_label(v, span);
        let size = self.size();
        let entries = self.legend_entries(&polys);
        let plan = fit(self.style.font(BASE_FONT, BASE_FONT) as f64, size, |scale| {
            let font = |own: u32| self.style.font(own, BASE_FONT) as f64 * scale;
            let (w, h) = (size.0 as f64, size.1 as f64);
            let title_size = font(24);
            let lines = match &title {
                Some(t) => title_lines(t, title_size, w - 2.0 * MARGIN, 3)?,
                None => Vec::new(),
            };
            let title_h =
                if lines.is_empty() { 0.0 } else { block_height(lines.len(), title_size) + 0.4 * em(title_size) };
            let legend = Legend { entries: entries.clone(), size: font(14) };
            let position = self.style.legend.unwrap_or(LegendPosition::Auto);
            let x = Axis { range: xr, desc: Some("x".into()), ticks: Ticks::Auto(&fmt) };
            let y = Axis { range: yr, desc: Some("y".into()), ticks: Ticks::Auto(&fmt) };
            let margins = (MARGIN, MARGIN + title_h, MARGIN, MARGIN);
            let (legend, region, axes) =
                plan_with_legend(legend, position, (w, h), margins, &x, &y, (font(16), font(18)), true)?;
            Ok((lines, title_size, legend, region, axes))
        })?;
        let (title_text, title_size, legend, region, axes) = plan;
        draw_lines(root, &title_text, title_size, (size.0 as f64 / 2.0, MARGIN), HPos::Center)?;
        let area = region_area(root, region);
        axes.draw(&area, xr, yr, false)?;
        let mut chart = axes.chart(&area, xr, yr)?;
        let grey = RGBColor(150, 150, 150);
        for f in &net {
            let mut closed = f.clone();
            closed.push(f[0]);
            chart.draw_series(std::iter::once(PathElement::new(closed, grey.stroke_width(1)))).map_err(err)?;
        }
        for (p, k, outline) in &polys {
            let fill = if self.sectors && !self.wedge {
                SECTOR_COLOURS[sector_colour(sector_of(p, m.valence), m.valence)]
            } else {
                FILLS[*k]
            };
            chart.draw_series(std::iter::once(Polygon::new(p.clone(), fill.filled()))).map_err(err)?;
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
        if let Some((legend, shape, at)) = &legend {
            legend.draw(root, *shape, *at)?;
        }
        Ok(())
    }
    fn data_csv(&self) -> Result<String, Error> {
        use super::csv_number;
        let (polys, net) = self.shapes()?;
        // the faces as painted (the ring and its scaled copies, or the
        // wedge), then the control net's faces
        let mut out = String::from("kind,polygon,vertex,x,y\n");
        for (i, (p, _, _)) in polys.iter().enumerate() {
            for (j, q) in p.iter().enumerate() {
                out += &format!("face,{i},{j},{},{}\n", csv_number(q.0), csv_number(q.1));
            }
        }
        for (i, f) in net.iter().enumerate() {
            for (j, q) in f.iter().enumerate() {
                out += &format!("control net,{i},{j},{},{}\n", csv_number(q.0), csv_number(q.1));
            }
        }
        Ok(out)
    }
}

impl RingFigure<'_> {
    /// What is drawn: the painted polygons and the control net's faces.
    #[allow(clippy::type_complexity)]
    fn shapes(&self) -> Result<(Vec<Painted>, Vec<Vec<(f64, f64)>>), Error> {
        let m = self.map;
        let ring = m
            .display
            .as_ref()
            .or(m.ring.as_ref())
            .ok_or_else(|| Error::Input("no characteristic ring to draw".into()))?;
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
        Ok((polys, net))
    }

    /// The legend: one entry per colour drawn (the ring and the copies
    /// between alternate, so copy 0 is the ring itself; with sectors one per
    /// sector while each has its own colour, else one for the scheme, sector
    /// 0 naming where the turn starts), and the control net's dots.
    fn legend_entries(&self, polys: &[Painted]) -> Vec<(Swatch, String)> {
        let m = self.map;
        let mut entries = Vec::new();
        let mut labelled = [false; 2];
        let mut sector_labelled = vec![false; SECTOR_COLOURS.len()];
        for (p, k, _) in polys {
            if self.sectors && !self.wedge {
                let sector = sector_of(p, m.valence);
                let colour = sector_colour(sector, m.valence);
                let entry = if m.valence <= SECTOR_COLOURS.len() {
                    Some(format!("sector {sector}"))
                } else if sector == 0 {
                    Some("sector 0 (from the x-axis), then each in turn".to_string())
                } else {
                    None
                };
                if let Some(name) = entry.filter(|_| !sector_labelled[colour]) {
                    sector_labelled[colour] = true;
                    entries.push((Swatch::Patch { fill: SECTOR_COLOURS[colour], edge: BLACK }, name));
                }
            } else if !labelled[*k] {
                labelled[*k] = true;
                let name = match (self.wedge, *k, self.copies) {
                    (true, _, _) => "sector 0 of the ring, angles stretched by n/4",
                    (false, 0, 0..=2) => "characteristic ring",
                    (false, 0, _) => "ring, copies scaled by λ₁², λ₁⁴, …",
                    (false, _, 2) => "copy scaled by λ₁",
                    _ => "copies scaled by λ₁, λ₁³, …",
                };
                entries.push((Swatch::Patch { fill: FILLS[*k], edge: LINES[*k] }, name.to_string()));
            }
        }
        if !self.wedge {
            entries.push((Swatch::Dot(BLACK), "control net (subdominant eigenvectors)".to_string()));
        }
        entries
    }
}
