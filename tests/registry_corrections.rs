//! The claims added by issue 13's registry corrections, each reached by a
//! derivation independent of the claim machinery: hand-built matrices in
//! exact rationals, closed-form counts, tensor products of univariate rules.

use crate::common;
use common::exact::{algebraic, q};

use num_traits::{One, Zero};
use subdlab::claims::{evaluate, Outcome, Verdict};
use subdlab::numeric::Rational;

fn verdict(paper: &str, id: &str, want: Verdict) -> Outcome {
    let o = common::registry_outcome_in(paper, id);
    assert_eq!(o.verdict, want, "{id}: {} / {} / {}", o.stated, o.computed, o.detail);
    o
}

/// Lemma 3.5's M at n = 4 (cos(2π(i − j)/4) ∈ {1, 0, −1, 0}: rational), in
/// the matrix convention α_M = 1 − c with the centre weight c.
fn m_matrix(c: Rational) -> Vec<Vec<Rational>> {
    let n = 4i64;
    let al = Rational::one() - c;
    let cosq = |d: i64| match d.rem_euclid(4) {
        0 => 1,
        2 => -1,
        _ => 0,
    };
    let mut m = vec![vec![Rational::zero(); 5]; 5];
    m[0][0] = Rational::one() - al.clone();
    for row in m.iter_mut().skip(1) {
        row[0] = q(1, 2);
    }
    for x in m[0].iter_mut().skip(1) {
        *x = al.clone() / Rational::from_integer(n.into());
    }
    for i in 0..4 {
        for j in 0..4 {
            // (I + E + C)/4, E = 1/n, C = (2/n) cos(2π(i − j)/n)
            let e = q(1, n) + q(2 * cosq(i - j), n) + if i == j { Rational::one() } else { Rational::zero() };
            m[i as usize + 1][j as usize + 1] = e / Rational::from_integer(4.into());
        }
    }
    m
}

/// S on the analysis neighbourhood of the 4-3 eon QTQT (n = 4), exact.
fn s_exact(c: &str) -> Vec<Vec<Rational>> {
    let scheme = subdlab::schemes::build("four-three", &[("centre_weight".into(), c.into())]).unwrap();
    let config = subdlab::neighbourhood::Configuration::with_faces(scheme.as_ref(), 4, "QTQT").unwrap();
    let a = subdlab::spectrum::analyse(scheme.as_ref(), &config, &subdlab::spectrum::Options::default()).unwrap();
    let exact = a.exact_matrix.expect("n = 4 has rational weights");
    let n = exact.rows.len();
    let mut d = vec![vec![Rational::zero(); n]; n];
    for (i, row) in exact.rows.iter().enumerate() {
        for (j, w) in row {
            d[i][*j] = w.clone();
        }
    }
    d
}

// ------------------------------------------------- Theorem 3.7 at α = 1/4

#[test]
fn theorem37_boundary_in_the_matrix_convention_has_one_quarter_more() {
    // α_M = 1/4 (c = 3/4): Lemma 3.5's α = 1/4 case, n − 2 = 2 in M (exact)
    let m = m_matrix(q(3, 4));
    assert_eq!(algebraic(&m, &q(1, 4)), 2);
    // in all of S (QTQT: n = 4, two quads): n + n_quad − 2 = 4, not the stated 3
    let s = s_exact("3/4");
    assert_eq!(algebraic(&s, &q(1, 4)), 4 + 2 - 2);
    verdict("peters-shiue", "ps.theorem3.7-boundary-quarter-Mconv", Verdict::Refuted);
    // and 1/2 − α_M = 1/4 > 0: no negative eigenvalue in M
    assert_eq!(algebraic(&m, &q(-1, 4)), 0);
    verdict("peters-shiue", "ps.theorem3.7-boundary-positive-Mconv", Verdict::Holds);
}

#[test]
fn theorem37_boundary_in_figure4s_convention_has_minus_a_quarter() {
    // α = c = 1/4, α_M = 3/4: 1/2 − α_M = −1/4 is an eigenvalue of M (exact)
    let m = m_matrix(q(1, 4));
    assert_eq!(algebraic(&m, &q(-1, 4)), 1);
    assert_eq!(algebraic(&m, &q(1, 4)), 4 - 3);
    let s = s_exact("1/4");
    // the value 1/4: n + n_quad − 3 = 3 as stated; modulus 1/4: one more
    assert_eq!(algebraic(&s, &q(1, 4)), 4 + 2 - 3);
    assert_eq!(algebraic(&s, &q(1, 4)) + algebraic(&s, &q(-1, 4)), 4 + 2 - 2);
    verdict("peters-shiue", "ps.theorem3.7-boundary-quarter-fig4-values", Verdict::Holds);
    verdict("peters-shiue", "ps.theorem3.7-boundary-quarter-fig4-moduli", Verdict::Refuted);
    verdict("peters-shiue", "ps.theorem3.7-boundary-positive", Verdict::Refuted);
}

// ------------------------------------------ the transition node's limit stencil

