//! `subdlab charmap` and `subdlab plot` as a user runs them: JSON fields,
//! figure files, one-line errors.

use crate::common;
use common::{fails, subdlab};

#[test]
fn charmap_json_carries_the_stable_fields() {
    let out =
        subdlab(&["charmap", "catmull-clark", "--valence", "5", "--levels", "3", "--resolution", "128", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["regular"], true);
    assert_eq!(v["injective"], true);
    assert_eq!(v["winding_number"], 1);
    assert_eq!(v["overlap_pixels"], 0);
    assert_eq!(v["levels"], 3);
    assert_eq!(v["resolution"], 128);
    let r = v["min_jacobian_ratio"].as_f64().unwrap();
    assert!(r > 0.0 && r <= 1.0);
    assert_eq!(v["spectral_status"], "ok");
}

#[test]
fn charmap_json_has_the_fields_even_without_a_map() {
    // non-box with a = 0 at valence 3 freezes the centre's vertex and face
    // rules; whatever the spectrum then is, the stable fields are present and
    // the verdict is explained
    let out = subdlab(&["charmap", "non-box", "--valence", "3", "--param", "a=0", "--levels", "2", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for f in ["regular", "injective", "winding_number", "overlap_pixels", "min_jacobian_ratio", "levels", "resolution"]
    {
        assert!(v.get(f).is_some(), "field {f}");
    }
    assert!(!v["explanation"].as_str().unwrap().is_empty());
}

#[test]
fn figures_are_written_as_svg_and_png() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("ring.svg");
    let png = dir.path().join("ring.PNG");
    let spec = dir.path().join("spectrum.png");
    let wedge = dir.path().join("wedge.svg");
    for (args, path) in [
        (vec!["charmap", "loop", "--valence", "7", "--levels", "2", "--out"], &svg),
        (vec!["charmap", "doo-sabin", "--valence", "5", "--levels", "2", "--out"], &png),
        (vec!["charmap", "catmull-clark", "--valence", "24", "--levels", "2", "--wedge", "--out"], &wedge),
        (vec!["plot", "spectrum", "loop", "--valences", "3..8", "--out"], &spec),
    ] {
        let mut a = args.clone();
        a.push(path.to_str().unwrap());
        let out = subdlab(&a);
        assert!(out.status.success(), "{a:?}: {}", String::from_utf8_lossy(&out.stderr));
        let bytes = std::fs::read(path).unwrap();
        if path.extension().unwrap().eq_ignore_ascii_case("png") {
            assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{path:?}");
        } else {
            let text = String::from_utf8(bytes).unwrap();
            // the ring figure's title writes λ₁, the spectrum plot's legend λ1
            assert!(text.contains("<svg") && (text.contains("λ₁") || text.contains("λ1")), "{path:?}");
        }
    }
    // no temporary files left behind
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 4);
}

#[test]
fn bad_input_gives_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("x.svg");
    let good = good.to_str().unwrap();
    let e = fails(&["charmap", "no-such-scheme", "--valence", "5"]);
    assert!(e.contains("unknown scheme"), "{e}");
    fails(&["charmap", "loop", "--valence", "2"]);
    fails(&["charmap", "loop", "--valence", "1000000000"]);
    let e = fails(&["charmap", "loop", "--valence", "5", "--resolution", "0"]);
    assert!(e.contains("resolution"), "{e}");
    fails(&["charmap", "loop", "--valence", "5", "--resolution", "1000000"]);
    fails(&["charmap", "loop", "--valence", "5", "--levels", "0"]);
    fails(&["charmap", "loop", "--valence", "5", "--levels", "99"]);
    fails(&["charmap", "loop", "--valence", "5", "--rings", "0"]);
    let e = fails(&["charmap", "loop", "--valence", "5", "--out", "/nonexistent-dir/ring.svg"]);
    assert!(e.contains("cannot write"), "{e}");
    let e = fails(&["charmap", "loop", "--valence", "5", "--out", "ring.jpg"]);
    assert!(e.contains("extension"), "{e}");
    fails(&["charmap", "loop", "--valence", "5", "--out", "ring"]);
    // the regular-lattice scheme has its map at valence 4 only
    fails(&["charmap", "khan-mustafa", "--valence", "5"]);
    fails(&["charmap", "loop", "--valence", "5", "--wedge"]);
    fails(&["charmap", "loop", "--valence", "5", "--param", "a=1"]);
    fails(&["plot", "spectrum", "loop", "--valences", "9..3", "--out", good]);
    fails(&["plot", "spectrum", "loop", "--valences", "2..5", "--out", good]);
    fails(&["plot", "spectrum", "loop", "--valences", "three", "--out", good]);
    fails(&["plot", "spectrum", "loop", "--valences", "3..500", "--out", good]);
    fails(&["plot", "spectrum", "loop", "--count", "0", "--out", good]);
    fails(&["plot", "spectrum", "loop", "--out", "/nonexistent-dir/s.png"]);
    fails(&["plot", "spectrum", "loop", "--out", "s.gif"]);
    fails(&["plot", "nothing"]);
    assert!(!std::path::Path::new(good).exists());
}

