//! The registry of refinement hosts: the `hosts!` table mapping each
//! `sdc::Host` variant to the unit its host file defines. Kept out of
//! `topology/mod.rs` so that the host files, which import shared code, never
//! import the module that imports them.

use crate::sdc::host::{Host, RefinementHost, Registry};

/// The registry: one line per host, `Variant => crate::topology::file::Unit`
/// (the full path, so that the line alone names the host file), mapping the
/// `sdc::Host` variant to the unit its file defines. The generated match is
/// exhaustive, so a variant added to `sdc::Host` without its line here does
/// not compile.
macro_rules! hosts {
    ($($variant:ident => $unit:path,)*) => {
        impl Registry for Host {
            fn unit(self) -> &'static dyn RefinementHost {
                match self {
                    $(Host::$variant => &$unit,)*
                }
            }
        }
    };
}

hosts! {
    PrimalQuad => crate::topology::primal_quad::PrimalQuad,
    PrimalTriangle => crate::topology::primal_triangle::PrimalTriangle,
    MixedQuadTriangle => crate::topology::mixed_quad_triangle::MixedQuadTriangle,
    Fcv => crate::topology::fcv_split::FcvSplit,
    Dual => crate::topology::dual_split::DualSplit,
    Sqrt3 => crate::topology::sqrt3_split::Sqrt3Split,
    Ternary => crate::topology::ternary_split::TernarySplit,
    AugmentedDual => crate::topology::augmented_dual::AugmentedDual,
    Polar => crate::topology::polar_split::PolarSplit,
}
