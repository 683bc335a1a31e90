//! Spectral C¹ conditions for every valence of a range, or for every
//! valence from A on (`subdlab spectrum SCHEME --certify --valences A..`).
//!
//! * a finite range A..B: the interval certificate (`certify`) at each n;
//! * an open range A..: one parametric computation for every n ≥ N
//!   (`laurent`: the blocks k ≠ 0 as P(x, cos θ); `tail`: their decision;
//!   `centre`: block 0), and the per-valence certificate for A ≤ n < N.
//!   Where the parametric part does not prove its statement, the
//!   per-valence certificates scan upward from A to find the first valence
//!   where the conditions fail (DISPROVED) up to `SCAN_LIMIT`; none found:
//!   NOT PROVED with the reason.
//!
//! Spectral conditions only: the characteristic map is not part of this.

pub mod centre;
pub mod composite;
pub mod laurent;
pub mod special;
pub mod symbol;
pub mod tail;

use std::collections::BTreeMap;
use std::time::Instant;

use serde::Serialize;

use crate::certify::spectrum::analysis_orbits;
use crate::certify::{certify_analysis, Verdict};
use crate::error::Error;
use crate::matrix::assemble_rows;
use crate::neighbourhood::{Configuration, NeighbourhoodKind};
use crate::numeric::{Cyclotomic, Rational, Weight};
use crate::schemes;
use crate::schemes::user::probe;
use crate::spectrum::{analyse, Options};

use crate::sweep::exact::BiPoly;
use laurent::LaurentRows;

/// The valences at which the rows away from the centre are read (two, to
/// check that they agree): large enough that no rule reaches around the
/// centre, not a valence of a regular vertex or face.
pub const PROBE_VALENCE: usize = 24;
/// How far the per-valence certificates scan for a first failure when the
/// parametric part does not prove its statement.
pub const SCAN_LIMIT: usize = 64;

/// What the command asks.
#[derive(Clone, Debug)]
pub struct Request {
    pub scheme: String,
    pub params: Vec<(String, String)>,
    pub from: usize,
    /// None: every valence from `from` on
    pub to: Option<usize>,
}

/// One valence's certificate.
#[derive(Clone, Debug, Serialize)]
pub struct AtValence {
    pub valence: usize,
    #[serde(flatten)]
    pub verdict: Verdict,
    /// a verdict given identities confirmed only to interval overlap
    pub conditional: bool,
}

/// The parametric part's account.
#[derive(Clone, Debug, Serialize)]
pub struct Parametric {
    /// PROVED, or NOT PROVED with the reason
    #[serde(flatten)]
    pub verdict: Verdict,
    pub evidence: &'static str,
    /// the rows away from the centre: where their independence of n comes from
    pub rows: String,
    /// the blocks k ≠ 0
    #[serde(skip_serializing_if = "Option::is_none")]
    pub blocks: Option<tail::TailFacts>,
    /// block 0: its variable and range
    #[serde(skip_serializing_if = "Option::is_none")]
    pub block0: Option<Block0>,
    /// face-centred schemes: the blocks through the centre face's symbol
    #[serde(skip_serializing_if = "Option::is_none")]
    pub special: Option<special::SpecialFacts>,
    pub seconds: f64,
}

#[derive(Clone, Debug, Serialize)]
pub struct Block0 {
    /// the one variable the centre's row totals are polynomials in
    pub variable: centre::Variable,
    /// its range over the valences ≥ N and what the eigenvalues are compared with
    pub range: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub scheme: String,
    pub valences: String,
    #[serde(flatten)]
    pub verdict: Verdict,
    /// what kind of evidence the verdict is
    pub evidence: String,
    pub scope: &'static str,
    /// N: the parametric part covers n ≥ N (open ranges, when proved)
    pub threshold: Option<usize>,
    pub parametric: Option<Parametric>,
    pub per_valence: Vec<AtValence>,
    pub per_valence_seconds: f64,
}

pub const SCOPE: &str = "spectral conditions only (λ0 = 1 simple; λ1 = λ2 real, positive, from blocks 1 and n−1, \
                         simple in each; every other eigenvalue of modulus below λ1); the characteristic map is not \
                         checked";

fn q(p: i64, d: i64) -> Rational {
    Rational::new(p.into(), d.into())
}

/// The interval certificate at one valence (as `spectrum --certify`).
pub fn certify_at(req: &Request, n: usize) -> Result<AtValence, Error> {
    let scheme = schemes::resolve(&req.scheme, &req.params)?;
    let config = Configuration::regular(scheme.as_ref(), n)?;
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &opts)?;
    let c = certify_analysis(scheme.as_ref(), &analysis)?;
    Ok(AtValence { valence: n, verdict: c.verdict.clone(), conditional: c.conditional })
}

