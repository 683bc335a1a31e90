//! The mixed quad/triangle host (4-3 subdivision; scheme files `topology =
//! "mixed-quad-triangle"`): the primal split with
//! `TriangleSplit::FourTriangles`, quads around their face point and
//! triangles into 4. Its rules tell vertices apart by the faces around them
//! (`slots::classify`: regular quad, regular triangle, transition, eon) and
//! edges by the faces beside them. Regular part: binary primal refinement,
//! A_4 (or bicubic) over quads, the three-direction quartic box spline over
//! triangles.

use crate::error::Error;
use crate::mesh::Tags;
use crate::mesh::{PolyMesh, SectorKind, VertexId};
use crate::sdc::host::{refuse_tags, Refined, RefinementHost, RegularSpline, TriangleSplit};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Edge as E, Face as F, Vertex as V};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    canonical, classify, edge_faces, ev_part, face_corners, fam, node_type, rule, unsupported, vertex_fan_part, Arity,
    Family, Gather, GatherError, Gathered, HostSpec, NodeType, Part, RuleSlots, Wants, ONE, PER_J, QUAD_VERTEX,
    TRI_VERTEX,
};
use crate::sdc::{CentreKind, Origin};
use crate::topology::primal_split;

pub struct MixedQuadTriangle;

static SPEC: HostSpec = HostSpec {
    host: Host::MixedQuadTriangle,
    name: "mixed-quad-triangle",
    sector: SectorKind::Quad,
    centre: CentreKind::Vertex,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for MixedQuadTriangle {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        primal_split::refine(mesh, TriangleSplit::FourTriangles)
    }
    fn refine_tags(&self, mesh: &PolyMesh, _: &[Origin]) -> Result<Option<Tags>, Error> {
        refuse_tags(Host::MixedQuadTriangle, mesh)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, wants: &dyn Wants) -> Gather {
        match origin {
            Origin::Vertex(v) => mixed_vertex(mesh, v, wants),
            Origin::Edge(a, b) => mixed_edge(mesh, a, b, wants),
            Origin::Face(f) => {
                if mesh.face(f).len() != 4 {
                    return Err(GatherError::NotCovered);
                }
                Ok(Gathered::one(face_corners("face", mesh, f)))
            }
            Origin::Corner { .. } => unsupported(Host::MixedQuadTriangle, origin),
        }
    }
    fn steps_per_analysis(&self) -> usize {
        1
    }
    fn growth_per_level(&self) -> usize {
        4
    }
    fn size_bound(&self, mesh: &PolyMesh) -> usize {
        primal_split::size_bound(mesh, TriangleSplit::FourTriangles)
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed mesh of triangles and quads"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::BinaryPrimal
    }
}

const RULES: &[RuleSlots] = &[
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
    let kind = |v: VertexId| node_type(mesh, v).ok_or(GatherError::Truncated);
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

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, quad_torus, triangle_torus};
    use super::*;

    /// Quads and triangles both become 4 faces each.
    #[test]
    fn states_its_growth_bound_and_rules() {
        check_host(Host::MixedQuadTriangle, &quad_torus(4, 5), 4 * 20, true);
        check_host(Host::MixedQuadTriangle, &triangle_torus(4, 5), 4 * 40, true);
    }
}
