//! The analysis commands on the mesh pipeline (the front door's mesh route):
//! `spectrum` (and `--certify`), `stencils`, `matrix`, `charmap`, `curvature`.

use crate::cli::args::AnalysisArgs;
use crate::cli::command_line::Command;
use crate::cli::commands::{
    certified_status, configuration, kind_name, matrix_format, out_text, spectrum_table, stencil_table,
};
use crate::error::Error;
use crate::io::{print_json, write_atomic};
use crate::matrix::export::{to_matrix_market, MatrixJson};
use crate::neighbourhood::NeighbourhoodKind;
use crate::schemes::Scheme;
use crate::spectrum::stencils::stencils;
use crate::spectrum::{analyse, Analysis, Method, Options, Spectrum};

/// An analysis command on the mesh pipeline, with the scheme the front door
/// resolved (a mesh scheme, or a lattice scheme on oriented quad meshes).
/// Ok holds the exit status.
pub(super) fn mesh_analysis(cmd: &Command, scheme: Box<dyn Scheme>) -> Result<i32, Error> {
    match cmd {
        Command::Spectrum { common: a, certify: true, certificate } => {
            certified_spectrum(a, scheme, certificate.as_deref())
        }
        Command::Charmap(a) => super::charmap_commands::charmap(a, scheme),
        Command::Curvature(a) => super::curvature::run(a, scheme).map(|()| 0),
        Command::Spectrum { common: a, certify: false, .. } => {
            let (_, analysis) = run_analysis(a, scheme)?;
            // at a tagged vertex: the spectrum per block of the reflection
            // that keeps the sharp rays, where the rules commute with it
            let reflection = match analysis.discovered.config.tagging {
                Some(_) => crate::spectrum::reflection::reflection_spectra(
                    &analysis.discovered.config,
                    &analysis.matrix.labels,
                    &analysis.matrix.to_dense_f64(),
                )?,
                None => None,
            };
            if a.json {
                #[derive(serde::Serialize)]
                struct WithReflection<'a> {
                    #[serde(flatten)]
                    spectrum: &'a crate::spectrum::Spectrum,
                    #[serde(skip_serializing_if = "Option::is_none")]
                    reflection: Option<&'a crate::spectrum::reflection::ReflectionSpectra>,
                }
                print_json(&WithReflection { spectrum: &analysis.spectrum, reflection: reflection.as_ref() })?;
            } else {
                let mut text = spectrum_table(&analysis.spectrum);
                if let Some(r) = &reflection {
                    text += &reflection_table(r, analysis.discovered.config.tagging);
                }
                out_text(&text)?;
            }
            Ok(0)
        }
        Command::Stencils(a) => {
            let (_, analysis) = run_analysis(a, scheme)?;
            let st = stencils(&analysis.spectrum)?;
            if a.json {
                print_json(&st)?;
            } else {
                out_text(&stencil_table(&st))?;
            }
            Ok(0)
        }
        Command::Matrix { common, format, output } => {
            let format = matrix_format(format.as_deref(), common.json)?;
            let (scheme, analysis) = run_analysis(common, scheme)?;
            let text = match format {
                "mtx" => to_matrix_market(
                    &analysis.matrix,
                    &format!(
                        "subdlab local subdivision matrix: scheme {} valence {} faces {} neighbourhood {}",
                        scheme.name(),
                        common.config.valence,
                        analysis.spectrum.faces,
                        kind_name(analysis.spectrum.neighbourhood)
                    ),
                ),
                "json" => {
                    let m = &analysis.matrix;
                    let j = MatrixJson {
                        scheme: scheme.name(),
                        valence: common.config.valence,
                        neighbourhood: m.kind,
                        size: m.size(),
                        labels: m.labels.iter().map(|l| l.name.as_str()).collect(),
                        vertices: &m.labels,
                        matrix: m.to_dense_f64(),
                        exact: analysis.exact_matrix.as_ref().map(|q| {
                            (0..q.size()).map(|i| (0..q.size()).map(|j| q.get(i, j).to_string()).collect()).collect()
                        }),
                    };
                    crate::io::json_text(&j)? + "\n"
                }
                other => return Err(Error::Input(format!("unknown matrix format '{other}'; use mtx or json"))),
            };
            match output {
                Some(p) => write_atomic(p, text.as_bytes())?,
                None => out_text(&text)?,
            }
            Ok(0)
        }
        _ => Err(Error::Input("not an analysis command".into())),
    }
}

