//! Khan & Mustafa, "A new non-tensor product C¹ subdivision scheme for regular
//! quad meshes" (2013): binary rules on the regular lattice Z² obtained by
//! fitting a quadratic f = Ax² + Bxy + Cy² + Dx + Ey + F to the 3×3 control
//! points around p_{i,j} (eq. 3.1–3.2) and evaluating it at the four new
//! positions (0,0), (1/2,0), (0,1/2), (1/2,1/2) in coarse lattice units.
//!
//! The masks are not symmetric under the lattice rotations (the new points lie
//! in the quadrant i, j ≥ 0 of p_{i,j} while the data are centred on it), so
//! the scheme lives on the lattice with explicit (i, j) coordinates
//! (`crate::lattice`), never on a mesh with sector charts.
//!
//! These masks are the single source of the scheme's weights: the local
//! matrices (f64 and exact) are assembled from them, and the tests compare them
//! with the least-squares derivation and with the numbers printed in the paper.
//!
//! Two schemes are registered: `khan-mustafa` (the quadratic 9-point scheme of
//! eq. 3.3) and `khan-mustafa-cubic` (the 16-point variant of the paper's
//! Discussion section). They are separate names rather than a parameter because
//! scheme parameters are numbers with a range, and the variant is a choice.

use crate::lattice::{LatticeDomain, LatticeScheme, Parity, Point};
use crate::numeric::Weight;
use crate::schemes::entry::LatticeEntry;
use crate::sdc::Rules;

/// Weights given as integer numerators over a common denominator, with offsets
/// (r, s) meaning p_{i+r, j+s}.
fn over<W: Weight>(den: i64, terms: &[((i64, i64), i64)]) -> Vec<(Point, W)> {
    terms.iter().map(|&(p, num)| (p, W::ratio(num, den))).collect()
}

/// The quadratic 9-point scheme, eq. (3.3).
pub struct KhanMustafa;

impl<W: Weight> Rules<LatticeDomain, W> for KhanMustafa {
    fn rule(&self, _: &(), (alpha, beta): Parity) -> Vec<(Point, W)> {
        match (alpha, beta) {
            // p_{2i,2j} = 1/144 {−16 p_{i−1,j−1} + 32 p_{i−1,j} − 16 p_{i−1,j+1} + 32 p_{i,j−1} + 80 p_{i,j}
            //                    + 32 p_{i,j+1} − 16 p_{i+1,j−1} + 32 p_{i+1,j} − 16 p_{i+1,j+1}}   (vertex rule)
            (0, 0) => over(
                144,
                &[
                    ((-1, -1), -16),
                    ((-1, 0), 32),
                    ((-1, 1), -16),
                    ((0, -1), 32),
                    ((0, 0), 80),
                    ((0, 1), 32),
                    ((1, -1), -16),
                    ((1, 0), 32),
                    ((1, 1), -16),
                ],
            ),
            // p_{2i+1,2j} = 1/144 {−22 p_{i−1,j−1} + 26 p_{i−1,j} − 22 p_{i−1,j+1} + 20 p_{i,j−1} + 68 p_{i,j}
            //                      + 20 p_{i,j+1} + 2 p_{i+1,j−1} + 50 p_{i+1,j} + 2 p_{i+1,j+1}}   (edge rule)
            (1, 0) => over(
                144,
                &[
                    ((-1, -1), -22),
                    ((-1, 0), 26),
                    ((-1, 1), -22),
                    ((0, -1), 20),
                    ((0, 0), 68),
                    ((0, 1), 20),
                    ((1, -1), 2),
                    ((1, 0), 50),
                    ((1, 1), 2),
                ],
            ),
            // p_{2i,2j+1} = 1/144 {−22 p_{i−1,j−1} + 20 p_{i−1,j} + 2 p_{i−1,j+1} + 26 p_{i,j−1} + 68 p_{i,j}
            //                      + 50 p_{i,j+1} − 22 p_{i+1,j−1} + 20 p_{i+1,j} + 2 p_{i+1,j+1}}   (edge rule)
            (0, 1) => over(
                144,
                &[
                    ((-1, -1), -22),
                    ((-1, 0), 20),
                    ((-1, 1), 2),
                    ((0, -1), 26),
                    ((0, 0), 68),
                    ((0, 1), 50),
                    ((1, -1), -22),
                    ((1, 0), 20),
                    ((1, 1), 2),
                ],
            ),
            // p_{2i+1,2j+1} = 1/144 {−19 p_{i−1,j−1} + 14 p_{i−1,j} − 13 p_{i−1,j+1} + 14 p_{i,j−1} + 56 p_{i,j}
            //                        + 38 p_{i,j+1} − 13 p_{i+1,j−1} + 38 p_{i+1,j} + 29 p_{i+1,j+1}}   (face rule)
            _ => over(
                144,
                &[
                    ((-1, -1), -19),
                    ((-1, 0), 14),
                    ((-1, 1), -13),
                    ((0, -1), 14),
                    ((0, 0), 56),
                    ((0, 1), 38),
                    ((1, -1), -13),
                    ((1, 0), 38),
                    ((1, 1), 29),
                ],
            ),
        }
    }
}

