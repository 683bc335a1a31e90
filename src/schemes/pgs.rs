//! Point-augmented bi-2 subdivision, PGS (Karčiauskas & Peters,
//! "Point-augmented biquadratic C^1 subdivision surfaces", section 2).
//!
//! A Doo–Sabin net (all vertices of valence 4) plus a central point p in
//! every face that is not a quad. With a_i the corners of such an n-gon,
//! b_i, d_i the two other neighbours of a_i, c = cos(2π/n):
//!
//! * quad corners away from points: the biquadratic rule (9, 3, 3, 1)/16
//!   (also eq. (4)'s neighbours b, c, d: "standard binary refinement");
//! * p' = (1 − α) p + α ā                                            (3)
//! * a_i' = (1 − w1 − 2w2) p + w1 a_i + w2 (a_{i−1} + a_{i+1})       (4)
//! * α = 3/4 + μ_n (w1 + 2w2 − 1)                                    (8)
//! * w2 = w1/4, w1 = 2 λ_sub/(2 + c)                                 (9)
//! * λ_sub = Σ_{i=0..3} b_i C(3,i) (1 − c)^{3−i} c^i, b = (1/2, .5519, .5985, .64367)  (10)
//!
//! A face without a point (the user's net, or a face born in the last step)
//! takes p := μ_n ā + (1 − μ_n)(b̄ + d̄)/2 (eq. (1), μ_3 = 3/5,
//! μ_n = 2(n − 2)/n) before the step. Parameters `mu` and `lambda_sub`, when
//! given, replace μ_n and λ_sub at every valence n ≠ 4 (valence 4 keeps the
//! paper's values, which make a 4-gon's rules the biquadratic ones).

