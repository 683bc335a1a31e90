//! Named checks for statements that need a bespoke computation. Each returns
//! (verdict, stated, computed, detail). Printed values come in `data`, from
//! the claim file, never from here.

use super::Verdict;
use crate::error::Error;
use crate::neighbourhood::{build_patch, Configuration};
use crate::numeric::exact::{q, QMatrix};
use crate::numeric::Rational;
use crate::refine::mesh::CompositeRows;
use crate::refine::step_selected;
use crate::schemes;
use crate::spectrum::{analyse, fmt_f, Options};
use num_traits::{Signed, Zero};

type Result4 = Result<(Verdict, String, String, String), Error>;

pub fn run(name: &str, data: Option<&toml::Value>) -> Result4 {
    match name {
        "nonbox.vector-mask" => nonbox_vector_mask(data.ok_or_else(|| Error::Claim("needs data.cells".into()))?),
        "nonbox.negative-eigenvalues" => nonbox_negative_eigenvalues(),
        "linluo.section6" => linluo_section6(data),
        "lattice.fit-masks" => lattice_fit_masks(need(data)?),
        "strip.defective" => strip_defective(need(data)?),
        "strip.structure" => strip_structure(need(data)?),
        "strip.shifted-eigenvectors" => strip_shifted_eigenvectors(need(data)?),
        "strip.jsr" => strip_jsr(need(data)?),
        "window.polynomials" => window_polynomials(need(data)?),
        "window.box-spline" => window_box_spline(need(data)?),
        "window.checkerboard-kernel" => window_checkerboard_kernel(need(data)?),
        "fourthree.lemma3.4" => fourthree_lemma_3_4(need(data)?),
        "fourthree.step-two-weights" => fourthree_step_two(need(data)?),
        "fourthree.convex-hull" => fourthree_convex_hull(need(data)?),
        "fourthree.node-counts" => fourthree_node_counts(need(data)?),
        "fourthree.step-two-bound" => fourthree_step_two_bound(need(data)?),
        "fourthree.ripple-free-unique" => fourthree_ripple_free_unique(need(data)?),
        "matrix.nonnegative" => matrix_nonnegative(need(data)?),
        "curve.relation3" => curve_relation3(),
        "curve.c1-laurent" => curve_c1_laurent(need(data)?),
        other => Err(Error::Claim(format!("no built-in check named '{other}'"))),
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
        let st = step.stencils[v].as_ref().ok_or_else(|| Error::Undecided("rule not evaluable".into()))?;
        for (u, w) in &st.terms {
            let j = usize::from(!fcv0.contains(u));
            t[i][j] = &t[i][j] + w;
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
/// Lin–Luo section 6: "n > 3: λ0 = 1, λ1 = λ2 > λ3 = λ4; n = 3: λ0 = 1,
/// λ1 = λ2 > λ3" for uniform α = C ∈ [0, 2]. `data.reading` (optional):
/// "moduli" (default; the λ's ordered by modulus, "λ3 = λ4" as |λ3| = |λ4|)
/// or "values" ("λ3 = λ4" as equal eigenvalues, a complex pair does not do).
/// Each case is computed twice, by the Fourier blocks and by the whole
/// matrix, and the verdict needs both routes to agree.
fn linluo_section6(data: Option<&toml::Value>) -> Result4 {
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
                let sp = analyse(s.as_ref(), &config, &opts)?.spectrum;
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
                lead = l.iter().take(5).map(|z| super::checks::show(*z)).collect::<Vec<String>>();
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
        return Ok((
            Verdict::Inconclusive,
            stated.into(),
            format!("the two routes disagree at {}", disagreements.join("; ")),
            routes.into(),
        ));
    }
    Ok((
        if failures.is_empty() { Verdict::Holds } else { Verdict::Refuted },
        stated.into(),
        format!(
            "{} of {checked} cases (α ∈ {{0, 1/2, 1, 3/2, 2}}, n = 3..8) fail, both routes agreeing",
            failures.len()
        ),
        format!("{routes}; {}", failures.iter().take(8).cloned().collect::<Vec<_>>().join("; ")),
    ))
}

// ---------------------------------------------------------------- data helpers

fn need(data: Option<&toml::Value>) -> Result<&toml::Value, Error> {
    data.ok_or_else(|| Error::Claim("this check needs `data`".to_string()))
}

fn field<'a>(data: &'a toml::Value, key: &str) -> Result<&'a toml::Value, Error> {
    data.get(key).ok_or_else(|| Error::Claim(format!("data.{key} is missing")))
}

fn text<'a>(data: &'a toml::Value, key: &str) -> Result<&'a str, Error> {
    field(data, key)?.as_str().ok_or_else(|| Error::Claim(format!("data.{key} must be a string")))
}

fn int(v: &toml::Value, what: &str) -> Result<i64, Error> {
    v.as_integer().ok_or_else(|| Error::Claim(format!("{what} must be an integer")))
}

/// An integer of the claim data within [lo, hi]: the data drive loops and
/// allocations, so every size is bounded (and never wraps when negative).
fn int_in(data: &toml::Value, key: &str, lo: i64, hi: i64) -> Result<i64, Error> {
    let v = int(field(data, key)?, &format!("data.{key}"))?;
    if v < lo || v > hi {
        return Err(Error::Claim(format!("data.{key} = {v} is outside the supported range {lo}..{hi}")));
    }
    Ok(v)
}

/// A window [x0, x1, y0, y1] of at most `max_points` lattice points.
fn small_window(data: &toml::Value, max_points: i64) -> Result<Vec<i64>, Error> {
    let w = ints(data, "window")?;
    if w.len() != 4 {
        return Err(Error::Claim("data.window is [x0, x1, y0, y1]".into()));
    }
    if w[0] > w[1] || w[2] > w[3] {
        return Err(Error::Claim(format!("data.window {w:?} is empty (it must have x0 <= x1 and y0 <= y1)")));
    }
    let points = (w[1] as i128 - w[0] as i128 + 1) * (w[3] as i128 - w[2] as i128 + 1);
    if points > max_points as i128 {
        return Err(Error::Claim(format!("data.window {w:?} has {points} points; at most {max_points} are supported")));
    }
    Ok(w)
}

/// Most points of the window of a strip or polynomial check.
const MAX_DATA_WINDOW: i64 = 144;

fn ints(data: &toml::Value, key: &str) -> Result<Vec<i64>, Error> {
    field(data, key)?
        .as_array()
        .ok_or_else(|| Error::Claim(format!("data.{key} must be a list of integers")))?
        .iter()
        .map(|x| int(x, &format!("data.{key}")))
        .collect()
}

fn exact(s: &str) -> Result<Rational, Error> {
    crate::numeric::expr::Expr::parse(s)?
        .exact(&Default::default())
        .ok_or_else(|| Error::Claim(format!("'{s}' is not an exact rational")))
}

