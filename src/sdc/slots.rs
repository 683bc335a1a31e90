//! Mask slots: the named neighbour positions a rule of each refinement host
//! weighs (OpenSubdiv's vertex/edge/face weights of a mask, CGAL's
//! `vertex_node`/`edge_node`/`corner_node`).
//!
//! A host declares, per origin kind (`Origin::{Vertex, Edge, Face, Corner}`),
//! its rules (`RuleSlots`) and each rule's slot families (`Family`): e.g. the
//! vertex rule of the primal quad split weighs the centre, the edge
//! neighbours e_j and the face-opposite neighbours f_j. [`gather`] maps the
//! slots of one origin to mesh vertices; a mask then only puts a weight on
//! every slot. The gatherer is the one place that walks the mesh, so a scheme
//! file and the built-in masks of the same shape need no gathering of their
//! own. Rules over general polygons weigh `face-corner` slots (every corner
//! of a face, with the face's corner count `Slot::m`), so that Catmull–Clark's
//! centroids of any m-gon are slot weights like the rest.
//!
//! Conventions: fans and rings run counter-clockwise as
//! `PolyMesh::vertex_fan` gives them. Where a rule says its j is canonical,
//! j = 0 is a definite neighbour (the edge's other end, the corner itself);
//! elsewhere the first neighbour is arbitrary and weights may not depend on j.

use crate::mesh::{FaceId, PolyMesh, SectorKind, VertexId};
use crate::numeric::{Inexact, Weight};
use crate::sdc::{CentreKind, Origin, RuleResult, Stencil, Topology, TriangleSplit};

/// Every refinement host a mask can be written for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Host {
    /// primal split, every face into quads around a face point (Catmull–Clark)
    PrimalQuad,
    /// primal split of triangles into 4 (Loop, butterfly)
    PrimalTriangle,
    /// primal split of quads and triangles together (4-3 subdivision)
    MixedQuadTriangle,
    /// quads around face control vertices (non-box)
    Fcv,
    /// dual split (Doo–Sabin)
    Dual,
    /// Kobbelt's sqrt(3) split
    Sqrt3,
    /// ternary quad split (TPS)
    Ternary,
    /// dual split plus central points (PGS)
    AugmentedDual,
    /// radial split of polar nets (polar bi-2)
    Polar,
}

pub const HOSTS: [Host; 9] = [
    Host::PrimalQuad,
    Host::PrimalTriangle,
    Host::MixedQuadTriangle,
    Host::Fcv,
    Host::Dual,
    Host::Sqrt3,
    Host::Ternary,
    Host::AugmentedDual,
    Host::Polar,
];

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
    pub topology: Topology,
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

const fn fam(name: &'static str, arity: Arity, doc: &'static str) -> Family {
    Family { name, arity, optional: false, quad_only: false, doc }
}

/// A family of the primal quad host whose slots exist at quads only.
const fn quad_fam(name: &'static str, arity: Arity, doc: &'static str) -> Family {
    Family { quad_only: true, ..fam(name, arity, doc) }
}

/// The corners of the faces of a primal quad rule, for masks over general
/// polygons. Optional: a mask without it keeps the quad-only rule (its
/// gatherer refuses other faces, as the quad scheme files expect).
const fn corner_family(arity: Arity, doc: &'static str) -> Family {
    Family { optional: true, ..fam("face-corner", arity, doc) }
}

const ONE: Arity = Arity::Fixed(1);
const PER_J: Arity = Arity::PerJ(1);

const fn rule(
    name: &'static str,
    origin: OriginKind,
    valence: Valence,
    families: &'static [Family],
    doc: &'static str,
) -> RuleSlots {
    RuleSlots { name, origin, families, optional: false, canonical_j: false, valence, doc }
}

/// An optional rule with a canonical j.
const fn canonical(
    name: &'static str,
    origin: OriginKind,
    families: &'static [Family],
    optional: bool,
    doc: &'static str,
) -> RuleSlots {
    RuleSlots { name, origin, families, optional, canonical_j: true, valence: Valence::Any, doc }
}

use OriginKind::{Corner as C, Edge as E, Face as F, Vertex as V};
use Valence::{Any, Fixed};

const QUAD_VERTEX: &[Family] = &[
    fam("centre", ONE, "the vertex v"),
    fam("edge", PER_J, "e_j, the other end of the j-th edge at v"),
    fam("face", PER_J, "f_j, the corner opposite v in the quad [v, e_j, f_j, e_{j+1}]"),
];
const TRI_VERTEX: &[Family] = &[fam("centre", ONE, "the vertex v"), fam("edge", PER_J, "e_j, v's j-th neighbour")];

const PRIMAL_QUAD: &[RuleSlots] = &[
    rule(
        "vertex",
        V,
        Any,
        &[
            fam("centre", ONE, "the vertex v"),
            fam("edge", PER_J, "e_j, the other end of the j-th edge at v"),
            quad_fam("face", PER_J, "f_j, the corner opposite v in the quad [v, e_j, f_j, e_{j+1}]"),
            corner_family(
                Arity::FaceCorners(None),
                "every corner of fan face j [v, e_j, ..., e_{j+1}] (v and e_j, e_{j+1} included), m its corner count",
            ),
        ],
        "the new vertex point of v (valence n; any polygons around v where the mask weighs face-corner)",
    ),
    rule(
        "edge",
        E,
        Fixed(4),
        &[
            fam("ends", Arity::Fixed(2), "the edge's two ends"),
            quad_fam("side", Arity::Fixed(4), "the two other corners of each of the edge's two quads"),
            corner_family(
                Arity::FaceCorners(Some(2)),
                "every corner of the edge's left (j = 0) and right (j = 1) face (the ends included), m its corner count",
            ),
        ],
        "the new edge point (between any polygons where the mask weighs face-corner)",
    ),
    canonical(
        "edge-extraordinary",
        E,
        QUAD_VERTEX,
        true,
        "the edge point seen from an extraordinary end v (valence n != 4); e_0 is the edge's other end",
    ),
    rule("face", F, Any, &[fam("corner", PER_J, "corner j of the n-gon")], "the face point of an n-gon"),
];

