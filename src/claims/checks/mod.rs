//! The check kinds: one file per kind, each a type read from the claim's
//! keys and an implementation of [`CheckKind`] (`claims::check_kind`), and
//! one table ([`check_kinds!`] below) that maps a claim's `check = "KIND"`
//! to its type. The table makes the [`Check`] enum (what a claim holds), the
//! keys each kind reads ([`CHECK_KEYS`]) and the dispatch to the kind's
//! `validate` and `evaluate`.
//!
//! Adding a check kind: write `checks/KIND.rs` (the type, deriving
//! `Deserialize`, with `#[serde(flatten)] subject: Subject` when it
//! analyses a scheme, and its `impl CheckKind`), declare it below and add
//! its line to the table; an example claim file `examples/claims/KIND.toml`
//! and a negative control go with it (tests/hardening.rs,
//! tests/negative_controls.rs).

pub mod builtin;
pub mod central_shape;
pub mod characteristic_map;
pub mod curvature;
pub mod eigenvalues;
pub mod identity;
pub mod inequality;
pub mod invariant_set;
pub mod lattice_matrix;
pub mod limit_stencil;
pub mod matrix_eigenvalues;
pub mod nonnegative_spectrum;
pub mod parameter_range;
pub mod size;
pub mod spectral_c1;
pub mod subdominant;
pub mod tangent_stencils;

use serde::Deserialize;

use crate::claims::check_kind::CheckKind;
use crate::claims::common::spectra::Cache;
use crate::claims::verdict::Finding;
use crate::error::Error;

/// The table of check kinds: `"kind" => Variant(Type)`, one line per kind.
/// Makes the `Check` enum (serde-tagged by `check`, plus `Malformed` for a
/// claim that could not be read), [`CHECK_KEYS`], [`TAKES_SUBJECT`] and
/// the dispatch [`Check::validate`] / [`Check::evaluate`].
macro_rules! check_kinds {
    ($($name:literal => $variant:ident($kind:ty)),+ $(,)?) => {
        /// How a claim is evaluated: one variant per check kind.
        #[derive(Clone, Debug, Deserialize)]
        #[serde(tag = "check")]
        pub enum Check {
            $(
                #[serde(rename = $name)]
                $variant($kind),
            )+
            /// A claim that could not be read (unknown key, missing field, wrong
            /// type): its verdict is ERROR with this message; never in a file.
            #[serde(skip)]
            Malformed(String),
        }

        /// The keys each check kind reads, besides the common ones
        /// (`parse::COMMON_KEYS`, and the subject's where the kind takes
        /// one); anything else in a claim is an error naming its line.
        pub const CHECK_KEYS: &[(&str, &[&str])] = &[$(($name, <$kind as CheckKind>::KEYS)),+];

        /// Whether each check kind analyses a scheme (reads the subject's keys).
        pub const TAKES_SUBJECT: &[(&str, bool)] = &[$(($name, <$kind as CheckKind>::TAKES_SUBJECT)),+];

        impl Check {
            /// What a claim must satisfy before anything is computed (the
            /// kind's [`CheckKind::validate`]): an error here makes the
            /// claim an ERROR.
            pub fn validate(&self) -> Result<(), Error> {
                match self {
                    $(Check::$variant(c) => c.validate(),)+
                    Check::Malformed(_) => Ok(()),
                }
            }

            /// The kind's [`CheckKind::evaluate`].
            pub fn evaluate(&self, cache: &mut Cache) -> Result<Finding, Error> {
                match self {
                    $(Check::$variant(c) => c.evaluate(cache),)+
                    // the message names the claim file and line
                    Check::Malformed(m) => Err(Error::File(m.clone())),
                }
            }
        }
    };
}

check_kinds! {
    "eigenvalues" => Eigenvalues(eigenvalues::Eigenvalues),
    "subdominant" => Subdominant(subdominant::Subdominant),
    "size" => Size(size::Size),
    "invariant-set" => InvariantSet(invariant_set::InvariantSet),
    "limit-stencil" => LimitStencil(limit_stencil::LimitStencil),
    "tangent-stencils" => TangentStencils(tangent_stencils::TangentStencils),
    "inequality" => Inequality(inequality::Inequality),
    "nonnegative-spectrum" => NonnegativeSpectrum(nonnegative_spectrum::NonnegativeSpectrum),
    "characteristic-map" => CharacteristicMap(characteristic_map::CharacteristicMap),
    "spectral-c1" => SpectralC1(spectral_c1::SpectralC1),
    "curvature" => Curvature(curvature::CurvatureCheck),
    "central-shape" => CentralShape(central_shape::CentralShapeCheck),
    "identity" => Identity(identity::Identity),
    "matrix-eigenvalues" => MatrixEigenvalues(matrix_eigenvalues::MatrixEigenvalues),
    "lattice-matrix" => LatticeMatrix(lattice_matrix::LatticeMatrix),
    "parameter-range" => ParameterRange(parameter_range::ParameterRange),
    "builtin" => Builtin(builtin::Builtin),
}
