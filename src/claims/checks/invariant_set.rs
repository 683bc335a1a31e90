//! The `invariant-set` check: a statement that a vertex set of some size
//! "suffices" (or "is invariant") for the analysis at an extraordinary point,
//! read as the authors mean it: the set need not be the smallest one, it has
//! to be invariant and hold what the analysis needs.
//!
//! The set is built from the tool's vertex labels: every vertex of ring ≤
//! `rings` (rings as `neighbourhood::labels::rings` defines them: ring k + 1
//! holds the corners of faces touching ring k, a face control vertex takes the
//! outermost ring of its face), optionally only those with i + j ≤
//! `lattice_sum` in their sector's chart and of the listed kinds. Then, on a
//! patch two rings larger than the set (more when a rule needs it):
//!
//! 1. its size against the stated one (a set of another size is not the
//!    statement's set: the claim cannot be decided, INCONCLUSIVE);
//! 2. invariance: the row of S of every vertex of the set (the stencil, over
//!    one analysis step, of the refined vertex that plays its role) has
//!    weight only on the set: exact rationals where every weight is rational,
//!    else floating point with |w| ≤ 1e-12 read as 0;
//! 3. containment of the subject's `neighbourhood` (default `analysis`: the
//!    invariant set holding every control point of the limit over the first
//!    ring's descendants, which the characteristic map and the eigenvectors
//!    the analysis uses need; `minimal` for statements about eigenvalues only);
//! 4. the spectrum of S on the set against S on that neighbourhood: S on an
//!    invariant superset is block triangular with S on the neighbourhood as a
//!    block, so the neighbourhood's eigenvalues recur and the set adds others;
//!    the leading eigenvalues agree when every added eigenvalue is below λ1 in
//!    modulus (floating point, dense eigenvalues, relative 1e-7). The added
//!    non-zero eigenvalues are listed.

use num_complex::Complex64;
use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::{kind_of, subject_config, Cache};
use crate::claims::common::values::{env_for, eval_real, show};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::{Error, Result};
use crate::matrix::local::{step_rows_of, AssembleError};
use crate::neighbourhood::labels::kind_name;
use crate::neighbourhood::{discover_with_rings, Discovered, VertexKind};
use crate::numeric::{Rational, Weight};
use crate::spectrum::{eigen, eigenvalue_order, Spectrum};

/// A stated vertex set "suffices" (or "is invariant"): the set built from
/// the vertex labels (every vertex of ring ≤ `rings`, optionally only
/// those with i + j ≤ `lattice_sum` in their sector's chart and of the
/// listed `kinds`) must have the stated size `value`, be invariant under
/// one analysis step, contain the `neighbourhood` (analysis by default:
/// what the analysis needs) and have the same leading eigenvalues as S
/// on it (every extra eigenvalue below λ1 in modulus).
#[derive(Clone, Debug, Deserialize)]
pub struct InvariantSet {
    #[serde(flatten)]
    pub subject: Subject,
    pub rings: String,
    #[serde(default)]
    pub lattice_sum: Option<String>,
    #[serde(default)]
    pub kinds: Option<Vec<String>>,
    pub value: String,
}

impl CheckKind for InvariantSet {
    const KEYS: &'static [&'static str] = &["rings", "lattice_sum", "kinds", "value"];

    fn validate(&self) -> Result<()> {
        if self.kinds.as_ref().is_some_and(|k| k.is_empty()) {
            return vacuous("kinds");
        }
        Ok(())
    }

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding> {
        let InvariantSet { subject, rings, lattice_sum, kinds, value } = self;
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            one(subject, n, rings, lattice_sum.as_deref(), kinds.as_deref(), value, &spec)
        })
    }
}

/// Eigenvalues closer than this (relative) are the same.
const SAME: f64 = 1e-7;
/// Below this modulus an eigenvalue counts as zero (nilpotent parts split
/// in floating point by about eps^(1/k)).
const ZERO: f64 = 1e-6;