fn proved(a: &AtValence) -> bool {
    a.verdict == Verdict::Proved && !a.conditional
}

/// The largest sum of the valences whose certificates one request makes:
/// that of 3..200. A certificate costs about linearly in n or more (√3's
/// two-step rows), and 3..64 — the open range's scan — takes seconds, so
/// 3..100000 would run for days: refused up front instead.
pub const MAX_CERTIFIED_VALENCE_SUM: u128 = (3 + 200) * 198 / 2;

/// Refuses per-valence certificates at from..=to past
/// [`MAX_CERTIFIED_VALENCE_SUM`] (nothing to do when to < from).
fn check_per_valence_work(from: usize, to: usize) -> Result<(), Error> {
    if to < from {
        return Ok(());
    }
    let work: u128 = (from as u128 + to as u128) * (to - from + 1) as u128 / 2;
    if work > MAX_CERTIFIED_VALENCE_SUM {
        return Err(Error::Input(format!(
            "certificates at valences {from}..{to} sum to {work} over their valences, above the limit \
             {MAX_CERTIFIED_VALENCE_SUM} (that of 3..200; a certificate costs at least linearly in n): split the \
             range, or give an open range A.. (certificates below the parametric proof's N only)"
        )));
    }
    Ok(())
}

/// Runs the request.
pub fn run(req: &Request) -> Result<Report, Error> {
    if req.from < 3 {
        return Err(Error::Input(format!("--valences: the lowest valence is 3, got {}", req.from)));
    }
    if let Some(to) = req.to {
        if to < req.from {
            return Err(Error::Input(format!("--valences {}..{to}: the range is empty", req.from)));
        }
    }
    if let Some(to) = req.to {
        check_per_valence_work(req.from, to)?;
    }
    let scheme = schemes::resolve(&req.scheme, &req.params)?;
    let name = scheme.name().to_string();
    let valences = match req.to {
        Some(to) => format!("{}..{to}", req.from),
        None => format!("{}..", req.from),
    };
    let mut report = Report {
        scheme: name,
        valences,
        verdict: Verdict::Proved,
        evidence: String::new(),
        scope: SCOPE,
        threshold: None,
        parametric: None,
        per_valence: Vec::new(),
        per_valence_seconds: 0.0,
    };
    let (scan_to, finite) = match req.to {
        Some(to) => (to, true),
        None => {
            let t0 = Instant::now();
            let (verdict, rows, blocks, block0, special, threshold) = match parametric(req) {
                Ok(p) => (Verdict::Proved, p.rows, p.blocks, p.block0, p.special, Some(p.threshold)),
                Err(missing) => (Verdict::NotProved(missing.reason), missing.rows, missing.blocks, None, None, None),
            };
            report.parametric = Some(Parametric {
                verdict,
                evidence: "exact (rational arithmetic, subresultants and Sturm sequences) over every valence ≥ N",
                rows,
                blocks,
                block0,
                special,
                seconds: t0.elapsed().as_secs_f64(),
            });
            report.threshold = threshold;
            match threshold {
                Some(n) => {
                    check_per_valence_work(req.from, n - 1)?;
                    (n - 1, true)
                }
                None => (SCAN_LIMIT.max(req.from), false),
            }
        }
    };
    let t1 = Instant::now();
    for n in req.from..=scan_to {
        let at = certify_at(req, n)?;
        let stop = matches!(at.verdict, Verdict::Disproved(_)) && !at.conditional;
        report.per_valence.push(at);
        if stop {
            break;
        }
    }
    report.per_valence_seconds = t1.elapsed().as_secs_f64();
    let first_bad = report.per_valence.iter().find(|a| matches!(a.verdict, Verdict::Disproved(_)) && !a.conditional);
    let first_open = report.per_valence.iter().find(|a| !proved(a));
    let scanned = match report.per_valence.last() {
        Some(l) => format!("{}..{}", req.from, l.valence),
        None => "none".into(),
    };
    (report.verdict, report.evidence) = if let Some(bad) = first_bad {
        let why = match &bad.verdict {
            Verdict::Disproved(r) => r.clone(),
            _ => String::new(),
        };
        (
            Verdict::Disproved(format!("first failing valence n = {}: {why}", bad.valence)),
            format!(
                "interval certificate at n = {} (the valences before it proved by their certificates)",
                bad.valence
            ),
        )
    } else if let Some(open) = first_open {
        (
            Verdict::NotProved(format!("valence {}: {}", open.valence, open.verdict.display())),
            "interval certificates per valence".into(),
        )
    } else if finite && report.parametric.is_none() {
        (Verdict::Proved, format!("interval certificate at each valence {scanned}"))
    } else if finite {
        let n = report.threshold.expect("proved parametric part");
        let below = if req.from < n { format!("interval certificates at {scanned}, ") } else { String::new() };
        (Verdict::Proved, format!("{below}exact parametric proof for every n ≥ {n}"))
    } else {
        let why = match report.parametric.as_ref().map(|p| &p.verdict) {
            Some(Verdict::NotProved(r)) => r.clone(),
            _ => String::new(),
        };
        (
            Verdict::NotProved(format!(
                "the parametric part does not cover n ≥ {}: {why}; the certificates prove {scanned} and find no \
                 failure there",
                req.from
            )),
            format!("interval certificates at {scanned}; no proof beyond"),
        )
    };
    Ok(report)
}

