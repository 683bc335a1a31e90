//! Paper statements as data (`claims/*.toml`), evaluated against the tool's
//! computations: every claim ends HOLDS, REFUTED (with the numbers that show
//! it), INCONCLUSIVE (the computation ran and could not decide, with the
//! reason) or ERROR (the claim cannot be read as written, or asserts
//! nothing: see [`checks::undecided`] and [`Check::validate`]).
//!
//! A claim file names its paper and lists claims; each claim has an id, where
//! it stands in the paper, the statement as printed, the convention it uses,
//! and a `check` saying how it is evaluated (see [`Check`]). Values are
//! expressions (`numeric::expr`) in the valence `n` (alias `k`), the Fourier
//! block index `m` where relevant, and the scheme's parameters by name.

pub mod builtin;
pub mod checks;
pub mod curvature;
pub mod invariant_set;
mod schedule;

use std::collections::BTreeMap;

use crate::error::Error;
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClaimFile {
    /// short paper key, e.g. "huang-nonbox"
    pub paper: String,
    pub title: String,
    /// the full reference (authors, title, venue, year) the report cites
    #[serde(default)]
    pub citation: Option<String>,
    /// figures for the paper's report page (characteristic rings, spectra)
    #[serde(default, rename = "figure")]
    pub figures: Vec<FigureSpec>,
    /// admissible-interval figures (`subdlab sweep --plot`) for the report page
    #[serde(default, rename = "sweep")]
    pub sweeps: Vec<SweepFigureSpec>,
    #[serde(default, rename = "claim")]
    pub claims: Vec<Claim>,
}

/// A sweep figure of the report: `scheme` over `valences` ("A..B") and one
/// swept parameter `param` ("NAME=START:END:STEP"), with reference `bounds`
/// (expressions in n) drawn across the rows and a `caption` saying what they are.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFigureSpec {
    pub scheme: String,
    pub valences: String,
    pub param: String,
    #[serde(default)]
    pub params: BTreeMap<String, String>,
    #[serde(default)]
    pub charmap: bool,
    /// levels and resolution of the characteristic-map check (default: `subdlab charmap`'s)
    #[serde(default)]
    pub levels: Option<usize>,
    #[serde(default)]
    pub resolution: Option<usize>,
    #[serde(default)]
    pub bounds: Vec<String>,
    pub caption: String,
}

/// A figure of the report: the characteristic rings of `scheme` at `valence`
/// and its leading eigenvalue moduli against the valence (3..`up_to`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FigureSpec {
    pub scheme: String,
    pub valence: usize,
    #[serde(default)]
    pub params: BTreeMap<String, String>,
    #[serde(default = "default_up_to")]
    pub up_to: usize,
}

fn default_up_to() -> usize {
    20
}

// (no deny_unknown_fields below: serde cannot combine it with `flatten`)
#[derive(Clone, Debug, Deserialize)]
pub struct Claim {
    pub id: String,
    /// section, equation or figure; required in the built-in registry
    /// (every claim there cites its place in the paper), optional in a
    /// user's claim file, where it may mean nothing
    #[serde(default)]
    pub location: String,
    /// the statement as printed
    pub statement: String,
    /// the convention the statement uses (e.g. which α)
    #[serde(default)]
    pub convention: Option<String>,
    /// the verdict this registry expects (regression-tested for the built-in
    /// papers; a change means the tool's computation changed)
    #[serde(default)]
    pub expected: Option<Verdict>,
    /// set where subdlab's rules were themselves built from the statement (a
    /// reconstruction the paper does not print, or a weight prescribed by the
    /// stated formula): says what was built from it and what the verdict
    /// still tests, so the verdict is never read as an independent check
    #[serde(default)]
    pub by_construction: Option<String>,
    #[serde(flatten)]
    pub check: Check,
}

/// Valences: a list `[3, 5, 8]` or a range string `"3..12"`.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum Valences {
    List(Vec<usize>),
    Range(String),
}

impl Subject {
    /// The face sequence of valence n, when this subject holds one
    /// configuration of that valence (a subject narrowed by
    /// [`Subject::configurations`]).
    pub fn faces_for(&self, n: usize) -> Option<&str> {
        self.faces.iter().find(|f| f.len() == n).map(|s| s.as_str())
    }

