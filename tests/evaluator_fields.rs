//! One expression evaluator, four arithmetics (`numeric::field`): every
//! weight of every scheme file, and a few hundred generated expressions, read
//! alike in floating point, exact rationals, exact cyclotomic numbers and
//! outward-rounded intervals: rational = cyclotomic where both exist, the
//! interval encloses the exact value and the float reading. And the
//! reproducer of a false proof: a file whose kronecker(1e-13-ish) argument
//! floats once called zero is now the same scheme in floats and exactly, and
//! a kronecker that floats cannot decide is refused, not guessed.

use std::path::{Path, PathBuf};

use num_complex::Complex64;
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::numeric::expr::{env_int, Env, Expr};
use subdlab::numeric::{Cyclotomic, EvalError, Interval, ParamValue, Rational, Reading, Weight};
use subdlab::schemes::files::weight_sites;
use subdlab::spectrum::{analyse, Options};

fn q(p: i64, d: i64) -> Rational {
    Rational::new(p.into(), d.into())
}

/// What the four arithmetics said of one expression, checked to agree.
#[derive(Default)]
struct Tally {
    checked: usize,
    /// an exact value, its enclosure and its float reading were compared
    complete: usize,
    undecidable: usize,
}

/// Check the readings of `e` at `env` against one another; `what` names it.
fn check_agreement(e: &Expr, env: &Env, what: &str, tally: &mut Tally) {
    tally.checked += 1;
    let rational = e.evaluate::<Rational>(env);
    let cyclotomic = e.evaluate::<Cyclotomic>(env);
    let float = e.evaluate::<Complex64>(env);
    let interval = e.evaluate::<Interval>(env);
    // exact fields never give up on a decision
    for err in [rational.as_ref().err(), cyclotomic.as_ref().err()].into_iter().flatten() {
        assert!(!matches!(err, EvalError::Undecidable(_)), "{what}: an exact field could not decide: {err:?}");
    }
    if matches!(float, Err(EvalError::Undecidable(_))) {
        tally.undecidable += 1;
    }
    // rational = cyclotomic where both exist; where the rationals have a
    // value the cyclotomic field has the same
    if let Ok(r) = &rational {
        let c = cyclotomic.as_ref().unwrap_or_else(|e| panic!("{what}: rational {r} but cyclotomic {e:?}"));
        assert_eq!(c, &Cyclotomic::from_rational(r), "{what}");
    }
    // an exact zero divisor is no value in any exact field
    if let Err(EvalError::Invalid(_)) = &cyclotomic {
        assert!(rational.is_err(), "{what}: the rationals found a value where the cyclotomic field found none");
    }
    let Ok(c) = &cyclotomic else { return };
    // the interval encloses the exact value: decided exactly for a rational,
    // by overlap with the element's own enclosure (from its coefficients,
    // not from the expression) otherwise
    if let Ok(i) = &interval {
        match c.to_rational() {
            Some(r) => assert!(i.contains_rational(&r), "{what}: {i:?} does not contain {r}"),
            None => {
                let own = Interval::from_cyclotomic(c)
                    .unwrap_or_else(|_| panic!("{what}: an interval reading of a non-real value {c}"));
                assert!(i.overlaps(&own), "{what}: {i:?} misses the exact value's enclosure {own:?}");
            }
        }
    }
    // the float walk is close to the exact value
    let (re, im) = c.to_complex();
    if let Ok(z) = &float {
        let tol = 1e-9 * (1.0 + re.abs() + im.abs());
        assert!((z.re - re).abs() <= tol && (z.im - im).abs() <= tol, "{what}: float {z} vs exact {c}");
    }
    // the reading a scheme file uses is exact, and rounded inside the enclosure
    if c.is_real() {
        let reading = e.reading(env).unwrap_or_else(|err| panic!("{what}: {err}"));
        assert!(!matches!(reading, Reading::Float(_)), "{what}: an exact value read in floats");
        let x = reading.real().unwrap();
        if let Ok(i) = &interval {
            assert!(i.contains(x), "{what}: the float reading {x} lies outside {i:?}");
            if float.is_ok() {
                tally.complete += 1;
            }
        }
    }
}

fn scheme_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("schemes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_scheme_file_reads_alike_in_every_field() {
    let files = scheme_files();
    assert!(files.len() >= 20, "the scheme files: {files:?}");
    let mut tally = Tally::default();
    for path in &files {
        let sites = weight_sites(path, 3..=8).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(!sites.is_empty(), "{}", path.display());
        for s in &sites {
            let what = format!("{} {} at {:?}", path.display(), s.field, s.env);
            check_agreement(&s.expr, &s.env, &what, &mut tally);
            // every weight of every file has an exact, real reading
            let reading = s.expr.reading(&s.env).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert!(!matches!(reading, Reading::Float(_)), "{what}: no exact reading");
            // and its interval reading exists (no file weight is complex)
            assert!(s.expr.evaluate::<Interval>(&s.env).is_ok(), "{what}: no enclosure");
        }
    }
    assert_eq!(tally.undecidable, 0);
    assert!(tally.complete * 2 >= tally.checked, "{} of {} complete", tally.complete, tally.checked);
}

