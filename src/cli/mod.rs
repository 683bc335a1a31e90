//! The `subdlab` command line. Every analysis command (`spectrum`,
//! `stencils`, `matrix`, `charmap`, `curvature`) takes the same scheme and
//! configuration flags ([`SchemeArgs`]: the scheme, `--valence N`, repeated
//! `--param NAME=VALUE`, `--faces`) and `--json`; the scheme is resolved once
//! (`front_door`) and its domain decides which analyses run on it. Errors are
//! one line on stderr with a non-zero exit.

mod charmap_commands;
mod commands;
mod curvature;
mod front_door;
mod lattice;
mod mesh_commands;
mod verify;

use clap::{Args, Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(name = "subdlab", version = env!("SUBDLAB_VERSION_LONG"), about = "Eigenanalysis and smoothness verification of subdivision surfaces")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

// Exit statuses, one meaning for every command that prints a verdict: 0 the
// verdict holds (HOLDS, PROVED), 1 a verdict that did not hold (REFUTED,
// INCONCLUSIVE, DISPROVED, NOT PROVED), 2 an error (nothing was decided).
const VERIFY_EXIT: &str = "Exit status: 0 every claim HOLDS (with --check-expected: every verdict is the recorded \
one); 1 a claim is REFUTED or INCONCLUSIVE (with --check-expected: a verdict differs from the recorded one); 2 an \
error: a claim is ERROR (malformed or vacuous, a missing scheme file, an unknown parameter, a non-real value where \
a real one is required) or a file cannot be read, whatever --check-expected records.";
const SPECTRUM_EXIT: &str = "Exit status: with --certify, 0 PROVED unconditionally; 1 DISPROVED, NOT PROVED, or \
PROVED only given premises confirmed to interval overlap; 2 an error. Without --certify the verdict is a \
floating-point observation and the exit status is 0 whatever it says (2 on an error).";
const CHARMAP_EXIT: &str = "Exit status: with --certify, 0 Reif's criterion PROVED unconditionally; 1 DISPROVED, \
NOT PROVED, or PROVED only given premises confirmed to interval overlap; 2 an error. Without --certify the verdict \
is a numerical observation and the exit status is 0 whatever it says (2 on an error).";
const OBSERVED_EXIT: &str = "Exit status: 0 when the analysis ran, whatever the observed verdicts say (they are \
floating-point observations; decide with `spectrum --certify`, `charmap --certify` or a claim in `verify`); 2 an \
error.";

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Sweep valences (and one parameter): λ0..λ3, verdicts, admissible intervals
    #[command(after_help = OBSERVED_EXIT)]
    Sweep(SweepArgs),
    /// Write reports/: an index and one page per paper (claims, figures, refuted statements)
    Report {
        /// the report folder
        #[arg(short, long, default_value = "reports")]
        out: std::path::PathBuf,
    },
    /// Check the papers' statements (built-in registry, or your own claim files)
    #[command(after_help = VERIFY_EXIT)]
    Verify {
        /// only this paper of the built-in registry (see the list printed without it)
        #[arg(long)]
        paper: Option<String>,
        /// a claim file of your own (TOML, same format as claims/, see
        /// examples/claims/); repeatable
        #[arg(long)]
        claims: Vec<std::path::PathBuf>,
        /// machine-readable JSON output (stable field names)
        #[arg(long)]
        json: bool,
        /// also write a JUnit XML report (atomically; written even when a
        /// claim is malformed)
        #[arg(long)]
        junit: Option<std::path::PathBuf>,
        /// pass a claim when its verdict is the one the file records in
        /// `expected` (HOLDS when it records none): an expected refutation
        /// passes. Exit status 0 when every verdict is as recorded
        #[arg(long)]
        check_expected: bool,
        /// write the certificate document of every certified claim at every
        /// valence into DIR (`CLAIM-ID-nN.json`, the format of `--certificate`),
        /// for `scripts/check_cert.py`; DIR is created if missing
        #[arg(long, value_name = "DIR")]
        certificates: Option<std::path::PathBuf>,
        /// after the table, list the K claims that took longest (wall-clock
        /// seconds and share of the total; `--json` gives every claim's
        /// `seconds`)
        #[arg(long, value_name = "K")]
        slowest: Option<usize>,
    },
    /// List the built-in schemes (or the given scheme files) with their parameters, defaults and ranges
    Schemes {
        /// scheme files (TOML) to describe instead of the built-in schemes
        files: Vec<std::path::PathBuf>,
        /// machine-readable JSON output (stable field names)
        #[arg(long)]
        json: bool,
    },
    /// Spectrum of the local subdivision matrix with multiplicities and the Reif verdict
    #[command(after_help = SPECTRUM_EXIT)]
    Spectrum {
        #[command(flatten)]
        common: AnalysisArgs,
        /// prove the spectral C¹ conditions with interval enclosures of every
        /// Fourier block (PROVED / DISPROVED / NOT PROVED, with the margins)
        #[arg(long)]
        certify: bool,
        /// also write the certificate document (JSON, atomically): the exact
        /// rows of S and everything the proof rests on, for an independent
        /// checker (`python3 scripts/check_cert.py FILE`)
        #[arg(long, value_name = "FILE", requires = "certify")]
        certificate: Option<std::path::PathBuf>,
    },
    /// Limit and tangent stencils (left eigenvectors) on labelled vertices
    Stencils(AnalysisArgs),
    /// Export the local subdivision matrix
    Matrix {
        #[command(flatten)]
        common: AnalysisArgs,
        /// mtx (Matrix Market, the default) or json (also chosen by --json)
        #[arg(long)]
        format: Option<String>,
        /// write to this file (atomically) instead of standard output
        #[arg(short = 'o', long = "out", visible_alias = "output")]
        output: Option<std::path::PathBuf>,
    },
    /// Refine a closed OBJ mesh with a scheme (the same rules as the analysis); writes OBJ
    Refine {
        /// input mesh (Wavefront OBJ, closed)
        mesh: std::path::PathBuf,
        /// scheme name (see `subdlab schemes`) or a scheme file (.toml, see schemes/)
        #[arg(long)]
        scheme: String,
        /// number of refinement steps (1 to 12)
        #[arg(long, short = 'l')]
        levels: usize,
        /// scheme parameter NAME=VALUE; repeatable
        #[arg(long = "param", short = 'p')]
        params: Vec<String>,
        /// output OBJ file (written atomically)
        #[arg(short = 'o', long = "out", visible_alias = "output")]
        output: std::path::PathBuf,
        /// schemes with face control vertices (non-box): initial FCVs at this
        /// multiple of each face's barycentre (the paper's section 5 uses 0.5, 1, 1.5)
        #[arg(long, default_value = "1")]
        fcv_scale: f64,
        /// schemes with face control vertices: write the four-directional form
        /// (every face split into triangles around its FCV) instead of quads + FCVs
        #[arg(long)]
        four_directional: bool,
        /// schemes with a per-vertex parameter (unified-sqrt3: alpha): a file with
        /// one value per line for each input vertex, in order ('#' starts a comment)
        #[arg(long)]
        vertex_params: Option<std::path::PathBuf>,
    },
    /// Curve schemes of Lin–Luo section 3: local subdivision matrix at a vertex and its spectrum
    Curve {
        /// cubic-bspline, four-point or unified-curve
        scheme: String,
        /// scheme parameter NAME=VALUE (unified-curve: alpha in [0, 2]); repeatable
        #[arg(long = "param", short = 'p')]
        params: Vec<String>,
        /// minimal (closure of the one-ring) or analysis (also the limit over both adjacent segments)
        #[arg(long, default_value = "analysis")]
        neighbourhood: String,
        /// machine-readable JSON output
        #[arg(long)]
        json: bool,
    },
    /// Characteristic map: regularity and injectivity of the characteristic ring; optional figure
    #[command(after_help = CHARMAP_EXIT)]
    Charmap(charmap_commands::CharmapArgs),
    /// Second order at the centre: curvature class, L_p limit, F(μ) and shapes, Reif's C² test
    #[command(after_help = OBSERVED_EXIT)]
    Curvature(curvature::CurvatureArgs),
    /// Figures (SVG, PDF or PNG by the file extension)
    Plot {
        #[command(subcommand)]
        what: charmap_commands::PlotWhat,
    },
}

