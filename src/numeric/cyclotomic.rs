//! Exact arithmetic in cyclotomic fields Q(ζ_N), ζ_N = e^{2πi/N}: the weight
//! type that makes the certificate's premises exact where the weights hold
//! cos(2πk/n) (Loop, Doo–Sabin, Kobbelt's sqrt(3), ... at n ∉ {3, 4, 6}).
//!
//! An element of Q(ζ_N) is a polynomial in ζ_N with rational coefficients
//! of degree below φ(N), reduced modulo the N-th cyclotomic polynomial Φ_N,
//! the minimal polynomial of ζ_N over Q: the powers 1, ζ_N, ..., ζ_N^{φ(N)−1}
//! are a basis, so every element has exactly one such polynomial and
//! equality is equality of coefficients. Φ_N is computed exactly, as
//! x^N − 1 divided by Φ_d for every proper divisor d of N. The coefficients
//! are stored as integer numerators over one common positive denominator in
//! lowest terms (the same rationals as a list of fractions, at the cost of
//! one gcd per operation instead of one per coefficient).
//!
//! cos(2πk/n) = (ζ_n^k + ζ_n^{−k})/2 lies in Q(ζ_n). Every element carries
//! its own N (its *order*; rationals have N = 1, and an element whose
//! polynomial is a constant is stored as a rational): elements of Q(ζ_N) and
//! Q(ζ_M) combine in Q(ζ_L), L = lcm(N, M), through the embedding
//! ζ_N ↦ ζ_L^{L/N}.
//!
//! The *undefined* element: `Weight`'s operators return `Self`, so a quotient
//! by zero, a ratio p/0, or a field beyond [`MAX_ORDER`] (a cosine of a huge
//! n, the lcm of many unrelated n) cannot be an error. They give the
//! undefined element instead, which behaves like a NaN: every operation
//! involving it is undefined, it equals nothing (itself included), it is not
//! zero, and `to_f64` is NaN. Callers that decide with exact values check
//! [`Cyclotomic::is_defined`] (the certificate treats a row holding it as not
//! exact).

pub use super::cyclotomic_element::Cyclotomic;
use super::exact::Poly;
use super::weight::{gcd, rational_cos_2pi, Inexact, ParamValue, Rational, Weight};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::collections::HashMap;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::sync::{Arc, Mutex, OnceLock};

/// The largest N of a field Q(ζ_N) that elements live in (Φ_N of degree up
/// to φ(N) ≤ N − 1): past it cosines are `Err(Inexact)` and combinations
/// are undefined, so the cost of every operation stays bounded.
pub const MAX_ORDER: u64 = 1024;

/// Φ_N: its degree, the dense coefficients (lowest first) and the nonzero
/// terms below the leading one (x^d ≡ −Σ c_j x^j modulo Φ_N).
struct Phi {
    degree: usize,
    coeffs: Vec<BigInt>,
    low: Vec<(usize, i64)>,
}

fn phi(n: u32) -> Arc<Phi> {
    // every operation asks: a per-thread copy of the shared table's entries
    thread_local! {
        static LOCAL: std::cell::RefCell<HashMap<u32, Arc<Phi>>> = std::cell::RefCell::new(HashMap::new());
    }
    if let Some(p) = LOCAL.with(|m| m.borrow().get(&n).cloned()) {
        return p;
    }
    let p = shared_phi(n);
    LOCAL.with(|m| m.borrow_mut().insert(n, p.clone()));
    p
}

fn shared_phi(n: u32) -> Arc<Phi> {
    static CACHE: OnceLock<Mutex<HashMap<u32, Arc<Phi>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    if let Some(p) = cache.lock().unwrap_or_else(|e| e.into_inner()).get(&n) {
        return p.clone();
    }
    // x^n − 1 = Π_{d | n} Φ_d: divide out the proper divisors' (computed
    // outside the lock: they are found through this function)
    let mut p = vec![BigInt::zero(); n as usize + 1];
    p[0] = -BigInt::one();
    p[n as usize] = BigInt::one();
    for d in 1..n {
        if n.is_multiple_of(d) {
            p = divide_exactly(&p, &phi(d).coeffs);
        }
    }
    let degree = p.len() - 1;
    let low = p[..degree]
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.is_zero())
        .map(|(j, c)| (j, c.to_i64().expect("cyclotomic coefficients are small below MAX_ORDER")))
        .collect();
    let made = Arc::new(Phi { degree, coeffs: p, low });
    cache.lock().unwrap_or_else(|e| e.into_inner()).insert(n, made.clone());
    made
}

/// p / q for a monic integer q that divides p exactly.
fn divide_exactly(p: &[BigInt], q: &[BigInt]) -> Vec<BigInt> {
    let e = q.len() - 1;
    let mut r = p.to_vec();
    let mut quotient = vec![BigInt::zero(); p.len() - e];
    for i in (e..p.len()).rev() {
        let c = std::mem::take(&mut r[i]);
        if c.is_zero() {
            continue;
        }
        for (j, qj) in q[..e].iter().enumerate() {
            if !qj.is_zero() {
                r[i - e + j] -= &c * qj;
            }
        }
        quotient[i - e] = c;
    }
    debug_assert!(r.iter().all(Zero::is_zero), "Φ_d divides x^n − 1");
    quotient
}

