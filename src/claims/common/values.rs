//! The stated values of a claim: its expressions evaluated in the
//! environment of a configuration (the valence n, alias k, the block m, the
//! face counts, the subject's parameters and variables), and how computed
//! and stated values are compared and shown. Shared by every check plug-in;
//! imports none of them.

use num_complex::Complex64;

use crate::claims::subject::Subject;
use crate::error::Error;
use crate::numeric::expr::{Env, Expr};
use crate::numeric::ParamValue;
use crate::spectrum::fmt_f;

/// Relative tolerance for comparing computed with stated values.
pub const TOL: f64 = 1e-9;

/// The subject's parameters evaluated at valence n, as `name=value` overrides.
pub fn subject_params(s: &Subject, n: usize) -> Result<Vec<(String, String)>, Error> {
    let base = crate::numeric::expr::env_int(&[("n", n as i64), ("k", n as i64)]);
    let mut params: Vec<(String, String)> = Vec::new();
    for (k, v) in &s.params {
        let e = Expr::parse(v).map_err(|e| Error::Claim(format!("parameter {k} = '{v}': {e}")))?;
        let text = match e.exact(&base) {
            Some(q) => q.to_string(),
            None => format!("{:e}", real(e.eval(&base)?, v)?),
        };
        params.push((k.clone(), text));
    }
    Ok(params)
}

pub fn env_for(s: &Subject, n: usize) -> Result<Env, Error> {
    env_with(s, n, None)
}

/// The environment of valence n, with the Fourier block index m when given.
pub fn env_with(s: &Subject, n: usize, m: Option<usize>) -> Result<Env, Error> {
    let mut env = crate::numeric::expr::env_int(&[("n", n as i64), ("k", n as i64)]);
    if let Some(m) = m {
        env.insert("m".into(), ParamValue::from_ratio(m as i64, 1));
    }
    if let Some(f) = s.faces_for(n) {
        // numbers of quads and triangles around the centre
        let quads = f.chars().filter(|&c| c == 'Q').count() as i64;
        env.insert("quads".into(), ParamValue::from_ratio(quads, 1));
        env.insert("tris".into(), ParamValue::from_ratio(n as i64 - quads, 1));
    }
    let defs: Vec<(&String, &String)> = s.params.iter().chain(s.vars.iter()).collect();
    if let Some((name, _)) = defs.iter().find(|(k, _)| env.contains_key(k.as_str())) {
        return Err(Error::Claim(format!(
            "'{name}' is given by the check (the valence n or k, the block m, quads, tris) and cannot be redefined in params or vars"
        )));
    }
    define(env, defs)
}

/// `env` with the definitions `defs` (expressions in the names already in
/// `env` and in each other) added, evaluated in dependency order: exactly
/// where rational, else in floating point.
pub fn define(mut env: Env, defs: Vec<(&String, &String)>) -> Result<Env, Error> {
    // definitions may refer to each other: evaluate in dependency order
    let mut pending = defs;
    while !pending.is_empty() {
        let before = pending.len();
        let mut later = Vec::new();
        for (k, v) in pending {
            let e = Expr::parse(v).map_err(|e| Error::Claim(format!("'{v}': {e}")))?;
            if e.variables().iter().any(|x| !env.contains_key(x)) {
                later.push((k, v));
                continue;
            }
            if real_variables(&e, &env).is_err() {
                // defined from a non-real variable: marked in turn
                let text = format!("'{v}' (from a non-real variable)");
                env.insert(k.clone(), ParamValue { value: f64::NAN, text, exact: None });
                continue;
            }
            let value = match e.exact(&env) {
                Some(q) => {
                    ParamValue { value: crate::numeric::Weight::to_f64(&q), text: q.to_string(), exact: Some(q) }
                }
                None => {
                    let z = finite(e.eval(&env)?, v)?;
                    match real(z, v) {
                        Ok(x) => ParamValue::from_f64(x),
                        // the environment holds real numbers: a non-real
                        // variable is marked (NaN) and is an error where it
                        // is used ([`real_variables`]), never its real part
                        Err(_) => ParamValue { value: f64::NAN, text: format!("'{v}' = {}", show(z)), exact: None },
                    }
                }
            };
            env.insert(k.clone(), value);
        }
        if later.len() == before {
            let names: Vec<&str> = later.iter().map(|(k, _)| k.as_str()).collect();
            return Err(Error::Claim(format!("variables {} refer to unknown or circular names", names.join(", "))));
        }
        pending = later;
    }
    Ok(env)
}

