//! 4-3 subdivision (J. Peters and L.-J. Shiue, "Combining 4- and 3-direction
//! subdivision"): one scheme for meshes of quads and triangles.
//!
//! The paper's figure 4 (the stencils) is missing from the text; the weights
//! below are those of the authors' implementation as recorded in ARCHITECTURE.md
//! ("Facts for 4-3 subdivision"), unnormalised / denominator:
//!
//! (1a) regular quad vertex (4 quads):       (4 v + Σ 4 neighbours) / 8
//! (3a) regular triangle vertex (6 tris):    (10 v + Σ 6 neighbours) / 16
//! (2a) transition vertex (2 quads, 3 tris): (18 v + 4 u_between-quads
//!                                            + 3 (2 u on the quad/tri boundary)
//!                                            + 2 (2 other tri-side u)) / 32
//! (4a) eon of valence n:                    c v + (1 − c)/n Σ u_j,  c = `centre_weight`
//! (1b) quad edge:      (6 (p1 + p2) + the 4 other quad corners) / 16
//! (3b) triangle edge:  (3 (p1 + p2) + the 2 apexes) / 8
//! (2b) quad/tri edge:  (6 (p1 + p2) + the 2 other quad corners + 2 apex) / 16
//! (4b) edge at an eon: (2 v* + v_i + Σ_j β_{i−j} v_j) / 4, β_k = (1 + 2 cos(2πk/n)) / n
//!      quad face point: average of the 4 corners; triangles split 1 → 4.
//!
//! An eon is any vertex that is neither regular nor a transition vertex. The
//! quad rules are the subdivision rules of the four-direction box spline A_4
//! (not Catmull–Clark's bicubic B-spline) and the triangle rules those of the
//! three-direction quartic box spline A_3 (Loop's regular rules); see
//! tests/four_three.rs for the derivation from the direction matrices.
//!
//! Rule (4a') of section 3.3 adds (1/16n) Σ_{quads q_i} (w_i − (v_i + v_{i−1})/2)
//! to the eon (w_i the corner of quad q_i opposite the eon). Parameter
//! `eon_quad_term` t blends it in: eon rule = (1 − t)·(4a) + t·(4a'); t = 0 (the
//! default) is section 2's algorithm.
//!
//! Stationary rules (the local subdivision matrix): (4b) alone on edges at an eon,
//! as the paper's analysis assumes. Mesh refinement (`at_level`): in step σ ≤ σ0 = 3
//! the edge at an eon is (σ−1)/σ (4b) + 1/σ (regular rule), after σ0 (4b) alone
//! (section 2); the (4a') share is blended with the same factor (Lemma 3.8).

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::schemes::entry::SchemeEntry;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, ParamSpec, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};

/// σ0 of section 2: the last refinement step that still blends (4b) with the
/// regular edge rules ("say σ0 = 3").
pub const BLEND_LEVELS: usize = 3;

#[derive(Clone)]
pub struct FourThree {
    params: Params,
    /// refinement step of a real mesh (1-based); `None`: the stationary rules
    level: Option<usize>,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "four-three",
    description:
        "Peters–Shiue 4-3 subdivision of quad/triangle meshes (A_4 and A_3 box splines, 4-3 transition, eon rules)",
    topology: Topology::MixedQuadTriangle,
    centre: CentreKind::Vertex,
    sector: SectorKind::Quad,
    caps: Caps { face_sequences: true, mesh_requirement: Some("a closed mesh of triangles and quads"), ..Caps::NONE },
};

const CENTRE_WEIGHT: ParamSpec = ParamSpec {
    name: "centre_weight",
    default: "",
    min: 0.25,
    max: 0.75,
    description: "the eon's own weight (figure 4's alpha; 1 - alpha of the matrix M); default the paper's 3/8 (n = 3), 1/2 (n = 4), 3/5 (n > 4)",
};

const EON_QUAD_TERM: ParamSpec = ParamSpec {
    name: "eon_quad_term",
    default: "0",
    min: 0.0,
    max: 1.0,
    description: "share t of rule (4a') in the eon rule: (1 - t) (4a) + t (4a')",
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![CENTRE_WEIGHT, EON_QUAD_TERM],
        build: |params| Box::new(FourThree { params, level: None }),
    }
}

/// The paper's recommended centre weight (figure 4 caption) at valence n.
pub fn paper_centre_weight<W: Weight>(n: i64) -> W {
    match n {
        3 => W::ratio(3, 8),
        4 => W::ratio(1, 2),
        _ => W::ratio(3, 5),
    }
}

/// β_k = (1 + 2 cos(2πk/n)) / n of rule (4b).
pub fn beta_4b<W: Weight>(k: i64, n: i64) -> Result<W, Inexact> {
    Ok((W::one() + W::int(2) * W::cos_2pi(k, n)?) / W::int(n))
}

