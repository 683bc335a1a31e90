//! Lin–Luo's unified sqrt(3) and curve schemes (`claims/lin-luo.toml`): the
//! eigenvalue pattern of section 6, relation (3) between the B-spline and
//! four-point curve steps, and C¹ of the curve family by the symbol (with an
//! exact obstruction where the sufficient test fails).

use num_traits::{Signed, Zero};

use crate::claims::builtin::data::{field, int_in, not_decided, text};
use crate::claims::common::values::show;
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::neighbourhood::Configuration;
use crate::numeric::exact::q;
use crate::numeric::Rational;
use crate::schemes;
use crate::spectrum::{analyse_shared, fmt_f, Options};

/// Section 6: for C ∈ [0, 2], n > 3: λ0 = 1, λ1 = λ2 > λ3 = λ4; n = 3: λ0 = 1, λ1 = λ2 > λ3.
/// Read generously: λ1 = λ2 real (Reif's condition, which the paper cites),
/// |λ3| = |λ4| in modulus (a conjugate pair counts as equal).
/// Lin–Luo section 6: "n > 3: λ0 = 1, λ1 = λ2 > λ3 = λ4; n = 3: λ0 = 1,
/// λ1 = λ2 > λ3" for uniform α = C ∈ [0, 2]. `data.reading` (optional):
/// "moduli" (default; the λ's ordered by modulus, "λ3 = λ4" as |λ3| = |λ4|)
/// or "values" ("λ3 = λ4" as equal eigenvalues, a complex pair does not do).
/// Each case is computed twice, by the Fourier blocks and by the whole
/// matrix, and the verdict needs both routes to agree.
pub fn linluo_section6(data: Option<&toml::Value>) -> Result<Finding, Error> {
    let reading = match data.map(|d| text(d, "reading")).transpose()? {
        None | Some("moduli") => "moduli",
        Some("values") => "values",
        Some(other) => return Err(Error::Claim(format!("data.reading = '{other}': use moduli or values"))),
    };
    let mut failures = Vec::new();
    let mut disagreements = Vec::new();
    let mut checked = 0;
    for alpha in ["0", "1/2", "1", "3/2", "2"] {
        for n in 3..=8usize {
            let s = schemes::build("unified-sqrt3", &[("alpha".into(), alpha.into())])?;
            let config = Configuration::regular(s.as_ref(), n)?;
            let mut verdicts = Vec::new();
            let mut lead = Vec::new();
            for method in [crate::spectrum::Method::Dft, crate::spectrum::Method::Full] {
                let opts = Options { exact: false, method: Some(method), ..Options::default() };
                let sp = analyse_shared(s.as_ref(), &config, &opts)?.spectrum.clone();
                let l: Vec<faer::c64> = sp
                    .eigenvalues
                    .iter()
                    .flat_map(|e| std::iter::repeat_n(faer::c64::new(e.re, e.im), e.algebraic_multiplicity))
                    .collect();
                let eq = |a: faer::c64, b: faer::c64| (a - b).norm() < 1e-7;
                let three_four = match reading {
                    "moduli" => (l[3].norm() - l[4].norm()).abs() < 1e-7,
                    _ => eq(l[3], l[4]),
                };
                let ok = eq(l[0], faer::c64::new(1.0, 0.0))
                    && l[1].im.abs() < 1e-9
                    && l[1].re > 0.0
                    && eq(l[1], l[2])
                    && l[2].norm() > l[3].norm() + 1e-7
                    && (n == 3 || three_four);
                verdicts.push(ok);
                lead = l.iter().take(5).map(|z| show(*z)).collect::<Vec<String>>();
            }
            checked += 1;
            if verdicts[0] != verdicts[1] {
                disagreements.push(format!("alpha={alpha}, n={n}"));
            }
            if !verdicts[0] {
                failures.push(format!("alpha={alpha}, n={n}: [{}]", lead.join(", ")));
            }
        }
    }
    let stated = match reading {
        "moduli" => "λ0 = 1, λ1 = λ2 (real) > |λ3| (= |λ4| for n > 3) for α ∈ [0, 2]",
        _ => "λ0 = 1, λ1 = λ2 (real) > |λ3|, λ3 = λ4 as values for n > 3, for α ∈ [0, 2]",
    };
    let routes = "routes: Fourier blocks and the whole matrix (floating point, 1e-7)";
    if !disagreements.is_empty() {
        return Err(not_decided(stated, &format!("the two routes disagree at {}", disagreements.join("; ")), routes));
    }
    Ok(Finding::new(
        failures.is_empty(),
        stated.into(),
        format!(
            "{} of {checked} cases (α ∈ {{0, 1/2, 1, 3/2, 2}}, n = 3..8) fail, both routes agreeing",
            failures.len()
        ),
        format!("{routes}; {}", failures.iter().take(8).cloned().collect::<Vec<_>>().join("; ")),
    ))
}

