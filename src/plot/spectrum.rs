//! Leading eigenvalue moduli against valence, one curve per branch: an
//! eigenvalue's branch is its Fourier block (k and n − k carry conjugate
//! values, so the block is named by min(k, n − k)) and its rank among that
//! block's distinct moduli, so curves follow eigenvalues through crossings
//! instead of jumping where the k-th largest changes hands (the papers plot
//! λ against n the same way). λ0 = 1 is left out: it would squeeze the rest.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{err, Figure, Style, FONT};
use crate::error::Error;

/// A curve of the figure: Fourier block min(k, n − k) and rank (0 = largest
/// modulus of that block, λ0 excluded).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Branch {
    pub block: usize,
    pub rank: usize,
}

impl Branch {
    pub fn name(&self) -> String {
        let ordinal = match self.rank {
            0 => String::new(),
            1 => ", 2nd".into(),
            2 => ", 3rd".into(),
            r => format!(", {}th", r + 1),
        };
        format!("block {}{ordinal}", self.block)
    }
}

/// One valence's points: its branches and their moduli.
pub type Row = (usize, Vec<(Branch, f64)>);

/// The rows of the figure: for each valence, the moduli of the distinct
/// eigenvalues after λ0 by branch (regular configuration, analysis
/// neighbourhood, Fourier blocks where the configuration is symmetric).
pub fn leading_moduli(
    scheme: &dyn crate::schemes::Scheme,
    valences: std::ops::RangeInclusive<usize>,
) -> Result<Vec<Row>, Error> {
    use crate::neighbourhood::{Configuration, NeighbourhoodKind};
    use crate::spectrum::{analyse, Options};
    valences
        .map(|n| {
            let config = Configuration::regular(scheme, n)?;
            let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
            let spec = analyse(scheme, &config, &opts)?.spectrum;
            let mut ranks: std::collections::BTreeMap<usize, usize> = Default::default();
            // eigenvalues come largest modulus first, so ranks count down a block
            // a value several blocks carry (merged into one eigenvalue) is a
            // point of each of their branches
            let mut points = Vec::new();
            for e in spec.eigenvalues.iter().skip(1) {
                let mut classes: Vec<usize> = e.blocks.iter().map(|&k| k.min(n - k)).collect();
                classes.sort_unstable();
                classes.dedup();
                for block in classes {
                    let rank = ranks.entry(block).or_insert(0);
                    points.push((Branch { block, rank: *rank }, e.modulus));
                    *rank += 1;
                }
            }
            Ok((n, points))
        })
        .collect()
}

pub struct SpectrumFigure {
    pub scheme: String,
    /// (valence, (branch, modulus) of the distinct eigenvalues after λ0)
    pub rows: Vec<Row>,
    /// how many branches to draw: those reaching the largest moduli
    pub count: usize,
    pub style: Style,
}

impl SpectrumFigure {
    /// The `count` branches whose largest modulus over the valences is
    /// largest, with their points, in that order.
    pub fn branches(&self) -> Vec<(Branch, Vec<(f64, f64)>)> {
        let mut all: std::collections::BTreeMap<Branch, Vec<(f64, f64)>> = Default::default();
        for (n, points) in &self.rows {
            for &(b, m) in points {
                all.entry(b).or_default().push((*n as f64, m));
            }
        }
        let top = |pts: &Vec<(f64, f64)>| pts.iter().map(|p| p.1).fold(0.0, f64::max);
        let mut list: Vec<(Branch, Vec<(f64, f64)>)> = all.into_iter().collect();
        list.sort_by(|a, b| top(&b.1).total_cmp(&top(&a.1)).then(a.0.cmp(&b.0)));
        list.truncate(self.count);
        list
    }
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
        let branches = self.branches();
        let top = branches.iter().flat_map(|b| b.1.iter().map(|p| p.1)).fold(0.0, f64::max);
        let font = |own: u32| self.style.font(own, BASE_FONT);
        let mut builder = ChartBuilder::on(root);
        if let Some(title) = self.style.title(format!("{}: leading eigenvalue moduli against valence", self.scheme)) {
            builder.caption(title, (FONT, font(26)));
        }
        let mut chart = builder
            .margin(20)
            .x_label_area_size(font(17) * 3 + 4)
            .y_label_area_size(font(17) * 4)
            .build_cartesian_2d(x_range, 0.0..(1.12 * top).max(1e-3))
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
        for (k, (branch, pts)) in branches.into_iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            let name =
                if branch == (Branch { block: 1, rank: 0 }) { "block 1 (λ1)".to_string() } else { branch.name() };
            chart
                .draw_series(LineSeries::new(pts.clone(), colour.stroke_width(2)))
                .map_err(err)?
                .label(name)
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