/// One valence: (holds, stated, computed).
fn one(
    subject: &Subject,
    n: usize,
    rings: &str,
    lattice_sum: Option<&str>,
    kinds: Option<&[String]>,
    value: &str,
    spec: &Spectrum,
) -> Result<(bool, String, String)> {
    let env = env_for(subject, n)?;
    let whole = |text: &str| -> Result<i64> {
        let x = eval_real(text, &env)?;
        if (x - x.round()).abs() > 1e-9 || !(0.0..=1e6).contains(&x) {
            return Err(Error::Claim(format!("'{text}' is {x} at n = {n}, not a count")));
        }
        Ok(x.round() as i64)
    };
    let r = whole(rings)? as usize;
    let cut = lattice_sum.map(whole).transpose()?;
    let stated = whole(value)? as usize;
    if let Some(ks) = kinds {
        let known = ["centre", "corner", "edge", "face", "vertex", "fcv"];
        if let Some(k) = ks.iter().find(|k| !known.contains(&k.as_str())) {
            return Err(Error::Claim(format!("unknown vertex kind '{k}' (one of {})", known.join(", "))));
        }
    }
    let (scheme, config) = subject_config(subject, n)?;
    let kind = kind_of(subject)?;
    let mut last = Error::NotDetermined(String::new());
    for extra in 2..=4 {
        let d = match discover_with_rings(scheme.as_ref(), &config, r + extra) {
            Ok(d) => d,
            Err(e) => {
                last = e;
                continue;
            }
        };
        let set = stated_set(&d, r, cut, kinds);
        let what = describe(r, cut, kinds);
        if set.len() != stated {
            // the statement's set is not identified: nothing about it is decided
            return Err(Error::Undecided(format!(
                "the set {what} has {} vertices at n = {n}, the statement {stated}: it is not the statement's set",
                set.len()
            )));
        }
        // exact rows where every weight is rational, else floating point
        let (rows, evidence) = match step_rows_of::<Rational>(scheme.as_ref(), &d, &set) {
            Ok(rows) => (to_f64_exact(rows), "exact rows"),
            Err(AssembleError::Inexact) => match step_rows_of::<f64>(scheme.as_ref(), &d, &set) {
                Ok(rows) => (rows, "floating-point rows, |w| ≤ 1e-12 read as 0"),
                Err(e) => {
                    last = e.into();
                    continue;
                }
            },
            Err(e) => {
                last = e.into();
                continue;
            }
        };
        return judge(&d, spec, kind, &set, &rows, &what, evidence);
    }
    Err(Error::NotDetermined(format!(
        "the stated set could not be evaluated on patches of up to {} rings: {last}",
        r + 4
    )))
}

/// Rows with exact weights, to f64 with exact zeros dropped.
fn to_f64_exact(rows: Vec<Vec<(usize, Rational)>>) -> Vec<Vec<(usize, f64)>> {
    rows.into_iter()
        .map(|row| row.into_iter().filter(|(_, w)| !w.is_zero()).map(|(u, w)| (u, Weight::to_f64(&w))).collect())
        .collect()
}

fn describe(r: usize, cut: Option<i64>, kinds: Option<&[String]>) -> String {
    let mut s = format!("rings 0..{r}");
    if let Some(c) = cut {
        s += &format!(" with i + j ≤ {c}");
    }
    if let Some(ks) = kinds {
        s += &format!(" of kinds {}", ks.join(", "));
    }
    s
}

/// The patch vertices of the stated set, in canonical order.
fn stated_set(d: &Discovered, r: usize, cut: Option<i64>, kinds: Option<&[String]>) -> Vec<usize> {
    let mut set: Vec<usize> = (0..d.labels.len())
        .filter(|&v| {
            let l = &d.labels[v];
            l.ring <= r
                && (l.kind == VertexKind::Centre || cut.is_none_or(|c| l.i + l.j <= c))
                && kinds.is_none_or(|ks| ks.iter().any(|k| k == kind_name(l.kind)))
        })
        .collect();
    crate::neighbourhood::labels::canonical_order(&d.labels, &mut set);
    set
}

