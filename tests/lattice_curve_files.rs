//! Lattice (Z²) and curve (Z) scheme files: each shipped file gives exactly the
//! local matrix of the built-in scheme it restates (two separate routes: the
//! file's masks are typed from the paper, the built-in's are Rust code), a
//! wrong weight gives another matrix, malformed files fail with one line that
//! names the file, the line and the field, and the command line runs the files
//! end to end.

use crate::common;
use common::{fails, subdlab};

use std::path::{Path, PathBuf};

use num_bigint::BigInt;
use subdlab::curves::local::{analysis_window, curve_spectrum, local_matrix as curve_matrix, minimal_window};
use subdlab::curves::{CurveScheme, CurveWeight};
use subdlab::lattice::{self, LatticeScheme};
use subdlab::neighbourhood::NeighbourhoodKind;
use subdlab::numeric::Rational;
use subdlab::schemes::curves;
use subdlab::schemes::registry::{self, Built, Family};

fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn q(p: i64, d: i64) -> Rational {
    Rational::new(BigInt::from(p), BigInt::from(d))
}

fn lattice_of(arg: &str) -> Box<dyn LatticeScheme> {
    registry::lattice(arg, &[]).unwrap()
}

fn curve_of(arg: &str, params: &[(&str, &str)]) -> Box<dyn CurveScheme> {
    let p: Vec<(String, String)> = params.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
    curves::build(arg, &p).unwrap()
}

/// Minimal and analysis windows of both schemes, and their exact matrices.
fn lattice_matrices(s: &dyn LatticeScheme) -> Vec<(lattice::Window, Vec<Vec<Rational>>)> {
    let minimal = lattice::minimal_invariant_window(s, &[(0, 0)]).unwrap();
    let analysis = lattice::analysis_window(s, 1).unwrap();
    [minimal, analysis]
        .into_iter()
        .map(|w| {
            let m = lattice::local_matrix::<Rational>(s, &w).unwrap();
            (w, m)
        })
        .collect()
}

#[test]
fn lattice_files_give_the_builtin_matrices_exactly() {
    for (file, builtin) in
        [("schemes/khan-mustafa.toml", "khan-mustafa"), ("schemes/khan-mustafa-cubic.toml", "khan-mustafa-cubic")]
    {
        let path = repo(file);
        let f = lattice_of(path.to_str().unwrap());
        let b = lattice_of(builtin);
        assert_ne!(f.name(), b.name(), "{file}: a file must not pass for the built-in");
        // each window is found from each scheme's own masks; they must coincide
        for ((wf, mf), (wb, mb)) in lattice_matrices(f.as_ref()).into_iter().zip(lattice_matrices(b.as_ref())) {
            assert_eq!(wf, wb, "{file}: windows differ");
            assert!(!mf.is_empty());
            for (r, (rf, rb)) in mf.iter().zip(&mb).enumerate() {
                assert_eq!(rf, rb, "{file}: row {r} ({}) differs", lattice::point_name(wf.points[r]));
            }
        }
        // the float stencils are the built-in's to the last bit (each weight
        // the correctly rounded value of the same rational), parity by parity
        for (a, bb) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let sorted = |s: &dyn LatticeScheme| {
                let mut v = lattice::stencil::<f64>(s, (a, bb));
                v.sort_by_key(|e| e.0);
                v
            };
            assert_eq!(sorted(f.as_ref()), sorted(b.as_ref()), "{file}: float stencil of parity ({a}, {bb})");
        }
    }
}

/// The files' curve masks and local matrices against the built-ins, exactly.
fn same_curve(file: &dyn CurveScheme, builtin: &dyn CurveScheme, what: &str) {
    let mf = Rational::mask(file).unwrap();
    let mb = Rational::mask(builtin).unwrap();
    assert_eq!(mf, mb, "{what}: masks differ");
    for (wf, wb) in [
        (minimal_window(&mf).unwrap(), minimal_window(&mb).unwrap()),
        (analysis_window(&mf).unwrap(), analysis_window(&mb).unwrap()),
    ] {
        assert_eq!(wf, wb, "{what}: windows differ");
        let (a, b) = (curve_matrix(&mf, &wf).unwrap().dense(), curve_matrix(&mb, &wb).unwrap().dense());
        assert_eq!(a, b, "{what}: local matrices differ on {wf:?}");
    }
}

