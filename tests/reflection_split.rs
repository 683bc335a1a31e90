//! The reflection split of a tagged vertex's local matrix
//! (`spectrum::reflection`, issue 26), checked in exact rational arithmetic.
//!
//! 1. The rules of Hoppe et al. (and BLZ's) do not prefer a direction, so
//!    S commutes exactly with the reflection that keeps the sharp rays.
//! 2. In the basis of even vectors e_b + e_Pb and odd vectors e_b − e_Pb,
//!    S = diag(E, O), so det(x − S) = det(x − E) · det(x − O) exactly: the
//!    union of the blocks' spectra is S's, with multiplicity. Negative
//!    control: a permutation S does not commute with (the reflection about
//!    the wrong axis, composed with a swap) fails the commutation test, and
//!    its "blocks" do not factor det(x − S).
//! 3. Which block holds what, by hand (boundary vertex, Catmull–Clark): the
//!    curve's eigenvectors on (c, v_0, v_k) are (1, 1, 1) for 1 and
//!    (1, −2, −2) for 1/4 — even under v_0 ↔ v_k — and the tangent
//!    (0, 1, −1) for 1/2 — odd. The interior's sine mode m,
//!    v_j = sin(jmπ/k), goes under j ↦ k − j to
//!    sin(mπ − jmπ/k) = (−1)^(m+1) sin(jmπ/k): even for odd m, odd for even
//!    m. So at k = 2 (m = 1 at 1/2) the two 1/2s lie in different blocks
//!    (simple in each: non-defective), while at k = 4 mode m = 2 (at 1/2)
//!    shares the odd block with the tangent, where it couples into a Jordan
//!    block: O − 1/2 has rank size − 1 with 1/2 a double root of det(x − O),
//!    and 1/2 is not an eigenvalue of E at all.

use crate::common::exact::{q, rank};
use num_traits::{One, Zero};
use subdlab::neighbourhood::{Configuration, Tagging};
use subdlab::numeric::berkowitz::charpoly;
use subdlab::numeric::Rational;
use subdlab::schemes;
use subdlab::spectrum::reflection::{commutes, reflection_of, split};
use subdlab::spectrum::{analyse, Options};

/// The exact dense S and its reflection at a tagged configuration.
fn exact(scheme: &str, n: usize, tagging: Tagging) -> (Vec<Vec<Rational>>, Vec<usize>) {
    let s = schemes::build(scheme, &[]).unwrap();
    let config = Configuration::tagged(s.as_ref(), n, None, tagging).unwrap();
    let opts = Options { exact: true, ..Options::default() };
    let an = analyse(s.as_ref(), &config, &opts).unwrap();
    let m = an.exact_matrix.as_ref().expect("Hoppe's rules are rational");
    let image = reflection_of(&config, &m.labels).expect("the set is mapped onto itself");
    (m.dense(), image)
}

