//! Refining a real mesh with a scheme: the same topology operators and the same
//! stencils (`SchemeWeight::stencil`) that assemble the local subdivision
//! matrix, applied here to 3-D points. No rule is restated in this file, so a
//! refined mesh and the matrix analysis cannot disagree about the scheme.
//!
//! An open edge must be tagged sharp (`PolyMesh::tag_open_edges`: a real open
//! mesh's boundary, which the `refine` command tags on reading); an untagged
//! one is a cut, and the mesh is refused. A tagged mesh (boundaries, creases,
//! corners: `mesh::tags`) needs a host with boundary/crease rules (the primal
//! quad and triangle hosts) and a scheme that weighs them (Catmull–Clark,
//! Loop, scheme files with the `[vertex-crease]`, `[vertex-corner]` and
//! `[edge-crease]` rules); the tags are refined with the mesh. Any vertex,
//! edge or face where a rule does not apply (a face type the scheme does not
//! cover, e.g. a quad for Loop; a tagged vertex whose rule the scheme lacks)
//! is reported by name, with the reason the host's gatherer gave
//! (`GatherError`), instead of being guessed.

use super::{apply, step, GatherError, Origin, Stencil, Step, StepStencil};
use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::sdc::Scheme;

/// Most refinement levels accepted in one call.
pub const MAX_LEVELS: usize = 12;
/// Largest refined mesh produced (faces, and also vertices): about a gigabyte of
/// connectivity at the peak, which bounds memory and run time of a refinement.
pub const MAX_REFINED_FACES: usize = 2_000_000;

/// Refine `mesh` (positions `points`) `levels` times with `scheme`.
/// Vertex numbers in error messages are 1-based, as in the OBJ file.
pub fn refine_mesh(
    scheme: &dyn Scheme,
    mesh: &PolyMesh,
    points: &[[f64; 3]],
    levels: usize,
) -> Result<(PolyMesh, Vec<[f64; 3]>), Error> {
    if levels == 0 || levels > MAX_LEVELS {
        return Err(Error::Input(format!("the number of levels must be between 1 and {MAX_LEVELS}, got {levels}")));
    }
    if points.len() != mesh.num_vertices() {
        return Err(Error::Input(format!("{} positions for {} vertices", points.len(), mesh.num_vertices())));
    }
    // Doo–Sabin's corner rule would happily shrink an open mesh away from its
    // boundary; without boundary rules that is not the scheme, so every scheme
    // requires a closed mesh
    // (a tagged boundary is a boundary: its edges are sharp)
    if let Some((a, b)) = mesh.edges().into_iter().find(|&(a, b)| !mesh.is_interior_edge(a, b) && !mesh.is_sharp(a, b))
    {
        return Err(Error::Input(format!(
            "{} needs {}: vertex {} is on the boundary (edge {}-{} has a face on one side only) and the boundary \
             is not tagged (an untagged open edge is a cut: tag it, as `subdlab refine` does, where the scheme \
             has boundary rules){}",
            scheme.name(),
            requirement(scheme),
            a + 1,
            a + 1,
            b + 1,
            scheme.boundary_note().map(|n| format!(" ({n})")).unwrap_or_default()
        )));
    }
    // refuse before any work: tags on a host without boundary/crease rules,
    // the first level's size, then the host's growth per level
    let host = scheme.topology();
    host.check_tags(mesh).map_err(|e| e.context(scheme.name()))?;
    let estimate = (1..levels).fold(host.size_bound(mesh), |size, _| size.saturating_mul(host.growth_per_level()));
    if estimate > MAX_REFINED_FACES {
        return Err(Error::Input(format!(
            "{levels} level(s) would produce about {estimate} faces or vertices (estimated before refining), above the supported {MAX_REFINED_FACES}; use fewer levels"
        )));
    }
    let mut mesh = mesh.clone();
    let mut points: Vec<Option<[f64; 3]>> = points.iter().map(|p| Some(*p)).collect();
    for level in 1..=levels {
        let bound = host.size_bound(&mesh);
        if bound > MAX_REFINED_FACES {
            return Err(Error::Input(format!(
                "level {level} would produce {bound} faces or vertices, above the supported {MAX_REFINED_FACES}; use fewer levels"
            )));
        }
        // non-stationary schemes (4-3 blends in its eon rules over the first steps)
        let step_rules = scheme.at_level(level);
        let rules: &dyn Scheme = step_rules.as_deref().unwrap_or(scheme);
        let Step { refined, stencils } = step::<f64>(rules, &mesh)?;
        // a closed mesh must have every rule apply; name the first that does
        // not, and why (every new vertex was selected, so none is NotSelected)
        if let Some((k, cause)) = stencils.iter().enumerate().find_map(|(k, s)| Some((k, s.cause()?))) {
            return Err(not_applicable(scheme, &mesh, refined.vertex_origins[k], cause, level));
        }
        let new_points = apply(stencils.iter().map(StepStencil::stencil), &points);
        if new_points.iter().any(|p| p.is_none_or(|p| !p.iter().all(|x| x.is_finite()))) {
            return Err(Error::Input(format!(
                "level {level}: a refined position is not finite (coordinates too large?)"
            )));
        }
        points = new_points;
        let mut next = refined.mesh;
        if let Some(params) = &mesh.vertex_params {
            // a per-vertex parameter (Lin–Luo's α) is refined by the scheme's own rule for it
            let name = scheme.vertex_param().map_or("parameter", |p| p.name);
            let rules: Vec<Option<Stencil<f64>>> =
                refined.vertex_origins.iter().map(|&o| scheme.vertex_param_rule(&mesh, o)).collect();
            let old: Vec<Option<[f64; 1]>> = params.iter().map(|&a| Some([a])).collect();
            let new: Option<Vec<f64>> =
                apply(rules.iter().map(Option::as_ref), &old).into_iter().map(|a| a.map(|a| a[0])).collect();
            next.vertex_params =
                Some(new.ok_or_else(|| {
                    Error::Input(format!("{}: no rule refines the per-vertex {name}", scheme.name()))
                })?);
        }
        mesh = next;
    }
    Ok((mesh, points.into_iter().map(|p| p.expect("checked above")).collect()))
}

