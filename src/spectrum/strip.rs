//! Smoothness along a line of special nodes (the procedure of Levin & Levin,
//! "Analysis of quasi-uniform subdivision", that Peters–Shiue follow for the
//! 4-3 transition in Lemma 3.3): a window L of lattice points around a node of
//! the line, the matrix S that maps the control points on L to the refined
//! points at the same positions, and the matrix S⁺ that maps them to the
//! refined points shifted by one lattice step along the line. Products of S and
//! S⁺ generate the refined points over a segment of the line, so smoothness
//! there is a question about the joint spectral radius of the pair acting
//! modulo the eigenvectors that reproduce polynomials.
//!
//! The matrices come from the scheme's own stencils on a generous patch of the
//! node's configuration (the sectors of the configuration must tile the plane,
//! e.g. the transition node QQTTT of 4-3 subdivision with the quads on one side
//! of the line and the triangles on the other), never from a restated rule:
//! one refinement step of the patch (`refine::step_selected`, stencils of the
//! refined points the rows need) and the engine's assembly on the window
//! (`engine::closure::assemble`), whose points are the planar positions.

use std::collections::HashMap;

use faer::Mat;
use num_traits::Zero;

use crate::engine::closure::{assemble, ClosureError, Refinement};
use crate::error::Error;
use crate::neighbourhood::{build_patch, Configuration};
use crate::numeric::Rational;
use crate::refine::{step_selected, Step, StepStencil};
use crate::sdc::Scheme;

/// Planar integer position of a chart point: sector s point (i, j) is
/// i·d_s + j·d_{s+1} with the given spoke vectors d.
fn planar(spokes: &[[i64; 2]], sector: usize, i: i64, j: i64) -> [i64; 2] {
    let n = spokes.len();
    let (u, v) = (spokes[sector % n], spokes[(sector + 1) % n]);
    [i * u[0] + j * v[0], i * u[1] + j * v[1]]
}

/// One refinement step of the node's patch seen on the planar lattice, with
/// the refined point at fine position p + `shift` standing for the coarse
/// point p (the identity for S, one lattice step along the line for S⁺).
struct Shifted<'a> {
    step: &'a Step<Rational>,
    /// planar position of each coarse vertex
    coarse: &'a HashMap<usize, [i64; 2]>,
    /// refined vertex at each fine planar position
    fine: &'a HashMap<[i64; 2], usize>,
    shift: [i64; 2],
}

impl Shifted<'_> {
    /// The stencil of the refined point at fine position `at`, over coarse positions.
    fn stencil(&self, at: &[i64; 2]) -> Result<Vec<([i64; 2], Rational)>, Error> {
        // a point or rule missing on the patch: not determined by it
        let v = *self.fine.get(at).ok_or_else(|| Error::NotDetermined(format!("no refined point at {at:?}")))?;
        let st = match &self.step.stencils[v] {
            StepStencil::Stencil(st) => st,
            StepStencil::Missing(cause) => {
                return Err(Error::NotDetermined(format!("no rule for the refined point at {at:?}: {cause}")))
            }
            // the step selected every window position: a lookup outside it is ours
            StepStencil::NotSelected => {
                return Err(Error::Message(format!("the refined point at {at:?} was not selected for a stencil")))
            }
        };
        Ok(st.terms.iter().map(|(u, w)| (self.coarse[u], w.clone())).collect())
    }
}

impl Refinement for Shifted<'_> {
    type Point = [i64; 2];
    fn dependencies(&self, q: &[i64; 2]) -> Result<Vec<[i64; 2]>, Error> {
        Ok(self.stencil(q)?.into_iter().map(|(p, _)| p).collect())
    }
    fn successor(&self, p: &[i64; 2]) -> Result<[i64; 2], Error> {
        Ok([p[0] + self.shift[0], p[1] + self.shift[1]])
    }
}