const PRIMAL_TRIANGLE: &[RuleSlots] = &[
    rule("vertex", V, Any, TRI_VERTEX, "the new vertex point of v (valence n)"),
    rule(
        "edge",
        E,
        Fixed(6),
        &[
            fam("ends", Arity::Fixed(2), "the edge's two ends"),
            fam("opposite", Arity::Fixed(2), "the apexes of the edge's two triangles"),
            Family {
                name: "wing",
                arity: Arity::Fixed(4),
                optional: true,
                quad_only: false,
                doc: "2-ring: the apexes of the four triangles across the other edges of the edge's two triangles \
                      (the butterfly's wings)",
            },
        ],
        "the new edge point",
    ),
    canonical(
        "edge-extraordinary",
        E,
        TRI_VERTEX,
        true,
        "the edge point seen from an extraordinary end v (valence n != 6); e_0 is the edge's other end",
    ),
];

const MIXED: &[RuleSlots] = &[
    rule("vertex-quad", V, Fixed(4), QUAD_VERTEX, "a vertex with 4 quads"),
    rule("vertex-triangle", V, Fixed(6), TRI_VERTEX, "a vertex with 6 triangles"),
    rule(
        "vertex-transition",
        V,
        Fixed(5),
        &[
            fam("centre", ONE, "the vertex v"),
            fam("between", ONE, "the neighbour between the two quads"),
            fam("boundary", Arity::Fixed(2), "the two neighbours on the quad/triangle boundary"),
            fam("triangle-side", Arity::Fixed(2), "the two other neighbours (triangle side)"),
        ],
        "a transition vertex: 2 quads then 3 triangles",
    ),
    rule(
        "vertex-eon",
        V,
        Any,
        &[
            fam("centre", ONE, "the vertex v"),
            fam("edge", PER_J, "e_j, v's j-th neighbour"),
            Family {
                name: "quad-opposite",
                arity: Arity::PerQuad(1),
                optional: true,
                quad_only: false,
                doc: "(4a') the corner w_i opposite v in each quad [v, e_i, w_i, e_{i+1}] of the fan",
            },
            Family {
                name: "quad-side",
                arity: Arity::PerQuad(2),
                optional: true,
                quad_only: false,
                doc: "(4a') e_i and e_{i+1} of each quad of the fan",
            },
        ],
        "any other vertex (an eon) of valence n; the quad families are blended in like [edge-eon]",
    ),
    rule(
        "edge-quad",
        E,
        Fixed(4),
        &[
            fam("ends", Arity::Fixed(2), "the edge's two ends"),
            fam("side", Arity::Fixed(4), "the two other corners of each quad"),
        ],
        "an edge between two quads",
    ),
    rule(
        "edge-triangle",
        E,
        Fixed(6),
        &[
            fam("ends", Arity::Fixed(2), "the edge's two ends"),
            fam("opposite", Arity::Fixed(2), "the apexes of the two triangles"),
        ],
        "an edge between two triangles",
    ),
    rule(
        "edge-mixed",
        E,
        Fixed(5),
        &[
            fam("ends", Arity::Fixed(2), "the edge's two ends"),
            fam("side", Arity::Fixed(2), "the quad's two other corners"),
            fam("opposite", ONE, "the triangle's apex"),
        ],
        "an edge between a quad and a triangle",
    ),
    canonical(
        "edge-eon",
        E,
        TRI_VERTEX,
        true,
        "the edge point seen from an eon v (valence n); e_0 is the edge's other end",
    ),
    rule("face", F, Any, &[fam("corner", PER_J, "corner j of the quad")], "the face point of a quad"),
];

const FCV: &[RuleSlots] = &[
    rule(
        "vertex",
        V,
        Any,
        &[fam("centre", ONE, "the vertex v"), fam("fcv", PER_J, "the FCV of fan face j")],
        "the new vertex point of v (valence n)",
    ),
    rule(
        "edge",
        E,
        Fixed(4),
        &[
            fam("ends", Arity::Fixed(2), "the edge's two ends"),
            fam("fcv", Arity::Fixed(2), "the FCVs of its two faces"),
        ],
        "the new edge point",
    ),
    rule(
        "face",
        F,
        Any,
        &[fam("centre", ONE, "the face's old FCV"), fam("corner", PER_J, "corner j of the n-gon")],
        "the new FCV of an old n-gon",
    ),
    rule(
        "corner",
        C,
        Any,
        &[
            fam("vertex", ONE, "the corner V_0"),
            fam("fcv", ONE, "the FCV of the face F_0"),
            fam("side", Arity::Fixed(2), "the FCVs of F_0's two neighbours at V_0"),
        ],
        "the FCV of the new quad at corner V_0 of face F_0 (an n-gon)",
    ),
];

const DUAL: &[RuleSlots] = &[canonical(
    "corner",
    C,
    &[fam("corner", PER_J, "c_j, the face's corners counter-clockwise from c_0, the corner itself")],
    false,
    "the new vertex near corner c_0 of an n-gon",
)];

const SQRT3: &[RuleSlots] = &[
    rule("vertex", V, Any, TRI_VERTEX, "the new position of old vertex v (valence n)"),
    rule(
        "face",
        F,
        Any,
        &[
            fam("corner", Arity::Fixed(3), "each corner P of the triangle; n is P's valence"),
            fam("ring", Arity::PerJ(3), "2-ring: each neighbour of each corner P; n is P's valence"),
        ],
        "the new vertex in a triangle, summed over its three corners P",
    ),
];

const TERNARY: &[RuleSlots] = &[
    rule("vertex", V, Any, QUAD_VERTEX, "the new position of old vertex v (valence n)"),
    rule(
        "edge",
        E,
        Fixed(4),
        &[
            fam("near", ONE, "the near end a of edge a-b"),
            fam("far", ONE, "the far end b"),
            fam("near-side", Arity::Fixed(2), "a's neighbours across the edge's two quads"),
            fam("far-side", Arity::Fixed(2), "b's neighbours across the edge's two quads"),
        ],
        "the new vertex on edge a-b near a",
    ),
    rule(
        "corner",
        C,
        Fixed(4),
        &[
            fam("near", ONE, "the quad's corner c_0"),
            fam("side", Arity::Fixed(2), "the corners c_1 and c_3 next to it"),
            fam("far", ONE, "the opposite corner c_2"),
        ],
        "the new interior vertex of a quad near its corner c_0",
    ),
];

