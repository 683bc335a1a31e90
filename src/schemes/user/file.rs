//! The scheme file: TOML schema and validation. Everything that can be
//! checked is checked at load time, each error one line naming the line and
//! the field.

use std::collections::BTreeMap;
use std::path::Path;

use serde::de::{self, Deserializer, MapAccess, Visitor};
use serde::Deserialize;
use toml::Spanned;

use super::weights::eval_f64;
use crate::numeric::expr::{Env, Expr};
use crate::numeric::ParamValue;
use crate::schemes::files::shared_format::{
    line_of, parameter_env, parameter_table, read_scheme_file, substitute, ParamDoc, UserParam, WeightSite,
};
use crate::sdc::slots::{Arity, Host, HostSpec, OriginKind, RuleSlots, Valence, HOSTS};

// the caps every scheme file has (one place: `schemes::files::shared_format`)
use crate::error::Error;
use crate::schemes::files::shared_format::{MAX_DESCRIPTION_CHARS, MAX_NAME_CHARS};
pub use crate::schemes::files::shared_format::{MAX_EXPR_CHARS, MAX_FILE_BYTES};
/// Most refinement steps an extraordinary edge rule may be blended over.
const MAX_BLEND_LEVELS: i64 = 12;
/// Valences (and face sizes) at which weights are checked at load time.
const CHECK_N: std::ops::RangeInclusive<i64> = 3..=12;
/// Top-level keys that are not rule sections.
const HEADER: [&str; 7] = ["name", "description", "topology", "affine", "blend-levels", "vertex-param", "params"];

type Section = Spanned<BTreeMap<String, Spanned<toml::Value>>>;

/// The document: header keys typed, every other key a rule section. Written
/// by hand (not derived) because the section names depend on the host, and
/// serde's `flatten` would lose the spans that give error lines.
#[derive(Default)]
struct FileDoc {
    name: Option<Spanned<String>>,
    description: Option<Spanned<String>>,
    topology: Option<Spanned<String>>,
    affine: Option<bool>,
    blend_levels: Option<Spanned<i64>>,
    vertex_param: Option<Spanned<String>>,
    params: BTreeMap<String, Spanned<ParamDoc>>,
    sections: Vec<(String, Section)>,
    /// the first key that is neither a header key nor a rule name, and where
    unknown: Option<Spanned<String>>,
}

impl<'de> Deserialize<'de> for FileDoc {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = FileDoc;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                write!(f, "a scheme file")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<FileDoc, A::Error> {
                let mut doc = FileDoc::default();
                while let Some(spanned) = map.next_key::<Spanned<String>>()? {
                    let key = spanned.get_ref().clone();
                    match key.as_str() {
                        "name" => doc.name = Some(map.next_value()?),
                        "description" => doc.description = Some(map.next_value()?),
                        "topology" => doc.topology = Some(map.next_value()?),
                        "affine" => doc.affine = Some(map.next_value()?),
                        "blend-levels" => doc.blend_levels = Some(map.next_value()?),
                        "vertex-param" => doc.vertex_param = Some(map.next_value()?),
                        "params" => doc.params = map.next_value()?,
                        _ if all_sections().contains(&key.as_str()) => {
                            let s: Section = map.next_value()?;
                            doc.sections.push((key, s));
                        }
                        // reported with its line after the document is read
                        _ => {
                            map.next_value::<de::IgnoredAny>()?;
                            doc.unknown.get_or_insert(spanned);
                        }
                    }
                }
                Ok(doc)
            }
        }
        d.deserialize_map(V)
    }
}

/// Every rule name of every host, each once.
fn all_sections() -> Vec<&'static str> {
    let mut out: Vec<&'static str> = Vec::new();
    for h in HOSTS {
        for r in h.spec().rules {
            if !out.contains(&r.name) {
                out.push(r.name);
            }
        }
    }
    out
}

/// A weight expression and where it was written.
#[derive(Clone, Debug)]
pub(super) struct Field {
    /// "rule.family"
    pub key: String,
    pub family: &'static str,
    pub line: usize,
    pub expr: Expr,
    pub arity: Arity,
    /// the family's slots exist at quads only (`Family::quad_only`)
    pub quad_only: bool,
    pub uses_j: bool,
}

