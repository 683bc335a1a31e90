//! Invariant windows and influence sets, written once for every point type.
//!
//! A stationary binary scheme on a grid maps coarse points to fine points by a
//! dilation about the centre. Each fine point q is a combination of coarse
//! points, its *dependencies*. A window W (a finite set of points) is
//! *invariant* when every fine point that stands for a point of W depends on
//! coarse points of W only; then the restriction of one step to W is a square
//! matrix, the local subdivision matrix.
//!
//! The routines below need only two things of a scheme, the `Refinement`
//! trait: the dependencies of a fine point, and the successor map (the fine
//! point that plays the role of a coarse point after one step). Windows come
//! out of these by closure; nothing is typed in per scheme.
//!
//! - `invariant_closure`: the smallest invariant window containing a seed.
//! - `influence_set`: the coarse points that influence the limit over a region
//!   (fine points of level L over the region, pulled back L levels), collected
//!   over L until the union stops growing.
//! - `assemble`: the local matrix (`engine::local::LocalMatrix`) on an
//!   invariant window.
//!
//! On Z² (`crate::lattice`, point (i, j)) and Z (`crate::curves`, point i) the
//! centre is the origin and the successor is the identity: the fine point with
//! index q sits where the coarse point q sat, at half the scale.
//!
//! The mesh pipeline (`crate::neighbourhood::discovery`) uses the same
//! `invariant_closure`: its points are vertex ids of the analysis patch
//! (orbit representatives), `successor` is the vertex at the same lattice
//! coordinates after one analysis step (a lookup that fails when the patch is
//! too small, whereupon discovery grows the patch and retries), and
//! `dependencies` is the support of the composed stencil of that vertex. Its
//! influence set is collected by a backward walk of its own, because each
//! level of a mesh is a different (pruned) mesh, not one grid.

use std::collections::BTreeSet;
use std::fmt;

use super::local::LocalMatrix;
use crate::error::Error;
use crate::numeric::Weight;

/// What the closure routines need of a stationary binary scheme.
pub trait Refinement {
    /// A grid point: (i, j) on Z², i on Z, a vertex label on a mesh patch.
    type Point: Clone + Ord + fmt::Debug;

    /// The coarse points that fine point `q` depends on (non-zero weights).
    fn dependencies(&self, q: &Self::Point) -> Result<Vec<Self::Point>, Error>;

    /// The fine point that stands for coarse point `p` after one step. On Z
    /// and Z² with the centre at the origin the dilation maps index q to the
    /// same index one level finer, hence the identity default. On a mesh
    /// patch it is a lookup that fails when the patch is too small.
    fn successor(&self, p: &Self::Point) -> Result<Self::Point, Error> {
        Ok(p.clone())
    }
}

/// Why a window could not be found or used.
#[derive(Clone, Debug, PartialEq)]
pub enum ClosureError<P> {
    /// the closure grew past `limit` points: the masks are not local (a finite
    /// mask under binary dilation always closes; a malformed one must not loop)
    Unbounded { limit: usize },
    /// the influence set still grew after `levels` levels
    Unsettled { levels: u32 },
    /// the window is not invariant: fine point `fine` needs coarse point `needs`
    NotInvariant { fine: P, needs: P },
    /// a dependency could not be evaluated
    Dependency(Error),
}

impl<P: fmt::Debug> fmt::Display for ClosureError<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ClosureError::Unbounded { limit } => {
                write!(f, "no invariant window of at most {limit} points: the masks are not local")
            }
            ClosureError::Unsettled { levels } => {
                write!(f, "the control points influencing the limit near the centre did not settle in {levels} levels")
            }
            ClosureError::NotInvariant { fine, needs } => {
                write!(f, "the window is not invariant: fine point {fine:?} needs {needs:?}")
            }
            ClosureError::Dependency(e) => write!(f, "{e}"),
        }
    }
}

/// A dependency's own error keeps its variant; a window that cannot be
/// closed or is not invariant comes from the masks the caller gave.
impl<P: fmt::Debug> From<ClosureError<P>> for Error {
    fn from(e: ClosureError<P>) -> Error {
        match e {
            ClosureError::Dependency(e) => e,
            other => Error::Input(other.to_string()),
        }
    }
}

