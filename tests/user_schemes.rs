//! Scheme files: the shipped examples in `schemes/` must reproduce the built-in
//! schemes (which their own tests check against closed forms) entry by entry,
//! exactly where the weights are rational; the parser must reject bad files
//! with the line and the field, and survive random and mutated input.

use crate::common;
use common::{fails, subdlab, Rng};
use subdlab::matrix::local::AssembleError;
use subdlab::matrix::{assemble, LocalMatrix};
use subdlab::neighbourhood::{discover, Configuration, NeighbourhoodKind};
use subdlab::numeric::Rational;
use subdlab::schemes::user::{UserSchemeDef, MAX_EXPR_CHARS, MAX_FILE_BYTES};
use subdlab::schemes::{self, Scheme};
use subdlab::spectrum::stencils::{limit_stencil, tangent_stencils};
use subdlab::spectrum::{analyse, Options};

const EXAMPLES: [(&str, &str); 4] = [
    ("schemes/loop.toml", "loop"),
    ("schemes/catmull-clark.toml", "catmull-clark"),
    ("schemes/non-box.toml", "non-box"),
    // the edge rule at extraordinary vertices written out with j (kronecker)
    ("schemes/catmull-clark-edge-rule.toml", "catmull-clark"),
];

fn path(rel: &str) -> String {
    format!("{}/{rel}", env!("CARGO_MANIFEST_DIR"))
}

fn file_scheme(rel: &str, overrides: &[(String, String)]) -> Box<dyn Scheme> {
    schemes::resolve(&path(rel), overrides).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn parse(text: &str) -> Result<UserSchemeDef, subdlab::error::Error> {
    UserSchemeDef::parse(text, "x.toml")
}

fn assert_same_f64(a: &LocalMatrix<f64>, b: &LocalMatrix<f64>, what: &str) {
    assert_eq!(a.labels, b.labels, "{what}: labels");
    for i in 0..a.size() {
        for j in 0..a.size() {
            let (x, y) = (a.get(i, j), b.get(i, j));
            assert!((x - y).abs() <= 1e-14, "{what}: S[{i}][{j}] = {x} from the file, {y} built in");
        }
    }
}

/// Local subdivision matrices of the file and the built-in scheme on both
/// neighbourhoods: floats to 1e-14, exact rationals equal wherever the
/// built-in one is exact (and then the file's must be exact too).
fn compare_matrices(file: &dyn Scheme, builtin: &dyn Scheme, n: usize) -> usize {
    let (cf, cb) = (Configuration::regular(file, n).unwrap(), Configuration::regular(builtin, n).unwrap());
    let (df, db) = (discover(file, &cf).unwrap(), discover(builtin, &cb).unwrap());
    let mut exact = 0;
    for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
        let what = format!("{} vs {} n = {n} {kind:?}", file.name(), builtin.name());
        let (mf, mb) = (assemble::<f64>(file, &df, kind).unwrap(), assemble::<f64>(builtin, &db, kind).unwrap());
        assert_eq!(mf.size(), mb.size(), "{what}: sizes");
        assert_same_f64(&mf, &mb, &what);
        let (ef, eb) = (assemble::<Rational>(file, &df, kind), assemble::<Rational>(builtin, &db, kind));
        match (ef, eb) {
            (Ok(ef), Ok(eb)) => {
                assert_eq!(ef.labels, eb.labels);
                for i in 0..ef.size() {
                    for j in 0..ef.size() {
                        assert_eq!(ef.get(i, j), eb.get(i, j), "{what}: exact S[{i}][{j}]");
                    }
                }
                exact += 1;
            }
            (Err(AssembleError::Inexact), Err(AssembleError::Inexact)) => {}
            (f, b) => panic!("{what}: exact path differs: file {:?}, built-in {:?}", f.is_ok(), b.is_ok()),
        }
    }
    exact
}

#[test]
fn example_files_give_the_built_in_matrices_for_valences_3_to_12() {
    for (rel, name) in EXAMPLES {
        let file = file_scheme(rel, &[]);
        let builtin = schemes::build(name, &[]).unwrap();
        assert_eq!(file.topology(), builtin.topology());
        assert_eq!(file.sector_kind(), builtin.sector_kind());
        assert_eq!(file.face_control(), builtin.face_control());
        for n in 3..=12 {
            let exact = compare_matrices(file.as_ref(), builtin.as_ref(), n);
            // cos(2π/n) is rational at n = 4 and 6: every example is exact there
            if n == 4 || n == 6 {
                assert_eq!(exact, 2, "{rel}: exact matrices at n = {n}");
            }
        }
    }
}

