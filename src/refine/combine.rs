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
    fn combine(terms: &[(W, &Self)]) -> Self {
        let mut acc: std::collections::BTreeMap<usize, W> = Default::default();
        for (w, row) in terms {
            for (i, x) in &row.entries {
                let v = w.clone() * x.clone();
                let e = acc.entry(*i).or_insert_with(W::zero);
                *e = e.clone() + v;
            }
        }
        SparseRow { entries: acc.into_iter().filter(|(_, v)| !v.is_zero()).collect() }
    }
}
