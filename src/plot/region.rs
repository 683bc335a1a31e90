//! The (a, b) plane of a two-parameter sweep (`sweep --param a=… --param
//! b=… --plot`): one row of cells per grid value of b, one cell per grid
//! value of a, coloured by the strongest test the point passes (the same
//! statuses and colours as the one-parameter sweep figure), and the exact
//! ends in a of each set at each b drawn as black ticks across the row.
//! The legend states the evidence of both: cells floating point, ticks
//! exact.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::HPos;

use super::layout::MARGIN;
use super::layout::{
    draw_lines, fit, plan_with_legend, region_area, title_block, Axis, Legend, LegendPosition, Marker, NoFit, Swatch,
    Ticks,
};
use super::sweep::CellStatus;
use super::{err, Figure, Style};
use crate::error::Error;
use crate::sweep::region::Region;

pub struct RegionFigure {
    pub scheme: String,
    pub valence: usize,
    pub x_name: String,
    pub y_name: String,
    /// (y, x, status)
    pub cells: Vec<(f64, f64, CellStatus)>,
    /// (y, x, set) of the exact ends
    pub ends: Vec<(f64, f64, String)>,
    pub charmap: bool,
    /// why the exact ends are missing, when they are
    pub exact_missing: Option<String>,
    pub style: Style,
}

const BASE_FONT: u32 = 17;

/// The colour of a set's end ticks.
fn tick_colour(set: &str) -> RGBColor {
    match set {
        "convergent" => RGBColor(120, 20, 20),
        "C1 spectral" => RGBColor(0, 0, 0),
        _ => RGBColor(31, 80, 200),
    }
}

/// The legend's name of a set's ends (the curvature classes share one).
fn tick_name(set: &str) -> &str {
    if set.starts_with("curvature") {
        "curvature classes'"
    } else {
        set
    }
}

/// Drawing order: curvature classes first, then convergence, then C¹ on
/// top (a C¹ end is often a class's end too, at the same place).
fn tick_rank(set: &str) -> u8 {
    match set {
        "C1 spectral" => 2,
        "convergent" => 1,
        _ => 0,
    }
}

/// Everything placed before drawing (`layout::AxesFigurePlan`).
use super::layout::AxesFigurePlan as Plan;

impl RegionFigure {
    pub fn new(
        scheme: &str,
        valence: usize,
        x_name: &str,
        y_name: &str,
        region: &Region,
        charmap: bool,
    ) -> Result<Self, Error> {
        let mut cells = Vec::new();
        for (y, points) in &region.rows {
            let yv = crate::numeric::ParamValue::parse(y)?.value;
            for p in points {
                let text =
                    p.param.as_deref().ok_or_else(|| Error::Input("the figure needs a swept parameter".into()))?;
                cells.push((yv, crate::numeric::ParamValue::parse(text)?.value, CellStatus::of(p)));
            }
        }
        if cells.is_empty() {
            return Err(Error::Input("no sweep points to plot".into()));
        }
        Ok(RegionFigure {
            scheme: scheme.to_string(),
            valence,
            x_name: x_name.to_string(),
            y_name: y_name.to_string(),
            cells,
            ends: region.ends.iter().map(|e| (e.y, e.x, e.set.clone())).collect(),
            charmap,
            exact_missing: region.exact_missing.clone(),
            style: Style::default(),
        })
    }

