//! The certificate document (`spectrum --certify --certificate FILE`) and its
//! independent checker, `scripts/check_cert.py`: certificates that subdlab
//! writes are accepted, and tampered ones are rejected, each by the check
//! that the tampering breaks.
//!
//! The checker needs `python3` (standard library only); where it is absent
//! the tests say so and pass (CI's machine has it).

use crate::common::checker_can_run;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const CHECKER: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/check_cert.py");

/// Writes the certificate of `COMMAND ARGS --certify` (`spectrum` or
/// `charmap`) to `dir/name.json`.
fn certificate_of(command: &str, dir: &Path, name: &str, args: &[&str]) -> PathBuf {
    let path = dir.join(format!("{name}.json"));
    let out = Command::new(env!("CARGO_BIN_EXE_subdlab"))
        .arg(command)
        .args(args)
        .args(["--certify", "--certificate"])
        .arg(&path)
        .output()
        .unwrap();
    // 0 proved, 1 disproved or not proved (the certificate is written
    // either way), 2 an error
    assert!(matches!(out.status.code(), Some(0 | 1)), "{command} {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    path
}

/// The spectral certificate of `spectrum ARGS --certify`.
fn certificate(dir: &Path, name: &str, args: &[&str]) -> PathBuf {
    certificate_of("spectrum", dir, name, args)
}

/// The checker's exit status, its output, and its time.
fn check(path: &Path) -> (i32, String, Duration) {
    let start = Instant::now();
    let out = Command::new("python3").arg(CHECKER).arg(path).output().unwrap();
    let took = start.elapsed();
    let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    (out.status.code().unwrap_or(-1), text, took)
}

fn assert_accepted(path: &Path, what: &str) {
    let (code, text, took) = check(path);
    eprintln!("checker {:>6.0} ms  {what}", took.as_secs_f64() * 1e3);
    assert_eq!(code, 0, "{what}: {text}");
    assert!(text.contains("CERTIFICATE ACCEPTED"), "{what}: {text}");
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Writes a tampered copy and expects the checker to reject it (exit 1) with
/// a reason containing `because` (alternatives separated by " | ": a
/// tampering may break more than one check, and the first failed one is
/// reported).
fn assert_rejected(dir: &Path, name: &str, doc: &Value, because: &str) {
    let path = dir.join(format!("tampered-{name}.json"));
    std::fs::write(&path, serde_json::to_string(doc).unwrap()).unwrap();
    assert_rejected_file(&path, because);
}

/// Expects the checker to reject the document at `path` (exit 1) with a
/// reason containing `because` (alternatives separated by " | ").
fn assert_rejected_file(path: &Path, because: &str) {
    let (code, text, _) = check(path);
    assert_eq!(code, 1, "{}: {text}", path.display());
    let reason = text.lines().find(|l| l.starts_with("CERTIFICATE REJECTED")).unwrap_or_default();
    assert!(
        because.split(" | ").any(|b| reason.contains(b)),
        "{}: expected a rejection for '{because}', got: {text}",
        path.display()
    );
}

#[test]
fn certificates_of_catmull_clark_loop_and_doo_sabin_are_accepted() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for scheme in ["catmull-clark", "loop", "doo-sabin"] {
        for n in ["3", "5", "8"] {
            let path = certificate(dir.path(), &format!("{scheme}-{n}"), &[scheme, "-n", n]);
            let doc = read(&path);
            assert_eq!(doc["format"], "subdlab-certificate");
            assert_eq!(doc["version"], 1);
            assert_eq!(doc["parts"]["spectrum"]["verdict"], "PROVED", "{scheme} {n}");
            assert_accepted(&path, &format!("{scheme} n = {n}"));
        }
    }
}

/// The registry's certified claims (`certified = true`): id, check kind and
/// the number of configurations each decides (a listed valence that no face
/// sequence has the length of, and every face sequence), read from the TOML
/// files here, not from subdlab.
fn certified_claims() -> Vec<(String, String, usize)> {
    let mut out = Vec::new();
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/claims");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    for file in files.iter().filter(|f| f.extension().is_some_and(|e| e == "toml")) {
        let doc: toml::Value = toml::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
        for claim in doc.get("claim").and_then(|c| c.as_array()).into_iter().flatten() {
            if claim.get("certified").and_then(|c| c.as_bool()) != Some(true) {
                continue;
            }
            let faces: Vec<&str> = claim
                .get("faces")
                .and_then(|f| f.as_array())
                .into_iter()
                .flatten()
                .filter_map(|f| f.as_str())
                .collect();
            let mut valences: Vec<usize> = match claim.get("valences") {
                Some(toml::Value::String(range)) => {
                    let (a, b) = range.split_once("..").unwrap();
                    (a.parse().unwrap()..=b.parse().unwrap()).collect()
                }
                Some(toml::Value::Array(list)) => list.iter().map(|v| v.as_integer().unwrap() as usize).collect(),
                None => Vec::new(),
                v => panic!("valences {v:?}"),
            };
            valences.sort_unstable();
            valences.dedup();
            let mut distinct = faces.clone();
            distinct.sort_unstable();
            distinct.dedup();
            let regular = valences.iter().filter(|&&n| !faces.iter().any(|f| f.len() == n)).count();
            let id = claim["id"].as_str().unwrap().to_string();
            out.push((id, claim["check"].as_str().unwrap().to_string(), regular + distinct.len()));
        }
    }
    out
}

