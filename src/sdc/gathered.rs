//! What gathering the slots of one origin gives (`Gather`): the rules applied
//! to the neighbourhood (`Part`s of `Slot`s), or why they could not be
//! gathered (`GatherError`), and what a mask asks to be gathered (`Wants`).
//! The hosts' gatherers return it (`RefinementHost::gather`); the gatherer
//! entry point and the weighing are in `sdc::slots`.

use crate::mesh::VertexId;
use crate::numeric::Inexact;
use crate::sdc::host_list::Host;
use crate::sdc::host_spec::OriginKind;
use crate::sdc::stencil::Stencil;

/// Which rules and optional families a mask has: the gatherer collects only
/// what is weighed (a 2-ring family costs a larger neighbourhood).
pub trait Wants {
    fn rule(&self, rule: &str) -> bool;
    fn family(&self, rule: &str, family: &str) -> bool;
}

/// Why an origin's slots could not be gathered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GatherError {
    /// the mesh ends before the neighbourhood the rule weighs (boundary of a
    /// truncated patch)
    Truncated,
    /// the neighbourhood is complete but of a shape the host's rules do not
    /// cover (a face size or valence outside the host)
    NotCovered,
    /// the host never creates this kind of origin
    Unsupported(Host, OriginKind),
    /// the origin is a tagged boundary, crease or corner vertex or a sharp
    /// edge, and the mask has no weights for the host's rule there (the rule
    /// named: `vertex-crease`, `vertex-corner`, `edge-crease`)
    MissingRule(Host, &'static str),
}

impl std::fmt::Display for GatherError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GatherError::Truncated => write!(f, "the neighbourhood is truncated"),
            GatherError::NotCovered => write!(f, "no rule of the host covers this neighbourhood"),
            GatherError::Unsupported(h, o) => write!(f, "host {} creates no {o:?} points", h.spec().name),
            GatherError::MissingRule(h, rule) => {
                write!(f, "the mask has no {rule} rule of host {} (boundary/crease rules)", h.spec().name)
            }
        }
    }
}

/// Where a slot's weight goes.
#[derive(Clone, Debug, PartialEq)]
pub enum Target {
    Vertex(VertexId),
    /// a point that is itself a combination of mesh vertices (PGS: the central
    /// point of a face that has none, given by the host's `point` rule)
    Derived(Box<Part>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Slot {
    pub family: &'static str,
    pub j: usize,
    /// the valence (or face size) the slot's weight is evaluated at
    pub n: usize,
    /// the vertex concerned (whose valence n is, and whose per-vertex
    /// parameters the weight takes): the centre of a vertex rule, the corner
    /// P of a sqrt(3) face rule, the extraordinary end of an edge rule;
    /// `None` where a rule concerns no single vertex (regular edges, faces)
    pub at: Option<VertexId>,
    /// the corner count of the face a face-corner slot lies in (its own for
    /// each face of a vertex's fan or an edge); `None` for other slots
    pub m: Option<usize>,
    pub target: Target,
}

/// One rule applied to one neighbourhood, scaled by `scale` (num, den).
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    pub rule: &'static str,
    pub n: usize,
    /// the vertex concerned, for the slots put from now on (see `Slot::at`)
    pub at: Option<VertexId>,
    pub scale: (i64, i64),
    pub slots: Vec<Slot>,
}

impl Part {
    pub(crate) fn new(rule: &'static str, n: usize) -> Self {
        Part { rule, n, at: None, scale: (1, 1), slots: Vec::new() }
    }
    /// A rule about vertex `v` (of valence n).
    pub(crate) fn around(rule: &'static str, n: usize, v: VertexId) -> Self {
        Part { at: Some(v), ..Part::new(rule, n) }
    }
    pub(crate) fn put(&mut self, family: &'static str, j: usize, v: VertexId) {
        self.slots.push(Slot { family, j, n: self.n, at: self.at, m: None, target: Target::Vertex(v) });
    }
    /// A slot of the neighbourhood of vertex `at` (valence n) inside a larger rule.
    pub(crate) fn put_around(&mut self, family: &'static str, j: usize, n: usize, at: VertexId, v: VertexId) {
        self.slots.push(Slot { family, j, n, at: Some(at), m: None, target: Target::Vertex(v) });
    }
    pub(crate) fn put_target(&mut self, family: &'static str, target: Target) {
        self.slots.push(Slot { family, j: 0, n: self.n, at: self.at, m: None, target });
    }
    /// The face-corner slots of face j: its corners from `start` on.
    pub(crate) fn put_face_corners(&mut self, j: usize, face: &[VertexId], start: usize) {
        let m = face.len();
        for t in 0..m {
            let target = Target::Vertex(face[(start + t) % m]);
            self.slots.push(Slot { family: "face-corner", j, n: self.n, at: self.at, m: Some(m), target });
        }
    }
    pub(crate) fn scaled(mut self, num: i64, den: i64) -> Self {
        self.scale = (num, den);
        self
    }
}

/// The slots of one origin: the sum of `parts` and `extraordinary`.
/// `extraordinary` holds the rules of extraordinary vertices that a mask may
/// blend in over a real mesh's first steps (4-3): an edge at an
/// extraordinary vertex (the mean of the two ends' rules where both are),
/// then with `regular`, the regular rule of the same edge that they replace;
/// 4-3's quad term (4a') at an eon.
#[derive(Clone, Debug, PartialEq)]
pub struct Gathered {
    pub parts: Vec<Part>,
    pub extraordinary: Vec<Part>,
    pub regular: Option<Part>,
}

impl Gathered {
    pub(crate) fn one(part: Part) -> Self {
        Gathered { parts: vec![part], extraordinary: Vec::new(), regular: None }
    }
    pub(crate) fn replacing(extraordinary: Vec<Part>, regular: Part) -> Self {
        Gathered { parts: Vec::new(), extraordinary, regular: Some(regular) }
    }
}

pub type Gather = Result<Gathered, GatherError>;

/// What a mask returns for one origin: `Ok(Ok(stencil))`; `Ok(Err(cause))`
/// when the old mesh does not hold a neighbourhood the rule applies to, with
/// the gatherer's reason (a truncated patch, a face size or valence the host's
/// rules do not cover, an origin the host never creates), so that whoever
/// reports the missing stencil can say why; `Err(Inexact)` when the weights
/// are not representable in `W`. Declared here, beside `GatherError`, rather
/// than with `Stencil`: the stencil file stays below the hosts' declarations.
pub type RuleResult<W> = Result<Result<Stencil<W>, GatherError>, Inexact>;
