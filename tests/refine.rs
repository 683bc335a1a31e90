//! Mesh I/O and `subdlab refine`: counts from the refinement hosts' definitions,
//! positions from the schemes' published formulas (derived by hand below), and
//! limit positions from the closed-form limit stencils.

use crate::common;
#[allow(unused_imports)]
use common::{fails, subdlab};

use std::collections::BTreeSet;
use std::path::PathBuf;

use subdlab::mesh::obj::{parse_obj, read_obj_file, write_obj};
use subdlab::mesh::PolyMesh;
use subdlab::refine::mesh::refine_mesh;
use subdlab::schemes::{self, Scheme};

fn mesh_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("meshes").join(name)
}

fn load(name: &str) -> (PolyMesh, Vec<[f64; 3]>) {
    read_obj_file(&mesh_path(name)).unwrap()
}

fn scheme(name: &str) -> Box<dyn Scheme> {
    schemes::build(name, &[]).unwrap()
}

fn counts(m: &PolyMesh) -> (usize, usize, usize) {
    (m.num_vertices(), m.edges().len(), m.num_faces())
}

fn euler(m: &PolyMesh) -> i64 {
    let (v, e, f) = counts(m);
    v as i64 - e as i64 + f as i64
}

const ALL: [&str; 5] = ["cube.obj", "tetrahedron.obj", "octahedron.obj", "mixed-quads.obj", "mixed-triangles.obj"];
const TRIANGLE_MESHES: [&str; 3] = ["tetrahedron.obj", "octahedron.obj", "mixed-triangles.obj"];

#[test]
fn shipped_meshes_are_closed_spheres_with_the_documented_valences() {
    for name in ALL {
        let (m, p) = load(name);
        assert_eq!(p.len(), m.num_vertices());
        assert_eq!(euler(&m), 2, "{name}: a closed genus-0 surface has V - E + F = 2");
        for (a, b) in m.edges() {
            assert!(m.is_interior_edge(a, b), "{name}: edge {a}-{b} is on the boundary");
        }
    }
    let valences = |name: &str| -> BTreeSet<usize> {
        let (m, _) = load(name);
        (0..m.num_vertices()).map(|v| m.valence(v).unwrap()).collect()
    };
    assert_eq!(valences("cube.obj"), [3].into());
    assert_eq!(valences("tetrahedron.obj"), [3].into());
    assert_eq!(valences("octahedron.obj"), [4].into());
    assert_eq!(valences("mixed-triangles.obj"), [3, 4, 5, 6].into());
    assert_eq!(valences("mixed-quads.obj"), [3, 4, 5, 6].into());
    let (q, _) = load("mixed-quads.obj");
    assert!(q.faces().iter().all(|f| f.len() == 4));
    for name in TRIANGLE_MESHES {
        assert!(load(name).0.faces().iter().all(|f| f.len() == 3), "{name}");
    }
}

/// Counts of one step from the definitions of the refinement hosts:
/// Catmull–Clark adds a point per edge and per face and splits every face into
/// one quad per corner; Loop adds a point per edge and splits every triangle
/// into 4; Doo–Sabin makes one point per face corner and one face per old
/// face, edge and vertex.
#[test]
fn refined_counts_follow_the_topology_of_each_scheme() {
    for name in ALL {
        let (m, p) = load(name);
        let mut cases = vec!["catmull-clark", "doo-sabin"];
        if TRIANGLE_MESHES.contains(&name) {
            cases.push("loop");
        }
        for s in cases {
            let (mut mesh, mut pts) = (m.clone(), p.clone());
            for level in 1..=2 {
                let (v, e, f) = counts(&mesh);
                let corners: usize = mesh.faces().iter().map(|f| f.len()).sum();
                let (next, next_pts) = refine_mesh(scheme(s).as_ref(), &mesh, &pts, 1).unwrap();
                let (v2, _, f2) = counts(&next);
                let want = match s {
                    "catmull-clark" => (v + e + f, corners),
                    "loop" => (v + e, 4 * f),
                    _ => (corners, f + e + v),
                };
                assert_eq!((v2, f2), want, "{name} {s} level {level}");
                assert_eq!(euler(&next), 2, "{name} {s} level {level}: refinement keeps the topology");
                if s == "catmull-clark" {
                    assert!(next.faces().iter().all(|f| f.len() == 4), "{name}: Catmull–Clark makes quads");
                }
                if s == "loop" {
                    assert!(next.faces().iter().all(|f| f.len() == 3), "{name}: Loop makes triangles");
                }
                assert_eq!(next_pts.len(), v2);
                assert!(next_pts.iter().all(|p| p.iter().all(|x| x.is_finite())));
                mesh = next;
                pts = next_pts;
            }
        }
    }
}

