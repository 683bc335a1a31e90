//! The exact parameter sweep (`subdlab sweep --exact`): for one free
//! parameter t and each valence n, the set of t where the scheme converges
//! (λ0 = 1 simple and strictly dominant) and where it is spectrally C¹ (λ1
//! real, positive, double from Fourier blocks 1 and n − 1, strictly
//! dominant over the rest), as unions of intervals whose endpoints are exact
//! real algebraic numbers. ARCHITECTURE.md ("The exact sweep") gives the
//! method; in short:
//!
//! 1. the rows of S(t) exactly, as polynomials in t over Q(ζ_N) (the rules
//!    in the weight type `numeric::TPoly`), re-checked against the ordinary
//!    exact rows at two rational points;
//! 2. the Fourier blocks B_m(t) and their characteristic polynomials
//!    P_m(x, t) (Berkowitz, division-free, over Q(ζ_N)[t]);
//! 3. the candidate endpoints: where two root branches of one block meet
//!    (P_m, ∂P_m/∂x), where a branch of P_a meets one of P_b (P_a(x),
//!    P_b(x)), or its negative (P_a(x), P_b(−x)): for each pair, the first
//!    principal subresultant coefficient that is not identically zero in t
//!    (its vanishing is exactly a change of the gcd's degree), computed by
//!    evaluation at integer points and interpolation (its degree in t is
//!    bounded by isobaric weight), taken to Q[t] by the product of its
//!    Galois conjugates, made square-free, and its real roots in the swept
//!    range isolated by Sturm sequences; coinciding roots merged exactly;
//! 4. every open piece between candidates decided at one rational interior
//!    point (certified spectrum where it decides, else floating point), and
//!    each candidate itself: both conditions are open in t, so a candidate
//!    next to a failing piece fails; between two passing pieces it is
//!    decided at the point (exactly there when it is rational).
//!
//! The candidates are complete (no order change of moduli is missed) when
//! every block polynomial has real coefficients and every root is real at
//! each piece's point: real roots change modulus order only by meeting
//! each other or each other's negatives. Moduli of complex pairs are not
//! followed: where a piece has a non-real eigenvalue, the output says its
//! intervals are not proved exact.

pub mod curvature;
pub(crate) mod modulus;
pub(crate) mod subresultant;

use num_traits::{One, Signed, ToPrimitive, Zero};
use serde::Serialize;

use crate::certify::spectrum::analysis_orbits;
use crate::certify::{certify_analysis, Verdict as CertVerdict};
use crate::curvature::CurvatureClass;
use crate::dft::Orbits;
use crate::error::Error;
use crate::matrix::assemble_rows;
use crate::neighbourhood::{Configuration, NeighbourhoodKind};
use crate::numeric::berkowitz::charpoly;
use crate::numeric::exact::Poly;
use crate::numeric::sturm::{self, RealRoot};
use crate::numeric::tpoly::{take_non_polynomial, SymbolGuard};
use crate::numeric::{Cyclotomic, Rational, TPoly, Weight};
use crate::schemes;
use crate::spectrum::{analyse, Options};

/// Most evaluation points of one subresultant (a bound on work).
pub const MAX_POINTS: usize = 2000;

/// What the exact sweep is asked.
#[derive(Clone, Debug)]
pub struct ExactSweep {
    pub scheme: String,
    pub valences: Vec<usize>,
    pub param: String,
    pub lo: Rational,
    pub hi: Rational,
    pub fixed: Vec<(String, String)>,
    /// a face sequence around the centre (schemes of mixed meshes, e.g.
    /// four-three's `QQTQT`); its length is the one valence swept
    pub faces: Option<String>,
    /// decide the pieces with the interval certificate too (else the
    /// floating-point spectrum alone: the certificate costs seconds per
    /// point at higher valences)
    pub certify: bool,
    /// also the sets of each curvature class (`sweep --exact --curvature`,
    /// [`curvature`]): more candidates (where |μ| = λ1² can happen) and the
    /// second-order analysis at every decided point
    pub curvature: bool,
}

/// A real algebraic endpoint, exactly and as a decimal.
#[derive(Clone, Debug, Serialize)]
pub struct Endpoint {
    /// the endpoint when it is rational ("p/q")
    pub rational: Option<String>,
    /// otherwise: the one root of this square-free integer polynomial
    /// (coefficients from the constant term up) in `isolating_interval`
    pub polynomial: Option<Vec<String>>,
    /// open interval (lo, hi) of rationals holding exactly one root
    pub isolating_interval: Option<[String; 2]>,
    pub decimal: f64,
    /// the polynomial as text, "16 t^2 - 8 t - 1"
    pub text: String,
}

/// One interval of a condition's set.
#[derive(Clone, Debug, Serialize)]
pub struct ExactInterval {
    pub from: Endpoint,
    pub to: Endpoint,
    pub from_closed: bool,
    pub to_closed: bool,
    /// how the condition was decided inside: "certified" (interval
    /// certificate), "floating point", or "exact" where every piece is
    pub evidence: String,
    /// the endpoints are proved to be where the condition changes (the
    /// candidate set is complete for this interval's pieces)
    pub endpoints_exact: bool,
    /// the ends as exact real algebraic numbers, for exact comparison
    /// (claims of kind `parameter-range`)
    #[serde(skip)]
    pub from_root: RealRoot,
    #[serde(skip)]
    pub to_root: RealRoot,
}

/// The sets of the swept parameter per curvature class.
#[derive(Clone, Debug, Serialize)]
pub struct CurvatureSets {
    pub zero: Vec<ExactInterval>,
    pub bounded: Vec<ExactInterval>,
    pub unbounded: Vec<ExactInterval>,
    /// the candidates where |x| = y² for a root x of a block and a root y
    /// of λ1's block (|μ| = λ1² can only happen at these, or on whole pieces)
    pub square_candidates: Vec<Endpoint>,
    /// candidate points whose class could not be decided (in no set)
    pub undecided: Vec<String>,
    /// the classes' candidate set is proved complete (the first-order one
    /// is, and |μ| = λ1² is followed for real and non-real μ)
    pub exact: bool,
    /// why the curvature sets are not proved exact beyond the first-order
    /// reasons (`not_exact_because` of the valence), when they are not
    pub not_exact_because: Vec<String>,
}

/// The exact sets at one valence.
#[derive(Clone, Debug, Serialize)]
pub struct ValenceSets {
    pub valence: usize,
    /// N of the cyclotomic field Q(ζ_N) of the block polynomials
    pub field_order: u64,
    /// distinct characteristic polynomials of the Fourier blocks, with their
    /// degrees in x and in t
    pub block_polynomials: Vec<[usize; 2]>,
    /// every candidate endpoint inside the swept range
    pub candidates: Vec<Endpoint>,
    pub convergent: Vec<ExactInterval>,
    pub c1_spectral: Vec<ExactInterval>,
    /// whether the candidate set is proved complete over the whole range
    pub exact: bool,
    /// why not, when not
    pub not_exact_because: Vec<String>,
    /// the pieces and candidate points decided, with what evidence
    pub decisions: Vec<Decision>,
    /// the sets of each curvature class (with `curvature` asked)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curvature: Option<CurvatureSets>,
}

