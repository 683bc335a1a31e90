//! Parameter and valence sweeps: the leading spectrum, the spectral verdict
//! and (optionally) the characteristic-map verdict at every point of a grid,
//! computed in parallel, identical to single-point runs (each point is an
//! ordinary `spectrum::analyse`), optionally the curvature class and L_p
//! limit of the second-order analysis (`Grid::curvature`, from the same
//! analysis), and the admissible intervals of the swept parameter per valence.
//! A grid may sit at a tagged vertex (`Grid::tagging`: boundary, corner,
//! crease, dart; issue 26): its valences are then the sectors of that
//! configuration and its verdict the sector criterion (Zorin 2000), exactly
//! as `subdlab spectrum --tag` decides it.

pub mod exact;
pub mod region;

use serde::Serialize;

use crate::charmap::{check_map, CharMapOptions};
use crate::curvature::{curvature_of_analysis, CurvatureClass, CurvatureOptions};
use crate::error::Error;
use crate::neighbourhood::{Configuration, NeighbourhoodKind, Tagging};
use crate::schemes;
use crate::spectrum::{analyse, Options};

/// Most grid points in one sweep (a bound on time, not a modelling limit).
pub const MAX_POINTS: usize = 100_000;

#[derive(Clone, Debug)]
pub struct Grid {
    pub scheme: String,
    pub valences: Vec<usize>,
    /// the swept parameter and its values (None: valences only)
    pub param: Option<(String, Vec<String>)>,
    /// other fixed parameters
    pub fixed: Vec<(String, String)>,
    pub charmap: bool,
    /// levels and resolution of the characteristic-map check (default: those
    /// of `subdlab charmap`)
    pub charmap_options: CharMapOptions,
    /// the face sequence around the centre (mixed-mesh schemes such as
    /// `four-three`, e.g. "QQTTT"); its length is the one valence of the grid
    pub faces: Option<String>,
    /// also run the second-order analysis at every point (opt-in: it costs
    /// about as much as a `subdlab curvature --no-exact` run per point, far
    /// more than the spectrum alone)
    pub curvature: bool,
    /// a tagged vertex instead of an interior one (`--tag`): the valences
    /// count the sectors of that configuration (an open fan's from 1)
    pub tagging: Option<Tagging>,
}

#[derive(Clone, Debug, Serialize)]
pub struct Point {
    pub valence: usize,
    /// the swept parameter's value (text as given)
    pub param: Option<String>,
    /// moduli of λ0..λ3 (with multiplicity), as far as they exist
    pub lambda: Vec<f64>,
    /// λ0 = 1 simple and strictly dominant
    pub convergent: bool,
    pub c1_spectral: bool,
    /// regular and injective characteristic map (when asked for)
    pub charmap: Option<bool>,
    /// why the point could not be analysed, if it could not
    pub error: Option<String>,
    /// the curvature class, exactly `subdlab curvature --no-exact` at this
    /// point (when asked for: `Grid::curvature`)
    pub curvature_class: Option<CurvatureClass>,
    /// principal curvatures are in L_p for p < lp_limit (unbounded class
    /// with |μ| > λ²); null: every finite p, or not computed
    pub lp_limit: Option<f64>,
    /// the conditions that fail, in the order they were checked: the
    /// spectral verdict's failing reasons, then the characteristic map's
    /// (when checked), or why the point could not be analysed; empty when
    /// the point passes every computed test
    pub failing: Vec<String>,
}

impl Grid {
    /// A grid from the command-line form: a valence range `A..B` and
    /// `NAME=VALUE` (fixed) or `NAME=START:END:STEP` (swept, at most one)
    /// parameters, and optionally a face sequence around the centre (then the
    /// valence range must be that one valence, its length). The scheme and the
    /// first and last swept values are checked here, so a bad grid fails
    /// before the long run.
    pub fn parse(
        scheme: &str,
        valences: &str,
        faces: Option<&str>,
        params: &[(String, String)],
        charmap: bool,
    ) -> Result<Grid, Error> {
        Grid::parse_at(scheme, valences, faces, params, charmap, None)
    }

