//! Regression tests of the robustness findings (output files, expressions,
//! claim files, standard output, usage errors, expensive requests) and of the
//! CI user's path (exit statuses, ERROR verdicts, --check-expected, JUnit,
//! versions, the example claim files). Big inputs are generated here.

use crate::common;
use common::{fails, subdlab};
use std::path::Path;

fn claim_file(dir: &Path, name: &str, claims: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, format!("paper = \"t\"\ntitle = \"t\"\n{claims}")).unwrap();
    p.to_str().unwrap().to_string()
}

fn claim(id: &str, body: &str) -> String {
    format!("\n[[claim]]\nid = \"{id}\"\nlocation = \"x\"\nstatement = \"x\"\n{body}\n")
}

fn verdicts(args: &[&str]) -> (Vec<(String, String)>, std::process::Output) {
    let mut a = args.to_vec();
    a.push("--json");
    let out = subdlab(&a);
    let v: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&out.stderr)));
    let list = v
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|p| p["claims"].as_array().unwrap().clone())
        .map(|c| (c["id"].as_str().unwrap().to_string(), c["verdict"].as_str().unwrap().to_string()))
        .collect();
    (list, out)
}

// ------------------------------------------------------------ output files

#[cfg(unix)]
#[test]
fn outputs_get_umask_modes_and_replaced_files_keep_theirs() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("m.mtx");
    let o = subdlab(&["matrix", "loop", "-n", "3", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // the test harness runs with the umask of its parent; the file must be 0666 minus it
    let umask = {
        let probe = dir.path().join("probe");
        std::fs::File::create(&probe).unwrap();
        0o666 & !std::fs::metadata(&probe).unwrap().permissions().mode() & 0o777
    };
    assert_eq!(std::fs::metadata(&out).unwrap().permissions().mode() & 0o777, 0o666 & !umask);
    // an existing file's mode is kept when it is replaced
    std::fs::set_permissions(&out, std::fs::Permissions::from_mode(0o640)).unwrap();
    assert!(subdlab(&["matrix", "loop", "-n", "4", "--out", out.to_str().unwrap()]).status.success());
    assert_eq!(std::fs::metadata(&out).unwrap().permissions().mode() & 0o777, 0o640);
    assert!(std::fs::read_to_string(&out).unwrap().contains("valence 4"));
}

#[cfg(unix)]
#[test]
fn symlinks_keep_pointing_and_special_files_are_written_in_place() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("target.txt");
    std::fs::write(&target, "old").unwrap();
    let link = dir.path().join("link.mtx");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    assert!(subdlab(&["matrix", "loop", "-n", "3", "--output", link.to_str().unwrap()]).status.success());
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link must stay a link");
    assert!(std::fs::read_to_string(&target).unwrap().starts_with("%%MatrixMarket"));
    // a FIFO is written into, not replaced by a regular file
    let fifo = dir.path().join("pipe");
    let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    // SAFETY: mkfifo with a valid C string
    assert_eq!(unsafe { libc_mkfifo(c.as_ptr(), 0o600) }, 0);
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    assert!(subdlab(&["matrix", "loop", "-n", "3", "-o", fifo.to_str().unwrap()]).status.success());
    assert!(reader.join().unwrap().starts_with("%%MatrixMarket"));
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    // /dev/null stays the device; /dev/stdout reaches standard output
    assert!(subdlab(&["matrix", "loop", "-n", "3", "-o", "/dev/null"]).status.success());
    assert!(std::fs::metadata("/dev/null").unwrap().file_type().is_char_device());
    let o = subdlab(&["matrix", "loop", "-n", "3", "-o", "/dev/stdout"]);
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("%%MatrixMarket"));
    // a directory or a dangling link: one-line errors
    assert!(fails(&["matrix", "loop", "-n", "3", "-o", dir.path().to_str().unwrap()]).contains("is a directory"));
    let dangling = dir.path().join("dangling");
    std::os::unix::fs::symlink(dir.path().join("nowhere/x"), &dangling).unwrap();
    assert!(fails(&["matrix", "loop", "-n", "3", "-o", dangling.to_str().unwrap()]).contains("does not exist"));
    // nothing else was left in the folder
    let mut names: Vec<String> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
    names.sort();
    assert_eq!(names, ["dangling", "link.mtx", "pipe", "target.txt"]);
}

/// The text `matrix loop -n 3` writes (to standard output, or any -o file).
fn loop_matrix() -> Vec<u8> {
    let o = subdlab(&["matrix", "loop", "-n", "3"]);
    assert!(o.status.success() && o.stdout.starts_with(b"%%MatrixMarket"));
    o.stdout
}