/// The verdict at one point of t.
#[derive(Clone, Debug, Serialize)]
pub struct Decision {
    /// the point ("p/q"), or "≈ decimal" near an irrational candidate
    pub at: String,
    /// "piece" (interior point), "candidate", or "range end"
    pub kind: &'static str,
    pub convergent: bool,
    pub c1_spectral: bool,
    pub evidence: String,
    /// every eigenvalue real here (None: not checked, at a candidate)
    pub all_real: Option<bool>,
    /// the rational point decided (None: a rational near an irrational
    /// candidate, or a candidate decided from its neighbours)
    #[serde(skip)]
    pub point: Option<Rational>,
    /// the curvature class here (with `--curvature`; None: not asked, or
    /// not decided at this candidate)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curvature_class: Option<crate::curvature::CurvatureClass>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub curvature_evidence: Option<String>,
    /// the class holds on a neighbourhood (zero, or |μ| > λ² strictly)
    #[serde(skip)]
    pub curvature_strict: bool,
}

pub(crate) use crate::numeric::BiPoly;
/// A polynomial in x over Q(ζ) (lowest first).
pub(crate) type CPoly = Vec<Cyclotomic>;

/// Progress of the stages on standard error (SUBDLAB_EXACT_TRACE=1).
fn trace(what: impl FnOnce() -> String) {
    if std::env::var_os("SUBDLAB_EXACT_TRACE").is_some() {
        static START: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();
        let t = START.get_or_init(std::time::Instant::now).elapsed().as_secs_f64();
        eprintln!("sweep --exact [{t:.2} s]: {}", what());
    }
}

fn q(p: i64, d: i64) -> Rational {
    Rational::new(p.into(), d.into())
}

/// Run the exact sweep over every valence.
pub fn run(s: &ExactSweep) -> Result<Vec<ValenceSets>, Error> {
    s.valences.iter().map(|&n| valence(s, n)).collect()
}

fn resolve(s: &ExactSweep, value: &Rational) -> Result<Box<dyn schemes::Scheme>, Error> {
    let mut params = s.fixed.clone();
    params.push((s.param.clone(), value.to_string()));
    schemes::resolve(&s.scheme, &params)
}

/// The marker: a rational inside the range that no scheme writes as a
/// constant (denominator a large prime).
fn marker(lo: &Rational, hi: &Rational) -> Rational {
    lo + (hi - lo) * q(500_009, 1_000_003)
}

/// The configuration swept: the face sequence when one is given, else the
/// regular configuration of valence n.
fn configuration(s: &ExactSweep, scheme: &dyn schemes::Scheme, n: usize) -> Result<Configuration, Error> {
    match &s.faces {
        Some(f) => Configuration::with_faces(scheme, n, f),
        None => Configuration::regular(scheme, n),
    }
}

