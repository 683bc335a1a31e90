//! Rigorous eigenvalue enclosures of an interval matrix A: discs in the
//! complex plane whose union holds every eigenvalue of every matrix in A, with
//! counts per connected component.
//!
//! Method (a posteriori, Gershgorin after an approximate diagonalisation):
//!
//! 1. floating point: eigenvectors V of the midpoint of A, and an approximate
//!    inverse R of V (LU with full pivoting);
//! 2. enclosures M ⊇ R·A·V and ε ≥ ‖I − R·V‖∞ (balls about floating-point
//!    products with their rounding errors bounded, `certify::midrad`);
//! 3. if ε < 1 then R·V = I − E is invertible, so V is, and for each A
//!    V⁻¹AV = (RV)⁻¹·RAV = (I + F)·M with F = Σ_{k≥1} Eᵏ, ‖F‖∞ ≤ ε/(1 − ε);
//! 4. Gershgorin on (I + F)·M: row i's disc has a centre within
//!    |Mᵢᵢ − cᵢ| + |(FM)ᵢᵢ| of cᵢ = mid(Mᵢᵢ) and a radius at most
//!    Σ_{j≠i} |Mᵢⱼ| + Σ_{j≠i} |(FM)ᵢⱼ|, and Σ_j |(FM)ᵢⱼ| ≤ ‖F‖∞‖M‖∞ =: δ. So the
//!    disc about cᵢ of radius rᵢ = |Mᵢᵢ − cᵢ| + Σ_{j≠i} |Mᵢⱼ| + δ holds row i's
//!    Gershgorin disc, for every A in the interval matrix.
//!
//! Gershgorin's theorem: a union of k discs disjoint from the other discs
//! holds exactly k eigenvalues (with algebraic multiplicity). Two discs count
//! as disjoint only when the distance of their centres, bounded from below,
//! exceeds the sum of their radii, bounded from above.
//!
//! A defective or nearly defective eigenvalue makes V ill-conditioned: ε and
//! the radii grow, but the enclosure stays valid; when ε ≥ 1 no enclosure is
//! given (the caller says so).

use super::complex::{CInterval, CIntervalMatrix};
use super::midrad;
use crate::numeric::Interval;
use faer::c64;
use faer::linalg::solvers::DenseSolveCore;
use faer::Mat;

/// One Gershgorin disc: every point within `radius` of `centre`.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Disc {
    pub re: f64,
    pub im: f64,
    pub radius: f64,
}

impl Disc {
    pub fn centre(&self) -> c64 {
        c64::new(self.re, self.im)
    }
    /// Upper bound of |z| over the disc.
    pub fn max_modulus(&self) -> f64 {
        (CInterval::point(self.centre()).mag() + self.radius).next_up()
    }
    /// Lower bound of |z| over the disc (0 when it holds the origin).
    pub fn min_modulus(&self) -> f64 {
        (CInterval::point(self.centre()).mig() - self.radius).next_down().max(0.0)
    }
    /// Whether the two discs are proven disjoint.
    pub fn disjoint(&self, o: &Disc) -> bool {
        let d = (CInterval::point(self.centre()) - CInterval::point(o.centre())).mig();
        d > (Interval::point(self.radius) + Interval::point(o.radius)).hi
    }
    /// Whether the disc may meet the real axis.
    pub fn meets_real_axis(&self) -> bool {
        self.im.abs() <= self.radius
    }
    /// Whether the disc holds the point.
    pub fn may_hold(&self, z: c64) -> bool {
        (CInterval::point(self.centre()) - CInterval::point(z)).mig() <= self.radius
    }
    /// Bounds of the real parts over the disc.
    pub fn real_range(&self) -> (f64, f64) {
        ((self.re - self.radius).next_down(), (self.re + self.radius).next_up())
    }
}

/// A connected component of the union of discs: it holds exactly `count`
/// eigenvalues (with algebraic multiplicity).
#[derive(Clone, Debug, serde::Serialize)]
pub struct Component {
    pub discs: Vec<Disc>,
    pub count: usize,
    /// the rows of V⁻¹AV whose discs these are (in `discs` order): a proof
    /// names the eigenvalue it speaks about by these, never by a float value
    #[serde(skip)]
    pub rows: Vec<usize>,
}

