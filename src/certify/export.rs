//! The certificate document: everything a certified verdict rests on, written
//! as JSON for a program other than subdlab to re-check
//! (`scripts/check_cert.py`, Python standard library only).
//!
//! The document is the proof's input and its claims, never its conclusions
//! alone: the exact rows of S (the definition of the matrix the verdict is
//! about), the rotation orbits and the reflection the premises use, and per
//! Fourier block the floating-point V and R ≈ V⁻¹ the discs were verified
//! with, with the claimed ε, discs, components and counts; for a block whose
//! eigenvalues the proof bounds by lemma S6 instead (`certify::power`), the
//! power k = 2^s, the claimed bound of ‖B^k‖∞ and the lower bound of λ1 it
//! is compared with (`claims.power_bounds`). A checker
//! recomputes the blocks from the rows, M ⊇ R·A·V and ε itself, so nothing
//! subdlab computed in floating point or intervals is trusted; V and R need
//! no trust at all (any V, R with ‖I − RV‖∞ < 1 give valid discs).
//!
//! Layout (version 1):
//!
//! ```text
//! { "format": "subdlab-certificate", "version": 1, "tool": ...,
//!   "float_encoding": ..., "scheme", "params", "valence", "faces", "neighbourhood",
//!   "parts": { "spectrum": { ... }, "charmap": { ... } }, "charmap_omitted": ... }
//! ```
//!
//! `parts` holds one object per certified statement (a checker rejects a
//! part it does not know how to re-check): `spectrum`, and from
//! `charmap --certify` `charmap`, the geometric proof at its decisive level
//! (`charmap_part`); when that cannot be written, or would make the document
//! exceed [`MAX_DOCUMENT_BYTES`], `charmap_omitted` says why.
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

