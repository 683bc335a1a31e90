fn main() {
    if let Err(e) = subdlab::cli::run() {
        eprintln!("error: {e}");
        std::process::exit(2);
    }
}
