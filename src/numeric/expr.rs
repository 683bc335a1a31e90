//! A small expression language for claims and scheme files, evaluated both in
//! floating point (complex, so that printed eigenvalues such as
//! −1/16 ± √5/48 i can be written down) and exactly (rationals; cos and sin of
//! rational multiples of π where the value is rational; square roots of
//! rational squares).
//!
//! Grammar: sums and differences of products and quotients of powers of unary
//! terms; `^` binds tighter than unary minus (−2^2 = −4), and is
//! right-associative. Atoms: numbers (`3`, `0.375`, `1e-3`), variables, `pi`,
//! `i` (the imaginary unit), calls `cos(x)`, `sin(x)`, `sqrt(x)`, `cbrt(x)`,
//! `abs(x)`, `kronecker(x)` (1 when x = 0, else 0: piecewise definitions such
//! as a_3 = 3/4), and parentheses. Errors name the column.

use std::collections::BTreeMap;

use num_complex::Complex64;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::weight::{exact_cos_2pi, Rational};

#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    Num(f64, Option<Rational>),
    Var(String),
    Pi,
    I,
    Neg(Box<Expr>),
    Bin(char, Box<Expr>, Box<Expr>),
    Call(String, Box<Expr>),
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(String),
    Ident(String),
    Op(char),
}

fn tokenize(s: &str) -> Result<Vec<(usize, Tok)>, String> {
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
        } else if "+-*/^()".contains(c) {
            out.push((k, Tok::Op(c)));
            k += 1;
        } else {
            return Err(format!("unexpected character '{c}' at column {}", k + 1));
        }
    }
    Ok(out)
}

struct Parser {
    toks: Vec<(usize, Tok)>,
    pos: usize,
    len: usize,
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
    fn sum(&mut self, depth: usize) -> Result<Expr, String> {
        let mut e = self.product(depth)?;
        loop {
            let op = match self.peek() {
                Some(Tok::Op(c)) if *c == '+' || *c == '-' => *c,
                _ => return Ok(e),
            };
            self.pos += 1;
            e = Expr::Bin(op, Box::new(e), Box::new(self.product(depth)?));
        }
    }
    fn product(&mut self, depth: usize) -> Result<Expr, String> {
        let mut e = self.unary(depth)?;
        loop {
            let op = match self.peek() {
                Some(Tok::Op(c)) if *c == '*' || *c == '/' => *c,
                // implicit multiplication: `2 pi`, `3 cos(x)`, `4a`
                Some(Tok::Num(_)) | Some(Tok::Ident(_)) | Some(Tok::Op('(')) => '*',
                _ => return Ok(e),
            };
            if op != '*' || matches!(self.peek(), Some(Tok::Op('*'))) {
                self.pos += 1;
            }
            e = Expr::Bin(op, Box::new(e), Box::new(self.unary(depth)?));
        }
    }
    fn unary(&mut self, depth: usize) -> Result<Expr, String> {
        if depth > 200 {
            return Err("expression nested too deeply".into());
        }
        if self.eat('-') {
            return Ok(Expr::Neg(Box::new(self.unary(depth + 1)?)));
        }
        if self.eat('+') {
            return self.unary(depth + 1);
        }
        self.power(depth)
    }
    fn power(&mut self, depth: usize) -> Result<Expr, String> {
        let base = self.atom(depth)?;
        if self.eat('^') {
            let exp = self.unary(depth + 1)?; // right-associative; allows 2^-1
            return Ok(Expr::Bin('^', Box::new(base), Box::new(exp)));
        }
        Ok(base)
    }
    fn atom(&mut self, depth: usize) -> Result<Expr, String> {
        let col = self.col();
        match self.toks.get(self.pos).map(|t| t.1.clone()) {
            Some(Tok::Num(t)) => {
                self.pos += 1;
                let p = super::weight::ParamValue::parse(&t).map_err(|e| format!("column {col}: {e}"))?;
                Ok(Expr::Num(p.value, p.exact))
            }
            Some(Tok::Ident(name)) => {
                self.pos += 1;
                const FUNCTIONS: [&str; 6] = ["cos", "sin", "sqrt", "cbrt", "abs", "kronecker"];
                if FUNCTIONS.contains(&name.as_str()) {
                    if !self.eat('(') {
                        return Err(format!("'{name}' needs an argument in parentheses at column {}", self.col()));
                    }
                    let arg = self.sum(depth + 1)?;
                    if !self.eat(')') {
                        return Err(format!("missing ')' at column {}", self.col()));
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
                    return Err(format!("missing ')' at column {}", self.col()));
                }
                Ok(e)
            }
            Some(Tok::Op(c)) => Err(format!("unexpected '{c}' at column {col}")),
            None => Err(format!("unexpected end of expression at column {col}")),
        }
    }
}

impl Expr {
    pub fn parse(s: &str) -> Result<Expr, String> {
        if s.len() > 10_000 {
            return Err("expression longer than 10000 characters".into());
        }
        let toks = tokenize(s)?;
        let mut p = Parser { toks, pos: 0, len: s.chars().count() };
        let e = p.sum(0)?;
        if p.pos != p.toks.len() {
            return Err(format!("unexpected '{}' at column {}", token_text(&p.toks[p.pos].1), p.col()));
        }
        Ok(e)
    }

