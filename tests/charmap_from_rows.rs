//! The characteristic map read off refined unit rows (as `curvature` does)
//! against the map refined from the eigenvectors.

use approx::assert_relative_eq;
use subdlab::charmap::{check_map, check_map_over, net, CharMapOptions};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::spectrum::{analyse_shared, Options};

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
