//! Khan & Mustafa, "A new non-tensor product C¹ subdivision scheme for regular
//! quad meshes" (2013): every number the paper prints is kept here as data (a
//! CLAIM) and compared with what is true. Expected values come from the paper's
//! own construction (least-squares fits re-derived exactly), from textbook
//! identities (affine invariance, the mixed central difference, Cardano's
//! formula, the rational root theorem), or from the paper's own stencils placed
//! by hand; never from the program's output.
//!
//! Verdicts (see also the report in the commit message / README):
//! - stencils (3.3): HOLD (= least-squares quadratic on the 3×3 grid);
//! - A, C, D, F: HOLD; B: REFUTED (printed −p_{i+1,j+1} where −p_{i−1,j+1} belongs);
//!   E: REFUTED (printed −p_{i−1,j} where −p_{i−1,j+1} belongs);
//! - "interpolating": REFUTED, the printed F (and the stencils) are the least-squares fit;
//! - 16×16 matrix: row/point correspondence HOLDS, two rows garbled (row 1 col 2
//!   prints 31 for 32; row 13 prints the rule of p_{2i,2j+1}, a copy of row 15);
//! - eigenvalues: 1, 1/2², 3/8², 1/16, 1/24, −1/16 ± √5/48 i and the Cardano
//!   roots HOLD; "1/4 four times" is REFUTED: 1/4 has multiplicity 3 and 1/8 is
//!   the sixteenth eigenvalue;
//! - cubic variant: vertex and face rules HOLD; each edge rule has one sign
//!   wrong (sums to 9/8); the label p_{2i+2,j+1} is p_{2i,2j+1}.

use crate::common;
#[allow(unused_imports)]
use common::{fails, subdlab};

use num_traits::{One, Signed, Zero};
use subdlab::lattice::analysis::{analyse, charpoly, to_qmatrix};
use subdlab::lattice::fit::{derive_masks, grid, least_squares, total_degree, Monomial};
use subdlab::lattice::{
    analysis_window, invariance_defects, local_matrix, minimal_invariant_window, stencil, LatticeDomain, LatticeScheme,
    Point, Window,
};
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::numeric::exact::{q, Poly};
use subdlab::numeric::Rational;
use subdlab::schemes::khan_mustafa::{KhanMustafa, KhanMustafaCubic};
use subdlab::sdc::Rules;

// ---------------------------------------------------------------- paper data

/// Eq. (3.3) as printed, numerators over 144; entry [r+1][s+1] is the weight of
/// p_{i+r, j+s}. Order: p_{2i,2j}, p_{2i+1,2j}, p_{2i,2j+1}, p_{2i+1,2j+1}.
const PRINTED_QUADRATIC: [[[i64; 3]; 3]; 4] = [
    [[-16, 32, -16], [32, 80, 32], [-16, 32, -16]],
    [[-22, 26, -22], [20, 68, 20], [2, 50, 2]],
    [[-22, 20, 2], [26, 68, 50], [-22, 20, 2]],
    [[-19, 14, -13], [14, 56, 38], [-13, 38, 29]],
];
const PARITIES: [(u8, u8); 4] = [(0, 0), (1, 0), (0, 1), (1, 1)];

/// The printed coefficients A..F at t = 1, k = 0, as weights on the 3×3 grid
/// ([r+1][s+1] is the weight of p_{i+r,j+s}), each with its printed factor.
fn printed_coefficients() -> Vec<(&'static str, Monomial, Rational, [[i64; 3]; 3])> {
    vec![
        // A = 1/6 {−2(p_{i,j−1} + p_{i,j} + p_{i,j+1}) + p_{i+1,j−1} + p_{i−1,j−1} + p_{i−1,j} + p_{i−1,j+1} + p_{i+1,j+1} + p_{i+1,j}}
        ("A", (2, 0), q(1, 6), [[1, 1, 1], [-2, -2, -2], [1, 1, 1]]),
        // B = 1/4 {p_{i−1,j−1} − p_{i+1,j+1} − p_{i+1,j−1} + p_{i+1,j+1}}  (the two p_{i+1,j+1} cancel)
        ("B", (1, 1), q(1, 4), [[1, 0, 0], [0, 0, 0], [-1, 0, 0]]),
        // C = 1/6 {−2(p_{i,j} + p_{i−1,j} + p_{i+1,j}) + p_{i,j−1} + p_{i,j+1} + p_{i+1,j−1} + p_{i−1,j−1} + p_{i−1,j+1} + p_{i+1,j+1}}
        ("C", (0, 2), q(1, 6), [[1, -2, 1], [1, -2, 1], [1, -2, 1]]),
        // D = −1/6 {p_{i−1,j−1} + p_{i−1,j} + p_{i−1,j+1} − p_{i+1,j−1} − p_{i+1,j} − p_{i+1,j+1}}
        ("D", (1, 0), q(-1, 6), [[1, 1, 1], [0, 0, 0], [-1, -1, -1]]),
        // E = −1/6 {p_{i−1,j−1} − p_{i−1,j} + p_{i,j−1} − p_{i,j+1} + p_{i+1,j−1} − p_{i+1,j+1}}
        ("E", (0, 1), q(-1, 6), [[1, -1, 0], [1, 0, -1], [1, 0, -1]]),
        // F = 2/9 {p_{i,j−1} + p_{i,j+1} + p_{i−1,j} + p_{i+1,j}} − 1/9 {diagonals} + 5/9 p_{i,j}
        ("F", (0, 0), q(1, 9), [[-1, 2, -1], [2, 5, 2], [-1, 2, -1]]),
    ]
}