    /// Variables the expression uses.
    pub fn variables(&self) -> Vec<String> {
        let mut out = Vec::new();
        self.walk(&mut |e| {
            if let Expr::Var(v) = e {
                if !out.contains(v) {
                    out.push(v.clone());
                }
            }
        });
        out
    }

    fn walk(&self, f: &mut dyn FnMut(&Expr)) {
        f(self);
        match self {
            Expr::Neg(a) | Expr::Call(_, a) => a.walk(f),
            Expr::Bin(_, a, b) => {
                a.walk(f);
                b.walk(f);
            }
            _ => {}
        }
    }

    /// Floating-point (complex) value.
    pub fn eval(&self, env: &Env) -> Result<Complex64, String> {
        Ok(match self {
            Expr::Num(x, _) => Complex64::new(*x, 0.0),
            Expr::Pi => Complex64::new(std::f64::consts::PI, 0.0),
            Expr::I => Complex64::new(0.0, 1.0),
            Expr::Var(v) => Complex64::new(env.get(v).ok_or_else(|| format!("unknown variable '{v}'"))?.value, 0.0),
            Expr::Neg(a) => -a.eval(env)?,
            Expr::Bin(op, a, b) => {
                let (x, y) = (a.eval(env)?, b.eval(env)?);
                match op {
                    '+' => x + y,
                    '-' => x - y,
                    '*' => x * y,
                    '/' => {
                        if y.norm() == 0.0 {
                            return Err("division by zero".into());
                        }
                        x / y
                    }
                    _ => {
                        if y.im == 0.0 && y.re.fract() == 0.0 && y.re.abs() <= 64.0 {
                            x.powi(y.re as i32)
                        } else {
                            x.powc(y)
                        }
                    }
                }
            }
            Expr::Call(f, a) => {
                let x = a.eval(env)?;
                match f.as_str() {
                    "cos" => x.cos(),
                    "sin" => x.sin(),
                    "sqrt" => x.sqrt(),
                    "cbrt" if x.im == 0.0 => Complex64::new(x.re.cbrt(), 0.0),
                    "cbrt" => x.powf(1.0 / 3.0),
                    "kronecker" => Complex64::new(if x.norm() < 1e-12 { 1.0 } else { 0.0 }, 0.0),
                    _ => Complex64::new(x.norm(), 0.0),
                }
            }
        })
    }

