//! Paper statements as data (`claims/*.toml`), evaluated against the tool's
//! computations: every claim ends HOLDS, REFUTED (with the numbers that show
//! it), INCONCLUSIVE (the computation ran and could not decide, with the
//! reason: `Error::Undecided`) or ERROR (the claim cannot be read as
//! written, or asserts nothing: every other error).
//!
//! A claim file names its paper and lists claims; each claim has an id, where
//! it stands in the paper, the statement as printed, the convention it uses,
//! and a `check` saying how it is evaluated: one of the check kinds of
//! `checks/` (one file each, behind the `CheckKind` trait), the `builtin`
//! kind naming a paper-specific computation of `builtin/` (one file per
//! paper). Values are expressions (`numeric::expr`) in the valence `n`
//! (alias `k`), the Fourier block index `m` where relevant, and the scheme's
//! parameters by name.
//!
//! The files import each other without a cycle (tests/layers.rs checks it),
//! bottom up: `subject`, `verdict`, `schedule`; `common/` (values, shared
//! spectra, the verdict over configurations) and `check_kind` (the trait);
//! `builtin/data` and the paper files; the kinds of `checks/` and their
//! table `checks/mod.rs`; `claim`, `parse`, `evaluate`. This file only
//! declares them and re-exports the public API.

pub mod builtin;
pub mod check_kind;
pub mod checks;
pub mod claim;
pub mod common;
pub mod evaluate;
pub mod parse;
mod schedule;
pub mod subject;
pub mod verdict;

pub use self::checks::{Check, CHECK_KEYS};
pub use self::claim::{Claim, ClaimFile, FigureSpec, SweepFigureSpec};
pub use self::evaluate::{evaluate, evaluate_all, evaluate_all_with, evaluate_with, EvaluationOptions};
pub use self::parse::{builtin_files, parse_file, BUILTIN, COMMON_KEYS, SUBJECT_KEYS};
pub use self::subject::{Subject, Valences};
pub use self::verdict::{Finding, Outcome, Verdict};
