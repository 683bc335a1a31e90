//! The `curvature` check: a stated curvature class (and optionally the
//! outcome of Reif's C² test and the Fourier index set F(μ)) against the
//! second-order analysis of `subdlab curvature` (`crate::curvature`).
//!
//! Where the class hinges on a Jordan block at λ² (|μ| = λ²), the
//! floating-point Jordan structure (cluster sizes against SVD null spaces,
//! chain tops sampled on the ring) is confirmed by a second route before it
//! decides anything: the growth test of `curvature::jordan` (projected
//! iteration, and the limit of the growing direction level by level), and,
//! where S is rational, the exact nullities of S − λ²I and (S − λ²I)². When
//! the routes disagree the claim is INCONCLUSIVE with both.

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::spectra::{subject_config, Cache};
use crate::claims::common::values::{env_for, eval};
use crate::claims::schedule;
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::curvature::jordan::{exact_jordan, growth_test, ExactJordan, GrowthTest};
use crate::curvature::{curvature_of_analysis, Curvature as SecondOrder, CurvatureOptions, Evidence, EIG_TOL};
use crate::error::Error;
use crate::neighbourhood::NeighbourhoodKind;
use crate::numeric::Rational;
use crate::spectrum::{analyse_shared, fmt_f, Options};

/// `class = "bounded"` or `class = ["zero", "bounded"]` (any of them).
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum ClassSpec {
    One(String),
    Any(Vec<String>),
}

/// An entry of a stated F(μ): an integer or an expression in n ("n-2").
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum FourierEntry {
    Int(i64),
    Expr(String),
}

/// The second-order analysis (`subdlab curvature`): the curvature class
/// (one name or a list of admissible names: zero, bounded, unbounded,
/// not-applicable), optionally whether Reif's C² test passes (`c2`) and
/// the Fourier index set F(μ) (`fourier`, integers or expressions in n
/// such as "n-2"); `levels` refines the ring samples (default 3).
#[derive(Clone, Debug, Deserialize)]
pub struct CurvatureCheck {
    #[serde(flatten)]
    pub subject: Subject,
    pub class: ClassSpec,
    #[serde(default)]
    pub c2: Option<bool>,
    #[serde(default)]
    pub fourier: Option<Vec<FourierEntry>>,
    #[serde(default)]
    pub levels: Option<usize>,
}

impl CheckKind for CurvatureCheck {
    const KEYS: &'static [&'static str] = &["class", "c2", "fourier", "levels"];

    fn evaluate(&self, _cache: &mut Cache) -> Result<Finding, Error> {
        run(&self.subject, &self.class, self.c2, self.fourier.as_deref(), self.levels)
    }
}

const CLASSES: &[&str] = &["zero", "bounded", "unbounded", "not-applicable"];

impl ClassSpec {
    fn names(&self) -> Result<Vec<String>, Error> {
        let v = match self {
            ClassSpec::One(s) => vec![s.clone()],
            ClassSpec::Any(v) => v.clone(),
        };
        if v.is_empty() {
            return Err(Error::Claim("class: at least one class must be given".into()));
        }
        for c in &v {
            if !CLASSES.contains(&c.as_str()) {
                return Err(Error::Claim(format!("class '{c}': the classes are {}", CLASSES.join(", "))));
            }
        }
        Ok(v)
    }
}

/// One valence: the analysis and the second routes.
struct Computed {
    c: SecondOrder,
    growth: Option<Result<GrowthTest, Error>>,
    exact: Option<ExactJordan>,
}

/// The analysis of the subject at valence n (exact when λ and μ read as
/// small rationals, as `subdlab curvature` does), with the second routes
/// when |μ| = λ².
fn compute(subject: &Subject, n: usize, levels: usize) -> Result<Computed, Error> {
    if subject.neighbourhood.as_deref().is_some_and(|k| k != "analysis") {
        return Err(Error::Claim(
            "the curvature check uses the analysis neighbourhood; leave 'neighbourhood' out".into(),
        ));
    }
    subject.refuse_tag("the curvature check")?;
    let (scheme, config) = subject_config(subject, n)?;
    let opts = CurvatureOptions { levels, ..CurvatureOptions::default() };
    let options = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let mut analysis = analyse_shared(scheme.as_ref(), &config, &options)?;
    let mut c = curvature_of_analysis(scheme.as_ref(), &analysis, &opts)?;
    let readable = |x: f64| crate::numeric::recognise::recognise(x).is_some();
    let rational = analysis.spectrum.eigenvalues.get(1).is_some_and(|e| e.recognised.is_some())
        && c.mu.as_ref().is_some_and(|m| m.im == 0.0 && readable(m.re));
    if rational {
        analysis = analyse_shared(scheme.as_ref(), &config, &Options { exact: true, ..options })?;
        c = curvature_of_analysis(scheme.as_ref(), &analysis, &opts)?;
    }
    let at_lambda2 = c.mu_over_lambda_squared.is_some_and(|r| (r - 1.0).abs() <= EIG_TOL);
    let (mut growth, mut exact) = (None, None);
    if at_lambda2 {
        let lambda = c.lambda.ok_or_else(|| Error::Undecided("no subdominant eigenvalue".into()))?;
        growth = Some(growth_test(scheme.as_ref(), &analysis, lambda, levels, 5));
        let lambda_exact = analysis.spectrum.eigenvalues.get(1).and_then(|e| e.exact.as_deref()).and_then(parse_q);
        if let Some(l) = lambda_exact {
            exact = exact_jordan(&analysis, &(l.clone() * l));
        }
    }
    Ok(Computed { c, growth, exact })
}

