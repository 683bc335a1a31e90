//! `eigenvalues`: the eigenvalues of S, or of Fourier block `block`, against
//! the stated values.

use num_complex::Complex64;
use serde::Deserialize;

use crate::claims::check_kind::{vacuous, CheckKind};
use crate::claims::common::configurations::over_valences;
use crate::claims::common::spectra::{expanded, Cache};
use crate::claims::common::values::{close, env_for, env_with, eval_real, show_list, stated_values, unmatched};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::spectrum::{eigen, eigenvalue_order, Spectrum, Synthesis};

/// Eigenvalues (with repetition = multiplicity; `"EXPR ; COUNT"` repeats
/// EXPR COUNT times) of S or of Fourier block `block`, compared as `all`
/// (the whole multiset), `leading` (the largest ones in the display order),
/// `contains` (each stated value at least as often as stated) or `count`
/// (each stated value exactly as often as stated, others ignored).
#[derive(Clone, Debug, Deserialize)]
pub struct Eigenvalues {
    #[serde(flatten)]
    pub subject: Subject,
    pub values: Vec<String>,
    #[serde(default = "default_compare")]
    pub compare: String,
    #[serde(default)]
    pub block: Option<String>,
    /// compare moduli |λ| instead of values (the other reading of a
    /// statement such as "λ3 = λ4" about eigenvalues ordered by modulus)
    #[serde(default)]
    pub moduli: bool,
}

fn default_compare() -> String {
    "all".to_string()
}

impl CheckKind for Eigenvalues {
    const KEYS: &'static [&'static str] = &["values", "compare", "block", "moduli"];

    fn validate(&self) -> Result<(), Error> {
        if self.values.is_empty() {
            return vacuous("values");
        }
        Ok(())
    }

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let Eigenvalues { subject, values, compare, block, moduli } = self;
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            let blocks: Vec<Option<usize>> = match block.as_deref() {
                None => vec![None],
                // every non-trivial Fourier block, with m in the environment
                Some("m") => (1..n).map(Some).collect(),
                Some(b) => {
                    let m = eval_real(b, &env_for(subject, n)?)?.round();
                    if !(0.0..n as f64).contains(&m) {
                        return Err(Error::Claim(format!("block '{b}' is {m} at n = {n}")));
                    }
                    vec![Some(m as usize)]
                }
            };
            let mut first = None;
            for b in blocks {
                let env = env_with(subject, n, b)?;
                let mut stated = stated_values(values, &env)?;
                stated.sort_by(|a, b| eigenvalue_order(*a, *b));
                let mut computed = match b {
                    Some(m) => block_values(&spec, m)?,
                    None => expanded(&spec),
                };
                computed.sort_by(|a, b| eigenvalue_order(*a, *b));
                if *moduli {
                    // the other reading: only |λ| is compared
                    for z in stated.iter_mut().chain(computed.iter_mut()) {
                        *z = Complex64::new(z.norm(), 0.0);
                    }
                    stated.sort_by(|a, b| eigenvalue_order(*a, *b));
                    computed.sort_by(|a, b| eigenvalue_order(*a, *b));
                }
                let shown: Vec<Complex64> = match compare.as_str() {
                    "leading" => computed.iter().take(stated.len()).copied().collect(),
                    "all" | "contains" => computed.clone(),
                    // only the computed copies of the stated values count
                    "count" => computed.iter().copied().filter(|w| stated.iter().any(|z| close(*z, *w))).collect(),
                    other => {
                        return Err(Error::Claim(format!(
                            "unknown comparison '{other}' (all, leading, contains, count)"
                        )))
                    }
                };
                let (missing, extra) = unmatched(&stated, &shown);
                let ok = missing.is_empty() && (compare == "contains" || extra.is_empty());
                let tag = b.map(|m| format!("block {m}: ")).unwrap_or_default();
                let tag = if *moduli { format!("{tag}moduli ") } else { tag };
                let text = (format!("{tag}{}", show_list(&stated)), format!("{tag}{}", show_list(&shown)));
                if !ok {
                    let why = format!(
                        " (stated but not found: {}; found but not stated: {})",
                        show_list(&missing),
                        show_list(&extra)
                    );
                    return Ok((false, text.0, text.1 + &why));
                }
                first.get_or_insert(text);
            }
            let (s, c) = first.unwrap_or_default();
            Ok((true, s, c))
        })
    }
}

/// Eigenvalues of Fourier block m (repeated by multiplicity).
fn block_values(spec: &Spectrum, m: usize) -> Result<Vec<Complex64>, Error> {
    let Synthesis::Dft { blocks, .. } = &spec.synthesis else {
        return Err(Error::Claim("the configuration was not decomposed into Fourier blocks".into()));
    };
    let b = blocks.get(m).ok_or_else(|| Error::Claim(format!("there is no Fourier block {m}")))?;
    let mut v: Vec<Complex64> =
        eigen::block_eigen(b)?.into_iter().flat_map(|e| std::iter::repeat_n(e.value, e.algebraic)).collect();
    v.sort_by(|a, b| eigenvalue_order(*a, *b));
    Ok(v)
}