/// Every certificate the registry's certified claims rest on, one per claim
/// and configuration (`verify --certificates DIR`), is re-checked by the
/// independent checker: the spectral part of every one, and the map part of
/// every characteristic-map claim's. Two checkers run side by side; each
/// file is removed once accepted (the whole set is about half a gigabyte).
#[test]
fn every_certificate_of_the_registry_is_accepted() {
    if !checker_can_run() {
        return;
    }
    let claims = certified_claims();
    let kinds: Vec<&str> = claims.iter().map(|c| c.1.as_str()).collect();
    assert!(kinds.contains(&"spectral-c1") && kinds.contains(&"characteristic-map"), "{kinds:?}");
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_subdlab"))
        .args(["verify", "--check-expected", "--certificates"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(out.status.success(), "verify: {}", String::from_utf8_lossy(&out.stderr));
    let mut written: Vec<PathBuf> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().path()).collect();
    written.sort();
    let name = |p: &Path| p.file_name().unwrap().to_string_lossy().into_owned();
    for (id, kind, configurations) in &claims {
        let prefix = format!("{id}-n");
        let mine: Vec<&PathBuf> = written.iter().filter(|p| name(p).starts_with(&prefix)).collect();
        assert_eq!(mine.len(), *configurations, "{id}: certificates written");
        if kind == "characteristic-map" {
            for p in &mine {
                let doc = read(p);
                assert!(doc["parts"]["charmap"].is_object(), "{}: no map part ({})", name(p), doc["charmap_omitted"]);
            }
        }
    }
    let total: usize = claims.iter().map(|c| c.2).sum();
    assert_eq!(written.len(), total, "certificates written in all");
    let next = std::sync::atomic::AtomicUsize::new(0);
    let failures = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let k = next.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                let Some(path) = written.get(k) else { break };
                let (code, text, _) = check(path);
                if code == 0 && text.contains("CERTIFICATE ACCEPTED") {
                    std::fs::remove_file(path).unwrap();
                } else {
                    failures.lock().unwrap().push(format!("{}: {text}", name(path)));
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    assert!(failures.is_empty(), "{} of {total} certificates rejected: {failures:#?}", failures.len());
    eprintln!("{total} registry certificates accepted");
}

#[test]
fn the_disproof_of_a_block_2_dominant_loop_variant_is_accepted() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let scheme = concat!(env!("CARGO_MANIFEST_DIR"), "/schemes/loop-block2-dominant.toml");
    let path = certificate(dir.path(), "block2", &[scheme, "-n", "5"]);
    assert_eq!(read(&path)["parts"]["spectrum"]["verdict"], "DISPROVED");
    assert_accepted(&path, "loop-block2-dominant n = 5 (DISPROVED)");
}

/// The certificate of `charmap ARGS --certify` (spectral and map parts).
fn charmap_certificate(dir: &Path, name: &str, args: &[&str]) -> PathBuf {
    certificate_of("charmap", dir, name, args)
}

/// The characteristic-map part beside the spectral one: accepted for a
/// primal quad, a triangle, a dual, the 4-3 scheme (PROVED), and for the
/// folded control (regularity DISPROVED by faces of both proved signs).
#[test]
fn charmap_certificates_are_accepted() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let folded = concat!(env!("CARGO_MANIFEST_DIR"), "/schemes/catmull-clark-folded-ring.toml");
    let cases: [(&str, &str, &str, &str); 6] = [
        ("catmull-clark", "3", "PROVED", "PROVED"),
        ("catmull-clark", "5", "PROVED", "PROVED"),
        ("loop", "5", "PROVED", "PROVED"),
        ("doo-sabin", "5", "PROVED", "PROVED"),
        ("four-three", "5", "PROVED", "PROVED"),
        (folded, "5", "DISPROVED", "DISPROVED"),
    ];
    for (k, (scheme, n, regularity, c1)) in cases.into_iter().enumerate() {
        let start = Instant::now();
        let path = charmap_certificate(dir.path(), &format!("charmap-{k}"), &[scheme, "-n", n]);
        let written = start.elapsed();
        let doc = read(&path);
        let part = &doc["parts"]["charmap"];
        assert!(part.is_object(), "{scheme} {n}: no charmap part ({})", doc["charmap_omitted"]);
        assert_eq!(part["regularity"], regularity, "{scheme} {n}");
        assert_eq!(part["c1"], c1, "{scheme} {n}");
        let bytes = std::fs::metadata(&path).unwrap().len();
        eprintln!("written {:>6.0} ms, {bytes:>9} bytes", written.as_secs_f64() * 1e3);
        assert_accepted(&path, &format!("charmap {scheme} n = {n}"));
    }
}

