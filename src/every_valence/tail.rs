//! The blocks k ≠ 0 of every valence n ≥ N at once, from P(x, c)
//! (`laurent`): block k of valence n has the characteristic polynomial
//! P(x, cos 2πk/n).
//!
//! With μ(c) the largest real root of P(·, c), it is proved exactly that on
//! c ∈ [−1, 1]:
//!
//! 1. every root of P(·, c) is real and of modulus ≤ μ(c);
//! 2. μ is strictly increasing;
//! 3. on [q_N, 1), q_N ≤ cos(2π/N), μ is a simple root and every other root
//!    has modulus < μ (strictly).
//!
//! Then for n ≥ N: λ1 = μ(cos 2π/n) is a simple eigenvalue of block 1 (and of
//! block n − 1, same c) strictly dominating the rest of those blocks, and
//! block k, 2 ≤ k ≤ n − 2, has c_k ≤ cos(4π/n) < c_1, so its eigenvalues
//! have modulus ≤ μ(c_k) < μ(c_1) = λ1. Also μ(1) ≤ 1 gives λ1 < 1.
//!
//! How. The root structure of P(·, c) (which roots are real, their order,
//! multiplicities and the order of their moduli) changes only where two
//! roots meet (P and ∂P/∂x share a root), where a root meets another's
//! negative (P(x) and P(−x) share a root) — and μ can stop increasing only
//! where ∂P/∂c vanishes on a root (P and P + ∂P/∂c share one). The first
//! principal subresultant coefficient of each pair that is not identically
//! zero vanishes exactly there (`sweep::exact::first_subresultant`); its
//! rational norm's real roots in [−1, 1] (Sturm) are the candidates. Each
//! open piece between candidates is checked at two rationals: all roots real
//! (a root leaves the real line only through a double root, a candidate),
//! μ simple and strictly above the other moduli, and μ larger at the right
//! point (μ′ has one sign on the piece, or μ is constant and the two values
//! are equal: refused). By continuity 1 holds at the candidates too
//! (non-strictly), and 2 on all of [−1, 1]; N is the least valence ≥ the
//! lower limit with q_N above every candidate below 1 — the last piece, open,
//! holds [q_N, 1) — so 3 holds. q_N = 1 − 2(355/113)²/N² ≤ 1 − (2π/N)²/2 ≤
//! cos(2π/N) (355/113 > π, and cos x ≥ 1 − x²/2).

use num_traits::{One, Signed, ToPrimitive, Zero};
use serde::Serialize;

use crate::error::Error;
use crate::numeric::exact::Poly;
use crate::numeric::sturm::{self, compare, negated, real_roots, root_bound, RealRoot};
use crate::numeric::{Cyclotomic, Rational, TPoly};
use crate::sweep::exact::{all_real, first_subresultant, rational_norm, BiPoly};

/// What the parametric part proved about the blocks k ≠ 0.
#[derive(Clone, Debug, Serialize)]
pub struct TailFacts {
    /// the least valence the proof covers
    pub threshold: usize,
    /// q_N: a rational ≤ cos(2π/N)
    pub q_threshold: String,
    /// degree of P in x and in c
    pub degree_x: usize,
    pub degree_c: usize,
    /// the candidates in [−1, 1], as isolating intervals (or exact values)
    pub candidates: Vec<String>,
    /// open pieces checked
    pub pieces: usize,
    /// μ(q_N) enclosed: a lower bound of λ1 at every valence ≥ N
    pub lambda1_lower: String,
    /// μ(1) enclosed: λ1 < μ(1) ≤ 1 at every valence
    pub lambda1_limit: String,
}

/// The outcome: proved, or the first condition that fails (and where).
pub enum Tail {
    Proved(TailFacts),
    Fails(String),
}

fn q(p: i64, d: i64) -> Rational {
    Rational::new(p.into(), d.into())
}

