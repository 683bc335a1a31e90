//! The configurations a scheme is analysed at (`Configuration::regular`,
//! `Configuration::with_faces`), refused before any work where the analysis
//! would not fit in memory: the estimate is measured by discovering the
//! scheme's neighbourhood at a small valence (`discovery::bytes_per_sector`),
//! so this sits above both `configuration` and `discovery`.

use super::configuration::{check_tagged, check_valence, Configuration, Tagging, MAX_VALENCE};
use crate::error::Error;
use crate::mesh::SectorKind;
use crate::sdc::{CentreKind, Scheme};

/// Valences up to this are accepted without an estimate: every built-in
/// scheme needs under 100 MB there (README, "Every analysis command"), and
/// sweeps over 3..1000 then pay no probe per valence.
pub const UNESTIMATED_VALENCE: usize = 1000;

impl Configuration {
    /// The scheme's regular configuration of valence n.
    pub fn regular(scheme: &dyn Scheme, n: usize) -> Result<Self, Error> {
        check_valence(n)?;
        if let Some(k) = scheme.fixed_valence().filter(|&k| k != n) {
            return Err(Error::Input(format!(
                "{} is defined on the regular lattice only (valence {k}), not at valence {n}",
                scheme.name()
            )));
        }
        check_valence_for(scheme, n)?;
        Ok(Configuration {
            centre: scheme.centre_kind(),
            sectors: vec![scheme.sector_kind(); n],
            face_control: scheme.face_control(),
            tagging: None,
        })
    }

    /// The configuration with the given face sequence around the centre (one
    /// letter per sector, counter-clockwise: Q a quad, T a triangle), for schemes
    /// that accept face sequences (4-3 subdivision).
    pub fn with_faces(scheme: &dyn Scheme, n: usize, faces: &str) -> Result<Self, Error> {
        check_valence_for(scheme, n)?;
        let sectors = parse_faces(scheme, n, faces)?;
        Ok(Configuration { centre: scheme.centre_kind(), sectors, face_control: scheme.face_control(), tagging: None })
    }

    /// The configuration of a tagged vertex (`--tag`): k sectors of a
    /// boundary or corner vertex (an open fan, k >= 1), or n sectors around
    /// a crease or dart, all of the scheme's face kind or as `faces` lists
    /// them. The scheme's rules must have crease and corner rules, and its
    /// refinement must carry tags (the discovery says so where they do not).
    pub fn tagged(scheme: &dyn Scheme, n: usize, faces: Option<&str>, tagging: Tagging) -> Result<Self, Error> {
        check_tagged(n, tagging)?;
        if scheme.centre_kind() != CentreKind::Vertex || scheme.face_control() {
            return Err(Error::Input(format!(
                "--tag {}: tagged configurations are vertex-centred, but {} is {}",
                tagging.name(),
                scheme.name(),
                if scheme.face_control() { "a face-control-vertex scheme" } else { "centred on a face or a pole" }
            )));
        }
        let sectors = match faces {
            Some(f) => parse_faces(scheme, n, f)?,
            None => vec![scheme.sector_kind(); n],
        };
        check_memory_for(scheme, n)?;
        Ok(Configuration { centre: CentreKind::Vertex, sectors, face_control: false, tagging: Some(tagging) })
    }
}

/// The sectors of a `--faces` sequence of `n` letters (Q a quad, T a
/// triangle), for schemes that accept face sequences (4-3 subdivision).
fn parse_faces(scheme: &dyn Scheme, n: usize, faces: &str) -> Result<Vec<SectorKind>, Error> {
    if !scheme.face_sequences() {
        return Err(Error::Input(format!(
            "scheme '{}' takes no --faces: its configurations are all {}",
            scheme.name(),
            match scheme.sector_kind() {
                SectorKind::Quad => "quads",
                SectorKind::Tri => "triangles",
            }
        )));
    }
    let sectors: Vec<SectorKind> = faces
        .chars()
        .enumerate()
        .map(|(k, c)| match c {
            'Q' => Ok(SectorKind::Quad),
            'T' => Ok(SectorKind::Tri),
            _ => Err(Error::Input(format!(
                "--faces '{faces}': character {} ('{c}') is neither Q (quad) nor T (triangle)",
                k + 1
            ))),
        })
        .collect::<Result<Vec<_>, _>>()?;
    if sectors.len() != n {
        return Err(Error::Input(format!("--faces '{faces}' has {} letters but the valence is {n}", sectors.len())));
    }
    Ok(sectors)
}

/// [`check_valence`] and the memory the analysis of `scheme` at valence `n`
/// is estimated to need, refused above [`crate::error::MEMORY_BUDGET`] before
/// any work. Time and memory of an analysis are linear in the valence (the
/// patch, its refinement around the orbit representatives, the labels and
/// the n Fourier blocks of fixed size), so the estimate is the scheme's
/// bytes per sector, measured on its neighbourhood at a small valence
/// ([`super::discovery::bytes_per_sector`]), times n. The one valence limit
/// of every command that builds a configuration (`Configuration::regular`,
/// `Configuration::with_faces`).
pub fn check_valence_for(scheme: &dyn Scheme, n: usize) -> Result<(), Error> {
    check_valence(n)?;
    check_memory_for(scheme, n)
}

/// The memory part of [`check_valence_for`], for `n` sectors of any
/// configuration (tagged ones have their own lower bound on n).
fn check_memory_for(scheme: &dyn Scheme, n: usize) -> Result<(), Error> {
    if n <= UNESTIMATED_VALENCE {
        return Ok(());
    }
    let per = super::discovery::bytes_per_sector(scheme);
    // hosts of two refinements per analysis step (sqrt(3)) also grow as n²:
    // measured 15 (sqrt3) and 31 (unified-sqrt3) bytes per n², e.g. sqrt3
    // 0.51 GB at n = 5000 and 1.8 GB at n = 10000
    let square = if scheme.topology().steps_per_analysis() > 1 { TWO_STEP_BYTES_PER_N2 } else { 0.0 };
    let estimate = |n: usize| per * n as f64 + square * (n as f64).powi(2);
    // the estimate grows with n: the largest valence within the budget by bisection
    let (mut fits, mut over) = (UNESTIMATED_VALENCE, MAX_VALENCE + 1);
    while over - fits > 1 {
        let mid = fits + (over - fits) / 2;
        if estimate(mid) <= crate::error::MEMORY_BUDGET {
            fits = mid;
        } else {
            over = mid;
        }
    }
    crate::error::check_memory(
        estimate(n),
        &format!("{} at valence {n}", scheme.name()),
        &format!(
            "about {:.0} KiB per sector, from its neighbourhood at valence {}{}",
            per / 1024.0,
            super::discovery::PROBE_VALENCE,
            if square > 0.0 {
                format!(", and {square:.0} bytes per n² for its two-refinement steps")
            } else {
                String::new()
            }
        ),
        &format!("the largest valence that fits is about {fits}"),
    )
}

/// The quadratic part of the estimate for hosts of two refinements per
/// analysis step (see [`check_valence_for`]): the largest measured, with no
/// margin beyond the linear part's.
const TWO_STEP_BYTES_PER_N2: f64 = 32.0;
