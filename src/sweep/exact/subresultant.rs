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
//! 4. Coefficients in Q(ζ_N) (valences 5, 7, ...: the block polynomials
//!    are real but not rational): psc_j(A, B) has coefficients in Z[ζ_N]
//!    (A, B scaled to integer ζ-coefficients). Its norm ∏_σ σ(psc_j) over
//!    the distinct Galois conjugates σ(A, B) of the pair is fixed by the
//!    Galois group and integral, so in Z[t]; its roots contain psc_j's, and
//!    it is zero exactly when psc_j is (a field). Modulo a prime p ≡ 1
//!    (mod N) with w a primitive N-th root of unity in F_p, ζ_N ↦ w^a is a
//!    ring map Z[ζ_N] → F_p sending x to the image of σ_a(x) under ζ_N ↦ w,
//!    so the norm's value at t modulo p is ∏_a psc_j(A, B)(t) evaluated at
//!    ζ_N = w^a. Every |σ(x)| is at most the sum of x's |ζ-coefficients|
//!    (|ζ| = 1), so the 1-norms below bound every conjugate and the norm's
//!    coefficients are at most M_j^k (k conjugates), of degree ≤ k·bound(j).
//! 5. j runs 0, 1, ... and the first psc_j that lifts to a nonzero
//!    polynomial is returned: exactly the coefficient whose vanishing marks
//!    a rise of deg gcd_x(a, b) (von zur Gathen–Gerhard, *Modern Computer
//!    Algebra*, §6.10–6.11, the fundamental theorem on subresultants).

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use crate::numeric::modular::{det_word, eval_word, from_word_values, pow_mod, residue, word_mul, Lifted};
use crate::numeric::{BiPoly, Cyclotomic, Rational, TPoly};

/// An element of Z[ζ_N] as (exponent of ζ_N, integer coefficient) pairs.
pub(crate) type ZetaInt = Vec<(u64, BigInt)>;

/// A block polynomial scaled to integer ζ-coefficients: [x^k][t^i].
pub(crate) type ZetaPoly = Vec<Vec<ZetaInt>>;

/// N: the lcm of the orders of every coefficient's field; None when one is
/// undefined.
fn common_order(polys: &[&BiPoly]) -> Option<u64> {
    let mut n = 1u64;
    for p in polys {
        for c in p.iter() {
            if !c.is_defined() {
                return None;
            }
            for x in c.coeffs() {
                let m = x.order()? as u64;
                n = n / n.gcd(&m) * m;
            }
        }
    }
    Some(n)
}

/// p's coefficients in Z[ζ_N] after multiplying by the lcm of every
/// denominator (the same roots in x; psc_j only gains a constant factor).
fn integer_zeta_poly(p: &BiPoly, order: u64) -> ZetaPoly {
    let entries = |x: &Cyclotomic| -> Vec<(u64, Rational)> {
        let m = x.order().unwrap_or(1) as u64;
        x.coefficients().map(|(i, r)| (i as u64 * (order / m), r)).collect()
    };
    let l =
        p.iter().flat_map(|c| c.coeffs().iter().flat_map(entries)).fold(BigInt::one(), |l, (_, r)| l.lcm(r.denom()));
    let l = Rational::from_integer(l);
    p.iter()
        .map(|c: &TPoly| {
            c.coeffs()
                .iter()
                .map(|x| entries(x).into_iter().map(|(e, r)| (e, (r * &l).to_integer())).collect())
                .collect()
        })
        .collect()
}

/// ⌈log₂ N⌉ for N = (Σ_k ‖A_k‖₁²)^{1/2}, ‖·‖₁ summing |coefficients| over
/// the powers of t and of ζ: on |t| = 1 it bounds the Euclidean norm of a
/// Sylvester row of A under every embedding.
fn row_norm_bits(p: &ZetaPoly) -> u64 {
    let sum: BigInt = p
        .iter()
        .map(|c| {
            let one_norm: BigInt = c.iter().flatten().map(|(_, x)| x.abs()).sum();
            &one_norm * &one_norm
        })
        .sum();
    // sum < 2^bits(sum), so its square root < 2^{bits/2} ≤ 2^{⌈bits/2⌉}
    sum.bits().div_ceil(2)
}

/// A primitive N-th root of unity modulo p (N | p − 1): g^((p−1)/N) of
/// order exactly N for the first g = 2, 3, ... that gives one.
pub(crate) fn primitive_root_of_unity(order: u64, p: u64) -> u64 {
    let prime_factors: Vec<u64> = (2..=order).filter(|q| order % q == 0 && (2..*q).all(|r| q % r != 0)).collect();
    (2..p)
        .map(|g| pow_mod(g, (p - 1) / order, p))
        .find(|&w| prime_factors.iter().all(|&q| pow_mod(w, order / q, p) != 1))
        .expect("F_p* is cyclic, so a generator exists")
}

