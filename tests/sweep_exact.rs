//! `subdlab sweep --exact`: the sets of the swept parameter where a scheme
//! converges and is spectrally C¹, with exact algebraic endpoints, checked
//! against closed forms derived here (never against numbers the program
//! printed): Huang's non-box scheme's G¹/C¹ bound a > 1/4 − cos(2π/k)/4, and
//! a Loop variant with a free vertex weight whose spectrum is written down by
//! hand. Every endpoint is also re-checked with the ordinary floating-point
//! spectrum just inside and just outside.

use crate::common;
use common::{fails, subdlab};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

fn json(args: &[&str]) -> serde_json::Value {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

fn rat(s: &str) -> BigRational {
    let (p, q) = s.split_once('/').unwrap_or((s, "1"));
    BigRational::new(p.parse::<BigInt>().unwrap(), q.parse::<BigInt>().unwrap())
}

/// Polynomials over Q, lowest degree first.
type P = Vec<BigRational>;

fn trim(mut p: P) -> P {
    while p.last().is_some_and(|c| c.is_zero()) {
        p.pop();
    }
    p
}

fn mul(a: &P, b: &P) -> P {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![BigRational::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    trim(out)
}

fn add(a: &P, b: &P) -> P {
    let n = a.len().max(b.len());
    let z = BigRational::zero();
    trim((0..n).map(|k| a.get(k).unwrap_or(&z) + b.get(k).unwrap_or(&z)).collect())
}

/// p(u) for a polynomial u: Horner.
fn compose(p: &P, u: &P) -> P {
    p.iter().rev().fold(Vec::new(), |acc, c| add(&mul(&acc, u), &vec![c.clone()]))
}

/// The remainder of a modulo a monic m.
fn rem(a: &P, m: &P) -> P {
    let mut r = trim(a.clone());
    let d = m.len() - 1;
    while r.len() > d {
        let k = r.len() - 1 - d;
        let c = r[r.len() - 1].clone();
        for (i, mc) in m.iter().enumerate() {
            r[i + k] -= &c * mc;
        }
        r = trim(r);
    }
    r
}

/// The minimal polynomial of y = 2 cos(2π/k) over Q, from its definition:
/// ∏ (y − 2 cos(2πj/k)) over 1 ≤ j < k/2 coprime to k (and j = k/2 for
/// k = 2), whose coefficients are integers (the conjugates of 2 cos(2π/k)
/// are exactly these), so rounding the floating-point product is exact for
/// small k.
fn min_poly_2cos(k: i64) -> P {
    let gcd = |mut a: i64, mut b: i64| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let mut c: Vec<f64> = vec![1.0];
    for j in 1..=k / 2 {
        if gcd(j, k) != 1 || 2 * j == k && k > 2 {
            continue;
        }
        let r = 2.0 * (2.0 * std::f64::consts::PI * j as f64 / k as f64).cos();
        let mut next = vec![0.0; c.len() + 1];
        for (i, x) in c.iter().enumerate() {
            next[i + 1] += x;
            next[i] -= r * x;
        }
        c = next;
    }
    c.iter().map(|x| BigRational::from_integer(BigInt::from(x.round() as i64))).collect()
}

/// The endpoint `e` (JSON) is exactly a + b·cos(2π/k), a and b rational:
/// its polynomial p vanishes there (p(a + b y/2) ≡ 0 modulo the minimal
/// polynomial of y = 2cos(2π/k)), its isolating interval holds the value,
/// and the decimal agrees; a rational endpoint must equal the value itself.
fn assert_endpoint_is(e: &serde_json::Value, a: &BigRational, b: &BigRational, k: i64, what: &str) {
    let value = num_traits::ToPrimitive::to_f64(a).unwrap()
        + num_traits::ToPrimitive::to_f64(b).unwrap() * (2.0 * std::f64::consts::PI / k as f64).cos();
    assert!((e["decimal"].as_f64().unwrap() - value).abs() < 1e-12, "{what}: {e} ≠ {value}");
    let m = min_poly_2cos(k);
    if let Some(r) = e["rational"].as_str() {
        // then cos(2π/k) is rational (degree-1 minimal polynomial): compare exactly
        assert_eq!(m.len(), 2, "{what}: a rational endpoint {r} where the closed form is irrational");
        let y = -&m[0] / &m[1];
        let exact = a + b * y / BigRational::from_integer(2.into());
        assert_eq!(rat(r), exact, "{what}");
        return;
    }
    let p: P = e["polynomial"].as_array().unwrap().iter().map(|c| rat(c.as_str().unwrap())).collect();
    let half_b = b / BigRational::from_integer(2.into());
    let u: P = vec![a.clone(), half_b];
    assert!(rem(&compose(&p, &u), &m).is_empty(), "{what}: {e} does not vanish at {a} + {b} cos(2π/{k})");
    let iv = e["isolating_interval"].as_array().unwrap();
    let (lo, hi) = (rat(iv[0].as_str().unwrap()), rat(iv[1].as_str().unwrap()));
    assert!(lo < hi, "{what}");
    let (lo, hi) = (num_traits::ToPrimitive::to_f64(&lo).unwrap(), num_traits::ToPrimitive::to_f64(&hi).unwrap());
    assert!(lo <= value + 1e-14 && value - 1e-14 <= hi, "{what}: ({lo}, {hi}) misses {value}");
}

/// The float spectrum's C¹ and convergence verdicts at one value.
fn verdict(scheme: &str, param: &str, n: usize, value: f64) -> (bool, bool) {
    let v = json(&[
        "spectrum",
        scheme,
        "--valence",
        &n.to_string(),
        "--param",
        &format!("{param}={value:.12}"),
        "--json",
        "--no-exact",
    ]);
    (v["verdict"]["c1_spectral"].as_bool().unwrap(), v["verdict"]["convergent"].as_bool().unwrap())
}

fn intervals<'a>(v: &'a serde_json::Value, n: usize, key: &str) -> &'a Vec<serde_json::Value> {
    let set = v["valences"].as_array().unwrap().iter().find(|s| s["valence"].as_u64() == Some(n as u64)).unwrap();
    assert_eq!(set["exact"], true, "n = {n}: {}", set["not_exact_because"]);
    set[key].as_array().unwrap()
}

