//! Leading eigenvalue moduli against valence, one curve per branch: an
//! eigenvalue's branch is its Fourier block (k and n − k carry conjugate
//! values, so the block is named by min(k, n − k)) and its rank among that
//! block's distinct moduli, so curves follow eigenvalues through crossings
//! instead of jumping where the k-th largest changes hands (the papers plot
//! λ against n the same way). λ0 = 1 is left out: it would squeeze the rest.
//! Reference curves (expressions in n, e.g. a closed form a paper states)
//! are drawn dashed over the branches.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::lines::{Line, ValenceChart};
use super::sweep::Bound;
use super::{Figure, Style};
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
    /// reference curves over the same valences, drawn dashed
    pub references: Vec<Bound>,
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

impl Figure for SpectrumFigure {
    fn size(&self) -> (u32, u32) {
        self.style.size(super::lines::SIZE)
    }
    fn dpi(&self) -> Option<f64> {
        self.style.dpi
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        let lines = self.lines();
        self.chart(&lines)?.draw(root)
    }
    fn data_csv(&self) -> Result<String, Error> {
        let lines = self.lines();
        Ok(self.chart(&lines)?.csv())
    }
}

impl SpectrumFigure {
    /// The drawn curves: the branches, λ1's named as such.
    fn lines(&self) -> Vec<Line> {
        self.branches()
            .into_iter()
            .map(|(branch, points)| Line {
                label: if branch == (Branch { block: 1, rank: 0 }) {
                    "block 1 (λ1)".to_string()
                } else {
                    branch.name()
                },
                points,
            })
            .collect()
    }
    fn chart<'a>(&'a self, lines: &'a [Line]) -> Result<ValenceChart<'a>, Error> {
        let (n0, n1) = (
            self.rows.first().map(|r| r.0).ok_or_else(|| Error::Input("no valences to plot".into()))?,
            self.rows.last().map(|r| r.0).ok_or_else(|| Error::Input("no valences to plot".into()))?,
        );
        Ok(ValenceChart {
            title: format!("{}: leading eigenvalue moduli against valence", self.scheme),
            y_desc: "|λ|",
            lines,
            references: &self.references,
            style: &self.style,
            valences: (n0, n1),
        })
    }
}
