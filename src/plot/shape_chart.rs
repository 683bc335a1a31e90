//! Shape-chart figures (`subdlab shape-chart -o`, `--theta-out`): the heat
//! map (t across, valence down; one panel per step m: the first, a middle
//! one and ∞) and the t × θ chart of one valence. Cells are coloured by
//! category (`shape_chart::classify`, worst over θ in the heat map); a
//! black dot marks the divergent overlay.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{err, Figure, Style, FONT};
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

/// Draw `grids` (one per panel) side by side, rows `y` down, t across,
/// with a legend strip at the bottom.
fn draw_grids<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    style: &Style,
    title: String,
    ts: &[f64],
    grids: &[(String, Vec<GridRow>)],
    y_desc: &str,
    y_step: f64,
) -> Result<(), Error>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(err)?;
    let font = |own: u32| style.font(own, BASE_FONT);
    let (_, h) = root.dim_in_pixel();
    let legend_height = (font(16) * 2 + 24).min(h / 3);
    let (top, legend) = root.split_vertically(h - legend_height);
    let title_height = style.title(title.clone()).map_or(0, |_| font(22) + 16);
    let (head, body) = top.split_vertically(title_height);
    if let Some(t) = style.title(title) {
        head.draw(&Text::new(t, (16, 8), (FONT, font(22)).into_font())).map_err(err)?;
    }
    let half_t = if ts.len() > 1 { (ts[1] - ts[0]).abs() / 2.0 } else { 0.5 };
    let areas = body.split_evenly((1, grids.len().max(1)));
    for ((label, rows), area) in grids.iter().zip(areas.iter()) {
        let ys: Vec<f64> = rows.iter().map(|r| r.0).collect();
        let (y0, y1) = ys.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(*y), b.max(*y)));
        let (y0, y1) = if y0.is_finite() { (y0, y1) } else { (0.0, 1.0) };
        let hy = y_step / 2.0;
        let mut chart = ChartBuilder::on(area)
            .caption(panel_label(label), (FONT, font(18)))
            .margin(8)
            .x_label_area_size(font(16) * 3)
            .y_label_area_size(font(16) * 4)
            // valence (or θ) grows downwards
            .build_cartesian_2d(-1.0 - half_t..1.0 + half_t, (y1 + hy)..(y0 - hy))
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("t (hyperbolic < 0 < elliptic)")
            .y_desc(y_desc)
            .x_labels(5)
            .y_labels(rows.len().min(13))
            .label_style((FONT, font(14)))
            .axis_desc_style((FONT, font(15)))
            .x_label_formatter(&|x| super::tick_label(*x, 2.0))
            // whole valences and whole degrees without a decimal point
            .y_label_formatter(&|y| {
                if (y - y.round()).abs() < 1e-9 {
                    format!("{y:.0}")
                } else {
                    super::tick_label(*y, (y1 - y0).max(1.0))
                }
            })
            .draw()
            .map_err(err)?;
        for (y, cells) in rows {
            for (t, cell) in ts.iter().zip(cells) {
                let Some((c, divergent)) = cell else { continue };
                chart
                    .draw_series(std::iter::once(Rectangle::new(
                        [(t - half_t, y - hy), (t + half_t, y + hy)],
                        colour(*c).filled(),
                    )))
                    .map_err(err)?;
                if *divergent {
                    chart
                        .draw_series(std::iter::once(Circle::new((*t, *y), 2 + font(16) / 8, BLACK.filled())))
                        .map_err(err)?;
                }
            }
        }
    }
    // legend: one swatch per category, then the overlay
    let size = font(14) as i32;
    let text = TextStyle::from((FONT, font(14)).into_font()).color(&BLACK);
    let (w, _) = legend.dim_in_pixel();
    let per_row = 4usize;
    let col_w = (w as i32 - 20) / per_row as i32;
    let mut items: Vec<(Option<Category>, String)> =
        Category::ALL.iter().map(|c| (Some(*c), c.name().replace('-', " "))).collect();
    items.push((None, "divergent (|ν*| > λ² or Jordan chain)".into()));
    for (k, (c, label)) in items.iter().enumerate() {
        let x = 10 + col_w * (k % per_row) as i32;
        let y = 6 + (size + 8) * (k / per_row) as i32;
        match c {
            Some(c) => legend.draw(&Rectangle::new([(x, y), (x + size, y + size)], colour(*c).filled())),
            None => legend.draw(&Circle::new((x + size / 2, y + size / 2), size / 4 + 1, BLACK.filled())),
        }
        .map_err(err)?;
        legend.draw(&Text::new(label.clone(), (x + size + 6, y), text.clone())).map_err(err)?;
    }
    Ok(())
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
        let c = self.chart;
        let grids: Vec<(String, Vec<GridRow>)> = panels(&c.steps)
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
        let title = format!("{}: shape chart (worst over θ)", c.scheme);
        draw_grids(root, &self.style, title, &c.ts, &grids, "valence n", 1.0)
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
        let v = self.valence;
        let step = if v.thetas.len() > 1 { v.thetas[1] - v.thetas[0] } else { v.theta_range_degrees.max(1.0) };
        let grids: Vec<(String, Vec<GridRow>)> = panels(&self.chart.steps)
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
        let title = format!("{} n = {} ({}): shape chart over t and θ", self.chart.scheme, v.n, v.faces);
        draw_grids(root, &self.style, title, &self.chart.ts, &grids, "θ (degrees)", step)
    }
}
