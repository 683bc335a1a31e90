//! Rasterising the characteristic ring (coverage per pixel, ring and its
//! scaled copies): Catmull–Clark at valence 5, at 2048² for analysis levels
//! 2..6 (facets grow 4× per level), and at level 4 for resolutions
//! 256..2048 (pixels grow 4× per doubling). The ring is built once outside
//! the timed loop; only `raster::rasterise_ring` is timed.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::charmap::{characteristic_map_of, raster, CharMapOptions};
use subdlab::schemes;

fn ring(levels: usize) -> subdlab::charmap::Ring {
    let scheme = schemes::build("catmull-clark", &[]).unwrap();
    let opts = CharMapOptions { levels, resolution: 64, display_levels: None };
    characteristic_map_of(scheme.as_ref(), 5, &opts).unwrap().ring.unwrap()
}

fn rasterise(c: &mut Criterion) {
    let mut group = c.benchmark_group("charmap_raster");
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    for levels in [2, 3, 4, 5, 6] {
        let r = ring(levels);
        group.bench_with_input(BenchmarkId::new("levels_at_2048", levels), &r, |b, r| {
            b.iter(|| raster::rasterise_ring(&r.ring, &r.inner, 2048).unwrap().0.ring_pixels)
        });
    }
    let r = ring(4);
    for resolution in [256, 512, 1024, 2048] {
        group.bench_with_input(BenchmarkId::new("resolution_at_level_4", resolution), &r, |b, r| {
            b.iter(|| raster::rasterise_ring(&r.ring, &r.inner, resolution).unwrap().0.ring_pixels)
        });
    }
    group.finish();
}

criterion_group!(benches, rasterise);
criterion_main!(benches);
