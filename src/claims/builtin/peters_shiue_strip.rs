//! Peters–Shiue's 4-3 transition strip (Lemma 3.3, `claims/peters-shiue.toml`):
//! S and the shifted S⁺ on a planar window around a 4-3 node, exactly: the
//! defective eigenvalue, the block triangular form of V⁻¹ S⁺ V, the
//! 1/2-eigenvectors of S⁺ and the joint spectral radius bound.

use std::sync::Arc;

use num_traits::Zero;

use crate::claims::builtin::data::{
    exact, field, int_in, ints, lattice_node, not_decided, small_window, text, MAX_DATA_WINDOW,
};
use crate::claims::verdict::Finding;
use crate::engine::memo::Memo;
use crate::error::Error;
use crate::numeric::exact::q;
use crate::numeric::Rational;
use crate::spectrum::fmt_f;

// ---------------------------------------------------------------- Peters–Shiue: the 4-3 transition strip

struct Strip {
    s: Vec<Vec<Rational>>,
    s_plus: Vec<Vec<Rational>>,
    leading: Vec<Rational>,
    window: String,
}

/// The strip claims' shared work. The four Lemma 3.3 claims and the
/// transition-curve claim of `claims/peters-shiue.toml` read one strip (the
/// same scheme, node, window and shift), and its exact eigenvectors and the
/// 2^11 products of the JSR bound are most of each claim's time: each is made
/// once per data and shared. Keyed by the data without the fields that only
/// say what to compare (`length` and `bound` do not change the strip).
static STRIPS: Memo<Strip> = Memo::new(64 << 20);
static EIGENBASES: Memo<Vec<Vec<Rational>>> = Memo::new(64 << 20);
static JSR: Memo<crate::spectrum::strip::JsrBounds> = Memo::new(1 << 20);

fn strip_key(data: &toml::Value) -> String {
    let mut table = data.as_table().cloned().unwrap_or_default();
    table.remove("length");
    table.remove("bound");
    toml::Value::Table(table).to_string()
}

/// Bytes a matrix of rationals holds, about (for the memo's budget).
fn rational_bytes(rows: &[Vec<Rational>]) -> usize {
    rows.iter()
        .map(|r| r.iter().map(|x| 32 + 8 * (x.numer().bits() + x.denom().bits()) as usize / 64).sum::<usize>())
        .sum()
}

fn strip(data: &toml::Value) -> Result<Arc<Strip>, Error> {
    STRIPS.get_or_try_insert(
        strip_key(data),
        || make_strip(data),
        |st| rational_bytes(&st.s) + rational_bytes(&st.s_plus),
    )
}

/// S (window to the same positions) and S⁺ (shifted by `shift`) on the window
/// [x0, x1] × [y0, y1] of the planar lattice around the node `faces`.
fn make_strip(data: &toml::Value) -> Result<Strip, Error> {
    use crate::spectrum::strip::window_matrices;
    let (scheme, config, spokes) = lattice_node(data)?;
    let w = small_window(data, MAX_DATA_WINDOW)?;
    let t = ints(data, "shift")?;
    if t.len() != 2 || t.iter().any(|x| x.abs() > 16) {
        return Err(Error::Claim("data.shift is [dx, dy] with |dx|, |dy| <= 16".into()));
    }
    let window: Vec<[i64; 2]> = (w[2]..=w[3]).flat_map(|y| (w[0]..=w[1]).map(move |x| [x, y])).collect();
    let mut m = window_matrices(scheme.as_ref(), &config, &spokes, &window, &[[0, 0], [t[0], t[1]]])?;
    let s_plus = m.pop().expect("two matrices");
    let s = m.pop().expect("two matrices");
    let leading = field(data, "leading")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.leading: eigenvalues as strings".into()))?
        .iter()
        .map(|v| v.as_str().ok_or_else(|| Error::Claim("data.leading: strings".to_string())).and_then(exact))
        .collect::<Result<_, _>>()?;
    let label = format!("L = [{}, {}] × [{}, {}] ({} points)", w[0], w[1], w[2], w[3], window.len());
    Ok(Strip { s, s_plus, leading, window: label })
}

