//! What the scheme file formats share (mesh files in `schemes::user`, lattice
//! and curve files here): the size caps, reading a file, the header (`Head`:
//! name, description, `affine`, `[params.NAME]` tables, `UserParam`), error
//! texts with file and line, weight expressions and their evaluation, offset
//! keys, and the weight sites a file defines (`WeightSite`). Imports no file
//! format, so that every format and the router (`files/mod.rs`) import it.

use std::collections::{BTreeMap, HashSet};
use std::path::Path;
use std::sync::Mutex;

use serde::Deserialize;
use toml::Spanned;

use crate::error::Error;
use crate::numeric::expr::{Env, Expr};
use crate::numeric::{Cyclotomic, Interval, ParamValue, Rational, Reading, Weight};
use crate::schemes::builtins::known_names;
use crate::sdc::Params;

/// Scheme files are a few dozen lines; the caps keep a malformed or hostile
/// file from costing unbounded time or memory (mesh, lattice and curve files).
pub const MAX_FILE_BYTES: usize = 64 * 1024;
pub const MAX_EXPR_CHARS: usize = 1000;
pub(crate) const MAX_NAME_CHARS: usize = 64;
pub(crate) const MAX_DESCRIPTION_CHARS: usize = 1000;
const MAX_PARAMS: usize = 16;
/// Largest |offset| a mask may use: masks are local, and the window search
/// follows them level by level.
pub const MAX_OFFSET: i64 = 32;
/// Names the expression language reserves.
const RESERVED: [&str; 11] = ["n", "j", "pi", "i", "cos", "sin", "sqrt", "cbrt", "abs", "kronecker", "sum"];

/// A TOML table whose values keep their positions in the file.
pub(crate) type Section = Spanned<BTreeMap<String, Spanned<toml::Value>>>;

/// Read a scheme file of any family (size capped before reading it all).
pub(crate) fn read_scheme_file(path: &Path) -> Result<String, Error> {
    use std::io::Read;
    let shown = path.display().to_string();
    let file = std::fs::File::open(path).map_err(|e| Error::File(format!("cannot read scheme file {shown}: {e}")))?;
    let mut bytes = Vec::new();
    file.take(MAX_FILE_BYTES as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Error::File(format!("cannot read scheme file {shown}: {e}")))?;
    if bytes.len() > MAX_FILE_BYTES {
        return Err(Error::File(format!("{shown}: larger than {MAX_FILE_BYTES} bytes; scheme files are short")));
    }
    crate::io::decode_text(bytes).map_err(|_| Error::File(format!("{shown}: not UTF-8 text")))
}

/// One weight of a scheme file at one point of its rules: the field that
/// writes it, its expression, and the variables it is evaluated with (the
/// parameters at their defaults, and for mesh files n, j and m).
#[derive(Clone, Debug)]
pub struct WeightSite {
    /// "rule.family" (mesh files) or "section.\"offset\"" (lattice and curve files)
    pub field: String,
    pub expr: Expr,
    pub env: Env,
}

/// A parameter of a scheme file (any family).
#[derive(Clone, Debug)]
pub struct UserParam {
    pub name: String,
    /// the default value; empty text (and no value) when `rule` is the default
    pub default: ParamValue,
    /// a default that is an expression in the valence n (a built-in's
    /// "scheme rule" default): the parameter is absent until given, and the
    /// expression stands in for it in every weight
    pub rule: Option<Expr>,
    pub min: f64,
    pub max: f64,
    pub description: String,
}

pub(crate) fn line_of(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())].iter().filter(|&&b| b == b'\n').count() + 1
}

/// "FILE line L, field F: message", the form of every scheme-file error.
pub(crate) fn field_error(file: &str, line: usize, field: &str, msg: impl std::fmt::Display) -> Error {
    Error::File(format!("{file} line {line}, field {field}: {msg}"))
}

/// The error of an affine file whose rule (or mask) `section` does not sum
/// to 1: every family words it alike.
pub(crate) fn not_affine(head: &Head, line: usize, section: &str, what: &str, sum: impl std::fmt::Display) -> Error {
    field_error(
        &head.file,
        line,
        section,
        format!("the weights of the {section} {what} sum to {sum}, not 1 (set affine = false to allow this)"),
    )
}

