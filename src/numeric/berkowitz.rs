//! The characteristic polynomial over any commutative ring of weights
//! (Berkowitz's division-free algorithm): the exact sweep takes it of
//! Fourier blocks whose entries are polynomials in a parameter, where a
//! method that divides (Gauss, Hessenberg) would leave the ring.

use super::weight::Weight;

/// det(xI − A) by Berkowitz's division-free algorithm (coefficients lowest
/// first, monic), over any commutative ring of weights.
pub fn charpoly<W: Weight>(a: &[Vec<W>]) -> Vec<W> {
    let n = a.len();
    // c: coefficients highest first
    let mut c: Vec<W> = vec![W::one()];
    for r in 0..n {
        // T = [1, −a_rr, −R C, −R M C, ..., −R M^{r−1} C]
        let mut t = vec![W::one(), -a[r][r].clone()];
        let mut v: Vec<W> = (0..r).map(|i| a[i][r].clone()).collect();
        for _ in 0..r {
            let rv = (0..r).fold(W::zero(), |s, j| s + a[r][j].clone() * v[j].clone());
            t.push(-rv);
            v = (0..r).map(|i| (0..r).fold(W::zero(), |s, j| s + a[i][j].clone() * v[j].clone())).collect();
        }
        // new c = Toeplitz(T) (r+2 × r+1) · c
        let new: Vec<W> = (0..r + 2)
            .map(|i| (0..(r + 1).min(i + 1)).fold(W::zero(), |s, j| s + t[i - j].clone() * c[j].clone()))
            .collect();
        c = new;
    }
    c.reverse();
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::new(p.into(), d.into())
    }

    #[test]
    fn berkowitz_on_a_small_matrix() {
        // [[2, 1], [1, 2]]: x² − 4x + 3
        let a = vec![vec![q(2, 1), q(1, 1)], vec![q(1, 1), q(2, 1)]];
        assert_eq!(charpoly(&a), vec![q(3, 1), q(-4, 1), q(1, 1)]);
        let b = vec![vec![q(1, 1), q(2, 1), q(0, 1)], vec![q(0, 1), q(3, 1), q(1, 1)], vec![q(4, 1), q(0, 1), q(1, 1)]];
        // det(xI − B) = x³ − 5x² + 7x − 11 (trace 5, principal minors 3 + 1 + 3, det 11)
        assert_eq!(charpoly(&b), vec![q(-11, 1), q(7, 1), q(-5, 1), q(1, 1)]);
    }
}
