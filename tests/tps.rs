//! Primal bi-2 subdivision (TPS, Karčiauskas–Peters section 4) against values
//! derived here, independently of the code under test, and the paper's
//! statements checked one by one.
//!
//! 1-D ternary quadratic B-spline (mask (1,3,6,7,6,3,1)/9) on the 5 points
//! c_{-2..2} around a vertex: c'_0 = (c_{-1} + 7c_0 + c_1)/9,
//! c'_{±1} = (2c_0 + c_{±1})/3, c'_{±2} = (c_0 + 2c_{±1})/3. Antisymmetric
//! mode (1, 0, −1) on c_{-1..1}: λ = 1/3. Symmetric modes: u' = u/3 + 2v/3,
//! v' = 2u/9 + 7v/9 (u = c_{±1}, v = c_0): trace 10/9, det 1/9, so λ = 1, 1/9.
//! c_{±2} do not feed back: λ = 0 twice. Local spectrum {1, 1/3, 1/9, 0, 0}.
//!
//! Fourier blocks at valence n (q the centre, a_i edge, b_i diagonal
//! neighbours, ring 2 points c..f depend only on q, a, b): block k ≠ 0 on
//! (â, b̂): â' = (7 + 4 c_k)/27 â + (1 + ω)/27 b̂, b̂' = 2(1 + ω̄)/9 â + b̂/9;
//! trace (10 + 4c_k)/27, det (7 + 4c_k)/243 − 2|1+ω|²/243 = 3/243 = 1/81,
//! which is the paper's eq. (20). Block 0 on (q, ā, b̄):
//! q' = (1−α1−α2) q + α1 ā + α2 b̄, ā' = (14 q + 11 ā + 2 b̄)/27,
//! b̄' = (4q + 4ā + b̄)/9: trace 1 − α1 − α2 + 14/27, eigenvalue 1.

use crate::common;
use common::*;
use subdlab::mesh::obj::parse_obj;
use subdlab::neighbourhood::{NeighbourhoodKind, VertexKind};
use subdlab::refine::mesh::refine_mesh;
use subdlab::spectrum::stencils::limit_stencil;

fn alpha1(n: usize) -> f64 {
    if n == 3 {
        339.0 / 896.0
    } else {
        7.0 * n as f64 / ((2 * n + 1) * (2 * n + 1)) as f64
    }
}

/// Real roots of λ² + bλ + c (panics on complex roots: none occur here).
fn roots(b: f64, c: f64) -> [f64; 2] {
    let d = b * b - 4.0 * c;
    assert!(d >= 0.0, "complex roots");
    [(-b + d.sqrt()) / 2.0, (-b - d.sqrt()) / 2.0]
}

/// The paper's D_0 (19) and D_k (20), evaluated from the printed formulas.
fn paper_spectrum(n: usize) -> Vec<f64> {
    let (a1, a2) = (alpha1(n), alpha1(n) / 7.0);
    let mut v = vec![1.0, 0.0, 0.0, 0.0, 0.0];
    v.extend(roots(a1 + a2 - 14.0 / 27.0, (1.0 - 3.0 * a1 + 3.0 * a2) / 81.0));
    for k in 1..n {
        v.extend([0.0; 5]);
        v.extend(roots(-2.0 / 27.0 * (5.0 + 2.0 * cos2pi(k, n)), 1.0 / 81.0));
    }
    v
}

fn paper_subdominant(c: f64) -> f64 {
    (5.0 + 2.0 * c + 2.0 * (c * c + 5.0 * c + 4.0).sqrt()) / 27.0
}

#[test]
fn regular_valence_is_the_ternary_biquadratic_tensor_product() {
    let a = run("tps", 4, NeighbourhoodKind::Analysis, None, true);
    let ternary = [1.0, 1.0 / 3.0, 1.0 / 9.0, 0.0, 0.0];
    assert_same_multiset(real_spectrum(&a), products(&ternary, &ternary), 1e-12, "TPS n=4");
    // every eigenvalue proven by the exact characteristic polynomial
    assert_eq!(a.spectrum.exact_analysis.as_ref().unwrap().remaining_degree, 0);
}

