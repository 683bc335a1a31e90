//! Characteristic maps: exact rings of regular (polynomial) cases, synthetic
//! folds and windings, the papers' C¹ claims, and the spectra that admit no
//! characteristic map or an obviously wrong one.

use std::f64::consts::PI;

use subdlab::charmap::{characteristic_map_of, net, raster, regularity, ring, wedge, CharMapOptions, SpectralStatus};
use subdlab::mesh::{PolyMesh, SectorKind};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::refine::{GatherError, Origin, RuleResult, Stencil};
use subdlab::schemes::{self, Caps, CentreKind, MeshDomain, Params, Rules, Scheme, SchemeInfo, SchemeWeight};
use subdlab::sdc::Topology;
use subdlab::spectrum::{analyse, Options};

fn opts(levels: usize, resolution: usize) -> CharMapOptions {
    CharMapOptions { levels, resolution, display_levels: None }
}

fn check(name: &str, valences: std::ops::RangeInclusive<usize>, levels: usize) {
    let s = schemes::build(name, &[]).unwrap();
    for n in valences {
        let m = characteristic_map_of(s.as_ref(), n, &opts(levels, 256)).unwrap();
        assert_eq!(m.spectral_status, SpectralStatus::Ok, "{name} n={n}: {}", m.explanation);
        assert!(m.regular, "{name} n={n} not regular: {:?}", m.reasons);
        assert!(m.injective, "{name} n={n} not injective: {:?}", m.reasons);
        assert_eq!(m.winding_number, Some(1), "{name} n={n}");
        assert_eq!(m.overlap_pixels, Some(0), "{name} n={n}");
        assert!(m.min_jacobian_ratio.unwrap() > 0.0);
    }
}

#[test]
fn catmull_clark_regular_and_injective_for_valences_3_to_50() {
    check("catmull-clark", 3..=50, 3);
}

#[test]
fn loop_regular_and_injective_for_valences_3_to_50() {
    check("loop", 3..=50, 3);
}

#[test]
fn doo_sabin_regular_and_injective() {
    // Peters–Reif: Doo–Sabin is C1 at every valence
    check("doo-sabin", 3..=24, 3);
}

#[test]
fn non_box_regular_and_injective_with_the_papers_weights() {
    // Huang: C1 for all k >= 3 with a_3 = 3/4, a_k = 3/4 - (1/2 + cos(2pi/k)/4)^2
    check("non-box", 3..=24, 3);
}

#[test]
fn sqrt3_regular_and_injective() {
    // Kobbelt: the sqrt(3) scheme is C1 at every valence (whole analysis
    // steps of two refinements each)
    check("sqrt3", 3..=20, 2);
}

/// Lattice position of a label of the regular quad configuration: sector s is
/// the quadrant turned by s quarter turns; `scale` is the chart's (2 where face
/// control vertices sit at odd points).
fn quad_lattice(label: &subdlab::neighbourhood::VertexLabel, scale: f64) -> [f64; 2] {
    let (mut x, mut y) = (label.i as f64 / scale, label.j as f64 / scale);
    for _ in 0..label.sector {
        (x, y) = (-y, x);
    }
    [x, y]
}

/// The net x = i, y = j of the regular quad grid, refined, for a scheme that
/// reproduces linear functions.
fn linear_quad_ring(name: &str, levels: usize, moved: Option<([i64; 3], [f64; 2])>) -> ring::Ring {
    let s = schemes::build(name, &[]).unwrap();
    let config = Configuration::regular(s.as_ref(), 4).unwrap();
    let a = analyse(
        s.as_ref(),
        &config,
        &Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false },
    )
    .unwrap();
    let d = &a.discovered;
    let scale = d.patch.chart.as_ref().unwrap().scale as f64;
    let values: Vec<[f64; 2]> = d
        .analysis
        .iter()
        .map(|&v| {
            let l = &d.labels[v];
            match moved {
                Some(([s, i, j], to)) if l.sector == s as usize && l.i == i && l.j == j => to,
                _ => quad_lattice(l, scale),
            }
        })
        .collect();
    let pts = net::initial_points(d, &values).unwrap();
    let refined = net::refine_net(s.as_ref(), d, pts, levels).unwrap();
    ring::extract(&refined)
}

