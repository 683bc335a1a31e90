//! The shape chart (`subdlab::shape_chart`) against the spectra derived by
//! hand from the schemes' masks, never against numbers the program printed.
//!
//! Each expectation of issue 25 §1 is checked through a second route: the
//! closed-form Fourier-block eigenvalues of the 1-ring (derived below from
//! the masks), which say which eigenvalue ν* carries each input's central
//! shape and what g = |ν*|/λ² is, and — for the 4-3 Jordan chains — exact
//! rational nullities of S − ¼I and (S − ¼I)². The chart's categories then
//! follow from which Fourier blocks ν* lives in: the inputs
//! q_{t,θ} = u² + t v² are |x|²(1 + t)/2 in block 0 plus a frequency-2 part
//! (1 − t)/2 · cos 2(φ − θ) in blocks ±2, so t = 1 has no block-2 part and
//! t = −1 no block-0 part.

use subdlab::curvature::jordan::exact_jordan;
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::numeric::Rational;
use subdlab::schemes;
use subdlab::shape_chart::{chart, Category, ChartOptions, Row, ValenceChart};
use subdlab::spectrum::{analyse_shared, Options};

const TS: [f64; 7] = [-1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0];

fn options() -> ChartOptions {
    ChartOptions { ts: TS.to_vec(), thetas: 2, steps: vec![0, 3], ..ChartOptions::default() }
}

fn chart_of(name: &str, n: usize, faces: Option<&str>) -> ValenceChart {
    let s = schemes::build(name, &[]).unwrap();
    let config = match faces {
        Some(f) => Configuration::with_faces(s.as_ref(), n, f).unwrap(),
        None => Configuration::regular(s.as_ref(), n).unwrap(),
    };
    let c = chart(s.as_ref(), &config, &options()).unwrap();
    assert!(c.error.is_none(), "{name} n = {n}: {:?}", c.error);
    c
}

fn central(c: &ValenceChart) -> impl Iterator<Item = &Row> {
    c.rows.iter().filter(|r| r.central())
}

fn cos(k: f64, n: usize) -> f64 {
    (2.0 * std::f64::consts::PI * k / n as f64).cos()
}

/// Catmull–Clark, 1-ring (v; edge neighbours e_j; face neighbours f_j):
/// face point (v + e_j + e_{j+1} + f_j)/4, edge point 3/8 (v + e_j) +
/// 1/16 (e_{j−1} + e_{j+1} + f_{j−1} + f_j), vertex point
/// (1 − 7/(4n)) v + 3/(2n²) Σ e + 1/(4n²) Σ f.
///
/// Block k ≠ 0 (ω = 2πk/n): the 2 × 2 block of (e, f) has the eigenvalues
/// (5 + cos ω ± cos(ω/2) √(18 + 2 cos ω))/16 (Stam 1998), λ = the larger at
/// k = 1. Block 0, rows (v, e, f): [1 − 7/(4n), 3/(2n), 1/(4n)],
/// [3/8, 1/2, 1/8], [1/4, 1/2, 1/4]: eigenvalue 1 (rows sum to one), and the
/// other two have sum (trace − 1) = 3/4 − 7/(4n) and product det = (1 − 3/n)/16.
/// The 2-ring adds the regular bicubic eigenvalues 1/8, 1/16, 1/32, 1/64,
/// all below λ² ≥ 0.168 (n ≥ 3), so they never carry ν*.
struct CcSpectrum {
    lambda: f64,
    /// the larger block-0 eigenvalue below 1
    mu0: f64,
    /// the larger eigenvalue of block 2 (for n = 3 block 2 is block 1: the
    /// smaller root, λ itself being the affine part)
    mu2: f64,
}

