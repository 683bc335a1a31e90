//! A face-list polygon mesh with half-edge lookup.
//!
//! Faces are counter-clockwise vertex cycles. The mesh may have boundary (the
//! analysis neighbourhoods are truncated discs); queries that need a complete
//! one-ring return `None` there, which the refinement marks as "rule not
//! applicable" instead of guessing.

use std::collections::{HashMap, HashSet};
use std::hash::{BuildHasherDefault, Hasher};
use std::sync::OnceLock;

use super::face_list::FaceList;
pub use super::face_list::VertexId;
use super::lattice::Chart;
use super::tags::{Tags, VertexTag};
use crate::error::Error;

pub type FaceId = usize;

/// A multiplicative (Fx-style) hasher for the small integer keys of mesh
/// code: vertex ids, pairs of them, origins, lattice coordinates. std's
/// SipHash guards against adversarial keys, which these are not, at several
/// times the cost, and half-edge and origin look-ups are most of the work of
/// building and refining the O(n)-vertex neighbourhoods of valence n.
#[derive(Clone, Copy, Debug, Default)]
pub struct IdHasher(u64);

const ID_HASH_K: u64 = 0x517c_c1b7_2722_0a95;

impl IdHasher {
    #[inline]
    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(ID_HASH_K);
    }
}

impl Hasher for IdHasher {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.add(u64::from_le_bytes(word));
        }
    }
    #[inline]
    fn write_u8(&mut self, n: u8) {
        self.add(n as u64);
    }
    #[inline]
    fn write_u32(&mut self, n: u32) {
        self.add(n as u64);
    }
    #[inline]
    fn write_u64(&mut self, n: u64) {
        self.add(n);
    }
    #[inline]
    fn write_usize(&mut self, n: usize) {
        self.add(n as u64);
    }
    #[inline]
    fn write_i64(&mut self, n: i64) {
        self.add(n as u64);
    }
    #[inline]
    fn write_isize(&mut self, n: isize) {
        self.add(n as u64);
    }
    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }
}

/// A vertex's fan as (face, corner) pairs counter-clockwise; None when open.
type Fan = Option<Box<[(FaceId, usize)]>>;

pub type IdBuild = BuildHasherDefault<IdHasher>;
/// A `HashMap` with [`IdHasher`] (iteration order is unspecified, as for any
/// `HashMap`; mesh code only looks keys up).
pub type IdMap<K, V> = HashMap<K, V, IdBuild>;
pub type IdSet<K> = HashSet<K, IdBuild>;

/// Where each vertex's corners start in a list of all face corners grouped
/// by vertex (compressed rows): vertex v owns `offsets[v]..offsets[v + 1]`.
/// Indices must be valid.
pub(crate) fn corner_offsets<F: AsRef<[VertexId]>>(
    num_vertices: usize,
    faces: impl IntoIterator<Item = F>,
) -> Vec<usize> {
    let mut offsets = vec![0usize; num_vertices + 1];
    for face in faces {
        for &v in face.as_ref() {
            offsets[v + 1] += 1;
        }
    }
    for v in 0..num_vertices {
        offsets[v + 1] += offsets[v];
    }
    offsets
}

/// The half-edges of a mesh, grouped by start vertex (compressed rows):
/// the half-edges leaving vertex a are `out[start[a]..start[a + 1]]`, sorted
/// by end vertex. Built with two linear passes and a sort of each (short)
/// group, and read with a scan or a binary search, this is several times
/// cheaper than a hash map keyed by vertex pairs, and building the meshes of
/// each refinement level is a large part of analysing a high valence.
///
/// Ids are stored as `u32` (12 bytes a half-edge instead of 24): the rows of
/// every refined mesh are written once and mostly read a little, so their
/// size (fresh memory touched, page faults) is much of what they cost. A
/// mesh has far fewer than 2³² vertices and faces (refinement stops at
/// `refine::mesh::MAX_REFINED_FACES`); more is refused with a panic rather
/// than truncated.
#[derive(Clone, Debug, Default)]
struct HalfEdges {
    start: Vec<u32>,
    /// (end vertex b, face, index of a in that face)
    out: Vec<(u32, u32, u32)>,
}

/// Each corner's successor in the face cycle, in corner order (the last
/// corner's is the first): a face's sides without an integer division per
/// corner, in the loops that every new mesh runs over all its corners.
fn cyclic_next(face: &[VertexId]) -> impl Iterator<Item = &VertexId> {
    face.iter().skip(1).chain(face.first())
}

/// `x` as a stored id (see [`HalfEdges`]).
fn small(x: usize) -> u32 {
    u32::try_from(x).expect("a mesh has fewer than 2^32 vertices, faces and corners")
}

