//! Test meshes and the checks every host's own tests run on what its file
//! states (the tests themselves sit beside each host, in its file).

use crate::mesh::PolyMesh;
use crate::sdc::host::{Host, Registry, RegularSpline};
use crate::sdc::slots::{OriginKind, Wants};

/// Grid point (i, j) of an m × n torus.
fn at(n: usize, i: usize, j: usize, m: usize) -> usize {
    (i % m) * n + (j % n)
}

/// The m × n quad torus: every vertex of valence 4, no boundary, so a split
/// is the same everywhere (no extraordinary point, Euler characteristic 0).
pub fn quad_torus(m: usize, n: usize) -> PolyMesh {
    let mut faces = Vec::new();
    for i in 0..m {
        for j in 0..n {
            faces.push(vec![at(n, i, j, m), at(n, i + 1, j, m), at(n, i + 1, j + 1, m), at(n, i, j + 1, m)]);
        }
    }
    PolyMesh::new(m * n, faces).expect("a torus is a closed manifold")
}

/// The m × n quad torus with every quad cut along one diagonal: every vertex
/// of valence 6.
pub fn triangle_torus(m: usize, n: usize) -> PolyMesh {
    let mut faces = Vec::new();
    for i in 0..m {
        for j in 0..n {
            let (a, b, c, d) = (at(n, i, j, m), at(n, i + 1, j, m), at(n, i + 1, j + 1, m), at(n, i, j + 1, m));
            faces.push(vec![a, b, c]);
            faces.push(vec![a, c, d]);
        }
    }
    PolyMesh::new(m * n, faces).expect("a torus is a closed manifold")
}

/// Every rule and every optional family: the gatherer collects all it can.
pub struct All;
impl Wants for All {
    fn rule(&self, _: &str) -> bool {
        true
    }
    fn family(&self, _: &str, _: &str) -> bool {
        true
    }
}

/// Check what `host` states against one split of the closed `mesh`:
/// * the split gives `expected_faces` faces (counted independently by the
///   caller from the split's definition), and on a `regular` mesh (a torus:
///   no extraordinary point, no boundary) exactly `growth_per_level` times
///   as many as before;
/// * `size_bound` bounds the new face and vertex counts;
/// * every new vertex's origin is of a kind the host has a rule for, and its
///   gatherer finds the slots of that rule on the closed mesh;
/// * the regular part's spline fits the growth: a box spline of a lattice
///   refinement dilates the lattice by d per step, so a face becomes d²
///   faces (d = 2 binary, 3 ternary); a host without one grows by a factor
///   that is no square (a rotating or radial-only split);
/// * the spec names the host, and the name finds it again.
pub fn check_host(host: Host, mesh: &PolyMesh, expected_faces: usize, regular: bool) {
    let unit = host.unit();
    let spec = unit.spec();
    assert_eq!(spec.host, host);
    assert_eq!(Host::by_name(spec.name), Some(host));
    let refined = unit.refine(mesh).expect("the host refines its test mesh");
    let (before, after) = (mesh.num_faces(), refined.mesh.num_faces());
    assert_eq!(after, expected_faces, "{}: faces after one split", spec.name);
    if regular {
        assert_eq!(after, unit.growth_per_level() * before, "{}: growth per level", spec.name);
    }
    let bound = unit.size_bound(mesh);
    assert!(bound >= after && bound >= refined.mesh.num_vertices(), "{}: size bound {bound}", spec.name);
    let kinds = spec.origins();
    for &origin in &refined.vertex_origins {
        assert!(kinds.contains(&OriginKind::of(origin)), "{}: no rule for {origin:?}", spec.name);
        let gathered = unit.gather(mesh, origin, &All);
        assert!(gathered.is_ok(), "{}: {origin:?}: {gathered:?}", spec.name);
    }
    let growth = unit.growth_per_level();
    let square = (1..=growth).any(|d| d * d == growth);
    match unit.regular_spline() {
        RegularSpline::BinaryPrimal | RegularSpline::BinaryDual | RegularSpline::NonBoxS31 => assert_eq!(growth, 4),
        RegularSpline::TernaryPrimal => assert_eq!(growth, 9),
        RegularSpline::NoBoxSpline => assert!(!square, "{}: growth {growth}", spec.name),
    }
}