/// One rule section of a file.
#[derive(Clone, Debug)]
pub(super) struct RuleDef {
    pub spec: &'static RuleSlots,
    pub line: usize,
    pub fields: Vec<Field>,
}

/// A parsed scheme file, before parameter values are fixed.
#[derive(Clone, Debug)]
pub struct UserSchemeDef {
    pub(super) file: String,
    pub name: String,
    pub description: String,
    pub(super) host: Host,
    pub affine: bool,
    /// refinement steps 1..=k of a real mesh blend the extraordinary edge
    /// rule with the regular one ((σ−1)/σ and 1/σ), as 4-3 subdivision does
    pub blend_levels: Option<usize>,
    /// a parameter that may vary per vertex (Lin–Luo's α on the sqrt3 host)
    pub vertex_param: Option<String>,
    pub params: Vec<UserParam>,
    pub(super) rules: Vec<RuleDef>,
}

/// The key a TOML error line assigns (`key = ...`), with its table's name
/// (`params.a.min`), so that type errors name the field too; `None` on a
/// line without an assignment (a table header, a syntax error).
fn key_at(text: &str, line: usize) -> Option<String> {
    let lines: Vec<&str> = text.lines().collect();
    let (key, _) = lines.get(line.checked_sub(1)?)?.split_once('=')?;
    let key = key.trim().trim_matches('"');
    let plain = !key.is_empty() && key.chars().all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c));
    if !plain {
        return None;
    }
    let table = lines[..line - 1].iter().rev().map(|l| l.trim()).find(|l| l.starts_with('['));
    Some(match table.map(|t| t.trim_matches(|c| c == '[' || c == ']').trim()) {
        Some(t) => format!("{t}.{key}"),
        None => key.to_string(),
    })
}

/// Where j-dependent weights may go instead, for error messages.
fn j_pointer(spec: &HostSpec) -> &'static str {
    match spec.host {
        Host::PrimalQuad | Host::PrimalTriangle => {
            "; weights that depend on j belong in [edge-extraordinary], where j = 0 is the edge's other end"
        }
        Host::MixedQuadTriangle => {
            "; weights that depend on j belong in [edge-eon], where j = 0 is the edge's other end"
        }
        Host::Fcv | Host::Dual | Host::Sqrt3 | Host::Ternary | Host::AugmentedDual | Host::Polar => "",
    }
}

/// The valences a rule's weights are checked at.
fn check_ns(rule: &RuleSlots) -> std::ops::RangeInclusive<i64> {
    match rule.valence {
        Valence::Any => CHECK_N,
        Valence::Fixed(k) => k as i64..=k as i64,
    }
}

impl UserSchemeDef {
    fn err(&self, line: usize, field: &str, msg: impl std::fmt::Display) -> Error {
        Error::File(format!("{} line {line}, field {field}: {msg}", self.file))
    }

