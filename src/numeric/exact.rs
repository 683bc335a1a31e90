//! Exact linear algebra over the rationals: characteristic polynomials,
//! rational roots with multiplicity, and exact ranks. This turns "1/4 appears
//! three times" from a floating-point observation into a fact.

use super::weight::Rational;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// Dense exact matrix, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct QMatrix {
    pub n: usize,
    pub data: Vec<Rational>,
}

impl QMatrix {
    pub fn zeros(n: usize) -> Self {
        QMatrix { n, data: vec![Rational::zero(); n * n] }
    }
    pub fn get(&self, i: usize, j: usize) -> &Rational {
        &self.data[i * self.n + j]
    }
    pub fn set(&mut self, i: usize, j: usize, v: Rational) {
        self.data[i * self.n + j] = v;
    }

    /// Characteristic polynomial det(xI - A), coefficients from x^0 upwards.
    /// Similarity reduction to upper Hessenberg form by exact elimination, then
    /// the Hessenberg determinant recurrence.
    pub fn charpoly(&self) -> Poly {
        let n = self.n;
        let mut h = self.data.clone();
        let at = |i: usize, j: usize| i * n + j;
        for col in 0..n.saturating_sub(2) {
            // pick a non-zero pivot below the subdiagonal, preferring small ones
            let mut pivot = None;
            for r in col + 1..n {
                if !h[at(r, col)].is_zero() {
                    let better = match pivot {
                        None => true,
                        Some(p) => height(&h[at(r, col)]) < height(&h[at(p, col)]),
                    };
                    if better {
                        pivot = Some(r);
                    }
                }
            }
            let Some(p) = pivot else { continue };
            if p != col + 1 {
                // swap rows and columns p and col+1 (a similarity)
                for j in 0..n {
                    h.swap(at(p, j), at(col + 1, j));
                }
                for i in 0..n {
                    h.swap(at(i, p), at(i, col + 1));
                }
            }
            let piv = h[at(col + 1, col)].clone();
            for r in col + 2..n {
                if h[at(r, col)].is_zero() {
                    continue;
                }
                let m = &h[at(r, col)] / &piv;
                // row_r -= m * row_{col+1}
                // (zero entries skipped before multiplying: local matrices
                // are sparse, and a big-rational product allocates)
                for j in 0..n {
                    if h[at(col + 1, j)].is_zero() {
                        continue;
                    }
                    let t = &m * &h[at(col + 1, j)];
                    h[at(r, j)] = &h[at(r, j)] - t;
                }
                // col_{col+1} += m * col_r  (keeps the similarity)
                for i in 0..n {
                    if h[at(i, r)].is_zero() {
                        continue;
                    }
                    let t = &m * &h[at(i, r)];
                    h[at(i, col + 1)] = &h[at(i, col + 1)] + t;
                }
            }
        }
        // p_k = det(xI - H[0..k, 0..k]) by the Hessenberg recurrence
        let mut ps: Vec<Poly> = vec![Poly::one()];
        for k in 1..=n {
            let hkk = h[at(k - 1, k - 1)].clone();
            let mut pk = ps[k - 1].mul_linear(&hkk); // (x - h_kk) p_{k-1}
            let mut prod = Rational::one();
            for i in (1..k).rev() {
                prod = &prod * &h[at(i, i - 1)];
                if prod.is_zero() {
                    break;
                }
                let c = &prod * &h[at(i - 1, k - 1)];
                if !c.is_zero() {
                    pk = pk.sub(&ps[i - 1].scale(&c));
                }
            }
            ps.push(pk);
        }
        ps.pop().unwrap()
    }

    /// Exact rank by Gaussian elimination.
    pub fn rank(&self) -> usize {
        rank_of(self.n, self.n, self.data.clone())
    }

    /// A - λI
    pub fn shifted(&self, lambda: &Rational) -> QMatrix {
        let mut m = self.clone();
        for i in 0..self.n {
            let v = m.get(i, i) - lambda;
            m.set(i, i, v);
        }
        m
    }
}

fn height(r: &Rational) -> usize {
    (r.numer().bits() + r.denom().bits()) as usize
}

/// The rank of the `rows` × `cols` rational matrix `a` (row-major).
pub fn rank_of(rows: usize, cols: usize, a: Vec<Rational>) -> usize {
    integer_echelon(rows, cols, &a, false).1.len()
}

