//! The `curvature` check: a stated curvature class (and optionally the
//! outcome of Reif's C² test and the Fourier index set F(μ)) against the
//! second-order analysis of `subdlab curvature` (`crate::curvature`).
//!
//! Where the class hinges on a Jordan block at λ² (|μ| = λ²), the
//! floating-point Jordan structure (cluster sizes against SVD null spaces,
//! chain tops sampled on the ring) is confirmed by a second route before it
//! decides anything: the growth test of `curvature::jordan` (projected
//! iteration, and the limit of the growing direction level by level), and,
//! where S is rational, the exact nullities of S − λ²I and (S − λ²I)²
//! (`claims::common::curvature`, shared with `parameter-range`). When the
//! routes disagree the claim is INCONCLUSIVE with both.

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::curvature::{compute, evidence};
use crate::claims::common::spectra::Cache;
use crate::claims::common::values::{env_for, eval};
use crate::claims::schedule;
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::spectrum::fmt_f;

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
