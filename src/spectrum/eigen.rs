//! Dense eigenanalysis of one block (a Fourier block, or the whole matrix):
//! eigenvalues clustered into distinct values with algebraic and geometric
//! multiplicity, right eigenvectors, and left eigenvectors on request.
//!
//! A multiple or defective eigenvalue comes out of floating-point QR as a
//! cluster split by about eps^(1/k). Eigenvalues closer than a loose tolerance
//! form a cluster. When the cluster's computed eigenvectors are independent the
//! eigenvalue is semisimple (the cheap common case). When they are not, the
//! eigenvalue may be defective, and the computed vectors only bound the
//! eigenspace from below; then the geometric multiplicity is the number of
//! singular values of B − λ̄I below a tight tolerance (λ̄ the cluster mean, which
//! is accurate even when the members are not). A cluster whose vectors do not
//! satisfy B x = λ̄ x was several distinct eigenvalues and is split again.

use crate::error::Error;
use faer::c64;
use faer::Mat;

/// Eigenvalues within this relative distance in one block are one cluster.
const CLUSTER_TOL: f64 = 1e-5;
/// Relative singular value below which eigenvectors count as dependent.
const RANK_TOL: f64 = 1e-6;
/// Relative residual ‖(B − λ̄I)x‖ / ‖B‖ that a cluster's eigenvectors must meet.
const RESIDUAL_TOL: f64 = 1e-7;
/// Singular values of B − λ̄I below this (relative to ‖B‖) count as zero.
const NULL_TOL: f64 = 1e-9;

#[derive(Clone, Debug)]
pub struct BlockEigen {
    pub value: c64,
    pub algebraic: usize,
    pub geometric: usize,
    /// an orthonormal basis of the right eigenspace (B x = λ x), block coordinates
    pub right: Vec<Vec<c64>>,
}

impl BlockEigen {
    /// The eigenvalue and eigenvectors of the conjugate matrix.
    pub fn conjugate(&self) -> BlockEigen {
        BlockEigen {
            value: self.value.conj(),
            algebraic: self.algebraic,
            geometric: self.geometric,
            right: self.right.iter().map(|x| x.iter().map(|z| z.conj()).collect()).collect(),
        }
    }
}

pub fn block_eigen(b: &Mat<c64>) -> Result<Vec<BlockEigen>, Error> {
    let n = b.nrows();
    if n == 0 {
        return Ok(Vec::new());
    }
    let finite = (0..n).all(|i| (0..n).all(|j| b[(i, j)].re.is_finite() && b[(i, j)].im.is_finite()));
    if !finite {
        return Err(Error::Numeric("matrix has non-finite entries".into()));
    }
    let evd = b.eigen().map_err(|e| Error::Numeric(format!("eigen-decomposition failed: {e:?}")))?;
    let vals: Vec<c64> = (0..n).map(|k| evd.S().column_vector()[k]).collect();
    let vecs: Vec<Vec<c64>> = (0..n).map(|k| (0..n).map(|i| evd.U()[(i, k)]).collect()).collect();
    let norm = b.norm_l2().max(1e-300);
    let mut clusters = cluster(&vals, CLUSTER_TOL);
    let mut out = Vec::new();
    while let Some(members) = clusters.pop() {
        let k = members.len();
        let mean = members.iter().fold(c64::new(0.0, 0.0), |a, &i| a + vals[i]) / k as f64;
        let mut basis = orthonormal_basis(members.iter().map(|&i| vecs[i].clone()).collect());
        if k > 1 && basis.len() < k {
            basis = right_null_space(b, mean, NULL_TOL * norm.max(1.0))?;
        }
        if k > 1 && (basis.is_empty() || basis.iter().any(|x| residual(b, mean, x) > RESIDUAL_TOL * norm.max(1.0))) {
            // not one multiple eigenvalue: treat the members separately
            clusters.extend(members.iter().map(|&i| vec![i]));
            continue;
        }
        let geometric = basis.len().clamp(1, k);
        basis.truncate(geometric);
        out.push(BlockEigen { value: mean, algebraic: k, geometric, right: basis });
    }
    Ok(out)
}

