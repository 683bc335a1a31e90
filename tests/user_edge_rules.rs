//! The `[edge-extraordinary]` rule of scheme files: the only place where a
//! weight may depend on the neighbour index j (j = 0 is the edge's other end,
//! counter-clockwise around the extraordinary vertex), and the `sum` function
//! that lets a file give ring weights by their Fourier coefficients.
//!
//! Expected values are closed forms derived in the comments (circulant
//! eigenvalues, hand-computed stencils on small meshes), never program output.
//! `tests/user_schemes.rs` checks that `schemes/catmull-clark-edge-rule.toml`
//! gives the built-in Catmull–Clark matrices, spectra and meshes.

use crate::common;
use common::{expanded, fails, subdlab};
use subdlab::matrix::assemble;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::numeric::ParamValue;
use subdlab::schemes::user::UserSchemeDef;
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::{analyse, Analysis, Method, Options};

use std::f64::consts::PI;

fn path(rel: &str) -> String {
    format!("{}/{rel}", env!("CARGO_MANIFEST_DIR"))
}

fn file_scheme(rel: &str) -> Box<dyn Scheme> {
    schemes::resolve(&path(rel), &[]).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn parse(text: &str) -> Result<UserSchemeDef, String> {
    UserSchemeDef::parse(text, "x.toml").map_err(|e| e.to_string())
}

fn run(scheme: &dyn Scheme, n: usize, kind: NeighbourhoodKind, method: Option<Method>) -> Analysis {
    let config = Configuration::regular(scheme, n).unwrap();
    analyse(scheme, &config, &Options { neighbourhood: kind, method, exact: true }).unwrap()
}

/// Sorted (re, im) pairs agree to `tol`.
fn assert_same_spectrum(mut got: Vec<(f64, f64)>, mut want: Vec<(f64, f64)>, tol: f64, what: &str) {
    let key = |a: &(f64, f64), b: &(f64, f64)| {
        let (ra, rb) = ((a.0 / tol).round(), (b.0 / tol).round());
        ra.total_cmp(&rb).then(a.1.total_cmp(&b.1))
    };
    got.sort_by(key);
    want.sort_by(key);
    assert_eq!(got.len(), want.len(), "{what}: got {got:?}, want {want:?}");
    for (g, w) in got.iter().zip(&want) {
        assert!((g.0 - w.0).abs() < tol && (g.1 - w.1).abs() < tol, "{what}: got {got:?}, want {want:?}");
    }
}

// ---------------------------------------------------------------------------
// The Fourier-designed Loop variant, schemes/loop-fourier-edge.toml

/// μ(m) of the file: by the frequency d = min(m, n − m) of block m,
/// 5/8 (d = 0), 1/2 (d = 1), 1/4 (d = 2), 1/8 (d ≥ 3).
fn mu(n: usize, m: usize) -> f64 {
    match m.min(n - m) {
        0 => 5.0 / 8.0,
        1 => 0.5,
        2 => 0.25,
        _ => 0.125,
    }
}

/// The file's ring weight s_j = (1/n) Σ_m μ(m) cos(2π j m / n) in closed form.
/// μ = 1/8 + (1/2)[d = 0] + (3/8)[d = 1] + (1/8)[d = 2]; (1/n) Σ_m cos(2π j m/n)
/// = δ_{j,0}; the pair m = 1, n − 1 gives 2 cos θ, θ = 2π j / n; the pair
/// m = 2, n − 2 gives 2 cos 2θ when n ≥ 5, the single m = 2 gives cos 2θ at
/// n = 4, and n = 3 has no d = 2. So
/// s_j = δ_{j,0}/8 + (1/n) (1/2 + (3/4) cos θ + c2 cos 2θ), c2 = 1/4, 1/8, 0.
fn ring_weight(n: usize, j: usize) -> f64 {
    let theta = 2.0 * PI * j as f64 / n as f64;
    let c2 = match n {
        3 => 0.0,
        4 => 0.125,
        _ => 0.25,
    };
    let delta = if j == 0 { 0.125 } else { 0.0 };
    delta + (0.5 + 0.75 * theta.cos() + c2 * (2.0 * theta).cos()) / n as f64
}

#[test]
fn fourier_designed_ring_weights_and_their_spectrum_on_the_one_ring() {
    let file = file_scheme("schemes/loop-fourier-edge.toml");
    for n in 3..=12 {
        let what = format!("loop-fourier-edge n = {n}");
        // the closed form satisfies the design: Σ_j s_j cos(2π j m/n) = μ(m)
        // (s is even in j, so the sine part vanishes) and the rule is affine
        for m in 0..n {
            let c: f64 = (0..n).map(|j| ring_weight(n, j) * (2.0 * PI * (j * m) as f64 / n as f64).cos()).sum();
            assert!((c - mu(n, m)).abs() < 1e-14, "{what}: closed form at m = {m}");
        }
        let a = run(file.as_ref(), n, NeighbourhoodKind::Minimal, None);
        // the centre and its 1-ring: every new point there (the vertex point,
        // the edge points on the n edges at the centre) needs only these
        assert_eq!(a.spectrum.minimal_size, n + 1, "{what}: minimal neighbourhood");
        assert_eq!(a.matrix.size(), n + 1, "{what}");
        if n != 6 {
            // rows of the ring: 3/8 on the centre, s_{k - k'} on ring vertex k'
            // (ring vertices are one per sector; s is even, so the direction of
            // counting does not matter here: tests below check the direction)
            let m = &a.matrix;
            let centre = m.labels.iter().position(|l| l.ring == 0).unwrap();
            let ring: Vec<usize> = (0..m.size()).filter(|&i| m.labels[i].ring == 1).collect();
            assert_eq!(ring.len(), n);
            for &r in &ring {
                assert!((m.get(r, centre) - 0.375).abs() < 1e-14, "{what}: centre weight");
                for &c in &ring {
                    let k = (m.labels[c].sector + n - m.labels[r].sector) % n;
                    let (got, want) = (m.get(r, c), ring_weight(n, k));
                    assert!((got - want).abs() < 1e-14, "{what}: S[{r}][{c}] = {got}, s_{k} = {want}");
                }
            }
        }
        // S = [[5/8, 3/(8n) 1^T], [3/8 1, C]], C circulant with C[k][k+j] = s_j.
        // Block 0 (centre, constant ring): [[5/8, 3/8], [3/8, Σ s_j = μ(0) = 5/8]],
        // eigenvalues 5/8 ± 3/8 = 1 and 1/4. Block m ≥ 1 (ring vector ω^{mk},
        // orthogonal to the centre row): Σ_j s_j ω^{jm} = μ(m). (At n = 6 the
        // edge rule is Loop's, which has the same μ; Warren's β = 3/48 = 1/16.)
        let mut want = vec![(1.0, 0.0), (0.25, 0.0)];
        want.extend((1..n).map(|m| (mu(n, m), 0.0)));
        assert_same_spectrum(expanded(&a), want, 1e-10, &what);
        // so: 1, 1/2 twice, 1/4 three times (n ≥ 5; twice at n = 4, once at
        // n = 3), 1/8 (n − 5) times, as in the regular case
        let count = |x: f64| {
            a.spectrum.eigenvalues.iter().find(|e| (e.re - x).abs() < 1e-10).map_or(0, |e| e.algebraic_multiplicity)
        };
        assert_eq!(count(0.5), 2, "{what}");
        assert_eq!(count(0.25), if n >= 5 { 3 } else { n - 2 }, "{what}");
        assert_eq!(count(0.125), n.saturating_sub(5), "{what}");
        assert!(a.spectrum.eigenvalues.iter().all(|e| e.geometric_multiplicity == e.algebraic_multiplicity));
        // cos(2π k/n) is rational at n = 3, 4, 6: every weight is, and the
        // exact path proves each eigenvalue
        if [3, 4, 6].contains(&n) {
            for e in &a.spectrum.eigenvalues {
                let q = e.exact.as_ref().unwrap_or_else(|| panic!("{what}: {} not proved exact", e.re));
                assert!((ParamValue::parse(q).unwrap().value - e.re).abs() < 1e-12, "{what}: {q} vs {}", e.re);
            }
        }
    }
}

#[test]
fn a_whole_ring_edge_stencil_keeps_the_neighbourhoods() {
    // Loop-like files: the edge points at the centre reach the whole 1-ring,
    // which the vertex point needs anyway: the minimal set stays centre +
    // 1-ring (n + 1); the analysis set stays the built-in Loop's, centre and
    // two rings (1 + n + 2n).
    let fourier = file_scheme("schemes/loop-fourier-edge.toml");
    // Catmull–Clark with an edge rule on V, all e_j and all f_j: minimal set
    // V, e_j, f_j (2n + 1), analysis set the built-in's (6n + 1).
    let wide = parse(CC_WIDE).unwrap().build(&[]).unwrap();
    let (builtin_loop, builtin_cc) =
        (schemes::build("loop", &[]).unwrap(), schemes::build("catmull-clark", &[]).unwrap());
    for n in 3..=12 {
        for (file, builtin, minimal, analysis) in [
            (fourier.as_ref(), builtin_loop.as_ref(), n + 1, 3 * n + 1),
            (&wide as &dyn Scheme, builtin_cc.as_ref(), 2 * n + 1, 6 * n + 1),
        ] {
            let d = discover(file, &Configuration::regular(file, n).unwrap()).unwrap();
            let b = discover(builtin, &Configuration::regular(builtin, n).unwrap()).unwrap();
            let what = format!("{} n = {n}", file.name());
            assert_eq!((d.minimal.len(), d.analysis.len()), (minimal, analysis), "{what}");
            assert_eq!((b.minimal.len(), b.analysis.len()), (minimal, analysis), "{what}: built-in");
        }
        // the wide rule is really used: the n edge points at the centre weigh
        // all 2n ring vertices (V, e_j, f_j all get 1/(4n) or more)
        if n != 4 {
            let d = discover(&wide, &Configuration::regular(&wide, n).unwrap()).unwrap();
            let m = assemble::<f64>(&wide, &d, NeighbourhoodKind::Minimal).unwrap();
            let ring: Vec<usize> = (0..m.size()).filter(|&i| m.labels[i].ring == 1).collect();
            assert_eq!(ring.len(), 2 * n);
            let wide_rows = ring.iter().filter(|&&r| ring.iter().all(|&c| m.get(r, c) >= 0.25 / n as f64)).count();
            assert_eq!(wide_rows, n, "cc-wide n = {n}");
        }
    }
}

/// Catmull–Clark vertex and face rules; at an extraordinary end, the edge
/// point averages V (1/4), the other end (1/4) and spreads 1/2 over the whole
/// 1-ring: 1/(4n) on each e_j and on each f_j.
const CC_WIDE: &str = r#"name = "cc-wide"
topology = "primal-quad"
[vertex]
centre = "1 - 7 / (4 n)"
edge = "3 / (2 n^2)"
face = "1 / (4 n^2)"
[edge]
ends = "3/8"
side = "1/16"
[edge-extraordinary]
centre = "1/4"
edge = "kronecker(j)/4 + 1/(4 n)"
face = "1/(4 n)"
[face]
corner = "1 / n"
"#;

// ---------------------------------------------------------------------------
// An asymmetric edge rule: e_1 and e_{n-1} weigh differently

/// Warren's vertex rule; at an extraordinary end V the edge point is
/// 3/8 V + 1/4 e_0 + 3/16 e_1 + 1/16 e_{n-1} + 1/(8n) Σ_j e_j
/// (3/8 + 1/4 + 3/16 + 1/16 + 1/8 = 1).
const ASYMMETRIC: &str = r#"name = "asym-loop"
topology = "primal-triangle"
[vertex]
centre = "5/8"
edge = "3 / (8 n)"
[edge]
ends = "3/8"
opposite = "1/8"
[edge-extraordinary]
centre = "3/8"
edge = "kronecker(j)/4 + 3 kronecker(j - 1)/16 + kronecker(j - n + 1)/16 + 1/(8 n)"
"#;

fn asym_weight(n: usize, j: usize) -> f64 {
    let d = |k: usize| if j == k { 1.0 } else { 0.0 };
    d(0) / 4.0 + 3.0 * d(1) / 16.0 + d(n - 1) / 16.0 + 1.0 / (8.0 * n as f64)
}

#[test]
fn an_asymmetric_edge_rule_keeps_rotation_symmetry_dft_and_full_agree() {
    let scheme = parse(ASYMMETRIC).unwrap().build(&[]).unwrap();
    for n in 3..=12 {
        for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
            let what = format!("asymmetric n = {n} {kind:?}");
            let dft = run(&scheme, n, kind, Some(Method::Dft));
            let full = run(&scheme, n, kind, Some(Method::Full));
            assert_eq!(dft.spectrum.method, Method::Dft);
            assert_eq!(full.spectrum.method, Method::Full);
            assert_same_spectrum(expanded(&dft), expanded(&full), 1e-9, &what);
            // without a method the rotation-symmetric configuration takes the DFT
            assert_eq!(run(&scheme, n, kind, None).spectrum.method, Method::Dft, "{what}");
            if kind == NeighbourhoodKind::Minimal && n != 6 {
                // block 0: [[5/8, 3/8], [3/8, 5/8]] -> 1, 1/4; block m >= 1:
                // Σ_j s_j ω^{jm} = 1/4 + (3/16) ω^m + (1/16) ω^{-m} (the uniform
                // 1/(8n) sums to 0) = 1/4 + cos(2πm/n)/4 + i sin(2πm/n)/8:
                // complex, as reflection symmetry is broken; m and n − m conjugate
                let mut want = vec![(1.0, 0.0), (0.25, 0.0)];
                for m in 1..n {
                    let t = 2.0 * PI * m as f64 / n as f64;
                    want.push((0.25 + t.cos() / 4.0, t.sin() / 8.0));
                }
                assert_same_spectrum(expanded(&dft), want, 1e-10, &what);
                assert!(expanded(&dft).iter().any(|e| e.1.abs() > 0.01), "{what}: complex eigenvalues");
            }
        }
    }
}

