//! The regular part of Huang's non-box scheme, derived from the definition of
//! the four-directional S_3^1 spline and not from the scheme's rules (nor
//! from the paper's printed mask, eq. (3), which fails its own refinement
//! condition: claim `nonbox.vector-mask`).
//!
//! **Convention (centred, primal).** Level-0 V-vertices sit at Z² and face
//! control vertices (FCVs) at the face centres (Z + ½)². The limit is
//! f = Σ_V λ_V B_V(· − V) + Σ_F λ_F B_F(· − F) with
//! B_V = φ_□ * χ and B_F = φ_◇ * χ, where χ is the indicator of the centred
//! unit square [−½, ½]², φ_□(x) = max(0, 1 − 2 max(|x₁|, |x₂|)) the hat over
//! the unit square centred at the V-vertex (linear on the four triangles its
//! diagonals cut) and φ_◇(x) = max(0, 1 − |x₁| − |x₂|) the hat over the
//! diamond centred at the FCV. The two kinds of hats are the nodal basis of
//! the piecewise linears on the four-directional triangulation T with lines
//! x₁, x₂ ∈ Z + ½ and x₁ ± x₂ ∈ Z (the FCVs its valence-8 vertices, the
//! V-vertices its valence-4 ones). The paper's wording pairs the square hat
//! with the FCV; the rules of section 3.2.2 say otherwise: that pairing
//! gives, for the new point of a V–FCV edge, weight ½ on the V-vertex, where
//! the NFCV rule puts ½ on the FCV (the pairing here reproduces all four
//! rules; `tests/certify_nonbox.rs` checks the derivation independently).
//!
//! **Refinement.** T is refined by T₁ = T/2 + (¼, ¼), whose lines are
//! x₁, x₂, x₁ ± x₂ ∈ Z/2: each level-0 hat is the linear interpolant of its
//! values at T₁'s vertices, φ = Σ_w φ(w) ψ_w, with ψ_w the level-1 hat,
//! φ_□(2(· − w)) at T₁'s valence-4 vertices (Z/2 + ¼)² and φ_◇(2(· − w)) at
//! its valence-8 vertices (Z/2)². The square splits into its quarters,
//! χ = Σ_q χ(2(· − q)), q ∈ {±¼}², and (g(2(· − a)) * h(2(· − b)))(x) =
//! ¼ (g * h)(2(x − a − b)). Hence
//! B(x) = ¼ Σ_w Σ_q φ(w) B_{kind(w)}(2(x − w − q)): the level-1 basis
//! function at p' = w + q has the level-1 coefficient
//! μ_{p'} = ¼ Σ_q Σ_p λ_p φ_{kind(p)}(p' − q − p).
//! Square-kind p' (new V-vertices) lie at (Z/2)² — the old V-vertices, the
//! edge midpoints and the old FCVs' positions, as the FCV host nests them —
//! and diamond-kind p' (new FCVs) at (Z/2 + ¼)², the centres of the new
//! quads: primal nesting, each control face's parameter square is the face.
//!
//! Positions here are in quarter units of the coarse lattice: coarse
//! V-vertices at 4Z², coarse FCVs at 4Z² + (2, 2); new V-vertices at 2Z², new
//! FCVs at 2Z² + (1, 1).

use crate::numeric::{Rational, Weight};

/// The two kinds of control point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// a V-vertex: basis φ_□ * χ
    Vertex,
    /// a face control vertex: basis φ_◇ * χ
    Fcv,
}

/// The kind of a coarse control point at `p` (quarter units), if `p` is one.
pub fn coarse_kind(p: (i64, i64)) -> Option<Kind> {
    match (p.0.rem_euclid(4), p.1.rem_euclid(4)) {
        (0, 0) => Some(Kind::Vertex),
        (2, 2) => Some(Kind::Fcv),
        _ => None,
    }
}

/// The kind of a new (level + 1) control point at `p` (quarter units of the
/// coarse lattice), if `p` is one.
pub fn fine_kind(p: (i64, i64)) -> Option<Kind> {
    match (p.0.rem_euclid(2), p.1.rem_euclid(2)) {
        (0, 0) => Some(Kind::Vertex),
        (1, 1) => Some(Kind::Fcv),
        _ => None,
    }
}

/// The coarse hat of a control point of kind `kind` at the offset `d`
/// (quarter units) from it: φ_□ = 1 − 2 max(|x₁|, |x₂|), φ_◇ = 1 − |x₁| − |x₂|,
/// clipped at 0.
pub fn hat(kind: Kind, d: (i64, i64)) -> Rational {
    let (a, b) = (d.0.abs(), d.1.abs());
    // in quarter units: 1 − 2·max/4 and 1 − (a + b)/4
    let numerator = match kind {
        Kind::Vertex => 2 - a.max(b),
        Kind::Fcv => 4 - a - b,
    };
    let denominator = match kind {
        Kind::Vertex => 2,
        Kind::Fcv => 4,
    };
    if numerator <= 0 {
        Rational::zero()
    } else {
        Rational::ratio(numerator, denominator)
    }
}