    /// [`Grid::parse`] at a tagged vertex (`tagging`; None: interior): the
    /// valence range then counts that configuration's sectors, each checked
    /// as `--tag` checks one (an open fan from 1, a crease ray inside the fan).
    pub fn parse_at(
        scheme: &str,
        valences: &str,
        faces: Option<&str>,
        params: &[(String, String)],
        charmap: bool,
        tagging: Option<Tagging>,
    ) -> Result<Grid, Error> {
        let mut param = None;
        let mut fixed = Vec::new();
        for (k, v) in params {
            if v.contains(':') {
                if param.is_some() {
                    return Err(Error::Input("only one parameter can be swept here (NAME=START:END:STEP; two draw their plane at one valence)".into()));
                }
                param = Some((k.clone(), parse_range(v)?));
            } else {
                fixed.push((k.clone(), v.clone()));
            }
        }
        let valences = match tagging {
            None => parse_valences(valences)?,
            Some(t) => parse_sectors(valences, t)?,
        };
        if let Some(f) = faces {
            if valences != [f.chars().count()] {
                return Err(Error::Input(format!(
                    "--faces {f} fixes the valence to {}; use --valences {0}..{0}",
                    f.chars().count()
                )));
            }
        }
        let faces = faces.map(str::to_string);
        let charmap_options = CharMapOptions::default();
        let mut grid = Grid {
            scheme: scheme.to_string(),
            valences,
            param,
            fixed,
            charmap,
            charmap_options,
            faces,
            curvature: false,
            tagging,
        };
        let mut first = grid.fixed.clone();
        if let Some((name, values)) = &grid.param {
            first.push((name.clone(), values[0].clone()));
            let mut last = grid.fixed.clone();
            last.push((name.clone(), values[values.len() - 1].clone()));
            schemes::resolve(scheme, &last)?;
        }
        let first = schemes::resolve(scheme, &first)?;
        grid.configuration(first.as_ref(), grid.valences[0])?;
        grid.charmap_options.levels = crate::charmap::default_levels(first.as_ref());
        Ok(grid)
    }

    /// The configuration of a point at valence n: regular, or the face
    /// sequence, at an interior or a tagged vertex.
    pub fn configuration(&self, scheme: &dyn schemes::Scheme, n: usize) -> Result<Configuration, Error> {
        match (&self.faces, self.tagging) {
            (faces, Some(t)) => Configuration::tagged(scheme, n, faces.as_deref(), t),
            (Some(f), None) => Configuration::with_faces(scheme, n, f),
            (None, None) => Configuration::regular(scheme, n),
        }
    }

    /// Levels and resolution of the characteristic-map check, validated;
    /// each left out keeps `subdlab charmap`'s default (levels: the scheme
    /// host's, [`crate::charmap::default_levels`], set by [`Grid::parse`]).
    pub fn set_charmap_options(&mut self, levels: Option<usize>, resolution: Option<usize>) -> Result<(), Error> {
        let d = CharMapOptions::default();
        let levels = levels.unwrap_or(self.charmap_options.levels);
        self.charmap_options = CharMapOptions::checked(levels, resolution.unwrap_or(d.resolution))?;
        Ok(())
    }