/// The TOML parser's error as one line with the file and line.
pub(crate) fn toml_error(e: toml::de::Error, text: &str, file: &str) -> Error {
    let msg = e.message().trim().replace('\n', "; ");
    Error::File(match e.span() {
        Some(span) => format!("{file} line {}: {msg}", line_of(text, span.start)),
        None => format!("{file}: {msg}"),
    })
}

/// A parameter table as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ParamDoc {
    default: Spanned<toml::Value>,
    min: Option<Spanned<toml::Value>>,
    max: Option<Spanned<toml::Value>>,
    description: Option<String>,
}

/// A number in the file: strings are parsed as numbers (3/8, 0.375), TOML
/// integers and floats taken as written.
pub(crate) fn literal(v: &toml::Value) -> Result<ParamValue, Error> {
    match v {
        toml::Value::String(s) => ParamValue::parse(s),
        toml::Value::Integer(k) => Ok(ParamValue::from_ratio(*k, 1)),
        // the shortest decimal that round-trips, so 0.375 is exactly 3/8
        toml::Value::Float(x) => ParamValue::parse(&format!("{x}")),
        other => Err(Error::File(format!("expected a number, got a {}", other.type_str()))),
    }
}

/// The `[params.NAME]` tables of a scheme file (mesh, lattice or curve),
/// checked: names are identifiers and not reserved, min and max are numbers,
/// and the default is a number in [min, max] or, where rules have a valence
/// (`valence`: mesh files), an expression in n (the parameter is then absent
/// until given, as a built-in's parameter with the scheme's own rule for a
/// default). Errors name line and field.
pub(crate) fn parameter_table(
    params: &BTreeMap<String, Spanned<ParamDoc>>,
    text: &str,
    file: &str,
    valence: bool,
) -> Result<Vec<UserParam>, Error> {
    let at = |span: std::ops::Range<usize>| line_of(text, span.start);
    let err = |line: usize, field: &str, msg: &dyn std::fmt::Display| field_error(file, line, field, msg);
    if params.len() > MAX_PARAMS {
        return Err(Error::File(format!("{file}: more than {MAX_PARAMS} parameters")));
    }
    let mut out = Vec::new();
    for (pname, p) in params {
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
        let default_at = at(p.default.span());
        let default_key = format!("{key}.default");
        let (default, rule) = match (literal(p.default.get_ref()), p.default.get_ref()) {
            (Ok(v), _) => (v, None),
            // not a number: the built-ins' "scheme rule" default, a formula
            // in the valence that stands for the parameter until it is given
            (Err(e), toml::Value::String(s)) => {
                if s.chars().count() > MAX_EXPR_CHARS {
                    return Err(err(
                        default_at,
                        &default_key,
                        &format!("expression longer than {MAX_EXPR_CHARS} characters"),
                    ));
                }
                // a string that is neither a number nor an expression in n keeps the number's error
                let in_n = Expr::parse(s).ok().filter(|x| x.variables().iter().any(|v| v == "n"));
                let Some(expr) = in_n else { return Err(err(default_at, &default_key, &e)) };
                if let Some(v) = expr.variables().into_iter().find(|v| v != "n") {
                    return Err(err(
                        default_at,
                        &default_key,
                        &format!("a default is a number or an expression in the valence n only (found '{v}')"),
                    ));
                }
                if !valence {
                    return Err(err(
                        default_at,
                        &default_key,
                        &"a default in the valence n needs a mesh scheme file (lattice and curve rules have no n)",
                    ));
                }
                (ParamValue { value: f64::NAN, exact: None, text: String::new() }, Some(expr))
            }
            (Err(e), _) => return Err(err(default_at, &default_key, &e)),
        };
        let bound = |b: &Option<Spanned<toml::Value>>, which: &str, none: f64| -> Result<f64, Error> {
            match b {
                None => Ok(none),
                Some(v) => {
                    literal(v.get_ref()).map(|x| x.value).map_err(|e| err(at(v.span()), &format!("{key}.{which}"), &e))
                }
            }
        };
        let (min, max) = (bound(&p.min, "min", f64::NEG_INFINITY)?, bound(&p.max, "max", f64::INFINITY)?);
        if !(min <= max && (rule.is_some() || (default.value >= min && default.value <= max))) {
            return Err(err(line, &key, &format!("default {} is not in [{min}, {max}]", default.text)));
        }
        out.push(UserParam {
            name: pname.clone(),
            default,
            rule,
            min,
            max,
            description: p.description.clone().unwrap_or_default(),
        });
    }
    Ok(out)
}

