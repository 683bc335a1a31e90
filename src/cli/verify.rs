//! `subdlab verify`: evaluate claim files and report HOLDS / REFUTED /
//! INCONCLUSIVE with stated against computed values.

use std::path::{Path, PathBuf};

use crate::claims::{self, ClaimFile, Outcome, Verdict};
use crate::error::Error;
use crate::io::{print_json, write_atomic};

pub struct VerifyOptions {
    pub json: bool,
    pub junit: Option<PathBuf>,
    /// a claim passes when its verdict is the recorded `expected` one
    pub check_expected: bool,
    /// write every certified claim's certificate documents here
    pub certificates: Option<PathBuf>,
    /// after the table, the K claims that took longest (text output only)
    pub slowest: Option<usize>,
}

/// Largest claim file read (the read stops there: devices and pipes have no
/// length to check beforehand).
pub const MAX_CLAIM_FILE: u64 = 16 * 1024 * 1024;

/// Reads at most `limit` bytes of a text file; more is an error.
pub(super) fn read_capped(path: &Path, limit: u64, what: &str) -> Result<String, Error> {
    use std::io::Read;
    let f = std::fs::File::open(path).map_err(|e| Error::File(format!("{}: {e}", path.display())))?;
    let mut bytes = Vec::new();
    f.take(limit + 1).read_to_end(&mut bytes).map_err(|e| Error::File(format!("{}: {e}", path.display())))?;
    if bytes.len() as u64 > limit {
        return Err(Error::File(format!("{}: {what} larger than {} MiB", path.display(), limit >> 20)));
    }
    crate::io::decode_text(bytes).map_err(|_| Error::File(format!("{}: not UTF-8 text", path.display())))
}

/// A file that could not be read or parsed: one ERROR outcome standing for it,
/// so the other files are still evaluated and the JUnit report is complete.
fn unreadable(path: &Path, message: String) -> (ClaimFile, Vec<Outcome>) {
    let name = path.display().to_string();
    let file = ClaimFile {
        paper: name.clone(),
        title: "(unreadable claim file)".into(),
        citation: None,
        figures: vec![],
        sweeps: vec![],
        claims: vec![],
    };
    let outcome = Outcome {
        id: "file".into(),
        paper: name,
        location: String::new(),
        statement: "the claim file can be read".into(),
        convention: None,
        verdict: Verdict::Error,
        expected: None,
        by_construction: None,
        stated: String::new(),
        computed: String::new(),
        detail: message,
        seconds: 0.0,
    };
    (file, vec![outcome])
}

/// Evaluates the claims and reports them; Ok holds the exit status (0 when
/// every claim passes, 1 when one is REFUTED or INCONCLUSIVE, or with
/// `check_expected` differs from its recorded verdict); a malformed claim or
/// an unreadable file is an error (exit 2) after everything was reported.
pub fn run(paper: Option<String>, user: &[PathBuf], opts: &VerifyOptions) -> Result<i32, Error> {
    let builtin = user.is_empty();
    let mut results: Vec<(ClaimFile, Vec<Outcome>)> = Vec::new();
    let files: Vec<ClaimFile> = if builtin {
        let all = claims::builtin_files()?;
        match &paper {
            None => all,
            Some(p) => {
                let known: Vec<String> = all.iter().map(|f| f.paper.clone()).collect();
                let chosen: Vec<ClaimFile> = all.into_iter().filter(|f| &f.paper == p).collect();
                if chosen.is_empty() {
                    return Err(Error::Input(format!("unknown paper '{p}'; built-in papers: {}", known.join(", "))));
                }
                chosen
            }
        }
    } else {
        if paper.is_some() {
            return Err(Error::Input(
                "--paper selects from the built-in registry; it does not combine with --claims".into(),
            ));
        }
        let mut ok = Vec::new();
        for p in user {
            let parsed = read_capped(p, MAX_CLAIM_FILE, "claim file")
                .and_then(|text| claims::parse_file(&p.display().to_string(), &text));
            match parsed {
                Ok(f) => ok.push(f),
                Err(e) => results.push(unreadable(p, e.to_string())),
            }
        }
        ok
    };
    if let Some(dir) = &opts.certificates {
        std::fs::create_dir_all(dir).map_err(|e| Error::File(format!("{}: {e}", dir.display())))?;
    }
    let evaluation = claims::EvaluationOptions { certificates: opts.certificates.clone() };
    let outcomes = claims::evaluate_all_with(&files, &evaluation)?;
    results.extend(files.into_iter().zip(outcomes));
    let judge = Judge { check_expected: opts.check_expected, builtin };
    if let Some(path) = &opts.junit {
        write_atomic(path, junit_xml(&results, &judge).as_bytes())?;
    }
    if opts.json {
        #[derive(serde::Serialize)]
        struct Paper<'a> {
            paper: &'a str,
            title: &'a str,
            summary: Summary,
            claims: &'a [Outcome],
        }
        let out: Vec<Paper> = results
            .iter()
            .map(|(f, o)| Paper { paper: &f.paper, title: &f.title, summary: summary(o), claims: o })
            .collect();
        print_json(&out)?;
    } else {
        let mut text = table(&results, &judge);
        if let Some(k) = opts.slowest {
            text += &slowest(&results, k);
        }
        crate::io::out(&text)?;
    }
    let all: Vec<&Outcome> = results.iter().flat_map(|(_, o)| o).collect();
    let errors: Vec<&&Outcome> = all.iter().filter(|o| o.verdict == Verdict::Error).collect();
    if let Some(first) = errors.first() {
        return Err(Error::Claim(format!(
            "{} claim(s) or file(s) could not be read; first: {}",
            errors.len(),
            first.detail
        )));
    }
    let failed = all.iter().filter(|o| !judge.passes(o)).count();
    if failed > 0 {
        if opts.check_expected {
            eprintln!("verify: {failed} claim(s) differ from their recorded verdict");
        } else {
            eprintln!("verify: {failed} claim(s) did not hold");
        }
        return Ok(1);
    }
    Ok(0)
}