/// Huang's non-box scheme: the paper's bound (tests/non_box.rs derives it)
/// a > 1/4 − cos(2π/k)/4 is the lower end of the spectral C¹ set, exactly,
/// open, at every k = 3..12 but the regular k = 4 (whose rules do not read
/// a); just above it the float spectrum is C¹, just below it is not.
#[test]
fn non_box_lower_end_is_the_papers_bound_exactly() {
    let v = json(&["sweep", "non-box", "--valences", "3..12", "--param", "a=0:1:1/10", "--exact", "--json"]);
    let quarter = BigRational::new(1.into(), 4.into());
    for k in (3..=12).filter(|&k| k != 4) {
        let c1 = intervals(&v, k, "c1_spectral");
        assert_eq!(c1.len(), 1, "k = {k}: {c1:?}");
        let from = &c1[0]["from"];
        assert_eq!(c1[0]["from_closed"], false, "k = {k}: a strict bound");
        assert_endpoint_is(from, &quarter, &-quarter.clone(), k as i64, &format!("non-box k = {k}"));
        let x = from["decimal"].as_f64().unwrap();
        assert!(verdict("non-box", "a", k, x + 1e-6).0, "k = {k}: C¹ just above {x}");
        assert!(!verdict("non-box", "a", k, x - 1e-6).0, "k = {k}: not C¹ just below {x}");
    }
}

