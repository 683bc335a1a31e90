//! Negative controls: for every check kind and every compare mode, a true
//! statement that HOLDS and a false one that must come out REFUTED with the
//! disagreement named. (The `curvature` kind has its own file,
//! tests/curvature_claims.rs; `identity` and `subdominant` are also in
//! tests/verify.rs.)
//!
//! Expected values, derived independently of the code:
//! - Loop on its minimal neighbourhood (the centre and its n neighbours):
//!   the edge point next to the centre is 3/8 v + 3/8 e_j + 1/8 (e_{j−1} +
//!   e_{j+1}), a circulant on the ring, so Fourier block m ≥ 1 is the 1 × 1
//!   matrix 3/8 + cos(2πm/n)/4 (Loop 1987). Block 0 on (v, mean e) is
//!   [[1 − nβ, nβ], [3/8, 5/8]]: eigenvalues 1 and 5/8 − nβ ≥ 0, so no
//!   eigenvalue is negative (3/8 + cos/4 ≥ 1/8).
//! - Catmull–Clark at n = 4 is the bicubic B-spline: the cubic B-spline's
//!   leading eigenvalues are 1, 1/2, 1/4, 1/8, so the tensor product leads
//!   with 1, 1/2 (twice: 1·1/2 and 1/2·1), 1/4 (three times: 1·1/4, 1/4·1,
//!   1/2·1/2).
//! - Catmull–Clark's λ1 = (5 + c + sqrt((c + 1)(c + 9)))/16, c = cos(2π/n)
//!   (Doo–Sabin 1978 / Ball–Storry): at n = 3 that is 0.4101 < 1/2, at n = 4
//!   exactly 1/2; its limit stencil is (n² v + 4 Σ e_j + Σ f_j)/(n (n + 5))
//!   (Halstead–Kass–DeRose 1993); its analysis neighbourhood is rings 0..2,
//!   1 + 2n + 4n = 6n + 1 vertices.
//! - Loop's tangents are Σ cos(2πj/n) e_j and Σ sin(2πj/n) e_j (Loop 1987).
//!   The block-2 patterns cos(4πj/n), sin(4πj/n) span another plane for
//!   n ≥ 5 (they are orthogonal to the block-1 patterns), but at n = 3 block
//!   2 is block n − 1 and the plane is the same: the false statement is made
//!   at n = 5..7 only.
//! - The symmetric matrix [[2, 1], [1, 2]] has eigenvalues 3 and 1.
//! - Bicubic B-spline subdivision (Catmull–Clark on the regular lattice) maps
//!   cubic data to cubic data, but not quartic data: on rows of data x⁴ it
//!   acts as the cubic B-spline rules, whose vertex rule (1, 6, 1)/8 gives
//!   x⁴ + 3x²/2 + 1/4 at the old points x, and edge rule (1, 1)/2 gives
//!   y⁴ + 3y²/2 + 1/16 at the midpoints y: two different quartics, so no one
//!   polynomial of degree ≤ 4 matches the refined data.
//! - The joint spectral radius bound of a product of matrices is a norm to a
//!   positive power, never below 0: a statement "ρ^[k] < 0" is false.
//! - The butterfly scheme (schemes file below: Loop's topology with the
//!   edge rule 1/2 (ends) + 1/8 (opposite) − 1/16 (wings), the vertex kept)
//!   has the negative weight −1/16 in its subdivision matrix.
//! - The builtins `strip.defective`, `strip.structure`, `curve.c1-laurent`,
//!   `fourthree.lemma3.4` and `matrix.nonnegative` with a stated range: the
//!   derivations are in each test's doc comment (Fourier blocks of a one-ring
//!   typed by hand, tensor products of the cubic B-spline, the four-point
//!   scheme with tension, the projections E and C, Huang's V-vertex rule).

use crate::common;

use subdlab::claims::{evaluate, parse_file, Outcome, Verdict};

fn run(body: &str) -> Outcome {
    let text =
        format!("paper = \"t\"\ntitle = \"t\"\n\n[[claim]]\nid = \"c\"\nlocation = \"-\"\nstatement = \"-\"\n{body}");
    let f = parse_file("t.toml", &text).unwrap();
    evaluate(&f).pop().unwrap()
}

fn holds(body: &str) {
    let o = run(body);
    assert_eq!(o.verdict, Verdict::Holds, "{body}: {} / {} / {}", o.stated, o.computed, o.detail);
}

/// REFUTED, with `needle` in what the outcome says (stated, computed or
/// detail): the disagreement is named.
fn refuted(body: &str, needle: &str) -> Outcome {
    let o = run(body);
    assert_eq!(o.verdict, Verdict::Refuted, "{body}: {} / {} / {}", o.stated, o.computed, o.detail);
    let said = format!("{} | {} | {}", o.stated, o.computed, o.detail);
    assert!(said.contains(needle), "{body}: '{needle}' not in {said}");
    o
}

