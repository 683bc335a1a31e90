//! The analysis of a mesh neighbourhood (`analyse`): discovery, then the
//! driver with the scheme's rows; shared once per process and scheme
//! (`analyse_shared`).

use std::sync::Arc;

use super::crease_sides;
use super::driver;
use super::exact;
use super::spectrum_result::{Method, Spectrum};
use crate::engine::memo::{Derived, Memo};
use crate::error::Error;
use crate::matrix::local::{assemble_rows_f64, assemble_rows_rational, lazy_full_f64, set_labels};
use crate::matrix::{assemble, FullMatrix, LocalMatrix};
use crate::neighbourhood::{discover_shared, Configuration, Discovered, NeighbourhoodKind};
use crate::numeric::Rational;
use crate::sdc::Scheme;

#[derive(Clone, Debug)]
pub struct Options {
    pub neighbourhood: NeighbourhoodKind,
    pub method: Option<Method>,
    /// confirm eigenvalues in exact arithmetic where S is rational
    pub exact: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: true }
    }
}

/// Everything computed for one scheme and configuration.
pub struct Analysis {
    /// shared with every analysis of the same scheme and configuration
    /// (`discover_shared`)
    pub discovered: Arc<Discovered>,
    /// S over the whole neighbourhood; with Fourier blocks only the
    /// representative rows were needed, and the rest is assembled on first
    /// access (see [`FullMatrix`])
    pub matrix: FullMatrix<f64>,
    pub exact_matrix: Option<FullMatrix<Rational>>,
    pub spectrum: Spectrum,
    /// What later stages derive from this analysis alone (a spectral
    /// certificate), made once for every caller that shares it
    /// ([`analyse_shared`]); see [`Analysis::derived`].
    derived: Derived,
}

impl Analysis {
    /// The value of type `T` derived from this analysis (and the scheme that
    /// made it) under `key`, made by `make` the first time it is asked for.
    pub fn derived<T: std::any::Any + Send + Sync, E>(
        &self,
        key: u64,
        make: impl FnOnce() -> Result<T, E>,
    ) -> Result<Arc<T>, E> {
        self.derived.get_or_try_insert(key, make)
    }
}

/// Analyses made in this process, by scheme identity, configuration and
/// options (see [`analyse_shared`]).
static ANALYSES: Memo<Analysis> = Memo::new(1 << 30);

/// Bytes an analysis holds per label, besides its shared discovery: the
/// rows of S, labels, and per block its eigenvalues and right eigenvectors
/// (a block of size m holds m² complex numbers, so this grows with the block
/// size; counted generously as 16 bytes per entry plus the rest).
fn analysis_bytes(a: &Analysis) -> usize {
    let size = a.spectrum.labels.len();
    let block = size.div_ceil(a.spectrum.valence.max(1)).max(1);
    size * (16 * block + 2048)
}

/// [`analyse`], shared: one scheme (by [`Scheme::identity`]), configuration
/// and set of options are analysed once per process, and every caller
/// reads the same analysis (`subdlab verify` decides many claims about the
/// same scheme and valence; the curvature class and its exact route ask
/// twice). A scheme without an identity is analysed afresh.
pub fn analyse_shared(scheme: &dyn Scheme, config: &Configuration, opts: &Options) -> Result<Arc<Analysis>, Error> {
    let Some(identity) = scheme.identity() else {
        return analyse(scheme, config, opts).map(Arc::new);
    };
    let key = format!("{identity} {config:?} {opts:?}");
    ANALYSES.get_or_try_insert(key, || analyse(scheme, config, opts), analysis_bytes)
}

pub fn analyse(scheme: &dyn Scheme, config: &Configuration, opts: &Options) -> Result<Analysis, Error> {
    let discovered = discover_shared(scheme, config)?;
    let kind = opts.neighbourhood;
    let n = config.valence();
    let rows = MeshRows { scheme, discovered: &discovered, kind };
    let problem = driver::Problem {
        identity: driver::Identity {
            scheme: scheme.name().to_string(),
            valence: n,
            params: scheme.params().values.iter().map(|(k, v)| (k.clone(), v.text.clone())).collect(),
            faces: config.face_sequence(),
            centre: config.centre,
            neighbourhood: kind,
            minimal_size: discovered.minimal.len(),
            analysis_size: discovered.analysis.len(),
            tagging: config.tagging.map(|t| t.name()),
        },
        labels: set_labels(&discovered, kind),
        period: config.rotation_period(scheme),
        // the chart's sectors: a tagged configuration's period is all of
        // them (an open fan has one empty sector more than its valence)
        sectors: config.chart_sectors(),
        method: opts.method,
        exact: opts.exact,
        candidates: exact::Candidates::Recognised,
        rows: &rows,
    };
    let identity = problem.identity.clone();
    let driver::Solved { matrix, exact_matrix, mut spectrum } = driver::solve(problem)?;
    // a crease vertex is decided side by side where its rules decouple the
    // sides (`crease_sides`); S whole's verdict is kept beside it
    if let Some(c) =
        crease_sides::crease_verdict(config, &identity, &matrix, exact_matrix.as_ref(), &spectrum.verdict, opts.exact)?
    {
        spectrum.verdict = crease_sides::combined(&c);
        spectrum.crease = Some(c);
    }
    Ok(Analysis { discovered, matrix, exact_matrix, spectrum, derived: Derived::default() })
}

/// The rows of S on a mesh neighbourhood, assembled from the scheme's rules
/// through the refinements discovery made.
struct MeshRows<'a> {
    scheme: &'a dyn Scheme,
    discovered: &'a Discovered,
    kind: NeighbourhoodKind,
}

impl driver::RowSource for MeshRows<'_> {
    fn float_rows(&self, which: &[usize]) -> Result<driver::Rows<f64>, Error> {
        Ok(assemble_rows_f64(self.scheme, self.discovered, self.kind, which)?)
    }
    fn float_matrix(&self) -> Result<FullMatrix<f64>, Error> {
        Ok(lazy_full_f64(self.scheme, self.discovered, self.kind)?)
    }
    fn exact_rows(&self, which: &[usize]) -> Option<driver::Rows<Rational>> {
        assemble_rows_rational(self.scheme, self.discovered, self.kind, which).ok()
    }
    fn exact_matrix(&self) -> Option<LocalMatrix<Rational>> {
        assemble::<Rational>(self.scheme, self.discovered, self.kind).ok()
    }
}

/// The regular configuration's spectrum with default options: the common call.
pub fn spectrum_of(scheme: &dyn Scheme, valence: usize) -> Result<Spectrum, Error> {
    let config = Configuration::regular(scheme, valence)?;
    Ok(analyse(scheme, &config, &Options::default())?.spectrum)
}
