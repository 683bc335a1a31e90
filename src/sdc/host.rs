//! The refinement host a scheme runs on, named: which connectivity one
//! subdivision step produces. The hosts themselves (the operators that build
//! the refined mesh) live in `crate::topology`; a scheme only names its host,
//! as OpenSubdiv's Sdc names a split type without knowing the refiner.

/// How triangles are split by a primal operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriangleSplit {
    /// 1 -> 4 triangles, no face point (Loop, the triangle part of 4-3)
    FourTriangles,
    /// a face point and 3 quads (Catmull–Clark on triangles)
    FacePointQuads,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Topology {
    /// vertex, edge and (for quads and larger) face points; each face split
    /// into quads around its face point, triangles as `TriangleSplit` says
    PrimalSplit(TriangleSplit),
    /// one new vertex per face corner; F-, E- and V-faces (Doo–Sabin)
    Dual,
    /// a new vertex in every triangle, old edges flipped (Kobbelt's sqrt(3))
    Sqrt3,
    /// quads around each face's control vertex, a new FCV per new quad (non-box)
    FcvSplit,
    /// every quad split into 3 x 3 quads (ternary primal bi-2, TPS)
    TernarySplit,
    /// the dual split plus a central point per non-quad (or already augmented)
    /// face (point-augmented bi-2, PGS)
    AugmentedDual,
    /// radial-only binary split of polar nets (polar bi-2)
    PolarSplit,
}

impl Topology {
    /// Refinements in one analysis step: the number after which the refined
    /// lattice is the old one scaled, without rotation, so that vertices can be
    /// matched by lattice coordinates.
    pub fn steps_per_analysis(&self) -> usize {
        // exhaustive on purpose: a new host must say how its lattice realigns
        match self {
            Topology::Sqrt3 => 2,
            Topology::PrimalSplit(_)
            | Topology::Dual
            | Topology::FcvSplit
            | Topology::TernarySplit
            | Topology::AugmentedDual
            | Topology::PolarSplit => 1,
        }
    }

    /// How many faces one face becomes in one refinement, away from
    /// extraordinary points and boundaries: what the cost of refining a net
    /// grows by per level. Dual hosts make a face per old face, edge and
    /// vertex (F + E + V = 4F on a closed quad net).
    pub fn faces_per_face(&self) -> usize {
        match self {
            Topology::PrimalSplit(_) | Topology::Dual | Topology::FcvSplit | Topology::AugmentedDual => 4,
            Topology::Sqrt3 => 3,
            Topology::TernarySplit => 9,
            // radial-only: each ring of faces becomes two
            Topology::PolarSplit => 2,
        }
    }
}
