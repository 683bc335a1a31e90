//! Evaluation of the claim checks. Analyses are cached per scheme, parameters,
//! valence and neighbourhood, since many claims look at the same spectrum.

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use num_complex::Complex64;

use super::{Check, Claim, Outcome, Subject, Valences, Verdict};
use crate::error::Error;
use crate::lattice;
use crate::neighbourhood::{Configuration, NeighbourhoodKind, VertexKind};
use crate::numeric::expr::{Env, Expr};
use crate::numeric::ParamValue;
use crate::schemes;
use crate::schemes::registry::{self, Family};
use crate::spectrum::stencils::{limit_stencil, tangent_stencils};
use crate::spectrum::{analyse, eigen, eigenvalue_order, fmt_f, Options, Spectrum, Synthesis};

/// Relative tolerance for comparing computed with stated values.
const TOL: f64 = 1e-9;

#[derive(Default)]
pub struct Cache {
    spectra: HashMap<String, Result<Arc<Spectrum>, Error>>,
    /// where certified claims write their certificate documents
    pub(super) certificates: Option<std::path::PathBuf>,
    /// the claim being evaluated (names its certificate files)
    claim: String,
}

/// Names the certificate files of one claim (what a configuration evaluated
/// on another thread needs of the cache).
struct CertificateNames {
    directory: Option<std::path::PathBuf>,
    claim: String,
}

impl CertificateNames {
    /// The file the certificate of the claim at valence n goes to, when
    /// certificates are asked for.
    fn path(&self, subject: &Subject, n: usize) -> Option<std::path::PathBuf> {
        let faces = subject.faces_for(n).map(|f| format!("-{f}")).unwrap_or_default();
        let safe: String = format!("{}-n{n}{faces}", self.claim)
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() || "-_.".contains(c) { c } else { '_' })
            .collect();
        self.directory.as_ref().map(|dir| dir.join(format!("{safe}.json")))
    }
}

impl Cache {
    pub(super) fn writing_certificates(certificates: Option<std::path::PathBuf>) -> Cache {
        Cache { certificates, ..Default::default() }
    }

    fn certificate_names(&self) -> CertificateNames {
        CertificateNames { directory: self.certificates.clone(), claim: self.claim.clone() }
    }

    fn key(s: &Subject, n: usize) -> String {
        format!("{}|{:?}|{n}|{:?}|{:?}", s.scheme, s.params, s.neighbourhood, s.faces_for(n))
    }

    pub(super) fn spectrum(&mut self, s: &Subject, n: usize) -> Result<Arc<Spectrum>, Error> {
        self.spectra.entry(Cache::key(s, n)).or_insert_with(|| compute(s, n).map(Arc::new)).clone()
    }

    /// Analyse, side by side, every configuration of `subject` that is not
    /// cached yet, for a check that asks for the spectrum of each (the
    /// sequential pass then finds them all cached: the same analyses, as
    /// `compute` reads only the narrowed subject). A subject whose
    /// configurations cannot be listed is left to that pass to report.
    fn prefetch(&mut self, subject: &Subject) {
        let Ok(configurations) = subject.configurations() else { return };
        let mut missing: Vec<(usize, Subject)> = Vec::new();
        let mut keys: Vec<String> = Vec::new();
        for (n, s) in configurations {
            let key = Cache::key(&s, n);
            if !self.spectra.contains_key(&key) && !keys.contains(&key) {
                keys.push(key);
                missing.push((n, s));
            }
        }
        if missing.len() < 2 {
            return;
        }
        let computed = super::schedule::each_configuration(&missing, |s, n| compute(s, n).map(Arc::new));
        self.spectra.extend(keys.into_iter().zip(computed));
    }
}

pub(super) fn kind_of(s: &Subject) -> Result<NeighbourhoodKind, Error> {
    s.neighbourhood.as_deref().unwrap_or("analysis").parse()
}

/// The subject's parameters evaluated at valence n, as `name=value` overrides.
fn subject_params(s: &Subject, n: usize) -> Result<Vec<(String, String)>, Error> {
    let base = crate::numeric::expr::env_int(&[("n", n as i64), ("k", n as i64)]);
    let mut params: Vec<(String, String)> = Vec::new();
    for (k, v) in &s.params {
        let e = Expr::parse(v).map_err(|e| Error::Claim(format!("parameter {k} = '{v}': {e}")))?;
        let text = match e.exact(&base) {
            Some(q) => q.to_string(),
            None => format!("{:e}", real(e.eval(&base)?, v)?),
        };
        params.push((k.clone(), text));
    }
    Ok(params)
}

/// The scheme (with parameters evaluated at valence n) and configuration.
pub(super) fn subject_config(s: &Subject, n: usize) -> Result<(Box<dyn schemes::Scheme>, Configuration), Error> {
    let scheme = schemes::resolve(&s.scheme, &subject_params(s, n)?)?;
    let config = match s.faces_for(n) {
        Some(f) => Configuration::with_faces(scheme.as_ref(), n, f)?,
        None => Configuration::regular(scheme.as_ref(), n)?,
    };
    Ok((scheme, config))
}

fn compute(s: &Subject, n: usize) -> Result<Spectrum, Error> {
    let kind = kind_of(s)?;
    // lattice schemes (built-in or files) are analysed on Z², not on a mesh
    if registry::family_of(&s.scheme) == Ok(Family::Lattice) {
        if n != 4 {
            return Err(Error::Claim(format!("{} is defined on the regular lattice only (valence 4)", s.scheme)));
        }
        let scheme = registry::lattice(&s.scheme, &subject_params(s, n)?)?;
        return Ok(lattice::analysis::analyse(scheme.as_ref(), kind, false)?.spectrum);
    }
    let (scheme, config) = subject_config(s, n)?;
    Ok(analyse(scheme.as_ref(), &config, &Options { neighbourhood: kind, method: None, exact: false })?.spectrum)
}

