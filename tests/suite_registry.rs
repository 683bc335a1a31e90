//! Integration-test binary `suite_registry` (`cargo test --release --test suite_registry`).
//! What the repository promises: the claim registry and its verdicts (each
//! derived independently), negative controls, the committed reports, README
//! figures and notebooks, the crate's layer order, and that every test file
//! belongs to one suite.
//!
//! The integration tests are grouped into a few binaries by theme (issue 24):
//! each binary links the whole crate, so one binary per test file made
//! linking most of a clean `cargo test`. Each test file stays a file of its
//! own and is compiled here as a module, so its tests are named
//! `FILE::test`; `tests/common` is one shared module per binary
//! (`use crate::common;` in the files). `tests/suites.rs` checks that every
//! test file is listed in exactly one suite and every suite in Cargo.toml.

mod common;

mod curvature_claims;
mod layers;
mod lin_luo_statements;
mod negative_controls;
mod notebooks;
mod parameter_range_claims;
mod parameter_range_curvature;
mod readme_figures;
mod registry_corrections;
mod registry_independent;
mod registry_second_pass;
mod reports;
mod suites;
mod verify;
mod verify_errors;