impl Component {
    pub fn max_modulus(&self) -> f64 {
        self.discs.iter().map(Disc::max_modulus).fold(0.0, f64::max)
    }
    pub fn min_modulus(&self) -> f64 {
        self.discs.iter().map(Disc::min_modulus).fold(f64::INFINITY, f64::min)
    }
    pub fn meets_real_axis(&self) -> bool {
        self.discs.iter().any(Disc::meets_real_axis)
    }
    pub fn may_hold(&self, z: c64) -> bool {
        self.discs.iter().any(|d| d.may_hold(z))
    }
    pub fn disjoint(&self, o: &Component) -> bool {
        self.discs.iter().all(|a| o.discs.iter().all(|b| a.disjoint(b)))
    }
    /// The largest radius: how tight the enclosure is.
    pub fn max_radius(&self) -> f64 {
        self.discs.iter().map(|d| d.radius).fold(0.0, f64::max)
    }
    pub fn real_range(&self) -> (f64, f64) {
        let lo = self.discs.iter().map(|d| d.real_range().0).fold(f64::INFINITY, f64::min);
        let hi = self.discs.iter().map(|d| d.real_range().1).fold(f64::NEG_INFINITY, f64::max);
        (lo, hi)
    }
}

/// The enclosure of one interval matrix's eigenvalues.
#[derive(Clone, Debug)]
pub struct Enclosure {
    /// components, largest modulus first
    pub components: Vec<Component>,
    /// the bound ε ≥ ‖I − RV‖∞ (how well V was inverted)
    pub epsilon: f64,
    /// the verified diagonalisation the components come from: an eigenvector
    /// enclosure for a component is taken from this very one
    pub diagonalisation: Diagonalisation,
}

/// `Err` says why there is no enclosure (ε ≥ 1, non-finite entries).
pub fn enclose(a: &CIntervalMatrix) -> Result<Enclosure, String> {
    let d = diagonalise(a)?;
    Ok(Enclosure { components: components(d.discs.clone()), epsilon: d.epsilon, diagonalisation: d })
}

/// The verified approximate diagonalisation behind [`enclose`]: the float
/// eigenvectors V of the midpoint, the Gershgorin disc of each row of
/// V⁻¹AV (for every A in the interval matrix) and ε.
#[derive(Clone, Debug)]
pub struct Diagonalisation {
    pub v: Mat<c64>,
    /// R ≈ V⁻¹ as used in the verification (kept for the certificate
    /// document: a checker redoes the interval products with V and R)
    pub r: Mat<c64>,
    pub discs: Vec<Disc>,
    pub epsilon: f64,
}

fn diagonalise(a: &CIntervalMatrix) -> Result<Diagonalisation, String> {
    let k = a.size;
    if k == 0 {
        return Ok(Diagonalisation { v: Mat::zeros(0, 0), r: Mat::zeros(0, 0), discs: Vec::new(), epsilon: 0.0 });
    }
    if !a.entries.iter().all(CInterval::is_finite) {
        return Err("an entry of the matrix has no finite enclosure".into());
    }
    let mid = a.mid();
    let evd = mid.eigen().map_err(|e| format!("eigen-decomposition of the midpoint failed: {e:?}"))?;
    let v: Mat<c64> = evd.U().to_owned();
    let r: Mat<c64> = v.full_piv_lu().inverse();
    let finite = |m: &Mat<c64>| (0..k).all(|i| (0..k).all(|j| m[(i, j)].re.is_finite() && m[(i, j)].im.is_finite()));
    if !finite(&v) || !finite(&r) {
        return Err("the eigenvector matrix of the midpoint could not be inverted".into());
    }
    // M ⊇ R·A·V and ε ≥ ‖I − R·V‖∞ as balls about floating-point products
    // (certify::midrad: the rounding errors bounded a priori)
    let products = midrad::products(a, &v, &r)?;
    let eps = products.epsilon;
    if !(eps < 1.0) {
        return Err(format!(
            "the eigenvectors of the midpoint are too ill-conditioned to verify (‖I − RV‖∞ ≤ {eps:.3e} is not below 1)"
        ));
    }
    let m_norm = midrad::norm_inf(&products.m);
    // δ = ε‖M‖∞/(1 − ε), rounded up: the product and quotient up, 1 − ε down
    let delta = ((eps * m_norm).next_up() / (1.0 - eps).next_down()).next_up();
    let discs: Vec<Disc> = (0..k)
        .map(|i| {
            let (c, r) = midrad::row_radius(&products.m, i);
            Disc { re: c.re, im: c.im, radius: (r + delta).next_up() }
        })
        .collect();
    Ok(Diagonalisation { v, r, discs, epsilon: eps })
}

