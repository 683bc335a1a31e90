//! Real roots of polynomials over Q, exactly: square-free parts, Sturm
//! sequences, isolation of every real root in a closed interval by
//! bisection on Sturm counts, refinement, and real algebraic numbers (a
//! square-free integer polynomial with a rational isolating interval, or a
//! rational) compared exactly. The exact sweep (`sweep::exact`) writes its
//! interval endpoints as these numbers.

use super::exact::Poly;
use super::weight::Rational;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// The polynomial scaled by a positive rational to integer coefficients
/// without common factor (the same roots and the same signs everywhere).
pub fn primitive(p: &Poly) -> Poly {
    let p = trimmed(p);
    // integer coefficients (the exact sweep's polynomials, mostly already
    // primitive): no lcm and no rational products, whose normalising gcds
    // on thousand-bit numbers were a tenth of a sweep
    let ints: Vec<BigInt> = if p.coeffs.iter().all(|c| c.is_integer()) {
        p.coeffs.iter().map(|c| c.numer().clone()).collect()
    } else {
        let l = p.coeffs.iter().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
        p.coeffs.iter().map(|c| (c * Rational::from_integer(l.clone())).to_integer()).collect()
    };
    // the content, with its sign from the leading coefficient's scaling
    // unchanged (a gcd is nonnegative); 1 ends the search
    let g = super::content::content(&ints);
    if g.is_zero() {
        return p;
    }
    if g.is_one() {
        return Poly { coeffs: ints.into_iter().map(Rational::from_integer).collect() };
    }
    Poly { coeffs: ints.into_iter().map(|c| Rational::from_integer(c / &g)).collect() }
}

fn trimmed(p: &Poly) -> Poly {
    let mut c = p.coeffs.clone();
    while c.len() > 1 && c.last().is_some_and(|x| x.is_zero()) {
        c.pop();
    }
    if c.is_empty() {
        c.push(Rational::zero());
    }
    Poly { coeffs: c }
}

/// Integer coefficients of a primitive polynomial (lowest first).
pub fn integer_coefficients(p: &Poly) -> Vec<BigInt> {
    primitive(p).coeffs.iter().map(|c| c.to_integer()).collect()
}

/// p / gcd(p, p′): the same roots, each simple (primitive).
pub fn squarefree(p: &Poly) -> Poly {
    let p = trimmed(p);
    if p.degree() == 0 {
        return p;
    }
    let g = p.gcd(&p.derivative());
    if g.degree() == 0 {
        return primitive(&p);
    }
    // p / g exactly in integers (g divides p; rational division spent its
    // time normalising thousand-digit fractions)
    let (f, d) = (integer_coefficients(&p), integer_coefficients(&g));
    match super::modular::exact_quotient(&f, &d) {
        Some(q) => primitive(&Poly { coeffs: q.into_iter().map(Rational::from_integer).collect() }),
        // not reached (the modular gcd is accepted only when it divides
        // exactly); the rational division stays correct either way
        None => primitive(&p.div_rem(&g).0),
    }
}

/// The Sturm sequence p, p′, −rem(p, p′), ... (each scaled by a positive
/// rational, which changes no sign).
pub fn sturm_chain(p: &Poly) -> Vec<Poly> {
    let p = primitive(p);
    let mut chain = vec![p.clone()];
    if p.degree() == 0 {
        return chain;
    }
    let mut b = primitive(&p.derivative());
    let mut a = p;
    while !b.is_zero() {
        chain.push(b.clone());
        let r = a.div_rem(&b).1;
        if r.is_zero() {
            break;
        }
        let r = primitive(&r.scale(&-Rational::one()));
        a = b;
        b = r;
    }
    chain
}

fn sign_changes(chain: &[Poly], x: &Rational) -> usize {
    let mut last = 0i8;
    let mut changes = 0;
    for p in chain {
        let s = p.sign_at(x);
        if s != 0 {
            if last != 0 && s != last {
                changes += 1;
            }
            last = s;
        }
    }
    changes
}

