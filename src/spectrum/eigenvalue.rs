//! An eigenvalue of S as an analysis reports it: its value, multiplicities,
//! the blocks it came from, exact and recognised values and right
//! eigenvectors in block coordinates; its display, and the canonical order
//! of eigenvalues.

use faer::c64;
use serde::Serialize;

/// Right eigenvectors of one eigenvalue from one block, in block coordinates
/// (B x = λ x). Left eigenvectors are computed on request from the block, and
/// both are mapped to the whole neighbourhood on request
/// ([`Spectrum::right_vectors`](super::Spectrum::right_vectors),
/// [`Spectrum::left_vectors`](super::Spectrum::left_vectors)): at high
/// valence most of the n blocks' vectors are never looked at.
#[derive(Clone, Debug)]
pub struct EigenVectors {
    pub block: usize,
    pub right: Vec<Vec<c64>>,
}

#[derive(Clone, Debug, Serialize)]
pub struct Eigenvalue {
    pub re: f64,
    pub im: f64,
    pub modulus: f64,
    pub algebraic_multiplicity: usize,
    pub geometric_multiplicity: usize,
    pub defective: bool,
    /// first block containing it
    pub block: usize,
    pub blocks: Vec<usize>,
    /// exact rational value, proven by the exact path (root of an exact
    /// characteristic polynomial), else null
    pub exact: Option<String>,
    /// a small rational close to the value (a reading aid, not a proof)
    pub recognised: Option<String>,
    #[serde(skip)]
    pub vectors: Vec<EigenVectors>,
}

impl Eigenvalue {
    pub fn value(&self) -> c64 {
        c64::new(self.re, self.im)
    }
    pub fn is_real(&self) -> bool {
        self.im.abs() <= 1e-9 * self.modulus.max(1.0)
    }
    /// "0.25 (1/4)" style display.
    pub fn display(&self) -> String {
        let num = if self.is_real() {
            fmt_f(self.re)
        } else {
            let sign = if self.im < 0.0 { '-' } else { '+' };
            format!("{}{sign}{}i", fmt_f(self.re), fmt_f(self.im.abs()))
        };
        match (&self.exact, &self.recognised) {
            (Some(e), _) => format!("{num} (= {e})"),
            (None, Some(r)) => format!("{num} (≈ {r})"),
            _ => num,
        }
    }
}

pub fn fmt_f(x: f64) -> String {
    let s = format!("{x:.12}");
    let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// Modulus descending; ties by real part, then imaginary part, descending.
pub fn sort_eigenvalues(list: &mut [Eigenvalue]) {
    list.sort_by(|a, b| eigenvalue_order(c64::new(a.re, a.im), c64::new(b.re, b.im)));
}

/// The display order of eigenvalues (ARCHITECTURE.md): modulus descending, ties by
/// real part, then imaginary part, descending.
pub fn eigenvalue_order(a: c64, b: c64) -> std::cmp::Ordering {
    let tie = |x: f64, y: f64| (x - y).abs() <= 1e-10 * x.abs().max(y.abs()).max(1.0);
    if !tie(a.norm(), b.norm()) {
        return b.norm().total_cmp(&a.norm());
    }
    if !tie(a.re, b.re) {
        return b.re.total_cmp(&a.re);
    }
    b.im.total_cmp(&a.im)
}
