//! Lemma S7 (ARCHITECTURE.md, "The proofs, step by step"): the spectral C¹
//! conditions of a rational matrix decided exactly, from its characteristic
//! polynomial, with no enclosure at all.
//!
//! The Fourier blocks split λ1's double eigenvalue into two simple ones, which
//! the disc enclosures can prove real and simple. Without a rotation of order
//! ≥ 3 (a 4-3 eon surrounded by QQT, a face sequence of period 2) λ1 is a
//! double eigenvalue of one matrix, and no enclosure of a cluster can show it
//! real or semisimple. When every weight is rational and λ1 is rational (4-3
//! subdivision: λ1 = 1/2), exact arithmetic can:
//!
//! with p(x) = det(xI − S) over Q,
//! 1. 1 is a root of p of multiplicity 1: λ0 = 1 is simple;
//! 2. r (0 < r < 1) is a root of multiplicity exactly 2, and rank(S − rI) =
//!    N − 2: λ1 = λ2 = r, real, positive, semisimple;
//! 3. the cofactor q = p / ((x − 1)(x − r)²) has every root strictly inside
//!    |x| < ρ for a rational ρ ≤ r (Schur–Cohn, `numeric::exact::
//!    roots_inside_disc`): every other eigenvalue is smaller than λ1 in
//!    modulus.
//!
//! That is Reif's spectral condition, proved. The floating-point spectrum only
//! proposes the candidate r (small-denominator convergents of its real
//! eigenvalues); a wrong proposal fails step 2 or 3 and proves nothing.

use num_traits::{One, Signed, Zero};
use serde::Serialize;

use super::matrix::ExactRows;
use crate::numeric::exact::{roots_inside_disc, QMatrix};
use crate::numeric::Rational;

/// Largest matrix the exact route is tried on (exact Hessenberg reduction
/// and ranks of an N × N rational matrix).
pub const MAX_EXACT_ROUTE_SIZE: usize = 120;

/// What the exact route proved (lemma S7).
#[derive(Clone, Debug, Serialize)]
pub struct ExactSpectrum {
    /// λ1 = λ2, a fraction
    pub lambda1: String,
    /// every eigenvalue other than 1 and λ1 has modulus strictly below this
    /// fraction (≤ λ1)
    pub others_below: String,
    /// the matrix size N
    pub size: usize,
    /// degree of the cofactor q tested by Schur–Cohn (N − 3)
    pub cofactor_degree: usize,
    #[serde(skip)]
    pub lambda1_value: Rational,
    #[serde(skip)]
    pub others_below_value: Rational,
}

/// The whole matrix over Q from its exact rows, or why there is none.
fn rational_matrix(rows: &ExactRows) -> Result<QMatrix, String> {
    let n = rows.len();
    let mut m = QMatrix::zeros(n);
    for (i, row) in rows.iter().enumerate() {
        let row = row.as_ref().ok_or_else(|| format!("row {i} has no exact form"))?;
        for (j, w) in row {
            let w = w.to_rational().ok_or_else(|| format!("row {i} holds an irrational weight"))?;
            let sum = m.get(i, *j) + &w;
            m.set(i, *j, sum);
        }
    }
    Ok(m)
}

