//! The planar control net of the characteristic map and its refinement.
//!
//! The net is the pair of subdominant eigenvectors put on the patch vertices
//! of the analysis neighbourhood (nothing elsewhere). It is refined with the
//! scheme's own topology operator and stencils (`refine::apply`), so a vertex
//! whose stencil reaches outside the neighbourhood stays undefined; the first
//! ring around the centre stays defined because that is how the analysis
//! neighbourhood was found (`neighbourhood::discovery`).
//!
//! Two face sets are tracked through the levels, with the same descent rule as
//! discovery (a new face descends from a region when its parent entity and all
//! its vertices come from the region's vertices, edges, faces or corners):
//! `outer`, the descendants of the level-0 first ring (faces touching the
//! centre), and `inner`, the descendants of the first ring after one analysis
//! step. The characteristic ring is `outer` minus `inner`; `inner` is the ring
//! scaled by λ1 together with all smaller copies.

use std::collections::HashSet;
use std::marker::PhantomData;

use nalgebra::{Matrix2, Vector2};

use crate::mesh::{LatticeCoord, PolyMesh};
use crate::neighbourhood::discovery::RegionEntities;
use crate::neighbourhood::Discovered;

use crate::error::Error;
use crate::refine::{apply, connectivity, stencils_of, Combine, StepStencil};
use crate::sdc::{Origin, Scheme, SchemeWeight};

/// Largest number of faces of a refined net: peak memory is about 1 KB per
/// face (connectivity hash maps and the tracked region entities), so this
/// bounds a run to roughly a gigabyte.
pub const MAX_NET_FACES: usize = 1_000_000;

/// A refined net with the two tracked face sets: planar points for the
/// characteristic map, or any data refinement averages (`refine::Combine`),
/// e.g. sparse weight rows over the level-0 vertices (`curvature`).
#[derive(Clone, Debug)]
pub struct Net<T = [f64; 2]> {
    pub mesh: PolyMesh,
    pub points: Vec<Option<T>>,
    /// descendants of the level-0 first ring
    pub outer: Vec<bool>,
    /// descendants of the first ring after one analysis step
    pub inner: Vec<bool>,
    /// descendants of the first ring after two analysis steps (all false
    /// before the second step, or without a lattice chart): `inner` minus
    /// `inner2` is the ring scaled by λ1, a fundamental annulus whose faces'
    /// one-rings stay inside the first ring
    pub inner2: Vec<bool>,
    /// refinements applied to the patch
    pub refinements: usize,
}

impl Net<crate::refine::SparseRow<f64>> {
    /// The net of level-0 data `values` (analysis order, as the unit rows
    /// of a net refined from `SparseRow::unit(k)` at analysis vertex k):
    /// every point its row applied to the data. The same mesh, flags and
    /// defined points as refining the data itself (definedness and pruning
    /// depend on the rules and the mesh only), at the cost of one dot
    /// product per vertex: the curvature analysis refines unit rows once
    /// and reads the characteristic map off them instead of refining again.
    pub fn evaluate<const D: usize>(&self, values: &[[f64; D]]) -> Net<[f64; D]> {
        let points = self.evaluate_points(values);
        Net {
            mesh: self.mesh.clone(),
            points,
            outer: self.outer.clone(),
            inner: self.inner.clone(),
            inner2: self.inner2.clone(),
            refinements: self.refinements,
        }
    }

    /// Every net vertex's row applied to level-0 data `values` (analysis
    /// order); `None` where the row is undefined.
    pub fn evaluate_points<const D: usize>(&self, values: &[[f64; D]]) -> Vec<Option<[f64; D]>> {
        self.points
            .iter()
            .map(|row| {
                row.as_ref().map(|row| {
                    let mut p = [0.0; D];
                    for (k, w) in &row.entries {
                        for (c, x) in p.iter_mut().zip(&values[*k]) {
                            *c += w * x;
                        }
                    }
                    p
                })
            })
            .collect()
    }
}

/// Apply a linear map to every defined point.
pub fn transform(points: &mut [Option<[f64; 2]>], m: Matrix2<f64>) {
    for p in points.iter_mut().flatten() {
        *p = apply_linear(&m, *p);
    }
}

