// jemalloc: a sixth of `verify`'s time was glibc's malloc and free of small
// vectors (see Cargo.toml)
#[global_allocator]
static ALLOCATOR: ZeroByMemset = ZeroByMemset(tikv_jemallocator::Jemalloc);

/// jemalloc with zeroed allocations (`vec![0; n]`, `calloc`) zeroed by
/// `memset`. jemalloc zeroes a large block it recycles by handing its pages
/// back to the kernel (`madvise(MADV_DONTNEED)`) so that they come back
/// zero: every page is then faulted in again on first touch, and each call
/// interrupts the other threads to flush their TLBs. Half the main job's
/// page faults were such re-faults of recycled meshes and rasters. The
/// buffers are written right after anyway, so writing the zeros costs
/// little; only fresh pages, which the kernel hands out zeroed, are touched
/// earlier than they would be.
struct ZeroByMemset(tikv_jemallocator::Jemalloc);

// SAFETY: every call is forwarded to jemalloc with the same layout; the
// zeroing writes only the `layout.size()` bytes the allocation owns.
unsafe impl std::alloc::GlobalAlloc for ZeroByMemset {
    unsafe fn alloc(&self, layout: std::alloc::Layout) -> *mut u8 {
        unsafe { self.0.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: std::alloc::Layout) -> *mut u8 {
        let p = unsafe { self.0.alloc(layout) };
        if !p.is_null() {
            unsafe { std::ptr::write_bytes(p, 0, layout.size()) };
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: std::alloc::Layout) {
        unsafe { self.0.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: std::alloc::Layout, new_size: usize) -> *mut u8 {
        unsafe { self.0.realloc(ptr, layout, new_size) }
    }
}

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
