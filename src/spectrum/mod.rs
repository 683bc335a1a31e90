//! Spectrum of the local subdivision matrix: via Fourier blocks when the
//! configuration is rotation-symmetric, via the full matrix otherwise; merged
//! into distinct eigenvalues with multiplicities, eigenvectors mapped back to
//! labelled vertices, exact confirmation where S is rational.

pub mod driver;
pub mod eigen;
pub mod exact;
pub mod stencils;
pub mod strip;
pub mod verdict;

use crate::error::Error;
use faer::c64;
use faer::Mat;
use rayon::prelude::*;
use serde::Serialize;

use crate::dft::{fourier_blocks_from_rows, omega_pow, Orbits};
use crate::matrix::local::{assemble_rows_f64, assemble_rows_rational, lazy_full_f64, set_labels};
use crate::matrix::{assemble, FullMatrix, LocalMatrix};
use crate::neighbourhood::{discover_shared, Configuration, Discovered, NeighbourhoodKind, VertexLabel};
use std::sync::Arc;

use crate::engine::memo::{Derived, Memo};
use crate::numeric::recognise::recognise;
use crate::numeric::Rational;
use crate::sdc::Scheme;
pub use exact::ExactSummary;
pub use verdict::Verdict;

/// Two eigenvalues from different blocks are the same when this close (relative).
const MERGE_TOL: f64 = 1e-8;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Fourier blocks of the rotation-symmetric matrix
    Dft,
    /// the full matrix (no rotation symmetry, or forced)
    Full,
}

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

#[derive(Clone, Debug, Serialize)]
pub struct BlockInfo {
    pub index: usize,
    pub size: usize,
}

/// Right eigenvectors of one eigenvalue from one block, in block coordinates
/// (B x = λ x). Left eigenvectors are computed on request from the block, and
/// both are mapped to the whole neighbourhood on request
/// ([`Spectrum::right_vectors`], [`Spectrum::left_vectors`]): at high valence
/// most of the n blocks' vectors are never looked at.
#[derive(Clone, Debug)]
pub struct EigenVectors {
    pub block: usize,
    pub right: Vec<Vec<c64>>,
}

/// The blocks that were decomposed, and how block coordinates map to
/// neighbourhood vertices.
#[derive(Clone, Debug)]
pub enum Synthesis {
    /// block m's coordinate k is orbit `block_orbits[m][k]`
    Dft { orbits: Orbits, block_orbits: Vec<Vec<usize>>, blocks: Vec<Mat<c64>> },
    /// the single block is the whole matrix
    Full { matrix: Mat<c64> },
}

