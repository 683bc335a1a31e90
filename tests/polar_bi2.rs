//! Polar bi-2 subdivision (PolBS, Karčiauskas–Peters section 3) against
//! values derived here, independently of the code under test, and the
//! paper's statements checked one by one.
//!
//! Net: pole p, spoke points a_i, b_i, c_i (rings 1..3). Rules: b_i' =
//! 3/4 a_i + 1/4 b_i, c_i' = 1/4 a_i + 3/4 b_i, a_i' = (1 − β) p + Σ γ_j a_{i+j},
//! p' = (1 − α) p + α ā. Fourier mode k on (a, b, c): a' = γ̂_k a (k ≠ 0),
//! b' = 3/4 a + 1/4 b, c' = 1/4 a + 3/4 b: lower triangular, eigenvalues
//! γ̂_k, 1/4, 0. Block 0 on (p, ā, b̄, c̄): [[1 − α, α], [1 − β, β]] on (p, ā)
//! gives 1 and β − α; then 1/4 and 0.
//!
//! Defectiveness (not stated in the paper): with α = 1/4, β = 1/2, block 0 has
//! 1/4 twice. An eigenvector for 1/4 with ā ≠ 0 would need b̄: 1/4 b̄ = 3/4 ā +
//! 1/4 b̄, impossible; with ā = 0 the (p, ā) part forces p = 0. So only
//! (0, 0, 1, 3) remains: 1/4 is a 2 × 2 Jordan block in block 0.

use crate::common;
use common::*;
use subdlab::mesh::PolyMesh;
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind, VertexKind};
use subdlab::refine::mesh::refine_mesh;
use subdlab::schemes;
use subdlab::spectrum::stencils::limit_stencil;
use subdlab::spectrum::{analyse, Options};

/// γ_j of eq. (15), evaluated here.
fn gamma(j: usize, n: usize) -> f64 {
    (0.5 + cos2pi(j, n)) / n as f64
}

/// γ̂_k of eq. (14) from the γ_j.
fn gamma_hat(k: usize, n: usize) -> f64 {
    (0..n).map(|j| gamma(j, n) * cos2pi(k * j % n, n)).sum()
}

#[test]
fn eq_15_gives_the_prescribed_gamma_hat_and_beta_one_half() {
    for n in 3..=60 {
        let beta: f64 = (0..n).map(|j| gamma(j, n)).sum();
        assert!((beta - 0.5).abs() < 1e-13 && (gamma_hat(0, n) - 0.5).abs() < 1e-13, "n = {n}");
        for k in 1..n {
            let want = if k == 1 || k == n - 1 { 0.5 } else { 0.0 };
            assert!((gamma_hat(k, n) - want).abs() < 1e-13, "n = {n}, k = {k}");
        }
    }
    assert_registry_verdict("polar.gamma", subdlab::claims::Verdict::Holds);
    assert_registry_verdict("polar.beta", subdlab::claims::Verdict::Holds);
}

#[test]
fn neighbourhoods_are_the_pole_and_the_net_of_depth_three() {
    // the paper's 4n × 4n matrix replicates p n times: 3n + 1 distinct points
    for n in [3, 4, 7, 12] {
        let a = run("polar-bi2", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.spectrum.matrix_size, 3 * n + 1, "n = {n}");
        assert_eq!(a.spectrum.minimal_size, n + 1, "n = {n}: the pole and the a_i");
        assert!(a.spectrum.labels.iter().all(|l| l.ring <= 3));
    }
}

#[test]
fn spectrum_is_the_union_of_the_roots_of_eqs_13_and_14() {
    for n in 3..=30 {
        let beta: f64 = (0..n).map(|j| gamma(j, n)).sum();
        let alpha = 0.25;
        let mut want = vec![1.0, 0.25, 0.0, beta - alpha];
        for k in 1..n {
            // D_k = (λ − 1/4) λ² (λ − γ̂_k); one zero of each is the replica of p
            want.extend([0.25, 0.0, gamma_hat(k, n)]);
        }
        let a = run("polar-bi2", n, NeighbourhoodKind::Analysis, None, false);
        assert_same_multiset(real_spectrum(&a), want, 1e-7, &format!("PolBS n={n}"));
    }
}

#[test]
fn subdominant_one_half_subsubdominant_one_quarter_and_c1_spectral() {
    for n in 3..=40 {
        let a = run("polar-bi2", n, NeighbourhoodKind::Analysis, None, false);
        let v = &a.spectrum.verdict;
        assert!(v.c1_spectral, "n = {n}: {:?}", v.reasons);
        assert!((v.subdominant.unwrap() - 0.5).abs() < 1e-12);
        assert_eq!(a.spectrum.eigenvalues[1].algebraic_multiplicity, 2);
        assert!((a.spectrum.eigenvalues[2].modulus - 0.25).abs() < 1e-7, "n = {n}");
    }
}