    /// The refinement topology the file names (`primal-triangle`, ...).
    pub fn topology_name(&self) -> &'static str {
        self.host.spec().name
    }

    /// Parse a scheme file's text; `file` names it in error messages.
    pub fn parse(text: &str, file: &str) -> Result<UserSchemeDef, Error> {
        if text.len() > MAX_FILE_BYTES {
            return Err(Error::File(format!("{file}: larger than {MAX_FILE_BYTES} bytes; scheme files are short")));
        }
        let doc: FileDoc = toml::from_str(text).map_err(|e| {
            let msg = e.message().trim().replace('\n', "; ");
            Error::File(match e.span() {
                Some(span) => {
                    let line = line_of(text, span.start);
                    match key_at(text, line) {
                        Some(key) => format!("{file} line {line}, field {key}: {msg}"),
                        None => format!("{file} line {line}: {msg}"),
                    }
                }
                None => format!("{file}: {msg}"),
            })
        })?;
        let cx = Cx { text, file };
        if let Some(key) = &doc.unknown {
            let mut known: Vec<&str> = HEADER.to_vec();
            known.extend(all_sections());
            return Err(Error::File(format!(
                "{file} line {}: unknown field `{}`, expected one of {}",
                cx.line(key.span()),
                key.get_ref(),
                known.join(", ")
            )));
        }
        let Some(doc_name) = &doc.name else { return Err(Error::File(format!("{file}: missing field `name`"))) };
        let name = cx.name(doc_name)?;
        let description = match &doc.description {
            Some(d) if d.get_ref().chars().count() > MAX_DESCRIPTION_CHARS => {
                return Err(cx.err(
                    cx.line(d.span()),
                    "description",
                    format!("longer than {MAX_DESCRIPTION_CHARS} characters"),
                ))
            }
            Some(d) => d.get_ref().replace('\n', " "),
            None => format!("user scheme from {file}"),
        };
        let Some(doc_topology) = &doc.topology else {
            return Err(Error::File(format!("{file}: missing field `topology`")));
        };
        let topo_name = doc_topology.get_ref().as_str();
        let Some(host) = Host::by_name(topo_name) else {
            let known: Vec<_> = HOSTS.iter().map(|h| h.spec().name).collect();
            return Err(cx.err(
                cx.line(doc_topology.span()),
                "topology",
                format!("unknown topology '{topo_name}'; known: {}", known.join(", ")),
            ));
        };
        let params = cx.params(&doc)?;
        let rules = cx.rules(&doc, host.spec(), &params)?;
        let def = UserSchemeDef {
            file: file.to_string(),
            blend_levels: cx.blend_levels(&doc, host.spec(), &rules)?,
            vertex_param: cx.vertex_param(&doc, host, &params)?,
            name,
            description,
            host,
            affine: doc.affine.unwrap_or(true),
            params,
            rules,
        };
        // check the defaults now, so that a file that cannot work fails at load
        def.instantiate(&[])?;
        Ok(def)
    }

    /// Parameter values (the defaults, then `name=value` overrides) and the
    /// rules with every parameter that is not given but has a default rule in
    /// n replaced by that rule, weights checked.
    pub(super) fn instantiate(&self, overrides: &[(String, String)]) -> Result<(Env, Vec<RuleDef>), Error> {
        let env = parameter_env(&self.name, &self.params, overrides)?;
        let mut rules = self.rules.clone();
        for p in &self.params {
            let Some(by) = p.rule.as_ref().filter(|_| !env.contains_key(&p.name)) else { continue };
            for field in rules.iter_mut().flat_map(|r| r.fields.iter_mut()) {
                field.expr = substitute(&field.expr, &p.name, by);
            }
        }
        self.check(&rules, &env)?;
        Ok((env, rules))
    }

    /// Every weight of the rules at the default parameters, at each valence
    /// in `valences` (a rule with a fixed valence at that one), every j the
    /// field is asked for and, for face-corner fields, every corner count m
    /// in `valences`.
    pub fn weight_sites(&self, valences: std::ops::RangeInclusive<i64>) -> Result<Vec<WeightSite>, Error> {
        let (params, rules) = self.instantiate(&[])?;
        let mut out = Vec::new();
        for rule in &rules {
            let ns = match rule.spec.valence {
                Valence::Any => valences.clone(),
                Valence::Fixed(k) => k as i64..=k as i64,
            };
            for field in &rule.fields {
                let corners = matches!(field.arity, Arity::FaceCorners(_));
                let ms: Vec<Option<i64>> = if corners { valences.clone().map(Some).collect() } else { vec![None] };
                for n in ns.clone() {
                    for &m in &ms {
                        for j in 0..field.arity.js(n as usize) as i64 {
                            let mut env = params.clone();
                            env.insert("n".into(), ParamValue::from_ratio(n, 1));
                            env.insert("j".into(), ParamValue::from_ratio(j, 1));
                            if let Some(m) = m {
                                env.insert("m".into(), ParamValue::from_ratio(m, 1));
                            }
                            out.push(WeightSite { field: field.key.clone(), expr: field.expr.clone(), env });
                        }
                    }
                }
            }
        }
        Ok(out)
    }

    /// Every weight must be a finite real number at n = 3..12 (or at the
    /// rule's fixed valence) and, where the rule's j is not canonical, the
    /// same for every j (the first neighbour around a vertex or in a face is
    /// arbitrary, so a weight that varies with j would make the rule depend
    /// on how the mesh is stored); with `affine`, every rule's weights sum to
    /// 1 (at a uniform valence n: a derived point counts as one point; with
    /// face-corner fields, at every uniform corner count m = 3..12).
    fn check(&self, rules: &[RuleDef], params: &Env) -> Result<(), Error> {
        for rule in rules {
            // a rule with face-corner fields takes any polygons: checked at
            // every corner count m (quad-only families at m = 4 only), which
            // makes it affine on fans of mixed faces too, as each face then
            // carries the same share; other rules see quads (m = 4) only
            let polygons = rule.fields.iter().any(|f| matches!(f.arity, Arity::FaceCorners(_)));
            let ms = if polygons { CHECK_N } else { 4..=4 };
            for n in check_ns(rule.spec) {
                for m in ms.clone() {
                    self.check_at(rule, params, n, m, polygons)?;
                }
            }
        }
        Ok(())
    }

    /// One rule at valence n with faces of m corners (`polygons`: m is a
    /// variable of the rule, named in messages).
    fn check_at(&self, rule: &RuleDef, params: &Env, n: i64, m: i64, polygons: bool) -> Result<(), Error> {
        let at = if polygons { format!("n = {n}, m = {m}") } else { format!("n = {n}") };
        // per-quad families: their own sum, per quad
        let (mut sum, mut quad_sum) = (0.0, 0.0);
        for field in rule.fields.iter().filter(|f| m == 4 || !f.quad_only) {
            let corners = matches!(field.arity, Arity::FaceCorners(_));
            let js = if field.uses_j { field.arity.js(n as usize) } else { 1 };
            // j canonical and used: every neighbour has its own weight
            let per_j = rule.spec.canonical_j && field.uses_j;
            let mut first = None;
            for j in 0..js as i64 {
                let w = eval_f64(&field.expr, params, n, j, corners.then_some(m)).map_err(|e| {
                    let m = if corners { format!(", m = {m}") } else { String::new() };
                    self.err(field.line, &field.key, format!("at n = {n}, j = {j}{m}: {e}"))
                })?;
                if per_j {
                    sum += w;
                    continue;
                }
                match first {
                    None => first = Some(w),
                    Some(w0) if (w - w0).abs() > 1e-12 * f64::max(w0.abs(), 1.0) => {
                        return Err(self.err(
                            field.line,
                            &field.key,
                            format!(
                                "the weight differs between j = 0 and j = {j} at {at}; the first neighbour is \
                                 arbitrary, so weights may not depend on j{}",
                                j_pointer(self.host.spec())
                            ),
                        ))
                    }
                    _ => {}
                }
            }
            if per_j {
                continue;
            }
            match field.arity {
                Arity::PerQuad(k) => quad_sum += first.unwrap_or(0.0) * k as f64,
                Arity::Fixed(_) | Arity::PerJ(_) | Arity::FaceCorners(_) => {
                    sum += first.unwrap_or(0.0) * field.arity.count(n as usize, m as usize) as f64
                }
            }
        }
        let section = rule.spec.name;
        if self.affine && quad_sum.abs() > 1e-12 {
            return Err(Error::File(format!(
                "{} line {}, field {section}: the per-quad weights of the {section} rule sum to {quad_sum} per quad \
                 at {at}, not 0 (the fan may have any number of quads; set affine = false to allow this)",
                self.file, rule.line
            )));
        }
        if self.affine && (sum - 1.0).abs() > 1e-12 {
            return Err(Error::File(format!(
                "{} line {}, field {section}: the weights of the {section} rule sum to {sum} at {at}, not 1 (set \
                 affine = false to allow this)",
                self.file, rule.line
            )));
        }
        Ok(())
    }
}

