//! The Fourier blocks k ≠ 0 as functions of ω = e^{2πik/n}, and their
//! characteristic polynomial as a polynomial P(x, c) in x and c = cos θ.
//!
//! Block k of S has the entries B_k[a][b] = Σ_τ S[(0,a),(τ,b)] ω^τ over the
//! orbits a, b away from the centre (the centre is a fixed point and belongs
//! to block 0 only). When the representative rows do not depend on n (see
//! `probe` in `schemes::user`) and reach only the sectors −T..T, each entry is
//! the same Laurent polynomial in ω at every n > 2T + 1, so one polynomial
//! P(x, ω) = det(xI − B(ω)) serves every block of every such valence.
//!
//! P(x, ω) is computed by value: the coefficient of x^i is a sum of i × i
//! minors of B(ω), a Laurent polynomial in ω with exponents in
//! [−iT, iT] ⊂ [−D, D] (D = dT, d the block's size); so ω^D times it is a
//! polynomial of degree ≤ 2D, fixed by its values at the 2D + 1 rationals
//! ω = 1, 2, ..., 2D + 1 (Berkowitz's determinant over Q at each). On
//! |ω| = 1 the coefficient is real for every θ exactly when that Laurent
//! polynomial is palindromic (coefficients of ω^m and ω^{−m} equal), which is
//! checked, and then ω^m + ω^{−m} = 2 T_m(c) (Chebyshev) turns it into a
//! polynomial in c.

use std::collections::BTreeMap;

use num_traits::{One, Zero};

use crate::numeric::berkowitz::charpoly;
use crate::numeric::{Cyclotomic, Rational, TPoly};
use crate::sweep::exact::{interpolate, BiPoly};

/// The rows of the orbit representatives away from the centre, by signed
/// sector offset.
#[derive(Clone, Debug, PartialEq)]
pub struct LaurentRows {
    /// entries[a][b]: signed sector offset τ ↦ S[(0,a),(τ,b)] (a, b index
    /// the orbits away from the centre, in block order)
    pub entries: Vec<Vec<BTreeMap<i64, Rational>>>,
    /// S[(0,a), centre] for each orbit a away from the centre
    pub centre_column: Vec<Rational>,
}

impl LaurentRows {
    /// The block size d.
    pub fn size(&self) -> usize {
        self.entries.len()
    }

    /// T: the largest |τ| with a nonzero entry.
    pub fn reach(&self) -> i64 {
        self.entries.iter().flatten().flat_map(|m| m.keys().map(|t| t.abs())).max().unwrap_or(0)
    }

    /// B(ω) at a nonzero rational ω.
    pub fn block_at(&self, omega: &Rational) -> Vec<Vec<Rational>> {
        self.entries
            .iter()
            .map(|row| {
                row.iter().map(|m| m.iter().fold(Rational::zero(), |s, (t, w)| s + w * power(omega, *t))).collect()
            })
            .collect()
    }

    /// M = B(1): block 0 restricted to the orbits away from the centre.
    pub fn at_one(&self) -> Vec<Vec<Rational>> {
        self.block_at(&Rational::one())
    }
}

fn power(x: &Rational, e: i64) -> Rational {
    let p = num_traits::pow(x.clone(), e.unsigned_abs() as usize);
    if e < 0 {
        p.recip()
    } else {
        p
    }
}

/// Why the characteristic polynomial is not a polynomial in c.
pub const NOT_REAL: &str = "the characteristic polynomial of the blocks is not real on |ω| = 1 (its coefficients \
                            are not palindromic Laurent polynomials in ω): the blocks' spectra are not closed under \
                            conjugation";