#[test]
fn tampered_charmap_parts_are_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cc = read(&charmap_certificate(d, "cc5", &["catmull-clark", "-n", "5"]));
    let edit = |f: &dyn Fn(&mut Value)| {
        let mut doc = cc.clone();
        f(&mut doc["parts"]["charmap"]);
        doc
    };
    // a Jacobian sign claimed the other way
    let t = edit(&|c| c["faces"][0]["sign"] = Value::from("-"));
    assert_rejected(d, "sign", &t, "claimed negative");
    // one exact stencil weight by 1/1000
    let t = edit(&|c| {
        let w = c["points"]["stencils"][0][0][1].as_str().unwrap().to_string();
        c["points"]["stencils"][0][0][1] = Value::from(nudged(&w));
    });
    assert_rejected(d, "stencil", &t, "do not sum to 1");
    // the eigenvector of another disc than λ1's
    let t = edit(&|c| c["eigenvector"]["disc"] = Value::from(1));
    assert_rejected(d, "disc", &t, "λ1's disc is row");
    // a polygon point moved to the other side of the centre
    let t = edit(&|c| {
        let p = c["winding"]["polygon"][0].clone();
        c["winding"]["polygon"][0] = Value::from(vec![-p[0].as_f64().unwrap(), -p[1].as_f64().unwrap()]);
    });
    assert_rejected(d, "polygon", &t, "not in the half-plane");
    // a half-plane turned away from its window
    let t = edit(&|c| {
        let p = c["winding"]["directions"][3].clone();
        c["winding"]["directions"][3] = Value::from(vec![p[1].as_f64().unwrap(), -p[0].as_f64().unwrap()]);
    });
    assert_rejected(d, "direction", &t, "not proved in its half-plane | not in the half-plane");
    // a wrong winding number
    let t = edit(&|c| c["winding"]["number"] = Value::from(2));
    assert_rejected(d, "winding", &t, "the document claims 2");
    // regularity PROVED with a face left undecided
    let t = edit(&|c| c["faces"][5]["sign"] = Value::from("?"));
    assert_rejected(d, "undecided", &t, "every ring face proved of one sign");
    // a C¹ verdict that does not follow from its parts
    let t = edit(&|c| c["injectivity"] = Value::from("NOT PROVED"));
    assert_rejected(d, "c1", &t, "does not follow from its parts");
}

/// A non-box certificate (the S_3^1 window: the face's own edges and the
/// differences of the 9 FCVs around it, with their lattice layout) is
/// accepted, and the checker, which re-derives from the layout which
/// differences and hull points the spline's bounds need, rejects a window
/// missing one of them or laid out otherwise.
#[test]
fn a_non_box_charmap_certificate_is_re_derived_and_its_tampering_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let path = charmap_certificate(d, "nb5", &["non-box", "-n", "5"]);
    let nb = read(&path);
    let part = &nb["parts"]["charmap"];
    assert_eq!(part["regular_part"], "non-box-s31");
    assert_eq!(part["c1"], "PROVED");
    // per face 2 V–V and 6 FCV–FCV differences along each direction, over
    // the face's 4 corners and the 9 FCVs around it (lemma C3′)
    let face = &part["faces"][0];
    assert_eq!(face["u_edges"].as_array().unwrap().len(), 8);
    assert_eq!(face["v_edges"].as_array().unwrap().len(), 8);
    assert_eq!(face["layout"].as_array().unwrap().len(), 13);
    assert_accepted(&path, "charmap non-box n = 5");
    let edit = |f: &dyn Fn(&mut Value)| {
        let mut doc = nb.clone();
        f(&mut doc["parts"]["charmap"]);
        doc
    };
    // an FCV–FCV difference left out of a window (the last u-edge is one)
    let t = edit(&|c| {
        c["faces"][0]["u_edges"].as_array_mut().unwrap().pop();
    });
    assert_rejected(d, "nb-missing-difference", &t, "not listed");
    // the layout moved by one face: the edges no longer cover the face
    let t = edit(&|c| {
        for e in c["faces"][2]["layout"].as_array_mut().unwrap() {
            e[1] = Value::from(e[1].as_i64().unwrap() + 2);
        }
    });
    assert_rejected(d, "nb-layout", &t, "lacks the face's corner | not listed | not among the window's points");
    // a window claimed of another kind: the layout no longer belongs
    let t = edit(&|c| c["regular_part"] = Value::from("bicubic-b-spline"));
    let path = d.join("tampered-nb-kind.json");
    std::fs::write(&path, serde_json::to_string(&t).unwrap()).unwrap();
    let (code, text, _) = check(&path);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("a lattice layout, but the regular part"), "{text}");
}

/// Weights known in floating point only: the document says so, and the
/// checker cannot re-verify it.
#[test]
fn a_certificate_without_exact_rows_is_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let scheme = dir.path().join("loop-root-two.toml");
    std::fs::write(
        &scheme,
        "name = \"loop-root-two\"\ntopology = \"primal-triangle\"\n\n[vertex]\n\
         centre = \"3/8 + (3/8 + sqrt(2) / 8)^2\"\nedge = \"(5/8 - (3/8 + sqrt(2) / 8)^2) / n\"\n\n\
         [edge]\nends = \"3/8\"\nopposite = \"1/8\"\n",
    )
    .unwrap();
    let path = certificate(dir.path(), "float-only", &[scheme.to_str().unwrap(), "-n", "5"]);
    let doc = read(&path);
    assert_eq!(doc["parts"]["spectrum"]["exact"], false);
    assert!(!doc["parts"]["spectrum"]["inexact_rows"].as_array().unwrap().is_empty());
    let (code, text, _) = check(&path);
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("floating point only"), "{text}");
}

/// p/q + 1/1000, as the document writes rationals.
fn nudged(ratio: &str) -> String {
    let (p, q) = ratio.split_once('/').unwrap();
    let (p, q): (i128, i128) = (p.parse().unwrap(), q.parse().unwrap());
    format!("{}/{}", p * 1000 + q, q * 1000)
}

