//! Dual split (Doo–Sabin and other dual schemes): a new vertex near every face
//! corner; F-faces shrink the old faces, E-faces sit on interior edges,
//! V-faces on interior vertices.
//!
//! The host unit (`Host::Dual`, scheme files `topology = "dual"`): one rule,
//! the new vertex near a face corner over the face's corners. Regular part:
//! the biquadratic B-spline (binary dual refinement of quads).

use crate::error::Error;
use crate::mesh::FaceList;
use crate::mesh::PolyMesh;
use crate::mesh::SectorKind;
use crate::mesh::Tags;
use crate::sdc::host::{refuse_tags, Refined, RefinementHost, RegularSpline};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::Corner as C;
use crate::sdc::slots::{canonical, fam, unsupported, Gather, Gathered, HostSpec, Part, RuleSlots, Wants, PER_J};
use crate::sdc::CentreKind;
use crate::sdc::Origin;
use crate::topology::chart_builder::ChartBuilder;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    // the new point at corner k of face f is number start[f] + k: face
    // corners are numbered in face order, so no map from (face, vertex) is
    // needed (a half-edge look-up gives the corner of a vertex in a face)
    let mut start = Vec::with_capacity(mesh.num_faces() + 1);
    let mut origins = Vec::new();
    for (f, face) in mesh.faces().iter().enumerate() {
        start.push(origins.len());
        origins.extend((0..face.len()).map(|k| Origin::Corner { face: f, corner: k }));
    }
    let corner = |f: usize, k: usize| start[f] + k % mesh.face(f).len();
    let face_count = mesh.num_faces() + origins.len() + mesh.num_vertices();
    // each old corner is a corner of its F-face, of two E-faces and of a V-face
    let mut faces = FaceList::with_capacity(face_count, 4 * origins.len());
    let mut parents = Vec::with_capacity(face_count);
    for (f, face) in mesh.faces().iter().enumerate() {
        faces.push_iter((0..face.len()).map(|k| corner(f, k)));
        parents.push(Origin::Face(f));
    }
    for (a, b) in mesh.edges() {
        // f holds a -> b with a at corner ka (b at ka + 1), g holds b -> a
        let (Some((f, ka)), Some((g, kb))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
            continue;
        };
        faces.push(&[corner(f, ka + 1), corner(f, ka), corner(g, kb + 1), corner(g, kb)]);
        parents.push(Origin::Edge(a, b));
    }
    for v in 0..mesh.num_vertices() {
        let Some(fan) = mesh.fan_corners(v) else {
            continue;
        };
        faces.push_iter(fan.iter().map(|&(f, k)| corner(f, k)));
        parents.push(Origin::Vertex(v));
    }
    let mut new_mesh = PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?;
    if let Some(chart) = mesh.chart.as_ref().filter(|c| c.scale == 1) {
        let mut cb = ChartBuilder::new(chart);
        for o in &origins {
            let Origin::Corner { face: f, corner: k } = *o else { unreachable!() };
            let face = mesh.face(f);
            let v = face[k];
            // new corner = face centre + corner, in the face's chart (lattice doubles)
            match chart.face_sector[f] {
                None => {
                    let c = chart.vertex_coords[v];
                    cb.push(c.sector, c.i, c.j);
                }
                Some(s) => {
                    let pts: Vec<(i64, i64)> =
                        face.iter().map(|&u| chart.in_chart(chart.vertex_coords[u], s)).collect();
                    let m = pts.len() as i64;
                    let (si, sj) = pts.iter().fold((0, 0), |a, p| (a.0 + p.0, a.1 + p.1));
                    if si % m != 0 || sj % m != 0 {
                        cb.ok = false;
                    }
                    cb.push(s, si / m + pts[k].0, sj / m + pts[k].1);
                }
            }
        }
        for p in &parents {
            let sector = match *p {
                Origin::Face(f) => chart.face_sector[f],
                Origin::Edge(a, b) => {
                    let (f, _) = mesh.half_edge(a, b).expect("edge");
                    Some(chart.face_sector[f].unwrap_or(chart.vertex_coords[a].sector))
                }
                Origin::Vertex(v) => {
                    let c = chart.vertex_coords[v];
                    if c.is_centre() {
                        None
                    } else {
                        Some(c.sector)
                    }
                }
                Origin::Corner { .. } => unreachable!(),
            };
            cb.face_sector.push(sector);
        }
        new_mesh.chart = cb.finish(1);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: parents })
}

/// The host unit: everything the engine asks of this host.
pub struct DualSplit;

static SPEC: HostSpec = HostSpec {
    host: Host::Dual,
    name: "dual",
    sector: SectorKind::Quad,
    centre: CentreKind::Face,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for DualSplit {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        refine(mesh)
    }
    fn refine_tags(&self, mesh: &PolyMesh, _: &[Origin]) -> Result<Option<Tags>, Error> {
        refuse_tags(Host::Dual, mesh)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, _wants: &dyn Wants) -> Gather {
        match origin {
            Origin::Corner { face, corner } => {
                let cyc = mesh.face_from(face, corner);
                let mut p = Part::new("corner", cyc.len());
                cyc.iter().enumerate().for_each(|(j, &c)| p.put("corner", j, c));
                Ok(Gathered::one(p))
            }
            Origin::Vertex(_) | Origin::Edge(..) | Origin::Face(_) => unsupported(Host::Dual, origin),
        }
    }
    fn steps_per_analysis(&self) -> usize {
        1
    }
    fn growth_per_level(&self) -> usize {
        4
    }
    fn size_bound(&self, mesh: &PolyMesh) -> usize {
        let corners: usize = mesh.faces().iter().map(|f| f.len()).sum();
        let (v, e, f) = (mesh.num_vertices(), mesh.edges().len(), mesh.num_faces());
        // one vertex per corner; F-, E- and V-faces
        corners.max(f + e + v)
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed mesh"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::BinaryDual
    }
}

const RULES: &[RuleSlots] = &[canonical(
    "corner",
    C,
    &[fam("corner", PER_J, "c_j, the face's corners counter-clockwise from c_0, the corner itself")],
    false,
    "the new vertex near corner c_0 of an n-gon",
)];

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, quad_torus};
    use super::*;

    /// A face per old face, edge and vertex: F + E + V = F + 2F + F on a
    /// quad torus.
    #[test]
    fn states_its_growth_bound_and_rules() {
        check_host(Host::Dual, &quad_torus(4, 5), 20 + 40 + 20, true);
    }
}
