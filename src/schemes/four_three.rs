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

use super::{Caps, CentreKind, ParamSpec, Params, Rules, Scheme, SchemeEntry, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::sdc::{Origin, RuleResult, Stencil};
use crate::sdc::{Topology, TriangleSplit};

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
    topology: Topology::PrimalSplit(TriangleSplit::FourTriangles),
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

    fn vertex_rule<W: Weight>(&self, v: usize, fan: &[Vec<usize>], t: &NodeType) -> Result<Stencil<W>, Inexact> {
        let n = fan.len();
        // u_i = fan[i][1]: the neighbour shared by fan faces i - 1 and i
        let u = |i: usize| fan[i % n][1];
        let mut s = Stencil::new();
        match *t {
            NodeType::RegularQuad => {
                s.add(v, W::ratio(1, 2));
                (0..4).for_each(|i| s.add(u(i), W::ratio(1, 8)));
            }
            NodeType::RegularTri => {
                s.add(v, W::ratio(10, 16));
                (0..6).for_each(|i| s.add(u(i), W::ratio(1, 16)));
            }
            NodeType::Transition { k } => {
                s.add(v, W::ratio(18, 32));
                s.add(u(k + 1), W::ratio(4, 32)); // between the two quads
                s.add(u(k), W::ratio(3, 32)); // quad/tri boundary
                s.add(u(k + 2), W::ratio(3, 32)); // quad/tri boundary
                s.add(u(k + 3), W::ratio(2, 32));
                s.add(u(k + 4), W::ratio(2, 32));
            }
            NodeType::Eon => {
                let nn = n as i64;
                let c: W = self.centre_weight(nn)?;
                s.add(v, c.clone());
                let b = (W::one() - c) / W::int(nn);
                (0..n).for_each(|i| s.add(u(i), b.clone()));
                let share = self.eon_quad_term::<W>()? * self.eon_share();
                if !share.is_zero() {
                    // (4a'): + 1/(16n) (w_i − (u_i + u_{i+1})/2) per quad face i = [v, u_i, w_i, u_{i+1}]
                    let w = share / W::int(16 * nn);
                    let half = w.clone() * W::ratio(-1, 2);
                    for f in fan.iter().filter(|f| f.len() == 4) {
                        s.add(f[2], w.clone());
                        s.add(f[1], half.clone());
                        s.add(f[3], half.clone());
                    }
                }
            }
        }
        Ok(s)
    }

    fn eon_quad_term<W: Weight>(&self) -> Result<W, Inexact> {
        match self.params.of(&EON_QUAD_TERM) {
            Some(p) => W::param(p),
            None => Ok(W::zero()),
        }
    }

    /// (4b) for the edge from eon `e` (fan `fan`) to its neighbour `b`.
    fn rule_4b<W: Weight>(e: usize, fan: &[Vec<usize>], b: usize) -> Result<Option<Stencil<W>>, Inexact> {
        let n = fan.len();
        let Some(i) = (0..n).find(|&i| fan[i][1] == b) else { return Ok(None) };
        let quarter = W::ratio(1, 4);
        let mut s = Stencil::new().with(e, W::ratio(1, 2)).with(b, quarter.clone());
        for (j, f) in fan.iter().enumerate() {
            let k = (i as i64 - j as i64).rem_euclid(n as i64);
            s.add(f[1], beta_4b::<W>(k, n as i64)? * quarter.clone());
        }
        Ok(Some(s))
    }
}

/// The regular edge rules (1b), (2b), (3b) for the edge a–b between faces
/// `left` (holding a → b, starting at a) and `right` (holding b → a, starting at b).
fn regular_edge<W: Weight>(a: usize, b: usize, left: &[usize], right: &[usize]) -> Stencil<W> {
    let (ql, qr) = (left.len() == 4, right.len() == 4);
    let mut s = Stencil::new();
    let d = if ql || qr { 16 } else { 8 };
    let end = if ql || qr { 6 } else { 3 };
    s.add(a, W::ratio(end, d));
    s.add(b, W::ratio(end, d));
    for (face, quad) in [(left, ql), (right, qr)] {
        if quad {
            // the two corners off the edge
            s.add(face[2], W::ratio(1, 16));
            s.add(face[3], W::ratio(1, 16));
        } else {
            // the apex: 1/8 in (3b), 2/16 in (2b)
            s.add(face[2], W::ratio(1, 8));
        }
    }
    s
}

impl<W: Weight> Rules<W> for FourThree {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        match origin {
            Origin::Vertex(v) => {
                let Some((fan, t)) = classify(mesh, v) else { return Ok(None) };
                Ok(Some(self.vertex_rule(v, &fan, &t)?))
            }
            Origin::Face(f) => {
                let face = mesh.face(f);
                if face.len() != 4 {
                    return Ok(None);
                }
                let mut s = Stencil::new();
                face.iter().for_each(|&v| s.add(v, W::ratio(1, 4)));
                Ok(Some(s))
            }
            Origin::Edge(a, b) => {
                let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
                    return Ok(None);
                };
                let (left, right) = (mesh.face_from(fl, kl), mesh.face_from(fr, kr));
                if [&left, &right].iter().any(|f| f.len() != 3 && f.len() != 4) {
                    return Ok(None);
                }
                // both ends must be classifiable: whether an end is an eon decides the rule
                let (Some(ca), Some(cb)) = (classify(mesh, a), classify(mesh, b)) else { return Ok(None) };
                let regular = regular_edge::<W>(a, b, &left, &right);
                let mut eon_rules = Vec::new();
                for (e, (fan, t), other) in [(a, &ca, b), (b, &cb, a)] {
                    if *t == NodeType::Eon {
                        match Self::rule_4b::<W>(e, fan, other)? {
                            Some(s) => eon_rules.push(s),
                            None => return Ok(None),
                        }
                    }
                }
                if eon_rules.is_empty() {
                    return Ok(Some(regular));
                }
                // an edge joining two eons (the paper does not say): the mean of both (4b)
                let mean = W::ratio(1, eon_rules.len() as i64);
                let share: W = self.eon_share();
                let mut s = Stencil::new();
                for r in &eon_rules {
                    s.add_scaled(r, &(mean.clone() * share.clone()));
                }
                s.add_scaled(&regular, &(W::one() - share));
                Ok(Some(s))
            }
            Origin::Corner { .. } => Ok(None),
        }
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
}
