//! Negative controls for the sector verdict at a boundary vertex (issue 26):
//! the verdict must fail where a reason independent of the program says so,
//! and pass where the literature says it passes. Every expected value here
//! is derived by hand below (and checked in exact arithmetic), none is a
//! number the program printed.
//!
//! The derivation. A boundary vertex c of k sectors (faces), its edge
//! neighbours v_0 .. v_k (v_0 and v_k on the boundary), and for
//! Catmull–Clark the far corners f_0 .. f_{k−1} (f_s in the quad
//! c, v_s, f_s, v_{s+1}). The rules (Hoppe et al. 1994; the edge rule next
//! to c with Biermann–Levin–Zorin's γ where `blz` is set):
//!
//! - c' = 3/4 c + 1/8 (v_0 + v_k); v_0' = (c + v_0)/2, v_k' = (c + v_k)/2
//! - v_j' (0 < j < k) = (3/4 − γ) c + γ v_j + CC: 1/16 (v_{j−1} + v_{j+1} +
//!   f_{j−1} + f_j), Loop: 1/8 (v_{j−1} + v_{j+1}); γ = 3/8 (Hoppe: the
//!   smooth edge rule)
//! - f_s' = (c + v_s + v_{s+1} + f_s)/4 (the face point)
//!
//! 1. Every new point of the 1-ring R = {c, v_s, f_s} is a rule over R
//!    alone, so S = [[A, 0], [B, C]] (R first) and spec S = spec A ∪ spec C;
//!    where μ is not an eigenvalue of C, the Jordan structure of μ in S is
//!    that of A ((S − μ)(x, y) = 0 iff (A − μ)x = 0 and y = −(C − μ)⁻¹Bx).
//! 2. A is block triangular again: the curve rows (c, v_0, v_k) read only
//!    the curve, with eigenvalues 1, 1/2, 1/4 (eigenvectors (1, 1, 1),
//!    (0, 1, −1), (1, −2, −2)). On the interior block T (the curve set to
//!    zero) the sine modes v_j = a sin(jφ), f_j = b sin((j + 1/2)φ),
//!    φ = mπ/k, m = 1 .. k − 1, are eigenvectors: Loop λ = γ + cos(φ)/4;
//!    Catmull–Clark the two eigenvalues of M(φ) = [[γ + cos φ/8, cos(φ/2)/8],
//!    [cos(φ/2)/2, 1/4]], and 1/4 once more (m = k: the faces alternate).
//! 3. Hoppe's γ = 3/8 puts the mode m at 1/2 when mπ/k = π/3 (Loop: the
//!    regular valence 6) or π/2 (Catmull–Clark: valence 4), i.e. k = 3m or
//!    k = 2m. The curve's tangent (0, 1, −1) then couples to the mode
//!    through B (the rows v_1, f_0 read v_0, the rows v_{k−1}, f_{k−1} read
//!    v_k) by sin(mφ')(1 + (−1)^m) up to a factor: zero for odd m (m = 1: the
//!    regular boundary, 1/2 double and non-defective), non-zero for even m
//!    (m = 2: Catmull–Clark k = 4, Loop k = 6, 1/2 defective). For larger k
//!    two modes lie above 1/2, and their eigenvectors vanish on the curve
//!    (any eigenvalue outside the curve's spectrum does, by 2.): the
//!    characteristic map sends both boundary rays to the centre.
//! 4. BLZ choose γ so that the mode m = 1 is 1/2 exactly (Loop: γ = 1/2 −
//!    cos(π/k)/4, Catmull–Clark: M(π/k) has eigenvalue 1/2 iff γ = 3/8 −
//!    cos(π/k)/4), the other modes below it; m = 1 is odd, so 1/2 is double
//!    and non-defective at every k.
//!
//! The tests check the program's S against the hand rules (exactly, or to
//! rounding where γ is irrational), the modes against the hand matrix, the
//! Jordan structure at μ by exact ranks over Q(√d), and bound spec C by an
//! exact norm of a power of C; then the program's verdict and the raster
//! characteristic map must agree with what that proves.

use crate::common::exact::q;
use num_traits::{Signed, ToPrimitive, Zero};
use subdlab::charmap::{characteristic_map, CharMapOptions};
use subdlab::neighbourhood::{Configuration, Tagging};
use subdlab::numeric::Rational;
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Analysis, Options};

// ---- Q(√d): enough of a number field for the BLZ weights ----

/// a + b√d (d a square-free integer; d is irrelevant while b = 0).
#[derive(Clone, Debug)]
struct Qd {
    a: Rational,
    b: Rational,
    d: i64,
}