#[test]
fn neighbourhoods_are_the_q_net_of_depth_three() {
    // The paper's matrix is 7n × 7n with q/n replicated n times: 6n + 1
    // distinct points (q and a..f per sector); the minimal invariant set is
    // {q, a_i, b_i}, since (17)-(18) give a, b, q from q, a, b alone.
    for n in [3, 5, 6, 9] {
        let a = run("tps", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.spectrum.matrix_size, 6 * n + 1, "n = {n}");
        assert_eq!(a.spectrum.minimal_size, 2 * n + 1, "n = {n}");
        assert!(a.spectrum.labels.iter().all(|l| l.ring <= 2));
    }
}

#[test]
fn spectrum_is_the_union_of_the_roots_of_eqs_19_and_20() {
    // Paper's D_k have 7n roots in all; our matrix omits the n − 1 replicas
    // of q, each of which adds one zero root to a block k ≠ 0.
    for n in 3..=24 {
        let a = run("tps", n, NeighbourhoodKind::Analysis, None, false);
        let mut want = paper_spectrum(n);
        for _ in 0..n - 1 {
            let z = want.iter().position(|x| *x == 0.0).unwrap();
            want.remove(z);
        }
        assert_same_multiset(real_spectrum(&a), want, 1e-10, &format!("TPS n={n}"));
    }
}

#[test]
fn subdominant_eigenvalue_formula_and_c1_spectral_test() {
    // "the scheme is C^1 with subdominant eigenvalue λ from Â_1, Â_{n−1},
    //  λ = (5 + 2c + 2 sqrt(c² + 5c + 4))/27"
    for n in 3..=100 {
        let a = run("tps", n, NeighbourhoodKind::Analysis, None, false);
        let v = &a.spectrum.verdict;
        assert!(v.c1_spectral, "n = {n}: {:?}", v.reasons);
        assert!((v.subdominant.unwrap() - paper_subdominant(cos2pi(1, n))).abs() < 1e-12, "n = {n}");
        let e = &a.spectrum.eigenvalues[1];
        assert_eq!(e.algebraic_multiplicity, 2, "n = {n}");
        assert!(e.blocks.contains(&1) && e.blocks.contains(&(n - 1)), "n = {n}: blocks {:?}", e.blocks);
    }
}

/// The largest eigenvalue modulus below the subdominant one.
fn subsubdominant(a: &subdlab::spectrum::Analysis) -> f64 {
    let l1 = a.spectrum.verdict.subdominant.unwrap();
    a.spectrum.eigenvalues.iter().map(|e| e.modulus).filter(|m| *m < l1 - 1e-9).fold(0.0, f64::max)
}

#[test]
fn nu_3_is_the_larger_root_of_d0_about_0_082() {
    let a = run("tps", 3, NeighbourhoodKind::Analysis, None, false);
    let (a1, a2) = (339.0 / 896.0, 339.0 / 6272.0);
    let r = roots(a1 + a2 - 14.0 / 27.0, (1.0 - 3.0 * a1 + 3.0 * a2) / 81.0)[0];
    let nu = subsubdominant(&a);
    assert!((nu - r).abs() < 1e-12);
    assert!((nu - 0.082).abs() < 5e-4, "printed .082, got {nu}");
}

#[test]
fn nu_n_needs_c2_equal_cos_4pi_over_n_not_the_printed_cos_pi_over_n() {
    // Printed: ν_n = (5 + 2c_2 + 2 sqrt(c_2² + 5c_2 + 4))/27 with c_2 := cos(π/n).
    // That value exceeds the subdominant eigenvalue (cos(π/n) > cos(2π/n)),
    // so it cannot be the subsubdominant one. With c_2 = cos(2π·2/n) (block 2,
    // the notation c_k of eq. (20)) the statement holds for n ≥ 5.
    for n in 5..=40 {
        let a = run("tps", n, NeighbourhoodKind::Analysis, None, false);
        let nu = subsubdominant(&a);
        assert!((nu - paper_subdominant(cos2pi(2, n))).abs() < 1e-12, "n = {n}");
        let printed = paper_subdominant((std::f64::consts::PI / n as f64).cos());
        assert!(printed > a.spectrum.verdict.subdominant.unwrap(), "n = {n}");
    }
}

