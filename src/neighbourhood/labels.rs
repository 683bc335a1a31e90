//! Stable, human-readable vertex labels: ring, sector, index within the ring's
//! sector (counter-clockwise from the sector's spoke), and kind.

use serde::Serialize;

use crate::mesh::{LatticeCoord, PolyMesh, SectorKind};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum VertexKind {
    /// the extraordinary vertex itself
    Centre,
    /// a corner of the central face (face-centred neighbourhoods)
    Corner,
    /// on a spoke: an edge neighbour of the centre or further out along the edge line
    Edge,
    /// on the diagonal of a quad sector: opposite the centre across a face
    Face,
    Vertex,
    /// a face control vertex (non-box subdivision)
    Fcv,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct VertexLabel {
    pub name: String,
    pub ring: usize,
    pub sector: usize,
    pub index: usize,
    pub kind: VertexKind,
    /// lattice coordinates in the sector's chart
    pub i: i64,
    pub j: i64,
}

/// Ring of every vertex: ring 0 is the given centre set; ring k+1 holds the
/// unvisited corners of faces that touch ring k. A face control vertex takes
/// the largest ring of its face's corners.
pub fn rings(mesh: &PolyMesh, centre_set: &[usize]) -> Vec<usize> {
    let mut ring = vec![usize::MAX; mesh.num_vertices()];
    let vf = mesh.vertex_faces();
    let mut frontier: Vec<usize> = centre_set.to_vec();
    for &v in centre_set {
        ring[v] = 0;
    }
    let mut k = 0;
    while !frontier.is_empty() {
        let mut next = Vec::new();
        for &v in &frontier {
            for &f in &vf[v] {
                for &u in mesh.face(f) {
                    if ring[u] == usize::MAX {
                        ring[u] = k + 1;
                        next.push(u);
                    }
                }
            }
        }
        frontier = next;
        k += 1;
    }
    // a face point sits in the outermost ring of its face's corners
    for (f, p) in mesh.face_points.iter().enumerate() {
        if let Some(p) = *p {
            ring[p] = mesh.face(f).iter().map(|&v| ring[v]).max().unwrap_or(usize::MAX);
        }
    }
    ring
}

/// Labels for all vertices of a charted mesh.
pub fn label_vertices(mesh: &PolyMesh, centre_set: &[usize], face_centred: bool) -> Vec<VertexLabel> {
    let chart = mesh.chart.as_ref().expect("labels need a lattice chart");
    let ring = rings(mesh, centre_set);
    let coords: &[LatticeCoord] = &chart.vertex_coords;
    let is_fcv: std::collections::HashSet<usize> = mesh.face_points.iter().flatten().copied().collect();
    let mut labels: Vec<VertexLabel> = (0..mesh.num_vertices())
        .map(|v| {
            let c = coords[v];
            let kind = if c.is_centre() {
                VertexKind::Centre
            } else if is_fcv.contains(&v) {
                VertexKind::Fcv
            } else if face_centred && ring[v] == 0 {
                VertexKind::Corner
            } else if face_centred {
                VertexKind::Vertex
            } else if c.j == 0 {
                VertexKind::Edge
            } else if c.i == c.j && chart.sector_kinds[c.sector] == SectorKind::Quad {
                VertexKind::Face
            } else {
                VertexKind::Vertex
            };
            VertexLabel { name: String::new(), ring: ring[v], sector: c.sector, index: 0, kind, i: c.i, j: c.j }
        })
        .collect();
    // index: rank within (ring, sector), walking from the spoke counter-clockwise
    let mut order: Vec<usize> = (0..labels.len()).collect();
    order.sort_by_key(|&v| (labels[v].ring, labels[v].sector, labels[v].j - labels[v].i, labels[v].j));
    let mut prev = None;
    let mut idx = 0;
    order.retain(|&v| labels[v].kind != VertexKind::Centre); // the centre has no index
    for &v in &order {
        let key = (labels[v].ring, labels[v].sector);
        idx = if prev == Some(key) { idx + 1 } else { 0 };
        prev = Some(key);
        labels[v].index = idx;
    }
    for l in &mut labels {
        l.name = match l.kind {
            VertexKind::Centre => "centre".to_string(),
            k => format!("{}[r{},s{},{}]", kind_name(k), l.ring, l.sector, l.index),
        };
    }
    labels
}

pub fn kind_name(k: VertexKind) -> &'static str {
    match k {
        VertexKind::Centre => "centre",
        VertexKind::Corner => "corner",
        VertexKind::Edge => "edge",
        VertexKind::Face => "face",
        VertexKind::Vertex => "vertex",
        VertexKind::Fcv => "fcv",
    }
}

/// Canonical order: by ring, then sector, then index.
pub fn canonical_order(labels: &[VertexLabel], set: &mut [usize]) {
    set.sort_by_key(|&v| (labels[v].ring, labels[v].sector, labels[v].index));
}