/// The image of one plane point under a linear map (points are stored as
/// `[f64; 2]`, the form the JSON output and the figures use).
pub fn apply_linear(m: &Matrix2<f64>, p: [f64; 2]) -> [f64; 2] {
    (m * Vector2::from(p)).into()
}

/// The level-0 net: `values[k]` sits on patch vertex `d.analysis[k]`.
pub fn initial_points(d: &Discovered, values: &[[f64; 2]]) -> Result<Vec<Option<[f64; 2]>>, Error> {
    if values.len() != d.analysis.len() {
        return Err(Error::Message(format!(
            "{} eigenvector entries for {} neighbourhood vertices",
            values.len(),
            d.analysis.len()
        )));
    }
    let mut pts = vec![None; d.patch.num_vertices()];
    for (k, &v) in d.analysis.iter().enumerate() {
        pts[v] = Some(values[k]);
    }
    Ok(pts)
}

/// The vertices whose faces carry the first ring: ring 0 of the patch (the
/// centre vertex or the central face's corners), and for layouts whose first
/// non-degenerate ring lies further out (polar) the rings up to
/// `CentreKind::first_ring_depth`, as in neighbourhood discovery.
pub fn centre_set(d: &Discovered) -> Vec<usize> {
    let depth = d.config.centre.first_ring_depth();
    (0..d.patch.num_vertices()).filter(|&v| d.labels[v].ring <= depth).collect()
}

fn faces_touching(mesh: &PolyMesh, set: &HashSet<usize>) -> Vec<bool> {
    mesh.faces().iter().map(|f| f.iter().any(|v| set.contains(v))).collect()
}

/// Vertex rings kept around the first ring when pruning, tried in turn: two
/// cover every one-ring rule; schemes with wider masks get a wider margin
/// instead of an error.
const MARGINS: [usize; 3] = [2, 4, 8];

/// Refine the level-0 net `analysis_steps` whole analysis steps (at least one).
pub fn refine_net<T: Combine<f64> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: Vec<Option<T>>,
    analysis_steps: usize,
) -> Result<Net<T>, Error> {
    refine_net_visiting(scheme, d, level0, analysis_steps, &mut |_, _| Ok(()))
}

/// [`refine_net`] of the part of the first ring made of the level-0 patch
/// faces flagged in `first_ring` (one flag per patch face; the faces that do
/// not touch the centre are ignored): the ring of one side of a crease
/// vertex, whose eigenvectors are defined on that side's points only. Only
/// those faces' descendants are tracked (`outer`), so only their vertices
/// need to be defined; the rest of the net may stay undefined.
pub fn refine_net_within<T: Combine<f64> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: Vec<Option<T>>,
    analysis_steps: usize,
    first_ring: &[bool],
) -> Result<Net<T>, Error> {
    refine_net_within_visiting(scheme, d, level0, analysis_steps, first_ring, &mut |_, _| Ok(()))
}

/// [`refine_net_within`] showing the net after each whole analysis step to
/// `visit`, as [`refine_net_visiting`] does for the whole first ring.
pub fn refine_net_within_visiting<T: Combine<f64> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: Vec<Option<T>>,
    analysis_steps: usize,
    first_ring: &[bool],
    visit: &mut Visit<T>,
) -> Result<Net<T>, Error> {
    if first_ring.len() != d.patch.num_faces() {
        return Err(Error::Message(format!(
            "{} face flags for a patch of {} faces",
            first_ring.len(),
            d.patch.num_faces()
        )));
    }
    let first =
        |k: usize, points: &[Option<T>]| Ok(apply(d.float_stencils(scheme)[k].iter().map(Option::as_ref), points));
    refine_net_in::<f64, T>(scheme, d, level0, analysis_steps, Some(first_ring), &first, visit)
}

/// [`refine_net`] to `analysis_steps` levels, showing the net after each
/// whole analysis step 1, 2, ..., `analysis_steps` to `visit` (with the
/// level): one refinement for a question asked at every level (the Jordan
/// growth test's ring sizes at levels 1..5), instead of one per level, each
/// repeating the ones below. The net shown at level l is the net
/// `refine_net(.., l)` returns (the same steps and pruning); a level may be
/// shown again when a wider pruning margin is tried, so `visit` should
/// overwrite what it keeps per level.
pub fn refine_net_visiting<T: Combine<f64> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: Vec<Option<T>>,
    analysis_steps: usize,
    visit: &mut Visit<T>,
) -> Result<Net<T>, Error> {
    // the first analysis step reuses discovery's float stencils
    let first =
        |k: usize, points: &[Option<T>]| Ok(apply(d.float_stencils(scheme)[k].iter().map(Option::as_ref), points));
    refine_net_in::<f64, T>(scheme, d, level0, analysis_steps, None, &first, visit)
}

