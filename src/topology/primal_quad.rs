//! The primal quad host (Catmull–Clark, scheme files `topology =
//! "primal-quad"`): every face split into quads around its face point, the
//! primal split with `TriangleSplit::FacePointQuads`. Its rules: the vertex
//! point (centre, edge neighbours e_j, face-opposite neighbours f_j, or every
//! corner of the fan's faces for masks over general polygons), the edge
//! point (optionally seen from an extraordinary end) and the face point of an
//! n-gon. Regular part: the bicubic B-spline or the four-direction box spline
//! A_4 (binary primal refinement of quads).

use crate::error::Error;
use crate::mesh::{PolyMesh, SectorKind, Tags, VertexId};
use crate::sdc::host::{Refined, RefinementHost, RegularSpline, TriangleSplit};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Edge as E, Face as F, Vertex as V};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    canonical, corner_family, face_corners, fam, quad_fam, rule, unsupported, vertex_fan_part, Arity, Gather,
    GatherError, Gathered, HostSpec, Part, RuleSlots, Wants, ONE, PER_J, QUAD_VERTEX,
};
use crate::sdc::{CentreKind, Origin};
use crate::topology::primal_split::{
    self, primal_edge, tagged, EDGE_CREASE, EDGE_SECTOR_QUAD, VERTEX_CORNER, VERTEX_CREASE,
};

pub struct PrimalQuad;

static SPEC: HostSpec = HostSpec {
    host: Host::PrimalQuad,
    name: "primal-quad",
    sector: SectorKind::Quad,
    centre: CentreKind::Vertex,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for PrimalQuad {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        primal_split::refine(mesh, TriangleSplit::FacePointQuads)
    }
    fn refine_tags(&self, mesh: &PolyMesh, vertex_origins: &[Origin]) -> Result<Option<Tags>, Error> {
        primal_split::refine_tags(mesh, vertex_origins)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, wants: &dyn Wants) -> Gather {
        // boundary, crease and corner rules at tagged origins
        if let Some(g) = tagged(Host::PrimalQuad, mesh, origin, wants) {
            return g;
        }
        match origin {
            // a mask that weighs the fan faces' corners takes any polygons;
            // without them the rule is written for quads and refuses others
            Origin::Vertex(v) => match wants.family("vertex", "face-corner") {
                true => polygon_vertex(mesh, v, wants.family("vertex", "face")),
                false => vertex_fan_part("vertex", mesh, v, Some(4)),
            }
            .map(Gathered::one),
            Origin::Edge(a, b) => primal_edge(mesh, a, b, 4, wants),
            Origin::Face(f) => Ok(Gathered::one(face_corners("face", mesh, f))),
            Origin::Corner { .. } => unsupported(Host::PrimalQuad, origin),
        }
    }
    fn steps_per_analysis(&self) -> usize {
        1
    }
    fn growth_per_level(&self) -> usize {
        4
    }
    fn size_bound(&self, mesh: &PolyMesh) -> usize {
        primal_split::size_bound(mesh, TriangleSplit::FacePointQuads)
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed mesh"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::BinaryPrimal
    }
}

const RULES: &[RuleSlots] = &[
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
    VERTEX_CREASE,
    VERTEX_CORNER,
    EDGE_CREASE,
    EDGE_SECTOR_QUAD,
];

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

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, quad_torus};
    use super::*;

    /// A quad torus (no extraordinary vertex, no boundary): every face
    /// becomes exactly `growth_per_level` faces, within the size bound.
    #[test]
    fn states_its_growth_bound_and_rules() {
        // a quad with a face point becomes one quad per corner
        check_host(Host::PrimalQuad, &quad_torus(4, 5), 4 * 4 * 5, true);
    }
}