/// What a figure's reader sees besides the data (title, size, font,
/// resolution): the style flags every figure command takes (`charmap`,
/// `curvature`, `plot spectrum`, `plot compare`, `sweep --plot`).
#[derive(Args, Debug, Clone, Default)]
pub struct FigureArgs {
    /// the figure's title (an empty text: no title); default: names the scheme
    #[arg(long)]
    pub title: Option<String>,
    /// figure width in points (SVG user units, PDF points), 200 to 6000
    #[arg(long)]
    pub width: Option<u32>,
    /// figure height in points (SVG user units, PDF points), 200 to 6000
    #[arg(long)]
    pub height: Option<u32>,
    /// base font size (tick labels) in points, 6 to 72; other text scales with it
    #[arg(long)]
    pub font_size: Option<u32>,
    /// PNG resolution in dots per inch, 36 to 1200 (default 150): the PNG has
    /// width × dpi / 72 pixels; SVG and PDF are vector and ignore it
    #[arg(long)]
    pub dpi: Option<f64>,
}

impl FigureArgs {
    /// Whether any style flag was given (they need a figure to shape).
    pub fn is_set(&self) -> bool {
        self.title.is_some()
            || self.width.is_some()
            || self.height.is_some()
            || self.font_size.is_some()
            || self.dpi.is_some()
    }
    pub fn style(&self) -> Result<crate::plot::Style, crate::error::Error> {
        crate::plot::Style {
            title: self.title.clone(),
            width: self.width,
            height: self.height,
            font_size: self.font_size,
            dpi: self.dpi,
        }
        .checked()
    }
}

