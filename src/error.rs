//! The library's typed error. Every variant displays as the one-line message
//! the command line prints (the CLI's contract: one line on stderr, non-zero
//! exit), while callers that must react to a failure match on the variant,
//! never on the text.
//!
//! Migration note: older stages still return `Result<_, String>`; `Error`
//! converts into `String` (so `?` works across the boundary) and a `String`
//! converts into `Error::Message`, which carries such a message unchanged.

#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// A message from a stage that does not yet have a typed error.
    Message(String),
    /// The caller asked for something out of range or unknown: a valence
    /// below 3 or too large, an unknown scheme, parameter or option value,
    /// a parameter outside its admissible range, NaN.
    Input(String),
    /// A file (mesh, scheme or claim file) that cannot be read or parsed;
    /// the message names the file and, where known, the line.
    File(String),
    /// A point the computation needs is not determined by the control points
    /// at hand (a rule reaches past a truncated patch or a pruned margin):
    /// the caller may retry with a larger neighbourhood.
    NotDetermined(String),
    /// A file could not be written; names the file and the reason.
    Write { path: String, reason: String },
}

pub type Result<T> = std::result::Result<T, Error>;

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Error::Message(m) | Error::Input(m) | Error::File(m) | Error::NotDetermined(m) => f.write_str(m),
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
    }
}
