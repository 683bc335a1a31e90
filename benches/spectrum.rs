//! Mesh schemes.
//!
//! `cc_spectrum`: Catmull–Clark spectrum on the analysis neighbourhood (6n+1
//! vertices): Fourier blocks against the full matrix, n = 3..200. Only the
//! eigen stage is timed (the matrix is assembled once outside the loop); both
//! methods return eigenvalues with algebraic and geometric multiplicities.
//! `scripts/bench-dft-ratio.sh` runs this and prints full/dft per valence.
//!
//! `mesh_analysis`: the whole analysis as `subdlab spectrum --no-exact` runs
//! it (discovery, representative rows, Fourier blocks, merge) for the schemes
//! with wide masks, n = 125..1000: the time should double with n.
//!
//! `exact_path`: the default analysis with exact confirmation, at a size that
//! takes the whole characteristic polynomial (CC n = 8, 49 vertices) and at
//! sizes that take Fourier block 0 from the representative rows.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::matrix::assemble;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::schemes;
use subdlab::spectrum::{analyse, decompose, Method, Options};

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

/// Schemes whose masks reach far (dense rows at the centre, two-step sqrt(3)
/// composition, face control vertices), and CC as the reference.
const WIDE: [(&str, &str); 6] = [
    ("catmull-clark", ""),
    ("doo-sabin", ""),
    ("sqrt3", ""),
    ("non-box", ""),
    ("unified-sqrt3", "1"),
    ("four-three", ""),
];

fn build(name: &str, alpha: &str) -> Box<dyn schemes::Scheme> {
    let overrides: Vec<(String, String)> =
        if alpha.is_empty() { Vec::new() } else { vec![("alpha".into(), alpha.into())] };
    schemes::build(name, &overrides).unwrap()
}

fn mesh_analysis(c: &mut Criterion) {
    let mut group = c.benchmark_group("mesh_analysis");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    let opts = Options { exact: false, ..Options::default() };
    for (name, alpha) in WIDE {
        let scheme = build(name, alpha);
        let id = if alpha.is_empty() { name.to_string() } else { format!("{name}-alpha{alpha}") };
        for n in [125, 250, 500, 1000] {
            let config = Configuration::regular(scheme.as_ref(), n).unwrap();
            group.bench_with_input(BenchmarkId::new(&id, n), &config, |b, config| {
                b.iter(|| analyse(scheme.as_ref(), config, &opts).unwrap().spectrum.eigenvalues.len())
            });
        }
    }
    group.finish();
}

fn exact_path(c: &mut Criterion) {
    let mut group = c.benchmark_group("exact_path");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for (name, n) in [("catmull-clark", 8), ("catmull-clark", 125), ("catmull-clark", 1000), ("tps", 125)] {
        let scheme = build(name, "");
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        group.bench_with_input(BenchmarkId::new(name, n), &config, |b, config| {
            b.iter(|| {
                let a = analyse(scheme.as_ref(), config, &Options::default()).unwrap();
                assert!(a.spectrum.exact_analysis.is_some());
                a.spectrum.eigenvalues.len()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, cc_spectrum, mesh_analysis, exact_path);
criterion_main!(benches);