/// The 16×16 matrix printed in section 4 (numerators over 144), typed as printed.
const PRINTED_MATRIX: [[i64; 16]; 16] = [
    [-16, 31, -16, 0, 32, 80, 32, 0, -16, 32, -16, 0, 0, 0, 0, 0],
    [-22, 20, 2, 0, 26, 68, 50, 0, -22, 20, 2, 0, 0, 0, 0, 0],
    [0, -16, 32, -16, 0, 32, 80, 32, 0, -16, 32, -16, 0, 0, 0, 0],
    [0, -22, 20, 2, 0, 26, 68, 50, 0, -22, 20, 2, 0, 0, 0, 0],
    [-22, 26, -22, 0, 20, 68, 20, 0, 2, 50, 2, 0, 0, 0, 0, 0],
    [-19, 14, -13, 0, 14, 56, 38, 0, -13, 38, 29, 0, 0, 0, 0, 0],
    [0, -22, 26, -22, 0, 20, 68, 20, 0, 2, 50, 2, 0, 0, 0, 0],
    [0, -19, 14, -13, 0, 14, 56, 38, 0, -13, 38, 29, 0, 0, 0, 0],
    [0, 0, 0, 0, -16, 32, -16, 0, 32, 80, 32, 0, -16, 32, -16, 0],
    [0, 0, 0, 0, -22, 20, 2, 0, 26, 68, 50, 0, -22, 20, 2, 0],
    [0, 0, 0, 0, 0, -16, 32, -16, 0, 32, 80, 32, 0, -16, 32, -16],
    [0, 0, 0, 0, 0, -22, 20, 2, 0, 26, 68, 50, 0, -22, 20, 2],
    [0, 0, 0, 0, 0, -22, 26, -22, 0, 20, 68, 20, 0, 2, 50, 2],
    [0, 0, 0, 0, -19, 14, -13, 0, 14, 56, 38, 0, -13, 38, 29, 0],
    [0, 0, 0, 0, 0, -22, 26, -22, 0, 20, 68, 20, 0, 2, 50, 2],
    [0, 0, 0, 0, 0, -19, 14, -13, 0, 14, 56, 38, 0, -13, 38, 29],
];

/// The cubic rules of the Discussion section as printed, numerators over 800,
/// entry [r+1][s+1] the weight of p_{i+r,j+s}, r, s = −1..2. Order as
/// PARITIES; the third is printed under the label p_{2i+2,j+1}.
const PRINTED_CUBIC: [[[i64; 4]; 4]; 4] = [
    [[-92, 176, -16, -68], [176, 372, 148, 104], [-16, 148, -68, -64], [-68, 104, -64, 28]],
    // 100(−p_{i−1,j−1} + p_{i,j−1} + p_{i+1,j−1} − p_{i+2,j−1}) + 125(p_{i−1,j} + p_{i+2,j}) + 275(p_{i,j} + p_{i+1,j})
    // + 50(−p_{i−1,j+1} + p_{i,j+1} + p_{i+1,j+1} + p_{i+2,j+1}) + 25(−p_{i−1,j+2} + p_{i,j+2} + p_{i+1,j+2} − p_{i+2,j+2})
    [[-100, 125, -50, -25], [100, 275, 50, 25], [100, 275, 50, 25], [-100, 125, 50, -25]],
    // 100(−p_{i−1,j−1} + p_{i−1,j} + p_{i−1,j+1} − p_{i−1,j+2}) + 125(p_{i,j−1} + p_{i,j+2}) + 275(p_{i,j} + p_{i,j+1})
    // + 50(−p_{i+1,j−1} + p_{i+1,j} + p_{i+1,j+1} + p_{i+1,j+2}) + 25(−p_{i+2,j−1} + p_{i+2,j} + p_{i+2,j+1} − p_{i+2,j+2})
    [[-100, 100, 100, -100], [125, 275, 275, 125], [-50, 50, 50, 50], [-25, 25, 25, -25]],
    [[-75, 50, 50, -75], [50, 175, 175, 50], [50, 175, 175, 50], [-75, 50, 50, -75]],
];

// ---------------------------------------------------------------- helpers

fn quadratic_space() -> Vec<Monomial> {
    // {1, x, y, xy, x², y²}
    total_degree(2)
}

fn cubic_space() -> Vec<Monomial> {
    // A + Bx + Cy + Dxy + Ex² + Fy² + Gxy² + H x²y + Jx³ + Ky³ (the paper's "Hxyx²" is x²y)
    vec![(0, 0), (1, 0), (0, 1), (1, 1), (2, 0), (0, 2), (1, 2), (2, 1), (3, 0), (0, 3)]
}