const LOOP_MINIMAL: &str = "scheme = \"loop\"\nneighbourhood = \"minimal\"\nvalences = \"5..7\"\n";

#[test]
fn eigenvalues_all_per_block() {
    let body = |value: &str| format!("check = \"eigenvalues\"\n{LOOP_MINIMAL}block = \"m\"\nvalues = [\"{value}\"]");
    holds(&body("3/8 + cos(2 pi m / n)/4"));
    // half the cosine term: wrong at every block (cos(2πm/n) ≠ 0 for n = 5)
    refuted(&body("3/8 + cos(2 pi m / n)/8"), "stated but not found");
    // an extra value: the 1 × 1 block has one eigenvalue, not two
    refuted(
        &format!("check = \"eigenvalues\"\n{LOOP_MINIMAL}block = \"1\"\nvalues = [\"3/8 + cos(2 pi / n)/4\", \"1/8\"]"),
        "1/8",
    );
}

const CC4: &str = "check = \"eigenvalues\"\nscheme = \"catmull-clark\"\nvalences = [4]\n";

#[test]
fn eigenvalues_leading() {
    holds(&format!("{CC4}values = [\"1\", \"1/2 ; 2\", \"1/4\"]\ncompare = \"leading\""));
    // the third eigenvalue is the second 1/2, not 1/4
    refuted(&format!("{CC4}values = [\"1\", \"1/2\", \"1/4\"]\ncompare = \"leading\""), "found but not stated");
}

#[test]
fn eigenvalues_contains() {
    holds(&format!("{CC4}values = [\"1\", \"1/2 ; 2\", \"1/4 ; 3\"]\ncompare = \"contains\""));
    // 1/2 three times: there are only two
    refuted(&format!("{CC4}values = [\"1/2 ; 3\"]\ncompare = \"contains\""), "stated but not found");
    // a value that is not an eigenvalue
    refuted(&format!("{CC4}values = [\"1\", \"3/8\"]\ncompare = \"contains\""), "0.375");
}

#[test]
fn eigenvalues_count() {
    holds(&format!("{CC4}values = [\"1/2 ; 2\", \"1/4 ; 3\"]\ncompare = \"count\""));
    // 1/2 once: it occurs twice
    refuted(&format!("{CC4}values = [\"1/2\"]\ncompare = \"count\""), "found but not stated");
    // 1/4 four times: it occurs three times among the leading ones and the
    // analysis neighbourhood's other eigenvalues (1/8, 1/16, ...) are below
    refuted(&format!("{CC4}values = [\"1/4 ; 4\"]\ncompare = \"count\""), "stated but not found");
}

#[test]
fn eigenvalues_moduli() {
    holds(&format!("{CC4}values = [\"1\", \"-1/2 ; 2\"]\ncompare = \"leading\"\nmoduli = true"));
    // as values (moduli = false) −1/2 is not an eigenvalue
    refuted(&format!("{CC4}values = [\"1\", \"-1/2 ; 2\"]\ncompare = \"leading\""), "stated but not found");
    refuted(&format!("{CC4}values = [\"1\", \"1/3 ; 2\"]\ncompare = \"leading\"\nmoduli = true"), "moduli");
}

#[test]
fn subdominant() {
    let body = |sign: &str| {
        format!(
            "check = \"subdominant\"\nscheme = \"catmull-clark\"\nvalences = \"3..8\"\nvars = {{ c = \"cos(2 pi / n)\" }}\nvalue = \"(5 + c {sign} sqrt((c + 1) (c + 9)))/16\""
        )
    };
    holds(&body("+"));
    refuted(&body("-"), "n = 3");
}

#[test]
fn size() {
    let body = |v: &str| format!("check = \"size\"\nscheme = \"catmull-clark\"\nvalences = \"3..6\"\nvalue = \"{v}\"");
    holds(&body("6 n + 1"));
    refuted(&body("4 n + 1"), "analysis 19");
}

#[test]
fn invariant_set() {
    let body = |v: &str| {
        format!("check = \"invariant-set\"\nscheme = \"catmull-clark\"\nvalences = \"3..5\"\nrings = \"2\"\nvalue = \"{v}\"")
    };
    holds(&body("6 n + 1"));
    // rings 0..1 (2n + 1 vertices) are invariant but lack ring 2, the 4n
    // vertices the characteristic ring needs: 12 at n = 3
    refuted(&body("2 n + 1").replace("rings = \"2\"", "rings = \"1\""), "lacks 12 of the analysis neighbourhood");
    // a stated size that is not the size of the stated rings: the statement
    // names another set, which the check cannot build
    let o = run(&body("6 n"));
    assert_eq!(o.verdict, Verdict::Inconclusive, "{}", o.detail);
    assert!(o.detail.contains("19 vertices at n = 3, the statement 18"), "{}", o.detail);
}

