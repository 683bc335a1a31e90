//! Polynomials in one swept parameter t with coefficients in cyclotomic
//! fields: the weight type of the exact sweep (`sweep::exact`), so that the
//! ordinary rule code and matrix assembly give the rows of S(t) as exact
//! polynomials in t over Q(ζ_N).
//!
//! How t enters: the scheme is built with the swept parameter at a marker
//! value, a rational no scheme writes as a constant (a large prime
//! denominator), set per thread with [`SymbolGuard`]. `Weight::param`, and a
//! scheme file's expressions evaluated in this type (`ExprField`), read that
//! value as the indeterminate t and every other parameter as a constant.
//! Everything that would make the rows leave the polynomials — a quotient by
//! a non-constant polynomial, a square root of one, a discontinuous function
//! (`kronecker`, a sum bound) of t — gives the undefined element or an
//! evaluation error, and a question a scheme file asks about t (is it zero,
//! is it an integer) is recorded ([`take_non_polynomial`]) so the sweep can
//! refuse rather than follow the marker's answer. The sweep also re-checks
//! the polynomial rows against the ordinary exact rows at rational points.

use super::cyclotomic_element::Cyclotomic;
use super::field::{Decision, EvalError, ExprField};
use super::weight::{Inexact, ParamValue, Rational, Weight};
use crate::error::Error;
use std::cell::{Cell, RefCell};
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Highest degree in t a weight may reach (a bound on the work: the rows of
/// the schemes here are of degree 1 or 2 in their parameters).
pub const MAX_T_DEGREE: usize = 64;

thread_local! {
    static MARKER: RefCell<Option<Rational>> = const { RefCell::new(None) };
    static NON_POLYNOMIAL: Cell<bool> = const { Cell::new(false) };
}

/// While alive, the parameter value `marker` reads as t on this thread.
pub struct SymbolGuard;

impl SymbolGuard {
    pub fn new(marker: &Rational) -> SymbolGuard {
        MARKER.with(|m| *m.borrow_mut() = Some(marker.clone()));
        NON_POLYNOMIAL.with(|f| f.set(false));
        SymbolGuard
    }
}

impl Drop for SymbolGuard {
    fn drop(&mut self) {
        MARKER.with(|m| *m.borrow_mut() = None);
    }
}

/// Whether a discontinuous question about t was asked since the guard was
/// made (or since the last call); clears the record.
pub fn take_non_polynomial() -> bool {
    NON_POLYNOMIAL.with(|f| f.replace(false))
}

fn note_non_polynomial() {
    NON_POLYNOMIAL.with(|f| f.set(true));
}

fn is_marker(q: &Rational) -> bool {
    MARKER.with(|m| m.borrow().as_ref() == Some(q))
}

/// A polynomial in x (lowest first) with coefficients polynomials in t:
/// the exact sweep's block polynomials P(x, t).
pub type BiPoly = Vec<TPoly>;

/// Σ c_k t^k, c_k in a cyclotomic field (lowest degree first, no trailing
/// zeros; empty: zero), or the undefined element (`defined == false`).
#[derive(Clone, Debug)]
pub struct TPoly {
    coeffs: Vec<Cyclotomic>,
    defined: bool,
}

impl TPoly {
    pub fn undefined() -> TPoly {
        TPoly { coeffs: Vec::new(), defined: false }
    }
    pub fn constant(c: Cyclotomic) -> TPoly {
        TPoly::from_coeffs(vec![c])
    }
    /// The indeterminate t.
    pub fn variable() -> TPoly {
        TPoly::from_coeffs(vec![Cyclotomic::zero(), Cyclotomic::one()])
    }
    pub fn from_coeffs(mut coeffs: Vec<Cyclotomic>) -> TPoly {
        if coeffs.iter().any(|c| !c.is_defined()) || coeffs.len() > MAX_T_DEGREE + 1 + 64 {
            return TPoly::undefined();
        }
        while coeffs.last().is_some_and(|c| Weight::is_zero(c)) {
            coeffs.pop();
        }
        if coeffs.len() > MAX_T_DEGREE + 1 {
            return TPoly::undefined();
        }
        TPoly { coeffs, defined: true }
    }
    pub fn is_defined(&self) -> bool {
        self.defined
    }
    /// Coefficients of 1, t, t², ... (none for zero).
    pub fn coeffs(&self) -> &[Cyclotomic] {
        &self.coeffs
    }
    /// Degree in t (0 for constants and zero).
    pub fn degree(&self) -> usize {
        self.coeffs.len().saturating_sub(1)
    }
    pub fn is_constant(&self) -> bool {
        self.defined && self.coeffs.len() <= 1
    }
    /// The constant term of a constant polynomial.
    pub fn as_constant(&self) -> Option<Cyclotomic> {
        self.is_constant().then(|| self.coeffs.first().cloned().unwrap_or_else(Cyclotomic::zero))
    }
    /// The value at t = x (the undefined element for the undefined polynomial).
    pub fn eval(&self, x: &Rational) -> Cyclotomic {
        if !self.defined {
            return Cyclotomic::undefined();
        }
        let x = Cyclotomic::from_rational(x);
        self.coeffs.iter().rev().fold(Cyclotomic::zero(), |acc, c| acc * x.clone() + c.clone())
    }
    /// Every coefficient is real (in Q(ζ_N) ∩ R).
    pub fn is_real(&self) -> bool {
        self.defined && self.coeffs.iter().all(|c| c.is_real())
    }
    /// The lcm of the orders N of the coefficients' fields (1: rational).
    pub fn field_order(&self) -> u64 {
        self.coeffs.iter().fold(1u64, |l, c| {
            let n = c.order().unwrap_or(1) as u64;
            l / super::weight::gcd(l as i64, n as i64) as u64 * n
        })
    }
    fn scale(&self, c: &Cyclotomic) -> TPoly {
        if !self.defined || !c.is_defined() {
            return TPoly::undefined();
        }
        TPoly::from_coeffs(self.coeffs.iter().map(|x| x.clone() * c.clone()).collect())
    }
}

impl PartialEq for TPoly {
    fn eq(&self, o: &TPoly) -> bool {
        self.defined && o.defined && self.coeffs.len() == o.coeffs.len() && self.coeffs == o.coeffs
    }
}

impl Add for TPoly {
    type Output = TPoly;
    fn add(self, o: TPoly) -> TPoly {
        if !self.defined || !o.defined {
            return TPoly::undefined();
        }
        let (mut long, short) = if self.coeffs.len() >= o.coeffs.len() { (self, o) } else { (o, self) };
        for (k, c) in short.coeffs.into_iter().enumerate() {
            long.coeffs[k] = std::mem::replace(&mut long.coeffs[k], Cyclotomic::zero()) + c;
        }
        TPoly::from_coeffs(long.coeffs)
    }
}

impl Neg for TPoly {
    type Output = TPoly;
    fn neg(self) -> TPoly {
        if !self.defined {
            return self;
        }
        TPoly { coeffs: self.coeffs.into_iter().map(|c| -c).collect(), defined: true }
    }
}

impl Sub for TPoly {
    type Output = TPoly;
    fn sub(self, o: TPoly) -> TPoly {
        self + (-o)
    }
}

impl Mul for TPoly {
    type Output = TPoly;
    fn mul(self, o: TPoly) -> TPoly {
        if !self.defined || !o.defined {
            return TPoly::undefined();
        }
        if self.coeffs.is_empty() || o.coeffs.is_empty() {
            return TPoly::from_coeffs(Vec::new());
        }
        if self.coeffs.len() + o.coeffs.len() - 1 > MAX_T_DEGREE + 1 {
            return TPoly::undefined();
        }
        let mut out = vec![Cyclotomic::zero(); self.coeffs.len() + o.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            if Weight::is_zero(a) {
                continue;
            }
            for (j, b) in o.coeffs.iter().enumerate() {
                if Weight::is_zero(b) {
                    continue;
                }
                out[i + j] = std::mem::replace(&mut out[i + j], Cyclotomic::zero()) + a.clone() * b.clone();
            }
        }
        TPoly::from_coeffs(out)
    }
}

/// Division by a nonzero constant; by anything else the undefined element
/// (the rows would leave the polynomials in t).
impl Div for TPoly {
    type Output = TPoly;
    fn div(self, o: TPoly) -> TPoly {
        match o.as_constant() {
            Some(c) if !Weight::is_zero(&c) => self.scale(&(Cyclotomic::one() / c)),
            _ => TPoly::undefined(),
        }
    }
}

impl fmt::Display for TPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.defined {
            return write!(f, "undefined");
        }
        if self.coeffs.is_empty() {
            return write!(f, "0");
        }
        let terms: Vec<String> = self
            .coeffs
            .iter()
            .enumerate()
            .filter(|(_, c)| !Weight::is_zero(*c))
            .map(|(k, c)| match k {
                0 => format!("({c})"),
                1 => format!("({c})·t"),
                _ => format!("({c})·t^{k}"),
            })
            .collect();
        write!(f, "{}", terms.join(" + "))
    }
}

