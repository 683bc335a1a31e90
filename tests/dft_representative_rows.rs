//! The Fourier path assembles only the representative rows of S (one per
//! rotation orbit) and closes neighbourhood dependencies on orbits. These
//! tests check it against the second route that does not use the rotation:
//! every row assembled from the rules, and discovery on a copy of the scheme
//! that declares itself asymmetric (so every vertex is its own orbit).

use crate::common;
use common::*;
use num_traits::Zero;
use subdlab::dft::Orbits;
use subdlab::matrix::{assemble, assemble_rows};
use subdlab::mesh::PolyMesh;
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::numeric::Rational;
use subdlab::refine::{Origin, RuleResult, Stencil};
use subdlab::schemes::{self, MeshDomain, Params, Rules, Scheme, SchemeInfo};
use subdlab::spectrum::{analyse, decompose, Method, Options};

/// Every built-in mesh scheme of the registry with its default parameters
/// (unified sqrt(3) at its default α = 1), and the unified sqrt(3) family at
/// two more α.
fn all_schemes() -> Vec<(String, Box<dyn Scheme>)> {
    let mut out: Vec<(String, Box<dyn Scheme>)> = Vec::new();
    for name in mesh_scheme_names() {
        out.push((name.to_string(), scheme(name)));
    }
    for alpha in ["0", "1/2"] {
        let s = schemes::build("unified-sqrt3", &[("alpha".into(), alpha.into())]).unwrap();
        out.push((format!("unified-sqrt3 alpha={alpha}"), s));
    }
    out
}

/// The same rules, declared asymmetric: discovery then tracks every vertex
/// and the spectrum comes from the full matrix.
struct Asymmetric<'a>(&'a dyn Scheme, SchemeInfo);

impl<'a> Asymmetric<'a> {
    fn of(s: &'a dyn Scheme) -> Self {
        let mut info = *s.info();
        info.caps.rotation_symmetric = false;
        Asymmetric(s, info)
    }
}

impl<W: subdlab::schemes::SchemeWeight> Rules<MeshDomain, W> for Asymmetric<'_> {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        W::rule(self.0, mesh, origin)
    }
}

impl Scheme for Asymmetric<'_> {
    fn info(&self) -> &SchemeInfo {
        &self.1
    }
    fn params(&self) -> &Params {
        self.0.params()
    }
    fn vertex_param_rule(&self, mesh: &PolyMesh, origin: Origin) -> Option<Stencil<f64>> {
        self.0.vertex_param_rule(mesh, origin)
    }
}

#[test]
fn orbit_discovery_finds_the_same_neighbourhoods_as_tracking_every_vertex() {
    for (name, s) in all_schemes() {
        for n in [3, 5, 6, 7, 12, 40] {
            let config = Configuration::regular(s.as_ref(), n).unwrap();
            let by_orbits = discover(s.as_ref(), &config).unwrap();
            let every = discover(&Asymmetric::of(s.as_ref()), &config).unwrap();
            assert_eq!(by_orbits.minimal, every.minimal, "{name} n={n}: minimal neighbourhood");
            assert_eq!(by_orbits.analysis, every.analysis, "{name} n={n}: analysis neighbourhood");
            assert_eq!(by_orbits.analysis_levels, every.analysis_levels, "{name} n={n}");
        }
    }
}

#[test]
fn four_three_face_sequences_with_symmetry_match_tracking_every_vertex() {
    let s = scheme("four-three");
    for faces in ["QTQT", "QQTQQT", "QTQTQTQT", "QQQTTT"] {
        let config = Configuration::with_faces(s.as_ref(), faces.len(), faces).unwrap();
        assert!(config.symmetry_period() < faces.len() || faces == "QQQTTT");
        let by_orbits = discover(s.as_ref(), &config).unwrap();
        let every = discover(&Asymmetric::of(s.as_ref()), &config).unwrap();
        assert_eq!(by_orbits.minimal, every.minimal, "{faces}");
        assert_eq!(by_orbits.analysis, every.analysis, "{faces}");
    }
}

