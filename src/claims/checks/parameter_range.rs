//! `parameter-range`: a paper's statement about a range of one scheme
//! parameter ("C¹ for 1/4 − cos(2π/k)/4 < a_k ≤ 3/4"), decided from the
//! exact parameter sets of `sweep --exact` (`sweep::exact`): per
//! configuration, the set of t in a rational window where the scheme
//! converges, is spectrally C¹, or (`condition = "bounded-curvature"`) is
//! spectrally C¹ with curvature class zero or bounded (`sweep --exact
//! --curvature`), as intervals with exact algebraic ends.
//!
//! Two readings, registered separately where both are possible:
//! - `asserts = "inside"`: every t of the stated range satisfies the
//!   condition (a sufficient condition: "if t is in R then C¹");
//! - `asserts = "exactly"`: within the window, the condition holds exactly on
//!   the stated range (the range is also necessary: the bound is sharp).
//!
//! The stated ends are expressions in n (rational, or real elements of a
//! cyclotomic field such as 1/4 − cos(2π/n)/4). They are compared with the
//! computed ends exactly: a computed end is a rational or the one root of a
//! square-free integer polynomial p in an isolating interval; a stated end s
//! equals it when p(s) = 0 in Q(ζ_N) exactly and an interval enclosure of s
//! lies inside the isolating interval (which holds exactly one root of p);
//! otherwise the isolating interval is bisected until it is disjoint from
//! the enclosure of s (rational s: exactly). The sets themselves are proved
//! complete by the sweep (`exact: true`), else the claim is INCONCLUSIVE.
//!
//! A REFUTED names a rational witness t* where the statement fails (a point
//! of the range outside the set, or with `exactly` also a point of the set
//! outside the range) and is confirmed there by a second route: the interval
//! certificate of the spectrum at t* (`spectrum --certify`), which must prove
//! (t* in the set) or disprove (t* outside it) spectral C¹ — for a curvature
//! range, or prove it and the registry's curvature route at t* (exact |μ|
//! against λ² where rational, the Jordan structure at λ² confirmed by the
//! growth test and exact nullities) must give the class; without that
//! confirmation the claim is INCONCLUSIVE.

use std::cmp::Ordering;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::configurations::over_independent_valences;
use crate::claims::common::curvature::confirmed_class;
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::{env_for, subject_params};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::curvature::CurvatureClass;
use crate::error::Error;
use crate::numeric::expr::{Env, Expr};
use crate::numeric::sturm::{self, RealRoot};
use crate::numeric::{Cyclotomic, Interval, ParamValue, Rational, Weight};
use crate::sweep::exact::{Decision, ExactInterval, ExactSweep, ValenceSets};

/// A statement about the parameter range where a scheme converges, is
/// spectrally C¹, or has bounded curvature.
#[derive(Clone, Debug, Deserialize)]
pub struct ParameterRange {
    #[serde(flatten)]
    pub subject: Subject,
    /// the swept parameter (its other parameters are the subject's `params`)
    pub parameter: String,
    /// the stated range, "(A, B]" with `(`/`[` and `)`/`]` for open/closed
    /// ends; A and B expressions in n (and the subject's variables)
    pub range: String,
    /// the rational window [lo, hi] swept (must hold the range); default the
    /// range's own ends, which must then be rational
    #[serde(default)]
    pub window: Option<[String; 2]>,
    /// "c1-spectral" (default), "convergent" or "bounded-curvature"
    #[serde(default = "c1")]
    pub condition: String,
    /// "inside" (every t in the range satisfies the condition) or "exactly"
    /// (within the window, the condition holds exactly on the range)
    pub asserts: String,
    /// decide the sweep's pieces with the interval certificate (else in
    /// floating point)
    #[serde(default)]
    pub certified: bool,
}

fn c1() -> String {
    "c1-spectral".into()
}

/// What the statement asserts at each t of the range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Condition {
    C1Spectral,
    Convergent,
    /// spectrally C¹ with curvature class zero or bounded (|μ| < λ1², or
    /// |μ| = λ1² without a visible Jordan block): "bounded curvature" read
    /// as the registry's `curvature` claims read it, "does not blow up".
    /// Not applicable (not C¹) and unbounded fail.
    BoundedCurvature,
}

impl Condition {
    fn of(text: &str) -> Result<Condition, Error> {
        match text {
            "c1-spectral" => Ok(Condition::C1Spectral),
            "convergent" => Ok(Condition::Convergent),
            "bounded-curvature" => Ok(Condition::BoundedCurvature),
            _ => Err(Error::Claim(format!("condition '{text}': use c1-spectral, convergent or bounded-curvature"))),
        }
    }