use super::charmap::CharMapCertificate;
use super::discs::{Component, Diagonalisation};
use super::matrix::mirror_map;
use super::spectrum::{analysis_orbits, exact_rows, SpectrumCertificate, Verdict};
use crate::error::Error;
use crate::matrix::local::assemble_rows_rational;
use crate::numeric::{Cyclotomic, Rational, Weight};
use crate::refine::Combine;
use crate::sdc::Scheme;
use crate::sdc::SchemeWeight;
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
    if let Ok(rows) = assemble_rows_rational(scheme, &analysis.discovered, analysis.spectrum.neighbourhood, &everyone) {
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
            let mut block = json!({
                "block": b.block,
                "orbits": block_orbits,
                "size": b.size,
                "epsilon": b.epsilon,
                "failure": b.failure,
                "power_bound": b.power_bound,
            });
            add_enclosure(&mut block, &b.diagonalisation, &b.components);
            block
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
        // lemma S6: the blocks whose eigenvalues the gap bounds by
        // ‖B^k‖∞^(1/k) (a checker recomputes B^k from the rows), and the
        // lower bound of λ1 each is compared with
        "power_bounds": cert.margins.power_bounded.iter().filter_map(|&m| {
            let p = cert.blocks.iter().find(|b| b.block == m)?.power_bound?;
            Some(json!({
                "block": m,
                "k": p.k,
                "norm": p.norm,
                "radius": p.radius,
                "lambda1_lower": cert.margins.lambda1_lower,
            }))
        }).collect::<Vec<_>>(),
        // lemma S7: what the exact route claims (the checker recomputes the
        // characteristic polynomial from the rows itself)
        "exact_route": cert.exact_route.as_ref().map(|e| json!({
            "proved": e.proved,
            "one_multiplicity": e.one_multiplicity,
            "lambda1": e.lambda1,
            "algebraic": e.algebraic,
            "geometric": e.geometric,
            "others_below": e.others_below,
        })),
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

/// The tagged part (`certify::tagged`): the exact rows, the reflection
/// (E and O are rebuilt from them by a checker), each block's verified
/// diagonalisation and discs, and the components and exact claims the
/// verdict names.
pub fn tagged_part(scheme: &dyn Scheme, analysis: &Analysis, cert: &super::tagged::TaggedCertificate) -> Value {
    let s = &analysis.spectrum;
    let rows = all_exact_rows(scheme, analysis);
    let inexact: Vec<usize> = rows.iter().enumerate().filter(|(_, r)| r.is_none()).map(|(k, _)| k).collect();
    let rows: Vec<Option<Vec<(usize, ExactValue)>>> =
        rows.iter().map(|r| r.as_ref().map(|r| r.iter().map(|(c, w)| (*c, exact_value(w))).collect())).collect();
    let mut part = tagged_fields(cert);
    let fields = part.as_object_mut().expect("an object");
    fields.insert("tag".into(), json!(analysis.discovered.config.tagging.map(|t| t.name())));
    fields.insert("size".into(), json!(s.labels.len()));
    fields.insert("labels".into(), json!(s.labels.iter().map(|l| l.name.as_str()).collect::<Vec<_>>()));
    fields.insert("exact".into(), json!(inexact.is_empty()));
    fields.insert("inexact_rows".into(), json!(inexact));
    fields.insert("rows".into(), json!(rows));
    // a crease vertex: each side's certificate on its points (the checker
    // rebuilds each side's rows from the rows above), S whole's verdict
    if let Some(c) = &cert.crease {
        let sides: Vec<Value> = c
            .sides
            .iter()
            .map(|side| {
                let mut v = tagged_fields(&side.certificate);
                let f = v.as_object_mut().expect("an object");
                f.insert("name".into(), json!(side.name));
                f.insert("faces".into(), json!(side.faces));
                f.insert("indices".into(), json!(side.indices));
                f.insert("size".into(), json!(side.indices.len()));
                v
            })
            .collect();
        fields.insert(
            "crease".into(),
            json!({
                "decoupled": c.coupled.is_none(),
                // whose verdict the document's is: the sides', or S whole's
                // where they do not decouple (the fallback, with why)
                "verdict_of": if c.coupled.is_none() { "sides" } else { "S whole" },
                "coupled": c.coupled,
                "whole_verdict": c.whole_verdict.word(),
                "whole_reason": verdict_reason(&c.whole_verdict),
                "whole_conditional": c.whole_conditional,
                "whole_decided_by": c.whole_decided_by,
                "invariance": c.invariance,
                "curve": c.curve,
                "sides": sides,
            }),
        );
    }
    part
}

fn verdict_reason(v: &Verdict) -> Option<String> {
    match v {
        Verdict::Proved => None,
        Verdict::Disproved(r) | Verdict::NotProved(r) => Some(r.clone()),
    }
}

/// The fields of one tagged certificate (S whole's, or a crease side's):
/// its verdict, the reflection, premises, blocks and the routes' claims.
fn tagged_fields(cert: &super::tagged::TaggedCertificate) -> Value {
    let blocks: Vec<Value> = cert
        .blocks
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let mut block = json!({
                "block": i,
                "name": b.name,
                "size": b.size,
                "epsilon": b.epsilon,
                "failure": b.failure,
            });
            add_enclosure(&mut block, &b.diagonalisation, &b.components);
            block
        })
        .collect();
    let index = |name: &str| cert.blocks.iter().position(|b| b.name == name);
    let named = |n: &Option<super::tagged::Named>| {
        n.as_ref().map(|n| json!({ "block": index(n.block), "component": n.component }))
    };
    let e = &cert.enclosure_route;
    json!({
        "statement": cert.statement,
        "verdict": cert.verdict.word(),
        "reason": verdict_reason(&cert.verdict),
        "conditional": cert.conditional,
        "decided_by": cert.decided_by,
        "field": cert.premises.field,
        "reflection": cert.reflection,
        "premises": cert.premises,
        "blocks": blocks,
        "claims": {
            "enclosures": e.verdict.word(),
            "lambda0": named(&e.lambda0),
            "lambda1": named(&e.lambda1),
            "lambda2": named(&e.lambda2),
            "exact_route": cert.exact_route.as_ref().map(|x| json!({
                "verdict": x.verdict.word(),
                "one_multiplicity": x.one_multiplicity,
                "r": x.r,
                "algebraic": x.algebraic,
                "geometric": x.geometric,
                "above": x.above,
            })),
        },
    })
}

/// The tagged certificate's document, written to `path`.
pub fn write_tagged(
    path: &std::path::Path,
    scheme: &dyn Scheme,
    analysis: &Analysis,
    cert: &super::tagged::TaggedCertificate,
) -> Result<(), Error> {
    let doc = document(analysis, vec![("tagged", tagged_part(scheme, analysis, cert))]);
    write(path, &doc)
}

