//! Reading claim files: TOML into [`ClaimFile`]s, with every malformed
//! claim (an unknown check or key, a missing field, a value of the wrong
//! type, a repeated id) kept as a claim whose check is `Check::Malformed`
//! naming the file and line, so the others are still evaluated. The
//! built-in registry's files are compiled in.

use crate::claims::checks::{Check, CHECK_KEYS, TAKES_SUBJECT};
use crate::claims::claim::{Claim, ClaimFile};
use crate::error::Error;

/// Keys of every claim.
pub const COMMON_KEYS: &[&str] = &["id", "location", "statement", "convention", "expected", "by_construction", "check"];
/// Keys of the checks that analyse a scheme (`CheckKind::TAKES_SUBJECT`:
/// all but identity, matrix-eigenvalues, lattice-matrix and builtin).
pub const SUBJECT_KEYS: &[&str] = &["scheme", "valences", "faces", "params", "neighbourhood", "tag", "vars"];

/// The built-in registry: one file per source paper, compiled in.
pub const BUILTIN: &[(&str, &str)] = &[
    ("huang-nonbox", include_str!("../../claims/huang-nonbox.toml")),
    ("khan-mustafa", include_str!("../../claims/khan-mustafa.toml")),
    ("lin-luo", include_str!("../../claims/lin-luo.toml")),
    ("peters-shiue", include_str!("../../claims/peters-shiue.toml")),
    ("karciauskas-peters", include_str!("../../claims/karciauskas-peters.toml")),
    ("known-results", include_str!("../../claims/known-results.toml")),
];

/// Reads a claim file. A TOML syntax error or a bad top level (paper,
/// title, figures) fails the file; a malformed claim (an unknown key, a
/// missing field, a value of the wrong type, a repeated id) becomes a claim
/// whose check is [`Check::Malformed`], so the others are still evaluated.
/// Errors name the file and the line.
pub fn parse_file(name: &str, text: &str) -> Result<ClaimFile, Error> {
    let short = |e: &dyn std::fmt::Display| {
        let msg = e.to_string();
        // toml reports "TOML parse error at line L, column C" first; keep the message short
        let first = msg.lines().next().unwrap_or("").trim().to_string();
        let detail = msg.lines().last().unwrap_or("").trim().to_string();
        if first == detail {
            first
        } else {
            format!("{first}: {detail}")
        }
    };
    let mut table: toml::Table = toml::from_str(text).map_err(|e| Error::File(format!("{name}: {}", short(&e))))?;
    let raw_claims = match table.remove("claim") {
        None => Vec::new(),
        Some(toml::Value::Array(a)) => a,
        Some(_) => return Err(Error::File(format!("{name}: 'claim' must be an array of tables ([[claim]])"))),
    };
    let mut f: ClaimFile =
        toml::Value::Table(table).try_into().map_err(|e| Error::File(format!("{name}: {}", short(&e))))?;
    let headers = claim_header_lines(text);
    let mut seen = std::collections::HashSet::new();
    for (k, raw) in raw_claims.into_iter().enumerate() {
        let header = headers.get(k).copied();
        let mut claim = read_claim(name, k, header, text, raw);
        if !seen.insert(claim.id.clone()) && !matches!(claim.check, Check::Malformed(_)) {
            let at = header.map(|l| format!(" line {l}")).unwrap_or_default();
            claim.check = Check::Malformed(format!("{name}{at}: claim id '{}' appears twice", claim.id));
        }
        f.claims.push(claim);
    }
    Ok(f)
}

/// The 1-based line of each `[[claim]]` header, in order.
fn claim_header_lines(text: &str) -> Vec<usize> {
    text.lines()
        .enumerate()
        .filter(|(_, l)| {
            let t: String = l.split('#').next().unwrap_or("").chars().filter(|c| !c.is_whitespace()).collect();
            t == "[[claim]]"
        })
        .map(|(k, _)| k + 1)
        .collect()
}

/// The line of `key = ...` in the claim whose header is on line `header`.
fn key_line(text: &str, header: usize, key: &str) -> Option<usize> {
    for (k, line) in text.lines().enumerate().skip(header) {
        let t = line.trim_start();
        if t.starts_with('[') {
            return None;
        }
        let name = t.split(['=', '.']).next().unwrap_or("").trim().trim_matches('"').trim_matches('\'');
        if name == key && t.contains('=') {
            return Some(k + 1);
        }
    }
    None
}