fn valence(s: &ExactSweep, n: usize) -> Result<ValenceSets, Error> {
    let t0 = marker(&s.lo, &s.hi);
    let scheme = resolve(s, &t0)?;
    if !scheme.rotation_symmetric() {
        return Err(Error::Input(format!(
            "sweep --exact needs Fourier blocks; '{}' is not rotation symmetric",
            s.scheme
        )));
    }
    let config = configuration(s, scheme.as_ref(), n)?;
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &opts)?;
    let orbits = analysis_orbits(scheme.as_ref(), &analysis);
    orbits.check_free().map_err(|e| Error::Message(format!("valence {n}: no Fourier blocks ({e})")))?;
    let (d, kind) = (&analysis.discovered, analysis.spectrum.neighbourhood);
    let which = orbits.representative.clone();
    let rows = {
        let _guard = SymbolGuard::new(&t0);
        let rows = assemble_rows::<TPoly>(scheme.as_ref(), d, kind, &which);
        let asked = take_non_polynomial();
        match rows {
            Ok(r) if !asked && r.iter().all(|row| row.iter().all(|(_, w)| w.is_defined())) => r,
            _ => {
                return Err(Error::Input(format!(
                    "sweep --exact: the rows of S at valence {n} are not polynomials in {} over a cyclotomic field \
                     (a quotient by, a root or a discontinuous function of the parameter, or a weight known in \
                     floating point only)",
                    s.param
                )))
            }
        }
    };
    // the polynomial rows are the scheme's rows at rational points
    for point in [t0.clone(), s.lo.clone() + (&s.hi - &s.lo) * q(1, 3)] {
        let at = resolve(s, &point)?;
        let exact = assemble_rows::<Cyclotomic>(at.as_ref(), d, kind, &which).map_err(|_| {
            Error::Input(format!("sweep --exact: no exact rows at {} = {point} (valence {n})", s.param))
        })?;
        for (prow, erow) in rows.iter().zip(&exact) {
            let mut diff: std::collections::HashMap<usize, Cyclotomic> = std::collections::HashMap::new();
            for (c, w) in prow {
                let e = diff.remove(c).unwrap_or_else(Cyclotomic::zero);
                diff.insert(*c, e + w.eval(&point));
            }
            for (c, w) in erow {
                let e = diff.remove(c).unwrap_or_else(Cyclotomic::zero);
                diff.insert(*c, e - w.clone());
            }
            if diff.values().any(|v| !Weight::is_zero(v)) {
                return Err(Error::Input(format!(
                    "sweep --exact: the rows of S in {} disagree with the scheme's rows at {} = {point} (the rules \
                     depend on the parameter other than polynomially)",
                    s.param, s.param
                )));
            }
        }
    }
    trace(|| format!("n = {n}: rows checked"));
    let blocks = fourier_blocks(&rows, &orbits);
    let mut polys: Vec<BiPoly> = Vec::new();
    for b in &blocks {
        let p = charpoly(b);
        if !p.iter().all(TPoly::is_defined) {
            return Err(Error::Message(format!("valence {n}: a block polynomial left the polynomials in t")));
        }
        if !polys.contains(&p) {
            polys.push(p);
        }
    }
    let field_order = polys.iter().flatten().fold(1u64, |l, c| {
        let m = c.field_order();
        l / crate::numeric::weight::gcd(l as i64, m as i64) as u64 * m
    });
    // Q(ζ_N) with φ(N) > 2: the exact stages work with norms over several
    // conjugates, minutes where Q takes seconds; minutes without a line
    // printed look like a hang
    // (blocks of low degree in t, as non-box's, stay fast: under a second
    // for k = 3..12)
    let phi = (1..=field_order).filter(|&k| crate::numeric::weight::gcd(k as i64, field_order as i64) == 1).count();
    let t_degree = polys.iter().flatten().map(TPoly::degree).max().unwrap_or(0);
    if phi > 2 && t_degree >= 4 {
        eprintln!(
            "sweep --exact: n = {n}: the blocks' coefficients lie in Q(ζ_{field_order}) (degree {phi}) and have degree {t_degree} \
             in the parameter: the exact \
             stages work with norms over its conjugates and take long (measured on 2 cores: unified-sqrt3 n = 5 \
             about 35 s, n = 7 about 3 min)"
        );
    }
    let mut not_exact = Vec::new();
    if polys.iter().any(|p| !p.iter().all(TPoly::is_real)) {
        not_exact.push("a block's characteristic polynomial has non-real coefficients".to_string());
    }
    // candidates
    let deriv = |p: &BiPoly| -> BiPoly {
        p.iter().enumerate().skip(1).map(|(k, c)| c.clone() * TPoly::int(k as i64)).collect()
    };
    let negated = |p: &BiPoly| -> BiPoly {
        p.iter().enumerate().map(|(k, c)| if k % 2 == 1 { -c.clone() } else { c.clone() }).collect()
    };
    // each pair with the kind of event its common roots mark
    let mut pairs: Vec<(BiPoly, BiPoly, Family)> = Vec::new();
    for (a, pa) in polys.iter().enumerate() {
        pairs.push((pa.clone(), deriv(pa), Family::Meeting));
        pairs.push((pa.clone(), negated(pa), Family::Opposite));
        for pb in &polys[a + 1..] {
            pairs.push((pa.clone(), pb.clone(), Family::Meeting));
            pairs.push((pa.clone(), negated(pb), Family::Opposite));
        }
    }
    // λ1 lives in blocks 1 and g − 1 (Reif's condition as `spectrum` tests
    // it); without rotations (one block) it is in block 0
    let lambda_polys: Vec<BiPoly> = if blocks.len() >= 3 { vec![charpoly(&blocks[1])] } else { polys.clone() };
    if s.curvature {
        for (a, b) in curvature::square_pairs(&polys, &lambda_polys) {
            pairs.push((a, b, Family::Square));
        }
    }
    trace(|| {
        format!(
            "n = {n}: {} block polynomials, degrees {:?}",
            polys.len(),
            polys.iter().map(|p| (p.len() - 1, p.iter().map(TPoly::degree).max())).collect::<Vec<_>>()
        )
    });
    let mut cands: Vec<(RealRoot, Family)> = Vec::new();
    // one pair per Galois orbit: a conjugate pair's norm is the same
    // polynomial, so the same candidates (`one_per_galois_orbit`)
    let all_pairs = pairs.len();
    let pairs = one_per_galois_orbit(pairs, |a, b, family| match family {
        Family::Meeting => Some((b.clone(), a.clone())),
        Family::Opposite => Some((negated(b), negated(a))),
        _ => None,
    });
    trace(|| format!("n = {n}: {} pairs, {} up to conjugation", all_pairs, pairs.len()));
    for (a, b, family) in &pairs {
        let r = first_subresultant(a, b)?;
        trace(|| {
            format!(
                "n = {n}: pair ({}, {}): subresultant of degree {:?}",
                a.len() - 1,
                b.len() - 1,
                r.as_ref().map(|r| r.len())
            )
        });
        let Some(r) = r else { continue };
        let r = rational_norm(&r)?;
        if r.degree() == 0 {
            continue;
        }
        trace(|| format!("n = {n}: norm of degree {}", r.degree()));
        for root in sturm::isolate(&r, &s.lo, &s.hi) {
            cands.push((root, *family));
        }
    }
    // the modulus family: where a non-real root u of a block has |u| = λ1
    // (C¹) or |u| = 1 (convergence) — `modulus`; only where the block
    // polynomials are real (else the sweep is not exact anyway). With
    // `--curvature`, the same family against λ1's root-squared polynomial
    // (roots y²): |u| = λ1², u·ū = λ1⁴, where the class of a non-real μ
    // can change (`curvature`, "non-real μ").
    let mut moduli_followed = not_exact.is_empty();
    let mut moduli_not_followed_because: Option<String> = None;
    let mut square_moduli_not_followed_because: Option<String> = None;
    if moduli_followed {
        let one_minus_x: BiPoly = vec![TPoly::int(-1), TPoly::int(1)];
        let mut targets: Vec<(BiPoly, Family)> = lambda_polys.iter().map(|l| (l.clone(), Family::Modulus)).collect();
        targets.push((one_minus_x, Family::Modulus));
        if s.curvature {
            targets.extend(lambda_polys.iter().map(|l| (curvature::root_squared(l), Family::ModulusSquare)));
        }
        // (block outer, target inner: the order the candidates were always
        // found in, so a merged end keeps the same defining polynomial),
        // one pair per Galois orbit as for the first-order pairs
        let modulus_pairs: Vec<(BiPoly, BiPoly, Family)> = polys
            .iter()
            .flat_map(|p| targets.iter().map(move |(target, family)| (p.clone(), target.clone(), *family)))
            .collect();
        let all_modulus_pairs = modulus_pairs.len();
        // (a block against a target: no reading the other way round)
        let modulus_pairs = one_per_galois_orbit(modulus_pairs, |_, _, _| None);
        trace(|| format!("n = {n}: {all_modulus_pairs} modulus pairs, {} up to conjugation", modulus_pairs.len()));
        'family: for (p, target, family) in &modulus_pairs {
            {
                if *family == Family::ModulusSquare && square_moduli_not_followed_because.is_some() {
                    continue;
                }
                // rational coefficients: the family in Q[t]; Q(ζ_N) ones
                // (n = 5, 7): its norm over the pair's conjugates
                let found = match modulus::rational_coefficients(p).and(modulus::rational_coefficients(target)) {
                    Some(_) => modulus::crossings(p, target),
                    None => modulus::crossings_cyclotomic(p, target, &distinct_conjugates(p, target)),
                };
                match found {
                    Ok(modulus::Crossings::Resultant(r)) => {
                        trace(|| {
                            format!(
                                "n = {n}: modulus pair ({}, {}, {family:?}): resultant of degree {}",
                                p.len() - 1,
                                target.len() - 1,
                                r.degree()
                            )
                        });
                        if r.degree() == 0 {
                            continue;
                        }
                        for root in sturm::isolate(&r, &s.lo, &s.hi) {
                            cands.push((root, *family));
                        }
                    }
                    Ok(modulus::Crossings::Nothing) => {}
                    Err(why) if *family == Family::ModulusSquare => {
                        // the curvature sets alone lose exactness, and
                        // only where a piece has a non-real eigenvalue
                        square_moduli_not_followed_because = Some(why);
                    }
                    Err(why) => {
                        // matters only where a piece has a non-real
                        // eigenvalue (below): all-real sets stay exact
                        moduli_not_followed_because = Some(why);
                        moduli_followed = false;
                        break 'family;
                    }
                }
            }
        }
    }
    trace(|| format!("n = {n}: {} candidates before merging", cands.len()));
    // merge equal candidates, drop the range ends
    // (with the families each candidate came from: a square-family root is
    // where |μ| = λ1² can hold)
    let mut merged: Vec<(RealRoot, Vec<Family>)> = Vec::new();
    'next: for (mut c, family) in cands {
        if c.rational.as_ref().is_some_and(|x| x == &s.lo || x == &s.hi) {
            continue;
        }
        for (m, families) in merged.iter_mut() {
            if sturm::same_root(m, &mut c) {
                // keep the common factor as the defining polynomial
                let g = sturm::primitive(&m.poly.gcd(&c.poly));
                if g.degree() >= 1 && g.degree() < m.poly.degree() {
                    m.poly = g;
                }
                if !families.contains(&family) {
                    families.push(family);
                }
                continue 'next;
            }
        }
        merged.push((c, vec![family]));
    }
    trace(|| format!("n = {n}: {} candidates after merging", merged.len()));
    for (c, _) in merged.iter_mut() {
        c.recognise_rational();
    }
    merged.sort_by(|a, b| a.0.mid().cmp(&b.0.mid()));
    // |μ| = λ1² can hold at these: |x| = y² for a real x, or u·ū = y⁴
    let square_family: Vec<bool> =
        merged.iter().map(|(_, f)| f.contains(&Family::Square) || f.contains(&Family::ModulusSquare)).collect();
    let merged: Vec<RealRoot> = merged.into_iter().map(|(c, _)| c).collect();
    trace(|| format!("n = {n}: {} candidates", merged.len()));
    // sample points of the open pieces
    let lo_root = RealRoot::exact(s.lo.clone());
    let hi_root = RealRoot::exact(s.hi.clone());
    let mut fences: Vec<RealRoot> = vec![lo_root];
    fences.extend(merged.iter().cloned());
    fences.push(hi_root);
    let samples = sturm::points_between(&mut fences);
    trace(|| format!("n = {n}: {} pieces to decide", samples.len()));
    // decide: pieces, range ends, candidates
    let mut decisions = Vec::new();
    let mut piece = Vec::new();
    // reasons the curvature sets alone are not proved exact
    let mut curvature_not_exact: Vec<String> = Vec::new();
    for t in &samples {
        let mut d = decide(s, n, t)?;
        d.kind = "piece";
        d.all_real = Some(all_real(&polys, t));
        if d.all_real == Some(false) {
            // with the modulus family the first-order candidates cover
            // complex pairs, and with its square targets the curvature
            // classes' |μ| = λ1² for a non-real μ
            if !moduli_followed {
                let what = match &moduli_not_followed_because {
                    Some(why) => format!("moduli of complex pairs are not followed ({why})"),
                    None => "moduli of complex pairs are not followed".to_string(),
                };
                let why = format!(
                    "a non-real eigenvalue at {} = {t}: {what}, so the pieces' ends are not proved exact",
                    s.param
                );
                if !not_exact.contains(&why) {
                    not_exact.push(why);
                }
            } else if let (true, Some(because)) = (s.curvature, &square_moduli_not_followed_because) {
                let why = format!(
                    "a non-real eigenvalue at {} = {t}: |μ| = λ1² for non-real μ is not followed ({because}), so the \
                     curvature sets' ends are not proved exact (the first-order sets' are)",
                    s.param
                );
                if !curvature_not_exact.contains(&why) {
                    curvature_not_exact.push(why);
                }
            }
        }
        piece.push(d.clone());
        decisions.push(d);
    }
    let mut at_lo = decide(s, n, &s.lo)?;
    at_lo.kind = "range end";
    let mut at_hi = decide(s, n, &s.hi)?;
    at_hi.kind = "range end";
    decisions.push(at_lo.clone());
    decisions.push(at_hi.clone());
    let mut at_cand = Vec::new();
    let mut undecided: Vec<String> = Vec::new();
    for (k, c) in merged.iter().enumerate() {
        let (l, r) = (&piece[k], &piece[k + 1]);
        let mut d = Decision {
            at: endpoint(c).text,
            kind: "candidate",
            convergent: false,
            c1_spectral: false,
            evidence: "exact (the condition is open in t and fails next to it)".into(),
            all_real: None,
            point: None,
            curvature_class: s.curvature.then_some(CurvatureClass::NotApplicable),
            curvature_evidence: s.curvature.then(|| "exact (not C¹ here: the first-order test fails)".to_string()),
            curvature_strict: false,
        };
        if (l.convergent && r.convergent) || (l.c1_spectral && r.c1_spectral) {
            let (t, label) = match &c.rational {
                Some(x) => (x.clone(), x.to_string()),
                None => (c.mid(), format!("≈ {:.17}", c.to_f64())),
            };
            let here = decide(s, n, &t)?;
            let near = if c.rational.is_some() { "" } else { " (at a rational within 1e-30 of the candidate)" };
            if l.convergent && r.convergent {
                d.convergent = here.convergent;
            }
            if l.c1_spectral && r.c1_spectral {
                d.c1_spectral = here.c1_spectral;
            }
            d.evidence = format!("{}{near}", here.evidence);
            d.at = label;
            d.point = c.rational.clone();
            if s.curvature && d.c1_spectral {
                let class = here.curvature_class.unwrap_or(CurvatureClass::NotApplicable);
                // |μ| = λ1² exactly (bounded, or a Jordan block at λ1²)
                // can only hold at a rational point or on a root of the
                // square family; at an irrational candidate of no such
                // family a nearby point's "equal within tolerance" is not
                // evidence of equality here
                if c.rational.is_none() && curvature::needs_equality(class, here.curvature_strict) && !square_family[k]
                {
                    d.curvature_class = None;
                    d.curvature_evidence = None;
                    undecided.push(format!(
                        "{} = {}: |μ| = λ1² within tolerance nearby, but no |x| = y² relation vanishes there",
                        s.param, d.at
                    ));
                } else {
                    d.curvature_class = Some(class);
                    d.curvature_strict = here.curvature_strict;
                    d.curvature_evidence = here.curvature_evidence.as_ref().map(|e| {
                        let why = if square_family[k] && c.rational.is_none() {
                            "; the candidate is a root of the |x| = y² family"
                        } else {
                            ""
                        };
                        format!("{e}{near}{why}")
                    });
                }
            }
        }
        at_cand.push(d.clone());
        decisions.push(d);
    }
    trace(|| format!("n = {n}: decided"));
    let exact = not_exact.is_empty();
    let curvature_exact = exact && curvature_not_exact.is_empty();
    let sets = |pick: &dyn Fn(&Decision) -> bool,
                evidence_of: &dyn Fn(&Decision) -> &str,
                exact: bool|
     -> Vec<ExactInterval> {
        // the sequence lo, piece 0, cand 0, piece 1, ..., piece k, hi
        let mut seq: Vec<(Option<&RealRoot>, &Decision)> = Vec::new();
        seq.push((Some(&fences[0]), &at_lo));
        for k in 0..piece.len() {
            seq.push((None, &piece[k]));
            if k < at_cand.len() {
                seq.push((Some(&merged[k]), &at_cand[k]));
            }
        }
        seq.push((Some(&fences[fences.len() - 1]), &at_hi));
        let mut out = Vec::new();
        let mut k = 0;
        while k < seq.len() {
            if !pick(seq[k].1) {
                k += 1;
                continue;
            }
            let start = k;
            while k + 1 < seq.len() && pick(seq[k + 1].1) {
                k += 1;
            }
            let end = k;
            // ends: a point entry is closed; a piece entry is open at the fence before/after it
            let (from, from_closed) = match seq[start].0 {
                Some(r) => (r, true),
                None => (seq[start - 1].0.expect("a piece follows a fence"), false),
            };
            let (to, to_closed) = match seq[end].0 {
                Some(r) => (r, true),
                None => (seq[end + 1].0.expect("a piece precedes a fence"), false),
            };
            let evidence = weakest(seq[start..=end].iter().map(|e| evidence_of(e.1)));
            out.push(ExactInterval {
                from: endpoint(from),
                to: endpoint(to),
                from_closed,
                to_closed,
                evidence,
                endpoints_exact: exact,
                from_root: from.clone(),
                to_root: to.clone(),
            });
            k += 1;
        }
        out
    };
    fn first_order(d: &Decision) -> &str {
        d.evidence.as_str()
    }
    fn class_evidence(d: &Decision) -> &str {
        d.curvature_evidence.as_deref().unwrap_or("floating point")
    }
    let convergent = sets(&|d| d.convergent, &first_order, exact);
    let c1_spectral = sets(&|d| d.c1_spectral, &first_order, exact);
    let curvature = s.curvature.then(|| {
        let class_set = |class: CurvatureClass| {
            sets(&move |d: &Decision| d.curvature_class == Some(class), &class_evidence, curvature_exact)
        };
        CurvatureSets {
            zero: class_set(CurvatureClass::Zero),
            bounded: class_set(CurvatureClass::Bounded),
            unbounded: class_set(CurvatureClass::Unbounded),
            square_candidates: merged
                .iter()
                .zip(&square_family)
                .filter(|(_, sq)| **sq)
                .map(|(c, _)| endpoint(c))
                .collect(),
            undecided: undecided.clone(),
            exact: curvature_exact,
            not_exact_because: curvature_not_exact.clone(),
        }
    });
    Ok(ValenceSets {
        valence: n,
        field_order,
        block_polynomials: polys
            .iter()
            .map(|p| [p.len() - 1, p.iter().map(TPoly::degree).max().unwrap_or(0)])
            .collect(),
        candidates: merged.iter().map(endpoint).collect(),
        convergent,
        c1_spectral,
        exact,
        not_exact_because: not_exact,
        decisions,
        curvature,
    })
}

