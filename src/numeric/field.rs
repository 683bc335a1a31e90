//! The number fields an expression (`numeric::expr`) is evaluated in, and
//! what each can decide.
//!
//! One recursive walk of an expression (`Expr::evaluate`) serves every
//! arithmetic: floating point (complex, `Complex64`), exact rationals
//! (`Rational`), exact elements of cyclotomic fields (`Cyclotomic`) and
//! outward-rounded real intervals (`Interval`). A field supplies the numbers,
//! the operations and the answers to the two discontinuous questions of the
//! language: is a value zero (`kronecker`), is it an integer (the bounds of a
//! `sum`). The exact fields always answer. The approximate ones answer only
//! where the answer cannot be wrong, and otherwise say that they cannot
//! decide (`Decision::Unknown`); the walk then asks the exact fields about
//! the argument, and if they have no reading of it either, the evaluation
//! fails with [`EvalError::Undecidable`]. Never a guess: a float reading of
//! kronecker(1e-13) that said 1 once made a file read as Catmull–Clark in
//! floating point and as another scheme exactly.
//!
//! [`Reading`] is the policy scheme files use: a weight is read exactly where
//! it can be (rational, then cyclotomic) and its float value is that exact
//! value rounded, so the float and exact readings of a file cannot disagree.

use num_complex::Complex64;
use num_traits::{Signed, ToPrimitive, Zero};

use super::cyclotomic::Cyclotomic;
use super::expr::{Env, Expr, MAX_EXACT_BITS};
use super::interval::{cos_sin_2pi, Interval};
use super::weight::{exact_cos_2pi, Rational, Weight};
use crate::error::Error;

/// Why an evaluation has no value.
#[derive(Clone, Debug, PartialEq)]
pub enum EvalError {
    /// The expression has no value here in any arithmetic: an unknown
    /// variable, a division by zero, a sum's bound that is not an integer,
    /// too many sum terms.
    Invalid(Error),
    /// This arithmetic cannot hold the value (π or √2 in the rationals, a
    /// float-only parameter in an exact field, a complex number in the
    /// intervals, an exact number past the size limits); another may.
    Unrepresentable(String),
    /// A discontinuous function (kronecker, a sum's integer bound) at an
    /// argument this arithmetic cannot decide, and no exact reading of the
    /// argument decides it either.
    Undecidable(String),
}

impl From<EvalError> for Error {
    fn from(e: EvalError) -> Error {
        match e {
            EvalError::Invalid(e) => e,
            EvalError::Unrepresentable(m) => Error::Numeric(m),
            EvalError::Undecidable(m) => Error::Numeric(m),
        }
    }
}

/// The answer to a question a discontinuous function asks of its argument.
#[derive(Clone, Debug, PartialEq)]
pub enum Decision<T> {
    Known(T),
    /// this arithmetic cannot tell; the reason, for the error message
    Unknown(String),
}

fn invalid(msg: impl Into<String>) -> EvalError {
    EvalError::Invalid(Error::Input(msg.into()))
}

fn unrepresentable<T>(msg: impl Into<String>) -> Result<T, EvalError> {
    Err(EvalError::Unrepresentable(msg.into()))
}

/// Largest |bound| of a sum: past it no arithmetic here counts exactly.
const MAX_BOUND: f64 = 1e15;
/// Integer exponents up to this modulus are computed exactly.
const MAX_EXPONENT: i64 = 256;
/// A floating-point value this close to zero (but not zero) may be a zero
/// blurred by rounding, or a tiny nonzero number: floats cannot tell.
pub const FLOAT_ZERO_TOLERANCE: f64 = 1e-12;
/// A floating-point bound this close to an integer (but not one) may be that
/// integer blurred by rounding: floats cannot tell.
const FLOAT_INTEGER_TOLERANCE: f64 = 1e-9;