#[test]
fn representative_rows_and_the_lazy_matrix_are_the_rows_the_rules_give() {
    for (name, s) in all_schemes() {
        for n in [3, 5, 8, 13] {
            for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
                let config = Configuration::regular(s.as_ref(), n).unwrap();
                let opts = Options { neighbourhood: kind, method: None, exact: false };
                let a = analyse(s.as_ref(), &config, &opts).unwrap();
                // second route: a fresh discovery, every row from the rules
                let full = assemble::<f64>(s.as_ref(), &discover(s.as_ref(), &config).unwrap(), kind).unwrap();
                assert!(!a.matrix.is_assembled(), "{name} n={n}: the DFT path needs no full S");
                assert_eq!(a.matrix.labels, full.labels, "{name} n={n} {kind:?}");
                // the lazy S rotates the representative rows; a row evaluated in
                // another sector sums the same terms in another order, so the
                // two agree in pattern exactly and in value to rounding
                assert_eq!(a.matrix.size(), full.size(), "{name} n={n} {kind:?}");
                for (k, (lazy_row, rule_row)) in a.matrix.rows.iter().zip(&full.rows).enumerate() {
                    let columns = |r: &[(usize, f64)]| r.iter().map(|e| e.0).collect::<Vec<_>>();
                    assert_eq!(columns(lazy_row), columns(rule_row), "{name} n={n} {kind:?}: row {k}'s columns");
                    for ((_, x), (_, y)) in lazy_row.iter().zip(rule_row) {
                        assert!(approx::relative_eq!(*x, *y, max_relative = 1e-14), "{name} n={n} {kind:?}: row {k}");
                    }
                }
                // the representative rows alone give the same blocks, so the
                // same eigenvalues to the last bit
                let orbits = Orbits::new(&full, config.symmetry_period(), n);
                let reps = assemble_rows::<f64>(s.as_ref(), &a.discovered, kind, &orbits.representative).unwrap();
                for (o, &k) in orbits.representative.iter().enumerate() {
                    assert_eq!(reps[o], full.rows[k], "{name} n={n}: representative row {k}");
                }
                let from_full = decompose(&full, config.symmetry_period(), n, Method::Dft).unwrap();
                let mut want: Vec<(f64, f64, usize)> =
                    from_full.eigenvalues.iter().map(|e| (e.re, e.im, e.algebraic_multiplicity)).collect();
                let mut got: Vec<(f64, f64, usize)> =
                    a.spectrum.eigenvalues.iter().map(|e| (e.re, e.im, e.algebraic_multiplicity)).collect();
                want.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
                got.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
                assert_eq!(got, want, "{name} n={n} {kind:?}: spectrum from representative rows");
            }
        }
    }
}

#[test]
fn exact_matrix_rebuilt_by_rotation_equals_the_exact_assembly() {
    // sizes above the full exact method's limit, with rational weights
    for (name, n) in [("catmull-clark", 14), ("catmull-clark", 17), ("tps", 14)] {
        let s = scheme(name);
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let a = analyse(s.as_ref(), &config, &Options::default()).unwrap();
        assert_eq!(a.spectrum.exact_analysis.as_ref().unwrap().method, "block0", "{name} n={n}");
        let lazy = a.exact_matrix.as_ref().expect("rational weights");
        assert!(!lazy.is_assembled());
        let direct = assemble::<Rational>(s.as_ref(), &a.discovered, NeighbourhoodKind::Analysis).unwrap();
        assert_eq!(lazy.rows, direct.rows, "{name} n={n}");
        // the float matrix agrees with the exact one entry by entry
        for (rf, rq) in a.matrix.rows.iter().zip(&direct.rows) {
            assert_eq!(rf.len(), rq.len());
            for ((cf, wf), (cq, wq)) in rf.iter().zip(rq) {
                assert_eq!(cf, cq);
                assert!(!wq.is_zero());
                let q: f64 = num_traits::ToPrimitive::to_f64(wq).unwrap();
                assert!((wf - q).abs() <= 1e-15, "{name} n={n}: {wf} against {wq}");
            }
        }
    }
}

#[test]
fn high_valence_subdominant_eigenvalues_match_closed_forms() {
    // Loop: 3/8 + cos(2π/n)/4; Catmull–Clark: (5 + cos(2π/n) + cos(π/n)·sqrt(18 + 2cos(2π/n)))/16
    for n in [250, 1000] {
        let c = cos2pi(1, n);
        let a = run("loop", n, NeighbourhoodKind::Analysis, None, false);
        let l1 = a.spectrum.verdict.subdominant.unwrap();
        assert!((l1 - (0.375 + c / 4.0)).abs() < 1e-14, "loop n={n}: {l1}");
        let half = (std::f64::consts::PI / n as f64).cos();
        let cc = (5.0 + c + half * (18.0 + 2.0 * c).sqrt()) / 16.0;
        let a = run("catmull-clark", n, NeighbourhoodKind::Analysis, None, false);
        let l1 = a.spectrum.verdict.subdominant.unwrap();
        assert!((l1 - cc).abs() < 1e-14, "catmull-clark n={n}: {l1} against {cc}");
        let e = a.spectrum.eigenvalues.iter().find(|e| (e.re - l1).abs() < 1e-12).unwrap();
        assert_eq!(e.algebraic_multiplicity, 2);
        assert_eq!(e.blocks, vec![1, n - 1]);
        // the multiplicities account for the whole matrix (6n + 1)
        let total: usize = a.spectrum.eigenvalues.iter().map(|e| e.algebraic_multiplicity).sum();
        assert_eq!(total, 6 * n + 1);
        assert_eq!(a.spectrum.matrix_size, 6 * n + 1);
    }
}

