//! Curve schemes on Z: the local subdivision matrix and its spectrum (exact
//! where the weights are rational) on the minimal and analysis windows, for
//! every registered curve scheme at its default parameters, through
//! `curves::local::curve_spectrum` as `subdlab curve` runs it.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::curves;
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::schemes;

fn curve_spectrum(c: &mut Criterion) {
    let mut group = c.benchmark_group("curve_spectrum");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for name in schemes::curves::known_names() {
        let scheme = schemes::curves::build(name, &[]).unwrap();
        for (kind, kind_name) in [(NeighbourhoodKind::Minimal, "minimal"), (NeighbourhoodKind::Analysis, "analysis")] {
            group.bench_function(BenchmarkId::new(name, kind_name), |b| {
                b.iter(|| curves::local::curve_spectrum(scheme.as_ref(), kind).unwrap().eigenvalues.len())
            });
        }
    }
    group.finish();
}

criterion_group!(benches, curve_spectrum);
criterion_main!(benches);