/// The event the common roots of a pair of polynomials mark.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Family {
    /// two root branches meet (a multiplicity changes)
    Meeting,
    /// a branch meets another's negative (a modulus order changes)
    Opposite,
    /// |x| = y² for a root x of a block and a root y of λ1's block
    Square,
    /// |u| = λ1 or |u| = 1 for a non-real root u (a complex pair's modulus
    /// crosses; `modulus`)
    Modulus,
    /// |u| = λ1² for a non-real root u: u·ū = y⁴, the modulus family
    /// against λ1's root-squared block polynomial (`--curvature`)
    ModulusSquare,
}

/// The weakest evidence of several: floating point < certified < exact.
fn weakest<'a>(kinds: impl Iterator<Item = &'a str>) -> String {
    weakest_of(kinds).unwrap_or_else(|| "exact".to_string())
}

/// The weakest evidence of several ("floating point" < "certified" <
/// "exact", read from the start of each text); None when there is none.
pub fn weakest_of<'a>(kinds: impl Iterator<Item = &'a str>) -> Option<String> {
    let mut rank = None;
    for k in kinds {
        let r = if k.starts_with("floating") {
            1
        } else if k.starts_with("certified") {
            2
        } else {
            3
        };
        rank = Some(rank.map_or(r, |x: i32| x.min(r)));
    }
    rank.map(|r| {
        match r {
            1 => "floating point",
            2 => "certified",
            _ => "exact",
        }
        .to_string()
    })
}