/// A mask as a dense grid [r−lo][s−lo] of rationals.
fn dense<const N: usize>(mask: &[(Point, Rational)], lo: i64) -> [[Rational; N]; N] {
    let mut g: [[Rational; N]; N] = std::array::from_fn(|_| std::array::from_fn(|_| Rational::zero()));
    for ((r, s), w) in mask {
        let (a, b) = ((r - lo) as usize, (s - lo) as usize);
        g[a][b] = &g[a][b] + w;
    }
    g
}

fn grid_over<const N: usize>(nums: &[[i64; N]; N], den: i64) -> [[Rational; N]; N] {
    std::array::from_fn(|a| std::array::from_fn(|b| q(nums[a][b], den)))
}

fn sum_mask(mask: &[(Point, Rational)]) -> Rational {
    mask.iter().fold(Rational::zero(), |acc, (_, w)| acc + w)
}

/// Multiplicity of r as a root, by substitution into p, p', p'', ...
fn multiplicity_by_derivatives(p: &Poly, r: &Rational) -> usize {
    let mut d = p.clone();
    let mut m = 0;
    while d.degree() > 0 && d.eval(r).is_zero() {
        m += 1;
        d = d.derivative();
    }
    m
}

fn paper_window() -> Window {
    // p_{i+l, j+m}, l, m = −2..1, l fastest (the printed vector p_{i−2,j−2}, p_{i−1,j−2}, ...)
    Window::rect(-2, 1, -2, 1)
}

/// The paper's 16×16 matrix built by hand from the printed stencils (3.3):
/// row k is new point p_{2i+l,2j+m} of the printed vector [P^{k+1}], i.e. the
/// rule of parity (l mod 2, m mod 2) centred at (⌊l/2⌋, ⌊m/2⌋); column of
/// p_{i+l',j+m'} is (l'+2) + 4(m'+2). Numerators over 144.
fn matrix_from_printed_stencils() -> [[i64; 16]; 16] {
    let mut m = [[0i64; 16]; 16];
    for (row, out) in m.iter_mut().enumerate() {
        let (l, mm) = (row as i64 % 4 - 2, row as i64 / 4 - 2);
        let parity = (l.rem_euclid(2) as u8, mm.rem_euclid(2) as u8);
        let rule = PARITIES.iter().position(|&p| p == parity).unwrap();
        let (ci, cj) = (l.div_euclid(2), mm.div_euclid(2));
        for r in -1..=1i64 {
            for s in -1..=1i64 {
                let col = ((ci + r + 2) + 4 * (cj + s + 2)) as usize;
                out[col] += PRINTED_QUADRATIC[rule][(r + 1) as usize][(s + 1) as usize];
            }
        }
    }
    m
}

fn assembled_paper_matrix() -> Vec<Vec<Rational>> {
    local_matrix::<Rational>(&KhanMustafa, &paper_window()).unwrap()
}

// ---------------------------------------------------------------- masks and the derivation

#[test]
fn every_mask_is_an_affine_combination() {
    // weights summing to 1: the rules commute with translations of the data
    for (a, b) in PARITIES {
        let m: Vec<(Point, Rational)> = Rules::<LatticeDomain, Rational>::rule(&KhanMustafa, &(), (a, b));
        assert_eq!(sum_mask(&m), Rational::one(), "quadratic rule ({a},{b})");
        let m: Vec<(Point, Rational)> = Rules::<LatticeDomain, Rational>::rule(&KhanMustafaCubic, &(), (a, b));
        assert_eq!(sum_mask(&m), Rational::one(), "cubic rule ({a},{b})");
        assert_eq!(m.len(), 16, "the cubic variant has support 16");
    }
}

#[test]
fn float_and_exact_masks_come_from_the_same_code() {
    for (a, b) in PARITIES {
        let e: Vec<(Point, Rational)> = Rules::<LatticeDomain, Rational>::rule(&KhanMustafa, &(), (a, b));
        let f: Vec<(Point, f64)> = Rules::<LatticeDomain, f64>::rule(&KhanMustafa, &(), (a, b));
        for ((pe, we), (pf, wf)) in e.iter().zip(&f) {
            assert_eq!(pe, pf);
            assert!((subdlab::numeric::Weight::to_f64(we) - wf).abs() < 1e-15);
        }
    }
}

/// Claim (3.3): the four printed stencils. HOLD: they are the least-squares
/// quadratic on the 3×3 grid evaluated at (0,0), (1/2,0), (0,1/2), (1/2,1/2),
/// and they are the masks the scheme uses.
#[test]
fn printed_stencils_are_the_least_squares_quadratic() {
    let derived = derive_masks(&quadratic_space(), &grid(-1, 1), &Rational::one()).unwrap();
    for (k, &(a, b)) in PARITIES.iter().enumerate() {
        let d: [[Rational; 3]; 3] = dense(&derived[a as usize][b as usize], -1);
        assert_eq!(d, grid_over(&PRINTED_QUADRATIC[k], 144), "printed rule {k} vs least-squares fit");
        let used: Vec<(Point, Rational)> = Rules::<LatticeDomain, Rational>::rule(&KhanMustafa, &(), (a, b));
        assert_eq!(dense::<3>(&used, -1), d, "scheme mask ({a},{b}) vs derivation");
    }
}