/// Distinct real roots of the chain's polynomial in (a, b].
pub fn count_roots(chain: &[Poly], a: &Rational, b: &Rational) -> usize {
    sign_changes(chain, a).saturating_sub(sign_changes(chain, b))
}

/// A real root: exactly a rational, or the one root of a square-free
/// primitive integer polynomial in the open interval (lo, hi).
#[derive(Clone, Debug)]
pub struct RealRoot {
    pub poly: Poly,
    pub lo: Rational,
    pub hi: Rational,
    /// the root itself when it is known to be this rational
    pub rational: Option<Rational>,
}

impl RealRoot {
    pub fn exact(q: Rational) -> RealRoot {
        let poly = primitive(&Poly { coeffs: vec![-q.clone(), Rational::one()] });
        RealRoot { poly, lo: q.clone(), hi: q.clone(), rational: Some(q) }
    }
    /// Midpoint of the isolating interval (the value for a rational).
    pub fn mid(&self) -> Rational {
        match &self.rational {
            Some(q) => q.clone(),
            None => (&self.lo + &self.hi) / Rational::from_integer(2.into()),
        }
    }
    pub fn to_f64(&self) -> f64 {
        super::weight::Weight::to_f64(&self.mid())
    }
    /// Halve the isolating interval (no-op for a rational).
    pub fn bisect(&mut self) {
        if self.rational.is_some() {
            return;
        }
        let m = self.mid();
        let v = self.poly.sign_at(&m);
        if v == 0 {
            *self = RealRoot { rational: Some(m.clone()), lo: m.clone(), hi: m, poly: self.poly.clone() };
            return;
        }
        // the root is where the sign changes; an end that is itself a
        // (simple) root of the polynomial — a range end — has the sign of
        // the derivative just inside it
        let s_lo = match self.poly.sign_at(&self.lo) {
            0 => self.poly.derivative().sign_at(&self.lo),
            s => s,
        };
        if v == s_lo {
            self.lo = m;
        } else {
            self.hi = m;
        }
    }
    /// Bisect until the interval is narrower than `width`: the same steps
    /// as repeated [`RealRoot::bisect`], with one evaluation each. The sign
    /// just inside lo (bisect's s_lo) is the sign on the whole of (lo, root),
    /// so it does not change when lo moves towards the root: found once.
    pub fn refine(&mut self, width: &Rational) {
        if self.rational.is_some() || &(&self.hi - &self.lo) < width {
            return;
        }
        let s_lo = match self.poly.sign_at(&self.lo) {
            0 => self.poly.derivative().sign_at(&self.lo),
            s => s,
        };
        let two = Rational::from_integer(2.into());
        while &(&self.hi - &self.lo) >= width {
            let m = (&self.lo + &self.hi) / &two;
            let v = self.poly.sign_at(&m);
            if v == 0 {
                *self = RealRoot { rational: Some(m.clone()), lo: m.clone(), hi: m, poly: self.poly.clone() };
                return;
            }
            if v == s_lo {
                self.lo = m;
            } else {
                self.hi = m;
            }
        }
    }
    /// Try the small-denominator rationals near the root: a rational root
    /// of the polynomial inside the interval is the root.
    pub fn recognise_rational(&mut self) {
        if self.rational.is_some() {
            return;
        }
        self.refine(&Rational::new(1.into(), BigInt::from(10u64).pow(30)));
        for c in convergents(&self.mid(), 40) {
            if c > self.lo && c < self.hi && self.poly.sign_at(&c) == 0 {
                self.rational = Some(c.clone());
                self.lo = c.clone();
                self.hi = c;
                return;
            }
        }
    }
}

/// The continued-fraction convergents of x (at most `max`).
pub fn convergents(x: &Rational, max: usize) -> Vec<Rational> {
    let mut out = Vec::new();
    let (mut h0, mut h1) = (BigInt::zero(), BigInt::one());
    let (mut k0, mut k1) = (BigInt::one(), BigInt::zero());
    let mut r = x.clone();
    for _ in 0..max {
        let a = r.floor().to_integer();
        let h = &a * &h1 + &h0;
        let k = &a * &k1 + &k0;
        out.push(Rational::new(h.clone(), k.clone()));
        h0 = std::mem::replace(&mut h1, h);
        k0 = std::mem::replace(&mut k1, k);
        let f = &r - Rational::from_integer(a);
        if f.is_zero() {
            break;
        }
        r = Rational::one() / f;
    }
    out
}

