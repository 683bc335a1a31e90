//! Dual split of point-augmented meshes (point-augmented bi-2 subdivision,
//! PGS): the Doo–Sabin split, plus a central point in the shrunken copy
//! (F-face) of every face that carries one or is not a quad. A face without a
//! point gets one at its first refinement (the scheme's rule then defines the
//! missing old point from the net, as PGS's eq. (1) does).
//!
//! New central points have origin `Face(f)`. Charts: the centre of a central
//! face is the origin (0, 0); any other face's point is the centroid of its
//! refined F-face, which must be a lattice point.
//!
//! The host unit (`Host::AugmentedDual`, scheme files `topology =
//! "augmented-dual"`): the corner rule of a plain quad, the corner rule of a
//! face with a central point, the new central point, and the `point` rule
//! that derives a central point from the net. Regular part: the biquadratic
//! B-spline (binary dual refinement of quads without central points).

use crate::error::Error;
use crate::mesh::FaceId;
use crate::mesh::SectorKind;
use crate::mesh::Tags;
use crate::mesh::{LatticeCoord, PolyMesh};
use crate::sdc::host::{refuse_tags, Refined, RefinementHost, RegularSpline};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Corner as C, Face as F};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    face_corners, fam, fan, quad_corner, rule, unsupported, Arity, Gather, GatherError, Gathered, HostSpec, Part,
    RuleSlots, Target, Wants, ONE, PER_J,
};
use crate::sdc::CentreKind;
use crate::sdc::Origin;
use crate::topology::dual_split;

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    let base = dual_split::refine(mesh)?;
    // dual_split emits the F-face of old face f as new face f
    if (0..mesh.num_faces()).any(|f| base.face_parents.get(f) != Some(&Origin::Face(f))) {
        return Err(Error::Input("dual split: F-faces are not first in face order".to_string()));
    }
    let mut origins = base.vertex_origins;
    let faces = base.mesh.faces().clone();
    let mut centres = vec![None; faces.len()];
    for (f, centre) in centres.iter_mut().enumerate().take(mesh.num_faces()) {
        if mesh.face_point(f).is_some() || mesh.face(f).len() != 4 {
            *centre = Some(origins.len());
            origins.push(Origin::Face(f));
        }
    }
    let mut new_mesh =
        PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?.with_face_points(centres)?;
    if let (Some(old), Some(mut chart)) = (mesh.chart.as_ref(), base.mesh.chart) {
        let mut ok = true;
        for o in &origins[chart.vertex_coords.len()..] {
            let Origin::Face(f) = *o else { unreachable!("only central points are added") };
            let c = match old.face_sector[f] {
                None => LatticeCoord::CENTRE,
                Some(s) => {
                    let corners = new_mesh.face(f);
                    let (si, sj) = corners.iter().fold((0, 0), |a, &v| {
                        let p = chart.in_chart(chart.vertex_coords[v], s);
                        (a.0 + p.0, a.1 + p.1)
                    });
                    let m = corners.len() as i64;
                    ok &= si % m == 0 && sj % m == 0;
                    chart.canonical(s, si / m, sj / m).unwrap_or(LatticeCoord::CENTRE)
                }
            };
            chart.vertex_coords.push(c);
        }
        new_mesh.chart = ok.then_some(chart);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: base.face_parents })
}

/// The host unit: everything the engine asks of this host.
pub struct AugmentedDual;

