//! Midpoint–radius enclosures of the products a disc enclosure needs
//! (`discs`): R·A·V and I − R·V for an interval matrix A and point matrices
//! R, V, computed with floating-point matrix products and an a-priori bound
//! of their rounding errors instead of an interval operation per scalar
//! product. The certificates' O(k³) products took most of their time in
//! directed-rounding scalar arithmetic; here they are seven plain products
//! (the interval route stays for ill-conditioned V, see [`COARSE_EPSILON`]).
//!
//! Why the bounds hold (u = 2⁻⁵³, rounding to nearest, k the inner
//! dimension):
//!
//! - A complex inner product of length k computed in real arithmetic is two
//!   real inner products of length 2k (Σ aᵣbᵣ − aᵢbᵢ and Σ aᵣbᵢ + aᵢbᵣ); in
//!   any summation order, fused or not, each term passes through at most 2k
//!   roundings, so each part is within γ_2k = 2ku/(1 − 2ku) of its terms'
//!   absolute sum (Higham, Accuracy and Stability of Numerical Algorithms,
//!   2nd ed., §3.1), and (|aᵣbᵣ| + |aᵢbᵢ|, |aᵣbᵢ| + |aᵢbᵣ|) has length at
//!   most √2·|a||b|: the error is below √2·γ_2k·Σ|xₗ||yₗ| ≤ g·Σ|xₗ||yₗ| with
//!   g = 3(k + 1)u for (k + 2)u ≤ 1/100. Underflow adds at most an absolute
//!   2⁻¹⁰⁷⁴ per operation, covered by the floor below.
//! - For A = A_c + Δ, |Δ| ≤ ρ entrywise, P = fl(A_c·V), Q = fl(R·P):
//!   R·A·V − Q = R·Δ·V + R·(A_c·V − P) + (R·P − Q), so
//!   |R·A·V − Q| ≤ |R|·(ρ + g|A_c|)·|V| + g·|R|·|P| entrywise.
//! - The right-hand sides are sums and products of non-negative numbers.
//!   Computed in floating point each is at least its exact value times
//!   (1 − u)^D, D the number of roundings on its longest path; so the exact
//!   value is at most the computed one times (1 + 2Du) (D·u ≤ 1/2), which
//!   [`upper`] applies, with a floor far above any underflow loss (every
//!   loss is 2⁻¹⁰⁷⁴ per operation, carried through at most k² entries of
//!   the largest magnitudes involved).
//! - Moduli |z| are hypot, accurate to one ulp, then moved up two ulps.
//!
//! Every product runs sequentially (`Par::Seq`): the same bits for any
//! thread count. The bounds assume conventional products (each entry a sum
//! of the k products of its row and column), which faer 0.24's kernels are:
//! no 3M complex product, no Strassen scheme.

use super::complex::{CInterval, CIntervalMatrix};
use crate::numeric::Interval;
use faer::linalg::matmul::matmul;
use faer::{c64, Accum, Mat, Par};

/// Unit roundoff of binary64.
const U: f64 = f64::EPSILON / 2.0;

/// A point complex matrix and a radius per entry: every matrix X with
/// |Xᵢⱼ − midᵢⱼ| ≤ radᵢⱼ.
pub struct BallMatrix {
    pub mid: Mat<c64>,
    pub rad: Mat<f64>,
}

/// The enclosures [`products`] returns.
pub struct Products {
    /// M ⊇ R·A·V for every A in the interval matrix
    pub m: BallMatrix,
    /// ε ≥ ‖I − R·V‖∞
    pub epsilon: f64,
}

/// An upper bound of |z|.
fn modulus_up(z: c64) -> f64 {
    z.re.hypot(z.im).next_up().next_up()
}

fn modulus_matrix(m: &Mat<c64>) -> Mat<f64> {
    Mat::from_fn(m.nrows(), m.ncols(), |i, j| modulus_up(m[(i, j)]))
}

fn product<T: faer::traits::ComplexField>(a: &Mat<T>, b: &Mat<T>, one: T) -> Mat<T> {
    let mut out = Mat::<T>::zeros(a.nrows(), b.ncols());
    matmul(&mut out, Accum::Replace, a, b, one, Par::Seq);
    out
}

