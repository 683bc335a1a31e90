//! The two measures of one shape h (level-0 data over the neighbourhood)
//! on the characteristic ring: the area fraction with the right sign of the
//! Gaussian curvature, and the residual of the best fit h ≈ c·q∘χ + affine.
//!
//! Both look at h refined `levels` analysis steps over the characteristic
//! ring ([`RingSampler`], the sampler `subdlab curvature` uses). The sign of
//! K comes from `curvature::figure::face_signs`: per ring face, a
//! least-squares quadratic with the mixed xy term fitted to the refined
//! points (χ, h) around the face (polar nets refined around first), never an
//! angle defect. The residual fits the ring values of h over span{q∘χ, 1,
//! χ_x, χ_y} (χ the refined control values of the characteristic map) and
//! divides by the part of h that is not affine: 0 means h is the input
//! quadratic up to a factor c and an affine part, 1 that h has nothing of q.

use crate::curvature::figure::{face_signs, RingFits};
use crate::curvature::{Quadratic, RingSampler};

/// The characteristic ring with what every cell's measures need.
pub struct Ring<'a> {
    pub sampler: &'a RingSampler,
    /// the characteristic map's level-0 control points, scaled to unit size
    pub pair: Vec<[f64; 2]>,
    /// χ at the ring vertices (refined control values)
    pub chi: Vec<[f64; 2]>,
    pub polar: bool,
    /// every ring face's fit over χ, prepared once for all heights (None:
    /// a polar net, whose faces are refined around per height)
    fits: Option<RingFits>,
}

impl<'a> Ring<'a> {
    pub fn new(sampler: &'a RingSampler, pair: Vec<[f64; 2]>, polar: bool) -> Ring<'a> {
        let xs = sampler.ring_values(&pair.iter().map(|p| p[0]).collect::<Vec<_>>());
        let ys = sampler.ring_values(&pair.iter().map(|p| p[1]).collect::<Vec<_>>());
        let chi = xs.iter().zip(&ys).map(|(x, y)| [*x, *y]).collect();
        let fits = (!polar).then(|| RingFits::new(sampler, &sampler.points(&pair)));
        Ring { sampler, pair, chi, polar, fits }
    }

    /// Fraction of ring area (in the plane of χ) whose fitted K has sign
    /// `sign` (for t = 0: where the fit reads K = 0).
    pub fn sign_fraction(&self, h: &[f64], sign: i8) -> f64 {
        let scale = h.iter().map(|v| v.abs()).fold(0.0, f64::max).max(1e-300);
        let mut faces: Vec<(&[[f64; 2]], i8)> = Vec::new();
        let polar_faces;
        if let Some(fits) = &self.fits {
            let z: Vec<f64> = self
                .sampler
                .points(&h.iter().map(|v| [v / scale]).collect::<Vec<_>>())
                .iter()
                .map(|p| p.map_or(f64::NAN, |p| p[0]))
                .collect();
            faces.extend(fits.faces.iter().map(|f| (f.poly.as_slice(), f.sign(&z))));
        } else {
            let data: Vec<[f64; 3]> = self.pair.iter().zip(h).map(|(p, v)| [p[0], p[1], v / scale]).collect();
            polar_faces = face_signs(self.sampler, &self.sampler.points(&data), self.polar);
            faces.extend(polar_faces.iter().map(|(poly, s)| (poly.as_slice(), *s)));
        }
        let (mut agree, mut total) = (0.0, 0.0);
        for (poly, s) in &faces {
            let a = area(poly);
            if a.is_finite() {
                total += a;
                if *s == sign {
                    agree += a;
                }
            }
        }
        if total > 0.0 {
            agree / total
        } else {
            f64::NAN
        }
    }

    /// (relative residual, c) of the fit h ≈ c·q∘χ + a + b·χ on the ring
    /// vertices (see the module documentation); residual NaN when h is
    /// affine on the ring.
    pub fn residual(&self, h: &[f64], q: Quadratic) -> (f64, f64) {
        let values = self.sampler.ring_values(h);
        let scale = values.iter().map(|v| v.abs()).fold(0.0, f64::max);
        if scale == 0.0 || !scale.is_finite() {
            return (f64::NAN, 0.0);
        }
        let b = nalgebra::DVector::<f64>::from_iterator(values.len(), values.iter().map(|v| v / scale));
        let affine = |p: &[f64; 2]| [1.0, p[0], p[1]];
        let m = self.chi.len();
        let a3 = nalgebra::DMatrix::<f64>::from_fn(m, 3, |i, j| affine(&self.chi[i])[j]);
        let a4 = nalgebra::DMatrix::<f64>::from_fn(m, 4, |i, j| {
            if j == 0 {
                q.eval(self.chi[i][0], self.chi[i][1])
            } else {
                affine(&self.chi[i])[j - 1]
            }
        });
        let solve = |a: nalgebra::DMatrix<f64>| -> Option<(f64, f64)> {
            let x = a.clone().svd(true, true).solve(&b, 1e-13).ok()?;
            Some(((&b - &a * &x).norm(), x[0]))
        };
        let (Some((rest, _)), Some((fit, c))) = (solve(a3), solve(a4)) else { return (f64::NAN, 0.0) };
        if rest <= 1e-12 * b.norm() {
            return (f64::NAN, 0.0);
        }
        (fit / rest, c * scale)
    }

    /// The size (Euclidean norm over the ring vertices) of the ring values
    /// of h left after the least-squares affine fit a + b·χ: what of h is
    /// not a plane, the part whose decay or growth is the curvature's.
    pub fn curved_size(&self, h: &[f64]) -> f64 {
        let values = self.sampler.ring_values(h);
        let b = nalgebra::DVector::<f64>::from_column_slice(&values);
        let a = nalgebra::DMatrix::<f64>::from_fn(self.chi.len(), 3, |i, j| match j {
            0 => 1.0,
            _ => self.chi[i][j - 1],
        });
        match a.clone().svd(true, true).solve(&b, 1e-13) {
            Ok(x) => (&b - &a * &x).norm(),
            Err(_) => f64::NAN,
        }
    }
}

/// |area| of a polygon (shoelace).
fn area(poly: &[[f64; 2]]) -> f64 {
    let n = poly.len();
    (0..n).map(|i| poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1]).sum::<f64>().abs() / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shoelace_area() {
        assert_eq!(area(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]), 2.0);
        assert_eq!(area(&[[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]]), 0.5);
    }
}
