//! Curves against the valence: the one chart the spectrum figure (one curve
//! per eigenvalue branch) and the comparison figure (one curve per scheme or
//! parameter value) draw, with optional reference curves (expressions in n,
//! read as `sweep --bound` reads them) drawn dashed and labelled.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::sweep::Bound;
use super::{err, Style, FONT};
use crate::error::Error;

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

/// Colours of the data curves (matplotlib's first six, distinct in print).
pub const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
];

/// Colours of the reference curves: greys, so they read as references next
/// to the coloured data and apart from the black axes.
pub const REFERENCE_COLOURS: [RGBColor; 3] = [RGBColor(50, 50, 50), RGBColor(115, 115, 115), RGBColor(165, 165, 165)];

/// The default figure size in points.
pub const SIZE: (u32, u32) = (1000, 650);

impl ValenceChart<'_> {
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE).map_err(err)?;
        let (n0, n1) = self.valences;
        let x_range = if n1 > n0 { n0 as f64 - 0.5..n1 as f64 + 0.5 } else { n0 as f64 - 1.0..n0 as f64 + 1.0 };
        let values = self
            .lines
            .iter()
            .flat_map(|l| l.points.iter().map(|p| p.1))
            .chain(self.references.iter().flat_map(|b| b.values.iter().map(|v| v.1)));
        let top = values.fold(0.0, f64::max);
        let font = |own: u32| self.style.font(own, BASE_FONT);
        let mut builder = ChartBuilder::on(root);
        if let Some(title) = self.style.title(self.title.clone()) {
            builder.caption(title, (FONT, font(26)));
        }
        let y_top = (1.12 * top).max(1e-3);
        let mut chart = builder
            .margin(20)
            .x_label_area_size(font(17) * 3 + 4)
            .y_label_area_size(font(17) * 4)
            .build_cartesian_2d(x_range, 0.0..y_top)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("valence n")
            .y_desc(self.y_desc)
            .label_style((FONT, font(17)))
            .axis_desc_style((FONT, font(20)))
            .x_label_formatter(&|x| format!("{x:.0}"))
            .y_label_formatter(&|y| super::tick_label(*y, y_top))
            .draw()
            .map_err(err)?;
        for (k, line) in self.lines.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            chart
                .draw_series(LineSeries::new(line.points.clone(), colour.stroke_width(2)))
                .map_err(err)?
                .label(line.label.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
            chart.draw_series(line.points.iter().map(|p| Circle::new(*p, 3, colour.filled()))).map_err(err)?;
        }
        for (k, bound) in self.references.iter().enumerate() {
            let colour = REFERENCE_COLOURS[k % REFERENCE_COLOURS.len()];
            let points: Vec<(f64, f64)> = bound.values.iter().map(|&(n, v)| (n as f64, v)).collect();
            chart
                .draw_series(DashedLineSeries::new(points, 8, 5, colour.stroke_width(2)))
                .map_err(err)?
                .label(format!("reference {}", bound.label))
                .legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (8, 0)], colour.stroke_width(2))
                        + PathElement::new(vec![(12, 0), (20, 0)], colour.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .label_font((FONT, font(17)))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
        Ok(())
    }
}
