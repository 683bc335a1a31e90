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

use std::collections::{BTreeSet, HashMap, HashSet};

use super::builder::build_patch;
use super::configuration::Configuration;
use super::labels::{canonical_order, label_vertices, VertexLabel};
use crate::mesh::{LatticeCoord, PolyMesh};
use crate::refine::{apply, SparseRow};
use crate::sdc::{Origin, Stencil};
use crate::sdc::{Scheme, SchemeWeight};
use crate::topology::Refined;

#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum NeighbourhoodKind {
    Minimal,
    Analysis,
}

impl std::str::FromStr for NeighbourhoodKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "minimal" => Ok(NeighbourhoodKind::Minimal),
            "analysis" => Ok(NeighbourhoodKind::Analysis),
            _ => Err(format!("unknown neighbourhood '{s}'; use minimal or analysis")),
        }
    }
}

pub struct Discovered {
    pub config: Configuration,
    /// the generous level-0 patch
    pub patch: PolyMesh,
    pub labels: Vec<VertexLabel>,
    /// the refinements of one analysis step (one for binary schemes, two for
    /// sqrt(3) schemes, whose lattice only realigns after two steps)
    pub refinements: Vec<Refined>,
    /// float stencils of each refinement (index k: level k+1 from level k)
    pub stencils: Vec<Vec<Option<Stencil<f64>>>>,
    /// vertex of the last refinement with given lattice coordinates
    pub step_at: HashMap<LatticeCoord, usize>,
    /// level-0 vertex ids in canonical order
    pub minimal: Vec<usize>,
    pub analysis: Vec<usize>,
    /// rings of the generous patch that were needed
    pub patch_rings: usize,
    /// analysis steps after which the analysis set stopped growing
    pub analysis_levels: usize,
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
        self.step_at.get(&c).copied()
    }
    /// The mesh before refinement k (0 = the patch).
    pub fn mesh_before(&self, k: usize) -> &PolyMesh {
        if k == 0 {
            &self.patch
        } else {
            &self.refinements[k - 1].mesh
        }
    }
}

const MAX_PATCH_RINGS: usize = 8;
/// Face rings kept around the region when pruning refined meshes in the
/// search for the analysis neighbourhood. Stencils reach at most two rings
/// and a ring of a coarser level spans about two of the finer one, so the
/// backward walk stays within about four rings; a scheme that needed more
/// would fail to evaluate a stencil there, and `discover` retries unpruned.
const PRUNE_MARGIN: usize = 4;
const MAX_LEVELS: usize = 3;

