//! Weight evaluation: a field's expression at (n, j) (and m), read once
//! (`Expr::reading`: exactly in the rationals, else in a cyclotomic field,
//! else in floats) and handed to every weight type from that one reading: f64
//! gets the exact value rounded, the rationals rational weights, the
//! cyclotomic and interval types the exact element. Cached because
//! refinement asks for the same weight at every vertex and a Fourier-sum
//! weight costs n terms.

use std::any::TypeId;
use std::collections::HashMap;
use std::sync::Mutex;

use crate::error::Error;
use crate::numeric::expr::{Env, Expr};
use crate::numeric::{Cyclotomic, Inexact, ParamValue, Reading, TPoly, Weight};

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

/// A scheme file's weight as read (`Expr::reading`): exactly where it can
/// be, the float value that exact value rounded.
pub(super) fn reading(expr: &Expr, params: &Env, n: i64, j: i64, m: Option<i64>) -> Result<Reading, Error> {
    expr.reading(&with_nj(params, n, j, m))
}

/// A weight in floating point (the exact value rounded wherever there is
/// one), with a reason when it is not a finite real.
pub(super) fn eval_f64(expr: &Expr, params: &Env, n: i64, j: i64, m: Option<i64>) -> Result<f64, Error> {
    reading(expr, params, n, j, m)?.real()
}

/// A weight as evaluated once for every weight type: an exact value with its
/// rounding, or (no exact reading) a float.
#[derive(Clone, Debug)]
enum Evaluated {
    Rational(ParamValue),
    /// exact in a cyclotomic field, real and not rational; its rounding
    Field(Cyclotomic, f64),
    Float(f64),
}

/// (field, n, j, m, per-vertex parameter value's bits) -> the weight.
type Cache = HashMap<(usize, i64, i64, Option<i64>, Option<u64>), Result<Evaluated, Inexact>>;

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

    /// Field k for the valence probe (`probe::record`): whether its
    /// expression has any variable (n, j, m, a parameter, whose value may
    /// come from n; none: one constant everywhere), the expression and the
    /// parameters' values.
    pub fn field(&self, k: usize) -> (bool, Expr, Env) {
        (!self.exprs[k].variables().is_empty(), self.exprs[k].clone(), self.env.clone())
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
        let float = TypeId::of::<W>() == TypeId::of::<f64>();
        if vertex.is_some() && !float {
            return Err(Inexact);
        }
        let j = if self.uses_j[k] { j } else { 0 };
        // m is a variable of face-corner fields only (a face-corner slot always has one)
        let m = if self.face_corner[k] { Some(m.ok_or(Inexact)?) } else { None };
        // the exact sweep's polynomials in the swept parameter: the
        // expression itself in that arithmetic (a number read at the
        // parameter's marker value would be a constant), never cached
        if TypeId::of::<W>() == TypeId::of::<TPoly>() {
            let value = self.exprs[k].evaluate::<TPoly>(&with_nj(&self.env, n, j, m)).map_err(|_| Inexact)?;
            let any: Box<dyn std::any::Any> = Box::new(value);
            return any.downcast::<W>().map(|w| *w).map_err(|_| Inexact);
        }
        // one reading serves every weight type: the float stencils see the
        // exact value rounded, so they cannot describe another scheme than
        // the exact and interval ones
        let id = (k, n, j, m, vertex.map(|v| v.1.to_bits()));
        let cached = self.cache.lock().unwrap_or_else(|e| e.into_inner()).get(&id).cloned();
        let value = match cached {
            Some(v) => v,
            None => {
                let v = self.evaluate(k, n, j, m, vertex);
                let mut cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
                if cache.len() >= CACHE_ENTRIES {
                    cache.clear();
                }
                cache.insert(id, v.clone());
                v
            }
        };
        match value? {
            // a rational weight is taken exactly in floats too: a zero is
            // then a zero (as with the built-ins' exact cosines), not 6e-17,
            // and the stencil's support is the built-in's
            Evaluated::Rational(p) => W::param(&p),
            Evaluated::Field(_, x) if float => W::param(&ParamValue::from_f64(x)),
            Evaluated::Field(c, _) => W::from_cyclotomic(&c),
            Evaluated::Float(x) => W::param(&ParamValue { value: x, exact: None, text: String::new() }),
        }
    }

    fn evaluate(
        &self,
        k: usize,
        n: i64,
        j: i64,
        m: Option<i64>,
        vertex: Option<(&str, f64)>,
    ) -> Result<Evaluated, Inexact> {
        let mut env = with_nj(&self.env, n, j, m);
        if let Some((name, value)) = vertex {
            env.insert(name.to_string(), ParamValue::from_f64(value));
        }
        let reading = self.exprs[k].reading(&env).map_err(|_| Inexact)?;
        // a weight is a real number: an exact value with an imaginary part
        // (however small) is no weight
        let x = reading.real().map_err(|_| Inexact)?;
        Ok(match reading {
            Reading::Rational(q) => Evaluated::Rational(ParamValue { value: x, exact: Some(q), text: String::new() }),
            Reading::Cyclotomic(c, _) => Evaluated::Field(c, x),
            Reading::Float(_) => Evaluated::Float(x),
        })
    }
}
