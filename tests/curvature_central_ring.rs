//! The central-ring figure of a defective μ: where a block's eigenvectors all
//! vanish on the ring, the figure draws that block's generalised
//! eigenvectors (`curvature::figure_vectors`).

use faer::c64;
use faer::linalg::solvers::SolveLstsq;
use subdlab::curvature::jordan;
use subdlab::curvature::sampler::RingSampler;
use subdlab::curvature::{figure_vectors, VANISH_TOL};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::spectrum::{analyse, EigenVectors, Eigenvalue, Options};

/// Doo–Sabin at n = 5 has a defective eigenvalue at |μ| = λ² = 1/4 (its
/// block 0 carries the regular biquadratic's 1/4 with a Jordan chain, see
/// the README's curvature section). Hiding every eigenvector of that
/// eigenvalue, as if all vanished on the ring, must make the central-ring
/// figure draw the generalised eigenvectors of each of its blocks: a space
/// of the algebraic multiplicity's size per block, containing the hidden
/// eigenvectors (S − νI maps it into itself) and showing on the ring.
#[test]
fn hidden_eigenvectors_fall_back_to_the_generalised_eigenspace() {
    let scheme = subdlab::schemes::build("doo-sabin", &[]).unwrap();
    let config = Configuration::regular(scheme.as_ref(), 5).unwrap();
    let options = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &options).unwrap();
    let spec = &analysis.spectrum;
    let sampler = RingSampler::new(scheme.as_ref(), &analysis.discovered, 3).unwrap();
    let e = spec.eigenvalues.iter().find(|e| e.defective).expect("a defective eigenvalue");
    // every eigenvector present is drawn, nothing generalised
    let drawn = figure_vectors(spec, &sampler, e);
    assert!(!drawn.is_empty() && drawn.iter().all(|(_, _, kind)| kind.is_empty()));
    // the same eigenvalue with its eigenvectors hidden
    let hidden = Eigenvalue {
        vectors: e.blocks.iter().map(|&m| EigenVectors { block: m, right: Vec::new() }).collect(),
        ..e.clone()
    };
    let fallback = figure_vectors(spec, &sampler, &hidden);
    for &m in &e.blocks {
        let space: Vec<&Vec<c64>> = fallback.iter().filter(|(b, _, _)| *b == m).map(|(_, x, _)| x).collect();
        assert!(fallback.iter().filter(|(b, _, _)| *b == m).all(|(_, _, kind)| *kind == "generalised, "));
        // the block's algebraic multiplicity of ν, counted from its
        // eigenvalues (a Jordan chain of length k spreads the computed
        // eigenvalues by about eps^(1/k) around ν)
        let nu = c64::new(e.re, e.im);
        let block_eigenvalues = spec.synthesis.block(m).eigenvalues().unwrap();
        let algebraic = block_eigenvalues.iter().filter(|z| (**z - nu).norm() < 1e-5).count();
        assert_eq!(space.len(), algebraic, "block {m}: generalised eigenspace of dimension {algebraic}");
        assert!(space.iter().any(|x| jordan::ring_size_c(&sampler, x) > VANISH_TOL));
        // each hidden eigenvector of block m lies in the span: the
        // residual of its least-squares projection is rounding
        for (_, x, _) in drawn.iter().filter(|(b, _, _)| *b == m) {
            let a = faer::Mat::<c64>::from_fn(x.len(), space.len(), |i, j| space[j][i]);
            let rhs = faer::Mat::<c64>::from_fn(x.len(), 1, |i, _| x[i]);
            let qr = a.qr();
            let coef = qr.solve_lstsq(&rhs);
            let fit = &a * &coef;
            let residual = (0..x.len()).map(|i| (fit[(i, 0)] - x[i]).norm()).fold(0.0, f64::max);
            let size = x.iter().map(|z| z.norm()).fold(0.0, f64::max);
            assert!(residual < 1e-8 * size, "block {m}: eigenvector outside the generalised eigenspace ({residual:e})");
        }
    }
}
