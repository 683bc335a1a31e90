//! The certified characteristic-map verdict: a proof (or disproof, or the
//! reason for neither) that the characteristic map is regular and injective,
//! the geometric half of Reif's C¹ criterion.
//!
//! Attempted only after the spectral certificate PROVED its statement; the
//! lemmas C1–C8 of ARCHITECTURE.md ("The proofs, step by step") are written
//! there in full, and each function below names the one it implements.
//!
//! 1. **Eigenvectors (C1).** The eigenvector of the disc the spectral proof
//!    named as λ1's, in block 1's verified diagonalisation (the very one the
//!    spectral certificate enclosed: `SpectrumCertificate::proof`), is
//!    enclosed (`discs::eigenvector`) and spread over the neighbourhood by
//!    the rotation: x₍ₜ,ₐ₎ = ω^t·zₐ. No floating-point eigenvalue or block
//!    is consulted. Re and Im are the two coordinate functions; any complex
//!    multiple gives the same map up to a linear change of coordinates,
//!    which keeps regularity and injectivity.
//! 2. **Net (C2).** The level-0 net of enclosures is refined with the
//!    scheme's own rules in interval arithmetic (`net::refine_net_exactly_as`).
//! 3. **Regular part (C3, C3′).** Over a ring face whose one-ring of faces
//!    is a regular grid, the rules at the window's regular entities are
//!    compared exactly with the masks of the bicubic B-spline, A_4, the
//!    biquadratic B-spline (dual and ternary) or the three-direction quartic
//!    box spline; on a net with face control vertices (non-box) with the
//!    four-directional S_3^1 spline's mask, derived from its definition in
//!    `certify::s31` (never from the scheme or the paper's printed mask).
//! 4. **Jacobian (C3, C3′).** det(∂ᵤx, ∂ᵥx) lies between the smallest and
//!    the largest det(uᵢ, vⱼ) over the window's edge vectors along the two
//!    lattice directions; for the biquadratic B-spline on the face enlarged
//!    by half a face on every side; for S_3^1 the differences are the face's
//!    own two edges per direction and the six differences of the 9 FCVs
//!    around it (the window's hull: its 4 corners and those 9 FCVs).
//! 5. **Regularity (C4, C5).** The annulus's scaled copies, with (dual
//!    schemes) the half-face enlargement covering the quarter-face bands
//!    between consecutive copies, cover the punctured neighbourhood; one
//!    sign on every ring face proves regularity, both signs disprove it.
//! 6. **Winding number (C6, C7).** From half-planes holding the windows'
//!    hulls and exact orientation signs of a polygon through the chain's
//!    control points (`winding_number`, `half_plane`, `polygon_winding`);
//!    Peters–Reif: a regular characteristic map is injective if and only if
//!    its winding number is ±1.

use std::collections::{HashMap, HashSet};

use serde::Serialize;

use super::complex::CInterval;
use super::difference;
use super::discs::eigenvector;
use super::s31;
use super::spectrum::{certify_analysis, SpectrumCertificate, Verdict};
use super::window_orbits;
use crate::charmap::net::{self, Net};
use crate::error::Error;
use crate::mesh::{IdMap, IdSet, PolyMesh};
use crate::numeric::{Interval, Rational, SmallRational, Weight};
use crate::refine::{connectivity, stencil_at, GatherError, Origin};
use crate::sdc::host::RegularSpline;
use crate::sdc::Scheme;
use crate::spectrum::Analysis;

/// Analysis steps of refinement tried in turn until every ring face is
/// decided (the first level whose ring faces all have regular windows is 2).
pub const DEFAULT_MAX_LEVELS: usize = 5;
pub const MAX_LEVELS: usize = 6;

pub type Point = [Interval; 2];

/// The box splines whose masks the certificate recognises.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RegularPart {
    /// primal quad rules: vertex 9/16, 3/32, 1/64; edge 3/8, 1/16; face 1/4
    BicubicBSpline,
    /// dual quad rules: corner 9/16, 3/16, 3/16, 1/16
    BiquadraticBSpline,
    /// triangle rules: vertex 5/8, 1/16; edge 3/8, 3/8, 1/8, 1/8
    ThreeDirectionQuarticBoxSpline,
    /// ternary quad rules, the tensor products of the univariate ternary
    /// quadratic mask (1, 3, 6, 7, 6, 3, 1)/9: vertex (1, 7, 1)²/81, edge
    /// (6, 3) ⊗ (1, 7, 1)/81, interior (6, 3)²/81
    BiquadraticBSplineTernary,
    /// primal quad rules of the four-direction box spline A_4 with directions
    /// {±e1, ±e2, e1 + e2, −e1 + e2} (degree 4, C², 4-3 subdivision's quads):
    /// vertex 1/2, 1/8 (nothing on the diagonal); edge and face as bicubic.
    /// Its support around a control point is |x|, |y| ≤ 2, |x ± y| ≤ 3, and
    /// that of its derivative along e1 (A_4 without e1) is |x| ≤ 3/2,
    /// |y| ≤ 2 about each e1-edge's midpoint, so over a face both lie in the
    /// 4×4 window as the bicubic's do: the same Jacobian and hull bounds hold.
    FourDirectionBoxSpline,
    /// Huang's non-box scheme's regular part: the four-directional S_3^1
    /// spline f = Σ λ_V (φ_□ * χ)(· − V) + Σ λ_F (φ_◇ * χ)(· − F), a vector
    /// (two-generator) spline whose V-vertices carry the square hat and
    /// whose face control vertices carry the diamond hat; its mask is
    /// derived from that definition (`certify::s31`), and the windows hold
    /// the face's own edges and the differences of the 9 FCVs around it.
    NonBoxS31,
    /// no box spline: the scheme's own regular rules on the triangular
    /// lattice, with the derivative and position bounds of lemma C9 from
    /// the contraction of their difference scheme (`certify::difference`)
    DifferenceScheme,
}

impl RegularPart {
    pub fn describe(self) -> &'static str {
        match self {
            RegularPart::BicubicBSpline => "bicubic B-spline",
            RegularPart::BiquadraticBSpline => "biquadratic B-spline",
            RegularPart::ThreeDirectionQuarticBoxSpline => "three-direction quartic box spline",
            RegularPart::BiquadraticBSplineTernary => "biquadratic B-spline (ternary refinement)",
            RegularPart::FourDirectionBoxSpline => "four-direction box spline A_4",
            RegularPart::NonBoxS31 => "four-directional S_3^1 non-box spline",
            RegularPart::DifferenceScheme => "the scheme's regular rules, difference-scheme bounds",
        }
    }
}

/// Everything `charmap --certify` proves. Field names are stable API.
#[derive(Clone, Debug, Serialize)]
pub struct CharMapCertificate {
    pub scheme: String,
    pub valence: usize,
    /// the spectral half (λ0, λ1, the gap)
    pub spectrum: SpectrumCertificate,
    /// the Jacobian of the characteristic map has one sign
    pub regularity: Verdict,
    /// the characteristic map is injective
    pub injectivity: Verdict,
    /// Reif's criterion as a whole: spectrum, regularity and injectivity
    pub c1: Verdict,
    /// proved only given premises confirmed to interval overlap (see the
    /// spectral certificate)
    pub conditional: bool,
    /// regularity and injectivity rest on S commuting with the rotation (the
    /// eigenvector is spread over the sectors by it), and that premise was
    /// confirmed to interval overlap only
    pub geometry_conditional: bool,
    /// the box spline the regular rules were matched with
    pub regular_part: Option<RegularPart>,
    /// regular entities whose rational stencils were compared with its masks
    pub rules_checked: usize,
    /// analysis steps of refinement of the decisive net
    pub levels: Option<usize>,
    pub ring_faces: usize,
    pub positive_faces: usize,
    pub negative_faces: usize,
    pub undecided_faces: usize,
    /// smallest lower bound of the Jacobian over the ring (orientation made
    /// positive), in level-0 parameter units, for the map scaled so that the
    /// ring lies in the unit disc
    pub min_jacobian_lower_bound: Option<f64>,
    /// the same over the largest upper bound of the Jacobian over the ring
    pub min_jacobian_ratio: Option<f64>,
    /// the largest |yⱼ| of the eigenvector enclosure (0 for an exact vector)
    pub eigenvector_radius: Option<f64>,
    pub max_point_width: Option<f64>,
    pub winding_number: Option<i64>,
    /// when regularity is disproved: a ring face where the Jacobian is
    /// proved negative and one where it is proved positive
    pub fold_witness: Option<FoldWitness>,
    pub reasons: Vec<String>,
    /// what the geometric verdicts rest on, for the certificate document
    /// (`export::charmap_part`); set when regularity is decided
    #[serde(skip)]
    pub evidence: Option<Evidence>,
}

/// The decisive level's geometric proof as data an independent checker can
/// redo: which nets points the windows use, the signs claimed, and the
/// winding computation. Vertex indices are the level-`levels` net's (the
/// exporter re-refines the net with exact stencils and maps them).
#[derive(Clone, Debug)]
pub struct Evidence {
    pub levels: usize,
    /// the disc of block 1's diagonalisation whose eigenvector spans the map
    pub lambda1_row: usize,
    pub faces: Vec<FaceEvidence>,
    pub winding: Option<WindingEvidence>,
    /// lemma C9's lattice data, when the regular part is `DifferenceScheme`
    pub difference: Option<std::sync::Arc<difference::LatticeBound>>,
}