// ---------------------------------------------------------------- Lin–Luo: curves

/// Eq. (3): P³_i = P¹_i − (Δ(P_i) + Δ(P_{i+1}))/2 with Δ(P_i) = P²_i − P⁰_i of a
/// cubic B-spline step is the four-point point. Both sides are linear maps of
/// the polygon: compared exactly on every unit polygon of length 8.
pub fn curve_relation3() -> Result<Finding, Error> {
    use crate::curves::{refine_closed, CurveWeight};
    use crate::schemes::curves::{self, relation::four_point_by_relation3};
    let four = Rational::mask(curves::build("four-point", &[])?.as_ref())
        .map_err(|_| Error::Undecided("inexact four-point mask".into()))?;
    let n = 8;
    let mut diffs = 0;
    for k in 0..n {
        let e: Vec<Rational> = (0..n).map(|i| if i == k { q(1, 1) } else { q(0, 1) }).collect();
        let lhs = four_point_by_relation3(&e).map_err(|_| Error::Undecided("inexact B-spline mask".into()))?;
        let rhs = refine_closed(&four, &e);
        diffs += lhs.iter().zip(&rhs).filter(|(a, b)| a != b).count();
    }
    Ok(Finding::new(
        diffs == 0,
        "P³_i = P¹_i − (Δ(P_i) + Δ(P_{i+1}))/2 is the four-point scheme's new point (Δ = new − old B-spline position)"
            .into(),
        if diffs == 0 { "equal on every unit polygon".into() } else { format!("{diffs} refined values differ") },
        "exact, closed polygons of 8 points (the relation is linear, so unit polygons decide it)".into(),
    ))
}

