//! `spectral-c1`: Reif's spectral C¹ test, from the file's shared spectra or
//! certified (`spectrum --certify`, writing each configuration's
//! certificate when asked).

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::configurations::{over_independent_valences, over_valences};
use crate::claims::common::spectra::{kind_of, subject_config, Cache, CertificateNames};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;

/// The spectral C^1 test (Reif) passes (`expect = true`, the default) or fails.
#[derive(Clone, Debug, Deserialize)]
pub struct SpectralC1 {
    #[serde(flatten)]
    pub subject: Subject,
    #[serde(default = "yes")]
    pub expect: bool,
    /// decide by the certified spectrum (`spectrum --certify`):
    /// PROVED (unconditionally) or DISPROVED decide, anything else is
    /// INCONCLUSIVE with the certificate's reason
    #[serde(default)]
    pub certified: bool,
}

fn yes() -> bool {
    true
}

impl CheckKind for SpectralC1 {
    const KEYS: &'static [&'static str] = &["expect", "certified"];

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let SpectralC1 { subject, expect, certified } = self;
        if *certified {
            return certified_c1(subject, expect, cache.certificate_names());
        }
        cache.prefetch(subject);
        over_valences(subject, |subject, n| {
            let spec = cache.spectrum(subject, n)?;
            let got = spec.verdict.c1_spectral;
            // a crease decided side by side names that route and the
            // failing side; elsewhere the first reason that says why
            let per_side = spec.verdict.criterion == "sector per side";
            let why = if per_side {
                spec.verdict.failures.first().cloned()
            } else {
                spec.verdict.reasons.iter().find(|r| r.contains("not") || r.contains("defective")).cloned()
            };
            Ok((
                got == *expect,
                if *expect { "passes".into() } else { "fails".into() },
                format!(
                    "{}{}{}",
                    if per_side { "per side (each side's principal submatrix of S, floating point): " } else { "" },
                    if got { "passes" } else { "fails" },
                    why.map(|w| format!(": {w}")).unwrap_or_default()
                ),
            ))
        })
    }
}

/// An unconditional PROVED (true) or DISPROVED (false), else why not (a
/// verdict resting on identities confirmed only to interval overlap, or no
/// proof: the claim asked for one).
fn unconditional(verdict: &crate::certify::Verdict, conditional: bool, n: usize) -> Result<bool, Error> {
    match verdict {
        crate::certify::Verdict::Proved if !conditional => Ok(true),
        crate::certify::Verdict::Disproved(_) if !conditional => Ok(false),
        crate::certify::Verdict::Proved | crate::certify::Verdict::Disproved(_) => Err(Error::Undecided(format!(
            "n = {n}: certified {} only given the premises the enclosures confirm to interval overlap (not exactly): \
             no unconditional proof",
            verdict.word()
        ))),
        crate::certify::Verdict::NotProved(why) => {
            Err(Error::Undecided(format!("n = {n}: certificate NOT PROVED ({why})")))
        }
    }
}

/// The certified spectral test at every configuration side by side.
fn certified_c1(subject: &Subject, expect: &bool, names: CertificateNames) -> Result<Finding, Error> {
    over_independent_valences(subject, |subject, n| {
        let (scheme, config) = subject_config(subject, n)?;
        let options = crate::spectrum::Options { neighbourhood: kind_of(subject)?, method: None, exact: false };
        let analysis = crate::spectrum::analyse_shared(scheme.as_ref(), &config, &options)?;
        // at a tagged vertex: the sector criterion's spectral part
        // (`certify::tagged`: the reflection's blocks by enclosures, and
        // exactly over Q where S is rational)
        if config.tagging.is_some() {
            let c = crate::certify::tagged::certify_tagged(scheme.as_ref(), &analysis)?;
            if let Some(path) = names.path(subject, n) {
                crate::certify::export::write_tagged(&path, scheme.as_ref(), &analysis, &c)?;
            }
            let got = unconditional(&c.verdict, c.conditional, n)?;
            return Ok((
                got == *expect,
                if *expect { "proved".into() } else { "disproved".into() },
                format!(
                    "certified sector criterion {} (decided by {})",
                    c.verdict.display(),
                    c.decided_by.unwrap_or("neither route")
                ),
            ));
        }
        let c = crate::certify::certify_analysis(scheme.as_ref(), &analysis)?;
        if let Some(path) = names.path(subject, n) {
            crate::certify::export::write_spectrum(&path, scheme.as_ref(), &analysis, &c)?;
        }
        let got = unconditional(&c.verdict, c.conditional, n)?;
        let gap = c.margins.gap_lower_bound.map(|g| format!(", gap ≥ {g:.6e}")).unwrap_or_default();
        Ok((
            got == *expect,
            if *expect { "proved".into() } else { "disproved".into() },
            format!("certified {}{gap}", c.verdict.display()),
        ))
    })
}