/// The weight of the coarse control point at `old` (quarter units) in the
/// new control point at `new`: ¼ Σ_{q ∈ {±¼}²} φ_{kind(old)}(new − q − old).
/// `None` when either position is not a control point of its level.
pub fn refinement_weight(new: (i64, i64), old: (i64, i64)) -> Option<Rational> {
    fine_kind(new)?;
    let kind = coarse_kind(old)?;
    let mut sum = Rational::zero();
    for q in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
        sum += hat(kind, (new.0 - q.0 - old.0, new.1 - q.1 - old.1));
    }
    Some(sum * Rational::ratio(1, 4))
}

/// Every coarse control point with a nonzero weight in the new point `new`,
/// with that weight (the hats reach 2 quarter units, the quarter squares one
/// more: a box of radius 4 holds them all).
///
/// Both lattices repeat under shifts by 4Z² (the coarse period; the kinds
/// depend on positions mod 4 and 2, the weights on `new − old`), so the
/// mask of `new` is the mask of `new mod 4` shifted: the sixteen masks are
/// derived once per process and translated.
pub fn mask(new: (i64, i64)) -> Option<Vec<((i64, i64), Rational)>> {
    static BY_RESIDUE: std::sync::OnceLock<Vec<Option<Vec<((i64, i64), Rational)>>>> = std::sync::OnceLock::new();
    let masks = BY_RESIDUE.get_or_init(|| (0..16).map(|r| derived_mask((r / 4, r % 4))).collect());
    let residue = (new.0.rem_euclid(4), new.1.rem_euclid(4));
    let shift = (new.0 - residue.0, new.1 - residue.1);
    let at = masks[(residue.0 * 4 + residue.1) as usize].as_ref()?;
    Some(at.iter().map(|&((x, y), ref w)| ((x + shift.0, y + shift.1), w.clone())).collect())
}

/// [`mask`] from the definition, at any position.
fn derived_mask(new: (i64, i64)) -> Option<Vec<((i64, i64), Rational)>> {
    fine_kind(new)?;
    let mut out = Vec::new();
    for x in new.0 - 4..=new.0 + 4 {
        for y in new.1 - 4..=new.1 + 4 {
            if let Some(w) = refinement_weight(new, (x, y)) {
                if !Weight::is_zero(&w) {
                    out.push(((x, y), w));
                }
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(p: i64, q: i64) -> Rational {
        Rational::ratio(p, q)
    }

    /// The translated masks equal the masks derived at the point itself,
    /// over several coarse periods in both directions and signs.
    #[test]
    fn masks_translate_with_the_coarse_period() {
        for x in -9..=9 {
            for y in -9..=9 {
                assert_eq!(mask((x, y)), derived_mask((x, y)), "at ({x}, {y})");
            }
        }
    }

    #[test]
    fn the_four_regular_rules_of_section_3_2_2() {
        // V-vertex: V/2 + Σ 4 FCVs/8 (a_4 = 1/2)
        let mut m = mask((0, 0)).unwrap();
        m.sort_by_key(|(p, _)| *p);
        assert_eq!(
            m,
            vec![((-2, -2), r(1, 8)), ((-2, 2), r(1, 8)), ((0, 0), r(1, 2)), ((2, -2), r(1, 8)), ((2, 2), r(1, 8))]
        );
        // E-vertex on the edge (0,0)–(4,0): both ends and both FCVs, 1/4 each
        let mut m = mask((2, 0)).unwrap();
        m.sort_by_key(|(p, _)| *p);
        assert_eq!(m, vec![((0, 0), r(1, 4)), ((2, -2), r(1, 4)), ((2, 2), r(1, 4)), ((4, 0), r(1, 4))]);
        // the old FCV at (2,2) becomes a V-vertex: FCV/2 + Σ 4 corners/8
        let mut m = mask((2, 2)).unwrap();
        m.sort_by_key(|(p, _)| *p);
        assert_eq!(
            m,
            vec![((0, 0), r(1, 8)), ((0, 4), r(1, 8)), ((2, 2), r(1, 2)), ((4, 0), r(1, 8)), ((4, 4), r(1, 8))]
        );
        // NFCV of the new quad at corner (0,0) of the face centred at (2,2):
        // V_0/4 + FCV_0/2 + the FCVs of the faces beside it at V_0, 1/8 each
        let mut m = mask((1, 1)).unwrap();
        m.sort_by_key(|(p, _)| *p);
        assert_eq!(m, vec![((-2, 2), r(1, 8)), ((0, 0), r(1, 4)), ((2, -2), r(1, 8)), ((2, 2), r(1, 2))]);
    }
}