pub(super) fn env_for(s: &Subject, n: usize) -> Result<Env, Error> {
    env_with(s, n, None)
}

/// The environment of valence n, with the Fourier block index m when given.
fn env_with(s: &Subject, n: usize, m: Option<usize>) -> Result<Env, Error> {
    let mut env = crate::numeric::expr::env_int(&[("n", n as i64), ("k", n as i64)]);
    if let Some(m) = m {
        env.insert("m".into(), ParamValue::from_ratio(m as i64, 1));
    }
    if let Some(f) = s.faces_for(n) {
        // numbers of quads and triangles around the centre
        let quads = f.chars().filter(|&c| c == 'Q').count() as i64;
        env.insert("quads".into(), ParamValue::from_ratio(quads, 1));
        env.insert("tris".into(), ParamValue::from_ratio(n as i64 - quads, 1));
    }
    let defs: Vec<(&String, &String)> = s.params.iter().chain(s.vars.iter()).collect();
    if let Some((name, _)) = defs.iter().find(|(k, _)| env.contains_key(k.as_str())) {
        return Err(Error::Claim(format!(
            "'{name}' is given by the check (the valence n or k, the block m, quads, tris) and cannot be redefined in params or vars"
        )));
    }
    define(env, defs)
}

/// `env` with the definitions `defs` (expressions in the names already in
/// `env` and in each other) added, evaluated in dependency order: exactly
/// where rational, else in floating point.
fn define(mut env: Env, defs: Vec<(&String, &String)>) -> Result<Env, Error> {
    // definitions may refer to each other: evaluate in dependency order
    let mut pending = defs;
    while !pending.is_empty() {
        let before = pending.len();
        let mut later = Vec::new();
        for (k, v) in pending {
            let e = Expr::parse(v).map_err(|e| Error::Claim(format!("'{v}': {e}")))?;
            if e.variables().iter().any(|x| !env.contains_key(x)) {
                later.push((k, v));
                continue;
            }
            if real_variables(&e, &env).is_err() {
                // defined from a non-real variable: marked in turn
                let text = format!("'{v}' (from a non-real variable)");
                env.insert(k.clone(), ParamValue { value: f64::NAN, text, exact: None });
                continue;
            }
            let value = match e.exact(&env) {
                Some(q) => {
                    ParamValue { value: crate::numeric::Weight::to_f64(&q), text: q.to_string(), exact: Some(q) }
                }
                None => {
                    let z = finite(e.eval(&env)?, v)?;
                    match real(z, v) {
                        Ok(x) => ParamValue::from_f64(x),
                        // the environment holds real numbers: a non-real
                        // variable is marked (NaN) and is an error where it
                        // is used ([`real_variables`]), never its real part
                        Err(_) => ParamValue { value: f64::NAN, text: format!("'{v}' = {}", show(z)), exact: None },
                    }
                }
            };
            env.insert(k.clone(), value);
        }
        if later.len() == before {
            let names: Vec<&str> = later.iter().map(|(k, _)| k.as_str()).collect();
            return Err(Error::Claim(format!("variables {} refer to unknown or circular names", names.join(", "))));
        }
        pending = later;
    }
    Ok(env)
}

/// The value of a stated expression; a value that is not a finite number
/// (0·10^400, an overflow) is a malformed value (the claim is an ERROR).
pub(super) fn eval(text: &str, env: &Env) -> Result<Complex64, Error> {
    let e = Expr::parse(text).map_err(|e| Error::Claim(format!("'{text}': {e}")))?;
    real_variables(&e, env)?;
    let z = e.eval(env).map_err(|e| Error::Claim(format!("'{text}': {e}")))?;
    finite(z, text)
}

/// An error when `e` uses a variable whose value is not real: variables
/// (`vars`, `params`) are real numbers; a complex quantity is written into
/// the expression itself (its imaginary part was once dropped silently).
fn real_variables(e: &Expr, env: &Env) -> Result<(), Error> {
    match e.variables().iter().find_map(|v| env.get(v).filter(|p| p.value.is_nan())) {
        Some(p) => Err(Error::Claim(format!(
            "variable {} is not a real number: variables must be real (write a complex quantity into the expression \
             itself)",
            p.text
        ))),
        None => Ok(()),
    }
}

/// [`eval`] of a quantity that must be real (a weight, a count, a size, a
/// block index): a non-real value is a malformed claim, never its real part.
pub(super) fn eval_real(text: &str, env: &Env) -> Result<f64, Error> {
    real(eval(text, env)?, text)
}

/// The real number `z`, or an error naming `text` when `z` is not real
/// (imaginary part beyond rounding, relative 1e-12).
fn real(z: Complex64, text: &str) -> Result<f64, Error> {
    if z.im.abs() > 1e-12 * z.norm().max(1.0) {
        return Err(Error::Claim(format!("'{text}' is {}, not a real number: a real value is required here", show(z))));
    }
    Ok(z.re)
}

fn finite(z: Complex64, text: &str) -> Result<Complex64, Error> {
    if z.re.is_finite() && z.im.is_finite() {
        Ok(z)
    } else {
        Err(Error::Claim(format!("'{text}' is not a finite number ({}): it cannot decide the claim", show(z))))
    }
}