impl Qd {
    fn rat(a: Rational) -> Qd {
        Qd { a, b: Rational::zero(), d: 1 }
    }
    fn r(p: i64, s: i64) -> Qd {
        Qd::rat(q(p, s))
    }
    fn d_of(&self, o: &Qd) -> i64 {
        match (self.b.is_zero(), o.b.is_zero()) {
            (true, _) => o.d,
            (_, true) => self.d,
            _ => {
                assert_eq!(self.d, o.d, "one field at a time");
                self.d
            }
        }
    }
    fn add(&self, o: &Qd) -> Qd {
        Qd { a: &self.a + &o.a, b: &self.b + &o.b, d: self.d_of(o) }
    }
    fn sub(&self, o: &Qd) -> Qd {
        Qd { a: &self.a - &o.a, b: &self.b - &o.b, d: self.d_of(o) }
    }
    fn mul(&self, o: &Qd) -> Qd {
        let d = self.d_of(o);
        Qd { a: &self.a * &o.a + &self.b * &o.b * q(d, 1), b: &self.a * &o.b + &self.b * &o.a, d }
    }
    fn inv(&self) -> Qd {
        // (a − b√d)/(a² − d b²); the norm is non-zero for a non-zero element of a field
        let norm = &self.a * &self.a - &self.b * &self.b * q(self.d, 1);
        assert!(!norm.is_zero(), "inverse of zero");
        Qd { a: &self.a / &norm, b: -(&self.b / &norm), d: self.d }
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    fn f64(&self) -> f64 {
        self.a.to_f64().unwrap() + self.b.to_f64().unwrap() * (self.d as f64).sqrt()
    }
}

type QdMat = Vec<Vec<Qd>>;

/// Rank over Q(√d) by Gaussian elimination.
fn rank(mut a: QdMat) -> usize {
    let (rows, cols) = (a.len(), a.first().map_or(0, Vec::len));
    let mut r = 0;
    for c in 0..cols {
        let Some(p) = (r..rows).find(|&i| !a[i][c].is_zero()) else { continue };
        a.swap(r, p);
        let inv = a[r][c].inv();
        let pivot = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != r && !row[c].is_zero() {
                let f = row[c].mul(&inv);
                for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                    *x = x.sub(&f.mul(p));
                }
            }
        }
        r += 1;
    }
    r
}

fn shifted(a: &QdMat, mu: &Qd) -> QdMat {
    let mut m = a.clone();
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = row[i].sub(mu);
    }
    m
}

fn square(a: &QdMat) -> QdMat {
    let n = a.len();
    (0..n).map(|i| (0..n).map(|j| (0..n).fold(Qd::r(0, 1), |s, k| s.add(&a[i][k].mul(&a[k][j])))).collect()).collect()
}

/// (dim ker(A − μ), dim ker(A − μ)²): (1, 2) is a 2 × 2 Jordan block, (2, 2)
/// a double non-defective eigenvalue.
fn nullities(a: &QdMat, mu: &Qd) -> (usize, usize) {
    let s = shifted(a, mu);
    let n = a.len();
    (n - rank(s.clone()), n - rank(square(&s)))
}

/// cos(π/k) in Q(√d), k = 1 .. 6 (the values with a square root at most).
fn cos_pi_over(k: usize) -> Qd {
    let half = q(1, 2);
    match k {
        1 => Qd::r(-1, 1),
        2 => Qd::r(0, 1),
        3 => Qd::r(1, 2),
        4 => Qd { a: q(0, 1), b: half, d: 2 },
        5 => Qd { a: q(1, 4), b: q(1, 4), d: 5 },
        6 => Qd { a: q(0, 1), b: half, d: 3 },
        _ => panic!("cos(π/{k}) is not in a quadratic field"),
    }
}

// ---- the two schemes and their hand rules ----

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    CatmullClark,
    Loop,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::CatmullClark => "catmull-clark",
            Kind::Loop => "loop",
        }
    }
    /// Hoppe's γ (the smooth edge rule's weight on each end: 3/8 for both
    /// schemes) or BLZ's (derivation item 4).
    fn gamma(self, k: usize, blz: bool) -> Qd {
        let base = if blz {
            match self {
                Kind::CatmullClark => q(3, 8),
                Kind::Loop => q(1, 2),
            }
        } else {
            return Qd::r(3, 8);
        };
        Qd::rat(base).sub(&cos_pi_over(k).mul(&Qd::r(1, 4)))
    }
    fn gamma_f64(self, k: usize, blz: bool) -> f64 {
        let c = (std::f64::consts::PI / k as f64).cos();
        match (blz, self) {
            (false, _) => 0.375,
            (true, Kind::CatmullClark) => 0.375 - c / 4.0,
            (true, Kind::Loop) => 0.5 - c / 4.0,
        }
    }
}