/// The exact value of a non-negative expression computed as `x` with at most
/// `depth` roundings on any path, bounded from above (see the module
/// documentation), plus `floor` for underflow.
fn upper(x: f64, depth: usize, floor: f64) -> f64 {
    // the two roundings of this very line are counted in depth + 3
    (x * (1.0 + 2.0 * (depth + 3) as f64 * U) + floor).next_up()
}

fn largest(m: &Mat<f64>) -> f64 {
    (0..m.nrows()).flat_map(|i| (0..m.ncols()).map(move |j| (i, j))).map(|(i, j)| m[(i, j)]).fold(0.0, f64::max)
}

/// Above this ε the a-priori bounds are too coarse to be worth keeping: an
/// ill-conditioned V (a nearly defective block) makes |R|·|V| large, and
/// the worst-case rounding term g·|R|·|V| with it, while the rounding
/// actually committed is often far smaller (exact products stay exact).
/// There the products are redone in interval arithmetic, whose ε is the
/// one actually committed.
const COARSE_EPSILON: f64 = 1e-3;

/// M ⊇ R·A·V and ε ≥ ‖I − R·V‖∞: floating-point products with a-priori
/// rounding bounds, or interval products where those give ε ≥
/// [`COARSE_EPSILON`] (both are enclosures; which one is used changes only
/// how tight they are).
pub fn products(a: &CIntervalMatrix, v: &Mat<c64>, r: &Mat<c64>) -> Result<Products, String> {
    match fast_products(a, v, r) {
        Ok(p) if p.epsilon < COARSE_EPSILON => Ok(p),
        _ => Ok(interval_products(a, v, r)),
    }
}

/// The products in outward-rounded interval arithmetic, one scalar product
/// at a time: O(k³) interval operations, tight where floating-point products
/// are exact.
pub fn interval_products(a: &CIntervalMatrix, v: &Mat<c64>, r: &Mat<c64>) -> Products {
    let k = a.size;
    let point = |m: &Mat<c64>, i: usize, j: usize| CInterval::point(m[(i, j)]);
    let mut av = CIntervalMatrix::zeros(k);
    for i in 0..k {
        for j in 0..k {
            let mut s = CInterval::zero();
            for l in 0..k {
                s = s + a.get(i, l) * point(v, l, j);
            }
            *av.at(i, j) = s;
        }
    }
    let mut m = CIntervalMatrix::zeros(k);
    let mut epsilon: f64 = 0.0;
    for i in 0..k {
        let mut row_e = Interval::point(0.0);
        for j in 0..k {
            let (mut s, mut rv) = (CInterval::zero(), CInterval::zero());
            for l in 0..k {
                s = s + point(r, i, l) * av.get(l, j);
                rv = rv + point(r, i, l) * point(v, l, j);
            }
            *m.at(i, j) = s;
            let identity = CInterval::point(c64::new(if i == j { 1.0 } else { 0.0 }, 0.0));
            row_e = row_e + Interval::point((identity - rv).mag());
        }
        epsilon = epsilon.max(row_e.hi);
    }
    let mid = m.mid();
    let rad = Mat::from_fn(k, k, |i, j| m.get(i, j).distance_from(mid[(i, j)]));
    Products { m: BallMatrix { mid, rad }, epsilon }
}

