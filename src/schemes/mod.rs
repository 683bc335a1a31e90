//! The scheme catalogue, above the engine (nothing in the engine imports
//! it): one file per built-in scheme, the registry of every family
//! (`registry`), and scheme files (`user` for meshes, `files` for lattices
//! and curves). A scheme's rules are written once, generic over the weight
//! scalar so that the same code gives float and exact stencils; most are
//! masks over their refinement host's slots (`sdc::slots`).

pub mod catmull_clark;
// the curve schemes of Lin–Luo section 3 (the Z domain)
pub mod curves;
pub mod doo_sabin;
// scheme files of the lattice and curve families (mesh scheme files: `user`)
pub mod files;
pub mod four_three;
// regular-lattice schemes (Z², `crate::lattice`), listed in `registry` with the rest
pub mod khan_mustafa;
pub mod lattice_on_mesh;
pub mod loop_subdivision;
pub mod memo;
pub mod non_box;
pub mod pgs;
pub mod polar_bi2;
// every built-in name of every family, and the routing of names and files
pub mod registry;
pub mod tps;
pub mod unified_sqrt3;
// scheme files (TOML) over the built-in topologies
pub mod user;

// The scheme interface lives in the description layer below the engine
// (`crate::sdc`); re-exported here because every scheme file implements it.
use crate::error::Error;
pub use crate::sdc::params;
pub use crate::sdc::{
    Caps, CentreKind, Domain, MeshDomain, ParamSpec, Params, RuleWeight, Rules, Scheme, SchemeInfo, SchemeWeight,
};

/// Every built-in scheme: name, description and parameter specification.
pub type SchemeEntry = registry::BuiltinEntry<dyn Scheme>;

/// The built-in mesh schemes (the mesh family of `registry::entries`).
pub fn registry() -> Vec<SchemeEntry> {
    registry::entries()
        .into_iter()
        .filter_map(|e| match e {
            registry::Entry::Mesh(m) => Some(m),
            _ => None,
        })
        .collect()
}

/// Every built-in name, of every family: a scheme file may not use one.
pub fn known_names() -> Vec<&'static str> {
    registry::known_names()
}

/// The scheme as a mesh scheme: regular-lattice schemes refine meshes and give
/// characteristic maps through their masks on oriented quad meshes; curve
/// schemes have no mesh rules.
pub fn on_mesh(built: registry::Built, name: &str) -> Result<Box<dyn Scheme>, Error> {
    match built {
        registry::Built::Mesh(s) => Ok(s),
        registry::Built::Lattice(l) => Ok(Box::new(lattice_on_mesh::LatticeOnMesh::new(l))),
        registry::Built::Curve(_) => Err(Error::Input(format!(
            "'{name}' is a curve scheme: it has no mesh rules (analyse it with `subdlab curve {name}`)"
        ))),
    }
}

/// Build a scheme by name with `name=value` parameter overrides.
pub fn build(name: &str, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, Error> {
    let entry = registry::find(name)
        .ok_or_else(|| Error::Input(format!("unknown scheme '{name}'; known schemes: {}", known_names().join(", "))))?;
    on_mesh(entry.build(overrides)?, name)
}

/// Build a scheme from a name or a scheme file (`registry::resolve`): an
/// argument that ends in `.toml` or names an existing file is loaded as a
/// file, anything else is a built-in name. The entry point for command-line
/// arguments that need a mesh scheme.
pub fn resolve(name_or_path: &str, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, Error> {
    on_mesh(registry::resolve(name_or_path, overrides)?, name_or_path)
}
