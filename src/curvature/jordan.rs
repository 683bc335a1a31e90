//! Second routes to a Jordan block at λ², independent of the floating-point
//! multiplicities (SVD null spaces) that [`super::curvature`] uses.
//!
//! A defective λ² (S w2 = λ² w2 + w1) puts m (λ²)^(m−1) on w1 in S^m: the
//! curvature of ring m grows like m exactly when w1's *limit function* does
//! not vanish on the characteristic ring. Two routes confirm or refute the
//! float finding:
//!
//! - [`growth_test`]: generic data with every eigenvalue of modulus above λ²
//!   projected out (right and left null spaces of S − νI, computed here by
//!   SVD of the dense S, not taken from the spectrum) is iterated,
//!   x ← P S x / λ²; the ring values of x_k (refined `level` analysis steps)
//!   grow linearly in k for a visible Jordan block and stay bounded
//!   otherwise. The growing direction g = lim x_k / k (the sum of the chain
//!   tops) is then refined 1, 2, ... levels: refined values converge to the
//!   limit function, so when they decay geometrically level after level the
//!   limit function of g vanishes on the ring — a combination of linearly
//!   dependent generating functions (box splines with non-unimodular
//!   directions, such as the four-direction splines of 4-3 subdivision, have
//!   such combinations), which the surface never shows.
//! - [`exact_jordan`]: where S is rational, the exact nullities of S − νI and
//!   (S − νI)² (a Jordan block exactly when the second is larger).

use crate::error::Error;
use faer::c64;
use serde::Serialize;

use super::sampler::RingSampler;
use crate::numeric::exact::QMatrix;
use crate::numeric::Rational;
use crate::sdc::Scheme;
use crate::spectrum::Analysis;

/// The growth test's evidence.
#[derive(Clone, Debug, Serialize)]
pub struct GrowthTest {
    /// ν = λ², the eigenvalue tested
    pub eigenvalue: f64,
    /// eigenvalues projected out (modulus above ν)
    pub projected: Vec<f64>,
    /// the window length K: x_k is averaged over k in [K, 2K) and [8K, 16K)
    pub window: usize,
    /// refinement level of the ring samples of x_k
    pub level: usize,
    /// mean ring size of x_k over [K, 2K) and over [8K, 16K), relative to
    /// the data's largest entry
    pub early: f64,
    pub late: f64,
    /// late / early: about 8 for linear growth, about 1 when bounded
    pub ratio: f64,
    /// the ring values grow linearly (ratio above 3)
    pub grows: bool,
    /// ring size of the growing direction g over its largest entry, refined
    /// 1, 2, ... levels (only when `grows`)
    pub top_levels: Vec<f64>,
    /// the growing direction's limit function does not vanish on the ring
    /// (its refined values do not decay level after level); null when
    /// nothing grows or the levels do not decide
    pub top_visible: Option<bool>,
    pub explanation: String,
}

/// The exact route: nullities of N = S − νI and N².
#[derive(Clone, Debug, Serialize)]
pub struct ExactJordan {
    pub eigenvalue: String,
    pub size: usize,
    pub nullity: usize,
    pub nullity_squared: usize,
    /// nullity(N²) > nullity(N): some Jordan block of ν has size ≥ 2
    pub defective: bool,
}

/// Exact nullities of S − νI and (S − νI)² on the exact S of `analysis`
/// (analysed with `exact: true`); `None` when S is not rational or ν is not
/// given as a rational.
pub fn exact_jordan(analysis: &Analysis, nu: &Rational) -> Option<ExactJordan> {
    let m = analysis.exact_matrix.as_ref()?;
    let q: QMatrix = m.to_qmatrix();
    let s = q.n;
    let n1 = q.shifted(nu);
    let mut n2 = QMatrix::zeros(s);
    for i in 0..s {
        for k in 0..s {
            let a = n1.get(i, k);
            if num_traits::Zero::is_zero(a) {
                continue;
            }
            for j in 0..s {
                let b = n1.get(k, j);
                if !num_traits::Zero::is_zero(b) {
                    let v = n2.get(i, j) + a * b;
                    n2.set(i, j, v);
                }
            }
        }
    }
    let (r1, r2) = (n1.rank(), n2.rank());
    Some(ExactJordan {
        eigenvalue: nu.to_string(),
        size: s,
        nullity: s - r1,
        nullity_squared: s - r2,
        defective: r2 < r1,
    })
}

