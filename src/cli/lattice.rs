//! The analysis commands (`spectrum`, `stencils`, `matrix`) on the native
//! windows of the schemes that have no mesh configuration: regular-lattice
//! schemes (built-in `khan-mustafa`, `khan-mustafa-cubic`, or a `domain =
//! "lattice"` file) and curve schemes (`spectrum` only, the same output as
//! `subdlab curve`). The front door (`cli::front_door`) resolves the scheme
//! and routes it here by its domain; lattice output reuses the mesh tables
//! and JSON types, so the stable field names are the same as for every other
//! scheme.

use super::commands::out_text;
use super::{AnalysisArgs, Command};
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
    if a.config.faces.is_some() {
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

/// A regular-lattice scheme under `spectrum`, `stencils` or `matrix`: the
/// analysis of its invariant window.
pub(super) fn run(cmd: &Command, built: Box<dyn LatticeScheme>) -> Result<(), Error> {
    let a = match cmd {
        Command::Spectrum { common: a, .. } | Command::Stencils(a) => a,
        Command::Matrix { common, .. } => common,
        _ => return Err(Error::Input(format!("'{}' is a lattice scheme: no such analysis here", built.name()))),
    };
    run_window(cmd, a, built)
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
    if a.config.faces.is_some() {
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