    /// Half the smallest distance between neighbouring values of one axis.
    fn half_step(values: impl Iterator<Item = f64>) -> f64 {
        let mut v: Vec<f64> = values.collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        let step = v.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
        if step.is_finite() && step > 0.0 {
            step / 2.0
        } else {
            0.5
        }
    }
    fn halves(&self) -> (f64, f64) {
        (Self::half_step(self.cells.iter().map(|c| c.1)), Self::half_step(self.cells.iter().map(|c| c.0)))
    }
    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        let (hx, hy) = self.halves();
        let span = |f: &dyn Fn(&(f64, f64, CellStatus)) -> f64| {
            self.cells.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| (a.min(f(c)), b.max(f(c))))
        };
        let (x0, x1) = span(&|c| c.1);
        let (y0, y1) = span(&|c| c.0);
        (self.style.xlim.unwrap_or((x0 - hx, x1 + hx)), self.style.ylim.unwrap_or((y0 - hy, y1 + hy)))
    }
    fn legend(&self, size: f64) -> Legend {
        let mut shown: Vec<CellStatus> = Vec::new();
        for c in &self.cells {
            if !shown.contains(&c.2) {
                shown.push(c.2);
            }
        }
        shown.sort_by_key(|s| std::cmp::Reverse(*s as u8));
        let mut entries: Vec<(Swatch, String)> = shown
            .into_iter()
            .map(|s| {
                (Swatch::Patch { fill: s.colour(), edge: RGBColor(90, 90, 90) }, s.label(self.charmap).to_string())
            })
            .collect();
        let mut sets: Vec<&str> = Vec::new();
        for (_, _, s) in &self.ends {
            if !sets.iter().any(|k| tick_name(k) == tick_name(s)) {
                sets.push(s);
            }
        }
        sets.sort_by_key(|s| std::cmp::Reverse(tick_rank(s)));
        for s in sets {
            let name = match tick_name(s) {
                "C1 spectral" => "spectral C¹ set's".to_string(),
                "convergent" => "convergent set's".to_string(),
                other => other.to_string(),
            };
            entries.push((
                Swatch::Line { colour: tick_colour(s), width: 3, dash: None, marker: Marker::None },
                format!("the {name} exact ends (sweep --exact)"),
            ));
        }
        entries.push((
            Swatch::Patch { fill: RGBColor(255, 255, 255), edge: RGBColor(255, 255, 255) },
            match &self.exact_missing {
                None => "cells: floating point at the cell centre; ticks: exact".to_string(),
                Some(_) => "cells: floating point at the cell centre; exact ends not available".to_string(),
            },
        ));
        Legend { entries, size }
    }
    fn plan(&self, scale: f64, x_fmt: &dyn Fn(f64) -> String, y_fmt: &dyn Fn(f64) -> String) -> Result<Plan, NoFit> {
        let font = |own: u32| self.style.font(own, BASE_FONT) as f64 * scale;
        let (w, h) = self.size();
        let (w, h) = (w as f64, h as f64);
        let caption =
            format!("{} at n = {}: verdicts over ({}, {})", self.scheme, self.valence, self.x_name, self.y_name);
        let title_size = font(26);
        let (title, title_h) = title_block(self.style.title(caption), title_size, w)?;
        let position = self.style.legend.unwrap_or(LegendPosition::Auto);
        let (xr, yr) = self.ranges();
        let x = Axis { range: xr, desc: Some(format!("parameter {}", self.x_name)), ticks: Ticks::Auto(x_fmt) };
        let y = Axis { range: yr, desc: Some(format!("parameter {}", self.y_name)), ticks: Ticks::Auto(y_fmt) };
        let margins = (MARGIN, MARGIN + title_h, MARGIN, MARGIN);
        let (legend, region, axes) =
            plan_with_legend(self.legend(font(17)), position, (w, h), margins, &x, &y, (font(17), font(20)), false)?;
        Ok(Plan { title, title_size, legend, region, axes })
    }
}

impl Figure for RegionFigure {
    fn size(&self) -> (u32, u32) {
        self.style.size((1100, 900))
    }
    fn dpi(&self) -> Option<f64> {
        self.style.dpi
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE).map_err(err)?;
        let (xr, yr) = self.ranges();
        let (hx, hy) = self.halves();
        let (sx, sy) = (xr.1 - xr.0 - 2.0 * hx, yr.1 - yr.0 - 2.0 * hy);
        let x_fmt = |x: f64| super::tick_label(x, sx);
        let y_fmt = |y: f64| super::tick_label(y, sy);
        let size = self.size();
        let plan = fit(self.style.font(BASE_FONT, BASE_FONT) as f64, size, |scale| self.plan(scale, &x_fmt, &y_fmt))?;
        draw_lines(root, &plan.title, plan.title_size, (size.0 as f64 / 2.0, MARGIN), HPos::Center)?;
        let area = region_area(root, plan.region);
        plan.axes.draw(&area, xr, yr, false)?;
        let mut chart = plan.axes.chart(&area, xr, yr)?;
        chart
            .draw_series(
                self.cells.iter().map(|&(y, x, status)| {
                    Rectangle::new([(x - hx, y - hy), (x + hx, y + hy)], status.colour().filled())
                }),
            )
            .map_err(err)?;
        // each exact end: a tick across its row at its exact position
        let mut ends: Vec<&(f64, f64, String)> = self.ends.iter().collect();
        ends.sort_by_key(|e| tick_rank(&e.2));
        chart
            .draw_series(ends.into_iter().map(|(y, x, set)| {
                PathElement::new(vec![(*x, y - hy), (*x, y + hy)], tick_colour(set).stroke_width(3))
            }))
            .map_err(err)?;
        if let Some((legend, shape, at)) = &plan.legend {
            legend.draw(root, *shape, *at)?;
        }
        Ok(())
    }
    fn data_csv(&self) -> Result<String, Error> {
        use super::{csv_field, csv_number};
        let mut out = format!("kind,{},{},status\n", csv_field(&self.y_name), csv_field(&self.x_name));
        for &(y, x, status) in &self.cells {
            out += &format!("cell,{},{},{}\n", csv_number(y), csv_number(x), csv_field(status.label(self.charmap)));
        }
        for (y, x, set) in &self.ends {
            out += &format!("exact end,{},{},{}\n", csv_number(*y), csv_number(*x), csv_field(set));
        }
        Ok(out)
    }
}