/// P(x, c) of the blocks k ≠ 0 as the parametric part computes it
/// (coefficients lowest power of x first, each a polynomial in c = cos θ),
/// or why it is not computed.
pub fn block_polynomial(req: &Request) -> Result<Vec<crate::numeric::TPoly>, String> {
    let r0 = read_rows(req, PROBE_VALENCE).map_err(|m| m.reason)?;
    laurent::charpoly_in_c(&r0.rows).map_err(String::from)
}

/// What the parametric part proved.
struct ParametricProof {
    rows: String,
    /// vertex-centred: the blocks k ≠ 0 and block 0
    blocks: Option<tail::TailFacts>,
    block0: Option<Block0>,
    /// face-centred: every block through the centre face's symbol
    special: Option<special::SpecialFacts>,
    /// N
    threshold: usize,
}

/// Why it did not, and how far it got.
struct Missing {
    reason: String,
    rows: String,
    blocks: Option<tail::TailFacts>,
}

fn missing(reason: impl Into<String>) -> Missing {
    Missing { reason: reason.into(), rows: "not established".into(), blocks: None }
}

/// The rows at valence n: the rows away from the centre by sector offset
/// (with what the probe saw), and the centre's row totals per orbit.
struct Read {
    rows: LaurentRows,
    reads: probe::Reads,
    /// matrix index of the centre (None: face-centred) and the orbits away
    /// from it (block order)
    centre: Option<usize>,
    /// face-centred: the one row that depends on n
    varying: Option<Varying>,
    free: Vec<usize>,
    /// the representatives' matrix indices (block order)
    reps: Vec<usize>,
    orbit_of: Vec<(usize, usize)>,
    analysis: crate::spectrum::Analysis,
    /// composite schemes: the fields the centre's stencils read at n (the
    /// only ones with variables, `composite::centre_only`)
    centre_fields: Option<Vec<probe::FieldRead>>,
}