/// The scheme and the configuration at its centre: the one definition of the
/// flags every analysis command takes (`spectrum`, `stencils`, `matrix`,
/// `charmap`, `curvature`), flattened into each command's arguments so that
/// they cannot drift apart. The front door (`cli::front_door`) resolves the
/// scheme once and asks its domain what it can do.
#[derive(Args, Debug, Clone)]
pub struct SchemeArgs {
    /// scheme name (see `subdlab schemes`) or a scheme file (.toml, see schemes/)
    pub scheme: String,
    /// valence of the extraordinary vertex (or face); regular-lattice schemes: 4, curve schemes: 2
    #[arg(long, short = 'n')]
    pub valence: usize,
    /// scheme parameter NAME=VALUE (3/8, 0.375 and 1e-3 are accepted); repeatable
    #[arg(long = "param", short = 'p')]
    pub params: Vec<String>,
    /// face sequence around the centre, counter-clockwise, one letter per face:
    /// Q (quad) or T (triangle), e.g. QQTTT; as many letters as the valence
    /// (schemes of mixed meshes only: four-three; default all quads)
    #[arg(long)]
    pub faces: Option<String>,
}

#[derive(Args, Debug, Clone)]
pub struct AnalysisArgs {
    #[command(flatten)]
    pub config: SchemeArgs,
    /// minimal (smallest invariant set) or analysis (also defines the first limit ring)
    #[arg(long, default_value = "analysis")]
    pub neighbourhood: String,
    /// dft (Fourier blocks) or full (whole matrix); default: dft when rotation-symmetric
    #[arg(long)]
    pub method: Option<String>,
    /// skip the exact rational confirmation
    #[arg(long)]
    pub no_exact: bool,
    /// machine-readable JSON output (stable field names)
    #[arg(long)]
    pub json: bool,
}

