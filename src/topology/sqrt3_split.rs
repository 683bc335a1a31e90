//! Kobbelt's sqrt(3) split: a new vertex in every face, connected to the
//! face's corners, and every interior old edge flipped so that it joins the two
//! new face vertices beside it. Boundary edges produce no triangle: the refined
//! patch ends there, and rules near it are not evaluable.
//!
//! Chart coordinates: one step rotates the lattice by 30 degrees and scales it
//! by 1/sqrt(3), which no integer lattice of the same axes represents. So after
//! an odd step the coordinates are positions in the previous frame times 3
//! (chart scale 3: old vertex p -> 3p, face vertex -> a + b + c). After the
//! next step the lattice is the original one scaled by 1/3 with no rotation,
//! and coordinates return to its own units (scale 1: vertex c -> c, face vertex
//! -> (a + b + c)/3), so vertices two steps apart match by coordinates.
//!
//! The host unit (`Host::Sqrt3`, scheme files `topology = "sqrt3"`): the
//! vertex rule (centre and ring) and the face rule summed over the
//! triangle's three corners and their rings. Two steps make one analysis
//! step (the lattice turns back); no box spline: a triangle ring is bounded
//! by the difference scheme (`certify::difference`).

use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::mesh::SectorKind;
use crate::mesh::Tags;
use crate::mesh::{FaceId, FaceList};
use crate::sdc::host::{refuse_tags, Refined, RefinementHost, RegularSpline};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Face as F, Vertex as V};
use crate::sdc::slots::Valence::Any;
use crate::sdc::slots::{
    fam, rule, unsupported, vertex_fan_part, Arity, Gather, GatherError, Gathered, HostSpec, Part, RuleSlots, Wants,
    TRI_VERTEX,
};
use crate::sdc::CentreKind;
use crate::sdc::Origin;
use crate::topology::chart_builder::ChartBuilder;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    let nv = mesh.num_vertices();
    // sized up front: the refinements of discovery's patches are large, and
    // growing these by doubling copied them several times
    let mut origins: Vec<Origin> = Vec::with_capacity(nv + mesh.num_faces());
    origins.extend((0..nv).map(Origin::Vertex));
    let mut face_vertex = Vec::with_capacity(mesh.num_faces());
    for f in 0..mesh.num_faces() {
        face_vertex.push(origins.len());
        origins.push(Origin::Face(f));
    }
    // two triangles per interior edge, at most 3 per triangle's corners
    let corners = mesh.faces().corners().len();
    let mut faces = FaceList::with_capacity(corners, 3 * corners);
    let mut parents = Vec::with_capacity(corners);
    // every edge once, in the order of `PolyMesh::edges` (the half-edge of
    // face f at corner k, unless its twin comes first), with the face that
    // holds it read off directly instead of looked up
    for (f, face) in mesh.faces().iter().enumerate() {
        for k in 0..face.len() {
            let (a, b) = (face[k], face[(k + 1) % face.len()]);
            let twin = mesh.half_edge(b, a);
            if twin.is_some() && a > b {
                continue;
            }
            let cf = face_vertex[f];
            // a boundary edge has no partner face to flip towards: its triangle
            // is left out (the refined patch ends there; no boundary rules)
            if let Some((g, _)) = twin {
                let cg = face_vertex[g];
                faces.push(&[a, cg, cf]);
                parents.push(Origin::Edge(a, b));
                faces.push(&[b, cf, cg]);
                parents.push(Origin::Edge(a, b));
            }
        }
    }
    let mut new_mesh = PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?;
    if let Some(chart) = &mesh.chart {
        let mut cb = ChartBuilder::new(chart);
        // from scale 1: multiply by 3; from scale 3: back to the new lattice's units
        let (vertex_factor, face_divisor, new_scale) = if chart.scale == 1 { (3, 1, 3) } else { (1, 3, 1) };
        for o in &origins {
            match *o {
                Origin::Vertex(v) => cb.push_scaled(v, vertex_factor),
                Origin::Face(f) => {
                    let face = mesh.face(f);
                    let s = cb.face_chart(chart.face_sector[f], face[0]);
                    let (si, sj) = face.iter().fold((0, 0), |acc, &v| {
                        let p = chart.in_chart(chart.vertex_coords[v], s);
                        (acc.0 + p.0, acc.1 + p.1)
                    });
                    if face.len() != 3 || si % face_divisor != 0 || sj % face_divisor != 0 {
                        cb.ok = false; // not a lattice point (centroid of another polygon)
                    }
                    cb.push(s, si / face_divisor, sj / face_divisor);
                }
                _ => unreachable!("sqrt(3) split creates vertex and face points only"),
            }
        }
        for p in &parents {
            let Origin::Edge(a, b) = *p else { unreachable!() };
            let (f, _) = mesh.half_edge(a, b).expect("oriented above");
            cb.face_sector.push(Some(cb.face_chart(chart.face_sector[f], a)));
        }
        new_mesh.chart = cb.finish(new_scale);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: parents })
}

/// The host unit: everything the engine asks of this host.
pub struct Sqrt3Split;

static SPEC: HostSpec = HostSpec {
    host: Host::Sqrt3,
    name: "sqrt3",
    sector: SectorKind::Tri,
    centre: CentreKind::Vertex,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for Sqrt3Split {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        refine(mesh)
    }
    fn refine_tags(&self, mesh: &PolyMesh, _: &[Origin]) -> Result<Option<Tags>, Error> {
        refuse_tags(Host::Sqrt3, mesh)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, _wants: &dyn Wants) -> Gather {
        match origin {
            Origin::Vertex(v) => vertex_fan_part("vertex", mesh, v, Some(3)).map(Gathered::one),
            Origin::Face(f) => sqrt3_face(mesh, f).map(Gathered::one),
            Origin::Edge(..) | Origin::Corner { .. } => unsupported(Host::Sqrt3, origin),
        }
    }
    fn steps_per_analysis(&self) -> usize {
        2
    }
    fn growth_per_level(&self) -> usize {
        3
    }
    fn size_bound(&self, mesh: &PolyMesh) -> usize {
        let (v, e, f) = (mesh.num_vertices(), mesh.edges().len(), mesh.num_faces());
        // old vertices plus one per face; two triangles per flipped edge
        (2 * e).max(v + f)
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed triangle mesh"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::NoBoxSpline
    }
}

const RULES: &[RuleSlots] = &[
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

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, triangle_torus};
    use super::*;

    /// Two triangles per flipped edge: 2E = 3F on a closed triangle mesh.
    #[test]
    fn states_its_growth_bound_and_rules() {
        check_host(Host::Sqrt3, &triangle_torus(4, 5), 2 * 60, true);
    }
}
