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
use crate::sdc::centre::CentreKind;
use crate::sdc::stencil::{Origin, RuleResult, Stencil};

pub use super::host::{Host, Registry, HOSTS};

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
    pub(crate) fn new(rule: &'static str, n: usize) -> Self {
        Part { rule, n, at: None, scale: (1, 1), slots: Vec::new() }
    }
    /// A rule about vertex `v` (of valence n).
    pub(crate) fn around(rule: &'static str, n: usize, v: VertexId) -> Self {
        Part { at: Some(v), ..Part::new(rule, n) }
    }
    pub(crate) fn put(&mut self, family: &'static str, j: usize, v: VertexId) {
        self.slots.push(Slot { family, j, n: self.n, at: self.at, m: None, target: Target::Vertex(v) });
    }
    /// A slot of the neighbourhood of vertex `at` (valence n) inside a larger rule.
    pub(crate) fn put_around(&mut self, family: &'static str, j: usize, n: usize, at: VertexId, v: VertexId) {
        self.slots.push(Slot { family, j, n, at: Some(at), m: None, target: Target::Vertex(v) });
    }
    pub(crate) fn put_target(&mut self, family: &'static str, target: Target) {
        self.slots.push(Slot { family, j: 0, n: self.n, at: self.at, m: None, target });
    }
    /// The face-corner slots of face j: its corners from `start` on.
    pub(crate) fn put_face_corners(&mut self, j: usize, face: &[VertexId], start: usize) {
        let m = face.len();
        for t in 0..m {
            let target = Target::Vertex(face[(start + t) % m]);
            self.slots.push(Slot { family: "face-corner", j, n: self.n, at: self.at, m: Some(m), target });
        }
    }
    pub(crate) fn scaled(mut self, num: i64, den: i64) -> Self {
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
    pub(crate) fn one(part: Part) -> Self {
        Gathered { parts: vec![part], extraordinary: Vec::new(), regular: None }
    }
    pub(crate) fn replacing(extraordinary: Vec<Part>, regular: Part) -> Self {
        Gathered { parts: Vec::new(), extraordinary, regular: Some(regular) }
    }
}

pub type Gather = Result<Gathered, GatherError>;

/// The closed fan of v; `Truncated` when v is on the boundary.
pub(crate) fn fan(mesh: &PolyMesh, v: VertexId) -> Result<Vec<Vec<VertexId>>, GatherError> {
    mesh.vertex_fan(v).ok_or(GatherError::Truncated)
}

/// The closed fan of v when all its faces have `size` corners.
pub(crate) fn uniform_fan(mesh: &PolyMesh, v: VertexId, size: usize) -> Result<Vec<Vec<VertexId>>, GatherError> {
    let fan = fan(mesh, v)?;
    if fan.iter().all(|f| f.len() == size) {
        Ok(fan)
    } else {
        Err(GatherError::NotCovered)
    }
}

/// The faces on both sides of edge a-b, as cycles from a (left, holding
/// a -> b) and from b (right, holding b -> a).
pub(crate) fn edge_faces(
    mesh: &PolyMesh,
    a: VertexId,
    b: VertexId,
) -> Result<(Vec<VertexId>, Vec<VertexId>), GatherError> {
    let ((fl, kl), (fr, kr)) =
        (mesh.half_edge(a, b).ok_or(GatherError::Truncated)?, mesh.half_edge(b, a).ok_or(GatherError::Truncated)?);
    Ok((mesh.face_from(fl, kl), mesh.face_from(fr, kr)))
}

pub(crate) fn sized(cycles: [&[VertexId]; 2], size: usize) -> Result<(), GatherError> {
    if cycles.iter().all(|c| c.len() == size) {
        Ok(())
    } else {
        Err(GatherError::NotCovered)
    }
}

/// Gather the slots of `origin` for host `host`, only the rules and optional
/// families `wants` names (the host's own gatherer, in its file).
pub fn gather(host: Host, mesh: &PolyMesh, origin: Origin, wants: &dyn Wants) -> Gather {
    host.unit().gather(mesh, origin, wants)
}

/// The error of a host asked for an origin kind it never creates.
pub(crate) fn unsupported(host: Host, origin: Origin) -> Gather {
    Err(GatherError::Unsupported(host, OriginKind::of(origin)))
}

/// v and its fan: centre, edge neighbours e_j = fan[j][1] and, for quads,
/// face-opposite neighbours f_j = fan[j][2]. `size`: the faces must all have
/// this many corners.
pub(crate) fn vertex_fan_part(
    rule: &'static str,
    mesh: &PolyMesh,
    v: VertexId,
    size: Option<usize>,
) -> Result<Part, GatherError> {
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

/// Corner j of face f.
pub(crate) fn face_corners(rule: &'static str, mesh: &PolyMesh, f: FaceId) -> Part {
    let face = mesh.face(f);
    let mut p = Part::new(rule, face.len());
    face.iter().enumerate().for_each(|(j, &c)| p.put("corner", j, c));
    p
}

/// A quad cycle c from the corner: `own` c_0, side c_1 and c_3, far c_2.
pub(crate) fn quad_corner(rule: &'static str, own: &'static str, c: &[VertexId]) -> Part {
    let mut p = Part::new(rule, 4);
    p.put(own, 0, c[0]);
    p.put("side", 0, c[1]);
    p.put("side", 1, c[3]);
    p.put("far", 0, c[2]);
    p
}

/// The `rule` seen from end v of edge v-other: v and its fan turned so that
/// e_0 = other.
/// `size`: the faces must all have this many corners, and quads add their
/// face-opposite corners f_j; `None`: any faces, edge neighbours only.
pub(crate) fn ev_part(
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
