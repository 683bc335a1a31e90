//! Weight evaluation: a field's expression at (n, j), in the arithmetic the
//! caller asks for (floats; exact rationals where the weight is rational;
//! for the weight types that take them, `Weight::CYCLOTOMIC`, exact elements
//! of a cyclotomic field where it holds cos(2πk/n)), cached because
//! refinement asks for the same weight at every vertex and a Fourier-sum
//! weight costs n terms.

use std::any::TypeId;
use std::collections::HashMap;
use std::sync::Mutex;

use crate::error::Error;
use crate::numeric::expr::{Env, Expr};
use crate::numeric::{Cyclotomic, Inexact, ParamValue, Weight};

/// Entries the weight cache holds before it starts afresh (a sweep over many
/// valences must not grow it without bound).
const CACHE_ENTRIES: usize = 100_000;

/// The parameters with n, j and, for face-corner fields, the face's corner
/// count m (only there: elsewhere `m` may be a sum's index or a parameter).
fn with_nj(params: &Env, n: i64, j: i64, m: Option<i64>) -> Env {
    let mut env = params.clone();
    env.insert("n".into(), ParamValue::from_ratio(n, 1));
    env.insert("j".into(), ParamValue::from_ratio(j, 1));
    if let Some(m) = m {
        env.insert("m".into(), ParamValue::from_ratio(m, 1));
    }
    env
}

/// A weight in floating point, with a reason when it is not a finite real.
pub(super) fn eval_f64(expr: &Expr, params: &Env, n: i64, j: i64, m: Option<i64>) -> Result<f64, Error> {
    let z = expr.eval(&with_nj(params, n, j, m))?;
    if !z.re.is_finite() || !z.im.is_finite() {
        return Err(Error::File("the weight is not a finite number".into()));
    }
    if z.im.abs() > 1e-12 * z.re.abs().max(1.0) {
        return Err(Error::File(format!("the weight is complex ({} + {}i)", z.re, z.im)));
    }
    Ok(z.re)
}

/// The arithmetic a weight is evaluated in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Arithmetic {
    Float,
    /// rational weights only
    Rational,
    /// rational weights, else exact in a cyclotomic field
    Cyclotomic,
}

/// A weight as evaluated: a number (float, or exact rational), or an exact
/// element of a cyclotomic field that is not rational.
#[derive(Clone, Debug)]
enum Evaluated {
    Number(ParamValue),
    Field(Cyclotomic),
}

/// (field, n, j, m, arithmetic, per-vertex parameter value's bits) -> the weight.
type Cache = HashMap<(usize, i64, i64, Option<i64>, Arithmetic, Option<u64>), Result<Evaluated, Inexact>>;

/// The weight fields of a built scheme with their parameter values.
pub(super) struct WeightTable {
    env: Env,
    exprs: Vec<Expr>,
    /// whether field k's expression uses j (else every j shares one entry)
    uses_j: Vec<bool>,
    /// whether field k is a face-corner field (its expression may use m)
    face_corner: Vec<bool>,
    cache: Mutex<Cache>,
}

impl WeightTable {
    /// `face_corner[k]`: field k is a face-corner field.
    pub fn new(env: Env, exprs: Vec<Expr>, face_corner: Vec<bool>) -> Self {
        let uses_j = exprs.iter().map(|e| e.variables().iter().any(|v| v == "j")).collect();
        WeightTable { env, exprs, uses_j, face_corner, cache: Mutex::new(HashMap::new()) }
    }

    /// The weight of field `k` at valence (or face size) n, index j, and for
    /// a face-corner field at corner count m; with
    /// `vertex`, parameter `vertex.0` set to the per-vertex value
    /// `vertex.1` (Lin–Luo's α at the vertex concerned). Per-vertex values are
    /// floats read from a file: the exact path cannot take them.
    pub fn get_at<W: Weight>(
        &self,
        k: usize,
        n: i64,
        j: i64,
        m: Option<i64>,
        vertex: Option<(&str, f64)>,
    ) -> Result<W, Inexact> {
        // evaluate only in the arithmetic asked for: exact evaluation of an
        // irrational weight fails, and float stencils must not pay for it
        let float = TypeId::of::<W>() == TypeId::of::<f64>();
        if vertex.is_some() && !float {
            return Err(Inexact);
        }
        let arithmetic = match (float, W::CYCLOTOMIC) {
            (true, _) => Arithmetic::Float,
            (false, true) => Arithmetic::Cyclotomic,
            (false, false) => Arithmetic::Rational,
        };
        let j = if self.uses_j[k] { j } else { 0 };
        // m is a variable of face-corner fields only (a face-corner slot always has one)
        let m = if self.face_corner[k] { Some(m.ok_or(Inexact)?) } else { None };
        let id = (k, n, j, m, arithmetic, vertex.map(|v| v.1.to_bits()));
        let cached = self.cache.lock().unwrap_or_else(|e| e.into_inner()).get(&id).cloned();
        let value = match cached {
            Some(v) => v,
            None => {
                let v = self.evaluate(k, n, j, m, arithmetic, vertex);
                let mut cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
                if cache.len() >= CACHE_ENTRIES {
                    cache.clear();
                }
                cache.insert(id, v.clone());
                v
            }
        };
        match value? {
            Evaluated::Number(p) => W::param(&p),
            Evaluated::Field(c) => W::from_cyclotomic(&c),
        }
    }

    fn evaluate(
        &self,
        k: usize,
        n: i64,
        j: i64,
        m: Option<i64>,
        arithmetic: Arithmetic,
        vertex: Option<(&str, f64)>,
    ) -> Result<Evaluated, Inexact> {
        let mut env = with_nj(&self.env, n, j, m);
        if let Some((name, value)) = vertex {
            env.insert(name.to_string(), ParamValue::from_f64(value));
        }
        // a rational weight is taken exactly in floats too: a zero is then a
        // zero (as with the built-ins' exact cosines), not 6e-17, and the
        // stencil's support is the built-in's
        if let Some(q) = self.exprs[k].exact(&env) {
            return Ok(Evaluated::Number(ParamValue { value: q.to_f64(), exact: Some(q), text: String::new() }));
        }
        match arithmetic {
            Arithmetic::Float => {
                let z = self.exprs[k].eval(&env).map_err(|_| Inexact)?;
                if !z.re.is_finite() || z.im.abs() > 1e-12 * z.re.abs().max(1.0) {
                    return Err(Inexact);
                }
                Ok(Evaluated::Number(ParamValue { value: z.re, exact: None, text: String::new() }))
            }
            Arithmetic::Rational => Err(Inexact),
            // a weight is a real number: an exact value with an imaginary
            // part (however small) is no weight
            Arithmetic::Cyclotomic => {
                self.exprs[k].cyclotomic(&env).filter(Cyclotomic::is_real).map(Evaluated::Field).ok_or(Inexact)
            }
        }
    }
}
