//! The library's typed error. Every variant displays as the one-line message
//! the command line prints (the CLI's contract: one line on stderr, non-zero
//! exit), while callers that must react to a failure match on the variant,
//! never on the text.
//!
//! Every fallible library call returns [`Result`]. A stage adding context to
//! a lower-level error keeps its variant ([`Error::context`],
//! [`Error::map_message`]); a stage that knows better says what happened
//! (a scheme file's expression that does not parse is a [`Error::File`], even
//! though the expression parser reports [`Error::Input`]).
//!
//! Errors of the engine's invariant closure (`engine::closure::ClosureError`)
//! and of assembly (`matrix::local::AssembleError`) are typed too and convert
//! into `Error`: a dependency's own error keeps its variant.
//! `Error::Message` remains for internal failures that none of the other
//! variants describes (rendering, serialisation).

#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// A message from a stage that still reports plain strings (see the
    /// module documentation); its category is not known here.
    Message(String),
    /// The caller asked for something out of range or unknown: a valence
    /// below 3 or too large, an unknown scheme, parameter or option value,
    /// a parameter outside its admissible range, NaN, an expression given on
    /// the command line that does not parse or evaluate.
    Input(String),
    /// A file (mesh, scheme or claim file) that cannot be read or parsed;
    /// the message names the file and, where known, the line.
    File(String),
    /// A point the computation needs is not determined by the control points
    /// at hand (a rule reaches past a truncated patch or a pruned margin):
    /// the caller may retry with a larger neighbourhood.
    NotDetermined(String),
    /// A file could not be written (or standard output, with the path
    /// "to standard output"); names the file and the reason.
    Write { path: String, reason: String },
    /// A numerical stage failed on valid input: the eigen solver did not
    /// converge, a weight is not representable exactly, a matrix is singular
    /// or a value is not finite.
    Numeric(String),
    /// A claim cannot be evaluated: a field of its data is missing or
    /// malformed, or a stated value does not evaluate. The outcome carrying
    /// the message names the claim.
    Claim(String),
    /// A computation ran on valid input and could not decide the question
    /// asked (a proof not found, a quantity this tool does not compute for
    /// the configuration, a size beyond what is analysed): a claim's
    /// INCONCLUSIVE, never a malformed input.
    Undecided(String),
}

pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// The same error with its message (as displayed) rewritten by `f`,
    /// keeping the variant. A [`Error::Write`] has no free-form message: the
    /// rewritten "cannot write PATH: REASON" becomes a [`Error::Message`], so
    /// the text is always exactly `f` of what was displayed.
    pub fn map_message(self, f: impl FnOnce(String) -> String) -> Error {
        match self {
            Error::Message(m) => Error::Message(f(m)),
            Error::Input(m) => Error::Input(f(m)),
            Error::File(m) => Error::File(f(m)),
            Error::NotDetermined(m) => Error::NotDetermined(f(m)),
            Error::Numeric(m) => Error::Numeric(f(m)),
            Error::Claim(m) => Error::Claim(f(m)),
            Error::Undecided(m) => Error::Undecided(f(m)),
            w @ Error::Write { .. } => Error::Message(f(w.to_string())),
        }
    }

    /// The same error with "`prefix`: " before its message, keeping the
    /// variant (see [`Error::map_message`]).
    pub fn context(self, prefix: impl std::fmt::Display) -> Error {
        self.map_message(|m| format!("{prefix}: {m}"))
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Error::Message(m)
            | Error::Input(m)
            | Error::File(m)
            | Error::NotDetermined(m)
            | Error::Numeric(m)
            | Error::Claim(m)
            | Error::Undecided(m) => f.write_str(m),
            Error::Write { path, reason } => write!(f, "cannot write {path}: {reason}"),
        }
    }
}

impl std::error::Error for Error {}

impl From<String> for Error {
    fn from(m: String) -> Self {
        Error::Message(m)
    }
}

impl From<&str> for Error {
    fn from(m: &str) -> Self {
        Error::Message(m.to_string())
    }
}

impl From<Error> for String {
    fn from(e: Error) -> Self {
        e.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_is_the_one_line_message() {
        assert_eq!(Error::from("valence 2 is below 3").to_string(), "valence 2 is below 3");
        let e = Error::Write { path: "a.svg".into(), reason: "permission denied".into() };
        assert_eq!(String::from(e), "cannot write a.svg: permission denied");
        assert!(matches!(Error::from("x"), Error::Message(_)));
        assert_eq!(Error::Numeric("no convergence".into()).to_string(), "no convergence");
        assert_eq!(Error::Claim("missing field 'n'".into()).to_string(), "missing field 'n'");
    }

    #[test]
    fn context_keeps_the_variant() {
        let e = Error::Input("unknown variable 'x'".into()).context("bound 'x'");
        assert_eq!(e, Error::Input("bound 'x': unknown variable 'x'".into()));
        let e = Error::NotDetermined("a vertex".into()).map_message(|m| format!("{m} (level 2)"));
        assert_eq!(e, Error::NotDetermined("a vertex (level 2)".into()));
        let w = Error::Write { path: "a.svg".into(), reason: "disk full".into() }.context("figure");
        assert_eq!(w.to_string(), "figure: cannot write a.svg: disk full");
    }
}
