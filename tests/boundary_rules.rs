//! Boundary, crease and corner rules of Catmull–Clark and Loop (issue 26):
//! Hoppe et al. 1994 / OpenSubdiv's crease rules at infinite sharpness. The
//! expected values are derived here from the cubic B-spline curve alone (its
//! subdivision rules (1/8, 6/8, 1/8) and (1/2, 1/2), and its published limit
//! masks (1, 4, 1)/6 and (−1, 0, 1)/2), never from what the program prints.

use crate::common;
use common::exact::{null_space, q, shifted};

use num_traits::Zero;
use subdlab::mesh::obj::read_obj_file;
use subdlab::mesh::{PolyMesh, Tags, VertexTag};
use subdlab::numeric::Rational;
use subdlab::refine::mesh::refine_mesh;
use subdlab::refine::{step, GatherError, Origin, Step, StepStencil};
use subdlab::schemes::{self, Scheme};
use subdlab::sdc::slots::Host;

fn scheme(name: &str) -> Box<dyn Scheme> {
    schemes::resolve(name, &[]).unwrap()
}

fn repo(rel: &str) -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(rel)
}

type P = [Rational; 3];

/// A w × h grid of quads (vertex (i, j) is j (w + 1) + i), or of triangles
/// (each quad cut along its diagonal), with integer points whose heights are
/// no polynomial of low degree in (i, j).
fn grid(w: usize, h: usize, triangles: bool) -> (PolyMesh, Vec<P>) {
    let id = |i: usize, j: usize| j * (w + 1) + i;
    let mut faces = Vec::new();
    for j in 0..h {
        for i in 0..w {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            if triangles {
                faces.push(vec![a, b, c]);
                faces.push(vec![a, c, d]);
            } else {
                faces.push(vec![a, b, c, d]);
            }
        }
    }
    let mut pts = Vec::new();
    for j in 0..=h {
        for i in 0..=w {
            let z = ((i * i * 3 + j * 7 + i * j) % 5) as i64;
            pts.push([q(2 * i as i64 + (j % 2) as i64, 1), q(2 * j as i64, 1), q(z, 1)]);
        }
    }
    (PolyMesh::new(pts.len(), faces).unwrap(), pts)
}

/// The boundary cycle of `grid(w, h, _)`, counter-clockwise.
fn grid_boundary(w: usize, h: usize) -> Vec<usize> {
    let id = |i: usize, j: usize| j * (w + 1) + i;
    let mut c: Vec<usize> = (0..w).map(|i| id(i, 0)).collect();
    c.extend((0..h).map(|j| id(w, j)));
    c.extend((1..=w).rev().map(|i| id(i, h)));
    c.extend((1..=h).rev().map(|j| id(0, j)));
    c
}

/// One exact refinement step: the refined mesh (with its tags), its points
/// (every stencil must apply), and the new vertices' origins.
fn step_exact(s: &dyn Scheme, mesh: &PolyMesh, pts: &[P]) -> (PolyMesh, Vec<P>, Vec<Origin>) {
    let Step { refined, stencils } = step::<Rational>(s, mesh).unwrap();
    let new = stencils
        .iter()
        .enumerate()
        .map(|(k, st)| {
            let st =
                st.stencil().unwrap_or_else(|| panic!("{}: no stencil for {:?}", s.name(), refined.vertex_origins[k]));
            let mut p = [Rational::zero(), Rational::zero(), Rational::zero()];
            for (v, w) in &st.terms {
                for x in 0..3 {
                    p[x] = p[x].clone() + w.clone() * pts[*v][x].clone();
                }
            }
            p
        })
        .collect();
    (refined.mesh, new, refined.vertex_origins)
}

/// The new id of old vertex `v` and of old edge {a, b}.
fn of_vertex(origins: &[Origin], v: usize) -> usize {
    origins.iter().position(|o| *o == Origin::Vertex(v)).unwrap()
}
fn of_edge(origins: &[Origin], a: usize, b: usize) -> usize {
    origins.iter().position(|o| *o == Origin::Edge(a, b) || *o == Origin::Edge(b, a)).unwrap()
}

