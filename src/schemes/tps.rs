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
//! Adjustable TPS (section 4.1, parameter `e`, the split ratio
//! e : 1 − 2e : e; e = 1/3 is TPS). The paper gives only the subdominant
//! eigenvalue (22), not the rules. Rules of the same tensor form — 1-D vertex
//! weights (v1, v0, v1), edge weights (near, far) — have, in Fourier block
//! k ≠ 0 on (â, b̂), trace far·v0 + far² + 2·near·v1·c_k and determinant
//! far²(far·v0 − 2·near·v1). Eq. (22) is the larger root of a quadratic with
//! sum 2(1 − 2e)(e²(1 + 2c) + (1 − e)²) and product (1 − 2e)^4 (the
//! discriminant's e²−(1−e)² = 2e − 1 makes it a square). Matching the three
//! coefficients (for all c) with the two unknowns left by affine invariance has
//! the solution far = 1 − 2e, near = 2e, v1 = e(1 − 2e), v0 = 1 − 2e(1 − 2e),
//! which gives eq. (17) at e = 1/3; these are the rules used. At a vertex of
//! valence n ≠ 4, α1 and α2 are chosen, as the paper says, so that the limit
//! point equals TPS's: the left eigenvector (1, l_a, l_b) of block 0 of TPS
//! (l_a = 9(2α1 + α2)/10, l_b = 3(α1 + 8α2)/20 at TPS's α) must be the left
//! eigenvector for 1 of the adjustable block 0, which is linear in α1, α2.
//! Valence 4 keeps the tensor-product rule, so regular regions stay the
//! regular adjustable scheme.

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::schemes::entry::SchemeEntry;
use crate::schemes::memo::WeightMemo;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, ParamSpec, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};
use std::sync::Arc;

pub struct Tps {
    params: Params,
    /// the 1-D weights in each weight type asked for, made once: every
    /// weight of the rules needs them, and converting e and forming them
    /// anew at each weight, in exact arithmetic, was most of the cost of the
    /// exact stencils the characteristic-map certificate checks
    one_d_made: WeightMemo,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "tps",
    description: "Karčiauskas–Peters primal (ternary) bi-2 subdivision of quad meshes (TPS; adjustable with e != 1/3)",
    topology: Topology::Ternary,
    centre: CentreKind::Vertex,
    sector: SectorKind::Quad,
    caps: Caps::NONE,
};

const E: ParamSpec = ParamSpec {
    name: "e",
    default: "1/3",
    min: 0.01,
    max: 0.49,
    description: "split ratio e : 1-2e : e (1/3: TPS; other values: adjustable TPS, section 4.1); \
                  e = 0 stops the contraction, e = 1/2 collapses the net",
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![E],
        build: |params| Box::new(Tps { params, one_d_made: WeightMemo::new() }),
    }
}

/// α1 of eq. (18) for TPS (e = 1/3) at valence n (the paper's experimental choice).
pub fn alpha1<W: Weight>(n: i64) -> W {
    if n == 3 {
        W::ratio(339, 896)
    } else {
        W::ratio(7 * n, (2 * n + 1) * (2 * n + 1))
    }
}

/// 1-D weights of the (adjustable) ternary rules at split ratio e.
struct OneD<W> {
    /// edge point: weight of the near and of the far end
    near: W,
    far: W,
    /// vertex: weight of the vertex and of each neighbour
    v0: W,
    v1: W,
}

impl<W: Weight> OneD<W> {
    fn new(e: W) -> Self {
        let two_e = W::int(2) * e.clone();
        let far = W::one() - two_e.clone();
        let v1 = e * far.clone();
        let v0 = W::one() - W::int(2) * v1.clone();
        OneD { near: two_e, far, v0, v1 }
    }
}

impl Tps {
    fn one_d<W: Weight>(&self) -> Result<Arc<OneD<W>>, Inexact> {
        self.one_d_made.get::<W, _>(0, || W::param(self.params.of(&E).expect("e has a default")).map(OneD::new))
    }

    /// (α1, α2) of eq. (18) at valence n.
    pub fn alphas<W: Weight>(&self, n: i64) -> Result<(W, W), Inexact> {
        let w = self.one_d::<W>()?;
        if n == 4 {
            // the tensor-product vertex rule: v0² q + v0 v1 Σ edge + v1² Σ diagonal
            let four = W::int(4);
            return Ok((four.clone() * w.v0.clone() * w.v1.clone(), four * w.v1.clone() * w.v1.clone()));
        }
        let (a1, a2): (W, W) = (alpha1(n), alpha1::<W>(n) / W::int(7));
        // TPS's left eigenvector (1, l_a, l_b) of block 0 for eigenvalue 1
        let la = W::ratio(9, 10) * (W::int(2) * a1.clone() + a2.clone());
        let lb = W::ratio(3, 20) * (a1 + W::int(8) * a2);
        // adjustable block 0: ā' = s_q q + aa ā + ab b̄, b̄' = t_q q + ba ā + bb b̄
        let aa = w.far.clone() * w.v0.clone() + W::int(2) * w.near.clone() * w.v1.clone();
        let ab = W::int(2) * w.far.clone() * w.v1.clone();
        let ba = W::int(2) * w.near.clone() * w.far.clone();
        let bb = w.far.clone() * w.far.clone();
        // columns ā and b̄ of (1, l_a, l_b)·B = (1, l_a, l_b)
        let alpha1 = la.clone() * (W::one() - aa) - lb.clone() * ba;
        let alpha2 = lb * (W::one() - bb) - la * ab;
        Ok((alpha1, alpha2))
    }
}

// The rules are a mask on the ternary host's slots (as a scheme file on that
// host): corner points, edge points and vertex points of the 3 x 3 split.
impl Wants for Tps {
    fn rule(&self, rule: &str) -> bool {
        matches!(rule, "vertex" | "edge" | "corner")
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        matches!(
            (rule, family),
            ("vertex", "centre" | "edge" | "face")
                | ("edge", "near" | "far" | "near-side" | "far-side")
                | ("corner", "near" | "side" | "far")
        )
    }
}

impl<W: Weight> Mask<W> for Tps {
    fn weight(&self, _mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        let w = self.one_d::<W>()?;
        Ok(match (rule, slot.family) {
            // the corner point near c_0 of a quad: the tensor product of the 1-D rule
            ("corner", "near") => w.near.clone() * w.near.clone(),
            ("corner", "side") => w.near.clone() * w.far.clone(),
            ("corner", "far") => w.far.clone() * w.far.clone(),
            // the edge point near a on edge a-b, and the quads' other corners
            ("edge", "near") => w.near.clone() * w.v0.clone(),
            ("edge", "far") => w.far.clone() * w.v0.clone(),
            ("edge", "near-side") => w.near.clone() * w.v1.clone(),
            ("edge", "far-side") => w.far.clone() * w.v1.clone(),
            // the vertex point (valence n) with the weights α1, α2 of `alphas`
            ("vertex", family) => {
                let n = slot.n as i64;
                let (a1, a2): (W, W) = self.alphas(n)?;
                match family {
                    "centre" => W::one() - a1 - a2,
                    "edge" => a1 / W::int(n),
                    "face" => a2 / W::int(n),
                    _ => W::zero(),
                }
            }
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for Tps {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::Ternary, mesh, origin, self, &W::one())
    }
}

impl Scheme for Tps {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
