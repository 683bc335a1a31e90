//! With the rotation P of the neighbourhood by `period` sectors (P^g = I,
//! PS = SP, g = n / period), vertices fall into orbits {(t, a) : t = 0..g-1}
//! plus fixed points (the centre). In the basis u_a^m = Σ_t ω^{mt} e_(t,a),
//! ω = exp(2πi/g), S is block diagonal: block m has entries
//!
//!   B_m[a][b] = Σ_τ S[(0,a), (τ,b)] ω^{mτ},
//!
//! and fixed points belong to block 0 only (their row sums over an orbit).
//! This basis is not normalised on purpose: block 0 of a rational S stays
//! rational, so the exact path can use it.

use faer::c64;
use faer::Mat;
use rayon::prelude::*;

use crate::numeric::Rational;

use crate::matrix::{FullMatrix, LocalMatrix};
use crate::neighbourhood::{NeighbourhoodKind, VertexLabel};
use crate::numeric::Weight;

/// Orbit structure of a labelled neighbourhood under rotation by `period` sectors.
#[derive(Clone, Debug)]
pub struct Orbits {
    pub group_order: usize,
    /// for each matrix index: (orbit, position t in the orbit); fixed points have t = 0
    pub member: Vec<(usize, usize)>,
    /// for each orbit: the matrix index of its t = 0 representative
    pub representative: Vec<usize>,
    pub fixed: Vec<bool>,
}

impl Orbits {
    pub fn new<W: Weight>(m: &LocalMatrix<W>, period: usize, sectors: usize) -> Orbits {
        Orbits::from_labels(&m.labels, period, sectors)
    }
    /// The orbits of the vertices with these labels (matrix order): the
    /// labels alone decide them, so the rows of S can be assembled after.
    pub fn from_labels(labels: &[VertexLabel], period: usize, sectors: usize) -> Orbits {
        let g = sectors / period;
        let mut key_to_orbit = std::collections::HashMap::new();
        let mut member = Vec::with_capacity(labels.len());
        let mut representative = Vec::new();
        let mut fixed = Vec::new();
        let mut order: Vec<usize> = (0..labels.len()).collect();
        // make representatives the t = 0 copies: visit sector < period first
        order.sort_by_key(|&k| labels[k].sector / period);
        let mut tmp = vec![(0, 0); labels.len()];
        for &k in &order {
            let l = &labels[k];
            let is_fixed = l.i == 0 && l.j == 0;
            let key = if is_fixed { (usize::MAX, 0, 0) } else { (l.sector % period, l.i, l.j) };
            let orbit = *key_to_orbit.entry(key).or_insert_with(|| {
                representative.push(k);
                fixed.push(is_fixed);
                representative.len() - 1
            });
            tmp[k] = (orbit, if is_fixed { 0 } else { l.sector / period });
        }
        member.extend(tmp);
        Orbits { group_order: g, member, representative, fixed }
    }
    /// Whether the rotation acts freely off the centre: every orbit that is
    /// not a fixed point has exactly one member at each position t = 0..g−1.
    /// The Fourier blocks count an orbit once per block, so an orbit with a
    /// missing or doubled position would make them a different matrix from S
    /// (with the wrong dimension); a proof checks this instead of assuming it.
    pub fn check_free(&self) -> Result<(), String> {
        let g = self.group_order;
        let mut seen = vec![vec![0usize; g.max(1)]; self.num_orbits()];
        for &(o, t) in &self.member {
            if t >= g.max(1) {
                return Err(format!("a point of orbit {o} has position {t} outside 0..{g}"));
            }
            seen[o][t] += 1;
        }
        for (o, counts) in seen.iter().enumerate() {
            let expected = |t: usize| if self.fixed[o] { usize::from(t == 0) } else { 1 };
            if let Some(t) = (0..counts.len()).find(|&t| counts[t] != expected(t)) {
                return Err(format!(
                    "orbit {o} ({}) has {} member(s) at position {t}, not {}",
                    if self.fixed[o] { "a fixed point" } else { "moving" },
                    counts[t],
                    expected(t)
                ));
            }
        }
        Ok(())
    }
    pub fn num_orbits(&self) -> usize {
        self.representative.len()
    }
    /// Orbits present in block m (fixed points only in block 0).
    pub fn block_orbits(&self, m: usize) -> Vec<usize> {
        (0..self.num_orbits()).filter(|&o| m == 0 || !self.fixed[o]).collect()
    }
}