#[cfg(target_os = "linux")]
#[test]
fn outputs_through_proc_and_dev_links_are_replaced_or_appended_never_mixed() {
    let dir = tempfile::tempdir().unwrap();
    let want = loop_matrix();
    // old contents longer than the new: written in place, their tail would stay
    let old = vec![b'z'; want.len() + 5000];
    let run = |out: &str, stdout: std::process::Stdio| {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab"))
            .current_dir(dir.path())
            .args(["matrix", "loop", "-n", "3", "-o", out])
            .stdout(stdout)
            .output()
            .unwrap();
        assert!(o.status.success(), "{out}: {}", String::from_utf8_lossy(&o.stderr));
    };
    // a folder reached through a link (/proc/self/cwd): the real file is replaced
    let real = dir.path().join("x.mtx");
    std::fs::write(&real, &old).unwrap();
    run("/proc/self/cwd/x.mtx", std::process::Stdio::null());
    assert_eq!(std::fs::read(&real).unwrap(), want);
    // a relative link in another folder: the file it names is replaced
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    std::os::unix::fs::symlink("../x.mtx", dir.path().join("sub/l.mtx")).unwrap();
    std::fs::write(&real, &old).unwrap();
    run("sub/l.mtx", std::process::Stdio::null());
    assert_eq!(std::fs::read(&real).unwrap(), want);
    assert!(std::fs::symlink_metadata(dir.path().join("sub/l.mtx")).unwrap().file_type().is_symlink());
    // standard output appended to a log (`-o /dev/stdout >> log`): the log
    // keeps what it had and gains the output, as `>>` means
    let log = dir.path().join("log.txt");
    for path in ["/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"] {
        std::fs::write(&log, &old).unwrap();
        run(path, std::fs::OpenOptions::new().append(true).open(&log).unwrap().into());
        assert_eq!(std::fs::read(&log).unwrap(), [old.as_slice(), &want].concat(), "{path} >> log");
        // `> log`: the shell empties the log, which then holds exactly the output
        run(path, std::fs::File::create(&log).unwrap().into());
        assert_eq!(std::fs::read(&log).unwrap(), want, "{path} > log");
    }
    let mut names: Vec<String> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
    names.sort();
    assert_eq!(names, ["log.txt", "sub", "x.mtx"], "no temporaries left");
}

#[cfg(unix)]
extern "C" {
    #[link_name = "mkfifo"]
    fn libc_mkfifo(path: *const std::os::raw::c_char, mode: u32) -> i32;
}

