//! Property test of the OBJ reader and of the mesh code behind it: random and
//! mutated versions of the shipped meshes must give a mesh or a one-line
//! error, never a panic or a hang; a mesh that is accepted must refine.
//! Sizes are capped before allocation (an oversized file is refused from its
//! length alone).

use crate::common;
use common::Rng;
use std::path::Path;
use subdlab::mesh::obj::{parse_obj, read_obj_file, MAX_FILE_BYTES};
use subdlab::refine::mesh::refine_mesh;
use subdlab::schemes;

/// Tokens that probe the reader's number and index handling.
const TOKENS: [&str; 24] = [
    "0",
    "-1",
    "-99",
    "1",
    "2",
    "7",
    "99999999999999999999",
    "4294967297",
    "nan",
    "inf",
    "-inf",
    "1e309",
    "1e-320",
    "-0",
    "1/2/3",
    "1//3",
    "1/x",
    "//",
    "/",
    "f",
    "v",
    "vt",
    "#",
    "\t",
];

fn mutate(rng: &mut Rng, text: &str) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    for _ in 0..1 + rng.below(3) {
        let k = rng.below(lines.len().max(1));
        match rng.below(8) {
            0 if !lines.is_empty() => {
                lines.remove(k);
            }
            1 if !lines.is_empty() => {
                // a repeated face is an edge used twice in one direction
                let l = lines[k].clone();
                lines.insert(k, l);
            }
            2 if !lines.is_empty() => {
                // reversed face: inconsistent orientation
                let l = &lines[k];
                if let Some(rest) = l.strip_prefix("f ") {
                    let mut v: Vec<&str> = rest.split_whitespace().collect();
                    v.reverse();
                    lines[k] = format!("f {}", v.join(" "));
                }
            }
            3 if !lines.is_empty() => {
                // one token replaced
                let mut toks: Vec<String> = lines[k].split_whitespace().map(String::from).collect();
                if !toks.is_empty() {
                    let t = rng.below(toks.len());
                    toks[t] = TOKENS[rng.below(TOKENS.len())].to_string();
                }
                lines[k] = toks.join(" ");
            }
            4 if !lines.is_empty() => {
                // one token dropped or added
                let mut toks: Vec<String> = lines[k].split_whitespace().map(String::from).collect();
                if rng.below(2) == 0 && !toks.is_empty() {
                    toks.remove(rng.below(toks.len()));
                } else {
                    toks.push(TOKENS[rng.below(TOKENS.len())].to_string());
                }
                lines[k] = toks.join(" ");
            }
            5 => {
                // a random line of tokens
                let l: Vec<&str> = (0..rng.below(8)).map(|_| TOKENS[rng.below(TOKENS.len())]).collect();
                lines.insert(k.min(lines.len()), l.join(" "));
            }
            6 if !lines.is_empty() => {
                // cut a line short (as a truncated download would)
                let cut = rng.below(lines[k].len() + 1);
                lines[k] = lines[k].chars().take(cut).collect();
            }
            _ => {
                // a random character, possibly non-ASCII
                let c = char::from_u32(rng.below(0x3000) as u32).unwrap_or('?');
                if !lines.is_empty() {
                    let at = rng.below(lines[k].chars().count() + 1);
                    let mut chars: Vec<char> = lines[k].chars().collect();
                    chars.insert(at, c);
                    lines[k] = chars.into_iter().collect();
                }
            }
        }
    }
    lines.join("\n")
}

#[test]
fn random_and_mutated_meshes_never_panic_or_hang() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes");
    let mut bases: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "obj"))
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    bases.sort();
    assert!(bases.len() >= 6);
    let cc = schemes::build("catmull-clark", &[]).unwrap();
    let mut rng = Rng(0xD1B5_4A32_D192_ED03);
    let (mut accepted, mut rejected) = (0, 0);
    for case in 0..3000 {
        let text = if case % 10 == 9 {
            // pure noise from the token alphabet
            (0..rng.below(40)).map(|_| TOKENS[rng.below(TOKENS.len())]).collect::<Vec<_>>().join(" ")
        } else {
            mutate(&mut rng, &bases[case % bases.len()])
        };
        let t0 = std::time::Instant::now();
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let (mesh, points) = parse_obj(&text)?;
            // an accepted mesh must be usable: one Catmull–Clark step (any polygons)
            refine_mesh(cc.as_ref(), &mesh, &points, 1).map(|_| ())
        }));
        match result {
            Ok(Ok(())) => accepted += 1,
            Ok(Err(e)) => {
                let e = e.to_string();
                assert!(!e.is_empty() && !e.contains('\n'), "case {case}: error not one line: {e:?}\n{text}");
                rejected += 1;
            }
            Err(_) => panic!("case {case} panicked on:\n{text}"),
        }
        assert!(t0.elapsed().as_secs() < 5, "case {case} took {:?}:\n{text}", t0.elapsed());
    }
    eprintln!("{accepted} meshes accepted, {rejected} rejected");
    // both outcomes must occur often, or the mutations test little
    assert!(accepted > 200 && rejected > 1000, "accepted {accepted}, rejected {rejected}");
}

#[test]
fn invalid_utf8_and_oversized_files_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.obj");
    std::fs::write(&bad, b"v 0 0 0\nv 1 0 0\nv 0 1 0\n\xff\xfe f 1 2 3\n").unwrap();
    let e = read_obj_file(&bad).unwrap_err();
    assert!(matches!(e, subdlab::error::Error::File(_)), "a file error, typed as such: {e:?}");
    let e = e.to_string();
    assert!(e.contains("line 4") && e.contains("UTF-8"), "{e}");
    // a sparse file (no disk used) one byte above the cap
    let big = dir.path().join("big.obj");
    std::fs::File::create(&big).unwrap().set_len(MAX_FILE_BYTES + 1).unwrap();
    let e = read_obj_file(&big).unwrap_err().to_string();
    assert!(e.contains("larger than the supported"), "{e}");
}
