//! Paper statements as data (`claims/*.toml`), evaluated against the tool's
//! computations: every claim ends HOLDS, REFUTED (with the numbers that show
//! it) or INCONCLUSIVE (the computation could not decide, with the reason).
//!
//! A claim file names its paper and lists claims; each claim has an id, where
//! it stands in the paper, the statement as printed, the convention it uses,
//! and a `check` saying how it is evaluated (see [`Check`]). Values are
//! expressions (`numeric::expr`) in the valence `n` (alias `k`), the Fourier
//! block index `m` where relevant, and the scheme's parameters by name.

pub mod builtin;
pub mod checks;

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClaimFile {
    /// short paper key, e.g. "huang-nonbox"
    pub paper: String,
    pub title: String,
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
    /// section, equation or figure
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
    /// The valences to check: the listed ones and the lengths of `faces`.
    pub fn valence_list(&self) -> Result<Vec<usize>, String> {
        let mut v = self.valences.expand()?;
        for f in &self.faces {
            if !v.contains(&f.len()) {
                v.push(f.len());
            }
        }
        Ok(v)
    }
    pub fn faces_for(&self, n: usize) -> Option<&str> {
        self.faces.iter().find(|f| f.len() == n).map(|s| s.as_str())
    }
}

impl Valences {
    pub fn expand(&self) -> Result<Vec<usize>, String> {
        match self {
            Valences::List(v) => Ok(v.clone()),
            Valences::Range(s) => {
                let (a, b) =
                    s.split_once("..").ok_or_else(|| format!("valence range '{s}' is not of the form A..B"))?;
                let (a, b): (usize, usize) = (
                    a.trim().parse().map_err(|_| format!("bad valence range '{s}'"))?,
                    b.trim().parse().map_err(|_| format!("bad valence range '{s}'"))?,
                );
                if a > b || b > crate::neighbourhood::configuration::MAX_VALENCE {
                    return Err(format!("bad valence range '{s}'"));
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
    /// face sequences around the centre (schemes of mixed meshes), one per
    /// valence; each adds its length to the valences
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
    /// Every real eigenvalue is non-negative (`expect = true`) or not.
    NonnegativeSpectrum {
        #[serde(flatten)]
        subject: Subject,
        expect: bool,
    },
    /// The characteristic map is regular and injective (`expect = true`) or
    /// not (Reif's test, `charmap`); `levels` and `resolution` as for
    /// `subdlab charmap` (defaults 3 and 256).
    CharacteristicMap {
        #[serde(flatten)]
        subject: Subject,
        expect: bool,
        #[serde(default)]
        levels: Option<usize>,
        #[serde(default)]
        resolution: Option<usize>,
    },
    /// The spectral C^1 test (Reif) passes (`expect = true`) or fails.
    SpectralC1 {
        #[serde(flatten)]
        subject: Subject,
        expect: bool,
    },
    /// An algebraic identity between two expressions, exact where possible.
    Identity {
        lhs: String,
        rhs: String,
        #[serde(default)]
        vars: BTreeMap<String, String>,
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
}

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
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Verdict::Holds => "HOLDS",
            Verdict::Refuted => "REFUTED",
            Verdict::Inconclusive => "INCONCLUSIVE",
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
    /// the stated value(s) as evaluated
    pub stated: String,
    /// the computed value(s)
    pub computed: String,
    /// what decided the verdict
    pub detail: String,
}

/// The built-in registry: one file per source paper, compiled in.
pub const BUILTIN: &[(&str, &str)] = &[
    ("huang-nonbox", include_str!("../../claims/huang-nonbox.toml")),
    ("khan-mustafa", include_str!("../../claims/khan-mustafa.toml")),
    ("lin-luo", include_str!("../../claims/lin-luo.toml")),
    ("peters-shiue", include_str!("../../claims/peters-shiue.toml")),
    ("karciauskas-peters", include_str!("../../claims/karciauskas-peters.toml")),
];

pub fn parse_file(name: &str, text: &str) -> Result<ClaimFile, String> {
    let f: ClaimFile = toml::from_str(text).map_err(|e| {
        let msg = e.to_string();
        let first = msg.lines().next().unwrap_or("").trim().to_string();
        // toml reports "TOML parse error at line L, column C" first; keep the message short
        let detail = msg.lines().last().unwrap_or("").trim().to_string();
        format!("{name}: {first}: {detail}")
    })?;
    let mut seen = std::collections::HashSet::new();
    for c in &f.claims {
        if !seen.insert(&c.id) {
            return Err(format!("{name}: claim id '{}' appears twice", c.id));
        }
    }
    Ok(f)
}

pub fn builtin_files() -> Result<Vec<ClaimFile>, String> {
    BUILTIN.iter().map(|(name, text)| parse_file(name, text)).collect()
}

/// Evaluate several files side by side (papers are independent; each has its
/// own cache of analyses).
pub fn evaluate_all(files: &[ClaimFile]) -> Result<Vec<Vec<Outcome>>, String> {
    std::thread::scope(|scope| {
        let handles: Vec<_> = files.iter().map(|f| scope.spawn(move || evaluate(f))).collect();
        handles
            .into_iter()
            .map(|h| h.join().map_err(|_| "internal error while evaluating claims".to_string()))
            .collect()
    })
}

/// Evaluate every claim of a file.
pub fn evaluate(file: &ClaimFile) -> Vec<Outcome> {
    let mut cache = checks::Cache::default();
    file.claims.iter().map(|c| checks::evaluate(&file.paper, c, &mut cache)).collect()
}
