//! Catmull–Clark subdivision (Catmull & Clark 1978), for arbitrary polygons.
//!
//! face point  = average of the face's corners
//! edge point  = (a + b + F_left + F_right) / 4
//! vertex point = (Q + 2R + (n - 3) v) / n, Q = average of the adjacent face
//!                points, R = average of the adjacent edge midpoints.
//!
//! Boundaries, creases and corners (Hoppe et al. 1994; OpenSubdiv's crease
//! rules at infinite sharpness), on a tagged mesh (`mesh::tags`):
//!
//! crease/boundary vertex = 3/4 v + 1/8 (a + b), a and b its sharp neighbours
//! corner vertex = v
//! sharp edge point = (a + b) / 2
//!
//! (the cubic B-spline rules along the crease; a dart, and every edge that is
//! not sharp, keeps the smooth rule).
//!
//! With the parameter `blz` (`schemes::blz`): an edge that is not sharp at a
//! crease or boundary vertex v0 of k sectors takes Biermann–Levin–Zorin's
//! (3/4 − γ) v0 + γ v_j + 1/16 (sides), γ = 3/8 − cos(π/k)/4.

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::schemes::blz;
use crate::schemes::entry::SchemeEntry;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};

pub struct CatmullClark {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "catmull-clark",
    description: "Catmull–Clark primal quad subdivision (bicubic B-spline in the regular case)",
    topology: Topology::PrimalQuad,
    centre: CentreKind::Vertex,
    sector: SectorKind::Quad,
    caps: Caps::NONE,
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![blz::BLZ],
        build: |params| Box::new(CatmullClark { params }),
    }
}

// The rules are a mask on the primal quad host's slots for general polygons:
// the gatherer names every corner of each face of a vertex's fan and of an
// edge's two faces (with the face's corner count m), so the centroids of
// triangles, pentagons, ... are weighed like those of quads, and a scheme
// file weighing the same slots (schemes/catmull-clark-polygons.toml) is the
// same scheme on any closed polygon mesh.
impl Wants for CatmullClark {
    fn rule(&self, rule: &str) -> bool {
        matches!(rule, "vertex" | "edge" | "face" | "vertex-crease" | "vertex-corner" | "edge-crease")
            || (rule == blz::RULE && blz::share(&self.params).is_some())
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        matches!(
            (rule, family),
            ("vertex", "centre" | "edge" | "face-corner")
                | ("edge", "ends" | "face-corner")
                | ("face", "corner")
                | ("vertex-crease", "centre" | "crease")
                | ("vertex-corner", "centre")
                | ("edge-crease", "ends")
                | ("edge-sector", "crease-end" | "other-end" | "side")
        )
    }
}

impl<W: Weight> Mask<W> for CatmullClark {
    fn weight(&self, _mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        let n = slot.n as i64;
        Ok(match (rule, slot.family, slot.m) {
            // (n - 3)/n of v, and v's half of the n edge midpoints (weight 2/n^2 each)
            ("vertex", "centre", _) => W::ratio(n - 2, n),
            // e_j's half of its edge midpoint
            ("vertex", "edge", _) => W::ratio(1, n * n),
            // Q/n: the centroid of each fan face, 1/n^2 each (the factor
            // 1/m first, as the face point is a stencil of its own)
            ("vertex", "face-corner", Some(m)) => W::ratio(1, m as i64) * W::ratio(1, n * n),
            ("edge", "ends", _) => W::ratio(1, 4),
            // a quarter of each of the two face points
            ("edge", "face-corner", Some(m)) => W::ratio(1, m as i64) * W::ratio(1, 4),
            // the face point: the centroid of the n corners
            ("face", "corner", _) => W::ratio(1, n),
            // the cubic B-spline along a crease or boundary; corners interpolate
            ("vertex-crease", "centre", _) => W::ratio(3, 4),
            ("vertex-crease", "crease", _) => W::ratio(1, 8),
            ("vertex-corner", "centre", _) => W::one(),
            ("edge-crease", "ends", _) => W::ratio(1, 2),
            // BLZ next to a crease vertex (slot.n = k): (3/4 − γ) v0 + γ v_j, sides 1/16
            ("edge-sector", "crease-end", _) => W::ratio(3, 4) - blz::gamma(&self.params, W::ratio(3, 8), slot.n)?,
            ("edge-sector", "other-end", _) => blz::gamma(&self.params, W::ratio(3, 8), slot.n)?,
            ("edge-sector", "side", _) => W::ratio(1, 16),
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for CatmullClark {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::PrimalQuad, mesh, origin, self, &W::one())
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
