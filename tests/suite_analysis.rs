//! Integration-test binary `suite_analysis` (`cargo test --release --test suite_analysis`).
//! The analysis stages across schemes: Fourier blocks and representative rows,
//! exact against floating-point multiplicities, Jordan blocks, the local
//! matrix, characteristic maps and second-order (curvature) analysis.
//!
//! The integration tests are grouped into a few binaries by theme (issue 24):
//! each binary links the whole crate, so one binary per test file made
//! linking most of a clean `cargo test`. Each test file stays a file of its
//! own and is compiled here as a module, so its tests are named
//! `FILE::test`; `tests/common` is one shared module per binary
//! (`use crate::common;` in the files). `tests/suites.rs` checks that every
//! test file is listed in exactly one suite and every suite in Cargo.toml.

mod common;

mod charmap;
mod charmap_from_rows;
mod crease_charmap;
mod curvature_catmull_clark;
mod curvature_central_ring;
mod curvature_generalised;
mod curvature_jordan;
mod curvature_loop;
mod curvature_surface_signs;
mod dft_blocks;
mod dft_representative_rows;
mod exact_vs_float;
mod jordan_irrational;
mod local_matrix;
mod reflection_split;
mod shape_chart;
mod tagged_verdicts;
mod tagged_vertices;