#[test]
fn one_quarter_is_defective_in_block_zero() {
    // γ_j rational at n = 3, 4, 6: exact ranks give the geometric multiplicity
    for n in [3usize, 4, 6] {
        let a = run("polar-bi2", n, NeighbourhoodKind::Analysis, None, true);
        let e = a.spectrum.eigenvalues.iter().find(|e| e.exact.as_deref() == Some("1/4")).expect("1/4 proven");
        assert_eq!(e.algebraic_multiplicity, n + 1, "n = {n}: twice in block 0, once in every other block");
        assert_eq!(e.geometric_multiplicity, n, "n = {n}");
        assert!(e.defective);
    }
}

#[test]
fn limit_point_is_eq_16() {
    // left eigenvector of (p, ā) for 1: l_p α = l_a (1 − β), so with α = 1/4,
    // β = 1/2: l_a = l_p/2, eop = 2/3 p + 1/3 ā; b, c carry no weight.
    for n in 3..=20 {
        let a = run("polar-bi2", n, NeighbourhoodKind::Analysis, None, false);
        let l = limit_stencil(&a.spectrum).unwrap();
        for (k, lab) in a.spectrum.labels.iter().enumerate() {
            let want = match (lab.kind, lab.ring) {
                (VertexKind::Centre, _) => 2.0 / 3.0,
                (_, 1) => 1.0 / (3.0 * n as f64),
                _ => 0.0,
            };
            assert!((l[k] - want).abs() < 1e-12, "n = {n}, {}", lab.name);
        }
    }
}

#[test]
fn alpha_moves_the_block_zero_eigenvalue_and_the_limit_point() {
    // α = 1/8: β − α = 3/8 (exact at n = 4), eop = (1 − τ) p + τ ā with
    // τ = α/(1 − β + α) = 1/5
    let s = schemes::build("polar-bi2", &[("alpha".into(), "1/8".into())]).unwrap();
    let config = Configuration::regular(s.as_ref(), 4).unwrap();
    let a = analyse(s.as_ref(), &config, &Options::default()).unwrap();
    assert!(a.spectrum.eigenvalues.iter().any(|e| e.exact.as_deref() == Some("3/8")));
    let l = limit_stencil(&a.spectrum).unwrap();
    let centre = a.spectrum.labels.iter().position(|l| l.kind == VertexKind::Centre).unwrap();
    assert!((l[centre] - 0.8).abs() < 1e-12);
}

/// A polar sphere: poles N and S, `rings` rings of n spokes.
fn polar_sphere(n: usize, rings: usize) -> (PolyMesh, Vec<[f64; 3]>) {
    let mut pts = vec![[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
    let v = |r: usize, s: usize| 2 + r * n + s % n;
    for r in 0..rings {
        let phi = std::f64::consts::PI * (r + 1) as f64 / (rings + 1) as f64;
        for s in 0..n {
            let t = 2.0 * std::f64::consts::PI * s as f64 / n as f64;
            pts.push([phi.sin() * t.cos(), phi.sin() * t.sin(), phi.cos()]);
        }
    }
    let mut faces = Vec::new();
    for s in 0..n {
        faces.push(vec![0, v(0, s), v(0, s + 1)]);
        faces.push(vec![1, v(rings - 1, s + 1), v(rings - 1, s)]);
        for r in 0..rings - 1 {
            faces.push(vec![v(r, s), v(r + 1, s), v(r + 1, s + 1), v(r, s + 1)]);
        }
    }
    (PolyMesh::new(pts.len(), faces).unwrap(), pts)
}

#[test]
fn refines_a_closed_polar_net() {
    // R rings of n spokes: 2n triangles and n(R − 1) quads; a step turns R
    // rings into 2R (a spoke point next to each pole, two points per radial
    // edge), so after two steps R = 12: n(R + 1) faces, 2 + nR vertices.
    let n = 6;
    let (mesh, pts) = polar_sphere(n, 3);
    let (out, out_pts) = refine_mesh(scheme("polar-bi2").as_ref(), &mesh, &pts, 2).unwrap();
    assert_eq!(out.num_faces(), n * 13);
    assert_eq!(out.num_vertices(), 2 + n * 12);
    assert_eq!(out.faces().iter().filter(|f| f.len() == 3).count(), 2 * n);
    // the input is symmetric under z -> −z and so are the rules, so the
    // refined net must be too: its z coordinates sum to zero
    let z_sum: f64 = out_pts.iter().map(|p| p[2]).sum();
    assert!(z_sum.abs() < 1e-9, "mirror-symmetric input stays symmetric");
    // a Doo–Sabin or Catmull–Clark net is not polar
    let (cube, cube_pts) = subdlab::mesh::obj::parse_obj(&std::fs::read_to_string("meshes/cube.obj").unwrap()).unwrap();
    let err = refine_mesh(scheme("polar-bi2").as_ref(), &cube, &cube_pts, 1).unwrap_err();
    assert!(matches!(err, subdlab::error::Error::Input(_)), "{err:?}");
    let err = err.to_string();
    assert!(err.contains("not a polar net"), "{err}");
}