/// The uniform curve scheme is C¹ at each listed parameter value. Proven by
/// the symbol: (1 + z)² b(z)/2 with ‖S_b^L‖_∞ < 1 for some L ≤ `max_steps`
/// (sufficient). Where that test fails, an exact obstruction on the local
/// matrix disproves C¹ ([`curve_c1_obstruction`]); without either the value
/// is undecided. REFUTED when some value is disproved.
pub fn curve_c1_laurent(data: &toml::Value) -> Result<Finding, Error> {
    use crate::curves::{smoothness::c1_test, CurveWeight};
    use crate::schemes::curves;
    let name = text(data, "scheme")?;
    let param = text(data, "param")?;
    let max_steps = int_in(data, "max_steps", 1, 64)? as u32;
    let values = field(data, "values")?.as_array().ok_or_else(|| Error::Claim("data.values: strings".into()))?;
    if values.is_empty() || values.len() > 100 {
        return Err(Error::Claim("data.values: 1 to 100 parameter values".into()));
    }
    let mut out = Vec::new();
    let (mut proven, mut disproven) = (0, 0);
    for v in values {
        let v = v.as_str().ok_or_else(|| Error::Claim("data.values: strings".into()))?;
        let s = curves::build(name, &[(param.to_string(), v.to_string())])?;
        let mask = Rational::mask(s.as_ref()).map_err(|_| Error::Undecided("inexact mask".into()))?;
        let failed = match c1_test(&mask, max_steps) {
            Ok((Some(l), norms)) => {
                proven += 1;
                out.push(format!("{param} = {v}: ‖S_b^{l}‖ = {}", norms.last().expect("one norm")));
                continue;
            }
            Ok((None, norms)) => format!(
                "‖S_b^L‖ ≥ 1 up to L = {max_steps} (last {})",
                fmt_f(crate::numeric::Weight::to_f64(norms.last().expect("one norm")))
            ),
            Err(e) => e.to_string(),
        };
        match curve_c1_obstruction(&mask)? {
            Some(why) => {
                disproven += 1;
                out.push(format!("{param} = {v}: not C¹: {why}"));
            }
            None => out.push(format!("{param} = {v}: {failed}; no obstruction found either")),
        }
    }
    let finding = Finding::new(
        disproven == 0,
        format!("C¹ limit curves for constant {param}"),
        out.join("; "),
        "exact Laurent-polynomial test: a(z) = (1 + z)² b(z)/2 and S_b contractive (sufficient for C¹); where it fails, \
         the exact local matrix on the analysis window (an eigenvector whose limit is not differentiable at the vertex \
         disproves C¹)"
            .into(),
    );
    // no value disproved and not every value proved: nothing is decided
    if disproven == 0 && proven != values.len() {
        return Err(not_decided(&finding.stated, &finding.computed, &finding.detail));
    }
    Ok(finding)
}

