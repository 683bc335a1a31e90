//! The first principal subresultant coefficient that is not identically
//! zero, for two block polynomials whose coefficients are polynomials in t
//! over Q (valences 3, 4, 6, and every scheme without rotations), by values
//! modulo word primes (`numeric::modular::from_word_values`).
//!
//! Why: over Q(ζ_N) the determinants at each integer t are exact
//! cyclotomic eliminations whose every step normalises big fractions; at
//! unified-sqrt3, n = 3, most of the exact sweep's time went into proving
//! psc_0 and psc_1 identically zero (the blocks share a double branch).
//! Modulo a prime below 2^31 the same determinants are machine words.
//!
//! Exactness, step by step:
//!
//! 1. a and b are scaled by the lcm of their denominators (A = l_a·a,
//!    B = l_b·b): psc_j(A, B) = l_a^{n−j}·l_b^{m−j}·psc_j(a, b), the same
//!    roots in t, and integer coefficients.
//! 2. psc_j(A, B)(t) is the determinant of n − j rows of A's coefficients
//!    and m − j rows of B's. On |t| = 1 each coefficient A_k(t) is at most
//!    its 1-norm, so each row's Euclidean norm is at most
//!    N_A = (Σ_k ‖A_k‖₁²)^{1/2}, and by Hadamard |psc_j(t)| ≤
//!    N_A^{n−j}·N_B^{m−j} =: M_j there; every coefficient of psc_j (a Cauchy
//!    integral over |t| = 1) is at most M_j.
//! 3. Its degree in t is at most the caller's bound(j) (isobaric weight and
//!    row degrees, `first_subresultant`): the values at t = 0..bound(j)
//!    modulo primes give it modulo their product, and once that exceeds
//!    2M_j the symmetric lift is psc_j itself — in particular an
//!    identically zero psc_j is *proved* zero (all its coefficients are 0),
//!    not guessed from a few values.
//! 4. j runs 0, 1, ... and the first psc_j that lifts to a nonzero
//!    polynomial is returned: exactly the coefficient whose vanishing marks
//!    a rise of deg gcd_x(a, b) (von zur Gathen–Gerhard, *Modern Computer
//!    Algebra*, §6.10–6.11, the fundamental theorem on subresultants).

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use crate::numeric::modular::{det_word, eval_word, from_word_values, residue, Lifted};
use crate::numeric::Rational;

/// A polynomial in t over Q, lowest first.
pub(crate) type QT = Vec<Rational>;

/// The coefficients of x^0, x^1, ... times the lcm of every denominator.
fn integer_multiple(p: &[QT]) -> Vec<Vec<BigInt>> {
    let l = p.iter().flatten().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
    let l = Rational::from_integer(l);
    p.iter().map(|c| c.iter().map(|x| (x * &l).to_integer()).collect()).collect()
}

/// ⌈log₂ N⌉ bound for N = (Σ_k ‖A_k‖₁²)^{1/2}, the Euclidean norm bound of
/// a Sylvester row of A on |t| = 1.
fn row_norm_bits(p: &[Vec<BigInt>]) -> u64 {
    let sum: BigInt = p
        .iter()
        .map(|c| {
            let one_norm: BigInt = c.iter().map(|x| x.abs()).sum();
            &one_norm * &one_norm
        })
        .sum();
    // sum < 2^bits(sum), so its square root < 2^{bits/2} ≤ 2^{⌈bits/2⌉}
    sum.bits().div_ceil(2)
}

/// psc_j of a (degree m) and b (degree n) given by their coefficients
/// modulo p at one t: the determinant of the (m + n − 2j)-square matrix of
/// the coefficients of x^i a (i < n − j) and x^i b (i < m − j) at the
/// powers x^{m+n−j−1} down to x^j (the same matrix as the exact `psc`).
fn psc_word(a: &[u64], b: &[u64], j: usize, p: u64) -> u64 {
    let (m, n) = (a.len() - 1, b.len() - 1);
    let size = m + n - 2 * j;
    if size == 0 {
        return 1;
    }
    let top = m + n - j - 1;
    let coef = |q: &[u64], k: isize| if k >= 0 && (k as usize) < q.len() { q[k as usize] } else { 0 };
    let mut mat: Vec<Vec<u64>> = Vec::with_capacity(size);
    for i in 0..n - j {
        mat.push((0..size).map(|col| coef(a, (top - col) as isize - i as isize)).collect());
    }
    for i in 0..m - j {
        mat.push((0..size).map(|col| coef(b, (top - col) as isize - i as isize)).collect());
    }
    det_word(mat, p)
}

/// The first psc_j(a, b) not identically zero, as an integer polynomial in
/// t (lowest first; a positive rational multiple of psc_j(a, b)), for a and
/// b with constant nonzero leading coefficients; `bound(j)` bounds its
/// degree in t. None when every psc_j vanishes identically (not a pair of
/// polynomials of positive degree): the caller's exact path then says why.
pub(crate) fn first_nonzero_psc(a: &[QT], b: &[QT], bound: &dyn Fn(usize) -> usize) -> Option<Vec<BigInt>> {
    let (za, zb) = (integer_multiple(a), integer_multiple(b));
    let (m, n) = (za.len() - 1, zb.len() - 1);
    let (bits_a, bits_b) = (row_norm_bits(&za), row_norm_bits(&zb));
    for j in 0..=m.min(n) {
        let degree = bound(j);
        // |coefficient| ≤ M_j < 2^{(n−j)·bits_a + (m−j)·bits_b + 1}
        let bits = (n - j) as u64 * bits_a + (m - j) as u64 * bits_b + 1;
        let lifted = from_word_values(degree, bits, None, |p| {
            let ra: Vec<Vec<u64>> = za.iter().map(|c| c.iter().map(|x| residue(x, p)).collect()).collect();
            let rb: Vec<Vec<u64>> = zb.iter().map(|c| c.iter().map(|x| residue(x, p)).collect()).collect();
            (0..=degree as u64)
                .map(|t| {
                    let ca: Vec<u64> = ra.iter().map(|c| eval_word(c, t, p)).collect();
                    let cb: Vec<u64> = rb.iter().map(|c| eval_word(c, t, p)).collect();
                    psc_word(&ca, &cb, j, p)
                })
                .collect()
        });
        match lifted {
            Lifted::Exact(c) if c.iter().all(Zero::is_zero) => continue,
            Lifted::Exact(c) => return Some(c),
            // not reached: no give-up was asked for
            Lifted::GaveUpOnZero => return None,
        }
    }
    None
}