/// Loop on the regular tetrahedron (vertices (±1,±1,±1) with an even number of
/// minus signs, centroid 0). Valence 3: β = (5/8 − (3/8 + cos(2π/3)/4)²)/3 =
/// (5/8 − 1/16)/3 = 3/16. The three neighbours of v sum to −v, so the vertex
/// point is (1 − 3β)v + β(−v) = (1 − 4β)v = v/4. The apexes c, d of edge ab
/// are the other two vertices, c + d = −(a + b), so the edge point is
/// 3/8(a + b) − 1/8(a + b) = (a + b)/4. All these are dyadic: exact in f64.
#[test]
fn loop_on_the_tetrahedron_matches_the_hand_computed_step_and_keeps_the_centroid() {
    let (m, p) = load("tetrahedron.obj");
    let (r, q) = refine_mesh(scheme("loop").as_ref(), &m, &p, 1).unwrap();
    for v in 0..4 {
        assert_eq!(q[v], p[v].map(|x| x / 4.0), "vertex point of {v}");
    }
    let mut edge_points: Vec<[f64; 3]> = q[4..].to_vec();
    let mut want: Vec<[f64; 3]> = Vec::new();
    for a in 0..4 {
        for b in a + 1..4 {
            want.push([0, 1, 2].map(|k| (p[a][k] + p[b][k]) / 4.0));
        }
    }
    let key = |x: &[f64; 3]| x.map(|c| (c * 64.0) as i64);
    edge_points.sort_by_key(key);
    want.sort_by_key(key);
    assert_eq!(edge_points, want);
    assert_eq!(r.num_vertices(), 10);
    // by symmetry (every symmetry of the tetrahedron permutes the refined
    // vertices) and affine invariance, the centroid stays at the origin
    let (_, q3) = refine_mesh(scheme("loop").as_ref(), &m, &p, 4).unwrap();
    let n = q3.len() as f64;
    for k in 0..3 {
        let c: f64 = q3.iter().map(|x| x[k]).sum::<f64>() / n;
        assert!(c.abs() < 1e-14, "centroid coordinate {k} = {c}");
    }
}

/// Catmull–Clark on the cube [−1,1]³: at v = (1,1,1) (valence 3) the face
/// points average to (1/3,1/3,1/3), the edge midpoints (1,1,0),(1,0,1),(0,1,1)
/// average to (2/3,2/3,2/3), so v' = (Q + 2R + 0·v)/3 = (5/9)(1,1,1); the edge
/// point of (1,1,1)-(1,1,−1) is ((1,1,1) + (1,1,−1) + (1,0,0) + (0,1,0))/4 =
/// (3/4, 3/4, 0); face points are the face centres.
#[test]
fn catmull_clark_on_the_cube_matches_the_hand_computed_step() {
    let (m, p) = load("cube.obj");
    let (r, q) = refine_mesh(scheme("catmull-clark").as_ref(), &m, &p, 1).unwrap();
    for v in 0..8 {
        for k in 0..3 {
            assert!((q[v][k] - p[v][k] * 5.0 / 9.0).abs() < 1e-15);
        }
    }
    let has = |x: [f64; 3]| q.iter().any(|y| (0..3).all(|k| (y[k] - x[k]).abs() < 1e-15));
    assert!(has([0.75, 0.75, 0.0]) && has([-0.75, 0.0, 0.75]) && has([0.0, -0.75, -0.75]));
    for c in [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]] {
        assert!(has(c), "face centre {c:?}");
    }
    assert_eq!(r.num_vertices(), 26);
}

