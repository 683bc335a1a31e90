//! `subdlab curvature`: the second-order analysis at an extraordinary point
//! (curvature class, L_p limit, F(μ) and shapes, Reif's C² test) and its figures.

use std::path::PathBuf;

use clap::Args;

use super::charmap_commands::check_out;
use crate::cli::args::{FigureArgs, SchemeArgs};
use crate::curvature::{curvature, Curvature, CurvatureOptions, Quadratic, DEFAULT_LEVELS, MAX_LEVELS};
use crate::error::Error;
use crate::io::print_json;
use crate::plot::{self, curvature::CurvatureFigure, curvature::CurvatureFigureKind};

#[derive(Args, Debug, Clone)]
pub struct CurvatureArgs {
    #[command(flatten)]
    pub config: SchemeArgs,
    /// analysis steps of refinement of the ring samples (1 to 6)
    #[arg(long, default_value_t = DEFAULT_LEVELS)]
    pub levels: usize,
    /// write a figure (.svg, .pdf or .png); which one: --figure
    #[arg(short = 'o', long)]
    pub out: Option<PathBuf>,
    /// central-ring (μ-eigenfunctions over the characteristic ring) or
    /// surface (sign of Gaussian curvature of refined quadratics, per ring)
    #[arg(long, default_value = "central-ring")]
    pub figure: String,
    /// rings of the surface figure (1 to 8)
    #[arg(long, default_value_t = 4)]
    pub rings: usize,
    /// the surface figure's input quadratic q = (x cos θ + y sin θ)² +
    /// T (−x sin θ + y cos θ)², as T,THETA (T in [−1, 1], THETA in degrees);
    /// default: two rows, T = 0.5 and T = −0.5 at THETA = 23
    #[arg(long, value_name = "T,THETA", allow_hyphen_values = true)]
    pub input: Option<String>,
    /// skip the exact rational confirmation (evidence is then floating-point)
    #[arg(long)]
    pub no_exact: bool,
    /// machine-readable JSON output (stable field names)
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub style: FigureArgs,
}

/// The flags of `curvature` that need no scheme, checked before the scheme
/// is resolved; the figure kind they name.
pub(super) fn check_flags(a: &CurvatureArgs) -> Result<(), Error> {
    figure_kind(a).map(|_| ())
}

fn figure_kind(a: &CurvatureArgs) -> Result<CurvatureFigureKind, Error> {
    if a.levels == 0 || a.levels > MAX_LEVELS {
        return Err(Error::Input(format!("--levels must be between 1 and {MAX_LEVELS}, got {}", a.levels)));
    }
    if a.rings == 0 || a.rings > 8 {
        return Err(Error::Input(format!("--rings must be between 1 and 8, got {}", a.rings)));
    }
    let kind = match a.figure.as_str() {
        "central-ring" => CurvatureFigureKind::CentralRing,
        "surface" => CurvatureFigureKind::Surface,
        other => return Err(Error::Input(format!("unknown figure '{other}'; use central-ring or surface"))),
    };
    if let Some(q) = &a.input {
        Quadratic::parse(q)?;
    }
    let style = a.style.style()?;
    if style.xlim.is_some() || style.ylim.is_some() {
        return Err(Error::Input(
            "--xlim/--ylim set a numeric axis; the curvature figures' panels share the ring's own window".into(),
        ));
    }
    if let Some(out) = &a.out {
        check_out(out)?;
    }
    Ok(kind)
}