/// Lemma 3.3: "V ... corresponding to the integer grid L is not of full rank":
/// S on L has fewer independent eigenvectors than points (a defective eigenvalue).
pub fn strip_defective(data: &toml::Value) -> Result<Finding, Error> {
    let st = strip(data)?;
    let n = st.s.len();
    let (spec, irrational) = crate::spectrum::strip::rational_spectrum(&st.s)?;
    if irrational > 0 {
        return Err(Error::Undecided(format!(
            "{irrational} eigenvalues are not rational; geometric multiplicities not decided"
        )));
    }
    let rank: usize = spec.iter().map(|e| e.2).sum();
    let defective: Vec<String> =
        spec.iter().filter(|e| e.2 < e.1).map(|e| format!("{} (algebraic {}, geometric {})", e.0, e.1, e.2)).collect();
    let all: Vec<String> = spec.iter().map(|e| format!("{}^{}", e.0, e.1)).collect();
    Ok(Finding::new(
        rank < n,
        format!("the eigenvectors of S on {} do not span R^{n}", st.window),
        format!("{rank} independent eigenvectors for {n} points"),
        format!(
            "exact spectrum {}; defective: {}",
            all.join(" "),
            if defective.is_empty() { "none".into() } else { defective.join(", ") }
        ),
    ))
}

fn eigenbasis(data: &toml::Value, st: &Strip) -> Result<Arc<Vec<Vec<Rational>>>, Error> {
    EIGENBASES.get_or_try_insert(strip_key(data), || make_eigenbasis(st), |b| rational_bytes(b))
}

fn make_eigenbasis(st: &Strip) -> Result<Vec<Vec<Rational>>, Error> {
    let basis = crate::spectrum::strip::exact_eigenvectors(&st.s, &st.leading);
    if basis.len() != st.leading.len() {
        return Err(Error::Claim(format!(
            "the leading eigenvalues have {} independent eigenvectors, not {}",
            basis.len(),
            st.leading.len()
        )));
    }
    Ok(basis)
}

/// Lemma 3.3: V⁻¹ S⁺ V is block upper triangular: the span of the leading
/// eigenvectors of S is invariant under S⁺, which acts on it upper
/// triangularly with the same diagonal (1, 1/2, 1/2, d = I/4), and the rest
/// (Q⁺) is of the remaining size.
pub fn strip_structure(data: &toml::Value) -> Result<Finding, Error> {
    let st = strip(data)?;
    let basis = eigenbasis(data, &st)?;
    let k = basis.len();
    let Some(a) = crate::spectrum::strip::action_on(&st.s_plus, &basis) else {
        return Ok(Finding::new(
            false,
            "V⁻¹ S⁺ V = [[1, m1, m2, *], [0, 1/2, 0, *], [0, 0, 1/2, *], [0, 0, 0, d], Q⁺], d = I/4".into(),
            "the span of the leading eigenvectors of S is not invariant under S⁺".into(),
            "exact: [W | S⁺ W] has rank above that of W".into(),
        ));
    };
    let mut bad = Vec::new();
    for (i, row) in a.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            let want_zero = j < i || (i != j && st.leading[i] == st.leading[j] && i > 0);
            if i == j && *x != st.leading[i] {
                bad.push(format!("diagonal {i}: {x}, not {}", st.leading[i]));
            } else if want_zero && !x.is_zero() {
                bad.push(format!("({i}, {j}) = {x}, not 0"));
            }
        }
    }
    let shown: Vec<String> =
        a.iter().map(|r| format!("[{}]", r.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", "))).collect();
    Ok(Finding::new(
        bad.is_empty(),
        format!(
            "on {}: V⁻¹ S⁺ V upper block triangular with diagonal ({}), Q⁺ of size {}",
            st.window,
            st.leading.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", "),
            st.s.len() - k
        ),
        format!("S⁺ on the leading eigenvectors: {}", shown.join(", ")),
        if bad.is_empty() {
            format!(
                "exact: the span is invariant under S⁺ and the action has the printed form; Q⁺ is {0}×{0}",
                st.s.len() - k
            )
        } else {
            bad.join("; ")
        },
    ))
}

