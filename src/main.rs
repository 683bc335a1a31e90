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
    // an interrupted write leaves no temporary file behind
    subdlab::io::install_cleanup_handlers();
    std::process::exit(subdlab::cli::main());
}
