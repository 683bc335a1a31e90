//! Primal split: Catmull–Clark-like (quads around face points) and Loop-like
//! (1 -> 4 triangles) refinement, and any mixture (4-3 subdivision). The
//! split, its counting rule and the edge gatherer shared by the three primal
//! hosts (`primal_quad`, `primal_triangle`, `mixed_quad_triangle`), which
//! state which triangle split they use; and the boundary, crease and corner
//! rules of the primal quad and triangle hosts (declarations, the gatherer's
//! routing of tagged origins, and what a split does to tags).

use crate::error::Error;
use crate::mesh::{FaceList, PolyMesh, Tags, VertexId, VertexTag};
use crate::sdc::host::{Refined, TriangleSplit};
use crate::sdc::slots::OriginKind::{Edge as E, Vertex as V};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    ev_part, fam, rule, sized, Arity, Gather, GatherError, Gathered, Host, Part, RuleSlots, Wants, ONE,
};
use crate::sdc::Origin;
use crate::topology::chart_builder::ChartBuilder;

pub fn refine(mesh: &PolyMesh, tri: TriangleSplit) -> Result<Refined, Error> {
    let nv = mesh.num_vertices();
    // the edge points in edge order, found from a face's sides by number
    let numbering = mesh.edge_numbering();
    // sized up front: growing these by doubling copied the large meshes of
    // discovery and of the certificates' nets several times
    let mut origins: Vec<Origin> = Vec::with_capacity(nv + numbering.edges.len() + mesh.num_faces());
    origins.extend((0..nv).map(Origin::Vertex));
    origins.extend(numbering.edges.iter().map(|&(a, b)| Origin::Edge(a, b)));
    let wants_face_point = |len: usize| len >= 4 || tri == TriangleSplit::FacePointQuads;
    let mut face_point = vec![None; mesh.num_faces()];
    for (f, face) in mesh.faces().iter().enumerate() {
        if wants_face_point(face.len()) {
            face_point[f] = Some(origins.len());
            origins.push(Origin::Face(f));
        }
    }
    let corners = mesh.faces().corners().len();
    let mut faces = FaceList::with_capacity(corners + mesh.num_faces(), 4 * (corners + mesh.num_faces()));
    let mut parents = Vec::with_capacity(corners + mesh.num_faces());
    for (f, face) in mesh.faces().iter().enumerate() {
        let m = face.len();
        // the point of the edge on side k (mod m) of the face
        let e = |k: usize| nv + numbering.side(f, k % m);
        match face_point[f] {
            Some(c) => {
                for (k, &v) in face.iter().enumerate() {
                    faces.push(&[v, e(k), c, e(k + m - 1)]);
                    parents.push(Origin::Face(f));
                }
            }
            None => {
                for (k, &v) in face.iter().enumerate().take(3) {
                    faces.push(&[v, e(k), e(k + 2)]);
                    parents.push(Origin::Face(f));
                }
                faces.push(&[e(0), e(1), e(2)]);
                parents.push(Origin::Face(f));
            }
        }
    }
    let mut new_mesh = PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?;
    if let Some(dirs) = &mesh.lattice_dirs {
        // the child quad at corner k starts along the parent's edge k
        let mut child = Vec::with_capacity(new_mesh.num_faces());
        for (f, face) in mesh.faces().iter().enumerate() {
            if face_point[f].is_none() {
                return Err(Error::Input("lattice directions need quads".into()));
            }
            child.extend((0..face.len()).map(|k| ((dirs[f] as usize + k) % 4) as u8));
        }
        new_mesh.lattice_dirs = Some(child);
    }
    if let Some(chart) = mesh.chart.as_ref().filter(|c| c.scale == 1) {
        let mut cb = ChartBuilder::new(chart);
        for o in &origins {
            match *o {
                Origin::Vertex(v) => cb.push_scaled(v, 2),
                Origin::Edge(a, b) => cb.push_on_edge(mesh, a, b, 1, 1)?,
                Origin::Face(f) => match chart.face_sector[f] {
                    None => cb.push(0, 0, 0), // a central face is centred on the origin
                    Some(s) => {
                        let face = mesh.face(f);
                        let (si, sj) = face.iter().fold((0, 0), |acc, &v| {
                            let p = chart.in_chart(chart.vertex_coords[v], s);
                            (acc.0 + p.0, acc.1 + p.1)
                        });
                        let m = face.len() as i64;
                        if (2 * si) % m != 0 || (2 * sj) % m != 0 {
                            cb.ok = false;
                        }
                        cb.push(s, 2 * si / m, 2 * sj / m);
                    }
                },
                Origin::Corner { .. } => unreachable!("primal split creates no corner vertices"),
            }
        }
        for (k, p) in parents.iter().enumerate() {
            let Origin::Face(f) = *p else { unreachable!() };
            let first_corner = new_mesh.face(k)[0];
            let sector = match chart.face_sector[f] {
                Some(s) => Some(s),
                // children of a central face lie in the sector of their old corner
                None => Some(chart.vertex_coords[first_corner].sector),
            };
            cb.face_sector.push(sector);
        }
        new_mesh.chart = cb.finish(1);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: parents })
}