/// Gaussian elimination of the `rows` × `cols` rational matrix `a`
/// (row-major) over the integers: the rows (scaled to integers) in echelon
/// form and the pivot columns (row k holds pivot k). With `reduced` every
/// pivot column is cleared above its pivot too (a reduced form whose pivots
/// are not scaled to 1: row k over its pivot is the reduced row).
///
/// Each row is first scaled by the common denominator of its entries, then
/// row r ← p·row r − a_rc·pivot row (p the pivot, non-zero), each changed
/// row divided by the gcd of its entries. Every step multiplies a row by a
/// non-zero rational or adds a multiple of another row, so the row space,
/// the rank and the pivot columns (the first column at which each rank is
/// reached, whichever pivots are chosen) are those over Q, and a reduced
/// row over its pivot is the reduced row over Q; but no entry is a fraction
/// to normalise (one gcd per changed row instead of one per entry and
/// operation, which made rational elimination the exact analyses' largest
/// cost). Rows without an entry in the pivot column are untouched, so
/// sparse local matrices stay cheap.
fn integer_echelon(rows: usize, cols: usize, a: &[Rational], reduced: bool) -> (Vec<Vec<BigInt>>, Vec<usize>) {
    let mut m: Vec<Vec<BigInt>> = a.chunks(cols.max(1)).take(rows).map(integer_row).collect();
    let mut pivots = Vec::new();
    for c in 0..cols {
        let rank = pivots.len();
        if rank == rows {
            break;
        }
        // the pivot of fewest bits keeps the products short; any non-zero
        // one gives the same row space
        let Some(p) = (rank..rows).filter(|&r| !m[r][c].is_zero()).min_by_key(|&r| m[r][c].bits()) else {
            continue;
        };
        m.swap(rank, p);
        let pivot_row = std::mem::take(&mut m[rank]);
        let others = if reduced { 0..rows } else { rank + 1..rows };
        for (r, row) in m.iter_mut().enumerate().skip(others.start).take(others.len()) {
            if r == rank || row[c].is_zero() {
                continue;
            }
            eliminate(row, &pivot_row, c);
        }
        m[rank] = pivot_row;
        pivots.push(c);
    }
    (m, pivots)
}

/// row ← p·row − row_c·pivot_row (p = pivot_row[c]), then made primitive.
/// Every entry is scaled, those before `c` too (a row above the pivot row
/// has its own pivot there; the pivot row is zero there).
fn eliminate(row: &mut [BigInt], pivot_row: &[BigInt], c: usize) {
    let piv = &pivot_row[c];
    // column c becomes p·f − f·p = 0: taken out, not computed
    let f = std::mem::take(&mut row[c]);
    for (x, y) in row.iter_mut().zip(pivot_row).enumerate().filter(|(j, _)| *j != c).map(|(_, xy)| xy) {
        if !x.is_zero() {
            *x *= piv;
        }
        if !y.is_zero() {
            *x -= &f * y;
        }
    }
    make_primitive(row);
}

/// A rational row times the least common multiple of its denominators: an
/// integer row with the same span.
fn integer_row(row: &[Rational]) -> Vec<BigInt> {
    let l = row.iter().filter(|x| !x.is_zero()).fold(BigInt::one(), |l, x| num_integer::Integer::lcm(&l, x.denom()));
    row.iter().map(|x| if x.is_zero() { BigInt::zero() } else { x.numer() * (&l / x.denom()) }).collect()
}

/// Divide an integer row by the gcd of its entries (nothing for a zero row).
fn make_primitive(row: &mut [BigInt]) {
    let g = super::content::content(row.iter().filter(|x| !x.is_zero()));
    if !g.is_zero() && !g.is_one() {
        for x in row.iter_mut().filter(|x| !x.is_zero()) {
            *x /= &g;
        }
    }
}

/// The pivot columns of the `rows` × `cols` matrix `a` (row-major) under
/// Gaussian elimination: a maximal set of linearly independent columns.
pub fn pivot_columns(rows: usize, cols: usize, a: Vec<Rational>) -> Vec<usize> {
    integer_echelon(rows, cols, &a, false).1
}

/// The inverse of the `n` × `n` matrix `a` (row-major) by Gauss–Jordan on
/// [a | I], or `None` when `a` is singular.
pub fn inverse(n: usize, a: &[Rational]) -> Option<Vec<Rational>> {
    let cols = 2 * n;
    let mut aug = vec![Rational::zero(); n * cols];
    for i in 0..n {
        for j in 0..n {
            aug[i * cols + j] = a[i * n + j].clone();
        }
        aug[i * cols + n + i] = Rational::one();
    }
    let (m, pivots) = integer_echelon(n, cols, &aug, true);
    if pivots.len() < n || pivots.iter().any(|&c| c >= n) {
        return None;
    }
    // row i is d_i·[e_i | row i of the inverse]
    Some(
        (0..n)
            .flat_map(|i| m[i][n..].iter().map(|x| Rational::new(x.clone(), m[i][i].clone())).collect::<Vec<_>>())
            .collect(),
    )
}

/// A basis of the null space {x : A x = 0} of the `rows` × `cols` matrix `a`
/// (row-major), by reduction to row echelon form: one vector per free column.
pub fn null_space(rows: usize, cols: usize, a: Vec<Rational>) -> Vec<Vec<Rational>> {
    let (m, pivots) = integer_echelon(rows, cols, &a, true);
    let free: Vec<usize> = (0..cols).filter(|c| !pivots.contains(c)).collect();
    free.iter()
        .map(|&f| {
            let mut x = vec![Rational::zero(); cols];
            x[f] = Rational::one();
            for (r, &pc) in pivots.iter().enumerate() {
                // the reduced row over its pivot: −(entry at f)/pivot
                x[pc] = -Rational::new(m[r][f].clone(), m[r][pc].clone());
            }
            x
        })
        .collect()
}

/// Polynomial with rational coefficients, lowest degree first.
#[derive(Clone, Debug, PartialEq)]
pub struct Poly {
    pub coeffs: Vec<Rational>,
}

