//! Finding the two neighbourhoods of ARCHITECTURE.md by tracking dependencies, not by
//! hard-coding them per scheme.
//!
//! * minimal invariant set: the closure of the ring-0 vertices under "the new
//!   vertex with this label depends on these old vertices".
//! * analysis neighbourhood: the invariant closure of every old vertex that a
//!   refined vertex of the first ring depends on, over refinement levels 1, 2,
//!   3 until nothing new appears. The first ring is the set of faces touching
//!   ring 0; its descendants are the new faces built only from new vertices
//!   that come from first-ring vertices, edges and faces.
//!
//! Both need the old patch large enough that every rule involved can be
//! evaluated; when one cannot, the patch grows by a ring and discovery restarts.

use std::cell::RefCell;
use std::collections::{BTreeSet, HashMap};
use std::sync::{Arc, Mutex, OnceLock};

use crate::engine::memo::{Derived, Memo};

use super::builder::build_patch;
use super::configuration::Configuration;
use super::labels::{canonical_order, label_vertices, VertexLabel};
use crate::engine::closure::{invariant_closure, Refinement};
use crate::error::Error;
use crate::mesh::{IdMap, IdSet, LatticeCoord, PolyMesh};
use crate::refine::{Combine, SparseRow};
use crate::sdc::Topology;
use crate::sdc::{Origin, Scheme, Stencil};
use crate::topology::Refined;

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum NeighbourhoodKind {
    Minimal,
    Analysis,
}

impl std::str::FromStr for NeighbourhoodKind {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        match s {
            "minimal" => Ok(NeighbourhoodKind::Minimal),
            "analysis" => Ok(NeighbourhoodKind::Analysis),
            _ => Err(Error::Input(format!("unknown neighbourhood '{s}'; use minimal or analysis"))),
        }
    }
}

pub struct Discovered {
    pub config: Configuration,
    /// the generous level-0 patch (shared with every discovery on the same
    /// host, configuration and patch size: see `PatchTopology`)
    pub patch: Arc<PolyMesh>,
    pub labels: Arc<Vec<VertexLabel>>,
    /// the host that refines the patch
    topology: Topology,
    /// one analysis step of the whole patch, made on first use (see
    /// [`Discovered::refinements`])
    full_step: OnceLock<Arc<FullStep>>,
    /// float stencils of each refinement (index k: level k+1 from level k),
    /// completed on first use by [`Discovered::float_stencils`]
    stencils: FloatStencils,
    /// level-0 vertex ids in canonical order
    pub minimal: Vec<usize>,
    pub analysis: Vec<usize>,
    /// rings of the generous patch that were needed
    pub patch_rings: usize,
    /// analysis steps after which the analysis set stopped growing
    pub analysis_levels: usize,
    /// Rows over one analysis step (in level-0 vertices, f64) of the
    /// successors of the level-0 vertices whose dependencies discovery
    /// needed: the orbit representatives of both neighbourhoods when the
    /// configuration is rotation-symmetric. These are the rows of S that the
    /// Fourier blocks need, composed exactly as assembly composes them, so
    /// assembly takes them from here instead of composing them again.
    pub(crate) composite: HashMap<usize, SparseRow<f64>>,
    /// What later stages derive from this discovery alone (see
    /// [`Discovered::derived`]).
    derived: Derived,
}

/// The refinements of one analysis step of the whole patch (one for binary
/// schemes, two for sqrt(3) schemes, whose lattice only realigns after two
/// steps) and, per lattice coordinate, the vertex of the last one there.
struct FullStep {
    refinements: Vec<Refined>,
    step_at: IdMap<LatticeCoord, usize>,
}

impl FullStep {
    fn new(refinements: Vec<Refined>) -> Result<FullStep, Error> {
        let last =
            refinements.last().ok_or_else(|| Error::Message("an analysis step has at least one refinement".into()))?;
        let chart =
            last.mesh.chart.as_ref().ok_or_else(|| Error::Message("refined patch lost its lattice chart".into()))?;
        let mut step_at = IdMap::with_capacity_and_hasher(chart.vertex_coords.len(), Default::default());
        step_at.extend(chart.vertex_coords.iter().enumerate().map(|(i, c)| (*c, i)));
        Ok(FullStep { refinements, step_at })
    }
}