    fn what(self) -> &'static str {
        match self {
            Condition::C1Spectral => "spectrally C¹",
            Condition::Convergent => "convergent",
            Condition::BoundedCurvature => "spectrally C¹ with bounded curvature (class zero or bounded)",
        }
    }

    /// The condition at a decided point of the sweep (None: the class was
    /// not decided there).
    fn passes(self, d: &Decision) -> Option<bool> {
        match self {
            Condition::C1Spectral => Some(d.c1_spectral),
            Condition::Convergent => Some(d.convergent),
            Condition::BoundedCurvature => {
                d.curvature_class.map(|k| matches!(k, CurvatureClass::Zero | CurvatureClass::Bounded))
            }
        }
    }

    /// The computed set where the condition holds: for bounded curvature
    /// the union of the zero and bounded class sets (an undecided candidate
    /// is in neither, so no interval of the union holds it).
    fn set(self, sets: &ValenceSets) -> Result<Vec<ExactInterval>, Error> {
        match self {
            Condition::C1Spectral => Ok(sets.c1_spectral.clone()),
            Condition::Convergent => Ok(sets.convergent.clone()),
            Condition::BoundedCurvature => {
                let c = sets
                    .curvature
                    .as_ref()
                    .ok_or_else(|| Error::Message("the exact sweep gave no curvature sets".into()))?;
                Ok(union(&[&c.zero, &c.bounded]))
            }
        }
    }

    /// Why the sets cannot show that the statement holds (None: they can):
    /// candidates not proved complete, or, for a curvature range, the class
    /// sets not proved complete or (with `exactly`) a candidate of the
    /// window whose class is undecided (it might belong to the set). With
    /// `inside` an undecided candidate in the range needs no rule: the set
    /// excludes it, so the range is not inside the set.
    fn incomplete(self, sets: &ValenceSets, exactly: bool) -> Option<String> {
        if !sets.exact {
            return Some(sets.not_exact_because.join("; "));
        }
        let c = sets.curvature.as_ref().filter(|_| self == Condition::BoundedCurvature)?;
        if !c.exact {
            return Some(c.not_exact_because.join("; "));
        }
        (exactly && !c.undecided.is_empty()).then(|| format!("curvature class undecided at {}", c.undecided.join("; ")))
    }
}

/// The union of disjoint intervals of one sweep's sets (the curvature
/// classes): sorted by their lower ends (exactly, a closed end first), and
/// two consecutive ones joined where one ends at the number the next
/// starts from and one of them holds that number. Two class sets of one
/// sweep are built from one sequence of pieces and candidates, so such a
/// shared end is one fence and the joined interval has no hole.
fn union(parts: &[&[ExactInterval]]) -> Vec<ExactInterval> {
    let mut all: Vec<ExactInterval> = parts.iter().flat_map(|p| p.iter().cloned()).collect();
    all.sort_by(|x, y| {
        let (mut a, mut b) = (x.from_root.clone(), y.from_root.clone());
        match sturm::compare(&mut a, &mut b) {
            Some(true) => Ordering::Less,
            Some(false) => Ordering::Greater,
            None => y.from_closed.cmp(&x.from_closed),
        }
    });
    let mut out: Vec<ExactInterval> = Vec::new();
    for i in all {
        if let Some(last) = out.last_mut() {
            let (mut a, mut b) = (last.to_root.clone(), i.from_root.clone());
            if (last.to_closed || i.from_closed) && sturm::same_root(&mut a, &mut b) {
                let evidence =
                    crate::sweep::exact::weakest_of([last.evidence.as_str(), i.evidence.as_str()].into_iter());
                last.evidence = evidence.unwrap_or_default();
                last.endpoints_exact &= i.endpoints_exact;
                last.to = i.to;
                last.to_root = i.to_root;
                last.to_closed = i.to_closed;
                continue;
            }
        }
        out.push(i);
    }
    out
}

/// The stated range, parsed: (lower closed, A, B, upper closed).
fn parse_range(s: &str) -> Result<(bool, String, String, bool), Error> {
    let t = s.trim();
    let bad = || Error::Claim(format!("range '{s}' is not of the form (A, B], [A, B), (A, B) or [A, B]"));
    let lo_closed = match t.chars().next() {
        Some('[') => true,
        Some('(') => false,
        _ => return Err(bad()),
    };
    let hi_closed = match t.chars().last() {
        Some(']') => true,
        Some(')') => false,
        _ => return Err(bad()),
    };
    let inner = &t[1..t.len() - 1];
    // the comma at parenthesis depth 0 separates the ends
    let mut depth = 0i32;
    let mut cut = None;
    for (i, c) in inner.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                if cut.is_some() {
                    return Err(bad());
                }
                cut = Some(i);
            }
            _ => {}
        }
    }
    let i = cut.ok_or_else(bad)?;
    let (a, b) = (inner[..i].trim(), inner[i + 1..].trim());
    if a.is_empty() || b.is_empty() {
        return Err(bad());
    }
    Ok((lo_closed, a.to_string(), b.to_string(), hi_closed))
}

