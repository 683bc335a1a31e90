//! Writing results: standard output, or files replaced atomically (write to a
//! temporary file in the same directory, then rename), so a crash leaves the
//! old file intact. A library module (not part of `cli`) because figures and
//! reports are written by library code too.
//!
//! - Only regular files are replaced. Symbolic links are followed, those of
//!   the folders too (`/proc/self/cwd/x`): the temporary is made and renamed
//!   next to the real file, and a link keeps pointing where it did. Devices
//!   and FIFOs (`/dev/null`, a named pipe) are written into directly; a
//!   directory or a dangling link is a one-line error.
//! - A path naming one of the process's open descriptors (`/dev/stdout`,
//!   `/dev/fd/N`, `/proc/self/fd/N`) is written through that descriptor, as
//!   standard output is: `-o /dev/stdout >> log` appends to `log`, and
//!   `-o /dev/stdout > log` leaves exactly the output in it.
//! - A new file gets the mode 0666 minus the umask (as `>` in a shell); a
//!   replaced file keeps its mode.
//! - Temporaries are named `.NAME.subdlab-PID-K.tmp`. They are removed when
//!   the process is interrupted (SIGINT, SIGTERM, SIGHUP: see
//!   [`install_cleanup_handlers`]), and a later write of the same file removes
//!   those left by a process that no longer runs (after SIGKILL).
//! - Standard output is written with [`out`], which turns a write error (a
//!   full disk, a closed descriptor) into the one-line error instead of a panic.

use std::fs::{self, File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

/// The tool's version (Cargo.toml).
pub const TOOL_VERSION: &str = env!("CARGO_PKG_VERSION");
/// The version of the JSON and report layouts: raised when a field changes
/// meaning or disappears (adding fields keeps it).
pub const SCHEMA_VERSION: u32 = 1;

/// The git commit the binary was built from, when it was built from a
/// checkout with git available (build.rs); None otherwise.
pub fn git_commit() -> Option<&'static str> {
    option_env!("SUBDLAB_GIT_COMMIT").filter(|c| !c.is_empty())
}

/// "0.1.0 (commit 1a2b3c4d5e6f)" or "0.1.0".
pub fn version_line() -> String {
    match git_commit() {
        Some(c) => format!("{TOOL_VERSION} (commit {c})"),
        None => TOOL_VERSION.to_string(),
    }
}

/// The text of an input file's bytes (mesh, scheme, claim and parameter
/// files all read through here): UTF-8 without the byte-order mark some
/// editors put first, which would otherwise be part of the first line
/// (`\u{feff}v 0 0 0` is no vertex, `\u{feff}name = ...` no TOML key).
pub fn decode_text(mut bytes: Vec<u8>) -> std::result::Result<String, std::string::FromUtf8Error> {
    const BOM: &[u8] = "\u{feff}".as_bytes();
    if bytes.starts_with(BOM) {
        bytes.drain(..BOM.len());
    }
    String::from_utf8(bytes)
}

/// Writes `contents` to `path` (see the module documentation).
pub fn write_atomic(path: &Path, contents: &[u8]) -> Result<()> {
    let fail = |why: &dyn std::fmt::Display| Error::Write { path: path.display().to_string(), reason: why.to_string() };
    match resolve(path).map_err(|e| fail(&e))? {
        Target::Missing(real) => replace(&real, contents, None).map_err(|e| fail(&e)),
        Target::Existing(_, m) if m.is_dir() => Err(fail(&"it is a directory")),
        Target::Existing(real, m) if m.is_file() => replace(&real, contents, Some(&m)).map_err(|e| fail(&e)),
        Target::Existing(real, _) => write_in_place(&real, contents).map_err(|e| fail(&e)),
        Target::Descriptor(fd) => write_descriptor(fd, contents).map_err(|e| fail(&e)),
        Target::Dangling => Err(fail(&"it is a symbolic link to a file that does not exist")),
    }
}

/// Where a path written to leads, symbolic links followed.
#[derive(Debug)]
enum Target {
    /// a file or directory at this real path (no link in it)
    Existing(PathBuf, fs::Metadata),
    /// nothing yet at this real path (its folder exists)
    Missing(PathBuf),
    /// one of the process's own open descriptors (`/dev/stdout`,
    /// `/dev/fd/N`, `/proc/self/fd/N`): the file the caller opened, with the
    /// caller's offset and append mode
    Descriptor(i32),
    /// a symbolic link to nothing
    Dangling,
}