impl Discovered {
    pub fn set(&self, kind: NeighbourhoodKind) -> &[usize] {
        match kind {
            NeighbourhoodKind::Minimal => &self.minimal,
            NeighbourhoodKind::Analysis => &self.analysis,
        }
    }
    /// The vertex after one analysis step that plays the role of level-0 vertex
    /// `v`: the one at the same lattice coordinates of the refined lattice.
    /// (For sqrt(3) schemes this is the permutation R of R·S·S: labels are
    /// positional, so the 60-degree turn of two steps is undone by the lookup.)
    pub fn successor(&self, v: usize) -> Option<usize> {
        let c = self.patch.chart.as_ref()?.vertex_coords[v];
        self.full_step().step_at.get(&c).copied()
    }
    /// The refinements of one analysis step of the whole patch (one for
    /// binary schemes, two for sqrt(3) schemes). Discovery of a large
    /// rotation-symmetric configuration refines only the sectors around the
    /// orbit representatives (see `window_faces`); whoever needs every vertex
    /// (the characteristic map, exact or full assembly) gets the whole step,
    /// made here on first use.
    pub fn refinements(&self) -> &[Refined] {
        &self.full_step().refinements
    }
    /// Whether the whole analysis step has been made: by discovery itself
    /// (small or asymmetric configurations) or on demand since (for tests and
    /// benchmarks of the windowed path).
    pub fn whole_step_made(&self) -> bool {
        self.full_step.get().is_some()
    }
    fn full_step(&self) -> &FullStep {
        self.full_step.get_or_init(|| {
            let mut refinements: Vec<Refined> = Vec::new();
            for _ in 0..self.topology.steps_per_analysis() {
                let before = refinements.last().map_or(&*self.patch, |r| &r.mesh);
                // discovery refined part of this patch, and the whole refines
                // as any mesh the host accepts does
                refinements.push(self.topology.refine(before).expect("the patch discovery refined refines"));
            }
            Arc::new(FullStep::new(refinements).expect("a refined patch keeps its lattice chart"))
        })
    }
    /// The mesh before refinement k (0 = the patch).
    pub fn mesh_before(&self, k: usize) -> &PolyMesh {
        if k == 0 {
            &self.patch
        } else {
            &self.refinements()[k - 1].mesh
        }
    }
    /// The float stencils of every vertex of each refinement of one analysis
    /// step (index k: level k+1 from level k; None where the patch is too
    /// small to evaluate the rule). Discovery evaluates only the stencils of
    /// orbit representatives (O(1) vertices per level, see `Rotation`); the
    /// spectrum needs no more, so the rest (O(n) stencils, those of the
    /// centre's ring with O(n) terms each) is evaluated here on first use,
    /// by whoever needs every vertex: the characteristic map, which refines
    /// whole nets, and the full matrix. `scheme` must be the scheme that
    /// discovered `self`.
    pub fn float_stencils(&self, scheme: &dyn Scheme) -> &Arc<FloatStencilTable> {
        self.stencils.all.get_or_init(|| {
            let partial = self.stencils.partial.lock().unwrap_or_else(|e| e.into_inner()).take();
            let evaluated = partial
                .unwrap_or_else(|| self.refinements().iter().map(|r| vec![None; r.vertex_origins.len()]).collect());
            let all = evaluated
                .into_iter()
                .enumerate()
                .map(|(k, level)| {
                    let (before, origins) = (self.mesh_before(k), &self.refinements()[k].vertex_origins);
                    level
                        .into_iter()
                        .enumerate()
                        .map(|(v, st)| st.unwrap_or_else(|| stencil_f64(scheme, before, origins[v])))
                        .collect()
                })
                .collect();
            Arc::new(all)
        })
    }
    /// The f64 row over one analysis step of the successor of level-0 vertex
    /// `v`, if discovery composed it.
    pub(crate) fn composite_row(&self, v: usize) -> Option<&SparseRow<f64>> {
        self.composite.get(&v)
    }
    /// The value of type `T` derived from this discovery under `key`, made by
    /// `make` the first time it is asked for (a failure is not kept). For
    /// values that depend on nothing but the discovery, its scheme (the
    /// one that discovered it, as for [`Discovered::float_stencils`]) and
    /// `key`: the characteristic ring's net at a level count is refined once
    /// for the curvature class, the Jordan growth test and the exact route.
    pub fn derived<T: std::any::Any + Send + Sync, E>(
        &self,
        key: u64,
        make: impl FnOnce() -> Result<T, E>,
    ) -> Result<Arc<T>, E> {
        self.derived.get_or_try_insert(key, make)
    }
}

/// Per refinement and vertex, the float stencil once evaluated: the outer
/// `Option` says whether it was (discovery evaluates the representatives'
/// only), the inner one whether the rule could be.
type PartialStencils = Vec<Vec<Option<Option<Stencil<f64>>>>>;
/// Per refinement and vertex, the float stencil (None: not evaluable).
pub type FloatStencilTable = Vec<Vec<Option<Stencil<f64>>>>;

/// Discovery's float stencils and, once someone needs every vertex's, all of
/// them (see [`Discovered::float_stencils`]).
struct FloatStencils {
    partial: std::sync::Mutex<Option<PartialStencils>>,
    all: std::sync::OnceLock<Arc<FloatStencilTable>>,
}

pub const MAX_PATCH_RINGS: usize = 8;
/// Face rings kept around the region when pruning refined meshes in the
/// search for the analysis neighbourhood. Stencils reach at most two rings
/// and a ring of a coarser level spans about two of the finer one, so the
/// backward walk stays within about four rings; a scheme that needed more
/// would fail to evaluate a stencil there, and `discover` retries unpruned.
const PRUNE_MARGIN: usize = 4;
const MAX_LEVELS: usize = 3;

pub fn discover(scheme: &dyn Scheme, config: &Configuration) -> Result<Discovered, Error> {
    discover_from(scheme, config, first_patch_rings(scheme, config))
}

/// Discoveries made in this process, by scheme identity and configuration.
static DISCOVERIES: Memo<Discovered> = Memo::new(512 << 20);

/// Bytes a discovery holds per vertex of its level-0 patch: the patch, the
/// refined meshes of one analysis step (several times the patch), labels,
/// and the composite and float stencil rows. A generous estimate, used only
/// to bound the memo.
const MEMO_BYTES_PER_PATCH_VERTEX: usize = 4096;

/// The part of a discovery attempt that depends on the host, the
/// configuration, the patch size and the symmetry period alone, not on the
/// rules' weights: the level-0 patch with its centre and labels, the
/// rotation's orbits, the sector window and discovery's refinements of one
/// analysis step. Every scheme and parameter set on one host (a parameter
/// range decided at many values, a paper's schemes at the same valences, a
/// failed smaller patch tried again for the next scheme) refines the same
/// meshes; they are made once per process and shared (`Arc`), and since
/// each is a deterministic function of the key, a discovery finds exactly
/// what it would find on meshes of its own.
struct PatchTopology {
    patch: Arc<PolyMesh>,
    centre_set: Vec<usize>,
    labels: Arc<Vec<VertexLabel>>,
    rot0: Rotation,
    /// the window's faces (patch face ids), when the window applies
    kept: Option<Vec<usize>>,
    window: Option<PolyMesh>,
    /// one analysis step of the window (or of the whole patch without one)
    step: Arc<FullStep>,
    /// the first ring's faces of the window (or patch): the region whose
    /// descendants the search for the analysis neighbourhood follows
    region0: Vec<bool>,
    /// the search's refinements 1, 2, ... (index r − 1), made on first use
    levels: Mutex<Vec<Arc<SearchLevel>>>,
}

/// Refinement r ≥ 1 of the search for the analysis neighbourhood: the mesh
/// after it (pruned to a margin around the region once the first analysis
/// step is done), the region's descendants on it and its rotation. As
/// `PatchTopology`, scheme-independent.
struct SearchLevel {
    /// refinements past the first analysis step: the origins of the
    /// refinement's vertices (unpruned ids), for its stencils, which are
    /// evaluated lazily on the mesh before it; within the step the
    /// step's own refinements hold them
    origins: Option<Vec<Origin>>,
    /// the mesh after this refinement, if it is not the step's own
    /// (refinement r ≤ steps unpruned)
    mesh: Option<PolyMesh>,
    /// pruned: per kept vertex, its id in the unpruned refinement
    old_ids: Option<Vec<usize>>,
    region_faces: Vec<bool>,
    rot: Rotation,
}