/// A Loop variant with a free vertex weight w (tests/data/
/// loop-free-vertex-weight.toml): v' = (1 − w) v + (w/n) Σ e_j at the
/// extraordinary vertex, Loop's edge rule e_j' = 3/8 v + 3/8 e_j +
/// 1/8 (e_{j−1} + e_{j+1}), regular vertices Loop's. On the centre and its
/// ring the Fourier block 0 (v and the ring's mean ē) is
///     [[1 − w, w], [3/8, 5/8]]: trace 13/8 − w, determinant 5/8 − w,
/// eigenvalues 1 and 5/8 − w; block m ≥ 1 is the ring's circulant,
///     3/8 + (ζ^m + ζ^{−m})/8 = 3/8 + cos(2πm/n)/4,
/// largest at m = 1 and n − 1: λ1 = 3/8 + c/4, c = cos(2π/n), ≥ 1/4; the
/// outer rings of the neighbourhood add the regular rules' 1/8 and below.
/// Hence convergence iff |5/8 − w| < 1: w ∈ [0, 13/8) in the range [0, 2]
/// (0 itself: 5/8 < 1); spectral C¹ iff |5/8 − w| < 3/8 + c/4:
///     1/4 − c/4 < w < 1 + c/4 (both ends open).
/// At n = 6 the rules do not read w (regular Loop): both sets are [0, 2].
#[test]
fn loop_free_vertex_weight_matches_the_hand_derived_sets() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/loop-free-vertex-weight.toml");
    let v = json(&["sweep", file, "--valences", "3..8", "--param", "w=0:2:1/8", "--exact", "--json"]);
    let r = |p: i64, q: i64| BigRational::new(p.into(), q.into());
    for n in 3..=8usize {
        let conv = intervals(&v, n, "convergent");
        let c1 = intervals(&v, n, "c1_spectral");
        assert_eq!(conv.len(), 1, "n = {n}");
        assert_eq!(c1.len(), 1, "n = {n}");
        assert_eq!(conv[0]["from"]["rational"], "0");
        assert_eq!(conv[0]["from_closed"], true);
        if n == 6 {
            for set in [&conv[0], &c1[0]] {
                assert_eq!(set["to"]["rational"], "2");
                assert_eq!(set["to_closed"], true);
            }
            assert_eq!(c1[0]["from"]["rational"], "0");
            continue;
        }
        assert_eq!(conv[0]["to"]["rational"], "13/8", "n = {n}");
        assert_eq!(conv[0]["to_closed"], false, "n = {n}");
        assert_eq!(c1[0]["from_closed"], false);
        assert_eq!(c1[0]["to_closed"], false);
        let what = format!("loop-w n = {n}");
        assert_endpoint_is(&c1[0]["from"], &r(1, 4), &r(-1, 4), n as i64, &format!("{what} lower"));
        assert_endpoint_is(&c1[0]["to"], &r(1, 1), &r(1, 4), n as i64, &format!("{what} upper"));
        // just inside and just outside, in floating point
        let (lo, hi) = (c1[0]["from"]["decimal"].as_f64().unwrap(), c1[0]["to"]["decimal"].as_f64().unwrap());
        assert!(verdict(file, "w", n, lo + 1e-6).0 && verdict(file, "w", n, hi - 1e-6).0, "{what}: C¹ inside");
        assert!(!verdict(file, "w", n, lo - 1e-6).0 && !verdict(file, "w", n, hi + 1e-6).0, "{what}: not outside");
        assert!(verdict(file, "w", n, 13.0 / 8.0 - 1e-6).1 && !verdict(file, "w", n, 13.0 / 8.0 + 1e-6).1, "{what}");
    }
    // the text names the sets with their exact ends
    let out = subdlab(&["sweep", file, "--valences", "3..3", "--param", "w=0:2:1/8", "--exact"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("C1 spectral: (3/8, 7/8)"), "{text}");
    assert!(text.contains("convergent: [0, 13/8)"), "{text}");
    // the certified path decides the same sets
    let c = json(&["sweep", file, "--valences", "4..4", "--param", "w=0:2:1/8", "--exact", "--certify", "--json"]);
    let c1 = intervals(&c, 4, "c1_spectral");
    assert_eq!((c1[0]["from"]["rational"].as_str(), c1[0]["to"]["rational"].as_str()), (Some("1/4"), Some("1")));
    assert!(c1[0]["evidence"].as_str().unwrap().starts_with("certified"), "{}", c1[0]);
}

/// Bad input: one clear line, non-zero exit.
#[test]
fn exact_sweep_refuses_what_it_cannot_do() {
    let err = fails(&["sweep", "non-box", "--valences", "3..4", "--exact"]);
    assert!(err.contains("--param NAME=START:END:STEP"), "{err}");
    fails(&["sweep", "non-box", "--valences", "3..4", "--param", "a=0:1:1/2", "--exact", "--charmap"]);
    fails(&["sweep", "non-box", "--valences", "3..4", "--param", "a=0:1:1/2", "--certify"]);
    let dir = tempfile::tempdir().unwrap();
    for (name, centre, edge) in [
        ("quotient", "1 - w/(1 + w)", "w/((1 + w) n)"),
        ("kronecker", "1 - w + kronecker(w - 1/2)/8", "(w - kronecker(w - 1/2)/8) / n"),
    ] {
        let file = dir.path().join(format!("{name}.toml"));
        std::fs::write(
            &file,
            format!(
                "name = \"{name}\"\ntopology = \"primal-triangle\"\n[params.w]\ndefault = \"3/8\"\nmin = 0\nmax = 2\n\
                 [vertex]\ncentre = \"{centre}\"\nedge = \"{edge}\"\n[edge]\nends = \"3/8\"\nopposite = \"1/8\"\n"
            ),
        )
        .unwrap();
        let err = fails(&["sweep", file.to_str().unwrap(), "--valences", "5..5", "--param", "w=0:1:1/4", "--exact"]);
        assert!(err.contains("not polynomials in w"), "{name}: {err}");
    }
}

