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

use crate::charmap::net::{facet_triangles, refine_net, refine_net_visiting, Net};
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

    /// The ring values of one level-0 function `x` (analysis order) after
    /// each of 1, 2, ..., `levels` analysis steps, refining the function
    /// itself rather than unit rows (a single value per vertex instead of a
    /// row over the neighbourhood) and once for all levels: for a function
    /// sampled once at levels no other question asks for (the growth test's
    /// growing direction at levels 1..5). Entry l − 1 equals
    /// `RingSampler::new(.., l).ring_values(x)`: the same rules, mesh and
    /// pruning, applied to the data instead of the rows.
    pub fn ring_values_each_level(
        scheme: &dyn Scheme,
        d: &Discovered,
        levels: usize,
        x: &[f64],
    ) -> Result<Vec<Vec<f64>>, Error> {
        let level0 = on_analysis_vertices(d, |k| [x[k]]);
        // one value per vertex: the memory is the net's faces
        refuse_beyond_memory(scheme, d, &level0, levels, |net| net.mesh.num_faces() as f64 * FACE_BYTES)?;
        let mut each = vec![Vec::new(); levels];
        refine_net_visiting(scheme, d, level0, levels, &mut |level, net: &Net<[f64; 1]>| {
            let (_, ring_vertices) = ring_of(net)?;
            each[level - 1] =
                ring_vertices.iter().map(|&v| net.points[v].expect("ring vertices are defined")[0]).collect();
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
