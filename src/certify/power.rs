//! Lemma S6 (ARCHITECTURE.md, "The proofs, step by step"): an upper bound of
//! the spectral radius of an interval matrix that needs no eigenvectors.
//!
//! For every square matrix B, every induced norm and every k ≥ 1,
//! ρ(B)^k = ρ(B^k) ≤ ‖B^k‖. With k = 2^s and B^k formed by s interval
//! squarings of the interval block, the enclosure of B^k holds the k-th power
//! of every matrix in the box (each interval operation holds every result of
//! its operands), so the row-sum bound of its moduli bounds ‖B^k‖∞ for every
//! such B, the true block included. Defective or ill-conditioned blocks,
//! where the disc enclosure of `discs` fails or is wide, are bounded this way
//! as well: a Jordan block of size p at μ contributes about k^{p−1}|μ|^k to
//! ‖B^k‖, whose k-th root tends to |μ|.
//!
//! Only the number of squarings is chosen with a floating-point target; the
//! inequality the proof uses (`spectrum::decide`: the bound below λ1's lower
//! bound) is decided on the rigorous bounds computed here.

use super::complex::{CInterval, CIntervalMatrix};
use crate::numeric::Interval;
use serde::Serialize;

/// The most squarings tried (k up to 2^12 = 4096): beyond, the interval
/// widths of a block whose spectral radius is near the target grow faster
/// than the bound improves.
pub const MAX_SQUARINGS: u32 = 12;

/// A proved bound ρ(B) ≤ ‖B^k‖∞^{1/k} ≤ `radius` for every B in an interval
/// block.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PowerBound {
    /// the power, k = 2^s
    pub k: u64,
    /// an upper bound of ‖B^k‖∞ (largest row sum of moduli)
    pub norm: f64,
    /// an upper bound of norm^{1/k}, checked by interval powers of it
    pub radius: f64,
}

/// The interval product a·a: holds A² for every A in the box.
pub fn square(a: &CIntervalMatrix) -> CIntervalMatrix {
    let k = a.size;
    let mut out = CIntervalMatrix::zeros(k);
    for i in 0..k {
        for l in 0..k {
            let x = a.get(i, l);
            // a zero entry adds nothing: skip its row of products
            if x == CInterval::zero() {
                continue;
            }
            for j in 0..k {
                let e = out.at(i, j);
                *e = *e + x * a.get(l, j);
            }
        }
    }
    out
}

/// An upper bound of ‖A‖∞ = max_i Σ_j |A_ij| over the box (moduli and sums
/// rounded upward).
pub fn inf_norm(a: &CIntervalMatrix) -> f64 {
    (0..a.size)
        .map(|i| (0..a.size).fold(Interval::point(0.0), |s, j| s + Interval::point(a.get(i, j).mag())).hi)
        .fold(0.0, f64::max)
}

/// An r ≥ norm^{1/2^s}: a floating-point root, raised until the lower end of
/// the interval r^(2^s) (s interval squarings) is at least `norm`. `None` for
/// a norm that is not finite.
pub fn root_upper(norm: f64, squarings: u32) -> Option<f64> {
    if !norm.is_finite() || norm < 0.0 {
        return None;
    }
    if norm == 0.0 {
        return Some(0.0);
    }
    let k = 2f64.powi(squarings as i32);
    let mut r = norm.powf(1.0 / k);
    for _ in 0..200 {
        let mut p = Interval::point(r);
        for _ in 0..squarings {
            p = p.square();
        }
        if p.lo >= norm {
            return Some(r);
        }
        // powf is accurate to a few ulps; the factor covers that in a few steps
        r = (r * (1.0 + 1e-13)).next_up();
    }
    None
}