/// Every real root of `p` (not the zero polynomial) in the closed interval
/// [lo, hi], in increasing order: rational roots found exactly, the others
/// each in an open interval (a, b) with rational ends that are not roots.
///
/// Descartes' rule of signs with bisection (Collins–Akritas; the
/// Vincent–Collins–Akritas method in the form of Krandick's bisection),
/// in integer arithmetic: the square-free part is mapped to [0, 1]
/// (x = lo + (hi − lo)·y, denominators cleared), and an interval of y is
/// split at its midpoint until the sign variations of
/// (1 + y)^d q(1/(1 + y)) — the number of roots of q in (0, 1) or exceeding
/// it by an even number — are 0 or 1 (exactly 1 root then). Each half is
/// again a polynomial on [0, 1]: 2^d q(y/2) and its Taylor shift by 1, so
/// no rational is normalised on the way. Sturm sequences (`sturm_chain`)
/// decide the same counts but their coefficients grow with the degree
/// squared: at degree 84 they took minutes.
pub fn isolate(p: &Poly, lo: &Rational, hi: &Rational) -> Vec<RealRoot> {
    let sq = squarefree(p);
    let mut out = Vec::new();
    if sq.degree() == 0 || lo > hi {
        return out;
    }
    let exact = |x: &Rational| RealRoot { poly: sq.clone(), lo: x.clone(), hi: x.clone(), rational: Some(x.clone()) };
    for end in [lo, hi] {
        if sq.sign_at(end) == 0 && out.iter().all(|r: &RealRoot| r.rational.as_ref() != Some(end)) {
            out.push(exact(end));
        }
    }
    if lo == hi {
        return out;
    }
    let width = hi - lo;
    // y in [0, 1] ↦ lo + width·y; the dyadic interval [a/2^k, (a+1)/2^k]
    let at = |a: &BigInt, k: u32| lo + &width * Rational::new(a.clone(), BigInt::one() << k);
    let mut stack: Vec<(Vec<BigInt>, BigInt, u32)> = vec![(affine_image(&sq, lo, &width), BigInt::zero(), 0)];
    while let Some((mut q, a, k)) = stack.pop() {
        // a root at the interval's left end was recorded already (a range
        // end or a midpoint): divide it out (it is simple)
        while q.first().is_some_and(Zero::is_zero) {
            q.remove(0);
        }
        if q.len() <= 1 {
            continue;
        }
        match descartes_bound(&q) {
            0 => continue,
            1 => {
                out.push(RealRoot { poly: sq.clone(), lo: at(&a, k), hi: at(&(&a + 1), k), rational: None });
                continue;
            }
            _ => {}
        }
        let left = remove_power_of_two(half_scaled(&q));
        let mut right = left.clone();
        taylor_shift_one(&mut right);
        let (a2, k2) = (&a * 2, k + 1);
        if right[0].is_zero() {
            out.push(exact(&at(&(&a2 + 1), k2)));
        }
        stack.push((right, &a2 + 1, k2));
        stack.push((left, a2, k2));
    }
    // an interval next to a root at a range end: bisect until neither end
    // is a root (the one root inside is apart from both ends)
    for r in out.iter_mut() {
        while r.rational.is_none() && (sq.sign_at(&r.lo) == 0 || sq.sign_at(&r.hi) == 0) {
            r.bisect();
        }
    }
    out.sort_by(|a, b| a.mid().cmp(&b.mid()));
    out
}