/// Pairs (point of a window, coarse point outside it that its successor needs).
pub type Defects<P> = Vec<(P, P)>;

/// The smallest invariant window containing `seed`: add, for every point p of
/// the set, the dependencies of its successor, until nothing new appears. At
/// most `limit` points.
pub fn invariant_closure<R: Refinement>(
    scheme: &R,
    seed: impl IntoIterator<Item = R::Point>,
    limit: usize,
) -> Result<BTreeSet<R::Point>, ClosureError<R::Point>> {
    let mut set: BTreeSet<R::Point> = seed.into_iter().collect();
    let mut todo: Vec<R::Point> = set.iter().cloned().collect();
    while let Some(p) = todo.pop() {
        let fine = scheme.successor(&p).map_err(ClosureError::Dependency)?;
        for d in scheme.dependencies(&fine).map_err(ClosureError::Dependency)? {
            if set.insert(d.clone()) {
                if set.len() > limit {
                    return Err(ClosureError::Unbounded { limit });
                }
                todo.push(d);
            }
        }
    }
    Ok(set)
}

/// The pairs (point of the window, coarse point outside it that its successor
/// needs) that break invariance; empty when the window is invariant.
pub fn invariance_defects<R: Refinement>(
    scheme: &R,
    window: &[R::Point],
) -> Result<Defects<R::Point>, ClosureError<R::Point>> {
    let inside: BTreeSet<&R::Point> = window.iter().collect();
    let mut out = Vec::new();
    for p in window {
        let fine = scheme.successor(p).map_err(ClosureError::Dependency)?;
        for d in scheme.dependencies(&fine).map_err(ClosureError::Dependency)? {
            if !inside.contains(&d) {
                out.push((p.clone(), d));
            }
        }
    }
    Ok(out)
}

/// When to stop collecting the influence set.
#[derive(Clone, Copy, Debug)]
pub struct Levels {
    /// do not stop before this level: the region at level L must reach well past
    /// the masks (see `Levels::past_reach`), or a short stationary run could be
    /// mistaken for the end
    pub min: u32,
    /// give up after this level
    pub max: u32,
}

impl Levels {
    /// From the largest |offset| of the masks (`reach`) and the region's
    /// radius in level-0 units: the first level L with radius · 2^L greater
    /// than 4 (reach + 1), i.e. the fine region spans several mask widths, so
    /// that further levels only repeat the pattern near its ends.
    pub fn past_reach(reach: i64, radius: i64, max: u32) -> Levels {
        let bound = 4 * (reach.max(0) + 1);
        let min = (1..=max).find(|&l| radius.max(1) << l > bound).unwrap_or(max);
        Levels { min, max }
    }
}

/// The coarse (level-0) points that influence the limit over a region:
/// `region(L)` lists the level-L points over it, each level is pulled back to
/// level 0 through the dependencies, and the union over L = 1, 2, ... is
/// returned once it has not grown for two consecutive levels at or past
/// `levels.min`.
pub fn influence_set<R: Refinement>(
    scheme: &R,
    region: impl Fn(u32) -> Vec<R::Point>,
    levels: Levels,
) -> Result<BTreeSet<R::Point>, ClosureError<R::Point>> {
    let mut union: BTreeSet<R::Point> = BTreeSet::new();
    let mut unchanged = 0;
    for level in 1..=levels.max {
        let mut set: BTreeSet<R::Point> = region(level).into_iter().collect();
        for _ in 0..level {
            let mut coarser = BTreeSet::new();
            for q in &set {
                coarser.extend(scheme.dependencies(q).map_err(ClosureError::Dependency)?);
            }
            set = coarser;
        }
        let before = union.len();
        union.extend(set);
        unchanged = if union.len() == before { unchanged + 1 } else { 0 };
        if unchanged >= 2 && level >= levels.min {
            return Ok(union);
        }
    }
    Err(ClosureError::Unsettled { levels: levels.max })
}

