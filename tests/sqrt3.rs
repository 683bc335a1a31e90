//! sqrt(3) subdivision: Kobbelt's scheme and the Lin–Luo unified scheme.
//!
//! Closed form for Kobbelt's two-step matrix on the one-ring (derived in the
//! comments, independent of the code): one step maps the neighbours p_j to face
//! points c_j = (v + p_j + p_{j+1})/3, the second to d_j = (v' + c_j + c_{j+1})/3,
//! which lies on the ray of p_{j+1}. In Fourier block m ≠ 0 (v = 0):
//! d̂ = (1 + ω^m)^2 / 9 p̂, and relabelling d_j as p_{j+1} multiplies by ω^{-m}:
//! λ_m = ω^{-m} (1 + ω^m)^2 / 9 = (2 + 2 cos(2πm/n)) / 9.
//! Block 0 of one step is [[1 − β, β], [1/3, 2/3]] with eigenvalues 1 and
//! 2/3 − β = (2 + 2 cos(2π/n))/9 for Kobbelt's β = (4 − 2 cos(2π/n))/9, so the
//! two-step block 0 has 1 and λ_1^2.

use crate::common;
use common::*;
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::schemes;

#[test]
fn kobbelt_one_ring_two_step_spectrum_for_valences_3_to_30() {
    for n in 3..=30 {
        let a = run("sqrt3", n, NeighbourhoodKind::Minimal, None, false);
        assert_eq!(a.spectrum.matrix_size, n + 1);
        let l = |m: usize| (2.0 + 2.0 * cos2pi(m, n)) / 9.0;
        let mut want = vec![1.0, l(1) * l(1)];
        want.extend((1..n).map(l));
        assert_same_multiset(real_spectrum(&a), want, 1e-12, &format!("sqrt3 n={n}"));
        assert!((a.spectrum.verdict.subdominant.unwrap() - l(1)).abs() < 1e-12);
    }
}

#[test]
fn unified_rules_at_alpha_zero_are_kobbelts_rules() {
    // Kobbelt's rules (1) and (2), typed from the paper, against the unified
    // scheme's stencils at α = 0 on every interior vertex and face of a patch.
    use subdlab::neighbourhood::build_patch;
    use subdlab::refine::Origin;
    use subdlab::schemes::SchemeWeight;
    let s = schemes::build("unified-sqrt3", &[("alpha".into(), "0".into())]).unwrap();
    for n in [3, 5, 7] {
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let (mesh, _) = build_patch(&config, 3);
        let mut checked = 0;
        for v in 0..mesh.num_vertices() {
            let Some(fan) = mesh.vertex_fan(v) else { continue };
            let k = fan.len();
            let beta = (4.0 - 2.0 * cos2pi(1, k)) / 9.0;
            let st = <f64 as SchemeWeight>::stencil(s.as_ref(), &mesh, Origin::Vertex(v)).unwrap().unwrap();
            for (u, w) in &st.terms {
                let want = if *u == v { 1.0 - beta } else { beta / k as f64 };
                assert!((w - want).abs() < 1e-15);
            }
            assert_eq!(st.terms.len(), k + 1);
            checked += 1;
        }
        for f in 0..mesh.num_faces() {
            // the face rule needs the corners' one-rings: only interior faces
            if mesh.face(f).iter().any(|&c| mesh.vertex_fan(c).is_none()) {
                continue;
            }
            let st = <f64 as SchemeWeight>::stencil(s.as_ref(), &mesh, Origin::Face(f)).unwrap().unwrap();
            assert_eq!(st.terms.len(), 3);
            assert!(st.terms.iter().all(|(u, w)| mesh.face(f).contains(u) && (w - 1.0 / 3.0).abs() < 1e-15));
            checked += 1;
        }
        assert!(checked > 3 * n);
    }
}

#[test]
fn interpolatory_variant_keeps_the_centre() {
    // α = 1: old vertices are not moved, so the centre's row is the unit row
    // and the minimal invariant set is the centre alone
    for n in [3, 5, 6, 9] {
        let a = run("unified-sqrt3", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.matrix.labels[0].name, "centre");
        assert_eq!(a.matrix.rows[0].len(), 1);
        assert_eq!(a.matrix.rows[0][0].0, 0);
        assert!((a.matrix.rows[0][0].1 - 1.0).abs() < 1e-15);
        assert_eq!(a.spectrum.minimal_size, 1);
    }
}