/// An enclosure of an eigenvector of every matrix in the interval matrix
/// that `d` diagonalises, for the eigenvalue in disc `i` (a component of one
/// disc, count 1, which the caller's proof identified by its enclosures).
///
/// With C = V⁻¹AV, the disc i and rᵢ the row radii (each
/// bounding |Cⱼⱼ − cⱼ| + Σ_{k≠j} |Cⱼₖ|): the eigenvalue μ of C in disc i has
/// |cⱼ − μ| ≥ Dⱼ := |cⱼ − cᵢ| − rᵢ for j ≠ i, and an eigenvector y of C
/// satisfies |cⱼ − μ|·|yⱼ| ≤ rⱼ‖y‖∞. If every qⱼ = rⱼ/Dⱼ is below 1, the
/// largest entry of y can only be yᵢ (else |y_p| ≤ q_p|y_p| forces y = 0), so
/// with yᵢ = 1 every |yⱼ| ≤ qⱼ, and x = V·y is the eigenvector of A:
/// xₗ ∈ Vₗᵢ + Σ_{j≠i} |Vₗⱼ|·qⱼ·(unit disc). Returns x (a rectangle per
/// entry) and max qⱼ.
pub fn eigenvector(d: &Diagonalisation, i: usize) -> Result<(Vec<CInterval>, f64), String> {
    let k = d.discs.len();
    if i >= k {
        return Err(format!("disc {i} of a {k}-row diagonalisation does not exist"));
    }
    let near = d.discs[i].centre();
    let di = d.discs[i];
    let mut q = vec![0.0; k];
    for j in (0..k).filter(|&j| j != i) {
        let gap = (CInterval::point(d.discs[j].centre()) - CInterval::point(di.centre())).mig();
        let lower = (Interval::point(gap) - Interval::point(di.radius)).lo;
        if !(lower > 0.0) {
            return Err(format!(
                "the eigenvalue near {near} is not isolated: its disc (radius {:.2e}) meets the disc about {}",
                di.radius,
                d.discs[j].centre()
            ));
        }
        q[j] = (Interval::point(d.discs[j].radius) / Interval::point(lower)).hi;
        if !(q[j] < 1.0) {
            return Err(format!(
                "the eigenvector near {near} is not enclosed: the disc about {} is too wide for its distance",
                d.discs[j].centre()
            ));
        }
    }
    let x = (0..k)
        .map(|l| {
            let mut s = Interval::point(0.0);
            for j in (0..k).filter(|&j| j != i) {
                s = s + Interval::point(CInterval::point(d.v[(l, j)]).mag()) * Interval::point(q[j]);
            }
            let r = Interval::symmetric(s.hi);
            CInterval::point(d.v[(l, i)]) + CInterval::new(r, r)
        })
        .collect();
    Ok((x, q.iter().copied().fold(0.0, f64::max)))
}

