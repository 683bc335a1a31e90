//! The certified spectral verdict at a tagged vertex (boundary, corner,
//! crease, dart): the spectral part of the sector criterion
//! (`spectrum::verdict::sector`; Zorin 2000, Biermann–Levin–Zorin 2000)
//! proved about the true local subdivision matrix S:
//!
//! (a) λ0 = 1 is a simple eigenvalue;
//! (b) the next two eigenvalues by modulus, λ1 ≥ λ2, are real, positive and
//!     non-defective (they may be equal);
//! (c) every other eigenvalue has modulus strictly below λ2 (and λ1 < 1).
//!
//! A tagged configuration has no rotation symmetry, so there are no Fourier
//! blocks; the reflection that keeps the sharp rays (`spectrum::reflection`)
//! splits S into an even block E and an odd block O when the rules commute
//! with it. Two routes, each a proof on its own:
//!
//! - **the enclosure route** (lemma T4): E and O (or S whole, when the
//!   reflection does not commute) as interval matrices from the interval rows
//!   of S (every weight enclosed, cos(π/k) of BLZ's rule included), Gershgorin
//!   discs after a verified diagonalisation (`certify::discs`). The blocks are
//!   real, so each block's spectrum is closed under conjugation: a
//!   one-eigenvalue component that meets the real axis and whose mirror image
//!   meets no other component of its block is real. Which eigenvalue is which
//!   comes from the discs alone: λ0 the one component (of all blocks) that
//!   may hold 1, λ1 and λ2 the two components of largest lower modulus bound.
//!   Two one-eigenvalue components are two simple eigenvalues of their block;
//!   in one block they are distinct (disjoint), in two blocks their
//!   eigenvectors are one even and one odd: either way λ1, λ2 span a
//!   two-dimensional eigenspace (non-defective), whether or not λ1 = λ2.
//! - **the exact route** (lemma T7), where every weight is rational: the
//!   characteristic polynomials of the blocks over Q (det(x − S) =
//!   det(x − E)·det(x − O)), ranks over Q, and the counting Schur–Cohn
//!   recursion (`numeric::exact::roots_above`), which counts the roots
//!   above a rational radius and proves that none lies on its circle. The
//!   floating-point spectrum only proposes rational candidates r; a wrong
//!   proposal decides nothing. It disproves what the enclosures cannot (a
//!   Jordan block at λ2: Hoppe's Catmull–Clark boundary at k = 4).
//!
//! The premises are equalities checked on the exact rows (in Q, or in
//! Q(ζ_N) for BLZ's cos(π/k)): every row sums to 1 (1 is an eigenvalue), and
//! S commutes with the reflection (E and O are S in another basis). Where a
//! row is known only in floating point they hold to interval overlap, and a
//! verdict resting on them says so (`conditional`).

use num_traits::{One, Signed, Zero};
use serde::Serialize;

use super::complex::{CInterval, CIntervalMatrix};
use super::discs::{enclose, Component, Diagonalisation, Disc};
use super::matrix::{row_sums, Check, ExactRows, IntervalRows};
use super::spectrum::{exact_rows, RealEnclosure, Verdict};
use crate::error::Error;
use crate::matrix::local::{assemble_rows, AssembleError};
use crate::neighbourhood::NeighbourhoodKind;
use crate::numeric::exact::{roots_above, Poly, QMatrix};
use crate::numeric::{Cyclotomic, Interval, Rational, Weight};
use crate::sdc::Scheme;
use crate::spectrum::crease_sides::{decoupling, principal, principal_row, weight_outside, Decoupling};
use crate::spectrum::reflection::{commutes, reflection_of, split};
use crate::spectrum::Analysis;

/// Largest tagged matrix enclosed (interval products cost about 100 times
/// the floating-point ones; the blocks are about half of it each).
pub const MAX_TAGGED_SIZE: usize = 800;

/// Largest matrix whose decided enclosure verdict the exact route re-decides.
pub const CROSS_CHECK_SIZE: usize = 64;

/// Largest block the exact route reduces over Q.
pub const MAX_EXACT_BLOCK: usize = 160;

const CREASE_STATEMENT: &str = "for each side of the crease vertex (the principal submatrix of the true local \
     subdivision matrix S on the side's points with the crease curve's, whose rows have zero weight outside them): \
     λ0 = 1 simple; the next two eigenvalues by modulus λ1 ≥ λ2 real, positive, non-defective; every other \
     eigenvalue of modulus below λ2 (the spectral part of the sector criterion, side by side)";

const STATEMENT: &str = "for the true local subdivision matrix S on the analysis neighbourhood of the tagged \
     vertex (every weight enclosed, cos(π/k) included): λ0 = 1 simple; the next two eigenvalues by modulus \
     λ1 ≥ λ2 real, positive, non-defective; every other eigenvalue of modulus below λ2 (the spectral part of the \
     sector criterion)";

/// One block the enclosure route encloses: the reflection's even or odd
/// block, or S whole.
#[derive(Clone, Debug, Serialize)]
pub struct TaggedBlock {
    /// "even", "odd" or "whole"
    pub name: &'static str,
    pub size: usize,
    /// ε ≥ ‖I − RV‖∞ of the verification (null when it failed)
    pub epsilon: Option<f64>,
    /// largest modulus first
    pub components: Vec<Component>,
    /// why there is no enclosure, when there is none
    pub failure: Option<String>,
    #[serde(skip)]
    pub diagonalisation: Option<Diagonalisation>,
}

/// Which component of which block an eigenvalue of the proof is.
#[derive(Clone, Debug, Serialize)]
pub struct Named {
    pub block: &'static str,
    /// index into the block's `components`
    pub component: usize,
    pub enclosure: RealEnclosure,
}

