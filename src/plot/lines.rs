//! Curves against the valence: the one chart the spectrum figure (one curve
//! per eigenvalue branch) and the comparison figure (one curve per scheme or
//! parameter value) draw, with optional reference curves (expressions in n,
//! read as `sweep --bound` reads them) drawn dashed and labelled.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::{
    draw_lines, draw_marker, em, fit, plan_with_legend, region_area, title_block, Axis, Legend, LegendPosition, Marker,
    NoFit, Swatch, Ticks, MARGIN,
};
use super::sweep::Bound;
use super::{err, Style};
use crate::error::Error;
use plotters::style::text_anchor::HPos;

/// One drawn curve: its legend text and its points (valence, value).
pub struct Line {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// What the chart shows: the curves, the reference curves, the texts.
pub struct ValenceChart<'a> {
    /// the figure's own title (the style may replace or drop it)
    pub title: String,
    pub y_desc: &'a str,
    pub lines: &'a [Line],
    pub references: &'a [Bound],
    pub style: &'a Style,
    /// the valences the x axis spans (the first and last)
    pub valences: (usize, usize),
}

/// Base font size of the chart (tick labels), which `Style::font_size` replaces.
pub const BASE_FONT: u32 = 17;

/// Colours of the data curves: the Okabe–Ito palette, told apart in the
/// common forms of colour blindness and in grey print (yellow left out: it
/// vanishes on white).
pub const COLOURS: [RGBColor; 6] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
];

/// The stroke width of curve k of `count`: earlier curves are wider, so
/// where two curves coincide the later one runs inside the earlier one and
/// both colours show (with the markers, a second cue besides colour).
pub fn stroke(k: usize, count: usize) -> u32 {
    2 + (count.saturating_sub(1 + k)).min(4) as u32
}

/// The marker of the k-th curve.
pub const MARKERS: [Marker; 6] =
    [Marker::Circle, Marker::Square, Marker::TriangleUp, Marker::Diamond, Marker::TriangleDown, Marker::Cross];

/// Colours of the reference curves: greys, so they read as references next
/// to the coloured data and apart from the black axes.
pub const REFERENCE_COLOURS: [RGBColor; 3] = [RGBColor(50, 50, 50), RGBColor(115, 115, 115), RGBColor(165, 165, 165)];

/// The default figure size in points.
pub const SIZE: (u32, u32) = (1000, 650);

/// Everything placed before drawing (`layout::AxesFigurePlan`).
use super::layout::AxesFigurePlan as Plan;