pub fn discover(scheme: &dyn Scheme, config: &Configuration) -> Result<Discovered, String> {
    let mut last_err = String::new();
    for rings in 2..=MAX_PATCH_RINGS {
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
    Err(format!(
        "could not find an invariant neighbourhood for {} (valence {}) within {MAX_PATCH_RINGS} rings: {last_err}",
        scheme.name(),
        config.valence()
    ))
}

fn stencils_f64(scheme: &dyn Scheme, mesh: &PolyMesh, refined: &Refined) -> Vec<Option<Stencil<f64>>> {
    refined.vertex_origins.iter().map(|&o| <f64 as SchemeWeight>::stencil(scheme, mesh, o).ok().flatten()).collect()
}

/// Stencils of the last level in terms of level-0 vertices, composed through
/// the intermediate levels (sparse rows refined like points).
fn compose(levels: &[Vec<Option<Stencil<f64>>>], level0: usize) -> Vec<Option<SparseRow<f64>>> {
    let mut rows: Vec<Option<SparseRow<f64>>> = (0..level0).map(|v| Some(SparseRow::unit(v))).collect();
    for st in levels {
        rows = apply(st, &rows);
    }
    rows
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
) -> Result<Discovered, String> {
    let (patch, centre_set) = build_patch(config, rings);
    let labels = label_vertices(&patch, &centre_set, config.centre.is_face_centred());
    let topology = scheme.topology();
    let steps = topology.steps_per_analysis();
    let mut refinements: Vec<Refined> = Vec::new();
    let mut stencils_by_level: Vec<Vec<Option<Stencil<f64>>>> = Vec::new();
    for k in 0..steps {
        let before = if k == 0 { &patch } else { &refinements[k - 1].mesh };
        let r = topology.refine(before)?;
        stencils_by_level.push(stencils_f64(scheme, before, &r));
        refinements.push(r);
    }
    let last = &refinements[steps - 1];
    let chart = last.mesh.chart.as_ref().ok_or("refined patch lost its lattice chart")?;
    let step_at: HashMap<LatticeCoord, usize> = chart.vertex_coords.iter().enumerate().map(|(i, c)| (*c, i)).collect();
    let composite = compose(&stencils_by_level, patch.num_vertices());
    let chart0 = patch.chart.as_ref().expect("patch has a chart");

    // D(v): old vertices on which the successor of v depends
    let dep = |v: usize| -> Option<Vec<usize>> {
        let w = *step_at.get(&chart0.vertex_coords[v])?;
        Some(composite[w].as_ref()?.entries.iter().map(|e| e.0).collect())
    };
    let closure = |start: &mut dyn Iterator<Item = usize>| -> Result<BTreeSet<usize>, String> {
        let mut set: BTreeSet<usize> = BTreeSet::new();
        let mut stack: Vec<usize> = start.collect();
        while let Some(v) = stack.pop() {
            if !set.insert(v) {
                continue;
            }
            let d =
                dep(v).ok_or_else(|| format!("rule for {} not evaluable in a {rings}-ring patch", labels[v].name))?;
            stack.extend(d.into_iter().filter(|u| !set.contains(u)));
        }
        Ok(set)
    };

    let minimal = closure(&mut centre_set.iter().copied())?;

    // --- analysis neighbourhood: dependencies of the first ring's descendants.
    // Dependencies are tracked backwards: mark the first-ring vertices after r
    // refinements, then walk the stencils of refinements r, r-1, ..., 1 down to
    // level 0. This is linear in the stencil sizes (forward dependency sets
    // would cost O(n^3) at the dense central face of a dual scheme).
    // the first ring: faces touching ring 0 (or deeper rings, see `CentreKind::first_ring_depth`)
    let depth = config.centre.first_ring_depth();
    let mut region_faces: Vec<bool> =
        patch.faces().iter().map(|f| f.iter().any(|&v| labels[v].ring <= depth)).collect();
    let mut all_stencils = stencils_by_level.clone();
    let mut collected: BTreeSet<usize> = BTreeSet::new();
    let mut previous: Option<BTreeSet<usize>> = None;
    let mut analysis = None;
    let mut levels_used = 0;
    let mut mesh_k = patch.clone();
    // Beyond the first analysis step only the region and a margin around it
    // are kept: the mesh would otherwise grow geometrically with the level,
    // while the backward walk below only ever reaches a bounded number of
    // rings around the (shrinking) region. `relabel[k]`: for the mesh after
    // refinement k+1, the id each kept vertex had before pruning; `sizes[k]`:
    // the vertex count of the mesh refinement k+1 started from.
    let mut relabel: Vec<Option<Vec<usize>>> = Vec::new();
    let mut sizes: Vec<usize> = Vec::new();
    for r in 1..=MAX_LEVELS * steps {
        sizes.push(mesh_k.num_vertices());
        let refined = if r <= steps {
            refinements[r - 1].clone()
        } else {
            let refined = topology.refine(&mesh_k)?;
            all_stencils.push(stencils_f64(scheme, &mesh_k, &refined));
            refined
        };
        let in_region = region_entities(&mesh_k, &region_faces);
        let descends: Vec<bool> = refined.vertex_origins.iter().map(|o| in_region.contains(o)).collect();
        let next_region: Vec<bool> = refined
            .mesh
            .faces()
            .iter()
            .zip(&refined.face_parents)
            .map(|(f, p)| in_region.contains(p) && f.iter().all(|&v| descends[v]))
            .collect();
        mesh_k = refined.mesh;
        region_faces = next_region;
        let pruned = if prune && r >= steps { prune_around(&mesh_k, &region_faces, PRUNE_MARGIN)? } else { None };
        if let Some((pruned, old, region)) = pruned {
            mesh_k = pruned;
            region_faces = region;
            relabel.push(Some(old));
        } else {
            relabel.push(None);
        }
        if r % steps != 0 {
            continue; // only whole analysis steps are compared
        }
        let mut marked = vec![false; mesh_k.num_vertices()];
        for (f, face) in mesh_k.faces().iter().enumerate() {
            if region_faces[f] {
                face.iter().for_each(|&v| marked[v] = true);
                if let Some(p) = mesh_k.face_point(f) {
                    marked[p] = true;
                }
            }
        }
        for k in (0..r).rev() {
            let st = &all_stencils[k];
            if let Some(old) = &relabel[k] {
                // back to the ids of the unpruned refinement, which `st` indexes
                let mut full = vec![false; st.len()];
                old.iter().zip(&marked).filter(|(_, m)| **m).for_each(|(&o, _)| full[o] = true);
                marked = full;
            }
            let mut marked_below = vec![false; sizes[k]];
            for (v, _) in marked.iter().enumerate().filter(|(_, m)| **m) {
                let Some(stencil) = st[v].as_ref() else {
                    // the mesh this stencil is evaluated on was pruned
                    *blame_pruning |= k >= 1 && relabel[k - 1].is_some();
                    return Err(format!("first-ring vertex after {r} steps not evaluable in a {rings}-ring patch"));
                };
                stencil.support().for_each(|u| marked_below[u] = true);
            }
            marked = marked_below;
        }
        collected.extend(marked.iter().enumerate().filter(|(_, m)| **m).map(|(u, _)| u));
        let closed = closure(&mut collected.iter().copied())?;
        levels_used = r / steps;
        if levels_used >= 2 && previous.as_ref() == Some(&closed) {
            analysis = Some(closed);
            break;
        }
        previous = Some(closed);
    }
    let analysis = analysis.or(previous).expect("at least one level");
    let mut minimal: Vec<usize> = minimal.into_iter().collect();
    let mut analysis: Vec<usize> = analysis.into_iter().collect();
    canonical_order(&labels, &mut minimal);
    canonical_order(&labels, &mut analysis);
    Ok(Discovered {
        config: config.clone(),
        patch,
        labels,
        refinements,
        stencils: stencils_by_level,
        step_at,
        minimal,
        analysis,
        patch_rings: rings,
        analysis_levels: levels_used,
    })
}

/// Vertices, edges (both orientations), faces and corners of the region
/// faces, as origins: the old entities whose new vertices descend from the
/// region (also used to follow the characteristic ring through refinement).
pub fn region_entities(mesh: &PolyMesh, region_faces: &[bool]) -> HashSet<Origin> {
    let mut set = HashSet::new();
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

/// The sub-mesh of the region faces and `margin` rings of faces around them
/// (faces sharing a vertex with the previous ring), with the region flags of
/// the kept faces and, per kept vertex, its id in `mesh`; None when that would
/// keep more than half the faces (copying then costs more than it saves).
type Pruned = (PolyMesh, Vec<usize>, Vec<bool>);
fn prune_around(mesh: &PolyMesh, region_faces: &[bool], margin: usize) -> Result<Option<Pruned>, String> {
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
    let kept: Vec<usize> = (0..mesh.num_faces()).filter(|&f| keep[f]).collect();
    if 2 * kept.len() > mesh.num_faces() {
        return Ok(None);
    }
    let region = kept.iter().map(|&f| region_faces[f]).collect();
    let (pruned, old) = mesh.restrict(&kept)?;
    Ok(Some((pruned, old, region)))
}