pub fn show(z: Complex64) -> String {
    if z.im.abs() <= 1e-12 * z.norm().max(1.0) {
        let r = crate::numeric::recognise::recognise(z.re);
        match r {
            Some(r) if r.len() < 8 && r != fmt_f(z.re) => format!("{} ({r})", fmt_f(z.re)),
            _ => fmt_f(z.re),
        }
    } else {
        format!("{}{}{}i", fmt_f(z.re), if z.im < 0.0 { "-" } else { "+" }, fmt_f(z.im.abs()))
    }
}

fn show_list(v: &[Complex64]) -> String {
    const SHOWN: usize = 12;
    let mut s: Vec<String> = v.iter().take(SHOWN).map(|z| show(*z)).collect();
    if v.len() > SHOWN {
        s.push(format!("… ({} in all)", v.len()));
    }
    format!("[{}]", s.join(", "))
}

fn close(a: Complex64, b: Complex64) -> bool {
    (a - b).norm() <= TOL * a.norm().max(b.norm()).max(1.0)
}

/// Multiset difference: stated values not matched, computed values not matched.
fn unmatched(stated: &[Complex64], computed: &[Complex64]) -> (Vec<Complex64>, Vec<Complex64>) {
    let mut left: Vec<Complex64> = computed.to_vec();
    let mut missing = Vec::new();
    for &z in stated {
        match left.iter().position(|&w| close(z, w)) {
            Some(k) => {
                left.remove(k);
            }
            None => missing.push(z),
        }
    }
    (missing, left)
}

fn expanded(spec: &Spectrum) -> Vec<Complex64> {
    spec.eigenvalues
        .iter()
        .flat_map(|e| std::iter::repeat_n(Complex64::new(e.re, e.im), e.algebraic_multiplicity))
        .collect()
}

/// Eigenvalues of Fourier block m (repeated by multiplicity).
fn block_values(spec: &Spectrum, m: usize) -> Result<Vec<Complex64>, Error> {
    let Synthesis::Dft { blocks, .. } = &spec.synthesis else {
        return Err(Error::Claim("the configuration was not decomposed into Fourier blocks".into()));
    };
    let b = blocks.get(m).ok_or_else(|| Error::Claim(format!("there is no Fourier block {m}")))?;
    let mut v: Vec<Complex64> =
        eigen::block_eigen(b)?.into_iter().flat_map(|e| std::iter::repeat_n(e.value, e.algebraic)).collect();
    v.sort_by(|a, b| eigenvalue_order(*a, *b));
    Ok(v)
}

pub(super) struct Partial {
    verdict: Verdict,
    stated: String,
    computed: String,
    detail: String,
}

fn inconclusive(detail: String) -> Partial {
    Partial { verdict: Verdict::Inconclusive, stated: String::new(), computed: String::new(), detail }
}

/// Whether an error says the computation could not decide (the claim is
/// INCONCLUSIVE): a proof not found, a quantity not computed for this
/// configuration, a numerical stage that failed on valid input. Every other
/// error (a malformed or vacuous claim, a missing or misspelt scheme file, an
/// unknown scheme or parameter, a value of the wrong kind) says the claim
/// cannot be read as written: ERROR, which no recorded verdict can pass.
pub(super) fn undecided(e: &Error) -> bool {
    matches!(e, Error::Undecided(_) | Error::Numeric(_) | Error::NotDetermined(_) | Error::Message(_))
}

pub fn evaluate(paper: &str, claim: &Claim, cache: &mut Cache) -> Outcome {
    if let Check::Malformed(message) = &claim.check {
        return error_outcome(paper, claim, message.clone());
    }
    if let Err(e) = claim.check.validate() {
        return error_outcome(paper, claim, e.to_string());
    }
    cache.claim = claim.id.clone();
    match run(&claim.check, cache) {
        Ok(p) => outcome(paper, claim, p),
        Err(e) if undecided(&e) => outcome(paper, claim, inconclusive(e.to_string())),
        Err(e) => error_outcome(paper, claim, e.to_string()),
    }
}

/// The ERROR outcome of a claim that could not be read or evaluated.
pub fn error_outcome(paper: &str, claim: &Claim, detail: String) -> Outcome {
    outcome(paper, claim, Partial { verdict: Verdict::Error, stated: String::new(), computed: String::new(), detail })
}

/// A claim's outcome: what the claim says of itself, and the verdict.
fn outcome(paper: &str, claim: &Claim, p: Partial) -> Outcome {
    Outcome {
        id: claim.id.clone(),
        paper: paper.to_string(),
        location: claim.location.clone(),
        statement: claim.statement.clone(),
        convention: claim.convention.clone(),
        verdict: p.verdict,
        expected: claim.expected,
        by_construction: claim.by_construction.clone(),
        stated: p.stated,
        computed: p.computed,
        detail: p.detail,
        seconds: 0.0,
    }
}

/// What a per-configuration comparison gives: whether it agrees, the stated
/// and the computed value.
type Comparison = Result<(bool, String, String), Error>;

/// Runs a per-valence comparison and reports the first valence where it fails.
pub(super) fn over_valences(
    subject: &Subject,
    mut one: impl FnMut(&Subject, usize) -> Comparison,
) -> Result<Partial, Error> {
    // one run per configuration (a valence, or a face sequence: QQQ and TTT
    // are two), each with the subject narrowed to it
    let configurations = subject.configurations()?;
    let results: Vec<Comparison> = configurations.iter().map(|(n, narrowed)| one(narrowed, *n)).collect();
    summarise(&configurations, results)
}

