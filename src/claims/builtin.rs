//! Named checks for statements that need a bespoke computation. Each returns
//! (verdict, stated, computed, detail). Printed values come in `data`, from
//! the claim file, never from here.

use super::Verdict;
use crate::neighbourhood::{build_patch, Configuration};
use crate::numeric::exact::{q, QMatrix};
use crate::numeric::Rational;
use crate::schemes::{self, SchemeWeight};
use crate::spectrum::{analyse, Options};

type Result4 = Result<(Verdict, String, String, String), String>;

pub fn run(name: &str, data: Option<&toml::Value>) -> Result4 {
    match name {
        "nonbox.vector-mask" => nonbox_vector_mask(data.ok_or("needs data.cells")?),
        "nonbox.negative-eigenvalues" => nonbox_negative_eigenvalues(),
        "linluo.section6" => linluo_section6(),
        other => Err(format!("no built-in check named '{other}'")),
    }
}

fn has_eigenvalue(m: &[[Rational; 2]; 2], lambda: &Rational) -> bool {
    let mut a = QMatrix::zeros(2);
    for (i, row) in m.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            a.set(i, j, x.clone());
        }
    }
    a.charpoly().eval(lambda) == q(0, 1)
}

/// The printed vector mask A of eq. (3) must satisfy the refinement
/// condition: Σ_α A_α has the eigenvalue 4 (integrate the refinement
/// equation; the generators have positive integrals). The rules of section
/// 3.2.2 do (their total mask over one coarse cell is [[3, 1], [2, 2]]).
fn nonbox_vector_mask(data: &toml::Value) -> Result4 {
    let cells = data.get("cells").and_then(|c| c.as_array()).ok_or("data.cells: a list of [a11, a12, a21, a22]")?;
    let mut sum = [[q(0, 1), q(0, 1)], [q(0, 1), q(0, 1)]];
    for c in cells {
        let v: Vec<Rational> = c
            .as_array()
            .ok_or("each cell is a list")?
            .iter()
            .map(|x| x.as_str().and_then(|s| crate::numeric::ParamValue::parse(s).ok()?.exact))
            .collect::<Option<_>>()
            .ok_or("cell entries are exact numbers as strings")?;
        if v.len() != 4 {
            return Err("each cell has four entries".into());
        }
        for k in 0..4 {
            sum[k / 2][k % 2] = &sum[k / 2][k % 2] + &v[k];
        }
    }
    // the rules' own total mask, from the scheme's exact stencils on a regular patch
    let scheme = schemes::build("non-box", &[])?;
    let config = Configuration::regular(scheme.as_ref(), 4)?;
    let (patch, _) = build_patch(&config, 4);
    let refined = scheme.topology().refine(&patch)?;
    let chart = refined.mesh.chart.as_ref().ok_or("no chart")?;
    let fcv0: std::collections::HashSet<usize> = patch.face_points.iter().flatten().copied().collect();
    let fcv1: std::collections::HashSet<usize> = refined.mesh.face_points.iter().flatten().copied().collect();
    let mut t = [[q(0, 1), q(0, 1)], [q(0, 1), q(0, 1)]];
    for (v, &o) in refined.vertex_origins.iter().enumerate() {
        let (x, y) = chart.in_chart(chart.vertex_coords[v], 0);
        if !(4..8).contains(&x) || !(4..8).contains(&y) {
            continue;
        }
        let i = usize::from(!fcv1.contains(&v));
        let st = <Rational as SchemeWeight>::stencil(scheme.as_ref(), &patch, o)
            .map_err(|_| "an irrational weight")?
            .ok_or("rule not evaluable")?;
        for (u, w) in st.terms {
            let j = usize::from(!fcv0.contains(&u));
            t[i][j] = &t[i][j] + &w;
        }
    }
    let four = q(4, 1);
    let printed_ok = has_eigenvalue(&sum, &four);
    let rules_ok = has_eigenvalue(&t, &four);
    let show = |m: &[[Rational; 2]; 2]| format!("[[{}, {}], [{}, {}]]", m[0][0], m[0][1], m[1][0], m[1][1]);
    Ok((
        if printed_ok { Verdict::Holds } else { Verdict::Refuted },
        format!("printed Σ A_α = {}", show(&sum)),
        format!("rules of 3.2.2: Σ = {} (eigenvalue 4: {rules_ok})", show(&t)),
        format!(
            "a refinable vector with non-zero integrals needs eigenvalue 4 of Σ A_α; the printed mask {} it",
            if printed_ok { "has" } else { "does not have" }
        ),
    ))
}