/// The text being parsed, for line numbers and error messages.
struct Cx<'a> {
    text: &'a str,
    file: &'a str,
}

impl Cx<'_> {
    fn line(&self, span: std::ops::Range<usize>) -> usize {
        line_of(self.text, span.start)
    }

    fn err(&self, line: usize, field: &str, msg: impl std::fmt::Display) -> Error {
        Error::File(format!("{} line {line}, field {field}: {msg}", self.file))
    }

    fn name(&self, doc_name: &Spanned<String>) -> Result<String, Error> {
        let name = doc_name.get_ref().trim().to_string();
        let name_ok = !name.is_empty()
            && name.chars().count() <= MAX_NAME_CHARS
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if !name_ok {
            return Err(self.err(
                self.line(doc_name.span()),
                "name",
                format!("'{name}' is not a scheme name (1 to {MAX_NAME_CHARS} letters, digits, '-' or '_')"),
            ));
        }
        // output and claims identify schemes by name: a file must not pass for a built-in
        if crate::schemes::builtins::known_names().contains(&name.as_str()) {
            return Err(self.err(
                self.line(doc_name.span()),
                "name",
                format!("'{name}' is a built-in scheme; choose another name"),
            ));
        }
        Ok(name)
    }

    fn params(&self, doc: &FileDoc) -> Result<Vec<UserParam>, Error> {
        parameter_table(&doc.params, self.text, self.file, true)
    }

    /// The file's rule sections in the host's order, each field parsed.
    fn rules(&self, doc: &FileDoc, spec: &HostSpec, params: &[UserParam]) -> Result<Vec<RuleDef>, Error> {
        // sections the host does not have
        for (section, table) in &doc.sections {
            if spec.rule(section).is_none() {
                let have: Vec<_> = spec.rules.iter().map(|r| r.name).collect();
                return Err(self.err(
                    self.line(table.span()),
                    section,
                    format!("topology {} has no {section} rule (its rules: {})", spec.name, have.join(", ")),
                ));
            }
        }
        let mut rules = Vec::new();
        for rule in spec.rules {
            let section = rule.name;
            let Some((_, table)) = doc.sections.iter().find(|(s, _)| s == section) else {
                if rule.optional {
                    continue;
                }
                return Err(Error::File(format!(
                    "{}: missing section [{section}] (topology {})",
                    self.file, spec.name
                )));
            };
            let section_line = self.line(table.span());
            for (key, value) in table.get_ref() {
                if !rule.families.iter().any(|fs| fs.name == key) {
                    let known: Vec<_> = rule.families.iter().map(|fs| fs.name).collect();
                    return Err(self.err(
                        self.line(value.span()),
                        &format!("{section}.{key}"),
                        format!("unknown field; the {section} rule of {} has {}", spec.name, known.join(", ")),
                    ));
                }
            }
            let mut fields = Vec::new();
            for fs in rule.families {
                let key = format!("{section}.{}", fs.name);
                let Some(value) = table.get_ref().get(fs.name) else {
                    if fs.optional {
                        continue;
                    }
                    return Err(self.err(section_line, &key, "missing (write 0 for a zero weight)"));
                };
                let line = self.line(value.span());
                let source = match value.get_ref() {
                    toml::Value::String(s) => s.clone(),
                    toml::Value::Integer(k) => k.to_string(),
                    toml::Value::Float(x) => format!("{x}"),
                    other => {
                        return Err(self.err(
                            line,
                            &key,
                            format!("expected an expression string, got a {}", other.type_str()),
                        ))
                    }
                };
                if source.chars().count() > MAX_EXPR_CHARS {
                    return Err(self.err(line, &key, format!("expression longer than {MAX_EXPR_CHARS} characters")));
                }
                let expr = Expr::parse(&source).map_err(|e| self.err(line, &key, e))?;
                let has_n = rule.valence == Valence::Any;
                let corners = matches!(fs.arity, Arity::FaceCorners(_));
                // in a face-corner field m is the face's corner count: a
                // parameter of that name would be ambiguous there
                if corners && params.iter().any(|p| p.name == "m") {
                    return Err(self.err(
                        line,
                        &key,
                        "the parameter 'm' hides the corner count m of face-corner fields; rename it",
                    ));
                }
                // a default rule in n is substituted for its parameter: only where there is an n
                let by_rule = params.iter().find(|p| p.rule.is_some() && expr.variables().contains(&p.name));
                if let (false, Some(p)) = (has_n, by_rule) {
                    return Err(self.err(
                        line,
                        &key,
                        format!(
                            "parameter '{}' defaults to a rule in the valence n, which {section} rules do not have; \
                             give it a number default",
                            p.name
                        ),
                    ));
                }
                for var in expr.variables() {
                    let allowed = (var == "n" && has_n)
                        || (var == "j"
                            && matches!(fs.arity, Arity::PerJ(_) | Arity::PerQuad(_) | Arity::FaceCorners(_)))
                        || (var == "m" && corners)
                        || params.iter().any(|p| p.name == var);
                    if !allowed {
                        let hint = match var.as_str() {
                            "j" if rule.canonical_j => " (j indexes neighbours only in per-neighbour fields)".into(),
                            "j" => format!(" (j indexes neighbours only in per-neighbour fields{})", j_pointer(spec)),
                            "n" => format!(" ({section} rules have no valence n)"),
                            "m" => " (m, a face's corner count, is a variable of face-corner fields only)".into(),
                            _ => String::new(),
                        };
                        return Err(self.err(line, &key, format!("unknown variable '{var}'{hint}")));
                    }
                }
                let uses_j = expr.variables().iter().any(|v| v == "j");
                fields.push(Field {
                    key,
                    family: fs.name,
                    line,
                    expr,
                    arity: fs.arity,
                    quad_only: fs.quad_only,
                    uses_j,
                });
            }
            rules.push(RuleDef { spec: rule, line: section_line, fields });
        }
        Ok(rules)
    }

    fn blend_levels(&self, doc: &FileDoc, spec: &HostSpec, rules: &[RuleDef]) -> Result<Option<usize>, Error> {
        let Some(b) = &doc.blend_levels else { return Ok(None) };
        let line = self.line(b.span());
        let k = *b.get_ref();
        // the extraordinary edge rule: the optional edge rule whose j is
        // canonical ([edge-extraordinary], [edge-eon])
        let ev = spec.rules.iter().find(|r| r.canonical_j && r.optional && r.origin == OriginKind::Edge);
        let Some(ev) = ev else {
            return Err(self.err(
                line,
                "blend-levels",
                format!("topology {} has no extraordinary edge rule to blend", spec.name),
            ));
        };
        if !rules.iter().any(|r| r.spec.name == ev.name) {
            return Err(self.err(
                line,
                "blend-levels",
                format!("blends the [{}] rule, which the file does not give", ev.name),
            ));
        }
        if !(1..=MAX_BLEND_LEVELS).contains(&k) {
            return Err(self.err(line, "blend-levels", format!("{k} is not in 1..{MAX_BLEND_LEVELS}")));
        }
        Ok(Some(k as usize))
    }

    fn vertex_param(&self, doc: &FileDoc, host: Host, params: &[UserParam]) -> Result<Option<String>, Error> {
        let Some(v) = &doc.vertex_param else { return Ok(None) };
        let line = self.line(v.span());
        let name = v.get_ref();
        // only the sqrt(3) host has a rule for the parameter of new vertices
        // (Lin–Luo eq. 7: the mean of the parents')
        if host != Host::Sqrt3 {
            return Err(self.err(
                line,
                "vertex-param",
                format!("topology {} has no per-vertex parameters (sqrt3 has)", host.spec().name),
            ));
        }
        if !params.iter().any(|p| &p.name == name) {
            return Err(self.err(line, "vertex-param", format!("'{name}' is not a parameter of the file")));
        }
        // per-vertex values replace a number; a default rule in n has none
        if params.iter().any(|p| &p.name == name && p.rule.is_some()) {
            return Err(self.err(line, "vertex-param", format!("'{name}' needs a number default")));
        }
        Ok(Some(name.clone()))
    }
}

/// Read and parse a scheme file (size capped before reading it all).
pub fn load_def(path: &Path) -> Result<UserSchemeDef, Error> {
    let shown = path.display().to_string();
    let text = read_scheme_file(path)?;
    UserSchemeDef::parse(&text, &shown)
}