// Boundary, crease and corner rules (Hoppe et al. 1994; OpenSubdiv's
// Sdc::Crease at infinite sharpness), declared once for the primal quad and
// triangle hosts. A tagged mesh (`mesh::tags`) routes a vertex by its kind
// (smooth and dart: the host's smooth vertex rule; crease: `vertex-crease`;
// corner: `vertex-corner`) and a sharp edge to `edge-crease`; an edge
// between a crease vertex and a smooth one keeps the smooth edge rule.

/// The rule of a crease or boundary vertex (two sharp edges).
pub(crate) const VERTEX_CREASE: RuleSlots = RuleSlots {
    optional: true,
    ..rule(
        "vertex-crease",
        V,
        Any,
        &[
            fam("centre", ONE, "the vertex v"),
            fam(
                "crease",
                Arity::Fixed(2),
                "the neighbours of v across its two sharp (boundary or crease) edges, j = 0, 1",
            ),
        ],
        "the new vertex point of a crease or boundary vertex v (two sharp edges; n: the number of faces at v)",
    )
};
/// The rule of a corner vertex (a corner tag, or three or more sharp edges).
pub(crate) const VERTEX_CORNER: RuleSlots = RuleSlots {
    optional: true,
    ..rule(
        "vertex-corner",
        V,
        Any,
        &[fam("centre", ONE, "the vertex v")],
        "the new vertex point of a corner v (a corner tag or three or more sharp edges; n: the number of faces at v)",
    )
};
/// The rule of a sharp (boundary or crease) edge.
pub(crate) const EDGE_CREASE: RuleSlots = RuleSlots {
    optional: true,
    ..rule(
        "edge-crease",
        E,
        Fixed(2),
        &[fam("ends", Arity::Fixed(2), "the edge's two ends")],
        "the new edge point of a sharp (boundary or crease) edge",
    )
};

/// The edge rule next to a crease or boundary vertex v0 (Biermann, Levin
/// and Zorin 2000; `schemes::blz`): an edge v0–v that is not sharp, seen
/// from v0, `n` the number k of faces of v0's sector (between its two sharp
/// edges) that holds the edge, since BLZ's weights depend on θ_k = π/k.
/// Where both ends are crease vertices the mean of the two ends' rules
/// applies (our choice, as for two extraordinary ends). Gathered only for a
/// mask that weighs it; otherwise the smooth edge rule stays (Hoppe).
pub(crate) const EDGE_SECTOR_QUAD: RuleSlots = RuleSlots {
    optional: true,
    ..rule(
        "edge-sector",
        E,
        Any,
        &[
            fam("crease-end", ONE, "the crease or boundary end v0"),
            fam("other-end", ONE, "the edge's other end"),
            fam("side", Arity::Fixed(4), "the two other corners of each of the edge's two quads"),
        ],
        "the new point of an edge that is not sharp at a crease or boundary vertex v0 (n: the faces of v0's sector holding the edge)",
    )
};
/// [`EDGE_SECTOR_QUAD`] on the triangle host: the two apexes instead of the sides.
pub(crate) const EDGE_SECTOR_TRIANGLE: RuleSlots = RuleSlots {
    optional: true,
    ..rule(
        "edge-sector",
        E,
        Any,
        &[
            fam("crease-end", ONE, "the crease or boundary end v0"),
            fam("other-end", ONE, "the edge's other end"),
            fam("opposite", Arity::Fixed(2), "the apexes of the edge's two triangles"),
        ],
        "the new point of an edge that is not sharp at a crease or boundary vertex v0 (n: the faces of v0's sector holding the edge)",
    )
};

