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
    // S is real, so block g − m is the complex conjugate of block m (its
    // entries are sums of the same real weights times conjugate powers of
    // ω): its eigenvalues and eigenvectors are the conjugates of block m's.
    // Only blocks 0..=g/2 are solved; the rest are read off their partners
    // (half the eigenproblems at large valences). The blocks are independent
    // eigenproblems: solved side by side, and collected in block order, so
    // the result does not depend on scheduling.
    let g = orbits.group_order;
    let partner = |m: usize| if m > g / 2 { Some(g - m) } else { None };
    let mut solved: Vec<Option<Result<Vec<eigen::BlockEigen>, Error>>> = blocks
        .par_iter()
        .map(|b| if partner(b.index).is_some() { None } else { Some(eigen::block_eigen(&b.matrix)) })
        .collect();
    for m in 0..blocks.len() {
        if let Some(p) = partner(blocks[m].index) {
            let conjugated = match &solved[p] {
                Some(Ok(list)) => Ok(list.iter().map(eigen::BlockEigen::conjugate).collect()),
                Some(Err(e)) => Err(e.clone()),
                None => unreachable!("a partner below g/2 is solved"),
            };
            solved[m] = Some(conjugated);
        }
    }
    let solved = solved.into_iter().map(|s| s.expect("every block solved or conjugated"));
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A rotation-symmetric real matrix of order g = 7 (a centre and two
    /// free orbits, pseudo-random weights): every block g − m has the
    /// conjugate spectrum of block m when both are solved on their own, and
    /// the decomposition (which solves blocks 0..=g/2 and conjugates the
    /// rest) lists the same eigenvalues as solving all g blocks.
    #[test]
    fn conjugate_blocks_have_conjugate_spectra() {
        let g = 7;
        let mut member = vec![(0, 0)];
        member.extend((0..g).map(|t| (1, t)));
        member.extend((0..g).map(|t| (2, t)));
        let orbits =
            Orbits { group_order: g, member, representative: vec![0, 1, 1 + g], fixed: vec![true, false, false] };
        let mut state: u64 = 12345;
        let mut weight = || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let size = 1 + 2 * g;
        let rows: Vec<Vec<(usize, f64)>> = (0..3).map(|_| (0..size).map(|c| (c, weight())).collect()).collect();
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(|r| r.as_slice()).collect();
        let blocks = fourier_blocks_from_rows(&refs, &orbits);
        let values = |b: &Mat<c64>| -> Vec<c64> {
            eigen::block_eigen(b).unwrap().iter().flat_map(|e| std::iter::repeat_n(e.value, e.algebraic)).collect()
        };
        // equal as multisets: each value matched to an unused one within 1e-10
        let close = |a: &[c64], b: &[c64]| {
            let mut used = vec![false; b.len()];
            a.len() == b.len()
                && a.iter().all(|x| match (0..b.len()).find(|&j| !used[j] && (x - b[j]).norm() < 1e-10) {
                    Some(j) => {
                        used[j] = true;
                        true
                    }
                    None => false,
                })
        };
        let mut all = Vec::new();
        for m in 0..g {
            let own = values(&blocks[m].matrix);
            let partner: Vec<c64> = values(&blocks[(g - m) % g].matrix).iter().map(|z| z.conj()).collect();
            assert!(close(&own, &partner), "block {m}");
            all.extend(own);
        }
        let d = decompose_dft(&refs, orbits).unwrap();
        let listed: Vec<c64> =
            d.eigenvalues.iter().flat_map(|e| std::iter::repeat_n(e.value(), e.algebraic_multiplicity)).collect();
        assert!(close(&listed, &all));
    }
}
