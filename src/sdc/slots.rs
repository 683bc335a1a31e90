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
//! centroids of any m-gon are slot weights like the rest. The declarations
//! are in `sdc::host_spec`, what a gatherer returns in `sdc::gathered`
//! (both re-exported here); this file gathers and weighs.
//!
//! Conventions: fans and rings run counter-clockwise as
//! `PolyMesh::vertex_fan` gives them. Where a rule says its j is canonical,
//! j = 0 is a definite neighbour (the edge's other end, the corner itself);
//! elsewhere the first neighbour is arbitrary and weights may not depend on j.

use crate::mesh::{FaceId, PolyMesh, VertexId};
use crate::numeric::{Inexact, Weight};
use crate::sdc::stencil::{Origin, Stencil};

// the hosts' identities, declarations and gather results live below the
// host interface (`sdc::host`), which the gatherer here calls; re-exported
// under the paths the host files and the schemes name them by
pub use crate::sdc::gathered::{Gather, GatherError, Gathered, Part, RuleResult, Slot, Target, Wants};
pub use crate::sdc::host::Registry;
pub use crate::sdc::host_list::{Host, HOSTS};
pub(crate) use crate::sdc::host_spec::{
    canonical, corner_family, fam, quad_fam, rule, ONE, PER_J, QUAD_VERTEX, TRI_VERTEX,
};
pub use crate::sdc::host_spec::{Arity, Family, HostSpec, OriginKind, RuleSlots, Valence};

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
/// them in, as 4-3 does). `Ok(Err(cause))` where the neighbourhood is
/// truncated, not covered by the host's rules, or of an origin the host
/// never creates: the gatherer's reason is passed on, not dropped.
pub fn weigh<W: Weight>(
    host: Host,
    mesh: &PolyMesh,
    origin: Origin,
    mask: &dyn Mask<W>,
    extraordinary_share: &W,
) -> RuleResult<W> {
    let g = match gather(host, mesh, origin, mask) {
        Ok(g) => g,
        Err(cause) => return Ok(Err(cause)),
    };
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
    Ok(Ok(s))
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
    let t = node_type(mesh, v)?;
    Some((mesh.vertex_fan(v)?, t))
}

/// The node type of [`classify`] alone, read off the mesh's cached fan
/// without building the fan's faces: an edge rule asks it of both ends of
/// every edge, and that allocation was most of a 4-3 refinement step.
pub fn node_type(mesh: &PolyMesh, v: usize) -> Option<NodeType> {
    let fan = mesh.fan_corners(v)?;
    let size = |&(f, _): &(usize, usize)| mesh.face(f).len();
    if fan.iter().map(size).any(|s| s != 3 && s != 4) {
        return None;
    }
    let n = fan.len();
    let is_quad = |i: usize| size(&fan[i]) == 4;
    let quads = (0..n).filter(|&i| is_quad(i)).count();
    Some(if quads == n && n == 4 {
        NodeType::RegularQuad
    } else if quads == 0 && n == 6 {
        NodeType::RegularTri
    } else if n == 5 && quads == 2 && (0..n).any(|k| is_quad(k) && is_quad((k + 1) % n)) {
        // the quads are cyclically adjacent; k is the first of the two, CCW
        let k = (0..n).find(|&k| is_quad(k) && is_quad((k + 1) % n)).expect("checked above");
        NodeType::Transition { k }
    } else {
        NodeType::Eon
    })
}

#[cfg(test)]
mod gather_tests;