fn cc(n: usize) -> CcSpectrum {
    let block = |k: f64| {
        let w = cos(k, n);
        let half = (std::f64::consts::PI * k / n as f64).cos().abs();
        let r = (18.0 + 2.0 * w).sqrt();
        ((5.0 + w + half * r) / 16.0, (5.0 + w - half * r) / 16.0)
    };
    let lambda = block(1.0).0;
    let (sum, product) = (0.75 - 7.0 / (4.0 * n as f64), (1.0 - 3.0 / n as f64) / 16.0);
    let mu0 = (sum + (sum * sum - 4.0 * product).sqrt()) / 2.0;
    let mu2 = if n == 3 { block(1.0).1 } else { block(2.0).0 };
    CcSpectrum { lambda, mu0, mu2 }
}

/// CC n = 4 is the regular bicubic B-spline: its refined control values of a
/// quadratic are the quadratic plus a constant (quadratic precision), so at
/// every step and at m = ∞ every input is reproduced: all correct.
#[test]
fn catmull_clark_regular_reproduces_every_input() {
    let c = chart_of("catmull-clark", 4, None);
    assert!((c.lambda.unwrap() - 0.5).abs() < 1e-12);
    for r in &c.rows {
        assert_eq!(r.category, Category::Correct, "t = {} θ = {} m = {}: {r:?}", r.t, r.theta_degrees, r.m);
        assert!(!r.divergent);
    }
    // λ² = 1/4 is the block-0 root (sum 5/16, product 1/64: 1/4 and 1/16)
    let s = cc(4);
    assert!((s.mu0 - 0.25).abs() < 1e-15 && (s.mu2 - 0.25).abs() < 1e-15);
    assert!(central(&c).all(|r| (r.g - 1.0).abs() < 1e-8));
}

/// CC n = 3: block 0's roots are 1/6 and 0 (product (1 − 3/3)/16 = 0), block
/// 2 is block 1, whose second root is below 1/6, and λ² ≈ 0.16818 > 1/6:
/// every input's central shape decays relative to λ², flat at m = ∞. Inputs
/// with a block-0 part take ν* = 1/6; x² − y² (t = −1) takes block 1's
/// second root.
#[test]
fn catmull_clark_three_is_flat_at_the_centre() {
    let s = cc(3);
    assert!((s.mu0 - 1.0 / 6.0).abs() < 1e-15);
    assert!(s.mu2 < s.mu0 && s.mu0 < s.lambda * s.lambda);
    let c = chart_of("catmull-clark", 3, None);
    assert!((c.lambda.unwrap() - s.lambda).abs() < 1e-12);
    let l2 = s.lambda * s.lambda;
    for r in central(&c) {
        assert_eq!(r.category, Category::Flat, "{r:?}");
        let want = if r.t == -1.0 { s.mu2 } else { s.mu0 };
        assert!((r.g - want / l2).abs() < 1e-9, "t = {}: g = {}, want {}", r.t, r.g, want / l2);
    }
}

/// The second route (deflated iteration, `ChartOptions::iterated`) reads
/// the same g from growth alone: on CC its rate (‖h_96‖/‖h_48‖)^(1/48) is
/// the closed-form ν*/λ² of the tests above — μ0/λ² < 1 at n = 3 (flat) and
/// μ2/λ² > 1 at n = 5 for inputs with a block-2 part (t < 1), μ0/λ² for
/// x² + y² (t = 1, no block-2 part: the restriction to the input's Fourier
/// blocks keeps rounding from seeding the larger μ2).
#[test]
fn the_iterated_route_grows_like_the_closed_form_g() {
    for n in [3, 5] {
        let s = schemes::build("catmull-clark", &[]).unwrap();
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let opts =
            ChartOptions { ts: vec![-1.0, 0.5, 1.0], thetas: 2, steps: vec![], iterated: Some((48, 96)), ..options() };
        let c = chart(s.as_ref(), &config, &opts).unwrap();
        let k = cc(n);
        let l2 = k.lambda * k.lambda;
        assert_eq!(c.iterated.len(), 6);
        for it in &c.iterated {
            let want = if n == 3 {
                (if it.t == -1.0 { k.mu2 } else { k.mu0 }) / l2
            } else if it.t == 1.0 {
                k.mu0 / l2
            } else {
                k.mu2 / l2
            };
            assert!((it.rate - want).abs() < 1e-3 * want, "n = {n} t = {}: rate {} against g = {want}", it.t, it.rate);
            if n == 3 {
                assert_eq!(it.category, Category::Flat, "{it:?}");
            } else {
                assert_ne!(it.category, Category::Flat, "{it:?}");
            }
        }
    }
}