/// [`over_valences`] for a comparison that needs nothing but its
/// configuration (no cache): the configurations are evaluated side by side
/// (`schedule`), and the verdict is drawn from their results in
/// configuration order, as from a sequential run.
fn over_independent_valences(
    subject: &Subject,
    one: impl Fn(&Subject, usize) -> Comparison + Sync,
) -> Result<Partial, Error> {
    let configurations = subject.configurations()?;
    let results = super::schedule::each_configuration(&configurations, one);
    summarise(&configurations, results)
}

/// The verdict from the comparison at each configuration (in order): HOLDS
/// when all agree, REFUTED at the first that disagrees, and no verdict when
/// nothing disagrees but a configuration could not be decided.
fn summarise(configurations: &[(usize, Subject)], results: Vec<Comparison>) -> Result<Partial, Error> {
    let name = |s: &Subject, n: usize| match s.faces_for(n) {
        Some(f) => format!("n={n} ({f})"),
        None => format!("n={n}"),
    };
    // a malformed value at any configuration makes the claim an ERROR,
    // whatever the others give: the claim cannot be read as written
    let mut results = results;
    if let Some(k) = results.iter().position(|r| r.as_ref().is_err_and(|e| !undecided(e))) {
        return Err(results.swap_remove(k).err().unwrap_or_else(|| Error::Claim("malformed claim".into())));
    }
    let mut first = None;
    // a configuration that cannot be decided leaves the claim undecided,
    // unless another configuration refutes it: one counterexample refutes a
    // statement about all of them, whatever the others give
    let mut undecided: Option<(String, Error)> = None;
    let (mut stated0, mut computed0) = (String::new(), String::new());
    for ((n, narrowed), result) in configurations.iter().zip(results) {
        let (ok, stated, computed) = match result {
            Ok(r) => r,
            Err(e) => {
                undecided.get_or_insert((narrowed.label(*n), e));
                continue;
            }
        };
        if stated0.is_empty() {
            stated0 = format!("{}: {stated}", name(narrowed, *n));
            computed0 = format!("{}: {computed}", name(narrowed, *n));
        }
        if !ok && first.is_none() {
            first = Some((name(narrowed, *n), narrowed.label(*n), stated, computed));
        }
    }
    let lo = configurations.iter().map(|(n, _)| *n).min();
    let hi = configurations.iter().map(|(n, _)| *n).max();
    let count = configurations.len();
    let span = match (lo, hi) {
        (Some(a), Some(b)) if a != b => format!("valences {a}..{b} ({count} checked)"),
        (Some(a), _) if count > 1 => format!("valence {a} ({count} configurations)"),
        (Some(a), _) => format!("valence {a}"),
        _ => return Err(Error::Claim("no valences given: the claim asserts nothing".into())),
    };
    if first.is_none() {
        if let Some((_, e)) = undecided {
            // nothing refutes, and something is not decided: no verdict
            return Err(e);
        }
    }
    let also = undecided
        .map(|(label, e)| {
            let why = e.to_string();
            let why = why.strip_prefix(&format!("{label}: ")).map(str::to_string).unwrap_or(why);
            format!("; {label} not decided: {why}")
        })
        .unwrap_or_default();
    Ok(match first {
        None => Partial {
            verdict: Verdict::Holds,
            stated: stated0,
            computed: computed0,
            detail: format!("agrees at {span}"),
        },
        Some((short, label, s, c)) => Partial {
            verdict: Verdict::Refuted,
            stated: format!("{short}: {s}"),
            computed: format!("{short}: {c}"),
            detail: format!("first disagreement at {label} ({span}){also}"),
        },
    })
}

/// `lhs = rhs` in `env`: exactly where both sides are rational, else in
/// floating point (relative 1e-12); the two values as shown, and whether the
/// comparison was exact.
fn identity_at(l: &Expr, r: &Expr, lhs: &str, rhs: &str, env: &Env) -> Result<(bool, String, bool), Error> {
    real_variables(l, env)?;
    real_variables(r, env)?;
    if let (Some(a), Some(b)) = (l.exact(env), r.exact(env)) {
        return Ok((a == b, format!("{a} vs {b}"), true));
    }
    let (a, b) = (finite(l.eval(env)?, lhs)?, finite(r.eval(env)?, rhs)?);
    let ok = (a - b).norm() <= 1e-12 * a.norm().max(b.norm()).max(1.0);
    Ok((ok, format!("{} vs {}", show(a), show(b)), false))
}

