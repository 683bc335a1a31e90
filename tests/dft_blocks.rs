//! The Fourier block decomposition must not change the spectrum: the union of
//! the block spectra equals the spectrum of the full matrix, and the rotation
//! permutation commutes with S.

use crate::common;
use common::*;
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::spectrum::Method;

fn assert_same_complex_multiset(a: Vec<(f64, f64)>, b: Vec<(f64, f64)>, tol: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    let mut unused = b.clone();
    for x in &a {
        let k = unused
            .iter()
            .position(|y| ((x.0 - y.0).powi(2) + (x.1 - y.1).powi(2)).sqrt() < tol)
            .unwrap_or_else(|| panic!("{what}: {x:?} from the blocks is not in the full spectrum {b:?}"));
        unused.remove(k);
    }
}

#[test]
fn union_of_block_spectra_equals_full_spectrum_for_valences_3_to_12() {
    for scheme in ["catmull-clark", "loop", "doo-sabin"] {
        for n in 3..=12 {
            for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
                let dft = run(scheme, n, kind, Some(Method::Dft), false);
                let full = run(scheme, n, kind, Some(Method::Full), false);
                assert_eq!(dft.spectrum.blocks.len(), n);
                let total: usize = dft.spectrum.blocks.iter().map(|b| b.size).sum();
                assert_eq!(total, full.spectrum.matrix_size, "block sizes add up");
                assert_same_complex_multiset(
                    expanded(&dft),
                    expanded(&full),
                    1e-7,
                    &format!("{scheme} n={n} {kind:?}"),
                );
            }
        }
    }
}

#[test]
fn rotation_commutes_with_s_and_has_order_n() {
    // every built-in mesh scheme's rules commute with the rotation of its
    // regular configuration
    for scheme in mesh_scheme_names() {
        for n in 3..=9 {
            let a = run(scheme, n, NeighbourhoodKind::Analysis, None, false);
            let s = a.matrix.to_dense_f64();
            let p = a.matrix.rotation(1, n);
            let size = s.len();
            // (PS)[p(i)][p(j)] = S[i][j]
            for i in 0..size {
                for j in 0..size {
                    assert!((s[p[i]][p[j]] - s[i][j]).abs() < 1e-15, "{scheme} n={n}: S not rotation invariant");
                }
            }
            let mut q: Vec<usize> = (0..size).collect();
            for _ in 0..n {
                q = q.iter().map(|&k| p[k]).collect();
            }
            assert_eq!(q, (0..size).collect::<Vec<_>>(), "P^n = I");
        }
    }
}

#[test]
fn rows_of_s_sum_to_one() {
    // affine invariance of every rule of every built-in mesh scheme
    for scheme in mesh_scheme_names() {
        for n in [3, 5, 8, 13] {
            let a = run(scheme, n, NeighbourhoodKind::Analysis, None, false);
            for row in &a.matrix.rows {
                let s: f64 = row.iter().map(|e| e.1).sum();
                assert!((s - 1.0).abs() < 1e-14, "{scheme} n={n}: row sum {s}");
            }
        }
    }
}

/// The same agreement above valence 12, at primes and composites (13, 17,
/// 24, 31), for one scheme of every refinement host (the registry's first
/// mesh scheme on each). Defective clusters (Doo–Sabin's 1/4, non-box's
/// repeated eigenvalues) split by about √eps on the whole-matrix path, so the
/// match tolerance is 1e-6 here.
#[test]
fn union_of_block_spectra_equals_full_spectrum_above_valence_12() {
    let mut hosts = Vec::new();
    let one_per_host: Vec<&str> = mesh_scheme_names()
        .into_iter()
        .filter(|name| {
            let topology = common::scheme(name).topology();
            let new = !hosts.contains(&topology);
            hosts.push(topology);
            new
        })
        .collect();
    for scheme in one_per_host {
        for n in [13, 17, 24, 31] {
            let dft = run(scheme, n, NeighbourhoodKind::Analysis, Some(Method::Dft), false);
            let full = run(scheme, n, NeighbourhoodKind::Analysis, Some(Method::Full), false);
            let total: usize = dft.spectrum.blocks.iter().map(|b| b.size).sum();
            assert_eq!(total, full.spectrum.matrix_size, "{scheme} n={n}: block sizes add up");
            assert_same_complex_multiset(expanded(&dft), expanded(&full), 1e-6, &format!("{scheme} n={n}"));
            // the verdict and the subdominant eigenvalue agree too
            assert_eq!(dft.spectrum.verdict.c1_spectral, full.spectrum.verdict.c1_spectral, "{scheme} n={n}");
            let (l1, l2) = (dft.spectrum.verdict.subdominant.unwrap(), full.spectrum.verdict.subdominant.unwrap());
            assert!((l1 - l2).abs() < 1e-9, "{scheme} n={n}: λ1 {l1} vs {l2}");
        }
    }
}
