//! The refinement host a scheme runs on: which connectivity one subdivision
//! step produces, which neighbour positions (mask slots) its rules weigh, and
//! what the rest of the engine must know of it. A scheme only names its host
//! (`Host`), as OpenSubdiv's Sdc names a split type without knowing the
//! refiner.
//!
//! One host is one unit: a file `src/topology/<host>.rs` that implements
//! [`RefinementHost`] — its split, its slots and their gatherer, its counting
//! rules (growth per level, size bound), the mesh it needs and the spline of
//! its regular part. Every question about a host is a method of that trait
//! without a default, so a new host must answer all of them, and nothing
//! outside its file matches on which host it is.
//!
//! The registry is split over the two layers that must know it: the variant
//! list of [`Host`] (the identity scheme descriptions name; in
//! `sdc::host_list`, re-exported here), and the table that maps each variant
//! to its unit in `crate::topology` (which sees every host file; [`Registry`]
//! is the interface this layer calls it through, so `sdc` imports nothing
//! from above). The table is an exhaustive match: a variant without a unit
//! does not compile.

use crate::error::Error;
use crate::mesh::{PolyMesh, SectorKind, Tags};
use crate::sdc::centre::CentreKind;
use crate::sdc::gathered::{Gather, Wants};
pub use crate::sdc::host_list::{Host, HOSTS};
use crate::sdc::host_spec::HostSpec;
use crate::sdc::stencil::Origin;

/// The host a scheme runs on (the name scheme descriptions have always used).
pub type Topology = Host;

/// How triangles are split by a primal operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriangleSplit {
    /// 1 -> 4 triangles, no face point (Loop, the triangle part of 4-3)
    FourTriangles,
    /// a face point and 3 quads (Catmull–Clark on triangles)
    FacePointQuads,
}

/// The refined connectivity of one step: the new mesh, where each new vertex
/// comes from, and the parent entity of each new face.
#[derive(Clone, Debug)]
pub struct Refined {
    pub mesh: PolyMesh,
    pub vertex_origins: Vec<Origin>,
    pub face_parents: Vec<Origin>,
}

/// The spline a host's regular rules may be, as far as the certified
/// characteristic map (`certify::charmap`, lemmas C3 and C3′) must know it to
/// choose the masks it compares the rules with and the windows it bounds.
/// Which of a family's candidates fits (bicubic or A_4, quads or triangles)
/// the certificate decides by comparing exactly; the host only says which
/// family its lattice refinement belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RegularSpline {
    /// binary primal refinement: over quads the bicubic B-spline or the
    /// four-direction box spline A_4 (vertex, edge and face masks), over
    /// triangles the three-direction quartic box spline
    BinaryPrimal,
    /// binary dual refinement: the biquadratic B-spline (corner masks)
    BinaryDual,
    /// ternary primal refinement of quads: the biquadratic B-spline with the
    /// ternary mask (1, 3, 6, 7, 6, 3, 1)/9 in each direction
    TernaryPrimal,
    /// quads with face control vertices: the four-directional S_3^1
    /// non-box spline (`certify::s31`)
    NonBoxS31,
    /// no box spline of a lattice refinement (a rotating or radial-only
    /// split): the certificate has no mask to compare with, and a triangle
    /// ring falls back on the difference-scheme bounds
    NoBoxSpline,
}

