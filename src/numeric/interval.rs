//! Real intervals with outward rounding: the weight scalar of the certified
//! path (`certify`). An `Interval` [lo, hi] encloses one real number; every
//! operation returns an interval that encloses the exact result of the
//! operation on every pair of enclosed numbers.
//!
//! Rounding: f64 arithmetic rounds to nearest. The exact error of a sum is
//! recovered by TwoSum and that of a product or quotient by a fused
//! multiply-add (both exact in IEEE 754 away from overflow and underflow), so
//! a bound is moved outward by one ulp (`next_down`/`next_up`) only when the
//! rounded result is on the wrong side of the exact one. Exact results stay
//! point intervals: 3/8 + 1/8 is [1/2, 1/2], which lets the certificate see
//! that rational weights are exact. Near underflow the error terms are not
//! exact, so there the bounds are moved outward unconditionally.
//!
//! The interval lives here, beside f64 and the rationals, because it is a
//! `Weight`: every scheme's rules evaluate in it unchanged (`sdc::Scheme`
//! requires `Rules<Interval>`), so the certified matrix is assembled by the
//! same rule code as the floating-point one.

use super::cyclotomic_element::Cyclotomic;
use super::weight::{gcd, Inexact, ParamValue, Rational, Weight};
use num_bigint::BigInt;
use num_traits::ToPrimitive;
use std::ops::{Add, Div, Mul, Neg, Sub};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    pub lo: f64,
    pub hi: f64,
}

/// Below this magnitude the error terms of TwoSum and FMA may be inexact
/// (underflow): bounds are then widened without looking at them.
const TINY: f64 = 1e-290;

/// Lower and upper bounds of a rounded result `r` whose exact value is
/// `r + err` (`err` exact) or, when `sure` is false, anywhere within an ulp.
fn bounds(r: f64, err: f64, sure: bool) -> (f64, f64) {
    if !r.is_finite() || !err.is_finite() {
        return (f64::NEG_INFINITY, f64::INFINITY);
    }
    if !sure {
        return (r.next_down(), r.next_up());
    }
    if err < 0.0 {
        (r.next_down(), r)
    } else if err > 0.0 {
        (r, r.next_up())
    } else {
        (r, r)
    }
}

/// Bounds of a + b.
fn add_bounds(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    // TwoSum (Knuth): a + b = s + e exactly
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    // the error of a sum is a double even in the subnormal range
    bounds(s, e, true)
}

/// Bounds of a · b.
fn mul_bounds(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    if a == 0.0 || b == 0.0 {
        return (0.0, 0.0);
    }
    let e = a.mul_add(b, -p);
    bounds(p, e, p.abs() > TINY)
}

/// Bounds of a / b (b ≠ 0).
fn div_bounds(a: f64, b: f64) -> (f64, f64) {
    let q = a / b;
    if a == 0.0 {
        return (0.0, 0.0);
    }
    // a − q·b exactly; the exact quotient is q + rem / b
    let rem = (-q).mul_add(b, a);
    let err = if b > 0.0 { rem } else { -rem };
    bounds(q, err, q.abs() > TINY && a.abs() > TINY)
}

impl Interval {
    pub const ENTIRE: Interval = Interval { lo: f64::NEG_INFINITY, hi: f64::INFINITY };