/// The local matrix on an invariant window, rows and columns in the window's
/// order: row k is the stencil of the successor of point k, as (column,
/// weight) with repeated columns summed, zero sums dropped and columns
/// ascending. `Err` names the first dependency outside the window (the
/// restriction would not be a subdivision matrix), or passes on a stencil
/// that could not be evaluated.
pub fn assemble<R: Refinement, W: Weight>(
    scheme: &R,
    window: &[R::Point],
    mut stencil: impl FnMut(&R::Point) -> Result<Vec<(R::Point, W)>, Error>,
) -> Result<LocalMatrix<R::Point, W>, ClosureError<R::Point>> {
    let index: std::collections::BTreeMap<&R::Point, usize> = window.iter().enumerate().map(|(k, p)| (p, k)).collect();
    let mut rows = Vec::with_capacity(window.len());
    for p in window {
        let fine = scheme.successor(p).map_err(ClosureError::Dependency)?;
        let mut row: Vec<(usize, W)> = Vec::new();
        for (d, w) in stencil(&fine).map_err(ClosureError::Dependency)? {
            let Some(&col) = index.get(&d) else {
                return Err(ClosureError::NotInvariant { fine, needs: d });
            };
            match row.iter_mut().find(|e| e.0 == col) {
                Some(e) => e.1 = e.1.clone() + w,
                None => row.push((col, w)),
            }
        }
        row.retain(|e| !e.1.is_zero());
        row.sort_by_key(|e| e.0);
        rows.push(row);
    }
    Ok(LocalMatrix::new(window.to_vec(), rows))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The uniform cubic B-spline on Z: P'_{2i} = (P_{i−1} + 6 P_i + P_{i+1})/8,
    /// P'_{2i+1} = (P_i + P_{i+1})/2, so fine point 2i needs {i−1, i, i+1} and
    /// fine point 2i+1 needs {i, i+1}.
    struct CubicBSpline;

    fn bspline_deps(q: i64) -> Vec<i64> {
        let i = q.div_euclid(2);
        if q.rem_euclid(2) == 0 {
            vec![i - 1, i, i + 1]
        } else {
            vec![i, i + 1]
        }
    }

    impl Refinement for CubicBSpline {
        type Point = i64;
        fn dependencies(&self, q: &i64) -> Result<Vec<i64>, Error> {
            Ok(bspline_deps(*q))
        }
    }

    /// The tensor product of two cubic B-splines on Z²: a fine point needs the
    /// product of the 1-D dependency sets of its coordinates.
    struct Bicubic;

    impl Refinement for Bicubic {
        type Point = (i64, i64);
        fn dependencies(&self, q: &(i64, i64)) -> Result<Vec<(i64, i64)>, Error> {
            let (a, b) = (bspline_deps(q.0), bspline_deps(q.1));
            Ok(a.iter().flat_map(|&i| b.iter().map(move |&j| (i, j))).collect())
        }
    }

    /// The four-point scheme: fine 2i needs {i} (interpolatory), 2i+1 needs
    /// {i−1, i, i+1, i+2}.
    struct FourPoint;

    impl Refinement for FourPoint {
        type Point = i64;
        fn dependencies(&self, q: &i64) -> Result<Vec<i64>, Error> {
            let i = q.div_euclid(2);
            Ok(if q.rem_euclid(2) == 0 { vec![i] } else { vec![i - 1, i, i + 1, i + 2] })
        }
    }

    fn range(a: i64, b: i64) -> BTreeSet<i64> {
        (a..=b).collect()
    }

    #[test]
    fn cubic_bspline_windows() {
        // one-ring {−1, 0, 1}: fine 0 needs {−1, 0, 1}, fine 1 = 2·0+1 needs
        // {0, 1}, fine −1 = 2·(−1)+1 needs {−1, 0}, so the one-ring is
        // already invariant: 3 points
        let minimal = invariant_closure(&CubicBSpline, [-1, 0, 1], 100).unwrap();
        assert_eq!(minimal, range(-1, 1));
        // the limit curve over [−1, 1]: the basis function of point i is
        // supported on (i − 2, i + 2), so points i with |i| ≤ 2 reach into
        // [−1, 1] and none beyond: {−2..2}, invariant since fine ±2 = 2·(±1)
        // needs {0, ±1, ±2}
        let levels = Levels::past_reach(1, 1, 16);
        let influence = influence_set(&CubicBSpline, |l| (-(1i64 << l)..=1i64 << l).collect(), levels).unwrap();
        assert_eq!(influence, range(-2, 2));
        assert_eq!(invariant_closure(&CubicBSpline, influence, 100).unwrap(), range(-2, 2));
    }

    #[test]
    fn four_point_windows() {
        // the centre alone is invariant for an interpolatory scheme
        assert_eq!(invariant_closure(&FourPoint, [0], 100).unwrap(), range(0, 0));
        // fine 1 needs {−1, 0, 1, 2} and fine −1 needs {−2, −1, 0, 1}; fine ±2
        // need only {±1}: the one-ring closes to {−2..2}
        assert_eq!(invariant_closure(&FourPoint, [-1, 0, 1], 100).unwrap(), range(-2, 2));
        // basis functions supported on (i − 3, i + 3): the limit over [−1, 1]
        // sees points −3..3
        let levels = Levels::past_reach(2, 1, 16);
        let influence = influence_set(&FourPoint, |l| (-(1i64 << l)..=1i64 << l).collect(), levels).unwrap();
        assert_eq!(influence, range(-3, 3));
    }

    #[test]
    fn the_same_routines_on_z2() {
        let ring: Vec<(i64, i64)> = (-1..=1).flat_map(|i| (-1..=1).map(move |j| (i, j))).collect();
        let minimal = invariant_closure(&Bicubic, ring.clone(), 100).unwrap();
        assert_eq!(minimal, ring.iter().copied().collect());
        let levels = Levels::past_reach(1, 1, 9);
        let square = |l: u32| {
            let r = 1i64 << l;
            (-r..=r).flat_map(|i| (-r..=r).map(move |j| (i, j))).collect::<Vec<_>>()
        };
        let influence = influence_set(&Bicubic, square, levels).unwrap();
        assert_eq!(influence.len(), 25);
        assert!(influence.iter().all(|&(i, j)| i.abs() <= 2 && j.abs() <= 2));
    }

    #[test]
    fn defects_and_assembly() {
        // {−1, 0}: fine 0 needs 1, which is outside
        assert_eq!(invariance_defects(&CubicBSpline, &[-1, 0]).unwrap(), vec![(0, 1)]);
        assert!(invariance_defects(&CubicBSpline, &[-1, 0, 1]).unwrap().is_empty());
        // the 3×3 matrix on the one-ring, weights ×8: rows [4 4 0], [1 6 1], [0 4 4]
        let weights = |q: &i64| -> Result<Vec<(i64, f64)>, Error> {
            let i = q.div_euclid(2);
            Ok(if q.rem_euclid(2) == 0 {
                vec![(i - 1, 1.0), (i, 6.0), (i + 1, 1.0)]
            } else {
                // a repeated offset must be summed: 4 = 2 + 2
                let mut v = vec![(i, 2.0), (i + 1, 4.0), (i, 2.0)];
                if *q == 1 {
                    // weights that cancel are no entry
                    v.extend([(-1, 1.0), (-1, -1.0)]);
                }
                v
            })
        };
        let m = assemble(&CubicBSpline, &[-1, 0, 1], weights).unwrap();
        assert_eq!(m.labels, vec![-1, 0, 1]);
        assert_eq!(
            m.rows,
            vec![vec![(0, 4.0), (1, 4.0)], vec![(0, 1.0), (1, 6.0), (2, 1.0)], vec![(1, 4.0), (2, 4.0)]]
        );
        assert_eq!(
            assemble(&CubicBSpline, &[-1, 0], weights).unwrap_err(),
            ClosureError::NotInvariant { fine: 0, needs: 1 }
        );
        let failing = |_: &i64| -> Result<Vec<(i64, f64)>, Error> { Err(Error::Input("no rule".into())) };
        assert_eq!(
            assemble(&CubicBSpline, &[0], failing).unwrap_err(),
            ClosureError::Dependency(Error::Input("no rule".into()))
        );
    }

    #[test]
    fn a_mask_that_is_not_local_is_an_error_not_a_loop() {
        // fine q needs q + 1: closure never stops on its own
        struct Drift;
        impl Refinement for Drift {
            type Point = i64;
            fn dependencies(&self, q: &i64) -> Result<Vec<i64>, Error> {
                Ok(vec![q + 1])
            }
        }
        assert_eq!(invariant_closure(&Drift, [0], 50).unwrap_err(), ClosureError::Unbounded { limit: 50 });
    }
}
