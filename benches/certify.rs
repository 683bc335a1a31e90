//! The certified verdicts alone, after the floating-point analysis they
//! reuse (made once outside the timed loop):
//! - `certify_spectrum` (interval rows of S from the rules, interval Fourier
//!   blocks, their verified enclosures, the premises and the verdict) at
//!   n = 3..200, for every seed mesh scheme (its default parameters);
//! - `certify_charmap` (the spectral certificate, the enclosed block
//!   eigenvector, the interval net refined with the rules, the exact check of
//!   the regular rules, the Jacobian bounds per ring face and the certified
//!   winding number) at n = 3..50, for every scheme whose characteristic map
//!   the certificate covers (Catmull–Clark, Loop, Doo–Sabin, non-box, 4-3 at
//!   its quad eons, PGS, TPS).
//!
//! - `certify_charmap_difference`: the same for Kobbelt √3, whose map is
//!   proved by the difference-scheme bound (lemma C9) at n = 4, 5, 6, 8
//!   (seconds per valence, so only these; n = 3 is NOT PROVED).
//!
//! `scripts/bench-certify.sh` runs them and prints the README's tables
//! ("Certified verdicts", "Certified characteristic maps").

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;
use subdlab::certify::certify_charmap;
use subdlab::certify::charmap::DEFAULT_MAX_LEVELS;
use subdlab::neighbourhood::Configuration;
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Analysis, Options};

/// Every seed mesh scheme (the spectral certificate).
const SPECTRUM_SCHEMES: [&str; 10] = [
    "catmull-clark",
    "loop",
    "doo-sabin",
    "non-box",
    "four-three",
    "sqrt3",
    "unified-sqrt3",
    "pgs",
    "tps",
    "polar-bi2",
];

/// The schemes whose characteristic map the certificate covers.
const CHARMAP_SCHEMES: [&str; 7] = ["catmull-clark", "loop", "doo-sabin", "non-box", "four-three", "pgs", "tps"];

/// Time `run` on the analysis of every scheme at every valence, in a group.
fn bench_group(c: &mut Criterion, group: &str, names: &[&str], valences: &[usize], run: fn(&dyn Scheme, &Analysis)) {
    let mut group = c.benchmark_group(group);
    group.sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(2));
    for &name in names {
        let scheme = schemes::build(name, &[]).unwrap();
        for &n in valences {
            let config = Configuration::regular(scheme.as_ref(), n).unwrap();
            let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
            group.bench_with_input(BenchmarkId::new(name, n), &analysis, |b, a| b.iter(|| run(scheme.as_ref(), a)));
        }
    }
    group.finish();
}

fn spectrum(c: &mut Criterion) {
    bench_group(c, "certify_spectrum", &SPECTRUM_SCHEMES, &[3, 5, 10, 25, 50, 100, 200], |s, a| {
        std::hint::black_box(subdlab::certify::certify_analysis(s, a).unwrap().verdict);
    });
}

fn charmap(c: &mut Criterion) {
    bench_group(c, "certify_charmap", &CHARMAP_SCHEMES, &[3, 5, 10, 25, 50], |s, a| {
        std::hint::black_box(certify_charmap(s, a, DEFAULT_MAX_LEVELS).unwrap().c1);
    });
}

fn charmap_difference(c: &mut Criterion) {
    bench_group(c, "certify_charmap_difference", &["sqrt3"], &[4, 5, 6, 8], |s, a| {
        std::hint::black_box(certify_charmap(s, a, DEFAULT_MAX_LEVELS).unwrap().c1);
    });
}

criterion_group!(benches, spectrum, charmap, charmap_difference);
criterion_main!(benches);