/// Connected components of the union of discs (discs not proven disjoint
/// are connected), largest modulus first.
pub fn components(discs: Vec<Disc>) -> Vec<Component> {
    let k = discs.len();
    let mut parent: Vec<usize> = (0..k).collect();
    fn find(p: &mut [usize], i: usize) -> usize {
        let mut r = i;
        while p[r] != r {
            r = p[r];
        }
        p[i] = r;
        r
    }
    for i in 0..k {
        for j in i + 1..k {
            if !discs[i].disjoint(&discs[j]) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[a] = b;
            }
        }
    }
    let mut groups: std::collections::BTreeMap<usize, Vec<usize>> = std::collections::BTreeMap::new();
    for i in 0..k {
        let root = find(&mut parent, i);
        groups.entry(root).or_default().push(i);
    }
    let mut out: Vec<Component> = groups
        .into_values()
        .map(|rows| Component { count: rows.len(), discs: rows.iter().map(|&i| discs[i]).collect(), rows })
        .collect();
    out.sort_by(|a, b| b.max_modulus().total_cmp(&a.max_modulus()));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn real_matrix(rows: &[&[Interval]]) -> CIntervalMatrix {
        let k = rows.len();
        let mut m = CIntervalMatrix::zeros(k);
        for i in 0..k {
            for j in 0..k {
                *m.at(i, j) = CInterval::real(rows[i][j]);
            }
        }
        m
    }

    #[test]
    fn companion_matrix_of_known_roots() {
        // x³ − 11/6 x² + x − 1/6 = (x − 1)(x − 1/2)(x − 1/3): the companion
        // matrix, with entries enclosing 11/6 and 1/6, has these eigenvalues
        let q = |p, r| Interval::ratio(p, r);
        let z = Interval::point(0.0);
        let one = Interval::point(1.0);
        let m = real_matrix(&[&[z, z, q(1, 6)], &[one, z, -one], &[z, one, q(11, 6)]]);
        let e = enclose(&m).unwrap();
        assert_eq!(e.components.len(), 3);
        for (c, root) in e.components.iter().zip([1.0, 0.5, 1.0 / 3.0]) {
            assert_eq!(c.count, 1);
            assert!(c.may_hold(c64::new(root, 0.0)));
            // rounding-sized: the a-priori bound 3(k + 1)u·|R|·|A|·|V| of
            // certify::midrad is about 10⁻¹² here (cond(V) ≈ 10²)
            assert!(c.max_radius() < 1e-11);
        }
    }

    #[test]
    fn rotation_block_has_conjugate_pair() {
        // [[0, −1], [1, 0]] has eigenvalues ±i, none real
        let z = Interval::point(0.0);
        let one = Interval::point(1.0);
        let m = real_matrix(&[&[z, -one], &[one, z]]);
        let e = enclose(&m).unwrap();
        assert_eq!(e.components.len(), 2);
        assert!(e.components.iter().all(|c| !c.meets_real_axis()));
        assert!(e.components.iter().any(|c| c.may_hold(c64::new(0.0, 1.0))));
        assert!(e.components.iter().any(|c| c.may_hold(c64::new(0.0, -1.0))));
    }

    #[test]
    fn a_jordan_block_is_one_component_of_two() {
        // [[1/2, 1], [0, 1/2]]: defective; the discs cannot separate, and say so
        let z = Interval::point(0.0);
        let h = Interval::ratio(1, 2);
        let m = real_matrix(&[&[h, Interval::point(1.0)], &[z, h]]);
        match enclose(&m) {
            Ok(e) => {
                assert_eq!(e.components.len(), 1);
                assert_eq!(e.components[0].count, 2);
                assert!(e.components[0].may_hold(c64::new(0.5, 0.0)));
            }
            Err(msg) => assert!(msg.contains("ill-conditioned")),
        }
    }

    #[test]
    fn wide_entries_widen_the_discs() {
        // diag(1, [0.2, 0.3]): the second eigenvalue anywhere in [0.2, 0.3]
        let z = Interval::point(0.0);
        let m = real_matrix(&[&[Interval::point(1.0), z], &[z, Interval::new(0.2, 0.3)]]);
        let e = enclose(&m).unwrap();
        let small = &e.components[1];
        assert!(small.may_hold(c64::new(0.2, 0.0)) && small.may_hold(c64::new(0.3, 0.0)));
    }
}