#[test]
fn transition_node_limit_stencil_by_hand() {
    // v, e0..e4 (quads between e0, e1 and e1, e2), f0, f1 (their diagonals);
    // the rules of ARCHITECTURE.md's 4-3 table, typed here
    let (v, e, f0, f1) = (0usize, [1usize, 2, 3, 4, 5], 6usize, 7usize);
    let mut s = vec![vec![Rational::zero(); 8]; 8];
    let mut put = |r: usize, terms: &[(usize, i64)], den: i64| {
        for &(c, w) in terms {
            s[r][c] += q(w, den);
        }
    };
    put(v, &[(v, 18), (e[1], 4), (e[0], 3), (e[2], 3), (e[3], 2), (e[4], 2)], 32);
    put(e[1], &[(v, 6), (e[1], 6), (f0, 1), (f1, 1), (e[0], 1), (e[2], 1)], 16);
    put(e[0], &[(v, 6), (e[0], 6), (e[1], 1), (f0, 1), (e[4], 2)], 16);
    put(e[2], &[(v, 6), (e[2], 6), (e[1], 1), (f1, 1), (e[3], 2)], 16);
    put(e[3], &[(v, 3), (e[3], 3), (e[2], 1), (e[4], 1)], 8);
    put(e[4], &[(v, 3), (e[4], 3), (e[3], 1), (e[0], 1)], 8);
    put(f0, &[(v, 1), (e[0], 1), (e[1], 1), (f0, 1)], 4);
    put(f1, &[(v, 1), (e[1], 1), (e[2], 1), (f1, 1)], 4);
    // the left eigenvector of 1: l (S − I) = 0 with Σ l = 1, solved exactly as
    // the (S − I)ᵀ system with the last equation replaced by the sum
    let mut a: Vec<Vec<Rational>> = (0..8)
        .map(|i| {
            let mut row: Vec<Rational> =
                (0..8).map(|j| s[j][i].clone() - if i == j { Rational::one() } else { Rational::zero() }).collect();
            row.push(Rational::zero());
            row
        })
        .collect();
    a[7] = vec![Rational::one(); 9];
    for c in 0..8 {
        let p = (c..8).find(|&i| !a[i][c].is_zero()).unwrap();
        a.swap(c, p);
        let piv = a[c][c].clone();
        for x in a[c].iter_mut() {
            *x = x.clone() / piv.clone();
        }
        let pivot = a[c].clone();
        for (i, row) in a.iter_mut().enumerate().take(8) {
            if i != c && !row[c].is_zero() {
                let fct = row[c].clone();
                for (x, p) in row.iter_mut().zip(&pivot).take(9) {
                    let t = fct.clone() * p.clone();
                    *x -= t;
                }
            }
        }
    }
    let l: Vec<Rational> = a.iter().map(|r| r[8].clone()).collect();
    let want = [q(41, 90), q(19, 180), q(23, 180), q(19, 180), q(1, 12), q(1, 12), q(7, 360), q(7, 360)];
    assert_eq!(l, want);
    verdict("peters-shiue", "ps.S43-limit-stencil", Verdict::Holds);
}

// ------------------------------------------------------- TPS's rules (17)

#[test]
fn tps_rules_are_tensor_products_of_ternary_quadratic_rules() {
    // univariate ternary quadratic B-spline: symbol (1 + z + z²)³/9; its three
    // sub-masks by the residue of the fine index mod 3
    let coeffs = [1i64, 3, 6, 7, 6, 3, 1];
    let sub = |r: usize| -> Vec<Rational> { coeffs.iter().skip(r).step_by(3).map(|&c| q(c, 9)).collect() };
    assert_eq!(sub(0), vec![q(1, 9), q(7, 9), q(1, 9)]);
    assert_eq!(sub(1), vec![q(3, 9), q(6, 9)]);
    let (centre, near) = ([q(1, 9), q(7, 9), q(1, 9)], [q(2, 3), q(1, 3)]);
    // a_i^new (on spoke i, a third of the way from q): near ⊗ centre, /27
    let printed_a = [(q(14, 27), (0, 1)), (q(7, 27), (1, 1)), (q(2, 27), (0, 0)), (q(1, 27), (1, 0))];
    for (w, (x, y)) in printed_a {
        assert_eq!(w, near[x].clone() * centre[y].clone());
    }
    // b, c, d, e: near ⊗ near with weights 4, 2, 2, 1 over 9
    for (w, (x, y)) in [(q(4, 9), (0, 0)), (q(2, 9), (0, 1)), (q(2, 9), (1, 0)), (q(1, 9), (1, 1))] {
        assert_eq!(w, near[x].clone() * near[y].clone());
    }
    verdict("karciauskas-peters", "tps.rules17-ternary", Verdict::Holds);
}

// ------------------------------------------------ size statements, both readings

