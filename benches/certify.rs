//! `certify_spectrum`: the certified spectral verdict alone (interval rows of
//! S from the rules, interval Fourier blocks, their verified enclosures, the
//! premises and the verdict), after the floating-point analysis it reuses
//! (made once outside the timed loop), for Catmull–Clark, Loop and Doo–Sabin
//! at n = 3..200. `scripts/bench-certify.sh` runs it and prints the table of
//! the README ("Certified verdicts").

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::certify::certify_spectrum;
use subdlab::neighbourhood::Configuration;
use subdlab::schemes;
use subdlab::spectrum::{analyse, Options};

const VALENCES: [usize; 7] = [3, 5, 10, 25, 50, 100, 200];

fn certify(c: &mut Criterion) {
    let mut group = c.benchmark_group("certify_spectrum");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for name in ["catmull-clark", "loop", "doo-sabin"] {
        let scheme = schemes::build(name, &[]).unwrap();
        for n in VALENCES {
            let config = Configuration::regular(scheme.as_ref(), n).unwrap();
            let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
            group.bench_with_input(BenchmarkId::new(name, n), &analysis, |b, a| {
                b.iter(|| certify_spectrum(scheme.as_ref(), a, 1).unwrap().verdict)
            });
        }
    }
    group.finish();
}

criterion_group!(benches, certify);
criterion_main!(benches);
