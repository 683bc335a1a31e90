//! Unit tests of the gatherers: which mesh vertices each slot of a rule lands
//! on, on small meshes whose neighbourhoods are known by construction (a quad
//! star around a vertex of valence n, the octahedron, the cube).

use super::{gather, GatherError, Gathered, Host, OriginKind, Part, Target, Wants};
use crate::mesh::PolyMesh;
use crate::sdc::Origin;

/// A mask that weighs only the mandatory rules and families.
struct Plain;
impl Wants for Plain {
    fn rule(&self, _: &str) -> bool {
        false
    }
    fn family(&self, _: &str, _: &str) -> bool {
        false
    }
}

/// A mask that weighs every rule and optional family.
struct Everything;
impl Wants for Everything {
    fn rule(&self, _: &str) -> bool {
        true
    }
    fn family(&self, _: &str, _: &str) -> bool {
        true
    }
}

/// The targets of one family of a part, in slot order (j ascending as put).
fn family(part: &Part, name: &str) -> Vec<usize> {
    part.slots
        .iter()
        .filter(|s| s.family == name)
        .map(|s| match s.target {
            Target::Vertex(v) => v,
            Target::Derived(_) => panic!("family {name}: a derived point"),
        })
        .collect()
}

fn one(g: Gathered) -> Part {
    assert!(g.extraordinary.is_empty() && g.regular.is_none(), "{g:?}");
    let [p] = <[Part; 1]>::try_from(g.parts).expect("one part");
    p
}

/// A star of n quads around vertex 0: e_j = 1 + j, f_j = 1 + n + j, faces
/// [0, e_j, f_j, e_{j+1}] (counter-clockwise). Only vertex 0 is interior.
fn quad_star(n: usize) -> PolyMesh {
    let e = |j: usize| 1 + j % n;
    let faces: Vec<Vec<usize>> = (0..n).map(|j| vec![0, e(j), 1 + n + j, e(j + 1)]).collect();
    PolyMesh::new(1 + 2 * n, faces).unwrap()
}

/// The octahedron: vertex 2a + s is the point ±1 on axis a (s = 1: −1), so v
/// and v ^ 1 are antipodes and two vertices are adjacent iff their axes differ.
fn octahedron() -> PolyMesh {
    let mut faces = Vec::new();
    for sx in 0..2 {
        for sy in 0..2 {
            for sz in 0..2 {
                let (x, y, z) = (sx, 2 + sy, 4 + sz);
                // (x, y, z) is counter-clockwise seen from outside when an even
                // number of the coordinates is negative
                faces.push(if (sx + sy + sz) % 2 == 0 { vec![x, y, z] } else { vec![x, z, y] });
            }
        }
    }
    PolyMesh::new(6, faces).unwrap()
}

fn adjacent(a: usize, b: usize) -> bool {
    a / 2 != b / 2
}

/// The cube with corners i = (x, y, z) bits; two corners are adjacent iff
/// they differ in one bit.
fn cube() -> PolyMesh {
    let faces = vec![
        vec![0, 2, 3, 1],
        vec![4, 5, 7, 6],
        vec![0, 1, 5, 4],
        vec![2, 6, 7, 3],
        vec![0, 4, 6, 2],
        vec![1, 3, 7, 5],
    ];
    PolyMesh::new(8, faces).unwrap()
}

fn cube_adjacent(a: usize, b: usize) -> bool {
    (a ^ b).count_ones() == 1
}

/// `got` is `want` turned by some shift s: got[j] = want[(j + s) % n].
fn is_rotation(got: &[usize], want: &[usize]) -> bool {
    let n = want.len();
    got.len() == n && (0..n).any(|s| (0..n).all(|j| got[j] == want[(j + s) % n]))
}

