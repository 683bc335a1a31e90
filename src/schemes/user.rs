//! User-defined schemes: a TOML file names one of the built-in refinement
//! topologies and gives the stencil weights as expressions (`numeric::expr`)
//! in the valence or face size `n`, the neighbour index `j` and named
//! parameters. The result implements `Scheme`, so every analysis runs on it
//! unchanged.
//!
//! ```toml
//! name = "my-loop"
//! topology = "primal-triangle"
//! [vertex]
//! centre = "3/8 + (3/8 + cos(2 pi / n)/4)^2"
//! edge = "(5/8 - (3/8 + cos(2 pi / n)/4)^2) / n"
//! [edge]
//! ends = "3/8"
//! opposite = "1/8"
//! ```
//!
//! Which neighbours each field weighs is fixed per topology (`TOPOLOGIES`),
//! in the order `PolyMesh::vertex_fan` returns them (counter-clockwise). The
//! first neighbour around a vertex or in a face is arbitrary, so weights there
//! may not depend on `j`. The optional `[edge-extraordinary]` rule of the
//! primal topologies is where `j` is canonical: the new point on an edge with
//! an extraordinary end V, as a stencil over V's 1-ring with e_0 the edge's
//! other end (and, for quads, f_j the corner opposite V in the face between
//! e_j and e_{j+1}). Everything that can be checked is checked at load time,
//! each error naming the line and the field.

use std::any::TypeId;
use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::Path;
use std::sync::Mutex;

use serde::Deserialize;
use toml::Spanned;

use super::{uniform_fan, Caps, CentreKind, Params, Rules, Scheme, SchemeInfo};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::expr::{Env, Expr};
use crate::numeric::{Inexact, ParamValue, Weight};
use crate::refine::{Origin, RuleResult, Stencil};
use crate::sdc::{Topology, TriangleSplit};

/// Scheme files are a few dozen lines; the caps keep a malformed or hostile
/// file from costing unbounded time or memory.
pub const MAX_FILE_BYTES: usize = 64 * 1024;
pub const MAX_EXPR_CHARS: usize = 1000;
const MAX_NAME_CHARS: usize = 64;
const MAX_DESCRIPTION_CHARS: usize = 1000;
const MAX_PARAMS: usize = 16;
/// Valences (and face sizes) at which weights are checked at load time.
const CHECK_N: std::ops::RangeInclusive<i64> = 3..=12;
/// Names the expression language or the rules reserve.
const RESERVED: [&str; 11] = ["n", "j", "pi", "i", "cos", "sin", "sqrt", "cbrt", "abs", "kronecker", "sum"];
/// The optional rule for edges with an extraordinary end (primal topologies).
const EV_EDGE: &str = "edge-extraordinary";

/// How many neighbours a field weighs: one per index j = 0..n-1, or a fixed count.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Count {
    PerJ,
    Fixed(i64),
}

struct FieldSpec {
    name: &'static str,
    count: Count,
}

struct RuleSpec {
    section: &'static str,
    fields: &'static [FieldSpec],
    /// a file may leave the section out (then the rule is not used)
    optional: bool,
    /// j has a canonical meaning here, so weights may depend on it
    canonical_j: bool,
}

const fn rule(section: &'static str, fields: &'static [FieldSpec]) -> RuleSpec {
    RuleSpec { section, fields, optional: false, canonical_j: false }
}

struct TopologySpec {
    name: &'static str,
    topology: Topology,
    sector: SectorKind,
    face_control: bool,
    /// the face size and the regular valence (primal topologies, which may
    /// have an `[edge-extraordinary]` rule)
    regular: Option<(usize, usize)>,
    rules: &'static [RuleSpec],
}

const fn f(name: &'static str, count: Count) -> FieldSpec {
    FieldSpec { name, count }
}

use Count::{Fixed, PerJ};