#[test]
fn tampered_certificates_are_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cc = read(&certificate(d, "cc5", &["catmull-clark", "-n", "5"]));
    let lp = read(&certificate(d, "loop5", &["loop", "-n", "5"]));
    // a copy with its spectral part edited
    let edit = |doc: &Value, f: &dyn Fn(&mut Value)| {
        let mut doc = doc.clone();
        f(&mut doc["parts"]["spectrum"]);
        doc
    };

    // one weight of one row, by 1/1000: a rational (the centre's row) ...
    let t = edit(&cc, &|s| {
        let w = s["rows"][0][0][1].as_str().unwrap().to_string();
        s["rows"][0][0][1] = Value::from(nudged(&w));
    });
    assert_rejected(d, "weight", &t, "does not sum to 1 | Gershgorin bound");
    // ... a weight of a row off the representatives (its rotation no longer matches)
    let t = edit(&cc, &|s| {
        let last = s["rows"].as_array().unwrap().len() - 1;
        let w = s["rows"][last][0][1].as_str().unwrap().to_string();
        s["rows"][last][0][1] = Value::from(nudged(&w));
        let w = s["rows"][last][1][1].as_str().unwrap().to_string();
        // keep its sum 1: only the rotation premise can catch it
        let (p, q) = w.split_once('/').unwrap();
        let (p, q): (i128, i128) = (p.parse().unwrap(), q.parse().unwrap());
        s["rows"][last][1][1] = Value::from(format!("{}/{}", p * 1000 - q, q * 1000));
    });
    assert_rejected(d, "weight-rotated", &t, "rotated");
    // ... and a cyclotomic weight (Loop's centre row holds cos(2π/5))
    let t = edit(&lp, &|s| {
        let coeffs = &mut s["rows"][0][0][1]["coefficients"];
        let w = coeffs[0][1].as_str().unwrap().to_string();
        coeffs[0][1] = Value::from(nudged(&w));
    });
    assert_rejected(d, "cyclotomic-weight", &t, "does not sum to 1 | Gershgorin bound");

    // a disc radius shrunk far below any Gershgorin bound (δ alone is about
    // ε·‖M‖ with ε ≥ 1e-16 for a floating-point V; the radius holds rounding
    // bounds a few times that, so shrinking by 10⁶ must be caught)
    let t = edit(&cc, &|s| {
        let r = s["blocks"][1]["discs"][0][2].as_f64().unwrap();
        s["blocks"][1]["discs"][0][2] = Value::from(r / 1e6);
    });
    assert_rejected(d, "radius", &t, "Gershgorin bound");

    // V perturbed: the claimed ε understates ‖I − RV‖∞
    let t = edit(&cc, &|s| {
        let v = s["blocks"][1]["v"][0][0][0].as_f64().unwrap();
        s["blocks"][1]["v"][0][0][0] = Value::from(v + 1e-6);
    });
    assert_rejected(d, "v", &t, "claimed ε");

    // a claimed count
    let t = edit(&cc, &|s| {
        let c = s["blocks"][0]["components"][1]["count"].as_u64().unwrap();
        s["blocks"][0]["components"][1]["count"] = Value::from(c + 1);
    });
    assert_rejected(d, "count", &t, "eigenvalue(s) for its");
    // two components merged into one claimed as simple (λ0's with the next)
    let t = edit(&cc, &|s| {
        let comps = s["blocks"][0]["components"].as_array_mut().unwrap();
        let second = comps.remove(1);
        comps[0]["discs"].as_array_mut().unwrap().extend(second["discs"].as_array().unwrap().clone());
    });
    assert_rejected(d, "merged", &t, "eigenvalue(s) for its");

    // λ1's component swapped for the next one of block 1
    let t = edit(&cc, &|s| s["claims"]["lambda1"][0]["component"] = Value::from(1));
    assert_rejected(d, "lambda1", &t, "gap not shown");

    // a row dropped
    let t = edit(&cc, &|s| {
        s["rows"].as_array_mut().unwrap().pop();
    });
    assert_rejected(d, "row-dropped", &t, "rows for a matrix of");

    // the mirror map of another reflection (two points swapped)
    let t = edit(&cc, &|s| {
        let q = s["mirror"].as_array_mut().unwrap();
        let (a, b) = (q[1].clone(), q[2].clone());
        q[1] = b;
        q[2] = a;
    });
    assert_rejected(d, "mirror", &t, "premise");

    // PROVED claimed on a DISPROVED certificate: as written (it names no
    // λ1), and with λ1 named as the leading components of blocks 1 and g − 1
    let scheme = concat!(env!("CARGO_MANIFEST_DIR"), "/schemes/loop-block2-dominant.toml");
    let wrong = read(&certificate(d, "block2", &[scheme, "-n", "5"]));
    let t = edit(&wrong, &|s| s["verdict"] = Value::from("PROVED"));
    assert_rejected(d, "proved-unnamed", &t, "names no λ1");
    let t = edit(&wrong, &|s| {
        s["verdict"] = Value::from("PROVED");
        s["claims"]["lambda1"] = serde_json::json!([{ "block": 1, "component": 0 }, { "block": 4, "component": 0 }]);
    });
    assert_rejected(d, "proved-named", &t, "gap not shown");
    // and DISPROVED claimed on a PROVED one, with a witness
    let t = edit(&cc, &|s| {
        s["verdict"] = Value::from("DISPROVED");
        s["claims"]["witness"] = serde_json::json!({ "block": 2, "component": 0 });
    });
    assert_rejected(d, "disproved", &t, "DISPROVED");

    // a part this checker cannot re-check
    let mut t = cc.clone();
    t["parts"]["curvature"] = serde_json::json!({});
    assert_rejected(d, "unknown-part", &t, "re-checks only");

    // not a certificate at all: exit 2
    let path = d.join("garbage.json");
    std::fs::write(&path, "{\"format\": \"something else\"}").unwrap();
    assert_eq!(check(&path).0, 2);
    std::fs::write(&path, "not json").unwrap();
    assert_eq!(check(&path).0, 2);
}

