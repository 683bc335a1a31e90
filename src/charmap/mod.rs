//! Characteristic maps (Reif): the planar map whose control net is the pair of
//! subdominant eigenvectors, refined with the scheme's own rules; the scheme
//! is C¹ at the extraordinary point (given the spectral conditions) when the
//! map is regular and injective on its characteristic ring.
//!
//! Files, one per concern: `spectral` (choosing the pair, or why there is
//! none), `net` (the control net and its refinement), `ring` (ring extraction,
//! winding numbers), `regularity` (signs of the Jacobian), `raster` (coverage
//! per pixel), `wedge` (normalised wedges for large valences).

pub mod net;
pub mod raster;
pub mod regularity;
pub mod ring;
pub mod spectral;
pub mod wedge;

use nalgebra::{Matrix2, Vector2};
use serde::Serialize;

use crate::error::Error;
use crate::neighbourhood::{Configuration, NeighbourhoodKind};
use crate::sdc::Scheme;
use crate::spectrum::{analyse_shared, Analysis, Options};
pub use raster::Coverage;
pub use regularity::Regularity;
pub use ring::{Ring, Tri};
pub use spectral::SpectralStatus;

/// Most analysis steps of refinement (a ring facet count grows 4^levels).
pub const MAX_LEVELS: usize = 8;
/// Levels of a host that splits a face into 4 per analysis step; other hosts
/// get the level count of about the same resolution ([`default_levels`]).
pub const DEFAULT_LEVELS: usize = 4;
pub const DEFAULT_RESOLUTION: usize = 512;
/// A winding number this far from an integer means the boundary is not closed
/// around the centre (a bug or a degenerate net), not a count.
const WINDING_TOL: f64 = 1e-6;

#[derive(Clone, Debug)]
pub struct CharMapOptions {
    /// analysis steps of refinement (sqrt(3) schemes: two refinements each)
    pub levels: usize,
    /// pixels per side of the rasterisation
    pub resolution: usize,
    /// also build the ring at this (coarser) level for drawing
    pub display_levels: Option<usize>,
}

impl CharMapOptions {
    /// The options for a check at `levels` and `resolution`, validated.
    pub fn checked(levels: usize, resolution: usize) -> Result<Self, Error> {
        let opts = CharMapOptions { levels, resolution, display_levels: None };
        opts.check()?;
        Ok(opts)
    }
    pub fn check(&self) -> Result<(), Error> {
        if self.levels == 0 || self.levels > MAX_LEVELS {
            return Err(Error::Input(format!("levels must be between 1 and {MAX_LEVELS}, got {}", self.levels)));
        }
        if self.resolution < 16 || self.resolution > raster::MAX_RESOLUTION {
            return Err(Error::Input(format!(
                "resolution must be between 16 and {} pixels, got {}",
                raster::MAX_RESOLUTION,
                self.resolution
            )));
        }
        Ok(())
    }
}

/// The default level count for `scheme`'s host: the one whose ring is about
/// as finely resolved as [`DEFAULT_LEVELS`] steps of a 1-to-4 split. A level
/// is one analysis step, which multiplies the faces by g (4 for the binary
/// hosts; 9 for the ternary host and for sqrt(3)'s two steps), so its edges
/// shrink by √g; the level count is 4 · ln 2 / ln √g, rounded: 4 for g = 4,
/// 3 for g = 9 (where 4 levels refine 9⁴ = 6561 facets per face, 26 times a
/// binary host's 256, and decided the same sweeps as 3). A host that grows
/// more slowly (the polar split's 2) keeps [`DEFAULT_LEVELS`]: the default
/// only ever lowers the cost.
pub fn default_levels(scheme: &dyn Scheme) -> usize {
    let host = scheme.topology();
    let growth = (host.faces_per_face() as f64).powi(host.steps_per_analysis() as i32);
    if growth <= 1.0 {
        return DEFAULT_LEVELS;
    }
    let levels = (DEFAULT_LEVELS as f64 * 2f64.ln() / growth.sqrt().ln()).round() as usize;
    levels.clamp(2, DEFAULT_LEVELS)
}

impl Default for CharMapOptions {
    fn default() -> Self {
        CharMapOptions { levels: DEFAULT_LEVELS, resolution: DEFAULT_RESOLUTION, display_levels: None }
    }
}

