//! What the commands' files share: scheme parameters and configuration
//! from the flags, the exit status of a certified verdict, and the tables and
//! formats the analyses print. Imports no command's file.

use std::collections::BTreeMap;

use crate::cli::args::SchemeArgs;
use crate::error::Error;
use crate::neighbourhood::{Configuration, NeighbourhoodKind, Tagging};
use crate::schemes::Scheme;
use crate::spectrum::{Method, Spectrum};

/// The exit status of a command that prints a certified verdict, with the
/// meaning `verify` gives it: 0 PROVED unconditionally; 1 anything else
/// (DISPROVED, NOT PROVED, or PROVED only given premises confirmed to
/// interval overlap, which a certified claim reads as INCONCLUSIVE). Errors
/// exit 2 before a verdict exists.
pub(super) fn certified_status(verdict: &crate::certify::Verdict, conditional: bool) -> i32 {
    match verdict {
        crate::certify::Verdict::Proved if !conditional => 0,
        _ => 1,
    }
}

pub(super) use crate::io::out as out_text;

/// The matrix format: `--format` (mtx or json), or json for `--json`.
pub(super) fn matrix_format(format: Option<&str>, json: bool) -> Result<&str, Error> {
    match (format, json) {
        (None, false) => Ok("mtx"),
        (None, true) | (Some("json"), _) => Ok("json"),
        (Some(f), true) => Err(Error::Input(format!("--json asks for the json format, but --format is {f}"))),
        (Some(f), false) => Ok(f),
    }
}

/// "minimal" or "analysis", as on the command line.
pub(super) fn kind_name(k: NeighbourhoodKind) -> &'static str {
    match k {
        NeighbourhoodKind::Minimal => "minimal",
        NeighbourhoodKind::Analysis => "analysis",
    }
}

pub(super) fn parse_params(list: &[String]) -> Result<Vec<(String, String)>, Error> {
    list.iter()
        .map(|p| {
            p.split_once('=')
                .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
                .ok_or_else(|| Error::Input(format!("parameter '{p}' is not of the form NAME=VALUE")))
        })
        .collect()
}

/// The scheme (name or file, with `--param`s) and its configuration at the
/// valence (regular, or the `--faces` sequence), as every analysis command
/// reads them.
pub(super) fn configuration(scheme: &dyn Scheme, a: &SchemeArgs) -> Result<Configuration, Error> {
    match (a.tag.as_deref(), a.setup.faces.as_deref()) {
        (Some(tag), faces) => Configuration::tagged(scheme, a.valence, faces, Tagging::parse(tag)?),
        (None, None) => Configuration::regular(scheme, a.valence),
        (None, Some(faces)) => Configuration::with_faces(scheme, a.valence, faces),
    }
}

/// The one-line refusal of an analysis that is not available at a tagged
/// vertex yet (`--tag`): the characteristic map, curvature and proofs use
/// the interior criteria (Reif's), and the sector criteria of a boundary,
/// crease or corner vertex (Zorin; Biermann–Levin–Zorin) are not built.
pub(super) fn refuse_tagged(command: &str, config: &Configuration) -> Result<(), Error> {
    match config.tagging {
        None => Ok(()),
        Some(t) => Err(Error::Input(format!(
            "{command} --tag {}: not available at tagged vertices yet (the sector criteria of boundary, \
             crease and corner vertices are not implemented); spectrum, stencils, matrix and charmap accept --tag",
            t.name()
        ))),
    }
}

/// 4-3's `centre_weight` is the weight of an eon's own point (rule 4a); a
/// centre that is a regular quad vertex (4 quads), a regular triangle vertex
/// (6 triangles) or a transition vertex (2 adjacent quads and 3 triangles)
/// takes its fixed rule instead (`sdc::slots::classify`), so the parameter
/// has no effect there: a one-line note for the human output.
pub(super) fn unused_centre_weight(scheme: &str, params: &BTreeMap<String, String>, faces: &str) -> Option<String> {
    if scheme != "four-three" || !params.contains_key("centre_weight") {
        return None;
    }
    let f: Vec<char> = faces.chars().filter(|c| matches!(c, 'Q' | 'T')).collect();
    let n = f.len();
    let quads: Vec<usize> = (0..n).filter(|&i| f[i] == 'Q').collect();
    let rule = if n == 4 && quads.len() == 4 {
        "a regular quad vertex (rule 1a)"
    } else if n == 6 && quads.is_empty() {
        "a regular triangle vertex (rule 3a)"
    } else if n == 5 && quads.len() == 2 && (quads[0] + 1 == quads[1] || (quads[0] == 0 && quads[1] == 4)) {
        "a transition vertex (rule 2a)"
    } else {
        return None;
    };
    Some(format!("note: centre_weight has no effect here: the centre of {faces} is {rule}, not an eon"))
}