/// Integer coefficients (primitive) of p(lo + w·y).
fn affine_image(p: &Poly, lo: &Rational, w: &Rational) -> Vec<BigInt> {
    // lo = A/D, w = B/D: D^d p((A + B y)/D) = Σ s_k (A + B y)^k D^(d−k) by
    // Horner (R ← R·(A + B y) + s_k D^(d−k)) with p's integer multiple s
    let s = integer_coefficients(p);
    let d = s.len() - 1;
    let den = lo.denom().lcm(w.denom());
    let a = (lo * Rational::from_integer(den.clone())).to_integer();
    let b = (w * Rational::from_integer(den.clone())).to_integer();
    let mut r: Vec<BigInt> = vec![s[d].clone()];
    let mut dpow = BigInt::one();
    for k in (0..d).rev() {
        dpow *= &den;
        let mut next = vec![BigInt::zero(); r.len() + 1];
        for (i, c) in r.iter().enumerate() {
            next[i] += c * &a;
            next[i + 1] += c * &b;
        }
        next[0] += &s[k] * &dpow;
        r = next;
    }
    super::modular::primitive_part(&r)
}

/// 2^d q(y/2): the left half of [0, 1] as [0, 1].
fn half_scaled(q: &[BigInt]) -> Vec<BigInt> {
    let d = q.len() - 1;
    q.iter().enumerate().map(|(k, c)| c << (d - k)).collect()
}

/// Divide by the largest power of two dividing every coefficient (keeps
/// the numbers small; the roots are the same).
fn remove_power_of_two(mut q: Vec<BigInt>) -> Vec<BigInt> {
    let z = q.iter().filter_map(|c| c.trailing_zeros()).min().unwrap_or(0);
    if z > 0 {
        for c in q.iter_mut() {
            *c = &*c >> z;
        }
    }
    q
}

/// q(y) ← q(y + 1), in place (Horner's Taylor shift, O(d²) additions).
fn taylor_shift_one(q: &mut [BigInt]) {
    let d = q.len() - 1;
    for i in 0..d {
        for j in (i..d).rev() {
            let next = q[j + 1].clone();
            q[j] += next;
        }
    }
}

/// Sign variations of (1 + y)^d q(1/(1 + y)): at least the number of roots
/// of q in (0, 1), and of the same parity (Descartes); 0 or 1 is exact.
fn descartes_bound(q: &[BigInt]) -> usize {
    let mut t: Vec<BigInt> = q.iter().rev().cloned().collect();
    taylor_shift_one(&mut t);
    let mut last = 0i8;
    let mut changes = 0;
    for c in &t {
        let s = if c.is_positive() {
            1
        } else if c.is_negative() {
            -1
        } else {
            0
        };
        if s != 0 {
            if last != 0 && s != last {
                changes += 1;
                if changes > 1 {
                    return changes;
                }
            }
            last = s;
        }
    }
    changes
}

/// Distinct real roots of the square-free polynomial g strictly between lo
/// and hi.
fn roots_strictly_between(g: &Poly, lo: &Rational, hi: &Rational) -> usize {
    isolate(g, lo, hi).iter().filter(|r| r.rational.as_ref().is_none_or(|x| x != lo && x != hi)).count()
}

/// Whether two real roots are the same number (exact: by the common factor
/// of their polynomials having a root where both intervals meet, after
/// refining them until they are disjoint or the factor decides).
pub fn same_root(a: &mut RealRoot, b: &mut RealRoot) -> bool {
    loop {
        match (&a.rational, &b.rational) {
            (Some(x), Some(y)) => return x == y,
            (Some(x), None) => return x > &b.lo && x < &b.hi && b.poly.sign_at(x) == 0,
            (None, Some(y)) => return y > &a.lo && y < &a.hi && a.poly.sign_at(y) == 0,
            _ => {}
        }
        if a.hi <= b.lo || b.hi <= a.lo {
            return false;
        }
        let g = a.poly.gcd(&b.poly);
        if g.degree() == 0 {
            // no common root at all: refine until apart
            a.bisect();
            b.bisect();
            continue;
        }
        let lo = std::cmp::max(a.lo.clone(), b.lo.clone());
        let hi = std::cmp::min(a.hi.clone(), b.hi.clone());
        // a common root in the overlap, strictly inside both intervals
        let inside = roots_strictly_between(&g, &lo, &hi);
        if inside > 0 {
            // both intervals hold exactly one root of their polynomial, and
            // the common factor has one in the overlap: it is that root
            return true;
        }
        a.bisect();
        b.bisect();
    }
}

