fn main() {
    // Like other command-line tools, end quietly when the reader of our output
    // goes away (`subdlab spectrum ... | head`): Rust ignores SIGPIPE by
    // default, which would turn the closed pipe into a panic in `print!`.
    #[cfg(unix)]
    // SAFETY: restoring the default disposition of SIGPIPE before any thread
    // starts; no other code has installed a handler.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    if let Err(e) = subdlab::cli::run() {
        eprintln!("error: {e}");
        std::process::exit(2);
    }
}
