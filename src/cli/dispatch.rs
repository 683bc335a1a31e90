//! The subcommands: `verify` first, the analysis commands through the front
//! door (`front_door`), and every other command here.

use crate::cli::args::SweepArgs;
use crate::cli::command_line::Command;
use crate::cli::commands::{out_text, parse_params};
use crate::error::Error;
use crate::io::print_json;
use crate::schemes;

/// Runs a command; Ok holds the exit status: 0, or 1 from a command whose
/// verdict did not hold (`verify`: a claim not as required; `spectrum
/// --certify`, `charmap --certify`: not proved unconditionally).
pub fn dispatch(cmd: Command) -> Result<i32, Error> {
    if let Command::Verify { paper, claims, json, junit, check_expected, certificates, slowest } = cmd {
        let opts = super::verify::VerifyOptions { json, junit, check_expected, certificates, slowest };
        return super::verify::run(paper, &claims, &opts);
    }
    // the analysis commands: one front door resolves the scheme and routes it by its domain
    if let Some(result) = super::front_door::dispatch(&cmd) {
        return result;
    }
    dispatch_other(cmd).map(|()| 0)
}

fn dispatch_other(cmd: Command) -> Result<(), Error> {
    match cmd {
        Command::Verify { .. } => unreachable!("verify is dispatched first"),
        Command::Spectrum { .. }
        | Command::Stencils(_)
        | Command::Matrix { .. }
        | Command::Charmap(_)
        | Command::Curvature(_) => unreachable!("the analysis commands go through the front door"),
        Command::Sweep(a) => sweep(&a),
        Command::ShapeChart(a) => super::shape_chart::run(&a),
        Command::Report { out } => {
            crate::report::check_destination(&out)?;
            let files = crate::report::build()?;
            crate::report::write(&out, &files)?;
            out_text(&format!("wrote {} files to {}\n", files.len(), out.display()))
        }
        Command::Schemes { files, json } => list_schemes(&files, json),
        Command::Refine { mesh, scheme, levels, params, output, fcv_scale, four_directional, vertex_params, tags } => {
            let opts = super::mesh_commands::MeshOptions { fcv_scale, four_directional, vertex_params, tags };
            super::mesh_commands::refine(&mesh, &scheme, levels, &params, &output, &opts)
        }
        Command::Curve { scheme, params, neighbourhood, json } => {
            super::mesh_commands::curve(&scheme, &params, &neighbourhood, json)
        }
        Command::Plot { what } => super::charmap_commands::plot(&what),
    }
}

fn list_schemes(files: &[std::path::PathBuf], json: bool) -> Result<(), Error> {
    #[derive(serde::Serialize)]
    struct Param {
        name: String,
        /// empty when the scheme's own rule applies
        default: String,
        min: f64,
        max: f64,
        description: String,
    }
    #[derive(serde::Serialize)]
    struct Entry {
        name: String,
        description: String,
        /// the file a user scheme was read from, and the topology it names
        file: Option<String>,
        topology: Option<&'static str>,
        params: Vec<Param>,
    }
    let builtin = |p: crate::schemes::ParamSpec| Param {
        name: p.name.into(),
        default: p.default.into(),
        min: p.min,
        max: p.max,
        description: p.description.into(),
    };
    let list: Vec<Entry> = if files.is_empty() {
        // every family from the one registry: mesh, then lattice, then curve schemes
        schemes::registry::entries()
            .into_iter()
            .map(|e| Entry {
                name: e.name().into(),
                description: e.description().into(),
                file: None,
                topology: None,
                params: e.params().into_iter().map(builtin).collect(),
            })
            .collect()
    } else {
        files
            .iter()
            .map(|f| {
                let def = crate::schemes::files::describe(f)?;
                Ok(Entry {
                    name: def.name,
                    description: def.description,
                    file: Some(f.display().to_string()),
                    topology: Some(def.topology),
                    params: def
                        .params
                        .into_iter()
                        .map(|p| Param {
                            name: p.name,
                            default: p.default.text,
                            min: p.min,
                            max: p.max,
                            description: p.description,
                        })
                        .collect(),
                })
            })
            .collect::<Result<_, Error>>()?
    };
    if json {
        return print_json(&list);
    }
    let w = list.iter().map(|e| e.name.chars().count() + 1).max().unwrap_or(0).max(16);
    let mut text = String::new();
    // names and descriptions come from files: shown with control characters escaped
    let shown = crate::io::printable;
    for e in &list {
        text += &format!("{:<w$} {}\n", shown(&e.name), shown(&e.description));
        if let (Some(f), Some(t)) = (&e.file, e.topology) {
            text += &format!("{:<w$} file {}, topology {t}\n", "", shown(f));
        }
        if e.params.is_empty() {
            text += &format!("{:<w$} (no parameters)\n", "");
        }
        for p in &e.params {
            let default = if p.default.is_empty() { "(scheme rule)" } else { p.default.as_str() };
            text += &format!(
                "{:<w$} --param {}=VALUE  default {}  range [{}, {}]  {}\n",
                "",
                shown(&p.name),
                shown(default),
                p.min,
                p.max,
                shown(&p.description)
            );
        }
    }
    out_text(&text)
}

