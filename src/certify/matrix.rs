//! The certified matrix: rows of S in interval arithmetic, their Fourier
//! blocks as interval matrices, and the structural facts the spectral proof
//! uses, checked on the same rows, exactly where the rows are exact (in Q, or
//! in a cyclotomic field Q(ζ_N) where they hold cos(2πk/n)).
//!
//! The rows come from the scheme's own rules evaluated with `Interval`
//! weights (`matrix::local::assemble_rows`): every weight, cos(2πk/n)
//! included, is enclosed, and so is every sum and product of the stencil
//! composition. So the interval rows enclose the rows of the true S, not of a
//! rounded one. The Fourier blocks B_m[a][b] = Σ_τ S[(0,a),(τ,b)] ω^{mτ} (the
//! formula of `dft::blocks`, on the same orbits) are then enclosed with
//! ω^k = cos(2πk/g) + i sin(2πk/g) enclosed as well.

use super::complex::{CInterval, CIntervalMatrix};
use crate::dft::Orbits;
use crate::neighbourhood::VertexLabel;
use crate::numeric::interval::cos_sin_2pi;
use crate::numeric::{Cyclotomic, Interval, Weight};
use serde::Serialize;
use std::collections::HashMap;

/// Rows of S with interval entries, by matrix index, each over all columns.
pub type IntervalRows = Vec<Vec<(usize, Interval)>>;

/// The same rows exactly (the structural identities are then checked
/// exactly, whatever the intervals' widths): rational rows, and rows whose
/// weights hold cos(2πk/n), as elements of a cyclotomic field (a rational
/// row's entries are elements of Q = Q(ζ_1)). `None` for a row with a weight
/// known in floating point only (a float parameter or expression).
pub type ExactRows = Vec<Option<Vec<(usize, Cyclotomic)>>>;

/// The work an orbit's exact rotation check may take: its members times the
/// entries of its representative's row times N of their field (a bound of
/// the coefficients of each entry). Past it (Doo–Sabin's ring 0, whose rows
/// are dense, near valence 200) the orbit's rows are compared on their
/// enclosures, and the premise says so: the cost of the exact rows grows
/// with the square of the valence times the field's degree.
pub const MAX_EXACT_ORBIT_WORK: u64 = 1 << 23;

/// How a structural identity of S was checked.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "status", content = "detail")]
pub enum Check {
    /// every entry involved is exact (rational, or an element of a
    /// cyclotomic field) and the identity holds exactly
    Exact,
    /// the identity holds to interval overlap: an entry involved is known in
    /// floating point only (or its exact rows are beyond the certificate's
    /// work bound, [`MAX_EXACT_ORBIT_WORK`]), so equality is an
    /// identity of the rules' formulas that enclosures can confirm only to
    /// their width
    Overlap,
    /// the identity is proven false, or cannot be stated (the witness)
    Fails(String),
}

impl Check {
    /// Both hold: the weaker status of the two (a failure wins).
    pub fn and(self, other: Check) -> Check {
        match (self, other) {
            (Check::Fails(a), _) => Check::Fails(a),
            (_, Check::Fails(b)) => Check::Fails(b),
            (Check::Overlap, _) | (_, Check::Overlap) => Check::Overlap,
            _ => Check::Exact,
        }
    }
    pub fn holds(&self) -> bool {
        !matches!(self, Check::Fails(_))
    }
}

/// Compare two enclosed numbers that should be equal.
fn equal(a: &Interval, b: &Interval) -> Check {
    if a.is_point() && a == b {
        Check::Exact
    } else if a.overlaps(b) {
        Check::Overlap
    } else {
        Check::Fails(format!("[{:e}, {:e}] ≠ [{:e}, {:e}]", a.lo, a.hi, b.lo, b.hi))
    }
}

