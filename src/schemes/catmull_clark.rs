//! Catmull–Clark subdivision (Catmull & Clark 1978), for arbitrary polygons.
//!
//! face point  = average of the face's corners
//! edge point  = (a + b + F_left + F_right) / 4
//! vertex point = (Q + 2R + (n - 3) v) / n, Q = average of the adjacent face
//!                points, R = average of the adjacent edge midpoints.

use super::{Caps, CentreKind, Params, Rules, Scheme, SchemeEntry, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Weight;
use crate::sdc::{Origin, RuleResult, Stencil};
use crate::sdc::{Topology, TriangleSplit};

pub struct CatmullClark {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "catmull-clark",
    description: "Catmull–Clark primal quad subdivision (bicubic B-spline in the regular case)",
    topology: Topology::PrimalSplit(TriangleSplit::FacePointQuads),
    centre: CentreKind::Vertex,
    sector: SectorKind::Quad,
    caps: Caps::NONE,
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: Vec::new,
        build: |params| Box::new(CatmullClark { params }),
    }
}

fn face_point<W: Weight>(face: &[usize]) -> Stencil<W> {
    let w = W::ratio(1, face.len() as i64);
    let mut s = Stencil::new();
    for &v in face {
        s.add(v, w.clone());
    }
    s
}

impl<W: Weight> Rules<W> for CatmullClark {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        Ok(match origin {
            Origin::Face(f) => Some(face_point(mesh.face(f))),
            Origin::Edge(a, b) => {
                let (Some((fl, _)), Some((fr, _))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
                    return Ok(None);
                };
                let quarter = W::ratio(1, 4);
                let mut s = Stencil::new().with(a, quarter.clone()).with(b, quarter.clone());
                s.add_scaled(&face_point(mesh.face(fl)), &quarter);
                s.add_scaled(&face_point(mesh.face(fr)), &quarter);
                Some(s)
            }
            Origin::Vertex(v) => {
                let Some(fan) = mesh.vertex_fan(v) else {
                    return Ok(None);
                };
                let n = fan.len() as i64;
                let mut s = Stencil::new().with(v, W::ratio(n - 3, n));
                let inv_n2 = W::ratio(1, n * n);
                for face in &fan {
                    // Q / n: each adjacent face point with weight 1/n^2
                    s.add_scaled(&face_point(face), &inv_n2);
                    // 2R / n: each edge midpoint (v + e)/2 with weight 2/n^2
                    s.add(v, inv_n2.clone());
                    s.add(face[1], inv_n2.clone());
                }
                Some(s)
            }
            Origin::Corner { .. } => None,
        })
    }
}

impl Scheme for CatmullClark {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