/// The residues (coefficients of t) of p under ζ_N ↦ w modulo p.
pub(crate) fn embedded(p: &ZetaPoly, w: u64, order: u64, prime: u64) -> Vec<Vec<u64>> {
    p.iter()
        .map(|c| {
            c.iter()
                .map(|x| {
                    x.iter().fold(0u64, |acc, (e, v)| {
                        (acc + residue(v, prime) * pow_mod(w, e % order, prime) % prime) % prime
                    })
                })
                .collect()
        })
        .collect()
}

/// The images of two polynomials over Q(ζ_N) under the embeddings
/// ζ_N ↦ w^c of F_p, one pair per conjugate exponent c (w a primitive N-th
/// root of unity modulo p); None where F_p has none (p ≢ 1 mod N).
fn conjugate_images(
    a: &ZetaPoly,
    b: &ZetaPoly,
    conjugates: &[u64],
    order: u64,
    p: u64,
) -> Option<Vec<(Vec<Vec<u64>>, Vec<Vec<u64>>)>> {
    if (p - 1) % order != 0 {
        return None;
    }
    let w = primitive_root_of_unity(order, p);
    Some(
        conjugates
            .iter()
            .map(|&c| {
                let wc = pow_mod(w, c, p);
                (embedded(a, wc, order, p), embedded(b, wc, order, p))
            })
            .collect(),
    )
}

/// The values at t = 0..=degree, modulo p, of the norm of `f(a, b)` over
/// the pair's conjugates: the product over the embeddings of
/// [`conjugate_images`] of `f` applied to the two polynomials' coefficients
/// at t. None where F_p has no N-th root of unity.
pub(crate) fn norm_values(
    a: &ZetaPoly,
    b: &ZetaPoly,
    conjugates: &[u64],
    order: u64,
    p: u64,
    degree: usize,
    f: impl Fn(&[u64], &[u64]) -> u64,
) -> Option<Vec<u64>> {
    let images = conjugate_images(a, b, conjugates, order, p)?;
    Some(
        (0..=degree as u64)
            .map(|t| {
                images.iter().fold(1u64, |acc, (ia, ib)| {
                    let ca: Vec<u64> = ia.iter().map(|c| eval_word(c, t, p)).collect();
                    let cb: Vec<u64> = ib.iter().map(|c| eval_word(c, t, p)).collect();
                    word_mul(acc, f(&ca, &cb), p)
                })
            })
            .collect(),
    )
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

/// The first psc_j(a, b) not identically zero — for coefficients in
/// Q(ζ_N), its norm over the distinct Galois conjugates of the pair — as
/// an integer polynomial in t (lowest first) whose roots contain
/// psc_j(a, b)'s, for a and b with constant nonzero leading coefficients;
/// `bound(j)` bounds psc_j's degree in t. `conjugates` lists a's with the
/// distinct conjugates σ_a(a, b) (just [1] for rational coefficients).
/// None when every psc_j vanishes identically (not a pair of polynomials
/// of positive degree), or the coefficients are not numbers: the caller's
/// exact path then says why.
///
/// `known_zero`: psc_0, ..., psc_{known_zero − 1} are already proved to
/// vanish identically (`exact::proved_common_degree`); the search starts there.
pub(crate) fn first_nonzero_psc(
    a: &BiPoly,
    b: &BiPoly,
    conjugates: &[u64],
    bound: &dyn Fn(usize) -> usize,
    known_zero: usize,
) -> Option<Vec<BigInt>> {
    let order = common_order(&[a, b])?;
    let (za, zb) = (integer_zeta_poly(a, order), integer_zeta_poly(b, order));
    let (m, n) = (za.len() - 1, zb.len() - 1);
    let (bits_a, bits_b) = (row_norm_bits(&za), row_norm_bits(&zb));
    let k = conjugates.len();
    for j in known_zero..=m.min(n) {
        let degree = k * bound(j);
        // |coefficient| ≤ M_j^k < 2^{k·((n−j)·bits_a + (m−j)·bits_b) + 1}
        let bits = k as u64 * ((n - j) as u64 * bits_a + (m - j) as u64 * bits_b) + 1;
        let lifted = from_word_values(degree, bits, None, |p| {
            norm_values(&za, &zb, conjugates, order, p, degree, |ca, cb| psc_word(ca, cb, j, p))
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
