//! The shape chart: which quadratic input shapes a scheme reproduces at an
//! extraordinary point, keeps the sign of, turns into the wrong sign, or
//! flattens (`subdlab shape-chart`). Defined here from first principles,
//! after the idea of Karčiauskas, Peters and Reif (a chart that tells a
//! designer early which input shapes a scheme gets wrong); it is not their
//! chart.
//!
//! # Inputs
//!
//! q_{t,θ}(x, y) = (x cos θ + y sin θ)² + t (−x sin θ + y cos θ)²
//! ([`Quadratic`]), t ∈ [−1, 1] (elliptic t > 0, parabolic t = 0,
//! hyperbolic t < 0), sampled as heights over the characteristic map's
//! control net: z_i = q(C_i), C_i the control points of χ (the subdominant
//! eigenvector pair, scaled to unit size). q = u² + t v² with u, v the
//! rotated coordinates, so z = z_a + t z_b is affine in t for fixed θ: two
//! projections per θ serve every t. On a configuration with rotation group
//! Z_g, C is rotation-equivariant (up to an affine map), so z lives in Fourier
//! blocks 0 and ±2 only, and the rotation by 2π/g maps q_{t,θ} to
//! q_{t,θ+2π/g}; q has period π in θ, so θ ∈ [0, min(π, 2π/g)) covers every
//! input without assuming a mirror symmetry ([`theta_range_degrees`]).
//!
//! # Per input
//!
//! The affine part (the projections on λ0 = 1 and on λ, [`project`]) is
//! removed: z' = z − P_1 z − P_λ z. Among the eigenvalues below λ whose
//! component P_ν z' does not vanish on the characteristic ring (ring values
//! at most `curvature::VANISH_TOL` of the input's largest entry vanish),
//! taken in descending modulus, the first is ν*; with a Jordan chain, the
//! highest power N^j P_ν z' (N = S − νI) that still shows on the ring is its
//! top, which S^m multiplies by C(m, j) ν^(m−j). The central shape h_∞ is
//! that top (real part; a complex ν contributes with its conjugate). The
//! finite-step shapes are h_m = S^m z' / λ^(2m), m in [`ChartOptions::steps`].
//! g = |ν*|/λ²: the curvature of the input's limit surface at the centre
//! goes like g^m (times m^j for a chain).
//!
//! # Per cell
//!
//! The fraction of ring area where sign K(h) = sign t and the residual of
//! h ≈ c·q∘χ + affine ([`measure`]), g and the Jordan flag, and a category
//! ([`classify`]: the thresholds are defined there and only there).
//!
//! On a rotation-symmetric configuration only eigenvalues of blocks 0 and
//! ±2 can carry z, so the others are skipped without computing their
//! projectors (exactly: the other blocks' left eigenvectors are orthogonal
//! to z); without symmetry every eigenvalue below λ is tried.

pub mod classify;
pub mod measure;
pub mod project;

use faer::c64;
use serde::Serialize;

use crate::charmap::spectral::{subdominant_pair, SpectralStatus};
use crate::curvature::{Quadratic, RingSampler, EIG_TOL, MAX_LEVELS, VANISH_TOL};
use crate::error::Error;
use crate::neighbourhood::{Configuration, NeighbourhoodKind};
use crate::sdc::{CentreKind, Scheme};
use crate::spectrum::{analyse_shared, Analysis, Method, Options, Synthesis};
pub use classify::Category;
use measure::Ring;
use project::{DenseS, Projector};

/// What the chart samples.
#[derive(Clone, Debug)]
pub struct ChartOptions {
    /// the values of t (each in [−1, 1])
    pub ts: Vec<f64>,
    /// number of angles θ over the fundamental range
    pub thetas: usize,
    /// finite steps m of the shapes h_m (m = ∞ is always added)
    pub steps: Vec<usize>,
    /// analysis steps of refinement of the ring samples (as `curvature --levels`)
    pub levels: usize,
    /// the second route to the central shapes ([`Iterated`]): deflated
    /// iteration to steps (m1, m2), m1 < m2; None: not run
    pub iterated: Option<(usize, usize)>,
}

