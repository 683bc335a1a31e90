//! Reading the `data` of a built-in check (every integer bounded, every
//! exact number parsed, every missing key a claim ERROR naming it) and the
//! shapes several papers' checks share: a lattice node with its planar
//! window, the smallest weight of a non-negativity statement. Used by every
//! paper file; imports none of them.

use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::neighbourhood::Configuration;
use crate::numeric::Rational;
use crate::schemes;
use crate::spectrum::fmt_f;

// ---------------------------------------------------------------- data helpers

pub fn need(data: Option<&toml::Value>) -> Result<&toml::Value, Error> {
    data.ok_or_else(|| Error::Claim("this check needs `data`".to_string()))
}

pub fn field<'a>(data: &'a toml::Value, key: &str) -> Result<&'a toml::Value, Error> {
    data.get(key).ok_or_else(|| Error::Claim(format!("data.{key} is missing")))
}

pub fn text<'a>(data: &'a toml::Value, key: &str) -> Result<&'a str, Error> {
    field(data, key)?.as_str().ok_or_else(|| Error::Claim(format!("data.{key} must be a string")))
}

pub fn int(v: &toml::Value, what: &str) -> Result<i64, Error> {
    v.as_integer().ok_or_else(|| Error::Claim(format!("{what} must be an integer")))
}

/// An integer of the claim data within [lo, hi]: the data drive loops and
/// allocations, so every size is bounded (and never wraps when negative).
pub fn int_in(data: &toml::Value, key: &str, lo: i64, hi: i64) -> Result<i64, Error> {
    let v = int(field(data, key)?, &format!("data.{key}"))?;
    if v < lo || v > hi {
        return Err(Error::Claim(format!("data.{key} = {v} is outside the supported range {lo}..{hi}")));
    }
    Ok(v)
}

/// A window [x0, x1, y0, y1] of at most `max_points` lattice points.
pub fn small_window(data: &toml::Value, max_points: i64) -> Result<Vec<i64>, Error> {
    let w = ints(data, "window")?;
    if w.len() != 4 {
        return Err(Error::Claim("data.window is [x0, x1, y0, y1]".into()));
    }
    if w[0] > w[1] || w[2] > w[3] {
        return Err(Error::Claim(format!("data.window {w:?} is empty (it must have x0 <= x1 and y0 <= y1)")));
    }
    let points = (w[1] as i128 - w[0] as i128 + 1) * (w[3] as i128 - w[2] as i128 + 1);
    if points > max_points as i128 {
        return Err(Error::Claim(format!("data.window {w:?} has {points} points; at most {max_points} are supported")));
    }
    Ok(w)
}

/// Most points of the window of a strip or polynomial check.
pub const MAX_DATA_WINDOW: i64 = 144;

pub fn ints(data: &toml::Value, key: &str) -> Result<Vec<i64>, Error> {
    field(data, key)?
        .as_array()
        .ok_or_else(|| Error::Claim(format!("data.{key} must be a list of integers")))?
        .iter()
        .map(|x| int(x, &format!("data.{key}")))
        .collect()
}

pub fn ints_of(v: &toml::Value, what: &str) -> Result<Vec<i64>, Error> {
    v.as_array()
        .ok_or_else(|| Error::Claim(format!("{what}: a list of integers")))?
        .iter()
        .map(|x| int(x, what))
        .collect()
}

pub fn exact(s: &str) -> Result<Rational, Error> {
    crate::numeric::expr::Expr::parse(s)?
        .exact(&Default::default())
        .ok_or_else(|| Error::Claim(format!("'{s}' is not an exact rational")))
}

/// Exact rationals from a list of strings `data.key`.
pub fn exact_list(data: &toml::Value, key: &str) -> Result<Vec<Rational>, Error> {
    field(data, key)?
        .as_array()
        .ok_or_else(|| Error::Claim(format!("data.{key}: a list of exact numbers as strings")))?
        .iter()
        .map(|x| x.as_str().ok_or_else(|| Error::Claim(format!("data.{key}: strings"))).and_then(exact))
        .collect()
}