/// 4-3 subdivision's centre weight c at mixed eons (`--faces`): Peters and
/// Shiue's Lemma 3.5 gives the eon block's eigenvalues 1, 1/2, 1/2, 1/4
/// (n − 3 times) and 1/2 − α_M = c − 1/2, and the proof of Theorem 3.7 puts
/// the rest of the spectrum at 1/4, 1/8, ...; so on the scheme's range
/// [1/4, 3/4] every other modulus is at most 1/4 < λ1 = 1/2 and both sets
/// are the whole closed range. Checked at both ends with the float spectrum.
#[test]
fn four_three_centre_weight_sets_at_mixed_eons_are_the_whole_range() {
    for faces in ["QTQT", "TTTTT", "QQQ"] {
        let n = faces.len().to_string();
        let valences = format!("{n}..{n}");
        let v = json(&[
            "sweep",
            "four-three",
            "--valences",
            &valences,
            "--faces",
            faces,
            "--param",
            "centre_weight=1/4:3/4:1/10",
            "--exact",
            "--json",
        ]);
        for key in ["convergent", "c1_spectral"] {
            let set = intervals(&v, faces.len(), key);
            assert_eq!(set.len(), 1, "{faces} {key}: {set:?}");
            let i = &set[0];
            assert_eq!(i["from"]["rational"], "1/4", "{faces} {key}");
            assert_eq!(i["to"]["rational"], "3/4", "{faces} {key}");
            assert_eq!((i["from_closed"].as_bool(), i["to_closed"].as_bool()), (Some(true), Some(true)), "{faces}");
        }
        for c in ["1/4", "3/4"] {
            let s = json(&[
                "spectrum",
                "four-three",
                "--valence",
                &n,
                "--faces",
                faces,
                "--param",
                &format!("centre_weight={c}"),
                "--json",
                "--no-exact",
            ]);
            assert_eq!(s["verdict"]["c1_spectral"], true, "{faces} at c = {c}");
        }
    }
    // the sequence fixes the valence
    let err = fails(&[
        "sweep",
        "four-three",
        "--valences",
        "3..5",
        "--faces",
        "QTQT",
        "--param",
        "centre_weight=1/4:3/4:1/10",
        "--exact",
    ]);
    assert!(err.contains("QTQT"), "{err}");
}