#[test]
fn limit_stencil() {
    let body = |centre: &str| {
        format!(
            "check = \"limit-stencil\"\nscheme = \"catmull-clark\"\nvalences = \"3..7\"\nweights = {{ centre = \"{centre}\", \"edge.1\" = \"4 / (n (n + 5))\", \"face.1\" = \"1 / (n (n + 5))\" }}"
        )
    };
    holds(&body("n / (n + 5)"));
    // a wrong centre weight is named with both values
    refuted(&body("n / (n + 4)"), "computed 0.375, stated 0.428571");
    // a missing vertex kind: the face weights are not zero
    refuted(
        "check = \"limit-stencil\"\nscheme = \"catmull-clark\"\nvalences = [5]\nweights = { centre = \"n / (n + 5)\", \"edge.1\" = \"4 / (n (n + 5))\" }",
        "stated 0",
    );
}

#[test]
fn tangent_stencils() {
    let body = |k: &str, valences: &str| {
        format!(
            "check = \"tangent-stencils\"\nscheme = \"loop\"\nvalences = \"{valences}\"\ncos = {{ \"edge.1\" = \"cos({k} pi s / n)\" }}\nsin = {{ \"edge.1\" = \"sin({k} pi s / n)\" }}"
        )
    };
    holds(&body("2", "3..8"));
    refuted(&body("4", "5..7"), "different span");
    // the block-2 patterns at n = 3 are the block-1 plane (block 2 = block n − 1)
    holds(&body("4", "3..3"));
}

#[test]
fn inequality() {
    let body = |rhs: &str| {
        format!("check = \"inequality\"\nscheme = \"catmull-clark\"\nvalences = \"3..6\"\nlhs = \"lambda1\"\nop = \">=\"\nrhs = \"{rhs}\"")
    };
    holds(&body("0.4"));
    // λ1(3) = 0.4101 < 1/2
    refuted(&body("1/2"), "n = 3");
}

#[test]
fn nonnegative_spectrum() {
    holds(&format!("check = \"nonnegative-spectrum\"\n{LOOP_MINIMAL}"));
    refuted(&format!("check = \"nonnegative-spectrum\"\n{LOOP_MINIMAL}expect = false"), "no negative eigenvalue");
}

#[test]
fn spectral_c1_and_characteristic_map() {
    holds("check = \"spectral-c1\"\nscheme = \"catmull-clark\"\nvalences = \"3..6\"");
    refuted("check = \"spectral-c1\"\nscheme = \"catmull-clark\"\nvalences = \"3..6\"\nexpect = false", "passes");
    holds("check = \"characteristic-map\"\nscheme = \"catmull-clark\"\nvalences = [3, 5]");
    refuted(
        "check = \"characteristic-map\"\nscheme = \"catmull-clark\"\nvalences = [3, 5]\nexpect = false",
        "regular, injective",
    );
}

#[test]
fn certified_characteristic_map() {
    // Catmull–Clark is C¹ at every valence (Peters & Reif 1998): proved;
    // schemes/catmull-clark-folded-ring.toml folds by design (its comment
    // derives the darts): disproved; Kobbelt's sqrt(3) is C¹ (Kobbelt 2000)
    // and proved by lemma C9 at valence 5; at valence 3 its windows leave the
    // net (README): no proof either way
    let cc = "check = \"characteristic-map\"\nscheme = \"catmull-clark\"\nvalences = [3, 5]\ncertified = true";
    holds(cc);
    refuted(&format!("{cc}\nexpect = false"), "injectivity PROVED");
    let folded = format!(
        "check = \"characteristic-map\"\nscheme = \"{}/schemes/catmull-clark-folded-ring.toml\"\nvalences = [3]\ncertified = true",
        env!("CARGO_MANIFEST_DIR")
    );
    refuted(&folded, "regularity DISPROVED");
    holds(&format!("{folded}\nexpect = false"));
    holds("check = \"characteristic-map\"\nscheme = \"sqrt3\"\nvalences = [5]\ncertified = true");
    let o = run("check = \"characteristic-map\"\nscheme = \"sqrt3\"\nvalences = [3]\ncertified = true");
    assert_eq!(o.verdict, Verdict::Inconclusive, "{} / {}", o.computed, o.detail);
}

