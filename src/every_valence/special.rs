//! Every valence n ≥ N when one row of S depends on n (face-centred schemes:
//! the centre face's rule, `symbol`): the blocks are the n-independent
//! Laurent rows B(ω) (`laurent`) with that row's entry on its own orbit
//! (a, b) raised by the symbol's correction e_k(c) at the special blocks
//! k ∈ {0, ±1, ..., ±M}, c = cos(2π/n). λ1 is taken from block 1 (and
//! n − 1, the same polynomial); every other block is compared with it.
//!
//! Polynomials (all exact, over Q):
//! * P(x, c) = det(xI − B(ω)), ω + 1/ω = 2c (`laurent::charpoly_in_c`), and
//!   P⁺ the same with the entry (a, b) raised by 1. A change of one entry is
//!   a rank-one change, so det is affine in it:
//!   Q_k(x, c) = P(x, T_k(c)) + e_k(c) (P⁺ − P)(x, T_k(c)) is block k's
//!   characteristic polynomial for 0 ≤ k ≤ M (cos(2πk/n) = T_k(c)).
//! * generic blocks M < k < n − M: P(x, c_k), c_k ∈ [−1, 1].
//!
//! Decision for c ∈ [q_N, 1) (q_N ≤ cos(2π/N), `tail::cos_lower`):
//! 1. block 1: every root of Q_1(·, c) real, the top one μ1(c) simple,
//!    strictly above every other modulus, in (0, 1). The structure of the
//!    roots changes only where two meet, one meets another's negative, or a
//!    root crosses 0 or 1: the real roots of the subresultants of
//!    (Q_1, ∂Q_1/∂x), (Q_1(x), Q_1(−x)) and of Q_1(0, c), Q_1(1, c). N is
//!    raised until none lies in [q_N, 1); one rational point then decides.
//! 2. blocks 2..M and block 0 (its factor x − 1 divided out, the rows
//!    summing to 1): every root real and of modulus below μ1(c) on the range
//!    (`centre::decide`, the same comparison as block 0 of vertex-centred
//!    schemes, against λ1's polynomial Q_1 in the same c).
//! 3. generic blocks: a rational L with μ1(c) > L on [q_N, 1] (Q_1(L, c) has
//!    no root there and μ1 > L at one point) and every root of P(·, c′) real
//!    and in (−L, L) for every c′ ∈ [−1, 1] (real on each piece between the
//!    real roots of the subresultant of (P, ∂P/∂x); P(±L, c′) has no root in
//!    [−1, 1]; at c′ = 0 the roots lie in (−L, L)). Roots move continuously
//!    with c′ and cannot pass ±L.
//!
//! Then for n ≥ N: λ0 = 1 is simple (block 0's other roots are below
//! λ1 < 1), λ1 = μ1(cos 2π/n) is simple in blocks 1 and n − 1 and every
//! other eigenvalue has modulus below it.

use num_traits::{One, Signed, ToPrimitive, Zero};
use serde::Serialize;

use super::centre::{self, Variable};
use super::laurent::chebyshev;
use super::symbol::TrigInJ;
use super::tail::{at, cos_lower, top_root_at};
use crate::numeric::exact::Poly;
use crate::numeric::sturm::{self, compare, real_roots, RealRoot};
use crate::numeric::{Cyclotomic, Rational, TPoly};
use crate::sweep::exact::{all_real, first_subresultant, rational_norm, BiPoly};

/// What was proved about the blocks when a row depends on n.
#[derive(Clone, Debug, Serialize)]
pub struct SpecialFacts {
    /// the least valence the proof covers
    pub threshold: usize,
    /// the n-dependent row's symbol: generic value and corrections e_0..e_M in c
    pub symbol: String,
    /// M: blocks 0, ±1, ..., ±M are special
    pub frequencies: u32,
    /// degree of P in x and in c
    pub degree_x: usize,
    pub degree_c: usize,
    /// λ1 at the point checked, enclosed, and the bound L of the generic blocks
    pub lambda1: String,
    pub generic_bound: String,
    /// one line per special block k ≥ 2 and block 0
    pub blocks: Vec<String>,
}

fn q(p: i64, d: i64) -> Rational {
    Rational::new(p.into(), d.into())
}