impl Synthesis {
    /// Fourier block `m`, or the whole matrix when there is no symmetry.
    pub fn block(&self, m: usize) -> &Mat<c64> {
        match self {
            Synthesis::Dft { blocks, .. } => &blocks[m],
            Synthesis::Full { matrix } => matrix,
        }
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Eigenvalue {
    pub re: f64,
    pub im: f64,
    pub modulus: f64,
    pub algebraic_multiplicity: usize,
    pub geometric_multiplicity: usize,
    pub defective: bool,
    /// first block containing it
    pub block: usize,
    pub blocks: Vec<usize>,
    /// exact rational value, proven by the exact path (root of an exact
    /// characteristic polynomial), else null
    pub exact: Option<String>,
    /// a small rational close to the value (a reading aid, not a proof)
    pub recognised: Option<String>,
    #[serde(skip)]
    pub vectors: Vec<EigenVectors>,
}

impl Eigenvalue {
    pub fn value(&self) -> c64 {
        c64::new(self.re, self.im)
    }
    pub fn is_real(&self) -> bool {
        self.im.abs() <= 1e-9 * self.modulus.max(1.0)
    }
    /// "0.25 (1/4)" style display.
    pub fn display(&self) -> String {
        let num = if self.is_real() {
            fmt_f(self.re)
        } else {
            let sign = if self.im < 0.0 { '-' } else { '+' };
            format!("{}{sign}{}i", fmt_f(self.re), fmt_f(self.im.abs()))
        };
        match (&self.exact, &self.recognised) {
            (Some(e), _) => format!("{num} (= {e})"),
            (None, Some(r)) => format!("{num} (≈ {r})"),
            _ => num,
        }
    }
}

pub fn fmt_f(x: f64) -> String {
    let s = format!("{x:.12}");
    let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Spectrum {
    pub scheme: String,
    pub valence: usize,
    pub params: std::collections::BTreeMap<String, String>,
    pub faces: String,
    pub centre: crate::sdc::CentreKind,
    pub neighbourhood: NeighbourhoodKind,
    pub matrix_size: usize,
    pub minimal_size: usize,
    pub analysis_size: usize,
    pub method: Method,
    pub blocks: Vec<BlockInfo>,
    pub eigenvalues: Vec<Eigenvalue>,
    pub verdict: Verdict,
    pub exact_analysis: Option<ExactSummary>,
    #[serde(skip)]
    pub labels: Vec<VertexLabel>,
    #[serde(skip)]
    pub synthesis: Synthesis,
}

impl Spectrum {
    /// Right eigenvectors of `e` over the neighbourhood (S x = λ x).
    pub fn right_vectors(&self, e: &Eigenvalue) -> Vec<Vec<c64>> {
        self.map_vectors(e, false)
    }
    /// Left eigenvectors of `e` over the neighbourhood, as rows l with l S = λ l.
    pub fn left_vectors(&self, e: &Eigenvalue) -> Vec<Vec<c64>> {
        self.map_vectors(e, true)
    }
    fn map_vectors(&self, e: &Eigenvalue, left: bool) -> Vec<Vec<c64>> {
        let mut out = Vec::new();
        for vs in &e.vectors {
            let list = if left {
                let lambda = c64::new(e.re, e.im);
                eigen::left_eigenvectors(self.synthesis.block(vs.block), lambda, vs.right.len()).unwrap_or_default()
            } else {
                vs.right.clone()
            };
            for x in &list {
                out.push(match &self.synthesis {
                    Synthesis::Full { .. } => {
                        if left {
                            x.iter().map(|z| z.conj()).collect()
                        } else {
                            x.clone()
                        }
                    }
                    Synthesis::Dft { orbits, block_orbits, .. } => {
                        synthesise(x, vs.block, &block_orbits[vs.block], orbits, self.matrix_size, left)
                    }
                });
            }
        }
        out
    }
}

/// Largest matrix analysed whole (`Method::Full`): a dense eigenproblem of
/// this size takes seconds; beyond, the request is refused up front.
pub const MAX_FULL_SIZE: usize = 1500;

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
        },
        labels: set_labels(&discovered, kind),
        period: config.rotation_period(scheme),
        sectors: n,
        method: opts.method,
        exact: opts.exact,
        candidates: exact::Candidates::Recognised,
        rows: &rows,
    };
    let driver::Solved { matrix, exact_matrix, spectrum } = driver::solve(problem)?;
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

/// Eigenvalues of a local matrix (unsorted distinct values with multiplicities,
/// vectors in block coordinates) and the blocks they came from.
pub struct Decomposition {
    pub blocks: Vec<BlockInfo>,
    pub eigenvalues: Vec<Eigenvalue>,
    pub synthesis: Synthesis,
}

/// The eigen-stage of the pipeline on its own (the benchmark times this):
/// `period` is the configuration's rotation period, `n` its valence.
pub fn decompose(matrix: &LocalMatrix<f64>, period: usize, n: usize, method: Method) -> Result<Decomposition, Error> {
    match method {
        Method::Dft => {
            let orbits = Orbits::new(matrix, period, n);
            let rows: Vec<&[(usize, f64)]> = orbits.representative.iter().map(|&k| matrix.rows[k].as_slice()).collect();
            decompose_dft(&rows, orbits)
        }
        Method::Full => {
            let dense = Mat::<c64>::from_fn(matrix.size(), matrix.size(), |i, j| c64::new(matrix.get(i, j), 0.0));
            let all = eigen::block_eigen(&dense)?.into_iter().map(|e| Eigenvalue::from_block(e, 0)).collect();
            Ok(finish(vec![BlockInfo { index: 0, size: matrix.size() }], all, Synthesis::Full { matrix: dense }))
        }
    }
}

/// The Fourier path from the representative rows (`rows[o]`: the row of S of
/// orbit o's representative, over all columns).
pub fn decompose_dft(rows: &[&[(usize, f64)]], orbits: Orbits) -> Result<Decomposition, Error> {
    let blocks = fourier_blocks_from_rows(rows, &orbits);
    // the blocks are independent eigenproblems: solved side by side, and
    // collected in block order, so the result does not depend on scheduling
    let solved: Vec<Result<Vec<eigen::BlockEigen>, Error>> =
        blocks.par_iter().map(|b| eigen::block_eigen(&b.matrix)).collect();
    let mut all = Vec::new();
    for (b, eigen) in blocks.iter().zip(solved) {
        all.extend(eigen?.into_iter().map(|e| Eigenvalue::from_block(e, b.index)));
    }
    let info = blocks.iter().map(|b| BlockInfo { index: b.index, size: b.matrix.nrows() }).collect();
    let (block_orbits, mats) = blocks.into_iter().map(|b| (b.orbits, b.matrix)).unzip();
    Ok(finish(info, all, Synthesis::Dft { orbits, block_orbits, blocks: mats }))
}

fn finish(blocks: Vec<BlockInfo>, eigenvalues: Vec<Eigenvalue>, synthesis: Synthesis) -> Decomposition {
    let mut eigenvalues = merge(eigenvalues);
    for e in &mut eigenvalues {
        // snap tiny imaginary parts of real eigenvalues (conjugate blocks) to zero
        if e.im.abs() < 1e-12 * e.modulus.max(1.0) {
            e.im = 0.0;
        }
        e.recognised = if e.is_real() { recognise(e.re) } else { None };
    }
    Decomposition { blocks, eigenvalues, synthesis }
}

impl Eigenvalue {
    fn from_block(e: eigen::BlockEigen, m: usize) -> Eigenvalue {
        Eigenvalue {
            re: e.value.re,
            im: e.value.im,
            modulus: e.value.norm(),
            algebraic_multiplicity: e.algebraic,
            geometric_multiplicity: e.geometric,
            defective: e.geometric < e.algebraic,
            block: m,
            blocks: vec![m],
            exact: None,
            recognised: None,
            vectors: vec![EigenVectors { block: m, right: e.right }],
        }
    }
}

/// Map one block vector to the whole neighbourhood: right vectors by
/// X[(t,a)] = ω^{mt} x_a, left rows by l[(t,a)] = conj(y_a) ω^{-mt} / g (the
/// dual basis of u_a^m); fixed points (the centre) carry their value as is.
fn synthesise(x: &[c64], m: usize, block_orbits: &[usize], orbits: &Orbits, size: usize, left: bool) -> Vec<c64> {
    let g = orbits.group_order;
    let mut pos = vec![usize::MAX; orbits.num_orbits()];
    for (k, &o) in block_orbits.iter().enumerate() {
        pos[o] = k;
    }
    (0..size)
        .map(|k| {
            let (o, t) = orbits.member[k];
            if pos[o] == usize::MAX {
                return c64::new(0.0, 0.0);
            }
            let v = if left { x[pos[o]].conj() } else { x[pos[o]] };
            if orbits.fixed[o] {
                v
            } else if left {
                v * omega_pow(m, t, g).conj() / g as f64
            } else {
                v * omega_pow(m, t, g)
            }
        })
        .collect()
}

/// Merge equal eigenvalues found in different blocks: each joins the first
/// earlier distinct value within the tolerance. Candidates are looked up in
/// buckets of the real part (a match is at most the tolerance away in it), so
/// n blocks' eigenvalues are not each compared with every distinct one.
fn merge(list: Vec<Eigenvalue>) -> Vec<Eigenvalue> {
    const BUCKET: f64 = 1e-6;
    const MAX_SPAN: f64 = 64.0;
    let mut out: Vec<Eigenvalue> = Vec::new();
    let mut buckets: std::collections::HashMap<i64, Vec<usize>> = std::collections::HashMap::new();
    let key = |re: f64| (re / BUCKET).floor() as i64;
    for e in list {
        let z = e.value();
        let tol = MERGE_TOL * z.norm().max(1.0);
        let close = |t: &Eigenvalue| (t.value() - z).norm() < tol;
        let found = if (tol / BUCKET) < MAX_SPAN && z.re.is_finite() {
            // the first (lowest index) match among the buckets the tolerance
            // reaches, one more on each side against rounding at the edges
            (key(z.re - tol) - 1..=key(z.re + tol) + 1)
                .filter_map(|b| buckets.get(&b))
                .flat_map(|ids| ids.iter().copied())
                .filter(|&i| close(&out[i]))
                .min()
        } else {
            out.iter().position(close)
        };
        if let Some(i) = found {
            let t = &mut out[i];
            t.algebraic_multiplicity += e.algebraic_multiplicity;
            t.geometric_multiplicity += e.geometric_multiplicity;
            t.defective |= e.defective;
            t.blocks.extend(e.blocks);
            t.blocks.sort_unstable();
            t.block = t.blocks[0];
            t.vectors.extend(e.vectors);
        } else {
            buckets.entry(key(z.re)).or_default().push(out.len());
            out.push(e);
        }
    }
    out
}

/// Modulus descending; ties by real part, then imaginary part, descending.
pub fn sort_eigenvalues(list: &mut [Eigenvalue]) {
    list.sort_by(|a, b| eigenvalue_order(c64::new(a.re, a.im), c64::new(b.re, b.im)));
}

/// The display order of eigenvalues (ARCHITECTURE.md): modulus descending, ties by
/// real part, then imaginary part, descending.
pub fn eigenvalue_order(a: c64, b: c64) -> std::cmp::Ordering {
    let tie = |x: f64, y: f64| (x - y).abs() <= 1e-10 * x.abs().max(y.abs()).max(1.0);
    if !tie(a.norm(), b.norm()) {
        return b.norm().total_cmp(&a.norm());
    }
    if !tie(a.re, b.re) {
        return b.re.total_cmp(&a.re);
    }
    b.im.total_cmp(&a.im)
}

/// The regular configuration's spectrum with default options: the common call.
pub fn spectrum_of(scheme: &dyn Scheme, valence: usize) -> Result<Spectrum, Error> {
    let config = Configuration::regular(scheme, valence)?;
    Ok(analyse(scheme, &config, &Options::default())?.spectrum)
}