/// Closed-form limit position of vertex v: Catmull–Clark (all-quad ring)
/// n/(n+5) on v, 4/(n(n+5)) on each edge neighbour, 1/(n(n+5)) on each
/// diagonal neighbour; Loop 1 − nχ on v and χ = 1/(n + 3/(8β)) on each
/// neighbour, β Loop's weight.
fn closed_form_limit(name: &str, m: &PolyMesh, p: &[[f64; 3]], v: usize) -> [f64; 3] {
    let fan = m.vertex_fan(v).unwrap();
    let n = fan.len() as f64;
    let mut out = [0.0; 3];
    let mut add = |u: usize, w: f64| (0..3).for_each(|k| out[k] += w * p[u][k]);
    match name {
        "catmull-clark" => {
            add(v, n / (n + 5.0));
            for f in &fan {
                assert_eq!(f.len(), 4);
                add(f[1], 4.0 / (n * (n + 5.0)));
                add(f[2], 1.0 / (n * (n + 5.0)));
            }
        }
        "loop" => {
            let c = (2.0 * std::f64::consts::PI / n).cos();
            let beta = (5.0 / 8.0 - (3.0 / 8.0 + c / 4.0).powi(2)) / n;
            let chi = 1.0 / (n + 3.0 / (8.0 * beta));
            add(v, 1.0 - n * chi);
            for f in &fan {
                add(f[1], chi);
            }
        }
        _ => unreachable!(),
    }
    out
}

/// Refining many times moves every original vertex to its limit position. The
/// refined vertex that replaces old vertex v keeps number v (primal splits
/// number the vertex points first). The centre converges with the largest
/// eigenvalue of Fourier block 0 other than 1, below 1/2 for these schemes and
/// valences, so the distance must at least halve per level.
#[test]
fn repeated_refinement_converges_to_the_closed_form_limit_stencil() {
    for (s, name, levels) in [
        ("catmull-clark", "mixed-quads.obj", 6),
        ("catmull-clark", "cube.obj", 7),
        ("loop", "mixed-triangles.obj", 7),
        ("loop", "octahedron.obj", 7),
    ] {
        let (m, p) = load(name);
        let limits: Vec<[f64; 3]> = (0..m.num_vertices()).map(|v| closed_form_limit(s, &m, &p, v)).collect();
        let dist = |q: &[[f64; 3]]| -> f64 {
            limits
                .iter()
                .enumerate()
                .map(|(v, l)| (0..3).map(|k| (q[v][k] - l[k]).powi(2)).sum::<f64>().sqrt())
                .fold(0.0, f64::max)
        };
        let (mut mesh, mut pts) = (m.clone(), p.clone());
        let mut errors = vec![dist(&pts)];
        for _ in 0..levels {
            let (a, b) = refine_mesh(scheme(s).as_ref(), &mesh, &pts, 1).unwrap();
            mesh = a;
            pts = b;
            errors.push(dist(&pts));
        }
        for w in errors[1..].windows(2) {
            assert!(w[1] <= 0.5 * w[0], "{s} on {name}: errors {errors:?} do not halve per level");
        }
        // the meshes span about 2 units: the last level is within 1e-3 of the limit
        assert!(*errors.last().unwrap() < 1e-3, "{s} on {name}: errors {errors:?}");
    }
}

#[test]
fn obj_round_trip_is_exact() {
    for name in ALL {
        let (m, p) = load(name);
        let (r, q) = refine_mesh(scheme("catmull-clark").as_ref(), &m, &p, 2).unwrap();
        let text = write_obj(&r, &q, "round trip\nsecond header line");
        let (r2, q2) = parse_obj(&text).unwrap();
        assert_eq!(r2.faces(), r.faces());
        assert_eq!(q2, q, "{name}: coordinates must read back bit for bit");
    }
}

#[test]
fn obj_reader_accepts_the_usual_face_forms_and_ignores_other_statements() {
    let plain = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
    let fancy = "# a comment\r\nmtllib x.mtl\r\no thing\r\nv 0 0 0 1\r\nv 1 0 0\r\nvt 0 0\r\nvn 0 0 1\r\nv 0 1 0 0.5 0.5 0.5\r\n\
                 v 0 0 1 # trailing comment\r\ng group\r\ns 1\r\nusemtl m\r\nf 1/1/1 3/1/1 2/1/1\r\nf 1//1 2//1 4//1\r\n\
                 f -3/1 -2/1 -1/1\r\nl 1 2\r\nf 3 1 -1\r\n";
    let (a, pa) = parse_obj(plain).unwrap();
    let (b, pb) = parse_obj(fancy).unwrap();
    assert_eq!(a.faces(), b.faces());
    assert_eq!(pa, pb);
}

