//! The `central-shape` check: a stated shape property at the extraordinary
//! point ("for convex input the surface is flat there", "saddles come out
//! elliptic") against the shape chart (`crate::shape_chart`).
//!
//! The inputs are the chart's quadratics q_{t,θ} over the characteristic
//! map's control net, for the claim's values of t and angles θ over the
//! fundamental range; the statement is that the central shape h_∞ of every
//! input (`quantifier = "every"`) or of at least one (`"some"`), over every
//! listed configuration, falls in one of the stated categories (correct,
//! right-sign, flat, degenerate, mixed-sign, wrong-sign).
//!
//! Every input's category is decided by two routes that share only the
//! subdivision matrix, the affine projections and the ring measures:
//! (a) the eigen route: ν* (the largest eigenvalue below λ whose component
//! shows on the ring, a Jordan chain's top where there is one), g = |ν*|/λ²
//! (flat when g < 1); (b) the deflated iteration h_(m+1) = (I − P_affine)
//! S h_m / λ² to steps m1 < m2 (no eigenvector of ν* enters): flat when the
//! non-affine part of h_m decays (rate below 1 − `classify::RATE_TOL`),
//! otherwise h_m2's category. An input where the routes disagree is
//! undecided; the claim is decided only by inputs where they agree, and is
//! INCONCLUSIVE when the undecided inputs could change the verdict.

use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::spectra::{subject_config, Cache};
use crate::claims::schedule;
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::shape_chart::{chart, classify, Category, ChartOptions, ValenceChart};
use crate::spectrum::fmt_f;

/// Steps of the deflated iteration: far enough that the eigenvalues below
/// ν* have faded (their share shrinks like (|ν₂|/|ν*|)^m), near enough that
/// a growing input stays far from overflow (g^m2 < 10^40 for g < 2.6).
const ITERATED: (usize, usize) = (48, 96);

/// `shape = "flat"` or `shape = ["right-sign", "correct"]` (any of them).
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum ShapeSpec {
    One(String),
    Any(Vec<String>),
}

/// The central shapes of the inputs q_{t,θ} (`t`: the values of t, each in
/// [−1, 1]; `thetas`: angles per t over the fundamental range, default 3)
/// fall in the stated categories (`shape`), for every input or for some
/// (`quantifier`, default "every"); `levels` refines the ring (default 2,
/// as `subdlab shape-chart`).
#[derive(Clone, Debug, Deserialize)]
pub struct CentralShapeCheck {
    #[serde(flatten)]
    pub subject: Subject,
    pub t: Vec<f64>,
    pub shape: ShapeSpec,
    #[serde(default)]
    pub quantifier: Option<String>,
    #[serde(default)]
    pub thetas: Option<usize>,
    #[serde(default)]
    pub levels: Option<usize>,
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Quantifier {
    Every,
    Some,
}

impl CentralShapeCheck {
    fn categories(&self) -> Result<Vec<Category>, Error> {
        let names = match &self.shape {
            ShapeSpec::One(s) => vec![s.clone()],
            ShapeSpec::Any(v) => v.clone(),
        };
        if names.is_empty() {
            vacuous("shape")?;
        }
        names
            .iter()
            .map(|s| {
                Category::ALL.into_iter().find(|c| c.name() == s).ok_or_else(|| {
                    let all: Vec<&str> = Category::ALL.iter().map(|c| c.name()).collect();
                    Error::Claim(format!("shape '{s}': the categories are {}", all.join(", ")))
                })
            })
            .collect()
    }

    fn quantifier(&self) -> Result<Quantifier, Error> {
        match self.quantifier.as_deref() {
            None | Some("every") => Ok(Quantifier::Every),
            Some("some") => Ok(Quantifier::Some),
            Some(q) => Err(Error::Claim(format!("quantifier '{q}': use \"every\" or \"some\""))),
        }
    }

    fn options(&self) -> ChartOptions {
        ChartOptions {
            ts: self.t.clone(),
            thetas: self.thetas.unwrap_or(crate::shape_chart::DEFAULT_THETAS),
            steps: Vec::new(),
            levels: self.levels.unwrap_or(crate::shape_chart::DEFAULT_LEVELS),
            iterated: Some(ITERATED),
        }
    }
}

impl CheckKind for CentralShapeCheck {
    const KEYS: &'static [&'static str] = &["t", "shape", "quantifier", "thetas", "levels"];

