//! Jordan blocks in floating point where S has irrational weights
//! (cos(2πk/n) at n = 5, 7, 8, 12), at two distinct eigenvalues at once, next
//! to repeated eigenvalues that are not defective and must not be flagged.
//!
//! The scheme is written here so that its Fourier blocks are known in closed
//! form (a hand derivation, below), not read off the program. It is
//! Catmull–Clark's host (`primal-quad`) on the centre v, its edge neighbours
//! e_j and face neighbours f_j (f_j in quad [v, e_j, f_j, e_{j+1}]): the
//! minimal neighbourhood, 2n + 1 points (the face rule reaches no further,
//! and the vertex and edge rules next to v only reach the one-ring).
//!
//! Rules next to the extraordinary vertex v (valence n):
//! - vertex: v' = v/2 + (1/2n) Σ e_j;
//! - face: f_j' = (v + e_j + f_j + e_{j+1})/4;
//! - edge (`edge-extraordinary`, the edge v-e_i, weights relative to i):
//!   e_i' = 3/8 v + Σ_j s_{j−i} e_j + Σ_j t_{j−i} f_j with
//!   s_k = (1/n) Σ_m σ(m) cos(2πkm/n) and t_k = u_k + u_{k+1},
//!   u_k = (1/n) Σ_m κ(m) cos(2πkm/n), σ and κ real and symmetric
//!   (σ(m) = σ(n − m)), so Σ_k s_k ω^{mk} = σ(m) and
//!   Σ_k t_k ω^{mk} = κ(m)(1 + ω^{−m}), ω = exp(2πi/n).
//!
//! Fourier block m ≥ 1 on (e, f) (data e_j = ω^{mj} E, f_j = ω^{mj} F):
//!   B_m = [[σ(m), κ(m)(1 + ω^{−m})], [(1 + ω^m)/4, 1/4]],
//! trace σ + 1/4, determinant σ/4 − κ|1 + ω^m|²/4, discriminant
//! (σ − 1/4)² + κ(2 + 2 cos(2πm/n)). With d = min(m, n − m):
//! - d = 1: σ = 3/4, κ = −(1/4)²/(2 + 2 cos) = −1/(8(1 + cos(2πm/n))): a double
//!   root (σ + 1/4)/2 = 1/2, and B_m − I/2 ≠ 0 (its lower left (1 + ω^m)/4 ≠ 0):
//!   one eigenvector, a 2 × 2 Jordan block, in blocks 1 and n − 1;
//! - d = 2: σ = 1/2, κ = −(1/4)²/(2 + 2 cos) = −1/(32(1 + cos)): a Jordan block
//!   at 3/8 in blocks 2 and n − 2 (distinct from blocks 1, n − 1 for n ≥ 5);
//! - d ≥ 3, m ≠ n/2: σ = 1/8, κ = 1/32: discriminant (5 + 4 cos)/64 > 0, two
//!   simple roots (3 ± sqrt(5 + 4 cos(2πm/n)))/16, irrational for these n,
//!   each also in block n − m (the conjugate block): twice, not defective;
//! - m = n/2 (n even): 1 + ω^m = 0, B_m = diag(1/8, 1/4).
//! Block 0 on (v, e, f), with σ(0) = 5/8 and κ(0) = 0 (the edge row sums to
//! 3/8 + 5/8 = 1): [[1/2, 1/2, 0], [3/8, 5/8, 0], [1/4, 1/2, 1/4]], eigenvalues
//! 1, 1/8 (the upper left 2 × 2: trace 9/8, determinant 1/8) and 1/4.
//!
//! So: 1/2 and 3/8 have algebraic multiplicity 4 and geometric 2 (n ≥ 5);
//! 1/4 and 1/8 occur 1 + [n even] times, each non-defective; the d ≥ 3 roots
//! twice each, non-defective. The formulas divide by 1 + cos(2πm/n) only where
//! d ∈ {1, 2} (then cos > −1 for n ≥ 5); `kronecker(n − 2m)` keeps the division
//! finite at m = n/2, where κ is multiplied by 1 + ω^m = 0 anyway.

use crate::common;

use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::schemes;
use subdlab::spectrum::{analyse, Analysis, Method, Options};

/// [d = k] for d = min(m, n − m): 2d = n − |n − 2m|.
const SCHEME: &str = r#"name = "jordan-two-irrational"
description = "Fourier-designed edge rule: Jordan blocks at 1/2 and 3/8 with irrational weights"
topology = "primal-quad"