#[test]
fn malformed_obj_gives_one_line_errors_naming_the_line() {
    let tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
    let faces = "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
    let cases: Vec<(String, &str, &str)> = vec![
        (format!("v 1 2\n{faces}"), "line 1", "3 coordinates"),
        (format!("{tet}v 1 x 3\n{faces}"), "line 5", "not a number"),
        (format!("v nan 0 0\n{tet}{faces}"), "line 1", "not finite"),
        (format!("v inf 0 0\n{tet}{faces}"), "line 1", "not finite"),
        (format!("v 1e400 0 0\n{tet}{faces}"), "line 1", "not finite"),
        (format!("{tet}f 1 2 9\n"), "line 5", "only 4 vertices"),
        (format!("{tet}f 1 2 4000000000\n"), "line 5", "out of range"),
        (format!("{tet}f 1 2 99999999999999999999999\n"), "line 5", "not a vertex reference"),
        (format!("{tet}f 0 1 2\n"), "line 5", "index 0"),
        (format!("{tet}f -5 -1 -2\n"), "line 5", "before the first vertex"),
        (format!("{tet}f 1 2\n"), "line 5", "at least 3"),
        (format!("{tet}f 1 2 2\n"), "line 5", "twice"),
        (format!("{tet}f 1/x 2 3\n"), "line 5", "not a vertex reference"),
        // the second face repeats the direction 1->2: inconsistent orientation
        (format!("{tet}f 1 2 3\nf 1 2 4\n"), "line 6", "same direction"),
        // three triangles on the edge 1-2: non-manifold edge
        (format!("{tet}v 1 1 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"), "line 8", "same direction"),
        (String::new(), "", "empty mesh"),
        ("# nothing here\n\n".to_string(), "", "empty mesh"),
        (tet.to_string(), "", "no faces"),
    ];
    for (text, line, what) in cases {
        let err = parse_obj(&text).expect_err(&format!("should fail: {text:?}")).to_string();
        assert!(!err.contains('\n'), "one line: {err:?}");
        assert!(err.contains(line) && err.contains(what), "{text:?}: got {err:?}, want '{line}' and '{what}'");
    }
}

/// Two tetrahedra sharing one vertex: every edge has two faces, but the shared
/// vertex has two separate fans; rules that walk its one-ring would see half.
#[test]
fn a_vertex_shared_by_two_closed_surfaces_is_rejected() {
    let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n");
    text += "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
    text += "f 1 6 5\nf 1 5 7\nf 5 6 7\nf 6 1 7\n";
    let err = parse_obj(&text).unwrap_err().to_string();
    assert!(err.contains("line 1") && err.contains("vertex 1") && err.contains("non-manifold"), "{err}");
}

#[test]
fn invalid_utf8_and_missing_files_are_reported() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.obj");
    std::fs::write(&path, b"v 0 0 0\nv 1 0 \xff 0\n").unwrap();
    let err = read_obj_file(&path).unwrap_err().to_string();
    assert!(err.contains("line 2") && err.contains("UTF-8"), "{err}");
    let err = read_obj_file(&dir.path().join("missing.obj")).unwrap_err().to_string();
    assert!(err.contains("cannot read"), "{err}");
}

fn open_cube() -> (PolyMesh, Vec<[f64; 3]>) {
    let text = std::fs::read_to_string(mesh_path("cube.obj")).unwrap();
    let last_face = text.lines().rfind(|l| l.starts_with("f ")).unwrap().to_string();
    parse_obj(&text.replace(&last_face, "")).unwrap()
}

#[test]
fn refining_an_open_or_wrongly_typed_mesh_is_a_clear_error() {
    let (m, p) = open_cube();
    for s in ["catmull-clark", "doo-sabin", "loop"] {
        let err = refine_mesh(scheme(s).as_ref(), &m, &p, 1).unwrap_err().to_string();
        assert!(err.contains("boundary") && err.starts_with(s) && !err.contains('\n'), "{s}: {err}");
    }
    let (c, q) = load("cube.obj");
    let err = refine_mesh(scheme("loop").as_ref(), &c, &q, 1).unwrap_err().to_string();
    assert!(err.contains("triangle mesh"), "{err}");
    let err = refine_mesh(scheme("catmull-clark").as_ref(), &c, &q, 0).unwrap_err();
    assert!(matches!(err, subdlab::error::Error::Input(_)), "{err:?}");
    let err = err.to_string();
    assert!(err.contains("between 1 and"), "{err}");
    let err = refine_mesh(scheme("catmull-clark").as_ref(), &c, &q, 13).unwrap_err().to_string();
    assert!(err.contains("between 1 and"), "{err}");
    // 6·4^L faces: level 11 is far beyond the output limit; refused, not attempted
    let err = refine_mesh(scheme("catmull-clark").as_ref(), &c, &q, 11).unwrap_err().to_string();
    assert!(err.contains("fewer levels"), "{err}");
    // a vertex used by no face has no rule to apply
    let (t, tp) =
        parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 5 5\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n").unwrap();
    let err = refine_mesh(scheme("loop").as_ref(), &t, &tp, 1).unwrap_err().to_string();
    assert!(err.contains("vertex 5 is not used"), "{err}");
}

