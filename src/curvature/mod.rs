//! Second-order analysis at an extraordinary point: the curvature class, the
//! L_p limit of the principal curvatures, the Fourier index set F(μ) and the
//! shapes it allows, and Reif's C² test (Peters & Reif, *Subdivision
//! Surfaces*, 2008, ch. 7; Karčiauskas, Peters & Reif, CAGD 21, 2004).
//!
//! # The expansion
//!
//! With the subdominant eigenvalue λ (double, from Fourier blocks 1 and n−1,
//! characteristic map χ = (ψ1, ψ2)) and the eigenvalues below it, the
//! surface rings near the centre are, after m steps and up to the limit point,
//!
//! x_m ≈ λ^m (c1 ψ1 + c2 ψ2) + μ^m Σ_j r_j ψ_j + o(|μ|^m),
//!
//! where μ is the largest-modulus eigenvalue below λ whose eigenfunctions
//! ψ_j do not vanish on the characteristic ring (an eigenfunction that
//! vanishes there vanishes on the whole first ring of faces by
//! self-similarity, so it never shows in the surface). In the tangent plane
//! the ring has size ~λ^m; its height over the plane is ~|μ|^m. The second
//! fundamental form divided by the first gives principal curvatures of size
//!
//! κ_m ~ |μ|^m / λ^(2m) = (|μ| / λ²)^m,
//!
//! so the curvature tends to zero (|μ| < λ²: a forced flat spot for generic
//! data), stays bounded (|μ| = λ² without a Jordan block; it oscillates from
//! ring to ring when an eigenvalue of that modulus is not λ² itself), or
//! diverges (|μ| > λ², or a Jordan block at λ², where κ_m ~ m). A Jordan
//! chain S w2 = λ² w2 + w1 puts m λ^(2m−2) on the eigenvector w1 at its top,
//! so it counts when w1's eigenfunction does not vanish on the ring
//! (`EigenInfo::jordan_visible`: per block B, with N = B − νI, the vectors
//! N·w for w in the generalised eigenspace G of ν, which S^m multiplies by a
//! positive power of m). G is also where an eigenvalue shows: when w1
//! vanishes on the ring but w2 does not, the ring sees ν^m w2, so ν counts
//! for μ (with no growth) although every eigenvector vanishes there. G is
//! computed level by level ([`jordan::generalised_eigenspace`]): null(N),
//! then the w with N w in it, and so on.
//!
//! # The L_p limit
//!
//! Ring m has area ~λ^(2m), so ∫|κ|^p ≈ Σ_m λ^(2m) (|μ|/λ²)^(pm), a geometric
//! series with ratio λ² (|μ|/λ²)^p. It converges iff
//! 2 ln λ + p (ln|μ| − 2 ln λ) < 0; for |μ| > λ² the bracket is positive and
//!
//! p < p* = 2 ln λ / (2 ln λ − ln|μ|) = 2 ln λ / ln(λ²/|μ|),
//!
//! the limit exponent of Peters–Reif (section 7.1). For |μ| ≤ λ² every p is
//! admissible (a Jordan block at λ² adds a factor m^p, which does not change
//! the geometric ratio λ² < 1: every finite p, not p = ∞).
//!
//! # Which eigenfunctions vanish on the ring
//!
//! Each eigenvector (real and imaginary parts of its block vector mapped to
//! the neighbourhood) is refined with the scheme's own rules over the
//! characteristic ring ([`sampler`]: the same refinement as the
//! characteristic map's net, `levels` analysis steps). The eigenvalue is
//! excluded when, for every eigenvector, the largest refined value on the ring
//! is at most [`VANISH_TOL`] times the vector's largest entry. The refined
//! control values converge to the limit function; when they are all zero the
//! limit function is zero on the ring. (A scheme with linearly dependent
//! generating functions could have a zero limit function with nonzero
//! refined values; such an eigenvalue would be counted, which can only make
//! the reported class worse, never better.)
//!
//! # Evidence
//!
//! Eigenvalues are compared with a relative tolerance [`EIG_TOL`]
//! (`floating-point`; the margin |μ|/λ² − 1 is reported). When λ and μ both
//! read as small rationals, [`curvature`] runs the exact path, and when it
//! proves both (`Eigenvalue::exact`), |μ| and λ² are compared in exact
//! arithmetic (`exact`); the Jordan structure still comes from the
//! floating-point multiplicities.
//!
//! # C² (Reif)
//!
//! The scheme can be C² at the centre (through this route: the
//! eigenfunctions of λ² are homogeneous quadratic polynomials in χ) only when
//! no eigenfunction has an eigenvalue strictly between λ² and λ in modulus,
//! every eigenvalue of modulus λ² is λ² itself and non-defective, and each
//! eigenfunction of λ² lies in span{x², xy, y²} ∘ χ. The last condition is
//! tested by a least-squares fit of the refined eigenvector over the refined
//! χ on the ring vertices; refined *control* values of q∘χ differ from q of
//! the refined control values of χ by a constant for box splines, so the fit
//! space is span{x², xy, y², 1}. The relative residual ‖ψ − fit‖/‖ψ‖ is
//! reported; the fit passes below [`C2_TOL`].