fn read_rows(req: &Request, n: usize) -> Result<Read, Missing> {
    let err = |e: Error| missing(format!("valence {n}: {e}"));
    let scheme = schemes::resolve(&req.scheme, &req.params).map_err(err)?;
    if !scheme.rotation_symmetric() {
        return Err(missing("the scheme's rules are not rotation symmetric (no Fourier blocks)"));
    }
    let config = Configuration::regular(scheme.as_ref(), n).map_err(err)?;
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &opts).map_err(err)?;
    let orbits = analysis_orbits(scheme.as_ref(), &analysis);
    orbits.check_free().map_err(|e| missing(format!("valence {n}: no Fourier blocks ({e})")))?;
    if orbits.group_order != n {
        return Err(missing(format!("valence {n}: the rotation period is not one sector")));
    }
    let fixed: Vec<usize> = (0..orbits.num_orbits()).filter(|&o| orbits.fixed[o]).collect();
    if fixed.len() > 1 {
        return Err(missing("more than one vertex is fixed by the rotation"));
    }
    // several refinement steps: the centre's rule reaches the other rows
    // through the steps in between (`composite`)
    let composite = analysis.discovered.refinements().len() > 1;
    if composite && fixed.is_empty() {
        return Err(missing(
            "S is a composite of several refinement steps around a centre face: not followed (vertex-centred \
             composites are)",
        ));
    }
    let free = orbits.block_orbits(1);
    let mut pos = vec![usize::MAX; orbits.num_orbits()];
    for (k, &o) in free.iter().enumerate() {
        pos[o] = k;
    }
    let which: Vec<usize> = free.iter().map(|&o| orbits.representative[o]).collect();
    let (d, kind) = (&analysis.discovered, analysis.spectrum.neighbourhood);
    let (rows, reads) = probe::watch(n, || assemble_rows::<Cyclotomic>(scheme.as_ref(), d, kind, &which));
    // composite: the n-dependent fields reach the rows away from the centre
    // only through the centre's stencils, so only uniformly over the sectors
    // (`composite`); the rows with those fields at 0 keep everything else
    let (rows, centre_fields) = if composite && reads.total > 0 {
        let set = d.set(kind);
        let centre = set[orbits.representative[fixed[0]]];
        let targets: Vec<usize> = which.iter().map(|&k| set[k]).collect();
        let fields = composite::centre_only(scheme.as_ref(), d, &targets, centre, n)
            .map_err(|e| missing(format!("valence {n}: {e}")))?;
        let zero = composite::substitution(&fields, &vec![0; fields.len()]);
        let (rows, _) =
            probe::watch_substituted(n, zero, || assemble_rows::<Cyclotomic>(scheme.as_ref(), d, kind, &which));
        (rows, Some(fields))
    } else {
        (rows, None)
    };
    // the rows away from the centre must not read a field with a variable at
    // the centre's valence; and a scheme-file weight must have been read at all
    if reads.total == 0 {
        return Err(missing(
            "the scheme's rules are compiled code (a built-in): how its weights depend on the centre's valence \
             cannot be read; the same rules as a scheme file can be (e.g. schemes/catmull-clark.toml, \
             schemes/loop.toml)",
        ));
    }
    // face-centred (no fixed vertex): the centre face's own rule may depend
    // on n; it is followed through its symbol (`symbol`)
    let varying = if fixed.is_empty() && reads.at_valence.iter().any(|f| f.varies) {
        Some(varying_row(scheme.as_ref(), &analysis, &orbits, &free, &pos, n)?)
    } else {
        None
    };
    if let Some(f) = reads.at_valence.iter().find(|f| f.varies).filter(|_| varying.is_none() && !composite) {
        return Err(missing(format!(
            "the rows away from the centre read [{}] {} at the centre's valence, an expression with variables: the \
             blocks k ≠ 0 may depend on n other than through cos(2πk/n)",
            f.rule, f.family
        )));
    }
    let rows = rows.map_err(|_| missing(format!("valence {n}: no exact rows of S")))?;
    let g = n as i64;
    let size = free.len();
    let mut entries = vec![vec![BTreeMap::new(); size]; size];
    let mut centre_column = vec![Rational::from_integer(0.into()); size];
    for (a, row) in rows.iter().enumerate() {
        for (col, w) in row {
            if let Some(v) = &varying {
                // the n-dependent entries: replaced by their generic value below
                if a == v.row && pos[orbits.member[*col].0] == v.orbit {
                    continue;
                }
            }
            let w = w.to_rational().ok_or_else(|| {
                missing("a weight of a row away from the centre is irrational: not followed as a Laurent polynomial")
            })?;
            let (ob, tau) = orbits.member[*col];
            if orbits.fixed[ob] {
                centre_column[a] = &centre_column[a] + w;
                continue;
            }
            let tau = tau as i64;
            let signed = if 2 * tau > g { tau - g } else { tau };
            let e: &mut BTreeMap<i64, Rational> = &mut entries[a][pos[ob]];
            let v = e.remove(&signed).unwrap_or_else(|| Rational::from_integer(0.into())) + w;
            if !Weight::is_zero(&v) {
                e.insert(signed, v);
            }
        }
    }
    if let Some(v) = &varying {
        let d = v.symbol.generic().as_rational().ok_or_else(|| {
            missing(
                "the centre face's rule at the generic blocks depends on n (its kronecker(j) term): not followed as \
                 a Laurent polynomial",
            )
        })?;
        if !Weight::is_zero(&d) {
            entries[v.row][v.orbit].insert(0, d);
        }
    }
    if composite {
        // what is left of the uniform part U_ab (constant weights the
        // centre's stencils read at n): the entry at the farthest sector
        let far = g / 2;
        for m in entries.iter_mut().flatten() {
            let u = m.get(&far).cloned().unwrap_or_else(|| Rational::from_integer(0.into()));
            if Weight::is_zero(&u) {
                continue;
            }
            let mut local = BTreeMap::new();
            for tau in (far - g + 1)..=far {
                let v = m.get(&tau).cloned().unwrap_or_else(|| Rational::from_integer(0.into())) - &u;
                if !Weight::is_zero(&v) {
                    local.insert(tau, v);
                }
            }
            *m = local;
        }
    }
    let rows = LaurentRows { entries, centre_column };
    // a composite's local part must leave the farthest sectors free
    let margin = if composite { 4 } else { 2 };
    if 2 * rows.reach() + margin > g {
        return Err(missing(format!(
            "the rows away from the centre reach {} sectors: too far for the probe",
            rows.reach()
        )));
    }
    let orbit_of = orbits.member.clone();
    Ok(Read {
        rows,
        reads,
        centre: fixed.first().map(|&o| orbits.representative[o]),
        varying,
        free,
        reps: which,
        orbit_of,
        analysis,
        centre_fields,
    })
}