/// One step of the closed cubic B-spline curve: (1/8, 6/8, 1/8) at the old
/// points, (1/2, 1/2) between them.
fn bspline_step(poly: &[P]) -> Vec<P> {
    let k = poly.len();
    let mut out = Vec::new();
    for i in 0..k {
        let (a, b, c) = (&poly[(i + k - 1) % k], &poly[i], &poly[(i + 1) % k]);
        out.push(std::array::from_fn(|x| q(1, 8) * a[x].clone() + q(6, 8) * b[x].clone() + q(1, 8) * c[x].clone()));
        out.push(std::array::from_fn(|x| q(1, 2) * (b[x].clone() + c[x].clone())));
    }
    out
}

/// (a) The boundary of a refined open mesh is the cubic B-spline curve of
/// its boundary polygon, exactly, level by level, whatever the interior.
#[test]
fn the_boundary_is_the_cubic_bspline_of_the_boundary_polygon() {
    for (name, triangles) in [("catmull-clark", false), ("loop", true)] {
        let s = scheme(name);
        for lift in [0, 7] {
            let (w, h) = (3, 2);
            let (mut mesh, mut pts) = grid(w, h, triangles);
            mesh.tag_open_edges();
            let mut cycle = grid_boundary(w, h);
            // the interior points moved: the boundary curve must not notice
            for (v, p) in pts.iter_mut().enumerate() {
                if !cycle.contains(&v) {
                    p[2] = p[2].clone() + q(lift * (v as i64 % 3 + 1), 3);
                }
            }
            let mut poly: Vec<P> = cycle.iter().map(|&v| pts[v].clone()).collect();
            for level in 1..=3 {
                let (m, p, origins) = step_exact(s.as_ref(), &mesh, &pts);
                let k = cycle.len();
                cycle = (0..k)
                    .flat_map(|i| [of_vertex(&origins, cycle[i]), of_edge(&origins, cycle[i], cycle[(i + 1) % k])])
                    .collect();
                poly = bspline_step(&poly);
                let got: Vec<P> = cycle.iter().map(|&v| p[v].clone()).collect();
                assert_eq!(got, poly, "{name}, interior lifted by {lift}, level {level}");
                // the refined boundary is tagged, and is the refined mesh's open edges
                for i in 0..cycle.len() {
                    assert!(m.is_sharp(cycle[i], cycle[(i + 1) % cycle.len()]), "{name} level {level}");
                }
                (mesh, pts) = (m, p);
            }
        }
    }
}

/// (b) The crease curve's 3 × 3 matrix at a boundary vertex v (rows and
/// columns: its sharp neighbour a, v, its sharp neighbour b), read off the
/// program's stencils, has the left eigenvectors (1, 4, 1)/6 for 1 and
/// (−1, 0, 1)/2 for 1/2 (OpenSubdiv's crease limit position and tangent
/// masks), exactly; nothing else in the mesh enters the three stencils.
#[test]
fn crease_limit_masks_are_the_left_eigenvectors_of_the_crease_matrix() {
    for (name, triangles) in [("catmull-clark", false), ("loop", true)] {
        let s = scheme(name);
        let (mut mesh, _) = grid(3, 2, triangles);
        mesh.tag_open_edges();
        let v = 1; // (1, 0): on the bottom boundary, neighbours 0 and 2 along it
        let VertexTag::Crease(a, b) = mesh.vertex_tag(v) else { panic!("{name}: vertex 1 is a boundary vertex") };
        assert_eq!([a.min(b), a.max(b)], [0, 2]);
        let Step { refined, stencils } = step::<Rational>(s.as_ref(), &mesh).unwrap();
        let origins = &refined.vertex_origins;
        let rows = [of_edge(origins, a, v), of_vertex(origins, v), of_edge(origins, v, b)];
        let cols = [a, v, b];
        let matrix: Vec<Vec<Rational>> = rows
            .iter()
            .map(|&r| {
                let st = stencils[r].stencil().unwrap();
                for (u, w) in &st.terms {
                    assert!(cols.contains(u) || w.is_zero(), "{name}: the crease stencil reaches vertex {u}");
                }
                cols.iter()
                    .map(|c| st.terms.iter().filter(|(u, _)| u == c).fold(Rational::zero(), |x, (_, w)| x + w.clone()))
                    .collect()
            })
            .collect();
        let left = |l: &[Rational]| -> Vec<Rational> {
            (0..3).map(|j| (0..3).fold(Rational::zero(), |x, i| x + l[i].clone() * matrix[i][j].clone())).collect()
        };
        let position = vec![q(1, 6), q(4, 6), q(1, 6)];
        let tangent = vec![q(-1, 2), q(0, 1), q(1, 2)];
        assert_eq!(left(&position), position, "{name}: (1, 4, 1)/6 S");
        assert_eq!(left(&tangent), tangent.iter().map(|t| t.clone() * q(1, 2)).collect::<Vec<_>>(), "{name}");
        // and they are the only ones: each eigenspace of S^T is one line
        let transposed: Vec<Vec<Rational>> = (0..3).map(|i| (0..3).map(|j| matrix[j][i].clone()).collect()).collect();
        for (lambda, want) in [(q(1, 1), &position), (q(1, 2), &tangent)] {
            let basis = null_space(&shifted(&transposed, &lambda));
            assert_eq!(basis.len(), 1, "{name}: eigenvalue {lambda}");
            let scale = want[2].clone() / basis[0][2].clone();
            let scaled: Vec<Rational> = basis[0].iter().map(|x| x.clone() * scale.clone()).collect();
            assert_eq!(&scaled, want, "{name}: eigenvalue {lambda}");
        }
    }
}