// The node types of a quad/triangle mesh belong to the mixed host's slot
// layer (the host's gatherer and these rules classify alike); re-exported
// here, where the 4-3 rules use them.
pub use crate::sdc::slots::{classify, NodeType};

impl FourThree {
    fn centre_weight<W: Weight>(&self, n: i64) -> Result<W, Inexact> {
        match self.params.of(&CENTRE_WEIGHT) {
            Some(p) => W::param(p),
            None => Ok(paper_centre_weight(n)),
        }
    }

    /// Share of the eon-specific variants ((4b), (4a')) at this step.
    fn eon_share<W: Weight>(&self) -> W {
        match self.level {
            Some(s) if s <= BLEND_LEVELS => W::ratio(s as i64 - 1, s as i64),
            _ => W::one(),
        }
    }

    fn eon_quad_term<W: Weight>(&self) -> Result<W, Inexact> {
        match self.params.of(&EON_QUAD_TERM) {
            Some(p) => W::param(p),
            None => Ok(W::zero()),
        }
    }
}

// The rules are a mask on the mixed quad/triangle host's slots (as a scheme
// file on that host): the host classifies every vertex (regular quad,
// regular triangle, transition, eon) and edge; the eon's rule (4a) with the
// optional quad term (4a') and the eon edge rule (4b) are blended in over
// the first levels of a real mesh by `weigh`'s extraordinary share.
impl Wants for FourThree {
    fn rule(&self, rule: &str) -> bool {
        matches!(
            rule,
            "vertex-quad"
                | "vertex-triangle"
                | "vertex-transition"
                | "vertex-eon"
                | "edge-quad"
                | "edge-triangle"
                | "edge-mixed"
                | "edge-eon"
                | "face"
        )
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        match (rule, family) {
            // the quad term (4a') only when it has weight
            ("vertex-eon", "quad-opposite" | "quad-side") => !self.eon_quad_term::<f64>().is_ok_and(|t| t == 0.0),
            _ => Wants::rule(self, rule),
        }
    }
}

impl<W: Weight> Mask<W> for FourThree {
    fn weight(&self, _mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        let n = slot.n as i64;
        Ok(match (rule, slot.family) {
            ("vertex-quad", "centre") => W::ratio(1, 2),
            ("vertex-quad", "edge") => W::ratio(1, 8),
            ("vertex-triangle", "centre") => W::ratio(10, 16),
            ("vertex-triangle", "edge") => W::ratio(1, 16),
            // two quads, then three triangles
            ("vertex-transition", "centre") => W::ratio(18, 32),
            ("vertex-transition", "between") => W::ratio(4, 32),
            ("vertex-transition", "boundary") => W::ratio(3, 32),
            ("vertex-transition", "triangle-side") => W::ratio(2, 32),
            // (4a): the centre weight, the rest shared by the n neighbours
            ("vertex-eon", "centre") => self.centre_weight(n)?,
            ("vertex-eon", "edge") => (W::one() - self.centre_weight::<W>(n)?) / W::int(n),
            // (4a'): + t/(16n) (w_i − (u_i + u_{i+1})/2) per quad face i = [v, u_i, w_i, u_{i+1}]
            ("vertex-eon", "quad-opposite") => self.eon_quad_term::<W>()? / W::int(16 * n),
            ("vertex-eon", "quad-side") => self.eon_quad_term::<W>()? / W::int(16 * n) * W::ratio(-1, 2),
            ("edge-quad", "ends") => W::ratio(6, 16),
            ("edge-quad", "side") => W::ratio(1, 16),
            ("edge-triangle", "ends") => W::ratio(3, 8),
            ("edge-triangle", "opposite") => W::ratio(1, 8),
            ("edge-mixed", "ends") => W::ratio(6, 16),
            ("edge-mixed", "side") => W::ratio(1, 16),
            ("edge-mixed", "opposite") => W::ratio(2, 16),
            // (4b): (2 e + u_0 + Σ_j β_j u_j) / 4, u_0 the edge's other end
            ("edge-eon", "centre") => W::ratio(1, 2),
            ("edge-eon", "edge") => {
                let j = slot.j as i64;
                let beta = beta_4b::<W>((-j).rem_euclid(n), n)? * W::ratio(1, 4);
                if j == 0 {
                    W::ratio(1, 4) + beta
                } else {
                    beta
                }
            }
            ("face", "corner") => W::ratio(1, n),
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for FourThree {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::MixedQuadTriangle, mesh, origin, self, &self.eon_share())
    }
}

impl Scheme for FourThree {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
    fn at_level(&self, level: usize) -> Option<Box<dyn Scheme>> {
        Some(Box::new(FourThree { params: self.params.clone(), level: Some(level) }))
    }
    /// The first levels of a real mesh blend the eon rules in, so the level
    /// is part of what the rules are.
    fn identity(&self) -> Option<String> {
        Some(format!("{} [{}] level {:?}", INFO.name, self.params.identity_text(), self.level))
    }
}
