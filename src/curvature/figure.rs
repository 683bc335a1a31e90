//! Samples for the second-order figures (`plot::curvature`): the central
//! ring (μ-eigenfunctions over the characteristic ring) and the limit-surface
//! rings of sampled quadratics.
//!
//! # The sign of the Gaussian curvature
//!
//! The input net samples a quadratic z = q(x, y) over the characteristic
//! map's control points (x, y) = χ; it is refined with the scheme's rules
//! (the subdivision matrix k times for ring k, then the ring sampler's
//! `levels` steps). The limit surface is then a graph z(x, y) over the
//! plane of the map, and the sign of its Gaussian curvature is the sign of
//! det Hess z = z_xx z_yy − z_xy². Each ring face gets that sign from a
//! least-squares fit of z over span{1, x, y, x², xy, y²} on the refined
//! control points of the face's neighbourhood (the corners, and face points,
//! of every face sharing a corner with it): sign(4 a b − c²) for the fitted
//! a x² + c xy + b y². The fit keeps the mixed term: an angle defect at the
//! corners of a quad net does not see z_xy, and drew a false elliptic lens
//! for z = x² − y² on Catmull–Clark n = 5 where the exact bicubic patches
//! have K < 0 at every sample (issue 25 §2). For a box spline over a linear
//! map, the refined control values of a quadratic are the quadratic plus a
//! constant, so the fit is exact there; near the centre the map is smooth
//! on each face at the refined scale, and the fit converges to the limit's
//! Hessian as the levels grow.
//!
//! Polar schemes refine along the spokes only: every ring keeps n control
//! points, so at n = 3 a ring is a triangle of control points and a
//! neighbourhood fit sees three directions. Their rings are refined around
//! first: each circle of control points is refined with the periodic
//! uniform quadratic B-spline rule (Chaikin), the angular direction of the
//! polar bi-2 (PolBS) tensor-product biquadratic surface, until it has at
//! least [`POLAR_AROUND`] points; the fit then runs on the (ring, angle)
//! grid.
//!
//! # The inputs
//!
//! z = x² + y² and z = x² − y² are invariant (up to sign) under the rotations
//! by 2π/n of most configurations, so a scheme's own rotation symmetry can
//! hide what a generic quadratic does. The inputs are the rotated quadratics
//! q_{t,θ}(x, y) = (x cos θ + y sin θ)² + t (−x sin θ + y cos θ)² ([`Quadratic`]):
//! by default t = 1/2 (elliptic) and t = −1/2 (hyperbolic) at θ = 23°, which
//! is no multiple of 180°/n for n < 180 (no symmetry angle of a valence-n
//! configuration); `subdlab curvature --input T,THETA` draws one of them.

use std::collections::BTreeSet;

use faer::c64;

// the siblings only: mod.rs calls this file, and hands it what it needs
// from there (the vectors to draw, the vanishing tolerance)
use super::jordan;
use super::sampler::RingSampler;
use crate::error::Error;
use crate::spectrum::{Analysis, Eigenvalue, Spectrum, Synthesis};

/// A polar ring is refined around until it has at least this many points.
pub const POLAR_AROUND: usize = 48;
/// Default angle θ of the inputs, in degrees (no symmetry angle kπ/n for
/// n < 180).
pub const DEFAULT_THETA_DEGREES: f64 = 23.0;

/// q_{t,θ}(x, y) = (x cos θ + y sin θ)² + t (−x sin θ + y cos θ)²: principal
/// curvatures 2 and 2t along the directions θ and θ + 90°; elliptic for
/// t > 0, hyperbolic for t < 0, parabolic for t = 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quadratic {
    pub t: f64,
    /// the angle θ in degrees
    pub theta_degrees: f64,
}

impl Quadratic {
    /// The default inputs: t = 1/2 and t = −1/2 at θ = 23°.
    pub fn defaults() -> Vec<Quadratic> {
        [0.5, -0.5].iter().map(|&t| Quadratic { t, theta_degrees: DEFAULT_THETA_DEGREES }).collect()
    }

