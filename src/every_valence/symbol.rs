//! A row whose weights depend on n (face-centred schemes: the centre face's
//! own rule, e.g. Doo–Sabin's α_j(n)) enters the Fourier blocks through the
//! discrete Fourier transform of its weights, its *symbol*
//! σ(k, n) = Σ_{j=0}^{n−1} w(j, n) ω^{kj}, ω = e^{2πi/n}.
//!
//! The weight is read from the scheme file as a trigonometric polynomial in
//! the slot's position j of bounded degree M:
//!
//!   w(j, n) = d(n) δ_{j,0} + Σ_{m=0}^{M} A_m(n) cos(2πmj/n),
//!
//! (`kronecker(j)` is δ_{j,0}; products of cosines are expanded by
//! cos a cos b = (cos(a+b) + cos(a−b))/2; d and A_m are expressions in n
//! alone, `centre::InN`). Its transform is exact for every n:
//! Σ_j cos(2πmj/n) ω^{kj} = (n/2)([k ≡ m] + [k ≡ −m]) (mod n), so
//!
//!   σ(k, n) = d(n) + Σ_m (n/2) A_m(n) ([k ≡ m] + [k ≡ −m]).
//!
//! For n > 2M the blocks split in two kinds: the *generic* blocks
//! M < k < n − M, where σ = d(n) (required constant: the block is then the
//! same Laurent polynomial in ω as the other rows', `laurent`), and the
//! *special* blocks k ∈ {0, ±1, ..., ±M}, where σ = d + e_k(n) with
//! e_0 = n A_0 and e_m = (n/2) A_m (required polynomials in c = cos(2π/n)).
//! The reading is checked against the actual row's transform at every block
//! of the two probe valences (`matches_row`).

use std::collections::BTreeMap;

use num_traits::{One, Zero};

use super::centre::{symbolic, InN};
use crate::numeric::expr::{Env, Expr};
use crate::numeric::{Cyclotomic, Rational};

/// One term's dependence on the position j.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Freq {
    /// δ_{j,0}
    Delta,
    /// cos(2πmj/n) (m = 0: constant in j)
    Cos(u32),
}

/// Σ coefficient(n) · term(j).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct TrigInJ(pub BTreeMap<Freq, InN>);

impl TrigInJ {
    fn single(f: Freq, c: InN) -> TrigInJ {
        let mut m = BTreeMap::new();
        m.insert(f, c);
        TrigInJ(m)
    }
    fn add(&self, o: &TrigInJ, sign: i64) -> TrigInJ {
        let mut m = self.0.clone();
        for (f, c) in &o.0 {
            let e = m.remove(f).unwrap_or_default().add(c, sign);
            if e != InN::default() {
                m.insert(*f, e);
            }
        }
        TrigInJ(m)
    }
    fn mul(&self, o: &TrigInJ) -> TrigInJ {
        let half = InN::constant(Rational::new(1.into(), 2.into()));
        let mut out = TrigInJ::default();
        for (f, x) in &self.0 {
            for (g, y) in &o.0 {
                let xy = x.mul(y);
                let terms: Vec<(Freq, InN)> = match (*f, *g) {
                    // δ_j times anything is δ_j times its value at j = 0 (cos 0 = 1)
                    (Freq::Delta, _) | (_, Freq::Delta) => vec![(Freq::Delta, xy)],
                    (Freq::Cos(a), Freq::Cos(b)) => {
                        let h = xy.mul(&half);
                        vec![(Freq::Cos(a + b), h.clone()), (Freq::Cos(a.abs_diff(b)), h)]
                    }
                };
                for (k, v) in terms {
                    out = out.add(&TrigInJ::single(k, v), 1);
                }
            }
        }
        out
    }
    /// The largest frequency M.
    pub fn degree(&self) -> u32 {
        self.0.keys().map(|f| if let Freq::Cos(m) = f { *m } else { 0 }).max().unwrap_or(0)
    }
    fn coefficient(&self, f: Freq) -> InN {
        self.0.get(&f).cloned().unwrap_or_default()
    }
    /// d(n): the symbol at the generic blocks (M < k < n − M).
    pub fn generic(&self) -> InN {
        self.coefficient(Freq::Delta)
    }
    /// e_m(n): what block m (0 ≤ m ≤ M, n > 2M) adds to d: n A_0 for m = 0,
    /// (n/2) A_m otherwise.
    pub fn correction(&self, m: u32) -> InN {
        let a = self.coefficient(Freq::Cos(m)).mul_n();
        if m == 0 {
            a
        } else {
            a.mul(&InN::constant(Rational::new(1.into(), 2.into())))
        }
    }
    /// σ(k, n) from the formula, exact at valence n.
    pub fn symbol_at(&self, n: i64, k: i64) -> Option<Cyclotomic> {
        let mut s = self.generic().at(n)?;
        for (f, a) in &self.0 {
            if let Freq::Cos(m) = f {
                let m = *m as i64;
                let hits = i64::from((k - m).rem_euclid(n) == 0) + i64::from((k + m).rem_euclid(n) == 0);
                if hits > 0 {
                    let factor = Rational::new((n * hits).into(), 2.into());
                    s = s + a.at(n)? * Cyclotomic::from_rational(&factor);
                }
            }
        }
        Some(s)
    }
}

/// Whether the formula's σ(k, n) is the transform Σ_τ w_τ ω^{kτ} of the
/// actual weights w_τ (τ = 0..n−1, one per sector) at every k = 0..n−1.
pub fn matches_row(sym: &TrigInJ, n: usize, weights: &[Cyclotomic]) -> bool {
    let n = n as i64;
    (0..n).all(|k| {
        let mut actual = <Cyclotomic as crate::numeric::Weight>::zero();
        for (tau, w) in weights.iter().enumerate() {
            let Ok(z) = Cyclotomic::root_of_unity(k * tau as i64, n) else { return false };
            actual = actual + w.clone() * z;
        }
        sym.symbol_at(n, k).as_ref() == Some(&actual)
    })
}

