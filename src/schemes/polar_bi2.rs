//! Polar bi-2 subdivision, PolBS (Karčiauskas & Peters, "Point-augmented
//! biquadratic C^1 subdivision surfaces", section 3), on polar nets: a pole p
//! with a fan of n triangles, rings of n quads outside (topology: the radial
//! polar split). With a_i the spoke neighbours of p:
//!
//! * radial points: binary 1-D (Chaikin) subdivision along every spoke, e.g.
//!   b_i' = 3/4 a_i + 1/4 b_i, c_i' = 1/4 a_i + 3/4 b_i;
//! * a_i' = (1 − Σ_j γ_j) p + Σ_j γ_j a_{i+j}                        (11)
//! * p'   = (1 − α) p + α ā                                         (12)
//! * γ_j = (1/2 + cos(2πj/n))/n (15), so Σ γ_j = 1/2; α = 1/4 by default
//!   (parameter `alpha`).

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Inexact;
use crate::numeric::Weight;
use crate::schemes::entry::SchemeEntry;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, ParamSpec, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};

pub struct PolarBi2 {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "polar-bi2",
    description: "Karčiauskas–Peters polar bi-2 subdivision (PolBS): a pole with a triangle fan, quad rings",
    topology: Topology::Polar,
    centre: CentreKind::Polar,
    // the faces around the pole
    sector: SectorKind::Tri,
    caps: Caps::NONE,
};

const ALPHA: ParamSpec = ParamSpec {
    name: "alpha",
    default: "1/4",
    min: 0.0,
    max: 1.0,
    description: "weight of the ring average in the pole rule (12)",
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![ALPHA],
        build: |params| Box::new(PolarBi2 { params }),
    }
}

// The rules are a mask on the polar host's slots (as a scheme file on that
// host): the pole (eq. 12), the spoke points next to it (eq. 11, ring turned
// so that a_0 is the spoke's end) and the radial Chaikin points.
impl Wants for PolarBi2 {
    fn rule(&self, rule: &str) -> bool {
        matches!(rule, "pole" | "spoke" | "radial")
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        matches!((rule, family), ("pole", "centre" | "ring") | ("spoke", "pole" | "ring") | ("radial", "near" | "far"))
    }
}

impl<W: Weight> Mask<W> for PolarBi2 {
    fn weight(&self, _mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        let n = slot.n as i64;
        Ok(match (rule, slot.family) {
            // p' = (1 − α) p + α ā
            ("pole", "centre") => W::one() - W::param(self.params.of(&ALPHA).expect("alpha has a default"))?,
            ("pole", "ring") => W::param(self.params.of(&ALPHA).expect("alpha has a default"))? / W::int(n),
            // a_i' = p/2 + Σ_j γ_j a_{i+j}, γ_j = (1/2 + cos(2πj/n))/n (Σ γ_j = 1/2)
            ("spoke", "pole") => W::ratio(1, 2),
            ("spoke", "ring") => (W::ratio(1, 2) + W::cos_2pi(slot.j as i64, n)?) / W::int(n),
            // binary 1-D (Chaikin) subdivision along every spoke
            ("radial", "near") => W::ratio(3, 4),
            ("radial", "far") => W::ratio(1, 4),
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for PolarBi2 {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::Polar, mesh, origin, self, &W::one())
    }
}

impl Scheme for PolarBi2 {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