#[test]
fn file_weights_match_known_closed_forms() {
    let file = |name: &str| Path::new(env!("CARGO_MANIFEST_DIR")).join("schemes").join(name);
    let at = |sites: &[subdlab::schemes::files::WeightSite], field: &str, n: i64, j: i64| {
        let s = sites
            .iter()
            .find(|s| s.field == field && s.env["n"].exact == Some(q(n, 1)) && s.env["j"].exact == Some(q(j, 1)))
            .unwrap_or_else(|| panic!("{field} n = {n} j = {j}"));
        s.expr.reading(&s.env).unwrap()
    };
    // Loop: β(3) = 3/16; β(5) = (5/8 − (3/8 + cos(2π/5)/4)²)/5 with
    // cos(2π/5) = (√5 − 1)/4, i.e. (5/8 − ((5 + √5)/16)²)/5 = (130 − 10√5)/1280
    let lp = weight_sites(&file("loop.toml"), 3..=8).unwrap();
    assert_eq!(at(&lp, "vertex.edge", 3, 0), Reading::Rational(q(3, 16)));
    let beta5 = at(&lp, "vertex.edge", 5, 0).real().unwrap();
    let s5 = Interval::point(5.0).sqrt();
    let closed = (Interval::point(130.0) - Interval::point(10.0) * s5) / Interval::point(1280.0);
    assert!(closed.lo - 1e-16 <= beta5 && beta5 <= closed.hi + 1e-16, "{beta5} vs {closed:?}");
    // Doo–Sabin at n = 4: 9/16, 3/16, 1/16, 3/16
    let ds = weight_sites(&file("doo-sabin.toml"), 3..=8).unwrap();
    for (j, w) in [(0, q(9, 16)), (1, q(3, 16)), (2, q(1, 16)), (3, q(3, 16))] {
        assert_eq!(at(&ds, "corner.corner", 4, j), Reading::Rational(w), "j = {j}");
    }
    // Catmull–Clark's vertex rule at n = 5: 1 − 7/20, 3/50, 1/100
    let cc = weight_sites(&file("catmull-clark.toml"), 3..=8).unwrap();
    assert_eq!(at(&cc, "vertex.centre", 5, 0), Reading::Rational(q(13, 20)));
    assert_eq!(at(&cc, "vertex.edge", 5, 0), Reading::Rational(q(3, 50)));
}

/// A small deterministic generator (a linear congruential sequence) of
/// expressions over + − × ÷ ^, cos and sin of rational multiples of π,
/// square roots of rationals, kronecker and sums.
struct Gen(u64, u32);

impl Gen {
    fn next(&mut self, k: u64) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 33) % k
    }
    fn expr(&mut self, depth: u32) -> String {
        if depth == 0 {
            return self.leaf();
        }
        match self.next(10) {
            0..=3 => {
                let op = ["+", "-", "*", "/"][self.next(4) as usize];
                format!("({} {op} {})", self.expr(depth - 1), self.expr(depth - 1))
            }
            4 => format!("({})^{}", self.expr(depth - 1), self.next(5) as i64 - 2),
            5 => format!("kronecker({})", self.zeroish(depth - 1)),
            6 => {
                // a fresh index per sum: nested sums may not rebind one
                self.1 += 1;
                let (m, to) = (format!("m{}", self.1), self.next(4));
                format!("sum({m}, 0, {to}, {} cos(2 pi {m} / n))", self.expr(depth - 1))
            }
            7 => format!("sqrt({})", self.square_or_not()),
            _ => self.leaf(),
        }
    }
    fn leaf(&mut self) -> String {
        match self.next(8) {
            0 => format!("{}/{}", self.next(9) as i64 - 4, self.next(7) + 1),
            1 => "n".into(),
            2 => "j".into(),
            3 => format!("cos({} pi / {})", 2 * self.next(5), self.next(11) + 1),
            4 => format!("sin({} pi / {})", self.next(7), self.next(8) + 1),
            5 => "cos(2 pi j / n)".into(),
            6 => format!("{}", self.next(6)),
            _ => format!("0.{}", self.next(1000)),
        }
    }
    /// An argument for kronecker that is often exactly zero, sometimes
    /// tiny, sometimes neither.
    fn zeroish(&mut self, depth: u32) -> String {
        match self.next(6) {
            // cos 72° + cos 144° = −1/2
            0 => "cos(2 pi / 5) + cos(4 pi / 5) + 1/2".into(),
            1 => format!("j - {}", self.next(3)),
            2 => format!(
                "(cos(2 pi / 5) + cos(4 pi / 5) + 1/2 + {}) / 10^13",
                ["0", "1/7", "cos(2 pi / 7)"][self.next(3) as usize]
            ),
            3 => "sin(pi / 6)^2 - 1/4".into(),
            4 => format!("cos(2 pi / {}) / 10^13", self.next(9) + 3),
            _ => self.expr(depth),
        }
    }
    fn square_or_not(&mut self) -> String {
        let (a, b) = (self.next(7) + 1, self.next(5) + 1);
        match self.next(3) {
            0 => format!("{}/{}", a * a, b * b),
            1 => format!("{a}/{b}"),
            _ => format!("{} + 2 cos(2 pi / 5)", a),
        }
    }
}