fn run_analysis(a: &AnalysisArgs, scheme: Box<dyn Scheme>) -> Result<(Box<dyn Scheme>, Analysis), Error> {
    let config = configuration(scheme.as_ref(), &a.config)?;
    let neighbourhood: NeighbourhoodKind = a.neighbourhood.parse()?;
    let method = match a.method.as_deref() {
        None => None,
        Some("dft") => Some(Method::Dft),
        Some("full") => Some(Method::Full),
        Some(m) => return Err(Error::Input(format!("unknown method '{m}'; use dft or full"))),
    };
    if method == Some(Method::Dft) && config.symmetry_period() >= config.valence() {
        return Err(Error::Input("this configuration has no rotation symmetry; use --method full".into()));
    }
    let opts = Options { neighbourhood, method, exact: !a.no_exact };
    let analysis = analyse(scheme.as_ref(), &config, &opts)?;
    Ok((scheme, analysis))
}

/// `spectrum --certify`: the floating-point spectrum and, beside it, the
/// certificate (`certify::spectrum`) from the same discovery and labels.
/// `spectrum --certify`: the table and the certificate; Ok holds the exit
/// status ([`certified_status`]).
fn certified_spectrum(
    a: &AnalysisArgs,
    scheme: Box<dyn Scheme>,
    document: Option<&std::path::Path>,
) -> Result<i32, Error> {
    let (scheme, analysis) = run_analysis(a, scheme)?;
    if analysis.discovered.config.tagging.is_some() {
        return certified_tagged(a, scheme.as_ref(), &analysis, document);
    }
    let certificate = crate::certify::certify_analysis(scheme.as_ref(), &analysis)?;
    if let Some(path) = document {
        crate::certify::export::write_spectrum(path, scheme.as_ref(), &analysis, &certificate)?;
    }
    if a.json {
        #[derive(serde::Serialize)]
        struct Certified<'a> {
            #[serde(flatten)]
            spectrum: &'a Spectrum,
            certificate: &'a crate::certify::SpectrumCertificate,
        }
        print_json(&Certified { spectrum: &analysis.spectrum, certificate: &certificate })?;
    } else {
        out_text(&format!("{}\n{}", spectrum_table(&analysis.spectrum), certificate_table(&certificate)))?;
    }
    Ok(certified_status(&certificate.verdict, certificate.conditional))
}

/// `spectrum --tag T --certify`: the table and the certificate of the
/// sector criterion's spectral part (`certify::tagged`); Ok holds the exit
/// status ([`certified_status`]).
fn certified_tagged(
    a: &AnalysisArgs,
    scheme: &dyn Scheme,
    analysis: &Analysis,
    document: Option<&std::path::Path>,
) -> Result<i32, Error> {
    let certificate = crate::certify::tagged::certify_tagged(scheme, analysis)?;
    if let Some(path) = document {
        crate::certify::export::write_tagged(path, scheme, analysis, &certificate)?;
    }
    if a.json {
        #[derive(serde::Serialize)]
        struct Certified<'a> {
            #[serde(flatten)]
            spectrum: &'a Spectrum,
            certificate: &'a crate::certify::tagged::TaggedCertificate,
        }
        print_json(&Certified { spectrum: &analysis.spectrum, certificate: &certificate })?;
    } else {
        out_text(&format!("{}\n{}", spectrum_table(&analysis.spectrum), tagged_certificate_table(&certificate)))?;
    }
    Ok(certified_status(&certificate.verdict, certificate.conditional))
}

/// A certificate's first lines, interior or tagged: what it certifies and
/// the verdict, the statement, and which of table and certificate decides.
fn certificate_head(what: &str, verdict: &crate::certify::Verdict, conditional: bool, statement: &str) -> String {
    let mut out = format!(
        "{what}: {}{}\n",
        verdict.display(),
        if conditional { ", given the premises marked 'identity' below" } else { "" }
    );
    out += &format!("  statement: {statement}\n");
    out += "  (the floating-point table above observes; where it disagrees with this certificate, the certificate \
            decides)\n";
    out
}

/// How a premise was checked, in words (`field`: where the exact rows lie).
fn premise_text(check: &crate::certify::matrix::Check, field: &str) -> String {
    use crate::certify::matrix::Check;
    match check {
        Check::Exact => format!("exact, in {field}"),
        Check::Overlap => "identity of the rules' formulas, confirmed to interval overlap only".to_string(),
        Check::Fails(w) => format!("fails: {w}"),
    }
}