    /// Read `T,THETA` (THETA in degrees): T in [−1, 1], both finite.
    pub fn parse(s: &str) -> Result<Quadratic, Error> {
        let bad = |why: &str| {
            Error::Input(format!(
                "--input must be T,THETA (T in [-1, 1], THETA in degrees, e.g. --input -0.5,23): {why}, got '{s}'"
            ))
        };
        let (t, theta) = s.split_once(',').ok_or_else(|| bad("no comma"))?;
        let t: f64 = t.trim().parse().map_err(|_| bad("T is not a number"))?;
        let theta_degrees: f64 = theta.trim().parse().map_err(|_| bad("THETA is not a number"))?;
        if !t.is_finite() || !theta_degrees.is_finite() {
            return Err(bad("T and THETA must be finite"));
        }
        if !(-1.0..=1.0).contains(&t) {
            return Err(bad("T is outside [-1, 1]"));
        }
        Ok(Quadratic { t, theta_degrees })
    }

    pub fn eval(&self, x: f64, y: f64) -> f64 {
        let (s, c) = self.theta_degrees.to_radians().sin_cos();
        let u = x * c + y * s;
        let v = -x * s + y * c;
        u * u + self.t * v * v
    }

    /// The sign of its Gaussian curvature (of t).
    pub fn sign(&self) -> i8 {
        if self.t > 0.0 {
            1
        } else if self.t < 0.0 {
            -1
        } else {
            0
        }
    }

    pub fn label(&self) -> String {
        format!("q(t = {}, θ = {}°)", self.t, self.theta_degrees)
    }
}

/// Samples for the figures (`plot::curvature`).
#[derive(Clone, Debug, Default)]
pub struct FigureData {
    /// ring triangles in the characteristic map's plane
    pub triangles: Vec<[[f64; 2]; 3]>,
    /// μ-eigenfunctions: (label, value at each triangle corner); the label
    /// says "Jordan chain top (× m)" for an eigenvector at the top of a
    /// Jordan chain (S^m w2 = ν^m w2 + m ν^(m−1) w1 puts the factor m on the
    /// top w1) and "block with a Jordan chain" for another eigenvector of a
    /// block that has one ([`chain_tops`])
    pub mu_functions: Vec<(String, Vec<[f64; 3]>)>,
    /// limit-surface rings: one list per input quadratic
    pub surface: Vec<SurfaceRows>,
}

/// The refined rings of one input quadratic.
#[derive(Clone, Debug)]
pub struct SurfaceRows {
    /// the input, "q(t = 0.5, θ = 23°)"
    pub input: String,
    pub quadratic: Quadratic,
    /// ring k: its faces in the plane (normalised by λ^k) with the sign of the
    /// Gaussian curvature of the fitted quadratic (see the module
    /// documentation): +1, −1, or 0 when the fit is degenerate. Except for
    /// polar schemes, face i is the sampler's ring face i
    /// (`RingSampler::ring_faces`); polar rings are refined around first.
    pub rings: Vec<Vec<(Vec<[f64; 2]>, i8)>>,
}

/// What the surface rows need besides the sampler.
pub struct SurfaceInput<'a> {
    pub analysis: &'a Analysis,
    /// the characteristic map's level-0 control points
    pub pair: &'a [[f64; 2]],
    pub lambda: f64,
    pub rings: usize,
    /// the scheme refines along spokes only (`CentreKind::Polar`)
    pub polar: bool,
}