#[test]
fn primal_quad_vertex_rule_gathers_the_one_ring_in_fan_order() {
    for n in [3, 4, 5, 7] {
        let mesh = quad_star(n);
        let p = one(gather(Host::PrimalQuad, &mesh, Origin::Vertex(0), &Plain).unwrap());
        assert_eq!(p.n, n);
        assert_eq!(family(&p, "centre"), vec![0]);
        let (edge, face) = (family(&p, "edge"), family(&p, "face"));
        let e: Vec<usize> = (0..n).map(|j| 1 + j).collect();
        assert!(is_rotation(&edge, &e), "n = {n}: edge neighbours {edge:?}, counter-clockwise from any");
        // f_j is the corner opposite v in the quad [v, e_j, f_j, e_{j+1}]:
        // vertex 1 + n + j beside e_j = 1 + j
        for (j, (&f, &e)) in face.iter().zip(&edge).enumerate() {
            assert_eq!(f, e + n, "n = {n}: f_{j} pairs with e_{j}");
        }
        assert!(p.slots.iter().all(|s| s.n == n && s.at == Some(0)), "every slot at the centre's valence");
        // over general polygons the fan faces' corners come too, each face
        // from v on, with its corner count
        let p = one(gather(Host::PrimalQuad, &mesh, Origin::Vertex(0), &Everything).unwrap());
        let corners = family(&p, "face-corner");
        assert_eq!(corners.len(), 4 * n);
        for (j, quad) in corners.chunks(4).enumerate() {
            assert_eq!(quad, [0, edge[j], face[j], edge[(j + 1) % n]], "n = {n}, face {j}");
        }
        assert!(p.slots.iter().filter(|s| s.family == "face-corner").all(|s| s.m == Some(4)));
        // a vertex on the star's rim has an open fan: truncated
        assert_eq!(gather(Host::PrimalQuad, &mesh, Origin::Vertex(1), &Plain), Err(GatherError::Truncated));
    }
}

#[test]
fn primal_quad_edge_rule_gathers_both_quads() {
    // edge (0, e_0) of the star: left quad [0, e_0, f_0, e_1], right quad
    // [e_0, 0, e_{n−1}, f_{n−1}] read from e_0
    let n = 5;
    let mesh = quad_star(n);
    let (e0, f0, e1, elast, flast) = (1, 1 + n, 2, n, 2 * n);
    let g = gather(Host::PrimalQuad, &mesh, Origin::Edge(0, e0), &Plain).unwrap();
    let p = one(g);
    assert_eq!(family(&p, "ends"), vec![0, e0]);
    assert_eq!(family(&p, "side"), vec![f0, e1, elast, flast]);
    // with the extraordinary-edge rule wanted: the centre (valence 5) is
    // extraordinary, e_0 is on the rim (open fan, regular part); the rule of
    // the centre turned so that its e_0 is the edge's other end replaces the
    // regular one
    let g = gather(Host::PrimalQuad, &mesh, Origin::Edge(0, e0), &Everything).unwrap();
    assert!(g.parts.is_empty());
    let [ev] = <[Part; 1]>::try_from(g.extraordinary).unwrap();
    assert_eq!(ev.rule, "edge-extraordinary");
    assert_eq!(family(&ev, "edge"), (1..=n).collect::<Vec<_>>(), "j = 0 is the edge's other end");
    assert_eq!(g.regular.as_ref().map(|r| family(r, "ends")), Some(vec![0, e0]));
}

#[test]
fn loop_rules_on_the_octahedron() {
    let mesh = octahedron();
    for v in 0..6 {
        // vertex rule: the 4 vertices not antipodal to v, consecutive ones adjacent
        let p = one(gather(Host::PrimalTriangle, &mesh, Origin::Vertex(v), &Plain).unwrap());
        let ring = family(&p, "edge");
        assert_eq!(ring.len(), 4);
        let mut sorted = ring.clone();
        sorted.sort();
        assert_eq!(sorted, (0..6).filter(|&u| u != v && u != v ^ 1).collect::<Vec<_>>());
        for j in 0..4 {
            assert!(adjacent(ring[j], ring[(j + 1) % 4]), "fan order: {ring:?}");
        }
    }
    // edge rule at (+z, +x) = (4, 0): opposite vertices are the two common
    // neighbours (±y); the triangle across an edge from apex r has apex −r,
    // so the wings across b–c, c–a, a–d, d–b are −a, −b, −b, −a
    let (a, b) = (4, 0);
    let g = gather(Host::PrimalTriangle, &mesh, Origin::Edge(a, b), &Everything).unwrap();
    let regular = g.regular.clone().expect("both ends have valence 4 ≠ 6: extraordinary rules replace it");
    assert_eq!(family(&regular, "ends"), vec![a, b]);
    let opposite = family(&regular, "opposite");
    let mut common = opposite.clone();
    common.sort();
    assert_eq!(common, vec![2, 3]);
    assert_eq!(family(&regular, "wing"), vec![a ^ 1, b ^ 1, b ^ 1, a ^ 1]);
    // both ends extraordinary: the mean of the two ends' rules, each with its
    // j = 0 at the other end
    assert_eq!(g.extraordinary.len(), 2);
    for (part, (end, other)) in g.extraordinary.iter().zip([(a, b), (b, a)]) {
        assert_eq!(part.scale, (1, 2));
        assert_eq!(family(part, "centre"), vec![end]);
        assert_eq!(family(part, "edge")[0], other);
    }
}

