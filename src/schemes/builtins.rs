//! The catalogue of built-in schemes: every built-in name of every family,
//! listed once (`entries`), and the look-ups by name. Scheme files (`files`,
//! `user`) check here that a file does not take a built-in's name.

use crate::schemes::curves::{cubic_bspline, four_point, unified};
use crate::schemes::entry::{Entry, Family};
use crate::schemes::{catmull_clark, doo_sabin, four_three, khan_mustafa, loop_subdivision, non_box, pgs, polar_bi2};
use crate::schemes::{tps, unified_sqrt3};

/// Every built-in scheme: mesh schemes, then lattice schemes, then curve
/// schemes (the order `subdlab schemes` lists them in).
pub fn entries() -> Vec<Entry> {
    let mesh = [
        catmull_clark::entry(),
        loop_subdivision::entry(),
        doo_sabin::entry(),
        non_box::entry(),
        four_three::entry(),
        unified_sqrt3::kobbelt_entry(),
        unified_sqrt3::entry(),
        tps::entry(),
        pgs::entry(),
        polar_bi2::entry(),
    ];
    let lattice = [khan_mustafa::entry(), khan_mustafa::cubic_entry()];
    let curve = [cubic_bspline::entry(), four_point::entry(), unified::entry()];
    mesh.into_iter()
        .map(Entry::Mesh)
        .chain(lattice.into_iter().map(Entry::Lattice))
        .chain(curve.into_iter().map(Entry::Curve))
        .collect()
}

/// The built-in scheme of this name.
pub fn find(name: &str) -> Option<Entry> {
    entries().into_iter().find(|e| e.name() == name)
}

/// Every built-in name, of every family.
pub fn known_names() -> Vec<&'static str> {
    entries().iter().map(Entry::name).collect()
}

/// The built-in names of one family.
pub fn names_of(family: Family) -> Vec<&'static str> {
    entries().iter().filter(|e| e.family() == family).map(Entry::name).collect()
}