/// Follows every symbolic link of `path` (its folders' too, such as
/// `/proc/self/cwd`) to the real place of the file, so a temporary is made
/// and renamed next to the real file, never next to a link or inside /proc.
/// The links of /proc that name the process's descriptors are not followed:
/// opening one would open the file anew, at offset 0 and without the
/// caller's append mode, and overwrite what the file held in place.
fn resolve(path: &Path) -> std::io::Result<Target> {
    let mut path = path.to_path_buf();
    // as the kernel's limit on links followed in one lookup
    for _ in 0..40 {
        let name = match path.file_name() {
            Some(n) => n.to_os_string(),
            // "/", "..", "a/..": a folder (or nothing), never a file to write
            None => return fs::metadata(&path).map(|m| Target::Existing(path.clone(), m)),
        };
        let parent = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let folder = fs::canonicalize(parent)?;
        if let Some(fd) = own_descriptor(&folder, &name) {
            return Ok(Target::Descriptor(fd));
        }
        let real = folder.join(&name);
        match fs::symlink_metadata(&real) {
            Ok(m) if m.file_type().is_symlink() => {
                // a relative link is relative to the folder it is in (an
                // absolute one replaces the path whole)
                path = folder.join(fs::read_link(&real)?);
                if fs::symlink_metadata(&path).is_err() {
                    return Ok(Target::Dangling);
                }
            }
            Ok(m) => return Ok(Target::Existing(real, m)),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Target::Missing(real)),
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::new(std::io::ErrorKind::InvalidInput, "too many levels of symbolic links"))
}

/// The descriptor `name` names when `folder` (canonical) is this process's
/// descriptor folder, `/proc/PID/fd` or `/proc/PID/task/TID/fd`
/// (`/proc/self/fd`, `/dev/fd` and `/proc/thread-self/fd` canonicalise to
/// these).
fn own_descriptor(folder: &Path, name: &std::ffi::OsStr) -> Option<i32> {
    let fd: i32 = name.to_str()?.parse().ok()?;
    let process = Path::new("/proc").join(std::process::id().to_string());
    let tasks = process.join("task");
    let own = folder == process.join("fd")
        || (folder.file_name() == Some("fd".as_ref()) && folder.parent().and_then(Path::parent) == Some(&tasks));
    own.then_some(fd)
}

/// Writes into an open descriptor of the process (see [`Target::Descriptor`]).
#[cfg(unix)]
fn write_descriptor(fd: i32, contents: &[u8]) -> std::io::Result<()> {
    use std::os::unix::io::FromRawFd;
    if fd == 1 && stdout_closed() {
        // the runtime's /dev/null stands in for a closed standard output
        return Err(std::io::Error::new(std::io::ErrorKind::BrokenPipe, "standard output is closed"));
    }
    // SAFETY: fcntl(F_DUPFD_CLOEXEC) only duplicates the descriptor; the
    // duplicate is owned by the File and closed when it drops, the caller's
    // descriptor stays open.
    let dup = unsafe { libc::fcntl(fd, libc::F_DUPFD_CLOEXEC, 0) };
    if dup == -1 {
        return Err(std::io::Error::last_os_error());
    }
    // SAFETY: `dup` is a fresh descriptor nothing else owns.
    let mut f = unsafe { File::from_raw_fd(dup) };
    f.write_all(contents)?;
    f.flush()
}

#[cfg(not(unix))]
fn write_descriptor(_fd: i32, _contents: &[u8]) -> std::io::Result<()> {
    Err(std::io::Error::new(std::io::ErrorKind::Unsupported, "descriptor paths are a Unix feature"))
}

fn write_in_place(path: &Path, contents: &[u8]) -> std::io::Result<()> {
    let mut f = OpenOptions::new().write(true).open(path)?;
    f.write_all(contents)?;
    f.flush()
}

