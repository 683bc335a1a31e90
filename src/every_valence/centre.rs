//! Block 0 for every valence n ≥ N: the centre's row is the only one that
//! depends on n there.
//!
//! Block 0 is [[a, rᵀ], [v, M]]: the centre's row (its own weight a and its
//! totals r_b over the orbits b away from the centre), the centre's column v
//! of the other rows and M = B(1), both independent of n (`laurent`). Rows
//! sum to 1 (a + Σr = 1, v + M1 = 1), so with T = [[1, 0], [1, I]]
//! T⁻¹ B_0 T = [[1, rᵀ], [0, M − 1rᵀ]]: the eigenvalues of block 0 other
//! than λ0 = 1 are those of M − 1rᵀ, q(x) = det(xI − M + 1rᵀ).
//!
//! r(n) is read from the scheme file: the fields the centre's rule reads at
//! n (`probe`), each an expression in n alone, evaluated symbolically here as
//! a Laurent polynomial in n with coefficients polynomial in c = cos(2π/n)
//! (cos(2πk/n) = T_k(c)); the number of the field's slots on each orbit is
//! counted by assembling the centre's row with that field weighing 1 and
//! every other 0 (`probe::watch_indicator`), n per sector at every valence
//! (the centre's fan has n identical sectors; the count per sector is
//! checked equal at two valences). Covered: r a polynomial in one variable
//! t — h = 1/n ∈ [0, 1/N] (Catmull–Clark) or c ∈ [q_N, 1] (Loop).
//!
//! Decision, exactly (`decide`): every root of q(·, t) is real and of
//! modulus below μ̃(t) ≤ λ1 for every t of the range, μ̃ the top root of
//! P(·, c) at c = t (Loop: the same c as block 1's) or at c = γ(h) =
//! 1 − 2(355/113)²h² ≤ cos(2πh) (Catmull–Clark: μ increases, `tail`, so
//! μ(γ(1/n)) ≤ λ1(n); both tend to μ(1) as n → ∞, so no fixed radius
//! separates them). Roots leave the real line only through a double root
//! and meet ±μ̃ only at a common root of q(x) and P̃(±x): the subresultants
//! of those pairs have their real roots outside the range once N is large
//! enough (the end n = ∞ excluded), and one point of the range decides.

use std::collections::BTreeMap;

use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::numeric::berkowitz::charpoly;
use crate::numeric::expr::{Env, Expr};
use crate::numeric::sturm;
use crate::numeric::{Cyclotomic, Rational, TPoly};

type W = Cyclotomic;
use crate::sweep::exact::{all_real, first_subresultant, rational_norm, BiPoly};

use super::laurent::chebyshev;
use super::tail::at;
use crate::numeric::sturm::{compare, negated, real_roots};

/// A Laurent polynomial in n with coefficients in Q[c, π]: (power of n,
/// power of c, power of π) ↦ coefficient. π appears only inside angles.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct InN(BTreeMap<(i32, u32, u32), Rational>);