/// Section 4: "the real eigenvalues cannot be negative" (used to bound a_k by
/// 3/4 for convergence). Counter-example: a = 9/10 at k = 5 gives the real
/// eigenvalue 3/4 − a < 0 while 1 stays simple and dominant.
fn nonbox_negative_eigenvalues() -> Result4 {
    let scheme = schemes::build("non-box", &[("a".into(), "9/10".into())])?;
    let config = Configuration::regular(scheme.as_ref(), 5)?;
    let s = analyse(scheme.as_ref(), &config, &Options { exact: false, ..Options::default() })?.spectrum;
    let neg = s.eigenvalues.iter().filter(|e| e.is_real() && e.re < -1e-9).map(|e| e.display()).collect::<Vec<_>>();
    let dominant = s.eigenvalues[0].algebraic_multiplicity == 1
        && (s.eigenvalues[0].re - 1.0).abs() < 1e-9
        && s.eigenvalues.iter().skip(1).all(|e| e.modulus < 1.0 - 1e-9);
    let refuted = !neg.is_empty() && dominant;
    Ok((
        if refuted { Verdict::Refuted } else { Verdict::Inconclusive },
        "negative real eigenvalues are excluded (so a_k ≤ 3/4 for convergence)".into(),
        format!("a = 9/10, k = 5: negative eigenvalues {}, 1 simple and all others below 1 in modulus: {dominant}", neg.join(", ")),
        "convergence needs 1 simple and dominant, not non-negative eigenvalues; the bound a_k ≤ 3/4 is sufficient, not necessary".into(),
    ))
}

/// Section 6: for C ∈ [0, 2], n > 3: λ0 = 1, λ1 = λ2 > λ3 = λ4; n = 3: λ0 = 1, λ1 = λ2 > λ3.
/// Read generously: λ1 = λ2 real (Reif's condition, which the paper cites),
/// |λ3| = |λ4| in modulus (a conjugate pair counts as equal).
fn linluo_section6() -> Result4 {
    let mut failures = Vec::new();
    let mut checked = 0;
    for alpha in ["0", "1/2", "1", "3/2", "2"] {
        for n in 3..=8usize {
            let s = schemes::build("unified-sqrt3", &[("alpha".into(), alpha.into())])?;
            let config = Configuration::regular(s.as_ref(), n)?;
            let sp = analyse(s.as_ref(), &config, &Options { exact: false, ..Options::default() })?.spectrum;
            let l: Vec<faer::c64> = sp
                .eigenvalues
                .iter()
                .flat_map(|e| std::iter::repeat_n(faer::c64::new(e.re, e.im), e.algebraic_multiplicity))
                .collect();
            let eq = |a: faer::c64, b: faer::c64| (a - b).norm() < 1e-7;
            let ok = eq(l[0], faer::c64::new(1.0, 0.0))
                && l[1].im.abs() < 1e-9
                && l[1].re > 0.0
                && eq(l[1], l[2])
                && l[2].norm() > l[3].norm() + 1e-7
                && (n == 3 || (l[3].norm() - l[4].norm()).abs() < 1e-7);
            checked += 1;
            if !ok {
                let lead: Vec<String> = l.iter().take(5).map(|z| super::checks::show(*z)).collect();
                failures.push(format!("alpha={alpha}, n={n}: [{}]", lead.join(", ")));
            }
        }
    }
    Ok((
        if failures.is_empty() { Verdict::Holds } else { Verdict::Refuted },
        "λ0 = 1, λ1 = λ2 (real) > |λ3| (= |λ4| for n > 3) for α ∈ [0, 2]".into(),
        format!("{} of {checked} cases (α ∈ {{0, 1/2, 1, 3/2, 2}}, n = 3..8) fail", failures.len()),
        failures.iter().take(8).cloned().collect::<Vec<_>>().join("; "),
    ))
}