[vertex]
centre = "1/2"
edge = "1 / (2 n)"
face = "0"

[edge]
ends = "3/8"
side = "1/16"

[face]
corner = "1 / n"

# sigma(m) = 1/8 + (1/2) [d = 0] + (5/8) [d = 1] + (3/8) [d = 2]
# kappa(m) = -[d = 1]/(8 (1 + cos)) - [d = 2]/(32 (1 + cos)) + [d >= 3]/32
[edge-extraordinary]
centre = "3/8"
edge = "sum(m, 0, n-1, (1/8 + kronecker(n - abs(n-2m))/2 + 5 kronecker(n - abs(n-2m) - 2)/8 + 3 kronecker(n - abs(n-2m) - 4)/8) cos(2 pi j m / n)) / n"
face = "sum(m, 0, n-1, ((-kronecker(n - abs(n-2m) - 2)/8 - kronecker(n - abs(n-2m) - 4)/32) / (1 + cos(2 pi m / n) + kronecker(n - 2 m)) + (1 - kronecker(n - abs(n-2m)) - kronecker(n - abs(n-2m) - 2) - kronecker(n - abs(n-2m) - 4))/32) (cos(2 pi j m / n) + cos(2 pi (j + 1) m / n))) / n"
"#;

/// (value, algebraic, geometric) of the derivation in the module doc.
fn derived(n: usize) -> Vec<(f64, usize, usize)> {
    let mut want = vec![(1.0, 1, 1), (0.5, 4, 2), (0.375, 4, 2)];
    let even = usize::from(n % 2 == 0);
    want.push((0.25, 1 + even, 1 + even));
    want.push((0.125, 1 + even, 1 + even));
    for m in 3..n.div_ceil(2) {
        let r = (5.0 + 4.0 * common::cos2pi(m, n)).sqrt();
        want.push(((3.0 + r) / 16.0, 2, 2));
        want.push(((3.0 - r) / 16.0, 2, 2));
    }
    want
}

fn spectrum(n: usize, method: Method, exact: bool) -> Analysis {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("jordan.toml");
    std::fs::write(&file, SCHEME).unwrap();
    let s = schemes::resolve(file.to_str().unwrap(), &[]).unwrap();
    let config = Configuration::regular(s.as_ref(), n).unwrap();
    analyse(s.as_ref(), &config, &Options { neighbourhood: NeighbourhoodKind::Minimal, method: Some(method), exact })
        .unwrap()
}

#[test]
fn two_defective_eigenvalues_with_irrational_weights() {
    for n in [5, 7, 8, 12] {
        for method in [Method::Dft, Method::Full] {
            let a = spectrum(n, method, false);
            let what = format!("n = {n}, {method:?}");
            assert_eq!(a.spectrum.matrix_size, 2 * n + 1, "{what}");
            let want = derived(n);
            let got = &a.spectrum.eigenvalues;
            assert_eq!(got.len(), want.len(), "{what}: {got:?}");
            for (value, alg, geo) in &want {
                // defective eigenvalues split by about sqrt(eps): 1e-6 is ample
                let e = got
                    .iter()
                    .find(|e| (e.re - value).abs() < 1e-6 && e.im.abs() < 1e-6)
                    .unwrap_or_else(|| panic!("{what}: no eigenvalue {value} in {got:?}"));
                assert_eq!(
                    (e.algebraic_multiplicity, e.geometric_multiplicity, e.defective),
                    (*alg, *geo, geo < alg),
                    "{what}: eigenvalue {value}"
                );
            }
            let defective: Vec<f64> = got.iter().filter(|e| e.defective).map(|e| e.re).collect();
            assert_eq!(defective.len(), 2, "{what}: exactly 1/2 and 3/8 are defective, not {defective:?}");
        }
    }
}

/// The weights are irrational: the exact path cannot assemble S (a weight
/// such as s_1 = (1/n) Σ σ(m) cos(2πm/n) is no rational at n = 7), so the
/// multiplicities above came from the floating-point route alone.
#[test]
fn the_weights_are_irrational() {
    for n in [5, 7] {
        let a = spectrum(n, Method::Dft, true);
        assert!(a.exact_matrix.is_none(), "n = {n}: S was assembled exactly");
        assert!(a.spectrum.eigenvalues.iter().all(|e| e.exact.is_none()), "n = {n}");
    }
}