#[test]
fn limit_point_is_eq_21() {
    // τ1 = 18(2α1 + α2)/(39α1 + 42α2 + 20), τ2 = 3(α1 + 8α2)/(39α1 + 42α2 + 20);
    // re-derived from the left eigenvector of block 0 (module comment):
    // with l_q = 1, 16 l_a − 12 l_b = 27 α1 and −2 l_a + 24 l_b = 27 α2.
    for n in 3..=20 {
        let a = run("tps", n, NeighbourhoodKind::Analysis, None, false);
        let (a1, a2) = (alpha1(n), alpha1(n) / 7.0);
        let den = 39.0 * a1 + 42.0 * a2 + 20.0;
        let (t1, t2) = (18.0 * (2.0 * a1 + a2) / den, 3.0 * (a1 + 8.0 * a2) / den);
        let la = 9.0 * (2.0 * a1 + a2) / 10.0;
        let lb = 3.0 * (a1 + 8.0 * a2) / 20.0;
        assert!((t1 - la / (1.0 + la + lb)).abs() < 1e-14 && (t2 - lb / (1.0 + la + lb)).abs() < 1e-14);
        let l = limit_stencil(&a.spectrum).unwrap();
        for (k, lab) in a.spectrum.labels.iter().enumerate() {
            let want = match (lab.kind, lab.ring) {
                (VertexKind::Centre, _) => 1.0 - t1 - t2,
                (VertexKind::Edge, 1) => t1 / n as f64,
                (VertexKind::Face, 1) => t2 / n as f64,
                _ => 0.0,
            };
            assert!((l[k] - want).abs() < 1e-12, "n = {n}, {}: {} vs {want}", lab.name, l[k]);
        }
    }
}

#[test]
fn refines_closed_quad_meshes_and_refuses_triangles() {
    for (file, faces) in [("meshes/cube.obj", 6), ("meshes/mixed-quads.obj", 36)] {
        let text = std::fs::read_to_string(file).unwrap();
        let (m, points) = parse_obj(&text).unwrap();
        let s = scheme("tps");
        let (mesh, pts) = refine_mesh(s.as_ref(), &m, &points, 2).unwrap();
        assert_eq!(mesh.num_faces(), 81 * faces, "{file}");
        assert!(mesh.faces().iter().all(|f| f.len() == 4));
        // refinement is an affine combination: the result stays inside the input's bounding box
        for d in 0..3 {
            let lo = points.iter().map(|p| p[d]).fold(f64::INFINITY, f64::min);
            let hi = points.iter().map(|p| p[d]).fold(f64::NEG_INFINITY, f64::max);
            assert!(pts.iter().all(|p| p[d] >= lo - 1e-12 && p[d] <= hi + 1e-12), "{file}");
        }
    }
    let text = std::fs::read_to_string("meshes/octahedron.obj").unwrap();
    let (m, points) = parse_obj(&text).unwrap();
    let err = refine_mesh(scheme("tps").as_ref(), &m, &points, 1).unwrap_err().to_string();
    assert!(err.contains("quad mesh"), "{err}");
}

// ---------------------------------------------------------------------------
// Adjustable TPS (section 4.1). The paper prints no rules, only eq. (22); the
// scheme's rules are reconstructed from (22) (see src/schemes/tps.rs), so
// agreement with (22) checks the reconstruction and its implementation, not
// the paper. What is checked against the paper: (22) at e = 1/3 is the TPS
// formula, and the limit point coincides with TPS's (its choice of α1, α2).

fn adjustable(e: f64, n: usize) -> subdlab::spectrum::Analysis {
    use subdlab::neighbourhood::Configuration;
    use subdlab::spectrum::{analyse, Options};
    let s = subdlab::schemes::build("tps", &[("e".into(), format!("{e}"))]).unwrap();
    let config = Configuration::regular(s.as_ref(), n).unwrap();
    analyse(s.as_ref(), &config, &Options { exact: false, ..Options::default() }).unwrap()
}

fn eq_22(e: f64, c: f64) -> f64 {
    (1.0 - 2.0 * e)
        * (e * e * (1.0 + 2.0 * c)
            + (1.0 - e) * (1.0 - e)
            + 2.0 * e * ((c + 1.0) * (e * e * c + (1.0 - e) * (1.0 - e))).sqrt())
}

#[test]
fn eq_22_at_one_third_is_the_tps_subdominant_eigenvalue() {
    for n in 3..=100 {
        let c = cos2pi(1, n);
        assert!((eq_22(1.0 / 3.0, c) - paper_subdominant(c)).abs() < 1e-14, "n = {n}");
    }
    assert_registry_verdict("tps.adjustable-e-third", subdlab::claims::Verdict::Holds);
}