/// The products as floating-point matrix products with the rounding errors
/// bounded a priori (the module documentation). `Err` when a bound is not
/// finite or k·u is too large for the error bounds (k above 10¹³: never, in
/// practice).
fn fast_products(a: &CIntervalMatrix, v: &Mat<c64>, r: &Mat<c64>) -> Result<Products, String> {
    let k = a.size;
    if (k as f64 + 2.0) * U > 1e-2 {
        return Err(format!("a block of size {k} is beyond the rounding-error bounds"));
    }
    let one = c64::new(1.0, 0.0);
    let g = 3.0 * (k as f64 + 1.0) * U;
    let a_mid = a.mid();
    // ρ: how far each entry of A reaches from its midpoint (directed rounding)
    let rho = Mat::from_fn(k, k, |i, j| a.get(i, j).distance_from(a_mid[(i, j)]));
    let (abs_a, abs_v, abs_r) = (modulus_matrix(&a_mid), modulus_matrix(v), modulus_matrix(r));
    // how far an underflow loss can be carried: k² terms of the largest sizes
    let scale = (k * k + 1) as f64
        * largest(&abs_a).max(largest(&rho)).max(1.0)
        * largest(&abs_v).max(1.0)
        * largest(&abs_r).max(1.0);
    let floor = 1e-290 * scale;

    let p = product(&a_mid, v, one);
    let q = product(r, &p, one);
    let spread = Mat::from_fn(k, k, |i, j| rho[(i, j)] + g * abs_a[(i, j)]);
    let through_v = product(&spread, &abs_v, 1.0);
    let through_r = product(&abs_r, &through_v, 1.0);
    let rounding_q = product(&abs_r, &modulus_matrix(&p), 1.0);
    // longest path: the spread (2), two products of length k (k + 1 each),
    // the scaled rounding term and the sum (2)
    let depth = 2 * k + 6;
    let rad = Mat::from_fn(k, k, |i, j| upper(through_r[(i, j)] + g * rounding_q[(i, j)], depth, floor));

    let w = product(r, v, one);
    let rv_rounding = product(&abs_r, &abs_v, 1.0);
    let mut epsilon: f64 = 0.0;
    for i in 0..k {
        let mut row = 0.0;
        for j in 0..k {
            let identity = if i == j { one } else { c64::new(0.0, 0.0) };
            let e = identity - w[(i, j)];
            row += modulus_up(e) + g * rv_rounding[(i, j)];
        }
        // the difference (1), its modulus (moved up), the product of length
        // k (k + 1), the scaled term and the row sum of k terms
        epsilon = epsilon.max(upper(row, 2 * k + 6, floor));
    }
    let finite = |m: &Mat<f64>| (0..k).all(|i| (0..k).all(|j| m[(i, j)].is_finite()));
    let finite_c = |m: &Mat<c64>| (0..k).all(|i| (0..k).all(|j| m[(i, j)].re.is_finite() && m[(i, j)].im.is_finite()));
    if !finite(&rad) || !finite_c(&q) || !epsilon.is_finite() {
        return Err("a product of the verification is not finite".into());
    }
    Ok(Products { m: BallMatrix { mid: q, rad }, epsilon })
}

/// The Gershgorin quantities of M's row i: its centre Mᵢᵢ's midpoint and an
/// upper bound of |Mᵢᵢ − centre| + Σ_{j≠i} |Mᵢⱼ|, for every M in the balls.
pub fn row_radius(m: &BallMatrix, i: usize) -> (c64, f64) {
    let k = m.mid.ncols();
    let mut sum = m.rad[(i, i)];
    for j in (0..k).filter(|&j| j != i) {
        sum += modulus_up(m.mid[(i, j)]) + m.rad[(i, j)];
    }
    (m.mid[(i, i)], upper(sum, k + 1, 0.0))
}

