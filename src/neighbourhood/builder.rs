//! Generous patches: `rings` rings of regular lattice around the centre, with
//! lattice charts. Vertex-centred patches glue n lattice wedges (quad or
//! triangle, per sector); face-centred patches surround a central n-gon with
//! quads (coordinates doubled so that vertices sit at odd lattice points),
//! with an extra point at the origin for point-augmented faces; polar patches
//! put a pole in a fan of triangles and rings of quads, every vertex on a spoke
//! at (spoke, ring, 0).
//! With face control vertices (non-box subdivision) every quad also gets an FCV
//! at its centre; coordinates are doubled there too (chart scale 2), vertices at
//! even and FCVs at odd lattice points.

use crate::mesh::IdMap;

use super::configuration::{Configuration, Tagging};
use crate::mesh::{Chart, LatticeCoord, PolyMesh, SectorKind, Tags};
use crate::sdc::CentreKind;

struct PatchBuilder {
    chart: Chart,
    ids: IdMap<LatticeCoord, usize>,
    faces: Vec<Vec<usize>>,
}

impl PatchBuilder {
    fn vertex(&mut self, s: usize, i: i64, j: i64) -> usize {
        let c = self.chart.canonical(s, i, j).expect("patch points lie in adjacent wedges");
        if let Some(&id) = self.ids.get(&c) {
            return id;
        }
        let id = self.chart.vertex_coords.len();
        self.chart.vertex_coords.push(c);
        self.ids.insert(c, id);
        id
    }
    fn face(&mut self, sector: Option<usize>, corners: &[(usize, i64, i64)]) {
        let f = corners.iter().map(|&(s, i, j)| self.vertex(s, i, j)).collect();
        self.faces.push(f);
        self.chart.face_sector.push(sector);
    }
}

/// Returns the patch and its ring-0 vertices (the centre vertex, or the
/// corners of the central face).
pub fn build_patch(config: &Configuration, rings: usize) -> (PolyMesh, Vec<usize>) {
    let n = config.valence();
    let r = rings as i64;
    // lattice points are doubled when FCVs sit at face centres
    let k: i64 = if config.face_control { 2 } else { 1 };
    // an open (boundary or corner) fan gets empty chart sectors after its
    // last, so that its last ray is not sector 0's (`Configuration::chart_sectors`)
    let mut sector_kinds = config.sectors.clone();
    let last = *config.sectors.last().expect("a configuration has a sector");
    sector_kinds.resize(config.chart_sectors(), last);
    let mut b = PatchBuilder {
        chart: Chart { sector_kinds, scale: k, vertex_coords: Vec::new(), face_sector: Vec::new() },
        ids: IdMap::default(),
        faces: Vec::new(),
    };
    let centre_set = match config.centre {
        CentreKind::Vertex => {
            let c = b.vertex(0, 0, 0);
            for s in 0..n {
                match config.sectors[s] {
                    SectorKind::Quad => {
                        for a in 0..r {
                            for c in 0..r {
                                let (x, y) = (k * a, k * c);
                                b.face(Some(s), &[(s, x, y), (s, x + k, y), (s, x + k, y + k), (s, x, y + k)]);
                            }
                        }
                    }
                    SectorKind::Tri => {
                        for a in 0..r {
                            for c in 0..r - a {
                                b.face(Some(s), &[(s, a, c), (s, a + 1, c), (s, a, c + 1)]);
                                if a + c + 2 <= r {
                                    b.face(Some(s), &[(s, a + 1, c), (s, a + 1, c + 1), (s, a, c + 1)]);
                                }
                            }
                        }
                    }
                }
            }
            vec![c]
        }
        CentreKind::Polar => {
            // the pole, a fan of n triangles and r rings of n quads, all
            // vertices on the spokes (spoke, ring, 0)
            let c = b.vertex(0, 0, 0);
            for s in 0..n {
                b.face(Some(s), &[(s, 0, 0), (s, 1, 0), (s + 1, 1, 0)]);
                for a in 1..=r {
                    b.face(Some(s), &[(s, a, 0), (s, a + 1, 0), (s + 1, a + 1, 0), (s + 1, a, 0)]);
                }
            }
            vec![c]
        }
        CentreKind::Face | CentreKind::AugmentedFace => {
            let corners: Vec<_> = (0..n).map(|s| (s, 1, 1)).collect();
            b.face(None, &corners);
            for s in 0..n {
                for a in 1..=r {
                    for c in 0..=r {
                        let (x, y) = (2 * a, 2 * c);
                        b.face(Some(s), &[(s, x - 1, y - 1), (s, x + 1, y - 1), (s, x + 1, y + 1), (s, x - 1, y + 1)]);
                    }
                }
            }
            let mut ring0 = b.faces[0].clone();
            if config.centre == CentreKind::AugmentedFace {
                // the central face's extra point sits at the origin
                ring0.push(b.vertex(0, 0, 0));
            }
            ring0
        }
    };
    let mut fcv = Vec::new();
    if config.face_control {
        // one FCV per (quad) face, at its centre
        for f in 0..b.faces.len() {
            let s = b.chart.face_sector[f].expect("vertex-centred quad patches have no central face");
            let corners: Vec<(i64, i64)> =
                b.faces[f].iter().map(|&v| b.chart.in_chart(b.chart.vertex_coords[v], s)).collect();
            let (si, sj) = corners.iter().fold((0, 0), |a, p| (a.0 + p.0, a.1 + p.1));
            fcv.push(b.vertex(s, si / 4, sj / 4));
        }
    }
    let tags = config.tagging.map(|t| ray_tags(&b, t, n, rings as i64));
    let mut mesh = PolyMesh::new(b.chart.vertex_coords.len(), b.faces).expect("patch is a manifold disc");
    if config.face_control {
        mesh = mesh.with_face_points(fcv.into_iter().map(Some).collect()).expect("one FCV per face");
    }
    if config.centre == CentreKind::AugmentedFace {
        let mut centres = vec![None; mesh.num_faces()];
        centres[0] = centre_set.last().copied();
        mesh = mesh.with_face_points(centres).expect("the centre is a vertex of no face");
    }
    mesh.tags = tags;
    mesh.chart = Some(b.chart);
    (mesh, centre_set)
}

/// The tags of a tagged configuration's patch: its sharp rays (the edges
/// from the centre out along the i-axis of each sharp sector, as far as the
/// patch reaches) and, at a corner, the centre. The patch's outer rim stays
/// untagged: it is where the patch was cut off, not a boundary.
fn ray_tags(b: &PatchBuilder, tagging: Tagging, n: usize, rings: i64) -> Tags {
    let mut tags = Tags::new();
    for s in tagging.sharp_rays(n) {
        let at = |i: i64| b.chart.canonical(s, i, 0).and_then(|c| b.ids.get(&c).copied());
        for i in 0..rings {
            if let (Some(p), Some(q)) = (at(i), at(i + 1)) {
                tags.mark_sharp(p, q);
            }
        }
    }
    if tagging == Tagging::Corner {
        let centre = b.ids[&LatticeCoord::CENTRE];
        tags.mark_corner(centre);
    }
    tags
}