#[test]
fn matrix_eigenvalues() {
    let body = |values: &str| {
        format!("check = \"matrix-eigenvalues\"\nvalences = [3]\nrows = [[\"2\", \"1\"], [\"1\", \"2\"]]\nvalues = [{values}]")
    };
    holds(&body("\"3\", \"1\""));
    refuted(&body("\"3\", \"2\""), "stated but not found");
    // a printed matrix that is not square
    refuted(
        "check = \"matrix-eigenvalues\"\nvalences = [3]\nrows = [[\"2\", \"1\"], [\"1\"]]\nvalues = [\"3\", \"1\"]",
        "not square",
    );
}

#[test]
fn window_polynomials() {
    let body = |degree: u32| {
        format!(
            "check = \"builtin\"\nname = \"window.polynomials\"\ndata = {{ scheme = \"catmull-clark\", faces = \"QQQQ\", spokes = [[1, 0], [0, 1], [-1, 0], [0, -1]], window = [-4, 4, -4, 4], degree = {degree} }}"
        )
    };
    holds(&body(3));
    refuted(&body(4), "degree ≤ 4: not kept");
}

#[test]
fn strip_jsr_bound_below_zero_is_refuted() {
    let data = "data = { scheme = \"four-three\", faces = \"QQTTT\", spokes = [[0, 1], [-1, 0], [0, -1], [1, 0], [1, 1]], window = [-3, 3, -3, 4], shift = [0, 1], leading = [\"1\", \"1/2\", \"1/2\", \"1/4\", \"1/4\", \"1/4\"], length = 4, bound = \"0\" }";
    refuted(&format!("check = \"builtin\"\nname = \"strip.jsr\"\n{data}"), "ρ^[4]");
}

#[test]
fn nonnegative_weights_builtin() {
    holds("check = \"builtin\"\nname = \"matrix.nonnegative\"\ndata = { scheme = \"loop\", valences = [3, 6, 7], params = [{}] }");
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("butterfly.toml");
    std::fs::write(
        &file,
        "name = \"butterfly\"\ndescription = \"the butterfly scheme\"\ntopology = \"primal-triangle\"\n\n[vertex]\ncentre = \"1\"\nedge = \"0\"\n\n[edge]\nends = \"1/2\"\nopposite = \"1/8\"\nwing = \"-1/16\"\n",
    )
    .unwrap();
    let o = refuted(
        &format!(
            "check = \"builtin\"\nname = \"matrix.nonnegative\"\ndata = {{ scheme = \"{}\", valences = [6], params = [{{}}] }}",
            file.display()
        ),
        "-0.0625",
    );
    assert!(o.computed.contains("-0.0625"), "{}", o.computed);
}

/// `window.box-spline`: the four-direction box spline ±e1, ±e2, e1 + e2,
/// −e1 + e2 has 6 directions on 4 lines, at most 2 on one: degree 6 − 2 = 4
/// and C^(6 − 2 − 2) = C² (de Boor–Höllig–Riemenschneider). A false
/// smoothness (C³) and a false degree are refuted; Catmull–Clark's rules are
/// not that box spline's (its vertex weight is 36/64, the A_4 mask's 8/16).
#[test]
fn box_spline_mask_degree_and_smoothness() {
    let body = |scheme: &str, degree: u32, smoothness: u32| {
        format!(
            "check = \"builtin\"\nname = \"window.box-spline\"\ndata = {{ scheme = \"{scheme}\", faces = \"QQQQ\", spokes = [[1, 0], [0, 1], [-1, 0], [0, -1]], window = [-4, 4, -4, 4], directions = [[1, 0], [-1, 0], [0, 1], [0, -1], [1, 1], [-1, 1]], degree = {degree}, smoothness = {smoothness} }}"
        )
    };
    holds(&body("four-three", 4, 2));
    refuted(&body("four-three", 4, 3), "C^2");
    refuted(&body("four-three", 5, 2), "degree 4");
    refuted(&body("catmull-clark", 4, 2), "weights differ from the mask");
}

/// A scheme file in a temporary folder (kept alive by the returned guard).
fn scheme_file(name: &str, text: &str) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join(name);
    std::fs::write(&file, text).unwrap();
    let path = file.display().to_string();
    (dir, path)
}

