//! What a rule produces: the origin of a new vertex in the old mesh and its
//! stencil, a weighted sum of old vertices.

use crate::mesh::{FaceId, VertexId};
use crate::numeric::Weight;

/// Where a new vertex (or a new face) comes from in the old mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Origin {
    /// the new vertex that replaces an old vertex (primal schemes)
    Vertex(VertexId),
    /// the new vertex on an old edge; (a, b) is a half-edge of the old mesh
    Edge(VertexId, VertexId),
    /// the new vertex inside an old face
    Face(FaceId),
    /// the new vertex near corner `corner` of old face `face` (dual schemes)
    Corner { face: FaceId, corner: usize },
}

/// Weights on old vertices. Rules may add the same vertex several times;
/// [`Stencil::merged`] (applied to every rule result by
/// `schemes::SchemeWeight::stencil`) sums duplicates and drops zeros.
#[derive(Clone, Debug, PartialEq)]
pub struct Stencil<W> {
    pub terms: Vec<(VertexId, W)>,
}

impl<W: Weight> Default for Stencil<W> {
    fn default() -> Self {
        Stencil { terms: Vec::new() }
    }
}

impl<W: Weight> Stencil<W> {
    pub fn new() -> Self {
        Self::default()
    }
    /// Add `w` to the weight of vertex `v` (duplicates are summed by `merged`).
    pub fn add(&mut self, v: VertexId, w: W) {
        self.terms.push((v, w));
    }
    /// Sum duplicate vertices, drop zero weights, sort by vertex.
    pub fn merged(mut self) -> Self {
        self.terms.sort_by_key(|t| t.0);
        let mut out: Vec<(VertexId, W)> = Vec::with_capacity(self.terms.len());
        for (v, w) in self.terms {
            match out.last_mut() {
                Some(last) if last.0 == v => last.1 = last.1.clone() + w,
                _ => out.push((v, w)),
            }
        }
        out.retain(|t| !t.1.is_zero());
        Stencil { terms: out }
    }
    pub fn with(mut self, v: VertexId, w: W) -> Self {
        self.add(v, w);
        self
    }
    /// Add `scale` times another stencil.
    pub fn add_scaled(&mut self, other: &Stencil<W>, scale: &W) {
        for (v, w) in &other.terms {
            self.add(*v, w.clone() * scale.clone());
        }
    }
    /// Vertices with non-zero weight (call on a merged stencil).
    pub fn support(&self) -> impl Iterator<Item = VertexId> + '_ {
        self.terms.iter().filter(|t| !t.1.is_zero()).map(|t| t.0)
    }
}
