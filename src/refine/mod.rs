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
pub use crate::sdc::{GatherError, Origin, RuleResult, Stencil};

use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::numeric::{Inexact, Weight};
use crate::sdc::{Scheme, SchemeWeight};
use crate::topology::Refined;

/// Evaluate stencils on data; a new value is `None` when its stencil is missing
/// or touches a missing old value. Takes the stencils as an iterator so that a
/// step's [`StepStencil`]s (`.iter().map(StepStencil::stencil)`) and plain
/// optional stencils (`.iter().map(Option::as_ref)`) are applied alike.
pub fn apply<'s, W: Weight + 's, T: Combine<W>>(
    stencils: impl IntoIterator<Item = Option<&'s Stencil<W>>>,
    data: &[Option<T>],
) -> Vec<Option<T>> {
    stencils
        .into_iter()
        .map(|st| {
            let st = st?;
            let mut terms = Vec::with_capacity(st.terms.len());
            for (v, w) in &st.terms {
                terms.push((w.clone(), data.get(*v)?.as_ref()?));
            }
            Some(T::combine(&terms))
        })
        .collect()
}

/// One refinement step of a mesh: the host's refined connectivity and, per
/// new vertex, its stencil over the old vertices, or why there is none.
/// This is the one place where a host and a scheme's rules meet; discovery,
/// characteristic-map nets, mesh refinement, strip matrices and the claims'
/// mask sums all step through it.
pub struct Step<W> {
    pub refined: Refined,
    pub stencils: Vec<StepStencil<W>>,
}

/// What a step holds for one new vertex.
#[derive(Clone, Debug, PartialEq)]
pub enum StepStencil<W> {
    /// the rule applied: the new vertex's weights on old vertices
    Stencil(Stencil<W>),
    /// the rule does not apply on this mesh, and the gatherer's reason (the
    /// rim of a truncated patch or a pruned net, a face the host's rules do
    /// not cover, an origin the host never creates)
    Missing(GatherError),
    /// the step was asked for other new vertices only ([`step_selected`])
    NotSelected,
}

impl<W> StepStencil<W> {
    /// The stencil, if the rule was evaluated and applied.
    pub fn stencil(&self) -> Option<&Stencil<W>> {
        match self {
            StepStencil::Stencil(s) => Some(s),
            StepStencil::Missing(_) | StepStencil::NotSelected => None,
        }
    }
    /// Why the rule does not apply, if it was evaluated and did not.
    pub fn cause(&self) -> Option<GatherError> {
        match self {
            StepStencil::Missing(cause) => Some(*cause),
            StepStencil::Stencil(_) | StepStencil::NotSelected => None,
        }
    }
}

impl<W> From<Result<Stencil<W>, GatherError>> for StepStencil<W> {
    fn from(rule: Result<Stencil<W>, GatherError>) -> Self {
        match rule {
            Ok(s) => StepStencil::Stencil(s),
            Err(cause) => StepStencil::Missing(cause),
        }
    }
}

/// Refine `mesh` once with `rules` (a scheme, or its rules at one level for
/// non-stationary schemes). Fails when the host cannot refine the mesh or a
/// weight is not representable in `W` (irrational weights in exact arithmetic).
pub fn step<W: SchemeWeight>(rules: &dyn Scheme, mesh: &PolyMesh) -> Result<Step<W>, Error> {
    step_selected(rules, mesh, |refined| Ok((0..refined.vertex_origins.len()).collect()))
}

/// [`step`] with stencils for the new vertices that `select` picks from the
/// refined connectivity only (the others are [`StepStencil::NotSelected`]): a window of a large
/// patch needs a few stencils, and an exact weight elsewhere on the patch may
/// be irrational without concerning it. `select` may fail (a position it needs
/// is not on the refined mesh); a vertex selected twice is evaluated once.
pub fn step_selected<W: SchemeWeight>(
    rules: &dyn Scheme,
    mesh: &PolyMesh,
    select: impl FnOnce(&Refined) -> Result<Vec<usize>, Error>,
) -> Result<Step<W>, Error> {
    let refined = connectivity(rules, mesh)?;
    let stencils = stencils_of(rules, mesh, &refined, select(&refined)?)?;
    Ok(Step { refined, stencils })
}

/// The stencils of the new vertices `vertices` of `refined` (a refinement
/// of `mesh` by `rules`'s host), the others [`StepStencil::NotSelected`]:
/// for callers that decide from the refined connectivity which vertices
/// they keep (a pruned net) before any rule is evaluated. A vertex listed
/// twice is evaluated once.
pub fn stencils_of<W: SchemeWeight>(
    rules: &dyn Scheme,
    mesh: &PolyMesh,
    refined: &Refined,
    vertices: impl IntoIterator<Item = usize>,
) -> Result<Vec<StepStencil<W>>, Error> {
    let mut stencils: Vec<StepStencil<W>> = vec![StepStencil::NotSelected; refined.vertex_origins.len()];
    let mut done = vec![false; stencils.len()];
    for v in vertices {
        if std::mem::replace(&mut done[v], true) {
            continue;
        }
        stencils[v] = new_stencil(rules, mesh, refined, v)
            .map_err(|Inexact| Error::Numeric(format!("{}: a weight is not representable exactly", rules.name())))?
            .into();
    }
    Ok(stencils)
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