/// [`refine_net`] with weights of type `W` (e.g. outward-rounded intervals
/// for the certified characteristic map): the rules are evaluated in `W` at
/// every step, the first analysis step on discovery's refinements.
pub fn refine_net_exactly_as<W: SchemeWeight, T: Combine<W> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: Vec<Option<T>>,
    analysis_steps: usize,
) -> Result<Net<T>, Error> {
    let first = exact_first_step::<W, T>(scheme, d);
    refine_net_in::<W, T>(scheme, d, level0, analysis_steps, None, &first, &mut |_, _| Ok(()))
}

/// The first analysis step of [`refine_net_exactly_as`]: discovery's
/// refinements with the rules evaluated in `W`.
fn exact_first_step<'a, W: SchemeWeight, T: Combine<W> + Clone>(
    scheme: &'a dyn Scheme,
    d: &'a Discovered,
) -> impl Fn(usize, &[Option<T>]) -> Result<Vec<Option<T>>, Error> + 'a {
    move |k: usize, points: &[Option<T>]| -> Result<Vec<Option<T>>, Error> {
        let r = &d.refinements()[k];
        let before = d.mesh_before(k);
        let stencils = (0..r.vertex_origins.len())
            .map(|v| {
                crate::refine::new_stencil::<W>(scheme, before, r, v).map_err(|_| {
                    Error::Numeric(format!("{}: a weight has no enclosure in this arithmetic", scheme.name()))
                })
            })
            .collect::<Result<Vec<_>, Error>>()?;
        // a missing stencil leaves its point undefined; `check_defined` and
        // pruning decide whether that matters
        Ok(apply(stencils.iter().map(|s| s.as_ref().ok()), points))
    }
}

type FirstStep<'a, T> = dyn Fn(usize, &[Option<T>]) -> Result<Vec<Option<T>>, Error> + 'a;
type Visit<'a, T> = dyn FnMut(usize, &Net<T>) -> Result<(), Error> + 'a;

fn refine_net_in<W: SchemeWeight, T: Combine<W> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: Vec<Option<T>>,
    analysis_steps: usize,
    first_ring: Option<&[bool]>,
    first: &FirstStep<T>,
    visit: &mut Visit<T>,
) -> Result<Net<T>, Error> {
    let mut last = Err(Error::Message("no pruning margin tried".into()));
    for margin in MARGINS {
        last = refine_with_margin::<W, T>(scheme, d, level0.clone(), analysis_steps, margin, first_ring, first, visit);
        // only a point left undetermined by the pruned margin is worth a
        // wider margin; every other failure is final
        if !matches!(last, Err(Error::NotDetermined(_))) {
            return last;
        }
    }
    last
}

fn refine_with_margin<W: SchemeWeight, T: Combine<W> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: Vec<Option<T>>,
    analysis_steps: usize,
    margin: usize,
    first_ring: Option<&[bool]>,
    first: &FirstStep<T>,
    visit: &mut Visit<T>,
) -> Result<Net<T>, Error> {
    if analysis_steps == 0 {
        return Err(Error::Input("the characteristic ring needs at least one analysis step".into()));
    }
    let mut refining = Refining::<W, T>::start(scheme, d, level0, margin, first_ring, first)?;
    visit(1, &refining.net)?;
    refining.refuse_beyond_limit(analysis_steps)?;
    let steps = refining.steps;
    for _ in steps..analysis_steps * steps {
        refining.refine_once()?;
        if refining.net.refinements % steps == 0 {
            visit(refining.net.refinements / steps, &refining.net)?;
        }
    }
    Ok(refining.net)
}