    /// Number of grid points.
    pub fn len(&self) -> usize {
        self.valences.len() * self.param.as_ref().map_or(1, |p| p.1.len())
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// A reference bound `EXPR` in the valence `n` (alias `k`) and the fixed
    /// parameters, evaluated at every valence of the grid (for figures: e.g. a
    /// bound a paper states, drawn against the computed intervals).
    pub fn bound(&self, text: &str) -> Result<Vec<(usize, f64)>, Error> {
        expression_over_valences(text, &self.fixed, &self.valences)
    }
}

/// An expression `EXPR` in the valence `n` (alias `k`) and the parameters
/// `params`, evaluated at each of `valences`: the one reading of a reference
/// curve (`sweep --bound`, `plot spectrum --reference`, `plot compare
/// --reference`). Each value must be a finite real number.
pub fn expression_over_valences(
    text: &str,
    params: &[(String, String)],
    valences: &[usize],
) -> Result<Vec<(usize, f64)>, Error> {
    use crate::numeric::{expr::Expr, ParamValue};
    let expr = Expr::parse(text).map_err(|e| Error::Input(format!("reference '{text}': {e}")))?;
    let mut env = crate::numeric::expr::Env::new();
    for (k, v) in params {
        env.insert(k.clone(), ParamValue::parse(v)?);
    }
    valences
        .iter()
        .map(|&n| {
            for var in ["n", "k"] {
                env.insert(var.into(), ParamValue::from_ratio(n as i64, 1));
            }
            let z = expr.eval(&env).map_err(|e| Error::Input(format!("reference '{text}' at n = {n}: {e}")))?;
            if !z.re.is_finite() || z.im.abs() > 1e-12 * (1.0 + z.re.abs()) {
                return Err(Error::Input(format!("reference '{text}' is not a finite real number at n = {n}")));
            }
            Ok((n, z.re))
        })
        .collect()
}

/// `"a:b:step"` → the values a, a + step, ..., up to b (exact decimal text).
pub fn parse_range(s: &str) -> Result<Vec<String>, Error> {
    let parts: Vec<&str> = s.split(':').collect();
    let [a, b, step] = parts[..] else { return Err(Error::Input(format!("'{s}' is not of the form START:END:STEP"))) };
    let p = |t: &str| crate::numeric::ParamValue::parse(t).map_err(|e| Error::Input(format!("'{s}': {e}")));
    let (a, b, step) = (p(a)?, p(b)?, p(step)?);
    let (Some(qa), Some(qb), Some(qs)) = (a.exact, b.exact, step.exact) else {
        return Err(Error::Input(format!("'{s}': use exact decimals or fractions")));
    };
    if qs <= crate::numeric::exact::q(0, 1) || qb < qa {
        return Err(Error::Input(format!("'{s}': need START <= END and STEP > 0")));
    }
    let count = ((&qb - &qa) / &qs).floor();
    let count: usize =
        num_traits::ToPrimitive::to_usize(&count.to_integer()).ok_or_else(|| Error::Input("too many values".into()))?;
    if count >= MAX_POINTS {
        return Err(Error::Input(format!("'{s}' has more than {MAX_POINTS} values")));
    }
    Ok((0..=count).map(|k| (qa.clone() + qs.clone() * crate::numeric::exact::q(k as i64, 1)).to_string()).collect())
}

/// `"3..100"` → 3, 4, ..., 100.
pub fn parse_valences(s: &str) -> Result<Vec<usize>, Error> {
    let (a, b) = valence_bounds(s)?;
    crate::neighbourhood::configuration::check_valence(a)?;
    crate::neighbourhood::configuration::check_valence(b)?;
    check_work(s, a, b)?;
    Ok((a..=b).collect())
}

/// `"1..8"` → 1, 2, ..., 8: the sector counts of a tagged configuration,
/// each as `--tag` accepts it (`configuration::check_tagged`: an open fan
/// has at least 1 sector, a closed one 3, a crease's second ray K < n).
pub fn parse_sectors(s: &str, tagging: Tagging) -> Result<Vec<usize>, Error> {
    let (a, b) = valence_bounds(s)?;
    // the bounds first: a huge range is refused before it is walked
    crate::neighbourhood::configuration::check_tagged(b, tagging)?;
    check_work(s, a, b)?;
    for n in a..=b {
        crate::neighbourhood::configuration::check_tagged(n, tagging)?;
    }
    Ok((a..=b).collect())
}

/// The two ends of `A..B`, A <= B.
fn valence_bounds(s: &str) -> Result<(usize, usize), Error> {
    let (a, b) =
        s.split_once("..").ok_or_else(|| Error::Input(format!("valence range '{s}' is not of the form A..B")))?;
    let (a, b): (usize, usize) = (
        a.trim().parse().map_err(|_| Error::Input(format!("bad valence range '{s}'")))?,
        b.trim().parse().map_err(|_| Error::Input(format!("bad valence range '{s}'")))?,
    );
    if a > b {
        return Err(Error::Input(format!("bad valence range '{s}'")));
    }
    Ok((a, b))
}

/// Refuses a range whose points would cost more than [`MAX_VALENCE_SUM`].
fn check_work(s: &str, a: usize, b: usize) -> Result<(), Error> {
    // a point costs about linearly in n, so a sweep about the sum of its
    // valences: refused up front past that of 3..1000 (half a minute on
    // one core), not after minutes of work
    let work: u128 = (a as u128 + b as u128) * (b - a + 1) as u128 / 2;
    if work > MAX_VALENCE_SUM {
        return Err(Error::Input(format!(
            "valence range '{s}' sums to {work} over its points, above a sweep's limit {MAX_VALENCE_SUM} (that of \
             3..1000; a point costs about linearly in n): split the range, or use `spectrum` at single valences"
        )));
    }
    Ok(())
}

/// The largest sum of the valences of one sweep: that of 3..1000.
pub const MAX_VALENCE_SUM: u128 = (3 + 1000) * 998 / 2;

/// One point, exactly as `subdlab spectrum` (and `charmap`) would compute it.
pub fn point(grid: &Grid, n: usize, value: Option<&str>) -> Point {
    let mut params = grid.fixed.clone();
    if let (Some((name, _)), Some(v)) = (&grid.param, value) {
        params.push((name.clone(), v.to_string()));
    }
    let run = || -> Result<Point, Error> {
        let scheme = schemes::resolve(&grid.scheme, &params)?;
        let config = grid.configuration(scheme.as_ref(), n)?;
        let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
        let analysis = analyse(scheme.as_ref(), &config, &opts)?;
        let s = &analysis.spectrum;
        let lambda = s
            .eigenvalues
            .iter()
            .flat_map(|e| std::iter::repeat_n(e.modulus, e.algebraic_multiplicity))
            .take(4)
            .collect();
        let mut failing = s.verdict.failures.clone();
        let charmap = if grid.charmap && s.verdict.c1_spectral {
            // the same analysis `subdlab charmap` starts from (analysis neighbourhood, no exact stage)
            let m = check_map(scheme.as_ref(), &analysis, &grid.charmap_options)?;
            let ok = m.regular && m.injective;
            if !ok {
                failing.push(format!("characteristic map: {}", map_failure(&m)));
            }
            Some(ok)
        } else if grid.charmap {
            Some(false)
        } else {
            None
        };
        // the second-order analysis of the same analysis, as `subdlab
        // curvature --no-exact` computes it (no figures, no exact stage)
        let (curvature_class, lp_limit) = if grid.curvature {
            let opts = CurvatureOptions { exact: false, ..CurvatureOptions::default() };
            let c = curvature_of_analysis(scheme.as_ref(), &analysis, &opts)?;
            (Some(c.class), c.lp_limit)
        } else {
            (None, None)
        };
        Ok(Point {
            valence: n,
            param: value.map(str::to_string),
            lambda,
            convergent: s.verdict.convergent,
            c1_spectral: s.verdict.c1_spectral,
            charmap,
            error: None,
            curvature_class,
            lp_limit,
            failing,
        })
    };
    run().unwrap_or_else(|e| Point {
        valence: n,
        param: value.map(str::to_string),
        lambda: Vec::new(),
        convergent: false,
        c1_spectral: false,
        charmap: None,
        error: Some(e.to_string()),
        curvature_class: None,
        lp_limit: None,
        failing: vec![e.to_string()],
    })
}

/// Why a characteristic map failed, in one line: no map at all (its
/// explanation), or which of regularity and injectivity failed.
fn map_failure(m: &crate::charmap::CharMap) -> String {
    // a crease vertex: each side's own map, the failing ones named
    if let Some(c) = m.crease.as_ref().filter(|c| !c.sides.is_empty()) {
        return c
            .sides
            .iter()
            .filter(|side| !(side.regular && side.injective))
            .map(|side| {
                let t = side.tagging.as_deref().unwrap_or("");
                format!("{}: {}", t.find("side ").map_or(t, |k| &t[k..]), map_failure(side))
            })
            .collect::<Vec<_>>()
            .join("; ");
    }
    match (m.ring.is_some(), m.regular, m.injective) {
        (false, _, _) => m.explanation.clone(),
        (true, false, false) => "neither regular nor injective".into(),
        (true, false, true) => "not regular".into(),
        _ => "not injective".into(),
    }
}

/// Every point of the grid, in order, on all available cores.
pub fn run(grid: &Grid, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<Point>, Error> {
    run_on(grid, 0, progress)
}

/// Every point of the grid, in order, on `threads` worker threads (0: one per
/// available core). The points do not depend on the thread count.
pub fn run_on(grid: &Grid, threads: usize, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Vec<Point>, Error> {
    let values: Vec<Option<String>> = match &grid.param {
        Some((_, v)) => v.iter().cloned().map(Some).collect(),
        None => vec![None],
    };
    let tasks: Vec<(usize, Option<String>)> =
        grid.valences.iter().flat_map(|&n| values.iter().map(move |v| (n, v.clone()))).collect();
    if tasks.len() > MAX_POINTS {
        return Err(Error::Input(format!("{} grid points, above the supported {MAX_POINTS}", tasks.len())));
    }
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    let threads = if threads == 0 { cores } else { threads }.min(tasks.len().max(1));
    let next = std::sync::atomic::AtomicUsize::new(0);
    let done = std::sync::atomic::AtomicUsize::new(0);
    let mut out: Vec<Option<Point>> = vec![None; tasks.len()];
    let results: Vec<Vec<(usize, Point)>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|_| {
                scope.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let Some((n, v)) = tasks.get(k) else { break };
                        mine.push((k, point(grid, *n, v.as_deref())));
                        let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                        progress(d, tasks.len());
                    }
                    mine
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap_or_default()).collect()
    });
    for (k, p) in results.into_iter().flatten() {
        out[k] = Some(p);
    }
    out.into_iter().map(|p| p.ok_or_else(|| Error::Message("a sweep worker stopped".to_string()))).collect()
}

