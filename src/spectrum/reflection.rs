//! The reflection symmetry of a tagged configuration (issue 26): a tagged
//! vertex has no rotation symmetry, but its sharp rays are kept (as a set)
//! by one reflection of the fan, and rules that do not prefer a direction
//! (Hoppe's, BLZ's) commute with it. Then S splits into an even block (on
//! vectors with x(Pv) = x(v)) and an odd block (x(Pv) = −x(v)), and spec S is
//! the union of the two blocks' spectra (Biermann–Levin–Zorin 2000 state
//! their conditions per block).
//!
//! The reflection. Rays are numbered counter-clockwise, sector s lies
//! between rays s and s + 1 and a point of it has chart coordinates (i, j),
//! i along ray s, j along ray s + 1 (`neighbourhood::labels`; a point on
//! ray s has j = 0 and belongs to sector s). The reflection r ↦ a − r of
//! the rays (mod n for a closed fan) maps sector s onto sector a − 1 − s
//! with its two axes swapped: (s, i, j) ↦ (a − 1 − s, j, i) for j > 0 and
//! (s, i, 0) ↦ (a − s, i, 0) on a ray; the centre is fixed. The axis keeps
//! the sharp rays: boundary and corner a = k (ray 0 ↔ ray k), crease:K
//! a = K (the two sharp rays swap, each side onto itself), dart a = 0 (the
//! sharp ray onto itself).
//!
//! The blocks. With P the permutation and S P = P S, the vectors
//! u_b = e_b + e_{Pb} (b ≤ Pb) span the even subspace and
//! w_b = e_b − e_{Pb} (b < Pb) the odd one, and both are invariant; the
//! coefficient of S u_b on u_a is its a-th entry, so
//! E[a][b] = S[a][b] + S[a][Pb] (S[a][b] when Pb = b) and
//! O[a][b] = S[a][b] − S[a][Pb], in any ring of weights (no division).
//! In the basis (u, w), S is block diagonal diag(E, O), so
//! det(x − S) = det(x − E) det(x − O): `tests/reflection_split.rs` checks
//! this exactly (Berkowitz over the rationals).

use serde::Serialize;

use crate::neighbourhood::{Configuration, Tagging, VertexLabel};
use crate::numeric::Weight;

/// The reflection's axis: the ray index a of r ↦ a − r.
pub fn axis(tagging: Tagging, sectors: usize) -> usize {
    match tagging {
        Tagging::Boundary | Tagging::Corner => sectors,
        Tagging::Crease { at } => at,
        Tagging::Dart => 0,
    }
}

/// The image of every vertex (matrix index) under the reflection that keeps
/// the sharp rays of `config`; `None` for an untagged configuration or
/// where an image lies outside the labelled set (it then is not invariant).
pub fn reflection_of(config: &Configuration, labels: &[VertexLabel]) -> Option<Vec<usize>> {
    let tagging = config.tagging?;
    let n = config.valence();
    let a = axis(tagging, n) as i64;
    // a closed fan's rays and sectors are mod n; an open fan's are 0..=k
    let wrap = |x: i64| -> Option<usize> {
        if tagging.is_open() {
            usize::try_from(x).ok()
        } else {
            Some(x.rem_euclid(n as i64) as usize)
        }
    };
    let key = |l: &VertexLabel| (l.sector, l.i, l.j);
    let pos: std::collections::HashMap<_, _> = labels.iter().enumerate().map(|(k, l)| (key(l), k)).collect();
    labels
        .iter()
        .map(|l| {
            if l.i == 0 && l.j == 0 {
                return pos.get(&key(l)).copied();
            }
            let s = l.sector as i64;
            let image = if l.j == 0 { (wrap(a - s)?, l.i, 0) } else { (wrap(a - 1 - s)?, l.j, l.i) };
            pos.get(&image).copied()
        })
        .collect()
}

/// Whether S commutes with the permutation `image` (S[Pa][Pb] = S[a][b]),
/// entries compared by `same`.
pub fn commutes<W>(s: &[Vec<W>], image: &[usize], same: impl Fn(&W, &W) -> bool) -> bool {
    (0..s.len()).all(|a| (0..s.len()).all(|b| same(&s[image[a]][image[b]], &s[a][b])))
}