/// The curvature classes of the Loop variant with a free vertex weight w
/// (`sweep --exact --curvature`), derived by hand (tests/curvature_loop.rs
/// derives Loop's spectrum; only block 0 reads w):
///
/// - λ = L = 3/8 + c/4, c = cos(2π/n) (blocks 1 and n − 1); block 0 adds
///   5/8 − w; block m adds b(m) = 3/8 + cos(2πm/n)/4, largest below λ at
///   m = 2: b(2) = 3/8 + (2c² − 1)/4 = 1/8 + c²/2; ring 2 adds 1/8 and 1/16
///   in every block. All of them show on the characteristic ring.
/// - L² = 9/64 + 3c/16 + c²/16, so b(2) − L² = (28c² − 12c − 1)/64, whose
///   larger root is c = 1/2: b(2) > L² for n ≥ 7, and then the class is
///   unbounded on the whole C¹ set, whatever w is.
/// - n = 3: blocks 1 and 2 both carry λ = 3/8 − 1/8 = 1/4, and 1/8 > λ² =
///   1/16: unbounded on the whole C¹ set (3/8, 7/8).
/// - n = 4: c = 0, L² = 9/64 > b(2) = 1/8 = 8/64; n = 5: c² = (1 − 2c)/4
///   (4c² + 2c − 1 = 0), L² = 5(1 + c)/32, b(2) = (1 − c)/4, L² − b(2) =
///   (13c − 3)/32 > 0 and L² − 1/8 = (5c + 1)/32 > 0. So μ's modulus
///   against L² is |5/8 − w| against L²: zero on (5/8 − L², 5/8 + L²),
///   bounded at its two ends, unbounded between them and the C¹ ends
///   (5/8 ∓ L). n = 4: (31/64, 49/64); n = 5: 5/8 − L² = 15/32 − 5c/32,
///   5/8 + L² = 25/32 + 5c/32.
/// - n = 6: the rules do not read w (regular Loop): λ = 1/2, b(2) = 1/4 =
///   λ² = 5/8 − 3/8: bounded on all of [0, 2].
///
/// Each end is re-checked with `subdlab curvature` just inside and outside.
#[test]
fn loop_free_vertex_weight_curvature_classes_match_the_hand_derived_sets() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/loop-free-vertex-weight.toml");
    let v = json(&["sweep", file, "--valences", "3..8", "--param", "w=0:2:1/8", "--exact", "--curvature", "--json"]);
    let r = |p: i64, q: i64| BigRational::new(p.into(), q.into());
    let class_at = |n: usize, w: f64| -> String {
        let c =
            json(&["curvature", file, "-n", &n.to_string(), "--param", &format!("w={w:.12}"), "--json", "--no-exact"]);
        c["class"].as_str().unwrap().to_string()
    };
    let classes = |n: usize| {
        let set = v["valences"].as_array().unwrap().iter().find(|s| s["valence"].as_u64() == Some(n as u64)).unwrap();
        assert_eq!(set["exact"], true, "n = {n}: {}", set["not_exact_because"]);
        let c = set["curvature"].clone();
        assert!(c["undecided"].as_array().unwrap().is_empty(), "n = {n}: {}", c["undecided"]);
        (set["c1_spectral"].clone(), c)
    };
    for n in [3usize, 7, 8] {
        let (c1, c) = classes(n);
        assert!(c["zero"].as_array().unwrap().is_empty(), "n = {n}");
        assert!(c["bounded"].as_array().unwrap().is_empty(), "n = {n}");
        let u = c["unbounded"].as_array().unwrap();
        assert_eq!(u.len(), 1, "n = {n}");
        let c1 = &c1[0];
        for key in ["from", "to"] {
            assert_eq!(u[0][key]["decimal"], c1[key]["decimal"], "n = {n} {key}");
            assert_eq!(u[0][format!("{key}_closed")], false, "n = {n}");
        }
        if n == 3 {
            assert_eq!(
                (u[0]["from"]["rational"].as_str(), u[0]["to"]["rational"].as_str()),
                (Some("3/8"), Some("7/8"))
            );
        }
    }
    let (_, c) = classes(6);
    let b = c["bounded"].as_array().unwrap();
    assert_eq!(b.len(), 1);
    assert_eq!((b[0]["from"]["rational"].as_str(), b[0]["to"]["rational"].as_str()), (Some("0"), Some("2")));
    assert_eq!((b[0]["from_closed"].as_bool(), b[0]["to_closed"].as_bool()), (Some(true), Some(true)));
    assert!(c["zero"].as_array().unwrap().is_empty() && c["unbounded"].as_array().unwrap().is_empty());
    for n in [4usize, 5] {
        let (c1, c) = classes(n);
        // the closed forms a + b cos(2π/n) of the zero set's ends
        let (lo, hi) = if n == 4 {
            ((r(31, 64), r(0, 1)), (r(49, 64), r(0, 1)))
        } else {
            ((r(15, 32), r(-5, 32)), (r(25, 32), r(5, 32)))
        };
        let what = format!("loop-w n = {n}");
        let zero = c["zero"].as_array().unwrap();
        assert_eq!(zero.len(), 1, "{what}: {zero:?}");
        assert_eq!((zero[0]["from_closed"].as_bool(), zero[0]["to_closed"].as_bool()), (Some(false), Some(false)));
        assert_endpoint_is(&zero[0]["from"], &lo.0, &lo.1, n as i64, &format!("{what} zero from"));
        assert_endpoint_is(&zero[0]["to"], &hi.0, &hi.1, n as i64, &format!("{what} zero to"));
        // bounded exactly at the two ends, as single closed points
        let bounded = c["bounded"].as_array().unwrap();
        assert_eq!(bounded.len(), 2, "{what}: {bounded:?}");
        for (i, end) in bounded.iter().zip([&lo, &hi]) {
            assert_eq!((i["from_closed"].as_bool(), i["to_closed"].as_bool()), (Some(true), Some(true)));
            assert_endpoint_is(&i["from"], &end.0, &end.1, n as i64, &format!("{what} bounded"));
            assert_endpoint_is(&i["to"], &end.0, &end.1, n as i64, &format!("{what} bounded"));
        }
        // unbounded from each C¹ end (open) to the zero set (open)
        let unbounded = c["unbounded"].as_array().unwrap();
        assert_eq!(unbounded.len(), 2, "{what}: {unbounded:?}");
        assert_eq!(unbounded[0]["from"]["decimal"], c1[0]["from"]["decimal"]);
        assert_eq!(unbounded[1]["to"]["decimal"], c1[0]["to"]["decimal"]);
        assert_endpoint_is(&unbounded[0]["to"], &lo.0, &lo.1, n as i64, &format!("{what} unbounded"));
        assert_endpoint_is(&unbounded[1]["from"], &hi.0, &hi.1, n as i64, &format!("{what} unbounded"));
        for i in unbounded {
            assert_eq!((i["from_closed"].as_bool(), i["to_closed"].as_bool()), (Some(false), Some(false)));
        }
        // just inside and just outside each end of the zero set
        let (x, y) = (zero[0]["from"]["decimal"].as_f64().unwrap(), zero[0]["to"]["decimal"].as_f64().unwrap());
        assert_eq!(class_at(n, x + 1e-6), "zero", "{what}");
        assert_eq!(class_at(n, y - 1e-6), "zero", "{what}");
        assert_eq!(class_at(n, x - 1e-6), "unbounded", "{what}");
        assert_eq!(class_at(n, y + 1e-6), "unbounded", "{what}");
    }
    // the bounded points themselves, where rational (n = 4), with the
    // exact comparison of |μ| = |5/8 − w| and λ² = 9/64
    for w in ["31/64", "49/64"] {
        let c = json(&["curvature", file, "-n", "4", "--param", &format!("w={w}"), "--json"]);
        assert_eq!(c["class"], "bounded", "n = 4, w = {w}");
        assert_eq!(c["evidence"], "exact", "n = 4, w = {w}");
    }
    // the text names the classes
    let out = subdlab(&["sweep", file, "--valences", "4..4", "--param", "w=0:2:1/8", "--exact", "--curvature"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("curvature zero: (31/64, 49/64)"), "{text}");
    assert!(text.contains("curvature bounded: [31/64, 31/64]"), "{text}");
}

