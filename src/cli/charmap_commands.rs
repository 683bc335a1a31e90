//! `subdlab charmap` and `subdlab plot`.

use std::path::{Path, PathBuf};

use clap::{Args, Subcommand};

use super::commands::parse_params;
use crate::charmap::{check_map, CharMap, CharMapOptions, DEFAULT_RESOLUTION, MAX_LEVELS};
use crate::cli::args::{FigureArgs, SchemeArgs};
use crate::error::Error;
use crate::io::print_json;
use crate::neighbourhood::configuration::check_valence;
use crate::neighbourhood::NeighbourhoodKind;
use crate::plot::{self, charmap::RingFigure, spectrum::SpectrumFigure, sweep::Bound};
use crate::schemes::{self, Scheme};
use crate::spectrum::{analyse, Options};

/// Most valences in one spectrum plot (each is a full analysis).
const MAX_PLOT_VALENCES: usize = 200;
/// Most curves in one comparison figure: the colours that stay distinct in print.
const MAX_COMPARED: usize = crate::plot::lines::COLOURS.len();
/// Largest analysis level drawn in a figure: finer facets only blacken the
/// picture and inflate the SVG.
const FIGURE_LEVELS: usize = 3;

#[derive(Args, Debug, Clone)]
pub struct CharmapArgs {
    #[command(flatten)]
    pub config: SchemeArgs,
    /// analysis steps of refinement of the control net (1 to 8; default 4 on hosts that split a face into 4,
    /// 3 where an analysis step splits it into 9: sqrt(3) and ternary hosts, about the same resolution)
    #[arg(long)]
    pub levels: Option<usize>,
    /// pixels per side when rasterising the ring (16 to 8192)
    #[arg(long, default_value_t = DEFAULT_RESOLUTION)]
    pub resolution: usize,
    /// write a figure (.svg, .pdf or .png) of the nested rings and the control net
    #[arg(short, long)]
    pub out: Option<PathBuf>,
    /// draw the normalised wedge of one sector (angle 2π/n stretched to π/2) instead of the rings
    #[arg(long)]
    pub wedge: bool,
    /// rings drawn: the ring and its copies scaled by λ1, λ1², ... (1 to 12)
    #[arg(long, default_value_t = 4)]
    pub rings: usize,
    /// colour the rings' faces by sector (sector 0 starts on the positive x-axis)
    #[arg(long)]
    pub sectors: bool,
    #[command(flatten)]
    pub figure: FigureArgs,
    /// also prove (or disprove) Reif's criterion: certified spectrum,
    /// Jacobian bounds of the ring's box-spline patches (or of the scheme's own rules by difference-scheme bounds), certified winding number
    #[arg(long)]
    pub certify: bool,
    /// most analysis steps of refinement the certificate tries (2 to 6)
    #[arg(long, default_value_t = crate::certify::charmap::DEFAULT_MAX_LEVELS, requires = "certify")]
    pub certify_levels: usize,
    /// also write the certificate document (JSON, atomically) for an
    /// independent checker (`python3 scripts/check_cert.py FILE`): the
    /// spectral and the characteristic-map parts (at a boundary vertex: the
    /// tagged spectral part and the sector map's)
    #[arg(long, value_name = "FILE", requires = "certify")]
    pub certificate: Option<PathBuf>,
    /// machine-readable JSON output
    #[arg(long)]
    pub json: bool,
}