/// One ring face's window: its edge vectors along the two lattice
/// directions as (from, to) net vertices, and the Jacobian sign proved on it
/// (+1, −1, or 0 undecided).
#[derive(Clone, Debug)]
pub struct FaceEvidence {
    pub u_edges: Vec<(usize, usize)>,
    pub v_edges: Vec<(usize, usize)>,
    pub sign: i8,
    /// non-box windows (empty otherwise): the edges' points with their
    /// lattice positions in half units (the face is [0, 2]², V-vertices at
    /// even and FCVs at odd positions), from which a checker re-derives
    /// which differences and hull points the S_3^1 bounds need
    pub layout: Vec<(usize, [i64; 2])>,
    /// difference-scheme windows (empty otherwise): every point of the
    /// face's window W_up with its lattice position, from which a checker
    /// recomputes the second differences N(p) and the face's bounds
    pub window: Vec<(usize, [i64; 2])>,
}

/// The winding-number lemma's data (see `winding_number`): per chain edge
/// i, the window (index into the ring faces) beside it, the chain vertex
/// i + 1 that ends it, the half-plane direction dᵢ and the polygon point wᵢ.
#[derive(Clone, Debug)]
pub struct WindingEvidence {
    pub windows: Vec<usize>,
    pub vertices: Vec<usize>,
    pub directions: Vec<[f64; 2]>,
    pub polygon: Vec<[f64; 2]>,
    pub number: i64,
}

/// Two ring faces with Jacobians of proved opposite signs.
#[derive(Clone, Debug, Serialize)]
pub struct FoldWitness {
    /// the image of the negative face's centre (the average of its corners'
    /// enclosure midpoints; a location, not part of the proof)
    pub negative_at: [f64; 2],
    /// the Jacobian's upper bound there (below 0), in net units
    pub negative_upper_bound: f64,
    pub positive_at: [f64; 2],
    /// the Jacobian's lower bound there (above 0), in net units
    pub positive_lower_bound: f64,
}

/// The one range check of the certificate's most refinement levels, shared
/// by `charmap --certify-levels`, certified claims' `levels` and
/// [`certify_charmap`]: 2 to [`MAX_LEVELS`]; `what` names the value where it
/// was given.
pub fn check_levels(max_levels: usize, what: &str) -> Result<(), Error> {
    if !(2..=MAX_LEVELS).contains(&max_levels) {
        return Err(Error::Input(format!("{what} must be between 2 and {MAX_LEVELS}, got {max_levels}")));
    }
    Ok(())
}

/// Certify the characteristic map of an analysis (analysis neighbourhood), once per analysis and
/// number of levels: two claims about the same scheme, configuration and
/// valence (the 4-3 eons of Peters–Shiue's theorem 3.7 are certified by two)
/// read one certificate.
pub fn certify_charmap(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    max_levels: usize,
) -> Result<CharMapCertificate, Error> {
    check_levels(max_levels, "certification levels")?;
    let shared = analysis.derived(max_levels as u64, || certify_charmap_once(scheme, analysis, max_levels))?;
    Ok(CharMapCertificate::clone(&shared))
}

fn certify_charmap_once(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    max_levels: usize,
) -> Result<CharMapCertificate, Error> {
    let spectrum = certify_analysis(scheme, analysis)?;
    let s = &analysis.spectrum;
    let mut cert = CharMapCertificate {
        scheme: s.scheme.clone(),
        valence: s.valence,
        conditional: spectrum.conditional,
        geometry_conditional: false,
        spectrum,
        regularity: Verdict::NotProved(String::new()),
        injectivity: Verdict::NotProved(String::new()),
        c1: Verdict::NotProved(String::new()),
        regular_part: None,
        rules_checked: 0,
        levels: None,
        ring_faces: 0,
        positive_faces: 0,
        negative_faces: 0,
        undecided_faces: 0,
        min_jacobian_lower_bound: None,
        min_jacobian_ratio: None,
        eigenvector_radius: None,
        max_point_width: None,
        winding_number: None,
        fold_witness: None,
        reasons: Vec::new(),
        evidence: None,
    };
    // regularity and injectivity are statements about the map of λ1's
    // eigenvectors: attempted only once the spectrum is proved
    let geometric = match &cert.spectrum.verdict {
        Verdict::Proved => geometric_half(scheme, analysis, max_levels, &mut cert),
        other => Err(format!(
            "not attempted: the spectrum is {} ({}), so there is no certified λ1 whose eigenvectors define the map",
            other.word(),
            match other {
                Verdict::Disproved(w) | Verdict::NotProved(w) => w.as_str(),
                Verdict::Proved => "",
            }
        )),
    };
    let (regularity, injectivity) = match geometric {
        Ok(v) => v,
        Err(why) => (Verdict::NotProved(why.clone()), Verdict::NotProved(why)),
    };
    use super::matrix::Check;
    let rotation = cert.spectrum.premises.as_ref().map(|p| p.rotation_symmetry.clone());
    let (regularity, injectivity) = match rotation {
        Some(Check::Exact) => (regularity, injectivity),
        Some(Check::Overlap) => {
            cert.geometry_conditional = true;
            (regularity, injectivity)
        }
        // the blocks are not S in another basis: nothing about its eigenvectors follows
        _ => {
            let why = "the rotation symmetry of S, which spreads the block eigenvector over the sectors, is not \
                       established"
                .to_string();
            (Verdict::NotProved(why.clone()), Verdict::NotProved(why))
        }
    };
    cert.regularity = regularity;
    cert.injectivity = injectivity;
    cert.c1 = combine(&cert.spectrum.verdict, &cert.regularity, &cert.injectivity);
    cert.conditional = cert.c1 == Verdict::Proved && cert.spectrum.conditional;
    Ok(cert)
}

/// Reif's criterion from its three parts: proved when all are, disproved
/// when one is.
pub(super) fn combine(spectrum: &Verdict, regularity: &Verdict, injectivity: &Verdict) -> Verdict {
    let parts = [("spectrum", spectrum), ("regularity", regularity), ("injectivity", injectivity)];
    if let Some((what, Verdict::Disproved(why))) = parts.iter().find(|(_, v)| matches!(v, Verdict::Disproved(_))) {
        return Verdict::Disproved(format!("{what}: {why}"));
    }
    if let Some((what, Verdict::NotProved(why))) = parts.iter().find(|(_, v)| matches!(v, Verdict::NotProved(_))) {
        return Verdict::NotProved(format!("{what}: {why}"));
    }
    Verdict::Proved
}

