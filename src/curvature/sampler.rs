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

use crate::charmap::net::{facet_triangles, refine_net, Net};
use crate::error::Error;
use crate::neighbourhood::Discovered;
use crate::refine::SparseRow;
use crate::sdc::Scheme;

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

impl RingSampler {
    /// Refine unit rows `levels` analysis steps.
    pub fn new(scheme: &dyn Scheme, d: &Discovered, levels: usize) -> Result<Self, Error> {
        let mut level0 = vec![None; d.patch.num_vertices()];
        for (k, &v) in d.analysis.iter().enumerate() {
            level0[v] = Some(SparseRow::<f64>::unit(k));
        }
        let net = refine_net(scheme, d, level0, levels)?;
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
        Ok(RingSampler { net, ring_faces, ring_vertices, size: d.analysis.len() })
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
        self.net
            .points
            .iter()
            .map(|r| {
                r.as_ref().map(|r| {
                    let mut p = [0.0; D];
                    for (k, w) in &r.entries {
                        for (c, x) in p.iter_mut().zip(&data[*k]) {
                            *c += w * x;
                        }
                    }
                    p
                })
            })
            .collect()
    }

    /// The ring's facets as triangles of net vertex ids.
    pub fn ring_triangles(&self) -> Vec<[usize; 3]> {
        self.ring_faces.iter().flat_map(|&f| facet_triangles(&self.net.mesh, f)).collect()
    }
}
