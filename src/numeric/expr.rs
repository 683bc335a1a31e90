//! A small expression language for claims and scheme files, evaluated by
//! one recursive walk (`Expr::evaluate`) generic over the number field
//! (`numeric::field`): floating point (complex, so that printed eigenvalues
//! such as −1/16 ± √5/48 i can be written down), exact rationals (cos and
//! sin of rational multiples of π where the value is rational; square roots
//! of rational squares), exact cyclotomic fields (cos and sin of rational
//! multiples of π whatever their value) and outward-rounded intervals.
//! `Expr::eval`, `Expr::exact` and `Expr::cyclotomic` are that walk in one
//! field each.
//!
//! Grammar: sums and differences of products and quotients of powers of unary
//! terms; `^` binds tighter than unary minus (−2^2 = −4), and is
//! right-associative. Atoms: numbers (`3`, `0.375`, `1e-3`), variables, `pi`,
//! `i` (the imaginary unit), calls `cos(x)`, `sin(x)`, `sqrt(x)`, `cbrt(x)`,
//! `abs(x)`, `kronecker(x)` (1 when x = 0, else 0: piecewise definitions such
//! as a_3 = 3/4; decided exactly, and an error where neither the arithmetic
//! at hand nor an exact reading of x can decide it), the bounded sum
//! `sum(m, FROM, TO, EXPR)` (EXPR summed over
//! the integers m = FROM..TO, m a fresh name bound inside EXPR only; at most
//! `MAX_SUM_TERMS` terms per evaluation, nested sums counted in full; e.g.
//! weights given by their Fourier coefficients) and parentheses. Errors name
//! the column.

use std::collections::BTreeMap;

use num_complex::Complex64;
use num_traits::{One, ToPrimitive, Zero};

use super::cyclotomic_element::Cyclotomic;
use super::field::{AsInteger, Decision, EvalError, ExprField, IsZero, Question};
use super::weight::Rational;
use crate::error::Error;

#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    Num(f64, Option<Rational>),
    Var(String),
    Pi,
    I,
    Neg(Box<Expr>),
    Bin(char, Box<Expr>, Box<Expr>),
    /// a left-associative chain `first op1 e1 op2 e2 ...` of `+ -` or of
    /// `* /` (implicit multiplication included), kept flat so that evaluation
    /// of a long chain does not recurse once per operator
    Chain(Box<Expr>, Vec<(char, Expr)>),
    Call(String, Box<Expr>),
    /// `sum(var, from, to, body)`: body summed over the integers var = from..=to
    Sum(String, Box<Expr>, Box<Expr>, Box<Expr>),
}

/// The most terms one evaluation of an expression may add up, counting every
/// term of nested sums: evaluation time stays bounded whatever the input.
pub const MAX_SUM_TERMS: u64 = 10_000;
/// Deepest nesting of parentheses, signs, powers and calls.
pub const MAX_DEPTH: usize = 200;
/// Names the language itself gives a meaning (not usable as a sum variable).
const BUILTIN_NAMES: [&str; 9] = ["pi", "i", "cos", "sin", "sqrt", "cbrt", "abs", "kronecker", "sum"];
const SUM_FORM: &str = "sum(variable, from, to, expression)";

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(String),
    Ident(String),
    Op(char),
}

fn tokenize(s: &str) -> Result<Vec<(usize, Tok)>, Error> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut k = 0;
    while k < chars.len() {
        let c = chars[k];
        if c.is_whitespace() {
            k += 1;
        } else if c.is_ascii_digit() || (c == '.' && chars.get(k + 1).is_some_and(|d| d.is_ascii_digit())) {
            let start = k;
            while k < chars.len() && (chars[k].is_ascii_digit() || chars[k] == '.') {
                k += 1;
            }
            if k < chars.len() && (chars[k] == 'e' || chars[k] == 'E') {
                let save = k;
                k += 1;
                if k < chars.len() && (chars[k] == '+' || chars[k] == '-') {
                    k += 1;
                }
                if k < chars.len() && chars[k].is_ascii_digit() {
                    while k < chars.len() && chars[k].is_ascii_digit() {
                        k += 1;
                    }
                } else {
                    k = save; // not an exponent: `2e` is 2 times a variable e
                }
            }
            out.push((start, Tok::Num(chars[start..k].iter().collect())));
        } else if c.is_alphabetic() || c == '_' {
            let start = k;
            while k < chars.len() && (chars[k].is_alphanumeric() || chars[k] == '_') {
                k += 1;
            }
            out.push((start, Tok::Ident(chars[start..k].iter().collect())));
        } else if "+-*/^(),".contains(c) {
            out.push((k, Tok::Op(c)));
            k += 1;
        } else {
            return Err(Error::Input(format!("unexpected character '{c}' at column {}", k + 1)));
        }
    }
    Ok(out)
}