/// Everything a refinement host states. Implemented once per host, in its
/// file under `src/topology/`; no method has a default, so a new host answers
/// every question and the compiler names any it leaves out.
pub trait RefinementHost: Sync {
    /// Name, sector and centre kinds, face control vertices, and the rules
    /// with their slot families (what scheme files write weights for).
    fn spec(&self) -> &'static HostSpec;
    /// One refinement step of the connectivity (the split).
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error>;
    /// What one split does to boundary, crease and corner tags
    /// (`mesh::tags`): the refined mesh's tags, given the new vertices'
    /// origins (`None` for a mesh without tags). A host without
    /// boundary/crease rules refuses a mesh with tags ([`refuse_tags`]);
    /// asked with no origins, the method says whether the host takes the
    /// mesh at all, before any work.
    fn refine_tags(&self, mesh: &PolyMesh, vertex_origins: &[Origin]) -> Result<Option<Tags>, Error>;
    /// The slots of `origin`'s rule mapped to mesh vertices, only the rules
    /// and optional families `wants` names.
    fn gather(&self, mesh: &PolyMesh, origin: Origin, wants: &dyn Wants) -> Gather;
    /// Refinements in one analysis step: the number after which the refined
    /// lattice is the old one scaled, without rotation, so that vertices can
    /// be matched by lattice coordinates.
    fn steps_per_analysis(&self) -> usize;
    /// How many faces one face becomes in one refinement, away from
    /// extraordinary points and boundaries: what the cost of refining a net
    /// grows by per level, and what a face's parameter area shrinks by.
    fn growth_per_level(&self) -> usize;
    /// An upper bound of the larger of the face and vertex counts after one
    /// refinement of `mesh`, from the split's counting rules, before any work.
    fn size_bound(&self, mesh: &PolyMesh) -> usize;
    /// What the split needs of a real mesh to refine it, for error messages.
    fn mesh_requirement(&self) -> &'static str;
    /// The spline family of the regular part (see [`RegularSpline`]).
    fn regular_spline(&self) -> RegularSpline;
}

/// [`RefinementHost::refine_tags`] of a host without boundary/crease rules:
/// a mesh with tags is refused in one line naming the host; an untagged mesh
/// stays untagged (and an empty tag set, open edges as cuts, stays empty).
pub fn refuse_tags(host: Host, mesh: &PolyMesh) -> Result<Option<Tags>, Error> {
    match &mesh.tags {
        Some(t) if !t.is_empty() => Err(Error::Input(format!(
            "the {} host has no boundary or crease rules: boundary/crease rules are not available there, so a mesh \
             with boundary edges or tagged creases or corners cannot be refined on it",
            host.spec().name
        ))),
        tags => Ok(tags.as_ref().map(|_| Tags::new())),
    }
}

/// The table from a host's identity to its unit. Implemented for [`Host`] by
/// `crate::topology` (the one place that sees every host file); this layer
/// only calls it.
pub trait Registry {
    fn unit(self) -> &'static dyn RefinementHost;
}

impl Host {
    /// Name, rules and slot families (the unit's [`RefinementHost::spec`]).
    pub fn spec(self) -> &'static HostSpec {
        self.unit().spec()
    }
    /// The host named `name` (as scheme files name it, `topology = "..."`).
    pub fn by_name(name: &str) -> Option<Host> {
        HOSTS.iter().copied().find(|h| h.spec().name == name)
    }
    /// One split, tags included ([`RefinementHost::refine_tags`]): a host
    /// without boundary/crease rules refuses a tagged mesh before splitting.
    pub fn refine(self, mesh: &PolyMesh) -> Result<Refined, Error> {
        let unit = self.unit();
        if mesh.tags.is_some() {
            unit.refine_tags(mesh, &[])?;
        }
        let mut refined = unit.refine(mesh)?;
        refined.mesh.tags = unit.refine_tags(mesh, &refined.vertex_origins)?;
        Ok(refined)
    }
    /// Whether the host refines `mesh`'s tags (an error naming the host if
    /// it has no boundary/crease rules and the mesh has tags).
    pub fn check_tags(self, mesh: &PolyMesh) -> Result<(), Error> {
        self.unit().refine_tags(mesh, &[]).map(|_| ())
    }
    pub fn steps_per_analysis(self) -> usize {
        self.unit().steps_per_analysis()
    }
    /// [`RefinementHost::growth_per_level`], under the name the analyses use.
    pub fn faces_per_face(self) -> usize {
        self.unit().growth_per_level()
    }
    pub fn growth_per_level(self) -> usize {
        self.unit().growth_per_level()
    }
    pub fn size_bound(self, mesh: &PolyMesh) -> usize {
        self.unit().size_bound(mesh)
    }
    pub fn mesh_requirement(self) -> &'static str {
        self.unit().mesh_requirement()
    }
    pub fn regular_spline(self) -> RegularSpline {
        self.unit().regular_spline()
    }
    pub fn sector(self) -> SectorKind {
        self.spec().sector
    }
    pub fn centre(self) -> CentreKind {
        self.spec().centre
    }
}