fn rational_text(s: &str, what: &str) -> Result<Rational, Error> {
    ParamValue::parse(s)
        .ok()
        .and_then(|p| p.exact)
        .ok_or_else(|| Error::Claim(format!("{what} '{s}' is not an exact rational (use 1/4 or 0.25)")))
}

/// A stated end as a real number that can be compared exactly.
#[derive(Clone, Debug)]
enum Stated {
    Rational(Rational),
    /// an irrational real element of a cyclotomic field, with an interval
    /// enclosure of its value
    Cyclotomic(Cyclotomic, Interval),
}

impl Stated {
    fn of(text: &str, env: &Env) -> Result<Stated, Error> {
        let e = Expr::parse(text).map_err(|e| Error::Claim(format!("range end '{text}': {e}")))?;
        if let Some(q) = e.exact(env) {
            return Ok(Stated::Rational(q));
        }
        let c = e.cyclotomic(env).ok_or_else(|| {
            Error::Claim(format!(
                "range end '{text}' is neither rational nor a cyclotomic number: it cannot be compared exactly"
            ))
        })?;
        if !c.is_real() {
            return Err(Error::Claim(format!("range end '{text}' is not real")));
        }
        if let Some(q) = c.to_rational() {
            return Ok(Stated::Rational(q));
        }
        let enclosure = e
            .evaluate::<Interval>(env)
            .map_err(|e| Error::Claim(format!("range end '{text}': no interval enclosure ({e:?})")))?;
        Ok(Stated::Cyclotomic(c, enclosure))
    }

    /// Its decimal value (for messages).
    fn decimal(&self) -> f64 {
        match self {
            Stated::Rational(q) => q.to_f64(),
            Stated::Cyclotomic(_, i) => i.mid(),
        }
    }
}

/// How an exact comparison was decided: by exact arithmetic alone, or with
/// an interval enclosure of a stated irrational end (certified).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Route {
    Exact,
    Certified,
}

/// Most bisections of an isolating interval in one comparison (the
/// enclosure of a stated end is about 1e-16 wide; 200 halvings pass that).
const MAX_BISECTIONS: usize = 200;

/// The order of the algebraic number `root` against the stated end `s`.
fn compare(root: &RealRoot, s: &Stated) -> Result<(Ordering, Route), Error> {
    let mut root = root.clone();
    let enclose = |q: &Rational| Interval::rational(q);
    for _ in 0..MAX_BISECTIONS {
        match (&root.rational, s) {
            (Some(r), Stated::Rational(q)) => return Ok((r.cmp(q), Route::Exact)),
            (Some(r), Stated::Cyclotomic(_, e)) => {
                // s is irrational, so r ≠ s: the enclosures separate them
                let ir = enclose(r);
                if ir.hi < e.lo {
                    return Ok((Ordering::Less, Route::Certified));
                }
                if ir.lo > e.hi {
                    return Ok((Ordering::Greater, Route::Certified));
                }
                break;
            }
            (None, Stated::Rational(q)) => {
                // the one root of p in (lo, hi) is q exactly when p(q) = 0
                if &root.lo < q && q < &root.hi && root.poly.eval(q) == Rational::from_integer(0.into()) {
                    return Ok((Ordering::Equal, Route::Exact));
                }
                if &root.hi < q {
                    return Ok((Ordering::Less, Route::Exact));
                }
                if &root.lo > q {
                    return Ok((Ordering::Greater, Route::Exact));
                }
            }
            (None, Stated::Cyclotomic(c, e)) => {
                let (lo, hi) = (enclose(&root.lo), enclose(&root.hi));
                if poly_at(&root.poly.coeffs, c) && one_root_around(&root, e) {
                    // s is a root of p, and an interval holding both s and
                    // e holds one root of p only
                    return Ok((Ordering::Equal, Route::Certified));
                }
                if hi.hi < e.lo {
                    return Ok((Ordering::Less, Route::Certified));
                }
                if lo.lo > e.hi {
                    return Ok((Ordering::Greater, Route::Certified));
                }
            }
        }
        root.bisect();
    }
    Err(Error::Undecided(format!(
        "a computed end ≈ {:.17} and a stated end ≈ {:.17} are not separated by the enclosures and not proved equal",
        root.to_f64(),
        s.decimal()
    )))
}