struct Parser {
    toks: Vec<(usize, Tok)>,
    pos: usize,
    len: usize,
    /// variables bound by the enclosing sums
    bound: Vec<String>,
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos).map(|t| &t.1)
    }
    fn col(&self) -> usize {
        self.toks.get(self.pos).map(|t| t.0 + 1).unwrap_or(self.len + 1)
    }
    fn eat(&mut self, c: char) -> bool {
        if self.peek() == Some(&Tok::Op(c)) {
            self.pos += 1;
            true
        } else {
            false
        }
    }
    fn sum(&mut self, depth: usize) -> Result<Expr, Error> {
        let first = self.product(depth)?;
        let mut rest = Vec::new();
        loop {
            let op = match self.peek() {
                Some(Tok::Op(c)) if *c == '+' || *c == '-' => *c,
                _ => return Ok(chain(first, rest)),
            };
            self.pos += 1;
            rest.push((op, self.product(depth)?));
        }
    }
    fn product(&mut self, depth: usize) -> Result<Expr, Error> {
        let first = self.unary(depth)?;
        let mut rest = Vec::new();
        loop {
            let op = match self.peek() {
                Some(Tok::Op(c)) if *c == '*' || *c == '/' => *c,
                // implicit multiplication: `2 pi`, `3 cos(x)`, `4a`
                Some(Tok::Num(_)) | Some(Tok::Ident(_)) | Some(Tok::Op('(')) => '*',
                _ => return Ok(chain(first, rest)),
            };
            if op != '*' || matches!(self.peek(), Some(Tok::Op('*'))) {
                self.pos += 1;
            }
            rest.push((op, self.unary(depth)?));
        }
    }
    fn unary(&mut self, depth: usize) -> Result<Expr, Error> {
        if depth > MAX_DEPTH {
            return Err(Error::Input(format!("expression nested too deeply (more than {MAX_DEPTH} levels)")));
        }
        if self.eat('-') {
            return Ok(Expr::Neg(Box::new(self.unary(depth + 1)?)));
        }
        if self.eat('+') {
            return self.unary(depth + 1);
        }
        self.power(depth)
    }
    fn power(&mut self, depth: usize) -> Result<Expr, Error> {
        let base = self.atom(depth)?;
        if self.eat('^') {
            let exp = self.unary(depth + 1)?; // right-associative; allows 2^-1
            return Ok(Expr::Bin('^', Box::new(base), Box::new(exp)));
        }
        Ok(base)
    }
    fn atom(&mut self, depth: usize) -> Result<Expr, Error> {
        let col = self.col();
        match self.toks.get(self.pos).map(|t| t.1.clone()) {
            Some(Tok::Num(t)) => {
                self.pos += 1;
                let p = super::weight::ParamValue::parse(&t).map_err(|e| Error::Input(format!("column {col}: {e}")))?;
                Ok(Expr::Num(p.value, p.exact))
            }
            Some(Tok::Ident(name)) => {
                self.pos += 1;
                if name == "sum" {
                    return self.sum_call(depth);
                }
                const FUNCTIONS: [&str; 6] = ["cos", "sin", "sqrt", "cbrt", "abs", "kronecker"];
                if FUNCTIONS.contains(&name.as_str()) {
                    if !self.eat('(') {
                        return Err(Error::Input(format!(
                            "'{name}' needs an argument in parentheses at column {}",
                            self.col()
                        )));
                    }
                    let arg = self.sum(depth + 1)?;
                    if !self.eat(')') {
                        return Err(Error::Input(format!("missing ')' at column {}", self.col())));
                    }
                    return Ok(Expr::Call(name, Box::new(arg)));
                }
                // any other name is a variable; `n (1 + a)` multiplies
                Ok(match name.as_str() {
                    "pi" => Expr::Pi,
                    "i" => Expr::I,
                    _ => Expr::Var(name),
                })
            }
            Some(Tok::Op('(')) => {
                self.pos += 1;
                let e = self.sum(depth + 1)?;
                if !self.eat(')') {
                    return Err(Error::Input(format!("missing ')' at column {}", self.col())));
                }
                Ok(e)
            }
            Some(Tok::Op(c)) => Err(Error::Input(format!("unexpected '{c}' at column {col}"))),
            None => Err(Error::Input(format!("unexpected end of expression at column {col}"))),
        }
    }
    /// The arguments of `sum`, after the name.
    fn sum_call(&mut self, depth: usize) -> Result<Expr, Error> {
        if !self.eat('(') {
            return Err(Error::Input(format!("'sum' needs arguments {SUM_FORM} at column {}", self.col())));
        }
        let col = self.col();
        let var = match self.peek() {
            Some(Tok::Ident(v)) if BUILTIN_NAMES.contains(&v.as_str()) => {
                return Err(Error::Input(format!("'{v}' cannot be a sum variable (column {col}); use a fresh name")));
            }
            Some(Tok::Ident(v)) if self.bound.contains(v) => {
                return Err(Error::Input(format!(
                    "'{v}' is already bound by an enclosing sum (column {col}); use a fresh name"
                )));
            }
            Some(Tok::Ident(v)) => v.clone(),
            _ => {
                return Err(Error::Input(format!(
                    "the first argument of sum must be a variable name, {SUM_FORM}, at column {col}"
                )))
            }
        };
        self.pos += 1;
        let mut args = Vec::new();
        for what in ["from", "to", "expression"] {
            if !self.eat(',') {
                return Err(Error::Input(format!(
                    "expected ',' before the {what} of {SUM_FORM} at column {}",
                    self.col()
                )));
            }
            if what == "expression" {
                self.bound.push(var.clone());
            }
            let arg = self.sum(depth + 1);
            if what == "expression" {
                self.bound.pop();
            }
            args.push(arg?);
        }
        if !self.eat(')') {
            return Err(Error::Input(format!("missing ')' after {SUM_FORM} at column {}", self.col())));
        }
        let body = args.pop().expect("three arguments");
        let to = args.pop().expect("three arguments");
        let from = args.pop().expect("three arguments");
        Ok(Expr::Sum(var, Box::new(from), Box::new(to), Box::new(body)))
    }
}

