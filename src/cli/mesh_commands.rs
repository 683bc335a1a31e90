//! `subdlab refine` (OBJ in, OBJ out) and `subdlab curve` (curve schemes of
//! Lin–Luo section 3). Kept apart from the analysis commands.

use std::path::Path;

use super::commands::parse_params;
use crate::curves::local::{curve_spectrum, CurveSpectrum};
use crate::error::Error;
use crate::io::{print_json, write_atomic};
use crate::mesh::obj::{read_obj_file, read_tags, write_obj, MAX_TAG_FILE_BYTES};
use crate::neighbourhood::NeighbourhoodKind;
use crate::refine::mesh::{add_face_control_vertices, four_directional, refine_mesh};
use crate::schemes;

/// How meshes are prepared and written for schemes with face control vertices
/// (non-box) or a per-vertex parameter (unified-sqrt3).
pub struct MeshOptions {
    pub fcv_scale: f64,
    pub four_directional: bool,
    pub vertex_params: Option<std::path::PathBuf>,
    /// a side file of boundary, crease and corner tags (`mesh::obj::read_tags`)
    pub tags: Option<std::path::PathBuf>,
}

pub fn refine(
    mesh: &Path,
    scheme: &str,
    levels: usize,
    params: &[String],
    output: &Path,
    opts: &MeshOptions,
) -> Result<(), Error> {
    // check the cheap arguments before reading a possibly large file
    let scheme = schemes::resolve(scheme, &parse_params(params)?)?;
    if levels == 0 || levels > crate::refine::mesh::MAX_LEVELS {
        return Err(Error::Input(format!(
            "--levels must be between 1 and {}, got {levels}",
            crate::refine::mesh::MAX_LEVELS
        )));
    }
    if !opts.fcv_scale.is_finite() {
        return Err(Error::Input(format!("--fcv-scale must be a finite number, got {}", opts.fcv_scale)));
    }
    if !scheme.face_control() && (opts.four_directional || opts.fcv_scale != 1.0) {
        return Err(Error::Input(format!(
            "{} has no face control vertices: --fcv-scale and --four-directional do not apply",
            scheme.name()
        )));
    }
    if opts.vertex_params.is_some() && scheme.vertex_param().is_none() {
        return Err(Error::Input(format!(
            "{} has no per-vertex parameter: --vertex-params does not apply",
            scheme.name()
        )));
    }
    let (mut m, mut points) = read_obj_file(mesh)?;
    if let Some(path) = &opts.tags {
        let text = super::verify::read_capped(path, MAX_TAG_FILE_BYTES as u64, "file of tags")?;
        read_tags(&text, &mut m, &path.display().to_string())?;
    }
    // a real mesh's open edges are its boundary: tagged sharp, so that the
    // boundary rules apply (hosts without them refuse the mesh in one line)
    if m.tags.is_some() || m.edges().into_iter().any(|(a, b)| !m.is_interior_edge(a, b)) {
        m.tag_open_edges();
    }
    if let Some(path) = &opts.vertex_params {
        m.vertex_params = Some(read_vertex_params(path, scheme.as_ref(), m.num_vertices())?);
    }
    if scheme.face_control() {
        (m, points) = add_face_control_vertices(&m, &points, opts.fcv_scale)?;
    }
    if scheme.lattice_oriented() {
        // asymmetric masks need the lattice directions (i, j) on every quad
        m.orient_lattice().map_err(|e| e.map_message(|e| format!("{}: {} {e}", mesh.display(), scheme.name())))?;
    }
    let (mut refined, mut new_points) =
        refine_mesh(scheme.as_ref(), &m, &points, levels).map_err(|e| e.context(mesh.display()))?;
    if opts.four_directional {
        (refined, new_points) = four_directional(&refined, new_points)?;
    }
    let params_text: Vec<String> = scheme.params().values.iter().map(|(k, v)| format!("{k}={}", v.text)).collect();
    let header = format!(
        "subdlab refine: {} refined {levels} level(s) with {}{}\n{} vertices, {} faces",
        mesh.file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default(),
        scheme.name(),
        if params_text.is_empty() { String::new() } else { format!(" ({})", params_text.join(", ")) },
        refined.num_vertices(),
        refined.num_faces()
    );
    write_atomic(output, write_obj(&refined, &new_points, &header).as_bytes())
}