/// The default t grid: −1 to 1 in steps of 0.1.
pub fn default_ts() -> Vec<f64> {
    (0..=20).map(|k| (k as f64 - 10.0) / 10.0).collect()
}

/// Default finite steps: m = 0 (the input itself), 3 (a middle step), 6.
pub const DEFAULT_STEPS: [usize; 3] = [0, 3, 6];
/// Largest step of the deflated iteration ([`ChartOptions::iterated`]).
pub const MAX_ITERATED: usize = 200;
/// Default number of angles over the fundamental range.
pub const DEFAULT_THETAS: usize = 3;
/// Default analysis steps of refinement of the ring samples: one fewer than
/// `subdlab curvature`'s, since every cell fits a quadratic per ring face
/// (the faces grow with the host's faces per face to the power of the
/// levels: at 3 levels a ternary host's chart of 3..8 takes 50 s, at 2 six);
/// the central shapes' categories agree at 2 and 3 on the seed schemes.
pub const DEFAULT_LEVELS: usize = 2;

impl Default for ChartOptions {
    fn default() -> Self {
        ChartOptions {
            ts: default_ts(),
            thetas: DEFAULT_THETAS,
            steps: DEFAULT_STEPS.to_vec(),
            levels: DEFAULT_LEVELS,
            iterated: None,
        }
    }
}

impl ChartOptions {
    pub fn checked(self) -> Result<ChartOptions, Error> {
        if self.levels == 0 || self.levels > MAX_LEVELS {
            return Err(Error::Input(format!("levels must be between 1 and {MAX_LEVELS}, got {}", self.levels)));
        }
        if self.ts.is_empty() || self.ts.iter().any(|t| !t.is_finite() || !(-1.0..=1.0).contains(t)) {
            return Err(Error::Input("every t must be a number in [-1, 1]".into()));
        }
        if self.thetas == 0 || self.thetas > 360 {
            return Err(Error::Input(format!("the number of angles must be between 1 and 360, got {}", self.thetas)));
        }
        if self.steps.iter().any(|&m| m > 60) {
            return Err(Error::Input("finite steps m must be at most 60".into()));
        }
        if let Some((m1, m2)) = self.iterated {
            if m1 == 0 || m1 >= m2 || m2 > MAX_ITERATED {
                return Err(Error::Input(format!(
                    "the iterated steps must satisfy 0 < m1 < m2 <= {MAX_ITERATED}, got ({m1}, {m2})"
                )));
            }
        }
        Ok(self)
    }
}

/// One cell: input (t, θ) at step m.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    pub n: usize,
    pub faces: String,
    pub t: f64,
    pub theta_degrees: f64,
    /// "0", "3", ... or "inf" (the central shape h_∞)
    pub m: String,
    /// ν*, formatted (null: no component below λ shows on the ring)
    pub nu: Option<String>,
    pub nu_re: Option<f64>,
    pub nu_im: Option<f64>,
    /// |ν*| / λ² (0 when there is no ν*)
    pub g: f64,
    /// ν* has a Jordan chain whose top (not ν*'s component itself) is the
    /// central shape
    pub jordan: bool,
    /// the divergent overlay (`classify::divergent`)
    pub divergent: bool,
    /// fraction of ring area with sign K(h) = sign t
    pub sign_fraction: f64,
    /// relative residual of h ≈ c·q∘χ + affine (0: the input shape)
    pub residual: f64,
    /// the fitted factor c
    pub c: f64,
    pub category: Category,
}

impl Row {
    pub fn central(&self) -> bool {
        self.m == "inf"
    }
}

/// The chart of one configuration.
#[derive(Clone, Debug, Serialize)]
pub struct ValenceChart {
    pub n: usize,
    pub faces: String,
    pub lambda: Option<f64>,
    /// the rotation group's order (1 without symmetry)
    pub group_order: usize,
    /// θ is sampled over [0, theta_range_degrees)
    pub theta_range_degrees: f64,
    pub thetas: Vec<f64>,
    pub rows: Vec<Row>,
    /// the second route's shapes ([`ChartOptions::iterated`]), one per
    /// input (t, θ); empty when not asked for
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub iterated: Vec<Iterated>,
    /// why there is no chart (the first-order test fails, ...)
    pub error: Option<String>,
}

