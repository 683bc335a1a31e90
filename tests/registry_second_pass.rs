//! The claims added by the second pass over the five papers' statements
//! (issue 13), each reached by a derivation independent of the claim
//! machinery: hand-built matrices in exact rationals, closed forms derived in
//! the comments, tensor products of univariate rules, and (for the one
//! floating-point refutation) a second method and a second neighbourhood.

use crate::common;
use common::exact::{algebraic, q, rank, shifted, Mat};

use num_traits::{One, Zero};
use subdlab::claims::{builtin_files, evaluate, Outcome, Verdict};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::numeric::Rational;
use subdlab::schemes;
use subdlab::spectrum::{analyse, Method, Options};

fn verdict(paper: &str, id: &str, want: Verdict) -> Outcome {
    let o = common::registry_outcome_in(paper, id);
    assert_eq!(o.verdict, want, "{id}: {} / {} / {}", o.stated, o.computed, o.detail);
    assert_eq!(o.expected, Some(want), "{id}: the registry records the verdict found here");
    o
}

// ---------------------------------------------------------------- 4-3 transition node

/// The one-ring of the 4-3 transition node (QQTTT: quads in sectors 0 and 1,
/// sector s between the spokes e_s and e_{s+1}) in the order
/// v, e0, e1, e2, e3, e4, f0, f1 (f_s the quad diagonal of sector s). The set
/// is invariant: every rule below reads only these points. Rows from the
/// stencil table of ARCHITECTURE.md:
///   v'  = (18 v + 4 e1 + 3 (e0 + e2) + 2 (e3 + e4)) / 32        (transition vertex)
///   e0' = (6 (v + e0) + f0 + e1 + 2 e4) / 16                      (quad–triangle edge)
///   e1' = (6 (v + e1) + e0 + f0 + f1 + e2) / 16                   (quad edge)
///   e2' = (6 (v + e2) + f1 + e1 + 2 e3) / 16                      (quad–triangle edge)
///   e3' = (3 (v + e3) + e2 + e4) / 8,  e4' = (3 (v + e4) + e3 + e0) / 8   (triangle edges)
///   f0' = (v + e0 + f0 + e1) / 4,      f1' = (v + e1 + f1 + e2) / 4       (face points)
fn transition_one_ring() -> Mat {
    let rows: [(&[i64; 8], i64); 8] = [
        (&[18, 3, 4, 3, 2, 2, 0, 0], 32),
        (&[6, 6, 1, 0, 0, 2, 1, 0], 16),
        (&[6, 1, 6, 1, 0, 0, 1, 1], 16),
        (&[6, 0, 1, 6, 2, 0, 0, 1], 16),
        (&[3, 0, 0, 1, 3, 1, 0, 0], 8),
        (&[3, 1, 0, 0, 1, 3, 0, 0], 8),
        (&[1, 1, 1, 0, 0, 0, 1, 0], 4),
        (&[1, 0, 1, 1, 0, 0, 0, 1], 4),
    ];
    rows.iter().map(|(r, d)| r.iter().map(|x| q(*x, *d)).collect()).collect()
}

fn left_times(l: &[Rational], s: &Mat) -> Vec<Rational> {
    (0..s.len()).map(|j| (0..s.len()).fold(Rational::zero(), |acc, i| acc + l[i].clone() * s[i][j].clone())).collect()
}

fn times_right(s: &Mat, r: &[Rational]) -> Vec<Rational> {
    s.iter().map(|row| row.iter().zip(r).fold(Rational::zero(), |acc, (a, b)| acc + a.clone() * b.clone())).collect()
}

