//! One registry for the three scheme families: mesh schemes (rules over a
//! refinement topology, `schemes::Scheme`), regular-lattice schemes (four
//! parity masks on Z², `lattice::LatticeScheme`) and curve schemes (even and
//! odd rules on Z, `curves::CurveScheme`).
//!
//! Every built-in name is listed once (in `builtins`), and every command-line
//! argument that names a scheme (a built-in name or a scheme file) is resolved here:
//! `resolve` gives the scheme in its own family, and the callers pick the
//! analysis for that family. Scheme files say which family they belong to by
//! a `domain` key (`"lattice"` or `"curve"`); files without one are mesh
//! scheme files (`schemes::user`, which names a topology instead).
//! The entry types are in `entry`; they and the look-ups of `builtins` are
//! re-exported here, so `schemes::registry::X` names each of them.

use std::path::Path;

use crate::error::Error;

use crate::lattice::LatticeScheme;
pub use crate::schemes::builtins::{entries, find, known_names, names_of};
pub use crate::schemes::entry::{Built, BuiltinEntry, CurveEntry, Entry, Family, LatticeEntry};
use crate::schemes::files;

/// Whether a command-line argument denotes a scheme file rather than a name:
/// a built-in name always means the built-in scheme, even if a file of that
/// name happens to exist in the working directory; otherwise an argument that
/// ends in `.toml` or names an existing file is a file.
pub fn is_file_argument(name_or_path: &str) -> bool {
    !known_names().contains(&name_or_path) && (name_or_path.ends_with(".toml") || Path::new(name_or_path).is_file())
}

/// The family of a name or scheme file, without building the scheme (a file
/// is only read as far as its `domain` key). `Err` for an unknown name.
pub fn family_of(name_or_path: &str) -> Result<Family, Error> {
    if is_file_argument(name_or_path) {
        return files::family(Path::new(name_or_path));
    }
    find(name_or_path).map(|e| e.family()).ok_or_else(|| unknown(name_or_path))
}

fn unknown(name: &str) -> Error {
    Error::Input(format!("unknown scheme '{name}'; known schemes: {}", known_names().join(", ")))
}

/// Build a scheme of any family from a built-in name or a scheme file, with
/// `name=value` parameter overrides. The one entry point for arguments that
/// name a scheme.
pub fn resolve(name_or_path: &str, overrides: &[(String, String)]) -> Result<Built, Error> {
    if is_file_argument(name_or_path) {
        return files::load(Path::new(name_or_path), overrides);
    }
    find(name_or_path).ok_or_else(|| unknown(name_or_path))?.build(overrides)
}

/// A regular-lattice scheme from a built-in name or a `domain = "lattice"`
/// file; `Err` for a scheme of another family.
pub fn lattice(name_or_path: &str, overrides: &[(String, String)]) -> Result<Box<dyn LatticeScheme>, Error> {
    match resolve(name_or_path, overrides)? {
        Built::Lattice(l) => Ok(l),
        other => Err(Error::Input(format!(
            "'{name_or_path}' is a {} scheme, not a regular-lattice scheme",
            other.family().name()
        ))),
    }
}
