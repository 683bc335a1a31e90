//! The subcommands.

use super::{AnalysisArgs, Command};
use crate::error::Error;
use crate::io::{print_json, write_atomic};
use crate::matrix::export::{to_matrix_market, MatrixJson};
use crate::neighbourhood::{Configuration, NeighbourhoodKind};
use crate::schemes::{self, Scheme};
use crate::spectrum::stencils::stencils;
use crate::spectrum::{analyse, Analysis, Method, Options, Spectrum};

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

/// An analysis command on the mesh pipeline, with the scheme the front door
/// resolved (a mesh scheme, or a lattice scheme on oriented quad meshes).
/// Ok holds the exit status.
pub(super) fn mesh_analysis(cmd: &Command, scheme: Box<dyn Scheme>) -> Result<i32, Error> {
    match cmd {
        Command::Spectrum { common: a, certify: true, certificate } => {
            certified_spectrum(a, scheme, certificate.as_deref())
        }
        Command::Charmap(a) => super::charmap_commands::charmap(a, scheme),
        Command::Curvature(a) => super::curvature::run(a, scheme).map(|()| 0),
        Command::Spectrum { common: a, certify: false, .. } => {
            let (_, analysis) = run_analysis(a, scheme)?;
            if a.json {
                print_json(&analysis.spectrum)?;
            } else {
                out_text(&spectrum_table(&analysis.spectrum))?;
            }
            Ok(0)
        }
        Command::Stencils(a) => {
            let (_, analysis) = run_analysis(a, scheme)?;
            let st = stencils(&analysis.spectrum)?;
            if a.json {
                print_json(&st)?;
            } else {
                out_text(&stencil_table(&st))?;
            }
            Ok(0)
        }
        Command::Matrix { common, format, output } => {
            let format = matrix_format(format.as_deref(), common.json)?;
            let (scheme, analysis) = run_analysis(common, scheme)?;
            let text = match format {
                "mtx" => to_matrix_market(
                    &analysis.matrix,
                    &format!(
                        "subdlab local subdivision matrix: scheme {} valence {} faces {} neighbourhood {}",
                        scheme.name(),
                        common.config.valence,
                        analysis.spectrum.faces,
                        kind_name(analysis.spectrum.neighbourhood)
                    ),
                ),
                "json" => {
                    let m = &analysis.matrix;
                    let j = MatrixJson {
                        scheme: scheme.name(),
                        valence: common.config.valence,
                        neighbourhood: m.kind,
                        size: m.size(),
                        labels: m.labels.iter().map(|l| l.name.as_str()).collect(),
                        vertices: &m.labels,
                        matrix: m.to_dense_f64(),
                        exact: analysis.exact_matrix.as_ref().map(|q| {
                            (0..q.size()).map(|i| (0..q.size()).map(|j| q.get(i, j).to_string()).collect()).collect()
                        }),
                    };
                    crate::io::json_text(&j)? + "\n"
                }
                other => return Err(Error::Input(format!("unknown matrix format '{other}'; use mtx or json"))),
            };
            match output {
                Some(p) => write_atomic(p, text.as_bytes())?,
                None => out_text(&text)?,
            }
            Ok(0)
        }
        _ => Err(Error::Input("not an analysis command".into())),
    }
}

/// The exit status of a command that prints a certified verdict, with the
/// meaning `verify` gives it: 0 PROVED unconditionally; 1 anything else
/// (DISPROVED, NOT PROVED, or PROVED only given premises confirmed to
/// interval overlap, which a certified claim reads as INCONCLUSIVE). Errors
/// exit 2 before a verdict exists.
pub(super) fn certified_status(verdict: &crate::certify::Verdict, conditional: bool) -> i32 {
    match verdict {
        crate::certify::Verdict::Proved if !conditional => 0,
        _ => 1,
    }
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
        Command::Report { out } => {
            crate::report::check_destination(&out)?;
            let files = crate::report::build()?;
            crate::report::write(&out, &files)?;
            out_text(&format!("wrote {} files to {}\n", files.len(), out.display()))
        }
        Command::Schemes { files, json } => list_schemes(&files, json),
        Command::Refine { mesh, scheme, levels, params, output, fcv_scale, four_directional, vertex_params } => {
            let opts = super::mesh_commands::MeshOptions { fcv_scale, four_directional, vertex_params };
            super::mesh_commands::refine(&mesh, &scheme, levels, &params, &output, &opts)
        }
        Command::Curve { scheme, params, neighbourhood, json } => {
            super::mesh_commands::curve(&scheme, &params, &neighbourhood, json)
        }
        Command::Plot { what } => super::charmap_commands::plot(&what),
    }
}