#[test]
fn dual_and_sqrt3_face_rules_gather_the_face_and_its_corners_rings() {
    let cube = cube();
    // Doo–Sabin's corner k of a face: the face's corners from corner k on
    let p = one(gather(Host::Dual, &cube, Origin::Corner { face: 0, corner: 2 }, &Plain).unwrap());
    assert_eq!(family(&p, "corner"), vec![3, 1, 0, 2]);
    assert_eq!(p.n, 4);
    // the dual host creates corner points only
    assert_eq!(
        gather(Host::Dual, &cube, Origin::Vertex(0), &Plain),
        Err(GatherError::Unsupported(Host::Dual, OriginKind::Vertex))
    );
    // sqrt(3)'s face rule: each corner P and P's ring (valence 4 on the
    // octahedron: the 4 vertices other than P and its antipode)
    let oct = octahedron();
    let p = one(gather(Host::Sqrt3, &oct, Origin::Face(0), &Plain).unwrap());
    let corners = family(&p, "corner");
    assert_eq!(corners, oct.face(0).to_vec());
    let ring = family(&p, "ring");
    assert_eq!(ring.len(), 12);
    for (k, &c) in corners.iter().enumerate() {
        let mut r = ring[4 * k..4 * k + 4].to_vec();
        r.sort();
        assert_eq!(r, (0..6).filter(|&u| u != c && u != c ^ 1).collect::<Vec<_>>(), "ring of corner {c}");
    }
    assert!(p.slots.iter().all(|s| s.n == 4));
}

#[test]
fn ternary_edge_rule_takes_the_side_vertices_next_to_each_end() {
    // on the cube, for every directed edge a → b: the near-side vertices are
    // the corners of the two quads adjacent to a (not b), the far-side ones
    // those adjacent to b (not a)
    let cube = cube();
    for (a, b) in cube.edges() {
        for (a, b) in [(a, b), (b, a)] {
            let p = one(gather(Host::Ternary, &cube, Origin::Edge(a, b), &Plain).unwrap());
            assert_eq!((family(&p, "near"), family(&p, "far")), (vec![a], vec![b]));
            let (near, far) = (family(&p, "near-side"), family(&p, "far-side"));
            assert_eq!((near.len(), far.len()), (2, 2));
            for &x in &near {
                assert!(cube_adjacent(x, a) && x != b && !cube_adjacent(x, b), "{a}->{b}: near side {x}");
            }
            for &x in &far {
                assert!(cube_adjacent(x, b) && x != a && !cube_adjacent(x, a), "{a}->{b}: far side {x}");
            }
            // near side j and far side j lie on the same quad: adjacent
            for (j, (&x, &y)) in near.iter().zip(&far).enumerate() {
                assert!(cube_adjacent(x, y), "{a}->{b}: side {j}");
            }
        }
    }
}

#[test]
fn fcv_rules_take_the_face_control_vertices_around() {
    // the cube with FCV 8 + f on face f
    let m = cube();
    let faces = m.faces().to_vec();
    let mesh =
        PolyMesh::new(14, faces.clone()).unwrap().with_face_points((0..6).map(|f| Some(8 + f)).collect()).unwrap();
    for v in 0..8 {
        let p = one(gather(Host::Fcv, &mesh, Origin::Vertex(v), &Plain).unwrap());
        let mut got = family(&p, "fcv");
        got.sort();
        let want: Vec<usize> = (0..6).filter(|&f| faces[f].contains(&v)).map(|f| 8 + f).collect();
        assert_eq!(got, want, "vertex {v}: the FCVs of its 3 faces");
    }
    for (a, b) in mesh.edges() {
        let p = one(gather(Host::Fcv, &mesh, Origin::Edge(a, b), &Plain).unwrap());
        let mut got = family(&p, "fcv");
        got.sort();
        let want: Vec<usize> =
            (0..6).filter(|&f| faces[f].contains(&a) && faces[f].contains(&b)).map(|f| 8 + f).collect();
        assert_eq!(got, want, "edge {a}-{b}: the FCVs of its 2 faces");
    }
    let p = one(gather(Host::Fcv, &mesh, Origin::Face(3), &Plain).unwrap());
    assert_eq!((family(&p, "corner"), family(&p, "centre")), (faces[3].clone(), vec![11]));
    // a mesh without FCVs is not covered
    assert_eq!(gather(Host::Fcv, &m, Origin::Vertex(0), &Plain), Err(GatherError::NotCovered));
}

