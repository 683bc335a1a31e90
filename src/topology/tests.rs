//! Unit tests of every refinement host: one step on a small closed convex mesh.
//!
//! Expected counts come from counting what each host's definition (its module
//! comment) creates per old vertex, edge and face, and from Euler's formula:
//! a split of a closed sphere-like mesh is again a closed sphere-like mesh,
//! so V − E + F = 2 before and after. Orientation: with positions given to the
//! new vertices by their origin (old vertex: itself; edge (a, b): a point of
//! the segment nearer a; face: its centroid; corner k of face f: halfway
//! between f's centroid and that corner), every face of the refined mesh of a
//! convex polyhedron around the origin must face outwards, as the old faces
//! do, and every directed edge must have its reverse in another face (closed,
//! consistently oriented).

use std::collections::{BTreeMap, BTreeSet};

use super::Topology;
use crate::mesh::PolyMesh;
use crate::sdc::Origin;

type P = [f64; 3];

fn add(a: P, b: P) -> P {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn scale(a: P, s: f64) -> P {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn centroid(points: &[P], face: &[usize]) -> P {
    let sum = face.iter().fold([0.0; 3], |acc, &v| add(acc, points[v]));
    scale(sum, 1.0 / face.len() as f64)
}

/// Newell's normal of a polygon (the area vector, valid for non-planar cycles).
fn newell(points: &[P], face: &[usize]) -> P {
    let mut n = [0.0; 3];
    for (k, &a) in face.iter().enumerate() {
        let (p, q) = (points[a], points[face[(k + 1) % face.len()]]);
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    n
}

/// The unit cube around the origin, every face counter-clockwise seen from outside.
fn cube() -> (PolyMesh, Vec<P>) {
    let points: Vec<P> =
        (0..8).map(|i| [(i & 1) as f64 - 0.5, ((i >> 1) & 1) as f64 - 0.5, ((i >> 2) & 1) as f64 - 0.5]).collect();
    let faces = vec![
        vec![0, 2, 3, 1], // z = -1/2
        vec![4, 5, 7, 6], // z = +1/2
        vec![0, 1, 5, 4], // y = -1/2
        vec![2, 6, 7, 3], // y = +1/2
        vec![0, 4, 6, 2], // x = -1/2
        vec![1, 3, 7, 5], // x = +1/2
    ];
    (PolyMesh::new(8, faces).unwrap(), points)
}

/// The regular tetrahedron with vertices at alternate corners of a cube.
fn tetrahedron() -> (PolyMesh, Vec<P>) {
    let points = vec![[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];
    let faces = vec![vec![0, 1, 2], vec![0, 2, 3], vec![0, 3, 1], vec![1, 3, 2]];
    (PolyMesh::new(4, faces).unwrap(), points)
}

/// A polar net: poles N = 0 and S = 1, rings of `n` vertices at z = ±1 (ring
/// 1 at z = +1: vertices 2..2+n, ring 2 at z = −1: 2+n..2+2n), a fan of n
/// triangles at each pole and one ring of n quads between the rings.
fn polar_net(n: usize) -> (PolyMesh, Vec<P>) {
    let mut points = vec![[0.0, 0.0, 2.0], [0.0, 0.0, -2.0]];
    for z in [1.0, -1.0] {
        for k in 0..n {
            let t = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            points.push([t.cos(), t.sin(), z]);
        }
    }
    let (up, down) = (|k: usize| 2 + k % n, |k: usize| 2 + n + k % n);
    let mut faces = Vec::new();
    for k in 0..n {
        faces.push(vec![0, up(k), up(k + 1)]);
        faces.push(vec![1, down(k + 1), down(k)]);
        faces.push(vec![up(k), down(k), down(k + 1), up(k + 1)]);
    }
    (PolyMesh::new(2 + 2 * n, faces).unwrap(), points)
}

/// Attach a face control vertex (a vertex of no face) to every face: vertices
/// nv..nv+F, at the face centroids.
fn with_fcvs(mesh: PolyMesh, mut points: Vec<P>) -> (PolyMesh, Vec<P>) {
    let nv = mesh.num_vertices();
    let faces = mesh.faces().to_vec();
    for f in &faces {
        points.push(centroid(&points, f));
    }
    let fcv = (0..faces.len()).map(|f| Some(nv + f)).collect();
    (PolyMesh::new(nv + faces.len(), faces).unwrap().with_face_points(fcv).unwrap(), points)
}

/// (V, E, F) of the surface: V counts the corners of faces only (face points
/// lie on no face cycle), E the undirected edges.
fn counts(mesh: &PolyMesh) -> (usize, usize, usize) {
    let corners: BTreeSet<usize> = mesh.faces().iter().flatten().copied().collect();
    let mut edges = BTreeSet::new();
    for face in mesh.faces() {
        for (k, &a) in face.iter().enumerate() {
            let b = face[(k + 1) % face.len()];
            edges.insert((a.min(b), a.max(b)));
        }
    }
    (corners.len(), edges.len(), mesh.num_faces())
}

fn euler(c: (usize, usize, usize)) -> i64 {
    c.0 as i64 - c.1 as i64 + c.2 as i64
}

/// Positions of the refined vertices from their origins (see the module comment).
fn refined_points(old: &PolyMesh, points: &[P], origins: &[Origin]) -> Vec<P> {
    origins
        .iter()
        .map(|o| match *o {
            Origin::Vertex(v) => points[v],
            Origin::Edge(a, b) => scale(add(scale(points[a], 2.0), points[b]), 1.0 / 3.0),
            Origin::Face(f) => centroid(points, old.face(f)),
            Origin::Corner { face, corner } => {
                scale(add(centroid(points, old.face(face)), points[old.face(face)[corner]]), 0.5)
            }
        })
        .collect()
}

/// Closed and consistently oriented (every directed edge's reverse is in
/// exactly one face), and every face's normal points away from the origin.
fn assert_closed_and_outward(mesh: &PolyMesh, points: &[P], what: &str) {
    let mut directed: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for face in mesh.faces() {
        for (k, &a) in face.iter().enumerate() {
            *directed.entry((a, face[(k + 1) % face.len()])).or_default() += 1;
        }
    }
    for (&(a, b), &uses) in &directed {
        assert_eq!(uses, 1, "{what}: edge {a}->{b} used {uses} times");
        assert_eq!(directed.get(&(b, a)), Some(&1), "{what}: edge {a}->{b} has no reverse (open or flipped face)");
    }
    for (f, face) in mesh.faces().iter().enumerate() {
        let outward = dot(newell(points, face), centroid(points, face));
        assert!(outward > 1e-12, "{what}: face {f} {face:?} faces inwards ({outward})");
    }
}

/// One step of `host`: checks the refined counts against `want` (V, E, F),
/// Euler's characteristic, orientation, and that every face has a parent and
/// every vertex an origin. Returns the refined mesh.
fn check_step(host: Topology, mesh: &PolyMesh, points: &[P], want: (usize, usize, usize), what: &str) -> PolyMesh {
    let before = counts(mesh);
    assert_eq!(euler(before), 2, "{what}: premise, a sphere-like mesh");
    assert_closed_and_outward(mesh, points, &format!("{what} (premise)"));
    let refined = host.refine(mesh).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(refined.vertex_origins.len(), refined.mesh.num_vertices(), "{what}: one origin per vertex");
    assert_eq!(refined.face_parents.len(), refined.mesh.num_faces(), "{what}: one parent per face");
    let after = counts(&refined.mesh);
    assert_eq!(after, want, "{what}: (V, E, F) after one step");
    assert_eq!(euler(after), 2, "{what}: Euler characteristic");
    let new_points = refined_points(mesh, points, &refined.vertex_origins);
    assert_closed_and_outward(&refined.mesh, &new_points, what);
    refined.mesh
}

#[test]
fn primal_quad_split_of_the_cube() {
    // a vertex per old vertex, edge and face; every k-gon gives k quads, and
    // every old edge two halves, every k-gon k inner edges
    let (m, p) = cube();
    let (v, e, f, corners) = (8, 12, 6, 24);
    // on quads the mixed host's split is Catmull–Clark's
    for host in [Topology::PrimalQuad, Topology::MixedQuadTriangle] {
        let r = check_step(host, &m, &p, (v + e + f, 2 * e + corners, corners), "cube");
        assert!(r.faces().iter().all(|q| q.len() == 4), "Catmull–Clark's split gives quads only");
    }
}

#[test]
fn primal_triangle_splits_of_the_tetrahedron() {
    let (m, p) = tetrahedron();
    let (v, e, f) = (4, 6, 4);
    // Loop's 1 -> 4: a vertex per old vertex and edge; 2 halves per old edge
    // and 3 inner edges per triangle
    let r = check_step(Topology::PrimalTriangle, &m, &p, (v + e, 2 * e + 3 * f, 4 * f), "loop");
    assert!(r.faces().iter().all(|t| t.len() == 3));
    // a face point and 3 quads per triangle (Catmull–Clark on triangles)
    let r = check_step(Topology::PrimalQuad, &m, &p, (v + e + f, 2 * e + 3 * f, 3 * f), "catmull-clark on triangles");
    assert!(r.faces().iter().all(|q| q.len() == 4));
}

#[test]
fn dual_split_of_the_cube() {
    // a vertex per face corner (2E of them on a closed mesh), each of valence
    // 4; faces: one per old face, edge and vertex
    let (m, p) = cube();
    let (v, e, f) = (8, 12, 6);
    let r = check_step(Topology::Dual, &m, &p, (2 * e, 4 * e, f + e + v), "doo-sabin");
    let sizes: Vec<usize> = r.faces().iter().map(<[usize]>::len).collect();
    assert_eq!(sizes.iter().filter(|&&s| s == 3).count(), v, "a triangle per cube vertex (valence 3)");
    assert_eq!(sizes.iter().filter(|&&s| s == 4).count(), f + e, "a quad per old face and per edge");
}

#[test]
fn sqrt3_split_of_the_tetrahedron() {
    // a vertex per face; every old edge is flipped (E edges stay) and every
    // face vertex joins its 3 corners; each old edge carries 2 triangles
    let (m, p) = tetrahedron();
    let (v, e, f) = (4, 6, 4);
    let r = check_step(Topology::Sqrt3, &m, &p, (v + f, e + 3 * f, 2 * e), "sqrt3");
    assert!(r.faces().iter().all(|t| t.len() == 3));
    // no old edge survives: the flip replaces each by one between face vertices
    for (a, b) in m.edges() {
        assert!(r.half_edge(a, b).is_none() && r.half_edge(b, a).is_none(), "old edge {a}-{b} was not flipped");
    }
}

#[test]
fn ternary_split_of_the_cube() {
    // every quad becomes a 3 × 3 grid: 2 vertices per edge, 4 inside each
    // quad; 3 pieces per old edge and the grid's 12 inner edges per quad
    let (m, p) = cube();
    let (v, e, f) = (8, 12, 6);
    check_step(Topology::Ternary, &m, &p, (v + 2 * e + 4 * f, 3 * e + 12 * f, 9 * f), "ternary");
    // a triangle is refused with a message (the host needs a quad mesh)
    let (t, _) = tetrahedron();
    assert!(Topology::Ternary.refine(&t).is_err());
}

#[test]
fn fcv_split_of_the_cube_with_face_control_vertices() {
    // the surface splits as Catmull–Clark's does; the old FCVs become the new
    // face centres and each new quad gets a new FCV of its own
    let (m, p) = with_fcvs(cube().0, cube().1);
    let (v, e, f, corners) = (8, 12, 6, 24);
    let refined = Topology::Fcv.refine(&m).unwrap();
    assert!(refined.mesh.has_face_point_on_every_face(), "every new quad carries an FCV");
    assert_eq!(refined.mesh.num_vertices(), v + e + f + corners, "surface vertices plus one NFCV per quad");
    check_step(Topology::Fcv, &m, &p, (v + e + f, 2 * e + corners, corners), "non-box");
    // without FCVs the host refuses
    assert!(Topology::Fcv.refine(&cube().0).is_err());
}

#[test]
fn augmented_dual_split_adds_points_to_non_quads_only() {
    // the dual split's surface; a central point (a vertex of no face) in the
    // F-face of every old face that is not a quad or carries a point
    let (m, p) = cube();
    let (v, e, f) = (8, 12, 6);
    let r = Topology::AugmentedDual.refine(&m).unwrap();
    assert_eq!(r.mesh.num_vertices(), 2 * e, "quads without points get no central point");
    check_step(Topology::AugmentedDual, &m, &p, (2 * e, 4 * e, f + e + v), "pgs on the cube");
    let (t, tp) = tetrahedron();
    let (v, e, f) = (4, 6, 4);
    let r = Topology::AugmentedDual.refine(&t).unwrap();
    assert_eq!(r.mesh.num_vertices(), 2 * e + f, "a central point per triangle");
    assert_eq!(r.mesh.face_points.iter().flatten().count(), f);
    check_step(Topology::AugmentedDual, &t, &tp, (2 * e, 4 * e, f + e + v), "pgs on the tetrahedron");
}

#[test]
fn polar_split_doubles_the_rings_and_keeps_the_spokes() {
    // poles stay; every spoke gets one point, every radial quad edge two (one
    // near each end); so 4 rings of n vertices; faces: the 3n shrunken faces
    // plus a quad on each of the 2n circumferential edges; edges: 2n spokes,
    // n on each of the 4 rings, n between consecutive rings (3n)
    for n in [3, 4, 6] {
        let (m, p) = polar_net(n);
        check_step(Topology::Polar, &m, &p, (2 + 4 * n, 9 * n, 5 * n), &format!("polar n = {n}"));
        let r = Topology::Polar.refine(&m).unwrap();
        for pole in [0, 1] {
            let new_pole = r.vertex_origins.iter().position(|o| *o == Origin::Vertex(pole)).expect("the pole stays");
            assert_eq!(r.mesh.valence(new_pole), Some(n), "n = {n}: the number of spokes never changes");
        }
    }
    // a closed all-triangle mesh is no polar net: every vertex is a pole
    let (t, _) = tetrahedron();
    assert!(Topology::Polar.refine(&t).is_err());
}
