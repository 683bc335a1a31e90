//! The chart's categories and every threshold they use, in one place.
//!
//! A cell is one input q_{t,θ} at one step m (or m = ∞, the central shape).
//! Its measures are the fraction of ring area whose fitted Gaussian
//! curvature has the sign of t ([`super::measure`]), the relative residual of
//! the best fit h ≈ c·q∘χ + affine, and g = |ν*|/λ² with the Jordan flag of
//! ν*. In order:
//!
//! 1. **flat** (m = ∞ only): g < 1 − [`G_TOL`] with no Jordan chain reaching
//!    g = 1: the curvature of this input tends to zero at the centre (also
//!    when no component below λ shows on the ring at all: g = 0);
//! 2. **correct shape**: residual ≤ [`CORRECT_RESIDUAL`] and (t ≠ 0) sign
//!    fraction ≥ [`RIGHT_SIGN`]: the input shape is reproduced up to a factor
//!    and an affine part;
//! 3. t = 0 otherwise: **degenerate** (a parabolic input has no sign of K to
//!    keep);
//! 4. **right sign**: sign fraction ≥ [`RIGHT_SIGN`];
//! 5. **wrong sign**: sign fraction ≤ [`WRONG_SIGN`];
//! 6. **mixed sign**: in between.
//!
//! The **divergent** overlay (every m of the input): g > 1 + [`G_TOL`], or a
//! Jordan chain of ν* shows on the ring with g ≥ 1 − [`G_TOL`] (curvature
//! ~ m·g^m; a chain below λ² still decays and is only flagged `jordan`).

use serde::Serialize;

/// |ν*|/λ² within this relative tolerance of 1 counts as 1 (the curvature
/// analysis's tolerance for |μ| against λ²).
pub const G_TOL: f64 = crate::curvature::EIG_TOL;
/// Largest relative residual of h ≈ c·q∘χ + affine that counts as the input
/// shape reproduced (the C² test's tolerance for a quadratic fit).
pub const CORRECT_RESIDUAL: f64 = crate::curvature::C2_TOL;
/// Smallest fraction of ring area with sign K = sign t for "right sign".
pub const RIGHT_SIGN: f64 = 0.99;
/// Largest fraction of ring area with sign K = sign t for "wrong sign".
pub const WRONG_SIGN: f64 = 0.01;

/// The deflated iteration's growth rate below 1 − RATE_TOL reads as flat
/// (`super::Iterated`): the rate estimates g from two finite steps, so it
/// is held to a looser tolerance than g itself; a g in between leaves the
/// routes disagreeing, and a claim built on them undecided.
pub const RATE_TOL: f64 = 1e-3;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Category {
    Correct,
    RightSign,
    Flat,
    Degenerate,
    MixedSign,
    WrongSign,
}

impl Category {
    pub const ALL: [Category; 6] = [
        Category::Correct,
        Category::RightSign,
        Category::Flat,
        Category::Degenerate,
        Category::MixedSign,
        Category::WrongSign,
    ];
    pub fn name(self) -> &'static str {
        match self {
            Category::Correct => "correct",
            Category::RightSign => "right-sign",
            Category::Flat => "flat",
            Category::Degenerate => "degenerate",
            Category::MixedSign => "mixed-sign",
            Category::WrongSign => "wrong-sign",
        }
    }
    /// One letter for the text chart.
    pub fn letter(self) -> char {
        match self {
            Category::Correct => 'C',
            Category::RightSign => 'R',
            Category::Flat => 'F',
            Category::Degenerate => 'D',
            Category::MixedSign => 'M',
            Category::WrongSign => 'W',
        }
    }
}

/// The divergent overlay (see the module documentation).
pub fn divergent(g: f64, jordan: bool) -> bool {
    g > 1.0 + G_TOL || (jordan && g >= 1.0 - G_TOL)
}

/// The input's curvature tends to zero (m = ∞ only).
pub fn flat(g: f64, jordan: bool) -> bool {
    g < 1.0 - G_TOL && !divergent(g, jordan)
}

/// The category of one cell; `central` for m = ∞.
pub fn categorise(t: f64, central: bool, g: f64, jordan: bool, sign_fraction: f64, residual: f64) -> Category {
    if central && flat(g, jordan) {
        return Category::Flat;
    }
    let reproduced = residual <= CORRECT_RESIDUAL;
    if t == 0.0 {
        return if reproduced { Category::Correct } else { Category::Degenerate };
    }
    if reproduced && sign_fraction >= RIGHT_SIGN {
        Category::Correct
    } else if sign_fraction >= RIGHT_SIGN {
        Category::RightSign
    } else if sign_fraction <= WRONG_SIGN {
        Category::WrongSign
    } else {
        Category::MixedSign
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn categories_follow_the_thresholds() {
        assert_eq!(categorise(0.5, true, 0.5, false, 1.0, 0.0), Category::Flat);
        // flat applies to the central shape only
        assert_eq!(categorise(0.5, false, 0.5, false, 1.0, 0.0), Category::Correct);
        assert_eq!(categorise(0.5, true, 1.0, false, 1.0, 0.1), Category::RightSign);
        assert_eq!(categorise(0.5, true, 1.0, false, 0.0, 0.1), Category::WrongSign);
        assert_eq!(categorise(0.5, true, 1.0, false, 0.5, 0.1), Category::MixedSign);
        assert_eq!(categorise(0.0, true, 1.0, false, 0.0, 0.1), Category::Degenerate);
        assert_eq!(categorise(0.0, true, 1.0, false, 0.0, 0.0), Category::Correct);
        // a Jordan chain at g = 1 diverges, below 1 it is flat
        assert!(divergent(1.0, true) && !divergent(1.0, false) && divergent(1.2, false));
        assert!(flat(0.9, true) && !flat(1.0, true));
    }
}