/// The value of a stated expression; a value that is not a finite number
/// (0·10^400, an overflow) is a malformed value (the claim is an ERROR).
pub fn eval(text: &str, env: &Env) -> Result<Complex64, Error> {
    let e = Expr::parse(text).map_err(|e| Error::Claim(format!("'{text}': {e}")))?;
    real_variables(&e, env)?;
    let z = e.eval(env).map_err(|e| Error::Claim(format!("'{text}': {e}")))?;
    finite(z, text)
}

/// An error when `e` uses a variable whose value is not real: variables
/// (`vars`, `params`) are real numbers; a complex quantity is written into
/// the expression itself (its imaginary part was once dropped silently).
pub fn real_variables(e: &Expr, env: &Env) -> Result<(), Error> {
    match e.variables().iter().find_map(|v| env.get(v).filter(|p| p.value.is_nan())) {
        Some(p) => Err(Error::Claim(format!(
            "variable {} is not a real number: variables must be real (write a complex quantity into the expression \
             itself)",
            p.text
        ))),
        None => Ok(()),
    }
}

/// [`eval`] of a quantity that must be real (a weight, a count, a size, a
/// block index): a non-real value is a malformed claim, never its real part.
pub fn eval_real(text: &str, env: &Env) -> Result<f64, Error> {
    real(eval(text, env)?, text)
}

/// The real number `z`, or an error naming `text` when `z` is not real
/// (imaginary part beyond rounding, relative 1e-12).
pub fn real(z: Complex64, text: &str) -> Result<f64, Error> {
    if z.im.abs() > 1e-12 * z.norm().max(1.0) {
        return Err(Error::Claim(format!("'{text}' is {}, not a real number: a real value is required here", show(z))));
    }
    Ok(z.re)
}

pub fn finite(z: Complex64, text: &str) -> Result<Complex64, Error> {
    if z.re.is_finite() && z.im.is_finite() {
        Ok(z)
    } else {
        Err(Error::Claim(format!("'{text}' is not a finite number ({}): it cannot decide the claim", show(z))))
    }
}

pub fn show(z: Complex64) -> String {
    if z.im.abs() <= 1e-12 * z.norm().max(1.0) {
        let r = crate::numeric::recognise::recognise(z.re);
        match r {
            Some(r) if r.len() < 8 && r != fmt_f(z.re) => format!("{} ({r})", fmt_f(z.re)),
            _ => fmt_f(z.re),
        }
    } else {
        format!("{}{}{}i", fmt_f(z.re), if z.im < 0.0 { "-" } else { "+" }, fmt_f(z.im.abs()))
    }
}

pub fn show_list(v: &[Complex64]) -> String {
    const SHOWN: usize = 12;
    let mut s: Vec<String> = v.iter().take(SHOWN).map(|z| show(*z)).collect();
    if v.len() > SHOWN {
        s.push(format!("… ({} in all)", v.len()));
    }
    format!("[{}]", s.join(", "))
}

pub fn close(a: Complex64, b: Complex64) -> bool {
    (a - b).norm() <= TOL * a.norm().max(b.norm()).max(1.0)
}

/// Multiset difference: stated values not matched, computed values not matched.
pub fn unmatched(stated: &[Complex64], computed: &[Complex64]) -> (Vec<Complex64>, Vec<Complex64>) {
    let mut left: Vec<Complex64> = computed.to_vec();
    let mut missing = Vec::new();
    for &z in stated {
        match left.iter().position(|&w| close(z, w)) {
            Some(k) => {
                left.remove(k);
            }
            None => missing.push(z),
        }
    }
    (missing, left)
}

/// Most stated values of one claim, counting repeats.
pub const MAX_STATED_VALUES: usize = 100_000;

/// Stated values; an entry "EXPR ; COUNT" stands for COUNT copies of EXPR.
pub fn stated_values(values: &[String], env: &Env) -> Result<Vec<Complex64>, Error> {
    let mut out = Vec::new();
    for v in values {
        let (e, count) = match v.split_once(';') {
            Some((e, c)) => {
                let k = eval_real(c, env)?.round();
                if !(0.0..=100_000.0).contains(&k) {
                    return Err(Error::Claim(format!("repeat count of '{v}' is {k}")));
                }
                (e, k as usize)
            }
            None => (v.as_str(), 1),
        };
        if out.len() + count > MAX_STATED_VALUES {
            return Err(Error::Claim(format!("more than {MAX_STATED_VALUES} stated values (counting repeats)")));
        }
        let z = eval(e, env)?;
        out.extend(std::iter::repeat_n(z, count));
    }
    Ok(out)
}