const AUGMENTED: &[RuleSlots] = &[
    rule(
        "corner",
        C,
        Fixed(4),
        &[
            fam("vertex", ONE, "the corner c_0 (valence 4)"),
            fam("side", Arity::Fixed(2), "the corners c_1 and c_3 next to it"),
            fam("far", ONE, "the opposite corner c_2"),
        ],
        "the new vertex near corner c_0 of a quad without a central point",
    ),
    rule(
        "corner-augmented",
        C,
        Any,
        &[
            fam("vertex", ONE, "the corner c_0"),
            fam("side", Arity::Fixed(2), "the corners c_1 and c_{n-1} next to it"),
            fam("point", ONE, "the face's central point (or the [point] rule's point)"),
        ],
        "the new vertex near corner c_0 of an n-gon with a central point (or not a quad)",
    ),
    rule(
        "face",
        F,
        Any,
        &[
            fam("point", ONE, "the face's central point (or the [point] rule's point)"),
            fam("corner", PER_J, "corner j of the n-gon"),
        ],
        "the new central point of an n-gon",
    ),
    rule(
        "point",
        F,
        Any,
        &[
            fam("corner", PER_J, "corner a_j of the n-gon"),
            fam("outer", Arity::PerJ(2), "the two neighbours of a_j that are not corners of the face"),
        ],
        "the central point of an n-gon that has none, from the net (all corners valence 4)",
    ),
];

const POLAR: &[RuleSlots] = &[
    rule(
        "pole",
        V,
        Any,
        &[fam("centre", ONE, "the pole p"), fam("ring", PER_J, "the pole's j-th neighbour")],
        "the new pole (n spokes)",
    ),
    canonical(
        "spoke",
        E,
        &[fam("pole", ONE, "the pole p"), fam("ring", PER_J, "a_j, the pole's neighbours, a_0 the spoke's end")],
        false,
        "the new vertex on spoke p-a_0",
    ),
    rule(
        "radial",
        E,
        Fixed(2),
        &[fam("near", ONE, "the near end x of radial edge x-y"), fam("far", ONE, "the far end y")],
        "the new vertex on a radial edge near x (away from the pole)",
    ),
];

impl Host {
    pub fn spec(self) -> &'static HostSpec {
        const fn h(
            host: Host,
            name: &'static str,
            topology: Topology,
            sector: SectorKind,
            centre: CentreKind,
            rules: &'static [RuleSlots],
        ) -> HostSpec {
            HostSpec { host, name, topology, sector, centre, face_control: false, rules }
        }
        use CentreKind as K;
        use SectorKind::{Quad, Tri};
        static PQ: HostSpec = h(
            Host::PrimalQuad,
            "primal-quad",
            Topology::PrimalSplit(TriangleSplit::FacePointQuads),
            Quad,
            K::Vertex,
            PRIMAL_QUAD,
        );
        static PT: HostSpec = h(
            Host::PrimalTriangle,
            "primal-triangle",
            Topology::PrimalSplit(TriangleSplit::FourTriangles),
            Tri,
            K::Vertex,
            PRIMAL_TRIANGLE,
        );
        static MX: HostSpec = h(
            Host::MixedQuadTriangle,
            "mixed-quad-triangle",
            Topology::PrimalSplit(TriangleSplit::FourTriangles),
            Quad,
            K::Vertex,
            MIXED,
        );
        static FC: HostSpec = HostSpec {
            host: Host::Fcv,
            name: "fcv",
            topology: Topology::FcvSplit,
            sector: Quad,
            centre: K::Vertex,
            face_control: true,
            rules: FCV,
        };
        static DU: HostSpec = h(Host::Dual, "dual", Topology::Dual, Quad, K::Face, DUAL);
        static S3: HostSpec = h(Host::Sqrt3, "sqrt3", Topology::Sqrt3, Tri, K::Vertex, SQRT3);
        static TE: HostSpec = h(Host::Ternary, "ternary", Topology::TernarySplit, Quad, K::Vertex, TERNARY);
        static AD: HostSpec =
            h(Host::AugmentedDual, "augmented-dual", Topology::AugmentedDual, Quad, K::AugmentedFace, AUGMENTED);
        static PO: HostSpec = h(Host::Polar, "polar", Topology::PolarSplit, Tri, K::Polar, POLAR);
        match self {
            Host::PrimalQuad => &PQ,
            Host::PrimalTriangle => &PT,
            Host::MixedQuadTriangle => &MX,
            Host::Fcv => &FC,
            Host::Dual => &DU,
            Host::Sqrt3 => &S3,
            Host::Ternary => &TE,
            Host::AugmentedDual => &AD,
            Host::Polar => &PO,
        }
    }

    pub fn by_name(name: &str) -> Option<Host> {
        HOSTS.iter().copied().find(|h| h.spec().name == name)
    }
}