/// Null space of a dense real matrix (columns of V whose singular values are
/// below `tol` times the largest).
fn null_space(a: &nalgebra::DMatrix<f64>, tol: f64) -> Vec<nalgebra::DVector<f64>> {
    let svd = a.clone().svd(false, true);
    let v_t = svd.v_t.expect("V requested");
    let top = svd.singular_values.iter().cloned().fold(0.0, f64::max).max(1e-300);
    (0..svd.singular_values.len())
        .filter(|&k| svd.singular_values[k] <= tol * top)
        .map(|k| v_t.row(k).transpose())
        .collect()
}

/// A fixed pseudo-random vector (xorshift64*), so results reproduce.
fn generic(size: usize) -> Vec<f64> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    (0..size)
        .map(|_| {
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            let r = state.wrapping_mul(0x2545_F491_4F6C_DD1D);
            (r >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        })
        .collect()
}

fn inf_norm(x: &[f64]) -> f64 {
    x.iter().map(|v| v.abs()).fold(0.0, f64::max)
}

/// The growth test for ν = λ² (see the module documentation). `levels` is
/// the deepest refinement of the growing direction (2 to 6).
pub fn growth_test(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    lambda: f64,
    level: usize,
    levels: usize,
) -> Result<GrowthTest, Error> {
    let nu = lambda * lambda;
    let spec = &analysis.spectrum;
    let dense = analysis.matrix.to_dense_f64();
    let s = dense.len();
    let sm = nalgebra::DMatrix::<f64>::from_fn(s, s, |i, j| dense[i][j]);
    // eigenvalues above ν in modulus: each must be real and non-defective
    let above: Vec<&crate::spectrum::Eigenvalue> =
        spec.eigenvalues.iter().filter(|e| e.modulus > nu * (1.0 + 1e-6)).collect();
    let mut right = Vec::new();
    let mut left = Vec::new();
    for e in &above {
        if e.im.abs() > 1e-12 || e.defective {
            return Err(Error::Numeric(format!(
                "the eigenvalue {} above λ² is complex or defective: the growth test projects real, non-defective ones only",
                crate::spectrum::fmt_f(e.modulus)
            )));
        }
        let shifted = &sm - nalgebra::DMatrix::<f64>::identity(s, s) * e.re;
        let r = null_space(&shifted, 1e-9);
        let l = null_space(&shifted.transpose(), 1e-9);
        if r.len() != e.algebraic_multiplicity || l.len() != e.algebraic_multiplicity {
            return Err(Error::Numeric(format!(
                "the null spaces of S − {}·I have dimensions {} and {}, not the multiplicity {}",
                crate::spectrum::fmt_f(e.re),
                r.len(),
                l.len(),
                e.algebraic_multiplicity
            )));
        }
        right.extend(r);
        left.extend(l);
    }
    let q = right.len();
    let projector = if q == 0 {
        nalgebra::DMatrix::<f64>::identity(s, s)
    } else {
        let r = nalgebra::DMatrix::<f64>::from_columns(&right);
        let l = nalgebra::DMatrix::<f64>::from_columns(&left);
        let g = (l.transpose() * &r).try_inverse().ok_or_else(|| {
            // a singular pairing of valid eigenvectors: a numerical failure
            Error::Numeric("the left and right eigenvectors above λ² are not dual".into())
        })?;
        nalgebra::DMatrix::<f64>::identity(s, s) - &r * g * l.transpose()
    };
    // the step: x ← P S x / ν
    let step = &projector * &sm / nu;
    // window: the next eigenvalue below ν decays within it to 1e-10
    let below = spec.eigenvalues.iter().map(|e| e.modulus).filter(|&m| m < nu * (1.0 - 1e-6)).fold(0.0, f64::max);
    let window =
        if below <= 0.0 { 10 } else { ((1e-10f64).ln() / (below / nu).ln()).ceil().clamp(10.0, 400.0) as usize };
    let sampler = RingSampler::shared(scheme, &analysis.discovered, level)?;
    let mut x = nalgebra::DVector::<f64>::from_vec(generic(s));
    x = &projector * x;
    let scale = inf_norm(x.as_slice()).max(1e-300);
    let mut tail = nalgebra::DVector::<f64>::zeros(s);
    // the ring is sampled only over the two averaging windows: the iterates
    // there are kept and their ring sizes taken together afterwards
    let (mut early_x, mut late_x) = (Vec::with_capacity(window), Vec::with_capacity(8 * window));
    for k in 1..16 * window {
        x = &step * x;
        if (window..2 * window).contains(&k) {
            early_x.push(x.as_slice().to_vec());
        }
        if k >= 8 * window {
            late_x.push(x.as_slice().to_vec());
            tail += &x / (k as f64 * (8 * window) as f64);
        }
    }
    // summed in step order, as when each was added at its step
    let mean = |xs: &[Vec<f64>], over: usize| {
        sampler.ring_sizes(xs).into_iter().fold(0.0, |a, size| a + size / scale / over as f64)
    };
    let (early, late) = (mean(&early_x, window), mean(&late_x, 8 * window));
    let ratio = if early > 0.0 { late / early } else { f64::NAN };
    let grows = ratio > 3.0;
    let projected: Vec<f64> = above.iter().map(|e| e.re).collect();
    let mut top_levels = Vec::new();
    let mut top_visible = None;
    let mut explanation = format!(
        "growth test: generic data with the eigenvalues {projected:?} projected out, iterated x ← P·S·x/λ² \
         ({} steps); mean ring size (level {level}) over steps [{window}, {}) = {early:.4e}, over [{}, {}) = {late:.4e}, \
         ratio {ratio:.3} ({})",
        16 * window - 1,
        2 * window,
        8 * window,
        16 * window,
        if grows { "linear growth: a Jordan block at λ²" } else { "bounded: no Jordan block at λ² shows at this level" }
    );
    if grows {
        let g = tail.as_slice();
        let gs = inf_norm(g).max(1e-300);
        // one function at levels nothing else samples: refine it (not the
        // unit rows), once for every level
        for size in RingSampler::ring_sizes_each_level(scheme, &analysis.discovered, levels, g)? {
            top_levels.push(size / gs);
        }
        let last = top_levels.len();
        if last >= 3 {
            let (a, b, c) = (top_levels[last - 3], top_levels[last - 2], top_levels[last - 1]);
            if c > 1e-3 && b / a > 0.8 && c / b > 0.8 {
                top_visible = Some(true);
            } else if c / b < 0.7 && b / a < 0.7 {
                top_visible = Some(false);
            }
        }
        let levels_text: Vec<String> = top_levels.iter().map(|v| format!("{v:.3e}")).collect();
        explanation += &format!(
            "; the growing direction g = lim x_k/k refined 1..{levels} levels has ring size [{}] of its largest entry: {}",
            levels_text.join(", "),
            match top_visible {
                Some(true) => "the refined values converge to a nonzero limit function, so the chain shows in the surface",
                Some(false) => {
                    "the refined values decay geometrically level after level: its limit function vanishes on the ring \
                     (a combination of linearly dependent generating functions), so the chain does not show in the surface"
                }
                None => "the levels do not decide whether its limit function vanishes",
            }
        );
    }
    Ok(GrowthTest {
        eigenvalue: nu,
        projected,
        window,
        level,
        early,
        late,
        ratio,
        grows,
        top_levels,
        top_visible,
        explanation,
    })
}