/// The bound for k = 1, 2, 4, …: squarings stop once the bound is below
/// `target` (a floating-point guide, e.g. λ1's lower bound; it decides only
/// when to stop), after [`MAX_SQUARINGS`], or when an entry stops being
/// finite. Returns the smallest radius found (`None`: not even ‖B‖∞ is
/// finite).
pub fn power_bound(a: &CIntervalMatrix, target: f64) -> Option<PowerBound> {
    let bound = |p: &CIntervalMatrix, s: u32| {
        let norm = inf_norm(p);
        root_upper(norm, s).map(|radius| PowerBound { k: 1 << s, norm, radius })
    };
    let mut best = bound(a, 0)?;
    let mut p = a.clone();
    for s in 1..=MAX_SQUARINGS {
        if best.radius < target {
            break;
        }
        p = square(&p);
        if !p.entries.iter().all(CInterval::is_finite) {
            break;
        }
        match bound(&p, s) {
            Some(b) if b.radius < best.radius => best = b,
            Some(_) => {}
            None => break,
        }
    }
    Some(best)
}

#[cfg(test)]
mod tests {
    use super::*;
    use faer::c64;

    fn real_matrix(rows: &[&[f64]]) -> CIntervalMatrix {
        let k = rows.len();
        let mut m = CIntervalMatrix::zeros(k);
        for i in 0..k {
            for j in 0..k {
                *m.at(i, j) = CInterval::point(c64::new(rows[i][j], 0.0));
            }
        }
        m
    }

    #[test]
    fn a_jordan_block_is_bounded_by_powers() {
        // [[1/4, 1], [0, 1/4]]: ρ = 1/4, ‖B‖∞ = 5/4, and B^k = [[4^-k,
        // k·4^{1−k}], [0, 4^-k]], so ‖B^k‖∞ = (1 + 4k)/4^k: for k = 8,
        // 33/65536 < 1/2^8 = 1/256, i.e. the 8th root is below 1/2
        let b = real_matrix(&[&[0.25, 1.0], &[0.0, 0.25]]);
        let pb = power_bound(&b, 0.5).unwrap();
        assert!(pb.radius < 0.5 && pb.radius >= 0.25, "{pb:?}");
        let k = pb.k as f64;
        // the exact norm of B^k, from the closed form above (all dyadic)
        let exact = (1.0 + 4.0 * k) / 4f64.powf(k);
        assert!(pb.norm >= exact && pb.norm <= exact * (1.0 + 1e-12), "{pb:?} vs {exact}");
        // k = 2: 9/16 = 0.5625, root 0.75, not below 1/2; k = 4: 17/256, root
        // 0.5077; k = 8: root 33^{1/8}/4 = 0.3869: the first that clears
        assert_eq!(pb.k, 8);
    }

    #[test]
    fn the_radius_bounds_the_norm_from_above() {
        for (norm, s) in [(2.0, 3), (1e-30, 10), (0.7, 1), (33.0 / 65536.0, 3)] {
            let r = root_upper(norm, s).unwrap();
            // r^(2^s) ≥ norm, rechecked in exact rationals
            let q = num_rational::BigRational::from_float(r).unwrap();
            let n = num_rational::BigRational::from_float(norm).unwrap();
            let mut p = q.clone();
            for _ in 0..s {
                p = &p * &p;
            }
            assert!(p >= n, "{r}^(2^{s}) < {norm}");
            // and not much above the true root
            assert!(r <= norm.powf(1.0 / 2f64.powi(s as i32)) * (1.0 + 1e-10));
        }
        assert_eq!(root_upper(0.0, 4), Some(0.0));
        assert_eq!(root_upper(f64::INFINITY, 4), None);
    }

    #[test]
    fn a_spectral_radius_at_the_target_is_never_cleared() {
        // ρ(B) = 1/2 exactly ([[1/2, 1], [0, 1/2]]): no k gives a bound below
        // 1/2, since ρ(B) ≤ ‖B^k‖^{1/k} for every k
        let b = real_matrix(&[&[0.5, 1.0], &[0.0, 0.5]]);
        let pb = power_bound(&b, 0.5).unwrap();
        assert!(pb.radius >= 0.5, "{pb:?}");
    }
}