/// The one row of a face-centred scheme whose weights depend on n (the
/// centre face's rule), read as a trigonometric polynomial in its slot's
/// position (`symbol`).
#[derive(Clone, Debug, PartialEq)]
struct Varying {
    /// block indices: the row's orbit a and the orbit b it reads with the field
    row: usize,
    orbit: usize,
    field: (&'static str, &'static str),
    symbol: symbol::TrigInJ,
}

/// Finds the n-dependent row and reads it: exactly one representative row
/// reads a field with variables at n, exactly one such field, whose slots
/// are one per sector on one orbit b (weight 1 each in indicator mode); its
/// weights' symbol, read from the field's expression, must be the exact
/// transform of the actual weights on b at every block k = 0..n−1.
fn varying_row(
    scheme: &dyn crate::sdc::Scheme,
    analysis: &crate::spectrum::Analysis,
    orbits: &crate::dft::blocks::Orbits,
    free: &[usize],
    pos: &[usize],
    n: usize,
) -> Result<Varying, Missing> {
    let (d, kind) = (&analysis.discovered, analysis.spectrum.neighbourhood);
    let assemble = |rep: usize| assemble_rows::<Cyclotomic>(scheme, d, kind, &[rep]);
    let mut found: Option<(usize, probe::FieldRead)> = None;
    for (a, &o) in free.iter().enumerate() {
        let (_, reads) = probe::watch(n, || assemble(orbits.representative[o]));
        let vary: Vec<_> = reads.at_valence.into_iter().filter(|f| f.varies).collect();
        match (vary.len(), &found) {
            (0, _) => {}
            (1, None) => found = Some((a, vary[0].clone())),
            _ => {
                return Err(missing(
                    "more than one row or field of the centre face's neighbourhood depends on n (one is followed)",
                ))
            }
        }
    }
    let (a, f) = found.ok_or_else(|| missing("no row reads the field that depends on n"))?;
    let rep = orbits.representative[free[a]];
    // the field's slots: its indicator row minus the row with every n-read at 0
    let (ones, _) = probe::watch_indicator(n, (f.rule, f.family), || assemble(rep));
    let (zeros, _) = probe::watch_indicator(n, ("", ""), || assemble(rep));
    let (ones, zeros) = match (ones, zeros) {
        (Ok(x), Ok(y)) => (x, y),
        _ => return Err(missing("no exact rows of S")),
    };
    let mut slots: BTreeMap<usize, Cyclotomic> = BTreeMap::new();
    for (col, w) in &ones[0] {
        slots.insert(*col, w.clone());
    }
    for (col, w) in &zeros[0] {
        let e = slots.remove(col).unwrap_or_else(Cyclotomic::zero) - w.clone();
        slots.insert(*col, e);
    }
    slots.retain(|_, w| !Weight::is_zero(w));
    let bad = || {
        missing(format!(
            "[{}] {}: its slots are not one per sector on one orbit (not followed as a symbol)",
            f.rule, f.family
        ))
    };
    let orbit_b = slots.keys().next().map(|c| orbits.member[*c].0).ok_or_else(bad)?;
    let mut per_sector = vec![0usize; n];
    for (col, w) in &slots {
        let (o, t) = orbits.member[*col];
        if o != orbit_b || *w != Cyclotomic::one() {
            return Err(bad());
        }
        per_sector[t] += 1;
    }
    if per_sector.iter().any(|&c| c != 1) {
        return Err(bad());
    }
    let sym = symbol::trig_in_j(&f.expr, &f.env).map_err(|e| missing(format!("[{}] {}: {e}", f.rule, f.family)))?;
    // the actual weights on orbit b by sector, and the check of the symbol
    let row = assemble(rep).map_err(|_| missing("no exact rows of S"))?;
    let mut weights = vec![Cyclotomic::zero(); n];
    for (col, w) in &row[0] {
        let (o, t) = orbits.member[*col];
        if o == orbit_b {
            weights[t] = weights[t].clone() + w.clone();
        }
    }
    if !symbol::matches_row(&sym, n, &weights) {
        return Err(missing(format!(
            "[{}] {}: the symbol read from its expression is not the transform of the actual row at n = {n}",
            f.rule, f.family
        )));
    }
    Ok(Varying { row: a, orbit: pos[orbit_b], field: (f.rule, f.family), symbol: sym })
}