/// Whether the hull of e's isolating interval and the enclosure `enc` of a
/// stated end holds exactly one root of e's polynomial (Sturm count over
/// rational ends that are not roots themselves).
fn one_root_around(root: &RealRoot, enc: &Interval) -> bool {
    let (Some(a), Some(b)) = (Rational::from_float(enc.lo), Rational::from_float(enc.hi)) else { return false };
    let l = if a < root.lo { a } else { root.lo.clone() };
    let h = if b > root.hi { b } else { root.hi.clone() };
    let zero = Rational::from_integer(0.into());
    if root.poly.eval(&l) == zero || root.poly.eval(&h) == zero {
        return false;
    }
    let chain = crate::numeric::sturm::sturm_chain(&root.poly);
    crate::numeric::sturm::count_roots(&chain, &l, &h) == 1
}

/// p(c) = 0 exactly, p with rational coefficients (lowest first).
fn poly_at(p: &[Rational], c: &Cyclotomic) -> bool {
    let v = p.iter().rev().fold(Cyclotomic::zero(), |acc, a| acc * c.clone() + Cyclotomic::from_rational(a));
    Weight::is_zero(&v)
}

/// The exact sets of one configuration, computed once per process (two
/// readings of one statement share them).
fn exact_sets(sweep: &ExactSweep, n: usize) -> Result<Arc<ValenceSets>, Error> {
    static MEMO: OnceLock<Mutex<HashMap<String, Arc<ValenceSets>>>> = OnceLock::new();
    let key = format!(
        "{}|{:?}|{:?}|{}|{}|{}|{}|{}|{n}",
        sweep.scheme, sweep.fixed, sweep.faces, sweep.param, sweep.lo, sweep.hi, sweep.certify, sweep.curvature
    );
    let memo = MEMO.get_or_init(Default::default);
    if let Some(v) = memo.lock().map_err(|_| Error::Message("memo poisoned".into()))?.get(&key) {
        return Ok(v.clone());
    }
    let one = ExactSweep { valences: vec![n], ..sweep.clone() };
    let sets = crate::sweep::exact::run(&one)?.pop().ok_or_else(|| Error::Message("no valence swept".into()))?;
    let sets = Arc::new(sets);
    memo.lock().map_err(|_| Error::Message("memo poisoned".into()))?.insert(key, sets.clone());
    Ok(sets)
}

/// An interval as text: "(the root of 64 t^2 - 40 t + 5 in (…), 1] ≈ (0.1727…, 1]".
fn show(i: &ExactInterval) -> String {
    let (l, r) = (if i.from_closed { "[" } else { "(" }, if i.to_closed { "]" } else { ")" });
    let short = |e: &crate::sweep::exact::Endpoint| match &e.rational {
        Some(q) => q.clone(),
        None => format!("the root of {} near {:.12}", poly_only(&e.text), e.decimal),
    };
    format!("{l}{}, {}{r}", short(&i.from), short(&i.to))
}

fn poly_only(text: &str) -> String {
    text.strip_prefix("the root of ").and_then(|t| t.split(" in (").next()).unwrap_or(text).to_string()
}

/// Whether a rational point lies in one of the computed intervals (its ends
/// compared with the point exactly).
fn in_set(t: &Rational, list: &[ExactInterval]) -> Result<bool, Error> {
    let point = Stated::Rational(t.clone());
    for i in list {
        let (from, _) = compare(&i.from_root, &point)?;
        let (to, _) = compare(&i.to_root, &point)?;
        let after_from = from == Ordering::Less || (from == Ordering::Equal && i.from_closed);
        let before_to = to == Ordering::Greater || (to == Ordering::Equal && i.to_closed);
        if after_from && before_to {
            return Ok(true);
        }
    }
    Ok(false)
}

/// Where a point lies against the stated range.
fn in_range(t: &Rational, a: &Stated, lo_closed: bool, b: &Stated, hi_closed: bool) -> Result<bool, Error> {
    let r = RealRoot::exact(t.clone());
    let (ca, _) = compare(&r, a)?;
    let (cb, _) = compare(&r, b)?;
    let above = ca == Ordering::Greater || (ca == Ordering::Equal && lo_closed);
    let below = cb == Ordering::Less || (cb == Ordering::Equal && hi_closed);
    Ok(above && below)
}

impl ParameterRange {
    fn sweep(&self, subject: &Subject, n: usize) -> Result<ExactSweep, Error> {
        let (lo, hi) = self.window_ends()?;
        let fixed = subject_params(subject, n)?;
        Ok(ExactSweep {
            scheme: subject.scheme.clone(),
            valences: vec![n],
            param: self.parameter.clone(),
            lo,
            hi,
            fixed,
            faces: subject.faces_for(n).map(str::to_string),
            certify: self.certified,
            curvature: Condition::of(&self.condition)? == Condition::BoundedCurvature,
        })
    }