/// Scheme parameters from a table of strings.
fn params(data: &toml::Value, key: &str) -> Result<Vec<(String, String)>, Error> {
    match data.get(key) {
        None => Ok(Vec::new()),
        Some(t) => t
            .as_table()
            .ok_or_else(|| Error::Claim(format!("data.{key} must be a table")))?
            .iter()
            .map(|(k, v)| {
                v.as_str()
                    .map(|s| (k.clone(), s.to_string()))
                    .ok_or_else(|| Error::Claim(format!("data.{key}.{k}: a string")))
            })
            .collect(),
    }
}

/// The configuration with face sequence `faces` (its length is the valence;
/// schemes without face sequences take the regular one of that valence).
fn configuration(scheme: &dyn schemes::Scheme, faces: &str) -> Result<Configuration, Error> {
    if scheme.face_sequences() {
        Configuration::with_faces(scheme, faces.len(), faces)
    } else {
        Configuration::regular(scheme, faces.len())
    }
}

/// The smallest of a stream of weights and where it occurs (the place is
/// described only when it becomes the new minimum). HOLDS when no weight is
/// negative: the shared shape of the non-negativity (convex hull) checks.
struct SmallestWeight {
    value: f64,
    at: String,
}

impl SmallestWeight {
    fn new() -> Self {
        SmallestWeight { value: f64::INFINITY, at: String::new() }
    }
    fn offer(&mut self, w: f64, at: impl FnOnce() -> String) {
        if w < self.value {
            self.value = w;
            self.at = at();
        }
    }
    /// (verdict, stated, computed, detail) with the computed value described as `what`.
    fn outcome(self, statement: &str, what: &str, detail: String) -> Result4 {
        Ok((
            verdict(self.value >= -1e-12),
            statement.into(),
            format!("{what} {} ({})", fmt_f(self.value), self.at),
            detail,
        ))
    }
}

fn verdict(holds: bool) -> Verdict {
    if holds {
        Verdict::Holds
    } else {
        Verdict::Refuted
    }
}

// ---------------------------------------------------------------- Khan–Mustafa: rules from a fit

/// The printed rules against the exact least-squares fit of span{x^a y^b}
/// (`monomials`) to the grid {lo..hi}², evaluated at the new points (α/2, β/2).
/// `rules` lists the four printed masks in the order p_{2i,2j}, p_{2i+1,2j},
/// p_{2i,2j+1}, p_{2i+1,2j+1}; mask[r − lo][s − lo] is the numerator (over
/// `denominator`) of the weight of p_{i+r, j+s}.
fn lattice_fit_masks(data: &toml::Value) -> Result4 {
    use crate::lattice::fit::{derive_masks, grid, least_squares};
    let monomials: Vec<(u32, u32)> = field(data, "monomials")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.monomials: a list of [a, b] exponents".into()))?
        .iter()
        .map(|m| {
            let e =
                m.as_array().filter(|e| e.len() == 2).ok_or_else(|| Error::Claim("each monomial is [a, b]".into()))?;
            let exponent = |v: &toml::Value| match int(v, "an exponent")? {
                x @ 0..=6 => Ok(x as u32),
                x => Err(Error::Claim(format!("monomial exponent {x} is outside the supported range 0..6"))),
            };
            Ok((exponent(&e[0])?, exponent(&e[1])?))
        })
        .collect::<Result<_, Error>>()?;
    let (lo, hi) = (int_in(data, "lo", -4, 4)?, int_in(data, "hi", -4, 4)?);
    if lo >= hi {
        return Err(Error::Claim(format!("data.lo = {lo} must be below data.hi = {hi}")));
    }
    let den = int(field(data, "denominator")?, "data.denominator")?;
    if den == 0 {
        return Err(Error::Claim("data.denominator must not be 0".into()));
    }
    let den = Rational::from_integer(den.into());
    let rules = field(data, "rules")?
        .as_array()
        .filter(|r| r.len() == 4)
        .ok_or_else(|| Error::Claim("data.rules: four masks".into()))?;
    let size = (hi - lo + 1) as usize;
    let derived = derive_masks(&monomials, &grid(lo, hi), &q(1, 1))?;
    let samples: Vec<(Rational, Rational)> = grid(lo, hi)
        .iter()
        .map(|&(r, s)| (Rational::from_integer(r.into()), Rational::from_integer(s.into())))
        .collect();
    let interpolates = least_squares(&monomials, &samples)?.interpolates();
    let names = ["p_{2i,2j}", "p_{2i+1,2j}", "p_{2i,2j+1}", "p_{2i+1,2j+1}"];
    let mut diffs = Vec::new();
    for (k, &(a, b)) in [(0usize, 0usize), (1, 0), (0, 1), (1, 1)].iter().enumerate() {
        let rows = rules[k]
            .as_array()
            .filter(|r| r.len() == size)
            .ok_or_else(|| Error::Claim("each mask is a square grid".into()))?;
        for (ri, row) in rows.iter().enumerate() {
            let row = row
                .as_array()
                .filter(|r| r.len() == size)
                .ok_or_else(|| Error::Claim("each mask is a square grid".into()))?;
            for (si, x) in row.iter().enumerate() {
                let printed = Rational::from_integer(int(x, "a mask entry")?.into()) / &den;
                let (r, s) = (lo + ri as i64, lo + si as i64);
                let fit = derived[a][b].iter().find(|e| e.0 == (r, s)).map(|e| e.1.clone()).unwrap_or_default();
                if printed != fit {
                    diffs.push(format!("{}: p_{{i{r:+},j{s:+}}} printed {printed}, fit {fit}", names[k]));
                }
            }
        }
    }
    Ok((
        verdict(diffs.is_empty()),
        format!("4 printed masks on the {size}×{size} grid"),
        if diffs.is_empty() {
            "every weight is the least-squares fit's".into()
        } else {
            format!("{} weights differ from the least-squares fit", diffs.len())
        },
        format!(
            "exact least squares of {} monomials on {} points ({}); {}",
            monomials.len(),
            size * size,
            if interpolates { "the fit interpolates" } else { "more points than monomials: a fit, not an interpolant" },
            if diffs.is_empty() { "all weights agree".into() } else { diffs.join("; ") }
        ),
    ))
}

// ---------------------------------------------------------------- Peters–Shiue: the 4-3 transition strip

struct Strip {
    s: Vec<Vec<Rational>>,
    s_plus: Vec<Vec<Rational>>,
    leading: Vec<Rational>,
    window: String,
}

/// The scheme, the configuration of the node `faces` and the planar
/// positions of its `spokes`: the setting of the lattice-window checks.
type LatticeNode = (Box<dyn schemes::Scheme>, Configuration, Vec<[i64; 2]>);
fn lattice_node(data: &toml::Value) -> Result<LatticeNode, Error> {
    let scheme = schemes::resolve(text(data, "scheme")?, &params(data, "params")?)?;
    let config = configuration(scheme.as_ref(), text(data, "faces")?)?;
    let spokes = field(data, "spokes")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.spokes: a list of [x, y]".into()))?
        .iter()
        .map(|p| {
            let v = p.as_array().filter(|v| v.len() == 2).ok_or_else(|| Error::Claim("each spoke is [x, y]".into()))?;
            Ok([int(&v[0], "a spoke")?, int(&v[1], "a spoke")?])
        })
        .collect::<Result<_, Error>>()?;
    Ok((scheme, config, spokes))
}

