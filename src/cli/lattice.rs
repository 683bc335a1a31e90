//! The analysis commands (`spectrum`, `stencils`, `matrix`) on the native
//! windows of the schemes that have no mesh configuration: regular-lattice
//! schemes (built-in `khan-mustafa`, `khan-mustafa-cubic`, or a `domain =
//! "lattice"` file) and curve schemes (`spectrum` only, the same output as
//! `subdlab curve`). The front door (`cli::front_door`) resolves the scheme
//! and routes it here by its domain; lattice output reuses the mesh tables
//! and JSON types, so the stable field names are the same as for every other
//! scheme.

use super::commands::out_text;
use crate::cli::args::AnalysisArgs;
use crate::cli::command_line::Command;
use crate::curves::CurveScheme;
use crate::error::Error;
use crate::io::{print_json, write_atomic};
use crate::lattice::analysis::{analyse, LatticeAnalysis};
use crate::lattice::{self, LatticeScheme};
use crate::matrix::export::{to_matrix_market, MatrixJson};
use crate::neighbourhood::NeighbourhoodKind;
use crate::spectrum::stencils::stencils;

/// A curve scheme under `spectrum` (the front door routes only that here):
/// its vertex has two neighbours, so the valence must be 2; the output is
/// that of `subdlab curve`.
pub(super) fn curve(cmd: &Command, scheme: &dyn CurveScheme) -> Result<(), Error> {
    let Command::Spectrum { common: a, .. } = cmd else {
        return Err(Error::Input(format!("'{}' is a curve scheme: only `subdlab spectrum` runs on it", scheme.name())));
    };
    let name = &a.config.scheme;
    if a.config.valence != 2 {
        return Err(Error::Input(format!(
            "'{name}' is a curve scheme: a curve vertex has two neighbours (use --valence 2)"
        )));
    }
    if a.config.setup.faces.is_some() {
        return Err(Error::Input(format!("scheme '{name}' takes no --faces: it is a curve scheme")));
    }
    match a.method.as_deref() {
        None | Some("full") => {}
        Some(m) => {
            return Err(Error::Input(format!(
                "'{name}' is a curve scheme: its matrix is analysed whole (got --method {m})"
            )))
        }
    }
    super::mesh_commands::curve_of(scheme, &a.neighbourhood, a.json)
}

/// A regular-lattice scheme under `spectrum` (with or without `--certify`),
/// `stencils` or `matrix`: the analysis of its invariant window. Ok holds the
/// exit status (`spectrum --certify`: 0 only when PROVED).
pub(super) fn run(cmd: &Command, built: Box<dyn LatticeScheme>) -> Result<i32, Error> {
    let a = match cmd {
        Command::Spectrum { common: a, .. } | Command::Stencils(a) => a,
        Command::Matrix { common, .. } => common,
        _ => return Err(Error::Input(format!("'{}' is a lattice scheme: no such analysis here", built.name()))),
    };
    if let Command::Spectrum { certify: true, certificate, .. } = cmd {
        if certificate.is_some() {
            return Err(Error::Input(format!(
                "--certificate writes the document of a mesh configuration's proof; '{}' is a lattice scheme, whose \
                 proof is the exact route printed (and given by --json)",
                a.config.scheme
            )));
        }
        return certified(a, built);
    }
    run_window(cmd, a, built).map(|()| 0)
}

/// What `spectrum --certify` proves of a lattice scheme: lemma S7 on the
/// window's whole matrix, which is rational (the masks are): 1 simple, λ1 a
/// double root of det(xI − S) with a two-dimensional eigenspace, every other
/// root strictly inside |x| < λ1 (ARCHITECTURE.md, "The proofs, step by
/// step"). No enclosure is involved, so nothing is conditional.
#[derive(serde::Serialize)]
struct LatticeCertificate {
    #[serde(flatten)]
    verdict: crate::certify::Verdict,
    statement: &'static str,
    method: &'static str,
    exact_route: Option<crate::certify::exact_spectrum::ExactSpectrum>,
}

const LATTICE_STATEMENT: &str = "λ0 = 1 is simple; λ1 = λ2 is real, positive and semisimple; every other eigenvalue \
has modulus < λ1 (the spectral conditions of Reif's criterion, for the window's matrix)";