fn run(check: &Check, cache: &mut Cache) -> Result<Partial, Error> {
    match check {
        Check::Eigenvalues { subject, values, compare, block, moduli } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                let blocks: Vec<Option<usize>> = match block.as_deref() {
                    None => vec![None],
                    // every non-trivial Fourier block, with m in the environment
                    Some("m") => (1..n).map(Some).collect(),
                    Some(b) => {
                        let m = eval_real(b, &env_for(subject, n)?)?.round();
                        if !(0.0..n as f64).contains(&m) {
                            return Err(Error::Claim(format!("block '{b}' is {m} at n = {n}")));
                        }
                        vec![Some(m as usize)]
                    }
                };
                let mut first = None;
                for b in blocks {
                    let env = env_with(subject, n, b)?;
                    let mut stated = stated_values(values, &env)?;
                    stated.sort_by(|a, b| eigenvalue_order(*a, *b));
                    let mut computed = match b {
                        Some(m) => block_values(&spec, m)?,
                        None => expanded(&spec),
                    };
                    computed.sort_by(|a, b| eigenvalue_order(*a, *b));
                    if *moduli {
                        // the other reading: only |λ| is compared
                        for z in stated.iter_mut().chain(computed.iter_mut()) {
                            *z = Complex64::new(z.norm(), 0.0);
                        }
                        stated.sort_by(|a, b| eigenvalue_order(*a, *b));
                        computed.sort_by(|a, b| eigenvalue_order(*a, *b));
                    }
                    let shown: Vec<Complex64> = match compare.as_str() {
                        "leading" => computed.iter().take(stated.len()).copied().collect(),
                        "all" | "contains" => computed.clone(),
                        // only the computed copies of the stated values count
                        "count" => computed.iter().copied().filter(|w| stated.iter().any(|z| close(*z, *w))).collect(),
                        other => {
                            return Err(Error::Claim(format!(
                                "unknown comparison '{other}' (all, leading, contains, count)"
                            )))
                        }
                    };
                    let (missing, extra) = unmatched(&stated, &shown);
                    let ok = missing.is_empty() && (compare == "contains" || extra.is_empty());
                    let tag = b.map(|m| format!("block {m}: ")).unwrap_or_default();
                    let tag = if *moduli { format!("{tag}moduli ") } else { tag };
                    let text = (format!("{tag}{}", show_list(&stated)), format!("{tag}{}", show_list(&shown)));
                    if !ok {
                        let why = format!(
                            " (stated but not found: {}; found but not stated: {})",
                            show_list(&missing),
                            show_list(&extra)
                        );
                        return Ok((false, text.0, text.1 + &why));
                    }
                    first.get_or_insert(text);
                }
                let (s, c) = first.unwrap_or_default();
                Ok((true, s, c))
            })
        }
        Check::Subdominant { subject, value } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                let stated = eval(value, &env_for(subject, n)?)?;
                let l1 = spec
                    .eigenvalues
                    .get(1)
                    .map(|e| Complex64::new(e.re, e.im))
                    .ok_or_else(|| Error::Undecided("no subdominant eigenvalue".into()))?;
                let double = spec.eigenvalues[1].algebraic_multiplicity;
                Ok((close(stated, l1), show(stated), format!("{} (multiplicity {double})", show(l1))))
            })
        }
        Check::Size { subject, value } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                let stated = eval_real(value, &env_for(subject, n)?)?;
                let size = spec.matrix_size as f64;
                Ok((
                    (stated - size).abs() < 0.5,
                    format!("{stated}"),
                    format!("{} (minimal {}, analysis {})", spec.matrix_size, spec.minimal_size, spec.analysis_size),
                ))
            })
        }
        Check::InvariantSet { subject, rings, lattice_sum, kinds, value } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                super::invariant_set::one(subject, n, rings, lattice_sum.as_deref(), kinds.as_deref(), value, &spec)
            })
        }
        Check::Inequality { subject, lhs, op, rhs } => over_valences(subject, |subject, n| {
            let mut env = env_for(subject, n)?;
            let (l, r) = (Expr::parse(lhs)?, Expr::parse(rhs)?);
            let uses_spectrum = l
                .variables()
                .iter()
                .chain(r.variables().iter())
                .any(|v| ["lambda1", "lambda3", "size"].contains(&v.as_str()));
            if uses_spectrum && !subject.scheme.is_empty() {
                let spec = cache.spectrum(subject, n)?;
                let l1 = spec
                    .eigenvalues
                    .get(1)
                    .map(|e| e.re)
                    .ok_or_else(|| Error::Undecided("no subdominant eigenvalue".into()))?;
                let l3 = spec.eigenvalues.get(2).map(|e| e.modulus).unwrap_or(0.0);
                env.insert("lambda1".into(), ParamValue::from_f64(l1));
                env.insert("lambda3".into(), ParamValue::from_f64(l3));
                env.insert("size".into(), ParamValue::from_ratio(spec.matrix_size as i64, 1));
            }
            real_variables(&l, &env)?;
            real_variables(&r, &env)?;
            let (a, b) = (finite(l.eval(&env)?, lhs)?, finite(r.eval(&env)?, rhs)?);
            if a.im.abs() > 1e-12 || b.im.abs() > 1e-12 {
                return Err(Error::Claim(format!("'{lhs}' or '{rhs}' is not real at n = {n}")));
            }
            let (a, b) = (a.re, b.re);
            let ok = match op.as_str() {
                "<" => a < b,
                "<=" => a <= b,
                ">" => a > b,
                ">=" => a >= b,
                other => return Err(Error::Claim(format!("unknown comparison '{other}' (<, <=, >, >=)"))),
            };
            Ok((ok, format!("{lhs} {op} {rhs}"), format!("{} {op} {}: {ok}", fmt_f(a), fmt_f(b))))
        }),
        Check::NonnegativeSpectrum { subject, expect } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                let negative: Vec<Complex64> = spec
                    .eigenvalues
                    .iter()
                    .filter(|e| e.is_real() && e.re < -1e-12)
                    .map(|e| Complex64::new(e.re, 0.0))
                    .collect();
                let got = negative.is_empty();
                Ok((
                    got == *expect,
                    if *expect { "no negative eigenvalue".into() } else { "a negative eigenvalue".into() },
                    if got { "no negative eigenvalue".into() } else { format!("negative: {}", show_list(&negative)) },
                ))
            })
        }
        Check::CharacteristicMap { subject, expect, levels, certified: true, .. } => {
            let names = cache.certificate_names();
            over_independent_valences(subject, |subject, n| {
                let (scheme, config) = subject_config(subject, n)?;
                let options =
                    crate::spectrum::Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
                let analysis = crate::spectrum::analyse(scheme.as_ref(), &config, &options)?;
                let most = levels.unwrap_or(crate::certify::charmap::DEFAULT_MAX_LEVELS);
                let c = crate::certify::certify_charmap(scheme.as_ref(), &analysis, most)?;
                if let Some(path) = names.path(subject, n) {
                    crate::certify::export::write_charmap(&path, scheme.as_ref(), &analysis, &c)?;
                }
                use crate::certify::Verdict;
                // Reif's criterion as a whole: the spectrum, regularity and
                // injectivity all proved (a disproof of any one refutes), each
                // unconditionally
                let got = match &c.c1 {
                Verdict::Disproved(_) if !c.conditional && !c.geometry_conditional => false,
                Verdict::Proved if !c.conditional && !c.geometry_conditional => true,
                Verdict::Proved | Verdict::Disproved(_) => {
                    return Err(Error::Undecided(format!(
                        "n = {n}: the certificate is {} only given a premise confirmed to interval overlap (not exactly): no unconditional proof",
                        c.c1.word()
                    )))
                }
                Verdict::NotProved(why) => return Err(Error::Undecided(format!("n = {n}: certificate NOT PROVED ({why})"))),
            };
                let bound = c.min_jacobian_lower_bound.map(|b| format!(", Jacobian ≥ {b:.4e}")).unwrap_or_default();
                Ok((
                    got == *expect,
                    if *expect { "proved regular and injective".into() } else { "disproved".into() },
                    format!(
                        "certified spectrum {}, regularity {}, injectivity {} (winding {}{bound})",
                        c.spectrum.verdict.word(),
                        c.regularity.display(),
                        c.injectivity.display(),
                        c.winding_number.map(|w| w.to_string()).unwrap_or_else(|| "-".into())
                    ),
                ))
            })
        }
        Check::CharacteristicMap { subject, expect, levels, resolution, certified: false } => {
            over_independent_valences(subject, |subject, n| {
                let (scheme, config) = subject_config(subject, n)?;
                let opts = crate::charmap::CharMapOptions {
                    levels: levels.unwrap_or(3),
                    resolution: resolution.unwrap_or(256),
                    display_levels: None,
                };
                let m = crate::charmap::characteristic_map(scheme.as_ref(), &config, &opts)?;
                let good = m.regular && m.injective;
                let what = format!(
                    "{}, {} (winding {}, overlap pixels {}, min Jacobian ratio {})",
                    if m.regular { "regular" } else { "not regular" },
                    if m.injective { "injective" } else { "not injective" },
                    m.winding_number.map(|w| w.to_string()).unwrap_or_else(|| "-".into()),
                    m.overlap_pixels.map(|w| w.to_string()).unwrap_or_else(|| "-".into()),
                    m.min_jacobian_ratio.map(fmt_f).unwrap_or_else(|| "-".into()),
                );
                let what = if m.reasons.is_empty() { what } else { format!("{what}: {}", m.explanation) };
                Ok((
                    good == *expect,
                    if *expect { "regular and injective".into() } else { "not regular and injective".into() },
                    what,
                ))
            })
        }
        Check::SpectralC1 { subject, expect, certified: true } => {
            let names = cache.certificate_names();
            over_independent_valences(subject, |subject, n| {
                let (scheme, config) = subject_config(subject, n)?;
                let options = crate::spectrum::Options { neighbourhood: kind_of(subject)?, method: None, exact: false };
                let analysis = crate::spectrum::analyse(scheme.as_ref(), &config, &options)?;
                let c = crate::certify::certify_analysis(scheme.as_ref(), &analysis)?;
                if let Some(path) = names.path(subject, n) {
                    crate::certify::export::write_spectrum(&path, scheme.as_ref(), &analysis, &c)?;
                }
                let got = match &c.verdict {
                crate::certify::Verdict::Proved if !c.conditional => true,
                crate::certify::Verdict::Disproved(_) if !c.conditional => false,
                // a verdict resting on identities checked only to interval
                // overlap, or no proof: the claim asked for one
                crate::certify::Verdict::Proved | crate::certify::Verdict::Disproved(_) => {
                    return Err(Error::Undecided(format!(
                        "n = {n}: certified {} only given the premises the enclosures confirm to interval overlap (not exactly): no unconditional proof",
                        c.verdict.word()
                    )))
                }
                crate::certify::Verdict::NotProved(why) => {
                    return Err(Error::Undecided(format!("n = {n}: certificate NOT PROVED ({why})")))
                }
            };
                let gap = c.margins.gap_lower_bound.map(|g| format!(", gap ≥ {g:.6e}")).unwrap_or_default();
                Ok((
                    got == *expect,
                    if *expect { "proved".into() } else { "disproved".into() },
                    format!("certified {}{gap}", c.verdict.display()),
                ))
            })
        }
        Check::SpectralC1 { subject, expect, .. } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                let got = spec.verdict.c1_spectral;
                let why = spec.verdict.reasons.iter().find(|r| r.contains("not") || r.contains("defective")).cloned();
                Ok((
                    got == *expect,
                    if *expect { "passes".into() } else { "fails".into() },
                    format!(
                        "{}{}",
                        if got { "passes" } else { "fails" },
                        why.map(|w| format!(": {w}")).unwrap_or_default()
                    ),
                ))
            })
        }
        Check::LimitStencil { subject, weights } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                let env = env_for(subject, n)?;
                let l = limit_stencil(&spec)?;
                let mut worst = (0.0f64, String::new());
                for (k, lab) in spec.labels.iter().enumerate() {
                    // a whole label name (`edge[r1,s2,0]`) before its kind and ring
                    let want = match weights.get(&lab.name).or_else(|| weights.get(&selector(lab.kind, lab.ring))) {
                        Some(e) => eval_real(e, &env)?,
                        None => 0.0,
                    };
                    let d = (l[k] - want).abs();
                    if d > worst.0 {
                        worst = (d, format!("{}: computed {}, stated {}", lab.name, fmt_f(l[k]), fmt_f(want)));
                    }
                }
                if let Some(key) =
                    weights.keys().find(|k| k.contains('[') && !spec.labels.iter().any(|l| &l.name == *k))
                {
                    return Err(Error::Claim(format!("'{key}' names no vertex of the neighbourhood at n = {n}")));
                }
                let stated = weights.iter().map(|(k, v)| format!("{k} = {v}")).collect::<Vec<_>>().join(", ");
                let ok = worst.0 < 1e-9;
                Ok((ok, stated, if ok { "every weight as stated".into() } else { worst.1 }))
            })
        }
        Check::TangentStencils { subject, cos, sin } => {
            cache.prefetch(subject);
            over_valences(subject, |subject, n| {
                let spec = cache.spectrum(subject, n)?;
                let t = tangent_stencils(&spec)?;
                let mut basis = vec![vec![0.0; spec.labels.len()]; 2];
                for (k, lab) in spec.labels.iter().enumerate() {
                    let mut env = env_for(subject, n)?;
                    env.insert("s".into(), ParamValue::from_ratio(lab.sector as i64, 1));
                    for (b, map) in [cos, sin].iter().enumerate() {
                        if let Some(e) = map.get(&selector(lab.kind, lab.ring)) {
                            basis[b][k] = eval_real(e, &env)?;
                        }
                    }
                }
                let ok = t.len() == 2 && t.iter().all(|v| in_span(&basis, v)) && basis.iter().all(|v| in_span(&t, v));
                Ok((
                    ok,
                    "span of the stated cos/sin stencils".into(),
                    format!("{} tangent stencils, {}", t.len(), if ok { "same span" } else { "different span" }),
                ))
            })
        }
        Check::Identity { lhs, rhs, vars, valences } => {
            let (l, r) = (Expr::parse(lhs)?, Expr::parse(rhs)?);
            let Some(valences) = valences else {
                let env = define(Env::new(), vars.iter().collect())?;
                let (ok, computed, exact) = identity_at(&l, &r, lhs, rhs, &env)?;
                return Ok(Partial {
                    verdict: if ok { Verdict::Holds } else { Verdict::Refuted },
                    stated: format!("{lhs} = {rhs}"),
                    computed,
                    detail: if exact { "exact rational arithmetic" } else { "floating point (relative 1e-12)" }.into(),
                });
            };
            // a statement in n: the identity at every listed valence, with
            // n (alias k) defined and the vars expressions in n
            let subject = valences_only(valences, vars);
            let mut modes = (0, 0);
            let mut p = over_valences(&subject, |subject, n| {
                let (ok, computed, exact) = identity_at(&l, &r, lhs, rhs, &env_for(&subject, n)?)?;
                if exact {
                    modes.0 += 1;
                } else {
                    modes.1 += 1;
                }
                Ok((ok, format!("{lhs} = {rhs}"), computed))
            })?;
            p.detail = format!(
                "{}; {} valences in exact rational arithmetic, {} in floating point (relative 1e-12)",
                p.detail, modes.0, modes.1
            );
            Ok(p)
        }
        Check::MatrixEigenvalues { valences, vars, rows, values } => {
            let subject = valences_only(valences, vars);
            over_valences(&subject, |subject, n| {
                let env = env_for(&subject, n)?;
                let cols = rows.first().map(|r| r.len()).unwrap_or(0);
                if rows.iter().any(|r| r.len() != cols) || rows.len() != cols {
                    return Ok((
                        false,
                        format!("{} stated eigenvalues", values.len()),
                        format!(
                            "the printed matrix is not square ({} rows, column counts {:?})",
                            rows.len(),
                            rows.iter().map(|r| r.len()).collect::<Vec<_>>()
                        ),
                    ));
                }
                let mut m = faer::Mat::<Complex64>::zeros(cols, cols);
                for (i, r) in rows.iter().enumerate() {
                    for (j, e) in r.iter().enumerate() {
                        m[(i, j)] = eval(e, &env)?;
                    }
                }
                let mut computed: Vec<Complex64> = eigen::block_eigen(&m)?
                    .into_iter()
                    .flat_map(|e| std::iter::repeat_n(e.value, e.algebraic))
                    .collect();
                computed.sort_by(|a, b| eigenvalue_order(*a, *b));
                let mut stated = stated_values(values, &env)?;
                stated.sort_by(|a, b| eigenvalue_order(*a, *b));
                let (missing, extra) = unmatched(&stated, &computed);
                let ok = missing.is_empty() && extra.is_empty();
                let why = if ok {
                    String::new()
                } else {
                    format!(
                        " (stated but not found: {}; found but not stated: {})",
                        show_list(&missing),
                        show_list(&extra)
                    )
                };
                Ok((ok, show_list(&stated), format!("{}{why}", show_list(&computed))))
            })
        }
        Check::LatticeMatrix { scheme, window, scale, rows } => {
            let s = registry::lattice(scheme, &[])?;
            let [i0, i1, j0, j1] = *window;
            check_window(*window)?;
            if rows.is_empty() {
                return Err(Error::Claim("no printed rows: nothing to compare".into()));
            }
            let w = lattice::Window::rect(i0, i1, j0, j1);
            let assembled = lattice::local_matrix::<crate::numeric::Rational>(s.as_ref(), &w)?;
            let scale = Expr::parse(scale)?
                .exact(&Env::new())
                .ok_or_else(|| Error::Claim("the scale must be an exact rational".into()))?;
            let printed: Vec<Vec<crate::numeric::Rational>> = rows
                .iter()
                .map(|r| {
                    r.split_whitespace()
                        .map(|x| Expr::parse(x).ok().and_then(|e| e.exact(&Env::new())).map(|q| q * scale.clone()))
                        .collect::<Option<Vec<_>>>()
                        .ok_or_else(|| Error::Claim(format!("row '{r}' is not a list of numbers")))
                })
                .collect::<Result<_, _>>()?;
            if printed.len() != assembled.len() || printed.iter().any(|r| r.len() != assembled.len()) {
                return Ok(Partial {
                    verdict: Verdict::Refuted,
                    stated: format!("{} printed rows", printed.len()),
                    computed: format!("{}×{} assembled", assembled.len(), assembled.len()),
                    detail: "the printed matrix has the wrong shape".into(),
                });
            }
            let mut diffs = Vec::new();
            for (i, (p, a)) in printed.iter().zip(&assembled).enumerate() {
                for (j, (x, y)) in p.iter().zip(a).enumerate() {
                    if x != y {
                        diffs.push(format!("({},{}): printed {x}, rules give {y}", i + 1, j + 1));
                    }
                }
            }
            let n = assembled.len();
            Ok(Partial {
                verdict: if diffs.is_empty() { Verdict::Holds } else { Verdict::Refuted },
                stated: format!("{n}×{n} printed matrix"),
                computed: if diffs.is_empty() {
                    "every entry as printed".into()
                } else {
                    format!("{} entries differ", diffs.len())
                },
                detail: if diffs.is_empty() {
                    "entry by entry, exact".into()
                } else {
                    diffs.iter().take(12).cloned().collect::<Vec<_>>().join("; ")
                },
            })
        }
        // the message names the claim file and line
        Check::Malformed(m) => Err(Error::File(m.clone())),
        Check::Curvature { subject, class, c2, fourier, levels } => {
            let (verdict, stated, computed, detail) =
                super::curvature::run(subject, class, *c2, fourier.as_deref(), *levels)?;
            Ok(Partial { verdict, stated, computed, detail })
        }
        Check::Builtin { name, data } => {
            let (verdict, stated, computed, detail) = super::builtin::run(name, data.as_ref())?;
            Ok(Partial { verdict, stated, computed, detail })
        }
    }
}

