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

use num_traits::{One, Signed};
use serde::Serialize;

use super::matrix::ExactRows;
use crate::numeric::exact::{roots_inside_disc, QMatrix};
use crate::numeric::Rational;

/// Largest matrix the exact route is tried on (exact Hessenberg reduction
/// and ranks of an N × N rational matrix).
pub const MAX_EXACT_ROUTE_SIZE: usize = 120;

/// What the exact route decided (lemma S7): a proof, or a disproof with
/// the multiplicities that break the statement.
#[derive(Clone, Debug, Serialize)]
pub struct ExactSpectrum {
    /// true: PROVED; false: DISPROVED (λ1 dominant but not a double
    /// semisimple eigenvalue, or 1 not simple)
    pub proved: bool,
    /// the multiplicity of 1 as a root of det(xI − S)
    pub one_multiplicity: usize,
    /// λ1, a fraction (absent when 1 is not simple)
    pub lambda1: Option<String>,
    /// its algebraic and geometric multiplicities
    pub algebraic: usize,
    pub geometric: usize,
    /// every eigenvalue other than 1 and λ1 has modulus strictly below this
    /// fraction (≤ λ1)
    pub others_below: Option<String>,
    /// the matrix size N
    pub size: usize,
    /// degree of the cofactor q tested by Schur–Cohn
    pub cofactor_degree: usize,
    /// why a disproof disproves
    #[serde(skip)]
    pub why: String,
    #[serde(skip)]
    pub lambda1_value: Option<Rational>,
    #[serde(skip)]
    pub others_below_value: Option<Rational>,
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

/// Lemma S7 on the whole matrix given by `rows`: `Ok` with a proof or a
/// disproof, `Err` with why neither (no candidate λ1 is a rational root with
/// every other eigenvalue below it).
///
/// A disproof needs the same dominance: r a root with every root other than
/// 1 and r inside |x| < r (Schur–Cohn on the cofactor of (x − r)^m), 1
/// simple; then r is λ1, and multiplicity m ≠ 2 or an eigenspace of
/// dimension ≠ 2 (a Jordan block at λ1) falsifies the statement. 1 of
/// multiplicity ≥ 2 falsifies "λ0 = 1 simple" outright.
pub fn prove(rows: &ExactRows, candidates: &[Rational]) -> Result<ExactSpectrum, String> {
    let n = rows.len();
    if n > MAX_EXACT_ROUTE_SIZE {
        return Err(format!("the matrix has {n} rows, above the {MAX_EXACT_ROUTE_SIZE} of the exact route"));
    }
    let s = rational_matrix(rows)?;
    let p = s.charpoly();
    let one = Rational::one();
    let (m1, p1) = p.root_multiplicity(&one);
    let outcome =
        |proved, why: String, lambda1: Option<Rational>, algebraic, geometric, below: Option<Rational>, q_degree| {
            ExactSpectrum {
                proved,
                one_multiplicity: m1,
                lambda1: lambda1.as_ref().map(|r: &Rational| r.to_string()),
                algebraic,
                geometric,
                others_below: below.as_ref().map(|r: &Rational| r.to_string()),
                size: n,
                cofactor_degree: q_degree,
                why,
                lambda1_value: lambda1,
                others_below_value: below,
            }
        };
    match m1 {
        0 => return Err("1 is not a root of the characteristic polynomial".into()),
        1 => {}
        m => {
            let why = format!("λ0 = 1 is not simple: a root of det(xI − S) of multiplicity {m} (exact, over Q)");
            return Ok(outcome(false, why, None, 0, 0, None, p1.degree()));
        }
    }
    let mut rs: Vec<Rational> = candidates.iter().filter(|r| r.is_positive() && **r < one).cloned().collect::<Vec<_>>();
    rs.sort_by(|a, b| b.cmp(a));
    rs.dedup();
    let mut why = Vec::new();
    for r in rs {
        let (mr, q) = p1.root_multiplicity(&r);
        if mr == 0 {
            continue;
        }
        if !roots_inside_disc(&q, &r) {
            why.push(format!("{r} is a root of multiplicity {mr}, but another eigenvalue has modulus ≥ {r}"));
            continue;
        }
        // r is λ1: every other eigenvalue but 1 is smaller in modulus
        let geometric = n - s.shifted(&r).rank();
        if mr != 2 || geometric != 2 {
            let why = format!(
                "λ1 = {r} (every other eigenvalue but 1 below it in modulus) has algebraic multiplicity {mr} and \
                 geometric multiplicity {geometric}, not a double semisimple eigenvalue (exact, over Q){}",
                if geometric < mr { ": a Jordan block at λ1" } else { "" }
            );
            return Ok(outcome(false, why, Some(r), mr, geometric, None, q.degree()));
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
        return Ok(outcome(true, String::new(), Some(r), 2, 2, Some(below), q.degree()));
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
        assert!(e.proved);
        assert_eq!(e.lambda1_value, Some(q(1, 2)));
        let below = e.others_below_value.unwrap();
        assert!(below > q(1, 4) && below < q(1, 2));
    }

    /// A Jordan block at 1/2 (defective) and a triple 1/2, each dominant:
    /// disproved with the multiplicities; a negative eigenvalue −1/2 of
    /// λ1's modulus, or a wrong candidate: neither proved nor disproved.
    #[test]
    fn defective_tied_and_equimodular_matrices_are_not_proved() {
        let jordan = rows_of(&[&[(1, 1), (0, 1), (0, 1)], &[(0, 1), (1, 2), (1, 1)], &[(0, 1), (0, 1), (1, 2)]]);
        let e = prove(&jordan, &[q(1, 2)]).unwrap();
        assert!(!e.proved && (e.algebraic, e.geometric) == (2, 1), "{e:?}");
        assert!(e.why.contains("Jordan block"));
        let triple = rows_of(&[
            &[(1, 1), (0, 1), (0, 1), (0, 1)],
            &[(0, 1), (1, 2), (0, 1), (0, 1)],
            &[(0, 1), (0, 1), (1, 2), (0, 1)],
            &[(0, 1), (0, 1), (0, 1), (1, 2)],
        ]);
        let e = prove(&triple, &[q(1, 2)]).unwrap();
        assert!(!e.proved && (e.algebraic, e.geometric) == (3, 3), "{e:?}");
        let negative = rows_of(&[
            &[(1, 1), (0, 1), (0, 1), (0, 1)],
            &[(0, 1), (1, 2), (0, 1), (0, 1)],
            &[(0, 1), (0, 1), (1, 2), (0, 1)],
            &[(0, 1), (0, 1), (0, 1), (-1, 2)],
        ]);
        assert!(prove(&negative, &[q(1, 2)]).unwrap_err().contains("modulus ≥ 1/2"));
        // 1 double: "λ0 = 1 simple" is false
        let two_ones = rows_of(&[&[(1, 1), (0, 1), (0, 1)], &[(0, 1), (1, 1), (0, 1)], &[(0, 1), (0, 1), (1, 2)]]);
        let e = prove(&two_ones, &[q(1, 2)]).unwrap();
        assert!(!e.proved && e.one_multiplicity == 2, "{e:?}");
        // and a wrong candidate decides nothing
        let fine = rows_of(&[&[(1, 1), (0, 1), (0, 1)], &[(0, 1), (1, 2), (0, 1)], &[(0, 1), (0, 1), (1, 2)]]);
        assert!(prove(&fine, &[q(1, 3)]).is_err());
    }
}