    pub fn point(x: f64) -> Interval {
        if x.is_finite() {
            Interval { lo: x, hi: x }
        } else {
            Interval::ENTIRE
        }
    }
    /// [lo, hi]; a NaN or reversed pair gives the entire line (nothing is known).
    pub fn new(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() || lo > hi {
            Interval::ENTIRE
        } else {
            Interval { lo, hi }
        }
    }
    /// [−r, r]
    pub fn symmetric(r: f64) -> Interval {
        Interval::new(-r, r)
    }
    /// The enclosure of an exact rational: the nearest double, widened by
    /// whole ulps until exact comparison confirms lo ≤ q ≤ hi.
    pub fn rational(q: &Rational) -> Interval {
        Interval::small_rational(q).unwrap_or_else(|| Interval::rational_by_comparison(q))
    }
    /// [`Interval::rational`] by exact comparison with big integers.
    fn rational_by_comparison(q: &Rational) -> Interval {
        let f = ToPrimitive::to_f64(q).unwrap_or(f64::NAN);
        if !f.is_finite() {
            return Interval::ENTIRE;
        }
        let exact = |x: f64| Rational::from_float(x);
        if exact(f).as_ref() == Some(q) {
            return Interval::point(f);
        }
        let (mut lo, mut hi) = (f, f);
        while exact(lo).is_some_and(|l| &l > q) || lo == f {
            lo = lo.next_down();
        }
        while exact(hi).is_some_and(|h| &h < q) || hi == f {
            hi = hi.next_up();
        }
        Interval::new(lo, hi)
    }
    /// [`Interval::rational`] without big-integer arithmetic, for a fraction
    /// whose numerator and denominator are exact doubles (|·| ≤ 2^53): the
    /// scheme rules convert their parameters (TPS's e = 1/3) at every weight,
    /// and the general route's exact comparisons dominated the certificates.
    /// It returns the very interval the general route does: there f is the
    /// nearest double to q (num-rational divides exact doubles here too), the
    /// point [f, f] when q = f, else [f⁻, f⁺] one ulp either side (q lies
    /// strictly between them, so each widening loop stops after one step).
    /// q = f is decided exactly: the remainder n − f·d of a correctly rounded
    /// quotient is a double, and a fused multiply-add computes it exactly
    /// (|f| ≥ 2^−53 here, far from underflow).
    fn small_rational(q: &Rational) -> Option<Interval> {
        const EXACT: i64 = 1 << 53;
        let (n, d) = (q.numer().to_i64()?, q.denom().to_i64()?);
        if n.abs() > EXACT || d.abs() > EXACT || d == 0 {
            return None;
        }
        if n == 0 {
            return Some(Interval::point(0.0));
        }
        let (n, d) = (n as f64, d as f64);
        let f = n / d;
        let remainder = (-f).mul_add(d, n);
        Some(if remainder == 0.0 { Interval::point(f) } else { Interval::new(f.next_down(), f.next_up()) })
    }
    /// p / q for machine integers (point interval when the quotient is a double).
    pub fn ratio(p: i64, q: i64) -> Interval {
        if q == 0 {
            return Interval::ENTIRE;
        }
        const EXACT: i64 = 1 << 53;
        if p.abs() <= EXACT && q.abs() <= EXACT {
            let (lo, hi) = div_bounds(p as f64, q as f64);
            return Interval::new(lo, hi);
        }
        Interval::rational(&Rational::new(BigInt::from(p), BigInt::from(q)))
    }
    pub fn mid(&self) -> f64 {
        if self.lo == self.hi {
            self.lo
        } else {
            self.lo / 2.0 + self.hi / 2.0
        }
    }
    /// An upper bound of the distance from `mid()` to the ends.
    pub fn rad(&self) -> f64 {
        let m = self.mid();
        (m - self.lo).max(self.hi - m).next_up()
    }
    pub fn width(&self) -> f64 {
        add_bounds(self.hi, -self.lo).1
    }
    /// The largest |x| over the interval.
    pub fn mag(&self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }
    /// The smallest |x| over the interval.
    pub fn mig(&self) -> f64 {
        if self.lo <= 0.0 && self.hi >= 0.0 {
            0.0
        } else {
            self.lo.abs().min(self.hi.abs())
        }
    }
    pub fn contains(&self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }
    /// Whether the exact rational lies in the interval (decided exactly).
    pub fn contains_rational(&self, q: &Rational) -> bool {
        let lo_ok = self.lo == f64::NEG_INFINITY || Rational::from_float(self.lo).is_some_and(|l| &l <= q);
        let hi_ok = self.hi == f64::INFINITY || Rational::from_float(self.hi).is_some_and(|h| &h >= q);
        lo_ok && hi_ok
    }
    pub fn is_point(&self) -> bool {
        self.lo == self.hi
    }
    pub fn is_finite(&self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }
    /// The smallest interval holding both.
    pub fn hull(&self, other: &Interval) -> Interval {
        Interval::new(self.lo.min(other.lo), self.hi.max(other.hi))
    }
    pub fn overlaps(&self, other: &Interval) -> bool {
        self.lo <= other.hi && other.lo <= self.hi
    }
    /// x², tighter than x·x when the interval holds 0.
    pub fn square(&self) -> Interval {
        let (a, b) = (self.mig(), self.mag());
        Interval::new(mul_bounds(a, a).0, mul_bounds(b, b).1)
    }
    /// √x; the part of the interval below zero is ignored only when it is
    /// rounding noise of a non-negative quantity: a negative upper end gives
    /// the entire line.
    pub fn sqrt(&self) -> Interval {
        if self.hi < 0.0 || self.hi.is_nan() {
            return Interval::ENTIRE;
        }
        // f64::sqrt is correctly rounded: one ulp outward encloses the root
        let lo = if self.lo <= 0.0 { 0.0 } else { self.lo.sqrt().next_down().max(0.0) };
        Interval::new(lo, self.hi.sqrt().next_up())
    }
    /// An enclosure of π: the double `PI` is the nearest double below π.
    pub fn pi() -> Interval {
        Interval::new(std::f64::consts::PI, std::f64::consts::PI.next_up())
    }
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, o: Interval) -> Interval {
        Interval::new(add_bounds(self.lo, o.lo).0, add_bounds(self.hi, o.hi).1)
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, o: Interval) -> Interval {
        self + (-o)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval { lo: -self.hi, hi: -self.lo }
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        if !self.is_finite() || !o.is_finite() {
            return Interval::ENTIRE;
        }
        product_by_signs(self, o)
    }
}

