//! A statement about several configurations, decided from one comparison
//! per configuration: the first disagreement refutes, an undecided
//! configuration leaves the claim INCONCLUSIVE unless another refutes it,
//! and a malformed value at any configuration makes it an ERROR. Also the
//! one place where an error's variant becomes a claim's verdict
//! ([`undecided`], [`engine_failure_undecided`]). Shared by every check
//! plug-in; imports none of them.

use crate::claims::schedule;
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;

/// Whether an error leaves the claim INCONCLUSIVE: only `Error::Undecided`
/// (a computation that ran on valid input and did not decide: a proof not
/// found, a quantity not computed for this configuration). Every other error
/// (a malformed or vacuous claim, a missing or misspelt scheme file, an
/// unknown scheme or parameter, a value of the wrong kind) says the claim
/// cannot be read as written: ERROR, which no recorded verdict can pass.
pub fn undecided(e: &Error) -> bool {
    matches!(e, Error::Undecided(_))
}

/// What an error of the engine means for a claim, applied where a plug-in's
/// result is read (per configuration, and for the claim as a whole): a
/// numerical stage that failed on valid input (`Numeric`), a point the
/// control points at hand do not determine (`NotDetermined`) or a stage's
/// plain `Message` is a computation that did not decide the claim, so it
/// becomes `Error::Undecided` with the same message. The claims' own errors
/// say what they are already (`Claim` for malformed data, `Undecided`) and
/// pass unchanged, as do `Input`, `File` and `Write`.
pub fn engine_failure_undecided(e: Error) -> Error {
    match e {
        Error::Numeric(m) | Error::NotDetermined(m) | Error::Message(m) => Error::Undecided(m),
        other => other,
    }
}

/// What a per-configuration comparison gives: whether it agrees, the stated
/// and the computed value.
pub type Comparison = Result<(bool, String, String), Error>;

/// Runs a per-valence comparison and reports the first valence where it fails.
pub fn over_valences(subject: &Subject, mut one: impl FnMut(&Subject, usize) -> Comparison) -> Result<Finding, Error> {
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
pub fn over_independent_valences(
    subject: &Subject,
    one: impl Fn(&Subject, usize) -> Comparison + Sync,
) -> Result<Finding, Error> {
    let configurations = subject.configurations()?;
    let results = schedule::each_configuration(&configurations, one);
    summarise(&configurations, results)
}

/// The verdict from the comparison at each configuration (in order): HOLDS
/// when all agree, REFUTED at the first that disagrees, and no verdict when
/// nothing disagrees but a configuration could not be decided.
fn summarise(configurations: &[(usize, Subject)], results: Vec<Comparison>) -> Result<Finding, Error> {
    let name = |s: &Subject, n: usize| match s.faces_for(n) {
        Some(f) => format!("n={n} ({f})"),
        None => format!("n={n}"),
    };
    // a malformed value at any configuration makes the claim an ERROR,
    // whatever the others give: the claim cannot be read as written
    let mut results: Vec<Comparison> = results.into_iter().map(|r| r.map_err(engine_failure_undecided)).collect();
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
        None => Finding::new(true, stated0, computed0, format!("agrees at {span}")),
        Some((short, label, s, c)) => Finding::new(
            false,
            format!("{short}: {s}"),
            format!("{short}: {c}"),
            format!("first disagreement at {label} ({span}){also}"),
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The variant is the decision: only `Undecided` is INCONCLUSIVE; the
    /// engine's failures on valid input become `Undecided` with their
    /// message; malformed data (`Claim`), a bad request (`Input`) or file
    /// (`File`) stay what they are and so are ERROR.
    #[test]
    fn only_undecided_is_inconclusive_and_engine_failures_become_undecided() {
        for e in [
            Error::Numeric("no convergence".into()),
            Error::NotDetermined("a vertex".into()),
            Error::Message("x".into()),
        ] {
            let text = e.to_string();
            let typed = engine_failure_undecided(e.clone());
            assert_eq!(typed, Error::Undecided(text));
            assert!(!undecided(&e) && undecided(&typed));
        }
        for e in
            [Error::Claim("data.lo is missing".into()), Error::Input("unknown scheme".into()), Error::File("f".into())]
        {
            assert_eq!(engine_failure_undecided(e.clone()), e);
            assert!(!undecided(&e));
        }
    }

    /// A malformed value at one configuration makes the claim an ERROR even
    /// when another configuration refutes it; an undecided one does not
    /// hide a refutation.
    #[test]
    fn summarise_ranks_malformed_over_refuted_over_undecided() {
        let subject = Subject::valences_only(&crate::claims::subject::Valences::List(vec![3, 4]), &Default::default());
        let configurations = subject.configurations().unwrap();
        let refuted: Comparison = Ok((false, "1".into(), "2".into()));
        let malformed = summarise(&configurations, vec![Err(Error::Claim("bad".into())), refuted.clone()]);
        assert_eq!(malformed, Err(Error::Claim("bad".into())));
        let f = summarise(&configurations, vec![Err(Error::Numeric("stage".into())), refuted]).unwrap();
        assert!(!f.holds);
        assert!(f.detail.contains("n = 3 not decided: stage"), "{}", f.detail);
        let only_undecided =
            summarise(&configurations, vec![Err(Error::Numeric("stage".into())), Ok((true, "".into(), "".into()))]);
        assert_eq!(only_undecided, Err(Error::Undecided("stage".into())));
    }
}