#[derive(Clone, Debug)]
pub struct FourierBlock {
    pub index: usize,
    /// orbit of each row/column
    pub orbits: Vec<usize>,
    pub matrix: Mat<c64>,
}

pub fn omega_pow(m: usize, t: usize, g: usize) -> c64 {
    let k = (m * t) % g;
    // exact values at quarter turns keep real blocks exactly real
    if (4 * k).is_multiple_of(g) {
        return [c64::new(1.0, 0.0), c64::new(0.0, 1.0), c64::new(-1.0, 0.0), c64::new(0.0, -1.0)][4 * k / g];
    }
    let theta = 2.0 * std::f64::consts::PI * k as f64 / g as f64;
    c64::new(theta.cos(), theta.sin())
}

/// All g Fourier blocks of a rotation-symmetric local matrix.
pub fn fourier_blocks(s: &LocalMatrix<f64>, orbits: &Orbits) -> Vec<FourierBlock> {
    let rows: Vec<&[(usize, f64)]> = orbits.representative.iter().map(|&k| s.rows[k].as_slice()).collect();
    fourier_blocks_from_rows(&rows, orbits)
}

/// All g Fourier blocks from the representative rows alone: `rows[o]` is the
/// row of S (over all columns) of orbit o's representative. The other rows
/// are rotations of these, so nothing else of S is needed.
/// Blocks built in one run of [`fourier_blocks_from_rows`]: enough work per
/// run to outweigh handing it to another thread.
const BLOCKS_PER_RUN: usize = 64;

pub fn fourier_blocks_from_rows(rows: &[&[(usize, f64)]], orbits: &Orbits) -> Vec<FourierBlock> {
    let g = orbits.group_order;
    // ω^k for every k: the same values `omega_pow` gives (it depends on m·t
    // mod g only), computed once instead of a cos and sin per entry and block.
    // A fixed point's column has τ = 0, so its factor is ω^0 = 1 exactly.
    let powers: Vec<c64> = (0..g).map(|k| omega_pow(k, 1, g)).collect();
    // block coordinates: block 0 holds every orbit, the others all but the fixed ones
    let position = |m: usize| {
        let mut pos = vec![usize::MAX; orbits.num_orbits()];
        for (k, &o) in orbits.block_orbits(m).iter().enumerate() {
            pos[o] = k;
        }
        pos
    };
    let (pos0, pos1) = (position(0), position(1.min(g - 1)));
    // per row entry: its column in block 0 and in the other blocks, τ, the
    // weight, and k = m·τ mod g for the current block m, advanced by τ from
    // block to block (a division per entry and block would cost more than
    // the rest of the sum)
    let entries: Vec<Vec<(usize, usize, usize, f64)>> = rows
        .iter()
        .map(|row| {
            row.iter()
                .map(|&(col, w)| {
                    let (ob, tau) = orbits.member[col];
                    (pos0[ob], pos1[ob], tau, w)
                })
                .collect()
        })
        .collect();
    // blocks are independent: contiguous runs of them are built side by
    // side, each run starting its k = m·τ mod g at its first block
    let runs = g.div_ceil(BLOCKS_PER_RUN);
    let built: Vec<Vec<FourierBlock>> = (0..runs)
        .into_par_iter()
        .map(|run| {
            let first = run * BLOCKS_PER_RUN;
            let mut turn: Vec<Vec<usize>> =
                entries.iter().map(|r| r.iter().map(|e| (first % g) * e.2 % g).collect()).collect();
            let mut blocks = Vec::with_capacity(BLOCKS_PER_RUN);
            for m in first..(first + BLOCKS_PER_RUN).min(g) {
                let list = orbits.block_orbits(m);
                let size = list.len();
                let mut acc = vec![c64::new(0.0, 0.0); size * size];
                for (ra, &a) in list.iter().enumerate() {
                    for (&(cb0, cbm, tau, w), k) in entries[a].iter().zip(turn[a].iter_mut()) {
                        let cb = if m == 0 { cb0 } else { cbm };
                        // a fixed point's column outside block 0: its contribution sums to zero
                        if cb != usize::MAX {
                            acc[ra * size + cb] += powers[*k] * w;
                        }
                        // every row but a fixed point's is in every block, so its k
                        // is advanced here; a fixed point's row is only used in block 0
                        *k += tau;
                        if *k >= g {
                            *k -= g;
                        }
                    }
                }
                let matrix = Mat::<c64>::from_fn(size, size, |i, j| acc[i * size + j]);
                blocks.push(FourierBlock { index: m, orbits: list, matrix });
            }
            blocks
        })
        .collect();
    built.into_iter().flatten().collect()
}