/// One operand, or a flat chain of several.
fn chain(first: Expr, rest: Vec<(char, Expr)>) -> Expr {
    if rest.is_empty() {
        first
    } else {
        Expr::Chain(Box::new(first), rest)
    }
}

/// Count a sum's `count` terms against the budget of one evaluation.
fn spend(terms: &mut u64, count: i128) -> Result<(), Error> {
    let total = *terms as i128 + count.max(0);
    if total > MAX_SUM_TERMS as i128 {
        return Err(Error::Input(format!(
            "a sum of {count} terms; at most {MAX_SUM_TERMS} terms in all (nested sums count every term)"
        )));
    }
    *terms = total as u64;
    Ok(())
}

/// The value of a sum's variable (no text: nothing prints it).
fn sum_index(k: i64) -> super::weight::ParamValue {
    super::weight::ParamValue { value: k as f64, exact: Some(Rational::from_integer(k.into())), text: String::new() }
}

fn shadow_error(var: &str) -> Error {
    Error::Input(format!("sum variable '{var}' is already a variable here; use a fresh name"))
}

impl Expr {
    pub fn parse(s: &str) -> Result<Expr, Error> {
        if s.len() > 10_000 {
            return Err(Error::Input("expression longer than 10000 characters".into()));
        }
        let toks = tokenize(s)?;
        let mut p = Parser { toks, pos: 0, len: s.chars().count(), bound: Vec::new() };
        let e = p.sum(0)?;
        if p.pos != p.toks.len() {
            return Err(Error::Input(format!("unexpected '{}' at column {}", token_text(&p.toks[p.pos].1), p.col())));
        }
        Ok(e)
    }

    /// The free variables of the expression (a sum's own variable is bound
    /// inside its summand and not reported).
    pub fn variables(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.free_variables(&mut Vec::new(), &mut out);
        out
    }

    fn free_variables(&self, bound: &mut Vec<String>, out: &mut Vec<String>) {
        match self {
            Expr::Var(v) => {
                if !bound.contains(v) && !out.contains(v) {
                    out.push(v.clone());
                }
            }
            Expr::Neg(a) | Expr::Call(_, a) => a.free_variables(bound, out),
            Expr::Chain(first, rest) => {
                first.free_variables(bound, out);
                for (_, e) in rest {
                    e.free_variables(bound, out);
                }
            }
            Expr::Bin(_, a, b) => {
                a.free_variables(bound, out);
                b.free_variables(bound, out);
            }
            Expr::Sum(v, from, to, body) => {
                from.free_variables(bound, out);
                to.free_variables(bound, out);
                bound.push(v.clone());
                body.free_variables(bound, out);
                bound.pop();
            }
            Expr::Num(..) | Expr::Pi | Expr::I => {}
        }
    }