/// 1-ring positions in hand order: c, v_0 .. v_k, then (CC) f_0 .. f_{k−1}.
fn ring_size(kind: Kind, k: usize) -> usize {
    match kind {
        Kind::CatmullClark => 2 * k + 2,
        Kind::Loop => k + 2,
    }
}

/// The hand matrix A over the 1-ring (derivation, the rules), γ given.
fn hand_matrix(kind: Kind, k: usize, gamma: &Qd) -> QdMat {
    let n = ring_size(kind, k);
    let (c, v, f) = (0, |s: usize| 1 + s, |s: usize| k + 2 + s);
    let mut a = vec![vec![Qd::r(0, 1); n]; n];
    a[c][c] = Qd::r(3, 4);
    a[c][v(0)] = Qd::r(1, 8);
    a[c][v(k)] = Qd::r(1, 8);
    for e in [0, k] {
        a[v(e)][c] = Qd::r(1, 2);
        a[v(e)][v(e)] = Qd::r(1, 2);
    }
    for j in 1..k {
        a[v(j)][c] = Qd::r(3, 4).sub(gamma);
        a[v(j)][v(j)] = gamma.clone();
        let side = if kind == Kind::CatmullClark { Qd::r(1, 16) } else { Qd::r(1, 8) };
        a[v(j)][v(j - 1)] = side.clone();
        a[v(j)][v(j + 1)] = side.clone();
        if kind == Kind::CatmullClark {
            a[v(j)][f(j - 1)] = side.clone();
            a[v(j)][f(j)] = side;
        }
    }
    if kind == Kind::CatmullClark {
        for s in 0..k {
            for col in [c, v(s), v(s + 1), f(s)] {
                a[f(s)][col] = Qd::r(1, 4);
            }
        }
    }
    a
}

/// The closed-form eigenvalues of the interior block T (derivation item 2),
/// each checked as an eigenvalue of the hand matrix with its sine-mode
/// eigenvector (zero on the curve), to rounding.
fn interior_modes(kind: Kind, k: usize, a: &QdMat, gamma: f64) -> Vec<f64> {
    let n = a.len();
    let af: Vec<Vec<f64>> = a.iter().map(|r| r.iter().map(Qd::f64).collect()).collect();
    let (v, f) = (|s: usize| 1 + s, |s: usize| k + 2 + s);
    let mut modes = Vec::new();
    let mut check = |lambda: f64, x: Vec<f64>| {
        for i in 0..n {
            let ax: f64 = (0..n).map(|j| af[i][j] * x[j]).sum();
            assert!((ax - lambda * x[i]).abs() < 1e-12, "{kind:?} k = {k}: mode λ = {lambda} row {i}");
        }
        assert!(x.iter().any(|t| t.abs() > 1e-6));
        modes.push(lambda);
    };
    for m in 1..k {
        let phi = m as f64 * std::f64::consts::PI / k as f64;
        match kind {
            Kind::Loop => {
                let mut x = vec![0.0; n];
                (1..k).for_each(|j| x[v(j)] = (j as f64 * phi).sin());
                check(gamma + phi.cos() / 4.0, x);
            }
            Kind::CatmullClark => {
                let (m11, m12, m21, m22) =
                    (gamma + phi.cos() / 8.0, (phi / 2.0).cos() / 8.0, (phi / 2.0).cos() / 2.0, 0.25);
                let (tr, det) = (m11 + m22, m11 * m22 - m12 * m21);
                for sign in [1.0, -1.0] {
                    let lambda = (tr + sign * (tr * tr - 4.0 * det).sqrt()) / 2.0;
                    let (ca, cb) = (m12, lambda - m11);
                    let mut x = vec![0.0; n];
                    (1..k).for_each(|j| x[v(j)] = ca * (j as f64 * phi).sin());
                    (0..k).for_each(|s| x[f(s)] = cb * ((s as f64 + 0.5) * phi).sin());
                    check(lambda, x);
                }
            }
        }
    }
    if kind == Kind::CatmullClark {
        let mut x = vec![0.0; n];
        (0..k).for_each(|s| x[f(s)] = if s % 2 == 0 { 1.0 } else { -1.0 });
        check(0.25, x);
    }
    modes
}

