//! Ternary primal split of quad meshes (ternary bi-2 subdivision, TPS): every
//! quad becomes a 3 × 3 grid of quads. Old vertices stay (`Vertex(v)`), every
//! edge gets two new vertices, one near each end (`Edge(a, b)` is the one near
//! a, `Edge(b, a)` the one near b), and every quad four interior vertices
//! (`Corner { face, corner: k }` is the one near corner k).
//!
//! Charts: the refined lattice has a third of the spacing, so in its own units
//! an old vertex p goes to 3p, the edge vertex near a on a–b to 2a + b, and
//! the interior vertex near corner v0 of quad (v0, v1, v2, v3) to
//! (4v0 + 2v1 + v2 + 2v3)/3 (the bilinear point at (1/3, 1/3), times 3).
//!
//! The host unit (`Host::Ternary`, scheme files `topology = "ternary"`): the
//! vertex rule, the edge rule (the new vertex near a) and the interior rule
//! (the new vertex near a corner). Regular part: the biquadratic B-spline
//! with the ternary mask (ternary primal refinement of quads).

use crate::error::Error;
use crate::mesh::FaceList;
use crate::mesh::PolyMesh;
use crate::mesh::SectorKind;
use crate::mesh::Tags;
use crate::sdc::host::{refuse_tags, Refined, RefinementHost, RegularSpline};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Corner as C, Edge as E, Vertex as V};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    edge_faces, fam, quad_corner, rule, sized, unsupported, vertex_fan_part, Arity, Gather, GatherError, Gathered,
    HostSpec, Part, RuleSlots, Wants, ONE, QUAD_VERTEX,
};
use crate::sdc::CentreKind;
use crate::sdc::Origin;
use crate::topology::chart_builder::ChartBuilder;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    if let Some(f) = (0..mesh.num_faces()).find(|&f| mesh.face(f).len() != 4) {
        return Err(Error::Input(format!(
            "the ternary quad split needs a quad mesh: face {} has {} vertices (apply one catmull-clark step first)",
            f + 1,
            mesh.face(f).len()
        )));
    }
    let nv = mesh.num_vertices();
    // two points per edge (one nearer each end), in edge order, found from
    // a face's sides by number
    let numbering = mesh.edge_numbering();
    // sized up front: discovery's patches are large, and growing these by
    // doubling copied them several times
    let mut origins: Vec<Origin> = Vec::with_capacity(nv + 2 * numbering.edges.len() + 4 * mesh.num_faces());
    origins.extend((0..nv).map(Origin::Vertex));
    origins.extend(numbering.edges.iter().flat_map(|&(a, b)| [Origin::Edge(a, b), Origin::Edge(b, a)]));
    let mut faces = FaceList::with_capacity(9 * mesh.num_faces(), 36 * mesh.num_faces());
    let mut parents = Vec::with_capacity(9 * mesh.num_faces());
    for (f, face) in mesh.faces().iter().enumerate() {
        let inner: Vec<usize> = (0..4)
            .map(|k| {
                origins.push(Origin::Corner { face: f, corner: k });
                origins.len() - 1
            })
            .collect();
        let [v0, v1, v2, v3] = [face[0], face[1], face[2], face[3]];
        // the point Edge(a, b) of the edge on side k, a being one end of
        // that side: edge number i has Edge(its first end, ..) at 2i, the
        // reverse at 2i + 1
        let e = |k: usize, a: usize| {
            let (i, forward) = numbering.side_from(f, k, a);
            nv + 2 * i + usize::from(!forward)
        };
        // grid point (i, j), i along v0 -> v1, j along v0 -> v3 (side k runs
        // from corner k to corner k + 1: side 3 is v3 -> v0, side 2 v2 -> v3)
        let grid = [
            [v0, e(3, v0), e(3, v3), v3],
            [e(0, v0), inner[0], inner[3], e(2, v3)],
            [e(0, v1), inner[1], inner[2], e(2, v2)],
            [v1, e(1, v1), e(1, v2), v2],
        ];
        for i in 0..3 {
            for j in 0..3 {
                faces.push(&[grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]]);
                parents.push(Origin::Face(f));
            }
        }
    }
    let mut new_mesh = PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?;
    if let Some(chart) = mesh.chart.as_ref().filter(|c| c.scale == 1) {
        let mut cb = ChartBuilder::new(chart);
        for o in &origins {
            match *o {
                Origin::Vertex(v) => cb.push_scaled(v, 3),
                Origin::Edge(a, b) => cb.push_on_edge(mesh, a, b, 2, 1)?,
                Origin::Corner { face: f, corner: k } => {
                    let cyc = mesh.face_from(f, k);
                    let s = cb.face_chart(chart.face_sector[f], cyc[0]);
                    let p: Vec<(i64, i64)> = cyc.iter().map(|&v| chart.in_chart(chart.vertex_coords[v], s)).collect();
                    let x = 4 * p[0].0 + 2 * p[1].0 + p[2].0 + 2 * p[3].0;
                    let y = 4 * p[0].1 + 2 * p[1].1 + p[2].1 + 2 * p[3].1;
                    if x % 3 != 0 || y % 3 != 0 {
                        cb.ok = false; // not a lattice quad
                    }
                    cb.push(s, x / 3, y / 3);
                }
                Origin::Face(_) => unreachable!("the ternary split creates no face points"),
            }
        }
        for (k, p) in parents.iter().enumerate() {
            let Origin::Face(f) = *p else { unreachable!() };
            let first = new_mesh.face(k)[0];
            // a child of a central face lies in the sector of its first corner
            cb.face_sector.push(Some(chart.face_sector[f].unwrap_or(cb.coords[first].sector)));
        }
        new_mesh.chart = cb.finish(1);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: parents })
}

/// The host unit: everything the engine asks of this host.
pub struct TernarySplit;

static SPEC: HostSpec = HostSpec {
    host: Host::Ternary,
    name: "ternary",
    sector: SectorKind::Quad,
    centre: CentreKind::Vertex,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for TernarySplit {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        refine(mesh)
    }
    fn refine_tags(&self, mesh: &PolyMesh, _: &[Origin]) -> Result<Option<Tags>, Error> {
        refuse_tags(Host::Ternary, mesh)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, _wants: &dyn Wants) -> Gather {
        match origin {
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
            Origin::Face(_) => unsupported(Host::Ternary, origin),
        }
    }
    fn steps_per_analysis(&self) -> usize {
        1
    }
    fn growth_per_level(&self) -> usize {
        9
    }
    fn size_bound(&self, mesh: &PolyMesh) -> usize {
        let (v, e, f) = (mesh.num_vertices(), mesh.edges().len(), mesh.num_faces());
        // 9 quads per quad; old vertices, 2 per edge, 4 per quad
        (9 * f).max(v + 2 * e + 4 * f)
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed quad mesh"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::TernaryPrimal
    }
}

const RULES: &[RuleSlots] = &[
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

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, quad_torus};
    use super::*;

    /// Every quad becomes a 3 × 3 grid.
    #[test]
    fn states_its_growth_bound_and_rules() {
        check_host(Host::Ternary, &quad_torus(4, 5), 9 * 20, true);
    }
}
