//! Complex intervals in rectangular form: a real and an imaginary interval.
//! Products are enclosed by interval arithmetic on the four real products, so
//! every operation encloses the exact result for every pair of enclosed
//! numbers (rectangles are not closed under multiplication; the enclosure is
//! the bounding rectangle, which is all the certificate needs).

use crate::numeric::Interval;
use faer::c64;
use std::ops::{Add, Mul, Neg, Sub};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CInterval {
    pub re: Interval,
    pub im: Interval,
}

impl CInterval {
    pub fn new(re: Interval, im: Interval) -> CInterval {
        CInterval { re, im }
    }
    pub fn real(re: Interval) -> CInterval {
        CInterval { re, im: Interval::point(0.0) }
    }
    pub fn zero() -> CInterval {
        CInterval::real(Interval::point(0.0))
    }
    /// A floating-point complex number, taken as exact.
    pub fn point(z: c64) -> CInterval {
        CInterval { re: Interval::point(z.re), im: Interval::point(z.im) }
    }
    pub fn mid(&self) -> c64 {
        c64::new(self.re.mid(), self.im.mid())
    }
    /// An upper bound of |z| over the rectangle.
    pub fn mag(&self) -> f64 {
        (Interval::point(self.re.mag()).square() + Interval::point(self.im.mag()).square()).sqrt().hi
    }
    /// A lower bound of |z| over the rectangle.
    pub fn mig(&self) -> f64 {
        (Interval::point(self.re.mig()).square() + Interval::point(self.im.mig()).square()).sqrt().lo
    }
    /// An upper bound of |z − c| over the rectangle, for a point c.
    pub fn distance_from(&self, c: c64) -> f64 {
        (*self - CInterval::point(c)).mag()
    }
    pub fn conj(&self) -> CInterval {
        CInterval { re: self.re, im: -self.im }
    }
    pub fn scale(&self, s: Interval) -> CInterval {
        CInterval { re: self.re * s, im: self.im * s }
    }
    pub fn is_finite(&self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
}

impl Add for CInterval {
    type Output = CInterval;
    fn add(self, o: CInterval) -> CInterval {
        CInterval { re: self.re + o.re, im: self.im + o.im }
    }
}

impl Sub for CInterval {
    type Output = CInterval;
    fn sub(self, o: CInterval) -> CInterval {
        CInterval { re: self.re - o.re, im: self.im - o.im }
    }
}

impl Neg for CInterval {
    type Output = CInterval;
    fn neg(self) -> CInterval {
        CInterval { re: -self.re, im: -self.im }
    }
}

impl Mul for CInterval {
    type Output = CInterval;
    fn mul(self, o: CInterval) -> CInterval {
        CInterval { re: self.re * o.re - self.im * o.im, im: self.re * o.im + self.im * o.re }
    }
}

/// Interval matrices, row-major, square.
#[derive(Clone, Debug)]
pub struct CIntervalMatrix {
    pub size: usize,
    pub entries: Vec<CInterval>,
}

impl CIntervalMatrix {
    pub fn zeros(size: usize) -> Self {
        CIntervalMatrix { size, entries: vec![CInterval::zero(); size * size] }
    }
    pub fn get(&self, i: usize, j: usize) -> CInterval {
        self.entries[i * self.size + j]
    }
    pub fn at(&mut self, i: usize, j: usize) -> &mut CInterval {
        &mut self.entries[i * self.size + j]
    }
    pub fn mid(&self) -> faer::Mat<c64> {
        faer::Mat::from_fn(self.size, self.size, |i, j| self.get(i, j).mid())
    }
    /// The largest width of an entry's real or imaginary part.
    pub fn max_width(&self) -> f64 {
        self.entries.iter().map(|z| z.re.width().max(z.im.width())).fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_enclose_exact_values() {
        // (1/3 + i/7)(3 − 7i) = 1 + 1 + i(3/7 − 7/3)
        let a = CInterval::new(Interval::ratio(1, 3), Interval::ratio(1, 7));
        let b = CInterval::point(c64::new(3.0, -7.0));
        let p = a * b;
        let q = |x: i64, y: i64| num_rational::BigRational::new(x.into(), y.into());
        assert!(p.re.contains_rational(&q(2, 1)));
        assert!(p.im.contains_rational(&q(9 - 49, 21)));
        // |3 + 4i| = 5 lies between the lower and upper bounds
        let z = CInterval::point(c64::new(3.0, 4.0));
        assert!(z.mig() <= 5.0 && z.mag() >= 5.0 && z.mag() - z.mig() < 1e-14);
        // i · i = −1 exactly
        let i = CInterval::point(c64::new(0.0, 1.0));
        assert_eq!(i * i, CInterval::point(c64::new(-1.0, 0.0)));
    }
}
