//! The eigen-stage: a local matrix decomposed by Fourier blocks or as a
//! whole, the blocks' eigenvalues merged into distinct values with
//! multiplicities and recognised where real.

use faer::c64;
use faer::Mat;
use rayon::prelude::*;

use super::eigen;
use super::eigenvalue::{EigenVectors, Eigenvalue};
use super::spectrum_result::{BlockInfo, Method, Synthesis};
use crate::dft::{fourier_blocks_from_rows, Orbits};
use crate::error::Error;
use crate::matrix::LocalMatrix;
use crate::numeric::recognise::recognise;

/// Two eigenvalues from different blocks are the same when this close (relative).
const MERGE_TOL: f64 = 1e-8;

/// Eigenvalues of a local matrix (unsorted distinct values with multiplicities,
/// vectors in block coordinates) and the blocks they came from.
pub struct Decomposition {
    pub blocks: Vec<BlockInfo>,
    pub eigenvalues: Vec<Eigenvalue>,
    pub synthesis: Synthesis,
}

/// The eigen-stage of the pipeline on its own (the benchmark times this):
/// `period` is the configuration's rotation period, `n` its valence.
pub fn decompose(matrix: &LocalMatrix<f64>, period: usize, n: usize, method: Method) -> Result<Decomposition, Error> {
    match method {
        Method::Dft => {
            let orbits = Orbits::new(matrix, period, n);
            let rows: Vec<&[(usize, f64)]> = orbits.representative.iter().map(|&k| matrix.rows[k].as_slice()).collect();
            decompose_dft(&rows, orbits)
        }
        Method::Full => {
            let dense = Mat::<c64>::from_fn(matrix.size(), matrix.size(), |i, j| c64::new(matrix.get(i, j), 0.0));
            let all = eigen::block_eigen(&dense)?.into_iter().map(|e| Eigenvalue::from_block(e, 0)).collect();
            Ok(finish(vec![BlockInfo { index: 0, size: matrix.size() }], all, Synthesis::Full { matrix: dense }))
        }
    }
}

/// The Fourier path from the representative rows (`rows[o]`: the row of S of
/// orbit o's representative, over all columns).
pub fn decompose_dft(rows: &[&[(usize, f64)]], orbits: Orbits) -> Result<Decomposition, Error> {
    let blocks = fourier_blocks_from_rows(rows, &orbits);
    // the blocks are independent eigenproblems: solved side by side, and
    // collected in block order, so the result does not depend on scheduling
    let solved: Vec<Result<Vec<eigen::BlockEigen>, Error>> =
        blocks.par_iter().map(|b| eigen::block_eigen(&b.matrix)).collect();
    let mut all = Vec::new();
    for (b, eigen) in blocks.iter().zip(solved) {
        all.extend(eigen?.into_iter().map(|e| Eigenvalue::from_block(e, b.index)));
    }
    let info = blocks.iter().map(|b| BlockInfo { index: b.index, size: b.matrix.nrows() }).collect();
    let (block_orbits, mats) = blocks.into_iter().map(|b| (b.orbits, b.matrix)).unzip();
    Ok(finish(info, all, Synthesis::Dft { orbits, block_orbits, blocks: mats }))
}

fn finish(blocks: Vec<BlockInfo>, eigenvalues: Vec<Eigenvalue>, synthesis: Synthesis) -> Decomposition {
    let mut eigenvalues = merge(eigenvalues);
    for e in &mut eigenvalues {
        // snap tiny imaginary parts of real eigenvalues (conjugate blocks) to zero
        if e.im.abs() < 1e-12 * e.modulus.max(1.0) {
            e.im = 0.0;
        }
        e.recognised = if e.is_real() { recognise(e.re) } else { None };
    }
    Decomposition { blocks, eigenvalues, synthesis }
}

impl Eigenvalue {
    fn from_block(e: eigen::BlockEigen, m: usize) -> Eigenvalue {
        Eigenvalue {
            re: e.value.re,
            im: e.value.im,
            modulus: e.value.norm(),
            algebraic_multiplicity: e.algebraic,
            geometric_multiplicity: e.geometric,
            defective: e.geometric < e.algebraic,
            block: m,
            blocks: vec![m],
            exact: None,
            recognised: None,
            vectors: vec![EigenVectors { block: m, right: e.right }],
        }
    }
}

/// Merge equal eigenvalues found in different blocks: each joins the first
/// earlier distinct value within the tolerance. Candidates are looked up in
/// buckets of the real part (a match is at most the tolerance away in it), so
/// n blocks' eigenvalues are not each compared with every distinct one.
fn merge(list: Vec<Eigenvalue>) -> Vec<Eigenvalue> {
    const BUCKET: f64 = 1e-6;
    const MAX_SPAN: f64 = 64.0;
    let mut out: Vec<Eigenvalue> = Vec::new();
    let mut buckets: std::collections::HashMap<i64, Vec<usize>> = std::collections::HashMap::new();
    let key = |re: f64| (re / BUCKET).floor() as i64;
    for e in list {
        let z = e.value();
        let tol = MERGE_TOL * z.norm().max(1.0);
        let close = |t: &Eigenvalue| (t.value() - z).norm() < tol;
        let found = if (tol / BUCKET) < MAX_SPAN && z.re.is_finite() {
            // the first (lowest index) match among the buckets the tolerance
            // reaches, one more on each side against rounding at the edges
            (key(z.re - tol) - 1..=key(z.re + tol) + 1)
                .filter_map(|b| buckets.get(&b))
                .flat_map(|ids| ids.iter().copied())
                .filter(|&i| close(&out[i]))
                .min()
        } else {
            out.iter().position(close)
        };
        if let Some(i) = found {
            let t = &mut out[i];
            t.algebraic_multiplicity += e.algebraic_multiplicity;
            t.geometric_multiplicity += e.geometric_multiplicity;
            t.defective |= e.defective;
            t.blocks.extend(e.blocks);
            t.blocks.sort_unstable();
            t.block = t.blocks[0];
            t.vectors.extend(e.vectors);
        } else {
            buckets.entry(key(z.re)).or_default().push(out.len());
            out.push(e);
        }
    }
    out
}