/// The spectral verdicts at one rational t: the interval certificate where it
/// decides C¹, else the floating-point spectrum.
fn decide(s: &ExactSweep, n: usize, t: &Rational) -> Result<Decision, Error> {
    let scheme = resolve(s, t)?;
    let config = configuration(s, scheme.as_ref(), n)?;
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &opts)?;
    let v = &analysis.spectrum.verdict;
    let (mut convergent, mut c1) = (v.convergent, v.c1_spectral);
    let mut evidence = "floating point".to_string();
    let cert = if s.certify { certify_analysis(scheme.as_ref(), &analysis).ok() } else { None };
    if let Some(cert) = cert {
        match cert.verdict {
            CertVerdict::Proved => {
                c1 = true;
                convergent = true;
                evidence = "certified (C¹ proved by interval enclosures)".into();
            }
            CertVerdict::Disproved(_) => {
                c1 = false;
                evidence = "certified (C¹ disproved by interval enclosures; convergence in floating point)".into();
            }
            CertVerdict::NotProved(_) => {}
        }
    }
    // the curvature class where asked, from the second-order analysis at
    // this point (not applicable where the first-order test fails)
    let (mut curvature_class, mut curvature_evidence, mut curvature_strict) = (None, None, false);
    if s.curvature {
        if c1 {
            let at = curvature::class_at(scheme.as_ref(), &config)?;
            curvature_class = Some(at.class);
            curvature_evidence = Some(at.evidence);
            curvature_strict = at.strict;
        } else {
            curvature_class = Some(CurvatureClass::NotApplicable);
            curvature_evidence = Some(evidence.clone());
        }
    }
    Ok(Decision {
        at: t.to_string(),
        kind: "piece",
        convergent,
        c1_spectral: c1,
        evidence,
        all_real: None,
        point: Some(t.clone()),
        curvature_class,
        curvature_evidence,
        curvature_strict,
    })
}

fn endpoint(r: &RealRoot) -> Endpoint {
    match &r.rational {
        Some(x) => Endpoint {
            rational: Some(x.to_string()),
            polynomial: None,
            isolating_interval: None,
            decimal: r.to_f64(),
            text: x.to_string(),
        },
        None => {
            let ints = sturm::integer_coefficients(&r.poly);
            let text = poly_text(&ints);
            Endpoint {
                rational: None,
                polynomial: Some(ints.iter().map(|c| c.to_string()).collect()),
                isolating_interval: Some([r.lo.to_string(), r.hi.to_string()]),
                decimal: r.to_f64(),
                text: format!("the root of {text} in ({}, {})", r.lo, r.hi),
            }
        }
    }
}

fn poly_text(c: &[num_bigint::BigInt]) -> String {
    let mut out = String::new();
    for (k, x) in c.iter().enumerate().rev() {
        if x.is_zero() {
            continue;
        }
        let sign = if x.is_negative() { "-" } else { "+" };
        let a = x.abs();
        let coef = if a.is_one() && k > 0 { String::new() } else { a.to_string() };
        let mono = match k {
            0 => String::new(),
            1 => "t".to_string(),
            _ => format!("t^{k}"),
        };
        let term = if coef.is_empty() {
            mono
        } else if mono.is_empty() {
            coef
        } else {
            format!("{coef} {mono}")
        };
        if out.is_empty() {
            out = if sign == "-" { format!("-{term}") } else { term };
        } else {
            out = format!("{out} {sign} {term}");
        }
    }
    if out.is_empty() {
        "0".into()
    } else {
        out
    }
}