#[test]
fn regular_valence_kobbelt_is_rational_and_exactly_confirmed() {
    let a = run("sqrt3", 6, NeighbourhoodKind::Minimal, None, true);
    let x = a.spectrum.exact_analysis.as_ref().unwrap();
    // λ_m = (2 + 2cos(2πm/6))/9: 1/3 (m=1,5), 1/9 (m=2,4), 0 (m=3); block 0: 1, 1/9
    let mult = |v: &str| x.rational_roots.iter().find(|r| r.value == v).map(|r| r.algebraic_multiplicity);
    assert_eq!((mult("1"), mult("1/3"), mult("1/9"), mult("0")), (Some(1), Some(2), Some(3), Some(1)));
    assert_eq!(x.remaining_degree, 0);
}

/// The unified rules at α ≠ 0 against the paper's expanded equations, typed
/// from the text (Lin–Luo section 5), on every interior vertex and face of a
/// patch with a centre of valence n (c_P = cos(2π/k_P), k_P the valence of P,
/// avg(P) the mean of P's neighbours):
/// - old vertex, eq. (11) expanded:
///   q' = (5 + 4α + 2(1 − α)c)/9 q + (1 − α)(4 − 2c)/9 avg(q);
/// - new vertex of triangle (P_i, P_j, P_k), eqs. (8), (10):
///   q = Σ_P [(9 + 4α − 2αc_P)/27 P − (4α − 2αc_P)/27 avg(P)].
///
/// Three REFUTED Lin–Luo verdicts rest on these rules at α = 1, 3/2 and 2.
#[test]
fn unified_rules_at_alpha_nonzero_are_the_papers_expanded_equations() {
    use std::collections::BTreeMap;
    use subdlab::neighbourhood::build_patch;
    use subdlab::refine::Origin;
    use subdlab::schemes::SchemeWeight;
    for alpha_text in ["1/2", "1", "3/2", "2"] {
        let (p, q) = alpha_text.split_once('/').unwrap_or((alpha_text, "1"));
        let alpha = p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap();
        let s = schemes::build("unified-sqrt3", &[("alpha".into(), alpha_text.into())]).unwrap();
        for n in [3, 5, 7] {
            let config = Configuration::regular(s.as_ref(), n).unwrap();
            let (mesh, _) = build_patch(&config, 3);
            let ring = |v: usize| mesh.uniform_ring(v, 3);
            let collect = |terms: &[(usize, f64)]| {
                let mut m: BTreeMap<usize, f64> = BTreeMap::new();
                for (u, w) in terms {
                    *m.entry(*u).or_default() += w;
                }
                m
            };
            let same = |got: &BTreeMap<usize, f64>, want: &BTreeMap<usize, f64>, what: &str| {
                let keys: std::collections::BTreeSet<usize> = got.keys().chain(want.keys()).copied().collect();
                for k in keys {
                    let (g, w) = (got.get(&k).copied().unwrap_or(0.0), want.get(&k).copied().unwrap_or(0.0));
                    assert!((g - w).abs() < 1e-14, "α = {alpha_text}, n = {n}, {what}: vertex {k}: {g} vs {w}");
                }
            };
            let mut checked = 0;
            for v in 0..mesh.num_vertices() {
                let Some(nb) = ring(v) else { continue };
                let k = nb.len();
                let c = cos2pi(1, k);
                let mut want = BTreeMap::new();
                want.insert(v, (5.0 + 4.0 * alpha + 2.0 * (1.0 - alpha) * c) / 9.0);
                for &u in &nb {
                    *want.entry(u).or_insert(0.0) += (1.0 - alpha) * (4.0 - 2.0 * c) / 9.0 / k as f64;
                }
                let st = <f64 as SchemeWeight>::stencil(s.as_ref(), &mesh, Origin::Vertex(v)).unwrap().unwrap();
                same(&collect(&st.terms), &want, "vertex rule (11)");
                checked += 1;
            }
            for f in 0..mesh.num_faces() {
                let corners = mesh.face(f).to_vec();
                let rings: Option<Vec<Vec<usize>>> = corners.iter().map(|&c| ring(c)).collect();
                let Some(rings) = rings else { continue };
                let mut want = BTreeMap::new();
                for (&p, nb) in corners.iter().zip(&rings) {
                    let k = nb.len();
                    let c = cos2pi(1, k);
                    *want.entry(p).or_insert(0.0) += (9.0 + 4.0 * alpha - 2.0 * alpha * c) / 27.0;
                    for &u in nb {
                        *want.entry(u).or_insert(0.0) -= (4.0 * alpha - 2.0 * alpha * c) / 27.0 / k as f64;
                    }
                }
                let st = <f64 as SchemeWeight>::stencil(s.as_ref(), &mesh, Origin::Face(f)).unwrap().unwrap();
                same(&collect(&st.terms), &want, "face rule (8), (10)");
                checked += 1;
            }
            assert!(checked > 3 * n, "α = {alpha_text}, n = {n}: {checked} rules checked");
        }
    }
}