/// The rational with the smallest denominator strictly between a < b.
pub fn simplest_between(a: &Rational, b: &Rational) -> Rational {
    // Stern–Brocot descent on the continued fractions
    let fl = a.floor();
    if &(fl.clone() + Rational::one()) < b {
        let c = fl + Rational::one();
        if &c > a {
            return c;
        }
    }
    if &a.floor() < a && &(a.floor() + Rational::one()) < b {
        return a.floor() + Rational::one();
    }
    let f = a.floor();
    if &f == a {
        // a integer, b < a + 1: search in (0, b − a)
        let (x, y) = (Rational::zero(), b - a);
        return f + simplest_between_unit(&x, &y);
    }
    f.clone() + simplest_between_unit(&(a - &f), &(b - &f))
}

/// The simplest rational in (a, b) with 0 ≤ a < b ≤ 1.
fn simplest_between_unit(a: &Rational, b: &Rational) -> Rational {
    if a.is_zero() {
        // 1/k with 1/k < b
        let k = (Rational::one() / b).floor().to_integer() + BigInt::one();
        return Rational::new(BigInt::one(), k);
    }
    // 1/x for x in (1/b, 1/a)
    let (lo, hi) = (Rational::one() / b, Rational::one() / a);
    Rational::one() / simplest_between(&lo, &hi)
}

/// The simplest rational in each open gap between consecutive fences
/// (isolated real numbers in increasing order, pairwise distinct): each
/// pair's isolating intervals are bisected until they are disjoint, so the
/// fences come back refined and `fences[k].hi < result[k] < fences[k + 1].lo`.
pub fn points_between(fences: &mut [RealRoot]) -> Vec<Rational> {
    let mut points = Vec::with_capacity(fences.len().saturating_sub(1));
    for k in 0..fences.len().saturating_sub(1) {
        let (left, right) = fences.split_at_mut(k + 1);
        let (a, b) = (&mut left[k], &mut right[0]);
        while a.hi >= b.lo {
            a.bisect();
            b.bisect();
        }
        points.push(simplest_between(&a.hi, &b.lo));
    }
    points
}

/// Cauchy's bound: every root of p has modulus < the bound.
pub fn root_bound(p: &Poly) -> Rational {
    let d = p.degree();
    let lead = p.coeffs[d].abs();
    p.coeffs.iter().map(|x| x.abs() / &lead).fold(Rational::zero(), |a, b| a.max(b)) + Rational::one()
}

/// The real roots of p, increasing, isolated.
pub fn real_roots(p: &Poly) -> Vec<RealRoot> {
    if p.degree() == 0 {
        return Vec::new();
    }
    let b = root_bound(p);
    isolate(p, &-b.clone(), &b)
}

/// a < b (Some(true)), a > b (Some(false)) or a = b (None), exactly.
pub fn compare(a: &mut RealRoot, b: &mut RealRoot) -> Option<bool> {
    if same_root(a, b) {
        return None;
    }
    loop {
        if a.hi < b.lo {
            return Some(true);
        }
        if b.hi < a.lo {
            return Some(false);
        }
        a.bisect();
        b.bisect();
    }
}