/// A file's parameter values: the defaults, then `name=value` overrides,
/// each checked against the parameter's range (mesh, lattice and curve files
/// alike, with the built-ins' wording).
pub(crate) fn parameter_env(scheme: &str, params: &[UserParam], overrides: &[(String, String)]) -> Result<Env, Error> {
    let mut env = Env::new();
    // a parameter whose default is a rule in n is absent until given (its
    // rule is substituted into the weights instead: `substitute`)
    for p in params.iter().filter(|p| p.rule.is_none()) {
        env.insert(p.name.clone(), p.default.clone());
    }
    for (name, text) in overrides {
        let Some(p) = params.iter().find(|p| &p.name == name) else {
            let known: Vec<_> = params.iter().map(|p| p.name.as_str()).collect();
            return Err(Error::Input(if known.is_empty() {
                format!("scheme '{scheme}' has no parameters (got '{name}')")
            } else {
                format!("scheme '{scheme}' has no parameter '{name}'; its parameters: {}", known.join(", "))
            }));
        };
        let v = ParamValue::parse(text).map_err(|e| Error::Input(format!("parameter {name}: {e}")))?;
        if v.value < p.min || v.value > p.max {
            return Err(Error::Input(format!(
                "parameter {name}={text} is out of range [{}, {}] for scheme '{scheme}'",
                p.min, p.max
            )));
        }
        env.insert(name.clone(), v);
    }
    Ok(env)
}

/// The parameter values a built scheme reports: every parameter with a value
/// (one whose default is a rule in n only when given, as the built-ins').
pub(crate) fn given_values(params: &[UserParam], env: &Env) -> Vec<(String, ParamValue)> {
    params.iter().filter_map(|p| Some((p.name.clone(), env.get(&p.name)?.clone()))).collect()
}

/// `expr` with every free occurrence of the variable `name` replaced by
/// `by` (a parameter's default rule in n, where the parameter is not given).
/// A sum that binds `name` hides it in its summand; `by` has no variable but
/// n, which no sum may bind (n is always in the environment), so nothing in
/// `by` is captured.
pub(crate) fn substitute(expr: &Expr, name: &str, by: &Expr) -> Expr {
    let sub = |e: &Expr| Box::new(substitute(e, name, by));
    match expr {
        Expr::Var(v) if v == name => by.clone(),
        Expr::Var(_) | Expr::Num(..) | Expr::Pi | Expr::I => expr.clone(),
        Expr::Neg(a) => Expr::Neg(sub(a)),
        Expr::Call(f, a) => Expr::Call(f.clone(), sub(a)),
        Expr::Bin(op, a, b) => Expr::Bin(*op, sub(a), sub(b)),
        Expr::Chain(first, rest) => {
            Expr::Chain(sub(first), rest.iter().map(|(op, e)| (*op, substitute(e, name, by))).collect())
        }
        Expr::Sum(v, from, to, body) => {
            let body = if v == name { body.clone() } else { sub(body) };
            Expr::Sum(v.clone(), sub(from), sub(to), body)
        }
    }
}

/// The keys every lattice and curve file has, checked.
#[derive(Clone, Debug)]
pub struct Head {
    pub file: String,
    pub name: String,
    pub description: String,
    pub affine: bool,
    pub params: Vec<UserParam>,
}