const TOPOLOGIES: [TopologySpec; 3] = [
    TopologySpec {
        name: "primal-quad",
        topology: Topology::PrimalSplit(TriangleSplit::FacePointQuads),
        sector: SectorKind::Quad,
        face_control: false,
        regular: Some((4, 4)),
        rules: &[
            // fan face j = [v, e_j, f_j, e_{j+1}]: edge neighbour e_j, face-opposite neighbour f_j
            rule("vertex", &[f("centre", Fixed(1)), f("edge", PerJ), f("face", PerJ)]),
            // the edge's two ends, and the two other corners of each of its two quads
            rule("edge", &[f("ends", Fixed(2)), f("side", Fixed(4))]),
            // an edge with an extraordinary end V (valence n != 4): V, and V's fan
            // as in the vertex rule, turned so that e_0 is the edge's other end
            RuleSpec {
                section: EV_EDGE,
                fields: &[f("centre", Fixed(1)), f("edge", PerJ), f("face", PerJ)],
                optional: true,
                canonical_j: true,
            },
            // corner j of a face with n corners
            rule("face", &[f("corner", PerJ)]),
        ],
    },
    TopologySpec {
        name: "primal-triangle",
        topology: Topology::PrimalSplit(TriangleSplit::FourTriangles),
        sector: SectorKind::Tri,
        face_control: false,
        regular: Some((3, 6)),
        rules: &[
            rule("vertex", &[f("centre", Fixed(1)), f("edge", PerJ)]),
            // the two ends and the apexes of the two triangles
            rule("edge", &[f("ends", Fixed(2)), f("opposite", Fixed(2))]),
            // an edge with an extraordinary end V (valence n != 6): V and its
            // 1-ring, e_0 the edge's other end, counter-clockwise
            RuleSpec {
                section: EV_EDGE,
                fields: &[f("centre", Fixed(1)), f("edge", PerJ)],
                optional: true,
                canonical_j: true,
            },
        ],
    },
    TopologySpec {
        name: "fcv",
        topology: Topology::FcvSplit,
        sector: SectorKind::Quad,
        face_control: true,
        regular: None,
        rules: &[
            // the vertex and the FCV of fan face j
            rule("vertex", &[f("centre", Fixed(1)), f("fcv", PerJ)]),
            // the two ends and the FCVs of the two faces
            rule("edge", &[f("ends", Fixed(2)), f("fcv", Fixed(2))]),
            // the new FCV of an old face: the old FCV and corner j of n
            rule("face", &[f("centre", Fixed(1)), f("corner", PerJ)]),
            // the FCV of the new quad at corner V_0 of old face F_0 (n corners):
            // V_0, the FCV of F_0, and the FCVs of F_0's two neighbours at V_0
            rule("corner", &[f("vertex", Fixed(1)), f("fcv", Fixed(1)), f("side", Fixed(2))]),
        ],
    },
];

type Section = Spanned<BTreeMap<String, Spanned<toml::Value>>>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileDoc {
    name: Spanned<String>,
    description: Option<Spanned<String>>,
    topology: Spanned<String>,
    affine: Option<bool>,
    #[serde(default)]
    params: BTreeMap<String, Spanned<ParamDoc>>,
    vertex: Option<Section>,
    edge: Option<Section>,
    #[serde(rename = "edge-extraordinary")]
    edge_extraordinary: Option<Section>,
    face: Option<Section>,
    corner: Option<Section>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ParamDoc {
    default: Spanned<toml::Value>,
    min: Option<Spanned<toml::Value>>,
    max: Option<Spanned<toml::Value>>,
    description: Option<String>,
}

/// A weight expression and where it was written.
#[derive(Clone, Debug)]
struct Field {
    key: String,
    line: usize,
    expr: Expr,
    count: Count,
    uses_j: bool,
    /// j is canonical in this field's rule (each j's weight is its own)
    canonical_j: bool,
}

#[derive(Clone, Debug)]
pub struct UserParam {
    pub name: String,
    pub default: ParamValue,
    pub min: f64,
    pub max: f64,
    pub description: String,
}

/// A parsed scheme file, before parameter values are fixed.
#[derive(Clone, Debug)]
pub struct UserSchemeDef {
    file: String,
    pub name: String,
    pub description: String,
    topology: usize,
    pub affine: bool,
    pub params: Vec<UserParam>,
    /// per rule of the topology: (section line, fields in the spec's order)
    rules: Vec<(usize, Vec<Field>)>,
}

/// A user scheme with its parameter values fixed and its weights checked.
pub struct UserScheme {
    info: SchemeInfo,
    topology: usize,
    params: Params,
    env: Env,
    /// "section.field" -> expression
    weights: HashMap<String, Expr>,
    /// the file has an `[edge-extraordinary]` rule
    ev_edges: bool,
    /// weights already evaluated, by (field, n, j, float): a weight that is a
    /// Fourier sum costs n terms, and refinement asks for it at every edge
    cache: Mutex<WeightCache>,
}

/// (field, n, j, float) -> the weight.
type WeightCache = HashMap<(String, i64, i64, bool), Result<ParamValue, Inexact>>;

/// Entries the weight cache holds before it starts afresh (a sweep over many
/// valences must not grow it without bound).
const CACHE_ENTRIES: usize = 100_000;

fn line_of(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())].iter().filter(|&&b| b == b'\n').count() + 1
}