/// The fundamental range of θ for rotation group Z_g: [0, min(180°, 360°/g)).
pub fn theta_range_degrees(group_order: usize) -> f64 {
    (360.0 / group_order.max(1) as f64).min(180.0)
}

/// Analyse `scheme` at `config` (analysis neighbourhood) and chart it.
pub fn chart(scheme: &dyn Scheme, config: &Configuration, opts: &ChartOptions) -> Result<ValenceChart, Error> {
    let options = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse_shared(scheme, config, &options)?;
    chart_of_analysis(scheme, &analysis, opts)
}

/// One eigenvalue entry of the spectrum below λ that can carry the input.
struct Entry {
    nu: c64,
    multiplicity: usize,
    /// 2 for a complex ν whose conjugate is not listed (its contribution
    /// then is 2 Re), else 1
    factor: f64,
    projector: Option<Projector>,
}

/// The chart of a finished analysis (analysis neighbourhood).
pub fn chart_of_analysis(scheme: &dyn Scheme, analysis: &Analysis, opts: &ChartOptions) -> Result<ValenceChart, Error> {
    let opts = opts.clone().checked()?;
    let spec = &analysis.spectrum;
    if spec.neighbourhood != NeighbourhoodKind::Analysis {
        return Err(Error::Input("the shape chart needs the analysis neighbourhood".into()));
    }
    let group_order = match (&spec.synthesis, spec.method) {
        (Synthesis::Dft { orbits, .. }, Method::Dft) => orbits.group_order,
        _ => 1,
    };
    let range = theta_range_degrees(group_order);
    let thetas: Vec<f64> = (0..opts.thetas).map(|k| range * k as f64 / opts.thetas as f64).collect();
    let mut out = ValenceChart {
        n: spec.valence,
        faces: spec.faces.clone(),
        lambda: None,
        group_order,
        theta_range_degrees: range,
        thetas: thetas.clone(),
        rows: Vec::new(),
        iterated: Vec::new(),
        error: None,
    };
    let pair = subdominant_pair(spec);
    if !spec.verdict.c1_spectral || pair.status != SpectralStatus::Ok {
        out.error = Some(format!(
            "not applicable: the first-order (C¹) spectral test fails{}",
            if pair.explanation.is_empty() { String::new() } else { format!(" ({})", pair.explanation) }
        ));
        return Ok(out);
    }
    let lambda = pair.lambda;
    out.lambda = Some(lambda);
    let lam2 = lambda * lambda;
    let r = pair.values.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max).max(1e-300);
    let unit: Vec<[f64; 2]> = pair.values.iter().map(|p| [p[0] / r, p[1] / r]).collect();
    let sampler = RingSampler::shared(scheme, &analysis.discovered, opts.levels)?;
    let ring = Ring::new(&sampler, unit.clone(), scheme.centre_kind() == CentreKind::Polar);
    let dense = DenseS::new(analysis.matrix.to_dense_f64());

    // the affine part: λ0 and λ (every eigenvalue of modulus ≥ λ)
    let eigs = &spec.eigenvalues;
    let conj_listed = |e: &crate::spectrum::Eigenvalue| {
        eigs.iter().any(|f| (f.re - e.re).abs() + (f.im + e.im).abs() <= 1e-9 * e.modulus)
    };
    let mut affine = Vec::new();
    let mut below: Vec<Entry> = Vec::new();
    for e in eigs {
        let factor = if e.im != 0.0 && !conj_listed(e) { 2.0 } else { 1.0 };
        if e.modulus >= lambda * (1.0 - EIG_TOL) {
            affine.push((Projector::new(&dense, e.value(), e.algebraic_multiplicity)?, factor));
            continue;
        }
        // on a symmetric net, z lives in blocks 0 and ±2 only
        let carries = group_order == 1
            || e.blocks.iter().any(|b| {
                [0, 2 % group_order, (group_order - 2 % group_order) % group_order].contains(&(b % group_order))
            });
        if carries {
            below.push(Entry { nu: e.value(), multiplicity: e.algebraic_multiplicity, factor, projector: None });
        }
    }
    below.sort_by(|a, b| b.nu.norm().total_cmp(&a.nu.norm()));
    // groups of equal modulus
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (i, e) in below.iter().enumerate() {
        match groups.last_mut() {
            Some(g) if (below[g[0]].nu.norm() - e.nu.norm()).abs() <= EIG_TOL * e.nu.norm().max(1e-300) => g.push(i),
            _ => groups.push(vec![i]),
        }
    }

    // the projections are applied one after another to the remainder;
    // P_ν P_μ = 0 for ν ≠ μ, so this is z − Σ P_ν z
    let remove_affine = |z: &[f64]| -> Vec<f64> {
        let mut z = z.to_vec();
        for (p, factor) in &affine {
            let pz = p.project(&z);
            for (zi, pi) in z.iter_mut().zip(pz) {
                *zi -= factor * pi.re;
            }
        }
        z
    };

    let fourier = FourierParts::new(&spec.synthesis);
    for &theta in &thetas {
        let (s, c) = theta.to_radians().sin_cos();
        let za: Vec<f64> = unit.iter().map(|p| (p[0] * c + p[1] * s).powi(2)).collect();
        let zb: Vec<f64> = unit.iter().map(|p| (-p[0] * s + p[1] * c).powi(2)).collect();
        let tol = VANISH_TOL * za.iter().zip(&zb).map(|(a, b)| a.abs() + b.abs()).fold(0.0, f64::max);
        let (za, zb) = (remove_affine(&za), remove_affine(&zb));
        // finite steps: S^m z' / λ^(2m), for z_a and z_b
        let last = opts.steps.iter().copied().max().unwrap_or(0);
        let (mut xa, mut xb) = (za.clone(), zb.clone());
        let mut finite: Vec<(usize, Vec<f64>, Vec<f64>)> = Vec::new();
        for m in 0..=last {
            if opts.steps.contains(&m) {
                finite.push((m, xa.clone(), xb.clone()));
            }
            xa = dense.apply(&xa).iter().map(|v| v / lam2).collect();
            xb = dense.apply(&xb).iter().map(|v| v / lam2).collect();
        }
        // the second route: deflated iteration of each Fourier part of the
        // input (blocks 0 and ±2, [`FourierParts`]) on its own, the affine
        // part and anything outside the part's blocks removed after every
        // step: rounding left there would otherwise grow like λ^(-m) or like
        // a larger block's eigenvalue, and swamp h_m at large m
        let iterated: Vec<[Vec<f64>; 4]> = match opts.iterated {
            None => Vec::new(),
            Some((m1, m2)) => {
                let mut x = [fourier.part(&za, 0), fourier.part(&zb, 0), fourier.part(&za, 2), fourier.part(&zb, 2)];
                let mut at = Vec::new();
                for m in 1..=m2 {
                    for (i, v) in x.iter_mut().enumerate() {
                        let next = remove_affine(&dense.apply(v).iter().map(|y| y / lam2).collect::<Vec<_>>());
                        *v = fourier.part(&next, if i < 2 { 0 } else { 2 });
                    }
                    if m == m1 || m == m2 {
                        at.push(x.clone());
                    }
                }
                at
            }
        };
        // the central shape of each t
        let mut central: Vec<Option<Central>> = vec![None; opts.ts.len()];
        let mut components: Vec<Option<(Vec<c64>, Vec<c64>)>> = (0..below.len()).map(|_| None).collect();
        for group in &groups {
            if central.iter().all(Option::is_some) {
                break;
            }
            for &i in group {
                if below[i].projector.is_none() {
                    below[i].projector = Some(Projector::new(&dense, below[i].nu, below[i].multiplicity)?);
                }
                if components[i].is_none() {
                    let p = below[i].projector.as_ref().expect("made above");
                    components[i] = Some((p.project(&za), p.project(&zb)));
                }
            }
            for (k, &t) in opts.ts.iter().enumerate() {
                if central[k].is_some() {
                    continue;
                }
                central[k] = central_shape(&dense, &sampler, &below, &components, group, t, tol);
            }
        }
        for (k, &t) in opts.ts.iter().enumerate() {
            let q = Quadratic { t, theta_degrees: theta };
            let sign = q.sign();
            let cs = central[k].take();
            let (nu, g, jordan) =
                cs.as_ref().map_or((None, 0.0, false), |c| (Some(c.nu), c.nu.norm() / lam2, c.jordan));
            let divergent = classify::divergent(g, jordan);
            let mut row = |m: String, h: Option<&[f64]>| {
                let (sign_fraction, (residual, cfit)) = match h {
                    Some(h) => (ring.sign_fraction(h, sign), ring.residual(h, q)),
                    None => (f64::NAN, (f64::NAN, 0.0)),
                };
                let central = m == "inf";
                let category = if h.is_none() {
                    Category::Flat
                } else {
                    classify::categorise(t, central, g, jordan, sign_fraction, residual)
                };
                out.rows.push(Row {
                    n: spec.valence,
                    faces: spec.faces.clone(),
                    t,
                    theta_degrees: theta,
                    m,
                    nu: nu.map(fmt_c),
                    nu_re: nu.map(|v| v.re),
                    nu_im: nu.map(|v| v.im),
                    g,
                    jordan,
                    divergent,
                    sign_fraction,
                    residual,
                    c: cfit,
                    category,
                });
            };
            for (m, a, b) in &finite {
                let h: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + t * y).collect();
                row(m.to_string(), Some(&h));
            }
            row("inf".into(), cs.as_ref().map(|c| c.shape.as_slice()));
            if let (Some((m1, m2)), [x1, x2]) = (opts.iterated, iterated.as_slice()) {
                // the input's block-±2 part, when it has one (at t = 1 on a
                // symmetric net, x² + y², it has none: only rounding)
                let block2 = fourier
                    .part(&za, 2)
                    .iter()
                    .zip(fourier.part(&zb, 2))
                    .map(|(a, b)| (a + t * b).abs())
                    .fold(0.0, f64::max)
                    > tol;
                let h = |x: &[Vec<f64>; 4]| -> Vec<f64> {
                    (0..x[0].len())
                        .map(|i| x[0][i] + t * x[1][i] + if block2 { x[2][i] + t * x[3][i] } else { 0.0 })
                        .collect()
                };
                let (h1, h2) = (h(x1), h(x2));
                let rate = (ring.curved_size(&h2) / ring.curved_size(&h1)).powf(1.0 / (m2 - m1) as f64);
                let sign_fraction = ring.sign_fraction(&h2, sign);
                let (residual, _) = ring.residual(&h2, q);
                let category = if rate < 1.0 - classify::RATE_TOL {
                    Category::Flat
                } else {
                    classify::categorise(t, false, g, jordan, sign_fraction, residual)
                };
                out.iterated.push(Iterated {
                    t,
                    theta_degrees: theta,
                    steps: (m1, m2),
                    rate,
                    sign_fraction,
                    residual,
                    category,
                });
            }
        }
    }
    Ok(out)
}

