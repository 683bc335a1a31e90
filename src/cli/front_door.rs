//! The one front door of the analysis commands (`spectrum`, `stencils`,
//! `matrix`, `charmap`, `curvature`, each with or without `--certify`).
//!
//! The scheme argument is resolved once (`schemes::registry::resolve`: a
//! built-in name or a scheme file, of any domain) into one value over the
//! domains (`registry::Built`), and each command asks that value's domain —
//! never the scheme's name — what it can do (`schemes::route::route`, the
//! table the claims consult too): run natively on the
//! domain (the lattice window, the curve window), run on the mesh pipeline
//! (mesh schemes, and lattice schemes through their masks on oriented quad
//! meshes, `schemes::lattice_on_mesh`), or refuse with a one-line reason that
//! names the domain.

use super::commands::parse_params;
use crate::cli::args::SchemeArgs;
use crate::cli::command_line::Command;
use crate::error::Error;
use crate::schemes::registry::{self, Built};
use crate::schemes::route::{refusal, route, Analysis, Route};

/// The analysis a command asks for, and its scheme arguments; `None` for a
/// command that is not an analysis.
fn analysis_of(cmd: &Command) -> Option<(Analysis, &SchemeArgs)> {
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

/// Runs an analysis command: `None` when `cmd` is not one. Flags that need
/// no scheme are checked first (as before any computation), then the scheme
/// is resolved once and its domain picks the route. Ok holds the exit status.
pub(super) fn dispatch(cmd: &Command) -> Option<Result<i32, Error>> {
    let (analysis, config) = analysis_of(cmd)?;
    Some(run(cmd, analysis, config))
}

fn run(cmd: &Command, analysis: Analysis, config: &SchemeArgs) -> Result<i32, Error> {
    match cmd {
        Command::Charmap(a) => super::charmap_commands::check_flags(a)?,
        Command::Curvature(a) => super::curvature::check_flags(a)?,
        _ => {}
    }
    let built = registry::resolve(&config.scheme, &parse_params(&config.setup.params)?)?;
    let domain = built.family();
    match (route(domain, analysis), built) {
        (Route::Refused(why), _) => Err(Error::Input(refusal(analysis, &config.scheme, domain, why))),
        (Route::Native, Built::Lattice(scheme)) => super::lattice::run(cmd, scheme),
        (Route::Native, Built::Curve(scheme)) => super::lattice::curve(cmd, scheme.as_ref()).map(|()| 0),
        (_, built) => {
            let scheme = crate::schemes::on_mesh(built, &config.scheme)?;
            super::mesh_analysis::mesh_analysis(cmd, scheme)
        }
    }
}