/// (b) in floating point: a boundary vertex of an open mesh refined many
/// levels tends to (p_a + 4 p_v + p_b)/6 of the control points, and
/// 2^L (p_b − p_a)/2 of its neighbours at level L to (p_b − p_a)/2.
#[test]
fn refined_boundary_vertices_reach_the_crease_limit_masks() {
    for (name, triangles, levels) in [("catmull-clark", false, 7), ("loop", true, 6)] {
        let s = scheme(name);
        let (mut mesh, exact) = grid(2, 1, triangles);
        mesh.tag_open_edges();
        let pts: Vec<[f64; 3]> = exact.iter().map(|p| std::array::from_fn(|x| to_f64(&p[x]))).collect();
        let v = 1;
        let (a, b) = (0, 2);
        let (mut m, mut p) = (mesh.clone(), pts.clone());
        let (mut na, mut nb) = (a, b);
        for _ in 0..levels {
            let Step { refined, .. } = step::<f64>(s.as_ref(), &m).unwrap();
            // the neighbours on a's and b's side: the new points of the edges v-a and v-b
            (na, nb) = (of_edge(&refined.vertex_origins, v, na), of_edge(&refined.vertex_origins, v, nb));
            let (m1, p1) = refine_mesh(s.as_ref(), &m, &p, 1).unwrap();
            (m, p) = (m1, p1);
        }
        let scale = 2f64.powi(levels);
        for x in 0..3 {
            let limit = (pts[a][x] + 4.0 * pts[v][x] + pts[b][x]) / 6.0;
            let tangent = (pts[b][x] - pts[a][x]) / 2.0;
            // the curve's third eigenvector, (2, -1, 2) for 1/4 with the left
            // one (1, -2, 1)/6, is what is left of the position after L steps;
            // it has equal ends, so the tangent combination is exact
            let rest = 0.25f64.powi(levels) * (pts[a][x] - 2.0 * pts[v][x] + pts[b][x]) / 6.0;
            assert!((p[v][x] - (limit - rest)).abs() < 1e-9, "{name}: {} vs {limit} - {rest}", p[v][x]);
            let t = scale * (p[nb][x] - p[na][x]) / 2.0;
            assert!((t - tangent).abs() < 1e-9, "{name}: tangent {t} vs {tangent}");
        }
        // and the data does tell (1, 4, 1)/6 from the vertex rule (1, 6, 1)/8
        assert!((0..3).any(|x| (pts[a][x] - 2.0 * pts[v][x] + pts[b][x]).abs() > 1.0));
    }
}

fn to_f64(x: &Rational) -> f64 {
    use num_traits::ToPrimitive;
    x.to_f64().unwrap()
}