/// Everything the characteristic-map check found. Field names are stable API
/// (`subdlab charmap --json`).
#[derive(Clone, Debug, Serialize)]
pub struct CharMap {
    pub scheme: String,
    pub valence: usize,
    /// the tagging of a tagged vertex (`--tag`), whose map is checked on its
    /// sectors: regular, and injective by the raster (an open fan's ring
    /// does not wind around the centre, so there is no winding number)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tagging: Option<String>,
    /// at a tagged vertex, the angle (degrees, counter-clockwise) from the
    /// image of the first sharp ray's vertex next to the centre to that of
    /// the last sharp ray's (level 0; a limit tangent angle only where both
    /// rays' images are straight, as when λ1 = λ2 is the curve's 1/2)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ray_angle_degrees: Option<f64>,
    pub params: std::collections::BTreeMap<String, String>,
    /// the subdominant eigenvalue λ1
    pub lambda1: f64,
    pub subdominant_blocks: Vec<usize>,
    pub spectral_status: SpectralStatus,
    pub explanation: String,
    pub c1_spectral: bool,
    pub levels: usize,
    pub refinements: usize,
    pub resolution: usize,
    pub regular: bool,
    pub injective: bool,
    /// winding number of the ring's outer boundary around the centre
    pub winding_number: Option<i64>,
    /// winding number of the ring's inner boundary (λ1 times the outer one)
    pub inner_winding_number: Option<i64>,
    pub overlap_pixels: Option<usize>,
    pub copy_overlap_pixels: Option<usize>,
    pub ring_pixels: Option<usize>,
    pub min_jacobian_ratio: Option<f64>,
    pub min_jacobian_at: Option<[f64; 2]>,
    pub folded_facets: Option<usize>,
    pub ring_facets: usize,
    /// the ring's area over the area inside it (λ1 scaling makes this
    /// (1 − λ1²)/λ1² for an injective map)
    pub ring_area: Option<f64>,
    pub inner_area: Option<f64>,
    pub reasons: Vec<String>,
    /// at a `crease:K` vertex: each side's own map, and S whole's beside
    /// them (`crease_map`); the fields above are then the crease's verdict
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crease: Option<CreaseMaps>,
    /// the normalised ring (the map rotated so that a sector spoke is on the
    /// positive x-axis, oriented counter-clockwise, outer radius 1)
    #[serde(skip)]
    pub ring: Option<Ring>,
    #[serde(skip)]
    pub display: Option<Ring>,
    /// level-0 control net faces (normalised), for figures
    #[serde(skip)]
    pub control_net: Vec<Vec<[f64; 2]>>,
}

/// The characteristic maps of a crease vertex (`--tag crease:K`), side by
/// side. Each side's map is built from that side's own subdominant
/// eigenvectors (the principal submatrix on its points,
/// `spectrum::crease_sides`) on that side's sectors only, and must be
/// regular and injective there (Zorin 2000; Biermann–Levin–Zorin 2000).
#[derive(Clone, Debug, Serialize)]
pub struct CreaseMaps {
    /// side A's and side B's maps (empty when the sides do not decouple)
    pub sides: Vec<CharMap>,
    /// S whole's map (both sides' eigenvectors at once; not the crease's
    /// criterion), where S whole passes the spectral part
    pub whole: Option<Box<CharMap>>,
    /// why S whole has no map, when it has none
    pub whole_missing: Option<String>,
    /// why there is no per-side map (the map is then S whole's)
    pub coupled: Option<String>,
}

/// Analyse `scheme` at `config` and check its characteristic map.
pub fn characteristic_map(
    scheme: &dyn Scheme,
    config: &Configuration,
    opts: &CharMapOptions,
) -> Result<CharMap, Error> {
    opts.check()?;
    let analysis = analyse_shared(
        scheme,
        config,
        &Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false },
    )?;
    check_map(scheme, &analysis, opts)
}

/// The check on a finished analysis (analysis neighbourhood).
pub fn check_map(scheme: &dyn Scheme, analysis: &Analysis, opts: &CharMapOptions) -> Result<CharMap, Error> {
    check_map_over(scheme, analysis, opts, None)
}

/// [`check_map`], reading the refined map off `rows` (the analysis's unit
/// rows refined `opts.levels` analysis steps, as the curvature analysis
/// holds them) instead of refining the eigenvectors again; `None`, or rows
/// of another level, refine as `check_map` does.
pub fn check_map_over(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    opts: &CharMapOptions,
    rows: Option<&net::Net<crate::refine::SparseRow<f64>>>,
) -> Result<CharMap, Error> {
    // `subdlab verify` checks one configuration's map several times (a
    // curvature claim on the float and again on the exact analysis, several
    // claims of one paper): the check is a function of the scheme, the
    // configuration (which fixes the discovered patch), the subdominant pair
    // and the options, so it is memoised on exactly those. Whether the
    // refined map was read off given rows is part of the key: that route
    // rounds differently, and a shared result must not depend on which
    // caller came first.
    let Some(identity) = scheme.identity() else {
        return check_map_uncached(scheme, analysis, opts, rows);
    };
    let spec = &analysis.spectrum;
    let tagged = spec.tagging.is_some();
    let pair = if tagged { spectral::sector_pair(spec) } else { spectral::subdominant_pair(spec) };
    let steps = scheme.topology().steps_per_analysis();
    let reads_rows = rows.is_some_and(|r| r.refinements == opts.levels * steps);
    let key = format!(
        "{identity} {:?} {:?} c1={} rows={reads_rows} {:?} {} {:?} {:?} {:?}",
        analysis.discovered.config,
        opts,
        spec.verdict.c1_spectral,
        pair.status,
        pair.explanation,
        pair.lambda.to_bits(),
        pair.blocks,
        pair.values.iter().map(|p| [p[0].to_bits(), p[1].to_bits()]).collect::<Vec<_>>(),
    );
    CHECKED_MAPS
        .get_or_try_insert(key, || check_map_uncached(scheme, analysis, opts, rows), charmap_bytes)
        .map(|m| (*m).clone())
}