/// The enclosure route's verdict and what it rests on.
#[derive(Clone, Debug, Serialize)]
pub struct EnclosureRoute {
    #[serde(flatten)]
    pub verdict: Verdict,
    pub lambda0: Option<Named>,
    pub lambda1: Option<Named>,
    pub lambda2: Option<Named>,
    /// upper bound of the modulus of every other eigenvalue
    pub others_max_modulus: Option<f64>,
    /// lower bound of λ2 − max |other| (positive when proved)
    pub gap_lower_bound: Option<f64>,
}

/// The exact route's verdict (lemma T7), when it applies.
#[derive(Clone, Debug, Serialize)]
pub struct ExactRoute {
    #[serde(flatten)]
    pub verdict: Verdict,
    /// the blocks reduced over Q, with their sizes
    pub blocks: Vec<(&'static str, usize)>,
    /// the multiplicity of 1 as a root of det(xI − S)
    pub one_multiplicity: usize,
    /// the rational candidate r that decided, its algebraic and geometric
    /// multiplicities and the number of eigenvalues other than 1 of modulus
    /// above r (none has modulus r but r itself)
    pub r: Option<String>,
    pub algebraic: usize,
    pub geometric: usize,
    pub above: usize,
}

/// The premises, each checked exactly where the rows are exact.
#[derive(Clone, Debug, Serialize)]
pub struct TaggedPremises {
    pub row_sums_one: Check,
    /// S commutes with the reflection keeping the sharp rays (null: the
    /// configuration's set is not mapped onto itself)
    pub reflection: Option<Check>,
    /// "Q", "Q(ζ_N)", or null when no row is exact
    pub field: Option<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct TaggedCertificate {
    #[serde(flatten)]
    pub verdict: Verdict,
    /// true when the verdict rests on a premise confirmed to interval overlap
    /// only (a weight known in floating point)
    pub conditional: bool,
    pub statement: String,
    /// which route decided: "enclosures", "exact", "both" or null
    pub decided_by: Option<&'static str>,
    pub premises: TaggedPremises,
    /// the reflection's image of every point (matrix index), when S commutes
    /// with it and the blocks are E and O
    #[serde(skip)]
    pub reflection: Option<Vec<usize>>,
    pub blocks: Vec<TaggedBlock>,
    pub enclosure_route: EnclosureRoute,
    /// null where a weight is irrational or known in floating point only, or
    /// a block is beyond [`MAX_EXACT_BLOCK`]; else its verdict
    pub exact_route: Option<ExactRoute>,
    /// why the exact route was not taken, when it was not
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact_route_skipped: Option<String>,
    /// at a `crease:K` vertex: each side's certificate and S whole's
    /// verdict (the verdict above is the sides' where they decouple)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crease: Option<CreaseCertificate>,
}

/// The per-side certificates of a crease vertex (`spectrum::crease_sides`).
#[derive(Clone, Debug, Serialize)]
pub struct CreaseCertificate {
    /// S whole's verdict, conditionality and route (both sides at once: not
    /// the crease's criterion where the sides decouple); the certificate's
    /// own verdict when they do not
    pub whole_verdict: Verdict,
    pub whole_conditional: bool,
    pub whole_decided_by: Option<&'static str>,
    /// each side's set has zero weight outside it in every row: checked on
    /// the exact rows (in Q or Q(ζ_N)), or on the interval rows (an entry
    /// outside must be the point 0)
    pub invariance: Option<Check>,
    /// the crease curve's points (both sides hold them), matrix indices
    pub curve: Vec<usize>,
    pub sides: Vec<SideCertificate>,
    /// why the sides do not decouple, when they do not
    pub coupled: Option<String>,
}

/// One side's certificate: the sector criterion's spectral part proved
/// about the principal submatrix of S on the side's points.
#[derive(Clone, Debug, Serialize)]
pub struct SideCertificate {
    /// "side A (sectors 0..1, 2 faces, 15 points)"
    pub name: String,
    pub faces: usize,
    /// the side's points (matrix indices of S, ascending)
    pub indices: Vec<usize>,
    pub certificate: TaggedCertificate,
}

/// A certificate that proves nothing, with why.
fn not_proved_with(why: String, premises: TaggedPremises, statement: &str) -> TaggedCertificate {
    TaggedCertificate {
        verdict: Verdict::NotProved(why.clone()),
        conditional: false,
        statement: statement.into(),
        decided_by: None,
        premises,
        reflection: None,
        blocks: Vec::new(),
        enclosure_route: EnclosureRoute {
            verdict: Verdict::NotProved(why),
            lambda0: None,
            lambda1: None,
            lambda2: None,
            others_max_modulus: None,
            gap_lower_bound: None,
        },
        exact_route: None,
        exact_route_skipped: None,
        crease: None,
    }
}

/// Certify the spectral part of the sector criterion at a tagged vertex, from
/// the analysis the driver made (its discovery and labels; the float spectrum
/// only proposes the exact route's candidates).
pub fn certify_tagged(scheme: &dyn Scheme, analysis: &Analysis) -> Result<TaggedCertificate, Error> {
    let s = &analysis.spectrum;
    let config = &analysis.discovered.config;
    if config.tagging.is_none() {
        return Err(Error::Input("certify_tagged: the configuration is not tagged".into()));
    }
    if s.neighbourhood != NeighbourhoodKind::Analysis {
        return Err(Error::Input(
            "certificates speak about the analysis neighbourhood only (the minimal invariant set may miss larger \
             eigenvalues of the points the surface ring depends on): drop --neighbourhood minimal"
                .into(),
        ));
    }
    let labels = &s.labels;
    let size = labels.len();
    let not_proved = |why: String, premises: TaggedPremises| not_proved_with(why, premises, STATEMENT);
    let no_premises =
        || TaggedPremises { row_sums_one: Check::Fails("not checked".into()), reflection: None, field: None };
    if size > MAX_TAGGED_SIZE {
        return Ok(not_proved(
            format!("the tagged configuration's {size} points exceed the {MAX_TAGGED_SIZE} the enclosures support"),
            no_premises(),
        ));
    }
    let everyone: Vec<usize> = (0..size).collect();
    let rows: IntervalRows =
        match assemble_rows::<Interval>(scheme, &analysis.discovered, s.neighbourhood, &everyone) {
            Ok(r) => r,
            Err(AssembleError::Inexact) => {
                return Ok(not_proved(
                    "numerical only: a weight has no enclosure (a parameter or scheme-file expression known only in \
                 floating point; give it as a fraction)"
                        .into(),
                    no_premises(),
                ))
            }
            Err(AssembleError::NotInvariant) => return Ok(not_proved(
                "the invariance of the neighbourhood is not proved: a weight on a point outside it is enclosed by an \
                 interval that holds 0 but is not 0"
                    .into(),
                no_premises(),
            )),
            Err(e) => return Err(Error::Numeric(format!("the interval rows of S could not be assembled: {e:?}"))),
        };
    // the same rows exactly, one by one (rational, else in Q(ζ_N))
    let exact: ExactRows =
        everyone.iter().map(|&k| exact_rows(scheme, analysis, &[k]).and_then(|mut r| r.pop())).collect();
    // the float spectrum proposes the exact route's candidates (a side's
    // spectrum is part of S's, so they serve the sides too)
    let reals = s.eigenvalues.iter().filter(|e| e.im.abs() <= 1e-9 * e.modulus.max(1.0)).map(|e| e.re);
    let candidates = crate::engine::exact::candidates(reals);
    let mut whole = certify_rows(&rows, &exact, labels, reflection_of(config, labels), &candidates, STATEMENT)?;
    // a crease vertex: the verdict is the sides' where the rules decouple them
    if let Some(crease) = crease_certificate(analysis, &rows, &exact, &candidates, &whole)? {
        if crease.coupled.is_none() {
            let (verdict, conditional) = sides_verdict(&crease.sides);
            whole.verdict = verdict;
            whole.conditional = conditional;
            whole.decided_by = Some("sides");
            whole.statement = CREASE_STATEMENT.into();
        }
        whole.crease = Some(crease);
    }
    Ok(whole)
}

/// The sides of a crease vertex, certified one by one: their sets are
/// proposed by the float rows' reads (`spectrum::crease_sides::decouple`,
/// the dependency closure of each side's inside points), their invariance
/// is checked on this certificate's own rows (exact rows: the weight is 0 in
/// Q or Q(ζ_N); interval rows: absent or the point 0), and each side's
/// principal submatrix is certified by [`certify_rows`] with the reflection
/// restricted to it (r ↦ K − r keeps each side). `None` for other tags.
fn crease_certificate(
    analysis: &Analysis,
    rows: &IntervalRows,
    exact: &ExactRows,
    candidates: &[Rational],
    whole: &TaggedCertificate,
) -> Result<Option<CreaseCertificate>, Error> {
    let config = &analysis.discovered.config;
    let labels = &analysis.spectrum.labels;
    let Some(decoupling) = decoupling(config, &analysis.matrix) else { return Ok(None) };
    let mut out = CreaseCertificate {
        whole_verdict: whole.verdict.clone(),
        whole_conditional: whole.conditional,
        whole_decided_by: whole.decided_by,
        invariance: None,
        curve: Vec::new(),
        sides: Vec::new(),
        coupled: None,
    };
    let sides = match decoupling {
        Decoupling::Coupled(why) => {
            out.coupled = Some(why);
            return Ok(Some(out));
        }
        Decoupling::Sides(sides) => sides,
    };
    // the invariance, on the certificate's rows: the exact row where there
    // is one, else the interval row
    let mut invariance = Check::Exact;
    for set in &sides.sides {
        for &a in set {
            let outside = match &exact[a] {
                Some(row) => weight_outside(row, set, |w| w.is_zero()),
                None => weight_outside(&rows[a], set, |w| w.lo == 0.0 && w.hi == 0.0),
            };
            if let Some(b) = outside {
                invariance = Check::Fails(format!(
                    "the row of {} has a weight on {}, outside its side, not shown to be 0",
                    labels[a].name, labels[b].name
                ));
            }
        }
    }
    out.invariance = Some(invariance.clone());
    if !invariance.holds() {
        out.coupled = Some(format!("the sides' invariance is not proved: {invariance:?}"));
        return Ok(Some(out));
    }
    out.curve = sides.curve.clone();
    let image = reflection_of(config, labels);
    for (side, set) in sides.sides.iter().enumerate() {
        let name = sides.name(side);
        let side_rows: IntervalRows = principal(rows, set);
        let side_exact: ExactRows = set.iter().map(|&a| exact[a].as_ref().map(|row| principal_row(row, set))).collect();
        let side_labels: Vec<_> = set.iter().map(|&k| labels[k].clone()).collect();
        // the reflection keeps each side: its restriction, where it maps the
        // side's set onto itself
        let side_image: Option<Vec<usize>> =
            image.as_ref().and_then(|p| set.iter().map(|&k| set.binary_search(&p[k]).ok()).collect());
        let statement = format!(
            "for the principal submatrix of the true S on {name} (its rows have zero weight outside it): λ0 = 1 \
             simple; the next two eigenvalues by modulus λ1 ≥ λ2 real, positive, non-defective; every other \
             eigenvalue of modulus below λ2"
        );
        let certificate = certify_rows(&side_rows, &side_exact, &side_labels, side_image, candidates, &statement)?;
        out.sides.push(SideCertificate { name, faces: sides.faces(side), indices: set.clone(), certificate });
    }
    Ok(Some(out))
}

/// The crease's verdict from its sides': PROVED when both are (conditional
/// when either is), DISPROVED when one is (naming it), else NOT PROVED.
fn sides_verdict(sides: &[SideCertificate]) -> (Verdict, bool) {
    if let Some(d) = sides.iter().find(|s| matches!(s.certificate.verdict, Verdict::Disproved(_))) {
        return (
            Verdict::Disproved(format!("{}: {}", d.name, reason(&d.certificate.verdict))),
            d.certificate.conditional,
        );
    }
    let open: Vec<String> = sides
        .iter()
        .filter(|s| matches!(s.certificate.verdict, Verdict::NotProved(_)))
        .map(|s| format!("{}: {}", s.name, reason(&s.certificate.verdict)))
        .collect();
    if !open.is_empty() {
        return (Verdict::NotProved(open.join("; ")), false);
    }
    (Verdict::Proved, sides.iter().any(|s| s.certificate.conditional))
}

/// The certificate of one matrix given by its rows (interval, and exact
/// where known) over `labels`, with the reflection `image` that keeps the
/// sharp rays (checked here) and the exact route's rational candidates.
fn certify_rows(
    rows: &IntervalRows,
    exact: &ExactRows,
    labels: &[crate::neighbourhood::VertexLabel],
    image: Option<Vec<usize>>,
    candidates: &[Rational],
    statement: &str,
) -> Result<TaggedCertificate, Error> {
    let size = rows.len();
    let everyone: Vec<usize> = (0..size).collect();
    let not_proved = |why: String, premises: TaggedPremises| not_proved_with(why, premises, statement);
    let row_check = row_sums(&rows, &exact, labels, &everyone);
    let field = field_name(&exact);
    let dense_interval = dense(&rows, size, Interval::point(0.0));
    let dense_exact: Option<Vec<Vec<Cyclotomic>>> = exact.iter().all(Option::is_some).then(|| {
        let exact_rows: IntervalRowsOf<Cyclotomic> = exact.iter().map(|r| r.clone().unwrap_or_default()).collect();
        dense(&exact_rows, size, Cyclotomic::zero())
    });
    // the reflection: checked exactly on exact rows, else to overlap
    let reflection_check = image.as_ref().map(|p| match &dense_exact {
        Some(e) => {
            if commutes(e, p, |a, b| a == b) {
                Check::Exact
            } else {
                Check::Fails("S does not commute with the reflection (exact)".into())
            }
        }
        None => {
            if commutes(&dense_interval, p, |a, b| a.overlaps(b)) {
                Check::Overlap
            } else {
                Check::Fails("S does not commute with the reflection (disjoint enclosures)".into())
            }
        }
    });
    let premises = TaggedPremises { row_sums_one: row_check.clone(), reflection: reflection_check.clone(), field };
    if !row_check.holds() {
        return Ok(not_proved(format!("1 is not known to be an eigenvalue: {row_check:?}"), premises));
    }
    let split_by = image.filter(|_| reflection_check.as_ref().is_some_and(Check::holds));
    // the interval blocks: E and O, or S whole
    let interval_blocks: Vec<(&'static str, Vec<Vec<Interval>>)> = match &split_by {
        Some(p) => {
            let b = split(&dense_interval, p);
            vec![("even", b.even), ("odd", b.odd)]
        }
        None => vec![("whole", dense_interval)],
    };
    let blocks: Vec<TaggedBlock> = interval_blocks
        .iter()
        .map(|(name, m)| {
            let k = m.len();
            let mut a = CIntervalMatrix::zeros(k);
            for (i, row) in m.iter().enumerate() {
                for (j, w) in row.iter().enumerate() {
                    *a.at(i, j) = CInterval::real(*w);
                }
            }
            match enclose(&a) {
                Ok(e) => TaggedBlock {
                    name,
                    size: k,
                    epsilon: Some(e.epsilon),
                    components: e.components,
                    failure: None,
                    diagonalisation: Some(e.diagonalisation),
                },
                Err(why) => TaggedBlock {
                    name,
                    size: k,
                    epsilon: None,
                    components: Vec::new(),
                    failure: Some(why),
                    diagonalisation: None,
                },
            }
        })
        .collect();
    let enclosure_route = decide(&blocks);
    // the exact route: every weight rational, each block within the bound
    let decisive = |v: &Verdict| !matches!(v, Verdict::NotProved(_));
    let rational: Option<Vec<(&'static str, QMatrix)>> = dense_exact.as_ref().and_then(|e| {
        let blocks: Vec<(&'static str, Vec<Vec<Cyclotomic>>)> = match &split_by {
            Some(p) => {
                let b = split(e, p);
                vec![("even", b.even), ("odd", b.odd)]
            }
            None => vec![("whole", e.clone())],
        };
        blocks.into_iter().map(|(name, m)| to_q(&m).map(|q| (name, q))).collect()
    });
    // the exact route decides what the enclosures cannot, and re-decides
    // small matrices (a cross-check: the two routes must agree); past
    // [`CROSS_CHECK_SIZE`] points a decided verdict is not re-derived, as
    // the rational reduction grows much faster than the enclosures
    let wanted = !decisive(&enclosure_route.verdict) || size <= CROSS_CHECK_SIZE;
    let (exact_route, exact_route_skipped) = match rational {
        None if dense_exact.is_none() => (None, Some("a row of S is known in floating point only".to_string())),
        None => (None, Some("a weight is irrational (in Q(ζ_N), not Q): the route needs S over Q".to_string())),
        Some(_) if !wanted => (
            None,
            Some(format!(
                "the enclosures decided and S has {size} points, above the {CROSS_CHECK_SIZE} re-decided exactly"
            )),
        ),
        Some(q) if q.iter().any(|(_, m)| m.n > MAX_EXACT_BLOCK) => {
            (None, Some(format!("a block exceeds the {MAX_EXACT_BLOCK} rows the exact route reduces over Q")))
        }
        Some(q) => (Some(exact_sector(&q, candidates)), None),
    };
    // the verdict: each route is a proof on its own; they must agree
    let enclosures_decide = decisive(&enclosure_route.verdict);
    let exact_decides = exact_route.as_ref().is_some_and(|e| decisive(&e.verdict));
    if let (true, Some(e)) = (enclosures_decide && exact_decides, &exact_route) {
        if enclosure_route.verdict.word() != e.verdict.word() {
            return Err(Error::Numeric(format!(
                "the certificate's two routes disagree (enclosures: {}; exact: {}): a defect of subdlab, please report it",
                enclosure_route.verdict.display(),
                e.verdict.display()
            )));
        }
    }
    let (verdict, decided_by) = match (enclosures_decide, exact_decides) {
        (true, true) => (enclosure_route.verdict.clone(), Some("both")),
        (true, false) => (enclosure_route.verdict.clone(), Some("enclosures")),
        (false, true) => (exact_route.as_ref().expect("decides").verdict.clone(), Some("exact")),
        (false, false) => {
            let mut why = format!("enclosures: {}", reason(&enclosure_route.verdict));
            match (&exact_route, &exact_route_skipped) {
                (Some(e), _) => why += &format!("; exact route: {}", reason(&e.verdict)),
                (None, Some(skip)) => why += &format!("; exact route not taken: {skip}"),
                (None, None) => {}
            }
            (Verdict::NotProved(why), None)
        }
    };
    // the enclosure route rests on the premises; the exact route reads S
    let overlap = |c: &Check| *c == Check::Overlap;
    let conditional = decided_by == Some("enclosures")
        && (overlap(&premises.row_sums_one) || premises.reflection.as_ref().is_some_and(overlap));
    Ok(TaggedCertificate {
        verdict,
        conditional,
        statement: statement.into(),
        decided_by,
        premises,
        reflection: split_by,
        blocks,
        enclosure_route,
        exact_route,
        exact_route_skipped,
        crease: None,
    })
}

fn reason(v: &Verdict) -> &str {
    match v {
        Verdict::Proved => "proved",
        Verdict::Disproved(w) | Verdict::NotProved(w) => w,
    }
}

type IntervalRowsOf<W> = Vec<Vec<(usize, W)>>;

/// Sparse rows to a dense matrix (a column listed twice is summed).
pub(super) fn dense<W: Weight>(rows: &IntervalRowsOf<W>, size: usize, zero: W) -> Vec<Vec<W>> {
    rows.iter()
        .map(|row| {
            let mut d = vec![zero.clone(); size];
            for (c, w) in row {
                d[*c] = d[*c].clone() + w.clone();
            }
            d
        })
        .collect()
}

/// The field of the exact rows: "Q", "Q(ζ_N)", or `None` when no row is exact.
fn field_name(exact: &ExactRows) -> Option<String> {
    let mut order: Option<u64> = None;
    for row in exact.iter().flatten() {
        let mut l = order.unwrap_or(1);
        for (_, w) in row {
            let n = w.order().unwrap_or(1) as u64;
            l = l / crate::numeric::weight::gcd(l as i64, n as i64) as u64 * n;
        }
        order = Some(l);
    }
    order.map(|n| if n == 1 { "Q".to_string() } else { format!("Q(ζ_{n})") })
}

/// A matrix over Q(ζ_N) as a rational matrix, when every entry is rational.
fn to_q(m: &[Vec<Cyclotomic>]) -> Option<QMatrix> {
    let mut q = QMatrix::zeros(m.len());
    for (i, row) in m.iter().enumerate() {
        for (j, w) in row.iter().enumerate() {
            q.set(i, j, w.to_rational()?);
        }
    }
    Some(q)
}

/// The enclosure route (lemma T4) on the blocks' components.
fn decide(blocks: &[TaggedBlock]) -> EnclosureRoute {
    let mut route = EnclosureRoute {
        verdict: Verdict::NotProved(String::new()),
        lambda0: None,
        lambda1: None,
        lambda2: None,
        others_max_modulus: None,
        gap_lower_bound: None,
    };
    let finish = |mut route: EnclosureRoute, v: Verdict| {
        route.verdict = v;
        route
    };
    // every component of every block, by (block, index)
    let all: Vec<(usize, usize, &Component)> = blocks
        .iter()
        .enumerate()
        .flat_map(|(b, blk)| blk.components.iter().enumerate().map(move |(i, c)| (b, i, c)))
        .collect();
    if let Some((b, _, c)) = all.iter().find(|(_, _, c)| c.min_modulus() > 1.0) {
        return finish(
            route,
            Verdict::Disproved(format!(
                "the {} block has an eigenvalue of modulus ≥ {:.9} > 1",
                blocks[*b].name,
                c.min_modulus()
            )),
        );
    }
    if let Some(b) = blocks.iter().find(|b| b.failure.is_some()) {
        return finish(
            route,
            Verdict::NotProved(format!("{} block: {}", b.name, b.failure.as_deref().unwrap_or_default())),
        );
    }
    // (a) λ0: the one component of all blocks that may hold 1 (1 is an
    // eigenvalue of S by the row sums)
    let holding_one: Vec<&(usize, usize, &Component)> =
        all.iter().filter(|(_, _, c)| c.may_hold(faer::c64::new(1.0, 0.0))).collect();
    let [&(b0, i0, c0)] = holding_one.as_slice() else {
        return finish(
            route,
            Verdict::NotProved(format!("{} components may hold 1: λ0 is not separated", holding_one.len())),
        );
    };
    let (lo0, hi0) = c0.real_range();
    route.lambda0 =
        Some(Named { block: blocks[b0].name, component: i0, enclosure: RealEnclosure { lo: lo0, hi: hi0 } });
    if c0.count != 1 {
        return finish(
            route,
            Verdict::NotProved(format!(
                "the enclosure of λ0 = 1 holds {} eigenvalues: simplicity is not separated",
                c0.count
            )),
        );
    }
    // (b) λ1, λ2: the two components of largest lower modulus bound (any
    // valid pair is these two: each of its lower bounds exceeds every other
    // component's upper, so every other's lower)
    let mut rest: Vec<(usize, usize, &Component)> =
        all.iter().copied().filter(|&(b, i, _)| !(b == b0 && i == i0)).collect();
    rest.sort_by(|x, y| y.2.min_modulus().total_cmp(&x.2.min_modulus()));
    let Some(&(ba, ia, ca)) = rest.first() else {
        return finish(route, Verdict::NotProved("no eigenvalue besides λ0".into()));
    };
    if ca.count != 1 {
        return finish(
            route,
            Verdict::NotProved(format!(
                "the leading enclosure of the {} block holds {} eigenvalues (modulus in [{:.9}, {:.9}]): the discs \
                 cannot separate them or show them non-defective",
                blocks[ba].name,
                ca.count,
                ca.min_modulus(),
                ca.max_modulus()
            )),
        );
    }
    let Some(&(bb, ib, cb)) = rest.get(1) else {
        return finish(route, Verdict::NotProved("fewer than three eigenvalues".into()));
    };
    // a real eigenvalue: one eigenvalue in a component meeting the real axis
    // whose mirror image meets no other component of its (real) block
    let real = |b: usize, c: &Component| {
        let mirror = Component {
            discs: c.discs.iter().map(|d| Disc { im: -d.im, ..*d }).collect(),
            count: c.count,
            rows: c.rows.clone(),
        };
        c.count == 1
            && c.meets_real_axis()
            && blocks[b].components.iter().filter(|o| !std::ptr::eq(*o, c)).all(|o| o.disjoint(&mirror))
    };
    let others = || rest.iter().skip(2);
    let others_max = others().map(|(_, _, c)| c.max_modulus()).fold(0.0, f64::max);
    route.others_max_modulus = Some(others_max);
    let separated = |c: &Component| c.min_modulus() > others_max;
    // a disproof: the top two are separated from the rest and hold exactly
    // two eigenvalues, one of which is proved not real or not positive
    if cb.count == 1 && separated(ca) && separated(cb) {
        for &(b, c) in &[(ba, ca), (bb, cb)] {
            if !c.meets_real_axis() {
                return finish(
                    route,
                    Verdict::Disproved(format!(
                        "a subdominant eigenvalue of the {} block is not real (its disc about {:.9}{:+.9}i of radius \
                         {:.2e} misses the real axis)",
                        blocks[b].name, c.discs[0].re, c.discs[0].im, c.discs[0].radius
                    )),
                );
            }
            if real(b, c) && c.real_range().1 < 0.0 {
                return finish(
                    route,
                    Verdict::Disproved(format!(
                        "a subdominant eigenvalue of the {} block is negative (≤ {:.9})",
                        blocks[b].name,
                        c.real_range().1
                    )),
                );
            }
        }
    }
    if cb.count != 1 {
        return finish(
            route,
            Verdict::NotProved(format!(
                "the second enclosure ({} block) holds {} eigenvalues (modulus in [{:.9}, {:.9}]): not separated",
                blocks[bb].name,
                cb.count,
                cb.min_modulus(),
                cb.max_modulus()
            )),
        );
    }
    let mut named = Vec::new();
    for &(b, i, c) in &[(ba, ia, ca), (bb, ib, cb)] {
        if !real(b, c) {
            return finish(
                route,
                Verdict::NotProved(format!(
                    "the enclosure of a subdominant eigenvalue of the {} block is not shown real (it misses the \
                     axis, or its mirror image meets another enclosure)",
                    blocks[b].name
                )),
            );
        }
        // real, so in the real range; the modulus bounds tighten it once
        // the sign is known from the range itself
        let (lo, hi) = c.real_range();
        if lo <= 0.0 {
            return finish(
                route,
                Verdict::NotProved(format!(
                    "a subdominant enclosure of the {} block holds 0 or negatives",
                    blocks[b].name
                )),
            );
        }
        let e = RealEnclosure { lo: lo.max(c.min_modulus()), hi: hi.min(c.max_modulus()) };
        if e.hi.partial_cmp(&lo0) != Some(std::cmp::Ordering::Less) {
            return finish(route, Verdict::NotProved("a subdominant eigenvalue is not separated from λ0 = 1".into()));
        }
        named.push(Named { block: blocks[b].name, component: i, enclosure: e });
    }
    // λ1 the larger (by enclosure midpoint: which one is called λ1 changes
    // nothing proved, both are simple, real and positive)
    named.sort_by(|x, y| (y.enclosure.lo + y.enclosure.hi).total_cmp(&(x.enclosure.lo + x.enclosure.hi)));
    let lambda2_lower = named.iter().map(|n| n.enclosure.lo).fold(f64::INFINITY, f64::min);
    let gap = (Interval::point(lambda2_lower) - Interval::point(others_max)).lo;
    route.gap_lower_bound = Some(gap);
    let mut named = named.into_iter();
    route.lambda1 = named.next();
    route.lambda2 = named.next();
    if gap <= 0.0 {
        let (b, _, c) = others().max_by(|x, y| x.2.max_modulus().total_cmp(&y.2.max_modulus())).copied().expect("gap");
        return finish(
            route,
            Verdict::NotProved(format!(
                "an eigenvalue enclosure of the {} block ({} eigenvalue(s), modulus up to {:.9}) reaches λ2 ≥ {:.9}",
                blocks[b].name,
                c.count,
                c.max_modulus(),
                lambda2_lower
            )),
        );
    }
    finish(route, Verdict::Proved)
}

/// Lemma T7: the sector criterion's spectral part decided over Q from the
/// blocks' characteristic polynomials and ranks. With p the product of the
/// blocks' characteristic polynomials (= det(xI − S)), 1 of multiplicity 1,
/// p1 = p/(x − 1), and a rational candidate 0 < r < 1 a root of p1 of
/// multiplicity m, q = p1/(x − r)^m, c = the number of roots of q of modulus
/// above r (the counting Schur–Cohn recursion, `numeric::exact::roots_above`,
/// which also shows that no root of q has modulus r): the eigenvalues other than λ0 by modulus are then c
/// roots above r, r m times, the rest below r. So
///
/// - c = 0, m = 2: λ1 = λ2 = r; PROVED iff rank(S − rI) = N − 2 (else a
///   Jordan block: DISPROVED);
/// - c = 0, m ≥ 3 or c = 1, m ≥ 2: |λ3| = r = λ2: DISPROVED;
/// - c = 1, m = 1: λ2 = r simple, λ1 = μ the one root of q above r in
///   modulus, simple and real (a non-real one comes with its conjugate);
///   μ > r iff q changes sign on (r, ∞), i.e. sign q(r) ≠ sign of q's
///   leading coefficient (q(r) ≠ 0: r was divided out); μ < 1 iff no root
///   of q has modulus ≥ 1 (the count at radius 1). PROVED when μ > r and the
///   count at 1 is 0; DISPROVED when μ < −r (λ1 negative) or a root lies
///   above 1;
/// - c ≥ 2, or m = 1 with c = 0 (λ1 = r: λ2 is a smaller candidate): not
///   decided by this r.
fn exact_sector(blocks: &[(&'static str, QMatrix)], candidates: &[Rational]) -> ExactRoute {
    let sizes: Vec<(&'static str, usize)> = blocks.iter().map(|(n, m)| (*n, m.n)).collect();
    let n: usize = sizes.iter().map(|s| s.1).sum();
    let mut route = ExactRoute {
        verdict: Verdict::NotProved(String::new()),
        blocks: sizes,
        one_multiplicity: 0,
        r: None,
        algebraic: 0,
        geometric: 0,
        above: 0,
    };
    let p = blocks.iter().fold(Poly::one(), |p, (_, m)| times(&p, &m.charpoly()));
    let one = <Rational as One>::one();
    let (m1, p1) = p.root_multiplicity(&one);
    route.one_multiplicity = m1;
    match m1 {
        0 => {
            route.verdict = Verdict::NotProved("1 is not a root of det(xI − S)".into());
            return route;
        }
        1 => {}
        m => {
            route.verdict = Verdict::Disproved(format!(
                "λ0 = 1 is not simple: a root of det(xI − S) of multiplicity {m} (exact, over Q)"
            ));
            return route;
        }
    }
    let mut rs: Vec<Rational> = candidates.iter().filter(|r| r.is_positive() && **r < one).cloned().collect();
    rs.sort_by(|a, b| b.cmp(a));
    rs.dedup();
    let rank_shifted = |r: &Rational| blocks.iter().map(|(_, m)| m.shifted(r).rank()).sum::<usize>();
    let mut why = Vec::new();
    for r in rs {
        let (m, q) = p1.root_multiplicity(&r);
        if m == 0 {
            continue;
        }
        let Some(c) = roots_above(&q, &r) else {
            why.push(format!("{r} (multiplicity {m}): another eigenvalue may have modulus {r}"));
            continue;
        };
        let set = |route: &mut ExactRoute, v: Verdict, geometric: usize| {
            route.r = Some(r.to_string());
            route.algebraic = m;
            route.geometric = geometric;
            route.above = c;
            route.verdict = v;
        };
        match (c, m) {
            (0, 2) => {
                let geometric = n - rank_shifted(&r);
                let v = if geometric == 2 {
                    Verdict::Proved
                } else {
                    Verdict::Disproved(format!(
                        "λ1 = λ2 = {r} (every other eigenvalue but 1 below it in modulus) has geometric multiplicity \
                         {geometric}: a Jordan block (exact, over Q)"
                    ))
                };
                set(&mut route, v, geometric);
                return route;
            }
            (0, _) | (1, _) if m >= 2 => {
                let geometric = n - rank_shifted(&r);
                let v = Verdict::Disproved(format!(
                    "{r} is a root of det(xI − S) of multiplicity {m} with {c} eigenvalue(s) other than 1 above it in \
                     modulus: |λ3| = λ2 = {r}{} (exact, over Q)",
                    if geometric < m {
                        format!(", and defective (geometric multiplicity {geometric})")
                    } else {
                        String::new()
                    }
                ));
                set(&mut route, v, geometric);
                return route;
            }
            (1, 1) => {
                let at_r = q.eval(&r);
                let lead = q.coeffs.last().cloned().unwrap_or_else(<Rational as Zero>::zero);
                let mu_above_r = at_r.is_positive() != lead.is_positive();
                let above_one = roots_above(&q, &one);
                let v = match (mu_above_r, above_one) {
                    (false, _) => Verdict::Disproved(format!(
                        "λ2 = {r} is simple and the one eigenvalue above it in modulus is negative (below −{r}): λ1 is \
                         not positive (exact, over Q)"
                    )),
                    (true, Some(0)) => Verdict::Proved,
                    (true, Some(k)) => Verdict::Disproved(format!(
                        "{k} eigenvalue(s) other than 1 have modulus above 1 (exact, over Q)"
                    )),
                    (true, None) => {
                        why.push(format!("{r}: an eigenvalue may have modulus 1"));
                        continue;
                    }
                };
                set(&mut route, v, 1);
                return route;
            }
            _ => why.push(format!("{r} (multiplicity {m}) has {c} eigenvalues above it in modulus")),
        }
        // every smaller candidate has these c roots and r's m above it:
        // c + m ≥ 2 of them leave it neither λ1 nor λ2
        if c + m >= 2 {
            break;
        }
    }
    if why.is_empty() {
        why.push("no rational candidate decides (λ2 irrational, or no candidate is a root)".into());
    }
    route.verdict = Verdict::NotProved(why.join("; "));
    route
}

/// The product of two polynomials over Q.
fn times(a: &Poly, b: &Poly) -> Poly {
    let mut coeffs = vec![<Rational as Zero>::zero(); a.coeffs.len() + b.coeffs.len() - 1];
    for (i, x) in a.coeffs.iter().enumerate() {
        for (j, y) in b.coeffs.iter().enumerate() {
            coeffs[i + j] = &coeffs[i + j] + x * y;
        }
    }
    Poly { coeffs }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::exact::q;

    fn qm(rows: &[&[(i64, i64)]]) -> QMatrix {
        let mut m = QMatrix::zeros(rows.len());
        for (i, r) in rows.iter().enumerate() {
            for (j, &(a, b)) in r.iter().enumerate() {
                m.set(i, j, q(a, b));
            }
        }
        m
    }

    /// Lemma T7's cases on matrices whose spectra are read off by hand
    /// (triangular: the diagonal; a 1 above the diagonal between equal
    /// diagonal entries is a Jordan block).
    #[test]
    fn the_exact_route_on_hand_made_spectra() {
        let z = (0, 1);
        // even diag(1, 1/2, 1/8), odd diag(1/2, 1/4): λ1 = λ2 = 1/2 one per block
        let even = qm(&[&[(1, 1), z, z], &[z, (1, 2), z], &[z, z, (1, 8)]]);
        let odd = qm(&[&[(1, 2), z], &[z, (1, 4)]]);
        let r = exact_sector(&[("even", even), ("odd", odd)], &[q(1, 2), q(1, 4)]);
        assert_eq!(r.verdict, Verdict::Proved, "{r:?}");
        assert_eq!((r.algebraic, r.geometric, r.above), (2, 2, 0));
        // the odd block a Jordan block at 1/2 under λ1 = 3/5: |λ3| = λ2, defective
        let even = qm(&[&[(1, 1), z, z], &[z, (3, 5), z], &[z, z, (1, 8)]]);
        let odd = qm(&[&[(1, 2), (1, 1)], &[z, (1, 2)]]);
        let r = exact_sector(&[("even", even), ("odd", odd)], &[q(3, 5), q(1, 2)]);
        assert!(matches!(&r.verdict, Verdict::Disproved(w) if w.contains("defective")), "{r:?}");
        assert_eq!((r.algebraic, r.geometric, r.above), (2, 1, 1));
        // λ1 = 3/5, λ2 = 1/2 simple, the rest below: proved from r = 1/2 (c = 1)
        let whole = qm(&[&[(1, 1), z, z, z], &[z, (3, 5), z, z], &[z, z, (1, 2), z], &[z, z, z, (1, 4)]]);
        let r = exact_sector(&[("whole", whole)], &[q(3, 5), q(1, 2), q(1, 4)]);
        assert_eq!(r.verdict, Verdict::Proved, "{r:?}");
        assert_eq!(r.r.as_deref(), Some("1/2"));
        // λ1 = −3/5 (negative) above λ2 = 1/2: disproved
        let whole = qm(&[&[(1, 1), z, z], &[z, (-3, 5), z], &[z, z, (1, 2)]]);
        let r = exact_sector(&[("whole", whole)], &[q(1, 2)]);
        assert!(matches!(&r.verdict, Verdict::Disproved(w) if w.contains("negative")), "{r:?}");
        // −1/2 beside 1/2: no root may have modulus r: not decided
        let whole = qm(&[&[(1, 1), z, z, z], &[z, (3, 5), z, z], &[z, z, (1, 2), z], &[z, z, z, (-1, 2)]]);
        let r = exact_sector(&[("whole", whole)], &[q(1, 2)]);
        assert!(matches!(r.verdict, Verdict::NotProved(_)), "{r:?}");
        // 1 double: disproved
        let whole = qm(&[&[(1, 1), z, z], &[z, (1, 1), z], &[z, z, (1, 2)]]);
        let r = exact_sector(&[("whole", whole)], &[q(1, 2)]);
        assert!(matches!(&r.verdict, Verdict::Disproved(w) if w.contains("not simple")), "{r:?}");
    }
}