/// A number field the expression language evaluates in.
pub trait ExprField: Clone + Sized {
    /// The arithmetic's name in messages ("cannot be decided in ...").
    const NAME: &'static str;
    /// Whether the field answers every question exactly (then the walk does
    /// not ask another field about an argument).
    const EXACT: bool;
    /// Whether cos and sin are taken of a rational multiple qπ of π, q found
    /// exactly (`Expr::pi_multiple`), rather than of the argument's value.
    const ANGLES_BY_PI: bool;
    /// A number as written: its double, and its exact value when it has one.
    fn number(value: f64, exact: Option<&Rational>) -> Result<Self, EvalError>;
    fn from_int(k: i64) -> Self;
    fn pi() -> Result<Self, EvalError>;
    fn imaginary_unit() -> Result<Self, EvalError>;
    fn negate(self) -> Self;
    /// x op y for `+ - * /`.
    fn arith(op: char, x: Self, y: Self) -> Result<Self, EvalError>;
    fn power(x: Self, y: Self) -> Result<Self, EvalError>;
    /// cos(2πk/n), n > 0 (fields with `ANGLES_BY_PI`).
    fn cos_turn(k: i64, n: i64) -> Result<Self, EvalError>;
    /// `cos`, `sin` (fields without `ANGLES_BY_PI`), `sqrt`, `cbrt`, `abs`.
    fn function(f: &str, x: Self) -> Result<Self, EvalError>;
    /// Whether x is zero.
    fn zero_test(x: &Self) -> Decision<bool>;
    /// x as an integer within ±1e15 (`Known(None)`: it is not one).
    fn integer(x: &Self) -> Decision<Option<i64>>;
    /// The value, or why it is refused (size limits, undefined elements).
    fn bounded(x: Self) -> Result<Self, EvalError>;
    /// The value for messages.
    fn describe(x: &Self) -> String;
}

/// Floating point, complex so that printed eigenvalues such as
/// −1/16 ± √5/48 i can be written down.
impl ExprField for Complex64 {
    const NAME: &'static str = "floating point";
    const EXACT: bool = false;
    const ANGLES_BY_PI: bool = false;
    fn number(value: f64, _: Option<&Rational>) -> Result<Self, EvalError> {
        Ok(Complex64::new(value, 0.0))
    }
    fn from_int(k: i64) -> Self {
        Complex64::new(k as f64, 0.0)
    }
    fn pi() -> Result<Self, EvalError> {
        Ok(Complex64::new(std::f64::consts::PI, 0.0))
    }
    fn imaginary_unit() -> Result<Self, EvalError> {
        Ok(Complex64::new(0.0, 1.0))
    }
    fn negate(self) -> Self {
        -self
    }
    fn arith(op: char, x: Self, y: Self) -> Result<Self, EvalError> {
        Ok(match op {
            '+' => x + y,
            '-' => x - y,
            '*' => x * y,
            _ => {
                if y.norm() == 0.0 {
                    return Err(invalid("division by zero"));
                }
                x / y
            }
        })
    }
    fn power(x: Self, y: Self) -> Result<Self, EvalError> {
        Ok(if y.im == 0.0 && y.re.fract() == 0.0 && y.re.abs() <= 64.0 {
            x.powi(y.re as i32)
        } else {
            // principal branch: a real base has imaginary part +0, never -0
            positive_zero(x).powc(y)
        })
    }
    fn cos_turn(k: i64, n: i64) -> Result<Self, EvalError> {
        Ok(Complex64::new(<f64 as Weight>::cos_2pi(k, n).unwrap_or(f64::NAN), 0.0))
    }
    fn function(f: &str, x: Self) -> Result<Self, EvalError> {
        let x = positive_zero(x);
        Ok(match f {
            "cos" => x.cos(),
            "sin" => x.sin(),
            "sqrt" => x.sqrt(),
            "cbrt" if x.im == 0.0 => Complex64::new(x.re.cbrt(), 0.0),
            "cbrt" => x.powf(1.0 / 3.0),
            _ => Complex64::new(x.norm(), 0.0),
        })
    }
    /// A modulus of at least [`FLOAT_ZERO_TOLERANCE`] is not zero; in between
    /// rounding may have made a zero nonzero or the converse, so floats do
    /// not answer. Exactly 0.0 counts as zero only where no exact reading of
    /// the argument says otherwise (`Question::certain`).
    fn zero_test(x: &Self) -> Decision<bool> {
        let r = x.norm();
        if *x == Complex64::new(0.0, 0.0) {
            Decision::Known(true)
        } else if r >= FLOAT_ZERO_TOLERANCE {
            Decision::Known(false)
        } else if r.is_nan() {
            Decision::Unknown("it is not a number".into())
        } else {
            Decision::Unknown(format!(
                "it is {}, within {FLOAT_ZERO_TOLERANCE:e} of zero but not zero",
                fmt_complex(*x)
            ))
        }
    }
    fn integer(x: &Self) -> Decision<Option<i64>> {
        let r = x.re.round();
        if x.im != 0.0 || !x.re.is_finite() || r.abs() > MAX_BOUND {
            return Decision::Known(None);
        }
        if x.re == r {
            Decision::Known(Some(r as i64))
        } else if (x.re - r).abs() > FLOAT_INTEGER_TOLERANCE * r.abs().max(1.0) {
            Decision::Known(None)
        } else {
            Decision::Unknown(format!("it is {}, within rounding of the integer {r} but not equal to it", x.re))
        }
    }
    fn bounded(x: Self) -> Result<Self, EvalError> {
        Ok(x)
    }
    fn describe(x: &Self) -> String {
        fmt_complex(*x)
    }
}

