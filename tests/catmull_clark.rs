//! Catmull–Clark against closed forms from the literature:
//! - block m ≠ 0 of the 2n+1 matrix: λ = (5 + c ± sqrt((c+1)(c+9)))/16, c = cos(2πm/n)
//!   (Doo–Sabin 1978, Ball–Storry 1988; the subdominant λ1 is the m = 1 "+" root);
//! - block 0: the 3×3 matrix of the vertex/edge/face rules averaged over sectors;
//! - limit stencil n/(n+5), 4/(n(n+5)) per edge neighbour, 1/(n(n+5)) per face
//!   neighbour (Halstead, Kass, DeRose 1993);
//! - tangent stencils spanned by A_n cos(2πi/n) e_i + (cos(2πi/n) + cos(2π(i+1)/n)) f_i
//!   and the sine analogue, A_n = 1 + cos(2π/n) + cos(π/n) sqrt(2(9 + cos(2π/n)));
//! - valence 4: the tensor product of the cubic B-spline's {1, 1/2, 1/4, 1/8, 1/8}.

use crate::common;
use approx::assert_abs_diff_eq;
use common::*;
use subdlab::neighbourhood::{NeighbourhoodKind, VertexKind};
use subdlab::spectrum::stencils::{limit_stencil, tangent_stencils};

fn block0_closed_form(n: f64) -> Vec<f64> {
    // v' = (1 - 7/(4n)) v + 3/(2n) ê + 1/(4n) f̂ ; ê' = (6v + 8ê + 2f̂)/16 ; f̂' = (v + 2ê + f̂)/4
    let m =
        [[1.0 - 7.0 / (4.0 * n), 3.0 / (2.0 * n), 1.0 / (4.0 * n)], [6.0 / 16.0, 0.5, 2.0 / 16.0], [0.25, 0.5, 0.25]];
    let trace = m[0][0] + m[1][1] + m[2][2];
    let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    // 1 is an eigenvalue (rows sum to 1): the others solve x^2 - (trace-1) x + det = 0
    let (s, p) = (trace - 1.0, det);
    let disc = (s * s - 4.0 * p).sqrt();
    vec![1.0, (s + disc) / 2.0, (s - disc) / 2.0]
}

#[test]
fn minimal_spectrum_matches_closed_forms_for_valences_3_to_50() {
    for n in 3..=50 {
        let a = run("catmull-clark", n, NeighbourhoodKind::Minimal, None, false);
        assert_eq!(a.spectrum.matrix_size, 2 * n + 1, "minimal invariant size at n = {n}");
        let mut want = block0_closed_form(n as f64);
        for m in 1..n {
            let c = cos2pi(m, n);
            let r = ((c + 1.0) * (c + 9.0)).sqrt();
            want.push((5.0 + c + r) / 16.0);
            want.push((5.0 + c - r) / 16.0);
        }
        assert_same_multiset(real_spectrum(&a), want, 1e-10, &format!("CC n={n}"));
        let c = cos2pi(1, n);
        let l1 = (5.0 + c + ((c + 1.0) * (c + 9.0)).sqrt()) / 16.0;
        let stam = (5.0 + c + (std::f64::consts::PI / n as f64).cos() * (2.0 * (9.0 + c)).sqrt()) / 16.0;
        assert_abs_diff_eq!(l1, stam, epsilon = 1e-14);
        assert_abs_diff_eq!(a.spectrum.verdict.subdominant.unwrap(), stam, epsilon = 1e-10);
        assert!(a.spectrum.verdict.c1_spectral, "CC passes the spectral test at n = {n}");
        let mut blocks = a.spectrum.verdict.subdominant_blocks.clone();
        blocks.dedup();
        assert_eq!(blocks, vec![1, n - 1], "subdominant pair from Fourier blocks 1 and n-1");
    }
}

