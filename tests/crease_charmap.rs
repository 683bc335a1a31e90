//! The per-side characteristic map at a crease vertex (`charmap --tag
//! crease:K`, `charmap::crease_map`).
//!
//! Expected values, derived by hand (not read off the program):
//!
//! - The regular crease (Catmull–Clark n = 4 `crease:2`, Loop n = 6
//!   `crease:3`) has on each side a piece of the regular lattice: the
//!   bicubic B-spline resp. the quartic box spline inside, the cubic B-spline
//!   curve's rules on the crease. Both reproduce linear functions, and a
//!   linear function ℓ sampled on the lattice refines to ℓ at the halved
//!   lattice, i.e. S·ℓ = ℓ/2 on the side's points (ℓ(0) = 0 at the centre).
//!   The side's 1/2 has multiplicity exactly 2 (tests/crease_sides.rs,
//!   exactly over Q), so the side's subdominant pair spans exactly the two
//!   coordinate functions of the lattice: the side's pair is a linear image
//!   of each point's lattice position i·e_s + j·e_(s+1) (e_s the unit vector
//!   of ray s, 360°/n apart). Hence the side's map is a linear image of the
//!   identity on the half-plane: λ1 = λ2 = 1/2, regular, injective, and the
//!   two sharp rays (e_0 and e_K = −e_0) go to opposite directions, 180°.
//! - A side of K faces has the boundary fan of K faces' matrix (the same
//!   closure; tests/crease_sides.rs shows the characteristic polynomials
//!   equal) and the same rules on its faces, so its map is the boundary
//!   fan's up to a linear map: every quantity invariant under linear maps
//!   (λ's, regularity, the smallest over the largest facet area, the ring's
//!   area over the area inside it, the facet count) and, after the common
//!   isotropic normalisation, the angle between the sharp rays' images
//!   agree with `charmap --tag boundary -n K`. Compared as an identity
//!   between the two runs, not against printed numbers.
//! - Hoppe's boundary rules (README "Analysing a tagged vertex", derived in
//!   tests/tagged_verdicts.rs): a side of 4 Catmull–Clark quads has 1/2
//!   defective (no map); a side of 5 quads has λ1, λ2 > 1/2 off the
//!   boundary curve's spectrum, so its eigenvectors vanish on the sharp rays
//!   and the map collapses them. The crease then fails naming that side,
//!   while the other side (2 quads, regular) passes. With BLZ's γ
//!   (`-p blz=1`) the side of 4 quads has λ1 = λ2 = 1/2 non-defective and
//!   passes.

use crate::common::subdlab;
use subdlab::charmap::spectral::sector_pair;
use subdlab::charmap::{characteristic_map, CharMap, CharMapOptions};
use subdlab::neighbourhood::{Configuration, Tagging};
use subdlab::schemes::{self, Scheme};

fn scheme(name: &str, params: &[(&str, &str)]) -> Box<dyn Scheme> {
    let params: Vec<(String, String)> = params.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect();
    schemes::build(name, &params).unwrap()
}

fn map_at(name: &str, params: &[(&str, &str)], n: usize, tag: &str) -> CharMap {
    let s = scheme(name, params);
    let config = Configuration::tagged(s.as_ref(), n, None, Tagging::parse(tag).unwrap()).unwrap();
    characteristic_map(s.as_ref(), &config, &CharMapOptions::default()).unwrap()
}

fn side_name(m: &CharMap) -> String {
    let t = m.tagging.clone().unwrap_or_default();
    t.find("side ").map_or(t.clone(), |k| t[k..].to_string())
}