/// Whether a claim passes: HOLDS, or with `check_expected` the verdict its
/// file records (HOLDS when none).
struct Judge {
    check_expected: bool,
    builtin: bool,
}

impl Judge {
    fn required(&self, o: &Outcome) -> Verdict {
        if self.check_expected {
            o.expected.unwrap_or(Verdict::Holds)
        } else {
            Verdict::Holds
        }
    }
    fn passes(&self, o: &Outcome) -> bool {
        o.verdict != Verdict::Error && o.verdict == self.required(o)
    }
}

#[derive(serde::Serialize, Default, Clone, Copy)]
pub struct Summary {
    pub holds: usize,
    pub refuted: usize,
    pub inconclusive: usize,
    /// malformed claims and unreadable files (left out of the JSON when 0,
    /// so existing summaries keep their exact shape)
    #[serde(skip_serializing_if = "is_zero")]
    pub error: usize,
    /// verdicts (of any kind) marked `by construction`: about subdlab's
    /// construction from the statement, so no independent confirmation
    /// (left out of the JSON when 0)
    #[serde(skip_serializing_if = "is_zero")]
    pub by_construction: usize,
}

fn is_zero(x: &usize) -> bool {
    *x == 0
}

pub fn summary(o: &[Outcome]) -> Summary {
    let mut s = Summary::default();
    for x in o {
        match x.verdict {
            Verdict::Holds => s.holds += 1,
            Verdict::Refuted => s.refuted += 1,
            Verdict::Inconclusive => s.inconclusive += 1,
            Verdict::Error => s.error += 1,
        }
        s.by_construction += usize::from(x.by_construction.is_some());
    }
    s
}

fn counts(s: &Summary) -> String {
    let mut t = format!("{} HOLDS, {} REFUTED, {} INCONCLUSIVE", s.holds, s.refuted, s.inconclusive);
    if s.error > 0 {
        t += &format!(", {} ERROR", s.error);
    }
    if s.by_construction > 0 {
        t += &format!("; {} of them by construction", s.by_construction);
    }
    t
}

/// The `k` claims that took longest, slowest first, with their share of the
/// summed claim time: where the main job's time goes (wall-clock per claim;
/// `verify --json` gives every claim's `seconds`).
fn slowest(results: &[(ClaimFile, Vec<Outcome>)], k: usize) -> String {
    let mut all: Vec<&Outcome> = results.iter().flat_map(|(_, o)| o).collect();
    let total: f64 = all.iter().map(|o| o.seconds).sum();
    all.sort_by(|a, b| b.seconds.total_cmp(&a.seconds).then_with(|| a.id.cmp(&b.id)));
    let mut out = format!(
        "\nslowest {} of {} claims (wall-clock seconds; all claims: {total:.2} s):\n",
        k.min(all.len()),
        all.len()
    );
    for o in all.iter().take(k) {
        let share = if total > 0.0 { 100.0 * o.seconds / total } else { 0.0 };
        out += &format!("  {:>8.3} s  {:>5.1} %  {}\n", o.seconds, share, crate::io::printable(&o.id));
    }
    out
}