#[test]
fn bicubic_ring_of_the_square_grid_has_area_three() {
    // Catmull–Clark at valence 4 is the bicubic B-spline, which reproduces
    // linear functions: the map of the net (i, j) is the identity on the four
    // quads [-1, 1]^2 around the centre, and one step later on [-1/2, 1/2]^2.
    // The ring is the square annulus between them: area 4 - 1 = 3, inside 1.
    for name in ["catmull-clark", "non-box"] {
        let r = linear_quad_ring(name, 3, None);
        let ring_area = regularity::total_signed_area(&r.ring);
        let inner_area = regularity::total_signed_area(&r.inner);
        assert!((ring_area - 3.0).abs() < 1e-12, "{name}: ring area {ring_area}");
        assert!((inner_area - 1.0).abs() < 1e-12, "{name}: inside {inner_area}");
        let reg = regularity::regularity(&r.ring);
        assert!(reg.regular);
        // a uniform grid: every facet of one kind has the same area
        assert!((reg.min_jacobian_ratio - 1.0).abs() < 1e-9, "{name}: {}", reg.min_jacobian_ratio);
        // outer boundary: the square's perimeter 8, once around; inner 4
        let len = |e: &[[[f64; 2]; 2]]| e.iter().map(|[a, b]| (b[0] - a[0]).hypot(b[1] - a[1])).sum::<f64>();
        assert!((len(&r.outer_boundary) - 8.0).abs() < 1e-12);
        assert!((len(&r.inner_boundary) - 4.0).abs() < 1e-12);
        assert!((ring::winding_number(&r.outer_boundary).unwrap() - 1.0).abs() < 1e-12);
        // rasterised: the pixel count times the pixel area is the area, up to
        // the pixels the boundary cuts (perimeter 12 over the pixel size)
        let (cov, _) = raster::rasterise_ring(&r.ring, &r.inner, 400).unwrap();
        let px = cov.pixel_size;
        let boundary_pixels = 12.0 / px;
        assert!(((cov.ring_pixels as f64) * px * px - 3.0).abs() < boundary_pixels * px * px);
        assert_eq!(cov.overlap_pixels, 0);
        assert_eq!(cov.copy_overlap_pixels, 0);
    }
}

#[test]
fn a_control_point_dragged_across_the_centre_folds_the_ring() {
    // moving the diagonal control point (1, 1) of sector 0 to (-100, -100):
    // the map is the identity plus -101·(1, 1)·B(u, v) with B that point's
    // bicubic basis function, whose Jacobian 1 - 101·(B_u + B_v) is negative
    // wherever B grows towards the point by more than 1/101 per unit, which
    // includes the ring's facets next to the point.
    let r = linear_quad_ring("catmull-clark", 3, Some(([0, 1, 1], [-100.0, -100.0])));
    let reg = regularity::regularity(&r.ring);
    assert!(!reg.regular);
    assert!(reg.folded_facets > 0);
    assert!(reg.min_jacobian_ratio < 0.0);
    let (cov, _) = raster::rasterise_ring(&r.ring, &r.inner, 256).unwrap();
    assert!(cov.overlap_pixels > 0, "a fold covers some pixels more than once");
}