impl HalfEdges {
    /// Every corner of the first `count` faces as a half-edge (their
    /// indices must be valid).
    fn new(num_vertices: usize, faces: &FaceList, count: usize) -> HalfEdges {
        // start[a + 1] counts a's corners, then holds where a's row starts,
        // then (advanced while filling) where it ends, which is where a + 1's
        // starts: one array, no cursor copy
        let mut start = vec![0u32; num_vertices + 1];
        for face in faces.iter().take(count) {
            for &a in face {
                start[a + 1] += 1;
            }
        }
        let mut total = 0u32;
        for count in &mut start[1..] {
            let c = *count;
            *count = total;
            total = total.checked_add(c).expect("a mesh has fewer than 2^32 corners");
        }
        let mut out = vec![(0, 0, 0); total as usize];
        for (fi, face) in faces.iter().take(count).enumerate() {
            let f = small(fi);
            for (k, (&a, &b)) in face.iter().zip(cyclic_next(face)).enumerate() {
                let at = &mut start[a + 1];
                out[*at as usize] = (small(b), f, k as u32);
                *at += 1;
            }
        }
        // each row was filled in face order, so a stable sort by end vertex
        // orders it by (end vertex, face, corner) comparing one key
        for v in 0..num_vertices {
            out[start[v] as usize..start[v + 1] as usize].sort_by_key(|e| e.0);
        }
        HalfEdges { start, out }
    }

    /// The half-edges leaving `a` (empty for an unknown vertex).
    fn row(&self, a: VertexId) -> &[(u32, u32, u32)] {
        match (self.start.get(a), self.start.get(a + 1)) {
            (Some(&s), Some(&e)) => &self.out[s as usize..e as usize],
            _ => &[],
        }
    }

    /// A half-edge that two faces (or one face twice) use in the same
    /// direction: the one whose second use comes first in face order.
    fn first_repeated(&self) -> Option<MeshError> {
        let mut first: Option<(u32, u32, VertexId, u32)> = None;
        for a in 0..self.start.len() - 1 {
            for pair in self.row(a).windows(2) {
                // sorted by (b, face, corner): the later use is the second
                if pair[0].0 == pair[1].0 {
                    let (b, f, k) = pair[1];
                    if first.is_none_or(|(f0, k0, ..)| (f, k) < (f0, k0)) {
                        first = Some((f, k, a, b));
                    }
                }
            }
        }
        first.map(|(_, _, a, b)| MeshError::NonManifoldEdge { a, b: b as usize })
    }

    fn get(&self, a: VertexId, b: VertexId) -> Option<(FaceId, usize)> {
        let group = self.row(a);
        let b = u32::try_from(b).ok()?;
        let found = if group.len() <= 16 {
            group.iter().find(|e| e.0 == b)
        } else {
            group.binary_search_by_key(&b, |e| e.0).ok().map(|i| &group[i])
        };
        found.map(|&(_, f, k)| (f as usize, k as usize))
    }

    /// The first corner of `a` in face order (face, index of a in it), where
    /// its fan walk starts; `None` for a vertex of no face.
    fn first_corner(&self, a: VertexId) -> Option<(FaceId, usize)> {
        self.row(a).iter().map(|&(_, f, k)| (f, k)).min().map(|(f, k)| (f as usize, k as usize))
    }
}

/// The undirected edges of a mesh in [`PolyMesh::edges`] order, and for
/// every face side the number of its edge in that list: a split gives each
/// edge its new vertices in edge order and finds them again from the faces
/// on both sides by index, where a hash map keyed by vertex pairs cost a
/// large part of refining the big meshes of discovery and the nets.
#[derive(Clone, Debug)]
pub struct EdgeNumbering {
    /// the edges, each once, as [`PolyMesh::edges`] lists them
    pub edges: Vec<(VertexId, VertexId)>,
    /// where the sides of face f start in `side_edge` (compressed rows)
    face_start: Vec<usize>,
    /// per face side (side k of face f runs from corner k to corner k + 1)
    /// the number of its edge
    side_edge: Vec<usize>,
}

impl EdgeNumbering {
    /// The number of the edge on side k of face f (from its corner k to
    /// corner k + 1; k below the face's size).
    pub fn side(&self, f: FaceId, k: usize) -> usize {
        debug_assert!(self.face_start[f] + k < self.face_start[f + 1]);
        self.side_edge[self.face_start[f] + k]
    }

    /// The number of the edge on side k of face f, and whether the edge
    /// list has it starting at `from` (one end of that side): for splits
    /// that make new vertices per edge direction.
    pub fn side_from(&self, f: FaceId, k: usize, from: VertexId) -> (usize, bool) {
        let e = self.side(f, k);
        (e, self.edges[e].0 == from)
    }
}