pub(super) fn spectrum_table(s: &Spectrum) -> String {
    let mut out = String::new();
    out += &format!(
        "scheme {}  {} {}  faces {}  neighbourhood {} ({} vertices; minimal {}, analysis {})\n",
        s.scheme,
        match &s.tagging {
            None => "valence".to_string(),
            Some(t) => format!("{t} vertex, sectors"),
        },
        s.valence,
        short_faces(&s.faces),
        kind_name(s.neighbourhood),
        s.matrix_size,
        s.minimal_size,
        s.analysis_size
    );
    if !s.params.is_empty() {
        out += &format!(
            "parameters: {}\n",
            s.params.iter().map(|(k, v)| format!("{k}={v}")).collect::<Vec<_>>().join(", ")
        );
    }
    if let Some(note) = unused_centre_weight(&s.scheme, &s.params, &s.faces) {
        out += &format!("{note}\n");
    }
    out += &format!(
        "method {}: blocks {}\n\n",
        match s.method {
            Method::Dft => "dft",
            Method::Full => "full",
        },
        s.blocks.iter().map(|b| format!("{}:{}", b.index, b.size)).collect::<Vec<_>>().join(" ")
    );
    out += &format!("{:>4}  {:<34} {:>14}  {:>4} {:>4}  {}\n", "#", "eigenvalue", "modulus", "alg", "geo", "blocks");
    for (k, e) in s.eigenvalues.iter().enumerate() {
        out += &format!(
            "{:>4}  {:<34} {:>14}  {:>4} {:>4}  {}{}\n",
            k,
            e.display(),
            crate::spectrum::fmt_f(e.modulus),
            e.algebraic_multiplicity,
            e.geometric_multiplicity,
            compact_blocks(&e.blocks),
            if e.defective { "  DEFECTIVE" } else { "" }
        );
    }
    if let Some(x) = &s.exact_analysis {
        out += &format!(
            "\nexact ({}): characteristic polynomial of degree {}; rational roots {}; remaining factor degree {}{}\n",
            x.method,
            x.polynomial_degree,
            x.rational_roots
                .iter()
                .map(|r| format!("{}^{}", r.value, r.algebraic_multiplicity))
                .collect::<Vec<_>>()
                .join(" "),
            x.remaining_degree,
            if x.agrees_with_float { "" } else { "  (DISAGREES with floating point multiplicities)" }
        );
    }
    let criterion = match s.verdict.criterion {
        "sector" => "Spectral part of the C1 criterion at a tagged vertex (Zorin 2000)",
        "sector per side" => {
            "Spectral part of the C1 criterion at a crease vertex, per side (Zorin 2000; Biermann–Levin–Zorin 2000)"
        }
        _ => "Reif spectral C1 criterion",
    };
    out += &format!("\n{criterion}: {}\n", if s.verdict.c1_spectral { "PASSES" } else { "FAILS" });
    for r in &s.verdict.reasons {
        out += &format!("  - {r}\n");
    }
    if let Some(c) = &s.crease {
        out += &crease_sides_table(c);
    }
    if let Some(r) = s.verdict.lambda3_over_lambda1_squared {
        out += &format!("  |λ3|/λ1² = {}\n", crate::spectrum::fmt_f(r));
    }
    out
}

/// Each side's leading eigenvalues at a crease vertex (with how they are
/// known), and S whole's verdict, labelled as not the crease's.
fn crease_sides_table(c: &crate::spectrum::spectrum_result::CreaseVerdict) -> String {
    const SHOWN: usize = 6;
    let mut out = String::new();
    for side in &c.sides {
        let shown: Vec<String> = side
            .eigenvalues
            .iter()
            .take(SHOWN)
            .map(|e| match (e.algebraic_multiplicity, e.geometric_multiplicity) {
                (1, _) => e.display(),
                (m, g) if m == g => format!("{} (x{m})", e.display()),
                (m, g) => format!("{} (x{m}, defective: geo {g})", e.display()),
            })
            .collect();
        let evidence = match &side.exact_analysis {
            Some(x) if x.complete() && x.agrees_with_float => {
                "floating point, every eigenvalue and multiplicity exact over Q"
            }
            Some(_) => "floating point, partly confirmed exactly",
            None => "floating point",
        };
        out += &format!(
            "  {} spectrum ({evidence}): {}{}\n",
            side.name,
            shown.join(", "),
            if side.eigenvalues.len() > SHOWN { ", ..." } else { "" }
        );
    }
    let w = &c.whole;
    out += &format!(
        "  S whole (both sides at once{}): {}{}\n",
        if c.coupled.is_some() { "" } else { "; not the crease's criterion" },
        if w.c1_spectral { "PASSES" } else { "FAILS" },
        if w.failures.is_empty() { String::new() } else { format!(" — {}", w.failures.join("; ")) }
    );
    out
}

/// "Q×200" for a long uniform face sequence.
fn short_faces(f: &str) -> String {
    match f.chars().next() {
        Some(c) if f.len() > 12 && f.chars().all(|x| x == c) => format!("{c}×{}", f.len()),
        _ => f.to_string(),
    }
}

fn compact_blocks(b: &[usize]) -> String {
    if b.len() > 6 {
        format!("{},{},…,{} ({} blocks)", b[0], b[1], b[b.len() - 1], b.len())
    } else {
        b.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(",")
    }
}

pub(super) fn stencil_table(st: &crate::spectrum::stencils::Stencils) -> String {
    let mut out = format!(
        "scheme {}  valence {}  faces {}  neighbourhood {}\n\n",
        st.scheme,
        st.valence,
        st.faces,
        kind_name(st.neighbourhood)
    );
    out += &format!("{:<22} {:>22}", "vertex", "limit");
    for k in 0..st.tangent.len() {
        out += &format!(" {:>22}", format!("tangent {}", k + 1));
    }
    out += "\n";
    for (k, w) in st.limit.iter().enumerate() {
        let all_zero = w.weight == 0.0 && st.tangent.iter().all(|t| t[k].weight == 0.0);
        if all_zero {
            continue;
        }
        let cell = |x: &crate::spectrum::stencils::StencilWeight| match &x.recognised {
            Some(r) if r != "0" => format!("{} ({})", crate::spectrum::fmt_f(x.weight), r),
            _ => crate::spectrum::fmt_f(x.weight),
        };
        out += &format!("{:<22} {:>22}", w.vertex, cell(w));
        for t in &st.tangent {
            out += &format!(" {:>22}", cell(&t[k]));
        }
        out += "\n";
    }
    out += "(vertices where every stencil is zero are omitted)\n";
    out
}
