//! `subdlab shape-chart`: the shape chart of a scheme over a range of
//! valences (`shape_chart`), as a text chart, JSON or CSV rows, and figures.

use std::path::PathBuf;

use clap::Args;

use super::charmap_commands::check_out;
use super::commands::parse_params;
use crate::cli::args::{FigureArgs, SchemeSetup};
use crate::error::Error;
use crate::neighbourhood::Configuration;
use crate::schemes::registry;
use crate::schemes::route::{refusal, route, Analysis, Route};
use crate::shape_chart::{self, ChartOptions, ShapeChart, ValenceChart};

/// Largest valence of a chart: each valence costs dense projections of the
/// whole neighbourhood (cubic in its size).
const MAX_VALENCE: usize = 40;

#[derive(Args, Debug, Clone)]
pub struct ShapeChartArgs {
    /// scheme name (see `subdlab schemes`) or a scheme file (.toml, see schemes/)
    pub scheme: String,
    /// valence range A..B (default 3..12; with --faces, its length)
    #[arg(long)]
    pub valences: Option<String>,
    #[command(flatten)]
    pub setup: SchemeSetup,
    /// analysis steps of refinement of the ring samples (1 to 6, as `curvature --levels`;
    /// more levels: finer sign fractions, more time)
    #[arg(long, default_value_t = shape_chart::DEFAULT_LEVELS)]
    pub levels: usize,
    /// number of values of t, evenly from −1 to 1 (2 to 201)
    #[arg(long, default_value_t = 21)]
    pub t_samples: usize,
    /// number of angles θ over the fundamental range [0, min(180°, 360°/g)) (1 to 90)
    #[arg(long, default_value_t = shape_chart::DEFAULT_THETAS)]
    pub thetas: usize,
    /// finite steps m of h_m = S^m z / λ^(2m), comma-separated (0 to 60); m = ∞ is always added
    #[arg(long, default_value = "0,3,6")]
    pub steps: String,
    /// write the heat map (t across, valence down; panels m = first, middle step, ∞) to
    /// FILE.svg, FILE.pdf or FILE.png
    #[arg(short = 'o', long)]
    pub out: Option<PathBuf>,
    /// write the t × θ chart of one valence (--theta-valence) to FILE.svg|pdf|png
    #[arg(long, value_name = "FILE")]
    pub theta_out: Option<PathBuf>,
    /// the valence of the t × θ chart (default: the first of --valences)
    #[arg(long)]
    pub theta_valence: Option<usize>,
    /// angles of the t × θ chart (1 to 90)
    #[arg(long, default_value_t = 12)]
    pub theta_samples: usize,
    /// machine-readable JSON (every row and the charts' settings)
    #[arg(long)]
    pub json: bool,
    /// one comma-separated row per cell (n, faces, t, θ, m, ν*, g, jordan, divergent,
    /// sign fraction, residual, category)
    #[arg(long)]
    pub csv: bool,
    #[command(flatten)]
    pub style: FigureArgs,
}

/// The t samples: K values evenly from −1 to 1 (t = 0 included for odd K).
fn t_grid(k: usize) -> Vec<f64> {
    (0..k)
        .map(|i| (2.0 * i as f64 / (k - 1) as f64 - 1.0).clamp(-1.0, 1.0))
        .map(|t| if t.abs() < 1e-15 { 0.0 } else { t })
        .collect()
}

fn parse_steps(s: &str) -> Result<Vec<usize>, Error> {
    let mut out = Vec::new();
    for part in s.split(',') {
        let m: usize = part.trim().parse().map_err(|_| {
            Error::Input(format!("--steps must be comma-separated whole numbers, e.g. 0,3,6; got '{s}'"))
        })?;
        if m > 60 {
            return Err(Error::Input(format!("--steps: m must be at most 60, got {m}")));
        }
        if !out.contains(&m) {
            out.push(m);
        }
    }
    out.sort_unstable();
    Ok(out)
}

