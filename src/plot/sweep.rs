//! Admissible parameter intervals of a sweep: one row per valence, one cell
//! per swept value, coloured by the strongest test the point passes, with
//! optional reference bounds (curves in the valence, e.g. a paper's stated
//! bound) drawn across the rows so the computed intervals can be compared
//! with the stated ones at a glance. When the sweep computed the curvature
//! class (`subdlab sweep --curvature`), the cells that pass the first-order
//! tests are coloured by their class instead (zero, bounded, unbounded), and
//! a sweep over valences alone draws one cell per valence.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::MARGIN;
use super::layout::{
    draw_lines, fit, plan_with_legend, region_area, title_block, Axis, Legend, LegendPosition, Marker, NoFit, Swatch,
    Ticks,
};
use super::{err, Figure, Style};
use crate::curvature::CurvatureClass;
use crate::error::Error;
use crate::sweep::Point;
use plotters::style::text_anchor::HPos;

/// What a grid point passed, in increasing order of strength.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CellStatus {
    /// the analysis failed (e.g. the rules are undefined for this value)
    Error,
    /// λ0 = 1 is not simple and strictly dominant
    NotConvergent,
    /// converges, fails Reif's spectral C¹ test
    NotSpectral,
    /// passes the spectral test, the characteristic map is not regular and injective
    SpectralOnly,
    /// passes every computed test
    Admissible,
    /// admissible, curvature class zero (a flat spot for generic data)
    CurvatureZero,
    /// admissible, curvature class bounded
    CurvatureBounded,
    /// admissible, curvature class unbounded
    CurvatureUnbounded,
}

impl CellStatus {
    pub fn of(p: &Point) -> Self {
        match (p.error.is_some(), p.c1_spectral, p.charmap) {
            (true, _, _) => CellStatus::Error,
            (false, false, _) if !p.convergent => CellStatus::NotConvergent,
            (false, false, _) => CellStatus::NotSpectral,
            (false, true, Some(false)) => CellStatus::SpectralOnly,
            (false, true, _) => match p.curvature_class {
                None => CellStatus::Admissible,
                Some(CurvatureClass::Zero) => CellStatus::CurvatureZero,
                Some(CurvatureClass::Bounded) => CellStatus::CurvatureBounded,
                Some(CurvatureClass::Unbounded) => CellStatus::CurvatureUnbounded,
                // spectral C¹ but not applicable: the curvature analysis's own
                // characteristic-map check failed
                Some(CurvatureClass::NotApplicable) => CellStatus::SpectralOnly,
            },
        }
    }
    pub(crate) fn colour(self) -> RGBColor {
        match self {
            CellStatus::Error => RGBColor(190, 190, 190),
            CellStatus::NotConvergent => RGBColor(214, 96, 77),
            CellStatus::NotSpectral => RGBColor(244, 190, 186),
            CellStatus::SpectralOnly => RGBColor(253, 208, 120),
            CellStatus::Admissible => RGBColor(102, 178, 102),
            CellStatus::CurvatureZero => RGBColor(107, 174, 214),
            CellStatus::CurvatureBounded => RGBColor(35, 139, 69),
            CellStatus::CurvatureUnbounded => RGBColor(128, 100, 180),
        }
    }
    pub(crate) fn label(self, charmap: bool) -> &'static str {
        match self {
            CellStatus::Error => "not analysable",
            CellStatus::NotConvergent => "does not converge (λ0 = 1 not simple and dominant)",
            CellStatus::NotSpectral => "converges, fails the spectral C¹ test",
            CellStatus::SpectralOnly => "spectral C¹, characteristic map fails",
            CellStatus::Admissible if charmap => "spectral C¹ and injective characteristic map",
            CellStatus::Admissible => "spectral C¹",
            CellStatus::CurvatureZero => "C¹, curvature class zero (|μ| < λ²: flat spot)",
            CellStatus::CurvatureBounded => "C¹, curvature class bounded (|μ| = λ², no Jordan block)",
            CellStatus::CurvatureUnbounded => "C¹, curvature class unbounded (|μ| > λ² or Jordan block at λ²)",
        }
    }
}

/// A reference curve: its legend text and its value per valence.
pub struct Bound {
    pub label: String,
    pub values: Vec<(usize, f64)>,
}