impl PatchTopology {
    /// The mesh the window's (or patch's) first analysis step starts from.
    fn base(&self) -> &PolyMesh {
        self.window.as_ref().unwrap_or(&self.patch)
    }

    /// The mesh after r refinements, given the levels 1..=r made so far.
    fn mesh_after<'a>(&'a self, levels: &'a [Arc<SearchLevel>], r: usize) -> &'a PolyMesh {
        if r == 0 {
            return self.base();
        }
        levels[r - 1].mesh.as_ref().unwrap_or_else(|| &self.step.refinements[r - 1].mesh)
    }

    /// Search level r (made, with those below it, if nobody has yet).
    fn level(&self, r: usize, topology: Topology, period: usize, prune: bool) -> Result<Arc<SearchLevel>, Error> {
        let mut levels = self.levels.lock().unwrap_or_else(|e| e.into_inner());
        let steps = topology.steps_per_analysis();
        while levels.len() < r {
            let i = levels.len() + 1;
            let (before, region_before) = match i {
                1 => (self.base(), &self.region0),
                _ => (self.mesh_after(&levels, i - 1), &levels[i - 2].region_faces),
            };
            let in_region = RegionEntities::new(before, region_before);
            // the first analysis step's refinements are the step's own (read,
            // not copied); later ones are made here
            let made = if i <= steps { None } else { Some(topology.refine(before)?) };
            let rf = made.as_ref().unwrap_or_else(|| &self.step.refinements[i - 1]);
            let descends: Vec<bool> = rf.vertex_origins.iter().map(|&o| in_region.contains(o)).collect();
            let mut region_faces: Vec<bool> = rf
                .mesh
                .faces()
                .iter()
                .zip(&rf.face_parents)
                .map(|(f, &p)| in_region.contains(p) && f.iter().all(|&v| descends[v]))
                .collect();
            let pruned =
                if prune && i >= steps { prune_around(&rf.mesh, &region_faces, PRUNE_MARGIN, period)? } else { None };
            let (origins, mut mesh, old_ids) = match made {
                Some(Refined { mesh, vertex_origins, .. }) => (Some(vertex_origins), Some(mesh), None),
                None => (None, None, None),
            };
            let old_ids = match pruned {
                Some((pruned, old, region)) => {
                    mesh = Some(pruned);
                    region_faces = region;
                    Some(old)
                }
                None => old_ids,
            };
            let after = mesh.as_ref().unwrap_or_else(|| &self.step.refinements[i - 1].mesh);
            let rot = Rotation::new(after, period, false);
            levels.push(Arc::new(SearchLevel { origins, mesh, old_ids, region_faces, rot }));
        }
        Ok(Arc::clone(&levels[r - 1]))
    }
}

/// Patch topologies made in this process, by host, configuration, patch
/// size, period and whether the window may apply.
static PATCH_TOPOLOGIES: Memo<PatchTopology> = Memo::new(256 << 20);

fn patch_topology(
    topology: Topology,
    config: &Configuration,
    rings: usize,
    period: usize,
    prune: bool,
) -> Result<Arc<PatchTopology>, Error> {
    let key = format!("{topology:?} {config:?} rings {rings} period {period} window {prune}");
    let make = || -> Result<PatchTopology, Error> {
        let (patch, centre_set) = build_patch(config, rings);
        let labels = label_vertices(&patch, &centre_set, config.centre.is_face_centred());
        let rot0 = Rotation::new(&patch, period, true);
        // Only representatives are walked, so a large symmetric patch is
        // refined only in the sectors around theirs (vertex ids kept); the
        // whole step is made later if someone needs it
        // (`Discovered::refinements`).
        let kept = if prune { window_faces(&patch, period) } else { None };
        let window = kept.as_ref().map(|kept| patch.keep_faces(kept)).transpose()?;
        let mut refinements: Vec<Refined> = Vec::new();
        for _ in 0..topology.steps_per_analysis() {
            let before = refinements.last().map_or(window.as_ref().unwrap_or(&patch), |r| &r.mesh);
            refinements.push(topology.refine(before)?);
        }
        let step = Arc::new(FullStep::new(refinements)?);
        // the first ring: faces touching ring 0 (or deeper rings, see
        // `CentreKind::first_ring_depth`)
        let depth = config.centre.first_ring_depth();
        let region0 = window
            .as_ref()
            .unwrap_or(&patch)
            .faces()
            .iter()
            .map(|f| f.iter().any(|&v| labels[v].ring <= depth))
            .collect();
        Ok(PatchTopology {
            patch: Arc::new(patch),
            centre_set,
            labels: Arc::new(labels),
            rot0,
            kept,
            window,
            step,
            region0,
            levels: Mutex::new(Vec::new()),
        })
    };
    // the search's later levels (pruned meshes, a few times the patch) are
    // added after the estimate is taken: counted here in advance
    PATCH_TOPOLOGIES.get_or_try_insert(key, make, |t| 4 * t.patch.num_vertices() * MEMO_BYTES_PER_PATCH_VERTEX)
}

/// [`discover`], shared: the same scheme (by [`Scheme::identity`]) and
/// configuration are discovered once per process, and every caller gets the
/// same value (its lazily made parts, the whole refinement step and the float
/// stencils, are made once too). A scheme without an identity is discovered
/// afresh.
pub fn discover_shared(scheme: &dyn Scheme, config: &Configuration) -> Result<Arc<Discovered>, Error> {
    let Some(identity) = scheme.identity() else {
        return discover(scheme, config).map(Arc::new);
    };
    let key = format!("{identity} {config:?}");
    DISCOVERIES.get_or_try_insert(
        key,
        || discover(scheme, config),
        |d| d.patch.num_vertices() * MEMO_BYTES_PER_PATCH_VERTEX,
    )
}

