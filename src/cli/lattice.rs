//! The analysis commands (`spectrum`, `stencils`, `matrix`) for the schemes
//! that have no mesh configuration: regular-lattice schemes (built-in
//! `khan-mustafa`, `khan-mustafa-cubic`, or a `domain = "lattice"` file) and
//! curve schemes (`spectrum` only, the same output as `subdlab curve`). The
//! family comes from the one registry (`schemes::registry`); lattice output
//! reuses the mesh tables and JSON types, so the stable field names are the
//! same as for every other scheme.

use super::commands::{out_text, parse_params};
use super::{AnalysisArgs, Command};
use crate::error::Error;
use crate::io::{print_json, write_atomic};
use crate::lattice::analysis::{analyse, LatticeAnalysis};
use crate::lattice::{self, LatticeScheme};
use crate::matrix::export::{to_matrix_market, MatrixJson};
use crate::neighbourhood::NeighbourhoodKind;
use crate::schemes::registry::{self, Family};
use crate::spectrum::stencils::stencils;

/// `None` when the command is not an analysis of a lattice or curve scheme
/// (the mesh path runs, and reports unknown names and unreadable files).
pub(super) fn dispatch(cmd: &Command) -> Option<Result<(), Error>> {
    let args = match cmd {
        Command::Spectrum { common: a, .. } | Command::Stencils(a) => a,
        Command::Matrix { common, .. } => common,
        // only the analysis commands are routed by family here
        _ => return None,
    };
    match registry::family_of(&args.scheme) {
        Ok(Family::Lattice) => Some(run(cmd, args)),
        Ok(Family::Curve) => Some(curve(cmd, args)),
        Ok(Family::Mesh) | Err(_) => None,
    }
}

/// A curve scheme under `spectrum`: its vertex has two neighbours, so the
/// valence must be 2; the output is that of `subdlab curve`.
fn curve(cmd: &Command, a: &AnalysisArgs) -> Result<(), Error> {
    let name = &a.scheme;
    if !matches!(cmd, Command::Spectrum { .. }) {
        return Err(Error::Input(format!(
            "'{name}' is a curve scheme: use `subdlab spectrum` or `subdlab curve` (the JSON carries the matrix)"
        )));
    }
    if matches!(cmd, Command::Spectrum { certify: true, .. }) {
        return Err(Error::Input(format!("--certify covers mesh schemes only; '{name}' is a curve scheme")));
    }
    if a.valence != 2 {
        return Err(Error::Input(format!(
            "'{name}' is a curve scheme: a curve vertex has two neighbours (use --valence 2)"
        )));
    }
    if a.faces.is_some() {
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
    super::mesh_commands::curve(name, &a.params, &a.neighbourhood, a.json)
}

fn run(cmd: &Command, a: &AnalysisArgs) -> Result<(), Error> {
    let (built, analysis) = prepare(a)?;
    let scheme = built.as_ref();
    match cmd {
        Command::Spectrum { certify: true, .. } => {
            Err(Error::Input(format!("--certify covers mesh schemes only; '{}' is a lattice scheme", a.scheme)))
        }
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
fn prepare(a: &AnalysisArgs) -> Result<(Box<dyn LatticeScheme>, LatticeAnalysis), Error> {
    let name = a.scheme.as_str();
    if a.valence != 4 {
        return Err(Error::Input(format!("{name} is defined on the regular quad lattice only (valence 4)")));
    }
    if a.faces.is_some() {
        return Err(Error::Input(format!("scheme '{name}' takes no --faces: it lives on the regular quad lattice")));
    }
    let scheme = registry::lattice(name, &parse_params(&a.params)?)?;
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