fn parse_q(s: &str) -> Option<Rational> {
    let (p, q) = s.split_once('/').unwrap_or((s, "1"));
    let (p, q): (num_bigint::BigInt, num_bigint::BigInt) = (p.trim().parse().ok()?, q.trim().parse().ok()?);
    (q != num_bigint::BigInt::from(0)).then(|| Rational::new(p, q))
}

/// The float route's finding at λ²: (defective, a chain top shows on the ring).
fn float_jordan(c: &SecondOrder) -> (bool, bool, String) {
    let Some(l2) = c.lambda_squared else { return (false, false, String::new()) };
    let at: Vec<_> = c.examined.iter().filter(|e| (e.modulus - l2).abs() <= EIG_TOL * l2 && !e.vanishes).collect();
    let defective = at.iter().any(|e| e.defective);
    let visible = at.iter().any(|e| e.jordan_visible == Some(true));
    let text = at
        .iter()
        .map(|e| {
            format!(
                "{} algebraic {} geometric {}{}",
                fmt_f(e.re),
                e.algebraic_multiplicity,
                e.geometric_multiplicity,
                match e.jordan_visible {
                    Some(true) => ", chain tops show on the ring",
                    Some(false) => ", chain tops vanish on the ring",
                    None => "",
                }
            )
        })
        .collect::<Vec<_>>()
        .join("; ");
    (defective, visible, text)
}

/// The evidence of one valence, and whether the routes agree on the Jordan
/// structure at λ² (None: the class does not hinge on it).
fn evidence(k: &Computed) -> (String, Option<bool>) {
    let c = &k.c;
    let mut parts = vec![match c.evidence {
        Evidence::Exact => "|μ| against λ² compared exactly (both proven rational roots)".to_string(),
        Evidence::FloatingPoint => format!(
            "|μ| against λ² in floating point (relative tolerance {EIG_TOL:e}; |μ|/λ² = {})",
            c.mu_over_lambda_squared.map(fmt_f).unwrap_or_else(|| "-".into())
        ),
        Evidence::None => "no second-order comparison (first-order test fails)".to_string(),
    }];
    let Some(growth) = &k.growth else { return (parts.join("; "), None) };
    let (defective, visible, text) = float_jordan(c);
    parts.push(format!(
        "Jordan structure at λ²: (a) floating-point multiplicities (cluster size against the SVD null space of B − λ²I per Fourier block; chain tops refined {} levels on the ring): {}",
        c.levels,
        if text.is_empty() { "no eigenfunction of λ² on the ring".into() } else { text }
    ));
    let float_says = defective && visible;
    let agree = match growth {
        Ok(g) => {
            parts.push(format!("(b) {}", g.explanation));
            let growth_says = g.grows && g.top_visible == Some(true);
            let undecided = g.grows && g.top_visible.is_none();
            !undecided && growth_says == float_says
        }
        Err(e) => {
            parts.push(format!("(b) growth test not run: {e}"));
            false
        }
    };
    let mut agree = agree;
    if let Some(x) = &k.exact {
        parts.push(format!(
            "(c) exact: S − ({})I on the rational {}×{} S has nullity {}, its square {} ({})",
            x.eigenvalue,
            x.size,
            x.size,
            x.nullity,
            x.nullity_squared,
            if x.defective { "a Jordan block" } else { "no Jordan block" }
        ));
        if x.defective != defective {
            agree = false;
        }
    }
    (parts.join("; "), Some(agree))
}

/// A stated F(μ) at valence n, reduced mod the group order, sorted.
fn stated_fourier(subject: &Subject, n: usize, entries: &[FourierEntry], g: usize) -> Result<Vec<usize>, Error> {
    let env = env_for(subject, n)?;
    let mut out = Vec::new();
    for e in entries {
        let v = match e {
            FourierEntry::Int(i) => *i,
            FourierEntry::Expr(s) => {
                let z = eval(s, &env)?;
                if (z.re - z.re.round()).abs() > 1e-9 || z.im.abs() > 1e-9 {
                    return Err(Error::Claim(format!("fourier entry '{s}' is not an integer at n = {n}")));
                }
                z.re.round() as i64
            }
        };
        out.push(v.rem_euclid(g as i64) as usize);
    }
    out.sort_unstable();
    out.dedup();
    Ok(out)
}