fn build(kind: Kind, blz: bool) -> Box<dyn Scheme> {
    let params: Vec<(String, String)> = if blz { vec![("blz".into(), "1".into())] } else { Vec::new() };
    schemes::build(kind.name(), &params).unwrap()
}

fn boundary(kind: Kind, k: usize, blz: bool) -> Analysis {
    let s = build(kind, blz);
    let config = Configuration::tagged(s.as_ref(), k, None, Tagging::Boundary).unwrap();
    analyse(s.as_ref(), &config, &Options::default()).unwrap()
}

/// The matrix index of each hand 1-ring position, from the labels (ring 1:
/// v_s at (sector s, 1, 0), f_s at (sector s, 1, 1)).
fn ring_indices(kind: Kind, k: usize, a: &Analysis) -> Vec<usize> {
    let labels = &a.matrix.labels;
    let find = |ring: usize, s: usize, i: i64, j: i64| {
        let hits: Vec<usize> = (0..labels.len())
            .filter(|&r| {
                let l = &labels[r];
                l.ring == ring && (ring == 0 || (l.sector == s && l.i == i && l.j == j))
            })
            .collect();
        assert_eq!(hits.len(), 1, "{kind:?} k = {k}: ring {ring} sector {s} ({i}, {j})");
        hits[0]
    };
    let mut idx = vec![find(0, 0, 0, 0)];
    idx.extend((0..=k).map(|s| find(1, s, 1, 0)));
    if kind == Kind::CatmullClark {
        idx.extend((0..k).map(|s| find(1, s, 1, 1)));
    }
    let ring1 = labels.iter().filter(|l| l.ring <= 1).count();
    assert_eq!(ring1, idx.len(), "{kind:?} k = {k}: the 1-ring is c, the v_s and the f_s");
    idx
}

/// What the derivation proves about S at one configuration.
struct Facts {
    /// the hand matrix A over the 1-ring
    a: QdMat,
    /// spec A, with multiplicity, in decreasing order: the curve's 1, 1/2,
    /// 1/4 and the interior modes
    spec_a: Vec<f64>,
    /// a bound r with every eigenvalue of C below r in modulus
    rest_below: Rational,
}

/// Check the program's S against the hand rules (derivation items 1 and 2)
/// and bound spec C: S's 1-ring rows are A (exactly for rational weights,
/// to 1e-15 otherwise) and read nothing else.
fn facts(kind: Kind, k: usize, blz: bool, rest_below: Rational) -> Facts {
    let an = boundary(kind, k, blz);
    let gamma = if blz && k > 6 { None } else { Some(kind.gamma(k, blz)) };
    let gamma_f = kind.gamma_f64(k, blz);
    let a = hand_matrix(
        kind,
        k,
        &gamma.clone().unwrap_or(Qd { a: Rational::from_float(gamma_f).unwrap(), b: q(0, 1), d: 1 }),
    );
    let idx = ring_indices(kind, k, &an);
    let s = &an.matrix;
    let n = s.labels.len();
    let in_ring: Vec<Option<usize>> = (0..n).map(|r| idx.iter().position(|&x| x == r)).collect();
    for (p, &row) in idx.iter().enumerate() {
        for col in 0..n {
            let want = in_ring[col].map_or(0.0, |qq| a[p][qq].f64());
            let got = s.get(row, col);
            assert!(
                (got - want).abs() < 1e-15,
                "{kind:?} k = {k} blz {blz}: S[{}][{}] = {got}, rules say {want}",
                s.labels[row].name,
                s.labels[col].name
            );
        }
    }
    if let Some(ex) = an.exact_matrix.as_ref() {
        // rational weights: the same, exactly
        for (p, &row) in idx.iter().enumerate() {
            for col in 0..n {
                let want = in_ring[col].map_or(q(0, 1), |qq| a[p][qq].a.clone());
                assert!(a[p].iter().all(|w| w.b.is_zero()));
                assert_eq!(
                    ex.get(row, col),
                    want,
                    "{kind:?} k = {k}: exact S[{}][{}]",
                    s.labels[row].name,
                    s.labels[col].name
                );
            }
        }
    } else {
        assert!(blz, "{kind:?} k = {k}: Hoppe's rules are rational");
    }
    // C: the rows and columns off the 1-ring. Its weights are the smooth
    // and crease rules' dyadic rationals (the BLZ γ is only used on edges
    // at the centre, which are 1-ring points), so f64 holds them exactly.
    let rest: Vec<usize> = (0..n).filter(|r| in_ring[*r].is_none()).collect();
    let c: Vec<Vec<Rational>> = rest
        .iter()
        .map(|&r| {
            rest.iter()
                .map(|&col| {
                    let w = s.get(r, col);
                    let x = Rational::from_float(w).unwrap();
                    assert!((x.denom().bits()) <= 20, "{kind:?} k = {k}: weight {w} of C is not a small dyadic");
                    x
                })
                .collect()
        })
        .collect();
    assert!(spectral_radius_below(&c, &rest_below), "{kind:?} k = {k} blz {blz}: ρ(C) not shown below {rest_below}");
    let mut spec_a = vec![1.0, 0.5, 0.25];
    spec_a.extend(interior_modes(kind, k, &a, gamma_f));
    spec_a.sort_by(|x, y| y.total_cmp(x));
    assert_eq!(spec_a.len(), a.len(), "the modes are all of spec A");
    Facts { a, spec_a, rest_below }
}