/// One value per line for each vertex, within the parameter's admissible range.
fn read_vertex_params(path: &Path, scheme: &dyn crate::schemes::Scheme, count: usize) -> Result<Vec<f64>, Error> {
    let spec = scheme.vertex_param().expect("checked by the caller");
    let name = spec.name;
    let text = super::verify::read_capped(path, 64 * 1024 * 1024, "file of per-vertex parameters")?;
    let mut values = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let t = line.split('#').next().unwrap_or("").trim();
        if t.is_empty() {
            continue;
        }
        let v = crate::numeric::ParamValue::parse(t)
            .map_err(|e| Error::File(format!("{} line {}: {e}", path.display(), k + 1)))?;
        if v.value < spec.min || v.value > spec.max {
            return Err(Error::File(format!(
                "{} line {}: {name} = {t} is out of range [{}, {}]",
                path.display(),
                k + 1,
                spec.min,
                spec.max
            )));
        }
        values.push(v.value);
        if values.len() > count {
            break;
        }
    }
    if values.len() != count {
        return Err(Error::File(format!("{}: {} values for {count} vertices", path.display(), values.len())));
    }
    Ok(values)
}

pub fn curve(scheme: &str, params: &[String], neighbourhood: &str, json: bool) -> Result<(), Error> {
    let scheme = crate::schemes::curves::build(scheme, &parse_params(params)?)?;
    curve_of(scheme.as_ref(), neighbourhood, json)
}

/// The curve analysis of a resolved curve scheme (`subdlab curve`, and
/// `subdlab spectrum` of a curve scheme through the front door).
pub fn curve_of(scheme: &dyn crate::curves::CurveScheme, neighbourhood: &str, json: bool) -> Result<(), Error> {
    let kind: NeighbourhoodKind = neighbourhood.parse()?;
    let spec = curve_spectrum(scheme, kind)?;
    if json {
        return print_json(&spec);
    }
    crate::io::out(&curve_table(&spec))
}

fn curve_table(s: &CurveSpectrum) -> String {
    let mut out = format!(
        "curve scheme {}  neighbourhood {}: {} points (indices {}..{}; minimal {}, analysis {})\n",
        s.scheme,
        match s.neighbourhood {
            NeighbourhoodKind::Minimal => "minimal",
            NeighbourhoodKind::Analysis => "analysis",
        },
        s.matrix_size,
        s.window.first().copied().unwrap_or(0),
        s.window.last().copied().unwrap_or(0),
        s.minimal_size,
        s.analysis_size
    );
    if !s.params.is_empty() {
        out += &format!(
            "parameters: {}\n",
            s.params.iter().map(|(k, v)| format!("{k}={v}")).collect::<Vec<_>>().join(", ")
        );
    }
    out += "\n";
    out += &format!("{:>4}  {:<34} {:>4} {:>4}\n", "#", "eigenvalue", "alg", "geo");
    for (k, e) in s.eigenvalues.iter().enumerate() {
        let num = if e.im == 0.0 {
            crate::spectrum::fmt_f(e.re)
        } else {
            format!("{}{:+}i", crate::spectrum::fmt_f(e.re), crate::spectrum::fmt_f(e.im))
        };
        let shown = match (&e.exact, &e.recognised) {
            (Some(x), _) => format!("{num} (= {x})"),
            (None, Some(r)) => format!("{num} (≈ {r})"),
            _ => num,
        };
        out += &format!(
            "{:>4}  {:<34} {:>4} {:>4}{}\n",
            k,
            shown,
            e.algebraic_multiplicity,
            e.geometric_multiplicity,
            if e.defective { "  DEFECTIVE" } else { "" }
        );
    }
    match &s.charpoly {
        Some(p) if s.exact => out += &format!("\nexact: det(xI - S) = {p}; every eigenvalue is rational and proven\n"),
        Some(p) => out += &format!("\nexact: det(xI - S) = {p}; not every root is rational\n"),
        None => out += "\n(no exact matrix: a weight is not rational)\n",
    }
    out
}
