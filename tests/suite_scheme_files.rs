//! Integration-test binary `suite_scheme_files` (`cargo test --release --test suite_scheme_files`).
//! Scheme files: each shipped file restates its built-in scheme, user rules
//! (edge-extraordinary, lattice, curve), the expression evaluator in every
//! arithmetic.
//!
//! The integration tests are grouped into a few binaries by theme (issue 24):
//! each binary links the whole crate, so one binary per test file made
//! linking most of a clean `cargo test`. Each test file stays a file of its
//! own and is compiled here as a module, so its tests are named
//! `FILE::test`; `tests/common` is one shared module per binary
//! (`use crate::common;` in the files). `tests/suites.rs` checks that every
//! test file is listed in exactly one suite and every suite in Cargo.toml.

mod common;

mod evaluator_fields;
mod lattice_curve_files;
mod scheme_files;
mod user_edge_rules;
mod user_schemes;
