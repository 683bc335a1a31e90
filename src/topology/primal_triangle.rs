//! The primal triangle host (Loop, butterfly; scheme files `topology =
//! "primal-triangle"`): every triangle split into 4, the primal split with
//! `TriangleSplit::FourTriangles`. Its rules: the vertex point (centre and
//! ring), the edge point (ends, apexes, optionally the butterfly's wings, and
//! the rule seen from an extraordinary end). Regular part: the
//! three-direction quartic box spline (binary primal refinement of
//! triangles) where the rules are Loop's.

use crate::error::Error;
use crate::mesh::{PolyMesh, SectorKind, Tags};
use crate::sdc::host::{Refined, RefinementHost, RegularSpline, TriangleSplit};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Edge as E, Vertex as V};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    canonical, fam, rule, unsupported, vertex_fan_part, Arity, Family, Gather, Gathered, HostSpec, RuleSlots, Wants,
    TRI_VERTEX,
};
use crate::sdc::{CentreKind, Origin};
use crate::topology::primal_split::{
    self, primal_edge, tagged, EDGE_CREASE, EDGE_SECTOR_TRIANGLE, VERTEX_CORNER, VERTEX_CREASE,
};

pub struct PrimalTriangle;

static SPEC: HostSpec = HostSpec {
    host: Host::PrimalTriangle,
    name: "primal-triangle",
    sector: SectorKind::Tri,
    centre: CentreKind::Vertex,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for PrimalTriangle {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        primal_split::refine(mesh, TriangleSplit::FourTriangles)
    }
    fn refine_tags(&self, mesh: &PolyMesh, vertex_origins: &[Origin]) -> Result<Option<Tags>, Error> {
        primal_split::refine_tags(mesh, vertex_origins)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, wants: &dyn Wants) -> Gather {
        // boundary, crease and corner rules at tagged origins
        if let Some(g) = tagged(Host::PrimalTriangle, mesh, origin, wants) {
            return g;
        }
        match origin {
            Origin::Vertex(v) => vertex_fan_part("vertex", mesh, v, Some(3)).map(Gathered::one),
            Origin::Edge(a, b) => primal_edge(mesh, a, b, 3, wants),
            Origin::Face(_) | Origin::Corner { .. } => unsupported(Host::PrimalTriangle, origin),
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
        "a closed triangle mesh"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::BinaryPrimal
    }
}

const RULES: &[RuleSlots] = &[
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
    VERTEX_CREASE,
    VERTEX_CORNER,
    EDGE_CREASE,
    EDGE_SECTOR_TRIANGLE,
];

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, triangle_torus};
    use super::*;

    /// Every triangle becomes 4 (a 4 × 5 torus has 40 triangles).
    #[test]
    fn states_its_growth_bound_and_rules() {
        check_host(Host::PrimalTriangle, &triangle_torus(4, 5), 4 * 40, true);
    }
}
