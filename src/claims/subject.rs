//! What the scheme-based checks analyse: a scheme with parameters, the
//! valences or face sequences it is checked at, and the variables the stated
//! expressions may use. Plain data: every other file of `claims` may use it.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::error::Error;

/// Valences: a list `[3, 5, 8]` or a range string `"3..12"`.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum Valences {
    List(Vec<usize>),
    Range(String),
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
    /// a tagged vertex (`--tag`): `boundary`, `corner`, `crease:K` or
    /// `dart`; the valences then count what `--tag` says (the faces of an
    /// open fan at a boundary or corner), and the spectral verdict is the
    /// sector criterion (`spectrum::verdict::sector`)
    #[serde(default)]
    pub tag: Option<String>,
    /// extra variables for the stated expressions, as expressions in n
    /// (e.g. `a = "3/4 - (1/2 + cos(2 pi / n)/4)^2"`)
    #[serde(default)]
    pub vars: BTreeMap<String, String>,
}

fn no_valences() -> Valences {
    Valences::List(Vec::new())
}

impl Subject {
    /// A subject with valences and variables only: the statements in n that
    /// analyse no scheme (identities, typed matrices) range over it.
    pub fn valences_only(valences: &Valences, vars: &BTreeMap<String, String>) -> Subject {
        Subject {
            scheme: String::new(),
            valences: valences.clone(),
            faces: Vec::new(),
            params: Default::default(),
            neighbourhood: None,
            tag: None,
            vars: vars.clone(),
        }
    }

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
    /// (QQTQT)` for a face sequence, `n = 4 (boundary)` for a tagged vertex.
    pub fn label(&self, n: usize) -> String {
        let mut notes: Vec<&str> = self.faces_for(n).into_iter().collect();
        notes.extend(self.tag.as_deref());
        match notes[..] {
            [] => format!("n = {n}"),
            _ => format!("n = {n} ({})", notes.join(", ")),
        }
    }

    /// The checks the tagged configurations do not have yet (the certified
    /// spectrum and map, curvature) refuse a `tag` in one line, as the
    /// command line refuses `--tag` there.
    pub fn refuse_tag(&self, what: &str) -> Result<(), Error> {
        match &self.tag {
            Some(t) => Err(Error::Claim(format!("tag = \"{t}\": {what} is not available at tagged vertices yet"))),
            None => Ok(()),
        }
    }
}