/// Most points of a printed lattice window (i fastest): matrices of that size
/// are assembled exactly, so the window is bounded like every other input.
pub const MAX_WINDOW_POINTS: i64 = 1024;

/// A window [i0, i1] × [j0, j1]: non-empty and at most [`MAX_WINDOW_POINTS`].
pub fn check_window([i0, i1, j0, j1]: [i64; 4]) -> Result<(), Error> {
    if i0 > i1 || j0 > j1 {
        return Err(Error::Claim(format!(
            "the window [{i0}, {i1}, {j0}, {j1}] is empty (it must have i0 <= i1 and j0 <= j1)"
        )));
    }
    let points = (i1 as i128 - i0 as i128 + 1) * (j1 as i128 - j0 as i128 + 1);
    if points > MAX_WINDOW_POINTS as i128 {
        return Err(Error::Claim(format!(
            "the window [{i0}, {i1}, {j0}, {j1}] has {points} points; at most {MAX_WINDOW_POINTS} are supported"
        )));
    }
    Ok(())
}

/// Most stated values of one claim, counting repeats.
pub const MAX_STATED_VALUES: usize = 100_000;

/// Stated values; an entry "EXPR ; COUNT" stands for COUNT copies of EXPR.
fn stated_values(values: &[String], env: &Env) -> Result<Vec<Complex64>, Error> {
    let mut out = Vec::new();
    for v in values {
        let (e, count) = match v.split_once(';') {
            Some((e, c)) => {
                let k = eval_real(c, env)?.round();
                if !(0.0..=100_000.0).contains(&k) {
                    return Err(Error::Claim(format!("repeat count of '{v}' is {k}")));
                }
                (e, k as usize)
            }
            None => (v.as_str(), 1),
        };
        if out.len() + count > MAX_STATED_VALUES {
            return Err(Error::Claim(format!("more than {MAX_STATED_VALUES} stated values (counting repeats)")));
        }
        let z = eval(e, env)?;
        out.extend(std::iter::repeat_n(z, count));
    }
    Ok(out)
}

/// "centre", or "kind.ring" such as "fcv.1".
fn selector(kind: VertexKind, ring: usize) -> String {
    match kind {
        VertexKind::Centre => "centre".into(),
        k => format!("{}.{ring}", crate::neighbourhood::labels::kind_name(k)),
    }
}

fn in_span(basis: &[Vec<f64>], v: &[f64]) -> bool {
    v.iter().any(|x| *x != 0.0) && crate::spectrum::stencils::span_residual(basis, v) < 1e-8
}

/// A subject with valences and variables only: the statements in n that
/// analyse no scheme (identities, typed matrices) range over it.
fn valences_only(valences: &Valences, vars: &BTreeMap<String, String>) -> Subject {
    Subject {
        scheme: String::new(),
        valences: valences.clone(),
        faces: Vec::new(),
        params: Default::default(),
        neighbourhood: None,
        vars: vars.clone(),
    }
}
