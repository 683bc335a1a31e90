//! Sector charts: integer lattice coordinates for the vertices of a
//! neighbourhood around an extraordinary point.
//!
//! Sector `s` is a wedge of a regular lattice (a quadrant of Z^2 for quad
//! sectors, a 60-degree wedge of the triangular lattice in skew coordinates for
//! triangle sectors). The wedge owns the points with i > 0, j >= 0 (the spoke
//! i-axis belongs to it; the j-axis is the i-axis of sector s+1). The centre
//! (0, 0) belongs to every chart.
//!
//! Why: refinement maps lattice points to lattice points (a vertex at p goes to
//! 2p, an edge midpoint to p + q, ...). Giving the refined mesh coordinates in the
//! refined lattice therefore identifies "the same" vertex before and after a
//! step purely from topology, which is what extracting the local subdivision
//! matrix needs, for any scheme and any face sequence.

use serde::Serialize;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum SectorKind {
    Quad,
    Tri,
}

impl SectorKind {
    pub fn letter(self) -> char {
        match self {
            SectorKind::Quad => 'Q',
            SectorKind::Tri => 'T',
        }
    }
}

/// Canonical lattice coordinates of a vertex: sector and (i, j) in that sector's
/// chart, normalised so that the point lies in the sector's own wedge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LatticeCoord {
    pub sector: usize,
    pub i: i64,
    pub j: i64,
}

impl LatticeCoord {
    pub const CENTRE: LatticeCoord = LatticeCoord { sector: 0, i: 0, j: 0 };
    pub fn is_centre(&self) -> bool {
        self.i == 0 && self.j == 0
    }
}

/// Lattice charts of a mesh: one coordinate per vertex and one chart (sector)
/// per face. `face_sector[f] == None` marks a face centred on the origin (the
/// central face of a face-centred neighbourhood).
#[derive(Clone, Debug)]
pub struct Chart {
    pub sector_kinds: Vec<SectorKind>,
    /// coordinates are the mesh's own lattice units times `scale`; 1 except
    /// half-way through a sqrt(3) analysis step (see `topology::sqrt3_split`)
    pub scale: i64,
    pub vertex_coords: Vec<LatticeCoord>,
    pub face_sector: Vec<Option<usize>>,
}

impl Chart {
    pub fn sectors(&self) -> usize {
        self.sector_kinds.len()
    }

    /// Chart s coordinates of a point that lies across the j-axis of sector s,
    /// re-expressed in sector s+1 (the inverse of [`Self::step_back`]).
    fn step_forward(&self, s: usize, i: i64, j: i64) -> (i64, i64) {
        match self.sector_kinds[s] {
            // quarter turn: the j-axis of chart s is the i-axis of chart s+1
            SectorKind::Quad => (j, -i),
            // sixty-degree turn in skew coordinates
            SectorKind::Tri => (i + j, -i),
        }
    }

    fn step_back(&self, s: usize, a: i64, b: i64) -> (i64, i64) {
        let prev = (s + self.sectors() - 1) % self.sectors();
        match self.sector_kinds[prev] {
            SectorKind::Quad => (-b, a),
            SectorKind::Tri => (-b, a + b),
        }
    }

    /// Normalise chart coordinates (sector s, i, j) to the owning sector.
    /// Returns `None` for points that are not near any wedge (never produced by
    /// faces that lie in adjacent sectors).
    pub fn canonical(&self, s: usize, i: i64, j: i64) -> Option<LatticeCoord> {
        let n = self.sectors();
        let (mut s, mut i, mut j) = (s % n, i, j);
        for _ in 0..=2 * n {
            if i == 0 && j == 0 {
                return Some(LatticeCoord::CENTRE);
            }
            if i > 0 && j >= 0 {
                return Some(LatticeCoord { sector: s, i, j });
            }
            if i <= 0 && j > 0 {
                let (a, b) = self.step_forward(s, i, j);
                s = (s + 1) % n;
                i = a;
                j = b;
            } else if j < 0 && i >= 0 {
                let (a, b) = self.step_back(s, i, j);
                s = (s + n - 1) % n;
                i = a;
                j = b;
            } else {
                return None; // i < 0 and j <= 0: behind the centre, ambiguous for n != 4
            }
        }
        None
    }

    /// Coordinates of a canonical point in the chart of sector `target`, going
    /// the short way round.
    pub fn in_chart(&self, c: LatticeCoord, target: usize) -> (i64, i64) {
        if c.is_centre() {
            return (0, 0);
        }
        let n = self.sectors();
        let fwd = (target + n - c.sector) % n;
        let (mut s, mut i, mut j) = (c.sector, c.i, c.j);
        if fwd <= n / 2 {
            for _ in 0..fwd {
                // a point of chart s seen from chart s+1 (the same map that moves
                // points across the j-axis of chart s)
                let (a, b) = self.step_forward(s, i, j);
                s = (s + 1) % n;
                i = a;
                j = b;
            }
        } else {
            for _ in 0..(n - fwd) {
                let (a, b) = self.step_back(s, i, j);
                s = (s + n - 1) % n;
                i = a;
                j = b;
            }
        }
        (i, j)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chart(kinds: Vec<SectorKind>) -> Chart {
        Chart { sector_kinds: kinds, scale: 1, vertex_coords: vec![], face_sector: vec![] }
    }

    #[test]
    fn spoke_points_belong_to_the_next_sector() {
        let c = chart(vec![SectorKind::Quad; 5]);
        assert_eq!(c.canonical(0, 0, 3), Some(LatticeCoord { sector: 1, i: 3, j: 0 }));
        assert_eq!(c.canonical(4, 0, 2), Some(LatticeCoord { sector: 0, i: 2, j: 0 }));
        assert_eq!(c.canonical(1, 2, -1), Some(LatticeCoord { sector: 0, i: 1, j: 2 }));
    }

    #[test]
    fn in_chart_inverts_canonical() {
        for kinds in [vec![SectorKind::Quad; 5], vec![SectorKind::Tri; 7]] {
            let c = chart(kinds);
            for s in 0..c.sectors() {
                for (i, j) in [(1, 0), (2, 1), (1, 3), (3, 3)] {
                    let p = LatticeCoord { sector: s, i, j };
                    for t in [s, (s + 1) % c.sectors(), (s + c.sectors() - 1) % c.sectors()] {
                        let (a, b) = c.in_chart(p, t);
                        assert_eq!(c.canonical(t, a, b), Some(p), "{p:?} via chart {t}");
                    }
                }
            }
        }
    }
}