/// ‖(B − λI) x‖ for unit x.
fn residual(b: &Mat<c64>, lambda: c64, x: &[c64]) -> f64 {
    let n = b.nrows();
    (0..n)
        .map(|i| {
            let mut s = -lambda * x[i];
            for j in 0..n {
                s += b[(i, j)] * x[j];
            }
            s.norm_sqr()
        })
        .sum::<f64>()
        .sqrt()
}

/// Orthonormal basis of the span of the vectors, dropping directions whose
/// singular value is below RANK_TOL relative to the largest.
fn orthonormal_basis(vectors: Vec<Vec<c64>>) -> Vec<Vec<c64>> {
    let (rows, cols) = (vectors[0].len(), vectors.len());
    let x = Mat::<c64>::from_fn(rows, cols, |i, j| vectors[j][i]);
    let Ok(svd) = x.thin_svd() else { return vectors.into_iter().take(1).collect() };
    let s = svd.S().column_vector();
    let smax = s[0].re.max(1e-300);
    (0..cols.min(rows))
        .filter(|&k| s[k].re > RANK_TOL * smax)
        .map(|k| (0..rows).map(|i| svd.U()[(i, k)]).collect())
        .collect()
}

/// Group indices whose values are within tol · max(1, |z|) (transitively).
fn cluster(vals: &[c64], tol: f64) -> Vec<Vec<usize>> {
    let n = vals.len();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| vals[a].re.total_cmp(&vals[b].re));
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], i: usize) -> usize {
        let mut r = i;
        while p[r] != r {
            r = p[r];
        }
        p[i] = r;
        r
    }
    // sorted by real part: only neighbours within the window can be close
    for (a, &i) in order.iter().enumerate() {
        for &j in &order[a + 1..] {
            let scale = vals[i].norm().max(vals[j].norm()).max(1.0);
            if vals[j].re - vals[i].re > tol * scale {
                break;
            }
            if (vals[i] - vals[j]).norm() < tol * scale {
                let (x, y) = (find(&mut parent, i), find(&mut parent, j));
                parent[x] = y;
            }
        }
    }
    let mut groups: std::collections::BTreeMap<usize, Vec<usize>> = Default::default();
    for i in 0..n {
        let r = find(&mut parent, i);
        groups.entry(r).or_default().push(i);
    }
    groups.into_values().collect()
}

/// Right singular vectors of B − λI whose singular values are below tol.
fn right_null_space(b: &Mat<c64>, lambda: c64, tol: f64) -> Result<Vec<Vec<c64>>, Error> {
    let n = b.nrows();
    let shifted = Mat::<c64>::from_fn(n, n, |i, j| if i == j { b[(i, j)] - lambda } else { b[(i, j)] });
    let svd = shifted.svd().map_err(|e| Error::Numeric(format!("SVD failed: {e:?}")))?;
    let s = svd.S().column_vector();
    Ok((0..n).rev().filter(|&k| s[k].re < tol).map(|k| (0..n).map(|i| svd.V()[(i, k)]).collect()).collect())
}

/// `count` left eigenvectors of λ: vectors y with y^H (B − λI) ≈ 0, i.e. the
/// null space of the adjoint, from the singular vectors of the smallest
/// singular values.
pub fn left_eigenvectors(b: &Mat<c64>, lambda: c64, count: usize) -> Result<Vec<Vec<c64>>, Error> {
    let n = b.nrows();
    let shifted = Mat::<c64>::from_fn(n, n, |i, j| if i == j { b[(i, j)] - lambda } else { b[(i, j)] });
    let svd = shifted.svd().map_err(|e| Error::Numeric(format!("SVD failed: {e:?}")))?;
    let u = svd.U();
    Ok((0..count.min(n)).map(|t| (0..n).map(|i| u[(i, n - 1 - t)]).collect()).collect())
}
