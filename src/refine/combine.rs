//! Things that refinement can average.

use crate::numeric::Weight;

pub trait Combine<W>: Sized {
    fn combine(terms: &[(W, &Self)]) -> Self;
}

impl<const D: usize> Combine<f64> for [f64; D] {
    fn combine(terms: &[(f64, &Self)]) -> Self {
        let mut out = [0.0; D];
        for (w, p) in terms {
            for k in 0..D {
                out[k] += w * p[k];
            }
        }
        out
    }
}

/// Outward-rounded interval points: every sum and product encloses the exact
/// one, so a refined net of enclosures encloses the refined exact net.
impl<const D: usize> Combine<crate::numeric::Interval> for [crate::numeric::Interval; D] {
    fn combine(terms: &[(crate::numeric::Interval, &Self)]) -> Self {
        let mut out = [crate::numeric::Interval::point(0.0); D];
        for (w, p) in terms {
            for k in 0..D {
                out[k] = out[k] + *w * p[k];
            }
        }
        out
    }
}

/// A sparse row of weights over some index set (for instance the vertices of
/// an earlier level): refining rows composes subdivision steps.
#[derive(Clone, Debug, PartialEq)]
pub struct SparseRow<W> {
    pub entries: Vec<(usize, W)>,
}

impl<W: Weight> SparseRow<W> {
    pub fn unit(i: usize) -> Self {
        SparseRow { entries: vec![(i, W::one())] }
    }
}

impl<W: Weight> Combine<W> for SparseRow<W> {
    /// Σ w·row, entries in increasing index order. Each index sums its
    /// contributions in the order of the terms, whichever path is taken, so
    /// the result is the same to the last bit. Rows next to a high-valence
    /// centre are dense (sqrt(3) face rules reach the centre's whole ring), so
    /// the accumulation is a flat array when the indices are dense enough and
    /// a stable sort otherwise, never a tree map.
    fn combine(terms: &[(W, &Self)]) -> Self {
        let count: usize = terms.iter().map(|(_, r)| r.entries.len()).sum();
        let Some(max) = terms.iter().flat_map(|(_, r)| r.entries.iter().map(|e| e.0)).max() else {
            return SparseRow { entries: Vec::new() };
        };
        let mut entries: Vec<(usize, W)> = Vec::new();
        if W::SUMS_IN_BATCHES {
            // each index's products collected, then summed at once
            let mut all: Vec<(usize, W)> = Vec::with_capacity(count);
            for (w, row) in terms {
                all.extend(row.entries.iter().map(|(i, x)| (*i, w.clone() * x.clone())));
            }
            all.sort_by_key(|e| e.0);
            let mut all = all.into_iter().peekable();
            while let Some((i, first)) = all.next() {
                let mut group = vec![first];
                while let Some((_, v)) = all.next_if(|e| e.0 == i) {
                    group.push(v);
                }
                entries.push((i, W::sum_all(group)));
            }
        } else if max < 4 * count + 64 {
            let mut acc: Vec<Option<W>> = vec![None; max + 1];
            for (w, row) in terms {
                for (i, x) in &row.entries {
                    let v = w.clone() * x.clone();
                    let e = acc[*i].get_or_insert_with(W::zero);
                    *e = e.clone() + v;
                }
            }
            entries.extend(acc.into_iter().enumerate().filter_map(|(i, v)| v.map(|v| (i, v))));
        } else {
            let mut all: Vec<(usize, W)> = Vec::with_capacity(count);
            for (w, row) in terms {
                all.extend(row.entries.iter().map(|(i, x)| (*i, w.clone() * x.clone())));
            }
            all.sort_by_key(|e| e.0); // stable: term order within an index
            for (i, v) in all {
                match entries.last_mut() {
                    Some((j, e)) if *j == i => *e = e.clone() + v,
                    _ => entries.push((i, W::zero() + v)),
                }
            }
        }
        entries.retain(|(_, v)| !v.is_zero());
        SparseRow { entries }
    }
}
