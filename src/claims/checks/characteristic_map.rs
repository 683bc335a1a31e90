//! `characteristic-map`: Reif's regularity and injectivity of the
//! characteristic map, sampled (`subdlab charmap`) or certified
//! (`charmap --certify`, writing each configuration's certificate when asked).

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::configurations::over_independent_valences;
use crate::claims::common::spectra::{subject_config, Cache, CertificateNames};
use crate::claims::subject::Subject;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::neighbourhood::NeighbourhoodKind;
use crate::spectrum::fmt_f;

/// The characteristic map is regular and injective (`expect = true`, the default) or
/// not (Reif's test, `charmap`); `levels` and `resolution` as for
/// `subdlab charmap` (defaults 3 and 256).
#[derive(Clone, Debug, Deserialize)]
pub struct CharacteristicMap {
    #[serde(flatten)]
    pub subject: Subject,
    #[serde(default = "yes")]
    pub expect: bool,
    #[serde(default)]
    pub levels: Option<usize>,
    #[serde(default)]
    pub resolution: Option<usize>,
    /// decide by the certified map (`charmap --certify`): regularity and
    /// injectivity both PROVED (unconditionally), or one DISPROVED,
    /// decide; anything else is INCONCLUSIVE with the certificate's reason
    #[serde(default)]
    pub certified: bool,
}

fn yes() -> bool {
    true
}

impl CheckKind for CharacteristicMap {
    const KEYS: &'static [&'static str] = &["expect", "levels", "resolution", "certified"];

    /// The options in the command line's own ranges
    /// (`certify::charmap::check_levels`, `CharMapOptions::checked`).
    fn validate(&self) -> Result<(), Error> {
        if self.certified {
            crate::certify::charmap::check_levels(
                self.levels.unwrap_or(crate::certify::charmap::DEFAULT_MAX_LEVELS),
                "levels",
            )
        } else {
            crate::charmap::CharMapOptions::checked(self.levels.unwrap_or(3), self.resolution.unwrap_or(256))
                .map(|_| ())
        }
    }

    fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
        let CharacteristicMap { subject, expect, levels, resolution, certified } = self;
        if *certified {
            certified_map(subject, expect, levels, cache.certificate_names())
        } else {
            sampled_map(subject, expect, levels, resolution)
        }
    }
}

/// Reif's criterion by the certified map, at every configuration side by side.
fn certified_map(
    subject: &Subject,
    expect: &bool,
    levels: &Option<usize>,
    names: CertificateNames,
) -> Result<Finding, Error> {
    if subject.tag.is_some() {
        return certified_boundary_map(subject, expect, levels, names);
    }
    over_independent_valences(subject, |subject, n| {
        let (scheme, config) = subject_config(subject, n)?;
        let options =
            crate::spectrum::Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
        let analysis = crate::spectrum::analyse_shared(scheme.as_ref(), &config, &options)?;
        let most = levels.unwrap_or(crate::certify::charmap::DEFAULT_MAX_LEVELS);
        let c = crate::certify::certify_charmap(scheme.as_ref(), &analysis, most)?;
        if let Some(path) = names.path(subject, n) {
            crate::certify::export::write_charmap(&path, scheme.as_ref(), &analysis, &c)?;
        }
        use crate::certify::Verdict;
        // Reif's criterion as a whole: the spectrum, regularity and
        // injectivity all proved (a disproof of any one refutes), each
        // unconditionally
        let got = match &c.c1 {
        Verdict::Disproved(_) if !c.conditional && !c.geometry_conditional => false,
        Verdict::Proved if !c.conditional && !c.geometry_conditional => true,
        Verdict::Proved | Verdict::Disproved(_) => {
            return Err(Error::Undecided(format!(
                "n = {n}: the certificate is {} only given a premise confirmed to interval overlap (not exactly): no unconditional proof",
                c.c1.word()
            )))
        }
        Verdict::NotProved(why) => return Err(Error::Undecided(format!("n = {n}: certificate NOT PROVED ({why})"))),
    };
        let bound = c.min_jacobian_lower_bound.map(|b| format!(", Jacobian ≥ {b:.4e}")).unwrap_or_default();
        Ok((
            got == *expect,
            if *expect { "proved regular and injective".into() } else { "disproved".into() },
            format!(
                "certified spectrum {}, regularity {}, injectivity {} (winding {}{bound})",
                c.spectrum.verdict.word(),
                c.regularity.display(),
                c.injectivity.display(),
                c.winding_number.map(|w| w.to_string()).unwrap_or_else(|| "-".into())
            ),
        ))
    })
}

