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

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::schemes::entry::SchemeEntry;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, ParamSpec, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};

pub struct NonBox {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "non-box",
    description: "Huang's non-box S_3^1 subdivision: quads with face control vertices (FCVs)",
    topology: Topology::Fcv,
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

// The rules are a mask on the FCV host's slots (the host gathers the face
// control vertices around each origin), as in a scheme file on that host.
impl Wants for NonBox {
    fn rule(&self, rule: &str) -> bool {
        matches!(rule, "vertex" | "edge" | "face" | "corner")
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        matches!(
            (rule, family),
            ("vertex", "centre" | "fcv")
                | ("edge", "ends" | "fcv")
                | ("face", "centre" | "corner")
                | ("corner", "vertex" | "fcv" | "side")
        )
    }
}

impl<W: Weight> Mask<W> for NonBox {
    fn weight(&self, _mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        // slot.n: the valence (vertex rule) or the face size (face rule)
        let k = slot.n as i64;
        Ok(match (rule, slot.family) {
            // V-vertex: (1 − a_k) v + a_k/k Σ FCVs around v
            ("vertex", "centre") | ("face", "centre") => W::one() - self.a(k)?,
            // the FCV of an old face: (1 − a_k) FCV + a_k/k Σ corners
            ("vertex", "fcv") | ("face", "corner") => self.a::<W>(k)? / W::int(k),
            // E-vertex: the mean of the two ends and the two faces' FCVs
            ("edge", "ends" | "fcv") => W::ratio(1, 4),
            // the NFCV at corner V_0 of face F_0: V_0/4 + F_0/2 + the two neighbouring FCVs /8
            ("corner", "vertex") => W::ratio(1, 4),
            ("corner", "fcv") => W::ratio(1, 2),
            ("corner", "side") => W::ratio(1, 8),
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for NonBox {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::Fcv, mesh, origin, self, &W::one())
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