    /// Floating-point (complex) value. A kronecker or sum bound that floats
    /// cannot decide is decided by an exact reading of its argument, or is
    /// an error (see `numeric::field`).
    pub fn eval(&self, env: &Env) -> Result<Complex64, Error> {
        Ok(self.evaluate::<Complex64>(env)?)
    }

    /// Exact rational value, when the expression has one this evaluator can
    /// prove (None otherwise: irrational, complex, or undecidable here).
    pub fn exact(&self, env: &Env) -> Option<Rational> {
        self.evaluate::<Rational>(env).ok()
    }

    /// Exact value in a cyclotomic field Q(ζ_N), when this evaluator can
    /// prove one: rationals, cos and sin of rational multiples of π (in
    /// Q(ζ_N), N ≤ `cyclotomic::MAX_ORDER`), `i`, the field operations,
    /// integer powers, `kronecker` (decided exactly), sums, and `sqrt`/`abs`
    /// of rationals. None otherwise (π itself, `cbrt`, square roots of
    /// non-squares, elements larger than [`MAX_EXACT_BITS`](super::field::MAX_EXACT_BITS)). What
    /// [`Expr::exact`] proves rational has the same value here.
    pub fn cyclotomic(&self, env: &Env) -> Option<Cyclotomic> {
        self.evaluate::<Cyclotomic>(env).ok()
    }

    /// The value in the field `F` (`numeric::field`): the one evaluator of
    /// the language, whatever the arithmetic.
    pub fn evaluate<F: ExprField>(&self, env: &Env) -> Result<F, EvalError> {
        self.walk(env, &mut 0)
    }

    /// `evaluate`, with the sum terms spent so far in this evaluation.
    fn walk<F: ExprField>(&self, env: &Env, terms: &mut u64) -> Result<F, EvalError> {
        let value = match self {
            Expr::Num(x, q) => F::number(*x, q.as_ref())?,
            Expr::Var(v) => {
                let p =
                    env.get(v).ok_or_else(|| EvalError::Invalid(Error::Input(format!("unknown variable '{v}'"))))?;
                F::number(p.value, p.exact.as_ref())?
            }
            Expr::Pi => F::pi()?,
            Expr::I => F::imaginary_unit()?,
            Expr::Neg(a) => a.walk::<F>(env, terms)?.negate(),
            Expr::Bin('^', a, b) => F::power(a.walk(env, terms)?, b.walk(env, terms)?)?,
            Expr::Bin(op, a, b) => F::arith(*op, a.walk(env, terms)?, b.walk(env, terms)?)?,
            Expr::Chain(first, rest) => {
                let mut x = first.walk::<F>(env, terms)?;
                for (op, e) in rest {
                    x = F::bounded(F::arith(*op, x, e.walk(env, terms)?)?)?;
                }
                x
            }
            Expr::Call(f, a) if f == "kronecker" => {
                let zero = a.decide::<F, _>(&IsZero, "kronecker", env, terms)?;
                F::from_int(zero as i64)
            }
            Expr::Call(f, a) if F::ANGLES_BY_PI && (f == "cos" || f == "sin") => {
                // cos(qπ) and sin(qπ) for rational q, q found exactly
                let Some(q) = a.pi_multiple(env, terms) else {
                    return Err(EvalError::Unrepresentable(format!(
                        "{f} of an argument that is not a rational multiple of π has no value in {}",
                        F::NAME
                    )));
                };
                let (k, n) = cos_angle(f, &q)
                    .ok_or_else(|| EvalError::Unrepresentable(format!("{f}({q} π): the integers overflow")))?;
                F::cos_turn(k, n)?
            }
            Expr::Call(f, a) => F::function(f, a.walk(env, terms)?)?,
            Expr::Sum(var, from, to, summand) => {
                let bound = |e: &Expr, what: &str, terms: &mut u64| -> Result<i64, EvalError> {
                    let context = format!("the {what} bound of a sum");
                    e.decide::<F, _>(&AsInteger, &context, env, terms)?.map_err(|got| {
                        EvalError::Invalid(Error::Input(format!("{context} must be an integer, got {got}")))
                    })
                };
                let lo = bound(from, "lower", terms)?;
                let hi = bound(to, "upper", terms)?;
                if env.contains_key(var) {
                    return Err(EvalError::Invalid(shadow_error(var)));
                }
                spend(terms, hi as i128 - lo as i128 + 1).map_err(EvalError::Invalid)?;
                let mut inner = env.clone();
                let mut total = F::from_int(0);
                for k in lo..=hi {
                    inner.insert(var.clone(), sum_index(k));
                    // as for every operation: a sum whose digits explode is not worth it
                    total = F::bounded(F::arith('+', total, summand.walk(&inner, terms)?)?)?;
                }
                total
            }
        };
        F::bounded(value)
    }