/// The centre's row at valence n with field `field` weighing 1 and every
/// other field read at n weighing 0: its totals per orbit away from the
/// centre (the field's slot counts).
fn indicator_totals(req: &Request, read: &Read, n: usize, field: (&str, &str)) -> Result<Vec<Rational>, Missing> {
    let centre = read.centre.ok_or_else(|| missing("no centre vertex"))?;
    let scheme = schemes::resolve(&req.scheme, &req.params).map_err(|e| missing(e.to_string()))?;
    let (d, kind) = (&read.analysis.discovered, read.analysis.spectrum.neighbourhood);
    let (row, _) =
        probe::watch_indicator(n, field, || assemble_rows::<Cyclotomic>(scheme.as_ref(), d, kind, &[centre]));
    let row = row.map_err(|_| missing("no exact centre row"))?;
    let mut totals = vec![Rational::from_integer(0.into()); read.free.len()];
    for (col, w) in &row[0] {
        let (ob, _) = read.orbit_of[*col];
        if let Some(k) = read.free.iter().position(|&o| o == ob) {
            totals[k] = &totals[k] + w.to_rational().ok_or_else(|| missing("an indicator weight is not rational"))?;
        }
    }
    Ok(totals)
}

/// The actual centre row's totals per orbit away from the centre.
fn centre_totals(req: &Request, read: &Read) -> Result<Vec<Cyclotomic>, Missing> {
    let centre = read.centre.ok_or_else(|| missing("no centre vertex"))?;
    let scheme = schemes::resolve(&req.scheme, &req.params).map_err(|e| missing(e.to_string()))?;
    let (d, kind) = (&read.analysis.discovered, read.analysis.spectrum.neighbourhood);
    let row =
        assemble_rows::<Cyclotomic>(scheme.as_ref(), d, kind, &[centre]).map_err(|_| missing("no exact centre row"))?;
    let mut totals = vec![Cyclotomic::zero(); read.free.len()];
    for (col, w) in &row[0] {
        let (ob, _) = read.orbit_of[*col];
        if let Some(k) = read.free.iter().position(|&o| o == ob) {
            totals[k] = totals[k].clone() + w.clone();
        }
    }
    Ok(totals)
}