/// Regularity and injectivity, or the reason neither can be decided.
fn geometric_half(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    max_levels: usize,
    cert: &mut CharMapCertificate,
) -> Result<(Verdict, Verdict), String> {
    let level0 = certified_net(analysis, cert)?;
    let d = &analysis.discovered;
    // the host says whether its regular part is the non-box S_3^1 spline
    // (windows with face control vertices) or a box spline
    let non_box = scheme.topology().regular_spline() == RegularSpline::NonBoxS31;
    let mut last_reason = String::new();
    // one refinement for every level tried: level l's net continues level
    // l − 1's, and is the net `refine_net_exactly_as(.., l)` gives
    let mut nets = net::ExactLevels::<Interval, Point>::new(scheme, d, level0);
    for levels in 2..=max_levels {
        let net = nets.at(levels).map_err(|e| format!("the interval net could not be refined {levels} levels: {e}"))?;
        // two annuli (C4): the ring, and the ring scaled by λ1 (whose faces'
        // one-rings stay inside the first ring, as a dual scheme's outermost
        // faces' do not; its scaled copies leave quarter-face bands that the
        // biquadratic bound's half-face enlargement covers)
        let vf = net.mesh.vertex_faces();
        let annuli = annuli(net);
        // the ring's faces in orbits of the rotation (C3, C5′)
        let period = d.config.rotation_period(scheme);
        let mut chosen = None;
        for (ring, inside) in annuli.iter().filter(|(_, inside)| !inside.is_empty()) {
            let orbits = window_orbits::RingOrbits::new(net, ring, period);
            match ring_windows(net, &vf, ring, &orbits, non_box) {
                Ok(w) => {
                    chosen = Some((ring, inside, w, orbits));
                    break;
                }
                Err(why) => last_reason = format!("at {levels} levels: {why}"),
            }
        }
        let Some((mut ring, mut inside, mut windows, orbits)) = chosen else { continue };
        let mut lattice = None;
        // one window per rotation orbit: the others' entities are their
        // images, and their stencils the images of theirs (`window_orbits`)
        let mut orbit_rep = orbits.representative_of(ring.len());
        let to_check: Vec<&Window> = (0..ring.len()).filter(|&i| orbit_rep[i] == i).map(|i| &windows[i]).collect();
        let part = match check_rules(scheme, &net.mesh, &to_check) {
            Ok(part) => part,
            // no box spline over a triangle ring: the scheme's own regular
            // rules with the difference-scheme bounds (lemma C9), on the
            // first annulus whose larger windows lie on the net
            Err(box_spline) if net.mesh.face(ring[0]).len() == 3 => {
                let mut found = None;
                for (r, i) in annuli.iter().filter(|(_, inside)| !inside.is_empty()) {
                    match difference_windows(scheme, &net, r) {
                        Ok(w) => {
                            found = Some((r, i, w));
                            break;
                        }
                        Err(difference::RingFailure::Level(why)) => {
                            last_reason = format!("at {levels} levels: {box_spline}; difference-scheme bound: {why}")
                        }
                        Err(difference::RingFailure::Final(why)) => {
                            return Err(format!("{box_spline}; difference-scheme bound: {why}"))
                        }
                    }
                }
                let Some((r, i, (w, checked, bound))) = found else { continue };
                if !std::ptr::eq(r, ring) {
                    orbit_rep = window_orbits::representative_of(net, r, period);
                }
                (ring, inside, windows) = (r, i, w);
                lattice = Some(bound);
                (RegularPart::DifferenceScheme, checked)
            }
            Err(why) => return Err(why),
        };
        cert.regular_part = Some(part.0);
        cert.rules_checked = part.1;
        // the Jacobian bounded on the orbits' representatives only (lemma
        // C5′): a face's Jacobian is its representative's, so a sign proved
        // there is proved on the orbit, and the counts count every face
        let reps: Vec<usize> = (0..ring.len()).filter(|&i| orbit_rep[i] == i).collect();
        let mut group = vec![usize::MAX; ring.len()];
        for (k, &i) in reps.iter().enumerate() {
            group[i] = k;
        }
        let bounds: Vec<Interval> = reps.iter().map(|&i| windows[i].jacobian_bounds()).collect();
        let signs: Vec<i8> = bounds.iter().map(Interval::decided_sign).collect();
        let sign_of = |i: usize| signs[group[orbit_rep[i]]];
        let positive = (0..ring.len()).filter(|&i| sign_of(i) > 0).count();
        let negative = (0..ring.len()).filter(|&i| sign_of(i) < 0).count();
        let undecided = ring.len() - positive - negative;
        cert.levels = Some(levels);
        cert.ring_faces = ring.len();
        cert.positive_faces = positive;
        cert.negative_faces = negative;
        cert.undecided_faces = undecided;
        cert.max_point_width =
            Some(net.points.iter().flatten().map(|p| p[0].width().max(p[1].width())).fold(0.0, f64::max));
        cert.evidence = Some(Evidence {
            levels,
            lambda1_row: cert.spectrum.proof.as_ref().and_then(|p| p.lambda1_row).unwrap_or(usize::MAX),
            faces: windows
                .iter()
                .enumerate()
                .map(|(i, w)| FaceEvidence {
                    u_edges: w.u_pairs.clone(),
                    v_edges: w.v_pairs.clone(),
                    layout: w
                        .layout
                        .iter()
                        .filter(|(v, _)| w.u_pairs.iter().chain(&w.v_pairs).any(|&(a, b)| a == *v || b == *v))
                        .copied()
                        .collect(),
                    window: w.window.clone(),
                    sign: sign_of(i),
                })
                .collect(),
            winding: None,
            difference: lattice.clone(),
        });
        if positive > 0 && negative > 0 {
            // the witnesses quote the tightest bounds, the pairwise ones, of
            // two representatives (a bound on one is a bound on its orbit)
            let bounds: Vec<Interval> = reps.iter().map(|&i| windows[i].jacobian_pairwise_bound()).collect();
            let centre = |f: usize| {
                let face = net.mesh.face(f);
                let mut c = [0.0; 2];
                for &v in face {
                    let p = net.points[v].expect("window corners are defined");
                    c[0] += p[0].mid() / face.len() as f64;
                    c[1] += p[1].mid() / face.len() as f64;
                }
                c
            };
            let most = |better: &dyn Fn(&Interval, &Interval) -> bool| {
                let mut best: Option<usize> = None;
                for (i, b) in bounds.iter().enumerate() {
                    if best.is_none_or(|j| better(b, &bounds[j])) {
                        best = Some(i);
                    }
                }
                best.expect("some face decided")
            };
            let neg = most(&|a, b| a.hi < b.hi);
            let pos = most(&|a, b| a.lo > b.lo);
            cert.fold_witness = Some(FoldWitness {
                negative_at: centre(ring[reps[neg]]),
                negative_upper_bound: bounds[neg].hi,
                positive_at: centre(ring[reps[pos]]),
                positive_lower_bound: bounds[pos].lo,
            });
            let why = format!(
                "at {levels} levels the Jacobian is proved positive on {positive} ring faces and negative on \
                 {negative}: it changes sign"
            );
            cert.reasons.push(why.clone());
            return Ok((Verdict::Disproved(why.clone()), Verdict::Disproved(format!("not regular ({why})"))));
        }
        if undecided > 0 {
            last_reason = format!(
                "at {levels} levels the Jacobian's sign is undecided on {undecided} of {} ring faces",
                ring.len()
            );
            continue;
        }
        let sign = if negative > 0 { -1.0 } else { 1.0 };
        // over the representatives: their bounds hold on their orbits
        record_margins(cert, net, &bounds, sign, scheme.topology().faces_per_face());
        let regular = format!(
            "the Jacobian is proved {} on all {} ring faces at {levels} levels ({} rules)",
            if sign > 0.0 { "positive" } else { "negative" },
            ring.len(),
            part.0.describe()
        );
        let regular = if std::ptr::eq(ring, &annuli[1].0) {
            format!("{regular}; the annulus is the ring scaled by λ1 (the ring's outer faces' one-rings leave the neighbourhood)")
        } else {
            regular
        };
        cert.reasons.push(regular);
        let winding = winding_number(net, ring, inside, &windows);
        if let (Ok((_, e)), Some(evidence)) = (&winding, cert.evidence.as_mut()) {
            evidence.winding = Some(e.clone());
        }
        let injective = match winding.map(|(w, _)| w) {
            Ok(w) if w == sign as i64 => {
                cert.winding_number = Some(w);
                cert.reasons.push(format!("the annulus's inner boundary winds {w} time around the centre"));
                Verdict::Proved
            }
            Ok(w) => {
                cert.winding_number = Some(w);
                Verdict::Disproved(format!(
                    "the map is regular but its winding number is {w}: it covers the neighbourhood of the centre {} \
                     times",
                    w.abs()
                ))
            }
            // a finer net has smaller windows, whose hulls may then clear the centre
            Err(why) if levels < max_levels => {
                cert.reasons.pop();
                last_reason = format!("at {levels} levels the winding number is not certified: {why}");
                continue;
            }
            Err(why) => Verdict::NotProved(format!("the winding number is not certified: {why}")),
        };
        return Ok((Verdict::Proved, injective));
    }
    // nothing decided: no evidence of an earlier, undecided level is kept
    cert.evidence = None;
    Err(last_reason)
}

/// The two annuli of lemma C4, each as (ring faces, faces inside them): the
/// ring (`outer` ∧ ¬`inner`), and the ring scaled by λ1 (`inner` ∧
/// ¬`inner2`), whose faces' one-rings stay inside the first ring.
fn annuli<T>(net: &Net<T>) -> [(Vec<usize>, Vec<usize>); 2] {
    let faces = |keep: &dyn Fn(usize) -> bool| (0..net.mesh.num_faces()).filter(|&f| keep(f)).collect::<Vec<_>>();
    [
        (faces(&|f| net.outer[f] && !net.inner[f]), faces(&|f| net.outer[f] && net.inner[f])),
        (faces(&|f| net.inner[f] && !net.inner2[f]), faces(&|f| net.inner2[f])),
    ]
}

/// Every ring face's window: laid out (`Window::around`) on each orbit's
/// representative and turned from it onto the orbit's other faces, one
/// turn at a time (lemma C5′: the rotation is a checked automorphism of the
/// net, so a turned layout is a layout of the image face, starting at the
/// image of the representative's first corner). The document lists each
/// face's window so; the checker takes its edges as listed.
fn ring_windows(
    net: &Net<Point>,
    vf: &[Vec<usize>],
    ring: &[usize],
    orbits: &window_orbits::RingOrbits,
    non_box: bool,
) -> Result<Vec<Window>, String> {
    let mut out: Vec<Option<Window>> = (0..ring.len()).map(|_| None).collect();
    for orbit in &orbits.orbits {
        let mut window = Window::around(net, vf, ring[orbit[0]], non_box)?;
        for (k, &p) in orbit.iter().enumerate() {
            let next = if k + 1 < orbit.len() { Some(window.turned(net, orbits)?) } else { None };
            out[p] = Some(window);
            match next {
                Some(w) => window = w,
                None => break,
            }
        }
    }
    Ok(out.into_iter().map(|w| w.expect("the orbits cover the ring")).collect())
}

/// The ring's windows for lemma C9 (`certify::difference`): per face its
/// own edges, the Jacobian bound (refined on the window where undecided) and the hull radius δ from
/// the window's second differences and the lattice constants.
fn difference_windows(
    scheme: &dyn Scheme,
    net: &Net<Point>,
    ring: &[usize],
) -> Result<(Vec<Window>, usize, std::sync::Arc<difference::LatticeBound>), difference::RingFailure> {
    use difference::RingFailure;
    let bound =
        difference::lattice_bound(scheme).map_err(|why| RingFailure::Final(format!("numerical only: {why}")))?;
    let (ring_windows, checked) = difference::ring_windows(scheme, &bound, &net.mesh, ring)?;
    let mut out = Vec::with_capacity(ring_windows.len());
    for rw in ring_windows {
        let p = |v: usize| net.points[v].ok_or_else(|| RingFailure::Level("a window point is not determined".into()));
        let values: Vec<Point> = rw.vertices.iter().map(|&v| p(v)).collect::<Result<_, _>>()?;
        let (_, radius) = difference::face_bounds(&bound, 0, &values);
        let jacobian = difference::jacobian(&bound, 0, &values, difference::DEPTH);
        let face = net.mesh.face(rw.face);
        let (a, b, c) = (face[0], face[1], face[2]);
        let diff = |from: Point, to: Point| [to[0] - from[0], to[1] - from[1]];
        let (u, v) = (diff(p(a)?, p(b)?), diff(p(a)?, p(c)?));
        out.push(Window {
            face: rw.face,
            faces: vec![rw.face],
            along_u: vec![u],
            along_v: vec![v],
            points: vec![p(a)?, p(b)?, p(c)?],
            ids: vec![a, b, c],
            u_pairs: vec![(a, b)],
            v_pairs: vec![(a, c)],
            layout: Vec::new(),
            jacobian: Some(jacobian),
            radius,
            window: bound.windows[0].iter().zip(&rw.vertices).map(|(l, &v)| (v, [l.0, l.1])).collect(),
        });
    }
    Ok((out, checked, bound))
}