/// [`discover`] on a level-0 patch of at least `min_rings` rings (at most
/// [`MAX_PATCH_RINGS`]): the same two neighbourhoods (they are closures under
/// the rules, found on any patch large enough to evaluate them), with labels
/// and one analysis step reaching further out, for callers that examine a
/// stated vertex set larger than the analysis neighbourhood
/// (`claims::invariant_set`).
pub fn discover_with_rings(scheme: &dyn Scheme, config: &Configuration, min_rings: usize) -> Result<Discovered, Error> {
    if min_rings > MAX_PATCH_RINGS {
        return Err(Error::NotDetermined(format!(
            "a patch of {min_rings} rings is more than the {MAX_PATCH_RINGS} supported"
        )));
    }
    discover_from(scheme, config, first_patch_rings(scheme, config).max(min_rings))
}

fn discover_from(scheme: &dyn Scheme, config: &Configuration, start: usize) -> Result<Discovered, Error> {
    let mut last_err = Error::NotDetermined(String::new());
    for rings in start..=MAX_PATCH_RINGS {
        let mut blame_pruning = false;
        match try_discover(scheme, config, rings, true, &mut blame_pruning) {
            Ok(d) => return Ok(d),
            Err(e) => last_err = e,
        }
        // a stencil missing next to a pruned margin: the margin was too small
        // for this scheme, so the same patch is tried without pruning
        if blame_pruning {
            match try_discover(scheme, config, rings, false, &mut blame_pruning) {
                Ok(d) => return Ok(d),
                Err(e) => last_err = e,
            }
        }
    }
    // the last attempt's variant: a rule reaching past every patch tried
    // stays NotDetermined, a host refusing the patch stays Input
    Err(last_err.map_message(|m| {
        format!(
            "could not find an invariant neighbourhood for {} (valence {}) within {MAX_PATCH_RINGS} rings: {m}",
            scheme.name(),
            config.valence()
        )
    }))
}

/// Valences above this are probed at about this valence first.
pub const PROBE_VALENCE: usize = 24;

/// Peak bytes of an analysis per vertex of the probe's patch and its one
/// analysis step (see [`bytes_per_sector`]). Measured: `spectrum` (exact
/// stage included) at n = 5000 of every built-in scheme peaks at 0.15 to
/// 0.45 times the estimate this gives.
const BYTES_PER_PROBE_VERTEX: f64 = 4096.0;

/// Bytes per sector when the probe itself fails (the analysis will then
/// report why): the largest per-sector estimate of the built-in schemes.
const FALLBACK_BYTES_PER_SECTOR: f64 = 512.0 * 1024.0;

/// The memory an analysis of `scheme` needs per sector of a configuration:
/// the vertices of the regular configuration's patch and of its analysis
/// step at [`PROBE_VALENCE`] (milliseconds to find), per sector, times
/// [`BYTES_PER_PROBE_VERTEX`]. Every structure of an analysis grows with
/// the patch, and the patch (the rings the rules reach) grows linearly in
/// the valence with the same rings, so this is a per-scheme linear estimate
/// available before any work at the valence asked for.
pub fn bytes_per_sector(scheme: &dyn Scheme) -> f64 {
    let probe = Configuration {
        centre: scheme.centre_kind(),
        sectors: vec![scheme.sector_kind(); PROBE_VALENCE],
        face_control: scheme.face_control(),
        tagging: None,
    };
    match discover_shared(scheme, &probe) {
        Ok(d) => {
            let vertices =
                d.patch.num_vertices() + d.refinements().iter().map(|r| r.mesh.num_vertices()).sum::<usize>();
            BYTES_PER_PROBE_VERTEX * vertices as f64 / PROBE_VALENCE as f64
        }
        Err(_) => FALLBACK_BYTES_PER_SECTOR,
    }
}

/// The first patch size worth trying. How many rings the rules reach does not
/// depend on the valence, so a large symmetric configuration starts with the
/// patch that the same sector pattern needed at about `PROBE_VALENCE`
/// sectors (found in milliseconds), instead of first failing on smaller
/// patches, each of which costs a refinement of O(n) faces. Starting larger
/// than necessary changes nothing found: both neighbourhoods are closures
/// under the rules, and a patch only has to be large enough to evaluate them.
fn first_patch_rings(scheme: &dyn Scheme, config: &Configuration) -> usize {
    let n = config.valence();
    let period = config.rotation_period(scheme);
    if n <= 2 * PROBE_VALENCE || 2 * period > PROBE_VALENCE || scheme.fixed_valence().is_some() {
        return 2;
    }
    let probe = Configuration { sectors: config.sectors[..period].repeat(PROBE_VALENCE / period), ..config.clone() };
    discover_shared(scheme, &probe).map_or(2, |d| d.patch_rings)
}

/// A float stencil as one refinement step evaluates it; None when the rule
/// cannot be evaluated on this mesh.
fn stencil_f64(scheme: &dyn Scheme, mesh: &PolyMesh, o: Origin) -> Option<Stencil<f64>> {
    crate::refine::stencil_at::<f64>(scheme, mesh, o).ok().and_then(Result::ok)
}

/// The rotation of a charted mesh by `period` sectors (the configuration's
/// symmetry) as a vertex map. Dependencies commute with it: the old vertices
/// a rotated vertex depends on are the rotated dependencies. So sets that are
/// unions of orbits (both neighbourhoods, the descendants of the first ring)
/// are tracked by their representatives, the orbit members in sectors
/// `0..period` (and the fixed centre): O(1) vertices per level instead of
/// O(n), whose stencils near a valence-n centre have O(n) terms each.
/// Without a usable chart, or without symmetry, every vertex represents
/// itself and the same code tracks whole sets.
pub(crate) struct Rotation {
    /// per vertex: its representative and the number of period-turns from it
    rep: Vec<(usize, usize)>,
    /// per representative: the orbit, in turn order (empty for
    /// non-representatives); no entry at all for a rotation made without
    /// orbits (`complete` false: the windowed meshes of the search)
    orbit: Vec<Vec<usize>>,
    /// the order of the rotation: n / period, 1 for the identity that stands
    /// in where the mesh shows no symmetry
    order: usize,
}

impl Rotation {
    fn identity(size: usize) -> Rotation {
        Rotation { rep: (0..size).map(|v| (v, 0)).collect(), orbit: (0..size).map(|v| vec![v]).collect(), order: 1 }
    }

