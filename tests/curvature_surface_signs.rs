//! The limit-surface figure's curvature signs (`curvature::figure`) against
//! an independent evaluation.
//!
//! Catmull–Clark's limit surface over a quad whose 4×4 control net is regular
//! (every corner of valence 4, all neighbours quads) is the uniform bicubic
//! B-spline patch of those 16 points. The sign of its Gaussian curvature at
//! the face centre is the sign of det II = (r_uu·ν)(r_vv·ν) − (r_uv·ν)², ν =
//! r_u × r_v, from the B-spline basis and its derivatives written out here.
//! The figure's sign on every such ring face must agree (z = x² − y² and a
//! rotated hyperbolic quadratic at n = 5, where an angle defect at the quad
//! corners drew a false elliptic lens: issue 25 §2).
//!
//! 4-3's quad rules are the four-direction box spline's, not bicubic (see
//! src/schemes/four_three.rs), so there is no bicubic patch to compare with:
//! at the all-quad valence-4 eon (QQQQ, the regular A_4 lattice) the
//! characteristic map is linear and refining a sampled quadratic reproduces
//! it up to a constant, so the figure's sign must be the input's own sign on
//! every face. (At QQQQQ there is no exact reference here: the ring's map is
//! not linear and the box spline's patches are not written out.)

use std::collections::BTreeMap;

use subdlab::charmap::spectral::subdominant_pair;
use subdlab::curvature::sampler::RingSampler;
use subdlab::curvature::{curvature_of_analysis, CurvatureOptions, Quadratic};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::spectrum::{analyse, Analysis, Options};

const LEVELS: usize = 3;
const RINGS: usize = 3;

fn analysis_of(scheme: &dyn subdlab::schemes::Scheme, config: &Configuration) -> Analysis {
    let options = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    analyse(scheme, config, &options).unwrap()
}

/// The figure's signs, ring by ring, for one input.
fn figure_signs(scheme: &dyn subdlab::schemes::Scheme, analysis: &Analysis, q: Quadratic) -> Vec<Vec<i8>> {
    let opts = CurvatureOptions { levels: LEVELS, figures: true, surface_rings: RINGS, input: Some(q), exact: false };
    let c = curvature_of_analysis(scheme, analysis, &opts).unwrap();
    let figures = c.figures.expect("a figure");
    assert_eq!(figures.surface.len(), 1);
    figures.surface[0].rings.iter().map(|ring| ring.iter().map(|(_, s)| *s).collect()).collect()
}

/// The input net of `q` over the characteristic map and its images under the
/// subdivision matrix (rows of S applied k times), refined to the sampler's
/// net: the 3-D control points of ring k.
fn ring_nets(analysis: &Analysis, sampler: &RingSampler, q: Quadratic) -> Vec<Vec<Option<[f64; 3]>>> {
    let pair = subdominant_pair(&analysis.spectrum).values;
    let mut data: Vec<[f64; 3]> = pair.iter().map(|p| [p[0], p[1], q.eval(p[0], p[1])]).collect();
    let mut out = Vec::new();
    for _ in 0..RINGS {
        out.push(sampler.points(&data));
        data = analysis.matrix.apply_points(&data);
    }
    out
}