#[test]
fn generated_expressions_read_alike_in_every_field() {
    let mut g = Gen(20_240_611, 0);
    let mut tally = Tally::default();
    let mut exprs = Vec::new();
    while exprs.len() < 400 {
        let depth = 1 + g.next(4) as u32;
        let text = g.expr(depth);
        exprs.push((Expr::parse(&text).unwrap_or_else(|e| panic!("{text}: {e}")), text));
    }
    for (k, (e, text)) in exprs.iter().enumerate() {
        let (n, j) = ([3, 5, 7, 8][k % 4], (k / 4 % 3) as i64);
        check_agreement(e, &env_int(&[("n", n), ("j", j)]), &format!("{text} at n = {n}, j = {j}"), &mut tally);
    }
    // every literal is exact, so floats never had to refuse, and most
    // expressions are values in every field
    assert_eq!(tally.undecidable, 0);
    assert!(tally.complete * 2 >= tally.checked, "{} of {} complete", tally.complete, tally.checked);
}

#[test]
fn cos_of_a_fifth_turn_is_its_closed_form_in_every_field() {
    // cos(2π/5) = (√5 − 1)/4, so 4 cos(2π/5) + 1 = √5 and its square is 5
    let e = Expr::parse("(4 cos(2 pi / 5) + 1)^2").unwrap();
    let env = Env::new();
    assert_eq!(e.exact(&env), None, "no rational value of the parts");
    assert_eq!(e.cyclotomic(&env), Some(Cyclotomic::from_rational(&q(5, 1))));
    assert!(e.evaluate::<Interval>(&env).unwrap().contains_rational(&q(5, 1)));
    assert!((e.eval(&env).unwrap().re - 5.0).abs() < 1e-14);
    let c = Expr::parse("cos(2 pi / 5)").unwrap().evaluate::<Interval>(&env).unwrap();
    let closed = (Interval::point(5.0).sqrt() - Interval::point(1.0)) / Interval::point(4.0);
    assert!(c.overlaps(&closed) && c.width() < 1e-15);
}

/// The reproducer, kept once in `tests/data/certify/` (its comment
/// derives what it is exactly).
fn toggle() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/certify/toggle-cc.toml")).unwrap()
}

