//! Doo–Sabin subdivision (Doo & Sabin 1978) with the Doo–Sabin weights:
//! the new vertex at corner 0 of an m-gon is Σ_j α_j v_j with
//! α_0 = 1/4 + 5/(4m), α_j = (3 + 2 cos(2πj/m)) / (4m).

use super::{Caps, CentreKind, Params, Rules, Scheme, SchemeEntry, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Weight;
use crate::sdc::Topology;
use crate::sdc::{Origin, RuleResult, Stencil};

pub struct DooSabin {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "doo-sabin",
    description: "Doo–Sabin dual subdivision with the Doo–Sabin weights (biquadratic B-spline when regular)",
    topology: Topology::Dual,
    centre: CentreKind::Face,
    sector: SectorKind::Quad,
    caps: Caps::NONE,
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: Vec::new,
        build: |params| Box::new(DooSabin { params }),
    }
}

impl<W: Weight> Rules<W> for DooSabin {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        let Origin::Corner { face, corner } = origin else {
            return Ok(None);
        };
        let cyc = mesh.face_from(face, corner);
        let m = cyc.len() as i64;
        let mut s = Stencil::new();
        for (j, &v) in cyc.iter().enumerate() {
            let mut w = (W::int(3) + W::int(2) * W::cos_2pi(j as i64, m)?) / W::int(4 * m);
            if j == 0 {
                w = w + W::ratio(1, 4);
            }
            s.add(v, w);
        }
        Ok(Some(s))
    }
}

impl Scheme for DooSabin {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
