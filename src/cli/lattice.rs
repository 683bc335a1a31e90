//! Routing of the regular-lattice schemes (`khan-mustafa`, `khan-mustafa-cubic`)
//! on the command line. They have no mesh configuration, so they are handled
//! before the mesh-based path; output reuses the same tables and JSON types, so
//! the stable field names are the same as for every other scheme.

use super::{AnalysisArgs, Command};
use crate::io::{print_json, write_atomic};
use crate::lattice::analysis::{analyse, LatticeAnalysis};
use crate::lattice::{self, LatticeScheme};
use crate::matrix::export::{to_matrix_market, MatrixJson};
use crate::neighbourhood::NeighbourhoodKind;
use crate::spectrum::stencils::stencils;

/// `None` when the command does not name a lattice scheme (the mesh path runs).
pub(super) fn dispatch(cmd: &Command) -> Option<Result<(), String>> {
    let args = match cmd {
        Command::Spectrum(a) | Command::Stencils(a) => a,
        Command::Matrix { common, .. } => common,
        // only the analysis commands concern lattice schemes
        _ => return None,
    };
    let entry = lattice::find(&args.scheme)?;
    let scheme = (entry.build)();
    Some(run(cmd, args, scheme.as_ref()))
}

fn run(cmd: &Command, a: &AnalysisArgs, scheme: &dyn LatticeScheme) -> Result<(), String> {
    let analysis = prepare(a, scheme)?;
    match cmd {
        Command::Spectrum(_) => {
            if a.json {
                print_json(&analysis.spectrum)
            } else {
                print!("{}", super::commands::spectrum_table(&analysis.spectrum));
                println!("window: {}", window_text(&analysis.window));
                Ok(())
            }
        }
        Command::Stencils(_) => {
            let st = stencils(&analysis.spectrum)?;
            if a.json {
                print_json(&st)
            } else {
                print!("{}", super::commands::stencil_table(&st));
                Ok(())
            }
        }
        Command::Matrix { format, output, .. } => {
            let m = &analysis.matrix;
            let text = match format.as_str() {
                "mtx" => to_matrix_market(
                    m,
                    &format!(
                        "subdlab local subdivision matrix: scheme {} (regular lattice) neighbourhood {:?}\nwindow {}",
                        scheme.name(),
                        m.kind,
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
                    serde_json::to_string_pretty(&j).map_err(|e| e.to_string())? + "\n"
                }
                other => return Err(format!("unknown matrix format '{other}'; use mtx or json")),
            };
            match output {
                Some(p) => write_atomic(p, text.as_bytes()),
                None => {
                    print!("{text}");
                    Ok(())
                }
            }
        }
        _ => Ok(()),
    }
}

/// Check the options that make sense on the lattice, then analyse.
fn prepare(a: &AnalysisArgs, scheme: &dyn LatticeScheme) -> Result<LatticeAnalysis, String> {
    let name = scheme.name();
    if a.valence != 4 {
        return Err(format!("{name} is defined on the regular quad lattice only (valence 4)"));
    }
    if a.faces.is_some() {
        return Err(format!("scheme '{name}' takes no --faces: it lives on the regular quad lattice"));
    }
    if let Some(p) = a.params.first() {
        let key = p.split_once('=').map(|(k, _)| k.trim()).unwrap_or(p.as_str());
        return Err(format!("scheme '{name}' has no parameters (got '{key}')"));
    }
    match a.method.as_deref() {
        None | Some("full") => {}
        Some("dft") => return Err(format!("{name} has asymmetric masks and no rotation symmetry; use --method full")),
        Some(m) => return Err(format!("unknown method '{m}'; use dft or full")),
    }
    let kind: NeighbourhoodKind = a.neighbourhood.parse()?;
    analyse(scheme, kind, !a.no_exact)
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

/// The lattice schemes for `subdlab schemes`: (name, description), no parameters.
pub(super) fn scheme_list() -> Vec<(&'static str, &'static str)> {
    lattice::registry().into_iter().map(|e| (e.name, e.description)).collect()
}