impl Head {
    /// Check the name (a scheme name, not a built-in one), the description and
    /// the parameter tables.
    pub(crate) fn parse(
        text: &str,
        file: &str,
        name: &Spanned<String>,
        description: &Option<Spanned<String>>,
        affine: Option<bool>,
        params: &BTreeMap<String, Spanned<ParamDoc>>,
    ) -> Result<Head, Error> {
        let at = |span: std::ops::Range<usize>| line_of(text, span.start);
        let err = |line: usize, field: &str, msg: &dyn std::fmt::Display| field_error(file, line, field, msg);
        let shown = name.get_ref().trim().to_string();
        let ok = !shown.is_empty()
            && shown.chars().count() <= MAX_NAME_CHARS
            && shown.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if !ok {
            return Err(err(
                at(name.span()),
                "name",
                &format!("'{shown}' is not a scheme name (1 to {MAX_NAME_CHARS} letters, digits, '-' or '_')"),
            ));
        }
        // output and claims identify schemes by name: a file must not pass for a built-in
        if known_names().contains(&shown.as_str()) {
            return Err(err(at(name.span()), "name", &format!("'{shown}' is a built-in scheme; choose another name")));
        }
        let description = match description {
            Some(d) if d.get_ref().chars().count() > MAX_DESCRIPTION_CHARS => {
                return Err(err(
                    at(d.span()),
                    "description",
                    &format!("longer than {MAX_DESCRIPTION_CHARS} characters"),
                ))
            }
            Some(d) => d.get_ref().replace('\n', " "),
            None => format!("scheme file {file}"),
        };
        let out = parameter_table(params, text, file, false)?;
        Ok(Head { file: file.to_string(), name: shown, description, affine: affine.unwrap_or(true), params: out })
    }

    /// Parameter values: the defaults, then `name=value` overrides (range-checked).
    pub(crate) fn values(&self, overrides: &[(String, String)]) -> Result<(Env, Params), Error> {
        let env = parameter_env(&self.name, &self.params, overrides)?;
        let values = given_values(&self.params, &env);
        Ok((env, Params { values }))
    }

    /// A weight expression from a TOML value (string, integer or float), with
    /// no variables but the parameters.
    pub(crate) fn expr(&self, value: &toml::Value, line: usize, field: &str) -> Result<Expr, Error> {
        let err = |msg: &dyn std::fmt::Display| field_error(&self.file, line, field, msg);
        let source = match value {
            toml::Value::String(s) => s.clone(),
            toml::Value::Integer(k) => k.to_string(),
            toml::Value::Float(x) => format!("{x}"),
            other => return Err(err(&format!("expected an expression string, got a {}", other.type_str()))),
        };
        if source.chars().count() > MAX_EXPR_CHARS {
            return Err(err(&format!("expression longer than {MAX_EXPR_CHARS} characters")));
        }
        let expr = Expr::parse(&source).map_err(|e| err(&e))?;
        for var in expr.variables() {
            if !self.params.iter().any(|p| p.name == var) {
                let hint =
                    if var == "n" || var == "j" { " (lattice and curve masks have no valence or index)" } else { "" };
                return Err(err(&format!("unknown variable '{var}'{hint}")));
            }
        }
        Ok(expr)
    }
}

/// A weight of a mask: its offset, its expression and where it was written.
#[derive(Clone, Debug)]
pub(crate) struct Term<O> {
    pub offset: O,
    pub expr: Expr,
    pub line: usize,
    pub field: String,
}

impl<O> Term<O> {
    /// The same weight without its offset.
    pub(crate) fn unplaced(&self) -> Term<()> {
        Term { offset: (), expr: self.expr.clone(), line: self.line, field: self.field.clone() }
    }
}

/// A weight evaluated: the float always, the rational when the expression has
/// an exact rational value at these parameter values.
pub(crate) struct Value {
    pub float: f64,
    pub exact: Option<Rational>,
}

