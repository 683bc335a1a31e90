//! The certificate document: everything a certified verdict rests on, written
//! as JSON for a program other than subdlab to re-check
//! (`scripts/check_cert.py`, Python standard library only).
//!
//! The document is the proof's input and its claims, never its conclusions
//! alone: the exact rows of S (the definition of the matrix the verdict is
//! about), the rotation orbits and the reflection the premises use, and per
//! Fourier block the floating-point V and R ≈ V⁻¹ the discs were verified
//! with, with the claimed ε, discs, components and counts. A checker
//! recomputes the blocks from the rows, M ⊇ R·A·V and ε itself, so nothing
//! subdlab computed in floating point or intervals is trusted; V and R need
//! no trust at all (any V, R with ‖I − RV‖∞ < 1 give valid discs).
//!
//! Layout (version 1):
//!
//! ```text
//! { "format": "subdlab-certificate", "version": 1, "tool": ...,
//!   "float_encoding": ..., "scheme", "params", "valence", "faces", "neighbourhood",
//!   "parts": { "spectrum": { ... } } }
//! ```
//!
//! `parts` holds one object per certified statement: `spectrum` now; the
//! characteristic-map part is to be added as `charmap` beside it (a checker
//! rejects a part it does not know how to re-check).
//!
//! Numbers: floating-point values (V, R, ε, disc centres and radii, margins)
//! are JSON numbers, written by serde_json as the shortest decimal that
//! round-trips to the same f64, so a reader that parses decimals correctly
//! rounded (Python's `float`, then `fractions.Fraction` for the exact value)
//! gets the very f64 subdlab used. Exact weights: a rational as the string
//! "p/q"; an element Σ cᵢ ζ_N^i of a cyclotomic field Q(ζ_N), ζ_N = e^{2πi/N},
//! as `{"order": N, "coefficients": [[i, "p/q"], ...]}` (the nonzero
//! coefficients; subdlab writes them reduced modulo Φ_N, a checker must not
//! rely on it).

use super::matrix::mirror_map;
use super::spectrum::{analysis_orbits, exact_rows, SpectrumCertificate, Verdict};
use crate::error::Error;
use crate::matrix::local::assemble_rows;
use crate::numeric::{Cyclotomic, Rational};
use crate::sdc::Scheme;
use crate::spectrum::{Analysis, Method};
use faer::c64;
use faer::Mat;
use serde::Serialize;
use serde_json::{json, Map, Value};

pub const FORMAT: &str = "subdlab-certificate";
pub const VERSION: u32 = 1;

const FLOAT_ENCODING: &str = "JSON numbers, the shortest decimal that round-trips to the IEEE 754 binary64 value used";

/// Rows assembled exactly at a time when not every row is rational (as the
/// rotation premise does: bounded memory, rows of one orbit together).
const EXACT_CHUNK: usize = 64;

/// An exact weight as the document writes it.
#[derive(Serialize)]
#[serde(untagged)]
enum ExactValue {
    Rational(String),
    Cyclotomic { order: u32, coefficients: Vec<(usize, String)> },
}

fn exact_value(w: &Cyclotomic) -> ExactValue {
    match (w.to_rational(), w.order()) {
        (Some(q), _) => ExactValue::Rational(ratio(&q)),
        (None, order) => ExactValue::Cyclotomic {
            order: order.unwrap_or(0),
            coefficients: w.coefficients().map(|(i, c)| (i, ratio(&c))).collect(),
        },
    }
}

/// "p/q", also for integers: one form for a reader to parse.
fn ratio(q: &Rational) -> String {
    format!("{}/{}", q.numer(), q.denom())
}

/// The whole document around its parts (`parts`: name and value, e.g.
/// `("spectrum", spectrum_part(..))`).
pub fn document(analysis: &Analysis, parts: Vec<(&str, Value)>) -> Value {
    let s = &analysis.spectrum;
    let parts: Map<String, Value> = parts.into_iter().map(|(k, v)| (k.to_string(), v)).collect();
    json!({
        "format": FORMAT,
        "version": VERSION,
        "tool": crate::io::version_line(),
        "float_encoding": FLOAT_ENCODING,
        "scheme": s.scheme,
        "params": s.params,
        "valence": s.valence,
        "faces": s.faces,
        "neighbourhood": s.neighbourhood,
        "parts": parts,
    })
}

/// Writes the document atomically (a reader never sees half a certificate).
pub fn write(path: &std::path::Path, doc: &Value) -> Result<(), Error> {
    let text = serde_json::to_string_pretty(doc).map_err(|e| Error::Message(e.to_string()))?;
    crate::io::write_atomic(path, (text + "\n").as_bytes())
}

