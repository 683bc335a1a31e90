//! The one local-matrix type (`engine::LocalMatrix`) in every scheme family:
//! the curve window of the cubic B-spline, the lattice window of its tensor
//! product and the mesh neighbourhood of Catmull–Clark at valence 4 (the same
//! bicubic B-spline) each equal the subdivision matrix written out by hand
//! here, whatever their point type; a different scheme does not.

use num_bigint::BigInt;
use subdlab::curves::local::local_matrix as curve_matrix;
use subdlab::curves::CurveWeight;
use subdlab::engine::LocalMatrix;
use subdlab::lattice::{self, LatticeDomain, LatticeScheme, Parity, Point, Window};
use subdlab::matrix::assemble;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::numeric::{Rational, Weight};
use subdlab::schemes;
use subdlab::sdc::Rules;

fn q(p: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(p), BigInt::from(d))
}

/// The cubic B-spline's subdivision matrix on the points −2..2 of Z, times 8:
/// a new vertex point is (1, 6, 1)/8 of its old neighbourhood, a new edge
/// point (1, 1)/2 of the edge's ends.
const BSPLINE_X8: [[i64; 5]; 5] = [[1, 6, 1, 0, 0], [0, 4, 4, 0, 0], [0, 1, 6, 1, 0], [0, 0, 4, 4, 0], [0, 0, 1, 6, 1]];

fn bspline(r: usize, c: usize) -> Rational {
    q(BSPLINE_X8[r][c], 8)
}

/// Index of the point p in −2..2 (per coordinate).
fn at(p: i64) -> usize {
    (p + 2) as usize
}

/// The entries of `m` that differ from `want(row label, column label)`.
fn differences<P, K>(m: &LocalMatrix<P, Rational, K>, want: impl Fn(&P, &P) -> Rational) -> usize {
    let n = m.size();
    (0..n)
        .flat_map(|i| (0..n).map(move |j| (i, j)))
        .filter(|&(i, j)| m.get(i, j) != want(&m.labels[i], &m.labels[j]))
        .count()
}

fn curve_of(name: &str) -> subdlab::curves::CurveMask<Rational> {
    let s = schemes::curves::build(name, &[]).unwrap();
    Rational::mask(s.as_ref()).unwrap()
}

#[test]
fn curve_window_is_the_b_spline_matrix() {
    let window: Vec<i64> = (-2..=2).collect();
    let m = curve_matrix(&curve_of("cubic-bspline"), &window).unwrap();
    assert_eq!(m.labels, window);
    assert_eq!(differences(&m, |&a, &b| bspline(at(a), at(b))), 0);
    // its eigenvalues 1, 1/2, 1/4, 1/8, 1/8 (the cubic B-spline's spectrum)
    let p = m.to_qmatrix().charpoly();
    assert_eq!(p, subdlab::numeric::exact::Poly::from_roots(&[q(1, 1), q(1, 2), q(1, 4), q(1, 8), q(1, 8)]));
    // negative control: the four-point scheme on the same (invariant) window
    let four = curve_matrix(&curve_of("four-point"), &window).unwrap();
    assert!(differences(&four, |&a, &b| bspline(at(a), at(b))) > 0);
    // a window that is not invariant has no local matrix
    assert!(curve_matrix(&curve_of("cubic-bspline"), &[-1, 0]).is_err());
}

/// A tensor-product scheme on Z² from two 1-D masks (offset, weight): even
/// and odd rule per coordinate.
struct Tensor {
    even: Vec<(i64, (i64, i64))>,
    odd: Vec<(i64, (i64, i64))>,
}

impl Tensor {
    fn bicubic() -> Tensor {
        Tensor { even: vec![(-1, (1, 8)), (0, (6, 8)), (1, (1, 8))], odd: vec![(0, (1, 2)), (1, (1, 2))] }
    }
    fn four_point() -> Tensor {
        Tensor { even: vec![(0, (1, 1))], odd: vec![(-1, (-1, 16)), (0, (9, 16)), (1, (9, 16)), (2, (-1, 16))] }
    }
    fn rule(&self, parity: u8) -> &[(i64, (i64, i64))] {
        if parity == 0 {
            &self.even
        } else {
            &self.odd
        }
    }
}

