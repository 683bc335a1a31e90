//! Cost of one sweep point against valence, by pipeline stage, for
//! Catmull–Clark (analysis neighbourhood 6n + 1): discovery of the invariant
//! neighbourhoods, assembly of S, the eigen stage over Fourier blocks, and
//! the whole point as `subdlab sweep` computes it (`sweep::point`).
//! `scripts/bench-sweep.sh` runs this, times the full sweep 3..1000 in the
//! same run and prints the growth exponent of each stage between valences.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::matrix::assemble;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::schemes;
use subdlab::spectrum::{decompose, Method};
use subdlab::sweep::{point, Grid};

const VALENCES: [usize; 6] = [3, 10, 30, 100, 300, 1000];

fn sweep_point(c: &mut Criterion) {
    let scheme = schemes::build("catmull-clark", &[]).unwrap();
    let grid = Grid {
        scheme: "catmull-clark".into(),
        valences: VALENCES.to_vec(),
        param: None,
        fixed: Vec::new(),
        charmap: false,
        charmap_options: Default::default(),
        faces: None,
        curvature: false,
        tagging: None,
    };
    let mut group = c.benchmark_group("sweep_point");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for n in VALENCES {
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        group.bench_with_input(BenchmarkId::new("discover", n), &config, |b, config| {
            b.iter(|| discover(scheme.as_ref(), config).unwrap().analysis.len())
        });
        let d = discover(scheme.as_ref(), &config).unwrap();
        group.bench_with_input(BenchmarkId::new("assemble", n), &d, |b, d| {
            b.iter(|| assemble::<f64>(scheme.as_ref(), d, NeighbourhoodKind::Analysis).unwrap().size())
        });
        let s = assemble::<f64>(scheme.as_ref(), &d, NeighbourhoodKind::Analysis).unwrap();
        group.bench_with_input(BenchmarkId::new("eigen", n), &s, |b, s| {
            b.iter(|| decompose(s, 1, n, Method::Dft).unwrap().eigenvalues.len())
        });
        group.bench_with_input(BenchmarkId::new("point", n), &n, |b, &n| {
            b.iter(|| {
                let p = point(&grid, n, None);
                assert!(p.error.is_none());
                p.lambda.len()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, sweep_point);
criterion_main!(benches);
