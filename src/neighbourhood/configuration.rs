//! A configuration: what sits around the centre (valence, face types, centre kind).

use crate::mesh::SectorKind;
use crate::schemes::{CentreKind, Scheme};

/// Largest valence accepted: the analysis neighbourhood of valence n has O(n)
/// vertices and is refined up to three times during discovery; beyond this the
/// work is dominated by memory traffic for no research value.
pub const MAX_VALENCE: usize = 1000;

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Configuration {
    pub centre: CentreKind,
    /// face type of each sector around the centre, counter-clockwise
    pub sectors: Vec<SectorKind>,
    /// every face carries a face control vertex (non-box subdivision)
    pub face_control: bool,
}

impl Configuration {
    /// The scheme's regular configuration of valence n.
    pub fn regular(scheme: &dyn Scheme, n: usize) -> Result<Self, String> {
        check_valence(n)?;
        Ok(Configuration {
            centre: scheme.centre_kind(),
            sectors: vec![scheme.sector_kind(); n],
            face_control: scheme.face_control(),
        })
    }

    pub fn valence(&self) -> usize {
        self.sectors.len()
    }

    /// Smallest p such that rotating by p sectors maps the configuration onto
    /// itself; the rotation group then has order n / p.
    pub fn symmetry_period(&self) -> usize {
        let n = self.sectors.len();
        (1..=n).find(|&p| n % p == 0 && (0..n).all(|s| self.sectors[s] == self.sectors[(s + p) % n])).unwrap_or(n)
    }

    pub fn face_sequence(&self) -> String {
        self.sectors.iter().map(|k| k.letter()).collect()
    }
}

pub fn check_valence(n: usize) -> Result<(), String> {
    if n < 3 {
        return Err(format!("valence {n} is below 3; extraordinary points have valence 3 or more"));
    }
    if n > MAX_VALENCE {
        return Err(format!("valence {n} is above the supported maximum {MAX_VALENCE}"));
    }
    Ok(())
}