/// Lemma S7 on the whole matrix given by `rows`, for the first candidate r
/// (largest first) that passes; `Err` says why none does.
pub fn prove(rows: &ExactRows, candidates: &[Rational]) -> Result<ExactSpectrum, String> {
    let n = rows.len();
    if n > MAX_EXACT_ROUTE_SIZE {
        return Err(format!("the matrix has {n} rows, above the {MAX_EXACT_ROUTE_SIZE} of the exact route"));
    }
    let s = rational_matrix(rows)?;
    let p = s.charpoly();
    let one = Rational::one();
    let (m1, p1) = p.root_multiplicity(&one);
    if m1 != 1 {
        return Err(format!("1 is a root of the characteristic polynomial of multiplicity {m1}, not 1"));
    }
    let mut rs: Vec<Rational> = candidates.iter().filter(|r| r.is_positive() && **r < one).cloned().collect::<Vec<_>>();
    rs.sort_by(|a, b| b.cmp(a));
    rs.dedup();
    let mut why = Vec::new();
    for r in rs {
        let (mr, q) = p1.root_multiplicity(&r);
        match mr {
            0 => continue,
            2 => {}
            _ => {
                why.push(format!("{r} is a root of multiplicity {mr}, not 2"));
                continue;
            }
        }
        let geometric = n - s.shifted(&r).rank();
        if geometric != 2 {
            why.push(format!("{r} is a double root but its eigenspace has dimension {geometric}: defective"));
            continue;
        }
        if !roots_inside_disc(&q, &r) {
            why.push(format!("{r} is a double semisimple root, but another eigenvalue has modulus ≥ {r}"));
            continue;
        }
        // the tightest ρ = r(1 − 2^-j) that still holds every other root
        let mut below = r.clone();
        let mut step = Rational::one();
        for _ in 0..40 {
            step = step / Rational::from_integer(2.into());
            let rho = &r * (Rational::one() - &step);
            if roots_inside_disc(&q, &rho) {
                below = rho;
                break;
            }
        }
        debug_assert!(below <= r && !below.is_zero() || q.degree() == 0 || below.is_zero());
        return Ok(ExactSpectrum {
            lambda1: r.to_string(),
            others_below: below.to_string(),
            size: n,
            cofactor_degree: q.degree(),
            lambda1_value: r,
            others_below_value: below,
        });
    }
    if why.is_empty() {
        why.push("no candidate rational λ1 is a root of the characteristic polynomial".into());
    }
    Err(why.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::cyclotomic::Cyclotomic;
    use crate::numeric::exact::q;

    fn rows_of(m: &[&[(i64, i64)]]) -> ExactRows {
        m.iter()
            .map(|row| {
                Some(
                    row.iter()
                        .enumerate()
                        .filter(|(_, (a, _))| *a != 0)
                        .map(|(j, &(a, b))| (j, Cyclotomic::from_rational(&q(a, b))))
                        .collect(),
                )
            })
            .collect()
    }

    /// diag(1, 1/2, 1/2, 1/4): proved, with λ1 = 1/2 and every other
    /// eigenvalue below 1/2 (the tightest ρ tried is 3/8 ≥ 1/4).
    #[test]
    fn a_diagonal_matrix_is_proved() {
        let rows = rows_of(&[
            &[(1, 1), (0, 1), (0, 1), (0, 1)],
            &[(0, 1), (1, 2), (0, 1), (0, 1)],
            &[(0, 1), (0, 1), (1, 2), (0, 1)],
            &[(0, 1), (0, 1), (0, 1), (1, 4)],
        ]);
        let e = prove(&rows, &[q(1, 2), q(1, 4)]).unwrap();
        assert_eq!(e.lambda1_value, q(1, 2));
        assert!(e.others_below_value > q(1, 4) && e.others_below_value < q(1, 2));
    }

    /// A Jordan block at 1/2 (defective), a third eigenvalue equal to λ1,
    /// and a negative eigenvalue −1/2 of λ1's modulus: none is proved.
    #[test]
    fn defective_tied_and_equimodular_matrices_are_not_proved() {
        let jordan = rows_of(&[&[(1, 1), (0, 1), (0, 1)], &[(0, 1), (1, 2), (1, 1)], &[(0, 1), (0, 1), (1, 2)]]);
        assert!(prove(&jordan, &[q(1, 2)]).unwrap_err().contains("defective"));
        let triple = rows_of(&[
            &[(1, 1), (0, 1), (0, 1), (0, 1)],
            &[(0, 1), (1, 2), (0, 1), (0, 1)],
            &[(0, 1), (0, 1), (1, 2), (0, 1)],
            &[(0, 1), (0, 1), (0, 1), (1, 2)],
        ]);
        assert!(prove(&triple, &[q(1, 2)]).unwrap_err().contains("multiplicity 3"));
        let negative = rows_of(&[
            &[(1, 1), (0, 1), (0, 1), (0, 1)],
            &[(0, 1), (1, 2), (0, 1), (0, 1)],
            &[(0, 1), (0, 1), (1, 2), (0, 1)],
            &[(0, 1), (0, 1), (0, 1), (-1, 2)],
        ]);
        assert!(prove(&negative, &[q(1, 2)]).unwrap_err().contains("modulus ≥ 1/2"));
        // and a wrong candidate proves nothing
        let fine = rows_of(&[&[(1, 1), (0, 1), (0, 1)], &[(0, 1), (1, 2), (0, 1)], &[(0, 1), (0, 1), (1, 2)]]);
        assert!(prove(&fine, &[q(1, 3)]).is_err());
    }
}
