//! Loop subdivision (C. Loop, 1987 thesis), with Loop's original weights:
//!
//! vertex point: (1 - nβ) v + β Σ v_i,  β = (1/n) (5/8 - (3/8 + cos(2π/n)/4)^2)
//! edge point:   3/8 (a + b) + 1/8 (c + d), c and d the opposite apexes

use super::{uniform_fan, Caps, CentreKind, Params, Rules, Scheme, SchemeEntry, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Weight;
use crate::sdc::{Origin, RuleResult, Stencil};
use crate::sdc::{Topology, TriangleSplit};

pub struct Loop {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "loop",
    description: "Loop primal triangle subdivision, Loop's original weights (quartic box spline when regular)",
    topology: Topology::PrimalSplit(TriangleSplit::FourTriangles),
    centre: CentreKind::Vertex,
    sector: SectorKind::Tri,
    caps: Caps::NONE,
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: Vec::new,
        build: |params| Box::new(Loop { params }),
    }
}

/// Loop's β for valence n.
pub fn loop_beta<W: Weight>(n: i64) -> Result<W, crate::numeric::Inexact> {
    let t = W::ratio(3, 8) + W::cos_2pi(1, n)? * W::ratio(1, 4);
    Ok((W::ratio(5, 8) - t.clone() * t) / W::int(n))
}

impl<W: Weight> Rules<W> for Loop {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        Ok(match origin {
            Origin::Edge(a, b) => {
                let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
                    return Ok(None);
                };
                if mesh.face(fl).len() != 3 || mesh.face(fr).len() != 3 {
                    return Ok(None);
                }
                let c = mesh.face_from(fl, kl)[2];
                let d = mesh.face_from(fr, kr)[2];
                Some(
                    Stencil::new()
                        .with(a, W::ratio(3, 8))
                        .with(b, W::ratio(3, 8))
                        .with(c, W::ratio(1, 8))
                        .with(d, W::ratio(1, 8)),
                )
            }
            Origin::Vertex(v) => {
                let Some(fan) = uniform_fan(mesh, v, 3) else {
                    return Ok(None);
                };
                let n = fan.len() as i64;
                let beta: W = loop_beta(n)?;
                let mut s = Stencil::new().with(v, W::one() - beta.clone() * W::int(n));
                for face in &fan {
                    s.add(face[1], beta.clone());
                }
                Some(s)
            }
            Origin::Face(_) | Origin::Corner { .. } => None,
        })
    }
}

impl Scheme for Loop {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