static SPEC: HostSpec = HostSpec {
    host: Host::AugmentedDual,
    name: "augmented-dual",
    sector: SectorKind::Quad,
    centre: CentreKind::AugmentedFace,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for AugmentedDual {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        refine(mesh)
    }
    fn refine_tags(&self, mesh: &PolyMesh, _: &[Origin]) -> Result<Option<Tags>, Error> {
        refuse_tags(Host::AugmentedDual, mesh)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, _wants: &dyn Wants) -> Gather {
        match origin {
            Origin::Corner { face, corner } => {
                let c = mesh.face_from(face, corner);
                if !augmented(mesh, face) {
                    // a Doo–Sabin net has valence-4 vertices only (a vertex on
                    // the rim of a truncated patch has no fan: allowed)
                    if mesh.valence(c[0]).is_some_and(|k| k != 4) {
                        return Err(GatherError::NotCovered);
                    }
                    return Ok(Gathered::one(quad_corner("corner", "vertex", &c)));
                }
                let mut p = Part::new("corner-augmented", c.len());
                p.put("vertex", 0, c[0]);
                p.put("side", 0, c[1]);
                p.put("side", 1, c[c.len() - 1]);
                p.put_target("point", central_point(mesh, face)?);
                Ok(Gathered::one(p))
            }
            Origin::Face(f) => {
                let mut p = face_corners("face", mesh, f);
                p.put_target("point", central_point(mesh, f)?);
                Ok(Gathered::one(p))
            }
            Origin::Vertex(_) | Origin::Edge(..) => unsupported(Host::AugmentedDual, origin),
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
        // the dual split plus at most one central point per face
        corners.max(f + e + v) + f
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed mesh whose vertices all have valence 4 (a Doo–Sabin net: apply one doo-sabin step first)"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::BinaryDual
    }
}

const RULES: &[RuleSlots] = &[
    rule(
        "corner",
        C,
        Fixed(4),
        &[
            fam("vertex", ONE, "the corner c_0 (valence 4)"),
            fam("side", Arity::Fixed(2), "the corners c_1 and c_3 next to it"),
            fam("far", ONE, "the opposite corner c_2"),
        ],
        "the new vertex near corner c_0 of a quad without a central point",
    ),
    rule(
        "corner-augmented",
        C,
        Any,
        &[
            fam("vertex", ONE, "the corner c_0"),
            fam("side", Arity::Fixed(2), "the corners c_1 and c_{n-1} next to it"),
            fam("point", ONE, "the face's central point (or the [point] rule's point)"),
        ],
        "the new vertex near corner c_0 of an n-gon with a central point (or not a quad)",
    ),
    rule(
        "face",
        F,
        Any,
        &[
            fam("point", ONE, "the face's central point (or the [point] rule's point)"),
            fam("corner", PER_J, "corner j of the n-gon"),
        ],
        "the new central point of an n-gon",
    ),
    rule(
        "point",
        F,
        Any,
        &[
            fam("corner", PER_J, "corner a_j of the n-gon"),
            fam("outer", Arity::PerJ(2), "the two neighbours of a_j that are not corners of the face"),
        ],
        "the central point of an n-gon that has none, from the net (all corners valence 4)",
    ),
];

/// Whether a face of a point-augmented net carries (or gets) a central point.
fn augmented(mesh: &PolyMesh, f: FaceId) -> bool {
    mesh.face_point(f).is_some() || mesh.face(f).len() != 4
}

/// The central point of face f: its own point, or the `point` rule over the
/// net (corners a_j of valence 4 and their two neighbours off the face).
fn central_point(mesh: &PolyMesh, f: FaceId) -> Result<Target, GatherError> {
    if let Some(p) = mesh.face_point(f) {
        return Ok(Target::Vertex(p));
    }
    let face = mesh.face(f);
    let m = face.len();
    let mut p = Part::new("point", m);
    for (k, &a) in face.iter().enumerate() {
        let (prev, next) = (face[(k + m - 1) % m], face[(k + 1) % m]);
        let fan = fan(mesh, a)?;
        if fan.len() != 4 {
            return Err(GatherError::NotCovered);
        }
        p.put("corner", k, a);
        for cyc in fan.iter().filter(|c| c[1] != prev && c[1] != next) {
            p.put("outer", k, cyc[1]);
        }
    }
    Ok(Target::Derived(Box::new(p)))
}

#[cfg(test)]
mod tests {
    use super::super::host_tests::{check_host, quad_torus};
    use super::*;

    /// A net of valence-4 vertices without central points splits as the dual
    /// split does: F + E + V faces.
    #[test]
    fn states_its_growth_bound_and_rules() {
        check_host(Host::AugmentedDual, &quad_torus(4, 5), 20 + 40 + 20, true);
    }
}