    /// The rotation of `mesh` by `period` sectors; the identity when it has
    /// no chart or no symmetry, or when a representative is missing. With
    /// `complete`, every orbit must be in the mesh (orbits are rebuilt from
    /// representatives there); without, only each vertex's representative
    /// (meshes cut down to a window of sectors, see `window_faces`).
    pub(crate) fn new(mesh: &PolyMesh, period: usize, complete: bool) -> Rotation {
        let size = mesh.num_vertices();
        let Some(chart) = mesh.chart.as_ref() else { return Rotation::identity(size) };
        let n = chart.sectors();
        if period == 0 || period >= n || !n.is_multiple_of(period) {
            return Rotation::identity(size);
        }
        let g = n / period;
        let mut at: IdMap<LatticeCoord, usize> = IdMap::with_capacity_and_hasher(size, Default::default());
        at.extend(chart.vertex_coords.iter().enumerate().map(|(v, c)| (*c, v)));
        if at.len() != size {
            return Rotation::identity(size); // coordinates do not identify vertices
        }
        let mut rep = Vec::with_capacity(size);
        for c in &chart.vertex_coords {
            if c.is_centre() {
                rep.push((at[c], 0));
                continue;
            }
            let Some(&r) = at.get(&LatticeCoord { sector: c.sector % period, ..*c }) else {
                return Rotation::identity(size);
            };
            rep.push((r, c.sector / period));
        }
        let mut orbit = Vec::new();
        if complete {
            orbit = vec![Vec::new(); size];
            for (v, &(r, _)) in rep.iter().enumerate() {
                if r == v {
                    orbit[r] = vec![usize::MAX; if chart.vertex_coords[v].is_centre() { 1 } else { g }];
                }
            }
            for (v, &(r, t)) in rep.iter().enumerate() {
                orbit[r][t] = v;
            }
            if orbit.iter().flatten().any(|&u| u == usize::MAX) {
                return Rotation::identity(size);
            }
        }
        Rotation { rep, orbit, order: g }
    }

    /// The order of the rotation (1: the identity, no symmetry found).
    pub(crate) fn order(&self) -> usize {
        self.order
    }

    /// The vertex that `v` is turned to by one period; `None` on a rotation
    /// made without its orbits (`complete` false).
    pub(crate) fn turned(&self, v: usize) -> Option<usize> {
        let (r, t) = self.rep[v];
        let orbit = self.orbit.get(r)?;
        (!orbit.is_empty()).then(|| orbit[(t + 1) % orbit.len()])
    }

    pub(crate) fn rep(&self, v: usize) -> usize {
        self.rep[v].0
    }

    /// All members of the orbit of representative `r` (none on a rotation
    /// made without its orbits).
    pub(crate) fn orbit(&self, r: usize) -> &[usize] {
        self.orbit.get(r).map_or(&[], Vec::as_slice)
    }
}

/// The float stencils of the refinements of one analysis step, evaluated on
/// demand: discovery needs those of the representatives (O(1) per level), and
/// a patch too small for the rules is rejected before the others are
/// evaluated. [`Discovered::float_stencils`] evaluates the rest for a caller
/// that needs them (the characteristic map refines whole nets with them).
struct StepStencils<'a> {
    scheme: &'a dyn Scheme,
    before: Vec<&'a PolyMesh>,
    origins: Vec<&'a [Origin]>,
    stencils: Vec<Vec<Option<Stencil<f64>>>>,
    done: Vec<Vec<bool>>,
}

impl<'a> StepStencils<'a> {
    fn new(scheme: &'a dyn Scheme, patch: &'a PolyMesh, refinements: &'a [Refined]) -> Self {
        let before = (0..refinements.len()).map(|k| if k == 0 { patch } else { &refinements[k - 1].mesh }).collect();
        let origins: Vec<&[Origin]> = refinements.iter().map(|r| r.vertex_origins.as_slice()).collect();
        let stencils = origins.iter().map(|o| vec![None; o.len()]).collect();
        let done = origins.iter().map(|o| vec![false; o.len()]).collect();
        StepStencils { scheme, before, origins, stencils, done }
    }

    /// The stencil of vertex v of refinement k+1 (None: not evaluable).
    fn get(&mut self, k: usize, v: usize) -> Option<&Stencil<f64>> {
        if v >= self.done[k].len() {
            return None;
        }
        if !self.done[k][v] {
            self.done[k][v] = true;
            self.stencils[k][v] = stencil_f64(self.scheme, self.before[k], self.origins[k][v]);
        }
        self.stencils[k][v].as_ref()
    }

    /// What was evaluated, for [`Discovered::float_stencils`] to complete.
    fn into_partial(self) -> PartialStencils {
        self.stencils
            .into_iter()
            .zip(self.done)
            .map(|(level, done)| level.into_iter().zip(done).map(|(st, d)| d.then_some(st)).collect())
            .collect()
    }
}

/// Rows over the analysis step of last-level vertices in terms of level-0
/// vertices, composed on demand through the intermediate levels (sparse rows
/// refined like points) and memoised per level: a valence-n centre's ring is
/// shared by the rows of several representatives.
struct Composer<'a> {
    stencils: StepStencils<'a>,
    /// memo[k][v]: row of vertex v after refinement k+1 (None inside: not composable)
    memo: Vec<IdMap<usize, Option<SparseRow<f64>>>>,
    /// the first (k, v) whose stencil could not be evaluated
    first_failure: Option<(usize, usize)>,
}

impl<'a> Composer<'a> {
    fn new(stencils: StepStencils<'a>) -> Self {
        let levels = stencils.done.len();
        Composer { stencils, memo: vec![IdMap::default(); levels], first_failure: None }
    }

    /// The row of vertex v after refinement k+1. Same arithmetic, in the same
    /// order, as applying the stencils level by level to unit rows.
    fn row(&mut self, k: usize, v: usize) -> Option<&SparseRow<f64>> {
        self.ensure(k, v);
        self.memo[k][&v].as_ref()
    }

    fn ensure(&mut self, k: usize, v: usize) {
        if self.memo[k].contains_key(&v) {
            return;
        }
        let Some(terms) = self.stencils.get(k, v).map(|st| st.terms.clone()) else {
            self.first_failure.get_or_insert((k, v));
            self.memo[k].insert(v, None);
            return;
        };
        let row = if k == 0 {
            // a merged stencil (sorted, no duplicates, no zeros) is already
            // its row over level 0: combining unit rows would give the same
            // entries at the cost of one allocation per term
            Some(SparseRow { entries: terms })
        } else {
            terms.iter().for_each(|&(u, _)| self.ensure(k - 1, u));
            let below = &self.memo[k - 1];
            let terms: Option<Vec<(f64, &SparseRow<f64>)>> =
                terms.iter().map(|&(u, w)| below[&u].as_ref().map(|r| (w, r))).collect();
            terms.map(|t| SparseRow::combine(&t))
        };
        self.memo[k].insert(v, row);
    }
}

