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

use std::collections::BTreeSet;

use crate::engine::closure::{self, assemble, influence_set, invariant_closure, ClosureError, Levels, Refinement};
use crate::engine::LocalMatrix;
use crate::error::Error;
use crate::numeric::{Rational, Weight};
use crate::sdc::{Domain, Params, RuleWeight, Rules};

/// A lattice point (i, j), or an offset (r, s) inside a mask.
pub type Point = (i64, i64);

/// The parity (α, β) ∈ {0,1}² of a fine index: which of the four masks
/// gives the point.
pub type Parity = (u8, u8);

/// The regular lattice Z² with binary dilation: a rule is the mask of one
/// parity, the weights w_{α,β}(r, s) with their offsets (the scheme's rules
/// are `sdc::Rules<LatticeDomain, W>`, written once generic over `W`).
pub enum LatticeDomain {}

impl Domain for LatticeDomain {
    type Host = ();
    type Position = Parity;
    type Rule<W: Weight> = Vec<(Point, W)>;
    type Scheme<'a> = dyn LatticeScheme + 'a;
}

crate::sdc::rule_weights!(LatticeDomain: f64, Rational);

/// A regular-lattice scheme: its four masks in f64 and exact rationals.
pub trait LatticeScheme: Rules<LatticeDomain, f64> + Rules<LatticeDomain, Rational> + Send + Sync {
    fn name(&self) -> &'static str;
    fn description(&self) -> &'static str;
    /// The parameter values the masks were built with (scheme files may have
    /// parameters; the built-in lattice schemes have none).
    fn params(&self) -> &Params {
        static NONE: Params = Params { values: Vec::new() };
        &NONE
    }
}

/// Weight types the lattice engine evaluates masks in ([`RuleWeight`] on
/// the lattice domain); lets generic code ask a `&dyn LatticeScheme` for
/// masks of either type.
pub trait LatticeWeight: RuleWeight<LatticeDomain> {
    fn mask_of(scheme: &dyn LatticeScheme, alpha: u8, beta: u8) -> Vec<(Point, Self)> {
        Self::rule_of(scheme, &(), (alpha, beta))
    }
}

impl<W: RuleWeight<LatticeDomain>> LatticeWeight for W {}

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

/// An ordered set of lattice points: the labels of a local matrix
/// (`window_matrix`), built as a rectangle or from a closure.
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

/// The lattice scheme as the engine sees it: fine point q depends on the
/// coarse points of its exact stencil (exact, so that a weight that is zero
/// only up to rounding is no dependency).
struct Deps<'a>(&'a dyn LatticeScheme);

impl Refinement for Deps<'_> {
    type Point = Point;
    fn dependencies(&self, q: &Point) -> Result<Vec<Point>, Error> {
        Ok(dependencies(self.0, *q))
    }
}

/// Most points an invariant window may have before the masks count as not local.
const MAX_WINDOW: usize = 100_000;
/// Most levels followed when collecting the analysis window's influence set.
const MAX_LEVELS: u32 = 9;

/// A closure failure of the scheme's masks (not local, not invariant): the
/// scheme asked for cannot be analysed.
fn named(scheme: &dyn LatticeScheme, e: ClosureError<Point>) -> Error {
    Error::Input(match e {
        ClosureError::NotInvariant { fine, needs } => format!(
            "{}: window is not invariant: fine point {} needs {}",
            scheme.name(),
            point_name(fine),
            point_name(needs)
        ),
        e => format!("{}: {e}", scheme.name()),
    })
}

/// The smallest invariant window containing `seed` (`engine::closure`):
/// every point's own index is a fine index of the next level, so the closure
/// under "fine point q needs coarse point p" is exactly the smallest set whose
/// refined points depend only on itself. An error, not a loop, when the masks
/// are not local.
pub fn minimal_invariant_window(scheme: &dyn LatticeScheme, seed: &[Point]) -> Result<Window, Error> {
    check_reach(scheme)?;
    let set = invariant_closure(&Deps(scheme), seed.iter().copied(), MAX_WINDOW).map_err(|e| named(scheme, e))?;
    Ok(Window::from_set(set))
}

