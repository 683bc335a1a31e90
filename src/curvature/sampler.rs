//! Eigenfunctions sampled on the refined characteristic ring.
//!
//! The level-0 net carries one unit weight row per vertex of the analysis
//! neighbourhood (`SparseRow::unit(k)` on `d.analysis[k]`) and is refined with
//! the scheme's own rules (`charmap::net::refine_net`, the same refinement as
//! the characteristic map's net). Every refined vertex then holds the row of
//! weights that gives its value from any level-0 data: refining a function is
//! one sparse dot product per vertex, whatever the function (eigenvectors,
//! the characteristic map's pair, sampled quadratics).

use faer::c64;

use crate::charmap::net::{
    centre_set, facet_triangles, refine_net, refine_net_visiting, refine_net_within_visiting, Net,
};
use crate::error::Error;
use crate::neighbourhood::Discovered;
use crate::refine::{Combine, SparseRow};
use crate::sdc::Scheme;
use std::sync::Arc;

pub struct RingSampler {
    pub net: Net<SparseRow<f64>>,
    /// faces of the characteristic ring: descendants of the first ring that
    /// are not descendants of the first ring one analysis step later
    pub ring_faces: Vec<usize>,
    /// the ring faces' vertices (corners and face points), ascending
    pub ring_vertices: Vec<usize>,
    /// level-0 size (the analysis neighbourhood)
    pub size: usize,
}

/// Bytes of one row entry (a level-0 index and its weight: 16, and up to
/// twice that in vector capacity, the rows being built by accumulation) and
/// of one face of a refined net (its connectivity and tracked sets, as
/// `charmap::net` measures them). Measured on sqrt(3), three levels: peaks
/// of 0.3, 1.0 and 2.3 GB at n = 200, 400, 600 (about 6 GB at n = 1000,
/// where the estimate is 9 GiB).
const ENTRY_BYTES: f64 = 32.0;
const FACE_BYTES: f64 = 1024.0;

/// The memory of a net of weight rows. Each vertex carries the row of
/// weights over the level-0 neighbourhood that gives its value; a vertex
/// near a valence-n centre depends on all n of the centre's neighbours, so
/// those rows have O(n) entries and the net's entries grow as n² (the
/// characteristic map's net of points is linear in n): at sqrt(3) n = 1000,
/// three levels would need about 6 GB.
fn estimate_bytes(net: &Net<SparseRow<f64>>) -> f64 {
    let entries: usize = net.points.iter().flatten().map(|r| r.entries.len()).sum();
    entries as f64 * ENTRY_BYTES + net.mesh.num_faces() as f64 * FACE_BYTES
}

fn check_memory(bytes: f64, levels: usize, size: usize) -> Result<(), Error> {
    crate::error::check_memory(
        bytes,
        &format!("sampling the characteristic ring {levels} levels deep"),
        &format!(
            "weight rows over the {size} neighbourhood points, estimated from the net after one level, whose faces \
             and rows grow with the host's faces per face at each further refinement"
        ),
        "use fewer --levels or a smaller valence",
    )
}

/// Level-0 data on the patch: `value(k)` at the k-th analysis vertex, the
/// other patch vertices undefined.
fn on_analysis_vertices<T: Clone>(d: &Discovered, value: impl Fn(usize) -> T) -> Vec<Option<T>> {
    let mut level0 = vec![None; d.patch.num_vertices()];
    for (k, &v) in d.analysis.iter().enumerate() {
        level0[v] = Some(value(k));
    }
    level0
}

/// Refuse up front a net that cannot fit: one step is cheap (it reuses
/// discovery's refinements) and the last level is about the host's
/// faces-per-face to the power of the remaining refinements times as large
/// as that step's net, whose bytes `bytes` estimates.
fn refuse_beyond_memory<T: Combine<f64> + Clone>(
    scheme: &dyn Scheme,
    d: &Discovered,
    level0: &[Option<T>],
    levels: usize,
    bytes: impl Fn(&Net<T>) -> f64,
) -> Result<(), Error> {
    if levels <= 1 {
        return Ok(());
    }
    let first = refine_net(scheme, d, level0.to_vec(), 1)?;
    let refinements = scheme.topology().steps_per_analysis() * (levels - 1);
    let growth = (scheme.topology().faces_per_face() as f64).powi(refinements as i32);
    check_memory(bytes(&first) * growth, levels, d.analysis.len())
}

