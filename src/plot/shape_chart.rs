//! Shape-chart figures (`subdlab shape-chart -o`, `--theta-out`): the heat
//! map (t across, valence down; one panel per step m: the first, a middle
//! one and ∞) and the t × θ chart of one valence. Cells are coloured by
//! category (`shape_chart::classify`, worst over θ in the heat map); a
//! black dot marks the divergent overlay.
//!
//! Laid out with `layout` like every other figure: the title wrapped to
//! the width, the legend measured and placed below the panels (never over
//! cells), each panel's caption, ticks and axis descriptions measured, and
//! everything set smaller (down to `layout::MIN_BASE_FONT`) until it fits.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::HPos;

use super::layout::{
    draw_lines, em, fit, line_step, place_outside, plan_axes, region_area, text_width, title_block, AxesPlan, Axis,
    Legend, LegendPosition, LegendShape, NoFit, Swatch, Ticks, MARGIN,
};
use super::{csv_field, csv_number, err, Figure, Style};
use crate::error::Error;
use crate::shape_chart::{panels, worst_over_theta, Category, ShapeChart, ValenceChart};

/// Base font size of the figures (tick labels), which `Style::font_size` replaces.
const BASE_FONT: u32 = 16;

/// Okabe–Ito colours (colour-blind safe), one per category.
fn colour(c: Category) -> RGBColor {
    match c {
        Category::Correct => RGBColor(0, 158, 115),
        Category::RightSign => RGBColor(86, 180, 233),
        Category::Flat => RGBColor(190, 190, 190),
        Category::Degenerate => RGBColor(240, 228, 66),
        Category::MixedSign => RGBColor(230, 159, 0),
        Category::WrongSign => RGBColor(213, 94, 0),
    }
}

fn panel_label(m: &str) -> String {
    if m == "inf" {
        "m = ∞ (central shape)".into()
    } else {
        format!("m = {m}")
    }
}

/// The panel's caption where the long one has no room.
fn short_panel_label(m: &str) -> String {
    if m == "inf" {
        "m = ∞".into()
    } else {
        format!("m = {m}")
    }
}

/// The heat map of a chart's valences.
pub struct HeatMap<'a> {
    pub chart: &'a ShapeChart,
    pub style: Style,
}

/// The t × θ chart of one valence.
pub struct ThetaChart<'a> {
    pub chart: &'a ShapeChart,
    pub valence: &'a ValenceChart,
    pub style: Style,
}

/// One row of cells: its label value and per t (category, divergent).
type GridRow = (f64, Vec<Option<(Category, bool)>>);

/// What a chart figure draws: panels of rows over the t samples.
struct Grids<'a> {
    title: String,
    ts: &'a [f64],
    /// (step m, rows) per panel
    grids: Vec<(String, Vec<GridRow>)>,
    y_desc: &'static str,
    /// distance between neighbouring rows' values (a cell's height)
    y_step: f64,
    /// whole-number rows (valences): integer ticks
    integer_rows: bool,
}

/// Everything placed before drawing.
struct Plan {
    title: Vec<String>,
    title_size: f64,
    caption_size: f64,
    legend: Option<(Legend, LegendShape, (f64, f64))>,
    /// per panel: its caption's top-centre and text, its region and its axes
    panels: Vec<((f64, f64), String, (f64, f64, f64, f64), AxesPlan)>,
}