    /// The answer to `question` about this expression's value in `F`. Where
    /// `F` cannot answer (a float within rounding of the discontinuity, an
    /// enclosure around it), or answers "on the discontinuity" from rounded
    /// numbers, an exact reading of the expression answers instead; without
    /// one an uncertain answer fails the evaluation: a guess here once turned
    /// a scheme file into another scheme in floating point.
    fn decide<F: ExprField, Q: Question>(
        &self,
        question: &Q,
        what: &str,
        env: &Env,
        terms: &mut u64,
    ) -> Result<Q::Answer, EvalError> {
        let x = self.walk::<F>(env, terms)?;
        let own = match question.ask(&x) {
            Decision::Known(answer) if F::EXACT || question.certain(&answer) => return Ok(answer),
            own => own,
        };
        match self.walk::<Rational>(env, terms).map(|q| question.ask(&q)) {
            Ok(Decision::Known(answer)) => return Ok(answer),
            Err(EvalError::Invalid(e)) => return Err(EvalError::Invalid(e)),
            _ => {}
        }
        match self.walk::<Cyclotomic>(env, terms).map(|c| question.ask(&c)) {
            Ok(Decision::Known(answer)) => return Ok(answer),
            Err(EvalError::Invalid(e)) => return Err(EvalError::Invalid(e)),
            _ => {}
        }
        match own {
            // exactly on the discontinuity in this arithmetic, and nothing
            // exact to say otherwise
            Decision::Known(answer) => Ok(answer),
            Decision::Unknown(why) => Err(EvalError::Undecidable(format!(
                "{what} cannot be decided in {}: its argument has no exact value, and {why}",
                F::NAME
            ))),
        }
    }

    /// q such that the expression is q·π (for exact trigonometry).
    fn pi_multiple(&self, env: &Env, terms: &mut u64) -> Option<Rational> {
        let exact = |e: &Expr, terms: &mut u64| e.walk::<Rational>(env, terms).ok();
        match self {
            Expr::Pi => Some(Rational::one()),
            Expr::Neg(a) => Some(-a.pi_multiple(env, terms)?),
            Expr::Bin('*', a, b) => match (a.pi_multiple(env, terms), b.pi_multiple(env, terms)) {
                (Some(p), None) => Some(p * exact(b, terms)?),
                (None, Some(p)) => Some(exact(a, terms)? * p),
                // p π · q π is a multiple of π only when a factor is zero (2 π j at j = 0)
                (Some(p), Some(q)) if p.is_zero() || q.is_zero() => Some(Rational::zero()),
                _ => None,
            },
            Expr::Bin('/', a, b) => Some(a.pi_multiple(env, terms)? / exact(b, terms).filter(|y| !y.is_zero())?),
            Expr::Bin(op @ ('+' | '-'), a, b) => {
                let (x, y) = (a.pi_multiple(env, terms)?, b.pi_multiple(env, terms)?);
                Some(if *op == '+' { x + y } else { x - y })
            }
            Expr::Chain(first, rest) if matches!(rest[0].0, '+' | '-') => {
                let mut x = first.pi_multiple(env, terms)?;
                for (op, e) in rest {
                    let y = e.pi_multiple(env, terms)?;
                    x = if *op == '+' { x + y } else { x - y };
                }
                Some(x)
            }
            Expr::Chain(first, rest) => {
                // a product coef · π^power: a multiple of π when power is 1,
                // or when the coefficient is 0
                let mut coef = Rational::one();
                let mut power = 0u32;
                let factors = std::iter::once(('*', &**first)).chain(rest.iter().map(|(op, e)| (*op, e)));
                let times = |x: Rational, op: char, y: Rational| {
                    <Rational as ExprField>::arith(op, x, y).and_then(<Rational as ExprField>::bounded).ok()
                };
                for (op, e) in factors {
                    match (exact(e, terms), op) {
                        (Some(q), _) => coef = times(coef, op, q)?,
                        (None, '*') => {
                            coef = times(coef, '*', e.pi_multiple(env, terms)?)?;
                            power += 1;
                        }
                        (None, _) => return None,
                    }
                }
                match power {
                    1 => Some(coef),
                    _ if coef.is_zero() => Some(coef),
                    _ => None,
                }
            }
            e => exact(e, terms).filter(|x| x.is_zero()),
        }
    }
}

