//! A λ²-eigenvalue whose eigenvectors vanish on the characteristic ring but
//! whose generalised eigenvectors do not (regression for a gap in
//! `curvature::examine`, which looked at eigenvectors only).
//!
//! Hand derivation. Let S act on the span of (e0, e1, e2, e3) by the Jordan
//! chain S e0 = ν e0, S e1 = ν e1 + e0 (ν = λ²), and S e3 = c e3 with c < ν,
//! and let the ring see a coordinate functional r (a linear map from level-0
//! data to ring values). Then S^m e1 = ν^m e1 + m ν^(m−1) e0, so on the ring
//! r(S^m e1) = ν^m r(e1) + m ν^(m−1) r(e0):
//!
//! - r(e0) = 0, r(e1) ≠ 0: the ring sees ν^m r(e1), so |μ| = ν = λ² with no
//!   growth: class **bounded** (and not zero, which the eigenvector-only
//!   reading gives: its only eigenvector e0 vanishes, so ν was dropped and
//!   μ = c < λ²);
//! - r(e0) ≠ 0: the ring sees m ν^(m−1) r(e0): a visible Jordan chain, class
//!   **unbounded**.
//!
//! A chain of length 3 (S e2 = ν e2 + e1 as well) with r seeing e1 only:
//! S^m e2 = ν^m e2 + m ν^(m−1) e1 + C(m, 2) ν^(m−2) e0, so the ring sees
//! m ν^(m−1) r(e1): **unbounded**, although the "tops" N·w for w in null(N²)
//! (that is, e0) vanish on the ring: the old test missed this chain too.

use faer::c64;
use faer::Mat;
use subdlab::curvature::jordan::{generalised_eigenspace, ring_structure};
use subdlab::curvature::VANISH_TOL;

const NU: f64 = 0.25;

fn jordan(size: usize, extra: f64) -> Mat<c64> {
    // a chain of `size` at ν, then one eigenvalue `extra`; conjugated by a
    // fixed well-conditioned matrix so the basis is not the unit vectors
    let k = size + 1;
    let j = Mat::<c64>::from_fn(k, k, |i, l| {
        if i == l {
            c64::new(if i < size { NU } else { extra }, 0.0)
        } else if l == i + 1 && l < size {
            c64::new(1.0, 0.0)
        } else {
            c64::new(0.0, 0.0)
        }
    });
    // B = P J P^-1 with P = I + U, U = 1/4 above the diagonal (nilpotent,
    // so P^-1 = I − U + U² − ... exactly)
    let u = Mat::<c64>::from_fn(k, k, |i, l| if l > i { c64::new(0.25, 0.0) } else { c64::new(0.0, 0.0) });
    let id = Mat::<c64>::from_fn(k, k, |i, l| if i == l { c64::new(1.0, 0.0) } else { c64::new(0.0, 0.0) });
    let p = &id + &u;
    let mut p_inv = id.clone();
    let mut power = id.clone();
    for t in 1..k {
        power = &power * &u;
        let sign = if t % 2 == 1 { -1.0 } else { 1.0 };
        p_inv = &p_inv + &(&power * faer::Scale(c64::new(sign, 0.0)));
    }
    &(&p * &j) * &p_inv
}

/// The ring sees the Jordan-basis coordinates `seen` of x (x = P y, the ring
/// reads y = P^-1 x at those coordinates), relative to x's largest entry.
fn ring_of(size: usize, seen: &'static [usize]) -> impl Fn(&[c64]) -> f64 {
    let k = size + 1;
    move |x: &[c64]| {
        // y = P^-1 x with P = I + U (U: 1/4 above the diagonal): back substitution
        let mut y = vec![c64::new(0.0, 0.0); k];
        for i in (0..k).rev() {
            let mut v = x[i];
            for &yl in &y[i + 1..k] {
                v -= c64::new(0.25, 0.0) * yl;
            }
            y[i] = v;
        }
        let scale = x.iter().map(|z| z.norm()).fold(0.0, f64::max).max(1e-300);
        seen.iter().map(|&i| y[i].norm()).fold(0.0, f64::max) / scale
    }
}

#[test]
fn the_generalised_eigenspace_is_the_whole_chain() {
    for size in 1..=3 {
        let b = jordan(size, 0.1);
        let g = generalised_eigenspace(&b, c64::new(NU, 0.0), 4);
        assert_eq!(g.len(), size, "chain of length {size}");
    }
}

#[test]
fn a_vanishing_eigenvector_with_a_visible_generalised_eigenvector_counts_without_growth() {
    // r sees e1 only: bounded
    let b = jordan(2, 0.1);
    let s = ring_structure(&b, c64::new(NU, 0.0), 2, &ring_of(2, &[1]));
    assert_eq!(s.dimension, 2);
    assert!(s.eigenvector_ring <= VANISH_TOL, "the eigenvector e0 vanishes: {}", s.eigenvector_ring);
    assert!(s.space_ring > 0.1, "e1 shows: the eigenvalue counts for μ ({})", s.space_ring);
    assert!(s.chain_ring <= VANISH_TOL, "N·G = span(e0) vanishes: no growth ({})", s.chain_ring);
    // r sees e0: the chain shows (unbounded)
    let s = ring_structure(&b, c64::new(NU, 0.0), 2, &ring_of(2, &[0]));
    assert!(s.eigenvector_ring > 0.1 && s.chain_ring > 0.1);
    // r sees only the other eigenvalue's coordinate: ν vanishes entirely
    let s = ring_structure(&b, c64::new(NU, 0.0), 2, &ring_of(2, &[2]));
    assert!(s.space_ring <= VANISH_TOL && s.chain_ring <= VANISH_TOL);
}

#[test]
fn a_chain_of_three_shows_through_its_middle_vector() {
    let b = jordan(3, 0.1);
    let s = ring_structure(&b, c64::new(NU, 0.0), 3, &ring_of(3, &[1]));
    assert_eq!(s.dimension, 3);
    assert!(s.eigenvector_ring <= VANISH_TOL);
    assert!(s.chain_ring > 0.1, "N·e2 = e1 shows: growth like m (unbounded)");
}