/// An upper bound of ‖M‖∞ over the balls.
pub fn norm_inf(m: &BallMatrix) -> f64 {
    let k = m.mid.ncols();
    (0..m.mid.nrows())
        .map(|i| upper((0..k).map(|j| modulus_up(m.mid[(i, j)]) + m.rad[(i, j)]).sum::<f64>(), k + 1, 0.0))
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    use num_traits::{FromPrimitive, ToPrimitive, Zero};

    /// A deterministic pseudo-random sequence in [−1, 1] (no crate needed).
    fn sequence(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        }
    }

    type Q = BigRational;
    fn q(x: f64) -> Q {
        Q::from_f64(x).unwrap()
    }

    /// Exact complex products over Q of the float matrices (re, im pairs).
    fn exact_product(a: &[Vec<(Q, Q)>], b: &[Vec<(Q, Q)>]) -> Vec<Vec<(Q, Q)>> {
        let k = a.len();
        (0..k)
            .map(|i| {
                (0..k)
                    .map(|j| {
                        (0..k).fold((Q::zero(), Q::zero()), |(sr, si), l| {
                            let (x, y) = (&a[i][l], &b[l][j]);
                            (sr + &x.0 * &y.0 - &x.1 * &y.1, si + &x.0 * &y.1 + &x.1 * &y.0)
                        })
                    })
                    .collect()
            })
            .collect()
    }

    fn exact(m: &Mat<c64>) -> Vec<Vec<(Q, Q)>> {
        (0..m.nrows()).map(|i| (0..m.ncols()).map(|j| (q(m[(i, j)].re), q(m[(i, j)].im))).collect()).collect()
    }

    /// |z − c|² ≤ r², decided over Q.
    fn within(z: &(Q, Q), c: c64, r: f64) -> bool {
        let (dr, di) = (&z.0 - q(c.re), &z.1 - q(c.im));
        &dr * &dr + &di * &di <= q(r) * q(r)
    }

    /// R·A·V (A at the midpoint and at corners of the interval matrix) and
    /// I − R·V computed exactly over Q (every float is a rational) must lie
    /// in the balls and under ε, whatever the rounding.
    fn assert_encloses(a: &CIntervalMatrix, v: &Mat<c64>, r: &Mat<c64>, got: &Products) {
        let k = a.size;
        for corner in 0..3 {
            let pick = |z: &CInterval| match corner {
                0 => (q(z.re.lo), q(z.im.lo)),
                1 => (q(z.re.hi), q(z.im.hi)),
                _ => (q(z.re.lo), q(z.im.hi)),
            };
            let am: Vec<Vec<(Q, Q)>> = (0..k).map(|i| (0..k).map(|j| pick(&a.get(i, j))).collect()).collect();
            let m = exact_product(&exact(r), &exact_product(&am, &exact(v)));
            for i in 0..k {
                for j in 0..k {
                    assert!(within(&m[i][j], got.m.mid[(i, j)], got.m.rad[(i, j)]), "k = {k}, entry {i},{j}");
                }
            }
        }
        // ε over Q: each exact |Eᵢⱼ| = √(re² + im²) is bounded by the least
        // float whose square is ≥ re² + im², and the row sum of those
        // bounds, added over Q, must not pass ε
        let rv = exact_product(&exact(r), &exact(v));
        for i in 0..k {
            let mut shares = Q::zero();
            for j in 0..k {
                let (re, im) = &rv[i][j];
                let re = if i == j { Q::from_integer(1.into()) - re } else { -re.clone() };
                let m2 = &re * &re + im * im;
                let mut share = m2.to_f64().unwrap().sqrt();
                while q(share) * q(share) < m2 {
                    share = share.next_up();
                }
                shares += q(share);
            }
            assert!(shares <= q(got.epsilon), "row {i}: the exact row sum passes ε = {}", got.epsilon);
        }
    }

    fn random_case(k: usize, seed: u64, width: f64) -> (CIntervalMatrix, Mat<c64>, Mat<c64>) {
        let mut next = sequence(seed);
        let mut a = CIntervalMatrix::zeros(k);
        for e in a.entries.iter_mut() {
            let (re, im, w) = (next(), next(), next().abs() * width);
            *e = CInterval::new(Interval::new(re - w, re + w), Interval::new(im, im + w));
        }
        let v = Mat::from_fn(k, k, |_, _| c64::new(next(), next()));
        let r = Mat::from_fn(k, k, |_, _| c64::new(next(), next()));
        (a, v, r)
    }

    #[test]
    fn the_balls_hold_the_exact_products_at_the_corners_of_a() {
        for (k, seed) in [(3usize, 1u64), (7, 2), (12, 3)] {
            let (a, v, r) = random_case(k, seed, 1e-6);
            assert_encloses(&a, &v, &r, &fast_products(&a, &v, &r).unwrap());
            assert_encloses(&a, &v, &r, &interval_products(&a, &v, &r));
        }
    }

    #[test]
    fn point_matrices_get_rounding_sized_balls_that_still_hold_the_exact_products() {
        // a point A: only the rounding bounds make the balls hold the exact
        // products (without them the radii would be 0 or the floor)
        for (k, seed) in [(5usize, 4u64), (10, 9), (16, 5)] {
            let (a, v, r) = random_case(k, seed, 0.0);
            let got = fast_products(&a, &v, &r).unwrap();
            assert_encloses(&a, &v, &r, &got);
            // rounding-sized: far below the entries (of size up to k²)
            assert!(largest(&got.m.rad) < 1e-12 * largest(&modulus_matrix(&got.m.mid)));
        }
    }
}