/// The 4×4 control net of quad `f` (P[i][j], i along corner 0 → 1, j along
/// corner 0 → 3, the face's corners at i, j ∈ {1, 2}), when every corner has
/// four quads around it and the net closes consistently; else None.
fn regular_net(mesh: &subdlab::mesh::PolyMesh, f: usize) -> Option<[[usize; 4]; 4]> {
    let vf = mesh.vertex_faces();
    let face = mesh.face(f);
    if face.len() != 4 {
        return None;
    }
    for &v in face {
        if vf[v].len() != 4 || vf[v].iter().any(|&g| mesh.face(g).len() != 4) {
            return None;
        }
    }
    // the quad other than `g` with edge a–b: its vertices next to a and to b
    let across = |g: usize, a: usize, b: usize| -> Option<(usize, usize, usize)> {
        let h = *vf[a].iter().find(|&&h| h != g && mesh.face(h).contains(&b))?;
        let q = mesh.face(h);
        if q.len() != 4 {
            return None;
        }
        let ia = q.iter().position(|&x| x == a)?;
        let ib = q.iter().position(|&x| x == b)?;
        // a and b adjacent in h; the vertex after a away from b, and after b away from a
        let step = if (ia + 1) % 4 == ib { 3 } else { 1 };
        Some((h, q[(ia + step) % 4], q[(ib + 4 - step) % 4]))
    };
    let [v0, v1, v2, v3] = [face[0], face[1], face[2], face[3]];
    let (bottom, p10, p20) = across(f, v0, v1)?;
    let (_, p31, p32) = across(f, v1, v2)?;
    let (top, p23, p13) = across(f, v2, v3)?;
    let (_, p02, p01) = across(f, v3, v0)?;
    let (_, c01, p00) = across(bottom, v0, p10)?;
    let (_, c31, p30) = across(bottom, v1, p20)?;
    let (_, c32, p33) = across(top, v2, p23)?;
    let (_, c02, p03) = across(top, v3, p13)?;
    if (c01, c31, c32, c02) != (p01, p31, p32, p02) {
        return None;
    }
    Some([[p00, p01, p02, p03], [p10, v0, v3, p13], [p20, v1, v2, p23], [p30, p31, p32, p33]])
}

/// The sign of the Gaussian curvature of the uniform bicubic B-spline patch
/// of `p` at (u, v) = (1/2, 1/2), with the relative size of det II.
fn bicubic_sign(p: &[[[f64; 3]; 4]; 4]) -> (i8, f64) {
    // B(t), B'(t), B''(t) of the uniform cubic B-spline at t = 1/2:
    // B = [(1−t)³, 3t³ − 6t² + 4, −3t³ + 3t² + 3t + 1, t³] / 6
    let b = [1.0 / 48.0, 23.0 / 48.0, 23.0 / 48.0, 1.0 / 48.0];
    let d1 = [-1.0 / 8.0, -5.0 / 8.0, 5.0 / 8.0, 1.0 / 8.0];
    let d2 = [0.5, -0.5, -0.5, 0.5];
    let sum = |wu: &[f64; 4], wv: &[f64; 4]| {
        let mut r = [0.0; 3];
        for i in 0..4 {
            for j in 0..4 {
                for c in 0..3 {
                    r[c] += wu[i] * wv[j] * p[i][j][c];
                }
            }
        }
        r
    };
    let (ru, rv) = (sum(&d1, &b), sum(&b, &d1));
    let (ruu, ruv, rvv) = (sum(&d2, &b), sum(&d1, &d1), sum(&b, &d2));
    let n = [ru[1] * rv[2] - ru[2] * rv[1], ru[2] * rv[0] - ru[0] * rv[2], ru[0] * rv[1] - ru[1] * rv[0]];
    let dot = |a: [f64; 3]| a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    let (l, m, nn) = (dot(ruu), dot(ruv), dot(rvv));
    let det = l * nn - m * m;
    let size = (l * l + 2.0 * m * m + nn * nn).max(1e-300);
    (if det > 0.0 { 1 } else { -1 }, det.abs() / size)
}

/// Every ring face with a regular 4×4 net: (ring, face index, bicubic sign, relative |det II|).
fn bicubic_signs(
    mesh: &subdlab::mesh::PolyMesh,
    sampler: &RingSampler,
    nets: &[Vec<Option<[f64; 3]>>],
) -> Vec<(usize, usize, i8, f64)> {
    let mut out = Vec::new();
    for (i, &f) in sampler.ring_faces.iter().enumerate() {
        let Some(ids) = regular_net(mesh, f) else { continue };
        for (k, pts) in nets.iter().enumerate() {
            let p: Option<Vec<[f64; 3]>> = ids.iter().flatten().map(|&v| pts[v]).collect();
            let Some(p) = p else { continue };
            let grid: [[[f64; 3]; 4]; 4] = std::array::from_fn(|a| std::array::from_fn(|b| p[4 * a + b]));
            let (s, size) = bicubic_sign(&grid);
            out.push((k, i, s, size));
        }
    }
    out
}