/// The number of faces of crease vertex v's sector that holds the edge v–w
/// (not sharp): around v from the edge both ways to a sharp edge. A walk
/// that leaves the mesh first is a cut patch (`Truncated`).
fn sector_faces(mesh: &PolyMesh, v: VertexId, w: VertexId) -> Result<usize, GatherError> {
    let limit = mesh.incident_faces(v).len();
    let mut count = 0;
    // forwards: the face of v -> u, whose other edge at v comes into v
    let mut u = w;
    loop {
        let (f, k) = mesh.half_edge(v, u).ok_or(GatherError::Truncated)?;
        let face = mesh.face(f);
        u = face[(k + face.len() - 1) % face.len()];
        count += 1;
        if mesh.is_sharp(v, u) {
            break;
        }
        if count > limit {
            return Err(GatherError::NotCovered);
        }
    }
    // backwards: the face of u -> v, whose other edge at v leaves v
    let mut u = w;
    loop {
        let (f, k) = mesh.half_edge(u, v).ok_or(GatherError::Truncated)?;
        let face = mesh.face(f);
        u = face[(k + 2) % face.len()];
        count += 1;
        if mesh.is_sharp(v, u) {
            break;
        }
        if count > limit {
            return Err(GatherError::NotCovered);
        }
    }
    Ok(count)
}

/// The `edge-sector` part of the edge v–w seen from crease vertex v.
fn sector_edge(mesh: &PolyMesh, v: VertexId, w: VertexId, size: usize) -> Result<Part, GatherError> {
    let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(v, w), mesh.half_edge(w, v)) else {
        return Err(GatherError::Truncated);
    };
    let (l, r) = (mesh.face(fl), mesh.face(fr));
    sized([l, r], size)?;
    let k = sector_faces(mesh, v, w)?;
    let at = |face: &[VertexId], k: usize, t: usize| face[(k + t) % face.len()];
    let mut p = Part::around(EDGE_SECTOR_QUAD.name, k, v);
    p.put("crease-end", 0, v);
    p.put("other-end", 0, w);
    if size == 4 {
        p.put("side", 0, at(l, kl, 2));
        p.put("side", 1, at(l, kl, 3));
        p.put("side", 2, at(r, kr, 2));
        p.put("side", 3, at(r, kr, 3));
    } else {
        p.put("opposite", 0, at(l, kl, 2));
        p.put("opposite", 1, at(r, kr, 2));
    }
    Ok(p)
}