/// ρ(C) < r, shown exactly: ρ(C)^m ≤ ‖C^m‖_∞ (maximum absolute row sum), so
/// ‖C^m‖_∞ < r^m for some m = 1, 2, 4, .., 64 suffices.
fn spectral_radius_below(c: &[Vec<Rational>], r: &Rational) -> bool {
    let n = c.len();
    if n == 0 {
        return true;
    }
    let norm =
        |m: &[Vec<Rational>]| m.iter().map(|row| row.iter().fold(Rational::zero(), |s, x| s + x.abs())).max().unwrap();
    let mut p = c.to_vec();
    let mut rm = r.clone();
    for _ in 0..7 {
        if norm(&p) < rm {
            return true;
        }
        p = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        (0..n)
                            .filter(|&t| !p[i][t].is_zero() && !p[t][j].is_zero())
                            .fold(Rational::zero(), |s, t| s + &p[i][t] * &p[t][j])
                    })
                    .collect()
            })
            .collect();
        rm = &rm * &rm;
    }
    false
}

fn verdict_fails_with(a: &Analysis, words: &[&str]) {
    let v = &a.spectrum.verdict;
    assert_eq!(v.criterion, "sector");
    assert!(!v.c1_spectral, "the verdict passes: {:?}", v.reasons);
    let text = v.reasons.join("; ");
    for w in words {
        assert!(text.contains(w), "the reasons do not say '{w}': {text}");
    }
}

fn charmap_of(kind: Kind, k: usize, blz: bool) -> subdlab::charmap::CharMap {
    let s = build(kind, blz);
    let config = Configuration::tagged(s.as_ref(), k, None, Tagging::Boundary).unwrap();
    characteristic_map(s.as_ref(), &config, &CharMapOptions::default()).unwrap()
}

/// Catmull–Clark, one quad at a boundary vertex: spec A = {1, 1/2, 1/4,
/// 1/4}; the curve's 1/4 (eigenvector (1, −2, −2) on c, v_0, v_1) and the
/// face point's 1/4 (f_0' = (c + v_0 + v_1 + f_0)/4) form one Jordan block,
/// since f_0 reads the curve vector with weight (1 − 2 − 2)/4 = −3/4 ≠ 0;
/// ρ(C) < 1/4. So λ1 = 1/2 simple and λ2 = 1/4 defective: the sector
/// criterion fails.
#[test]
fn catmull_clark_one_quad_fails_with_a_defective_quarter() {
    let f = facts(Kind::CatmullClark, 1, false, q(1, 4));
    assert_eq!(f.spec_a, vec![1.0, 0.5, 0.25, 0.25]);
    assert_eq!(nullities(&f.a, &Qd::r(1, 4)), (1, 2), "1/4 is a 2 × 2 Jordan block of A");
    assert_eq!(nullities(&f.a, &Qd::r(1, 2)), (1, 1));
    assert_eq!(f.rest_below, q(1, 4));
    let an = boundary(Kind::CatmullClark, 1, false);
    let e = &an.spectrum.eigenvalues;
    assert!((e[1].re - 0.5).abs() < 1e-12 && e[1].algebraic_multiplicity == 1);
    assert!((e[2].re - 0.25).abs() < 1e-12 && e[2].algebraic_multiplicity == 2 && e[2].geometric_multiplicity == 1);
    verdict_fails_with(&an, &["0.25", "defective"]);
    let map = charmap_of(Kind::CatmullClark, 1, false);
    assert!(!map.regular && !map.injective, "{:?}", map.reasons);
}