/// Exact matrices on a window of lattice points: for each `shift` t, the
/// matrix whose row r holds the stencil of the refined point at fine position
/// `window[r]` + t (fine lattice units) on the coarse points `window` (coarse
/// units). `spokes` are the planar integer directions of the configuration's
/// spokes, counter-clockwise; they must make the sectors tile the plane. Error
/// when a stencil reaches outside the window (the window is not invariant).
pub fn window_matrices(
    scheme: &dyn Scheme,
    config: &Configuration,
    spokes: &[[i64; 2]],
    window: &[[i64; 2]],
    shifts: &[[i64; 2]],
) -> Result<Vec<Vec<Vec<Rational>>>, Error> {
    if spokes.len() != config.valence() {
        return Err(Error::Input(format!("{} spokes for valence {}", spokes.len(), config.valence())));
    }
    let reach = window.iter().chain(shifts).flat_map(|p| [p[0].abs(), p[1].abs()]).max().unwrap_or(0);
    let rings = (2 * reach + 4) as usize;
    let (patch, _) = build_patch(config, rings);
    let chart = patch.chart.as_ref().ok_or_else(|| Error::Message("the patch has no lattice chart".into()))?;
    let coarse: HashMap<usize, [i64; 2]> =
        chart.vertex_coords.iter().enumerate().map(|(v, c)| (v, planar(spokes, c.sector, c.i, c.j))).collect();
    // the stencils of the refined points at the window's positions, shifted
    let mut fine: HashMap<[i64; 2], usize> = HashMap::new();
    let step = step_selected::<Rational>(scheme, &patch, |refined| {
        let fine_chart = refined
            .mesh
            .chart
            .as_ref()
            .ok_or_else(|| Error::Message("the refined patch has no lattice chart".into()))?;
        fine =
            fine_chart.vertex_coords.iter().enumerate().map(|(v, c)| (planar(spokes, c.sector, c.i, c.j), v)).collect();
        shifts
            .iter()
            .flat_map(|t| window.iter().map(move |p| [p[0] + t[0], p[1] + t[1]]))
            .map(|at| fine.get(&at).copied().ok_or_else(|| Error::NotDetermined(format!("no refined point at {at:?}"))))
            .collect()
    })?;
    shifts
        .iter()
        .map(|&shift| {
            let on_window = Shifted { step: &step, coarse: &coarse, fine: &fine, shift };
            let m = assemble(&on_window, window, |at| on_window.stencil(at)).map_err(|e| match e {
                ClosureError::NotInvariant { fine: at, needs } => Error::Input(format!(
                    "the refined point at {at:?} depends on {needs:?}, outside the window (not invariant)"
                )),
                // a stencil missing on the patch: not determined by it
                e => Error::NotDetermined(e.to_string()),
            })?;
            Ok(m.dense())
        })
        .collect()
}

/// Bounds on the joint spectral radius ρ(A_1, ..., A_m) = lim_k max ‖A_{ε_k} ⋯ A_{ε_1}‖^{1/k}.
#[derive(Clone, Debug)]
pub struct JsrBounds {
    /// ρ^[k] = max over all products of `length` factors of ‖P‖_∞^{1/length}: an upper bound
    pub length: usize,
    pub upper: f64,
    /// max over products of at most `lower_length` factors of ρ(P)^{1/len}: a lower bound
    pub lower_length: usize,
    pub lower: f64,
    /// the product attaining the lower bound, as indices of the factors (rightmost first)
    pub lower_word: Vec<usize>,
}

fn norm_inf(m: &Mat<f64>) -> f64 {
    (0..m.nrows()).map(|i| (0..m.ncols()).map(|j| m[(i, j)].abs()).sum::<f64>()).fold(0.0, f64::max)
}

fn spectral_radius(m: &Mat<f64>) -> Result<f64, Error> {
    let ev = m.eigenvalues().map_err(|e| Error::Numeric(format!("eigenvalues failed: {e:?}")))?;
    Ok(ev.iter().map(|z| z.norm()).fold(0.0, f64::max))
}

