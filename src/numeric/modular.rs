//! Greatest common divisors of integer polynomials by the small-primes
//! modular method (Brown/Collins; von zur Gathen–Gerhard, *Modern Computer
//! Algebra*, §6.7), exact.
//!
//! Euclid's algorithm over Q (`Poly::gcd` before) makes the coefficients of
//! the remainders grow until every step is a gcd of thousand-digit
//! integers: the square-free part of a degree-84 norm in the exact sweep of
//! unified-sqrt3 did not finish in a minute. Here the gcd is computed modulo
//! word-sized primes (where coefficients stay one word), the images are
//! combined by the Chinese remainder theorem, and the result is accepted
//! only when it divides both polynomials exactly over Z. That test makes the
//! answer exact whatever primes were used: a common divisor whose degree is
//! at least the degree of the gcd modulo a prime that divides neither
//! leading coefficient (which is ≥ the degree of the true gcd) is the gcd.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// a·b mod p (p < 2^63).
pub(crate) fn mul_mod(a: u64, b: u64, p: u64) -> u64 {
    ((a as u128 * b as u128) % p as u128) as u64
}

pub(crate) fn pow_mod(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1u64;
    a %= p;
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, a, p);
        }
        a = mul_mod(a, a, p);
        e >>= 1;
    }
    r
}

/// Deterministic Miller–Rabin for 64-bit integers (these twelve bases
/// decide every n < 2^64).
pub(crate) fn is_prime(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    for p in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        if n % p == 0 {
            return n == p;
        }
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'base: for a in [2u64, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37] {
        let mut x = pow_mod(a, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mul_mod(x, x, n);
            if x == n - 1 {
                continue 'base;
            }
        }
        return false;
    }
    true
}

/// The primes below 2^62, largest first.
fn primes() -> impl Iterator<Item = u64> {
    ((1u64 << 61)..(1u64 << 62)).rev().filter(|&n| n % 2 == 1 && is_prime(n))
}

/// a⁻¹ mod a prime p (a ≠ 0 mod p), by Fermat.
pub(crate) fn inv_mod(a: u64, p: u64) -> u64 {
    pow_mod(a, p - 2, p)
}

fn trim_mod(mut a: Vec<u64>) -> Vec<u64> {
    while a.last() == Some(&0) {
        a.pop();
    }
    a
}

/// The remainder of a by b modulo p (b nonzero).
fn rem_mod(mut a: Vec<u64>, b: &[u64], p: u64) -> Vec<u64> {
    let db = b.len() - 1;
    let inv = inv_mod(b[db], p);
    while a.len() > db {
        let k = a.len() - 1 - db;
        let c = mul_mod(a[a.len() - 1], inv, p);
        if c != 0 {
            for (i, &x) in b.iter().enumerate() {
                let s = mul_mod(c, x, p);
                a[i + k] = (a[i + k] + p - s) % p;
            }
        }
        a.pop();
        a = trim_mod(a);
    }
    a
}

/// One Chinese-remainder step: each x ≡ acc (mod M) becomes the x with
/// x ≡ acc (mod M) and x ≡ image (mod p), in [0, M·p) (p prime, p ∤ M).
fn crt_step(acc: &mut [BigInt], modulus: &BigInt, image: &[u64], p: u64) {
    let m_inv = inv_mod(residue(modulus, p), p);
    for (x, &r) in acc.iter_mut().zip(image) {
        let k = mul_mod((r + p - residue(x, p)) % p, m_inv, p);
        if k != 0 {
            *x += modulus * BigInt::from(k);
        }
    }
}

/// The monic gcd modulo p (both nonzero).
fn gcd_mod(a: &[u64], b: &[u64], p: u64) -> Vec<u64> {
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    while !b.is_empty() {
        let r = rem_mod(a, &b, p);
        a = b;
        b = r;
    }
    let inv = inv_mod(a[a.len() - 1], p);
    a.iter().map(|&x| mul_mod(x, inv, p)).collect()
}

