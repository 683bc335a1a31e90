//! Catmull–Clark against closed forms from the literature:
//! - block m ≠ 0 of the 2n+1 matrix: λ = (5 + c ± sqrt((c+1)(c+9)))/16, c = cos(2πm/n)
//!   (Doo–Sabin 1978, Ball–Storry 1988; the subdominant λ1 is the m = 1 "+" root);
//! - block 0: the 3×3 matrix of the vertex/edge/face rules averaged over sectors;
//! - limit stencil n/(n+5), 4/(n(n+5)) per edge neighbour, 1/(n(n+5)) per face
//!   neighbour (Halstead, Kass, DeRose 1993);
//! - tangent stencils spanned by A_n cos(2πi/n) e_i + (cos(2πi/n) + cos(2π(i+1)/n)) f_i
//!   and the sine analogue, A_n = 1 + cos(2π/n) + cos(π/n) sqrt(2(9 + cos(2π/n)));
//! - valence 4: the tensor product of the cubic B-spline's {1, 1/2, 1/4, 1/8, 1/8}.

use approx::assert_abs_diff_eq;
mod common;
use common::*;
use subdlab::neighbourhood::{NeighbourhoodKind, VertexKind};
use subdlab::spectrum::stencils::{limit_stencil, tangent_stencils};

fn block0_closed_form(n: f64) -> Vec<f64> {
    // v' = (1 - 7/(4n)) v + 3/(2n) ê + 1/(4n) f̂ ; ê' = (6v + 8ê + 2f̂)/16 ; f̂' = (v + 2ê + f̂)/4
    let m =
        [[1.0 - 7.0 / (4.0 * n), 3.0 / (2.0 * n), 1.0 / (4.0 * n)], [6.0 / 16.0, 0.5, 2.0 / 16.0], [0.25, 0.5, 0.25]];
    let trace = m[0][0] + m[1][1] + m[2][2];
    let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    // 1 is an eigenvalue (rows sum to 1): the others solve x^2 - (trace-1) x + det = 0
    let (s, p) = (trace - 1.0, det);
    let disc = (s * s - 4.0 * p).sqrt();
    vec![1.0, (s + disc) / 2.0, (s - disc) / 2.0]
}

#[test]
fn minimal_spectrum_matches_closed_forms_for_valences_3_to_50() {
    for n in 3..=50 {
        let a = run("catmull-clark", n, NeighbourhoodKind::Minimal, None, false);
        assert_eq!(a.spectrum.matrix_size, 2 * n + 1, "minimal invariant size at n = {n}");
        let mut want = block0_closed_form(n as f64);
        for m in 1..n {
            let c = cos2pi(m, n);
            let r = ((c + 1.0) * (c + 9.0)).sqrt();
            want.push((5.0 + c + r) / 16.0);
            want.push((5.0 + c - r) / 16.0);
        }
        assert_same_multiset(real_spectrum(&a), want, 1e-10, &format!("CC n={n}"));
        let c = cos2pi(1, n);
        let l1 = (5.0 + c + ((c + 1.0) * (c + 9.0)).sqrt()) / 16.0;
        let stam = (5.0 + c + (std::f64::consts::PI / n as f64).cos() * (2.0 * (9.0 + c)).sqrt()) / 16.0;
        assert_abs_diff_eq!(l1, stam, epsilon = 1e-14);
        assert_abs_diff_eq!(a.spectrum.verdict.subdominant.unwrap(), stam, epsilon = 1e-10);
        assert!(a.spectrum.verdict.c1_spectral, "CC passes the spectral test at n = {n}");
        let mut blocks = a.spectrum.verdict.subdominant_blocks.clone();
        blocks.dedup();
        assert_eq!(blocks, vec![1, n - 1], "subdominant pair from Fourier blocks 1 and n-1");
    }
}