/// Catmull–Clark's masks except the edge rule: 3/4 on each end and −1/8 on
/// each side corner (the affine combination 2·3/4 − 4·1/8 = 1), with the
/// vertex rule v/2 + (1/2n) Σ e_j. At the regular vertex (n = 4) the window
/// [−1, 1]² of the lattice is the one-ring: the centre v, its edge
/// neighbours e_j (the edge points) and its diagonal neighbours f_j (the face
/// points, f_j in quad [v, e_j, f_j, e_{j+1}]), 9 points. In Fourier block m
/// (ω = i^m) the rows of e and f on (e, f) are
///   e' = (3/4 − (1/4) cos(πm/2)) e + (−1/8)(1 + ω^{−m}) f,
///   f' = (1 + ω^m)/4 e + 1/4 f.
/// Block 1 (and 3): [[3/4, −(1 − i)/8], [(1 + i)/4, 1/4]], trace 1, determinant
/// 3/16 + 2/32 = 1/4: the double eigenvalue 1/2, and B − I/2 ≠ 0, so one
/// eigenvector each (a Jordan block). Block 2: [[1, 0], [0, 1/4]]. Block 0 on
/// (v, e, f): [[1/2, 1/2, 0], [3/4, 1/2, −1/4], [1/4, 1/2, 1/4]], eigenvalues
/// 1, 1/4 and 0 (trace 5/4, determinant 0). So S has 9 − 2 = 7 independent
/// eigenvectors: 1/2 with algebraic multiplicity 4 and geometric 2.
const QUAD_JORDAN: &str = "name = \"quad-jordan\"\ndescription = \"Catmull-Clark masks with a Jordan-block edge rule\"\ntopology = \"primal-quad\"\n\n[vertex]\ncentre = \"1/2\"\nedge = \"1 / (2 n)\"\nface = \"0\"\n\n[edge]\nends = \"3/4\"\nside = \"-1/8\"\n\n[face]\ncorner = \"1 / n\"\n";

const QUAD_SPOKES: &str = "faces = \"QQQQ\", spokes = [[1, 0], [0, 1], [-1, 0], [0, -1]]";

/// The one-ring matrix of `QUAD_JORDAN` typed from its rules (order v, e_0..e_3,
/// f_0..f_3), for the exact oracle of tests/common/exact.rs.
fn quad_jordan_one_ring() -> common::exact::Mat {
    use common::exact::q;
    let mut s = vec![vec![q(0, 1); 9]; 9];
    let (e, f) = (|j: usize| 1 + j % 4, |j: usize| 5 + j % 4);
    s[0][0] = q(1, 2);
    for j in 0..4 {
        s[0][e(j)] = q(1, 8);
        // the edge point of (v, e_j): its quads are [v, e_j, f_j, e_{j+1}] and [v, e_{j−1}, f_{j−1}, e_j]
        s[e(j)][0] = q(3, 4);
        s[e(j)][e(j)] = q(3, 4);
        for side in [e(j + 1), f(j), e(j + 3), f(j + 3)] {
            s[e(j)][side] = q(-1, 8);
        }
        // the face point of [v, e_j, f_j, e_{j+1}]
        for corner in [0, e(j), f(j), e(j + 1)] {
            s[f(j)][corner] = q(1, 4);
        }
    }
    s
}

#[test]
fn strip_defective() {
    use common::exact::{algebraic, q, rank, shifted};
    // the hand derivation above, by the test's own exact arithmetic
    let s = quad_jordan_one_ring();
    assert_eq!(algebraic(&s, &q(1, 2)), 4);
    assert_eq!(9 - rank(shifted(&s, &q(1, 2))), 2);
    let (_dir, file) = scheme_file("quad-jordan.toml", QUAD_JORDAN);
    let body = |scheme: &str, window: &str| {
        format!("check = \"builtin\"\nname = \"strip.defective\"\ndata = {{ scheme = \"{scheme}\", {QUAD_SPOKES}, window = {window}, shift = [0, 0], leading = [\"1\"] }}")
    };
    let o = run(&body(&file, "[-1, 1, -1, 1]"));
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("7 independent eigenvectors for 9 points"), "{}", o.computed);
    assert!(o.detail.contains("1/2 (algebraic 4, geometric 2)"), "{}", o.detail);
    // Catmull–Clark on the regular lattice is the tensor product of the cubic
    // B-spline: on [−2, 2] its matrix (rows 1/8 (1, 6, 1) at even, 1/2 (1, 1)
    // at odd positions) has the eigenvalues 1, 1/2, 1/4 of the inner three
    // points and 1/8 twice from the columns ±2, which only their own rows
    // reach (eigenvectors e_{±2}): diagonalisable, and so is its tensor
    // product, the 25 × 25 S on [−2, 2]²: the statement is false.
    let o = refuted(&body("catmull-clark", "[-2, 2, -2, 2]"), "25 independent eigenvectors for 25 points");
    // the tensor product's multiplicities: 1/8 = 1·1/8 (twice), 1/8·1 (twice), 1/2·1/4, 1/4·1/2
    assert!(
        o.detail.contains("1/8^6") && o.detail.contains("1/4^3") && o.detail.contains("defective: none"),
        "{}",
        o.detail
    );
}