/// The parts of a vector in the Fourier blocks ±k of a rotation-symmetric
/// configuration, from the rotation by one sector itself (a permutation of
/// the matrix indices read from the orbits), not from the blocks'
/// eigenvectors: P_±k x = (1/g) Σ_r c_k(r) R^r x with c_k(r) = 2 cos(2πkr/g)
/// (one cos where k ≡ −k). Without symmetry (g = 1) every part is x.
struct FourierParts {
    group_order: usize,
    /// index i goes to rotate[i] under the rotation by one sector
    rotate: Vec<usize>,
}

impl FourierParts {
    fn new(synthesis: &Synthesis) -> FourierParts {
        match synthesis {
            Synthesis::Dft { orbits, .. } => FourierParts::of(orbits),
            _ => FourierParts { group_order: 1, rotate: Vec::new() },
        }
    }

    fn of(orbits: &crate::dft::blocks::Orbits) -> FourierParts {
        let g = orbits.group_order.max(1);
        let mut at = std::collections::HashMap::new();
        for (i, &(o, t)) in orbits.member.iter().enumerate() {
            at.insert((o, t), i);
        }
        let rotate = orbits
            .member
            .iter()
            .enumerate()
            .map(|(i, &(o, t))| if orbits.fixed[o] { i } else { at.get(&(o, (t + 1) % g)).copied().unwrap_or(i) })
            .collect();
        FourierParts { group_order: g, rotate }
    }

