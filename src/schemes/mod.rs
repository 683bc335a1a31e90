//! Subdivision schemes: one file per scheme, each a mask (the weights) over a
//! topology operator (the connectivity). Masks are generic over the weight
//! scalar so that the same code gives float and exact stencils.

pub mod catmull_clark;
pub mod doo_sabin;
// scheme files of the lattice and curve families (mesh scheme files: `user`)
pub mod files;
pub mod four_three;
// regular-lattice schemes (Z², `crate::lattice`), listed in `registry` with the rest
pub mod khan_mustafa;
pub mod lattice_on_mesh;
pub mod loop_subdivision;
pub mod non_box;
pub mod params;
pub mod pgs;
pub mod polar_bi2;
// every built-in name of every family, and the routing of names and files
pub mod registry;
pub mod tps;
pub mod unified_sqrt3;
// scheme files (TOML) over the built-in topologies
pub mod user;

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Rational, Weight};
use crate::refine::{Origin, RuleResult};
use crate::topology::Topology;
pub use params::{ParamSpec, Params};

/// The rules of a scheme for one weight type.
pub trait Rules<W: Weight> {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W>;
}

/// What kind of point the analysis is centred on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CentreKind {
    /// an extraordinary vertex (Catmull–Clark, Loop, 4-3, ...)
    Vertex,
    /// an extraordinary face (Doo–Sabin, ...)
    Face,
    /// an extraordinary face with an extra control point at its centre
    /// (point-augmented bi-2 subdivision, PGS)
    AugmentedFace,
    /// a pole: a vertex surrounded by triangles, rings of quads outside
    /// (polar bi-2 subdivision)
    Polar,
}

impl CentreKind {
    /// Whether the analysis is centred on a face (its corners form ring 0).
    pub fn is_face_centred(self) -> bool {
        matches!(self, CentreKind::Face | CentreKind::AugmentedFace)
    }
    /// Vertex rings (beyond ring 0) whose faces carry the first ring of the
    /// limit surface. Normally the faces touching ring 0. In a polar layout a
    /// bi-2 ring of patches spans three rows of control points, and the first
    /// ring that is not degenerate at the pole spans rows 1 to 3, i.e. the
    /// faces touching rings 0 to 2.
    pub fn first_ring_depth(self) -> usize {
        match self {
            CentreKind::Polar => 2,
            _ => 0,
        }
    }
}

pub trait Scheme: Rules<f64> + Rules<Rational> + Send + Sync {
    fn name(&self) -> &'static str;
    fn description(&self) -> &'static str;
    fn topology(&self) -> Topology;
    fn centre_kind(&self) -> CentreKind;
    /// The face type of the regular lattice around the centre.
    fn sector_kind(&self) -> SectorKind;
    fn params(&self) -> &Params;
    /// Whether meshes carry a face control vertex per face (non-box).
    fn face_control(&self) -> bool {
        false
    }
    /// The name of a parameter that may vary per vertex (`PolyMesh::vertex_params`),
    /// if the scheme has one.
    fn vertex_param(&self) -> Option<&'static str> {
        None
    }
    /// How the per-vertex parameter of a new vertex derives from the old ones
    /// (weights on old vertices); `None` where the scheme has no such parameter.
    fn vertex_param_rule(&self, _mesh: &PolyMesh, _origin: Origin) -> Option<crate::refine::Stencil<f64>> {
        None
    }
    /// Why the scheme has no boundary rules here, for the open-mesh error.
    fn boundary_note(&self) -> Option<&'static str> {
        None
    }
    /// The only valence the scheme is defined at (regular-lattice schemes: 4).
    fn fixed_valence(&self) -> Option<usize> {
        None
    }
    /// Whether the rules commute with the rotation of a symmetric configuration
    /// (false for asymmetric masks: then no Fourier blocks).
    fn rotation_symmetric(&self) -> bool {
        true
    }
    /// Whether meshes must carry lattice directions (`PolyMesh::orient_lattice`).
    fn lattice_oriented(&self) -> bool {
        false
    }
    /// Whether the analysis accepts any sequence of quad and triangle sectors
    /// around the centre (`--faces`), not only the regular configuration.
    fn face_sequences(&self) -> bool {
        false
    }
    /// What the scheme needs of an input mesh, for error messages of `refine`;
    /// `None`: derived from the topology.
    fn mesh_requirement(&self) -> Option<&'static str> {
        None
    }
    /// The rules of refinement step `level` (1 = the first) of a real mesh, for
    /// schemes whose first steps differ from the stationary rules that the
    /// local subdivision matrix analyses; `None`: the same rules at every step.
    fn at_level(&self, _level: usize) -> Option<Box<dyn Scheme>> {
        None
    }
}

/// Weight types every scheme implements rules for; lets generic code ask a
/// `&dyn Scheme` for stencils of any of them. This is the one entry point to
/// the rules: results come back merged (duplicates summed, zeros dropped).
pub trait SchemeWeight: Weight {
    fn rule(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> RuleResult<Self>;
    fn stencil(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> RuleResult<Self> {
        Ok(Self::rule(scheme, mesh, origin)?.map(|s| s.merged()))
    }
}

impl SchemeWeight for f64 {
    fn rule(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> RuleResult<Self> {
        Rules::<f64>::stencil(scheme, mesh, origin)
    }
}

impl SchemeWeight for Rational {
    fn rule(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> RuleResult<Self> {
        Rules::<Rational>::stencil(scheme, mesh, origin)
    }
}

/// Every built-in scheme: name, description and parameter specification.
pub struct SchemeEntry {
    pub name: &'static str,
    pub description: &'static str,
    pub params: fn() -> Vec<ParamSpec>,
    pub build: fn(Params) -> Box<dyn Scheme>,
}

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
fn on_mesh(built: registry::Built, name: &str) -> Result<Box<dyn Scheme>, String> {
    match built {
        registry::Built::Mesh(s) => Ok(s),
        registry::Built::Lattice(l) => Ok(Box::new(lattice_on_mesh::LatticeOnMesh::new(l))),
        registry::Built::Curve(_) => {
            Err(format!("'{name}' is a curve scheme: it has no mesh rules (analyse it with `subdlab curve {name}`)"))
        }
    }
}

/// Build a scheme by name with `name=value` parameter overrides.
pub fn build(name: &str, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, String> {
    let entry = registry::find(name)
        .ok_or_else(|| format!("unknown scheme '{name}'; known schemes: {}", known_names().join(", ")))?;
    on_mesh(entry.build(overrides)?, name)
}

/// Build a scheme from a name or a scheme file (`registry::resolve`): an
/// argument that ends in `.toml` or names an existing file is loaded as a
/// file, anything else is a built-in name. The entry point for command-line
/// arguments that need a mesh scheme.
pub fn resolve(name_or_path: &str, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, String> {
    on_mesh(registry::resolve(name_or_path, overrides)?, name_or_path)
}

/// The one-ring fan of an interior vertex, restricted to faces of the given
/// size; `None` when the vertex is on the boundary or a face has another size.
pub(crate) fn uniform_fan(mesh: &PolyMesh, v: usize, size: usize) -> Option<Vec<Vec<usize>>> {
    let fan = mesh.vertex_fan(v)?;
    fan.iter().all(|f| f.len() == size).then_some(fan)
}