/// The coefficients of Φ_n, lowest first (n ≥ 1).
pub fn cyclotomic_polynomial(n: u32) -> Vec<BigInt> {
    phi(n).coeffs.clone()
}

/// An integer polynomial (any degree) modulo Φ: degree below deg Φ.
fn reduce(mut p: Vec<BigInt>, phi: &Phi) -> Vec<BigInt> {
    let d = phi.degree;
    for i in (d..p.len()).rev() {
        if p[i].is_zero() {
            continue;
        }
        let c = std::mem::take(&mut p[i]);
        for &(j, a) in &phi.low {
            let t = &mut p[i - d + j];
            match a {
                1 => *t -= &c,
                -1 => *t += &c,
                _ => *t -= &c * a,
            }
        }
    }
    p.truncate(d);
    p
}

/// gcd(d, c_0, c_1, ...) for a positive d (`numeric::content`, which
/// finishes in machine words once the running gcd is one: almost every
/// denominator met in a subdivision matrix is).
fn content_gcd(d: &BigInt, cs: &[BigInt]) -> BigInt {
    super::content::content(std::iter::once(d).chain(cs))
}

/// The numerators of a·b reduced modulo Φ_l, computed in machine words when
/// every numerator fits an i64 (the rows of a local subdivision matrix are
/// products of small fractions: 1/4, 3/8, cosines' halves): the convolution
/// and the reduction in checked i128, `None` as soon as a step would
/// overflow, and then the caller multiplies in big integers. The same
/// integers either way — only where they are computed differs.
fn product_in_words(a: &[BigInt], b: &[BigInt], l: u32) -> Option<Vec<BigInt>> {
    let words = |v: &[BigInt]| v.iter().map(|x| x.to_i64().map(i128::from)).collect::<Option<Vec<i128>>>();
    let (a, b) = (words(a)?, words(b)?);
    let mut c = vec![0i128; a.len() + b.len() - 1];
    for (i, &x) in a.iter().enumerate().filter(|(_, x)| **x != 0) {
        for (j, &y) in b.iter().enumerate().filter(|(_, y)| **y != 0) {
            c[i + j] = c[i + j].checked_add(x * y)?;
        }
    }
    let phi = phi(l);
    let d = phi.degree;
    if c.len() > d {
        for i in (d..c.len()).rev() {
            let top = std::mem::take(&mut c[i]);
            if top == 0 {
                continue;
            }
            for &(j, a) in &phi.low {
                let t = &mut c[i - d + j];
                *t = t.checked_sub(top.checked_mul(a as i128)?)?;
            }
        }
        c.truncate(d);
    }
    Some(c.into_iter().map(BigInt::from).collect())
}

/// Σ t.num · (den / t.den) over the terms (one field, `den` a common
/// multiple of their denominators) in checked i128 when every numerator and
/// factor fits an i64; `None` when one does not or a sum leaves i128, and
/// the caller sums in big integers (see [`product_in_words`]).
fn sum_in_words(terms: &[Cyclotomic], den: &BigInt) -> Option<Vec<BigInt>> {
    let mut num: Vec<i128> = Vec::new();
    for t in terms {
        let factor = i128::from((den / &t.den).to_i64()?);
        if num.len() < t.num.len() {
            num.resize(t.num.len(), 0);
        }
        for (acc, c) in num.iter_mut().zip(&t.num) {
            *acc = acc.checked_add(i128::from(c.to_i64()?) * factor)?;
        }
    }
    Some(num.into_iter().map(BigInt::from).collect())
}

/// lcm(a, b) when within [`MAX_ORDER`].
fn common_order(a: u32, b: u32) -> Option<u32> {
    if a == b {
        return Some(a);
    }
    let (a64, b64) = (a as u64, b as u64);
    let l = a64 / (gcd(a as i64, b as i64) as u64) * b64;
    (l <= MAX_ORDER).then_some(l as u32)
}

impl Cyclotomic {
    /// The undefined element (see the module documentation).
    pub fn undefined() -> Cyclotomic {
        Cyclotomic { order: 0, num: Vec::new(), den: BigInt::one() }
    }

    /// The element (Σ num_i ζ_N^i) / den in lowest terms (num of any length:
    /// reduced modulo Φ_N here when longer than φ(N)).
    fn make(order: u32, mut num: Vec<BigInt>, mut den: BigInt) -> Cyclotomic {
        if order == 0 || den.is_zero() {
            return Cyclotomic::undefined();
        }
        // φ(N) ≥ 2 for N ≥ 3: shorter polynomials are reduced already
        if num.len() > 2 || (order <= 2 && num.len() > 1) {
            let phi = phi(order);
            if num.len() > phi.degree {
                num = reduce(num, &phi);
            }
        }
        while num.last().is_some_and(Zero::is_zero) {
            num.pop();
        }
        if num.is_empty() {
            return Cyclotomic::zero();
        }
        if den.is_negative() {
            den = -den;
            num.iter_mut().for_each(|c| *c = -std::mem::take(c));
        }
        let g = content_gcd(&den, &num);
        if !g.is_one() {
            num.iter_mut().for_each(|c| *c /= &g);
            den /= &g;
        }
        // a constant polynomial is a rational, whatever field it came from
        let order = if num.len() == 1 { 1 } else { order };
        Cyclotomic { order, num, den }
    }