/// The soundness controls of `tests/certify_soundness.rs` (files in
/// `tests/data/certify/`): the checker re-derives each verdict from the
/// document alone — the disproofs by a dominant other block (toggle-block2)
/// and by "no candidate" (analysis-gap: every positive candidate of block 1
/// outdone by the outer −3/4), the PROVED spectrum of the toggle reproducer,
/// the QTQTQT 4-3 eon whose reflection is a sector's bisector — and rejects
/// each turned into a PROVED.
#[test]
fn the_soundness_controls_are_re_derived_and_their_flips_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let data = |f: &str| format!("{}/tests/data/certify/{f}", env!("CARGO_MANIFEST_DIR"));
    let cases: [(&str, Vec<String>, &str); 4] = [
        ("toggle-block2", vec![data("toggle-block2.toml"), "-n".into(), "7".into()], "DISPROVED"),
        ("analysis-gap", vec![data("analysis-gap.toml"), "-n".into(), "5".into()], "DISPROVED"),
        ("toggle-cc", vec![data("toggle-cc.toml"), "-n".into(), "5".into()], "PROVED"),
        (
            "four-three-QTQTQT",
            ["four-three", "-n", "6", "--faces", "QTQTQT"].iter().map(|s| s.to_string()).collect(),
            "PROVED",
        ),
    ];
    for (name, args, verdict) in cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let path = certificate(dir.path(), name, &args);
        let doc = read(&path);
        assert_eq!(doc["parts"]["spectrum"]["verdict"], verdict, "{name}");
        assert_accepted(&path, name);
        if verdict == "DISPROVED" {
            let mut flipped = doc.clone();
            flipped["parts"]["spectrum"]["verdict"] = "PROVED".into();
            assert_rejected(dir.path(), name, &flipped, "");
        }
    }
}

/// Lemma S7, the exact route: a 4-3 eon surrounded by QQT has no rotation
/// to split λ1's pair; its certificate rests on det(xI − S) over Q, which
/// the checker recomputes by another algorithm. Accepted as written; a
/// claimed λ1 that is not the double root, or a bound on the other
/// eigenvalues below the truth, rejected.
#[test]
fn the_exact_route_is_re_derived_and_its_tamperings_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let path = certificate(d, "qqt", &["four-three", "-n", "3", "--faces", "QQT"]);
    let doc = read(&path);
    let spectrum = &doc["parts"]["spectrum"];
    assert_eq!(spectrum["verdict"], "PROVED");
    // 4-3 subdivision's λ1 is 1/2 (the paper's leading eigenvalues 1, 1/2, 1/2, 1/4)
    assert_eq!(spectrum["claims"]["exact_route"]["lambda1"], "1/2");
    assert_accepted(&path, "four-three QQT (exact route)");
    let edit = |f: &dyn Fn(&mut Value)| {
        let mut doc = doc.clone();
        f(&mut doc["parts"]["spectrum"]["claims"]["exact_route"]);
        doc
    };
    // 1/4 is an eigenvalue too, but not a double one with the rest below it
    let quarter = edit(&|r| {
        r["lambda1"] = "1/4".into();
        r["others_below"] = "1/4".into();
    });
    assert_rejected(d, "lambda1-quarter", &quarter, "multiplicity | may have modulus");
    assert_rejected(d, "bound-above-lambda1", &edit(&|r| r["lambda1"] = "1/4".into()), "not in [0, λ1]");
    let third = edit(&|r| {
        r["lambda1"] = "1/3".into();
        r["others_below"] = "1/3".into();
    });
    assert_rejected(d, "lambda1-third", &third, "multiplicity 0");
    // the 1/4 of the spectrum is not below 1/8
    assert_rejected(d, "others-below", &edit(&|r| r["others_below"] = "1/8".into()), "may have modulus ≥ 1/8");
}

/// Lemma S6 (ARCHITECTURE.md): blocks other than 0, 1, g − 1 bounded by
/// ‖B^k‖∞^(1/k). Polar bi-2's blocks m ∉ {0, ±1} are lower triangular on
/// each radial line (a' = 0, b' = 3/4 a + 1/4 b, c' = 1/4 a + 3/4 b: the
/// spoke rule's ring weights have no Fourier component there), with
/// eigenvalues 1/4, 0, 0 and 0 defective, so their discs fail or are wide;
/// λ1 = 1/2. The proof takes these blocks from S6, and the checker
/// recomputes B^k from the exact rows.
#[test]
fn polar_bi2_certificates_by_lemma_s6_are_accepted() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // n = 12: blocks 2 and 10 have no disc enclosure at all
    for (args, failed) in [
        (vec!["polar-bi2", "-n", "5"], vec![]),
        (vec!["polar-bi2", "-n", "12"], vec![2, 10]),
        (vec!["unified-sqrt3", "--param", "alpha=1", "-n", "8"], vec![4]),
    ] {
        let name = args.join("-");
        let path = certificate(dir.path(), &name, &args);
        let doc = read(&path);
        let s = &doc["parts"]["spectrum"];
        assert_eq!(s["verdict"], "PROVED", "{name}");
        let g = s["group_order"].as_u64().unwrap();
        let bounded: Vec<u64> =
            s["claims"]["power_bounds"].as_array().unwrap().iter().map(|p| p["block"].as_u64().unwrap()).collect();
        assert!(!bounded.is_empty(), "{name}");
        // never λ0's or λ1's block, and every block without discs among them
        assert!(bounded.iter().all(|&m| m != 0 && m != 1 && m != g - 1), "{name}: {bounded:?}");
        for m in failed {
            assert!(!s["blocks"][m]["failure"].is_null(), "{name}: block {m} has discs");
            assert!(bounded.contains(&(m as u64)), "{name}: block {m}");
        }
        for p in s["claims"]["power_bounds"].as_array().unwrap() {
            // the bound is below λ1's lower bound, and above polar's true
            // spectral radius 1/4 of the block (a bound cannot beat ρ)
            let (radius, l1) = (p["radius"].as_f64().unwrap(), p["lambda1_lower"].as_f64().unwrap());
            assert!(radius < l1, "{name}: {p}");
            if name.starts_with("polar") {
                assert!(radius >= 0.25 && (l1 - 0.5).abs() < 1e-9, "{name}: {p}");
            }
        }
        assert_accepted(&path, &name);
    }
}