impl Grids<'_> {
    fn half_t(&self) -> f64 {
        if self.ts.len() > 1 {
            (self.ts[1] - self.ts[0]).abs() / 2.0
        } else {
            0.5
        }
    }
    fn ranges(&self, style: &Style) -> ((f64, f64), (f64, f64)) {
        let ht = self.half_t();
        let ys = self.grids.iter().flat_map(|(_, rows)| rows.iter().map(|r| r.0));
        let (y0, y1) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(y), b.max(y)));
        let (y0, y1) = if y0.is_finite() { (y0, y1) } else { (0.0, 1.0) };
        let hy = self.y_step / 2.0;
        // valence (or θ) grows downwards: the y axis runs from the last row up to the first
        (style.xlim.unwrap_or((-1.0 - ht, 1.0 + ht)), style.ylim.map_or((y1 + hy, y0 - hy), |(a, b)| (b, a)))
    }
    fn legend(&self, size: f64) -> Legend {
        let mut entries: Vec<(Swatch, String)> = Category::ALL
            .iter()
            .map(|c| (Swatch::Patch { fill: colour(*c), edge: RGBColor(90, 90, 90) }, c.name().replace('-', " ")))
            .collect();
        entries.push((Swatch::Dot(BLACK), "divergent (|ν*| > λ² or Jordan chain)".into()));
        Legend { entries, size }
    }
    fn plan(&self, style: &Style, size: (u32, u32), scale: f64, fmt: &dyn Fn(f64) -> String) -> Result<Plan, NoFit> {
        let font = |own: u32| style.font(own, BASE_FONT) as f64 * scale;
        let (w, h) = (size.0 as f64, size.1 as f64);
        let title_size = font(22);
        let (title, title_h) = title_block(style.title(self.title.clone()), title_size, w)?;
        let mut legend = self.legend(font(14));
        // below the panels unless asked otherwise: right of three panels would squeeze them
        let position = match style.legend.unwrap_or(LegendPosition::Below) {
            LegendPosition::Auto => LegendPosition::Below,
            p if p.inside() => {
                return Err(NoFit("the legend (a shape chart's legend goes right, below or none)".into()))
            }
            p => p,
        };
        let mut region = (MARGIN, MARGIN + title_h, MARGIN, MARGIN);
        let placed = place_outside(&mut legend, position, (w, h), &mut region)?;
        let caption_size = font(17);
        let caption_h = line_step(caption_size);
        let count = self.grids.len().max(1);
        let gap = em(font(14));
        let panel_w = (w - region.0 - region.2 - gap * (count - 1) as f64) / count as f64;
        let (xr, yr) = self.ranges(style);
        let mut panels = Vec::new();
        for k in 0..count {
            let left = region.0 + k as f64 * (panel_w + gap);
            let top = region.1 + caption_h;
            // the long description where a panel has room for it (with its y labels beside)
            let long = "t (hyperbolic < 0 < elliptic)";
            let desc = if text_width(long, font(15)) < 0.7 * panel_w { long } else { "t" };
            let x = Axis { range: xr, desc: Some(desc.into()), ticks: Ticks::Auto(fmt) };
            let y = Axis {
                range: (yr.1, yr.0),
                desc: Some(self.y_desc.into()),
                ticks: if self.integer_rows { Ticks::Integers } else { Ticks::Auto(fmt) },
            };
            let axes = plan_axes((panel_w, h - top - region.3), &x, &y, font(14), font(15), false)?;
            // the caption is centred over the plot and must stay inside the panel
            let centre = left + (axes.plot.0 + axes.plot.2) / 2.0;
            let room = 2.0 * (centre - left).min(left + panel_w - centre);
            let m = self.grids.get(k).map_or(String::new(), |g| g.0.clone());
            let caption = [panel_label(&m), short_panel_label(&m)]
                .into_iter()
                .find(|c| text_width(c, caption_size) <= room)
                .ok_or_else(|| NoFit(format!("the panel caption '{}'", panel_label(&m))))?;
            panels.push(((centre, region.1), caption, (left, top, w - left - panel_w, region.3), axes));
        }
        Ok(Plan { title, title_size, caption_size, legend: placed.map(|(s, at)| (legend, s, at)), panels })
    }
    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        style: &Style,
        size: (u32, u32),
    ) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE).map_err(err)?;
        let (xr, yr) = self.ranges(style);
        let fmt = |v: f64| {
            if (v - v.round()).abs() < 1e-9 {
                format!("{v:.0}")
            } else {
                super::tick_label(v, 2.0)
            }
        };
        let plan = fit(style.font(BASE_FONT, BASE_FONT) as f64, size, |scale| self.plan(style, size, scale, &fmt))?;
        draw_lines(root, &plan.title, plan.title_size, (size.0 as f64 / 2.0, MARGIN), HPos::Center)?;
        let (ht, hy) = (self.half_t(), self.y_step / 2.0);
        for ((_, rows), (caption_at, caption, region, axes)) in self.grids.iter().zip(&plan.panels) {
            draw_lines(root, std::slice::from_ref(caption), plan.caption_size, *caption_at, HPos::Center)?;
            let area = region_area(root, *region);
            // plotters' y grows upwards: the range (bottom, top) puts the first row on top
            let y = (yr.0, yr.1);
            let mut chart = axes.chart(&area, xr, y)?;
            let dot = (0.18 * em(axes.label_size)).max(1.5).round() as i32;
            for (row, cells) in rows {
                for (t, cell) in self.ts.iter().zip(cells) {
                    let Some((c, divergent)) = cell else { continue };
                    let rect = [(t - ht, row - hy), (t + ht, row + hy)];
                    chart.draw_series(std::iter::once(Rectangle::new(rect, colour(*c).filled()))).map_err(err)?;
                    if *divergent {
                        chart
                            .draw_series(std::iter::once(Circle::new((*t, *row), dot, BLACK.filled())))
                            .map_err(err)?;
                    }
                }
            }
            axes.draw(&area, xr, y, false)?;
        }
        if let Some((legend, shape, at)) = &plan.legend {
            legend.draw(root, *shape, *at)?;
        }
        Ok(())
    }
    /// The plotted cells as CSV: panel, row value, t, category, divergent.
    fn csv(&self, row_name: &str) -> String {
        let mut out = format!("m,{row_name},t,category,divergent\n");
        for (m, rows) in &self.grids {
            for (row, cells) in rows {
                for (t, cell) in self.ts.iter().zip(cells) {
                    if let Some((c, divergent)) = cell {
                        out += &format!(
                            "{},{},{},{},{divergent}\n",
                            csv_field(m),
                            csv_number(*row),
                            csv_number(*t),
                            c.name()
                        );
                    }
                }
            }
        }
        out
    }
}