/// Affine invariance: every row of S sums to 1, so the vector of ones is an
/// eigenvector of eigenvalue 1 (checked on the given rows: with rotation
/// symmetry the representative rows are all the rows up to rotation).
pub fn row_sums(rows: &IntervalRows, exact: &ExactRows, labels: &[VertexLabel], which: &[usize]) -> Check {
    let one = Interval::point(1.0);
    let mut all = Check::Exact;
    for ((row, exact_row), &k) in rows.iter().zip(exact).zip(which) {
        if let Some(e) = exact_row {
            let sum = e.iter().fold(Cyclotomic::zero(), |s, (_, w)| s + w.clone());
            if sum != Cyclotomic::one() {
                return Check::Fails(format!("the row of {} sums to {sum}, not 1", labels[k].name));
            }
            continue;
        }
        let sum = row.iter().fold(Interval::point(0.0), |s, (_, w)| s + *w);
        let c = match equal(&sum, &one) {
            Check::Fails(_) => {
                Check::Fails(format!("the row of {} sums to [{:.17e}, {:.17e}], not 1", labels[k].name, sum.lo, sum.hi))
            }
            c => c,
        };
        all = all.and(c);
        if !all.holds() {
            break;
        }
    }
    all
}

/// The reflection of the neighbourhood about axis `axis`: sector s ↦
/// axis − s (mod n) with the chart coordinates (i, j) swapped, a point that
/// lands on the next spoke (i = 0) relabelled in the sector that owns that
/// spoke. Axis n − 1 reflects across the spoke between sector n − 1 and
/// sector 0; axis 0 across the bisector of sector 0 (a mixed face sequence
/// such as QTQTQT has only reflections of that kind). `None` when a
/// reflected point is not in the neighbourhood (no such mirror).
pub fn mirror_map(labels: &[VertexLabel], sectors: usize, axis: usize) -> Option<Vec<usize>> {
    let n = sectors as i64;
    let key = |l: &VertexLabel| (if l.i == 0 && l.j == 0 { 0 } else { l.sector as i64 }, l.i, l.j, l.ring);
    let index: HashMap<(i64, i64, i64, usize), usize> = labels.iter().enumerate().map(|(k, l)| (key(l), k)).collect();
    labels
        .iter()
        .map(|l| {
            if l.i == 0 && l.j == 0 {
                return index.get(&key(l)).copied();
            }
            let (s, i, j) = ((axis as i64 - l.sector as i64).rem_euclid(n), l.j, l.i);
            let (s, i, j) = if i == 0 && j > 0 { ((s + 1).rem_euclid(n), j, 0) } else { (s, i, j) };
            index.get(&(s, i, j, l.ring)).copied()
        })
        .collect()
}

/// Mirror symmetry of S away from the fixed points: S[Q(r), Q(c)] = S[r, c]
/// for the reflection Q and every point r, c off the centre, where Q with
/// the rotation P satisfies QPQ = P⁻¹. Then Q maps Fourier block m onto block
/// −m, and those blocks (m ≠ 0) involve no fixed point, so the spectrum of
/// B_m equals that of B_{−m} = conj(B_m): closed under conjugation. Checked
/// on the representative rows `rows` (orbit o's row at `rows[o]`), every
/// other row being a rotation of one of them; exactly where both rows are
/// exact. Returns the check and the axis of the reflection that holds
/// (`mirror_map`'s).
pub fn mirror_symmetry(
    rows: &IntervalRows,
    exact: &ExactRows,
    orbits: &Orbits,
    labels: &[VertexLabel],
    sectors: usize,
) -> (Check, Option<usize>) {
    // any reflection will do: the spoke axis first (every rotation-symmetric
    // sequence of equal faces has it), then every other axis; the first that
    // maps the neighbourhood onto itself and commutes with S decides
    let mut first_failure = None;
    for axis in std::iter::once(sectors - 1).chain(0..sectors - 1) {
        let Some(q) = mirror_map(labels, sectors, axis) else { continue };
        match mirror_symmetry_about(&q, rows, exact, orbits, labels) {
            Check::Fails(why) => {
                first_failure.get_or_insert(why);
            }
            holds => return (holds, Some(axis)),
        }
    }
    (Check::Fails(first_failure.unwrap_or_else(|| "the neighbourhood has no mirror image of itself".into())), None)
}