/// Checked maps, shared by every caller in the process (see
/// [`check_map_over`]).
static CHECKED_MAPS: crate::engine::memo::Memo<CharMap> = crate::engine::memo::Memo::new(64 << 20);

/// What a memoised [`CharMap`] holds, roughly.
fn charmap_bytes(m: &CharMap) -> usize {
    1024 + m.control_net.iter().map(|ring| ring.len() * 16).sum::<usize>()
        + m.reasons.iter().map(String::len).sum::<usize>()
}

fn check_map_uncached(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    opts: &CharMapOptions,
    rows: Option<&net::Net<crate::refine::SparseRow<f64>>>,
) -> Result<CharMap, Error> {
    let spec = &analysis.spectrum;
    if spec.neighbourhood != NeighbourhoodKind::Analysis {
        return Err(Error::Input("the characteristic map needs the analysis neighbourhood".into()));
    }
    if let Some(crease) = spec.crease.as_ref().filter(|c| c.coupled.is_none()) {
        return crease_map(scheme, analysis, crease, opts);
    }
    let tagged = spec.tagging.is_some();
    let pair = if tagged { spectral::sector_pair(spec) } else { spectral::subdominant_pair(spec) };
    let mut out = unchecked(spec, &pair, spec.verdict.c1_spectral, opts);
    check_pair(&mut out, scheme, &analysis.discovered, &pair, opts, rows, None)?;
    if let Some(why) = spec.crease.as_ref().and_then(|c| c.coupled.clone()) {
        out.reasons.insert(0, format!("no per-side map: {why}; the map is S whole's"));
        out.crease = Some(CreaseMaps { sides: Vec::new(), whole: None, whole_missing: None, coupled: Some(why) });
    }
    Ok(out)
}

/// A map not checked yet: the analysis's identity and the pair's spectral
/// status; `c1_spectral` is the spectral verdict the pair stands under.
fn unchecked(
    spec: &crate::spectrum::Spectrum,
    pair: &spectral::Pair,
    c1_spectral: bool,
    opts: &CharMapOptions,
) -> CharMap {
    CharMap {
        tagging: spec.tagging.clone(),
        ray_angle_degrees: None,
        scheme: spec.scheme.clone(),
        valence: spec.valence,
        params: spec.params.clone(),
        lambda1: pair.lambda,
        subdominant_blocks: pair.blocks.clone(),
        spectral_status: pair.status,
        explanation: pair.explanation.clone(),
        c1_spectral,
        levels: opts.levels,
        refinements: 0,
        resolution: opts.resolution,
        regular: false,
        injective: false,
        winding_number: None,
        inner_winding_number: None,
        overlap_pixels: None,
        copy_overlap_pixels: None,
        ring_pixels: None,
        min_jacobian_ratio: None,
        min_jacobian_at: None,
        folded_facets: None,
        ring_facets: 0,
        ring_area: None,
        inner_area: None,
        reasons: Vec::new(),
        crease: None,
        ring: None,
        display: None,
        control_net: Vec::new(),
    }
}

/// One side of a crease vertex, for [`check_pair`]: the pair is defined on
/// `points` (indices of S, ascending; the pair's values are in this order)
/// and the map is checked on the first-ring faces flagged in `first_ring`.
struct SideOfCrease<'a> {
    points: &'a [usize],
    first_ring: Vec<bool>,
    /// the side's bounding sharp rays, counter-clockwise: (first, last)
    rays: (usize, usize),
}

