//! The curvature class in the exact sweep (`sweep --exact --curvature`).
//!
//! The class (`curvature::CurvatureClass`, Peters–Reif ch. 7, defined in
//! `src/curvature/mod.rs`) compares μ — the largest-modulus eigenvalue below
//! the subdominant λ1 whose eigenfunctions do not vanish on the
//! characteristic ring — with λ1²: zero (|μ| < λ1²), bounded (|μ| = λ1², no
//! visible Jordan block), unbounded (|μ| > λ1², or a visible Jordan block
//! at λ1²), not applicable (the first-order test fails).
//!
//! As a function of the swept t, the class can change only where
//!
//! - the order of the eigenvalues' moduli or their multiplicities change —
//!   the candidates the exact sweep already has (branches meeting, or
//!   meeting each other's negatives);
//! - |x(t)| = y(t)² for a real root x of some block polynomial P_a and a
//!   root y of the polynomial of λ1's block: x = y² or −x = y², i.e. a
//!   common root of P_a(±x) and the root-squared polynomial G(P)(x) =
//!   (−1)^d P(√x) P(−√x) (Graeffe's transform: its roots are the squares
//!   of P's). These pairs go through the same first-non-vanishing
//!   principal subresultant machinery as the others ([`square_pairs`]).
//! - |u(t)| = y(t)² for a non-real root u: u·ū = y⁴, the modulus family
//!   (`modulus`) with the target G(P) (roots y², so its own root-squared
//!   polynomial has the roots y⁴) — the exact sweep adds these targets
//!   with `--curvature`.
//!
//! Every open piece between the candidates is decided at one rational
//! point by the ordinary second-order analysis (`curvature::curvature`,
//! which compares |μ| and λ² exactly when both read as rationals and in
//! floating point otherwise). A candidate is decided at itself when it is
//! rational; an irrational candidate is decided at a rational within 1e-30
//! of it, and a class that needs |μ| = λ1² exactly there (bounded, or
//! unbounded through a Jordan block) is accepted only when the candidate is
//! a root of the |x| = y² family above, where such an equality can happen —
//! otherwise the point is left undecided and named.
//!
//! Assumptions: which eigenfunctions vanish on the ring is constant on each
//! open piece (it is decided in floating point at the piece's point). Where
//! the non-real family cannot be followed (its resultant vanishes
//! identically) and a piece has a non-real eigenvalue, the curvature sets'
//! `not_exact_because` says so.

use crate::curvature::{curvature, CurvatureClass, CurvatureOptions, Evidence, EIG_TOL};
use crate::error::Error;
use crate::neighbourhood::Configuration;
use crate::numeric::{TPoly, Weight};
use crate::sdc::Scheme;

/// A polynomial in x (lowest first) with coefficients polynomials in t
/// (as the exact sweep's block polynomials).
pub(crate) type BiPoly = Vec<TPoly>;

/// Graeffe's root squaring: the monic polynomial whose roots are the
/// squares of p's roots (with multiplicity). With p(y) = E(y²) + y O(y²),
/// p(y) p(−y) = E(y²)² − y² O(y²)², so G(x) = ±(E(x)² − x O(x)²), the sign
/// making it monic ((−1)^d for a monic p of degree d).
pub(crate) fn root_squared(p: &BiPoly) -> BiPoly {
    let d = p.len() - 1;
    let even: BiPoly = p.iter().step_by(2).cloned().collect();
    let odd: BiPoly = p.iter().skip(1).step_by(2).cloned().collect();
    let square = |a: &BiPoly| -> BiPoly {
        if a.is_empty() {
            return Vec::new();
        }
        let mut out = vec![TPoly::zero(); 2 * a.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in a.iter().enumerate() {
                let e = std::mem::replace(&mut out[i + j], TPoly::zero());
                out[i + j] = e + x.clone() * y.clone();
            }
        }
        out
    };
    let e2 = square(&even);
    let o2 = square(&odd);
    let mut g = vec![TPoly::zero(); d + 1];
    for (k, c) in e2.into_iter().enumerate() {
        g[k] = c;
    }
    for (k, c) in o2.into_iter().enumerate() {
        let e = std::mem::replace(&mut g[k + 1], TPoly::zero());
        g[k + 1] = e - c;
    }
    if d % 2 == 1 {
        g = g.into_iter().map(|c| -c).collect();
    }
    g
}

