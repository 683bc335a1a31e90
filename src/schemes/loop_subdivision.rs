//! Loop subdivision (C. Loop, 1987 thesis), with Loop's original weights:
//!
//! vertex point: (1 - nβ) v + β Σ v_i,  β = (1/n) (5/8 - (3/8 + cos(2π/n)/4)^2)
//! edge point:   3/8 (a + b) + 1/8 (c + d), c and d the opposite apexes
//!
//! Boundaries, creases and corners (Hoppe et al. 1994; OpenSubdiv's crease
//! rules at infinite sharpness), on a tagged mesh (`mesh::tags`): a crease or
//! boundary vertex 3/4 v + 1/8 (a + b) over its two sharp neighbours, a
//! corner v, a sharp edge (a + b)/2; darts and edges that are not sharp keep
//! the smooth rules.
//!
//! With the parameter `blz` (`schemes::blz`): an edge that is not sharp at a
//! crease or boundary vertex v0 of k sectors takes Biermann–Levin–Zorin's
//! (3/4 − γ) v0 + γ v_j + 1/8 (c + d), γ = 1/2 − cos(π/k)/4.

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Inexact;
use crate::numeric::Weight;
use crate::schemes::blz;
use crate::schemes::entry::SchemeEntry;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};

pub struct Loop {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "loop",
    description: "Loop primal triangle subdivision, Loop's original weights (quartic box spline when regular)",
    topology: Topology::PrimalTriangle,
    centre: CentreKind::Vertex,
    sector: SectorKind::Tri,
    caps: Caps::NONE,
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![blz::BLZ],
        build: |params| Box::new(Loop { params }),
    }
}

/// Loop's β for valence n.
pub fn loop_beta<W: Weight>(n: i64) -> Result<W, crate::numeric::Inexact> {
    let t = W::ratio(3, 8) + W::cos_2pi(1, n)? * W::ratio(1, 4);
    Ok((W::ratio(5, 8) - t.clone() * t) / W::int(n))
}

// The rules are a mask on the primal triangle host's slots: the host's
// gatherer finds the neighbours (and refuses boundaries and non-triangles),
// the mask only weighs them, exactly as a scheme file on that host does.
impl Wants for Loop {
    fn rule(&self, rule: &str) -> bool {
        matches!(rule, "vertex" | "edge" | "vertex-crease" | "vertex-corner" | "edge-crease")
            || (rule == blz::RULE && blz::share(&self.params).is_some())
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        matches!(
            (rule, family),
            ("vertex", "centre" | "edge")
                | ("edge", "ends" | "opposite")
                | ("vertex-crease", "centre" | "crease")
                | ("vertex-corner", "centre")
                | ("edge-crease", "ends")
                | ("edge-sector", "crease-end" | "other-end" | "opposite")
        )
    }
}

impl<W: Weight> Mask<W> for Loop {
    fn weight(&self, _mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        let n = slot.n as i64;
        Ok(match (rule, slot.family) {
            ("vertex", "centre") => W::one() - loop_beta::<W>(n)? * W::int(n),
            ("vertex", "edge") => loop_beta(n)?,
            ("edge", "ends") => W::ratio(3, 8),
            ("edge", "opposite") => W::ratio(1, 8),
            // the cubic B-spline along a crease or boundary; corners interpolate
            ("vertex-crease", "centre") => W::ratio(3, 4),
            ("vertex-crease", "crease") => W::ratio(1, 8),
            ("vertex-corner", "centre") => W::one(),
            ("edge-crease", "ends") => W::ratio(1, 2),
            // BLZ next to a crease vertex (slot.n = k): (3/4 − γ) v0 + γ v_j, apexes 1/8
            ("edge-sector", "crease-end") => W::ratio(3, 4) - blz::gamma(&self.params, W::ratio(1, 2), slot.n)?,
            ("edge-sector", "other-end") => blz::gamma(&self.params, W::ratio(1, 2), slot.n)?,
            ("edge-sector", "opposite") => W::ratio(1, 8),
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for Loop {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::PrimalTriangle, mesh, origin, self, &W::one())
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