/// p(x) for p over Q (lowest first), exactly.
fn eval_q(p: &P, x: &BigRational) -> BigRational {
    p.iter().rev().fold(BigRational::zero(), |acc, c| acc * x + c)
}

/// Lin–Luo's unified √3 scheme at n = 3 (issue 27): a complex pair of
/// block 0 has its modulus overtake λ1 = 1/9 below α = 0.8, which the
/// candidates of real roots meeting did not see. With the modulus family
/// the candidate set is complete: the output says exact. Every end is a
/// rational or the one root of its polynomial in its isolating interval
/// (the polynomial changes sign there, evaluated exactly here), and the
/// float spectrum agrees 1e-6 inside and outside each interior end. The
/// spectrum at α = 0.8 (not C¹ in floating point: |λ3| > 1/9 there) lies
/// outside the set.
/// The exact sets of unified-sqrt3's α in [0, 2] at valence n: complete
/// (`endpoints_exact`), every irrational end the one root of its polynomial
/// in its isolating interval (an exact sign change here), and the float
/// spectrum agreeing 1e-6 inside and outside each interior end. Returns the
/// C¹ set.
fn check_unified_sqrt3_exact_sets(n: usize) -> Vec<serde_json::Value> {
    let valences = format!("{n}..{n}");
    let v =
        json(&["sweep", "unified-sqrt3", "--valences", &valences, "--param", "alpha=0:2:1/10", "--exact", "--json"]);
    let c1 = intervals(&v, n, "c1_spectral");
    let conv = intervals(&v, n, "convergent");
    assert!(!c1.is_empty());
    let (window_lo, window_hi) = (0.0, 2.0);
    for (key, set) in [("c1_spectral", c1), ("convergent", conv)] {
        for iv in set {
            assert_eq!(iv["endpoints_exact"], true, "{iv}");
            for (end, inside_sign) in [("from", 1.0), ("to", -1.0)] {
                let e = &iv[end];
                let x = e["decimal"].as_f64().unwrap();
                if let Some(r) = e["polynomial"].as_array() {
                    let p: P = r.iter().map(|c| rat(c.as_str().unwrap())).collect();
                    let iv2 = e["isolating_interval"].as_array().unwrap();
                    let (a, b) = (rat(iv2[0].as_str().unwrap()), rat(iv2[1].as_str().unwrap()));
                    let (fa, fb) = (eval_q(&p, &a), eval_q(&p, &b));
                    assert!(fa.clone() * fb < BigRational::zero(), "{key} {end}: no sign change in ({a}, {b})");
                    let (af, bf) =
                        (num_traits::ToPrimitive::to_f64(&a).unwrap(), num_traits::ToPrimitive::to_f64(&b).unwrap());
                    assert!(af <= x && x <= bf, "{key} {end}: {x} outside ({af}, {bf})");
                } else {
                    assert_eq!(num_traits::ToPrimitive::to_f64(&rat(e["rational"].as_str().unwrap())).unwrap(), x);
                }
                if x <= window_lo || x >= window_hi {
                    continue;
                }
                let pick = |value: f64| {
                    let (c1, conv) = verdict("unified-sqrt3", "alpha", n, value);
                    if key == "c1_spectral" {
                        c1
                    } else {
                        conv
                    }
                };
                assert!(pick(x + inside_sign * 1e-6), "{key}: the float verdict fails just inside {x}");
                assert!(!pick(x - inside_sign * 1e-6), "{key}: the float verdict holds just outside {x}");
            }
        }
    }
    c1.clone()
}