/// Build the map of `pair` on the analysis's patch, refine it and check it
/// (regularity, injectivity on the raster), into `out`. With `side`, the
/// map of one side of a crease: its values live on that side's points, and
/// only that side's part of the first ring is refined and checked.
fn check_pair(
    out: &mut CharMap,
    scheme: &dyn Scheme,
    d: &crate::neighbourhood::Discovered,
    pair: &spectral::Pair,
    opts: &CharMapOptions,
    rows: Option<&net::Net<crate::refine::SparseRow<f64>>>,
    side: Option<&SideOfCrease>,
) -> Result<(), Error> {
    if !pair.status.has_map() {
        out.reasons.push(format!("no characteristic map: {}", pair.explanation));
        return Ok(());
    }
    let tagged = d.config.tagging.is_some();
    // the pair over the whole analysis set: a side's pair is zero off the
    // side (for the questions asked of level-0 values: collapsed rays, the
    // normalisation's reference point, the rays' angle), and undefined
    // there in the net that is refined
    let values: Vec<[f64; 2]> = match side {
        None => pair.values.clone(),
        Some(side) => {
            let mut all = vec![[0.0; 2]; d.analysis.len()];
            for (&k, v) in side.points.iter().zip(&pair.values) {
                all[k] = *v;
            }
            all
        }
    };
    if let Some(why) = collapsed_rays(d, &values) {
        out.spectral_status = SpectralStatus::NotDominant;
        out.explanation = why.clone();
        out.reasons.push(format!("no characteristic map: {why}"));
        return Ok(());
    }
    let mut level0 = net::initial_points(d, &values)?;
    if let Some(side) = side {
        for (k, &v) in d.analysis.iter().enumerate() {
            if side.points.binary_search(&k).is_err() {
                level0[v] = None;
            }
        }
    }
    let steps = scheme.topology().steps_per_analysis();
    let refine = |level0: Vec<Option<[f64; 2]>>, levels: usize| match side {
        None => net::refine_net(scheme, d, level0, levels),
        Some(side) => net::refine_net_within(scheme, d, level0, levels, &side.first_ring),
    };
    let mut fine = match rows.filter(|r| r.refinements == opts.levels * steps && side.is_none()) {
        Some(rows) => rows.evaluate(&values),
        None => refine(level0.clone(), opts.levels)?,
    };
    // an eigenvector pair is fixed only up to a linear map; a nearly parallel
    // pair (possible from the full matrix) would squash the ring to a few
    // pixels, so first make its outer boundary isotropic (regularity and
    // injectivity are invariant under linear maps)
    let w = isotropic(&ring::extract(&fine));
    net::transform(&mut fine.points, w);
    let values: Vec<[f64; 2]> = values.iter().map(|&p| net::apply_linear(&w, p)).collect();
    let m = normalisation(d, &values, &ring::extract(&fine));
    net::transform(&mut fine.points, m);
    let m = m * w;
    out.refinements = fine.refinements;
    let ring = ring::extract(&fine);

    let reg = regularity::regularity(&ring.ring);
    let (cov, _) = raster::rasterise_ring(&ring.ring, &ring.inner, opts.resolution)?;
    let outer_w = ring::winding_number(&ring.outer_boundary);
    let inner_w = ring::winding_number(&ring.inner_boundary);
    let round = |w: Option<f64>| w.filter(|w| (w - w.round()).abs() < WINDING_TOL).map(|w| w.round() as i64);
    out.winding_number = round(outer_w);
    out.inner_winding_number = round(inner_w);
    out.regular = reg.regular;
    out.min_jacobian_ratio = Some(reg.min_jacobian_ratio);
    out.min_jacobian_at = Some(reg.min_jacobian_at);
    out.folded_facets = Some(reg.folded_facets);
    out.ring_facets = reg.facets;
    out.overlap_pixels = Some(cov.overlap_pixels);
    out.copy_overlap_pixels = Some(cov.copy_overlap_pixels);
    out.ring_pixels = Some(cov.ring_pixels);
    out.ring_area = Some(regularity::total_signed_area(&ring.ring));
    out.inner_area = Some(regularity::total_signed_area(&ring.inner));

    let mut reasons = vec![pair.explanation.clone()];
    if reg.regular {
        reasons.push(format!(
            "regular: all {} facets positively oriented; smallest/largest signed area {:.4}",
            reg.facets, reg.min_jacobian_ratio
        ));
    } else {
        reasons.push(format!(
            "not regular: {} of {} facets folded or degenerate; smallest/largest signed area {:.4} at ({:.4}, {:.4})",
            reg.folded_facets, reg.facets, reg.min_jacobian_ratio, reg.min_jacobian_at[0], reg.min_jacobian_at[1]
        ));
    }
    if tagged {
        // an open fan's ring has the centre on its boundary: no winding
        // number; injectivity is the raster's (no pixel twice, none shared
        // with the inner copy) on a regular map
        out.winding_number = None;
        out.inner_winding_number = None;
        let normalised: Vec<[f64; 2]> = values.iter().map(|&p| net::apply_linear(&m, p)).collect();
        out.ray_angle_degrees = match side {
            None => d.config.tagging.and_then(|t| {
                let rays = t.sharp_rays(d.config.valence());
                ray_angle(d, &normalised, (*rays.first()?, *rays.last()?))
            }),
            Some(side) => ray_angle(d, &normalised, side.rays),
        };
        if let Some(a) = out.ray_angle_degrees {
            reasons.push(format!("the sharp rays' images meet at {a:.4}° at the centre"));
        }
    } else {
        match (outer_w, out.winding_number) {
            (Some(_), Some(1)) => reasons.push("the ring's outer boundary winds once around the centre".into()),
            (Some(_), Some(w)) => reasons.push(format!("the ring's outer boundary winds {w} times around the centre")),
            (Some(w), None) => reasons.push(format!("the outer boundary's winding number {w:.4} is not an integer")),
            (None, _) => reasons.push("the outer boundary passes through the centre".into()),
        }
        if out.inner_winding_number != Some(1) {
            reasons.push(format!(
                "the ring's inner boundary winds {:?} times around the centre",
                out.inner_winding_number
            ));
        }
    }
    reasons.push(format!(
        "{} of {} ring pixels covered more than once; {} pixels shared with the scaled copy (resolution {})",
        cov.overlap_pixels, cov.ring_pixels, cov.copy_overlap_pixels, opts.resolution
    ));
    let winds_once = tagged || (out.winding_number == Some(1) && out.inner_winding_number == Some(1));
    out.injective = reg.regular && winds_once && cov.overlap_pixels == 0 && cov.copy_overlap_pixels == 0;
    reasons.push(if out.injective {
        "injective: the characteristic map passes (regular and injective)".into()
    } else {
        "not injective".into()
    });
    out.reasons = reasons;

    if let Some(levels) = opts.display_levels {
        let mut coarse = refine(level0.clone(), levels.clamp(1, opts.levels))?;
        net::transform(&mut coarse.points, m);
        out.display = Some(ring::extract(&coarse));
    }
    let mut pts0 = level0;
    net::transform(&mut pts0, m);
    out.control_net = control_net(&d.patch, &pts0);
    out.ring = Some(ring);
    Ok(())
}