pub mod figure;
pub mod jordan;
pub mod sampler;

use std::cmp::Ordering;
use std::collections::BTreeMap;

use faer::c64;
use num_bigint::BigInt;
use serde::Serialize;

use crate::charmap::spectral::{subdominant_pair, SpectralStatus};
use crate::charmap::{check_map_over, CharMapOptions};
use crate::error::Error;
use crate::neighbourhood::{Configuration, NeighbourhoodKind};
use crate::numeric::Rational;
use crate::sdc::Scheme;
use crate::spectrum::{analyse_shared, Analysis, Eigenvalue, Method, Options, Spectrum, Synthesis};
pub use figure::{FigureData, Quadratic, SurfaceRows};
pub use sampler::RingSampler;

/// Relative tolerance for equal eigenvalue moduli (|μ| against λ²).
pub const EIG_TOL: f64 = 1e-8;
/// An eigenfunction whose refined values on the ring are at most this
/// fraction of its vector's largest entry vanishes there.
pub const VANISH_TOL: f64 = 1e-8;
/// Largest relative residual of a quadratic fit that passes the C² test.
pub const C2_TOL: f64 = 1e-6;
pub const DEFAULT_LEVELS: usize = 3;
pub const MAX_LEVELS: usize = 6;
/// Resolution of the characteristic-map check run for the first-order test.
const CHARMAP_RESOLUTION: usize = 256;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CurvatureClass {
    /// |μ| < λ²: the curvature tends to zero at the centre for generic data
    Zero,
    /// |μ| = λ², no Jordan block there
    Bounded,
    /// |μ| > λ², or a Jordan block at λ²
    Unbounded,
    /// the first-order test fails: no characteristic map to measure against
    NotApplicable,
}

impl Evidence {
    pub fn name(self) -> &'static str {
        match self {
            Evidence::Exact => "exact",
            Evidence::FloatingPoint => "floating-point",
            Evidence::None => "none",
        }
    }
}