impl Weight for TPoly {
    fn zero() -> Self {
        TPoly::from_coeffs(Vec::new())
    }
    fn one() -> Self {
        TPoly::constant(Cyclotomic::one())
    }
    fn ratio(p: i64, q: i64) -> Self {
        TPoly::constant(Cyclotomic::ratio(p, q))
    }
    fn cos_2pi(k: i64, n: i64) -> Result<Self, Inexact> {
        Cyclotomic::cos_2pi(k, n).map(TPoly::constant)
    }
    fn sqrt(&self) -> Result<Self, Inexact> {
        match self.as_constant() {
            Some(c) => Weight::sqrt(&c).map(TPoly::constant),
            None => Err(Inexact),
        }
    }
    /// The marker value is t; other exact values are constants.
    fn param(p: &ParamValue) -> Result<Self, Inexact> {
        let q = p.exact.as_ref().ok_or(Inexact)?;
        Ok(if is_marker(q) { TPoly::variable() } else { TPoly::constant(Cyclotomic::from_rational(q)) })
    }
    /// The value at the marker (rules asking a weight's float value see the
    /// marker's scheme; the sweep re-checks the rows at other points).
    fn to_f64(&self) -> f64 {
        match MARKER.with(|m| m.borrow().clone()) {
            Some(x) => self.eval(&x).to_f64(),
            None => self.as_constant().map_or(f64::NAN, |c| c.to_f64()),
        }
    }
    fn is_zero(&self) -> bool {
        self.defined && self.coeffs.is_empty()
    }
    fn from_cyclotomic(c: &Cyclotomic) -> Result<Self, Inexact> {
        Ok(TPoly::constant(c.clone()))
    }
}

