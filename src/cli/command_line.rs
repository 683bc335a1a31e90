//! The command line's grammar: `Cli` and its subcommands (`Command`), with
//! the exit-status texts of their help.

use clap::{Parser, Subcommand};

use crate::cli::args::{AnalysisArgs, SweepArgs};
use crate::cli::{charmap_commands, curvature, shape_chart};

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
floating-point observation and the exit status is 0 whatever it says (2 on an error). Every valence: \
`subdlab spectrum SCHEME --certify --valences A..B` (each valence) or `--valences A..` (every valence from A on: \
an exact parametric proof beyond a threshold N), in place of -n; spectral conditions only.";
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
    /// Refine an OBJ mesh with a scheme (the same rules as the analysis); writes OBJ.
    /// Open meshes and creases (`#crease i j`, `#corner i` lines) need a scheme with
    /// boundary rules (catmull-clark, loop)
    Refine {
        /// input mesh (Wavefront OBJ; closed, or open for schemes with boundary rules)
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
        /// boundary, crease and corner tags besides those in the OBJ file: lines
        /// `crease i j [k ...]` and `corner i [j ...]` (1-based vertex indices)
        #[arg(long)]
        tags: Option<std::path::PathBuf>,
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
    /// Shape chart: which quadratic input shapes (elliptic, parabolic, hyperbolic, rotated) the
    /// scheme reproduces, keeps the sign of, flattens or turns into the wrong sign at the centre
    #[command(name = "shape-chart", after_help = SHAPE_CHART_HELP)]
    ShapeChart(shape_chart::ShapeChartArgs),
    /// Figures (SVG, PDF or PNG by the file extension)
    Plot {
        #[command(subcommand)]
        what: charmap_commands::PlotWhat,
    },
}

/// How to read `subdlab shape-chart` (its `--help` epilogue).
const SHAPE_CHART_HELP: &str =
    "Inputs q = (x cos θ + y sin θ)² + t (−x sin θ + y cos θ)² sampled over the characteristic \
map's control points; per input, ν* is the largest eigenvalue below λ whose component shows on the ring, \
g = |ν*|/λ². Letters per cell (valence down, t from −1 to 1 across; panels m = 0, a middle m, ∞): \
C correct shape, R right sign of K, F flat (m = ∞, g < 1), D degenerate (t = 0), M mixed sign, W wrong sign; \
lower case: divergent (g > 1 or a Jordan chain at λ²). Example: subdlab shape-chart catmull-clark --valences 3..12 \
-o chart.svg --theta-out theta.png --theta-valence 5";