    /// Exact rational value, when the expression has one this evaluator can
    /// prove (None otherwise: irrational, complex, or undecidable here).
    pub fn exact(&self, env: &Env) -> Option<Rational> {
        Some(match self {
            Expr::Num(_, q) => q.clone()?,
            Expr::Var(v) => env.get(v)?.exact.clone()?,
            Expr::Neg(a) => -a.exact(env)?,
            Expr::Bin(op, a, b) => {
                let (x, y) = (a.exact(env)?, b.exact(env)?);
                match op {
                    '+' => x + y,
                    '-' => x - y,
                    '*' => x * y,
                    '/' => {
                        if y.is_zero() {
                            return None;
                        }
                        x / y
                    }
                    _ => {
                        if !y.is_integer() || y.abs() > Rational::from_integer(256.into()) {
                            return None;
                        }
                        let k = y.to_integer().to_i32()?;
                        if k < 0 && x.is_zero() {
                            return None;
                        }
                        // nested powers ((9^256)^256)^256 would need gigabytes of
                        // digits: past a million bits the value is not worth it
                        let bits = x.numer().bits() + x.denom().bits();
                        if bits.saturating_mul(k.unsigned_abs() as u64) > 1 << 20 {
                            return None;
                        }
                        num_traits::pow::Pow::pow(x, k)
                    }
                }
            }
            Expr::Call(f, a) => match f.as_str() {
                // cos(q π) and sin(q π) for rational q
                "cos" | "sin" => {
                    let q = a.pi_multiple(env)?;
                    let (num, den) = (q.numer().to_i64()?, q.denom().to_i64()?);
                    // cos(qπ) = cos(2π · num / (2 den)); sin(x) = cos(x − π/2)
                    let (k, n) = if f == "cos" { (num, 2 * den) } else { (num * 2 - den, 4 * den) };
                    exact_cos_2pi(k, n)?
                }
                "sqrt" => {
                    let x = a.exact(env)?;
                    use super::weight::Weight;
                    x.sqrt().ok()?
                }
                "abs" => a.exact(env)?.abs(),
                "kronecker" => {
                    if a.exact(env)?.is_zero() {
                        Rational::one()
                    } else {
                        Rational::zero()
                    }
                }
                _ => return None,
            },
            Expr::Pi | Expr::I => return None,
        })
    }

    /// q such that the expression is q·π (for exact trigonometry).
    fn pi_multiple(&self, env: &Env) -> Option<Rational> {
        match self {
            Expr::Pi => Some(Rational::one()),
            Expr::Neg(a) => Some(-a.pi_multiple(env)?),
            Expr::Bin('*', a, b) => match (a.pi_multiple(env), b.pi_multiple(env)) {
                (Some(p), None) => Some(p * b.exact(env)?),
                (None, Some(p)) => Some(a.exact(env)? * p),
                _ => None,
            },
            Expr::Bin('/', a, b) => Some(a.pi_multiple(env)? / b.exact(env).filter(|y| !y.is_zero())?),
            Expr::Bin(op @ ('+' | '-'), a, b) => {
                let (x, y) = (a.pi_multiple(env)?, b.pi_multiple(env)?);
                Some(if *op == '+' { x + y } else { x - y })
            }
            e => e.exact(env).filter(|x| x.is_zero()),
        }
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
        assert!(Expr::parse("1 + * 2").unwrap_err().contains("column 5"));
        assert!(Expr::parse("cos(1").unwrap_err().contains("missing ')'"));
        assert!(Expr::parse("cos 1").unwrap_err().contains("needs an argument"));
        // a variable before parentheses multiplies
        assert_eq!(Expr::parse("n (1 + n)").unwrap().eval(&env_int(&[("n", 3)])).unwrap().re, 12.0);
        assert!(Expr::parse("1 $ 2").unwrap_err().contains("column 3"));
        assert!(Expr::parse("").is_err());
        assert!(Expr::parse(&"(".repeat(5000)).is_err());
        assert!(Expr::parse("x").unwrap().eval(&Env::new()).unwrap_err().contains("unknown variable"));
    }
}