/// The class (and C² test, F(μ)) at every configuration, the analyses side
/// by side: REFUTED at the first configuration that disagrees.
fn run(
    subject: &Subject,
    class: &ClassSpec,
    c2: Option<bool>,
    fourier: Option<&[FourierEntry]>,
    levels: Option<usize>,
) -> Result<Finding, Error> {
    let classes = class.names()?;
    let levels = levels.unwrap_or(crate::curvature::DEFAULT_LEVELS);
    let configurations = subject.configurations()?;
    if configurations.is_empty() {
        return Err(Error::Claim("no valences given".into()));
    }
    let mut stated_all = Vec::new();
    let mut computed_all = Vec::new();
    let mut details = Vec::new();
    let mut refuted: Option<String> = None;
    // the analyses side by side (each reads only its configuration); the
    // verdict is drawn from them in order, as from a sequential run: the
    // first configuration that fails to compute or to decide ends it
    let analyses = schedule::each_configuration(&configurations, |s, n| compute(s, n, levels));
    for ((n, subject), k) in configurations.iter().zip(analyses) {
        let (n, subject) = (*n, subject);
        // "n = 5", or "n = 5 (QQTQT)" for a face sequence
        let label = subject.label(n);
        let k = k?;
        let c = &k.c;
        let (ev, agree) = evidence(&k);
        if agree == Some(false) {
            return Err(Error::Undecided(format!(
                "{label}: the routes to the Jordan structure at λ² disagree, so the class ({}) is not decided: {ev}",
                c.class.name()
            )));
        }
        let mut stated = vec![format!("class {}", classes.join(" or "))];
        let mut computed = vec![format!("class {}", c.class.name())];
        let mut wrong = Vec::new();
        if !classes.iter().any(|s| s == c.class.name()) {
            wrong.push(format!("class: stated {}, computed {}", classes.join(" or "), c.class.name()));
        }
        if let Some(want) = c2 {
            let got = c.c2.as_ref().is_some_and(|t| t.holds);
            stated.push(format!("C² test {}", if want { "passes" } else { "fails" }));
            let why =
                c.c2.as_ref()
                    .and_then(|t| t.reasons.first().cloned())
                    .unwrap_or_else(|| "not run: the first-order test fails".into());
            computed.push(format!("C² test {}", if got { "passes" } else { "fails" }));
            if got != want {
                wrong.push(format!(
                    "C² test: stated {}, computed {} ({why})",
                    if want { "passes" } else { "fails" },
                    if got { "passes" } else { "fails" }
                ));
            }
        }
        if let Some(entries) = fourier {
            let Some(sh) = &c.shapes else {
                return Err(Error::Undecided(format!(
                    "{label}: F(μ) is not computed here (class {}; F(μ) needs a rotation-symmetric configuration and an eigenvalue μ with an eigenfunction on the ring)",
                    c.class.name()
                )));
            };
            let want = stated_fourier(subject, n, entries, sh.group_order)?;
            stated.push(format!("F(μ) = {want:?}"));
            computed.push(format!("F(μ) = {:?}", sh.fourier_index));
            if want != sh.fourier_index {
                wrong.push(format!(
                    "F(μ): stated {want:?}, computed {:?} (blocks mod {})",
                    sh.fourier_index, sh.group_order
                ));
            }
        }
        let mu = c.mu.as_ref().map(|m| {
            format!(
                ", λ = {}, |μ| = {}, |μ|/λ² = {}",
                c.lambda.map(fmt_f).unwrap_or_default(),
                fmt_f(m.modulus),
                c.mu_over_lambda_squared.map(fmt_f).unwrap_or_default()
            )
        });
        let line = format!("n={n}: {}{}", c.class.name(), mu.unwrap_or_default());
        if stated_all.is_empty() || (!wrong.is_empty() && refuted.is_none()) {
            // the first valence, replaced by the first disagreement
            stated_all = vec![format!("n={n}: {}", stated.join(", "))];
            computed_all = vec![format!("n={n}: {}", computed.join(", "))];
        }
        if !wrong.is_empty() && refuted.is_none() {
            let reason = c.reasons.first().cloned().unwrap_or_default();
            refuted = Some(format!("{label}: {} ({reason}); evidence: {ev}", wrong.join("; ")));
        }
        details.push(format!("{line} [{ev}]"));
    }
    let lo = configurations.iter().map(|(n, _)| *n).min().unwrap_or(0);
    let hi = configurations.iter().map(|(n, _)| *n).max().unwrap_or(0);
    let span = if lo != hi {
        format!("valences {lo}..{hi} ({} checked)", configurations.len())
    } else if configurations.len() > 1 {
        format!("valence {lo} ({} configurations)", configurations.len())
    } else {
        format!("valence {lo}")
    };
    const SHOWN: usize = 4;
    let mut summary: Vec<String> = details.iter().take(SHOWN).cloned().collect();
    if details.len() > SHOWN {
        summary.push(format!("… ({} valences in all)", details.len()));
    }
    Ok(match refuted {
        None => Finding::new(
            true,
            stated_all.first().cloned().unwrap_or_default(),
            computed_all.first().cloned().unwrap_or_default(),
            format!("agrees at {span}: {}", summary.join(" | ")),
        ),
        Some(why) => Finding::new(
            false,
            stated_all.join("; "),
            computed_all.join("; "),
            format!("first disagreement at {why} ({span})"),
        ),
    })
}
