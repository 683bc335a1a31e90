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

mod common;

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