    fn validate(&self) -> Result<(), Error> {
        if self.t.is_empty() {
            vacuous("t")?;
        }
        self.categories()?;
        self.quantifier()?;
        if self.subject.neighbourhood.as_deref().is_some_and(|k| k != "analysis") {
            return Err(Error::Claim(
                "the central-shape check uses the analysis neighbourhood; leave 'neighbourhood' out".into(),
            ));
        }
        self.options().checked().map(|_| ()).map_err(|e| Error::Claim(e.to_string()))
    }

    fn evaluate(&self, _cache: &mut Cache) -> Result<Finding, Error> {
        self.validate()?;
        let wanted = self.categories()?;
        let quantifier = self.quantifier()?;
        let opts = self.options();
        let configurations = self.subject.configurations()?;
        if configurations.is_empty() {
            return Err(Error::Claim("no valences given".into()));
        }
        let charts = schedule::each_configuration(&configurations, |s, n| {
            let (scheme, config) = subject_config(s, n)?;
            chart(scheme.as_ref(), &config, &opts)
        });
        let mut cells = Vec::new();
        for ((n, subject), c) in configurations.iter().zip(charts) {
            let c = c?;
            if let Some(why) = &c.error {
                return Err(Error::Undecided(format!("{}: no central shape ({why})", subject.label(*n))));
            }
            cells.extend(cells_of(&subject.label(*n), &c)?);
        }
        decide(&cells, &wanted, quantifier, &opts)
    }
}

/// One input at one configuration, by both routes.
struct Cell {
    label: String,
    t: f64,
    theta: f64,
    eigen: Category,
    divergent: bool,
    g: f64,
    nu: String,
    sign_fraction: f64,
    iterated: Category,
    rate: f64,
}

impl Cell {
    /// Whether the two routes give the same answer to the claim: both
    /// categories stated, or neither (they may still name different
    /// categories, e.g. a Jordan chain's slow 1/m approach seen as mixed
    /// by one route and wrong-sign by the other when neither is stated).
    fn decided(&self, wanted: &[Category]) -> bool {
        wanted.contains(&self.eigen) == wanted.contains(&self.iterated)
    }

    fn describe(&self) -> String {
        format!(
            "{} t = {} θ = {}°: {}{} (ν* = {}, g = {}, sign fraction {}); iterated {} (rate {})",
            self.label,
            fmt_f(self.t),
            fmt_f(self.theta),
            self.eigen.name(),
            if self.divergent { ", divergent" } else { "" },
            self.nu,
            fmt_f(self.g),
            fmt_f(self.sign_fraction),
            self.iterated.name(),
            fmt_f(self.rate)
        )
    }
}

fn cells_of(label: &str, c: &ValenceChart) -> Result<Vec<Cell>, Error> {
    let mut out = Vec::new();
    for it in &c.iterated {
        let row = c
            .rows
            .iter()
            .find(|r| r.central() && r.t == it.t && r.theta_degrees == it.theta_degrees)
            .ok_or_else(|| Error::Undecided(format!("{label}: no central shape of t = {}", it.t)))?;
        out.push(Cell {
            label: label.to_string(),
            t: it.t,
            theta: it.theta_degrees,
            eigen: row.category,
            divergent: row.divergent,
            g: row.g,
            nu: row.nu.clone().unwrap_or_else(|| "none".into()),
            sign_fraction: row.sign_fraction,
            iterated: it.category,
            rate: it.rate,
        });
    }
    if out.is_empty() {
        return Err(Error::Undecided(format!("{label}: the chart has no inputs")));
    }
    Ok(out)
}

/// "3 right-sign, 2 mixed-sign": the categories of `cells` counted.
fn tally<'a>(cells: impl Iterator<Item = &'a Cell>) -> String {
    let mut counts: Vec<(Category, usize)> = Vec::new();
    for c in cells {
        match counts.iter_mut().find(|(k, _)| *k == c.eigen) {
            Some((_, k)) => *k += 1,
            None => counts.push((c.eigen, 1)),
        }
    }
    counts.sort();
    counts.iter().map(|(c, k)| format!("{k} {}", c.name())).collect::<Vec<_>>().join(", ")
}