    pub fn from_rational(q: &Rational) -> Cyclotomic {
        Cyclotomic::make(1, vec![q.numer().clone()], q.denom().clone())
    }

    /// ζ_n^k.
    pub fn root_of_unity(k: i64, n: i64) -> Result<Cyclotomic, Inexact> {
        if n <= 0 {
            return Err(Inexact);
        }
        let k = k.rem_euclid(n);
        let g = gcd(k, n).max(1);
        let (k, n) = (k / g, n / g);
        if n as u64 > MAX_ORDER {
            return Err(Inexact);
        }
        let mut num = vec![BigInt::zero(); k as usize + 1];
        num[k as usize] = BigInt::one();
        Ok(Cyclotomic::make(n as u32, num, BigInt::one()))
    }

    /// Whether the element is a number (not the undefined element).
    pub fn is_defined(&self) -> bool {
        self.order != 0
    }

    /// N of the field Q(ζ_N) the element is written in (1 for rationals);
    /// `None` for the undefined element.
    pub fn order(&self) -> Option<u32> {
        self.is_defined().then_some(self.order)
    }

    /// The value when it is rational.
    pub fn to_rational(&self) -> Option<Rational> {
        match (self.order, self.num.as_slice()) {
            (1, []) => Some(<Rational as Zero>::zero()),
            (1, [p]) => Some(Rational::new(p.clone(), self.den.clone())),
            _ => None,
        }
    }

