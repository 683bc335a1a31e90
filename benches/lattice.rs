//! Regular-lattice schemes on Z²: the whole analysis of Khan–Mustafa (and
//! any other registered lattice scheme) on its minimal and analysis windows,
//! with and without the exact confirmation, through
//! `lattice::analysis::analyse` as `subdlab spectrum khan-mustafa` runs it.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::lattice;
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::schemes::registry::{self, Family};

fn lattice_analysis(c: &mut Criterion) {
    let mut group = c.benchmark_group("lattice_analysis");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for name in registry::names_of(Family::Lattice) {
        let scheme = registry::lattice(name, &[]).unwrap();
        for (kind, kind_name) in [(NeighbourhoodKind::Minimal, "minimal"), (NeighbourhoodKind::Analysis, "analysis")] {
            for exact in [false, true] {
                let id = format!("{name}-{kind_name}-{}", if exact { "exact" } else { "float" });
                group.bench_function(BenchmarkId::from_parameter(id), |b| {
                    b.iter(|| {
                        let a = lattice::analysis::analyse(scheme.as_ref(), kind, exact).unwrap();
                        a.spectrum.eigenvalues.len()
                    })
                });
            }
        }
    }
    group.finish();
}

criterion_group!(benches, lattice_analysis);
criterion_main!(benches);
