//! Non-box refinement of real meshes (section 5 of Huang's paper): initial FCVs
//! at (scaled) barycentres, refinement with the scheme's rules, the
//! four-directional output form, and convergence of every original vertex to
//! the paper's limit position V∞ = (k V_0 + 4 a_k Σ_j FCV_j) / (k (1 + 4 a_k)).

use subdlab::mesh::obj::read_obj_file;
use subdlab::refine::mesh::{add_face_control_vertices, four_directional, refine_mesh};
use subdlab::schemes;

fn a_k(k: usize) -> f64 {
    if k == 3 {
        0.75
    } else {
        let t = 0.5 + 0.25 * (2.0 * std::f64::consts::PI / k as f64).cos();
        0.75 - t * t
    }
}

fn limit_errors(path: &str, scale: f64, levels: usize) -> Vec<f64> {
    let scheme = schemes::build("non-box", &[]).unwrap();
    let (mesh, points) = read_obj_file(std::path::Path::new(path)).unwrap();
    let (m, p) = add_face_control_vertices(&mesh, &points, scale).unwrap();
    let fcv: Vec<usize> = m.face_points.iter().map(|p| p.expect("an FCV on every face")).collect();
    // the paper's limit position of every original vertex
    let limits: Vec<[f64; 3]> = (0..mesh.num_vertices())
        .map(|v| {
            let faces = m.faces_around(v);
            let k = faces.len();
            let a = a_k(k);
            let mut x = [0.0; 3];
            for c in 0..3 {
                let s: f64 = faces.iter().map(|&f| p[fcv[f]][c]).sum();
                x[c] = (k as f64 * p[v][c] + 4.0 * a * s) / (k as f64 * (1.0 + 4.0 * a));
            }
            x
        })
        .collect();
    (1..=levels)
        .map(|l| {
            let (_, q) = refine_mesh(scheme.as_ref(), &m, &p, l).unwrap();
            // original vertices keep their indices (V-vertices come first)
            (0..mesh.num_vertices())
                .map(|v| (0..3).map(|c| (q[v][c] - limits[v][c]).powi(2)).sum::<f64>().sqrt())
                .fold(0.0, f64::max)
        })
        .collect()
}

#[test]
fn original_vertices_converge_to_the_papers_limit_position() {
    for (mesh, scale) in [("meshes/cube.obj", 1.0), ("meshes/cube.obj", 1.5), ("meshes/mixed-quads.obj", 1.0)] {
        let e = limit_errors(mesh, scale, 6);
        assert!(e[5] < 1e-2 * e[0].max(1e-300) || e[5] < 1e-9, "{mesh} x{scale}: {e:?}");
        for w in e.windows(2) {
            assert!(w[1] <= 0.8 * w[0] + 1e-12, "{mesh}: errors must shrink geometrically: {e:?}");
        }
    }
}

#[test]
fn scaled_fcvs_change_the_limit_surface() {
    // the paper's figure 10: 0.5, 1 and 1.5 times the barycentre give different
    // surfaces; at a cube corner the limit moves linearly with the FCV scale
    let scheme = schemes::build("non-box", &[]).unwrap();
    let (mesh, points) = read_obj_file(std::path::Path::new("meshes/cube.obj")).unwrap();
    let corner = |s: f64| {
        let (m, p) = add_face_control_vertices(&mesh, &points, s).unwrap();
        refine_mesh(scheme.as_ref(), &m, &p, 6).unwrap().1[0]
    };
    let (a, b, c) = (corner(0.5), corner(1.0), corner(1.5));
    for k in 0..3 {
        assert!((b[k] - a[k]).abs() > 1e-3);
        assert!(((c[k] - b[k]) - (b[k] - a[k])).abs() < 1e-6, "linear in the FCV scale");
    }
}

#[test]
fn four_directional_form_has_one_triangle_per_face_corner() {
    let scheme = schemes::build("non-box", &[]).unwrap();
    let (mesh, points) = read_obj_file(std::path::Path::new("meshes/mixed-quads.obj")).unwrap();
    let (m, p) = add_face_control_vertices(&mesh, &points, 1.0).unwrap();
    let (r, q) = refine_mesh(scheme.as_ref(), &m, &p, 1).unwrap();
    let corners: usize = r.faces().iter().map(|f| f.len()).sum();
    let (t, tq) = four_directional(&r, q.clone()).unwrap();
    assert_eq!(t.num_faces(), corners);
    assert!(t.faces().iter().all(|f| f.len() == 3));
    assert_eq!(tq, q, "the same points, only the connectivity differs");
    // every FCV of the quad form has valence 4 in the triangulation (section 3.2.1)
    assert!(r.has_face_point_on_every_face());
    for &f in r.face_points.iter().flatten() {
        assert_eq!(t.valence(f), Some(4));
    }
}