    /// Every configuration to check, each as (valence, the subject narrowed
    /// to it): one per `faces` sequence (several of one length are several
    /// configurations: QQQ and TTT are both checked), and one regular
    /// configuration per listed valence that no sequence has the length of.
    pub fn configurations(&self) -> Result<Vec<(usize, Subject)>, Error> {
        let narrowed = |faces: Vec<String>| Subject { faces, ..self.clone() };
        let mut out: Vec<(usize, Subject)> = Vec::new();
        for n in self.valences.expand()? {
            if !self.faces.iter().any(|f| f.len() == n) && !out.iter().any(|(m, _)| *m == n) {
                out.push((n, narrowed(Vec::new())));
            }
        }
        for f in &self.faces {
            if !out.iter().any(|(_, s)| s.faces.first() == Some(f)) {
                out.push((f.len(), narrowed(vec![f.clone()])));
            }
        }
        Ok(out)
    }

    /// How a configuration is named in verdicts: `n = 5`, or `n = 5
    /// (QQTQT)` for a face sequence.
    pub fn label(&self, n: usize) -> String {
        match self.faces_for(n) {
            Some(f) => format!("n = {n} ({f})"),
            None => format!("n = {n}"),
        }
    }
}

impl Valences {
    pub fn expand(&self) -> Result<Vec<usize>, Error> {
        match self {
            Valences::List(v) => Ok(v.clone()),
            Valences::Range(s) => {
                let (a, b) = s
                    .split_once("..")
                    .ok_or_else(|| Error::Claim(format!("valence range '{s}' is not of the form A..B")))?;
                let (a, b): (usize, usize) = (
                    a.trim().parse().map_err(|_| Error::Claim(format!("bad valence range '{s}'")))?,
                    b.trim().parse().map_err(|_| Error::Claim(format!("bad valence range '{s}'")))?,
                );
                if a > b || b > crate::neighbourhood::configuration::MAX_VALENCE {
                    return Err(Error::Claim(format!("bad valence range '{s}'")));
                }
                Ok((a..=b).collect())
            }
        }
    }
}

/// What the scheme-based checks analyse.
#[derive(Clone, Debug, Deserialize)]
pub struct Subject {
    pub scheme: String,
    /// the valences; may be left out when `faces` gives the configurations
    #[serde(default = "no_valences")]
    pub valences: Valences,
    /// face sequences around the centre (schemes of mixed meshes); each is
    /// its own configuration (QQQ and TTT are two), of valence its length
    #[serde(default)]
    pub faces: Vec<String>,
    #[serde(default)]
    pub params: BTreeMap<String, String>,
    /// "minimal" or "analysis" (default analysis)
    #[serde(default)]
    pub neighbourhood: Option<String>,
    /// extra variables for the stated expressions, as expressions in n
    /// (e.g. `a = "3/4 - (1/2 + cos(2 pi / n)/4)^2"`)
    #[serde(default)]
    pub vars: BTreeMap<String, String>,
}