/// A mask: a weight for every slot of the rules it has. Built-in schemes and
/// scheme files are both masks over the same slots, so neither gathers
/// neighbours itself: `weigh` gathers, the mask only weighs.
pub trait Mask<W: Weight>: Wants {
    /// The weight of `slot` of rule `rule` (`slot.n` is the valence or face
    /// size it is evaluated at, `slot.j` its index in its family).
    fn weight(&self, mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact>;
}

/// The stencil of `origin` on `host` under `mask`: the host's slots of the
/// origin, weighed. `extraordinary_share` is the share of the rules of
/// extraordinary vertices that replace a regular rule (1 for stationary
/// rules; less over the first steps of a real mesh where a scheme blends
/// them in, as 4-3 does). `Ok(None)` where the neighbourhood is truncated,
/// not covered by the host's rules, or of an origin the host never creates.
pub fn weigh<W: Weight>(
    host: Host,
    mesh: &PolyMesh,
    origin: Origin,
    mask: &dyn Mask<W>,
    extraordinary_share: &W,
) -> RuleResult<W> {
    let Ok(g) = gather(host, mesh, origin, mask) else { return Ok(None) };
    // one term per direct slot (a derived point adds its own): no regrowth
    let slots = g.parts.iter().chain(&g.extraordinary).chain(&g.regular).map(|p| p.slots.len()).sum();
    let mut s = Stencil { terms: Vec::with_capacity(slots) };
    for part in &g.parts {
        fill(mask, mesh, &mut s, part, &W::one())?;
    }
    for part in &g.extraordinary {
        fill(mask, mesh, &mut s, part, extraordinary_share)?;
    }
    if let Some(regular) = g.regular.as_ref().filter(|_| !g.extraordinary.is_empty()) {
        let rest = W::one() - extraordinary_share.clone();
        if !rest.is_zero() {
            fill(mask, mesh, &mut s, regular, &rest)?;
        }
    }
    Ok(Some(s))
}

/// Add `scale` times the weighed slots of `part` to `s`.
fn fill<W: Weight>(
    mask: &dyn Mask<W>,
    mesh: &PolyMesh,
    s: &mut Stencil<W>,
    part: &Part,
    scale: &W,
) -> Result<(), Inexact> {
    let scale = scale.clone() * W::ratio(part.scale.0, part.scale.1);
    for slot in &part.slots {
        let w = mask.weight(mesh, part.rule, slot)? * scale.clone();
        match &slot.target {
            Target::Vertex(v) => s.add(*v, w),
            Target::Derived(p) => fill(mask, mesh, s, p, &w)?,
        }
    }
    Ok(())
}

/// Which rules and optional families a mask has: the gatherer collects only
/// what is weighed (a 2-ring family costs a larger neighbourhood).
pub trait Wants {
    fn rule(&self, rule: &str) -> bool;
    fn family(&self, rule: &str, family: &str) -> bool;
}

/// Why an origin's slots could not be gathered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GatherError {
    /// the mesh ends before the neighbourhood the rule weighs (boundary of a
    /// truncated patch)
    Truncated,
    /// the neighbourhood is complete but of a shape the host's rules do not
    /// cover (a face size or valence outside the host)
    NotCovered,
    /// the host never creates this kind of origin
    Unsupported(Host, OriginKind),
}

impl std::fmt::Display for GatherError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GatherError::Truncated => write!(f, "the neighbourhood is truncated"),
            GatherError::NotCovered => write!(f, "no rule of the host covers this neighbourhood"),
            GatherError::Unsupported(h, o) => write!(f, "host {} creates no {o:?} points", h.spec().name),
        }
    }
}