pub(super) use crate::io::out as out_text;

/// The matrix format: `--format` (mtx or json), or json for `--json`.
pub(super) fn matrix_format(format: Option<&str>, json: bool) -> Result<&str, Error> {
    match (format, json) {
        (None, false) => Ok("mtx"),
        (None, true) | (Some("json"), _) => Ok("json"),
        (Some(f), true) => Err(Error::Input(format!("--json asks for the json format, but --format is {f}"))),
        (Some(f), false) => Ok(f),
    }
}

/// "minimal" or "analysis", as on the command line.
pub(super) fn kind_name(k: NeighbourhoodKind) -> &'static str {
    match k {
        NeighbourhoodKind::Minimal => "minimal",
        NeighbourhoodKind::Analysis => "analysis",
    }
}

pub(super) fn parse_params(list: &[String]) -> Result<Vec<(String, String)>, Error> {
    list.iter()
        .map(|p| {
            p.split_once('=')
                .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
                .ok_or_else(|| Error::Input(format!("parameter '{p}' is not of the form NAME=VALUE")))
        })
        .collect()
}

/// The scheme (name or file, with `--param`s) and its configuration at the
/// valence (regular, or the `--faces` sequence), as every analysis command
/// reads them.
pub(super) fn configuration(scheme: &dyn Scheme, a: &super::SchemeArgs) -> Result<Configuration, Error> {
    match a.faces.as_deref() {
        None => Configuration::regular(scheme, a.valence),
        Some(faces) => Configuration::with_faces(scheme, a.valence, faces),
    }
}

fn run_analysis(a: &AnalysisArgs, scheme: Box<dyn Scheme>) -> Result<(Box<dyn Scheme>, Analysis), Error> {
    let config = configuration(scheme.as_ref(), &a.config)?;
    let neighbourhood: NeighbourhoodKind = a.neighbourhood.parse()?;
    let method = match a.method.as_deref() {
        None => None,
        Some("dft") => Some(Method::Dft),
        Some("full") => Some(Method::Full),
        Some(m) => return Err(Error::Input(format!("unknown method '{m}'; use dft or full"))),
    };
    if method == Some(Method::Dft) && config.symmetry_period() == config.valence() {
        return Err(Error::Input("this configuration has no rotation symmetry; use --method full".into()));
    }
    let opts = Options { neighbourhood, method, exact: !a.no_exact };
    let analysis = analyse(scheme.as_ref(), &config, &opts)?;
    Ok((scheme, analysis))
}

/// `spectrum --certify`: the floating-point spectrum and, beside it, the
/// certificate (`certify::spectrum`) from the same discovery and labels.
/// `spectrum --certify`: the table and the certificate; Ok holds the exit
/// status ([`certified_status`]).
fn certified_spectrum(
    a: &AnalysisArgs,
    scheme: Box<dyn Scheme>,
    document: Option<&std::path::Path>,
) -> Result<i32, Error> {
    let (scheme, analysis) = run_analysis(a, scheme)?;
    let certificate = crate::certify::certify_analysis(scheme.as_ref(), &analysis)?;
    if let Some(path) = document {
        crate::certify::export::write_spectrum(path, scheme.as_ref(), &analysis, &certificate)?;
    }
    if a.json {
        #[derive(serde::Serialize)]
        struct Certified<'a> {
            #[serde(flatten)]
            spectrum: &'a Spectrum,
            certificate: &'a crate::certify::SpectrumCertificate,
        }
        print_json(&Certified { spectrum: &analysis.spectrum, certificate: &certificate })?;
    } else {
        out_text(&format!("{}\n{}", spectrum_table(&analysis.spectrum), certificate_table(&certificate)))?;
    }
    Ok(certified_status(&certificate.verdict, certificate.conditional))
}