/// The vectors the central-ring figure draws for one eigenvalue of modulus
/// |μ| (from `curvature::figure_vectors`), with what their labels need.
pub struct MuVectors {
    /// the eigenvalue, formatted
    pub value: String,
    pub blocks: Vec<usize>,
    /// (block, vector over the neighbourhood, label prefix)
    pub vectors: Vec<(usize, Vec<c64>, &'static str)>,
    /// [`chain_tops`] of the eigenvectors (the first entries of `vectors`)
    pub tops: Vec<Option<bool>>,
}

/// Samples for the central-ring and limit-surface figures; a function whose
/// refined values on the ring are at most `vanish` times its largest entry
/// is not drawn.
pub(super) fn figure_data(
    spec: &Spectrum,
    sampler: &RingSampler,
    mu: &[MuVectors],
    vanish: f64,
    surface: &SurfaceInput,
    inputs: &[Quadratic],
) -> Result<FigureData, Error> {
    let pts = sampler.points(surface.pair);
    let tris_ids = sampler.ring_triangles();
    let corner = |v: usize| pts[v].unwrap_or([f64::NAN; 2]);
    let triangles: Vec<[[f64; 2]; 3]> = tris_ids.iter().map(|t| [corner(t[0]), corner(t[1]), corner(t[2])]).collect();
    // μ-eigenfunctions: every vector of every non-vanishing eigenvalue of
    // modulus |μ|, real parts (and imaginary parts); where a defective
    // eigenvalue's eigenvectors of a block all vanish on the ring, the
    // generalised eigenvectors of that block, which then carry what the ring
    // shows (see `examine`)
    let mut mu_functions = Vec::new();
    for e in mu {
        for (i, (block, x, kind)) in e.vectors.iter().enumerate() {
            let block = *block;
            // a block m > g/2 whose conjugate block g − m is drawn repeats its functions
            if let Synthesis::Dft { orbits, .. } = &spec.synthesis {
                let g = orbits.group_order;
                if 2 * block > g && e.blocks.contains(&(g - block)) {
                    continue;
                }
            }
            let top = if kind.is_empty() { e.tops.get(i).copied().flatten() } else { None };
            for (part, f) in
                [("re", x.iter().map(|z| z.re).collect::<Vec<f64>>()), ("im", x.iter().map(|z| z.im).collect())]
            {
                if mu_functions.len() >= 6 {
                    break;
                }
                let vals: Vec<Option<f64>> = (0..sampler.net.points.len()).map(|v| sampler.value(v, &f)).collect();
                let size = sampler.ring_vertices.iter().filter_map(|&v| vals[v]).map(f64::abs).fold(0.0, f64::max);
                let scale = f.iter().map(|v| v.abs()).fold(0.0, f64::max);
                if size <= vanish * scale.max(1e-300) {
                    continue;
                }
                let mut label = format!("μ = {}, block {block}, {kind}{part}", e.value);
                match top {
                    Some(true) => label += ", Jordan chain top (× m)",
                    Some(false) => label += ", block with a Jordan chain",
                    None => {}
                }
                let per: Vec<[f64; 3]> = tris_ids
                    .iter()
                    .map(|t| [vals[t[0]].unwrap_or(0.0), vals[t[1]].unwrap_or(0.0), vals[t[2]].unwrap_or(0.0)])
                    .collect();
                mu_functions.push((label, per));
            }
        }
    }
    let surface = if surface.rings > 0 {
        inputs.iter().map(|q| surface_rows(sampler, surface, *q)).collect()
    } else {
        Vec::new()
    };
    Ok(FigureData { triangles, mu_functions, surface })
}

/// For each eigenvector of `e` (in the order of `Spectrum::right_vectors`):
/// None when its block has no Jordan chain, else whether it lies at the top
/// of one, in the span of N·G (N = B − νI on its block B, G the block's
/// generalised eigenspace) within 1e-6 of its norm. (In a block whose
/// eigenspace is larger than its chains' tops, a computed eigenvector can
/// mix a top with a chain-free eigenvector: Some(false).)
pub fn chain_tops(spec: &Spectrum, e: &Eigenvalue) -> Vec<Option<bool>> {
    let count: usize = e.vectors.iter().map(|v| v.right.len()).sum();
    if !e.defective {
        return vec![None; count];
    }
    let nu = c64::new(e.re, e.im);
    let mut out = Vec::with_capacity(count);
    for v in &e.vectors {
        let b = spec.synthesis.block(v.block);
        let k = b.nrows();
        let n = faer::Mat::<c64>::from_fn(k, k, |i, j| if i == j { b[(i, j)] - nu } else { b[(i, j)] });
        let norm = n.norm_l2().max(1e-300);
        let tops: Vec<Vec<c64>> = jordan::generalised_eigenspace(b, nu, e.algebraic_multiplicity)
            .iter()
            .map(|w| (0..k).map(|i| (0..k).fold(c64::new(0.0, 0.0), |a, j| a + n[(i, j)] * w[j])).collect::<Vec<_>>())
            .filter(|t: &Vec<c64>| t.iter().map(|z| z.norm()).fold(0.0, f64::max) > 1e-7 * norm)
            .collect();
        let basis = orthonormal(&tops);
        for x in &v.right {
            let xn = x.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
            // the residual of x after projecting onto span(tops)
            let mut r = x.clone();
            for q in &basis {
                let dot = q.iter().zip(x).fold(c64::new(0.0, 0.0), |a, (qi, xi)| a + qi.conj() * xi);
                for (ri, qi) in r.iter_mut().zip(q) {
                    *ri -= *qi * dot;
                }
            }
            let rn = r.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
            out.push((!basis.is_empty()).then_some(xn > 0.0 && rn <= 1e-6 * xn));
        }
    }
    out
}

/// Gram–Schmidt (twice), dropping dependent vectors.
fn orthonormal(vs: &[Vec<c64>]) -> Vec<Vec<c64>> {
    let mut basis: Vec<Vec<c64>> = Vec::new();
    for v in vs {
        let vn = v.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
        let mut r = v.clone();
        for _ in 0..2 {
            for q in &basis {
                let dot = q.iter().zip(&r).fold(c64::new(0.0, 0.0), |a, (qi, ri)| a + qi.conj() * ri);
                for (ri, qi) in r.iter_mut().zip(q) {
                    *ri -= *qi * dot;
                }
            }
        }
        let rn = r.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
        if rn > 1e-8 * vn {
            basis.push(r.iter().map(|z| *z / rn).collect());
        }
    }
    basis
}

/// The level-0 input net of `q` over the characteristic map (normalised to
/// unit size) and its images under the subdivision matrix: entry k is the
/// net of ring k, its plane coordinates divided by λ^k.
pub fn surface_nets(
    analysis: &Analysis,
    pair: &[[f64; 2]],
    lambda: f64,
    rings: usize,
    q: Quadratic,
) -> Vec<Vec<[f64; 3]>> {
    let s = &*analysis.matrix;
    let r = pair.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max).max(1e-300);
    let mut data: Vec<[f64; 3]> = pair.iter().map(|p| [p[0] / r, p[1] / r, q.eval(p[0] / r, p[1] / r)]).collect();
    let mut out = Vec::with_capacity(rings);
    let mut scale = 1.0;
    for _ in 0..rings {
        out.push(data.iter().map(|p| [p[0] / scale, p[1] / scale, p[2]]).collect());
        data = s.apply_points(&data);
        scale *= lambda;
    }
    out
}