/// The slots of a tagged origin on a primal quad or triangle host: `None`
/// where the host's smooth rules apply (an untagged mesh, a smooth or dart
/// vertex, an edge that is not sharp, a face), else the boundary, crease or
/// corner rule's slots, or `MissingRule` when the mask has no weights for it.
pub(crate) fn tagged(host: Host, mesh: &PolyMesh, origin: Origin, wants: &dyn Wants) -> Option<Gather> {
    mesh.tags.as_ref()?;
    let part = match origin {
        Origin::Vertex(v) => {
            // a vertex of no face has no rule at all (the smooth gatherer says why)
            let n = mesh.incident_faces(v).len();
            match mesh.vertex_tag(v) {
                VertexTag::Smooth | VertexTag::Dart => return None,
                _ if n == 0 => return None,
                VertexTag::Crease(a, b) => {
                    let mut p = Part::around(VERTEX_CREASE.name, n, v);
                    p.put("centre", 0, v);
                    p.put("crease", 0, a);
                    p.put("crease", 1, b);
                    p
                }
                VertexTag::Corner => {
                    let mut p = Part::around(VERTEX_CORNER.name, n, v);
                    p.put("centre", 0, v);
                    p
                }
            }
        }
        Origin::Edge(a, b) if mesh.is_sharp(a, b) => {
            let mut p = Part::new(EDGE_CREASE.name, 2);
            p.put("ends", 0, a);
            p.put("ends", 1, b);
            p
        }
        Origin::Edge(a, b) if wants.rule(EDGE_SECTOR_QUAD.name) => {
            let crease = |v| matches!(mesh.vertex_tag(v), VertexTag::Crease(..));
            let ends: Vec<(VertexId, VertexId)> = [(a, b), (b, a)].into_iter().filter(|&(v, _)| crease(v)).collect();
            if ends.is_empty() {
                return None;
            }
            let size = if host == Host::PrimalQuad { 4 } else { 3 };
            let share = ends.len() as i64;
            let parts: Result<Vec<Part>, GatherError> =
                ends.iter().map(|&(v, w)| sector_edge(mesh, v, w, size).map(|p| p.scaled(1, share))).collect();
            return Some(parts.map(|parts| Gathered { parts, extraordinary: Vec::new(), regular: None }));
        }
        Origin::Edge(..) | Origin::Face(_) | Origin::Corner { .. } => return None,
    };
    Some(match wants.rule(part.rule) {
        true => Ok(Gathered::one(part)),
        false => Err(GatherError::MissingRule(host, part.rule)),
    })
}

/// The tags after a primal split (the primal quad and triangle hosts'
/// `refine_tags`): a new vertex of an old vertex c is a corner iff c is; the
/// two halves vertex(a)–edge(a, b) and edge(a, b)–vertex(b) of a sharp edge
/// a–b are sharp. No other new edge is sharp.
pub(crate) fn refine_tags(mesh: &PolyMesh, vertex_origins: &[Origin]) -> Result<Option<Tags>, Error> {
    let Some(tags) = mesh.tags.as_ref() else { return Ok(None) };
    let mut of_vertex = vec![None; mesh.num_vertices()];
    for (i, o) in vertex_origins.iter().enumerate() {
        if let Origin::Vertex(c) = *o {
            of_vertex[c] = Some(i);
        }
    }
    let new = |c: VertexId| {
        of_vertex[c].ok_or_else(|| Error::Message(format!("the primal split has no new vertex of vertex {c}")))
    };
    let mut out = Tags::new();
    for (i, o) in vertex_origins.iter().enumerate() {
        match *o {
            Origin::Vertex(c) if tags.is_corner(c) => out.mark_corner(i),
            Origin::Edge(a, b) if tags.is_sharp(a, b) => {
                out.mark_sharp(new(a)?, i);
                out.mark_sharp(i, new(b)?);
            }
            _ => {}
        }
    }
    Ok(Some(out))
}

/// The larger of the face and vertex counts after one primal split of `mesh`:
/// a face with a face point becomes one quad per corner, a triangle without
/// one 4 triangles; old vertices, one per edge, one per face point.
pub(crate) fn size_bound(mesh: &PolyMesh, tri: TriangleSplit) -> usize {
    let face_point = |len: usize| len >= 4 || tri == TriangleSplit::FacePointQuads;
    let faces: usize = mesh.faces().iter().map(|fc| if face_point(fc.len()) { fc.len() } else { 4 }).sum();
    let face_points = mesh.faces().iter().filter(|fc| face_point(fc.len())).count();
    faces.max(mesh.num_vertices() + mesh.edges().len() + face_points)
}

