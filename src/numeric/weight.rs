//! The scalar type refinement rules are written over.
//!
//! Every mask is generic over `W: Weight`, so the same rule code yields f64
//! stencils for numerics and exact rational stencils whenever the weights are
//! rational (for instance valence 4 or 6, or any valence for Catmull–Clark).
//! Operations that leave the rationals (cos(2πk/n) for most n, square roots of
//! non-squares) return `Err(Inexact)` for the exact type. Two more weight
//! types serve the certificate: outward-rounded intervals
//! (`numeric::interval`) and exact elements of cyclotomic fields
//! (`numeric::cyclotomic`, where cos(2πk/n) is exact and only square roots of
//! non-squares are `Err(Inexact)`).

use super::cyclotomic_element::Cyclotomic;
use crate::error::Error;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

pub type Rational = BigRational;

/// The exact arithmetic path cannot represent this weight.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Inexact;

pub trait Weight:
    Clone
    + Debug
    + Send
    + Sync
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + 'static
{
    fn zero() -> Self;
    fn one() -> Self;
    fn ratio(p: i64, q: i64) -> Self;
    fn int(p: i64) -> Self {
        Self::ratio(p, 1)
    }
    /// cos(2πk/n)
    fn cos_2pi(k: i64, n: i64) -> Result<Self, Inexact>;
    fn sqrt(&self) -> Result<Self, Inexact>;
    fn param(p: &ParamValue) -> Result<Self, Inexact>;
    fn to_f64(&self) -> f64;
    fn is_zero(&self) -> bool;
    /// The weight of an exact element of a cyclotomic field (a scheme file's
    /// weight that is not rational); `Err(Inexact)` when this type cannot
    /// represent it (the rationals).
    fn from_cyclotomic(c: &Cyclotomic) -> Result<Self, Inexact>;
    /// Whether [`Weight::sum_all`] is cheaper than summing in turn, so that
    /// a long sum should be collected first (exact types that normalise
    /// after every addition). Sums of types that keep the default are made
    /// in turn, in the terms' order, so floats round as they always did.
    const SUMS_IN_BATCHES: bool = false;
    /// Σ terms, added in turn from zero in the terms' order (the exact
    /// types may sum at once: their sums do not depend on the order).
    fn sum_all(terms: Vec<Self>) -> Self {
        terms.into_iter().fold(Self::zero(), |a, b| a + b)
    }
}