/// Upper bound ρ^[length] (the ∞-norm of every product of `length` factors)
/// and lower bound (spectral radii of the products of at most `lower_length`
/// factors) on the joint spectral radius of `mats`.
pub fn jsr_bounds(mats: &[Mat<f64>], length: usize, lower_length: usize) -> Result<JsrBounds, Error> {
    if mats.is_empty() || length == 0 {
        return Err(Error::Input("no matrices or an empty product".into()));
    }
    // depth-first over all words, reusing prefixes: P_k = A_{ε_k} P_{k−1}
    let mut upper: f64 = 0.0;
    let (mut lower, mut lower_word) = (0.0f64, Vec::new());
    let mut stack: Vec<(Vec<usize>, Mat<f64>)> = mats.iter().enumerate().map(|(k, a)| (vec![k], a.clone())).collect();
    while let Some((word, p)) = stack.pop() {
        let len = word.len();
        if len <= lower_length {
            let r = spectral_radius(&p)?.powf(1.0 / len as f64);
            if r > lower {
                lower = r;
                lower_word = word.clone();
            }
        }
        if len == length {
            upper = upper.max(norm_inf(&p).powf(1.0 / length as f64));
            continue;
        }
        for (k, a) in mats.iter().enumerate() {
            let mut w = word.clone();
            w.push(k);
            stack.push((w, a * &p));
        }
    }
    Ok(JsrBounds { length, upper, lower_length, lower, lower_word })
}

/// Matrix of exact rationals as floats.
pub fn to_f64(m: &[Vec<Rational>]) -> Mat<f64> {
    Mat::from_fn(m.len(), m.first().map_or(0, |r| r.len()), |i, j| crate::numeric::Weight::to_f64(&m[i][j]))
}

/// An orthonormal basis of the orthogonal complement of the columns of `w`
/// (n × k, independent columns), as the columns of an n × (n − k) matrix.
pub fn orthogonal_complement(w: &Mat<f64>) -> Result<Mat<f64>, Error> {
    let (n, k) = (w.nrows(), w.ncols());
    let svd = w.svd().map_err(|e| Error::Numeric(format!("svd failed: {e:?}")))?;
    let u = svd.U();
    Ok(Mat::from_fn(n, n - k, |i, j| u[(i, k + j)]))
}

fn mul_vec(m: &[Vec<Rational>], x: &[Rational]) -> Vec<Rational> {
    m.iter()
        .map(|row| row.iter().zip(x).fold(Rational::zero(), |a, (w, y)| if w.is_zero() { a } else { a + w * y }))
        .collect()
}

/// Exact eigenvectors: a basis of the null space of M − λI for each distinct
/// value in `values`, in order.
pub fn exact_eigenvectors(m: &[Vec<Rational>], values: &[Rational]) -> Vec<Vec<Rational>> {
    let n = m.len();
    let mut out = Vec::new();
    let mut seen: Vec<&Rational> = Vec::new();
    for v in values {
        if seen.contains(&v) {
            continue;
        }
        seen.push(v);
        let mut a: Vec<Rational> = m.iter().flatten().cloned().collect();
        for i in 0..n {
            a[i * n + i] = &a[i * n + i] - v;
        }
        out.extend(crate::numeric::exact::null_space(n, n, a));
    }
    out
}

/// The matrix A with M W = W A for the columns W = `basis` (independent), or
/// `None` when span W is not invariant under M. Exact.
pub fn action_on(m: &[Vec<Rational>], basis: &[Vec<Rational>]) -> Option<Vec<Vec<Rational>>> {
    let (n, k) = (m.len(), basis.len());
    // reduce [W | M W] to row echelon form; consistent iff no pivot in the right part
    let images: Vec<Vec<Rational>> = basis.iter().map(|w| mul_vec(m, w)).collect();
    let mut a: Vec<Vec<Rational>> = (0..n)
        .map(|i| basis.iter().map(|w| w[i].clone()).chain(images.iter().map(|y| y[i].clone())).collect())
        .collect();
    // W has independent columns, so column c gets its pivot in row c
    for c in 0..k {
        let p = (c..n).find(|&i| !a[i][c].is_zero())?;
        a.swap(c, p);
        let piv = a[c][c].clone();
        for x in a[c].iter_mut() {
            *x = &*x / &piv;
        }
        let pivot_row = a[c].clone();
        for (i, row) in a.iter_mut().enumerate() {
            if i != c && !row[c].is_zero() {
                let f = row[c].clone();
                for (x, y) in row.iter_mut().zip(&pivot_row) {
                    *x = &*x - &f * y;
                }
            }
        }
    }
    if a[k..].iter().any(|row| row[k..].iter().any(|x| !x.is_zero())) {
        return None;
    }
    // row c of the reduced system holds row c of A
    Some(a[..k].iter().map(|row| row[k..].to_vec()).collect())
}