fn tpoly(p: &[Rational]) -> TPoly {
    TPoly::from_coeffs(p.iter().map(Cyclotomic::from_rational).collect())
}

/// p(x, inner(c)): each coefficient composed with `inner` (Horner).
fn compose(p: &BiPoly, inner: &TPoly) -> BiPoly {
    p.iter()
        .map(|coef| {
            coef.coeffs()
                .iter()
                .rev()
                .fold(tpoly(&[Rational::zero()]), |acc, a| acc * inner.clone() + TPoly::constant(a.clone()))
        })
        .collect()
}

fn trim(mut p: BiPoly) -> BiPoly {
    while p.len() > 1 && p.last().is_some_and(crate::numeric::Weight::is_zero) {
        p.pop();
    }
    p
}

/// Q_k(x, c) = P(x, T_k(c)) + e_k(c)·(P⁺ − P)(x, T_k(c)).
pub fn block_poly(p: &BiPoly, p_plus: &BiPoly, e_k: &[Rational], k: usize) -> BiPoly {
    let t_k = tpoly(&chebyshev(k).pop().expect("T_k"));
    let (a, b) = (compose(p, &t_k), compose(p_plus, &t_k));
    let e = tpoly(e_k);
    let len = a.len().max(b.len());
    let zero = tpoly(&[Rational::zero()]);
    trim(
        (0..len)
            .map(|i| {
                let ai = a.get(i).cloned().unwrap_or_else(|| zero.clone());
                let bi = b.get(i).cloned().unwrap_or_else(|| zero.clone());
                ai.clone() + e.clone() * (bi - ai)
            })
            .collect(),
    )
}

/// q(x, c) / (x − 1) when x = 1 is a root for every c, else None.
fn divide_by_x_minus_one(p: &BiPoly) -> Option<BiPoly> {
    // synthetic division from the top: quotient coefficients b_{i−1} = a_i + b_i
    let d = p.len() - 1;
    let mut quotient = vec![tpoly(&[Rational::zero()]); d];
    let mut carry = tpoly(&[Rational::zero()]);
    for i in (1..=d).rev() {
        carry = p[i].clone() + carry;
        quotient[i - 1] = carry.clone();
    }
    let remainder = p[0].clone() + carry;
    crate::numeric::Weight::is_zero(&remainder).then_some(quotient)
}

/// p(x0, c) as a polynomial in c, over Q.
fn at_x(p: &BiPoly, x0: &Rational) -> Poly {
    let mut acc = tpoly(&[Rational::zero()]);
    for coef in p.iter().rev() {
        acc = acc * tpoly(std::slice::from_ref(x0)) + coef.clone();
    }
    let mut coeffs: Vec<Rational> =
        acc.coeffs().iter().map(|c| c.to_rational().expect("rational coefficients")).collect();
    if coeffs.is_empty() {
        coeffs.push(Rational::zero());
    }
    Poly { coeffs }
}

fn derivative_x(p: &BiPoly) -> BiPoly {
    p.iter().enumerate().skip(1).map(|(k, c)| c.clone() * <TPoly as crate::numeric::Weight>::int(k as i64)).collect()
}

fn negate_x(p: &BiPoly) -> BiPoly {
    p.iter().enumerate().map(|(k, c)| if k % 2 == 1 { -c.clone() } else { c.clone() }).collect()
}

/// Whether a polynomial in c has a real root in [lo, hi] (true when it is zero).
fn has_root_in(p: &Poly, lo: &Rational, hi: &Rational) -> bool {
    if p.is_zero() {
        return true;
    }
    let sq = sturm::squarefree(p);
    sq.degree() > 0 && sturm::count_roots(&sturm::sturm_chain(&sq), lo, hi) > 0
}

fn show(r: &RealRoot) -> String {
    match &r.rational {
        Some(x) => x.to_string(),
        None => format!("({:.12}, {:.12})", r.lo.to_f64().unwrap_or(f64::NAN), r.hi.to_f64().unwrap_or(f64::NAN)),
    }
}