fn record_margins(cert: &mut CharMapCertificate, net: &Net<Point>, bounds: &[Interval], sign: f64, area_factor: usize) {
    let lower = bounds.iter().map(|b| if sign > 0.0 { b.lo } else { -b.hi }).fold(f64::INFINITY, f64::min);
    let upper = bounds.iter().map(|b| if sign > 0.0 { b.hi } else { -b.lo }).fold(0.0, f64::max);
    // the ring's points lie within radius R (R² bounded above); each
    // refinement divides a face's parameter area by the host's faces per face
    // (4 dyadic, 9 ternary), and the Jacobian in level-0 parameters
    // multiplies by as much
    let radius_squared = net
        .outer
        .iter()
        .enumerate()
        .filter(|(_, &o)| o)
        .flat_map(|(f, _)| net.mesh.face(f).iter())
        .filter_map(|&v| net.points[v])
        .map(|p| (p[0].square() + p[1].square()).hi)
        .fold(0.0, f64::max);
    if radius_squared > 0.0 {
        // a lower bound in interval arithmetic: lower · factorᴸ / R² rounded down
        let factor = (0..net.refinements).fold(Interval::point(1.0), |s, _| s * Interval::point(area_factor as f64));
        let bound = Interval::point(lower) * factor / Interval::point(radius_squared);
        cert.min_jacobian_lower_bound = Some(bound.lo.max(0.0));
    }
    if upper > 0.0 {
        cert.min_jacobian_ratio = Some(lower / upper);
    }
}

/// The level-0 net of enclosures of the subdominant pair: the eigenvector
/// of the disc that the spectral certificate proved to hold λ1 (in block 1's
/// verified diagonalisation, the one the proof enclosed), never one chosen by
/// a floating-point eigenvalue.
fn certified_net(analysis: &Analysis, cert: &mut CharMapCertificate) -> Result<Vec<Option<Point>>, String> {
    let spectrum = &cert.spectrum;
    if spectrum.verdict != Verdict::Proved {
        return Err("the spectrum is not proved, so λ1 and its eigenvectors are not known".into());
    }
    let proof = spectrum.proof.as_ref().ok_or("the spectral certificate hands on no proof data")?;
    let orbits = &proof.orbits;
    let g = orbits.group_order;
    // PROVED: λ1 is the simple leading eigenvalue of block 1 (and of g − 1)
    let m = 1;
    let row = proof.lambda1_row.ok_or("the spectral certificate names no disc for λ1")?;
    let diagonalisation = spectrum
        .blocks
        .iter()
        .find(|b| b.block == m)
        .and_then(|b| b.diagonalisation.as_ref())
        .ok_or("block 1's verified diagonalisation is missing")?;
    let (z, radius) = eigenvector(diagonalisation, row)
        .map_err(|why| format!("the subdominant eigenvector of block {m} is not enclosed: {why}"))?;
    cert.eigenvector_radius = Some(radius);
    let list = orbits.block_orbits(m);
    let mut pos = vec![usize::MAX; orbits.num_orbits()];
    for (k, &o) in list.iter().enumerate() {
        pos[o] = k;
    }
    let powers: Vec<CInterval> = (0..g)
        .map(|t| {
            let (c, s) = crate::numeric::interval::cos_sin_2pi(t as i64, g as i64);
            CInterval::new(c, s)
        })
        .collect();
    // x₍ₜ,ₐ₎ = ω^(mt)·zₐ: block m of S in the basis Σₜ ω^(mt) e₍ₜ,ₐ₎ (`fourier_blocks`)
    let values: Vec<Point> = orbits
        .member
        .iter()
        .map(|&(o, t)| {
            if orbits.fixed[o] {
                [Interval::point(0.0); 2]
            } else {
                let x = powers[(m * t) % g] * z[pos[o]];
                [x.re, x.im]
            }
        })
        .collect();
    let d = &analysis.discovered;
    let mut pts = vec![None; d.patch.num_vertices()];
    for (k, &v) in d.analysis.iter().enumerate() {
        pts[v] = Some(values[k]);
    }
    Ok(pts)
}

/// A ring face with its one-ring of faces laid out on the lattice: the
/// corners of the face get (0,0), (1,0), (1,1), (0,1) (triangles: (0,0),
/// (1,0), (0,1)), and every window vertex its lattice position.
#[derive(Default)]
pub(super) struct Window {
    pub(super) face: usize,
    pub(super) faces: Vec<usize>,
    /// edge vectors along (1, 0) and along (0, 1)
    pub(super) along_u: Vec<Point>,
    pub(super) along_v: Vec<Point>,
    /// every window point, for hulls
    pub(super) points: Vec<Point>,
    /// the net vertices of `points`, in the same (ascending) order
    pub(super) ids: Vec<usize>,
    /// the same edges as net vertex pairs (from, to), for the certificate
    /// document, whose checker recomputes the edge vectors itself
    pub(super) u_pairs: Vec<(usize, usize)>,
    pub(super) v_pairs: Vec<(usize, usize)>,
    /// non-box windows only (empty otherwise): every window point with its
    /// lattice position in half units (V-vertices even, FCVs odd; the ring
    /// face is [0, 2]²), for the rule check and the certificate document
    pub(super) layout: Vec<(usize, [i64; 2])>,
    /// difference-scheme windows only (None, 0 otherwise): the Jacobian
    /// over the face proved to lie in `jacobian` (lemma C9, not the edge
    /// vectors' range), and the face's image within `radius` of the hull of
    /// `points`
    pub(super) jacobian: Option<Interval>,
    pub(super) radius: f64,
    /// difference-scheme windows only: the window on the lattice
    pub(super) window: Vec<(usize, [i64; 2])>,
}

/// A window's vertices with their lattice positions: at most 16, so a
/// vector searched in order (the windows are built by the thousand, and a
/// hash map per window cost more than the search).
pub(super) struct LatticeLayout(pub(super) Vec<(usize, (i32, i32))>);

impl LatticeLayout {
    pub(super) fn get(&self, v: usize) -> Option<(i32, i32)> {
        self.0.iter().find(|&&(w, _)| w == v).map(|&(_, c)| c)
    }
    /// The position of a vertex laid out already.
    pub(super) fn at(&self, v: usize) -> (i32, i32) {
        self.get(v).expect("a laid-out window vertex")
    }
    /// The position of `v`, given `c` if it has none yet.
    pub(super) fn get_or_insert(&mut self, v: usize, c: (i32, i32)) -> (i32, i32) {
        self.get(v).unwrap_or_else(|| {
            self.0.push((v, c));
            c
        })
    }
}

