//! Unified interpolatory/approximating sqrt(3) subdivision (Lin & Luo), with a
//! uniform parameter α (the paper allows per-vertex α; the stationary analysis
//! uses a constant). α = 0 is Kobbelt's sqrt(3) scheme, α = 1 the new
//! interpolatory scheme.
//!
//! With c = cos(2π/n) for the valence n of the vertex concerned and
//! avg(P) = (1/n) Σ_{Q ∈ H(P)} Q the average of P's neighbours:
//!
//! face vertex (eq. 8, 10): q = Σ_{P corner} [ (9 + 4α − 2αc)/27 P − (4α − 2αc)/27 avg(P) ]
//! old vertex  (eq. 11):    q' = (5 + 4α + 2(1 − α)c)/9 q + (1 − α)(4 − 2c)/9 avg(q)
//!
//! These are the paper's expanded formulas. Its short forms (4), (9), (11,
//! first line) write them with the displacement Δ of a Kobbelt step, but the
//! signs only agree with the expansions when Δ is read as old − new, while the
//! text defines Δ as the displacement (new − old); the claims registry records
//! that. The expansions are implemented because they are the rules the paper
//! states in full and because they reduce to Kobbelt's rules (1), (2) at α = 0.

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Inexact;
use crate::numeric::Weight;
use crate::schemes::entry::SchemeEntry;
use crate::schemes::memo::WeightMemo;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::{Caps, CentreKind, MeshDomain, ParamSpec, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult, Stencil};
use crate::sdc::{Topology, VertexParam};

pub struct UnifiedSqrt3 {
    params: Params,
    /// the same rules under two names: `unified-sqrt3` with α as a parameter
    /// (also per vertex), `sqrt3` fixed at α = 0
    info: &'static SchemeInfo,
    /// the four weights per valence and weight type at the scheme's own α
    /// (a mesh without per-vertex α), made once (see `memo`)
    made: WeightMemo,
}

/// The weights of eqs. (1) and (2) at one valence and one α.
struct Sqrt3Weights<W> {
    centre: W,
    edge: W,
    corner: W,
    ring: W,
}

impl<W: Weight> Sqrt3Weights<W> {
    fn new(alpha: W, n: i64) -> Result<Self, Inexact> {
        let c = W::cos_2pi(1, n)?;
        let one_minus = W::one() - alpha.clone();
        let two_a_c = W::int(2) * alpha.clone() * c.clone();
        Ok(Sqrt3Weights {
            // eq. (2): the old vertex relaxed
            centre: (W::int(5) + W::int(4) * alpha.clone() + W::int(2) * one_minus.clone() * c.clone()) / W::int(9),
            edge: one_minus * (W::int(4) - W::int(2) * c) / W::int(9 * n),
            // eq. (1): the new face point, one term per corner P
            corner: (W::int(9) + W::int(4) * alpha.clone() - two_a_c.clone()) / W::int(27),
            ring: -((W::int(4) * alpha - two_a_c) / W::int(27 * n)),
        })
    }
}

const INFO: SchemeInfo = SchemeInfo {
    name: "unified-sqrt3",
    description: "Lin–Luo unified sqrt(3) subdivision: alpha = 0 Kobbelt, alpha = 1 interpolatory",
    topology: Topology::Sqrt3,
    centre: CentreKind::Vertex,
    sector: SectorKind::Tri,
    caps: Caps { vertex_param: Some(VertexParam { name: ALPHA.name, min: ALPHA.min, max: ALPHA.max }), ..Caps::NONE },
};

const KOBBELT_INFO: SchemeInfo = SchemeInfo {
    name: "sqrt3",
    description: "Kobbelt's approximating sqrt(3) subdivision (unified-sqrt3 at alpha = 0)",
    caps: Caps::NONE,
    ..INFO
};

const ALPHA: ParamSpec = ParamSpec {
    name: "alpha",
    default: "1",
    min: 0.0,
    max: 2.0,
    description: "blend: 0 approximating (Kobbelt), 1 interpolatory; the paper analyses [0, 2]",
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![ALPHA],
        build: |params| Box::new(UnifiedSqrt3 { params, info: &INFO, made: WeightMemo::new() }),
    }
}

/// Kobbelt's sqrt(3) scheme: the same rules at α = 0 (no parameter).
pub fn kobbelt_entry() -> SchemeEntry {
    SchemeEntry {
        name: KOBBELT_INFO.name,
        description: KOBBELT_INFO.description,
        params: Vec::new,
        build: |_| {
            let params = Params { values: vec![("alpha".to_string(), crate::numeric::ParamValue::from_ratio(0, 1))] };
            Box::new(UnifiedSqrt3 { params, info: &KOBBELT_INFO, made: WeightMemo::new() })
        },
    }
}

impl UnifiedSqrt3 {
    /// α at vertex v: the mesh's per-vertex value when it carries one (eq. 7,
    /// non-uniform scheme; floats only), else the uniform parameter.
    fn alpha<W: Weight>(&self, mesh: &PolyMesh, v: usize) -> Result<W, Inexact> {
        match &mesh.vertex_params {
            Some(a) => W::param(&crate::numeric::ParamValue::from_f64(a[v])),
            None => W::param(self.params.of(&ALPHA).expect("alpha has a default")),
        }
    }
}

// The rules are a mask on the sqrt(3) host's slots: the vertex rule weighs v
// and its ring, the face rule each corner P and P's ring (a 2-ring stencil of
// the new face point), every slot at the valence n of its vertex P and with α
// taken at P (`Slot::at`), exactly as a scheme file on that host does.
impl Wants for UnifiedSqrt3 {
    fn rule(&self, rule: &str) -> bool {
        matches!(rule, "vertex" | "face")
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        matches!((rule, family), ("vertex", "centre" | "edge") | ("face", "corner" | "ring"))
    }
}

impl<W: Weight> Mask<W> for UnifiedSqrt3 {
    fn weight(&self, mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        let at = slot.at.expect("every slot of the sqrt(3) host's rules belongs to a vertex");
        let n = slot.n as i64;
        // the scheme's own α is the same at every vertex: its weights are
        // made once per valence; a per-vertex α makes them at each slot
        let weights = match mesh.vertex_params {
            None => self.made.get::<W, _>(n, || Sqrt3Weights::new(self.alpha::<W>(mesh, at)?, n))?,
            Some(_) => std::sync::Arc::new(Sqrt3Weights::new(self.alpha::<W>(mesh, at)?, n)?),
        };
        Ok(match (rule, slot.family) {
            ("vertex", "centre") => weights.centre.clone(),
            ("vertex", "edge") => weights.edge.clone(),
            ("face", "corner") => weights.corner.clone(),
            ("face", "ring") => weights.ring.clone(),
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for UnifiedSqrt3 {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::Sqrt3, mesh, origin, self, &W::one())
    }
}

impl Scheme for UnifiedSqrt3 {
    fn info(&self) -> &SchemeInfo {
        self.info
    }
    fn params(&self) -> &Params {
        &self.params
    }
    /// Eq. (7): a new face vertex takes the mean α of the triangle's corners; an
    /// old vertex keeps its α.
    fn vertex_param_rule(&self, mesh: &PolyMesh, origin: Origin) -> Option<Stencil<f64>> {
        match origin {
            Origin::Vertex(v) => Some(Stencil::new().with(v, 1.0)),
            Origin::Face(f) => {
                let face = mesh.face(f);
                Some(face.iter().fold(Stencil::new(), |s, &v| s.with(v, 1.0 / face.len() as f64)))
            }
            _ => None,
        }
    }
}