fn certified(a: &AnalysisArgs, scheme: Box<dyn LatticeScheme>) -> Result<i32, Error> {
    use crate::certify::exact_spectrum::prove;
    use crate::certify::Verdict;
    use crate::numeric::{Cyclotomic, Weight as _};
    let (_, analysis) = prepare(a, scheme)?;
    let q = &analysis.exact_matrix;
    let rows: crate::certify::matrix::ExactRows = (0..q.size())
        .map(|i| {
            let row = (0..q.size()).map(|j| (j, q.get(i, j))).filter(|(_, w)| !w.is_zero());
            Some(row.map(|(j, w)| (j, Cyclotomic::from_rational(&w))).collect())
        })
        .collect();
    // the floating-point eigenvalues only propose λ1; the proof is exact
    let s = &analysis.spectrum;
    let reals = s.eigenvalues.iter().filter(|e| e.im.abs() <= 1e-9 * e.modulus.max(1.0)).map(|e| e.re);
    let candidates = crate::engine::exact::candidates(reals);
    let (verdict, exact_route) = match prove(&rows, &candidates) {
        Ok(e) if e.proved => (Verdict::Proved, Some(e)),
        Ok(e) => (Verdict::Disproved(e.why.clone()), Some(e)),
        Err(why) => (Verdict::NotProved(why), None),
    };
    let status = if verdict == Verdict::Proved { 0 } else { 1 };
    let c = LatticeCertificate {
        verdict,
        statement: LATTICE_STATEMENT,
        method: "exact: lemma S7 on the whole matrix of the window, over Q",
        exact_route,
    };
    if a.json {
        #[derive(serde::Serialize)]
        struct Certified<'a> {
            #[serde(flatten)]
            spectrum: &'a crate::spectrum::Spectrum,
            certificate: &'a LatticeCertificate,
        }
        print_json(&Certified { spectrum: s, certificate: &c })?;
    } else {
        let mut text = format!(
            "{}window: {}\n\ncertified spectral C1 conditions: {}\n  statement: {}\n",
            super::commands::spectrum_table(s),
            window_text(&analysis.window),
            c.verdict.display(),
            c.statement
        );
        if let Some(e) = &c.exact_route {
            text += &format!(
                "  exact route (lemma S7): det(xI − S) over Q ({} × {}): 1 of multiplicity {}, λ1 = {} of algebraic \
                 multiplicity {} and geometric multiplicity {}, the other {} roots inside |x| < {} (Schur–Cohn)\n",
                e.size,
                e.size,
                e.one_multiplicity,
                e.lambda1.as_deref().unwrap_or("-"),
                e.algebraic,
                e.geometric,
                e.cofactor_degree,
                e.others_below.as_deref().unwrap_or("-")
            );
        }
        out_text(&text)?;
    }
    Ok(status)
}

fn run_window(cmd: &Command, a: &AnalysisArgs, built: Box<dyn LatticeScheme>) -> Result<(), Error> {
    let (built, analysis) = prepare(a, built)?;
    let scheme = built.as_ref();
    match cmd {
        Command::Spectrum { .. } => {
            if a.json {
                print_json(&analysis.spectrum)
            } else {
                out_text(&format!(
                    "{}window: {}\n",
                    super::commands::spectrum_table(&analysis.spectrum),
                    window_text(&analysis.window)
                ))
            }
        }
        Command::Stencils(_) => {
            let st = stencils(&analysis.spectrum)?;
            if a.json {
                print_json(&st)
            } else {
                out_text(&super::commands::stencil_table(&st))
            }
        }
        Command::Matrix { format, output, .. } => {
            let m = &analysis.matrix;
            let text = match super::commands::matrix_format(format.as_deref(), a.json)? {
                "mtx" => to_matrix_market(
                    m,
                    &format!(
                        "subdlab local subdivision matrix: scheme {} (regular lattice) neighbourhood {}\nwindow {}",
                        scheme.name(),
                        super::commands::kind_name(m.kind),
                        window_text(&analysis.window)
                    ),
                ),
                "json" => {
                    let q = &analysis.exact_matrix;
                    let j = MatrixJson {
                        scheme: scheme.name(),
                        valence: 4,
                        neighbourhood: m.kind,
                        size: m.size(),
                        labels: m.labels.iter().map(|l| l.name.as_str()).collect(),
                        vertices: &m.labels,
                        matrix: m.to_dense_f64(),
                        exact: Some(
                            (0..q.size()).map(|i| (0..q.size()).map(|j| q.get(i, j).to_string()).collect()).collect(),
                        ),
                    };
                    crate::io::json_text(&j)? + "\n"
                }
                other => return Err(Error::Input(format!("unknown matrix format '{other}'; use mtx or json"))),
            };
            match output {
                Some(p) => write_atomic(p, text.as_bytes()),
                None => out_text(&text),
            }
        }
        _ => Ok(()),
    }
}

/// Check the options that make sense on the lattice, build the scheme with
/// its parameters, then analyse.
fn prepare(
    a: &AnalysisArgs,
    scheme: Box<dyn LatticeScheme>,
) -> Result<(Box<dyn LatticeScheme>, LatticeAnalysis), Error> {
    let name = a.config.scheme.as_str();
    if a.config.valence != 4 {
        return Err(Error::Input(format!("{name} is defined on the regular quad lattice only (valence 4)")));
    }
    if a.config.setup.faces.is_some() {
        return Err(Error::Input(format!("scheme '{name}' takes no --faces: it lives on the regular quad lattice")));
    }
    match a.method.as_deref() {
        None | Some("full") => {}
        Some("dft") => {
            return Err(Error::Input(format!(
                "{name} has asymmetric masks and no rotation symmetry; use --method full"
            )))
        }
        Some(m) => return Err(Error::Input(format!("unknown method '{m}'; use dft or full"))),
    }
    let kind: NeighbourhoodKind = a.neighbourhood.parse()?;
    let analysis = analyse(scheme.as_ref(), kind, !a.no_exact)?;
    Ok((scheme, analysis))
}

/// "6×6 rectangle i = -3..2, j = -3..2" or "N points".
fn window_text(w: &lattice::Window) -> String {
    match w.bounds() {
        Some((i0, i1, j0, j1)) if w.is_rect() => format!(
            "{}×{} rectangle of lattice points p[i+l,j+m], l = {i0}..{i1}, m = {j0}..{j1} (l fastest)",
            i1 - i0 + 1,
            j1 - j0 + 1
        ),
        _ => format!("{} lattice points", w.len()),
    }
}
