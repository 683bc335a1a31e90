//! Evaluating claim files: files side by side on worker threads with large
//! stacks, the claims of a file in turn sharing its analyses, each claim's
//! check dispatched to its kind (`checks::Check::evaluate`) and its result
//! or error turned into the claim's [`Outcome`]: a [`Finding`] is HOLDS or
//! REFUTED, `Error::Undecided` INCONCLUSIVE, any other error ERROR.

use crate::claims::checks::Check;
use crate::claims::claim::{Claim, ClaimFile};
use crate::claims::common::configurations::{engine_failure_undecided, undecided};
use crate::claims::common::spectra::Cache;
use crate::claims::schedule::EVALUATION_STACK;
use crate::claims::verdict::{Finding, Outcome, Verdict};
use crate::error::Error;

/// Evaluate several files side by side (papers are independent; each has its
/// own cache of analyses), on at most one worker per core. Workers have large
/// stacks (deeply nested expressions recurse), and a claim whose evaluation
/// fails unexpectedly gets an ERROR verdict instead of ending the run.
pub fn evaluate_all(files: &[ClaimFile]) -> Result<Vec<Vec<Outcome>>, Error> {
    evaluate_all_with(files, &EvaluationOptions::default())
}

/// What an evaluation writes besides the verdicts.
#[derive(Clone, Debug, Default)]
pub struct EvaluationOptions {
    /// write the certificate document (`--certificate FILE` of `spectrum` /
    /// `charmap --certify`) of every certified claim at every valence into
    /// this directory, as `CLAIM-ID-nN.json`, for an independent checker
    pub certificates: Option<std::path::PathBuf>,
}

/// [`evaluate_all`], writing what `options` asks for.
pub fn evaluate_all_with(files: &[ClaimFile], options: &EvaluationOptions) -> Result<Vec<Vec<Outcome>>, Error> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let workers = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1).min(files.len()).max(1);
    let next = AtomicUsize::new(0);
    let results: std::sync::Mutex<Vec<Option<Vec<Outcome>>>> = std::sync::Mutex::new(vec![None; files.len()]);
    std::thread::scope(|scope| {
        let mut handles = Vec::new();
        for _ in 0..workers {
            let work = || loop {
                let k = next.fetch_add(1, Ordering::SeqCst);
                let Some(f) = files.get(k) else { break };
                let o = evaluate_with(f, options);
                results.lock().unwrap_or_else(|e| e.into_inner())[k] = Some(o);
            };
            let h = std::thread::Builder::new()
                .stack_size(EVALUATION_STACK)
                .spawn_scoped(scope, work)
                .map_err(|e| Error::Message(format!("cannot start a worker thread: {e}")))?;
            handles.push(h);
        }
        for h in handles {
            h.join().map_err(|_| Error::Message("internal error while evaluating claims".to_string()))?;
        }
        Ok::<(), Error>(())
    })?;
    let results = results.into_inner().unwrap_or_else(|e| e.into_inner());
    Ok(results.into_iter().map(|o| o.unwrap_or_default()).collect())
}

/// Evaluate every claim of a file.
pub fn evaluate(file: &ClaimFile) -> Vec<Outcome> {
    evaluate_with(file, &EvaluationOptions::default())
}

/// [`evaluate`], writing what `options` asks for.
pub fn evaluate_with(file: &ClaimFile, options: &EvaluationOptions) -> Vec<Outcome> {
    let mut cache = Cache::writing_certificates(options.certificates.clone());
    file.claims
        .iter()
        .map(|c| {
            let started = std::time::Instant::now();
            let run = std::panic::AssertUnwindSafe(|| evaluate_claim(&file.paper, c, &mut cache));
            let mut outcome = std::panic::catch_unwind(run).unwrap_or_else(|p| {
                let why = p
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| p.downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                error_outcome(&file.paper, c, format!("internal error while evaluating this claim: {why}"))
            });
            outcome.seconds = started.elapsed().as_secs_f64();
            outcome
        })
        .collect()
}

/// The outcome of one claim, reading the file's shared analyses from `cache`.
pub fn evaluate_claim(paper: &str, claim: &Claim, cache: &mut Cache) -> Outcome {
    if let Check::Malformed(message) = &claim.check {
        return error_outcome(paper, claim, message.clone());
    }
    if let Err(e) = claim.check.validate() {
        return error_outcome(paper, claim, e.to_string());
    }
    cache.claim = claim.id.clone();
    match claim.check.evaluate(cache).map_err(engine_failure_undecided) {
        Ok(f) => outcome(paper, claim, f.verdict(), f),
        Err(e) if undecided(&e) => outcome(paper, claim, Verdict::Inconclusive, unexplained(e.to_string())),
        Err(e) => error_outcome(paper, claim, e.to_string()),
    }
}

/// The ERROR outcome of a claim that could not be read or evaluated.
pub fn error_outcome(paper: &str, claim: &Claim, detail: String) -> Outcome {
    outcome(paper, claim, Verdict::Error, unexplained(detail))
}

/// A claim's outcome: what the claim says of itself, and the verdict.
fn outcome(paper: &str, claim: &Claim, verdict: Verdict, p: Finding) -> Outcome {
    Outcome {
        id: claim.id.clone(),
        paper: paper.to_string(),
        location: claim.location.clone(),
        statement: claim.statement.clone(),
        convention: claim.convention.clone(),
        verdict,
        expected: claim.expected,
        by_construction: claim.by_construction.clone(),
        stated: p.stated,
        computed: p.computed,
        detail: p.detail,
        seconds: 0.0,
    }
}

/// The evidence of an outcome that has only a reason (INCONCLUSIVE, ERROR).
fn unexplained(detail: String) -> Finding {
    Finding { holds: false, stated: String::new(), computed: String::new(), detail }
}