/// q_N = 1 − 2(355/113)²/N², a rational lower bound of cos(2π/N).
pub fn cos_lower(n: usize) -> Rational {
    let pi_up = q(355, 113);
    let n = Rational::from_integer((n as i64).into());
    Rational::one() - q(2, 1) * &pi_up * &pi_up / (&n * &n)
}

/// P(x, c) at a rational c, over Q.
pub fn at(p: &BiPoly, c: &Rational) -> Poly {
    let mut coeffs: Vec<Rational> =
        p.iter().map(|t| t.eval(c).to_rational().expect("P has rational coefficients")).collect();
    while coeffs.len() > 1 && coeffs.last().is_some_and(Zero::is_zero) {
        coeffs.pop();
    }
    Poly { coeffs }
}

/// μ(c) with the checks of an open piece: all roots real, μ simple, every
/// other root of modulus < μ.
pub(super) fn top_root_at(p: &BiPoly, c: &Rational) -> Result<RealRoot, String> {
    if !all_real(&[p.clone()], c) {
        return Err(format!("a block has a non-real eigenvalue at c = {c}"));
    }
    let px = at(p, c);
    let roots = real_roots(&px);
    let mut mu = roots.last().cloned().ok_or_else(|| format!("no real eigenvalue at c = {c}"))?;
    let g = px.gcd(&px.derivative());
    if g.degree() >= 1 {
        for mut r in real_roots(&g) {
            if sturm::same_root(&mut r, &mut mu) {
                return Err(format!("the largest eigenvalue of the block is a multiple root at c = {c}"));
            }
        }
    }
    if roots.len() > 1 && roots[0].lo.is_negative() {
        let mut minus_lowest = negated(&roots[0]);
        if compare(&mut minus_lowest, &mut mu) != Some(true) {
            return Err(format!(
                "a negative eigenvalue of the block is at least as large in modulus as the largest at c = {c}"
            ));
        }
    }
    Ok(mu)
}

/// The candidates: the real roots in [−1, 1] of the subresultants of
/// (P, ∂P/∂x), (P(x), P(−x)), (P, P + ∂P/∂c), merged where equal.
fn candidates(p: &BiPoly) -> Result<Vec<RealRoot>, Error> {
    let dx: BiPoly = p
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| c.clone() * <TPoly as crate::numeric::Weight>::int(k as i64))
        .collect();
    let minus_x: BiPoly = p.iter().enumerate().map(|(k, c)| if k % 2 == 1 { -c.clone() } else { c.clone() }).collect();
    // P + ∂P/∂c: monic like P (∂P/∂c has degree < d in x), same common roots with P as ∂P/∂c
    let plus_dc: BiPoly = p
        .iter()
        .map(|c| {
            let d: Vec<Cyclotomic> = c
                .coeffs()
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, a)| a.clone() * Cyclotomic::from_rational(&q(k as i64, 1)))
                .collect();
            c.clone() + TPoly::from_coeffs(d)
        })
        .collect();
    let (lo, hi) = (-Rational::one(), Rational::one());
    let mut found: Vec<RealRoot> = Vec::new();
    for (a, b) in [(p, &dx), (p, &minus_x), (p, &plus_dc)] {
        let Some(r) = first_subresultant(a, b)? else { continue };
        let r = rational_norm(&r)?;
        if r.degree() == 0 {
            continue;
        }
        found.extend(sturm::isolate(&r, &lo, &hi));
    }
    let mut merged: Vec<RealRoot> = Vec::new();
    'next: for mut c in found {
        for m in merged.iter_mut() {
            if sturm::same_root(m, &mut c) {
                continue 'next;
            }
        }
        merged.push(c);
    }
    for c in merged.iter_mut() {
        c.recognise_rational();
    }
    merged.sort_by(|a, b| a.mid().cmp(&b.mid()));
    Ok(merged)
}