/// Writes a temporary next to `path` and renames it over `path`; `old` is
/// the metadata of the file replaced, whose mode the new file keeps.
fn replace(path: &Path, contents: &[u8], old: Option<&fs::Metadata>) -> std::io::Result<()> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file name"))?
        .to_string_lossy()
        .into_owned();
    remove_stale(dir, &name);
    let (tmp, mut file) = create_temporary(dir, &name)?;
    let guard = cleanup::register(&tmp);
    let result = (|| {
        file.write_all(contents)?;
        if let Some(m) = old {
            file.set_permissions(m.permissions())?;
        }
        file.sync_all()?;
        drop(file);
        fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    cleanup::unregister(guard);
    result
}

fn temporary_prefix(name: &str) -> String {
    format!(".{name}.subdlab-")
}

fn create_temporary(dir: &Path, name: &str) -> std::io::Result<(PathBuf, File)> {
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    loop {
        let k = COUNTER.fetch_add(1, Ordering::Relaxed);
        let tmp = dir.join(format!("{}{}-{k}.tmp", temporary_prefix(name), std::process::id()));
        let mut opts = OpenOptions::new();
        opts.write(true).create_new(true);
        #[cfg(unix)]
        {
            use std::os::unix::fs::OpenOptionsExt;
            // the kernel applies the umask, as for any new file
            opts.mode(0o666);
        }
        match opts.open(&tmp) {
            Ok(f) => return Ok((tmp, f)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
}

/// Removes temporaries of `name` left in `dir` by processes that no longer run.
fn remove_stale(dir: &Path, name: &str) {
    let prefix = temporary_prefix(name);
    let Ok(entries) = fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let file = entry.file_name().to_string_lossy().into_owned();
        let Some(rest) = file.strip_prefix(&prefix).and_then(|r| r.strip_suffix(".tmp")) else { continue };
        let Some(pid) = rest.split('-').next().and_then(|p| p.parse::<u32>().ok()) else { continue };
        if pid != std::process::id() && !process_alive(pid) {
            let _ = fs::remove_file(entry.path());
        }
    }
}

#[cfg(unix)]
fn process_alive(pid: u32) -> bool {
    let Ok(pid) = libc::pid_t::try_from(pid) else { return false };
    // SAFETY: kill with signal 0 only checks whether the process exists.
    let r = unsafe { libc::kill(pid, 0) };
    r == 0 || std::io::Error::last_os_error().raw_os_error() != Some(libc::ESRCH)
}

#[cfg(not(unix))]
fn process_alive(_pid: u32) -> bool {
    true
}

/// Removes the temporaries of writes in progress when the process receives
/// SIGINT, SIGTERM or SIGHUP, then dies of that signal as it would have.
/// Called once by the binary at start-up.
pub fn install_cleanup_handlers() {
    cleanup::install();
}

#[cfg(unix)]
mod cleanup {
    //! The registry of temporaries in progress is a fixed array of atomic
    //! pointers to C strings, so the signal handler needs neither locks nor
    //! allocation (both unsafe in a handler). A path's C string is leaked
    //! rather than freed, so the handler never reads freed memory.
    use std::ffi::CString;
    use std::path::Path;
    use std::sync::atomic::{AtomicPtr, Ordering};

    const SLOTS: usize = 64;
    static LIVE: [AtomicPtr<libc::c_char>; SLOTS] = [const { AtomicPtr::new(std::ptr::null_mut()) }; SLOTS];

    pub fn register(path: &Path) -> Option<usize> {
        use std::os::unix::ffi::OsStrExt;
        let c = CString::new(path.as_os_str().as_bytes()).ok()?;
        let ptr = c.into_raw();
        for (k, slot) in LIVE.iter().enumerate() {
            if slot.compare_exchange(std::ptr::null_mut(), ptr, Ordering::SeqCst, Ordering::SeqCst).is_ok() {
                return Some(k);
            }
        }
        // SAFETY: `ptr` came from `into_raw` just above and was not shared.
        drop(unsafe { CString::from_raw(ptr) });
        None
    }

    pub fn unregister(slot: Option<usize>) {
        if let Some(k) = slot {
            // leaked on purpose (see the module comment): a few bytes per write
            LIVE[k].store(std::ptr::null_mut(), Ordering::SeqCst);
        }
    }

    extern "C" fn on_signal(sig: libc::c_int) {
        for slot in &LIVE {
            let p = slot.load(Ordering::SeqCst);
            if !p.is_null() {
                // SAFETY: unlink is async-signal-safe; p is a leaked, never freed C string.
                unsafe { libc::unlink(p) };
            }
        }
        // SAFETY: signal and raise are async-signal-safe; restoring the default
        // disposition and re-raising ends the process as the signal would have.
        unsafe {
            libc::signal(sig, libc::SIG_DFL);
            libc::raise(sig);
        }
    }

    pub fn install() {
        for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
            // SAFETY: installing a handler that only calls async-signal-safe
            // functions; a signal the parent set to be ignored stays ignored.
            unsafe {
                let previous = libc::signal(sig, on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t);
                if previous == libc::SIG_IGN {
                    libc::signal(sig, libc::SIG_IGN);
                }
            }
        }
    }
}

#[cfg(not(unix))]
mod cleanup {
    pub fn register(_: &std::path::Path) -> Option<usize> {
        None
    }
    pub fn unregister(_: Option<usize>) {}
    pub fn install() {}
}

/// Writes text to standard output; a failed write (a full disk, a closed
/// descriptor) is the one-line error "cannot write to standard output: ...".
/// Every command's output goes through here (or [`print_json`]): `print!`
/// would panic on such a failure.
pub fn out(text: &str) -> Result<()> {
    if text.is_empty() {
        return Ok(());
    }
    if stdout_closed() {
        return Err(stdout_error("it is closed"));
    }
    let mut o = std::io::stdout().lock();
    o.write_all(text.as_bytes()).and_then(|_| o.flush()).map_err(stdout_error)
}

/// "cannot write to standard output: `reason`".
fn stdout_error(reason: impl std::fmt::Display) -> Error {
    Error::Write { path: "to standard output".into(), reason: reason.to_string() }
}

/// Whether standard output was closed when the process started (`>&-`),
/// as [`record_stdout_at_start`] saw it.
static STDOUT_CLOSED_AT_START: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Records whether descriptor 1 is open. The binary calls this before
/// `main` (from an `.init_array` constructor): by the time `main` runs, Rust's
/// runtime has put /dev/null (opened read-write) on a closed descriptor 1,
/// and that cannot be told from a /dev/null the caller opened read-write on
/// purpose (`1<>/dev/null`, Python's `subprocess.DEVNULL`), which is a valid
/// place to write. Only queries the descriptor and stores a flag, so it is
/// safe to run before the runtime is set up.
pub fn record_stdout_at_start() {
    #[cfg(unix)]
    {
        // SAFETY: fcntl only queries descriptor 1.
        if unsafe { libc::fcntl(1, libc::F_GETFD) } == -1 {
            STDOUT_CLOSED_AT_START.store(true, std::sync::atomic::Ordering::Relaxed);
        }
    }
}

/// Standard output was closed at start-up, or is closed now.
fn stdout_closed() -> bool {
    if STDOUT_CLOSED_AT_START.load(std::sync::atomic::Ordering::Relaxed) {
        return true;
    }
    #[cfg(unix)]
    {
        // SAFETY: fcntl only queries descriptor 1.
        if unsafe { libc::fcntl(1, libc::F_GETFD) } == -1 {
            return true;
        }
    }
    false
}

/// The JSON text of a value, with the tool's version, the git commit (when
/// known) and the schema version added to the top-level object (or to each
/// object of a top-level list).
pub fn json_text<T: serde::Serialize>(v: &T) -> Result<String> {
    // a value serde cannot represent is a bug of the caller's types
    let mut value = serde_json::to_value(v).map_err(|e| Error::Message(e.to_string()))?;
    stamp(&mut value);
    serde_json::to_string_pretty(&value).map_err(|e| Error::Message(e.to_string()))
}

/// Adds `subdlab_version`, `git_commit` and `schema_version` to a JSON value.
pub fn stamp(value: &mut serde_json::Value) {
    let add = |m: &mut serde_json::Map<String, serde_json::Value>| {
        m.insert("subdlab_version".into(), TOOL_VERSION.into());
        m.insert("git_commit".into(), git_commit().map(|c| c.into()).unwrap_or(serde_json::Value::Null));
        m.insert("schema_version".into(), SCHEMA_VERSION.into());
    };
    match value {
        serde_json::Value::Object(m) => add(m),
        serde_json::Value::Array(a) => a.iter_mut().filter_map(|x| x.as_object_mut()).for_each(add),
        _ => {}
    }
}

pub fn print_json<T: serde::Serialize>(v: &T) -> Result<()> {
    out(&(json_text(v)? + "\n"))
}

/// Text safe to print on a terminal: control characters (newlines, escape
/// sequences) are shown escaped instead of acting.
pub fn printable(s: &str) -> String {
    if !s.chars().any(char::is_control) {
        return s.to_string();
    }
    s.chars().map(|c| if c.is_control() { c.escape_default().to_string() } else { c.to_string() }).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decode_text_drops_a_leading_byte_order_mark_only() {
        assert_eq!(decode_text(b"\xEF\xBB\xBFv 0 0 0\n".to_vec()).unwrap(), "v 0 0 0\n");
        assert_eq!(decode_text(b"a\xEF\xBB\xBF".to_vec()).unwrap(), "a\u{feff}");
        assert_eq!(decode_text(b"\xEF\xBB\xBF\xEF\xBB\xBF".to_vec()).unwrap(), "\u{feff}");
        assert!(decode_text(b"\xEF\xBB".to_vec()).is_err());
    }

    #[test]
    fn printable_escapes_control_characters() {
        assert_eq!(printable("QQTQT\n"), "QQTQT\\n");
        assert_eq!(printable("\u{1b}[31mRED"), "\\u{1b}[31mRED");
        assert_eq!(printable("λ1 = 1/2"), "λ1 = 1/2");
    }

    #[test]
    fn stamp_adds_versions_to_objects_and_list_items() {
        let mut v = serde_json::json!({"a": 1});
        stamp(&mut v);
        assert_eq!(v["schema_version"], SCHEMA_VERSION);
        assert_eq!(v["subdlab_version"], env!("CARGO_PKG_VERSION"));
        let mut l = serde_json::json!([{"a": 1}, {"b": 2}]);
        stamp(&mut l);
        assert_eq!(l[1]["schema_version"], SCHEMA_VERSION);
    }
}
