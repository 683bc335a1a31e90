//! The rotation premise of the Fourier-block certificate, PS = SP, decided on
//! the refinement steps that make S instead of on S's composed rows.
//!
//! S is one analysis step (one refinement for binary schemes, two for sqrt(3)
//! schemes) composed from the steps' stencils, restricted to the
//! neighbourhood. Let ρ_k be the rotation of the mesh after k refinements
//! (by the configuration's period, read from the lattice charts: the vertex
//! with coordinates (sector s, x) goes to (s + period, x)), R_k the stencils
//! of refinement k+1 (rows: its new vertices, columns: the vertices before).
//! If, on the vertices the composition reaches (the successors of the
//! neighbourhood and, level by level down, the supports of their stencils;
//! each set closed under its rotation),
//!
//! 1. ρ_0 maps the neighbourhood onto itself as the Fourier orbits say,
//! 2. the successor of ρ_0 v is ρ_K of the successor of v (K refinements),
//! 3. every stencil turns with the mesh: R_k[ρ_{k+1} w, ρ_k u] = R_k[w, u],
//!
//! then the composed rows turn too, S[ρv, ρu] = S[v, u]: composing maps that
//! commute with the rotations gives one that commutes, and restricting to a
//! rotation-invariant set keeps it. Each stencil is a mask of a few weights,
//! and O(1) of them per vertex of the neighbourhood, where the composed rows
//! near a valence-n centre hold O(n) weights each (in a cyclotomic field when
//! the centre's rule holds cos(2π/n), and composed through two refinements
//! for sqrt(3) schemes): the premise costs what assembling S once costs
//! instead of growing with n times the field's degree.
//!
//! Every comparison is exact (rationals; cyclotomic numbers where a rule's
//! weight is irrational); the rotations are combinatorial (chart
//! coordinates). Where anything is out of reach of this route — a rotation
//! the mesh does not show, a weight that is not exact, two stencils that
//! differ — it answers nothing and the certificate checks the composed rows
//! as before: this route can only establish the premise, never refute it
//! (two stencils that differ might still compose to rows that agree).

use super::matrix::MAX_EXACT_ORBIT_WORK;
use crate::dft::Orbits;
use crate::neighbourhood::discovery::Rotation;
use crate::numeric::small::SmallRational;
use crate::numeric::weight::Weight;
use crate::numeric::Cyclotomic;
use crate::sdc::Scheme;
use crate::spectrum::Analysis;
use std::collections::BTreeSet;

/// One stencil of a refinement, exactly: in small rationals when every
/// weight is one, else in a cyclotomic field.
#[derive(PartialEq)]
enum ExactStencil {
    Rational(Vec<(usize, SmallRational)>),
    Cyclotomic(Vec<(usize, Cyclotomic)>),
}

impl ExactStencil {
    fn support(&self) -> Vec<usize> {
        match self {
            ExactStencil::Rational(t) => t.iter().map(|e| e.0).collect(),
            ExactStencil::Cyclotomic(t) => t.iter().map(|e| e.0).collect(),
        }
    }

    /// The same weights on the columns moved by `turn`; `None` when a column
    /// has no image.
    fn turned(&self, turn: &dyn Fn(usize) -> Option<usize>) -> Option<ExactStencil> {
        fn moved<W: Clone>(t: &[(usize, W)], turn: &dyn Fn(usize) -> Option<usize>) -> Option<Vec<(usize, W)>> {
            let mut out: Vec<(usize, W)> =
                t.iter().map(|(c, w)| Some((turn(*c)?, w.clone()))).collect::<Option<_>>()?;
            out.sort_by_key(|e| e.0);
            Some(out)
        }
        Some(match self {
            ExactStencil::Rational(t) => ExactStencil::Rational(moved(t, turn)?),
            ExactStencil::Cyclotomic(t) => ExactStencil::Cyclotomic(moved(t, turn)?),
        })
    }

    /// N of the smallest cyclotomic field holding the weights (1: rational).
    fn field_order(&self) -> u64 {
        match self {
            ExactStencil::Rational(_) => 1,
            ExactStencil::Cyclotomic(t) => t.iter().map(|(_, w)| w.order().unwrap_or(1) as u64).fold(1, lcm),
        }
    }
}

pub(super) fn lcm(a: u64, b: u64) -> u64 {
    a / crate::numeric::weight::gcd(a as i64, b as i64) as u64 * b
}

