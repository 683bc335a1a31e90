//! Smoothness of a uniform binary curve scheme from its symbol (Laurent
//! polynomial) a(z) = Σ_k a_k z^k, a_{e − 2o} = weight of P_{i+o} in the rule
//! for new P_{2i+e} (Dyn, "Analysis of convergence and smoothness by the
//! formalism of Laurent polynomials"): the scheme is C¹ if a(z) = (1 + z)² b(z)/2
//! and the scheme with symbol b is contractive, ‖S_b^L‖_∞ < 1 for some L.
//! Exact, over the rationals.

use super::CurveMask;
use crate::error::Error;
use crate::numeric::Rational;
use num_traits::{Signed, Zero};

/// The symbol's coefficients from the lowest power upwards.
pub fn symbol(mask: &CurveMask<Rational>) -> Vec<Rational> {
    let mut terms: Vec<(i64, Rational)> = Vec::new();
    for (e, rule) in [(0, &mask.even), (1, &mask.odd)] {
        for (o, w) in rule.iter() {
            terms.push((e - 2 * o, w.clone()));
        }
    }
    let lo = terms.iter().map(|t| t.0).min().unwrap_or(0);
    let hi = terms.iter().map(|t| t.0).max().unwrap_or(0);
    let mut c = vec![Rational::zero(); (hi - lo + 1) as usize];
    for (k, w) in terms {
        c[(k - lo) as usize] += w;
    }
    c
}

/// p / (1 + z), or `None` when (1 + z) does not divide p.
fn divide_by_one_plus_z(p: &[Rational]) -> Option<Vec<Rational>> {
    let d = p.len().checked_sub(1)?;
    if d == 0 {
        return p[0].is_zero().then(Vec::new);
    }
    let mut q = vec![Rational::zero(); d];
    q[d - 1] = p[d].clone();
    for k in (1..d).rev() {
        q[k - 1] = &p[k] - &q[k];
    }
    (p[0] == q[0]).then_some(q)
}

fn multiply(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut out = vec![Rational::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// ‖S_b^L‖_∞: the largest sum of |coefficients| of b(z) b(z²) ⋯ b(z^{2^{L−1}})
/// over one residue class modulo 2^L.
pub fn power_norm(b: &[Rational], steps: u32) -> Rational {
    let mut prod = vec![Rational::from_integer(1.into())];
    for l in 0..steps {
        let stride = 1usize << l;
        let mut up = vec![Rational::zero(); (b.len() - 1) * stride + 1];
        for (k, x) in b.iter().enumerate() {
            up[k * stride] = x.clone();
        }
        prod = multiply(&prod, &up);
    }
    let m = 1usize << steps;
    (0..m)
        .map(|r| prod.iter().skip(r).step_by(m).fold(Rational::zero(), |acc, x| acc + x.abs()))
        .max()
        .unwrap_or_else(Rational::zero)
}

/// The C¹ test: `Err` when (1 + z)² does not divide a(z) (the scheme does not
/// reproduce linear functions); otherwise the first L ≤ `max_steps` with
/// ‖S_b^L‖_∞ < 1 (C¹ proven) and the norms for L = 1, 2, ....
pub fn c1_test(mask: &CurveMask<Rational>, max_steps: u32) -> Result<(Option<u32>, Vec<Rational>), Error> {
    let a = symbol(mask);
    let a1 = divide_by_one_plus_z(&a)
        .ok_or_else(|| Error::Input("(1 + z) does not divide the symbol: constants are not reproduced".into()))?;
    let a2 = divide_by_one_plus_z(&a1).ok_or_else(|| {
        Error::Input("(1 + z)² does not divide the symbol: linear functions are not reproduced".into())
    })?;
    let b: Vec<Rational> = a2.iter().map(|x| x * Rational::from_integer(2.into())).collect();
    let mut norms = Vec::new();
    for l in 1..=max_steps {
        let nrm = power_norm(&b, l);
        let done = nrm < Rational::from_integer(1.into());
        norms.push(nrm);
        if done {
            return Ok((Some(l), norms));
        }
    }
    Ok((None, norms))
}
