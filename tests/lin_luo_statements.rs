//! Lin–Luo, section 6: "Let C ∈ [0, 2] ... the leading eigenvalues of each
//! S̃ = RSS satisfy: for n > 3, λ0 = 1, λ1 = λ2 > λ3 = λ4; for n = 3,
//! λ0 = 1, λ1 = λ2 > λ3."
//!
//! Checked at valences 3, 4 and 6 (rational cosines) for α ∈ {0, 1/2, 1, 3/2, 2}
//! along a path independent of the tool's eigen-solver: the exact
//! characteristic polynomial of the two-step matrix, split into square-free
//! factors over Q, each factor's (simple) roots from its companion matrix.
//! The test requires the tool's floating-point spectrum to reach the same
//! verdict in every case, and records that the paper's blanket statement is
//! false: it fails at α = 2 for every valence checked (a real block-0
//! eigenvalue overtakes the subdominant pair), and at valence 3 for α = 1.

use faer::{c64, Mat};
use subdlab::matrix::assemble;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::numeric::exact::{Poly, QMatrix};
use subdlab::numeric::{Rational, Weight};
use subdlab::schemes;
use subdlab::spectrum::{analyse, Options};

/// Roots of a polynomial with simple roots, from its companion matrix.
fn simple_roots(p: &Poly) -> Vec<c64> {
    let d = p.degree();
    if d == 0 {
        return vec![];
    }
    let lead = p.coeffs[d].to_f64();
    let comp = Mat::<c64>::from_fn(d, d, |i, j| {
        if i == 0 {
            c64::new(-p.coeffs[d - 1 - j].to_f64() / lead, 0.0)
        } else if i == j + 1 {
            c64::new(1.0, 0.0)
        } else {
            c64::new(0.0, 0.0)
        }
    });
    comp.eigenvalues().unwrap()
}

/// The statement, evaluated on a list of eigenvalues with repetition.
fn statement_holds(mut l: Vec<c64>, n: usize) -> bool {
    l.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    let eq = |a: c64, b: c64| (a - b).norm() < 1e-7;
    let real = |a: c64| a.im.abs() < 1e-7;
    let lead = eq(l[0], c64::new(1.0, 0.0)) && l[1].norm() < 1.0 - 1e-9;
    let pair = real(l[1]) && eq(l[1], l[2]) && l[1].re > 0.0;
    let gap = l[2].norm() > l[3].norm() + 1e-7;
    // λ3 = λ4 read in modulus: a conjugate pair counts as equal
    let third = if n > 3 { (l[3].norm() - l[4].norm()).abs() < 1e-7 } else { true };
    lead && pair && gap && third
}

#[test]
fn section_6_eigenvalue_statement() {
    let scheme_for = |alpha: &str| schemes::build("unified-sqrt3", &[("alpha".into(), alpha.into())]).unwrap();
    let mut failures = Vec::new();
    for n in [3usize, 4, 6] {
        for alpha in ["0", "1/2", "1", "3/2", "2"] {
            let s = scheme_for(alpha);
            let config = Configuration::regular(s.as_ref(), n).unwrap();
            // independent path: exact characteristic polynomial
            let d = discover(s.as_ref(), &config).unwrap();
            let m = assemble::<Rational>(s.as_ref(), &d, NeighbourhoodKind::Analysis).unwrap();
            let mut q = QMatrix::zeros(m.size());
            for (i, row) in m.rows.iter().enumerate() {
                for (j, w) in row {
                    q.set(i, *j, w.clone());
                }
            }
            let mut roots = Vec::new();
            for (k, f) in q.charpoly().squarefree_factors().iter().enumerate() {
                for r in simple_roots(f) {
                    roots.extend(std::iter::repeat_n(r, k + 1));
                }
            }
            assert_eq!(roots.len(), m.size());
            let exact_verdict = statement_holds(roots, n);
            // the tool's floating-point spectrum
            let a = analyse(s.as_ref(), &config, &Options { exact: false, ..Options::default() }).unwrap();
            let float: Vec<c64> = a
                .spectrum
                .eigenvalues
                .iter()
                .flat_map(|e| std::iter::repeat_n(c64::new(e.re, e.im), e.algebraic_multiplicity))
                .collect();
            assert_eq!(statement_holds(float, n), exact_verdict, "n = {n}, alpha = {alpha}");
            if !exact_verdict {
                failures.push((n, alpha));
            }
        }
    }
    // the statement is refuted: it fails at α = 2 for every valence checked
    for n in [3, 4, 6] {
        assert!(failures.contains(&(n, "2")), "n = {n}: {failures:?}");
    }
    assert!(failures.contains(&(3, "1")), "{failures:?}");
}
