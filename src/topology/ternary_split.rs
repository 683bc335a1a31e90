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

use crate::mesh::IdMap;

use super::{ChartBuilder, Refined};
use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::sdc::Origin;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    if let Some(f) = (0..mesh.num_faces()).find(|&f| mesh.face(f).len() != 4) {
        return Err(Error::Input(format!(
            "the ternary quad split needs a quad mesh: face {} has {} vertices (apply one catmull-clark step first)",
            f + 1,
            mesh.face(f).len()
        )));
    }
    let nv = mesh.num_vertices();
    let mut origins: Vec<Origin> = (0..nv).map(Origin::Vertex).collect();
    let mut edge_id: IdMap<(usize, usize), usize> = IdMap::default();
    for (a, b) in mesh.edges() {
        edge_id.insert((a, b), origins.len());
        origins.push(Origin::Edge(a, b));
        edge_id.insert((b, a), origins.len());
        origins.push(Origin::Edge(b, a));
    }
    let mut faces = Vec::new();
    let mut parents = Vec::new();
    for (f, face) in mesh.faces().iter().enumerate() {
        let inner: Vec<usize> = (0..4)
            .map(|k| {
                origins.push(Origin::Corner { face: f, corner: k });
                origins.len() - 1
            })
            .collect();
        let [v0, v1, v2, v3] = [face[0], face[1], face[2], face[3]];
        let e = |a: usize, b: usize| edge_id[&(a, b)];
        // grid point (i, j), i along v0 -> v1, j along v0 -> v3
        let grid = [
            [v0, e(v0, v3), e(v3, v0), v3],
            [e(v0, v1), inner[0], inner[3], e(v3, v2)],
            [e(v1, v0), inner[1], inner[2], e(v2, v3)],
            [v1, e(v1, v2), e(v2, v1), v2],
        ];
        for i in 0..3 {
            for j in 0..3 {
                faces.push(vec![grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]]);
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