/// A quad torus of `k` × `k` faces as OBJ text.
fn torus(k: usize) -> String {
    let mut s = String::new();
    for i in 0..k {
        for j in 0..k {
            let (u, v) = (i as f64 / k as f64 * std::f64::consts::TAU, j as f64 / k as f64 * std::f64::consts::TAU);
            s += &format!("v {} {} {}\n", (2.0 + v.cos()) * u.cos(), (2.0 + v.cos()) * u.sin(), v.sin());
        }
    }
    let id = |i: usize, j: usize| (i % k) * k + (j % k) + 1;
    for i in 0..k {
        for j in 0..k {
            s += &format!("f {} {} {} {}\n", id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
        }
    }
    s
}

#[cfg(unix)]
#[test]
fn interrupted_writes_leave_no_temporary_and_stale_ones_are_removed() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = dir.path().join("torus.obj");
    std::fs::write(&mesh, torus(350)).unwrap();
    let out = dir.path().join("out.obj");
    let temporaries = || {
        std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .filter(|n| n.contains(".subdlab-"))
            .collect::<Vec<_>>()
    };
    for signal in ["INT", "TERM"] {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab"))
            .args(["refine", mesh.to_str().unwrap(), "--scheme", "catmull-clark", "-l", "2", "-o"])
            .arg(&out)
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        // wait for the temporary to appear, then interrupt the write
        let t0 = std::time::Instant::now();
        while temporaries().is_empty() && t0.elapsed().as_secs() < 60 {
            if child.try_wait().unwrap().is_some() {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(2));
        }
        let seen = !temporaries().is_empty();
        let _ = std::process::Command::new("kill").args([&format!("-{signal}"), &child.id().to_string()]).status();
        let status = child.wait().unwrap();
        if seen {
            use std::os::unix::process::ExitStatusExt;
            assert!(status.signal().is_some() || status.success(), "{status:?}");
        }
        assert!(temporaries().is_empty(), "SIGINT/TERM left {:?}", temporaries());
    }
    // a temporary of a process that no longer runs (killed with SIGKILL) is
    // removed by the next write of the same file
    let stale = dir.path().join(".out.obj.subdlab-999999999-0.tmp");
    std::fs::write(&stale, "partial").unwrap();
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/cube.obj");
    let o = subdlab(&[
        "refine",
        cube.to_str().unwrap(),
        "--scheme",
        "catmull-clark",
        "-l",
        "1",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!stale.exists());
    assert!(temporaries().is_empty());
}

// ------------------------------------------------------------ standard output, usage

/// Typical invocations of every subcommand that prints to standard output
/// (`report` prints through the same `io::out` but takes minutes: left out).
fn printing_invocations(figure: &str) -> Vec<Vec<String>> {
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/cube.obj");
    let cube = cube.to_str().unwrap();
    let scheme_file = Path::new(env!("CARGO_MANIFEST_DIR")).join("schemes/loop.toml");
    let lists: [&[&str]; 17] = [
        &["schemes"],
        &["schemes", scheme_file.to_str().unwrap()],
        &["spectrum", "loop", "-n", "5", "--json"],
        &["spectrum", "loop", "-n", "5", "--certify"],
        &["stencils", "loop", "-n", "5"],
        &["matrix", "loop", "-n", "3"],
        &["curve", "four-point"],
        &["charmap", "loop", "-n", "5"],
        &["curvature", "loop", "-n", "7"],
        &["curvature", "loop", "-n", "7", "--json"],
        &["curvature", "loop", "-n", "7", "--out", figure],
        &["sweep", "loop", "--valences", "3..5"],
        &["sweep", "loop", "--valences", "3..5", "--csv"],
        &["verify", "--paper", "khan-mustafa"],
        &["matrix", "loop", "-n", "3", "-o", "/dev/stdout"],
        &["--help"],
        &["--version"],
    ];
    let mut all: Vec<Vec<String>> = lists.iter().map(|a| a.iter().map(|s| s.to_string()).collect()).collect();
    // commands that write files only: nothing to fail on standard output
    let refined = figure.replace(".svg", ".obj");
    let quiet: [&[&str]; 2] = [
        &["refine", cube, "--scheme", "catmull-clark", "-l", "1", "-o", &refined],
        &["plot", "spectrum", "loop", "--valences", "3..5", "-o", figure],
    ];
    all.extend(quiet.iter().map(|a| a.iter().map(|s| s.to_string()).collect()));
    all
}

#[cfg(unix)]
#[test]
fn full_or_closed_stdout_is_a_one_line_error() {
    let dir = tempfile::tempdir().unwrap();
    let figure = dir.path().join("f.svg");
    for args in printing_invocations(figure.to_str().unwrap()) {
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab")).args(&args).stdout(full).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        if args[0] == "refine" || args[0] == "plot" {
            assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
            continue;
        }
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains("cannot write"), "{args:?}: {err}");
    }
    // a closed stdout (`>&-`)
    let out = std::process::Command::new("sh")
        .arg("-c")
        .arg(format!("'{}' schemes >&-", env!("CARGO_BIN_EXE_subdlab")))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("standard output: it is closed"));
}

#[cfg(unix)]
#[test]
fn stdout_on_dev_null_opened_read_write_is_written() {
    // what Python's subprocess.DEVNULL and the shell's `1<>/dev/null` give:
    // a valid place to write, unlike a closed descriptor (above)
    let null = std::fs::OpenOptions::new().read(true).write(true).open("/dev/null").unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab")).arg("schemes").stdout(null).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
    let out = std::process::Command::new("sh")
        .arg("-c")
        .arg(format!("'{}' curvature loop -n 7 1<>/dev/null", env!("CARGO_BIN_EXE_subdlab")))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn long_inputs_are_cut_in_error_lines() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("r.svg");
    let svg = svg.to_str().unwrap();
    let run = |reference: &str| {
        let out = subdlab(&["plot", "spectrum", "loop", "--valences", "3..4", "--reference", reference, "-o", svg]);
        assert_eq!(out.status.code(), Some(2));
        String::from_utf8(out.stderr).unwrap()
    };
    // 120,001 characters without a space, then with spaces: one short line
    // naming the size, the message's own words kept
    for reference in ["1+".repeat(60_000) + "x", "1 + ".repeat(30_000) + "x"] {
        let err = run(&reference);
        assert_eq!(err.trim_end().lines().count(), 1, "{}", &err[..err.len().min(400)]);
        assert!(err.len() < 300, "{} bytes: {}", err.len(), &err[..err.len().min(400)]);
        assert!(err.starts_with(&format!("error: reference '{}", &reference[..40])), "{err}");
        assert!(err.contains(&format!("… ({} bytes)", reference.len())), "{err}");
    }
    // a value clap refuses is echoed by clap's usage message: cut too
    let out = subdlab(&["spectrum", "loop", "-n", &"9".repeat(120_000)]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stderr.len() < 600, "{}", String::from_utf8_lossy(&out.stderr[..out.stderr.len().min(600)]));
    assert!(String::from_utf8_lossy(&out.stderr).contains("… (120000 bytes)"));
}