/// Discovery's dependencies in the terms of the engine's closure
/// (`engine::closure`), so that the invariant neighbourhoods come out of the
/// same `invariant_closure` as the Z² and Z windows. A point is a vertex id:
/// coarse points are level-0 orbit representatives (see `Rotation`), fine
/// points vertices after one analysis step. The successor of a coarse vertex
/// is the fine vertex at its lattice coordinates; a fine vertex depends on
/// the representatives of the level-0 vertices in its composed row.
struct RepresentativeSteps<'a> {
    composer: RefCell<Composer<'a>>,
    rot0: &'a Rotation,
    step_at: &'a IdMap<LatticeCoord, usize>,
    coords: &'a [LatticeCoord],
    labels: &'a [VertexLabel],
    rings: usize,
    /// index of the analysis step's last refinement
    last: usize,
    /// successor → level-0 vertex, for every successor the closure asked for
    /// (their composed rows are the representative rows assembly needs)
    asked: RefCell<IdMap<usize, usize>>,
}

impl Refinement for RepresentativeSteps<'_> {
    type Point = usize;

    fn successor(&self, v: &usize) -> Result<usize, Error> {
        let w = self.step_at.get(&self.coords[*v]).copied().ok_or_else(|| self.not_evaluable(*v))?;
        self.asked.borrow_mut().insert(w, *v);
        Ok(w)
    }

    fn dependencies(&self, w: &usize) -> Result<Vec<usize>, Error> {
        let mut composer = self.composer.borrow_mut();
        match composer.row(self.last, *w) {
            Some(row) => Ok(row.entries.iter().map(|e| self.rot0.rep(e.0)).collect()),
            None => Err(self.asked.borrow().get(w).map_or_else(
                || Error::NotDetermined(format!("a refined vertex is not evaluable in a {}-ring patch", self.rings)),
                |&v| self.not_evaluable(v),
            )),
        }
    }
}

impl RepresentativeSteps<'_> {
    fn not_evaluable(&self, v: usize) -> Error {
        Error::NotDetermined(format!("rule for {} not evaluable in a {}-ring patch", self.labels[v].name, self.rings))
    }
}

