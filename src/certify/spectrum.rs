//! The certified spectral verdict: from the interval Fourier blocks of S,
//! rigorous eigenvalue enclosures per block, and from them a proof (or a
//! disproof, or the precise reason for neither) of the spectral part of
//! Reif's C¹ criterion:
//!
//! (a) λ0 = 1 is a simple eigenvalue;
//! (b) the subdominant eigenvalue λ1 is real and positive, one simple
//!     eigenvalue of block 1 and one of block g − 1 (so a semisimple double
//!     eigenvalue of S: its two eigenvectors lie in different blocks);
//! (c) every other eigenvalue is smaller in modulus than λ1, with a proven gap.
//!
//! What the enclosures prove directly: the number of eigenvalues of each
//! block in each disc component, and bounds of their moduli. Three facts are
//! equalities, which no enclosure can prove, and come from the structure of
//! S instead (`matrix::rotation_symmetry`, `matrix::row_sums`,
//! `matrix::mirror_symmetry`):
//!
//! - the Fourier blocks are S in another basis: S commutes with the rotation
//!   (checked on every row of S, not only the representatives' the blocks
//!   are built from);
//! - 1 is an eigenvalue (of block 0): every row of S sums to 1;
//! - λ1 is real: S commutes with a reflection of the neighbourhood, so the
//!   spectrum of every block is closed under conjugation, and a simple
//!   eigenvalue whose disc component is its own mirror image is real.
//!
//! Each is checked exactly when the rows involved are exact: rational rows in
//! Q, rows whose weights hold cos(2πk/n) (Loop's β, the Doo–Sabin weights) in
//! the cyclotomic field Q(ζ_N) (`numeric::cyclotomic`), assembled by the same
//! rules. Only where a weight is known in floating point alone (a float
//! parameter, a scheme-file expression outside the exact evaluator) is an
//! identity confirmed to interval overlap only (then it is an identity of
//! the rules' formulas, such as (1 − nβ) + n·β = 1, that the certificate
//! confirms to ~1e-16 but cannot prove); the verdict says which, and names
//! the field of the exact checks.

use super::discs::{enclose, Component, Diagonalisation, Disc};
use super::matrix::{
    fourier_blocks, mirror_symmetry, rotation_symmetry, row_sums, whole_matrix, Check, ExactRows, IntervalRows,
};
use super::power::{power_bound, PowerBound};
use crate::dft::Orbits;
use crate::error::Error;
use crate::matrix::local::{assemble_rows, assemble_rows_rational, AssembleError};
use crate::neighbourhood::NeighbourhoodKind;
use crate::numeric::{Cyclotomic, Interval};
use crate::sdc::Scheme;
use crate::spectrum::{Analysis, Method};
use faer::{c64, Mat};
use num_traits::ToPrimitive;
use rayon::prelude::*;
use serde::Serialize;
use std::cell::Cell;

/// Largest whole matrix (no rotation symmetry) enclosed: interval matrix
/// products cost about 100 times the floating-point ones.
pub const MAX_CERTIFIED_FULL_SIZE: usize = 400;

#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "verdict", content = "reason")]
pub enum Verdict {
    Proved,
    Disproved(String),
    NotProved(String),
}

impl Verdict {
    pub fn word(&self) -> &'static str {
        match self {
            Verdict::Proved => "PROVED",
            Verdict::Disproved(_) => "DISPROVED",
            Verdict::NotProved(_) => "NOT PROVED",
        }
    }
    pub fn display(&self) -> String {
        match self {
            Verdict::Proved => "PROVED".into(),
            Verdict::Disproved(r) => format!("DISPROVED ({r})"),
            Verdict::NotProved(r) => format!("NOT PROVED ({r})"),
        }
    }
}

/// The enclosure of one block's eigenvalues.
#[derive(Clone, Debug, Serialize)]
pub struct BlockEnclosure {
    pub block: usize,
    pub size: usize,
    /// ε ≥ ‖I − RV‖∞ of the verification (null when it failed)
    pub epsilon: Option<f64>,
    pub components: Vec<Component>,
    /// why there is no enclosure, when there is none
    pub failure: Option<String>,
    /// the verified diagonalisation the components come from (an
    /// eigenvector enclosure of a proved eigenvalue is taken from it)
    #[serde(skip)]
    pub diagonalisation: Option<Diagonalisation>,
    /// lemma S6 (`certify::power`): ρ(B) ≤ ‖B^k‖∞^{1/k}, computed for a
    /// block that need not hold λ0 or λ1 (every block but 0, 1 and g − 1)
    /// when its discs fail or reach λ1; the proof uses it in place of the
    /// discs' moduli. Absent when not computed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub power_bound: Option<PowerBound>,
}

impl BlockEnclosure {
    /// The enclosure of the complex-conjugate block, named `block`: every
    /// disc, the diagonalisation's V and R conjugated; sizes, ε and the
    /// failure unchanged (no power bound: it is computed per block later).
    fn conjugate(&self, block: usize) -> BlockEnclosure {
        let conj_discs =
            |discs: &[Disc]| discs.iter().map(|d| Disc { re: d.re, im: -d.im, radius: d.radius }).collect();
        BlockEnclosure {
            block,
            size: self.size,
            epsilon: self.epsilon,
            components: self
                .components
                .iter()
                .map(|c| Component { discs: conj_discs(&c.discs), count: c.count, rows: c.rows.clone() })
                .collect(),
            failure: self.failure.clone(),
            diagonalisation: self.diagonalisation.as_ref().map(|d| Diagonalisation {
                v: Mat::from_fn(d.v.nrows(), d.v.ncols(), |i, j| d.v[(i, j)].conj()),
                r: Mat::from_fn(d.r.nrows(), d.r.ncols(), |i, j| d.r[(i, j)].conj()),
                discs: conj_discs(&d.discs),
                epsilon: d.epsilon,
            }),
            power_bound: None,
        }
    }
}

/// An enclosure of a real eigenvalue: lo ≤ λ ≤ hi.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct RealEnclosure {
    pub lo: f64,
    pub hi: f64,
}

/// The proof's margins.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Margins {
    /// enclosure of λ0 (holds 1 when proved)
    pub lambda0: Option<RealEnclosure>,
    /// enclosure of λ1 (real when proved)
    pub lambda1: Option<RealEnclosure>,
    /// upper bound of the modulus of every other eigenvalue
    pub others_max_modulus: Option<f64>,
    /// lower bound of λ1 − max |other eigenvalue| (positive when proved)
    pub gap_lower_bound: Option<f64>,
    /// the lower bound of λ1's modulus the gap is measured from (lemma S6's
    /// bounds are compared with it)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda1_lower: Option<f64>,
    /// the blocks whose eigenvalues the gap bounds by lemma S6 (their
    /// `power_bound`) rather than by their discs
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub power_bounded: Vec<usize>,
    /// the largest radius of the discs of λ0 and λ1, and of any disc
    pub lambda_radius: Option<f64>,
    pub max_radius: f64,
    /// the largest width of an entry of the interval blocks
    pub max_entry_width: f64,
}

