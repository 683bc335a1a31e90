//! The analyses a file's claims share: the spectrum of each configuration
//! a claim asks about, computed once per file ([`Cache`]), the scheme and
//! configuration of a subject at a valence, and the names of the
//! certificate files certified claims write. Shared by every check plug-in;
//! imports none of them.

use std::collections::HashMap;
use std::sync::Arc;

use num_complex::Complex64;

use crate::claims::common::values::subject_params;
use crate::claims::schedule;
use crate::claims::subject::Subject;
use crate::error::Error;
use crate::lattice;
use crate::neighbourhood::{Configuration, NeighbourhoodKind, Tagging, VertexKind};
use crate::schemes;
use crate::schemes::registry::{self, Built};
use crate::schemes::route::{refusal, route, space, Analysis, Route};
use crate::spectrum::{analyse_shared, Options, Spectrum};

#[derive(Default)]
pub struct Cache {
    spectra: HashMap<String, Result<Arc<Spectrum>, Error>>,
    /// where certified claims write their certificate documents
    certificates: Option<std::path::PathBuf>,
    /// the claim being evaluated (names its certificate files)
    pub claim: String,
}

/// Names the certificate files of one claim (what a configuration evaluated
/// on another thread needs of the cache).
pub struct CertificateNames {
    directory: Option<std::path::PathBuf>,
    claim: String,
}

impl CertificateNames {
    /// The file the certificate of the claim at valence n goes to, when
    /// certificates are asked for.
    pub fn path(&self, subject: &Subject, n: usize) -> Option<std::path::PathBuf> {
        let faces = subject.faces_for(n).map(|f| format!("-{f}")).unwrap_or_default();
        let safe: String = format!("{}-n{n}{faces}", self.claim)
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() || "-_.".contains(c) { c } else { '_' })
            .collect();
        self.directory.as_ref().map(|dir| dir.join(format!("{safe}.json")))
    }
}

impl Cache {
    pub fn writing_certificates(certificates: Option<std::path::PathBuf>) -> Cache {
        Cache { certificates, ..Default::default() }
    }

    pub fn certificate_names(&self) -> CertificateNames {
        CertificateNames { directory: self.certificates.clone(), claim: self.claim.clone() }
    }

    fn key(s: &Subject, n: usize) -> String {
        format!("{}|{:?}|{n}|{:?}|{:?}|{:?}", s.scheme, s.params, s.neighbourhood, s.faces_for(n), s.tag)
    }

    pub fn spectrum(&mut self, s: &Subject, n: usize) -> Result<Arc<Spectrum>, Error> {
        self.spectra.entry(Cache::key(s, n)).or_insert_with(|| compute(s, n).map(Arc::new)).clone()
    }

    /// Analyse, side by side, every configuration of `subject` that is not
    /// cached yet, for a check that asks for the spectrum of each (the
    /// sequential pass then finds them all cached: the same analyses, as
    /// `compute` reads only the narrowed subject). A subject whose
    /// configurations cannot be listed is left to that pass to report.
    pub fn prefetch(&mut self, subject: &Subject) {
        let Ok(configurations) = subject.configurations() else { return };
        let mut missing: Vec<(usize, Subject)> = Vec::new();
        let mut keys: Vec<String> = Vec::new();
        for (n, s) in configurations {
            let key = Cache::key(&s, n);
            if !self.spectra.contains_key(&key) && !keys.contains(&key) {
                keys.push(key);
                missing.push((n, s));
            }
        }
        if missing.len() < 2 {
            return;
        }
        let computed = schedule::each_configuration(&missing, |s, n| compute(s, n).map(Arc::new));
        self.spectra.extend(keys.into_iter().zip(computed));
    }
}

pub fn kind_of(s: &Subject) -> Result<NeighbourhoodKind, Error> {
    s.neighbourhood.as_deref().unwrap_or("analysis").parse()
}

/// The scheme (with parameters evaluated at valence n) and configuration.
pub fn subject_config(s: &Subject, n: usize) -> Result<(Box<dyn schemes::Scheme>, Configuration), Error> {
    let scheme = schemes::resolve(&s.scheme, &subject_params(s, n)?)?;
    let config = configuration(s, scheme.as_ref(), n)?;
    Ok((scheme, config))
}

/// The subject's configuration at valence n: tagged, its face sequence, or regular.
fn configuration(s: &Subject, scheme: &dyn schemes::Scheme, n: usize) -> Result<Configuration, Error> {
    if let Some(tag) = &s.tag {
        return Configuration::tagged(scheme, n, s.faces_for(n), Tagging::parse(tag)?);
    }
    match s.faces_for(n) {
        Some(f) => Configuration::with_faces(scheme, n, f),
        None => Configuration::regular(scheme, n),
    }
}

fn compute(s: &Subject, n: usize) -> Result<Spectrum, Error> {
    let kind = kind_of(s)?;
    // the scheme's domain decides where its spectrum is computed, by the
    // table the command line's front door consults (`schemes::route`): a
    // lattice scheme's on its Z² window, a mesh scheme's on the mesh
    let built = registry::resolve(&s.scheme, &subject_params(s, n)?)?;
    let domain = built.family();
    match (route(domain, Analysis::Spectrum), built) {
        (Route::Refused(why), _) => Err(Error::Claim(refusal(Analysis::Spectrum, &s.scheme, domain, why))),
        (Route::Native, Built::Lattice(scheme)) => {
            if n != 4 {
                return Err(Error::Claim(format!("{} is defined on the regular lattice only (valence 4)", s.scheme)));
            }
            Ok(lattice::analysis::analyse(scheme.as_ref(), kind, false)?.spectrum)
        }
        (Route::Native, Built::Curve(_)) => Err(Error::Claim(format!(
            "'{}' is a curve scheme (domain: {}): claims speak about surfaces; its spectrum is `subdlab spectrum {0}`'s",
            s.scheme,
            space(domain)
        ))),
        (Route::Mesh, built) | (Route::Native, built @ Built::Mesh(_)) => {
            let scheme = schemes::on_mesh(built, &s.scheme)?;
            let config = configuration(s, scheme.as_ref(), n)?;
            Ok(analyse_shared(scheme.as_ref(), &config, &Options { neighbourhood: kind, method: None, exact: false })?
                .spectrum
                .clone())
        }
    }
}

pub fn expanded(spec: &Spectrum) -> Vec<Complex64> {
    spec.eigenvalues
        .iter()
        .flat_map(|e| std::iter::repeat_n(Complex64::new(e.re, e.im), e.algebraic_multiplicity))
        .collect()
}

/// "centre", or "kind.ring" such as "fcv.1".
pub fn selector(kind: VertexKind, ring: usize) -> String {
    match kind {
        VertexKind::Centre => "centre".into(),
        k => format!("{}.{ring}", crate::neighbourhood::labels::kind_name(k)),
    }
}