/// a · b from the two corners that are extreme for the signs of a and b
/// (Moore's nine cases): one fused multiply-add per bound instead of the
/// four of the corner hull, the same bounds (each bound is the directed
/// rounding of its corner's exact product, and rounding is monotone). Only
/// when both straddle zero are all four corners needed. The certificates'
/// O(k³) products spend most of their time here.
fn product_by_signs(a: Interval, b: Interval) -> Interval {
    let lower = |x: f64, y: f64| mul_bounds(x, y).0;
    let upper = |x: f64, y: f64| mul_bounds(x, y).1;
    let (a_pos, a_neg, b_pos, b_neg) = (a.lo >= 0.0, a.hi <= 0.0, b.lo >= 0.0, b.hi <= 0.0);
    let (lo, hi) = if a_pos {
        if b_pos {
            (lower(a.lo, b.lo), upper(a.hi, b.hi))
        } else if b_neg {
            (lower(a.hi, b.lo), upper(a.lo, b.hi))
        } else {
            (lower(a.hi, b.lo), upper(a.hi, b.hi))
        }
    } else if a_neg {
        if b_pos {
            (lower(a.lo, b.hi), upper(a.hi, b.lo))
        } else if b_neg {
            (lower(a.hi, b.hi), upper(a.lo, b.lo))
        } else {
            (lower(a.lo, b.hi), upper(a.lo, b.lo))
        }
    } else if b_pos {
        (lower(a.lo, b.hi), upper(a.hi, b.hi))
    } else if b_neg {
        (lower(a.hi, b.lo), upper(a.lo, b.lo))
    } else {
        return corner_hull(a, b, mul_bounds);
    };
    Interval::new(lo, hi)
}

impl Div for Interval {
    type Output = Interval;
    fn div(self, o: Interval) -> Interval {
        // a divisor that may be zero: nothing is known about the quotient
        if !self.is_finite() || !o.is_finite() || (o.lo <= 0.0 && o.hi >= 0.0) {
            return Interval::ENTIRE;
        }
        corner_hull(self, o, div_bounds)
    }
}

/// The hull of `op` (rounded outward: each call gives a (lower, upper)
/// bracket) over the four corners of a × b: products and quotients of
/// intervals take their extremes at the endpoints.
fn corner_hull(a: Interval, b: Interval, op: fn(f64, f64) -> (f64, f64)) -> Interval {
    let corners = [op(a.lo, b.lo), op(a.lo, b.hi), op(a.hi, b.lo), op(a.hi, b.hi)];
    let lo = corners.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let hi = corners.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
    Interval::new(lo, hi)
}