#[test]
fn winding_numbers_of_known_polygons() {
    let circle = |turns: usize, k: usize, centre: [f64; 2], r: f64, ccw: bool| -> Vec<[[f64; 2]; 2]> {
        let total = turns * k;
        let p = |t: usize| {
            let a = 2.0 * PI * t as f64 / k as f64 * if ccw { 1.0 } else { -1.0 };
            [centre[0] + r * a.cos(), centre[1] + r * a.sin()]
        };
        (0..total).map(|t| [p(t), p(t + 1)]).collect()
    };
    // z -> z^2 on a circle: the image circle is traversed twice
    assert!((ring::winding_number(&circle(2, 24, [0.0, 0.0], 1.0, true)).unwrap() - 2.0).abs() < 1e-12);
    assert!((ring::winding_number(&circle(1, 5, [0.0, 0.0], 1.0, false)).unwrap() + 1.0).abs() < 1e-12);
    // a loop that does not enclose the centre
    assert!(ring::winding_number(&circle(1, 12, [3.0, 0.0], 1.0, true)).unwrap().abs() < 1e-12);
    // an edge through the centre has no winding number
    assert!(ring::winding_number(&[[[-1.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [-1.0, 0.0]]]).is_none());
}

#[test]
fn rasterising_two_triangles_of_a_square_counts_each_pixel_once() {
    // the unit square as two triangles sharing the diagonal; at resolution 18
    // the window is [-1/16, 17/16]^2 with pixels of side 1/16, so the pixel
    // centres (2k - 1)/32 lie exactly on the diagonal for 16 of the pixels
    // inside: the shared-edge rule must count them once. 16 x 16 pixel
    // centres lie inside the square.
    let a: ring::Tri = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
    let b: ring::Tri = [[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let (cov, _) = raster::rasterise_ring(&[a, b], &[], 18).unwrap();
    assert_eq!(cov.pixel_size, 1.0 / 16.0);
    assert_eq!(cov.ring_pixels, 256);
    assert_eq!(cov.overlap_pixels, 0);
    // the same square listed twice (one copy clockwise) covers each pixel twice
    let (cov, _) = raster::rasterise_ring(&[a, b, [a[0], a[2], a[1]], [b[0], b[2], b[1]]], &[], 18).unwrap();
    assert_eq!(cov.overlap_pixels, 256);
    assert_eq!(cov.max_coverage, 2);
    // a triangle inside the square as the "scaled copy"
    let c: ring::Tri = [[0.25, 0.25], [0.75, 0.25], [0.75, 0.75]];
    let (cov, _) = raster::rasterise_ring(&[a, b], &[c], 18).unwrap();
    assert!(cov.copy_overlap_pixels > 0);
}

#[test]
fn synthetic_fold_has_negative_jacobian_ratio() {
    // two triangles of areas 2 and -1/2: ratio -1/4, the fold at the second's centroid
    let good: ring::Tri = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
    let bad: ring::Tri = [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]];
    let reg = regularity::regularity(&[good, bad]);
    assert!(!reg.regular);
    assert_eq!(reg.folded_facets, 1);
    assert!((reg.min_jacobian_ratio + 0.25).abs() < 1e-15);
    assert!((reg.min_jacobian_at[0] - 1.0 / 3.0).abs() < 1e-15);
}

#[test]
fn normalised_wedge_of_the_regular_grid_is_a_quarter_of_the_ring() {
    // at n = 4 the wedge map stretches angles by n/4 = 1: the wedge is one
    // quadrant of the square annulus of outer circumradius 1 (half-side
    // 1/sqrt 2), i.e. a quarter of 2 - 1/2
    let s = schemes::build("catmull-clark", &[]).unwrap();
    let m = characteristic_map_of(s.as_ref(), 4, &opts(3, 64)).unwrap();
    let w = wedge::normalised_wedge(&m.ring.as_ref().unwrap().ring, 4);
    let area = regularity::total_signed_area(&w);
    assert!((area - 0.375).abs() < 1e-9, "wedge area {area}");
}

#[test]
fn normalised_wedge_for_large_valence_spans_a_quarter_turn() {
    let s = schemes::build("catmull-clark", &[]).unwrap();
    let m = characteristic_map_of(s.as_ref(), 40, &opts(3, 64)).unwrap();
    let w = wedge::normalised_wedge(&m.ring.as_ref().unwrap().ring, 40);
    assert!(!w.is_empty());
    let angles: Vec<f64> = w.iter().flatten().map(|p| p[1].atan2(p[0])).collect();
    let (lo, hi) = angles.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    // one facet's angular size (stretched) of slack at either side
    assert!(lo > -0.3 && lo < 0.1, "{lo}");
    assert!(hi > PI / 2.0 - 0.1 && hi < PI / 2.0 + 0.3, "{hi}");
    // the angle stretch is conformal: a regular ring stays regular
    assert!(regularity::regularity(&w).regular);
}

/// Loop's rules except on edges at the extraordinary vertex, where the edge
/// point is v/2 + 5/8 p_i - p_{i-1}/16 - p_{i+1}/16 (v the extraordinary end,
/// p_i the other end, p_{i±1} the apexes). In Fourier block m (m ≠ 0) these
/// edge points have the eigenvalue 5/8 - cos(2πm/n)/8 (the centre drops out
/// of blocks m ≠ 0), which grows with m up to m = n/2: block 2 beats block 1.
struct SkewLoop {
    base: Box<dyn Scheme>,
    params: Params,
}

impl<W: SchemeWeight> Rules<MeshDomain, W> for SkewLoop {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        if let Origin::Edge(a, b) = origin {
            let (Some(va), Some(vb)) = (mesh.valence(a), mesh.valence(b)) else {
                return Ok(Err(GatherError::Truncated));
            };
            if va != 6 || vb != 6 {
                let (v, p) = if va != 6 { (a, b) } else { (b, a) };
                let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
                    return Ok(Err(GatherError::Truncated));
                };
                let (c, d) = (mesh.face_from(fl, kl)[2], mesh.face_from(fr, kr)[2]);
                return Ok(Ok(Stencil::new()
                    .with(v, W::ratio(1, 2))
                    .with(p, W::ratio(5, 8))
                    .with(c, W::ratio(-1, 16))
                    .with(d, W::ratio(-1, 16))));
            }
        }
        W::rule(self.base.as_ref(), mesh, origin)
    }
}