/// `p/q + r/s` for the document's rationals.
fn add_ratio(a: &str, b: &num_rational::BigRational) -> String {
    let x: num_rational::BigRational = a.parse().unwrap();
    let y = x + b;
    format!("{}/{}", y.numer(), y.denom())
}

#[test]
fn tampered_lemma_s6_evidence_is_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p5 = read(&certificate(d, "polar5", &["polar-bi2", "-n", "5"]));
    let p12 = read(&certificate(d, "polar12", &["polar-bi2", "-n", "12"]));
    let edit = |doc: &Value, f: &dyn Fn(&mut Value)| {
        let mut doc = doc.clone();
        f(&mut doc["parts"]["spectrum"]);
        doc
    };
    // a smaller claimed norm than the rows give
    let t = edit(&p5, &|s| {
        let n = s["claims"]["power_bounds"][0]["norm"].as_f64().unwrap();
        s["claims"]["power_bounds"][0]["norm"] = Value::from(n / 2.0);
    });
    assert_rejected(d, "s6-norm", &t, "below the recomputed bound");
    // k = 1: ‖B‖∞ itself (polar's block rows have sums up to 1) does not clear λ1
    let t = edit(&p5, &|s| s["claims"]["power_bounds"][0]["k"] = Value::from(1));
    assert_rejected(d, "s6-k", &t, "does not clear λ1");
    // a power k the checker does not accept
    let t = edit(&p5, &|s| s["claims"]["power_bounds"][0]["k"] = Value::from(3));
    assert_rejected(d, "s6-k3", &t, "not a power of two");
    // a lower bound of λ1 above λ1 = 1/2
    let t = edit(&p5, &|s| s["claims"]["power_bounds"][0]["lambda1_lower"] = Value::from(0.6));
    assert_rejected(d, "s6-ell", &t, "does not show");
    // S6 claimed for λ1's own block
    let t = edit(&p5, &|s| s["claims"]["power_bounds"][0]["block"] = Value::from(1));
    assert_rejected(d, "s6-block1", &t, "holds λ0 or λ1");
    // a claimed radius below norm^(1/k)
    let t = edit(&p5, &|s| s["claims"]["power_bounds"][0]["radius"] = Value::from(0.3));
    assert_rejected(d, "s6-radius", &t, "radius");
    // the bound of a block dropped: its wide discs (n = 5) reach λ1, and a
    // block without discs (n = 12) is left with nothing
    let t = edit(&p5, &|s| s["claims"]["power_bounds"] = Value::from(Vec::<Value>::new()));
    assert_rejected(d, "s6-dropped", &t, "gap not shown");
    let t = edit(&p12, &|s| {
        let kept: Vec<Value> =
            s["claims"]["power_bounds"].as_array().unwrap().iter().filter(|p| p["block"] != 2).cloned().collect();
        s["claims"]["power_bounds"] = Value::from(kept);
    });
    assert_rejected(d, "s6-dropped-failed", &t, "no enclosure");

    // the exact rows changed, every premise kept: at n = 4 (g = 4, all rows
    // rational) add δ·h(P) on the points off the pole, h(z) = (z + 1/z − 2)
    // (z + 1/z) = z² + z⁻² − 2z − 2z⁻¹ + 2 (P the rotation). h is symmetric
    // (commutes with the reflection), h(1) = 0 (row sums and block 0 kept),
    // h(±i) = 0 (blocks 1 and 3 kept), h(−1) = 8: block 2 gains 8δ·I. With
    // δ = 1/32 block 2's eigenvalues 1/4, 0, 0 become 1/2, 1/4, 1/4: its
    // spectral radius is λ1 = 1/2, which no bound clears. Block 2's discs are
    // dropped (declared failed) so that only S6 speaks for it.
    let p4 = read(&certificate(d, "polar4", &["polar-bi2", "-n", "4"]));
    assert!(
        p4["parts"]["spectrum"]["claims"]["power_bounds"].as_array().unwrap().iter().any(|p| p["block"] == 2),
        "polar n = 4 takes block 2 from S6"
    );
    let t = edit(&p4, &|s| {
        let g = s["group_order"].as_u64().unwrap() as usize;
        assert_eq!(g, 4);
        let member: Vec<(usize, usize)> = s["orbits"]["member"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| (m[0].as_u64().unwrap() as usize, m[1].as_u64().unwrap() as usize))
            .collect();
        let fixed: Vec<bool> = s["orbits"]["fixed"].as_array().unwrap().iter().map(|f| f.as_bool().unwrap()).collect();
        let mut index = vec![vec![usize::MAX; g]; fixed.len()];
        for (k, &(o, t)) in member.iter().enumerate() {
            index[o][t] = k;
        }
        let delta = num_rational::BigRational::new(1.into(), 32.into());
        // z⁰: 2, z^±1: −2 each, z² = z⁻² (g = 4): 1 + 1
        let h: [(usize, i64); 4] = [(0, 2), (1, -2), (3, -2), (2, 2)];
        for (k, &(o, t)) in member.iter().enumerate() {
            if fixed[o] {
                continue;
            }
            let row = s["rows"][k].as_array_mut().unwrap();
            for (steps, c) in h {
                let col = index[o][(t + steps) % g];
                let add = &delta * num_rational::BigRational::from_integer(c.into());
                match row.iter_mut().find(|e| e[0].as_u64() == Some(col as u64)) {
                    Some(e) => e[1] = Value::from(add_ratio(e[1].as_str().expect("rational rows at n = 4"), &add)),
                    None => row.push(Value::from(vec![
                        Value::from(col),
                        Value::from(format!("{}/{}", add.numer(), add.denom())),
                    ])),
                }
            }
        }
        let b = &mut s["blocks"][2];
        b["failure"] = Value::from("dropped");
        for key in ["v", "r"] {
            b[key] = Value::Null;
        }
        b["discs"] = Value::from(Vec::<Value>::new());
        b["components"] = Value::from(Vec::<Value>::new());
    });
    assert_rejected(d, "s6-rows", &t, "does not clear λ1");
}