/// A refinement under way with one pruning margin: the net after some
/// whole refinements, and what the next ones need. `refine_with_margin`
/// drives it to one level; [`ExactLevels`] stops at every level on the way.
struct Refining<'a, W, T> {
    scheme: &'a dyn Scheme,
    margin: usize,
    /// refinements per analysis step
    steps: usize,
    /// the centre's lattice coordinates (for `inner2`), and its size
    centre_coords: Option<HashSet<LatticeCoord>>,
    centre_len: usize,
    /// the pruned net after the first analysis step: first-ring faces and
    /// the others (the estimate of `refuse_beyond_limit`)
    region: usize,
    rest: usize,
    net: Net<T>,
    weight: PhantomData<W>,
}

impl<'a, W: SchemeWeight, T: Combine<W> + Clone> Refining<'a, W, T> {
    /// The net after the first analysis step (discovery's refinements),
    /// checked and pruned.
    fn start(
        scheme: &'a dyn Scheme,
        d: &Discovered,
        level0: Vec<Option<T>>,
        margin: usize,
        first_ring: Option<&[bool]>,
        first: &FirstStep<T>,
    ) -> Result<Self, Error> {
        let steps = scheme.topology().steps_per_analysis();
        let centre0: HashSet<usize> = centre_set(d).into_iter().collect();
        let mut outer = faces_touching(&d.patch, &centre0);
        if let Some(only) = first_ring {
            for (o, keep) in outer.iter_mut().zip(only) {
                *o &= *keep;
            }
        }
        let mut net = Net {
            outer,
            inner: vec![false; d.patch.num_faces()],
            inner2: vec![false; d.patch.num_faces()],
            mesh: PolyMesh::clone(&d.patch),
            points: level0,
            refinements: 0,
        };
        // the first analysis step reuses discovery's refinements, whose vertex ids
        // the successor map (lattice charts) refers to
        for k in 0..steps {
            let r = &d.refinements()[k];
            let points = first(k, &net.points)?;
            net = descend(&net, r.mesh.clone(), &r.vertex_origins, &r.face_parents, points);
        }
        let centre1: HashSet<usize> = centre0
            .iter()
            .map(|&v| {
                d.successor(v)
                    .ok_or_else(|| Error::Message("a centre vertex has no successor after one analysis step".into()))
            })
            .collect::<Result<_, _>>()?;
        net.inner = faces_touching(&net.mesh, &centre1);
        // the centre after k analysis steps is the set of vertices at the centre's
        // lattice coordinates (each level's chart counts in its own units), as
        // `Discovered::successor` finds it after one step
        let centre_coords: Option<HashSet<_>> =
            d.patch.chart.as_ref().map(|c| centre0.iter().map(|&v| c.vertex_coords[v]).collect());
        check_defined(&net)?;
        net = prune(net, margin)?;
        let region = net.outer.iter().filter(|&&o| o).count();
        let rest = net.mesh.num_faces() - region;
        Ok(Refining {
            scheme,
            margin,
            steps,
            centre_coords,
            centre_len: centre0.len(),
            region,
            rest,
            net,
            weight: PhantomData,
        })
    }

    /// [`refuse_beyond_limit`] for a refinement to `analysis_steps` levels.
    fn refuse_beyond_limit(&self, analysis_steps: usize) -> Result<(), Error> {
        let factor = self.scheme.topology().faces_per_face();
        refuse_beyond_limit(self.region, self.rest, factor, self.steps, analysis_steps)
    }