#[derive(Clone, Debug, Deserialize)]
#[serde(tag = "check", rename_all = "kebab-case")]
pub enum Check {
    /// Eigenvalues (with repetition = multiplicity; `"EXPR ; COUNT"` repeats
    /// EXPR COUNT times) of S or of Fourier block `block`, compared as `all`
    /// (the whole multiset), `leading` (the largest ones in the display order),
    /// `contains` (each stated value at least as often as stated) or `count`
    /// (each stated value exactly as often as stated, others ignored).
    Eigenvalues {
        #[serde(flatten)]
        subject: Subject,
        values: Vec<String>,
        #[serde(default = "default_compare")]
        compare: String,
        #[serde(default)]
        block: Option<String>,
        /// compare moduli |λ| instead of values (the other reading of a
        /// statement such as "λ3 = λ4" about eigenvalues ordered by modulus)
        #[serde(default)]
        moduli: bool,
    },
    /// The subdominant eigenvalue λ1 equals the expression.
    Subdominant {
        #[serde(flatten)]
        subject: Subject,
        value: String,
    },
    /// The neighbourhood size equals the expression.
    Size {
        #[serde(flatten)]
        subject: Subject,
        value: String,
    },
    /// A stated vertex set "suffices" (or "is invariant"): the set built from
    /// the vertex labels (every vertex of ring ≤ `rings`, optionally only
    /// those with i + j ≤ `lattice_sum` in their sector's chart and of the
    /// listed `kinds`) must have the stated size `value`, be invariant under
    /// one analysis step, contain the `neighbourhood` (analysis by default:
    /// what the analysis needs) and have the same leading eigenvalues as S
    /// on it (every extra eigenvalue below λ1 in modulus).
    InvariantSet {
        #[serde(flatten)]
        subject: Subject,
        rings: String,
        #[serde(default)]
        lattice_sum: Option<String>,
        #[serde(default)]
        kinds: Option<Vec<String>>,
        value: String,
    },
    /// Limit stencil weights by vertex selector ("centre", "kind.ring", e.g.
    /// "fcv.1", "edge.1"); every other vertex must have weight 0.
    LimitStencil {
        #[serde(flatten)]
        subject: Subject,
        weights: BTreeMap<String, String>,
    },
    /// The tangent stencils span the same plane as the stated cos/sin
    /// patterns (expressions in the vertex's sector `s`).
    TangentStencils {
        #[serde(flatten)]
        subject: Subject,
        cos: BTreeMap<String, String>,
        sin: BTreeMap<String, String>,
    },
    /// An inequality `lhs op rhs` (op one of <, <=, >, >=) at every valence;
    /// besides `n`, parameters and `vars`, the expressions may use the computed
    /// `lambda1` (subdominant eigenvalue), `lambda3` (modulus of the next one)
    /// and `size` (the neighbourhood size).
    Inequality {
        #[serde(flatten)]
        subject: Subject,
        lhs: String,
        op: String,
        rhs: String,
    },
    /// Every real eigenvalue is non-negative (`expect = true`, the default) or not.
    NonnegativeSpectrum {
        #[serde(flatten)]
        subject: Subject,
        #[serde(default = "yes")]
        expect: bool,
    },
    /// The characteristic map is regular and injective (`expect = true`, the default) or
    /// not (Reif's test, `charmap`); `levels` and `resolution` as for
    /// `subdlab charmap` (defaults 3 and 256).
    CharacteristicMap {
        #[serde(flatten)]
        subject: Subject,
        #[serde(default = "yes")]
        expect: bool,
        #[serde(default)]
        levels: Option<usize>,
        #[serde(default)]
        resolution: Option<usize>,
        /// decide by the certified map (`charmap --certify`): regularity and
        /// injectivity both PROVED (unconditionally), or one DISPROVED,
        /// decide; anything else is INCONCLUSIVE with the certificate's reason
        #[serde(default)]
        certified: bool,
    },
    /// The spectral C^1 test (Reif) passes (`expect = true`, the default) or fails.
    SpectralC1 {
        #[serde(flatten)]
        subject: Subject,
        #[serde(default = "yes")]
        expect: bool,
        /// decide by the certified spectrum (`spectrum --certify`):
        /// PROVED (unconditionally) or DISPROVED decide, anything else is
        /// INCONCLUSIVE with the certificate's reason
        #[serde(default)]
        certified: bool,
    },
    /// The second-order analysis (`subdlab curvature`): the curvature class
    /// (one name or a list of admissible names: zero, bounded, unbounded,
    /// not-applicable), optionally whether Reif's C² test passes (`c2`) and
    /// the Fourier index set F(μ) (`fourier`, integers or expressions in n
    /// such as "n-2"); `levels` refines the ring samples (default 3).
    Curvature {
        #[serde(flatten)]
        subject: Subject,
        class: curvature::ClassSpec,
        #[serde(default)]
        c2: Option<bool>,
        #[serde(default)]
        fourier: Option<Vec<curvature::FourierEntry>>,
        #[serde(default)]
        levels: Option<usize>,
    },
    /// An algebraic identity between two expressions, exact where possible.
    /// `vars` are expressions in each other; with `valences` (a statement in
    /// n) the identity must hold at every listed valence, with `n` (alias
    /// `k`) defined and `vars` expressions in n as well.
    Identity {
        lhs: String,
        rhs: String,
        #[serde(default)]
        vars: BTreeMap<String, String>,
        #[serde(default)]
        valences: Option<Valences>,
    },
    /// The eigenvalues of a matrix printed in the paper (entries are
    /// expressions in n and `vars`) against the eigenvalues the paper states
    /// for it: checks the paper's own consistency.
    MatrixEigenvalues {
        valences: Valences,
        #[serde(default)]
        vars: BTreeMap<String, String>,
        rows: Vec<Vec<String>>,
        values: Vec<String>,
    },
    /// A printed matrix of a regular-lattice scheme against the matrix
    /// assembled from its rules on the window [i0, i1] × [j0, j1] (i fastest),
    /// entry by entry: `scale` times the printed integers.
    LatticeMatrix { scheme: String, window: [i64; 4], scale: String, rows: Vec<String> },
    /// A named computation implemented in `claims::builtin` for statements
    /// that need bespoke work; `data` carries the printed values it needs.
    Builtin {
        name: String,
        #[serde(default)]
        data: Option<toml::Value>,
    },
    /// A claim that could not be read (unknown key, missing field, wrong
    /// type): its verdict is ERROR with this message; never in a file.
    #[serde(skip)]
    Malformed(String),
}

