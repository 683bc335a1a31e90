//! Where each analysis of a scheme runs, by the scheme's domain — the one
//! table (`route`) that the command line's front door (`cli::front_door`)
//! and the claims (`claims::common::spectra`) both consult, so that neither
//! decides by a scheme's name.

use crate::schemes::entry::Family;

/// The analyses a scheme of any domain can be asked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Analysis {
    Spectrum,
    CertifiedSpectrum,
    Stencils,
    Matrix,
    Charmap,
    CertifiedCharmap,
    Curvature,
}

impl Analysis {
    /// The analysis as the command a user types, for messages.
    pub fn command(self) -> &'static str {
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
pub enum Route {
    /// the mesh pipeline (configurations around an extraordinary vertex or face)
    Mesh,
    /// the domain's own pipeline: the invariant window on Z² or on Z
    Native,
    /// not defined on this domain; the reason, for the error message
    Refused(&'static str),
}

/// The domain a scheme lives on, as the user reads it.
pub fn space(domain: Family) -> &'static str {
    match domain {
        Family::Mesh => "meshes with an extraordinary vertex or face",
        Family::Lattice => "the regular lattice Z²",
        Family::Curve => "the line Z",
    }
}

/// What each domain does with each analysis. A lattice scheme is a mesh
/// scheme of valence 4 through its masks, so the surface analyses
/// (characteristic map, curvature) run there; its spectrum, stencils and
/// matrix are the lattice window's. A curve has no surface: no
/// characteristic map, no curvature.
pub fn route(domain: Family, analysis: Analysis) -> Route {
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

/// The refusal as one line: the analysis, the scheme, its domain and why.
pub fn refusal(analysis: Analysis, name: &str, domain: Family, why: &str) -> String {
    format!(
        "`{}` does not apply to '{name}': it is a {} scheme (domain: {}); {why}",
        analysis.command(),
        domain.name(),
        space(domain)
    )
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
        let e = refusal(Analysis::Charmap, "four-point", Family::Curve, "why");
        assert!(e.contains("`charmap`") && e.contains("'four-point'") && e.contains("curve scheme"), "{e}");
        assert!(e.contains("the line Z") && !e.contains('\n'), "{e}");
    }
}