    fn part(&self, x: &[f64], k: usize) -> Vec<f64> {
        let g = self.group_order;
        if g == 1 {
            return x.to_vec();
        }
        let k = k % g;
        let single = (2 * k) % g == 0;
        let mut out = vec![0.0; x.len()];
        let mut r_x = x.to_vec();
        for r in 0..g {
            let c = (2.0 * std::f64::consts::PI * (k * r) as f64 / g as f64).cos() * if single { 1.0 } else { 2.0 };
            for (o, v) in out.iter_mut().zip(&r_x) {
                *o += c * v / g as f64;
            }
            let mut next = vec![0.0; x.len()];
            for (i, &j) in self.rotate.iter().enumerate() {
                next[j] = r_x[i];
            }
            r_x = next;
        }
        out
    }
}

/// The second route to one input's central shape: h_m2 of the deflated
/// iteration h_(m+1) = (I − P_affine) S h_m / λ² (no eigenvector of ν*
/// enters), its categories measured as the central shape's are, and the
/// growth rate of its non-affine part, an estimate of g = |ν*|/λ² (a Jordan
/// chain adds the factor (m2/m1)^(j/(m2−m1))). Flat when the rate is below
/// 1 − [`classify::RATE_TOL`].
#[derive(Clone, Debug, Serialize)]
pub struct Iterated {
    pub t: f64,
    pub theta_degrees: f64,
    pub steps: (usize, usize),
    /// (‖h_m2‖ / ‖h_m1‖)^(1/(m2 − m1)), ‖·‖ the size of the ring values
    /// left after the best affine fit
    pub rate: f64,
    pub sign_fraction: f64,
    pub residual: f64,
    pub category: Category,
}

