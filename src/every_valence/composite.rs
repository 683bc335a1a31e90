//! Composite schemes (S is several refinement steps, √3: two): where the
//! centre's valence enters their rows, and block 0 as a matrix of
//! polynomials in one variable.
//!
//! S = S_m ⋯ S_1, each S_k = L_k + e_c r_kᵀ: the centre's row r_k (the only
//! stencil that reads an n-dependent field, checked stencil by stencil by
//! `centre_only`) and the rows L_k of every other vertex, local rules that do
//! not depend on n. Every rotation maps each level's mesh to itself and fixes
//! the centre, so r_kᵀ S_{k−1} ⋯ S_1 is rotation invariant. An entry of S
//! away from the centre's row and column is a sum over paths through the
//! levels: those that avoid the centre at every intermediate level are
//! products of the L_k's entries (a Laurent polynomial in the sector offset,
//! the same at every large n); the others enter the centre at some level k
//! and continue along the rotation-invariant row above: the same number U_ab
//! in every sector τ of orbit b. So
//!
//!   S[(0,a),(τ,b)] = local_ab(τ) + U_ab(n),
//!
//! and in a block k ≠ 0 Σ_τ U_ab ω^{kτ} = 0: the blocks k ≠ 0 are those of
//! the local part alone, which `read_rows` reads with the n-dependent
//! fields set to 0 (they reach only U) and the remaining uniform part read
//! off the farthest sector.
//!
//! Block 0 of S is the product of the steps' blocks 0 (each level is
//! rotation symmetric about the centre): each step's is affine in the values
//! v_f of the n-dependent fields (they weigh single slots) and in n (only the
//! centre's totals count its n sectors), so every entry of block 0 of S is a
//! polynomial in (v, n) of degree ≤ m in each v_f and in n. `block0` reads
//! it off S itself: the entries at the integer points v ∈ {0..m}^F (the
//! probe substitutes them for the fields) interpolated in v, at the valences
//! n0..n0+m interpolated in n, checked at n0+m+1; then each v_f is replaced
//! by its expression in n (`centre::symbolic`).

use std::collections::BTreeSet;

use num_traits::Zero;

use crate::matrix::assemble_rows;
use crate::neighbourhood::Discovered;
use crate::numeric::{Cyclotomic, Rational, Weight};
use crate::schemes::user::probe::{self, FieldRead, Substitution};
use crate::sdc::stencil::Origin;
use crate::sdc::Scheme;

use super::centre::InN;

/// The vertex that continues the centre after each refinement of the
/// analysis step (index 0: level 0), through its `Origin::Vertex` chain.
fn centre_chain(d: &Discovered, centre: usize) -> Result<Vec<usize>, String> {
    let mut chain = vec![centre];
    for r in d.refinements() {
        let last = *chain.last().expect("non-empty");
        let next = r
            .vertex_origins
            .iter()
            .position(|o| *o == Origin::Vertex(last))
            .ok_or("the centre has no vertex replacing it after a refinement step (not vertex-centred)")?;
        chain.push(next);
    }
    Ok(chain)
}

/// Checks that, of the stencils the rows of `targets` (level-0 vertices
/// whose successors' rows are wanted) are composed of, only the centre's
/// own at each level read a field with variables at valence n; returns the
/// distinct fields they read.
pub fn centre_only(
    scheme: &dyn Scheme,
    d: &Discovered,
    targets: &[usize],
    centre: usize,
    n: usize,
) -> Result<Vec<FieldRead>, String> {
    let chain = centre_chain(d, centre)?;
    let levels = d.refinements().len();
    if d.successor(centre) != Some(chain[levels]) {
        return Err("the centre's successor over the analysis step is not the vertex replacing it".into());
    }
    let mut wanted: Vec<usize> = targets
        .iter()
        .map(|&v| d.successor(v).ok_or_else(|| "a row's vertex has no successor".to_string()))
        .collect::<Result<_, _>>()?;
    wanted.push(chain[levels]);
    let mut fields: Vec<FieldRead> = Vec::new();
    for k in (0..levels).rev() {
        let mut seen = BTreeSet::new();
        let mut below = Vec::new();
        for v in wanted {
            if !seen.insert(v) {
                continue;
            }
            let (st, reads) = probe::watch(n, || {
                crate::refine::new_stencil::<Cyclotomic>(scheme, d.mesh_before(k), &d.refinements()[k], v)
            });
            let st = match st {
                Ok(Ok(st)) => st,
                _ => return Err(format!("a stencil of refinement {} cannot be evaluated exactly", k + 1)),
            };
            for f in reads.at_valence.into_iter().filter(|f| f.varies) {
                if v != chain[k + 1] {
                    return Err(format!(
                        "a stencil other than the centre's reads [{}] {} at the centre's valence (refinement {}): \
                         the rows away from the centre may depend on n other than through cos(2πk/n)",
                        f.rule,
                        f.family,
                        k + 1
                    ));
                }
                if !fields.iter().any(|g| g.rule == f.rule && g.family == f.family) {
                    fields.push(f);
                }
            }
            below.extend(st.support());
        }
        wanted = below;
    }
    Ok(fields)
}