#[test]
fn example_files_give_the_built_in_spectra_and_stencils() {
    for (rel, name) in EXAMPLES {
        let file = file_scheme(rel, &[]);
        let builtin = schemes::build(name, &[]).unwrap();
        for n in 3..=12 {
            let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: true };
            let run = |s: &dyn Scheme| analyse(s, &Configuration::regular(s, n).unwrap(), &opts).unwrap();
            let (af, ab) = (run(file.as_ref()), run(builtin.as_ref()));
            let what = format!("{rel} n = {n}");
            let (sf, sb) = (&af.spectrum, &ab.spectrum);
            assert_eq!((sf.matrix_size, sf.minimal_size), (sb.matrix_size, sb.minimal_size), "{what}");
            assert_eq!(sf.eigenvalues.len(), sb.eigenvalues.len(), "{what}: distinct eigenvalues");
            for (x, y) in sf.eigenvalues.iter().zip(&sb.eigenvalues) {
                assert!((x.re - y.re).abs() < 1e-10 && (x.im - y.im).abs() < 1e-10, "{what}: {x:?} vs {y:?}");
                assert_eq!(x.algebraic_multiplicity, y.algebraic_multiplicity, "{what}");
                assert_eq!(x.geometric_multiplicity, y.geometric_multiplicity, "{what}");
                assert_eq!(x.exact, y.exact, "{what}: exact value");
            }
            assert_eq!(sf.verdict.c1_spectral, sb.verdict.c1_spectral, "{what}");
            let close = |a: &[f64], b: &[f64]| a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9);
            assert!(close(&limit_stencil(sf).unwrap(), &limit_stencil(sb).unwrap()), "{what}: limit stencil");
            let (tf, tb) = (tangent_stencils(sf).unwrap(), tangent_stencils(sb).unwrap());
            assert_eq!(tf.len(), tb.len(), "{what}: tangent stencils");
            for (x, y) in tf.iter().zip(&tb) {
                assert!(close(x, y), "{what}: tangent stencil");
            }
        }
    }
}

/// Non-box with a parameter: a_n = a for n != 4, 1/2 at n = 4, as the
/// built-in `a` parameter; checks defaults and overrides.
const NON_BOX_A: &str = r#"
name = "non-box-a"
topology = "fcv"
[params.a]
default = "9/10"
min = 0
max = 1
[vertex]
centre = "1 - (kronecker(n - 4)/2 + (1 - kronecker(n - 4)) a)"
fcv = "(kronecker(n - 4)/2 + (1 - kronecker(n - 4)) a) / n"
[edge]
ends = 0.25
fcv = "1/4"
[face]
centre = "1 - (kronecker(n - 4)/2 + (1 - kronecker(n - 4)) a)"
corner = "(kronecker(n - 4)/2 + (1 - kronecker(n - 4)) a) / n"
[corner]
vertex = "1/4"
fcv = 0.5
side = "1/8"
"#;

#[test]
fn parameters_take_defaults_and_overrides_like_built_in_parameters() {
    let def = parse(NON_BOX_A).unwrap();
    let o = |v: &str| vec![("a".to_string(), v.to_string())];
    for (file_over, builtin_over) in [(vec![], o("9/10")), (o("3/5"), o("3/5"))] {
        let file = def.build(&file_over).unwrap();
        let builtin = schemes::build("non-box", &builtin_over).unwrap();
        assert_eq!(file.params().get("a").unwrap().exact, builtin.params().get("a").unwrap().exact);
        for n in [3, 5, 6] {
            assert_eq!(compare_matrices(&file, builtin.as_ref(), n), 2, "a rational: exact at n = {n}");
        }
    }
    let e = def.build(&o("2")).err().unwrap();
    assert!(matches!(e, subdlab::error::Error::Input(_)), "{e:?}");
    assert!(e.to_string().contains("out of range [0, 1]"));
    let e = def.build(&[("b".into(), "1".into())]).err().unwrap();
    assert!(matches!(e, subdlab::error::Error::Input(_)), "{e:?}");
    assert!(e.to_string().contains("no parameter 'b'"));
}

