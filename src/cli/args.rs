//! The argument groups several commands share: the figure style flags
//! (`FigureArgs`), the scheme and configuration of every analysis command
//! (`SchemeArgs`, `AnalysisArgs`), and `sweep`'s arguments (`SweepArgs`).
//! Imports no other file of `cli`, so every command's file imports it.

use clap::Args;

/// What a figure's reader sees besides the data (title, size, font,
/// resolution): the style flags every figure command takes (`charmap`,
/// `curvature`, `plot spectrum`, `plot compare`, `sweep --plot`).
#[derive(Args, Debug, Clone, Default)]
pub struct FigureArgs {
    /// the figure's title (an empty text: no title); default: names the scheme
    #[arg(long)]
    pub title: Option<String>,
    /// figure width in points (SVG user units, PDF points), 120 to 6000
    #[arg(long)]
    pub width: Option<u32>,
    /// figure height in points (SVG user units, PDF points), 120 to 6000
    #[arg(long)]
    pub height: Option<u32>,
    /// base font size (tick labels) in points, 6 to 72; other text scales with it
    #[arg(long)]
    pub font_size: Option<u32>,
    /// PNG resolution in dots per inch, 36 to 1200 (default 150): the PNG has
    /// width × dpi / 72 pixels; SVG and PDF are vector and ignore it
    #[arg(long)]
    pub dpi: Option<f64>,
    /// where the legend goes: auto (right of the plot when it fits, else
    /// below), right, below, upper-right, upper-left, lower-right, lower-left
    /// (inside the plot, over the data) or none
    #[arg(long)]
    pub legend: Option<String>,
    /// the x axis's range A:B (figures with a numeric x axis: not the curvature figures)
    #[arg(long, value_name = "A:B", allow_hyphen_values = true)]
    pub xlim: Option<String>,
    /// the y axis's range A:B (figures with a numeric y axis: not the curvature figures)
    #[arg(long, value_name = "A:B", allow_hyphen_values = true)]
    pub ylim: Option<String>,
    /// also write the plotted numbers to FILE.csv (a header line, then one row per point)
    #[arg(long, value_name = "FILE.csv")]
    pub data: Option<std::path::PathBuf>,
}

impl FigureArgs {
    /// Whether any style flag was given (they need a figure to shape).
    pub fn is_set(&self) -> bool {
        self.title.is_some()
            || self.width.is_some()
            || self.height.is_some()
            || self.font_size.is_some()
            || self.dpi.is_some()
            || self.legend.is_some()
            || self.data.is_some()
            || self.xlim.is_some()
            || self.ylim.is_some()
    }
    /// The `--data` file, which must end in `.csv` (any case).
    pub fn data_path(&self) -> Result<Option<&std::path::Path>, crate::error::Error> {
        match &self.data {
            Some(p) if p.extension().and_then(|e| e.to_str()).is_some_and(|e| e.eq_ignore_ascii_case("csv")) => {
                Ok(Some(p.as_path()))
            }
            Some(p) => Err(crate::error::Error::Input(format!("--data {}: the file must end in .csv", p.display()))),
            None => Ok(None),
        }
    }
    pub fn style(&self) -> Result<crate::plot::Style, crate::error::Error> {
        self.data_path()?;
        crate::plot::Style {
            title: self.title.clone(),
            width: self.width,
            height: self.height,
            font_size: self.font_size,
            dpi: self.dpi,
            legend: self.legend.as_deref().map(crate::plot::layout::LegendPosition::parse).transpose()?,
            xlim: self.xlim.as_deref().map(|t| crate::plot::parse_limits("--xlim", t)).transpose()?,
            ylim: self.ylim.as_deref().map(|t| crate::plot::parse_limits("--ylim", t)).transpose()?,
            labels: Vec::new(),
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
    #[command(flatten)]
    pub setup: SchemeSetup,
    /// a tagged vertex instead of an interior one (schemes with crease
    /// rules): boundary (the valence counts the faces of the open fan, from
    /// 1), corner (the same, the centre kept in place), crease:K (sharp rays
    /// at sectors 0 and K of a closed fan) or dart (one sharp ray)
    #[arg(long)]
    pub tag: Option<String>,
}

/// The scheme's parameters and the faces around the centre: shared by
/// [`SchemeArgs`] and the commands that run over a range of valences
/// (`shape-chart`).
#[derive(Args, Debug, Clone, Default)]
pub struct SchemeSetup {
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

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// scheme name or scheme file
    pub scheme: String,
    /// valence range A..B (with --tag: the sectors of the tagged configuration, e.g. 1..8)
    #[arg(long, visible_alias = "sectors")]
    pub valences: String,
    /// sweep a tagged vertex instead of an interior one (as `spectrum --tag`): boundary, corner,
    /// crease:K or dart; the verdict is then the sector criterion
    #[arg(long)]
    pub tag: Option<String>,
    /// NAME=VALUE fixes a parameter; NAME=START:END:STEP sweeps one (at most two: a second draws
    /// the plane of both at one valence, with the exact ends of the first at each value of the second)
    #[arg(long = "param", short = 'p')]
    pub params: Vec<String>,
    /// also check the characteristic map at every point that passes the spectral test
    #[arg(long)]
    pub charmap: bool,
    /// also compute the curvature class and L_p limit at every point (as `subdlab curvature
    /// --no-exact`; opt-in: about a curvature run per point, far more than the spectrum); with
    /// --exact: the exact sets of each curvature class
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
    /// exact sets of the swept parameter per valence: convergence and spectral C¹ as unions of
    /// intervals with exact algebraic endpoints (the grid's START and END bound the range; its
    /// points are not the answer)
    #[arg(long)]
    pub exact: bool,
    /// with --exact: decide each piece with the interval certificate as well (slower; else the
    /// floating-point spectrum decides)
    #[arg(long)]
    pub certify: bool,
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