/// The sector (0..n) a face of the level-0 first ring lies in, from its
/// corners' labels: a corner off the rays (j > 0) names it; otherwise its
/// two ray corners are on rays s and s + 1 (mod n), and it is sector s.
fn first_ring_sector(face: &[usize], labels: &[crate::neighbourhood::VertexLabel], n: usize) -> Option<usize> {
    if let Some(l) =
        face.iter().map(|&v| &labels[v]).find(|l| l.j > 0 && l.kind != crate::neighbourhood::VertexKind::Centre)
    {
        return Some(l.sector % n);
    }
    let rays: Vec<usize> = face
        .iter()
        .map(|&v| &labels[v])
        .filter(|l| l.kind != crate::neighbourhood::VertexKind::Centre && l.j == 0 && l.i > 0)
        .map(|l| l.sector % n)
        .collect();
    rays.iter().copied().find(|&a| rays.contains(&((a + 1) % n)))
}

/// The crease's map, side by side: each side's own pair (its principal
/// submatrix's eigenvectors) on its own sectors; the crease passes when
/// both sides' maps are regular and injective. S whole's map is kept
/// beside them where S whole passes the spectral part.
fn crease_map(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    crease: &crate::spectrum::spectrum_result::CreaseVerdict,
    opts: &CharMapOptions,
) -> Result<CharMap, Error> {
    let spec = &analysis.spectrum;
    let d = &analysis.discovered;
    let Some(crate::neighbourhood::Tagging::Crease { at }) = d.config.tagging else {
        return Err(Error::Message("a per-side verdict at a configuration that is not a crease".into()));
    };
    let n = d.config.valence();
    let centre: std::collections::HashSet<usize> = net::centre_set(d).into_iter().collect();
    let mut sides = Vec::new();
    for (s, side) in crease.sides.iter().enumerate() {
        let mut pair = spectral::sector_pair(&side.spectrum);
        let mut m = unchecked(spec, &pair, side.verdict.c1_spectral, opts);
        m.tagging = Some(format!("crease:{at} {}", side.name));
        // the pair on the side's points and on the curve's outer points
        // that no side's row reads (Loop's second points on the sharp rays),
        // which the side's refined first ring does read
        let e = &side.spectrum.eigenvalues;
        let points = if pair.status.has_map() && e.len() > 2 {
            let lambdas = if e[1].algebraic_multiplicity >= 2 { [e[1].re; 2] } else { [e[1].re, e[2].re] };
            match extend_over_curve(analysis, at, s, &side.points, &pair.values, lambdas) {
                Ok((points, values)) => {
                    pair.values = values;
                    points
                }
                Err(why) => {
                    m.reasons.push(format!("no characteristic map: {why}"));
                    m.explanation = why;
                    m.spectral_status = SpectralStatus::Missing;
                    sides.push(m);
                    continue;
                }
            }
        } else {
            side.points.clone()
        };
        // this side's faces of the first ring: sectors 0..K−1 (A), K..n−1 (B)
        let first_ring: Vec<bool> = d
            .patch
            .faces()
            .iter()
            .map(|f| {
                f.iter().any(|v| centre.contains(v))
                    && first_ring_sector(f, &d.labels, n).is_some_and(|sector| usize::from(sector >= at) == s)
            })
            .collect();
        let restriction = SideOfCrease { points: &points, first_ring, rays: if s == 0 { (0, at) } else { (at, 0) } };
        check_pair(&mut m, scheme, d, &pair, opts, None, Some(&restriction))?;
        sides.push(m);
    }
    // S whole's map, where S whole passes the spectral part on its own
    let whole_pair = spectral::sector_pair_under(spec, &crease.whole);
    let (whole, whole_missing) = if whole_pair.status.has_map() {
        let mut w = unchecked(spec, &whole_pair, crease.whole.c1_spectral, opts);
        match check_pair(&mut w, scheme, d, &whole_pair, opts, None, None) {
            Ok(()) => (Some(Box::new(w)), None),
            Err(e) => (None, Some(format!("S whole's map could not be checked: {e}"))),
        }
    } else {
        (None, Some(whole_pair.explanation.clone()))
    };

    let mut out = unchecked(spec, &spectral::Pair::missing(""), spec.verdict.c1_spectral, opts);
    out.lambda1 = sides.iter().map(|m| m.lambda1).fold(f64::NAN, f64::max);
    out.subdominant_blocks = Vec::new();
    let failing = sides.iter().find(|m| !m.spectral_status.has_map());
    out.spectral_status = failing.map_or(SpectralStatus::Ok, |m| m.spectral_status);
    let named = |m: &CharMap, what: &str| format!("{}: {what}", side_name(m));
    out.explanation = match failing {
        Some(m) => format!("per side: {}", named(m, &m.explanation)),
        None => format!("per side: {}", sides.iter().map(|m| named(m, &m.explanation)).collect::<Vec<_>>().join("; ")),
    };
    out.regular = sides.iter().all(|m| m.regular);
    out.injective = sides.iter().all(|m| m.regular && m.injective);
    out.refinements = sides.iter().map(|m| m.refinements).max().unwrap_or(0);
    let sum = |f: &dyn Fn(&CharMap) -> Option<usize>| sides.iter().map(f).sum::<Option<usize>>();
    out.overlap_pixels = sum(&|m| m.overlap_pixels);
    out.copy_overlap_pixels = sum(&|m| m.copy_overlap_pixels);
    out.ring_pixels = sum(&|m| m.ring_pixels);
    out.folded_facets = sum(&|m| m.folded_facets);
    out.ring_facets = sides.iter().map(|m| m.ring_facets).sum();
    out.min_jacobian_ratio = sides
        .iter()
        .map(|m| m.min_jacobian_ratio)
        .min_by(|a, b| a.unwrap_or(f64::NEG_INFINITY).total_cmp(&b.unwrap_or(f64::NEG_INFINITY)))
        .flatten();
    out.reasons.push(format!(
        "the crease's map, per side (Zorin 2000; Biermann–Levin–Zorin 2000): each side's own subdominant \
         eigenvectors on its own sectors, regular and injective there; floating point, the Jacobian's sign on \
         every facet and injectivity on the raster ({} levels, resolution {})",
        opts.levels, opts.resolution
    ));
    for m in &sides {
        let verdict = match (m.ring.is_some(), m.regular, m.injective) {
            (false, _, _) => format!("FAILS: no map: {}", m.explanation),
            (true, true, true) => "PASSES: regular and injective".to_string(),
            (true, false, _) => "FAILS: not regular".to_string(),
            (true, true, false) => "FAILS: not injective".to_string(),
        };
        let angle = m.ray_angle_degrees.map(|a| format!("; the sharp rays' images at {a:.4}°")).unwrap_or_default();
        let said = if m.ring.is_some() { format!(" ({}{angle})", m.explanation) } else { String::new() };
        out.reasons.push(format!("{}: {verdict}{said}", side_name(m)));
    }
    out.reasons.push(match (&whole, &whole_missing) {
        (Some(w), _) => format!(
            "S whole (both sides at once; not the crease's criterion): {}",
            if w.regular && w.injective { "regular and injective" } else { "not regular and injective" }
        ),
        (None, why) => format!(
            "S whole (both sides at once; not the crease's criterion): no map: {}",
            why.as_deref().unwrap_or("-")
        ),
    });
    // the figure shows both sides, each in its own normalisation: side A
    // from ray 0 (the positive x-axis) counter-clockwise to ray K, side B
    // from ray K on round to ray 0, so together they fill the plane
    if sides.iter().all(|m| m.ring.is_some()) {
        out.ring = merged(sides.iter().map(|m| m.ring.as_ref()));
        out.display = merged(sides.iter().map(|m| m.display.as_ref().or(m.ring.as_ref())));
        out.control_net = sides.iter().flat_map(|m| m.control_net.clone()).collect();
    }
    out.crease = Some(CreaseMaps { sides, whole, whole_missing, coupled: None });
    Ok(out)
}

