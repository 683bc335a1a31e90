//! Lemma C9 of ARCHITECTURE.md: derivative and position bounds of a limit
//! patch from contraction of the scheme's difference scheme, for regular
//! parts that are no box spline (√3 subdivision, user schemes on triangles).
//!
//! **Setting.** The regular part is the scheme's own rule on the regular
//! triangular lattice Z² (lattice coordinates: e1 = (1, 0), e2 = (0, 1),
//! third direction e2 − e1), read from the scheme on a regular torus
//! (`regular_mask`): after the host's refinements of one analysis step
//! (`steps`) every new point sits on (Z/D)² (D = 2 for the dyadic split,
//! 3 for two √3 steps) and is Σ a(y, x)·p_x over level-0 points x. Each
//! lattice triangle T (up: (0,0), (1,0), (0,1); down: (1,0), (1,1), (0,1))
//! is the union of D² triangles of the next level, its children.
//!
//! **Windows.** W_T, the smallest set of lattice points holding T's corners
//! such that every point of every child's window (scaled by 1/D) is
//! computed by the mask from points of W_T alone (a fixed point, `windows`).
//! The data on W_T therefore determine the data on the windows of all
//! descendants of T, through fixed matrices S_c (one per child c).
//!
//! **Seminorm.** N(p) = max over a basis of second differences of W_T (rows
//! that vanish on affine data, `|W_T| − 3` of them, chosen greedily among
//! p(x − e) − 2p(x) + p(x + e) and p(x) − p(x + e) − p(x + f) + p(x + e + f))
//! of their Euclidean length. A linear functional on W_T that vanishes on
//! affine data is κ·(second differences) for unique κ, so it is bounded by
//! ‖κ‖₁·N(p). The mask must reproduce affine data (checked exactly: every
//! functional below is then such a functional), so the second differences of
//! a child's window are M_c times T's: N(S_c p) ≤ ‖M_c‖∞·N(p).
//!
//! **Bounds.** L_k, the piecewise-linear interpolant of the level-k data,
//! converges to the limit f, and its gradient on a level-k triangle is
//! D^k times the triangle's own edge vectors (level-0 parameter units).
//! Along a chain T = T₀ ⊃ T₁ ⊃ … of triangles holding x:
//! - D·edge_e(T_{k+1}) − edge_e(T_k) and L_{k+1} − L_k at T_{k+1}'s corners
//!   are functionals of W_{T_k} vanishing on affine data, bounded by
//!   K_edge·N(p_k) and K_pos·N(p_k);
//! - N(p_k) ≤ ‖M_w‖∞·N(p₀) for the word w of children along the chain;
//!   with P_j = max over words of length j of D^j·‖M_w‖∞ and q = P_L < 1,
//!   Σ_j P_j ≤ (Σ_{j<L} P_j)/(1 − q), and likewise Q_j = P_j/D^j.
//!
//! So for every x ∈ T: |∂_e f(x) − edge_e(T)| ≤ ε = K_edge·ΣP·N(p), and
//! f(x) lies within δ = K_pos·ΣQ·N(p) of T's own linear interpolant — hence
//! in T's control triangle enlarged by δ + 2ε (f(x) − L₀(x) ≤ δ, and L₀
//! is T's own triangle). The Jacobian det(∂₁f, ∂₂f) over T lies within
//! ε(|u| + |v|) + ε² of det(u, v), u and v T's own edges. The uniform
//! convergence of the difference quotients (the chain's sums) also proves
//! the regular part C¹ with these derivatives.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::sync::{Arc, Mutex, OnceLock};

use num_traits::{One, Signed, Zero};

use crate::mesh::PolyMesh;
use crate::numeric::exact::{inverse, pivot_columns, rank_of};
use crate::numeric::{Interval, Rational};
use crate::refine::{connectivity, stencil_at, Origin};
use crate::sdc::Scheme;

/// A lattice position (level-0 units, or 1/D units where said).
pub type Lattice = (i64, i64);

/// Corners (counter-clockwise) of the up and the down triangle at the origin.
pub const CORNERS: [[Lattice; 3]; 2] = [[(0, 0), (1, 0), (0, 1)], [(1, 0), (1, 1), (0, 1)]];
/// Each type's own edges along e1 and along e2, as (from, to).
pub const OWN_EDGES: [[(Lattice, Lattice); 2]; 2] =
    [[((0, 0), (1, 0)), ((0, 0), (0, 1))], [((0, 1), (1, 1)), ((1, 0), (1, 1))]];
/// The regular torus the mask is read from: m × m vertices.
const TORUS: i64 = 12;
/// Windows larger than this are refused: the word products (9³ of them for
/// the ternary split) grow with the window's cube; Kobbelt √3's is 27 points.
const MAX_WINDOW: usize = 64;
/// Levels by which an undecided ring face is refined on its own window
/// (the bounds shrink by about D per level on smooth data).
pub const DEPTH: usize = 3;
/// Longest words of children whose norms are bounded (the cost grows by D²
/// per letter).
const MAX_WORD: usize = 3;

/// The regular rule of one analysis step: per class c = D·y mod D of a new
/// point y, the weights on the level-0 points x as offsets D·x − y (1/D
/// units).
#[derive(Clone, Debug, PartialEq)]
pub struct RegularMask {
    pub dilation: i64,
    pub steps: usize,
    pub classes: BTreeMap<Lattice, Vec<(Lattice, Rational)>>,
}

