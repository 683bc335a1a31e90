//! A built scheme file: its weights put on the host's mask slots
//! (`sdc::slots`). No neighbour gathering happens here; the host's gatherer
//! names the slots of every origin and this file only weighs them.

use std::collections::HashMap;
use std::sync::Arc;

use super::file::UserSchemeDef;
use super::weights::WeightTable;
use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::numeric::{Inexact, Weight};
use crate::schemes::files::shared_format::{given_values, intern};
use crate::sdc::slots::{weigh, Arity, Host, Mask, Slot, Wants};
use crate::sdc::VertexParam;
use crate::sdc::{Caps, MeshDomain, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{Origin, RuleResult, Stencil};

/// What all refinement levels of one built file share.
struct Shared {
    info: SchemeInfo,
    host: Host,
    params: Params,
    weights: WeightTable,
    /// (rule, family) -> field index in `weights`
    fields: HashMap<(&'static str, &'static str), usize>,
    blend_levels: Option<usize>,
    /// the file's parsed definition and the overrides, as text (`Scheme::identity`)
    identity: String,
}

/// A user scheme with its parameter values fixed and its weights checked.
#[derive(Clone)]
pub struct UserScheme {
    shared: Arc<Shared>,
    /// refinement step of a real mesh (1-based) when the file blends its
    /// extraordinary edge rule in over the first steps; `None`: stationary
    level: Option<usize>,
}

impl UserSchemeDef {
    /// Whether the file's vertex and edge rules both weigh face corners (then
    /// the primal quad host's gatherer takes any polygons for both).
    fn polygons(&self) -> bool {
        let weighs = |rule: &str| {
            self.rules
                .iter()
                .any(|r| r.spec.name == rule && r.fields.iter().any(|f| matches!(f.arity, Arity::FaceCorners(_))))
        };
        weighs("vertex") && weighs("edge")
    }

    /// The per-vertex parameter with the range its `[params]` entry gives.
    fn vertex_param_spec(&self) -> Option<VertexParam> {
        let name = self.vertex_param.as_deref()?;
        let p = self.params.iter().find(|p| p.name == name)?;
        Some(VertexParam { name: intern(name), min: p.min, max: p.max })
    }

    /// The scheme with the given parameter overrides, weights checked.
    pub fn build(&self, overrides: &[(String, String)]) -> Result<UserScheme, Error> {
        let (env, rules) = self.instantiate(overrides)?;
        let values = given_values(&self.params, &env);
        let mut fields = HashMap::new();
        let (mut exprs, mut face_corner) = (Vec::new(), Vec::new());
        for rule in &rules {
            for f in &rule.fields {
                fields.insert((rule.spec.name, f.family), exprs.len());
                exprs.push(f.expr.clone());
                face_corner.push(matches!(f.arity, Arity::FaceCorners(_)));
            }
        }
        Ok(UserScheme {
            shared: Arc::new(Shared {
                info: info_of(
                    intern(&self.name),
                    intern(&self.description),
                    self.host,
                    self.vertex_param_spec(),
                    self.polygons(),
                ),
                host: self.host,
                params: Params { values },
                weights: WeightTable::new(env, exprs, face_corner),
                fields,
                blend_levels: self.blend_levels,
                identity: format!("file {self:?} overrides {overrides:?}"),
            }),
            level: None,
        })
    }
}

impl Wants for Shared {
    fn rule(&self, rule: &str) -> bool {
        self.fields.keys().any(|(r, _)| *r == rule)
    }
    fn family(&self, rule: &str, family: &str) -> bool {
        self.fields.keys().any(|&(r, f)| r == rule && f == family)
    }
}

impl<W: Weight> Mask<W> for Shared {
    fn weight(&self, mesh: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        // the gatherer collects only the families the file weighs
        let k = *self.fields.get(&(rule, slot.family)).ok_or(Inexact)?;
        // `every_valence`: which fields are read at the centre's valence
        if let Some(value) = super::probe::record(rule, slot.family, slot.n, || self.weights.field(k)) {
            return Ok(W::ratio(value, 1));
        }
        // a mesh with per-vertex values: the parameter at the vertex concerned
        let vertex = match (self.info.caps.vertex_param, &mesh.vertex_params, slot.at) {
            (Some(p), Some(values), Some(at)) => Some((p.name, *values.get(at).ok_or(Inexact)?)),
            _ => None,
        };
        self.weights.get_at::<W>(k, slot.n as i64, slot.j as i64, slot.m.map(|m| m as i64), vertex)
    }
}

impl UserScheme {
    /// Share of the extraordinary edge rule at this step: (σ−1)/σ in steps
    /// σ ≤ blend-levels of a real mesh, else all of it.
    fn ev_share<W: Weight>(&self) -> W {
        match (self.level, self.shared.blend_levels) {
            (Some(s), Some(k)) if s <= k => W::ratio(s as i64 - 1, s as i64),
            _ => W::one(),
        }
    }
}

impl<W: Weight> Rules<MeshDomain, W> for UserScheme {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(self.shared.host, mesh, origin, self.shared.as_ref(), &self.ev_share())
    }
}