/// At high valence discovery refines only the sectors
/// around the orbit representatives (the rest of the patch is never read),
/// and makes the whole analysis step only when asked. Second route: the same
/// rules declared asymmetric, which tracks every vertex on the whole patch.
#[test]
fn windowed_discovery_at_high_valence_matches_tracking_every_vertex() {
    for (name, s) in all_schemes() {
        let n = 160;
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let by_orbits = discover(s.as_ref(), &config).unwrap();
        let every = discover(&Asymmetric::of(s.as_ref()), &config).unwrap();
        assert_eq!(by_orbits.minimal, every.minimal, "{name} n={n}: minimal neighbourhood");
        assert_eq!(by_orbits.analysis, every.analysis, "{name} n={n}: analysis neighbourhood");
        // the 2-ring rules of unified sqrt(3) at α ≠ 0 need a 4-ring patch, the
        // first size at which the window leaves out most of it (the others'
        // 2-ring patches are mostly the disc every sector keeps)
        if name.ends_with("alpha=1/2") || name.ends_with("alpha=1") {
            assert!(!by_orbits.whole_step_made(), "{name}: discovery refined only the window");
        }
        // the whole step, made on demand, is the step of the whole patch
        let whole = &every.refinements();
        let made = by_orbits.refinements();
        assert_eq!(made.len(), whole.len(), "{name}");
        for (a, b) in made.iter().zip(whole.iter()) {
            assert_eq!(a.mesh.num_faces(), b.mesh.num_faces(), "{name}: faces of the whole step");
            assert_eq!(a.vertex_origins, b.vertex_origins, "{name}: vertices of the whole step");
        }
        // and every row of S from it agrees with the representative rows
        for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
            let a = analyse(s.as_ref(), &config, &Options { neighbourhood: kind, method: None, exact: false }).unwrap();
            let rules = assemble::<f64>(s.as_ref(), &a.discovered, kind).unwrap();
            let orbits = Orbits::new(&rules, config.symmetry_period(), n);
            let reps =
                subdlab::matrix::local::assemble_rows_f64(s.as_ref(), &a.discovered, kind, &orbits.representative)
                    .unwrap();
            for (o, &k) in orbits.representative.iter().enumerate() {
                assert_eq!(reps[o], rules.rows[k], "{name} {kind:?}: representative row {k}");
            }
        }
    }
}

/// The Fourier blocks are built in runs of consecutive block indices, side
/// by side, each run starting its ω-powers at its first block. At a valence
/// spanning several runs every block must equal the definition evaluated
/// entry by entry: B_m[a, b] = Σ_τ S[rep a, (b, τ)] ω^{mτ}, with ω^{mτ} from
/// `omega_pow` (a cos and sin per entry) instead of the runs' table.
#[test]
fn fourier_blocks_built_in_runs_equal_the_definition_entry_by_entry() {
    use subdlab::dft::{fourier_blocks_from_rows, omega_pow};
    let n = 150;
    for name in ["loop", "catmull-clark"] {
        let s = scheme(name);
        let config = Configuration::regular(s.as_ref(), n).unwrap();
        let found = discover(s.as_ref(), &config).unwrap();
        let kind = NeighbourhoodKind::Analysis;
        let labels = subdlab::matrix::local::set_labels(&found, kind);
        let orbits = Orbits::from_labels(&labels, config.symmetry_period(), n);
        let rows = subdlab::matrix::local::assemble_rows_f64(s.as_ref(), &found, kind, &orbits.representative).unwrap();
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let blocks = fourier_blocks_from_rows(&refs, &orbits);
        assert_eq!(blocks.len(), n, "{name}: one block per rotation");
        for (m, b) in blocks.iter().enumerate() {
            assert_eq!(b.index, m);
            let list = orbits.block_orbits(m);
            for (ra, &a) in list.iter().enumerate() {
                let mut want = vec![faer::c64::new(0.0, 0.0); list.len()];
                for &(col, w) in &rows[a] {
                    let (ob, tau) = orbits.member[col];
                    if let Some(cb) = list.iter().position(|&o| o == ob) {
                        want[cb] += omega_pow(m, tau, n) * w;
                    }
                }
                for (cb, w) in want.iter().enumerate() {
                    let got = b.matrix[(ra, cb)];
                    assert!((got - w).norm() <= 1e-13, "{name} n={n}: block {m} entry ({ra},{cb}) {got} vs {w}");
                }
            }
        }
    }
}