#[test]
fn the_command_line_takes_a_file_where_it_takes_a_name() {
    let out = subdlab(&["spectrum", &path("schemes/catmull-clark.toml"), "--valence", "5", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let file: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let out = subdlab(&["spectrum", "catmull-clark", "--valence", "5", "--json"]);
    let builtin: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(file["scheme"], "catmull-clark-file");
    assert_eq!(file["matrix_size"], builtin["matrix_size"]);
    assert_eq!(file["eigenvalues"].as_array().unwrap().len(), builtin["eigenvalues"].as_array().unwrap().len());
    for (x, y) in file["eigenvalues"].as_array().unwrap().iter().zip(builtin["eigenvalues"].as_array().unwrap()) {
        assert!((x["re"].as_f64().unwrap() - y["re"].as_f64().unwrap()).abs() < 1e-10);
    }
    let e = fails(&["spectrum", "no/such/dir/s.toml", "--valence", "5"]);
    assert!(e.contains("cannot read scheme file no/such/dir/s.toml"), "{e}");
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, "name = \"x\"\ntopology = \"primal-triangle\"\n[vertex]\ncentre = \"1 - q\"\n").unwrap();
    let e = fails(&["stencils", bad.to_str().unwrap(), "--valence", "5"]);
    assert!(e.contains("line 4, field vertex.centre: unknown variable 'q'"), "{e}");
    let e = fails(&["spectrum", &path("schemes/loop.toml"), "--valence", "5", "--param", "a=1"]);
    assert!(e.contains("has no parameter 'a'; its parameters: blz"), "{e}");
    let e = fails(&["spectrum", &path("schemes/doo-sabin.toml"), "--valence", "5", "--param", "a=1"]);
    assert!(e.contains("has no parameters"), "{e}");
}

const LOOP: &str = r#"name = "l"
topology = "primal-triangle"
[vertex]
centre = "3/8 + (3/8 + cos(2 pi / n) / 4)^2"
edge = "(5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n"
[edge]
ends = "3/8"
opposite = "1/8"
"#;

/// The error for LOOP with `from` replaced by `to`.
fn error_of(from: &str, to: &str) -> String {
    assert!(LOOP.contains(from), "{from}");
    let e = parse(&LOOP.replacen(from, to, 1)).err().unwrap_or_else(|| panic!("{to} should be rejected"));
    // a malformed scheme file is a file error, whatever part of it is wrong
    assert!(matches!(e, subdlab::error::Error::File(_)), "{to}: {e:?}");
    let e = e.to_string();
    assert!(!e.contains('\n'), "one line: {e}");
    e
}

#[test]
fn parse_errors_name_the_line_and_the_field() {
    assert!(parse(LOOP).is_ok());
    let cases: [(&str, &str, &str); 17] = [
        (
            "[edge]\nends = \"3/8\"\nopposite = \"1/8\"\n",
            "",
            "x.toml: missing section [edge] (topology primal-triangle)",
        ),
        ("(5/8", "(5/8 - q", "x.toml line 5, field vertex.edge: unknown variable 'q'"),
        ("ends = \"3/8\"", "ends = \"3/8 j\"", "line 7, field edge.ends: unknown variable 'j'"),
        ("ends = \"3/8\"", "ends = \"3/8 n\"", "line 7, field edge.ends: unknown variable 'n' (edge rules"),
        ("opposite = \"1/8\"", "opposite = \"1/8 +\"", "line 8, field edge.opposite: unexpected end of expression"),
        ("opposite = \"1/8\"", "opposite = \"1/8\"\nextra = \"0\"", "line 9, field edge.extra: unknown field"),
        ("opposite = \"1/8\"", "opposite = \"1/4\"", "field edge: the weights of the edge rule sum to 1.25"),
        ("opposite = \"1/8\"\n", "", "line 6, field edge.opposite: missing"),
        ("3/8 + (", "1/8 + (", "field vertex: the weights of the vertex rule sum to 0.75 at n = 3"),
        ("name = \"l\"", "name = \"loop\"", "line 1, field name: 'loop' is a built-in scheme"),
        ("name = \"l\"", "name = \"a b\"", "line 1, field name: 'a b' is not a scheme name"),
        ("topology = \"primal-triangle\"", "topology = \"hex\"", "line 2, field topology: unknown topology 'hex'"),
        ("topology = \"primal-triangle\"", "topology = \"primal-quad\"", "line 3, field vertex.face: missing"),
        ("[edge]", "[face]\ncorner = \"1/n\"\n[edge]", "field face: topology primal-triangle has no face rule"),
        ("edge = \"(5/8", "edge = \"cos(2 pi j / n) + (5/8", "line 5, field vertex.edge: the weight differs between j"),
        (
            "centre = \"3/8",
            "centre = \"sqrt(-1) + 3/8",
            "line 4, field vertex.centre: at n = 3, j = 0: the weight is complex",
        ),
        (
            "centre = \"3/8",
            "centre = \"1/(n-3) + 3/8",
            "line 4, field vertex.centre: at n = 3, j = 0: division by zero",
        ),
    ];
    for (from, to, want) in cases {
        let e = error_of(from, to);
        assert!(e.contains(want), "{to}: got '{e}', want '{want}'");
    }
    // TOML-level errors: syntax, unknown top-level keys, wrong types
    assert!(error_of("[edge]", "[edge").starts_with("x.toml line 6:"));
    assert!(error_of("name = \"l\"", "name = \"l\"\ncolour = 1").contains("line 2: unknown field `colour`"));
    assert!(error_of("ends = \"3/8\"", "ends = [1]").contains("field edge.ends: expected an expression string"));
    // affine = false accepts a rule whose weights do not sum to 1
    assert!(parse(&LOOP.replacen("opposite = \"1/8\"", "opposite = \"1/4\"", 1).replacen(
        "topology",
        "affine = false\ntopology",
        1
    ))
    .is_ok());
    // parameters: name, range, and use
    let with_param = |p: &str| LOOP.replacen("[vertex]", &format!("{p}\n[vertex]"), 1);
    let e = parse(&with_param("[params.n]\ndefault = 1")).err().unwrap().to_string();
    assert!(e.contains("line 3, field params.n: 'n' is reserved"), "{e}");
    let e = parse(&with_param("[params.w]\ndefault = 2\nmax = 1")).err().unwrap().to_string();
    assert!(e.contains("field params.w: default 2 is not in [-inf, 1]"), "{e}");
    let e = parse(&with_param("[params.w]\ndefault = \"x\"")).err().unwrap().to_string();
    assert!(e.contains("line 4, field params.w.default: 'x' is not a number"), "{e}");
    let e = parse(&with_param("[params.w]\ndefault = 1\nstep = 2")).err().unwrap().to_string();
    assert!(e.contains("unknown field `step`"), "{e}");
    // caps on size
    let long = format!("1{}", " + 0".repeat(MAX_EXPR_CHARS));
    assert!(error_of("\"3/8\"", &format!("\"{long}\"")).contains("field edge.ends: expression longer than"));
    let big = format!("{LOOP}{}", "# padding\n".repeat(MAX_FILE_BYTES / 10));
    assert!(parse(&big).err().unwrap().to_string().contains("larger than"));
    // deep nesting within the size cap: TOML arrays and inline tables, parentheses
    for deep in [format!("x = {}", "[".repeat(30_000)), format!("x = {}", "{a=".repeat(15_000))] {
        assert!(parse(&deep).is_err());
    }
    assert!(error_of("\"3/8\"", &format!("\"{}1\"", "(".repeat(400)))
        .contains("field edge.ends: expression nested too deeply"));
}

/// The first `EXPR_PIECES` pieces are expression material.
const EXPR_PIECES: usize = 25;
const PIECES: [&str; 37] = [
    "n",
    "j",
    "pi",
    "cos(",
    "sqrt(",
    "kronecker(",
    "sum(",
    ",",
    "m",
    "sum(m, 0, n - 1, ",
    ")",
    "(",
    "^",
    "^256",
    "*",
    "/",
    "-",
    "+",
    "0",
    "1",
    "3/8",
    "1e308",
    "\"",
    "=",
    "[",
    "]",
    "\n",
    "#",
    "[params.a]\ndefault = 1\n",
    "a",
    "[face]",
    "corner",
    ".",
    "9999999999999999999999",
    "i",
    "[vertex]\n",
    "[edge-extraordinary]\n",
];

fn mutate(rng: &mut Rng, text: &str) -> String {
    let mut chars: Vec<char> = text.chars().collect();
    for _ in 0..1 + rng.below(4) {
        let at = if chars.is_empty() { 0 } else { rng.below(chars.len() + 1) };
        match rng.below(5) {
            0 if !chars.is_empty() => {
                let end = (at + 1 + rng.below(8)).min(chars.len());
                chars.drain(at.min(end)..end);
            }
            1 => chars.splice(at..at, PIECES[rng.below(PIECES.len())].chars()).for_each(drop),
            2 => chars.insert(at, char::from_u32(rng.below(0x250) as u32).unwrap_or('?')),
            3 if !chars.is_empty() => {
                // duplicate a stretch (repeated keys, nested parentheses)
                let end = (at + rng.below(40)).min(chars.len());
                let copy: Vec<char> = chars[at.min(end)..end].to_vec();
                chars.splice(at..at, copy).for_each(drop);
            }
            _ => chars.truncate(at),
        }
    }
    chars.into_iter().collect()
}

/// A random expression from the language's pieces, often ill-formed.
fn random_expr(rng: &mut Rng) -> String {
    (0..rng.below(30)).map(|_| PIECES[rng.below(EXPR_PIECES)]).collect::<Vec<_>>().join(if rng.below(2) == 0 {
        ""
    } else {
        " "
    })
}

#[test]
fn random_and_mutated_files_never_panic_or_hang() {
    let examples: Vec<String> = EXAMPLES.iter().map(|(rel, _)| std::fs::read_to_string(path(rel)).unwrap()).collect();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut accepted, mut rejected) = (0, 0);
    let start = std::time::Instant::now();
    for case in 0..4000 {
        let base = &examples[case % examples.len()];
        let text = match case % 4 {
            // one weight replaced by a random expression
            0 => {
                let e = random_expr(&mut rng).replace(['"', '\n'], "");
                let mut lines: Vec<String> = base.lines().map(String::from).collect();
                let weights: Vec<usize> = (0..lines.len()).filter(|&k| lines[k].contains("= \"")).collect();
                let k = weights[rng.below(weights.len())];
                let key = lines[k].split('=').next().unwrap().to_string();
                lines[k] = format!("{key}= \"{e}\"");
                lines.join("\n")
            }
            1 => mutate(&mut rng, LOOP),
            _ => mutate(&mut rng, base),
        };
        let t0 = std::time::Instant::now();
        let result = std::panic::catch_unwind(|| {
            let def = parse(&text)?;
            let scheme = def.build(&[])?;
            // a file that loads must also run: one analysis at valence 5
            let config = Configuration::regular(&scheme, 5)?;
            discover(&scheme, &config).map(|_| ())
        });
        common::tally_fuzz_case(case, &text, result, &mut accepted, &mut rejected);
        assert!(t0.elapsed().as_secs() < 10, "case {case} took {:?}:\n{text}", t0.elapsed());
    }
    eprintln!("{accepted} files accepted, {rejected} rejected");
    // the mutations must exercise both outcomes, or the test proves little
    assert!(accepted > 50 && rejected > 500, "accepted {accepted}, rejected {rejected}");
    assert!(start.elapsed().as_secs() < 300);
}