#[test]
fn cli_refine_writes_a_parseable_obj() {
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("cube2.obj");
    let cube = mesh_path("cube.obj");
    let out = subdlab(&[
        "refine",
        cube.to_str().unwrap(),
        "--scheme",
        "catmull-clark",
        "--levels",
        "2",
        "-o",
        out_path.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let (m, p) = read_obj_file(&out_path).unwrap();
    // level 1: V = 8 + 12 + 6 = 26, E = 48, F = 24; level 2: V = 26 + 48 + 24, F = 4·24
    assert_eq!((m.num_vertices(), m.num_faces()), (98, 96));
    assert_eq!(p.len(), 98);
    assert_eq!(euler(&m), 2);
    // the same as refining in the library
    let (c, q) = load("cube.obj");
    let (_, want) = refine_mesh(scheme("catmull-clark").as_ref(), &c, &q, 2).unwrap();
    assert_eq!(p, want);
}

#[test]
fn cli_refine_errors_are_one_line_and_leave_no_output() {
    let dir = tempfile::tempdir().unwrap();
    let open = dir.path().join("open.obj");
    let (m, p) = open_cube();
    std::fs::write(&open, write_obj(&m, &p, "open cube")).unwrap();
    let out_path = dir.path().join("out.obj");
    let o = out_path.to_str().unwrap();
    let cube = mesh_path("cube.obj");
    let c = cube.to_str().unwrap();
    // (catmull-clark and loop have boundary rules; doo-sabin's host has none)
    let err = fails(&["refine", open.to_str().unwrap(), "--scheme", "doo-sabin", "--levels", "1", "-o", o]);
    assert!(err.contains("boundary"), "{err}");
    for levels in ["0", "13", "-1", "two"] {
        fails(&["refine", c, "--scheme", "catmull-clark", "--levels", levels, "-o", o]);
    }
    let err = fails(&["refine", c, "--scheme", "loop", "--levels", "1", "-o", o]);
    assert!(err.contains("triangle"), "{err}");
    let err = fails(&["refine", c, "--scheme", "nope", "--levels", "1", "-o", o]);
    assert!(err.contains("unknown scheme"), "{err}");
    fails(&["refine", c, "--scheme", "catmull-clark", "--levels", "1", "--param", "x=1", "-o", o]);
    let err = fails(&["refine", "/nonexistent/x.obj", "--scheme", "loop", "--levels", "1", "-o", o]);
    assert!(err.contains("cannot read"), "{err}");
    fails(&["refine", c, "--scheme", "catmull-clark", "--levels", "1"]);
    fails(&["refine", c, "--scheme", "catmull-clark", "--levels", "1", "-o", "/nonexistent-dir/out.obj"]);
    assert!(!out_path.exists(), "no output file on failure");
}

/// The documented caps stop hostile sizes before the mesh is built.
#[test]
fn size_caps_are_enforced_with_the_offending_line() {
    use subdlab::mesh::obj::{MAX_CORNERS, MAX_FACES, MAX_VERTICES};
    let text = "v 0 0 0\n".repeat(MAX_VERTICES + 1);
    let err = parse_obj(&text).unwrap_err().to_string();
    assert!(err.contains(&format!("line {}", MAX_VERTICES + 1)) && err.contains("maximum"), "{err}");
    let text = format!("v 0 0 0\nv 1 0 0\nv 0 1 0\n{}", "f 1 2 3\n".repeat(MAX_FACES + 1));
    let err = parse_obj(&text).unwrap_err().to_string();
    assert!(err.contains(&format!("line {}", MAX_FACES + 4)) && err.contains("maximum"), "{err}");
    let text = format!("v 0 0 0\nf{}\n", " 1".repeat(MAX_CORNERS + 1));
    let err = parse_obj(&text).unwrap_err().to_string();
    assert!(err.contains("line 2") && err.contains("corners"), "{err}");
}
