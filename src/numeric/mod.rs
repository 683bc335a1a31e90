//! Number types: the weight scalar that rules are written over (f64 or exact
//! rationals), rational recognition, and exact polynomial/matrix algebra.

pub mod exact;
pub mod expr;
pub mod interval;
pub mod recognise;
pub mod weight;

pub use interval::Interval;
pub use weight::{Inexact, ParamValue, Rational, Weight};