#[derive(Subcommand, Debug, Clone)]
pub enum PlotWhat {
    /// Leading eigenvalue moduli against valence
    Spectrum {
        /// scheme name (see `subdlab schemes`) or a scheme file (.toml, see schemes/)
        scheme: String,
        /// valence range, e.g. 3..40 (inclusive) or a single valence
        #[arg(long, default_value = "3..40")]
        valences: String,
        /// scheme parameter NAME=VALUE; repeatable
        #[arg(long = "param", short = 'p')]
        params: Vec<String>,
        /// how many distinct moduli after λ0 = 1 to draw (1 to 6)
        #[arg(long, default_value_t = 3)]
        count: usize,
        /// a reference curve drawn dashed, an expression in n and the scheme's
        /// --param values (as `sweep --bound`), e.g. "3/8 + cos(2 pi/n)/4"; repeatable
        #[arg(long = "reference")]
        references: Vec<String>,
        /// output figure (.svg, .pdf or .png)
        #[arg(short, long)]
        out: PathBuf,
        /// legend text of the k-th drawn branch (in the legend's order), replacing
        /// its own; repeatable
        #[arg(long = "label")]
        labels: Vec<String>,
        #[command(flatten)]
        figure: FigureArgs,
    },
    /// One quantity of the leading spectrum against valence, one curve per scheme or parameter value
    Compare {
        /// a curve: scheme name or file, with fixed parameters after a colon,
        /// e.g. catmull-clark, non-box:a=1/2 or unified-sqrt3:alpha=0; repeatable (1 to 6)
        #[arg(long = "curve", visible_alias = "scheme", required = true)]
        curves: Vec<String>,
        /// valence range A..B (inclusive)
        #[arg(long, default_value = "3..16")]
        valences: String,
        /// lambdaK (|λK|) or lambdaJ/lambdaK, K and J from 0 to 3, moduli counted with
        /// multiplicity as `sweep` lists them (lambda1 = lambda2 for a double subdominant pair)
        #[arg(long, default_value = "lambda1")]
        quantity: String,
        /// a reference curve drawn dashed, an expression in n; repeatable
        #[arg(long = "reference")]
        references: Vec<String>,
        /// output figure (.svg, .pdf or .png)
        #[arg(short, long)]
        out: PathBuf,
        /// legend text of the k-th --curve, replacing its own (NAME and parameters);
        /// repeatable, at most one per curve
        #[arg(long = "label")]
        labels: Vec<String>,
        #[command(flatten)]
        figure: FigureArgs,
        /// worker threads (0, the default: one per available core)
        #[arg(long, default_value_t = 0, hide_default_value = true, value_parser = clap::value_parser!(u16).range(0..=1024))]
        threads: u16,
    },
}

fn build_scheme(name: &str, params: &[String]) -> Result<Box<dyn Scheme>, Error> {
    schemes::resolve(name, &parse_params(params)?)
}

/// Fails early, before any computation, when the output cannot be written.
pub(super) fn check_out(path: &Path) -> Result<(), Error> {
    plot::format_of(path)?;
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    if !dir.is_dir() {
        return Err(Error::Write {
            path: path.display().to_string(),
            reason: format!("directory {} does not exist", dir.display()),
        });
    }
    Ok(())
}

/// The flags of `charmap` that need no scheme, checked before the scheme is
/// resolved (and again by [`charmap`], which is cheap).
pub(super) fn check_flags(a: &CharmapArgs) -> Result<(), Error> {
    if let Some(levels) = a.levels.filter(|&l| l == 0 || l > MAX_LEVELS) {
        return Err(Error::Input(format!("--levels must be between 1 and {MAX_LEVELS}, got {levels}")));
    }
    if a.rings == 0 || a.rings > 12 {
        return Err(Error::Input(format!("--rings must be between 1 and 12, got {}", a.rings)));
    }
    if let Some(out) = &a.out {
        check_out(out)?;
    } else if a.wedge || a.sectors || a.figure.is_set() {
        return Err(Error::Input(
            "--wedge, --sectors and the style flags shape the figure; give the figure file with --out \
             FILE.svg|pdf|png"
                .into(),
        ));
    }
    if a.wedge && a.sectors {
        return Err(Error::Input("--sectors colours the rings' sectors; the wedge is one sector".into()));
    }
    a.figure.style()?;
    Ok(())
}