impl Window {
    fn around(net: &Net<Point>, vf: &[Vec<usize>], f: usize, non_box: bool) -> Result<Window, String> {
        let mesh = &net.mesh;
        let face = mesh.face(f);
        let m = face.len();
        // face control vertices: Huang's non-box S_3^1 spline (quads only)
        let fcv = non_box;
        if fcv && m != 4 {
            return Err(format!("a ring face with a face control vertex has {m} sides"));
        }
        let (valence, corners): (usize, &[(i32, i32)]) = match m {
            4 => (4, &[(0, 0), (1, 0), (1, 1), (0, 1)]),
            3 => (6, &[(0, 0), (1, 0), (0, 1)]),
            _ => return Err(format!("a ring face has {m} sides")),
        };
        for &c in face {
            if vf[c].len() != valence || vf[c].iter().any(|&g| mesh.face(g).len() != m) {
                return Err("a ring face has a corner that is not regular".into());
            }
        }
        let mut faces: Vec<usize> = face.iter().flat_map(|&c| vf[c].iter().copied()).collect();
        faces.sort_unstable();
        faces.dedup();
        let expected = if m == 4 { 9 } else { 13 };
        if faces.len() != expected {
            return Err("a ring face's one-ring of faces is not a regular grid".into());
        }
        // the next edge of a face turns by 90° (quads) or 120° (triangles,
        // in lattice coordinates whose third direction is (−1, 1))
        let turn = |(x, y): (i32, i32)| if m == 4 { (-y, x) } else { (-x - y, x) };
        let mut coords = LatticeLayout(face.iter().copied().zip(corners.iter().copied()).collect());
        // which of the one-ring's faces are laid out (`faces` is sorted)
        let mut placed: Vec<bool> = faces.iter().map(|&g| g == f).collect();
        let conflict = || "a ring face's one-ring of faces does not lie on one lattice".to_string();
        while placed.iter().any(|&p| !p) {
            let mut progress = false;
            for (slot, &g) in faces.iter().enumerate() {
                if placed[slot] {
                    continue;
                }
                let gf = mesh.face(g);
                let Some(k) = (0..m).find(|&k| coords.get(gf[k]).is_some() && coords.get(gf[(k + 1) % m]).is_some())
                else {
                    continue;
                };
                let (a, b) = (coords.at(gf[k]), coords.at(gf[(k + 1) % m]));
                let e = (b.0 - a.0, b.1 - a.1);
                let t = turn(e);
                let mut next = vec![(gf[(k + 2) % m], (b.0 + t.0, b.1 + t.1))];
                if m == 4 {
                    next.push((gf[(k + 3) % m], (a.0 + t.0, a.1 + t.1)));
                }
                for (v, c) in next {
                    if coords.get_or_insert(v, c) != c {
                        return Err(conflict());
                    }
                }
                placed[slot] = true;
                progress = true;
            }
            if !progress {
                return Err(conflict());
            }
        }
        let mut distinct: Vec<(i32, i32)> = coords.0.iter().map(|&(_, c)| c).collect();
        distinct.sort_unstable();
        distinct.dedup();
        if distinct.len() != coords.0.len() || coords.0.len() != if m == 4 { 16 } else { 12 } {
            return Err(conflict());
        }
        let p = |v: usize| net.points[v].ok_or_else(|| "a window point is not determined".to_string());
        if fcv {
            return Window::non_box(net, f, faces, &coords);
        }
        // each lattice edge once: an inner edge of the 3 × 3 block borders
        // two of its faces, and a repeated difference would only repeat
        // pairs in the pairwise Jacobian bound (the same hull, at up to
        // 18 × 18 products instead of 12 × 12)
        let (mut u_pairs, mut v_pairs) = (Vec::new(), Vec::new());
        for &g in &faces {
            let gf = mesh.face(g);
            for k in 0..m {
                let (a, b) = (gf[k], gf[(k + 1) % m]);
                let (ca, cb) = (coords.at(a), coords.at(b));
                let (pairs, edge) = match (cb.0 - ca.0, cb.1 - ca.1) {
                    (1, 0) => (&mut u_pairs, (a, b)),
                    (-1, 0) => (&mut u_pairs, (b, a)),
                    (0, 1) => (&mut v_pairs, (a, b)),
                    (0, -1) => (&mut v_pairs, (b, a)),
                    _ => continue,
                };
                if !pairs.contains(&edge) {
                    pairs.push(edge);
                }
            }
        }
        let diff = |&(from, to): &(usize, usize)| -> Result<Point, String> {
            let (from, to) = (p(from)?, p(to)?);
            Ok([to[0] - from[0], to[1] - from[1]])
        };
        let along_u = u_pairs.iter().map(diff).collect::<Result<Vec<_>, String>>()?;
        let along_v = v_pairs.iter().map(diff).collect::<Result<Vec<_>, String>>()?;
        // in vertex order: the half-plane direction sums these points'
        // midpoints, and a hash order would change its last bits run to run
        let mut ids: Vec<usize> = coords.0.iter().map(|&(v, _)| v).collect();
        ids.sort_unstable();
        let points = ids.iter().map(|&v| p(v)).collect::<Result<Vec<_>, String>>()?;
        Ok(Window { face: f, faces, along_u, along_v, points, ids, u_pairs, v_pairs, ..Window::default() })
    }

    /// The window of a ring face of the non-box S_3^1 spline (lemma C3′ of
    /// ARCHITECTURE.md, `certify::s31` for the convention): `coords` lays out
    /// the 16 V-vertices of the face's one-ring of 9 faces, the face at
    /// [0, 1]². The FCVs sit at the 9 faces' centres.
    ///
    /// ∂_u f = Σ_m d_m ψ(· − m) over the horizontal differences d_m of
    /// control points of one kind at distance 1 (midpoint m), with
    /// ψ = φ * χ^v ≥ 0 (χ^v the unit segment along v) and Σ_m ψ(· − m) = 1.
    /// The open support of ψ is m + (−½, ½) × (−1, 1) for V–V differences and
    /// {|x₁ − m₁| < 1, |x₁ − m₁| + |x₂ − m₂| < 3/2} for FCV–FCV ones; those
    /// meeting the closed face [0, 1]² are its own two u-edges and the six
    /// u-differences among the 9 FCVs (m₁ ∈ {0, 1}, m₂ ∈ {−½, ½, 3/2}); v
    /// likewise. The hull: B_V's open support (−1, 1)² about the V-vertex and
    /// B_F's octagon {|·|∞ < 3/2, |·|₁ < 2} about the FCV meet the face for
    /// its 4 corners and the 9 FCVs only.
    fn non_box(net: &Net<Point>, f: usize, faces: Vec<usize>, coords: &LatticeLayout) -> Result<Window, String> {
        let mesh = &net.mesh;
        // half units: V-vertices at even, FCVs at odd coordinates
        let mut layout: Vec<(usize, [i64; 2])> =
            coords.0.iter().map(|&(v, (x, y))| (v, [2 * x as i64, 2 * y as i64])).collect();
        for &g in &faces {
            let fp = mesh.face_point(g).ok_or("a face of a ring face's one-ring has no face control vertex")?;
            let sum = mesh
                .face(g)
                .iter()
                .fold([0i64; 2], |s, &v| [s[0] + 2 * coords.at(v).0 as i64, s[1] + 2 * coords.at(v).1 as i64]);
            layout.push((fp, [sum[0] / 4, sum[1] / 4]));
        }
        layout.sort_unstable();
        let at: HashMap<[i64; 2], usize> = layout.iter().map(|&(v, c)| (c, v)).collect();
        let id = |c: [i64; 2]| at.get(&c).copied().ok_or_else(|| "a non-box window point is missing".to_string());
        let p = |v: usize| net.points[v].ok_or_else(|| "a window point is not determined".to_string());
        let diff = |a: usize, b: usize| -> Result<Point, String> {
            let (from, to) = (p(a)?, p(b)?);
            Ok([to[0] - from[0], to[1] - from[1]])
        };
        let (mut along_u, mut along_v) = (Vec::new(), Vec::new());
        let (mut u_pairs, mut v_pairs) = (Vec::new(), Vec::new());
        // the face's own V–V edges, then the FCV–FCV differences
        let mut u_from: Vec<[i64; 2]> = vec![[0, 0], [0, 2]];
        let mut v_from: Vec<[i64; 2]> = vec![[0, 0], [2, 0]];
        for a in [-1, 1] {
            for b in [-1, 1, 3] {
                u_from.push([a, b]);
                v_from.push([b, a]);
            }
        }
        for c in u_from {
            let (a, b) = (id(c)?, id([c[0] + 2, c[1]])?);
            along_u.push(diff(a, b)?);
            u_pairs.push((a, b));
        }
        for c in v_from {
            let (a, b) = (id(c)?, id([c[0], c[1] + 2])?);
            along_v.push(diff(a, b)?);
            v_pairs.push((a, b));
        }
        let hull: Vec<usize> = layout
            .iter()
            .filter(|(_, c)| (c[0] % 2 != 0) || ((0..=2).contains(&c[0]) && (0..=2).contains(&c[1])))
            .map(|&(v, _)| v)
            .collect();
        let points = hull.iter().map(|&v| p(v)).collect::<Result<Vec<_>, String>>()?;
        Ok(Window {
            face: f,
            faces,
            along_u,
            along_v,
            points,
            ids: hull,
            u_pairs,
            v_pairs,
            layout,
            ..Window::default()
        })
    }

    /// The window of the image of this window's face under the rotation of
    /// `orbits`: every vertex turned, lattice positions kept, the edge
    /// vectors and points read at the turned vertices (in ascending order,
    /// as `around` and `non_box` list them: the winding's half-plane sums
    /// their midpoints in that order).
    fn turned(&self, net: &Net<Point>, orbits: &window_orbits::RingOrbits) -> Result<Window, String> {
        let mesh = &net.mesh;
        let lost = || "a window vertex has no image under the rotation".to_string();
        let t = |v: usize| orbits.turned(v).ok_or_else(lost);
        let face_of = |g: usize| -> Result<usize, String> {
            let gf = mesh.face(g);
            mesh.half_edge(t(gf[0])?, t(gf[1])?).map(|(h, _)| h).ok_or_else(lost)
        };
        let p = |v: usize| net.points[v].ok_or_else(|| "a window point is not determined".to_string());
        let pairs = |edges: &[(usize, usize)]| -> Result<Vec<(usize, usize)>, String> {
            edges.iter().map(|&(a, b)| Ok((t(a)?, t(b)?))).collect()
        };
        let diff = |&(from, to): &(usize, usize)| -> Result<Point, String> {
            let (from, to) = (p(from)?, p(to)?);
            Ok([to[0] - from[0], to[1] - from[1]])
        };
        let (u_pairs, v_pairs) = (pairs(&self.u_pairs)?, pairs(&self.v_pairs)?);
        let along_u = u_pairs.iter().map(diff).collect::<Result<Vec<_>, String>>()?;
        let along_v = v_pairs.iter().map(diff).collect::<Result<Vec<_>, String>>()?;
        let mut ids = self.ids.iter().map(|&v| t(v)).collect::<Result<Vec<_>, String>>()?;
        ids.sort_unstable();
        let points = ids.iter().map(|&v| p(v)).collect::<Result<Vec<_>, String>>()?;
        let mut layout = self.layout.iter().map(|&(v, c)| Ok((t(v)?, c))).collect::<Result<Vec<_>, String>>()?;
        layout.sort_unstable();
        let mut faces = self.faces.iter().map(|&g| face_of(g)).collect::<Result<Vec<_>, String>>()?;
        faces.sort_unstable();
        Ok(Window {
            face: face_of(self.face)?,
            faces,
            along_u,
            along_v,
            points,
            ids,
            u_pairs,
            v_pairs,
            layout,
            ..Window::default()
        })
    }

