//! Quadrilateral split with face control vertices (Huang's non-box
//! subdivision viewed as a quad scheme): like Catmull–Clark's split, each
//! k-gon becomes k quads around a new vertex at its centre; that vertex is the
//! face's old FCV moved by the FCV rule, and every new quad gets a new FCV
//! (NFCV) of its own.
//!
//! New vertices: `Vertex(v)` for old corner vertices (V-vertices), `Edge` for
//! edges (E-vertices), `Face(f)` for the updated FCV of f, and
//! `Corner { face: f, corner: k }` for the NFCV of the new quad at corner k.
//! Charts use doubled lattice coordinates (scale 2): vertices at even, FCVs at
//! odd points.

use crate::mesh::IdMap;

use super::{ChartBuilder, Refined};
use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::sdc::Origin;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    if !mesh.has_face_point_on_every_face() {
        return Err(Error::Input("this scheme needs a face control vertex on every face".into()));
    }
    let fcv: Vec<usize> = mesh.face_points.iter().flatten().copied().collect();
    let is_fcv: crate::mesh::IdSet<usize> = fcv.iter().copied().collect();
    let mut origins: Vec<Origin> = Vec::new();
    let mut vertex_id = vec![usize::MAX; mesh.num_vertices()];
    for (v, id) in vertex_id.iter_mut().enumerate() {
        if !is_fcv.contains(&v) {
            *id = origins.len();
            origins.push(Origin::Vertex(v));
        }
    }
    let mut edge_id: IdMap<(usize, usize), usize> = IdMap::default();
    for (a, b) in mesh.edges() {
        edge_id.insert((a, b), origins.len());
        edge_id.insert((b, a), origins.len());
        origins.push(Origin::Edge(a, b));
    }
    let face_id: Vec<usize> = (0..mesh.num_faces())
        .map(|f| {
            origins.push(Origin::Face(f));
            origins.len() - 1
        })
        .collect();
    let mut faces = Vec::new();
    let mut parents = Vec::new();
    let mut new_fcv = Vec::new();
    for (f, face) in mesh.faces().iter().enumerate() {
        let m = face.len();
        for k in 0..m {
            faces.push(vec![
                vertex_id[face[k]],
                edge_id[&(face[k], face[(k + 1) % m])],
                face_id[f],
                edge_id[&(face[(k + m - 1) % m], face[k])],
            ]);
            parents.push(Origin::Face(f));
            new_fcv.push(Some(origins.len()));
            origins.push(Origin::Corner { face: f, corner: k });
        }
    }
    let mut new_mesh =
        PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?.with_face_points(new_fcv)?;
    if let Some(chart) = mesh.chart.as_ref().filter(|c| c.scale == 2) {
        let mut cb = ChartBuilder::new(chart);
        let in_face = |f: usize| -> (usize, Vec<(i64, i64)>) {
            let s = chart.face_sector[f].expect("FCV patches have no central face");
            (s, mesh.face(f).iter().map(|&v| chart.in_chart(chart.vertex_coords[v], s)).collect())
        };
        for o in &origins {
            match *o {
                Origin::Vertex(v) => cb.push_scaled(v, 2),
                Origin::Edge(a, b) => cb.push_on_edge(mesh, a, b, 1, 1)?,
                Origin::Face(f) => {
                    let (s, p) = in_face(f);
                    let sum = p.iter().fold((0, 0), |a, q| (a.0 + q.0, a.1 + q.1));
                    let m = p.len() as i64;
                    if (2 * sum.0) % m != 0 || (2 * sum.1) % m != 0 {
                        cb.ok = false;
                    }
                    cb.push(s, 2 * sum.0 / m, 2 * sum.1 / m);
                }
                Origin::Corner { face: f, corner: k } => {
                    // centre of the new quad (V-vertex, E-vertex, face vertex, E-vertex)
                    let (s, p) = in_face(f);
                    let m = p.len();
                    let sum = p.iter().fold((0, 0), |a, q| (a.0 + q.0, a.1 + q.1));
                    let (v, next, prev) = (p[k], p[(k + 1) % m], p[(k + m - 1) % m]);
                    let mm = m as i64;
                    let x = 2 * v.0 + (v.0 + next.0) + 2 * sum.0 / mm + (prev.0 + v.0);
                    let y = 2 * v.1 + (v.1 + next.1) + 2 * sum.1 / mm + (prev.1 + v.1);
                    if x % 4 != 0 || y % 4 != 0 {
                        cb.ok = false;
                    }
                    cb.push(s, x / 4, y / 4);
                }
            }
        }
        for p in &parents {
            let Origin::Face(f) = *p else { unreachable!() };
            cb.face_sector.push(chart.face_sector[f]);
        }
        new_mesh.chart = cb.finish(2);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: parents })
}
