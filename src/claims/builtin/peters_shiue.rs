//! Peters–Shiue's 4-3 subdivision (`claims/peters-shiue.toml`), besides the
//! transition strip and the lattice windows: Lemma 3.4's projections, the
//! weights after two σ-blended steps and the convex hull (Lemma 3.8), the
//! node counts per step (section 2) and the ripple-free smoothing stencil
//! (Lemma 3.2).

use num_traits::Zero;

use crate::claims::builtin::data::{exact, field, int_in, ints_of, params, text, SmallestWeight};
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::neighbourhood::{build_patch, Configuration};
use crate::numeric::exact::q;
use crate::numeric::Rational;
use crate::refine::mesh::CompositeRows;
use crate::schemes;
use crate::spectrum::{analyse_shared, fmt_f, Options};

// ---------------------------------------------------------------- Peters–Shiue: M, E, C and the convex hull

/// Lemma 3.4 for n = 3..16: "E + C is a projection, (E + C)² = E + C, C² = C,
/// Ce = 0, eeᵗ = nE, eᵗe = n, Ee = e, EE = E; C is of rank 2 and E + C of
/// rank 3". The printed matrices come in `data.e` and `data.c` (expressions in
/// the row k = 0..n−1, the column l = 0..n−1 and n; `i` is the imaginary unit) and the printed ranks in `data.rank_c` and
/// `data.rank_e_plus_c`. Each identity is checked in floating point (largest
/// entry deviation at most 1e-12); a rank is the number of singular values
/// above 1e-9, and the evidence gives the gap around that threshold.
pub fn fourthree_lemma_3_4(data: &toml::Value) -> Result<Finding, Error> {
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
    Ok(Finding::new(
        holds,
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
pub fn fourthree_step_two(data: &toml::Value) -> Result<Finding, Error> {
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
pub fn fourthree_convex_hull(data: &toml::Value) -> Result<Finding, Error> {
    use crate::schemes::four_three::{classify, NodeType};
    use crate::spectrum::stencils::limit_stencil;
    let steps = int_in(data, "steps", 1, 4)? as usize;
    let (scheme, patch, fine, rows) = fourthree_patch(data, steps)?;
    // regular limit stencils: weights of the centre, its edge neighbours and (quads) its diagonal neighbours
    let regular = |faces: &str| -> Result<(f64, f64, f64), Error> {
        let config = Configuration::with_faces(scheme.as_ref(), faces.len(), faces)?;
        let a = analyse_shared(scheme.as_ref(), &config, &Options { exact: false, ..Options::default() })?;
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

/// Section 2: "in each subdivision step, the number of eons stays constant,
/// the number of boundary nodes and 4-3 transition nodes doubles and regular
/// nodes quadruple". Node types counted on a shipped closed mesh refined by
/// `subdlab refine`'s code, level by level.
pub fn fourthree_node_counts(data: &toml::Value) -> Result<Finding, Error> {
    use crate::schemes::four_three::{classify, NodeType};
    let (name, text_obj) = match text(data, "mesh")? {
        "house.obj" => ("house.obj", include_str!("../../../meshes/house.obj")),
        "prism.obj" => ("prism.obj", include_str!("../../../meshes/prism.obj")),
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
    Ok(Finding::new(
        bad.is_empty(),
        "eons constant, transition nodes ×2, regular nodes ×4 per step".into(),
        format!("{name}, eons/transition/regular {}", shown.join(", ")),
        if bad.is_empty() { "every step as stated".into() } else { bad.join("; ") },
    ))
}

// ---------------------------------------------------------------- 4-3: second pass over the statements

/// Lemma 3.8, after its proof: without rule (4a'), "the contribution of a node
/// w_i to a node v_0 after two subdivision steps is bounded below by −1/(64n)".
/// For every eon in `faces` (a list of face sequences): the smallest composite
/// weight of an old quad diagonal w_i ((1, 1) in a quad sector's chart) in a
/// new direct neighbour of the eon after the σ-blended steps 1 and 2, against
/// `bound`, an expression in n (the valence).
pub fn fourthree_step_two_bound(data: &toml::Value) -> Result<Finding, Error> {
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
    Ok(Finding::new(
        holds,
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
pub fn fourthree_ripple_free_unique(data: &toml::Value) -> Result<Finding, Error> {
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
    Ok(Finding::new(
        unique_as_stated,
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