/// The same number with a zero imaginary part of sign +: −1 as (−1, −0.0)
/// (what negating 1 gives) would put sqrt and powers on the wrong side of the
/// branch cut (sqrt(−1) = −i).
fn positive_zero(z: Complex64) -> Complex64 {
    Complex64::new(z.re, z.im + 0.0)
}

pub(crate) fn fmt_complex(z: Complex64) -> String {
    if z.im == 0.0 {
        format!("{}", z.re)
    } else {
        format!("{} + {}i", z.re, z.im)
    }
}

/// An exponent as a machine integer of modulus at most [`MAX_EXPONENT`].
fn small_exponent(e: Option<Rational>) -> Result<i64, EvalError> {
    match e {
        Some(e) if e.is_integer() && e.abs() <= Rational::from_integer(MAX_EXPONENT.into()) => {
            Ok(e.to_integer().to_i64().expect("at most 256"))
        }
        _ => unrepresentable(format!("only integer exponents up to {MAX_EXPONENT} are exact")),
    }
}

fn too_big(q: &Rational) -> bool {
    q.numer().bits() + q.denom().bits() > MAX_EXACT_BITS
}

fn integer_of(q: &Rational) -> Option<i64> {
    (q.is_integer() && q.abs() <= Rational::from_integer((MAX_BOUND as i64).into()))
        .then(|| q.to_integer().to_i64())
        .flatten()
}

/// Exact rationals: cos and sin of rational multiples of π where the value is
/// rational, square roots of rational squares.
impl ExprField for Rational {
    const NAME: &'static str = "rational arithmetic";
    const EXACT: bool = true;
    const ANGLES_BY_PI: bool = true;
    fn number(_: f64, exact: Option<&Rational>) -> Result<Self, EvalError> {
        exact.cloned().ok_or_else(|| EvalError::Unrepresentable("a floating-point value has no exact value".into()))
    }
    fn from_int(k: i64) -> Self {
        Rational::from_integer(k.into())
    }
    fn pi() -> Result<Self, EvalError> {
        unrepresentable("π is irrational")
    }
    fn imaginary_unit() -> Result<Self, EvalError> {
        unrepresentable("i is not rational")
    }
    fn negate(self) -> Self {
        -self
    }
    fn arith(op: char, x: Self, y: Self) -> Result<Self, EvalError> {
        Ok(match op {
            '+' => x + y,
            '-' => x - y,
            '*' => x * y,
            _ => {
                if Zero::is_zero(&y) {
                    return Err(invalid("division by zero"));
                }
                x / y
            }
        })
    }
    fn power(x: Self, y: Self) -> Result<Self, EvalError> {
        let k = small_exponent(Some(y))?;
        if k < 0 && Zero::is_zero(&x) {
            return Err(invalid("division by zero"));
        }
        // decide from the operands' sizes before computing the power
        let bits = x.numer().bits() + x.denom().bits();
        if bits.saturating_mul(k.unsigned_abs()) > 2 * MAX_EXACT_BITS {
            return unrepresentable(format!("an exact power larger than {MAX_EXACT_BITS} bits"));
        }
        Ok(num_traits::pow::Pow::pow(x, k as i32))
    }
    fn cos_turn(k: i64, n: i64) -> Result<Self, EvalError> {
        exact_cos_2pi(k, n).ok_or_else(|| EvalError::Unrepresentable(format!("cos(2π·{k}/{n}) is irrational")))
    }
    fn function(f: &str, x: Self) -> Result<Self, EvalError> {
        match f {
            "sqrt" => Weight::sqrt(&x).or_else(|_| unrepresentable(format!("sqrt({x}) is not rational"))),
            "abs" => Ok(x.abs()),
            _ => unrepresentable(format!("{f} is not evaluated exactly")),
        }
    }
    fn zero_test(x: &Self) -> Decision<bool> {
        Decision::Known(Zero::is_zero(x))
    }
    fn integer(x: &Self) -> Decision<Option<i64>> {
        Decision::Known(integer_of(x))
    }
    fn bounded(x: Self) -> Result<Self, EvalError> {
        // past the limit every further operation would cost without bound
        if too_big(&x) {
            return unrepresentable(format!("an exact value larger than {MAX_EXACT_BITS} bits"));
        }
        Ok(x)
    }
    fn describe(x: &Self) -> String {
        x.to_string()
    }
}

