//! The process entry: parse the command line, run the command, and turn an
//! error into one line on stderr and the exit status.

use clap::Parser;

use crate::cli::command_line::Cli;
// `main` and `run` call the dispatcher as `commands::dispatch`; it is in
// `dispatch.rs`, apart from the helpers in `commands.rs` that the commands'
// files import
use crate::cli::dispatch as commands;

/// Runs the command line and returns the exit status: 0 success; 1 when
/// `verify` finds a claim that is not as required (REFUTED or INCONCLUSIVE)
/// or a certified verdict is not PROVED unconditionally (`spectrum
/// --certify`, `charmap --certify`);
/// 2 for usage errors (clap's full message: what is missing, the usage line)
/// and for every other error (one line on stderr, control characters shown
/// escaped).
pub fn main() -> i32 {
    // `spectrum ... --valences A..[B]`: the every-valence form, its own parser
    let argv: Vec<std::ffi::OsString> = std::env::args_os().collect();
    if super::every_valence::wants(&argv) {
        return super::every_valence::main(&argv).unwrap_or_else(clap_failure);
    }
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return clap_failure(e),
    };
    match commands::dispatch(cli.command) {
        Ok(code) => code,
        Err(e) => {
            error_line(&e);
            2
        }
    }
}

/// The exit status of a command line clap refused: help and version go to
/// stdout with exit 0; a usage error (or the help after a bare `subdlab`):
/// clap's whole message, with a long echoed argument cut (see `error_line`),
/// exit 2.
fn clap_failure(e: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        return match crate::io::out(&e.to_string()) {
            Ok(()) => 0,
            Err(m) => {
                error_line(&m);
                2
            }
        };
    }
    to_stderr(&crate::error::shorten_echoes(&e.render().to_string()));
    2
}

/// Shows an error as the one line "error: MESSAGE": control characters
/// escaped, long echoes of the user's input cut
/// ([`crate::error::shorten_echoes`]).
fn error_line(e: &crate::error::Error) {
    let line = crate::error::shorten_echoes(&crate::io::printable(&e.to_string()));
    to_stderr(&format!("error: {line}\n"));
}

/// Writes to standard error; when even that fails (a full disk) there is
/// nowhere left to report to, and the exit status still says it.
fn to_stderr(text: &str) {
    use std::io::Write;
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}

/// Runs the command line; usage errors and failures are the message (see
/// [`main`] for the exit statuses the binary uses).
pub fn run() -> Result<(), crate::error::Error> {
    use crate::error::Error;
    let cli = Cli::try_parse().map_err(|e| Error::Input(e.to_string()))?;
    match commands::dispatch(cli.command)? {
        0 => Ok(()),
        _ => Err(Error::Claim("a verdict did not hold (a claim not as required, or a certificate not proved)".into())),
    }
}