/// Maximal runs of consecutive swept values, per valence, where a test passes.
/// `from` and `to` are the first and the last grid point of the run, not the
/// ends of the true interval (which lies between them and their outside
/// neighbours on the grid): [`Interval::grid_points`] says so in text.
#[derive(Clone, Debug, Serialize)]
pub struct Interval {
    pub valence: usize,
    pub from: String,
    pub to: String,
}

impl Interval {
    /// The run as what it is, "grid points A..B (step S)": the grid points
    /// that pass, never a closed interval [A, B] (the true set of passing
    /// values is open at a strict bound and reaches past the grid points).
    pub fn grid_points(&self, step: Option<&str>) -> String {
        let step = step.map(|s| format!(" (step {s})")).unwrap_or_default();
        if self.from == self.to {
            format!("grid point {}{step}", self.from)
        } else {
            format!("grid points {}..{}{step}", self.from, self.to)
        }
    }
}

impl Grid {
    /// The step of the swept parameter (exact text), when it has two values or more.
    pub fn step(&self) -> Option<String> {
        let (_, values) = self.param.as_ref()?;
        let exact = |s: &String| crate::numeric::ParamValue::parse(s).ok().and_then(|p| p.exact);
        match (values.first().and_then(exact), values.get(1).and_then(exact)) {
            (Some(a), Some(b)) => Some((b - a).to_string()),
            _ => None,
        }
    }
}

impl Point {
    /// Passes every computed test: spectral C^1, and the characteristic map when computed.
    pub fn admissible(&self) -> bool {
        self.error.is_none() && self.c1_spectral && self.charmap.unwrap_or(true)
    }
}

/// The intervals where every computed test passes.
pub fn admissible(points: &[Point]) -> Vec<Interval> {
    intervals(points, Point::admissible)
}

/// The intervals where the scheme converges (λ0 = 1 simple and dominant).
pub fn convergent(points: &[Point]) -> Vec<Interval> {
    intervals(points, |p| p.error.is_none() && p.convergent)
}

fn intervals(points: &[Point], pass: impl Fn(&Point) -> bool) -> Vec<Interval> {
    let mut out = Vec::new();
    let mut current: Option<Interval> = None;
    for p in points {
        let v = p.param.clone().unwrap_or_default();
        match (&mut current, pass(p)) {
            (Some(c), true) if c.valence == p.valence => c.to = v,
            (_, true) => {
                out.extend(current.take());
                current = Some(Interval { valence: p.valence, from: v.clone(), to: v });
            }
            (_, false) => out.extend(current.take()),
        }
    }
    out.extend(current);
    out
}
