// jemalloc: a sixth of `verify`'s time was glibc's malloc and free of small
// vectors (see Cargo.toml)
#[global_allocator]
static ALLOCATOR: tikv_jemallocator::Jemalloc = tikv_jemallocator::Jemalloc;

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
    // faer's parallel kernels split their reductions by the number of rayon
    // threads, so a dense eigenproblem (the whole-matrix method, Fourier
    // blocks above faer's parallel threshold) would differ in its last digits
    // with RAYON_NUM_THREADS; results must be byte-identical for any thread
    // count. Each dense solve runs sequentially; the parallelism is outside,
    // over blocks, valences and claims, whose results are collected in order.
    faer::set_global_parallelism(faer::Par::Seq);
    // an interrupted write leaves no temporary file behind
    subdlab::io::install_cleanup_handlers();
    std::process::exit(subdlab::cli::main());
}

/// Runs before `main`, and so before Rust's runtime replaces a closed
/// standard output with /dev/null: the only moment a closed descriptor 1
/// (`>&-`) can be told from one open on /dev/null (see
/// `subdlab::io::record_stdout_at_start`). glibc and musl call the
/// `.init_array` entries before `main`; elsewhere nothing is recorded and a
/// closed standard output reads as /dev/null.
#[cfg(any(target_os = "linux", target_os = "android"))]
#[used]
#[link_section = ".init_array"]
static RECORD_STDOUT_AT_START: extern "C" fn() = {
    extern "C" fn record() {
        subdlab::io::record_stdout_at_start();
    }
    record
};