#[test]
fn analysis_neighbourhood_is_the_two_ring_and_keeps_the_leading_spectrum() {
    for n in 3..=50 {
        let a = run("catmull-clark", n, NeighbourhoodKind::Analysis, None, false);
        assert_eq!(a.spectrum.matrix_size, 6 * n + 1, "analysis size at n = {n}");
        assert_eq!(a.spectrum.minimal_size, 2 * n + 1);
        let c = cos2pi(1, n);
        let l1 = (5.0 + c + ((c + 1.0) * (c + 9.0)).sqrt()) / 16.0;
        assert_abs_diff_eq!(a.spectrum.eigenvalues[1].re, l1, epsilon = 1e-10);
        assert_eq!(a.spectrum.eigenvalues[1].algebraic_multiplicity, 2);
        // the outer ring only adds 1/8, 1/16, 1/32, 1/64 (powers of the regular B-spline rules)
        let minimal = run("catmull-clark", n, NeighbourhoodKind::Minimal, None, false);
        let mut extra = real_spectrum(&a);
        for x in real_spectrum(&minimal) {
            let k = extra.iter().position(|y| (y - x).abs() < 1e-9).expect("minimal spectrum is contained");
            extra.remove(k);
        }
        for x in extra {
            assert!(
                [0.125, 0.0625, 0.03125, 0.015625].iter().any(|p| (x - p).abs() < 1e-9),
                "extra eigenvalue {x} at n = {n}"
            );
        }
    }
}

#[test]
fn regular_valence_is_the_bicubic_tensor_product() {
    let a = run("catmull-clark", 4, NeighbourhoodKind::Analysis, None, true);
    let cubic = [1.0, 0.5, 0.25, 0.125, 0.125];
    assert_same_multiset(real_spectrum(&a), products(&cubic, &cubic), 1e-12, "CC n=4");
    // exact path proves it: every root rational, multiplicities as above
    let x = a.spectrum.exact_analysis.as_ref().unwrap();
    assert_eq!(x.remaining_degree, 0);
    assert!(x.agrees_with_float);
    let mult = |v: &str| x.rational_roots.iter().find(|r| r.value == v).unwrap().algebraic_multiplicity;
    assert_eq!(
        (mult("1"), mult("1/2"), mult("1/4"), mult("1/8"), mult("1/16"), mult("1/32"), mult("1/64")),
        (1, 2, 3, 6, 5, 4, 4)
    );
}

#[test]
fn limit_and_tangent_stencils_match_halstead_kass_derose() {
    for n in 3..=50 {
        let a = run("catmull-clark", n, NeighbourhoodKind::Analysis, None, false);
        let l = limit_stencil(&a.spectrum).unwrap();
        let nf = n as f64;
        let mut cos_form = vec![0.0; l.len()];
        let mut sin_form = vec![0.0; l.len()];
        let an = 1.0 + cos2pi(1, n) + (std::f64::consts::PI / nf).cos() * (2.0 * (9.0 + cos2pi(1, n))).sqrt();
        for (k, lab) in a.spectrum.labels.iter().enumerate() {
            let want = match (lab.kind, lab.ring) {
                (VertexKind::Centre, _) => nf / (nf + 5.0),
                (VertexKind::Edge, 1) => 4.0 / (nf * (nf + 5.0)),
                (VertexKind::Face, 1) => 1.0 / (nf * (nf + 5.0)),
                _ => 0.0,
            };
            assert!((l[k] - want).abs() < 1e-12, "limit weight of {} at n = {n}: {} vs {want}", lab.name, l[k]);
            let i = lab.sector;
            match (lab.kind, lab.ring) {
                (VertexKind::Edge, 1) => {
                    cos_form[k] = an * cos2pi(i, n);
                    sin_form[k] = an * sin2pi(i, n);
                }
                (VertexKind::Face, 1) => {
                    cos_form[k] = cos2pi(i, n) + cos2pi(i + 1, n);
                    sin_form[k] = sin2pi(i, n) + sin2pi(i + 1, n);
                }
                _ => {}
            }
        }
        let t = tangent_stencils(&a.spectrum).unwrap();
        assert_eq!(t.len(), 2);
        for v in &t {
            assert!(
                in_span(&[cos_form.clone(), sin_form.clone()], v),
                "tangent stencil off the closed form at n = {n}"
            );
        }
        assert!(in_span(&t, &cos_form) && in_span(&t, &sin_form), "tangent stencils span the closed form at n = {n}");
    }
}

