//! Point-augmented bi-2 subdivision (PGS, Karčiauskas–Peters section 2)
//! against values derived here, independently of the code under test, and
//! the paper's statements checked one by one.
//!
//! Fourier blocks on the analysis neighbourhood {p} ∪ {a_i, b_i, c_i, d_i}
//! (the central n-gon's corners a_i and the ring of quads around it; b_i, d_i
//! the neighbours of a_i outside the n-gon, c_i opposite a_i in its diagonal quad):
//! * b_i' = (9a_i + 3a_{i−1} + 3b_i + d_{i−1})/16, d_i' = (9a_i + 3a_{i+1} + 3d_i + b_{i+1})/16,
//!   c_i' = (9a_i + 3b_i + 3d_i + c_i)/16: in mode k the (b, c, d) part is
//!   [[3, 0, ω̄], [3, 1, 3], [ω, 0, 3]]/16 with eigenvalues 1/16 (c alone) and
//!   3/16 ± |ω|/16 = 1/4, 1/8 — for every k;
//! * a_i depends on a and p only: eigenvalue w1 + 2w2 c_k in block k ≠ 0;
//! * block 0 on (p, ā): [[1 − α, α], [1 − ω, ω]] (ω = w1 + 2w2): trace
//!   1 − α + ω, determinant ω − α, eigenvalues 1 and ω − α.
//!
//! The paper's 10n × 10n matrix uses a larger net (9 points per sector plus
//! p replicated n times); its D_k of (5)-(6) add only zero roots to these.

use crate::common;
use common::*;
use subdlab::mesh::obj::parse_obj;
use subdlab::neighbourhood::{NeighbourhoodKind, VertexKind};
use subdlab::refine::mesh::refine_mesh;
use subdlab::spectrum::stencils::limit_stencil;

/// (μ_n, w1, w2, α) from eqs. (1), (8), (9), (10), evaluated here in f64.
fn weights(n: usize) -> (f64, f64, f64, f64) {
    let c = cos2pi(1, n);
    let b = [0.5, 0.5519, 0.5985, 0.64367];
    let binom = [1.0, 3.0, 3.0, 1.0];
    let lambda: f64 = (0..4).map(|i| b[i] * binom[i] * (1.0 - c).powi(3 - i as i32) * c.powi(i as i32)).sum();
    let w1 = 2.0 * lambda / (2.0 + c);
    let w2 = w1 / 4.0;
    let mu = if n == 3 { 0.6 } else { 2.0 * (n as f64 - 2.0) / n as f64 };
    let alpha = 0.75 + mu * (w1 + 2.0 * w2 - 1.0);
    (mu, w1, w2, alpha)
}

fn lambda_sub(n: usize) -> f64 {
    let (_, w1, w2, _) = weights(n);
    w1 + 2.0 * w2 * cos2pi(1, n)
}

/// Non-zero roots of the paper's D_0 (5) and D_k (6), k = 1..n−1.
fn paper_nonzero_roots(n: usize) -> Vec<f64> {
    let (_, w1, w2, alpha) = weights(n);
    let d = [0.25, 0.125, 0.0625];
    let mut v = vec![1.0, w1 + 2.0 * w2 - alpha];
    v.extend(d);
    for k in 1..n {
        v.push(w1 + 2.0 * w2 * cos2pi(k, n));
        v.extend(d);
    }
    v
}

#[test]
fn neighbourhoods_are_p_with_the_n_gon_and_its_ring_of_quads() {
    for n in [3, 4, 5, 8] {
        let a = run("pgs", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.spectrum.matrix_size, 4 * n + 1, "n = {n}");
        assert_eq!(a.spectrum.minimal_size, n + 1, "n = {n}: p and the corners");
        assert_eq!(a.spectrum.labels.iter().filter(|l| l.kind == VertexKind::Centre).count(), 1);
    }
}

#[test]
fn regular_valence_is_doo_sabin_plus_the_decay_of_p() {
    // n = 4: μ = 1, λ_sub = b_0 = 1/2, w1 = 1/2, w2 = 1/8, α = 1/2; with
    // p = ā, eq. (4) is the biquadratic (9, 3, 3, 1)/16 rule. The 16 net points
    // carry Chaikin's {1, 1/2, 1/4, 1/4} squared; p − ā decays by ω − α = 1/4.
    let a = run("pgs", 4, NeighbourhoodKind::Analysis, None, true);
    let chaikin = [1.0, 0.5, 0.25, 0.25];
    let mut want = products(&chaikin, &chaikin);
    want.push(0.25);
    assert_same_multiset(real_spectrum(&a), want, 1e-12, "PGS n=4");
    assert_eq!(a.spectrum.exact_analysis.as_ref().unwrap().remaining_degree, 0);
}

