//! The scheme-description layer (the role of OpenSubdiv's Sdc): what a
//! subdivision scheme *is*, independent of how it is analysed. It holds the
//! one rule interface of every domain (`Domain`, `Rules<D, W>`, `RuleWeight<D>`;
//! the mesh domain's `Scheme` and `SchemeWeight`), the stencil and origin
//! types mesh rules produce, the refinement host a scheme runs on
//! (`Topology`), the kind of centre it is analysed at and its typed parameters.
//!
//! Layering: `sdc` depends only on `numeric` and `mesh`. The engine (hosts,
//! refinement, discovery, assembly, spectrum, characteristic maps) is written
//! against this layer and never imports the scheme catalogue (`crate::schemes`);
//! `tests/layers.rs` enforces that.

// what kind of point an analysis is centred on (its own file: the hosts
// need it, and this file re-exports the hosts)
pub mod centre;
// what a host's gatherer gives
pub mod gathered;
pub mod host;
// every host by name (the identity below everything about hosts)
pub mod host_list;
// what a host declares: its rules and their slot families
pub mod host_spec;
pub mod params;
// per-host mask slots: the named neighbour positions a rule weighs
pub mod slots;
pub mod stencil;

pub use centre::CentreKind;
pub use gathered::{GatherError, RuleResult};
pub use host::{Topology, TriangleSplit};
pub use params::{ParamSpec, Params};
pub use stencil::{Origin, Stencil};

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Cyclotomic, Interval, Rational, SmallRational, TPoly, Weight};

/// A domain subdivision acts on: meshes with an extraordinary vertex or face
/// ([`MeshDomain`]), the regular lattice Z² (`lattice::LatticeDomain`), the
/// line Z (`curves::CurveDomain`). It names what a rule is asked and what it
/// answers, so that every scheme of every domain writes its rules as one
/// trait, [`Rules`], generic over the weight type.
pub trait Domain: 'static {
    /// What a rule reads besides its position: the mesh being refined; on Z²
    /// and Z nothing (`()`), their rules being masks over offsets.
    type Host: ?Sized;
    /// Where the new point is: its origin in the old mesh ([`Origin`]); on
    /// Z² the parity (α, β) of its index; on Z nothing (one rule gives the
    /// even and the odd mask).
    type Position: Copy;
    /// What a rule gives in weights `W`: a stencil over old vertices (or
    /// none where the rule does not apply), a mask over offsets.
    type Rule<W: Weight>;
    /// The domain's scheme, as the engine holds it: a trait object (`dyn
    /// Scheme + 'a`, `dyn LatticeScheme + 'a`, `dyn CurveScheme + 'a`), of
    /// any lifetime, as callers borrow it.
    type Scheme<'a>: ?Sized;
}

/// The rules of a scheme on domain `D` for one weight type: the one rule
/// trait every scheme implements (usually once, generic over `W`).
pub trait Rules<D: Domain, W: Weight> {
    fn rule(&self, host: &D::Host, at: D::Position) -> D::Rule<W>;
}

/// The one weight dispatch: lets generic code (`W: RuleWeight<D>`) ask a
/// domain's scheme object for its rule in any weight type the domain's
/// scheme trait demands; [`rule_weights!`](crate::sdc::rule_weights) implements
/// it for each (domain, weight) pair. `SchemeWeight`, `LatticeWeight` and
/// `CurveWeight` are this trait on one domain, with the domain's convenience
/// calls (merged results), and have no impls of their own.
pub trait RuleWeight<D: Domain>: Weight {
    fn rule_of(scheme: &D::Scheme<'_>, host: &D::Host, at: D::Position) -> D::Rule<Self>;
}

/// `RuleWeight<DOMAIN>` for each listed weight: the rule of the domain's
/// scheme object, which has rules for that weight (its scheme trait says so).
/// Invoked as `crate::sdc::rule_weights!` (a path inside the layer order).
macro_rules! rule_weights {
    ($domain:ty: $($w:ty),+) => {$(
        impl $crate::sdc::RuleWeight<$domain> for $w {
            fn rule_of(
                scheme: &<$domain as $crate::sdc::Domain>::Scheme<'_>,
                host: &<$domain as $crate::sdc::Domain>::Host,
                at: <$domain as $crate::sdc::Domain>::Position,
            ) -> <$domain as $crate::sdc::Domain>::Rule<$w> {
                $crate::sdc::Rules::<$domain, $w>::rule(scheme, host, at)
            }
        }
    )+};
}
pub(crate) use rule_weights;

/// Meshes with an extraordinary vertex or face: a rule gives the stencil of
/// the new vertex with this origin over the old mesh's vertices.
pub enum MeshDomain {}

impl Domain for MeshDomain {
    type Host = PolyMesh;
    type Position = Origin;
    type Rule<W: Weight> = RuleResult<W>;
    type Scheme<'a> = dyn Scheme + 'a;
}

rule_weights!(MeshDomain: f64, Rational, SmallRational, Interval, Cyclotomic, TPoly);

/// What a scheme is, as data: its identity, the host it refines on, the
/// centre it is analysed at, and what it can do beyond the common case. Every
/// built-in scheme states it once, as a `const`; engine and command line read
/// it through the accessors on `dyn Scheme`.
#[derive(Clone, Copy, Debug)]
pub struct SchemeInfo {
    pub name: &'static str,
    pub description: &'static str,
    pub topology: Topology,
    pub centre: CentreKind,
    /// The face type of the regular lattice around the centre.
    pub sector: SectorKind,
    pub caps: Caps,
}

/// Capabilities and requirements a scheme may have beyond the common case
/// (`Caps::NONE`): write `Caps { face_sequences: true, ..Caps::NONE }`.
#[derive(Clone, Copy, Debug)]
pub struct Caps {
    /// Meshes carry a face control vertex per face (non-box).
    pub face_control: bool,
    /// A parameter that may vary per vertex (`PolyMesh::vertex_params`),
    /// refined by `Scheme::vertex_param_rule`.
    pub vertex_param: Option<VertexParam>,
    /// The only valence the scheme is defined at (regular-lattice schemes: 4).
    pub fixed_valence: Option<usize>,
    /// The rules commute with the rotation of a symmetric configuration
    /// (false for asymmetric masks: then no Fourier blocks).
    pub rotation_symmetric: bool,
    /// Meshes must carry lattice directions (`PolyMesh::orient_lattice`).
    pub lattice_oriented: bool,
    /// The analysis accepts any sequence of quad and triangle sectors around
    /// the centre (`--faces`), not only the regular configuration.
    pub face_sequences: bool,
    /// What the scheme needs of an input mesh, for error messages of
    /// `refine`; `None`: derived from the host.
    pub mesh_requirement: Option<&'static str>,
    /// Why the scheme has no boundary rules here, for the open-mesh error.
    pub boundary_note: Option<&'static str>,
}

/// A parameter that may vary per vertex, with its admissible range (per-vertex
/// values read from a file are checked against it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexParam {
    pub name: &'static str,
    pub min: f64,
    pub max: f64,
}

