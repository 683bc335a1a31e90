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
}

impl Configuration {
    pub fn valence(&self) -> usize {
        self.sectors.len()
    }

    /// Smallest p such that rotating by p sectors maps the configuration onto
    /// itself; the rotation group then has order n / p.
    pub fn symmetry_period(&self) -> usize {
        let n = self.sectors.len();
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