/// The Fourier blocks B_m[a][b] = Σ_τ S[(0,a),(τ,b)] ζ_g^{mτ} over Q(ζ)[t].
fn fourier_blocks(rows: &[Vec<(usize, TPoly)>], orbits: &Orbits) -> Vec<Vec<Vec<TPoly>>> {
    let g = orbits.group_order;
    (0..g)
        .map(|m| {
            let list = orbits.block_orbits(m);
            let mut pos = vec![usize::MAX; orbits.num_orbits()];
            for (k, &o) in list.iter().enumerate() {
                pos[o] = k;
            }
            let mut b = vec![vec![TPoly::zero(); list.len()]; list.len()];
            for (ra, &a) in list.iter().enumerate() {
                for (col, w) in &rows[a] {
                    let (ob, tau) = orbits.member[*col];
                    if pos[ob] == usize::MAX {
                        continue;
                    }
                    let z = Cyclotomic::root_of_unity((m * tau) as i64, g as i64)
                        .unwrap_or_else(|_| Cyclotomic::undefined());
                    let e = std::mem::replace(&mut b[ra][pos[ob]], TPoly::zero());
                    b[ra][pos[ob]] = e + w.clone() * TPoly::constant(z);
                }
            }
            b
        })
        .collect()
}

fn eval_x(p: &BiPoly, t: &Rational) -> CPoly {
    let mut c: CPoly = p.iter().map(|w| w.eval(t)).collect();
    while c.last().is_some_and(Weight::is_zero) {
        c.pop();
    }
    c
}

fn cdeg(p: &CPoly) -> usize {
    p.len().saturating_sub(1)
}

/// The j-th principal subresultant coefficient of a (degree m) and b
/// (degree n): the determinant of the (m+n−2j)-square matrix of the
/// coefficients of x^i a (i < n − j) and x^i b (i < m − j) at the powers
/// x^{m+n−j−1} down to x^j.
fn psc(a: &CPoly, b: &CPoly, j: usize) -> Cyclotomic {
    let (m, n) = (cdeg(a), cdeg(b));
    let size = m + n - 2 * j;
    if size == 0 {
        return Cyclotomic::one();
    }
    let top = m + n - j - 1;
    let mut mat: Vec<Vec<Cyclotomic>> = Vec::with_capacity(size);
    let coef =
        |p: &CPoly, k: isize| if k >= 0 && (k as usize) < p.len() { p[k as usize].clone() } else { Cyclotomic::zero() };
    for i in 0..n - j {
        mat.push((0..size).map(|col| coef(a, (top - col) as isize - i as isize)).collect());
    }
    for i in 0..m - j {
        mat.push((0..size).map(|col| coef(b, (top - col) as isize - i as isize)).collect());
    }
    determinant(mat)
}

fn determinant(mut m: Vec<Vec<Cyclotomic>>) -> Cyclotomic {
    let n = m.len();
    let mut det = Cyclotomic::one();
    for c in 0..n {
        let Some(p) = (c..n).find(|&r| !Weight::is_zero(&m[r][c])) else { return Cyclotomic::zero() };
        if p != c {
            m.swap(p, c);
            det = -det;
        }
        let pivot = m[c][c].clone();
        det = det * pivot.clone();
        let inv = Cyclotomic::one() / pivot;
        for r in c + 1..n {
            if Weight::is_zero(&m[r][c]) {
                continue;
            }
            let f = m[r][c].clone() * inv.clone();
            for k in c..n {
                let v = m[r][k].clone() - f.clone() * m[c][k].clone();
                m[r][k] = v;
            }
        }
    }
    det
}

/// max over k ≥ 1 of deg_t(c_k)/k, c_k the coefficient of x^{d−k} (the
/// isobaric weight bound of the degree in t).
fn weight_slope(p: &BiPoly) -> Rational {
    let d = p.len() - 1;
    let mut e = <Rational as Zero>::zero();
    for k in 1..=d {
        let w = q(p[d - k].degree() as i64, k as i64);
        if w > e {
            e = w;
        }
    }
    e
}

/// The first principal subresultant coefficient of a and b (polynomials in
/// x whose leading coefficients are nonzero constants) that is not
/// identically zero, as a polynomial in t over Q(ζ); `None` when neither
/// depends on t (nothing changes).
pub(crate) fn first_subresultant(a: &BiPoly, b: &BiPoly) -> Result<Option<CPoly>, Error> {
    let (m, n) = (a.len() - 1, b.len() - 1);
    if m == 0 || n == 0 || (a.iter().all(TPoly::is_constant) && b.iter().all(TPoly::is_constant)) {
        return Ok(None);
    }
    for p in [a, b] {
        if !p[p.len() - 1].is_constant() || Weight::is_zero(&p[p.len() - 1]) {
            return Err(Error::Message("a block polynomial's leading coefficient depends on t".into()));
        }
    }
    let e = weight_slope(a).max(weight_slope(b));
    // two bounds of deg_t psc_j: isobaric weight (m − j)(n − j) times the
    // slope, and row by row (n − j rows of a's coefficients, m − j of b's)
    let (da, db) = (a.iter().map(TPoly::degree).max().unwrap_or(0), b.iter().map(TPoly::degree).max().unwrap_or(0));
    let bound = |j: usize| -> usize {
        let weight = (e.clone() * q(((m - j) * (n - j)) as i64, 1)).floor().to_usize().unwrap_or(usize::MAX);
        weight.min((n - j) * da + (m - j) * db)
    };
    let d0 = bound(0);
    if d0 + 1 > MAX_POINTS {
        return Err(Error::Message(format!(
            "a subresultant of degree up to {d0} in t: beyond the exact sweep's bound"
        )));
    }
    // rational coefficients (Q(ζ_N) ∩ R = Q at n = 3, 4, 6; no rotations):
    // the same psc_j by values modulo word primes, proved exact by a
    // coefficient bound (`subresultant`) — the cyclotomic eliminations
    // below cost seconds per pair at unified-sqrt3
    // (Q(ζ_N) coefficients: the norm over the pair's distinct conjugates,
    // whose roots contain psc_j's — the callers take that norm next anyway)
    // psc_j below the degree of a common factor proved by exact division
    // vanish identically: no values needed to prove them zero
    let known_zero = proved_common_degree(a, b);
    let conjugates = distinct_conjugates(a, b);
    if let Some(c) = subresultant::first_nonzero_psc(a, b, &conjugates, &bound, known_zero) {
        return Ok(Some(c.into_iter().map(|x| Cyclotomic::from_rational(&Rational::from_integer(x))).collect()));
    }
    // psc_j has degree ≤ bound(j) in t: one nonzero value shows it is not
    // identically zero, bound(j) + 1 zeros that it is; the points 0, −1, 1,
    // −2, 2, ... keep the numbers small
    let points: Vec<Rational> =
        (0..=d0 as i64).map(|i| if i % 2 == 0 { q(i / 2, 1) } else { q(-(i + 1) / 2, 1) }).collect();
    let evals: Vec<(CPoly, CPoly)> = points.iter().map(|t| (eval_x(a, t), eval_x(b, t))).collect();
    for j in known_zero..=m.min(n) {
        let dj = bound(j);
        let values: Vec<Cyclotomic> = evals[..=dj].iter().map(|(x, y)| psc(x, y, j)).collect();
        if values.iter().any(|v| !Weight::is_zero(v)) {
            return Ok(Some(interpolate(&points[..=dj], &values)));
        }
    }
    Err(Error::Message("no principal subresultant coefficient is nonzero (not a polynomial pair)".into()))
}

