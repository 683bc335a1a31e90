//! Choosing the subdominant pair for the characteristic map, and saying why
//! when the spectrum does not have one that a characteristic map can be built
//! from (a picture of a meaningless map would be worse than no picture).

use faer::c64;
use serde::Serialize;

use crate::spectrum::{Method, Spectrum};

/// Relative size below which the second real direction counts as dependent.
const INDEPENDENCE_TOL: f64 = 1e-8;
/// Relative size (of the Euclidean norms) below which a real direction is
/// rounding noise, not part of the pair.
const NEGLIGIBLE_PART: f64 = 1e-6;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SpectralStatus {
    /// λ1 = λ2 real, positive, non-defective, from Fourier blocks 1 and n−1
    /// (or from a configuration without rotation symmetry)
    Ok,
    /// a proper pair, but from Fourier blocks other than 1 and n−1: the map
    /// exists and is computed, and it winds |m| times around the centre
    WrongBlock,
    /// the subdominant eigenvalue is simple (λ1 ≠ λ2)
    Simple,
    /// the subdominant eigenvalue has multiplicity above two
    TooMany,
    /// algebraic multiplicity two, geometric one
    Defective,
    /// the subdominant eigenvalue is not real and positive
    NotRealPositive,
    /// another eigenvalue has the same modulus as λ1
    NotDominant,
    /// the spectrum has no subdominant eigenvalue at all
    Missing,
}

impl SpectralStatus {
    /// Whether the map can be built and checked.
    pub fn has_map(self) -> bool {
        matches!(self, SpectralStatus::Ok | SpectralStatus::WrongBlock)
    }
}

pub struct Pair {
    pub status: SpectralStatus,
    pub explanation: String,
    pub lambda: f64,
    pub blocks: Vec<usize>,
    /// the two real coordinate functions over the neighbourhood (matrix order)
    pub values: Vec<[f64; 2]>,
}

impl Pair {
    /// No pair (yet), with the reason.
    pub(crate) fn missing(why: &str) -> Pair {
        Pair {
            status: SpectralStatus::Missing,
            explanation: why.to_string(),
            lambda: f64::NAN,
            blocks: Vec::new(),
            values: Vec::new(),
        }
    }
}

/// The subdominant pair of `spec`, or the reason there is none.
pub fn subdominant_pair(spec: &Spectrum) -> Pair {
    let Some(l1) = spec.eigenvalues.get(1) else {
        return Pair::missing("the spectrum has no subdominant eigenvalue");
    };
    let mut pair = Pair::missing("");
    pair.lambda = l1.re;
    pair.blocks = l1.blocks.clone();
    let (status, why) = if !l1.is_real() || l1.re <= 0.0 {
        (
            SpectralStatus::NotRealPositive,
            format!("λ1 = {} is not real and positive: no real planar map scales by λ1", l1.display()),
        )
    } else if l1.algebraic_multiplicity == 1 {
        (
            SpectralStatus::Simple,
            format!(
                "λ1 = {} is simple (λ1 ≠ λ2): the limit surface is dominated by one direction, \
                 so no two-dimensional characteristic map exists",
                l1.display()
            ),
        )
    } else if l1.geometric_multiplicity < l1.algebraic_multiplicity {
        (
            SpectralStatus::Defective,
            format!(
                "λ1 = {} is defective (algebraic multiplicity {}, geometric {}): a generalised \
                 eigenvector grows like k·λ1^k, so the refined nets do not converge to a scaled ring",
                l1.display(),
                l1.algebraic_multiplicity,
                l1.geometric_multiplicity
            ),
        )
    } else if l1.algebraic_multiplicity > 2 {
        (
            SpectralStatus::TooMany,
            format!(
                "λ1 = {} has multiplicity {}: the subdominant eigenspace is not a pair, the map is not unique",
                l1.display(),
                l1.algebraic_multiplicity
            ),
        )
    } else if spec.eigenvalues.get(2).is_some_and(|l3| l3.modulus >= l1.modulus * (1.0 - 1e-9)) {
        (
            SpectralStatus::NotDominant,
            format!(
                "|λ3| = {} equals λ1 = {}: the pair does not dominate the rest of the spectrum",
                crate::spectrum::fmt_f(spec.eigenvalues[2].modulus),
                l1.display()
            ),
        )
    } else {
        (SpectralStatus::Ok, String::new())
    };
    if status != SpectralStatus::Ok {
        pair.status = status;
        pair.explanation = why;
        return pair;
    }
    let vectors = spec.right_vectors(l1);
    let Some(values) = real_pair(&vectors) else {
        pair.status = SpectralStatus::Defective;
        pair.explanation = "the eigenvectors of λ1 do not span two real directions".into();
        return pair;
    };
    pair.values = values;
    // the rotation group of the configuration has order g; blocks 1 and g−1
    // rotate the sectors by one turn in total, any other block m by m turns
    let g = match &spec.synthesis {
        crate::spectrum::Synthesis::Dft { orbits, .. } => Some(orbits.group_order),
        _ => None,
    };
    match (spec.method, g) {
        (Method::Dft, Some(g)) if g >= 3 => {
            let good = l1.blocks.iter().all(|&m| m == 1 || m == g - 1);
            if good {
                pair.status = SpectralStatus::Ok;
                pair.explanation = format!("λ1 = λ2 = {} from Fourier blocks 1 and {}", l1.display(), g - 1);
            } else {
                pair.status = SpectralStatus::WrongBlock;
                pair.explanation = format!(
                    "λ1 = λ2 = {} comes from Fourier blocks {:?}, not 1 and {}: the characteristic map \
                     wraps the sectors around the centre more than once, so it cannot be injective",
                    l1.display(),
                    l1.blocks,
                    g - 1
                );
            }
        }
        _ => {
            pair.status = SpectralStatus::Ok;
            pair.explanation =
                format!("λ1 = λ2 = {} (no Fourier blocks to check; the winding number decides)", l1.display());
        }
    }
    pair
}