/// The tagged certificate as text: the verdict, the premises, each route;
/// at a crease vertex each side's, then S whole's, labelled.
fn tagged_certificate_table(c: &crate::certify::tagged::TaggedCertificate) -> String {
    let mut out =
        certificate_head("certified sector criterion, spectral part", &c.verdict, c.conditional, &c.statement);
    let Some(crease) = &c.crease else {
        out += &tagged_routes(c, "  ");
        out += &format!("  decided by: {}\n", c.decided_by.unwrap_or("neither route"));
        return out;
    };
    if let Some(why) = &crease.coupled {
        out += &format!("  no per-side verdict: {why}; the criterion is applied to S whole\n");
        out += &tagged_routes(c, "  ");
        out += &format!("  decided by: {}\n", c.decided_by.unwrap_or("neither route"));
        return out;
    }
    let invariance = crease
        .invariance
        .as_ref()
        .map_or("-".to_string(), |x| premise_text(x, c.premises.field.as_deref().unwrap_or("Q")));
    out += &format!(
        "  premise each side's points (with the crease curve's {}) have zero weight outside them in every row: {invariance}\n",
        crease.curve.len()
    );
    for side in &crease.sides {
        let x = &side.certificate;
        out += &format!("  {}: {}\n", side.name, x.verdict.display());
        out += &tagged_routes(x, "    ");
        out += &format!("    decided by: {}\n", x.decided_by.unwrap_or("neither route"));
    }
    out += &format!(
        "  S whole (both sides at once; not the crease's criterion): {}, decided by: {}\n",
        crease.whole_verdict.display(),
        crease.whole_decided_by.unwrap_or("neither route")
    );
    out += &tagged_routes(c, "    ");
    out += "  decided by: each side's certificate\n";
    out
}

/// A tagged certificate's premises and routes, each line after `indent`.
fn tagged_routes(c: &crate::certify::tagged::TaggedCertificate, indent: &str) -> String {
    let mut out = String::new();
    let field = c.premises.field.as_deref().unwrap_or("Q");
    let show = |x: &crate::certify::matrix::Check| premise_text(x, field);
    out += &format!("  premise row sums = 1: {}\n", show(&c.premises.row_sums_one));
    out += &format!(
        "  premise S commutes with the reflection keeping the sharp rays: {}\n",
        c.premises.reflection.as_ref().map_or("no such reflection of the labelled set".to_string(), show)
    );
    let sizes: Vec<String> = c.blocks.iter().map(|b| format!("{} ({})", b.name, b.size)).collect();
    let e = &c.enclosure_route;
    out += &format!("  enclosure route (lemma T4) on the blocks {}: {}\n", sizes.join(", "), e.verdict.display());
    for (name, n) in [("λ0", &e.lambda0), ("λ1", &e.lambda1), ("λ2", &e.lambda2)] {
        if let Some(n) = n {
            out += &format!("    {name} ∈ [{:.15}, {:.15}] ({} block)\n", n.enclosure.lo, n.enclosure.hi, n.block);
        }
    }
    if let (Some(m), Some(g)) = (e.others_max_modulus, e.gap_lower_bound) {
        out += &format!("    max |other eigenvalue| ≤ {m:.12e}; gap λ2 − max|other| ≥ {g:.12e}\n");
    }
    match (&c.exact_route, &c.exact_route_skipped) {
        (Some(x), _) => {
            let sizes: Vec<String> = x.blocks.iter().map(|(n, s)| format!("{n} ({s})")).collect();
            out += &format!("  exact route (lemma T7) over Q on {}: {}\n", sizes.join(", "), x.verdict.display());
            if let Some(r) = &x.r {
                out += &format!(
                    "    r = {r}: algebraic multiplicity {}, geometric {}, {} eigenvalue(s) other than 1 above it in \
                     modulus, none of modulus r besides r (counting Schur–Cohn)\n",
                    x.algebraic, x.geometric, x.above
                );
            }
        }
        (None, Some(why)) => out += &format!("  exact route (lemma T7): not taken ({why})\n"),
        (None, None) => {}
    }
    out.lines().map(|l| format!("{indent}{}\n", l.strip_prefix("  ").unwrap_or(l))).collect()
}