/// The sector criterion at a boundary vertex by the certified sector map
/// (`charmap --tag boundary --certify`, `certify::tagged_charmap`), with its
/// certificate document where asked for; other tags are refused in one line.
fn certified_boundary_map(
    subject: &Subject,
    expect: &bool,
    levels: &Option<usize>,
    names: CertificateNames,
) -> Result<Finding, Error> {
    if subject.tag.as_deref() != Some("boundary") {
        subject.refuse_tag("the certified characteristic map (boundary vertices only)")?;
    }
    over_independent_valences(subject, |subject, n| {
        let (scheme, config) = subject_config(subject, n)?;
        let options =
            crate::spectrum::Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
        let analysis = crate::spectrum::analyse_shared(scheme.as_ref(), &config, &options)?;
        let most = levels.unwrap_or(crate::certify::charmap::DEFAULT_MAX_LEVELS);
        let c = crate::certify::tagged_charmap::certify_tagged_charmap(scheme.as_ref(), &analysis, most)?;
        // the document: the tagged part and, for a PROVED map, the sector
        // part (`export::write_tagged_charmap`)
        if let Some(path) = names.path(subject, n) {
            crate::certify::export::write_tagged_charmap(&path, scheme.as_ref(), &analysis, &c)?;
        }
        use crate::certify::Verdict;
        let got = match &c.sector_criterion {
            Verdict::Disproved(_) if !c.conditional => false,
            Verdict::Proved if !c.conditional => true,
            Verdict::Proved | Verdict::Disproved(_) => {
                return Err(Error::Undecided(format!(
                    "n = {n}: the certificate is {} only given a premise confirmed to interval overlap: no \
                     unconditional proof",
                    c.sector_criterion.word()
                )))
            }
            Verdict::NotProved(why) => {
                return Err(Error::Undecided(format!("n = {n}: certificate NOT PROVED ({why})")))
            }
        };
        Ok((
            got == *expect,
            if *expect { "proved regular and injective on the sector".into() } else { "disproved".into() },
            format!(
                "certified sector criterion {} by the sector map (spectral part {}, decided by {}); regularity {}, \
                 injectivity {} (doubled winding {})",
                c.sector_criterion.word(),
                c.spectrum.verdict.word(),
                c.spectrum.decided_by.unwrap_or("-"),
                c.regularity.display(),
                c.injectivity.display(),
                c.winding_number.map(|w| w.to_string()).unwrap_or_else(|| "-".into())
            ),
        ))
    })
}

/// The sampled characteristic map (`subdlab charmap`), at every configuration side by side.
fn sampled_map(
    subject: &Subject,
    expect: &bool,
    levels: &Option<usize>,
    resolution: &Option<usize>,
) -> Result<Finding, Error> {
    over_independent_valences(subject, |subject, n| {
        let (scheme, config) = subject_config(subject, n)?;
        let opts = crate::charmap::CharMapOptions {
            levels: levels.unwrap_or(3),
            resolution: resolution.unwrap_or(256),
            display_levels: None,
        };
        let m = crate::charmap::characteristic_map(scheme.as_ref(), &config, &opts)?;
        let good = m.regular && m.injective;
        let what = format!(
            "{}, {} (winding {}, overlap pixels {}, min Jacobian ratio {})",
            if m.regular { "regular" } else { "not regular" },
            if m.injective { "injective" } else { "not injective" },
            m.winding_number.map(|w| w.to_string()).unwrap_or_else(|| "-".into()),
            m.overlap_pixels.map(|w| w.to_string()).unwrap_or_else(|| "-".into()),
            m.min_jacobian_ratio.map(fmt_f).unwrap_or_else(|| "-".into()),
        );
        let what = if m.reasons.is_empty() { what } else { format!("{what}: {}", m.explanation) };
        Ok((
            good == *expect,
            if *expect { "regular and injective".into() } else { "not regular and injective".into() },
            what,
        ))
    })
}