/// A side's pair (over its points X, indices of S, ascending) extended to
/// the points R of S that lie on neither side's inside and outside X: the
/// outer points of the sharp rays, whose rows read only the curve but which
/// no side's row reads (so the side's closure leaves them out, and its
/// spectrum is right without them), while the side's refined first ring
/// reads them. With X ∪ R invariant (checked on the float rows, to the
/// closure's tolerance), S on it is [[S_XX, 0], [S_RX, S_RR]], and the
/// eigenvector of λ with x on X has (λ − S_RR) r = S_RX x on R: solved per
/// component, each with its own λ (λ1, λ2). Refused where λ is an
/// eigenvalue of S_RR (no unique extension).
fn extend_over_curve(
    analysis: &Analysis,
    at: usize,
    side: usize,
    points: &[usize],
    values: &[[f64; 2]],
    lambdas: [f64; 2],
) -> Result<(Vec<usize>, Vec<[f64; 2]>), String> {
    use crate::spectrum::crease_sides::{side_of, READ_TOLERANCE};
    let s: &crate::matrix::LocalMatrix<f64> = &analysis.matrix;
    let labels = &s.labels;
    let in_x = |p: usize| points.binary_search(&p).is_ok();
    let extra: Vec<usize> =
        (0..labels.len()).filter(|&p| !in_x(p) && side_of(&labels[p], at) != Some(1 - side)).collect();
    if extra.is_empty() {
        return Ok((points.to_vec(), values.to_vec()));
    }
    let scale = s.rows.iter().flatten().fold(0.0f64, |m, (_, w)| m.max(w.abs())).max(1.0);
    let position = |p: usize| extra.binary_search(&p).ok();
    let k = extra.len();
    let mut srr = nalgebra::DMatrix::<f64>::zeros(k, k);
    let mut srx = vec![[0.0f64; 2]; k];
    for (i, &r) in extra.iter().enumerate() {
        for &(b, w) in &s.rows[r] {
            if let Some(j) = position(b) {
                srr[(i, j)] = w;
            } else if let Ok(x) = points.binary_search(&b) {
                for c in 0..2 {
                    srx[i][c] += w * values[x][c];
                }
            } else if w.abs() > READ_TOLERANCE * scale {
                return Err(format!(
                    "the row of {} (outside the side, on the curve) reads {}, strictly inside the other side",
                    labels[r].name, labels[b].name
                ));
            }
        }
    }
    let mut ext = vec![[0.0f64; 2]; k];
    for c in 0..2 {
        let a = nalgebra::DMatrix::<f64>::identity(k, k) * lambdas[c] - &srr;
        let rhs = nalgebra::DVector::from_iterator(k, srx.iter().map(|v| v[c]));
        let lu = a.clone().lu();
        let solved = lu.solve(&rhs).filter(|x| x.iter().all(|v| v.is_finite()));
        // a pivot this small against the matrix is a λ of S_RR
        let min_singular = a.singular_values().min();
        let Some(x) = solved.filter(|_| min_singular > 1e-10 * (1.0 + lambdas[c].abs())) else {
            return Err(format!(
                "λ = {} is an eigenvalue of the rows of the curve's outer points: the side's eigenvector has no unique extension there",
                crate::spectrum::fmt_f(lambdas[c])
            ));
        };
        for (i, v) in x.iter().enumerate() {
            ext[i][c] = *v;
        }
    }
    let mut merged: Vec<(usize, [f64; 2])> =
        points.iter().copied().zip(values.iter().copied()).chain(extra.iter().copied().zip(ext)).collect();
    merged.sort_by_key(|(p, _)| *p);
    Ok(merged.into_iter().unzip())
}