/// The ring size of complex level-0 data (helper for tests and callers that
/// hold spectrum vectors).
pub fn ring_size_c(sampler: &RingSampler, x: &[c64]) -> f64 {
    sampler.ring_values_c(x).iter().map(|z| z.norm()).fold(0.0, f64::max)
}

/// How the generalised eigenspace G of ν in one block shows on the ring.
#[derive(Clone, Debug, PartialEq)]
pub struct RingStructure {
    /// dimension of G found (at most the cap given)
    pub dimension: usize,
    /// largest ring size over the eigenvectors (the null space of N = B − νI)
    pub eigenvector_ring: f64,
    /// largest ring size over a basis of G (eigenvectors and generalised
    /// eigenvectors): the eigenvalue shows in the surface when above the
    /// vanishing tolerance
    pub space_ring: f64,
    /// largest ring size over N·G (every vector that S^m multiplies by a
    /// positive power of m): a Jordan chain shows when above the tolerance
    pub chain_ring: f64,
    /// number of vectors N·w counted (0: no Jordan chain found at this
    /// tolerance)
    pub tops: usize,
}

/// The generalised eigenspace of ν in the square block `b`, orthonormal:
/// K_1 = null(N), K_j = {w : N w ∈ K_(j−1)} (the null space of (I − QQ*)N,
/// Q an orthonormal basis of K_(j−1)), until it stops growing or reaches
/// `cap` (the algebraic multiplicity). Singular values below 1e-9·max(‖N‖, 1)
/// count as zero (the spectrum's null-space tolerance). Computing the chain
/// level by level avoids the powers N^k, whose small singular values blur.
pub fn generalised_eigenspace(b: &faer::Mat<c64>, nu: c64, cap: usize) -> Vec<Vec<c64>> {
    chain_levels(b, nu, cap).pop().unwrap_or_default()
}