/// Claim: "an insertion rule can be obtained by interpolation" / "interpolating
/// the data points" (3.2). REFUTED: nine equations in six unknowns have no
/// solution for general data; from the fifth equation an interpolant would have
/// F = p_{i,j}, but the printed F weights p_{i,j} by 5/9.
#[test]
fn the_construction_is_least_squares_not_interpolation() {
    let samples: Vec<(Rational, Rational)> = grid(-1, 1)
        .iter()
        .map(|&(r, s)| (Rational::from_integer(r.into()), Rational::from_integer(s.into())))
        .collect();
    let fit = least_squares(&quadratic_space(), &samples).unwrap();
    assert!(!fit.interpolates(), "a 6-dimensional space cannot interpolate 9 arbitrary values");
    let f = fit.coefficient((0, 0)).unwrap();
    let centre = grid(-1, 1).iter().position(|&p| p == (0, 0)).unwrap();
    assert_ne!(f[centre], Rational::one(), "F is not p_ij");
    assert_eq!(f[centre], q(5, 9), "the printed F's centre weight");
    // least squares reproduces its own space: data sampled from a quadratic come back exactly
    let g =
        |x: &Rational, y: &Rational| q(3, 1) * x * x - q(2, 1) * x * y + q(1, 2) * y * y - x + q(4, 1) * y + q(7, 1);
    let data: Vec<Rational> = samples.iter().map(|(x, y)| g(x, y)).collect();
    let want = [(2, 0, q(3, 1)), (1, 1, q(-2, 1)), (0, 2, q(1, 2)), (1, 0, q(-1, 1)), (0, 1, q(4, 1)), (0, 0, q(7, 1))];
    for (a, b, c) in want {
        let w = fit.coefficient((a, b)).unwrap();
        let v = w.iter().zip(&data).fold(Rational::zero(), |acc, (x, y)| acc + x * y);
        assert_eq!(v, c, "coefficient of x^{a} y^{b}");
    }
}

/// Claims A, C, D, F HOLD; B and E are REFUTED.
/// B: the printed brace {p_{i−1,j−1} − p_{i+1,j+1} − p_{i+1,j−1} + p_{i+1,j+1}}
/// collapses to p_{i−1,j−1} − p_{i+1,j−1}, blind to p_{i−1,j+1} and p_{i+1,j+1};
/// the true B is the mixed central difference Σ r·s·p_{i+r,j+s} / 4 (on this
/// symmetric grid least squares decouples xy from the other monomials, and
/// Σ (rs)² = 4). E: the printed brace {p_{i−1,j−1} − p_{i−1,j} + p_{i,j−1} −
/// p_{i,j+1} + p_{i+1,j−1} − p_{i+1,j+1}} has −p_{i−1,j} where the true
/// E = Σ s·p_{i+r,j+s} / 6 (Σ s² = 6) has −p_{i−1,j+1}. Both look like index
/// typos; applied to the data f = xy (resp. f = y) the printed B gives 1/2 and
/// the printed E gives 5/6 instead of 1.
#[test]
fn printed_coefficients_a_to_f() {
    let samples: Vec<(Rational, Rational)> = grid(-1, 1)
        .iter()
        .map(|&(r, s)| (Rational::from_integer(r.into()), Rational::from_integer(s.into())))
        .collect();
    let fit = least_squares(&quadratic_space(), &samples).unwrap();
    let offsets = grid(-1, 1);
    let apply = |w: &[Rational], f: &dyn Fn(i64, i64) -> i64| {
        w.iter().zip(&offsets).fold(Rational::zero(), |acc, (c, &(r, s))| acc + c * q(f(r, s), 1))
    };
    for (name, mono, factor, nums) in printed_coefficients() {
        let derived = fit.coefficient(mono).unwrap();
        let printed: Vec<Rational> =
            offsets.iter().map(|&(r, s)| &factor * q(nums[(r + 1) as usize][(s + 1) as usize], 1)).collect();
        match name {
            "B" => {
                assert_ne!(derived, printed.as_slice(), "B as printed would be right");
                let truth: Vec<Rational> = offsets.iter().map(|&(r, s)| q(r * s, 4)).collect();
                assert_eq!(derived, truth.as_slice(), "B is the mixed central difference");
                assert_eq!(apply(derived, &|r, s| r * s), Rational::one());
                assert_eq!(apply(&printed, &|r, s| r * s), q(1, 2));
            }
            "E" => {
                assert_ne!(derived, printed.as_slice(), "E as printed would be right");
                let truth: Vec<Rational> = offsets.iter().map(|&(_, s)| q(s, 6)).collect();
                assert_eq!(derived, truth.as_slice(), "E is the averaged y-difference");
                assert_eq!(apply(derived, &|_, s| s), Rational::one());
                assert_eq!(apply(&printed, &|_, s| s), q(5, 6));
            }
            _ => assert_eq!(derived, printed.as_slice(), "coefficient {name}"),
        }
    }
}