#[derive(Clone, Debug)]
pub struct PolyMesh {
    faces: FaceList,
    num_vertices: usize,
    /// half-edge (a -> b) -> (face, index of a in that face); also each
    /// vertex's first corner in face order, where walks around it start
    half_edges: HalfEdges,
    /// The fan of each vertex as (face, corner) pairs, walked on first use
    /// (None inside: an open fan): rules ask for the fan of a high-valence
    /// centre once per face or edge around it, and rebuilding it by half-edge
    /// walks each time made discovery quadratic in the valence. The table
    /// itself is made at the first query: many meshes (the last level of a
    /// search or of a net) are never asked, and filling a slot per vertex
    /// was a large part of building them.
    fans: OnceLock<Box<[OnceLock<Fan>]>>,
    /// The faces at each vertex in face order, built on first use (the tag
    /// queries of a tagged mesh ask at every vertex and edge point).
    incident: OnceLock<Box<[Box<[FaceId]>]>>,
    /// `face_points` holds a point for every face (cached: FCV rules ask on
    /// every stencil, and scanning all faces each time was quadratic).
    every_face_has_point: bool,
    /// Optional lattice chart (sector coordinates) used to label the vertices of
    /// analysis neighbourhoods; absent for user meshes.
    pub chart: Option<Chart>,
    /// Control points that belong to a face rather than to its boundary
    /// cycle: `face_points[f]` is the point of face f, if it carries one, and
    /// the list is empty when no face does. Non-box subdivision puts a face
    /// control vertex (FCV) on every face; point-augmented schemes (the point p
    /// of PGS) on some faces only. Such points are vertices of no face cycle.
    pub face_points: Vec<Option<VertexId>>,
    /// A per-vertex scheme parameter, for schemes whose weights vary per vertex
    /// (Lin–Luo's α in unified sqrt(3) subdivision). Refined with the scheme's
    /// `vertex_param_rule`.
    pub vertex_params: Option<Vec<f64>>,
    /// For schemes on the regular lattice with asymmetric masks (Khan–Mustafa):
    /// per quad, the lattice direction of its first edge (corner 0 → 1) as
    /// 0 = +i, 1 = +j, 2 = −i, 3 = −j; edge k then has direction (d + k) mod 4.
    pub lattice_dirs: Option<Vec<u8>>,
    /// Boundary, crease and corner tags (`mesh::tags`); `None`: an open edge
    /// is where a patch was cut off, not a boundary.
    pub tags: Option<Tags>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub enum MeshError {
    BadIndex { face: usize, index: usize },
    DegenerateFace { face: usize },
    NonManifoldEdge { a: usize, b: usize },
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MeshError::BadIndex { face, index } => {
                write!(f, "face {face} refers to vertex {index}, which does not exist")
            }
            MeshError::DegenerateFace { face } => {
                write!(f, "face {face} has fewer than 3 distinct vertices")
            }
            MeshError::NonManifoldEdge { a, b } => write!(
                f,
                "edge {a}->{b} is used twice in the same direction (non-manifold or inconsistently oriented mesh)"
            ),
        }
    }
}

impl std::error::Error for MeshError {}

/// A malformed mesh comes from its file (OBJ): a file error.
impl From<MeshError> for crate::error::Error {
    fn from(e: MeshError) -> Self {
        crate::error::Error::File(e.to_string())
    }
}

impl PolyMesh {
    pub fn new(num_vertices: usize, faces: impl Into<FaceList>) -> Result<Self, MeshError> {
        let faces = faces.into();
        // face cycles are checked in face order; a repeated half-edge is
        // reported only if it comes before the first bad face, so the error
        // is the first defect in face order
        let bad = faces.iter().enumerate().find_map(|(fi, face)| {
            if face.len() < 3 {
                return Some(MeshError::DegenerateFace { face: fi });
            }
            face.iter().zip(cyclic_next(face)).find_map(|(&a, &b)| {
                if a >= num_vertices {
                    Some(MeshError::BadIndex { face: fi, index: a })
                } else if a == b {
                    Some(MeshError::DegenerateFace { face: fi })
                } else {
                    None
                }
            })
        });
        let good = match &bad {
            Some(MeshError::DegenerateFace { face } | MeshError::BadIndex { face, .. }) => *face,
            _ => faces.len(),
        };
        let half_edges = HalfEdges::new(num_vertices, &faces, good);
        if let Some(e) = half_edges.first_repeated().or(bad) {
            return Err(e);
        }
        Ok(PolyMesh {
            faces,
            num_vertices,
            half_edges,
            fans: OnceLock::new(),
            incident: OnceLock::new(),
            every_face_has_point: false,
            chart: None,
            face_points: Vec::new(),
            vertex_params: None,
            lattice_dirs: None,
            tags: None,
        })
    }

