//! Exact rational matrices for the tests' hand derivations: an oracle written
//! independently of `subdlab::numeric::exact` (plain Gaussian elimination).

use num_traits::Zero;
use subdlab::numeric::Rational;

pub type Mat = Vec<Vec<Rational>>;

pub fn q(a: i64, b: i64) -> Rational {
    Rational::new(a.into(), b.into())
}

/// Rank over the rationals (Gaussian elimination).
pub fn rank(mut a: Mat) -> usize {
    let (rows, cols) = (a.len(), a.first().map_or(0, |r| r.len()));
    let mut r = 0;
    for c in 0..cols {
        let Some(p) = (r..rows).find(|&i| !a[i][c].is_zero()) else { continue };
        a.swap(r, p);
        let pivot = a[r].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != r && !row[c].is_zero() {
                let f = row[c].clone() / pivot[c].clone();
                for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                    let t = f.clone() * p.clone();
                    *x -= t;
                }
            }
        }
        r += 1;
    }
    r
}

pub fn mul(a: &[Vec<Rational>], b: &[Vec<Rational>]) -> Mat {
    let n = a.len();
    (0..n)
        .map(|i| (0..n).map(|j| (0..n).fold(Rational::zero(), |s, k| s + a[i][k].clone() * b[k][j].clone())).collect())
        .collect()
}

/// A − λI.
pub fn shifted(a: &[Vec<Rational>], lambda: &Rational) -> Mat {
    let n = a.len();
    (0..n)
        .map(|i| (0..n).map(|j| a[i][j].clone() - if i == j { lambda.clone() } else { Rational::zero() }).collect())
        .collect()
}

/// Algebraic multiplicity of λ: the nullity of (A − λI)^size.
pub fn algebraic(a: &[Vec<Rational>], lambda: &Rational) -> usize {
    let s = shifted(a, lambda);
    let mut p = s.clone();
    for _ in 1..a.len() {
        p = mul(&p, &s);
    }
    a.len() - rank(p)
}

/// A basis of the null space {x : A x = 0} over the rationals (reduced row
/// echelon form; one basis vector per free column).
pub fn null_space(a: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    let mut m: Mat = a.to_vec();
    let (rows, cols) = (m.len(), m.first().map_or(0, |r| r.len()));
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..cols {
        let Some(p) = (r..rows).find(|&i| !m[i][c].is_zero()) else { continue };
        m.swap(r, p);
        let inv = Rational::from_integer(1.into()) / m[r][c].clone();
        for x in &mut m[r][c..] {
            *x = x.clone() * inv.clone();
        }
        let pivot = m[r].clone();
        for (i, row) in m.iter_mut().enumerate() {
            if i != r && !row[c].is_zero() {
                let f = row[c].clone();
                for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                    *x -= f.clone() * p.clone();
                }
            }
        }
        pivots.push(c);
        r += 1;
    }
    (0..cols)
        .filter(|c| !pivots.contains(c))
        .map(|free| {
            let mut x = vec![Rational::zero(); cols];
            x[free] = Rational::from_integer(1.into());
            for (k, &p) in pivots.iter().enumerate() {
                x[p] = -m[k][free].clone();
            }
            x
        })
        .collect()
}