/// [`mirror_symmetry`] for one reflection `q` of the labels.
fn mirror_symmetry_about(
    q: &[usize],
    rows: &IntervalRows,
    exact: &ExactRows,
    orbits: &Orbits,
    labels: &[VertexLabel],
) -> Check {
    let g = orbits.group_order;
    let index = orbit_index(orbits);
    // Q must be an involution with QPQ = P⁻¹ (P: one step of the rotation)
    let rotate = |k: usize, steps: usize| {
        let (o, t) = orbits.member[k];
        if orbits.fixed[o] {
            k
        } else {
            index[o][(t + steps) % g]
        }
    };
    let reflection = (0..q.len()).all(|k| q[q[k]] == k && q[rotate(q[k], 1)] == rotate(k, g - 1));
    if !reflection {
        return Check::Fails("the mirror image of the labels is not a reflection of the rotation group".into());
    }
    let off_centre = |col: &usize| !orbits.fixed[orbits.member[*col].0];
    let lookup: Vec<HashMap<usize, Interval>> =
        rows.iter().map(|r| r.iter().filter(|e| off_centre(&e.0)).copied().collect()).collect();
    let exact_lookup: Vec<Option<HashMap<usize, Cyclotomic>>> =
        exact.iter().map(|r| r.as_ref().map(|r| r.iter().filter(|e| off_centre(&e.0)).cloned().collect())).collect();
    // S[(t1, o1), c] = S[(0, o1), c rotated back by t1]: (orbit, column)
    let rotate_back = |row: usize, col: usize| -> Option<(usize, usize)> {
        let (o1, t1) = orbits.member[row];
        let (o2, t2) = orbits.member[col];
        let c = index[o2][(t2 + g - t1) % g];
        (c != usize::MAX).then_some((o1, c))
    };
    let mut all = Check::Exact;
    for (o, row) in rows.iter().enumerate() {
        let r = orbits.representative[o];
        if orbits.fixed[o] {
            continue;
        }
        let mirrored_row = q[r];
        let mirrored_len = lookup[orbits.member[mirrored_row].0].len();
        if mirrored_len != lookup[o].len() {
            return Check::Fails(format!(
                "the rows of {} and of its mirror image {} have different supports",
                labels[r].name, labels[mirrored_row].name
            ));
        }
        for (col, w) in row.iter().filter(|e| off_centre(&e.0)) {
            let Some((o1, c)) = rotate_back(mirrored_row, q[*col]) else {
                return Check::Fails(format!("no mirror image of {} in the neighbourhood", labels[*col].name));
            };
            if let (Some(a), Some(b)) = (&exact_lookup[o], &exact_lookup[o1]) {
                let zero = Cyclotomic::zero();
                if a.get(col).unwrap_or(&zero) != b.get(&c).unwrap_or(&zero) {
                    return Check::Fails(format!(
                        "S[{}, {}] and its mirror image S[{}, {}] differ",
                        labels[r].name, labels[*col].name, labels[mirrored_row].name, labels[q[*col]].name
                    ));
                }
                continue;
            }
            let m = lookup[o1].get(&c).copied().unwrap_or(Interval::point(0.0));
            all = all.and(match equal(w, &m) {
                Check::Fails(why) => Check::Fails(format!(
                    "S[{}, {}] and its mirror image S[{}, {}] differ: {why}",
                    labels[r].name, labels[*col].name, labels[mirrored_row].name, labels[q[*col]].name
                )),
                c => c,
            });
            if !all.holds() {
                return all;
            }
        }
    }
    all
}

/// Matrix index of (orbit, position): `index[o][t]` (fixed points at t = 0).
fn orbit_index(orbits: &Orbits) -> Vec<Vec<usize>> {
    let mut index = vec![vec![usize::MAX; orbits.group_order]; orbits.num_orbits()];
    for (k, &(o, t)) in orbits.member.iter().enumerate() {
        index[o][t] = k;
    }
    index
}