/// cos(qπ) (`f` = "cos") or sin(qπ) as cos(2πk/n): cos(qπ) = cos(2π·num/(2·den)),
/// sin(x) = cos(x − π/2). None when the integers overflow.
fn cos_angle(f: &str, q: &Rational) -> Option<(i64, i64)> {
    let (num, den) = (q.numer().to_i64()?, q.denom().to_i64()?);
    if f == "cos" {
        Some((num, den.checked_mul(2)?))
    } else {
        Some((num.checked_mul(2)?.checked_sub(den)?, den.checked_mul(4)?))
    }
}

fn token_text(t: &Tok) -> String {
    match t {
        Tok::Num(s) | Tok::Ident(s) => s.clone(),
        Tok::Op(c) => c.to_string(),
    }
}

/// Variable values for evaluation.
pub type Env = BTreeMap<String, super::weight::ParamValue>;

/// An environment from (name, integer) pairs, e.g. the valence.
pub fn env_int(pairs: &[(&str, i64)]) -> Env {
    pairs.iter().map(|(k, v)| (k.to_string(), super::weight::ParamValue::from_ratio(*v, 1))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::exact::q;

    fn ev(s: &str) -> Complex64 {
        Expr::parse(s).unwrap().eval(&env_int(&[("n", 5), ("k", 4)])).unwrap()
    }
    fn ex(s: &str) -> Option<Rational> {
        Expr::parse(s).unwrap().exact(&env_int(&[("n", 6), ("k", 4)]))
    }

    #[test]
    fn precedence_and_signs() {
        assert_eq!(ev("-2^2").re, -4.0);
        assert_eq!(ev("2^3^2").re, 512.0);
        assert_eq!(ev("1 - 2 - 3").re, -4.0);
        assert_eq!(ev("12 / 3 / 2").re, 2.0);
        assert_eq!(ev("2^-1").re, 0.5);
        assert_eq!(ex("3/4 - (1/2 + cos(2 pi / k)/4)^2"), Some(q(1, 2)));
    }

    #[test]
    fn exact_trigonometry() {
        assert_eq!(ex("cos(2*pi/n)"), Some(q(1, 2)));
        assert_eq!(ex("sin(pi/6)"), Some(q(1, 2)));
        assert_eq!(ex("cos(pi)"), Some(q(-1, 1)));
        assert_eq!(ex("cos(2*pi/5)"), None);
        assert_eq!(ex("sqrt(9/16)"), Some(q(3, 4)));
        assert_eq!(ex("sqrt(2)"), None);
    }

    #[test]
    fn exact_powers_stay_bounded() {
        assert_eq!(ex("(1/2)^10"), Some(q(1, 1024)));
        assert!(ex("9^256").is_some());
        // about 2^28 bits: refused rather than computed
        assert_eq!(ex("((9^256)^256)^256"), None);
        // the float value is still there
        assert!(ev("((9^2)^2)^2").re == 43046721.0);
    }

    #[test]
    fn complex_values() {
        let z = ev("-1/16 + sqrt(5)/48 i");
        assert!((z.re + 1.0 / 16.0).abs() < 1e-15 && (z.im - 5f64.sqrt() / 48.0).abs() < 1e-15);
    }

    #[test]
    fn errors_name_the_column() {
        assert!(Expr::parse("1 + * 2").unwrap_err().to_string().contains("column 5"));
        assert!(Expr::parse("cos(1").unwrap_err().to_string().contains("missing ')'"));
        assert!(Expr::parse("cos 1").unwrap_err().to_string().contains("needs an argument"));
        // a variable before parentheses multiplies
        assert_eq!(Expr::parse("n (1 + n)").unwrap().eval(&env_int(&[("n", 3)])).unwrap().re, 12.0);
        assert!(Expr::parse("1 $ 2").unwrap_err().to_string().contains("column 3"));
        assert!(Expr::parse("").is_err());
        assert!(Expr::parse(&"(".repeat(5000)).is_err());
        assert!(Expr::parse("x").unwrap().eval(&Env::new()).unwrap_err().to_string().contains("unknown variable"));
    }

    #[test]
    fn sums_evaluate_exactly_and_in_floating_point() {
        // Σ_{m=1}^{n} m = n(n+1)/2 = 15 at n = 5; Σ_{m=0}^{3} (1/2)^m = 15/8
        assert_eq!(ev("sum(m, 1, n, m)").re, 15.0);
        assert_eq!(ex("sum(m, 0, 3, (1/2)^m)"), Some(q(15, 8)));
        // an empty range sums to zero; a one-term range is the term
        assert_eq!(ex("sum(m, 1, 0, m)"), Some(q(0, 1)));
        assert_eq!(ex("sum(m, 4, 4, 1/m)"), Some(q(1, 4)));
        // Σ_{m=0}^{n-1} cos(2π m j / n) = n δ_{j,0} (mod n): exact at n = 6, float at n = 5
        let at = |n: i64, j: i64| env_int(&[("n", n), ("j", j)]);
        let e = Expr::parse("sum(m, 0, n-1, cos(2 pi j m / n))").unwrap();
        assert_eq!(e.exact(&at(6, 0)), Some(q(6, 1)));
        assert_eq!(e.exact(&at(6, 2)), Some(q(0, 1)));
        assert_eq!(e.exact(&at(5, 1)), None, "cos(2π/5) is irrational, so the sum is not proved exact");
        assert!(e.eval(&at(5, 1)).unwrap().norm() < 1e-14);
        assert!((e.eval(&at(5, 5)).unwrap().re - 5.0).abs() < 1e-14);
        // the brief's Fourier example: s_j = δ_{j,0}/4 + cos(2π j/n)/(2n)
        let f =
            Expr::parse("sum(m, 0, n-1, (1/4 + kronecker(m-1)/4 + kronecker(m-n+1)/4) cos(2 pi j m / n)) / n").unwrap();
        assert_eq!(f.exact(&at(4, 0)), Some(q(1, 4) + q(1, 8)));
        assert_eq!(f.exact(&at(6, 1)), Some(q(1, 24)));
        assert!((f.eval(&at(5, 2)).unwrap().re - (4.0 * std::f64::consts::PI / 5.0).cos() / 10.0).abs() < 1e-15);
        // complex terms sum as complex numbers: Σ_{m=0}^{3} i^m = 0, i^0 + i^1 = 1 + i
        assert!(ev("sum(m, 0, 3, i^m)").norm() < 1e-15);
        let z = ev("sum(m, 0, 1, i^m)");
        assert!((z.re - 1.0).abs() < 1e-15 && (z.im - 1.0).abs() < 1e-15);
        assert_eq!(ex("sum(m, 0, 1, i^m)"), None);
        // nested sums: Σ_{a=1}^{3} Σ_{b=1}^{a} 1 = 6; bounds may use outer variables
        assert_eq!(ex("sum(a, 1, 3, sum(b, 1, a, 1))"), Some(q(6, 1)));
        // bounds are expressions in the free variables; n/2 at n = 6 is 3
        assert_eq!(ex("sum(m, 1, n/2, 1)"), Some(q(3, 1)));
    }

    #[test]
    fn cyclotomic_evaluation_is_exact_where_cosines_are_irrational() {
        use crate::numeric::{cyclotomic_element::Cyclotomic, weight::Weight};
        let at = |n: i64, j: i64| env_int(&[("n", n), ("j", j)]);
        let cy = |s: &str, n: i64, j: i64| Expr::parse(s).unwrap().cyclotomic(&at(n, j));
        let rational = |p: i64, d: i64| Some(Cyclotomic::ratio(p, d));
        // Σ_{m=0}^{n-1} cos(2π m j / n) = n δ_{j,0} (mod n), now exact at n = 5 too
        for j in 0..5 {
            assert_eq!(
                cy("sum(m, 0, n-1, cos(2 pi j m / n))", 5, j),
                rational(if j == 0 { 5 } else { 0 }, 1),
                "j = {j}"
            );
        }
        // Loop's β at n = 5, as the file writes it and as the rule computes it
        let beta = cy("(5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n", 5, 0).unwrap();
        let t = Cyclotomic::ratio(3, 8) + Cyclotomic::cos_2pi(1, 5).unwrap() * Cyclotomic::ratio(1, 4);
        assert_eq!(beta, (Cyclotomic::ratio(5, 8) - t.clone() * t) / Cyclotomic::int(5));
        // sin through cos, i, kronecker decided exactly: cos 72° + cos 144° = −1/2
        assert_eq!(cy("sin(pi / 6)", 5, 0), rational(1, 2));
        assert_eq!(cy("sin(2 pi / 5)^2 + cos(2 pi / 5)^2", 5, 0), rational(1, 1));
        assert_eq!(cy("i^2", 5, 0), rational(-1, 1));
        assert_eq!(cy("kronecker(cos(2 pi / 5) + cos(4 pi / 5) + 1/2)", 5, 0), rational(1, 1));
        assert_eq!(cy("kronecker(cos(2 pi / 5) + cos(4 pi / 5))", 5, 0), rational(0, 1));
        // negative powers through the inverse: (2cos 72°)⁻¹ = 2cos 72° + 1 (the golden ratio)
        let inv = cy("(2 cos(2 pi / 5))^-1", 5, 0).unwrap();
        assert_eq!(Some(inv.clone()), cy("2 cos(2 pi / 5) + 1", 5, 0));
        assert!((inv.to_f64() - 0.5 / (0.4 * std::f64::consts::PI).cos()).abs() < 1e-14);
        // what it cannot prove: π, cube roots, roots of non-squares, division by zero
        for s in ["pi", "cbrt(2)", "sqrt(2)", "sqrt(cos(2 pi / 5))", "1 / (cos(2 pi / 5) + cos(4 pi / 5) + 1/2)"] {
            assert_eq!(cy(s, 5, 0), None, "{s}");
        }
        // whatever `exact` proves rational has the same value
        for s in ["3/8 + (3/8 + cos(2 pi / n) / 4)^2", "kronecker(j)/4 + (3 + 2 cos(2 pi j / n)) / (4 n)"] {
            for (n, j) in [(3, 1), (4, 2), (6, 5)] {
                let e = Expr::parse(s).unwrap();
                assert_eq!(e.cyclotomic(&at(n, j)), e.exact(&at(n, j)).map(|q| Cyclotomic::from_rational(&q)), "{s}");
            }
        }
    }

    #[test]
    fn sum_variables_are_bound() {
        let vars = |s: &str| Expr::parse(s).unwrap().variables();
        assert_eq!(vars("sum(m, 0, n - 1, m j a)"), ["n", "j", "a"]);
        // the bounds are outside the binding: m there is free
        assert_eq!(vars("sum(m, 0, m, m)"), ["m"]);
        // after the sum, m is free again
        assert_eq!(vars("sum(m, 0, 1, m) + m"), ["m"]);
        assert_eq!(vars("sum(a, 0, 2, sum(b, 0, a, b c))"), ["c"]);
    }

    #[test]
    fn sum_errors_are_clear() {
        let err = |s: &str| Expr::parse(s).unwrap_err().to_string();
        assert!(err("sum(1, 2)").contains("the first argument of sum must be a variable name"));
        assert!(err("sum(m, 0, 2)").contains("expected ',' before the expression of sum(variable, from, to"));
        assert!(err("sum(m 0, 2, m)").contains("expected ',' before the from"));
        assert!(err("sum(m, 0, 2, m").contains("missing ')' after sum"));
        assert!(err("sum").contains("'sum' needs arguments"));
        assert!(err("sum m").contains("'sum' needs arguments"));
        assert!(err("sum(pi, 0, 2, 1)").contains("'pi' cannot be a sum variable"));
        assert!(err("sum(sum, 0, 2, 1)").contains("'sum' cannot be a sum variable"));
        assert!(err("sum(m, 0, 2, sum(m, 0, 1, m))").contains("'m' is already bound by an enclosing sum"));
        assert!(err("sum(m, 0, , m)").contains("unexpected ','"));
        assert!(err("1, 2").contains("unexpected ',' at column 2"));
        assert!(err("cos(1, 2)").contains("missing ')'"));
        // evaluation errors: bounds, shadowing, size
        let env = env_int(&[("n", 5), ("k", 4)]);
        let run = |s: &str| Expr::parse(s).unwrap().eval(&env).unwrap_err().to_string();
        assert!(run("sum(m, 0, n/2, m)").contains("the upper bound of a sum must be an integer, got 2.5"));
        assert!(run("sum(m, i, 2, m)").contains("the lower bound of a sum must be an integer"));
        assert!(run("sum(m, 0, 1e300, m)").contains("must be an integer"));
        assert!(run("sum(n, 0, 2, n)").contains("sum variable 'n' is already a variable here"));
        assert!(run("sum(m, 1, 10001, m)").contains("a sum of 10001 terms; at most 10000 terms in all"));
        assert!(run("sum(m, 1, 10^12, m)").contains("at most 10000 terms"));
        // nested sums count every term: 200 × 100 = 20000 > 10000, refused quickly
        let t0 = std::time::Instant::now();
        assert!(run("sum(a, 1, 200, sum(b, 1, 100, a b))").contains("at most 10000 terms in all"));
        assert_eq!(Expr::parse("sum(m, 1, 10000, 1)").unwrap().eval(&env).unwrap().re, 10000.0);
        assert!(t0.elapsed().as_secs() < 2);
        // exactly 10000 terms are allowed; the exact path declines what eval refuses
        assert_eq!(ex("sum(m, 1, 10000, 1)"), Some(q(10000, 1)));
        assert_eq!(ex("sum(m, 1, 10001, 1)"), None);
        assert_eq!(ex("sum(n, 1, 2, 1)"), None);
        // a sum whose exact value would need huge numbers is declined, not computed
        assert_eq!(ex("sum(m, 1, 2000, (1/m)^256)"), None);
    }
}
