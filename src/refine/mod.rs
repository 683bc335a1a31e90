//! One refinement step, generic over what is averaged.
//!
//! A topology operator (`topology::`) says which new vertices exist and where
//! each comes from (`Origin`); a scheme's mask (`schemes::`) turns an origin into
//! a stencil `p_new = Σ w_i p_i`; `apply` evaluates stencils on any data that can
//! be combined linearly: 3-D points, 2-D points, sparse weight rows. The same
//! stencils therefore drive mesh refinement and matrix assembly.

pub mod combine;
pub mod mesh;

pub use combine::{Combine, SparseRow};

// Origins and stencils are part of the scheme description (`crate::sdc`);
// re-exported because every consumer of a refinement step uses them.
pub use crate::sdc::{Origin, RuleResult, Stencil};

use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::numeric::{Inexact, Weight};
use crate::sdc::{Scheme, SchemeWeight};
use crate::topology::Refined;

/// Evaluate stencils on data; a new value is `None` when its stencil is missing
/// or touches a missing old value.
pub fn apply<W: Weight, T: Combine<W>>(stencils: &[Option<Stencil<W>>], data: &[Option<T>]) -> Vec<Option<T>> {
    stencils
        .iter()
        .map(|st| {
            let st = st.as_ref()?;
            let mut terms = Vec::with_capacity(st.terms.len());
            for (v, w) in &st.terms {
                terms.push((w.clone(), data.get(*v)?.as_ref()?));
            }
            Some(T::combine(&terms))
        })
        .collect()
}

/// One refinement step of a mesh: the host's refined connectivity and, per
/// new vertex, its stencil over the old vertices (`None` where the rule
/// cannot be evaluated on this mesh, e.g. at the rim of a truncated patch or
/// a pruned net, or where the step was asked for some new vertices only).
/// This is the one place where a host and a scheme's rules meet; discovery,
/// characteristic-map nets, mesh refinement, strip matrices and the claims'
/// mask sums all step through it.
pub struct Step<W> {
    pub refined: Refined,
    pub stencils: Vec<Option<Stencil<W>>>,
}

/// Refine `mesh` once with `rules` (a scheme, or its rules at one level for
/// non-stationary schemes). Fails when the host cannot refine the mesh or a
/// weight is not representable in `W` (irrational weights in exact arithmetic).
pub fn step<W: SchemeWeight>(rules: &dyn Scheme, mesh: &PolyMesh) -> Result<Step<W>, Error> {
    step_selected(rules, mesh, |refined| Ok((0..refined.vertex_origins.len()).collect()))
}

/// [`step`] with stencils for the new vertices that `select` picks from the
/// refined connectivity only (the others are `None`): a window of a large
/// patch needs a few stencils, and an exact weight elsewhere on the patch may
/// be irrational without concerning it. `select` may fail (a position it needs
/// is not on the refined mesh); a vertex selected twice is evaluated once.
pub fn step_selected<W: SchemeWeight>(
    rules: &dyn Scheme,
    mesh: &PolyMesh,
    select: impl FnOnce(&Refined) -> Result<Vec<usize>, Error>,
) -> Result<Step<W>, Error> {
    let refined = connectivity(rules, mesh)?;
    let mut stencils: Vec<Option<Stencil<W>>> = vec![None; refined.vertex_origins.len()];
    let mut done = vec![false; stencils.len()];
    for v in select(&refined)? {
        if std::mem::replace(&mut done[v], true) {
            continue;
        }
        stencils[v] = new_stencil(rules, mesh, &refined, v)
            .map_err(|Inexact| Error::Numeric(format!("{}: a weight is not representable exactly", rules.name())))?;
    }
    Ok(Step { refined, stencils })
}

/// The stencil of new vertex `v` of `refined`, a refinement of `mesh` by
/// `rules`'s host: what a step evaluates per new vertex, for callers that keep
/// the refined connectivity of earlier steps (the assembly of S in another
/// weight type than discovery's) and need a few stencils again.
pub fn new_stencil<W: SchemeWeight>(rules: &dyn Scheme, mesh: &PolyMesh, refined: &Refined, v: usize) -> RuleResult<W> {
    stencil_at(rules, mesh, refined.vertex_origins[v])
}

/// The refined connectivity of one step without any stencil: for callers that
/// evaluate stencils lazily, vertex by vertex ([`stencil_at`]), such as
/// discovery, which needs those of orbit representatives only.
pub fn connectivity(rules: &dyn Scheme, mesh: &PolyMesh) -> Result<Refined, Error> {
    rules.topology().refine(mesh)
}

/// The stencil of the new vertex with the given origin on `mesh`, as a step
/// evaluates it.
pub fn stencil_at<W: SchemeWeight>(rules: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
    W::stencil(rules, mesh, origin)
}