/// Lemma S7's disproof: polar bi-2 with the radial rule (1/2, 1/2) at n = 6
/// (`tests/data/certify/polar-radial-tie.toml`, derived there by hand: the
/// radial 1/2 in every block beside the spoke's 1/2, a Jordan structure at
/// λ1 = 1/2). The checker recomputes the multiplicities; a claimed
/// geometric multiplicity of 2 (a semisimple double λ1, nothing disproved)
/// or another λ1 is rejected.
#[test]
fn an_exact_disproof_at_a_defective_lambda1_is_re_derived() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/certify/polar-radial-tie.toml");
    let path = certificate(d, "tie", &[file, "-n", "6", "--param", "w=1/2"]);
    let doc = read(&path);
    let s = &doc["parts"]["spectrum"];
    assert_eq!(s["verdict"], "DISPROVED", "{}", s["reason"]);
    let route = &s["claims"]["exact_route"];
    assert_eq!(route["lambda1"], "1/2");
    assert!(route["algebraic"].as_u64().unwrap() > route["geometric"].as_u64().unwrap(), "{route}");
    assert_accepted(&path, "polar-radial-tie w = 1/2, n = 6 (DISPROVED by lemma S7)");
    let edit = |f: &dyn Fn(&mut Value)| {
        let mut doc = doc.clone();
        f(&mut doc["parts"]["spectrum"]["claims"]["exact_route"]);
        doc
    };
    assert_rejected(d, "geometric", &edit(&|r| r["geometric"] = 2.into()), "dimension");
    assert_rejected(d, "lambda1", &edit(&|r| r["lambda1"] = "1/4".into()), "multiplicity | dominant");
}

// ---- Lemma C9 (difference-scheme) parts: Kobbelt √3's characteristic map is
// re-derived from the document alone — the mask's sanity, the windows'
// closure, the second-difference bases, S_c and M_c, K_edge and K_pos, the
// word norms and every face's Jacobian (refined on its own window where
// needed) and hull — and tampered documents are rejected by the check the
// tampering breaks.

/// The certificate of `charmap sqrt3 -n N --certify`, written once per
/// valence and test run under cargo's temporary directory for tests.
fn sqrt3_certificate(n: &str) -> PathBuf {
    // the tests run in parallel: one writes a valence's file, the others wait
    static WRITTEN: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("check_cert_c9");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("sqrt3-{n}.json"));
    let mut written = WRITTEN.lock().unwrap_or_else(|e| e.into_inner());
    if !written.iter().any(|w| w == n) {
        certificate_of("charmap", &dir, &format!("sqrt3-{n}"), &["sqrt3", "-n", n]);
        written.push(n.to_string());
    }
    path
}

/// Writes a copy of `source` with its charmap part `c` changed by the
/// Python statements `edit` (Python's json writes every float as the
/// shortest decimal that round-trips, so the rest of the document stays
/// bit-identical; serde_json's default parser may move a float by an ulp).
fn tampered(source: &Path, dir: &Path, name: &str, edit: &str) -> PathBuf {
    let path = dir.join(format!("tampered-{name}.json"));
    let script = format!(
        "import json, sys\ndoc = json.load(open(sys.argv[1], encoding='utf-8'))\nc = doc['parts']['charmap']\n{edit}\n\
         json.dump(doc, open(sys.argv[2], 'w', encoding='utf-8'))\n"
    );
    let out = Command::new("python3").arg("-c").arg(&script).arg(source).arg(&path).output().unwrap();
    assert!(out.status.success(), "{name}: the tampering failed: {}", String::from_utf8_lossy(&out.stderr));
    path
}