#[test]
fn nonzero_spectrum_is_that_of_eqs_5_and_6() {
    for n in 3..=30 {
        let a = run("pgs", n, NeighbourhoodKind::Analysis, None, false);
        let got: Vec<f64> = real_spectrum(&a).into_iter().filter(|x| x.abs() > 1e-12).collect();
        assert_same_multiset(got, paper_nonzero_roots(n), 1e-10, &format!("PGS n={n}"));
    }
}

#[test]
fn exact_spectrum_at_valences_3_and_6() {
    // cos(2π/n) is rational at n = 3, 6, so every weight is: the exact path
    // proves the rational roots 1, 1/4, 1/8, 1/16 with their multiplicities n, n, n (+1 for 1).
    for n in [3usize, 6] {
        let a = run("pgs", n, NeighbourhoodKind::Analysis, None, true);
        let ex = a.spectrum.exact_analysis.as_ref().expect("rational weights");
        let mult = |s: &str| {
            a.spectrum.eigenvalues.iter().find(|e| e.exact.as_deref() == Some(s)).map(|e| e.algebraic_multiplicity)
        };
        assert_eq!(mult("1"), Some(1), "n = {n}");
        assert_eq!(mult("1/8"), Some(n), "n = {n}");
        assert_eq!(mult("1/16"), Some(n), "n = {n}");
        assert!(ex.remaining_degree <= n + 1, "n = {n}");
    }
}

#[test]
fn subdominant_is_lambda_sub_of_eq_10_and_exceeds_one_half_for_n_above_4() {
    for n in 3..=40 {
        let a = run("pgs", n, NeighbourhoodKind::Analysis, None, false);
        let v = &a.spectrum.verdict;
        assert!(v.c1_spectral, "n = {n}: {:?}", v.reasons);
        assert!((v.subdominant.unwrap() - lambda_sub(n)).abs() < 1e-12, "n = {n}");
        assert!(a.spectrum.eigenvalues[1].blocks == vec![1, n - 1] || n == 3, "n = {n}");
        if n > 4 {
            assert!(lambda_sub(n) > 0.5, "n = {n}");
        }
    }
}

fn subsubdominant(a: &subdlab::spectrum::Analysis) -> f64 {
    let l1 = a.spectrum.verdict.subdominant.unwrap();
    a.spectrum.eigenvalues.iter().map(|e| e.modulus).filter(|m| *m < l1 - 1e-9).fold(0.0, f64::max)
}

#[test]
fn subsubdominant_nu_n_statements() {
    // ν_3 = 1/4; ν_5, ν_6 = w1 + 2w2 − α (root of D_0); n > 6: w1 + 2w2 c_2 (root of D_2)
    let a = run("pgs", 3, NeighbourhoodKind::Analysis, None, false);
    assert!((subsubdominant(&a) - 0.25).abs() < 1e-12);
    for n in [5, 6] {
        let (_, w1, w2, alpha) = weights(n);
        let a = run("pgs", n, NeighbourhoodKind::Analysis, None, false);
        assert!((subsubdominant(&a) - (w1 + 2.0 * w2 - alpha)).abs() < 1e-12, "n = {n}");
    }
    for n in 7..=40 {
        let (_, w1, w2, _) = weights(n);
        let a = run("pgs", n, NeighbourhoodKind::Analysis, None, false);
        assert!((subsubdominant(&a) - (w1 + 2.0 * w2 * cos2pi(2, n))).abs() < 1e-12, "n = {n}");
    }
}

#[test]
fn limit_point_is_eq_7() {
    // left eigenvector of block 0 for 1: l_p α = l_a (1 − ω), so
    // τ = l_a/(l_p + l_a) = α/(1 + α − ω); eop = (1 − τ) p + τ ā.
    for n in 3..=20 {
        let (_, w1, w2, alpha) = weights(n);
        let tau = alpha / (1.0 + alpha - w1 - 2.0 * w2);
        let a = run("pgs", n, NeighbourhoodKind::Analysis, None, false);
        let l = limit_stencil(&a.spectrum).unwrap();
        for (k, lab) in a.spectrum.labels.iter().enumerate() {
            let want = match lab.kind {
                VertexKind::Centre => 1.0 - tau,
                VertexKind::Corner => tau / n as f64,
                _ => 0.0,
            };
            assert!((l[k] - want).abs() < 1e-12, "n = {n}, {}", lab.name);
        }
    }
}