/// Checks every flag that needs no scheme; the valences and chart options.
fn checked(a: &ShapeChartArgs) -> Result<(Vec<usize>, ChartOptions), Error> {
    if a.json && a.csv {
        return Err(Error::Input("choose one of --json and --csv".into()));
    }
    if !(2..=201).contains(&a.t_samples) {
        return Err(Error::Input(format!("--t-samples must be between 2 and 201, got {}", a.t_samples)));
    }
    if !(1..=90).contains(&a.thetas) || !(1..=90).contains(&a.theta_samples) {
        return Err(Error::Input("--thetas and --theta-samples must be between 1 and 90".into()));
    }
    let valences = match (&a.valences, &a.setup.faces) {
        (Some(v), _) => crate::sweep::parse_valences(v)?,
        (None, Some(f)) => vec![f.chars().count()],
        (None, None) => (3..=12).collect(),
    };
    if let Some(f) = &a.setup.faces {
        if valences != [f.chars().count()] {
            return Err(Error::Input(format!(
                "--faces {f} fixes the valence to {}; use --valences {0}..{0} or leave --valences out",
                f.chars().count()
            )));
        }
    }
    if let Some(&n) = valences.iter().find(|&&n| n > MAX_VALENCE) {
        return Err(Error::Input(format!("valence {n} is above the shape chart's limit {MAX_VALENCE}")));
    }
    if a.theta_valence.is_some() && a.theta_out.is_none() && !a.json && !a.csv {
        return Err(Error::Input(
            "--theta-valence sets the t × θ chart; give --theta-out FILE (or --json/--csv)".into(),
        ));
    }
    if let Some(n) = a.theta_valence {
        if n > MAX_VALENCE {
            return Err(Error::Input(format!("--theta-valence {n} is above the shape chart's limit {MAX_VALENCE}")));
        }
        crate::neighbourhood::configuration::check_valence(n)?;
    }
    if a.style.is_set() && a.out.is_none() && a.theta_out.is_none() {
        return Err(Error::Input("the style flags shape a figure; give -o FILE or --theta-out FILE too".into()));
    }
    a.style.style()?;
    if a.style.data.is_some() && a.out.is_some() && a.theta_out.is_some() {
        return Err(Error::Input(
            "--data writes one figure's numbers: give it with -o or with --theta-out, not both \
             (--csv writes every row of both)"
                .into(),
        ));
    }
    for p in [&a.out, &a.theta_out].into_iter().flatten() {
        check_out(p)?;
    }
    let opts = ChartOptions {
        ts: t_grid(a.t_samples),
        thetas: a.thetas,
        steps: parse_steps(&a.steps)?,
        levels: a.levels,
        iterated: None,
    }
    .checked()?;
    Ok((valences, opts))
}

/// `subdlab shape-chart`.
pub fn run(a: &ShapeChartArgs) -> Result<(), Error> {
    let (valences, opts) = checked(a)?;
    let style = a.style.style()?;
    let params = parse_params(&a.setup.params)?;
    let built = registry::resolve(&a.scheme, &params)?;
    let domain = built.family();
    if let Route::Refused(why) = route(domain, Analysis::Curvature) {
        return Err(Error::Input(refusal(Analysis::Curvature, &a.scheme, domain, why).replacen(
            "`curvature`",
            "`shape-chart`",
            1,
        )));
    }
    let scheme = crate::schemes::on_mesh(built, &a.scheme)?;
    let configure = |n: usize| match &a.setup.faces {
        Some(f) => Configuration::with_faces(scheme.as_ref(), n, f),
        None => Configuration::regular(scheme.as_ref(), n),
    };
    let one = |n: usize, opts: &ChartOptions| -> Result<ValenceChart, Error> {
        let config = configure(n)?;
        shape_chart::chart(scheme.as_ref(), &config, opts)
    };
    let mut charts = Vec::new();
    for &n in &valences {
        charts.push(one(n, &opts)?);
    }
    let theta_chart = if a.theta_out.is_some() || a.theta_valence.is_some() {
        let n = a.theta_valence.unwrap_or(valences[0]);
        if a.setup.faces.is_some() && n != valences[0] {
            return Err(Error::Input(format!(
                "--faces fixes the valence to {}; --theta-valence {n} differs",
                valences[0]
            )));
        }
        Some(one(n, &ChartOptions { thetas: a.theta_samples, ..opts.clone() })?)
    } else {
        None
    };
    let chart = ShapeChart {
        scheme: a.scheme.clone(),
        params: params.iter().cloned().collect(),
        ts: opts.ts.clone(),
        steps: opts.steps.clone(),
        levels: opts.levels,
        valences: charts,
        theta_chart,
    };
    // --data goes with the heat map, or with the t × θ chart when that is the only figure
    let data = a.style.data_path()?;
    if let Some(out) = &a.out {
        let fig = crate::plot::shape_chart::HeatMap { chart: &chart, style: style.clone() };
        crate::plot::save(&fig, out)?;
        crate::plot::save_data(&fig, data)?;
    }
    if let (Some(out), Some(tc)) = (&a.theta_out, &chart.theta_chart) {
        let fig = crate::plot::shape_chart::ThetaChart { chart: &chart, valence: tc, style };
        crate::plot::save(&fig, out)?;
        if a.out.is_none() {
            crate::plot::save_data(&fig, data)?;
        }
    }
    if a.json {
        crate::io::print_json(&chart)
    } else if a.csv {
        crate::io::out(&csv(&chart))
    } else {
        crate::io::out(&text(&chart))
    }
}