/// The characteristic ring of a refined net: its faces (descendants of the
/// first ring that are not descendants of the first ring one analysis step
/// later) and their vertices (corners and face points, ascending), every one
/// of them determined by the neighbourhood.
fn ring_of<T>(net: &Net<T>) -> Result<(Vec<usize>, Vec<usize>), Error> {
    let ring_faces: Vec<usize> = (0..net.mesh.num_faces()).filter(|&f| net.outer[f] && !net.inner[f]).collect();
    if ring_faces.is_empty() {
        return Err(Error::Numeric("the characteristic ring is empty at this level".into()));
    }
    let mut ring_vertices: Vec<usize> =
        ring_faces.iter().flat_map(|&f| net.mesh.face(f).iter().copied().chain(net.mesh.face_point(f))).collect();
    ring_vertices.sort_unstable();
    ring_vertices.dedup();
    if ring_vertices.iter().any(|&v| net.points[v].is_none()) {
        return Err(Error::NotDetermined(
            "a vertex of the characteristic ring is not determined by the neighbourhood".into(),
        ));
    }
    Ok((ring_faces, ring_vertices))
}

impl RingSampler {
    /// Refine unit rows `levels` analysis steps.
    /// [`RingSampler::new`], made once per discovery and level count and
    /// shared: the curvature class, the Jordan growth test (at several
    /// levels) and the exact route of one scheme and configuration sample
    /// the same net.
    pub fn shared(scheme: &dyn Scheme, d: &Discovered, levels: usize) -> Result<Arc<Self>, Error> {
        d.derived(levels as u64, || RingSampler::new(scheme, d, levels))
    }

    pub fn new(scheme: &dyn Scheme, d: &Discovered, levels: usize) -> Result<Self, Error> {
        let level0 = on_analysis_vertices(d, SparseRow::<f64>::unit);
        refuse_beyond_memory(scheme, d, &level0, levels, estimate_bytes)?;
        let net = refine_net(scheme, d, level0, levels)?;
        let (ring_faces, ring_vertices) = ring_of(&net)?;
        Ok(RingSampler { net, ring_faces, ring_vertices, size: d.analysis.len() })
    }

    /// The ring size (largest |value| over the ring vertices) of one level-0
    /// function `x` (analysis order) after each of 1, 2, ..., `levels`
    /// analysis steps, refining the function itself rather than unit rows:
    /// for a function sampled once at levels no other question asks for (the
    /// growth test's growing direction at levels 1..5). Entry l − 1 is the
    /// largest |value| of `RingSampler::new(.., l).ring_values(x)`: the same
    /// rules, mesh and pruning, applied to the data instead of the rows.
    ///
    /// On a rotation-symmetric configuration (see [`Sectors`]) only one
    /// sector's share of the first ring is refined, carrying the g turns of
    /// the data at once: the rules commute with the rotation, so the turned
    /// data's values on that sector are the data's values on the other
    /// sectors, and the largest over all of them is the ring size. The net
    /// is then about 1/g of the whole ring's, its connectivity, pruning and
    /// stencils made once for the g functions.
    pub fn ring_sizes_each_level(
        scheme: &dyn Scheme,
        d: &Discovered,
        levels: usize,
        x: &[f64],
    ) -> Result<Vec<f64>, Error> {
        // one value per vertex: the memory is the net's faces
        let level0 = on_analysis_vertices(d, |k| [x[k]]);
        refuse_beyond_memory(scheme, d, &level0, levels, |net| net.mesh.num_faces() as f64 * FACE_BYTES)?;
        let largest = |values: &mut dyn Iterator<Item = f64>| values.map(f64::abs).fold(0.0, f64::max);
        if let Some(sectors) = Sectors::of(scheme, d) {
            let level0 = on_analysis_vertices(d, |k| Turns(sectors.turns.iter().map(|t| x[t[k]]).collect()));
            // one refinement shows every level (the net shown at level l is
            // the one refined to l levels; a level shown again under a wider
            // pruning margin overwrites its value)
            let mut each = vec![0.0; levels];
            refine_net_within_visiting(
                scheme,
                d,
                level0,
                levels,
                &sectors.first_ring,
                &mut |level, net: &Net<Turns>| {
                    let (_, ring_vertices) = ring_of(net)?;
                    each[level - 1] =
                        largest(&mut ring_vertices.iter().flat_map(|&v| {
                            net.points[v].as_ref().expect("ring vertices are defined").0.iter().copied()
                        }));
                    Ok(())
                },
            )?;
            return Ok(each);
        }
        let mut each = vec![0.0; levels];
        refine_net_visiting(scheme, d, level0, levels, &mut |level, net: &Net<[f64; 1]>| {
            let (_, ring_vertices) = ring_of(net)?;
            each[level - 1] =
                largest(&mut ring_vertices.iter().map(|&v| net.points[v].expect("ring vertices are defined")[0]));
            Ok(())
        })?;
        Ok(each)
    }