/// Terms of the Taylor series of cos and sin on [0, π/4]: the 2·TERMS-th
/// power of π/4 over its factorial is below 1e-40, far under one ulp.
const TERMS: usize = 14;

/// cos x and sin x for an interval x ⊂ [0, π/4] (Taylor series; the series
/// alternate with decreasing terms there, so the first omitted term bounds
/// the remainder).
fn cos_sin_small(x: Interval) -> (Interval, Interval) {
    let x2 = x.square();
    let (mut cos, mut sin) = (Interval::point(0.0), Interval::point(0.0));
    let (mut term_c, mut term_s) = (Interval::point(1.0), x);
    for k in 0..TERMS {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        cos = cos + Interval::point(sign) * term_c;
        sin = sin + Interval::point(sign) * term_s;
        // next terms: x^(2k+2)/(2k+2)!, x^(2k+3)/(2k+3)!
        let (a, b) = ((2 * k + 1) as i64, (2 * k + 2) as i64);
        term_c = term_c * x2 / Interval::ratio(a * b, 1);
        term_s = term_s * x2 / Interval::ratio(b * (b + 1), 1);
    }
    // remainder: at most the next term in modulus
    (cos + Interval::symmetric(term_c.mag()), sin + Interval::symmetric(term_s.mag()))
}

/// Enclosures of cos(2πk/n) and sin(2πk/n). The angle is reduced exactly,
/// in integer arithmetic, to 2πp/q ∈ [0, π/4] by the symmetries of cos and
/// sin; the rational cosines (n/gcd ∈ {1, 2, 3, 4, 6}) and their sines are
/// exact or enclosed from √3/2.
pub fn cos_sin_2pi(k: i64, n: i64) -> (Interval, Interval) {
    if n <= 0 {
        return (Interval::ENTIRE, Interval::ENTIRE);
    }
    let k = k.rem_euclid(n);
    let g = gcd(k, n).max(1);
    let (k, n) = (k / g, n / g);
    // the rules ask for the same few angles at every weight (unified sqrt(3)
    // evaluates cos(2π/n) per slot): each thread keeps the enclosures it made
    thread_local! {
        static MADE: std::cell::RefCell<std::collections::HashMap<(i64, i64), (Interval, Interval)>> =
            std::cell::RefCell::new(std::collections::HashMap::new());
    }
    if let Some(known) = MADE.with(|m| m.borrow().get(&(k, n)).copied()) {
        return known;
    }
    let made = reduced_cos_sin_2pi(k, n);
    MADE.with(|m| {
        let mut m = m.borrow_mut();
        // a bound on the memory, never reached by the rules' few angles
        if m.len() >= 1 << 16 {
            m.clear();
        }
        m.insert((k, n), made);
    });
    made
}

/// [`cos_sin_2pi`] of k/n in lowest terms, 0 ≤ k < n.
fn reduced_cos_sin_2pi(k: i64, n: i64) -> (Interval, Interval) {
    // reduce r = k/n ∈ [0, 1) to [0, 1/8], tracking signs and the swap
    let (mut p, mut q) = (k as i128, n as i128);
    let (mut cos_sign, mut sin_sign, mut swap) = (1.0, 1.0, false);
    if 2 * p > q {
        // r > 1/2: cos(2πr) = cos(2π(1 − r)), sin(2πr) = −sin(2π(1 − r))
        p = q - p;
        sin_sign = -1.0;
    }
    if 4 * p > q {
        // r ∈ (1/4, 1/2]: cos = −cos(2π(1/2 − r)), sin = sin(2π(1/2 − r))
        p = q - 2 * p;
        q *= 2;
        cos_sign = -cos_sign;
    }
    if 8 * p > q {
        // r ∈ (1/8, 1/4]: cos and sin swap, at 1/4 − r
        p = q - 4 * p;
        q *= 4;
        swap = true;
    }
    let x = Interval::point(2.0) * Interval::pi() * Interval::ratio(p as i64, 1) / Interval::ratio(q as i64, 1);
    let (c, s) = if p == 0 { (Interval::point(1.0), Interval::point(0.0)) } else { cos_sin_small(x) };
    let (c, s) = if swap { (s, c) } else { (c, s) };
    let mut c = Interval::point(cos_sign) * c;
    let s = Interval::point(sin_sign) * s;
    // rational cosines exactly, so that e.g. cos(2π/6) is the point 1/2
    if let Some((a, b)) = super::weight::rational_cos_2pi(k, n) {
        c = Interval::ratio(a, b);
    }
    (c, s)
}

