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
//! variants describes (rendering, serialisation). There is no `From<String>`
//! or `From<&str>`: a plain string cannot become an error without its site
//! saying which variant it is.

#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// An internal failure that none of the other variants describes
    /// (rendering, serialisation, a broken invariant of the program itself):
    /// never the user's input. There is no conversion from a plain string;
    /// every site names its variant.
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

impl From<Error> for String {
    fn from(e: Error) -> Self {
        e.to_string()
    }
}

/// Longest run of a message shown whole by [`shorten_echoes`], in characters.
pub const MAX_ECHO_CHARS: usize = 80;
/// Characters kept of a longer run.
const KEPT_ECHO_CHARS: usize = 60;

/// A displayed message with every long echo of user input cut to its first
/// [`KEPT_ECHO_CHARS`] characters and "… (N bytes)": a 100 KB argument
/// quoted whole would be an error line nobody can read. Messages quote input
/// as `'...'`; a quoted span, or a run without whitespace outside quotes (an
/// unquoted path or token), longer than [`MAX_ECHO_CHARS`] is cut. The
/// message's own words are short, so only echoes are affected; whitespace
/// and line breaks are kept. Applied where errors are displayed, so no
/// message needs to cap what it quotes.
pub fn shorten_echoes(message: &str) -> String {
    fn cut(run: &str, out: &mut String) {
        if run.chars().count() <= MAX_ECHO_CHARS {
            out.push_str(run);
        } else {
            out.extend(run.chars().take(KEPT_ECHO_CHARS));
            out.push_str(&format!("… ({} bytes)", run.len()));
        }
    }
    let chars: Vec<(usize, char)> = message.char_indices().collect();
    let start_of = |k: usize| chars.get(k).map_or(message.len(), |&(i, _)| i);
    let mut out = String::with_capacity(message.len().min(1024));
    let mut word_start: Option<usize> = None;
    let mut k = 0;
    while k < chars.len() {
        let (i, c) = chars[k];
        // an opening quote starts the message or follows a space, an opening
        // bracket or an operator: "scheme's" has an apostrophe, not a quote
        let opens = c == '\'' && (k == 0 || chars[k - 1].1.is_whitespace() || "([{=:,".contains(chars[k - 1].1));
        // its closing quote is the next one not followed by a letter or digit
        let close = opens
            .then(|| {
                (k + 1..chars.len())
                    .find(|&j| chars[j].1 == '\'' && chars.get(j + 1).is_none_or(|&(_, d)| !d.is_alphanumeric()))
            })
            .flatten();
        if let Some(j) = close {
            if let Some(w) = word_start.take() {
                cut(&message[w..i], &mut out);
            }
            out.push('\'');
            cut(&message[start_of(k + 1)..chars[j].0], &mut out);
            out.push('\'');
            k = j + 1;
            continue;
        }
        if c.is_whitespace() {
            if let Some(w) = word_start.take() {
                cut(&message[w..i], &mut out);
            }
            out.push(c);
        } else if word_start.is_none() {
            word_start = Some(i);
        }
        k += 1;
    }
    if let Some(w) = word_start {
        cut(&message[w..], &mut out);
    }
    out
}

/// Peak memory one command may be estimated to need before it is refused.
/// A fixed budget rather than a fraction of the memory available now, so
/// that the same request is accepted or refused on every machine (and in
/// every test run) alike; 4 GiB fits the machines subdlab is run on, and
/// each estimate is calibrated to lie above the measured peaks.
pub const MEMORY_BUDGET: f64 = (4u64 << 30) as f64;

/// The one refusal of work estimated to need more than [`MEMORY_BUDGET`]:
/// made before the work, with the estimate, so a request that cannot fit
/// fails in milliseconds instead of after minutes of paging or an abort by
/// the allocator. `what` names the work ("polar-bi2 at valence 10000000"),
/// `basis` says what the estimate rests on, `hint` what fits instead.
pub fn check_memory(bytes: f64, what: &str, basis: &str, hint: &str) -> Result<()> {
    if bytes <= MEMORY_BUDGET {
        return Ok(());
    }
    Err(Error::Input(format!(
        "{what} would need about {} of memory ({basis}), above the supported {}; {hint}",
        format_bytes(bytes),
        format_bytes(MEMORY_BUDGET)
    )))
}

/// A byte count as the refusals print it: MiB below a GiB, else GiB (TiB
/// for the absurd).
pub fn format_bytes(bytes: f64) -> String {
    const MIB: f64 = (1u64 << 20) as f64;
    const GIB: f64 = (1u64 << 30) as f64;
    const TIB: f64 = (1u64 << 40) as f64;
    if bytes < GIB {
        format!("{:.0} MiB", bytes / MIB)
    } else if bytes < TIB {
        format!("{:.1} GiB", bytes / GIB)
    } else {
        format!("{:.0} TiB", bytes / TIB)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_is_the_one_line_message() {
        assert_eq!(Error::Input("valence 2 is below 3".into()).to_string(), "valence 2 is below 3");
        let e = Error::Write { path: "a.svg".into(), reason: "permission denied".into() };
        assert_eq!(String::from(e), "cannot write a.svg: permission denied");
        assert_eq!(Error::Numeric("no convergence".into()).to_string(), "no convergence");
        assert_eq!(Error::Claim("missing field 'n'".into()).to_string(), "missing field 'n'");
    }

    #[test]
    fn long_echoes_are_cut_and_the_rest_is_kept() {
        let long = "1+".repeat(60_000);
        let m = shorten_echoes(&format!("reference '{long}x' at n = 3: unknown variable 'x'"));
        let kept = "1+".repeat(30);
        assert_eq!(m, format!("reference '{kept}… (120001 bytes)' at n = 3: unknown variable 'x'"));
        // a quoted input with spaces is cut as one echo
        let spaced = "1 + ".repeat(30_000);
        let m = shorten_echoes(&format!("bad value '{spaced}' for '--valence <N>'"));
        assert_eq!(m, format!("bad value '{}… (120000 bytes)' for '--valence <N>'", &spaced[..60]));
        // an unquoted run (a path) too; whitespace and line breaks stay
        let path = format!("/{}", "d".repeat(199));
        assert_eq!(
            shorten_echoes(&format!("cannot read {path}: no such file\nnext line")),
            format!("cannot read {}… (201 bytes) no such file\nnext line", &path[..60])
        );
        // short messages, apostrophes and quotes at the edges are untouched
        for m in [
            "unknown scheme 'nosuch'; known schemes: catmull-clark, loop, doo-sabin, non-box, four-three, sqrt3, \
             unified-sqrt3, tps, pgs, polar-bi2, khan-mustafa, khan-mustafa-cubic, cubic-bspline, four-point",
            "the scheme's parameter 'a' (got 'x=1')",
            "unexpected ''' at column 3",
            "'",
            "",
        ] {
            assert_eq!(shorten_echoes(m), m);
        }
        // after an apostrophe, runs are cut word by word
        let m = shorten_echoes(&format!("the scheme's {} x", "y".repeat(100)));
        assert_eq!(m, format!("the scheme's {}… (100 bytes) x", "y".repeat(60)));
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