    /// Attach face points (`points[f]`: the point of face f, if any; each a
    /// vertex of no face cycle).
    pub fn with_face_points(mut self, points: Vec<Option<VertexId>>) -> Result<Self, Error> {
        if points.len() != self.faces.len() {
            return Err(Error::Input(format!("{} face point entries for {} faces", points.len(), self.faces.len())));
        }
        if let Some(&v) =
            points.iter().flatten().find(|&&v| v >= self.num_vertices || self.half_edges.first_corner(v).is_some())
        {
            return Err(Error::Input(format!("face point {v} is missing or is a corner of a face")));
        }
        self.every_face_has_point = !points.is_empty() && points.iter().all(Option::is_some);
        self.face_points = points;
        Ok(self)
    }

    /// Whether every face carries a face point (as face control vertex schemes need).
    pub fn has_face_point_on_every_face(&self) -> bool {
        // the length check keeps the answer right if `face_points` was replaced
        // wholesale after `with_face_points`
        !self.faces.is_empty() && self.face_points.len() == self.faces.len() && self.every_face_has_point
    }

    /// Orient a closed regular quad mesh as a lattice: the first edge of face 0
    /// is +i, and directions carry across edges (a shared edge has opposite
    /// directions in its two faces). Fails unless every face is a quad, every
    /// vertex has valence 4 and the orientation is consistent (e.g. a torus grid).
    pub fn orient_lattice(&mut self) -> Result<(), Error> {
        if let Some(f) = self.faces.iter().position(|f| f.len() != 4) {
            return Err(Error::Input(format!(
                "a regular-lattice scheme needs quads only; face {} has {} vertices",
                f + 1,
                self.faces[f].len()
            )));
        }
        for v in 0..self.num_vertices {
            match self.valence(v) {
                Some(4) => {}
                Some(k) => {
                    return Err(Error::Input(format!(
                        "a regular-lattice scheme needs valence 4 everywhere; vertex {} has {k}",
                        v + 1
                    )))
                }
                None => {
                    if self.half_edges.first_corner(v).is_some() {
                        return Err(Error::Input(format!(
                            "a regular-lattice scheme needs a closed mesh; vertex {} is on the boundary",
                            v + 1
                        )));
                    }
                }
            }
        }
        let mut dirs: Vec<Option<u8>> = vec![None; self.faces.len()];
        for start in 0..self.faces.len() {
            if dirs[start].is_some() {
                continue;
            }
            dirs[start] = Some(0);
            let mut stack = vec![start];
            while let Some(f) = stack.pop() {
                let d = dirs[f].expect("set before pushing");
                for k in 0..4 {
                    let (a, b) = (self.faces[f][k], self.faces[f][(k + 1) % 4]);
                    let Some((g, kg)) = self.half_edge(b, a) else { continue };
                    let label = (d as usize + k) % 4;
                    // the same edge, walked the other way, has the opposite direction
                    let dg = ((label + 2 + 4 - kg % 4) % 4) as u8;
                    match dirs[g] {
                        None => {
                            dirs[g] = Some(dg);
                            stack.push(g);
                        }
                        Some(x) if x != dg => {
                            return Err(Error::Input(format!(
                                "the quad mesh has no consistent lattice orientation (faces {} and {} disagree)",
                                f + 1,
                                g + 1
                            )))
                        }
                        Some(_) => {}
                    }
                }
            }
        }
        self.lattice_dirs = Some(dirs.into_iter().map(|d| d.expect("every face reached")).collect());
        Ok(())
    }

    /// The sub-mesh of the faces `keep`, with every per-vertex and per-face
    /// attribute carried along (charts, face points, lattice directions,
    /// per-vertex parameters). Returns it and, for each new vertex, its old id.
    pub fn restrict(&self, keep: &[FaceId]) -> Result<(PolyMesh, Vec<VertexId>), Error> {
        let mut id = vec![usize::MAX; self.num_vertices];
        let mut old = Vec::new();
        let mut take = |v: usize| {
            if id[v] == usize::MAX {
                id[v] = old.len();
                old.push(v);
            }
            id[v]
        };
        let mut faces = self.faces_sized_for(keep);
        for &f in keep {
            faces.push_iter(self.faces[f].iter().map(|&v| take(v)));
        }
        let points: Vec<Option<usize>> = if self.face_points.is_empty() {
            Vec::new()
        } else {
            keep.iter().map(|&f| self.face_points[f].map(&mut take)).collect()
        };
        let mut m = PolyMesh::new(old.len(), faces).map_err(|e| Error::Input(e.to_string()))?;
        if !points.is_empty() {
            m = m.with_face_points(points)?;
        }
        m.lattice_dirs = self.lattice_dirs.as_ref().map(|d| keep.iter().map(|&f| d[f]).collect());
        m.vertex_params = self.vertex_params.as_ref().map(|p| old.iter().map(|&v| p[v]).collect());
        m.tags = self.tags.as_ref().map(|t| t.renumbered(&old));
        m.chart = self.chart.as_ref().map(|c| Chart {
            sector_kinds: c.sector_kinds.clone(),
            scale: c.scale,
            vertex_coords: old.iter().map(|&v| c.vertex_coords[v]).collect(),
            face_sector: keep.iter().map(|&f| c.face_sector[f]).collect(),
        });
        Ok((m, old))
    }

