//! `certify::step_rotation`: the rotation premise decided on the refinement
//! steps. Every rotation-symmetric built-in takes the route and agrees with
//! PS = SP checked by its definition on the exact composed S; orbits that
//! are not the mesh's rotation get no answer (the composed rows then decide).

use subdlab::certify::step_rotation::rotation_by_steps;
use subdlab::dft::Orbits;
use subdlab::matrix::local::assemble_rows_rational;
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::schemes::{builtins::names_of, entry::Family};
use subdlab::sdc::Scheme;
use subdlab::spectrum::Analysis;
use subdlab::spectrum::{analyse, Options};

fn analysis_of(scheme: &dyn Scheme, config: &Configuration) -> Analysis {
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    analyse(scheme, config, &opts).expect("analysed")
}

/// PS = SP checked by its definition, on the whole composed S in exact
/// rationals (the route this module replaces): row ρ(k) of S is row k
/// with every column turned.
fn composed_rows_turn(scheme: &dyn Scheme, analysis: &Analysis, orbits: &Orbits) -> bool {
    let g = orbits.group_order;
    let mut index = vec![vec![usize::MAX; g]; orbits.num_orbits()];
    for (k, &(o, t)) in orbits.member.iter().enumerate() {
        index[o][t] = k;
    }
    let turn = |k: usize| {
        let (o, t) = orbits.member[k];
        if orbits.fixed[o] {
            k
        } else {
            index[o][(t + 1) % g]
        }
    };
    let everyone: Vec<usize> = (0..orbits.member.len()).collect();
    let rows = assemble_rows_rational(scheme, &analysis.discovered, NeighbourhoodKind::Analysis, &everyone)
        .expect("rational rows");
    everyone.iter().all(|&k| {
        let mut moved: Vec<_> = rows[k].iter().map(|(c, w)| (turn(*c), w.clone())).collect();
        moved.sort_by_key(|e| e.0);
        moved == rows[turn(k)]
    })
}

/// Every rotation-symmetric built-in mesh scheme (at its defaults) is
/// decided by the steps' route, and where S is rational the composed
/// rows agree: S commutes with the rotation by its definition.
#[test]
fn every_builtin_takes_the_steps_route_and_the_composed_rows_agree() {
    let mut rational_checked = 0;
    for name in names_of(Family::Mesh) {
        let scheme = subdlab::schemes::resolve(name, &[]).expect("built-in");
        for n in [3, 5, 6] {
            let Ok(config) = Configuration::regular(scheme.as_ref(), n) else { continue };
            if scheme.fixed_valence().is_some() || config.rotation_period(scheme.as_ref()) >= n {
                continue;
            }
            let analysis = analysis_of(scheme.as_ref(), &config);
            let orbits = subdlab::certify::spectrum::analysis_orbits(scheme.as_ref(), &analysis);
            let order = rotation_by_steps(scheme.as_ref(), &analysis, &orbits);
            assert!(order.is_some(), "{name} n = {n}: the steps' route gave no answer");
            let everyone: Vec<usize> = (0..orbits.member.len()).collect();
            if assemble_rows_rational(scheme.as_ref(), &analysis.discovered, NeighbourhoodKind::Analysis, &everyone)
                .is_ok()
            {
                assert!(composed_rows_turn(scheme.as_ref(), &analysis, &orbits), "{name} n = {n}");
                rational_checked += 1;
            }
        }
    }
    assert!(rational_checked >= 10, "only {rational_checked} rational configurations compared");
}

/// Negative controls: orbits that do not describe the mesh's rotation
/// (two members of an orbit swapped; a rotation of another order) get
/// no answer, so the composed rows decide.
#[test]
fn orbits_that_are_not_the_meshs_rotation_get_no_answer() {
    let scheme = subdlab::schemes::resolve("catmull-clark", &[]).expect("built-in");
    let config = Configuration::regular(scheme.as_ref(), 6).expect("config");
    let analysis = analysis_of(scheme.as_ref(), &config);
    let orbits = subdlab::certify::spectrum::analysis_orbits(scheme.as_ref(), &analysis);
    assert!(rotation_by_steps(scheme.as_ref(), &analysis, &orbits).is_some());
    // swap positions 1 and 2 of the first orbit that moves
    let mut swapped = orbits.clone();
    let o = (0..swapped.num_orbits()).find(|&o| !swapped.fixed[o]).expect("a moving orbit");
    let a = swapped.member.iter().position(|&m| m == (o, 1)).expect("t = 1");
    let b = swapped.member.iter().position(|&m| m == (o, 2)).expect("t = 2");
    swapped.member.swap(a, b);
    assert_eq!(rotation_by_steps(scheme.as_ref(), &analysis, &swapped), None);
    // the orbits of the rotation by two sectors (order 3, the mesh's is 6)
    let labels = &analysis.spectrum.labels;
    let coarser = Orbits::from_labels(labels, 2, 6);
    assert_eq!(rotation_by_steps(scheme.as_ref(), &analysis, &coarser), None);
}