impl InN {
    pub(super) fn constant(q: Rational) -> InN {
        InN::term(q, (0, 0, 0))
    }
    pub(super) fn term(q: Rational, key: (i32, u32, u32)) -> InN {
        let mut m = BTreeMap::new();
        if !q.is_zero() {
            m.insert(key, q);
        }
        InN(m)
    }
    pub(super) fn add(&self, o: &InN, sign: i64) -> InN {
        let mut m = self.0.clone();
        for (k, v) in &o.0 {
            let e = m.remove(k).unwrap_or_else(Rational::zero) + v * Rational::from_integer(sign.into());
            if !e.is_zero() {
                m.insert(*k, e);
            }
        }
        InN(m)
    }
    pub(super) fn mul(&self, o: &InN) -> InN {
        let mut out = InN::default();
        for (a, x) in &self.0 {
            for (b, y) in &o.0 {
                out = out.add(&InN::term(x * y, (a.0 + b.0, a.1 + b.1, a.2 + b.2)), 1);
            }
        }
        out
    }
    /// n times this.
    pub fn mul_n(&self) -> InN {
        InN(self.0.iter().map(|(k, v)| ((k.0 + 1, k.1, k.2), v.clone())).collect())
    }
    /// self + s·o.
    pub fn add_scaled(&self, o: &InN, s: &Rational) -> InN {
        self.add(&o.mul(&InN::constant(s.clone())), 1)
    }
    /// The inverse of a single term without c or π (a rational times a power of n).
    pub(super) fn inverse(&self) -> Option<InN> {
        let (&(e, c, p), q) = self.0.iter().next()?;
        (self.0.len() == 1 && c == 0 && p == 0).then(|| InN::term(q.recip(), (-e, 0, 0)))
    }
    pub(super) fn as_rational(&self) -> Option<Rational> {
        match self.0.len() {
            0 => Some(Rational::zero()),
            1 => self.0.get(&(0, 0, 0)).cloned(),
            _ => None,
        }
    }
    /// As a polynomial in c alone (coefficients lowest first): no power of
    /// n and no π, else None.
    pub(super) fn polynomial_in_c(&self) -> Option<Vec<Rational>> {
        if self.0.keys().any(|k| k.0 != 0 || k.2 != 0) {
            return None;
        }
        let mut p = vec![Rational::zero(); self.0.keys().map(|k| k.1 as usize + 1).max().unwrap_or(1)];
        for (k, v) in &self.0 {
            p[k.1 as usize] = v.clone();
        }
        Some(p)
    }
    /// q when this is exactly q·π.
    pub(super) fn multiple_of_pi(&self) -> Option<Rational> {
        match (self.0.len(), self.0.iter().next()) {
            (1, Some((&(0, 0, 1), q))) => Some(q.clone()),
            _ => None,
        }
    }
    /// The value at valence n (c = cos 2π/n exactly), when free of π.
    pub fn at(&self, n: i64) -> Option<Cyclotomic> {
        let c = Cyclotomic::root_of_unity(1, n).ok()?;
        let c = (c.clone() + c.conj()) * Cyclotomic::from_rational(&Rational::new(1.into(), 2.into()));
        let mut s = <W as crate::numeric::Weight>::zero();
        for (&(e, k, p), q) in &self.0 {
            if p != 0 {
                return None;
            }
            let nn = Rational::from_integer(n.into());
            let pow_n =
                if e >= 0 { num_traits::pow(nn, e as usize) } else { num_traits::pow(nn, (-e) as usize).recip() };
            let mut term = Cyclotomic::from_rational(&(q * pow_n));
            for _ in 0..k {
                term = term * c.clone();
            }
            s = s + term;
        }
        Some(s)
    }
}

/// An expression in n (no other variable) as an `InN`, or why not.
pub fn symbolic(e: &Expr, env: &Env) -> Result<InN, String> {
    // `env` (the parameters' values) is passed down but not read: a centre
    // weight with a parameter is refused (its value might come from n)
    let go = |x: &Expr| symbolic(x, env);
    Ok(match e {
        Expr::Num(_, Some(q)) => InN::constant(q.clone()),
        Expr::Num(x, None) => return Err(format!("the number {x} is not exact")),
        Expr::Var(v) if v == "n" => InN::term(Rational::one(), (1, 0, 0)),
        Expr::Var(v) => return Err(format!("the centre's weights use '{v}' (only n is followed)")),
        Expr::Pi => InN::term(Rational::one(), (0, 0, 1)),
        Expr::I => return Err("the centre's weights use i".into()),
        Expr::Neg(a) => InN::default().add(&go(a)?, -1),
        Expr::Bin(op, a, b) => arith(*op, go(a)?, go(b)?)?,
        Expr::Chain(first, rest) => {
            let mut x = go(first)?;
            for (op, y) in rest {
                x = arith(*op, x, go(y)?)?;
            }
            x
        }
        Expr::Call(f, a) if f == "cos" => {
            // cos(2πk/n) = T_k(c); an angle of another form is not followed
            let angle = go(a)?;
            let q = match (angle.0.len(), angle.0.iter().next()) {
                (1, Some((&(-1, 0, 1), q))) => q.clone(),
                _ => return Err("a cosine of an angle other than 2πk/n in the centre's weights".into()),
            };
            let k = q / Rational::from_integer(2.into());
            if !k.is_integer() {
                return Err("a cosine of an angle other than 2πk/n in the centre's weights".into());
            }
            let k = k.to_integer().abs().to_usize().ok_or("an angle too large")?;
            let t = chebyshev(k).pop().expect("T_k");
            let mut out = InN::default();
            for (i, x) in t.iter().enumerate() {
                out = out.add(&InN::term(x.clone(), (0, i as u32, 0)), 1);
            }
            out
        }
        Expr::Call(f, _) => return Err(format!("the function {f} in the centre's weights is not followed")),
        Expr::Sum(..) => return Err("a sum in the centre's weights is not followed".into()),
    })
}