const SKEWLOOP_INFO: SchemeInfo = SchemeInfo {
    name: "skew-loop",
    description: "Loop with edge weights that favour Fourier block 2 (test only)",
    topology: Topology::PrimalTriangle,
    centre: CentreKind::Vertex,
    sector: SectorKind::Tri,
    caps: Caps::NONE,
};

impl Scheme for SkewLoop {
    fn info(&self) -> &SchemeInfo {
        &SKEWLOOP_INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}

fn skew_loop() -> SkewLoop {
    SkewLoop { base: schemes::build("loop", &[]).unwrap(), params: Params::default() }
}

#[test]
fn subdominant_pair_from_block_two_winds_twice_and_is_not_injective() {
    let s = skew_loop();
    let n = 5;
    let m = characteristic_map_of(&s, n, &opts(3, 256)).unwrap();
    let mu = |k: usize| 5.0 / 8.0 - (2.0 * PI * k as f64 / n as f64).cos() / 8.0;
    assert!(mu(2) > mu(1));
    assert!((m.lambda1 - mu(2)).abs() < 1e-9, "λ1 {} vs block-2 value {}", m.lambda1, mu(2));
    assert_eq!(m.subdominant_blocks, vec![2, 3]);
    assert_eq!(m.spectral_status, SpectralStatus::WrongBlock);
    assert_eq!(m.winding_number, Some(2), "{:?}", m.reasons);
    assert!(!m.injective);
    // a boundary of degree two: the ring and its copies cover the inside
    // twice, so some pixel is covered more than once
    assert!(m.overlap_pixels.unwrap() + m.copy_overlap_pixels.unwrap() > 0, "{:?}", m.reasons);
}

#[test]
fn simple_subdominant_eigenvalue_gets_a_verdict_and_no_map() {
    // at n = 4 block 2 is its own conjugate: 5/8 + 1/8 = 3/4 is a simple eigenvalue
    let s = skew_loop();
    let m = characteristic_map_of(&s, 4, &opts(3, 256)).unwrap();
    assert!((m.lambda1 - 0.75).abs() < 1e-9);
    assert_eq!(m.spectral_status, SpectralStatus::Simple);
    assert!(!m.regular && !m.injective);
    assert!(m.ring.is_none() && m.winding_number.is_none() && m.overlap_pixels.is_none());
    assert!(m.explanation.contains("simple"), "{}", m.explanation);
}

#[test]
fn bad_options_are_errors() {
    let s = schemes::build("loop", &[]).unwrap();
    for (levels, resolution) in [(0, 256), (9, 256), (3, 0), (3, 8), (3, 100_000)] {
        assert!(characteristic_map_of(s.as_ref(), 5, &opts(levels, resolution)).is_err());
    }
}

#[test]
fn inner_boundary_is_the_outer_boundary_one_step_coarser_scaled_by_lambda() {
    // S v = λ1 v: the net one analysis step later, restricted to the first
    // ring, is λ1 times the level-0 net. So the inner boundary of the ring
    // after L steps is λ1 times the outer boundary after L - 1 steps, as a
    // polygon; compare perimeters and winding. This checks the net's
    // refinement, the face tracking and the eigenvector together.
    for (name, n) in [("catmull-clark", 5), ("loop", 7), ("doo-sabin", 5), ("non-box", 6), ("sqrt3", 5)] {
        let s = schemes::build(name, &[]).unwrap();
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let a = analyse(
            s.as_ref(),
            &config,
            &Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false },
        )
        .unwrap();
        let pair = subdlab::charmap::spectral::subdominant_pair(&a.spectrum);
        assert_eq!(pair.status, SpectralStatus::Ok, "{name}");
        let d = &a.discovered;
        let at = |levels: usize| {
            let pts = net::initial_points(d, &pair.values).unwrap();
            ring::extract(&net::refine_net(s.as_ref(), d, pts, levels).unwrap())
        };
        let len = |e: &[[[f64; 2]; 2]]| e.iter().map(|[a, b]| (b[0] - a[0]).hypot(b[1] - a[1])).sum::<f64>();
        let (coarse, fine) = (at(2), at(3));
        assert_eq!(fine.inner_boundary.len(), coarse.outer_boundary.len(), "{name}: edge counts");
        let (inner, outer) = (len(&fine.inner_boundary), len(&coarse.outer_boundary));
        assert!((inner - pair.lambda * outer).abs() < 1e-9 * outer, "{name}: {inner} vs λ1·{outer}");
    }
}

