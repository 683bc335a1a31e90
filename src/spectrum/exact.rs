//! Exact confirmation of the floating-point spectrum when S is rational.
//!
//! Candidate rationals come from the floats; each is tested exactly as a root
//! of the characteristic polynomial (of the whole S when it is small enough,
//! else of Fourier block 0, which is rational too). Multiplicities from the
//! full polynomial and exact ranks are facts, not observations.

use num_bigint::BigInt;
use serde::Serialize;

use super::eigenvalue::Eigenvalue;
use crate::dft::blocks::{block_zero_exact, block_zero_exact_from_rows};
use crate::dft::Orbits;
use crate::engine::exact as engine_exact;
use crate::matrix::LocalMatrix;
use crate::numeric::exact::{rational_roots, Poly, QMatrix};
use crate::numeric::Rational;

/// Largest matrix whose full characteristic polynomial is computed exactly.
pub const EXACT_FULL_MAX: usize = 80;

#[derive(Clone, Debug, Serialize)]
pub struct ExactRoot {
    pub value: String,
    #[serde(skip)]
    pub rational: Rational,
    pub algebraic_multiplicity: usize,
    /// exact nullity of S − λI (full method only)
    pub geometric_multiplicity: Option<usize>,
}

#[derive(Clone, Debug, Serialize)]
pub struct ExactSummary {
    /// "full": characteristic polynomial of S; "block0": of Fourier block 0
    pub method: String,
    pub polynomial_degree: usize,
    /// the characteristic polynomial, when short enough to print
    pub charpoly: Option<String>,
    pub rational_roots: Vec<ExactRoot>,
    /// degree of the factor left after removing the rational roots
    pub remaining_degree: usize,
    /// "full": every exact multiplicity equals the floating-point one;
    /// "block0": every rational root of block 0 is a floating-point
    /// eigenvalue found in block 0, with at least block 0's algebraic
    /// multiplicity
    pub agrees_with_float: bool,
    /// the characteristic polynomial itself (printed in full by the curve
    /// report, whatever its degree)
    #[serde(skip)]
    pub poly: Poly,
}

impl ExactSummary {
    /// Every eigenvalue of S is one of the proven rationals, with its
    /// multiplicities from the whole S (not from block 0 alone).
    pub fn complete(&self) -> bool {
        self.method == "full" && self.remaining_degree == 0
    }
}

/// Which rationals are tried as eigenvalues.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Candidates {
    /// the small-denominator reading of each float (`recognise`,
    /// denominators up to 1024): cheap on the large matrices of meshes
    Recognised,
    /// every continued-fraction convergent of each real float (denominators
    /// up to 10⁹): for the few-point windows of curves, where a parameter
    /// such as 123/1000 makes large denominators
    Convergents,
}

fn parse_ratio(s: &str) -> Option<Rational> {
    let (p, q) = s.split_once('/').unwrap_or((s, "1"));
    Some(Rational::new(p.parse::<BigInt>().ok()?, q.parse::<BigInt>().ok()?))
}

pub fn to_qmatrix(m: &LocalMatrix<Rational>) -> QMatrix {
    m.to_qmatrix()
}

pub fn confirm(
    m: &LocalMatrix<Rational>,
    eigs: &mut [Eigenvalue],
    period: usize,
    n: usize,
    candidates: Candidates,
) -> ExactSummary {
    if needs_full(m.size(), period, n) {
        confirm_with("full", &to_qmatrix(m), true, eigs, candidates)
    } else {
        let orbits = Orbits::new(m, period, n);
        confirm_with("block0", &block_zero_exact(m, &orbits), false, eigs, candidates)
    }
}

/// Whether confirmation works on the whole S (small, or without rotation
/// symmetry) rather than on Fourier block 0.
pub fn needs_full(size: usize, period: usize, n: usize) -> bool {
    size <= EXACT_FULL_MAX || period == n
}

/// [`confirm`] for a rotation-symmetric S too large for the full method, from
/// its representative rows alone (`rows[o]`: the row of orbit o's
/// representative): block 0 needs nothing else.
pub fn confirm_block0(
    rows: &[&[(usize, Rational)]],
    orbits: &Orbits,
    eigs: &mut [Eigenvalue],
    candidates: Candidates,
) -> ExactSummary {
    confirm_with("block0", &block_zero_exact_from_rows(rows, orbits), false, eigs, candidates)
}

/// Test the float eigenvalues' rational readings against the exact
/// characteristic polynomial of `mat` (all of S when `full`, else block 0).
fn confirm_with(method: &str, mat: &QMatrix, full: bool, eigs: &mut [Eigenvalue], policy: Candidates) -> ExactSummary {
    // (index of the float eigenvalue, a rational it may be)
    let candidates: Vec<(usize, Rational)> = match policy {
        Candidates::Recognised => {
            eigs.iter().enumerate().filter_map(|(k, e)| Some((k, parse_ratio(e.recognised.as_deref()?)?))).collect()
        }
        Candidates::Convergents => eigs
            .iter()
            .enumerate()
            .filter(|(_, e)| e.im == 0.0)
            .flat_map(|(k, e)| engine_exact::candidates([e.re]).into_iter().map(move |c| (k, c)))
            .collect(),
    };
    let cand_values: Vec<Rational> = candidates.iter().map(|c| c.1.clone()).collect();
    // the whole S: the one exact confirmation every domain uses (roots and
    // exact ranks); block 0 alone: its rational roots only, since ranks of a
    // block say nothing about the eigenspaces of S
    let (poly, roots, remaining_degree) = if full {
        let c = engine_exact::confirm(mat, &cand_values);
        let roots: Vec<(Rational, usize, Option<usize>)> =
            c.eigenvalues.into_iter().map(|e| (e.value, e.algebraic, Some(e.geometric))).collect();
        (c.charpoly, roots, c.remaining_degree)
    } else {
        let poly = mat.charpoly();
        let (roots, rest) = rational_roots(&poly, &cand_values);
        let degree = rest.degree();
        (poly, roots.into_iter().map(|(r, a)| (r, a, None)).collect(), degree)
    };
    let mut agrees = true;
    let mut out = Vec::new();
    for (r, alg, geo) in &roots {
        let text = r.to_string();
        // the float it came from: the closest of those proposing it
        let rv = crate::numeric::Weight::to_f64(r);
        let closest = candidates
            .iter()
            .filter(|c| &c.1 == r)
            .map(|c| c.0)
            .min_by(|&a, &b| (eigs[a].re - rv).abs().total_cmp(&(eigs[b].re - rv).abs()));
        match closest {
            Some(k) => {
                let e = &mut eigs[k];
                e.exact = Some(text.clone());
                // the whole S: the same multiplicities; block 0 alone: the
                // float analysis must also find the root in block 0, at least
                // as often as block 0's characteristic polynomial has it
                // (other blocks may add copies)
                let differs = if full {
                    e.algebraic_multiplicity != *alg || Some(e.geometric_multiplicity) != *geo
                } else {
                    !e.blocks.contains(&0) || e.algebraic_multiplicity < *alg
                };
                agrees &= !differs;
            }
            None => agrees = false,
        }
        out.push(ExactRoot {
            value: text,
            rational: r.clone(),
            algebraic_multiplicity: *alg,
            geometric_multiplicity: *geo,
        });
    }
    ExactSummary {
        method: method.to_string(),
        polynomial_degree: poly.degree(),
        charpoly: (poly.degree() <= 12).then(|| poly.pretty()),
        rational_roots: out,
        remaining_degree,
        agrees_with_float: agrees,
        poly,
    }
}
