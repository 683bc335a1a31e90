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

use super::{err, Figure, Style, FONT};
use crate::curvature::CurvatureClass;
use crate::error::Error;
use crate::sweep::Point;

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
    fn colour(self) -> RGBColor {
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
    fn label(self, charmap: bool) -> &'static str {
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
        // the legend gets its own strip under the chart so it never hides cells
        let statuses = self.statuses();
        let legend_rows = statuses.len().max(self.bounds.len()) as u32;
        let font = |own: u32| self.style.font(own, BASE_FONT);
        let row_height = font(17) + 9;
        let (w, h_px) = self.size();
        let legend_height = (30 + row_height * legend_rows).min(h_px / 2);
        let (plot_area, legend_area) = root.split_vertically(h_px - legend_height);
        let h = self.half_step();
        let (x0, x1) = self.cells.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| (a.min(c.1), b.max(c.1)));
        let (n0, n1) = self.cells.iter().fold((usize::MAX, 0), |(a, b), c| (a.min(c.0), b.max(c.0)));
        let caption = match (&self.param, self.curvature) {
            (Some(p), false) => format!("{}: admissible {p} per valence", self.scheme),
            (Some(p), true) => format!("{}: curvature class over {p} per valence", self.scheme),
            (None, _) => format!("{}: curvature class per valence", self.scheme),
        };
        let x_desc = match &self.param {
            Some(p) => format!("parameter {p}"),
            None => "(no swept parameter)".to_string(),
        };
        let swept = self.param.is_some();
        let mut builder = ChartBuilder::on(&plot_area);
        if let Some(title) = self.style.title(caption) {
            builder.caption(title, (FONT, font(26)));
        }
        let mut chart = builder
            .margin(20)
            .x_label_area_size(font(17) * 3 + 4)
            .y_label_area_size(font(17) * 4)
            .build_cartesian_2d(x0 - h..x1 + h, n0 as f64 - 0.5..n1 as f64 + 0.5)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(x_desc)
            // the mesh's default (11) with a swept parameter; none without one
            .x_labels(if swept { 11 } else { 0 })
            .y_desc("valence n")
            .label_style((FONT, font(17)))
            .axis_desc_style((FONT, font(20)))
            .x_label_formatter(&|x| super::tick_label(*x, x1 - x0))
            // rows are whole valences: a tick between two rows has no label
            .y_label_formatter(&|y| if (y - y.round()).abs() < 1e-9 { format!("{y:.0}") } else { String::new() })
            .draw()
            .map_err(err)?;
        // rows get thinner with many valences; keep a hairline gap between them
        let gap = if n1 - n0 < 40 { 0.06 } else { 0.0 };
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
        // legend: statuses in the left column, reference bounds in the right
        let text = TextStyle::from((FONT, font(17)).into_font()).color(&BLACK);
        let (row, size) = (row_height as i32, font(17) as i32);
        let row_y = |k: usize| 10 + row * k as i32;
        for (k, status) in statuses.iter().enumerate() {
            let y = row_y(k);
            legend_area
                .draw(&Rectangle::new([(90, y), (90 + size, y + size)], status.colour().filled()))
                .map_err(err)?;
            legend_area.draw(&Text::new(status.label(self.charmap), (100 + size, y), text.clone())).map_err(err)?;
        }
        let x_col = w as i32 / 2 + 40;
        for (k, bound) in self.bounds.iter().enumerate() {
            let y = row_y(k) + size / 2;
            let colour = BOUND_COLOURS[k % BOUND_COLOURS.len()];
            legend_area
                .draw(&PathElement::new(vec![(x_col, y), (x_col + 24, y)], colour.stroke_width(3)))
                .map_err(err)?;
            legend_area
                .draw(&Text::new(format!("bound {}", bound.label), (x_col + 32, y - size / 2), text.clone()))
                .map_err(err)?;
        }
        Ok(())
    }
}