/// Where a slot's weight goes.
#[derive(Clone, Debug, PartialEq)]
pub enum Target {
    Vertex(VertexId),
    /// a point that is itself a combination of mesh vertices (PGS: the central
    /// point of a face that has none, given by the host's `point` rule)
    Derived(Box<Part>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Slot {
    pub family: &'static str,
    pub j: usize,
    /// the valence (or face size) the slot's weight is evaluated at
    pub n: usize,
    /// the vertex concerned (whose valence n is, and whose per-vertex
    /// parameters the weight takes): the centre of a vertex rule, the corner
    /// P of a sqrt(3) face rule, the extraordinary end of an edge rule;
    /// `None` where a rule concerns no single vertex (regular edges, faces)
    pub at: Option<VertexId>,
    /// the corner count of the face a face-corner slot lies in (its own for
    /// each face of a vertex's fan or an edge); `None` for other slots
    pub m: Option<usize>,
    pub target: Target,
}

/// One rule applied to one neighbourhood, scaled by `scale` (num, den).
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    pub rule: &'static str,
    pub n: usize,
    /// the vertex concerned, for the slots put from now on (see `Slot::at`)
    pub at: Option<VertexId>,
    pub scale: (i64, i64),
    pub slots: Vec<Slot>,
}

impl Part {
    fn new(rule: &'static str, n: usize) -> Self {
        Part { rule, n, at: None, scale: (1, 1), slots: Vec::new() }
    }
    /// A rule about vertex `v` (of valence n).
    fn around(rule: &'static str, n: usize, v: VertexId) -> Self {
        Part { at: Some(v), ..Part::new(rule, n) }
    }
    fn put(&mut self, family: &'static str, j: usize, v: VertexId) {
        self.slots.push(Slot { family, j, n: self.n, at: self.at, m: None, target: Target::Vertex(v) });
    }
    /// A slot of the neighbourhood of vertex `at` (valence n) inside a larger rule.
    fn put_around(&mut self, family: &'static str, j: usize, n: usize, at: VertexId, v: VertexId) {
        self.slots.push(Slot { family, j, n, at: Some(at), m: None, target: Target::Vertex(v) });
    }
    fn put_target(&mut self, family: &'static str, target: Target) {
        self.slots.push(Slot { family, j: 0, n: self.n, at: self.at, m: None, target });
    }
    /// The face-corner slots of face j: its corners from `start` on.
    fn put_face_corners(&mut self, j: usize, face: &[VertexId], start: usize) {
        let m = face.len();
        for t in 0..m {
            let target = Target::Vertex(face[(start + t) % m]);
            self.slots.push(Slot { family: "face-corner", j, n: self.n, at: self.at, m: Some(m), target });
        }
    }
    fn scaled(mut self, num: i64, den: i64) -> Self {
        self.scale = (num, den);
        self
    }
}

/// The slots of one origin: the sum of `parts` and `extraordinary`.
/// `extraordinary` holds the rules of extraordinary vertices that a mask may
/// blend in over a real mesh's first steps (4-3): an edge at an
/// extraordinary vertex (the mean of the two ends' rules where both are),
/// then with `regular`, the regular rule of the same edge that they replace;
/// 4-3's quad term (4a') at an eon.
#[derive(Clone, Debug, PartialEq)]
pub struct Gathered {
    pub parts: Vec<Part>,
    pub extraordinary: Vec<Part>,
    pub regular: Option<Part>,
}

impl Gathered {
    fn one(part: Part) -> Self {
        Gathered { parts: vec![part], extraordinary: Vec::new(), regular: None }
    }
    fn replacing(extraordinary: Vec<Part>, regular: Part) -> Self {
        Gathered { parts: Vec::new(), extraordinary, regular: Some(regular) }
    }
}

type Gather = Result<Gathered, GatherError>;

/// The closed fan of v; `Truncated` when v is on the boundary.
fn fan(mesh: &PolyMesh, v: VertexId) -> Result<Vec<Vec<VertexId>>, GatherError> {
    mesh.vertex_fan(v).ok_or(GatherError::Truncated)
}

/// The closed fan of v when all its faces have `size` corners.
fn uniform_fan(mesh: &PolyMesh, v: VertexId, size: usize) -> Result<Vec<Vec<VertexId>>, GatherError> {
    let fan = fan(mesh, v)?;
    if fan.iter().all(|f| f.len() == size) {
        Ok(fan)
    } else {
        Err(GatherError::NotCovered)
    }
}

/// The faces on both sides of edge a-b, as cycles from a (left, holding
/// a -> b) and from b (right, holding b -> a).
fn edge_faces(mesh: &PolyMesh, a: VertexId, b: VertexId) -> Result<(Vec<VertexId>, Vec<VertexId>), GatherError> {
    let ((fl, kl), (fr, kr)) =
        (mesh.half_edge(a, b).ok_or(GatherError::Truncated)?, mesh.half_edge(b, a).ok_or(GatherError::Truncated)?);
    Ok((mesh.face_from(fl, kl), mesh.face_from(fr, kr)))
}

fn sized(cycles: [&[VertexId]; 2], size: usize) -> Result<(), GatherError> {
    if cycles.iter().all(|c| c.len() == size) {
        Ok(())
    } else {
        Err(GatherError::NotCovered)
    }
}

/// Gather the slots of `origin` for host `host`, only the rules and optional
/// families `wants` names.
pub fn gather(host: Host, mesh: &PolyMesh, origin: Origin, wants: &dyn Wants) -> Gather {
    let unsupported = Err(GatherError::Unsupported(host, OriginKind::of(origin)));
    match host {
        Host::PrimalQuad => match origin {
            // a mask that weighs the fan faces' corners takes any polygons;
            // without them the rule is written for quads and refuses others
            Origin::Vertex(v) => match wants.family("vertex", "face-corner") {
                true => polygon_vertex(mesh, v, wants.family("vertex", "face")),
                false => vertex_fan_part("vertex", mesh, v, Some(4)),
            }
            .map(Gathered::one),
            Origin::Edge(a, b) => primal_edge(mesh, a, b, 4, wants),
            Origin::Face(f) => Ok(Gathered::one(face_corners("face", mesh, f))),
            Origin::Corner { .. } => unsupported,
        },
        Host::PrimalTriangle => match origin {
            Origin::Vertex(v) => vertex_fan_part("vertex", mesh, v, Some(3)).map(Gathered::one),
            Origin::Edge(a, b) => primal_edge(mesh, a, b, 3, wants),
            Origin::Face(_) | Origin::Corner { .. } => unsupported,
        },
        Host::MixedQuadTriangle => match origin {
            Origin::Vertex(v) => mixed_vertex(mesh, v, wants),
            Origin::Edge(a, b) => mixed_edge(mesh, a, b, wants),
            Origin::Face(f) => {
                if mesh.face(f).len() != 4 {
                    return Err(GatherError::NotCovered);
                }
                Ok(Gathered::one(face_corners("face", mesh, f)))
            }
            Origin::Corner { .. } => unsupported,
        },
        Host::Fcv => fcv(mesh, origin).map(Gathered::one),
        Host::Dual => match origin {
            Origin::Corner { face, corner } => {
                let cyc = mesh.face_from(face, corner);
                let mut p = Part::new("corner", cyc.len());
                cyc.iter().enumerate().for_each(|(j, &c)| p.put("corner", j, c));
                Ok(Gathered::one(p))
            }
            Origin::Vertex(_) | Origin::Edge(..) | Origin::Face(_) => unsupported,
        },
        Host::Sqrt3 => match origin {
            Origin::Vertex(v) => vertex_fan_part("vertex", mesh, v, Some(3)).map(Gathered::one),
            Origin::Face(f) => sqrt3_face(mesh, f).map(Gathered::one),
            Origin::Edge(..) | Origin::Corner { .. } => unsupported,
        },
        Host::Ternary => match origin {
            Origin::Vertex(v) => vertex_fan_part("vertex", mesh, v, Some(4)).map(Gathered::one),
            Origin::Edge(a, b) => {
                let (l, r) = edge_faces(mesh, a, b)?;
                sized([&l, &r], 4)?;
                let mut p = Part::new("edge", 4);
                p.put("near", 0, a);
                p.put("far", 0, b);
                p.put("near-side", 0, l[3]);
                p.put("near-side", 1, r[2]);
                p.put("far-side", 0, l[2]);
                p.put("far-side", 1, r[3]);
                Ok(Gathered::one(p))
            }
            Origin::Corner { face, corner } => {
                let c = mesh.face_from(face, corner);
                if c.len() != 4 {
                    return Err(GatherError::NotCovered);
                }
                Ok(Gathered::one(quad_corner("corner", "near", &c)))
            }
            Origin::Face(_) => unsupported,
        },
        Host::AugmentedDual => match origin {
            Origin::Corner { face, corner } => {
                let c = mesh.face_from(face, corner);
                if !augmented(mesh, face) {
                    // a Doo–Sabin net has valence-4 vertices only (a vertex on
                    // the rim of a truncated patch has no fan: allowed)
                    if mesh.valence(c[0]).is_some_and(|k| k != 4) {
                        return Err(GatherError::NotCovered);
                    }
                    return Ok(Gathered::one(quad_corner("corner", "vertex", &c)));
                }
                let mut p = Part::new("corner-augmented", c.len());
                p.put("vertex", 0, c[0]);
                p.put("side", 0, c[1]);
                p.put("side", 1, c[c.len() - 1]);
                p.put_target("point", central_point(mesh, face)?);
                Ok(Gathered::one(p))
            }
            Origin::Face(f) => {
                let mut p = face_corners("face", mesh, f);
                p.put_target("point", central_point(mesh, f)?);
                Ok(Gathered::one(p))
            }
            Origin::Vertex(_) | Origin::Edge(..) => unsupported,
        },
        Host::Polar => match origin {
            Origin::Vertex(p) => {
                mesh.fan_corners(p).ok_or(GatherError::Truncated)?;
                let ring = mesh.uniform_ring(p, 3).ok_or(GatherError::NotCovered)?;
                let mut part = Part::around("pole", ring.len(), p);
                part.put("centre", 0, p);
                ring.iter().enumerate().for_each(|(j, &a)| part.put("ring", j, a));
                Ok(Gathered::one(part))
            }
            // the pole's ring from the mesh's cached fan: every spoke point asks
            // for it, and copying the fan each time would be quadratic in n
            Origin::Edge(x, y) => match mesh.uniform_ring(x, 3) {
                // x is a pole: the spoke rule, ring turned so that a_0 = y
                Some(ring) => {
                    let n = ring.len();
                    let i = ring.iter().position(|&a| a == y).ok_or(GatherError::NotCovered)?;
                    let mut part = Part::around("spoke", n, x);
                    part.put("pole", 0, x);
                    (0..n).for_each(|j| part.put("ring", j, ring[(i + j) % n]));
                    Ok(Gathered::one(part))
                }
                None => {
                    let mut part = Part::new("radial", 2);
                    part.put("near", 0, x);
                    part.put("far", 0, y);
                    Ok(Gathered::one(part))
                }
            },
            Origin::Face(_) | Origin::Corner { .. } => unsupported,
        },
    }
}

/// v and its fan: centre, edge neighbours e_j = fan[j][1] and, for quads,
/// face-opposite neighbours f_j = fan[j][2]. `size`: the faces must all have
/// this many corners.
fn vertex_fan_part(rule: &'static str, mesh: &PolyMesh, v: VertexId, size: Option<usize>) -> Result<Part, GatherError> {
    // the fan as (face, corner) pairs from the mesh's cache, without copying faces
    let fan = mesh.fan_corners(v).ok_or(GatherError::Truncated)?;
    if size.is_some_and(|s| fan.iter().any(|&(f, _)| mesh.face(f).len() != s)) {
        return Err(GatherError::NotCovered);
    }
    let mut p = Part::around(rule, fan.len(), v);
    p.put("centre", 0, v);
    for (j, &(f, k)) in fan.iter().enumerate() {
        let face = mesh.face(f);
        p.put("edge", j, face[(k + 1) % face.len()]);
        if face.len() == 4 {
            p.put("face", j, face[(k + 2) % 4]);
        }
    }
    Ok(p)
}

/// The primal quad vertex rule over any polygons: per fan face j its
/// corners from v on, then e_j, then (at a quad, if weighed) f_j. Face j's
/// corners come before e_j so that each vertex's weights add up in the order
/// of the face-point-then-edge-midpoint formulas they come from.
fn polygon_vertex(mesh: &PolyMesh, v: VertexId, opposite: bool) -> Result<Part, GatherError> {
    let fan = mesh.fan_corners(v).ok_or(GatherError::Truncated)?;
    let mut p = Part::around("vertex", fan.len(), v);
    p.slots.reserve(1 + 2 * fan.len() + fan.iter().map(|&(f, _)| mesh.face(f).len()).sum::<usize>());
    p.put("centre", 0, v);
    for (j, &(f, k)) in fan.iter().enumerate() {
        let face = mesh.face(f);
        p.put_face_corners(j, face, k);
        p.put("edge", j, face[(k + 1) % face.len()]);
        if opposite && face.len() == 4 {
            p.put("face", j, face[(k + 2) % 4]);
        }
    }
    Ok(p)
}

/// Corner j of face f.
fn face_corners(rule: &'static str, mesh: &PolyMesh, f: FaceId) -> Part {
    let face = mesh.face(f);
    let mut p = Part::new(rule, face.len());
    face.iter().enumerate().for_each(|(j, &c)| p.put("corner", j, c));
    p
}

/// A quad cycle c from the corner: `own` c_0, side c_1 and c_3, far c_2.
fn quad_corner(rule: &'static str, own: &'static str, c: &[VertexId]) -> Part {
    let mut p = Part::new(rule, 4);
    p.put(own, 0, c[0]);
    p.put("side", 0, c[1]);
    p.put("side", 1, c[3]);
    p.put("far", 0, c[2]);
    p
}

/// Whether vertex v is extraordinary for a primal host: a closed fan of
/// `size`-gons whose count is not the regular valence. (Vertices with open
/// fans, such as the rim of a truncated neighbourhood, lie in the regular part.)
fn extraordinary(mesh: &PolyMesh, v: VertexId, size: usize) -> bool {
    let regular = if size == 4 { 4 } else { 6 };
    // from the cached fan: every edge at v asks, so copying the fan would cost valence²
    mesh.fan_corners(v).is_some_and(|fan| fan.len() != regular && fan.iter().all(|&(f, _)| mesh.face(f).len() == size))
}

/// The `rule` seen from end v of edge v-other: v and its fan turned so that
/// e_0 = other.
/// `size`: the faces must all have this many corners, and quads add their
/// face-opposite corners f_j; `None`: any faces, edge neighbours only.
fn ev_part(
    rule: &'static str,
    mesh: &PolyMesh,
    v: VertexId,
    other: VertexId,
    size: Option<usize>,
) -> Result<Part, GatherError> {
    let fan = match size {
        Some(s) => uniform_fan(mesh, v, s)?,
        None => fan(mesh, v)?,
    };
    let n = fan.len();
    let start = fan.iter().position(|f| f[1] == other).ok_or(GatherError::NotCovered)?;
    let mut p = Part::around(rule, n, v);
    p.put("centre", 0, v);
    for j in 0..n {
        let face = &fan[(start + j) % n];
        p.put("edge", j, face[1]);
        if size == Some(4) {
            p.put("face", j, face[2]);
        }
    }
    Ok(p)
}

/// The apex of the triangle on the other side of the triangle edge p -> q.
fn across(mesh: &PolyMesh, p: VertexId, q: VertexId) -> Result<VertexId, GatherError> {
    let (g, k) = mesh.half_edge(q, p).ok_or(GatherError::Truncated)?;
    let c = mesh.face_from(g, k);
    if c.len() != 3 {
        return Err(GatherError::NotCovered);
    }
    Ok(c[2])
}

fn primal_edge(mesh: &PolyMesh, a: VertexId, b: VertexId, size: usize, wants: &dyn Wants) -> Gather {
    // the two faces in the mesh's storage, each with the index of the edge's
    // first end (every edge point asks: no copies of the faces)
    let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
        return Err(GatherError::Truncated);
    };
    let (l, r) = (mesh.face(fl), mesh.face(fr));
    // corner t of a face counted from the edge's first end
    let at = |face: &[VertexId], k: usize, t: usize| face[(k + t) % face.len()];
    // a quad mask that weighs the two faces' corners takes any polygons
    let polygons = size == 4 && wants.family("edge", "face-corner");
    if !polygons {
        sized([l, r], size)?;
    }
    // (a quad mask always weighs `side`; a polygon mask may not)
    let sides = !polygons || wants.family("edge", "side");
    let mut p = Part::new("edge", if size == 4 { 4 } else { 6 });
    if polygons {
        p.slots.reserve(6 + l.len() + r.len());
    }
    p.put("ends", 0, a);
    p.put("ends", 1, b);
    if size == 4 {
        for (i, (face, k)) in [(l, kl), (r, kr)].into_iter().enumerate() {
            // side slots 0, 1 on the left quad, 2, 3 on the right one
            if sides && face.len() == 4 {
                p.put("side", 2 * i, at(face, k, 2));
                p.put("side", 2 * i + 1, at(face, k, 3));
            }
            if polygons {
                p.put_face_corners(i, face, k);
            }
        }
    } else {
        let (c, d) = (at(l, kl, 2), at(r, kr, 2));
        p.put("opposite", 0, c);
        p.put("opposite", 1, d);
        if wants.family("edge", "wing") {
            // left (a, b, c), right (b, a, d): across b-c, c-a, a-d, d-b
            let wings = [across(mesh, b, c)?, across(mesh, c, a)?, across(mesh, a, d)?, across(mesh, d, b)?];
            wings.iter().enumerate().for_each(|(j, &v)| p.put("wing", j, v));
        }
    }
    const EV: &str = "edge-extraordinary";
    if !wants.rule(EV) {
        return Ok(Gathered::one(p));
    }
    let parts = match (extraordinary(mesh, a, size), extraordinary(mesh, b, size)) {
        (false, false) => return Ok(Gathered::one(p)),
        (true, false) => vec![ev_part(EV, mesh, a, b, Some(size))?],
        (false, true) => vec![ev_part(EV, mesh, b, a, Some(size))?],
        // both ends extraordinary: the mean of the two ends' rules (Zorin's
        // convention for the modified butterfly, and our choice here)
        (true, true) => {
            vec![ev_part(EV, mesh, a, b, Some(size))?.scaled(1, 2), ev_part(EV, mesh, b, a, Some(size))?.scaled(1, 2)]
        }
    };
    Ok(Gathered::replacing(parts, p))
}

