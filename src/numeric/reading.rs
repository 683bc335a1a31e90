//! How a scheme file's weight is read (`Expr::reading`): exactly where it
//! can be (rational, then cyclotomic), else in floating point, with the
//! float value of an exact reading that value rounded, so the float and
//! exact readings of a file cannot disagree. On top of both the expression
//! language (`numeric::expr`) and its fields (`numeric::field`).

use num_complex::Complex64;

use super::cyclotomic_element::Cyclotomic;
use super::expr::{Env, Expr};
use super::field::EvalError;
use super::interval::Interval;
use super::weight::{Rational, Weight};
use crate::error::Error;

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
    use crate::numeric::weight::ParamValue;

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
        env.insert("a".into(), ParamValue::from_f64(1e-13));
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
        env.insert("a".into(), ParamValue::from_f64(0.25));
        assert_eq!(parse("kronecker(a)").evaluate::<Complex64>(&env), Ok(Complex64::new(0.0, 0.0)));
        env.insert("a".into(), ParamValue::from_f64(0.0));
        assert_eq!(parse("kronecker(a)").evaluate::<Complex64>(&env), Ok(Complex64::new(1.0, 0.0)));
    }

    #[test]
    fn sum_bounds_are_decided_not_rounded() {
        let mut env = Env::new();
        // a float-only bound next to 3: floats cannot say whether it is 3
        env.insert("b".into(), ParamValue::from_f64(3.0 + 4e-15));
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
        // √2: positive, its square holds 2, and tight (by the square's own
        // bounds rather than a decimal expansion typed in)
        let r2 = parse("sqrt(2)").evaluate::<Interval>(&env).unwrap();
        assert!(r2.lo > 0.0 && r2.square().contains(2.0) && r2.width() < 1e-12);
        assert!(r2.lo * r2.lo <= 2.0 && r2.hi * r2.hi >= 2.0);
        assert!(parse("2^-2").evaluate::<Interval>(&env).unwrap().is_exactly(&q(1, 4)));
        assert!(parse("pi").evaluate::<Interval>(&env).unwrap().contains(std::f64::consts::PI));
    }
}