/// Catmull–Clark except for the edge points on edges at the extraordinary
/// vertex v (valence n = 3): e' = a·v + b·p_i + c·(p_{i−1} + p_{i+1}) +
/// d·(f_{i−1} + f_i), with p the edge neighbours of v and f the opposite
/// corners of the quads at v. With CC's face points f' = (v + p_i + f_i +
/// p_{i+1})/4, Fourier block m ≠ 0 of the first ring is the 2×2 matrix
/// [[x_m, d(1 + ω̄)], [(1 + ω)/4, 1/4]] with x_m = b + 2c·cos θ_m, ω = e^{iθ_m},
/// θ_m = 2πm/n. Its discriminant is (x_m − 1/4)² + d·|1 + ω|², so
/// d = −(x_1 − 1/4)²/|1 + ω_1|² makes block 1 a double eigenvalue
/// (x_1 + 1/4)/2 with a non-zero off-diagonal entry: a Jordan block.
/// x_1 = 3/4 gives λ = 1/2 (in blocks 1 and 2, the only blocks besides 0 at
/// n = 3). c = −1/5 gives b = 11/20, d = −1/4, a = 27/20; block 0 over
/// (v, p, f) is then [[5/12, 1/2, 1/12], [27/20, 3/20, −1/2], [1/4, 1/2, 1/4]]
/// (CC's vertex rule in the first row) with eigenvalues 1, 1/6 and −7/20
/// (trace 49/60, determinant −7/120), below 1/2; the rest of the analysis
/// neighbourhood follows the regular rules (eigenvalues 1/8 and smaller).
struct JordanCc {
    base: Box<dyn Scheme>,
    params: Params,
}

