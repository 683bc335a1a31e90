//! The entry types of the scheme registry: a built-in scheme of each family
//! (`BuiltinEntry`, `SchemeEntry`, `LatticeEntry`, `CurveEntry`), the family
//! (`Family`), a built-in of any family (`Entry`) and a built scheme of any
//! family (`Built`). Every scheme file imports its entry type from here; the
//! catalogue (`builtins`) and the routing (`registry`) import the scheme files.

use crate::curves::CurveScheme;
use crate::error::Error;
use crate::lattice::LatticeScheme;
use crate::sdc::{ParamSpec, Params, Scheme};

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

/// Every built-in scheme: name, description and parameter specification.
pub type SchemeEntry = BuiltinEntry<dyn Scheme>;

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