fn parametric(req: &Request) -> Result<ParametricProof, Missing> {
    let (n0, n1) = (PROBE_VALENCE, PROBE_VALENCE + 1);
    let r0 = read_rows(req, n0)?;
    let r1 = read_rows(req, n1)?;
    if r0.rows != r1.rows {
        return Err(missing(format!(
            "the rows away from the centre differ between valences {n0} and {n1} (by sector offset)"
        )));
    }
    // the reads at n that are constants (all of them, but the centre face's
    // own field when the scheme is face-centred)
    let constant_reads = r0.reads.at_valence.iter().filter(|f| !f.varies).count();
    let rows_text = format!(
        "rows away from the centre independent of n: every scheme-file weight they read at the centre's valence is \
         a constant ({} read{}), checked at n = {n0}; identical at n = {n0} and {n1}; reach {} sector(s); blocks of \
         size {}",
        constant_reads,
        if constant_reads == 1 { "" } else { "s" },
        r0.rows.reach(),
        r0.rows.size()
    );
    if r0.varying != r1.varying {
        return Err(missing(format!("the centre face's rule reads differently at valences {n0} and {n1}")));
    }
    if let Some(v) = &r0.varying {
        return face_centred(&r0.rows, v, rows_text);
    }
    let p = laurent::charpoly_in_c(&r0.rows).map_err(|e| Missing {
        reason: e.into(),
        rows: rows_text.clone(),
        blocks: None,
    })?;
    let facts = match tail::decide(&p, n0) {
        Ok(tail::Tail::Proved(f)) => f,
        Ok(tail::Tail::Fails(why)) => {
            return Err(Missing { reason: format!("blocks k ≠ 0: {why}"), rows: rows_text, blocks: None })
        }
        Err(e) => return Err(Missing { reason: format!("blocks k ≠ 0: {e}"), rows: rows_text, blocks: None }),
    };
    let fail0 = |why: String, facts: &tail::TailFacts| Missing {
        reason: format!("block 0: {why}"),
        rows: rows_text.clone(),
        blocks: Some(facts.clone()),
    };
    if r0.centre_fields.is_some() {
        return composite_block0(req, &r0, &r1, &p, facts, rows_text);
    }
    // block 0: the centre's totals r(n)
    let (_, centre_reads) = probe::watch(n0, || centre_totals(req, &r0));
    let mut r_sym = vec![centre::InN::default(); r0.rows.size()];
    for f in &centre_reads.at_valence {
        let w = centre::symbolic(&f.expr, &f.env).map_err(|e| fail0(e, &facts))?;
        let c0 = indicator_totals(req, &r0, n0, (f.rule, f.family))?;
        let c1 = indicator_totals(req, &r1, n1, (f.rule, f.family))?;
        let per_sector: Vec<Rational> = c0.iter().map(|x| x / q(n0 as i64, 1)).collect();
        if c1.iter().map(|x| x / q(n1 as i64, 1)).collect::<Vec<_>>() != per_sector {
            return Err(fail0(
                format!("[{}] {}: its slots per sector differ between valences", f.rule, f.family),
                &facts,
            ));
        }
        let n_times_w = w.mul_n();
        for (b, k) in per_sector.iter().enumerate() {
            r_sym[b] = r_sym[b].add_scaled(&n_times_w, k);
        }
    }
    // the formula is the centre's row at both probe valences
    for (read, n) in [(&r0, n0), (&r1, n1)] {
        let actual = centre_totals(req, read)?;
        let formula: Option<Vec<Cyclotomic>> = r_sym.iter().map(|x| x.at(n as i64)).collect();
        if formula.as_ref() != Some(&actual) {
            return Err(fail0(format!("the centre's totals from its fields disagree with its row at n = {n}"), &facts));
        }
    }
    let (variable, r_poly) = centre::one_variable(&r_sym).map_err(|e| fail0(e, &facts))?;
    let qp = centre::block0_poly(&r0.rows.at_one(), &r_poly);
    let lambda1 = centre::lambda1_poly(&p, variable);
    match centre::decide(&qp, &lambda1, variable, facts.threshold) {
        Ok((n, range)) => {
            let mut blocks = facts;
            blocks.threshold = blocks.threshold.max(n);
            Ok(ParametricProof {
                rows: rows_text,
                block0: Some(Block0 { variable, range }),
                threshold: blocks.threshold,
                blocks: Some(blocks),
                special: None,
            })
        }
        Err(why) => Err(fail0(why, &facts)),
    }
}

/// The parametric part of a face-centred scheme: the Laurent rows with the
/// centre face's row at its generic value, P and P⁺ (that entry raised by
/// 1), and `special::decide`.
fn face_centred(rows: &LaurentRows, v: &Varying, rows_text: String) -> Result<ParametricProof, Missing> {
    let rows_text = format!(
        "{rows_text}; the centre face's row reads [{}] {} at n, followed as a symbol (a cosine polynomial in the \
         slot's position j, its transform checked at every block of n = {} and {})",
        v.field.0,
        v.field.1,
        PROBE_VALENCE,
        PROBE_VALENCE + 1
    );
    let fail = |why: String| Missing { reason: why, rows: rows_text.clone(), blocks: None };
    let mut raised = rows.clone();
    let e = raised.entries[v.row][v.orbit].remove(&0).unwrap_or_else(|| Rational::from_integer(0.into()))
        + Rational::from_integer(1.into());
    if !Weight::is_zero(&e) {
        raised.entries[v.row][v.orbit].insert(0, e);
    }
    let p = laurent::charpoly_in_c(rows).map_err(|e| fail(e.into()))?;
    let p_plus = laurent::charpoly_in_c(&raised).map_err(|e| fail(e.into()))?;
    let facts = special::decide(&p, &p_plus, &v.symbol, PROBE_VALENCE).map_err(fail)?;
    Ok(ParametricProof {
        rows: rows_text,
        blocks: None,
        block0: None,
        threshold: facts.threshold,
        special: Some(facts),
    })
}

