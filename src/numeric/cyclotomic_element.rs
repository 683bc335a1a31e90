//! The type of an exact element of a cyclotomic field, its fields only: the
//! `Weight` trait names it (`Weight::from_cyclotomic`) while its arithmetic
//! (`numeric::cyclotomic`) is written with `Weight`'s operations, so the
//! type sits below both and they import it one way.

use num_bigint::BigInt;

/// An exact element of a cyclotomic field (see `numeric::cyclotomic`, which
/// holds its arithmetic and the meaning of the fields).
#[derive(Clone, Debug)]
pub struct Cyclotomic {
    /// N: the element is written in Q(ζ_N); 0 marks the undefined element
    pub(super) order: u32,
    /// numerators of the coefficients of 1, ζ_N, ..., ζ_N^{φ(N)−1}, no
    /// trailing zeros (empty: zero)
    pub(super) num: Vec<BigInt>,
    /// the common denominator, positive, coprime to the numerators together
    pub(super) den: BigInt,
}
