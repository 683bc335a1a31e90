//! `subdlab verify`: evaluate claim files and report HOLDS / REFUTED /
//! INCONCLUSIVE with stated against computed values.

use std::path::Path;

use crate::claims::{self, ClaimFile, Outcome, Verdict};
use crate::io::{print_json, write_atomic};

pub fn run(paper: Option<String>, user: &[std::path::PathBuf], json: bool, junit: Option<&Path>) -> Result<(), String> {
    let files: Vec<ClaimFile> = if user.is_empty() {
        let all = claims::builtin_files()?;
        match &paper {
            None => all,
            Some(p) => {
                let known: Vec<String> = all.iter().map(|f| f.paper.clone()).collect();
                let chosen: Vec<ClaimFile> = all.into_iter().filter(|f| &f.paper == p).collect();
                if chosen.is_empty() {
                    return Err(format!("unknown paper '{p}'; built-in papers: {}", known.join(", ")));
                }
                chosen
            }
        }
    } else {
        if paper.is_some() {
            return Err("--paper selects from the built-in registry; it does not combine with --claims".into());
        }
        user.iter()
            .map(|p| {
                let meta = std::fs::metadata(p).map_err(|e| format!("{}: {e}", p.display()))?;
                if meta.len() > 16 * 1024 * 1024 {
                    return Err(format!("{}: claim file larger than 16 MiB", p.display()));
                }
                let text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
                claims::parse_file(&p.display().to_string(), &text)
            })
            .collect::<Result<_, _>>()?
    };
    let outcomes = claims::evaluate_all(&files)?;
    let results: Vec<(ClaimFile, Vec<Outcome>)> = files.into_iter().zip(outcomes).collect();
    if let Some(path) = junit {
        write_atomic(path, junit_xml(&results).as_bytes())?;
    }
    if json {
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
        print!("{}", table(&results));
    }
    let failed: usize = results.iter().flat_map(|(_, o)| o).filter(|o| o.verdict != Verdict::Holds).count();
    if !user.is_empty() && failed > 0 {
        return Err(format!("{failed} claim(s) did not hold"));
    }
    Ok(())
}

#[derive(serde::Serialize, Default, Clone, Copy)]
pub struct Summary {
    pub holds: usize,
    pub refuted: usize,
    pub inconclusive: usize,
}

pub fn summary(o: &[Outcome]) -> Summary {
    let mut s = Summary::default();
    for x in o {
        match x.verdict {
            Verdict::Holds => s.holds += 1,
            Verdict::Refuted => s.refuted += 1,
            Verdict::Inconclusive => s.inconclusive += 1,
        }
    }
    s
}

fn table(results: &[(ClaimFile, Vec<Outcome>)]) -> String {
    let mut out = String::new();
    let mut total = Summary::default();
    for (f, outcomes) in results {
        let s = summary(outcomes);
        out += &format!(
            "\n== {} — {} ({} claims: {} HOLDS, {} REFUTED, {} INCONCLUSIVE)\n",
            f.paper,
            f.title,
            outcomes.len(),
            s.holds,
            s.refuted,
            s.inconclusive
        );
        for o in outcomes {
            let changed = match o.expected {
                Some(e) if e != o.verdict => format!("  (registry expects {e})"),
                _ => String::new(),
            };
            out += &format!("  {:<12} {:<34} {}{changed}\n", o.verdict.to_string(), o.id, o.location);
            if o.verdict != Verdict::Holds {
                out += &format!("               statement: {}\n", o.statement);
                if !o.stated.is_empty() {
                    out += &format!("               stated:    {}\n", o.stated);
                }
                if !o.computed.is_empty() {
                    out += &format!("               computed:  {}\n", o.computed);
                }
                out += &format!("               {}\n", o.detail);
            }
        }
        total.holds += s.holds;
        total.refuted += s.refuted;
        total.inconclusive += s.inconclusive;
    }
    out += &format!(
        "\n{} claims: {} HOLDS, {} REFUTED, {} INCONCLUSIVE\n",
        total.holds + total.refuted + total.inconclusive,
        total.holds,
        total.refuted,
        total.inconclusive
    );
    out
}

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

fn junit_xml(results: &[(ClaimFile, Vec<Outcome>)]) -> String {
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"subdlab verify\">\n");
    for (f, outcomes) in results {
        let s = summary(outcomes);
        x += &format!(
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\">\n",
            xml_escape(&f.paper),
            outcomes.len(),
            s.refuted,
            s.inconclusive
        );
        for o in outcomes {
            x += &format!("    <testcase classname=\"{}\" name=\"{}\"", xml_escape(&f.paper), xml_escape(&o.id));
            let body = format!("{}\nstated: {}\ncomputed: {}\n{}", o.statement, o.stated, o.computed, o.detail);
            match o.verdict {
                Verdict::Holds => x += "/>\n",
                Verdict::Refuted => {
                    x += &format!(
                        ">\n      <failure message=\"REFUTED\">{}</failure>\n    </testcase>\n",
                        xml_escape(&body)
                    )
                }
                Verdict::Inconclusive => {
                    x += &format!(
                        ">\n      <error message=\"INCONCLUSIVE\">{}</error>\n    </testcase>\n",
                        xml_escape(&body)
                    )
                }
            }
        }
        x += "  </testsuite>\n";
    }
    x += "</testsuites>\n";
    x
}
