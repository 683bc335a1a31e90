//! The kind of point an analysis is centred on.

/// What kind of point the analysis is centred on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CentreKind {
    /// an extraordinary vertex (Catmull–Clark, Loop, 4-3, ...)
    Vertex,
    /// an extraordinary face (Doo–Sabin, ...)
    Face,
    /// an extraordinary face with an extra control point at its centre
    /// (point-augmented bi-2 subdivision, PGS)
    AugmentedFace,
    /// a pole: a vertex surrounded by triangles, rings of quads outside
    /// (polar bi-2 subdivision)
    Polar,
}

impl CentreKind {
    /// Whether the analysis is centred on a face (its corners form ring 0).
    pub fn is_face_centred(self) -> bool {
        matches!(self, CentreKind::Face | CentreKind::AugmentedFace)
    }
    /// Vertex rings (beyond ring 0) whose faces carry the first ring of the
    /// limit surface. Normally the faces touching ring 0. In a polar layout a
    /// bi-2 ring of patches spans three rows of control points, and the first
    /// ring that is not degenerate at the pole spans rows 1 to 3, i.e. the
    /// faces touching rings 0 to 2.
    pub fn first_ring_depth(self) -> usize {
        match self {
            CentreKind::Polar => 2,
            CentreKind::Vertex | CentreKind::Face | CentreKind::AugmentedFace => 0,
        }
    }
}