/// Step 1: the least N ≥ `n_min` with the root structure of Q_1 fixed on
/// [q_N, 1), and μ1 at a point of it.
fn lambda1(q1: &BiPoly, n_min: usize) -> Result<(usize, Rational, RealRoot), String> {
    let (lo, hi) = (-Rational::one(), Rational::one());
    let mut cands: Vec<RealRoot> = Vec::new();
    for b in [derivative_x(q1), negate_x(q1)] {
        if let Some(r) = first_subresultant(q1, &b).map_err(|e| e.to_string())? {
            let r = rational_norm(&r).map_err(|e| e.to_string())?;
            if r.degree() > 0 {
                cands.extend(sturm::isolate(&r, &lo, &hi));
            }
        }
    }
    for x0 in [Rational::zero(), Rational::one()] {
        let r = at_x(q1, &x0);
        if !r.is_zero() && r.degree() > 0 {
            cands.extend(sturm::isolate(&r, &lo, &hi));
        }
    }
    let mut n = n_min;
    for mut c in cands {
        c.recognise_rational();
        if c.rational.as_ref() == Some(&hi) {
            continue; // c = 1 is n = ∞, no valence
        }
        c.refine(&q(1, 1_000_000_000_000));
        while cos_lower(n) <= c.hi {
            n += 1;
            if n > 100_000 {
                return Err("block 1's eigenvalues change order arbitrarily close to n = ∞".into());
            }
        }
    }
    let s = (cos_lower(n) + &hi) / q(2, 1);
    let mut mu = top_root_at(q1, &s).map_err(|e| format!("block 1: {e}"))?;
    mu.refine(&q(1, 1_000_000_000_000_000));
    if !mu.lo.is_positive() {
        return Err(format!("λ1 is not positive (block 1 at c = {s})"));
    }
    if compare(&mut mu.clone(), &mut RealRoot::exact(Rational::one())) != Some(true) {
        return Err(format!("λ1 is not below 1 (block 1 at c = {s})"));
    }
    Ok((n, s, mu))
}

/// Step 3 for one L: every root of P(·, c′) real and in (−L, L) for every
/// c′ ∈ [−1, 1], or why not.
fn generic_within(p: &BiPoly, l: &Rational) -> Result<(), String> {
    let (lo, hi) = (-Rational::one(), Rational::one());
    let mut fences = vec![RealRoot::exact(lo.clone())];
    if let Some(r) = first_subresultant(p, &derivative_x(p)).map_err(|e| e.to_string())? {
        let r = rational_norm(&r).map_err(|e| e.to_string())?;
        if r.degree() > 0 {
            let mut inner = sturm::isolate(&r, &lo, &hi);
            for c in inner.iter_mut() {
                c.recognise_rational();
            }
            inner.retain(|c| c.rational.as_ref().is_none_or(|x| x != &lo && x != &hi));
            inner.sort_by_key(RealRoot::mid);
            let mut merged: Vec<RealRoot> = Vec::new();
            'next: for mut c in inner {
                for m in merged.iter_mut() {
                    if sturm::same_root(m, &mut c) {
                        continue 'next;
                    }
                }
                merged.push(c);
            }
            fences.extend(merged);
        }
    }
    fences.push(RealRoot::exact(hi.clone()));
    for s in sturm::points_between(&mut fences) {
        if !all_real(std::slice::from_ref(p), &s) {
            return Err(format!("a generic block has a non-real eigenvalue at cos θ = {s}"));
        }
    }
    for x0 in [l.clone(), -l.clone()] {
        if has_root_in(&at_x(p, &x0), &lo, &hi) {
            return Err(format!("an eigenvalue of a generic block reaches {x0} for some cos θ ∈ [−1, 1]"));
        }
    }
    let p0 = sturm::squarefree(&at(p, &Rational::zero()));
    if p0.degree() > 0 {
        let chain = sturm::sturm_chain(&p0);
        let all = sturm::count_roots(&chain, &-sturm::root_bound(&p0), &sturm::root_bound(&p0));
        if sturm::count_roots(&chain, &-l.clone(), l) != all {
            return Err(format!("an eigenvalue of a generic block is outside (−{l}, {l}) at cos θ = 0"));
        }
    }
    Ok(())
}