/// The degree k of a monic factor H ∈ Q[t][x] common to a and b (rational
/// coefficients, constant leading coefficients), proved by exact division
/// of both; 0 when none is found. Then deg gcd_x(a, b) ≥ k over the field
/// Q(t), so psc_0, ..., psc_{k−1} vanish identically (the fundamental
/// theorem on subresultants, von zur Gathen–Gerhard, *Modern Computer
/// Algebra*, §6.10) — without the primes that proving each of them zero
/// from its values needs (at unified-sqrt3, n = 3, two thirds of the
/// first-order pairs' time: every block has a double branch, so the blocks'
/// gcds have degree 2 for every α).
///
/// How: gcd_x(a(x, t₀), b(x, t₀)) at t₀ = 0, 1, 2, ... over Q (monic); its
/// degree is at least deg H everywhere and equals it except at finitely
/// many t₀, so the points of least degree k are kept. H's coefficient of
/// x^{k−j} is ± an elementary symmetric function of j roots, which grow at
/// most like |t|^e (e the slope max_k deg_t(c_k)/k of a), and lies in Q[t]
/// (a monic factor of a monic polynomial over Q[t], Gauss), so it has
/// degree ≤ e·j: ⌊e·k⌋ + 1 points determine H. Nothing here is trusted
/// without the final exact divisions: a wrong interpolation (too few
/// points of the true degree) fails them and gives 0, the search from j = 0.
pub(crate) fn proved_common_degree(a: &BiPoly, b: &BiPoly) -> usize {
    use crate::sweep::exact::modulus::{divide_exactly, interpolated_factor, rational_coefficients, slope, value_at};
    let (Some(qa), Some(qb)) = (rational_coefficients(a), rational_coefficients(b)) else { return 0 };
    let (da, db) = (qa.len() - 1, qb.len() - 1);
    if da == 0 || db == 0 {
        return 0;
    }
    let e = slope(&qa).min(slope(&qb));
    let tries = 2 * da.max(db) as i64 + 40;
    match interpolated_factor(&e, tries, |t| value_at(&qa, t).gcd(&value_at(&qb, t))) {
        Some(h) if divide_exactly(&qa, &h).is_some() && divide_exactly(&qb, &h).is_some() => h.len() - 1,
        _ => 0,
    }
}

/// The polynomial of degree < len through (x_i, y_i) (Newton form, then
/// expanded), coefficients lowest first.
pub(crate) fn interpolate(x: &[Rational], y: &[Cyclotomic]) -> CPoly {
    let n = x.len();
    let mut dd: Vec<Cyclotomic> = y.to_vec();
    for level in 1..n {
        for i in (level..n).rev() {
            let den = Cyclotomic::from_rational(&(&x[i] - &x[i - level]));
            dd[i] = (dd[i].clone() - dd[i - 1].clone()) / den;
        }
    }
    // Horner on the Newton form
    let mut p: CPoly = vec![dd[n - 1].clone()];
    for i in (0..n - 1).rev() {
        // p = p·(t − x_i) + dd[i]
        let xi = Cyclotomic::from_rational(&x[i]);
        let mut next = vec![Cyclotomic::zero(); p.len() + 1];
        for (k, c) in p.iter().enumerate() {
            next[k + 1] = next[k + 1].clone() + c.clone();
            next[k] = next[k].clone() - c.clone() * xi.clone();
        }
        next[0] = next[0].clone() + dd[i].clone();
        p = next;
    }
    while p.last().is_some_and(Weight::is_zero) {
        p.pop();
    }
    p
}

/// The a in (Z/N)^* (N the lcm of the coefficients' orders) whose σ_a
/// give the distinct conjugates σ_a(a, b) of the pair, 1 first.
pub(crate) fn distinct_conjugates(a: &BiPoly, b: &BiPoly) -> Vec<u64> {
    let order = a.iter().chain(b).flat_map(|c| c.coeffs().iter()).fold(1u64, |l, c| {
        let m = c.order().unwrap_or(1) as u64;
        l / crate::numeric::weight::gcd(l as i64, m as i64) as u64 * m
    });
    let conj = |p: &BiPoly, s: u64| -> Vec<Vec<Cyclotomic>> {
        p.iter().map(|c| c.coeffs().iter().map(|x| conjugate(x, s)).collect()).collect()
    };
    let mut seen: Vec<(Vec<Vec<Cyclotomic>>, Vec<Vec<Cyclotomic>>)> = Vec::new();
    let mut out = Vec::new();
    for s in 1..order.max(2) {
        if crate::numeric::weight::gcd(s as i64, order as i64) != 1 {
            continue;
        }
        let pair = (conj(a, s), conj(b, s));
        if !seen.contains(&pair) {
            seen.push(pair);
            out.push(s);
        }
    }
    out
}

/// The pairs (A, B, kind) with one representative per Galois orbit, in
/// their first order.
///
/// Why it is enough: for σ_c (ζ_N ↦ ζ_N^c, c coprime to N) and the pair
/// Q = σ_c(P), the conjugates of Q are σ_a σ_c(P) = σ_b(P): the same set
/// as P's (the σ form a group). The subresultant of Q is σ_c of P's (σ_c
/// is a field automorphism, so the first nonzero psc_j has the same j),
/// and the modulus resultant likewise (its reductions are canonical,
/// `modulus`, step 4 of "The exact sweep: speed"). Both are replaced by
/// their norm — the product over the distinct conjugates — so Q's norm is
/// P's up to a constant factor: the same real roots, the same candidates.
/// At n = 5 the blocks' polynomials P_1 and P_2 are exchanged by σ_2
/// (σ_a(B_m) = B_{am}), so (P_0, P_2) is (P_0, P_1)'s conjugate, (P_2, P_2′)
/// is (P_1, P_1′)'s, (P_2, x − 1) is (P_1, x − 1)'s. Pairs are compared as
/// they are ordered (A, B): (P_1, P_2) and (P_2, P_1) are kept both (their
/// polynomials are not conjugate as ordered pairs, only up to a sign).
///
/// `swapped` gives, for the kinds whose pair can be read the other way
/// round with the same candidates, that reading: (B, A) for two branches
/// meeting (psc_j(B, A) = ±psc_j(A, B)), (B(−x), A(−x)) for a branch
/// meeting another's negative, stored as (A(x), B(−x)) (the common roots
/// negated: psc_j of f(−x), g(−x) is ±psc_j of f, g). With it the orbit of
/// (P_1, P_2) at n = 7 (σ_3: P_1 → P_3 → P_2 → P_1) also holds (P_1, P_3)
/// and (P_2, P_3): their norms agree up to sign.
fn one_per_galois_orbit<K: PartialEq + Copy>(
    pairs: Vec<(BiPoly, BiPoly, K)>,
    swapped: impl Fn(&BiPoly, &BiPoly, K) -> Option<(BiPoly, BiPoly)>,
) -> Vec<(BiPoly, BiPoly, K)> {
    let conj = |p: &BiPoly, a: u64| -> BiPoly {
        p.iter().map(|c| TPoly::from_coeffs(c.coeffs().iter().map(|x| conjugate(x, a)).collect())).collect()
    };
    let mut kept: Vec<(BiPoly, BiPoly, K)> = Vec::new();
    for (a, b, kind) in pairs {
        let conjugates = distinct_conjugates(&a, &b);
        // σ_1 is the pair itself: an exact repeat is dropped too
        let readings: Vec<(BiPoly, BiPoly)> =
            std::iter::once((a.clone(), b.clone())).chain(swapped(&a, &b, kind)).collect();
        let seen = conjugates.iter().any(|&s| {
            readings.iter().any(|(x, y)| {
                let (ca, cb) = if s == 1 { (x.clone(), y.clone()) } else { (conj(x, s), conj(y, s)) };
                kept.iter().any(|(ka, kb, kk)| *kk == kind && *ka == ca && *kb == cb)
            })
        });
        if !seen {
            kept.push((a, b, kind));
        }
    }
    kept
}