/// Whether vertex v is extraordinary for a primal host: a closed fan of
/// `size`-gons whose count is not the regular valence. (Vertices with open
/// fans, such as the rim of a truncated neighbourhood, lie in the regular part.)
///
/// A crease or corner vertex of a tagged mesh is not: the edges at it keep
/// the smooth edge rule (as OpenSubdiv's do at sharpness 0).
fn extraordinary(mesh: &PolyMesh, v: VertexId, size: usize) -> bool {
    if mesh.tags.is_some() && matches!(mesh.vertex_tag(v), VertexTag::Crease(..) | VertexTag::Corner) {
        return false;
    }
    let regular = if size == 4 { 4 } else { 6 };
    // from the cached fan: every edge at v asks, so copying the fan would cost valence²
    mesh.fan_corners(v).is_some_and(|fan| fan.len() != regular && fan.iter().all(|&(f, _)| mesh.face(f).len() == size))
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

/// The edge rule of a primal host over `size`-gons (4: quads, 3: triangles),
/// with the rule seen from an extraordinary end where the mask has one.
pub(crate) fn primal_edge(mesh: &PolyMesh, a: VertexId, b: VertexId, size: usize, wants: &dyn Wants) -> Gather {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sdc::host::Registry;
    use crate::topology::host_tests::All;

    /// A 2 x 1 strip of quads with its open edges sharp and a corner at 0:
    /// the refined tags halve every sharp edge and keep the corner, and the
    /// gatherer routes each origin by its tag.
    #[test]
    fn a_split_refines_tags_and_the_gatherer_routes_by_them() {
        // 0 1 2 / 3 4 5
        let mut m = PolyMesh::new(6, vec![vec![0, 1, 4, 3], vec![1, 2, 5, 4]]).unwrap();
        m.tag_open_edges();
        m.tags.as_mut().unwrap().mark_corner(0);
        for host in [Host::PrimalQuad, Host::PrimalTriangle] {
            let r = host.refine(&m).unwrap();
            let tags = r.mesh.tags.as_ref().unwrap();
            assert_eq!(tags.sharp_edges().len(), 2 * 6, "{host:?}");
            assert_eq!(tags.corners(), vec![0]);
            for (a, b) in m.tags.as_ref().unwrap().sharp_edges() {
                let e = r.vertex_origins.iter().position(|o| *o == Origin::Edge(a, b) || *o == Origin::Edge(b, a));
                let e = e.unwrap();
                assert!(tags.is_sharp(a, e) && tags.is_sharp(e, b));
            }
        }
        let unit = Host::PrimalQuad.unit();
        let rule = |o: Origin| unit.gather(&m, o, &All).map(|g| g.parts[0].rule);
        assert_eq!(rule(Origin::Vertex(0)), Ok("vertex-corner"));
        assert_eq!(rule(Origin::Vertex(1)), Ok("vertex-crease"));
        assert_eq!(rule(Origin::Edge(0, 1)), Ok("edge-crease"));
        // the middle edge is not sharp, between two crease vertices: a mask
        // that weighs every rule (All) takes BLZ's edge-sector from each end,
        // each sector the strip's two faces (k = 2)
        assert_eq!(rule(Origin::Edge(1, 4)), Ok("edge-sector"));
        let g = unit.gather(&m, Origin::Edge(1, 4), &All).unwrap();
        assert_eq!(g.parts.iter().map(|p| (p.n, p.scale)).collect::<Vec<_>>(), vec![(2, (1, 2)), (2, (1, 2))]);
        assert_eq!(rule(Origin::Face(0)), Ok("face"));
        let slots = unit.gather(&m, Origin::Vertex(1), &All).unwrap().parts[0].slots.clone();
        let targets: Vec<_> = slots.iter().map(|s| (s.family, s.j, s.target.clone())).collect();
        use crate::sdc::slots::Target::Vertex as T;
        let VertexTag::Crease(a, b) = m.vertex_tag(1) else { panic!() };
        assert_eq!(targets, vec![("centre", 0, T(1)), ("crease", 0, T(a)), ("crease", 1, T(b))]);
        // another host refuses the tagged mesh in one line naming it
        let e = Host::Dual.refine(&m).unwrap_err().to_string();
        assert!(e.contains("dual host") && e.contains("boundary/crease rules are not available"), "{e}");
        assert!(Host::Dual.check_tags(&PolyMesh::new(3, vec![vec![0, 1, 2]]).unwrap()).is_ok());
    }
}