#[test]
fn polar_rules_take_the_pole_ring_turned_to_the_spoke() {
    // a pole 0 in a fan of n triangles [0, r_k, r_{k+1}], r_k = 1 + k, with a
    // ring of quads outside (so that r_k is no pole)
    let n = 6;
    let r = |k: usize| 1 + k % n;
    let o = |k: usize| 1 + n + k % n;
    let mut faces: Vec<Vec<usize>> = (0..n).map(|k| vec![0, r(k), r(k + 1)]).collect();
    faces.extend((0..n).map(|k| vec![r(k), o(k), o(k + 1), r(k + 1)]));
    let mesh = PolyMesh::new(1 + 2 * n, faces).unwrap();
    let p = one(gather(Host::Polar, &mesh, Origin::Vertex(0), &Plain).unwrap());
    assert_eq!(family(&p, "centre"), vec![0]);
    assert!(is_rotation(&family(&p, "ring"), &(1..=n).collect::<Vec<_>>()));
    for k in 0..n {
        let p = one(gather(Host::Polar, &mesh, Origin::Edge(0, r(k)), &Plain).unwrap());
        assert_eq!(p.rule, "spoke");
        assert_eq!(family(&p, "ring"), (0..n).map(|j| r(k + j)).collect::<Vec<_>>(), "spoke {k}: ring from r_k on");
        // a radial edge away from the pole: its two ends only
        let p = one(gather(Host::Polar, &mesh, Origin::Edge(r(k), o(k)), &Plain).unwrap());
        assert_eq!((p.rule, family(&p, "near"), family(&p, "far")), ("radial", vec![r(k)], vec![o(k)]));
    }
}

/// A mask over the mandatory slots that weighs every slot 1: the stencil of
/// an origin then lists each gathered vertex once, with weight 1.
struct Ones;
impl Wants for Ones {
    fn rule(&self, _: &str) -> bool {
        false
    }
    fn family(&self, _: &str, _: &str) -> bool {
        false
    }
}
impl super::Mask<f64> for Ones {
    fn weight(&self, _: &PolyMesh, _: &'static str, _: &super::Slot) -> Result<f64, crate::numeric::Inexact> {
        Ok(1.0)
    }
}

/// A pyramid over a pentagon: apex 0 (five triangles around it, valence 5),
/// base corners 1..=5, and the pentagon closing the base.
fn pentagonal_pyramid() -> PolyMesh {
    let mut faces: Vec<Vec<usize>> = (0..5).map(|j| vec![0, 1 + j, 1 + (j + 1) % 5]).collect();
    faces.push(vec![5, 4, 3, 2, 1]);
    PolyMesh::new(6, faces).unwrap()
}

#[test]
fn weigh_passes_the_gatherers_reason_on() {
    use super::weigh;
    let one = 1.0;
    // the quad star's centre has its closed fan: centre, n edge and n face
    // neighbours, each weighed 1
    let star = quad_star(5);
    let s = weigh(Host::PrimalQuad, &star, Origin::Vertex(0), &Ones, &one).unwrap().unwrap().merged();
    assert_eq!(s.terms, (0..11).map(|v| (v, 1.0)).collect::<Vec<_>>());
    // an outer vertex of the star lies on the rim: its fan is cut off
    let r = weigh(Host::PrimalQuad, &star, Origin::Vertex(1), &Ones, &one).unwrap();
    assert_eq!(r, Err(GatherError::Truncated));
    // under Loop's host, the apex (triangles only) has a rule, but a base
    // corner (two triangles and the pentagon) and an edge of the pentagon are
    // complete neighbourhoods of a shape no triangle rule covers
    let pyramid = pentagonal_pyramid();
    let s = weigh(Host::PrimalTriangle, &pyramid, Origin::Vertex(0), &Ones, &one).unwrap().unwrap().merged();
    assert_eq!(s.terms.len(), 6, "the apex and its five neighbours");
    for origin in [Origin::Vertex(1), Origin::Edge(1, 2)] {
        let r = weigh(Host::PrimalTriangle, &pyramid, origin, &Ones, &one).unwrap();
        assert_eq!(r, Err(GatherError::NotCovered), "{origin:?}");
    }
    // a primal host never creates points at the corners of a face
    let r = weigh(Host::PrimalTriangle, &pyramid, Origin::Corner { face: 0, corner: 0 }, &Ones, &one).unwrap();
    assert_eq!(r, Err(GatherError::Unsupported(Host::PrimalTriangle, OriginKind::Corner)));
}
