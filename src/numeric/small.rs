//! Exact rationals in machine integers, for the hot exact paths.
//!
//! The certificate compares the scheme's stencils with a box spline's mask
//! exactly at every regular entity of the ring's windows — tens of thousands
//! of stencils per valence, each a few dozen products of small fractions
//! (1/4, 3/8, 1/16 ...). In big rationals every product allocates and reduces
//! by a big-integer gcd, and that was most of a certified claim's time.
//! [`SmallRational`] does the same arithmetic in `i128` numerators and
//! denominators with checked operations. It never rounds: an operation that
//! would overflow (or divide by zero) makes the value *spoiled*, spoiled
//! values stay spoiled, and a caller that finds a spoiled term recomputes
//! with big rationals ([`SmallRational::to_rational`] returns `None`). So a
//! stencil computed this way is either the exact stencil or visibly not one.

use super::cyclotomic_element::Cyclotomic;
use super::weight::{rational_cos_2pi, Inexact, ParamValue, Rational, Weight};
use num_bigint::BigInt;
use num_rational::Ratio;
use num_traits::{CheckedAdd, CheckedDiv, CheckedMul, CheckedSub, ToPrimitive, Zero};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact rational in machine integers, or `None` once an operation left
/// them (see the module documentation).
#[derive(Clone, Copy, Debug)]
pub struct SmallRational(Option<Ratio<i128>>);

/// Equal values are equal; a spoiled value equals nothing, not even itself
/// (like a NaN), so an exact comparison never passes on spoiled data.
impl PartialEq for SmallRational {
    fn eq(&self, other: &Self) -> bool {
        matches!((self.0, other.0), (Some(a), Some(b)) if a == b)
    }
}

impl SmallRational {
    /// p/q, spoiled when q = 0.
    pub fn new(p: i128, q: i128) -> Self {
        if q == 0 {
            return SmallRational(None);
        }
        // the rules build their weights from small integers (1/n², 3/8 ...):
        // reduced by a 64-bit gcd, not `Ratio::new`'s 128-bit one
        if let (Ok(a), Ok(b)) = (i64::try_from(p), i64::try_from(q)) {
            if a != i64::MIN && b != i64::MIN {
                let g = gcd64(a.unsigned_abs(), b.unsigned_abs()) as i64;
                let sign = if b < 0 { -1 } else { 1 };
                return SmallRational(Some(Ratio::new_raw((sign * (a / g)) as i128, (sign * (b / g)) as i128)));
            }
        }
        SmallRational(Some(Ratio::new(p, q)))
    }

    /// The value, when it was never spoiled.
    pub fn to_rational(&self) -> Option<Rational> {
        self.0.map(|r| Rational::new(BigInt::from(*r.numer()), BigInt::from(*r.denom())))
    }

    /// A big rational as a small one, spoiled when it does not fit.
    pub fn from_rational(r: &Rational) -> Self {
        match (r.numer().to_i128(), r.denom().to_i128()) {
            (Some(p), Some(q)) => SmallRational::new(p, q),
            _ => SmallRational(None),
        }
    }

    pub fn is_spoiled(&self) -> bool {
        self.0.is_none()
    }

    fn checked(a: Self, b: Self, op: impl Fn(&Ratio<i128>, &Ratio<i128>) -> Option<Ratio<i128>>) -> Self {
        SmallRational(match (a.0, b.0) {
            (Some(x), Some(y)) => op(&x, &y),
            _ => None,
        })
    }
}

/// The four operations, each the checked one of `Ratio<i128>` (a `None`
/// spoils the value: an overflow, or a division by zero, which the big
/// rationals' division would panic on).
macro_rules! checked_operation {
    ($trait:ident, $method:ident, $checked:ident) => {
        impl $trait for SmallRational {
            type Output = Self;
            fn $method(self, b: Self) -> Self {
                Self::checked(self, b, |x, y| x.$checked(y))
            }
        }
    };
}

checked_operation!(Div, div, checked_div);

// Sums and products of fractions whose parts fit in 64 bits — nearly every
// weight a rule multiplies (1/4, 3/8, 1/n², 1/m · 1/4 ...) — in 64-bit gcds
// and 128-bit products, which cannot overflow; `Ratio<i128>`'s checked
// operations reduce by 128-bit gcds and divisions (a software routine), and
// the rule check spent most of its arithmetic there. Larger parts take the
// checked 128-bit route. Both give the reduced fraction, so the results are
// equal (the tests compare them with the big rationals).
impl Add for SmallRational {
    type Output = Self;
    fn add(self, b: Self) -> Self {
        match (self.parts64(), b.parts64()) {
            (Some(x), Some(y)) => sum64(x, y),
            _ => Self::checked(self, b, |x, y| x.checked_add(y)),
        }
    }
}