fn arith(op: char, x: InN, y: InN) -> Result<InN, String> {
    Ok(match op {
        '+' => x.add(&y, 1),
        '-' => x.add(&y, -1),
        '*' => x.mul(&y),
        '/' => x.mul(&y.inverse().ok_or("a division by more than a power of n in the centre's weights")?),
        '^' => {
            let e = y.as_rational().filter(|e| e.is_integer()).ok_or("a power that is not an integer")?;
            let e = e.to_integer().to_i64().ok_or("a power too large")?;
            let base = if e < 0 { x.inverse().ok_or("a negative power of more than a power of n")? } else { x };
            (0..e.unsigned_abs()).fold(InN::constant(Rational::one()), |acc, _| acc.mul(&base))
        }
        _ => return Err(format!("the operator {op} in the centre's weights")),
    })
}

/// Which one variable the centre's totals are polynomials in.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Variable {
    /// h = 1/n ∈ [0, 1/N]
    InverseValence,
    /// c = cos(2π/n) ∈ [q_N, 1]
    Cosine,
}

/// r_b as polynomials in one variable (coefficients lowest first).
pub fn one_variable(r: &[InN]) -> Result<(Variable, Vec<Vec<Rational>>), String> {
    let has_c = r.iter().any(|x| x.0.keys().any(|k| k.1 > 0));
    let has_n = r.iter().any(|x| x.0.keys().any(|k| k.0 != 0));
    if r.iter().any(|x| x.0.keys().any(|k| k.2 > 0)) {
        return Err("π outside an angle in the centre's weights".into());
    }
    match (has_n, has_c) {
        (true, true) => Err("the centre's totals depend on n both through 1/n and through cos(2π/n)".into()),
        (true, false) => {
            if r.iter().any(|x| x.0.keys().any(|k| k.0 > 0)) {
                return Err("the centre's totals grow with n".into());
            }
            let poly = |x: &InN| {
                let mut p = vec![Rational::zero(); x.0.keys().map(|k| (-k.0) as usize + 1).max().unwrap_or(1)];
                for (k, v) in &x.0 {
                    p[(-k.0) as usize] = v.clone();
                }
                p
            };
            Ok((Variable::InverseValence, r.iter().map(poly).collect()))
        }
        (false, _) => {
            let poly = |x: &InN| {
                let mut p = vec![Rational::zero(); x.0.keys().map(|k| k.1 as usize + 1).max().unwrap_or(1)];
                for (k, v) in &x.0 {
                    p[k.1 as usize] = v.clone();
                }
                p
            };
            Ok((Variable::Cosine, r.iter().map(poly).collect()))
        }
    }
}

fn tpoly(p: &[Rational]) -> TPoly {
    TPoly::from_coeffs(p.iter().map(Cyclotomic::from_rational).collect())
}

/// q(x, t) = det(xI − M + 1 r(t)ᵀ).
pub fn block0_poly(m: &[Vec<Rational>], r: &[Vec<Rational>]) -> BiPoly {
    let d = m.len();
    let a: Vec<Vec<TPoly>> =
        (0..d).map(|i| (0..d).map(|j| tpoly(&[m[i][j].clone()]) - tpoly(&r[j])).collect()).collect();
    charpoly(&a)
}

/// The eigenvalues of a whole block 0 other than λ0 = 1: det(xI − B_0(t))
/// divided by (x − 1), B_0 given entry by entry (row-major, `size`²
/// polynomials in t); an error when 1 is not an eigenvalue for every t.
pub fn block0_without_one(entries: &[Vec<Rational>], size: usize) -> Result<BiPoly, String> {
    let a: Vec<Vec<TPoly>> = (0..size).map(|i| (0..size).map(|j| tpoly(&entries[i * size + j])).collect()).collect();
    let full = charpoly(&a);
    // synthetic division by (x − 1), coefficients lowest power first
    let d = full.len() - 1;
    let mut quotient = vec![tpoly(&[Rational::zero()]); d];
    let mut carry = tpoly(&[Rational::zero()]);
    for i in (1..=d).rev() {
        carry = carry + full[i].clone();
        quotient[i - 1] = carry.clone();
    }
    let remainder = carry + full[0].clone();
    if !<TPoly as crate::numeric::Weight>::is_zero(&remainder) {
        return Err("1 is not an eigenvalue of block 0 at every valence (rows not summing to 1)".into());
    }
    Ok(quotient)
}