fn mixed_vertex(mesh: &PolyMesh, v: VertexId, wants: &dyn Wants) -> Gather {
    let (fan, t) = classify(mesh, v).ok_or_else(|| match mesh.vertex_fan(v) {
        None => GatherError::Truncated,
        Some(_) => GatherError::NotCovered,
    })?;
    let n = fan.len();
    let u = |i: usize| fan[i % n][1];
    Ok(Gathered::one(match t {
        NodeType::RegularQuad => vertex_fan_part("vertex-quad", mesh, v, Some(4))?,
        NodeType::RegularTri => vertex_fan_part("vertex-triangle", mesh, v, Some(3))?,
        NodeType::Transition { k } => {
            let mut p = Part::around("vertex-transition", 5, v);
            p.put("centre", 0, v);
            p.put("between", 0, u(k + 1));
            p.put("boundary", 0, u(k));
            p.put("boundary", 1, u(k + 2));
            p.put("triangle-side", 0, u(k + 3));
            p.put("triangle-side", 1, u(k + 4));
            p
        }
        NodeType::Eon => {
            let mut p = Part::around("vertex-eon", n, v);
            p.put("centre", 0, v);
            (0..n).for_each(|j| p.put("edge", j, u(j)));
            const EON: &str = "vertex-eon";
            let (opposite, side) = (wants.family(EON, "quad-opposite"), wants.family(EON, "quad-side"));
            if !opposite && !side {
                return Ok(Gathered::one(p));
            }
            // (4a'): per quad face i = [v, u_i, w_i, u_{i+1}] of the fan
            let mut quads = Part::around(EON, n, v);
            for (i, f) in fan.iter().enumerate().filter(|(_, f)| f.len() == 4) {
                if opposite {
                    quads.put("quad-opposite", i, f[2]);
                }
                if side {
                    quads.put("quad-side", i, f[1]);
                    quads.put("quad-side", i, f[3]);
                }
            }
            return Ok(Gathered { parts: vec![p], extraordinary: vec![quads], regular: None });
        }
    }))
}