/// Per refined vertex its weights on the vertices of the input mesh (`None`
/// where a rule did not apply).
pub type CompositeRows = Vec<Option<super::SparseRow<f64>>>;

/// Composite weights of the refinement steps `levels` (1-based, e.g. `1..=3`
/// for the first three steps of a real mesh) of a possibly open mesh such as an
/// analysis patch: for every vertex of the refined mesh, its weights on the
/// vertices of `mesh`, composed step by step with the rules of each level
/// (`Scheme::at_level`: 4-3 subdivision blends its eon rules in over the first
/// steps). `None` where a rule does not apply (near the boundary of a
/// patch). The refined mesh keeps the lattice chart of the input.
pub fn composite_weights(
    scheme: &dyn Scheme,
    mesh: &PolyMesh,
    levels: std::ops::RangeInclusive<usize>,
) -> Result<(PolyMesh, CompositeRows), Error> {
    let mut mesh = mesh.clone();
    let mut rows: CompositeRows = (0..mesh.num_vertices()).map(|v| Some(super::SparseRow::unit(v))).collect();
    for level in levels {
        let step_rules = scheme.at_level(level);
        let rules: &dyn Scheme = step_rules.as_deref().unwrap_or(scheme);
        let Step { refined, stencils } = step::<f64>(rules, &mesh)?;
        rows = apply(stencils.iter().map(StepStencil::stencil), &rows);
        mesh = refined.mesh;
    }
    Ok((mesh, rows))
}

/// Why the rule for `origin` does not apply, as one line. The gatherer's
/// `cause` decides what is said; the mesh is read only to name the place (the
/// vertex, the edge, the face sizes the host's rules do not cover).
fn not_applicable(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin, cause: GatherError, level: usize) -> Error {
    let name = scheme.name();
    let needs = requirement(scheme);
    let at_level = if level == 1 { String::new() } else { format!(" (at refinement level {level})") };
    let sizes = |faces: &[usize]| faces.iter().map(|&f| mesh.face(f).len().to_string()).collect::<Vec<_>>().join(", ");
    let (rule, place) = match origin {
        Origin::Vertex(v) => ("vertex", format!("vertex {}", v + 1)),
        Origin::Edge(a, b) => ("edge", format!("edge {}-{}", a + 1, b + 1)),
        Origin::Face(f) => ("face", format!("face {}", f + 1)),
        Origin::Corner { face, corner } => ("corner", format!("corner {} of face {}", corner + 1, face + 1)),
    };
    let reason = match cause {
        // the rule's neighbourhood is cut off: the mesh ends there, or (a
        // vertex in no face) has no neighbourhood at all
        GatherError::Truncated => match origin {
            Origin::Vertex(v) if mesh.faces_around(v).is_empty() => {
                format!("vertex {} is not used by any face", v + 1)
            }
            Origin::Vertex(v) if mesh.vertex_fan(v).is_none() => format!("vertex {} is on the boundary", v + 1),
            Origin::Edge(a, b) if !mesh.is_interior_edge(a, b) => {
                format!("edge {}-{} is on the boundary", a + 1, b + 1)
            }
            _ => format!("the mesh ends inside the neighbourhood its {rule} rule weighs at {place}"),
        },
        // the neighbourhood is complete but of a shape the host's rules do
        // not cover: name the shape
        GatherError::NotCovered => {
            let shape = match origin {
                Origin::Vertex(v) => {
                    let around = mesh.faces_around(v);
                    format!("valence {}, face sizes around it: {}", around.len(), sizes(&around))
                }
                Origin::Edge(a, b) => {
                    let faces: Vec<usize> =
                        [mesh.half_edge(a, b), mesh.half_edge(b, a)].into_iter().flatten().map(|h| h.0).collect();
                    format!("adjacent face sizes: {}", sizes(&faces))
                }
                Origin::Face(f) | Origin::Corner { face: f, .. } => {
                    format!("a face of {} vertices", mesh.face(f).len())
                }
            };
            format!("its {rule} rule does not cover {place} ({shape})")
        }
        // the host's topology asked for a point its own rules never create:
        // not the mesh's fault, so not an input error
        GatherError::Unsupported(host, kind) => {
            return Error::Message(format!(
                "{name}{at_level}: the {} host creates no {} points, yet the refinement asked for one at {place}",
                host.spec().name,
                format!("{kind:?}").to_lowercase()
            ));
        }
        // a tagged vertex or sharp edge whose rule the scheme does not weigh
        GatherError::MissingRule(_, missing) => {
            let what = match origin {
                Origin::Vertex(_) if missing == "vertex-corner" => "a corner",
                Origin::Vertex(_) => "a crease or boundary vertex",
                _ => "a sharp (boundary or crease) edge",
            };
            return Error::Input(format!(
                "{name}{at_level} has no {missing} rule (boundary/crease rules are not available in this scheme), \
                 and {place} is {what}"
            ));
        }
    };
    // only a mesh that ends somewhere would need boundary rules
    let open = cause == GatherError::Truncated && mesh.edges().into_iter().any(|(a, b)| !mesh.is_interior_edge(a, b));
    let boundary_note = if open { "; boundary rules are not implemented" } else { "" };
    Error::Input(format!("{name} needs {needs}{at_level}: {reason}{boundary_note}"))
}