/// −r for a real root r.
pub fn negated(r: &RealRoot) -> RealRoot {
    let coeffs = r.poly.coeffs.iter().enumerate().map(|(k, c)| if k % 2 == 1 { -c.clone() } else { c.clone() });
    RealRoot {
        poly: primitive(&Poly { coeffs: coeffs.collect() }),
        lo: -r.hi.clone(),
        hi: -r.lo.clone(),
        rational: r.rational.as_ref().map(|x| -x.clone()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::ToPrimitive;

    fn q(p: i64, d: i64) -> Rational {
        Rational::new(p.into(), d.into())
    }
    fn poly(c: &[i64]) -> Poly {
        Poly { coeffs: c.iter().map(|&x| q(x, 1)).collect() }
    }

    #[test]
    fn isolates_square_roots_and_rationals() {
        // x² − 2 on [−2, 2]: two roots, ∓√2
        let mut r = isolate(&poly(&[-2, 0, 1]), &q(-2, 1), &q(2, 1));
        assert_eq!(r.len(), 2);
        for x in r.iter_mut() {
            x.refine(&q(1, 1000));
        }
        let s = std::f64::consts::SQRT_2;
        assert!((r[0].to_f64() + s).abs() < 1e-3 && (r[1].to_f64() - s).abs() < 1e-3);
        // 2x − 1: the rational root 1/2, recognised
        let r = isolate(&poly(&[-1, 2]), &q(0, 1), &q(1, 1));
        let mut r0 = r[0].clone();
        r0.recognise_rational();
        assert_eq!(r0.rational, Some(q(1, 2)));
    }

    #[test]
    fn descartes_isolation_agrees_with_sturm_counts() {
        // (x − 1/3)(x − 1)(x² − 2)(5x² − 1)(x² + 1)·(x − 1): a double root,
        // rational roots (one at the range's end), irrational pairs and a
        // complex pair; roots in [−2, 1]: −√2, −1/√5, 1/3, 1/√5, 1
        let lin = |a: i64, b: i64| poly(&[-a, b]);
        let mul = |a: &Poly, b: &Poly| a.mul(b);
        let p = [lin(1, 3), lin(1, 1), poly(&[-2, 0, 1]), poly(&[-1, 0, 5]), poly(&[1, 0, 1]), lin(1, 1)]
            .iter()
            .fold(Poly::one(), |acc, f| mul(&acc, f));
        let roots = isolate(&p, &q(-2, 1), &q(1, 1));
        assert_eq!(roots.len(), 5);
        assert!(roots[2].rational.is_none() || roots[2].rational == Some(q(1, 3))); // 1/3 is no bisection point here
        assert_eq!(roots[4].rational, Some(q(1, 1)));
        let chain = sturm_chain(&squarefree(&p));
        let expect = [-std::f64::consts::SQRT_2, -(0.2f64).sqrt(), 1.0 / 3.0, (0.2f64).sqrt(), 1.0];
        for (r, e) in roots.iter().zip(expect) {
            if r.rational.is_none() {
                // exactly one root inside, by the independent Sturm count
                assert_eq!(count_roots(&chain, &r.lo, &r.hi), 1);
                assert!(r.lo.to_f64().unwrap() < e && e < r.hi.to_f64().unwrap());
            }
        }
        // roots at both range ends and one inside, next to each: x(x − 1)(3x − 1)
        let r = isolate(&mul(&mul(&lin(0, 1), &lin(1, 1)), &lin(1, 3)), &q(0, 1), &q(1, 1));
        assert_eq!(r.len(), 3);
        assert!(r[1].rational.is_none() && r[1].lo > q(0, 1) && r[1].hi < q(1, 1));
        assert_eq!(count_roots(&sturm_chain(&r[1].poly), &r[1].lo, &r[1].hi), 1);
        // a root exactly at the left end and at a bisection midpoint
        let r = isolate(&mul(&lin(0, 1), &lin(1, 2)), &q(0, 1), &q(1, 1));
        assert_eq!(r.iter().map(|r| r.rational.clone()).collect::<Vec<_>>(), vec![Some(q(0, 1)), Some(q(1, 2))]);
    }

    #[test]
    fn simplest_rationals() {
        assert_eq!(simplest_between(&q(1, 3), &q(1, 2)), q(2, 5));
        assert_eq!(simplest_between(&q(0, 1), &q(3, 1)), q(1, 1));
        assert_eq!(simplest_between(&q(-3, 2), &q(-1, 3)), q(-1, 1));
        let x = simplest_between(&q(707, 1000), &q(708, 1000));
        assert!(x > q(707, 1000) && x < q(708, 1000));
    }
}