#[test]
fn curve_files_give_the_builtin_matrices_exactly() {
    let file = |rel: &str| repo(rel).to_str().unwrap().to_string();
    same_curve(
        curve_of(&file("schemes/curve-cubic-bspline.toml"), &[]).as_ref(),
        curve_of("cubic-bspline", &[]).as_ref(),
        "cubic B-spline",
    );
    same_curve(
        curve_of(&file("schemes/curve-four-point.toml"), &[]).as_ref(),
        curve_of("four-point", &[]).as_ref(),
        "four-point",
    );
    // the unified scheme across its range, including both ends and the two
    // values where it is a named scheme (α = 1 B-spline, α = 0 four-point,
    // where the zero weights must drop out of the dependencies alike)
    for alpha in ["0", "1/3", "1/2", "1", "3/2", "2", "0.25"] {
        same_curve(
            curve_of(&file("schemes/curve-unified.toml"), &[("alpha", alpha)]).as_ref(),
            curve_of("unified-curve", &[("alpha", alpha)]).as_ref(),
            &format!("unified alpha = {alpha}"),
        );
    }
}

#[test]
fn cubic_bspline_file_has_the_closed_form_spectrum() {
    // The cubic B-spline reproduces cubics, and one step halves the parameter
    // about the centre, so the samples of 1, x, x², x³ are eigenvectors with
    // eigenvalues 1, 1/2, 1/4, 1/8. On the analysis window {−2..2} the matrix
    // is 5×5 with diagonal 1/8 (fine −2 = 2·(−1) weighs old −2 by 1/8), 1/2,
    // 3/4, 1/2, 1/8: trace 2 = 15/8 + λ₅, so λ₅ = 1/8 again.
    let s = curve_of(repo("schemes/curve-cubic-bspline.toml").to_str().unwrap(), &[]);
    let spec = curve_spectrum(s.as_ref(), NeighbourhoodKind::Analysis).unwrap();
    assert!(spec.exact);
    assert_eq!(spec.window, vec![-2, -1, 0, 1, 2]);
    let got: Vec<(String, usize)> =
        spec.eigenvalues.iter().map(|e| (e.exact.clone().unwrap(), e.algebraic_multiplicity)).collect();
    let want: Vec<(String, usize)> =
        [(q(1, 1), 1), (q(1, 2), 1), (q(1, 4), 1), (q(1, 8), 2)].iter().map(|(v, m)| (v.to_string(), *m)).collect();
    assert_eq!(got, want);
}

/// A copy of a shipped file with one line replaced, in a temporary folder.
fn edited(rel: &str, from: &str, to: &str) -> (tempfile::TempDir, PathBuf) {
    let text = std::fs::read_to_string(repo(rel)).unwrap();
    assert_eq!(text.matches(from).count(), 1, "'{from}' must occur once in {rel}");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(Path::new(rel).file_name().unwrap());
    std::fs::write(&path, text.replace(from, to)).unwrap();
    (dir, path)
}

#[test]
fn a_wrong_weight_gives_another_matrix() {
    // move 1/144 from p[i+1,j+1] to p[i,j] in the face rule: still affine, so
    // the file loads, but the matrix is no longer Khan–Mustafa's
    let text = std::fs::read_to_string(repo("schemes/khan-mustafa.toml")).unwrap();
    let face = text.find("[mask-11]").unwrap();
    let mut changed = text.clone();
    changed.replace_range(
        face..,
        &text[face..].replacen("\"0,0\" = 56", "\"0,0\" = 57", 1).replacen("\"1,1\" = 29", "\"1,1\" = 28", 1),
    );
    assert_ne!(changed, text);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("km-wrong.toml");
    std::fs::write(&path, changed).unwrap();
    let wrong = lattice_of(path.to_str().unwrap());
    let right = lattice_of("khan-mustafa");
    let w = lattice::minimal_invariant_window(right.as_ref(), &[(0, 0)]).unwrap();
    let (a, b) = (
        lattice::local_matrix::<Rational>(wrong.as_ref(), &w).unwrap(),
        lattice::local_matrix::<Rational>(right.as_ref(), &w).unwrap(),
    );
    // the face rule is the stencil of the fine points with both indices odd:
    // exactly their rows change, each in two entries by ∓1/144
    for (r, &p) in w.points.iter().enumerate() {
        let changed: Vec<Rational> = a[r].iter().zip(&b[r]).filter(|(u, v)| u != v).map(|(u, v)| u - v).collect();
        if p.0.rem_euclid(2) == 1 && p.1.rem_euclid(2) == 1 {
            let mut d = changed.clone();
            d.sort();
            assert_eq!(d, vec![q(-1, 144), q(1, 144)], "row {}", lattice::point_name(p));
        } else {
            assert!(changed.is_empty(), "row {}", lattice::point_name(p));
        }
    }

    // the same for a curve file: the four-point odd rule with a wrong tension
    // default (still affine) is not the built-in four-point scheme
    let (_d, path) = edited("schemes/curve-four-point.toml", "default = \"1/16\"", "default = \"1/17\"");
    let f = curve_of(path.to_str().unwrap(), &[]);
    assert_ne!(Rational::mask(f.as_ref()).unwrap(), Rational::mask(curve_of("four-point", &[]).as_ref()).unwrap());
}