    /// The nonzero coefficients (i, c_i) of the element Σ c_i ζ_N^i.
    pub fn coefficients(&self) -> impl Iterator<Item = (usize, Rational)> + '_ {
        self.num
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(i, c)| (i, Rational::new(c.clone(), self.den.clone())))
    }

    /// The size of the element: the bits of its largest numerator plus
    /// those of its denominator (for bounding the cost of a computation).
    pub fn bits(&self) -> u64 {
        self.num.iter().map(|c| c.bits()).max().unwrap_or(0) + self.den.bits()
    }

    /// The numerators over `self.den` in Q(ζ_l), l a multiple of the order,
    /// through ζ_N = ζ_l^{l/N}.
    fn numerators_in(&self, l: u32) -> Vec<BigInt> {
        if self.order == l || self.order == 1 {
            return self.num.clone();
        }
        let step = (l / self.order) as usize;
        let mut p = vec![BigInt::zero(); (self.num.len() - 1) * step + 1];
        for (i, c) in self.num.iter().enumerate() {
            p[i * step] = c.clone();
        }
        reduce(p, &phi(l))
    }

    /// The same element written in Q(ζ_l) (l a multiple of the order),
    /// normalised: for comparing elements of different fields.
    fn embedded(&self, l: u32) -> Cyclotomic {
        Cyclotomic::make(l, self.numerators_in(l), self.den.clone())
    }

    /// The complex conjugate (ζ ↦ ζ^{−1}).
    pub fn conj(&self) -> Cyclotomic {
        if !self.is_defined() || self.order <= 2 {
            return self.clone();
        }
        let n = self.order as usize;
        let mut p = vec![BigInt::zero(); n];
        for (i, c) in self.num.iter().enumerate() {
            p[(n - i) % n] = c.clone();
        }
        Cyclotomic::make(self.order, p, self.den.clone())
    }

    /// Whether the element is a real number (equals its conjugate).
    pub fn is_real(&self) -> bool {
        self.is_defined() && self.conj() == *self
    }

    /// Real and imaginary parts in floating point (Σ c_i ζ^i with ζ^i
    /// evaluated by cos and sin; not correctly rounded).
    pub fn to_complex(&self) -> (f64, f64) {
        if !self.is_defined() {
            return (f64::NAN, f64::NAN);
        }
        let n = self.order as i64;
        let (mut re, mut im) = (0.0, 0.0);
        for (i, c) in self.num.iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let q = ToPrimitive::to_f64(&Rational::new(c.clone(), self.den.clone())).unwrap_or(f64::NAN);
            let cos = <f64 as Weight>::cos_2pi(i as i64, n).unwrap_or(f64::NAN);
            let sin = (2.0 * std::f64::consts::PI * i as f64 / n as f64).sin();
            re += q * cos;
            im += q * sin;
        }
        (re, im)
    }

    /// The multiplicative inverse (zero and the undefined element: undefined).
    /// By the extended Euclidean algorithm over Q on the element's polynomial
    /// and Φ_N, coprime because Φ_N is irreducible.
    pub fn inverse(&self) -> Cyclotomic {
        if !self.is_defined() || self.is_zero() {
            return Cyclotomic::undefined();
        }
        if self.order == 1 {
            return Cyclotomic::make(1, vec![self.den.clone()], self.num[0].clone());
        }
        let phi = phi(self.order);
        let to_poly = |num: &[BigInt], den: &BigInt| Poly {
            coeffs: num.iter().map(|c| Rational::new(c.clone(), den.clone())).collect(),
        };
        let (mut r0, mut r1) = (to_poly(&phi.coeffs, &BigInt::one()), to_poly(&self.num, &self.den));
        let (mut s0, mut s1) = (Poly { coeffs: vec![<Rational as Zero>::zero()] }, Poly::one());
        while !r1.is_zero() {
            let (q, r) = r0.div_rem(&r1);
            let s = s0.sub(&poly_mul(&q, &s1));
            (r0, r1) = (r1, r);
            (s0, s1) = (s1, s);
        }
        // r0 is the gcd, a nonzero constant c: the element times s0 is c
        let c = r0.coeffs.iter().rev().find(|c| !Zero::is_zero(*c)).cloned();
        let (Some(c), 0) = (c, r0.degree()) else {
            return Cyclotomic::undefined();
        };
        let coeffs: Vec<Rational> = s0.coeffs.iter().map(|x| x / &c).collect();
        let den = coeffs.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
        let num = coeffs.iter().map(|x| x.numer() * (&den / x.denom())).collect();
        Cyclotomic::make(self.order, num, den)
    }

    /// x · q for a rational q given as p/d (d ≠ 0).
    fn scaled(&self, p: &BigInt, d: &BigInt) -> Cyclotomic {
        if p.is_one() && d.is_one() {
            return self.clone();
        }
        if d.is_one() && !p.is_zero() && self.is_defined() {
            // (num/den)·p in lowest terms without a pass over the numerators:
            // with g = gcd(den, p), num·(p/g) / (den/g) is reduced already
            let g = self.den.gcd(p);
            let (p, den) = (p / &g, &self.den / &g);
            let num = if p.is_one() { self.num.clone() } else { self.num.iter().map(|c| c * &p).collect() };
            return Cyclotomic { order: self.order, num, den };
        }
        Cyclotomic::make(self.order, self.num.iter().map(|c| c * p).collect(), &self.den * d)
    }

    /// The same representation (same field, same coefficients): a cheap
    /// sufficient test of equality.
    fn identical(&self, o: &Cyclotomic) -> bool {
        self.order == o.order && self.den == o.den && self.num == o.num
    }

    fn sum(&self, o: &Cyclotomic) -> Cyclotomic {
        if !self.is_defined() || !o.is_defined() {
            return Cyclotomic::undefined();
        }
        if o.is_zero() {
            return self.clone();
        }
        if self.is_zero() {
            return o.clone();
        }
        let Some(l) = common_order(self.order, o.order) else {
            return Cyclotomic::undefined();
        };
        let (mut a, b) = (self.numerators_in(l), o.numerators_in(l));
        // a/da + b/db = (a·(db/g) + b·(da/g)) / (da·db/g), g = gcd(da, db)
        let g = content_gcd(&self.den, std::slice::from_ref(&o.den));
        let (fa, fb) = if g.is_one() { (o.den.clone(), self.den.clone()) } else { (&o.den / &g, &self.den / &g) };
        let den = &self.den * &fa;
        if !fa.is_one() {
            a.iter_mut().for_each(|c| *c *= &fa);
        }
        if a.len() < b.len() {
            a.resize(b.len(), BigInt::zero());
        }
        for (x, y) in a.iter_mut().zip(&b) {
            if fb.is_one() {
                *x += y;
            } else {
                *x += y * &fb;
            }
        }
        Cyclotomic::make(l, a, den)
    }

    fn product(&self, o: &Cyclotomic) -> Cyclotomic {
        if !self.is_defined() || !o.is_defined() {
            return Cyclotomic::undefined();
        }
        if self.is_zero() || o.is_zero() {
            return Cyclotomic::zero();
        }
        if self.order == 1 {
            return o.scaled(&self.num[0], &self.den);
        }
        if o.order == 1 {
            return self.scaled(&o.num[0], &o.den);
        }
        // rules ask for the same product once per slot (Loop's β² at every
        // neighbour of the centre): the last few products are kept per thread
        if let Some(p) = RECENT_PRODUCTS.with(|r| {
            r.borrow()
                .iter()
                .find(|(x, y, _)| (x.identical(self) && y.identical(o)) || (x.identical(o) && y.identical(self)))
                .map(|e| e.2.clone())
        }) {
            return p;
        }
        let Some(l) = common_order(self.order, o.order) else {
            return Cyclotomic::undefined();
        };
        let (a, b) = (self.numerators_in(l), o.numerators_in(l));
        let c = product_in_words(&a, &b, l).unwrap_or_else(|| {
            let mut c = vec![BigInt::zero(); a.len() + b.len() - 1];
            for (i, x) in a.iter().enumerate().filter(|(_, x)| !Zero::is_zero(*x)) {
                for (j, y) in b.iter().enumerate().filter(|(_, y)| !Zero::is_zero(*y)) {
                    c[i + j] += x * y;
                }
            }
            c
        });
        let p = Cyclotomic::make(l, c, &self.den * &o.den);
        RECENT_PRODUCTS.with(|r| {
            let mut r = r.borrow_mut();
            if r.len() == RECENT {
                r.pop_front();
            }
            r.push_back((self.clone(), o.clone(), p.clone()));
        });
        p
    }

    fn quotient(&self, o: &Cyclotomic) -> Cyclotomic {
        if !self.is_defined() || !o.is_defined() || o.is_zero() {
            return Cyclotomic::undefined();
        }
        if o.order == 1 {
            return self.scaled(&o.den, &o.num[0]);
        }
        self.product(&o.inverse())
    }
}