/// "side A (sectors 0..1, 2 faces, 15 points)" from a side map's tagging.
fn side_name(m: &CharMap) -> &str {
    let t = m.tagging.as_deref().unwrap_or("");
    t.find("side ").map_or(t, |k| &t[k..])
}

/// The rings of several maps drawn as one (the crease's figure).
fn merged<'a>(rings: impl Iterator<Item = Option<&'a Ring>>) -> Option<Ring> {
    let mut out = Ring {
        ring: Vec::new(),
        inner: Vec::new(),
        outer_boundary: Vec::new(),
        inner_boundary: Vec::new(),
        ring_polys: Vec::new(),
        inner_polys: Vec::new(),
    };
    for r in rings {
        let r = r?;
        out.ring.extend(&r.ring);
        out.inner.extend(&r.inner);
        out.outer_boundary.extend(&r.outer_boundary);
        out.inner_boundary.extend(&r.inner_boundary);
        out.ring_polys.extend(r.ring_polys.iter().cloned());
        out.inner_polys.extend(r.inner_polys.iter().cloned());
    }
    Some(out)
}

/// The linear map that orients the ring counter-clockwise, puts the image of
/// the first spoke vertex (ring 1, sector 0) on the positive x-axis and the
/// outer boundary at radius at most 1. Orientation, rotation and scale of an
/// eigenvector pair are arbitrary; fixing them makes figures comparable.
fn normalisation(d: &crate::neighbourhood::Discovered, values: &[[f64; 2]], raw: &Ring) -> Matrix2<f64> {
    let area = regularity::total_signed_area(&raw.ring) + regularity::total_signed_area(&raw.inner);
    let flip = if area < 0.0 { -1.0 } else { 1.0 };
    let reference = d
        .analysis
        .iter()
        .zip(values)
        .filter(|(v, p)| d.labels[**v].ring == 1 && d.labels[**v].sector == 0 && p[0].hypot(p[1]) > 0.0)
        .map(|(_, p)| [p[0], flip * p[1]])
        .next()
        .or_else(|| values.iter().find(|p| p[0].hypot(p[1]) > 0.0).map(|p| [p[0], flip * p[1]]))
        .unwrap_or([1.0, 0.0]);
    let theta = reference[1].atan2(reference[0]);
    let (c, s) = (theta.cos(), theta.sin());
    let radius = raw.outer_boundary.iter().flatten().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max);
    let k = if radius > 0.0 { 1.0 / radius } else { 1.0 };
    // rotate by −θ after flipping y
    Matrix2::new(k * c, k * s * flip, -k * s, k * c * flip)
}