fn read_claim(file: &str, k: usize, header: Option<usize>, text: &str, raw: toml::Value) -> Claim {
    let get = |key: &str| raw.get(key).and_then(|v| v.as_str()).map(str::to_string);
    let id = get("id").unwrap_or_else(|| format!("claim-{}", k + 1));
    let at = |line: Option<usize>| match line {
        Some(l) => format!("{file} line {l}: claim {} ('{id}')", k + 1),
        None => format!("{file}: claim {} ('{id}')", k + 1),
    };
    let malformed = |message: String| Claim {
        id: id.clone(),
        location: get("location").unwrap_or_default(),
        statement: get("statement").unwrap_or_default(),
        convention: get("convention"),
        expected: raw.get("expected").and_then(|v| v.clone().try_into().ok()),
        by_construction: get("by_construction"),
        check: Check::Malformed(message),
    };
    let Some(table) = raw.as_table() else {
        return malformed(format!("{}: a claim must be a table", at(header)));
    };
    let kind = match table.get("check") {
        Some(toml::Value::String(c)) => c.as_str(),
        Some(_) => return malformed(format!("{}: 'check' must be a string", at(header))),
        None => return malformed(format!("{}: missing field 'check'", at(header))),
    };
    let Some((_, own)) = CHECK_KEYS.iter().find(|(c, _)| *c == kind) else {
        let kinds: Vec<&str> = CHECK_KEYS.iter().map(|(c, _)| *c).collect();
        let line = header.and_then(|h| key_line(text, h, "check"));
        return malformed(format!("{}: unknown check '{kind}'; the checks are {}", at(line), kinds.join(", ")));
    };
    let scheme_based = TAKES_SUBJECT.iter().any(|(c, takes)| *c == kind && *takes);
    let allowed =
        |key: &str| COMMON_KEYS.contains(&key) || own.contains(&key) || (scheme_based && SUBJECT_KEYS.contains(&key));
    if let Some(key) = table.keys().find(|key| !allowed(key)) {
        let mut known: Vec<&str> = COMMON_KEYS.to_vec();
        if scheme_based {
            known.extend(SUBJECT_KEYS);
        }
        known.extend(own.iter());
        let line = header.and_then(|h| key_line(text, h, key));
        return malformed(format!(
            "{}: unknown key '{key}' for check '{kind}'; its keys are {}",
            at(line),
            known.join(", ")
        ));
    }
    // a certificate speaks about the analysis neighbourhood only: a
    // certified claim on the minimal invariant set asks for a proof that
    // would say nothing of the eigenvalues the analysis set adds
    let certified = table.get("certified").and_then(toml::Value::as_bool) == Some(true);
    if certified && table.get("neighbourhood").and_then(toml::Value::as_str) == Some("minimal") {
        let line = header.and_then(|h| key_line(text, h, "neighbourhood"));
        return malformed(format!(
            "{}: certified = true proves statements about the analysis neighbourhood only; drop neighbourhood = \"minimal\"",
            at(line)
        ));
    }
    match raw.clone().try_into::<Claim>() {
        Ok(c) => c,
        Err(e) => {
            let msg = e.to_string();
            let detail = msg.lines().last().unwrap_or("").trim().to_string();
            malformed(format!("{}: {detail}", at(header)))
        }
    }
}

/// The built-in registry's files. Every registry claim cites its place in
/// the paper: one without a `location` is malformed (an ERROR) here.
pub fn builtin_files() -> Result<Vec<ClaimFile>, Error> {
    BUILTIN
        .iter()
        .map(|(name, text)| {
            let mut f = parse_file(name, text)?;
            for c in &mut f.claims {
                if c.location.trim().is_empty() && !matches!(c.check, Check::Malformed(_)) {
                    c.check = Check::Malformed(format!(
                        "{name}: claim '{}' has no location (every registry claim cites its place in the paper)",
                        c.id
                    ));
                }
            }
            Ok(f)
        })
        .collect()
}