impl CurvatureClass {
    pub fn name(self) -> &'static str {
        match self {
            CurvatureClass::Zero => "zero",
            CurvatureClass::Bounded => "bounded",
            CurvatureClass::Unbounded => "unbounded",
            CurvatureClass::NotApplicable => "not-applicable",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Evidence {
    // (names as in JSON: exact, floating-point, none)
    /// λ and μ proven rational by the exact path, compared exactly
    Exact,
    /// floating-point eigenvalues compared with the relative tolerance
    FloatingPoint,
    /// no comparison was made (not applicable)
    None,
}

#[derive(Clone, Debug)]
pub struct CurvatureOptions {
    /// analysis steps of refinement of the ring samples (1 to [`MAX_LEVELS`])
    pub levels: usize,
    /// keep samples for the figures (`Curvature::figures`)
    pub figures: bool,
    /// rings of the limit-surface figure (0: not computed; needs `figures`)
    pub surface_rings: usize,
    /// the limit-surface figure's input quadratic; None: the two defaults
    /// ([`Quadratic::defaults`], an elliptic and a hyperbolic one)
    pub input: Option<Quadratic>,
    /// confirm λ and μ in exact arithmetic when both read as small rationals
    /// and S is rational (the `exact` evidence; [`curvature`] only, a given
    /// [`Analysis`] is used as it is)
    pub exact: bool,
}

impl Default for CurvatureOptions {
    fn default() -> Self {
        CurvatureOptions { levels: DEFAULT_LEVELS, figures: false, surface_rings: 0, input: None, exact: true }
    }
}

/// One eigenvalue below λ that was examined.
#[derive(Clone, Debug, Serialize)]
pub struct EigenInfo {
    pub re: f64,
    pub im: f64,
    pub modulus: f64,
    /// modulus / λ²
    pub over_lambda_squared: f64,
    pub algebraic_multiplicity: usize,
    pub geometric_multiplicity: usize,
    pub defective: bool,
    /// Fourier blocks holding it (all, vanishing or not)
    pub blocks: Vec<usize>,
    /// Fourier blocks whose eigenvectors do not vanish on the ring
    pub ring_blocks: Vec<usize>,
    /// exact rational value (exact path), else null
    pub exact: Option<String>,
    /// largest refined value on the ring over the vector's largest entry,
    /// maximised over its eigenvectors (and, when defective, a basis of its
    /// generalised eigenspace)
    pub ring_size: f64,
    /// the eigenfunctions vanish on the characteristic ring (excluded); for
    /// a defective eigenvalue, the generalised eigenfunctions too
    pub vanishes: bool,
    /// for a defective eigenvalue: some vector multiplied by a positive power
    /// of m in S^m (N·w for w in the generalised eigenspace, N = S − νI; for
    /// chains of length 2 the eigenvectors at the top) does not vanish on the
    /// ring, so the chain shows in the surface; null when not defective
    pub jordan_visible: Option<bool>,
    #[serde(skip)]
    index: usize,
}

/// F(μ) and the shapes it allows at the centre.
#[derive(Clone, Debug, Serialize)]
pub struct Shapes {
    /// the Fourier blocks carrying non-vanishing eigenfunctions of modulus |μ|
    pub fourier_index: Vec<usize>,
    /// the rotation group's order (blocks are indices mod it)
    pub group_order: usize,
    /// F(μ) ⊇ {0, 2, n − 2}: necessary for both elliptic and hyperbolic shapes
    pub necessary_condition: bool,
    /// 0 ∈ F(μ): an elliptic (one-signed) central height is possible
    pub elliptic_possible: bool,
    /// {2, n − 2} ⊆ F(μ): an ordinary saddle (frequency 2) is possible
    pub saddle_possible: bool,
    pub explanation: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct QuadraticFit {
    /// the eigenvalue (λ²) and the Fourier block of the eigenvector
    pub eigenvalue: f64,
    pub block: usize,
    /// "re" or "im": which part of the complex eigenvector
    pub part: String,
    /// ‖ψ − fit‖ / ‖ψ‖ over the ring vertices
    pub residual: f64,
    /// coefficients of x², xy, y² (χ not normalised)
    pub coefficients: [f64; 3],
}

/// Reif's C² test.
#[derive(Clone, Debug, Serialize)]
pub struct C2Test {
    /// every condition holds (see the module documentation)
    pub holds: bool,
    /// every eigenfunction of λ² fits a quadratic within the tolerance
    pub quadratic: bool,
    /// the fitted quadratics span all of x², xy, y² (needed for a surface
    /// that can take any curvature at the centre)
    pub spans_quadratics: bool,
    pub tolerance: f64,
    pub max_residual: Option<f64>,
    pub fits: Vec<QuadraticFit>,
    pub reasons: Vec<String>,
}

/// Everything the second-order analysis found. Field names are stable API
/// (`subdlab curvature --json`).
#[derive(Clone, Debug, Serialize)]
pub struct Curvature {
    pub scheme: String,
    pub valence: usize,
    pub params: BTreeMap<String, String>,
    pub faces: String,
    pub class: CurvatureClass,
    pub evidence: Evidence,
    pub tolerance: f64,
    /// Reif's spectral conditions
    pub c1_spectral: bool,
    /// the characteristic map is regular and injective (null when not checked)
    pub charmap_injective: Option<bool>,
    pub lambda: Option<f64>,
    pub lambda_squared: Option<f64>,
    pub mu: Option<EigenInfo>,
    pub mu_over_lambda_squared: Option<f64>,
    /// principal curvatures are L_p-integrable for p < lp_limit; null: for
    /// every finite p (bounded or zero class, or a Jordan block at λ²)
    pub lp_limit: Option<f64>,
    /// every eigenvalue of modulus |μ| is μ = λ² itself (real, positive): the
    /// curvature converges rather than oscillates (bounded class only)
    pub curvature_converges: Option<bool>,
    pub shapes: Option<Shapes>,
    pub c2: Option<C2Test>,
    /// every eigenvalue below λ examined, down to min(|μ|, λ²)
    pub examined: Vec<EigenInfo>,
    pub levels: usize,
    pub ring_vertices: usize,
    pub reasons: Vec<String>,
    #[serde(skip)]
    pub figures: Option<FigureData>,
}

/// Analyse `scheme` at `config` (analysis neighbourhood, exact confirmation
/// on) and run the second-order analysis.
pub fn curvature(scheme: &dyn Scheme, config: &Configuration, opts: &CurvatureOptions) -> Result<Curvature, Error> {
    let options = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse_shared(scheme, config, &options)?;
    let c = curvature_of_analysis(scheme, &analysis, opts)?;
    // the exact path (a characteristic polynomial over Q, about a second for
    // 80 × 80) runs only where it can decide something: λ and μ both read as
    // small rationals
    let eigs = &analysis.spectrum.eigenvalues;
    let rational = |i: usize| eigs.get(i).is_some_and(|e| e.recognised.is_some());
    if opts.exact && c.mu.as_ref().is_some_and(|m| rational(1) && rational(m.index)) {
        let exact = analyse_shared(scheme, config, &Options { exact: true, ..options })?;
        return curvature_of_analysis(scheme, &exact, opts);
    }
    Ok(c)
}

/// The common call for the regular configuration.
pub fn curvature_of(scheme: &dyn Scheme, valence: usize, opts: &CurvatureOptions) -> Result<Curvature, Error> {
    let config = Configuration::regular(scheme, valence)?;
    curvature(scheme, &config, opts)
}

/// The second-order analysis of a finished analysis (analysis neighbourhood).
pub fn curvature_of_analysis(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    opts: &CurvatureOptions,
) -> Result<Curvature, Error> {
    if opts.levels == 0 || opts.levels > MAX_LEVELS {
        return Err(Error::Input(format!("levels must be between 1 and {MAX_LEVELS}, got {}", opts.levels)));
    }
    let spec = &analysis.spectrum;
    if spec.neighbourhood != NeighbourhoodKind::Analysis {
        return Err(Error::Input("the curvature analysis needs the analysis neighbourhood".into()));
    }
    let mut out = Curvature {
        scheme: spec.scheme.clone(),
        valence: spec.valence,
        params: spec.params.clone(),
        faces: spec.faces.clone(),
        class: CurvatureClass::NotApplicable,
        evidence: Evidence::None,
        tolerance: EIG_TOL,
        c1_spectral: spec.verdict.c1_spectral,
        charmap_injective: None,
        lambda: spec.verdict.subdominant,
        lambda_squared: spec.verdict.subdominant.map(|l| l * l),
        mu: None,
        mu_over_lambda_squared: None,
        lp_limit: None,
        curvature_converges: None,
        shapes: None,
        c2: None,
        examined: Vec::new(),
        levels: opts.levels,
        ring_vertices: 0,
        reasons: Vec::new(),
        figures: None,
    };
    // first order: Reif's spectral conditions, then the characteristic map
    let pair = subdominant_pair(spec);
    if !spec.verdict.c1_spectral || pair.status != SpectralStatus::Ok {
        out.reasons.push("not applicable: the first-order (C¹) test fails".into());
        out.reasons.extend(spec.verdict.reasons.iter().filter(|r| !r.starts_with('λ') && !r.starts_with('|')).cloned());
        if !pair.explanation.is_empty() && pair.status != SpectralStatus::Ok {
            out.reasons.push(pair.explanation.clone());
        }
        return Ok(out);
    }
    // the ring samples are the unit rows refined `levels` steps; where the
    // map is checked at that level too, it is read off them (one refinement
    // instead of two). A sampler that cannot be built leaves the map to
    // refine on its own, so its failure is reported as before.
    let map_levels = opts.levels.max(2);
    let sampled = RingSampler::shared(scheme, &analysis.discovered, opts.levels).ok();
    let rows = sampled.as_ref().filter(|_| map_levels == opts.levels).map(|s| &s.net);
    let map = check_map_over(scheme, analysis, &CharMapOptions::checked(map_levels, CHARMAP_RESOLUTION)?, rows)?;
    out.charmap_injective = Some(map.injective);
    if !map.injective {
        out.reasons.push("not applicable: the characteristic map is not regular and injective".into());
        out.reasons.extend(map.reasons.iter().cloned());
        return Ok(out);
    }
    let lambda = pair.lambda;
    let lam2 = lambda * lambda;
    let sampler = RingSampler::shared(scheme, &analysis.discovered, opts.levels)?;
    out.ring_vertices = sampler.ring_vertices.len();

    // eigenvalues below λ, descending, until μ is found and both |μ| and λ²
    // are passed
    let eigs = &spec.eigenvalues;
    let mut mu: Option<usize> = None; // index into out.examined
    for (index, e) in eigs.iter().enumerate().skip(2) {
        if let Some(m) = mu {
            let floor = out.examined[m].modulus.min(lam2) * (1.0 - EIG_TOL);
            if e.modulus < floor {
                break;
            }
        }
        let info = examine(spec, &sampler, e, index, lam2);
        if mu.is_none() && !info.vanishes {
            mu = Some(out.examined.len());
        }
        out.examined.push(info);
    }
    let counted: Vec<&EigenInfo> = out.examined.iter().filter(|i| !i.vanishes).collect();
    let excluded = out.examined.iter().filter(|i| i.vanishes).count();
    if excluded > 0 {
        out.reasons.push(format!(
            "{excluded} eigenvalue(s) below λ excluded: their eigenfunctions vanish on the characteristic ring"
        ));
    }
    let Some(mu_idx) = mu else {
        out.class = CurvatureClass::Zero;
        out.evidence = Evidence::FloatingPoint;
        out.reasons
            .push("every eigenfunction below λ vanishes on the ring: the surface is flat to second order".into());
        out.c2 = Some(c2_test(spec, &sampler, &pair.values, &[], lam2, out.class));
        return Ok(out);
    };
    let m = out.examined[mu_idx].clone();
    out.mu_over_lambda_squared = Some(m.modulus / lam2);
    // |μ| against λ²: exactly when both are proven rational
    let exact_cmp = compare_exact(&eigs[1], &eigs[m.index]);
    let cmp = exact_cmp.unwrap_or_else(|| {
        if (m.modulus - lam2).abs() <= EIG_TOL * lam2 {
            Ordering::Equal
        } else {
            m.modulus.total_cmp(&lam2)
        }
    });
    out.evidence = if exact_cmp.is_some() { Evidence::Exact } else { Evidence::FloatingPoint };
    let at_lam2: Vec<&EigenInfo> =
        counted.iter().copied().filter(|i| (i.modulus - lam2).abs() <= EIG_TOL * lam2).collect();
    match cmp {
        Ordering::Greater => {
            out.class = CurvatureClass::Unbounded;
            let p = 2.0 * lambda.ln() / (2.0 * lambda.ln() - m.modulus.ln());
            out.lp_limit = Some(p);
            out.reasons.push(format!(
                "|μ| = {} > λ² = {}: curvature grows like (|μ|/λ²)^m = {:.6}^m; principal curvatures in L_p for p < {:.6}",
                fmt(m.modulus),
                fmt(lam2),
                m.modulus / lam2,
                p
            ));
        }
        Ordering::Equal => {
            let hidden = at_lam2.iter().filter(|i| i.jordan_visible == Some(false)).count();
            if hidden > 0 {
                out.reasons.push(format!(
                    "{hidden} eigenvalue(s) of modulus λ² are defective, but the tops of their Jordan chains vanish \
                     on the ring: the chains do not show in the surface"
                ));
            }
            if let Some(d) = at_lam2.iter().find(|i| i.jordan_visible == Some(true)) {
                out.class = CurvatureClass::Unbounded;
                out.reasons.push(format!(
                    "|μ| = λ² = {} but the eigenvalue {} is defective (Jordan block): curvature grows like m",
                    fmt(lam2),
                    fmt_c(d.re, d.im)
                ));
            } else {
                out.class = CurvatureClass::Bounded;
                let converges = at_lam2.iter().all(|i| i.im.abs() <= EIG_TOL * lam2 && i.re > 0.0);
                out.curvature_converges = Some(converges);
                out.reasons.push(format!("|μ| = λ² = {}, non-defective: bounded curvature", fmt(lam2)));
                if !converges {
                    out.reasons.push(
                        "an eigenvalue of modulus λ² is not λ² itself: the curvature stays bounded but oscillates from ring to ring"
                            .into(),
                    );
                }
            }
        }
        Ordering::Less => {
            out.class = CurvatureClass::Zero;
            out.reasons.push(format!(
                "|μ| = {} < λ² = {}: curvature tends to zero at the centre (a flat spot for generic data)",
                fmt(m.modulus),
                fmt(lam2)
            ));
        }
    }
    out.reasons.push(match out.evidence {
        Evidence::Exact => format!(
            "λ = {} and μ = {} proven rational; compared exactly",
            eigs[1].exact.as_deref().unwrap_or("?"),
            m.exact.as_deref().unwrap_or("?")
        ),
        _ => format!(
            "floating-point eigenvalues, relative tolerance {EIG_TOL:e}; |μ|/λ² − 1 = {:.3e}",
            m.modulus / lam2 - 1.0
        ),
    });
    out.shapes = shapes(spec, &counted, m.modulus);
    out.c2 = Some(c2_test(spec, &sampler, &pair.values, &counted, lam2, out.class));
    out.mu = Some(m.clone());
    if opts.figures {
        let surface = figure::SurfaceInput {
            analysis,
            pair: &pair.values,
            lambda,
            rings: opts.surface_rings,
            polar: scheme.centre_kind() == crate::sdc::CentreKind::Polar,
        };
        let inputs = opts.input.map_or_else(Quadratic::defaults, |q| vec![q]);
        let mu_vectors: Vec<figure::MuVectors> = spec
            .eigenvalues
            .iter()
            .filter(|e| (e.modulus - m.modulus).abs() <= EIG_TOL * m.modulus.max(1e-300))
            .map(|e| figure::MuVectors {
                value: fmt_c(e.re, e.im),
                blocks: e.blocks.clone(),
                vectors: figure_vectors(spec, &sampler, e),
                tops: figure::chain_tops(spec, e),
            })
            .collect();
        out.figures = Some(figure::figure_data(spec, &sampler, &mu_vectors, VANISH_TOL, &surface, &inputs)?);
    }
    Ok(out)
}

fn fmt(x: f64) -> String {
    crate::spectrum::fmt_f(x)
}

fn fmt_c(re: f64, im: f64) -> String {
    if im == 0.0 {
        fmt(re)
    } else {
        format!("{}{}{}i", fmt(re), if im < 0.0 { '-' } else { '+' }, fmt(im.abs()))
    }
}

/// Each right eigenvector of `e` over the neighbourhood with its block.
fn vectors_with_blocks(spec: &Spectrum, e: &Eigenvalue) -> Vec<(usize, Vec<c64>)> {
    let blocks = e.vectors.iter().flat_map(|v| std::iter::repeat_n(v.block, v.right.len()));
    blocks.zip(spec.right_vectors(e)).collect()
}

fn examine(spec: &Spectrum, sampler: &RingSampler, e: &Eigenvalue, index: usize, lam2: f64) -> EigenInfo {
    let mut ring_size: f64 = 0.0;
    let mut ring_blocks = Vec::new();
    for (block, x) in vectors_with_blocks(spec, e) {
        let scale = x.iter().map(|z| z.norm()).fold(0.0, f64::max);
        if scale == 0.0 {
            continue;
        }
        let on_ring = sampler.ring_values_c(&x).iter().map(|z| z.norm()).fold(0.0, f64::max) / scale;
        ring_size = ring_size.max(on_ring);
        if on_ring > VANISH_TOL {
            ring_blocks.push(block);
        }
    }
    let jordan_visible = e.defective.then(|| {
        // the whole generalised eigenspace: an eigenvalue whose eigenvectors
        // all vanish on the ring still shows through a generalised
        // eigenvector that does not (S^m w2 = ν^m w2 + m ν^(m−1) w1 with w1
        // vanishing leaves ν^m w2 on the ring), and a chain shows when some
        // N·w, w in the generalised eigenspace, does not vanish
        let s = generalised_ring_structure(spec, sampler, e);
        for (block, size) in s.blocks {
            ring_size = ring_size.max(size);
            if size > VANISH_TOL {
                ring_blocks.push(block);
            }
        }
        s.visible
    });
    ring_blocks.sort_unstable();
    ring_blocks.dedup();
    EigenInfo {
        re: e.re,
        im: e.im,
        modulus: e.modulus,
        over_lambda_squared: e.modulus / lam2,
        algebraic_multiplicity: e.algebraic_multiplicity,
        geometric_multiplicity: e.geometric_multiplicity,
        defective: e.defective,
        blocks: e.blocks.clone(),
        ring_blocks,
        exact: e.exact.clone(),
        ring_size,
        vanishes: ring_size <= VANISH_TOL,
        jordan_visible,
        index,
    }
}

/// The vectors the central-ring figure draws for `e`, with their block and a
/// label prefix: the eigenvectors, and for a defective eigenvalue whose
/// eigenvectors of some block all vanish on the ring, a basis of that block's
/// generalised eigenspace (S^m w = ν^m w + m ν^(m−1) N w + ..., so with N w
/// vanishing on the ring the ring shows ν^m w).
pub fn figure_vectors(spec: &Spectrum, sampler: &RingSampler, e: &Eigenvalue) -> Vec<(usize, Vec<c64>, &'static str)> {
    let visible = |x: &[c64]| {
        let scale = x.iter().map(|z| z.norm()).fold(0.0, f64::max);
        scale > 0.0 && jordan::ring_size_c(sampler, x) / scale > VANISH_TOL
    };
    let mut out: Vec<(usize, Vec<c64>, &'static str)> =
        vectors_with_blocks(spec, e).into_iter().map(|(m, x)| (m, x, "")).collect();
    if !e.defective {
        return out;
    }
    let nu = c64::new(e.re, e.im);
    for &m in &e.blocks {
        if out.iter().any(|(b, x, _)| *b == m && visible(x)) {
            continue;
        }
        for w in jordan::generalised_eigenspace(spec.synthesis.block(m), nu, e.algebraic_multiplicity) {
            out.extend(on_neighbourhood(spec, e, m, &w).into_iter().map(|x| (m, x, "generalised, ")));
        }
    }
    out
}

/// A vector of block `m` synthesised over the whole neighbourhood.
fn on_neighbourhood(spec: &Spectrum, e: &Eigenvalue, m: usize, x: &[c64]) -> Vec<Vec<c64>> {
    let probe =
        Eigenvalue { vectors: vec![crate::spectrum::EigenVectors { block: m, right: vec![x.to_vec()] }], ..e.clone() };
    spec.right_vectors(&probe)
}

struct GeneralisedRing {
    /// per block: the largest ring size over its generalised eigenspace
    blocks: Vec<(usize, f64)>,
    /// some Jordan chain has a vector multiplied by a power of m in S^m (N·w)
    /// that does not vanish on the ring
    visible: bool,
}

/// The ring structure of a defective eigenvalue's generalised eigenspace,
/// block by block ([`jordan::ring_structure`]: the chain computed level by
/// level, null(N), then w with N w in it, ...).
fn generalised_ring_structure(spec: &Spectrum, sampler: &RingSampler, e: &Eigenvalue) -> GeneralisedRing {
    let nu = c64::new(e.re, e.im);
    let mut blocks = Vec::new();
    let mut chain: f64 = 0.0;
    let mut tops = 0;
    for &m in &e.blocks {
        let b = spec.synthesis.block(m);
        // a block vector over the neighbourhood, then its ring size
        let ring = |x: &[c64]| -> f64 {
            on_neighbourhood(spec, e, m, x)
                .iter()
                .map(|v| {
                    let scale = v.iter().map(|z| z.norm()).fold(0.0, f64::max);
                    if scale > 0.0 {
                        jordan::ring_size_c(sampler, v) / scale
                    } else {
                        0.0
                    }
                })
                .fold(0.0, f64::max)
        };
        let s = jordan::ring_structure(b, nu, e.algebraic_multiplicity, &ring);
        blocks.push((m, s.space_ring));
        chain = chain.max(s.chain_ring);
        tops += s.tops;
    }
    // the floating-point structure says defective but no chain was found at
    // this tolerance: keep the conservative reading (visible)
    GeneralisedRing { blocks, visible: tops == 0 || chain > VANISH_TOL }
}

fn parse_rational(s: &str) -> Option<Rational> {
    let (p, q) = s.split_once('/').unwrap_or((s, "1"));
    let (p, q) = (p.trim().parse::<BigInt>().ok()?, q.trim().parse::<BigInt>().ok()?);
    (q != BigInt::from(0)).then(|| Rational::new(p, q))
}

/// |μ| against λ² in exact arithmetic, when both are proven rational.
fn compare_exact(lambda: &Eigenvalue, mu: &Eigenvalue) -> Option<Ordering> {
    let l = parse_rational(lambda.exact.as_deref()?)?;
    let m = parse_rational(mu.exact.as_deref()?)?;
    let m = if m < Rational::from_integer(BigInt::from(0)) { -m } else { m };
    Some(m.cmp(&(l.clone() * l)))
}

fn shapes(spec: &Spectrum, counted: &[&EigenInfo], mu_modulus: f64) -> Option<Shapes> {
    let Synthesis::Dft { orbits, .. } = &spec.synthesis else { return None };
    if spec.method != Method::Dft {
        return None;
    }
    let g = orbits.group_order;
    let mut f: Vec<usize> = counted
        .iter()
        .filter(|i| (i.modulus - mu_modulus).abs() <= EIG_TOL * mu_modulus.max(1e-300))
        .flat_map(|i| i.ring_blocks.iter().copied())
        .collect();
    f.sort_unstable();
    f.dedup();
    let has = |m: usize| f.contains(&(m % g));
    let elliptic = has(0);
    let saddle = g > 2 && has(2) && has(g - 2);
    let necessary = elliptic && saddle;
    let mut explanation = format!("F(μ) = {f:?} (blocks mod {g})");
    if g != spec.valence {
        explanation += &format!(
            "; the configuration's rotation group has order {g}, not the valence {}: the condition on {{0, 2, n − 2}} \
             is stated for full rotation symmetry",
            spec.valence
        );
    }
    explanation += if necessary {
        "; F(μ) ⊇ {0, 2, n − 2}: the necessary condition for both elliptic and hyperbolic central shapes holds"
    } else {
        "; F(μ) ⊉ {0, 2, n − 2}: the scheme cannot produce both elliptic and hyperbolic shapes at the centre"
    };
    if !elliptic {
        explanation += "; no block 0: every μ-eigenfunction sums to zero over the n rotated copies of a sector, \
                        so the central height changes sign around the centre (no elliptic shape)";
    }
    if !saddle {
        explanation += "; no blocks 2 and n − 2: no frequency-2 height (no ordinary saddle)";
    }
    Some(Shapes {
        fourier_index: f,
        group_order: g,
        necessary_condition: necessary,
        elliptic_possible: elliptic,
        saddle_possible: saddle,
        explanation,
    })
}

/// Least squares over span{x², xy, y², 1}: (coefficients of x², xy, y²,
/// relative residual).
fn fit_quadratic(chi: &[[f64; 2]], psi: &[f64]) -> Option<([f64; 3], f64)> {
    let m = chi.len();
    let norm = psi.iter().map(|v| v * v).sum::<f64>().sqrt();
    if m < 4 || norm == 0.0 || !norm.is_finite() {
        return None;
    }
    let cols = |p: &[f64; 2]| [p[0] * p[0], p[0] * p[1], p[1] * p[1], 1.0];
    let a = nalgebra::DMatrix::<f64>::from_fn(m, 4, |i, j| cols(&chi[i])[j]);
    // scale the columns for conditioning
    let scale: Vec<f64> = (0..4).map(|j| a.column(j).norm().max(1e-300)).collect();
    let a = nalgebra::DMatrix::<f64>::from_fn(m, 4, |i, j| a[(i, j)] / scale[j]);
    let b = nalgebra::DVector::<f64>::from_column_slice(psi);
    let svd = a.clone().svd(true, true);
    let x = svd.solve(&b, 1e-13).ok()?;
    let r = &b - &a * &x;
    let c = [x[0] / scale[0], x[1] / scale[1], x[2] / scale[2]];
    Some((c, r.norm() / norm))
}

fn c2_test(
    spec: &Spectrum,
    sampler: &RingSampler,
    pair: &[[f64; 2]],
    counted: &[&EigenInfo],
    lam2: f64,
    class: CurvatureClass,
) -> C2Test {
    let mut reasons = Vec::new();
    let mut holds = true;
    match class {
        CurvatureClass::Unbounded => {
            holds = false;
            reasons.push("an eigenfunction between λ² and λ, or a Jordan block at λ², rules out C²".into());
        }
        CurvatureClass::Zero => reasons.push(
            "every eigenfunction below λ is below λ² in modulus: C² only with zero curvature at the centre (a flat spot)"
                .into(),
        ),
        _ => {}
    }
    let at_modulus: Vec<&&EigenInfo> = counted.iter().filter(|i| (i.modulus - lam2).abs() <= EIG_TOL * lam2).collect();
    let at_value: Vec<&&EigenInfo> = at_modulus
        .iter()
        .copied()
        .filter(|i| (c64::new(i.re, i.im) - c64::new(lam2, 0.0)).norm() <= EIG_TOL * lam2)
        .collect();
    if at_value.len() < at_modulus.len() {
        holds = false;
        reasons.push("an eigenvalue of modulus λ² is not λ² itself".into());
    }
    if at_value.iter().any(|i| i.jordan_visible == Some(true)) {
        holds = false;
        reasons.push("λ² has a Jordan chain that shows on the ring".into());
    }
    let chi_x: Vec<f64> = pair.iter().map(|p| p[0]).collect();
    let chi_y: Vec<f64> = pair.iter().map(|p| p[1]).collect();
    let xs = sampler.ring_values(&chi_x);
    let ys = sampler.ring_values(&chi_y);
    let chi: Vec<[f64; 2]> = xs.iter().zip(&ys).map(|(x, y)| [*x, *y]).collect();
    let mut fits = Vec::new();
    let mut quadratic = true;
    for info in &at_value {
        let e = &spec.eigenvalues[info.index];
        for (block, x) in vectors_with_blocks(spec, e) {
            let values = sampler.ring_values_c(&x);
            let scale = values.iter().map(|z| z.norm()).fold(0.0, f64::max);
            for (part, vals) in
                [("re", values.iter().map(|z| z.re).collect::<Vec<_>>()), ("im", values.iter().map(|z| z.im).collect())]
            {
                let size = vals.iter().map(|v| v.abs()).fold(0.0, f64::max);
                if size <= 1e-9 * scale || size <= VANISH_TOL {
                    continue;
                }
                match fit_quadratic(&chi, &vals) {
                    Some((coefficients, residual)) => {
                        quadratic &= residual <= C2_TOL;
                        fits.push(QuadraticFit { eigenvalue: lam2, block, part: part.into(), residual, coefficients });
                    }
                    None => quadratic = false,
                }
            }
        }
    }
    let max_residual = fits.iter().map(|f| f.residual).fold(None, |a: Option<f64>, r| Some(a.map_or(r, |a| a.max(r))));
    // rank of the fitted coefficient vectors
    let spans = if fits.len() >= 3 {
        let m = nalgebra::DMatrix::<f64>::from_fn(fits.len(), 3, |i, j| fits[i].coefficients[j]);
        let sv = m.singular_values();
        let top = sv.iter().cloned().fold(0.0, f64::max);
        sv.iter().filter(|s| **s > 1e-6 * top).count() == 3
    } else {
        false
    };
    if at_value.is_empty() {
        reasons.push("λ² is not an eigenvalue (with an eigenfunction on the ring): no quadratic part".into());
    } else {
        reasons.push(format!(
            "{} eigenfunction(s) of λ² fitted over span{{x², xy, y², 1}} ∘ χ on {} ring vertices: largest relative residual {:.3e} (tolerance {C2_TOL:e})",
            fits.len(),
            chi.len(),
            max_residual.unwrap_or(f64::NAN)
        ));
    }
    holds &= quadratic;
    if !spans {
        reasons.push("the λ²-eigenfunctions do not span all quadratics x², xy, y²".into());
    }
    C2Test { holds, quadratic, spans_quadratics: spans, tolerance: C2_TOL, max_residual, fits, reasons }
}
