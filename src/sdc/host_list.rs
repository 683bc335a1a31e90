//! The identities of the refinement hosts: the variant list of [`Host`] and
//! [`HOSTS`]. Below everything else about hosts (their declared rules, the
//! gatherers' results, the `RefinementHost` interface in `sdc::host`), all of
//! which name a host.

/// Every refinement host, by name: the registry's list of identities. Adding
/// a host adds one variant here and one line to the table in
/// `crate::topology` (the compiler asks for the latter).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Host {
    /// primal split, every face into quads around a face point (Catmull–Clark)
    PrimalQuad,
    /// primal split of triangles into 4 (Loop, butterfly)
    PrimalTriangle,
    /// primal split of quads and triangles together (4-3 subdivision)
    MixedQuadTriangle,
    /// quads around face control vertices (non-box)
    Fcv,
    /// dual split (Doo–Sabin)
    Dual,
    /// Kobbelt's sqrt(3) split
    Sqrt3,
    /// ternary quad split (TPS)
    Ternary,
    /// dual split plus central points (PGS)
    AugmentedDual,
    /// radial split of polar nets (polar bi-2)
    Polar,
}

/// Every host, in the order scheme-file documentation lists them.
pub const HOSTS: [Host; 9] = [
    Host::PrimalQuad,
    Host::PrimalTriangle,
    Host::MixedQuadTriangle,
    Host::Fcv,
    Host::Dual,
    Host::Sqrt3,
    Host::Ternary,
    Host::AugmentedDual,
    Host::Polar,
];