impl Scheme for UserScheme {
    fn info(&self) -> &SchemeInfo {
        &self.shared.info
    }
    fn params(&self) -> &Params {
        &self.shared.params
    }
    /// A new vertex's parameter is the mean of its parents' (Lin–Luo eq. 7
    /// on the sqrt(3) host, the only host with per-vertex parameters): an old
    /// vertex keeps its own, a face vertex takes the mean of the corners.
    fn vertex_param_rule(&self, mesh: &PolyMesh, origin: Origin) -> Option<Stencil<f64>> {
        self.shared.info.caps.vertex_param?;
        match origin {
            Origin::Vertex(v) => Some(Stencil::new().with(v, 1.0)),
            Origin::Face(f) => {
                let face = mesh.face(f);
                Some(face.iter().fold(Stencil::new(), |s, &v| s.with(v, 1.0 / face.len() as f64)))
            }
            Origin::Edge(..) | Origin::Corner { .. } => None,
        }
    }
    fn at_level(&self, level: usize) -> Option<Box<dyn Scheme>> {
        self.shared.blend_levels?;
        Some(Box::new(UserScheme { shared: self.shared.clone(), level: Some(level) }))
    }
    /// Two files may share a name: the whole parsed definition and the
    /// parameter values given are the identity, with the refinement level.
    fn identity(&self) -> Option<String> {
        Some(format!("{} level {:?}", self.shared.identity, self.level))
    }
}

/// A scheme file's description as data: the host's topology, centre and
/// sector, and the capabilities the host implies. `polygons`: the file's
/// vertex and edge rules weigh face corners, so they take any polygons.
fn info_of(
    name: &'static str,
    description: &'static str,
    host: Host,
    vertex_param: Option<VertexParam>,
    polygons: bool,
) -> SchemeInfo {
    let spec = host.spec();
    let mesh_requirement = match host {
        // any closed mesh (the host's own requirement)
        Host::PrimalQuad if polygons => None,
        // the vertex and edge rules of a primal-quad file without face-corner
        // fields are written for quads only
        Host::PrimalQuad => Some("a closed quad mesh (primal-quad scheme files have quad rules only)"),
        Host::MixedQuadTriangle => Some("a closed mesh of triangles and quads"),
        Host::Sqrt3 => Some("a closed triangle mesh"),
        Host::PrimalTriangle | Host::Fcv | Host::Dual | Host::Ternary | Host::AugmentedDual | Host::Polar => None,
    };
    SchemeInfo {
        name,
        description,
        topology: host,
        centre: spec.centre,
        sector: spec.sector,
        caps: Caps {
            face_control: spec.face_control,
            face_sequences: host == Host::MixedQuadTriangle,
            mesh_requirement,
            vertex_param,
            ..Caps::NONE
        },
    }
}