/// Exact elements of cyclotomic fields Q(ζ_N): cos and sin of rational
/// multiples of π whatever their value, `i`, square roots and moduli of
/// rationals.
impl ExprField for Cyclotomic {
    const NAME: &'static str = "cyclotomic arithmetic";
    const EXACT: bool = true;
    const ANGLES_BY_PI: bool = true;
    fn number(_: f64, exact: Option<&Rational>) -> Result<Self, EvalError> {
        match exact {
            Some(q) => Ok(Cyclotomic::from_rational(q)),
            None => unrepresentable("a floating-point value has no exact value"),
        }
    }
    fn from_int(k: i64) -> Self {
        <Cyclotomic as Weight>::int(k)
    }
    fn pi() -> Result<Self, EvalError> {
        unrepresentable("π lies in no cyclotomic field")
    }
    fn imaginary_unit() -> Result<Self, EvalError> {
        Cyclotomic::root_of_unity(1, 4).or_else(|_| unrepresentable("i"))
    }
    fn negate(self) -> Self {
        -self
    }
    fn arith(op: char, x: Self, y: Self) -> Result<Self, EvalError> {
        Ok(match op {
            '+' => x + y,
            '-' => x - y,
            '*' => x * y,
            _ => {
                if Weight::is_zero(&y) {
                    return Err(invalid("division by zero"));
                }
                x / y
            }
        })
    }
    fn power(x: Self, y: Self) -> Result<Self, EvalError> {
        let k = small_exponent(y.to_rational())?;
        let base = if k < 0 {
            if Weight::is_zero(&x) {
                return Err(invalid("division by zero"));
            }
            x.inverse()
        } else {
            x
        };
        // square and multiply, each step bounded like every operation
        let (mut acc, mut square, mut k) = (<Cyclotomic as Weight>::one(), base, k.unsigned_abs());
        while k > 0 {
            if k & 1 == 1 {
                acc = acc * square.clone();
            }
            k >>= 1;
            if k > 0 {
                square = square.clone() * square;
            }
            if acc.bits() > MAX_EXACT_BITS || square.bits() > MAX_EXACT_BITS {
                return unrepresentable(format!("an exact power larger than {MAX_EXACT_BITS} bits"));
            }
        }
        Ok(acc)
    }
    fn cos_turn(k: i64, n: i64) -> Result<Self, EvalError> {
        <Cyclotomic as Weight>::cos_2pi(k, n)
            .or_else(|_| unrepresentable(format!("cos(2π·{k}/{n}) lies in no cyclotomic field of order at most 1024")))
    }
    fn function(f: &str, x: Self) -> Result<Self, EvalError> {
        let Some(q) = x.to_rational().filter(|_| f == "sqrt" || f == "abs") else {
            return unrepresentable(format!("{f} is evaluated exactly for rational arguments only"));
        };
        let r = if f == "abs" { Ok(q.abs()) } else { Weight::sqrt(&q).map_err(|_| ()) };
        r.map(|r| Cyclotomic::from_rational(&r)).or_else(|_| unrepresentable(format!("sqrt({q}) is not rational")))
    }
    fn zero_test(x: &Self) -> Decision<bool> {
        Decision::Known(Weight::is_zero(x))
    }
    fn integer(x: &Self) -> Decision<Option<i64>> {
        // an irrational element is certainly no integer
        Decision::Known(x.to_rational().as_ref().and_then(integer_of))
    }
    fn bounded(x: Self) -> Result<Self, EvalError> {
        if !x.is_defined() {
            return unrepresentable("outside the cyclotomic fields of order at most 1024");
        }
        if x.bits() > MAX_EXACT_BITS {
            return unrepresentable(format!("an exact value larger than {MAX_EXACT_BITS} bits"));
        }
        Ok(x)
    }
    fn describe(x: &Self) -> String {
        x.to_string()
    }
}

