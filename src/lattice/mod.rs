//! Schemes on the regular lattice Z² with binary dilation and explicit (i, j)
//! coordinates (Khan–Mustafa and other non-tensor-product quad schemes whose
//! masks are not symmetric, so the mesh-based pipeline's sector charts and
//! rotation symmetry do not apply).
//!
//! A scheme is four masks, one per parity (α, β) ∈ {0,1}²:
//! `p_{2i+α, 2j+β} = Σ_{(r,s)} w_{α,β}(r,s) · p_{i+r, j+s}`.
//! Masks are generic over the weight scalar, so the same mask code yields the
//! f64 and the exact rational subdivision matrix.
//!
//! The local subdivision matrix on a window W of lattice points has one row per
//! point q ∈ W: the stencil of the *fine* point with index q (which plays the
//! role of the coarse point q after one step, the centre staying at the origin),
//! restricted to W. This is only a matrix of the scheme when W is invariant
//! (every fine point of W depends on coarse points of W only); windows are found
//! by closure under dependencies, not hard-coded.

pub mod analysis;
pub mod fit;

use std::collections::{BTreeSet, HashSet};

use crate::numeric::{Rational, Weight};

/// A lattice point (i, j), or an offset (r, s) inside a mask.
pub type Point = (i64, i64);

/// The four masks of a lattice scheme, for one weight type.
pub trait LatticeRules<W: Weight> {
    /// Mask of parity (α, β): the weights w_{α,β}(r, s) with their offsets.
    fn mask(&self, alpha: u8, beta: u8) -> Vec<(Point, W)>;
}

pub trait LatticeScheme: LatticeRules<f64> + LatticeRules<Rational> + Send + Sync {
    fn name(&self) -> &'static str;
    fn description(&self) -> &'static str;
}

/// Weight types the lattice engine evaluates masks in; lets generic code ask a
/// `&dyn LatticeScheme` for masks of either type.
pub trait LatticeWeight: Weight {
    fn mask_of(scheme: &dyn LatticeScheme, alpha: u8, beta: u8) -> Vec<(Point, Self)>;
}

impl LatticeWeight for f64 {
    fn mask_of(scheme: &dyn LatticeScheme, alpha: u8, beta: u8) -> Vec<(Point, Self)> {
        LatticeRules::<f64>::mask(scheme, alpha, beta)
    }
}

impl LatticeWeight for Rational {
    fn mask_of(scheme: &dyn LatticeScheme, alpha: u8, beta: u8) -> Vec<(Point, Self)> {
        LatticeRules::<Rational>::mask(scheme, alpha, beta)
    }
}

/// Split a fine index into (coarse index, parity): a = 2i + α with α ∈ {0, 1}.
pub fn split(a: i64) -> (i64, u8) {
    (a.div_euclid(2), a.rem_euclid(2) as u8)
}

/// Stencil of the fine point `q` over coarse points, zero weights dropped and
/// repeated offsets summed (a mask may list an offset twice).
pub fn stencil<W: LatticeWeight>(scheme: &dyn LatticeScheme, q: Point) -> Vec<(Point, W)> {
    let ((i, alpha), (j, beta)) = (split(q.0), split(q.1));
    let mut out: Vec<(Point, W)> = Vec::new();
    for ((r, s), w) in W::mask_of(scheme, alpha, beta) {
        let p = (i + r, j + s);
        match out.iter_mut().find(|(x, _)| *x == p) {
            Some(e) => e.1 = e.1.clone() + w,
            None => out.push((p, w)),
        }
    }
    out.retain(|(_, w)| !w.is_zero());
    out
}

/// Coarse points the fine point `q` depends on (non-zero weights, exact).
pub fn dependencies(scheme: &dyn LatticeScheme, q: Point) -> Vec<Point> {
    stencil::<Rational>(scheme, q).into_iter().map(|(p, _)| p).collect()
}

/// An ordered set of lattice points: the rows and columns of a local matrix.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Window {
    pub points: Vec<Point>,
}

impl Window {
    /// The rectangle [i0, i1] × [j0, j1] with i running fastest (the order of
    /// the Khan–Mustafa paper's vector p_{i-2,j-2}, p_{i-1,j-2}, ...).
    pub fn rect(i0: i64, i1: i64, j0: i64, j1: i64) -> Window {
        Window { points: (j0..=j1).flat_map(|j| (i0..=i1).map(move |i| (i, j))).collect() }
    }
    /// A set of points in the canonical order: by j, then i (i fastest).
    pub fn from_set(set: impl IntoIterator<Item = Point>) -> Window {
        let ordered: BTreeSet<(i64, i64)> = set.into_iter().map(|(i, j)| (j, i)).collect();
        Window { points: ordered.into_iter().map(|(j, i)| (i, j)).collect() }
    }
    pub fn len(&self) -> usize {
        self.points.len()
    }
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }
    /// Bounding box (i0, i1, j0, j1).
    pub fn bounds(&self) -> Option<(i64, i64, i64, i64)> {
        let is = self.points.iter().map(|p| p.0);
        let js = self.points.iter().map(|p| p.1);
        Some((is.clone().min()?, is.max()?, js.clone().min()?, js.max()?))
    }
    /// Is the window exactly its bounding rectangle?
    pub fn is_rect(&self) -> bool {
        match self.bounds() {
            Some((i0, i1, j0, j1)) => ((i1 - i0 + 1) * (j1 - j0 + 1)) as usize == self.len(),
            None => true,
        }
    }
    pub fn position(&self, p: Point) -> Option<usize> {
        self.points.iter().position(|&x| x == p)
    }
}

