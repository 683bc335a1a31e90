//! Leading eigenvalue moduli against valence: the subdominant λ1 and the next
//! distinct moduli, one line each, with 1 (the dominant eigenvalue) for scale.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{err, Figure, Style, FONT};
use crate::error::Error;

/// The rows of the figure: for each valence, the moduli of the distinct
/// eigenvalues after λ0 (regular configuration, analysis neighbourhood).
pub fn leading_moduli(
    scheme: &dyn crate::schemes::Scheme,
    valences: std::ops::RangeInclusive<usize>,
) -> Result<Vec<(usize, Vec<f64>)>, Error> {
    use crate::neighbourhood::{Configuration, NeighbourhoodKind};
    use crate::spectrum::{analyse, Options};
    valences
        .map(|n| {
            let config = Configuration::regular(scheme, n)?;
            let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
            let spec = analyse(scheme, &config, &opts)?.spectrum;
            Ok((n, spec.eigenvalues.iter().skip(1).map(|e| e.modulus).collect()))
        })
        .collect()
}

pub struct SpectrumFigure {
    pub scheme: String,
    /// (valence, moduli of the distinct eigenvalues after λ0, largest first)
    pub rows: Vec<(usize, Vec<f64>)>,
    /// how many moduli per valence to draw
    pub count: usize,
    pub style: Style,
}

/// Base font size of the figure (tick labels), which `Style::font_size` replaces.
const BASE_FONT: u32 = 17;

const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
];

fn series_name(k: usize) -> String {
    match k {
        0 => "λ1 (subdominant)".into(),
        k => format!("distinct eigenvalue {} after λ0 (modulus)", k + 1),
    }
}

impl Figure for SpectrumFigure {
    fn size(&self) -> (u32, u32) {
        self.style.size((1000, 650))
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE).map_err(err)?;
        let (n0, n1) = (
            self.rows.first().map(|r| r.0).ok_or_else(|| Error::Input("no valences to plot".into()))?,
            self.rows.last().map(|r| r.0).ok_or_else(|| Error::Input("no valences to plot".into()))?,
        );
        let x_range = if n1 > n0 { n0 as f64 - 0.5..n1 as f64 + 0.5 } else { n0 as f64 - 1.0..n0 as f64 + 1.0 };
        let font = |own: u32| self.style.font(own, BASE_FONT);
        let mut builder = ChartBuilder::on(root);
        if let Some(title) = self.style.title(format!("{}: leading eigenvalue moduli against valence", self.scheme)) {
            builder.caption(title, (FONT, font(26)));
        }
        let mut chart = builder
            .margin(20)
            .x_label_area_size(font(17) * 3 + 4)
            .y_label_area_size(font(17) * 4)
            .build_cartesian_2d(x_range, 0.0..1.05)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("valence n")
            .y_desc("|λ|")
            .label_style((FONT, font(17)))
            .axis_desc_style((FONT, font(20)))
            .x_label_formatter(&|x| format!("{x:.0}"))
            .draw()
            .map_err(err)?;
        chart
            .draw_series(LineSeries::new(vec![(n0 as f64 - 1.0, 1.0), (n1 as f64 + 1.0, 1.0)], BLACK.stroke_width(1)))
            .map_err(err)?
            .label("λ0 = 1")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
        for k in 0..self.count {
            let colour = COLOURS[k % COLOURS.len()];
            let pts: Vec<(f64, f64)> =
                self.rows.iter().filter_map(|(n, m)| m.get(k).map(|v| (*n as f64, *v))).collect();
            chart
                .draw_series(LineSeries::new(pts.clone(), colour.stroke_width(2)))
                .map_err(err)?
                .label(series_name(k))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
            chart.draw_series(pts.into_iter().map(|p| Circle::new(p, 3, colour.filled()))).map_err(err)?;
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
