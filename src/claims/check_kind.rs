//! The interface every check kind implements: a claim's `check = "KIND"`
//! names one, its keys are read into the kind's own type (serde, with the
//! keys listed in [`CheckKind::KEYS`] so that an unknown key is reported
//! with its line before that), [`CheckKind::validate`] refuses what cannot
//! be a claim before anything is computed, and [`CheckKind::evaluate`]
//! decides it: a [`Finding`] (HOLDS or REFUTED, with the stated and computed
//! values and what decided), `Error::Undecided` (INCONCLUSIVE) or any other
//! error (ERROR).
//!
//! Adding a check kind: one file in `checks/` with the type and its
//! `impl CheckKind`, and one line in the table of `checks/mod.rs`.

use crate::claims::common::spectra::Cache;
use crate::claims::verdict::Finding;
use crate::error::Error;

pub trait CheckKind {
    /// The keys this kind reads besides the common ones of every claim
    /// (and besides the subject's, when [`CheckKind::TAKES_SUBJECT`]).
    const KEYS: &'static [&'static str];
    /// Whether the kind analyses a scheme: it then reads the subject's keys
    /// (scheme, valences, faces, params, neighbourhood, vars).
    const TAKES_SUBJECT: bool = true;

    /// What the claim must satisfy before anything is computed: no list the
    /// check compares with is empty (a claim asserting nothing would HOLD
    /// vacuously), every option in the command line's own range. An error
    /// here makes the claim an ERROR.
    fn validate(&self) -> Result<(), Error> {
        Ok(())
    }

    /// Decide the claim, reading the file's shared analyses from `cache`.
    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error>;
}

/// The ERROR of a claim whose list `what` is empty: it asserts nothing.
pub fn vacuous(what: &str) -> Result<(), Error> {
    Err(Error::Claim(format!("{what} is empty: the claim asserts nothing (a vacuous claim is an ERROR)")))
}