/// Points of rings 1..r of one sector of the tool's charts: a quad sector
/// holds (i, j) with max(i, j) = ring, i ≥ 1, j ≥ 0 (its spoke j = 0, the next
/// spoke belongs to the next sector); a triangle sector i + j = ring.
fn sector_points(quad: bool, r: i64, cut: Option<i64>) -> usize {
    let mut k = 0;
    for i in 1..=r {
        for j in 0..=r {
            let ring = if quad { i.max(j) } else { i + j };
            // i ≥ 1 leaves the next sector's spoke (0, j) to that sector
            if ring <= r && cut.is_none_or(|c| i + j <= c) {
                k += 1;
            }
        }
    }
    k
}

#[test]
fn closed_form_counts_of_the_stated_sets() {
    // quad sector rings 1..2: 2 + 4; rings 1..3 cut at i + j ≤ 4: 2 + 4 + 3
    assert_eq!(sector_points(true, 2, None), 6);
    assert_eq!(sector_points(true, 3, Some(4)), 9);
    assert_eq!(sector_points(false, 3, Some(4)), 6);
    for n in 3..=12usize {
        for quads in 0..=n {
            let s = 1 + quads * sector_points(true, 3, Some(4)) + (n - quads) * sector_points(false, 3, Some(4));
            assert_eq!(s, 1 + 6 * n + 3 * quads, "Peters–Shiue's s");
        }
        // Huang: rings 0..2 of quads (6 per sector) and the FCVs of their 4 faces
        assert_eq!(1 + n * (sector_points(true, 2, None) + 4), 1 + 10 * n);
    }
}

#[test]
fn every_size_statement_holds_in_the_suffices_reading() {
    for (paper, id) in [
        ("huang-nonbox", "nonbox.neighbourhood-suffices"),
        ("peters-shiue", "ps.matrix-size-suffices"),
        ("karciauskas-peters", "pgs.size-suffices"),
        ("karciauskas-peters", "polar.size-suffices"),
        ("karciauskas-peters", "tps.size-suffices"),
    ] {
        let o = verdict(paper, id, Verdict::Holds);
        assert!(o.computed.contains("invariant (exact rows)"), "{id}: {}", o.computed);
    }
    // the 'equals the tool's size' readings stay as they were
    verdict("huang-nonbox", "nonbox.neighbourhood-size", Verdict::Refuted);
    verdict("peters-shiue", "ps.matrix-size", Verdict::Refuted);
    // PGS: 10n × 10n with p replicated is 9n + 1 points; the analysis set is smaller
    let o = verdict("karciauskas-peters", "pgs.size", Verdict::Refuted);
    assert!(o.stated.contains(&format!("n=3: {}", 9 * 3 + 1)), "{}", o.stated);
}

#[test]
fn a_set_that_misses_the_analysis_points_or_is_not_invariant_is_refuted() {
    let run = |body: &str| {
        let text = format!(
            "paper = \"t\"\ntitle = \"t\"\n\n[[claim]]\nid = \"c\"\nlocation = \"-\"\nstatement = \"-\"\ncheck = \"invariant-set\"\nscheme = \"catmull-clark\"\nvalences = [5]\n{body}"
        );
        evaluate(&subdlab::claims::parse_file("t.toml", &text).unwrap()).pop().unwrap()
    };
    // rings 0..1 (2n + 1, Catmull–Clark's minimal set): invariant, not enough for the analysis
    let o = run("rings = \"1\"\nvalue = \"2 n + 1\"");
    assert_eq!(o.verdict, Verdict::Refuted, "{}", o.computed);
    assert!(o.computed.contains("lacks"), "{}", o.computed);
    // edge points of rings 0..2 without the face points: Catmull–Clark's
    // vertex rule reads the face neighbours, so it is not invariant
    let o = run("rings = \"2\"\nkinds = [\"centre\", \"edge\"]\nvalue = \"2 n + 1\"");
    assert_eq!(o.verdict, Verdict::Refuted, "{}", o.computed);
    assert!(o.computed.contains("not invariant"), "{}", o.computed);
    // a stated size the built set does not have cannot be decided
    let o = run("rings = \"2\"\nvalue = \"5 n + 1\"");
    assert_eq!(o.verdict, Verdict::Inconclusive, "{}", o.detail);
}

// --------------------------------------------------- Lin–Luo's λ3 = λ4, two readings

#[test]
fn equal_values_is_the_stricter_reading_of_lambda3_equals_lambda4() {
    let moduli = verdict("lin-luo", "linluo.section6", Verdict::Refuted);
    let values = verdict("lin-luo", "linluo.section6-values", Verdict::Refuted);
    let count = |o: &Outcome| o.computed.split(' ').next().unwrap().parse::<usize>().unwrap();
    // equal values imply equal moduli: every case failing the moduli reading fails the other
    assert!(count(&values) >= count(&moduli), "{} / {}", values.computed, moduli.computed);
    // Kobbelt at n = 4 (α = 0): the third and fourth moduli 4/81 and 0.041… differ
    assert!(moduli.detail.contains("alpha=0, n=4"), "{}", moduli.detail);
}