    /// The mesh of the faces `keep` only, every vertex keeping its id: a
    /// vertex of no kept face stays, isolated (no fan, so no rule can be
    /// evaluated at it). Unlike [`PolyMesh::restrict`] nothing is renumbered,
    /// so ids, chart coordinates and per-vertex data mean what they meant.
    pub fn keep_faces(&self, keep: &[FaceId]) -> Result<PolyMesh, Error> {
        let mut faces = self.faces_sized_for(keep);
        keep.iter().for_each(|&f| faces.push(&self.faces[f]));
        let mut m = PolyMesh::new(self.num_vertices, faces).map_err(|e| Error::Input(e.to_string()))?;
        if !self.face_points.is_empty() {
            m = m.with_face_points(keep.iter().map(|&f| self.face_points[f]).collect())?;
        }
        m.lattice_dirs = self.lattice_dirs.as_ref().map(|d| keep.iter().map(|&f| d[f]).collect());
        m.vertex_params = self.vertex_params.clone();
        m.tags = self.tags.clone();
        m.chart = self.chart.as_ref().map(|c| Chart {
            sector_kinds: c.sector_kinds.clone(),
            scale: c.scale,
            vertex_coords: c.vertex_coords.clone(),
            face_sector: keep.iter().map(|&f| c.face_sector[f]).collect(),
        });
        Ok(m)
    }

    /// An empty face list with room for the faces `keep`.
    fn faces_sized_for(&self, keep: &[FaceId]) -> FaceList {
        FaceList::with_capacity(keep.len(), keep.iter().map(|&f| self.faces[f].len()).sum())
    }

    /// The face control vertex of face f, if the mesh carries them.
    pub fn face_point(&self, f: FaceId) -> Option<VertexId> {
        self.face_points.get(f).copied().flatten()
    }

    /// The face point of the face that holds the half-edge a -> b (the face on
    /// its left, faces being counter-clockwise).
    pub fn face_point_left_of(&self, a: VertexId, b: VertexId) -> Option<VertexId> {
        self.face_point(self.half_edge(a, b)?.0)
    }

    pub fn num_vertices(&self) -> usize {
        self.num_vertices
    }
    pub fn num_faces(&self) -> usize {
        self.faces.len()
    }
    pub fn faces(&self) -> &FaceList {
        &self.faces
    }
    pub fn face(&self, f: FaceId) -> &[VertexId] {
        &self.faces[f]
    }

    /// The face that contains the half-edge a -> b, with the index of a in it.
    pub fn half_edge(&self, a: VertexId, b: VertexId) -> Option<(FaceId, usize)> {
        self.half_edges.get(a, b)
    }

    /// Face `f` rotated so that it starts at its corner `k`.
    pub fn face_from(&self, f: FaceId, k: usize) -> Vec<VertexId> {
        let face = &self.faces[f];
        face[k..].iter().chain(&face[..k]).copied().collect()
    }

    /// Undirected edges, each once, as (a, b) with the half-edge a->b present.
    pub fn edges(&self) -> Vec<(VertexId, VertexId)> {
        let mut out = Vec::new();
        for face in &self.faces {
            for (&a, &b) in face.iter().zip(cyclic_next(face)) {
                if self.lists_edge(a, b) {
                    out.push((a, b));
                }
            }
        }
        out
    }

    /// Whether [`Self::edges`] lists the edge {a, b} as the half-edge
    /// a -> b (a face holds a -> b): when its twin is missing or a < b.
    fn lists_edge(&self, a: VertexId, b: VertexId) -> bool {
        a < b || self.half_edges.get(b, a).is_none()
    }

    /// [`Self::edges`] with, for every face side, the number of its edge
    /// in that list (see [`EdgeNumbering`]).
    pub fn edge_numbering(&self) -> EdgeNumbering {
        let mut face_start = Vec::with_capacity(self.faces.len() + 1);
        let mut sides = 0;
        for face in &self.faces {
            face_start.push(sides);
            sides += face.len();
        }
        face_start.push(sides);
        // the sides that list their edge are numbered in face order, as
        // `edges` lists them; every other side is the twin of one of those
        let mut side_edge = vec![usize::MAX; sides];
        let mut edges = Vec::new();
        for (f, face) in self.faces.iter().enumerate() {
            for (k, (&a, &b)) in face.iter().zip(cyclic_next(face)).enumerate() {
                if self.lists_edge(a, b) {
                    side_edge[face_start[f] + k] = edges.len();
                    edges.push((a, b));
                }
            }
        }
        for (f, face) in self.faces.iter().enumerate() {
            for (k, (&a, &b)) in face.iter().zip(cyclic_next(face)).enumerate() {
                if side_edge[face_start[f] + k] == usize::MAX {
                    let (g, kg) = self.half_edges.get(b, a).expect("a side that does not list its edge has a twin");
                    side_edge[face_start[f] + k] = side_edge[face_start[g] + kg];
                }
            }
        }
        EdgeNumbering { edges, face_start, side_edge }
    }

