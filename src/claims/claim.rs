//! A claim file as read: its paper, figures and claims. Each claim has an
//! id, where it stands in the paper, the statement as printed, the
//! convention it uses, the verdict the registry expects and its `check`
//! (one of the check kinds, `checks::Check`).

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::claims::checks::Check;
use crate::claims::verdict::Verdict;

#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClaimFile {
    /// short paper key, e.g. "huang-nonbox"
    pub paper: String,
    pub title: String,
    /// the full reference (authors, title, venue, year) the report cites
    #[serde(default)]
    pub citation: Option<String>,
    /// figures for the paper's report page (characteristic rings, spectra)
    #[serde(default, rename = "figure")]
    pub figures: Vec<FigureSpec>,
    /// admissible-interval figures (`subdlab sweep --plot`) for the report page
    #[serde(default, rename = "sweep")]
    pub sweeps: Vec<SweepFigureSpec>,
    #[serde(default, rename = "claim")]
    pub claims: Vec<Claim>,
}

/// A sweep figure of the report: `scheme` over `valences` ("A..B") and one
/// swept parameter `param` ("NAME=START:END:STEP"), with reference `bounds`
/// (expressions in n) drawn across the rows and a `caption` saying what they are.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFigureSpec {
    pub scheme: String,
    pub valences: String,
    pub param: String,
    #[serde(default)]
    pub params: BTreeMap<String, String>,
    #[serde(default)]
    pub charmap: bool,
    /// levels and resolution of the characteristic-map check (default: `subdlab charmap`'s)
    #[serde(default)]
    pub levels: Option<usize>,
    #[serde(default)]
    pub resolution: Option<usize>,
    #[serde(default)]
    pub bounds: Vec<String>,
    pub caption: String,
}

/// A figure of the report: the characteristic rings of `scheme` at `valence`
/// and its leading eigenvalue moduli against the valence (3..`up_to`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FigureSpec {
    pub scheme: String,
    pub valence: usize,
    #[serde(default)]
    pub params: BTreeMap<String, String>,
    #[serde(default = "default_up_to")]
    pub up_to: usize,
}

fn default_up_to() -> usize {
    20
}

// (no deny_unknown_fields below: serde cannot combine it with `flatten`)
#[derive(Clone, Debug, Deserialize)]
pub struct Claim {
    pub id: String,
    /// section, equation or figure; required in the built-in registry
    /// (every claim there cites its place in the paper), optional in a
    /// user's claim file, where it may mean nothing
    #[serde(default)]
    pub location: String,
    /// the statement as printed
    pub statement: String,
    /// the convention the statement uses (e.g. which α)
    #[serde(default)]
    pub convention: Option<String>,
    /// the verdict this registry expects (regression-tested for the built-in
    /// papers; a change means the tool's computation changed)
    #[serde(default)]
    pub expected: Option<Verdict>,
    /// set where subdlab's rules were themselves built from the statement (a
    /// reconstruction the paper does not print, or a weight prescribed by the
    /// stated formula): says what was built from it and what the verdict
    /// still tests, so the verdict is never read as an independent check
    #[serde(default)]
    pub by_construction: Option<String>,
    #[serde(flatten)]
    pub check: Check,
}
