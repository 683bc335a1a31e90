//! Dense eigenanalysis of one (Fourier) block: eigenvalues clustered into
//! distinct values with algebraic and geometric multiplicity, and bases of the
//! right and left eigenspaces.
//!
//! A multiple or defective eigenvalue comes out of floating-point QR as a
//! cluster split by about eps^(1/k). Eigenvalues closer than a loose tolerance
//! are clustered; the geometric multiplicity is the number of singular values
//! of B − λ̄I below a tight tolerance (λ̄ the cluster mean, which is accurate
//! even when the individual members are not). A cluster with no small singular
//! value was two genuinely distinct eigenvalues and is split again.

use faer::c64;
use faer::Mat;

/// Eigenvalues within this relative distance in one block are one cluster.
const CLUSTER_TOL: f64 = 1e-5;
/// Singular values below this (relative to the block norm) count as zero.
const NULL_TOL: f64 = 1e-9;

#[derive(Clone, Debug)]
pub struct BlockEigen {
    pub value: c64,
    pub algebraic: usize,
    pub geometric: usize,
    /// right eigenvectors x (B x = λ x), block coordinates
    pub right: Vec<Vec<c64>>,
    /// left eigenvectors as columns y with y^H B = λ y^H, block coordinates
    pub left: Vec<Vec<c64>>,
}

pub fn block_eigen(b: &Mat<c64>) -> Result<Vec<BlockEigen>, String> {
    let n = b.nrows();
    if n == 0 {
        return Ok(Vec::new());
    }
    let finite =
        (0..n).all(|i| (0..n).all(|j| b[(i, j)].re.is_finite() && b[(i, j)].im.is_finite()));
    if !finite {
        return Err("matrix has non-finite entries".into());
    }
    let vals = b
        .eigenvalues()
        .map_err(|e| format!("eigenvalue computation failed: {e:?}"))?;
    let norm = b.norm_l2().max(1e-300);
    let mut clusters = cluster(&vals, CLUSTER_TOL);
    let mut out = Vec::new();
    while let Some(members) = clusters.pop() {
        let mean = members.iter().fold(c64::new(0.0, 0.0), |a, z| a + z) / members.len() as f64;
        let (g, right, left) = null_spaces(b, mean, NULL_TOL * norm.max(1.0))?;
        if g == 0 && members.len() > 1 {
            // not a true multiple eigenvalue: treat the members separately
            clusters.extend(members.iter().map(|z| vec![*z]));
            continue;
        }
        let g = g.clamp(1, members.len());
        let (right, left) = if right.is_empty() {
            // a simple eigenvalue whose smallest singular value sits just above the
            // tolerance: take the singular vectors of the smallest singular value
            let (_, r, l) = null_spaces(b, mean, f64::INFINITY)?;
            (
                r.into_iter().take(1).collect(),
                l.into_iter().take(1).collect(),
            )
        } else {
            (
                right.into_iter().take(g).collect(),
                left.into_iter().take(g).collect(),
            )
        };
        out.push(BlockEigen {
            value: mean,
            algebraic: members.len(),
            geometric: g,
            right,
            left,
        });
    }
    Ok(out)
}

/// Group values whose distance is below tol · max(1, |z|) (transitively).
fn cluster(vals: &[c64], tol: f64) -> Vec<Vec<c64>> {
    let n = vals.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut Vec<usize>, i: usize) -> usize {
        let mut r = i;
        while p[r] != r {
            r = p[r];
        }
        p[i] = r;
        r
    }
    for i in 0..n {
        for j in i + 1..n {
            let scale = vals[i].norm().max(vals[j].norm()).max(1.0);
            if (vals[i] - vals[j]).norm() < tol * scale {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[a] = b;
            }
        }
    }
    let mut groups: std::collections::BTreeMap<usize, Vec<c64>> = Default::default();
    for i in 0..n {
        let r = find(&mut parent, i);
        groups.entry(r).or_default().push(vals[i]);
    }
    groups.into_values().collect()
}

/// Dimension of the null space of B − λI (singular values below tol) and bases
/// of the right null space and of the null space of the adjoint, ordered from
/// the smallest singular value up.
fn null_spaces(
    b: &Mat<c64>,
    lambda: c64,
    tol: f64,
) -> Result<(usize, Vec<Vec<c64>>, Vec<Vec<c64>>), String> {
    let n = b.nrows();
    let shifted = Mat::<c64>::from_fn(n, n, |i, j| {
        if i == j {
            b[(i, j)] - lambda
        } else {
            b[(i, j)]
        }
    });
    let svd = shifted.svd().map_err(|e| format!("SVD failed: {e:?}"))?;
    let s = svd.S().column_vector();
    let (u, v) = (svd.U(), svd.V());
    let mut right = Vec::new();
    let mut left = Vec::new();
    let mut g = 0;
    for k in (0..n).rev() {
        if s[k].re < tol {
            g += 1;
        }
        if s[k].re < tol || tol.is_infinite() {
            right.push((0..n).map(|i| v[(i, k)]).collect());
            left.push((0..n).map(|i| u[(i, k)]).collect());
        }
    }
    if tol.is_infinite() {
        g = 0;
    }
    Ok((g, right, left))
}