impl<W: Weight> Rules<LatticeDomain, W> for Tensor {
    fn rule(&self, _: &(), (alpha, beta): Parity) -> Vec<(Point, W)> {
        let mut out = Vec::new();
        for &(r, (a, b)) in self.rule(alpha) {
            for &(s, (c, d)) in self.rule(beta) {
                out.push(((r, s), W::ratio(a, b) * W::ratio(c, d)));
            }
        }
        out
    }
}

impl LatticeScheme for Tensor {
    fn name(&self) -> &'static str {
        "tensor"
    }
    fn description(&self) -> &'static str {
        "tensor product of two curve masks"
    }
}

/// The bicubic matrix on [−2, 2]²: the Kronecker product of the curve matrix.
fn bicubic(a: &Point, b: &Point) -> Rational {
    bspline(at(a.0), at(b.0)) * bspline(at(a.1), at(b.1))
}

#[test]
fn lattice_window_is_the_bicubic_matrix() {
    let w = Window::rect(-2, 2, -2, 2);
    let m = lattice::window_matrix::<Rational>(&Tensor::bicubic(), &w).unwrap();
    assert_eq!(m.labels, w.points);
    assert_eq!(differences(&m, bicubic), 0);
    // the dense form the papers print is the same matrix
    assert_eq!(lattice::local_matrix::<Rational>(&Tensor::bicubic(), &w).unwrap(), m.dense());
    // the analysis relabels the same rows with vertex labels
    let labelled =
        lattice::analysis::to_local::<Rational>(&Tensor::bicubic(), &w, NeighbourhoodKind::Analysis).unwrap();
    assert_eq!(labelled.rows, m.rows);
    assert_eq!(labelled.kind, NeighbourhoodKind::Analysis);
    assert!(labelled.labels.iter().zip(&w.points).all(|(l, p)| (l.i, l.j) == *p));
    // negative control: the tensor-product four-point scheme
    let four = lattice::window_matrix::<Rational>(&Tensor::four_point(), &w).unwrap();
    assert!(differences(&four, bicubic) > 0);
}

#[test]
fn mesh_neighbourhood_is_the_bicubic_matrix() {
    // Catmull–Clark at a regular vertex is the bicubic B-spline, and its
    // analysis neighbourhood (6n + 1 = 25 vertices) is the 5 × 5 grid
    let scheme = schemes::build("catmull-clark", &[]).unwrap();
    let config = Configuration::regular(scheme.as_ref(), 4).unwrap();
    let d = discover(scheme.as_ref(), &config).unwrap();
    let m = assemble::<Rational>(scheme.as_ref(), &d, NeighbourhoodKind::Analysis).unwrap();
    assert_eq!(m.size(), 25);
    // sector s's chart point (i, j) sits at i·d_s + j·d_{s+1} on the plane
    let spokes = [(1, 0), (0, 1), (-1, 0), (0, -1)];
    let planar = m.clone().relabel(|_, l| {
        let (u, v) = (spokes[l.sector % 4], spokes[(l.sector + 1) % 4]);
        (l.i * u.0 + l.j * v.0, l.i * u.1 + l.j * v.1)
    });
    assert_eq!(differences(&planar, bicubic), 0);
    assert_eq!(planar.to_dense_f64(), m.to_dense_f64());
    // the lattice window of the same scheme, matched by point, is the same
    // matrix; the four-point tensor product's (negative control) is not
    let w = Window::rect(-2, 2, -2, 2);
    let on_points = |other: &LocalMatrix<Point, Rational>| {
        differences(&planar, |a, b| other.get(other.position(a).unwrap(), other.position(b).unwrap()))
    };
    assert_eq!(on_points(&lattice::window_matrix::<Rational>(&Tensor::bicubic(), &w).unwrap()), 0);
    assert!(on_points(&lattice::window_matrix::<Rational>(&Tensor::four_point(), &w).unwrap()) > 0);
}
