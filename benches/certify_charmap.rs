//! `certify_charmap`: the certified characteristic-map verdict (the spectral
//! certificate, the enclosed block eigenvector, the interval net refined with
//! the rules, the exact check of the regular rules, the Jacobian bounds per
//! ring face and the certified winding number), after the floating-point
//! analysis it reuses (made once outside the timed loop), for Catmull–Clark,
//! Loop and Doo–Sabin at n = 3..50. `scripts/bench-certify-charmap.sh` runs
//! it and prints the README's table ("Certified characteristic maps").

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::certify::certify_charmap;
use subdlab::certify::charmap::DEFAULT_MAX_LEVELS;
use subdlab::neighbourhood::Configuration;
use subdlab::schemes;
use subdlab::spectrum::{analyse, Options};

const VALENCES: [usize; 5] = [3, 5, 10, 25, 50];

fn certify(c: &mut Criterion) {
    let mut group = c.benchmark_group("certify_charmap");
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for name in ["catmull-clark", "loop", "doo-sabin"] {
        let scheme = schemes::build(name, &[]).unwrap();
        for n in VALENCES {
            let config = Configuration::regular(scheme.as_ref(), n).unwrap();
            let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
            group.bench_with_input(BenchmarkId::new(name, n), &analysis, |b, a| {
                b.iter(|| certify_charmap(scheme.as_ref(), a, DEFAULT_MAX_LEVELS).unwrap().c1)
            });
        }
    }
    group.finish();
}

criterion_group!(benches, certify);
criterion_main!(benches);