impl Poly {
    pub fn one() -> Self {
        Poly { coeffs: vec![Rational::one()] }
    }
    pub fn from_roots(roots: &[Rational]) -> Self {
        roots.iter().fold(Poly::one(), |p, r| p.mul_linear(r))
    }
    pub fn degree(&self) -> usize {
        self.coeffs.len().saturating_sub(1)
    }
    fn trim(mut self) -> Self {
        while self.coeffs.len() > 1 && self.coeffs.last().is_some_and(|c| c.is_zero()) {
            self.coeffs.pop();
        }
        self
    }
    /// (x - r) * self
    pub fn mul_linear(&self, r: &Rational) -> Poly {
        let mut out = vec![Rational::zero(); self.coeffs.len() + 1];
        for (k, c) in self.coeffs.iter().enumerate() {
            out[k + 1] = &out[k + 1] + c;
            out[k] = &out[k] - r * c;
        }
        Poly { coeffs: out }.trim()
    }
    pub fn scale(&self, c: &Rational) -> Poly {
        Poly { coeffs: self.coeffs.iter().map(|x| x * c).collect() }.trim()
    }
    /// self · o
    pub fn mul(&self, o: &Poly) -> Poly {
        if self.coeffs.is_empty() || o.coeffs.is_empty() {
            return Poly { coeffs: Vec::new() };
        }
        let mut c = vec![Rational::zero(); self.coeffs.len() + o.coeffs.len() - 1];
        for (i, x) in self.coeffs.iter().enumerate() {
            for (j, y) in o.coeffs.iter().enumerate() {
                c[i + j] = &c[i + j] + x * y;
            }
        }
        Poly { coeffs: c }.trim()
    }
    pub fn sub(&self, o: &Poly) -> Poly {
        let n = self.coeffs.len().max(o.coeffs.len());
        let z = Rational::zero();
        let coeffs = (0..n).map(|k| self.coeffs.get(k).unwrap_or(&z) - o.coeffs.get(k).unwrap_or(&z)).collect();
        Poly { coeffs }.trim()
    }
    pub fn eval(&self, x: &Rational) -> Rational {
        match self.homogeneous_value(x) {
            Some(v) => Rational::new(v, x.denom().pow(self.degree() as u32)),
            None => self.coeffs.iter().rev().fold(Rational::zero(), |acc, c| acc * x + c),
        }
    }
    /// The sign of p(x) (−1, 0, 1).
    pub fn sign_at(&self, x: &Rational) -> i8 {
        let v = match self.homogeneous_value(x) {
            Some(v) => v,
            None => self.eval(x).numer().clone(),
        };
        if v.is_positive() {
            1
        } else if v.is_negative() {
            -1
        } else {
            0
        }
    }
    /// For integer coefficients c_k and x = a/b (b > 0): b^d p(a/b) =
    /// Σ c_k a^k b^(d−k), in integers by Horner (no rational is normalised
    /// on the way: at degree 100 and a 100-bit denominator the rational
    /// Horner spent its time in gcds). None when a coefficient is not an
    /// integer.
    fn homogeneous_value(&self, x: &Rational) -> Option<BigInt> {
        if !self.coeffs.iter().all(|c| c.is_integer()) {
            return None;
        }
        let (a, b) = (x.numer(), x.denom());
        let mut acc = BigInt::zero();
        let mut bpow = BigInt::one();
        for (i, c) in self.coeffs.iter().rev().enumerate() {
            if i > 0 {
                bpow *= b;
                acc = acc * a + c.numer() * &bpow;
            } else {
                acc = c.numer().clone();
            }
        }
        Some(acc)
    }
    /// Divide by (x - r) when r is a root; returns the quotient.
    pub fn deflate(&self, r: &Rational) -> Option<Poly> {
        if !self.eval(r).is_zero() || self.degree() == 0 {
            return None;
        }
        let d = self.degree();
        let mut q = vec![Rational::zero(); d];
        let mut carry = Rational::zero();
        for k in (1..=d).rev() {
            carry = &carry * r + &self.coeffs[k];
            q[k - 1] = carry.clone();
        }
        Some(Poly { coeffs: q }.trim())
    }
    /// Multiplicity of r as a root, and the cofactor.
    pub fn root_multiplicity(&self, r: &Rational) -> (usize, Poly) {
        let mut p = self.clone();
        let mut m = 0;
        while let Some(q) = p.deflate(r) {
            p = q;
            m += 1;
        }
        (m, p)
    }
    /// Human-readable form, highest degree first, e.g. "x^3 - 5/4 x^2 + 1/4 x".
    pub fn pretty(&self) -> String {
        let mut parts = Vec::new();
        for (k, c) in self.coeffs.iter().enumerate().rev() {
            if c.is_zero() {
                continue;
            }
            let sign = if c.is_negative() { "-" } else { "+" };
            let a = c.abs();
            let coef = if a.is_one() && k > 0 { String::new() } else { format!("{a} ") };
            let mono = match k {
                0 => String::new(),
                1 => "x".to_string(),
                _ => format!("x^{k}"),
            };
            parts.push((sign, format!("{coef}{mono}").trim().to_string()));
        }
        let mut s = String::new();
        for (i, (sign, t)) in parts.iter().enumerate() {
            if i == 0 {
                if *sign == "-" {
                    s.push('-');
                }
            } else {
                s.push_str(&format!(" {sign} "));
            }
            s.push_str(t);
        }
        if s.is_empty() {
            s.push('0');
        }
        s
    }
}