    /// One more refinement, checked and pruned.
    fn refine_once(&mut self) -> Result<(), Error> {
        let (scheme, steps, net) = (self.scheme, self.steps, &self.net);
        let bound = net.mesh.num_faces() * 4;
        if bound > MAX_NET_FACES {
            return Err(Error::Input(format!(
                "refinement level {} would need about {bound} faces, above the supported {MAX_NET_FACES}; use fewer levels",
                net.refinements + 1
            )));
        }
        // The refined connectivity first, then the faces pruning will keep,
        // and only then the stencils, for the kept faces' vertices alone: the
        // rest is dropped by the pruning anyway (about a fifth of a deep
        // level's vertices, the outer half of the margin band's children).
        let r = connectivity(scheme, &net.mesh)?;
        let [outer, inner, mut inner2] = descend_flags(net, &r.mesh, &r.vertex_origins, &r.face_parents);
        if net.refinements + 1 == 2 * steps {
            if let (Some(coords), Some(chart)) = (&self.centre_coords, r.mesh.chart.as_ref().filter(|c| c.scale == 1)) {
                let centre2: HashSet<usize> =
                    (0..r.mesh.num_vertices()).filter(|&v| coords.contains(&chart.vertex_coords[v])).collect();
                if centre2.len() == self.centre_len {
                    inner2 = faces_touching(&r.mesh, &centre2);
                }
            }
        }
        let keep = faces_near(&r.mesh, &outer, self.margin);
        let mut wanted = vec![false; r.mesh.num_vertices()];
        for &f in &keep {
            for v in face_vertices(&r.mesh, f) {
                wanted[v] = true;
            }
        }
        let stencils =
            stencils_of::<W>(scheme, &net.mesh, &r, wanted.iter().enumerate().filter(|(_, &w)| w).map(|(v, _)| v))?;
        let points = apply(stencils.iter().map(StepStencil::stencil), &net.points);
        let refined = Net { mesh: r.mesh, points, outer, inner, inner2, refinements: net.refinements + 1 };
        check_defined(&refined)?;
        self.net = restrict(refined, &keep)?;
        Ok(())
    }
}

/// [`refine_net_exactly_as`] at a rising sequence of levels from one
/// refinement: the certificate tries levels 2, 3, … until one decides, and
/// each level's net continues the previous one's instead of refining from
/// level 0 again. [`ExactLevels::at`]`(l)` is the net (or the error)
/// `refine_net_exactly_as(.., l)` gives: the same steps with the first
/// pruning margin, the limit checked for level l before its steps, as there.
/// Where the first margin leaves a point undetermined, the wider margins'
/// retries are `refine_net_exactly_as` itself, at that level and every later
/// one, so no path differs from it.
pub struct ExactLevels<'a, W, T> {
    scheme: &'a dyn Scheme,
    d: &'a Discovered,
    level0: Vec<Option<T>>,
    /// the first margin's refinement; None before the first level and after
    /// it failed (then `whole` holds each level's net from level 0)
    refining: Option<Refining<'a, W, T>>,
    failed: bool,
    whole: Option<Net<T>>,
}

impl<'a, W: SchemeWeight, T: Combine<W> + Clone> ExactLevels<'a, W, T> {
    pub fn new(scheme: &'a dyn Scheme, d: &'a Discovered, level0: Vec<Option<T>>) -> Self {
        ExactLevels { scheme, d, level0, refining: None, failed: false, whole: None }
    }

    /// The net of `analysis_steps` levels; levels are asked in rising order
    /// (an earlier level than the last one asked is an error).
    pub fn at(&mut self, analysis_steps: usize) -> Result<&Net<T>, Error> {
        if !self.failed {
            match self.advance(analysis_steps) {
                Ok(()) => return Ok(&self.refining.as_ref().expect("advanced").net),
                Err(Error::NotDetermined(_)) => {
                    self.failed = true;
                    self.refining = None;
                }
                Err(e) => return Err(e),
            }
        }
        let net = refine_net_exactly_as::<W, T>(self.scheme, self.d, self.level0.clone(), analysis_steps)?;
        Ok(self.whole.insert(net))
    }

    /// The first margin's refinement continued to `analysis_steps` levels.
    fn advance(&mut self, analysis_steps: usize) -> Result<(), Error> {
        if analysis_steps == 0 {
            return Err(Error::Input("the characteristic ring needs at least one analysis step".into()));
        }
        if self.refining.is_none() {
            let first = exact_first_step::<W, T>(self.scheme, self.d);
            let start = Refining::start(self.scheme, self.d, self.level0.clone(), MARGINS[0], None, &first)?;
            self.refining = Some(start);
        }
        let refining = self.refining.as_mut().expect("started");
        if refining.net.refinements > analysis_steps * refining.steps {
            return Err(Error::Message(format!(
                "the net is refined past {analysis_steps} levels already: levels are asked in rising order"
            )));
        }
        refining.refuse_beyond_limit(analysis_steps)?;
        while refining.net.refinements < analysis_steps * refining.steps {
            refining.refine_once()?;
        }
        Ok(())
    }
}