fn table(results: &[(ClaimFile, Vec<Outcome>)], judge: &Judge) -> String {
    use crate::io::printable;
    let mut out = String::new();
    let mut total = Summary::default();
    let who = if judge.builtin { "registry" } else { "file" };
    let mut differ = 0;
    for (f, outcomes) in results {
        let s = summary(outcomes);
        out += &format!(
            "\n== {} — {} ({} claims: {})\n",
            printable(&f.paper),
            printable(&f.title),
            outcomes.len(),
            counts(&s)
        );
        for o in outcomes {
            let changed = match o.expected {
                Some(e) if e != o.verdict => format!("  ({who} expects {e})"),
                _ => String::new(),
            };
            if judge.check_expected && !judge.passes(o) {
                differ += 1;
            }
            out +=
                &format!("  {:<12} {:<34} {}{changed}\n", o.shown_verdict(), printable(&o.id), printable(&o.location));
            if let Some(note) = &o.by_construction {
                out += &format!("               by construction: {}\n", printable(note));
            }
            if o.verdict != Verdict::Holds {
                if !o.statement.is_empty() {
                    out += &format!("               statement: {}\n", printable(&o.statement));
                }
                if !o.stated.is_empty() {
                    out += &format!("               stated:    {}\n", printable(&o.stated));
                }
                if !o.computed.is_empty() {
                    out += &format!("               computed:  {}\n", printable(&o.computed));
                }
                out += &format!("               {}\n", printable(&o.detail));
            }
        }
        total.holds += s.holds;
        total.refuted += s.refuted;
        total.inconclusive += s.inconclusive;
        total.error += s.error;
        total.by_construction += s.by_construction;
    }
    let n = total.holds + total.refuted + total.inconclusive + total.error;
    out += &format!("\n{n} claims: {}\n", counts(&total));
    if judge.check_expected {
        out += &if differ == 0 {
            format!("every verdict is the one its {who} records\n")
        } else {
            format!("{differ} verdict(s) differ from the ones their {who} records\n")
        };
    }
    out
}

/// Text for XML 1.0: markup characters escaped, and the control characters
/// XML cannot carry at all (every one below U+0020 but tab, newline and
/// carriage return) written as visible escapes.
fn xml_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out += "&amp;",
            '<' => out += "&lt;",
            '>' => out += "&gt;",
            '"' => out += "&quot;",
            '\t' | '\n' | '\r' => out.push(c),
            c if (c as u32) < 0x20 || c == '\u{fffe}' || c == '\u{ffff}' => out += &format!("\\u{{{:x}}}", c as u32),
            c => out.push(c),
        }
    }
    out
}

fn junit_xml(results: &[(ClaimFile, Vec<Outcome>)], judge: &Judge) -> String {
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"subdlab verify\">\n");
    for (f, outcomes) in results {
        let failing: Vec<&Outcome> = outcomes.iter().filter(|o| !judge.passes(o)).collect();
        // ERROR and INCONCLUSIVE are <error>s, a wrong verdict a <failure>
        let errors = failing.iter().filter(|o| matches!(o.verdict, Verdict::Error | Verdict::Inconclusive)).count();
        let failures = failing.len() - errors;
        x += &format!(
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\">\n",
            xml_escape(&f.paper),
            outcomes.len(),
        );
        x += &format!(
            "    <properties><property name=\"subdlab_version\" value=\"{}\"/></properties>\n",
            xml_escape(&crate::io::version_line())
        );
        for o in outcomes {
            x += &format!("    <testcase classname=\"{}\" name=\"{}\"", xml_escape(&f.paper), xml_escape(&o.id));
            let mut body = format!("{}\nstated: {}\ncomputed: {}\n{}", o.statement, o.stated, o.computed, o.detail);
            if let Some(note) = &o.by_construction {
                body += &format!("\nby construction: {note}");
            }
            let required = judge.required(o);
            if o.verdict == Verdict::Error {
                x += &format!(">\n      <error message=\"ERROR\">{}</error>\n    </testcase>\n", xml_escape(&body));
            } else if judge.passes(o) && o.verdict == Verdict::Holds && o.by_construction.is_none() {
                x += "/>\n";
            } else if judge.passes(o) {
                // an expected refutation (or undecided claim, or a verdict by
                // construction) passes, with its evidence
                x += &format!(
                    ">\n      <system-out>{} as recorded\n{}</system-out>\n    </testcase>\n",
                    o.shown_verdict(),
                    xml_escape(&body)
                );
            } else {
                let message = if required == Verdict::Holds {
                    o.verdict.to_string()
                } else {
                    format!("{} (expected {required})", o.verdict)
                };
                let tag = if o.verdict == Verdict::Inconclusive { "error" } else { "failure" };
                x += &format!(">\n      <{tag} message=\"{message}\">{}</{tag}>\n    </testcase>\n", xml_escape(&body));
            }
        }
        x += "  </testsuite>\n";
    }
    x += "</testsuites>\n";
    x
}