    /// The value at net vertex `v` of level-0 data `x` (analysis order).
    pub fn value(&self, v: usize, x: &[f64]) -> Option<f64> {
        self.net.points[v].as_ref().map(|r| r.entries.iter().map(|(k, w)| w * x[*k]).sum())
    }

    /// A complex vector's values on the ring vertices.
    pub fn ring_values_c(&self, x: &[c64]) -> Vec<c64> {
        self.ring_vertices
            .iter()
            .map(|&v| {
                let row = self.net.points[v].as_ref().expect("ring vertices are defined");
                row.entries.iter().fold(c64::new(0.0, 0.0), |a, (k, w)| a + x[*k] * *w)
            })
            .collect()
    }

    /// The ring size (largest |value| over the ring vertices) of each of the
    /// real functions `xs`, as `ring_values` gives the values: each value
    /// summed over its row in the row's order. The functions are taken
    /// together, each row entry applied to all of them at once (one pass
    /// over the rows instead of one per function: the growth test sizes
    /// hundreds of iterates on one ring).
    pub fn ring_sizes(&self, xs: &[Vec<f64>]) -> Vec<f64> {
        let m = xs.len();
        // the functions side by side: entry k of every function contiguous
        let mut by_entry = vec![0.0; self.size * m];
        for (j, x) in xs.iter().enumerate() {
            for (k, v) in x.iter().enumerate() {
                by_entry[k * m + j] = *v;
            }
        }
        let mut sizes = vec![0.0f64; m];
        let mut values = vec![0.0f64; m];
        for &v in &self.ring_vertices {
            let row = self.net.points[v].as_ref().expect("ring vertices are defined");
            // the start of `Iterator::sum` for f64 (the sign of a zero is
            // lost to the absolute value anyway)
            values.fill(-0.0);
            for (k, w) in &row.entries {
                for (value, x) in values.iter_mut().zip(&by_entry[k * m..(k + 1) * m]) {
                    *value += w * x;
                }
            }
            for (size, value) in sizes.iter_mut().zip(&values) {
                *size = size.max(value.abs());
            }
        }
        sizes
    }

    /// A real function's values on the ring vertices.
    pub fn ring_values(&self, x: &[f64]) -> Vec<f64> {
        self.ring_vertices.iter().map(|&v| self.value(v, x).unwrap_or(f64::NAN)).collect()
    }

    /// Level-0 points refined to every net vertex (`None` where undefined).
    pub fn points<const D: usize>(&self, data: &[[f64; D]]) -> Vec<Option<[f64; D]>> {
        self.net.evaluate_points(data)
    }