#[test]
fn transition_tangent_stencils_are_the_hand_solved_left_eigenvectors_of_one_half() {
    // Hand solution of l S = l/2 on the one-ring (v, e0..e4, f0, f1), in
    // the two symmetric combinations (×5 across the transition line):
    //   across: (−4, 2, 18, 2, −14, −14, 5, 5)/5   along: (0, 4, 0, −4, −2, 2, 1, −1)
    // (every column checked below, exactly).
    let s = transition_one_ring();
    let half = q(1, 2);
    let across: Vec<Rational> = [-4, 2, 18, 2, -14, -14, 5, 5].iter().map(|x| q(*x, 5)).collect();
    let along: Vec<Rational> = [0, 4, 0, -4, -2, 2, 1, -1].iter().map(|x| q(*x, 1)).collect();
    for l in [&across, &along] {
        let got = left_times(l, &s);
        let want: Vec<Rational> = l.iter().map(|x| x.clone() * half.clone()).collect();
        assert_eq!(got, want, "l S = l/2");
        assert!(l.iter().fold(Rational::zero(), |a, x| a + x.clone()).is_zero(), "a tangent stencil sums to 0");
    }
    assert_eq!(rank(vec![across.clone(), along.clone()]), 2);
    // 1/2 is a double, non-defective eigenvalue of the one-ring, so these two span its left eigenspace
    assert_eq!(algebraic(&s, &half), 2);
    assert_eq!(s.len() - rank(shifted(&s, &half)), 2);
    verdict("peters-shiue", "ps.S43-tangent-stencils", Verdict::Holds);
}

#[test]
fn transition_characteristic_strip_maps_the_transition_line_to_the_y_axis() {
    // Hand solution of S r = r/2 on the one-ring: x = (0, 0, 1, 0, −1, −1, 1, 1),
    // y = (0, −1, 0, 1, 1/2, −1/2, −1, 1). The net (x, y) is the unit square
    // lattice on the quad side (e1 = (1, 0), f0 = (1, −1), f1 = (1, 1)), the
    // transition line e0 — v — e2 on the y-axis (figure 9), and on the triangle
    // side e3 = (−1, 1/2), e4 = (−1, −1/2): a fan of 2 quads and 3 triangles,
    // each positively oriented, turning once around the origin.
    let s = transition_one_ring();
    let half = q(1, 2);
    let x: Vec<Rational> = [0, 0, 1, 0, -1, -1, 1, 1].iter().map(|a| q(*a, 1)).collect();
    let y: Vec<Rational> =
        [(0, 1), (-1, 1), (0, 1), (1, 1), (1, 2), (-1, 2), (-1, 1), (1, 1)].iter().map(|(a, b)| q(*a, *b)).collect();
    for r in [&x, &y] {
        let want: Vec<Rational> = r.iter().map(|a| a.clone() * half.clone()).collect();
        assert_eq!(times_right(&s, r), want, "S r = r/2");
    }
    for k in [0, 1, 3] {
        assert!(x[k].is_zero(), "the transition line (v, e0, e2) has x = 0");
    }
    let p = |k: usize| (x[k].clone(), y[k].clone());
    let cross = |a: (Rational, Rational), b: (Rational, Rational)| a.0 * b.1 - a.1 * b.0;
    // the fan around v: e0, f0, e1 (quad 0), e1, f1, e2 (quad 1), e2, e3, e4, e0 (triangles)
    let ring = [1usize, 6, 2, 7, 3, 4, 5];
    let mut angle = 0.0;
    for w in 0..ring.len() {
        let (a, b) = (p(ring[w]), p(ring[(w + 1) % ring.len()]));
        assert!(cross(a.clone(), b.clone()) > Rational::zero(), "positively oriented");
        let f = |t: &(Rational, Rational)| {
            use num_traits::ToPrimitive;
            (t.0.to_f64().unwrap(), t.1.to_f64().unwrap())
        };
        let (fa, fb) = (f(&a), f(&b));
        angle += (fa.0 * fb.1 - fa.1 * fb.0).atan2(fa.0 * fb.0 + fa.1 * fb.1);
    }
    assert!((angle - 2.0 * std::f64::consts::PI).abs() < 1e-12, "winding number 1");
    verdict("peters-shiue", "ps.S43-charmap", Verdict::Holds);
}

// ---------------------------------------------------------------- Lemma 3.8

/// β_k = (1 + 2 cos(2πk/n))/n at n = 3, 4, 6, where the cosines are rational.
fn beta(k: i64, n: i64) -> Rational {
    let k = k.rem_euclid(n) as usize;
    let c = match n {
        3 => [q(1, 1), q(-1, 2), q(-1, 2)][k].clone(),
        4 => [q(1, 1), q(0, 1), q(-1, 1), q(0, 1)][k].clone(),
        6 => [q(1, 1), q(1, 2), q(-1, 2), q(-1, 1), q(-1, 2), q(1, 2)][k].clone(),
        _ => unreachable!("rational cosines only"),
    };
    (Rational::one() + q(2, 1) * c) / q(n, 1)
}