    /// True when the edge {a, b} has a face on both sides.
    pub fn is_interior_edge(&self, a: VertexId, b: VertexId) -> bool {
        self.half_edges.get(a, b).is_some() && self.half_edges.get(b, a).is_some()
    }

    /// The faces around vertex `v` in counter-clockwise order, each given as the
    /// face's vertex cycle starting at `v`. `None` when `v` is on the boundary
    /// (its fan is open) or isolated.
    pub fn vertex_fan(&self, v: VertexId) -> Option<Vec<Vec<VertexId>>> {
        Some(self.fan_corners(v)?.iter().map(|&(f, k)| self.face_from(f, k)).collect())
    }

    /// The fan of `v` as (face, index of v in it), counter-clockwise from the
    /// corner the walk starts at; `None` on the boundary. Cached for all
    /// vertices at the first call.
    pub fn fan_corners(&self, v: VertexId) -> Option<&[(FaceId, usize)]> {
        let fans = self.fans.get_or_init(|| (0..self.num_vertices).map(|_| OnceLock::new()).collect());
        fans.get(v)?.get_or_init(|| self.walk_fan(v)).as_deref()
    }

    /// The neighbours of `v` in fan order (the second corner of each fan face)
    /// when every face around it has `size` corners; `None` on the boundary or
    /// next to a face of another size.
    pub fn uniform_ring(&self, v: VertexId, size: usize) -> Option<Vec<VertexId>> {
        let fan = self.fan_corners(v)?;
        fan.iter()
            .map(|&(f, k)| {
                let face = &self.faces[f];
                (face.len() == size).then(|| face[(k + 1) % face.len()])
            })
            .collect()
    }

    fn walk_fan(&self, v: VertexId) -> Fan {
        let (f0, k0) = self.half_edges.first_corner(v)?;
        let mut fan = Vec::new();
        let (mut f, mut k) = (f0, k0);
        loop {
            fan.push((f, k));
            let face = &self.faces[f];
            // the previous vertex of this face around v; the next face CCW holds v -> prev
            let prev = face[(k + face.len() - 1) % face.len()];
            let (g, kg) = self.half_edge(v, prev)?;
            if g == f0 {
                return Some(fan.into_boxed_slice());
            }
            if fan.len() > self.faces.len() {
                return None; // corrupt connectivity: never loop forever
            }
            f = g;
            k = kg;
        }
    }

    /// Valence of an interior vertex (number of faces around it).
    pub fn valence(&self, v: VertexId) -> Option<usize> {
        self.fan_corners(v).map(<[_]>::len)
    }

    /// The faces that have `v` as a corner (works on the boundary too).
    pub fn faces_around(&self, v: VertexId) -> Vec<FaceId> {
        self.faces.iter().enumerate().filter(|(_, f)| f.contains(&v)).map(|(i, _)| i).collect()
    }

    /// The faces that have `v` as a corner, in face order ([`Self::faces_around`]
    /// from a cache built for all vertices at the first call).
    pub fn incident_faces(&self, v: VertexId) -> &[FaceId] {
        let all = self.incident.get_or_init(|| {
            // sized to the corners (as `vertex_faces`): no growing, and the
            // boxed slices below reuse the allocations
            let offsets = corner_offsets(self.num_vertices, &self.faces);
            let mut out: Vec<Vec<FaceId>> = offsets.windows(2).map(|w| Vec::with_capacity(w[1] - w[0])).collect();
            for (fi, face) in self.faces.iter().enumerate() {
                for &c in face {
                    if out[c].last() != Some(&fi) {
                        out[c].push(fi);
                    }
                }
            }
            out.into_iter().map(Vec::into_boxed_slice).collect()
        });
        all.get(v).map_or(&[], |f| f)
    }

    /// For every vertex, the list of faces incident to it.
    pub fn vertex_faces(&self) -> Vec<Vec<FaceId>> {
        // each list sized to its corners first: growing them one face at a
        // time was most of the cost on the nets' large meshes
        let offsets = corner_offsets(self.num_vertices, &self.faces);
        let mut out: Vec<Vec<FaceId>> = offsets.windows(2).map(|w| Vec::with_capacity(w[1] - w[0])).collect();
        for (fi, face) in self.faces.iter().enumerate() {
            for &v in face {
                out[v].push(fi);
            }
        }
        out
    }
}

