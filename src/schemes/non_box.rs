//! Non-box subdivision (Z. Huang, "A surface subdivision scheme based on
//! four-directional S_3^1 non-box splines"), in its quadrilateral form with
//! face control vertices (FCVs), section 3.2.2:
//!
//! E-vertex:  (V_a + V_b + FCV_left + FCV_right) / 4
//! V-vertex:  (1 − a_k) V + (a_k / k) Σ FCV_i      (k faces around V)
//! FCV rule:  (1 − a_k) FCV + (a_k / k) Σ V_i      (k corners of the face)
//! NFCV:      V_0/4 + FCV_0/2 + FCV_1/8 + FCV_{−1}/8
//!            (F_0 the old face of the new quad, F_{±1} its neighbours at V_0)
//!
//! Weights (section 4): a_3 = 3/4, a_k = 3/4 − (1/2 + cos(2π/k)/4)^2 for
//! k ≥ 4, so a_4 = 1/2 (the regular S_3^1 spline). The parameter `a`, when
//! given, replaces a_k at every valence k ≠ 4 (vertices and k-gons); valence 4
//! keeps 1/2 so that the regular part stays the spline.

use super::{Caps, CentreKind, ParamSpec, Params, Rules, Scheme, SchemeEntry, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::sdc::Topology;
use crate::sdc::{Origin, RuleResult, Stencil};

pub struct NonBox {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "non-box",
    description: "Huang's non-box S_3^1 subdivision: quads with face control vertices (FCVs)",
    topology: Topology::FcvSplit,
    centre: CentreKind::Vertex,
    sector: SectorKind::Quad,
    caps: Caps {
        face_control: true,
        boundary_note: Some(
            "the paper's boundary rules are cubic B-spline V- and E-vertex rules plus a boundary NFCV stencil given \
             only in its figure 8(b), which the text lacks",
        ),
        ..Caps::NONE
    },
};

const PARAM_A: ParamSpec = ParamSpec {
    name: "a",
    default: "",
    min: 0.0,
    max: 1.0,
    description: "a_k at every valence k != 4 (default: the paper's a_3 = 3/4, a_k = 3/4 - (1/2 + cos(2pi/k)/4)^2)",
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![PARAM_A],
        build: |params| Box::new(NonBox { params }),
    }
}

/// The paper's weight a_k (section 4).
pub fn paper_a<W: Weight>(k: i64) -> Result<W, Inexact> {
    if k == 3 {
        return Ok(W::ratio(3, 4));
    }
    let t = W::ratio(1, 2) + W::cos_2pi(1, k)? * W::ratio(1, 4);
    Ok(W::ratio(3, 4) - t.clone() * t)
}

impl NonBox {
    fn a<W: Weight>(&self, k: i64) -> Result<W, Inexact> {
        match self.params.of(&PARAM_A) {
            Some(p) if k != 4 => W::param(p),
            _ => paper_a(k),
        }
    }
}

impl<W: Weight> Rules<W> for NonBox {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        if !mesh.has_face_point_on_every_face() {
            return Ok(None);
        }
        Ok(match origin {
            Origin::Edge(a, b) => {
                let (Some(l), Some(r)) = (mesh.face_point_left_of(a, b), mesh.face_point_left_of(b, a)) else {
                    return Ok(None);
                };
                let q = W::ratio(1, 4);
                Some(Stencil::new().with(a, q.clone()).with(b, q.clone()).with(l, q.clone()).with(r, q))
            }
            Origin::Vertex(v) => {
                let Some(fan) = mesh.vertex_fan(v) else { return Ok(None) };
                let k = fan.len() as i64;
                let a: W = self.a(k)?;
                let mut s = Stencil::new().with(v, W::one() - a.clone());
                for cyc in &fan {
                    let Some(p) = mesh.face_point_left_of(v, cyc[1]) else { return Ok(None) };
                    s.add(p, a.clone() / W::int(k));
                }
                Some(s)
            }
            Origin::Face(f) => {
                let face = mesh.face(f);
                let k = face.len() as i64;
                let a: W = self.a(k)?;
                let mut s = Stencil::new().with(mesh.face_point(f).expect("checked above"), W::one() - a.clone());
                for &v in face {
                    s.add(v, a.clone() / W::int(k));
                }
                Some(s)
            }
            Origin::Corner { face: f, corner: k } => {
                let cyc = mesh.face_from(f, k);
                let (v0, next, prev) = (cyc[0], cyc[1], cyc[cyc.len() - 1]);
                // the two old faces at V_0 adjacent to F_0: across (V_0, next) and (prev, V_0)
                let (Some(f1), Some(fm1)) = (mesh.face_point_left_of(next, v0), mesh.face_point_left_of(v0, prev))
                else {
                    return Ok(None);
                };
                let f0 = mesh.face_point(f).expect("checked above");
                Some(
                    Stencil::new()
                        .with(v0, W::ratio(1, 4))
                        .with(f0, W::ratio(1, 2))
                        .with(f1, W::ratio(1, 8))
                        .with(fm1, W::ratio(1, 8)),
                )
            }
        })
    }
}

impl Scheme for NonBox {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