fn reduce(f: &[BigInt], p: u64) -> Vec<u64> {
    trim_mod(f.iter().map(|c| residue(c, p)).collect())
}

/// The coefficients divided by their gcd, leading coefficient positive.
pub fn primitive_part(f: &[BigInt]) -> Vec<BigInt> {
    let g = super::content::content(f);
    if g.is_zero() {
        return f.to_vec();
    }
    let sign = if f.iter().rev().find(|c| !c.is_zero()).is_some_and(|c| c.is_negative()) { -1 } else { 1 };
    let g = g * sign;
    f.iter().map(|c| c / &g).collect()
}

/// f / d over Z when d divides f (d nonzero, lowest coefficient first),
/// else None. Every step divides by d's leading coefficient exactly, so no
/// rational is formed: dividing a degree-394 polynomial with
/// thousand-digit coefficients by its gcd with the derivative took
/// seconds over Q, in the gcds of each rational's normalisation. For a
/// primitive d, divisibility over Z is divisibility over Q (Gauss's lemma).
pub fn exact_quotient(f: &[BigInt], d: &[BigInt]) -> Option<Vec<BigInt>> {
    let mut r: Vec<BigInt> = f.to_vec();
    while r.last().is_some_and(Zero::is_zero) {
        r.pop();
    }
    let mut d = d.to_vec();
    while d.last().is_some_and(Zero::is_zero) {
        d.pop();
    }
    assert!(!d.is_empty(), "division by the zero polynomial");
    let dd = d.len() - 1;
    if r.len() <= dd {
        return r.is_empty().then(|| vec![BigInt::zero()]);
    }
    let mut quotient = vec![BigInt::zero(); r.len() - dd];
    let lead = &d[dd];
    while r.len() > dd {
        let top = r.len() - 1;
        let (c, rem) = r[top].div_rem(lead);
        if !rem.is_zero() {
            return None;
        }
        let k = top - dd;
        if !c.is_zero() {
            for (i, x) in d.iter().enumerate() {
                r[i + k] -= &c * x;
            }
        }
        quotient[k] = c;
        r.pop();
        while r.last().is_some_and(Zero::is_zero) {
            r.pop();
        }
    }
    r.is_empty().then_some(quotient)
}

/// Whether d divides f over Z (d primitive, nonzero; by Gauss's lemma this
/// is divisibility over Q too).
pub fn divides(d: &[BigInt], f: &[BigInt]) -> bool {
    exact_quotient(f, d).is_some()
}

/// The gcd of two nonzero integer polynomials (lowest coefficient first),
/// primitive with a positive leading coefficient.
pub fn gcd(f: &[BigInt], g: &[BigInt]) -> Vec<BigInt> {
    let trim = |f: &[BigInt]| {
        let mut v = f.to_vec();
        while v.last().is_some_and(Zero::is_zero) {
            v.pop();
        }
        primitive_part(&v)
    };
    let (f, g) = (trim(f), trim(g));
    assert!(!f.is_empty() && !g.is_empty(), "the gcd of the zero polynomial");
    if f.len() == 1 || g.len() == 1 {
        return vec![BigInt::one()];
    }
    if f == g {
        return f;
    }
    let (lf, lg) = (&f[f.len() - 1], &g[g.len() - 1]);
    // the gcd's leading coefficient divides both: scale each image to it
    let h = lf.gcd(lg);
    let mut best = usize::MAX;
    let mut acc: Vec<BigInt> = Vec::new();
    let mut modulus = BigInt::one();
    let mut last: Option<Vec<BigInt>> = None;
    for p in primes() {
        let pb = BigInt::from(p);
        if (lf % &pb).is_zero() || (lg % &pb).is_zero() {
            continue;
        }
        let image = gcd_mod(&reduce(&f, p), &reduce(&g, p), p);
        let d = image.len() - 1;
        if d == 0 {
            // the degree over Q is at most the degree modulo p
            return vec![BigInt::one()];
        }
        if d > best {
            continue; // an unlucky prime
        }
        let hp = residue(&h, p);
        let image: Vec<u64> = image.iter().map(|&c| mul_mod(c, hp, p)).collect();
        if d < best {
            best = d;
            acc = image.iter().map(|&c| BigInt::from(c)).collect();
            modulus = pb;
            last = None;
            continue;
        }
        crt_step(&mut acc, &modulus, &image, p);
        modulus *= &pb;
        // the symmetric representative, made primitive
        let half = &modulus / 2;
        let lifted: Vec<BigInt> = acc.iter().map(|a| if a > &half { a - &modulus } else { a.clone() }).collect();
        let candidate = primitive_part(&lifted);
        // test only once the lift stopped changing (one more prime agreed)
        if last.as_ref() == Some(&candidate) && divides(&candidate, &f) && divides(&candidate, &g) {
            return candidate;
        }
        last = Some(candidate);
    }
    unreachable!("there are infinitely many primes below 2^62 for this purpose")
}