/// `charmap`; Ok holds the exit status: 0, or with `--certify` the
/// certificate's ([`super::commands::certified_status`]: 0 only when Reif's
/// criterion is PROVED unconditionally).
pub fn charmap(a: &CharmapArgs, scheme: Box<dyn Scheme>) -> Result<i32, Error> {
    check_flags(a)?;
    let style = a.figure.style()?;
    let config = super::commands::configuration(scheme.as_ref(), &a.config)?;
    // at a tagged vertex the certificate is the sector map's
    // (`certify::tagged_charmap`): boundary vertices only; its document is
    // `export::write_tagged_charmap`'s
    let tagged = config.tagging.is_some();
    if a.certify && tagged {
        if let Some(t) = config.tagging.filter(|t| *t != crate::neighbourhood::Tagging::Boundary) {
            return Err(Error::Input(format!(
                "charmap --tag {} --certify: only boundary vertices (--tag boundary) are certified yet; the \
                 floating-point charmap --tag {} decides this one",
                t.name(),
                t.name()
            )));
        }
    }
    let levels = a.levels.unwrap_or_else(|| crate::charmap::default_levels(scheme.as_ref()));
    let opts = CharMapOptions {
        levels,
        resolution: a.resolution,
        display_levels: a.out.as_ref().map(|_| levels.min(FIGURE_LEVELS)),
    };
    if a.certify {
        crate::certify::charmap::check_levels(a.certify_levels, "--certify-levels")?;
    }
    opts.check()?;
    let analysis = analyse(
        scheme.as_ref(),
        &config,
        &Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false },
    )?;
    let map = check_map(scheme.as_ref(), &analysis, &opts)?;
    // the figure, if asked for (after the certificate: a refused
    // certificate writes no figure)
    let write_figure = || -> Result<(), Error> {
        if let Some(out) = &a.out {
            if map.ring.is_none() {
                return Err(Error::Input(format!("no figure written: {}", map.explanation)));
            }
            let fig = RingFigure { map: &map, copies: a.rings, wedge: a.wedge, sectors: a.sectors, style };
            plot::save(&fig, out)?;
            plot::save_data(&fig, a.figure.data_path()?)?;
        }
        Ok(())
    };
    if a.certify && tagged {
        let c = crate::certify::tagged_charmap::certify_tagged_charmap(scheme.as_ref(), &analysis, a.certify_levels)?;
        if let Some(path) = &a.certificate {
            crate::certify::export::write_tagged_charmap(path, scheme.as_ref(), &analysis, &c)?;
        }
        write_figure()?;
        let status = super::commands::certified_status(&c.sector_criterion, c.conditional);
        if a.json {
            #[derive(serde::Serialize)]
            struct Certified<'a> {
                #[serde(flatten)]
                map: &'a CharMap,
                certificate: &'a crate::certify::tagged_charmap::TaggedCharMapCertificate,
            }
            print_json(&Certified { map: &map, certificate: &c })?
        } else {
            crate::io::out(&format!("{}\n{}", table(&map), tagged_certificate_table(&c)))?
        }
        return Ok(status);
    }
    let certificate = if a.certify {
        let c = crate::certify::certify_charmap(scheme.as_ref(), &analysis, a.certify_levels)?;
        if let Some(path) = &a.certificate {
            crate::certify::export::write_charmap(path, scheme.as_ref(), &analysis, &c)?;
        }
        Some(c)
    } else {
        None
    };
    write_figure()?;
    let status = certificate
        .as_ref()
        .map(|c| super::commands::certified_status(&c.c1, c.conditional || c.geometry_conditional))
        .unwrap_or(0);
    match (a.json, &certificate) {
        (true, None) => print_json(&map)?,
        (true, Some(c)) => {
            #[derive(serde::Serialize)]
            struct Certified<'a> {
                #[serde(flatten)]
                map: &'a CharMap,
                certificate: &'a crate::certify::CharMapCertificate,
            }
            print_json(&Certified { map: &map, certificate: c })?
        }
        (false, None) => crate::io::out(&table(&map))?,
        (false, Some(c)) => crate::io::out(&format!("{}\n{}", table(&map), certificate_table(c)))?,
    }
    Ok(status)
}

/// The sector map's certificate at a boundary vertex as text.
fn tagged_certificate_table(c: &crate::certify::tagged_charmap::TaggedCharMapCertificate) -> String {
    let mut out = format!(
        "certified sector criterion (Zorin 2000; Biermann–Levin–Zorin 2000): {}{}\n",
        c.sector_criterion.display(),
        if c.conditional { ", given the spectral premises confirmed to interval overlap only" } else { "" }
    );
    out += &format!(
        "  spectral part: {} (decided by {})\n",
        c.spectrum.verdict.display(),
        c.spectrum.decided_by.unwrap_or("-")
    );
    out += &format!("  regularity:    {}\n", c.regularity.display());
    out += &format!("  injectivity:   {}\n", c.injectivity.display());
    if let Some(l) = c.levels {
        out += &format!(
            "  ring faces at {l} levels: {} ({} across a sharp ray; {} Jacobian > 0, {} Jacobian < 0, {} undecided); \
             {} stencils compared exactly\n",
            c.ring_faces, c.boundary_faces, c.positive_faces, c.negative_faces, c.undecided_faces, c.rules_checked
        );
    }
    let f = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.3e}"));
    out += &format!(
        "  eigenvector enclosure radius {}; widest net point {}; doubled chain's winding number {}\n",
        f(c.eigenvector_radius),
        f(c.max_point_width),
        c.winding_number.map_or("-".to_string(), |w| w.to_string())
    );
    for r in &c.reasons {
        out += &format!("  - {r}\n");
    }
    out += "  evidence: proof (interval enclosures and exact rational rule and curve checks)\n";
    out
}