#[test]
fn lemma_3_8_convolution_of_the_betas_is_beta_not_one_over_n() {
    // β_{i−j} is the (i, j) entry of E + C (Lemma 3.4), a projection, so
    // Σ_j β_j β_{i−j} = ((E + C)²)_{i0} = (E + C)_{i0} = β_i, which is 1/n only
    // where cos(2πi/n) = 0. By hand: n = 3: β = (1, 0, 0), the sum at i = 0 is
    // 1, not 1/3; n = 6: β = (1/2, 1/3, 0, −1/6, 0, 1/3), the sum at i = 0 is
    // 1/4 + 2/9 + 1/36 = 1/2, not 1/6.
    for n in [3i64, 4, 6] {
        for i in 0..n {
            let sum = (0..n).fold(Rational::zero(), |a, j| a + beta(j, n) * beta(i - j, n));
            assert_eq!(sum, beta(i, n), "n = {n}, i = {i}: the sum is β_i");
        }
        assert_ne!(beta(0, n), q(1, n), "n = {n}: β_0 ≠ 1/n");
    }
    assert_eq!(beta(0, 3), q(1, 1));
    assert_eq!((0..6).fold(Rational::zero(), |a, j| a + beta(j, 6) * beta(-j, 6)), q(1, 2));
    let o = verdict("peters-shiue", "ps.lemma3.8-convolution", Verdict::Refuted);
    assert!(o.computed.starts_with("1/2 vs 1/6"), "{}", o.computed);
}

