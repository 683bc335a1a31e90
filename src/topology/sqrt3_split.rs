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

use super::{ChartBuilder, Refined};
use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::sdc::Origin;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    let nv = mesh.num_vertices();
    let mut origins: Vec<Origin> = (0..nv).map(Origin::Vertex).collect();
    let mut face_vertex = Vec::with_capacity(mesh.num_faces());
    for f in 0..mesh.num_faces() {
        face_vertex.push(origins.len());
        origins.push(Origin::Face(f));
    }
    let mut faces = Vec::new();
    let mut parents = Vec::new();
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
                faces.push(vec![a, cg, cf]);
                parents.push(Origin::Edge(a, b));
                faces.push(vec![b, cf, cg]);
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
