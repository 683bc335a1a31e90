//! Characteristic-ring figures: the ring and its copies scaled by λ1, λ1², …
//! nested around the centre, over the control net of the subdominant
//! eigenvectors (the way papers draw characteristic rings), or the normalised
//! wedge of one sector for large valences. With `sectors` the ring's faces
//! are coloured by the sector [2πk/n, 2π(k+1)/n) their centroid lies in (the
//! map is normalised so that sector 0 starts on the positive x-axis).

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{err, square_window, tick_label, Figure, Style, FONT};
use crate::charmap::{wedge, CharMap};
use crate::error::Error;

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
        let ring = m
            .display
            .as_ref()
            .or(m.ring.as_ref())
            .ok_or_else(|| Error::Input("no characteristic ring to draw".into()))?;
        root.fill(&WHITE).map_err(err)?;
        // the verdict is not drawn: it belongs to the caption of the paper
        // and to the command's table and JSON
        let font = |own: u32| self.style.font(own, BASE_FONT);
        let title = self.style.title(format!(
            "{} n = {}: characteristic {}, λ₁ = {:.6}",
            m.scheme,
            m.valence,
            if self.wedge { "wedge (normalised)" } else { "rings" },
            m.lambda1
        ));
        let rest = match title {
            Some(title) => {
                let (top, rest) = root.split_vertically(font(24) as i32 + 24);
                top.draw(&Text::new(title, (20, 12), (FONT, font(24)).into_font())).map_err(err)?;
                rest
            }
            None => root.clone(),
        };

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
        let (c, half) =
            square_window(polys.iter().flat_map(|(p, _, _)| p.iter()).chain(net.iter().flatten()).map(|p| [p.0, p.1]))
                .ok_or_else(|| Error::Input("nothing to draw".into()))?;
        // equal scales: the plot area is a square (the larger side of the
        // area is left as margin)
        let (w, h) = rest.dim_in_pixel();
        let (label_x, label_y) = (font(16) as i32 * 3, font(16) as i32 * 4);
        let side = (w as i32 - label_y).min(h as i32 - label_x).max(1);
        let (_, area) = rest.split_horizontally(((w as i32 - label_y - side) / 2).max(0));
        let (area, _) = area.split_horizontally((side + label_y).min(w as i32));
        let (area, _) = area.split_vertically((side + label_x).min(h as i32));
        let mut chart = ChartBuilder::on(&area)
            .margin(10)
            .x_label_area_size(label_x)
            .y_label_area_size(label_y)
            .build_cartesian_2d(c.0 - half..c.0 + half, c.1 - half..c.1 + half)
            .map_err(err)?;
        let span = 2.0 * half;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x")
            .y_desc("y")
            .label_style((FONT, font(16)))
            .axis_desc_style((FONT, font(18)))
            .x_label_formatter(&|v| tick_label(*v, span))
            .y_label_formatter(&|v| tick_label(*v, span))
            .draw()
            .map_err(err)?;
        let grey = RGBColor(150, 150, 150);
        for f in &net {
            let mut closed = f.clone();
            closed.push(f[0]);
            chart.draw_series(std::iter::once(PathElement::new(closed, grey.stroke_width(1)))).map_err(err)?;
        }
        // one legend entry per colour: the ring (k even) and the copies
        // between (k odd) alternate, so copy 0 is the ring itself
        let mut labelled = [false; 2];
        let mut sector_labelled = vec![false; SECTOR_COLOURS.len()];
        for (p, k, outline) in &polys {
            if self.sectors && !self.wedge {
                let sector = sector_of(p, m.valence);
                let colour = sector_colour(sector, m.valence);
                let fill = SECTOR_COLOURS[colour];
                let series = chart.draw_series(std::iter::once(Polygon::new(p.clone(), fill.filled()))).map_err(err)?;
                // one entry per sector while each has its own colour, else
                // one for the scheme (sector 0 names where the turn starts)
                let entry = if m.valence <= SECTOR_COLOURS.len() {
                    Some(format!("sector {sector}"))
                } else if sector == 0 {
                    Some("sector 0 (from the x-axis), then each in turn".to_string())
                } else {
                    None
                };
                if let Some(name) = entry.filter(|_| !sector_labelled[colour]) {
                    sector_labelled[colour] = true;
                    series.label(name).legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + Rectangle::new([(0, -6), (18, 6)], fill.filled())
                            + Rectangle::new([(0, -6), (18, 6)], BLACK.stroke_width(1))
                    });
                }
            } else {
                let series =
                    chart.draw_series(std::iter::once(Polygon::new(p.clone(), FILLS[*k].filled()))).map_err(err)?;
                if !labelled[*k] {
                    labelled[*k] = true;
                    let (fill, line) = (FILLS[*k], LINES[*k]);
                    let name = match (self.wedge, *k, self.copies) {
                        (true, _, _) => "sector 0 of the ring, angles stretched by n/4",
                        (false, 0, 0..=2) => "characteristic ring",
                        (false, 0, _) => "ring, copies scaled by λ₁², λ₁⁴, …",
                        (false, _, 2) => "copy scaled by λ₁",
                        _ => "copies scaled by λ₁, λ₁³, …",
                    };
                    series.label(name).legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + Rectangle::new([(0, -6), (18, 6)], fill.filled())
                            + Rectangle::new([(0, -6), (18, 6)], line.stroke_width(1))
                    });
                }
            }
            if *outline {
                let mut closed = p.clone();
                closed.push(p[0]);
                chart.draw_series(std::iter::once(PathElement::new(closed, LINES[*k].stroke_width(1)))).map_err(err)?;
            }
        }
        if !self.wedge {
            let dots: Vec<(f64, f64)> = net.iter().flatten().copied().collect();
            chart
                .draw_series(dots.into_iter().map(|p| Circle::new(p, 3, BLACK.filled())))
                .map_err(err)?
                .label("control net (subdominant eigenvectors)")
                .legend(move |(x, y)| Circle::new((x + 9, y), 3, BLACK.filled()));
        }
        {
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .label_font((FONT, font(14)))
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .draw()
                .map_err(err)?;
        }
        Ok(())
    }
}