/// What a scheme needs of its input mesh, for error messages.
fn requirement(scheme: &dyn Scheme) -> &'static str {
    if let Some(r) = scheme.mesh_requirement() {
        return r;
    }
    scheme.topology().mesh_requirement()
}

/// Give every face a face control vertex at `scale` times its barycentre (the
/// non-box paper, section 5: "FCV as 0.5, 1, and 1.5 times the barycenter").
/// The FCVs are appended after the existing vertices.
pub fn add_face_control_vertices(
    mesh: &PolyMesh,
    points: &[[f64; 3]],
    scale: f64,
) -> Result<(PolyMesh, Vec<[f64; 3]>), Error> {
    if mesh.has_face_point_on_every_face() {
        return Ok((mesh.clone(), points.to_vec()));
    }
    let mut pts = points.to_vec();
    let mut fcv = Vec::with_capacity(mesh.num_faces());
    for face in mesh.faces() {
        let mut c = [0.0; 3];
        for &v in face {
            for k in 0..3 {
                c[k] += points[v][k] / face.len() as f64;
            }
        }
        fcv.push(Some(pts.len()));
        pts.push([scale * c[0], scale * c[1], scale * c[2]]);
    }
    let mut m = PolyMesh::new(pts.len(), mesh.faces().clone())
        .map_err(|e| Error::Input(e.to_string()))?
        .with_face_points(fcv)?;
    // the old vertices keep their ids, and so their tags
    m.tags = mesh.tags.clone();
    Ok((m, pts))
}

