//! Doo–Sabin subdivision (Doo & Sabin 1978) with the Doo–Sabin weights:
//! the new vertex at corner 0 of an m-gon is Σ_j α_j v_j with
//! α_0 = 1/4 + 5/(4m), α_j = (3 + 2 cos(2πj/m)) / (4m).

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Inexact;
use crate::numeric::Weight;
use crate::schemes::entry::SchemeEntry;
use crate::schemes::memo::WeightMemo;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};

pub struct DooSabin {
    params: Params,
    /// the m weights α_0..α_{m−1} of an m-gon, per weight type: asked at
    /// every corner slot of every stencil, and in interval or cyclotomic
    /// arithmetic each is a cosine enclosure or a field element and a
    /// division (a fifth of a certified Doo–Sabin map)
    weights_made: WeightMemo,
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
        build: |params| Box::new(DooSabin { params, weights_made: WeightMemo::new() }),
    }
}

// The rule is a mask on the dual host's corner slots c_0..c_{m-1} (c_0 the
// corner itself, counter-clockwise round the face), as in a scheme file.
impl Wants for DooSabin {
    fn rule(&self, rule: &str) -> bool {
        rule == "corner"
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        rule == "corner" && family == "corner"
    }
}

impl<W: Weight> Mask<W> for DooSabin {
    fn weight(&self, _mesh: &PolyMesh, _rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        let m = slot.n as i64;
        let alpha = |j: i64| -> Result<W, Inexact> {
            let w = (W::int(3) + W::int(2) * W::cos_2pi(j, m)?) / W::int(4 * m);
            Ok(if j == 0 { w + W::ratio(1, 4) } else { w })
        };
        if slot.j >= slot.n {
            // not a corner slot of the face: as the formula says
            return alpha(slot.j as i64);
        }
        let all = self.weights_made.get::<W, Vec<W>>(m, || (0..m).map(alpha).collect())?;
        Ok(all[slot.j].clone())
    }
}

impl<W: Weight> Rules<MeshDomain, W> for DooSabin {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::Dual, mesh, origin, self, &W::one())
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
