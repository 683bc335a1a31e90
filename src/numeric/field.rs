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
//! The policy scheme files use to read a weight in these fields (`Reading`)
//! is `numeric::reading`.

use num_complex::Complex64;
use num_traits::{Signed, ToPrimitive, Zero};

use super::cyclotomic_element::Cyclotomic;
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

/// Largest exact number an evaluation builds (bits of numerator plus
/// denominator): past it the exact fields decline (`Unrepresentable`) and a
/// scheme file's weight is read in floats, so the cost of every exact
/// operation stays bounded.
pub const MAX_EXACT_BITS: u64 = 4096;
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