#[test]
fn adjustable_blocks_k_reproduce_eq_22() {
    for e in [0.1, 0.2, 0.25, 0.4] {
        for n in 5..=30 {
            let a = adjustable(e, n);
            let sub = a.spectrum.verdict.subdominant.unwrap();
            assert!((sub - eq_22(e, cos2pi(1, n))).abs() < 1e-12, "e = {e}, n = {n}");
            assert!(a.spectrum.verdict.c1_spectral, "e = {e}, n = {n}: {:?}", a.spectrum.verdict.reasons);
        }
    }
}

#[test]
fn adjustable_regular_valence_is_a_tensor_product() {
    // 1-D rules (module comment of src/schemes/tps.rs): c'_{±1} = 2e c_0 + (1−2e) c_{±1},
    // c'_0 = e(1−2e)(c_{-1} + c_1) + (1 − 2e(1−2e)) c_0. Antisymmetric mode: 1 − 2e;
    // symmetric: trace (1 − 2e) + 1 − 2e(1 − 2e), one root 1, the other (1 − 2e)²;
    // the two outer points add 0, 0. At e = 1/5: {1, 3/5, 9/25, 0, 0}.
    use subdlab::neighbourhood::Configuration;
    use subdlab::spectrum::{analyse, Options};
    let s = subdlab::schemes::build("tps", &[("e".into(), "1/5".into())]).unwrap();
    let config = Configuration::regular(s.as_ref(), 4).unwrap();
    let a = analyse(s.as_ref(), &config, &Options::default()).unwrap();
    let one_d = [1.0, 0.6, 0.36, 0.0, 0.0];
    assert_same_multiset(real_spectrum(&a), products(&one_d, &one_d), 1e-12, "adjustable n=4");
    assert_eq!(a.spectrum.exact_analysis.as_ref().unwrap().remaining_degree, 0);
}

#[test]
fn adjustable_limit_point_coincides_with_tps() {
    for e in [0.15, 0.2, 0.3, 0.45] {
        for n in [3, 5, 6, 9] {
            let (a1, a2) = (alpha1(n), alpha1(n) / 7.0);
            let den = 39.0 * a1 + 42.0 * a2 + 20.0;
            let (t1, t2) = (18.0 * (2.0 * a1 + a2) / den, 3.0 * (a1 + 8.0 * a2) / den);
            let a = adjustable(e, n);
            let l = limit_stencil(&a.spectrum).unwrap();
            for (k, lab) in a.spectrum.labels.iter().enumerate() {
                let want = match (lab.kind, lab.ring) {
                    (VertexKind::Centre, _) => 1.0 - t1 - t2,
                    (VertexKind::Edge, 1) => t1 / n as f64,
                    (VertexKind::Face, 1) => t2 / n as f64,
                    _ => 0.0,
                };
                assert!((l[k] - want).abs() < 1e-12, "e = {e}, n = {n}, {}", lab.name);
            }
        }
    }
}

#[test]
fn adjustable_valence_3_fails_the_spectral_test_for_slow_splits() {
    // With the limit point tied to TPS's, block 0 at n = 3 is computed here
    // from its 3 × 3 matrix on (q, ā, b̄): its second eigenvalue is the larger
    // root of λ² − (tr − 1)λ + det, and for e = 1/5 it exceeds eq. (22).
    let (e, n) = (0.2, 3);
    let (near, far) = (2.0 * e, 1.0 - 2.0 * e);
    let v1 = e * far;
    let v0 = 1.0 - 2.0 * v1;
    let (a10, a20) = (alpha1(n), alpha1(n) / 7.0);
    let (la, lb) = (0.9 * (2.0 * a10 + a20), 0.15 * (a10 + 8.0 * a20));
    let (sq, aa, ab) = (near * v0, far * v0 + 2.0 * near * v1, 2.0 * far * v1);
    let (tq, ba, bb) = (near * near, 2.0 * near * far, far * far);
    // (1, la, lb) must be a left eigenvector for 1: solve the ā and b̄ columns
    let a1 = la * (1.0 - aa) - lb * ba;
    let a2 = lb * (1.0 - bb) - la * ab;
    let m = [[1.0 - a1 - a2, a1, a2], [sq, aa, ab], [tq, ba, bb]];
    let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    let tr = m[0][0] + m[1][1] + m[2][2];
    let r = roots(-(tr - 1.0), det)[0];
    assert!(r > eq_22(e, cos2pi(1, n)));
    let a = adjustable(e, n);
    assert!(!a.spectrum.verdict.c1_spectral);
    assert!((a.spectrum.eigenvalues[1].re - r).abs() < 1e-12);
    assert_eq!(a.spectrum.eigenvalues[1].blocks, vec![0]);
}
