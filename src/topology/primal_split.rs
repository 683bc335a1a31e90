//! Primal split: Catmull–Clark-like (quads around face points) and Loop-like
//! (1 -> 4 triangles) refinement, and any mixture (4-3 subdivision).

use crate::mesh::IdMap;

use super::{ChartBuilder, Refined, TriangleSplit};
use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::sdc::Origin;

pub fn refine(mesh: &PolyMesh, tri: TriangleSplit) -> Result<Refined, Error> {
    let nv = mesh.num_vertices();
    let mut origins: Vec<Origin> = (0..nv).map(Origin::Vertex).collect();
    let mut edge_id: IdMap<(usize, usize), usize> = IdMap::default();
    for (a, b) in mesh.edges() {
        let id = origins.len();
        origins.push(Origin::Edge(a, b));
        edge_id.insert((a, b), id);
        edge_id.insert((b, a), id);
    }
    let wants_face_point = |len: usize| len >= 4 || tri == TriangleSplit::FacePointQuads;
    let mut face_point = vec![None; mesh.num_faces()];
    for (f, face) in mesh.faces().iter().enumerate() {
        if wants_face_point(face.len()) {
            face_point[f] = Some(origins.len());
            origins.push(Origin::Face(f));
        }
    }
    let mut faces = Vec::new();
    let mut parents = Vec::new();
    for (f, face) in mesh.faces().iter().enumerate() {
        let m = face.len();
        let e = |k: usize| edge_id[&(face[k % m], face[(k + 1) % m])];
        match face_point[f] {
            Some(c) => {
                for (k, &v) in face.iter().enumerate() {
                    faces.push(vec![v, e(k), c, e(k + m - 1)]);
                    parents.push(Origin::Face(f));
                }
            }
            None => {
                for (k, &v) in face.iter().enumerate().take(3) {
                    faces.push(vec![v, e(k), e(k + 2)]);
                    parents.push(Origin::Face(f));
                }
                faces.push(vec![e(0), e(1), e(2)]);
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