/// A closed mesh of a pentagon, quads and triangles: a pentagonal prism
/// (bottom 0..4, top ring 5..9) with a pyramid roof (apex 10). Valences:
/// 3 at the bottom (pentagon, two quads), 4 on the top ring (two quads, two
/// triangles), 5 at the apex (triangles only).
fn pentagonal_house() -> Vec<Vec<usize>> {
    let mut faces = vec![vec![4, 3, 2, 1, 0]];
    for i in 0..5 {
        let k = (i + 1) % 5;
        faces.push(vec![i, k, 5 + k, 5 + i]);
        faces.push(vec![5 + i, 5 + k, 10]);
    }
    faces
}

type Row = std::collections::BTreeMap<usize, subdlab::numeric::Rational>;

fn q(p: i64, d: i64) -> subdlab::numeric::Rational {
    subdlab::numeric::Rational::new(p.into(), d.into())
}

fn add(row: &mut Row, v: usize, w: subdlab::numeric::Rational) {
    *row.entry(v).or_insert_with(|| q(0, 1)) += w;
}

fn add_row(row: &mut Row, other: &Row, scale: &subdlab::numeric::Rational) {
    for (&v, w) in other {
        add(row, v, w * scale);
    }
}

/// Catmull & Clark's rules (1978) written out on a raw face list, without
/// the mesh type or the scheme's code: face point = centroid; edge point =
/// (v + w + F1 + F2)/4 with F1, F2 the face points on both sides; vertex
/// point = (Q + 2R + (n − 3) S)/n with Q the mean of the face points around
/// S and R the mean of the midpoints of the n edges at S. `bump` adds 1/100
/// to the weight of the origin's first old vertex in one rule (a negative
/// control).
fn closed_form(faces: &[Vec<usize>], origin: subdlab::refine::Origin, bump: bool) -> Row {
    use subdlab::refine::Origin;
    let face_point = |f: &[usize]| {
        let mut r = Row::new();
        f.iter().for_each(|&c| add(&mut r, c, q(1, f.len() as i64)));
        r
    };
    // the face holding the directed edge a -> b
    let holding = |a: usize, b: usize| {
        faces.iter().find(|f| (0..f.len()).any(|k| f[k] == a && f[(k + 1) % f.len()] == b)).unwrap()
    };
    let mut row = match origin {
        Origin::Face(f) => face_point(&faces[f]),
        Origin::Edge(a, b) => {
            let mut r = Row::new();
            add(&mut r, a, q(1, 4));
            add(&mut r, b, q(1, 4));
            add_row(&mut r, &face_point(holding(a, b)), &q(1, 4));
            add_row(&mut r, &face_point(holding(b, a)), &q(1, 4));
            r
        }
        Origin::Vertex(s) => {
            let around: Vec<&Vec<usize>> = faces.iter().filter(|f| f.contains(&s)).collect();
            // the neighbours: the corner after s in each face around s
            let neighbours: Vec<usize> =
                around.iter().map(|f| f[(f.iter().position(|&c| c == s).unwrap() + 1) % f.len()]).collect();
            let n = neighbours.len() as i64;
            let mut qm = Row::new();
            around.iter().for_each(|f| add_row(&mut qm, &face_point(f), &q(1, n)));
            let mut rm = Row::new();
            for &w in &neighbours {
                add(&mut rm, s, q(1, 2 * n));
                add(&mut rm, w, q(1, 2 * n));
            }
            let mut r = Row::new();
            add_row(&mut r, &qm, &q(1, n));
            add_row(&mut r, &rm, &q(2, n));
            add(&mut r, s, q(n - 3, n));
            r
        }
        Origin::Corner { .. } => panic!("Catmull–Clark makes no corner points"),
    };
    if bump {
        let first = *row.keys().next().unwrap();
        add(&mut row, first, q(1, 100));
    }
    row.retain(|_, w| *w != q(0, 1));
    row
}