/// Evaluate a weight, `scale` times the term's expression. Each factor is
/// read exactly where it can be (`Expr::reading`), so the float is the exact
/// value rounded and cannot describe another mask than the exact one. An
/// error names the field when the value is not a finite real number.
pub(crate) fn evaluate<O>(head: &Head, term: &Term<O>, scale: Option<&Term<()>>, env: &Env) -> Result<Value, Error> {
    let err = |t_line: usize, field: &str, msg: &dyn std::fmt::Display| field_error(&head.file, t_line, field, msg);
    let one = |t_line: usize, field: &str, e: &Expr| -> Result<Reading, Error> {
        let r = e.reading(env).map_err(|m| err(t_line, field, &m))?;
        r.real().map_err(|m| err(t_line, field, &m))?;
        Ok(r)
    };
    let v = one(term.line, &term.field, &term.expr)?;
    let Some(s) = scale else {
        return Ok(Value { float: v.real()?, exact: v.rational().cloned() });
    };
    let f = one(s.line, &s.field, &s.expr)?;
    let floats = v.real()? * f.real()?;
    Ok(match (v, f) {
        // the float of an exact weight is its correctly rounded value, as a
        // built-in's `W::ratio(p, q)` is, not the product of rounded factors
        (Reading::Rational(a), Reading::Rational(b)) => {
            let q = a * b;
            Value { float: Weight::to_f64(&q), exact: Some(q) }
        }
        (Reading::Float(_), _) | (_, Reading::Float(_)) => Value { float: floats, exact: None },
        (a, b) => {
            let product = |r: Reading| match r {
                Reading::Rational(q) => Cyclotomic::from_rational(&q),
                Reading::Cyclotomic(c, _) => c,
                Reading::Float(_) => unreachable!("float readings are handled above"),
            };
            let c = product(a) * product(b);
            Value { float: Reading::Cyclotomic(c.clone(), Interval::from_cyclotomic(&c).ok()).real()?, exact: None }
        }
    })
}

/// A scheme's name and description live for the rest of the process (the
/// scheme traits return `&'static str`); each distinct string is leaked once.
pub(crate) fn intern(s: &str) -> &'static str {
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

/// Parse an offset key: `dims` integers separated by commas, each within
/// ±`MAX_OFFSET`.
pub(crate) fn offset_key(key: &str, dims: usize) -> Result<Vec<i64>, Error> {
    let what = if dims == 1 { "an integer offset such as \"-1\"" } else { "an offset \"r,s\" such as \"-1,0\"" };
    let parts: Vec<&str> = key.split(',').map(str::trim).collect();
    if parts.len() != dims {
        return Err(Error::File(format!("'{key}' is not {what}")));
    }
    parts
        .iter()
        .map(|p| {
            let v: i64 = p.parse().map_err(|_| Error::File(format!("'{key}' is not {what}")))?;
            if v.abs() > MAX_OFFSET {
                return Err(Error::File(format!("offset {v} is beyond ±{MAX_OFFSET}: masks are local")));
            }
            Ok(v)
        })
        .collect()
}

/// A rule's weighted offsets and its optional common factor.
pub(crate) type RuleTerms<O> = (Vec<Term<O>>, Option<Term<()>>);

/// The terms of one rule's table: every key an offset (or `scale`, a common
/// factor, when `allow_scale`), no offset twice.
pub(crate) fn rule_terms<O: PartialEq + Copy + std::fmt::Debug>(
    head: &Head,
    text: &str,
    section: &str,
    table: &Section,
    parse_offset: impl Fn(&str) -> Result<O, Error>,
) -> Result<RuleTerms<O>, Error> {
    let mut terms: Vec<Term<O>> = Vec::new();
    let mut scale = None;
    for (key, value) in table.get_ref() {
        let line = line_of(text, value.span().start);
        let field = format!("{section}.\"{key}\"");
        if key == "scale" {
            let expr = head.expr(value.get_ref(), line, &format!("{section}.scale"))?;
            scale = Some(Term { offset: (), expr, line, field: format!("{section}.scale") });
            continue;
        }
        let offset = parse_offset(key).map_err(|e| field_error(&head.file, line, &field, e))?;
        if let Some(t) = terms.iter().find(|t| t.offset == offset) {
            return Err(field_error(
                &head.file,
                line,
                &field,
                format!("offset {offset:?} is already given on line {}", t.line),
            ));
        }
        let expr = head.expr(value.get_ref(), line, &field)?;
        terms.push(Term { offset, expr, line, field });
    }
    if terms.is_empty() {
        return Err(field_error(
            &head.file,
            line_of(text, table.span().start),
            section,
            "the rule has no weights (keys are offsets)",
        ));
    }
    Ok((terms, scale))
}