/// Two independent real vectors from complex eigenvectors: the real and
/// imaginary parts of the first vector when they are independent (a Fourier
/// block vector, whose complex form keeps the rotation symmetry exact), else
/// the real parts of the first two vectors.
fn real_pair(vectors: &[Vec<c64>]) -> Option<Vec<[f64; 2]>> {
    let first = vectors.first()?;
    let re: Vec<f64> = first.iter().map(|z| z.re).collect();
    let im: Vec<f64> = first.iter().map(|z| z.im).collect();
    if independent(&re, &im) {
        return Some(re.into_iter().zip(im).map(|(a, b)| [a, b]).collect());
    }
    let candidates: Vec<Vec<f64>> = vectors
        .iter()
        .flat_map(|v| [v.iter().map(|z| z.re).collect::<Vec<_>>(), v.iter().map(|z| z.im).collect()])
        .collect();
    for (i, a) in candidates.iter().enumerate() {
        for b in &candidates[i + 1..] {
            if independent(a, b) {
                return Some(a.iter().zip(b).map(|(x, y)| [*x, *y]).collect());
            }
        }
    }
    None
}

fn independent(a: &[f64], b: &[f64]) -> bool {
    let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>();
    let (aa, bb, ab) = (dot(a, a), dot(b, b), dot(a, b));
    // a part NEGLIGIBLE_PART times the other's size is rounding (the
    // imaginary part a dense solver leaves on a real eigenvector), not a
    // direction: its angle to the other is noise, so the test below alone
    // would take it and the map would be flat
    let comparable = aa > NEGLIGIBLE_PART * NEGLIGIBLE_PART * bb && bb > NEGLIGIBLE_PART * NEGLIGIBLE_PART * aa;
    aa > 0.0 && bb > 0.0 && comparable && (aa * bb - ab * ab) > INDEPENDENCE_TOL * aa * bb
}

/// The characteristic map's pair at a tagged vertex (the spectrum's
/// `sector` verdict): the eigenvectors of λ1 = λ2 (a double eigenvalue, as
/// at an interior point), or of λ1 > λ2, one each (Zorin's sector
/// criterion allows two different subdominant eigenvalues: the map is then
/// scaled by λ1 in one direction and λ2 in the other). `lambda` is λ1.
pub fn sector_pair(spec: &Spectrum) -> Pair {
    sector_pair_under(spec, &spec.verdict)
}

/// [`sector_pair`] of `spec`'s eigenvectors, the spectral part decided by
/// `verdict`: at a crease vertex whose sides decouple, `spec.verdict` is the
/// per-side one, and S whole's map is built only where S whole's own
/// verdict (`crease.whole`) passes.
pub fn sector_pair_under(spec: &Spectrum, verdict: &crate::spectrum::Verdict) -> Pair {
    let Some(l1) = spec.eigenvalues.get(1) else {
        return Pair::missing("the spectrum has no subdominant eigenvalue");
    };
    let mut pair = Pair::missing("");
    pair.lambda = l1.re;
    if !verdict.c1_spectral {
        pair.status = SpectralStatus::NotDominant;
        pair.explanation = format!(
            "the spectral part of the sector criterion fails ({}), so there is no characteristic map",
            verdict.reasons.iter().filter(|r| !r.starts_with("not decided")).cloned().collect::<Vec<_>>().join("; ")
        );
        return pair;
    }
    let values = if l1.algebraic_multiplicity == 2 {
        real_pair(&spec.right_vectors(l1))
    } else {
        // λ1 > λ2, each simple and real: one real vector each
        let l2 = &spec.eigenvalues[2];
        let real = |e| spec.right_vectors(e).first().map(|v| v.iter().map(|z| z.re).collect::<Vec<f64>>());
        match (real(l1), real(l2)) {
            (Some(a), Some(b)) if independent(&a, &b) => Some(a.into_iter().zip(b).map(|(x, y)| [x, y]).collect()),
            _ => None,
        }
    };
    let Some(values) = values else {
        pair.status = SpectralStatus::Defective;
        pair.explanation = "the subdominant eigenvectors do not span two real directions".into();
        return pair;
    };
    pair.values = values;
    pair.status = SpectralStatus::Ok;
    pair.explanation = match l1.algebraic_multiplicity {
        2 => format!("λ1 = λ2 = {} at a tagged vertex", l1.display()),
        _ => format!(
            "λ1 = {} > λ2 = {} at a tagged vertex (the map scales by each in its own direction)",
            l1.display(),
            spec.eigenvalues[2].display()
        ),
    };
    pair
}