#[test]
fn alpha_of_eq_8_makes_eq_3_a_convex_combination() {
    for n in 3..=1000 {
        let (_, _, _, alpha) = weights(n);
        assert!(alpha > 0.0 && alpha < 1.0, "n = {n}: α = {alpha}");
    }
    assert_registry_verdict("pgs.alpha-convex-lower", subdlab::claims::Verdict::Holds);
    assert_registry_verdict("pgs.alpha-convex-upper", subdlab::claims::Verdict::Holds);
}

#[test]
fn refines_doo_sabin_nets_and_adds_a_point_to_every_non_quad() {
    // one Doo–Sabin step turns the cube into a net with valence-4 vertices:
    // 6 F-quads, 12 E-quads and 8 triangular V-faces
    let (cube, points) = parse_obj(&std::fs::read_to_string("meshes/cube.obj").unwrap()).unwrap();
    let (net, net_pts) = refine_mesh(scheme("doo-sabin").as_ref(), &cube, &points, 1).unwrap();
    let (mesh, pts) = refine_mesh(scheme("pgs").as_ref(), &net, &net_pts, 2).unwrap();
    // a dual step makes F + E + V faces and one vertex per corner; all vertices
    // keep valence 4 (E = 2V). Net: F = 26, V = 24, E = 48, corners 96.
    // Step 1: 26 + 48 + 24 = 98 faces, V = 96, E = 192. Step 2: 98 + 192 + 96.
    assert_eq!(mesh.num_faces(), 98 + 192 + 96, "F-, E-, V-faces of two dual steps");
    let centres = mesh.face_points.iter().flatten().count();
    assert_eq!(centres, 8, "one point per triangle");
    assert_eq!(pts.len(), mesh.num_vertices());
    assert!(pts.iter().all(|p| p.iter().all(|x| x.is_finite())));
    // the cube's own vertices have valence 3: not a Doo–Sabin net
    let err = refine_mesh(scheme("pgs").as_ref(), &cube, &points, 1).unwrap_err().to_string();
    assert!(err.contains("valence 4"), "{err}");
}

#[test]
fn appendix_with_eq_8_the_rules_are_stationary() {
    // Appendix: with α of (8), the point carried by (3) equals eq. (1) applied
    // to the refined net at every level, so the map from a Doo–Sabin net to
    // the next one does not depend on the level. Checked on the refinement
    // itself: scalar data on a patch, p^0 from (1), three steps.
    use subdlab::neighbourhood::{build_patch, Configuration};
    use subdlab::refine::{apply, Stencil};
    use subdlab::schemes::SchemeWeight;
    for n in [3, 5, 7, 10] {
        let s = scheme("pgs");
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let (mut mesh, _) = build_patch(&config, 7);
        let (mu, ..) = weights(n);
        // eq. (1) on the central face (face 0) of a mesh with values x
        let eq1 = |mesh: &subdlab::mesh::PolyMesh, x: &[Option<[f64; 1]>]| -> f64 {
            let face = mesh.face(0);
            let (mut a, mut bd) = (0.0, 0.0);
            for (k, &v) in face.iter().enumerate() {
                a += x[v].unwrap()[0] / n as f64;
                let (prev, next) = (face[(k + n - 1) % n], face[(k + 1) % n]);
                for cyc in mesh.vertex_fan(v).unwrap() {
                    if cyc[1] != prev && cyc[1] != next {
                        bd += x[cyc[1]].unwrap()[0] / (2.0 * n as f64);
                    }
                }
            }
            mu * a + (1.0 - mu) * bd
        };
        // pseudo-random values (a fixed linear congruential sequence)
        let mut seed: u64 = 12345 + n as u64;
        let mut x: Vec<Option<[f64; 1]>> = (0..mesh.num_vertices())
            .map(|_| {
                seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                Some([(seed >> 11) as f64 / (1u64 << 53) as f64])
            })
            .collect();
        let p = mesh.face_point(0).unwrap();
        x[p] = Some([eq1(&mesh, &x)]);
        for level in 1..=3 {
            let r = s.topology().refine(&mesh).unwrap();
            let st: Vec<Option<Stencil<f64>>> = r
                .vertex_origins
                .iter()
                .map(|&o| <f64 as SchemeWeight>::stencil(s.as_ref(), &mesh, o).unwrap().ok())
                .collect();
            x = apply(st.iter().map(Option::as_ref), &x);
            mesh = r.mesh;
            let carried = x[mesh.face_point(0).unwrap()].unwrap()[0];
            assert!((carried - eq1(&mesh, &x)).abs() < 1e-13, "n = {n}, level {level}");
        }
    }
}