/// Refuse up front a request whose last level would exceed
/// [`MAX_NET_FACES`], rather than after computing every level below the
/// limit (seconds and a gigabyte at valence 1000). Estimated from the pruned
/// net after the first analysis step: the `region` faces (the first ring's
/// descendants, an area) grow by the host's `factor` per refinement, the
/// `margin` faces around them (a band of fixed width along the region's
/// boundary, a length) by its square root, and the largest mesh is the last
/// refinement of the net pruned so. Within a factor of 1.6 of the faces
/// actually made for every built-in host (measured at n = 50..1000). The
/// per-level check in the loop stays as the backstop.
fn refuse_beyond_limit(
    region: usize,
    margin: usize,
    factor: usize,
    steps: usize,
    analysis_steps: usize,
) -> Result<(), Error> {
    // the largest mesh is the last refinement of the previous level's pruned
    // net, whole: every face of it times `factor`
    let f = factor as f64;
    let faces_at = |l: usize| {
        let k = (l - 1) * steps;
        if k == 0 {
            return 0.0;
        }
        let pruned = region as f64 * f.powi(k as i32 - 1) + margin as f64 * f.sqrt().powi(k as i32 - 1);
        pruned * f
    };
    let estimate = faces_at(analysis_steps);
    if estimate <= MAX_NET_FACES as f64 {
        return Ok(());
    }
    let fits = (1..analysis_steps).rev().find(|&l| faces_at(l) <= MAX_NET_FACES as f64).unwrap_or(1);
    Err(Error::Input(format!(
        "{analysis_steps} levels would need about {estimate:.0} faces at the last level (from {} after the first, \
         about {factor}× per refinement), above the supported {MAX_NET_FACES} (about 1 KB each); use --levels {fits} or fewer",
        region + margin
    )))
}

/// The net one refinement down: the refined mesh (taken, not copied: the
/// deeper levels hold most of a certificate's faces) with the flags carried.
fn descend<T>(old: &Net<T>, mesh: PolyMesh, origins: &[Origin], parents: &[Origin], points: Vec<Option<T>>) -> Net<T> {
    let [outer, inner, inner2] = descend_flags(old, &mesh, origins, parents);
    Net { outer, inner, inner2, mesh, points, refinements: old.refinements + 1 }
}

/// `outer`, `inner` and `inner2` of the refined `mesh`: a new face descends
/// from a region when its parent entity and every vertex's origin are
/// entities of the region (`neighbourhood::discovery::region_entities`).
fn descend_flags<T>(old: &Net<T>, mesh: &PolyMesh, origins: &[Origin], parents: &[Origin]) -> [Vec<bool>; 3] {
    let carry = |flags: &[bool]| -> Vec<bool> {
        let region = RegionEntities::new(&old.mesh, flags);
        let from: Vec<bool> = origins.iter().map(|&o| region.contains(o)).collect();
        mesh.faces().iter().zip(parents).map(|(f, &p)| region.contains(p) && f.iter().all(|&v| from[v])).collect()
    };
    [carry(&old.outer), carry(&old.inner), carry(&old.inner2)]
}

fn face_vertices(mesh: &PolyMesh, f: usize) -> impl Iterator<Item = usize> + '_ {
    mesh.face(f).iter().copied().chain(mesh.face_point(f))
}

/// Every vertex of the first ring's descendants must be defined; otherwise the
/// neighbourhood does not determine the ring and no verdict can be given.
fn check_defined<T>(net: &Net<T>) -> Result<(), Error> {
    for f in (0..net.mesh.num_faces()).filter(|&f| net.outer[f]) {
        if face_vertices(&net.mesh, f).any(|v| net.points[v].is_none()) {
            return Err(Error::NotDetermined(format!(
                "after {} refinements a vertex of the first ring is not determined by the analysis neighbourhood",
                net.refinements
            )));
        }
    }
    if !net.outer.iter().any(|&x| x) {
        return Err(Error::Message("the first ring around the centre is empty".into()));
    }
    Ok(())
}

/// Keep the faces that the next refinement of the first ring can need: the
/// faces within `margin` vertex rings of the first ring. Faces with undefined
/// corners stay (a rule may use only part of a face, e.g. non-box's vertex
/// rule reads the face control vertices around a vertex, not its neighbours). Without this the
/// net would grow by the whole defined region (4x per level) instead of by the
/// ring alone. A too-small margin shows up as an undefined first-ring vertex
/// (`check_defined`), never as a silent error, and `refine_net` then retries
/// with a wider one.
fn prune<T: Clone>(net: Net<T>, margin: usize) -> Result<Net<T>, Error> {
    let keep = faces_near(&net.mesh, &net.outer, margin);
    restrict(net, &keep)
}