#[test]
fn a_weight_that_breaks_the_sum_is_refused_with_its_line() {
    let (_d, path) = edited("schemes/khan-mustafa.toml", "\"0,0\" = 80", "\"0,0\" = 81");
    let e = registry::resolve(path.to_str().unwrap(), &[]).err().unwrap().to_string();
    assert!(e.contains("field mask-00: the weights of the mask-00 mask sum to 145/144"), "{e}");
}

/// Write `text` to a file and load it; the error.
fn load_error(text: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, text).unwrap();
    match registry::resolve(path.to_str().unwrap(), &[]) {
        Ok(_) => panic!("should not load:\n{text}"),
        Err(e) => {
            // a scheme file that does not load is a file error
            assert!(matches!(e, subdlab::error::Error::File(_)), "{e:?}");
            let e = e.to_string();
            assert_eq!(e.lines().count(), 1, "{e}");
            assert!(e.starts_with(path.to_str().unwrap()), "{e}");
            e
        }
    }
}

const CURVE_OK: &str = "domain = \"curve\"\nname = \"c\"\n[even]\n\"0\" = 1\n[odd]\n\"0\" = \"1/2\"\n\"1\" = \"1/2\"\n";

#[test]
fn malformed_files_fail_with_the_line_and_the_field() {
    // the well-formed base loads, so each error below is due to its one change
    let dir = tempfile::tempdir().unwrap();
    let ok = dir.path().join("ok.toml");
    std::fs::write(&ok, CURVE_OK).unwrap();
    assert_eq!(registry::resolve(ok.to_str().unwrap(), &[]).unwrap().family(), Family::Curve);

    let cases: [(String, &str); 11] = [
        (CURVE_OK.replace("\"curve\"", "\"torus\""), "line 1, field domain"),
        (CURVE_OK.replace("\"c\"", "\"four-point\""), "line 2, field name: 'four-point' is a built-in"),
        (CURVE_OK.replace("\"0\" = 1", "\"zero\" = 1"), "line 4, field even.\"zero\""),
        // keys are read in sorted order: " 0" (line 5) comes before "0" (line 4)
        (
            CURVE_OK.replace("\"0\" = 1", "\"0\" = 1\n\" 0\" = 0"),
            "line 4, field even.\"0\": offset 0 is already given on line 5",
        ),
        (CURVE_OK.replace("\"0\" = 1", "\"0\" = \"1 + t\""), "line 4, field even.\"0\": unknown variable 't'"),
        (CURVE_OK.replace("\"0\" = 1", "\"0\" = \"1 +\""), "line 4, field even.\"0\""),
        (CURVE_OK.replace("\"0\" = 1", "\"40\" = 1"), "line 4, field even.\"40\": offset 40 is beyond"),
        (CURVE_OK.replace("[odd]\n\"0\" = \"1/2\"\n\"1\" = \"1/2\"\n", ""), "missing section [odd]"),
        (
            CURVE_OK.replace("name = \"c\"", "name = \"c\"\ntopology = \"primal-quad\""),
            "line 3: unknown field `topology`",
        ),
        (
            "domain = \"lattice\"\nname = \"l\"\n[mask-00]\n\"0\" = 1\n".into(),
            "line 4, field mask-00.\"0\": '0' is not an offset",
        ),
        // a default rule in the valence belongs to mesh files
        (
            CURVE_OK.replace("name = \"c\"", "name = \"c\"\n[params.t]\ndefault = \"1/n\""),
            "line 4, field params.t.default: a default in the valence n needs a mesh scheme file",
        ),
    ];
    for (text, want) in cases {
        let e = load_error(&text);
        assert!(e.contains(want), "want '{want}' in: {e}");
    }
    // an irrational lattice weight is named as such: the lattice analysis is exact
    let irrational = "domain = \"lattice\"\nname = \"l\"\naffine = false\n\
                      [mask-00]\n\"0,0\" = \"sqrt(2)\"\n[mask-01]\n\"0,0\" = 1\n[mask-10]\n\"0,0\" = 1\n[mask-11]\n\"0,0\" = 1\n";
    assert!(load_error(irrational).contains("line 5, field mask-00.\"0,0\": the weight has no exact rational value"));
    // parameter overrides are range-checked like a built-in's
    let unified = repo("schemes/curve-unified.toml");
    let e = registry::resolve(unified.to_str().unwrap(), &[("alpha".into(), "3".into())]).err().unwrap().to_string();
    assert!(e.contains("out of range [0, 2]"), "{e}");
}