/// Every row of S exactly (`None`: a weight known in floating point only):
/// one rational assembly when all rows are rational, else in chunks, each
/// rational or cyclotomic, and row by row where a chunk is not exact.
fn all_exact_rows(scheme: &dyn Scheme, analysis: &Analysis) -> Vec<Option<Vec<(usize, Cyclotomic)>>> {
    let everyone: Vec<usize> = (0..analysis.spectrum.labels.len()).collect();
    if let Ok(rows) =
        assemble_rows::<Rational>(scheme, &analysis.discovered, analysis.spectrum.neighbourhood, &everyone)
    {
        return rows
            .into_iter()
            .map(|r| Some(r.into_iter().map(|(c, w)| (c, Cyclotomic::from_rational(&w))).collect()))
            .collect();
    }
    let mut out = Vec::with_capacity(everyone.len());
    for chunk in everyone.chunks(EXACT_CHUNK) {
        match exact_rows(scheme, analysis, chunk) {
            Some(rows) => out.extend(rows.into_iter().map(Some)),
            None => out.extend(chunk.iter().map(|&k| exact_rows(scheme, analysis, &[k]).and_then(|mut r| r.pop()))),
        }
    }
    out
}

fn matrix(m: &Mat<c64>) -> Vec<Vec<[f64; 2]>> {
    (0..m.nrows()).map(|i| (0..m.ncols()).map(|j| [m[(i, j)].re, m[(i, j)].im]).collect()).collect()
}

/// The spectral part: the exact rows, the symmetry the blocks and the
/// realness argument rest on, the blocks' verified diagonalisations and the
/// claimed verdict with the components it names.
pub fn spectrum_part(scheme: &dyn Scheme, analysis: &Analysis, cert: &SpectrumCertificate) -> Value {
    let s = &analysis.spectrum;
    let orbits = analysis_orbits(scheme, analysis);
    let g = orbits.group_order;
    let rows = all_exact_rows(scheme, analysis);
    let inexact: Vec<usize> = rows.iter().enumerate().filter(|(_, r)| r.is_none()).map(|(k, _)| k).collect();
    let rows: Vec<Option<Vec<(usize, ExactValue)>>> =
        rows.iter().map(|r| r.as_ref().map(|r| r.iter().map(|(c, w)| (*c, exact_value(w))).collect())).collect();
    let blocks: Vec<Value> = cert
        .blocks
        .iter()
        .map(|b| {
            // the row (and column) order of the block: its orbits (block 0
            // holds the fixed points too); the whole matrix: matrix order
            let block_orbits = (s.method == Method::Dft).then(|| orbits.block_orbits(b.block));
            let (v, r) = match &b.diagonalisation {
                Some(d) => (Some(matrix(&d.v)), Some(matrix(&d.r))),
                None => (None, None),
            };
            let discs: Vec<[f64; 3]> =
                b.diagonalisation.iter().flat_map(|d| &d.discs).map(|d| [d.re, d.im, d.radius]).collect();
            let components: Vec<Value> =
                b.components.iter().map(|c| json!({ "discs": c.rows, "count": c.count })).collect();
            json!({
                "block": b.block,
                "orbits": block_orbits,
                "size": b.size,
                "v": v,
                "r": r,
                "epsilon": b.epsilon,
                "discs": discs,
                "components": components,
                "failure": b.failure,
            })
        })
        .collect();
    let reason = match &cert.verdict {
        Verdict::Proved => None,
        Verdict::Disproved(r) | Verdict::NotProved(r) => Some(r.clone()),
    };
    let named = cert.named;
    let claims = json!({
        "lambda0": named.lambda0.map(|i| json!({ "block": 0, "component": i })),
        "lambda1": named.lambda1.map(|[a, b]| json!([{ "block": 1, "component": a }, { "block": g - 1, "component": b }])),
        "witness": cert.witness.as_ref().map(|w| json!({ "block": w.block, "component": w.index })),
    });
    let member: Vec<[usize; 2]> = orbits.member.iter().map(|&(o, t)| [o, t]).collect();
    json!({
        "statement": cert.statement,
        "verdict": cert.verdict.word(),
        "reason": reason,
        "conditional": cert.conditional,
        "method": s.method,
        "size": s.labels.len(),
        "labels": s.labels.iter().map(|l| l.name.as_str()).collect::<Vec<_>>(),
        "group_order": g,
        "orbits": { "member": member, "representative": orbits.representative, "fixed": orbits.fixed },
        "mirror": cert.premises.as_ref().and_then(|p| p.mirror_axis).and_then(|axis| mirror_map(&s.labels, s.valence, axis)),
        "exact": inexact.is_empty(),
        "inexact_rows": inexact,
        "field": cert.premises.as_ref().and_then(|p| p.field.clone()),
        "rows": rows,
        "premises": cert.premises,
        "blocks": blocks,
        "claims": claims,
        "margins": cert.margins,
    })
}

/// The spectral certificate's document, written to `path`.
pub fn write_spectrum(
    path: &std::path::Path,
    scheme: &dyn Scheme,
    analysis: &Analysis,
    cert: &SpectrumCertificate,
) -> Result<(), Error> {
    let doc = document(analysis, vec![("spectrum", spectrum_part(scheme, analysis, cert))]);
    write(path, &doc)
}