/// Vertices of an OBJ text.
fn obj_points(text: &str) -> Vec<[f64; 3]> {
    text.lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect()
}

/// `subdlab refine MESH --scheme FILE -l 1`: the refined points.
fn refine_once(mesh: &str, scheme_text: &str) -> Vec<[f64; 3]> {
    let dir = tempfile::tempdir().unwrap();
    let (scheme, out) = (dir.path().join("s.toml"), dir.path().join("out.obj"));
    std::fs::write(&scheme, scheme_text).unwrap();
    let o = subdlab(&[
        "refine",
        &path(&format!("meshes/{mesh}.obj")),
        "--scheme",
        scheme.to_str().unwrap(),
        "-l",
        "1",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    obj_points(&std::fs::read_to_string(&out).unwrap())
}

fn combination(terms: &[(f64, [f64; 3])]) -> [f64; 3] {
    let mut p = [0.0; 3];
    for (w, q) in terms {
        (0..3).for_each(|k| p[k] += w * q[k]);
    }
    p
}

fn holds(points: &[[f64; 3]], p: [f64; 3]) -> bool {
    points.iter().any(|q| (0..3).all(|k| (q[k] - p[k]).abs() < 1e-12))
}

#[test]
fn counter_clockwise_from_the_edge_on_a_real_mesh() {
    // meshes/mixed-triangles.obj (1-based): equator vertices 1..5, top apex 6
    // (valence 6, regular), bottom apex 7. Vertex 3 = (-0.809017, 0.587785, 0)
    // has the faces 2 3 6, 3 2 7, 3 4 6, 4 3 7: valence 4, neighbours 2, 6, 4, 7.
    // The edge {3, 6} has one extraordinary end, V = 3, e_0 = 6.
    let text = std::fs::read_to_string(path("meshes/mixed-triangles.obj")).unwrap();
    let p = obj_points(&text);
    let v = |k: usize| p[k - 1];
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let cross =
        |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    // counter-clockwise seen from outside (the outward normal at 3 is along
    // its position, the mesh being star-shaped about the origin): turning from
    // 6 towards 2 is positive, so around 3 the ring is e_0..e_3 = 6, 2, 7, 4
    assert!(dot(cross(sub(v(6), v(3)), sub(v(2), v(3))), v(3)) > 0.5);
    assert!(dot(cross(sub(v(2), v(3)), sub(v(7), v(3))), v(3)) > 0.5);
    let ring = [6, 2, 7, 4];
    let mut terms = vec![(0.375, v(3))];
    terms.extend(ring.iter().enumerate().map(|(j, &k)| (asym_weight(4, j), v(k))));
    let want = combination(&terms);
    // counting clockwise instead would give 3/16 to 4 and 1/16 to 2
    let mirrored: Vec<(f64, [f64; 3])> = [
        (0.375, 3),
        (0.25 + 1.0 / 32.0, 6),
        (1.0 / 16.0 + 1.0 / 32.0, 2),
        (1.0 / 32.0, 7),
        (3.0 / 16.0 + 1.0 / 32.0, 4),
    ]
    .iter()
    .map(|&(w, k)| (w, v(k)))
    .collect();
    let refined = refine_once("mixed-triangles", ASYMMETRIC);
    assert!(holds(&refined, want), "the hand-computed edge point {want:?} is not in the refined mesh");
    assert!(!holds(&refined, combination(&mirrored)));
}

#[test]
fn both_ends_extraordinary_take_the_mean_of_the_two_stencils() {
    // the octahedron: six vertices of valence 4, all extraordinary. For the
    // edge from a = +x to b = +z: around +x (counter-clockwise about +x:
    // y -> z -> -y -> -z) the ring from e_0 = +z is +z, -y, -z, +y, so a's
    // stencil is 3/8 x + 1/4 z + 3/16 (-y) + 1/16 y + (1/32)(ring sum = 0)
    // = (3/8, -1/8, 1/4); around +z (x -> y -> -x -> -y) from e_0 = +x:
    // 3/8 z + 1/4 x + 3/16 y + 1/16 (-y) = (1/4, 1/8, 3/8). The mean is
    // (5/16, 0, 5/16) = (5/16)(a + b); by symmetry every edge point is
    // (5/16)(a + b). Vertex points (Warren): 5/8 v + 3/32 (ring sum = 0) = 5/8 v.
    let refined = refine_once("octahedron", ASYMMETRIC);
    assert_eq!(refined.len(), 6 + 12);
    let axes: Vec<[f64; 3]> = (0..6)
        .map(|k| {
            let mut p = [0.0; 3];
            p[k / 2] = if k % 2 == 0 { 1.0 } else { -1.0 };
            p
        })
        .collect();
    for (i, a) in axes.iter().enumerate() {
        assert!(holds(&refined, combination(&[(0.625, *a)])), "vertex point of {a:?}");
        for b in &axes[i + 1..] {
            if (0..3).any(|k| a[k] != 0.0 && a[k] == -b[k]) {
                continue; // opposite vertices share no edge
            }
            assert!(holds(&refined, combination(&[(5.0 / 16.0, *a), (5.0 / 16.0, *b)])), "edge {a:?} {b:?}");
        }
    }
    // one end's stencil alone is not what the mesh gets
    assert!(!holds(&refined, [0.375, -0.125, 0.25]) && !holds(&refined, [0.25, 0.125, 0.375]));
}

// ---------------------------------------------------------------------------
// Errors

/// The error for ASYMMETRIC with `from` replaced by `to`: one line.
fn error_of(from: &str, to: &str) -> String {
    assert!(ASYMMETRIC.contains(from), "{from}");
    let e = parse(&ASYMMETRIC.replacen(from, to, 1)).err().unwrap_or_else(|| panic!("{to} should be rejected"));
    assert!(!e.contains('\n'), "one line: {e}");
    e
}

#[test]
fn j_stays_rejected_outside_the_edge_rule_with_a_pointer_to_it() {
    assert!(parse(ASYMMETRIC).is_ok());
    const POINTER: &str =
        "weights that depend on j belong in [edge-extraordinary], where j = 0 is the edge's other end";
    let cases: [(&str, &str, &str); 6] = [
        // a per-neighbour vertex weight that varies with j
        (
            "edge = \"3 / (8 n)\"",
            "edge = \"3 / (8 n) + kronecker(j) / 100\"",
            "x.toml line 5, field vertex.edge: the weight differs between j = 0 and j = 1 at n = 3",
        ),
        ("centre = \"5/8\"", "centre = \"5/8 + j\"", "x.toml line 4, field vertex.centre: unknown variable 'j'"),
        ("ends = \"3/8\"", "ends = \"3/8 + j\"", "x.toml line 7, field edge.ends: unknown variable 'j'"),
        // in the edge rule's own single-vertex field: no pointer to itself
        (
            "centre = \"3/8\"",
            "centre = \"3/8 + j\"",
            "line 10, field edge-extraordinary.centre: unknown variable 'j' (j indexes neighbours only in per-neighbour fields)",
        ),
        // n is the extraordinary vertex's valence here, but edge rules have none
        ("ends = \"3/8\"", "ends = \"3/8 n\"", "field edge.ends: unknown variable 'n' (edge rules have no valence n)"),
        (
            "edge = \"kronecker(j)/4",
            "bad = 1\nedge = \"kronecker(j)/4",
            "line 11, field edge-extraordinary.bad: unknown field; the edge-extraordinary rule of primal-triangle has centre, edge",
        ),
    ];
    for (from, to, want) in cases {
        let e = error_of(from, to);
        assert!(e.contains(want), "{to}: got '{e}', want '{want}'");
    }
    for (from, to) in [
        ("edge = \"3 / (8 n)\"", "edge = \"3 / (8 n) + kronecker(j) / 100\""),
        ("centre = \"5/8\"", "centre = \"5/8 + j\""),
    ] {
        assert!(error_of(from, to).contains(POINTER), "{to}");
    }
    assert!(!error_of("centre = \"3/8\"", "centre = \"3/8 + j\"").contains("belong in"));
    // a per-face weight of a quad file varies with j too
    let cc = std::fs::read_to_string(path("schemes/catmull-clark.toml")).unwrap();
    let e = parse(&cc.replacen("corner = \"1 / n\"", "corner = \"1 / n + (kronecker(j) - 1/n) / 10\"", 1)).unwrap_err();
    assert!(e.contains("field face.corner: the weight differs between j = 0 and j = 1") && e.contains(POINTER), "{e}");
    // fcv files have no [edge-extraordinary] rule, and their j errors point nowhere
    let nb = std::fs::read_to_string(path("schemes/non-box.toml")).unwrap();
    let e = parse(&format!("{nb}\n[edge-extraordinary]\ncentre = \"1\"\n")).unwrap_err();
    assert!(e.contains("field edge-extraordinary: topology fcv has no edge-extraordinary rule"), "{e}");
    let e = parse(&nb.replacen("ends = \"1/4\"", "ends = \"1/4 + j\"", 1)).unwrap_err();
    assert!(
        e.contains("unknown variable 'j' (j indexes neighbours only in per-neighbour fields)")
            && !e.contains("belong in")
    );
    // the command line shows the same one-line error
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, ASYMMETRIC.replacen("centre = \"5/8\"", "centre = \"5/8 + j\"", 1)).unwrap();
    let e = fails(&["spectrum", bad.to_str().unwrap(), "--valence", "5"]);
    assert!(e.contains("line 4, field vertex.centre: unknown variable 'j'") && e.contains(POINTER), "{e}");
}

#[test]
fn the_edge_rule_is_checked_at_load_time() {
    let edge = "edge = \"kronecker(j)/4 + 3 kronecker(j - 1)/16 + kronecker(j - n + 1)/16 + 1/(8 n)\"";
    let cases: [(&str, &str); 9] = [
        // affine: Σ_j of a j-dependent field counts each weight once; here
        // e_1 gets 1/4 instead of 3/16, so the weights sum to 1 + 1/16
        (
            "edge = \"kronecker(j)/4 + kronecker(j - 1)/4 + kronecker(j - n + 1)/16 + 1/(8 n)\"",
            "x.toml line 9, field edge-extraordinary: the weights of the edge-extraordinary rule sum to 1.06",
        ),
        // the sum function: syntax, bounds, size, fresh variable
        ("edge = \"sum(1, 2)\"", "line 11, field edge-extraordinary.edge: the first argument of sum must be a variable name"),
        ("edge = \"sum(m, 0, n - 1)\"", "line 11, field edge-extraordinary.edge: expected ',' before the expression of sum"),
        ("edge = \"sum(m, 0, n - 1, m\"", "line 11, field edge-extraordinary.edge: missing ')' after sum"),
        (
            "edge = \"sum(m, 0, n/2, m)\"",
            "line 11, field edge-extraordinary.edge: at n = 3, j = 0: the upper bound of a sum must be an integer, got 3/2",
        ),
        (
            "edge = \"sum(m, 1, 20000, 0)\"",
            "line 11, field edge-extraordinary.edge: at n = 3, j = 0: a sum of 20000 terms; at most 10000 terms in all",
        ),
        (
            "edge = \"sum(j, 0, n - 1, 1/n)\"",
            "line 11, field edge-extraordinary.edge: at n = 3, j = 0: sum variable 'j' is already a variable here",
        ),
        // weights must be real and finite at every j
        ("edge = \"1/(j - 1)\"", "line 11, field edge-extraordinary.edge: at n = 3, j = 1: division by zero"),
        ("edge = \"sqrt(j - 2)\"", "line 11, field edge-extraordinary.edge: at n = 3, j = 0: the weight is complex"),
    ];
    for (to, want) in cases {
        let e = error_of(edge, to);
        assert!(e.contains(want), "{to}: got '{e}', want '{want}'");
    }
    // a sum variable may not be a parameter either; parameters may not be called sum
    let with_param =
        |p: &str, e: &str| ASYMMETRIC.replacen("[vertex]", &format!("{p}\n[vertex]"), 1).replacen(edge, e, 1);
    let e = parse(&with_param(
        "[params.w]\ndefault = 1",
        "edge = \"sum(w, 0, 1, 0) + kronecker(j)/4 + 3 kronecker(j - 1)/16 + kronecker(j - n + 1)/16 + 1/(8 n)\"",
    ))
    .unwrap_err();
    assert!(e.contains("sum variable 'w' is already a variable here"), "{e}");
    let e = parse(&with_param("[params.sum]\ndefault = 1", edge)).unwrap_err();
    assert!(e.contains("field params.sum: 'sum' is reserved"), "{e}");
    // quads need all three fields
    let cc = std::fs::read_to_string(path("schemes/catmull-clark-edge-rule.toml")).unwrap();
    let e = parse(&cc.replacen("face = \"(kronecker(j)", "# face = \"(kronecker(j)", 1)).unwrap_err();
    assert!(e.contains("field edge-extraordinary.face: missing (write 0 for a zero weight)"), "{e}");
    // and the regular edge rule stays required
    let e = parse(&ASYMMETRIC.replacen("[edge]\nends = \"3/8\"\nopposite = \"1/8\"\n", "", 1)).unwrap_err();
    assert!(e.contains("missing section [edge]"), "{e}");
}