/// `sweep --exact`: the exact sets of the swept parameter (`sweep::exact`).
fn sweep_exact(args: &SweepArgs) -> Result<(), Error> {
    use crate::sweep::exact::{run, ExactSweep};
    use crate::sweep::Grid;
    if args.tag.is_some() {
        return Err(Error::Input(
            "--exact is not available with --tag (the exact sets are those of an interior vertex's Fourier blocks); \
             sweep the tagged vertex's grid points without --exact"
                .into(),
        ));
    }
    if args.charmap || args.csv || args.plot.is_some() {
        return Err(Error::Input(
            "--exact gives the exact sets of convergence, spectral C¹ and (with --curvature) the curvature classes; \
             it takes none of --charmap, --csv, --plot"
                .into(),
        ));
    }
    let params = parse_params(&args.params)?;
    if params.iter().filter(|(_, v)| v.contains(':')).count() > 1 {
        return Err(Error::Input(
            "--exact sweeps one parameter; without --exact two swept parameters draw their plane".into(),
        ));
    }
    let Some((name, range)) = params.iter().find(|(_, v)| v.contains(':')) else {
        return Err(Error::Input("--exact needs a swept parameter --param NAME=START:END:STEP".into()));
    };
    // the grid's checks: the scheme, the valences, the range's ends
    let grid = Grid::parse(&args.scheme, &args.valences, args.faces.as_deref(), &params, false)?;
    let parts: Vec<&str> = range.split(':').collect();
    let exact = |t: &str| {
        crate::numeric::ParamValue::parse(t)?
            .exact
            .ok_or_else(|| Error::Input(format!("--exact: '{t}' is not an exact number (use 3/8 or 0.375)")))
    };
    let (lo, hi) = (exact(parts[0])?, exact(parts[1])?);
    if lo >= hi {
        return Err(Error::Input(format!("--exact: the range {range} is empty (need START < END)")));
    }
    let fixed = params.iter().filter(|(k, _)| k != name).cloned().collect();
    let sweep = ExactSweep {
        scheme: args.scheme.clone(),
        valences: grid.valences.clone(),
        param: name.clone(),
        lo,
        hi,
        fixed,
        faces: args.faces.clone(),
        certify: args.certify,
        curvature: args.curvature,
    };
    let started = std::time::Instant::now();
    let sets = run(&sweep)?;
    let seconds = started.elapsed().as_secs_f64();
    if args.json {
        #[derive(serde::Serialize)]
        struct Out<'a> {
            scheme: &'a str,
            parameter: &'a str,
            range: [String; 2],
            valences: &'a [crate::sweep::exact::ValenceSets],
            seconds: f64,
        }
        let out = Out {
            scheme: &args.scheme,
            parameter: name,
            range: [sweep.lo.to_string(), sweep.hi.to_string()],
            valences: &sets,
            seconds,
        };
        return print_json(&out);
    }
    let mut text = format!("exact sweep of {} over {name} in [{}, {}]\n", args.scheme, sweep.lo, sweep.hi);
    let show = |i: &crate::sweep::exact::ExactInterval| {
        format!(
            "{}{}, {}{}  ≈ {}{:.12}, {:.12}{}  [{}]",
            if i.from_closed { "[" } else { "(" },
            i.from.text,
            i.to.text,
            if i.to_closed { "]" } else { ")" },
            if i.from_closed { "[" } else { "(" },
            i.from.decimal,
            i.to.decimal,
            if i.to_closed { "]" } else { ")" },
            i.evidence
        )
    };
    for v in &sets {
        text.push_str(&format!("n = {}\n", v.valence));
        for (label, list) in [("convergent", &v.convergent), ("C1 spectral", &v.c1_spectral)] {
            if list.is_empty() {
                text.push_str(&format!("  {label}: nowhere in the range\n"));
            }
            for i in list {
                text.push_str(&format!("  {label}: {}\n", show(i)));
            }
        }
        if let Some(c) = &v.curvature {
            for (label, list) in
                [("curvature zero", &c.zero), ("curvature bounded", &c.bounded), ("curvature unbounded", &c.unbounded)]
            {
                if list.is_empty() {
                    text.push_str(&format!("  {label}: nowhere in the range\n"));
                }
                for i in list {
                    text.push_str(&format!("  {label}: {}\n", show(i)));
                }
            }
            for u in &c.undecided {
                text.push_str(&format!("  curvature class NOT DECIDED at {u}\n"));
            }
        }
        if v.exact {
            text.push_str("  endpoints: exact (the candidate set is complete)\n");
        } else {
            for why in &v.not_exact_because {
                text.push_str(&format!("  NOT PROVED EXACT: {why}\n"));
            }
        }
        // the curvature sets' own reasons (the first-order sets above stay exact)
        for why in v.curvature.iter().flat_map(|c| &c.not_exact_because) {
            text.push_str(&format!("  curvature sets NOT PROVED EXACT: {why}\n"));
        }
    }
    text.push_str(&format!("({seconds:.2} s)\n"));
    out_text(&text)
}