/// Structural facts used by the proof, and how each was checked.
#[derive(Clone, Debug, Serialize)]
pub struct Premises {
    /// every row of S sums to 1 (1 is an eigenvalue)
    pub row_sums_one: Check,
    /// S commutes with a reflection (block spectra closed under conjugation)
    pub mirror_symmetry: Check,
    /// S commutes with the rotation (the Fourier blocks are S in another
    /// basis: checked on every row, not only the representatives')
    pub rotation_symmetry: Check,
    /// all three checked exactly: the proof uses no identity confirmed only
    /// to interval overlap
    pub exact: bool,
    /// the field the exact checks were made in: "Q" when every exact row is
    /// rational, else "Q(ζ_N)" (ζ_N = e^{2πi/N}, N the lcm of the orders of
    /// the entries: rows holding cos(2πk/n) for n | N); null when no row is
    /// exact
    pub field: Option<String>,
    /// the axis of the reflection that holds (`matrix::mirror_map`'s): the
    /// spoke axis n − 1, or another where the face sequence needs it
    #[serde(skip)]
    pub mirror_axis: Option<usize>,
}

#[derive(Clone, Debug, Serialize)]
pub struct SpectrumCertificate {
    #[serde(flatten)]
    pub verdict: Verdict,
    /// true when a PROVED or DISPROVED verdict uses a premise confirmed only
    /// to interval overlap (see `premises`): decided given that identity of
    /// the formulas
    pub conditional: bool,
    /// what the verdict covers (one sentence)
    pub statement: String,
    pub premises: Option<Premises>,
    pub margins: Margins,
    /// the enclosure that decides a disproof: the block and its component
    pub witness: Option<Witness>,
    pub blocks: Vec<BlockEnclosure>,
    /// what a proof built on this one needs (the characteristic-map
    /// certificate): the orbits and, when PROVED, which disc of which
    /// diagonalisation holds λ1. Taken from the enclosures, never from the
    /// floating-point spectrum.
    #[serde(skip)]
    pub proof: Option<SpectralProof>,
    /// the components the verdict rests on (for the certificate document)
    #[serde(skip)]
    pub named: Named,
    /// set when the verdict was proved by the exact route (lemma S7: the
    /// whole rational matrix's characteristic polynomial) instead of the
    /// block enclosures
    pub exact_route: Option<super::exact_spectrum::ExactSpectrum>,
}

/// The data a PROVED spectral certificate hands on.
#[derive(Clone, Debug)]
pub struct SpectralProof {
    pub orbits: Orbits,
    /// λ1: the row of its one-disc component in block 1's diagonalisation
    /// (`blocks[1].diagonalisation`), set only when the verdict is PROVED
    pub lambda1_row: Option<usize>,
}

#[derive(Clone, Debug, Serialize)]
pub struct Witness {
    pub block: usize,
    pub component: Component,
    /// the component's index among its block's components
    #[serde(skip)]
    pub index: usize,
}

/// The components a verdict names, as indices into a block's `components`:
/// a checker of the certificate document re-checks exactly these.
#[derive(Clone, Copy, Debug, Default)]
pub struct Named {
    /// λ0's component in block 0
    pub lambda0: Option<usize>,
    /// λ1's components: in block 1 and in block g − 1
    pub lambda1: Option<[usize; 2]>,
}

const STATEMENT: &str = "for the true local subdivision matrix S on the analysis neighbourhood (every point \
     whose position the surface ring around the centre depends on; every weight enclosed, cos(2πk/n) included): \
     λ0 = 1 simple; λ1 real, positive, simple in block 1 and in block g−1 (semisimple, geometric multiplicity 2); \
     every other eigenvalue of modulus below λ1";

/// [`certify_spectrum`] with the configuration's own rotation period (the
/// valence when the scheme's rules are not rotation symmetric).
/// Made once per analysis and shared (a spectral claim and a characteristic
/// map claim about the same scheme and valence prove the same spectrum).
pub fn certify_analysis(scheme: &dyn Scheme, analysis: &Analysis) -> Result<SpectrumCertificate, Error> {
    let config = &analysis.discovered.config;
    let period = config.rotation_period(scheme);
    let shared = analysis.derived(period as u64, || certify_spectrum(scheme, analysis, period))?;
    Ok(SpectrumCertificate::clone(&shared))
}

/// The orbits [`certify_analysis`] builds its Fourier blocks on (the
/// configuration's own rotation period).
pub fn analysis_orbits(scheme: &dyn Scheme, analysis: &Analysis) -> Orbits {
    let s = &analysis.spectrum;
    Orbits::from_labels(&s.labels, analysis.discovered.config.rotation_period(scheme), s.valence)
}