/// S (window to the same positions) and S⁺ (shifted by `shift`) on the window
/// [x0, x1] × [y0, y1] of the planar lattice around the node `faces`.
fn strip(data: &toml::Value) -> Result<Strip, Error> {
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
fn strip_defective(data: &toml::Value) -> Result4 {
    let st = strip(data)?;
    let n = st.s.len();
    let (spec, irrational) = crate::spectrum::strip::rational_spectrum(&st.s)?;
    if irrational > 0 {
        return Err(Error::Claim(format!(
            "{irrational} eigenvalues are not rational; geometric multiplicities not decided"
        )));
    }
    let rank: usize = spec.iter().map(|e| e.2).sum();
    let defective: Vec<String> =
        spec.iter().filter(|e| e.2 < e.1).map(|e| format!("{} (algebraic {}, geometric {})", e.0, e.1, e.2)).collect();
    let all: Vec<String> = spec.iter().map(|e| format!("{}^{}", e.0, e.1)).collect();
    Ok((
        verdict(rank < n),
        format!("the eigenvectors of S on {} do not span R^{n}", st.window),
        format!("{rank} independent eigenvectors for {n} points"),
        format!(
            "exact spectrum {}; defective: {}",
            all.join(" "),
            if defective.is_empty() { "none".into() } else { defective.join(", ") }
        ),
    ))
}

fn eigenbasis(st: &Strip) -> Result<Vec<Vec<Rational>>, Error> {
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
fn strip_structure(data: &toml::Value) -> Result4 {
    let st = strip(data)?;
    let basis = eigenbasis(&st)?;
    let k = basis.len();
    let Some(a) = crate::spectrum::strip::action_on(&st.s_plus, &basis) else {
        return Ok((
            Verdict::Refuted,
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
    Ok((
        verdict(bad.is_empty()),
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
fn strip_shifted_eigenvectors(data: &toml::Value) -> Result4 {
    let st = strip(data)?;
    let basis = eigenbasis(&st)?;
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
    Ok((
        verdict(all),
        "the 1/2-eigenvectors of S⁺ are v_i + m_i v0".into(),
        out.join("; "),
        "exact, in the leading eigenvectors of S (the statement does not depend on their scaling)".into(),
    ))
}

/// Lemma 3.3: ρ^[k](Q⁴³, Q⁺) < bound, Q the action of S and S⁺ modulo the
/// leading eigenvectors (an orthonormal complement stands for the paper's
/// unspecified remaining columns of V; ρ^[k] depends on that basis, the joint
/// spectral radius it bounds does not).
fn strip_jsr(data: &toml::Value) -> Result4 {
    use crate::spectrum::strip::{jsr_bounds, orthogonal_complement, to_f64};
    let st = strip(data)?;
    let basis = eigenbasis(&st)?;
    let n = st.s.len();
    if crate::spectrum::strip::action_on(&st.s_plus, &basis).is_none() {
        return Err(Error::Undecided("the leading eigenvectors are not invariant under S⁺: Q⁺ is not defined".into()));
    }
    let length = int_in(data, "length", 1, 16)? as usize;
    let bound = crate::numeric::Weight::to_f64(&exact(text(data, "bound")?)?);
    let w = faer::Mat::from_fn(n, basis.len(), |i, j| crate::numeric::Weight::to_f64(&basis[j][i]));
    let c = orthogonal_complement(&w)?;
    let (s, sp) = (to_f64(&st.s), to_f64(&st.s_plus));
    let q43 = c.transpose() * &s * &c;
    let qp = c.transpose() * &sp * &c;
    let b = jsr_bounds(&[q43, qp], length, 4)?;
    let word: Vec<&str> = b.lower_word.iter().rev().map(|&k| if k == 0 { "Q43" } else { "Q+" }).collect();
    Ok((
        if b.upper < bound {
            Verdict::Holds
        } else if b.lower >= bound {
            Verdict::Refuted
        } else {
            Verdict::Inconclusive
        },
        format!("ρ^[{length}](Q43, Q+) < {bound} (Q of size {})", n - basis.len()),
        format!("ρ^[{length}] = {} (upper bound); lower bound {} from {}", fmt_f(b.upper), fmt_f(b.lower), word.join("·")),
        format!(
            "every product of {length} factors in the ∞-norm, Q in an orthonormal basis of the complement of the {} leading eigenvectors; so ρ(Y43, Y+) = max(ρ(d), ρ(Q)) = {}",
            basis.len(),
            if b.upper < bound { format!("{bound}") } else { "undecided".into() }
        ),
    ))
}

// ---------------------------------------------------------------- Peters–Shiue: M, E, C and the convex hull

/// Lemma 3.4 for n = 3..16: "E + C is a projection, (E + C)² = E + C, C² = C,
/// Ce = 0, eeᵗ = nE, eᵗe = n, Ee = e, EE = E; C is of rank 2 and E + C of
/// rank 3". The printed matrices come in `data.e` and `data.c` (expressions in
/// the row k = 0..n−1, the column l = 0..n−1 and n; `i` is the imaginary unit) and the printed ranks in `data.rank_c` and
/// `data.rank_e_plus_c`. Each identity is checked in floating point (largest
/// entry deviation at most 1e-12); a rank is the number of singular values
/// above 1e-9, and the evidence gives the gap around that threshold.
fn fourthree_lemma_3_4(data: &toml::Value) -> Result4 {
    use crate::numeric::expr::{env_int, Expr};
    let (e_text, c_text) = (text(data, "e")?, text(data, "c")?);
    let (e_expr, c_expr) = (Expr::parse(e_text)?, Expr::parse(c_text)?);
    let stated_rank_c = int_in(data, "rank_c", 0, 16)? as usize;
    let stated_rank_ec = int_in(data, "rank_e_plus_c", 0, 16)? as usize;
    const IDENTITIES: [&str; 7] = ["(E + C)² = E + C", "C² = C", "Ce = 0", "eeᵗ = nE", "eᵗe = n", "Ee = e", "EE = E"];
    let mut worst = [0.0f64; 7];
    let mut ranks = Vec::new();
    // smallest singular value counted in a rank, largest not counted
    let (mut kept, mut dropped) = (f64::INFINITY, 0.0f64);
    for n in 3..=16usize {
        let nf = n as f64;
        let matrix = |expr: &Expr| -> Result<faer::Mat<f64>, Error> {
            let mut m = faer::Mat::<f64>::zeros(n, n);
            for i in 0..n {
                for j in 0..n {
                    let z = expr.eval(&env_int(&[("k", i as i64), ("l", j as i64), ("n", n as i64)]))?;
                    if z.im.abs() > 1e-12 || !z.re.is_finite() {
                        return Err(Error::Claim(format!("an entry is not a finite real number at n = {n}")));
                    }
                    m[(i, j)] = z.re;
                }
            }
            Ok(m)
        };
        let (e, c) = (matrix(&e_expr)?, matrix(&c_expr)?);
        let ec = &e + &c;
        let ones = faer::Mat::<f64>::from_fn(n, 1, |_, _| 1.0);
        let diff = |a: &faer::Mat<f64>, b: &faer::Mat<f64>| (a - b).norm_max();
        let deviations = [
            diff(&(&ec * &ec), &ec),
            diff(&(&c * &c), &c),
            (&c * &ones).norm_max(),
            diff(&(&ones * ones.transpose()), &(&e * nf)),
            ((ones.transpose() * &ones)[(0, 0)] - nf).abs(),
            diff(&(&e * &ones), &ones),
            diff(&(&e * &e), &e),
        ];
        for (w, d) in worst.iter_mut().zip(deviations) {
            *w = w.max(d);
        }
        let mut rank = |m: &faer::Mat<f64>| -> Result<usize, Error> {
            let s = m.singular_values().map_err(|e| Error::Numeric(format!("{e:?}")))?;
            for x in &s {
                if *x > 1e-9 {
                    kept = kept.min(*x);
                } else {
                    dropped = dropped.max(*x);
                }
            }
            Ok(s.iter().filter(|x| **x > 1e-9).count())
        };
        ranks.push((n, rank(&c)?, rank(&ec)?));
    }
    let failed: Vec<String> = IDENTITIES
        .iter()
        .zip(worst)
        .filter(|(_, w)| w.is_nan() || *w > 1e-12)
        .map(|(name, w)| format!("{name} fails (largest deviation {w:.3e})"))
        .collect();
    let rank_errors: Vec<String> = ranks
        .iter()
        .filter(|r| r.1 != stated_rank_c || r.2 != stated_rank_ec)
        .map(|r| format!("n = {}: rank C = {}, rank (E + C) = {}", r.0, r.1, r.2))
        .collect();
    let largest = worst.iter().cloned().fold(0.0, f64::max);
    let holds = failed.is_empty() && rank_errors.is_empty();
    Ok((
        verdict(holds),
        format!(
            "(E + C)² = E + C, C² = C, Ce = 0, eeᵗ = nE, eᵗe = n, Ee = e, EE = E; rank C = {stated_rank_c}, rank (E + C) = {stated_rank_ec}"
        ),
        format!(
            "{}; {}",
            if failed.is_empty() {
                format!("every identity holds (largest deviation {largest:.1e} over n = 3..16)")
            } else {
                failed.join(", ")
            },
            if rank_errors.is_empty() {
                format!("rank C = {stated_rank_c} and rank (E + C) = {stated_rank_ec} at every n")
            } else {
                let shown: Vec<String> = rank_errors.iter().take(4).cloned().collect();
                format!("ranks differ from the statement: {}", shown.join("; "))
            }
        ),
        format!(
            "E_kl = {e_text}, C_kl = {c_text}, n = 3..16, floating point; ranks from singular values: the smallest counted {}, the largest not counted {}",
            fmt_f(kept),
            if dropped < 1e-12 { "below 1e-12".to_string() } else { format!("{dropped:.1e}") }
        ),
    ))
}

/// The eon configuration `faces` of 4-3 subdivision on a patch, refined with the
/// rules of steps 1..=`steps` (σ-blended, (4a') with share `eon_quad_term`).
type Patch = (Box<dyn schemes::Scheme>, crate::mesh::PolyMesh, crate::mesh::PolyMesh, CompositeRows);

fn fourthree_patch(data: &toml::Value, steps: usize) -> Result<Patch, Error> {
    let scheme = schemes::build("four-three", &params(data, "params")?)?;
    let faces = text(data, "faces")?;
    let config = Configuration::with_faces(scheme.as_ref(), faces.len(), faces)?;
    let rings = int_in(data, "rings", 1, 8)? as usize;
    let (patch, _) = build_patch(&config, rings);
    let (fine, rows) = crate::refine::mesh::composite_weights(scheme.as_ref(), &patch, 1..=steps)?;
    Ok((scheme, patch, fine, rows))
}

fn coord(mesh: &crate::mesh::PolyMesh, v: usize) -> String {
    match mesh.chart.as_ref() {
        Some(c) => {
            let x = c.vertex_coords[v];
            format!("(sector {}, {}, {})", x.sector, x.i, x.j)
        }
        None => format!("#{v}"),
    }
}

/// Lemma 3.8's proof: after the second step (regular rules in step 1, half
/// (4b) and half (4a') in step 2) every weight of an old node in a new node is
/// non-negative. The most negative composite weight on the patch.
fn fourthree_step_two(data: &toml::Value) -> Result4 {
    let (_, patch, fine, rows) = fourthree_patch(data, 2)?;
    let mut worst = SmallestWeight::new();
    for (v, r) in rows.iter().enumerate() {
        for (u, w) in r.iter().flat_map(|r| r.entries.iter()) {
            worst.offer(*w, || format!("new node {} on old node {}", coord(&fine, v), coord(&patch, *u)));
        }
    }
    worst.outcome(
        "after two steps every contribution of an old node to a new node is non-negative",
        "most negative composite weight",
        format!(
            "eon {} with the σ-blended rules of steps 1 and 2, composed exactly as a mesh refinement does",
            text(data, "faces")?
        ),
    )
}

/// Lemma 3.8: with (4a') blended in over steps σ ≤ σ0 the surface lies in the
/// convex hull of its control points. A limit point with a negative weight on
/// a control point leaves the hull for suitable data. Limit points of nodes u
/// of the step-σ0 net that are regular (4 quads or 6 triangles) and at least 3
/// lattice steps from the eon: later steps around u use regular rules only, so
/// the limit is the regular limit stencil (computed from the scheme on the
/// regular configuration) applied to u and its neighbours.
fn fourthree_convex_hull(data: &toml::Value) -> Result4 {
    use crate::schemes::four_three::{classify, NodeType};
    use crate::spectrum::stencils::limit_stencil;
    let steps = int_in(data, "steps", 1, 4)? as usize;
    let (scheme, patch, fine, rows) = fourthree_patch(data, steps)?;
    // regular limit stencils: weights of the centre, its edge neighbours and (quads) its diagonal neighbours
    let regular = |faces: &str| -> Result<(f64, f64, f64), Error> {
        let config = Configuration::with_faces(scheme.as_ref(), faces.len(), faces)?;
        let a = analyse(scheme.as_ref(), &config, &Options { exact: false, ..Options::default() })?;
        let l = limit_stencil(&a.spectrum)?;
        let (mut c, mut e, mut d) = (None::<f64>, None::<f64>, None::<f64>);
        for (w, lab) in l.iter().zip(&a.spectrum.labels) {
            use crate::neighbourhood::VertexKind as K;
            let slot = match (lab.kind, lab.ring) {
                (K::Centre, _) => &mut c,
                (K::Edge, 1) => &mut e,
                (K::Face, 1) => &mut d,
                _ if w.abs() < 1e-12 => continue,
                _ => {
                    return Err(Error::Undecided(format!("the regular limit stencil of {faces} reaches {}", lab.name)))
                }
            };
            if slot.is_some_and(|x| (x - w).abs() > 1e-12) {
                return Err(Error::Undecided(format!("the regular limit stencil of {faces} is not symmetric")));
            }
            *slot = Some(*w);
        }
        Ok((c.unwrap_or(0.0), e.unwrap_or(0.0), d.unwrap_or(0.0)))
    };
    let quad = regular("QQQQ")?;
    let tri = regular("TTTTTT")?;
    let chart = fine.chart.as_ref().ok_or_else(|| Error::Claim("no chart".into()))?;
    let mut worst = SmallestWeight::new();
    let mut count = 0;
    'nodes: for u in 0..fine.num_vertices() {
        let c = chart.vertex_coords[u];
        if c.i + c.j < 3 {
            continue;
        }
        let Some((fan, t)) = classify(&fine, u) else { continue };
        let (wc, we, wd) = match t {
            NodeType::RegularQuad => quad,
            NodeType::RegularTri => tri,
            _ => continue,
        };
        let mut terms: Vec<(usize, f64)> = vec![(u, wc)];
        terms.extend(fan.iter().map(|f| (f[1], we)));
        if t == NodeType::RegularQuad {
            terms.extend(fan.iter().map(|f| (f[2], wd)));
        }
        let mut acc: std::collections::BTreeMap<usize, f64> = Default::default();
        for (v, w) in terms {
            let Some(r) = &rows[v] else { continue 'nodes };
            for (k, x) in &r.entries {
                *acc.entry(*k).or_default() += w * x;
            }
        }
        count += 1;
        for (k, x) in acc {
            worst.offer(x, || {
                format!("the limit of node {} of step {steps} on control point {}", coord(&fine, u), coord(&patch, k))
            });
        }
    }
    worst.outcome(
        "the limit surface lies in the convex hull of the control points (every limit weight ≥ 0)",
        "most negative limit weight",
        format!(
            "eon {} ({count} regular limit points checked, from the σ-blended rules of steps 1..{steps}); a negative weight puts that limit point outside the hull when its control point is moved away",
            text(data, "faces")?
        ),
    )
}

// ---------------------------------------------------------------- non-box: non-negative weights

/// Every entry of the local subdivision matrix is non-negative, at every
/// valence and parameter set listed (`data.params`, sampled: sufficiency
/// only). With `data.param` and `data.range` the statement is an equivalence
/// instead, decided in both directions: [`matrix_nonnegative_range`].
fn matrix_nonnegative(data: &toml::Value) -> Result4 {
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
            let a = analyse(scheme.as_ref(), &config, &Options { exact: false, ..Options::default() })?;
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

/// Exact rationals from a list of strings `data.key`.
fn exact_list(data: &toml::Value, key: &str) -> Result<Vec<Rational>, Error> {
    field(data, key)?
        .as_array()
        .ok_or_else(|| Error::Claim(format!("data.{key}: a list of exact numbers as strings")))?
        .iter()
        .map(|x| x.as_str().ok_or_else(|| Error::Claim(format!("data.{key}: strings"))).and_then(exact))
        .collect()
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
fn matrix_nonnegative_range(data: &toml::Value) -> Result4 {
    use crate::matrix::assemble;
    use crate::neighbourhood::{discover, NeighbourhoodKind};
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
    let kind = NeighbourhoodKind::Analysis;
    let shown = |x: &Rational| format!("{param} = {x}");
    let (mut if_fails, mut only_if_fails, mut evidence) = (Vec::new(), Vec::new(), Vec::new());
    let (mut not_affine, mut acting) = (Vec::new(), Vec::new());
    for &k in &valences {
        let config = Configuration::regular(rules[0].as_ref(), k as usize)?;
        let mut found = Vec::new();
        for r in &rules {
            found.push(discover(r.as_ref(), &config)?);
        }
        let d = found.iter().max_by_key(|d| d.set(kind).len()).expect("at least three samples");
        let mut mats = Vec::new();
        for (r, x) in rules.iter().zip(&samples) {
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
            continue;
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
            continue;
        }
        acting.push(k.to_string());
        if empty {
            if_fails.push(format!("k = {k}: S ≥ 0 at no {param}; at {}: {}", shown(&lo), most_negative(&lo)));
            evidence.push(format!("k = {k}: S ≥ 0 for no value of {param}"));
            continue;
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
    }
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
    let verdict = if !if_fails.is_empty() || !only_if_fails.is_empty() {
        Verdict::Refuted
    } else if !not_affine.is_empty() || acting.is_empty() {
        Verdict::Inconclusive
    } else {
        Verdict::Holds
    };
    let samples_text: Vec<String> = samples.iter().map(|x| x.to_string()).collect();
    Ok((
        verdict,
        format!("every subdivision weight is non-negative exactly when {range_text}"),
        format!("{if_part}; {only_if_part}"),
        format!(
            "exact S (analysis neighbourhood) at {param} = {}: every entry affine in {param} (the line through the first two samples meets the others exactly; the premise of the interval), so the set of {param} with S ≥ 0 is an interval whose ends are roots of single entries; {}",
            samples_text.join(", "),
            evidence.join("; ")
        ),
    ))
}

// ---------------------------------------------------------------- Lin–Luo: curves

/// Eq. (3): P³_i = P¹_i − (Δ(P_i) + Δ(P_{i+1}))/2 with Δ(P_i) = P²_i − P⁰_i of a
/// cubic B-spline step is the four-point point. Both sides are linear maps of
/// the polygon: compared exactly on every unit polygon of length 8.
fn curve_relation3() -> Result4 {
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
    Ok((
        verdict(diffs == 0),
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
fn curve_c1_laurent(data: &toml::Value) -> Result4 {
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
    Ok((
        if disproven > 0 {
            Verdict::Refuted
        } else if proven == values.len() {
            Verdict::Holds
        } else {
            Verdict::Inconclusive
        },
        format!("C¹ limit curves for constant {param}"),
        out.join("; "),
        "exact Laurent-polynomial test: a(z) = (1 + z)² b(z)/2 and S_b contractive (sufficient for C¹); where it fails, \
         the exact local matrix on the analysis window (an eigenvector whose limit is not differentiable at the vertex \
         disproves C¹)"
            .into(),
    ))
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

/// Section 2: "in each subdivision step, the number of eons stays constant,
/// the number of boundary nodes and 4-3 transition nodes doubles and regular
/// nodes quadruple". Node types counted on a shipped closed mesh refined by
/// `subdlab refine`'s code, level by level.
fn fourthree_node_counts(data: &toml::Value) -> Result4 {
    use crate::schemes::four_three::{classify, NodeType};
    let (name, text_obj) = match text(data, "mesh")? {
        "house.obj" => ("house.obj", include_str!("../../meshes/house.obj")),
        "prism.obj" => ("prism.obj", include_str!("../../meshes/prism.obj")),
        other => return Err(Error::Claim(format!("no built-in mesh '{other}' (house.obj, prism.obj)"))),
    };
    let obj = crate::mesh::obj::parse_obj(text_obj)?;
    let levels = int_in(data, "levels", 1, 5)? as usize;
    let scheme = schemes::build("four-three", &[])?;
    let count = |m: &crate::mesh::PolyMesh| -> Result<[usize; 3], Error> {
        let mut c = [0usize; 3];
        for v in 0..m.num_vertices() {
            match classify(m, v).ok_or_else(|| Error::Undecided("a vertex is not classifiable".into()))?.1 {
                NodeType::Eon => c[0] += 1,
                NodeType::Transition { .. } => c[1] += 1,
                NodeType::RegularQuad | NodeType::RegularTri => c[2] += 1,
            }
        }
        Ok(c)
    };
    let mut counts = vec![count(&obj.0)?];
    for l in 1..=levels {
        let (m, _) = crate::refine::mesh::refine_mesh(scheme.as_ref(), &obj.0, &obj.1, l)?;
        counts.push(count(&m)?);
    }
    let mut bad = Vec::new();
    for l in 1..counts.len() {
        let (a, b) = (counts[l - 1], counts[l]);
        if b[0] != a[0] {
            bad.push(format!("level {l}: eons {} → {}", a[0], b[0]));
        }
        if b[1] != 2 * a[1] {
            bad.push(format!("level {l}: transition nodes {} → {} (not doubled)", a[1], b[1]));
        }
        if b[2] != 4 * a[2] {
            bad.push(format!("level {l}: regular nodes {} → {} (not quadrupled)", a[2], b[2]));
        }
    }
    let shown: Vec<String> =
        counts.iter().enumerate().map(|(l, c)| format!("L{l}: {}/{}/{}", c[0], c[1], c[2])).collect();
    Ok((
        verdict(bad.is_empty()),
        "eons constant, transition nodes ×2, regular nodes ×4 per step".into(),
        format!("{name}, eons/transition/regular {}", shown.join(", ")),
        if bad.is_empty() { "every step as stated".into() } else { bad.join("; ") },
    ))
}

/// The samples of the polynomials of total degree ≤ `degree` on a lattice
/// window span a space that S maps into itself (S: coarse points of the
/// window to the refined points at the same positions, fine units): the
/// scheme maps polynomial data of that degree to polynomial data of that
/// degree, so its limits of such data are those polynomials' space (the
/// regular box-spline schemes "reproduce all polynomials of degree ≤ d").
/// Also reports the first degree that is not kept.
fn window_polynomials(data: &toml::Value) -> Result4 {
    use crate::spectrum::strip::{action_on, window_matrices};
    let (scheme, config, spokes) = lattice_node(data)?;
    let w = small_window(data, MAX_DATA_WINDOW)?;
    // a polynomial of degree ≤ d + 1 is determined by its samples only while
    // d + 1 is below the window's width and height
    let side = (w[1] - w[0]).min(w[3] - w[2]);
    let degree = int_in(data, "degree", 0, (side - 1).max(0))? as u32;
    let window: Vec<[i64; 2]> = (w[2]..=w[3]).flat_map(|y| (w[0]..=w[1]).map(move |x| [x, y])).collect();
    let s = window_matrices(scheme.as_ref(), &config, &spokes, &window, &[[0, 0]])?.pop().expect("one matrix");
    let samples = |d: u32| -> Vec<Vec<Rational>> {
        (0..=d)
            .flat_map(|t| (0..=t).map(move |b| (t - b, b)))
            .map(|(a, b)| window.iter().map(|p| Rational::from_integer((p[0].pow(a) * p[1].pow(b)).into())).collect())
            .collect()
    };
    let kept = |d: u32| action_on(&s, &samples(d)).is_some();
    let holds = kept(degree);
    let next = (degree + 1..=degree + 3).find(|&d| !kept(d));
    Ok((
        verdict(holds),
        format!("polynomial data of degree ≤ {degree} stay polynomial of degree ≤ {degree}"),
        format!(
            "degree ≤ {degree}: {}; first degree not kept: {}",
            if holds { "kept" } else { "not kept" },
            next.map(|d| d.to_string()).unwrap_or_else(|| format!("above {}", degree + 3))
        ),
        window_evidence(data, &w, window.len())?,
    ))
}

// ---------------------------------------------------------------- 4-3: second pass over the statements

/// Lemma 3.8, after its proof: without rule (4a'), "the contribution of a node
/// w_i to a node v_0 after two subdivision steps is bounded below by −1/(64n)".
/// For every eon in `faces` (a list of face sequences): the smallest composite
/// weight of an old quad diagonal w_i ((1, 1) in a quad sector's chart) in a
/// new direct neighbour of the eon after the σ-blended steps 1 and 2, against
/// `bound`, an expression in n (the valence).
fn fourthree_step_two_bound(data: &toml::Value) -> Result4 {
    use crate::mesh::SectorKind;
    let list = field(data, "faces")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.faces must be a list of face sequences".into()))?;
    if list.is_empty() || list.len() > 16 {
        return Err(Error::Claim("data.faces: 1 to 16 face sequences".into()));
    }
    let bound = crate::numeric::expr::Expr::parse(text(data, "bound")?)?;
    let (mut holds, mut computed, mut detail) = (true, Vec::new(), Vec::new());
    for f in list {
        let faces = f.as_str().ok_or_else(|| Error::Claim("data.faces: strings such as \"QQQQQ\"".into()))?;
        let mut one = data.clone();
        if let Some(t) = one.as_table_mut() {
            t.insert("faces".into(), toml::Value::String(faces.into()));
        }
        let (_, patch, fine, rows) = fourthree_patch(&one, 2)?;
        let n = faces.len() as i64;
        let mut env = crate::numeric::expr::Env::new();
        env.insert("n".into(), crate::numeric::weight::ParamValue::from_ratio(n, 1));
        let b = bound.eval(&env)?.re;
        let (pc, fc) = match (patch.chart.as_ref(), fine.chart.as_ref()) {
            (Some(p), Some(f)) => (p, f),
            _ => return Err(Error::Undecided("no lattice chart".into())),
        };
        let is_w = |u: usize| {
            let c = pc.vertex_coords[u];
            c.i == 1 && c.j == 1 && pc.sector_kinds[c.sector] == SectorKind::Quad
        };
        let mut worst = SmallestWeight::new();
        let mut pairs = 0;
        for (v, r) in rows.iter().enumerate() {
            let c = fc.vertex_coords[v];
            if c.i + c.j != 1 || c.i < 0 || c.j < 0 {
                continue;
            }
            for (u, w) in r.iter().flat_map(|r| r.entries.iter()).filter(|(u, _)| is_w(*u)) {
                pairs += 1;
                worst.offer(*w, || format!("w = {} in v = {}", coord(&patch, *u), coord(&fine, v)));
            }
        }
        if pairs == 0 {
            return Err(Error::Claim(format!("{faces}: no quad diagonal reaches a direct neighbour of the eon")));
        }
        let ok = worst.value >= b - 1e-15;
        holds &= ok;
        computed.push(format!("{faces}: {} ({}) vs bound {}", fmt_f(worst.value), worst.at, fmt_f(b)));
        detail.push(format!("{faces}: {pairs} (w_i, v_0) pairs"));
    }
    Ok((
        verdict(holds),
        format!("every contribution of a w_i to a v_0 after two steps is ≥ {}", text(data, "bound")?),
        computed.join("; "),
        format!(
            "composite weights of the σ-blended steps 1 (regular rules) and 2 (half (4b)), composed exactly as a mesh refinement does; {}",
            detail.join(", ")
        ),
    ))
}

/// Lemma 3.2: the factored step (bilinear refinement, then one symmetric 3×3
/// smoothing stencil [γ β γ; β α β; γ β γ], α + 4β + 4γ = 1) is ripple-free
/// in direction d when every net with zero first differences along d (a ridge
/// r(d⊥·x) with any profile) is refined to a net that is again constant along
/// d. Each ridge gives, for every fine node x of a window, the linear equation
/// "smoothed(x + d) − smoothed(x) = 0" in (α, β, γ), exactly. The solution set
/// over every direction of `directions` (with `profiles` integer ridge
/// profiles) against the `stated` stencil [α, β, γ]: HOLDS when the stated
/// stencil is the only solution.
fn fourthree_ripple_free_unique(data: &toml::Value) -> Result4 {
    let dirs = field(data, "directions")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.directions: a list of [dx, dy]".into()))?;
    if dirs.is_empty() || dirs.len() > 8 {
        return Err(Error::Claim("data.directions: 1 to 8 directions".into()));
    }
    let profiles = field(data, "profiles")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.profiles: a list of integer lists".into()))?;
    if profiles.is_empty() || profiles.len() > 8 {
        return Err(Error::Claim("data.profiles: 1 to 8 profiles".into()));
    }
    let stated: Vec<Rational> = field(data, "stated")?
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or_else(|| Error::Claim("data.stated: [α, β, γ]".into()))?
        .iter()
        .map(|x| x.as_str().ok_or_else(|| Error::Claim("data.stated: strings".into())).and_then(exact))
        .collect::<Result<_, _>>()?;
    const R: i64 = 6; // coarse window [-R, R]², fine equations on [-2R + 4, 2R - 4]²
    let mut eqs: Vec<[Rational; 4]> = vec![[q(1, 1), q(4, 1), q(4, 1), q(1, 1)]]; // α + 4β + 4γ = 1
    for d in dirs {
        let d = ints_of(d, "data.directions")?;
        if d.len() != 2 || d.iter().any(|x| x.abs() > 1) || d == [0, 0] {
            return Err(Error::Claim(format!("data.directions: {d:?} is not a unit lattice direction")));
        }
        for prof in profiles {
            let prof = ints_of(prof, "data.profiles")?;
            if prof.is_empty() || prof.len() > 64 || prof.iter().any(|x| x.abs() > 1_000_000) {
                return Err(Error::Claim("data.profiles: 1 to 64 integers of modulus ≤ 10⁶".into()));
            }
            // the coarse ridge: constant along d, the profile across it (repeated)
            let m = prof.len() as i64;
            let coarse = |i: i64, j: i64| -> Rational {
                let t = d[1] * i - d[0] * j; // constant along (d[0], d[1])
                Rational::from_integer(prof[t.rem_euclid(m) as usize].into())
            };
            // bilinear refinement
            let fine = |x: i64, y: i64| -> Rational {
                let (i, j) = (x.div_euclid(2), y.div_euclid(2));
                match (x.rem_euclid(2), y.rem_euclid(2)) {
                    (0, 0) => coarse(i, j),
                    (1, 0) => (coarse(i, j) + coarse(i + 1, j)) / q(2, 1),
                    (0, 1) => (coarse(i, j) + coarse(i, j + 1)) / q(2, 1),
                    _ => (coarse(i, j) + coarse(i + 1, j) + coarse(i, j + 1) + coarse(i + 1, j + 1)) / q(4, 1),
                }
            };
            // smoothing as a linear form in (α, β, γ)
            let smooth = |x: i64, y: i64| -> [Rational; 3] {
                let e = fine(x + 1, y) + fine(x - 1, y) + fine(x, y + 1) + fine(x, y - 1);
                let c = fine(x + 1, y + 1) + fine(x - 1, y - 1) + fine(x - 1, y + 1) + fine(x + 1, y - 1);
                [fine(x, y), e, c]
            };
            for x in -2 * R + 4..=2 * R - 4 {
                for y in -2 * R + 4..=2 * R - 4 {
                    let (a, b) = (smooth(x + d[0], y + d[1]), smooth(x, y));
                    eqs.push([
                        a[0].clone() - b[0].clone(),
                        a[1].clone() - b[1].clone(),
                        a[2].clone() - b[2].clone(),
                        q(0, 1),
                    ]);
                }
            }
        }
    }
    // reduced row echelon form of the augmented system
    let mut rows = eqs;
    let mut pivots = Vec::new();
    let mut r = 0;
    for c in 0..3 {
        let Some(p) = (r..rows.len()).find(|&i| !rows[i][c].is_zero()) else { continue };
        rows.swap(r, p);
        let lead = rows[r][c].clone();
        for x in rows[r].iter_mut() {
            *x = x.clone() / lead.clone();
        }
        let pivot_row = rows[r].clone();
        for (i, row) in rows.iter_mut().enumerate() {
            if i != r && !row[c].is_zero() {
                let f = row[c].clone();
                for (x, p) in row.iter_mut().zip(&pivot_row) {
                    *x -= f.clone() * p.clone();
                }
            }
        }
        pivots.push(c);
        r += 1;
    }
    let consistent = rows[r..].iter().all(|row| row[3].is_zero());
    let names = ["α", "β", "γ"];
    let computed = if !consistent {
        "no symmetric 3×3 stencil is ripple-free in these directions".to_string()
    } else if pivots.len() == 3 {
        format!("the only solution: α = {}, β = {}, γ = {}", rows[0][3], rows[1][3], rows[2][3])
    } else {
        let free: Vec<&str> = (0..3).filter(|c| !pivots.contains(c)).map(|c| names[c]).collect();
        format!("a {}-parameter family of solutions (free: {})", 3 - pivots.len(), free.join(", "))
    };
    let unique_as_stated = consistent && pivots.len() == 3 && (0..3).all(|k| rows[k][3] == stated[k]);
    Ok((
        verdict(unique_as_stated),
        format!(
            "the only symmetric 3×3 smoothing stencil after bilinear refinement that is ripple-free in every listed direction is α = {}, β = {}, γ = {}",
            stated[0], stated[1], stated[2]
        ),
        computed,
        format!(
            "exact linear system in (α, β, γ): {} directions × {} ridge profiles, one equation per fine node of [{}, {}]², plus α + 4β + 4γ = 1",
            dirs.len(),
            profiles.len(),
            -2 * R + 4,
            2 * R - 4
        ),
    ))
}

fn ints_of(v: &toml::Value, what: &str) -> Result<Vec<i64>, Error> {
    v.as_array()
        .ok_or_else(|| Error::Claim(format!("{what}: a list of integers")))?
        .iter()
        .map(|x| int(x, what))
        .collect()
}

/// Section 3.1 of the 4-3 paper: the ±1 checkerboard coefficient sequence
/// "generates the zero function" (the A_4 box splines are linearly
/// dependent). One step of the node's rules on a lattice window maps the
/// samples (−1)^(x + y) to zero exactly; then every later net is zero, and so
/// is the limit.
fn window_checkerboard_kernel(data: &toml::Value) -> Result4 {
    use crate::spectrum::strip::window_matrices;
    let (scheme, config, spokes) = lattice_node(data)?;
    let w = small_window(data, MAX_DATA_WINDOW)?;
    let window: Vec<[i64; 2]> = (w[2]..=w[3]).flat_map(|y| (w[0]..=w[1]).map(move |x| [x, y])).collect();
    let s = window_matrices(scheme.as_ref(), &config, &spokes, &window, &[[0, 0]])?.pop().expect("one matrix");
    let c: Vec<Rational> =
        window.iter().map(|p| if (p[0] + p[1]).rem_euclid(2) == 0 { q(1, 1) } else { q(-1, 1) }).collect();
    let image: Vec<Rational> =
        s.iter().map(|row| row.iter().zip(&c).fold(q(0, 1), |a, (x, y)| a + x.clone() * y.clone())).collect();
    let nonzero: Vec<String> = window
        .iter()
        .zip(&image)
        .filter(|(_, v)| !v.is_zero())
        .take(4)
        .map(|(p, v)| format!("{v} at ({}, {})", p[0], p[1]))
        .collect();
    let count = image.iter().filter(|v| !v.is_zero()).count();
    Ok((
        verdict(count == 0),
        "one step maps the checkerboard (−1)^(x + y) to zero (it generates the zero function)".into(),
        if count == 0 {
            "zero at every refined point of the window".into()
        } else {
            format!("{count} refined points non-zero, e.g. {}", nonzero.join(", "))
        },
        window_evidence(data, &w, window.len())?,
    ))
}

/// The evidence line of the window checks: exact, the configuration and the window.
fn window_evidence(data: &toml::Value, w: &[i64], points: usize) -> Result<String, Error> {
    Ok(format!(
        "exact, {} on the window [{}, {}] × [{}, {}] ({points} points)",
        text(data, "faces")?,
        w[0],
        w[1],
        w[2],
        w[3]
    ))
}

/// The rules on a regular window are subdivision of the box spline with the
/// given `directions` (chart coordinates), and that box spline has the stated
/// `degree` and smoothness C^`smoothness`. The mask is the box spline's own:
/// symbol 4 Π_ξ (1 + z^ξ)/2, centred (primal); row p of S (fine position p)
/// must hold mask(p − 2q) on the coarse point q, exactly. Degree and
/// smoothness follow from the directions alone (de Boor–Höllig–Riemenschneider,
/// *Box Splines*, ch. I): m directions in the plane give degree m − 2, and the
/// box spline is C^(r−2) where r is the fewest directions whose removal leaves
/// a set that does not span the plane (all but the most populous line).
fn window_box_spline(data: &toml::Value) -> Result4 {
    use crate::spectrum::strip::window_matrices;
    use std::collections::HashMap;
    let (scheme, config, spokes) = lattice_node(data)?;
    let w = small_window(data, MAX_DATA_WINDOW)?;
    let directions: Vec<[i64; 2]> = field(data, "directions")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.directions: a list of [x, y]".into()))?
        .iter()
        .map(|d| match ints_of(d, "data.directions")?.as_slice() {
            [x, y] if (x.abs() <= 4 && y.abs() <= 4) && (*x, *y) != (0, 0) => Ok([*x, *y]),
            _ => Err(Error::Claim("data.directions: non-zero [x, y] with entries in -4..4".into())),
        })
        .collect::<Result<_, _>>()?;
    if !(3..=12).contains(&directions.len()) {
        return Err(Error::Claim("data.directions: 3 to 12 directions".into()));
    }
    let stated_degree = int_in(data, "degree", 0, 20)?;
    let stated_smoothness = int_in(data, "smoothness", -1, 20)?;
    // the mask: coefficients of Π (1 + z^ξ), centred, over 2^m / 4
    let mut poly: HashMap<[i64; 2], i64> = HashMap::from([([0, 0], 1)]);
    for d in &directions {
        let mut next = poly.clone();
        for (p, c) in &poly {
            *next.entry([p[0] + d[0], p[1] + d[1]]).or_insert(0) += c;
        }
        poly = next;
    }
    let sum = directions.iter().fold([0, 0], |a, d| [a[0] + d[0], a[1] + d[1]]);
    if sum[0] % 2 != 0 || sum[1] % 2 != 0 {
        return Err(Error::Claim("the directions sum to an odd vector: not a primal box spline".into()));
    }
    let den = (1i64 << directions.len()) / 4;
    let mask = |p: [i64; 2]| q(*poly.get(&[p[0] + sum[0] / 2, p[1] + sum[1] / 2]).unwrap_or(&0), den);
    let window: Vec<[i64; 2]> = (w[2]..=w[3]).flat_map(|y| (w[0]..=w[1]).map(move |x| [x, y])).collect();
    let s = window_matrices(scheme.as_ref(), &config, &spokes, &window, &[[0, 0]])?.pop().expect("one matrix");
    let mut differ = Vec::new();
    for (r, p) in window.iter().enumerate() {
        for (c, qq) in window.iter().enumerate() {
            let want = mask([p[0] - 2 * qq[0], p[1] - 2 * qq[1]]);
            if s[r][c] != want {
                differ.push(format!("fine {p:?} on coarse {qq:?}: rules {}, mask {want}", s[r][c]));
            }
        }
    }
    // smoothness: directions grouped by the line they span
    let mut lines: Vec<([i64; 2], usize)> = Vec::new();
    for d in &directions {
        match lines.iter_mut().find(|(l, _)| l[0] * d[1] - l[1] * d[0] == 0) {
            Some((_, k)) => *k += 1,
            None => lines.push((*d, 1)),
        }
    }
    let most = lines.iter().map(|l| l.1).max().unwrap_or(0);
    let (degree, smoothness) = (directions.len() as i64 - 2, (directions.len() - most) as i64 - 2);
    let holds = differ.is_empty() && degree == stated_degree && smoothness == stated_smoothness;
    Ok((
        verdict(holds),
        format!("the rules are the box spline of {directions:?}: degree {stated_degree}, C^{stated_smoothness}"),
        format!(
            "{}; degree {degree}, C^{smoothness} ({} directions on {} lines, at most {most} on one)",
            if differ.is_empty() {
                "every weight is the box-spline mask's".to_string()
            } else {
                format!(
                    "{} weights differ from the mask: {}",
                    differ.len(),
                    differ.iter().take(3).cloned().collect::<Vec<_>>().join("; ")
                )
            },
            directions.len(),
            lines.len()
        ),
        window_evidence(data, &w, window.len())?,
    ))
}