fn surface_rows(sampler: &RingSampler, input: &SurfaceInput, q: Quadratic) -> SurfaceRows {
    let rings = surface_nets(input.analysis, input.pair, input.lambda, input.rings, q)
        .iter()
        .map(|data| {
            // heights rescaled to unit size: the sign of the Gaussian
            // curvature of a graph does not change
            let zmax = data.iter().map(|p| p[2].abs()).fold(0.0, f64::max).max(1e-300);
            let norm: Vec<[f64; 3]> = data.iter().map(|p| [p[0], p[1], p[2] / zmax]).collect();
            face_signs(sampler, &sampler.points(&norm), input.polar)
        })
        .collect();
    SurfaceRows { input: q.label(), quadratic: q, rings }
}

/// The ring faces of refined points (x, y, z) in the plane, each with the
/// sign of the Gaussian curvature of the graph z(x, y) from the fitted
/// quadratic ([`fitted_sign`], see the module documentation); polar nets
/// (`polar`) refined around first. The shape chart (`shape_chart::measure`)
/// reads its sign fractions from here too.
pub fn face_signs(sampler: &RingSampler, pts: &[Option<[f64; 3]>], polar: bool) -> Vec<(Vec<[f64; 2]>, i8)> {
    if polar {
        polar_ring_signs(sampler, pts).unwrap_or_else(|| ring_signs(sampler, pts))
    } else {
        ring_signs(sampler, pts)
    }
}