/// Lemma 3.3: "the eigenvectors of S⁺ corresponding to 1/2 are simply v1 + m1 v0
/// and v2 + m2 v0" (m_i the first row of V⁻¹ S⁺ V). With S⁺ v_i = m_i v0 + v_i/2
/// the eigenvector is v_i − 2 m_i v0; v_i + m_i v0 is one only where m_i = 0.
pub fn strip_shifted_eigenvectors(data: &toml::Value) -> Result<Finding, Error> {
    let st = strip(data)?;
    let basis = eigenbasis(data, &st)?;
    let a = crate::spectrum::strip::action_on(&st.s_plus, &basis)
        .ok_or_else(|| Error::Undecided("the leading eigenvectors are not invariant under S⁺".into()))?;
    let half = q(1, 2);
    let mut out = Vec::new();
    let mut all = true;
    for i in 1..basis.len() {
        if st.leading[i] != half {
            continue;
        }
        let m = a[0][i].clone();
        let x: Vec<Rational> = basis[i].iter().zip(&basis[0]).map(|(v, v0)| v + &m * v0).collect();
        let y: Vec<Rational> =
            st.s_plus.iter().map(|row| row.iter().zip(&x).fold(Rational::zero(), |acc, (w, z)| acc + w * z)).collect();
        let ok = y.iter().zip(&x).all(|(a, b)| *a == &half * b);
        all &= ok;
        out.push(format!(
            "v{i}: m{i} = {m}, v{i} + m{i} v0 {} (S⁺ (v{i} + c v0) = (v{i} + c v0)/2 needs c = −2 m{i} = {})",
            if ok { "is an eigenvector" } else { "is not an eigenvector" },
            -(q(2, 1) * &m)
        ));
    }
    Ok(Finding::new(
        all,
        "the 1/2-eigenvectors of S⁺ are v_i + m_i v0".into(),
        out.join("; "),
        "exact, in the leading eigenvectors of S (the statement does not depend on their scaling)".into(),
    ))
}

/// Lemma 3.3: ρ^[k](Q⁴³, Q⁺) < bound, Q the action of S and S⁺ modulo the
/// leading eigenvectors (an orthonormal complement stands for the paper's
/// unspecified remaining columns of V; ρ^[k] depends on that basis, the joint
/// spectral radius it bounds does not).
pub fn strip_jsr(data: &toml::Value) -> Result<Finding, Error> {
    use crate::spectrum::strip::{jsr_bounds, orthogonal_complement, to_f64};
    let st = strip(data)?;
    let basis = eigenbasis(data, &st)?;
    let n = st.s.len();
    if crate::spectrum::strip::action_on(&st.s_plus, &basis).is_none() {
        return Err(Error::Undecided("the leading eigenvectors are not invariant under S⁺: Q⁺ is not defined".into()));
    }
    let length = int_in(data, "length", 1, 16)? as usize;
    let bound = crate::numeric::Weight::to_f64(&exact(text(data, "bound")?)?);
    let bounds = JSR.get_or_try_insert(
        format!("{} length {length}", strip_key(data)),
        || {
            let w = faer::Mat::from_fn(n, basis.len(), |i, j| crate::numeric::Weight::to_f64(&basis[j][i]));
            let c = orthogonal_complement(&w)?;
            let (s, sp) = (to_f64(&st.s), to_f64(&st.s_plus));
            let q43 = c.transpose() * &s * &c;
            let qp = c.transpose() * &sp * &c;
            jsr_bounds(&[q43, qp], length, 4)
        },
        |b| 64 + 8 * b.lower_word.len(),
    )?;
    let b = &*bounds;
    let word: Vec<&str> = b.lower_word.iter().rev().map(|&k| if k == 0 { "Q43" } else { "Q+" }).collect();
    let finding = Finding::new(
        b.upper < bound,
        format!("ρ^[{length}](Q43, Q+) < {bound} (Q of size {})", n - basis.len()),
        format!("ρ^[{length}] = {} (upper bound); lower bound {} from {}", fmt_f(b.upper), fmt_f(b.lower), word.join("·")),
        format!(
            "every product of {length} factors in the ∞-norm, Q in an orthonormal basis of the complement of the {} leading eigenvectors; so ρ(Y43, Y+) = max(ρ(d), ρ(Q)) = {}",
            basis.len(),
            if b.upper < bound { format!("{bound}") } else { "undecided".into() }
        ),
    );
    // the bounds bracket the stated value: nothing is decided
    if b.upper >= bound && b.lower < bound {
        return Err(not_decided(&finding.stated, &finding.computed, &finding.detail));
    }
    Ok(finding)
}