#[test]
fn kobbelt_sqrt3_difference_scheme_certificates_are_re_derived_and_accepted() {
    if !checker_can_run() {
        return;
    }
    for n in ["4", "5"] {
        let path = sqrt3_certificate(n);
        let doc = read(&path);
        let part = &doc["parts"]["charmap"];
        assert_eq!(part["regular_part"], "difference-scheme", "sqrt3 n = {n}: the proof is lemma C9's");
        assert_eq!(part["c1"], "PROVED", "sqrt3 n = {n}");
        let (code, text, _) = check(&path);
        assert_eq!(code, 0, "sqrt3 n = {n}: {text}");
        assert!(text.contains("CERTIFICATE ACCEPTED (spectrum PROVED, C¹ PROVED)"), "sqrt3 n = {n}: {text}");
        // the lattice half is re-derived, not read: Kobbelt's √3 over one
        // analysis step (two √3 steps, D = 3), 27-point windows
        assert!(text.contains("lemma C9 mask: 9 classes"), "{text}");
        assert!(text.contains("K_edge = max‖κ‖₁ = 10/3"), "{text}");
        assert!(text.contains("P_3 < 1"), "{text}");
        assert!(text.contains("lemma C9 faces"), "{text}");
    }
}

#[test]
fn tampered_difference_scheme_parts_are_rejected() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let source = sqrt3_certificate("4");
    let cases: &[(&str, &str, &str)] = &[
        // a mask weight changed: the class's weights no longer sum to 1
        ("mask-weight", "c['difference']['mask'][0][2][0][2] = '1/27'", "the weights do not sum to 1"),
        // a mask weight moved one lattice point further: Σ w·δ ≠ 0
        (
            "mask-moment",
            "t = c['difference']['mask'][0][2]\nassert t[0] == [-3, 0, '2/27']\nt[0] = [-6, 0, '2/27']",
            "does not reproduce linear data",
        ),
        // a wider but still affine rule (sums and moments kept), reaching four
        // lattice points out: the windows are no longer closed under it (a
        // change of the mask that keeps them closed is checked like any mask:
        // that it is the scheme's rule is trusted)
        (
            "mask-wider",
            "t = c['difference']['mask'][0][2]\n\
             i = [k for k, e in enumerate(t) if e[:2] == [0, 0]][0]\nassert t[i][2] == '5/9'\n\
             t[i][2] = '241/450'\nt += [[-12, 0, '1/100'], [12, 0, '1/100']]",
            "window is not closed",
        ),
        // a window without one of its corners
        ("window-corner", "c['difference']['windows']['up'].remove([1, 0])", "lacks its corner"),
        // a basis row repeated in place of another: dependent rows
        ("basis-dependent", "b = c['difference']['basis']['up']\nb[1] = b[0]", "not independent"),
        // a basis row that is no second difference
        (
            "basis-not-second-difference",
            "c['difference']['basis']['up'][0][0][2] = 2",
            "does not vanish on affine data",
        ),
        // words of one child do not contract (P_1 ≈ 2.57)
        ("word-1", "c['difference']['word'] = 1", "not proved contractive"),
        // no refinement: every face of the valence-4 ring needs its window
        // refined to decide its sign
        ("depth-0", "c['difference']['depth'] = 0", "the Jacobian is claimed positive"),
        // a flipped face sign
        ("sign", "c['faces'][0]['sign'] = '-'", "the Jacobian is claimed negative"),
        // a window point's index swapped with a corner's: the face's own
        // edges are no longer the listed u- and v-edges
        (
            "window-swap",
            "w = c['faces'][0]['window']\n\
             i = [k for k, e in enumerate(w) if e[1:] == [0, 0]][0]\n\
             j = [k for k, e in enumerate(w) if e[1:] == [2, -1]][0]\n\
             w[i][0], w[j][0] = w[j][0], w[i][0]",
            "not the window's own edges",
        ),
        // the face mirrored: corners (1,0) and (0,1) swapped in the window
        // and in the edges alike, so the re-derived Jacobian is negative
        (
            "window-mirror",
            "f = c['faces'][0]\nw = f['window']\n\
             i = [k for k, e in enumerate(w) if e[1:] == [1, 0]][0]\n\
             j = [k for k, e in enumerate(w) if e[1:] == [0, 1]][0]\n\
             a, b = w[i][0], w[j][0]\nw[i][0], w[j][0] = b, a\n\
             assert f['u_edges'][0][1] == a and f['v_edges'][0][1] == b\n\
             f['u_edges'][0][1], f['v_edges'][0][1] = b, a",
            "the Jacobian is claimed positive",
        ),
        // a window position moved off W_up
        (
            "window-position",
            "w = c['faces'][0]['window']\ni = [k for k, e in enumerate(w) if e[1:] == [3, 0]][0]\nw[i][1] = 4",
            "not the up window",
        ),
    ];
    for (name, edit, because) in cases {
        assert_rejected_file(&tampered(&source, d, name, edit), because);
    }
}

#[test]
fn the_documents_own_constants_are_not_used() {
    if !checker_can_run() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // claimed constants zero change nothing: the checker derives its own
    // and only reports the document's
    let path = tampered(
        &sqrt3_certificate("5"),
        dir.path(),
        "constants-zero",
        "x = c['difference']\nfor k in ('k_edge', 'k_pos', 'edge_constant', 'position_constant'):\n    x[k] = 0.0\n\
         x['word_norms'] = [1.0, 0.0, 0.0, 0.0]",
    );
    let (code, text, _) = check(&path);
    assert_eq!(code, 0, "{text}");
    assert!(text.contains("ε ≤ 26.2421793·N(p)"), "the checker's own ε factor: {text}");
}
