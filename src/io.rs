//! Writing results: standard output, or files replaced atomically (write to a
//! temporary file in the same directory, then rename), so a crash leaves the
//! old file intact. A library module (not part of `cli`) because figures and
//! reports are written by library code too.
//!
//! - Only regular files are replaced. A symbolic link keeps pointing where it
//!   did: the file it names is replaced. Devices and FIFOs (`/dev/null`,
//!   `/dev/stdout`, a named pipe) are written into directly; a directory or a
//!   dangling link is a one-line error.
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

/// Writes `contents` to `path` (see the module documentation).
pub fn write_atomic(path: &Path, contents: &[u8]) -> Result<()> {
    let fail = |why: &dyn std::fmt::Display| Error::Write { path: path.display().to_string(), reason: why.to_string() };
    match fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => match fs::metadata(path) {
            Ok(t) if t.is_file() && !is_special_path(path) => {
                let real = fs::canonicalize(path).map_err(|e| fail(&e))?;
                replace(&real, contents, Some(&t)).map_err(|e| fail(&e))
            }
            Ok(t) if t.is_dir() => Err(fail(&"it is a directory")),
            Ok(_) => write_in_place(path, contents).map_err(|e| fail(&e)),
            Err(_) => Err(fail(&"it is a symbolic link to a file that does not exist")),
        },
        Ok(m) if m.is_dir() => Err(fail(&"it is a directory")),
        Ok(m) if m.is_file() && !is_special_path(path) => replace(path, contents, Some(&m)).map_err(|e| fail(&e)),
        Ok(_) => write_in_place(path, contents).map_err(|e| fail(&e)),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => replace(path, contents, None).map_err(|e| fail(&e)),
        Err(e) => Err(fail(&e)),
    }
}

/// Paths the system provides (`/dev/stdout` may resolve to a regular file
/// when standard output is redirected): written in place, never replaced.
fn is_special_path(path: &Path) -> bool {
    path.starts_with("/dev") || path.starts_with("/proc")
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
pub fn out(text: &str) -> Result<()> {
    if text.is_empty() {
        return Ok(());
    }
    #[cfg(unix)]
    {
        if stdout_was_closed() {
            return Err(stdout_error("it is closed"));
        }
    }
    let mut o = std::io::stdout().lock();
    o.write_all(text.as_bytes()).and_then(|_| o.flush()).map_err(stdout_error)
}

/// "cannot write to standard output: `reason`".
fn stdout_error(reason: impl std::fmt::Display) -> Error {
    Error::Write { path: "to standard output".into(), reason: reason.to_string() }
}

/// Whether the process started with standard output closed (`>&-`). Rust's
/// runtime then opens /dev/null read-write on descriptor 1, which a shell's
/// `> /dev/null` (write-only) never does; a descriptor that is closed now
/// counts too.
#[cfg(unix)]
fn stdout_was_closed() -> bool {
    // SAFETY: fcntl and fstat only query descriptor 1; `st` is plain data.
    unsafe {
        let flags = libc::fcntl(1, libc::F_GETFL);
        if flags == -1 {
            return true;
        }
        let mut st: libc::stat = std::mem::zeroed();
        if libc::fstat(1, &mut st) != 0 {
            return true;
        }
        let dev_null = (st.st_mode & libc::S_IFMT) == libc::S_IFCHR
            && libc::major(st.st_rdev) == 1
            && libc::minor(st.st_rdev) == 3;
        dev_null && (flags & libc::O_ACCMODE) == libc::O_RDWR
    }
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
