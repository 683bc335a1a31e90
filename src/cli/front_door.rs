//! The one front door of the analysis commands (`spectrum`, `stencils`,
//! `matrix`, `charmap`, `curvature`, each with or without `--certify`).
//!
//! The scheme argument is resolved once (`schemes::registry::resolve`: a
//! built-in name or a scheme file, of any domain) into one value over the
//! domains (`registry::Built`), and each command asks that value's domain —
//! never the scheme's name — what it can do ([`route`]): run natively on the
//! domain (the lattice window, the curve window), run on the mesh pipeline
//! (mesh schemes, and lattice schemes through their masks on oriented quad
//! meshes, `schemes::lattice_on_mesh`), or refuse with a one-line reason that
//! names the domain.

use super::commands::parse_params;
use crate::cli::args::SchemeArgs;
use crate::cli::command_line::Command;
use crate::error::Error;
use crate::schemes::registry::{self, Built, Family};

/// The analyses the front door routes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Analysis {
    Spectrum,
    CertifiedSpectrum,
    Stencils,
    Matrix,
    Charmap,
    CertifiedCharmap,
    Curvature,
}

impl Analysis {
    fn of(cmd: &Command) -> Option<(Analysis, &SchemeArgs)> {
        Some(match cmd {
            Command::Spectrum { common, certify: false, .. } => (Analysis::Spectrum, &common.config),
            Command::Spectrum { common, certify: true, .. } => (Analysis::CertifiedSpectrum, &common.config),
            Command::Stencils(a) => (Analysis::Stencils, &a.config),
            Command::Matrix { common, .. } => (Analysis::Matrix, &common.config),
            Command::Charmap(a) if a.certify => (Analysis::CertifiedCharmap, &a.config),
            Command::Charmap(a) => (Analysis::Charmap, &a.config),
            Command::Curvature(a) => (Analysis::Curvature, &a.config),
            _ => return None,
        })
    }

    /// The command as the user typed it, for error messages.
    fn command(self) -> &'static str {
        match self {
            Analysis::Spectrum => "spectrum",
            Analysis::CertifiedSpectrum => "spectrum --certify",
            Analysis::Stencils => "stencils",
            Analysis::Matrix => "matrix",
            Analysis::Charmap => "charmap",
            Analysis::CertifiedCharmap => "charmap --certify",
            Analysis::Curvature => "curvature",
        }
    }
}

/// Where an analysis of a scheme of one domain runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Route {
    /// the mesh pipeline (configurations around an extraordinary vertex or face)
    Mesh,
    /// the domain's own pipeline: the invariant window on Z² or on Z
    Native,
    /// not defined on this domain; the reason, for the error message
    Refused(&'static str),
}

/// The domain a scheme lives on, as the user reads it.
fn space(domain: Family) -> &'static str {
    match domain {
        Family::Mesh => "meshes with an extraordinary vertex or face",
        Family::Lattice => "the regular lattice Z²",
        Family::Curve => "the line Z",
    }
}

/// What each domain does with each analysis: the one table the commands
/// consult. A lattice scheme is a mesh scheme of valence 4 through its masks,
/// so the surface analyses (characteristic map, curvature) run there; its
/// spectrum, stencils and matrix are the lattice window's. A curve has no
/// surface: no characteristic map, no curvature.
pub(super) fn route(domain: Family, analysis: Analysis) -> Route {
    use Analysis::*;
    match (domain, analysis) {
        (Family::Mesh, _) => Route::Mesh,
        // the window's matrix is rational: `--certify` proves its spectrum exactly (lemma S7)
        (Family::Lattice, Spectrum | CertifiedSpectrum | Stencils | Matrix) => Route::Native,
        (Family::Lattice, Charmap | CertifiedCharmap | Curvature) => Route::Mesh,
        (Family::Curve, Spectrum) => Route::Native,
        (Family::Curve, CertifiedSpectrum) => Route::Refused(
            "--certify covers mesh schemes only (and lattice schemes, by the exact route): its statement (λ1 a \
             double, semisimple eigenvalue) is that of a surface, and a curve's λ1 is simple",
        ),
        (Family::Curve, Stencils | Matrix) => Route::Refused(
            "its local matrix and eigenvalues are printed by `subdlab spectrum --json` (or `subdlab curve --json`), \
             which carries the matrix",
        ),
        (Family::Curve, Charmap | CertifiedCharmap) => Route::Refused(
            "a curve has no characteristic map of a surface (its subdominant eigenvector parametrises a line, not a \
             ring around a point)",
        ),
        (Family::Curve, Curvature) => Route::Refused(
            "a curve has no surface curvature at its centre (the second-order analysis needs a surface's \
             characteristic map)",
        ),
    }
}

/// The refusal as one line: the command, the scheme, its domain and why.
fn refusal(analysis: Analysis, name: &str, domain: Family, why: &str) -> Error {
    Error::Input(format!(
        "`{}` does not apply to '{name}': it is a {} scheme (domain: {}); {why}",
        analysis.command(),
        domain.name(),
        space(domain)
    ))
}

/// Runs an analysis command: `None` when `cmd` is not one. Flags that need
/// no scheme are checked first (as before any computation), then the scheme
/// is resolved once and its domain picks the route. Ok holds the exit status.
pub(super) fn dispatch(cmd: &Command) -> Option<Result<i32, Error>> {
    let (analysis, config) = Analysis::of(cmd)?;
    Some(run(cmd, analysis, config))
}

fn run(cmd: &Command, analysis: Analysis, config: &SchemeArgs) -> Result<i32, Error> {
    match cmd {
        Command::Charmap(a) => super::charmap_commands::check_flags(a)?,
        Command::Curvature(a) => super::curvature::check_flags(a)?,
        _ => {}
    }
    let built = registry::resolve(&config.scheme, &parse_params(&config.params)?)?;
    let domain = built.family();
    match (route(domain, analysis), built) {
        (Route::Refused(why), _) => Err(refusal(analysis, &config.scheme, domain, why)),
        (Route::Native, Built::Lattice(scheme)) => super::lattice::run(cmd, scheme),
        (Route::Native, Built::Curve(scheme)) => super::lattice::curve(cmd, scheme.as_ref()).map(|()| 0),
        (_, built) => {
            let scheme = crate::schemes::on_mesh(built, &config.scheme)?;
            super::mesh_analysis::mesh_analysis(cmd, scheme)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesh_schemes_run_every_analysis_on_the_mesh() {
        use Analysis::*;
        for a in [Spectrum, CertifiedSpectrum, Stencils, Matrix, Charmap, CertifiedCharmap, Curvature] {
            assert_eq!(route(Family::Mesh, a), Route::Mesh, "{a:?}");
        }
    }

    #[test]
    fn a_curve_has_no_surface_analyses() {
        for a in [Analysis::Charmap, Analysis::CertifiedCharmap, Analysis::Curvature] {
            let Route::Refused(why) = route(Family::Curve, a) else { panic!("{a:?} routed on a curve") };
            assert!(why.contains("a curve has no"), "{why}");
        }
        assert_eq!(route(Family::Curve, Analysis::Spectrum), Route::Native);
    }

    #[test]
    fn refusals_name_the_command_the_scheme_and_the_domain() {
        let e = refusal(Analysis::Charmap, "four-point", Family::Curve, "why").to_string();
        assert!(e.contains("`charmap`") && e.contains("'four-point'") && e.contains("curve scheme"), "{e}");
        assert!(e.contains("the line Z") && !e.contains('\n'), "{e}");
    }
}
