//! Quadrilateral split with face control vertices (Huang's non-box
//! subdivision viewed as a quad scheme): like Catmull–Clark's split, each
//! k-gon becomes k quads around a new vertex at its centre; that vertex is the
//! face's old FCV moved by the FCV rule, and every new quad gets a new FCV
//! (NFCV) of its own.
//!
//! New vertices: `Vertex(v)` for old corner vertices (V-vertices), `Edge` for
//! edges (E-vertices), `Face(f)` for the updated FCV of f, and
//! `Corner { face: f, corner: k }` for the NFCV of the new quad at corner k.
//! Charts use doubled lattice coordinates (scale 2): vertices at even, FCVs at
//! odd points.
//!
//! The host unit (`Host::Fcv`, scheme files `topology = "fcv"`): meshes carry
//! a face control vertex (FCV) per face; its rules are the vertex, edge, FCV
//! (face) and new-quad FCV (corner) rules. Regular part: the four-directional
//! S_3^1 non-box spline (`certify::s31`).

use crate::error::Error;
use crate::mesh::FaceList;
use crate::mesh::PolyMesh;
use crate::mesh::SectorKind;
use crate::mesh::Tags;
use crate::mesh::VertexId;
use crate::sdc::host::{refuse_tags, Refined, RefinementHost, RegularSpline};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Corner as C, Edge as E, Face as F, Vertex as V};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    face_corners, fam, fan, rule, Arity, Gather, GatherError, Gathered, HostSpec, Part, RuleSlots, Wants, ONE, PER_J,
};
use crate::sdc::CentreKind;
use crate::sdc::Origin;
use crate::topology::chart_builder::ChartBuilder;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    if !mesh.has_face_point_on_every_face() {
        return Err(Error::Input("this scheme needs a face control vertex on every face".into()));
    }
    let fcv: Vec<usize> = mesh.face_points.iter().flatten().copied().collect();
    let is_fcv: crate::mesh::IdSet<usize> = fcv.iter().copied().collect();
    let mut origins: Vec<Origin> = Vec::new();
    let mut vertex_id = vec![usize::MAX; mesh.num_vertices()];
    for (v, id) in vertex_id.iter_mut().enumerate() {
        if !is_fcv.contains(&v) {
            *id = origins.len();
            origins.push(Origin::Vertex(v));
        }
    }
    // the edge points in edge order, found from a face's sides by number
    let numbering = mesh.edge_numbering();
    let edge_base = origins.len();
    origins.extend(numbering.edges.iter().map(|&(a, b)| Origin::Edge(a, b)));
    let face_id: Vec<usize> = (0..mesh.num_faces())
        .map(|f| {
            origins.push(Origin::Face(f));
            origins.len() - 1
        })
        .collect();
    let corners = mesh.faces().corners().len();
    let mut faces = FaceList::with_capacity(corners, 4 * corners);
    let mut parents = Vec::with_capacity(corners);
    let mut new_fcv = Vec::with_capacity(corners);
    for (f, face) in mesh.faces().iter().enumerate() {
        let m = face.len();
        for k in 0..m {
            faces.push(&[
                vertex_id[face[k]],
                edge_base + numbering.side(f, k),
                face_id[f],
                edge_base + numbering.side(f, (k + m - 1) % m),
            ]);
            parents.push(Origin::Face(f));
            new_fcv.push(Some(origins.len()));
            origins.push(Origin::Corner { face: f, corner: k });
        }
    }
    let mut new_mesh =
        PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?.with_face_points(new_fcv)?;
    if let Some(chart) = mesh.chart.as_ref().filter(|c| c.scale == 2) {
        let mut cb = ChartBuilder::new(chart);
        let in_face = |f: usize| -> (usize, Vec<(i64, i64)>) {
            let s = chart.face_sector[f].expect("FCV patches have no central face");
            (s, mesh.face(f).iter().map(|&v| chart.in_chart(chart.vertex_coords[v], s)).collect())
        };
        for o in &origins {
            match *o {
                Origin::Vertex(v) => cb.push_scaled(v, 2),
                Origin::Edge(a, b) => cb.push_on_edge(mesh, a, b, 1, 1)?,
                Origin::Face(f) => {
                    let (s, p) = in_face(f);
                    let sum = p.iter().fold((0, 0), |a, q| (a.0 + q.0, a.1 + q.1));
                    let m = p.len() as i64;
                    if (2 * sum.0) % m != 0 || (2 * sum.1) % m != 0 {
                        cb.ok = false;
                    }
                    cb.push(s, 2 * sum.0 / m, 2 * sum.1 / m);
                }
                Origin::Corner { face: f, corner: k } => {
                    // centre of the new quad (V-vertex, E-vertex, face vertex, E-vertex)
                    let (s, p) = in_face(f);
                    let m = p.len();
                    let sum = p.iter().fold((0, 0), |a, q| (a.0 + q.0, a.1 + q.1));
                    let (v, next, prev) = (p[k], p[(k + 1) % m], p[(k + m - 1) % m]);
                    let mm = m as i64;
                    let x = 2 * v.0 + (v.0 + next.0) + 2 * sum.0 / mm + (prev.0 + v.0);
                    let y = 2 * v.1 + (v.1 + next.1) + 2 * sum.1 / mm + (prev.1 + v.1);
                    if x % 4 != 0 || y % 4 != 0 {
                        cb.ok = false;
                    }
                    cb.push(s, x / 4, y / 4);
                }
            }
        }
        for p in &parents {
            let Origin::Face(f) = *p else { unreachable!() };
            cb.face_sector.push(chart.face_sector[f]);
        }
        new_mesh.chart = cb.finish(2);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: parents })
}