/// `strip.structure` on Catmull–Clark (the bicubic B-spline) at a regular
/// vertex, L = [−2, 2] × [−2, 3], S⁺ one step up (shift (0, 1)). On [−2, 2]
/// the cubic B-spline's matrix has the eigenvalues 1, 1/2, 1/4, 1/8, 1/8 and
/// on [−2, 3] also 0 (column 3 is empty), so 1, 1/2, 1/4 have eigenspaces of
/// dimension 1, 2, 3 on L (products 1·1; 1·1/2, 1/2·1; 1·1/4, 1/4·1,
/// 1/2·1/2). The samples of 1; x, y; and x² − c, xy, y² − c of the
/// polynomials the bicubic rules map to 1/λ times themselves lie in them, so
/// they span them. S⁺ reads the refined data one step up: an eigenvector
/// sampling P goes to λ·P(x, y + 1), the same degree with the same leading
/// part: upper triangular in the order 1, 1/2, 1/2, 1/4, 1/4, 1/4 with that
/// diagonal and no coupling inside a group (HOLDS). Listed the other way round
/// (1/4 first) the same action is lower triangular: (y + 1)² − c has the
/// terms 2y and 1 below the diagonal (REFUTED, the entries named).
#[test]
fn strip_structure() {
    let body = |leading: &str| {
        format!("check = \"builtin\"\nname = \"strip.structure\"\ndata = {{ scheme = \"catmull-clark\", {QUAD_SPOKES}, window = [-2, 2, -2, 3], shift = [0, 1], leading = [{leading}] }}")
    };
    holds(&body("\"1\", \"1/2\", \"1/2\", \"1/4\", \"1/4\", \"1/4\""));
    let o = refuted(&body("\"1/4\", \"1/4\", \"1/4\", \"1/2\", \"1/2\", \"1\""), "not 0");
    // below the diagonal: a quadratic's image has a constant term (row 5, the 1)
    assert!(o.detail.contains("(5, 3)") || o.detail.contains("(5, 4)"), "{}", o.detail);
}

/// The four-point scheme with tension w: P_{2i} = P_i, P_{2i+1} = (1/2 + w)
/// (P_i + P_{i+1}) − w (P_{i−1} + P_{i+2}). Dyn–Levin–Gregory (1987): C¹ for
/// 0 < w < (√5 − 1)/8 ≈ 0.1545 (w = 1/16 is the classical four-point scheme).
/// At w = 0 the rules insert midpoints: the limit is the control polygon,
/// with a corner wherever it turns. At w = 3/8: the scheme interpolates, so
/// the limit at old vertex i is P_i; on the window [−3, 3] the vector
/// v = (−1, −36/49, −27/49, 0, 27/49, 36/49, 1) satisfies S v = (3/4) v (checked
/// below with a matrix typed from the rules), so the limit G of these data
/// has G(2^−k) = (3/4)^k G(1) = (3/4)^k · 27/49 and G(0) = 0: the difference
/// quotients (3/2)^k · 27/49 diverge, not C¹.
const TENSION: &str = "domain = \"curve\"\nname = \"tension-four-point\"\ndescription = \"four-point scheme with tension w\"\n\n[params.w]\ndefault = \"1/16\"\nmin = -1\nmax = 1\ndescription = \"tension\"\n\n[even]\n\"0\" = \"1\"\n\n[odd]\n\"-1\" = \"-w\"\n\"0\" = \"1/2 + w\"\n\"1\" = \"1/2 + w\"\n\"2\" = \"-w\"\n";

#[test]
fn curve_c1_laurent() {
    use common::exact::q;
    // S v = (3/4) v at w = 3/8 on the window [−3, 3], rows from the rules
    let w = q(3, 8);
    let mut s = vec![vec![q(0, 1); 7]; 7];
    for k in -3i64..=3 {
        let row = (k + 3) as usize;
        let base = k.div_euclid(2);
        let terms = if k.rem_euclid(2) == 0 {
            vec![(base, q(1, 1))]
        } else {
            let a = q(1, 2) + w.clone();
            vec![(base - 1, -w.clone()), (base, a.clone()), (base + 1, a), (base + 2, -w.clone())]
        };
        for (i, x) in terms {
            s[row][(i + 3) as usize] += x;
        }
    }
    let v = [q(-1, 1), q(-36, 49), q(-27, 49), q(0, 1), q(27, 49), q(36, 49), q(1, 1)];
    for (row, vi) in s.iter().zip(&v) {
        let sv = row.iter().zip(&v).fold(q(0, 1), |acc, (a, b)| acc + a.clone() * b.clone());
        assert_eq!(sv, q(3, 4) * vi.clone());
    }
    let (_dir, file) = scheme_file("tension.toml", TENSION);
    let body = |values: &str| {
        format!("check = \"builtin\"\nname = \"curve.c1-laurent\"\ndata = {{ scheme = \"{file}\", param = \"w\", values = [{values}], max_steps = 8 }}")
    };
    holds(&body("\"1/16\", \"1/10\""));
    refuted(&body("\"0\""), "a corner");
    let o = refuted(&body("\"3/8\""), "an eigenvector of 3/4");
    assert!(o.computed.contains("G(1) = 27/49"), "{}", o.computed);
    // one value that is not C¹ among C¹ ones refutes the statement
    refuted(&body("\"1/16\", \"0\""), "w = 0: not C¹");
}