/// Claim: the factors 2^{2k}/(6t²) of A and 2^k/(6t) of D. HOLD: with samples
/// at spacing t/2^k the fitted x² coefficient scales by (2^k/t)², the x one by 2^k/t.
#[test]
fn coefficient_scaling_with_spacing() {
    let (t, k) = (3i64, 2u32);
    let spacing = q(t, 1 << k);
    let at = |h: &Rational| -> Vec<(Rational, Rational)> {
        grid(-1, 1)
            .iter()
            .map(|&(r, s)| (h * Rational::from_integer(r.into()), h * Rational::from_integer(s.into())))
            .collect()
    };
    let unit = least_squares(&quadratic_space(), &at(&Rational::one())).unwrap();
    let scaled = least_squares(&quadratic_space(), &at(&spacing)).unwrap();
    let f2 = q(1 << (2 * k), t * t);
    let f1 = q(1 << k, t);
    for (m, f) in [((2, 0), &f2), ((1, 1), &f2), ((0, 2), &f2), ((1, 0), &f1), ((0, 1), &f1)] {
        let want: Vec<Rational> = unit.coefficient(m).unwrap().iter().map(|w| w * f).collect();
        assert_eq!(scaled.coefficient(m).unwrap(), want.as_slice(), "monomial {m:?}");
    }
    assert_eq!(scaled.coefficient((0, 0)), unit.coefficient((0, 0)), "F does not scale");
}

/// The cubic variant: least-squares cubic in span{1, x, y, xy, x², y², xy², x²y,
/// x³, y³} on the 4×4 grid p_{i+r,j+s}, r, s = −1..2. Vertex and face rules HOLD.
/// Each printed edge rule has exactly one wrong sign (p_{i+2,j+1} in p_{2i+1,2j},
/// p_{i+1,j+2} in the rule labelled p_{2i+2,j+1}, which is p_{2i,2j+1}: its
/// weights are those of p_{2i+1,2j} with i and j exchanged): printed +50, true
/// −50, and the printed rules sum to 900/800, so they are not affine invariant.
#[test]
fn cubic_variant_against_the_least_squares_cubic() {
    let derived = derive_masks(&cubic_space(), &grid(-1, 2), &Rational::one()).unwrap();
    for (k, &(a, b)) in PARITIES.iter().enumerate() {
        let d: [[Rational; 4]; 4] = dense(&derived[a as usize][b as usize], -1);
        let printed = grid_over(&PRINTED_CUBIC[k], 800);
        let printed_sum = printed.iter().flatten().fold(Rational::zero(), |acc, x| acc + x);
        let diffs: Vec<(usize, usize)> =
            (0..4).flat_map(|r| (0..4).map(move |s| (r, s))).filter(|&(r, s)| d[r][s] != printed[r][s]).collect();
        match (a, b) {
            (1, 0) => {
                assert_eq!(diffs, vec![(3, 2)], "only p_{{i+2,j+1}} differs");
                assert_eq!((d[3][2].clone(), printed[3][2].clone()), (q(-50, 800), q(50, 800)));
                assert_eq!(printed_sum, q(9, 8));
            }
            (0, 1) => {
                assert_eq!(diffs, vec![(2, 3)], "only p_{{i+1,j+2}} differs");
                assert_eq!((d[2][3].clone(), printed[2][3].clone()), (q(-50, 800), q(50, 800)));
                assert_eq!(printed_sum, q(9, 8));
                // the mislabelled rule is the transpose of the p_{2i+1,2j} rule: it is p_{2i,2j+1}
                let e: [[Rational; 4]; 4] = dense(&derived[1][0], -1);
                assert!((0..4).all(|r| (0..4).all(|s| d[r][s] == e[s][r])));
            }
            _ => {
                assert!(diffs.is_empty(), "cubic rule ({a},{b}) differs at {diffs:?}");
                assert_eq!(printed_sum, Rational::one());
            }
        }
        let used: Vec<(Point, Rational)> = Rules::<LatticeDomain, Rational>::rule(&KhanMustafaCubic, &(), (a, b));
        assert_eq!(dense::<4>(&used, -1), d, "cubic scheme mask ({a},{b}) is the derived one");
    }
}

// ---------------------------------------------------------------- the 16×16 matrix

/// Is the paper's window invariant, and is it the minimal one? Fine point a
/// (per coordinate) depends on ⌊a/2⌋ − 1 ..= ⌊a/2⌋ + 1; an interval [L, H] is
/// closed under that iff ⌊L/2⌋ − 1 ≥ L and ⌊H/2⌋ + 1 ≤ H, i.e. L ≤ −2 and
/// H ≥ 1, so the smallest invariant set containing the origin is [−2, 1]²: the
/// paper's 16 points, in the paper's order.
#[test]
fn paper_window_is_the_minimal_invariant_window() {
    let w = minimal_invariant_window(&KhanMustafa, &[(0, 0)]).unwrap();
    assert_eq!(w, paper_window());
    assert!(invariance_defects(&KhanMustafa, &paper_window()).is_empty());
    // the 3×3 window around the origin is not invariant (p_{−1,−1}'s face rule needs p_{−2,−2})
    let small = Window::rect(-1, 1, -1, 1);
    assert!(invariance_defects(&KhanMustafa, &small).contains(&((-1, -1), (-2, -2))));
    assert!(local_matrix::<f64>(&KhanMustafa, &small).is_err());
    // cubic: dependencies ⌊a/2⌋ − 1 ..= ⌊a/2⌋ + 2, closed iff L ≤ −2 and H ≥ 3
    assert_eq!(minimal_invariant_window(&KhanMustafaCubic, &[(0, 0)]).unwrap(), Window::rect(-2, 3, -2, 3));
}