// ---- polynomials in t known by their values modulo word primes ----
//
// The exact sweep's resultants and subresultants are polynomials in t with
// integer coefficients of a known degree bound B and a proved bound 2^bits
// on every coefficient. Their values at t = 0, 1, ..., B modulo a prime p
// (computed in machine words) interpolate to the polynomial modulo p; the
// images for several primes combine by the Chinese remainder theorem, and
// once the primes' product exceeds 2^(bits + 1) the symmetric lift is the
// polynomial itself — no early stop, so the answer is exact whatever the
// values looked like (von zur Gathen–Gerhard, *Modern Computer Algebra*,
// §§5.4–5.5).

/// The primes in [2^30, 2^31), largest first: residues below 2^31, so a
/// product of two fits in a u64 and the remainders stay in hardware
/// division (the u128 remainders of `mul_mod` cost several times more).
///
/// The list is found once per process and grown on demand (Miller–Rabin on
/// every odd number below 2^31 from the top, in u128 arithmetic, was a few
/// per cent of an exact sweep when each resultant searched it again).
pub(crate) fn word_primes() -> impl Iterator<Item = u64> {
    (0usize..).map_while(word_prime)
}

/// The i-th word prime (largest first), None past the last one.
fn word_prime(i: usize) -> Option<u64> {
    static FOUND: std::sync::Mutex<Vec<u64>> = std::sync::Mutex::new(Vec::new());
    let mut found = FOUND.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    while found.len() <= i {
        let below = found.last().copied().unwrap_or(1u64 << 31);
        let next = ((1u64 << 30)..below).rev().find(|&n| n % 2 == 1 && is_prime(n))?;
        found.push(next);
    }
    Some(found[i])
}

/// a⁻¹ modulo a word prime p (a ≢ 0): the extended Euclidean algorithm in
/// machine integers (Fermat's a^(p−2) needs 60 u128 remainders, which
/// were a quarter of an exact sweep's time inside the eliminations).
pub(crate) fn word_inv(a: u64, p: u64) -> u64 {
    let (mut r0, mut r1) = (p as i64, (a % p) as i64);
    let (mut s0, mut s1) = (0i64, 1i64);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (s0, s1) = (s1, s0 - q * s1);
    }
    debug_assert_eq!(r0, 1, "{a} is invertible modulo the prime {p}");
    s0.rem_euclid(p as i64) as u64
}

/// The inverses of 1, 2, ..., n modulo a word prime p > n (index 0 unused):
/// inv(k) = −⌊p/k⌋·inv(p mod k), from p = ⌊p/k⌋·k + (p mod k).
pub(crate) fn word_inverses(n: usize, p: u64) -> Vec<u64> {
    let mut inv = vec![0u64; n + 1];
    if n >= 1 {
        inv[1] = 1;
    }
    for k in 2..=n as u64 {
        inv[k as usize] = (p - p / k) * inv[(p % k) as usize] % p;
    }
    inv
}

/// a·b mod p for a word prime p (a, b < p < 2^31).
#[inline]
pub(crate) fn word_mul(a: u64, b: u64, p: u64) -> u64 {
    a * b % p
}