/// Two swept parameters (`sweep::region`): the verdicts on the (a, b) grid
/// at one valence, the exact ends in a at each b, and the figure.
fn sweep_region(args: &SweepArgs) -> Result<(), Error> {
    use crate::sweep::region::{run, RegionSweep};
    if args.json || args.csv || args.tag.is_some() || !args.bounds.is_empty() {
        return Err(Error::Input(
            "a sweep over two parameters prints a table and draws --plot; it takes none of --json, --csv, --tag, \
             --bound"
                .into(),
        ));
    }
    let params = parse_params(&args.params)?;
    let swept: Vec<&(String, String)> = params.iter().filter(|(_, v)| v.contains(':')).collect();
    let (x, y) = (swept[0].clone(), swept[1].clone());
    let valences = crate::sweep::parse_valences(&args.valences)?;
    let [valence] = valences[..] else {
        return Err(Error::Input(format!(
            "a sweep over two parameters draws one valence; use --valences N..N (got {})",
            args.valences
        )));
    };
    if args.figure.is_set() && args.plot.is_none() {
        return Err(Error::Input("the style flags shape the figure; give --plot FILE.svg|pdf|png too".into()));
    }
    if let Some(path) = &args.plot {
        super::charmap_commands::check_out(path)?;
    }
    let style = args.figure.style()?;
    let fixed = params.iter().filter(|(_, v)| !v.contains(':')).cloned().collect();
    let r = RegionSweep {
        scheme: args.scheme.clone(),
        valence,
        faces: args.faces.clone(),
        x: x.clone(),
        y: y.clone(),
        fixed,
        curvature: args.curvature,
        charmap: args.charmap,
        threads: args.threads as usize,
    };
    let started = std::time::Instant::now();
    let region = run(&r)?;
    let seconds = started.elapsed().as_secs_f64();
    if let Some(path) = &args.plot {
        let mut fig = crate::plot::region::RegionFigure::new(&args.scheme, valence, &x.0, &y.0, &region, args.charmap)?;
        fig.style = style;
        crate::plot::save(&fig, path)?;
        crate::plot::save_data(&fig, args.figure.data_path()?)?;
    }
    let mut text = format!(
        "sweep of {} at n = {valence} over {} = {} and {} = {}\n\
         evidence: grid points floating point (the single-point analysis at each); ends exact (sweep --exact in {} \
         at each {}, pieces in floating point)\n",
        args.scheme, x.0, x.1, y.0, y.1, x.0, y.0
    );
    for (yv, points) in &region.rows {
        let pass = crate::sweep::admissible(points);
        let runs: Vec<String> = pass.iter().map(|i| i.grid_points(None)).collect();
        text += &format!(
            "{} = {yv}: {} in {}\n",
            y.0,
            if args.curvature || args.charmap { "admissible" } else { "C1 spectral" },
            if runs.is_empty() { "no grid point".to_string() } else { runs.join(", ") }
        );
        let yf = crate::numeric::ParamValue::parse(yv)?.value;
        for e in region.ends.iter().filter(|e| e.y == yf) {
            text += &format!("  exact end of the {} set: {} = {}  ≈ {:.12}\n", e.set, x.0, e.text, e.x);
        }
    }
    if let Some(why) = &region.exact_missing {
        text += &format!("exact ends NOT AVAILABLE or not proved complete: {why}\n");
    }
    text += &format!("({seconds:.2} s)\n");
    out_text(&text)
}

