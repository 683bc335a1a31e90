//! Shared helpers for the integration tests (closed forms live in each test).
#![allow(dead_code)]

pub mod exact;

use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Analysis, Method, Options};

pub fn scheme(name: &str) -> Box<dyn Scheme> {
    schemes::build(name, &[]).unwrap()
}

/// Every built-in mesh scheme, from the scheme registry (so a new scheme is
/// covered by the cross-scheme tests without editing a list).
pub fn mesh_scheme_names() -> Vec<&'static str> {
    schemes::registry::names_of(schemes::registry::Family::Mesh)
}

pub fn run(name: &str, n: usize, kind: NeighbourhoodKind, method: Option<Method>, exact: bool) -> Analysis {
    let s = scheme(name);
    let config = Configuration::regular(s.as_ref(), n).unwrap();
    analyse(s.as_ref(), &config, &Options { neighbourhood: kind, method, exact }).unwrap()
}

/// Every eigenvalue repeated by its algebraic multiplicity, as (re, im).
pub fn expanded(a: &Analysis) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = a
        .spectrum
        .eigenvalues
        .iter()
        .flat_map(|e| std::iter::repeat_n((e.re, e.im), e.algebraic_multiplicity))
        .collect();
    v.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    v
}

/// Assert that two multisets of real numbers agree to `tol` (sorted comparison).
pub fn assert_same_multiset(mut got: Vec<f64>, mut want: Vec<f64>, tol: f64, what: &str) {
    got.sort_by(f64::total_cmp);
    want.sort_by(f64::total_cmp);
    assert_eq!(got.len(), want.len(), "{what}: sizes differ: got {got:?}, want {want:?}");
    for (g, w) in got.iter().zip(&want) {
        assert!(approx::abs_diff_eq!(*g, *w, epsilon = tol), "{what}: got {got:?}, want {want:?}");
    }
}

pub fn real_spectrum(a: &Analysis) -> Vec<f64> {
    expanded(a)
        .into_iter()
        .map(|(re, im)| {
            assert!(im.abs() < 1e-9, "unexpected complex eigenvalue {re}+{im}i");
            re
        })
        .collect()
}