/// A word prime with its Barrett constant m = ⌊2^64/p⌋: x mod p for any
/// x < 2^64 by one high multiplication and at most one subtraction.
/// Why: a 64-bit division costs tens of cycles, and the determinants,
/// interpolations and exterior squares of the exact sweep do little else
/// (a remainder per product). Correctness: with m > 2^64/p − 1 and
/// q = ⌊x·m/2^64⌋, x/p − 1 − x/2^64 < q ≤ x/p, so q ≥ ⌊x/p⌋ − 1 and
/// x − q·p lies in [0, 2p).
#[derive(Clone, Copy, Debug)]
pub(crate) struct WordPrime {
    pub p: u64,
    m: u64,
}

impl WordPrime {
    pub(crate) fn new(p: u64) -> WordPrime {
        debug_assert!(p > 2 && p < 1 << 32, "a word prime");
        WordPrime { p, m: u64::MAX / p }
    }
    /// x mod p.
    #[inline]
    pub(crate) fn reduce(self, x: u64) -> u64 {
        let q = ((x as u128 * self.m as u128) >> 64) as u64;
        let r = x - q * self.p;
        if r >= self.p {
            r - self.p
        } else {
            r
        }
    }
    /// a·b mod p (a, b < 2^32).
    #[inline]
    pub(crate) fn mul(self, a: u64, b: u64) -> u64 {
        self.reduce(a * b)
    }
}

/// c mod p in [0, p).
pub(crate) fn residue(c: &BigInt, p: u64) -> u64 {
    c.mod_floor(&BigInt::from(p)).to_u64().expect("a residue below p")
}

/// a(t) mod p (coefficients lowest first, already residues).
pub(crate) fn eval_word(a: &[u64], t: u64, p: u64) -> u64 {
    let w = WordPrime::new(p);
    let t = w.reduce(t);
    // acc·t + c < p² + p < 2^63
    a.iter().rev().fold(0u64, |acc, &c| w.reduce(acc * t + c))
}

/// The coefficients (lowest first) of the polynomial of degree < len
/// through (i, y_i), i = 0, 1, ..., modulo p (Newton's divided
/// differences; p > len, so the points are distinct modulo p).
pub(crate) fn interpolate_word(y: &[u64], p: u64) -> Vec<u64> {
    let n = y.len();
    if n == 0 {
        return Vec::new();
    }
    let mut dd = y.to_vec();
    let inverses = word_inverses(n, p);
    let w = WordPrime::new(p);
    // one remainder per step: (x + p − y)·z < 2p·p < 2^63
    for level in 1..n {
        let il = inverses[level];
        for i in (level..n).rev() {
            dd[i] = w.reduce((dd[i] + p - dd[i - 1]) * il);
        }
    }
    // out ← out·(t − i) + dd[i], in place from the top: the new
    // coefficient of t^k is out_{k−1} + (p − i)·out_k (< p + p² < 2^63)
    let mut out = vec![0u64; n];
    out[0] = dd[n - 1];
    for i in (0..n - 1).rev() {
        let minus_i = (p - i as u64 % p) % p;
        let len = n - 1 - i;
        out[len] = out[len - 1];
        for k in (1..len).rev() {
            out[k] = w.reduce(out[k - 1] + minus_i * out[k]);
        }
        out[0] = w.reduce(dd[i] + minus_i * out[0]);
    }
    out
}

/// The determinant of a square matrix modulo a word prime (elimination).
pub(crate) fn det_word(mut m: Vec<Vec<u64>>, p: u64) -> u64 {
    let n = m.len();
    let w = WordPrime::new(p);
    let mut det = 1u64;
    for c in 0..n {
        let Some(r) = (c..n).find(|&r| m[r][c] != 0) else { return 0 };
        if r != c {
            m.swap(r, c);
            det = (p - det) % p;
        }
        det = w.mul(det, m[c][c]);
        let iv = word_inv(m[c][c], p);
        let (top, rest) = m.split_at_mut(c + 1);
        let pivot_row = &top[c];
        for row in rest.iter_mut() {
            if row[c] == 0 {
                continue;
            }
            // row −= f·pivot row, one remainder per entry:
            // x + (p − f)·y < p + p² < 2^63
            let minus_f = p - w.mul(row[c], iv);
            for (x, &y) in row[c..].iter_mut().zip(&pivot_row[c..]) {
                *x = w.reduce(*x + minus_f * y);
            }
        }
    }
    det
}