impl Poly {
    pub fn is_zero(&self) -> bool {
        self.coeffs.iter().all(|c| c.is_zero())
    }
    pub fn derivative(&self) -> Poly {
        if self.coeffs.len() <= 1 {
            return Poly { coeffs: vec![Rational::zero()] };
        }
        let coeffs = self
            .coeffs
            .iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| c * Rational::from_integer((k as i64).into()))
            .collect();
        Poly { coeffs }.trim()
    }
    /// Quotient and remainder of polynomial division.
    pub fn div_rem(&self, d: &Poly) -> (Poly, Poly) {
        assert!(!d.is_zero(), "division by the zero polynomial");
        let mut r = self.clone().trim();
        let dd = d.degree();
        let lead = d.coeffs[dd].clone();
        if r.degree() < dd || r.is_zero() {
            return (Poly { coeffs: vec![Rational::zero()] }, r);
        }
        let mut q = vec![Rational::zero(); r.degree() - dd + 1];
        while !r.is_zero() && r.degree() >= dd {
            let k = r.degree() - dd;
            let c = &r.coeffs[r.degree()] / &lead;
            for (i, dc) in d.coeffs.iter().enumerate() {
                r.coeffs[i + k] = &r.coeffs[i + k] - &c * dc;
            }
            q[k] = c;
            r = r.trim();
            if r.coeffs.len() == 1 && r.coeffs[0].is_zero() {
                break;
            }
        }
        (Poly { coeffs: q }.trim(), r)
    }
    /// Monic greatest common divisor (of the integer polynomials the two
    /// are rational multiples of, by the modular method of
    /// `numeric::modular`: Euclid over Q lets the coefficients explode).
    pub fn gcd(&self, other: &Poly) -> Poly {
        let (a, b) = (self.clone().trim(), other.clone().trim());
        let monic = |p: Poly| {
            let lead = p.coeffs.last().cloned().unwrap_or_else(Rational::one);
            if lead.is_zero() {
                return p;
            }
            p.scale(&(Rational::one() / lead))
        };
        if b.is_zero() {
            return monic(a);
        }
        if a.is_zero() {
            return monic(b);
        }
        let g = super::modular::gcd(&a.integer_multiple(), &b.integer_multiple());
        monic(Poly { coeffs: g.into_iter().map(Rational::from_integer).collect() })
    }
    /// The coefficients times the lcm of their denominators (integers, the
    /// same roots).
    pub fn integer_multiple(&self) -> Vec<num_bigint::BigInt> {
        // integer coefficients: themselves (no lcm, no normalised products)
        if self.coeffs.iter().all(|c| c.is_integer()) {
            return self.coeffs.iter().map(|c| c.numer().clone()).collect();
        }
        let l = self.coeffs.iter().fold(num_bigint::BigInt::one(), |l, c| num_integer::Integer::lcm(&l, c.denom()));
        self.coeffs.iter().map(|c| (c * Rational::from_integer(l.clone())).to_integer()).collect()
    }
    /// Square-free factorisation (Yun): factors f_1, f_2, ... with
    /// self = c · Π f_k^k, each f_k square-free and the f_k pairwise coprime.
    pub fn squarefree_factors(&self) -> Vec<Poly> {
        let mut out = Vec::new();
        let d = self.derivative();
        let a = self.gcd(&d);
        let mut b = self.div_rem(&a).0;
        let mut c = d.div_rem(&a).0;
        loop {
            let bd = b.derivative();
            let diff = c.sub(&bd);
            if b.degree() == 0 {
                break;
            }
            let f = b.gcd(&diff);
            out.push(f.clone());
            b = b.div_rem(&f).0;
            c = diff.div_rem(&f).0;
        }
        out
    }
}

/// Exact rational roots of `p` among `candidates`, with multiplicities, and the
/// remaining factor (whose roots are irrational or complex, or were not among
/// the candidates).
pub fn rational_roots(p: &Poly, candidates: &[Rational]) -> (Vec<(Rational, usize)>, Poly) {
    let mut rest = p.clone();
    let mut found = Vec::new();
    for r in candidates {
        if found.iter().any(|(q, _)| q == r) {
            continue;
        }
        let (m, q) = rest.root_multiplicity(r);
        if m > 0 {
            found.push((r.clone(), m));
            rest = q;
        }
    }
    (found, rest)
}

/// Whether every root of `p` lies strictly inside the disc |x| < r (r > 0),
/// decided exactly by the Schur–Cohn recursion, on f(x) = p(r·x):
///
/// with c the ratio of f's constant term to its leading one: if |c| ≥ 1,
/// not every root lies inside (|c| is the product of the roots' moduli).
/// Otherwise g = f − c·f* (f*(x) = x^d f(1/x), the reversed polynomial) has
/// as many roots inside the unit disc as f (Rouché: |c·f*| < |f| on |x| = 1,
/// where |f*| = |f|), and g(0) = 0, so g = x·h with h of degree d − 1: f has
/// all d roots inside if and only if h has all d − 1. A non-zero constant
/// has no roots. The zero polynomial is `false`.
///
/// The recursion runs on integer polynomials: f is scaled to integer
/// coefficients (a positive factor moves no root), each step takes
/// h = (f_d·f − f_0·f*)/x — the monic step times f_d², again a positive
/// factor — and divides out the coefficients' content. In rationals every
/// coefficient of every step paid a big-integer gcd and the numbers grew
/// with each step's common denominators; here one content gcd per step
/// keeps them the size of the Schur–Cohn minors, and the answer is the same
/// (the two recursions differ by positive factors only).
pub fn roots_inside_disc(p: &Poly, r: &Rational) -> bool {
    assert!(r.is_positive(), "the disc's radius must be positive");
    let mut f = scaled_integer_coefficients(p, r);
    loop {
        while f.len() > 1 && f.last().is_some_and(|c| c.is_zero()) {
            f.pop();
        }
        match f.len() {
            0 => return false,
            1 => return !f[0].is_zero(),
            _ => {}
        }
        let d = f.len() - 1;
        let (lead, c) = (f[d].clone(), f[0].clone());
        if c.abs() >= lead.abs() {
            return false;
        }
        // h_k = f_d·f_{k+1} − f_0·f_{d−k−1}, k = 0..d−1: f_d² times the
        // monic recursion's step, whatever f_d's sign
        let mut h: Vec<BigInt> = (1..=d).map(|k| &lead * &f[k] - &c * &f[d - k]).collect();
        let g = super::content::content(&h);
        if !g.is_zero() && !g.is_one() {
            h.iter_mut().for_each(|x| *x /= &g);
        }
        f = h;
    }
}