    fn window_ends(&self) -> Result<(Rational, Rational), Error> {
        match &self.window {
            Some([a, b]) => Ok((rational_text(a, "window end")?, rational_text(b, "window end")?)),
            None => {
                let (_, a, b, _) = parse_range(&self.range)?;
                Ok((
                    rational_text(&a, "range end (no window given)")?,
                    rational_text(&b, "range end (no window given)")?,
                ))
            }
        }
    }

    /// The comparison at one configuration: (statement holds, stated, computed).
    fn at(&self, subject: &Subject, n: usize, evidence: &Mutex<Vec<String>>) -> Result<(bool, String, String), Error> {
        let (lo_closed, a_text, b_text, hi_closed) = parse_range(&self.range)?;
        let condition = Condition::of(&self.condition)?;
        let env = env_for(subject, n)?;
        let (a, b) = (Stated::of(&a_text, &env)?, Stated::of(&b_text, &env)?);
        let sweep = self.sweep(subject, n)?;
        // the range must lie in the window (and not be empty)
        let (wlo, whi) = (RealRoot::exact(sweep.lo.clone()), RealRoot::exact(sweep.hi.clone()));
        if compare(&wlo, &a)?.0 == Ordering::Greater || compare(&whi, &b)?.0 == Ordering::Less {
            return Err(Error::Claim(format!(
                "the stated range {} reaches outside the window [{}, {}]",
                self.range, sweep.lo, sweep.hi
            )));
        }
        let sets = exact_sets(&sweep, n)?;
        // sets not proved complete (a complex pair whose modulus is not
        // followed) cannot show that the statement holds; they can still
        // lead to a refutation, which rests on the certified witness alone
        // (the certificate at one rational point does not use the sets)
        let incomplete = condition.incomplete(&sets, self.asserts == "exactly");
        let list = condition.set(&sets)?;
        let (holds, route) = self.decide(&list, &a, lo_closed, &b, hi_closed)?;
        let what = condition.what();
        let set_text = if list.is_empty() {
            "nowhere in the window".to_string()
        } else {
            list.iter().map(show).collect::<Vec<_>>().join(" ∪ ")
        };
        let piece_evidence =
            crate::sweep::exact::weakest_of(list.iter().map(|i| i.evidence.as_str())).unwrap_or_else(|| {
                if self.certified && condition != Condition::BoundedCurvature {
                    "certified".into()
                } else {
                    "floating point".into()
                }
            });
        let comparison = match route {
            Route::Certified => "ends compared exactly (an irrational stated end located by its interval enclosure)",
            Route::Exact => "ends compared exactly",
        };
        if let (true, Some(why)) = (holds, &incomplete) {
            return Err(Error::Undecided(format!("n = {n}: the exact sets are not proved complete ({why})")));
        }
        let ends = match &incomplete {
            None => "ends exact".to_string(),
            Some(_) if !sets.exact => "ends exact candidates, the set NOT PROVED complete (complex pairs' moduli not \
                                      followed): the refutation rests on the certified witness alone"
                .to_string(),
            Some(why) => format!(
                "ends exact candidates, the curvature sets NOT PROVED complete ({why}): the refutation rests on the \
                 second route alone"
            ),
        };
        // the curvature class is floating point even where |μ| and λ1² are
        // compared exactly (ARCHITECTURE.md, "Curvature classes in the exact
        // sweep", step 5): the verdict says so
        let class_note = match condition {
            Condition::BoundedCurvature => {
                "; the class in floating point: ring test, characteristic map and Jordan \
                                            structure, even where |μ| and λ1² are compared exactly"
            }
            _ => "",
        };
        let mut computed = format!(
            "{what} for {} in {set_text} within [{}, {}] ({ends}; pieces decided: {piece_evidence}{class_note}; \
             {comparison})",
            self.parameter, sweep.lo, sweep.hi
        );
        if !holds {
            computed.push_str(&self.refutation(
                condition,
                subject,
                &sweep,
                &sets,
                &list,
                &set_text,
                [&a, &b],
                [lo_closed, hi_closed],
            )?);
        }
        if let Ok(mut e) = evidence.lock() {
            e.push(piece_evidence);
        }
        let range =
            format!("{}{a_text}, {b_text}{}", if lo_closed { "[" } else { "(" }, if hi_closed { "]" } else { ")" });
        let stated = match self.asserts.as_str() {
            "inside" => format!("{what} for every {} in {range}", self.parameter),
            _ => format!("{what} exactly for {} in {range} within [{}, {}]", self.parameter, sweep.lo, sweep.hi),
        };
        Ok((holds, stated, computed))
    }

