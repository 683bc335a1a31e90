//! Tagged edges and vertices: boundaries, creases, corners and darts.
//!
//! A mesh without tags (`PolyMesh::tags == None`) is what the analysis
//! patches have always been: an open edge is where the patch was cut off,
//! and a rule that reaches over it cannot be evaluated (`Truncated`). A mesh
//! with tags says where the surface really ends or folds: every tagged
//! (sharp) edge is a boundary or crease edge, and the vertex rules read a
//! vertex's kind off the sharp edges around it as OpenSubdiv's `Sdc::Crease`
//! and Hoppe et al. (1994) do — no sharp edge: smooth; one: a dart (the
//! smooth rule applies); two: a crease (or boundary) vertex, whose rule runs
//! along the two sharp edges; three or more, or a corner tag: a corner.
//! An open edge left untagged on a tagged mesh is still a cut (so a local
//! patch around a boundary vertex tags the true boundary and leaves its
//! outer rim open); a real open mesh read from a file tags every open edge
//! ([`PolyMesh::tag_open_edges`]).

use std::collections::BTreeSet;

/// A vertex index (as `mesh::VertexId`; this file imports nothing of the
/// mesh, which holds its tags).
type VertexId = usize;

/// The tags of a mesh: its sharp edges (boundary and crease edges, stored
/// with the smaller vertex first) and its corner vertices.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tags {
    sharp: BTreeSet<(VertexId, VertexId)>,
    corners: BTreeSet<VertexId>,
}

/// What the vertex rules see at a vertex of a tagged mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VertexTag {
    /// no sharp edge
    Smooth,
    /// one sharp edge, ending here: the smooth rule applies
    Dart,
    /// two sharp edges, to these neighbours (a boundary vertex has its two
    /// boundary edges); the first is the one the fan walk leaves along
    Crease(VertexId, VertexId),
    /// a corner tag, or three or more sharp edges
    Corner,
}

fn key(a: VertexId, b: VertexId) -> (VertexId, VertexId) {
    (a.min(b), a.max(b))
}

impl Tags {
    pub fn new() -> Tags {
        Tags::default()
    }
    pub fn mark_sharp(&mut self, a: VertexId, b: VertexId) {
        self.sharp.insert(key(a, b));
    }
    pub fn mark_corner(&mut self, v: VertexId) {
        self.corners.insert(v);
    }
    pub fn is_sharp(&self, a: VertexId, b: VertexId) -> bool {
        self.sharp.contains(&key(a, b))
    }
    pub fn is_corner(&self, v: VertexId) -> bool {
        self.corners.contains(&v)
    }
    /// Sharp edges, each once as (smaller, larger), sorted.
    pub fn sharp_edges(&self) -> Vec<(VertexId, VertexId)> {
        self.sharp.iter().copied().collect()
    }
    /// Corner vertices, sorted.
    pub fn corners(&self) -> Vec<VertexId> {
        self.corners.iter().copied().collect()
    }
    pub fn is_empty(&self) -> bool {
        self.sharp.is_empty() && self.corners.is_empty()
    }
    /// The tags of a sub-mesh whose vertex `new` was vertex `old[new]`:
    /// those whose vertices all survive.
    pub fn renumbered(&self, old: &[VertexId]) -> Tags {
        let mut id = std::collections::HashMap::new();
        for (new, &o) in old.iter().enumerate() {
            id.insert(o, new);
        }
        let mut t = Tags::new();
        for &(a, b) in &self.sharp {
            if let (Some(&x), Some(&y)) = (id.get(&a), id.get(&b)) {
                t.mark_sharp(x, y);
            }
        }
        for c in &self.corners {
            if let Some(&x) = id.get(c) {
                t.mark_corner(x);
            }
        }
        t
    }
}

// tested beside the `PolyMesh` queries that read the tags (`mesh::polymesh`):
// this file imports nothing of the mesh, not even in its tests