impl RegularMask {
    /// The weights of the new point at `y` (1/D units) on level-0 points.
    pub fn weights(&self, y: Lattice) -> Vec<(Lattice, Rational)> {
        let d = self.dilation;
        let class = (y.0.rem_euclid(d), y.1.rem_euclid(d));
        self.classes
            .get(&class)
            .map(|list| list.iter().map(|((a, b), w)| (((y.0 + a) / d, (y.1 + b) / d), w.clone())).collect())
            .unwrap_or_default()
    }
}

/// What the lattice computation proves once per scheme: the windows, the
/// second-difference bases and the constants of the bounds.
#[derive(Clone, Debug)]
pub struct LatticeBound {
    pub mask: RegularMask,
    /// W_up and W_down
    pub windows: [Vec<Lattice>; 2],
    /// the basis of second differences per type: integer combinations of
    /// window points
    pub basis: [Vec<Vec<(Lattice, i64)>>; 2],
    /// words of length `word` bound the contraction
    pub word: usize,
    /// per type, per child (in `children` order): the child's type and S_c,
    /// the child window's values from the parent window's (exact weights as
    /// point intervals)
    pub refine: [Vec<(usize, Vec<Vec<(usize, Interval)>>)>; 2],
    /// P_j (j = 0..=word), upper bounds
    pub word_norms: Vec<f64>,
    pub k_edge: f64,
    pub k_pos: f64,
    /// ε ≤ edge_constant·N(p)
    pub edge_constant: f64,
    /// δ ≤ position_constant·N(p)
    pub position_constant: f64,
}