fn mentions_j(e: &Expr) -> bool {
    e.variables().iter().any(|v| v == "j")
}

/// A weight expression in n and j as a trigonometric polynomial in j, or why
/// not. Subexpressions free of j are expressions in n alone (`symbolic`).
pub fn trig_in_j(e: &Expr, env: &Env) -> Result<TrigInJ, String> {
    if !mentions_j(e) {
        return Ok(TrigInJ::single(Freq::Cos(0), symbolic(e, env)?));
    }
    let go = |x: &Expr| trig_in_j(x, env);
    Ok(match e {
        Expr::Neg(a) => TrigInJ::default().add(&go(a)?, -1),
        Expr::Bin(op, a, b) => arith(*op, go(a)?, b, env)?,
        Expr::Chain(first, rest) => {
            let mut x = go(first)?;
            for (op, y) in rest {
                x = arith(*op, x, y, env)?;
            }
            x
        }
        Expr::Call(f, a) if f == "cos" => {
            let m = frequency(a, env).ok_or("a cosine of an angle other than 2πmj/n in a weight that depends on j")?;
            TrigInJ::single(Freq::Cos(m), InN::constant(Rational::one()))
        }
        Expr::Call(f, a) if f == "kronecker" => {
            if !matches!(a.as_ref(), Expr::Var(v) if v == "j") {
                return Err("a kronecker of something other than j in a weight that depends on j".into());
            }
            TrigInJ::single(Freq::Delta, InN::constant(Rational::one()))
        }
        Expr::Var(_) => return Err("j outside a cosine or kronecker(j) in a weight".into()),
        _ => return Err("a weight's dependence on j is not a cosine polynomial (sum, sin, powers of j, ...)".into()),
    })
}

/// x op y, y read on its own: + and − of two trigonometric polynomials, ×
/// of two, / and ^ only by something free of j.
fn arith(op: char, x: TrigInJ, y: &Expr, env: &Env) -> Result<TrigInJ, String> {
    Ok(match op {
        '+' => x.add(&trig_in_j(y, env)?, 1),
        '-' => x.add(&trig_in_j(y, env)?, -1),
        '*' => x.mul(&trig_in_j(y, env)?),
        '/' if !mentions_j(y) => {
            let inv = symbolic(y, env)?.inverse().ok_or("a division by more than a power of n in a weight")?;
            x.mul(&TrigInJ::single(Freq::Cos(0), inv))
        }
        '^' if !mentions_j(y) => {
            let e = symbolic(y, env)?.as_rational().filter(|e| e.is_integer() && *e > Rational::zero());
            let e = e.ok_or("a power of a term in j that is not a positive integer")?;
            let e: u32 = e.to_integer().try_into().map_err(|_| "a power too large")?;
            (1..e).fold(x.clone(), |acc, _| acc.mul(&x))
        }
        _ => return Err(format!("the operator {op} applied to a term in j")),
    })
}

/// m ≥ 0 when the angle is exactly ±2πmj/n.
fn frequency(angle: &Expr, env: &Env) -> Option<u32> {
    let (slope, offset) = linear_in_j(angle, env)?;
    if offset != InN::default() {
        return None;
    }
    // slope = q·π/n: n·slope = q·π, and m = q/2 must be an integer
    let m = slope.mul_n().multiple_of_pi()? / Rational::from_integer(2.into());
    if !m.is_integer() {
        return None;
    }
    let m: i64 = m.to_integer().try_into().ok()?;
    u32::try_from(m.unsigned_abs()).ok()
}

/// (a, b) with the expression = a·j + b, a and b expressions in n alone
/// (read structurally: a product has at most one factor with j, a divisor
/// none), or None.
fn linear_in_j(e: &Expr, env: &Env) -> Option<(InN, InN)> {
    if !mentions_j(e) {
        return Some((InN::default(), symbolic(e, env).ok()?));
    }
    let combine = |x: (InN, InN), op: char, y: &Expr| -> Option<(InN, InN)> {
        match op {
            '+' | '-' => {
                let y = linear_in_j(y, env)?;
                let s = if op == '+' { 1 } else { -1 };
                Some((x.0.add(&y.0, s), x.1.add(&y.1, s)))
            }
            '*' => {
                let y = linear_in_j(y, env)?;
                if x.0 != InN::default() && y.0 != InN::default() {
                    return None;
                }
                Some((x.0.mul(&y.1).add(&y.0.mul(&x.1), 1), x.1.mul(&y.1)))
            }
            '/' if !mentions_j(y) => {
                let inv = symbolic(y, env).ok()?.inverse()?;
                Some((x.0.mul(&inv), x.1.mul(&inv)))
            }
            _ => None,
        }
    };
    match e {
        Expr::Var(v) if v == "j" => Some((InN::constant(Rational::one()), InN::default())),
        Expr::Neg(a) => {
            let (p, q) = linear_in_j(a, env)?;
            Some((InN::default().add(&p, -1), InN::default().add(&q, -1)))
        }
        Expr::Bin(op, a, b) => combine(linear_in_j(a, env)?, *op, b),
        Expr::Chain(first, rest) => {
            let mut x = linear_in_j(first, env)?;
            for (op, y) in rest {
                x = combine(x, *op, y)?;
            }
            Some(x)
        }
        _ => None,
    }
}