/// The sign of det Hess of the least-squares quadratic z ≈ 1, x, y, x², xy,
/// y² through `points` (0 when fewer than 6 points, rank-deficient, or the
/// determinant is at rounding level).
pub fn fitted_sign(points: &[[f64; 3]]) -> i8 {
    let xy: Vec<[f64; 2]> = points.iter().map(|p| [p[0], p[1]]).collect();
    let z: Vec<f64> = points.iter().map(|p| p[2]).collect();
    QuadraticFit::new(&xy).sign(&z)
}

/// The least-squares fit z ≈ 1, x, y, x², xy, y² over fixed plane points,
/// prepared once: the SVD of the design matrix depends on the points only,
/// so the shape chart, which fits dozens of heights over one characteristic
/// ring, factors each face's matrix once and solves per height.
pub struct QuadraticFit {
    /// None: fewer than 6 points, all at one place, or rank-deficient (the
    /// fit then reads no sign)
    svd: Option<nalgebra::SVD<f64, nalgebra::Dyn, nalgebra::Dyn>>,
}

impl QuadraticFit {
    pub fn new(xy: &[[f64; 2]]) -> QuadraticFit {
        let m = xy.len();
        if m < 6 {
            return QuadraticFit { svd: None };
        }
        // centred and scaled for conditioning: the Hessian's sign is unchanged
        let c = xy.iter().fold([0.0; 2], |a, p| [a[0] + p[0] / m as f64, a[1] + p[1] / m as f64]);
        let h = xy.iter().map(|p| (p[0] - c[0]).hypot(p[1] - c[1])).fold(0.0, f64::max);
        if h.is_nan() || h <= 0.0 {
            return QuadraticFit { svd: None };
        }
        let uv = |p: &[f64; 2]| [(p[0] - c[0]) / h, (p[1] - c[1]) / h];
        let a = nalgebra::DMatrix::<f64>::from_fn(m, 6, |i, j| {
            let [u, v] = uv(&xy[i]);
            [1.0, u, v, u * u, u * v, v * v][j]
        });
        let svd = a.svd(true, true);
        let top = svd.singular_values.iter().cloned().fold(0.0, f64::max);
        let full_rank = !svd.singular_values.iter().any(|s| *s <= 1e-10 * top);
        QuadraticFit { svd: full_rank.then_some(svd) }
    }

    /// The sign of det Hess of the fit to heights `z` (one per point, in the
    /// points' order); 0 where the fit reads none.
    pub fn sign(&self, z: &[f64]) -> i8 {
        let Some(svd) = &self.svd else { return 0 };
        let b = nalgebra::DVector::<f64>::from_column_slice(z);
        let Ok(x) = svd.solve(&b, 0.0) else { return 0 };
        let (p, r, s) = (x[3], x[4], x[5]);
        let det = 4.0 * p * s - r * r;
        if !det.is_finite() || det.abs() <= 1e-10 * (p * p + r * r + s * s).max(1e-300) {
            0
        } else if det > 0.0 {
            1
        } else {
            -1
        }
    }
}

