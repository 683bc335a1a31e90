//! Number types: the weight scalar that rules are written over (f64, exact
//! rationals — big, and in machine integers for the hot exact paths —
//! outward-rounded intervals, exact elements of cyclotomic fields),
//! rational recognition, and exact polynomial/matrix algebra.

pub mod berkowitz;
pub mod content;
pub mod cyclotomic;
pub mod cyclotomic_element;
pub mod exact;
pub mod expr;
pub mod field;
pub mod interval;
pub mod modular;
pub mod reading;
pub mod recognise;
pub mod small;
pub mod sturm;
pub mod tpoly;
pub mod weight;

pub use cyclotomic_element::Cyclotomic;
pub use field::{EvalError, ExprField};
pub use interval::Interval;
pub use reading::Reading;
pub use small::SmallRational;
pub use tpoly::{BiPoly, TPoly};
pub use weight::{Inexact, ParamValue, Rational, Weight};