// ------------------------------------------------------------ input files

#[test]
fn a_byte_order_mark_is_not_part_of_the_first_line() {
    let dir = tempfile::tempdir().unwrap();
    let bom = |text: &str| [b"\xEF\xBB\xBF".as_slice(), text.as_bytes()].concat();
    // a tetrahedron whose first line is a vertex: refined the same with a mark
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
    // unified-sqrt3 with one alpha per vertex, first line a value
    let alphas = "0\n1/2\n1\n3/2\n";
    let mesh = dir.path().join("t.obj");
    let params = dir.path().join("alpha.txt");
    let refine = |out: &str| {
        let out = dir.path().join(out);
        let mut args = vec!["refine", mesh.to_str().unwrap(), "--scheme", "unified-sqrt3", "-l", "1"];
        args.extend(["--vertex-params", params.to_str().unwrap(), "-o", out.to_str().unwrap()]);
        let o = subdlab(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read(out).unwrap()
    };
    std::fs::write(&mesh, obj).unwrap();
    std::fs::write(&params, alphas).unwrap();
    let plain = refine("plain.obj");
    assert!(String::from_utf8_lossy(&plain).lines().filter(|l| l.starts_with("f ")).count() > 4);
    std::fs::write(&mesh, bom(obj)).unwrap();
    std::fs::write(&params, bom(alphas)).unwrap();
    assert_eq!(refine("marked.obj"), plain);
    // scheme and claim files whose first line is a key
    let scheme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("schemes/loop.toml")).unwrap();
    let scheme: String =
        scheme.lines().filter(|l| !l.starts_with('#') && !l.is_empty()).map(|l| l.to_string() + "\n").collect();
    let file = dir.path().join("s.toml");
    let describe = |text: Vec<u8>| {
        std::fs::write(&file, text).unwrap();
        let o = subdlab(&["schemes", file.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        o.stdout
    };
    assert_eq!(describe(bom(&scheme)), describe(scheme.into_bytes()));
    let claims = claim_file(dir.path(), "c.toml", &claim("a", "check = \"identity\"\nlhs = \"1/2\"\nrhs = \"2/4\""));
    let text = std::fs::read_to_string(&claims).unwrap();
    std::fs::write(&claims, bom(&text)).unwrap();
    let (v, _) = verdicts(&["verify", "--claims", &claims]);
    assert_eq!(v, [("a".to_string(), "HOLDS".to_string())]);
}

#[test]
fn usage_errors_show_clap_s_whole_message() {
    let out = subdlab(&["spectrum", "loop"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--valence <VALENCE>") && err.contains("Usage: subdlab spectrum"), "{err}");
    let out = subdlab(&[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("Usage: subdlab <COMMAND>"));
    // user text in errors is shown with control characters escaped
    let err = fails(&["spectrum", "four-three", "-n", "5", "--faces", "QQTQT\n"]);
    assert!(err.contains("\\n"), "{err}");
}

#[test]
fn version_and_json_carry_tool_and_schema_versions() {
    let v = String::from_utf8(subdlab(&["--version"]).stdout).unwrap();
    assert!(v.starts_with(&format!("subdlab {}", env!("CARGO_PKG_VERSION"))), "{v}");
    for args in [
        vec!["spectrum", "loop", "-n", "5", "--json"],
        vec!["schemes", "--json"],
        vec!["matrix", "loop", "-n", "3", "--json"],
        vec!["verify", "--paper", "khan-mustafa", "--json"],
    ] {
        let out = subdlab(&args);
        let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let first = if j.is_array() { &j[0] } else { &j };
        assert_eq!(first["subdlab_version"], env!("CARGO_PKG_VERSION"), "{args:?}");
        assert_eq!(first["schema_version"], 1, "{args:?}");
        assert!(first.get("git_commit").is_some(), "{args:?}");
    }
}

#[test]
fn human_tables_print_no_debug_text() {
    for args in [
        vec!["spectrum", "catmull-clark", "-n", "4"],
        vec!["stencils", "loop", "-n", "5"],
        vec!["charmap", "loop", "-n", "5"],
    ] {
        let text = String::from_utf8(subdlab(&args).stdout).unwrap();
        for debug in ["Analysis", "Minimal", "Dft", "Full", "Some(", "None", "[0, "] {
            assert!(!text.contains(debug), "{args:?} prints {debug}: {text}");
        }
    }
    let text = String::from_utf8(subdlab(&["spectrum", "catmull-clark", "-n", "4"]).stdout).unwrap();
    assert!(text.contains("neighbourhood analysis") && text.contains("method dft"), "{text}");
}

// ------------------------------------------------------------ expensive requests

#[test]
fn expensive_requests_are_refused_up_front_with_the_estimate() {
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/cube.obj");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c.obj");
    let t0 = std::time::Instant::now();
    let err = fails(&[
        "refine",
        cube.to_str().unwrap(),
        "--scheme",
        "catmull-clark",
        "-l",
        "12",
        "-o",
        out.to_str().unwrap(),
    ]);
    // 6 quads: the first level has max(24 faces, 26 vertices) = 26, then 4x per level
    assert!(err.contains(&format!("about {}", 26usize * 4usize.pow(11))), "{err}");
    let err = fails(&["spectrum", "catmull-clark", "-n", "300", "--method", "full"]);
    // the analysis neighbourhood of Catmull–Clark has 6n + 1 vertices
    assert!(err.contains("1801×1801"), "{err}");
    // the characteristic map's net at valence 1000: TPS splits each quad
    // into 9, so four levels are far above the face limit; the refusal comes
    // after the first analysis step, with the estimate and the levels that fit
    let err = fails(&["charmap", "tps", "-n", "1000", "--levels", "4"]);
    let estimate: f64 = err
        .split("about ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no estimate in: {err}"));
    assert!(estimate > 1_000_000.0, "{err}");
    let fits: usize = err
        .split("--levels ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no level advice in: {err}"));
    assert!((1..4).contains(&fits), "{err}");
    assert!(t0.elapsed().as_secs() < 20, "refusals must come before the work");
}

// ------------------------------------------------------------ expressions

#[test]
fn long_expression_chains_do_not_overflow_the_stack() {
    let dir = tempfile::tempdir().unwrap();
    // 4999 terms of every chain kind (just under the 10000-character limit)
    let ones = |sep: &str| format!("1{}", format!("{sep}1").repeat(4999 / (sep.len() + 1)));
    let mut claims = String::new();
    let plus = format!("1{}", "+1".repeat(4999));
    claims += &claim("plus", &format!("check = \"identity\"\nlhs = \"{plus}\"\nrhs = \"5000\""));
    claims += &claim("times", &format!("check = \"identity\"\nlhs = \"{}\"\nrhs = \"1\"", ones("*")));
    claims += &claim("implicit", &format!("check = \"identity\"\nlhs = \"{}\"\nrhs = \"1\"", ones(" ")));
    claims += &claim("cos", &format!("check = \"identity\"\nlhs = \"cos(0 {})\"\nrhs = \"1\"", "*1".repeat(4000)));
    claims += &claim(
        "float",
        &format!(
            "check = \"inequality\"\nscheme = \"\"\nvalences = [3]\nlhs = \"{} + 0 pi\"\nop = \">\"\nrhs = \"4989\"",
            &plus[..9979]
        ),
    );
    let f = claim_file(dir.path(), "deep.toml", &claims);
    let (v, out) = verdicts(&["verify", "--claims", &f]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(v.iter().all(|(_, x)| x == "HOLDS"), "{v:?}");
    // nesting beyond the depth limit is a clear error, not a crash
    let deep = format!("{}1{}", "(".repeat(300), ")".repeat(300));
    let f = claim_file(
        dir.path(),
        "nest.toml",
        &claim("n", &format!("check = \"identity\"\nlhs = \"{deep}\"\nrhs = \"1\"")),
    );
    let (_, out) = verdicts(&["verify", "--claims", &f]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("nested too deeply"));
}

#[test]
fn principal_branch_and_kronecker_agree_between_exact_and_float() {
    let dir = tempfile::tempdir().unwrap();
    let mut c = String::new();
    for (id, lhs, rhs) in [
        ("sqrt-1", "sqrt(-1)", "i"),
        ("sqrt-4", "sqrt(-4)", "2 i"),
        ("half-power", "(-1)^(1/2)", "i"),
        ("var", "sqrt(-a)", "sqrt(a) i"),
        ("kron-exact", "kronecker(1e-13)", "0"),
        ("kron-float", "kronecker(1e-13) + 0 pi", "0"),
        ("kron-zero", "kronecker(cos(pi/2)) + 0 pi", "1"),
    ] {
        c += &claim(id, &format!("check = \"identity\"\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\nvars = {{ a = \"2\" }}"));
    }
    let f = claim_file(dir.path(), "branch.toml", &c);
    let (v, _) = verdicts(&["verify", "--claims", &f]);
    assert!(v.iter().all(|(_, x)| x == "HOLDS"), "{v:?}");
}

#[test]
fn the_exact_path_is_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let bomb = "sum(m,1,10000,((1001/1000)^256)^190-((1001/1000)^256)^190)";
    let big = vec!["((3^256)^256)^9"; 200].join("*");
    let mut c = claim("bomb", &format!("check = \"identity\"\nlhs = \"{bomb}\"\nrhs = \"0\""));
    c += &claim("product", &format!("check = \"identity\"\nlhs = \"{big}\"\nrhs = \"1\""));
    c += &claim("huge", "check = \"identity\"\nlhs = \"((3^256)^256)^9\"\nrhs = \"((3^256)^256)^9 + 1\"");
    let f = claim_file(dir.path(), "bomb.toml", &c);
    let t0 = std::time::Instant::now();
    let out = subdlab(&["verify", "--claims", &f]);
    assert!(t0.elapsed().as_secs() < 30, "{:?}", t0.elapsed());
    // no 500 KB line of digits
    assert!(out.stdout.len() < 20_000, "{}", out.stdout.len());
    // a long exact fraction as a parameter: a one-line error at once
    let a = format!("1{}/3{}", "7".repeat(3000), "1".repeat(3000));
    let t0 = std::time::Instant::now();
    let err = fails(&["spectrum", "non-box", "-n", "5", "-p", &format!("a={a}")]);
    assert!(err.contains("at most 400 bits"), "{err}");
    assert!(err.len() < 300, "{err}");
    assert!(t0.elapsed().as_secs() < 10);
    // exact values just outside an integer bound are outside
    let above_one = format!("a=1{}1/1{}", "0".repeat(29), "0".repeat(30));
    let err = fails(&["spectrum", "non-box", "-n", "5", "-p", &above_one]);
    assert!(err.contains("out of range"), "{err}");
}

// ------------------------------------------------------------ claim files

#[test]
fn unknown_keys_are_errors_naming_the_line_and_the_rest_is_evaluated() {
    let dir = tempfile::tempdir().unwrap();
    let good = claim("good", "check = \"identity\"\nlhs = \"1/2 + 1/4\"\nrhs = \"3/4\"");
    let typo = claim(
        "typo",
        "check = \"size\"\nscheme = \"loop\"\nvalences = [5]\nvalue = \"n + 1\"\nneighborhood = \"minimal\"",
    );
    let f = claim_file(dir.path(), "keys.toml", &format!("{good}{typo}"));
    let junit = dir.path().join("j.xml");
    let out = subdlab(&["verify", "--claims", &f, "--junit", junit.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    // header lines 1-2, good claim on lines 4-9, the typo claim's key on line 17
    let text = std::fs::read_to_string(&f).unwrap();
    let line = text.lines().position(|l| l.starts_with("neighborhood")).unwrap() + 1;
    assert!(err.contains(&format!("line {line}")) && err.contains("unknown key 'neighborhood'"), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("HOLDS        good") && stdout.contains("ERROR        typo"), "{stdout}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("<error message=\"ERROR\">") && xml.contains("tests=\"2\""), "{xml}");
    for (key, body) in [
        ("blok", "check = \"eigenvalues\"\nscheme = \"loop\"\nvalences = [5]\nvalues = [\"1\"]\ncompare = \"contains\"\nblok = \"1\""),
        ("rhss", "check = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\nrhss = \"2\""),
        ("expeted", "check = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\nexpeted = \"REFUTED\""),
    ] {
        let f = claim_file(dir.path(), "k.toml", &claim("k", body));
        let (v, out) = verdicts(&["verify", "--claims", &f]);
        assert_eq!(v, [("k".to_string(), "ERROR".to_string())]);
        assert!(String::from_utf8_lossy(&out.stderr).contains(&format!("unknown key '{key}'")));
    }
    // the valence cannot be redefined by vars
    let f = claim_file(
        dir.path(),
        "n.toml",
        &claim("n", "check = \"size\"\nscheme = \"loop\"\nvalences = [5]\nvalue = \"n + 1\"\nvars = { n = \"6\" }"),
    );
    let (v, _) = verdicts(&["verify", "--claims", &f]);
    assert_eq!(v[0].1, "ERROR");
}

#[test]
fn exit_statuses_junit_and_expected_verdicts() {
    let dir = tempfile::tempdir().unwrap();
    let holds = claim("holds", "check = \"identity\"\nlhs = \"cos(pi/3)\"\nrhs = \"1/2\"");
    // a known-false statement pinned as a regression
    let pinned = claim("pinned", "check = \"identity\"\nlhs = \"1/3\"\nrhs = \"0.333\"\nexpected = \"REFUTED\"");
    let f = claim_file(dir.path(), "a.toml", &format!("{holds}{pinned}"));
    let junit = dir.path().join("j.xml");
    let j = junit.to_str().unwrap();
    assert_eq!(subdlab(&["verify", "--claims", &f, "--junit", j]).status.code(), Some(1));
    assert!(std::fs::read_to_string(&junit).unwrap().contains("failures=\"1\""));
    let out = subdlab(&["verify", "--check-expected", "--claims", &f, "--junit", j]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("failures=\"0\" errors=\"0\"") && xml.contains("REFUTED as recorded"), "{xml}");
    // a syntax error in one file: its ERROR, the other file still evaluated, JUnit written
    let broken = dir.path().join("broken.toml");
    std::fs::write(&broken, "paper = \"x\"\ntitle = \n").unwrap();
    std::fs::remove_file(&junit).unwrap();
    let out = subdlab(&["verify", "--claims", broken.to_str().unwrap(), "--claims", &f, "--junit", j]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stdout).contains("HOLDS        holds"));
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("broken.toml") && xml.contains("<error message=\"ERROR\">"), "{xml}");
    // control characters are escaped in JUnit (XML 1.0 cannot carry them)
    let ctl = claim("ctl", "check = \"identity\"\nlhs = \"1\"\nrhs = \"2\"")
        .replace("statement = \"x\"", "statement = \"a\\u0001b\\u001b\"");
    let f = claim_file(dir.path(), "ctl.toml", &ctl);
    subdlab(&["verify", "--claims", &f, "--junit", j]);
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(!xml.chars().any(|c| (c as u32) < 0x20 && !"\t\n\r".contains(c)), "{xml:?}");
    assert!(xml.contains("a\\u{1}b\\u{1b}"), "{xml}");
    // the built-in registry under --check-expected is green
    let out = subdlab(&["verify", "--paper", "khan-mustafa", "--check-expected", "--junit", j]);
    assert_eq!(out.status.code(), Some(0));
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(!xml.contains("<failure") && !xml.contains("<error"), "{xml}");
    assert_eq!(subdlab(&["verify", "--paper", "khan-mustafa"]).status.code(), Some(1));
}

#[test]
fn non_finite_values_and_empty_ranges_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    let mut c = String::new();
    c += &claim(
        "ineq",
        "check = \"inequality\"\nscheme = \"\"\nvalences = [3]\nlhs = \"0*10^400\"\nop = \">=\"\nrhs = \"1\"",
    );
    c += &claim("size", "check = \"size\"\nscheme = \"loop\"\nvalences = [5]\nvalue = \"0*10^400\"");
    c += &claim("sub", "check = \"subdominant\"\nscheme = \"loop\"\nvalences = [5]\nvalue = \"0*10^400\"");
    c += &claim(
        "window",
        "check = \"lattice-matrix\"\nscheme = \"khan-mustafa\"\nwindow = [5, -5, 5, -5]\nscale = \"1\"\nrows = []",
    );
    c += &claim("bigwindow", "check = \"lattice-matrix\"\nscheme = \"khan-mustafa\"\nwindow = [-9223372036854775808, 9223372036854775807, 0, 0]\nscale = \"1\"\nrows = [\"1\"]");
    c += &claim("empty", "check = \"spectral-c1\"\nscheme = \"loop\"\nvalences = []");
    let f = claim_file(dir.path(), "nan.toml", &c);
    let (v, _) = verdicts(&["verify", "--claims", &f]);
    for (id, verdict) in &v {
        assert_eq!(verdict, "ERROR", "{id}: {v:?}");
    }
    assert_eq!(v.len(), 6);
}