fn write_file(dir: &tempfile::TempDir, name: &str, text: &str) -> PathBuf {
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn the_toggle_file_is_one_scheme_in_floats_and_exactly() {
    // cos(2π/5)/10^13 ≈ 3.1e-14 is not zero: kronecker of it is 0 in every field
    let k = Expr::parse("kronecker(cos(2 pi / 5) / 10^13)").unwrap();
    let env = Env::new();
    assert_eq!(k.cyclotomic(&env), Some(Cyclotomic::from_rational(&q(0, 1))));
    assert_eq!(k.eval(&env).unwrap(), Complex64::new(0.0, 0.0));
    assert!(k.evaluate::<Interval>(&env).unwrap().is_exactly(&q(0, 1)));

    let dir = tempfile::tempdir().unwrap();
    let path = write_file(&dir, "toggle-cc.toml", &toggle());
    let sites = weight_sites(&path, 3..=8).unwrap();
    let mut tally = Tally::default();
    for s in &sites {
        let what = format!("toggle {} at {:?}", s.field, s.env);
        check_agreement(&s.expr, &s.env, &what, &mut tally);
        // the float value the scheme uses is the exact value rounded
        let reading = s.expr.reading(&s.env).unwrap();
        let exact = match &reading {
            Reading::Rational(r) => Interval::rational(r),
            Reading::Cyclotomic(c, _) => Interval::from_cyclotomic(c).unwrap(),
            Reading::Float(z) => panic!("{what}: read in floats ({z})"),
        };
        assert!(exact.contains(reading.real().unwrap()), "{what}");
    }
    // the folded design's centre weight at n = 3 (cos(2π/3) = −1/2, so
    // 2 + 2cos = 1): with c = (31/32 + 11/20 − 1/4) − 4·(31/32)·(11/20) =
    // 203/160 − 341/160 = −69/80, the weight is 1/2 − 2c = 89/40
    let centre3 =
        sites.iter().find(|s| s.field == "edge-extraordinary.centre" && s.env["n"].exact == Some(q(3, 1))).unwrap();
    assert_eq!(centre3.expr.reading(&centre3.env).unwrap(), Reading::Rational(q(89, 40)));

    // the float analysis sees the folded design: 31/32 and 11/20 in block 1
    let scheme = subdlab::schemes::user::load(&path, &[]).unwrap();
    for n in [3, 5, 7] {
        let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
        let a = analyse(scheme.as_ref(), &Configuration::regular(scheme.as_ref(), n).unwrap(), &opts).unwrap();
        for want in [31.0 / 32.0, 11.0 / 20.0] {
            assert!(
                a.spectrum
                    .eigenvalues
                    .iter()
                    .any(|e| e.blocks.contains(&1) && (e.re - want).abs() < 1e-9 && e.im.abs() < 1e-9),
                "n = {n}: no eigenvalue {want} in block 1: {:?}",
                a.spectrum.eigenvalues.iter().map(|e| (e.re, e.im, e.blocks.clone())).collect::<Vec<_>>()
            );
        }
        // Catmull–Clark's subdominant eigenvalue at n = 5 is near 0.55 too;
        // 31/32 is what Catmull–Clark never has
        assert!(a.spectrum.eigenvalues.iter().any(|e| (e.re - 0.96875).abs() < 1e-9));
    }
}

#[test]
fn kronecker_of_a_float_only_value_is_refused_in_floats() {
    // 1e-13 as a float-only parameter: no exact reading to decide with
    let mut env = Env::new();
    env.insert("eps".into(), ParamValue::from_f64(1e-13));
    let e = Expr::parse("kronecker(eps)").unwrap();
    let err = e.eval(&env).unwrap_err().to_string();
    assert!(err.contains("cannot be decided in floating point"), "{err}");
    assert!(e.reading(&env).unwrap_err().to_string().contains("cannot be decided"));
    // the same number written exactly is decided: 1e-13 is not zero
    assert_eq!(Expr::parse("kronecker(1e-13)").unwrap().eval(&Env::new()).unwrap().re, 0.0);

    // a scheme file whose parameter has no exact value (an exponent past the
    // exact decimals) and whose weight asks kronecker of it: refused at load
    let dir = tempfile::tempdir().unwrap();
    let text = toggle()
        .replace("name = \"toggle-cc\"", "name = \"float-kronecker\"")
        .replace("kronecker(cos(2 pi / 5) / 10^13)", "kronecker(eps)")
        + "[params.eps]\ndefault = \"1e-70\"\n";
    let path = write_file(&dir, "float-kronecker.toml", &text);
    let err = subdlab::schemes::user::load(&path, &[]).err().expect("refused").to_string();
    assert!(err.contains("cannot be decided in floating point") && err.contains("edge-extraordinary"), "{err}");
    // a float-only parameter far from zero is decided
    let text = text.replace("default = \"1e-70\"", "default = \"1e70\"");
    let path = write_file(&dir, "float-kronecker-far.toml", &text);
    assert!(subdlab::schemes::user::load(&path, &[]).is_ok());
}

#[test]
fn weight_types_take_one_reading() {
    // the scheme's weights as f64, rational, cyclotomic and interval agree
    // with the reading: Loop at n = 5 through the stencil of its centre
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("schemes/loop.toml");
    let sites = weight_sites(&path, 5..=5).unwrap();
    let s = sites.iter().find(|s| s.field == "vertex.centre").unwrap();
    let Reading::Cyclotomic(c, _) = s.expr.reading(&s.env).unwrap() else { panic!("Loop's α(5) is irrational") };
    // α(5) = 3/8 + (3/8 + cos(2π/5)/4)² = 3/8 + ((5 + √5)/16)²
    let s5 = Interval::point(5.0).sqrt();
    let t = (Interval::point(5.0) + s5) / Interval::point(16.0);
    assert!(Interval::from_cyclotomic(&c).unwrap().overlaps(&(Interval::ratio(3, 8) + t.square())));
    assert!(<Rational as Weight>::from_cyclotomic(&c).is_err());
}