/// Runs the command line and returns the exit status: 0 success; 1 when
/// `verify` finds a claim that is not as required (REFUTED or INCONCLUSIVE)
/// or a certified verdict is not PROVED unconditionally (`spectrum
/// --certify`, `charmap --certify`);
/// 2 for usage errors (clap's full message: what is missing, the usage line)
/// and for every other error (one line on stderr, control characters shown
/// escaped).
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            use clap::error::ErrorKind;
            // help and version go to stdout with exit 0
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                return match crate::io::out(&e.to_string()) {
                    Ok(()) => 0,
                    Err(m) => {
                        error_line(&m);
                        2
                    }
                };
            }
            // a usage error (or the help after a bare `subdlab`): clap's whole
            // message, with a long echoed argument cut (see `error_line`)
            to_stderr(&crate::error::shorten_echoes(&e.render().to_string()));
            return 2;
        }
    };
    match commands::dispatch(cli.command) {
        Ok(code) => code,
        Err(e) => {
            error_line(&e);
            2
        }
    }
}

/// Shows an error as the one line "error: MESSAGE": control characters
/// escaped, long echoes of the user's input cut
/// ([`crate::error::shorten_echoes`]).
fn error_line(e: &crate::error::Error) {
    let line = crate::error::shorten_echoes(&crate::io::printable(&e.to_string()));
    to_stderr(&format!("error: {line}\n"));
}

/// Writes to standard error; when even that fails (a full disk) there is
/// nowhere left to report to, and the exit status still says it.
fn to_stderr(text: &str) {
    use std::io::Write;
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}

/// Runs the command line; usage errors and failures are the message (see
/// [`main`] for the exit statuses the binary uses).
pub fn run() -> Result<(), crate::error::Error> {
    use crate::error::Error;
    let cli = Cli::try_parse().map_err(|e| Error::Input(e.to_string()))?;
    match commands::dispatch(cli.command)? {
        0 => Ok(()),
        _ => Err(Error::Claim("a verdict did not hold (a claim not as required, or a certificate not proved)".into())),
    }
}

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// scheme name or scheme file
    pub scheme: String,
    /// valence range A..B
    #[arg(long)]
    pub valences: String,
    /// NAME=VALUE fixes a parameter; NAME=START:END:STEP sweeps one (at most one)
    #[arg(long = "param", short = 'p')]
    pub params: Vec<String>,
    /// also check the characteristic map at every point that passes the spectral test
    #[arg(long)]
    pub charmap: bool,
    /// also compute the curvature class and L_p limit at every point (as `subdlab curvature
    /// --no-exact`; opt-in: about a curvature run per point, far more than the spectrum)
    #[arg(long)]
    pub curvature: bool,
    /// with --charmap: analysis steps of refinement (default as `subdlab charmap`: 4)
    #[arg(long)]
    pub levels: Option<usize>,
    /// with --charmap: pixels per side of the rasterisation (default as `subdlab charmap`: 512)
    #[arg(long)]
    pub resolution: Option<usize>,
    /// machine-readable JSON output (stable field names)
    #[arg(long)]
    pub json: bool,
    /// comma-separated values, one row per point
    #[arg(long)]
    pub csv: bool,
    /// draw the admissible intervals (valence x swept value; with --curvature coloured by
    /// curvature class, and also for valences alone) into FILE.svg, FILE.pdf or FILE.png
    #[arg(short = 'o', long = "out", visible_alias = "plot")]
    pub plot: Option<std::path::PathBuf>,
    /// a reference bound to draw on the plot, an expression in n (e.g. a paper's
    /// stated bound "1/4 - cos(2 pi / n)/4"); repeatable
    #[arg(long = "bound")]
    pub bounds: Vec<String>,
    /// face sequence around the centre for mixed-mesh schemes (four-three), e.g. QQTTT;
    /// its length is the valence
    #[arg(long)]
    pub faces: Option<String>,
    #[command(flatten)]
    pub figure: FigureArgs,
    /// worker threads (0, the default: one per available core)
    #[arg(long, default_value_t = 0, hide_default_value = true, value_parser = clap::value_parser!(u16).range(0..=1024))]
    pub threads: u16,
}