/// Certify the spectrum of an analysis that the driver made (its discovery,
/// labels and method are reused; `period` is the configuration's rotation
/// period in sectors).
pub fn certify_spectrum(scheme: &dyn Scheme, analysis: &Analysis, period: usize) -> Result<SpectrumCertificate, Error> {
    let s = &analysis.spectrum;
    let n = s.valence;
    let labels = &s.labels;
    // a proof on a smaller invariant set says nothing of the eigenvalues the
    // analysis neighbourhood adds, which may be larger than its λ1
    if s.neighbourhood != NeighbourhoodKind::Analysis {
        return Err(Error::Input(
            "certificates speak about the analysis neighbourhood only (the minimal invariant set may miss larger \
             eigenvalues of the points the surface ring depends on): drop --neighbourhood minimal"
                .into(),
        ));
    }
    let orbits = Orbits::from_labels(labels, period, n);
    let not_proved = |why: String| SpectrumCertificate {
        verdict: Verdict::NotProved(why),
        conditional: false,
        statement: STATEMENT.into(),
        premises: None,
        margins: Margins::default(),
        witness: None,
        blocks: Vec::new(),
        proof: None,
        named: Named::default(),
        exact_route: None,
    };
    if s.method == Method::Dft {
        if let Err(why) = orbits.check_free() {
            return Ok(not_proved(format!("the rotation does not act freely off the centre: {why}")));
        }
    }
    let which: Vec<usize> = match s.method {
        Method::Dft => orbits.representative.clone(),
        Method::Full => {
            if labels.len() > MAX_CERTIFIED_FULL_SIZE {
                return Ok(not_proved(format!(
                    "the configuration has no rotation symmetry and its {} points exceed the {MAX_CERTIFIED_FULL_SIZE} \
                     that the whole-matrix enclosure supports",
                    labels.len()
                )));
            }
            (0..labels.len()).collect()
        }
    };
    let rows: IntervalRows =
        match assemble_rows::<Interval>(scheme, &analysis.discovered, s.neighbourhood, &which) {
            Ok(r) => r,
            Err(AssembleError::Inexact) => {
                return Ok(not_proved(
                    "numerical only: a weight has no enclosure (a parameter or scheme-file expression known only in \
                 floating point; give it as a fraction, or as rationals and cosines of rational multiples of π)"
                        .into(),
                ))
            }
            // a weight enclosing 0 on a point outside the neighbourhood (the
            // true weight is 0 when the float path finds the set invariant, but
            // its enclosure cannot show it)
            Err(AssembleError::NotInvariant) => return Ok(not_proved(
                "the invariance of the neighbourhood is not proved: a weight on a point outside it is enclosed by an \
                 interval that holds 0 but is not 0"
                    .into(),
            )),
            Err(e) => return Err(Error::Numeric(format!("the interval rows of S could not be assembled: {e:?}"))),
        };
    // the same rows exactly, one by one (the centre's row may hold
    // cos(2π/n) while the others are rational)
    let exact: ExactRows =
        which.iter().map(|&k| exact_rows(scheme, analysis, &[k]).and_then(|mut r| r.pop())).collect();
    let row_check = row_sums(&rows, &exact, labels, &which);
    let mut mirror_axis = None;
    let (blocks, mirror, rotation, order) = match s.method {
        Method::Dft => {
            let (mirror, axis) = mirror_symmetry(&rows, &exact, &orbits, labels, n);
            mirror_axis = axis;
            let (rotation, order) = rotation_premise(scheme, analysis, &orbits, &exact)?;
            (fourier_blocks(&rows, &orbits), mirror, rotation, order)
        }
        Method::Full => (
            vec![(0, whole_matrix(&rows))],
            Check::Fails("no rotation symmetry: the subdominant pair is not split by Fourier blocks".into()),
            Check::Exact,
            field_order(None, exact.iter()),
        ),
    };
    let max_entry_width = blocks.iter().map(|(_, b)| b.max_width()).fold(0.0, f64::max);
    // S is real and the rotation acts freely off the centre, so block g − m
    // is the complex conjugate of block m (its entries are the same real
    // weights times ω^{−mτ} = conj ω^{mτ}): only blocks m ≤ g − m are
    // enclosed; the conjugate of block m's enclosure — of its verified
    // diagonalisation V, R and discs, and so of every eigenvalue it bounds —
    // encloses block g − m's (outward rounding is symmetric under negating
    // the imaginary parts, so the conjugated discs are as rigorous)
    let g = blocks.len();
    let mirrored = |m: usize| s.method == Method::Dft && m > g - m;
    let computed: Vec<BlockEnclosure> = blocks
        .par_iter()
        .filter(|(m, _)| !mirrored(*m))
        .map(|(m, b)| match enclose(b) {
            Ok(e) => BlockEnclosure {
                block: *m,
                size: b.size,
                epsilon: Some(e.epsilon),
                components: e.components,
                failure: None,
                diagonalisation: Some(e.diagonalisation),
                power_bound: None,
            },
            Err(why) => BlockEnclosure {
                block: *m,
                size: b.size,
                epsilon: None,
                components: Vec::new(),
                failure: Some(why),
                diagonalisation: None,
                power_bound: None,
            },
        })
        .collect();
    let enclosures: Vec<BlockEnclosure> =
        (0..g).map(|m| if mirrored(m) { computed[g - m].conjugate(m) } else { computed[m].clone() }).collect();
    let enclosures = with_power_bounds(enclosures, &blocks, orbits.group_order, s.method);
    if !rotation.holds() {
        return Ok(not_proved(format!("the Fourier blocks need S to commute with the rotation: {rotation:?}")));
    }
    let field = order.map(|n| if n == 1 { "Q".to_string() } else { format!("Q(ζ_{n})") });
    let premises_exact = row_check == Check::Exact && mirror == Check::Exact && rotation == Check::Exact;
    let premises = Premises {
        row_sums_one: row_check,
        mirror_symmetry: mirror,
        rotation_symmetry: rotation,
        exact: premises_exact,
        field,
        mirror_axis,
    };
    let (mut cert, lambda1_row) = decide(&enclosures, &premises, orbits.group_order, s.method);
    cert.margins.max_entry_width = max_entry_width;
    // a PROVED rests on all three premises; a DISPROVED on the rotation
    // (the blocks are S) and the row sums (which component is λ0), never on
    // the mirror (realness is only needed to prove)
    let overlap = |c: &Check| *c == Check::Overlap;
    cert.conditional = match cert.verdict {
        Verdict::Proved => !premises_exact,
        Verdict::Disproved(_) => overlap(&premises.rotation_symmetry) || overlap(&premises.row_sums_one),
        Verdict::NotProved(_) => false,
    };
    // where the enclosures cannot prove λ1 (no rotation of order ≥ 3 splits
    // its pair, or a cluster is too ill-conditioned) and S is rational,
    // lemma S7 may prove it exactly from the whole matrix
    if let Verdict::NotProved(why) = &cert.verdict {
        if let Some(e) = exact_route(scheme, analysis, &which, &exact) {
            match e {
                Ok(route) => {
                    // the exact route decides alone: no enclosure is named
                    cert.named = Named::default();
                    cert.witness = None;
                    cert.margins.power_bounded.clear();
                    cert.margins.lambda0 = Some(RealEnclosure { lo: 1.0, hi: 1.0 });
                    if let Some(r) = route.lambda1_value.as_ref().and_then(|r| r.to_f64()) {
                        // the fraction rounded to nearest f64 is within half an ulp: one ulp out bounds it
                        cert.margins.lambda1 = Some(RealEnclosure { lo: r.next_down(), hi: r.next_up() });
                    }
                    if route.proved {
                        cert.verdict = Verdict::Proved;
                        cert.statement = EXACT_STATEMENT.into();
                        if let (Some(r), Some(below)) = (&route.lambda1_value, &route.others_below_value) {
                            cert.margins.others_max_modulus = below.to_f64().map(f64::next_up);
                            cert.margins.gap_lower_bound = (r - below).to_f64().map(|g| g.next_down().max(0.0));
                        }
                    } else {
                        cert.verdict = Verdict::Disproved(route.why.clone());
                    }
                    cert.exact_route = Some(route);
                }
                Err(exact_why) => {
                    cert.verdict = Verdict::NotProved(format!("{why}; the exact route (lemma S7): {exact_why}"))
                }
            }
        }
    }
    // the exact route rests on no premise: it reads S itself
    if cert.exact_route.is_some() {
        cert.conditional = false;
    }
    cert.premises = Some(premises);
    cert.blocks = enclosures;
    cert.proof =
        Some(SpectralProof { orbits, lambda1_row: if cert.exact_route.is_some() { None } else { lambda1_row } });
    Ok(cert)
}