/// An exact proof that a binary curve scheme is not C¹, or `None`. A is the
/// local matrix on the analysis window W (the old points that decide the
/// limit over [−1, 1]). Data d on W have a limit G_d there, and G_{Ad}(x) =
/// G_d(x/2) (A d is the next level's data, one level finer). A C¹ scheme
/// converges, so A^k → 1 lᵗ (l the left eigenvector of a simple eigenvalue
/// 1, lᵗ1 = 1): the limit at a vertex x is lᵗ(d_{x+w})_{w∈W}, and so:
/// - a second eigenvalue 1, or a rational eigenvalue of modulus ≥ 1 other
///   than 1, contradicts convergence (A^k v does not tend to a constant);
/// - an eigenvector v of a rational μ with |μ| > 1/2 or μ = −1/2 has
///   G_v(2^{−k}x) = μ^k G_v(x): with G_v(±1) ≠ 0 the difference quotients at 0,
///   (2μ)^k G_v(±1)/(±1), do not converge;
/// - an eigenvector of 1/2 has G_v(2^{−k}x) = 2^{−k} G_v(x): differentiable at
///   0 only if the slopes G_v(1) and −G_v(−1) agree (else a corner);
/// - a Jordan chain A u = u/2 + v at 1/2 gives 2^k G_u(2^{−k}) = G_u(1) +
///   2k G_v(1), unbounded when G_v(1) ≠ 0.
///
/// Only rational eigenvalues are used (exact null spaces).
fn curve_c1_obstruction(mask: &crate::curves::CurveMask<Rational>) -> Result<Option<String>, Error> {
    use crate::curves::local::{analysis_window, local_matrix};
    use crate::spectrum::strip::{exact_eigenvectors, rational_spectrum};
    let window = analysis_window(mask)?;
    let a = local_matrix(mask, &window)?.dense();
    let size = window.len();
    let (spectrum, _) = rational_spectrum(&a)?;
    let (one, half) = (q(1, 1), q(1, 2));
    for (mu, alg, _) in &spectrum {
        if *mu == one && *alg > 1 {
            return Ok(Some(format!(
                "the local matrix on the analysis window has the eigenvalue 1 {alg} times: data on a second eigenvector or Jordan chain do not tend to a constant at the vertex, so the scheme does not converge"
            )));
        }
        if *mu != one && mu.abs() >= one {
            return Ok(Some(format!(
                "the local matrix has the eigenvalue {mu}: data on its eigenvector are multiplied by {mu} each step and do not tend to a constant, so the scheme does not converge"
            )));
        }
    }
    if !spectrum.iter().any(|e| e.0 == one) {
        return Ok(None);
    }
    // the limit stencil: the left eigenvector of 1, summing to 1
    let at: Vec<Vec<Rational>> = (0..size).map(|i| (0..size).map(|j| a[j][i].clone()).collect()).collect();
    let Some(l) = exact_eigenvectors(&at, std::slice::from_ref(&one)).pop() else { return Ok(None) };
    let sum = l.iter().fold(q(0, 1), |s, x| s + x);
    if sum.is_zero() {
        return Ok(None);
    }
    let l: Vec<Rational> = l.iter().map(|x| x / &sum).collect();
    let position: std::collections::HashMap<i64, usize> = window.iter().enumerate().map(|(k, &i)| (i, k)).collect();
    // G_d at the vertex x, when the window holds every point its stencil needs
    let limit_at = |d: &[Rational], x: i64| -> Option<Rational> {
        let mut acc = q(0, 1);
        for (w, lw) in window.iter().zip(&l) {
            if !lw.is_zero() {
                acc += lw * &d[*position.get(&(x + w))?];
            }
        }
        Some(acc)
    };
    for (mu, alg, geo) in &spectrum {
        let grows = (mu.abs() * q(2, 1) > one && *mu != one) || *mu == -half.clone();
        if grows {
            for v in exact_eigenvectors(&a, std::slice::from_ref(mu)) {
                for x in [1, -1] {
                    if let Some(g) = limit_at(&v, x).filter(|g| !g.is_zero()) {
                        return Ok(Some(format!(
                            "an eigenvector of {mu} has a limit G with G({x}) = {g} and G(2^-k·{x}) = ({mu})^k·G({x}), so its difference quotients at the vertex, (2·{mu})^k·G({x})/({x}), do not converge"
                        )));
                    }
                }
            }
        }
        if *mu != half {
            continue;
        }
        let vectors = exact_eigenvectors(&a, std::slice::from_ref(mu));
        for v in &vectors {
            if let (Some(right), Some(left)) = (limit_at(v, 1), limit_at(v, -1)) {
                if right.clone() + &left != q(0, 1) {
                    return Ok(Some(format!(
                        "an eigenvector of 1/2 has a limit G with G(2^-k·x) = 2^-k·G(x): slope {right} to the right of the vertex (G(1) = {right}) and {} to the left (G(-1) = {left}), a corner",
                        -left.clone()
                    )));
                }
            }
        }
        if alg > geo {
            // a Jordan chain: w with (A − I/2)² w = 0, v = (A − I/2) w ≠ 0
            let shifted: Vec<Vec<Rational>> = (0..size)
                .map(|i| (0..size).map(|j| if i == j { &a[i][j] - &half } else { a[i][j].clone() }).collect())
                .collect();
            let squared: Vec<Rational> = (0..size)
                .flat_map(|i| {
                    let shifted = &shifted;
                    (0..size).map(move |j| (0..size).fold(q(0, 1), |s, k| s + &shifted[i][k] * &shifted[k][j]))
                })
                .collect();
            for w in crate::numeric::exact::null_space(size, size, squared) {
                let v: Vec<Rational> =
                    shifted.iter().map(|row| row.iter().zip(&w).fold(q(0, 1), |s, (x, y)| s + x * y)).collect();
                if v.iter().all(|x| x.is_zero()) {
                    continue;
                }
                if let Some(g) = limit_at(&v, 1).filter(|g| !g.is_zero()) {
                    return Ok(Some(format!(
                        "1/2 is defective: a Jordan chain A u = u/2 + v with G_v(1) = {g} gives 2^k·G_u(2^-k) = G_u(1) + 2k·{g}, unbounded, so G_u is not differentiable at the vertex"
                    )));
                }
            }
        }
    }
    Ok(None)
}