/// The host unit: everything the engine asks of this host.
pub struct FcvSplit;

static SPEC: HostSpec = HostSpec {
    host: Host::Fcv,
    name: "fcv",
    sector: SectorKind::Quad,
    centre: CentreKind::Vertex,
    face_control: true,
    rules: RULES,
};

impl RefinementHost for FcvSplit {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        refine(mesh)
    }
    fn refine_tags(&self, mesh: &PolyMesh, _: &[Origin]) -> Result<Option<Tags>, Error> {
        refuse_tags(Host::Fcv, mesh)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, _wants: &dyn Wants) -> Gather {
        fcv(mesh, origin).map(Gathered::one)
    }
    fn steps_per_analysis(&self) -> usize {
        1
    }
    fn growth_per_level(&self) -> usize {
        4
    }
    fn size_bound(&self, mesh: &PolyMesh) -> usize {
        let corners: usize = mesh.faces().iter().map(|f| f.len()).sum();
        let (v, e) = (mesh.num_vertices(), mesh.edges().len());
        // one quad per corner; old vertices (the old FCVs become the face
        // points), one per edge, one new FCV per new quad
        corners.max(v + e + corners)
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed mesh"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::NonBoxS31
    }
}

const RULES: &[RuleSlots] = &[
    rule(
        "vertex",
        V,
        Any,
        &[fam("centre", ONE, "the vertex v"), fam("fcv", PER_J, "the FCV of fan face j")],
        "the new vertex point of v (valence n)",
    ),
    rule(
        "edge",
        E,
        Fixed(4),
        &[
            fam("ends", Arity::Fixed(2), "the edge's two ends"),
            fam("fcv", Arity::Fixed(2), "the FCVs of its two faces"),
        ],
        "the new edge point",
    ),
    rule(
        "face",
        F,
        Any,
        &[fam("centre", ONE, "the face's old FCV"), fam("corner", PER_J, "corner j of the n-gon")],
        "the new FCV of an old n-gon",
    ),
    rule(
        "corner",
        C,
        Any,
        &[
            fam("vertex", ONE, "the corner V_0"),
            fam("fcv", ONE, "the FCV of the face F_0"),
            fam("side", Arity::Fixed(2), "the FCVs of F_0's two neighbours at V_0"),
        ],
        "the FCV of the new quad at corner V_0 of face F_0 (an n-gon)",
    ),
];

fn fcv(mesh: &PolyMesh, origin: Origin) -> Result<Part, GatherError> {
    if !mesh.has_face_point_on_every_face() {
        return Err(GatherError::NotCovered);
    }
    let point = |a: VertexId, b: VertexId| mesh.face_point_left_of(a, b).ok_or(GatherError::Truncated);
    match origin {
        Origin::Vertex(v) => {
            let fan = fan(mesh, v)?;
            let mut p = Part::around("vertex", fan.len(), v);
            p.put("centre", 0, v);
            for (j, cyc) in fan.iter().enumerate() {
                p.put("fcv", j, point(v, cyc[1])?);
            }
            Ok(p)
        }
        Origin::Edge(a, b) => {
            let mut p = Part::new("edge", 4);
            p.put("ends", 0, a);
            p.put("ends", 1, b);
            p.put("fcv", 0, point(a, b)?);
            p.put("fcv", 1, point(b, a)?);
            Ok(p)
        }
        Origin::Face(f) => {
            let mut p = face_corners("face", mesh, f);
            p.put("centre", 0, mesh.face_point(f).ok_or(GatherError::Truncated)?);
            Ok(p)
        }
        Origin::Corner { face: f, corner: k } => {
            let cyc = mesh.face_from(f, k);
            let (v0, next, prev) = (cyc[0], cyc[1], cyc[cyc.len() - 1]);
            let mut p = Part::new("corner", cyc.len());
            p.put("vertex", 0, v0);
            p.put("fcv", 0, mesh.face_point(f).ok_or(GatherError::Truncated)?);
            // the old faces at V_0 next to F_0: across (V_0, next) and across (prev, V_0)
            p.put("side", 0, point(next, v0)?);
            p.put("side", 1, point(v0, prev)?);
            Ok(p)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, quad_torus};
    use super::*;

    /// Every quad becomes one quad per corner around its FCV.
    #[test]
    fn states_its_growth_bound_and_rules() {
        let torus = quad_torus(4, 5);
        let (nv, nf) = (torus.num_vertices(), torus.num_faces());
        let with_fcvs = PolyMesh::new(nv + nf, torus.faces().to_vec())
            .unwrap()
            .with_face_points((0..nf).map(|f| Some(nv + f)).collect())
            .unwrap();
        check_host(Host::Fcv, &with_fcvs, 4 * 20, true);
    }
}