impl PolyMesh {
    // Tags (`mesh::tags`): boundaries, creases, corners.

    /// Tag every open edge sharp (a real open mesh: its open edges are its
    /// boundary), keeping tags already there.
    pub fn tag_open_edges(&mut self) {
        let open: Vec<(VertexId, VertexId)> =
            self.edges().into_iter().filter(|&(a, b)| !self.is_interior_edge(a, b)).collect();
        let tags = self.tags.get_or_insert_with(Tags::new);
        for (a, b) in open {
            tags.mark_sharp(a, b);
        }
    }

    /// Whether the edge {a, b} is tagged sharp (never on an untagged mesh).
    pub fn is_sharp(&self, a: VertexId, b: VertexId) -> bool {
        self.tags.as_ref().is_some_and(|t| t.is_sharp(a, b))
    }

    /// The neighbours of `v` across sharp edges, in the order the faces
    /// around v first meet them (each once).
    pub fn sharp_neighbours(&self, v: VertexId) -> Vec<VertexId> {
        let Some(tags) = self.tags.as_ref() else { return Vec::new() };
        let mut out = Vec::new();
        for &f in self.incident_faces(v) {
            let face = &self.faces[f];
            if let Some(k) = face.iter().position(|&c| c == v) {
                let m = face.len();
                for w in [face[(k + 1) % m], face[(k + m - 1) % m]] {
                    if tags.is_sharp(v, w) && !out.contains(&w) {
                        out.push(w);
                    }
                }
            }
        }
        out
    }

    /// The kind of vertex `v` for the vertex rules (`Smooth` on an untagged mesh).
    pub fn vertex_tag(&self, v: VertexId) -> VertexTag {
        let Some(tags) = self.tags.as_ref() else { return VertexTag::Smooth };
        if tags.is_corner(v) {
            return VertexTag::Corner;
        }
        match self.sharp_neighbours(v)[..] {
            [] => VertexTag::Smooth,
            [_] => VertexTag::Dart,
            [a, b] => VertexTag::Crease(a, b),
            _ => VertexTag::Corner,
        }
    }
}

#[cfg(test)]
mod tag_tests {
    use super::*;

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

#[cfg(test)]
mod edge_tests {
    use super::*;