/// σ_a(c): ζ_N ↦ ζ_N^a on an element of order dividing N (a coprime to N).
fn conjugate(c: &Cyclotomic, a: u64) -> Cyclotomic {
    let Some(order) = c.order() else { return Cyclotomic::undefined() };
    if order <= 2 {
        return c.clone();
    }
    c.coefficients().fold(Cyclotomic::zero(), |s, (i, r)| {
        let z = Cyclotomic::root_of_unity((i as u64 * a % order as u64) as i64, order as i64)
            .unwrap_or_else(|_| Cyclotomic::undefined());
        s + z * Cyclotomic::from_rational(&r)
    })
}

fn cmul(a: &CPoly, b: &CPoly) -> CPoly {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![Cyclotomic::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = out[i + j].clone() + x.clone() * y.clone();
        }
    }
    out
}

/// A polynomial over Q with the same roots and more: the product of the
/// distinct Galois conjugates of p (their product is fixed by the Galois
/// group, so rational).
pub(crate) fn rational_norm(p: &CPoly) -> Result<Poly, Error> {
    let order = p.iter().fold(1u64, |l, c| {
        let m = c.order().unwrap_or(1) as u64;
        l / crate::numeric::weight::gcd(l as i64, m as i64) as u64 * m
    });
    let mut conjugates: Vec<CPoly> = Vec::new();
    for a in 1..order.max(2) {
        if crate::numeric::weight::gcd(a as i64, order as i64) != 1 {
            continue;
        }
        let c: CPoly = p.iter().map(|x| conjugate(x, a)).collect();
        if !conjugates.contains(&c) {
            conjugates.push(c);
        }
    }
    let prod = conjugates.iter().fold(vec![Cyclotomic::one()], |acc, c| cmul(&acc, c));
    let coeffs: Option<Vec<Rational>> = prod.iter().map(Cyclotomic::to_rational).collect();
    let coeffs = coeffs.ok_or_else(|| Error::Message("a norm over the Galois group is not rational".into()))?;
    let mut poly = Poly { coeffs };
    while poly.coeffs.len() > 1 && poly.coeffs.last().is_some_and(|c| Zero::is_zero(c)) {
        poly.coeffs.pop();
    }
    if poly.coeffs.is_empty() {
        poly.coeffs.push(<Rational as Zero>::zero());
    }
    Ok(poly)
}

/// Every root of every block polynomial at t is real (exactly: the rational
/// norm of each, square-free, has as many real roots as its degree).
pub(crate) fn all_real(polys: &[BiPoly], t: &Rational) -> bool {
    polys.iter().all(|p| {
        let c = eval_x(p, t);
        let Ok(norm) = rational_norm(&c) else { return false };
        let sq = sturm::squarefree(&norm);
        if sq.degree() == 0 {
            return true;
        }
        let bound = sturm::root_bound(&sq);
        let chain = sturm::sturm_chain(&sq);
        sturm::count_roots(&chain, &-bound.clone(), &bound) == sq.degree()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subresultants_find_where_roots_meet() {
        // a = x² − t, b = x − 1: common root at t = 1
        let c = |x: i64| TPoly::int(x);
        let a = vec![-TPoly::variable(), c(0), c(1)];
        let b = vec![c(-1), c(1)];
        let r = first_subresultant(&a, &b).unwrap().unwrap();
        let r = rational_norm(&r).unwrap();
        assert_eq!(sturm::squarefree(&r), sturm::primitive(&Poly { coeffs: vec![q(-1, 1), q(1, 1)] }));
    }

    #[test]
    fn a_common_factor_makes_the_first_coefficients_vanish() {
        // a = (x − 1)(x² − t) = x³ − x² − t x + t, b = (x − 1)(x − 2) =
        // x² − 3x + 2: gcd x − 1 for every t, so psc_0 = Res ≡ 0 (proved by
        // the coefficient bound, modulo primes) and psc_1 ∝ Res(x² − t,
        // x − 2) = 4 − t: the gcd rises exactly at t = 4
        let c = |x: i64| TPoly::int(x);
        let t = TPoly::variable();
        let a = vec![t.clone(), -t, c(-1), c(1)];
        let b = vec![c(2), c(-3), c(1)];
        let r = rational_norm(&first_subresultant(&a, &b).unwrap().unwrap()).unwrap();
        assert_eq!(sturm::primitive(&r), sturm::primitive(&Poly { coeffs: vec![q(-4, 1), q(1, 1)] }));
        // the common factor x − 1 is found and proved by division: psc_0
        // is skipped, and the answer above is unchanged
        assert_eq!(proved_common_degree(&a, &b), 1);
    }

    #[test]
    fn a_common_factor_moving_with_t_is_proved_by_division() {
        // a = (x − t)²(x + 1) = x³ + (1 − 2t)x² + (t² − 2t)x + t²,
        // b = (x − t)²(x − 3) = x³ − (3 + 2t)x² + (t² + 6t)x − 3t²:
        // gcd (x − t)² for every t, so deg gcd = 2 over Q(t)
        let c = |x: i64| TPoly::int(x);
        let t = TPoly::variable();
        let t2 = t.clone() * t.clone();
        let a = vec![t2.clone(), t2.clone() - c(2) * t.clone(), c(1) - c(2) * t.clone(), c(1)];
        let b = vec![c(-3) * t2.clone(), t2.clone() + c(6) * t.clone(), c(-3) - c(2) * t.clone(), c(1)];
        assert_eq!(proved_common_degree(&a, &b), 2);
        // coprime for all but finitely many t: nothing is claimed
        // (x² − t and x − 2 meet only at t = 4)
        let f = vec![-t.clone(), c(0), c(1)];
        let g = vec![c(-2), c(1)];
        assert_eq!(proved_common_degree(&f, &g), 0);
        // (x − t)(x + 1) against (x − t − 1)(x + 1): the common factor
        // x + 1 only (x − t never meets x − t − 1)
        let h = vec![-t.clone(), c(1) - t.clone(), c(1)];
        let k = vec![-t.clone() - c(1), -t.clone(), c(1)];
        assert_eq!(proved_common_degree(&h, &k), 1);
    }
}