/// Runs repeat to the last bit (no hash-order dependence in the ring's
/// boundary sums, its normalisation or its smallest-Jacobian facet).
#[test]
fn charmap_runs_repeat_exactly() {
    for scheme in ["catmull-clark", "non-box", "unified-sqrt3"] {
        let args = ["charmap", scheme, "--valence", "5", "--json"];
        let runs: Vec<Vec<u8>> = (0..4).map(|_| subdlab(&args).stdout).collect();
        assert!(runs.iter().all(|r| r == &runs[0] && !r.is_empty()), "{scheme}: runs differ");
    }
}

/// The CLI's flag and the claim file's `faces` reach one configuration:
/// `charmap four-three --faces QQTT` (a mixed eon, quads and triangles)
/// and a `characteristic-map` claim on the same sequence give the same
/// verdict and the same smallest Jacobian ratio of the same ring; the
/// all-quad default is a different ring (so the flag is not ignored), and a
/// claim stating the opposite is refuted (the comparison can fail).
#[test]
fn charmap_faces_on_the_command_line_is_the_claim_file_route() {
    let run = |faces: Option<&str>| {
        let mut a = vec!["charmap", "four-three", "-n", "4", "--levels", "3", "--resolution", "256", "--json"];
        if let Some(f) = faces {
            a.extend(["--faces", f]);
        }
        let out = subdlab(&a);
        assert!(out.status.success(), "{a:?}: {}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let mixed = run(Some("QQTT"));
    let quads = run(None);
    assert_ne!(mixed["ring_facets"], quads["ring_facets"], "--faces QQTT analysed the all-quad ring");
    let dir = tempfile::tempdir().unwrap();
    let verdict = |expect: bool| {
        let file = dir.path().join(format!("mixed-{expect}.toml"));
        std::fs::write(
            &file,
            format!(
                "paper = \"t\"\ntitle = \"t\"\n[[claim]]\nid = \"mixed\"\nlocation = \"-\"\nstatement = \"-\"\n\
                 check = \"characteristic-map\"\nscheme = \"four-three\"\nfaces = [\"QQTT\"]\nlevels = 3\n\
                 resolution = 256\nexpect = {expect}\n"
            ),
        )
        .unwrap();
        let out = subdlab(&["verify", "--claims", file.to_str().unwrap(), "--json"]);
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let claim = v[0]["claims"][0].clone();
        (claim["verdict"].as_str().unwrap().to_string(), claim["computed"].as_str().unwrap().to_string())
    };
    let regular_and_injective = mixed["regular"] == true && mixed["injective"] == true;
    let (holds, computed) = verdict(regular_and_injective);
    assert_eq!(holds, "HOLDS", "{computed}");
    let (refuted, _) = verdict(!regular_and_injective);
    assert_eq!(refuted, "REFUTED");
    // the claim prints the ratio to 12 decimals: the same ring, not only the same verdict
    let printed: f64 = computed
        .split("min Jacobian ratio ")
        .nth(1)
        .and_then(|t| t.split(')').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no ratio in {computed}"));
    let cli = mixed["min_jacobian_ratio"].as_f64().unwrap();
    assert!((printed - cli).abs() < 1e-11, "claim: {computed}; cli: {cli}");
}

/// Analyses that a domain does not have are refused in one line naming the
/// command, the scheme and its domain; a curve has no surface analyses.
#[test]
fn a_curve_scheme_has_no_surface_analyses() {
    for (command, why) in [("charmap", "characteristic map"), ("curvature", "surface curvature")] {
        let e = fails(&[command, "four-point", "-n", "2"]);
        assert_eq!(e.trim().lines().count(), 1, "{e}");
        assert!(e.contains(&format!("`{command}`")) && e.contains("curve scheme") && e.contains("the line Z"), "{e}");
        assert!(e.contains(why), "{e}");
    }
    // the lattice scheme's map is the mesh pipeline's, at valence 4 (its masks on oriented quads)
    let out = subdlab(&["charmap", "khan-mustafa", "-n", "4", "--levels", "2", "--resolution", "64", "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}
