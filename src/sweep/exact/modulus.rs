//! The modulus family of the exact sweep: the values of t where a non-real
//! eigenvalue's modulus equals a real root of a target polynomial (λ1's
//! block polynomial, or x − 1 for convergence).
//!
//! Why these and how (ARCHITECTURE.md, "The exact sweep", step 3b):
//!
//! - A block polynomial P(x, t) with real coefficients has its non-real
//!   roots in conjugate pairs u, ū, and |u|² = u·ū is a product of two
//!   roots of P with distinct indices. So every |u|² is a root of
//!   E(s) = ∏_{i<j} (s − x_i x_j), the characteristic polynomial of the
//!   exterior square Λ²(B) of the block (degree D = d(d − 1)/2).
//! - |u| = r for a real root r of the target T means s = r² is also a root
//!   of G(s) = ∏_k (s − y_k²), T's root-squared polynomial (Graeffe; the
//!   y_k are T's roots). E and G have a common root, so their resultant
//!   Res_s(E, G)(t) vanishes. Its real roots in t contain every such
//!   crossing, plus spurious ones (products of two real roots, squares of
//!   other roots of T): candidates are only candidates, each piece is
//!   still decided at an interior point.
//!
//! Computation, exact, by small primes (no subresultant over Q(ζ)[t] of a
//! 45 × 9 pair, which evaluation over Q would take minutes for):
//!
//! 1. The coefficients of P and T as polynomials in t over Q (the sweep's
//!    block polynomials of real coefficients; at n = 3, 4, 6 they are
//!    rational, Q(ζ_n) ∩ R = Q); roots constant in t at 0, 1, −1 divided
//!    out (a constant real root is never one of a non-real pair).
//! 2. A common scale L, the least (up to primes above 1000) with
//!    L^k·c_{d−k} integral for every k and both polynomials:
//!    P̃(y) = L^d P(y/L) has integer coefficients in t and roots L·x, so E
//!    and G of the scaled polynomials have roots L²·x_i x_j and L²·y_k²:
//!    the same crossings, and Res only multiplied by L^{2D·deg G}.
//! 3. Res_s(E, G) is isobaric of weight D·deg G in the coefficients (the
//!    coefficient of s^{D−k} weighs k); the coefficient of x^{d−k} of P has
//!    degree ≤ e·k in t (e the larger slope max_k deg_t(c_k)/k of P and T),
//!    so E's and G's weigh 2e per unit and deg_t Res ≤ 2e·D·deg G =: B.
//! 4. On |t| = 1 every coefficient of P̃ is at most its integer 1-norm m_k,
//!    every root at most ρ = 2 max_k ⌈m_k^{1/k}⌉ (Fujiwara). Res(E, G) =
//!    ∏_{k, i<j} (y_k² − x_i x_j) (both monic), so |Res(t)| ≤
//!    (ρ_T² + ρ²)^{D·deg G} =: M there. Each coefficient of Res is a Cauchy
//!    integral over |t| = 1, so at most M.
//! 5. Modulo primes p < 2^31 (p > B): at t = 0, 1, ..., B, E by Newton's
//!    identities (power sums of P, q_k = (p_k² − p_{2k})/2 the power sums of
//!    the products, back to coefficients), G by root squaring, Res = det of
//!    multiplication by E on F_p[s]/(G) (G monic); the values interpolated;
//!    the images combined by the Chinese remainder theorem until the product
//!    of the primes exceeds 2M, then the symmetric lift is Res exactly.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::numeric::exact::Poly;
use crate::numeric::modular::{
    det_word, eval_word, from_word_values, is_prime, residue, word_inverses, word_mul as mm, Lifted, WordPrime,
};
use crate::numeric::{BiPoly, Rational, TPoly};

/// A polynomial in t over Q, lowest first.
pub(crate) type QT = Vec<Rational>;
/// A polynomial in t over Z, lowest first.
type ZT = Vec<BigInt>;

/// The coefficients of p (of x^0, x^1, ...) as polynomials in t over Q, or
/// None when one is not rational.
pub(crate) fn rational_coefficients(p: &BiPoly) -> Option<Vec<QT>> {
    p.iter()
        .map(|c: &TPoly| {
            if !c.is_defined() {
                return None;
            }
            c.coeffs().iter().map(|x| x.to_rational()).collect::<Option<QT>>()
        })
        .collect()
}

fn qt_is_zero(a: &QT) -> bool {
    a.iter().all(Zero::is_zero)
}

fn qt_add_scaled(a: &QT, b: &QT, c: &Rational) -> QT {
    let mut out = vec![<Rational as Zero>::zero(); a.len().max(b.len())];
    for (k, x) in a.iter().enumerate() {
        out[k] += x;
    }
    for (k, x) in b.iter().enumerate() {
        out[k] += x * c;
    }
    out
}

/// Divide out roots of p constant in t at 0, 1 and −1 (as often as they
/// divide): real for every t, they are never one of a non-real pair.
fn without_unit_roots(mut p: Vec<QT>) -> Vec<QT> {
    for c in [0i64, 1, -1] {
        let c = Rational::from_integer(c.into());
        loop {
            if p.len() <= 1 {
                break;
            }
            // p(c, t) as a polynomial in t
            let value = p.iter().rev().fold(QT::new(), |acc, a| qt_add_scaled(a, &acc, &c));
            if !qt_is_zero(&value) {
                break;
            }
            // synthetic division by (x − c): q_{k−1} = a_k + c q_k
            let d = p.len() - 1;
            let mut q = vec![QT::new(); d];
            q[d - 1] = p[d].clone();
            for k in (1..d).rev() {
                q[k - 1] = qt_add_scaled(&p[k], &q[k], &c);
            }
            p = q;
        }
    }
    p
}

/// Whether every root of the nonzero f (over Q) is real: its square-free
/// part has as many real roots as its degree (Sturm count).
pub(crate) fn all_roots_real(f: &Poly) -> bool {
    let sq = crate::numeric::sturm::squarefree(f);
    if sq.degree() == 0 {
        return true;
    }
    let bound = crate::numeric::sturm::root_bound(&sq);
    let chain = crate::numeric::sturm::sturm_chain(&sq);
    crate::numeric::sturm::count_roots(&chain, &-bound.clone(), &bound) == sq.degree()
}