fn mul(a: &[Rational], b: &[Rational]) -> Vec<Rational> {
    let mut out = vec![Rational::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// p(x) by Horner (coefficients lowest first).
fn eval(p: &[Rational], x: &Rational) -> Rational {
    p.iter().rev().fold(Rational::zero(), |acc, c| acc * x + c)
}

/// The multiplicity of the root x of p.
fn root_multiplicity(p: &[Rational], x: &Rational) -> usize {
    let mut p = p.to_vec();
    let mut m = 0;
    while p.len() > 1 && eval(&p, x).is_zero() {
        // synthetic division by (t − x)
        let mut quotient = vec![Rational::zero(); p.len() - 1];
        let mut carry = Rational::zero();
        for k in (1..p.len()).rev() {
            carry = &p[k] + carry * x;
            quotient[k - 1] = carry.clone();
        }
        p = quotient;
        m += 1;
    }
    m
}

fn check_factorisation(scheme: &str, n: usize, tagging: Tagging) {
    let (s, image) = exact(scheme, n, tagging);
    let what = format!("{scheme} {} n = {n}", tagging.name());
    assert!((0..s.len()).all(|v| image[image[v]] == v), "{what}: an involution");
    assert!(commutes(&s, &image, |x, y| x == y), "{what}: S P = P S exactly");
    let b = split(&s, &image);
    assert_eq!(b.even.len() + b.odd.len(), s.len(), "{what}");
    let whole = charpoly(&s);
    let product = mul(&charpoly(&b.even), &charpoly(&b.odd));
    assert_eq!(whole, product, "{what}: det(x − S) = det(x − E) det(x − O)");
}

#[test]
fn block_spectra_are_the_whole_spectrum_exactly() {
    for k in 1..=6 {
        check_factorisation("catmull-clark", k, Tagging::Boundary);
        check_factorisation("loop", k, Tagging::Boundary);
    }
    check_factorisation("catmull-clark", 3, Tagging::Corner);
    check_factorisation("loop", 4, Tagging::Corner);
    // creases: k1 = k2 and k1 ≠ k2 (each side onto itself, the sharp rays swapped)
    check_factorisation("catmull-clark", 4, Tagging::Crease { at: 2 });
    check_factorisation("catmull-clark", 5, Tagging::Crease { at: 2 });
    check_factorisation("loop", 6, Tagging::Crease { at: 3 });
    check_factorisation("loop", 7, Tagging::Crease { at: 2 });
    check_factorisation("catmull-clark", 5, Tagging::Dart);
}

/// Negative control: swapping the centre and v_0 is not a symmetry of S, and its "blocks" do
/// not factor det(x − S).
#[test]
fn a_wrong_permutation_neither_commutes_nor_factors() {
    let (s, image) = exact("catmull-clark", 3, Tagging::Boundary);
    // the transposition of the centre (fixed by the reflection) and v_0
    // (matrix indices 0 and 1: the centre, then ring 1 from sector 0's ray)
    assert_eq!(image[0], 0);
    let mut wrong: Vec<usize> = (0..s.len()).collect();
    wrong.swap(0, 1);
    assert!((0..s.len()).all(|v| wrong[wrong[v]] == v), "still an involution");
    assert!(!commutes(&s, &wrong, |x, y| x == y));
    let blocks = split(&s, &wrong);
    assert_ne!(charpoly(&s), mul(&charpoly(&blocks.even), &charpoly(&blocks.odd)));
}

/// Which block holds the curve's and the modes' eigenvalues (point 3 of the
/// module doc), exactly.
#[test]
fn the_tangent_is_odd_and_couples_with_even_modes_only() {
    let (one, half, quarter) = (Rational::one(), q(1, 2), q(1, 4));
    // k = 2: 1/2 once in each block, so non-defective
    let (s, image) = exact("catmull-clark", 2, Tagging::Boundary);
    let b = split(&s, &image);
    let (pe, po) = (charpoly(&b.even), charpoly(&b.odd));
    assert_eq!(root_multiplicity(&pe, &one), 1);
    assert_eq!(root_multiplicity(&po, &one), 0);
    assert_eq!(root_multiplicity(&pe, &half), 1, "mode m = 1 is even");
    assert_eq!(root_multiplicity(&po, &half), 1, "the tangent is odd");
    assert!(root_multiplicity(&pe, &quarter) >= 1, "the curve's 1/4 is even");
    // k = 4: mode 2 and the tangent, both odd, make a Jordan block in O
    let (s, image) = exact("catmull-clark", 4, Tagging::Boundary);
    let b = split(&s, &image);
    let (pe, po) = (charpoly(&b.even), charpoly(&b.odd));
    assert_eq!(root_multiplicity(&pe, &half), 0, "1/2 is not even at k = 4");
    assert_eq!(root_multiplicity(&po, &half), 2);
    let shifted: Vec<Vec<Rational>> = b
        .odd
        .iter()
        .enumerate()
        .map(|(i, row)| row.iter().enumerate().map(|(j, x)| if i == j { x - &half } else { x.clone() }).collect())
        .collect();
    assert_eq!(rank(shifted), b.odd.len() - 1, "one eigenvector for the double 1/2: defective");
}

/// The per-block spectra the `spectrum` command prints (floating point) are,
/// together, the whole matrix's spectrum with multiplicity; an interior
/// (untagged) vertex has no such split here.
#[test]
fn printed_block_spectra_make_up_the_whole_spectrum() {
    use subdlab::spectrum::reflection::reflection_spectra;
    for (scheme, n, tagging) in [
        ("catmull-clark", 4, Tagging::Boundary),
        ("loop", 6, Tagging::Crease { at: 3 }),
        ("catmull-clark", 5, Tagging::Dart),
    ] {
        let s = schemes::build(scheme, &[]).unwrap();
        let config = Configuration::tagged(s.as_ref(), n, None, tagging).unwrap();
        let an = analyse(s.as_ref(), &config, &Options { exact: false, ..Options::default() }).unwrap();
        let r = reflection_spectra(&config, &an.matrix.labels, &an.matrix.to_dense_f64()).unwrap().expect("symmetric");
        assert_eq!(r.even_size + r.odd_size, an.matrix.labels.len());
        let mut blocks: Vec<f64> = r
            .even
            .iter()
            .chain(&r.odd)
            .flat_map(|v| {
                assert!(v.im.abs() < 1e-9);
                std::iter::repeat_n(v.re, v.algebraic_multiplicity)
            })
            .collect();
        let mut whole = crate::common::real_spectrum(&an);
        blocks.sort_by(f64::total_cmp);
        whole.sort_by(f64::total_cmp);
        assert_eq!(blocks.len(), whole.len(), "{scheme} {n}");
        for (x, y) in blocks.iter().zip(&whole) {
            assert!((x - y).abs() < 1e-7, "{scheme} {n}: {blocks:?} against {whole:?}");
        }
    }
    let s = schemes::build("catmull-clark", &[]).unwrap();
    let config = Configuration::regular(s.as_ref(), 5).unwrap();
    let an = analyse(s.as_ref(), &config, &Options { exact: false, ..Options::default() }).unwrap();
    assert!(reflection_spectra(&config, &an.matrix.labels, &an.matrix.to_dense_f64()).unwrap().is_none());
}