/// The certificate as text: the verdict, the premises and the margins.
pub(super) fn certificate_table(c: &crate::certify::SpectrumCertificate) -> String {
    use crate::certify::matrix::Check;
    let mut out = format!(
        "certified spectral C1 conditions: {}{}\n",
        c.verdict.display(),
        if c.conditional { ", given the premises marked 'identity' below" } else { "" }
    );
    out += &format!("  statement: {}\n", c.statement);
    out += "  (the floating-point table above observes; where it disagrees with this certificate, the certificate \
            decides)\n";
    if let Some(p) = &c.premises {
        let field = p.field.as_deref().unwrap_or("Q");
        let show = |x: &Check| match x {
            Check::Exact => format!("exact, in {field}"),
            Check::Overlap => "identity of the rules' formulas, confirmed to interval overlap only".to_string(),
            Check::Fails(w) => format!("fails: {w}"),
        };
        out += &format!("  premise row sums = 1: {}\n", show(&p.row_sums_one));
        out += &format!("  premise mirror symmetry: {}\n", show(&p.mirror_symmetry));
        out += &format!("  premise rotation symmetry: {}\n", show(&p.rotation_symmetry));
    }
    if let Some(e) = &c.exact_route {
        let lambda1 = e.lambda1.as_deref().unwrap_or("-");
        out += &if e.proved {
            format!(
                "  exact route (lemma S7): det(xI − S) over Q ({} × {}): 1 simple, λ1 = {lambda1} a double root with \
                 a two-dimensional eigenspace, the other {} roots inside |x| < {} (Schur–Cohn)\n",
                e.size,
                e.size,
                e.cofactor_degree,
                e.others_below.as_deref().unwrap_or("-")
            )
        } else if e.one_multiplicity != 1 {
            format!(
                "  exact route (lemma S7): det(xI − S) over Q ({} × {}): 1 is a root of multiplicity {}\n",
                e.size, e.size, e.one_multiplicity
            )
        } else {
            format!(
                "  exact route (lemma S7): det(xI − S) over Q ({} × {}): λ1 = {lambda1} dominant (the other {} roots \
                 inside |x| < {lambda1}, Schur–Cohn), of algebraic multiplicity {} and geometric multiplicity {}\n",
                e.size, e.size, e.cofactor_degree, e.algebraic, e.geometric
            )
        };
    }
    let m = &c.margins;
    let f = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.12e}"));
    if let Some(l) = m.lambda0 {
        out += &format!("  λ0 ∈ [{:.15}, {:.15}]\n", l.lo, l.hi);
    }
    if let Some(l) = m.lambda1 {
        out += &format!("  λ1 ∈ [{:.15}, {:.15}]\n", l.lo, l.hi);
    }
    out += &format!(
        "  max |other eigenvalue| ≤ {}; gap λ1 − max|other| ≥ {}\n  largest disc radius {:.3e} (λ0, λ1: {}); widest block entry {:.3e}\n",
        f(m.others_max_modulus),
        f(m.gap_lower_bound),
        m.max_radius,
        f(m.lambda_radius),
        m.max_entry_width
    );
    for &b in &m.power_bounded {
        if let Some(p) = c.blocks.iter().find(|e| e.block == b).and_then(|e| e.power_bound) {
            out += &format!(
                "  block {b} by lemma S6 (no eigenvectors): ρ ≤ ‖B^{}‖∞^(1/{}) ≤ {:.9} (‖B^{}‖∞ ≤ {:.6e})\n",
                p.k, p.k, p.radius, p.k, p.norm
            );
        }
    }
    if let Some(w) = &c.witness {
        out += &format!(
            "  witness: block {}, {} eigenvalue(s) with modulus in [{:.12}, {:.12}]\n",
            w.block,
            w.component.count,
            w.component.min_modulus(),
            w.component.max_modulus()
        );
    }
    out
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

pub(super) fn spectrum_table(s: &Spectrum) -> String {
    let mut out = String::new();
    out += &format!(
        "scheme {}  valence {}  faces {}  neighbourhood {} ({} vertices; minimal {}, analysis {})\n",
        s.scheme,
        s.valence,
        short_faces(&s.faces),
        kind_name(s.neighbourhood),
        s.matrix_size,
        s.minimal_size,
        s.analysis_size
    );
    if !s.params.is_empty() {
        out += &format!(
            "parameters: {}\n",
            s.params.iter().map(|(k, v)| format!("{k}={v}")).collect::<Vec<_>>().join(", ")
        );
    }
    out += &format!(
        "method {}: blocks {}\n\n",
        match s.method {
            Method::Dft => "dft",
            Method::Full => "full",
        },
        s.blocks.iter().map(|b| format!("{}:{}", b.index, b.size)).collect::<Vec<_>>().join(" ")
    );
    out += &format!("{:>4}  {:<34} {:>14}  {:>4} {:>4}  {}\n", "#", "eigenvalue", "modulus", "alg", "geo", "blocks");
    for (k, e) in s.eigenvalues.iter().enumerate() {
        out += &format!(
            "{:>4}  {:<34} {:>14}  {:>4} {:>4}  {}{}\n",
            k,
            e.display(),
            crate::spectrum::fmt_f(e.modulus),
            e.algebraic_multiplicity,
            e.geometric_multiplicity,
            compact_blocks(&e.blocks),
            if e.defective { "  DEFECTIVE" } else { "" }
        );
    }
    if let Some(x) = &s.exact_analysis {
        out += &format!(
            "\nexact ({}): characteristic polynomial of degree {}; rational roots {}; remaining factor degree {}{}\n",
            x.method,
            x.polynomial_degree,
            x.rational_roots
                .iter()
                .map(|r| format!("{}^{}", r.value, r.algebraic_multiplicity))
                .collect::<Vec<_>>()
                .join(" "),
            x.remaining_degree,
            if x.agrees_with_float { "" } else { "  (DISAGREES with floating point multiplicities)" }
        );
    }
    out += &format!("\nReif spectral C1 criterion: {}\n", if s.verdict.c1_spectral { "PASSES" } else { "FAILS" });
    for r in &s.verdict.reasons {
        out += &format!("  - {r}\n");
    }
    if let Some(r) = s.verdict.lambda3_over_lambda1_squared {
        out += &format!("  |λ3|/λ1² = {}\n", crate::spectrum::fmt_f(r));
    }
    out
}