/// Scheme parameters from a table of strings.
pub fn params(data: &toml::Value, key: &str) -> Result<Vec<(String, String)>, Error> {
    match data.get(key) {
        None => Ok(Vec::new()),
        Some(t) => t
            .as_table()
            .ok_or_else(|| Error::Claim(format!("data.{key} must be a table")))?
            .iter()
            .map(|(k, v)| {
                v.as_str()
                    .map(|s| (k.clone(), s.to_string()))
                    .ok_or_else(|| Error::Claim(format!("data.{key}.{k}: a string")))
            })
            .collect(),
    }
}

/// The configuration with face sequence `faces` (its length is the valence;
/// schemes without face sequences take the regular one of that valence).
pub fn configuration(scheme: &dyn schemes::Scheme, faces: &str) -> Result<Configuration, Error> {
    if scheme.face_sequences() {
        Configuration::with_faces(scheme, faces.len(), faces)
    } else {
        Configuration::regular(scheme, faces.len())
    }
}

/// The smallest of a stream of weights and where it occurs (the place is
/// described only when it becomes the new minimum). HOLDS when no weight is
/// negative: the shared shape of the non-negativity (convex hull) checks.
pub struct SmallestWeight {
    pub value: f64,
    pub at: String,
}

impl Default for SmallestWeight {
    fn default() -> Self {
        SmallestWeight::new()
    }
}

impl SmallestWeight {
    pub fn new() -> Self {
        SmallestWeight { value: f64::INFINITY, at: String::new() }
    }
    pub fn offer(&mut self, w: f64, at: impl FnOnce() -> String) {
        if w < self.value {
            self.value = w;
            self.at = at();
        }
    }
    /// (verdict, stated, computed, detail) with the computed value described as `what`.
    pub fn outcome(self, statement: &str, what: &str, detail: String) -> Result<Finding, Error> {
        Ok(Finding::new(
            self.value >= -1e-12,
            statement.into(),
            format!("{what} {} ({})", fmt_f(self.value), self.at),
            detail,
        ))
    }
}

/// The scheme, the configuration of the node `faces` and the planar
/// positions of its `spokes`: the setting of the lattice-window checks.
pub type LatticeNode = (Box<dyn schemes::Scheme>, Configuration, Vec<[i64; 2]>);

pub fn lattice_node(data: &toml::Value) -> Result<LatticeNode, Error> {
    let scheme = schemes::resolve(text(data, "scheme")?, &params(data, "params")?)?;
    let config = configuration(scheme.as_ref(), text(data, "faces")?)?;
    let spokes = field(data, "spokes")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.spokes: a list of [x, y]".into()))?
        .iter()
        .map(|p| {
            let v = p.as_array().filter(|v| v.len() == 2).ok_or_else(|| Error::Claim("each spoke is [x, y]".into()))?;
            Ok([int(&v[0], "a spoke")?, int(&v[1], "a spoke")?])
        })
        .collect::<Result<_, Error>>()?;
    Ok((scheme, config, spokes))
}

/// The evidence line of the window checks: exact, the configuration and the window.
pub fn window_evidence(data: &toml::Value, w: &[i64], points: usize) -> Result<String, Error> {
    Ok(format!(
        "exact, {} on the window [{}, {}] × [{}, {}] ({points} points)",
        text(data, "faces")?,
        w[0],
        w[1],
        w[2],
        w[3]
    ))
}

/// The INCONCLUSIVE of a built-in check whose computation ran and did not
/// decide: the statement, what was computed, and why that does not decide.
pub fn not_decided(stated: &str, computed: &str, detail: &str) -> Error {
    Error::Undecided(format!("{stated}: not decided: {computed} ({detail})"))
}