    /// An enclosure of the range of det(uᵢ, vⱼ) over the window's edge
    /// vectors (the Jacobian over the face lies in it); the whole line when
    /// a bound is not finite, which decides no sign.
    pub(super) fn jacobian_bounds(&self) -> Interval {
        if let Some(j) = self.jacobian {
            return if j.is_finite() { j } else { Interval::new(f64::NEG_INFINITY, f64::INFINITY) };
        }
        // First a cheap enclosure: the hull of the v-edges, paired with each
        // u-edge (2·|U| products instead of 2·|U|·|V|). It contains every
        // det(u, v), so a sign it decides is the sign the pairwise bound
        // decides (which lies inside it); only an undecided face pays for
        // the pairwise bound, which keeps the correlation within each pair.
        if let Some(cheap) = self.jacobian_hull_bound() {
            if cheap.lo > 0.0 || cheap.hi < 0.0 {
                return cheap;
            }
        }
        self.jacobian_pairwise_bound()
    }

    /// An enclosure of det(u, v) over u ∈ `along_u` and v in the hull of
    /// `along_v` (None when a bound is not finite).
    fn jacobian_hull_bound(&self) -> Option<Interval> {
        let first = self.along_v.first()?;
        let (mut v0, mut v1) = (first[0], first[1]);
        for v in &self.along_v[1..] {
            v0 = v0.hull(&v[0]);
            v1 = v1.hull(&v[1]);
        }
        let mut out: Option<Interval> = None;
        for u in &self.along_u {
            let det = u[0] * v1 - u[1] * v0;
            out = Some(out.map_or(det, |o| o.hull(&det)));
        }
        out.filter(|j| j.lo.is_finite() && j.hi.is_finite())
    }

    /// The pairwise enclosure: the hull over every pair (u, v) of the
    /// window's edge vectors of det(u, v); the whole line when a bound is
    /// not finite, which decides no sign.
    fn jacobian_pairwise_bound(&self) -> Interval {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for u in &self.along_u {
            for v in &self.along_v {
                let det = u[0] * v[1] - u[1] * v[0];
                lo = lo.min(det.lo);
                hi = hi.max(det.hi);
            }
        }
        if lo.is_finite() && hi.is_finite() {
            Interval::new(lo, hi)
        } else {
            Interval::new(f64::NEG_INFINITY, f64::INFINITY)
        }
    }
}

/// Check the rules at every regular entity the windows hold against one
/// box spline's masks, exactly. Each entity's stencil must equal the mask of
/// at least one candidate box spline, and one box spline must fit every
/// entity (the candidates are intersected: the bicubic B-spline and A_4
/// share their edge and face masks and differ at vertices). Returns the box
/// spline and the number of stencils compared.
fn check_rules(scheme: &dyn Scheme, mesh: &PolyMesh, windows: &[&Window]) -> Result<(RegularPart, usize), String> {
    if windows.iter().any(|w| !w.layout.is_empty()) {
        return check_non_box_rules(scheme, mesh, windows);
    }
    let mut corners: IdSet<usize> = IdSet::default();
    let mut faces: IdSet<usize> = IdSet::default();
    for w in windows {
        corners.extend(mesh.face(w.face).iter().copied());
        faces.extend(w.faces.iter().copied());
    }
    let origins = origins_over(scheme, mesh, &faces)?;
    let vf = mesh.vertex_faces();
    let ternary = scheme.topology().regular_spline() == RegularSpline::TernaryPrimal;
    let mut fitting: Option<Vec<RegularPart>> = None;
    let mut checked = 0;
    for origin in origins {
        let masks: Vec<(RegularPart, Mask)> = match origin {
            Origin::Vertex(v) if corners.contains(&v) => vertex_masks(mesh, &vf, v, ternary)?,
            Origin::Edge(a, b) if corners.contains(&a) || corners.contains(&b) => {
                let (kind, mask) = edge_mask(mesh, &vf, a, b, ternary)?;
                let shared = kind == RegularPart::BicubicBSpline;
                let mut all = vec![(kind, mask.clone())];
                if shared {
                    all.push((RegularPart::FourDirectionBoxSpline, mask));
                }
                all
            }
            Origin::Face(g) if faces.contains(&g) => {
                let gf = mesh.face(g);
                if gf.len() != 4 {
                    return Err("a face rule on triangles is not a box-spline rule this certificate knows".into());
                }
                let mask: Mask = gf.iter().map(|&v| (v, SmallRational::ratio(1, 4))).collect();
                vec![(RegularPart::BicubicBSpline, mask.clone()), (RegularPart::FourDirectionBoxSpline, mask)]
            }
            Origin::Corner { face: g, corner: k } if faces.contains(&g) => {
                let gf = mesh.face(g);
                if gf.len() != 4 {
                    return Err("a corner rule of a non-quad is not a box-spline rule this certificate knows".into());
                }
                // dual: (3, 1)²/16 over the face; ternary: the interior
                // point near corner k, (6, 3)²/81
                let (kind, mask, denominator) = if ternary {
                    (RegularPart::BiquadraticBSplineTernary, [(0, 36), (1, 18), (2, 9), (3, 18)], 81)
                } else {
                    (RegularPart::BiquadraticBSpline, [(0, 9), (1, 3), (2, 1), (3, 3)], 16)
                };
                vec![(
                    kind,
                    mask.iter().map(|&(s, w)| (gf[(k + s) % 4], SmallRational::ratio(w, denominator))).collect(),
                )]
            }
            _ => continue,
        };
        let got = exact_stencil(scheme, mesh, origin)?;
        let matching: Vec<RegularPart> = masks.iter().filter(|(_, m)| *m == got).map(|(k, _)| *k).collect();
        let before = fitting.get_or_insert_with(|| masks.iter().map(|(k, _)| *k).collect());
        before.retain(|k| matching.contains(k));
        if before.is_empty() {
            let names: Vec<&str> = masks.iter().map(|(k, _)| k.describe()).collect();
            return Err(format!(
                "numerical only: the rules over the ring are not one box spline's (at {origin:?} the stencil is not \
                 the mask of the {} that fits the other entities), so the ring is not a box spline of its net",
                names.join(" or ")
            ));
        }
        checked += 1;
    }
    match fitting.as_deref() {
        Some([one, ..]) => Ok((*one, checked)),
        _ => Err("no rule over the ring was recognised".to_string()),
    }
}

/// The origins of the new points that one refinement of `mesh` makes over
/// the faces `faces`, in the order the refinement of the whole mesh lists
/// them. Only the entities at the windows are checked, so only the windows'
/// faces are refined (the refinement of the whole net, four or nine times
/// its faces, was most of the rule check's cost); the sub-mesh keeps the
/// vertex ids, and its faces map back through `keep`. An edge at a window's
/// corner has both its faces in the window (the window holds every face at
/// its corners), so it is interior to the sub-mesh and named as in the whole
/// mesh.
fn origins_over(scheme: &dyn Scheme, mesh: &PolyMesh, faces: &IdSet<usize>) -> Result<Vec<Origin>, String> {
    let mut keep: Vec<usize> = faces.iter().copied().collect();
    keep.sort_unstable();
    let refused = |e: Error| format!("the net could not be refined: {e}");
    let sub = mesh.keep_faces(&keep).map_err(refused)?;
    let refined = connectivity(scheme, &sub).map_err(refused)?;
    Ok(refined
        .vertex_origins
        .into_iter()
        .map(|o| match o {
            Origin::Face(f) => Origin::Face(keep[f]),
            Origin::Corner { face, corner } => Origin::Corner { face: keep[face], corner },
            o @ (Origin::Vertex(_) | Origin::Edge(..)) => o,
        })
        .collect())
}

/// A stencil or mask: weight per control point, exact in machine integers
/// (every mask weight is a small fraction; a stencil weight that does not
/// fit is kept spoiled, and a spoiled weight equals no mask weight).
pub(super) type Mask = IdMap<usize, SmallRational>;

/// The scheme's rational stencil at `origin`, repeated points merged and
/// zero weights dropped. Computed in machine-integer rationals first (the
/// rule check asks for tens of thousands of stencils per valence, and big
/// rationals allocate and reduce at every product); a term that left the
/// machine integers is recomputed in big rationals, so the result is the
/// exact stencil either way.
pub(super) fn exact_stencil(scheme: &dyn Scheme, mesh: &PolyMesh, origin: Origin) -> Result<Mask, String> {
    let irrational = |_| "a rule over the ring has an irrational weight".to_string();
    // the gatherer's reason names what the net lacks (a truncated margin, a
    // face the host's rules do not cover)
    let missing = |cause: GatherError| format!("a rule over the ring cannot be evaluated on the net: {cause}");
    // `stencil_at` gives the stencil merged (repeated points summed, zeros
    // dropped), so it only has to be keyed by point here
    let small = stencil_at::<SmallRational>(scheme, mesh, origin).map_err(irrational)?.map_err(missing)?;
    if small.terms.iter().all(|(_, w)| !w.is_spoiled()) {
        return Ok(small.terms.into_iter().collect());
    }
    // an intermediate left the machine integers: the big rationals decide,
    // and a final weight that still does not fit stays spoiled
    let big = stencil_at::<Rational>(scheme, mesh, origin).map_err(irrational)?.map_err(missing)?;
    Ok(big.terms.iter().map(|(v, w)| (*v, SmallRational::from_rational(w))).collect())
}