/// The sampler's ring faces in the plane with the fitted sign of each
/// (the neighbourhood: every face sharing a corner, its corners and face point).
fn ring_signs(sampler: &RingSampler, pts: &[Option<[f64; 3]>]) -> Vec<(Vec<[f64; 2]>, i8)> {
    let xy: Vec<Option<[f64; 2]>> = pts.iter().map(|p| p.map(|p| [p[0], p[1]])).collect();
    let z: Vec<f64> = pts.iter().map(|p| p.map_or(f64::NAN, |p| p[2])).collect();
    let fits = RingFits::new(sampler, &xy);
    fits.faces.iter().map(|f| (f.poly.clone(), f.sign(&z))).collect()
}

/// The fits of every ring face of a sampler over one plane map (the refined
/// points' x, y), prepared for many heights over the same map
/// ([`QuadraticFit`]). Non-polar nets only: a polar net's faces come from
/// circles refined around per height ([`face_signs`]).
pub struct RingFits {
    pub faces: Vec<FaceFit>,
}

/// One ring face: its polygon in the plane, the net vertices its fit reads
/// (the defined corners and face points of every face sharing a corner with
/// it) and the prepared fit over their plane positions.
pub struct FaceFit {
    pub poly: Vec<[f64; 2]>,
    sample: Vec<usize>,
    fit: QuadraticFit,
}

impl FaceFit {
    /// The fitted sign for heights `z` over the net's vertices.
    pub fn sign(&self, z: &[f64]) -> i8 {
        let heights: Vec<f64> = self.sample.iter().map(|&v| z[v]).collect();
        self.fit.sign(&heights)
    }
}

impl RingFits {
    /// `xy`: the refined points in the plane, None where undefined.
    pub fn new(sampler: &RingSampler, xy: &[Option<[f64; 2]>]) -> RingFits {
        let mesh = &sampler.net.mesh;
        let vf = mesh.vertex_faces();
        let faces = sampler
            .ring_faces
            .iter()
            .map(|&f| {
                let face = mesh.face(f);
                let poly: Vec<[f64; 2]> = face.iter().map(|&v| xy[v].unwrap_or([f64::NAN; 2])).collect();
                let mut near = BTreeSet::new();
                for &v in face {
                    for &g in &vf[v] {
                        near.extend(mesh.face(g).iter().copied().chain(mesh.face_point(g)));
                    }
                }
                near.extend(mesh.face_point(f));
                let sample: Vec<usize> = near.into_iter().filter(|&v| xy[v].is_some()).collect();
                let plane: Vec<[f64; 2]> = sample.iter().filter_map(|&v| xy[v]).collect();
                FaceFit { poly, fit: QuadraticFit::new(&plane), sample }
            })
            .collect();
        RingFits { faces }
    }
}

