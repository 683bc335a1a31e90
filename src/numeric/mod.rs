//! Number types: the weight scalar that rules are written over (f64, exact
//! rationals, outward-rounded intervals, exact elements of cyclotomic fields),
//! rational recognition, and exact polynomial/matrix algebra.

pub mod cyclotomic;
pub mod exact;
pub mod expr;
pub mod field;
pub mod interval;
pub mod recognise;
pub mod weight;

pub use cyclotomic::Cyclotomic;
pub use field::{EvalError, ExprField, Reading};
pub use interval::Interval;
pub use weight::{Inexact, ParamValue, Rational, Weight};