/// A literal in the file as a parameter value: strings are parsed as numbers
/// (3/8, 0.375), TOML integers and floats taken as written.
fn literal(v: &toml::Value) -> Result<ParamValue, String> {
    match v {
        toml::Value::String(s) => ParamValue::parse(s),
        toml::Value::Integer(k) => Ok(ParamValue::from_ratio(*k, 1)),
        // the shortest decimal that round-trips, so 0.375 is exactly 3/8
        toml::Value::Float(x) => ParamValue::parse(&format!("{x}")),
        other => Err(format!("expected a number, got a {}", other.type_str())),
    }
}

/// Where j-dependent weights may go instead, for error messages.
fn j_pointer(spec: &TopologySpec) -> &'static str {
    if spec.regular.is_some() {
        "; weights that depend on j belong in [edge-extraordinary], where j = 0 is the edge's other end"
    } else {
        ""
    }
}

impl UserSchemeDef {
    fn err(&self, line: usize, field: &str, msg: impl std::fmt::Display) -> String {
        format!("{} line {line}, field {field}: {msg}", self.file)
    }

    /// Parse a scheme file's text; `file` names it in error messages.
    pub fn parse(text: &str, file: &str) -> Result<UserSchemeDef, String> {
        if text.len() > MAX_FILE_BYTES {
            return Err(format!("{file}: larger than {MAX_FILE_BYTES} bytes; scheme files are short"));
        }
        let doc: FileDoc = toml::from_str(text).map_err(|e| {
            let msg = e.message().trim().replace('\n', "; ");
            match e.span() {
                Some(span) => format!("{file} line {}: {msg}", line_of(text, span.start)),
                None => format!("{file}: {msg}"),
            }
        })?;
        let at = |span: std::ops::Range<usize>| line_of(text, span.start);
        let err =
            |line: usize, field: &str, msg: &dyn std::fmt::Display| format!("{file} line {line}, field {field}: {msg}");

        let name = doc.name.get_ref().trim().to_string();
        let name_ok = !name.is_empty()
            && name.chars().count() <= MAX_NAME_CHARS
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if !name_ok {
            return Err(err(
                at(doc.name.span()),
                "name",
                &format!("'{name}' is not a scheme name (1 to {MAX_NAME_CHARS} letters, digits, '-' or '_')"),
            ));
        }
        // output and claims identify schemes by name: a file must not pass for a built-in
        if super::known_names().contains(&name.as_str()) {
            return Err(err(
                at(doc.name.span()),
                "name",
                &format!("'{name}' is a built-in scheme; choose another name"),
            ));
        }
        let description = match &doc.description {
            Some(d) if d.get_ref().chars().count() > MAX_DESCRIPTION_CHARS => {
                return Err(err(
                    at(d.span()),
                    "description",
                    &format!("longer than {MAX_DESCRIPTION_CHARS} characters"),
                ))
            }
            Some(d) => d.get_ref().replace('\n', " "),
            None => format!("user scheme from {file}"),
        };
        let topo_name = doc.topology.get_ref().as_str();
        let Some(topology) = TOPOLOGIES.iter().position(|t| t.name == topo_name) else {
            let known: Vec<_> = TOPOLOGIES.iter().map(|t| t.name).collect();
            return Err(err(
                at(doc.topology.span()),
                "topology",
                &format!("unknown topology '{topo_name}'; known: {}", known.join(", ")),
            ));
        };

        if doc.params.len() > MAX_PARAMS {
            return Err(format!("{file}: more than {MAX_PARAMS} parameters"));
        }
        let mut params = Vec::new();
        for (pname, p) in &doc.params {
            let line = at(p.span());
            let key = format!("params.{pname}");
            let ident = pname.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && pname.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                && pname.len() <= MAX_NAME_CHARS;
            if !ident {
                return Err(err(line, &key, &"a parameter name is letters, digits and '_', starting with a letter"));
            }
            if RESERVED.contains(&pname.as_str()) {
                return Err(err(line, &key, &format!("'{pname}' is reserved (n, j, pi, i and function names)")));
            }
            let p = p.get_ref();
            let default =
                literal(p.default.get_ref()).map_err(|e| err(at(p.default.span()), &format!("{key}.default"), &e))?;
            let bound = |b: &Option<Spanned<toml::Value>>, which: &str, none: f64| -> Result<f64, String> {
                match b {
                    None => Ok(none),
                    Some(v) => literal(v.get_ref())
                        .map(|x| x.value)
                        .map_err(|e| err(at(v.span()), &format!("{key}.{which}"), &e)),
                }
            };
            let (min, max) = (bound(&p.min, "min", f64::NEG_INFINITY)?, bound(&p.max, "max", f64::INFINITY)?);
            if !(min <= max && default.value >= min && default.value <= max) {
                return Err(err(line, &key, &format!("default {} is not in [{min}, {max}]", default.text)));
            }
            params.push(UserParam {
                name: pname.clone(),
                default,
                min,
                max,
                description: p.description.clone().unwrap_or_default(),
            });
        }

        let spec = &TOPOLOGIES[topology];
        let sections: [(&str, &Option<Section>); 5] = [
            ("vertex", &doc.vertex),
            ("edge", &doc.edge),
            (EV_EDGE, &doc.edge_extraordinary),
            ("face", &doc.face),
            ("corner", &doc.corner),
        ];
        let mut rules = Vec::new();
        for (section, table) in sections {
            let rule = spec.rules.iter().find(|r| r.section == section);
            let (rule, table) = match (rule, table) {
                (None, None) => continue,
                (None, Some(t)) => {
                    return Err(err(at(t.span()), section, &format!("topology {} has no {section} rule", spec.name)))
                }
                (Some(r), None) if r.optional => continue,
                (Some(_), None) => return Err(format!("{file}: missing section [{section}] (topology {})", spec.name)),
                (Some(r), Some(t)) => (r, t),
            };
            let section_line = at(table.span());
            for (key, value) in table.get_ref() {
                if !rule.fields.iter().any(|fs| fs.name == key) {
                    let known: Vec<_> = rule.fields.iter().map(|fs| fs.name).collect();
                    return Err(err(
                        at(value.span()),
                        &format!("{section}.{key}"),
                        &format!("unknown field; the {section} rule of {} has {}", spec.name, known.join(", ")),
                    ));
                }
            }
            let mut fields = Vec::new();
            for fs in rule.fields {
                let key = format!("{section}.{}", fs.name);
                let Some(value) = table.get_ref().get(fs.name) else {
                    return Err(err(section_line, &key, &"missing (write 0 for a zero weight)"));
                };
                let line = at(value.span());
                let source = match value.get_ref() {
                    toml::Value::String(s) => s.clone(),
                    toml::Value::Integer(k) => k.to_string(),
                    toml::Value::Float(x) => format!("{x}"),
                    other => {
                        return Err(err(
                            line,
                            &key,
                            &format!("expected an expression string, got a {}", other.type_str()),
                        ))
                    }
                };
                if source.chars().count() > MAX_EXPR_CHARS {
                    return Err(err(line, &key, &format!("expression longer than {MAX_EXPR_CHARS} characters")));
                }
                let expr = Expr::parse(&source).map_err(|e| err(line, &key, &e))?;
                for var in expr.variables() {
                    // edge rules concern no single vertex or face: no n there
                    let allowed = (var == "n" && section != "edge")
                        || (var == "j" && fs.count == PerJ)
                        || params.iter().any(|p| p.name == var);
                    if !allowed {
                        let hint = match var.as_str() {
                            "j" if rule.canonical_j => " (j indexes neighbours only in per-neighbour fields)".into(),
                            "j" => format!(" (j indexes neighbours only in per-neighbour fields{})", j_pointer(spec)),
                            "n" => " (edge rules have no valence n)".into(),
                            _ => String::new(),
                        };
                        return Err(err(line, &key, &format!("unknown variable '{var}'{hint}")));
                    }
                }
                let uses_j = expr.variables().iter().any(|v| v == "j");
                fields.push(Field { key, line, expr, count: fs.count, uses_j, canonical_j: rule.canonical_j });
            }
            rules.push((section_line, fields));
        }
        let def = UserSchemeDef {
            file: file.to_string(),
            name,
            description,
            topology,
            affine: doc.affine.unwrap_or(true),
            params,
            rules,
        };
        // check the defaults now, so that a file that cannot work fails at load
        def.check(&def.env(&[])?)?;
        Ok(def)
    }