/// The pairs (fine point of the window, coarse point outside it) that break
/// invariance; empty when the window is invariant.
pub fn invariance_defects(scheme: &dyn LatticeScheme, w: &Window) -> Vec<(Point, Point)> {
    // `Deps` never fails, so neither does this
    closure::invariance_defects(&Deps(scheme), &w.points).unwrap_or_default()
}

/// The local subdivision matrix on the window, rows and columns in the
/// window's order (its points are the matrix's labels). Error (naming the
/// first escaping dependency) when the window is not invariant, because the
/// restriction would not be a subdivision matrix.
pub fn window_matrix<W: LatticeWeight>(scheme: &dyn LatticeScheme, w: &Window) -> Result<LocalMatrix<Point, W>, Error> {
    assemble(&Deps(scheme), &w.points, |&q| Ok(stencil::<W>(scheme, q))).map_err(|e| match e {
        ClosureError::NotInvariant { fine, needs } => Error::Input(format!(
            "{}: window of {} points is not invariant: fine point {} needs {}",
            scheme.name(),
            w.len(),
            point_name(fine),
            point_name(needs)
        )),
        e => named(scheme, e),
    })
}

/// [`window_matrix`] as dense rows (the form the papers print).
pub fn local_matrix<W: LatticeWeight>(scheme: &dyn LatticeScheme, w: &Window) -> Result<Vec<Vec<W>>, Error> {
    Ok(window_matrix(scheme, w)?.dense())
}

/// Largest |offset| (in either coordinate) of a mask accepted. The window is
/// two-dimensional: its side grows with the reach, so its points as the
/// square of the reach, and the exact stage's characteristic polynomial
/// over Q steeply with the points: a dense mask of reach 2 (an 81-point
/// window) takes 3 s, of reach 3 over two minutes; masks out to ±32 ran for
/// minutes more. The built-in schemes reach 1 and 2.
pub const MAX_LATTICE_REACH: i64 = 2;

/// Every window is found by [`minimal_invariant_window`] (the analysis
/// window's influence set first), so every lattice analysis refuses a mask
/// past [`MAX_LATTICE_REACH`] there, before any work.
fn check_reach(scheme: &dyn LatticeScheme) -> Result<(), Error> {
    let r = reach(scheme);
    if r > MAX_LATTICE_REACH {
        return Err(Error::Input(format!(
            "{}: the masks reach offset {r}, beyond the supported {MAX_LATTICE_REACH} (the invariant window grows as \
             the square of the reach and its exact analysis as a high power of the window)",
            scheme.name()
        )));
    }
    Ok(())
}

/// Largest |offset| of the four masks.
fn reach(scheme: &dyn LatticeScheme) -> i64 {
    (0..4u8)
        .flat_map(|k| <Rational as LatticeWeight>::mask_of(scheme, k / 2, k % 2))
        .map(|((r, s), _)| r.abs().max(s.abs()))
        .max()
        .unwrap_or(0)
}

/// The window whose points hold every control point influencing the limit
/// surface over the cells around the origin, [-radius, radius]², closed under
/// dependencies (the lattice analogue of ARCHITECTURE.md's analysis neighbourhood):
/// the fine points of level k inside the region pulled back to level 0, their
/// union over k once it has settled (`engine::closure::influence_set`), with
/// the origin, closed.
pub fn analysis_window(scheme: &dyn LatticeScheme, radius: i64) -> Result<Window, Error> {
    let square = |k: u32| {
        let r = radius << k;
        (-r..=r).flat_map(|i| (-r..=r).map(move |j| (i, j))).collect::<Vec<Point>>()
    };
    check_reach(scheme)?;
    let levels = Levels::past_reach(reach(scheme), radius, MAX_LEVELS);
    let mut seed = influence_set(&Deps(scheme), square, levels).map_err(|e| named(scheme, e))?;
    seed.insert((0, 0));
    minimal_invariant_window(scheme, &seed.into_iter().collect::<Vec<_>>())
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
