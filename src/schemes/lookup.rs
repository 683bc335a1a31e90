//! Mesh schemes by name or file: the built-in mesh schemes, and a scheme
//! built from a name or a scheme file as a mesh scheme (a lattice scheme
//! through its masks on quad meshes).

use crate::error::Error;
use crate::schemes::entry::SchemeEntry;
use crate::schemes::lattice_on_mesh;
// the module only (`self`): this file defines the function `registry`
use crate::schemes::registry::{self};
use crate::sdc::Scheme;

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