/// Every row of every chart (the t × θ chart's rows last).
pub fn csv(c: &ShapeChart) -> String {
    let mut out =
        String::from("n,faces,t,theta_degrees,m,nu,nu_re,nu_im,g,jordan,divergent,sign_fraction,residual,c,category\n");
    let opt = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
    for r in c.valences.iter().chain(&c.theta_chart).flat_map(|v| &v.rows) {
        out += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            r.n,
            r.faces,
            r.t,
            r.theta_degrees,
            r.m,
            r.nu.clone().unwrap_or_default(),
            opt(r.nu_re),
            opt(r.nu_im),
            r.g,
            r.jordan,
            r.divergent,
            r.sign_fraction,
            r.residual,
            r.c,
            r.category.name()
        );
    }
    out
}

/// The text chart: one block per panel, valence down, t across, one letter
/// per cell (the worst over θ; `!` after it: divergent).
pub fn text(c: &ShapeChart) -> String {
    let mut out = format!("shape chart of {}  (levels {}, t from −1 to 1 across)\n", c.scheme, c.levels);
    out += "C correct shape  R right sign  F flat  D degenerate (t = 0)  M mixed sign  W wrong sign  \
            lower case: divergent (|ν*| > λ² or a Jordan chain at λ²)\n";
    for m in shape_chart::panels(&c.steps) {
        out += &format!("\nm = {}\n", if m == "inf" { "∞ (central shape)".to_string() } else { m.clone() });
        for v in &c.valences {
            out += &format!("  n = {:>2} {:>6}  ", v.n, short(&v.faces));
            if let Some(e) = &v.error {
                out += &format!("({e})\n");
                continue;
            }
            for &t in &c.ts {
                out.push(match shape_chart::worst_over_theta(v, t, &m) {
                    Some((cat, true)) => cat.letter().to_ascii_lowercase(),
                    Some((cat, false)) => cat.letter(),
                    None => '?',
                });
            }
            out.push('\n');
        }
    }
    out += "\n";
    for v in &c.valences {
        if let (Some(l), None) = (v.lambda, &v.error) {
            let inf: Vec<&shape_chart::Row> = v.rows.iter().filter(|r| r.central()).collect();
            let gmax = inf.iter().map(|r| r.g).fold(0.0, f64::max);
            out += &format!(
                "  n = {:>2}: λ = {}, largest g = |ν*|/λ² = {}\n",
                v.n,
                crate::spectrum::fmt_f(l),
                crate::spectrum::fmt_f(gmax)
            );
        }
    }
    out
}

fn short(faces: &str) -> String {
    if faces.chars().count() > 6 {
        faces.chars().take(5).chain(['…']).collect()
    } else {
        faces.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn t_grid_is_even_and_hits_zero() {
        let g = t_grid(21);
        assert_eq!(g.len(), 21);
        assert_eq!((g[0], g[10], g[20]), (-1.0, 0.0, 1.0));
        assert_eq!(t_grid(2), vec![-1.0, 1.0]);
    }

    #[test]
    fn steps_parse() {
        assert_eq!(parse_steps("6, 0,3,3").unwrap(), vec![0, 3, 6]);
        assert!(parse_steps("1,x").is_err() && parse_steps("61").is_err() && parse_steps("").is_err());
    }
}
