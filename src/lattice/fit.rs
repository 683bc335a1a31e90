//! Deriving stencils from a polynomial space, exactly: fit a polynomial from
//! span{x^a y^b} to samples of the control points by least squares, then
//! evaluate the fit at the new points. This is how Khan–Mustafa derive their
//! rules (a quadratic fitted to a 3×3 grid, a cubic to a 4×4 grid). When there
//! are as many independent samples as monomials the fit interpolates; with more
//! samples it is the least-squares fit (normal equations), which is the only
//! reading under which the printed Khan–Mustafa coefficients come out.

use crate::error::Error;
use crate::numeric::Rational;
use num_traits::{One, Zero};

/// A monomial x^a y^b as its exponents (a, b).
pub type Monomial = (u32, u32);

/// The exact least-squares fit: coefficient k of the fitted polynomial is
/// Σ_s `coeffs[k][s]` · (value at sample s), for any sample values.
#[derive(Clone, Debug)]
pub struct Fit {
    pub monomials: Vec<Monomial>,
    pub samples: Vec<(Rational, Rational)>,
    pub coeffs: Vec<Vec<Rational>>,
}

fn monomial_at(m: Monomial, x: &Rational, y: &Rational) -> Rational {
    num_traits::pow(x.clone(), m.0 as usize) * num_traits::pow(y.clone(), m.1 as usize)
}

/// Least-squares fit of span{monomials} to the sample positions. Error when
/// the monomials are linearly dependent on the samples (the fit is not unique).
pub fn least_squares(monomials: &[Monomial], samples: &[(Rational, Rational)]) -> Result<Fit, Error> {
    let (k, s) = (monomials.len(), samples.len());
    // V[s][k] = monomial k at sample s; solve (VᵀV) C = Vᵀ by Gauss–Jordan
    let v: Vec<Vec<Rational>> =
        samples.iter().map(|(x, y)| monomials.iter().map(|&m| monomial_at(m, x, y)).collect()).collect();
    let mut a: Vec<Vec<Rational>> = (0..k)
        .map(|r| {
            let mut row: Vec<Rational> =
                (0..k).map(|c| (0..s).fold(Rational::zero(), |acc, t| acc + &v[t][r] * &v[t][c])).collect();
            row.extend((0..s).map(|t| v[t][r].clone()));
            row
        })
        .collect();
    for col in 0..k {
        let p = (col..k)
            .find(|&r| !a[r][col].is_zero())
            .ok_or_else(|| Error::Numeric(format!("the {k} monomials are not independent on these {s} samples")))?;
        a.swap(col, p);
        let piv = a[col][col].clone();
        for x in a[col].iter_mut() {
            *x = &*x / &piv;
        }
        for r in 0..k {
            if r != col && !a[r][col].is_zero() {
                let f = a[r][col].clone();
                let pivot_row = a[col].clone();
                for (x, p) in a[r].iter_mut().zip(&pivot_row) {
                    *x = &*x - &f * p;
                }
            }
        }
    }
    let coeffs = a.into_iter().map(|row| row[k..].to_vec()).collect();
    Ok(Fit { monomials: monomials.to_vec(), samples: samples.to_vec(), coeffs })
}

impl Fit {
    /// Weights of the samples in the fitted polynomial's value at (x, y): the
    /// stencil of a new point at that position.
    pub fn weights_at(&self, x: &Rational, y: &Rational) -> Vec<Rational> {
        let mut w = vec![Rational::zero(); self.samples.len()];
        for (k, &m) in self.monomials.iter().enumerate() {
            let b = monomial_at(m, x, y);
            for (t, c) in self.coeffs[k].iter().enumerate() {
                w[t] = &w[t] + &b * c;
            }
        }
        w
    }
    /// Weights of the samples in the coefficient of monomial `m`.
    pub fn coefficient(&self, m: Monomial) -> Option<&[Rational]> {
        self.monomials.iter().position(|&x| x == m).map(|k| self.coeffs[k].as_slice())
    }
    /// True when the fit passes through every sample for all data (as many
    /// independent samples as monomials): interpolation rather than least squares.
    pub fn interpolates(&self) -> bool {
        (0..self.samples.len()).all(|t| {
            let (x, y) = &self.samples[t];
            let w = self.weights_at(x, y);
            w.iter().enumerate().all(|(u, c)| if u == t { c.is_one() } else { c.is_zero() })
        })
    }
}

/// A derived mask: (offset, weight) pairs.
pub type DerivedMask = Vec<((i64, i64), Rational)>;

/// The four masks of a binary lattice scheme derived from a polynomial space:
/// samples at the offsets (r, s) · spacing, new point of parity (α, β) at
/// (α/2, β/2) · spacing. Result indexed [α][β], each a list of (offset, weight).
pub fn derive_masks(
    monomials: &[Monomial],
    offsets: &[(i64, i64)],
    spacing: &Rational,
) -> Result<[[DerivedMask; 2]; 2], Error> {
    let samples: Vec<(Rational, Rational)> = offsets
        .iter()
        .map(|&(r, s)| (Rational::from_integer(r.into()) * spacing, Rational::from_integer(s.into()) * spacing))
        .collect();
    let fit = least_squares(monomials, &samples)?;
    let half = Rational::new(1.into(), 2.into()) * spacing;
    let mask = |alpha: i64, beta: i64| {
        let w = fit.weights_at(
            &(&half * Rational::from_integer(alpha.into())),
            &(&half * Rational::from_integer(beta.into())),
        );
        offsets.iter().copied().zip(w).collect::<Vec<_>>()
    };
    Ok([[mask(0, 0), mask(0, 1)], [mask(1, 0), mask(1, 1)]])
}

/// The offsets of a square grid {lo..=hi}², i fastest.
pub fn grid(lo: i64, hi: i64) -> Vec<(i64, i64)> {
    (lo..=hi).flat_map(|s| (lo..=hi).map(move |r| (r, s))).collect()
}

/// All monomials x^a y^b of total degree ≤ d.
pub fn total_degree(d: u32) -> Vec<Monomial> {
    (0..=d).flat_map(|t| (0..=t).map(move |b| (t - b, b))).collect()
}
