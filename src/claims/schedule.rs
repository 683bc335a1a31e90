//! Where the configurations of one claim are evaluated: side by side on a
//! pool of one worker per core, whichever file the claim belongs to.
//!
//! Files are evaluated two at a time and the claims of a file in turn (they
//! share the file's cache of analyses), but most of the time of the
//! built-in registry is a handful of certified claims, each proving 10 to
//! 98 independent configurations (tps.c1 at n = 3..100, the known results'
//! 144 characteristic-map proofs). With the claim as the unit of work, one
//! core waited on the longest file while the other had nothing left to do.
//! A configuration's evaluation reads only its narrowed subject, so its
//! result does not depend on where or in which order it runs; the callers
//! collect the results in configuration order and decide from them exactly
//! as they would from a sequential run.

use crate::claims::subject::Subject;

/// Stack of a claim-evaluation worker (the file workers of
/// `evaluate::evaluate_all_with` and this pool's): deeply nested expressions
/// recurse.
pub const EVALUATION_STACK: usize = 64 << 20;

/// Evaluate `one` at every configuration, largest valence first (the most
/// work, so that the last to finish is a short one), on the configuration
/// pool; the results come back in the order of `configurations`. Without a
/// pool (its threads could not be started) they are evaluated here in turn.
pub fn each_configuration<T: Send>(
    configurations: &[(usize, Subject)],
    one: impl Fn(&Subject, usize) -> T + Sync,
) -> Vec<T> {
    let Some(pool) = pool() else {
        return configurations.iter().map(|(n, s)| one(s, *n)).collect();
    };
    let mut order: Vec<usize> = (0..configurations.len()).collect();
    order.sort_by_key(|&k| std::cmp::Reverse(configurations[k].0));
    let mut results: Vec<(usize, T)> = pool.install(|| {
        use rayon::prelude::*;
        order
            .par_iter()
            .with_max_len(1)
            .map(|&k| {
                let (n, s) = &configurations[k];
                (k, one(s, *n))
            })
            .collect()
    });
    results.sort_by_key(|(k, _)| *k);
    results.into_iter().map(|(_, r)| r).collect()
}

/// The configuration pool: one worker per core, with the stack of a
/// claim-evaluation worker (a configuration evaluates the claim's
/// expressions, which may nest deeply). Its own pool rather than rayon's
/// global one, whose workers have the default stack; the analyses' inner
/// parallel loops (Fourier blocks) run on it too when called from it.
fn pool() -> Option<&'static rayon::ThreadPool> {
    static POOL: std::sync::OnceLock<Option<rayon::ThreadPool>> = std::sync::OnceLock::new();
    POOL.get_or_init(|| {
        let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
        rayon::ThreadPoolBuilder::new()
            .num_threads(cores)
            .stack_size(EVALUATION_STACK)
            .thread_name(|k| format!("subdlab-claims-{k}"))
            .build()
            .ok()
    })
    .as_ref()
}