use super::{Caps, CentreKind, ParamSpec, Params, Rules, Scheme, SchemeEntry, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::sdc::Topology;
use crate::sdc::{Origin, RuleResult, Stencil};

pub struct Pgs {
    params: Params,
}

const INFO: SchemeInfo = SchemeInfo {
    name: "pgs",
    description: "Karčiauskas–Peters point-augmented bi-2 subdivision (PGS): Doo–Sabin nets plus a central point",
    topology: Topology::AugmentedDual,
    centre: CentreKind::AugmentedFace,
    sector: SectorKind::Quad,
    caps: Caps::NONE,
};

const MU: ParamSpec = ParamSpec {
    name: "mu",
    default: "",
    min: 0.0,
    max: 2.0,
    description: "mu_n of eqs. (1), (8) at valences n != 4 (default 3/5 at n = 3, 2(n-2)/n)",
};

const LAMBDA_SUB: ParamSpec = ParamSpec {
    name: "lambda_sub",
    default: "",
    min: 0.0,
    max: 1.0,
    description: "the subdominant eigenvalue prescribed by eq. (9) at valences n != 4 (default eq. (10))",
};

pub fn entry() -> SchemeEntry {
    SchemeEntry {
        name: INFO.name,
        description: INFO.description,
        params: || vec![MU, LAMBDA_SUB],
        build: |params| Box::new(Pgs { params }),
    }
}

/// The weights of one valence: (μ, w1, w2, α).
pub struct PgsWeights<W> {
    pub mu: W,
    pub w1: W,
    pub w2: W,
    pub alpha: W,
}

/// λ_sub of eq. (10): a cubic Bernstein form in c = cos(2π/n).
pub fn paper_lambda_sub<W: Weight>(n: i64) -> Result<W, Inexact> {
    let c = W::cos_2pi(1, n)?;
    let d = W::one() - c.clone();
    let b = [W::ratio(1, 2), W::ratio(5519, 10000), W::ratio(5985, 10000), W::ratio(64367, 100000)];
    let binom = [1, 3, 3, 1];
    let mut sum = W::zero();
    for i in 0..4 {
        let mut t = b[i].clone() * W::int(binom[i]);
        for _ in 0..3 - i {
            t = t * d.clone();
        }
        for _ in 0..i {
            t = t * c.clone();
        }
        sum = sum + t;
    }
    Ok(sum)
}

/// μ_n of eq. (1).
pub fn paper_mu<W: Weight>(n: i64) -> W {
    if n == 3 {
        W::ratio(3, 5)
    } else {
        W::ratio(2 * (n - 2), n)
    }
}

impl Pgs {
    pub fn weights<W: Weight>(&self, n: i64) -> Result<PgsWeights<W>, Inexact> {
        let given = |spec: &ParamSpec| if n == 4 { None } else { self.params.of(spec) };
        let mu = match given(&MU) {
            Some(p) => W::param(p)?,
            None => paper_mu(n),
        };
        let lambda = match given(&LAMBDA_SUB) {
            Some(p) => W::param(p)?,
            None => paper_lambda_sub(n)?,
        };
        let c = W::cos_2pi(1, n)?;
        let w1 = W::int(2) * lambda / (W::int(2) + c);
        let w2 = w1.clone() / W::int(4);
        let omega = w1.clone() + W::int(2) * w2.clone();
        let alpha = W::ratio(3, 4) + mu.clone() * (omega - W::one());
        Ok(PgsWeights { mu, w1, w2, alpha })
    }

    /// The central point of face f: its own point, or eq. (1) from the net.
    /// `None` when a corner does not have valence 4.
    fn centre<W: Weight>(&self, mesh: &PolyMesh, f: usize) -> Result<Option<Stencil<W>>, Inexact> {
        if let Some(p) = mesh.face_point(f) {
            return Ok(Some(Stencil::new().with(p, W::one())));
        }
        let face = mesh.face(f);
        let n = face.len() as i64;
        let mu: W = self.weights::<W>(n)?.mu;
        let corner_w = mu.clone() / W::int(n);
        let outer_w = (W::one() - mu) / W::int(2 * n);
        let mut s = Stencil::new();
        for (k, &a) in face.iter().enumerate() {
            let (prev, next) = (face[(k + face.len() - 1) % face.len()], face[(k + 1) % face.len()]);
            let Some(fan) = mesh.vertex_fan(a) else { return Ok(None) };
            if fan.len() != 4 {
                return Ok(None);
            }
            s.add(a, corner_w.clone());
            // b_i and d_i: the neighbours of a_i that are not corners of the face
            for cyc in &fan {
                if cyc[1] != prev && cyc[1] != next {
                    s.add(cyc[1], outer_w.clone());
                }
            }
        }
        Ok(Some(s))
    }

    fn augmented(mesh: &PolyMesh, f: usize) -> bool {
        mesh.face_point(f).is_some() || mesh.face(f).len() != 4
    }
}

impl<W: Weight> Rules<W> for Pgs {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        match origin {
            Origin::Corner { face, corner } if Pgs::augmented(mesh, face) => {
                let cyc = mesh.face_from(face, corner);
                let n = cyc.len() as i64;
                let PgsWeights { w1, w2, .. } = self.weights::<W>(n)?;
                let Some(p) = self.centre::<W>(mesh, face)? else { return Ok(None) };
                let mut s = Stencil::new().with(cyc[0], w1.clone());
                s.add(cyc[1], w2.clone());
                s.add(cyc[cyc.len() - 1], w2.clone());
                s.add_scaled(&p, &(W::one() - w1 - W::int(2) * w2));
                Ok(Some(s))
            }
            Origin::Corner { face, corner } => {
                let cyc = mesh.face_from(face, corner);
                // a Doo–Sabin net has valence-4 vertices only (the patch
                // boundary of an analysis neighbourhood has no fan: allowed)
                if mesh.valence(cyc[0]).is_some_and(|v| v != 4) {
                    return Ok(None);
                }
                let w = |k: i64| W::ratio(k, 16);
                Ok(Some(Stencil::new().with(cyc[0], w(9)).with(cyc[1], w(3)).with(cyc[2], w(1)).with(cyc[3], w(3))))
            }
            Origin::Face(f) => {
                let face = mesh.face(f);
                let n = face.len() as i64;
                let alpha = self.weights::<W>(n)?.alpha;
                let Some(p) = self.centre::<W>(mesh, f)? else { return Ok(None) };
                let mut s = Stencil::new();
                s.add_scaled(&p, &(W::one() - alpha.clone()));
                for &a in face {
                    s.add(a, alpha.clone() / W::int(n));
                }
                Ok(Some(s))
            }
            Origin::Vertex(_) | Origin::Edge(..) => Ok(None),
        }
    }
}

impl Scheme for Pgs {
    fn info(&self) -> &SchemeInfo {
        &INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