/// Hoppe's rules where the mode m = 2 meets the curve's 1/2 (Catmull–Clark
/// k = 4: φ = π/2; Loop k = 6: φ = π/3): 1/2 is a Jordan block, above it
/// only the mode m = 1 (Catmull–Clark: the larger eigenvalue of M(π/4);
/// Loop: 3/8 + cos(π/6)/4 = (3 + √3)/8), so λ2 = 1/2 is defective and the
/// verdict fails.
#[test]
fn hoppe_rules_fail_with_a_defective_half_at_cc_four_and_loop_six() {
    for (kind, k, lambda1) in [
        (Kind::CatmullClark, 4, {
            let p = std::f64::consts::FRAC_PI_4;
            let (m11, m12, m21) = (0.375 + p.cos() / 8.0, (p / 2.0).cos() / 8.0, (p / 2.0).cos() / 2.0);
            let (tr, det) = (m11 + 0.25, m11 * 0.25 - m12 * m21);
            (tr + (tr * tr - 4.0 * det).sqrt()) / 2.0
        }),
        (Kind::Loop, 6, (3.0 + 3f64.sqrt()) / 8.0),
    ] {
        let f = facts(kind, k, false, q(1, 2));
        assert!(
            (f.spec_a[1] - lambda1).abs() < 1e-12 && f.spec_a[2] == 0.5 && f.spec_a[3] == 0.5 && f.spec_a[4] < 0.5,
            "{kind:?}: {:?}",
            f.spec_a
        );
        assert_eq!(nullities(&f.a, &Qd::r(1, 2)), (1, 2), "{kind:?} k = {k}: 1/2 is a Jordan block");
        let an = boundary(kind, k, false);
        let e = &an.spectrum.eigenvalues;
        assert!((e[1].re - lambda1).abs() < 1e-10, "{kind:?}: λ1 = {} against {lambda1}", e[1].re);
        assert!((e[2].re - 0.5).abs() < 1e-10 && e[2].algebraic_multiplicity == 2 && e[2].geometric_multiplicity == 1);
        verdict_fails_with(&an, &["0.5", "defective"]);
        let map = charmap_of(kind, k, false);
        assert!(!map.regular && !map.injective, "{kind:?}: {:?}", map.reasons);
    }
}

/// Hoppe's rules one sector further (Catmull–Clark k = 5, Loop k = 7): the
/// modes m = 1, 2 are both above 1/2, so λ1 and λ2 are interior modes,
/// outside the curve's spectrum, and their eigenvectors vanish on the
/// boundary rays: the characteristic map collapses the rays to the centre.
/// The spectral part alone cannot see this (λ1 > λ2 > |λ3| = 1/2, simple).
#[test]
fn hoppe_rules_collapse_the_rays_at_cc_five_and_loop_seven() {
    for (kind, k) in [(Kind::CatmullClark, 5), (Kind::Loop, 7)] {
        let f = facts(kind, k, false, q(1, 2));
        assert!(f.spec_a[2] > 0.5 + 1e-3 && f.spec_a[3] == 0.5, "{kind:?}: {:?}", f.spec_a);
        let an = boundary(kind, k, false);
        let e = &an.spectrum.eigenvalues;
        assert!((e[1].re - f.spec_a[1]).abs() < 1e-10 && (e[2].re - f.spec_a[2]).abs() < 1e-10, "{kind:?}: {e:?}");
        let map = charmap_of(kind, k, false);
        assert!(!map.regular && !map.injective);
        assert!(map.explanation.contains("vanish on the sharp rays"), "{kind:?}: {}", map.explanation);
    }
}

/// The regular boundary (Catmull–Clark 2 quads, Loop 3 triangles; the
/// bicubic and quartic box spline half-planes): λ1 = λ2 = 1/2 double and
/// non-defective (x along and y across the boundary), |λ3| = 1/4. The
/// verdict passes and the raster finds the map regular and injective.
#[test]
fn the_regular_boundary_passes_with_literature_values() {
    for (kind, k) in [(Kind::CatmullClark, 2), (Kind::Loop, 3)] {
        let f = facts(kind, k, false, q(1, 4));
        assert_eq!(f.spec_a[1..3], [0.5, 0.5], "{kind:?}");
        assert!(f.spec_a[3] <= 0.25 + 1e-15, "{kind:?}: {:?}", f.spec_a);
        assert_eq!(nullities(&f.a, &Qd::r(1, 2)), (2, 2), "{kind:?}: 1/2 double, non-defective");
        let an = boundary(kind, k, false);
        let v = &an.spectrum.verdict;
        assert!(v.c1_spectral, "{kind:?}: {:?}", v.reasons);
        assert!((v.sub_subdominant.unwrap() - 0.25).abs() < 1e-12);
        let map = charmap_of(kind, k, false);
        assert!(map.regular && map.injective, "{kind:?}: {:?}", map.reasons);
    }
}