/// Divide out the factor of p constant in t, when all its roots are real:
/// a real root is never one of a non-real pair, so the crossings are
/// unchanged. Why: P = Σ_k t^k P_k(x), and f(x) divides P for every t iff
/// it divides every P_k, so f = gcd_k P_k is the largest such factor. Two
/// constant roots a, b of the block and c of the target with a·b = c² make
/// Res(E, G) vanish identically (Catmull–Clark's outer eigenvalues 1/8 ·
/// 1/32 = (1/16)²) — the family would be lost for nothing. A constant
/// factor with non-real roots is kept (a constant pair can still cross a
/// moving target), and then only 0, ±1 are divided out, as always.
fn without_constant_roots(p: Vec<QT>) -> Vec<QT> {
    let t_len = p.iter().map(Vec::len).max().unwrap_or(0);
    let f = (0..t_len)
        .map(|k| Poly {
            coeffs: p.iter().map(|c| c.get(k).cloned().unwrap_or_else(<Rational as Zero>::zero)).collect(),
        })
        .filter(|slice| !slice.is_zero())
        .fold(None, |g: Option<Poly>, slice| Some(g.map_or_else(|| slice.gcd(&slice), |g| g.gcd(&slice))));
    match f {
        Some(f) if f.degree() >= 1 && all_roots_real(&f) => {
            // f is monic (Poly::gcd) and holds every constant root with its
            // multiplicity (f² | P for all t would make f² | gcd_k P_k = f)
            let h: Vec<QT> = f.coeffs.iter().map(|c| vec![c.clone()]).collect();
            divide_exactly(&p, &h).unwrap_or_else(|| without_unit_roots(p))
        }
        _ => without_unit_roots(p),
    }
}