/// Analysis window: control point c influences fine points 2c − 2 ..= 2c + 3, so
/// its basis function is supported on (c − 2, c + 3); the limit surface over the
/// cells around the origin, (−1, 1)², depends on c ∈ −3..=2 per coordinate, and
/// [−3, 2]² is invariant (⌊−3/2⌋ − 1 = −3, ⌊2/2⌋ + 1 = 2).
#[test]
fn analysis_window_holds_the_limit_surface_around_the_origin() {
    assert_eq!(analysis_window(&KhanMustafa, 1).unwrap(), Window::rect(-3, 2, -3, 2));
}

/// Claim: the printed 16×16 matrix. The correspondence "row k = new point k of
/// [P^{k+1}]" HOLDS for 14 rows; row 1 prints 31 at column 2 where the vertex
/// rule has 32 (the row then sums to 143/144); row 13 (new point p_{2i−2,2j+1},
/// the p_{2i,2j+1} rule centred at p_{i−1,j}) prints the same rule centred at
/// p_{i,j}, which is row 15 again.
#[test]
fn printed_matrix_entry_by_entry() {
    let by_hand = matrix_from_printed_stencils();
    let assembled = assembled_paper_matrix();
    for r in 0..16 {
        for c in 0..16 {
            assert_eq!(assembled[r][c], q(by_hand[r][c], 144), "assembled ({r},{c}) vs hand placement");
        }
    }
    let mismatches: Vec<(usize, usize)> = (0..16)
        .flat_map(|r| (0..16).map(move |c| (r, c)))
        .filter(|&(r, c)| PRINTED_MATRIX[r][c] != by_hand[r][c])
        .collect();
    let rows: std::collections::BTreeSet<usize> = mismatches.iter().map(|m| m.0).collect();
    assert_eq!(rows.into_iter().collect::<Vec<_>>(), vec![0, 12], "garbled rows (0-based)");
    assert!(mismatches.iter().filter(|m| m.0 == 0).eq([(0, 1)].iter()), "row 1: only column 2");
    assert_eq!((PRINTED_MATRIX[0][1], by_hand[0][1]), (31, 32));
    assert_eq!(PRINTED_MATRIX[12], PRINTED_MATRIX[14], "printed row 13 repeats row 15");
    assert_ne!(by_hand[12], by_hand[14]);
    // shifting the printed row 13 one column left gives the true row
    let mut shifted = [0i64; 16];
    shifted[..15].copy_from_slice(&PRINTED_MATRIX[12][1..]);
    assert_eq!(shifted, by_hand[12]);
    // affine invariance: every assembled row sums to 1; the printed row 1 does not
    for (r, row) in assembled.iter().enumerate() {
        assert_eq!(row.iter().fold(Rational::zero(), |a, x| a + x), Rational::one(), "row {r}");
    }
    assert_eq!(PRINTED_MATRIX[0].iter().sum::<i64>(), 143);
}

/// The printed matrix, taken as printed, has neither the eigenvalue 1 (its row
/// 1 does not sum to 1, and 1 is not a root of its characteristic polynomial)
/// nor full rank (rows 13 and 15 coincide, so 0 is an eigenvalue): its spectrum
/// is not the printed list, whatever the list.
#[test]
fn printed_matrix_as_typed_has_another_spectrum() {
    let m: Vec<Vec<Rational>> = PRINTED_MATRIX.iter().map(|r| r.iter().map(|&x| q(x, 144)).collect()).collect();
    let p = to_qmatrix(&m).charpoly();
    assert!(!p.eval(&Rational::one()).is_zero());
    assert!(p.eval(&Rational::zero()).is_zero());
}

/// Characteristic polynomial of the true 16×16 matrix: rational roots checked
/// by substitution (multiplicity = number of vanishing derivatives).
/// Claims: 1 (×1), 1/2 (×2), 3/8 (×2), 1/16, 1/24 HOLD; 1/4 ×4 is REFUTED
/// (multiplicity 3), and 1/8 (×1), not in the printed list, is an eigenvalue.
#[test]
fn exact_rational_eigenvalues_with_multiplicity() {
    let p = charpoly(&KhanMustafa, &paper_window()).unwrap();
    assert_eq!(p.degree(), 16);
    assert_eq!(p.coeffs[16], Rational::one());
    let expect = [(q(1, 1), 1), (q(1, 2), 2), (q(3, 8), 2), (q(1, 4), 3), (q(1, 8), 1), (q(1, 16), 1), (q(1, 24), 1)];
    for (r, m) in &expect {
        assert_eq!(multiplicity_by_derivatives(&p, r), *m, "multiplicity of {r}");
    }
    // the printed multiplicity of 1/4
    assert_ne!(multiplicity_by_derivatives(&p, &q(1, 4)), 4);
    // geometric multiplicities (exact ranks): the subdominant 1/2 is not defective
    let s = to_qmatrix(&assembled_paper_matrix());
    assert_eq!(16 - s.shifted(&q(1, 2)).rank(), 2);
    assert_eq!(16 - s.shifted(&q(1, 4)).rank(), 3);
    assert_eq!(16 - s.shifted(&q(3, 8)).rank(), 2);
}

