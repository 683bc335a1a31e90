//! Limit and tangent stencils from left eigenvectors.
//!
//! Limit stencil: left eigenvector of λ0 = 1, scaled to sum to 1.
//! Tangent stencils: a real basis of the left eigenspace of the subdominant
//! eigenvalue. From a Fourier block the eigenvector is complex; its phase is
//! fixed so the first non-zero weight in sector 0 is real and positive, then the
//! real and imaginary parts are the "cosine" and "sine" stencils. Each tangent
//! stencil is scaled to largest absolute weight 1.

use faer::c64;
use serde::Serialize;

use super::spectrum_result::Spectrum;
use crate::error::Error;

#[derive(Clone, Debug, Serialize)]
pub struct StencilWeight {
    pub vertex: String,
    pub weight: f64,
    pub recognised: Option<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct Stencils {
    pub scheme: String,
    pub valence: usize,
    /// face sequence around the centre (Q quad, T triangle), as in the spectrum
    pub faces: String,
    pub neighbourhood: crate::neighbourhood::NeighbourhoodKind,
    /// weights over all neighbourhood vertices (zeros included, in canonical order)
    pub limit: Vec<StencilWeight>,
    pub tangent: Vec<Vec<StencilWeight>>,
}

const ZERO: f64 = 1e-13;

fn weights(spec: &Spectrum, w: &[f64]) -> Vec<StencilWeight> {
    spec.labels
        .iter()
        .zip(w)
        .map(|(l, &x)| {
            let x = if x.abs() < ZERO { 0.0 } else { x };
            StencilWeight { vertex: l.name.clone(), weight: x, recognised: crate::numeric::recognise::recognise(x) }
        })
        .collect()
}

pub fn limit_stencil(spec: &Spectrum) -> Result<Vec<f64>, Error> {
    let e = spec.eigenvalues.first().ok_or_else(|| Error::Numeric("empty spectrum".into()))?;
    if (e.re - 1.0).abs() > 1e-9 || e.algebraic_multiplicity != 1 {
        return Err(Error::Numeric(format!("no simple eigenvalue 1 (dominant is {}): no limit stencil", e.display())));
    }
    let l = &spec.left_vectors(e)[0];
    let sum: c64 = l.iter().sum();
    if sum.norm() < 1e-12 {
        return Err(Error::Numeric("left eigenvector of 1 sums to zero".into()));
    }
    Ok(l.iter().map(|z| (z / sum).re).collect())
}

pub fn tangent_stencils(spec: &Spectrum) -> Result<Vec<Vec<f64>>, Error> {
    let e = spec.eigenvalues.get(1).ok_or_else(|| Error::Numeric("no subdominant eigenvalue".into()))?;
    let mut out: Vec<Vec<f64>> = Vec::new();
    {
        for l in &spec.left_vectors(e) {
            // fix the phase on the largest weight of the lowest-index vertex group
            let pivot = l.iter().copied().find(|z| z.norm() > 1e-8 * l.iter().map(|z| z.norm()).fold(0.0, f64::max));
            let phase = pivot.map(|z| z.conj() / z.norm()).unwrap_or(c64::new(1.0, 0.0));
            let rotated: Vec<c64> = l.iter().map(|z| z * phase).collect();
            for part in [rotated.iter().map(|z| z.re).collect::<Vec<_>>(), rotated.iter().map(|z| z.im).collect()] {
                if out.len() < e.algebraic_multiplicity.min(2) && independent(&out, &part) {
                    out.push(part);
                }
            }
        }
    }
    for t in &mut out {
        let m = t.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        if m > 0.0 {
            t.iter_mut().for_each(|x| *x /= m);
        }
    }
    Ok(out)
}

/// ‖v − projection of v onto span(basis)‖ / ‖v‖ (Gram–Schmidt); 0 for v = 0.
pub fn span_residual(basis: &[Vec<f64>], v: &[f64]) -> f64 {
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let mut ortho: Vec<Vec<f64>> = Vec::new();
    for b in basis {
        let mut r = b.clone();
        for q in &ortho {
            let d = dot(q, &r);
            r.iter_mut().zip(q).for_each(|(x, y)| *x -= d * y);
        }
        let n = dot(&r, &r).sqrt();
        if n > 1e-12 {
            ortho.push(r.iter().map(|x| x / n).collect());
        }
    }
    let vn = dot(v, v).sqrt();
    if vn == 0.0 {
        return 0.0;
    }
    let mut r = v.to_vec();
    for q in &ortho {
        let d = dot(q, &r);
        r.iter_mut().zip(q).for_each(|(x, y)| *x -= d * y);
    }
    dot(&r, &r).sqrt() / vn
}

/// Is v (non-zero) independent of the vectors in `basis`?
fn independent(basis: &[Vec<f64>], v: &[f64]) -> bool {
    v.iter().map(|x| x * x).sum::<f64>().sqrt() >= 1e-10 && span_residual(basis, v) > 1e-6
}

pub fn stencils(spec: &Spectrum) -> Result<Stencils, Error> {
    let limit = limit_stencil(spec)?;
    let tangent = tangent_stencils(spec)?;
    Ok(Stencils {
        scheme: spec.scheme.clone(),
        valence: spec.valence,
        faces: spec.faces.clone(),
        neighbourhood: spec.neighbourhood,
        limit: weights(spec, &limit),
        tangent: tangent.iter().map(|t| weights(spec, t)).collect(),
    })
}
