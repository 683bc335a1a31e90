//! The characteristic map read off refined unit rows (as `curvature` does)
//! against the map refined from the eigenvectors.

use approx::assert_relative_eq;
use subdlab::charmap::{check_map, check_map_over, net, CharMapOptions};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::spectrum::{analyse_shared, Options};

/// The scheme and its float analysis (analysis neighbourhood) at valence n,
/// with the face sequence `faces` where the scheme has mixed sectors.
fn analysis_of(
    name: &str,
    n: usize,
    faces: Option<&str>,
) -> (Box<dyn subdlab::sdc::Scheme>, std::sync::Arc<subdlab::spectrum::Analysis>) {
    let scheme = subdlab::schemes::build(name, &[]).unwrap();
    let config = match faces {
        Some(f) => Configuration::with_faces(scheme.as_ref(), n, f).unwrap(),
        None => Configuration::regular(scheme.as_ref(), n).unwrap(),
    };
    let options = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse_shared(scheme.as_ref(), &config, &options).unwrap();
    (scheme, analysis)
}

/// The map read off refined unit rows (as `curvature` does) is the map
/// refined from the eigenvectors: the same verdict, facets and pixel
/// counts, and ring points equal up to rounding (a composed row and a
/// step-by-step refinement sum in different orders). Catmull–Clark n = 5
/// (quads, 4 faces per face) and Loop n = 7 (triangles).
#[test]
fn the_map_from_unit_rows_is_the_refined_map() {
    for (name, n) in [("catmull-clark", 5), ("loop", 7)] {
        let scheme = subdlab::schemes::build(name, &[]).unwrap();
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        let options = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
        let analysis = analyse_shared(scheme.as_ref(), &config, &options).unwrap();
        let opts = CharMapOptions::checked(3, 128).unwrap();
        let rows = net::refine_net(
            scheme.as_ref(),
            &analysis.discovered,
            {
                let mut level0 = vec![None; analysis.discovered.patch.num_vertices()];
                for (k, &v) in analysis.discovered.analysis.iter().enumerate() {
                    level0[v] = Some(subdlab::refine::SparseRow::<f64>::unit(k));
                }
                level0
            },
            3,
        )
        .unwrap();
        let direct = check_map(scheme.as_ref(), &analysis, &opts).unwrap();
        let read = check_map_over(scheme.as_ref(), &analysis, &opts, Some(&rows)).unwrap();
        assert!(direct.injective && read.injective, "{name} n = {n}: the map is injective either way");
        assert_eq!(direct.ring_facets, read.ring_facets);
        assert_eq!(direct.ring_pixels, read.ring_pixels);
        let (a, b) = (direct.ring.unwrap(), read.ring.unwrap());
        assert_eq!(a.ring.len(), b.ring.len());
        for (s, t) in a.ring.iter().zip(&b.ring) {
            for (p, q) in s.iter().zip(t) {
                assert_relative_eq!(p[0], q[0], epsilon = 1e-12);
                assert_relative_eq!(p[1], q[1], epsilon = 1e-12);
            }
        }
    }
}

/// One function refined as data, once for levels 1..3
/// (`RingSampler::ring_sizes_each_level`, the Jordan growth test's route at
/// levels nothing else samples) has the ring size (largest |value| over the
/// ring) that its unit rows refined to that level give
/// (`RingSampler::ring_values`): the same rules, mesh and pruning applied to
/// the data instead of the rows, so sizes equal up to rounding. Catmull–Clark
/// n = 5, Loop n = 7 and 4-3 eons of six quads (rotation-symmetric: one
/// sector refined with the data turned), of QTQT (a half-turn) and of QQTQT
/// (no symmetry: the whole ring), on functions without symmetry, each with
/// a bump at a different vertex so that the largest value lies in different
/// sectors (a wrongly turned sector shows).
#[test]
fn a_function_refined_as_data_has_the_ring_size_of_its_rows() {
    use subdlab::curvature::sampler::RingSampler;
    let cases = [
        ("catmull-clark", 5, None),
        ("loop", 7, None),
        ("four-three", 6, Some("QQQQQQ")),
        ("four-three", 4, Some("QTQT")),
        ("four-three", 5, Some("QQTQT")),
    ];
    for (name, n, faces) in cases {
        let (scheme, analysis) = analysis_of(name, n, faces);
        let d = &analysis.discovered;
        let size = d.analysis.len();
        for bump in [1, size / 3, size / 2, size - 1] {
            let x: Vec<f64> = (0..size)
                .map(|k| ((k * 7 + 3) % 11) as f64 - 4.5 + 0.1 * k as f64 + if k == bump { 40.0 } else { 0.0 })
                .collect();
            let each = RingSampler::ring_sizes_each_level(scheme.as_ref(), d, 3, &x).unwrap();
            assert_eq!(each.len(), 3, "{name} n = {n}: one size per level");
            for (levels, once) in (1..=3).zip(each) {
                let rows = RingSampler::new(scheme.as_ref(), d, levels).unwrap().ring_values(&x);
                let largest = rows.iter().map(|v| v.abs()).fold(0.0, f64::max);
                assert_relative_eq!(largest, once, epsilon = 1e-11, max_relative = 1e-11);
            }
        }
    }
}

/// The ring sizes of many functions taken together
/// (`RingSampler::ring_sizes`, the growth test's windows of iterates) are,
/// to the last bit, the largest |value| of each function's ring values
/// (`RingSampler::ring_values`): each value is summed over its row in the
/// same order. Catmull–Clark n = 5 and a 4-3 eon of QQTQT, levels 2, on
/// functions without symmetry.
#[test]
fn ring_sizes_taken_together_are_each_function_s_own() {
    use subdlab::curvature::sampler::RingSampler;
    for (name, n, faces) in [("catmull-clark", 5, None), ("four-three", 5, Some("QQTQT"))] {
        let (scheme, analysis) = analysis_of(name, n, faces);
        let d = &analysis.discovered;
        let sampler = RingSampler::new(scheme.as_ref(), d, 2).unwrap();
        let xs: Vec<Vec<f64>> = (0..7)
            .map(|j| {
                (0..d.analysis.len())
                    .map(|k| (((k + 3 * j) * 7 + 3) % 11) as f64 - 4.5 + 0.37 * (k * j) as f64)
                    .collect()
            })
            .collect();
        let together = sampler.ring_sizes(&xs);
        for (x, size) in xs.iter().zip(together) {
            let own = sampler.ring_values(x).iter().map(|v| v.abs()).fold(0.0, f64::max);
            assert_eq!(own.to_bits(), size.to_bits(), "{name} n = {n}");
        }
    }
}