/// The remaining degree-5 factor: the printed pair −1/16 ± (√5/48) i are the
/// roots of x² + x/8 + 7/1152 (sum −1/8, product 1/256 + 5/2304 = 7/1152);
/// it divides exactly (HOLDS) and has negative discriminant, so it is
/// irreducible over Q. The quotient is a cubic without rational roots (rational
/// root theorem), hence irreducible, and the paper's Cardano expressions are its
/// roots (HOLDS): with c³ = 46450 + 18√1510431, u = −c/432, v = −593/(216c),
/// x = 25/216 + u + v solves x³ + a₂x² + a₁x + a₀ iff 25/216 = −a₂/3,
/// uv = −p/3 and u³ + v³ = −q for the depressed cubic t³ + pt + q; u³ + v³ is
/// rational iff 46450² − 18²·1510431 = 8·593³, and then equals −2·46450/432³.
#[test]
fn irrational_eigenvalues_match_the_printed_closed_forms() {
    let p = charpoly(&KhanMustafa, &paper_window()).unwrap();
    let rational =
        [q(1, 1), q(1, 2), q(1, 2), q(3, 8), q(3, 8), q(1, 4), q(1, 4), q(1, 4), q(1, 8), q(1, 16), q(1, 24)];
    let (rest, r0) = p.div_rem(&Poly::from_roots(&rational));
    assert!(r0.coeffs.iter().all(|c| c.is_zero()));
    assert_eq!(rest.degree(), 5);
    let quad = Poly { coeffs: vec![q(7, 1152), q(1, 8), q(1, 1)] };
    let disc = q(1, 64) - q(4 * 7, 1152);
    assert!(disc.is_negative());
    let (cubic, r1) = rest.div_rem(&quad);
    assert!(r1.coeffs.iter().all(|c| c.is_zero()), "x² + x/8 + 7/1152 divides the characteristic polynomial");
    assert_eq!(cubic.degree(), 3);
    let lead = cubic.coeffs[3].clone();
    let (a0, a1, a2) = (&cubic.coeffs[0] / &lead, &cubic.coeffs[1] / &lead, &cubic.coeffs[2] / &lead);
    // no rational roots: clear denominators, try ±d/e with d | constant, e | leading
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 {
            a.abs()
        } else {
            gcd(b, a % b)
        }
    }
    let den = [&a0, &a1, &a2].iter().fold(1i64, |l, c| {
        let d = i64::try_from(c.denom().clone()).unwrap();
        l / gcd(l, d) * d
    });
    let ints: Vec<i64> = [&a0, &a1, &a2, &Rational::one()]
        .iter()
        .map(|c| i64::try_from((*c * q(den, 1)).to_integer()).unwrap())
        .collect();
    let divisors = |n: i64| (1..=n.abs()).filter(move |d| n % d == 0).collect::<Vec<_>>();
    for d in divisors(ints[0]) {
        for e in divisors(ints[3]) {
            for sign in [1, -1] {
                assert!(!cubic.eval(&q(sign * d, e)).is_zero(), "rational root {}", q(sign * d, e));
            }
        }
    }
    // Cardano with the paper's numbers
    assert_eq!(-&a2 / q(3, 1), q(25, 216), "the paper's shift 25/216");
    let pp = &a1 - &a2 * &a2 / q(3, 1);
    let qq = q(2, 27) * &a2 * &a2 * &a2 - &a2 * &a1 / q(3, 1) + &a0;
    assert_eq!(q(593, 432 * 216), -&pp / q(3, 1), "uv = −p/3");
    let (a, b, d) = (46450i128, 18i128, 1510431i128);
    assert_eq!(a * a - b * b * d, 8 * 593i128.pow(3), "√1510431 cancels in u³ + v³");
    assert_eq!(Rational::new((-2 * 46450).into(), 432i64.pow(3).into()), -qq, "u³ + v³ = −q");
    // and numerically, the three printed expressions are roots of the cubic
    let c = (46450.0 + 18.0 * 1510431f64.sqrt()).cbrt();
    let real = -c / 432.0 - 593.0 / (216.0 * c) + 25.0 / 216.0;
    let re = c / 864.0 + 593.0 / (432.0 * c) + 25.0 / 216.0;
    let im = 3f64.sqrt() / 8.0 * (-c / 108.0 + 593.0 / (54.0 * c));
    let f = |x: num_complex::Complex64| {
        let k = |r: &Rational| num_complex::Complex64::new(subdlab::numeric::Weight::to_f64(r), 0.0);
        x * x * x + k(&a2) * x * x + k(&a1) * x + k(&a0)
    };
    for z in [
        num_complex::Complex64::new(real, 0.0),
        num_complex::Complex64::new(re, im),
        num_complex::Complex64::new(re, -im),
    ] {
        assert!(f(z).norm() < 1e-12, "{z} is not a root");
    }
}