/// The four-directional (quasi-four-directional, triangulated) form of a mesh
/// with face control vertices: every face becomes a fan of triangles around
/// its FCV (Huang, section 3.2.1: the two forms carry the same points).
pub fn four_directional(mesh: &PolyMesh, points: Vec<[f64; 3]>) -> Result<(PolyMesh, Vec<[f64; 3]>), Error> {
    if !mesh.has_face_point_on_every_face() {
        return Err(Error::Input("the mesh has no face control vertices".into()));
    }
    let mut faces = Vec::new();
    for (face, fcv) in mesh.faces().iter().zip(mesh.face_points.iter().flatten()) {
        for k in 0..face.len() {
            faces.push(vec![face[k], face[(k + 1) % face.len()], *fcv]);
        }
    }
    Ok((PolyMesh::new(points.len(), faces).map_err(|e| Error::Input(e.to_string()))?, points))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::SectorKind;
    use crate::numeric::{Inexact, Weight};
    use crate::sdc::slots::{weigh, Host, Mask, OriginKind, Slot, Wants};
    use crate::sdc::{Caps, CentreKind, MeshDomain, Params, RuleResult, Rules, SchemeInfo, Topology};

    /// Loop's host with every mandatory slot weighed 1: which stencils exist
    /// depends on the host's gatherer alone, which is what these tests are about.
    struct OnLoopsHost {
        info: SchemeInfo,
        params: Params,
    }

    impl OnLoopsHost {
        fn new() -> Self {
            let info = SchemeInfo {
                name: "ones",
                description: "test: weight 1 on every slot of Loop's host",
                topology: Topology::PrimalTriangle,
                centre: CentreKind::Vertex,
                sector: SectorKind::Tri,
                caps: Caps::NONE,
            };
            OnLoopsHost { info, params: Params::default() }
        }
    }

    impl Wants for OnLoopsHost {
        fn rule(&self, _: &str) -> bool {
            false
        }
        fn family(&self, _: &str, _: &str) -> bool {
            false
        }
    }

    impl<W: Weight> Mask<W> for OnLoopsHost {
        fn weight(&self, _: &PolyMesh, _: &'static str, _: &Slot) -> Result<W, Inexact> {
            Ok(W::one())
        }
    }

    impl<W: Weight> Rules<MeshDomain, W> for OnLoopsHost {
        fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
            weigh(Host::PrimalTriangle, mesh, origin, self, &W::one())
        }
    }

    impl Scheme for OnLoopsHost {
        fn info(&self) -> &SchemeInfo {
            &self.info
        }
        fn params(&self) -> &Params {
            &self.params
        }
    }

    /// The octahedron (vertex 2a + s is ±1 on axis a) without its face
    /// (0, 2, 4): vertices 0, 2, 4 lie on the boundary, 1, 3, 5 keep their
    /// closed fans of four triangles.
    fn open_octahedron() -> PolyMesh {
        let mut faces = Vec::new();
        for sx in 0..2 {
            for sy in 0..2 {
                for sz in 0..2 {
                    let (x, y, z) = (sx, 2 + sy, 4 + sz);
                    if (sx, sy, sz) != (0, 0, 0) {
                        faces.push(if (sx + sy + sz) % 2 == 0 { vec![x, y, z] } else { vec![x, z, y] });
                    }
                }
            }
        }
        PolyMesh::new(6, faces).unwrap()
    }

    /// A step keeps the gatherer's reason per new vertex: the vertex rule is
    /// cut off at the three boundary vertices and applies at the others.
    #[test]
    fn a_step_holds_why_a_rule_does_not_apply() {
        let mesh = open_octahedron();
        let Step { refined, stencils } = step::<f64>(&OnLoopsHost::new(), &mesh).unwrap();
        let mut seen = 0;
        for (origin, s) in refined.vertex_origins.iter().zip(&stencils) {
            if let Origin::Vertex(v) = *origin {
                seen += 1;
                if [0, 2, 4].contains(&v) {
                    assert_eq!(s, &StepStencil::Missing(GatherError::Truncated), "vertex {v}");
                } else {
                    // centre and its four neighbours, weight 1 each
                    assert_eq!(s.stencil().map(|s| s.terms.len()), Some(5), "vertex {v}");
                }
            }
        }
        assert_eq!(seen, 6);
    }

    /// The message says what the typed cause says: the same vertex of the
    /// same open mesh is "on the boundary" (and boundary rules are missing)
    /// when its neighbourhood is truncated, and of an uncovered shape when
    /// the host's rules do not cover it.
    #[test]
    fn not_applicable_starts_from_the_typed_cause() {
        let (scheme, mesh) = (OnLoopsHost::new(), open_octahedron());
        let e = not_applicable(&scheme, &mesh, Origin::Vertex(0), GatherError::Truncated, 1);
        assert_eq!(
            e,
            Error::Input(
                "ones needs a closed triangle mesh: vertex 1 is on the boundary; boundary rules are not implemented"
                    .into()
            )
        );
        // an interior place whose rule reaches the boundary: the open mesh is named too
        let e = not_applicable(&scheme, &mesh, Origin::Vertex(1), GatherError::Truncated, 2);
        assert_eq!(
            e.to_string(),
            "ones needs a closed triangle mesh (at refinement level 2): the mesh ends inside the neighbourhood \
             its vertex rule weighs at vertex 2; boundary rules are not implemented"
        );
        // vertex 1 (0-based) has four triangles around it
        let e = not_applicable(&scheme, &mesh, Origin::Vertex(1), GatherError::NotCovered, 1);
        assert_eq!(
            e,
            Error::Input(
                "ones needs a closed triangle mesh: its vertex rule does not cover vertex 2 \
                 (valence 4, face sizes around it: 3, 3, 3, 3)"
                    .into()
            )
        );
        // a host asked for a point it never creates is an internal failure
        let cause = GatherError::Unsupported(Host::PrimalTriangle, OriginKind::Corner);
        let e = not_applicable(&scheme, &mesh, Origin::Corner { face: 0, corner: 1 }, cause, 1);
        assert!(matches!(&e, Error::Message(m) if m.contains("creates no corner points")), "{e:?}");
    }
}