/// Lemma 3.4 with C_kl = (2/n) cos(2π(k − l)/n) = (2/n)(c_k c_l + s_k s_l),
/// c_k = cos(2πk/n), s_k = sin(2πk/n): c and s are orthogonal with |c|² =
/// |s|² = n/2 for n ≥ 3 and orthogonal to e = (1, ..., 1), so C is the
/// orthogonal projection onto span{c, s} (rank 2, Ce = 0) and E + C, E =
/// eeᵗ/n, the projection onto span{e, c, s} (rank 3). Half that C is not a
/// projection (C² = C/2 ≠ C) but still of rank 2; E doubled gives EE = 2E.
#[test]
fn lemma_3_4_identities_and_ranks() {
    let body = |e: &str, c: &str, rc: u32, rec: u32| {
        format!("check = \"builtin\"\nname = \"fourthree.lemma3.4\"\ndata = {{ e = \"{e}\", c = \"{c}\", rank_c = {rc}, rank_e_plus_c = {rec} }}")
    };
    let c = "2/n cos(2 pi (k - l)/n)";
    holds(&body("1/n", c, 2, 3));
    let o = refuted(&body("1/n", "1/n cos(2 pi (k - l)/n)", 2, 3), "C² = C fails");
    assert!(o.computed.contains("(E + C)² = E + C fails") && !o.computed.contains("Ce = 0 fails"), "{}", o.computed);
    assert!(o.computed.contains("rank C = 2 and rank (E + C) = 3 at every n"), "{}", o.computed);
    refuted(&body("1/n", c, 3, 3), "n = 3: rank C = 2, rank (E + C) = 3");
    refuted(&body("1/n", c, 2, 2), "ranks differ from the statement");
    let o = refuted(&body("2/n", c, 2, 3), "EE = E fails");
    assert!(o.computed.contains("eeᵗ = nE fails"), "{}", o.computed);
}

/// `matrix.nonnegative` with a stated range: Huang's non-box rules (§3.2.2)
/// at a vertex of valence k ≠ 4 (the parameter a is a_k there) weigh the
/// centre by 1 − a and each FCV around it by a/k (the V-vertex rule); every
/// other rule the analysis neighbourhood sees belongs to valence-4 vertices
/// and quads (a_4 = 1/2) or is the E-vertex and NFCV rule, with positive
/// constant weights. So S ≥ 0 exactly when 0 ≤ a ≤ 1: "0 ≤ a ≤ 2" fails the
/// "if" (at a = 2 the weight 1 − a = −1), "0 ≤ a ≤ 1/2" fails the "only if"
/// (at a = 3/4 every weight is ≥ 0), "−1 ≤ a ≤ 1" fails the "if" (a/5 = −1/5).
#[test]
fn nonnegative_weights_range_both_directions() {
    let body = |lo: &str, hi: &str, valences: &str| {
        format!("check = \"builtin\"\nname = \"matrix.nonnegative\"\ndata = {{ scheme = \"non-box\", valences = {valences}, param = \"a\", range = [\"{lo}\", \"{hi}\"], samples = [\"0\", \"1/4\", \"1/2\", \"3/4\", \"1\"] }}")
    };
    let o = run(&body("0", "1", "[3, 4, 5, 7]"));
    assert_eq!(o.verdict, Verdict::Holds, "{} / {}", o.computed, o.detail);
    assert!(o.computed.contains("if: S ≥ 0 for every 0 ≤ a ≤ 1"), "{}", o.computed);
    assert!(
        o.computed.contains("only if: every a < 0 and every a > 1 gives a negative weight (k = 3, 5, 7"),
        "{}",
        o.computed
    );
    for k in [3, 5, 7] {
        assert!(o.detail.contains(&format!("k = {k}: S ≥ 0 exactly for a from 0 (")), "{}", o.detail);
        assert!(o.detail.contains(&format!("= 1/{k}·a) to 1 (S[centre][centre] = 1 - a)")), "{}", o.detail);
    }
    assert!(o.detail.contains("k = 4: S does not depend on a"), "{}", o.detail);
    let o = refuted(&body("0", "2", "[3, 5]"), "if fails");
    assert!(o.computed.contains("a = 2: S[centre][centre] = 1 - a = -1"), "{}", o.computed);
    let o = refuted(&body("0", "1/2", "[3, 5]"), "only if fails");
    assert!(o.computed.contains("a = 3/4: every entry ≥ 0"), "{}", o.computed);
    refuted(&body("-1", "1", "[5]"), "= 1/5·a = -1/5");
    // the valence where a does not act decides no "only if"
    let o = run(&body("0", "1", "[4]"));
    assert_eq!(o.verdict, Verdict::Inconclusive, "{}", o.computed);
    common::assert_registry_verdict("nonbox.convex-hull", Verdict::Holds);
}