    /// Meshes with boundaries, mixed face sizes and a closed one: a 3 x 2
    /// grid of quads with its first quad split into two triangles, and the
    /// cube.
    fn meshes() -> Vec<PolyMesh> {
        // grid vertex (i, j) is 4 j + i, i in 0..4, j in 0..3
        let at = |i: usize, j: usize| 4 * j + i;
        let mut grid = vec![vec![at(0, 0), at(1, 0), at(1, 1)], vec![at(0, 0), at(1, 1), at(0, 1)]];
        for j in 0..2 {
            for i in 0..3 {
                if (i, j) != (0, 0) {
                    grid.push(vec![at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
        }
        let cube = vec![
            vec![0, 3, 2, 1],
            vec![4, 5, 6, 7],
            vec![0, 1, 5, 4],
            vec![1, 2, 6, 5],
            vec![2, 3, 7, 6],
            vec![3, 0, 4, 7],
        ];
        vec![PolyMesh::new(12, grid).unwrap(), PolyMesh::new(8, cube).unwrap()]
    }

    /// The numbering lists the edges `edges` lists, and every face side's
    /// number names the edge between its two corners (either way round);
    /// the two sides of an interior edge share the number.
    #[test]
    fn every_side_finds_its_edge_by_number() {
        for m in meshes() {
            let numbering = m.edge_numbering();
            assert_eq!(numbering.edges, m.edges());
            let mut sides_per_edge = vec![0; numbering.edges.len()];
            for (f, face) in m.faces().iter().enumerate() {
                for k in 0..face.len() {
                    let (a, b) = (face[k], face[(k + 1) % face.len()]);
                    let e = numbering.side(f, k);
                    assert!(numbering.edges[e] == (a, b) || numbering.edges[e] == (b, a), "face {f} side {k}");
                    assert_eq!(numbering.side_from(f, k, a), (e, numbering.edges[e].0 == a));
                    assert_eq!(numbering.side_from(f, k, b).1, numbering.edges[e].0 == b);
                    sides_per_edge[e] += 1;
                }
            }
            for (e, &(a, b)) in numbering.edges.iter().enumerate() {
                let expected = if m.is_interior_edge(a, b) { 2 } else { 1 };
                assert_eq!(sides_per_edge[e], expected, "edge {a}-{b}");
            }
        }
    }

    /// Random grids of quads, some split into triangles, with vertex ids
    /// permuted and faces shuffled (a fixed linear congruential sequence):
    /// the mesh keeps the faces given, finds every side's half-edge at its
    /// face and corner, and each vertex's fan is its corners exactly once,
    /// starting at its first corner, each face holding the side from v to
    /// the previous face's corner before v (None on the grid's border), as
    /// read off the face vectors directly; `restrict` and `keep_faces` keep
    /// the faces asked for.
    #[test]
    fn random_meshes_keep_their_faces_half_edges_and_fans() {
        let mut state = 99u64;
        let mut next = |m: usize| {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((state >> 33) % m as u64) as usize
        };
        for _ in 0..10 {
            let (w, h) = (2 + next(5), 2 + next(5));
            let nv = (w + 1) * (h + 1);
            let mut perm: Vec<usize> = (0..nv).collect();
            for i in (1..nv).rev() {
                perm.swap(i, next(i + 1));
            }
            let at = |i: usize, j: usize| perm[j * (w + 1) + i];
            let mut faces = Vec::new();
            for j in 0..h {
                for i in 0..w {
                    let q = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
                    match next(3) {
                        0 => faces.push(q.to_vec()),
                        d => {
                            let k = d - 1; // split along the diagonal from corner k
                            faces.push(vec![q[k], q[k + 1], q[k + 2]]);
                            faces.push(vec![q[k + 2], q[(k + 3) % 4], q[k]]);
                        }
                    }
                }
            }
            for i in (1..faces.len()).rev() {
                faces.swap(i, next(i + 1));
            }
            let m = PolyMesh::new(nv, faces.clone()).unwrap();
            assert_eq!(m.faces().to_vec(), faces);
            assert_eq!(m.num_faces(), faces.len());
            for (f, face) in faces.iter().enumerate() {
                assert_eq!(m.face(f), face.as_slice());
                for k in 0..face.len() {
                    assert_eq!(m.half_edge(face[k], face[(k + 1) % face.len()]), Some((f, k)));
                    assert_eq!(m.face_from(f, k), [&face[k..], &face[..k]].concat());
                }
            }
            let border = |v: usize| {
                (0..=w).any(|i| v == at(i, 0) || v == at(i, h)) || (0..=h).any(|j| v == at(0, j) || v == at(w, j))
            };
            for v in 0..nv {
                let corners: Vec<(usize, usize)> = faces
                    .iter()
                    .enumerate()
                    .flat_map(|(f, face)| {
                        face.iter().enumerate().filter(move |&(_, &c)| c == v).map(move |(k, _)| (f, k))
                    })
                    .collect();
                match m.fan_corners(v) {
                    None => assert!(border(v), "vertex {v}"),
                    Some(fan) => {
                        assert!(!border(v), "vertex {v}");
                        assert_eq!(fan[0], corners[0]);
                        let mut sorted = fan.to_vec();
                        sorted.sort_unstable();
                        assert_eq!(sorted, corners, "vertex {v}: its corners once each");
                        for (i, &(f, k)) in fan.iter().enumerate() {
                            let face = &faces[f];
                            let prev = face[(k + face.len() - 1) % face.len()];
                            let (g, kg) = fan[(i + 1) % fan.len()];
                            assert_eq!(faces[g][(kg + 1) % faces[g].len()], prev, "vertex {v}: fan order");
                        }
                        assert_eq!(m.valence(v), Some(fan.len()));
                    }
                }
                let around: Vec<usize> = corners.iter().map(|c| c.0).collect();
                assert_eq!(m.incident_faces(v), around.as_slice());
            }
            let keep: Vec<usize> = (0..faces.len()).filter(|_| next(2) == 0).collect();
            let kept = m.keep_faces(&keep).unwrap();
            assert_eq!(kept.faces().to_vec(), keep.iter().map(|&f| faces[f].clone()).collect::<Vec<_>>());
            let (restricted, old) = m.restrict(&keep).unwrap();
            let back: Vec<Vec<usize>> =
                restricted.faces().iter().map(|f| f.iter().map(|&v| old[v]).collect()).collect();
            assert_eq!(back, kept.faces().to_vec());
        }
    }

    /// A fan starts at the vertex's first corner in face order, and every
    /// half-edge is found in the face that holds it, at the right corner.
    #[test]
    fn fans_start_at_the_first_corner_and_half_edges_are_found() {
        for m in meshes() {
            for v in 0..m.num_vertices() {
                let first =
                    m.faces().iter().enumerate().find_map(|(f, face)| Some((f, face.iter().position(|&c| c == v)?)));
                if let Some(fan) = m.fan_corners(v) {
                    assert_eq!(Some(fan[0]), first, "vertex {v}");
                }
            }
            for (f, face) in m.faces().iter().enumerate() {
                for k in 0..face.len() {
                    assert_eq!(m.half_edge(face[k], face[(k + 1) % face.len()]), Some((f, k)));
                }
            }
            assert_eq!(m.half_edge(0, m.num_vertices()), None);
            assert_eq!(m.half_edge(m.num_vertices(), 0), None);
        }
    }
}