/// Claim: the scheme satisfies Reif's spectral condition (2.3). HOLDS on the
/// minimal window and on the analysis window (the characteristic map claim of
/// the paper is not checked here). The analysis window's spectrum contains the
/// minimal one (the minimal window is invariant inside it, so its matrix is a
/// diagonal block of a block-triangular form): checked as exact divisibility.
#[test]
fn reif_spectral_condition_and_window_dependence() {
    for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
        let a = analyse(&KhanMustafa, kind, true).unwrap();
        let s = &a.spectrum;
        assert!(s.verdict.c1_spectral, "{kind:?}: {:?}", s.verdict.reasons);
        assert_eq!(s.eigenvalues[0].exact.as_deref(), Some("1"));
        assert_eq!(s.eigenvalues[1].exact.as_deref(), Some("1/2"));
        assert_eq!(s.eigenvalues[1].algebraic_multiplicity, 2);
        assert_eq!(s.eigenvalues[2].exact.as_deref(), Some("3/8"));
        let x = s.exact_analysis.as_ref().unwrap();
        assert!(x.agrees_with_float, "{kind:?}: float multiplicities disagree with exact ones");
    }
    let p16 = charpoly(&KhanMustafa, &paper_window()).unwrap();
    let p36 = charpoly(&KhanMustafa, &Window::rect(-3, 2, -3, 2)).unwrap();
    let (_, r) = p36.div_rem(&p16);
    assert!(r.coeffs.iter().all(|c| c.is_zero()));
}

#[test]
fn cubic_variant_matrix_is_affine_invariant() {
    let w = minimal_invariant_window(&KhanMustafaCubic, &[(0, 0)]).unwrap();
    let m = local_matrix::<Rational>(&KhanMustafaCubic, &w).unwrap();
    for row in &m {
        assert_eq!(row.iter().fold(Rational::zero(), |a, x| a + x), Rational::one());
    }
    let p = to_qmatrix(&m).charpoly();
    assert!(p.eval(&Rational::one()).is_zero());
}

#[test]
fn stencils_follow_the_fine_index_parity() {
    // fine point (−1, 2) = (2·(−1) + 1, 2·1 + 0): the p_{2i+1,2j} rule centred at p_{−1,1}
    let st = stencil::<Rational>(&KhanMustafa, (-1, 2));
    let w = |p: Point| st.iter().find(|e| e.0 == p).map(|e| e.1.clone()).unwrap();
    assert_eq!(w((0, 1)), q(50, 144)); // p_{i+1,j}
    assert_eq!(w((-2, 0)), q(-22, 144)); // p_{i−1,j−1}
    assert_eq!(st.len(), 9);
}

#[test]
fn scheme_names() {
    assert_eq!(LatticeScheme::name(&KhanMustafa), "khan-mustafa");
    assert_eq!(LatticeScheme::name(&KhanMustafaCubic), "khan-mustafa-cubic");
}

// ---------------------------------------------------------------- command line

#[test]
fn cli_spectrum_json_has_the_stable_fields() {
    let out = subdlab(&["spectrum", "khan-mustafa", "--valence", "4", "--neighbourhood", "minimal", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["scheme"], "khan-mustafa");
    assert_eq!(v["valence"], 4);
    assert!(v["params"].is_object());
    assert_eq!(v["matrix_size"], 16);
    assert_eq!(v["blocks"][0]["index"], 0);
    assert_eq!(v["blocks"][0]["size"], 16);
    let eig = v["eigenvalues"].as_array().unwrap();
    for e in eig {
        for f in ["re", "im", "modulus", "algebraic_multiplicity", "geometric_multiplicity", "block"] {
            assert!(!e[f].is_null(), "field {f}");
        }
        assert!(e.get("exact").is_some());
    }
    let total: u64 = eig.iter().map(|e| e["algebraic_multiplicity"].as_u64().unwrap()).sum();
    assert_eq!(total, 16);
    assert_eq!(eig[1]["exact"], "1/2");
    assert_eq!(v["verdict"]["c1_spectral"], true);
    assert!(v["verdict"]["reasons"].is_array());
}

#[test]
fn cli_matrix_exports_and_lists_the_scheme() {
    let out = subdlab(&["matrix", "khan-mustafa", "--valence", "4", "--neighbourhood", "minimal", "--format", "json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["size"], 16);
    // row p[i-2,j-2] (the paper's first row): the vertex rule centred at p[i-1,j-1], 32/144 at p[i-1,j-2]
    assert_eq!(v["labels"][0], "p[i-2,j-2]");
    assert_eq!(v["exact"][0][1], "2/9");
    let out = subdlab(&["matrix", "khan-mustafa-cubic", "--valence", "4", "--format", "mtx"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("%%MatrixMarket matrix coordinate real general"));
    let out = subdlab(&["schemes"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("khan-mustafa ") && text.contains("khan-mustafa-cubic"));
}

#[test]
fn cli_rejects_other_valences_and_options_with_one_line() {
    let e = fails(&["spectrum", "khan-mustafa", "--valence", "5"]);
    assert!(e.contains("khan-mustafa is defined on the regular quad lattice only (valence 4)"), "{e}");
    fails(&["matrix", "khan-mustafa-cubic", "--valence", "3", "--format", "mtx"]);
    fails(&["spectrum", "khan-mustafa", "--valence", "4", "--method", "dft"]);
    fails(&["spectrum", "khan-mustafa", "--valence", "4", "--param", "a=1"]);
    fails(&["spectrum", "khan-mustafa", "--valence", "4", "--neighbourhood", "huge"]);
    fails(&["matrix", "khan-mustafa", "--valence", "4", "--format", "csv"]);
}