#[derive(Clone)]
struct Central {
    nu: c64,
    jordan: bool,
    shape: Vec<f64>,
}

/// The central shape of z_a + t z_b from one group of equal modulus, or
/// None when no component of the group shows on the ring.
#[allow(clippy::too_many_arguments)]
fn central_shape(
    dense: &DenseS,
    sampler: &RingSampler,
    below: &[Entry],
    components: &[Option<(Vec<c64>, Vec<c64>)>],
    group: &[usize],
    t: f64,
    tol: f64,
) -> Option<Central> {
    let ring_size = |v: &[c64]| sampler.ring_values_c(v).iter().map(|z| z.norm()).fold(0.0, f64::max);
    // per entry: the chain v, N v, N² v, ... and its highest visible power
    let mut best: Option<(usize, f64, usize)> = None; // (j, size, entry)
    let mut chains: Vec<Vec<Vec<c64>>> = Vec::new();
    for (slot, &i) in group.iter().enumerate() {
        let (a, b) = components[i].as_ref().expect("computed for the group");
        let mut v: Vec<c64> = a.iter().zip(b).map(|(x, y)| *x + *y * t).collect();
        let mut chain = Vec::new();
        for j in 0..below[i].multiplicity.max(1) {
            let size = ring_size(&v);
            if size > tol {
                let better = match best {
                    None => true,
                    Some((bj, bs, _)) => j > bj || (j == bj && size > bs),
                };
                if better {
                    best = Some((j, size, slot));
                }
            }
            let next = dense.shifted(below[i].nu, &v);
            chain.push(v);
            if next.iter().all(|z| z.norm() == 0.0) {
                break;
            }
            v = next;
        }
        chains.push(chain);
    }
    let (j, _, slot) = best?;
    let n = dense.size();
    let mut shape = vec![0.0; n];
    for (s, &i) in group.iter().enumerate() {
        if let Some(v) = chains[s].get(j) {
            if ring_size(v) > tol {
                for (h, z) in shape.iter_mut().zip(v) {
                    *h += below[i].factor * z.re;
                }
            }
        }
    }
    Some(Central { nu: below[group[slot]].nu, jordan: j > 0, shape })
}

