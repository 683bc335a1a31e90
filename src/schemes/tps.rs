//! Primal bi-2 subdivision, TPS (Karčiauskas & Peters, "Point-augmented
//! biquadratic C^1 subdivision surfaces", section 4): ternary refinement of
//! quad meshes, the biquadratic B-spline where the mesh is regular.
//!
//! The regular rules are the tensor product of the 1-D ternary quadratic
//! B-spline rules, mask (1, 3, 6, 7, 6, 3, 1)/9: a vertex keeps
//! (1, 7, 1)/9, the new point at a third of an edge is (2/3, 1/3). So
//!
//! * interior point near corner v0 of a quad (v0, v1, v2, v3):
//!   (4 v0 + 2 v1 + v2 + 2 v3)/9                     (eq. 17: b, c, d, e)
//! * edge point near a on edge a–b: 2/3 of a's column, 1/3 of b's, where a
//!   column is (7 · centre + the two neighbours across the edge)/9:
//!   (14 a + 7 b + 2 (a's across) + (b's across))/27   (eq. 17: a, f)
//!   "Across" neighbours are read off the two quads beside the edge, so the
//!   same rule gives eq. (17) next to a vertex of any valence.
//! * vertex of valence n: eq. (18), q' = (1 − α1 − α2) q + α1 ā + α2 b̄ (ā, b̄:
//!   averages of the edge and diagonal neighbours), α2 = α1/7,
//!   α1 = 7n/(2n + 1)^2 (n ≥ 4; n = 4 gives 28/81, the tensor rule), α1 = 339/896 at n = 3.
//!
//! The paper's adjustable TPS (split ratio e ≠ 1/3, section 4.1) is not
//! implemented: the paper does not give its refinement rules, and the rules
//! obtained by splitting the ring's patches in the ratio e : 1 − 2e : e do not
//! reproduce its eq. (22), so they cannot be recovered from the text.

use super::{uniform_fan, CentreKind, Params, Rules, Scheme, SchemeEntry};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Weight;
use crate::refine::{Origin, RuleResult, Stencil};
use crate::topology::Topology;

pub struct Tps {
    params: Params,
}

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: "tps",
        description: "Karčiauskas–Peters primal (ternary) bi-2 subdivision of quad meshes (TPS)",
        params: Vec::new,
        build: |params| Box::new(Tps { params }),
    }
}

/// α1 of eq. (18) at valence n (the paper's experimental choice).
pub fn alpha1<W: Weight>(n: i64) -> W {
    if n == 3 {
        W::ratio(339, 896)
    } else {
        W::ratio(7 * n, (2 * n + 1) * (2 * n + 1))
    }
}

/// The quad on the other side of a -> b, as a cycle starting at a.
fn quad_at(mesh: &PolyMesh, a: usize, b: usize) -> Option<Vec<usize>> {
    let (f, k) = mesh.half_edge(a, b)?;
    let cyc = mesh.face_from(f, k);
    (cyc.len() == 4).then_some(cyc)
}

impl<W: Weight> Rules<W> for Tps {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        Ok(match origin {
            Origin::Corner { face, corner } => {
                let c = mesh.face_from(face, corner);
                if c.len() != 4 {
                    return Ok(None);
                }
                let w = |k: i64| W::ratio(k, 9);
                Some(Stencil::new().with(c[0], w(4)).with(c[1], w(2)).with(c[2], w(1)).with(c[3], w(2)))
            }
            Origin::Edge(a, b) => {
                // left quad holds a -> b: (a, b, b_left, a_left); right quad b -> a: (b, a, a_right, b_right)
                let (Some(l), Some(r)) = (quad_at(mesh, a, b), quad_at(mesh, b, a)) else { return Ok(None) };
                let w = |k: i64| W::ratio(k, 27);
                Some(
                    Stencil::new()
                        .with(a, w(14))
                        .with(b, w(7))
                        .with(l[3], w(2))
                        .with(r[2], w(2))
                        .with(l[2], w(1))
                        .with(r[3], w(1)),
                )
            }
            Origin::Vertex(v) => {
                let Some(fan) = uniform_fan(mesh, v, 4) else { return Ok(None) };
                let n = fan.len() as i64;
                let a1: W = alpha1(n);
                let a2 = a1.clone() / W::int(7);
                let mut s = Stencil::new().with(v, W::one() - a1.clone() - a2.clone());
                for quad in &fan {
                    // each edge neighbour is the second corner of exactly one quad of the fan
                    s.add(quad[1], a1.clone() / W::int(n));
                    s.add(quad[2], a2.clone() / W::int(n));
                }
                Some(s)
            }
            Origin::Face(_) => None,
        })
    }
}

impl Scheme for Tps {
    fn name(&self) -> &'static str {
        "tps"
    }
    fn description(&self) -> &'static str {
        entry().description
    }
    fn topology(&self) -> Topology {
        Topology::TernarySplit
    }
    fn centre_kind(&self) -> CentreKind {
        CentreKind::Vertex
    }
    fn sector_kind(&self) -> SectorKind {
        SectorKind::Quad
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
