//! `lattice-matrix`: a printed matrix of a regular-lattice scheme against
//! the matrix assembled exactly from its rules on a window.

use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::spectra::Cache;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::lattice;
use crate::numeric::expr::{Env, Expr};
use crate::schemes::registry;

/// A printed matrix of a regular-lattice scheme against the matrix
/// assembled from its rules on the window [i0, i1] × [j0, j1] (i fastest),
/// entry by entry: `scale` times the printed integers.
#[derive(Clone, Debug, Deserialize)]
pub struct LatticeMatrix {
    pub scheme: String,
    pub window: [i64; 4],
    pub scale: String,
    pub rows: Vec<String>,
}

impl CheckKind for LatticeMatrix {
    const KEYS: &'static [&'static str] = &["scheme", "window", "scale", "rows"];
    const TAKES_SUBJECT: bool = false;

    fn validate(&self) -> Result<(), Error> {
        if self.rows.is_empty() {
            return vacuous("rows");
        }
        Ok(())
    }

    fn evaluate(&self, _cache: &mut Cache) -> Result<Finding, Error> {
        let LatticeMatrix { scheme, window, scale, rows } = self;
        let s = registry::lattice(scheme, &[])?;
        let [i0, i1, j0, j1] = *window;
        check_window(*window)?;
        if rows.is_empty() {
            return Err(Error::Claim("no printed rows: nothing to compare".into()));
        }
        let w = lattice::Window::rect(i0, i1, j0, j1);
        let assembled = lattice::local_matrix::<crate::numeric::Rational>(s.as_ref(), &w)?;
        let scale = Expr::parse(scale)?
            .exact(&Env::new())
            .ok_or_else(|| Error::Claim("the scale must be an exact rational".into()))?;
        let printed: Vec<Vec<crate::numeric::Rational>> = rows
            .iter()
            .map(|r| {
                r.split_whitespace()
                    .map(|x| Expr::parse(x).ok().and_then(|e| e.exact(&Env::new())).map(|q| q * scale.clone()))
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| Error::Claim(format!("row '{r}' is not a list of numbers")))
            })
            .collect::<Result<_, _>>()?;
        if printed.len() != assembled.len() || printed.iter().any(|r| r.len() != assembled.len()) {
            return Ok(Finding::new(
                false,
                format!("{} printed rows", printed.len()),
                format!("{}×{} assembled", assembled.len(), assembled.len()),
                "the printed matrix has the wrong shape".into(),
            ));
        }
        let mut diffs = Vec::new();
        for (i, (p, a)) in printed.iter().zip(&assembled).enumerate() {
            for (j, (x, y)) in p.iter().zip(a).enumerate() {
                if x != y {
                    diffs.push(format!("({},{}): printed {x}, rules give {y}", i + 1, j + 1));
                }
            }
        }
        let n = assembled.len();
        Ok(Finding::new(
            diffs.is_empty(),
            format!("{n}×{n} printed matrix"),
            if diffs.is_empty() { "every entry as printed".into() } else { format!("{} entries differ", diffs.len()) },
            if diffs.is_empty() {
                "entry by entry, exact".into()
            } else {
                diffs.iter().take(12).cloned().collect::<Vec<_>>().join("; ")
            },
        ))
    }
}

/// Most points of a printed lattice window (i fastest): matrices of that size
/// are assembled exactly, so the window is bounded like every other input.
pub const MAX_WINDOW_POINTS: i64 = 1024;

/// A window [i0, i1] × [j0, j1]: non-empty and at most [`MAX_WINDOW_POINTS`].
pub fn check_window([i0, i1, j0, j1]: [i64; 4]) -> Result<(), Error> {
    if i0 > i1 || j0 > j1 {
        return Err(Error::Claim(format!(
            "the window [{i0}, {i1}, {j0}, {j1}] is empty (it must have i0 <= i1 and j0 <= j1)"
        )));
    }
    let points = (i1 as i128 - i0 as i128 + 1) * (j1 as i128 - j0 as i128 + 1);
    if points > MAX_WINDOW_POINTS as i128 {
        return Err(Error::Claim(format!(
            "the window [{i0}, {i1}, {j0}, {j1}] has {points} points; at most {MAX_WINDOW_POINTS} are supported"
        )));
    }
    Ok(())
}