/// The characteristic-map certificate as text: the three verdicts and the
/// margins of the proof.
fn certificate_table(c: &crate::certify::CharMapCertificate) -> String {
    let mut out = format!(
        "certified C1 (Reif's criterion): {}{}\n",
        c.c1.display(),
        if c.conditional { ", given the spectral premises confirmed to interval overlap only" } else { "" }
    );
    out += &format!("  spectrum:    {}\n", c.spectrum.verdict.display());
    out += &format!("  regularity:  {}\n", c.regularity.display());
    out += &format!("  injectivity: {}\n", c.injectivity.display());
    if let Some(p) = c.regular_part {
        out += &format!("  regular part: {} ({} rules compared exactly)\n", p.describe(), c.rules_checked);
    }
    if let Some(l) = c.levels {
        out += &format!(
            "  ring faces at {l} levels: {} ({} Jacobian > 0, {} Jacobian < 0, {} undecided)\n",
            c.ring_faces, c.positive_faces, c.negative_faces, c.undecided_faces
        );
    }
    let f = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.6e}"));
    out += &format!(
        "  smallest Jacobian lower bound {} (ring in the unit disc, level-0 parameters), over the largest upper bound {}; eigenvector enclosure radius {}; \
         widest net point {}\n",
        f(c.min_jacobian_lower_bound),
        f(c.min_jacobian_ratio),
        f(c.eigenvector_radius),
        f(c.max_point_width)
    );
    if let Some(w) = c.winding_number {
        out += &format!("  winding number {w} (certified)\n");
    }
    if let Some(w) = &c.fold_witness {
        out += &format!(
            "  witness: Jacobian ≤ {:.3e} < 0 on the ring face at ({:.4}, {:.4}), ≥ {:.3e} > 0 on the one at ({:.4}, {:.4})\n",
            w.negative_upper_bound,
            w.negative_at[0],
            w.negative_at[1],
            w.positive_lower_bound,
            w.positive_at[0],
            w.positive_at[1]
        );
    }
    out
}

fn table(m: &CharMap) -> String {
    if let Some(c) = m.crease.as_ref().filter(|c| !c.sides.is_empty()) {
        return crease_table(m, c);
    }
    let mut out = format!(
        "scheme {}  {} {}  λ1 = {}  blocks {}\nlevels {} ({} refinements)  resolution {}\n\n",
        m.scheme,
        match &m.tagging {
            None => "valence".to_string(),
            Some(t) => format!("{t} vertex, sectors"),
        },
        m.valence,
        crate::spectrum::fmt_f(m.lambda1),
        m.subdominant_blocks.iter().map(|b| b.to_string()).collect::<Vec<_>>().join(", "),
        m.levels,
        m.refinements,
        m.resolution
    );
    let yes = |b: bool| if b { "yes" } else { "NO" };
    out += &format!("regular    {}\ninjective  {}\n", yes(m.regular), yes(m.injective));
    if let Some(a) = m.ray_angle_degrees {
        out += &format!("sharp rays' images at {a:.4}°\n");
    }
    if let Some(w) = m.winding_number {
        let inner = m.inner_winding_number.map(|x| x.to_string()).unwrap_or_else(|| "-".into());
        out += &format!("winding number {w} (inner boundary {inner})\n");
    }
    if let (Some(o), Some(c), Some(p)) = (m.overlap_pixels, m.copy_overlap_pixels, m.ring_pixels) {
        out += &format!("overlap pixels {o} (ring {p} pixels; shared with the scaled copy {c})\n");
    }
    if let (Some(r), Some(at)) = (m.min_jacobian_ratio, m.min_jacobian_at) {
        out += &format!("min/max Jacobian {r:.6} at ({:.4}, {:.4})\n", at[0], at[1]);
    }
    out += "\n";
    for r in &m.reasons {
        out += &format!("  - {r}\n");
    }
    out
}