pub fn cos2pi(k: usize, n: usize) -> f64 {
    (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos()
}
pub fn sin2pi(k: usize, n: usize) -> f64 {
    (2.0 * std::f64::consts::PI * k as f64 / n as f64).sin()
}

/// Is `v` (numerically) in the span of `basis`? Least squares by Gram–Schmidt.
pub fn in_span(basis: &[Vec<f64>], v: &[f64]) -> bool {
    let mut ortho: Vec<Vec<f64>> = Vec::new();
    for b in basis {
        let mut r = b.clone();
        for q in &ortho {
            let d: f64 = q.iter().zip(&r).map(|(x, y)| x * y).sum();
            r.iter_mut().zip(q).for_each(|(x, y)| *x -= d * y);
        }
        let n = r.iter().map(|x| x * x).sum::<f64>().sqrt();
        if n > 1e-12 {
            ortho.push(r.iter().map(|x| x / n).collect());
        }
    }
    let mut r = v.to_vec();
    for q in &ortho {
        let d: f64 = q.iter().zip(&r).map(|(x, y)| x * y).sum();
        r.iter_mut().zip(q).for_each(|(x, y)| *x -= d * y);
    }
    let vn = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    r.iter().map(|x| x * x).sum::<f64>().sqrt() < 1e-8 * vn.max(1.0)
}

/// All products a·b of two lists (tensor-product spectra).
pub fn products(a: &[f64], b: &[f64]) -> Vec<f64> {
    a.iter().flat_map(|x| b.iter().map(move |y| x * y)).collect()
}

/// Run the subdlab binary.
pub fn subdlab(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_subdlab")).args(args).output().expect("binary runs")
}

/// A failing invocation: non-zero exit, exactly one line on stderr, no panic;
/// returns the line.
pub fn fails(args: &[&str]) -> String {
    let out = subdlab(args);
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(!out.status.success(), "{args:?} should fail");
    assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    // usage errors are clap's whole message (the error line, the usage line,
    // the --help hint); every other error is one line
    if err.trim_end().ends_with("For more information, try '--help'.") {
        assert_eq!(out.status.code(), Some(2), "{args:?}: usage errors exit 2");
        assert!(err.starts_with("error: "), "{args:?}: {err:?}");
        return err.lines().next().unwrap_or_default().to_string();
    }
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: one-line error expected, got {err:?}");
    err
}

/// xorshift64*: a fixed seed, so a failure reproduces.
pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// Counts one case of a fuzz test that mutates a file and loads (and runs)
/// it: a load or run error must be one non-empty line, and a panic fails the
/// test with the input that caused it.
pub fn tally_fuzz_case<E: std::fmt::Display>(
    case: usize,
    text: &str,
    result: std::thread::Result<Result<(), E>>,
    accepted: &mut usize,
    rejected: &mut usize,
) {
    match result {
        Ok(Ok(())) => *accepted += 1,
        Ok(Err(e)) => {
            let e = e.to_string();
            assert!(!e.contains('\n') && !e.is_empty(), "case {case}: error not one line: {e:?}\n{text}");
            *rejected += 1;
        }
        Err(_) => panic!("case {case} panicked on:\n{text}"),
    }
}

/// The curvature class Peters–Reif's definitions give for a closed-form μ
/// (largest modulus below λ) and λ², for comparison with `subdlab::curvature`.
pub fn class_from_closed_forms(mu: f64, lambda_squared: f64) -> subdlab::curvature::CurvatureClass {
    use subdlab::curvature::CurvatureClass;
    if (mu - lambda_squared).abs() < 1e-12 {
        CurvatureClass::Bounded
    } else if mu > lambda_squared {
        CurvatureClass::Unbounded
    } else {
        CurvatureClass::Zero
    }
}

/// The outcome the built-in registry computes for claim `id`, evaluated on
/// its own (the claim's own check code: builtin, identity, matrix-eigenvalues,
/// ...). Tests that derive a paper statement by hand use it to pin the
/// registry's verdict by that independent derivation.
pub fn registry_outcome(id: &str) -> subdlab::claims::Outcome {
    for file in subdlab::claims::builtin_files().unwrap() {
        if let Some(claim) = file.claims.iter().find(|c| c.id == id) {
            let alone = subdlab::claims::ClaimFile { claims: vec![claim.clone()], ..file.clone() };
            return subdlab::claims::evaluate(&alone).pop().unwrap();
        }
    }
    panic!("no registry claim '{id}'")
}

/// [`registry_outcome`], checking that the claim belongs to `paper`.
pub fn registry_outcome_in(paper: &str, id: &str) -> subdlab::claims::Outcome {
    let o = registry_outcome(id);
    assert_eq!(o.paper, paper, "{id}");
    o
}

/// Asserts the registry's verdict on `id` is `want`, the verdict the calling
/// test derived by hand.
pub fn assert_registry_verdict(id: &str, want: subdlab::claims::Verdict) {
    let o = registry_outcome(id);
    assert_eq!(o.verdict, want, "{id}: the registry says {} ({}), the hand derivation {want}", o.verdict, o.detail);
}

/// Whether `python3` runs here (the certificate checker's tests skip, saying
/// so, where it does not).
pub fn checker_can_run() -> bool {
    let found = std::process::Command::new("python3").arg("--version").output().is_ok_and(|o| o.status.success());
    if !found {
        eprintln!("SKIPPED: python3 is not installed; the certificate checker cannot run");
    }
    found
}

/// `scripts/check_cert.py FILE`: its exit status and standard output.
pub fn check_certificate(path: &std::path::Path) -> (i32, String) {
    let checker = format!("{}/scripts/check_cert.py", env!("CARGO_MANIFEST_DIR"));
    let out = std::process::Command::new("python3").arg(&checker).arg(path).output().unwrap();
    (out.status.code().unwrap_or(-1), String::from_utf8_lossy(&out.stdout).to_string())
}

/// `subdlab charmap SCHEME ARGS --tag boundary --certify --certificate
/// DIR/FILE` (a certified sector map at a boundary vertex); the file's path.
/// The command must decide (exit 0 or 1), never fail.
pub fn write_sector_certificate(dir: &std::path::Path, file: &str, scheme: &str, args: &[&str]) -> std::path::PathBuf {
    let path = dir.join(file);
    let mut all = vec!["charmap", scheme];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--tag", "boundary", "--certify", "--certificate", path.to_str().unwrap()]);
    let out = subdlab(&all);
    assert!(out.status.code().is_some_and(|c| c <= 1), "{}", String::from_utf8_lossy(&out.stderr));
    path
}

/// `subdlab spectrum ARGS --certify --certificate DIR/FILE`; the file's path.
pub fn write_spectrum_certificate(dir: &std::path::Path, file: &str, args: &[&str]) -> std::path::PathBuf {
    let path = dir.join(file);
    let mut all: Vec<&str> = vec!["spectrum"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--certify", "--certificate", path.to_str().unwrap()]);
    subdlab(&all);
    path
}

/// The checker's answer `(code, text)` on a tampered document is a
/// rejection (exit 1) whose reason contains `why`; `what` names the edit.
pub fn assert_rejected((code, text): (i32, String), why: &str, what: &str) {
    assert_eq!(code, 1, "{what}: {text}");
    assert!(text.contains("CERTIFICATE REJECTED") && text.contains(why), "{what}: {text}");
}

/// A copy of the certificate `dir/file` with `edit` applied, written to
/// `dir/bad-file` and checked: the checker's exit status and output.
pub fn check_tampered_certificate(
    dir: &std::path::Path,
    file: &str,
    edit: &dyn Fn(&mut serde_json::Value),
) -> (i32, String) {
    let text = std::fs::read_to_string(dir.join(file)).unwrap();
    let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    edit(&mut doc);
    let bad = dir.join(format!("bad-{file}"));
    std::fs::write(&bad, serde_json::to_string(&doc).unwrap()).unwrap();
    check_certificate(&bad)
}