const EXACT_STATEMENT: &str = "for the true local subdivision matrix S on the analysis neighbourhood, every weight \
     rational: λ0 = 1 a simple root of det(xI − S); λ1 rational, positive, a root of multiplicity 2 with a \
     two-dimensional eigenspace (semisimple); every other root of modulus below λ1 (exact characteristic \
     polynomial over Q, Schur–Cohn)";

/// The whole matrix's exact rows for lemma S7, when S is small enough and
/// every weight rational: `None` when the route does not apply (too large,
/// a weight known in floating point or irrational); else its result.
fn exact_route(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    which: &[usize],
    exact: &ExactRows,
) -> Option<Result<super::exact_spectrum::ExactSpectrum, String>> {
    let s = &analysis.spectrum;
    let size = s.labels.len();
    if size > super::exact_spectrum::MAX_EXACT_ROUTE_SIZE {
        return None;
    }
    // the rows at hand are the representatives' (Fourier blocks) or all
    let all: ExactRows = if which.len() == size {
        exact.clone()
    } else {
        let all: Vec<usize> = (0..size).collect();
        match exact_rows(scheme, analysis, &all) {
            Some(rows) => rows.into_iter().map(Some).collect(),
            None => return Some(Err("the rows of S have no exact form".into())),
        }
    };
    if let Some(k) = all.iter().position(|r| r.is_none()) {
        return Some(Err(format!("row {k} of S has no exact form")));
    }
    if all.iter().flatten().any(|r| r.iter().any(|(_, w)| w.to_rational().is_none())) {
        return Some(Err("a weight is irrational (a cyclotomic element): the route needs S over Q".into()));
    }
    let reals = s.eigenvalues.iter().filter(|e| e.im.abs() <= 1e-9 * e.modulus.max(1.0)).map(|e| e.re);
    let candidates = crate::engine::exact::candidates(reals);
    Some(super::exact_spectrum::prove(&all, &candidates))
}

/// Whether lemma S6 (a spectral-radius bound without eigenvectors) may
/// stand for block `m`'s discs: the proof only bounds its eigenvalues from
/// above. Block 0 holds λ0 = 1 and blocks 1, g − 1 hold λ1, so their spectral
/// radius is λ0 or λ1 itself and a bound of it separates nothing; their
/// clusters stay with the discs (NOT PROVED when those cannot separate them).
fn s6_applies(m: usize, g: usize, method: Method) -> bool {
    method == Method::Dft && g >= 3 && m != 0 && m != 1 && m != g - 1
}

/// Lemma S6 for every block it applies to whose discs failed or reach the
/// guide λ1 ≥ `target` (the lower modulus bound of block 1's leading
/// component, a floating-point number that only chooses which blocks to try
/// and when to stop squaring: `decide` compares the rigorous bounds).
fn with_power_bounds(
    mut enclosures: Vec<BlockEnclosure>,
    blocks: &[(usize, super::complex::CIntervalMatrix)],
    g: usize,
    method: Method,
) -> Vec<BlockEnclosure> {
    if method != Method::Dft || g < 3 {
        return enclosures;
    }
    let target = match enclosures.get(1).and_then(|b| b.components.first()) {
        Some(c) => c.min_modulus(),
        None => return enclosures,
    };
    // NaN included: no guide, no attempt
    if target.is_nan() || target <= 0.0 {
        return enclosures;
    }
    let needed: Vec<usize> = enclosures
        .iter()
        .enumerate()
        .filter(|(_, b)| {
            s6_applies(b.block, g, method)
                && (b.failure.is_some() || b.components.iter().any(|c| c.max_modulus() >= target))
        })
        .map(|(i, _)| i)
        .collect();
    let bounds: Vec<(usize, Option<PowerBound>)> =
        needed.par_iter().map(|&i| (i, power_bound(&blocks[i].1, target))).collect();
    for (i, b) in bounds {
        enclosures[i].power_bound = b;
    }
    enclosures
}

/// Rows `which` of S exactly: in Q when every weight is rational, else in a
/// cyclotomic field Q(ζ_N) (weights holding cos(2πk/n)); `None` when a weight
/// is known in floating point only or is undefined (a quotient by zero, a
/// field beyond `cyclotomic::MAX_ORDER`), or the rows cannot be assembled.
/// Rational rows are assembled as rationals first: cheaper, and the rows of
/// most points are rational even where the centre's are not.
pub(super) fn exact_rows(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    which: &[usize],
) -> Option<Vec<Vec<(usize, Cyclotomic)>>> {
    let (d, kind) = (&analysis.discovered, analysis.spectrum.neighbourhood);
    match assemble_rows_rational(scheme, d, kind, which) {
        Ok(rows) => {
            return Some(
                rows.into_iter()
                    .map(|r| r.into_iter().map(|(c, w)| (c, Cyclotomic::from_rational(&w))).collect())
                    .collect(),
            )
        }
        Err(AssembleError::Inexact) => {}
        Err(_) => return None,
    }
    let rows = assemble_rows::<Cyclotomic>(scheme, d, kind, which).ok()?;
    rows.iter().all(|r| r.iter().all(|(_, w)| w.is_defined())).then_some(rows)
}

/// N of the smallest cyclotomic field Q(ζ_N) holding every entry of the
/// exact rows (1: all rational), with `order` the N of rows seen before;
/// `None` when no row is exact.
fn field_order<'a>(
    order: Option<u64>,
    rows: impl Iterator<Item = &'a Option<Vec<(usize, Cyclotomic)>>>,
) -> Option<u64> {
    let mut order = order;
    for row in rows.flatten() {
        let mut l = order.unwrap_or(1);
        for (_, w) in row {
            let n = w.order().unwrap_or(1) as u64;
            l = l / crate::numeric::weight::gcd(l as i64, n as i64) as u64 * n;
        }
        order = Some(l);
    }
    order
}

pub use super::matrix::MAX_EXACT_ORBIT_WORK;

/// Rows of an orbit assembled exactly at a time (the rows are compared and
/// dropped: memory stays bounded however large the orbit).
const EXACT_CHUNK: usize = 64;