/// (c) A corner is interpolated at every level, and stays a corner.
#[test]
fn corners_stay_fixed() {
    let (mut mesh, pts) = read_obj_file(&repo("examples/meshes/quad-frame-hole.obj")).unwrap();
    let corners = mesh.tags.as_ref().unwrap().corners();
    assert_eq!(corners, vec![0, 3, 12, 15], "the file's #corner line, 0-based");
    mesh.tag_open_edges();
    let s = scheme("catmull-clark");
    let (m, p) = refine_mesh(s.as_ref(), &mesh, &pts, 3).unwrap();
    for &c in &corners {
        // the primal split keeps old vertex ids
        assert_eq!(p[c], pts[c], "corner {c}");
        assert_eq!(m.vertex_tag(c), VertexTag::Corner);
    }
    assert_eq!(m.tags.as_ref().unwrap().corners(), corners);
    // an untagged grid corner is a boundary vertex of one face: it moves
    // along the boundary curve, 3/4 of itself and 1/8 of each neighbour
    mesh.tags = Some(Tags::new());
    mesh.tag_open_edges();
    let (_, p) = refine_mesh(s.as_ref(), &mesh, &pts, 1).unwrap();
    let want: [f64; 3] = std::array::from_fn(|x| 0.75 * pts[0][x] + 0.125 * (pts[1][x] + pts[4][x]));
    assert_eq!(p[0], want);
}

/// (d) A dart (one sharp edge ending at a vertex) takes the smooth vertex
/// rule: on the cube, valence 3, v gets 1 − 7/(4n) = 5/12 as without tags;
/// the sharp edge's point is its midpoint; the other edges are smooth.
#[test]
fn a_dart_uses_the_smooth_rule() {
    let (cube, _) = read_obj_file(&repo("meshes/cube.obj")).unwrap();
    let mut tagged = cube.clone();
    let mut tags = Tags::new();
    tags.mark_sharp(0, 1);
    tagged.tags = Some(tags);
    assert_eq!(tagged.vertex_tag(0), VertexTag::Dart);
    let s = scheme("catmull-clark");
    let (plain, darted) =
        (step::<Rational>(s.as_ref(), &cube).unwrap(), step::<Rational>(s.as_ref(), &tagged).unwrap());
    let sorted = |st: &StepStencil<Rational>| {
        let mut t = st.stencil().unwrap().terms.clone();
        t.sort_by_key(|x| x.0);
        t
    };
    for (k, origin) in darted.refined.vertex_origins.iter().enumerate() {
        match *origin {
            Origin::Edge(a, b) if [a.min(b), a.max(b)] == [0, 1] => {
                assert_eq!(sorted(&darted.stencils[k]), vec![(0, q(1, 2)), (1, q(1, 2))]);
            }
            _ => assert_eq!(sorted(&darted.stencils[k]), sorted(&plain.stencils[k]), "{origin:?}"),
        }
    }
    let k = of_vertex(&darted.refined.vertex_origins, 0);
    let centre =
        darted.stencils[k].stencil().unwrap().terms.iter().filter(|t| t.0 == 0).fold(q(0, 1), |x, t| x + t.1.clone());
    assert_eq!(centre, q(5, 12));
    // the refined dart: the two halves of the sharp edge are sharp, the new
    // vertex on it is a crease vertex, the old ends stay darts
    let m = &darted.refined.mesh;
    let e = of_edge(&darted.refined.vertex_origins, 0, 1);
    assert!(m.is_sharp(0, e) && m.is_sharp(e, 1));
    assert_eq!(m.tags.as_ref().unwrap().sharp_edges().len(), 2);
    assert_eq!(m.vertex_tag(0), VertexTag::Dart);
    assert!(matches!(m.vertex_tag(e), VertexTag::Crease(..)));
}

/// (e) An open patch without tags is cut off, as analysis patches are: no
/// rule applies at its rim (`Truncated`), tags or no tag set.
#[test]
fn an_untagged_open_edge_is_a_cut() {
    for tags in [None, Some(Tags::new())] {
        let (mut mesh, _) = grid(2, 2, false);
        mesh.tags = tags.clone();
        let Step { refined, stencils } = step::<f64>(scheme("catmull-clark").as_ref(), &mesh).unwrap();
        for (o, st) in refined.vertex_origins.iter().zip(&stencils) {
            match *o {
                // the centre (1, 1) of the 2 x 2 grid is its only interior vertex
                Origin::Vertex(4) => assert!(st.stencil().is_some()),
                Origin::Vertex(_) => assert_eq!(st.cause(), Some(GatherError::Truncated), "{tags:?} {o:?}"),
                _ => {}
            }
        }
    }
}