    /// Whether the computed set satisfies the statement (`inside`: an
    /// interval holds the range; `exactly`: the set is one interval with the
    /// range's ends and closedness), and how the ends were compared.
    fn decide(
        &self,
        list: &[ExactInterval],
        a: &Stated,
        lo_closed: bool,
        b: &Stated,
        hi_closed: bool,
    ) -> Result<(bool, Route), Error> {
        let mut route = Route::Exact;
        let mut cmp = |root: &RealRoot, s: &Stated| -> Result<Ordering, Error> {
            let (o, r) = compare(root, s)?;
            route = route.max(r);
            Ok(o)
        };
        // every interval is compared as for `inside`, whatever the reading
        // (the comparisons' route is reported)
        let mut inside = false;
        for i in list {
            let from = cmp(&i.from_root, a)?;
            let to = cmp(&i.to_root, b)?;
            let from_ok = from == Ordering::Less || (from == Ordering::Equal && (i.from_closed || !lo_closed));
            let to_ok = to == Ordering::Greater || (to == Ordering::Equal && (i.to_closed || !hi_closed));
            inside |= from_ok && to_ok;
        }
        let holds = match self.asserts.as_str() {
            "inside" => inside,
            // exactly: one interval, with the range's ends and closedness
            _ => match list {
                [i] => {
                    let from = cmp(&i.from_root, a)?;
                    let to = cmp(&i.to_root, b)?;
                    from == Ordering::Equal
                        && to == Ordering::Equal
                        && i.from_closed == lo_closed
                        && i.to_closed == hi_closed
                }
                _ => false,
            },
        };
        Ok((holds, route))
    }

    /// The second route of a failing statement: a rational witness where it
    /// fails, confirmed there (the text appended to the computed value), or
    /// `Error::Undecided` when there is none or it is not confirmed.
    #[allow(clippy::too_many_arguments)]
    fn refutation(
        &self,
        condition: Condition,
        subject: &Subject,
        sweep: &ExactSweep,
        sets: &ValenceSets,
        list: &[ExactInterval],
        set_text: &str,
        [a, b]: [&Stated; 2],
        [lo_closed, hi_closed]: [bool; 2],
    ) -> Result<String, Error> {
        let n = sweep.valences[0];
        let mut witness = self.witness(condition, sets, a, lo_closed, b, hi_closed)?;
        if witness.is_none() {
            // no decided point lies where they disagree: search the gaps
            // between the ends (a disagreement on a tiny interval)
            witness = self.gap_witness(list, sweep, a, lo_closed, b, hi_closed)?;
        }
        let Some((t, should_pass)) = witness else {
            let undecided = match &sets.curvature {
                Some(c) if condition == Condition::BoundedCurvature && !c.undecided.is_empty() => {
                    format!(" (curvature class undecided at {})", c.undecided.join("; "))
                }
                _ => String::new(),
            };
            return Err(Error::Undecided(format!(
                "n = {n}: the exact sets disagree with the statement ({set_text}) only at irrational points or \
                 on a gap narrower than the ends' brackets (1e-24, or a stated end's enclosure){undecided}; no \
                 rational witness to confirm it by a second route"
            )));
        };
        Ok(format!(
            "; confirmed at {} = {t}: {}",
            self.parameter,
            self.confirm(condition, subject, sweep, &t, should_pass)?
        ))
    }

    /// A rational point where the statement fails: in the range but outside
    /// the set (should_pass = false), or, with `exactly`, in the set but
    /// outside the range (should_pass = true). From the sweep's decided points.
    fn witness(
        &self,
        condition: Condition,
        sets: &ValenceSets,
        a: &Stated,
        lo_closed: bool,
        b: &Stated,
        hi_closed: bool,
    ) -> Result<Option<(Rational, bool)>, Error> {
        for d in &sets.decisions {
            let (Some(t), Some(passes)) = (&d.point, condition.passes(d)) else { continue };
            let inside = in_range(t, a, lo_closed, b, hi_closed)?;
            if inside && !passes {
                return Ok(Some((t.clone(), false)));
            }
            if self.asserts == "exactly" && !inside && passes {
                return Ok(Some((t.clone(), true)));
            }
        }
        Ok(None)
    }