/// The crease's maps as text: the crease's verdict (both sides), each
/// side's map, S whole's on a line of its own, then the reasons.
fn crease_table(m: &CharMap, c: &crate::charmap::CreaseMaps) -> String {
    let yes = |b: bool| if b { "yes" } else { "NO" };
    let mut out = format!(
        "scheme {}  {} vertex, valence {}: each side's own characteristic map\nlevels {} ({} refinements)  resolution {}\n\n",
        m.scheme,
        m.tagging.as_deref().unwrap_or("crease"),
        m.valence,
        m.levels,
        m.refinements,
        m.resolution
    );
    out += &format!(
        "crease (both sides): regular {}, injective {}  [floating point: the Jacobian's sign on every facet, \
         injectivity on the raster at resolution {}]\n",
        yes(m.regular),
        yes(m.injective),
        m.resolution
    );
    for side in &c.sides {
        let name = side.tagging.as_deref().and_then(|t| t.find("side ").map(|k| &t[k..])).unwrap_or("side");
        out += &format!("  {name}: {}\n", side.explanation);
        if side.ring.is_none() {
            out += "    no map\n";
            continue;
        }
        out += &format!("    regular {}  injective {}", yes(side.regular), yes(side.injective));
        if let Some(a) = side.ray_angle_degrees {
            out += &format!("  sharp rays' images at {a:.4}°");
        }
        if let (Some(o), Some(k), Some(p)) = (side.overlap_pixels, side.copy_overlap_pixels, side.ring_pixels) {
            out += &format!("  overlap pixels {o} (ring {p}; shared with the scaled copy {k})");
        }
        if let Some(r) = side.min_jacobian_ratio {
            out += &format!("  min/max Jacobian {r:.6}");
        }
        out += "\n";
    }
    out += &match (&c.whole, &c.whole_missing) {
        (Some(w), _) => format!(
            "  S whole (both sides at once; not the crease's criterion): regular {}, injective {} ({})\n",
            yes(w.regular),
            yes(w.injective),
            w.explanation
        ),
        (None, why) => format!(
            "  S whole (both sides at once; not the crease's criterion): no map: {}\n",
            why.as_deref().unwrap_or("-")
        ),
    };
    out += "\n";
    for r in &m.reasons {
        out += &format!("  - {r}\n");
    }
    out
}

/// "3..40", "3-40" or "7" (inclusive).
fn parse_range(s: &str) -> Result<(usize, usize), Error> {
    let bad = || Error::Input(format!("valence range '{s}' is not of the form A..B (e.g. 3..40)"));
    let (a, b) = match s.split_once("..").or_else(|| s.split_once('-')) {
        Some((a, b)) => (a.trim(), b.trim().trim_start_matches('=')),
        None => (s.trim(), s.trim()),
    };
    let (a, b): (usize, usize) = (a.parse().map_err(|_| bad())?, b.parse().map_err(|_| bad())?);
    if a > b {
        return Err(Error::Input(format!("valence range '{s}' is empty")));
    }
    check_valence(a)?;
    check_valence(b)?;
    if b - a + 1 > MAX_PLOT_VALENCES {
        return Err(Error::Input(format!("at most {MAX_PLOT_VALENCES} valences per plot, got {}", b - a + 1)));
    }
    Ok((a, b))
}

pub fn plot(what: &PlotWhat) -> Result<(), Error> {
    match what {
        PlotWhat::Spectrum { scheme, valences, params, count, references, out, labels, figure } => {
            if *count == 0 || *count > 6 {
                return Err(Error::Input(format!("--count must be between 1 and 6, got {count}")));
            }
            if labels.len() > *count {
                return Err(Error::Input(format!("{} --label texts for {count} branches (--count)", labels.len())));
            }
            let style = crate::plot::Style { labels: labels.clone(), ..figure.style()? };
            check_out(out)?;
            let (a, b) = parse_range(valences)?;
            let valences: Vec<usize> = (a..=b).collect();
            let references = Bound::over(references, &parse_params(params)?, &valences)?;
            let s = build_scheme(scheme, params)?;
            let rows = crate::plot::spectrum::leading_moduli(s.as_ref(), a..=b)?;
            let fig = SpectrumFigure { scheme: s.name().to_string(), rows, count: *count, references, style };
            plot::save(&fig, out)?;
            plot::save_data(&fig, figure.data_path()?)
        }
        PlotWhat::Compare { curves, valences, quantity, references, out, labels, figure, threads } => {
            use crate::plot::compare::{compare_lines, CompareFigure, CurveSpec, Quantity};
            if curves.len() > MAX_COMPARED {
                return Err(Error::Input(format!("at most {MAX_COMPARED} curves per figure, got {}", curves.len())));
            }
            if labels.len() > curves.len() {
                return Err(Error::Input(format!("{} --label texts for {} curves", labels.len(), curves.len())));
            }
            let style = crate::plot::Style { labels: labels.clone(), ..figure.style()? };
            check_out(out)?;
            let quantity = Quantity::parse(quantity)?;
            let specs: Vec<CurveSpec> = curves.iter().map(|c| CurveSpec::parse(c)).collect::<Result<_, _>>()?;
            let (a, b) = parse_range(valences)?;
            let range: Vec<usize> = (a..=b).collect();
            let references = Bound::over(references, &[], &range)?;
            // the sweep's own reading of the range (A..B)
            let lines = compare_lines(&specs, &format!("{a}..{b}"), quantity, *threads as usize)?;
            let fig = CompareFigure { quantity, lines, references, valences: (a, b), style };
            plot::save(&fig, out)?;
            plot::save_data(&fig, figure.data_path()?)
        }
    }
}
