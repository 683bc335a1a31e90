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

use super::{uniform_fan, Caps, CentreKind, ParamSpec, Params, Rules, Scheme, SchemeEntry, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Weight;
use crate::sdc::Topology;
use crate::sdc::{Origin, RuleResult, Stencil};

pub struct PolarBi2 {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "polar-bi2",
    description: "Karčiauskas–Peters polar bi-2 subdivision (PolBS): a pole with a triangle fan, quad rings",
    topology: Topology::PolarSplit,
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

impl<W: Weight> Rules<W> for PolarBi2 {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        Ok(match origin {
            Origin::Vertex(p) => {
                let Some(fan) = uniform_fan(mesh, p, 3) else { return Ok(None) };
                let alpha: W = W::param(self.params.of(&ALPHA).expect("alpha has a default"))?;
                let n = fan.len() as i64;
                let mut s = Stencil::new().with(p, W::one() - alpha.clone());
                for tri in &fan {
                    s.add(tri[1], alpha.clone() / W::int(n));
                }
                Some(s)
            }
            // the pole's ring from the mesh's cached fan: every spoke point
            // asks for it, and building the fan each time was quadratic in n
            Origin::Edge(x, y) => match mesh.uniform_ring(x, 3) {
                // a spoke point next to the pole: eq. (11)
                Some(ring) => {
                    let n = ring.len();
                    let Some(i) = ring.iter().position(|&a| a == y) else { return Ok(None) };
                    let mut s = Stencil::new().with(x, W::ratio(1, 2));
                    for j in 0..n {
                        let gamma = (W::ratio(1, 2) + W::cos_2pi(j as i64, n as i64)?) / W::int(n as i64);
                        s.add(ring[(i + j) % n], gamma);
                    }
                    Some(s)
                }
                None => Some(Stencil::new().with(x, W::ratio(3, 4)).with(y, W::ratio(1, 4))),
            },
            _ => None,
        })
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