    /// A rational witness in the gaps between the ends: the computed sets'
    /// ends, the stated ends and the window's ends are bracketed by
    /// rationals (a computed end's isolating interval refined below 1e-24,
    /// a stated irrational end's outward-rounded enclosure), and in each
    /// open gap between two consecutive disjoint brackets the simplest
    /// rational is a point where neither the set nor the range changes
    /// (both are unions of intervals with ends among the brackets), so
    /// deciding that one point decides the whole gap. The point is tested
    /// exactly — in the stated range (`in_range`) and in the computed set
    /// (its ends against the point) — and, where the statement fails there,
    /// returned for the certificate (`confirm`) like any other witness.
    fn gap_witness(
        &self,
        list: &[ExactInterval],
        sweep: &ExactSweep,
        a: &Stated,
        lo_closed: bool,
        b: &Stated,
        hi_closed: bool,
    ) -> Result<Option<(Rational, bool)>, Error> {
        use crate::numeric::sturm::simplest_between;
        let width = Rational::new(1.into(), num_bigint::BigInt::from(10u64).pow(24));
        let bracket_root = |r: &RealRoot| -> (Rational, Rational) {
            let mut r = r.clone();
            r.refine(&width);
            match &r.rational {
                Some(q) => (q.clone(), q.clone()),
                None => (r.lo.clone(), r.hi.clone()),
            }
        };
        let bracket_stated = |s: &Stated| -> Option<(Rational, Rational)> {
            match s {
                Stated::Rational(q) => Some((q.clone(), q.clone())),
                Stated::Cyclotomic(_, e) => Some((Rational::from_float(e.lo)?, Rational::from_float(e.hi)?)),
            }
        };
        let mut brackets: Vec<(Rational, Rational)> =
            vec![(sweep.lo.clone(), sweep.lo.clone()), (sweep.hi.clone(), sweep.hi.clone())];
        for i in list {
            brackets.push(bracket_root(&i.from_root));
            brackets.push(bracket_root(&i.to_root));
        }
        for s in [a, b] {
            match bracket_stated(s) {
                Some(x) => brackets.push(x),
                None => return Ok(None),
            }
        }
        brackets.sort_by(|x, y| x.0.cmp(&y.0));
        for pair in brackets.windows(2) {
            let (left, right) = (&pair[0], &pair[1]);
            // overlapping brackets: the same number, or two too close to
            // separate at this width (no gap searched between them)
            if left.1 >= right.0 {
                continue;
            }
            let t = simplest_between(&left.1, &right.0);
            if t < sweep.lo || t > sweep.hi {
                continue;
            }
            let inside = in_range(&t, a, lo_closed, b, hi_closed)?;
            let passes = in_set(&t, list)?;
            if inside && !passes {
                return Ok(Some((t, false)));
            }
            if self.asserts == "exactly" && !inside && passes {
                return Ok(Some((t, true)));
            }
        }
        Ok(None)
    }

    /// The second route at the witness t: the interval certificate of the
    /// spectrum there must prove (should_pass) or disprove spectral C¹,
    /// unconditionally. For a curvature range a disproof suffices for a
    /// failing point (no class); otherwise C¹ must be proved and the
    /// registry's curvature route at t (`confirmed_class`: exact |μ|
    /// against λ² where both are rational, the Jordan structure at λ²
    /// confirmed by the growth test and exact nullities) must put the class
    /// on the same side.
    fn confirm(
        &self,
        condition: Condition,
        subject: &Subject,
        sweep: &ExactSweep,
        t: &Rational,
        should_pass: bool,
    ) -> Result<String, Error> {
        let n = sweep.valences[0];
        let mut params = sweep.fixed.clone();
        params.push((sweep.param.clone(), t.to_string()));
        let scheme = crate::schemes::resolve(&sweep.scheme, &params)?;
        let config = match &sweep.faces {
            Some(f) => crate::neighbourhood::Configuration::with_faces(scheme.as_ref(), n, f)?,
            None => crate::neighbourhood::Configuration::regular(scheme.as_ref(), n)?,
        };
        let options = crate::spectrum::Options {
            neighbourhood: crate::neighbourhood::NeighbourhoodKind::Analysis,
            method: None,
            exact: false,
        };
        let analysis = crate::spectrum::analyse(scheme.as_ref(), &config, &options)?;
        let c = crate::certify::certify_analysis(scheme.as_ref(), &analysis)?;
        use crate::certify::Verdict as V;
        let proved = matches!(c.verdict, V::Proved) && !c.conditional;
        let disproved = matches!(c.verdict, V::Disproved(_)) && !c.conditional;
        let unconfirmed = |what: String| {
            Error::Undecided(format!(
                "n = {n}: the exact sets disagree with the statement at {} = {t}, but {what} (a second route must \
                 confirm a refutation)",
                sweep.param
            ))
        };
        let certificate = if should_pass { "proves" } else { "disproves" };
        match condition {
            // spectral C¹ disproved at a point of the range: the C¹ reading
            // fails (a convergence range is refuted only by a proof of C¹
            // outside it)
            Condition::C1Spectral | Condition::Convergent
                if (should_pass && proved) || (!should_pass && disproved && condition == Condition::C1Spectral) =>
            {
                Ok(format!("the interval certificate {certificate} spectral C¹ there (second route)"))
            }
            Condition::BoundedCurvature if !should_pass && disproved => {
                Ok("the interval certificate disproves spectral C¹ there (no curvature class; second route)".into())
            }
            Condition::BoundedCurvature if proved => {
                let mut at = subject.clone();
                at.params.insert(self.parameter.clone(), t.to_string());
                let (class, ev) = confirmed_class(&at, n)?;
                let bounded = matches!(class, CurvatureClass::Zero | CurvatureClass::Bounded);
                if bounded != should_pass {
                    return Err(unconfirmed(format!(
                        "the second-order analysis there gives class {} ({ev})",
                        class.name()
                    )));
                }
                Ok(format!(
                    "the interval certificate proves spectral C¹ there and the second-order analysis gives class {} \
                     ({ev}; second route)",
                    class.name()
                ))
            }
            _ => Err(unconfirmed(format!("the interval certificate there gives {}", c.verdict.display()))),
        }
    }
}