/// λ1's polynomial in the block-0 variable: P(x, c) itself for c, and
/// P(x, γ(h)) for h, γ(h) = 1 − 2(355/113)²h² ≤ cos(2πh) (so μ(γ(1/n)) ≤
/// μ(cos 2π/n) = λ1, μ being increasing).
pub fn lambda1_poly(p: &BiPoly, variable: Variable) -> BiPoly {
    match variable {
        Variable::Cosine => p.clone(),
        Variable::InverseValence => {
            let pi_up = Rational::new(355.into(), 113.into());
            let gamma =
                tpoly(&[Rational::one(), Rational::zero(), -Rational::from_integer(2.into()) * &pi_up * &pi_up]);
            p.iter()
                .map(|coef| {
                    // Horner in c at γ(h)
                    coef.coeffs().iter().rev().fold(tpoly(&[Rational::zero()]), |acc, a| {
                        acc * gamma.clone() + TPoly::from_coeffs(vec![a.clone()])
                    })
                })
                .collect()
        }
    }
}

/// The range of the block-0 variable for valences n ≥ `n`: (lo, hi, the
/// end that no valence reaches: h = 0 or c = 1).
pub fn range(variable: Variable, n: usize) -> (Rational, Rational, Rational) {
    match variable {
        Variable::InverseValence => (Rational::zero(), Rational::new(1.into(), (n as i64).into()), Rational::zero()),
        Variable::Cosine => (super::tail::cos_lower(n), Rational::one(), Rational::one()),
    }
}

/// The least valence N' ≥ `n_min` from which every eigenvalue of block 0
/// other than 1 is real and of modulus below the top root μ̃(t) of `lambda1`
/// (≤ λ1) for every t of the range; or why not. The roots of q(·, t) are
/// real and no root meets ±μ̃(t) away from the real roots of the
/// subresultants of (q, ∂q/∂x), (q, λ1's polynomial), (q(x), its value at
/// −x): N' puts them all outside the range (except its unreached end), and
/// one point of the range then decides.
pub fn decide(qp: &BiPoly, lambda1: &BiPoly, variable: Variable, n_min: usize) -> Result<(usize, String), String> {
    let (lo, hi, unreached) = range(variable, n_min);
    let dx: BiPoly = qp
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| c.clone() * <TPoly as crate::numeric::Weight>::int(k as i64))
        .collect();
    let minus: BiPoly =
        lambda1.iter().enumerate().map(|(k, c)| if k % 2 == 1 { -c.clone() } else { c.clone() }).collect();
    let mut cands = Vec::new();
    for (a, b) in [(qp, &dx), (qp, lambda1), (qp, &minus)] {
        let Some(r) = first_subresultant(a, b).map_err(|e| e.to_string())? else { continue };
        let r = rational_norm(&r).map_err(|e| e.to_string())?;
        if r.degree() > 0 {
            cands.extend(sturm::isolate(&r, &lo, &hi));
        }
    }
    let mut n = n_min;
    for mut c in cands {
        c.recognise_rational();
        if c.rational.as_ref() == Some(&unreached) {
            continue;
        }
        c.refine(&Rational::new(1.into(), 1_000_000_000_000i64.into()));
        loop {
            let (l, h, _) = range(variable, n);
            let clear = match variable {
                Variable::InverseValence => c.lo > h,
                Variable::Cosine => c.hi < l,
            };
            if clear {
                break;
            }
            let _ = l;
            n += 1;
            if n > 100_000 {
                return Err("an eigenvalue meets ±λ1's bound arbitrarily close to n = ∞".into());
            }
        }
    }
    let (l, h, _) = range(variable, n);
    let s = match variable {
        Variable::InverseValence => h.clone(),
        Variable::Cosine => (&l + &h) / Rational::from_integer(2.into()),
    };
    if !all_real(&[qp.clone()], &s) {
        return Err(format!("a non-real eigenvalue at t = {s} (moduli of complex pairs are not followed)"));
    }
    let mut mu = real_roots(&sturm::squarefree(&at(lambda1, &s))).pop().ok_or("no real λ1")?;
    let roots = real_roots(&sturm::squarefree(&at(qp, &s)));
    if let (Some(first), Some(last)) = (roots.first(), roots.last()) {
        let mut top = last.clone();
        if compare(&mut top, &mut mu) != Some(true) {
            return Err(format!("an eigenvalue is at least λ1 (at t = {s})"));
        }
        let mut minus_low = negated(first);
        if compare(&mut minus_low, &mut mu) != Some(true) {
            return Err(format!("a negative eigenvalue is at least λ1 in modulus (at t = {s})"));
        }
    }
    let text = match variable {
        Variable::InverseValence => format!("h = 1/n ∈ (0, {h}], against λ1 ≥ μ(1 − 2(355/113)²h²)"),
        Variable::Cosine => format!("c = cos(2π/n) ∈ [{l}, 1), against λ1 = μ(c)"),
    };
    Ok((n, text))
}