/// The faces within `margin` vertex rings of the `outer` faces (those with
/// a corner reached), in face order.
fn faces_near(mesh: &PolyMesh, outer: &[bool], margin: usize) -> Vec<usize> {
    // Breadth-first growth from the outer faces' corners, `margin` face
    // layers deep. Only the last layer's vertices are expanded at each
    // step (the earlier ones were), so the cost is linear in the vertices
    // reached: the net has hundreds of thousands of vertices at the deeper
    // levels of a ternary host, where re-expanding the whole set each layer
    // (and hashing every id) was most of a certificate's time.
    let mut near = vec![false; mesh.num_vertices()];
    let mut frontier: Vec<usize> = Vec::new();
    for f in (0..mesh.num_faces()).filter(|&f| outer[f]) {
        for &v in mesh.face(f) {
            if !near[v] {
                near[v] = true;
                frontier.push(v);
            }
        }
    }
    let vf = mesh.vertex_faces();
    for _ in 0..margin {
        let mut next = Vec::new();
        for &v in &frontier {
            for &f in &vf[v] {
                for &w in mesh.face(f) {
                    if !near[w] {
                        near[w] = true;
                        next.push(w);
                    }
                }
            }
        }
        frontier = next;
    }
    (0..mesh.num_faces()).filter(|&f| mesh.face(f).iter().any(|&v| near[v])).collect()
}

/// The net on the faces `keep` only, renumbered, every flag and point of a
/// kept face carried.
fn restrict<T: Clone>(net: Net<T>, keep: &[usize]) -> Result<Net<T>, Error> {
    // carry every attribute (charts, FCVs, face centres, lattice directions)
    let (new_mesh, old) = net.mesh.restrict(keep)?;
    // each kept vertex appears once in `old`: its row is moved, not cloned
    let mut all_points = net.points;
    let points: Vec<Option<T>> = old.iter().map(|&v| all_points[v].take()).collect();
    Ok(Net {
        outer: keep.iter().map(|&f| net.outer[f]).collect(),
        inner: keep.iter().map(|&f| net.inner[f]).collect(),
        inner2: keep.iter().map(|&f| net.inner2[f]).collect(),
        mesh: new_mesh,
        points,
        refinements: net.refinements,
    })
}

/// The facets of face f as triangles of net vertex ids: around the face
/// control vertex when there is one (the four-directional triangles of
/// non-box), else a fan from the first corner.
pub fn facet_triangles(mesh: &PolyMesh, f: usize) -> Vec<[usize; 3]> {
    let face = mesh.face(f);
    let m = face.len();
    match mesh.face_point(f) {
        Some(c) => (0..m).map(|k| [face[k], face[(k + 1) % m], c]).collect(),
        None => (1..m - 1).map(|k| [face[0], face[k], face[k + 1]]).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_estimate_refuses_only_past_the_limit_and_names_the_levels_that_fit() {
        // 100 000 region faces, no margin, 4 faces per face, one refinement
        // per level: the last mesh of level l has 100 000·4^(l−1) faces, so
        // level 2 (400 000) fits and level 3 (1 600 000) does not
        assert!(refuse_beyond_limit(100_000, 0, 4, 1, 1).is_ok());
        assert!(refuse_beyond_limit(100_000, 0, 4, 1, 2).is_ok());
        let e = refuse_beyond_limit(100_000, 0, 4, 1, 3).unwrap_err();
        assert!(matches!(e, Error::Input(_)));
        let m = e.to_string();
        assert!(m.contains("about 1600000 faces") && m.contains("--levels 2 or fewer"), "{m}");
        // a margin band grows by the square root of the factor: 200 000
        // margin faces are 400 000 after one refinement, and the last
        // refinement of that whole net makes 1 600 000 (not 3 200 000)
        let e = refuse_beyond_limit(0, 200_000, 4, 1, 3).unwrap_err().to_string();
        assert!(e.contains("about 1600000 faces"), "{e}");
        assert!(refuse_beyond_limit(0, 100_000, 4, 1, 3).is_ok());
    }
}