/// CC n ≥ 5: the block-2 root exceeds the block-0 root, which exceeds λ²
/// (μ2 > μ0 > λ²). Every input with a block-2 part (t < 1) has the block-2
/// eigenfunction alone as its central shape — a frequency-2 height, a saddle
/// — so elliptic inputs with t < 1 come out with the wrong sign (the known
/// wrong limit shape of Catmull–Clark), and every input diverges (g > 1:
/// also x² + y², through μ0 > λ²).
#[test]
fn catmull_clark_high_valence_turns_elliptic_inputs_into_saddles() {
    for n in [5, 6, 8] {
        let s = cc(n);
        let l2 = s.lambda * s.lambda;
        assert!(s.mu2 > s.mu0 && s.mu0 > l2, "n = {n}");
        let c = chart_of("catmull-clark", n, None);
        assert!((c.lambda.unwrap() - s.lambda).abs() < 1e-12);
        for r in central(&c) {
            assert!(r.divergent, "n = {n}: {r:?}");
            let want = if r.t == 1.0 { s.mu0 } else { s.mu2 };
            assert!((r.g - want / l2).abs() < 1e-9, "n = {n} t = {}: g = {}, want {}", r.t, r.g, want / l2);
            if r.t > 0.0 && r.t < 1.0 {
                assert_eq!(r.category, Category::WrongSign, "n = {n}: {r:?}");
            }
            if r.t < 0.0 {
                // hyperbolic inputs keep their sign (a saddle stays a saddle)
                assert_eq!(r.category, Category::RightSign, "n = {n}: {r:?}");
            }
        }
    }
}

/// Loop, 1-ring (v; e_j): vertex (1 − nβ) v + β Σ e, β = (5/8 − (3/8 +
/// cos(2π/n)/4)²)/n; edge 3/8 (v + e_j) + 1/8 (e_{j−1} + e_{j+1}). Block
/// k ≠ 0: 3/8 + cos(2πk/n)/4 (λ at k = 1); block 0 [[1 − nβ, nβ], [3/8, 5/8]]
/// has 1 and 5/8 − nβ = (3/8 + cos(2π/n)/4)² = λ² exactly (Loop's choice of
/// β). The 2-ring adds the regular eigenvalues 1/8 and 1/16 (box spline).
///
/// n = 4, 5: block 2's 3/8 + cos(4π/n)/4 (1/8 at n = 4, ≈ 0.1727 at n = 5)
/// and 1/8 are below λ² (9/64; ≈ 0.2045), so every input with a block-0 part
/// (t > −1) has the rotation-symmetric block-0 eigenfunction as its central
/// shape (g = 1): one-signed, elliptic. Hyperbolic inputs −1 < t < 0 come out
/// elliptic (wrong sign); x² − y² (t = −1, no block 0) is flat.
#[test]
fn loop_low_valence_turns_saddles_elliptic() {
    for n in [4, 5] {
        let lambda = 0.375 + cos(1.0, n) / 4.0;
        let l2 = lambda * lambda;
        let mu2 = (0.375 + cos(2.0, n) / 4.0).max(0.125);
        assert!(mu2 < l2);
        let c = chart_of("loop", n, None);
        assert!((c.lambda.unwrap() - lambda).abs() < 1e-12);
        for r in central(&c) {
            if r.t == -1.0 {
                assert_eq!(r.category, Category::Flat, "n = {n}: {r:?}");
                assert!((r.g - mu2 / l2).abs() < 1e-9, "n = {n}: g = {}, want {}", r.g, mu2 / l2);
            } else {
                assert!((r.g - 1.0).abs() < 1e-8 && !r.divergent, "n = {n}: {r:?}");
            }
            if r.t > -1.0 && r.t < 0.0 {
                assert_eq!(r.category, Category::WrongSign, "n = {n}: {r:?}");
            }
            if r.t > 0.0 {
                assert!(matches!(r.category, Category::RightSign | Category::Correct), "n = {n}: {r:?}");
            }
        }
    }
}