/// "p[i-2,j+1]": the paper's way of naming a point relative to the centre (i, j).
pub fn point_name(p: Point) -> String {
    let part = |name: char, d: i64| match d {
        0 => name.to_string(),
        d if d > 0 => format!("{name}+{d}"),
        d => format!("{name}{d}"),
    };
    format!("p[{},{}]", part('i', p.0), part('j', p.1))
}

/// The smallest invariant window containing `seed`: close under "fine point q
/// needs coarse point p". Every point's own index is a fine index of the next
/// level, so the closure is exactly the set whose refined points depend only on
/// itself. Returns an error if the closure does not stay bounded (a scheme whose
/// masks reach too far for any finite invariant window, which binary dilation
/// with finite masks excludes, but a malformed mask must not loop forever).
pub fn minimal_invariant_window(scheme: &dyn LatticeScheme, seed: &[Point]) -> Result<Window, String> {
    const LIMIT: usize = 100_000;
    let mut set: HashSet<Point> = seed.iter().copied().collect();
    let mut stack: Vec<Point> = seed.to_vec();
    while let Some(q) = stack.pop() {
        for p in dependencies(scheme, q) {
            if set.insert(p) {
                stack.push(p);
                if set.len() > LIMIT {
                    return Err(format!("{}: no invariant window of at most {LIMIT} points", scheme.name()));
                }
            }
        }
    }
    Ok(Window::from_set(set))
}

/// The pairs (fine point of the window, coarse point outside it) that break
/// invariance; empty when the window is invariant.
pub fn invariance_defects(scheme: &dyn LatticeScheme, w: &Window) -> Vec<(Point, Point)> {
    let inside: HashSet<Point> = w.points.iter().copied().collect();
    let mut out = Vec::new();
    for &q in &w.points {
        for p in dependencies(scheme, q) {
            if !inside.contains(&p) {
                out.push((q, p));
            }
        }
    }
    out
}

/// Dense local subdivision matrix on the window, rows and columns in the
/// window's order. Error (naming the first escaping dependency) when the window
/// is not invariant, because the restriction would not be a subdivision matrix.
pub fn local_matrix<W: LatticeWeight>(scheme: &dyn LatticeScheme, w: &Window) -> Result<Vec<Vec<W>>, String> {
    let n = w.len();
    let mut m = vec![vec![W::zero(); n]; n];
    for (row, &q) in w.points.iter().enumerate() {
        for (p, wt) in stencil::<W>(scheme, q) {
            let col = w.position(p).ok_or_else(|| {
                format!(
                    "{}: window of {n} points is not invariant: fine point {} needs {}",
                    scheme.name(),
                    point_name(q),
                    point_name(p)
                )
            })?;
            m[row][col] = m[row][col].clone() + wt;
        }
    }
    Ok(m)
}

/// The window whose points hold every control point influencing the limit
/// surface over the cells around the origin, [-radius, radius]², closed under
/// dependencies (the lattice analogue of ARCHITECTURE.md's analysis neighbourhood).
/// Found by tracking dependencies: the fine points of level k inside the region
/// are pulled back level by level to the control points of level 0; the union
/// grows with k and is stationary once two consecutive levels give the same set.
pub fn analysis_window(scheme: &dyn LatticeScheme, radius: i64) -> Result<Window, String> {
    const MAX_LEVELS: u32 = 9;
    let mut previous: Option<HashSet<Point>> = None;
    for k in 1..=MAX_LEVELS {
        let r = radius << k;
        let mut level: HashSet<Point> = (-r..=r).flat_map(|i| (-r..=r).map(move |j| (i, j))).collect();
        for _ in 0..k {
            let mut coarser = HashSet::new();
            for &q in &level {
                coarser.extend(dependencies(scheme, q));
            }
            level = coarser;
        }
        if previous.as_ref() == Some(&level) {
            level.insert((0, 0));
            let seed: Vec<Point> = level.into_iter().collect();
            return minimal_invariant_window(scheme, &seed);
        }
        previous = Some(level);
    }
    Err(format!("{}: the control points of the limit surface near the origin did not settle", scheme.name()))
}

/// Every built-in lattice scheme.
pub struct LatticeEntry {
    pub name: &'static str,
    pub description: &'static str,
    pub build: fn() -> Box<dyn LatticeScheme>,
}

pub fn registry() -> Vec<LatticeEntry> {
    vec![crate::schemes::khan_mustafa::entry(), crate::schemes::khan_mustafa::cubic_entry()]
}

pub fn find(name: &str) -> Option<LatticeEntry> {
    registry().into_iter().find(|e| e.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_rounds_towards_minus_infinity() {
        // a = 2i + α must hold for negative fine indices too
        assert_eq!(split(-3), (-2, 1));
        assert_eq!(split(-2), (-1, 0));
        assert_eq!(split(5), (2, 1));
    }

    #[test]
    fn windows_are_ordered_with_i_fastest() {
        let w = Window::from_set([(1, 0), (0, 1), (0, 0), (1, 1)]);
        assert_eq!(w.points, vec![(0, 0), (1, 0), (0, 1), (1, 1)]);
        assert_eq!(w, Window::rect(0, 1, 0, 1));
        assert!(w.is_rect());
        assert!(!Window::from_set([(0, 0), (2, 0)]).is_rect());
        assert_eq!(point_name((-2, 1)), "p[i-2,j+1]");
    }
}