/// Why a tagged vertex's map would send its sharp rays to the centre, if it
/// would. The rows of the vertices on a sharp curve read only that curve
/// (the crease rules), so S is block triangular and an eigenvector of an
/// eigenvalue that is not the curve's vanishes on the curve: when λ1 and
/// λ2 are not among the curve's eigenvalues (Hoppe's rules at larger k),
/// the map collapses every sharp ray to a point and cannot be injective.
/// Decided on the level-0 values (largest ray value against the largest
/// value, relative tolerance 1e-9).
fn collapsed_rays(d: &crate::neighbourhood::Discovered, values: &[[f64; 2]]) -> Option<String> {
    let tagging = d.config.tagging?;
    let rays = tagging.sharp_rays(d.config.valence());
    let size = |p: &[f64; 2]| p[0].hypot(p[1]);
    let all = values.iter().map(size).fold(0.0, f64::max);
    let on_rays = d
        .analysis
        .iter()
        .zip(values)
        .filter(|(&v, _)| {
            let l = &d.labels[v];
            l.j == 0 && l.i > 0 && rays.contains(&l.sector)
        })
        .map(|(_, p)| size(p))
        .fold(0.0, f64::max);
    (on_rays <= 1e-9 * all).then(|| {
        format!(
            "the subdominant eigenvectors vanish on the sharp rays (largest value there {on_rays:.3e} against \
             {all:.3e}): λ1 and λ2 are not eigenvalues of the sharp curve's rows, so the map sends the \
             rays to the centre and is not injective"
        )
    })
}

/// The angle (degrees in [0, 360), counter-clockwise) from the image of the
/// vertex next to the centre on ray `first` to that on ray `last`, `values`
/// over the analysis set; None when the rays are one (a dart) or an image is
/// at the centre.
fn ray_angle(d: &crate::neighbourhood::Discovered, values: &[[f64; 2]], (first, last): (usize, usize)) -> Option<f64> {
    if first == last {
        return None;
    }
    let at = |sector: usize| {
        d.analysis.iter().zip(values).find_map(|(&v, p)| {
            let l = &d.labels[v];
            (l.sector == sector && l.i == 1 && l.j == 0 && p[0].hypot(p[1]) > 0.0).then_some(*p)
        })
    };
    let (a, b) = (Vector2::from(at(first)?), Vector2::from(at(last)?));
    Some(a.perp(&b).atan2(a.dot(&b)).to_degrees().rem_euclid(360.0))
}

/// M^(-1/2) for the second-moment matrix M of the ring's outer boundary
/// vertices (about the centre, which the map sends to the origin).
fn isotropic(raw: &Ring) -> Matrix2<f64> {
    let (mut a, mut b, mut c) = (0.0, 0.0, 0.0);
    for p in raw.outer_boundary.iter().flatten() {
        a += p[0] * p[0];
        b += p[0] * p[1];
        c += p[1] * p[1];
    }
    let half = 0.5 * (a - c);
    let r = (half * half + b * b).sqrt();
    let (l1, l2) = (0.5 * (a + c) + r, 0.5 * (a + c) - r);
    // (NaN compares false, so a NaN l2 is degenerate too)
    if l2.partial_cmp(&(1e-300 * l1.max(1.0))) != Some(std::cmp::Ordering::Greater) || !l1.is_finite() {
        return Matrix2::identity(); // degenerate: leave it to the verdicts
    }
    let t = 0.5 * (2.0 * b).atan2(a - c);
    let (co, si) = (t.cos(), t.sin());
    let (d1, d2) = (1.0 / l1.sqrt(), 1.0 / l2.sqrt());
    // R diag(d1, d2) R^T with R the rotation by t
    let r = Matrix2::new(co, -si, si, co);
    r * Matrix2::from_diagonal(&Vector2::new(d1, d2)) * r.transpose()
}

/// Faces of the level-0 patch whose corners all carry the eigenvector.
fn control_net(patch: &crate::mesh::PolyMesh, pts: &[Option<[f64; 2]>]) -> Vec<Vec<[f64; 2]>> {
    patch.faces().iter().filter_map(|f| f.iter().map(|&v| pts[v]).collect::<Option<Vec<_>>>()).collect()
}

/// `run` for a configuration: the common call for the regular configuration.
pub fn characteristic_map_of(scheme: &dyn Scheme, valence: usize, opts: &CharMapOptions) -> Result<CharMap, Error> {
    let config = Configuration::regular(scheme, valence)?;
    characteristic_map(scheme, &config, opts)
}