#[test]
fn each_side_of_the_regular_crease_is_a_linear_image_of_the_half_plane() {
    for (name, n, tag) in [("catmull-clark", 4, "crease:2"), ("loop", 6, "crease:3")] {
        let s = scheme(name, &[]);
        let config = Configuration::tagged(s.as_ref(), n, None, Tagging::parse(tag).unwrap()).unwrap();
        let analysis = subdlab::spectrum::analyse(s.as_ref(), &config, &Default::default()).unwrap();
        let crease = analysis.spectrum.crease.as_ref().unwrap();
        assert!(crease.coupled.is_none());
        // the side's pair is a linear function of the lattice position
        let ray = |r: usize| {
            let a = 2.0 * std::f64::consts::PI * r as f64 / n as f64;
            [a.cos(), a.sin()]
        };
        for side in &crease.sides {
            let pair = sector_pair(&side.spectrum);
            assert_eq!(pair.values.len(), side.points.len());
            assert!((pair.lambda - 0.5).abs() < 1e-12, "{name} {}: λ1 = {}", side.name, pair.lambda);
            let pos: Vec<[f64; 2]> = side
                .spectrum
                .labels
                .iter()
                .map(|l| {
                    let (a, b) = (ray(l.sector), ray(l.sector + 1));
                    let (i, j) = (l.i as f64, l.j as f64);
                    [i * a[0] + j * b[0], i * a[1] + j * b[1]]
                })
                .collect();
            // least squares for L in value = L·pos, then every residual small
            let (mut g, mut h) = ([[0.0f64; 2]; 2], [[0.0f64; 2]; 2]);
            for (p, v) in pos.iter().zip(&pair.values) {
                for r in 0..2 {
                    for c in 0..2 {
                        g[r][c] += p[r] * p[c];
                        h[r][c] += v[r] * p[c];
                    }
                }
            }
            let det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
            let inv = [[g[1][1] / det, -g[0][1] / det], [-g[1][0] / det, g[0][0] / det]];
            let l = |r: usize, c: usize| h[r][0] * inv[0][c] + h[r][1] * inv[1][c];
            let scale = pair.values.iter().map(|v| v[0].hypot(v[1])).fold(0.0, f64::max);
            let det_l = l(0, 0) * l(1, 1) - l(0, 1) * l(1, 0);
            assert!(det_l.abs() > 1e-6 * scale * scale, "{name} {}: the pair is not two directions", side.name);
            for ((p, v), label) in pos.iter().zip(&pair.values).zip(&side.spectrum.labels) {
                for r in 0..2 {
                    let fit = l(r, 0) * p[0] + l(r, 1) * p[1];
                    assert!((fit - v[r]).abs() < 1e-9 * scale, "{name} {} at {}: not linear", side.name, label.name);
                }
            }
        }
        // the map: each side regular, injective, its sharp rays opposite
        let m = map_at(name, &[], n, tag);
        let c = m.crease.as_ref().unwrap();
        assert_eq!(c.sides.len(), 2);
        for side in &c.sides {
            assert!(side.regular && side.injective, "{name} {}: {:?}", side_name(side), side.reasons);
            assert!((side.lambda1 - 0.5).abs() < 1e-12);
            let angle = side.ray_angle_degrees.unwrap();
            assert!((angle - 180.0).abs() < 1e-6, "{name} {}: {angle}°", side_name(side));
        }
        assert!(m.regular && m.injective, "{name}: {:?}", m.reasons);
        // S whole has 1/2 three times: no map of its own, said on its line
        assert!(c.whole.is_none());
        assert!(m.reasons.iter().any(|r| r.starts_with("S whole") && r.contains("no map")), "{:?}", m.reasons);
    }
}

#[test]
fn a_side_is_the_boundary_fan_of_its_faces() {
    // (scheme, n, K): side A has K faces, side B n − K
    for (name, n, at) in [("catmull-clark", 5, 3), ("loop", 7, 3), ("catmull-clark", 6, 4)] {
        let params: &[(&str, &str)] = if n == 6 { &[("blz", "1")] } else { &[] };
        let m = map_at(name, params, n, &format!("crease:{at}"));
        let c = m.crease.as_ref().unwrap();
        for (side, faces) in c.sides.iter().zip([at, n - at]) {
            let b = map_at(name, params, faces, "boundary");
            let what = format!("{name} n = {n} crease:{at} {} against boundary {faces}", side_name(side));
            assert!(side_name(side).contains(&format!("{faces} faces")), "{what}");
            assert!(b.regular && b.injective, "{what}: the boundary fan passes");
            assert_eq!((side.regular, side.injective), (b.regular, b.injective), "{what}");
            assert!((side.lambda1 - b.lambda1).abs() < 1e-10, "{what}: λ1 {} against {}", side.lambda1, b.lambda1);
            assert_eq!(side.ring_facets, b.ring_facets, "{what}");
            let close = |x: Option<f64>, y: Option<f64>, tol: f64| (x.unwrap() - y.unwrap()).abs() <= tol;
            assert!(close(side.min_jacobian_ratio, b.min_jacobian_ratio, 1e-9), "{what}: Jacobian ratio");
            let area_ratio = |m: &CharMap| m.ring_area.unwrap() / m.inner_area.unwrap();
            assert!((area_ratio(side) - area_ratio(&b)).abs() < 1e-9 * area_ratio(&b), "{what}: area ratio");
            assert!(close(side.ray_angle_degrees, b.ray_angle_degrees, 1e-6), "{what}: ray angle");
        }
        assert!(m.regular && m.injective, "{name} n = {n}: {:?}", m.reasons);
    }
}

