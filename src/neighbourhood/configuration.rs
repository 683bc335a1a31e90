//! A configuration: what sits around the centre (valence, face types, centre kind).
//! A scheme's configurations (`Configuration::regular`, `with_faces`) are
//! built in `neighbourhood::valence_limit`, which checks the valence against
//! an estimate measured by discovery.

use crate::error::Error;
use crate::mesh::SectorKind;
use crate::sdc::{CentreKind, Scheme};

/// Largest valence accepted at all, whatever the scheme: a configuration
/// lists its sectors, and well below this every built-in scheme's estimate
/// exceeds the memory budget
/// ([`check_valence_for`](super::valence_limit::check_valence_for) refuses
/// by the estimate; this bound only keeps absurd numbers from being
/// allocated, e.g. by a valence range).
pub const MAX_VALENCE: usize = 10_000_000;

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Configuration {
    pub centre: CentreKind,
    /// face type of each sector around the centre, counter-clockwise
    pub sectors: Vec<SectorKind>,
    /// every face carries a face control vertex (non-box subdivision)
    pub face_control: bool,
    /// sharp edges through the centre and a corner tag (`mesh::tags`): a
    /// boundary, corner, crease or dart vertex; `None` for the interior
    /// extraordinary points of every scheme's regular configurations
    pub tagging: Option<Tagging>,
}

/// What is tagged at a vertex-centred configuration (Hoppe et al. 1994;
/// Biermann–Levin–Zorin 2000): which rays from the centre are sharp edges
/// and whether the centre is a corner. A tagged configuration has no
/// rotation symmetry (the local matrix is analysed whole).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Tagging {
    /// the centre on a boundary: the k sectors run from the boundary ray of
    /// sector 0 counter-clockwise to the boundary ray after sector k − 1,
    /// and nothing lies beyond (the sectors do not close around the centre)
    Boundary,
    /// a boundary vertex tagged as a corner (its rule keeps it in place)
    Corner,
    /// an interior crease: the sectors close around the centre, and the
    /// rays of sector 0 and of sector `at` are sharp (`at` sectors on one
    /// side of the crease, the rest on the other)
    Crease { at: usize },
    /// an interior dart: the ray of sector 0 alone is sharp
    Dart,
}

impl Tagging {
    /// Parse `boundary`, `corner`, `dart` or `crease:K` (sharp rays at
    /// sectors 0 and K).
    pub fn parse(text: &str) -> Result<Tagging, Error> {
        match text {
            "boundary" => Ok(Tagging::Boundary),
            "corner" => Ok(Tagging::Corner),
            "dart" => Ok(Tagging::Dart),
            _ => match text.strip_prefix("crease:").map(str::parse::<usize>) {
                Some(Ok(at)) => Ok(Tagging::Crease { at }),
                _ => Err(Error::Input(format!(
                    "--tag '{}': use boundary, corner, dart or crease:K (sharp rays at sectors 0 and K)",
                    text
                ))),
            },
        }
    }
    /// Whether the sectors stop at the boundary instead of closing around the centre.
    pub fn is_open(self) -> bool {
        matches!(self, Tagging::Boundary | Tagging::Corner)
    }
    /// The sectors whose first ray (their i-axis) is a sharp edge, for `n`
    /// sectors: sector n is the ray after the last sector of an open fan.
    pub fn sharp_rays(self, n: usize) -> Vec<usize> {
        match self {
            Tagging::Boundary | Tagging::Corner => vec![0, n],
            Tagging::Crease { at } => vec![0, at],
            Tagging::Dart => vec![0],
        }
    }
    pub fn name(self) -> String {
        match self {
            Tagging::Boundary => "boundary".into(),
            Tagging::Corner => "corner".into(),
            Tagging::Crease { at } => format!("crease:{at}"),
            Tagging::Dart => "dart".into(),
        }
    }
}

impl Configuration {
    pub fn valence(&self) -> usize {
        self.sectors.len()
    }

    /// Smallest p such that rotating by p sectors maps the configuration onto
    /// itself; the rotation group then has order n / p. A tagged
    /// configuration has none: its period is [`Self::chart_sectors`].
    pub fn symmetry_period(&self) -> usize {
        let n = self.sectors.len();
        if self.tagging.is_some() {
            // sharp rays and corners are not rotated onto each other: the
            // period is the whole chart (an open fan's empty sector included)
            return self.chart_sectors();
        }
        (1..=n)
            .find(|&p| n.is_multiple_of(p) && (0..n).all(|s| self.sectors[s] == self.sectors[(s + p) % n]))
            .unwrap_or(n)
    }

    /// The rotation period of the configuration under `scheme`'s rules:
    /// [`Self::symmetry_period`], or the valence (no rotation symmetry) for
    /// rules that are not rotation symmetric, whatever the configuration.
    pub fn rotation_period(&self, scheme: &dyn Scheme) -> usize {
        if scheme.rotation_symmetric() {
            self.symmetry_period()
        } else {
            self.valence()
        }
    }

    pub fn face_sequence(&self) -> String {
        self.sectors.iter().map(|k| k.letter()).collect()
    }

    /// Sectors of the configuration's lattice charts: an open (boundary or
    /// corner) fan of k sectors has k + 1 more, empty, after its last, so
    /// that its last ray is a ray of its own (not sector 0's) and the
    /// charts' "short way round" between two of its sectors never crosses
    /// the gap (`Chart::in_chart` goes forward when that is at most half
    /// the chart: with one empty sector, k = 1 would see its last ray from
    /// the wrong side).
    pub fn chart_sectors(&self) -> usize {
        let n = self.sectors.len();
        if self.tagging.is_some_and(Tagging::is_open) {
            2 * n + 1
        } else {
            n
        }
    }
}

/// The checks of a tagged configuration of `n` sectors: an open fan needs a
/// sector (k >= 1; k = 2 quads or 3 triangles is a regular boundary), a
/// closed one three, a crease ray inside the fan on neither sector 0's ray.
pub fn check_tagged(n: usize, tagging: Tagging) -> Result<(), Error> {
    let least = if tagging.is_open() { 1 } else { 3 };
    if n < least {
        return Err(Error::Input(format!(
            "a {} configuration needs at least {least} sector{} (got {n})",
            tagging.name(),
            if least == 1 { "" } else { "s" }
        )));
    }
    if n > MAX_VALENCE {
        return Err(Error::Input(format!("{n} sectors is above the supported maximum {MAX_VALENCE}")));
    }
    if let Tagging::Crease { at } = tagging {
        if at == 0 || at >= n {
            return Err(Error::Input(format!(
                "crease:{at}: the second sharp ray must be that of a sector 1..{} of the {n}",
                n - 1
            )));
        }
    }
    Ok(())
}

pub fn check_valence(n: usize) -> Result<(), Error> {
    if n < 3 {
        return Err(Error::Input(format!("valence {n} is below 3; extraordinary points have valence 3 or more")));
    }
    if n > MAX_VALENCE {
        return Err(Error::Input(format!(
            "valence {n} is above the supported maximum {MAX_VALENCE} (no scheme's analysis fits in memory there)"
        )));
    }
    Ok(())
}