/// A polar net's (ring, spoke) grid: `grid[r][j]` the vertex on ring r of
/// spoke j (ring 0: the pole), spokes in the pole's fan order.
fn polar_grid(sampler: &RingSampler) -> Option<Vec<Vec<usize>>> {
    let mesh = &sampler.net.mesh;
    let vf = mesh.vertex_faces();
    let pole = (0..mesh.num_vertices()).find(|&v| {
        !vf[v].is_empty() && vf[v].iter().all(|&f| mesh.face(f).len() == 3) && mesh.fan_corners(v).is_some()
    })?;
    // neighbours of each vertex
    let mut nb: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); mesh.num_vertices()];
    for f in 0..mesh.num_faces() {
        let face = mesh.face(f);
        for k in 0..face.len() {
            let (a, b) = (face[k], face[(k + 1) % face.len()]);
            nb[a].insert(b);
            nb[b].insert(a);
        }
    }
    // ring index: distance from the pole
    let mut dist = vec![usize::MAX; mesh.num_vertices()];
    dist[pole] = 0;
    let mut queue = std::collections::VecDeque::from([pole]);
    while let Some(v) = queue.pop_front() {
        for &u in &nb[v] {
            if dist[u] == usize::MAX {
                dist[u] = dist[v] + 1;
                queue.push_back(u);
            }
        }
    }
    // spokes in fan order: the corner after the pole in each fan triangle
    let fan = mesh.fan_corners(pole)?;
    let first: Vec<usize> = fan
        .iter()
        .map(|&(f, k)| {
            let face = mesh.face(f);
            face[(k + 1) % face.len()]
        })
        .collect();
    let mut grid = vec![vec![pole; first.len()], first];
    loop {
        let last = grid.last().expect("two rings");
        let next: Option<Vec<usize>> = last
            .iter()
            .map(|&v| {
                let out: Vec<usize> = nb[v].iter().copied().filter(|&u| dist[u] == dist[v] + 1).collect();
                (out.len() == 1).then(|| out[0])
            })
            .collect();
        match next {
            Some(ring) => grid.push(ring),
            None => break,
        }
    }
    Some(grid)
}

/// One step of the periodic uniform quadratic B-spline rule (Chaikin) on a
/// closed polygon: point 2j = ¾ p_j + ¼ p_(j+1), 2j + 1 = ¼ p_j + ¾ p_(j+1).
fn chaikin_closed(p: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let n = p.len();
    let mix = |a: &[f64; 3], b: &[f64; 3], s: f64| [0, 1, 2].map(|c| (1.0 - s) * a[c] + s * b[c]);
    (0..n).flat_map(|j| [mix(&p[j], &p[(j + 1) % n], 0.25), mix(&p[j], &p[(j + 1) % n], 0.75)]).collect()
}