impl Weight for Interval {
    fn zero() -> Self {
        Interval::point(0.0)
    }
    fn one() -> Self {
        Interval::point(1.0)
    }
    fn ratio(p: i64, q: i64) -> Self {
        Interval::ratio(p, q)
    }
    fn cos_2pi(k: i64, n: i64) -> Result<Self, Inexact> {
        if n <= 0 {
            return Err(Inexact);
        }
        Ok(cos_sin_2pi(k, n).0)
    }
    fn sqrt(&self) -> Result<Self, Inexact> {
        if self.hi < 0.0 {
            return Err(Inexact);
        }
        Ok(Interval::sqrt(self))
    }
    /// Only a parameter given exactly (a fraction or decimal) has an
    /// enclosure; a float-only value cannot be certified.
    fn param(p: &ParamValue) -> Result<Self, Inexact> {
        p.exact.as_ref().map(Interval::rational).ok_or(Inexact)
    }
    fn to_f64(&self) -> f64 {
        self.mid()
    }
    fn is_zero(&self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }
    /// The enclosure of a real element Σ c_i ζ_N^i of a cyclotomic field:
    /// Σ c_i cos(2πi/N), each coefficient and cosine enclosed. Realness is
    /// decided exactly; a non-real (or undefined) element has no enclosure.
    fn from_cyclotomic(c: &Cyclotomic) -> Result<Self, Inexact> {
        if !c.is_real() {
            return Err(Inexact);
        }
        let n = c.order().ok_or(Inexact)? as i64;
        Ok(c.coefficients()
            .fold(Interval::point(0.0), |s, (i, q)| s + Interval::rational(&q) * cos_sin_2pi(i as i64, n).0))
    }
}