    /// The ring's facets as triangles of net vertex ids.
    pub fn ring_triangles(&self) -> Vec<[usize; 3]> {
        self.ring_faces.iter().flat_map(|&f| facet_triangles(&self.net.mesh, f)).collect()
    }
}

/// Data turned by each rotation of the configuration, refined together: one
/// value per turn at every net vertex.
#[derive(Clone, Debug)]
struct Turns(Vec<f64>);

impl Combine<f64> for Turns {
    /// Each turn's value summed in the terms' order, as `[f64; 1]` sums it.
    fn combine(terms: &[(f64, &Self)]) -> Self {
        let mut out = vec![0.0; terms.first().map_or(0, |(_, t)| t.0.len())];
        for (w, t) in terms {
            for (o, v) in out.iter_mut().zip(&t.0) {
                *o += w * v;
            }
        }
        Turns(out)
    }
}

/// A fundamental domain of the configuration's rotation ρ (order g > 1) in
/// the first ring, and the analysis vertices turned: `turns[k][i]` is the
/// analysis index of ρ^k applied to analysis vertex i. The first-ring faces
/// are the disjoint union of ρ^k(domain), k = 0..g, so a function's
/// refined values on the descendants of ρ^k(domain) are those of the
/// function turned by ρ^k (value at v: the function at ρ^k(v)) on the
/// domain's descendants.
struct Sectors {
    /// per patch face: in the domain
    first_ring: Vec<bool>,
    turns: Vec<Vec<usize>>,
}

impl Sectors {
    /// `None` where there is no rotation, or where it does not act freely on
    /// the first-ring faces (a central face turned onto itself) or does not
    /// map the analysis neighbourhood onto itself: the whole ring is refined
    /// then.
    fn of(scheme: &dyn Scheme, d: &Discovered) -> Option<Sectors> {
        let period = d.config.rotation_period(scheme);
        let rotation = crate::neighbourhood::discovery::Rotation::new(&d.patch, period, true);
        let g = rotation.order();
        if g <= 1 {
            return None;
        }
        let mesh = &*d.patch;
        let mut index = vec![usize::MAX; mesh.num_vertices()];
        for (k, &v) in d.analysis.iter().enumerate() {
            index[v] = k;
        }
        let mut turn = Vec::with_capacity(d.analysis.len());
        for &v in &d.analysis {
            let t = index[rotation.turned(v)?];
            (t != usize::MAX).then_some(())?;
            turn.push(t);
        }
        let mut turns = vec![(0..d.analysis.len()).collect::<Vec<usize>>()];
        for _ in 1..g {
            let last = turns.last().expect("the identity is first");
            turns.push(last.iter().map(|&i| turn[i]).collect());
        }
        // the face a face is turned to: the one with its first side turned,
        // holding every turned corner
        let turned_face = |f: usize| -> Option<usize> {
            let face = mesh.face(f);
            let image: Vec<usize> = face.iter().map(|&v| rotation.turned(v)).collect::<Option<_>>()?;
            let (h, _) = mesh.half_edge(image[0], image[1])?;
            let other = mesh.face(h);
            (other.len() == image.len() && image.iter().all(|v| other.contains(v))).then_some(h)
        };
        let centre: std::collections::HashSet<usize> = centre_set(d).into_iter().collect();
        let mut seen = vec![false; mesh.num_faces()];
        let mut first_ring = vec![false; mesh.num_faces()];
        for f in 0..mesh.num_faces() {
            if seen[f] || !mesh.face(f).iter().any(|v| centre.contains(v)) {
                continue;
            }
            first_ring[f] = true;
            let mut orbit = vec![f];
            let mut at = turned_face(f)?;
            while at != f {
                orbit.push(at);
                at = turned_face(at)?;
                (orbit.len() <= g).then_some(())?;
            }
            (orbit.len() == g).then_some(())?;
            for o in orbit {
                seen[o] = true;
            }
        }
        Some(Sectors { first_ring, turns })
    }
}
