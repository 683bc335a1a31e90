//! Biermann–Levin–Zorin's edge rule next to a crease or boundary vertex
//! ("Piecewise smooth subdivision surfaces with normal control", SIGGRAPH
//! 2000), as the parameter `blz` of Catmull–Clark and Loop (shared here, one
//! place for both schemes).
//!
//! Why: with Hoppe's rules (the smooth edge rule next to a boundary vertex
//! of k sectors) the interior eigenvalues of the local matrix are those of
//! the sine modes of a closed fan of 2k sectors, which meet the boundary
//! curve's tangent eigenvalue 1/2 at Catmull–Clark k = 4 and Loop k = 6
//! (a Jordan block) and exceed it beyond (the characteristic map collapses
//! the boundary). BLZ change the edge rule on every edge v0–v_j that is not
//! sharp, v0 a crease or boundary vertex with k faces in the sector holding
//! the edge, to
//!
//!   Loop:          (3/4 − γ) v0 + γ v_j + 1/8 (v_{j−1} + v_{j+1})
//!   Catmull–Clark: (3/4 − γ) v0 + γ v_j + 1/16 (v_{j−1} + v_{j+1} + f_{j−1} + f_j)
//!
//! (v_{j±1}, f: the other corners of the edge's two faces), with
//! γ = 1/2 − cos(θ_k)/4 (Loop) and γ = 3/8 − cos(θ_k)/4 (Catmull–Clark),
//! θ_k = π/k at a crease or boundary vertex. These are the γ that put the
//! first sine mode's eigenvalue at 1/2 exactly (Loop: γ + cos(θ_k)/4 = 1/2;
//! Catmull–Clark: the 2 × 2 mode matrix [[γ + cos θ/8, cos(θ/2)/8],
//! [cos(θ/2)/2, 1/4]] has eigenvalue 1/2 iff γ = 3/8 − cos θ/4), and they
//! are Hoppe's (the smooth rule, γ = 3/8) at the regular boundary (Loop
//! k = 3, Catmull–Clark k = 2); `tests/tagged_verdicts.rs` derives and
//! checks both. The formulas were not confirmed against the paper's text
//! here (not available to this project); they were checked by that
//! derivation. BLZ's corner rules (θ_k = α/k, (2π − α)/k at convex and
//! concave corners of angle α) and normal control are not implemented: at a
//! corner the smooth edge rule stays.
//!
//! The parameter blends: `blz = t` gives γ = (1 − t) 3/8 + t γ_BLZ
//! (0, or no parameter: Hoppe's rules; 1: BLZ's).

use crate::numeric::{Inexact, Weight};
use crate::sdc::{ParamSpec, Params};

/// The rule name the primal hosts gather an edge next to a crease vertex
/// under (`topology::primal_split::EDGE_SECTOR_*`).
pub const RULE: &str = "edge-sector";

pub const BLZ: ParamSpec = ParamSpec {
    name: "blz",
    default: "",
    min: 0.0,
    max: 1.0,
    description: "Biermann–Levin–Zorin 2000 edge rule next to crease and boundary vertices of k sectors: \
                  1 takes their γ (θ_k = π/k), 0 or absent Hoppe's rules (the smooth edge rule), \
                  between them γ is blended linearly",
};

/// The share t of BLZ's γ, when the scheme was given a non-zero `blz`.
pub fn share(params: &Params) -> Option<&crate::numeric::ParamValue> {
    params.of(&BLZ).filter(|p| p.value != 0.0)
}

/// γ on the edge's other end, for a crease end with `k` faces in the edge's
/// sector: (1 − t) 3/8 + t γ_BLZ, γ_BLZ = `base` − cos(π/k)/4 (`base` 3/8 for
/// Catmull–Clark, 1/2 for Loop).
pub fn gamma<W: Weight>(params: &Params, base: W, k: usize) -> Result<W, Inexact> {
    let hoppe = W::ratio(3, 8);
    let Some(t) = share(params) else { return Ok(hoppe) };
    let t = W::param(t)?;
    // cos(π/k) = cos(2π/(2k))
    let blz = base - W::cos_2pi(1, 2 * k as i64)? * W::ratio(1, 4);
    Ok(hoppe.clone() + t * (blz - hoppe))
}