    /// Parameter values: the defaults, then `name=value` overrides.
    fn env(&self, overrides: &[(String, String)]) -> Result<Env, String> {
        let mut env = Env::new();
        for p in &self.params {
            env.insert(p.name.clone(), p.default.clone());
        }
        for (name, text) in overrides {
            let Some(p) = self.params.iter().find(|p| &p.name == name) else {
                let known: Vec<_> = self.params.iter().map(|p| p.name.as_str()).collect();
                return Err(if known.is_empty() {
                    format!("scheme '{}' has no parameters (got '{name}')", self.name)
                } else {
                    format!("scheme '{}' has no parameter '{name}'; its parameters: {}", self.name, known.join(", "))
                });
            };
            let v = ParamValue::parse(text).map_err(|e| format!("parameter {name}: {e}"))?;
            if v.value < p.min || v.value > p.max {
                return Err(format!(
                    "parameter {name}={text} is out of range [{}, {}] for scheme '{}'",
                    p.min, p.max, self.name
                ));
            }
            env.insert(name.clone(), v);
        }
        Ok(env)
    }

    /// Every weight must be a finite real number at n = 3..12 and, outside
    /// `[edge-extraordinary]`, the same for every j (the first neighbour
    /// around a vertex or in a face is arbitrary, so a weight that varies
    /// with j would make the rule depend on how the mesh is stored); with
    /// `affine`, every rule's weights sum to 1.
    fn check(&self, params: &Env) -> Result<(), String> {
        for (section_line, fields) in &self.rules {
            for n in CHECK_N {
                let mut sum = 0.0;
                for field in fields {
                    let js = if field.uses_j { 0..n } else { 0..1 };
                    // j canonical and used: every neighbour has its own weight
                    let per_j = field.canonical_j && field.uses_j;
                    let mut first = None;
                    for j in js {
                        let w = eval_f64(&field.expr, params, n, j)
                            .map_err(|e| self.err(field.line, &field.key, format!("at n = {n}, j = {j}: {e}")))?;
                        if per_j {
                            sum += w;
                            continue;
                        }
                        match first {
                            None => first = Some(w),
                            Some(w0) if (w - w0).abs() > 1e-12 * w0.abs().max(1.0) => {
                                return Err(self.err(
                                    field.line,
                                    &field.key,
                                    format!(
                                        "the weight differs between j = 0 and j = {j} at n = {n}; the first neighbour \
                                         is arbitrary, so weights may not depend on j{}",
                                        j_pointer(&TOPOLOGIES[self.topology])
                                    ),
                                ))
                            }
                            _ => {}
                        }
                    }
                    if per_j {
                        continue;
                    }
                    let w = first.unwrap_or(0.0);
                    sum += w * match field.count {
                        PerJ => n as f64,
                        Fixed(k) => k as f64,
                    };
                }
                if self.affine && (sum - 1.0).abs() > 1e-12 {
                    let section = fields.first().map(|f| f.key.split('.').next().unwrap_or("")).unwrap_or("");
                    return Err(format!(
                        "{} line {section_line}, field {section}: the weights of the {section} rule sum to {sum} at \
                         n = {n}, not 1 (set affine = false to allow this)",
                        self.file
                    ));
                }
            }
        }
        Ok(())
    }