#[test]
fn lemma_3_8_w_bound_holds_with_the_closed_form_of_the_step_two_weights() {
    // Without (4a'), step 1 regular, step 2 half (4b) + half the regular edge
    // rule. Level 0: eon v*, neighbours v_j, quad diagonals w_i (quad q_i =
    // v*, v_{i−1}, w_i, v_i). After step 1, w_i sits in the edge points
    // v_{i−1}¹, v_i¹ (weight 1/16 each, quad edge rule) and in the face point
    // of q_i (1/4); the eon v*¹ = α v* + Σ β v_j has none. Step 2 at spoke 0:
    // (4b) = (2 v*¹ + v_0¹ + Σ_j β_{−j} v_j¹)/4 gives w_i the weight
    // (β_i + β_{i−1})/64 when i ∉ {0, 1}; the regular edge rule reads v*¹,
    // v_0¹, v_{±1}¹ and the face points of q_0, q_1, so for i ∉ {−1, 0, 1, 2}
    // only (4b) reaches w_i and, halved, its weight in v_0² is
    // (β_i + β_{i−1})/128 ≥ 2 (1 − 2 cos(π/n))/(128 n) > −2/(128 n) = −1/(64 n).
    // The composite weights must be that closed form at its minimum.
    let o = verdict("peters-shiue", "ps.lemma3.8-w-bound", Verdict::Holds);
    for n in [5usize, 7, 8, 12] {
        let b = |k: i64| (1.0 + 2.0 * (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos()) / n as f64;
        let far = (3..n as i64 - 1).map(|i| (b(i) + b(i - 1)) / 128.0).fold(f64::INFINITY, f64::min);
        assert!(far > -1.0 / (64.0 * n as f64), "n = {n}");
        let faces = "Q".repeat(n);
        let part = o.computed.split("; ").find(|p| p.starts_with(&format!("{faces}:"))).expect("a part per eon");
        let got: f64 = part[faces.len() + 2..].split(' ').next().unwrap().parse().unwrap();
        assert!((got - far).abs() < 1e-11, "n = {n}: composite {got} against the closed form {far}");
    }
}

#[test]
fn lemma_3_2_uniqueness_by_the_second_difference_of_a_diagonal_ridge() {
    // A diagonal ridge p(i, j) = r(i − j). After bilinear refinement the fine
    // line x − y = 2k holds the coarse values r(k) at (2i, 2j) and
    // f(k) = (r(k − 1) + 2 r(k) + r(k + 1))/4 at (2i + 1, 2j + 1). Smoothing:
    // the four edge neighbours of both kinds of point carry the same values
    // (r(k) + r(k ± 1))/2, twice each, so β drops out; the diagonal
    // neighbours of (2i, 2j) are f(k), f(k), f(k − 1), f(k + 1), those of
    // (2i + 1, 2j + 1) are r(k), r(k), r(k − 1), r(k + 1). Constancy along the
    // line: α r(k) + γ (2f(k) + f(k−1) + f(k+1)) = α f(k) + γ (2r(k) + r(k−1) + r(k+1)),
    // i.e. with D = f − r = Δ²r/4 and A = (1, 2, 1)/4: −α D(k) + 4γ (A D)(k) = 0.
    // A profile with D = δ_0 gives at k = 1: 4γ/4 = 0, at k = 0: −α + 2γ = 0,
    // so α = γ = 0 and, from α + 4β + 4γ = 1, β = 1/4 (A_4). The odd lines
    // x − y = 2k + 1 carry (r(k) + r(k + 1))/2 at both kinds of point and are
    // kept by A_4 (the neighbours of either kind carry r(k), r(k+1), f(k), f(k+1)).
    let d = |k: i64| if k == 0 { q(1, 1) } else { q(0, 1) };
    let ad = |k: i64| (d(k - 1) + q(2, 1) * d(k) + d(k + 1)) / q(4, 1);
    let residual = |al: &Rational, ga: &Rational, k: i64| -al.clone() * d(k) + q(4, 1) * ga.clone() * ad(k);
    // k = 1 forces γ = 0: the residual there is γ
    assert_eq!(residual(&q(0, 1), &q(1, 1), 1), q(1, 1));
    // with γ = 0, k = 0 forces α = 0
    assert_eq!(residual(&q(1, 1), &q(0, 1), 0), q(-1, 1));
    // A_4 leaves every residual zero
    for k in -3..=3 {
        assert!(residual(&q(0, 1), &q(0, 1), k).is_zero());
    }
    let beta = (Rational::one() - q(0, 1) - q(4, 1) * q(0, 1)) / q(4, 1);
    assert_eq!(beta, q(1, 4));
    let o = verdict("peters-shiue", "ps.lemma3.2-uniqueness", Verdict::Holds);
    assert!(o.computed.contains("α = 0, β = 1/4, γ = 0"), "{}", o.computed);
}

// ---------------------------------------------------------------- Khan–Mustafa (1.3), (1.4), (2.2)

#[test]
fn eq_1_3_is_the_expansion_of_eq_1_2() {
    // (1.2) = 2((1 + z1)/2)^4 · 2((1 + z2)/2)^4 = (1 + z1)^4 (1 + z2)^4 / 64, whose
    // coefficients are C(4, a) C(4, b) / 64. The printed table (1.3), row by row:
    let printed = [[1, 4, 6, 4, 1], [4, 16, 24, 16, 4], [6, 24, 36, 24, 6], [4, 16, 24, 16, 4], [1, 4, 6, 4, 1]];
    let binom = [1, 4, 6, 4, 1];
    for (r, row) in printed.iter().enumerate() {
        for (c, x) in row.iter().enumerate() {
            assert_eq!(*x, binom[4 - r] * binom[c]);
        }
    }
    verdict("khan-mustafa", "km.eq1.3-expansion", Verdict::Holds);
}

#[test]
fn eq_1_4_against_the_tensor_product_of_the_univariate_rules() {
    // The univariate cubic B-spline: the new point at an old node k is
    // (p_{k−1} + 6 p_k + p_{k+1})/8, the new point at k + 1/2 is (p_k + p_{k+1})/2.
    // The tensor-product stencil of p_{2i+l,2j+m} (at (i + l/2, j + m/2)) is the
    // product of the x-rule for l and the y-rule for m, as offsets (r, s) → weight·64.
    use std::collections::BTreeMap;
    let uni = |odd: bool| -> Vec<(i64, i64)> {
        if odd {
            vec![(0, 4), (1, 4)]
        } else {
            vec![(-1, 1), (0, 6), (1, 1)]
        }
    };
    let tensor = |l: bool, m: bool| -> BTreeMap<(i64, i64), i64> {
        let mut t = BTreeMap::new();
        for (r, a) in uni(l) {
            for (s, b) in uni(m) {
                t.insert((r, s), a * b);
            }
        }
        t
    };
    let printed = |entries: &[((i64, i64), i64)]| -> BTreeMap<(i64, i64), i64> { entries.iter().cloned().collect() };
    // (1.4) as printed, weights × 64, offsets (r, s) of p_{i+r, j+s}
    let vertex = printed(&[
        ((-1, -1), 1),
        ((-1, 1), 1),
        ((1, -1), 1),
        ((1, 1), 1),
        ((-1, 0), 6),
        ((0, -1), 6),
        ((0, 1), 6),
        ((1, 0), 6),
        ((0, 0), 36),
    ]);
    let edge_x = printed(&[((0, -1), 4), ((0, 1), 4), ((1, -1), 4), ((1, 1), 4), ((0, 0), 24), ((1, 0), 24)]);
    let edge_y = printed(&[((-1, -1), 4), ((-1, 0), 4), ((1, -1), 4), ((1, 0), 4), ((0, -1), 24), ((0, 0), 24)]);
    let face = printed(&[((0, -1), 16), ((0, 0), 16), ((1, -1), 16), ((1, 0), 16)]);
    assert_eq!(vertex, tensor(false, false));
    assert_eq!(edge_x, tensor(true, false));
    assert_ne!(edge_y, tensor(false, true));
    assert_ne!(face, tensor(true, true));
    // the two that differ are the tensor-product stencils moved down by one in j
    let down =
        |t: BTreeMap<(i64, i64), i64>| t.into_iter().map(|((r, s), w)| ((r, s - 1), w)).collect::<BTreeMap<_, _>>();
    assert_eq!(edge_y, down(tensor(false, true)));
    assert_eq!(face, down(tensor(true, true)));
    // so applied to p_{r,s} = s they give y = −1/2 where their point is at y = +1/2
    let y_of = |t: &BTreeMap<(i64, i64), i64>| q(t.iter().map(|((_, s), w)| s * w).sum::<i64>(), 64);
    assert_eq!(y_of(&edge_y), q(-1, 2));
    assert_eq!(y_of(&face), q(-1, 2));
    let o = verdict("khan-mustafa", "km.eq1.4-positions", Verdict::Refuted);
    // the two y-residuals, (−1/2 − 1/2)² each
    assert!(o.computed.starts_with("2 vs 0"), "{}", o.computed);
}

#[test]
fn rules_3_3_are_affine() {
    // the printed numerators of (3.3), each rule over 144
    let rules: [[i64; 9]; 4] = [
        [-16, 32, -16, 32, 80, 32, -16, 32, -16],
        [-22, 26, -22, 20, 68, 20, 2, 50, 2],
        [-22, 20, 2, 26, 68, 50, -22, 20, 2],
        [-19, 14, -13, 14, 56, 38, -13, 38, 29],
    ];
    for r in rules {
        assert_eq!(r.iter().sum::<i64>(), 144);
    }
    verdict("khan-mustafa", "km.rules-affine", Verdict::Holds);
}

// ---------------------------------------------------------------- Huang, Lin–Luo

#[test]
fn theorem_1_at_the_regular_vertex() {
    // At k = 4, a_4 = 1/2: on the minimal set {V_0, FCV_0..3} block 0 is
    // [[1/2, 1/2], [1/4, 3/4]] (eigenvalues 1 and 1/4) and block m has
    // 1/2 + cos(πm/2)/4: 1/2 (m = 1, 3) and 1/4 (m = 2), so λ1 = λ2 = 1/2 in
    // blocks 1 and 3 (tests/non_box.rs pins the whole analysis spectrum).
    let block0 = [[q(1, 2), q(1, 2)], [q(1, 4), q(3, 4)]];
    let tr = block0[0][0].clone() + block0[1][1].clone();
    let det = block0[0][0].clone() * block0[1][1].clone() - block0[0][1].clone() * block0[1][0].clone();
    assert_eq!((tr, det), (q(5, 4), q(1, 4)), "roots 1 and 1/4");
    verdict("huang-nonbox", "nonbox.theorem1-regular", Verdict::Holds);
}

#[test]
fn section_6_at_alpha_four_fifths_fails_by_a_second_method_and_neighbourhood() {
    // The registry decides by the Fourier blocks on the analysis neighbourhood;
    // here the whole matrix (no Fourier transform) on the analysis
    // neighbourhood and the Fourier blocks on the minimal neighbourhood: at
    // n = 3 the largest eigenvalue after 1 is a non-real pair, so λ1 = λ2 real fails.
    let o = verdict("lin-luo", "linluo.section6-fig7-alpha", Verdict::Refuted);
    assert!(o.computed.contains("n=3"), "{}", o.computed);
    let s = schemes::build("unified-sqrt3", &[("alpha".into(), "4/5".into())]).unwrap();
    let config = Configuration::regular(s.as_ref(), 3).unwrap();
    for (kind, method) in [(NeighbourhoodKind::Analysis, Method::Full), (NeighbourhoodKind::Minimal, Method::Dft)] {
        let a =
            analyse(s.as_ref(), &config, &Options { neighbourhood: kind, method: Some(method), exact: false }).unwrap();
        let ev = &a.spectrum.eigenvalues;
        assert!((ev[0].re - 1.0).abs() < 1e-9 && ev[0].im.abs() < 1e-9, "{kind:?}: λ0 = 1");
        assert!(
            ev[1].im.abs() > 1e-3,
            "{kind:?}/{method:?}: the subdominant is not real: {} + {}i",
            ev[1].re,
            ev[1].im
        );
        assert!(!a.spectrum.verdict.c1_spectral, "{kind:?}/{method:?}");
    }
}

// ---------------------------------------------------------------- figures 5 and 15, rule (4b), PGS's b and d

#[test]
fn figure_5_factored_steps_compose_to_the_unfactored_rules() {
    // Compose on a lattice: bilinear refinement of a unit impulse at the coarse
    // origin, then a 3×3 smoothing stencil on the fine grid; the fine value at
    // a fine node is the weight of the coarse origin in that node's rule.
    let bilinear = |x: i64, y: i64| -> Rational {
        // the hat function of the coarse origin on the fine grid
        let h = |t: i64| if t.abs() >= 2 { q(0, 1) } else { q(2 - t.abs(), 2) };
        h(x) * h(y)
    };
    let smooth = |st: &[[Rational; 3]; 3], x: i64, y: i64| -> Rational {
        let mut s = Rational::zero();
        for (a, row) in st.iter().enumerate() {
            for (b, w) in row.iter().enumerate() {
                s += w.clone() * bilinear(x + a as i64 - 1, y + b as i64 - 1);
            }
        }
        s
    };
    let z = q(0, 1);
    let a4 = [[z.clone(), q(1, 4), z.clone()], [q(1, 4), z.clone(), q(1, 4)], [z.clone(), q(1, 4), z.clone()]];
    // the weight of the coarse origin in: the new node at the origin (1a: 4/8),
    // at the neighbour (2, 0) (1a: 1/8), in the edge point (1, 0) (1b: 6/16),
    // in the edge point (1, 2) (1b: 1/16), in the face point (1, 1) (1/4)
    assert_eq!(smooth(&a4, 0, 0), q(4, 8));
    assert_eq!(smooth(&a4, 2, 0), q(1, 8));
    assert_eq!(smooth(&a4, 2, 2), q(0, 1));
    assert_eq!(smooth(&a4, 1, 0), q(6, 16));
    assert_eq!(smooth(&a4, 1, 2), q(1, 16));
    assert_eq!(smooth(&a4, 1, 1), q(1, 4));
    // Catmull–Clark's regular vertex rule: 9/16, 3/32 (edge), 1/64 (diagonal)
    let cc = [[q(1, 16), q(2, 16), q(1, 16)], [q(2, 16), q(4, 16), q(2, 16)], [q(1, 16), q(2, 16), q(1, 16)]];
    assert_eq!(smooth(&cc, 0, 0), q(9, 16));
    assert_eq!(smooth(&cc, 2, 0), q(3, 32));
    assert_eq!(smooth(&cc, 2, 2), q(1, 64));
    verdict("peters-shiue", "ps.fig5-factored", Verdict::Holds);
}

#[test]
fn rule_4b_weights_sum_to_four() {
    // Σ_j β_j = 1 + (2/n) Σ_j cos(2πj/n) = 1 (the n-th roots of unity sum to
    // zero), so 2 + 1 + Σ β_j = 4 at every n.
    for n in 3..=16usize {
        let s: f64 = (0..n).map(|j| (2.0 * std::f64::consts::PI * j as f64 / n as f64).cos()).sum();
        assert!(s.abs() < 1e-12, "n = {n}");
    }
    verdict("peters-shiue", "ps.rule4b-normalisation", Verdict::Holds);
}

#[test]
fn pgs_b_and_d_rules_are_the_chaikin_tensor_product() {
    let chaikin = [q(3, 4), q(1, 4)];
    let printed = [[q(9, 16), q(3, 16)], [q(3, 16), q(1, 16)]];
    for a in 0..2 {
        for b in 0..2 {
            assert_eq!(printed[a][b], chaikin[a].clone() * chaikin[b].clone());
        }
    }
    verdict("karciauskas-peters", "pgs.rules-bd-binary", Verdict::Holds);
}

#[test]
fn figure_15_regular_nodes_have_linear_characteristic_maps() {
    // The part derived here: at the regular nodes among figure 15's eons
    // (QQQQ, A_4; TTTTTT, A_3) the rules reproduce linear functions, so the
    // lattice coordinates themselves are the subdominant pair (eigenvalue 1/2)
    // and the characteristic map is the identity of the lattice: injective.
    // (1a) at the origin on x: (4·0 + 1 − 1 + 0 + 0)/8 = 0 = x/2 there;
    // (1b) on the edge (0,0)–(1,0): (6(0 + 1) + (0 + 1 + 0 + 1))/16 = 1/2 = x at (1/2, 0);
    // (3a) at the origin: (10·0 + Σ six neighbours' x = 0)/16 = 0;
    // (3b) on the edge (0,0)–(1,0) with apexes (1,1), (0,−1): (3(0 + 1) + 1 + 0)/8 = 1/2.
    assert_eq!((q(6, 1) * q(1, 1) + q(2, 1)) / q(16, 1), q(1, 2));
    assert_eq!((q(3, 1) * q(1, 1) + q(1, 1)) / q(8, 1), q(1, 2));
    verdict("peters-shiue", "ps.fig15-charmap", Verdict::Holds);
}

// ---------------------------------------------------------------- claims/COVERAGE.md

#[test]
fn coverage_lists_every_claim_and_names_no_unknown_one() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/claims/COVERAGE.md")).unwrap();
    let ids: std::collections::BTreeSet<String> =
        builtin_files().unwrap().into_iter().flat_map(|f| f.claims.into_iter().map(|c| c.id)).collect();
    // every `code` span that looks like a claim id (letters, digits, '.', '-', with a '.')
    let spans: std::collections::BTreeSet<String> = text
        .split('`')
        .skip(1)
        .step_by(2)
        .filter(|t| t.contains('.') && t.chars().all(|c| c.is_ascii_alphanumeric() || c == '.' || c == '-'))
        .map(String::from)
        .collect();
    let builtin_names = ["fourthree.", "curve.", "strip.", "window.", "lattice.", "matrix."];
    for id in &ids {
        assert!(spans.contains(id), "claims/COVERAGE.md does not list {id}");
    }
    for s in &spans {
        assert!(
            ids.contains(s) || builtin_names.iter().any(|b| s.starts_with(b)),
            "claims/COVERAGE.md names {s}, which is no claim"
        );
    }
}