/// The certificate as text: the verdict, the premises and the margins.
pub(super) fn certificate_table(c: &crate::certify::SpectrumCertificate) -> String {
    let mut out = certificate_head("certified spectral C1 conditions", &c.verdict, c.conditional, &c.statement);
    if let Some(p) = &c.premises {
        let field = p.field.as_deref().unwrap_or("Q");
        let show = |x: &crate::certify::matrix::Check| premise_text(x, field);
        out += &format!("  premise row sums = 1: {}\n", show(&p.row_sums_one));
        out += &format!("  premise mirror symmetry: {}\n", show(&p.mirror_symmetry));
        out += &format!("  premise rotation symmetry: {}\n", show(&p.rotation_symmetry));
    }
    if let Some(e) = &c.exact_route {
        let lambda1 = e.lambda1.as_deref().unwrap_or("-");
        out += &if e.proved {
            format!(
                "  exact route (lemma S7): det(xI − S) over Q ({} × {}): 1 simple, λ1 = {lambda1} a double root with \
                 a two-dimensional eigenspace, the other {} roots inside |x| < {} (Schur–Cohn)\n",
                e.size,
                e.size,
                e.cofactor_degree,
                e.others_below.as_deref().unwrap_or("-")
            )
        } else if e.one_multiplicity != 1 {
            format!(
                "  exact route (lemma S7): det(xI − S) over Q ({} × {}): 1 is a root of multiplicity {}\n",
                e.size, e.size, e.one_multiplicity
            )
        } else {
            format!(
                "  exact route (lemma S7): det(xI − S) over Q ({} × {}): λ1 = {lambda1} dominant (the other {} roots \
                 inside |x| < {lambda1}, Schur–Cohn), of algebraic multiplicity {} and geometric multiplicity {}\n",
                e.size, e.size, e.cofactor_degree, e.algebraic, e.geometric
            )
        };
    }
    let m = &c.margins;
    let f = |x: Option<f64>| x.map_or("-".to_string(), |v| format!("{v:.12e}"));
    if let Some(l) = m.lambda0 {
        out += &format!("  λ0 ∈ [{:.15}, {:.15}]\n", l.lo, l.hi);
    }
    if let Some(l) = m.lambda1 {
        out += &format!("  λ1 ∈ [{:.15}, {:.15}]\n", l.lo, l.hi);
    }
    out += &format!(
        "  max |other eigenvalue| ≤ {}; gap λ1 − max|other| ≥ {}\n  largest disc radius {:.3e} (λ0, λ1: {}); widest block entry {:.3e}\n",
        f(m.others_max_modulus),
        f(m.gap_lower_bound),
        m.max_radius,
        f(m.lambda_radius),
        m.max_entry_width
    );
    for &b in &m.power_bounded {
        if let Some(p) = c.blocks.iter().find(|e| e.block == b).and_then(|e| e.power_bound) {
            out += &format!(
                "  block {b} by lemma S6 (no eigenvectors): ρ ≤ ‖B^{}‖∞^(1/{}) ≤ {:.9} (‖B^{}‖∞ ≤ {:.6e})\n",
                p.k, p.k, p.radius, p.k, p.norm
            );
        }
    }
    if let Some(w) = &c.witness {
        out += &format!(
            "  witness: block {}, {} eigenvalue(s) with modulus in [{:.12}, {:.12}]\n",
            w.block,
            w.component.count,
            w.component.min_modulus(),
            w.component.max_modulus()
        );
    }
    out
}

/// The spectrum per reflection block (`spectrum::reflection`), after the
/// whole matrix's table: the leading eigenvalues of each block.
fn reflection_table(
    r: &crate::spectrum::reflection::ReflectionSpectra,
    tagging: Option<crate::neighbourhood::Tagging>,
) -> String {
    const SHOWN: usize = 6;
    let mut out = format!(
        "\nreflection r -> {} - r (keeps the sharp rays{}): S = even ({}) + odd ({}) blocks, floating point\n",
        r.axis,
        tagging.map(|t| format!(" of the {} vertex", t.name())).unwrap_or_default(),
        r.even_size,
        r.odd_size
    );
    for (name, values) in [("even", &r.even), ("odd", &r.odd)] {
        let shown: Vec<String> = values
            .iter()
            .take(SHOWN)
            .map(|v| {
                let z = crate::spectrum::fmt_f(v.re);
                let z = if v.im.abs() > 1e-12 { format!("{z}{:+.6}i", v.im) } else { z };
                match (v.algebraic_multiplicity, v.geometric_multiplicity) {
                    (1, _) => z,
                    (m, g) if m == g => format!("{z} (x{m})"),
                    (m, g) => format!("{z} (x{m}, defective: geo {g})"),
                }
            })
            .collect();
        let more = if values.len() > SHOWN { ", ..." } else { "" };
        out += &format!("  {name:<4}: {}{more}\n", shown.join(", "));
    }
    out
}