/// The substitution giving each field in `fields` the integer in `values`
/// (every other field its own value).
pub fn substitution(fields: &[FieldRead], values: &[i64]) -> Substitution {
    Substitution {
        fields: fields.iter().zip(values).map(|(f, v)| ((f.rule.to_string(), f.family.to_string()), *v)).collect(),
        others: None,
    }
}

/// Block 0 of S at one valence and one substitution, over the centre
/// (index 0) and the orbits away from it: entry [a][b] = Σ_τ S[(0,a),(τ,b)].
pub type Block0Values = Vec<Vec<Rational>>;

/// Block 0 in rationals (every weight of a substituted S is rational when
/// the fields that are not substituted are constants).
pub fn rational_block(m: &[Vec<Cyclotomic>], n: usize) -> Result<Block0Values, String> {
    m.iter()
        .map(|row| {
            row.iter()
                .map(|w| w.to_rational().ok_or_else(|| format!("valence {n}: a weight of S is irrational")))
                .collect()
        })
        .collect()
}

/// The integer points {0..m}^F of the interpolation grid, first field
/// slowest.
pub fn grid(m: usize, f: usize) -> Vec<Vec<i64>> {
    let mut out = vec![vec![]];
    for _ in 0..f {
        out = out.into_iter().flat_map(|p| (0..=m as i64).map(move |x| [p.clone(), vec![x]].concat())).collect();
    }
    out
}

/// Coefficients (lowest power first) of the Lagrange basis polynomial of
/// node `g` on the nodes 0..=m.
fn lagrange_basis(g: usize, m: usize) -> Vec<Rational> {
    let mut p = vec![Rational::from_integer(1.into())];
    for h in (0..=m).filter(|&h| h != g) {
        let scale = Rational::new(1.into(), (g as i64 - h as i64).into());
        // p ← p · (v − h) / (g − h)
        let mut next = vec![Rational::from_integer(0.into()); p.len() + 1];
        for (i, c) in p.iter().enumerate() {
            next[i + 1] = &next[i + 1] + c * &scale;
            next[i] = &next[i] - c * &scale * Rational::from_integer((h as i64).into());
        }
        p = next;
    }
    p
}

/// The coefficients of a polynomial of degree ≤ m in each of F variables
/// from its values on `grid(m, F)`: monomial (exponents in grid order) ↦
/// coefficient.
pub fn interpolate_grid(values: &[Rational], m: usize, f: usize) -> Vec<(Vec<i64>, Rational)> {
    let basis: Vec<Vec<Rational>> = (0..=m).map(|g| lagrange_basis(g, m)).collect();
    let points = grid(m, f);
    points
        .iter()
        .map(|alpha| {
            let c = points.iter().zip(values).fold(Rational::from_integer(0.into()), |s, (g, y)| {
                let w = g
                    .iter()
                    .zip(alpha)
                    .fold(Rational::from_integer(1.into()), |p, (gi, ai)| p * &basis[*gi as usize][*ai as usize]);
                s + y * w
            });
            (alpha.clone(), c)
        })
        .collect()
}

/// The polynomial of degree ≤ len − 1 through (xs[i], ys[i]) (coefficients
/// lowest first), by Lagrange's formula.
pub fn interpolate_1d(xs: &[Rational], ys: &[Rational]) -> Vec<Rational> {
    let mut out = vec![Rational::from_integer(0.into()); xs.len()];
    for (i, (xi, yi)) in xs.iter().zip(ys).enumerate() {
        let mut p = vec![Rational::from_integer(1.into())];
        for (_, xj) in xs.iter().enumerate().filter(|&(j, _)| j != i) {
            let scale = (xi - xj).recip();
            let mut next = vec![Rational::from_integer(0.into()); p.len() + 1];
            for (k, c) in p.iter().enumerate() {
                next[k + 1] = &next[k + 1] + c * &scale;
                next[k] = &next[k] - c * &scale * xj;
            }
            p = next;
        }
        for (k, c) in p.iter().enumerate() {
            out[k] = &out[k] + c * yi;
        }
    }
    out
}