impl Bound {
    /// The reference bounds `texts` (expressions in n) over the grid's valences.
    pub fn all_of(grid: &crate::sweep::Grid, texts: &[String]) -> Result<Vec<Bound>, Error> {
        Self::over(texts, &grid.fixed, &grid.valences)
    }
    /// The reference curves `texts` (expressions in n and `params`) at `valences`.
    pub fn over(texts: &[String], params: &[(String, String)], valences: &[usize]) -> Result<Vec<Bound>, Error> {
        texts
            .iter()
            .map(|t| {
                Ok(Bound { label: t.clone(), values: crate::sweep::expression_over_valences(t, params, valences)? })
            })
            .collect()
    }
}

pub struct SweepFigure {
    pub scheme: String,
    /// the swept parameter (None: valences only, one cell per valence)
    pub param: Option<String>,
    /// (valence, swept value, status), the swept values in increasing order
    pub cells: Vec<(usize, f64, CellStatus)>,
    /// whether the characteristic map was part of the test
    pub charmap: bool,
    pub bounds: Vec<Bound>,
    /// the cells are coloured by curvature class (the points carry one)
    pub curvature: bool,
    pub style: Style,
}

impl SweepFigure {
    /// The figure of a sweep's points. With a swept parameter every point
    /// must carry a swept value; without one (`param` None) only a sweep
    /// with curvature classes is drawn, one cell per valence.
    pub fn new(
        scheme: &str,
        param: Option<&str>,
        points: &[Point],
        charmap: bool,
        bounds: Vec<Bound>,
    ) -> Result<Self, Error> {
        let curvature = points.iter().any(|p| p.curvature_class.is_some());
        if param.is_none() && !curvature {
            return Err(Error::Input("the figure needs a swept parameter (or curvature classes)".into()));
        }
        let cells = points
            .iter()
            .map(|p| {
                let v = match param {
                    Some(_) => {
                        let text = p
                            .param
                            .as_deref()
                            .ok_or_else(|| Error::Input("the figure needs a swept parameter".into()))?;
                        crate::numeric::ParamValue::parse(text)?.value
                    }
                    None => 0.0,
                };
                Ok((p.valence, v, CellStatus::of(p)))
            })
            .collect::<Result<Vec<_>, Error>>()?;
        if cells.is_empty() {
            return Err(Error::Input("no sweep points to plot".into()));
        }
        Ok(SweepFigure {
            scheme: scheme.to_string(),
            param: param.map(str::to_string),
            cells,
            charmap,
            bounds,
            curvature,
            style: Style::default(),
        })
    }

    /// The statuses that occur, strongest first.
    fn statuses(&self) -> Vec<CellStatus> {
        let mut shown: Vec<CellStatus> = Vec::new();
        for c in &self.cells {
            if !shown.contains(&c.2) {
                shown.push(c.2);
            }
        }
        shown.sort_by_key(|s| std::cmp::Reverse(*s as u8));
        shown
    }

    /// Half the distance between neighbouring swept values (cell half-width).
    fn half_step(&self) -> f64 {
        let mut xs: Vec<f64> = self.cells.iter().map(|c| c.1).collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        let step = xs.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
        if step.is_finite() && step > 0.0 {
            step / 2.0
        } else {
            0.5
        }
    }
}

const BOUND_COLOURS: [RGBColor; 4] =
    [RGBColor(0, 0, 0), RGBColor(31, 80, 200), RGBColor(160, 30, 160), RGBColor(120, 70, 20)];

/// Base font size of the figure (tick labels), which `Style::font_size` replaces.
const BASE_FONT: u32 = 17;

/// Everything placed before drawing (`layout::AxesFigurePlan`).
use super::layout::AxesFigurePlan as Plan;