/// Documents above this size keep the spectral part only (with
/// `charmap_omitted` saying why): the exact stencil DAG of a high-valence net
/// at five levels would otherwise reach hundreds of megabytes.
pub const MAX_DOCUMENT_BYTES: usize = 50_000_000;

/// A net point named by its node in the stencil DAG being recorded: refining
/// a net of `NodeId`s with exact weights records every new point's stencil
/// over the points it was made from, with the very pruning and numbering of
/// the interval net the proof used (the same refinement, another payload).
#[derive(Clone, Copy, Debug)]
struct NodeId(usize);

thread_local! {
    /// Stencils of the nodes made so far (`None`: a level-0 point). Combine
    /// is a plain function of its terms, so the recording lives beside it;
    /// `record_stencils` resets it around each use on this thread.
    static DAG: std::cell::RefCell<Vec<Option<Vec<(usize, Cyclotomic)>>>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The exact weight types a net is re-refined with: rational first, the
/// cyclotomic field where a rule's weight is irrational.
trait ExactWeight: SchemeWeight {
    fn exact(&self) -> Cyclotomic;
}

impl ExactWeight for Rational {
    fn exact(&self) -> Cyclotomic {
        Cyclotomic::from_rational(self)
    }
}

impl ExactWeight for Cyclotomic {
    fn exact(&self) -> Cyclotomic {
        self.clone()
    }
}

impl<W: ExactWeight> Combine<W> for NodeId {
    fn combine(terms: &[(W, &Self)]) -> Self {
        // repeated parents merged, so a checker sees one weight per parent
        let mut stencil: Vec<(usize, Cyclotomic)> = Vec::with_capacity(terms.len());
        for (w, p) in terms {
            match stencil.iter_mut().find(|(q, _)| *q == p.0) {
                Some((_, acc)) => *acc = acc.clone() + w.exact(),
                None => stencil.push((p.0, w.exact())),
            }
        }
        stencil.retain(|(_, w)| !Weight::is_zero(w));
        DAG.with(|d| {
            let mut d = d.borrow_mut();
            d.push(Some(stencil));
            NodeId(d.len() - 1)
        })
    }
}

/// The exact stencil DAG of the net refined `levels` analysis steps in `W`:
/// the level-L net's node per vertex, and every node's stencil (level-0
/// nodes are the analysis points, by matrix index).
fn record_stencils<W: ExactWeight>(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    levels: usize,
) -> Result<(Vec<Option<NodeId>>, Vec<Option<Vec<(usize, Cyclotomic)>>>), Error> {
    let d = &analysis.discovered;
    let mut level0 = vec![None; d.patch.num_vertices()];
    for (k, &v) in d.analysis.iter().enumerate() {
        level0[v] = Some(NodeId(k));
    }
    DAG.with(|g| *g.borrow_mut() = vec![None; d.analysis.len()]);
    let net = crate::charmap::net::refine_net_exactly_as::<W, NodeId>(scheme, d, level0, levels);
    let dag = DAG.with(|g| std::mem::take(&mut *g.borrow_mut()));
    Ok((net?.points, dag))
}

/// The nodes `roots` use and all their ancestors, renumbered in creation
/// order (a topological order: parents come first; the level-0 points keep
/// their matrix indices 0..n0): the new index of every node (usize::MAX
/// where not needed) and the needed refined nodes' stencils over the new
/// indices.
#[allow(clippy::type_complexity)]
fn pruned_stencils(
    dag: &[Option<Vec<(usize, Cyclotomic)>>],
    n0: usize,
    roots: impl IntoIterator<Item = usize>,
) -> Result<(Vec<usize>, Vec<Vec<(usize, ExactValue)>>), String> {
    let mut needed = vec![false; dag.len()];
    let mut stack: Vec<usize> = roots.into_iter().collect();
    while let Some(i) = stack.pop() {
        if !std::mem::replace(&mut needed[i], true) {
            if let Some(s) = &dag[i] {
                stack.extend(s.iter().map(|(p, _)| *p));
            }
        }
    }
    let mut index = vec![usize::MAX; dag.len()];
    for (i, slot) in index.iter_mut().enumerate().take(n0) {
        *slot = i;
    }
    let mut stencils: Vec<Vec<(usize, ExactValue)>> = Vec::new();
    for i in n0..dag.len() {
        if needed[i] {
            index[i] = n0 + stencils.len();
            let s = dag[i].as_ref().ok_or("a refined point has no stencil")?;
            stencils.push(s.iter().map(|(p, w)| (index[*p], exact_value(w))).collect());
        }
    }
    Ok((index, stencils))
}

/// The characteristic-map part: the exact refinement from the level-0 net
/// (the analysis points) to the decisive level, restricted to the points the
/// windows use and their ancestors; per ring face its window's edges and the
/// claimed Jacobian sign; the winding computation; the verdicts and the
/// premises taken as trusted. `Err`: why the part cannot be written.
pub fn charmap_part(scheme: &dyn Scheme, analysis: &Analysis, cert: &CharMapCertificate) -> Result<Value, String> {
    let e = cert
        .evidence
        .as_ref()
        .ok_or("the characteristic map's regularity was not decided: there is no proof to export")?;
    let (points, dag) = record_stencils::<Rational>(scheme, analysis, e.levels)
        .or_else(|_| record_stencils::<Cyclotomic>(scheme, analysis, e.levels))
        .map_err(|err| format!("the net could not be re-refined with exact weights: {err}"))?;
    let n0 = analysis.discovered.analysis.len();
    let node = |v: usize| points.get(v).copied().flatten().map(|n| n.0).ok_or("a window point has no exact stencil");
    // the nodes the windows use and all their ancestors, renumbered in
    // creation order (a topological order: parents come first); the level-0
    // points keep their matrix indices 0..n0
    let mut faces = Vec::with_capacity(e.faces.len());
    let pairs = |edges: &[(usize, usize)]| -> Result<Vec<[usize; 2]>, String> {
        edges.iter().map(|&(a, b)| Ok([node(a)?, node(b)?])).collect()
    };
    for f in &e.faces {
        let layout: Vec<(usize, [i64; 2])> =
            f.layout.iter().map(|&(v, c)| Ok((node(v)?, c))).collect::<Result<_, &str>>()?;
        let window: Vec<(usize, [i64; 2])> =
            f.window.iter().map(|&(v, c)| Ok((node(v)?, c))).collect::<Result<_, &str>>()?;
        faces.push((pairs(&f.u_edges)?, pairs(&f.v_edges)?, f.sign, layout, window));
    }
    let chain: Vec<usize> = match &e.winding {
        Some(w) => w.vertices.iter().map(|&v| node(v)).collect::<Result<_, _>>()?,
        None => Vec::new(),
    };
    let roots = faces
        .iter()
        .flat_map(|(u, v, _, l, w)| {
            u.iter().chain(v).flatten().copied().chain(l.iter().map(|p| p.0)).chain(w.iter().map(|p| p.0))
        })
        .chain(chain.iter().copied());
    let (index, stencils) = pruned_stencils(&dag, n0, roots)?;
    let faces: Vec<Value> = faces
        .iter()
        .map(|(u, v, sign, layout, window)| {
            let map = |edges: &Vec<[usize; 2]>| edges.iter().map(|[a, b]| [index[*a], index[*b]]).collect::<Vec<_>>();
            let mut face =
                json!({ "u_edges": map(u), "v_edges": map(v), "sign": match sign { 1 => "+", -1 => "-", _ => "?" } });
            // non-box windows: the points' lattice positions, [point, x, y]
            // in half units, from which the checker re-derives the edge set
            if !layout.is_empty() {
                face["layout"] = json!(layout.iter().map(|(p, c)| [index[*p] as i64, c[0], c[1]]).collect::<Vec<_>>());
            }
            // lemma C9 windows: W_up's points at their lattice positions,
            // the face's corners at (0,0), (1,0), (0,1)
            if !window.is_empty() {
                face["window"] = json!(window.iter().map(|(p, c)| [index[*p] as i64, c[0], c[1]]).collect::<Vec<_>>());
            }
            face
        })
        .collect();
    let winding = e.winding.as_ref().map(|w| {
        json!({
            "windows": w.windows,
            "vertices": chain.iter().map(|&c| index[c]).collect::<Vec<_>>(),
            "directions": w.directions,
            "polygon": w.polygon,
            "number": w.number,
        })
    });
    let difference = e.difference.as_ref().map(|b| difference_part(b));
    Ok(json!({
        "difference": difference,
        "statement": "the characteristic map of λ1's eigenvectors is regular and injective (Reif's C¹ criterion, \
                      with the spectral part)",
        "regularity": cert.regularity.word(),
        "injectivity": cert.injectivity.word(),
        "c1": cert.c1.word(),
        "regular_part": cert.regular_part,
        "levels": e.levels,
        "eigenvector": { "block": 1, "disc": e.lambda1_row },
        "points": points_json(n0, stencils),
        "faces": faces,
        "winding": winding,
        "trusted": [
            if e.difference.is_some() {
                "the rules over the ring faces' windows are the exported regular mask (read off a regular torus and \
                 compared exactly by subdlab at every child window point of the next analysis step), and by locality \
                 at every later level"
            } else {
                "the rules over the ring faces' windows are the regular part's box-spline masks, or for non-box the \
                 four-directional S_3^1 spline's mask derived from its definition (compared exactly by subdlab), so \
                 the Jacobian over a face lies between the least and greatest det(u_i, v_j) of its window"
            },
            "the ring faces, their scaled copies (and for dual schemes the half-face enlargement) cover the punctured \
             neighbourhood of the centre",
            "each window is the ring face's one-ring laid out on the lattice, with its u- and v-edges as listed (for \
             non-box windows: at the positions its layout gives; for lemma C9 windows: W_up at the positions its \
             `window` gives, the face's corners at (0,0), (1,0), (0,1)), and the chain is the annulus's inner boundary, \
             window i the ring face beside its edge i",
        ],
    }))
}

/// Lemma C9's data: the regular mask (per class c of a new point y, the
/// weights on old points x as [D·x − y, weight]), the windows and bases of
/// second differences per triangle type, and the constants subdlab claims
/// (a checker recomputes them from the mask and requires its own to be at
/// most these).
fn difference_part(b: &super::difference::LatticeBound) -> Value {
    let types = |f: &dyn Fn(usize) -> Value| json!({ "up": f(0), "down": f(1) });
    json!({
        "dilation": b.mask.dilation,
        "steps": b.mask.steps,
        "mask": b.mask.classes.iter().map(|(c, list)| json!([c.0, c.1, list.iter().map(|(o, w)| json!([o.0, o.1, format!("{}/{}", w.numer(), w.denom())])).collect::<Vec<_>>()])).collect::<Vec<_>>(),
        "windows": types(&|t| json!(b.windows[t].iter().map(|p| [p.0, p.1]).collect::<Vec<_>>())),
        "basis": types(&|t| json!(b.basis[t].iter().map(|row| row.iter().map(|(p, c)| [p.0, p.1, *c]).collect::<Vec<_>>()).collect::<Vec<_>>())),
        "word": b.word,
        "word_norms": b.word_norms,
        "k_edge": b.k_edge,
        "k_pos": b.k_pos,
        "edge_constant": b.edge_constant,
        "position_constant": b.position_constant,
        "depth": super::difference::DEPTH,
    })
}

/// The characteristic-map certificate's document: the spectral part and,
/// when the geometric proof can be exported within [`MAX_DOCUMENT_BYTES`],
/// the `charmap` part; otherwise `charmap_omitted` says why.
pub fn write_charmap(
    path: &std::path::Path,
    scheme: &dyn Scheme,
    analysis: &Analysis,
    cert: &CharMapCertificate,
) -> Result<(), Error> {
    let spectrum = spectrum_part(scheme, analysis, &cert.spectrum);
    let mut doc = match charmap_part(scheme, analysis, cert) {
        Ok(charmap) => {
            let doc = document(analysis, vec![("spectrum", spectrum.clone()), ("charmap", charmap)]);
            let size = serde_json::to_string(&doc).map(|t| t.len()).unwrap_or(usize::MAX);
            if size <= MAX_DOCUMENT_BYTES {
                doc
            } else {
                let mut doc = document(analysis, vec![("spectrum", spectrum)]);
                doc["charmap_omitted"] =
                    json!(format!("the characteristic-map part would take {size} bytes, above {MAX_DOCUMENT_BYTES}"));
                doc
            }
        }
        Err(why) => {
            let mut doc = document(analysis, vec![("spectrum", spectrum)]);
            doc["charmap_omitted"] = json!(why);
            doc
        }
    };
    if doc.get("charmap_omitted").is_none() {
        doc["charmap_omitted"] = Value::Null;
    }
    write(path, &doc)
}

/// A block's verified diagonalisation in its document: V, R, the discs and
/// their components (null/empty where the verification failed); the same
/// fields for the Fourier blocks of an interior vertex and the reflection
/// blocks of a tagged one, which the checker reads alike.
fn add_enclosure(block: &mut Value, diagonalisation: &Option<Diagonalisation>, components: &[Component]) {
    let (v, r) = match diagonalisation {
        Some(d) => (Some(matrix(&d.v)), Some(matrix(&d.r))),
        None => (None, None),
    };
    let discs: Vec<[f64; 3]> = diagonalisation.iter().flat_map(|d| &d.discs).map(|d| [d.re, d.im, d.radius]).collect();
    let components: Vec<Value> = components.iter().map(|c| json!({ "discs": c.rows, "count": c.count })).collect();
    let fields = [("v", json!(v)), ("r", json!(r)), ("discs", json!(discs)), ("components", json!(components))];
    if let Value::Object(map) = block {
        map.extend(fields.into_iter().map(|(k, x)| (k.to_string(), x)));
    }
}

/// The sector part (`certify::tagged_charmap`, lemmas B1–B6) of a PROVED
/// sector map, beside the tagged spectral part: per eigenvector of the pair
/// Krawczyk's data on its reflection block (the checker rebuilds the block
/// from the rows and recomputes K(Y)); the sharp curve's points; the exact
/// stencil DAG of the net at the decisive level (restricted to the points
/// the windows use and their ancestors); per ring face its ghost-extended
/// window (each of the 4 × 4 positions a net point or a ghost 2b − p), the
/// rows along its sharp edges and the claimed Jacobian sign; the inner
/// chain with its half-planes and float polygon. `Err`: why the part is not
/// written (the sector criterion is not PROVED, or an eigenvector was
/// enclosed by the disc bound only).
pub fn sector_part(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    cert: &super::tagged_charmap::TaggedCharMapCertificate,
) -> Result<Value, String> {
    use super::tagged_charmap::WindowSource;
    let e = cert.evidence.as_ref().ok_or_else(|| match &cert.sector_criterion {
        Verdict::Proved => "the sector map is PROVED, but an eigenvector was enclosed by the disc bound only (no \
                            Krawczyk data to re-check): no sector part is written"
            .to_string(),
        other => format!(
            "the sector criterion is {}: only a PROVED sector map is exported (the spectral part is, in `tagged`)",
            other.word()
        ),
    })?;
    let (points, dag) = record_stencils::<Rational>(scheme, analysis, e.levels)
        .or_else(|_| record_stencils::<Cyclotomic>(scheme, analysis, e.levels))
        .map_err(|err| format!("the net could not be re-refined with exact weights: {err}"))?;
    let n0 = analysis.discovered.analysis.len();
    let node = |v: usize| points.get(v).copied().flatten().map(|n| n.0).ok_or("a window point has no exact stencil");
    let mut roots = Vec::new();
    for f in &e.faces {
        for (_, from) in &f.layout {
            match *from {
                WindowSource::Net(v) => roots.push(node(v)?),
                WindowSource::Ghost(a, b, p) => roots.extend([node(a)?, node(b)?, node(p)?]),
            }
        }
    }
    for &v in &e.chain.vertices {
        roots.push(node(v)?);
    }
    let (index, stencils) = pruned_stencils(&dag, n0, roots)?;
    let id = |v: usize| -> Result<usize, String> { Ok(index[node(v)?]) };
    let faces: Vec<Value> = e
        .faces
        .iter()
        .map(|f| -> Result<Value, String> {
            let layout: Vec<Value> = f
                .layout
                .iter()
                .map(|&((x, y), from)| match from {
                    WindowSource::Net(v) => Ok(json!([x, y, id(v)?])),
                    // 2b − p (a = b, the bicubic host) as [x, y, b, p], else a + b − p as [x, y, a, b, p]
                    WindowSource::Ghost(a, b, p) if a == b => Ok(json!([x, y, id(b)?, id(p)?])),
                    WindowSource::Ghost(a, b, p) => Ok(json!([x, y, id(a)?, id(b)?, id(p)?])),
                })
                .collect::<Result<_, String>>()?;
            let rows: Vec<Vec<[i32; 2]>> = f.rows.iter().map(|r| r.iter().map(|&(x, y)| [x, y]).collect()).collect();
            Ok(json!({ "sign": if f.sign > 0 { "+" } else { "-" }, "layout": layout, "rows": rows }))
        })
        .collect::<Result<_, _>>()?;
    let block_index = |name: &str| cert.spectrum.blocks.iter().position(|b| b.name == name);
    let eigenvectors: Vec<Value> = e
        .eigenvectors
        .iter()
        .map(|v| {
            json!({
                "block": block_index(v.block),
                "component": v.component,
                "s": v.s,
                "x": v.x,
                "mu": v.mu,
                "r": v.r,
                "y": v.y,
            })
        })
        .collect();
    let c = &e.chain;
    let chain_vertices: Vec<usize> = c.vertices.iter().map(|&v| id(v)).collect::<Result<_, _>>()?;
    Ok(json!({
        "statement": cert.statement,
        "host": e.host.name(),
        "regularity": cert.regularity.word(),
        "injectivity": cert.injectivity.word(),
        "sector_criterion": cert.sector_criterion.word(),
        "levels": e.levels,
        "normal": if e.normal == 0 { "lambda1" } else { "lambda2" },
        "eigenvectors": eigenvectors,
        "curve": e.curve,
        "points": points_json(n0, stencils),
        "faces": faces,
        "chain": {
            "vertices": chain_vertices,
            "arcs": c.arcs,
            "directions": c.directions,
            "polygon": c.polygon,
            "number": c.number,
        },
        "trusted": [
            format!(
                "the stencils are {}'s rules with the boundary tag (their weights are checked to sum to 1), and over \
                 the ring faces' windows the ghost-extended {}'s (compared exactly by subdlab: lemma B3)",
                analysis.spectrum.scheme,
                e.host.name()
            ),
            format!(
                "each window is its ring face's one-ring laid out on the {} lattice, the missing positions across a \
                 sharp ray filled by {} (the checker confirms the positions of the points the ghost is built from \
                 and that those on the ray have normal coordinate exactly 0), and the rows are the face's edges on a \
                 sharp ray",
                if e.host == super::tagged_charmap::GhostHost::Bicubic { "square" } else { "triangle" },
                if e.host == super::tagged_charmap::GhostHost::Bicubic {
                    "2b − p with b on the ray and p two steps beside the ghost"
                } else {
                    "a + b − p with a–b a sharp edge and p the apex opposite the ghost across it"
                }
            ),
            "the ring faces and their scaled copies cover the punctured sector, and the chain is the inner boundary \
             of the ring from one sharp ray to the other, arc i the ring face beside its edge i".to_string(),
        ],
    }))
}

/// The sector map's document at a boundary vertex: the tagged spectral part
/// and, where the sector criterion is PROVED and exportable within
/// [`MAX_DOCUMENT_BYTES`], the `sector` part; otherwise `sector_omitted`
/// says why (a DISPROVED or NOT PROVED sector map writes no sector part, so
/// no checker can accept it as PROVED).
pub fn write_tagged_charmap(
    path: &std::path::Path,
    scheme: &dyn Scheme,
    analysis: &Analysis,
    cert: &super::tagged_charmap::TaggedCharMapCertificate,
) -> Result<(), Error> {
    let tagged = tagged_part(scheme, analysis, &cert.spectrum);
    let omitted = |why: String| {
        let mut doc = document(analysis, vec![("tagged", tagged.clone())]);
        doc["sector_omitted"] = json!(why);
        doc["sector_claimed"] = json!(cert.sector_criterion.word());
        doc
    };
    let doc = match sector_part(scheme, analysis, cert) {
        Ok(sector) => {
            let mut doc = document(analysis, vec![("tagged", tagged.clone()), ("sector", sector)]);
            let size = serde_json::to_string(&doc).map(|t| t.len()).unwrap_or(usize::MAX);
            if size <= MAX_DOCUMENT_BYTES {
                doc["sector_omitted"] = Value::Null;
                doc["sector_claimed"] = json!(cert.sector_criterion.word());
                doc
            } else {
                omitted(format!("the sector part would take {size} bytes, above {MAX_DOCUMENT_BYTES}"))
            }
        }
        Err(why) => omitted(why),
    };
    write(path, &doc)
}

/// The refined net's points as both documents (interior and sector map)
/// write them: the analysis points, then each stencil over earlier points.
fn points_json(level0: usize, stencils: impl serde::Serialize) -> Value {
    json!({
        "level0": level0,
        "note": "points 0..level0 are the analysis points by matrix index; point level0 + k is stencil k over \
                 earlier points (creation order across the refinement levels)",
        "stencils": stencils,
    })
}
