//! Finding the two neighbourhoods of DESIGN.md by tracking dependencies, not by
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
use crate::refine::{Origin, Stencil};
use crate::schemes::{CentreKind, Scheme, SchemeWeight};
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
    /// one refinement step of the patch
    pub level1: Refined,
    /// level-1 vertex with given lattice coordinates
    pub level1_at: HashMap<LatticeCoord, usize>,
    /// level-0 vertex ids in canonical order
    pub minimal: Vec<usize>,
    pub analysis: Vec<usize>,
    /// rings of the generous patch that were needed
    pub patch_rings: usize,
    /// refinement levels after which the analysis set stopped growing
    pub analysis_levels: usize,
}

impl Discovered {
    pub fn set(&self, kind: NeighbourhoodKind) -> &[usize] {
        match kind {
            NeighbourhoodKind::Minimal => &self.minimal,
            NeighbourhoodKind::Analysis => &self.analysis,
        }
    }
    /// The level-1 vertex that plays the role of level-0 vertex `v`.
    pub fn successor(&self, v: usize) -> Option<usize> {
        let c = self.patch.chart.as_ref()?.vertex_coords[v];
        self.level1_at.get(&c).copied()
    }
}

const MAX_PATCH_RINGS: usize = 8;
const MAX_LEVELS: usize = 3;

pub fn discover(scheme: &dyn Scheme, config: &Configuration) -> Result<Discovered, String> {
    let mut last_err = String::new();
    for rings in 2..=MAX_PATCH_RINGS {
        match try_discover(scheme, config, rings) {
            Ok(d) => return Ok(d),
            Err(e) => last_err = e,
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

fn try_discover(scheme: &dyn Scheme, config: &Configuration, rings: usize) -> Result<Discovered, String> {
    let (patch, centre_set) = build_patch(config, rings);
    let labels = label_vertices(&patch, &centre_set, config.centre == CentreKind::Face);
    let topology = scheme.topology();
    let level1 = topology.refine(&patch)?;
    let chart1 = level1.mesh.chart.as_ref().ok_or("refined patch lost its lattice chart")?;
    let level1_at: HashMap<LatticeCoord, usize> =
        chart1.vertex_coords.iter().enumerate().map(|(i, c)| (*c, i)).collect();
    let st1 = stencils_f64(scheme, &patch, &level1);
    let chart0 = patch.chart.as_ref().expect("patch has a chart");

    // D(v): old vertices on which the successor of v depends
    let dep = |v: usize| -> Option<Vec<usize>> {
        let w = *level1_at.get(&chart0.vertex_coords[v])?;
        Some(st1[w].as_ref()?.support().collect())
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

    // --- analysis neighbourhood: dependencies of the first ring's descendants
    let centre_lookup: HashSet<usize> = centre_set.iter().copied().collect();
    let mut region_faces: Vec<bool> =
        patch.faces().iter().map(|f| f.iter().any(|v| centre_lookup.contains(v))).collect();
    // Dependencies are tracked backwards: mark the first-ring vertices of level
    // L, then walk the stencils of levels L, L-1, ..., 1 down to level 0. This is
    // linear in the stencil sizes (forward dependency sets would cost O(n^3) at
    // the dense central face of a dual scheme).
    let mut mesh_k = patch.clone();
    let mut stencils_by_level: Vec<Vec<Option<Stencil<f64>>>> = Vec::new();
    let mut collected: BTreeSet<usize> = BTreeSet::new();
    let mut previous: Option<BTreeSet<usize>> = None;
    let mut analysis = None;
    let mut levels_used = 0;
    for level in 1..=MAX_LEVELS {
        let (refined, stencils) = if level == 1 {
            (level1.clone(), st1.clone())
        } else {
            let r = topology.refine(&mesh_k)?;
            let s = stencils_f64(scheme, &mesh_k, &r);
            (r, s)
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
        stencils_by_level.push(stencils);
        let mut marked = vec![false; refined.mesh.num_vertices()];
        for (f, face) in refined.mesh.faces().iter().enumerate() {
            if next_region[f] {
                face.iter().for_each(|&v| marked[v] = true);
            }
        }
        for k in (0..level).rev() {
            let st = &stencils_by_level[k];
            let below = if k == 0 { patch.num_vertices() } else { stencils_by_level[k - 1].len() };
            let mut marked_below = vec![false; below];
            for (v, _) in marked.iter().enumerate().filter(|(_, m)| **m) {
                let stencil = st[v].as_ref().ok_or_else(|| {
                    format!("first-ring vertex at level {level} not evaluable in a {rings}-ring patch")
                })?;
                stencil.support().for_each(|u| marked_below[u] = true);
            }
            marked = marked_below;
        }
        collected.extend(marked.iter().enumerate().filter(|(_, m)| **m).map(|(u, _)| u));
        let closed = closure(&mut collected.iter().copied())?;
        levels_used = level;
        if level >= 2 && previous.as_ref() == Some(&closed) {
            analysis = Some(closed);
            break;
        }
        previous = Some(closed);
        mesh_k = refined.mesh;
        region_faces = next_region;
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
        level1,
        level1_at,
        minimal,
        analysis,
        patch_rings: rings,
        analysis_levels: levels_used,
    })
}

/// Vertices, edges (both orientations) and faces of the region faces, as origins.
fn region_entities(mesh: &PolyMesh, region_faces: &[bool]) -> HashSet<Origin> {
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