fn fmt_c(z: c64) -> String {
    let f = crate::spectrum::fmt_f;
    if z.im == 0.0 {
        f(z.re)
    } else {
        format!("{}{}{}i", f(z.re), if z.im < 0.0 { '-' } else { '+' }, f(z.im.abs()))
    }
}

/// The charts of several valences of one scheme (`subdlab shape-chart`).
#[derive(Clone, Debug, Serialize)]
pub struct ShapeChart {
    pub scheme: String,
    pub params: std::collections::BTreeMap<String, String>,
    pub ts: Vec<f64>,
    /// the finite steps m (the rows also hold m = ∞, "inf")
    pub steps: Vec<usize>,
    pub levels: usize,
    pub valences: Vec<ValenceChart>,
    /// the t × θ chart of one valence (more angles), when asked for
    pub theta_chart: Option<ValenceChart>,
}

/// A heat-map cell: the worst category over the angles θ of input t at
/// step `m` ("inf" for the central shape), in the order of [`Category`]
/// (correct < right sign < flat < degenerate < mixed < wrong), and whether
/// any angle is divergent. None when the valence has no rows there.
pub fn worst_over_theta(chart: &ValenceChart, t: f64, m: &str) -> Option<(Category, bool)> {
    chart.rows.iter().filter(|r| r.t == t && r.m == m).fold(None, |acc, r| {
        Some(match acc {
            None => (r.category, r.divergent),
            Some((c, d)) => (c.max(r.category), d || r.divergent),
        })
    })
}

/// The heat map's three panels: the first finite step, the middle one, ∞.
pub fn panels(steps: &[usize]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    if let Some(first) = steps.first() {
        out.push(first.to_string());
    }
    if steps.len() > 1 {
        out.push(steps[steps.len() / 2].to_string());
    }
    out.push("inf".into());
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dft::blocks::Orbits;

    /// A centre fixed by the rotation and one orbit of four points: the
    /// parts of blocks 0, ±1 and 2 add up to x, block 0 is the average over
    /// the rotations, and a rotation-invariant x has no other part.
    #[test]
    fn fourier_parts_split_a_vector() {
        let orbits = Orbits {
            group_order: 4,
            member: vec![(0, 0), (1, 0), (1, 1), (1, 2), (1, 3)],
            representative: vec![0, 1],
            fixed: vec![true, false],
        };
        let f = FourierParts::of(&orbits);
        let x = [5.0, 1.0, 2.0, 4.0, 8.0];
        let (p0, p1, p2) = (f.part(&x, 0), f.part(&x, 1), f.part(&x, 2));
        for i in 0..5 {
            approx::assert_abs_diff_eq!(p0[i] + p1[i] + p2[i], x[i], epsilon = 1e-12);
        }
        approx::assert_abs_diff_eq!(p0[0], 5.0, epsilon = 1e-12);
        for v in &p0[1..] {
            approx::assert_abs_diff_eq!(*v, 15.0 / 4.0, epsilon = 1e-12);
        }
        // block 2 of four points: the alternating pattern (1 − 2 + 4 − 8)/4 · (1, −1, 1, −1)
        approx::assert_abs_diff_eq!(p2[1], -5.0 / 4.0, epsilon = 1e-12);
        approx::assert_abs_diff_eq!(p2[2], 5.0 / 4.0, epsilon = 1e-12);
        let invariant = [1.0, 3.0, 3.0, 3.0, 3.0];
        assert!(f.part(&invariant, 1).iter().chain(&f.part(&invariant, 2)).all(|v| v.abs() < 1e-12));
    }
}