/// Biermann–Levin–Zorin's γ (`-p blz=1`) where Hoppe's rules fail
/// (Catmull–Clark k = 4: 1/2 defective, k = 5, 6: rays collapsed; Loop
/// k = 6: 1/2 defective, k = 7: rays collapsed). By the derivation the mode
/// m = 1 is 1/2 exactly, every other mode below it, and 1/2 is double and
/// non-defective (m = 1 is odd): shown exactly over Q(√d) where cos(π/k) is
/// in one (k ≤ 6); at Loop k = 7 (cos(π/7) is a cubic irrational) the mode
/// argument and the raster stand. ρ(C) < 1/2, so λ1 = λ2 = 1/2 and |λ3| is
/// the largest other mode. The program's verdict must pass there, the
/// raster find the map regular and injective, and Hoppe's rules at the same
/// k must not pass both.
#[test]
fn blz_rules_pass_where_hoppe_rules_fail() {
    for (kind, k) in
        [(Kind::CatmullClark, 4), (Kind::CatmullClark, 5), (Kind::CatmullClark, 6), (Kind::Loop, 6), (Kind::Loop, 7)]
    {
        let f = facts(kind, k, true, q(1, 2));
        assert!(
            (f.spec_a[1] - 0.5).abs() < 1e-12 && (f.spec_a[2] - 0.5).abs() < 1e-12,
            "{kind:?} k = {k}: {:?}",
            f.spec_a
        );
        assert!(f.spec_a[3] < 0.5 - 1e-3, "{kind:?} k = {k}: {:?}", f.spec_a);
        if k <= 6 {
            assert_eq!(nullities(&f.a, &Qd::r(1, 2)), (2, 2), "{kind:?} k = {k}: 1/2 double, non-defective");
        }
        let an = boundary(kind, k, true);
        let v = &an.spectrum.verdict;
        assert!(v.c1_spectral, "{kind:?} k = {k}: {:?}", v.reasons);
        let e = &an.spectrum.eigenvalues;
        assert!((e[1].re - 0.5).abs() < 1e-10 && e[1].algebraic_multiplicity == 2 && e[1].geometric_multiplicity == 2);
        assert!(
            (v.sub_subdominant.unwrap() - f.spec_a[3]).abs() < 1e-10,
            "{kind:?} k = {k}: |λ3| against {}",
            f.spec_a[3]
        );
        let map = charmap_of(kind, k, true);
        assert!(map.regular && map.injective, "{kind:?} k = {k}: {:?}", map.reasons);
        // Hoppe's rules at the same configuration: no C¹ verdict
        let hoppe_spectral = boundary(kind, k, false).spectrum.verdict.c1_spectral;
        let hoppe_map = charmap_of(kind, k, false);
        assert!(!(hoppe_spectral && hoppe_map.regular && hoppe_map.injective), "{kind:?} k = {k}: Hoppe passes");
    }
}

/// At the regular boundary BLZ's γ is Hoppe's (Catmull–Clark k = 2:
/// 3/8 − cos(π/2)/4 = 3/8; Loop k = 3: 1/2 − cos(π/3)/4 = 3/8), so S is the
/// same matrix exactly, and so it is at one sector (no edge at the centre
/// is interior; the ray vertices' sectors are regular); `blz = 0` is
/// Hoppe's rules (Loop k = 6 still fails); a value
/// outside [0, 1] is refused in one line.
#[test]
fn blz_is_hoppe_at_the_regular_boundary_and_checks_its_range() {
    for (kind, k) in [(Kind::CatmullClark, 2), (Kind::Loop, 3), (Kind::CatmullClark, 1), (Kind::Loop, 1)] {
        let hoppe = boundary(kind, k, false);
        let blz = boundary(kind, k, true);
        let (h, b) = (hoppe.exact_matrix.as_ref().unwrap(), blz.exact_matrix.as_ref().unwrap());
        assert_eq!(h.labels.len(), b.labels.len());
        assert_eq!(h.rows, b.rows, "{kind:?} k = {k}");
    }
    let zero = schemes::build("loop", &[("blz".into(), "0".into())]).unwrap();
    let config = Configuration::tagged(zero.as_ref(), 6, None, Tagging::Boundary).unwrap();
    assert!(!analyse(zero.as_ref(), &config, &Options::default()).unwrap().spectrum.verdict.c1_spectral);
    let e = schemes::build("catmull-clark", &[("blz".into(), "2".into())]).err().unwrap().to_string();
    assert!(e.contains("blz") && e.contains("out of range") && !e.contains('\n'), "{e}");
}