#[test]
fn the_registry_routes_every_family() {
    assert_eq!(registry::family_of("catmull-clark").unwrap(), Family::Mesh);
    assert_eq!(registry::family_of("khan-mustafa").unwrap(), Family::Lattice);
    assert_eq!(registry::family_of("unified-curve").unwrap(), Family::Curve);
    assert_eq!(registry::family_of(repo("schemes/loop.toml").to_str().unwrap()).unwrap(), Family::Mesh);
    assert_eq!(registry::family_of(repo("schemes/khan-mustafa.toml").to_str().unwrap()).unwrap(), Family::Lattice);
    assert_eq!(registry::family_of(repo("schemes/curve-unified.toml").to_str().unwrap()).unwrap(), Family::Curve);
    assert!(registry::family_of("butterfly").is_err());
    // every name once, across families
    let names = registry::known_names();
    let mut unique = names.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), names.len());
    // a curve scheme has no mesh rules; a lattice file refines oriented quad meshes
    assert!(subdlab::schemes::resolve("four-point", &[]).err().unwrap().to_string().contains("curve scheme"));
    let on_mesh = subdlab::schemes::resolve(repo("schemes/khan-mustafa.toml").to_str().unwrap(), &[]).unwrap();
    assert_eq!(on_mesh.fixed_valence(), Some(4));
    assert!(matches!(registry::resolve("cubic-bspline", &[]).unwrap(), Built::Curve(_)));
}