fn yes() -> bool {
    true
}

impl Check {
    /// What a claim must satisfy before anything is computed: no list that
    /// the check compares with is empty (a claim that asserts nothing would
    /// HOLD vacuously), and every option in its range by the same check the
    /// command line uses. An error here makes the claim an ERROR.
    pub fn validate(&self) -> Result<(), Error> {
        let vacuous = |what: &str| {
            Err(Error::Claim(format!("{what} is empty: the claim asserts nothing (a vacuous claim is an ERROR)")))
        };
        match self {
            Check::Eigenvalues { values, .. } if values.is_empty() => vacuous("values"),
            Check::MatrixEigenvalues { rows, .. } if rows.is_empty() => vacuous("rows"),
            Check::MatrixEigenvalues { values, .. } if values.is_empty() => vacuous("values"),
            Check::LimitStencil { weights, .. } if weights.is_empty() => vacuous("weights"),
            Check::TangentStencils { cos, .. } if cos.is_empty() => vacuous("cos"),
            Check::TangentStencils { sin, .. } if sin.is_empty() => vacuous("sin"),
            Check::InvariantSet { kinds: Some(k), .. } if k.is_empty() => vacuous("kinds"),
            Check::LatticeMatrix { rows, .. } if rows.is_empty() => vacuous("rows"),
            Check::Identity { valences: Some(v), .. } if matches!(v, Valences::List(l) if l.is_empty()) => {
                vacuous("valences")
            }
            Check::CharacteristicMap { levels, certified: true, .. } => crate::certify::charmap::check_levels(
                levels.unwrap_or(crate::certify::charmap::DEFAULT_MAX_LEVELS),
                "levels",
            ),
            Check::CharacteristicMap { levels, resolution, certified: false, .. } => {
                crate::charmap::CharMapOptions::checked(levels.unwrap_or(3), resolution.unwrap_or(256)).map(|_| ())
            }
            _ => Ok(()),
        }
    }
}

/// The keys each check kind reads, besides the common ones
/// ([`COMMON_KEYS`]); anything else in a claim is an error naming its line.
pub const CHECK_KEYS: &[(&str, &[&str])] = &[
    ("eigenvalues", &["values", "compare", "block", "moduli"]),
    ("subdominant", &["value"]),
    ("size", &["value"]),
    ("invariant-set", &["rings", "lattice_sum", "kinds", "value"]),
    ("limit-stencil", &["weights"]),
    ("tangent-stencils", &["cos", "sin"]),
    ("inequality", &["lhs", "op", "rhs"]),
    ("nonnegative-spectrum", &["expect"]),
    ("characteristic-map", &["expect", "levels", "resolution", "certified"]),
    ("spectral-c1", &["expect", "certified"]),
    ("curvature", &["class", "c2", "fourier", "levels"]),
    ("identity", &["lhs", "rhs", "vars", "valences"]),
    ("matrix-eigenvalues", &["valences", "vars", "rows", "values"]),
    ("lattice-matrix", &["scheme", "window", "scale", "rows"]),
    ("builtin", &["name", "data"]),
];
/// Keys of every claim.
pub const COMMON_KEYS: &[&str] = &["id", "location", "statement", "convention", "expected", "by_construction", "check"];
/// Keys of the checks that analyse a scheme (all but identity,
/// matrix-eigenvalues, lattice-matrix and builtin).
pub const SUBJECT_KEYS: &[&str] = &["scheme", "valences", "faces", "params", "neighbourhood", "vars"];

fn no_valences() -> Valences {
    Valences::List(Vec::new())
}

fn default_compare() -> String {
    "all".to_string()
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "UPPERCASE")]
pub enum Verdict {
    Holds,
    Refuted,
    Inconclusive,
    /// the claim itself could not be read (a malformed claim of a file)
    Error,
}