/// One exact refinement step of `scheme` on the mesh against the closed
/// form: every new vertex's stencil (a row of the step's subdivision matrix)
/// equal entry by entry; `bump` perturbs the closed form at the first origin
/// of that kind. `Err` names the first origin that differs.
fn step_against_closed_form(
    scheme: &dyn subdlab::sdc::Scheme,
    faces: &[Vec<usize>],
    bump: Option<fn(&subdlab::refine::Origin) -> bool>,
) -> Result<usize, String> {
    use subdlab::mesh::PolyMesh;
    use subdlab::numeric::Rational;
    let mesh = PolyMesh::new(1 + faces.iter().flatten().max().unwrap(), faces.to_vec()).unwrap();
    let step = subdlab::refine::step::<Rational>(scheme, &mesh).unwrap();
    let mut bumped = false;
    for (origin, stencil) in step.refined.vertex_origins.iter().zip(&step.stencils) {
        if let subdlab::refine::Origin::Face(f) = origin {
            assert_eq!(mesh.face(*f), &faces[*f][..], "faces keep their order");
        }
        let bump_here = !bumped && bump.is_some_and(|b| b(origin));
        bumped |= bump_here;
        let want = closed_form(faces, *origin, bump_here);
        let got: Row = stencil
            .stencil()
            .ok_or(format!("{origin:?}: no stencil ({:?})", stencil.cause()))?
            .terms
            .iter()
            .cloned()
            .collect();
        if got != want {
            return Err(format!("{origin:?}: {got:?} against the closed form {want:?}"));
        }
    }
    Ok(step.stencils.len())
}

/// Catmull–Clark on a mesh with a pentagon, quads and triangles (valences
/// 3, 4 and 5; fans mixing a pentagon with quads, and quads with
/// triangles): every row of one exact refinement step is the closed-form
/// rule, computed independently above.
#[test]
fn non_quad_faces_follow_the_closed_form_rules_exactly() {
    use subdlab::refine::Origin;
    let faces = pentagonal_house();
    let cc = scheme("catmull-clark");
    // 11 vertices, 20 edges, 11 faces
    assert_eq!(step_against_closed_form(cc.as_ref(), &faces, None), Ok(42));
    // the same on the cube (quads only), and on the triangles of an octahedron
    let cube = vec![
        vec![0, 3, 2, 1],
        vec![4, 5, 6, 7],
        vec![0, 1, 5, 4],
        vec![1, 2, 6, 5],
        vec![2, 3, 7, 6],
        vec![3, 0, 4, 7],
    ];
    assert_eq!(step_against_closed_form(cc.as_ref(), &cube, None), Ok(26));
    let octahedron = vec![
        vec![0, 2, 4],
        vec![2, 1, 4],
        vec![1, 3, 4],
        vec![3, 0, 4],
        vec![2, 0, 5],
        vec![1, 2, 5],
        vec![3, 1, 5],
        vec![0, 3, 5],
    ];
    assert_eq!(step_against_closed_form(cc.as_ref(), &octahedron, None), Ok(26));
    // negative controls: a closed form off by 1/100 in one weight of each
    // rule is told apart (the apex's vertex rule, a pentagon's face point, an
    // edge between a pentagon and a quad)
    let bumps: [fn(&Origin) -> bool; 3] = [
        |o| *o == Origin::Vertex(10),
        |o| *o == Origin::Face(0),
        |o| matches!(*o, Origin::Edge(a, b) if a < 5 && b < 5),
    ];
    for bump in bumps {
        let e = step_against_closed_form(cc.as_ref(), &faces, Some(bump)).unwrap_err();
        assert!(e.contains("against the closed form"), "{e}");
    }
    // and a scheme that weighs the faces around a vertex as if they were
    // quads (1/(4n²) on every corner where 1/(m n²) belongs) agrees on the
    // cube but not where the faces are not quads
    let text =
        std::fs::read_to_string(format!("{}/schemes/catmull-clark-polygons.toml", env!("CARGO_MANIFEST_DIR"))).unwrap();
    assert_eq!(text.matches("face-corner = \"1 / (m n^2)\"").count(), 1);
    let as_quads = text
        .replace("face-corner = \"1 / (m n^2)\"", "face-corner = \"1 / (4 n^2)\"")
        .replace("topology = \"primal-quad\"", "topology = \"primal-quad\"\naffine = false");
    let as_quads = subdlab::schemes::user::UserSchemeDef::parse(&as_quads, "x.toml").unwrap().build(&[]).unwrap();
    assert_eq!(step_against_closed_form(&as_quads, &cube, None), Ok(26));
    let e = step_against_closed_form(&as_quads, &faces, None).unwrap_err();
    assert!(e.starts_with("Vertex("), "{e}");
}