impl CheckKind for ParameterRange {
    const KEYS: &'static [&'static str] = &["parameter", "range", "window", "condition", "asserts", "certified"];

    fn validate(&self) -> Result<(), Error> {
        parse_range(&self.range)?;
        Condition::of(&self.condition)?;
        if !matches!(self.asserts.as_str(), "inside" | "exactly") {
            return Err(Error::Claim(format!(
                "asserts '{}': use inside (every t of the range) or exactly (the range is the whole set in the window)",
                self.asserts
            )));
        }
        if self.parameter.trim().is_empty() {
            return Err(Error::Claim("parameter is empty: the claim asserts nothing".into()));
        }
        if self.subject.params.contains_key(&self.parameter) {
            return Err(Error::Claim(format!(
                "parameter '{}' is swept; it cannot also be fixed in params",
                self.parameter
            )));
        }
        let (lo, hi) = self.window_ends()?;
        if lo >= hi {
            return Err(Error::Claim(format!("the window [{lo}, {hi}] is empty")));
        }
        Ok(())
    }

    fn evaluate(&self, _cache: &mut Cache) -> Result<Finding, Error> {
        self.subject.refuse_tag("the exact parameter sweep")?;
        let evidence = Mutex::new(Vec::new());
        let mut p = over_independent_valences(&self.subject, |subject, n| self.at(subject, n, &evidence))?;
        let kinds = evidence.into_inner().unwrap_or_default();
        let kind = crate::sweep::exact::weakest_of(kinds.iter().map(String::as_str)).unwrap_or_else(|| "exact".into());
        p.detail = format!(
            "{}; exact parameter sets (sweep --exact: ends exact algebraic numbers; the candidate set complete \
             unless the computed text says NOT PROVED complete), pieces decided in {kind}",
            p.detail
        );
        Ok(p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_parse_with_commas_inside_functions() {
        let (l, a, b, h) = parse_range("(1/4 - cos(2 pi / n)/4, 3/4]").unwrap();
        assert!(!l && h);
        assert_eq!(a, "1/4 - cos(2 pi / n)/4");
        assert_eq!(b, "3/4");
        assert!(parse_range("1/4, 3/4").is_err());
        assert!(parse_range("[1/4, 1/2, 3/4]").is_err());
    }

    #[test]
    fn a_stated_cyclotomic_end_equals_the_root_of_its_polynomial() {
        // 1/4 − cos(2π/5)/4 is the root of 64 t² − 40 t + 5 near 0.1727:
        // cos(2π/5) = (√5 − 1)/4, so t = (5 − √5)/16 and (16 t − 5)² = 5,
        // 256 t² − 160 t + 20 = 0, i.e. 64 t² − 40 t + 5 = 0
        let q = |a: i64, b: i64| Rational::new(a.into(), b.into());
        let poly = crate::numeric::exact::Poly { coeffs: vec![q(5, 1), q(-40, 1), q(64, 1)] };
        let root = RealRoot { poly, lo: q(1, 10), hi: q(1, 5), rational: None };
        let env = crate::numeric::expr::env_int(&[("n", 5)]);
        let s = Stated::of("1/4 - cos(2 pi / n)/4", &env).unwrap();
        assert_eq!(compare(&root, &s).unwrap().0, Ordering::Equal);
        // the other root (5 + √5)/16 ≈ 0.4523 is a different number
        let s6 = Stated::of("1/4 - cos(2 pi / n)/4 + 1/1000", &env).unwrap();
        assert_eq!(compare(&root, &s6).unwrap().0, Ordering::Less);
        assert_eq!(compare(&root, &Stated::Rational(q(1, 8))).unwrap().0, Ordering::Greater);
    }
}