    /// The scheme with the given parameter overrides, weights checked.
    /// The refinement topology the file names (`primal-triangle`, ...).
    pub fn topology_name(&self) -> &'static str {
        TOPOLOGIES[self.topology].name
    }

    pub fn build(&self, overrides: &[(String, String)]) -> Result<UserScheme, String> {
        let env = self.env(overrides)?;
        self.check(&env)?;
        let values = self.params.iter().map(|p| (p.name.clone(), env[&p.name].clone())).collect();
        let weights: HashMap<String, Expr> =
            self.rules.iter().flat_map(|(_, fs)| fs.iter().map(|f| (f.key.clone(), f.expr.clone()))).collect();
        let spec = &TOPOLOGIES[self.topology];
        let info = SchemeInfo {
            name: intern(&self.name),
            description: intern(&self.description),
            topology: spec.topology,
            centre: CentreKind::Vertex,
            sector: spec.sector,
            caps: Caps {
                face_control: spec.face_control,
                // the vertex and edge rules of a primal-quad file are written for quads only
                mesh_requirement: (spec.name == "primal-quad")
                    .then_some("a closed quad mesh (primal-quad scheme files have quad rules only)"),
                ..Caps::NONE
            },
        };
        Ok(UserScheme {
            info,
            topology: self.topology,
            params: Params { values },
            env,
            ev_edges: weights.contains_key("edge-extraordinary.centre"),
            weights,
            cache: Mutex::new(HashMap::new()),
        })
    }
}