impl Interval {
    /// Whether the exact rational q could be the enclosed number and the
    /// enclosure is exactly q (a point interval equal to q).
    pub fn is_exactly(&self, q: &Rational) -> bool {
        self.is_point() && Rational::from_float(self.lo).as_ref() == Some(q)
    }
    /// Whether 0 is excluded (the sign is decided).
    pub fn sign_decided(&self) -> bool {
        self.lo > 0.0 || self.hi < 0.0
    }
    /// The sign every enclosed number has: 1 or −1, 0 when 0 is not
    /// excluded (undecided).
    pub fn decided_sign(&self) -> i8 {
        if self.lo > 0.0 {
            1
        } else if self.hi < 0.0 {
            -1
        } else {
            0
        }
    }
    /// The exact value when the interval is a point.
    pub fn exact_value(&self) -> Option<Rational> {
        if self.is_point() {
            Rational::from_float(self.lo)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, r: i64) -> Rational {
        Rational::new(BigInt::from(p), BigInt::from(r))
    }

    #[test]
    fn small_fractions_get_the_enclosure_of_the_exact_comparison() {
        let mut fractions = vec![(1i64 << 53, 3i64), (-(1i64 << 53), (1i64 << 53) - 1), (1, 1i64 << 52)];
        for p in -40..=40 {
            for r in 1..=40 {
                fractions.push((p, r));
                fractions.push((p * 1_000_003, r * 999_983));
            }
        }
        for (p, r) in fractions {
            let x = q(p, r);
            let small = Interval::small_rational(&x).expect("machine-sized fraction");
            assert_eq!(small, Interval::rational_by_comparison(&x), "{p}/{r}");
        }
    }

    /// The product by sign cases gives the corner hull's bounds for every
    /// sign pattern (positive, negative, straddling, touching zero, points),
    /// and both bounds enclose every exact corner product (compared as
    /// rationals, independently of the float arithmetic).
    #[test]
    fn products_by_signs_are_the_corner_hull() {
        let ends = [-2.5, -1.0 / 3.0, -0.0, 0.0, 0.1, 1.0 / 7.0, 3.0, 1e-200, -7e150];
        let mut intervals = Vec::new();
        for &x in &ends {
            for &y in &ends {
                if x <= y {
                    intervals.push(Interval::new(x, y));
                }
            }
        }
        let exact = |x: f64| Rational::from_float(x).expect("finite");
        for &a in &intervals {
            for &b in &intervals {
                let by_signs = a * b;
                // below TINY a corner's bounds are widened blindly, so a
                // corner that is not extreme may widen the hull by an ulp
                let underflows = [a.lo, a.hi].iter().any(|x| {
                    [b.lo, b.hi]
                        .iter()
                        .any(|y| (x * y).abs() <= TINY && x * y != 0.0 || (*x != 0.0 && *y != 0.0 && x * y == 0.0))
                });
                if !underflows {
                    assert_eq!(by_signs, corner_hull(a, b, mul_bounds), "{a:?} · {b:?}");
                }
                for x in [a.lo, a.hi] {
                    for y in [b.lo, b.hi] {
                        let p = exact(x) * exact(y);
                        assert!(exact(by_signs.lo) <= p && p <= exact(by_signs.hi), "{a:?} · {b:?} misses {x}·{y}");
                    }
                }
            }
        }
    }

    #[test]
    fn thirds_and_sevenths_are_enclosed_not_equalled() {
        let third = Interval::ratio(1, 3);
        assert!(third.contains_rational(&q(1, 3)));
        assert!(!third.is_point());
        // 1/3 + 1/3 + 1/3 encloses 1, and so does 3 · (1/3)
        let sum = third + third + third;
        assert!(sum.contains_rational(&q(1, 1)));
        assert!((Interval::point(3.0) * third).contains_rational(&q(1, 1)));
        // 1/7 − 1/7 encloses 0 and is tiny
        let s = Interval::ratio(1, 7);
        let d = s - s;
        assert!(d.contains(0.0) && d.width() < 1e-16);
        assert!(Interval::rational(&q(22, 7)).contains_rational(&q(22, 7)));
        assert!(!Interval::rational(&q(22, 7)).contains_rational(&q(3_141_592_653, 1_000_000_000)));
    }

    #[test]
    fn exact_operations_stay_points() {
        let a = Interval::ratio(3, 8) + Interval::ratio(1, 8);
        assert!(a.is_exactly(&q(1, 2)));
        assert!((Interval::ratio(1, 16) * Interval::point(6.0)).is_exactly(&q(3, 8)));
        assert!((Interval::point(1.0) / Interval::point(4.0)).is_exactly(&q(1, 4)));
    }

    #[test]
    fn division_by_an_interval_holding_zero_knows_nothing() {
        let z = Interval::new(-1e-20, 1e-20);
        assert_eq!(Interval::point(1.0) / z, Interval::ENTIRE);
    }

    #[test]
    fn square_roots_enclose_known_roots() {
        let r2 = Interval::point(2.0).sqrt();
        // r2² ∋ 2, and r2 holds √2 = 1.41421356237309504..., which lies
        // between the double SQRT_2 (above it) and the double below that
        assert!(r2.square().contains(2.0));
        let s2 = std::f64::consts::SQRT_2;
        assert!(r2.lo < s2 && r2.hi > s2.next_down());
        assert!(Interval::ratio(1, 4).sqrt().contains(0.5));
    }

    #[test]
    fn pi_is_enclosed() {
        let pi = Interval::pi();
        // π = 3.14159265358979323846...: 355/113 is above it, 333/106 below
        assert!(pi.lo < pi.hi);
        assert!(pi.hi < 355.0 / 113.0 && pi.lo > 333.0 / 106.0);
    }

    #[test]
    fn cosines_contain_closed_forms() {
        // cos(2π/5) = (√5 − 1)/4, cos(4π/5) = −(√5 + 1)/4
        let s5 = Interval::point(5.0).sqrt();
        let c1 = (s5 - Interval::point(1.0)) / Interval::point(4.0);
        let c2 = -(s5 + Interval::point(1.0)) / Interval::point(4.0);
        assert!(cos_sin_2pi(1, 5).0.overlaps(&c1));
        assert!(cos_sin_2pi(2, 5).0.overlaps(&c2));
        assert!(cos_sin_2pi(3, 5).0.overlaps(&c2));
        assert!(cos_sin_2pi(1, 5).0.width() < 1e-14);
        // cos(2π/8) = √2/2, sin(2π/12) = 1/2, cos(2π/12) = √3/2
        let half_r2 = Interval::point(2.0).sqrt() / Interval::point(2.0);
        assert!(cos_sin_2pi(1, 8).0.overlaps(&half_r2));
        assert!(cos_sin_2pi(1, 8).1.overlaps(&half_r2));
        assert!(cos_sin_2pi(1, 12).1.contains(0.5));
        assert!(cos_sin_2pi(1, 12).0.overlaps(&(Interval::point(3.0).sqrt() / Interval::point(2.0))));
        // rational cosines are exact
        assert!(cos_sin_2pi(1, 6).0.is_exactly(&q(1, 2)));
        assert!(cos_sin_2pi(2, 3).0.is_exactly(&q(-1, 2)));
        assert!(cos_sin_2pi(1, 4).0.is_exactly(&q(0, 1)));
        assert!(cos_sin_2pi(3, 4).1.contains(-1.0));
    }

    #[test]
    fn cyclotomic_elements_are_enclosed() {
        // cos(2π/5) = (√5 − 1)/4 from its exact element; Loop's β at n = 7
        let c = Cyclotomic::cos_2pi(1, 5).unwrap();
        let enclosed = Interval::from_cyclotomic(&c).unwrap();
        let s5 = Interval::point(5.0).sqrt();
        assert!(enclosed.overlaps(&((s5 - Interval::point(1.0)) / Interval::point(4.0))));
        assert!(enclosed.width() < 1e-14);
        let beta = |x: f64| (5.0 / 8.0 - (3.0 / 8.0 + x / 4.0).powi(2)) / 7.0;
        let t = Cyclotomic::ratio(3, 8) + Cyclotomic::cos_2pi(1, 7).unwrap() * Cyclotomic::ratio(1, 4);
        let b = (Cyclotomic::ratio(5, 8) - t.clone() * t) / Cyclotomic::int(7);
        let e = Interval::from_cyclotomic(&b).unwrap();
        assert!((e.mid() - beta((2.0 * std::f64::consts::PI / 7.0).cos())).abs() < 1e-15 && e.width() < 1e-15);
        // rationals stay points; non-real and undefined elements have no enclosure
        assert!(Interval::from_cyclotomic(&Cyclotomic::ratio(3, 8)).unwrap().is_exactly(&q(3, 8)));
        assert!(Interval::from_cyclotomic(&Cyclotomic::root_of_unity(1, 5).unwrap()).is_err());
        assert!(Interval::from_cyclotomic(&(c / Cyclotomic::zero())).is_err());
    }

    #[test]
    fn cosine_identities_hold_in_enclosure() {
        for n in [5, 7, 9, 11, 13, 50, 97] {
            for k in 0..n {
                let (c, s) = cos_sin_2pi(k, n);
                // cos² + sin² = 1
                assert!((c.square() + s.square()).contains(1.0), "k={k} n={n}");
                // cos(2·θ) = 2cos²θ − 1
                let c2 = cos_sin_2pi(2 * k, n).0;
                assert!((Interval::point(2.0) * c.square() - Interval::point(1.0)).overlaps(&c2), "k={k} n={n}");
                assert!(c.width() < 1e-14 && s.width() < 1e-14);
            }
            // Σ_k cos(2πk/n) = 0 for n ≥ 2
            let sum = (0..n).fold(Interval::point(0.0), |a, k| a + cos_sin_2pi(k, n).0);
            assert!(sum.contains(0.0));
        }
        // cos(2π/7) is the root of 8x³ + 4x² − 4x − 1 in (0.6, 0.7)
        let c = cos_sin_2pi(1, 7).0;
        let p = |x: Interval| {
            Interval::point(8.0) * x * x * x + Interval::point(4.0) * x * x
                - Interval::point(4.0) * x
                - Interval::point(1.0)
        };
        assert!(p(c).contains(0.0));
        assert!(p(Interval::point(c.lo - 1e-12)).hi < 0.0 && p(Interval::point(c.hi + 1e-12)).lo > 0.0);
    }
}