#[test]
fn analysis_neighbourhood_is_the_two_ring_and_keeps_the_leading_spectrum() {
    for n in 3..=50 {
        let a = run("catmull-clark", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.spectrum.matrix_size, 6 * n + 1, "analysis size at n = {n}");
        assert_eq!(a.spectrum.minimal_size, 2 * n + 1);
        let c = cos2pi(1, n);
        let l1 = (5.0 + c + ((c + 1.0) * (c + 9.0)).sqrt()) / 16.0;
        assert_abs_diff_eq!(a.spectrum.eigenvalues[1].re, l1, epsilon = 1e-10);
        assert_eq!(a.spectrum.eigenvalues[1].algebraic_multiplicity, 2);
        // the outer ring only adds 1/8, 1/16, 1/32, 1/64 (powers of the regular B-spline rules)
        let minimal = run("catmull-clark", n, NeighbourhoodKind::Minimal, None, false);
        let mut extra = real_spectrum(&a);
        for x in real_spectrum(&minimal) {
            let k = extra.iter().position(|y| (y - x).abs() < 1e-9).expect("minimal spectrum is contained");
            extra.remove(k);
        }
        for x in extra {
            assert!(
                [0.125, 0.0625, 0.03125, 0.015625].iter().any(|p| (x - p).abs() < 1e-9),
                "extra eigenvalue {x} at n = {n}"
            );
        }
    }
}

#[test]
fn regular_valence_is_the_bicubic_tensor_product() {
    let a = run("catmull-clark", 4, NeighbourhoodKind::Analysis, None, true);
    let cubic = [1.0, 0.5, 0.25, 0.125, 0.125];
    assert_same_multiset(real_spectrum(&a), products(&cubic, &cubic), 1e-12, "CC n=4");
    // exact path proves it: every root rational, multiplicities as above
    let x = a.spectrum.exact_analysis.as_ref().unwrap();
    assert_eq!(x.remaining_degree, 0);
    assert!(x.agrees_with_float);
    let mult = |v: &str| x.rational_roots.iter().find(|r| r.value == v).unwrap().algebraic_multiplicity;
    assert_eq!(
        (mult("1"), mult("1/2"), mult("1/4"), mult("1/8"), mult("1/16"), mult("1/32"), mult("1/64")),
        (1, 2, 3, 6, 5, 4, 4)
    );
}

#[test]
fn limit_and_tangent_stencils_match_halstead_kass_derose() {
    for n in 3..=50 {
        let a = run("catmull-clark", n, NeighbourhoodKind::Analysis, None, false);
        let l = limit_stencil(&a.spectrum).unwrap();
        let nf = n as f64;
        let mut cos_form = vec![0.0; l.len()];
        let mut sin_form = vec![0.0; l.len()];
        let an = 1.0 + cos2pi(1, n) + (std::f64::consts::PI / nf).cos() * (2.0 * (9.0 + cos2pi(1, n))).sqrt();
        for (k, lab) in a.spectrum.labels.iter().enumerate() {
            let want = match (lab.kind, lab.ring) {
                (VertexKind::Centre, _) => nf / (nf + 5.0),
                (VertexKind::Edge, 1) => 4.0 / (nf * (nf + 5.0)),
                (VertexKind::Face, 1) => 1.0 / (nf * (nf + 5.0)),
                _ => 0.0,
            };
            assert!((l[k] - want).abs() < 1e-12, "limit weight of {} at n = {n}: {} vs {want}", lab.name, l[k]);
            let i = lab.sector;
            match (lab.kind, lab.ring) {
                (VertexKind::Edge, 1) => {
                    cos_form[k] = an * cos2pi(i, n);
                    sin_form[k] = an * sin2pi(i, n);
                }
                (VertexKind::Face, 1) => {
                    cos_form[k] = cos2pi(i, n) + cos2pi(i + 1, n);
                    sin_form[k] = sin2pi(i, n) + sin2pi(i + 1, n);
                }
                _ => {}
            }
        }
        let t = tangent_stencils(&a.spectrum).unwrap();
        assert_eq!(t.len(), 2);
        for v in &t {
            assert!(
                in_span(&[cos_form.clone(), sin_form.clone()], v),
                "tangent stencil off the closed form at n = {n}"
            );
        }
        assert!(in_span(&t, &cos_form) && in_span(&t, &sin_form), "tangent stencils span the closed form at n = {n}");
    }
}
