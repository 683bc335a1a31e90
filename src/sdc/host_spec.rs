//! What a refinement host declares (`HostSpec`): per origin kind
//! (`Origin::{Vertex, Edge, Face, Corner}`) its rules (`RuleSlots`) and each
//! rule's slot families (`Family`), with the const builders the host files
//! write them with. The gatherer and the weighing are in `sdc::slots`.

use crate::mesh::SectorKind;
use crate::sdc::centre::CentreKind;
use crate::sdc::host_list::Host;
use crate::sdc::stencil::Origin;

/// The kind of a refinement origin, without its mesh entities.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OriginKind {
    Vertex,
    Edge,
    Face,
    Corner,
}

impl OriginKind {
    pub fn of(origin: Origin) -> Self {
        match origin {
            Origin::Vertex(_) => OriginKind::Vertex,
            Origin::Edge(..) => OriginKind::Edge,
            Origin::Face(_) => OriginKind::Face,
            Origin::Corner { .. } => OriginKind::Corner,
        }
    }
}

/// How many vertices a slot family holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arity {
    /// a fixed number of slots, j = 0..k-1
    Fixed(usize),
    /// k slots per index j = 0..n-1 (n the rule's valence or face size)
    PerJ(usize),
    /// k slots per quad of a vertex's fan (j = the fan face's index): as
    /// many as the fan has quads, so their weights must sum to 0 per quad
    /// for the rule to stay affine
    PerQuad(usize),
    /// one slot per corner of each face the rule names (j = the face's
    /// index, the slot's `m` its corner count): `Some(k)` faces (the two
    /// faces of an edge), `None` one per j = 0..n-1 (the fan of a vertex).
    /// The faces may be any polygons, so a rule over general polygons (the
    /// centroids in Catmull–Clark's rules) needs no rule per face size
    FaceCorners(Option<usize>),
}

impl Arity {
    /// Slots of the family at valence (or face size) n when every face it
    /// names has m corners, for affine checks.
    pub fn count(self, n: usize, m: usize) -> usize {
        match self {
            Arity::Fixed(k) => k,
            Arity::PerJ(k) | Arity::PerQuad(k) => k * n,
            Arity::FaceCorners(_) => self.js(n) * m,
        }
    }
    /// The indices j a weight is asked for.
    pub fn js(self, n: usize) -> usize {
        match self {
            Arity::Fixed(k) | Arity::FaceCorners(Some(k)) => k,
            Arity::PerJ(_) | Arity::PerQuad(_) | Arity::FaceCorners(None) => n,
        }
    }
}

/// One family of slots of a rule.
#[derive(Debug)]
pub struct Family {
    pub name: &'static str,
    pub arity: Arity,
    /// a file may leave it out (then it is not gathered: the rule keeps its
    /// smaller stencil, e.g. the 1-ring edge rule without butterfly wings)
    pub optional: bool,
    /// the slots exist at quads only: in a rule that also has face-corner
    /// slots (and so takes any polygons), a face of another size has none
    pub quad_only: bool,
    pub doc: &'static str,
}

/// What `n` means in a rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Valence {
    /// the valence of the vertex (or the size of the face) concerned: a variable
    Any,
    /// no variable n; per-j families have this many slots
    Fixed(usize),
}

/// One rule of a host: the origin kind it serves and its slots.
#[derive(Debug)]
pub struct RuleSlots {
    pub name: &'static str,
    pub origin: OriginKind,
    pub families: &'static [Family],
    /// the rule may be absent from a file (then a fallback rule applies)
    pub optional: bool,
    /// j = 0 is a definite neighbour, so weights may depend on j
    pub canonical_j: bool,
    pub valence: Valence,
    pub doc: &'static str,
}

/// What a host is and which rules it has.
pub struct HostSpec {
    pub host: Host,
    /// the name scheme files use (`topology = "..."`)
    pub name: &'static str,
    pub sector: SectorKind,
    pub centre: CentreKind,
    /// meshes carry a face control vertex per face
    pub face_control: bool,
    pub rules: &'static [RuleSlots],
}

impl HostSpec {
    pub fn rule(&self, name: &str) -> Option<&'static RuleSlots> {
        self.rules.iter().find(|r| r.name == name)
    }
    /// The origin kinds the host creates, each once, in rule order.
    pub fn origins(&self) -> Vec<OriginKind> {
        let mut out: Vec<OriginKind> = Vec::new();
        for r in self.rules {
            if !out.contains(&r.origin) {
                out.push(r.origin);
            }
        }
        out
    }
}

pub(crate) const fn fam(name: &'static str, arity: Arity, doc: &'static str) -> Family {
    Family { name, arity, optional: false, quad_only: false, doc }
}

/// A family of the primal quad host whose slots exist at quads only.
pub(crate) const fn quad_fam(name: &'static str, arity: Arity, doc: &'static str) -> Family {
    Family { quad_only: true, ..fam(name, arity, doc) }
}

/// The corners of the faces of a primal quad rule, for masks over general
/// polygons. Optional: a mask without it keeps the quad-only rule (its
/// gatherer refuses other faces, as the quad scheme files expect).
pub(crate) const fn corner_family(arity: Arity, doc: &'static str) -> Family {
    Family { optional: true, ..fam("face-corner", arity, doc) }
}

pub(crate) const ONE: Arity = Arity::Fixed(1);
pub(crate) const PER_J: Arity = Arity::PerJ(1);

pub(crate) const fn rule(
    name: &'static str,
    origin: OriginKind,
    valence: Valence,
    families: &'static [Family],
    doc: &'static str,
) -> RuleSlots {
    RuleSlots { name, origin, families, optional: false, canonical_j: false, valence, doc }
}

/// An optional rule with a canonical j.
pub(crate) const fn canonical(
    name: &'static str,
    origin: OriginKind,
    families: &'static [Family],
    optional: bool,
    doc: &'static str,
) -> RuleSlots {
    RuleSlots { name, origin, families, optional, canonical_j: true, valence: Valence::Any, doc }
}

pub(crate) const QUAD_VERTEX: &[Family] = &[
    fam("centre", ONE, "the vertex v"),
    fam("edge", PER_J, "e_j, the other end of the j-th edge at v"),
    fam("face", PER_J, "f_j, the corner opposite v in the quad [v, e_j, f_j, e_{j+1}]"),
];
pub(crate) const TRI_VERTEX: &[Family] =
    &[fam("centre", ONE, "the vertex v"), fam("edge", PER_J, "e_j, v's j-th neighbour")];
