//! The chart a split carries from the old neighbourhood to the refined one.

use crate::error::Error;
use crate::mesh::{Chart, LatticeCoord, PolyMesh};

/// Builds the chart of a refined mesh: new vertex coordinates from the old
/// chart, new face sectors as given.
pub(crate) struct ChartBuilder<'a> {
    pub old: &'a Chart,
    pub coords: Vec<LatticeCoord>,
    pub face_sector: Vec<Option<usize>>,
    pub ok: bool,
}

impl<'a> ChartBuilder<'a> {
    pub fn new(old: &'a Chart) -> Self {
        ChartBuilder { old, coords: Vec::new(), face_sector: Vec::new(), ok: true }
    }
    /// Record a new vertex at chart coordinates (sector, i, j) of the refined lattice.
    pub fn push(&mut self, s: usize, i: i64, j: i64) {
        match self.old.canonical(s, i, j) {
            Some(c) => self.coords.push(c),
            None => {
                self.ok = false;
                self.coords.push(LatticeCoord::CENTRE);
            }
        }
    }
    pub fn finish(self, scale: i64) -> Option<Chart> {
        self.ok.then(|| Chart {
            sector_kinds: self.old.sector_kinds.clone(),
            scale,
            vertex_coords: self.coords,
            face_sector: self.face_sector,
        })
    }
    /// A new vertex at `factor` times the old vertex v's coordinates (the
    /// vertex point of a refinement that scales the lattice by `factor`).
    pub fn push_scaled(&mut self, v: usize, factor: i64) {
        let c = self.old.vertex_coords[v];
        self.push(c.sector, factor * c.i, factor * c.j);
    }
    /// A new vertex at wa·A + wb·B on the old edge (a, b), in the chart of a
    /// face holding the edge (a midpoint is 1·A + 1·B in the doubled lattice).
    pub fn push_on_edge(&mut self, mesh: &PolyMesh, a: usize, b: usize, wa: i64, wb: i64) -> Result<(), Error> {
        let (f, _) = mesh
            .half_edge(a, b)
            .or_else(|| mesh.half_edge(b, a))
            .ok_or_else(|| Error::Input("dangling edge".into()))?;
        let s = self.face_chart(self.old.face_sector[f], a);
        let (pa, pb) =
            (self.old.in_chart(self.old.vertex_coords[a], s), self.old.in_chart(self.old.vertex_coords[b], s));
        self.push(s, wa * pa.0 + wb * pb.0, wa * pa.1 + wb * pb.1);
        Ok(())
    }
    /// Sector in which to express an old face: its own, or for a central face
    /// the sector of the given corner.
    pub fn face_chart(&self, old_face_sector: Option<usize>, corner_vertex: usize) -> usize {
        old_face_sector.unwrap_or(self.old.vertex_coords[corner_vertex].sector)
    }
}