fn unrepresentable<T>(why: String) -> Result<T, EvalError> {
    Err(EvalError::Unrepresentable(why))
}

/// A scheme file's expressions in the swept parameter: the field operations
/// of polynomials in t, with exact cyclotomic constants; quotients by, and
/// functions of, expressions in t are refused.
impl ExprField for TPoly {
    const NAME: &'static str = "polynomials in the swept parameter";
    const EXACT: bool = true;
    const ANGLES_BY_PI: bool = true;
    fn number(_: f64, exact: Option<&Rational>) -> Result<Self, EvalError> {
        match exact {
            Some(q) if is_marker(q) => Ok(TPoly::variable()),
            Some(q) => Ok(TPoly::constant(Cyclotomic::from_rational(q))),
            None => unrepresentable("a floating-point value has no exact value".into()),
        }
    }
    fn from_int(k: i64) -> Self {
        <TPoly as Weight>::int(k)
    }
    fn pi() -> Result<Self, EvalError> {
        unrepresentable("π lies in no cyclotomic field".into())
    }
    fn imaginary_unit() -> Result<Self, EvalError> {
        <Cyclotomic as ExprField>::imaginary_unit().map(TPoly::constant)
    }
    fn negate(self) -> Self {
        -self
    }
    fn arith(op: char, x: Self, y: Self) -> Result<Self, EvalError> {
        Ok(match op {
            '+' => x + y,
            '-' => x - y,
            '*' => x * y,
            _ => match y.as_constant() {
                Some(c) if Weight::is_zero(&c) => {
                    return Err(EvalError::Invalid(Error::Input("division by zero".into())));
                }
                Some(_) => x / y,
                None => {
                    note_non_polynomial();
                    return unrepresentable("a quotient by an expression in the swept parameter".into());
                }
            },
        })
    }
    fn power(x: Self, y: Self) -> Result<Self, EvalError> {
        let Some(k) = y.as_constant().and_then(|c| c.to_rational()).filter(|q| q.is_integer()) else {
            note_non_polynomial();
            return unrepresentable("a power whose exponent is not a constant integer".into());
        };
        let k = num_traits::ToPrimitive::to_i64(&k.to_integer()).unwrap_or(i64::MAX);
        if k < 0 || k > MAX_T_DEGREE as i64 {
            return match x.as_constant() {
                Some(c) => {
                    <Cyclotomic as ExprField>::power(c, Cyclotomic::from_rational(&Rational::from_integer(k.into())))
                        .map(TPoly::constant)
                }
                None => {
                    note_non_polynomial();
                    unrepresentable("a negative (or huge) power of an expression in the swept parameter".into())
                }
            };
        }
        let mut acc = <TPoly as Weight>::one();
        for _ in 0..k {
            acc = acc * x.clone();
        }
        Ok(acc)
    }
    fn cos_turn(k: i64, n: i64) -> Result<Self, EvalError> {
        <Cyclotomic as ExprField>::cos_turn(k, n).map(TPoly::constant)
    }
    fn function(f: &str, x: Self) -> Result<Self, EvalError> {
        match x.as_constant() {
            Some(c) => <Cyclotomic as ExprField>::function(f, c).map(TPoly::constant),
            None => {
                note_non_polynomial();
                unrepresentable(format!("{f} of an expression in the swept parameter"))
            }
        }
    }
    fn zero_test(x: &Self) -> Decision<bool> {
        match x.as_constant() {
            Some(c) => Decision::Known(Weight::is_zero(&c)),
            None => {
                note_non_polynomial();
                Decision::Unknown("the argument depends on the swept parameter".into())
            }
        }
    }
    fn integer(x: &Self) -> Decision<Option<i64>> {
        match x.as_constant() {
            Some(c) => <Cyclotomic as ExprField>::integer(&c),
            None => {
                note_non_polynomial();
                Decision::Unknown("the argument depends on the swept parameter".into())
            }
        }
    }
    fn bounded(x: Self) -> Result<Self, EvalError> {
        if !x.is_defined() {
            return unrepresentable("not a polynomial in the swept parameter over a cyclotomic field".into());
        }
        Ok(x)
    }
    fn describe(x: &Self) -> String {
        x.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_and_the_marker() {
        let marker = Rational::new(7.into(), 1_000_003.into());
        let _g = SymbolGuard::new(&marker);
        let p = ParamValue { value: 0.0, exact: Some(marker.clone()), text: String::new() };
        let t = TPoly::param(&p).unwrap();
        let w = (TPoly::ratio(1, 2) - t.clone()) * (t.clone() + TPoly::one()) / TPoly::int(4);
        assert_eq!(w.degree(), 2);
        // (1/2 − 3)(3 + 1)/4 = −5/2
        assert_eq!(w.eval(&Rational::from_integer(3.into())), Cyclotomic::ratio(-5, 2));
        assert!(!(TPoly::one() / t.clone()).is_defined());
        assert!(TPoly::sqrt(&t).is_err());
        assert!(!take_non_polynomial());
    }
}
