//! User-defined schemes: a TOML file names one of the refinement hosts
//! (`sdc::slots::Host`) and gives, per rule of the host, a weight for every
//! slot family as an expression (`numeric::expr`) in the valence or face
//! size `n`, the neighbour index `j`, the corner count `m` of the face a
//! `face-corner` slot lies in, and named parameters. The result
//! implements `Scheme`, so every analysis runs on it unchanged.
//!
//! ```toml
//! name = "my-loop"
//! topology = "primal-triangle"
//! [vertex]
//! centre = "3/8 + (3/8 + cos(2 pi / n)/4)^2"
//! edge = "(5/8 - (3/8 + cos(2 pi / n)/4)^2) / n"
//! [edge]
//! ends = "3/8"
//! opposite = "1/8"
//! ```
//!
//! Which neighbours each field weighs is the host's slot declaration
//! (`sdc::slots`), counter-clockwise as `PolyMesh::vertex_fan` gives them.
//! The first neighbour around a vertex or in a face is arbitrary, so weights
//! there may not depend on `j`; in rules with a canonical j (the
//! `[edge-extraordinary]` rule of the primal hosts, the dual corner rule, the
//! polar spoke rule, ...) j = 0 is a definite neighbour and weights may.
//!
//! * `file.rs`: the TOML schema and line-numbered validation;
//! * `weights.rs`: expression evaluation and the weight cache;
//! * `rules.rs`: the weights put on the host's slots (the `Scheme`);
//! * `probe.rs`: which fields a computation read at one valence (`every_valence`).

mod file;
pub mod probe;
mod rules;
mod weights;

use std::path::Path;

pub use crate::schemes::files::shared_format::UserParam;
pub use file::{load_def, UserSchemeDef, MAX_EXPR_CHARS, MAX_FILE_BYTES};
pub use rules::UserScheme;

use crate::error::Error;
use crate::sdc::Scheme;

/// Load a scheme file with `name=value` parameter overrides.
pub fn load(path: &Path, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, Error> {
    Ok(Box::new(load_def(path)?.build(overrides)?))
}