/// a · b for rational polynomials.
fn poly_mul(a: &Poly, b: &Poly) -> Poly {
    if a.coeffs.is_empty() || b.coeffs.is_empty() {
        return Poly { coeffs: vec![<Rational as Zero>::zero()] };
    }
    let mut c = vec![<Rational as Zero>::zero(); a.coeffs.len() + b.coeffs.len() - 1];
    for (i, x) in a.coeffs.iter().enumerate().filter(|(_, x)| !Zero::is_zero(*x)) {
        for (j, y) in b.coeffs.iter().enumerate().filter(|(_, y)| !Zero::is_zero(*y)) {
            c[i + j] += x * y;
        }
    }
    Poly { coeffs: c }
}

/// Equal field elements (elements of different fields compared in the field
/// of the lcm of their orders). The undefined element equals nothing.
impl PartialEq for Cyclotomic {
    fn eq(&self, o: &Cyclotomic) -> bool {
        if !self.is_defined() || !o.is_defined() {
            return false;
        }
        if self.order == o.order {
            return self.num == o.num && self.den == o.den;
        }
        let Some(l) = common_order(self.order, o.order) else {
            return false;
        };
        let (a, b) = (self.embedded(l), o.embedded(l));
        a.num == b.num && a.den == b.den
    }
}

impl Add for Cyclotomic {
    type Output = Cyclotomic;
    fn add(self, o: Cyclotomic) -> Cyclotomic {
        self.sum(&o)
    }
}

impl Sub for Cyclotomic {
    type Output = Cyclotomic;
    fn sub(self, o: Cyclotomic) -> Cyclotomic {
        self.sum(&-o)
    }
}

impl Mul for Cyclotomic {
    type Output = Cyclotomic;
    fn mul(self, o: Cyclotomic) -> Cyclotomic {
        self.product(&o)
    }
}

/// Division; by zero (or by the undefined element) it gives the undefined
/// element, never a panic.
impl Div for Cyclotomic {
    type Output = Cyclotomic;
    fn div(self, o: Cyclotomic) -> Cyclotomic {
        self.quotient(&o)
    }
}

impl Neg for Cyclotomic {
    type Output = Cyclotomic;
    fn neg(mut self) -> Cyclotomic {
        self.num.iter_mut().for_each(|c| *c = -std::mem::take(c));
        self
    }
}

/// `(3 + 2·ζ_5 − ζ_5^3)/8`, `3/8`, `undefined`.
impl fmt::Display for Cyclotomic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.is_defined() {
            return write!(f, "undefined");
        }
        if let Some(q) = self.to_rational() {
            return write!(f, "{q}");
        }
        let mut s = String::new();
        for (i, c) in self.num.iter().enumerate().filter(|(_, c)| !c.is_zero()) {
            let sign = if c.is_negative() { "-" } else { "+" };
            if s.is_empty() {
                if c.is_negative() {
                    s.push('-');
                }
            } else {
                s.push_str(&format!(" {sign} "));
            }
            let a = c.abs();
            let power = match i {
                0 => String::new(),
                1 => format!("ζ_{}", self.order),
                _ => format!("ζ_{}^{i}", self.order),
            };
            match (i, a.is_one()) {
                (0, _) => s.push_str(&a.to_string()),
                (_, true) => s.push_str(&power),
                _ => s.push_str(&format!("{a}·{power}")),
            }
        }
        if self.den.is_one() {
            write!(f, "{s}")
        } else {
            write!(f, "({s})/{}", self.den)
        }
    }
}

thread_local! {
    /// cos(2πk/n) by reduced (k, n): rules ask for the same cosine once per
    /// slot, and each costs a reduction modulo Φ_n.
    static COSINES: std::cell::RefCell<HashMap<(i64, i64), Cyclotomic>> = std::cell::RefCell::new(HashMap::new());
}

/// Products of two irrational elements kept per thread.
const RECENT: usize = 4;

thread_local! {
    /// The last products of two irrational elements: comparing operands costs
    /// φ(N) coefficient comparisons, a product φ(N)² multiplications.
    static RECENT_PRODUCTS: std::cell::RefCell<std::collections::VecDeque<(Cyclotomic, Cyclotomic, Cyclotomic)>> =
        const { std::cell::RefCell::new(std::collections::VecDeque::new()) };
}

/// Cosines kept per thread before the cache starts afresh.
const COSINE_CACHE: usize = 4096;

