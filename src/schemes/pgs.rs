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

use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Inexact, Weight};
use crate::schemes::entry::SchemeEntry;
use crate::schemes::memo::WeightMemo;
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::Topology;
use crate::sdc::{Caps, CentreKind, MeshDomain, ParamSpec, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult};
use std::sync::Arc;

pub struct Pgs {
    params: Params,
    /// (μ, w1, w2, α) per valence and weight type, made once (see `memo`)
    made: WeightMemo,
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
        build: |params| Box::new(Pgs { params, made: WeightMemo::new() }),
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
    pub fn weights<W: Weight>(&self, n: i64) -> Result<Arc<PgsWeights<W>>, Inexact> {
        self.made.get::<W, _>(n, || self.make_weights(n))
    }

    fn make_weights<W: Weight>(&self, n: i64) -> Result<PgsWeights<W>, Inexact> {
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
}

// The rules are a mask on the augmented dual host's slots (as a scheme file
// on that host): the biquadratic corner of a plain quad, the corner of a
// face with a central point, the new central point, and eq. (1), the central
// point a face without one gets from the net (a derived slot).
impl Wants for Pgs {
    fn rule(&self, rule: &str) -> bool {
        matches!(rule, "corner" | "corner-augmented" | "face" | "point")
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        matches!(
            (rule, family),
            ("corner", "vertex" | "side" | "far")
                | ("corner-augmented", "vertex" | "side" | "point")
                | ("face", "point" | "corner")
                | ("point", "corner" | "outer")
        )
    }
}

impl<W: Weight> Mask<W> for Pgs {
    fn weight(&self, _mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        // slot.n: the size of the face concerned
        let n = slot.n as i64;
        Ok(match (rule, slot.family) {
            ("corner", "vertex") => W::ratio(9, 16),
            ("corner", "side") => W::ratio(3, 16),
            ("corner", "far") => W::ratio(1, 16),
            ("corner-augmented", family) => {
                let weights = self.weights::<W>(n)?;
                let (w1, w2) = (weights.w1.clone(), weights.w2.clone());
                match family {
                    "vertex" => w1,
                    "side" => w2,
                    "point" => W::one() - w1 - W::int(2) * w2,
                    _ => W::zero(),
                }
            }
            ("face", "point") => W::one() - self.weights::<W>(n)?.alpha.clone(),
            ("face", "corner") => self.weights::<W>(n)?.alpha.clone() / W::int(n),
            // eq. (1): μ/n on the corners a_i, (1 − μ)/(2n) on their outer neighbours
            ("point", "corner") => self.weights::<W>(n)?.mu.clone() / W::int(n),
            ("point", "outer") => (W::one() - self.weights::<W>(n)?.mu.clone()) / W::int(2 * n),
            // no weight on slots the mask does not use
            _ => W::zero(),
        })
    }
}

impl<W: Weight> Rules<MeshDomain, W> for Pgs {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(Host::AugmentedDual, mesh, origin, self, &W::one())
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
