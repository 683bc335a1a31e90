//! Integration-test binary `suite_certify` (`cargo test --release --test suite_certify`).
//! Certified verdicts: spectra and characteristic maps proved in exact or
//! interval arithmetic, the exported certificates and their independent
//! checker, soundness controls.
//!
//! The integration tests are grouped into a few binaries by theme (issue 24):
//! each binary links the whole crate, so one binary per test file made
//! linking most of a clean `cargo test`. Each test file stays a file of its
//! own and is compiled here as a module, so its tests are named
//! `FILE::test`; `tests/common` is one shared module per binary
//! (`use crate::common;` in the files). `tests/suites.rs` checks that every
//! test file is listed in exactly one suite and every suite in Cargo.toml.

mod common;

mod certificate_checker;
mod certify;
mod certify_charmap;
mod certify_difference;
mod certify_loop_sector;
mod certify_nonbox;
mod certify_soundness;
mod certify_tagged;
mod certify_tagged_charmap;
mod crease_sides;
mod cyclotomic;
mod every_valence;
mod step_rotation;