fn json(args: &[&str]) -> serde_json::Value {
    let out = subdlab(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// (value, algebraic multiplicity) of a JSON spectrum.
fn eigen_list(v: &serde_json::Value) -> Vec<(f64, f64, u64)> {
    v["eigenvalues"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e["re"].as_f64().unwrap(), e["im"].as_f64().unwrap(), e["algebraic_multiplicity"].as_u64().unwrap()))
        .collect()
}

#[test]
fn cli_spectrum_runs_the_files() {
    let km = repo("schemes/khan-mustafa.toml");
    let from_file = json(&["spectrum", km.to_str().unwrap(), "--valence", "4", "--json"]);
    let builtin = json(&["spectrum", "khan-mustafa", "--valence", "4", "--json"]);
    assert_eq!(from_file["scheme"], "khan-mustafa-file");
    assert_eq!(from_file["matrix_size"], builtin["matrix_size"]);
    let (a, b) = (eigen_list(&from_file), eigen_list(&builtin));
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert!((x.0 - y.0).abs() < 1e-12 && (x.1 - y.1).abs() < 1e-12 && x.2 == y.2, "{x:?} vs {y:?}");
    }
    let text = String::from_utf8_lossy(
        &subdlab(&["spectrum", km.to_str().unwrap(), "-n", "4", "--neighbourhood", "minimal"]).stdout,
    )
    .to_string();
    assert!(text.contains("scheme khan-mustafa-file") && text.contains("window: 4×4 rectangle"), "{text}");

    // refinement of a closed lattice mesh through the file (the masks on an
    // oriented quad mesh) gives the built-in's vertices exactly
    let dir = tempfile::tempdir().unwrap();
    let torus = repo("meshes/torus-grid.obj");
    let refine = |scheme: &str, out: &Path| {
        let o =
            subdlab(&["refine", torus.to_str().unwrap(), "--scheme", scheme, "-l", "2", "-o", out.to_str().unwrap()]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        // without the header line, which names the scheme
        std::fs::read_to_string(out).unwrap().lines().skip(1).map(String::from).collect::<Vec<_>>()
    };
    let (a, b) =
        (refine(km.to_str().unwrap(), &dir.path().join("f.obj")), refine("khan-mustafa", &dir.path().join("b.obj")));
    assert!(a.iter().filter(|l| l.starts_with("v ")).count() > 0);
    assert_eq!(a, b);

    // a curve file under `spectrum` gives `subdlab curve`'s analysis
    let unified = repo("schemes/curve-unified.toml");
    let from_file = json(&["spectrum", unified.to_str().unwrap(), "--valence", "2", "--param", "alpha=1/3", "--json"]);
    let builtin = json(&["curve", "unified-curve", "--param", "alpha=1/3", "--json"]);
    assert_eq!(from_file["scheme"], "unified-curve-file");
    assert_eq!(from_file["params"]["alpha"], "1/3");
    // exactly equal in rationals; the floats may differ in the last bit (the
    // file rounds each exact weight once, the built-in computes (α − 1)/16 in
    // floating point)
    assert_eq!(from_file["exact_matrix"], builtin["exact_matrix"]);
    let floats = |v: &serde_json::Value| -> Vec<f64> {
        v["matrix"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|r| r.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
            .collect()
    };
    let (fa, fb) = (floats(&from_file), floats(&builtin));
    assert_eq!(fa.len(), 49);
    assert!(fa.iter().zip(&fb).all(|(x, y)| (x - y).abs() <= 1e-15), "{fa:?} vs {fb:?}");
    assert_eq!(from_file["charpoly"], builtin["charpoly"]);
    let out = subdlab(&["curve", repo("schemes/curve-four-point.toml").to_str().unwrap()]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("curve scheme four-point-file"));

    // one-line errors where a family does not fit the command
    let e = fails(&["spectrum", unified.to_str().unwrap(), "--valence", "4"]);
    assert!(e.contains("a curve vertex has two neighbours"), "{e}");
    fails(&["stencils", "cubic-bspline", "--valence", "2"]);
    let e = fails(&["spectrum", km.to_str().unwrap(), "--valence", "5"]);
    assert!(e.contains("regular quad lattice only (valence 4)"), "{e}");
    fails(&["curve", "khan-mustafa"]);
    let cube = repo("meshes/cube.obj");
    let out = tempfile::tempdir().unwrap();
    let e = fails(&[
        "refine",
        cube.to_str().unwrap(),
        "--scheme",
        "four-point",
        "-l",
        "1",
        "-o",
        out.path().join("x.obj").to_str().unwrap(),
    ]);
    assert!(e.contains("is a curve scheme"), "{e}");
}

#[test]
fn cli_schemes_lists_every_family_and_describes_the_files() {
    let v = json(&["schemes", "--json"]);
    let names: Vec<&str> = v.as_array().unwrap().iter().map(|e| e["name"].as_str().unwrap()).collect();
    for n in ["catmull-clark", "khan-mustafa", "khan-mustafa-cubic", "cubic-bspline", "four-point", "unified-curve"] {
        assert!(names.contains(&n), "{n} not listed");
    }
    let unified = v.as_array().unwrap().iter().find(|e| e["name"] == "unified-curve").unwrap();
    assert_eq!(unified["params"][0]["name"], "alpha");
    let files = [repo("schemes/khan-mustafa.toml"), repo("schemes/curve-unified.toml")];
    let v = json(&["schemes", files[0].to_str().unwrap(), files[1].to_str().unwrap(), "--json"]);
    assert_eq!(v[0]["name"], "khan-mustafa-file");
    assert_eq!(v[0]["topology"], "lattice");
    assert_eq!(v[1]["topology"], "curve");
    assert_eq!(v[1]["params"][0]["default"], "1/2");
}
