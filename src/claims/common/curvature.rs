//! The second-order analysis of one configuration as the claims read it
//! (`check = "curvature"`, and the second route of a `parameter-range`
//! claim about curvature at its witness): the class of `subdlab curvature`
//! (exact comparison of |μ| and λ² where both read as rationals) and, where
//! the class hinges on a Jordan block at λ² (|μ| = λ²), the floating-point
//! Jordan structure confirmed by the growth test of `curvature::jordan` and,
//! where S is rational, by the exact nullities of S − λ²I and (S − λ²I)².
//! Shared so that both plug-ins run one route, not two copies of it.

use crate::claims::common::spectra::subject_config;
use crate::claims::subject::Subject;
use crate::curvature::jordan::{exact_jordan, growth_test, ExactJordan, GrowthTest};
use crate::curvature::{
    curvature_of_analysis, Curvature as SecondOrder, CurvatureClass, CurvatureOptions, Evidence, EIG_TOL,
};
use crate::error::Error;
use crate::neighbourhood::NeighbourhoodKind;
use crate::numeric::Rational;
use crate::spectrum::{analyse_shared, fmt_f, Options};

/// One valence: the analysis and the second routes.
pub struct Computed {
    pub c: SecondOrder,
    pub growth: Option<Result<GrowthTest, Error>>,
    pub exact: Option<ExactJordan>,
}

/// The analysis of the subject at valence n (exact when λ and μ read as
/// small rationals, as `subdlab curvature` does), with the second routes
/// when |μ| = λ².
pub fn compute(subject: &Subject, n: usize, levels: usize) -> Result<Computed, Error> {
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
pub fn evidence(k: &Computed) -> (String, Option<bool>) {
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

/// The class at one configuration with its evidence, the Jordan structure
/// at λ² (where the class hinges on it) confirmed by the second routes:
/// `Error::Undecided` when they disagree.
pub fn confirmed_class(subject: &Subject, n: usize) -> Result<(CurvatureClass, String), Error> {
    let k = compute(subject, n, crate::curvature::DEFAULT_LEVELS)?;
    let (ev, agree) = evidence(&k);
    if agree == Some(false) {
        return Err(Error::Undecided(format!(
            "{}: the routes to the Jordan structure at λ² disagree, so the class ({}) is not decided: {ev}",
            subject.label(n),
            k.c.class.name()
        )));
    }
    Ok((k.c.class, ev))
}
