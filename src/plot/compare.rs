//! Comparison figures: one quantity of the leading spectrum (a modulus
//! |λk| or a ratio |λj| / |λk|, multiplicities counted as `sweep` counts
//! them) against the valence, one curve per scheme or parameter value, as
//! papers compare schemes. Each curve is a valence sweep (`sweep::run_on`),
//! so every point is exactly the single-point `spectrum` run.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::lines::{Line, ValenceChart};
use super::sweep::Bound;
use super::{Figure, Style};
use crate::error::Error;
use crate::sweep::{run_on, Grid, Point};

/// A curve of the comparison: a scheme (name or file) with fixed parameters,
/// from the command-line form `NAME[:P=V[,P=V...]]`.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveSpec {
    pub scheme: String,
    pub params: Vec<(String, String)>,
}

impl CurveSpec {
    pub fn parse(text: &str) -> Result<Self, Error> {
        let (scheme, rest) = match text.split_once(':') {
            Some((s, r)) => (s.trim(), Some(r)),
            None => (text.trim(), None),
        };
        if scheme.is_empty() {
            return Err(Error::Input(format!("curve '{text}' names no scheme (NAME[:P=V,...])")));
        }
        let params = rest
            .into_iter()
            .flat_map(|r| r.split(','))
            .map(|p| {
                p.split_once('=')
                    .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
                    .filter(|(k, v)| !k.is_empty() && !v.is_empty())
                    .ok_or_else(|| Error::Input(format!("curve '{text}': '{p}' is not of the form NAME=VALUE")))
            })
            .collect::<Result<_, _>>()?;
        Ok(CurveSpec { scheme: scheme.to_string(), params })
    }
    /// The legend text: the scheme, then its parameters.
    pub fn label(&self) -> String {
        if self.params.is_empty() {
            return self.scheme.clone();
        }
        let params: Vec<String> = self.params.iter().map(|(k, v)| format!("{k} = {v}")).collect();
        format!("{} ({})", self.scheme, params.join(", "))
    }
}

/// What is plotted: |λ_num| or |λ_num| / |λ_den|, indices into the moduli a
/// sweep point carries (λ0..λ3, with multiplicity).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quantity {
    pub num: usize,
    pub den: Option<usize>,
}

/// The moduli a sweep point carries (λ0..λ3).
const MODULI: usize = 4;

impl Quantity {
    /// `lambdaK` or `lambdaJ/lambdaK`, J and K in 0..=3.
    pub fn parse(text: &str) -> Result<Self, Error> {
        let bad = || {
            Error::Input(format!(
                "quantity '{text}' is not lambdaK or lambdaJ/lambdaK (J, K from 0 to {}), e.g. lambda1 or lambda3/lambda1",
                MODULI - 1
            ))
        };
        let index = |t: &str| -> Result<usize, Error> {
            let k: usize = t.trim().strip_prefix("lambda").ok_or_else(bad)?.parse().map_err(|_| bad())?;
            if k < MODULI {
                Ok(k)
            } else {
                Err(bad())
            }
        };
        match text.split_once('/') {
            Some((a, b)) => Ok(Quantity { num: index(a)?, den: Some(index(b)?) }),
            None => Ok(Quantity { num: index(text)?, den: None }),
        }
    }
    /// The axis text, e.g. "|λ3| / |λ1|".
    pub fn axis(&self) -> String {
        match self.den {
            None => format!("|λ{}|", self.num),
            Some(d) => format!("|λ{}| / |λ{d}|", self.num),
        }
    }
    /// The value at a sweep point (None: the point failed or lacks the moduli).
    pub fn of(&self, p: &Point) -> Option<f64> {
        if p.error.is_some() {
            return None;
        }
        let num = *p.lambda.get(self.num)?;
        match self.den {
            None => Some(num),
            Some(d) => p.lambda.get(d).filter(|x| **x > 0.0).map(|x| num / x),
        }
    }
}

/// The curves of a comparison: each spec swept over `valences` (text
/// `A..B`, as `sweep --valences`), the quantity at every point that could be
/// analysed (a point that could not is left out of its curve).
pub fn compare_lines(
    specs: &[CurveSpec],
    valences: &str,
    quantity: Quantity,
    threads: usize,
) -> Result<Vec<Line>, Error> {
    specs
        .iter()
        .map(|spec| {
            let grid = Grid::parse(&spec.scheme, valences, None, &spec.params, false)?;
            if grid.param.is_some() {
                return Err(Error::Input(format!(
                    "curve '{}' sweeps a parameter; give one curve per value",
                    spec.label()
                )));
            }
            let points = run_on(&grid, threads, &|_, _| {})?;
            let points = points.iter().filter_map(|p| Some((p.valence as f64, quantity.of(p)?))).collect();
            Ok(Line { label: spec.label(), points })
        })
        .collect()
}

pub struct CompareFigure {
    pub quantity: Quantity,
    pub lines: Vec<Line>,
    pub references: Vec<Bound>,
    /// first and last valence
    pub valences: (usize, usize),
    pub style: Style,
}

impl Figure for CompareFigure {
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
        let axis = self.quantity.axis();
        self.chart(&axis).draw(root)
    }
    fn data_csv(&self) -> Result<String, Error> {
        Ok(self.chart(&self.quantity.axis()).csv())
    }
}

impl CompareFigure {
    fn chart<'a>(&'a self, axis: &'a str) -> ValenceChart<'a> {
        ValenceChart {
            title: format!("{axis} against valence"),
            y_desc: axis,
            lines: &self.lines,
            references: &self.references,
            style: &self.style,
            valences: self.valences,
        }
    }
}
