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
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            use clap::error::ErrorKind;
            // help and version go to stdout with exit 0
            if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
                return match crate::io::out(&e.to_string()) {
                    Ok(()) => 0,
                    Err(m) => {
                        error_line(&m);
                        2
                    }
                };
            }
            // a usage error (or the help after a bare `subdlab`): clap's whole
            // message, with a long echoed argument cut (see `error_line`)
            to_stderr(&crate::error::shorten_echoes(&e.render().to_string()));
            return 2;
        }
    };
    match commands::dispatch(cli.command) {
        Ok(code) => code,
        Err(e) => {
            error_line(&e);
            2
        }
    }
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
