//! Spectral projections of an input over the whole neighbourhood: the
//! component of level-0 data z along one eigenvalue ν of S, and the top of
//! its Jordan chain.
//!
//! The projector onto the generalised eigenspace G_ν along the sum of the
//! other generalised eigenspaces is P_ν = R (Lᵀ R)⁻¹ Lᵀ, with R a basis of
//! G_ν (right, null spaces of (S − νI)^k) and L a basis of the generalised
//! eigenspace of Sᵀ for ν: a left generalised eigenvector of ν is orthogonal
//! (bilinear pairing, no conjugation) to every right generalised eigenvector
//! of every other eigenvalue, so Lᵀ x = 0 for the rest and Lᵀ R is
//! invertible. Both bases come from [`jordan::generalised_eigenspace`]
//! (level by level, not from powers of N), the routine the Jordan analysis
//! of `subdlab curvature` uses; here it runs on the dense S of the whole
//! neighbourhood, so it serves configurations without rotation symmetry
//! too.

use faer::c64;

use crate::curvature::jordan;
use crate::error::Error;

/// The dense S as a real matrix (row-major) and as faer matrices of S and Sᵀ.
pub struct DenseS {
    pub rows: Vec<Vec<f64>>,
    s: faer::Mat<c64>,
    st: faer::Mat<c64>,
}

impl DenseS {
    pub fn new(rows: Vec<Vec<f64>>) -> DenseS {
        let k = rows.len();
        let s = faer::Mat::<c64>::from_fn(k, k, |i, j| c64::new(rows[i][j], 0.0));
        let st = faer::Mat::<c64>::from_fn(k, k, |i, j| c64::new(rows[j][i], 0.0));
        DenseS { rows, s, st }
    }

    pub fn size(&self) -> usize {
        self.rows.len()
    }

    /// S x for real x.
    pub fn apply(&self, x: &[f64]) -> Vec<f64> {
        self.rows.iter().map(|r| r.iter().zip(x).map(|(a, b)| a * b).sum()).collect()
    }

    /// (S − νI) x for complex x.
    pub fn shifted(&self, nu: c64, x: &[c64]) -> Vec<c64> {
        self.rows
            .iter()
            .enumerate()
            .map(|(i, r)| r.iter().zip(x).fold(c64::new(0.0, 0.0), |a, (w, v)| a + *v * *w) - nu * x[i])
            .collect()
    }
}

/// The spectral projector of one eigenvalue, kept as its two bases.
pub struct Projector {
    pub nu: c64,
    /// basis of the right generalised eigenspace (columns as vectors)
    right: Vec<Vec<c64>>,
    /// (Lᵀ R)⁻¹ Lᵀ as k rows over the neighbourhood
    coefficients: Vec<Vec<c64>>,
}

impl Projector {
    /// The projector of ν with algebraic multiplicity `multiplicity`.
    pub fn new(s: &DenseS, nu: c64, multiplicity: usize) -> Result<Projector, Error> {
        let right = jordan::generalised_eigenspace(&s.s, nu, multiplicity);
        let left = jordan::generalised_eigenspace(&s.st, nu, multiplicity);
        if right.is_empty() || right.len() != left.len() {
            return Err(Error::Numeric(format!(
                "the generalised eigenspaces of {nu} have dimensions {} (right) and {} (left)",
                right.len(),
                left.len()
            )));
        }
        let k = right.len();
        // M = Lᵀ R (bilinear)
        let dot = |a: &[c64], b: &[c64]| a.iter().zip(b).fold(c64::new(0.0, 0.0), |acc, (x, y)| acc + *x * *y);
        let m: Vec<Vec<c64>> = (0..k).map(|i| (0..k).map(|j| dot(&left[i], &right[j])).collect()).collect();
        let inv = invert(m).ok_or_else(|| {
            Error::Numeric(format!("the left and right generalised eigenvectors of {nu} are not dual"))
        })?;
        let size = s.size();
        let coefficients = (0..k)
            .map(|i| (0..size).map(|c| (0..k).fold(c64::new(0.0, 0.0), |a, j| a + inv[i][j] * left[j][c])).collect())
            .collect();
        Ok(Projector { nu, right, coefficients })
    }

    /// P_ν z for real z.
    pub fn project(&self, z: &[f64]) -> Vec<c64> {
        let c: Vec<c64> = self
            .coefficients
            .iter()
            .map(|row| row.iter().zip(z).fold(c64::new(0.0, 0.0), |a, (w, v)| a + *w * *v))
            .collect();
        let size = z.len();
        (0..size).map(|i| self.right.iter().zip(&c).fold(c64::new(0.0, 0.0), |a, (r, ci)| a + r[i] * *ci)).collect()
    }
}

/// Gauss–Jordan inversion with partial pivoting of a small complex matrix;
/// None when a pivot is below 1e-12 of the largest entry.
fn invert(mut m: Vec<Vec<c64>>) -> Option<Vec<Vec<c64>>> {
    let k = m.len();
    let top = m.iter().flatten().map(|z| z.norm()).fold(0.0, f64::max);
    let mut inv: Vec<Vec<c64>> =
        (0..k).map(|i| (0..k).map(|j| c64::new(if i == j { 1.0 } else { 0.0 }, 0.0)).collect()).collect();
    for col in 0..k {
        let p = (col..k).max_by(|&a, &b| m[a][col].norm().total_cmp(&m[b][col].norm()))?;
        if m[p][col].norm() <= 1e-12 * top {
            return None;
        }
        m.swap(col, p);
        inv.swap(col, p);
        let d = m[col][col];
        for j in 0..k {
            m[col][j] /= d;
            inv[col][j] /= d;
        }
        for r in 0..k {
            if r != col {
                let f = m[r][col];
                if f.norm() != 0.0 {
                    for j in 0..k {
                        let (a, b) = (m[col][j], inv[col][j]);
                        m[r][j] -= f * a;
                        inv[r][j] -= f * b;
                    }
                }
            }
        }
    }
    Some(inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3 × 3 upper-triangular S with a Jordan block at 1/2 and a simple
    /// 1/4: P_{1/2} + P_{1/4} = I, and P_{1/4} of (S − ½I)-images is exact.
    #[test]
    fn projectors_sum_to_the_identity() {
        let rows = vec![vec![0.5, 1.0, 0.3], vec![0.0, 0.5, 0.2], vec![0.0, 0.0, 0.25]];
        let s = DenseS::new(rows);
        let a = Projector::new(&s, c64::new(0.5, 0.0), 2).unwrap();
        let b = Projector::new(&s, c64::new(0.25, 0.0), 1).unwrap();
        let z = [0.7, -1.1, 2.0];
        let (pa, pb) = (a.project(&z), b.project(&z));
        for i in 0..3 {
            assert!((pa[i] + pb[i] - c64::new(z[i], 0.0)).norm() < 1e-12);
        }
        // P_{1/4} z is an eigenvector of 1/4: (S − ¼I) P z = 0
        let r = s.shifted(c64::new(0.25, 0.0), &pb);
        assert!(r.iter().all(|x| x.norm() < 1e-12));
    }

    #[test]
    fn inversion_refuses_singular() {
        let one = c64::new(1.0, 0.0);
        assert!(invert(vec![vec![one, one], vec![one, one]]).is_none());
        let inv = invert(vec![vec![c64::new(0.0, 2.0)]]).unwrap();
        assert!((inv[0][0] - c64::new(0.0, -0.5)).norm() < 1e-15);
    }
}
