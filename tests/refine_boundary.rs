//! `subdlab refine` on open and creased meshes (issue 26): open edges are
//! tagged as the boundary on reading, creases and corners come from
//! `#crease` / `#corner` lines or a `--tags` side file, the refined tags are
//! written back (so refine → refine composes), and malformed tags are one-line
//! errors with a non-zero exit and no output file.

use crate::common;
use common::{fails, subdlab};

use std::path::{Path, PathBuf};

use subdlab::mesh::obj::{parse_obj, read_obj_file, read_tags, write_obj};
use subdlab::mesh::VertexTag;

fn example(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/meshes").join(name)
}

fn refine(input: &Path, scheme: &str, levels: &str, out: &Path, extra: &[&str]) {
    let mut args = vec!["refine", input.to_str().unwrap(), "--scheme", scheme, "--levels", levels];
    args.extend(["-o", out.to_str().unwrap()]);
    args.extend(extra);
    let o = subdlab(&args);
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
}

/// The shipped examples refine with the schemes that have boundary rules,
/// and the output is the same mesh whether refined in one run or in two
/// (the second run reads the first's tags back).
#[test]
fn open_and_creased_examples_refine_and_compose() {
    let dir = tempfile::tempdir().unwrap();
    for (mesh, scheme) in [
        ("open-cube.obj", "catmull-clark"),
        ("quad-frame-hole.obj", "catmull-clark"),
        ("creased-cube.obj", "catmull-clark"),
        ("triangle-disc.obj", "loop"),
    ] {
        let (once, half, twice) =
            (dir.path().join("once.obj"), dir.path().join("half.obj"), dir.path().join("twice.obj"));
        refine(&example(mesh), scheme, "3", &once, &[]);
        refine(&example(mesh), scheme, "1", &half, &[]);
        refine(&half, scheme, "2", &twice, &[]);
        let body = |p: &Path| -> Vec<String> {
            std::fs::read_to_string(p).unwrap().lines().filter(|l| !l.starts_with("# ")).map(String::from).collect()
        };
        assert_eq!(body(&once), body(&twice), "{mesh}: 3 levels = 1 + 2 levels");
        let (m, p) = read_obj_file(&once).unwrap();
        assert_eq!(p.len(), m.num_vertices());
    }
    // the creased cube: its crease has 4 edges, each halved three times, and one corner
    let out = dir.path().join("c.obj");
    refine(&example("creased-cube.obj"), "catmull-clark", "3", &out, &[]);
    let (m, _) = read_obj_file(&out).unwrap();
    let tags = m.tags.as_ref().unwrap();
    assert_eq!(tags.sharp_edges().len(), 4 * 8);
    assert_eq!(tags.corners(), vec![1]);
    assert_eq!(m.vertex_tag(1), VertexTag::Corner);
}

/// A closed mesh's creases may come from a side file instead of the OBJ:
/// the same result as the `#crease` lines.
#[test]
fn a_tags_side_file_is_the_same_as_tag_lines() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(example("creased-cube.obj")).unwrap();
    let plain: String = text.lines().filter(|l| !l.starts_with("#c")).map(|l| format!("{l}\n")).collect();
    let (plain_path, side) = (dir.path().join("plain.obj"), dir.path().join("cube.tags"));
    std::fs::write(&plain_path, plain).unwrap();
    std::fs::write(&side, "# the top rim\ncrease 2 6 8 4 2\ncorner 2  # interpolated\n").unwrap();
    let (a, b) = (dir.path().join("a.obj"), dir.path().join("b.obj"));
    refine(&example("creased-cube.obj"), "catmull-clark", "2", &a, &[]);
    refine(&plain_path, "catmull-clark", "2", &b, &["--tags", side.to_str().unwrap()]);
    let body = |p: &Path| -> String {
        std::fs::read_to_string(p).unwrap().lines().filter(|l| !l.starts_with("# ")).collect::<Vec<_>>().join("\n")
    };
    assert_eq!(body(&a), body(&b));
}