fn decide(cells: &[Cell], wanted: &[Category], quantifier: Quantifier, opts: &ChartOptions) -> Result<Finding, Error> {
    let names: Vec<&str> = wanted.iter().map(|c| c.name()).collect();
    let stated = format!(
        "{} input's central shape {}",
        match quantifier {
            Quantifier::Every => "every",
            Quantifier::Some => "some",
        },
        names.join(" or ")
    );
    let admissible = |c: &Cell| wanted.contains(&c.eigen);
    let decided: Vec<&Cell> = cells.iter().filter(|c| c.decided(wanted)).collect();
    let undecided: Vec<&Cell> = cells.iter().filter(|c| !c.decided(wanted)).collect();
    let differing = cells.iter().filter(|c| c.eigen != c.iterated).count();
    let computed = format!(
        "{} of {} inputs decided: {}{}",
        decided.len(),
        cells.len(),
        tally(decided.iter().copied()),
        if undecided.is_empty() { String::new() } else { format!("; {} undecided", undecided.len()) }
    );
    let computed = if differing > undecided.len() {
        format!(
            "{computed} ({} inputs named a different category by the iteration, on the same side of the statement)",
            differing - undecided.len()
        )
    } else {
        computed
    };
    let evidence = format!(
        "floating point, two routes per input: (a) eigen-projection (ν*, g = |ν*|/λ², flat when g < 1 − {}) and (b) deflated iteration to steps {} and {} (flat when the growth rate of the non-affine part is below 1 − {}); K's sign from least-squares quadratics on the characteristic ring refined {} levels (right sign ≥ {} of the ring area, wrong ≤ {}); {} angles θ per t",
        classify::G_TOL,
        ITERATED.0,
        ITERATED.1,
        classify::RATE_TOL,
        opts.levels,
        classify::RIGHT_SIGN,
        classify::WRONG_SIGN,
        opts.thetas
    );
    let per_label = summary(cells, wanted);
    let (holds, why) = match quantifier {
        Quantifier::Every => match decided.iter().find(|c| !admissible(c)) {
            Some(bad) => (Some(false), format!("not {}: {}", names.join(" or "), bad.describe())),
            None if undecided.is_empty() => (Some(true), format!("all {} inputs {}", cells.len(), names.join(" or "))),
            None => (None, String::new()),
        },
        Quantifier::Some => match decided.iter().find(|c| admissible(c)) {
            Some(good) => (Some(true), format!("for instance {}", good.describe())),
            None if undecided.is_empty() => {
                (Some(false), format!("none of the {} inputs is {}", cells.len(), names.join(" or ")))
            }
            None => (None, String::new()),
        },
    };
    match holds {
        Some(h) => Ok(Finding::new(
            h,
            stated,
            computed,
            format!("{why}; per configuration: {per_label}; evidence: {evidence}"),
        )),
        None => Err(Error::Undecided(format!(
            "the routes disagree on {} inputs, which decide the claim: {}; evidence: {evidence}",
            undecided.len(),
            undecided.iter().take(3).map(|c| c.describe()).collect::<Vec<_>>().join(" | ")
        ))),
    }
}

/// "n = 3: 4 right-sign, 8 mixed-sign (g = 1) | n = 5: ..." over the
/// configurations (g = |ν*|/λ² over the inputs: below 1 flat, above 1
/// divergent).
fn summary(cells: &[Cell], wanted: &[Category]) -> String {
    let mut labels: Vec<&str> = Vec::new();
    for c in cells {
        if !labels.contains(&c.label.as_str()) {
            labels.push(&c.label);
        }
    }
    labels
        .iter()
        .map(|l| {
            let mine: Vec<&Cell> = cells.iter().filter(|c| c.label == *l).collect();
            let gmin = mine.iter().map(|c| c.g).fold(f64::INFINITY, f64::min);
            let gmax = mine.iter().map(|c| c.g).fold(0.0, f64::max);
            let g = if gmax - gmin <= classify::G_TOL * gmax {
                format!("g = {}", fmt_f(gmax))
            } else {
                format!("g from {} to {}", fmt_f(gmin), fmt_f(gmax))
            };
            let divergent = mine.iter().filter(|c| c.divergent).count();
            let undecided = mine.iter().filter(|c| !c.decided(wanted)).count();
            format!(
                "{l}: {} ({g}{}{})",
                tally(mine.iter().copied()),
                if divergent > 0 { format!(", {divergent} divergent") } else { String::new() },
                if undecided > 0 { format!(", {undecided} undecided") } else { String::new() }
            )
        })
        .collect::<Vec<_>>()
        .join(" | ")
}