/// Rotation symmetry of S, PS = SP, which the Fourier blocks rest on: every
/// row (t, a) of S (`all[k]` for matrix index k, all rows) is the row of its
/// representative (0, a) with every column moved on by t, and a fixed point's
/// row is invariant under the rotation. Checked on the rows `which` (matrix
/// indices), exactly where the rows involved are exact (`exact[k]`, indexed
/// by matrix index; rows not at hand are `None`), else on the intervals.
pub fn rotation_symmetry(
    all: &IntervalRows,
    exact: &ExactRows,
    which: &[usize],
    orbits: &Orbits,
    labels: &[VertexLabel],
) -> Check {
    let g = orbits.group_order;
    let index = orbit_index(orbits);
    let moved = |col: usize, t: usize| {
        let (o, tau) = orbits.member[col];
        if orbits.fixed[o] {
            col
        } else {
            index[o][(tau + t) % g]
        }
    };
    fn sorted<W: Clone>(row: impl Iterator<Item = (usize, W)>) -> Vec<(usize, W)> {
        let mut v: Vec<(usize, W)> = row.collect();
        v.sort_by_key(|e| e.0);
        v
    }
    let mut status = Check::Exact;
    for &k in which {
        let (o, t) = orbits.member[k];
        // the row that row k must equal: the representative's moved on by t,
        // or for a fixed point its own row moved on by one step
        let (source, steps) = if orbits.fixed[o] { (k, 1) } else { (orbits.representative[o], t) };
        let fails =
            || Check::Fails(format!("the row of {} is not the rotated row of {}", labels[k].name, labels[source].name));
        if let (Some(target), Some(from)) = (&exact[k], &exact[source]) {
            if sorted(from.iter().map(|(c, w)| (moved(*c, steps), w.clone()))) != sorted(target.iter().cloned()) {
                return fails();
            }
            continue;
        }
        let rotated = sorted(all[source].iter().map(|(c, w)| (moved(*c, steps), *w)));
        let row = sorted(all[k].iter().copied());
        if rotated.len() != row.len() || rotated.iter().zip(&row).any(|(a, b)| a.0 != b.0 || !a.1.overlaps(&b.1)) {
            return fails();
        }
        status = status.and(Check::Overlap);
    }
    status
}

/// The interval Fourier blocks of S from its representative rows (`rows[o]`:
/// the row of orbit o's representative), in block order.
pub fn fourier_blocks(rows: &IntervalRows, orbits: &Orbits) -> Vec<(usize, CIntervalMatrix)> {
    let g = orbits.group_order;
    let powers: Vec<CInterval> = (0..g)
        .map(|k| {
            let (c, s) = cos_sin_2pi(k as i64, g as i64);
            CInterval::new(c, s)
        })
        .collect();
    (0..g)
        .map(|m| {
            let list = orbits.block_orbits(m);
            let mut pos = vec![usize::MAX; orbits.num_orbits()];
            for (k, &o) in list.iter().enumerate() {
                pos[o] = k;
            }
            let mut b = CIntervalMatrix::zeros(list.len());
            for (ra, &a) in list.iter().enumerate() {
                for (col, w) in &rows[a] {
                    let (ob, tau) = orbits.member[*col];
                    // a fixed point's column outside block 0 sums to zero
                    if pos[ob] == usize::MAX {
                        continue;
                    }
                    let term = powers[(m * tau) % g].scale(*w);
                    let e = b.at(ra, pos[ob]);
                    *e = *e + term;
                }
            }
            (m, b)
        })
        .collect()
}

/// The whole interval matrix (no rotation symmetry), as one real block.
pub fn whole_matrix(rows: &IntervalRows) -> CIntervalMatrix {
    let mut b = CIntervalMatrix::zeros(rows.len());
    for (i, row) in rows.iter().enumerate() {
        for (col, w) in row {
            let e = b.at(i, *col);
            *e = *e + CInterval::real(*w);
        }
    }
    b
}