impl SweepFigure {
    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        let h = self.half_step();
        let (x0, x1) = self.cells.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| (a.min(c.1), b.max(c.1)));
        let (n0, n1) = self.cells.iter().fold((usize::MAX, 0), |(a, b), c| (a.min(c.0), b.max(c.0)));
        (self.style.xlim.unwrap_or((x0 - h, x1 + h)), self.style.ylim.unwrap_or((n0 as f64 - 0.5, n1 as f64 + 0.5)))
    }
    fn legend(&self, size: f64) -> Legend {
        let mut entries: Vec<(Swatch, String)> = self
            .statuses()
            .into_iter()
            .map(|s| {
                (Swatch::Patch { fill: s.colour(), edge: RGBColor(90, 90, 90) }, s.label(self.charmap).to_string())
            })
            .collect();
        for (k, bound) in self.bounds.iter().enumerate() {
            let colour = BOUND_COLOURS[k % BOUND_COLOURS.len()];
            entries.push((
                Swatch::Line { colour, width: 3, dash: None, marker: Marker::None },
                format!("bound {}", bound.label),
            ));
        }
        Legend { entries, size }
    }
    fn plan(&self, scale: f64, x_fmt: &dyn Fn(f64) -> String) -> Result<Plan, NoFit> {
        let font = |own: u32| self.style.font(own, BASE_FONT) as f64 * scale;
        let (w, h) = self.size();
        let (w, h) = (w as f64, h as f64);
        let caption = match (&self.param, self.curvature) {
            (Some(p), false) => format!("{}: admissible {p} per valence", self.scheme),
            (Some(p), true) => format!("{}: curvature class over {p} per valence", self.scheme),
            (None, _) => format!("{}: curvature class per valence", self.scheme),
        };
        let title_size = font(26);
        let (title, title_h) = title_block(self.style.title(caption), title_size, w)?;
        // the legend's own place is outside the grid, so it never hides cells
        let position = self.style.legend.unwrap_or(LegendPosition::Auto);
        let (xr, yr) = self.ranges();
        let x = match &self.param {
            Some(p) => Axis { range: xr, desc: Some(format!("parameter {p}")), ticks: Ticks::Auto(x_fmt) },
            None => Axis { range: xr, desc: Some("(no swept parameter)".into()), ticks: Ticks::None },
        };
        let y = Axis { range: yr, desc: Some("valence n".into()), ticks: Ticks::Integers };
        let margins = (MARGIN, MARGIN + title_h, MARGIN, MARGIN);
        let (legend, region, axes) =
            plan_with_legend(self.legend(font(17)), position, (w, h), margins, &x, &y, (font(17), font(20)), false)?;
        Ok(Plan { title, title_size, legend, region, axes })
    }
}

impl Figure for SweepFigure {
    fn size(&self) -> (u32, u32) {
        self.style.size((1100, 760))
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
        let span = xr.1 - xr.0 - 2.0 * self.half_step();
        let x_fmt = |x: f64| super::tick_label(x, span);
        let size = self.size();
        let plan = fit(self.style.font(BASE_FONT, BASE_FONT) as f64, size, |scale| self.plan(scale, &x_fmt))?;
        draw_lines(root, &plan.title, plan.title_size, (size.0 as f64 / 2.0, MARGIN), HPos::Center)?;
        let area = region_area(root, plan.region);
        plan.axes.draw(&area, xr, yr, false)?;
        let mut chart = plan.axes.chart(&area, xr, yr)?;
        let h = self.half_step();
        // rows get thinner with many valences; keep a hairline gap between them
        let gap = if yr.1 - yr.0 < 41.0 { 0.06 } else { 0.0 };
        chart
            .draw_series(self.cells.iter().map(|&(n, x, status)| {
                let n = n as f64;
                Rectangle::new([(x - h, n - 0.5 + gap), (x + h, n + 0.5 - gap)], status.colour().filled())
            }))
            .map_err(err)?;
        for (k, bound) in self.bounds.iter().enumerate() {
            // a vertical tick through each valence row, joined row to row
            let mut path = Vec::new();
            for &(n, v) in &bound.values {
                path.push((v, n as f64 - 0.5));
                path.push((v, n as f64 + 0.5));
            }
            let colour = BOUND_COLOURS[k % BOUND_COLOURS.len()];
            chart.draw_series(std::iter::once(PathElement::new(path, colour.stroke_width(2)))).map_err(err)?;
        }
        if let Some((legend, shape, at)) = &plan.legend {
            legend.draw(root, *shape, *at)?;
        }
        Ok(())
    }
    fn data_csv(&self) -> Result<String, Error> {
        use super::{csv_field, csv_number};
        let mut out = String::from("kind,valence,value,status\n");
        for &(n, x, status) in &self.cells {
            let value = if self.param.is_some() { csv_number(x) } else { String::new() };
            out += &format!("cell,{n},{value},{}\n", csv_field(status.label(self.charmap)));
        }
        for bound in &self.bounds {
            for &(n, v) in &bound.values {
                out += &format!("bound,{n},{},{}\n", csv_number(v), csv_field(&format!("bound {}", bound.label)));
            }
        }
        Ok(out)
    }
}