/// `curvature` of the scheme the front door resolved.
pub fn run(a: &CurvatureArgs, scheme: Box<dyn crate::schemes::Scheme>) -> Result<(), Error> {
    let kind = figure_kind(a)?;
    let style = a.style.style()?;
    let config = super::commands::configuration(scheme.as_ref(), &a.config)?;
    super::commands::refuse_tagged("curvature", &config)?;
    let opts = CurvatureOptions {
        levels: a.levels,
        figures: a.out.is_some(),
        surface_rings: if a.out.is_some() && kind == CurvatureFigureKind::Surface { a.rings } else { 0 },
        input: a.input.as_deref().map(Quadratic::parse).transpose()?,
        exact: !a.no_exact,
    };
    let c = curvature(scheme.as_ref(), &config, &opts)?;
    if let Some(out) = &a.out {
        if c.figures.is_none() {
            return Err(Error::Input(format!("no figure written: the curvature class is {}", c.class.name())));
        }
        let fig = CurvatureFigure { c: &c, kind, style };
        plot::save(&fig, out)?;
        plot::save_data(&fig, a.style.data_path()?)?;
    }
    if a.json {
        print_json(&c)
    } else {
        crate::io::out(&table(&c))
    }
}

fn table(c: &Curvature) -> String {
    let f = crate::spectrum::fmt_f;
    let opt = |x: Option<f64>| x.map_or("-".to_string(), f);
    let mut out = format!(
        "scheme {}  valence {}  faces {}\nλ = {}  λ² = {}  |μ| = {}  |μ|/λ² = {}\n\n",
        c.scheme,
        c.valence,
        c.faces,
        opt(c.lambda),
        opt(c.lambda_squared),
        opt(c.mu.as_ref().map(|m| m.modulus)),
        opt(c.mu_over_lambda_squared)
    );
    if let Some(note) = super::commands::unused_centre_weight(&c.scheme, &c.params, &c.faces) {
        out += &format!("{note}\n");
    }
    out += &format!("curvature class  {}  (evidence: {})\n", c.class.name(), c.evidence.name());
    out += &format!(
        "L_p limit        {}\n",
        match (c.class, c.lp_limit) {
            (_, Some(p)) => format!("principal curvatures in L_p for p < {}", f(p)),
            (crate::curvature::CurvatureClass::NotApplicable, None) => "-".into(),
            (_, None) => "every finite p".into(),
        }
    );
    if let Some(s) = &c.shapes {
        out += &format!(
            "F(μ)             {:?}  (necessary condition F ⊇ {{0, 2, n−2}}: {})\nshapes           elliptic {}  saddle {}\n",
            s.fourier_index,
            if s.necessary_condition { "holds" } else { "fails" },
            if s.elliptic_possible { "possible" } else { "impossible" },
            if s.saddle_possible { "possible" } else { "impossible" }
        );
    }
    if let Some(t) = &c.c2 {
        out += &format!(
            "C² test (Reif)   {}  (quadratic {}, spans x², xy, y²: {}, largest residual {})\n",
            // the flat-spot class passes only with zero curvature at the
            // centre: say so rather than a bare "holds" (JSON keeps holds)
            match (t.holds, c.class) {
                (true, crate::curvature::CurvatureClass::Zero) => "C² (flat: curvature → 0)",
                (true, _) => "holds",
                (false, _) => "fails",
            },
            t.quadratic,
            t.spans_quadratics,
            t.max_residual.map_or("-".into(), |r| format!("{r:.3e}"))
        );
    }
    if !c.examined.is_empty() {
        out += "\neigenvalues below λ examined:\n";
        for e in &c.examined {
            out += &format!(
                "  {:<24} |·|/λ² = {:<12} blocks {:?}{}{}\n",
                if e.im == 0.0 { f(e.re) } else { format!("{}{:+}i", f(e.re), e.im) },
                f(e.over_lambda_squared),
                e.blocks,
                if e.defective { "  defective" } else { "" },
                if e.vanishes { "  (vanishes on the ring: excluded)" } else { "" }
            );
        }
    }
    out += "\n";
    for r in &c.reasons {
        out += &format!("  - {r}\n");
    }
    if let Some(s) = &c.shapes {
        out += &format!("  - {}\n", s.explanation);
    }
    if let Some(t) = &c.c2 {
        for r in &t.reasons {
            out += &format!("  - C²: {r}\n");
        }
    }
    out
}
