//! Dual split of point-augmented meshes (point-augmented bi-2 subdivision,
//! PGS): the Doo–Sabin split, plus a central point in the shrunken copy
//! (F-face) of every face that carries one or is not a quad. A face without a
//! point gets one at its first refinement (the scheme's rule then defines the
//! missing old point from the net, as PGS's eq. (1) does).
//!
//! New central points have origin `Face(f)`. Charts: the centre of a central
//! face is the origin (0, 0); any other face's point is the centroid of its
//! refined F-face, which must be a lattice point.

use super::{dual_split, Refined};
use crate::error::Error;
use crate::mesh::{LatticeCoord, PolyMesh};
use crate::sdc::Origin;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    let base = dual_split::refine(mesh)?;
    // dual_split emits the F-face of old face f as new face f
    if (0..mesh.num_faces()).any(|f| base.face_parents.get(f) != Some(&Origin::Face(f))) {
        return Err(Error::Input("dual split: F-faces are not first in face order".to_string()));
    }
    let mut origins = base.vertex_origins;
    let faces = base.mesh.faces().to_vec();
    let mut centres = vec![None; faces.len()];
    for (f, centre) in centres.iter_mut().enumerate().take(mesh.num_faces()) {
        if mesh.face_point(f).is_some() || mesh.face(f).len() != 4 {
            *centre = Some(origins.len());
            origins.push(Origin::Face(f));
        }
    }
    let mut new_mesh =
        PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?.with_face_points(centres)?;
    if let (Some(old), Some(mut chart)) = (mesh.chart.as_ref(), base.mesh.chart) {
        let mut ok = true;
        for o in &origins[chart.vertex_coords.len()..] {
            let Origin::Face(f) = *o else { unreachable!("only central points are added") };
            let c = match old.face_sector[f] {
                None => LatticeCoord::CENTRE,
                Some(s) => {
                    let corners = new_mesh.face(f);
                    let (si, sj) = corners.iter().fold((0, 0), |a, &v| {
                        let p = chart.in_chart(chart.vertex_coords[v], s);
                        (a.0 + p.0, a.1 + p.1)
                    });
                    let m = corners.len() as i64;
                    ok &= si % m == 0 && sj % m == 0;
                    chart.canonical(s, si / m, sj / m).unwrap_or(LatticeCoord::CENTRE)
                }
            };
            chart.vertex_coords.push(c);
        }
        new_mesh.chart = ok.then_some(chart);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: base.face_parents })
}