#[test]
fn unified_sqrt3_alpha_sets_are_exact_at_valence_3() {
    let c1 = check_unified_sqrt3_exact_sets(3);
    assert!(!verdict("unified-sqrt3", "alpha", 3, 0.8).0, "float C¹ at 0.8");
    assert!(
        c1.iter()
            .all(|iv| iv["to"]["decimal"].as_f64().unwrap() < 0.8 || iv["from"]["decimal"].as_f64().unwrap() > 0.8),
        "0.8 inside the C¹ set"
    );
    let out = subdlab(&["sweep", "unified-sqrt3", "--valences", "3..3", "--param", "alpha=0:2:1/10", "--exact"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(!text.contains("NOT PROVED"), "{text}");
}

/// unified-sqrt3 at n = 4 (exact since the modulus family; minutes before
/// the modular subresultants, seconds now): the same checks as at n = 3,
/// and the C¹ set is one interval from 0 whose end the float spectrum
/// confirms (inside/outside, in the helper).
/// unified-sqrt3 at n = 5: the block polynomials have coefficients in
/// Q(√5) (Q(ζ_5) ∩ R), and complex pairs occur on every piece; the modulus
/// family over Q(ζ_5) (norms over the Galois conjugates) makes the
/// candidate set complete. The same checks as at n = 3 (every end by an
/// exact sign change and by the float spectrum 1e-6 inside and outside).
#[test]
fn unified_sqrt3_alpha_sets_are_exact_at_valence_5() {
    let c1 = check_unified_sqrt3_exact_sets(5);
    assert_eq!(c1.len(), 1, "{c1:?}");
    assert_eq!(c1[0]["from"]["rational"], "0");
}

#[test]
fn unified_sqrt3_alpha_sets_are_exact_at_valence_4() {
    let c1 = check_unified_sqrt3_exact_sets(4);
    assert_eq!(c1.len(), 1, "{c1:?}");
    assert_eq!(c1[0]["from"]["rational"], "0");
    assert!(c1[0]["to"]["decimal"].as_f64().unwrap() < 2.0);
}

/// The curvature classes where μ is a complex pair
/// (`tests/data/catmull-clark-complex-centre.toml`, `sweep --exact
/// --curvature`), derived by hand:
///
/// - Only Fourier block 0 reads the centre's rule. On the 1-ring (v, e, f)
///   it is [[1/2 − b, b, 1/2], [3/8, 1/2, 1/8], [1/4, 1/2, 1/4]] (edge
///   point 3/8 (v + e_j) + 1/16 (e_{j±1} + f_{j−1} + f_j), face point 1/4
///   of its corners), rows summing to 1: eigenvalue 1, and the other two
///   have sum trace − 1 = 1/4 − b and product det = ((1/2 − b)/16 − b/16 +
///   1/2 · 1/16) = (1 − 2b)/16. Discriminant (1/4 − b)² − (1 − 2b)/4 =
///   b² − 3/16 < 0 on [0, 2/5] (2/5 < √3/4): a complex pair μ, μ̄ with
///   |μ|² = (1 − 2b)/16.
/// - λ1 is Catmull–Clark's (blocks 1, 2 do not read b): block m on the
///   1-ring has x² − (5 + c)/8 x + 1/16, c = cos(2πm/n) (sum (5 + c)/8,
///   product ((5 + c)² − (1 + c)(9 + c))/256 = 1/16); n = 3, c = −1/2:
///   16x² − 9x + 1, λ1 = (9 + √17)/32 ≈ 0.41010, the other root ≈ 0.15240.
///   The outer rings add 1/8, 1/16, 1/32, 1/64 (Stam).
/// - λ1² = (49 + 9√17)/512 ≈ 0.16818: every real eigenvalue below λ1 is
///   below λ1² (0.15240, 1/8, ...), so the class is |μ| against λ1²:
///   |μ|² = λ1⁴ ⟺ (1 − 2b)/16 = (3778 + 882√17)/262144 ⟺ b* = (6303 −
///   441√17)/16384 ≈ 0.273725, the smaller root of 16384 b² − 12606 b +
///   2223 (irreducible: discriminant 882²·17). |μ| falls as b grows:
///   unbounded on [0, b*), bounded at b*, zero on (b*, 2/5]; C¹ on all of
///   [0, 2/5] (|μ|² ≤ 1/16 < λ1²).
///
/// Before, the classes' ends were floating point (the modulus resultant
/// against λ1's block vanished identically: 1/8 · 1/32 = (1/16)², and
/// |μ| = λ1² for non-real μ was not followed at all) and put the end at
/// 1/4. The end is re-checked with `subdlab curvature` 1e-6 on each side.
#[test]
fn curvature_classes_with_a_complex_mu_are_exact() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/catmull-clark-complex-centre.toml");
    let v = json(&["sweep", file, "--valences", "3..3", "--param", "b=0:2/5:1/10", "--exact", "--curvature", "--json"]);
    let set = &v["valences"][0];
    assert_eq!(set["exact"], true, "{}", set["not_exact_because"]);
    let c = &set["curvature"];
    assert_eq!(c["exact"], true, "{}", c["not_exact_because"]);
    assert!(c["undecided"].as_array().unwrap().is_empty(), "{}", c["undecided"]);
    // a piece has a non-real eigenvalue, so the exactness above rests on the
    // modulus family (not on an all-real spectrum)
    let decisions = set["decisions"].as_array().unwrap();
    assert!(decisions.iter().any(|d| d["all_real"] == false), "no piece with a complex pair");
    for key in ["convergent", "c1_spectral"] {
        let i = set[key].as_array().unwrap();
        assert_eq!(i.len(), 1, "{key}");
        assert_eq!((i[0]["from"]["rational"].as_str(), i[0]["to"]["rational"].as_str()), (Some("0"), Some("2/5")));
    }
    // b* as the root of m = 16384 b² − 12606 b + 2223 (made monic for rem)
    let m: P = vec![rat("2223/16384"), rat("-12606/16384"), rat("1")];
    let b_star = (6303.0 - 441.0 * 17f64.sqrt()) / 16384.0;
    let is_b_star = |e: &serde_json::Value, what: &str| {
        assert!(e["rational"].is_null(), "{what}: {e}");
        let p: P = e["polynomial"].as_array().unwrap().iter().map(|x| rat(x.as_str().unwrap())).collect();
        assert!(rem(&p, &m).is_empty(), "{what}: {e} does not vanish at b*");
        let iv = e["isolating_interval"].as_array().unwrap();
        let (lo, hi) = (rat(iv[0].as_str().unwrap()), rat(iv[1].as_str().unwrap()));
        let (lo, hi) = (num_traits::ToPrimitive::to_f64(&lo).unwrap(), num_traits::ToPrimitive::to_f64(&hi).unwrap());
        assert!(lo <= b_star + 1e-14 && b_star - 1e-14 <= hi, "{what}: ({lo}, {hi}) misses {b_star}");
        // the other root of m (≈ 0.4957) is outside [0, 2/5], so b* is the one
    };
    let one = |key: &str| -> serde_json::Value {
        let list = c[key].as_array().unwrap();
        assert_eq!(list.len(), 1, "{key}: {list:?}");
        list[0].clone()
    };
    let (u, b, z) = (one("unbounded"), one("bounded"), one("zero"));
    assert_eq!(u["from"]["rational"], "0");
    assert_eq!((u["from_closed"].as_bool(), u["to_closed"].as_bool()), (Some(true), Some(false)));
    is_b_star(&u["to"], "unbounded to");
    assert_eq!((b["from_closed"].as_bool(), b["to_closed"].as_bool()), (Some(true), Some(true)));
    is_b_star(&b["from"], "bounded from");
    is_b_star(&b["to"], "bounded to");
    assert_eq!((z["from_closed"].as_bool(), z["to_closed"].as_bool()), (Some(false), Some(true)));
    is_b_star(&z["from"], "zero from");
    assert_eq!(z["to"]["rational"], "2/5");
    for i in [&u, &b, &z] {
        assert_eq!(i["endpoints_exact"], true);
    }
    // b* is a root of the non-real |μ| = λ1² family
    let squares = c["square_candidates"].as_array().unwrap();
    assert!(squares.iter().any(|e| (e["decimal"].as_f64().unwrap() - b_star).abs() < 1e-12), "{squares:?}");
    // the floating-point analysis 1e-6 on each side, and at the old end 1/4
    let class_at = |b: f64| -> String {
        let c = json(&["curvature", file, "-n", "3", "--param", &format!("b={b:.12}"), "--json", "--no-exact"]);
        c["class"].as_str().unwrap().to_string()
    };
    assert_eq!(class_at(b_star - 1e-6), "unbounded");
    assert_eq!(class_at(b_star + 1e-6), "zero");
    assert_eq!(class_at(0.26), "unbounded");
}