/// Loop n = 6 is the regular three-direction quartic box spline: quadratic
/// precision, every input reproduced at every step.
#[test]
fn loop_regular_reproduces_every_input() {
    let c = chart_of("loop", 6, None);
    for r in &c.rows {
        assert_eq!(r.category, Category::Correct, "{r:?}");
    }
}

/// Peters–Shiue 4-3 (derivation in `curvature_jordan.rs`): at an eon of
/// valence n, block m ≥ 2 is [[1/4, 0], [(1 + ω)/4, 1/4]] on (e, f),
/// ω = e^{2πim/n}: the eigenvalue 1/4 = λ² (λ = 1/2) with a Jordan chain
/// unless ω = −1, whose top (the f-direction) shows on the ring. Block 2 has
/// ω = −1 only at n = 4. Block 0 on (v, e, f) is lower triangular in f:
/// [[α, 1 − α, 0], [1/2, 1/2, 0], [1/4, 1/2, 1/4]] with α = 3/5 (n > 4), so
/// its eigenvalues 1, α − 1/2 = 1/10 and 1/4 are simple: no chain. Hence at
/// n ≥ 5 every input with a block-2 part (t < 1) is divergent through a
/// Jordan chain at g = 1, and x² + y² is not; at n = 4 (QQQQ, the regular
/// four-direction box spline) every input is reproduced. At n = 6 the
/// chain is confirmed in exact arithmetic as well.
#[test]
fn four_three_eons_diverge_through_block_two() {
    let c = chart_of("four-three", 4, Some("QQQQ"));
    for r in &c.rows {
        assert_eq!(r.category, Category::Correct, "QQQQ: {r:?}");
    }
    let s = schemes::build("four-three", &[]).unwrap();
    for n in [5, 6] {
        let faces = "Q".repeat(n);
        let c = chart_of("four-three", n, Some(&faces));
        assert!((c.lambda.unwrap() - 0.5).abs() < 1e-12);
        for r in central(&c) {
            assert!((r.g - 1.0).abs() < 1e-8, "n = {n}: {r:?}");
            if r.t < 1.0 {
                assert!(r.jordan && r.divergent, "n = {n}: {r:?}");
            } else {
                assert!(!r.jordan && !r.divergent, "n = {n}: {r:?}");
            }
        }
        // the second route: exact nullities over Q of S − ¼I and (S − ¼I)²,
        // where S is rational (the eon's edge weights (1 + 2cos(2πk/n))/n
        // are rational at n = 6, not at n = 5)
        if n != 6 {
            continue;
        }
        let config = Configuration::with_faces(s.as_ref(), n, &faces).unwrap();
        let exact = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: true };
        let a = analyse_shared(s.as_ref(), &config, &exact).unwrap();
        let quarter = Rational::new(1.into(), 4.into());
        let j = exact_jordan(&a, &quarter).expect("4-3's S is rational");
        assert!(j.defective && j.nullity_squared > j.nullity, "n = {n}: {j:?}");
    }
}

/// The chart's rows are complete: every (t, θ, m) once, m = ∞ included, and
/// θ over [0, 360°/g) with g the rotation group's order (72° at n = 5).
#[test]
fn rows_cover_the_grid() {
    let c = chart_of("catmull-clark", 5, None);
    assert_eq!(c.group_order, 5);
    assert_eq!(c.theta_range_degrees, 72.0);
    assert_eq!(c.thetas, vec![0.0, 36.0]);
    assert_eq!(c.rows.len(), TS.len() * 2 * 3);
    for m in ["0", "3", "inf"] {
        assert_eq!(c.rows.iter().filter(|r| r.m == m).count(), TS.len() * 2);
    }
    // at m = 0 the shape is the input itself: an elliptic x² + y² keeps its sign
    assert!(c.rows.iter().filter(|r| r.m == "0" && r.t == 1.0).all(|r| r.sign_fraction > 0.99));
}