fn mixed_edge(mesh: &PolyMesh, a: VertexId, b: VertexId, wants: &dyn Wants) -> Gather {
    let (l, r) = edge_faces(mesh, a, b)?;
    if [&l, &r].iter().any(|f| f.len() != 3 && f.len() != 4) {
        return Err(GatherError::NotCovered);
    }
    // whether an end is an eon decides the rule: both ends must be classifiable
    let kind = |v: VertexId| classify(mesh, v).map(|(_, t)| t).ok_or(GatherError::Truncated);
    let (ta, tb) = (kind(a)?, kind(b)?);
    let regular = match (l.len(), r.len()) {
        (4, 4) => {
            let mut p = Part::new("edge-quad", 4);
            [l[2], l[3], r[2], r[3]].iter().enumerate().for_each(|(j, &v)| p.put("side", j, v));
            p
        }
        (3, 3) => {
            let mut p = Part::new("edge-triangle", 6);
            p.put("opposite", 0, l[2]);
            p.put("opposite", 1, r[2]);
            p
        }
        _ => {
            let (quad, tri) = if l.len() == 4 { (&l, &r) } else { (&r, &l) };
            let mut p = Part::new("edge-mixed", 5);
            p.put("side", 0, quad[2]);
            p.put("side", 1, quad[3]);
            p.put("opposite", 0, tri[2]);
            p
        }
    };
    let mut regular = regular;
    regular.put("ends", 0, a);
    regular.put("ends", 1, b);
    const EON: &str = "edge-eon";
    let eons: Vec<(VertexId, VertexId)> =
        [(a, b, &ta), (b, a, &tb)].into_iter().filter(|t| *t.2 == NodeType::Eon).map(|t| (t.0, t.1)).collect();
    if eons.is_empty() || !wants.rule(EON) {
        return Ok(Gathered::one(regular));
    }
    let k = eons.len() as i64;
    let parts = eons
        .into_iter()
        .map(|(e, other)| ev_part(EON, mesh, e, other, None).map(|p| p.scaled(1, k)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Gathered::replacing(parts, regular))
}

fn fcv(mesh: &PolyMesh, origin: Origin) -> Result<Part, GatherError> {
    if !mesh.has_face_point_on_every_face() {
        return Err(GatherError::NotCovered);
    }
    let point = |a: VertexId, b: VertexId| mesh.face_point_left_of(a, b).ok_or(GatherError::Truncated);
    match origin {
        Origin::Vertex(v) => {
            let fan = fan(mesh, v)?;
            let mut p = Part::around("vertex", fan.len(), v);
            p.put("centre", 0, v);
            for (j, cyc) in fan.iter().enumerate() {
                p.put("fcv", j, point(v, cyc[1])?);
            }
            Ok(p)
        }
        Origin::Edge(a, b) => {
            let mut p = Part::new("edge", 4);
            p.put("ends", 0, a);
            p.put("ends", 1, b);
            p.put("fcv", 0, point(a, b)?);
            p.put("fcv", 1, point(b, a)?);
            Ok(p)
        }
        Origin::Face(f) => {
            let mut p = face_corners("face", mesh, f);
            p.put("centre", 0, mesh.face_point(f).ok_or(GatherError::Truncated)?);
            Ok(p)
        }
        Origin::Corner { face: f, corner: k } => {
            let cyc = mesh.face_from(f, k);
            let (v0, next, prev) = (cyc[0], cyc[1], cyc[cyc.len() - 1]);
            let mut p = Part::new("corner", cyc.len());
            p.put("vertex", 0, v0);
            p.put("fcv", 0, mesh.face_point(f).ok_or(GatherError::Truncated)?);
            // the old faces at V_0 next to F_0: across (V_0, next) and across (prev, V_0)
            p.put("side", 0, point(next, v0)?);
            p.put("side", 1, point(v0, prev)?);
            Ok(p)
        }
    }
}

/// The triangle's corners P and their rings, each slot at P's valence.
fn sqrt3_face(mesh: &PolyMesh, f: FaceId) -> Result<Part, GatherError> {
    let face = mesh.face(f);
    if face.len() != 3 {
        return Err(GatherError::NotCovered);
    }
    let mut p = Part::new("face", 3);
    for (k, &c) in face.iter().enumerate() {
        // the ring from the mesh's cached fan: a corner of valence n is asked
        // for by its n faces, so copying its whole fan each time would cost n²
        mesh.fan_corners(c).ok_or(GatherError::Truncated)?;
        let ring = mesh.uniform_ring(c, 3).ok_or(GatherError::NotCovered)?;
        let n = ring.len();
        p.put_around("corner", k, n, c, c);
        ring.iter().enumerate().for_each(|(j, &t)| p.put_around("ring", j, n, c, t));
    }
    Ok(p)
}

/// Whether a face of a point-augmented net carries (or gets) a central point.
fn augmented(mesh: &PolyMesh, f: FaceId) -> bool {
    mesh.face_point(f).is_some() || mesh.face(f).len() != 4
}

/// The central point of face f: its own point, or the `point` rule over the
/// net (corners a_j of valence 4 and their two neighbours off the face).
fn central_point(mesh: &PolyMesh, f: FaceId) -> Result<Target, GatherError> {
    if let Some(p) = mesh.face_point(f) {
        return Ok(Target::Vertex(p));
    }
    let face = mesh.face(f);
    let m = face.len();
    let mut p = Part::new("point", m);
    for (k, &a) in face.iter().enumerate() {
        let (prev, next) = (face[(k + m - 1) % m], face[(k + 1) % m]);
        let fan = fan(mesh, a)?;
        if fan.len() != 4 {
            return Err(GatherError::NotCovered);
        }
        p.put("corner", k, a);
        for cyc in fan.iter().filter(|c| c[1] != prev && c[1] != next) {
            p.put("outer", k, cyc[1]);
        }
    }
    Ok(Target::Derived(Box::new(p)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every rule's families are named once, and every host creates the
    /// origins its topology refines to (the rules cover them).
    #[test]
    fn hosts_declare_distinct_rules_and_families() {
        for h in HOSTS {
            let spec = h.spec();
            assert_eq!(spec.host, h);
            assert_eq!(Host::by_name(spec.name), Some(h));
            for (i, r) in spec.rules.iter().enumerate() {
                assert!(spec.rules[..i].iter().all(|q| q.name != r.name), "{}: {}", spec.name, r.name);
                for (k, f) in r.families.iter().enumerate() {
                    assert!(r.families[..k].iter().all(|g| g.name != f.name), "{}.{}", r.name, f.name);
                }
            }
            assert!(!spec.origins().is_empty());
        }
    }
}

/// What the vertex rules of a quad/triangle mesh (4-3 subdivision) see at a
/// vertex.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NodeType {
    RegularQuad,
    RegularTri,
    /// fan faces `k` and `k + 1` are the two quads
    Transition {
        k: usize,
    },
    Eon,
}

/// The fan of an interior vertex whose faces are all quads or triangles, and its
/// node type; `None` on the boundary or next to a face of another size.
pub fn classify(mesh: &PolyMesh, v: usize) -> Option<(Vec<Vec<usize>>, NodeType)> {
    let fan = mesh.vertex_fan(v)?;
    if fan.iter().any(|f| f.len() != 3 && f.len() != 4) {
        return None;
    }
    let n = fan.len();
    let quads: Vec<usize> = (0..n).filter(|&i| fan[i].len() == 4).collect();
    let t = if quads.len() == n && n == 4 {
        NodeType::RegularQuad
    } else if quads.is_empty() && n == 6 {
        NodeType::RegularTri
    } else if n == 5 && quads.len() == 2 && (quads[0] + 1 == quads[1] || (quads[0] == 0 && quads[1] == 4)) {
        // the quads are cyclically adjacent; k is the first of the two, CCW
        let k = if quads[0] + 1 == quads[1] { quads[0] } else { 4 };
        NodeType::Transition { k }
    } else {
        NodeType::Eon
    };
    Some((fan, t))
}

#[cfg(test)]
mod gather_tests;
