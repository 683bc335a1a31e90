//! Integration-test binary `suite_schemes` (`cargo test --release --test suite_schemes`).
//! Each built-in scheme against the closed forms of its papers: spectra,
//! neighbourhoods, stencils, masks (one file per scheme).
//!
//! The integration tests are grouped into a few binaries by theme (issue 24):
//! each binary links the whole crate, so one binary per test file made
//! linking most of a clean `cargo test`. Each test file stays a file of its
//! own and is compiled here as a module, so its tests are named
//! `FILE::test`; `tests/common` is one shared module per binary
//! (`use crate::common;` in the files). `tests/suites.rs` checks that every
//! test file is listed in exactly one suite and every suite in Cargo.toml.

mod common;

mod boundary_rules;
mod catmull_clark;
mod curves;
mod doo_sabin;
mod four_three;
mod khan_mustafa;
mod loop_scheme;
mod non_box;
mod non_box_mask;
mod pgs;
mod polar_bi2;
mod sqrt3;
mod sqrt3_neighbourhood;
mod tps;