impl<W: SchemeWeight> Rules<MeshDomain, W> for JordanCc {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        if let Origin::Edge(a, b) = origin {
            let (Some(va), Some(vb)) = (mesh.valence(a), mesh.valence(b)) else {
                return Ok(Err(GatherError::Truncated));
            };
            if va != 4 || vb != 4 {
                let (v, p) = if va != 4 { (a, b) } else { (b, a) };
                let n = mesh.valence(v).unwrap() as i64;
                let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(v, p), mesh.half_edge(p, v)) else {
                    return Ok(Err(GatherError::Truncated));
                };
                // [v, p, f_i, p_{i+1}] and [p, v, p_{i-1}, f_{i-1}]
                let left = mesh.face_from(fl, kl);
                let right = mesh.face_from(fr, kr);
                if left.len() != 4 || right.len() != 4 {
                    return Ok(Err(GatherError::NotCovered));
                }
                let cos = W::cos_2pi(1, n)?;
                let c = W::ratio(-1, 5);
                let x1 = W::ratio(3, 4);
                let b = x1.clone() - W::int(2) * c.clone() * cos.clone();
                let k = W::int(2) + W::int(2) * cos;
                let t = x1 - W::ratio(1, 4);
                let d = W::zero() - t.clone() * t / k;
                let a = W::one() - b.clone() - W::int(2) * c.clone() - W::int(2) * d.clone();
                return Ok(Ok(Stencil::new()
                    .with(v, a)
                    .with(p, b)
                    .with(left[3], c.clone())
                    .with(right[2], c)
                    .with(left[2], d.clone())
                    .with(right[3], d)));
            }
        }
        W::rule(self.base.as_ref(), mesh, origin)
    }
}

const JORDANCC_INFO: SchemeInfo = SchemeInfo {
    name: "jordan-cc",
    description: "Catmull–Clark with edge weights that make lambda1 defective (test only)",
    topology: Topology::PrimalQuad,
    centre: CentreKind::Vertex,
    sector: SectorKind::Quad,
    caps: Caps::NONE,
};

impl Scheme for JordanCc {
    fn info(&self) -> &SchemeInfo {
        &JORDANCC_INFO
    }
    fn params(&self) -> &Params {
        &self.params
    }
}

#[test]
fn defective_subdominant_eigenvalue_gets_a_verdict_and_no_map() {
    let s = JordanCc { base: schemes::build("catmull-clark", &[]).unwrap(), params: Params::default() };
    let m = characteristic_map_of(&s, 3, &opts(3, 256)).unwrap();
    assert!((m.lambda1 - 0.5).abs() < 1e-6, "λ1 = {}: {:?}", m.lambda1, m.reasons);
    assert_eq!(m.spectral_status, SpectralStatus::Defective, "{:?}", m.reasons);
    assert!(m.ring.is_none() && !m.injective && m.winding_number.is_none());
    assert!(m.explanation.contains("defective"));
}

#[test]
fn defective_pair_is_double_in_each_conjugate_block() {
    // the Jordan blocks of blocks 1 and 2: algebraic 4, geometric 2 in all
    let s = JordanCc { base: schemes::build("catmull-clark", &[]).unwrap(), params: Params::default() };
    let spec = subdlab::spectrum::spectrum_of(&s, 3).unwrap();
    let l1 = &spec.eigenvalues[1];
    assert!((l1.re - 0.5).abs() < 1e-6);
    assert_eq!((l1.algebraic_multiplicity, l1.geometric_multiplicity), (4, 2));
    assert_eq!(l1.blocks, vec![1, 2]);
    // block 0's other eigenvalues, derived above
    let has = |x: f64| spec.eigenvalues.iter().any(|e| (e.re - x).abs() < 1e-9 && e.im.abs() < 1e-9);
    assert!(has(1.0 / 6.0) && has(-7.0 / 20.0));
}