/// The even and odd blocks of S (see the module doc), with the matrix
/// indices of their basis representatives.
#[derive(Clone, Debug)]
pub struct Blocks<W> {
    pub even: Vec<Vec<W>>,
    pub odd: Vec<Vec<W>>,
    pub even_of: Vec<usize>,
    pub odd_of: Vec<usize>,
}

/// The blocks of S for a permutation it commutes with (check [`commutes`]
/// first: otherwise these are not blocks of S).
pub fn split<W: Weight>(s: &[Vec<W>], image: &[usize]) -> Blocks<W> {
    let even_of: Vec<usize> = (0..s.len()).filter(|&b| b <= image[b]).collect();
    let odd_of: Vec<usize> = (0..s.len()).filter(|&b| b < image[b]).collect();
    let even = even_of
        .iter()
        .map(|&a| {
            even_of
                .iter()
                .map(|&b| if image[b] == b { s[a][b].clone() } else { s[a][b].clone() + s[a][image[b]].clone() })
                .collect()
        })
        .collect();
    let odd =
        odd_of.iter().map(|&a| odd_of.iter().map(|&b| s[a][b].clone() - s[a][image[b]].clone()).collect()).collect();
    Blocks { even, odd, even_of, odd_of }
}

/// One eigenvalue of a block, as the spectrum table shows it.
#[derive(Clone, Debug, Serialize)]
pub struct BlockValue {
    pub re: f64,
    pub im: f64,
    pub modulus: f64,
    pub algebraic_multiplicity: usize,
    pub geometric_multiplicity: usize,
}

/// The spectrum of S per reflection block (floating point, the same dense
/// eigen-solver and clustering as the whole matrix).
#[derive(Clone, Debug, Serialize)]
pub struct ReflectionSpectra {
    /// the axis a of r ↦ a − r
    pub axis: usize,
    pub even_size: usize,
    pub odd_size: usize,
    /// by decreasing modulus
    pub even: Vec<BlockValue>,
    pub odd: Vec<BlockValue>,
}

/// The per-block spectra of the f64 matrix `s` over `labels` at `config`:
/// `Ok(None)` when the configuration is not tagged, the set is not mapped
/// onto itself, or S does not commute with the reflection (rules that
/// prefer a direction); entries are compared to 1e-12 relative to the
/// largest, as the float matrix's rows come from composed stencils.
pub fn reflection_spectra(
    config: &Configuration,
    labels: &[VertexLabel],
    s: &[Vec<f64>],
) -> Result<Option<ReflectionSpectra>, crate::error::Error> {
    let Some(image) = reflection_of(config, labels) else { return Ok(None) };
    let scale = s.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs())).max(1.0);
    if !commutes(s, &image, |x, y| (x - y).abs() <= 1e-12 * scale) {
        return Ok(None);
    }
    let blocks = split(s, &image);
    let values = |m: &[Vec<f64>]| -> Result<Vec<BlockValue>, crate::error::Error> {
        let mat = faer::Mat::from_fn(m.len(), m.len(), |i, j| faer::c64::new(m[i][j], 0.0));
        let mut out: Vec<BlockValue> = super::eigen::block_eigen(&mat)?
            .into_iter()
            .map(|e| BlockValue {
                re: e.value.re,
                im: e.value.im,
                modulus: e.value.norm(),
                algebraic_multiplicity: e.algebraic,
                geometric_multiplicity: e.geometric,
            })
            .collect();
        out.sort_by(|x, y| y.modulus.total_cmp(&x.modulus).then(y.re.total_cmp(&x.re)).then(y.im.total_cmp(&x.im)));
        Ok(out)
    };
    let n = config.valence();
    Ok(Some(ReflectionSpectra {
        axis: axis(config.tagging.expect("reflection_of needs a tagging"), n),
        even_size: blocks.even.len(),
        odd_size: blocks.odd.len(),
        even: values(&blocks.even)?,
        odd: values(&blocks.odd)?,
    }))
}