#[test]
fn example_files_refine_meshes_as_the_built_in_schemes_do() {
    use subdlab::mesh::obj::read_obj_file;
    use subdlab::refine::mesh::{add_face_control_vertices, refine_mesh};
    for (rel, name, mesh) in [
        ("schemes/loop.toml", "loop", "octahedron"),
        ("schemes/catmull-clark.toml", "catmull-clark", "cube"),
        ("schemes/non-box.toml", "non-box", "cube"),
        // valence 3 everywhere: both ends extraordinary, the mean of two stencils
        ("schemes/catmull-clark-edge-rule.toml", "catmull-clark", "cube"),
        // valences 3 to 6: edges with one, two and no extraordinary ends
        ("schemes/catmull-clark-edge-rule.toml", "catmull-clark", "mixed-quads"),
    ] {
        let (m, p) = read_obj_file(std::path::Path::new(&path(&format!("meshes/{mesh}.obj")))).unwrap();
        let (m, p) = if name == "non-box" { add_face_control_vertices(&m, &p, 1.0).unwrap() } else { (m, p) };
        let (file, builtin) = (file_scheme(rel, &[]), schemes::build(name, &[]).unwrap());
        let (mf, pf) = refine_mesh(file.as_ref(), &m, &p, 3).unwrap();
        let (mb, pb) = refine_mesh(builtin.as_ref(), &m, &p, 3).unwrap();
        assert_eq!(mf.faces(), mb.faces(), "{rel}: connectivity");
        for (x, y) in pf.iter().zip(&pb) {
            assert!((0..3).all(|k| (x[k] - y[k]).abs() < 1e-13), "{rel}: {x:?} vs {y:?}");
        }
    }
    // a primal-quad file has quad rules only, and says so
    let (m, p) = read_obj_file(std::path::Path::new(&path("meshes/octahedron.obj"))).unwrap();
    let e = refine_mesh(file_scheme("schemes/catmull-clark.toml", &[]).as_ref(), &m, &p, 1).unwrap_err().to_string();
    assert!(e.contains("a closed quad mesh (primal-quad scheme files have quad rules only)"), "{e}");
}
