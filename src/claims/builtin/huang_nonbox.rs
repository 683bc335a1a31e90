//! Huang's four-directional S_3^1 non-box scheme (`claims/huang-nonbox.toml`):
//! the printed vector mask, the "no negative eigenvalues" convergence
//! argument, and the non-negativity of the subdivision weights (sampled, or
//! as an exact equivalence over a parameter range).

use num_traits::{Signed, Zero};

use crate::claims::builtin::data::{exact_list, field, ints, not_decided, params, text, SmallestWeight};
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::neighbourhood::{build_patch, Configuration};
use crate::numeric::exact::{q, QMatrix};
use crate::numeric::Rational;
use crate::refine::step_selected;
use crate::schemes;
use crate::spectrum::{analyse_shared, Options};

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
pub fn nonbox_vector_mask(data: &toml::Value) -> Result<Finding, Error> {
    let cells = data
        .get("cells")
        .and_then(|c| c.as_array())
        .ok_or_else(|| Error::Claim("data.cells: a list of [a11, a12, a21, a22]".into()))?;
    let mut sum = [[q(0, 1), q(0, 1)], [q(0, 1), q(0, 1)]];
    for c in cells {
        let v: Vec<Rational> = c
            .as_array()
            .ok_or_else(|| Error::Claim("each cell is a list".into()))?
            .iter()
            .map(|x| x.as_str().and_then(|s| crate::numeric::ParamValue::parse(s).ok()?.exact))
            .collect::<Option<_>>()
            .ok_or_else(|| Error::Claim("cell entries are exact numbers as strings".into()))?;
        if v.len() != 4 {
            return Err(Error::Claim("each cell has four entries".into()));
        }
        for k in 0..4 {
            sum[k / 2][k % 2] = &sum[k / 2][k % 2] + &v[k];
        }
    }
    // the rules' own total mask, from the scheme's exact stencils on a regular patch
    let scheme = schemes::build("non-box", &[])?;
    let config = Configuration::regular(scheme.as_ref(), 4)?;
    let (patch, _) = build_patch(&config, 4);
    // one step of the patch, with the stencils of the fine points over the
    // coarse cells [2, 4)² of sector 0 (fine chart coordinates [4, 8)²)
    let mut cells = Vec::new();
    let step = step_selected::<Rational>(scheme.as_ref(), &patch, |refined| {
        let chart = refined.mesh.chart.as_ref().ok_or_else(|| Error::Undecided("no chart".into()))?;
        cells = (0..refined.vertex_origins.len())
            .filter(|&v| {
                let (x, y) = chart.in_chart(chart.vertex_coords[v], 0);
                (4..8).contains(&x) && (4..8).contains(&y)
            })
            .collect();
        Ok(cells.clone())
    })?;
    let fcv0: std::collections::HashSet<usize> = patch.face_points.iter().flatten().copied().collect();
    let fcv1: std::collections::HashSet<usize> = step.refined.mesh.face_points.iter().flatten().copied().collect();
    let mut t = [[q(0, 1), q(0, 1)], [q(0, 1), q(0, 1)]];
    for v in cells {
        let i = usize::from(!fcv1.contains(&v));
        // every cell was selected, so a missing stencil is the rule's: say why
        let st = step.stencils[v].stencil().ok_or_else(|| match step.stencils[v].cause() {
            Some(cause) => Error::Undecided(format!("rule not evaluable: {cause}")),
            None => Error::Message("a selected cell has no stencil".into()),
        })?;
        for (u, w) in &st.terms {
            let j = usize::from(!fcv0.contains(u));
            t[i][j] = &t[i][j] + w;
        }
    }
    let four = q(4, 1);
    let printed_ok = has_eigenvalue(&sum, &four);
    let rules_ok = has_eigenvalue(&t, &four);
    let show = |m: &[[Rational; 2]; 2]| format!("[[{}, {}], [{}, {}]]", m[0][0], m[0][1], m[1][0], m[1][1]);
    Ok(Finding::new(
        printed_ok,
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
pub fn nonbox_negative_eigenvalues() -> Result<Finding, Error> {
    let scheme = schemes::build("non-box", &[("a".into(), "9/10".into())])?;
    let config = Configuration::regular(scheme.as_ref(), 5)?;
    let s = analyse_shared(scheme.as_ref(), &config, &Options { exact: false, ..Options::default() })?.spectrum.clone();
    let neg = s.eigenvalues.iter().filter(|e| e.is_real() && e.re < -1e-9).map(|e| e.display()).collect::<Vec<_>>();
    let dominant = s.eigenvalues[0].algebraic_multiplicity == 1
        && (s.eigenvalues[0].re - 1.0).abs() < 1e-9
        && s.eigenvalues.iter().skip(1).all(|e| e.modulus < 1.0 - 1e-9);
    let refuted = !neg.is_empty() && dominant;
    let stated = "negative real eigenvalues are excluded (so a_k ≤ 3/4 for convergence)".to_string();
    let computed = format!(
        "a = 9/10, k = 5: negative eigenvalues {}, 1 simple and all others below 1 in modulus: {dominant}",
        neg.join(", ")
    );
    let detail = "convergence needs 1 simple and dominant, not non-negative eigenvalues; the bound a_k ≤ 3/4 is sufficient, not necessary".to_string();
    if !refuted {
        // the counter-example did not come out as one: nothing is decided
        return Err(not_decided(&stated, &computed, &detail));
    }
    Ok(Finding::new(false, stated, computed, detail))
}

// ---------------------------------------------------------------- non-box: non-negative weights

/// Every entry of the local subdivision matrix is non-negative, at every
/// valence and parameter set listed (`data.params`, sampled: sufficiency
/// only). With `data.param` and `data.range` the statement is an equivalence
/// instead, decided in both directions: [`matrix_nonnegative_range`].
pub fn matrix_nonnegative(data: &toml::Value) -> Result<Finding, Error> {
    if data.get("range").is_some() {
        return matrix_nonnegative_range(data);
    }
    let name = text(data, "scheme")?;
    let valences = ints(data, "valences")?;
    let sets = field(data, "params")?.as_array().ok_or_else(|| Error::Claim("data.params: a list of tables".into()))?;
    let mut worst = SmallestWeight::new();
    let mut checked = 0;
    for set in sets {
        let p: Vec<(String, String)> = set
            .as_table()
            .ok_or_else(|| Error::Claim("data.params: tables".into()))?
            .iter()
            .map(|(k, v)| {
                v.as_str()
                    .map(|s| (k.clone(), s.to_string()))
                    .ok_or_else(|| Error::Claim("parameter values are strings".into()))
            })
            .collect::<Result<_, _>>()?;
        let scheme = schemes::resolve(name, &p)?;
        for &n in &valences {
            let config = Configuration::regular(scheme.as_ref(), n as usize)?;
            let a = analyse_shared(scheme.as_ref(), &config, &Options { exact: false, ..Options::default() })?;
            checked += 1;
            for (i, row) in a.matrix.to_dense_f64().iter().enumerate() {
                for (j, w) in row.iter().enumerate() {
                    let lab = &a.spectrum.labels;
                    worst.offer(*w, || format!("{p:?}, n = {n}: S[{}][{}]", lab[i].name, lab[j].name));
                }
            }
        }
    }
    worst.outcome(
        "all subdivision weights are non-negative",
        "smallest entry of S",
        format!("{checked} matrices (analysis neighbourhood)"),
    )
}

/// c0 + c1·p, readably ("1 - a", "1/3·a").
fn affine_text(c0: &Rational, c1: &Rational, p: &str) -> String {
    let slope = |c: &Rational| if c.abs() == q(1, 1) { p.to_string() } else { format!("{}·{p}", c.abs()) };
    match (c0.is_zero(), c1.is_zero()) {
        (_, true) => c0.to_string(),
        (true, false) => format!("{}{}", if c1.is_negative() { "-" } else { "" }, slope(c1)),
        (false, false) => format!("{c0} {} {}", if c1.is_negative() { "-" } else { "+" }, slope(c1)),
    }
}

/// One entry of S as an affine function c0 + c1·p of the parameter.
struct AffineEntry {
    row: usize,
    col: usize,
    c0: Rational,
    c1: Rational,
}

impl AffineEntry {
    fn at(&self, x: &Rational) -> Rational {
        &self.c0 + &self.c1 * x
    }
    /// The parameter value where the entry is zero (c1 ≠ 0).
    fn root(&self) -> Rational {
        -(&self.c0 / &self.c1)
    }
}

/// "S ≥ 0 exactly when lo ≤ p ≤ hi" (`data.range = [lo, hi]` for the scheme
/// parameter `data.param`, other parameters in `data.fixed`) at every listed
/// valence, both directions. S (analysis neighbourhood) is computed exactly at
/// the `data.samples` values of p, all on one neighbourhood (the largest the
/// samples' rules give, so every sample's rows stay in it). Its entries are
/// affine in p when the line through the first two samples meets every other
/// sample exactly (the premise of what follows: a rule weight such as 1 − a
/// or a/k is affine, and finitely many samples cannot prove it); then the set
/// of p with S ≥ 0 is an interval whose ends are roots of single entries,
/// computed exactly. "If": [lo, hi] lies in that interval; "only if": the
/// interval lies in [lo, hi], i.e. below lo and above hi some entry is
/// negative. A valence where S does not depend on p takes part in the "if"
/// only. Each failure is shown at a witness value of p.
fn matrix_nonnegative_range(data: &toml::Value) -> Result<Finding, Error> {
    let name = text(data, "scheme")?;
    let param = text(data, "param")?;
    let valences = ints(data, "valences")?;
    if valences.is_empty() || valences.len() > 16 || valences.iter().any(|&n| !(3..=64).contains(&n)) {
        return Err(Error::Claim("data.valences: 1 to 16 valences in 3..64".into()));
    }
    let range = exact_list(data, "range")?;
    let [lo, hi] = <[Rational; 2]>::try_from(range).map_err(|_| Error::Claim("data.range is [lo, hi]".into()))?;
    if lo > hi {
        return Err(Error::Claim(format!("data.range [{lo}, {hi}] is empty")));
    }
    let samples = exact_list(data, "samples")?;
    if !(3..=12).contains(&samples.len()) || (0..samples.len()).any(|i| samples[..i].contains(&samples[i])) {
        return Err(Error::Claim(
            "data.samples: 3 to 12 distinct values (two define the line, the rest check it)".into(),
        ));
    }
    let fixed = params(data, "fixed")?;
    let at = |x: &Rational| -> Result<Box<dyn schemes::Scheme>, Error> {
        let mut p = fixed.clone();
        p.push((param.to_string(), x.to_string()));
        schemes::resolve(name, &p)
    };
    let rules: Vec<Box<dyn schemes::Scheme>> = samples.iter().map(at).collect::<Result<_, _>>()?;
    let mut tally = Tally::default();
    for &k in &valences {
        study_valence(k, &rules, &samples, (lo.clone(), hi.clone()), param, &mut tally)?;
    }
    let Tally { if_fails, only_if_fails, evidence, not_affine, acting } = tally;
    let range_text = format!("{lo} ≤ {param} ≤ {hi}");
    let if_part = if if_fails.is_empty() {
        if not_affine.is_empty() {
            format!("if: S ≥ 0 for every {range_text}")
        } else {
            format!("if: not decided (S not affine in {param})")
        }
    } else {
        format!("if fails: a negative weight at {}", if_fails.iter().take(4).cloned().collect::<Vec<_>>().join("; "))
    };
    let only_if_part = if !not_affine.is_empty() {
        format!("only if: not decided (S not affine in {param}: {})", not_affine.join("; "))
    } else if acting.is_empty() {
        format!("only if: not decided ({param} does not act on S at any listed valence)")
    } else if only_if_fails.is_empty() {
        format!(
            "only if: every {param} < {lo} and every {param} > {hi} gives a negative weight (k = {}, where {param} acts)",
            acting.join(", ")
        )
    } else {
        format!(
            "only if fails: S ≥ 0 outside the range at {}",
            only_if_fails.iter().take(4).cloned().collect::<Vec<_>>().join("; ")
        )
    };
    let refuted = !if_fails.is_empty() || !only_if_fails.is_empty();
    let decided = refuted || (not_affine.is_empty() && !acting.is_empty());
    let samples_text: Vec<String> = samples.iter().map(|x| x.to_string()).collect();
    let finding = Finding::new(
        !refuted,
        format!("every subdivision weight is non-negative exactly when {range_text}"),
        format!("{if_part}; {only_if_part}"),
        format!(
            "exact S (analysis neighbourhood) at {param} = {}: every entry affine in {param} (the line through the first two samples meets the others exactly; the premise of the interval), so the set of {param} with S ≥ 0 is an interval whose ends are roots of single entries; {}",
            samples_text.join(", "),
            evidence.join("; ")
        ),
    );
    if !decided {
        return Err(not_decided(&finding.stated, &finding.computed, &finding.detail));
    }
    Ok(finding)
}

/// What [`matrix_nonnegative_range`] found over the valences so far.
#[derive(Default)]
struct Tally {
    /// failures of "if" (a negative weight inside the range)
    if_fails: Vec<String>,
    /// failures of "only if" (S ≥ 0 outside the range)
    only_if_fails: Vec<String>,
    evidence: Vec<String>,
    /// valences where S is not affine in the parameter (the premise fails)
    not_affine: Vec<String>,
    /// valences where the parameter acts on S
    acting: Vec<String>,
}

/// One valence k of [`matrix_nonnegative_range`]: the exact S at every
/// sample on a common neighbourhood, the interval of the parameter with
/// S ≥ 0 when S is affine in it, and the two directions against
/// `(lo, hi)`, added to `tally`.
fn study_valence(
    k: i64,
    rules: &[Box<dyn schemes::Scheme>],
    samples: &[Rational],
    (lo, hi): (Rational, Rational),
    param: &str,
    tally: &mut Tally,
) -> Result<(), Error> {
    use crate::matrix::assemble;
    use crate::neighbourhood::{discover, NeighbourhoodKind};
    let Tally { if_fails, only_if_fails, evidence, not_affine, acting } = tally;
    let kind = NeighbourhoodKind::Analysis;
    let shown = |x: &Rational| format!("{param} = {x}");
    let config = Configuration::regular(rules[0].as_ref(), k as usize)?;
    let mut found = Vec::new();
    for r in rules {
        found.push(discover(r.as_ref(), &config)?);
    }
    let d = found.iter().max_by_key(|d| d.set(kind).len()).expect("at least three samples");
    let mut mats = Vec::new();
    for (r, x) in rules.iter().zip(samples) {
        let m = assemble::<Rational>(r.as_ref(), d, kind).map_err(|e| {
            Error::Undecided(format!("k = {k}, {}: no exact S on the common neighbourhood ({e:?})", shown(x)))
        })?;
        mats.push(m);
    }
    let labels: Vec<String> = mats[0].labels.iter().map(|l| l.name.clone()).collect();
    let dense: Vec<Vec<Vec<Rational>>> = mats.iter().map(|m| m.dense()).collect();
    let size = labels.len();
    let entry = |e: &AffineEntry| format!("S[{}][{}]", labels[e.row], labels[e.col]);
    // the line through the first two samples, entry by entry
    let (s0, s1) = (&samples[0], &samples[1]);
    let mut entries = Vec::with_capacity(size * size);
    for (row, (r0, r1)) in dense[0].iter().zip(&dense[1]).enumerate() {
        for (col, (x0, x1)) in r0.iter().zip(r1).enumerate() {
            let c1 = (x1 - x0) / (s1 - s0);
            let c0 = x0 - &c1 * s0;
            entries.push(AffineEntry { row, col, c0, c1 });
        }
    }
    let off_line = entries.iter().find_map(|e| {
        (2..samples.len()).find(|&t| dense[t][e.row][e.col] != e.at(&samples[t])).map(|t| {
            format!(
                "k = {k}: {} at {} is {}, off the line {}",
                entry(e),
                shown(&samples[t]),
                dense[t][e.row][e.col],
                affine_text(&e.c0, &e.c1, param)
            )
        })
    });
    if let Some(why) = off_line {
        // no interval without the premise; a negative sample inside the range still refutes "if"
        for (t, x) in samples.iter().enumerate() {
            if lo <= *x && *x <= hi {
                if let Some(e) = entries.iter().find(|e| dense[t][e.row][e.col].is_negative()) {
                    if_fails.push(format!("k = {k}, {}: {} = {}", shown(x), entry(e), dense[t][e.row][e.col]));
                }
            }
        }
        not_affine.push(why);
        return Ok(());
    }
    // the set of p with S ≥ 0: [lower, upper] (None: unbounded), or empty
    let empty_const = entries.iter().find(|e| e.c1.is_zero() && e.c0.is_negative());
    // the binding entries (the first in matrix order on ties)
    let lower = entries.iter().filter(|e| e.c1.is_positive()).fold(None::<&AffineEntry>, |best, e| match best {
        Some(b) if b.root() >= e.root() => Some(b),
        _ => Some(e),
    });
    let upper = entries.iter().filter(|e| e.c1.is_negative()).fold(None::<&AffineEntry>, |best, e| match best {
        Some(b) if b.root() <= e.root() => Some(b),
        _ => Some(e),
    });
    let empty = empty_const.is_some() || matches!((lower, upper), (Some(l), Some(u)) if l.root() > u.root());
    // the most negative entry at x, for a witness
    let most_negative = |x: &Rational| {
        let e = entries.iter().min_by(|a, b| a.at(x).cmp(&b.at(x))).expect("S is not empty");
        format!("{} = {} = {}", entry(e), affine_text(&e.c0, &e.c1, param), e.at(x))
    };
    let end = |e: Option<&AffineEntry>| match e {
        Some(e) => format!("{} ({} = {})", e.root(), entry(e), affine_text(&e.c0, &e.c1, param)),
        None => "unbounded".into(),
    };
    if entries.iter().all(|e| e.c1.is_zero()) {
        if empty {
            if_fails.push(format!("k = {k} (S does not depend on {param}): {}", most_negative(&lo)));
        }
        evidence.push(format!(
            "k = {k}: S does not depend on {param}{}",
            if empty { " and has a negative entry" } else { ", S ≥ 0" }
        ));
        return Ok(());
    }
    acting.push(k.to_string());
    if empty {
        if_fails.push(format!("k = {k}: S ≥ 0 at no {param}; at {}: {}", shown(&lo), most_negative(&lo)));
        evidence.push(format!("k = {k}: S ≥ 0 for no value of {param}"));
        return Ok(());
    }
    evidence.push(format!("k = {k}: S ≥ 0 exactly for {param} from {} to {}", end(lower), end(upper)));
    // "if": [lo, hi] inside [lower, upper]
    if lower.is_some_and(|l| l.root() > lo) {
        if_fails.push(format!("k = {k}, {}: {}", shown(&lo), most_negative(&lo)));
    } else if upper.is_some_and(|u| u.root() < hi) {
        if_fails.push(format!("k = {k}, {}: {}", shown(&hi), most_negative(&hi)));
    }
    // "only if": [lower, upper] inside [lo, hi]; a witness outside [lo, hi] with S ≥ 0
    let outside_below = match lower {
        None => Some(&lo - q(1, 1)),
        Some(l) if l.root() < lo => Some((l.root() + &lo) / q(2, 1)),
        _ => None,
    };
    let outside_above = match upper {
        None => Some(&hi + q(1, 1)),
        Some(u) if u.root() > hi => Some((u.root() + &hi) / q(2, 1)),
        _ => None,
    };
    for x in outside_below.into_iter().chain(outside_above) {
        let smallest = entries.iter().map(|e| e.at(&x)).min().expect("S is not empty");
        only_if_fails.push(format!("k = {k}, {}: every entry ≥ 0 (the smallest {smallest})", shown(&x)));
    }
    Ok(())
}
