//! Records the git commit the binary is built from (`subdlab --version`, the
//! JSON outputs) when the crate is built from a git checkout and git is
//! available; otherwise the commit is simply absent.

use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    if !out.status.success() {
        return None;
    }
    let s = String::from_utf8(out.stdout).ok()?.trim().to_string();
    (!s.is_empty()).then_some(s)
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let commit = git(&["rev-parse", "--short=12", "HEAD"]).unwrap_or_default();
    // rebuild when HEAD moves (the files exist only in a checkout)
    for what in ["--git-path", "--git-common-dir"] {
        let arg = if what == "--git-path" { vec!["rev-parse", what, "HEAD"] } else { vec!["rev-parse", what] };
        if let Some(p) = git(&arg) {
            let p = std::path::PathBuf::from(p);
            if what == "--git-path" {
                println!("cargo:rerun-if-changed={}", p.display());
            } else {
                println!("cargo:rerun-if-changed={}", p.join("refs").join("heads").display());
                println!("cargo:rerun-if-changed={}", p.join("packed-refs").display());
            }
        }
    }
    println!("cargo:rustc-env=SUBDLAB_GIT_COMMIT={commit}");
    let version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default();
    let long = if commit.is_empty() { version } else { format!("{version} (commit {commit})") };
    println!("cargo:rustc-env=SUBDLAB_VERSION_LONG={long}");
}