impl ValenceChart<'_> {
    /// The plotted numbers: one row per point of every curve and reference
    /// curve (`series` is its legend text; `kind` says which).
    pub fn csv(&self) -> String {
        use super::{csv_field, csv_number};
        let mut out = String::from("kind,series,valence,value\n");
        for (k, line) in self.lines.iter().enumerate() {
            for &(n, v) in &line.points {
                out += &format!("curve,{},{},{}\n", csv_field(self.label(k)), n, csv_number(v));
            }
        }
        for bound in self.references {
            for &(n, v) in &bound.values {
                out += &format!("reference,{},{},{}\n", csv_field(&bound.label), n, csv_number(v));
            }
        }
        out
    }
    /// The legend text of curve k: the user's (`--label`) or its own.
    fn label(&self, k: usize) -> &str {
        self.style.labels.get(k).unwrap_or(&self.lines[k].label)
    }
    fn x_range(&self) -> (f64, f64) {
        if let Some(lim) = self.style.xlim {
            return lim;
        }
        let (n0, n1) = self.valences;
        if n1 > n0 {
            (n0 as f64 - 0.5, n1 as f64 + 0.5)
        } else {
            (n0 as f64 - 1.0, n0 as f64 + 1.0)
        }
    }
    fn y_range(&self) -> (f64, f64) {
        if let Some(lim) = self.style.ylim {
            return lim;
        }
        let top = self
            .lines
            .iter()
            .flat_map(|l| l.points.iter().map(|p| p.1))
            .chain(self.references.iter().flat_map(|b| b.values.iter().map(|v| v.1)))
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max);
        (0.0, (1.12 * top).max(1e-3))
    }
    fn legend(&self, size: f64) -> Legend {
        let mut entries: Vec<(Swatch, String)> = self
            .lines
            .iter()
            .enumerate()
            .map(|(k, _)| {
                let k6 = k % COLOURS.len();
                (
                    Swatch::Line {
                        colour: COLOURS[k6],
                        width: stroke(k, self.lines.len()),
                        dash: None,
                        marker: MARKERS[k6],
                    },
                    self.label(k).to_string(),
                )
            })
            .collect();
        for (k, bound) in self.references.iter().enumerate() {
            let colour = REFERENCE_COLOURS[k % REFERENCE_COLOURS.len()];
            entries.push((
                Swatch::Line { colour, width: 2, dash: Some((8, 5)), marker: Marker::None },
                format!("reference {}", bound.label),
            ));
        }
        Legend { entries, size }
    }
    fn plan(&self, scale: f64, y_fmt: &dyn Fn(f64) -> String) -> Result<Plan, NoFit> {
        let font = |own: u32| self.style.font(own, BASE_FONT) as f64 * scale;
        let (w, h) = self.style.size(SIZE);
        let (w, h) = (w as f64, h as f64);
        let title_size = font(26);
        let (title, title_h) = title_block(self.style.title(self.title.clone()), title_size, w)?;
        let position = self.style.legend.unwrap_or(LegendPosition::Auto);
        let x = Axis { range: self.x_range(), desc: Some("valence n".into()), ticks: Ticks::Integers };
        let y = Axis { range: self.y_range(), desc: Some(self.y_desc.to_string()), ticks: Ticks::Auto(y_fmt) };
        let margins = (MARGIN, MARGIN + title_h, MARGIN, MARGIN);
        let (legend, region, axes) =
            plan_with_legend(self.legend(font(17)), position, (w, h), margins, &x, &y, (font(17), font(20)), false)?;
        Ok(Plan { title, title_size, legend, region, axes })
    }

    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE).map_err(err)?;
        let (x_range, y_range) = (self.x_range(), self.y_range());
        let y_fmt = |y: f64| super::tick_label(y, y_range.1);
        let size = self.style.size(SIZE);
        let plan = fit(self.style.font(BASE_FONT, BASE_FONT) as f64, size, |scale| self.plan(scale, &y_fmt))?;
        draw_lines(root, &plan.title, plan.title_size, (size.0 as f64 / 2.0, MARGIN), HPos::Center)?;
        let area = region_area(root, plan.region);
        plan.axes.draw(&area, x_range, y_range, true)?;
        let mut chart = plan.axes.chart(&area, x_range, y_range)?;
        let radius =
            |k: usize| (em(plan.axes.label_size) * 0.3).clamp(2.0, 4.0) as i32 + (self.lines.len() - 1 - k) as i32;
        for (k, line) in self.lines.iter().enumerate() {
            let k6 = k % COLOURS.len();
            let colour = COLOURS[k6];
            let style = colour.stroke_width(stroke(k, self.lines.len()));
            chart.draw_series(LineSeries::new(line.points.clone(), style)).map_err(err)?;
            // markers of later curves are smaller, so coinciding points show
            // every curve's marker
            let inside =
                |p: &(f64, f64)| (x_range.0..=x_range.1).contains(&p.0) && (y_range.0..=y_range.1).contains(&p.1);
            for p in line.points.iter().filter(|p| inside(p)) {
                let at = chart.backend_coord(p);
                let base = area.get_base_pixel();
                draw_marker(&area, MARKERS[k6], (at.0 - base.0, at.1 - base.1), radius(k), colour)?;
            }
        }
        for (k, bound) in self.references.iter().enumerate() {
            let colour = REFERENCE_COLOURS[k % REFERENCE_COLOURS.len()];
            let points: Vec<(f64, f64)> = bound.values.iter().map(|&(n, v)| (n as f64, v)).collect();
            chart.draw_series(DashedLineSeries::new(points, 8, 5, colour.stroke_width(2))).map_err(err)?;
        }
        if let Some((legend, shape, at)) = &plan.legend {
            legend.draw(root, *shape, *at)?;
        }
        Ok(())
    }
}