/// One attempt on a patch of `rings` rings. With `prune`, refined meshes past
/// the first analysis step keep only a margin around the region; a failure
/// that may come from that sets `blame_pruning`.
fn try_discover(
    scheme: &dyn Scheme,
    config: &Configuration,
    rings: usize,
    prune: bool,
    blame_pruning: &mut bool,
) -> Result<Discovered, Error> {
    let topology = scheme.topology();
    let steps = topology.steps_per_analysis();
    let period = config.rotation_period(scheme);
    // the scheme-independent part of this attempt, made once per process
    // for every scheme and parameter set on the same host (see `PatchTopology`)
    let shared = patch_topology(topology, config, rings, period, prune)?;
    let PatchTopology { patch, centre_set, labels, rot0, kept, window, step, .. } = &*shared;
    let chart0 = patch.chart.as_ref().expect("patch has a chart");
    let windowed = window.is_some();
    let base: &PolyMesh = window.as_ref().unwrap_or(patch);
    // Whether the window may be why the stencil of vertex v of refinement
    // k+1 could not be evaluated. A rule that fails on the whole patch too
    // needs a larger patch, not the whole one (so no costly retry); that is
    // checked at level 0, where window and patch share vertex ids, and
    // assumed deeper down.
    let cut_by_window = |k: usize, v: usize, refinements: &[Refined]| -> bool {
        let Some(kept) = kept.as_ref() else { return false };
        if k > 0 {
            return true;
        }
        let origin = match refinements[0].vertex_origins[v] {
            Origin::Face(f) => Origin::Face(kept[f]),
            Origin::Corner { face, corner } => Origin::Corner { face: kept[face], corner },
            o @ (Origin::Vertex(_) | Origin::Edge(..)) => o,
        };
        stencil_f64(scheme, patch, origin).is_some()
    };
    let (refinements, step_at) = (&step.refinements, &step.step_at);
    let orbits = RepresentativeSteps {
        composer: RefCell::new(Composer::new(StepStencils::new(scheme, base, refinements))),
        rot0,
        step_at,
        coords: &chart0.vertex_coords,
        labels,
        rings,
        last: steps - 1,
        asked: RefCell::new(IdMap::default()),
    };
    let closure = |seed: &mut dyn Iterator<Item = usize>| -> Result<BTreeSet<usize>, Error> {
        let seed: Vec<usize> = seed.map(|v| rot0.rep(v)).collect();
        // a dependency that cannot be evaluated, or a closure that outgrows
        // the patch: a larger patch may determine it
        invariant_closure(&orbits, seed, patch.num_vertices()).map_err(|e| Error::NotDetermined(e.to_string()))
    };

    let blame_closure = |blame: &mut bool| {
        let failure = orbits.composer.borrow().first_failure;
        // a successor missing is not the window's doing: the last refinement
        // keeps every level-0 vertex's child
        *blame |= failure.is_some_and(|(k, v)| cut_by_window(k, v, refinements));
    };
    let minimal = closure(&mut centre_set.iter().copied()).inspect_err(|_| blame_closure(blame_pruning))?;

    // --- analysis neighbourhood: dependencies of the first ring's descendants.
    // Dependencies are tracked backwards: mark the first-ring vertices after r
    // refinements, then walk the stencils of refinements r, r-1, ..., 1 down to
    // level 0. This is linear in the stencil sizes (forward dependency sets
    // would cost O(n^3) at the dense central face of a dual scheme), and only
    // representatives are walked (see `Rotation`).
    // Beyond the first analysis step only the region and a margin around it
    // are kept: the mesh would otherwise grow geometrically with the level,
    // while the backward walk below only ever reaches a bounded number of
    // rings around the (shrinking) region. The refined (and pruned) meshes,
    // their regions and rotations are scheme-independent: `SearchLevel`s of
    // the shared patch topology, made on first use.
    // levels[k - 1]: refinement k (its mesh, region, rotation, pruning)
    let mut levels: Vec<Arc<SearchLevel>> = Vec::new();
    // per refinement k + 1 > steps: its stencils as this scheme evaluates them
    let mut lazy: Vec<IdMap<usize, Option<Stencil<f64>>>> = Vec::new();
    let mut collected: BTreeSet<usize> = BTreeSet::new();
    let mut previous: Option<BTreeSet<usize>> = None;
    let mut analysis = None;
    let mut levels_used = 0;
    for r in 1..=MAX_LEVELS * steps {
        levels.push(shared.level(r, topology, period, prune)?);
        if r > steps {
            lazy.push(IdMap::default());
        }
        let level = &levels[r - 1];
        let (mesh_k, region_faces) = (shared.mesh_after(&levels, r), &level.region_faces);
        if r % steps != 0 {
            continue; // only whole analysis steps are compared
        }
        // representatives of the region's vertices after r refinements, as
        // sorted lists without repeats (a set's order, without a tree node
        // per vertex: these sets are rebuilt at every level)
        let mut marked: Vec<usize> = Vec::new();
        for (f, face) in mesh_k.faces().iter().enumerate() {
            if region_faces[f] {
                marked.extend(face.iter().map(|&v| level.rot.rep(v)));
                if let Some(p) = mesh_k.face_point(f) {
                    marked.push(level.rot.rep(p));
                }
            }
        }
        sort_dedup(&mut marked);
        for k in (0..r).rev() {
            let mut marked_below = Vec::new();
            for &v in &marked {
                // back to the id of the unpruned refinement, which stencils index
                let v = levels[k].old_ids.as_ref().map_or(v, |old| old[v]);
                let support: Option<Vec<usize>> = if k < steps {
                    orbits.composer.borrow_mut().stencils.get(k, v).map(|st| st.support().collect())
                } else {
                    // refinement k + 1 of the mesh after k refinements
                    let before = shared.mesh_after(&levels, k);
                    let origin =
                        levels[k].origins.as_ref().expect("a refinement past the first step keeps its origins")[v];
                    let stencil = lazy[k - steps].entry(v).or_insert_with(|| stencil_f64(scheme, before, origin));
                    stencil.as_ref().map(|st| st.support().collect())
                };
                let Some(support) = support else {
                    // the mesh this stencil is evaluated on was cut down
                    *blame_pruning |= (k >= 1 && levels[k - 1].old_ids.is_some()) || cut_by_window(k, v, refinements);
                    return Err(Error::NotDetermined(format!(
                        "first-ring vertex after {r} steps not evaluable in a {rings}-ring patch"
                    )));
                };
                let below = if k == 0 { rot0 } else { &levels[k - 1].rot };
                marked_below.extend(support.into_iter().map(|u| below.rep(u)));
            }
            sort_dedup(&mut marked_below);
            marked = marked_below;
        }
        collected.extend(marked);
        let closed = closure(&mut collected.iter().copied()).inspect_err(|_| blame_closure(blame_pruning))?;
        levels_used = r / steps;
        if levels_used >= 2 && previous.as_ref() == Some(&closed) {
            analysis = Some(closed);
            break;
        }
        previous = Some(closed);
    }
    let analysis = analysis.or(previous).expect("at least one level");
    let expand = |reps: BTreeSet<usize>| -> Vec<usize> {
        let mut all: Vec<usize> = reps.iter().flat_map(|&r| rot0.orbit(r).iter().copied()).collect();
        canonical_order(&labels, &mut all);
        all
    };
    let minimal = expand(minimal);
    let analysis = expand(analysis);
    // the composed rows of the last level, keyed by the level-0 vertex they belong to
    let asked = orbits.asked.into_inner();
    let mut composer = orbits.composer.into_inner();
    let last_rows = composer.memo.pop().expect("one level at least");
    let partial = composer.stencils.into_partial();
    let composite = asked.into_iter().filter_map(|(w, v)| Some((v, last_rows.get(&w)?.clone()?))).collect();
    // what discovery refined and evaluated is the whole step unless windowed
    let (full_step, partial) =
        if windowed { (OnceLock::new(), None) } else { (OnceLock::from(Arc::clone(step)), Some(partial)) };
    Ok(Discovered {
        config: config.clone(),
        patch: Arc::clone(patch),
        labels: Arc::clone(labels),
        topology,
        full_step,
        stencils: FloatStencils { partial: std::sync::Mutex::new(partial), all: OnceLock::new() },
        minimal,
        analysis,
        patch_rings: rings,
        analysis_levels: levels_used,
        composite,
        derived: Derived::default(),
    })
}

/// `ids` sorted, each once: a set's iteration order.
fn sort_dedup(ids: &mut Vec<usize>) {
    ids.sort_unstable();
    ids.dedup();
}

/// Vertices, edges (both orientations), faces and corners of the region
/// faces, as origins: the old entities whose new vertices descend from the
/// region (also used to follow the characteristic ring through refinement).
/// The definition; the search asks [`RegionEntities`], which answers the same
/// without building the set.
pub fn region_entities(mesh: &PolyMesh, region_faces: &[bool]) -> IdSet<Origin> {
    let mut set = IdSet::default();
    for (f, face) in mesh.faces().iter().enumerate() {
        if !region_faces[f] {
            continue;
        }
        set.insert(Origin::Face(f));
        for (k, &v) in face.iter().enumerate() {
            let w = face[(k + 1) % face.len()];
            set.insert(Origin::Vertex(v));
            set.insert(Origin::Edge(v, w));
            set.insert(Origin::Edge(w, v));
            set.insert(Origin::Corner { face: f, corner: k });
        }
    }
    set
}

/// The entities of the region faces ([`region_entities`]' set), asked from
/// per-face and per-vertex flags and the mesh's half-edges instead of
/// hashed into a set: the search asks for every new vertex and face of
/// each refinement whether it descends from the region, and building the
/// set of every entity of the region was a large part of a search level.
pub struct RegionEntities<'a> {
    mesh: &'a PolyMesh,
    faces: &'a [bool],
    /// the corners of the region faces
    vertices: Vec<bool>,
}