impl Sub for SmallRational {
    type Output = Self;
    fn sub(self, b: Self) -> Self {
        match (self.parts64(), b.parts64()) {
            // −c fits: c > i64::MIN, as `parts64` only gives such numerators
            (Some(x), Some((c, d))) => sum64(x, (-c, d)),
            _ => Self::checked(self, b, |x, y| x.checked_sub(y)),
        }
    }
}

impl Mul for SmallRational {
    type Output = Self;
    fn mul(self, b: Self) -> Self {
        match (self.parts64(), b.parts64()) {
            // (a/b)(c/d) with a/b and c/d reduced: cancel a with d and c with
            // b first, and the product of the rest is reduced
            (Some((a, b)), Some((c, d))) => {
                let (g1, g2) = (gcd64(a.unsigned_abs(), d as u64) as i64, gcd64(c.unsigned_abs(), b as u64) as i64);
                let (a, d, c, b) = (a / g1, d / g1, c / g2, b / g2);
                SmallRational(Some(Ratio::new_raw(a as i128 * c as i128, b as i128 * d as i128)))
            }
            _ => Self::checked(self, b, |x, y| x.checked_mul(y)),
        }
    }
}

impl SmallRational {
    /// Numerator and denominator when both fit in 64 bits (the numerator
    /// above `i64::MIN`, so that it can be negated): the fast operations'
    /// domain. A `Ratio` is kept reduced with a positive denominator.
    fn parts64(&self) -> Option<(i64, i64)> {
        let r = self.0.as_ref()?;
        let (p, q) = (i64::try_from(*r.numer()).ok()?, i64::try_from(*r.denom()).ok()?);
        (p != i64::MIN).then_some((p, q))
    }
}

/// a/b + c/d for reduced fractions with 64-bit parts (Knuth, TAOCP 4.5.1):
/// with g = gcd(b, d), t = a·(d/g) + c·(b/g) and h = gcd(t, g), the reduced
/// sum is (t/h) / ((b/g)·(d/h)). Every product is of two 64-bit numbers, and
/// |t| < 2^127, so nothing overflows 128 bits.
fn sum64((a, b): (i64, i64), (c, d): (i64, i64)) -> SmallRational {
    let g = gcd64(b as u64, d as u64) as i64;
    let t = a as i128 * (d / g) as i128 + c as i128 * (b / g) as i128;
    if t == 0 {
        return SmallRational(Some(Ratio::new_raw(0, 1)));
    }
    // gcd(t, g) = gcd(t mod g, g): one 128-bit remainder, then 64-bit
    let h = gcd64((t % g as i128).unsigned_abs() as u64, g as u64) as i128;
    SmallRational(Some(Ratio::new_raw(t / h, (b / g) as i128 * (d as i128 / h))))
}

/// gcd of two 64-bit integers, not both zero (binary: shifts and
/// subtractions, no division).
fn gcd64(mut u: u64, mut v: u64) -> u64 {
    if u == 0 {
        return v;
    }
    if v == 0 {
        return u;
    }
    let shift = (u | v).trailing_zeros();
    u >>= u.trailing_zeros();
    loop {
        v >>= v.trailing_zeros();
        if u > v {
            std::mem::swap(&mut u, &mut v);
        }
        v -= u;
        if v == 0 {
            return u << shift;
        }
    }
}

impl Neg for SmallRational {
    type Output = Self;
    fn neg(self) -> Self {
        Self::checked(SmallRational::new(0, 1), self, |x, y| x.checked_sub(y))
    }
}

