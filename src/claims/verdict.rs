//! What a claim's evaluation ends in: the [`Finding`] a check plug-in
//! returns (HOLDS or REFUTED, with its evidence), and the [`Outcome`] shown
//! for a claim (with INCONCLUSIVE, from an `Error::Undecided`, and ERROR,
//! from every other error: see `common::configurations::undecided`).

use serde::{Deserialize, Serialize};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "UPPERCASE")]
pub enum Verdict {
    Holds,
    Refuted,
    Inconclusive,
    /// the claim itself could not be read (a malformed claim of a file)
    Error,
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

/// A decided claim with its evidence: what a check plug-in returns when the
/// computation decided the statement. A computation that could not decide
/// returns `Error::Undecided` instead (the only way to INCONCLUSIVE), and a
/// claim that cannot be read returns any other error (ERROR).
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// HOLDS when true, REFUTED when false
    pub holds: bool,
    /// the stated value(s) as evaluated
    pub stated: String,
    /// the computed value(s)
    pub computed: String,
    /// what decided the verdict
    pub detail: String,
}

impl Finding {
    pub fn new(holds: bool, stated: String, computed: String, detail: String) -> Self {
        Finding { holds, stated, computed, detail }
    }

    pub fn verdict(&self) -> Verdict {
        if self.holds {
            Verdict::Holds
        } else {
            Verdict::Refuted
        }
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