/// `Scheme::name` returns `&'static str`; a loaded scheme's name lives for the
/// rest of the process. Interning leaks each distinct string once only, so
/// loading the same file again costs nothing.
fn intern(s: &str) -> &'static str {
    static SEEN: Mutex<Option<HashSet<&'static str>>> = Mutex::new(None);
    let mut guard = SEEN.lock().unwrap_or_else(|e| e.into_inner());
    let set = guard.get_or_insert_with(HashSet::new);
    if let Some(&s) = set.get(s) {
        return s;
    }
    let leaked: &'static str = Box::leak(s.to_string().into_boxed_str());
    set.insert(leaked);
    leaked
}

fn with_nj(params: &Env, n: i64, j: i64) -> Env {
    let mut env = params.clone();
    env.insert("n".into(), ParamValue::from_ratio(n, 1));
    env.insert("j".into(), ParamValue::from_ratio(j, 1));
    env
}

fn eval_f64(expr: &Expr, params: &Env, n: i64, j: i64) -> Result<f64, String> {
    let z = expr.eval(&with_nj(params, n, j))?;
    if !z.re.is_finite() || !z.im.is_finite() {
        return Err("the weight is not a finite number".into());
    }
    if z.im.abs() > 1e-12 * z.re.abs().max(1.0) {
        return Err(format!("the weight is complex ({} + {}i)", z.re, z.im));
    }
    Ok(z.re)
}

/// Read and parse a scheme file (size capped before reading it all).
pub fn load_def(path: &Path) -> Result<UserSchemeDef, String> {
    use std::io::Read;
    let shown = path.display().to_string();
    let file = std::fs::File::open(path).map_err(|e| format!("cannot read scheme file {shown}: {e}"))?;
    let mut bytes = Vec::new();
    file.take(MAX_FILE_BYTES as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read scheme file {shown}: {e}"))?;
    if bytes.len() > MAX_FILE_BYTES {
        return Err(format!("{shown}: larger than {MAX_FILE_BYTES} bytes; scheme files are short"));
    }
    let text = String::from_utf8(bytes).map_err(|_| format!("{shown}: not UTF-8 text"))?;
    UserSchemeDef::parse(&text, &shown)
}

/// Load a scheme file with `name=value` parameter overrides.
pub fn load(path: &Path, overrides: &[(String, String)]) -> Result<Box<dyn Scheme>, String> {
    Ok(Box::new(load_def(path)?.build(overrides)?))
}

impl UserScheme {
    /// The weight of field `key` at valence (or face size) n, index j.
    fn w<W: Weight>(&self, key: &str, n: i64, j: i64) -> Result<W, Inexact> {
        // evaluate only in the arithmetic asked for: exact evaluation of an
        // irrational weight fails, and float stencils must not pay for it
        let float = TypeId::of::<W>() == TypeId::of::<f64>();
        let id = (key.to_string(), n, j, float);
        let cached = self.cache.lock().unwrap_or_else(|e| e.into_inner()).get(&id).cloned();
        let value = match cached {
            Some(v) => v,
            None => {
                let v = self.evaluate(key, n, j, float);
                let mut cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
                if cache.len() >= CACHE_ENTRIES {
                    cache.clear();
                }
                cache.insert(id, v.clone());
                v
            }
        };
        W::param(&value?)
    }

    fn evaluate(&self, key: &str, n: i64, j: i64, float: bool) -> Result<ParamValue, Inexact> {
        let expr = self.weights.get(key).ok_or(Inexact)?;
        let env = with_nj(&self.env, n, j);
        Ok(if float {
            let z = expr.eval(&env).map_err(|_| Inexact)?;
            if !z.re.is_finite() || z.im.abs() > 1e-12 * z.re.abs().max(1.0) {
                return Err(Inexact);
            }
            ParamValue { value: z.re, exact: None, text: String::new() }
        } else {
            let q = expr.exact(&env).ok_or(Inexact)?;
            ParamValue { value: q.to_f64(), exact: Some(q), text: String::new() }
        })
    }

    fn spec(&self) -> &'static TopologySpec {
        &TOPOLOGIES[self.topology]
    }
}

