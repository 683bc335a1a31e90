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
    let l = p.coeffs.iter().fold(BigInt::one(), |l, c| l.lcm(c.denom()));
    let ints: Vec<BigInt> = p.coeffs.iter().map(|c| (c * Rational::from_integer(l.clone())).to_integer()).collect();
    let g = ints.iter().fold(BigInt::zero(), |g, c| g.gcd(c));
    if g.is_zero() {
        return p;
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
    primitive(&p.div_rem(&g).0)
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
        let v = p.eval(x);
        let s = if v.is_positive() {
            1
        } else if v.is_negative() {
            -1
        } else {
            0
        };
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
        let v = self.poly.eval(&m);
        if v.is_zero() {
            *self = RealRoot { rational: Some(m.clone()), lo: m.clone(), hi: m, poly: self.poly.clone() };
            return;
        }
        // the root is where the sign changes; the ends are never roots
        let s_lo = self.poly.eval(&self.lo).signum();
        if v.signum() == s_lo {
            self.lo = m;
        } else {
            self.hi = m;
        }
    }
    /// Bisect until the interval is narrower than `width`.
    pub fn refine(&mut self, width: &Rational) {
        while self.rational.is_none() && &(&self.hi - &self.lo) >= width {
            self.bisect();
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
            if c > self.lo && c < self.hi && self.poly.eval(&c).is_zero() {
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
/// [lo, hi], in increasing order.
pub fn isolate(p: &Poly, lo: &Rational, hi: &Rational) -> Vec<RealRoot> {
    let sq = squarefree(p);
    if sq.degree() == 0 {
        return Vec::new();
    }
    let chain = sturm_chain(&sq);
    let mut out = Vec::new();
    if sq.eval(lo).is_zero() {
        out.push(RealRoot { poly: sq.clone(), lo: lo.clone(), hi: lo.clone(), rational: Some(lo.clone()) });
    }
    // (a, b] with its count
    let mut stack = vec![(lo.clone(), hi.clone(), count_roots(&chain, lo, hi))];
    let mut found = Vec::new();
    while let Some((a, b, k)) = stack.pop() {
        if k == 0 {
            continue;
        }
        if k == 1 {
            if sq.eval(&b).is_zero() {
                found.push(RealRoot { poly: sq.clone(), lo: b.clone(), hi: b.clone(), rational: Some(b) });
            } else {
                found.push(RealRoot { poly: sq.clone(), lo: a, hi: b, rational: None });
            }
            continue;
        }
        let m = (&a + &b) / Rational::from_integer(2.into());
        let left = count_roots(&chain, &a, &m);
        stack.push((m.clone(), b, k - left));
        stack.push((a, m, left));
    }
    // an isolating interval (a, b] with a a root found separately: make it open
    for r in found.iter_mut() {
        while r.rational.is_none() && sq.eval(&r.lo).is_zero() {
            let m = r.mid();
            if sq.eval(&m).is_zero() {
                r.lo = m.clone();
                r.hi = m.clone();
                r.rational = Some(m);
            } else if count_roots(&chain, &r.lo, &m) == 1 {
                r.hi = m;
            } else {
                r.lo = m;
            }
        }
    }
    out.extend(found);
    out.sort_by(|a, b| a.mid().cmp(&b.mid()));
    out
}

/// Whether two real roots are the same number (exact: by the common factor
/// of their polynomials having a root where both intervals meet, after
/// refining them until they are disjoint or the factor decides).
pub fn same_root(a: &mut RealRoot, b: &mut RealRoot) -> bool {
    loop {
        match (&a.rational, &b.rational) {
            (Some(x), Some(y)) => return x == y,
            (Some(x), None) => return x > &b.lo && x < &b.hi && b.poly.eval(x).is_zero(),
            (None, Some(y)) => return y > &a.lo && y < &a.hi && a.poly.eval(y).is_zero(),
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
        let chain = sturm_chain(&g);
        // a common root in the overlap, strictly inside both intervals
        let inside = count_roots(&chain, &lo, &hi) - usize::from(g.eval(&hi).is_zero());
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
    fn simplest_rationals() {
        assert_eq!(simplest_between(&q(1, 3), &q(1, 2)), q(2, 5));
        assert_eq!(simplest_between(&q(0, 1), &q(3, 1)), q(1, 1));
        assert_eq!(simplest_between(&q(-3, 2), &q(-1, 3)), q(-1, 1));
        let x = simplest_between(&q(707, 1000), &q(708, 1000));
        assert!(x > q(707, 1000) && x < q(708, 1000));
    }
}