/// The whole decision (steps 1–3); `n_min` ≥ 2M + 1.
pub fn decide(p: &BiPoly, p_plus: &BiPoly, sym: &TrigInJ, n_min: usize) -> Result<SpecialFacts, String> {
    let big_m = sym.degree();
    let corrections: Vec<Vec<Rational>> = (0..=big_m)
        .map(|m| {
            sym.correction(m).polynomial_in_c().ok_or_else(|| {
                format!(
                    "block {m}'s correction to the n-dependent row's symbol depends on n other than through \
                     cos(2π/n) (not followed)"
                )
            })
        })
        .collect::<Result<_, _>>()?;
    if big_m == 0 {
        return Err("the n-dependent row's symbol has no frequency 1: λ1 is not taken from it (not followed)".into());
    }
    let q1 = block_poly(p, p_plus, &corrections[1], 1);
    let (mut n, s, mu) = lambda1(&q1, n_min.max(2 * big_m as usize + 1))?;
    let mut lines = Vec::new();
    // step 2: blocks 2..M and block 0, against Q_1 in the same c
    let mut special: Vec<(String, BiPoly)> = Vec::new();
    for (m, e_m) in corrections.iter().enumerate().skip(2) {
        special.push((format!("block {m}"), block_poly(p, p_plus, e_m, m)));
    }
    let q0 = block_poly(p, p_plus, &corrections[0], 0);
    let r0 = divide_by_x_minus_one(&q0).ok_or("block 0 does not have the eigenvalue 1 at every c")?;
    special.push(("block 0 (1 divided out)".into(), r0));
    for (name, qk) in &special {
        let (n_k, range) = centre::decide(qk, &q1, Variable::Cosine, n).map_err(|e| format!("{name}: {e}"))?;
        n = n.max(n_k);
        lines.push(format!("{name}: every eigenvalue real and of modulus below λ1 for {range}"));
    }
    // step 3: a bound L between the generic blocks and λ1
    let (lo_n, one) = (cos_lower(n), Rational::one());
    let mut at_one = real_roots(&sturm::squarefree(&at(&q1, &one))).pop().ok_or("no real λ1 at c = 1")?;
    at_one.refine(&q(1, 1_000_000_000_000));
    let m = mu.lo.clone().min(at_one.lo.clone());
    let mut chosen = None;
    for t in [q(1, 1000), q(1, 10), q(1, 2)] {
        // the simplest rational just below m (1 − t): short to print
        let l = sturm::simplest_between(&(&m * (Rational::one() - &t * q(2, 1))), &(&m * (Rational::one() - &t)));
        if !l.is_positive() {
            break;
        }
        if !has_root_in(&at_x(&q1, &l), &lo_n, &one) {
            chosen = Some(l);
            break;
        }
    }
    let l = chosen.ok_or("no rational bound L below λ1 on the whole range was found")?;
    generic_within(p, &l).map_err(|e| format!("generic blocks (|k| > {big_m}): {e}"))?;
    let symbol = format!(
        "generic value {}; corrections {}",
        sym.generic().polynomial_in_c().map(|v| show_poly(&v)).unwrap_or_default(),
        corrections.iter().enumerate().map(|(k, e)| format!("e_{k} = {}", show_poly(e))).collect::<Vec<_>>().join(", ")
    );
    Ok(SpecialFacts {
        threshold: n,
        symbol,
        frequencies: big_m,
        degree_x: p.len() - 1,
        degree_c: p.iter().map(TPoly::degree).max().unwrap_or(0),
        lambda1: format!("μ1({s}) ∈ {}", show(&mu)),
        generic_bound: format!(
            "every eigenvalue of the blocks |k| > {big_m} real and of modulus < L = {} < λ1 on c ∈ [{lo_n}, 1]",
            l
        ),
        blocks: lines,
    })
}

/// A polynomial in c, lowest first, as text.
fn show_poly(p: &[Rational]) -> String {
    let terms: Vec<String> = p
        .iter()
        .enumerate()
        .filter(|(_, a)| !a.is_zero())
        .map(|(k, a)| match k {
            0 => a.to_string(),
            1 => format!("({a})c"),
            _ => format!("({a})c^{k}"),
        })
        .collect();
    if terms.is_empty() {
        "0".into()
    } else {
        terms.join(" + ")
    }
}
