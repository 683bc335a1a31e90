//! Catmull–Clark spectrum on the analysis neighbourhood (6n+1 vertices):
//! Fourier blocks against the full matrix, n = 3..200. Only the eigen stage is
//! timed (the matrix is assembled once outside the loop); both methods return
//! eigenvalues with algebraic and geometric multiplicities.
//! `scripts/bench-dft-ratio.sh` runs this and prints full/dft per valence.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::matrix::assemble;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::schemes;
use subdlab::spectrum::{decompose, Method};

const VALENCES: [usize; 7] = [3, 5, 10, 25, 50, 100, 200];

fn cc_spectrum(c: &mut Criterion) {
    let scheme = schemes::build("catmull-clark", &[]).unwrap();
    let mut group = c.benchmark_group("cc_spectrum");
    group.sample_size(10).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
    for n in VALENCES {
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        let d = discover(scheme.as_ref(), &config).unwrap();
        let s = assemble::<f64>(scheme.as_ref(), &d, NeighbourhoodKind::Analysis).unwrap();
        group.bench_with_input(BenchmarkId::new("dft", n), &s, |b, s| {
            b.iter(|| decompose(s, 1, n, Method::Dft).unwrap().eigenvalues.len())
        });
        group.bench_with_input(BenchmarkId::new("full", n), &s, |b, s| {
            b.iter(|| decompose(s, 1, n, Method::Full).unwrap().eigenvalues.len())
        });
    }
    group.finish();
}

criterion_group!(benches, cc_spectrum);
criterion_main!(benches);