#[test]
fn catmull_clark_n5_signs_match_the_bicubic_patches() {
    let scheme = subdlab::schemes::build("catmull-clark", &[]).unwrap();
    let config = Configuration::regular(scheme.as_ref(), 5).unwrap();
    let analysis = analysis_of(scheme.as_ref(), &config);
    let sampler = RingSampler::new(scheme.as_ref(), &analysis.discovered, LEVELS).unwrap();
    for q in [Quadratic { t: -1.0, theta_degrees: 0.0 }, Quadratic { t: -0.5, theta_degrees: 23.0 }] {
        let figure = figure_signs(scheme.as_ref(), &analysis, q);
        let exact = bicubic_signs(&sampler.net.mesh, &sampler, &ring_nets(&analysis, &sampler, q));
        // most of the ring's faces have a regular net (all but those touching
        // the pruned outer boundary)
        assert!(exact.len() >= RINGS * sampler.ring_faces.len() / 2, "{} regular faces", exact.len());
        let mut counts: BTreeMap<(i8, i8), usize> = BTreeMap::new();
        for &(k, i, s, _) in &exact {
            *counts.entry((s, figure[k][i])).or_default() += 1;
        }
        let wrong: Vec<_> = exact.iter().filter(|(k, i, s, _)| figure[*k][*i] != *s).collect();
        assert!(
            wrong.is_empty(),
            "{}: {} of {} faces disagree ((exact, figure): count {counts:?}); first {:?}",
            q.label(),
            wrong.len(),
            exact.len(),
            wrong.first()
        );
    }
}

#[test]
fn four_three_quad_eons_keep_the_input_sign() {
    let scheme = subdlab::schemes::build("four-three", &[]).unwrap();
    // QQQQ: the regular lattice, the map linear, the quadratic reproduced
    let config = Configuration::with_faces(scheme.as_ref(), 4, "QQQQ").unwrap();
    let analysis = analysis_of(scheme.as_ref(), &config);
    for q in [
        Quadratic { t: 0.5, theta_degrees: 23.0 },
        Quadratic { t: -0.5, theta_degrees: 23.0 },
        Quadratic { t: -1.0, theta_degrees: 0.0 },
    ] {
        let signs = figure_signs(scheme.as_ref(), &analysis, q);
        for ring in &signs {
            assert!(!ring.is_empty() && ring.iter().all(|&s| s == q.sign()), "QQQQ {}: {ring:?}", q.label());
        }
    }
}

/// The central-ring figure marks Jordan chain tops. At 4-3's all-quad eon,
/// block m ≥ 2 of the 1-ring (e, f) is [[1/4, 0], [(1 + ω)/4, 1/4]] with
/// ω = e^{2πim/n} (derived in tests/curvature_jordan.rs): a chain whenever
/// ω ≠ −1, whose top is the pure f-direction; at even n block n/2 has
/// ω = −1 and no chain, and blocks 0 and 1 have none at 1/4 either.
#[test]
fn four_three_central_ring_marks_the_chain_tops() {
    let scheme = subdlab::schemes::build("four-three", &[]).unwrap();
    for faces in ["QQQQQ", "QQQQQQ"] {
        let n = faces.len();
        let config = Configuration::with_faces(scheme.as_ref(), n, faces).unwrap();
        let analysis = analysis_of(scheme.as_ref(), &config);
        let opts = CurvatureOptions { figures: true, exact: false, ..CurvatureOptions::default() };
        let c = curvature_of_analysis(scheme.as_ref(), &analysis, &opts).unwrap();
        let labels: Vec<String> = c.figures.unwrap().mu_functions.into_iter().map(|(l, _)| l).collect();
        let block = |l: &str| -> usize {
            let rest = &l[l.find("block ").expect("a block") + 6..];
            rest[..rest.find(',').unwrap()].parse().unwrap()
        };
        for l in &labels {
            let m = block(l);
            let chain = m >= 2 && 2 * m != n;
            assert_eq!(l.contains("Jordan chain top"), chain, "{faces}: {l}");
        }
        // block 2 is drawn (its conjugate n − 2 is not)
        assert!(labels.iter().any(|l| block(l) == 2), "{faces}: {labels:?}");
    }
}