/// The number of roots of `p` (with multiplicity) of modulus strictly above
/// r (r > 0), decided exactly; `None` when the recursion meets a singular
/// step (|f_0| = |f_d|), which it does whenever p has a root of modulus
/// exactly r, and may otherwise (then nothing is decided).
///
/// The counting form of the Schur–Cohn recursion of [`roots_inside_disc`],
/// on f(x) = p(r·x) (real coefficients; O(f) = roots outside the closed unit
/// disc, I(f) inside the open one; f* reversed, |f*| = |f| on |x| = 1):
///
/// - |f_d| > |f_0|: g = f_d·f − f_0·f* has I(g) = I(f) (Rouché), g(0) = 0
///   and deg g = d (leading coefficient f_d² − f_0² ≠ 0), so h = g/x has
///   degree d − 1, I(h) = I(f) − 1 and O(h) = O(f);
/// - |f_0| > |f_d|: g = f_0·f* − f_d·f = −(f_d·f − f_0·f*) has I(g) =
///   I(f*) = O(f) (f(0) ≠ 0: the roots of f* are the reciprocals), so
///   O(f) = I(h) + 1 = d − O(h);
/// - a non-zero constant has no roots.
///
/// A root ζ on the unit circle is a root of f* too (f*(ζ) = ζ^d·conj f(ζ)),
/// hence of g and h: it would survive to the final constant, which has no
/// roots. So a recursion that ends without a singular step proves that f has
/// no root on the circle, which the two Rouché steps assumed. The steps
/// divide by no coefficient: the same integer recursion as
/// [`roots_inside_disc`] (positive factors and contents move no root; the
/// second case's sign flip moves none either).
pub fn roots_outside_disc(p: &Poly, r: &Rational) -> Option<usize> {
    assert!(r.is_positive(), "the disc's radius must be positive");
    let mut f = scaled_integer_coefficients(p, r);
    // O(p) = Σ of the steps' contributions: each step either keeps the count
    // (a) or reflects it (b): O(f) = d − O(h); track it as O = sign·O(h) + offset
    let (mut sign, mut offset) = (1i64, 0i64);
    loop {
        while f.len() > 1 && f.last().is_some_and(|c| c.is_zero()) {
            f.pop();
        }
        match f.len() {
            0 => return None,
            1 => return if f[0].is_zero() { None } else { usize::try_from(offset).ok() },
            _ => {}
        }
        let d = f.len() - 1;
        let (lead, c) = (f[d].clone(), f[0].clone());
        let (al, ac) = (lead.abs(), c.abs());
        if al == ac {
            return None;
        }
        if ac > al {
            // O(f) = d − O(h): O = sign·(d − O(h)) + offset
            offset += sign * d as i64;
            sign = -sign;
        }
        let mut h: Vec<BigInt> = (1..=d).map(|k| &lead * &f[k] - &c * &f[d - k]).collect();
        let g = super::content::content(&h);
        if !g.is_zero() && !g.is_one() {
            h.iter_mut().for_each(|x| *x /= &g);
        }
        f = h;
    }
}

/// The number of roots of `p` of modulus above r, with the proof that none
/// has modulus exactly r; `None` when that is not shown (a root of modulus
/// r, or the recursion singular at every radius tried).
///
/// [`roots_outside_disc`] at r itself first. Its recursion is singular not
/// only for a root on the circle but also, spuriously, for a pair of roots
/// symmetric about it (z and r²/z̄: 1/2 and 1/8 about r = 1/4). Then the
/// counts at ρ− = r(1 − 2^−j) and ρ+ = r(1 + 2^−j), j = 1..16: when both are
/// decided and equal, no root has modulus in [ρ−, ρ+] ∋ r (the roots above
/// ρ− and above ρ+ are the same ones), so the count above r is theirs.
pub fn roots_above(p: &Poly, r: &Rational) -> Option<usize> {
    if let Some(c) = roots_outside_disc(p, r) {
        return Some(c);
    }
    let mut step = Rational::one();
    for _ in 0..16 {
        step = step / Rational::from_integer(2.into());
        let below = roots_outside_disc(p, &(r * (Rational::one() - &step)));
        let above = roots_outside_disc(p, &(r * (Rational::one() + &step)));
        if let (Some(b), Some(a)) = (below, above) {
            if a == b {
                return Some(a);
            }
        }
    }
    None
}