impl Weight for Cyclotomic {
    const SUMS_IN_BATCHES: bool = true;

    /// One common denominator and one normalisation for the whole sum,
    /// where adding in turn takes a gcd of every partial sum's content (the
    /// rows of a cyclotomic local matrix are long sums of products). Only
    /// when the terms lie in Q(ζ_l) for one l (rationals and elements of one
    /// field): the result is then the normalised element of Q(ζ_l), or a
    /// rational, exactly what adding in turn gives. Terms from several
    /// fields are added in turn, so the field the sum is written in stays
    /// the one adding in turn reaches.
    fn sum_all(terms: Vec<Self>) -> Self {
        if terms.iter().any(|t| !t.is_defined()) {
            return Cyclotomic::undefined();
        }
        let terms: Vec<Cyclotomic> = terms.into_iter().filter(|t| !t.is_zero()).collect();
        let mut orders = terms.iter().map(|t| t.order).filter(|&o| o != 1);
        let l = orders.next().unwrap_or(1);
        if terms.len() < 3 || orders.any(|o| o != l) {
            return terms.into_iter().fold(Cyclotomic::zero(), |a, b| a + b);
        }
        let mut den = BigInt::one();
        for t in &terms {
            let g = den.gcd(&t.den);
            den = &den / &g * &t.den;
        }
        let num = match sum_in_words(&terms, &den) {
            Some(num) => num,
            None => {
                let mut num: Vec<BigInt> = Vec::new();
                for t in &terms {
                    let factor = &den / &t.den;
                    if num.len() < t.num.len() {
                        num.resize(t.num.len(), BigInt::zero());
                    }
                    for (acc, c) in num.iter_mut().zip(&t.num) {
                        *acc += c * &factor;
                    }
                }
                num
            }
        };
        Cyclotomic::make(l, num, den)
    }