/// Polar rings refined around (see the module documentation), each ring face
/// split into 2^a angular pieces with the fitted sign on the (ring, angle)
/// grid. None when the net is not a polar grid.
fn polar_ring_signs(sampler: &RingSampler, pts: &[Option<[f64; 3]>]) -> Option<Vec<(Vec<[f64; 2]>, i8)>> {
    let grid = polar_grid(sampler)?;
    let n = grid[0].len();
    let mut a = 0;
    while n << a < POLAR_AROUND {
        a += 1;
    }
    let per = 1usize << a;
    let total = n * per;
    // the refined circles (None where a control point is undefined); ring 0
    // is the pole, repeated
    let circles: Vec<Option<Vec<[f64; 3]>>> = grid
        .iter()
        .enumerate()
        .map(|(r, ring)| {
            let p: Option<Vec<[f64; 3]>> = ring.iter().map(|&v| pts[v]).collect();
            let p = p?;
            if r == 0 {
                return Some(vec![p[0]; total]);
            }
            let mut c = p;
            for _ in 0..a {
                c = chaikin_closed(&c);
            }
            Some(c)
        })
        .collect();
    let mesh = &sampler.net.mesh;
    let mut where_: std::collections::BTreeMap<usize, (usize, usize)> = Default::default();
    for (r, ring) in grid.iter().enumerate().skip(1) {
        for (j, &v) in ring.iter().enumerate() {
            where_.insert(v, (r, j));
        }
    }
    let mut out = Vec::new();
    for &f in &sampler.ring_faces {
        let face = mesh.face(f);
        let at: Option<Vec<(usize, usize)>> = face.iter().map(|v| where_.get(v).copied()).collect();
        let at = at?;
        let r = at.iter().map(|p| p.0).min()?;
        // the spoke j with j and j + 1 (mod n) both at ring r
        let js: BTreeSet<usize> = at.iter().filter(|p| p.0 == r).map(|p| p.1).collect();
        let j = *js.iter().find(|&&j| js.contains(&((j + 1) % n)))?;
        let (inner, outer) = (circles[r].as_ref()?, circles.get(r + 1)?.as_ref()?);
        // piece k spans angles k .. k + 1 of the refined circle; the pieces
        // of spokes j .. j + 1 start half a face before 2^a j (Chaikin's
        // points are shifted by (2^a − 1)/2 refined steps)
        for i in 0..per {
            let k = (j * per + total + i - per / 2) % total;
            let k1 = (k + 1) % total;
            let poly = [inner[k], inner[k1], outer[k1], outer[k]].iter().map(|p| [p[0], p[1]]).collect();
            let mut sample = Vec::new();
            for rr in r.saturating_sub(1)..=r + 2 {
                let Some(Some(c)) = circles.get(rr) else { continue };
                if rr == 0 {
                    sample.push(c[0]);
                    continue;
                }
                for dk in 0..4 {
                    sample.push(c[(k + total + dk - 1) % total]);
                }
            }
            out.push((poly, fitted_sign(&sample)));
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// z = q_{t,θ} sampled on a scattered patch: the fitted Hessian is q's own
    /// (2·rotation of diag(1, t)), so the sign is t's, at any θ, also with a
    /// linear part and a constant added.
    #[test]
    fn fitted_sign_is_the_quadratics() {
        for t in [0.5, -0.5, 0.1, -1.0, 1.0] {
            for theta in [0.0, 23.0, 45.0, 100.0] {
                let q = Quadratic { t, theta_degrees: theta };
                let pts: Vec<[f64; 3]> = (0..16)
                    .map(|i| {
                        let (x, y) = (0.3 + 0.1 * (i % 4) as f64 + 0.01 * i as f64, -0.2 + 0.1 * (i / 4) as f64);
                        [x, y, q.eval(x, y) + 0.7 * x - 0.2 * y + 3.0]
                    })
                    .collect();
                assert_eq!(fitted_sign(&pts), q.sign(), "t = {t}, θ = {theta}");
            }
        }
        // too few points, or all on a line: no sign
        assert_eq!(fitted_sign(&[[0.0; 3]; 5]), 0);
        let line: Vec<[f64; 3]> = (0..8).map(|i| [i as f64, 2.0 * i as f64, (i * i) as f64]).collect();
        assert_eq!(fitted_sign(&line), 0);
    }

    /// q_{t,θ}: value 1 one unit along θ, t one unit along θ + 90°.
    #[test]
    fn quadratic_directions_and_parse() {
        let q = Quadratic { t: -0.5, theta_degrees: 30.0 };
        let (s, c) = 30f64.to_radians().sin_cos();
        assert!((q.eval(c, s) - 1.0).abs() < 1e-15);
        assert!((q.eval(-s, c) + 0.5).abs() < 1e-15);
        assert_eq!(Quadratic::parse(" -0.5 , 30 ").unwrap(), q);
        for bad in ["1.01,0", "-2,0", "nan,0", "0,inf", "0", "x,1", ""] {
            assert!(Quadratic::parse(bad).is_err(), "{bad}");
        }
        assert!(Quadratic::defaults().iter().map(|q| q.sign()).eq([1, -1]));
    }

    /// Chaikin on a closed polygon keeps the centroid (each point's weights
    /// ¾ + ¼ sum to one over the two new points it enters) and doubles it.
    #[test]
    fn chaikin_closed_keeps_the_centroid() {
        let p = [[0.0, 0.0, 1.0], [1.0, 0.0, 2.0], [0.0, 1.0, 0.0]];
        let c = chaikin_closed(&p);
        assert_eq!(c.len(), 6);
        assert_eq!(c[0], [0.25, 0.0, 1.25]);
        assert_eq!(c[5], [0.0, 0.25, 0.75]);
        let mean = |v: &[[f64; 3]]| [0, 1, 2].map(|k| v.iter().map(|x| x[k]).sum::<f64>() / v.len() as f64);
        let (a, b) = (mean(&p), mean(&c));
        assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-15));
    }
}
