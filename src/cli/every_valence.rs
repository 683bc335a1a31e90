//! `subdlab spectrum SCHEME --certify --valences A..[B]`: the spectral C¹
//! conditions at every valence of a range, or at every valence from A on
//! (`every_valence`). Its own argument parser: the single-valence
//! `spectrum` requires `-n`, this form takes a range instead, and the main
//! parser sends a `spectrum` command line with `--valences` here.

use std::ffi::OsString;

use clap::Parser;

use crate::certify::Verdict;
use crate::error::Error;
use crate::every_valence::{run, Report, Request};
use crate::io::print_json;

#[derive(Parser, Debug)]
#[command(
    name = "subdlab spectrum",
    about = "Spectral C¹ conditions at every valence of a range (A..B) or from A on (A..)",
    after_help = "Exit status: 0 PROVED; 1 DISPROVED or NOT PROVED; 2 an error. Spectral conditions only (the \
                  characteristic map is not checked)."
)]
pub struct EveryValenceArgs {
    /// scheme name (see `subdlab schemes`) or a scheme file (.toml)
    pub scheme: String,
    /// A..B (each valence) or A.. (every valence from A on)
    #[arg(long)]
    pub valences: String,
    /// required: the verdict is a proof (interval certificates, exact parametric part)
    #[arg(long)]
    pub certify: bool,
    /// the parameters (and faces) as every analysis command takes them
    #[command(flatten)]
    pub setup: super::args::SchemeSetup,
    /// refused with a reason: the range is of interior vertices
    #[arg(long)]
    pub tag: Option<String>,
    /// machine-readable JSON output
    #[arg(long)]
    pub json: bool,
}

/// Whether this command line is `spectrum ... --valences ...`.
pub fn wants(argv: &[OsString]) -> bool {
    argv.get(1).is_some_and(|a| a == "spectrum")
        && argv[2..].iter().any(|a| a.to_str().is_some_and(|s| s == "--valences" || s.starts_with("--valences=")))
}

/// Parses A..B or A.. .
pub fn parse_range(text: &str) -> Result<(usize, Option<usize>), Error> {
    let bad = || Error::Input(format!("--valences '{text}': expected A..B or A.. (e.g. 3..20, 3..)"));
    let (a, b) = text.trim().split_once("..").ok_or_else(bad)?;
    let a: usize = a.trim().parse().map_err(|_| bad())?;
    let b = b.trim();
    let b = if b.is_empty() { None } else { Some(b.parse::<usize>().map_err(|_| bad())?) };
    Ok((a, b))
}

/// Runs the command from the process's arguments (argv[1] is "spectrum");
/// the exit status.
pub fn main(argv: &[OsString]) -> Result<i32, clap::Error> {
    let mut args = vec![OsString::from("subdlab spectrum")];
    args.extend(argv[2..].iter().cloned());
    let a = EveryValenceArgs::try_parse_from(args)?;
    Ok(match execute(&a) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {}", crate::error::shorten_echoes(&crate::io::printable(&e.to_string())));
            2
        }
    })
}

pub fn execute(a: &EveryValenceArgs) -> Result<i32, Error> {
    if !a.certify {
        return Err(Error::Input(
            "--valences proves the conditions at every valence of the range: give --certify too (for observed \
             spectra over valences use `subdlab sweep SCHEME --valences A..B`)"
                .into(),
        ));
    }
    // one face sequence fixes one valence, and a tagged vertex has no
    // Fourier blocks: neither has a meaning over a range of valences
    if a.setup.faces.is_some() {
        return Err(Error::Input(
            "--faces with --valences: a face sequence fixes one valence; prove one configuration with              `subdlab spectrum SCHEME -n N --faces ... --certify`"
                .into(),
        ));
    }
    if let Some(tag) = &a.tag {
        return Err(Error::Input(format!(
            "--tag {tag} with --valences: the every-valence proof is for interior vertices (Fourier blocks);              sweep tagged configurations with `subdlab sweep SCHEME --tag {tag} --sectors A..B`"
        )));
    }
    let (from, to) = parse_range(&a.valences)?;
    let params = super::commands::parse_params(&a.setup.params)?;
    let report = run(&Request { scheme: a.scheme.clone(), params, from, to })?;
    if a.json {
        print_json(&report)?;
    } else {
        crate::io::out(&table(&report))?;
    }
    Ok(match report.verdict {
        Verdict::Proved => 0,
        _ => 1,
    })
}

/// The report as text.
pub fn table(r: &Report) -> String {
    let mut out = format!(
        "scheme {}  valences {}\nspectral C1 conditions at every valence: {}\n  evidence: {}\n  scope: {}\n",
        r.scheme,
        r.valences,
        r.verdict.display(),
        r.evidence,
        r.scope
    );
    if let Some(p) = &r.parametric {
        let part = match r.threshold {
            Some(n) => format!("n ≥ {n}"),
            None => "not established".into(),
        };
        out += &format!("  parametric part ({part}): {}, {:.2} s\n", p.verdict.display(), p.seconds);
        out += &format!("    evidence: {}\n    rows: {}\n", p.evidence, p.rows);
        if let Some(b) = &p.blocks {
            out += &format!(
                "    blocks k ≠ 0: P(x, c), c = cos(2πk/n), of degree {} in x and {} in c; {} candidate(s) in [−1, 1] {}; \
                 {} piece(s): every root real, of modulus ≤ μ(c), μ strictly increasing, simple and strictly \
                 dominant on [{}, 1) ∋ cos(2π/n); λ1 ≥ μ(q_N) ∈ {}; λ1 < μ(1) ∈ {} ≤ 1\n",
                b.degree_x,
                b.degree_c,
                b.candidates.len(),
                if b.candidates.is_empty() { String::new() } else { format!("[{}]", b.candidates.join(", ")) },
                b.pieces,
                b.q_threshold,
                b.lambda1_lower,
                b.lambda1_limit
            );
        }
        if let Some(b) = &p.block0 {
            out += &format!("    block 0: eigenvalues other than 1 real and of modulus below λ1 for {}\n", b.range);
        }
        if let Some(f) = &p.special {
            out += &format!(
                "    centre face's symbol σ(k) = generic value + e_k(c) at blocks |k| ≤ {}: {}\n    block 1: P(x, c) + \
                 e_1(c)(P⁺ − P)(x, c), P of degree {} in x and {} in c; every root real, the top one λ1 simple, \
                 strictly dominant, in (0, 1) on [q_N, 1) ∋ cos(2π/n); {}\n",
                f.frequencies, f.symbol, f.degree_x, f.degree_c, f.lambda1
            );
            for line in &f.blocks {
                out += &format!("    {line}\n");
            }
            out += &format!("    {}\n", f.generic_bound);
        }
    }
    let proved = r.per_valence.iter().filter(|a| a.verdict == Verdict::Proved && !a.conditional).count();
    match (r.per_valence.first(), r.per_valence.last()) {
        (Some(f), Some(l)) => {
            out += &format!(
                "  per-valence part ({}..{}): {} interval certificate(s), {} PROVED, {:.2} s\n",
                f.valence,
                l.valence,
                r.per_valence.len(),
                proved,
                r.per_valence_seconds
            );
            for a in r.per_valence.iter().filter(|a| a.verdict != Verdict::Proved || a.conditional) {
                out += &format!(
                    "    n = {}: {}{}\n",
                    a.valence,
                    a.verdict.display(),
                    if a.conditional { " (conditional)" } else { "" }
                );
            }
        }
        _ => out += "  per-valence part: none (the parametric part covers the whole range)\n",
    }
    out
}