/// The pairs whose common roots mark |x| = y²: (P_a(x), G(P_λ)(x)) and
/// (P_a(−x), G(P_λ)(x)) for every block polynomial P_a and every
/// polynomial P_λ of a block that can carry λ1.
pub(crate) fn square_pairs(polys: &[BiPoly], lambda_polys: &[BiPoly]) -> Vec<(BiPoly, BiPoly)> {
    let negated = |p: &BiPoly| -> BiPoly {
        p.iter().enumerate().map(|(k, c)| if k % 2 == 1 { -c.clone() } else { c.clone() }).collect()
    };
    let mut out = Vec::new();
    for l in lambda_polys {
        let g = root_squared(l);
        for a in polys {
            out.push((a.clone(), g.clone()));
            out.push((negated(a), g.clone()));
        }
    }
    out
}

/// The class at one point and how it was decided.
#[derive(Clone, Debug)]
pub(crate) struct ClassAt {
    pub class: CurvatureClass,
    pub evidence: String,
    /// the class holds on an open neighbourhood of the point when the
    /// eigenvalues move continuously: zero, or unbounded with |μ| > λ²
    /// beyond the tolerance (not through a Jordan block at λ²)
    pub strict: bool,
}

/// The second-order analysis at one point, exactly as `subdlab curvature`
/// computes it (exact comparison of |μ| and λ² when both read as
/// rationals).
pub(crate) fn class_at(scheme: &dyn Scheme, config: &Configuration) -> Result<ClassAt, Error> {
    let c = curvature(scheme, config, &CurvatureOptions::default())?;
    let ratio = c.mu_over_lambda_squared;
    let strict = match c.class {
        CurvatureClass::Zero => true,
        CurvatureClass::Unbounded => ratio.is_some_and(|r| r > 1.0 + EIG_TOL),
        _ => false,
    };
    // the ring test, the characteristic map and the Jordan structure are
    // floating point even where |μ| and λ² are compared exactly
    let evidence = match c.evidence {
        Evidence::Exact => {
            "floating point (|μ| against λ² exactly: both rational; ring and Jordan tests in floating point)".into()
        }
        Evidence::FloatingPoint => format!("floating point (|μ| against λ² with relative tolerance {EIG_TOL:e})"),
        Evidence::None => "floating point (first-order test)".into(),
    };
    Ok(ClassAt { class: c.class, evidence, strict })
}

/// Whether a class that needs |μ| = λ² exactly may stand at a point.
pub(crate) fn needs_equality(class: CurvatureClass, strict: bool) -> bool {
    matches!(class, CurvatureClass::Bounded | CurvatureClass::Unbounded) && !strict
}

#[cfg(test)]
mod tests {
    use super::*;

    fn constant_poly(c: &[i64]) -> BiPoly {
        c.iter().map(|&x| TPoly::int(x)).collect()
    }

    #[test]
    fn root_squaring_squares_the_roots() {
        // (x − 2)(x + 3) = x² + x − 6 → (x − 4)(x − 9) = x² − 13x + 36
        assert_eq!(root_squared(&constant_poly(&[-6, 1, 1])), constant_poly(&[36, -13, 1]));
        // (x − 1)(x − 2)(x + 1) = x³ − 2x² − x + 2 → (x − 1)²(x − 4) = x³ − 6x² + 9x − 4
        assert_eq!(root_squared(&constant_poly(&[2, -1, -2, 1])), constant_poly(&[-4, 9, -6, 1]));
        // x − t → x − t² (a root moving with t)
        let p = vec![-TPoly::variable(), TPoly::int(1)];
        assert_eq!(root_squared(&p), vec![-(TPoly::variable() * TPoly::variable()), TPoly::int(1)]);
    }
}
