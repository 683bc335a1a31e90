//! Unified sqrt(3) refinement of real meshes with per-vertex α (Lin–Luo,
//! sections 5 and 3): α = 1 vertices are interpolated (eq. 11 with α_q = 1
//! leaves q in place), new face vertices take the mean α of their triangle
//! (eq. 7), and a constant per-vertex α is the uniform scheme.

use std::path::Path;
use std::process::Command;
use subdlab::mesh::obj::read_obj_file;
use subdlab::refine::mesh::refine_mesh;
use subdlab::schemes;

fn octahedron() -> (subdlab::mesh::PolyMesh, Vec<[f64; 3]>) {
    read_obj_file(std::path::Path::new("meshes/octahedron.obj")).unwrap()
}

#[test]
fn vertices_with_alpha_one_are_interpolated() {
    let scheme = schemes::build("unified-sqrt3", &[("alpha".into(), "0".into())]).unwrap();
    let (mut m, p) = octahedron();
    m.vertex_params = Some(vec![1.0, 0.0, 1.0, 0.0, 1.0, 0.0]);
    for levels in 1..=4 {
        let (_, q) = refine_mesh(scheme.as_ref(), &m, &p, levels).unwrap();
        for v in 0..6 {
            let moved = (0..3).map(|k| (q[v][k] - p[v][k]).abs()).fold(0.0, f64::max);
            if v % 2 == 0 {
                assert!(moved < 1e-15, "vertex {v} with α = 1 moved by {moved}");
            } else {
                assert!(moved > 1e-3, "vertex {v} with α = 0 must be smoothed");
            }
        }
    }
}

#[test]
fn constant_per_vertex_alpha_is_the_uniform_scheme() {
    for alpha in ["0", "1/2", "1"] {
        let uniform = schemes::build("unified-sqrt3", &[("alpha".into(), alpha.into())]).unwrap();
        let (m, p) = octahedron();
        let (_, a) = refine_mesh(uniform.as_ref(), &m, &p, 3).unwrap();
        let mut mv = m.clone();
        let value = subdlab::numeric::ParamValue::parse(alpha).unwrap().value;
        mv.vertex_params = Some(vec![value; 6]);
        // a different uniform parameter must be ignored when per-vertex values exist
        let other = schemes::build("unified-sqrt3", &[("alpha".into(), "2".into())]).unwrap();
        let (_, b) = refine_mesh(other.as_ref(), &mv, &p, 3).unwrap();
        for (x, y) in a.iter().zip(&b) {
            for k in 0..3 {
                assert!((x[k] - y[k]).abs() < 1e-14);
            }
        }
    }
}

#[test]
fn new_face_vertices_take_the_mean_alpha() {
    let scheme = schemes::build("unified-sqrt3", &[]).unwrap();
    let (mut m, p) = octahedron();
    let alphas = vec![0.0, 0.25, 0.5, 0.75, 1.0, 2.0];
    m.vertex_params = Some(alphas.clone());
    let refined = scheme.topology().refine(&m).unwrap();
    // one level through the public refinement, then read the propagated values
    let (r, _) = refine_mesh(scheme.as_ref(), &m, &p, 1).unwrap();
    let got = r.vertex_params.unwrap();
    for (v, o) in refined.vertex_origins.iter().enumerate() {
        let want = match *o {
            subdlab::refine::Origin::Vertex(u) => alphas[u],
            subdlab::refine::Origin::Face(f) => m.face(f).iter().map(|&u| alphas[u]).sum::<f64>() / 3.0,
            _ => unreachable!(),
        };
        assert!((got[v] - want).abs() < 1e-15);
    }
}

#[test]
fn vertex_parameter_file_errors_are_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| Command::new(env!("CARGO_BIN_EXE_subdlab")).args(args).output().unwrap();
    let out = dir.path().join("o.obj");
    let short = dir.path().join("short.txt");
    std::fs::write(&short, "1\n0\n").unwrap();
    let bad = dir.path().join("bad.txt");
    std::fs::write(&bad, "1\n0\n1\n0\n1\n7\n").unwrap();
    let good = dir.path().join("good.txt");
    std::fs::write(&good, "# alpha per vertex\n1\n0\n1\n0\n1\n0\n").unwrap();
    for (args, needle) in [
        (vec!["--scheme", "unified-sqrt3", "--vertex-params", short.to_str().unwrap()], "2 values for 6 vertices"),
        (vec!["--scheme", "unified-sqrt3", "--vertex-params", bad.to_str().unwrap()], "out of range"),
        (vec!["--scheme", "loop", "--vertex-params", good.to_str().unwrap()], "no per-vertex parameter"),
    ] {
        let mut full = vec!["refine", "meshes/octahedron.obj", "--levels", "1", "-o", out.to_str().unwrap()];
        full.extend(args);
        let o = run(&full);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.contains(needle) && err.trim_end().lines().count() == 1, "{err}");
        assert!(!out.exists(), "no output on error");
    }
    let full = [
        "refine",
        "meshes/octahedron.obj",
        "--levels",
        "1",
        "-o",
        out.to_str().unwrap(),
        "--scheme",
        "unified-sqrt3",
        "--vertex-params",
        good.to_str().unwrap(),
    ];
    assert!(run(&full).status.success());
}

/// `subdlab refine meshes/octahedron.obj` with per-vertex parameters.
fn refine_octahedron(out: &Path, levels: &str, scheme: &str, params: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_subdlab"))
        .args(["refine", "meshes/octahedron.obj", "--levels", levels, "-o", out.to_str().unwrap()])
        .args(["--scheme", scheme, "--vertex-params", params.to_str().unwrap()])
        .output()
        .unwrap()
}

/// `--vertex-params` with a scheme file: the file's per-vertex parameter and
/// its range come from the file, so the command line gives the built-in's mesh.
#[test]
fn vertex_parameters_with_a_scheme_file_equal_the_builtin() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.txt");
    std::fs::write(&good, "1\n0\n1/2\n0\n1\n0\n").unwrap();
    let mut outputs = Vec::new();
    for scheme in ["unified-sqrt3", "schemes/unified-sqrt3.toml"] {
        let out = dir.path().join(format!("{}.obj", outputs.len()));
        let o = refine_octahedron(&out, "2", scheme, &good);
        assert!(o.status.success(), "{scheme}: {}", String::from_utf8_lossy(&o.stderr));
        let (m, p) = read_obj_file(&out).unwrap();
        outputs.push((m.faces().to_vec(), p));
    }
    assert_eq!(outputs[0].0, outputs[1].0, "same connectivity");
    for (a, b) in outputs[0].1.iter().zip(&outputs[1].1) {
        for k in 0..3 {
            assert!((a[k] - b[k]).abs() < 1e-12, "{a:?} vs {b:?}");
        }
    }
    // the file's range applies: α = 3 is outside [0, 2]
    let bad = dir.path().join("bad.txt");
    std::fs::write(&bad, "1\n0\n3\n0\n1\n0\n").unwrap();
    let o = refine_octahedron(&dir.path().join("x.obj"), "1", "schemes/unified-sqrt3.toml", &bad);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("out of range"));
}