impl Outcome {
    /// The verdict as shown to a reader: "HOLDS (by construction)" where
    /// the claim carries a `by_construction` note.
    pub fn shown_verdict(&self) -> String {
        match &self.by_construction {
            Some(_) => format!("{} (by construction)", self.verdict),
            None => self.verdict.to_string(),
        }
    }
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Verdict::Holds => "HOLDS",
            Verdict::Refuted => "REFUTED",
            Verdict::Inconclusive => "INCONCLUSIVE",
            Verdict::Error => "ERROR",
        })
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Outcome {
    pub id: String,
    pub paper: String,
    pub location: String,
    pub statement: String,
    pub convention: Option<String>,
    pub verdict: Verdict,
    /// the verdict the claim file expects, if it records one
    pub expected: Option<Verdict>,
    /// the claim's `by_construction` note: the verdict is about subdlab's
    /// construction from the statement, not an independent confirmation
    pub by_construction: Option<String>,
    /// the stated value(s) as evaluated
    pub stated: String,
    /// the computed value(s)
    pub computed: String,
    /// what decided the verdict
    pub detail: String,
    /// wall-clock seconds the claim's evaluation took (its configurations
    /// run side by side, so on several cores this is less than its CPU
    /// time); 0 for a file that could not be read
    pub seconds: f64,
}

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
    let scheme_based = !["identity", "matrix-eigenvalues", "lattice-matrix", "builtin"].contains(&kind);
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

/// Evaluate several files side by side (papers are independent; each has its
/// own cache of analyses), on at most one worker per core. Workers have large
/// stacks (deeply nested expressions recurse), and a claim whose evaluation
/// fails unexpectedly gets an ERROR verdict instead of ending the run.
pub fn evaluate_all(files: &[ClaimFile]) -> Result<Vec<Vec<Outcome>>, Error> {
    evaluate_all_with(files, &EvaluationOptions::default())
}

/// What an evaluation writes besides the verdicts.
#[derive(Clone, Debug, Default)]
pub struct EvaluationOptions {
    /// write the certificate document (`--certificate FILE` of `spectrum` /
    /// `charmap --certify`) of every certified claim at every valence into
    /// this directory, as `CLAIM-ID-nN.json`, for an independent checker
    pub certificates: Option<std::path::PathBuf>,
}

/// [`evaluate_all`], writing what `options` asks for.
pub fn evaluate_all_with(files: &[ClaimFile], options: &EvaluationOptions) -> Result<Vec<Vec<Outcome>>, Error> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let workers = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1).min(files.len()).max(1);
    let next = AtomicUsize::new(0);
    let results: std::sync::Mutex<Vec<Option<Vec<Outcome>>>> = std::sync::Mutex::new(vec![None; files.len()]);
    std::thread::scope(|scope| {
        let mut handles = Vec::new();
        for _ in 0..workers {
            let work = || loop {
                let k = next.fetch_add(1, Ordering::SeqCst);
                let Some(f) = files.get(k) else { break };
                let o = evaluate_with(f, options);
                results.lock().unwrap_or_else(|e| e.into_inner())[k] = Some(o);
            };
            let h = std::thread::Builder::new()
                .stack_size(EVALUATION_STACK)
                .spawn_scoped(scope, work)
                .map_err(|e| Error::Message(format!("cannot start a worker thread: {e}")))?;
            handles.push(h);
        }
        for h in handles {
            h.join().map_err(|_| Error::Message("internal error while evaluating claims".to_string()))?;
        }
        Ok::<(), Error>(())
    })?;
    let results = results.into_inner().unwrap_or_else(|e| e.into_inner());
    Ok(results.into_iter().map(|o| o.unwrap_or_default()).collect())
}

/// Stack of a claim-evaluation worker.
const EVALUATION_STACK: usize = 64 << 20;

/// Evaluate every claim of a file.
pub fn evaluate(file: &ClaimFile) -> Vec<Outcome> {
    evaluate_with(file, &EvaluationOptions::default())
}

/// [`evaluate`], writing what `options` asks for.
pub fn evaluate_with(file: &ClaimFile, options: &EvaluationOptions) -> Vec<Outcome> {
    let mut cache = checks::Cache::writing_certificates(options.certificates.clone());
    file.claims
        .iter()
        .map(|c| {
            let started = std::time::Instant::now();
            let run = std::panic::AssertUnwindSafe(|| checks::evaluate(&file.paper, c, &mut cache));
            let mut outcome = std::panic::catch_unwind(run).unwrap_or_else(|p| {
                let why = p
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| p.downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                checks::error_outcome(&file.paper, c, format!("internal error while evaluating this claim: {why}"))
            });
            outcome.seconds = started.elapsed().as_secs_f64();
            outcome
        })
        .collect()
}