#[test]
fn the_new_builtins_refuse_bad_data_without_panicking() {
    let cases = [
        ("fourthree.step-two-bound", r#"{ faces = [], rings = 4, bound = "0" }"#),
        ("fourthree.step-two-bound", r#"{ faces = ["QQQQQ"], rings = 40, bound = "0" }"#),
        ("fourthree.step-two-bound", r#"{ faces = ["QQQQQ"], rings = 4, bound = "1/(" }"#),
        ("fourthree.step-two-bound", r#"{ faces = ["TTTTT"], rings = 4, bound = "0" }"#),
        ("fourthree.ripple-free-unique", r#"{ directions = [[2, 0]], profiles = [[1]], stated = ["0", "1/4", "0"] }"#),
        (
            "fourthree.ripple-free-unique",
            r#"{ directions = [[1, 0]], profiles = [[9999999]], stated = ["0", "1/4", "0"] }"#,
        ),
        ("fourthree.ripple-free-unique", r#"{ directions = [[1, 0]], profiles = [[1]], stated = ["0", "1/4"] }"#),
        ("fourthree.ripple-free-unique", r#"{ directions = [], profiles = [[1]], stated = ["0", "1/4", "0"] }"#),
    ];
    let mut text = String::from("paper = \"bad\"\ntitle = \"bad\"\n");
    for (k, (name, data)) in cases.iter().enumerate() {
        text += &format!(
            "[[claim]]\nid = \"c{k}\"\nlocation = \"x\"\nstatement = \"x\"\ncheck = \"builtin\"\nname = \"{name}\"\ndata = {data}\n"
        );
    }
    let file = subdlab::claims::parse_file("bad.toml", &text).unwrap();
    for o in evaluate(&file) {
        assert_eq!(o.verdict, Verdict::Error, "{}: {} / {}", o.id, o.computed, o.detail);
    }
    // and the readings that are not unique: the axis directions alone leave a
    // two-parameter family (every symmetric stencil keeps axis-aligned ridges)
    let text = "paper = \"p\"\ntitle = \"p\"\n[[claim]]\nid = \"axis\"\nlocation = \"x\"\nstatement = \"x\"\ncheck = \"builtin\"\nname = \"fourthree.ripple-free-unique\"\ndata = { directions = [[1, 0], [0, 1]], profiles = [[0, 3, 7, -2, 5]], stated = [\"0\", \"1/4\", \"0\"] }\n";
    let o = evaluate(&subdlab::claims::parse_file("p.toml", text).unwrap()).pop().unwrap();
    assert_eq!(o.verdict, Verdict::Refuted, "{}", o.computed);
    assert!(o.computed.contains("2-parameter family"), "{}", o.computed);
}

#[test]
fn the_checkerboard_is_in_the_kernel_of_the_a4_rules_and_not_of_catmull_clark() {
    // By hand on c = (−1)^(x + y): (1a) (4c + Σ 4 neighbours (−c))/8 = 0; (1b)
    // (6(c − c) + the four other corners, two c and two −c)/16 = 0; the face
    // point (c − c + c − c)/4 = 0. Catmull–Clark's regular vertex rule gives
    // (36 c − 4·6 c + 4·c)/64 = c/4 ≠ 0: its B-splines are independent.
    let c = q(1, 1);
    let neg = -c.clone();
    assert!(((q(4, 1) * c.clone() + q(4, 1) * neg.clone()) / q(8, 1)).is_zero());
    assert!(((q(6, 1) * (c.clone() + neg.clone()) + q(2, 1) * c.clone() + q(2, 1) * neg.clone()) / q(16, 1)).is_zero());
    assert_eq!((q(36, 1) * c.clone() + q(24, 1) * neg + q(4, 1) * c.clone()) / q(64, 1), q(1, 4));
    verdict("peters-shiue", "ps.A4-zero-sequence", Verdict::Holds);
    let text = "paper = \"p\"\ntitle = \"p\"\n[[claim]]\nid = \"cc\"\nlocation = \"x\"\nstatement = \"x\"\ncheck = \"builtin\"\nname = \"window.checkerboard-kernel\"\ndata = { scheme = \"catmull-clark\", faces = \"QQQQ\", spokes = [[1, 0], [0, 1], [-1, 0], [0, -1]], window = [-4, 4, -4, 4] }\n";
    let o = evaluate(&subdlab::claims::parse_file("p.toml", text).unwrap()).pop().unwrap();
    assert_eq!(o.verdict, Verdict::Refuted, "{}", o.computed);
    assert!(o.computed.contains("1/4 at"), "the vertex rule's c/4: {}", o.computed);
}