/// Real intervals with outward rounding: every result encloses the exact
/// value. Complex values are not weights: `i` has no enclosure here.
impl ExprField for Interval {
    const NAME: &'static str = "interval arithmetic";
    const EXACT: bool = false;
    const ANGLES_BY_PI: bool = true;
    fn number(_: f64, exact: Option<&Rational>) -> Result<Self, EvalError> {
        match exact {
            Some(q) => Ok(Interval::rational(q)),
            // a value known only as a double: what it stands for is unknown
            None => unrepresentable("a floating-point value has no enclosure"),
        }
    }
    fn from_int(k: i64) -> Self {
        Interval::ratio(k, 1)
    }
    fn pi() -> Result<Self, EvalError> {
        Ok(Interval::pi())
    }
    fn imaginary_unit() -> Result<Self, EvalError> {
        unrepresentable("complex values have no real enclosure")
    }
    fn negate(self) -> Self {
        -self
    }
    fn arith(op: char, x: Self, y: Self) -> Result<Self, EvalError> {
        Ok(match op {
            '+' => x + y,
            '-' => x - y,
            '*' => x * y,
            _ => {
                if Weight::is_zero(&y) {
                    return Err(invalid("division by zero"));
                }
                if !y.sign_decided() {
                    return Err(EvalError::Undecidable(format!(
                        "a division cannot be decided in interval arithmetic: the divisor's enclosure [{}, {}] \
                         contains zero",
                        y.lo, y.hi
                    )));
                }
                x / y
            }
        })
    }
    fn power(x: Self, y: Self) -> Result<Self, EvalError> {
        let k = small_exponent(y.exact_value())?;
        // square and multiply: each product encloses, so the power does
        let (mut acc, mut square, mut e) = (Interval::point(1.0), x, k.unsigned_abs());
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * square;
            }
            e >>= 1;
            if e > 0 {
                square = square.square();
            }
        }
        if k < 0 {
            return Self::arith('/', Interval::point(1.0), acc);
        }
        Ok(acc)
    }
    fn cos_turn(k: i64, n: i64) -> Result<Self, EvalError> {
        Ok(cos_sin_2pi(k, n).0)
    }
    fn function(f: &str, x: Self) -> Result<Self, EvalError> {
        match f {
            "sqrt" if x.lo >= 0.0 => Ok(Interval::sqrt(&x)),
            "sqrt" if x.hi < 0.0 => unrepresentable("the square root of a negative number is not real"),
            "sqrt" => Err(EvalError::Undecidable(format!(
                "a square root cannot be decided in interval arithmetic: its argument [{}, {}] may be negative",
                x.lo, x.hi
            ))),
            "abs" => Ok(Interval::new(x.mig(), x.mag())),
            _ => unrepresentable(format!("{f} has no enclosure here")),
        }
    }
    /// The point 0 is zero and an enclosure without 0 is not; an enclosure
    /// around 0 may hold a zero or a tiny nonzero number.
    fn zero_test(x: &Self) -> Decision<bool> {
        if Weight::is_zero(x) {
            Decision::Known(true)
        } else if x.sign_decided() {
            Decision::Known(false)
        } else {
            Decision::Unknown(format!("its enclosure [{}, {}] contains zero but is not the point zero", x.lo, x.hi))
        }
    }
    fn integer(x: &Self) -> Decision<Option<i64>> {
        if x.is_point() && x.lo.fract() == 0.0 && x.lo.abs() <= MAX_BOUND {
            Decision::Known(Some(x.lo as i64))
        } else if !x.is_finite() || x.hi.floor() < x.lo || x.lo.abs().min(x.hi.abs()) > MAX_BOUND {
            Decision::Known(None)
        } else {
            Decision::Unknown(format!("its enclosure [{}, {}] contains an integer but is not a point", x.lo, x.hi))
        }
    }
    fn bounded(x: Self) -> Result<Self, EvalError> {
        if !x.is_finite() {
            return unrepresentable("the enclosure is not finite");
        }
        Ok(x)
    }
    fn describe(x: &Self) -> String {
        if x.is_point() {
            format!("{}", x.lo)
        } else {
            format!("[{}, {}]", x.lo, x.hi)
        }
    }
}