impl LatticeScheme for KhanMustafa {
    fn name(&self) -> &'static str {
        "khan-mustafa"
    }
    fn description(&self) -> &'static str {
        "Khan–Mustafa non-tensor-product C1 quad scheme, 9-point masks from a least-squares quadratic (regular lattice only)"
    }
}

/// The cubic variant of the Discussion section: a cubic in
/// span{1, x, y, xy, x², y², xy², x²y, x³, y³} on the 4×4 points
/// p_{i+r,j+s}, r, s = −1..2 (support 16).
///
/// The vertex and face rules are as printed. The two edge rules are printed
/// with one weight of the wrong sign each: p_{2i+1,2j} prints
/// +50 p_{i+2,j+1} and p_{2i,2j+1} (labelled "p_{2i+2,j+1}" in the paper) prints
/// +50 p_{i+1,j+2}; with those signs a rule sums to 900/800, so it would not
/// even reproduce constants. Here both are −50, the value the least-squares
/// cubic gives (tests/khan_mustafa.rs derives it and keeps the printed rules as
/// data).
pub struct KhanMustafaCubic;

impl<W: Weight> Rules<LatticeDomain, W> for KhanMustafaCubic {
    fn rule(&self, _: &(), (alpha, beta): Parity) -> Vec<(Point, W)> {
        match (alpha, beta) {
            // p_{2i,2j} = 1/800 {−92 p_{i−1,j−1} + 176 (p_{i−1,j} + p_{i,j−1}) − 16 (p_{i−1,j+1} + p_{i+1,j−1})
            //   − 68 (p_{i−1,j+2} + p_{i+1,j+1} + p_{i+2,j−1}) + 372 p_{i,j} + 148 (p_{i,j+1} + p_{i+1,j})
            //   + 104 (p_{i,j+2} + p_{i+2,j}) − 64 (p_{i+1,j+2} + p_{i+2,j+1}) + 28 p_{i+2,j+2}}
            (0, 0) => over(
                800,
                &[
                    ((-1, -1), -92),
                    ((-1, 0), 176),
                    ((0, -1), 176),
                    ((-1, 1), -16),
                    ((1, -1), -16),
                    ((-1, 2), -68),
                    ((1, 1), -68),
                    ((2, -1), -68),
                    ((0, 0), 372),
                    ((0, 1), 148),
                    ((1, 0), 148),
                    ((0, 2), 104),
                    ((2, 0), 104),
                    ((1, 2), -64),
                    ((2, 1), -64),
                    ((2, 2), 28),
                ],
            ),
            // p_{2i+1,2j} = 1/800 {100 (−p_{i−1,j−1} + p_{i,j−1} + p_{i+1,j−1} − p_{i+2,j−1})
            //   + 125 (p_{i−1,j} + p_{i+2,j}) + 275 (p_{i,j} + p_{i+1,j})
            //   + 50 (−p_{i−1,j+1} + p_{i,j+1} + p_{i+1,j+1} − p_{i+2,j+1})      [paper: + p_{i+2,j+1}]
            //   + 25 (−p_{i−1,j+2} + p_{i,j+2} + p_{i+1,j+2} − p_{i+2,j+2})}
            (1, 0) => over(
                800,
                &[
                    ((-1, -1), -100),
                    ((0, -1), 100),
                    ((1, -1), 100),
                    ((2, -1), -100),
                    ((-1, 0), 125),
                    ((2, 0), 125),
                    ((0, 0), 275),
                    ((1, 0), 275),
                    ((-1, 1), -50),
                    ((0, 1), 50),
                    ((1, 1), 50),
                    ((2, 1), -50),
                    ((-1, 2), -25),
                    ((0, 2), 25),
                    ((1, 2), 25),
                    ((2, 2), -25),
                ],
            ),
            // p_{2i,2j+1} (printed label "p_{2i+2,j+1}") = 1/800 {100 (−p_{i−1,j−1} + p_{i−1,j} + p_{i−1,j+1} − p_{i−1,j+2})
            //   + 125 (p_{i,j−1} + p_{i,j+2}) + 275 (p_{i,j} + p_{i,j+1})
            //   + 50 (−p_{i+1,j−1} + p_{i+1,j} + p_{i+1,j+1} − p_{i+1,j+2})      [paper: + p_{i+1,j+2}]
            //   + 25 (−p_{i+2,j−1} + p_{i+2,j} + p_{i+2,j+1} − p_{i+2,j+2})}
            (0, 1) => over(
                800,
                &[
                    ((-1, -1), -100),
                    ((-1, 0), 100),
                    ((-1, 1), 100),
                    ((-1, 2), -100),
                    ((0, -1), 125),
                    ((0, 2), 125),
                    ((0, 0), 275),
                    ((0, 1), 275),
                    ((1, -1), -50),
                    ((1, 0), 50),
                    ((1, 1), 50),
                    ((1, 2), -50),
                    ((2, -1), -25),
                    ((2, 0), 25),
                    ((2, 1), 25),
                    ((2, 2), -25),
                ],
            ),
            // p_{2i+1,2j+1} = 1/800 {−75 (p_{i−1,j−1} + p_{i−1,j+2} + p_{i+2,j−1} + p_{i+2,j+2})
            //   + 175 (p_{i,j} + p_{i,j+1} + p_{i+1,j} + p_{i+1,j+1})
            //   + 50 (p_{i−1,j} + p_{i−1,j+1} + p_{i,j−1} + p_{i,j+2} + p_{i+1,j−1} + p_{i+1,j+2} + p_{i+2,j} + p_{i+2,j+1})}
            _ => {
                let mut t: Vec<((i64, i64), i64)> =
                    [(-1, -1), (-1, 2), (2, -1), (2, 2)].iter().map(|&p| (p, -75)).collect();
                t.extend([(0, 0), (0, 1), (1, 0), (1, 1)].iter().map(|&p| (p, 175)));
                t.extend([(-1, 0), (-1, 1), (0, -1), (0, 2), (1, -1), (1, 2), (2, 0), (2, 1)].iter().map(|&p| (p, 50)));
                over(800, &t)
            }
        }
    }
}

impl LatticeScheme for KhanMustafaCubic {
    fn name(&self) -> &'static str {
        "khan-mustafa-cubic"
    }
    fn description(&self) -> &'static str {
        "Khan–Mustafa cubic variant (Discussion section), 16-point masks from a least-squares cubic (regular lattice only)"
    }
}

pub fn entry() -> LatticeEntry {
    LatticeEntry {
        name: "khan-mustafa",
        description: LatticeScheme::description(&KhanMustafa),
        params: Vec::new,
        build: |_| Box::new(KhanMustafa),
    }
}

pub fn cubic_entry() -> LatticeEntry {
    LatticeEntry {
        name: "khan-mustafa-cubic",
        description: LatticeScheme::description(&KhanMustafaCubic),
        params: Vec::new,
        build: |_| Box::new(KhanMustafaCubic),
    }
}