    fn zero() -> Self {
        Cyclotomic { order: 1, num: Vec::new(), den: BigInt::one() }
    }
    fn one() -> Self {
        Cyclotomic { order: 1, num: vec![BigInt::one()], den: BigInt::one() }
    }
    /// p/q; q = 0 gives the undefined element.
    fn ratio(p: i64, q: i64) -> Self {
        Cyclotomic::make(1, vec![BigInt::from(p)], BigInt::from(q))
    }
    /// (ζ_n^k + ζ_n^{−k})/2 in Q(ζ_n), n the reduced denominator of k/n
    /// (rational values as rationals); `Err(Inexact)` for n ≤ 0 or a reduced n
    /// beyond [`MAX_ORDER`].
    fn cos_2pi(k: i64, n: i64) -> Result<Self, Inexact> {
        if n <= 0 {
            return Err(Inexact);
        }
        let k = k.rem_euclid(n);
        let g = gcd(k, n).max(1);
        let (k, n) = (k / g, n / g);
        if let Some((p, q)) = rational_cos_2pi(k, n) {
            return Ok(Cyclotomic::ratio(p, q));
        }
        if n as u64 > MAX_ORDER {
            return Err(Inexact);
        }
        if let Some(c) = COSINES.with(|m| m.borrow().get(&(k, n)).cloned()) {
            return Ok(c);
        }
        let mut num = vec![BigInt::zero(); n as usize];
        num[k as usize] += 1;
        num[(n - k) as usize] += 1;
        let c = Cyclotomic::make(n as u32, num, BigInt::from(2));
        COSINES.with(|m| {
            let mut m = m.borrow_mut();
            if m.len() >= COSINE_CACHE {
                m.clear();
            }
            m.insert((k, n), c.clone());
        });
        Ok(c)
    }
    /// Square roots of rational squares only.
    fn sqrt(&self) -> Result<Self, Inexact> {
        let q = self.to_rational().ok_or(Inexact)?;
        Ok(Cyclotomic::from_rational(&Weight::sqrt(&q)?))
    }
    /// Exact (rational) parameters only.
    fn param(p: &ParamValue) -> Result<Self, Inexact> {
        p.exact.as_ref().map(Cyclotomic::from_rational).ok_or(Inexact)
    }
    /// The real part, Σ c_i cos(2πi/N) in floating point (approximate).
    fn to_f64(&self) -> f64 {
        self.to_complex().0
    }
    fn is_zero(&self) -> bool {
        self.is_defined() && self.num.is_empty()
    }
    fn from_cyclotomic(c: &Cyclotomic) -> Result<Self, Inexact> {
        Ok(c.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Cyclotomic {
        Cyclotomic::ratio(p, d)
    }
    fn cos(k: i64, n: i64) -> Cyclotomic {
        Cyclotomic::cos_2pi(k, n).unwrap()
    }

    /// The word-size product is the big-integer product: the same reduced
    /// numerators for small inputs in fields with Φ_N of coefficients other
    /// than ±1 (N = 105, the first such), and `None` — never a wrapped
    /// value — where a step leaves i128.
    #[test]
    fn products_in_words_are_the_big_integer_products() {
        let big = |a: &[BigInt], b: &[BigInt], l: u32| {
            let mut c = vec![BigInt::zero(); a.len() + b.len() - 1];
            for (i, x) in a.iter().enumerate() {
                for (j, y) in b.iter().enumerate() {
                    c[i + j] += x * y;
                }
            }
            let phi = phi(l);
            if c.len() > phi.degree {
                c = reduce(c, &phi);
            }
            c
        };
        for l in [5u32, 12, 23, 105] {
            let d = phi(l).degree;
            let a: Vec<BigInt> = (0..d).map(|i| BigInt::from((i as i64 * 7919) % 23 - 11)).collect();
            let b: Vec<BigInt> = (0..d).map(|i| BigInt::from((i as i64 * 104729) % 17 - 8)).collect();
            assert_eq!(product_in_words(&a, &b, l), Some(big(&a, &b, l)), "Q(ζ_{l})");
        }
        // i64::MAX² summed twice leaves i128: refused, not wrapped
        let huge = vec![BigInt::from(i64::MAX); 3];
        assert_eq!(product_in_words(&huge, &huge, 5), None);
        // a numerator beyond i64 is refused before any product
        let beyond = vec![BigInt::from(i64::MAX) * 2, BigInt::one()];
        assert_eq!(product_in_words(&beyond, &[BigInt::one(), BigInt::one()], 5), None);
        // and the element product still goes through: (2^64 − 2 + ζ)(1 + ζ) by the big path
        let x = Cyclotomic::make(5, beyond.clone(), BigInt::one());
        let y = Cyclotomic::make(5, vec![BigInt::one(), BigInt::one()], BigInt::one());
        assert_eq!(Cyclotomic::make(5, big(&beyond, &[BigInt::one(), BigInt::one()], 5), BigInt::one()), x * y);
    }

    /// A batch sum is the same element, written the same way (field,
    /// numerators, denominator), as adding in turn: 1 + 2cos(2π/5) +
    /// 2cos(4π/5) = 0 (the sum of the fifth roots of unity), plus 1/2, collapses to a
    /// rational; terms of two fields take the in-turn path.
    #[test]
    fn sums_at_once_are_sums_in_turn() {
        let in_turn = |t: &[Cyclotomic]| t.iter().cloned().fold(Cyclotomic::zero(), |a, b| a + b);
        let cases: Vec<Vec<Cyclotomic>> = vec![
            vec![q(1, 3), cos(1, 7) * q(5, 4), cos(2, 7), q(-2, 9), cos(3, 7) * q(1, 6)],
            vec![q(1, 1), cos(1, 5) * q(2, 1), cos(2, 5) * q(2, 1), q(0, 1), q(1, 2)],
            vec![cos(1, 5), cos(1, 3), cos(1, 4), q(3, 8)],
            vec![q(1, 2), q(1, 3), q(1, 6)],
            vec![cos(1, 9), -cos(1, 9), cos(2, 9) * q(7, 3)],
        ];
        for t in &cases {
            let (a, b) = (Cyclotomic::sum_all(t.clone()), in_turn(t));
            assert!(a.identical(&b), "{t:?}: {a:?} vs {b:?}");
        }
        let five = Cyclotomic::sum_all(cases[1].clone());
        assert!(five.identical(&q(1, 2)), "{five:?}"); // 0 + 0 + 1/2
        let undefined = Cyclotomic::sum_all(vec![q(1, 2), q(1, 0), cos(1, 7)]);
        assert!(!undefined.is_defined());
    }

    #[test]
    fn cyclotomic_polynomials_of_small_orders() {
        let int = |v: &[i64]| v.iter().map(|&c| BigInt::from(c)).collect::<Vec<_>>();
        assert_eq!(cyclotomic_polynomial(1), int(&[-1, 1]));
        assert_eq!(cyclotomic_polynomial(2), int(&[1, 1]));
        assert_eq!(cyclotomic_polynomial(4), int(&[1, 0, 1]));
        assert_eq!(cyclotomic_polynomial(5), int(&[1, 1, 1, 1, 1]));
        assert_eq!(cyclotomic_polynomial(6), int(&[1, -1, 1]));
        assert_eq!(cyclotomic_polynomial(12), int(&[1, 0, -1, 0, 1]));
        // Φ_105 is the first with a coefficient −2 (at x^7 and x^41)
        let p = cyclotomic_polynomial(105);
        assert_eq!(p.len(), 49);
        assert_eq!(p[7], BigInt::from(-2));
        assert_eq!(p[41], BigInt::from(-2));
        // the degree is φ(n)
        for (n, totient) in [(50, 20), (49, 42), (97, 96), (360, 96)] {
            assert_eq!(cyclotomic_polynomial(n).len() - 1, totient, "n = {n}");
        }
    }

    #[test]
    fn cosines_sum_to_zero_and_satisfy_their_minimal_polynomials() {
        for n in 2..=60 {
            let sum = (0..n).fold(Cyclotomic::zero(), |s, k| s + cos(k, n));
            assert!(sum.is_zero(), "n = {n}: {sum}");
        }
        // 2cos(2π/5) = (√5 − 1)/2: x² + x − 1 = 0 at x = 2cos(2π/5)
        let x = q(2, 1) * cos(1, 5);
        assert!((x.clone() * x.clone() + x - q(1, 1)).is_zero());
        // cos(2π/8)² = 1/2, cos(2π/7) a root of 8x³ + 4x² − 4x − 1
        assert_eq!(cos(1, 8) * cos(1, 8), q(1, 2));
        let c = cos(1, 7);
        let p = q(8, 1) * c.clone() * c.clone() * c.clone() + q(4, 1) * c.clone() * c.clone() - q(4, 1) * c - q(1, 1);
        assert!(p.is_zero(), "{p}");
        // double angles across fields: cos(4π/n) = 2cos²(2π/n) − 1
        for n in [5, 7, 9, 10, 12, 50] {
            let c = cos(1, n);
            assert_eq!(cos(2, n), q(2, 1) * c.clone() * c - q(1, 1), "n = {n}");
        }
    }

    #[test]
    fn inverses_and_division() {
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((seed >> 33) % 19) as i64 - 9
        };
        for n in [3u32, 5, 7, 8, 12, 15, 50] {
            for _ in 0..5 {
                let deg = phi(n).degree;
                let num: Vec<BigInt> = (0..deg).map(|_| BigInt::from(next())).collect();
                let x = Cyclotomic::make(n, num, BigInt::from(next().abs() + 1));
                if x.is_zero() {
                    continue;
                }
                assert_eq!(x.clone() * x.inverse(), q(1, 1), "n = {n}: {x}");
                assert_eq!(q(3, 7) / x.clone() * x, q(3, 7));
            }
        }
        // division by zero and p/0 are undefined, and the undefined element propagates
        let u = cos(1, 5) / Cyclotomic::zero();
        assert!(!u.is_defined() && !u.is_zero() && u != u);
        assert!(!(u.clone() + q(1, 1)).is_defined());
        assert!(!(q(0, 1) * u.clone()).is_defined());
        assert!(!Cyclotomic::ratio(1, 0).is_defined());
        assert!(u.to_f64().is_nan());
    }

    #[test]
    fn embedding_preserves_values() {
        for (n, k) in [(5, 1), (5, 2), (7, 3), (12, 5), (25, 4)] {
            let c = cos(k, n);
            let e = c.embedded(2 * n as u32);
            assert_eq!(e.order(), Some(2 * n as u32));
            approx::assert_abs_diff_eq!(e.to_f64(), c.to_f64(), epsilon = 1e-14);
            approx::assert_abs_diff_eq!(
                c.to_f64(),
                (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos(),
                epsilon = 1e-14
            );
            assert_eq!(e, c);
        }
        // cos(2π/5) + cos(2π/3) lives in Q(ζ_5), with cos(2π/10) in Q(ζ_10)
        let s = cos(1, 5) + cos(1, 10);
        assert_eq!(s.order(), Some(10));
        approx::assert_abs_diff_eq!(
            s.to_f64(),
            (0.4 * std::f64::consts::PI).cos() + (0.2 * std::f64::consts::PI).cos(),
            epsilon = 1e-14
        );
        // cos(2π/10) = −cos(2π·3/10)... and cos(2π/10) = −cos(2π·2/5)
        assert_eq!(cos(1, 10), -cos(2, 5));
    }

    #[test]
    fn conjugates_and_realness() {
        let i = Cyclotomic::root_of_unity(1, 4).unwrap();
        assert_eq!(i.clone() * i.clone(), q(-1, 1));
        assert!(!i.is_real());
        assert_eq!(i.conj(), -i);
        assert!(cos(2, 9).is_real());
        let z = Cyclotomic::root_of_unity(1, 7).unwrap();
        let (re, im) = z.to_complex();
        approx::assert_abs_diff_eq!(re, (2.0 * std::f64::consts::PI / 7.0).cos(), epsilon = 1e-14);
        approx::assert_abs_diff_eq!(im, (2.0 * std::f64::consts::PI / 7.0).sin(), epsilon = 1e-14);
        assert_eq!(z.clone() * z.conj(), q(1, 1));
    }

    #[test]
    fn square_roots_of_rational_squares_only() {
        assert_eq!(Weight::sqrt(&q(9, 4)).unwrap(), q(3, 2));
        assert!(Weight::sqrt(&q(2, 1)).is_err());
        assert!(Weight::sqrt(&cos(1, 5)).is_err());
        assert!(Cyclotomic::cos_2pi(1, MAX_ORDER as i64 + 1).is_err());
        assert_eq!(Cyclotomic::cos_2pi(3, 12).unwrap(), q(0, 1));
    }

    #[test]
    fn display() {
        assert_eq!(q(3, 8).to_string(), "3/8");
        // cos(2π/5) = (ζ + ζ⁴)/2 and ζ⁴ = −1 − ζ − ζ² − ζ³ modulo Φ_5
        assert_eq!(cos(1, 5).to_string(), "(-1 - ζ_5^2 - ζ_5^3)/2");
        assert_eq!((q(2, 1) * cos(1, 12)).to_string(), "2·ζ_12 - ζ_12^3");
    }
}