/// Block 0 of S from its values: `at[i][g]` is block 0 at valence
/// `valences[i]` and grid point g of `grid(m, F)`; the first m + 1 valences
/// fit each monomial's coefficient as a polynomial in n, the last checks
/// the fit. Each entry as an expression in n: Σ C_{α,e} n^e Π w_f^{α_f}.
pub fn block0_symbolic(
    valences: &[usize],
    at: &[Vec<Block0Values>],
    m: usize,
    symbols: &[InN],
) -> Result<Vec<Vec<InN>>, String> {
    let f = symbols.len();
    let size = at[0][0].len();
    let xs: Vec<Rational> = valences[..=m].iter().map(|&n| Rational::from_integer((n as i64).into())).collect();
    let mut out = vec![vec![InN::default(); size]; size];
    for a in 0..size {
        for b in 0..size {
            // monomial α ↦ its coefficient at each valence
            let per_valence: Vec<Vec<(Vec<i64>, Rational)>> = at
                .iter()
                .map(|grid_values| {
                    let ys: Vec<Rational> = grid_values.iter().map(|m0| m0[a][b].clone()).collect();
                    interpolate_grid(&ys, m, f)
                })
                .collect();
            for (idx, (alpha, _)) in per_valence[0].iter().enumerate() {
                let ys: Vec<Rational> = per_valence[..=m].iter().map(|p| p[idx].1.clone()).collect();
                let in_n = interpolate_1d(&xs, &ys);
                // the check at the last valence
                let last = Rational::from_integer((*valences.last().expect("valences") as i64).into());
                let predicted = in_n.iter().rev().fold(Rational::from_integer(0.into()), |acc, c| acc * &last + c);
                if predicted != per_valence.last().expect("valences")[idx].1 {
                    return Err(format!(
                        "block 0's entries are not polynomials of degree ≤ {m} in n (checked at n = {})",
                        valences.last().expect("valences")
                    ));
                }
                let mut monomial = InN::constant(Rational::from_integer(1.into()));
                for (sym, e) in symbols.iter().zip(alpha) {
                    for _ in 0..*e {
                        monomial = monomial.mul(sym);
                    }
                }
                for (e, c) in in_n.iter().enumerate() {
                    if Zero::is_zero(c) {
                        continue;
                    }
                    let term = InN::term(c.clone(), (e as i32, 0, 0)).mul(&monomial);
                    out[a][b] = out[a][b].add(&term, 1);
                }
            }
        }
    }
    Ok(out)
}

/// Block 0 at one valence under one substitution: the rows of the centre
/// (matrix index `centre`) and of the representatives `reps`, summed per
/// orbit (`orbit_of`: column ↦ (orbit, sector); `free`: the orbits away from
/// the centre in block order).
#[allow(clippy::too_many_arguments)]
pub fn block0_values(
    scheme: &dyn Scheme,
    d: &Discovered,
    kind: crate::neighbourhood::NeighbourhoodKind,
    centre: usize,
    reps: &[usize],
    orbit_of: &[(usize, usize)],
    free: &[usize],
    n: usize,
    values: Option<Substitution>,
) -> Result<Vec<Vec<Cyclotomic>>, String> {
    let which: Vec<usize> = std::iter::once(centre).chain(reps.iter().copied()).collect();
    let assemble = || assemble_rows::<Cyclotomic>(scheme, d, kind, &which);
    let rows = match values {
        Some(v) => probe::watch_substituted(n, v, assemble).0,
        None => assemble(),
    };
    let rows = rows.map_err(|_| format!("valence {n}: no exact rows of S"))?;
    let size = which.len();
    let mut out = vec![vec![Cyclotomic::zero(); size]; size];
    for (a, row) in rows.iter().enumerate() {
        for (col, w) in row {
            let b = if *col == centre {
                0
            } else {
                1 + free.iter().position(|&o| o == orbit_of[*col].0).ok_or("a column outside the orbits")?
            };
            out[a][b] = out[a][b].clone() + w.clone();
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::new(p.into(), d.into())
    }

    #[test]
    fn grid_interpolation_recovers_a_polynomial() {
        // p(u, v) = 3 − u v + 2 u² v², degree ≤ 2 in each
        let p = |u: i64, v: i64| q(3 - u * v + 2 * u * u * v * v, 1);
        let values: Vec<Rational> = grid(2, 2).iter().map(|g| p(g[0], g[1])).collect();
        let coeffs = interpolate_grid(&values, 2, 2);
        for (alpha, c) in coeffs {
            let expected = match (alpha[0], alpha[1]) {
                (0, 0) => q(3, 1),
                (1, 1) => q(-1, 1),
                (2, 2) => q(2, 1),
                _ => q(0, 1),
            };
            assert_eq!(c, expected, "{alpha:?}");
        }
        // 1D: 1 + n² through n = 24, 25, 26
        let xs: Vec<Rational> = [24, 25, 26].iter().map(|&x| q(x, 1)).collect();
        let ys: Vec<Rational> = [24i64, 25, 26].iter().map(|&x| q(1 + x * x, 1)).collect();
        assert_eq!(interpolate_1d(&xs, &ys), vec![q(1, 1), q(0, 1), q(1, 1)]);
    }
}