/// The regular rule of one analysis step, read off the scheme on a regular
/// triangulated torus (every vertex of valence 6).
pub fn regular_mask(scheme: &dyn Scheme) -> Result<RegularMask, String> {
    let topology = scheme.topology();
    let steps = topology.steps_per_analysis();
    let per_step = topology.faces_per_face().pow(steps as u32) as i64;
    let d = (2..=per_step).find(|d| d * d == per_step).ok_or("the host's refinement is not a lattice dilation")?;
    let m = TORUS;
    let period = m * d;
    let id = |i: i64, j: i64| (i.rem_euclid(m) * m + j.rem_euclid(m)) as usize;
    let mut faces = Vec::new();
    for i in 0..m {
        for j in 0..m {
            faces.push(vec![id(i, j), id(i + 1, j), id(i, j + 1)]);
            faces.push(vec![id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    let mut mesh =
        PolyMesh::new((m * m) as usize, faces).map_err(|e| format!("the regular torus is not a mesh: {e}"))?;
    let wrap = |t: i64| (t + period / 2).rem_euclid(period) - period / 2;
    let level0: Vec<Lattice> = (0..m * m).map(|v| ((v / m) * d, (v % m) * d)).collect();
    let mut pos = level0.clone();
    let mut stencils: Vec<HashMap<usize, Rational>> =
        (0..level0.len()).map(|v| HashMap::from([(v, Rational::one())])).collect();
    for _ in 0..steps {
        let refined =
            connectivity(scheme, &mesh).map_err(|e| format!("the regular torus could not be refined: {e}"))?;
        let mut new_pos = Vec::with_capacity(refined.vertex_origins.len());
        let mut new_stencils = Vec::with_capacity(refined.vertex_origins.len());
        for &origin in &refined.vertex_origins {
            let around: Vec<Lattice> = match origin {
                Origin::Vertex(v) => vec![pos[v]],
                Origin::Edge(a, b) => vec![pos[a], pos[b]],
                Origin::Face(g) => mesh.face(g).iter().map(|&v| pos[v]).collect(),
                Origin::Corner { .. } => return Err("a dual host has no primal lattice of new points".into()),
            };
            // the centroid, unwrapped around the first point
            let first = around[0];
            let sum = around.iter().fold((0, 0), |s, p| (s.0 + wrap(p.0 - first.0), s.1 + wrap(p.1 - first.1)));
            let k = around.len() as i64;
            if sum.0 % k != 0 || sum.1 % k != 0 {
                return Err("a new point does not sit on the refined lattice".into());
            }
            new_pos.push(((first.0 + sum.0 / k).rem_euclid(period), (first.1 + sum.1 / k).rem_euclid(period)));
            let stencil = stencil_at::<Rational>(scheme, &mesh, origin)
                .map_err(|_| "a regular rule has an irrational weight".to_string())?
                .map_err(|cause| format!("a regular rule cannot be evaluated on the regular torus: {cause}"))?;
            let mut composed: HashMap<usize, Rational> = HashMap::new();
            for (v, w) in &stencil.terms {
                for (x, wx) in &stencils[*v] {
                    *composed.entry(*x).or_insert_with(Rational::zero) += w * wx;
                }
            }
            composed.retain(|_, w| !w.is_zero());
            new_stencils.push(composed);
        }
        mesh = refined.mesh;
        pos = new_pos;
        stencils = new_stencils;
    }
    let distinct: HashSet<Lattice> = pos.iter().copied().collect();
    if distinct.len() != pos.len() || pos.len() as i64 != period * period {
        return Err("the refined torus's points are not the refined lattice".into());
    }
    let mut classes: BTreeMap<Lattice, Vec<(Lattice, Rational)>> = BTreeMap::new();
    for (y, stencil) in pos.iter().zip(&stencils) {
        let mut list: Vec<(Lattice, Rational)> =
            stencil.iter().map(|(x, w)| ((wrap(level0[*x].0 - y.0), wrap(level0[*x].1 - y.1)), w.clone())).collect();
        list.sort_by(|a, b| a.0.cmp(&b.0));
        if list.iter().any(|((a, b), _)| a.abs() > period / 3 || b.abs() > period / 3) {
            return Err("the regular rule's support is too wide for the torus".into());
        }
        let class = (y.0.rem_euclid(d), y.1.rem_euclid(d));
        match classes.get(&class) {
            Some(seen) if *seen != list => {
                return Err("the rules on the regular lattice are not translation invariant".into());
            }
            Some(_) => {}
            None => {
                classes.insert(class, list);
            }
        }
    }
    let mask = RegularMask { dilation: d, steps, classes };
    check_rotation_symmetry(&mask)?;
    Ok(mask)
}

/// The regular rule commutes with the lattice's rotation by 60° (in lattice
/// coordinates (x, y) ↦ (−y, x + y)): then a stencil that equals the mask in
/// one ring face's chart equals it in every chart (charts differ by lattice
/// rotations and translations), and each new vertex is compared once.
fn check_rotation_symmetry(mask: &RegularMask) -> Result<(), String> {
    let d = mask.dilation;
    let rotate = |(x, y): Lattice| (-y, x + y);
    for (class, list) in &mask.classes {
        let y = *class;
        let turned: HashMap<Lattice, Rational> = mask.weights(rotate(y)).into_iter().collect();
        if turned.len() != list.len() {
            return Err("the regular rule is not symmetric under the lattice's rotations".into());
        }
        for ((a, b), w) in list {
            let x = ((y.0 + a) / d, (y.1 + b) / d);
            if turned.get(&rotate(x)) != Some(w) {
                return Err("the regular rule is not symmetric under the lattice's rotations".into());
            }
        }
    }
    Ok(())
}

/// The children of the triangle of type `t` at the origin: (offset in 1/D
/// units, type), D² of them.
pub fn children(t: usize, d: i64) -> Vec<(Lattice, usize)> {
    let inside = |(x, y): Lattice| {
        if t == 0 {
            x >= 0 && y >= 0 && x + y <= d
        } else {
            x <= d && y <= d && x + y >= d
        }
    };
    let mut out = Vec::new();
    for ox in -1..=d {
        for oy in -1..=d {
            for (t2, corners) in CORNERS.iter().enumerate() {
                if corners.iter().all(|c| inside((ox + c.0, oy + c.1))) {
                    out.push(((ox, oy), t2));
                }
            }
        }
    }
    out
}

/// W_up and W_down: the smallest sets holding the corners and closed under
/// "a child's window point is computed from the parent's window".
pub fn windows(mask: &RegularMask) -> Result<[Vec<Lattice>; 2], String> {
    let d = mask.dilation;
    let mut w: [HashSet<Lattice>; 2] = [CORNERS[0].iter().copied().collect(), CORNERS[1].iter().copied().collect()];
    let kids = [children(0, d), children(1, d)];
    loop {
        let mut grown = false;
        for t in 0..2 {
            for &(o, t2) in &kids[t] {
                let child: Vec<Lattice> = w[t2].iter().copied().collect();
                for c in child {
                    for (x, _) in mask.weights((o.0 + c.0, o.1 + c.1)) {
                        grown |= w[t].insert(x);
                    }
                }
            }
            if w[t].len() > MAX_WINDOW {
                return Err(format!("the regular rule's windows exceed {MAX_WINDOW} points"));
            }
        }
        if !grown {
            break;
        }
    }
    let sorted = |s: &HashSet<Lattice>| {
        let mut v: Vec<Lattice> = s.iter().copied().collect();
        v.sort_unstable();
        v
    };
    Ok([sorted(&w[0]), sorted(&w[1])])
}

/// A basis of the second differences on a window: collinear ones first (in
/// the three lattice directions), then mixed ones, kept when independent of
/// those before.
fn second_difference_basis(window: &[Lattice]) -> Result<Vec<Vec<(Lattice, i64)>>, String> {
    let set: HashSet<Lattice> = window.iter().copied().collect();
    let dirs: [Lattice; 3] = [(1, 0), (0, 1), (-1, 1)];
    let add = |a: Lattice, b: Lattice| (a.0 + b.0, a.1 + b.1);
    let mut candidates: Vec<Vec<(Lattice, i64)>> = Vec::new();
    for e in dirs {
        for &x in window {
            let (before, after) = ((x.0 - e.0, x.1 - e.1), add(x, e));
            if set.contains(&before) && set.contains(&after) {
                candidates.push(vec![(before, 1), (x, -2), (after, 1)]);
            }
        }
    }
    for (e, f) in [(dirs[0], dirs[1]), (dirs[0], dirs[2]), (dirs[1], dirs[2])] {
        for &x in window {
            let pts = [x, add(x, e), add(x, f), add(add(x, e), f)];
            if pts.iter().all(|p| set.contains(p)) {
                candidates.push(vec![(pts[0], 1), (pts[1], -1), (pts[2], -1), (pts[3], 1)]);
            }
        }
    }
    let index: HashMap<Lattice, usize> = window.iter().enumerate().map(|(i, &p)| (p, i)).collect();
    let n = window.len();
    let dense = |row: &[(Lattice, i64)]| {
        let mut v = vec![Rational::zero(); n];
        for (p, c) in row {
            v[index[p]] += Rational::from_integer((*c).into());
        }
        v
    };
    // greedy: keep a candidate when it raises the rank of those kept
    let mut chosen: Vec<Vec<(Lattice, i64)>> = Vec::new();
    let mut kept: Vec<Rational> = Vec::new();
    for row in candidates {
        let before = kept.len();
        kept.extend(dense(&row));
        if rank_of(chosen.len() + 1, n, kept.clone()) > chosen.len() {
            chosen.push(row);
        } else {
            kept.truncate(before);
        }
        if chosen.len() + 3 == n {
            break;
        }
    }
    if chosen.len() + 3 != n {
        return Err("a window's second differences do not determine its data up to an affine function".into());
    }
    Ok(chosen)
}

/// Coordinates in the basis of second differences of a window: κ with
/// κᵀR = g for a functional g that vanishes on affine data.
struct Coordinates {
    rows: Vec<Vec<Rational>>,
    pivots: Vec<usize>,
    /// the inverse of (R restricted to the pivot columns)ᵀ
    inverse: Vec<Rational>,
}

impl Coordinates {
    fn new(rows: Vec<Vec<Rational>>) -> Result<Coordinates, String> {
        let (k, n) = (rows.len(), rows.first().map_or(0, Vec::len));
        let flat: Vec<Rational> = rows.iter().flatten().cloned().collect();
        let pivots = pivot_columns(k, n, flat);
        if pivots.len() != k {
            return Err("the second differences are not independent".into());
        }
        let mut transposed = vec![Rational::zero(); k * k];
        for (i, row) in rows.iter().enumerate() {
            for (j, &c) in pivots.iter().enumerate() {
                transposed[j * k + i] = row[c].clone();
            }
        }
        let inverse = inverse(k, &transposed).ok_or("the second differences are not independent")?;
        Ok(Coordinates { rows, pivots, inverse })
    }

    /// κ for g, checked on every column (which fails exactly when g does not
    /// vanish on affine data).
    fn of(&self, g: &[Rational]) -> Result<Vec<Rational>, String> {
        let k = self.rows.len();
        let kappa: Vec<Rational> = (0..k)
            .map(|i| (0..k).fold(Rational::zero(), |s, j| s + &self.inverse[i * k + j] * &g[self.pivots[j]]))
            .collect();
        for (c, target) in g.iter().enumerate() {
            let got = (0..k).fold(Rational::zero(), |s, i| s + &kappa[i] * &self.rows[i][c]);
            if got != *target {
                return Err("the regular rule does not reproduce affine data in lattice coordinates".into());
            }
        }
        Ok(kappa)
    }
}

fn l1_upper(v: &[Rational]) -> f64 {
    v.iter().fold(Interval::point(0.0), |s, x| s + Interval::rational(&x.abs())).hi
}

/// The lattice half of lemma C9 for a scheme: cached by its regular mask
/// (the same rules give the same constants at every valence).
pub fn lattice_bound(scheme: &dyn Scheme) -> Result<Arc<LatticeBound>, String> {
    static CACHE: OnceLock<Mutex<Vec<(RegularMask, Result<Arc<LatticeBound>, String>)>>> = OnceLock::new();
    let mask = regular_mask(scheme)?;
    let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
    if let Some((_, found)) =
        cache.lock().map_err(|_| "the lattice cache is poisoned")?.iter().find(|(m, _)| *m == mask)
    {
        return found.clone();
    }
    let computed = compute_bound(mask.clone()).map(Arc::new);
    cache.lock().map_err(|_| "the lattice cache is poisoned")?.push((mask, computed.clone()));
    computed
}

fn compute_bound(mask: RegularMask) -> Result<LatticeBound, String> {
    let d = mask.dilation;
    let windows = windows(&mask)?;
    let basis = [second_difference_basis(&windows[0])?, second_difference_basis(&windows[1])?];
    let index: [HashMap<Lattice, usize>; 2] =
        [0, 1].map(|t| windows[t].iter().enumerate().map(|(i, &p)| (p, i)).collect());
    let dense_rows = |t: usize| -> Vec<Vec<Rational>> {
        basis[t]
            .iter()
            .map(|row| {
                let mut v = vec![Rational::zero(); windows[t].len()];
                for (p, c) in row {
                    v[index[t][p]] += Rational::from_integer((*c).into());
                }
                v
            })
            .collect()
    };
    let coordinates = [Coordinates::new(dense_rows(0))?, Coordinates::new(dense_rows(1))?];
    let (mut k_edge, mut k_pos) = (0.0f64, 0.0f64);
    // per (parent type, child): M_c as an interval matrix, and the child's type
    let mut steps: [Vec<(usize, Vec<Vec<Interval>>)>; 2] = [Vec::new(), Vec::new()];
    let mut refine: [Vec<(usize, Vec<Vec<(usize, Interval)>>)>; 2] = [Vec::new(), Vec::new()];
    for t in 0..2 {
        let n = windows[t].len();
        for (o, t2) in children(t, d) {
            // S_c: the child's window points over the parent's window
            let s: Vec<Vec<Rational>> = windows[t2]
                .iter()
                .map(|c| {
                    let mut row = vec![Rational::zero(); n];
                    for (x, w) in mask.weights((o.0 + c.0, o.1 + c.1)) {
                        match index[t].get(&x) {
                            Some(&i) => row[i] += w,
                            None => return Err("a child's window reaches outside its parent's".to_string()),
                        }
                    }
                    Ok(row)
                })
                .collect::<Result<_, String>>()?;
            let sparse = |row: &Vec<Rational>| {
                row.iter().enumerate().filter(|(_, w)| !w.is_zero()).map(|(i, w)| (i, Interval::rational(w))).collect()
            };
            refine[t].push((t2, s.iter().map(sparse).collect()));
            let row_of = |p: &Lattice| &s[index[t2][p]];
            let combine = |terms: &[(Lattice, i64)]| -> Vec<Rational> {
                let mut g = vec![Rational::zero(); n];
                for (p, c) in terms {
                    let c = Rational::from_integer((*c).into());
                    for (j, v) in row_of(p).iter().enumerate() {
                        g[j] += &c * v;
                    }
                }
                g
            };
            let mut m = Vec::new();
            for row in &basis[t2] {
                let kappa = coordinates[t].of(&combine(row))?;
                m.push(kappa.iter().map(Interval::rational).collect());
            }
            steps[t].push((t2, m));
            // D·(child's own edge) − (parent's own edge), along e1 and e2
            for e in 0..2 {
                let (ca, cb) = OWN_EDGES[t2][e];
                let (pa, pb) = OWN_EDGES[t][e];
                let mut g = combine(&[(cb, d), (ca, -d)]);
                g[index[t][&pb]] -= Rational::one();
                g[index[t][&pa]] += Rational::one();
                k_edge = k_edge.max(l1_upper(&coordinates[t].of(&g)?));
            }
            // the child's corners minus the parent's linear interpolant there
            for c in CORNERS[t2] {
                let y = (o.0 + c.0, o.1 + c.1);
                let mut g = combine(&[(c, 1)]);
                for (corner, weight) in barycentric(t, y, d) {
                    g[index[t][&corner]] -= weight;
                }
                k_pos = k_pos.max(l1_upper(&coordinates[t].of(&g)?));
            }
        }
    }
    // P_j = max over words of length j of D^j·‖M_w‖∞, by depth-first products
    let mut word_norms = vec![1.0f64];
    let mut frontier: Vec<(usize, Option<Vec<Vec<Interval>>>)> = vec![(0, None), (1, None)];
    let mut chosen = None;
    for j in 1..=MAX_WORD {
        let mut next = Vec::new();
        let mut worst = 0.0f64;
        for (t, product) in &frontier {
            for (t2, m) in &steps[*t] {
                let p = match product {
                    None => m.clone(),
                    Some(p) => multiply(m, p),
                };
                worst = worst.max(norm_upper(&p));
                next.push((*t2, Some(p)));
            }
        }
        let scaled = (Interval::point(worst) * Interval::point((d as f64).powi(j as i32))).hi;
        word_norms.push(scaled);
        if scaled < 1.0 {
            chosen = Some(j);
            break;
        }
        frontier = next;
    }
    let word = chosen.ok_or_else(|| {
        format!(
            "the difference scheme is not proved contractive: words of up to {MAX_WORD} children scale the second \
             differences by D^j·‖M_w‖∞ = {:.3} ≥ 1",
            word_norms.last().copied().unwrap_or(f64::NAN)
        )
    })?;
    let q = Interval::point(word_norms[word]);
    let one = Interval::point(1.0);
    let dj = |j: usize| Interval::point((d as f64).powi(j as i32));
    let sum_p = word_norms[..word].iter().fold(Interval::point(0.0), |s, &p| s + Interval::point(p)) / (one - q);
    let q_unscaled = q / dj(word);
    let sum_q =
        (0..word).fold(Interval::point(0.0), |s, j| s + Interval::point(word_norms[j]) / dj(j)) / (one - q_unscaled);
    let edge_constant = (Interval::point(k_edge) * sum_p).hi;
    let position_constant = (Interval::point(k_pos) * sum_q).hi;
    Ok(LatticeBound { mask, windows, basis, refine, word, word_norms, k_edge, k_pos, edge_constant, position_constant })
}

/// Barycentric weights of the point `y` (1/D units) in the triangle of
/// type `t` at the origin, over its corners.
fn barycentric(t: usize, y: Lattice, d: i64) -> Vec<(Lattice, Rational)> {
    let r = |p: i64| Rational::new(p.into(), d.into());
    let (x, z) = (r(y.0), r(y.1));
    if t == 0 {
        vec![((0, 0), Rational::one() - &x - &z), ((1, 0), x), ((0, 1), z)]
    } else {
        // y = a(1,0) + b(1,1) + c(0,1), a + b + c = 1
        let b = &x + &z - Rational::one();
        vec![((1, 0), &x - &b), ((0, 1), &z - &b), ((1, 1), b)]
    }
}

fn multiply(a: &[Vec<Interval>], b: &[Vec<Interval>]) -> Vec<Vec<Interval>> {
    let cols = b.first().map_or(0, Vec::len);
    a.iter()
        .map(|row| {
            (0..cols).map(|j| row.iter().zip(b).fold(Interval::point(0.0), |s, (x, brow)| s + *x * brow[j])).collect()
        })
        .collect()
}

fn norm_upper(m: &[Vec<Interval>]) -> f64 {
    m.iter()
        .map(|row| row.iter().fold(Interval::point(0.0), |s, x| s + Interval::point(x.mag())).hi)
        .fold(0.0, f64::max)
}

/// A ring face's window laid out on the lattice: the net vertex at each
/// point of W_up (in `LatticeBound::windows[0]` order), the face's corners
/// at (0,0), (1,0), (0,1) in face order.
#[derive(Clone, Debug)]
pub struct RingWindow {
    pub face: usize,
    pub vertices: Vec<usize>,
}

/// Why a ring's windows are not available at this level.
pub enum RingFailure {
    /// a deeper level may do (a window leaves the net or meets the centre)
    Level(String),
    /// no level will (a rule differs from the regular one)
    Final(String),
}

/// The windows of the ring faces, each checked to lie on a regular piece of
/// the net (every window vertex and its neighbours of valence 6), with the
/// rules of the next analysis step compared exactly with the regular mask at
/// every point of every child's window. Returns the windows and the number
/// of stencils compared.
pub fn ring_windows(
    scheme: &dyn Scheme,
    bound: &LatticeBound,
    mesh: &PolyMesh,
    ring: &[usize],
) -> Result<(Vec<RingWindow>, usize), RingFailure> {
    let vf = mesh.vertex_faces();
    let window = &bound.windows[0];
    let mut out = Vec::with_capacity(ring.len());
    let mut charts = Vec::with_capacity(ring.len());
    for &f in ring {
        let chart = chart_around(mesh, &vf, f, window).map_err(RingFailure::Level)?;
        let vertices: Vec<usize> = window.iter().map(|p| chart.at[p]).collect();
        out.push(RingWindow { face: f, vertices });
        charts.push(chart);
    }
    let checked = check_rules(scheme, bound, mesh, &charts)?;
    Ok((out, checked))
}

struct Chart {
    /// lattice position → net vertex
    at: HashMap<Lattice, usize>,
    /// net vertex → lattice position
    of: HashMap<usize, Lattice>,
}

/// Lay out the net around face `f` on the lattice, far enough to hold
/// `needed` and a margin of one: across each edge (a, b) of a placed face
/// (a, b, c) the other face's third vertex sits at a + b − c.
fn chart_around(mesh: &PolyMesh, vf: &[Vec<usize>], f: usize, needed: &[Lattice]) -> Result<Chart, String> {
    let face = mesh.face(f);
    if face.len() != 3 {
        return Err("a ring face is not a triangle".into());
    }
    // the window and its lattice neighbours: enough to reach every window
    // point, and no further (a wider chart could wrap around the centre)
    let region: HashSet<Lattice> = needed
        .iter()
        .flat_map(|&(x, y)| [(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1), (-1, 1), (1, -1)].map(|(a, b)| (x + a, y + b)))
        .collect();
    let within = |p: Lattice| region.contains(&p);
    let mut of: HashMap<usize, Lattice> = HashMap::new();
    let mut at: HashMap<Lattice, usize> = HashMap::new();
    let mut place = |v: usize, p: Lattice, of: &mut HashMap<usize, Lattice>| -> Result<(), String> {
        if *of.entry(v).or_insert(p) != p || *at.entry(p).or_insert(v) != v {
            return Err("a ring face's window does not lie on one lattice (it meets the centre)".into());
        }
        Ok(())
    };
    for (k, c) in [(0, 0), (1, 0), (0, 1)].into_iter().enumerate() {
        place(face[k], c, &mut of)?;
    }
    let mut queue = vec![f];
    let mut visited: HashSet<usize> = HashSet::from([f]);
    while let Some(g) = queue.pop() {
        let gf = mesh.face(g);
        for k in 0..3 {
            let (a, b, c) = (gf[k], gf[(k + 1) % 3], gf[(k + 2) % 3]);
            let (pa, pb, pc) = (of[&a], of[&b], of[&c]);
            let across: Vec<usize> = vf[a].iter().copied().filter(|&h| h != g && mesh.face(h).contains(&b)).collect();
            let &[h] = across.as_slice() else {
                return Err("a window edge does not have two faces (the window leaves the net)".into());
            };
            if visited.contains(&h) {
                continue;
            }
            let hf = mesh.face(h);
            if hf.len() != 3 {
                return Err("a window face is not a triangle".into());
            }
            let third = *hf.iter().find(|&&v| v != a && v != b).ok_or("a degenerate face")?;
            let p = (pa.0 + pb.0 - pc.0, pa.1 + pb.1 - pc.1);
            if !within(p) && !of.contains_key(&third) {
                continue;
            }
            place(third, p, &mut of)?;
            visited.insert(h);
            if [pa, pb, p].iter().all(|&q| within(q)) {
                queue.push(h);
            }
        }
    }
    drop(place);
    for p in needed {
        let v = *at.get(p).ok_or("a ring face's window is not on the net at this level")?;
        // the window's vertices and their neighbours are regular, so the
        // rules over the window are the regular ones at every later level
        for &g in &vf[v] {
            for &u in mesh.face(g) {
                if vf[u].len() != 6 || vf[u].iter().any(|&h| mesh.face(h).len() != 3) {
                    return Err("a ring face's window meets a vertex that is not regular".into());
                }
            }
        }
    }
    Ok(Chart { at, of })
}

/// Compare the rules of one analysis step with the regular mask, exactly,
/// at every point of every child window of every ring face.
fn check_rules(
    scheme: &dyn Scheme,
    bound: &LatticeBound,
    mesh: &PolyMesh,
    charts: &[Chart],
) -> Result<usize, RingFailure> {
    let d = bound.mask.dilation;
    let fail = |e: String| RingFailure::Level(e);
    // the analysis step's refinements, with each new vertex's origin parents
    let mut levels: Vec<(PolyMesh, Vec<Origin>)> = Vec::new();
    let mut current = mesh.clone();
    for _ in 0..bound.mask.steps {
        let r = connectivity(scheme, &current).map_err(|e| fail(format!("the net could not be refined: {e}")))?;
        levels.push((current, r.vertex_origins));
        current = r.mesh;
    }
    let parents = |mesh: &PolyMesh, o: Origin| -> Vec<usize> {
        match o {
            Origin::Vertex(v) => vec![v],
            Origin::Edge(a, b) => vec![a, b],
            Origin::Face(g) => mesh.face(g).to_vec(),
            Origin::Corner { face, .. } => mesh.face(face).to_vec(),
        }
    };
    // children of each vertex per step, for locating new points near a window
    let children_of: Vec<Vec<Vec<usize>>> = levels
        .iter()
        .map(|(m, origins)| {
            let mut c = vec![Vec::new(); m.num_vertices()];
            for (v, &o) in origins.iter().enumerate() {
                for p in parents(m, o) {
                    c[p].push(v);
                }
            }
            c
        })
        .collect();
    // composed stencils over the net's vertices, per new vertex (cached)
    let mut composed: HashMap<usize, HashMap<usize, Rational>> = HashMap::new();
    let mut stencil_cache: Vec<HashMap<usize, Vec<(usize, Rational)>>> = vec![HashMap::new(); levels.len()];
    let mut checked = 0;
    // the mask is rotation symmetric (`check_rotation_symmetry`), so a new
    // vertex verified in one chart is verified in all
    let mut verified: HashSet<usize> = HashSet::new();
    for chart in charts {
        // positions (1/D units) of the new vertices near the window, step by step
        let mut pos: HashMap<usize, Lattice> = chart.of.iter().map(|(&v, &p)| (v, (d * p.0, d * p.1))).collect();
        for (step, (m, origins)) in levels.iter().enumerate() {
            let mut next: HashMap<usize, Lattice> = HashMap::new();
            for &v in pos.keys() {
                for &c in &children_of[step][v] {
                    if next.contains_key(&c) {
                        continue;
                    }
                    let ps = parents(m, origins[c]);
                    let placed: Option<Vec<Lattice>> = ps.iter().map(|p| pos.get(p).copied()).collect();
                    let Some(placed) = placed else { continue };
                    let k = placed.len() as i64;
                    let sum = placed.iter().fold((0, 0), |s, p| (s.0 + p.0, s.1 + p.1));
                    if sum.0 % k == 0 && sum.1 % k == 0 {
                        next.insert(c, (sum.0 / k, sum.1 / k));
                    }
                }
            }
            pos = next;
        }
        let at: HashMap<Lattice, usize> = pos.iter().map(|(&v, &p)| (p, v)).collect();
        for (o, t2) in children(0, d) {
            for c in &bound.windows[t2] {
                let y = (o.0 + c.0, o.1 + c.1);
                let &v = at.get(&y).ok_or_else(|| fail("a child window's point is not on the refined net".into()))?;
                if verified.contains(&v) {
                    continue;
                }
                let actual = compose(scheme, &levels, &mut stencil_cache, &mut composed, v)?;
                let mut expected: HashMap<usize, Rational> = HashMap::new();
                for (x, w) in bound.mask.weights(y) {
                    let &u =
                        chart.at.get(&x).ok_or_else(|| fail("the regular mask reaches beyond the chart".into()))?;
                    expected.insert(u, w);
                }
                if *actual != expected {
                    return Err(RingFailure::Final(format!(
                        "numerical only: a rule over the ring is not the scheme's regular rule on the lattice (the \
                         new point at {y:?}/{d} of a ring face's chart), so the difference-scheme bound does not apply"
                    )));
                }
                verified.insert(v);
                checked += 1;
            }
        }
    }
    Ok(checked)
}

/// The stencil of the last step's new vertex `v` over the net's vertices,
/// composed through the analysis step's refinements.
fn compose<'a>(
    scheme: &dyn Scheme,
    levels: &[(PolyMesh, Vec<Origin>)],
    cache: &mut [HashMap<usize, Vec<(usize, Rational)>>],
    composed: &'a mut HashMap<usize, HashMap<usize, Rational>>,
    v: usize,
) -> Result<&'a HashMap<usize, Rational>, RingFailure> {
    if !composed.contains_key(&v) {
        let mut current: HashMap<usize, Rational> = HashMap::from([(v, Rational::one())]);
        for step in (0..levels.len()).rev() {
            let (mesh, origins) = &levels[step];
            let mut next: HashMap<usize, Rational> = HashMap::new();
            for (u, w) in current {
                if !cache[step].contains_key(&u) {
                    let s = stencil_at::<Rational>(scheme, mesh, origins[u])
                        .map_err(|_| RingFailure::Final("a rule over the ring has an irrational weight".into()))?
                        .map_err(|cause| {
                            RingFailure::Level(format!("a rule over the ring cannot be evaluated on the net: {cause}"))
                        })?;
                    cache[step].insert(u, s.terms);
                }
                for (x, wx) in &cache[step][&u] {
                    *next.entry(*x).or_insert_with(Rational::zero) += &w * wx;
                }
            }
            next.retain(|_, w| !w.is_zero());
            current = next;
        }
        composed.insert(v, current);
    }
    Ok(&composed[&v])
}

/// Bounds over one triangle of type `t` from its window's values (in
/// `LatticeBound::windows[t]` order): the Jacobian det(∂₁f, ∂₂f) within
/// ε(|u| + |v|) + ε² of det(u, v), and δ, the distance of f from the
/// triangle's own linear interpolant.
pub fn face_bounds(bound: &LatticeBound, t: usize, values: &[[Interval; 2]]) -> (Interval, f64) {
    let at = |p: Lattice| values[bound.windows[t].binary_search(&p).expect("own corners are window points")];
    let edge = |(a, b): (Lattice, Lattice)| {
        let (pa, pb) = (at(a), at(b));
        [pb[0] - pa[0], pb[1] - pa[1]]
    };
    let (u, v) = (edge(OWN_EDGES[t][0]), edge(OWN_EDGES[t][1]));
    let mut n = 0.0f64;
    for row in &bound.basis[t] {
        let mut s = [Interval::point(0.0); 2];
        for (p, c) in row {
            let q = at(*p);
            for k in 0..2 {
                s[k] = s[k] + Interval::point(*c as f64) * q[k];
            }
        }
        n = n.max(Interval::sqrt(&(s[0].square() + s[1].square())).hi);
    }
    let length = |w: [Interval; 2]| Interval::sqrt(&(w[0].square() + w[1].square()));
    let eps = Interval::point((Interval::point(bound.edge_constant) * Interval::point(n)).hi);
    let pad = (eps * (length(u) + length(v)) + eps * eps).hi;
    let det = u[0] * v[1] - u[1] * v[0];
    let delta = (Interval::point(bound.position_constant) * Interval::point(n)).hi;
    (det + Interval::new(-pad, pad), delta)
}

/// The Jacobian over the triangle of type `t` (in its own lattice
/// parameter), refined up to `depth` more levels where its sign is
/// undecided: the triangle's Jacobian lies in the hull of its children's
/// (a child's, in its own parameter, times D²), intersected with its
/// own bound.
pub fn jacobian(bound: &LatticeBound, t: usize, values: &[[Interval; 2]], depth: usize) -> Interval {
    let (here, _) = face_bounds(bound, t, values);
    if here.lo > 0.0 || here.hi < 0.0 || depth == 0 || !here.is_finite() {
        return here;
    }
    let scale = Interval::point((bound.mask.dilation * bound.mask.dilation) as f64);
    let mut hull: Option<Interval> = None;
    for (t2, s) in &bound.refine[t] {
        let child: Vec<[Interval; 2]> = s
            .iter()
            .map(|row| {
                row.iter().fold([Interval::point(0.0); 2], |acc, &(i, w)| {
                    [acc[0] + w * values[i][0], acc[1] + w * values[i][1]]
                })
            })
            .collect();
        let j = jacobian(bound, *t2, &child, depth - 1) * scale;
        // a child of undecided sign leaves the parent undecided: stop early
        if !(j.lo > 0.0 || j.hi < 0.0) {
            return here;
        }
        hull = Some(hull.map_or(j, |h| h.hull(&j)));
    }
    let children = hull.expect("a triangle has children");
    let (lo, hi) = (children.lo.max(here.lo), children.hi.min(here.hi));
    if lo <= hi {
        Interval::new(lo, hi)
    } else {
        children
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn children_tile_the_triangle() {
        for d in [2, 3] {
            for t in 0..2 {
                let kids = children(t, d);
                assert_eq!(kids.len() as i64, d * d);
                let ups = kids.iter().filter(|(_, t2)| *t2 == t).count() as i64;
                assert_eq!(ups, d * (d + 1) / 2, "same-orientation children of a ternary/dyadic split");
            }
        }
    }

    #[test]
    fn barycentric_weights_reproduce_the_point() {
        for t in 0..2 {
            for y in [(1, 1), (2, 0), (1, 2), (3, 0), (2, 2)] {
                let b = barycentric(t, y, 3);
                let sum: Rational = b.iter().map(|(_, w)| w.clone()).sum();
                assert_eq!(sum, Rational::one());
                let x: Rational = b.iter().map(|(c, w)| w * Rational::from_integer(c.0.into())).sum();
                assert_eq!(x * Rational::from_integer(3.into()), Rational::from_integer(y.0.into()));
            }
        }
    }
}