/// P(x, c) = det(xI − B(ω)) with ω + 1/ω = 2c: coefficients lowest power of
/// x first, each a polynomial in c (the `TPoly` variable) over Q.
pub fn charpoly_in_c(rows: &LaurentRows) -> Result<BiPoly, &'static str> {
    let d = rows.size();
    let big_d = d as i64 * rows.reach();
    let points: Vec<Rational> = (1..=2 * big_d + 1).map(|k| Rational::from_integer(k.into())).collect();
    let values: Vec<Vec<Rational>> = points.iter().map(|w| charpoly(&rows.block_at(w))).collect();
    let chebyshev = chebyshev(big_d as usize);
    let mut out = Vec::with_capacity(d + 1);
    for i in 0..=d {
        // ω^D · coefficient of x^i, a polynomial of degree ≤ 2D in ω
        let y: Vec<Cyclotomic> =
            points.iter().zip(&values).map(|(w, p)| Cyclotomic::from_rational(&(&p[i] * power(w, big_d)))).collect();
        let mut laurent: Vec<Rational> = interpolate(&points, &y)
            .iter()
            .map(|c| c.to_rational().expect("interpolation of rationals is rational"))
            .collect();
        laurent.resize(2 * big_d as usize + 1, Rational::zero());
        // a_m: the coefficient of ω^m, m = −D..D, at index D + m
        let a = |m: i64| &laurent[(big_d + m) as usize];
        if (1..=big_d).any(|m| a(m) != a(-m)) {
            return Err(NOT_REAL);
        }
        let mut in_c = vec![a(0).clone()];
        for m in 1..=big_d {
            let two_am = a(m) * Rational::from_integer(2.into());
            for (k, t) in chebyshev[m as usize].iter().enumerate() {
                if in_c.len() <= k {
                    in_c.resize(k + 1, Rational::zero());
                }
                in_c[k] = &in_c[k] + &two_am * t;
            }
        }
        out.push(TPoly::from_coeffs(in_c.iter().map(Cyclotomic::from_rational).collect()));
    }
    Ok(out)
}

/// T_0, ..., T_m (Chebyshev polynomials of the first kind, cos mθ = T_m(cos θ)),
/// coefficients lowest first.
pub fn chebyshev(m: usize) -> Vec<Vec<Rational>> {
    let mut t: Vec<Vec<Rational>> = vec![vec![Rational::one()], vec![Rational::zero(), Rational::one()]];
    while t.len() <= m {
        let k = t.len();
        // T_k = 2c T_{k−1} − T_{k−2}
        let mut next = vec![Rational::zero(); k + 1];
        for (i, x) in t[k - 1].iter().enumerate() {
            next[i + 1] = &next[i + 1] + x * Rational::from_integer(2.into());
        }
        for (i, x) in t[k - 2].iter().enumerate() {
            next[i] = &next[i] - x;
        }
        t.push(next);
    }
    t.truncate(m + 1);
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::new(p.into(), d.into())
    }

    #[test]
    fn chebyshev_polynomials() {
        // T_3 = 4c³ − 3c, T_4 = 8c⁴ − 8c² + 1
        let t = chebyshev(4);
        assert_eq!(t[3], vec![q(0, 1), q(-3, 1), q(0, 1), q(4, 1)]);
        assert_eq!(t[4], vec![q(1, 1), q(0, 1), q(-8, 1), q(0, 1), q(8, 1)]);
    }

    #[test]
    fn a_one_by_one_block_is_its_entry_in_c() {
        // B(ω) = 1/4 + (ω + 1/ω)/8 = 1/4 + c/4: P = x − 1/4 − c/4
        let mut m = BTreeMap::new();
        m.insert(0, q(1, 4));
        m.insert(1, q(1, 8));
        m.insert(-1, q(1, 8));
        let rows = LaurentRows { entries: vec![vec![m]], centre_column: vec![q(1, 2)] };
        let p = charpoly_in_c(&rows).unwrap();
        assert_eq!(p.len(), 2);
        assert_eq!(p[1], <TPoly as crate::numeric::Weight>::int(1));
        let expected =
            TPoly::from_coeffs(vec![Cyclotomic::from_rational(&q(-1, 4)), Cyclotomic::from_rational(&q(-1, 4))]);
        assert_eq!(p[0], expected);
        // a one-sided entry (ω only) is not real on the circle
        let mut m = BTreeMap::new();
        m.insert(1, q(1, 2));
        let rows = LaurentRows { entries: vec![vec![m]], centre_column: vec![q(1, 2)] };
        assert_eq!(charpoly_in_c(&rows), Err(NOT_REAL));
    }
}