/// PS = SP on every row: the interval rows of all points, and their exact
/// rows where they are exact: all off-centre rows in one rational assembly
/// when they are rational, else orbit by orbit, rational or cyclotomic (in
/// chunks, within [`MAX_EXACT_ORBIT_WORK`]); each row is compared with the
/// representative's (`exact_reps`, in orbit order) rotated. Also returns N of
/// the field of the exact rows compared (`None`: none was exact).
fn rotation_premise(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    orbits: &Orbits,
    exact_reps: &ExactRows,
) -> Result<(Check, Option<u64>), Error> {
    // the cheap route first: the refinement steps' stencils turn with the
    // mesh (exactly), so their composition S does (see `step_rotation`)
    if let Some(steps_order) = super::step_rotation::rotation_by_steps(scheme, analysis, orbits) {
        let reps = field_order(None, exact_reps.iter()).unwrap_or(1);
        return Ok((Check::Exact, Some(super::step_rotation::lcm(reps, steps_order))));
    }
    let s = &analysis.spectrum;
    let labels = &s.labels;
    let everyone: Vec<usize> = (0..labels.len()).collect();
    let all = match assemble_rows::<Interval>(scheme, &analysis.discovered, s.neighbourhood, &everyone) {
        Ok(rows) => rows,
        Err(AssembleError::NotInvariant) => {
            return Ok((
                Check::Fails("a row's enclosure reaches outside the neighbourhood (a weight enclosing 0)".into()),
                None,
            ))
        }
        Err(e) => return Err(Error::Numeric(format!("the interval rows of S could not be assembled: {e:?}"))),
    };
    // the representatives' exact rows stay at hand: every row is compared with one
    let mut exact: ExactRows = vec![None; everyone.len()];
    for (o, &r) in orbits.representative.iter().enumerate() {
        exact[r] = exact_reps[o].clone();
    }
    let mut order = field_order(None, exact_reps.iter());
    let is_rep = |k: usize| orbits.representative[orbits.member[k].0] == k;
    let (fixed, moving): (Vec<usize>, Vec<usize>) = everyone.iter().partition(|&&k| orbits.fixed[orbits.member[k].0]);
    let mut check = rotation_symmetry(&all, &exact, &fixed, orbits, labels);
    // the common case: every row off the centre rational, in one assembly
    let others: Vec<usize> = moving.iter().copied().filter(|&k| !is_rep(k)).collect();
    if let Ok(rows) = assemble_rows_rational(scheme, &analysis.discovered, s.neighbourhood, &others) {
        for (k, row) in others.iter().zip(rows) {
            exact[*k] = Some(row.into_iter().map(|(c, w)| (c, Cyclotomic::from_rational(&w))).collect());
        }
        order = field_order(order, others.iter().map(|&k| &exact[k]));
        return Ok((check.and(rotation_symmetry(&all, &exact, &moving, orbits, labels)), order));
    }
    for o in (0..orbits.num_orbits()).filter(|&o| !orbits.fixed[o]) {
        if !check.holds() {
            break;
        }
        let rep = orbits.representative[o];
        let members: Vec<usize> = others.iter().copied().filter(|&k| orbits.member[k].0 == o).collect();
        check = check.and(rotation_symmetry(&all, &exact, &[rep], orbits, labels));
        let rational = assemble_rows_rational(scheme, &analysis.discovered, s.neighbourhood, &members);
        let chunks: Vec<&[usize]> = match (&rational, &exact_reps[o]) {
            (Ok(_), _) => vec![&members[..]],
            // nothing to compare exactly with, or too much work: on the enclosures
            (Err(_), None) => Vec::new(),
            (Err(_), Some(row)) => {
                let n = row.iter().map(|(_, w)| w.order().unwrap_or(1) as u64).max().unwrap_or(1);
                let work = (members.len() as u64).saturating_mul(row.len() as u64).saturating_mul(n);
                if work <= MAX_EXACT_ORBIT_WORK {
                    members.chunks(EXACT_CHUNK).collect()
                } else {
                    Vec::new()
                }
            }
        };
        if chunks.is_empty() {
            check = check.and(rotation_symmetry(&all, &exact, &members, orbits, labels));
            continue;
        }
        let mut rational = rational.ok();
        for chunk in chunks {
            let rows = match rational.take() {
                Some(rows) => Some(
                    rows.into_iter()
                        .map(|r| r.into_iter().map(|(c, w)| (c, Cyclotomic::from_rational(&w))).collect())
                        .collect(),
                ),
                None => exact_rows(scheme, analysis, chunk),
            };
            for (k, row) in chunk.iter().zip(rows.into_iter().flatten()) {
                exact[*k] = Some(row);
            }
            order = field_order(order, chunk.iter().map(|&k| &exact[k]));
            check = check.and(rotation_symmetry(&all, &exact, chunk, orbits, labels));
            chunk.iter().for_each(|&k| exact[k] = None);
            if !check.holds() {
                break;
            }
        }
    }
    Ok((check, order))
}