/// A mask without boundary rules, asked at a tagged origin, says which
/// rule it lacks (typed), and `refine` names it in one line; a host without
/// boundary/crease rules refuses a tagged mesh.
#[test]
fn missing_boundary_rules_are_named() {
    let (mut mesh, pts) = grid(2, 2, false);
    mesh.tag_open_edges();
    let file = repo("schemes/catmull-clark-edge-rule.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    assert!(!text.contains("[vertex-crease]"), "this test needs a file without boundary rules");
    let s = scheme(file.to_str().unwrap());
    let Step { refined, stencils } = step::<f64>(s.as_ref(), &mesh).unwrap();
    let cause = |o: Origin| stencils[refined.vertex_origins.iter().position(|x| *x == o).unwrap()].cause();
    assert_eq!(cause(Origin::Vertex(1)), Some(GatherError::MissingRule(Host::PrimalQuad, "vertex-crease")));
    assert_eq!(cause(Origin::Vertex(4)), None);
    assert_eq!(cause(Origin::Edge(0, 1)), Some(GatherError::MissingRule(Host::PrimalQuad, "edge-crease")));
    mesh.tags.as_mut().unwrap().mark_corner(0);
    let Step { refined, stencils } = step::<f64>(s.as_ref(), &mesh).unwrap();
    let k = refined.vertex_origins.iter().position(|x| *x == Origin::Vertex(0)).unwrap();
    assert_eq!(stencils[k].cause(), Some(GatherError::MissingRule(Host::PrimalQuad, "vertex-corner")));
    let pts: Vec<[f64; 3]> = pts.iter().map(|p| std::array::from_fn(|x| to_f64(&p[x]))).collect();
    let err = refine_mesh(s.as_ref(), &mesh, &pts, 1).unwrap_err().to_string();
    assert!(
        err.contains("no vertex-corner rule") && err.contains("vertex 1 is a corner") && !err.contains('\n'),
        "{err}"
    );
    for name in ["doo-sabin", "four-three", "sqrt3"] {
        let (mut t, tp) = read_obj_file(&repo("meshes/octahedron.obj")).unwrap();
        let mut tags = Tags::new();
        tags.mark_corner(0);
        t.tags = Some(tags);
        let err = refine_mesh(scheme(name).as_ref(), &t, &tp, 1).unwrap_err().to_string();
        assert!(err.starts_with(name) && err.contains("boundary/crease rules are not available"), "{err}");
    }
}

/// The repository's Catmull–Clark and Loop files weigh the boundary,
/// crease and corner rules as the built-ins do: the same refined meshes and
/// tags on open, creased and cornered meshes.
#[test]
fn scheme_files_refine_tagged_meshes_as_the_built_ins_do() {
    for (files, built, meshes) in [
        (
            vec!["schemes/catmull-clark.toml", "schemes/catmull-clark-polygons.toml"],
            "catmull-clark",
            vec!["creased-cube", "open-cube", "quad-frame-hole"],
        ),
        (vec!["schemes/loop.toml"], "loop", vec!["triangle-disc"]),
    ] {
        for mesh in meshes {
            let (mut m, p) = read_obj_file(&repo(&format!("examples/meshes/{mesh}.obj"))).unwrap();
            m.tag_open_edges();
            let (mb, pb) = refine_mesh(scheme(built).as_ref(), &m, &p, 3).unwrap();
            for file in &files {
                let what = format!("{file} on {mesh}");
                let (mf, pf) = refine_mesh(scheme(repo(file).to_str().unwrap()).as_ref(), &m, &p, 3).unwrap();
                assert_eq!(mf.faces(), mb.faces(), "{what}");
                assert_eq!(mf.tags, mb.tags, "{what}");
                for (x, y) in pf.iter().zip(&pb) {
                    assert!((0..3).all(|k| (x[k] - y[k]).abs() < 1e-12), "{what}: {x:?} vs {y:?}");
                }
            }
        }
    }
}