/// The rule check for non-box windows: every new point that the limit over
/// a ring face depends on after one step — its corners' V-vertex rules, the
/// E-vertex rules of the edges at its corners, the FCV rules of the one-ring's
/// faces and the NFCV rules of their quads at the face's corners (the new
/// face's corners and the 3×3 new FCVs around it, lemma C3′) — compared
/// exactly with the mask derived from the S_3^1 spline's definition
/// (`s31::mask`), laid out by the window's lattice positions. The one-ring
/// of the new faces is again regular, so by the rules' locality the same
/// comparison holds at every later level.
fn check_non_box_rules(
    scheme: &dyn Scheme,
    mesh: &PolyMesh,
    windows: &[&Window],
) -> Result<(RegularPart, usize), String> {
    // per origin of interest, the window whose layout places it (any one:
    // the derived mask is symmetric under the lattice's rotations and
    // reflections, so every window that holds it gives the same mask)
    let mut vertex: HashMap<usize, usize> = HashMap::new();
    let mut edge: HashMap<(usize, usize), usize> = HashMap::new();
    let mut face: HashMap<usize, usize> = HashMap::new();
    let mut corner: HashMap<(usize, usize), usize> = HashMap::new();
    for (i, w) in windows.iter().enumerate() {
        if w.layout.is_empty() {
            return Err("the ring mixes faces with and without face control vertices".into());
        }
        let own = mesh.face(w.face);
        for &c in own {
            vertex.entry(c).or_insert(i);
        }
        for &g in &w.faces {
            face.entry(g).or_insert(i);
            let gf = mesh.face(g);
            for k in 0..gf.len() {
                let (a, b) = (gf[k], gf[(k + 1) % gf.len()]);
                if own.contains(&a) || own.contains(&b) {
                    edge.entry((a.min(b), a.max(b))).or_insert(i);
                }
                if own.contains(&a) {
                    corner.entry((g, k)).or_insert(i);
                }
            }
        }
    }
    let refined = connectivity(scheme, mesh).map_err(|e| format!("the net could not be refined: {e}"))?;
    let mut checked = 0;
    for &origin in &refined.vertex_origins {
        let window = match origin {
            Origin::Vertex(v) => vertex.get(&v),
            Origin::Edge(a, b) => edge.get(&(a.min(b), a.max(b))),
            Origin::Face(g) => face.get(&g),
            Origin::Corner { face: g, corner: k } => corner.get(&(g, k)),
        };
        let Some(&i) = window else { continue };
        let w = &windows[i];
        // quarter units of the coarse lattice (`s31`): twice the half units
        let quarter: HashMap<usize, (i64, i64)> = w.layout.iter().map(|&(v, c)| (v, (2 * c[0], 2 * c[1]))).collect();
        let at: HashMap<(i64, i64), usize> = quarter.iter().map(|(&v, &c)| (c, v)).collect();
        let q =
            |v: usize| quarter.get(&v).copied().ok_or_else(|| "a rule's entity lies outside its window".to_string());
        let mid = |a: (i64, i64), b: (i64, i64)| ((a.0 + b.0) / 2, (a.1 + b.1) / 2);
        let new = match origin {
            Origin::Vertex(v) => q(v)?,
            Origin::Edge(a, b) => mid(q(a)?, q(b)?),
            Origin::Face(g) => q(mesh.face_point(g).ok_or("a window face has no face control vertex")?)?,
            Origin::Corner { face: g, corner: k } => {
                mid(q(mesh.face(g)[k])?, q(mesh.face_point(g).ok_or("a window face has no face control vertex")?)?)
            }
        };
        let derived = s31::mask(new).ok_or("a new point is not at a control position of the S_3^1 lattice")?;
        let mut expected = Mask::default();
        for (p, weight) in derived {
            let &v = at.get(&p).ok_or("the S_3^1 mask reaches beyond the window")?;
            expected.insert(v, SmallRational::from_rational(&weight));
        }
        if exact_stencil(scheme, mesh, origin)? != expected {
            return Err(format!(
                "numerical only: at {origin:?} the stencil is not the four-directional S_3^1 spline's refinement \
                 mask, so the ring is not that spline of its net"
            ));
        }
        checked += 1;
    }
    if checked == 0 {
        return Err("no rule over the ring was recognised".into());
    }
    Ok((RegularPart::NonBoxS31, checked))
}

/// The masks at a regular vertex: bicubic or A_4 (valence-4 quads), ternary
/// biquadratic, or Loop's (valence-6 triangles).
pub(super) fn vertex_masks(
    mesh: &PolyMesh,
    vf: &[Vec<usize>],
    v: usize,
    ternary: bool,
) -> Result<Vec<(RegularPart, Mask)>, String> {
    let around = &vf[v];
    let m = mesh.face(around[0]).len();
    let mut neighbours: IdSet<usize> = IdSet::default();
    let mut diagonal: IdSet<usize> = IdSet::default();
    for &g in around {
        let gf = mesh.face(g);
        let k = gf.iter().position(|&x| x == v).ok_or("a vertex's face does not hold it")?;
        neighbours.insert(gf[(k + 1) % gf.len()]);
        neighbours.insert(gf[(k + gf.len() - 1) % gf.len()]);
        if gf.len() == 4 {
            diagonal.insert(gf[(k + 2) % 4]);
        }
    }
    let candidates: &[(RegularPart, (i64, i64), (i64, i64), (i64, i64))] = match (m, around.len()) {
        (4, 4) if ternary => &[(RegularPart::BiquadraticBSplineTernary, (49, 81), (7, 81), (1, 81))],
        (4, 4) => &[
            (RegularPart::BicubicBSpline, (9, 16), (3, 32), (1, 64)),
            (RegularPart::FourDirectionBoxSpline, (1, 2), (1, 8), (0, 1)),
        ],
        (3, 6) => &[(RegularPart::ThreeDirectionQuarticBoxSpline, (5, 8), (1, 16), (0, 1))],
        _ => return Err("a vertex over the ring is not regular".into()),
    };
    Ok(candidates
        .iter()
        .map(|&(kind, centre, edge, diag)| {
            let mut mask = Mask::default();
            mask.insert(v, SmallRational::ratio(centre.0, centre.1));
            for &n in &neighbours {
                mask.insert(n, SmallRational::ratio(edge.0, edge.1));
            }
            if diag.0 != 0 {
                for &n in &diagonal {
                    mask.insert(n, SmallRational::ratio(diag.0, diag.1));
                }
            }
            (kind, mask)
        })
        .collect())
}

/// The mask at an edge between regular faces (ternary: the new vertex on
/// a–b near a).
pub(super) fn edge_mask(
    mesh: &PolyMesh,
    vf: &[Vec<usize>],
    a: usize,
    b: usize,
    ternary: bool,
) -> Result<(RegularPart, Mask), String> {
    let sides: Vec<usize> = vf[a].iter().copied().filter(|g| mesh.face(*g).contains(&b)).collect();
    if sides.len() != 2 {
        return Err("an edge over the ring does not have two faces".into());
    }
    let m = mesh.face(sides[0]).len();
    if sides.iter().any(|&g| mesh.face(g).len() != m) {
        return Err("an edge over the ring lies between a quad and a triangle".into());
    }
    if ternary && m == 4 {
        // along the edge (6, 3)/9, across it (1, 7, 1)/9
        let mut mask = Mask::default();
        mask.insert(a, SmallRational::ratio(42, 81));
        mask.insert(b, SmallRational::ratio(21, 81));
        for g in sides {
            let gf = mesh.face(g);
            let k = gf.iter().position(|&x| x == a).ok_or("an edge's face does not hold it")?;
            // the corner of g next to a that is not b, and the one next to b
            let (next, prev) = (gf[(k + 1) % 4], gf[(k + 3) % 4]);
            let beside_a = if next == b { prev } else { next };
            let beside_b = gf[(k + 2) % 4];
            mask.insert(beside_a, SmallRational::ratio(6, 81));
            mask.insert(beside_b, SmallRational::ratio(3, 81));
        }
        return Ok((RegularPart::BiquadraticBSplineTernary, mask));
    }
    let (kind, end, other) = match m {
        4 => (RegularPart::BicubicBSpline, (3, 8), (1, 16)),
        3 => (RegularPart::ThreeDirectionQuarticBoxSpline, (3, 8), (1, 8)),
        _ => return Err("an edge over the ring borders a face that is neither a quad nor a triangle".into()),
    };
    let mut mask = Mask::default();
    mask.insert(a, SmallRational::ratio(end.0, end.1));
    mask.insert(b, SmallRational::ratio(end.0, end.1));
    for g in sides {
        for &x in mesh.face(g).iter().filter(|&&x| x != a && x != b) {
            mask.insert(x, SmallRational::ratio(other.0, other.1));
        }
    }
    Ok((kind, mask))
}