/// The stencil of vertex `v` of refinement `k` exactly, sorted by column
/// with zero weights dropped; `None` when a weight is neither rational (in
/// machine integers) nor cyclotomic, or the rule cannot be evaluated.
fn exact_stencil(scheme: &dyn Scheme, analysis: &Analysis, k: usize, v: usize) -> Option<ExactStencil> {
    let d = &analysis.discovered;
    let (before, refined) = (d.mesh_before(k), &d.refinements()[k]);
    fn tidy<W: Weight>(terms: Vec<(usize, W)>) -> Vec<(usize, W)> {
        let mut t: Vec<(usize, W)> = terms.into_iter().filter(|e| !e.1.is_zero()).collect();
        t.sort_by_key(|e| e.0);
        t
    }
    match crate::refine::new_stencil::<SmallRational>(scheme, before, refined, v) {
        Ok(Ok(st)) => {
            let st = st.merged();
            // a spoiled weight (beyond machine integers) equals nothing: the
            // composed rows decide such a scheme
            if st.terms.iter().any(|(_, w)| w.is_spoiled()) {
                return None;
            }
            Some(ExactStencil::Rational(tidy(st.terms)))
        }
        Ok(Err(_)) => None,
        Err(_) => {
            let st = crate::refine::new_stencil::<Cyclotomic>(scheme, before, refined, v).ok()?.ok()?.merged();
            st.terms.iter().all(|(_, w)| w.is_defined()).then(|| ExactStencil::Cyclotomic(tidy(st.terms)))
        }
    }
}

/// The premise decided on the refinement steps: `Some(order)` (N of the
/// field the stencils compared lie in) when S commutes with the rotation by
/// conditions 1–3 of the module's comment, all checked exactly; `None` when
/// this route cannot tell (see the module's comment), and the composed rows
/// must decide.
pub fn rotation_by_steps(scheme: &dyn Scheme, analysis: &Analysis, orbits: &Orbits) -> Option<u64> {
    let d = &analysis.discovered;
    let set = d.set(analysis.spectrum.neighbourhood);
    let g = orbits.group_order;
    let period = d.config.rotation_period(scheme);
    let levels = d.refinements().len();
    if g < 2 || levels == 0 || set.len() != orbits.member.len() {
        return None;
    }
    // ρ_k for k = 0..=levels, each of the configuration's order (the
    // identity stands in where a mesh shows no symmetry: then no route)
    let rotations: Vec<Rotation> = (0..=levels)
        .map(|k| {
            let mesh = if k == 0 { &d.patch } else { &d.refinements()[k - 1].mesh };
            Rotation::new(mesh, period, true)
        })
        .collect();
    if rotations.iter().any(|r| r.order() != g) {
        return None;
    }
    // 1. ρ_0 on the neighbourhood is the rotation the Fourier orbits encode
    let mut index = vec![vec![usize::MAX; g]; orbits.num_orbits()];
    for (k, &(o, t)) in orbits.member.iter().enumerate() {
        index[o][t] = k;
    }
    for (k, &v) in set.iter().enumerate() {
        let (o, t) = orbits.member[k];
        let expected = if orbits.fixed[o] { k } else { index[o][(t + 1) % g] };
        if expected == usize::MAX || rotations[0].turned(v)? != set[expected] {
            return None;
        }
    }
    // 2. successors turn with the rotation
    let mut wanted: BTreeSet<usize> = BTreeSet::new();
    for &v in set {
        let (s, turned) = (d.successor(v)?, d.successor(rotations[0].turned(v)?)?);
        if rotations[levels].turned(s)? != turned {
            return None;
        }
        wanted.insert(s);
    }
    // 3. level by level down, every stencil reached turns with the mesh:
    // orbit by orbit, each member's stencil against its predecessor's turned
    // (and the first against the last's), two or three stencils alive at a
    // time, so memory stays bounded however large the orbit
    let mut order = 1;
    for k in (0..levels).rev() {
        let (above, below) = (&rotations[k + 1], &rotations[k]);
        let turn = |u: usize| below.turned(u);
        let mut seen: BTreeSet<usize> = BTreeSet::new();
        let mut next = BTreeSet::new();
        for &w in &wanted {
            if seen.contains(&w) {
                continue;
            }
            // the orbit of w (closing the wanted set under the rotation keeps
            // the argument free of assuming it closed)
            let mut orbit = vec![w];
            let mut u = above.turned(w)?;
            while u != w {
                if orbit.len() == g {
                    return None;
                }
                orbit.push(u);
                u = above.turned(u)?;
            }
            seen.extend(orbit.iter().copied());
            let first = exact_stencil(scheme, analysis, k, orbit[0])?;
            if let ExactStencil::Cyclotomic(terms) = &first {
                // the composed-row route's bound on an orbit's exact work
                let work = (orbit.len() as u64).saturating_mul(terms.len() as u64).saturating_mul(first.field_order());
                if work > MAX_EXACT_ORBIT_WORK {
                    return None;
                }
            }
            order = lcm(order, first.field_order());
            let mut previous_turned = first.turned(&turn)?;
            next.extend(first.support());
            for &member in &orbit[1..] {
                let st = exact_stencil(scheme, analysis, k, member)?;
                if st != previous_turned {
                    return None;
                }
                next.extend(st.support());
                previous_turned = st.turned(&turn)?;
            }
            if previous_turned != first {
                return None;
            }
        }
        wanted = next;
    }
    Some(order)
}