/// A question a discontinuous function asks of its argument, put to any field.
pub(crate) trait Question {
    type Answer;
    fn ask<F: ExprField>(&self, x: &F) -> Decision<Self::Answer>;
    /// Whether an approximate field's answer stands without an exact
    /// reading's confirmation: "far from the discontinuity" does, but "on
    /// it" may be rounding (1 + 1e-17 − 1 is 0.0 in floats, 1e-200² too).
    fn certain(&self, answer: &Self::Answer) -> bool;
}

/// Is the value zero? (`kronecker`)
pub(crate) struct IsZero;

impl Question for IsZero {
    type Answer = bool;
    fn ask<F: ExprField>(&self, x: &F) -> Decision<bool> {
        F::zero_test(x)
    }
    fn certain(&self, zero: &bool) -> bool {
        !zero
    }
}

/// Which integer is the value? (a sum's bound; `Err` with the value shown
/// when it is not an integer)
pub(crate) struct AsInteger;

impl Question for AsInteger {
    type Answer = Result<i64, String>;
    fn ask<F: ExprField>(&self, x: &F) -> Decision<Result<i64, String>> {
        match F::integer(x) {
            Decision::Known(Some(k)) => Decision::Known(Ok(k)),
            Decision::Known(None) => Decision::Known(Err(F::describe(x))),
            Decision::Unknown(why) => Decision::Unknown(why),
        }
    }
    fn certain(&self, integer: &Result<i64, String>) -> bool {
        integer.is_err()
    }
}

/// A scheme-file weight as read: exactly where it can be, else in floats.
#[derive(Clone, Debug, PartialEq)]
pub enum Reading {
    Rational(Rational),
    /// exact and not rational (an element of Q(ζ_N) that is not in Q),
    /// with an enclosure when it is real: the tighter of the element's own
    /// (from its coefficients) and the expression's interval reading, both
    /// of which hold the exact value
    Cyclotomic(Cyclotomic, Option<Interval>),
    /// the expression has no exact reading (a float-only parameter or
    /// literal, π outside a cosine, a cube root, a size limit)
    Float(Complex64),
}

impl Reading {
    /// The real value in floating point: an exact reading rounded (a rational
    /// correctly, a cyclotomic element to the middle of its enclosure), a
    /// float reading as computed. An error when the value is not a finite
    /// real number.
    pub fn real(&self) -> Result<f64, Error> {
        match self {
            Reading::Rational(q) => {
                let x = Weight::to_f64(q);
                if !x.is_finite() {
                    return Err(Error::Numeric("the weight is not a finite number".into()));
                }
                Ok(x)
            }
            Reading::Cyclotomic(_, Some(i)) if i.is_finite() => Ok(i.mid()),
            Reading::Cyclotomic(_, Some(_)) => Err(Error::Numeric("the weight is not a finite number".into())),
            Reading::Cyclotomic(c, None) => {
                let (re, im) = c.to_complex();
                Err(Error::Numeric(format!("the weight is complex ({re} + {im}i)")))
            }
            Reading::Float(z) => {
                if !z.re.is_finite() || !z.im.is_finite() {
                    return Err(Error::Numeric("the weight is not a finite number".into()));
                }
                if z.im.abs() > 1e-12 * z.re.abs().max(1.0) {
                    return Err(Error::Numeric(format!("the weight is complex ({} + {}i)", z.re, z.im)));
                }
                Ok(z.re)
            }
        }
    }

    /// The exact value when it is rational.
    pub fn rational(&self) -> Option<&Rational> {
        match self {
            Reading::Rational(q) => Some(q),
            _ => None,
        }
    }
}