/// "Q×200" for a long uniform face sequence.
fn short_faces(f: &str) -> String {
    match f.chars().next() {
        Some(c) if f.len() > 12 && f.chars().all(|x| x == c) => format!("{c}×{}", f.len()),
        _ => f.to_string(),
    }
}

fn compact_blocks(b: &[usize]) -> String {
    if b.len() > 6 {
        format!("{},{},…,{} ({} blocks)", b[0], b[1], b[b.len() - 1], b.len())
    } else {
        b.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(",")
    }
}

pub(super) fn stencil_table(st: &crate::spectrum::stencils::Stencils) -> String {
    let mut out = format!(
        "scheme {}  valence {}  faces {}  neighbourhood {}\n\n",
        st.scheme,
        st.valence,
        st.faces,
        kind_name(st.neighbourhood)
    );
    out += &format!("{:<22} {:>22}", "vertex", "limit");
    for k in 0..st.tangent.len() {
        out += &format!(" {:>22}", format!("tangent {}", k + 1));
    }
    out += "\n";
    for (k, w) in st.limit.iter().enumerate() {
        let all_zero = w.weight == 0.0 && st.tangent.iter().all(|t| t[k].weight == 0.0);
        if all_zero {
            continue;
        }
        let cell = |x: &crate::spectrum::stencils::StencilWeight| match &x.recognised {
            Some(r) if r != "0" => format!("{} ({})", crate::spectrum::fmt_f(x.weight), r),
            _ => crate::spectrum::fmt_f(x.weight),
        };
        out += &format!("{:<22} {:>22}", w.vertex, cell(w));
        for t in &st.tangent {
            out += &format!(" {:>22}", cell(&t[k]));
        }
        out += "\n";
    }
    out += "(vertices where every stencil is zero are omitted)\n";
    out
}

fn sweep(args: &super::SweepArgs) -> Result<(), Error> {
    use crate::sweep::{admissible, convergent, run_on, Grid};
    let (scheme, json, csv) = (args.scheme.as_str(), args.json, args.csv);
    if json && csv {
        return Err(Error::Input("choose one of --json and --csv".into()));
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
    let mut grid =
        Grid::parse(scheme, &args.valences, args.faces.as_deref(), &parse_params(&args.params)?, args.charmap)?;
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
    let mut print_row = |cells: &[String], error: &str, added: &[String]| {
        if csv {
            text += &format!("{},{},{}\n", cells.join(","), error.replace(',', ";"), added.join(","));
        } else {
            let all = cells.iter().chain(added);
            let padded: Vec<String> = all.zip(WIDTHS).map(|(c, w)| format!("{c:>w$}")).collect();
            let note = if error.is_empty() { String::new() } else { format!("  ({error})") };
            text += &format!("{}{note}\n", padded.join(" "));
        }
    };
    if csv {
        print_row(
            &[format!("valence,{name},lambda0,lambda1,lambda2,lambda3,convergent,c1_spectral,charmap")],
            "error",
            &["curvature_class,lp_limit".into()],
        );
    } else {
        let head = ["valence", name.as_str(), "|λ0|", "|λ1|", "|λ2|", "|λ3|", "conv", "C1", "charmap"];
        // the table shows the curvature columns only when they were computed
        let added: &[String] = if grid.curvature { &["curvature".into(), "L_p: p <".into()] } else { &[] };
        print_row(&head.map(String::from), "", added);
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
        print_row(&cells, p.error.as_deref().unwrap_or_default(), if csv || grid.curvature { &added } else { &[] });
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
