//! One registry for the three scheme families: mesh schemes (rules over a
//! refinement topology, `schemes::Scheme`), regular-lattice schemes (four
//! parity masks on Z², `lattice::LatticeScheme`) and curve schemes (even and
//! odd rules on Z, `curves::CurveScheme`).
//!
//! Every built-in name is listed here once, and every command-line argument
//! that names a scheme (a built-in name or a scheme file) is resolved here:
//! `resolve` gives the scheme in its own family, and the callers pick the
//! analysis for that family. Scheme files say which family they belong to by
//! a `domain` key (`"lattice"` or `"curve"`); files without one are mesh
//! scheme files (`schemes::user`, which names a topology instead).

use std::path::Path;

use crate::error::Error;

use super::files;
use super::{catmull_clark, doo_sabin, four_three, khan_mustafa, loop_subdivision, non_box, pgs, polar_bi2, tps};
use super::{unified_sqrt3, ParamSpec, Params, Scheme, SchemeEntry};
use crate::curves::CurveScheme;
use crate::lattice::LatticeScheme;
use crate::schemes::curves;

/// A built-in scheme of one family: name, description, parameter
/// specification and constructor; `S` is the family's scheme trait.
pub struct BuiltinEntry<S: ?Sized> {
    pub name: &'static str,
    pub description: &'static str,
    pub params: fn() -> Vec<ParamSpec>,
    pub build: fn(Params) -> Box<S>,
}

/// A built-in regular-lattice scheme.
pub type LatticeEntry = BuiltinEntry<dyn LatticeScheme>;

/// A built-in curve scheme.
pub type CurveEntry = BuiltinEntry<dyn CurveScheme>;

/// The domain a scheme lives on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// meshes with extraordinary vertices or faces (`subdlab spectrum`, `charmap`, `refine`)
    Mesh,
    /// the regular lattice Z² with explicit (i, j) masks
    Lattice,
    /// the line Z (`subdlab curve`)
    Curve,
}

impl Family {
    /// The value of a scheme file's `domain` key (mesh files have none).
    pub fn name(self) -> &'static str {
        match self {
            Family::Mesh => "mesh",
            Family::Lattice => "lattice",
            Family::Curve => "curve",
        }
    }
}

/// A built-in scheme of any family.
pub enum Entry {
    Mesh(SchemeEntry),
    Lattice(LatticeEntry),
    Curve(CurveEntry),
}

impl Entry {
    /// Name, description and parameter specification: the part every family shares.
    fn common(&self) -> (&'static str, &'static str, fn() -> Vec<ParamSpec>) {
        match self {
            Entry::Mesh(e) => (e.name, e.description, e.params),
            Entry::Lattice(e) => (e.name, e.description, e.params),
            Entry::Curve(e) => (e.name, e.description, e.params),
        }
    }
    pub fn name(&self) -> &'static str {
        self.common().0
    }
    pub fn description(&self) -> &'static str {
        self.common().1
    }
    pub fn params(&self) -> Vec<ParamSpec> {
        (self.common().2)()
    }
    pub fn family(&self) -> Family {
        match self {
            Entry::Mesh(_) => Family::Mesh,
            Entry::Lattice(_) => Family::Lattice,
            Entry::Curve(_) => Family::Curve,
        }
    }
    /// The scheme with `name=value` parameter overrides.
    pub fn build(&self, overrides: &[(String, String)]) -> Result<Built, Error> {
        let params = Params::resolve(self.name(), &self.params(), overrides)?;
        Ok(match self {
            Entry::Mesh(e) => Built::Mesh((e.build)(params)),
            Entry::Lattice(e) => Built::Lattice((e.build)(params)),
            Entry::Curve(e) => Built::Curve((e.build)(params)),
        })
    }
}

/// Every built-in scheme: mesh schemes, then lattice schemes, then curve
/// schemes (the order `subdlab schemes` lists them in).
pub fn entries() -> Vec<Entry> {
    let mesh = [
        catmull_clark::entry(),
        loop_subdivision::entry(),
        doo_sabin::entry(),
        non_box::entry(),
        four_three::entry(),
        unified_sqrt3::kobbelt_entry(),
        unified_sqrt3::entry(),
        tps::entry(),
        pgs::entry(),
        polar_bi2::entry(),
    ];
    let lattice = [khan_mustafa::entry(), khan_mustafa::cubic_entry()];
    let curve = [curves::cubic_bspline::entry(), curves::four_point::entry(), curves::unified::entry()];
    mesh.into_iter()
        .map(Entry::Mesh)
        .chain(lattice.into_iter().map(Entry::Lattice))
        .chain(curve.into_iter().map(Entry::Curve))
        .collect()
}

/// The built-in scheme of this name.
pub fn find(name: &str) -> Option<Entry> {
    entries().into_iter().find(|e| e.name() == name)
}

/// Every built-in name, of every family.
pub fn known_names() -> Vec<&'static str> {
    entries().iter().map(Entry::name).collect()
}

/// The built-in names of one family.
pub fn names_of(family: Family) -> Vec<&'static str> {
    entries().iter().filter(|e| e.family() == family).map(Entry::name).collect()
}

/// A scheme of any family, built.
pub enum Built {
    Mesh(Box<dyn Scheme>),
    Lattice(Box<dyn LatticeScheme>),
    Curve(Box<dyn CurveScheme>),
}

impl Built {
    pub fn family(&self) -> Family {
        match self {
            Built::Mesh(_) => Family::Mesh,
            Built::Lattice(_) => Family::Lattice,
            Built::Curve(_) => Family::Curve,
        }
    }
}

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
