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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::PolyMesh;

    /// A 2 x 1 strip of quads: every open edge becomes sharp, the middle
    /// edge does not; the four outer corners have two sharp edges (a
    /// boundary "crease" unless tagged corner), the middle boundary vertices
    /// too, and a corner tag wins.
    #[test]
    fn open_edges_tag_as_boundary_and_vertices_read_their_kind() {
        // 0 1 2 / 3 4 5
        let mut m = PolyMesh::new(6, vec![vec![0, 1, 4, 3], vec![1, 2, 5, 4]]).unwrap();
        assert_eq!(m.vertex_tag(1), VertexTag::Smooth, "untagged mesh");
        m.tag_open_edges();
        assert!(m.is_sharp(0, 1) && m.is_sharp(1, 0) && m.is_sharp(2, 5));
        assert!(!m.is_sharp(1, 4), "the shared edge is interior");
        assert_eq!(m.tags.as_ref().unwrap().sharp_edges().len(), 6);
        match m.vertex_tag(1) {
            VertexTag::Crease(a, b) => assert_eq!([a.min(b), a.max(b)], [0, 2]),
            t => panic!("{t:?}"),
        }
        m.tags.as_mut().unwrap().mark_corner(0);
        assert_eq!(m.vertex_tag(0), VertexTag::Corner);
        // one more sharp edge at 1 makes it a corner; at an interior vertex, a dart
        m.tags.as_mut().unwrap().mark_sharp(1, 4);
        assert_eq!(m.vertex_tag(1), VertexTag::Corner);
        let t = m.tags.as_ref().unwrap().renumbered(&[1, 4]);
        assert!(t.is_sharp(0, 1) && t.sharp_edges().len() == 1 && t.corners().is_empty());
    }
}
