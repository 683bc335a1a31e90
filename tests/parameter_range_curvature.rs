//! Claims of kind `parameter-range` with `condition = "bounded-curvature"`
//! (issue 27): the set of t where the scheme is spectrally C¹ with curvature
//! class zero or bounded, from `sweep --exact --curvature`. The claims are
//! written to a file in a temporary folder and run by `subdlab verify`.
//!
//! The Loop variant with a free vertex weight w (tests/data/
//! loop-free-vertex-weight.toml; its classes are derived by hand in
//! tests/sweep_exact.rs, `loop_free_vertex_weight_curvature_classes_...`):
//! λ = L = 3/8 + c/4 with c = cos(2π/n); block 0 adds 5/8 − w, the largest
//! eigenvalue below λ besides it is b(2) = 1/8 + c²/2, and every eigenvalue
//! shows on the ring. Where b(2) < L² (n = 4, 5) the class is zero where
//! |5/8 − w| < L², bounded where |5/8 − w| = L², unbounded where L² <
//! |5/8 − w| < L (and not applicable beyond). So the bounded-curvature set
//! is the closed interval [5/8 − L², 5/8 + L²]:
//! - n = 4: c = 0, L² = 9/64: [31/64, 49/64];
//! - n = 5: 4c² + 2c − 1 = 0 gives L² = 5(1 + c)/32: [15/32 − 5c/32,
//!   25/32 + 5c/32];
//! - n = 3: 1/8 > λ² = 1/16 (blocks 1 and 2 carry λ = 1/4): unbounded on
//!   the whole C¹ set, the bounded-curvature set is empty;
//! - n = 6: the rules do not read w (regular Loop): bounded on all of [0, 2].
//!
//! These numbers are computed below from L and 5/8, not read off the program.

use num_bigint::BigInt;
use num_rational::BigRational;
use serde_json::Value;

use crate::common::subdlab;

const SCHEME: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/loop-free-vertex-weight.toml");

fn q(p: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(p), BigInt::from(d))
}

/// The bounded-curvature set's ends at n = 4 from the derivation above:
/// 5/8 ∓ L², L = 3/8 + cos(π/2)/4 = 3/8.
fn ends_n4() -> (BigRational, BigRational) {
    let l = q(3, 8);
    let l2 = &l * &l;
    (q(5, 8) - &l2, q(5, 8) + &l2)
}

/// One claim: the Loop variant at valence n, w swept.
fn claim(id: &str, n: usize, range: &str, asserts: &str, window: Option<&str>) -> String {
    let window = window.map(|w| format!("window = {w}\n")).unwrap_or_default();
    format!(
        "\n[[claim]]\nid = \"{id}\"\nlocation = \"test\"\nstatement = \"s\"\ncheck = \"parameter-range\"\n\
         scheme = \"{SCHEME}\"\nvalences = [{n}]\nparameter = \"w\"\nrange = \"{range}\"\n\
         condition = \"bounded-curvature\"\nasserts = \"{asserts}\"\n{window}"
    )
}

/// Runs `subdlab verify --json` on a claim file in a temporary folder: the
/// outcomes by id.
fn verify(claims: &[String]) -> Vec<Value> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("claims.toml");
    std::fs::write(&path, format!("paper = \"t\"\ntitle = \"t\"\n{}", claims.concat())).unwrap();
    let out = subdlab(&["verify", "--claims", path.to_str().unwrap(), "--json"]);
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"), "a panic");
    let v: Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    v[0]["claims"].as_array().unwrap().clone()
}

fn outcome<'a>(all: &'a [Value], id: &str) -> &'a Value {
    all.iter().find(|c| c["id"] == id).unwrap_or_else(|| panic!("no claim {id}"))
}

fn verdict(all: &[Value], id: &str) -> String {
    let o = outcome(all, id);
    format!("{}: {} / {}", o["verdict"].as_str().unwrap(), o["computed"], o["detail"])
}

/// The rational witness "w = p/q" named in a REFUTED's computed text.
fn witness(all: &[Value], id: &str) -> BigRational {
    let computed = outcome(all, id)["computed"].as_str().unwrap();
    let at = computed.split("confirmed at w = ").nth(1).unwrap_or_else(|| panic!("no witness: {computed}"));
    at.split(':').next().unwrap().trim().parse().unwrap()
}