impl Caps {
    /// A symmetric scheme on any valence with nothing extra.
    pub const NONE: Caps = Caps {
        face_control: false,
        vertex_param: None,
        fixed_valence: None,
        rotation_symmetric: true,
        lattice_oriented: false,
        face_sequences: false,
        mesh_requirement: None,
        boundary_note: None,
    };
}

/// A subdivision scheme: rules for every weight type (f64, exact rationals,
/// intervals, exact cyclotomic numbers), its description, its
/// parameter values, and the two behaviours some schemes add (a per-vertex
/// parameter rule, different rules at the first levels of a real mesh).
pub trait Scheme:
    Rules<MeshDomain, f64>
    + Rules<MeshDomain, Rational>
    + Rules<MeshDomain, SmallRational>
    + Rules<MeshDomain, Interval>
    + Rules<MeshDomain, Cyclotomic>
    + Rules<MeshDomain, TPoly>
    + Send
    + Sync
{
    fn info(&self) -> &SchemeInfo;
    fn params(&self) -> &Params;
    /// How the per-vertex parameter of a new vertex derives from the old ones
    /// (weights on old vertices); `None` where the scheme has no such parameter.
    fn vertex_param_rule(&self, _mesh: &PolyMesh, _origin: Origin) -> Option<Stencil<f64>> {
        None
    }
    /// The rules of refinement step `level` (1 = the first) of a real mesh, for
    /// schemes whose first steps differ from the stationary rules that the
    /// local subdivision matrix analyses; `None`: the same rules at every step.
    fn at_level(&self, _level: usize) -> Option<Box<dyn Scheme>> {
        None
    }
    /// What identifies these rules to results memoised across callers
    /// (`engine::memo`): equal identities must mean equal rules. `None`: never
    /// memoised. The default, name and parameter values, holds for a built-in
    /// whose rules depend on nothing else; a scheme read from a file (two files
    /// may share a name) or one with another input (a refinement level) says so.
    fn identity(&self) -> Option<String> {
        Some(format!("{} [{}]", self.info().name, self.params().identity_text()))
    }
}

/// Accessors to the description, so callers write `scheme.name()` rather
/// than `scheme.info().name` (defined on the trait object: the description
/// has one source, `Scheme::info`, which no scheme can contradict).
impl dyn Scheme + '_ {
    pub fn name(&self) -> &'static str {
        self.info().name
    }
    pub fn description(&self) -> &'static str {
        self.info().description
    }
    pub fn topology(&self) -> Topology {
        self.info().topology
    }
    pub fn centre_kind(&self) -> CentreKind {
        self.info().centre
    }
    pub fn sector_kind(&self) -> SectorKind {
        self.info().sector
    }
    pub fn face_control(&self) -> bool {
        self.info().caps.face_control
    }
    pub fn vertex_param(&self) -> Option<VertexParam> {
        self.info().caps.vertex_param
    }
    pub fn boundary_note(&self) -> Option<&'static str> {
        self.info().caps.boundary_note
    }
    pub fn fixed_valence(&self) -> Option<usize> {
        self.info().caps.fixed_valence
    }
    pub fn rotation_symmetric(&self) -> bool {
        self.info().caps.rotation_symmetric
    }
    pub fn lattice_oriented(&self) -> bool {
        self.info().caps.lattice_oriented
    }
    pub fn face_sequences(&self) -> bool {
        self.info().caps.face_sequences
    }
    pub fn mesh_requirement(&self) -> Option<&'static str> {
        self.info().caps.mesh_requirement
    }
}

/// Weight types every mesh scheme implements rules for ([`RuleWeight`] on the
/// mesh domain): lets generic code ask a `&dyn Scheme` for stencils of any of
/// them (f64, exact rationals, rationals in machine integers for the
/// certificate's many exact comparisons, interval enclosures, exact
/// cyclotomic numbers). `stencil` is the one entry point to the mesh rules:
/// results come back merged (duplicates summed, zeros dropped).
pub trait SchemeWeight: RuleWeight<MeshDomain> {
    fn rule(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> RuleResult<Self> {
        Self::rule_of(scheme, mesh, origin)
    }
    fn stencil(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> RuleResult<Self> {
        Ok(Self::rule(scheme, mesh, origin)?.map(Stencil::merged))
    }
}

impl<W: RuleWeight<MeshDomain>> SchemeWeight for W {}