/// Tags round-trip through the writer; creases only (the boundary is the
/// open edges, tagged again on reading).
#[test]
fn tags_round_trip_through_obj() {
    let (mut m, p) = read_obj_file(&example("creased-cube.obj")).unwrap();
    let text = write_obj(&m, &p, "round trip");
    let (back, _) = parse_obj(&text).unwrap();
    assert_eq!(back.tags, m.tags);
    let (mut open, q) = read_obj_file(&example("open-cube.obj")).unwrap();
    assert!(open.tags.is_none(), "no tag lines: no tags");
    open.tag_open_edges();
    assert_eq!(open.tags.as_ref().unwrap().sharp_edges().len(), 4);
    assert!(!write_obj(&open, &q, "x").contains("#crease"), "boundary edges are not written");
    // a side file adds to the file's tags
    read_tags("corner 3\n", &mut m, "side").unwrap();
    assert_eq!(m.tags.as_ref().unwrap().corners(), vec![1, 2]);
}

/// Malformed tags: one line naming the line and what is wrong, a non-zero
/// exit, no panic, no output file.
#[test]
fn malformed_tags_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let cube = std::fs::read_to_string(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("meshes/cube.obj")).unwrap();
    let out = dir.path().join("out.obj");
    let o = out.to_str().unwrap();
    for (line, want) in [
        ("#crease 1 8", "not an edge"),
        ("#crease 1 2 8", "2-8 is not an edge"),
        ("#crease 1", "at least two"),
        ("#crease 1 NaN", "'NaN' is not a vertex index"),
        ("#crease 1 -2", "'-2' is not a vertex index"),
        ("#crease 1 2.5", "not a vertex index"),
        ("#corner 0", "out of range"),
        ("#corner 9", "out of range"),
        ("#corner 99999999999999999999999", "not a vertex index"),
        ("#corner", "at least one"),
    ] {
        let path = dir.path().join("bad.obj");
        std::fs::write(&path, format!("{cube}{line}\n")).unwrap();
        let lines = cube.lines().count() + 1;
        let err = parse_obj(&format!("{cube}{line}\n")).unwrap_err().to_string();
        assert!(err.contains(want) && err.contains(&format!("line {lines}")), "{line}: {err}");
        let err = fails(&["refine", path.to_str().unwrap(), "--scheme", "catmull-clark", "--levels", "1", "-o", o]);
        assert!(err.contains(want), "{line}: {err}");
        // the same in a side file
        let (plain, side) = (dir.path().join("plain.obj"), dir.path().join("t.tags"));
        std::fs::write(&plain, &cube).unwrap();
        std::fs::write(&side, format!("\n{}\n", line.trim_start_matches('#'))).unwrap();
        let args = ["refine", plain.to_str().unwrap(), "--scheme", "loop", "--levels", "1", "-o", o];
        let err = fails(&[&args[..], &["--tags", side.to_str().unwrap()]].concat());
        assert!(err.contains(want) && err.contains("line 2"), "{line}: {err}");
    }
    let side = dir.path().join("t.tags");
    std::fs::write(&side, "bevel 1 2\n").unwrap();
    let plain = dir.path().join("plain.obj");
    let args = ["refine", plain.to_str().unwrap(), "--scheme", "catmull-clark", "--levels", "1", "-o", o];
    let err = fails(&[&args[..], &["--tags", side.to_str().unwrap()]].concat());
    assert!(err.contains("unknown tag 'bevel'"), "{err}");
    let err = fails(&[&args[..], &["--tags", "/nonexistent/t.tags"]].concat());
    assert!(err.contains("/nonexistent/t.tags"), "{err}");
    // `# crease` with a space is an ordinary comment
    assert!(parse_obj(&format!("{cube}# crease 1 8\n")).unwrap().0.tags.is_none());
    // schemes without boundary rules refuse open and creased meshes in one line
    for (mesh, scheme) in
        [("open-cube.obj", "doo-sabin"), ("creased-cube.obj", "four-three"), ("triangle-disc.obj", "sqrt3")]
    {
        let m = example(mesh);
        let err = fails(&["refine", m.to_str().unwrap(), "--scheme", scheme, "--levels", "1", "-o", o]);
        assert!(err.contains("boundary/crease rules are not available"), "{scheme}: {err}");
    }
    assert!(!out.exists(), "no output file on failure");
}