impl Weight for SmallRational {
    fn zero() -> Self {
        SmallRational::new(0, 1)
    }
    fn one() -> Self {
        SmallRational::new(1, 1)
    }
    fn ratio(p: i64, q: i64) -> Self {
        SmallRational::new(p as i128, q as i128)
    }
    fn cos_2pi(k: i64, n: i64) -> Result<Self, Inexact> {
        rational_cos_2pi(k, n).map(|(p, q)| SmallRational::ratio(p, q)).ok_or(Inexact)
    }
    fn sqrt(&self) -> Result<Self, Inexact> {
        let Some(r) = self.0 else { return Ok(*self) };
        let root = |x: i128| -> Option<i128> {
            if x < 0 {
                return None;
            }
            // the float estimate is off by at most a few units at i128
            // magnitudes; the exact square decides
            let s = (x as f64).sqrt() as i128;
            (s.saturating_sub(2)..=s.saturating_add(2)).find(|&t| t >= 0 && t.checked_mul(t) == Some(x))
        };
        match (root(*r.numer()), root(*r.denom())) {
            (Some(p), Some(q)) => Ok(SmallRational::new(p, q)),
            _ => Err(Inexact),
        }
    }
    fn param(p: &ParamValue) -> Result<Self, Inexact> {
        p.exact.as_ref().map(SmallRational::from_rational).ok_or(Inexact)
    }
    fn to_f64(&self) -> f64 {
        self.0.map_or(f64::NAN, |r| *r.numer() as f64 / *r.denom() as f64)
    }
    fn is_zero(&self) -> bool {
        self.0.is_some_and(|r| r.is_zero())
    }
    fn from_cyclotomic(c: &Cyclotomic) -> Result<Self, Inexact> {
        c.to_rational().map(|r| SmallRational::from_rational(&r)).ok_or(Inexact)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_is_that_of_the_rationals() {
        let q = |p, q| SmallRational::ratio(p, q);
        assert_eq!((q(1, 4) + q(3, 8)).to_rational(), Some(Rational::ratio(5, 8)));
        assert_eq!((q(1, 4) - q(3, 8)).to_rational(), Some(Rational::ratio(-1, 8)));
        assert_eq!((q(2, 3) * q(9, 16)).to_rational(), Some(Rational::ratio(3, 8)));
        assert_eq!((q(2, 3) / q(4, 9)).to_rational(), Some(Rational::ratio(3, 2)));
        assert_eq!((-q(5, 7)).to_rational(), Some(Rational::ratio(-5, 7)));
        assert_eq!(q(9, 16).sqrt().map(|r| r.to_rational()), Ok(Some(Rational::ratio(3, 4))));
        assert_eq!(q(2, 1).sqrt(), Err(Inexact));
        assert_eq!(SmallRational::cos_2pi(1, 6).map(|r| r.to_rational()), Ok(Some(Rational::ratio(1, 2))));
        assert_eq!(SmallRational::cos_2pi(1, 5), Err(Inexact));
    }

    /// The 64-bit fast paths against the big rationals on a grid of
    /// fractions (signs, common factors, parts near 2^63, zero), and the
    /// result reduced exactly as `Ratio` keeps it.
    #[test]
    fn the_fast_paths_are_the_rational_operations() {
        let near = i64::MAX as i128;
        let parts: [i128; 12] = [0, 1, -1, 2, -3, 12, -45, 64, 360, near, -near, near - 1];
        let dens: [i128; 7] = [1, 2, 3, 16, 90, near, near - 2];
        let mut values = Vec::new();
        for &p in &parts {
            for &q in &dens {
                values.push(SmallRational::new(p, q));
            }
        }
        let exact = |x: &SmallRational| x.to_rational().unwrap();
        for x in &values {
            for y in &values {
                let (ex, ey) = (exact(x), exact(y));
                for (got, want) in [(*x + *y, &ex + &ey), (*x - *y, &ex - &ey), (*x * *y, &ex * &ey)] {
                    match got.to_rational() {
                        Some(g) => {
                            assert_eq!(g, want, "{x:?} {y:?}");
                            let r = got.0.unwrap();
                            assert!(*r.denom() > 0, "positive denominator");
                            let reduced = Ratio::new(*r.numer(), *r.denom());
                            assert_eq!((reduced.numer(), reduced.denom()), (r.numer(), r.denom()), "kept reduced");
                        }
                        // spoiled only when the exact value does not fit
                        None => assert!(SmallRational::from_rational(&want).is_spoiled(), "{x:?} {y:?}"),
                    }
                }
            }
        }
        // construction reduces and puts the sign on the numerator
        for (p, q) in [(6i128, -4i128), (-6, -4), (0, -5), (near, -near), (-near, 3 * near)] {
            let r = SmallRational::new(p, q).0.unwrap();
            assert_eq!((*r.numer(), *r.denom()), (*Ratio::new(p, q).numer(), *Ratio::new(p, q).denom()), "{p}/{q}");
        }
        assert_eq!(gcd64(0, 7), 7);
        assert_eq!(gcd64(12, 18), 6);
        assert_eq!(gcd64(1 << 40, 3 << 20), 1 << 20);
    }

    #[test]
    fn overflow_and_division_by_zero_spoil_instead_of_rounding() {
        let big = SmallRational::new(i128::MAX / 3, 1);
        assert!((big * SmallRational::int(4)).is_spoiled());
        assert!((big * SmallRational::int(4) - big).is_spoiled(), "a spoiled value stays spoiled");
        assert!((SmallRational::one() / SmallRational::zero()).is_spoiled());
        assert!(SmallRational::new(1, 0).to_rational().is_none());
        assert!(!SmallRational::new(0, 1).is_spoiled() && !(big * SmallRational::int(2)).is_spoiled());
        let spoiled = SmallRational::new(1, 0);
        assert!(spoiled != spoiled, "a spoiled value equals nothing, so no exact comparison passes on it");
        // a big rational that does not fit is spoiled, one that fits is kept
        let huge = Rational::new(BigInt::from(10).pow(40), BigInt::from(3));
        assert!(SmallRational::from_rational(&huge).is_spoiled());
        assert_eq!(SmallRational::from_rational(&Rational::ratio(-7, 12)).to_rational(), Some(Rational::ratio(-7, 12)));
    }
}