fn show(r: &RealRoot) -> String {
    match &r.rational {
        Some(x) => x.to_string(),
        None => format!("({:.12}, {:.12})", r.lo.to_f64().unwrap_or(f64::NAN), r.hi.to_f64().unwrap_or(f64::NAN)),
    }
}

/// Decides the blocks k ≠ 0 for every valence from `min_n` on; the
/// threshold N is the least valence ≥ `min_n` the proof covers.
pub fn decide(p: &BiPoly, min_n: usize) -> Result<Tail, Error> {
    let degree_x = p.len() - 1;
    let degree_c = p.iter().map(TPoly::degree).max().unwrap_or(0);
    let cands = candidates(p)?;
    // fences −1, candidates strictly inside, 1; the open pieces between
    let (minus_one, one) = (-Rational::one(), Rational::one());
    let mut fences = vec![RealRoot::exact(minus_one.clone())];
    fences.extend(cands.iter().filter(|c| c.rational.as_ref().map_or(true, |x| x != &minus_one && x != &one)).cloned());
    fences.push(RealRoot::exact(one.clone()));
    let mut pieces = 0;
    let firsts = sturm::points_between(&mut fences);
    for (k, s1) in firsts.into_iter().enumerate() {
        // a second, larger point of the same piece: μ(s1) < μ(s2) there
        let s2 = sturm::simplest_between(&s1, &fences[k + 1].lo);
        let mut m1 = match top_root_at(p, &s1) {
            Ok(m) => m,
            Err(why) => return Ok(Tail::Fails(why)),
        };
        let mut m2 = match top_root_at(p, &s2) {
            Ok(m) => m,
            Err(why) => return Ok(Tail::Fails(why)),
        };
        if compare(&mut m1, &mut m2) != Some(true) {
            return Ok(Tail::Fails(format!(
                "the largest eigenvalue μ(c) of the blocks is not increasing in c = cos θ (compared at c = {s1} and \
                 {s2}): a block k ≥ 2 may reach λ1"
            )));
        }
        pieces += 1;
    }
    // N: q_N above every candidate below 1
    let mut top = minus_one.clone();
    for mut c in cands.iter().cloned() {
        if c.rational.as_ref() == Some(&one) {
            continue;
        }
        c.refine(&q(1, 1_000_000_000_000));
        top = top.max(c.hi.clone());
    }
    let mut n = min_n.max(3);
    while cos_lower(n) <= top {
        n += 1;
        if n > 10_000_000 {
            return Ok(Tail::Fails("a candidate lies too close to c = 1 for any valence threshold".into()));
        }
    }
    let qn = cos_lower(n).max(minus_one.clone());
    // λ1 ≥ μ(q_N) > 0
    let mut lower = match top_root_at(p, &qn) {
        Ok(m) => m,
        Err(why) => return Ok(Tail::Fails(why)),
    };
    lower.refine(&q(1, 1_000_000_000_000_000));
    if !lower.lo.is_positive() {
        return Ok(Tail::Fails(format!("λ1 is not positive at c = cos(2π/{n})")));
    }
    // μ(1) ≤ 1: no root of P(·, 1) above 1
    let p1 = sturm::squarefree(&at(p, &one));
    let chain = sturm::sturm_chain(&p1);
    let above = sturm::count_roots(&chain, &one, &root_bound(&p1));
    if above > 0 {
        return Ok(Tail::Fails("an eigenvalue of the blocks k ≠ 0 exceeds 1 as θ → 0 (λ1 ≥ 1 for large n)".into()));
    }
    let mut limit = real_roots(&p1).pop().expect("P(·, 1) has real roots");
    limit.refine(&q(1, 1_000_000_000_000));
    Ok(Tail::Proved(TailFacts {
        threshold: n,
        q_threshold: qn.to_string(),
        degree_x,
        degree_c,
        candidates: cands.iter().map(show).collect(),
        pieces,
        lambda1_lower: show(&lower),
        lambda1_limit: show(&limit),
    }))
}