fn judge(
    d: &Discovered,
    spec: &Spectrum,
    kind: crate::neighbourhood::NeighbourhoodKind,
    set: &[usize],
    rows: &[Vec<(usize, f64)>],
    what: &str,
    evidence: &str,
) -> Result<(bool, String, String)> {
    let position: std::collections::HashMap<usize, usize> = set.iter().enumerate().map(|(k, &v)| (v, k)).collect();
    let name = |v: usize| d.labels[v].name.clone();
    let mut outside: Vec<usize> =
        rows.iter().flatten().filter(|(u, w)| w.abs() > 1e-12 && !position.contains_key(u)).map(|(u, _)| *u).collect();
    outside.sort_unstable();
    outside.dedup();
    let needed = d.set(kind);
    let missing: Vec<usize> = needed.iter().copied().filter(|v| !position.contains_key(v)).collect();
    let kind_text = format!("{kind:?}").to_lowercase();
    let list = |vs: &[usize]| {
        let mut s: Vec<String> = vs.iter().take(6).map(|&v| name(v)).collect();
        if vs.len() > 6 {
            s.push(format!("… ({} in all)", vs.len()));
        }
        s.join(", ")
    };
    let invariant = outside.is_empty();
    let contains = missing.is_empty();
    let mut parts = vec![format!("{} vertices ({what})", set.len())];
    parts.push(if invariant {
        format!("invariant ({evidence})")
    } else {
        format!("not invariant ({evidence}): rows depend on {}", list(&outside))
    });
    parts.push(if contains {
        format!("contains the {kind_text} neighbourhood ({} vertices)", needed.len())
    } else {
        format!("lacks {} of the {kind_text} neighbourhood: {}", missing.len(), list(&missing))
    });
    let mut leading = false;
    if invariant {
        match spectrum_on(set.len(), rows, &position) {
            Ok(mut on_set) => {
                let base: Vec<Complex64> = spec
                    .eigenvalues
                    .iter()
                    .flat_map(|e| std::iter::repeat_n(Complex64::new(e.re, e.im), e.algebraic_multiplicity))
                    .filter(|z| z.norm() > ZERO)
                    .collect();
                on_set.retain(|z| z.norm() > ZERO);
                // the neighbourhood's non-zero eigenvalues, matched in the set's
                let mut lost = Vec::new();
                for z in &base {
                    match on_set.iter().position(|w| (z - w).norm() <= SAME * z.norm().max(1.0)) {
                        Some(k) => {
                            on_set.remove(k);
                        }
                        None => lost.push(*z),
                    }
                }
                on_set.sort_by(|a, b| eigenvalue_order(*a, *b));
                let l1 = spec.eigenvalues.get(1).map(|e| e.modulus).unwrap_or(0.0);
                // the leading eigenvalues: those of modulus ≥ |λ1| on either side
                let lead = |z: &&Complex64| z.norm() >= l1 - SAME;
                leading = !on_set.iter().any(|z| lead(&z)) && !lost.iter().any(|z| lead(&z));
                let shown = |v: &[Complex64]| {
                    let mut s: Vec<String> = v.iter().take(8).map(|z| show(*z)).collect();
                    if v.len() > 8 {
                        s.push(format!("… ({} in all)", v.len()));
                    }
                    format!("[{}]", s.join(", "))
                };
                parts.push(if on_set.is_empty() && lost.is_empty() {
                    "the same non-zero spectrum (floating point, relative 1e-7)".to_string()
                } else if leading && lost.is_empty() {
                    format!(
                        "the same leading eigenvalues; it adds the non-zero eigenvalues {} below λ1 = {} (floating point, relative 1e-7)",
                        shown(&on_set),
                        crate::spectrum::fmt_f(l1)
                    )
                } else if leading {
                    format!(
                        "the same leading eigenvalues; added {}, not found {}, all below λ1 = {} (floating point, relative 1e-7)",
                        shown(&on_set),
                        shown(&lost),
                        crate::spectrum::fmt_f(l1)
                    )
                } else {
                    format!(
                        "different leading eigenvalues: added {}, not found {} (λ1 = {}, floating point)",
                        shown(&on_set),
                        shown(&lost),
                        crate::spectrum::fmt_f(l1)
                    )
                });
            }
            // an invariant set containing the neighbourhood whose spectrum
            // is not computed leaves the claim undecided, never refuted
            Err(e) if contains => {
                parts.push(format!("spectrum not computed: {e}"));
                return Err(Error::Undecided(parts.join("; ")));
            }
            Err(e) => parts.push(format!("spectrum not computed: {e}")),
        }
    } else {
        parts.push("S on a set that is not invariant is not defined".into());
    }
    let ok = invariant && contains && leading;
    Ok((
        ok,
        format!(
            "{} vertices: invariant, containing the {kind_text} neighbourhood, same leading eigenvalues",
            set.len()
        ),
        parts.join("; "),
    ))
}

/// Eigenvalues (repeated by multiplicity) of S on an invariant set.
fn spectrum_on(
    size: usize,
    rows: &[Vec<(usize, f64)>],
    position: &std::collections::HashMap<usize, usize>,
) -> Result<Vec<Complex64>> {
    if size > crate::spectrum::MAX_FULL_SIZE {
        return Err(Error::Input(format!(
            "{size} vertices are more than the {} analysed whole",
            crate::spectrum::MAX_FULL_SIZE
        )));
    }
    let mut m = faer::Mat::<Complex64>::zeros(size, size);
    for (i, row) in rows.iter().enumerate() {
        for &(u, w) in row {
            if let Some(&j) = position.get(&u) {
                m[(i, j)] += Complex64::new(w, 0.0);
            }
        }
    }
    Ok(eigen::block_eigen(&m)?.into_iter().flat_map(|e| std::iter::repeat_n(e.value, e.algebraic)).collect())
}