#[test]
fn bounded_curvature_ranges_inside_the_hand_derived_sets_hold() {
    let (lo, hi) = ends_n4();
    let n4 = format!("[{lo}, {hi}]");
    let all = verify(&[
        // the whole set, both readings (the union of the zero set (lo, hi)
        // and the two bounded points is one closed interval)
        claim("n4-inside", 4, &n4, "inside", None),
        claim("n4-exactly", 4, &n4, "exactly", Some("[\"0\", \"2\"]")),
        // n = 5: the ends 5/8 ∓ 5(1 + c)/32 as cyclotomic numbers, compared
        // exactly with the computed algebraic ends
        claim(
            "n5-exactly",
            5,
            "[15/32 - 5 cos(2 pi / n)/32, 25/32 + 5 cos(2 pi / n)/32]",
            "exactly",
            Some("[\"0\", \"2\"]"),
        ),
        // regular Loop: bounded everywhere
        claim("n6-exactly", 6, "[0, 2]", "exactly", None),
    ]);
    for id in ["n4-inside", "n4-exactly", "n5-exactly", "n6-exactly"] {
        let v = verdict(&all, id);
        assert!(v.starts_with("HOLDS"), "{id}: {v}");
        // the class is floating point even where |μ| and λ² are exact
        assert!(v.contains("the class in floating point"), "{id}: {v}");
    }
}

#[test]
fn bounded_curvature_ranges_crossing_an_end_are_refuted_at_a_confirmed_witness() {
    let (lo, hi) = ends_n4();
    let past = &hi + q(1, 64);
    let all = verify(&[
        // [lo, hi + 1/64]: (hi, hi + 1/64] is unbounded (L² < |5/8 − w| < L)
        claim("n4-cross", 4, &format!("[{lo}, {past}]"), "inside", None),
        // (lo, hi] as the whole set: lo itself is in the set (bounded)
        claim("n4-open-exactly", 4, &format!("({lo}, {hi}]"), "exactly", Some("[\"0\", \"2\"]")),
        // n = 3: nowhere bounded
        claim("n3-inside", 3, "[1/2, 3/4]", "inside", None),
    ]);
    let l2 = q(9, 64);
    let gap = |w: &BigRational| {
        let d = q(5, 8) - w;
        if d < q(0, 1) {
            -d
        } else {
            d
        }
    };
    let v = verdict(&all, "n4-cross");
    assert!(v.starts_with("REFUTED") && v.contains("second route") && v.contains("class unbounded"), "{v}");
    let t = witness(&all, "n4-cross");
    assert!(t > hi && t <= past && gap(&t) > l2 && gap(&t) < q(3, 8), "witness {t} not where the class is unbounded");
    let v = verdict(&all, "n4-open-exactly");
    assert!(v.starts_with("REFUTED") && v.contains("class bounded"), "{v}");
    assert_eq!(witness(&all, "n4-open-exactly"), lo, "the one point of the set outside the range");
    let v = verdict(&all, "n3-inside");
    assert!(v.starts_with("REFUTED") && v.contains("nowhere in the window"), "{v}");
    let t = witness(&all, "n3-inside");
    assert!(t >= q(1, 2) && t <= q(3, 4), "{t}");
}

#[test]
fn malformed_or_vacuous_bounded_curvature_claims_are_errors() {
    let all = verify(&[
        claim("typo", 4, "[1/2, 3/4]", "inside", None).replace("bounded-curvature", "bounded-curvatures"),
        claim("nothing-asserted", 4, "[1/2, 3/4]", "inside", None).replace("asserts = \"inside\"\n", ""),
        claim("no-parameter", 4, "[1/2, 3/4]", "inside", None).replace("parameter = \"w\"", "parameter = \" \""),
    ]);
    for (id, needle) in [("typo", "condition"), ("nothing-asserted", "asserts"), ("no-parameter", "asserts nothing")] {
        let o = outcome(&all, id);
        assert_eq!(o["verdict"], "ERROR", "{id}: {o}");
        assert!(o["detail"].as_str().unwrap().contains(needle), "{id}: {o}");
    }
}