/// The verdict from the block enclosures and the premises, and when PROVED
/// the row of λ1's disc in block 1's diagonalisation.
fn decide(
    blocks: &[BlockEnclosure],
    premises: &Premises,
    g: usize,
    method: Method,
) -> (SpectrumCertificate, Option<usize>) {
    let mut margins = Margins {
        max_radius: blocks.iter().flat_map(|b| &b.components).map(Component::max_radius).fold(0.0, f64::max),
        ..Margins::default()
    };
    // set as the proof names them: every verdict's document says which
    // components it rested on so far
    let lambda0 = Cell::new(None);
    let lambda1 = Cell::new(None);
    let finish = |verdict: Verdict, margins: Margins, witness: Option<Witness>| {
        let cert = SpectrumCertificate {
            verdict,
            conditional: false,
            statement: STATEMENT.into(),
            premises: None,
            margins,
            witness,
            blocks: Vec::new(),
            proof: None,
            named: Named { lambda0: lambda0.get(), lambda1: lambda1.get() },
            exact_route: None,
        };
        (cert, None)
    };
    let index = |m: usize, c: &Component| blocks[m].components.iter().position(|o| std::ptr::eq(o, c)).unwrap_or(0);
    let witness = |m: usize, c: &Component| Witness { block: m, component: c.clone(), index: index(m, c) };
    let all: Vec<(usize, &Component)> =
        blocks.iter().flat_map(|b| b.components.iter().map(move |c| (b.block, c))).collect();
    // an eigenvalue outside the unit disc disproves convergence, whatever else
    if let Some((m, c)) = all.iter().find(|(_, c)| c.min_modulus() > 1.0) {
        return finish(
            Verdict::Disproved(format!("block {m} has an eigenvalue of modulus ≥ {:.6} > 1", c.min_modulus())),
            margins,
            Some(witness(*m, c)),
        );
    }
    // a block without discs is left to lemma S6 when that applies and was
    // computed (its eigenvalues are then bounded at the gap, below)
    if let Some(b) =
        blocks.iter().find(|b| b.failure.is_some() && !(b.power_bound.is_some() && s6_applies(b.block, g, method)))
    {
        return finish(
            Verdict::NotProved(format!("block {}: {}", b.block, b.failure.as_deref().unwrap_or_default())),
            margins,
            None,
        );
    }
    if !premises.row_sums_one.holds() {
        return finish(
            Verdict::NotProved(format!("1 is not known to be an eigenvalue: {:?}", premises.row_sums_one)),
            margins,
            None,
        );
    }
    // (a) λ0: the one component of block 0 that may hold 1
    let block0 = &blocks[0].components;
    let holding_one: Vec<&Component> = block0.iter().filter(|c| c.may_hold(c64::new(1.0, 0.0))).collect();
    let [c0] = holding_one.as_slice() else {
        return finish(Verdict::NotProved("no single component of block 0 holds 1".into()), margins, None);
    };
    lambda0.set(Some(index(0, c0)));
    let (lo0, hi0) = c0.real_range();
    margins.lambda0 = Some(RealEnclosure { lo: lo0, hi: hi0 });
    if c0.count != 1 {
        return finish(
            Verdict::NotProved(format!(
                "the enclosure of λ0 = 1 holds {} eigenvalues of block 0: simplicity is not separated",
                c0.count
            )),
            margins,
            None,
        );
    }
    if method == Method::Full || g < 3 {
        let why = if method == Method::Full {
            "no rotation symmetry: λ1 is a double eigenvalue of one matrix, whose realness and semisimplicity \
             enclosures cannot prove"
        } else {
            "the rotation group has fewer than 3 elements: blocks 1 and g − 1 coincide"
        };
        return finish(Verdict::NotProved(why.into()), margins, None);
    }
    // (b) λ1: the leading component of block 1 and of block g − 1
    let lead = |m: usize| blocks[m].components.first();
    let (Some(c1), Some(c1c)) = (lead(1), lead(g - 1)) else {
        return finish(Verdict::NotProved("block 1 is empty".into()), margins, None);
    };
    let block1_max = c1.max_modulus().max(c1c.max_modulus());
    let is_lambda1 = |m: usize, c: &Component| (m == 1 && std::ptr::eq(c, c1)) || (m == g - 1 && std::ptr::eq(c, c1c));
    let is_lambda0 = |m: usize, c: &Component| m == 0 && std::ptr::eq(c, *c0);
    // a component elsewhere proven larger than anything in block 1: the
    // subdominant eigenvalues are not the pair from blocks 1 and g − 1
    let others: Vec<(usize, &Component)> =
        all.iter().copied().filter(|(m, c)| !is_lambda0(*m, c) && !is_lambda1(*m, c)).collect();
    if let Some((m, c)) = others
        .iter()
        .filter(|(m, _)| *m != 1 && *m != g - 1)
        .max_by(|a, b| a.1.min_modulus().total_cmp(&b.1.min_modulus()))
    {
        if c.min_modulus() > block1_max {
            return finish(
                Verdict::Disproved(format!(
                    "block {m} has {} eigenvalue(s) of modulus ≥ {:.9}, above every eigenvalue of block 1 (≤ {:.9}): \
                     the subdominant eigenvalue is not the pair from blocks 1 and {}",
                    c.count,
                    c.min_modulus(),
                    block1_max,
                    g - 1
                )),
                margins,
                Some(witness(*m, c)),
            );
        }
    }
    // Lemma (no candidate). λ1 must be a positive real eigenvalue of block 1
    // of modulus above every eigenvalue other than λ0 and its conjugate
    // partner in block g − 1. If every component of block 1 that may hold a
    // positive real number is outdone — some other component (of block 1,
    // or of a block other than 1 and g − 1, λ0's excepted) has a modulus
    // proved at least its largest — no eigenvalue can be that λ1. This is
    // the only way a leading component that is negative, complex, or tied
    // disproves the statement: the leading component by the sort may not be
    // the largest eigenvalue when moduli overlap, so its sign alone decides
    // nothing.
    let competitors = |c: &Component| {
        others
            .iter()
            .filter(|(m, o)| *m != g - 1 && !(*m == 1 && std::ptr::eq(*o, c)))
            .chain(std::iter::once(&(1usize, c1)).filter(|(_, o)| !std::ptr::eq(*o, c)))
            .copied()
            .max_by(|a, b| a.1.min_modulus().total_cmp(&b.1.min_modulus()))
    };
    let candidates: Vec<&Component> =
        blocks[1].components.iter().filter(|c| c.meets_real_axis() && c.real_range().1 > 0.0).collect();
    let outdone = |c: &Component| competitors(c).filter(|(_, o)| o.min_modulus() >= c.max_modulus());
    if candidates.iter().all(|c| outdone(c).is_some()) {
        // the component that outdoes the largest candidate, or (no
        // candidate) block 1's leading component
        let witnessed = match candidates.first() {
            Some(c) => outdone(c),
            None => Some((1, c1)),
        };
        let why = match candidates.first() {
            None => {
                "block 1 has no eigenvalue that may be positive and real (no enclosure meets the positive real axis)"
                    .to_string()
            }
            Some(c) => {
                let (m, o) = outdone(c).expect("every candidate is outdone");
                // name what block 1's leading eigenvalue is, when it is the
                // one that outdoes the candidates
                let leading = if m == 1 && std::ptr::eq(o, c1) && !c1.meets_real_axis() {
                    format!(
                        "the subdominant eigenvalue of block 1 is not real (its disc about {:.9}{:+.9}i of radius \
                         {:.2e} misses the real axis); ",
                        c1.discs[0].re, c1.discs[0].im, c1.discs[0].radius
                    )
                } else if m == 1 && std::ptr::eq(o, c1) && c1.real_range().1 < 0.0 {
                    format!("the subdominant eigenvalue of block 1 is negative (≤ {:.9}); ", c1.real_range().1)
                } else {
                    String::new()
                };
                format!(
                    "{leading}no eigenvalue of block 1 can be a dominant positive λ1: the largest candidate (modulus ≤ {:.9}) is \
                     matched or exceeded by an eigenvalue of block {m} (modulus ≥ {:.9}){}",
                    c.max_modulus(),
                    o.min_modulus(),
                    if candidates.len() > 1 { format!(", and so are the other {}", candidates.len() - 1) } else { String::new() }
                )
            }
        };
        return finish(Verdict::Disproved(why), margins, witnessed.map(|(m, c)| witness(m, c)));
    }
    if c1.count != 1 || c1c.count != 1 {
        return finish(
            Verdict::NotProved(format!(
                "the leading enclosure of block 1 holds {} eigenvalues (block {}: {}): they are not separated",
                c1.count,
                g - 1,
                c1c.count
            )),
            margins,
            None,
        );
    }
    lambda1.set(Some([index(1, c1), index(g - 1, c1c)]));
    let lambda1_mod = (c1.min_modulus(), c1.max_modulus());
    margins.lambda_radius = Some(c0.max_radius().max(c1.max_radius()).max(c1c.max_radius()));
    // (c) every other eigenvalue below λ1 in modulus: per block, the largest
    // modulus of its discs (λ0's and λ1's excepted), or lemma S6's bound of
    // its spectral radius where that applies and is smaller (a block whose
    // discs failed has only the latter)
    let block_bound = |b: &BlockEnclosure| {
        let discs = if b.failure.is_some() {
            f64::INFINITY
        } else {
            others.iter().filter(|(m, _)| *m == b.block).map(|(_, c)| c.max_modulus()).fold(0.0, f64::max)
        };
        match b.power_bound {
            Some(p) if s6_applies(b.block, g, method) && p.radius < discs => (p.radius, Some(p)),
            _ => (discs, None),
        }
    };
    let bounds: Vec<(usize, f64, Option<PowerBound>)> = blocks
        .iter()
        .map(|b| {
            let (r, p) = block_bound(b);
            (b.block, r, p)
        })
        .collect();
    let rest = bounds.iter().map(|&(_, r, _)| r).fold(0.0, f64::max);
    margins.others_max_modulus = Some(rest);
    margins.lambda1_lower = Some(lambda1_mod.0);
    margins.power_bounded = bounds.iter().filter(|(_, _, p)| p.is_some()).map(|&(m, _, _)| m).collect();
    let gap = (Interval::point(lambda1_mod.0) - Interval::point(rest)).lo;
    margins.gap_lower_bound = Some(gap);
    // realness: a simple eigenvalue of a conjugation-closed block spectrum
    // whose component's mirror image meets no other component is real
    let self_conjugate = |m: usize, c: &Component| {
        let mirror = Component {
            discs: c.discs.iter().map(|d| Disc { im: -d.im, ..*d }).collect(),
            count: c.count,
            rows: c.rows.clone(),
        };
        c.meets_real_axis() && blocks[m].components.iter().filter(|o| !std::ptr::eq(*o, c)).all(|o| o.disjoint(&mirror))
    };
    // λ1 is real (proved below) and lies in the component, so in its real
    // range; its modulus bounds tighten that range only once the sign is
    // known from the real range itself (a disc far off the axis can have a
    // modulus bounded away from 0 while its real segment is negative)
    let (lo1, hi1) = c1.real_range();
    let real_enclosure = if lo1 > 0.0 {
        RealEnclosure { lo: lo1.max(lambda1_mod.0), hi: hi1.min(lambda1_mod.1) }
    } else if hi1 < 0.0 {
        RealEnclosure { lo: lo1.max(-lambda1_mod.1), hi: hi1.min(-lambda1_mod.0) }
    } else {
        RealEnclosure { lo: lo1, hi: hi1 }
    };
    // a leading component that is not real or negative and separated from
    // the rest was disproved above (no candidate); here it is not separated
    if !c1.meets_real_axis() {
        return finish(
            Verdict::NotProved(
                "the leading eigenvalue of block 1 is not real, and not separated from the others".into(),
            ),
            margins,
            Some(witness(1, c1)),
        );
    }
    if !premises.mirror_symmetry.holds() {
        return finish(
            Verdict::NotProved(format!(
                "realness of λ1 is an equality that needs the mirror symmetry of S: {:?}",
                premises.mirror_symmetry
            )),
            margins,
            None,
        );
    }
    if !self_conjugate(1, c1) {
        return finish(
            Verdict::NotProved("the mirror image of λ1's enclosure meets another enclosure of block 1".into()),
            margins,
            None,
        );
    }
    margins.lambda1 = Some(real_enclosure);
    if real_enclosure.hi < 0.0 {
        return finish(
            Verdict::NotProved(
                "the leading enclosure of block 1 is negative, but not separated from the others: it may not be λ1"
                    .into(),
            ),
            margins,
            None,
        );
    }
    if real_enclosure.lo <= 0.0 {
        return finish(Verdict::NotProved("λ1's enclosure holds 0: its sign is not decided".into()), margins, None);
    }
    // not below (NaN included)
    if real_enclosure.hi.partial_cmp(&lo0) != Some(std::cmp::Ordering::Less) {
        return finish(Verdict::NotProved("λ1 is not separated from λ0 = 1".into()), margins, None);
    }
    if gap <= 0.0 {
        // the block whose bound reaches λ1; when lemma S6 bounds it, say so
        let (bm, _, power) = bounds.iter().max_by(|a, b| a.1.total_cmp(&b.1)).copied().expect("g ≥ 3 blocks");
        if let Some(p) = power.or(blocks[bm].power_bound.filter(|_| blocks[bm].failure.is_some())) {
            return finish(
                Verdict::NotProved(format!(
                    "block {bm}: {}, and lemma S6 bounds its spectral radius only by ‖B^{}‖∞^(1/{}) ≤ {:.9}, not \
                     below λ1 ≥ {:.9} (squared up to k = {}): its eigenvalues may reach λ1",
                    blocks[bm].failure.as_deref().unwrap_or("its eigenvalue enclosures reach λ1"),
                    p.k,
                    p.k,
                    p.radius,
                    lambda1_mod.0,
                    1u64 << super::power::MAX_SQUARINGS
                )),
                margins,
                None,
            );
        }
        // name the enclosure that reaches λ1: the largest of block bm, whose
        // bound came from its discs (a wider one in a block that S6 bounded
        // is not the obstacle)
        let largest = |of: &dyn Fn(usize) -> bool| {
            others
                .iter()
                .filter(|(m, _)| of(*m))
                .max_by(|a, b| a.1.max_modulus().total_cmp(&b.1.max_modulus()))
                .copied()
        };
        let Some((m, c)) = largest(&|m| m == bm).or_else(|| largest(&|_| true)) else {
            return finish(
                Verdict::NotProved(format!("the gap below λ1 ≥ {:.9} is not shown", lambda1_mod.0)),
                margins,
                None,
            );
        };
        let held = if m == 0 {
            " (block 0 holds λ0 = 1, so lemma S6, a bound of the block's spectral radius, cannot separate it)"
        } else if m == 1 || m == g - 1 {
            " (the block holds λ1, so lemma S6, a bound of the block's spectral radius, cannot separate it)"
        } else {
            ""
        };
        return finish(
            Verdict::NotProved(
                format!(
                "an eigenvalue enclosure of block {m} ({} eigenvalue(s), modulus in [{:.9}, {:.9}], disc radius up to \
                 {:.3e}) reaches λ1 ≥ {:.9}: the enclosures cannot separate them ({})",
                c.count,
                c.min_modulus(),
                c.max_modulus(),
                c.max_radius(),
                lambda1_mod.0,
                if c.max_radius() < 1e-6 {
                    "equal or nearly equal moduli"
                } else {
                    "the enclosure is wide: defective or ill-conditioned eigenvalues in that block"
                },
            ) + held,
            ),
            margins,
            Some(witness(m, c)),
        );
    }
    // the proof hands on which disc holds λ1: the component was chosen by
    // its enclosure, and holds one disc (count 1)
    (finish(Verdict::Proved, margins, None).0, c1.rows.first().copied())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(m: usize, discs: &[(f64, f64, f64)]) -> BlockEnclosure {
        let components = discs
            .iter()
            .enumerate()
            .map(|(i, &(re, im, radius))| Component { discs: vec![Disc { re, im, radius }], count: 1, rows: vec![i] })
            .collect();
        BlockEnclosure {
            block: m,
            size: discs.len(),
            epsilon: Some(0.0),
            components,
            failure: None,
            diagonalisation: None,
            power_bound: None,
        }
    }

    fn exact_premises() -> Premises {
        Premises {
            row_sums_one: Check::Exact,
            mirror_symmetry: Check::Exact,
            rotation_symmetry: Check::Exact,
            exact: true,
            field: Some("Q".into()),
            mirror_axis: Some(2),
        }
    }

    #[test]
    fn the_sign_of_lambda1_comes_from_its_real_range_not_its_modulus() {
        // block 1's only disc, about −0.3 + 0.25i of radius 0.32, meets the
        // real axis only in [−0.4985, −0.1015] (negative), while its modulus
        // is bounded below by 0.39 − 0.32 = 0.07 > 0: a sign taken from the
        // modulus would "prove" a positive λ1
        let blocks =
            [block(0, &[(1.0, 0.0, 1e-12)]), block(1, &[(-0.3, 0.25, 0.32)]), block(2, &[(-0.3, -0.25, 0.32)])];
        let (cert, row) = decide(&blocks, &exact_premises(), 3, Method::Dft);
        assert!(matches!(&cert.verdict, Verdict::NotProved(w) if w.contains("sign")), "{:?}", cert.verdict);
        assert_eq!(row, None);
        // the same disc moved right, about +0.5 + 0.1i of radius 0.2: real
        // range [0.3, 0.7], positive: proved, and the disc is named
        let blocks = [
            block(0, &[(1.0, 0.0, 1e-12)]),
            block(1, &[(0.5, 0.1, 0.2), (0.1, 0.0, 0.01)]),
            block(2, &[(0.5, -0.1, 0.2), (0.1, 0.0, 0.01)]),
        ];
        let (cert, row) = decide(&blocks, &exact_premises(), 3, Method::Dft);
        assert_eq!(cert.verdict, Verdict::Proved);
        assert_eq!(row, Some(0));
        let l1 = cert.margins.lambda1.unwrap();
        assert!(l1.lo > 0.0 && l1.lo <= 0.5 && 0.5 <= l1.hi);
    }

    #[test]
    fn lemma_s6_stands_for_failed_blocks_other_than_0_1_and_g_minus_1() {
        // g = 5, λ1 = 1/2 ± 1e-12 in blocks 1 and 4; block 2's discs failed
        let failed = |m: usize, power: Option<PowerBound>| BlockEnclosure {
            block: m,
            size: 3,
            epsilon: None,
            components: Vec::new(),
            failure: Some("ill-conditioned".into()),
            diagonalisation: None,
            power_bound: power,
        };
        let blocks = |b2: BlockEnclosure| {
            vec![
                block(0, &[(1.0, 0.0, 1e-12), (0.25, 0.0, 1e-3)]),
                block(1, &[(0.5, 0.0, 1e-12), (0.25, 0.0, 1e-3)]),
                b2,
                block(3, &[(0.1, 0.0, 1e-3)]),
                block(4, &[(0.5, 0.0, 1e-12), (0.25, 0.0, 1e-3)]),
            ]
        };
        // no bound: NOT PROVED naming the block
        let (cert, _) = decide(&blocks(failed(2, None)), &exact_premises(), 5, Method::Dft);
        assert!(matches!(&cert.verdict, Verdict::NotProved(w) if w.contains("block 2")), "{:?}", cert.verdict);
        // ρ(B_2) ≤ 0.4653 (polar bi-2's ‖B^4‖∞ = 3/64): PROVED, the gap from it
        let bound = PowerBound { k: 4, norm: 3.0 / 64.0, radius: 0.4653024295510502 };
        let (cert, _) = decide(&blocks(failed(2, Some(bound))), &exact_premises(), 5, Method::Dft);
        assert_eq!(cert.verdict, Verdict::Proved);
        assert_eq!(cert.margins.power_bounded, vec![2]);
        assert_eq!(cert.margins.others_max_modulus, Some(bound.radius));
        // a bound that does not clear λ1 (ρ may equal it): NOT PROVED, naming S6
        let weak = PowerBound { k: 512, norm: 1e-150, radius: 0.5000001 };
        let (cert, _) = decide(&blocks(failed(2, Some(weak))), &exact_premises(), 5, Method::Dft);
        assert!(matches!(&cert.verdict, Verdict::NotProved(w) if w.contains("lemma S6")), "{:?}", cert.verdict);
        // λ1's own block never takes S6: block 1 without discs stays NOT PROVED
        let mut b = blocks(block(2, &[(0.1, 0.0, 1e-3)]));
        b[1] = failed(1, Some(bound));
        let (cert, _) = decide(&b, &exact_premises(), 5, Method::Dft);
        assert!(matches!(&cert.verdict, Verdict::NotProved(w) if w.starts_with("block 1")), "{:?}", cert.verdict);
    }

    #[test]
    fn a_negative_leading_disc_disproves_only_when_it_outdoes_every_candidate() {
        // block 1 leads with −0.6 ± 0.001; a positive 0.5995 ± 0.001 in block
        // 1 cannot be separated from it in modulus: NOT PROVED, never
        // DISPROVED on the leading disc's sign alone
        let blocks = [
            block(0, &[(1.0, 0.0, 1e-12)]),
            block(1, &[(-0.6, 0.0, 1e-3), (0.5995, 0.0, 1e-3)]),
            block(2, &[(-0.6, 0.0, 1e-3), (0.5995, 0.0, 1e-3)]),
        ];
        let (cert, _) = decide(&blocks, &exact_premises(), 3, Method::Dft);
        assert!(matches!(cert.verdict, Verdict::NotProved(_)), "{:?}", cert.verdict);
        // separated (0.4 ± 0.001): every candidate is outdone, DISPROVED
        let blocks = [
            block(0, &[(1.0, 0.0, 1e-12)]),
            block(1, &[(-0.6, 0.0, 1e-3), (0.4, 0.0, 1e-3)]),
            block(2, &[(-0.6, 0.0, 1e-3), (0.4, 0.0, 1e-3)]),
        ];
        let (cert, _) = decide(&blocks, &exact_premises(), 3, Method::Dft);
        assert!(matches!(&cert.verdict, Verdict::Disproved(w) if w.contains("negative")), "{:?}", cert.verdict);
    }
}
