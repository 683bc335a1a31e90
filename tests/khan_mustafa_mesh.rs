//! The Khan–Mustafa masks on quad meshes (`schemes::lattice_on_mesh`): the
//! same masks drive the lattice engine (windows on Z²) and mesh refinement /
//! characteristic maps (quad meshes with lattice directions). Independent
//! checks: refinement of a torus grid against a direct periodic convolution
//! with the masks; the mesh path's local matrix spectrum against the lattice
//! engine's; the characteristic map of a scheme with linear precision.

use crate::common;
use common::{fails, subdlab};
use subdlab::lattice::{self, LatticeScheme};
use subdlab::mesh::PolyMesh;
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::refine::mesh::refine_mesh;
use subdlab::schemes;
use subdlab::spectrum::{analyse, Options};

const N: usize = 8;
const M: usize = 6;

/// A torus grid of N x M quads; vertex (i, j) has id j N + i; data z(i, j).
fn torus() -> (PolyMesh, Vec<[f64; 3]>) {
    let id = |i: usize, j: usize| (j % M) * N + (i % N);
    let mut faces = Vec::new();
    for j in 0..M {
        for i in 0..N {
            faces.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    // x, y: the lattice position (exact away from the seam, by linear precision); z: data
    let pts = (0..N * M)
        .map(|v| {
            let (i, j) = ((v % N) as f64, (v / N) as f64);
            [i, j, (1.3 * i).sin() + (0.7 * j).cos() + 0.1 * i * j]
        })
        .collect();
    (PolyMesh::new(N * M, faces).unwrap(), pts)
}

#[test]
fn torus_refinement_is_the_periodic_convolution_with_the_masks() {
    let scheme = schemes::build("khan-mustafa", &[]).unwrap();
    let km = schemes::registry::lattice("khan-mustafa", &[]).unwrap();
    let (mut mesh, pts) = torus();
    mesh.orient_lattice().unwrap();
    let (_, out) = refine_mesh(scheme.as_ref(), &mesh, &pts, 1).unwrap();
    // direct: fine point q = (a, b) is Σ w p_{(i + r) mod N, (j + s) mod M}
    let z = |i: i64, j: i64| pts[(j.rem_euclid(M as i64) as usize) * N + i.rem_euclid(N as i64) as usize][2];
    // every interior fine point (a, b), computed directly, must be among the
    // refined points: at (a/2, b/2) (linear precision) with the convolved z
    let mut checked = 0;
    for a in 4..=(2 * N as i64 - 6) {
        for b in 4..=(2 * M as i64 - 6) {
            let want: f64 = lattice::stencil::<f64>(km.as_ref() as &dyn LatticeScheme, (a, b))
                .into_iter()
                .map(|((i, j), w)| w * z(i, j))
                .sum();
            let (x, y) = (a as f64 / 2.0, b as f64 / 2.0);
            let found =
                out.iter().any(|p| (p[0] - x).abs() < 1e-9 && (p[1] - y).abs() < 1e-9 && (p[2] - want).abs() < 1e-12);
            assert!(found, "fine point ({a}, {b}) with z = {want} is not among the refined points");
            checked += 1;
        }
    }
    assert!(checked >= 20, "only {checked} interior points compared");
}

#[test]
fn mesh_and_lattice_engines_agree_on_the_local_spectrum() {
    let scheme = schemes::build("khan-mustafa", &[]).unwrap();
    let km = schemes::registry::lattice("khan-mustafa", &[]).unwrap();
    for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
        let config = Configuration::regular(scheme.as_ref(), 4).unwrap();
        let mesh =
            analyse(scheme.as_ref(), &config, &Options { neighbourhood: kind, method: None, exact: false }).unwrap();
        let lat = lattice::analysis::analyse(km.as_ref(), kind, false).unwrap();
        assert_eq!(mesh.spectrum.matrix_size, lat.spectrum.matrix_size, "{kind:?}");
        let ev = |s: &subdlab::spectrum::Spectrum| -> Vec<(f64, f64, usize)> {
            s.eigenvalues.iter().map(|e| (e.re, e.im, e.algebraic_multiplicity)).collect()
        };
        let (a, b) = (ev(&mesh.spectrum), ev(&lat.spectrum));
        assert_eq!(a.len(), b.len(), "{kind:?}: {a:?} vs {b:?}");
        for (x, y) in a.iter().zip(&b) {
            assert!((x.0 - y.0).abs() < 1e-9 && (x.1 - y.1).abs() < 1e-9 && x.2 == y.2, "{kind:?}: {x:?} vs {y:?}");
        }
    }
}

#[test]
fn characteristic_map_is_linear_and_injective() {
    // the least-squares quadratic reproduces linear functions, so the
    // subdominant eigenvectors (1/2) are the coordinates: the map is linear,
    // every facet has the same area
    let out = subdlab(&["charmap", "khan-mustafa", "--valence", "4", "--levels", "3", "--resolution", "128", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["regular"], true);
    assert_eq!(v["injective"], true);
    assert!((v["min_jacobian_ratio"].as_f64().unwrap() - 1.0).abs() < 1e-9);
}

#[test]
fn refine_needs_a_regular_closed_quad_lattice() {
    let dir = tempfile::tempdir().unwrap();
    let o = dir.path().join("o.obj");
    let err =
        fails(&["refine", "meshes/cube.obj", "--scheme", "khan-mustafa", "--levels", "1", "-o", o.to_str().unwrap()]);
    assert!(err.contains("valence 4"), "{err}");
    let out = subdlab(&[
        "refine",
        "meshes/torus-grid.obj",
        "--scheme",
        "khan-mustafa",
        "--levels",
        "2",
        "-o",
        o.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}