/// Orthonormal bases of K_1 ⊂ K_2 ⊂ ... (see [`generalised_eigenspace`]).
fn chain_levels(b: &faer::Mat<c64>, nu: c64, cap: usize) -> Vec<Vec<Vec<c64>>> {
    let k = b.nrows();
    let cap = cap.min(k);
    let n = faer::Mat::<c64>::from_fn(k, k, |i, j| if i == j { b[(i, j)] - nu } else { b[(i, j)] });
    let tol = 1e-9 * n.norm_l2().max(1.0);
    let mut levels: Vec<Vec<Vec<c64>>> = Vec::new();
    let empty = Vec::new();
    loop {
        let basis = levels.last().unwrap_or(&empty);
        // (I − QQ*) N
        let mut m = n.clone();
        for q in basis {
            for j in 0..k {
                let dot = (0..k).fold(c64::new(0.0, 0.0), |a, i| a + q[i].conj() * n[(i, j)]);
                for i in 0..k {
                    m[(i, j)] -= q[i] * dot;
                }
            }
        }
        let Ok(svd) = m.svd() else { break };
        let sv = svd.S().column_vector();
        let mut next: Vec<Vec<c64>> =
            (0..k).filter(|&c| sv[c].re < tol).map(|c| (0..k).map(|i| svd.V()[(i, c)]).collect()).collect();
        if next.len() <= basis.len() {
            break;
        }
        next.truncate(cap);
        let full = next.len() >= cap;
        levels.push(next);
        if full {
            break;
        }
    }
    levels
}

/// The ring structure of ν in block `b`: `ring(x)` is the ring size of the
/// block vector x relative to its largest entry (over the neighbourhood).
/// Vectors N·w smaller than 1e-7·‖N‖ (rounding of N on the eigenvectors)
/// are skipped.
pub fn ring_structure(b: &faer::Mat<c64>, nu: c64, cap: usize, ring: &dyn Fn(&[c64]) -> f64) -> RingStructure {
    let k = b.nrows();
    let levels = chain_levels(b, nu, cap);
    let empty = Vec::new();
    let g = levels.last().unwrap_or(&empty);
    let n = faer::Mat::<c64>::from_fn(k, k, |i, j| if i == j { b[(i, j)] - nu } else { b[(i, j)] });
    let norm = n.norm_l2().max(1e-300);
    let apply = |w: &[c64]| -> Vec<c64> {
        (0..k).map(|i| (0..k).fold(c64::new(0.0, 0.0), |a, j| a + n[(i, j)] * w[j])).collect()
    };
    let size = |x: &[c64]| x.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let max_ring = |vs: &[Vec<c64>]| vs.iter().map(|w| ring(w)).fold(0.0, f64::max);
    let eigenvector_ring = levels.first().map_or(0.0, |k1| max_ring(k1));
    let space_ring = max_ring(g);
    let tops: Vec<Vec<c64>> = g.iter().map(|w| apply(w)).filter(|t| size(t) > 1e-7 * norm).collect();
    let chain_ring = max_ring(&tops);
    RingStructure { dimension: g.len(), eigenvector_ring, space_ring, chain_ring, tops: tops.len() }
}