#[test]
fn a_side_with_a_defective_or_collapsing_boundary_fails_naming_that_side() {
    // Catmull–Clark n = 6 crease:4: side A of 4 quads, 1/2 defective
    let m = map_at("catmull-clark", &[], 6, "crease:4");
    let c = m.crease.as_ref().unwrap();
    assert!(!m.injective && !m.regular);
    assert!(c.sides[0].ring.is_none(), "side A has no map");
    assert!(c.sides[1].regular && c.sides[1].injective, "side B (2 quads) passes: {:?}", c.sides[1].reasons);
    assert!(m.explanation.starts_with("per side: side A (sectors 0..3, 4 faces"), "{}", m.explanation);
    // Catmull–Clark n = 7 crease:5: side A of 5 quads, the rays collapse
    let m = map_at("catmull-clark", &[], 7, "crease:5");
    let c = m.crease.as_ref().unwrap();
    assert!(m.c1_spectral, "the spectral part passes on both sides (k = 5: λ1 > λ2 > |λ3| = 1/2)");
    assert!(!m.injective);
    assert!(c.sides[0].ring.is_none());
    assert!(c.sides[0].explanation.contains("vanish on the sharp rays"), "{}", c.sides[0].explanation);
    assert!(m.explanation.starts_with("per side: side A (sectors 0..4, 5 faces"), "{}", m.explanation);
    assert!(c.sides[1].regular && c.sides[1].injective);
    // BLZ's γ: the side of 4 quads passes, and so the crease
    let m = map_at("catmull-clark", &[("blz", "1")], 6, "crease:4");
    assert!(m.regular && m.injective, "{:?}", m.reasons);
}

#[test]
fn the_command_names_each_side_and_its_evidence() {
    let out = subdlab(&["charmap", "catmull-clark", "-n", "4", "--tag", "crease:2"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("crease (both sides): regular yes, injective yes"), "{text}");
    assert!(text.contains("floating point") && text.contains("raster at resolution 512"), "{text}");
    assert!(text.contains("side A (sectors 0..1, 2 faces") && text.contains("side B (sectors 2..3, 2 faces"), "{text}");
    assert!(text.contains("S whole (both sides at once; not the crease's criterion): no map"), "{text}");
    let out = subdlab(&["charmap", "catmull-clark", "-n", "6", "--tag", "crease:4"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("crease (both sides): regular NO, injective NO"), "{text}");
    // the figure shows both sides: side A above the x-axis, side B below
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("crease.svg");
    let out = subdlab(&["charmap", "loop", "-n", "6", "--tag", "crease:3", "-o", svg.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(std::fs::metadata(&svg).unwrap().len() > 1000);
    let m = map_at("loop", &[], 6, "crease:3");
    let ring = m.ring.as_ref().unwrap();
    let c = m.crease.as_ref().unwrap();
    assert_eq!(ring.ring.len(), c.sides.iter().map(|s| s.ring.as_ref().unwrap().ring.len()).sum::<usize>());
    let side_y = |s: &CharMap| {
        let r = s.ring.as_ref().unwrap();
        r.ring.iter().flatten().map(|p| p[1]).sum::<f64>() / (3 * r.ring.len()) as f64
    };
    assert!(side_y(&c.sides[0]) > 0.0 && side_y(&c.sides[1]) < 0.0, "side A above, side B below the x-axis");
}

#[test]
fn the_sweep_reads_the_per_side_map() {
    // crease:2 at n = 4..7: side A 2 quads (passes), side B n − 2 quads:
    // 2, 3 pass; 4 has 1/2 defective (the spectral part fails); 5 collapses
    // the rays (the map fails, naming side B)
    let out = subdlab(&["sweep", "catmull-clark", "--tag", "crease:2", "--valences", "4..7", "--charmap", "--csv"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    let rows: Vec<&str> = text.lines().filter(|l| l.chars().next().is_some_and(|c| c.is_ascii_digit())).collect();
    assert_eq!(rows.len(), 4, "{text}");
    assert!(rows[0].contains("PASSES") && rows[1].contains("PASSES"), "{text}");
    assert!(rows[2].contains("FAILS") && rows[2].contains("side B"), "{text}");
    // (CSV writes the text's commas as semicolons)
    assert!(rows[3].contains("FAILS") && rows[3].contains("side B (sectors 2..6; 5 faces"), "{text}");
    assert!(rows[3].contains("vanish on the sharp rays"), "{text}");
}
