//! Subdivision schemes: one file per scheme, each a mask (the weights) over a
//! topology operator (the connectivity). Masks are generic over the weight
//! scalar so that the same code gives float and exact stencils.

pub mod catmull_clark;
pub mod doo_sabin;
pub mod four_three;
// a regular-lattice scheme: registered in `crate::lattice::registry`, not here
pub mod khan_mustafa;
pub mod lattice_on_mesh;
pub mod loop_subdivision;
pub mod non_box;
pub mod pgs;
pub mod polar_bi2;
pub mod tps;
pub mod unified_sqrt3;
// scheme files (TOML) over the built-in topologies
pub mod user;

use crate::mesh::PolyMesh;
// The scheme interface lives in the description layer below the engine
// (`crate::sdc`); re-exported here because every scheme file implements it.
pub use crate::sdc::params;
pub use crate::sdc::{Caps, CentreKind, ParamSpec, Params, Rules, Scheme, SchemeInfo, SchemeWeight};

/// Every built-in scheme: name, description and parameter specification.
pub struct SchemeEntry {
    pub name: &'static str,
    pub description: &'static str,
    pub params: fn() -> Vec<ParamSpec>,
    pub build: fn(Params) -> Box<dyn Scheme>,
}

pub fn registry() -> Vec<SchemeEntry> {
    vec![
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
    ]
}

pub fn known_names() -> Vec<&'static str> {
    // the regular-lattice schemes are built by `crate::lattice`, but are names all the same
    registry().iter().map(|e| e.name).chain(crate::lattice::registry().iter().map(|e| e.name)).collect()
}

/// Build a scheme by name with `name=value` parameter overrides.
pub fn build(name: &str, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, String> {
    let reg = registry();
    if let Some(l) = crate::lattice::find(name) {
        // regular-lattice schemes refine meshes and give characteristic maps
        // through their masks on oriented quad meshes
        if let Some((k, _)) = overrides.first() {
            return Err(format!("scheme '{name}' has no parameters (got '{k}')"));
        }
        return Ok(Box::new(lattice_on_mesh::LatticeOnMesh::new((l.build)())));
    }
    let entry = reg
        .iter()
        .find(|e| e.name == name)
        .ok_or_else(|| format!("unknown scheme '{name}'; known schemes: {}", known_names().join(", ")))?;
    let params = Params::resolve(entry.name, &(entry.params)(), overrides)?;
    Ok((entry.build)(params))
}

/// Build a scheme from a name or a scheme file: an argument that ends in
/// `.toml` or names an existing file is loaded as a file (`user`), anything
/// else is a built-in name. The one entry point for command-line arguments.
pub fn resolve(name_or_path: &str, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, String> {
    let path = std::path::Path::new(name_or_path);
    // a built-in name always means the built-in scheme, even if a file of that
    // name happens to exist in the working directory
    let builtin = known_names().contains(&name_or_path);
    if !builtin && (name_or_path.ends_with(".toml") || path.is_file()) {
        return user::load(path, overrides);
    }
    build(name_or_path, overrides)
}

/// The one-ring fan of an interior vertex, restricted to faces of the given
/// size; `None` when the vertex is on the boundary or a face has another size.
pub(crate) fn uniform_fan(mesh: &PolyMesh, v: usize, size: usize) -> Option<Vec<Vec<usize>>> {
    let fan = mesh.vertex_fan(v)?;
    fan.iter().all(|f| f.len() == size).then_some(fan)
}
