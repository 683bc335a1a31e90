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

use super::{CentreKind, ParamSpec, Params, Rules, Scheme, SchemeEntry};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::Weight;
use crate::refine::{Origin, RuleResult, Stencil};
use crate::topology::Topology;

pub struct UnifiedSqrt3 {
    params: Params,
    name: &'static str,
}

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: "unified-sqrt3",
        description: "Lin–Luo unified sqrt(3) subdivision: alpha = 0 Kobbelt, alpha = 1 interpolatory",
        params: || {
            vec![ParamSpec {
                name: "alpha",
                default: "1",
                min: 0.0,
                max: 2.0,
                description: "blend: 0 approximating (Kobbelt), 1 interpolatory; the paper analyses [0, 2]",
            }]
        },
        build: |params| Box::new(UnifiedSqrt3 { params, name: "unified-sqrt3" }),
    }
}

/// Kobbelt's sqrt(3) scheme: the same rules at α = 0 (no parameter).
pub fn kobbelt_entry() -> SchemeEntry {
    SchemeEntry {
        name: "sqrt3",
        description: "Kobbelt's approximating sqrt(3) subdivision (unified-sqrt3 at alpha = 0)",
        params: Vec::new,
        build: |_| {
            let params = Params { values: vec![("alpha".to_string(), crate::numeric::ParamValue::from_ratio(0, 1))] };
            Box::new(UnifiedSqrt3 { params, name: "sqrt3" })
        },
    }
}

impl UnifiedSqrt3 {
    /// α at vertex v: the mesh's per-vertex value when it carries one (eq. 7,
    /// non-uniform scheme; floats only), else the uniform parameter.
    fn alpha<W: Weight>(&self, mesh: &PolyMesh, v: usize) -> Result<W, crate::numeric::Inexact> {
        match &mesh.vertex_params {
            Some(a) => W::param(&crate::numeric::ParamValue::from_f64(a[v])),
            None => W::param(self.params.get("alpha").expect("alpha has a default")),
        }
    }
}

/// The one-ring of an interior vertex of a triangle mesh: its neighbours.
fn ring(mesh: &PolyMesh, v: usize) -> Option<Vec<usize>> {
    // read from the mesh's cached fans: the face rule asks for the centre's
    // ring once per face around it
    mesh.uniform_ring(v, 3)
}

impl<W: Weight> Rules<W> for UnifiedSqrt3 {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        Ok(match origin {
            Origin::Face(f) => {
                let face = mesh.face(f);
                if face.len() != 3 {
                    return Ok(None);
                }
                let mut s = Stencil::new();
                for &p in face {
                    let alpha: W = self.alpha(mesh, p)?;
                    let Some(nb) = ring(mesh, p) else { return Ok(None) };
                    let n = nb.len() as i64;
                    let c = W::cos_2pi(1, n)?;
                    let two_a_c = W::int(2) * alpha.clone() * c;
                    s.add(p, (W::int(9) + W::int(4) * alpha.clone() - two_a_c.clone()) / W::int(27));
                    let w = (W::int(4) * alpha.clone() - two_a_c) / W::int(27 * n);
                    for q in nb {
                        s.add(q, -w.clone());
                    }
                }
                Some(s)
            }
            Origin::Vertex(v) => {
                let alpha: W = self.alpha(mesh, v)?;
                let Some(nb) = ring(mesh, v) else { return Ok(None) };
                let n = nb.len() as i64;
                let c = W::cos_2pi(1, n)?;
                let one_minus = W::one() - alpha.clone();
                let centre =
                    (W::int(5) + W::int(4) * alpha.clone() + W::int(2) * one_minus.clone() * c.clone()) / W::int(9);
                let w = one_minus * (W::int(4) - W::int(2) * c) / W::int(9 * n);
                let mut s = Stencil::new().with(v, centre);
                for q in nb {
                    s.add(q, w.clone());
                }
                Some(s)
            }
            Origin::Edge(..) | Origin::Corner { .. } => None,
        })
    }
}

impl Scheme for UnifiedSqrt3 {
    fn name(&self) -> &'static str {
        self.name
    }
    fn description(&self) -> &'static str {
        if self.name == "sqrt3" {
            kobbelt_entry().description
        } else {
            entry().description
        }
    }
    fn topology(&self) -> Topology {
        Topology::Sqrt3
    }
    fn centre_kind(&self) -> CentreKind {
        CentreKind::Vertex
    }
    fn sector_kind(&self) -> SectorKind {
        SectorKind::Tri
    }
    fn params(&self) -> &Params {
        &self.params
    }
    fn vertex_param(&self) -> Option<&'static str> {
        (self.name == "unified-sqrt3").then_some("alpha")
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