/// Whether `v` is extraordinary for a primal rule: a closed fan of `size`-gons
/// whose count is not the regular valence. (Vertices with open fans, such as
/// the rim of a truncated neighbourhood, lie in the regular part.)
fn extraordinary(mesh: &PolyMesh, v: usize, size: usize, regular: usize) -> bool {
    uniform_fan(mesh, v, size).is_some_and(|fan| fan.len() != regular)
}

impl<W: Weight> Rules<W> for UserScheme {
    fn stencil(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        match self.spec().name {
            "primal-quad" => self.primal_quad(mesh, origin),
            "primal-triangle" => self.primal_triangle(mesh, origin),
            _ => self.fcv(mesh, origin),
        }
    }
}

impl UserScheme {
    /// The `[edge-extraordinary]` stencil of the new point on edge (v, other)
    /// seen from its extraordinary end v: v, and v's 1-ring in the
    /// counter-clockwise order of `vertex_fan` starting at e_0 = other (with
    /// quads, fan face j = [v, e_j, f_j, e_{j+1}]).
    fn ev_edge<W: Weight>(&self, mesh: &PolyMesh, v: usize, other: usize, size: usize) -> RuleResult<W> {
        let Some(fan) = uniform_fan(mesh, v, size) else { return Ok(None) };
        let Some(start) = fan.iter().position(|face| face[1] == other) else { return Ok(None) };
        let n = fan.len();
        let mut s = Stencil::new().with(v, self.w("edge-extraordinary.centre", n as i64, 0)?);
        for j in 0..n {
            let face = &fan[(start + j) % n];
            s.add(face[1], self.w("edge-extraordinary.edge", n as i64, j as i64)?);
            if size == 4 {
                s.add(face[2], self.w("edge-extraordinary.face", n as i64, j as i64)?);
            }
        }
        Ok(Some(s))
    }

    /// The new point on edge (a, b) when the file has an `[edge-extraordinary]`
    /// rule and an end is extraordinary; `None`: the regular `[edge]` rule.
    /// With both ends extraordinary, the mean of the two ends' stencils
    /// (Zorin's convention for the modified butterfly, and our choice here).
    fn extraordinary_edge<W: Weight>(&self, mesh: &PolyMesh, a: usize, b: usize) -> Option<RuleResult<W>> {
        let (size, regular) = self.spec().regular?;
        if !self.ev_edges {
            return None;
        }
        let ends = (extraordinary(mesh, a, size, regular), extraordinary(mesh, b, size, regular));
        Some(match ends {
            (false, false) => return None,
            (true, false) => self.ev_edge(mesh, a, b, size),
            (false, true) => self.ev_edge(mesh, b, a, size),
            (true, true) => self.ev_edge_mean(mesh, a, b, size),
        })
    }

    /// The mean of the `[edge-extraordinary]` stencils from both ends.
    fn ev_edge_mean<W: Weight>(&self, mesh: &PolyMesh, a: usize, b: usize, size: usize) -> RuleResult<W> {
        let (Some(sa), Some(sb)) = (self.ev_edge(mesh, a, b, size)?, self.ev_edge(mesh, b, a, size)?) else {
            return Ok(None);
        };
        let half = W::ratio(1, 2);
        let mut s = Stencil::new();
        s.add_scaled(&sa, &half);
        s.add_scaled(&sb, &half);
        Ok(Some(s))
    }

