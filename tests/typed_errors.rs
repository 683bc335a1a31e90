//! The library's errors say what happened by their variant (`subdlab::error::Error`),
//! while their text stays the one-line message the command line prints.

use subdlab::error::Error;
use subdlab::neighbourhood::Configuration;
use subdlab::schemes;

#[test]
fn an_unknown_scheme_is_an_input_error() {
    let e = schemes::build("no-such-scheme", &[]).err().unwrap();
    assert!(matches!(e, Error::Input(_)), "{e:?}");
    assert!(e.to_string().starts_with("unknown scheme 'no-such-scheme'; known schemes: "), "{e}");
    let e = schemes::resolve("loop", &[("no_such_param".into(), "1".into())]).err().unwrap();
    assert!(matches!(e, Error::Input(_)), "{e:?}");
}

#[test]
fn valence_out_of_range_is_an_input_error() {
    let scheme = schemes::build("loop", &[]).unwrap();
    let e = Configuration::regular(scheme.as_ref(), 2).unwrap_err();
    assert_eq!(e, Error::Input("valence 2 is below 3; extraordinary points have valence 3 or more".into()));
    let e = Configuration::with_faces(scheme.as_ref(), 4, "QQX").unwrap_err();
    assert!(matches!(e, Error::Input(_)), "{e:?}");
}

#[test]
fn a_malformed_scheme_file_is_a_file_error() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, "name = \"bad\"\ntopology = \"primal-triangle\"\n[vertex\n").unwrap();
    let e = schemes::resolve(path.to_str().unwrap(), &[]).err().unwrap();
    assert!(matches!(e, Error::File(_)), "{e:?}");
    assert!(e.to_string().starts_with(path.to_str().unwrap()), "{e}");
    // a missing one too
    let e = schemes::resolve(dir.path().join("missing.toml").to_str().unwrap(), &[]).err().unwrap();
    assert!(matches!(e, Error::File(_)), "{e:?}");
}

#[test]
fn an_unwritable_output_is_a_write_error() {
    let dir = tempfile::tempdir().unwrap();
    // a directory cannot be replaced by a file
    let e = subdlab::io::write_atomic(dir.path(), b"x").unwrap_err();
    let shown = dir.path().display().to_string();
    assert_eq!(e, Error::Write { path: shown.clone(), reason: "it is a directory".into() });
    assert_eq!(e.to_string(), format!("cannot write {shown}: it is a directory"));
    // a folder that does not exist
    let e = subdlab::io::write_atomic(&dir.path().join("no/such/dir/out.svg"), b"x").unwrap_err();
    assert!(matches!(e, Error::Write { .. }), "{e:?}");
}

#[test]
fn a_bad_expression_is_an_input_error() {
    let e = subdlab::numeric::expr::Expr::parse("1 + * 2").unwrap_err();
    assert!(matches!(e, Error::Input(_)), "{e:?}");
    let e = subdlab::numeric::ParamValue::parse("nan").unwrap_err();
    assert!(matches!(e, Error::Input(_)), "{e:?}");
}