/// The winding number of the annulus's inner boundary (the boundary of the
/// faces `inside` it) around the centre, from
/// the angular ranges of the hulls of the adjacent ring faces' windows.
fn winding_number(
    net: &Net<Point>,
    ring: &[usize],
    inside: &[usize],
    windows: &[Window],
) -> Result<(i64, WindingEvidence), String> {
    let mesh = &net.mesh;
    let mut half: HashSet<(usize, usize)> = HashSet::new();
    for &f in inside {
        let face = mesh.face(f);
        for k in 0..face.len() {
            half.insert((face[k], face[(k + 1) % face.len()]));
        }
    }
    // directed boundary edges of the inner region, in face orientation
    let mut next: HashMap<usize, usize> = HashMap::new();
    for &(a, b) in &half {
        if !half.contains(&(b, a)) && next.insert(a, b).is_some() {
            return Err("the inner boundary is not a simple chain".into());
        }
    }
    let ring_of_half: HashMap<(usize, usize), usize> = ring
        .iter()
        .enumerate()
        .flat_map(|(i, &f)| {
            let face = mesh.face(f);
            (0..face.len()).map(move |k| ((face[k], face[(k + 1) % face.len()]), i))
        })
        .collect();
    let start = *next.keys().min().ok_or("the inner region has no boundary")?;
    // the chain a₀ → a₁ → … → a₀, and for each edge the window of the ring
    // face on its other side (which holds the edge as (b, a))
    let mut chain: Vec<(usize, usize)> = Vec::new();
    let mut a = start;
    loop {
        let b = next[&a];
        let &w = ring_of_half.get(&(b, a)).ok_or("an inner boundary edge has no ring face beside it")?;
        chain.push((a, w));
        a = b;
        if a == start {
            break;
        }
        if chain.len() > next.len() {
            return Err("the inner boundary is not one closed chain".into());
        }
    }
    if chain.len() != next.len() {
        return Err("the inner boundary has more than one component".into());
    }
    // Lemma (winding from half-planes). Arc i (the image of chain edge i)
    // lies in the hull of window i, proved inside the open half-plane
    // Hᵢ = {p : dᵢ·p > 0}. Its end points p_{i−1}, pᵢ (images of the chain
    // vertices) lie in both adjacent hulls. Take wᵢ = the midpoint of the
    // control point at chain vertex i + 1, proved in Hᵢ ∩ H_{i+1}. Then the
    // angle the curve turns along arc i is the principal angle from p_{i−1}
    // to pᵢ (a path in a half-plane turns by less than π), and replacing
    // each pᵢ by wᵢ changes the sum by terms that cancel (pᵢ and wᵢ lie in a
    // common half-plane with both neighbours). So the curve's winding number
    // is that of the closed polygon w₀ w₁ …, whose consecutive vertices
    // share an open half-plane (so no edge passes through the origin): a
    // crossing count with exact orientation signs.
    let directions: Vec<[f64; 2]> =
        chain.iter().map(|&(_, w)| half_plane(&windows[w].points, windows[w].radius)).collect::<Result<_, String>>()?;
    let point = |v: usize| net.points[v].ok_or_else(|| "a chain vertex has no point".to_string());
    let k = chain.len();
    let mut polygon: Vec<[f64; 2]> = Vec::with_capacity(k);
    for i in 0..k {
        // chain vertex i + 1 ends edge i and starts edge i + 1
        let v = chain[(i + 1) % k].0;
        let p = point(v)?;
        let w = [p[0].mid(), p[1].mid()];
        for d in [directions[i], directions[(i + 1) % k]] {
            if !(dot(d, [Interval::point(w[0]), Interval::point(w[1])]).lo > 0.0) {
                return Err("a chain vertex's point is not in both adjacent arcs' half-planes".into());
            }
        }
        polygon.push(w);
    }
    let number = polygon_winding(&polygon)?;
    Ok((
        number,
        WindingEvidence {
            windows: chain.iter().map(|&(_, w)| w).collect(),
            vertices: (0..k).map(|i| chain[(i + 1) % k].0).collect(),
            directions,
            polygon,
            number,
        },
    ))
}

/// d·p enclosed, for a float direction d and an enclosed point p.
fn dot(d: [f64; 2], p: Point) -> Interval {
    Interval::point(d[0]) * p[0] + Interval::point(d[1]) * p[1]
}

/// A direction d with d·p > 0 proved for every enclosed point p (so their
/// hull lies in the open half-plane d·x > 0): the sum of the midpoints,
/// checked in interval arithmetic; with a `radius`, for every point within
/// that distance of the hull (d·p − radius·|d| > 0).
pub(super) fn half_plane(points: &[Point], radius: f64) -> Result<[f64; 2], String> {
    let d = points.iter().fold([0.0, 0.0], |s, p| [s[0] + p[0].mid(), s[1] + p[1].mid()]);
    let reach =
        Interval::point(radius) * Interval::sqrt(&(Interval::point(d[0]).square() + Interval::point(d[1]).square()));
    if points.iter().all(|p| (dot(d, *p) - reach).lo > 0.0) {
        Ok(d)
    } else {
        Err("the hull of a boundary arc's window is not in a half-plane through the centre".into())
    }
}

/// The winding number of a closed polygon of float points around the
/// origin, none of whose edges passes through it: signed crossings of the
/// positive x-axis, upward crossings with the origin on the left counted +1,
/// downward ones with it on the right −1. The y signs are exact; the sign of
/// the orientation a × b is taken from its enclosure and must be decided.
pub(super) fn polygon_winding(polygon: &[[f64; 2]]) -> Result<i64, String> {
    let k = polygon.len();
    let mut winding = 0i64;
    for i in 0..k {
        let (a, b) = (polygon[i], polygon[(i + 1) % k]);
        let upward = a[1] <= 0.0 && b[1] > 0.0;
        let downward = b[1] <= 0.0 && a[1] > 0.0;
        if !upward && !downward {
            continue;
        }
        let cross = Interval::point(a[0]) * Interval::point(b[1]) - Interval::point(a[1]) * Interval::point(b[0]);
        if !cross.sign_decided() {
            return Err("the orientation of a boundary polygon edge about the centre is not decided".into());
        }
        match (upward, cross.lo > 0.0) {
            (true, true) => winding += 1,
            (false, false) => winding -= 1,
            _ => {}
        }
    }
    Ok(winding)
}

/// Per ring face of the certified net at `levels` (the annulus the
/// certificate takes: the first whose faces all have box-spline
/// windows): the Jacobian sign from the face's own window, as every face
/// was bounded before the orbit reduction, and the position of its
/// orbit's representative. None when no annulus has such windows. For
/// cross-checks of lemma C5′ (tests/certify_charmap.rs): the route that
/// bounded every face, which the certificate no longer takes.
pub fn own_window_signs(scheme: &dyn Scheme, analysis: &Analysis, levels: usize) -> Option<(Vec<i8>, Vec<usize>)> {
    let mut cert = certify_charmap(scheme, analysis, DEFAULT_MAX_LEVELS).ok()?;
    let level0 = certified_net(analysis, &mut cert).ok()?;
    let d = &analysis.discovered;
    let net = net::refine_net_exactly_as::<Interval, Point>(scheme, d, level0, levels).ok()?;
    let vf = net.mesh.vertex_faces();
    for (ring, _) in annuli(&net).iter().filter(|(_, inside)| !inside.is_empty()) {
        let Ok(windows) = ring.iter().map(|&f| Window::around(&net, &vf, f, false)).collect::<Result<Vec<_>, _>>()
        else {
            continue;
        };
        let signs = windows.iter().map(|w| w.jacobian_bounds().decided_sign()).collect();
        let period = d.config.rotation_period(scheme);
        return Some((signs, window_orbits::representative_of(&net, ring, period)));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The regular n-gon at angle offset `phase`, traversed `turns` times
    /// (negative: clockwise): its winding number about the origin is
    /// `turns` by construction.
    fn polygon(n: usize, turns: i64, phase: f64) -> Vec<[f64; 2]> {
        (0..n)
            .map(|k| {
                let t = phase + 2.0 * std::f64::consts::PI * turns as f64 * k as f64 / n as f64;
                [t.cos(), t.sin()]
            })
            .collect()
    }

    #[test]
    fn polygon_winding_counts_turns_exactly() {
        for (turns, n) in [(1, 7), (-1, 7), (2, 13), (3, 20), (-2, 9)] {
            // a phase of 0 puts a vertex on the ray: the half-open rule counts it once
            for phase in [0.0, 0.3, -1e-300] {
                assert_eq!(polygon_winding(&polygon(n, turns, phase)).unwrap(), turns, "{turns} turns, phase {phase}");
            }
        }
        // a loop that does not surround the origin
        let off: Vec<[f64; 2]> = polygon(8, 1, 0.1).iter().map(|p| [p[0] + 3.0, p[1] - 0.5]).collect();
        assert_eq!(polygon_winding(&off).unwrap(), 0);
    }

    #[test]
    fn a_half_plane_is_proved_or_refused() {
        let box_at = |x: f64, y: f64| [Interval::new(x - 1e-3, x + 1e-3), Interval::new(y - 1e-3, y + 1e-3)];
        // points in an open quadrant: a direction is found and checked
        let d = half_plane(&[box_at(1.0, 0.1), box_at(0.2, 1.0), box_at(0.5, 0.5)], 0.0).unwrap();
        assert!(d[0] > 0.0 && d[1] > 0.0);
        // points on both sides of the origin: no open half-plane holds them
        assert!(half_plane(&[box_at(1.0, 0.0), box_at(-1.0, 0.01), box_at(0.0, 1.0)], 0.0).is_err());
        // a box holding the origin: refused, however the others lie
        assert!(half_plane(&[box_at(1.0, 1.0), [Interval::new(-0.1, 0.1), Interval::new(-0.1, 0.1)]], 0.0).is_err());
    }
}