impl Expr {
    /// The expression read as a scheme file's weight is: exactly in the
    /// rationals, else exactly in a cyclotomic field, and only when it has no
    /// exact reading in floating point (where an undecidable kronecker or
    /// bound is then an error). An exact reading that finds the expression
    /// invalid (a division by an exact zero) is final: floats would only
    /// blur it into a huge number.
    pub fn reading(&self, env: &Env) -> Result<Reading, Error> {
        match self.evaluate::<Rational>(env) {
            Ok(q) => return Ok(Reading::Rational(q)),
            Err(EvalError::Unrepresentable(_)) => {}
            Err(e) => return Err(e.into()),
        }
        match self.evaluate::<Cyclotomic>(env) {
            Ok(c) => {
                if let Some(q) = c.to_rational() {
                    return Ok(Reading::Rational(q));
                }
                // the rounding is the middle of the tightest enclosure at
                // hand, so it lies inside every interval reading of the weight
                let own = Interval::from_cyclotomic(&c).ok();
                let walked = self.evaluate::<Interval>(env).ok();
                let enclosure = match (own, walked) {
                    (Some(a), Some(b)) if a.lo.max(b.lo) <= a.hi.min(b.hi) => {
                        Some(Interval::new(a.lo.max(b.lo), a.hi.min(b.hi)))
                    }
                    (a, _) => a,
                };
                return Ok(Reading::Cyclotomic(c, enclosure));
            }
            Err(EvalError::Unrepresentable(_)) => {}
            Err(e) => return Err(e.into()),
        }
        Ok(Reading::Float(self.evaluate::<Complex64>(env)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::expr::env_int;

    fn at(n: i64, j: i64) -> Env {
        env_int(&[("n", n), ("j", j)])
    }
    fn parse(s: &str) -> Expr {
        Expr::parse(s).unwrap()
    }
    fn q(p: i64, d: i64) -> Rational {
        Rational::new(p.into(), d.into())
    }
    /// √5 enclosed from above and below by rationals: 2.2360679774997896964...
    fn sqrt5_between() -> (f64, f64) {
        (2.236_067_977_499_789, 2.236_067_977_499_790_5)
    }

    #[test]
    fn every_field_reads_the_same_rational() {
        let e = parse("3/8 + (3/8 + cos(2 pi / n) / 4)^2");
        // at n = 6, cos(2π/6) = 1/2: 3/8 + (1/2)^2 = 5/8
        assert_eq!(e.evaluate::<Rational>(&at(6, 0)), Ok(q(5, 8)));
        assert_eq!(e.evaluate::<Cyclotomic>(&at(6, 0)), Ok(Cyclotomic::from_rational(&q(5, 8))));
        assert!(e.evaluate::<Interval>(&at(6, 0)).unwrap().is_exactly(&q(5, 8)));
        assert!((e.evaluate::<Complex64>(&at(6, 0)).unwrap().re - 0.625).abs() < 1e-15);
    }

    #[test]
    fn cos_of_a_fifth_is_enclosed_and_exact() {
        // cos(2π/5) = (√5 − 1)/4
        let e = parse("cos(2 pi / 5)");
        let env = Env::new();
        assert!(matches!(e.evaluate::<Rational>(&env), Err(EvalError::Unrepresentable(_))));
        let c = e.evaluate::<Cyclotomic>(&env).unwrap();
        // (4c + 1)² = 5 exactly
        let t = c * Cyclotomic::int(4) + Cyclotomic::int(1);
        assert_eq!(t.clone() * t, Cyclotomic::int(5));
        let i = e.evaluate::<Interval>(&env).unwrap();
        let (lo, hi) = sqrt5_between();
        assert!(i.lo <= (hi - 1.0) / 4.0 && i.hi >= (lo - 1.0) / 4.0 && i.width() < 1e-15);
        assert!(e.evaluate::<Interval>(&env).unwrap().contains(e.evaluate::<Complex64>(&env).unwrap().re));
    }

    #[test]
    fn kronecker_is_decided_exactly_or_refused() {
        // the reproducer: cos(2π/5)/10^13 is about 3e-14, not zero
        let toggle = parse("kronecker(cos(2 pi / 5) / 10^13)");
        let env = Env::new();
        assert_eq!(toggle.evaluate::<Cyclotomic>(&env), Ok(Cyclotomic::int(0)));
        // floats cannot decide it alone, but the exact reading of the
        // argument does: 0, never the old 1
        assert_eq!(toggle.evaluate::<Complex64>(&env), Ok(Complex64::new(0.0, 0.0)));
        assert!(toggle.evaluate::<Interval>(&env).unwrap().is_exactly(&q(0, 1)));
        // a float-only parameter: nothing decides it, and floats say so
        let mut env = Env::new();
        env.insert("a".into(), crate::numeric::ParamValue::from_f64(1e-13));
        let err = parse("kronecker(a)").evaluate::<Complex64>(&env).unwrap_err();
        assert!(
            matches!(&err, EvalError::Undecidable(m) if m.contains("cannot be decided in floating point")),
            "{err:?}"
        );
        assert!(parse("kronecker(a)").reading(&env).unwrap_err().to_string().contains("cannot be decided"));
        // a float that rounding made exactly 0.0 is overruled by the exact
        // reading: 10^-400 underflows, 1 + 1e-17 − 1 cancels, neither is 0
        for s in ["kronecker(10^-200 10^-200)", "kronecker(1 + 1e-17 - 1)"] {
            assert_eq!(parse(s).evaluate::<Complex64>(&Env::new()), Ok(Complex64::new(0.0, 0.0)), "{s}");
        }
        // far from zero, or exactly zero, floats decide
        env.insert("a".into(), crate::numeric::ParamValue::from_f64(0.25));
        assert_eq!(parse("kronecker(a)").evaluate::<Complex64>(&env), Ok(Complex64::new(0.0, 0.0)));
        env.insert("a".into(), crate::numeric::ParamValue::from_f64(0.0));
        assert_eq!(parse("kronecker(a)").evaluate::<Complex64>(&env), Ok(Complex64::new(1.0, 0.0)));
    }

    #[test]
    fn sum_bounds_are_decided_not_rounded() {
        let mut env = Env::new();
        // a float-only bound next to 3: floats cannot say whether it is 3
        env.insert("b".into(), crate::numeric::ParamValue::from_f64(3.0 + 4e-15));
        let err = parse("sum(m, 0, b, m)").evaluate::<Complex64>(&env).unwrap_err();
        assert!(matches!(&err, EvalError::Undecidable(m) if m.contains("upper bound")), "{err:?}");
        // an exact bound that floats blur is read exactly: 3 (1/3) 3 = 3
        assert_eq!(parse("sum(m, 0, 3 (1/3) 3, m)").evaluate::<Complex64>(&env).unwrap().re, 6.0);
        // not an integer in any field
        for e in [
            parse("sum(m, 0, 5/2, m)").evaluate::<Interval>(&env).unwrap_err(),
            parse("sum(m, 0, 5/2, m)").evaluate::<Rational>(&env).unwrap_err(),
        ] {
            assert!(matches!(&e, EvalError::Invalid(m) if m.to_string().contains("must be an integer")), "{e:?}");
        }
    }

    #[test]
    fn readings_prefer_exact_values() {
        let e = parse("(5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n");
        // Loop's β at n = 6: (5/8 − (3/8 + 1/8)²)/6 = 1/16
        assert_eq!(e.reading(&at(6, 0)).unwrap(), Reading::Rational(q(1, 16)));
        let r = e.reading(&at(5, 0)).unwrap();
        assert!(matches!(r, Reading::Cyclotomic(..)));
        let enclosed = e.evaluate::<Interval>(&at(5, 0)).unwrap();
        assert!(enclosed.contains(r.real().unwrap()));
        // π alone has no exact reading: floats
        assert!(matches!(parse("pi / 4").reading(&Env::new()).unwrap(), Reading::Float(_)));
        // an exact division by zero is an error, not a huge float
        let err = parse("1 / cos(pi / 2)").reading(&Env::new()).unwrap_err().to_string();
        assert!(err.contains("division by zero"), "{err}");
        // complex exact values are no weights
        assert!(parse("i").reading(&Env::new()).unwrap().real().unwrap_err().to_string().contains("complex"));
    }

    #[test]
    fn intervals_refuse_what_they_cannot_enclose() {
        let env = Env::new();
        assert!(matches!(parse("i").evaluate::<Interval>(&env), Err(EvalError::Unrepresentable(_))));
        assert!(parse("1 / (cos(2 pi / 5) - cos(2 pi / 5))").evaluate::<Interval>(&env).is_err());
        // √2: positive, its square holds 2, and tight (2 = (√2)² with both
        // ends within 1e-12 of each other, by the square's own bounds
        // rather than a decimal expansion typed in)
        let r2 = parse("sqrt(2)").evaluate::<Interval>(&env).unwrap();
        assert!(r2.lo > 0.0 && r2.square().contains(2.0) && r2.width() < 1e-12);
        assert!(r2.lo * r2.lo <= 2.0 && r2.hi * r2.hi >= 2.0);
        assert!(parse("2^-2").evaluate::<Interval>(&env).unwrap().is_exactly(&q(1, 4)));
        assert!(parse("pi").evaluate::<Interval>(&env).unwrap().contains(std::f64::consts::PI));
    }
}
