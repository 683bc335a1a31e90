//! Extracting the characteristic ring from a refined net: the facets of the
//! first ring's descendants minus those of the first ring one analysis step
//! later (which is the level-0 part scaled by λ1), and the two boundary
//! polygons of the ring.

use nalgebra::{Matrix2, Vector2};

use super::net::{facet_triangles, Net};

/// A triangle of the refined net in the plane.
pub type Tri = [[f64; 2]; 3];

#[derive(Clone, Debug)]
pub struct Ring {
    /// facets of the ring (outer minus inner)
    pub ring: Vec<Tri>,
    /// facets inside the ring: λ1 times the ring and all smaller copies
    pub inner: Vec<Tri>,
    /// directed boundary edges of the outer region (the ring's outer boundary),
    /// oriented like the faces
    pub outer_boundary: Vec<[[f64; 2]; 2]>,
    /// directed boundary edges of the inner region (the ring's inner boundary)
    pub inner_boundary: Vec<[[f64; 2]; 2]>,
    /// the ring's faces as corner polygons (for drawing parameter lines)
    pub ring_polys: Vec<Vec<[f64; 2]>>,
    /// the faces inside the ring as corner polygons
    pub inner_polys: Vec<Vec<[f64; 2]>>,
}

pub fn extract(net: &Net) -> Ring {
    let mesh = &net.mesh;
    let p = |v: usize| net.points[v].expect("first-ring vertices are defined (checked during refinement)");
    let mut ring = Vec::new();
    let mut inner = Vec::new();
    let mut ring_polys = Vec::new();
    let mut inner_polys = Vec::new();
    for f in (0..mesh.num_faces()).filter(|&f| net.outer[f]) {
        let tris = facet_triangles(mesh, f).into_iter().map(|t| [p(t[0]), p(t[1]), p(t[2])]);
        if net.inner[f] {
            inner_polys.push(mesh.face(f).iter().map(|&v| p(v)).collect());
            inner.extend(tris);
        } else {
            ring_polys.push(mesh.face(f).iter().map(|&v| p(v)).collect());
            ring.extend(tris);
        }
    }
    let boundary = |flags: &dyn Fn(usize) -> bool| -> Vec<[[f64; 2]; 2]> {
        // a directed side (a, b) is on the boundary when no flagged face has
        // the side (b, a); the sides leaving each vertex are few, so a list
        // per vertex answers that without hashing the (many) sides of a deep
        // level's ring
        let mut leaving: Vec<Vec<usize>> = vec![Vec::new(); mesh.num_vertices()];
        for f in (0..mesh.num_faces()).filter(|&f| flags(f)) {
            let face = mesh.face(f);
            for k in 0..face.len() {
                leaving[face[k]].push(face[(k + 1) % face.len()]);
            }
        }
        // in face order, not the set's (randomly seeded) order: sums over the
        // boundary (normalisation, winding) then repeat to the last bit
        (0..mesh.num_faces())
            .filter(|&f| flags(f))
            .flat_map(|f| {
                let face = mesh.face(f);
                (0..face.len()).map(move |k| (face[k], face[(k + 1) % face.len()]))
            })
            .filter(|(a, b)| !leaving[*b].contains(a))
            .map(|(a, b)| [p(a), p(b)])
            .collect()
    };
    let outer_boundary = boundary(&|f| net.outer[f]);
    let inner_boundary = boundary(&|f| net.outer[f] && net.inner[f]);
    Ring { ring, inner, outer_boundary, inner_boundary, ring_polys, inner_polys }
}

/// Signed area of a triangle (positive when counter-clockwise).
pub fn signed_area(t: &Tri) -> f64 {
    // half the determinant of the edge vectors: the Jacobian of the affine
    // map from the reference triangle, times 1/2
    let (a, b, c) = (Vector2::from(t[0]), Vector2::from(t[1]), Vector2::from(t[2]));
    0.5 * Matrix2::from_columns(&[b - a, c - a]).determinant()
}

/// How many times a closed set of directed edges winds around the origin
/// (the sum of the angles the edges subtend, over 2π). `None` when an edge
/// passes through the origin, where the winding number is undefined.
pub fn winding_number(edges: &[[[f64; 2]; 2]]) -> Option<f64> {
    let mut total = 0.0;
    for [a, b] in edges {
        let (a, b) = (Vector2::from(*a), Vector2::from(*b));
        let cross = a.perp(&b);
        let dot = a.dot(&b);
        if cross == 0.0 && dot <= 0.0 {
            return None;
        }
        total += cross.atan2(dot);
    }
    Some(total / (2.0 * std::f64::consts::PI))
}