/// The claims file recording these verdicts (subject key `tag`) verifies
/// with every verdict the one it records, the spectral ones also by a
/// certified second route (`certified = true`: `certify::tagged`); a
/// tagged curvature claim is refused in one line.
#[test]
fn the_boundary_claims_file_verifies() {
    let exe = env!("CARGO_BIN_EXE_subdlab");
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/claims/boundary-blz.toml");
    let out = std::process::Command::new(exe)
        .args(["verify", "--check-expected", "--claims", file, "--json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let claims = v[0]["claims"].as_array().unwrap();
    assert_eq!(claims.len(), 37);
    for c in claims {
        assert_eq!(c["verdict"], "HOLDS", "{c}");
    }
    // every spectral verdict of the first routes (floating point) has a
    // certified second route, which names its evidence
    let ids: Vec<&str> = claims.iter().map(|c| c["id"].as_str().unwrap()).collect();
    for (first, second) in [
        ("cc.boundary.regular", "cc.boundary.regular.certified"),
        ("cc.boundary.one-quad", "cc.boundary.one-quad.certified"),
        ("cc.boundary.hoppe-defective", "cc.boundary.hoppe-defective.certified"),
        ("cc.boundary.blz", "cc.boundary.blz.certified"),
        ("loop.boundary.hoppe-defective", "loop.boundary.hoppe-defective.certified"),
        ("cc.crease.regular", "cc.crease.regular.certified"),
        ("loop.crease.regular", "loop.crease.regular.certified"),
        ("cc.crease.four-quad-side", "cc.crease.four-quad-side.certified"),
        ("cc.crease.blz", "cc.crease.blz.certified"),
        // the sector map's certified route (`charmap --tag boundary --certify`)
        ("cc.boundary.regular", "cc.boundary.regular.map.certified"),
        ("cc.boundary.hoppe-collapse", "cc.boundary.hoppe-collapse.certified"),
        ("cc.boundary.blz-map", "cc.boundary.blz-map.certified"),
        ("loop.boundary.hoppe-passes", "loop.boundary.hoppe-map.certified"),
        ("loop.boundary.hoppe-defective", "loop.boundary.hoppe-defective.map.certified"),
        ("loop.boundary.hoppe-collapse", "loop.boundary.hoppe-collapse.certified"),
        ("loop.boundary.blz", "loop.boundary.blz-map.certified"),
    ] {
        assert!(ids.contains(&first) && ids.contains(&second), "{first} / {second}");
    }
    // crease claims are decided per side, and their evidence says so (the
    // failing one names its side: side A of 4 quads, tests/crease_sides.rs)
    for c in claims.iter().filter(|c| {
        c["id"].as_str().unwrap().starts_with("cc.crease") || c["id"].as_str().unwrap().starts_with("loop.crease")
    }) {
        let computed = c["computed"].as_str().unwrap();
        assert!(computed.contains("per side") || computed.contains("decided by sides"), "{c}");
    }
    let four = claims.iter().find(|c| c["id"] == "cc.crease.four-quad-side").unwrap();
    assert!(four["computed"].as_str().unwrap().contains("side A (sectors 0..3, 4 faces"), "{four}");
    for c in claims.iter().filter(|c| c["id"].as_str().unwrap().ends_with(".certified")) {
        let computed = c["computed"].as_str().unwrap();
        assert!(computed.contains("certified sector criterion") && computed.contains("decided by"), "{c}");
    }
    let dir = std::env::temp_dir().join(format!("subdlab-tagged-claims-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("tagged-curvature.toml");
    std::fs::write(
        &bad,
        "paper = \"t\"\ntitle = \"t\"\n[[claim]]\nid = \"c\"\nlocation = \"-\"\nstatement = \"-\"\ncheck = \"curvature\"\nscheme = \"loop\"\ntag = \"boundary\"\nvalences = [3]\nclass = \"bounded\"\n",
    )
    .unwrap();
    let out = std::process::Command::new(exe).args(["verify", "--claims", bad.to_str().unwrap()]).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    assert!(text.contains("not available at tagged vertices"), "{text}");
    std::fs::remove_dir_all(&dir).ok();
}