/// The coefficients of p(r·x) times a positive integer that clears every
/// denominator (r = a/b: b^d · p(a x / b), then the lcm of p's denominators).
fn scaled_integer_coefficients(p: &Poly, r: &Rational) -> Vec<BigInt> {
    let d = p.coeffs.len().saturating_sub(1);
    let (a, b) = (r.numer().clone(), r.denom().clone());
    let lcm = p.coeffs.iter().fold(BigInt::one(), |l, c| num_integer::Integer::lcm(&l, c.denom()));
    let mut a_pow = BigInt::one();
    let mut b_pow: Vec<BigInt> = Vec::with_capacity(d + 1);
    let mut bp = BigInt::one();
    for _ in 0..=d {
        b_pow.push(bp.clone());
        bp *= &b;
    }
    p.coeffs
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let t = (c.numer() * (&lcm / c.denom())) * &a_pow * &b_pow[d - k];
            a_pow *= &a;
            t
        })
        .collect()
}

pub fn q(p: i64, qd: i64) -> Rational {
    Rational::new(BigInt::from(p), BigInt::from(qd))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Roots known by construction: inside, on and outside circles.
    #[test]
    fn schur_cohn_decides_roots_inside_a_disc() {
        let half = q(1, 2);
        // (x − 1/4)(x + 1/3): both inside |x| < 1/2
        assert!(roots_inside_disc(&Poly::from_roots(&[q(1, 4), q(-1, 3)]), &half));
        // a root on the circle is not inside
        assert!(!roots_inside_disc(&Poly::from_roots(&[q(1, 4), q(-1, 2)]), &half));
        assert!(!roots_inside_disc(&Poly::from_roots(&[q(1, 2)]), &half));
        // x² + 1/4: roots ±i/2, on |x| = 1/2, inside |x| < 51/100
        let circle = Poly { coeffs: vec![q(1, 4), q(0, 1), q(1, 1)] };
        assert!(!roots_inside_disc(&circle, &half));
        assert!(roots_inside_disc(&circle, &q(51, 100)));
        // x² − x + 1/2: roots (1 ± i)/2 of modulus 1/√2 ≈ 0.7071
        let pair = Poly { coeffs: vec![q(1, 2), q(-1, 1), q(1, 1)] };
        assert!(roots_inside_disc(&pair, &q(708, 1000)));
        assert!(!roots_inside_disc(&pair, &q(707, 1000)));
        // zero roots (x³) are inside any disc; a constant has no roots
        assert!(roots_inside_disc(&Poly::from_roots(&[q(0, 1), q(0, 1), q(0, 1)]), &q(1, 1000)));
        assert!(roots_inside_disc(&Poly::one(), &half));
        // a product of many: the degree-8 polynomial with roots ±k/20, k = 1..4, and ±9/20
        let roots: Vec<Rational> = [1, 2, 3, 4, 9].iter().flat_map(|&k| [q(k, 20), q(-k, 20)]).collect();
        let p = Poly::from_roots(&roots);
        assert!(roots_inside_disc(&p, &q(91, 200)));
        assert!(!roots_inside_disc(&p, &q(9, 20)));
    }

    /// A degree-24 polynomial with roots of known moduli: ±k/37 (k = 1..9),
    /// a pair (1 ± i)/4 of modulus √2/4 ≈ 0.35355, a pair ±(3/10)i and a
    /// double root 1/3. The largest modulus is √2/4: the test must flip
    /// between 0.3535 and 0.3536, and the scaled integer recursion must keep
    /// up with 24 steps of growing coefficients.
    #[test]
    fn schur_cohn_on_a_long_polynomial_flips_at_the_largest_modulus() {
        let mut roots: Vec<Rational> = (1..=9).flat_map(|k| [q(k, 37), q(-k, 37)]).collect();
        roots.extend([q(1, 3), q(1, 3)]);
        let real = Poly::from_roots(&roots);
        // (x − (1+i)/4)(x − (1−i)/4) = x² − x/2 + 1/8; (x² + 9/100)
        let pair = Poly { coeffs: vec![q(1, 8), q(-1, 2), q(1, 1)] };
        let imaginary = Poly { coeffs: vec![q(9, 100), q(0, 1), q(1, 1)] };
        let mul = |a: &Poly, b: &Poly| a.mul(b);
        let p = mul(&mul(&real, &pair), &imaginary);
        assert_eq!(p.degree(), 24);
        assert!(roots_inside_disc(&p, &q(3536, 10000)));
        assert!(!roots_inside_disc(&p, &q(3535, 10000)));
        // a negative leading coefficient changes nothing
        let negated = p.scale(&q(-7, 3));
        assert!(roots_inside_disc(&negated, &q(3536, 10000)));
        assert!(!roots_inside_disc(&negated, &q(3535, 10000)));
        // the double root 1/3 alone: inside 34/100, not inside 1/3
        let double = Poly::from_roots(&[q(1, 3), q(1, 3)]);
        assert!(roots_inside_disc(&double, &q(34, 100)));
        assert!(!roots_inside_disc(&double, &q(1, 3)));
    }

    #[test]
    fn charpoly_of_companion_like_matrix() {
        // upper triangular with diagonal 1, 1/2, 1/2: det(xI-A) = (x-1)(x-1/2)^2
        let mut a = QMatrix::zeros(3);
        a.set(0, 0, q(1, 1));
        a.set(1, 1, q(1, 2));
        a.set(2, 2, q(1, 2));
        a.set(0, 2, q(3, 1));
        a.set(2, 0, q(0, 1));
        let p = a.charpoly();
        assert_eq!(p, Poly::from_roots(&[q(1, 1), q(1, 2), q(1, 2)]));
        let (roots, rest) = rational_roots(&p, &[q(1, 2), q(1, 1)]);
        assert_eq!(roots, vec![(q(1, 2), 2), (q(1, 1), 1)]);
        assert_eq!(rest.degree(), 0);
    }

    #[test]
    fn null_space_of_a_rank_one_matrix() {
        // [[1, 2, 3], [2, 4, 6]]: x + 2y + 3z = 0, basis (-2, 1, 0), (-3, 0, 1)
        let a: Vec<Rational> = [1, 2, 3, 2, 4, 6].iter().map(|&k| q(k, 1)).collect();
        let ns = null_space(2, 3, a);
        assert_eq!(ns, vec![vec![q(-2, 1), q(1, 1), q(0, 1)], vec![q(-3, 1), q(0, 1), q(1, 1)]]);
        assert!(null_space(2, 2, vec![q(1, 1), q(0, 1), q(0, 1), q(1, 1)]).is_empty());
    }

    #[test]
    fn charpoly_matches_trace_and_determinant_of_dense_matrix() {
        // [[2,1,0],[1,3,1],[0,1,4]] : trace 9, det 2*(12-1) - 1*(4) = 18
        let vals = [[2, 1, 0], [1, 3, 1], [0, 1, 4]];
        let mut a = QMatrix::zeros(3);
        for (i, row) in vals.iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                a.set(i, j, q(v, 1));
            }
        }
        let p = a.charpoly();
        assert_eq!(p.coeffs[3], q(1, 1));
        assert_eq!(p.coeffs[2], q(-9, 1));
        assert_eq!(p.coeffs[0], q(-18, 1));
        // sum of principal 2x2 minors: (6-1) + (8-0) + (12-1) = 24
        assert_eq!(p.coeffs[1], q(24, 1));
    }

    #[test]
    fn squarefree_factorisation_separates_multiplicities() {
        // (x - 1)(x - 1/2)^2 (x^2 + 1)^3
        let base = Poly::from_roots(&[q(1, 1), q(1, 2), q(1, 2)]);
        let x2p1 = Poly { coeffs: vec![q(1, 1), q(0, 1), q(1, 1)] };
        let mut p = base.clone();
        for _ in 0..3 {
            let mut coeffs = vec![q(0, 1); p.coeffs.len() + 2];
            for (i, c) in p.coeffs.iter().enumerate() {
                for (j, d) in x2p1.coeffs.iter().enumerate() {
                    coeffs[i + j] = &coeffs[i + j] + c * d;
                }
            }
            p = Poly { coeffs };
        }
        let f = p.squarefree_factors();
        assert_eq!(f.len(), 3);
        assert_eq!(f[0], Poly::from_roots(&[q(1, 1)]));
        assert_eq!(f[1], Poly::from_roots(&[q(1, 2)]));
        assert_eq!(f[2], x2p1);
    }

    /// Products of known factors: the count is the number of roots of
    /// modulus above r, read off the factors by hand.
    #[test]
    fn roots_outside_disc_counts_the_roots_above_r() {
        let times = |a: &Poly, b: &Poly| {
            let mut coeffs = vec![q(0, 1); a.coeffs.len() + b.coeffs.len() - 1];
            for (i, c) in a.coeffs.iter().enumerate() {
                for (j, d) in b.coeffs.iter().enumerate() {
                    coeffs[i + j] = &coeffs[i + j] + c * d;
                }
            }
            Poly { coeffs }
        };
        // (x − 2)(x − 1/3)(x + 3)(x² + 1/4): above 1 are 2 and −3 (±i/2 inside)
        let p =
            times(&Poly::from_roots(&[q(2, 1), q(1, 3), q(-3, 1)]), &Poly { coeffs: vec![q(1, 4), q(0, 1), q(1, 1)] });
        assert_eq!(roots_outside_disc(&p, &q(1, 1)), Some(2));
        // above 1/4: all five (|±i/2| = 1/2); above 5/2: −3 only; above 4: none
        assert_eq!(roots_outside_disc(&p, &q(1, 4)), Some(5));
        assert_eq!(roots_outside_disc(&p, &q(5, 2)), Some(1));
        assert_eq!(roots_outside_disc(&p, &q(4, 1)), Some(0));
        // x² + 4 (modulus 2, a complex pair) times (x − 1/3): two above 1
        let p = times(&Poly::from_roots(&[q(1, 3)]), &Poly { coeffs: vec![q(4, 1), q(0, 1), q(1, 1)] });
        assert_eq!(roots_outside_disc(&p, &q(1, 1)), Some(2));
        // with 1/4 for 1/3 the moduli multiply to 1 = |f_0/f_d|: the first
        // step is singular without a root on the circle; roots_above decides
        let p = times(&Poly::from_roots(&[q(1, 4)]), &Poly { coeffs: vec![q(4, 1), q(0, 1), q(1, 1)] });
        assert_eq!(roots_outside_disc(&p, &q(1, 1)), None);
        assert_eq!(roots_above(&p, &q(1, 1)), Some(2));
        // a root on the circle |x| = r: not decided
        assert_eq!(roots_outside_disc(&Poly::from_roots(&[q(1, 1), q(1, 3)]), &q(1, 1)), None);
        assert_eq!(roots_outside_disc(&Poly::from_roots(&[q(-1, 2), q(1, 3)]), &q(1, 2)), None);
        // a root at 0 is inside
        assert_eq!(roots_outside_disc(&Poly::from_roots(&[q(0, 1), q(3, 1)]), &q(1, 1)), Some(1));
        // 1/2 and 1/8 are symmetric about |x| = 1/4 (1/2 · 1/8 = (1/4)²): the
        // recursion at 1/4 is singular although no root has modulus 1/4;
        // roots_above decides from the radii about it (1/2 above; 1/8, 1/16
        // below): Catmull–Clark's boundary at k = 1 has this cofactor
        let p = Poly::from_roots(&[q(1, 2), q(1, 8), q(1, 8), q(1, 16)]);
        assert_eq!(roots_outside_disc(&p, &q(1, 4)), None);
        assert_eq!(roots_above(&p, &q(1, 4)), Some(1));
        // a root of modulus exactly r stays undecided (−1/4 at r = 1/4)
        assert_eq!(roots_above(&Poly::from_roots(&[q(1, 2), q(-1, 4)]), &q(1, 4)), None);
    }

    /// A = B·C with B = [I_k; M] and C = [I_k | N]: its top-left k × k
    /// block is I_k and its columns are combinations of B's k columns, so
    /// its rank is k by construction, whatever M and N. Rows scaled by
    /// non-zero fractions and rows and columns shuffled keep the rank; the
    /// entries (fractions with denominators up to 9, signs mixed) make the
    /// integer elimination's rows long and their gcds non-trivial.
    #[test]
    fn integer_elimination_finds_the_rank_kernel_and_inverse_of_a_product_of_rank_k() {
        let mut state: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = |m: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % m
        };
        for trial in 0..200 {
            let rows = 1 + next(9) as usize;
            let cols = 1 + next(9) as usize;
            let k = next(rows.min(cols) as u64 + 1) as usize;
            let mut frac = |zero_share: u64| {
                if next(10) < zero_share {
                    q(0, 1)
                } else {
                    q(next(19) as i64 - 9, 1 + next(9) as i64)
                }
            };
            let b: Vec<Vec<Rational>> = (0..rows)
                .map(|i| (0..k).map(|j| if i < k { q((i == j) as i64, 1) } else { frac(3) }).collect())
                .collect();
            let c: Vec<Vec<Rational>> = (0..k)
                .map(|i| (0..cols).map(|j| if j < k { q((i == j) as i64, 1) } else { frac(3) }).collect())
                .collect();
            let mut a: Vec<Vec<Rational>> = (0..rows)
                .map(|i| (0..cols).map(|j| (0..k).fold(q(0, 1), |s, t| s + &b[i][t] * &c[t][j])).collect())
                .collect();
            for row in a.iter_mut() {
                let s = q(1 + next(7) as i64, 1 + next(5) as i64) * q(if next(2) == 0 { 1 } else { -1 }, 1);
                for x in row.iter_mut() {
                    *x = &*x * &s;
                }
            }
            for i in (1..rows).rev() {
                a.swap(i, next(i as u64 + 1) as usize);
            }
            let perm: Vec<usize> = {
                let mut p: Vec<usize> = (0..cols).collect();
                for i in (1..cols).rev() {
                    p.swap(i, next(i as u64 + 1) as usize);
                }
                p
            };
            let flat: Vec<Rational> = a.iter().flat_map(|row| perm.iter().map(|&j| row[j].clone())).collect();
            assert_eq!(rank_of(rows, cols, flat.clone()), k, "trial {trial}: {rows}×{cols} of rank {k}");
            assert_eq!(pivot_columns(rows, cols, flat.clone()).len(), k, "trial {trial}");
            // cols − k vectors, each with a 1 at its own free column (so
            // independent) and each mapped to zero
            let kernel = null_space(rows, cols, flat.clone());
            assert_eq!(kernel.len(), cols - k, "trial {trial}");
            for x in &kernel {
                for i in 0..rows {
                    let ax = (0..cols).fold(q(0, 1), |s, j| s + &flat[i * cols + j] * &x[j]);
                    assert!(ax.is_zero(), "trial {trial}: A x ≠ 0");
                }
            }
            // a square matrix of full rank has an inverse, A·A⁻¹ = I; one
            // of lower rank none
            if rows == cols {
                let inv = inverse(rows, &flat);
                assert_eq!(inv.is_some(), k == rows, "trial {trial}");
                if let Some(inv) = inv {
                    for i in 0..rows {
                        for j in 0..rows {
                            let e = (0..rows).fold(q(0, 1), |s, t| s + &flat[i * rows + t] * &inv[t * rows + j]);
                            assert_eq!(e, q((i == j) as i64, 1), "trial {trial}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn exact_rank_detects_jordan_block() {
        let mut a = QMatrix::zeros(2);
        a.set(0, 0, q(1, 4));
        a.set(1, 1, q(1, 4));
        a.set(0, 1, q(1, 1));
        assert_eq!(a.shifted(&q(1, 4)).rank(), 1);
    }
}
