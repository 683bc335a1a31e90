//! The scheme catalogue, above the engine (nothing in the engine imports
//! it): one file per built-in scheme, the registry of every family
//! (`registry`), and scheme files (`user` for meshes, `files` for lattices
//! and curves). A scheme's rules are written once, generic over the weight
//! scalar so that the same code gives float and exact stencils; most are
//! masks over their refinement host's slots (`sdc::slots`).

// Biermann–Levin–Zorin's edge rule at crease vertices, a parameter of catmull_clark and loop
pub mod blz;
pub mod catmull_clark;
// the curve schemes of Lin–Luo section 3 (the Z domain)
pub mod curves;
pub mod doo_sabin;
// the entry types of the registry (one per family), below every scheme file
pub mod entry;
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
// every built-in name of every family (`builtins`), and the routing of names
// and files (`registry`)
pub mod builtins;
pub mod registry;
// where each analysis runs, by the scheme's domain (the CLI and the claims)
pub mod route;
// mesh schemes by name or file (`build`, `resolve`, ...), re-exported here
pub mod lookup;
pub mod tps;
pub mod unified_sqrt3;
// scheme files (TOML) over the built-in topologies
pub mod user;

// The scheme interface lives in the description layer below the engine
// (`crate::sdc`); re-exported here because every scheme file implements it.
pub use crate::sdc::params;
pub use crate::sdc::{
    Caps, CentreKind, Domain, MeshDomain, ParamSpec, Params, RuleWeight, Rules, Scheme, SchemeInfo, SchemeWeight,
};

pub use entry::SchemeEntry;
pub use lookup::{build, known_names, on_mesh, registry, resolve};