impl HeatMap<'_> {
    fn grids(&self) -> Grids<'_> {
        let c = self.chart;
        let grids = panels(&c.steps)
            .into_iter()
            .map(|m| {
                let rows = c
                    .valences
                    .iter()
                    .map(|v| (v.n as f64, c.ts.iter().map(|&t| worst_over_theta(v, t, &m)).collect()))
                    .collect();
                (m, rows)
            })
            .collect();
        Grids {
            title: format!("{}: shape chart (worst over θ)", c.scheme),
            ts: &c.ts,
            grids,
            y_desc: "valence n",
            y_step: 1.0,
            integer_rows: true,
        }
    }
}

impl Figure for HeatMap<'_> {
    fn size(&self) -> (u32, u32) {
        let rows = self.chart.valences.len() as u32;
        self.style.size((3 * 330 + 40, (rows * 26).max(200) + 200))
    }
    fn dpi(&self) -> Option<f64> {
        self.style.dpi
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        self.grids().draw(root, &self.style, self.size())
    }
    fn data_csv(&self) -> Result<String, Error> {
        Ok(self.grids().csv("valence"))
    }
}

impl ThetaChart<'_> {
    fn grids(&self) -> Grids<'_> {
        let v = self.valence;
        let step = if v.thetas.len() > 1 { v.thetas[1] - v.thetas[0] } else { v.theta_range_degrees.max(1.0) };
        let grids = panels(&self.chart.steps)
            .into_iter()
            .map(|m| {
                let rows = v
                    .thetas
                    .iter()
                    .map(|&th| {
                        let cells = self
                            .chart
                            .ts
                            .iter()
                            .map(|&t| {
                                v.rows
                                    .iter()
                                    .find(|r| r.t == t && r.theta_degrees == th && r.m == m)
                                    .map(|r| (r.category, r.divergent))
                            })
                            .collect();
                        (th, cells)
                    })
                    .collect();
                (m, rows)
            })
            .collect();
        Grids {
            title: format!("{} n = {} ({}): shape chart over t and θ", self.chart.scheme, v.n, v.faces),
            ts: &self.chart.ts,
            grids,
            y_desc: "θ (degrees)",
            y_step: step,
            integer_rows: false,
        }
    }
}

impl Figure for ThetaChart<'_> {
    fn size(&self) -> (u32, u32) {
        let rows = self.valence.thetas.len() as u32;
        self.style.size((3 * 330 + 40, (rows * 24).max(200) + 200))
    }
    fn dpi(&self) -> Option<f64> {
        self.style.dpi
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        self.grids().draw(root, &self.style, self.size())
    }
    fn data_csv(&self) -> Result<String, Error> {
        Ok(self.grids().csv("theta_degrees"))
    }
}