/// What [`from_word_values`] found.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum Lifted {
    /// the polynomial exactly (lowest first, trailing zeros trimmed; empty:
    /// proved identically zero)
    Exact(Vec<BigInt>),
    /// `give_up_on_zero` images in a row were zero before any nonzero one:
    /// the caller asked not to pay for the proof that it vanishes
    GaveUpOnZero,
}

/// The integer polynomial f of degree ≤ `degree` whose every coefficient is
/// below 2^`bits` in absolute value, from `values(p)` = (f(0), ..., f(degree))
/// modulo each word prime p (None: p is not usable, skip it — e.g. no
/// root of unity of the order needed). The primes are used until their
/// product exceeds 2^(bits + 1) (then the symmetric lift is f exactly).
/// `give_up_on_zero`: stop after that many all-zero images while every image
/// so far is zero (None: prove the zero too).
pub(crate) fn from_word_values(
    degree: usize,
    bits: u64,
    give_up_on_zero: Option<usize>,
    mut values: impl FnMut(u64) -> Option<Vec<u64>>,
) -> Lifted {
    assert!(degree < 1 << 29, "the points 0..degree are distinct modulo word primes");
    let mut acc: Vec<BigInt> = vec![BigInt::zero(); degree + 1];
    let mut modulus = BigInt::one();
    let mut all_zero_so_far = 0usize;
    for p in word_primes() {
        let Some(v) = values(p) else { continue };
        debug_assert_eq!(v.len(), degree + 1);
        let image = interpolate_word(&v, p);
        if image.iter().all(|&c| c == 0) && acc.iter().all(Zero::is_zero) {
            all_zero_so_far += 1;
            if give_up_on_zero.is_some_and(|g| all_zero_so_far >= g) {
                return Lifted::GaveUpOnZero;
            }
        }
        crt_step(&mut acc, &modulus, &image, p);
        modulus *= BigInt::from(p);
        if modulus.bits() > bits + 1 {
            break;
        }
    }
    if std::env::var_os("SUBDLAB_EXACT_TRACE").is_some() {
        eprintln!("  from_word_values: degree {degree}, {bits} bits, {} bits of primes", modulus.bits());
    }
    let half = &modulus / 2;
    let mut out: Vec<BigInt> = acc.into_iter().map(|x| if x > half { x - &modulus } else { x }).collect();
    while out.last().is_some_and(Zero::is_zero) {
        out.pop();
    }
    Lifted::Exact(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn z(c: &[i64]) -> Vec<BigInt> {
        c.iter().map(|&x| BigInt::from(x)).collect()
    }

    fn mul(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
        let mut out = vec![BigInt::zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j] += x * y;
            }
        }
        out
    }

    #[test]
    fn gcd_of_products_is_the_common_factor() {
        // (3x² − 5)(7x + 2)² and (3x² − 5)(x − 11)(7x + 2): gcd (3x² − 5)(7x + 2)
        let a = z(&[-5, 0, 3]);
        let b = z(&[2, 7]);
        let f = mul(&mul(&a, &b), &b);
        let g = mul(&mul(&a, &z(&[-11, 1])), &b);
        assert_eq!(gcd(&f, &g), mul(&a, &b));
        // coprime
        assert_eq!(gcd(&z(&[-2, 0, 1]), &z(&[-3, 0, 1])), z(&[1]));
        // large coefficients: (10^40 x + 1)(x² + 1) and (10^40 x + 1)(x − 1)
        let big = vec![BigInt::one(), BigInt::from(10).pow(40)];
        let f = mul(&big, &z(&[1, 0, 1]));
        let g = mul(&big, &z(&[-1, 1]));
        assert_eq!(gcd(&f, &g), big);
    }

    #[test]
    fn exact_quotients() {
        // (3x² − 5)(7x + 2) / (7x + 2) = 3x² − 5; by x − 1: not exact
        let a = z(&[-5, 0, 3]);
        let b = z(&[2, 7]);
        assert_eq!(exact_quotient(&mul(&a, &b), &b), Some(a.clone()));
        assert_eq!(exact_quotient(&mul(&a, &b), &z(&[-1, 1])), None);
        // 2x + 2 by 2x + 1: the remainder 1 is not zero
        assert_eq!(exact_quotient(&z(&[2, 2]), &z(&[1, 2])), None);
    }

    #[test]
    fn polynomials_from_values_modulo_word_primes() {
        // f(t) = −3·10^30 + 7t − t³: coefficients below 2^100; its values
        // modulo each prime give it back exactly
        let big: BigInt = BigInt::from(10).pow(30u32) * 3;
        let f = vec![-big.clone(), BigInt::from(7), BigInt::zero(), BigInt::from(-1)];
        let value = |p: u64| -> Option<Vec<u64>> {
            let r: Vec<u64> = f.iter().map(|c| residue(c, p)).collect();
            Some((0..=5u64).map(|t| eval_word(&r, t, p)).collect())
        };
        assert_eq!(from_word_values(5, 100, None, value), Lifted::Exact(f.clone()));
        // the zero polynomial: proved (empty), or given up on when asked
        assert_eq!(from_word_values(3, 100, None, |_| Some(vec![0; 4])), Lifted::Exact(vec![]));
        assert_eq!(from_word_values(3, 100, Some(2), |_| Some(vec![0; 4])), Lifted::GaveUpOnZero);
        // det [[2, 3], [5, 7]] = −1
        let p = word_primes().next().unwrap();
        assert_eq!(det_word(vec![vec![2, 3], vec![5, 7]], p), p - 1);
    }

    #[test]
    fn word_arithmetic_agrees_with_hardware_remainders() {
        let primes: Vec<u64> = word_primes().take(3).collect();
        assert_eq!(primes[0], (1u64 << 31) - 1); // 2^31 − 1 is prime (Mersenne)
        for &p in primes.iter().chain([3u64, 5, 1_000_000_007].iter()) {
            let w = WordPrime::new(p);
            // Barrett against the hardware remainder, at the edges and inside
            for x in [0, 1, p - 1, p, p + 1, 2 * p - 1, p * p - 1, (p - 1) * (p - 1) + p, u64::MAX, u64::MAX - p] {
                assert_eq!(w.reduce(x), x % p, "{x} mod {p}");
            }
            let mut x = 0x9e37_79b9_7f4a_7c15u64;
            for _ in 0..1000 {
                x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
                assert_eq!(w.reduce(x), x % p);
            }
            // inverses: a·a⁻¹ ≡ 1, and the table of 1..n is the same
            let table = word_inverses(50.min(p as usize - 1), p);
            for a in 1..table.len() as u64 {
                assert_eq!(a * word_inv(a, p) % p, 1, "{a}⁻¹ mod {p}");
                assert_eq!(table[a as usize], word_inv(a, p));
            }
            assert_eq!((p - 1) * word_inv(p - 1, p) % p, 1);
        }
        // interpolation through (i, f(i)) of f = 3 + 2t − t³ (mod p)
        let p = primes[1];
        let f = |t: u64| (3 + 2 * t + p * p - t * t * t % p) % p;
        let y: Vec<u64> = (0..6).map(f).collect();
        assert_eq!(interpolate_word(&y, p), vec![3, 2, 0, p - 1, 0, 0]);
    }

    #[test]
    fn primes_are_prime() {
        assert!(is_prime(2_305_843_009_213_693_951)); // 2^61 − 1, a Mersenne prime
        assert!(!is_prime(3_215_031_751)); // a strong pseudoprime to bases 2, 3, 5, 7
        assert!(primes().take(3).all(|p| p > 1 << 61));
    }
}