#[test]
fn builtin_data_is_validated() {
    let dir = tempfile::tempdir().unwrap();
    let strip = r#"scheme = "four-three", faces = "QQTTT", spokes = [[0, 1], [-1, 0], [0, -1], [1, 0], [1, 1]], shift = [0, 1], leading = ["1", "1/2", "1/2", "1/4", "1/4", "1/4"], bound = "1/4""#;
    let km = r#"monomials = [[0, 0], [1, 0], [0, 1], [1, 1], [2, 0], [0, 2]], lo = -1, hi = 1, rules = [[[0]], [[0]], [[0]], [[0]]]"#;
    let poly = r#"scheme = "catmull-clark", faces = "QQQQ", spokes = [[1, 0], [0, 1], [-1, 0], [0, -1]]"#;
    let cases = [
        (
            "curve.c1-laurent",
            r#"{ scheme = "unified-curve", param = "alpha", values = ["2"], max_steps = 0 }"#.to_string(),
        ),
        ("lattice.fit-masks", format!("{{ {km}, denominator = 0 }}")),
        ("lattice.fit-masks", "{ monomials = [[0, 0], [-1, 0]], lo = -1, hi = 1, denominator = 1, rules = [] }".into()),
        (
            "lattice.fit-masks",
            format!("{{ {km}, denominator = 1, lo = -300, hi = 300 }}").replace("lo = -1, hi = 1, ", ""),
        ),
        ("strip.jsr", format!("{{ {strip}, window = [-9223372036854775808, 9223372036854775807, 0, 0], length = 3 }}")),
        ("strip.jsr", format!("{{ {strip}, window = [-3, 3, -3, 4], length = -1 }}")),
        ("strip.jsr", format!("{{ {strip}, window = [-3, 3, -3, 4], length = 40 }}")),
        ("strip.jsr", format!("{{ {strip}, window = [-100000, 100000, -100000, 100000], length = 3 }}")),
        ("strip.defective", format!("{{ {strip}, window = [-20, 20, -20, 20] }}")),
        ("window.polynomials", format!("{{ {poly}, window = [-4, 4, -4, 4], degree = -1 }}")),
        ("window.polynomials", format!("{{ {poly}, window = [-60, 60, -60, 60], degree = 3 }}")),
        ("window.polynomials", format!("{{ {poly}, window = [-4, 4, -4, 4], degree = 20 }}")),
        (
            "fourthree.convex-hull",
            r#"{ faces = "QQQQQ", params = { eon_quad_term = "1" }, rings = 4, steps = 12 }"#.into(),
        ),
        (
            "fourthree.convex-hull",
            r#"{ faces = "QQQQQ", params = { eon_quad_term = "1" }, rings = 1000000, steps = 3 }"#.into(),
        ),
        (
            "fourthree.convex-hull",
            r#"{ faces = "QQQQQ", params = { eon_quad_term = "1" }, rings = -1, steps = 3 }"#.into(),
        ),
        (
            "fourthree.convex-hull",
            r#"{ faces = "QQQQQ", params = { eon_quad_term = "1" }, rings = 4, steps = 0 }"#.into(),
        ),
        ("fourthree.step-two-weights", r#"{ faces = "QQQQQ", params = { eon_quad_term = "1" }, rings = 0 }"#.into()),
    ];
    let mut c = String::new();
    for (k, (name, data)) in cases.iter().enumerate() {
        c += &claim(&format!("c{k}"), &format!("check = \"builtin\"\nname = \"{name}\"\ndata = {data}"));
    }
    // 3000 entries of 100000 repeats: refused, not allocated
    let many = vec!["\"0;100000\""; 3000].join(",");
    c += &claim("count", &format!("check = \"eigenvalues\"\nscheme = \"loop\"\nvalences = [5]\nvalues = [{many}]"));
    let f = claim_file(dir.path(), "data.toml", &c);
    let t0 = std::time::Instant::now();
    let (v, out) = verdicts(&["verify", "--claims", &f]);
    assert!(t0.elapsed().as_secs() < 60, "{:?}", t0.elapsed());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(v.len(), cases.len() + 1);
    for (id, verdict) in &v {
        assert_eq!(verdict, "ERROR", "{id}: {v:?}");
    }
}

#[cfg(unix)]
#[test]
fn unbounded_inputs_are_capped() {
    let t0 = std::time::Instant::now();
    let err = fails(&["verify", "--claims", "/dev/zero"]);
    assert!(err.contains("larger than 16 MiB"), "{err}");
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/cube.obj");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o.obj");
    let err = fails(&[
        "refine",
        cube.to_str().unwrap(),
        "--scheme",
        "unified-sqrt3",
        "-l",
        "1",
        "--vertex-params",
        "/dev/zero",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(err.contains("larger than 64 MiB"), "{err}");
    assert!(t0.elapsed().as_secs() < 30);
    // many claim files: bounded worker threads
    let f = claim_file(dir.path(), "one.toml", &claim("a", "check = \"identity\"\nlhs = \"1\"\nrhs = \"1\""));
    let mut args = vec!["verify"];
    for _ in 0..500 {
        args.push("--claims");
        args.push(&f);
    }
    assert_eq!(subdlab(&args).status.code(), Some(0));
}

// ------------------------------------------------------------ the README's examples

#[test]
fn every_check_kind_has_a_runnable_example_claim_file() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/claims");
    for (kind, _) in subdlab::claims::CHECK_KEYS {
        let file = dir.join(format!("{kind}.toml"));
        let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        assert!(text.contains(&format!("check = \"{kind}\"")), "{kind}");
        let out = subdlab(&["verify", "--check-expected", "--claims", file.to_str().unwrap(), "--json"]);
        assert_eq!(out.status.code(), Some(0), "{kind}: {}", String::from_utf8_lossy(&out.stderr));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let claims = v[0]["claims"].as_array().unwrap();
        assert!(!claims.is_empty());
        for c in claims {
            let want = c["expected"].as_str().unwrap_or("HOLDS");
            assert_eq!(c["verdict"], want, "{kind}: {c}");
        }
    }
}