/// The equivalence needs S affine in the parameter: a Loop variant whose
/// centre weight is 1 − t² is not (at t = 1/2 it is 3/4, the line through
/// t = 0 and t = 1 gives 1/2), and the verdict says the "only if" is
/// undecided rather than extrapolating.
#[test]
fn nonnegative_weights_range_needs_affine_weights() {
    let (_dir, file) = scheme_file(
        "quadratic.toml",
        "name = \"loop-quadratic\"\ndescription = \"Loop-like, centre weight quadratic in t\"\ntopology = \"primal-triangle\"\n\n[params.t]\ndefault = \"1/2\"\nmin = 0\nmax = 1\ndescription = \"t\"\n\n[vertex]\ncentre = \"1 - t^2\"\nedge = \"t^2 / n\"\n\n[edge]\nends = \"3/8\"\nopposite = \"1/8\"\n",
    );
    let o = run(&format!(
        "check = \"builtin\"\nname = \"matrix.nonnegative\"\ndata = {{ scheme = \"{file}\", valences = [5], param = \"t\", range = [\"0\", \"1\"], samples = [\"0\", \"1\", \"1/2\"] }}"
    ));
    assert_eq!(o.verdict, Verdict::Inconclusive, "{} / {}", o.computed, o.detail);
    // INCONCLUSIVE is an `Error::Undecided`, whose message carries the evidence
    assert!(o.detail.contains("only if: not decided (S not affine in t"), "{}", o.detail);
    assert!(o.detail.contains("at t = 1/2 is 3/4, off the line 1 - t"), "{}", o.detail);
}

/// The `central-shape` kind. Catmull–Clark at n = 4 is the bicubic
/// B-spline, which reproduces quadratics: every input's central shape is
/// the input (correct), and none is flat (λ = 1/2 and the quadratics'
/// eigenvalue 1/4 = λ², so the curvature neither fades nor grows).
/// Doo–Sabin's central face has the eigenvalues 1, 1/2 and 1/4 (Doo–Sabin
/// 1978) and λ = 1/2, so at n = 5 the quadratics' part sits at 1/4 = λ²
/// (g = 1) and no convex input comes out flat: the statement "some convex
/// input is flat" is false.
#[test]
fn central_shape() {
    holds("check = \"central-shape\"\nscheme = \"catmull-clark\"\nvalences = [4]\nt = [-1, 0.5, 1]\nshape = \"correct\"\n");
    refuted(
        "check = \"central-shape\"\nscheme = \"catmull-clark\"\nvalences = [4]\nt = [0.5, 1]\nshape = \"flat\"\nquantifier = \"some\"\n",
        "none of the",
    );
    refuted(
        "check = \"central-shape\"\nscheme = \"doo-sabin\"\nvalences = [5]\nt = [0.5, 1]\nshape = \"flat\"\nquantifier = \"some\"\n",
        "g = 1",
    );
    holds("check = \"central-shape\"\nscheme = \"doo-sabin\"\nvalences = [5]\nt = [0.5, 1]\nshape = [\"correct\", \"right-sign\", \"mixed-sign\", \"wrong-sign\"]\n");
    // a claim that asserts nothing, or names no category, is an ERROR
    for bad in [
        "t = []\nshape = \"flat\"\n",
        "t = [1]\nshape = []\n",
        "t = [1]\nshape = \"convex\"\n",
        "t = [1]\nshape = \"flat\"\nquantifier = \"most\"\n",
        "t = [2]\nshape = \"flat\"\n",
    ] {
        let o = run(&format!("check = \"central-shape\"\nscheme = \"doo-sabin\"\nvalences = [5]\n{bad}"));
        assert_eq!(o.verdict, Verdict::Error, "{bad}: {}", o.detail);
    }
}