/// Block 0 of a composite scheme (`composite`): its entries as polynomials
/// in (the n-dependent fields' values, n), read off S at the integer grid
/// and the valences n0..n0+m+1, the fields replaced by their expressions
/// in n; checked against block 0 of S itself at n0 and n0 + 1. Returns the
/// variable t, q(x, t) = det(xI − B_0(t))/(x − 1) (the eigenvalues other
/// than λ0 = 1) and what was read.
fn composite_q(req: &Request, r0: &Read, r1: &Read) -> Result<(centre::Variable, BiPoly, String), String> {
    let fields = r0.centre_fields.clone().ok_or("not a composite scheme")?;
    let m = r0.analysis.discovered.refinements().len();
    let symbols: Vec<centre::InN> =
        fields.iter().map(|f| centre::symbolic(&f.expr, &f.env)).collect::<Result<_, _>>()?;
    let scheme = schemes::resolve(&req.scheme, &req.params).map_err(|e| e.to_string())?;
    let valences: Vec<usize> = (0..m + 2).map(|i| PROBE_VALENCE + i).collect();
    let mut more = Vec::new();
    for &n in &valences[2..] {
        more.push(read_rows(req, n).map_err(|e| e.reason)?);
    }
    let reads: Vec<&Read> = [r0, r1].into_iter().chain(more.iter()).collect();
    let key = |fs: &[probe::FieldRead]| fs.iter().map(|f| (f.rule, f.family)).collect::<Vec<_>>();
    if !reads.iter().all(|r| r.centre_fields.as_deref().map(key) == Some(key(&fields))) {
        return Err("the centre's stencils read different fields at different valences".into());
    }
    let block = |r: &Read, n: usize, values: Option<probe::Substitution>| {
        composite::block0_values(
            scheme.as_ref(),
            &r.analysis.discovered,
            r.analysis.spectrum.neighbourhood,
            r.centre.ok_or("no centre vertex")?,
            &r.reps,
            &r.orbit_of,
            &r.free,
            n,
            values,
        )
    };
    let points = composite::grid(m, fields.len());
    let mut at = Vec::new();
    for (r, &n) in reads.iter().zip(&valences) {
        let mut per_point = Vec::new();
        for g in &points {
            let b = block(r, n, Some(composite::substitution(&fields, g)))?;
            per_point.push(composite::rational_block(&b, n)?);
        }
        at.push(per_point);
    }
    let entries = composite::block0_symbolic(&valences, &at, m, &symbols)?;
    // the formula is block 0 of S at the first two valences
    for (r, &n) in reads.iter().zip(&valences).take(2) {
        let actual = block(r, n, None)?;
        let formula: Option<Vec<Vec<Cyclotomic>>> =
            entries.iter().map(|row| row.iter().map(|x| x.at(n as i64)).collect()).collect();
        if formula.as_ref() != Some(&actual) {
            return Err(format!("the fitted entries disagree with block 0 of S at n = {n}"));
        }
    }
    let size = entries.len();
    let flat: Vec<centre::InN> = entries.into_iter().flatten().collect();
    let (variable, polys) = centre::one_variable(&flat)?;
    let qp = centre::block0_without_one(&polys, size)?;
    let text = format!(
        "S is {m} refinement steps: the centre's stencils alone read [{}] at n (checked stencil by stencil), so \
         the rows away from the centre are read with those fields at 0, and block 0 is fitted as a polynomial of \
         degree ≤ {m} in them and in n (valences {}..{}, checked against S at {} and {})",
        fields.iter().map(|f| format!("{} {}", f.rule, f.family)).collect::<Vec<_>>().join(", "),
        valences[0],
        valences[valences.len() - 1],
        valences[0],
        valences[1]
    );
    Ok((variable, qp, text))
}

/// Composite schemes: q(x, t) of block 0 (its eigenvalues other than 1)
/// with its variable, as the parametric part computes it.
pub fn composite_block0_polynomial(req: &Request) -> Result<(centre::Variable, BiPoly), String> {
    let r0 = read_rows(req, PROBE_VALENCE).map_err(|m| m.reason)?;
    let r1 = read_rows(req, PROBE_VALENCE + 1).map_err(|m| m.reason)?;
    composite_q(req, &r0, &r1).map(|(v, q, _)| (v, q))
}

/// The parametric part of a composite scheme, once the blocks k ≠ 0 are
/// decided: block 0 (`composite_q`) against λ1 as for one-step schemes
/// (`centre::decide`).
fn composite_block0(
    req: &Request,
    r0: &Read,
    r1: &Read,
    p: &BiPoly,
    facts: tail::TailFacts,
    rows_text: String,
) -> Result<ParametricProof, Missing> {
    let fail = |why: String| Missing {
        reason: format!("block 0: {why}"),
        rows: rows_text.clone(),
        blocks: Some(facts.clone()),
    };
    let (variable, qp, read) = composite_q(req, r0, r1).map_err(fail)?;
    let lambda1 = centre::lambda1_poly(p, variable);
    let (n, range) = centre::decide(&qp, &lambda1, variable, facts.threshold).map_err(fail)?;
    let mut blocks = facts.clone();
    blocks.threshold = blocks.threshold.max(n);
    Ok(ParametricProof {
        rows: format!("{rows_text}; {read}"),
        block0: Some(Block0 { variable, range }),
        threshold: blocks.threshold,
        blocks: Some(blocks),
        special: None,
    })
}