impl Weight for f64 {
    fn zero() -> Self {
        0.0
    }
    fn one() -> Self {
        1.0
    }
    fn ratio(p: i64, q: i64) -> Self {
        p as f64 / q as f64
    }
    fn cos_2pi(k: i64, n: i64) -> Result<Self, Inexact> {
        // exact values where they exist, so that e.g. cos(2π/4) is 0, not 6e-17
        // Rules ask for the same cosine once per slot (a valence-1000 centre
        // has thousands of slots), and the rational test plus `cos` cost far
        // more than a lookup, so the last few answers are kept per thread.
        thread_local! {
            static RECENT: std::cell::RefCell<[(i64, i64, f64); 4]> =
                const { std::cell::RefCell::new([(0, 0, f64::NAN); 4]) };
        }
        if n <= 0 {
            return Ok(f64::NAN); // no such angle; callers validate n first
        }
        let k = k.rem_euclid(n);
        if let Some(c) = RECENT.with(|r| r.borrow().iter().find(|e| e.0 == k && e.1 == n).map(|e| e.2)) {
            return Ok(c);
        }
        let c = match rational_cos_2pi(k, n) {
            Some((p, q)) => p as f64 / q as f64,
            None => (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos(),
        };
        RECENT.with(|r| {
            let mut r = r.borrow_mut();
            r.rotate_right(1);
            r[0] = (k, n, c);
        });
        Ok(c)
    }
    fn sqrt(&self) -> Result<Self, Inexact> {
        Ok(f64::sqrt(*self))
    }
    fn param(p: &ParamValue) -> Result<Self, Inexact> {
        Ok(p.value)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn from_cyclotomic(c: &Cyclotomic) -> Result<Self, Inexact> {
        let (re, im) = c.to_complex();
        (re.is_finite() && im.abs() <= 1e-12 * re.abs().max(1.0)).then_some(re).ok_or(Inexact)
    }
}

impl Weight for Rational {
    fn zero() -> Self {
        <Rational as Zero>::zero()
    }
    fn one() -> Self {
        <Rational as One>::one()
    }
    fn ratio(p: i64, q: i64) -> Self {
        Rational::new(BigInt::from(p), BigInt::from(q))
    }
    fn cos_2pi(k: i64, n: i64) -> Result<Self, Inexact> {
        exact_cos_2pi(k, n).ok_or(Inexact)
    }
    fn sqrt(&self) -> Result<Self, Inexact> {
        if self.is_negative() {
            return Err(Inexact);
        }
        let (n, d) = (self.numer().sqrt(), self.denom().sqrt());
        if &(&n * &n) == self.numer() && &(&d * &d) == self.denom() {
            Ok(Rational::new(n, d))
        } else {
            Err(Inexact)
        }
    }
    fn param(p: &ParamValue) -> Result<Self, Inexact> {
        p.exact.clone().ok_or(Inexact)
    }
    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn from_cyclotomic(c: &Cyclotomic) -> Result<Self, Inexact> {
        c.to_rational().ok_or(Inexact)
    }
}

/// cos(2πk/n) as a fraction p/q when it is rational (n/gcd ∈ {1, 2, 3, 4, 6}),
/// in machine integers: the float path asks for it at every stencil weight,
/// so it must not build big rationals.
pub fn rational_cos_2pi(k: i64, n: i64) -> Option<(i64, i64)> {
    if n <= 0 {
        return None;
    }
    let k = k.rem_euclid(n);
    let g = gcd(k, n).max(1);
    match (k / g, n / g) {
        (0, 1) => Some((1, 1)),
        (_, 2) => Some((-1, 1)),
        (_, 3) => Some((-1, 2)),
        (_, 4) => Some((0, 1)),
        (_, 6) => Some((1, 2)),
        _ => None,
    }
}

/// cos(2πk/n) when it is rational (n/gcd ∈ {1, 2, 3, 4, 6}).
pub fn exact_cos_2pi(k: i64, n: i64) -> Option<Rational> {
    rational_cos_2pi(k, n).map(|(p, q)| Rational::new(BigInt::from(p), BigInt::from(q)))
}

pub fn gcd(a: i64, b: i64) -> i64 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

/// A scheme parameter as the user wrote it: its f64 value, and the exact
/// rational when the text denotes one (integers, fractions, decimals).
#[derive(Clone, Debug, PartialEq)]
pub struct ParamValue {
    pub value: f64,
    pub exact: Option<Rational>,
    pub text: String,
}

impl ParamValue {
    pub fn from_ratio(p: i64, q: i64) -> Self {
        let text = if q == 1 { format!("{p}") } else { format!("{p}/{q}") };
        ParamValue { value: p as f64 / q as f64, exact: Some(Rational::ratio(p, q)), text }
    }
    pub fn from_f64(x: f64) -> Self {
        ParamValue { value: x, exact: None, text: format!("{x}") }
    }

    /// Parse "3/8", "-1", "0.375", "1e-3". Rejects NaN, infinities and anything
    /// else with a message that names the accepted forms.
    pub fn parse(text: &str) -> Result<Self, Error> {
        let t = text.trim();
        if t.is_empty() {
            return Err(Error::Input("empty parameter value".into()));
        }
        if let Some((p, q)) = t.split_once('/') {
            let p: BigInt = p
                .trim()
                .parse()
                .map_err(|_| Error::Input(format!("'{t}' is not a number (use 3/8, 0.375 or 1e-3)")))?;
            let q: BigInt = q
                .trim()
                .parse()
                .map_err(|_| Error::Input(format!("'{t}' is not a number (use 3/8, 0.375 or 1e-3)")))?;
            if q.is_zero() {
                return Err(Error::Input(format!("'{t}' divides by zero")));
            }
            let r = Rational::new(p, q);
            // like decimals (60 digits), exact values stay small enough for the
            // exact analysis to finish
            if r.numer().bits() > MAX_FRACTION_BITS || r.denom().bits() > MAX_FRACTION_BITS {
                return Err(Error::Input(format!(
                    "'{}': numerator and denominator (reduced) of at most {MAX_FRACTION_BITS} bits (about 120 digits) are supported",
                    if t.len() > 40 { format!("{}…", &t[..t.char_indices().nth(40).map_or(t.len(), |c| c.0)]) } else { t.to_string() }
                )));
            }
            return Ok(ParamValue { value: Weight::to_f64(&r), exact: Some(r), text: t.to_string() });
        }
        let value: f64 =
            t.parse().map_err(|_| Error::Input(format!("'{t}' is not a number (use 3/8, 0.375 or 1e-3)")))?;
        if !value.is_finite() {
            return Err(Error::Input(format!("'{t}' is not a finite number")));
        }
        Ok(ParamValue { value, exact: decimal_to_rational(t), text: t.to_string() })
    }
}

/// Largest numerator or denominator of a fraction `p/q` parameter value.
pub const MAX_FRACTION_BITS: u64 = 400;

/// Exact value of a decimal literal such as "-0.375" or "1.5e-2".
fn decimal_to_rational(t: &str) -> Option<Rational> {
    let (mantissa, exp) = match t.find(['e', 'E']) {
        Some(k) => (&t[..k], t[k + 1..].parse::<i32>().ok()?),
        None => (t, 0),
    };
    let neg = mantissa.starts_with('-');
    let m = mantissa.trim_start_matches(['-', '+']);
    let (int, frac) = m.split_once('.').unwrap_or((m, ""));
    if !int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit()) || (int.is_empty() && frac.is_empty()) {
        return None;
    }
    if exp.unsigned_abs() > 60 || frac.len() > 60 {
        return None;
    }
    let digits: BigInt = format!("{int}{frac}").parse().ok()?;
    let scale = exp - frac.len() as i32;
    let ten = BigInt::from(10);
    let mut r = if scale >= 0 {
        Rational::from_integer(digits * num_traits::pow(ten, scale as usize))
    } else {
        Rational::new(digits, num_traits::pow(ten, (-scale) as usize))
    };
    if neg {
        r = -r;
    }
    Some(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_exact_forms() {
        assert_eq!(ParamValue::parse("3/8").unwrap().exact, Some(Rational::ratio(3, 8)));
        assert_eq!(ParamValue::parse("0.375").unwrap().exact, Some(Rational::ratio(3, 8)));
        assert_eq!(ParamValue::parse("-1.5e-1").unwrap().exact, Some(Rational::ratio(-3, 20)));
        assert!(ParamValue::parse("nan").is_err());
        assert!(ParamValue::parse("inf").is_err());
        assert!(ParamValue::parse("1/0").is_err());
        assert!(ParamValue::parse("abc").is_err());
    }

    #[test]
    fn rational_cosines() {
        assert_eq!(exact_cos_2pi(1, 6), Some(Rational::ratio(1, 2)));
        assert_eq!(exact_cos_2pi(1, 4), Some(Rational::ratio(0, 1)));
        assert_eq!(exact_cos_2pi(2, 6), Some(Rational::ratio(-1, 2)));
        assert_eq!(exact_cos_2pi(1, 5), None);
        assert_eq!(<f64 as Weight>::cos_2pi(1, 4).unwrap(), 0.0);
    }
}