/// Block 0 in exact arithmetic (real and rational when S is).
pub fn block_zero_exact(s: &LocalMatrix<crate::numeric::Rational>, orbits: &Orbits) -> crate::numeric::exact::QMatrix {
    let rows: Vec<&[(usize, Rational)]> = orbits.representative.iter().map(|&k| s.rows[k].as_slice()).collect();
    block_zero_exact_from_rows(&rows, orbits)
}

/// Block 0 in exact arithmetic from the representative rows (`rows[o]`: the
/// row of orbit o's representative, as in [`fourier_blocks_from_rows`]).
pub fn block_zero_exact_from_rows(rows: &[&[(usize, Rational)]], orbits: &Orbits) -> crate::numeric::exact::QMatrix {
    let list = orbits.block_orbits(0);
    let mut pos = vec![usize::MAX; orbits.num_orbits()];
    for (k, &o) in list.iter().enumerate() {
        pos[o] = k;
    }
    let mut q = crate::numeric::exact::QMatrix::zeros(list.len());
    for (ra, &a) in list.iter().enumerate() {
        for (col, w) in rows[a] {
            let cb = orbits.member[*col].0;
            let idx = pos[cb];
            let v = q.get(ra, idx) + w;
            q.set(ra, idx, v);
        }
    }
    q
}

/// The whole exact matrix from its representative rows, assembled on first
/// use by rotating them: row (t, a) is row (0, a) with every column (τ, b)
/// moved to (τ + t, b). S commutes with the rotation exactly, so this is the
/// matrix [`assemble`] gives, without evaluating the rules again.
pub fn lazy_full_by_rotation<W: Weight>(
    labels: Vec<VertexLabel>,
    kind: NeighbourhoodKind,
    orbits: &Orbits,
    rep_rows: Vec<Vec<(usize, W)>>,
) -> FullMatrix<W> {
    let orbits = orbits.clone();
    FullMatrix::lazy(move || {
        let g = orbits.group_order;
        let mut index = vec![vec![usize::MAX; g]; orbits.num_orbits()];
        for (k, &(o, t)) in orbits.member.iter().enumerate() {
            index[o][t] = k;
        }
        let rows = orbits
            .member
            .iter()
            .map(|&(o, t)| {
                let mut row: Vec<(usize, W)> = rep_rows[o]
                    .iter()
                    .map(|(col, w)| {
                        let (ob, tau) = orbits.member[*col];
                        let c = if orbits.fixed[ob] { *col } else { index[ob][(tau + t) % g] };
                        (c, w.clone())
                    })
                    .collect();
                row.sort_by_key(|e| e.0);
                row
            })
            .collect();
        LocalMatrix { kind, labels, rows }
    })
}

#[cfg(test)]
mod free_orbit_tests {
    use super::Orbits;

    #[test]
    fn orbits_must_be_free_off_the_centre() {
        // a centre and two orbits of a rotation of order 3
        let good = Orbits {
            group_order: 3,
            member: vec![(0, 0), (1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (2, 2)],
            representative: vec![0, 1, 4],
            fixed: vec![true, false, false],
        };
        assert!(good.check_free().is_ok());
        // an orbit missing a member: its Fourier blocks would not be S
        let mut missing = good.clone();
        missing.member.pop();
        assert!(missing.check_free().unwrap_err().contains("orbit 2"));
        // a doubled position
        let mut doubled = good.clone();
        doubled.member[3] = (1, 1);
        assert!(doubled.check_free().is_err());
        // a fixed point that moves
        let mut moving = good;
        moving.member[0] = (0, 1);
        assert!(moving.check_free().is_err());
    }
}
