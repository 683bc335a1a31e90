//! Integration-test binary `suite_cli` (`cargo test --release --test suite_cli`).
//! The command line as a user runs it: every subcommand's output formats,
//! figure files, one-line errors, limits, mesh refinement of real meshes and
//! the robustness findings.
//!
//! The integration tests are grouped into a few binaries by theme (issue 24):
//! each binary links the whole crate, so one binary per test file made
//! linking most of a clean `cargo test`. Each test file stays a file of its
//! own and is compiled here as a module, so its tests are named
//! `FILE::test`; `tests/common` is one shared module per binary
//! (`use crate::common;` in the files). `tests/suites.rs` checks that every
//! test file is listed in exactly one suite and every suite in Cargo.toml.

mod common;

mod charmap_cli;
mod cli;
mod cli_bi2;
mod curvature_user_scheme;
mod figure_formats;
mod figure_layout;
mod hardening;
mod json_schemas;
mod khan_mustafa_mesh;
mod limits;
mod mesh_fuzz;
mod non_box_refine;
mod refine;
mod refine_boundary;
mod shape_chart_cli;
mod sqrt3_refine;
mod sweep;
mod sweep_exact;
mod sweep_region;
mod tagged_sweep;
mod typed_errors;