impl<'a> RegionEntities<'a> {
    pub fn new(mesh: &'a PolyMesh, region_faces: &'a [bool]) -> RegionEntities<'a> {
        let mut vertices = vec![false; mesh.num_vertices()];
        for (face, _) in mesh.faces().iter().zip(region_faces).filter(|(_, &flagged)| flagged) {
            face.iter().for_each(|&v| vertices[v] = true);
        }
        RegionEntities { mesh, faces: region_faces, vertices }
    }

    /// Whether `o` is in [`region_entities`]' set.
    pub fn contains(&self, o: Origin) -> bool {
        let flagged = |f: usize| self.faces.get(f).copied().unwrap_or(false);
        match o {
            Origin::Vertex(v) => self.vertices.get(v).copied().unwrap_or(false),
            // a side of a region face, either way round: each half-edge is
            // a side of one face at most
            Origin::Edge(a, b) => {
                [(a, b), (b, a)].into_iter().any(|(x, y)| self.mesh.half_edge(x, y).is_some_and(|(f, _)| flagged(f)))
            }
            Origin::Face(f) => flagged(f),
            Origin::Corner { face, corner } => flagged(face) && corner < self.mesh.face(face).len(),
        }
    }
}

/// Sectors kept on each side of the representatives' sectors `0..period` in
/// the refinements past the first analysis step. The walk evaluates stencils
/// of representatives (and the centre) only; their supports reach one sector
/// to each side, and each refinement of a mesh cut at a sector boundary
/// loses at most about one sector of evaluable vertices next to the cut.
/// Every built-in scheme's search ends within three refinements, each
/// costing at most about one sector next to a cut: four on each side stay
/// clear of it (the window then applies from valence 2·(period + 8), and a
/// discovery at any valence above costs about what it costs there; with 16
/// the window began at n ≈ 66 and TPS's discoveries at n = 3..100 took
/// twice as long). A scheme that reached further would fail to evaluate a
/// stencil next to the cut, and `discover` retries without pruning; the
/// unit test `windowed_discovery_equals_the_whole_patchs` compares both.
const WINDOW_SECTORS: usize = 4;
/// Vertex rings around the centre (or the central face) whose faces are kept
/// in every sector: the centre's rules read its whole fan, and the next
/// refinement rebuilds that fan (and its first ring's fans) from the faces
/// touching rings 0 and 1.
const DISC_RINGS: usize = 1;

/// The faces within `WINDOW_SECTORS` sectors of the representatives'
/// sectors `0..period`, and the faces near the centre (within `DISC_RINGS`
/// rings) in every sector. Only representatives are walked (see `Rotation`),
/// so the rest of a valence-n mesh is never read, and cutting it makes every
/// deeper refinement O(1) in size per sector outside the disc. None when
/// that would keep more than half the faces (or the mesh has no usable
/// symmetry).
fn window_faces(mesh: &PolyMesh, period: usize) -> Option<Vec<usize>> {
    let chart = mesh.chart.as_ref()?;
    let n = chart.sectors();
    if period == 0 || period >= n || !n.is_multiple_of(period) || 2 * (period + 2 * WINDOW_SECTORS) > n {
        return None;
    }
    // distance in sectors to the representatives' sectors 0..period
    let sector_distance = |s: usize| if s < period { 0 } else { (s + 1 - period).min(n - s) };
    // rings around the centre: ring 0 is the centre vertex or the central face's corners
    let mut ring = vec![usize::MAX; mesh.num_vertices()];
    for (v, c) in chart.vertex_coords.iter().enumerate() {
        if c.is_centre() {
            ring[v] = 0;
        }
    }
    for (f, face) in mesh.faces().iter().enumerate() {
        if chart.face_sector[f].is_none() {
            face.iter().for_each(|&v| ring[v] = 0);
        }
    }
    // a few passes over the faces (no per-vertex face lists: only the rings
    // up to DISC_RINGS matter)
    for k in 1..=DISC_RINGS {
        let reached: Vec<usize> = mesh
            .faces()
            .iter()
            .filter(|face| face.iter().any(|&v| ring[v] == k - 1))
            .flat_map(|face| face.iter().copied())
            .filter(|&u| ring[u] == usize::MAX)
            .collect();
        reached.into_iter().for_each(|u| ring[u] = k);
    }
    let kept: Vec<usize> = (0..mesh.num_faces())
        .filter(|&f| match chart.face_sector[f] {
            None => true,
            Some(s) => sector_distance(s) <= WINDOW_SECTORS || mesh.face(f).iter().any(|&v| ring[v] <= DISC_RINGS),
        })
        .collect();
    (2 * kept.len() <= mesh.num_faces()).then_some(kept)
}

/// The sub-mesh of the region faces and `margin` rings of faces around them
/// (faces sharing a vertex with the previous ring), cut down further to the
/// window around the representatives (`window_faces`) where the mesh has
/// one, with the region flags of the kept faces and, per kept vertex, its id
/// in `mesh`; None when that would keep more than half the faces (copying
/// then costs more than it saves). Both cuts make one sub-mesh: building the
/// mesh of a deep level is a large part of discovery at high valence.
type Pruned = (PolyMesh, Vec<usize>, Vec<bool>);
fn prune_around(mesh: &PolyMesh, region_faces: &[bool], margin: usize, period: usize) -> Result<Option<Pruned>, Error> {
    let mut keep = region_faces.to_vec();
    let mut near = vec![false; mesh.num_vertices()];
    for _ in 0..margin {
        for (f, face) in mesh.faces().iter().enumerate() {
            if keep[f] {
                face.iter().for_each(|&v| near[v] = true);
            }
        }
        for (f, face) in mesh.faces().iter().enumerate() {
            if !keep[f] && face.iter().any(|&v| near[v]) {
                keep[f] = true;
            }
        }
    }
    if let Some(window) = window_faces(mesh, period) {
        let mut in_window = vec![false; mesh.num_faces()];
        window.into_iter().for_each(|f| in_window[f] = true);
        keep.iter_mut().zip(in_window).for_each(|(k, w)| *k &= w);
    }
    let kept: Vec<usize> = (0..mesh.num_faces()).filter(|&f| keep[f]).collect();
    if 2 * kept.len() > mesh.num_faces() {
        return Ok(None);
    }
    let region = kept.iter().map(|&f| region_faces[f]).collect();
    let (pruned, old) = mesh.restrict(&kept)?;
    Ok(Some((pruned, old, region)))
}

#[cfg(test)]
mod tests;