fn qt_mul(a: &QT, b: &QT) -> QT {
    if a.is_empty() || b.is_empty() {
        return QT::new();
    }
    let mut out = vec![<Rational as Zero>::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// p divided by the monic h in Q[t][x], when h divides p exactly.
pub(crate) fn divide_exactly(p: &[QT], h: &[QT]) -> Option<Vec<QT>> {
    let (dp, dh) = (p.len() - 1, h.len() - 1);
    if dh > dp {
        return None;
    }
    let mut r: Vec<QT> = p.to_vec();
    let mut q = vec![QT::new(); dp - dh + 1];
    let minus_one = -<Rational as One>::one();
    for k in (0..=dp - dh).rev() {
        let c = r[k + dh].clone();
        for (i, hc) in h.iter().enumerate() {
            r[k + i] = qt_add_scaled(&r[k + i], &qt_mul(&c, hc), &minus_one);
        }
        q[k] = c;
    }
    r.iter().all(qt_is_zero).then_some(q)
}

/// The polynomial of degree < len through (x_i, y_i) over Q.
pub(crate) fn interpolate_q(x: &[Rational], y: &[Rational]) -> QT {
    let n = x.len();
    let mut dd = y.to_vec();
    for level in 1..n {
        for i in (level..n).rev() {
            dd[i] = (&dd[i] - &dd[i - 1]) / (&x[i] - &x[i - level]);
        }
    }
    let mut out: QT = vec![dd[n - 1].clone()];
    for i in (0..n - 1).rev() {
        let mut next = vec![<Rational as Zero>::zero(); out.len() + 1];
        for (k, c) in out.iter().enumerate() {
            next[k + 1] += c;
            next[k] -= c * &x[i];
        }
        next[0] += &dd[i];
        out = next;
    }
    out
}

/// Divide out a repeated factor of p: a root branch of multiplicity two
/// for every t (unified-sqrt3 has one in every block) makes x_i x_i a root
/// of E for all t and x_i² one of G, so Res(E, G) vanishes identically.
/// H = gcd_x(p, ∂p/∂x) is found at integer points t (where its degree is
/// least, it is H(t): monic, coefficients of degree ≤ e·j in t) and
/// interpolated; it is used only when H² divides p exactly — then p/H has
/// every root of p, so no non-real pair is lost. Otherwise p is kept.
fn without_repeated_factor(p: Vec<QT>) -> Vec<QT> {
    let d = p.len() - 1;
    let h = interpolated_factor(&slope(&p), 2 * d as i64 + 40, |t| {
        let f = value_at(&p, t);
        f.gcd(&f.derivative())
    });
    match h.and_then(|h| divide_exactly(&p, &h).and_then(|q| divide_exactly(&q, &h).map(|_| q))) {
        Some(q) => q,
        None => p,
    }
}

/// p ∈ Q[t][x] at t (coefficients of x, lowest first).
pub(crate) fn value_at(p: &[QT], t: i64) -> Poly {
    let t = Rational::from_integer(t.into());
    Poly { coeffs: p.iter().map(|c| c.iter().rev().fold(<Rational as Zero>::zero(), |acc, x| acc * &t + x)).collect() }
}

/// A monic H ∈ Q[t][x] read off its values: `at(t₀)` (t₀ = 0, 1, ...,
/// `tries` − 1) is a monic polynomial over Q whose degree is at least
/// deg H everywhere and equals it but at finitely many t₀, and which is
/// H(t₀) there (a gcd in x at t₀ of polynomials H divides). The points of
/// least degree k are kept; H's coefficient of x^{k−j} is ± an elementary
/// symmetric function of j roots, growing at most like |t|^e (`e` the
/// slope of the polynomials H divides), so it has degree ≤ e·j and
/// ⌊e·k⌋ + 1 points of degree k determine H, coefficient by coefficient.
/// `None` when a point has degree 0 (no common factor) or the points run
/// out. Nothing here is trusted: the caller accepts H only by exact
/// division (a wrong interpolation, from too few points of the true
/// degree, fails it).
pub(crate) fn interpolated_factor(e: &Rational, tries: i64, at: impl Fn(i64) -> Poly) -> Option<Vec<QT>> {
    // (degree, points of that degree) for the least degree seen
    let mut best: Option<(usize, Vec<(Rational, Poly)>)> = None;
    for t in 0..tries {
        let g = at(t);
        let k = g.degree();
        if k == 0 {
            return None;
        }
        match &mut best {
            Some((bk, points)) if *bk == k => points.push((Rational::from_integer(t.into()), g)),
            Some((bk, _)) if *bk < k => continue,
            _ => best = Some((k, vec![(Rational::from_integer(t.into()), g)])),
        }
        let (bk, points) = best.as_ref().expect("set above");
        let need = (e.clone() * Rational::from_integer((*bk as i64).into())).floor().to_integer();
        let need = need.to_usize().unwrap_or(usize::MAX).saturating_add(1);
        if points.len() < need {
            continue;
        }
        let xs: Vec<Rational> = points.iter().map(|(x, _)| x.clone()).collect();
        return Some(
            (0..=*bk)
                .map(|j| {
                    let ys: Vec<Rational> = points
                        .iter()
                        .map(|(_, g)| g.coeffs.get(j).cloned().unwrap_or_else(<Rational as Zero>::zero))
                        .collect();
                    interpolate_q(&xs, &ys)
                })
                .collect(),
        );
    }
    None
}

/// max over k ≥ 1 of deg_t(c_k)/k, c_k the coefficient of x^{d−k}.
pub(crate) fn slope(p: &[QT]) -> Rational {
    let d = p.len() - 1;
    let mut e = <Rational as Zero>::zero();
    for k in 1..=d {
        let deg = p[d - k].iter().rposition(|c| !Zero::is_zero(c)).unwrap_or(0);
        let w = Rational::new((deg as i64).into(), (k as i64).into());
        if w > e {
            e = w;
        }
    }
    e
}

/// The least common scale L (up to primes above 1000) with L^k·c_{d−k}
/// integral for every k ≥ 1 and each monic P = Σ c_j x^j given: then
/// P̃(y) = L^d P(y/L) has integer coefficients.
///
/// Why not the lcm of all denominators (as before): a coefficient of
/// x^{d−k} with denominator 3^{3k} needs L = 3³, not 3^{3d}. The
/// resultant's coefficients grow like L^{2·D·deg G}: at unified-sqrt3,
/// n = 3, the lcm was 2⁸·3³⁰ and 12 466 of the 13 355 bits of the largest
/// coefficient were that content — the primes paid for it, and the
/// isolation too. Primes below 1000 get the exponent max_k ⌈v_q(den_k)/k⌉
/// (trial division); any cofactor left is taken whole (still sound:
/// it divides L, so L^k too).
fn common_scale(polys: &[&Vec<QT>]) -> BigInt {
    let small: Vec<u64> = (2u64..1000).filter(|&q| is_prime(q)).collect();
    let mut exponent = vec![0u64; small.len()];
    let mut rough = BigInt::one();
    for p in polys {
        let d = p.len() - 1;
        for k in 1..=d {
            let mut den = p[d - k].iter().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
            for (i, &q) in small.iter().enumerate() {
                let qb = BigInt::from(q);
                let mut v = 0u64;
                while (&den % &qb).is_zero() {
                    den /= &qb;
                    v += 1;
                }
                exponent[i] = exponent[i].max(v.div_ceil(k as u64));
            }
            rough = rough.lcm(&den);
        }
    }
    small.iter().zip(&exponent).fold(rough, |l, (&q, &e)| l * num_traits::pow(BigInt::from(q), e as usize))
}

/// P̃(y) = L^d P(y/L) (P monic): integer coefficients when L is a
/// `common_scale` of P; None when one is not an integer.
fn scaled(p: &[QT], l: &BigInt) -> Option<Vec<ZT>> {
    let d = p.len() - 1;
    p.iter()
        .enumerate()
        .map(|(k, a)| {
            let f = Rational::from_integer(num_traits::pow(l.clone(), d - k));
            a.iter()
                .map(|c| {
                    let v = c * &f;
                    v.is_integer().then(|| v.to_integer())
                })
                .collect()
        })
        .collect()
}

/// Fujiwara's bound on |y| over the roots of P̃ for every |t| = 1:
/// 2 max_k ⌈m_k^{1/k}⌉, m_k the 1-norm of the coefficient of y^{d−k}.
fn root_bound(p: &[ZT]) -> BigInt {
    let d = p.len() - 1;
    let mut r = BigInt::one();
    for k in 1..=d {
        let m: BigInt = p[d - k].iter().map(|c| c.abs()).sum();
        let root = m.nth_root(k as u32) + 1;
        if root > r {
            r = root;
        }
    }
    r * 2
}

// ---- arithmetic modulo a word prime (`numeric::modular`) ----

/// Power sums p_1..p_k of the roots of the monic c (lowest first), by
/// Newton's identities.
fn power_sums(c: &[u64], k: usize, p: u64) -> Vec<u64> {
    let d = c.len() - 1;
    // b_j = coefficient of x^{d−j}
    let b = |j: usize| c[d - j];
    let mut s = vec![0u64; k + 1];
    let w = WordPrime::new(p);
    for n in 1..=k {
        // p_n + b_1 p_{n−1} + … + b_{min(n−1, d)} p_{n−min} + [n ≤ d] n b_n = 0
        let mut acc = if n <= d { mm(n as u64 % p, b(n), p) } else { 0 };
        for i in 1..=(n - 1).min(d) {
            // one remainder: acc + b·s < p + p² < 2^63
            acc = w.reduce(acc + b(i) * s[n - i]);
        }
        s[n] = (p - acc) % p;
    }
    s
}

/// The monic polynomial of degree D (lowest first) with power sums q_1..q_D.
fn from_power_sums(q: &[u64], dd: usize, p: u64) -> Vec<u64> {
    let mut e = vec![0u64; dd + 1];
    e[0] = 1;
    let inverses = word_inverses(dd, p);
    let w = WordPrime::new(p);
    for k in 1..=dd {
        let mut acc = 0u64;
        for i in 1..=k {
            // ± e·q with one remainder: acc + (p − e)·q < p + p² < 2^63
            let ei = if i % 2 == 1 { e[k - i] } else { (p - e[k - i]) % p };
            acc = w.reduce(acc + ei * q[i]);
        }
        e[k] = mm(acc, inverses[k], p);
    }
    let mut out = vec![0u64; dd + 1];
    for (k, ek) in e.iter().enumerate() {
        out[dd - k] = if k % 2 == 0 { *ek } else { (p - ek) % p };
    }
    out
}

/// E(s) = ∏_{i<j} (s − x_i x_j) for the roots x of the monic c.
fn exterior_square(c: &[u64], p: u64) -> Vec<u64> {
    let d = c.len() - 1;
    let dd = d * (d - 1) / 2;
    if dd == 0 {
        return vec![1];
    }
    let s = power_sums(c, 2 * dd, p);
    let half = p.div_ceil(2); // 2⁻¹ modulo the odd p
    let w = WordPrime::new(p);
    let mut q = vec![0u64; dd + 1];
    for k in 1..=dd {
        // (s_k² + p − s_2k)·2⁻¹ with two remainders
        q[k] = w.mul(w.reduce(s[k] * s[k] + p - s[2 * k]), half);
    }
    from_power_sums(&q, dd, p)
}

/// G(s) = ∏_k (s − y_k²) for the roots y of the monic c: (−1)^d (Ev(s)² −
/// s Od(s)²) with c(y) = Ev(y²) + y Od(y²).
fn root_squared(c: &[u64], p: u64) -> Vec<u64> {
    let d = c.len() - 1;
    let even: Vec<u64> = c.iter().step_by(2).copied().collect();
    let odd: Vec<u64> = c.iter().skip(1).step_by(2).copied().collect();
    let mut g = vec![0u64; d + 1];
    let w = WordPrime::new(p);
    for (i, &x) in even.iter().enumerate() {
        for (j, &y) in even.iter().enumerate() {
            g[i + j] = w.reduce(g[i + j] + x * y);
        }
    }
    for (i, &x) in odd.iter().enumerate() {
        // − x·y as (p − x)·y: one remainder
        let minus_x = (p - x) % p;
        for (j, &y) in odd.iter().enumerate() {
            g[i + j + 1] = w.reduce(g[i + j + 1] + minus_x * y);
        }
    }
    if d % 2 == 1 {
        for x in g.iter_mut() {
            *x = (p - *x) % p;
        }
    }
    g
}

/// a mod the monic g (lowest first; the result has g's degree entries).
fn rem_monic(a: &[u64], g: &[u64], p: u64) -> Vec<u64> {
    let n = g.len() - 1;
    let w = WordPrime::new(p);
    let mut r = a.to_vec();
    for top in (n..r.len()).rev() {
        let c = r[top];
        if c != 0 {
            // r −= c·g with one remainder: x + (p − c)·y < p + p² < 2^63
            let minus_c = p - c;
            for i in 0..n {
                r[top - n + i] = w.reduce(r[top - n + i] + minus_c * g[i]);
            }
        }
        r[top] = 0;
    }
    r.resize(n, 0);
    r
}

/// ∏_{G(w) = 0} E(w) = det of multiplication by E on F_p[s]/(G), G monic.
fn resultant_monic(e: &[u64], g: &[u64], p: u64) -> u64 {
    let n = g.len() - 1;
    if n == 0 {
        return 1;
    }
    let mut cols = Vec::with_capacity(n);
    let mut v = rem_monic(e, g, p);
    for _ in 0..n {
        cols.push(v.clone());
        let mut shifted = vec![0u64; n + 1];
        shifted[1..].copy_from_slice(&v);
        v = rem_monic(&shifted, g, p);
    }
    // the determinant of the transpose: the same
    det_word(cols, p)
}

/// What the family gives for one pair (block polynomial, target).
#[derive(Debug)]
pub(crate) enum Crossings {
    /// Res_s(E, G) as a polynomial in t over Q (nonzero; may be constant)
    Resultant(Poly),
    /// the block has no two roots that can be a non-real pair (degree < 2
    /// after the constant roots are divided out)
    Nothing,
}

/// The polynomial in t whose real roots include every t where a non-real
/// root u of `block` has |u| equal to a real root of `target` (both monic
/// in x with real coefficients). Err: why the family cannot be followed
/// for this pair (coefficients not rational, a resultant that vanishes
/// identically).
pub(crate) fn crossings(block: &BiPoly, target: &BiPoly) -> Result<Crossings, String> {
    let not_rational = "the modulus family needs block polynomials with rational coefficients";
    let not_integral = "the modulus family's scaled block polynomial is not integral (an internal error)";
    let a = rational_coefficients(block).ok_or(not_rational)?;
    let b = rational_coefficients(target).ok_or(not_rational)?;
    for p in [&a, &b] {
        if p.last().map(|c| c.len() == 1 && c[0].is_one()) != Some(true) {
            return Err("the modulus family needs monic block polynomials".into());
        }
    }
    let a = without_repeated_factor(without_constant_roots(a));
    let d = a.len() - 1;
    if d < 2 || b.len() < 2 {
        return Ok(Crossings::Nothing);
    }
    let l = common_scale(&[&a, &b]);
    let (za, zb) = (scaled(&a, &l).ok_or(not_integral)?, scaled(&b, &l).ok_or(not_integral)?);
    let dd = d * (d - 1) / 2;
    let ng = b.len() - 1;
    let e = slope(&a).max(slope(&b));
    let bound = (e * Rational::from_integer(BigInt::from(2 * dd * ng))).floor().to_integer();
    let bound = bound.to_usize().filter(|&b| b < 100_000).ok_or("a modulus resultant of too high degree in t")?;
    let (ra, rb) = (root_bound(&za), root_bound(&zb));
    // |Res(t)| = ∏_{k, i<j} |y_k² − x_i x_j| ≤ (ρ_b² + ρ_a²)^{D·deg G} on
    // |t| = 1, so every coefficient (a Cauchy integral there) too; twice
    // that, plus one bit for the sign, is what the primes' product exceeds
    let need_bits = (dd * ng) as u64 * (&ra * &ra + &rb * &rb).bits() + 2;
    let lifted = from_word_values(bound, need_bits, Some(3), |p| {
        Some({
            let (pa, pb): (Vec<Vec<u64>>, Vec<Vec<u64>>) = (
                za.iter().map(|c| c.iter().map(|x| residue(x, p)).collect()).collect(),
                zb.iter().map(|c| c.iter().map(|x| residue(x, p)).collect()).collect(),
            );
            (0..=bound as u64)
                .map(|t| {
                    let ca: Vec<u64> = pa.iter().map(|c| eval_word(c, t, p)).collect();
                    let cb: Vec<u64> = pb.iter().map(|c| eval_word(c, t, p)).collect();
                    resultant_monic(&exterior_square(&ca, p), &root_squared(&cb, p), p)
                })
                .collect()
        })
    });
    let coeffs: Vec<Rational> = match lifted {
        Lifted::GaveUpOnZero => {
            return Err("the modulus resultant vanishes modulo three primes (identically, probably)".into())
        }
        Lifted::Exact(c) if c.is_empty() => return Err("the modulus resultant vanishes identically".into()),
        Lifted::Exact(c) => c.into_iter().map(Rational::from_integer).collect(),
    };
    Ok(Crossings::Resultant(Poly { coeffs }))
}

// ---- block polynomials over Q(ζ_N) (valences 5, 7, ...) ----
//
// The same family where the block polynomials are real but not rational:
// the constant roots and the repeated branch are divided out over Q(ζ_N)
// (the same steps as above, in cyclotomic arithmetic; the polynomials are
// small), and Res_s(E, G)(t) — in Q(ζ_N)[t] — is replaced by its norm over
// the distinct Galois conjugates of the pair (block, target), computed by
// the embeddings ζ_N ↦ w^a modulo primes p ≡ 1 (mod N) as in
// `subresultant` (step 4 there): the norm is in Z[t] after the scaling,
// its roots contain Res's, and each conjugate obeys the same coefficient
// bound, so the norm's coefficients are at most M^k for k conjugates.

use crate::numeric::Cyclotomic;
use crate::sweep::exact::subresultant::{norm_values, ZetaPoly};

/// A polynomial in t over Q(ζ), lowest first.
type KT = Vec<Cyclotomic>;

fn kzero() -> Cyclotomic {
    Cyclotomic::from_rational(&<Rational as Zero>::zero())
}

fn kt_trim(mut a: KT) -> KT {
    while a.last().is_some_and(crate::numeric::Weight::is_zero) {
        a.pop();
    }
    a
}

fn kt_add_scaled(a: &KT, b: &KT, c: &Cyclotomic) -> KT {
    let mut out = vec![kzero(); a.len().max(b.len())];
    for (k, x) in a.iter().enumerate() {
        out[k] = out[k].clone() + x.clone();
    }
    for (k, x) in b.iter().enumerate() {
        out[k] = out[k].clone() + x.clone() * c.clone();
    }
    kt_trim(out)
}

fn kt_mul(a: &KT, b: &KT) -> KT {
    if a.is_empty() || b.is_empty() {
        return KT::new();
    }
    let mut out = vec![kzero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = out[i + j].clone() + x.clone() * y.clone();
        }
    }
    kt_trim(out)
}

fn kt_eval(a: &KT, t: &Cyclotomic) -> Cyclotomic {
    a.iter().rev().fold(kzero(), |acc, c| acc * t.clone() + c.clone())
}

/// The polynomial in t of degree < len through (x_i, y_i) over Q(ζ)
/// (Newton's divided differences).
fn k_interpolate(x: &[Rational], y: &[Cyclotomic]) -> KT {
    let n = x.len();
    let q = |r: &Rational| Cyclotomic::from_rational(r);
    let mut dd = y.to_vec();
    for level in 1..n {
        for i in (level..n).rev() {
            dd[i] = (dd[i].clone() - dd[i - 1].clone()) / q(&(&x[i] - &x[i - level]));
        }
    }
    let mut out: KT = vec![dd[n - 1].clone()];
    for i in (0..n - 1).rev() {
        let mut next = vec![kzero(); out.len() + 1];
        for (k, c) in out.iter().enumerate() {
            next[k + 1] = next[k + 1].clone() + c.clone();
            next[k] = next[k].clone() - c.clone() * q(&x[i]);
        }
        next[0] = next[0].clone() + dd[i].clone();
        out = next;
    }
    out
}

/// The factor constant in t divided out when it has rational coefficients
/// and its roots are all real (as `without_constant_roots`: f = gcd_k P_k
/// over Q(ζ), monic), else 0, ±1 only.
fn k_without_constant_roots(p: Vec<KT>) -> Vec<KT> {
    let t_len = p.iter().map(Vec::len).max().unwrap_or(0);
    let f = (0..t_len)
        .map(|k| kt_trim(p.iter().map(|c| c.get(k).cloned().unwrap_or_else(kzero)).collect()))
        .filter(|slice| !slice.is_empty())
        .fold(None, |g: Option<Vec<Cyclotomic>>, slice| {
            Some(g.map_or_else(|| k_gcd(&slice, &[]), |g| k_gcd(&g, &slice)))
        });
    if let Some(f) = f.filter(|f| f.len() >= 2) {
        let rational: Option<Vec<Rational>> = f.iter().map(Cyclotomic::to_rational).collect();
        let real = rational.is_some_and(|coeffs| all_roots_real(&Poly { coeffs }));
        if real {
            let h: Vec<KT> = f.iter().map(|c| kt_trim(vec![c.clone()])).collect();
            if let Some(q) = k_divide_exactly(&p, &h) {
                return q;
            }
        }
    }
    k_without_unit_roots(p)
}

/// Constant roots 0, 1, −1 divided out (as `without_unit_roots`).
fn k_without_unit_roots(mut p: Vec<KT>) -> Vec<KT> {
    for c in [0i64, 1, -1] {
        let c = Cyclotomic::from_rational(&Rational::from_integer(c.into()));
        while p.len() > 1 {
            let value = p.iter().rev().fold(KT::new(), |acc, a| kt_add_scaled(a, &acc, &c));
            if !value.is_empty() {
                break;
            }
            let d = p.len() - 1;
            let mut q = vec![KT::new(); d];
            q[d - 1] = p[d].clone();
            for k in (1..d).rev() {
                q[k - 1] = kt_add_scaled(&p[k], &q[k], &c);
            }
            p = q;
        }
    }
    p
}

/// p / h for the monic h in Q(ζ)[t][x], when h divides p exactly.
fn k_divide_exactly(p: &[KT], h: &[KT]) -> Option<Vec<KT>> {
    let (dp, dh) = (p.len() - 1, h.len() - 1);
    if dh > dp {
        return None;
    }
    let mut r: Vec<KT> = p.to_vec();
    let mut q = vec![KT::new(); dp - dh + 1];
    let minus_one = Cyclotomic::from_rational(&-<Rational as One>::one());
    for k in (0..=dp - dh).rev() {
        let c = r[k + dh].clone();
        for (i, hc) in h.iter().enumerate() {
            r[k + i] = kt_add_scaled(&r[k + i], &kt_mul(&c, hc), &minus_one);
        }
        q[k] = c;
    }
    r.iter().all(|c| c.is_empty()).then_some(q)
}

/// The monic gcd of two polynomials in x over Q(ζ) (Euclid; degree ≤ 10
/// here, so the cyclotomic fractions stay small).
fn k_gcd(a: &[Cyclotomic], b: &[Cyclotomic]) -> Vec<Cyclotomic> {
    let (mut a, mut b) = (kt_trim(a.to_vec()), kt_trim(b.to_vec()));
    while !b.is_empty() {
        // a mod b
        let lead = b[b.len() - 1].clone();
        while a.len() >= b.len() && !a.is_empty() {
            let f = a[a.len() - 1].clone() / lead.clone();
            let shift = a.len() - b.len();
            for (i, x) in b.iter().enumerate() {
                a[shift + i] = a[shift + i].clone() - f.clone() * x.clone();
            }
            a.pop();
            a = kt_trim(a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    match a.last().cloned() {
        Some(lead) => a.into_iter().map(|c| c / lead.clone()).collect(),
        None => a,
    }
}

/// The repeated branch divided out over Q(ζ) (as `without_repeated_factor`:
/// H = gcd_x(p, ∂p/∂x) at integer t where its degree is least, its
/// coefficients interpolated (degree ≤ e·j in t), used only when H²
/// divides p exactly).
fn k_without_repeated_factor(p: Vec<KT>) -> Vec<KT> {
    let d = p.len() - 1;
    let e = p
        .iter()
        .enumerate()
        .take(d)
        .map(|(k, c)| Rational::new((c.len().saturating_sub(1) as i64).into(), ((d - k) as i64).into()))
        .fold(<Rational as Zero>::zero(), |a, b| a.max(b));
    let mut best: Option<(usize, Vec<(Rational, Vec<Cyclotomic>)>)> = None;
    for t in 0..(2 * d as i64 + 40) {
        let tq = Rational::from_integer(t.into());
        let tc = Cyclotomic::from_rational(&tq);
        let f: Vec<Cyclotomic> = p.iter().map(|c| kt_eval(c, &tc)).collect();
        let df: Vec<Cyclotomic> = f
            .iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| c.clone() * Cyclotomic::from_rational(&Rational::from_integer((k as i64).into())))
            .collect();
        let g = k_gcd(&f, &df);
        let k = g.len().saturating_sub(1);
        if k == 0 {
            return p;
        }
        match &mut best {
            Some((bk, pts)) if *bk == k => pts.push((tq, g)),
            Some((bk, _)) if *bk < k => {}
            _ => best = Some((k, vec![(tq, g)])),
        }
        let need =
            (e.clone() * Rational::from_integer((k as i64).into())).floor().to_integer().to_usize().unwrap_or(0) + 1;
        if let Some((bk, pts)) = &best {
            if *bk == k && pts.len() >= need {
                let xs: Vec<Rational> = pts.iter().map(|(x, _)| x.clone()).collect();
                let h: Vec<KT> = (0..=*bk)
                    .map(|j| {
                        let ys: Vec<Cyclotomic> = pts.iter().map(|(_, g)| g[j].clone()).collect();
                        kt_trim(k_interpolate(&xs, &ys))
                    })
                    .collect();
                return match k_divide_exactly(&p, &h).and_then(|q| k_divide_exactly(&q, &h).map(|_| q)) {
                    Some(q) => q,
                    None => p,
                };
            }
        }
    }
    p
}

/// The ζ-coefficients (exponent of ζ_N, rational) of one element.
fn zeta_entries(x: &Cyclotomic, order: u64) -> Vec<(u64, Rational)> {
    let m = x.order().unwrap_or(1) as u64;
    x.coefficients().map(|(i, r)| (i as u64 * (order / m), r)).collect()
}

/// The modulus family's polynomial for block polynomials over Q(ζ_N): the
/// norm of Res_s(E, G) over the `conjugates` (the a with distinct
/// σ_a(block, target)), as `crossings` for rational ones.
pub(crate) fn crossings_cyclotomic(block: &BiPoly, target: &BiPoly, conjugates: &[u64]) -> Result<Crossings, String> {
    let coefficients = |p: &BiPoly| -> Option<Vec<KT>> {
        p.iter().map(|c| c.is_defined().then(|| kt_trim(c.coeffs().to_vec()))).collect()
    };
    let not_numbers = "the modulus family needs block polynomials with defined coefficients";
    let (a, b) = (coefficients(block).ok_or(not_numbers)?, coefficients(target).ok_or(not_numbers)?);
    let one = Cyclotomic::from_rational(&<Rational as One>::one());
    for p in [&a, &b] {
        if p.last().map(|c| c.len() == 1 && c[0] == one) != Some(true) {
            return Err("the modulus family needs monic block polynomials".into());
        }
    }
    let a = k_without_repeated_factor(k_without_constant_roots(a));
    let d = a.len() - 1;
    if d < 2 || b.len() < 2 {
        return Ok(Crossings::Nothing);
    }
    let order = a.iter().chain(&b).flatten().fold(1u64, |l, c| {
        let m = c.order().unwrap_or(1) as u64;
        l / l.gcd(&m) * m
    });
    // the least scale: per power of x, the lcm of the ζ-coefficients' denominators
    let as_qt = |p: &[KT]| -> Vec<QT> {
        p.iter()
            .map(|c| {
                let den =
                    c.iter().flat_map(|x| zeta_entries(x, order)).fold(BigInt::one(), |l, (_, r)| l.lcm(r.denom()));
                vec![Rational::new(BigInt::one(), den)]
            })
            .collect()
    };
    let l = common_scale(&[&as_qt(&a), &as_qt(&b)]);
    let scale = |p: &[KT]| -> Option<ZetaPoly> {
        let dp = p.len() - 1;
        p.iter()
            .enumerate()
            .map(|(k, c)| {
                let f = Rational::from_integer(num_traits::pow(l.clone(), dp - k));
                c.iter()
                    .map(|x| {
                        zeta_entries(x, order)
                            .into_iter()
                            .map(|(e, r)| {
                                let v = r * &f;
                                v.is_integer().then(|| (e, v.to_integer()))
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect()
    };
    let not_integral = "the modulus family's scaled block polynomial is not integral (an internal error)";
    let (za, zb) = (scale(&a).ok_or(not_integral)?, scale(&b).ok_or(not_integral)?);
    // Fujiwara's bound from the 1-norms over t and ζ (every embedding)
    let bound_of = |z: &ZetaPoly| -> BigInt {
        let dz = z.len() - 1;
        let mut r = BigInt::one();
        for k in 1..=dz {
            let m: BigInt = z[dz - k].iter().flatten().map(|(_, c)| c.abs()).sum();
            r = r.max(m.nth_root(k as u32) + 1);
        }
        r * 2
    };
    let (ra, rb) = (bound_of(&za), bound_of(&zb));
    let dd = d * (d - 1) / 2;
    let ng = b.len() - 1;
    let slope_k = |p: &[KT]| -> Rational {
        let dp = p.len() - 1;
        (1..=dp)
            .map(|k| Rational::new((p[dp - k].len().saturating_sub(1) as i64).into(), (k as i64).into()))
            .fold(<Rational as Zero>::zero(), |x, y| x.max(y))
    };
    let e = slope_k(&a).max(slope_k(&b));
    let kc = conjugates.len();
    let one_bound = (e * Rational::from_integer(BigInt::from(2 * dd * ng))).floor().to_integer();
    let bound = one_bound
        .to_usize()
        .map(|b| b * kc)
        .filter(|&b| b < 100_000)
        .ok_or("a modulus resultant of too high degree in t")?;
    let need_bits = kc as u64 * (dd * ng) as u64 * (&ra * &ra + &rb * &rb).bits() + 2;
    let lifted = from_word_values(bound, need_bits, Some(3), |p| {
        norm_values(&za, &zb, conjugates, order, p, bound, |ca, cb| {
            resultant_monic(&exterior_square(ca, p), &root_squared(cb, p), p)
        })
    });
    match lifted {
        Lifted::GaveUpOnZero => {
            Err("the modulus resultant vanishes modulo three primes (identically, probably)".into())
        }
        Lifted::Exact(c) if c.is_empty() => Err("the modulus resultant vanishes identically".into()),
        Lifted::Exact(c) => {
            Ok(Crossings::Resultant(Poly { coeffs: c.into_iter().map(Rational::from_integer).collect() }))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: u64 = 1_000_000_007;

    #[test]
    fn power_sums_and_back() {
        // (x − 2)(x − 3)(x − 5): p_1 = 10, p_2 = 38, p_3 = 160, p_4 = 722
        let c = [P - 30, 31, P - 10, 1];
        let s = power_sums(&c, 4, P);
        assert_eq!(&s[1..], &[10, 38, 160, 722]);
        assert_eq!(from_power_sums(&s, 3, P), c.to_vec());
        // products 6, 10, 15: (s − 6)(s − 10)(s − 15) = s³ − 31 s² + 300 s − 900
        assert_eq!(exterior_square(&c, P), vec![P - 900, 300, P - 31, 1]);
        // squares 4, 9, 25: s³ − 38 s² + 361 s − 900
        assert_eq!(root_squared(&c, P), vec![P - 900, 361, P - 38, 1]);
    }

    /// A polynomial in x with coefficients in Q[t]: rows[k] = coefficients
    /// of x^k, as (numerator, denominator) of t^0, t^1, ...
    fn bipoly(rows: &[&[(i64, i64)]]) -> BiPoly {
        rows.iter()
            .map(|r| {
                TPoly::from_coeffs(
                    r.iter()
                        .map(|&(a, b)| crate::numeric::Cyclotomic::from_rational(&Rational::new(a.into(), b.into())))
                        .collect(),
                )
            })
            .collect()
    }

    /// `p` divided by its leading coefficient: the resultants are known up
    /// to a constant factor only (∝ in the derivations)
    fn monic(p: &Poly) -> Poly {
        let lead = p.coeffs.last().expect("a nonzero polynomial").clone();
        p.scale(&(Rational::one() / lead))
    }

    fn from_roots_squarefree(factors: &[&[i64]]) -> Poly {
        let p = factors.iter().fold(Poly { coeffs: vec![Rational::one()] }, |acc, f| {
            acc.mul(&Poly { coeffs: f.iter().map(|&c| Rational::from_integer(c.into())).collect() })
        });
        crate::numeric::sturm::squarefree(&p)
    }

    #[test]
    fn a_complex_pair_crossing_a_constant_modulus() {
        // P = x² + t: for t > 0 the pair ±i√t, |u|² = t; target x − 1/2:
        // |u| = 1/2 exactly at t = 1/4 (E(s) = s − t, G(s) = s − 1/4,
        // Res ∝ 1/4 − t; scaled by L = 2: 1 − 4t)
        let p = bipoly(&[&[(0, 1), (1, 1)], &[], &[(1, 1)]]);
        let target = bipoly(&[&[(-1, 2)], &[(1, 1)]]);
        let Crossings::Resultant(r) = crossings(&p, &target).unwrap() else { panic!("no resultant") };
        assert_eq!(monic(&crate::numeric::sturm::squarefree(&r)), monic(&from_roots_squarefree(&[&[-1, 4]])));
    }

    #[test]
    fn a_repeated_branch_is_divided_out() {
        // P = (x² + t)(x − t/2)², target T = (x − 1/2)(x − t/2): the double
        // branch t/2 gives (t/2)(t/2) in E and (t/2)² in G for every t, so
        // Res(E, G) of P itself vanishes identically. With P/(x − t/2) =
        // (x² + t)(x − t/2): E has roots t (the pair ±i√t), ±i√t·t/2, i.e.
        // E = (s − t)(s² + t³/4); G has roots 1/4 and t²/4; the product
        // of E over G's roots is (1/4 − t)(1/16 + t³/4)(t²/4 − t)(t⁴/16 +
        // t³/4), square-free part ∝ (4t − 1)(4t³ + 1) t (t − 4)(t + 4).
        // (x² + t)(x² − t x + t²/4) = x⁴ − t x³ + (t + t²/4) x² − t² x + t³/4
        let p = bipoly(&[
            &[(0, 1), (0, 1), (0, 1), (1, 4)],
            &[(0, 1), (0, 1), (-1, 1)],
            &[(0, 1), (1, 1), (1, 4)],
            &[(0, 1), (-1, 1)],
            &[(1, 1)],
        ]);
        // (x − 1/2)(x − t/2) = x² − (1/2 + t/2) x + t/4
        let target = bipoly(&[&[(0, 1), (1, 4)], &[(-1, 2), (-1, 2)], &[(1, 1)]]);
        let Crossings::Resultant(r) = crossings(&p, &target).unwrap() else { panic!("no resultant") };
        let expected = from_roots_squarefree(&[&[-1, 4], &[1, 0, 0, 4], &[0, 1], &[-4, 1], &[4, 1]]);
        assert_eq!(monic(&crate::numeric::sturm::squarefree(&r)), monic(&expected));
    }

    #[test]
    fn constant_real_roots_are_divided_out() {
        // P = (x − 1/8)(x − 1/32)(x² + t) against T = (x − 1/16)(x − 1/2):
        // the constant roots give 1/8 · 1/32 = 1/256 = (1/16)² in E and G
        // for every t, so Res(E, G) of P itself vanishes identically
        // (Catmull–Clark's outer eigenvalues do this). Without the constant
        // factor (1/8, 1/32 real): E = s − t (the pair ±i√t, |u|² = t), G =
        // (s − 1/256)(s − 1/4), Res ∝ (t − 1/256)(t − 1/4): |u| = 1/16 and
        // |u| = 1/2.
        // (x − 1/8)(x − 1/32) = x² − (5/32) x + 1/256; times (x² + t):
        // x⁴ − (5/32) x³ + (1/256 + t) x² − (5t/32) x + t/256
        let p = bipoly(&[&[(0, 1), (1, 256)], &[(0, 1), (-5, 32)], &[(1, 256), (1, 1)], &[(-5, 32)], &[(1, 1)]]);
        // (x − 1/16)(x − 1/2) = x² − (9/16) x + 1/32
        let target = bipoly(&[&[(1, 32)], &[(-9, 16)], &[(1, 1)]]);
        let Crossings::Resultant(r) = crossings(&p, &target).unwrap() else { panic!("no resultant") };
        let expected = from_roots_squarefree(&[&[-1, 256], &[-1, 4]]);
        assert_eq!(monic(&crate::numeric::sturm::squarefree(&r)), monic(&expected));
    }

    #[test]
    fn a_constant_complex_pair_is_kept() {
        // P = (x² + 1/4)(x − t): the constant pair ±i/2 has |u| = 1/2, and
        // the target T = x − t reaches it at t = ±1/2, so the constant
        // factor x² + 1/4 (non-real roots) must stay. E has roots
        // (i/2)(−i/2) = 1/4 and ±(i/2)t: E = (s − 1/4)(s² + t²/4); G =
        // s − t²; Res = E(t²) = (t² − 1/4)(t⁴ + t²/4) = (t² − 1/4) t² (t² +
        // 1/4), square-free ∝ (4t² − 1) t (4t² + 1).
        // (x² + 1/4)(x − t) = x³ − t x² + x/4 − t/4
        let p = bipoly(&[&[(0, 1), (-1, 4)], &[(1, 4)], &[(0, 1), (-1, 1)], &[(1, 1)]]);
        let target = bipoly(&[&[(0, 1), (-1, 1)], &[(1, 1)]]);
        let Crossings::Resultant(r) = crossings(&p, &target).unwrap() else { panic!("no resultant") };
        let expected = from_roots_squarefree(&[&[-1, 0, 4], &[0, 1], &[1, 0, 4]]);
        assert_eq!(monic(&crate::numeric::sturm::squarefree(&r)), monic(&expected));
    }

    #[test]
    fn a_crossing_at_a_cyclotomic_modulus_gives_the_norm() {
        // P = x² + t (the pair ±i√t, |u|² = t) against T = x − γ, γ =
        // ζ_5 + ζ_5⁴ = 2cos(2π/5) = (√5 − 1)/2: the crossing is t = γ².
        // Over Q(√5), Res ∝ t − γ²; its conjugate (γ' = ζ_5² + ζ_5³ =
        // (−1 − √5)/2) gives t − γ'², and γ² + γ'² = 3, γ²γ'² = (γγ')² = 1,
        // so the norm is ∝ t² − 3t + 1
        let p = bipoly(&[&[(0, 1), (1, 1)], &[], &[(1, 1)]]);
        let z = |k: i64| crate::numeric::Cyclotomic::root_of_unity(k, 5).unwrap();
        let gamma = z(1) + z(4);
        let target: BiPoly =
            vec![TPoly::constant(-gamma), TPoly::constant(crate::numeric::Cyclotomic::from_rational(&Rational::one()))];
        // σ_1 keeps γ, σ_2 sends it to γ' (σ_4, σ_3 repeat them)
        let conjugates = [1, 2];
        let Crossings::Resultant(r) = crossings_cyclotomic(&p, &target, &conjugates).unwrap() else {
            panic!("no resultant")
        };
        assert_eq!(monic(&crate::numeric::sturm::squarefree(&r)), monic(&from_roots_squarefree(&[&[1, -3, 1]])));
    }

    #[test]
    fn the_common_scale_is_the_least_per_power() {
        // P = x² + (t/3) x − t/72: c_1 has denominator 3 (k = 1: 3¹), c_0
        // denominator 2³·3² (k = 2: 2^⌈3/2⌉·3^⌈2/2⌉ = 4·3), so L = 12 and
        // 144·P(y/12) = y² + 4t y − 2t (the lcm 72 would also work, with
        // 72² instead of 12² in every coefficient)
        let p = vec![
            vec![Rational::zero(), Rational::new((-1).into(), 72.into())],
            vec![Rational::zero(), Rational::new(1.into(), 3.into())],
            vec![Rational::one()],
        ];
        let l = common_scale(&[&p]);
        assert_eq!(l, BigInt::from(12));
        let z = scaled(&p, &l).unwrap();
        let ints = |v: &[i64]| v.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>();
        assert_eq!(z, vec![ints(&[0, -2]), ints(&[0, 4]), ints(&[1])]);
    }

    #[test]
    fn resultant_is_the_product_over_roots() {
        // E = s − 7, G = (s − 2)(s − 3): E(2) E(3) = 20
        assert_eq!(resultant_monic(&[P - 7, 1], &[6, P - 5, 1], P), 20);
        // x² − 1 and (s − 1): 0
        assert_eq!(resultant_monic(&[P - 1, 0, 1], &[P - 1, 1], P), 0);
    }
}