    fn primal_quad<W: Weight>(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        Ok(match origin {
            Origin::Vertex(v) => {
                let Some(fan) = uniform_fan(mesh, v, 4) else { return Ok(None) };
                let n = fan.len() as i64;
                let mut s = Stencil::new().with(v, self.w("vertex.centre", n, 0)?);
                for (j, face) in fan.iter().enumerate() {
                    s.add(face[1], self.w("vertex.edge", n, j as i64)?);
                    s.add(face[2], self.w("vertex.face", n, j as i64)?);
                }
                Some(s)
            }
            Origin::Edge(a, b) => {
                let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
                    return Ok(None);
                };
                if mesh.face(fl).len() != 4 || mesh.face(fr).len() != 4 {
                    return Ok(None);
                }
                if let Some(result) = self.extraordinary_edge(mesh, a, b) {
                    return result;
                }
                let ends: W = self.w("edge.ends", 4, 0)?;
                let side: W = self.w("edge.side", 4, 0)?;
                let mut s = Stencil::new().with(a, ends.clone()).with(b, ends);
                for cyc in [mesh.face_from(fl, kl), mesh.face_from(fr, kr)] {
                    s.add(cyc[2], side.clone());
                    s.add(cyc[3], side.clone());
                }
                Some(s)
            }
            Origin::Face(f) => {
                let face = mesh.face(f);
                let n = face.len() as i64;
                let mut s = Stencil::new();
                for (j, &v) in face.iter().enumerate() {
                    s.add(v, self.w("face.corner", n, j as i64)?);
                }
                Some(s)
            }
            Origin::Corner { .. } => None,
        })
    }

    fn primal_triangle<W: Weight>(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        Ok(match origin {
            Origin::Vertex(v) => {
                let Some(fan) = uniform_fan(mesh, v, 3) else { return Ok(None) };
                let n = fan.len() as i64;
                let mut s = Stencil::new().with(v, self.w("vertex.centre", n, 0)?);
                for (j, face) in fan.iter().enumerate() {
                    s.add(face[1], self.w("vertex.edge", n, j as i64)?);
                }
                Some(s)
            }
            Origin::Edge(a, b) => {
                let (Some((fl, kl)), Some((fr, kr))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else {
                    return Ok(None);
                };
                if mesh.face(fl).len() != 3 || mesh.face(fr).len() != 3 {
                    return Ok(None);
                }
                if let Some(result) = self.extraordinary_edge(mesh, a, b) {
                    return result;
                }
                let ends: W = self.w("edge.ends", 3, 0)?;
                let opposite: W = self.w("edge.opposite", 3, 0)?;
                Some(
                    Stencil::new()
                        .with(a, ends.clone())
                        .with(b, ends)
                        .with(mesh.face_from(fl, kl)[2], opposite.clone())
                        .with(mesh.face_from(fr, kr)[2], opposite),
                )
            }
            Origin::Face(_) | Origin::Corner { .. } => None,
        })
    }

    fn fcv<W: Weight>(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        if !mesh.has_face_point_on_every_face() {
            return Ok(None);
        }
        Ok(match origin {
            Origin::Vertex(v) => {
                let Some(fan) = mesh.vertex_fan(v) else { return Ok(None) };
                let n = fan.len() as i64;
                let mut s = Stencil::new().with(v, self.w("vertex.centre", n, 0)?);
                for (j, cyc) in fan.iter().enumerate() {
                    let Some(p) = mesh.face_point_left_of(v, cyc[1]) else { return Ok(None) };
                    s.add(p, self.w("vertex.fcv", n, j as i64)?);
                }
                Some(s)
            }
            Origin::Edge(a, b) => {
                let (Some(l), Some(r)) = (mesh.face_point_left_of(a, b), mesh.face_point_left_of(b, a)) else {
                    return Ok(None);
                };
                let ends: W = self.w("edge.ends", 4, 0)?;
                let fcv: W = self.w("edge.fcv", 4, 0)?;
                Some(Stencil::new().with(a, ends.clone()).with(b, ends).with(l, fcv.clone()).with(r, fcv))
            }
            Origin::Face(f) => {
                let Some(p) = mesh.face_point(f) else { return Ok(None) };
                let face = mesh.face(f);
                let n = face.len() as i64;
                let mut s = Stencil::new().with(p, self.w("face.centre", n, 0)?);
                for (j, &v) in face.iter().enumerate() {
                    s.add(v, self.w("face.corner", n, j as i64)?);
                }
                Some(s)
            }
            Origin::Corner { face: f, corner: k } => {
                let cyc = mesh.face_from(f, k);
                let n = cyc.len() as i64;
                let (v0, next, prev) = (cyc[0], cyc[1], cyc[cyc.len() - 1]);
                // the old faces at V_0 next to F_0: across (V_0, next) and across (prev, V_0)
                let (Some(f1), Some(fm1), Some(f0)) =
                    (mesh.face_point_left_of(next, v0), mesh.face_point_left_of(v0, prev), mesh.face_point(f))
                else {
                    return Ok(None);
                };
                let side: W = self.w("corner.side", n, 0)?;
                Some(
                    Stencil::new()
                        .with(v0, self.w("corner.vertex", n, 0)?)
                        .with(f0, self.w("corner.fcv", n, 0)?)
                        .with(f1, side.clone())
                        .with(fm1, side),
                )
            }
        })
    }
}

impl Scheme for UserScheme {
    fn info(&self) -> &SchemeInfo {
        &self.info
    }
    fn params(&self) -> &Params {
        &self.params
    }
}