fn sweep(args: &SweepArgs) -> Result<(), Error> {
    use crate::sweep::{admissible, convergent, run_on, Grid};
    let (scheme, json, csv) = (args.scheme.as_str(), args.json, args.csv);
    if json && csv {
        return Err(Error::Input("choose one of --json and --csv".into()));
    }
    if args.exact {
        return sweep_exact(args);
    }
    if args.certify {
        return Err(Error::Input("--certify decides the pieces of --exact; give --exact too".into()));
    }
    if args.params.iter().filter(|p| p.contains(':')).count() == 2 {
        return sweep_region(args);
    }
    if args.plot.is_some() && !args.curvature && !args.params.iter().any(|p| p.contains(':')) {
        return Err(Error::Input(
            "--plot needs a swept parameter NAME=START:END:STEP or --curvature (for valences alone use \
             `plot spectrum`)"
                .into(),
        ));
    }
    if !args.bounds.is_empty() && args.plot.is_none() {
        return Err(Error::Input("--bound is drawn on the figure; give --plot FILE.svg too".into()));
    }
    if args.figure.is_set() && args.plot.is_none() {
        return Err(Error::Input("the style flags shape the figure; give --plot FILE.svg|pdf|png too".into()));
    }
    if let Some(path) = &args.plot {
        super::charmap_commands::check_out(path)?;
    }
    let style = args.figure.style()?;
    if !args.charmap && (args.levels.is_some() || args.resolution.is_some()) {
        return Err(Error::Input(
            "--levels and --resolution set the characteristic-map check; give --charmap too".into(),
        ));
    }
    let tagging = args.tag.as_deref().map(crate::neighbourhood::Tagging::parse).transpose()?;
    if let (Some(t), true) = (tagging, args.curvature) {
        return Err(Error::Input(format!(
            "sweep --curvature --tag {}: curvature is not available at tagged vertices yet",
            t.name()
        )));
    }
    let mut grid = Grid::parse_at(
        scheme,
        &args.valences,
        args.faces.as_deref(),
        &parse_params(&args.params)?,
        args.charmap,
        tagging,
    )?;
    grid.set_charmap_options(args.levels, args.resolution)?;
    grid.curvature = args.curvature;
    let bounds = crate::plot::sweep::Bound::all_of(&grid, &args.bounds)?;
    let total = grid.len();
    // indicatif draws only when standard error is a terminal
    let bar = indicatif::ProgressBar::new(total as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} points, eta {eta}")
            .map_err(|e| Error::Message(e.to_string()))?
            .progress_chars("=> "),
    );
    // under a pipe (CI, a notebook) the bar draws nothing: a plain line at
    // most every 10 seconds (SUBDLAB_PROGRESS_SECONDS) says the sweep is
    // alive and how far it got
    let plain = !std::io::IsTerminal::is_terminal(&std::io::stderr());
    let every = std::env::var("SUBDLAB_PROGRESS_SECONDS")
        .ok()
        .and_then(|s| s.trim().parse::<f64>().ok())
        .filter(|s| s.is_finite() && *s >= 0.0)
        .map_or(std::time::Duration::from_secs(10), std::time::Duration::from_secs_f64);
    let started = std::time::Instant::now();
    let last_line = std::sync::Mutex::new(started);
    let progress = |done: usize, total: usize| {
        bar.set_position(done as u64);
        if plain {
            let mut last = last_line.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
            if last.elapsed() >= every {
                eprintln!("sweep: {done}/{total} points after {:.0} s", started.elapsed().as_secs_f64());
                *last = std::time::Instant::now();
            }
        }
    };
    let points = run_on(&grid, args.threads as usize, &progress)?;
    bar.finish_and_clear();
    let intervals = admissible(&points);
    let converging = convergent(&points);
    if let Some(path) = &args.plot {
        let name = grid.param.as_ref().map(|p| p.0.as_str());
        let mut fig = crate::plot::sweep::SweepFigure::new(scheme, name, &points, grid.charmap, bounds)?;
        fig.style = style;
        crate::plot::save(&fig, path)?;
        crate::plot::save_data(&fig, args.figure.data_path()?)?;
    }
    if json {
        #[derive(serde::Serialize)]
        struct Out<'a> {
            scheme: &'a str,
            parameter: Option<&'a str>,
            points: &'a [crate::sweep::Point],
            admissible: &'a [crate::sweep::Interval],
            convergent: &'a [crate::sweep::Interval],
        }
        let parameter = grid.param.as_ref().map(|p| p.0.as_str());
        return print_json(&Out {
            scheme,
            parameter,
            points: &points,
            admissible: &intervals,
            convergent: &converging,
        });
    }
    let name = grid.param.as_ref().map(|p| p.0.clone()).unwrap_or_default();
    // one row of cells per point; CSV joins them (the error, then the
    // columns added later, so the older columns keep their positions), the
    // table pads them
    const WIDTHS: [usize; 11] = [7, 10, 14, 14, 14, 14, 5, 5, 8, 14, 10];
    let mut text = String::new();
    if let (Some(t), false) = (grid.tagging, csv) {
        // what a tagged sweep decides, and on what evidence
        text += &format!(
            "{scheme} at a {} vertex (k: its sectors); verdict: the sector criterion (Zorin 2000){}, floating point \
             (relative tolerance 1e-9)\n",
            t.name(),
            if grid.charmap { " and the characteristic map on the raster" } else { ", spectral part only" }
        );
    }
    // `verdict`: PASSES or FAILS and the failing conditions (CSV: two
    // columns, the conditions joined by "; "; the table: the first
    // condition after the row, or the error that stopped the point)
    let mut print_row = |cells: &[String], error: &str, added: &[String], verdict: [&str; 2]| {
        if csv {
            let [word, why] = verdict.map(|t| t.replace(',', ";"));
            text += &format!("{},{},{},{word},{why}\n", cells.join(","), error.replace(',', ";"), added.join(","));
        } else {
            let all = cells.iter().chain(added);
            let padded: Vec<String> = all.zip(WIDTHS).map(|(c, w)| format!("{c:>w$}")).collect();
            let note = match (error.is_empty(), verdict) {
                (false, _) => format!("  ({error})"),
                (true, [word, ""]) => format!("  {word}"),
                (true, [word, why]) => format!("  {word}: {why}"),
            };
            text += &format!("{}{note}\n", padded.join(" "));
        }
    };
    if csv {
        print_row(
            &[format!("valence,{name},lambda0,lambda1,lambda2,lambda3,convergent,c1_spectral,charmap")],
            "error",
            &["curvature_class,lp_limit".into()],
            ["verdict", "failing"],
        );
    } else {
        let first = if grid.tagging.is_some() { "k" } else { "valence" };
        let head = [first, name.as_str(), "|λ0|", "|λ1|", "|λ2|", "|λ3|", "conv", "C1", "charmap"];
        // the table shows the curvature columns only when they were computed
        let added: &[String] = if grid.curvature { &["curvature".into(), "L_p: p <".into()] } else { &[] };
        print_row(&head.map(String::from), "", added, ["verdict", ""]);
    }
    for p in &points {
        let l = |k: usize| p.lambda.get(k).map(|x| crate::spectrum::fmt_f(*x)).unwrap_or_default();
        let cells = [
            p.valence.to_string(),
            p.param.clone().unwrap_or_default(),
            l(0),
            l(1),
            l(2),
            l(3),
            p.convergent.to_string(),
            p.c1_spectral.to_string(),
            p.charmap.map(|b| b.to_string()).unwrap_or_default(),
        ];
        // CSV: the L_p limit in full precision, empty for "every finite p" or
        // not computed; the table reads "any" for every finite p
        let lp = match (p.curvature_class, p.lp_limit) {
            (_, Some(x)) if csv => format!("{x}"),
            (_, Some(x)) => crate::spectrum::fmt_f(x),
            (Some(c), None) if !csv && c != crate::curvature::CurvatureClass::NotApplicable => "any".into(),
            _ => String::new(),
        };
        let added = [p.curvature_class.map(|c| c.name().to_string()).unwrap_or_default(), lp];
        let word = if p.admissible() { "PASSES" } else { "FAILS" };
        let why = if csv { p.failing.join("; ") } else { p.failing.first().cloned().unwrap_or_default() };
        print_row(
            &cells,
            p.error.as_deref().unwrap_or_default(),
            if csv || grid.curvature { &added } else { &[] },
            [word, &why],
        );
    }
    if !csv && grid.param.is_some() {
        // runs of grid points, not intervals: the true ends lie between a
        // run's end and the next grid point
        let step = grid.step();
        for (what, list) in
            [("convergent (λ0 = 1 simple and dominant)", &converging), ("admissible (every computed test)", &intervals)]
        {
            text += &format!("\ngrid points of {name} where the scheme is {what}:\n");
            for i in list {
                text += &format!("  valence {:>4}: {}\n", i.valence, i.grid_points(step.as_deref()));
            }
        }
    }
    out_text(&text)
}