/// A rational eigenvalue with its algebraic and geometric multiplicity.
pub type RationalEigenvalue = (Rational, usize, usize);

/// The eigenvalues of an exact matrix that are rational, with algebraic and
/// geometric multiplicity (candidates come from the floating-point spectrum
/// and are confirmed exactly); the second value is the number of eigenvalues
/// (with multiplicity) that are not rational.
pub fn rational_spectrum(m: &[Vec<Rational>]) -> Result<(Vec<RationalEigenvalue>, usize), Error> {
    use crate::numeric::exact::{q, rational_roots, QMatrix};
    let n = m.len();
    let mut qm = QMatrix::zeros(n);
    for (i, row) in m.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            qm.set(i, j, x.clone());
        }
    }
    let ev = to_f64(m).eigenvalues().map_err(|e| Error::Numeric(format!("eigenvalues failed: {e:?}")))?;
    let mut candidates = vec![q(0, 1)];
    for z in ev {
        if let Some((p, d)) = crate::numeric::recognise::small_rational(z.re, 4096, 1e-6) {
            candidates.push(q(p, d));
        }
    }
    let (roots, _) = rational_roots(&qm.charpoly(), &candidates);
    let found: usize = roots.iter().map(|r| r.1).sum();
    let out = roots.into_iter().map(|(r, alg)| (r.clone(), alg, n - qm.shifted(&r).rank())).collect();
    Ok((out, n - found))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Commuting diagonal matrices: every product is diag(Π a, Π b), so the
    /// joint spectral radius is the largest entry, 3/4 here, reached by the
    /// word of B alone; both bounds must be exactly that (the ∞-norm of a
    /// diagonal matrix is its largest entry).
    #[test]
    fn diagonal_pair_has_the_largest_entry_as_joint_spectral_radius() {
        let a = Mat::from_fn(2, 2, |i, j| {
            if i != j {
                0.0
            } else if i == 0 {
                0.5
            } else {
                0.25
            }
        });
        let b = Mat::from_fn(2, 2, |i, j| {
            if i != j {
                0.0
            } else if i == 0 {
                1.0 / 3.0
            } else {
                0.75
            }
        });
        let bounds = jsr_bounds(&[a, b], 6, 3).unwrap();
        assert!((bounds.upper - 0.75).abs() < 1e-12 && (bounds.lower - 0.75).abs() < 1e-12, "{bounds:?}");
        assert!(bounds.lower_word.iter().all(|&k| k == 1));
    }

    /// A = [[1, 1], [0, 1]], B = [[1, 0], [1, 1]]: each has spectral radius 1,
    /// but AB = [[2, 1], [1, 1]] has ρ = (3 + √5)/2 = φ², so the joint
    /// spectral radius is at least φ (and equals it, a classical example).
    /// The lower bound over words of length ≤ 2 is φ; the upper bound of any
    /// length is at least the true value.
    #[test]
    fn shear_pair_has_the_golden_ratio() {
        let a = Mat::from_fn(2, 2, |i, j| if i == 0 || j == 1 { 1.0 } else { 0.0 });
        let b = Mat::from_fn(2, 2, |i, j| if i == 1 || j == 0 { 1.0 } else { 0.0 });
        let phi = (1.0 + 5f64.sqrt()) / 2.0;
        let bounds = jsr_bounds(&[a, b], 8, 2).unwrap();
        assert!((bounds.lower - phi).abs() < 1e-12, "{bounds:?}");
        assert_eq!(bounds.lower_word.len(), 2);
        assert!(bounds.upper >= phi - 1e-12 && bounds.upper < 2.0, "{bounds:?}");
        assert!(jsr_bounds(&[], 3, 1).is_err());
    }
}
