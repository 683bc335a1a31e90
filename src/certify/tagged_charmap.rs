//! The certified characteristic map at a boundary vertex: a proof (or
//! disproof, or the reason for neither) that the sector characteristic map
//! of the piecewise-smooth theory (Zorin 2000; Biermann–Levin–Zorin 2000) is
//! regular and injective on the sector. Lemmas B1–B6 of ARCHITECTURE.md
//! ("Certified characteristic maps at a boundary vertex") are written there
//! in full; each function below names the one it implements.
//!
//! 1. **Eigenvectors (B1).** The spectral part is the tagged certificate's
//!    (`certify::tagged`). Its enclosure route names λ1 and λ2 by a block
//!    (even, odd) and a disc of that block's verified diagonalisation; the
//!    eigenvector of each is enclosed there (`discs::eigenvector`) and
//!    spread over S's points by the reflection (even: the same value at a
//!    point and its mirror, odd: opposite values).
//! 2. **The rays (B2).** The sharp curve's points (centre and both sharp
//!    rays) are shown invariant on S's exact rows; where λ's enclosure holds
//!    no root of the characteristic polynomial of the curve's block of λ's
//!    parity (Sturm, over Q), that eigenvector vanishes on the curve
//!    exactly. One must vanish (the normal coordinate: the rays land on a
//!    line through the origin); both vanishing disproves the map (the rays
//!    collapse to the centre).
//! 3. **Net and windows (B3).** The net is refined in interval arithmetic
//!    with the scheme's rules; a ring face on a sharp ray gets its missing
//!    window positions as ghost points of its host box spline
//!    (`GhostHost`: the bicubic B-spline's 2b − p, b on the ray and p its
//!    neighbour across; the three-direction quartic box spline's a + b − p,
//!    a–b the sharp edge and p the apex across it), and the rules at every
//!    boundary entity of the windows are compared exactly with the
//!    ghost-extended box spline's (boundary vertex (1, 6, 1)/8 along the
//!    ray, boundary edge midpoint: the same for both hosts).
//! 4. **Regularity (B4)** from the window Jacobian bounds, as inside.
//! 5. **Rays again (B5).** Along each ray the tangent coordinate's
//!    differences of the boundary row, in the face's own orientation, have
//!    one sign on both rays: the two rays' neighbourhoods map to the same
//!    side of the line.
//! 6. **Injectivity (B6).** The map doubled by the mirror in that line is a
//!    local homeomorphism of the punctured disc of 2k sectors; the winding
//!    number of the doubled chain is computed from half-planes as inside,
//!    and Peters–Reif's argument gives injectivity for ±1.

use std::collections::{HashMap, HashSet};

use serde::Serialize;

use super::charmap::{
    combine, edge_mask, exact_stencil, half_plane, polygon_winding, vertex_masks, LatticeLayout, Mask, Point,
    RegularPart, Window,
};
use super::discs::eigenvector;
use super::spectrum::{exact_rows, Verdict};
use super::tagged::{certify_tagged, Named, TaggedCertificate};
use crate::charmap::net::{self, Net};
use crate::error::Error;
use crate::matrix::local::assemble_rows;
use crate::mesh::{PolyMesh, VertexTag};
use crate::neighbourhood::Tagging;
use crate::numeric::exact::QMatrix;
use crate::numeric::sturm::{count_roots, squarefree, sturm_chain};
use crate::numeric::{Interval, Rational, SmallRational, Weight};
use crate::refine::{connectivity, Origin};
use crate::sdc::Scheme;
use crate::spectrum::reflection::split;
use crate::spectrum::Analysis;

/// Everything `charmap --tag boundary --certify` proves. Field names are
/// stable API.
#[derive(Clone, Debug, Serialize)]
pub struct TaggedCharMapCertificate {
    pub scheme: String,
    /// "boundary"
    pub tagging: String,
    /// faces of the fan
    pub sectors: usize,
    pub statement: String,
    /// the spectral part (the tagged certificate of `spectrum --tag --certify`)
    pub spectrum: TaggedCertificate,
    /// the sector map's Jacobian has one sign on the punctured sector
    pub regularity: Verdict,
    /// the sector map is injective
    pub injectivity: Verdict,
    /// the sector criterion as a whole: spectral part, regularity, injectivity
    pub sector_criterion: Verdict,
    /// proved only given premises confirmed to interval overlap
    pub conditional: bool,
    /// which eigenvector vanishes on the sharp rays ("lambda1" or "lambda2")
    pub normal_coordinate: Option<&'static str>,
    /// the sharp curve's points (centre and both rays) in S
    pub curve_points: usize,
    pub regular_part: Option<RegularPart>,
    pub rules_checked: usize,
    pub levels: Option<usize>,
    pub ring_faces: usize,
    /// ring faces whose windows reach across a sharp ray (ghost points)
    pub boundary_faces: usize,
    pub positive_faces: usize,
    pub negative_faces: usize,
    pub undecided_faces: usize,
    /// the largest |yⱼ| of the two eigenvector enclosures
    pub eigenvector_radius: Option<f64>,
    pub max_point_width: Option<f64>,
    /// of the chain doubled by the mirror
    pub winding_number: Option<i64>,
    pub reasons: Vec<String>,
    /// what a certificate document exports of a PROVED sector map (the
    /// proof's input and claims at its decisive level, `export::sector_part`);
    /// `None` where the sector criterion is not PROVED
    #[serde(skip)]
    pub evidence: Option<SectorEvidence>,
}

/// The data of a PROVED sector map that an independent checker re-derives
/// the verdict from (`export::sector_part`, `scripts/check_cert.py`).
#[derive(Clone, Debug)]
pub struct SectorEvidence {
    /// the box spline of the windows and its ghost extension (lemma B3)
    pub host: GhostHost,
    /// analysis steps of the interval net
    pub levels: usize,
    /// 0: λ1's eigenvector vanishes on the sharp curve, 1: λ2's
    pub normal: usize,
    /// the sharp curve's points (matrix indices)
    pub curve: Vec<usize>,
    /// λ1's and λ2's eigenvectors, each proved by Krawczyk's test on its block
    pub eigenvectors: [EigenvectorEvidence; 2],
    /// per ring face (in the order the winding data names them)
    pub faces: Vec<FaceEvidence>,
    pub chain: ChainEvidence,
}

/// Krawczyk's test of one eigenpair of a reflection block (`krawczyk_eigenpair`):
/// the float approximation ũ = (x̃, μ̃) with x̃_s = 1, the float matrix R and
/// the radii of the box Y with K(Y) ⊂ int Y.
#[derive(Clone, Debug)]
pub struct EigenvectorEvidence {
    /// "even", "odd" or "whole"
    pub block: &'static str,
    pub component: usize,
    pub s: usize,
    pub x: Vec<f64>,
    pub mu: f64,
    pub r: Vec<Vec<f64>>,
    pub y: Vec<f64>,
}

/// Where a ghost-extended window's position takes its value from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WindowSource {
    /// a vertex of the refined net
    Net(usize),
    /// the ghost point a + b − p: a and b on a sharp ray, p across it
    /// (`GhostHost::ghost_candidates`: Catmull–Clark's 2b − p has a = b)
    Ghost(usize, usize, usize),
}

/// The regular part a ring face's window is a patch of, with the lattice its
/// one-ring lies on and the linear ghost extension across a sharp ray that
/// makes the box spline's rules reproduce the boundary rules (lemma B3 of
/// ARCHITECTURE.md). One mechanism for both hosts: only the face's shape,
/// the window's positions and the ghost's stencil differ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GhostHost {
    /// primal quads: the bicubic B-spline, 4 × 4 windows, ghost 2b − p
    Bicubic,
    /// primal triangles: the three-direction quartic box spline, 12-point
    /// windows, ghost a + b − p
    QuarticBox,
}

impl GhostHost {
    /// The host whose faces have `sides` sides.
    pub fn of(sides: usize) -> Option<GhostHost> {
        match sides {
            4 => Some(GhostHost::Bicubic),
            3 => Some(GhostHost::QuarticBox),
            _ => None,
        }
    }

    pub fn regular_part(self) -> RegularPart {
        match self {
            GhostHost::Bicubic => RegularPart::BicubicBSpline,
            GhostHost::QuarticBox => RegularPart::ThreeDirectionQuarticBoxSpline,
        }
    }

    /// The name a certificate document gives the host (`sector.host`).
    pub fn name(self) -> &'static str {
        self.regular_part().describe()
    }

    fn sides(self) -> usize {
        match self {
            GhostHost::Bicubic => 4,
            GhostHost::QuarticBox => 3,
        }
    }

    /// Faces at a regular vertex inside, and at a regular vertex on a sharp
    /// ray (a straight boundary: half the lattice's turn).
    fn valences(self) -> (usize, usize) {
        match self {
            GhostHost::Bicubic => (4, 2),
            GhostHost::QuarticBox => (6, 3),
        }
    }

    /// The face's corners on the lattice, in its orientation.
    fn corners(self) -> &'static [(i32, i32)] {
        match self {
            GhostHost::Bicubic => &[(0, 0), (1, 0), (1, 1), (0, 1)],
            GhostHost::QuarticBox => &[(0, 0), (1, 0), (0, 1)],
        }
    }

    /// The next edge of a face turns by 90° (quads) or by 120° (triangles,
    /// in lattice coordinates whose third direction is (−1, 1)).
    fn turn(self, (x, y): (i32, i32)) -> (i32, i32) {
        match self {
            GhostHost::Bicubic => (-y, x),
            GhostHost::QuarticBox => (-x - y, x),
        }
    }

    /// The lattice's unit steps: the directions of the edges.
    fn steps(self) -> &'static [(i32, i32)] {
        match self {
            GhostHost::Bicubic => &[(1, 0), (0, 1), (-1, 0), (0, -1)],
            GhostHost::QuarticBox => &[(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)],
        }
    }

    /// The positions of the face's window: the control points whose basis
    /// functions do not vanish on the face (the 4 × 4 grid of the bicubic
    /// B-spline; the face's three corners and their nine neighbours for the
    /// quartic box spline, the union of the corners' one-rings).
    fn positions(self) -> Vec<(i32, i32)> {
        match self {
            GhostHost::Bicubic => (-1..=2).flat_map(|x| (-1..=2).map(move |y| (x, y))).collect(),
            GhostHost::QuarticBox => {
                let mut all: Vec<(i32, i32)> = self
                    .corners()
                    .iter()
                    .flat_map(|&c| std::iter::once(c).chain(self.steps().iter().map(move |s| (c.0 + s.0, c.1 + s.1))))
                    .collect();
                all.sort_unstable();
                all.dedup();
                all
            }
        }
    }

    /// The ways the ghost at a missing position q may be built, each as
    /// (a, b, p) positions, the ghost being a + b − p with a and b on a
    /// sharp ray and p across it (lemma B3):
    ///
    /// * bicubic B-spline: a = b = q + e, p = q + 2e for a unit step e (the
    ///   point reflection 2b − p through the ray vertex; across the ray the
    ///   tensor rules act as the cubic B-spline's on rows r₋₁ = 2r₀ − r₁,
    ///   r₀, r₁: the new row 0 is (r₋₁ + 6r₀ + r₁)/8 = r₀, so along the ray
    ///   they reduce to (1, 6, 1)/8 and the midpoint);
    /// * quartic box spline: a and b the ends of the lattice edge opposite
    ///   q in a triangle (a = q + dᵢ, b = q + dᵢ₊₁ for consecutive unit
    ///   steps), p = a + b − q the apex on the other side: the reflection of
    ///   p through the midpoint of the edge a–b. Derivation (ARCHITECTURE.md,
    ///   B3): on the boundary row v_i = (i, 0) with r_i = (i, 1) and ghosts
    ///   g_i = (i + 1, −1) = v_i + v_{i+1} − r_i, the box spline's edge rule
    ///   at v_i–v_{i+1} is 3/8 (v_i + v_{i+1}) + 1/8 (r_i + g_i) =
    ///   1/2 (v_i + v_{i+1}), and its vertex rule at v_i is
    ///   10/16 v_i + 1/16 (v_{i−1} + v_{i+1} + r_i + r_{i−1} + g_i + g_{i−1})
    ///   = 3/4 v_i + 1/8 (v_{i−1} + v_{i+1}): Loop's boundary rules. The
    ///   refined ghost row is again a + b − p of the refined net (checked
    ///   for both parities of the new row −1 in ARCHITECTURE.md). The point
    ///   reflection 2b − p does not do this for triangles: its vertex rule
    ///   at a ray vertex is not symmetric in v_{i±1}.
    fn ghost_candidates(self, q: (i32, i32)) -> Vec<[(i32, i32); 3]> {
        let add = |a: (i32, i32), b: (i32, i32)| (a.0 + b.0, a.1 + b.1);
        match self {
            GhostHost::Bicubic => self
                .steps()
                .iter()
                .map(|&e| {
                    let b = add(q, e);
                    [b, b, add(b, e)]
                })
                .collect(),
            GhostHost::QuarticBox => {
                let steps = self.steps();
                (0..steps.len())
                    .map(|i| {
                        let (a, b) = (add(q, steps[i]), add(q, steps[(i + 1) % steps.len()]));
                        [a, b, (a.0 + b.0 - q.0, a.1 + b.1 - q.1)]
                    })
                    .collect()
            }
        }
    }
}

/// A ring face's window: its 4 × 4 positions, the rows of positions along
/// its sharp edges (in the face's orientation) and the sign its Jacobian
/// was proved to have.
#[derive(Clone, Debug)]
pub struct FaceEvidence {
    pub layout: Vec<((i32, i32), WindowSource)>,
    pub rows: Vec<Vec<(i32, i32)>>,
    pub sign: i8,
}

/// The inner chain of lemma B6: net vertices from ray to ray, the ring
/// face (index into the faces) beside each of its edges, the half-planes'
/// directions and the float polygon's points (one per chain vertex, before
/// mirroring), and the winding number of the doubled polygon.
#[derive(Clone, Debug)]
pub struct ChainEvidence {
    pub vertices: Vec<usize>,
    pub arcs: Vec<usize>,
    pub directions: Vec<[f64; 2]>,
    pub polygon: Vec<[f64; 2]>,
    pub number: i64,
}

const STATEMENT: &str = "the sector characteristic map at the boundary vertex (the eigenvectors of λ1 and λ2 of \
     the true S, on the k sectors; Zorin 2000, Biermann–Levin–Zorin 2000) is regular and injective on the \
     punctured sector, and the spectral part of the sector criterion holds";

/// Certify the sector characteristic map of a tagged analysis. Only an
/// open fan with the boundary tag is covered (an input error otherwise).
pub fn certify_tagged_charmap(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    max_levels: usize,
) -> Result<TaggedCharMapCertificate, Error> {
    super::charmap::check_levels(max_levels, "certification levels")?;
    let d = &analysis.discovered;
    let tagging = d.config.tagging.ok_or_else(|| Error::Input("no tag: use charmap --certify".into()))?;
    if tagging != Tagging::Boundary {
        return Err(Error::Input(format!(
            "charmap --tag {} --certify: only boundary vertices (--tag boundary) are certified yet; the \
             floating-point charmap --tag {} decides the others",
            tagging.name(),
            tagging.name()
        )));
    }
    let spectrum = certify_tagged(scheme, analysis)?;
    let mut cert = TaggedCharMapCertificate {
        scheme: analysis.spectrum.scheme.clone(),
        tagging: tagging.name(),
        sectors: d.config.valence(),
        statement: STATEMENT.into(),
        conditional: spectrum.conditional,
        spectrum,
        regularity: Verdict::NotProved(String::new()),
        injectivity: Verdict::NotProved(String::new()),
        sector_criterion: Verdict::NotProved(String::new()),
        normal_coordinate: None,
        curve_points: 0,
        regular_part: None,
        rules_checked: 0,
        levels: None,
        ring_faces: 0,
        boundary_faces: 0,
        positive_faces: 0,
        negative_faces: 0,
        undecided_faces: 0,
        eigenvector_radius: None,
        max_point_width: None,
        winding_number: None,
        reasons: Vec::new(),
        evidence: None,
    };
    let geometric = match &cert.spectrum.verdict {
        Verdict::Proved => geometric_half(scheme, analysis, max_levels, &mut cert),
        other => Err(format!(
            "not attempted: the spectral part is {}, so there is no certified pair λ1, λ2 whose eigenvectors define \
             the map",
            other.word()
        )),
    };
    let (regularity, injectivity) = match geometric {
        Ok(v) => v,
        Err(why) => (Verdict::NotProved(why.clone()), Verdict::NotProved(why)),
    };
    cert.regularity = regularity;
    cert.injectivity = injectivity;
    cert.sector_criterion = combine(&cert.spectrum.verdict, &cert.regularity, &cert.injectivity);
    cert.conditional = cert.sector_criterion == Verdict::Proved && cert.spectrum.conditional;
    Ok(cert)
}

/// Lemma B1: a real enclosure of the eigenvector of `named` over S's points
/// (matrix order), the radius of its enclosure, and Krawczyk's data where
/// that test gave it (a document exports only those: `SectorEvidence`).
fn enclosed_eigenvector(
    spectrum: &TaggedCertificate,
    rows: &[Vec<Interval>],
    named: &Named,
    size: usize,
) -> Result<(Vec<Interval>, f64, Option<EigenvectorEvidence>), String> {
    let block = spectrum
        .blocks
        .iter()
        .find(|b| b.name == named.block)
        .ok_or_else(|| format!("the {} block is missing from the spectral certificate", named.block))?;
    let component = block.components.get(named.component).ok_or("the named component does not exist")?;
    let [row] = component.rows.as_slice() else {
        return Err(format!("the {} block's component holds {} discs, not one", block.name, component.rows.len()));
    };
    let diagonalisation = block.diagonalisation.as_ref().ok_or("the block's verified diagonalisation is missing")?;
    let (z, radius) = eigenvector(diagonalisation, *row)
        .map_err(|why| format!("the eigenvector of the {} block is not enclosed: {why}", block.name))?;
    // The block is real and the eigenvalue real and simple, so the true
    // eigenvector in the enclosure is c·r for a real r: its real and its
    // imaginary part are real multiples of r, and one whose enclosure keeps
    // an entry away from 0 is a real eigenvector.
    let re: Vec<Interval> = z.iter().map(|c| c.re).collect();
    let im: Vec<Interval> = z.iter().map(|c| c.im).collect();
    let nonzero = |v: &[Interval]| v.iter().any(|x| x.lo > 0.0 || x.hi < 0.0);
    let x = if nonzero(&re) {
        re
    } else if nonzero(&im) {
        im
    } else {
        return Err("neither the real nor the imaginary part of the eigenvector enclosure is shown non-zero".into());
    };
    // The disc bound above is loose where other discs are wide (defective
    // clusters near 0 or 1/8 give radii of 1e-2): Krawczyk's test on the
    // block itself, started from the enclosure's midpoint, gives a tight one
    // when it succeeds; the disc bound stands otherwise.
    let (x, radius, evidence) = match block_matrix(rows, spectrum.reflection.as_ref(), block.name)
        .and_then(|a| krawczyk_eigenpair(&a, &x, component))
    {
        Ok((tight, mut evidence)) => {
            let width = tight.iter().map(|v| v.width()).fold(0.0, f64::max);
            evidence.block = block.name;
            evidence.component = named.component;
            (tight, width, Some(evidence))
        }
        Err(_) => (x, radius, None),
    };
    // from the block's basis to S's points (`spectrum::reflection::split`)
    let values = match (block.name, spectrum.reflection.as_ref()) {
        ("whole", _) => x,
        (parity, Some(image)) => {
            let even = parity == "even";
            let reps: Vec<usize> = (0..size).filter(|&b| if even { b <= image[b] } else { b < image[b] }).collect();
            if reps.len() != x.len() {
                return Err("the block's size does not match the reflection".into());
            }
            let mut v = vec![Interval::point(0.0); size];
            for (k, &b) in reps.iter().enumerate() {
                v[b] = x[k];
                if image[b] != b {
                    v[image[b]] = if even { x[k] } else { -x[k] };
                }
            }
            v
        }
        (_, None) => return Err("the blocks are the reflection's, but the reflection is not recorded".into()),
    };
    Ok((values, radius, evidence))
}

/// Lemma B2: the sharp curve's points (matrix indices) and, per eigenvector
/// of the pair, whether it is proved to vanish on them.
fn vanishing_on_curve(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    spectrum: &TaggedCertificate,
    pair: [&Named; 2],
) -> Result<(Vec<usize>, [bool; 2]), String> {
    let d = &analysis.discovered;
    let rays = d.config.tagging.map(|t| t.sharp_rays(d.config.valence())).unwrap_or_default();
    let curve: Vec<usize> = (0..d.analysis.len())
        .filter(|&k| {
            let l = &d.labels[d.analysis[k]];
            l.j == 0 && (l.i == 0 || rays.contains(&l.sector))
        })
        .collect();
    let rows = exact_rows(scheme, analysis, &curve).ok_or("the sharp curve's rows of S are not exact")?;
    let pos: HashMap<usize, usize> = curve.iter().enumerate().map(|(k, &v)| (v, k)).collect();
    let mut q = QMatrix::zeros(curve.len());
    for (a, row) in rows.iter().enumerate() {
        for (c, w) in row {
            match pos.get(c) {
                Some(&b) => {
                    let r = w.to_rational().ok_or("a weight of the sharp curve's rows is irrational")?;
                    q.set(a, b, q.get(a, b) + &r);
                }
                None if w.is_zero() => {}
                None => return Err("a row of the sharp curve has weight outside the curve: it is not invariant".into()),
            }
        }
    }
    let image = spectrum.reflection.as_ref().ok_or("S is not split by the reflection keeping the sharp rays")?;
    // the curve's even and odd blocks, as `spectrum::reflection::split` builds S's
    let local = |v: usize| pos.get(&image[curve[v]]).copied();
    let mirror: Vec<usize> =
        (0..curve.len()).map(local).collect::<Option<_>>().ok_or("the reflection does not keep the curve")?;
    let block = |even: bool| {
        let reps: Vec<usize> =
            (0..curve.len()).filter(|&b| if even { b <= mirror[b] } else { b < mirror[b] }).collect();
        let mut m = QMatrix::zeros(reps.len());
        for (i, &a) in reps.iter().enumerate() {
            for (j, &b) in reps.iter().enumerate() {
                let w = if b == mirror[b] {
                    q.get(a, b).clone()
                } else if even {
                    q.get(a, b) + q.get(a, mirror[b])
                } else {
                    q.get(a, b) - q.get(a, mirror[b])
                };
                m.set(i, j, w);
            }
        }
        m
    };
    let mut vanish = [false; 2];
    for (i, named) in pair.iter().enumerate() {
        let m = block(named.block == "even");
        if m.n == 0 {
            vanish[i] = true;
            continue;
        }
        // no root of det(x − B) in [lo, hi] ∋ λ: then B·x_c = λ·x_c forces x_c = 0
        let p = m.charpoly();
        let (lo, hi) = (
            Rational::from_float(named.enclosure.lo).ok_or("an enclosure end is not finite")?,
            Rational::from_float(named.enclosure.hi).ok_or("an enclosure end is not finite")?,
        );
        let chain = sturm_chain(&squarefree(&p));
        vanish[i] = p.sign_at(&lo) != 0 && count_roots(&chain, &lo, &hi) == 0;
    }
    Ok((curve, vanish))
}

/// The regularity and injectivity verdicts, or why neither is decided.
fn geometric_half(
    scheme: &dyn Scheme,
    analysis: &Analysis,
    max_levels: usize,
    cert: &mut TaggedCharMapCertificate,
) -> Result<(Verdict, Verdict), String> {
    let route = &cert.spectrum.enclosure_route;
    let (Verdict::Proved, Some(l1), Some(l2)) = (&route.verdict, &route.lambda1, &route.lambda2) else {
        return Err("the enclosure route did not prove the spectral part, so no eigenvector pair is enclosed".into());
    };
    let faces = analysis.discovered.patch.faces();
    let host = match faces.first().map(|f| f.len()).and_then(GhostHost::of) {
        Some(host) if scheme.topology().faces_per_face() == 4 && faces.iter().all(|f| f.len() == host.sides()) => host,
        _ => {
            return Err("numerical only: ghost windows across a sharp ray are derived for the bicubic B-spline \
                        (primal quads) and the three-direction quartic box spline (primal triangles) only"
                .into())
        }
    };
    let d = &analysis.discovered;
    let size = d.analysis.len();
    let rows = interval_matrix(scheme, analysis)?;
    let (v1, r1, e1) = enclosed_eigenvector(&cert.spectrum, &rows, l1, size)?;
    let (v2, r2, e2) = enclosed_eigenvector(&cert.spectrum, &rows, l2, size)?;
    cert.eigenvector_radius = Some(r1.max(r2));
    let (curve, vanish) = vanishing_on_curve(scheme, analysis, &cert.spectrum, [l1, l2])?;
    cert.curve_points = curve.len();
    let normal = match vanish {
        [true, true] => {
            let why = "both eigenvectors vanish on the sharp rays (λ1 and λ2 are not eigenvalues of the sharp \
                       curve's rows, exactly over Q): the map sends the rays to the centre, so it is neither regular \
                       (its derivative along a ray is 0) nor injective"
                .to_string();
            cert.reasons.push(why.clone());
            return Ok((Verdict::Disproved(why.clone()), Verdict::Disproved(why)));
        }
        [false, false] => {
            return Err("neither eigenvector is shown to vanish on the sharp rays, so the rays' images are not known \
                        to lie on a line"
                .into())
        }
        [true, false] => 0,
        [false, true] => 1,
    };
    cert.normal_coordinate = Some(["lambda1", "lambda2"][normal]);
    let mut values: Vec<Point> = v1.iter().zip(&v2).map(|(a, b)| [*a, *b]).collect();
    for &c in &curve {
        if !values[c][normal].contains(0.0) {
            return Err("the eigenvector enclosure excludes 0 where the eigenvector is proved to vanish".into());
        }
        values[c][normal] = Interval::point(0.0);
    }
    let mut level0 = vec![None; d.patch.num_vertices()];
    for (k, &v) in d.analysis.iter().enumerate() {
        level0[v] = Some(values[k]);
    }
    let mut last_reason = String::from("no level tried");
    for levels in 2..=max_levels {
        let net = net::refine_net_exactly_as::<Interval, Point>(scheme, d, level0.clone(), levels)
            .map_err(|e| format!("the interval net could not be refined {levels} levels: {e}"))?;
        let vf = net.mesh.vertex_faces();
        let ring: Vec<usize> = (0..net.mesh.num_faces()).filter(|&f| net.outer[f] && !net.inner[f]).collect();
        let inside: Vec<usize> = (0..net.mesh.num_faces()).filter(|&f| net.outer[f] && net.inner[f]).collect();
        let windows =
            match ring.iter().map(|&f| boundary_window(&net, &vf, f, host)).collect::<Result<Vec<_>, String>>() {
                Ok(w) => w,
                Err(why) => {
                    last_reason = format!("at {levels} levels: {why}");
                    continue;
                }
            };
        cert.rules_checked = check_boundary_rules(scheme, &net.mesh, &windows, host)?;
        cert.regular_part = Some(host.regular_part());
        let bounds: Vec<Interval> = windows.iter().map(|w| w.window.jacobian_bounds()).collect();
        let positive = bounds.iter().filter(|b| b.lo > 0.0).count();
        let negative = bounds.iter().filter(|b| b.hi < 0.0).count();
        let undecided = ring.len() - positive - negative;
        cert.levels = Some(levels);
        cert.ring_faces = ring.len();
        cert.boundary_faces = windows.iter().filter(|w| !w.rows.is_empty()).count();
        cert.positive_faces = positive;
        cert.negative_faces = negative;
        cert.undecided_faces = undecided;
        cert.max_point_width =
            Some(net.points.iter().flatten().map(|p| p[0].width().max(p[1].width())).fold(0.0, f64::max));
        if positive > 0 && negative > 0 {
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
        let sign: i64 = if negative > 0 { -1 } else { 1 };
        // lemma B5: the rays' images on the line, and the tangent coordinate
        // monotone along each ray with one sign in the faces' orientation
        let tangent = 1 - normal;
        let mut ray_sign: Option<bool> = None;
        let mut undecided_ray = false;
        for row in windows.iter().flat_map(|w| &w.rows) {
            if row.iter().any(|p| !(p[normal].lo == 0.0 && p[normal].hi == 0.0)) {
                return Err("a sharp ray's point of the refined net is not exactly on the line".into());
            }
            for pair in row.windows(2) {
                let diff = pair[1][tangent] - pair[0][tangent];
                if !diff.sign_decided() {
                    undecided_ray = true;
                    continue;
                }
                let up = diff.lo > 0.0;
                if *ray_sign.get_or_insert(up) != up {
                    return Ok((
                        Verdict::Proved,
                        Verdict::NotProved(
                            "the two sharp rays' neighbourhoods are not shown to map to one side of the line".into(),
                        ),
                    ));
                }
            }
        }
        if undecided_ray || ray_sign.is_none() {
            last_reason = format!("at {levels} levels the map's direction along a sharp ray is undecided");
            continue;
        }
        let mut level_reasons = Vec::new();
        level_reasons.push(format!(
            "the Jacobian is proved {} on all {} ring faces at {levels} levels ({} of them across a sharp ray, with \
             ghost points; ghost-extended {} rules, {} compared exactly)",
            if sign > 0 { "positive" } else { "negative" },
            ring.len(),
            cert.boundary_faces,
            host.name(),
            cert.rules_checked
        ));
        level_reasons.push(format!(
            "the {} eigenvector vanishes on the sharp rays (exactly over Q), the {} one is monotone along both with \
             one orientation",
            ["λ1", "λ2"][normal],
            ["λ1", "λ2"][tangent]
        ));
        match doubled_winding(&net, &ring, &inside, &windows, normal) {
            Ok(chain) => {
                let number = chain.number;
                cert.winding_number = Some(number);
                cert.reasons.extend(level_reasons);
                if number == sign {
                    // what a document exports: Krawczyk's data for both
                    // eigenvectors (a disc-bound enclosure is not exported)
                    if let (Some(a), Some(b)) = (e1.clone(), e2.clone()) {
                        let faces = windows
                            .iter()
                            .zip(&bounds)
                            .map(|(w, b)| FaceEvidence {
                                layout: w.layout.clone(),
                                rows: w.row_positions.clone(),
                                sign: if b.lo > 0.0 { 1 } else { -1 },
                            })
                            .collect();
                        cert.evidence = Some(SectorEvidence {
                            host,
                            levels,
                            normal,
                            curve: curve.clone(),
                            eigenvectors: [a, b],
                            faces,
                            chain,
                        });
                    }
                    cert.reasons.push(format!(
                        "the annulus's inner chain, doubled by the mirror in the rays' line, winds {number} time \
                         around the centre"
                    ));
                    return Ok((Verdict::Proved, Verdict::Proved));
                }
                return Ok((
                    Verdict::Proved,
                    Verdict::Disproved(format!(
                        "the map is regular but the doubled chain winds {number} times around the centre (Jacobian \
                         sign {sign})"
                    )),
                ));
            }
            Err(why) if levels < max_levels => {
                last_reason = format!("at {levels} levels the winding number is not certified: {why}");
                continue;
            }
            Err(why) => {
                cert.reasons.extend(level_reasons);
                return Ok((
                    Verdict::Proved,
                    Verdict::NotProved(format!("the winding number is not certified: {why}")),
                ));
            }
        }
    }
    Err(last_reason)
}

/// A ring face's window, with the rows of points on a sharp ray it holds
/// (each in the face's orientation along the ray: empty inside).
struct BoundaryWindow {
    window: Window,
    rows: Vec<Vec<Point>>,
    /// every position's source, and the rows' positions (for the document)
    layout: Vec<((i32, i32), WindowSource)>,
    row_positions: Vec<Vec<(i32, i32)>>,
}

/// Lemma B3: the window of a ring face, ghost-extended across a sharp ray.
/// The face's corners must be regular: interior (four quads, six
/// triangles), or on a sharp ray with two sharp edges (two quads, three
/// triangles). The one-ring's faces are laid out on the host's lattice as
/// inside; every missing position q of the window gets the host's ghost
/// a + b − p (`GhostHost::ghost_candidates`), a and b laid-out vertices on a
/// sharp ray (for triangles, the ends of a sharp edge), p laid out across,
/// and exactly one such construction must exist.
fn boundary_window(net: &Net<Point>, vf: &[Vec<usize>], f: usize, host: GhostHost) -> Result<BoundaryWindow, String> {
    let mesh = &net.mesh;
    let face = mesh.face(f);
    let m = host.sides();
    if face.len() != m {
        return Err(format!("a ring face has {} sides", face.len()));
    }
    let on_ray = |v: usize| matches!(mesh.vertex_tag(v), VertexTag::Crease(_, _));
    let (inner, ray) = host.valences();
    for &c in face {
        let regular = match mesh.vertex_tag(c) {
            VertexTag::Smooth => vf[c].len() == inner,
            VertexTag::Crease(_, _) => vf[c].len() == ray,
            _ => false,
        };
        if !regular || vf[c].iter().any(|&g| mesh.face(g).len() != m) {
            return Err("a ring face has a corner that is not regular (interior or on a sharp ray)".into());
        }
    }
    let mut faces: Vec<usize> = face.iter().flat_map(|&c| vf[c].iter().copied()).collect();
    faces.sort_unstable();
    faces.dedup();
    let mut coords = LatticeLayout(face.iter().copied().zip(host.corners().iter().copied()).collect());
    let mut placed: Vec<bool> = faces.iter().map(|&g| g == f).collect();
    let conflict = || "a ring face's one-ring of faces does not lie on one lattice".to_string();
    while placed.iter().any(|&p| !p) {
        let mut progress = false;
        for (slot, &g) in faces.iter().enumerate() {
            if placed[slot] {
                continue;
            }
            let gf = mesh.face(g);
            let Some(k) = (0..m).find(|&k| coords.get(gf[k]).is_some() && coords.get(gf[(k + 1) % m]).is_some()) else {
                continue;
            };
            let (a, b) = (coords.at(gf[k]), coords.at(gf[(k + 1) % m]));
            let t = host.turn((b.0 - a.0, b.1 - a.1));
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
    let positions = host.positions();
    let mut distinct: Vec<(i32, i32)> = coords.0.iter().map(|&(_, c)| c).collect();
    distinct.sort_unstable();
    distinct.dedup();
    if distinct.len() != coords.0.len() || coords.0.iter().any(|(_, c)| !positions.contains(c)) {
        return Err(conflict());
    }
    let p = |v: usize| net.points[v].ok_or_else(|| "a window point is not determined".to_string());
    let at: HashMap<(i32, i32), usize> = coords.0.iter().map(|&(v, c)| (c, v)).collect();
    // every position of the window: a net vertex, or a ghost
    let mut value: HashMap<(i32, i32), Point> = HashMap::new();
    let mut source: HashMap<(i32, i32), WindowSource> = HashMap::new();
    for (&c, &v) in &at {
        value.insert(c, p(v)?);
        source.insert(c, WindowSource::Net(v));
    }
    let laid = |w: usize| at.iter().find(|(_, &u)| u == w).map(|(&c, _)| c);
    let mut ghosts = 0;
    for &q in &positions {
        if at.contains_key(&q) {
            continue;
        }
        let mut found: Option<(usize, usize, usize)> = None;
        for [aq, bq, pq] in host.ghost_candidates(q) {
            let (Some(&a), Some(&b), Some(&pv)) = (at.get(&aq), at.get(&bq), at.get(&pq)) else { continue };
            if !(on_ray(a) && on_ray(b)) {
                continue;
            }
            let across = if a == b {
                // one ray vertex b: the ray crosses the step q → b, so b's
                // sharp edges (those the window holds, at least one) go to
                // laid-out neighbours on the line through b perpendicular to it
                let VertexTag::Crease(s, t) = mesh.vertex_tag(b) else { continue };
                let e = (bq.0 - q.0, bq.1 - q.1);
                let perpendicular = |c: (i32, i32)| (c.0 - bq.0) * e.0 + (c.1 - bq.1) * e.1 == 0;
                let (ls, lt) = (laid(s), laid(t));
                !(ls.is_none() && lt.is_none()) && [ls, lt].into_iter().flatten().all(perpendicular)
            } else {
                // a sharp edge a–b: the ray runs along it, q on one side, p on the other
                mesh.is_sharp(a, b)
            };
            if !across {
                continue;
            }
            if found.is_some_and(|g| g != (a, b, pv)) {
                return Err("a ring face's window has a position two sharp rays extend differently".into());
            }
            found = Some((a, b, pv));
        }
        let (a, b, pv) = found.ok_or("a ring face's window lacks a point that no sharp ray accounts for")?;
        let (pa, pb, pp) = (p(a)?, p(b)?, p(pv)?);
        value.insert(q, [pa[0] + pb[0] - pp[0], pa[1] + pb[1] - pp[1]]);
        source.insert(q, WindowSource::Ghost(a, b, pv));
        ghosts += 1;
    }
    // the derivatives along the lattice's first two directions are convex
    // combinations of the window's differences along them (each box spline
    // without that direction is a non-negative partition of unity, and both
    // ends of a difference it weighs on the face are window positions)
    let (mut along_u, mut along_v) = (Vec::new(), Vec::new());
    let diff = |a: Point, b: Point| [b[0] - a[0], b[1] - a[1]];
    for &(x, y) in &positions {
        if let Some(&next) = value.get(&(x + 1, y)) {
            along_u.push(diff(value[&(x, y)], next));
        }
        if let Some(&next) = value.get(&(x, y + 1)) {
            along_v.push(diff(value[&(x, y)], next));
        }
    }
    // the rows on a sharp ray: the face's own sharp edges (the limit along
    // one is the cubic B-spline of the four ray points of its window row,
    // for both hosts: the boundary rules are that curve's)
    let mut rows = Vec::new();
    let mut row_positions = Vec::new();
    if ghosts > 0 {
        for k in 0..m {
            let (a, b) = (face[k], face[(k + 1) % m]);
            if !(on_ray(a) && on_ray(b) && mesh.is_sharp(a, b)) {
                continue;
            }
            let (ca, cb) = (coords.at(a), coords.at(b));
            let step = (cb.0 - ca.0, cb.1 - ca.1);
            let positions: Vec<(i32, i32)> = (-1..=2).map(|s| (ca.0 + s * step.0, ca.1 + s * step.1)).collect();
            rows.push(positions.iter().map(|c| value.get(c).copied().ok_or_else(conflict)).collect::<Result<_, _>>()?);
            row_positions.push(positions);
        }
    }
    let mut ids: Vec<(i32, i32)> = value.keys().copied().collect();
    ids.sort_unstable();
    let points: Vec<Point> = ids.iter().map(|c| value[c]).collect();
    let layout = ids.iter().map(|c| (*c, source[c])).collect();
    Ok(BoundaryWindow {
        window: Window { face: f, faces, along_u, along_v, points, ..Window::default() },
        rows,
        layout,
        row_positions,
    })
}

/// Lemma B3's rule check: at every entity the windows' limits depend on
/// (the ring faces' corners and the edges meeting them; for quads also the
/// one-ring's faces), the scheme's rational stencil equals the
/// ghost-extended host box spline's: inside, the host's regular masks
/// (bicubic: 9/16, 3/32, 1/64; 3/8, 1/16; 1/4. quartic box: 5/8, 1/16;
/// 3/8, 3/8, 1/8, 1/8); at a vertex on a sharp ray, 3/4 on it and 1/8 on its
/// two ray neighbours; on a sharp edge, the midpoint — what either host's
/// rules give on its ghost extension (`GhostHost::ghost_candidates`), the
/// cubic B-spline's along the ray. Returns the number of stencils compared.
fn check_boundary_rules(
    scheme: &dyn Scheme,
    mesh: &PolyMesh,
    windows: &[BoundaryWindow],
    host: GhostHost,
) -> Result<usize, String> {
    let mut corners: HashSet<usize> = HashSet::new();
    let mut faces: HashSet<usize> = HashSet::new();
    for w in windows {
        corners.extend(mesh.face(w.window.face).iter().copied());
        faces.extend(w.window.faces.iter().copied());
    }
    let refined = connectivity(scheme, mesh).map_err(|e| format!("the net could not be refined: {e}"))?;
    let vf = mesh.vertex_faces();
    let ratio = |p: i64, q: i64| <SmallRational as Weight>::ratio(p, q);
    let mut checked = 0;
    for &origin in &refined.vertex_origins {
        let mask: Mask = match origin {
            Origin::Vertex(v) if corners.contains(&v) => match mesh.vertex_tag(v) {
                VertexTag::Crease(a, b) => [(v, ratio(3, 4)), (a, ratio(1, 8)), (b, ratio(1, 8))].into_iter().collect(),
                _ => vertex_masks(mesh, &vf, v, false)?
                    .into_iter()
                    .find(|(k, _)| *k == host.regular_part())
                    .map(|(_, m)| m)
                    .ok_or("a vertex over the ring is not a regular vertex of the host")?,
            },
            Origin::Edge(a, b) if corners.contains(&a) || corners.contains(&b) => {
                if mesh.is_sharp(a, b) {
                    [(a, ratio(1, 2)), (b, ratio(1, 2))].into_iter().collect()
                } else {
                    let (kind, m) = edge_mask(mesh, &vf, a, b, false)?;
                    if kind != host.regular_part() {
                        return Err("an edge over the ring is not between two faces of the host".into());
                    }
                    m
                }
            }
            Origin::Face(g) if faces.contains(&g) && host == GhostHost::Bicubic => {
                mesh.face(g).iter().map(|&v| (v, ratio(1, 4))).collect()
            }
            _ => continue,
        };
        let got = exact_stencil(scheme, mesh, origin)?;
        if got != mask {
            return Err(format!(
                "numerical only: at {origin:?} the stencil is not the ghost-extended {}'s mask, so the ring is not \
                 a box spline of its net",
                host.name()
            ));
        }
        checked += 1;
    }
    Ok(checked)
}

/// Lemma B6: the winding number of the annulus's inner chain (from one
/// sharp ray to the other) followed by its mirror image in the line the
/// rays map to, from half-planes holding the windows' hulls (the argument
/// of `charmap::winding_number`, the mirrored arcs in the mirrored
/// half-planes).
fn doubled_winding(
    net: &Net<Point>,
    ring: &[usize],
    inside: &[usize],
    windows: &[BoundaryWindow],
    normal: usize,
) -> Result<ChainEvidence, String> {
    let mesh = &net.mesh;
    let mut half: HashSet<(usize, usize)> = HashSet::new();
    for &f in inside {
        let face = mesh.face(f);
        for k in 0..face.len() {
            half.insert((face[k], face[(k + 1) % face.len()]));
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
    // the inner chain: the inside region's boundary edges with a ring face
    // beside them (the others lie on the sharp rays)
    let mut next: HashMap<usize, (usize, usize)> = HashMap::new();
    for &(a, b) in &half {
        if half.contains(&(b, a)) {
            continue;
        }
        if let Some(&w) = ring_of_half.get(&(b, a)) {
            if next.insert(a, (b, w)).is_some() {
                return Err("the inner chain is not simple".into());
            }
        }
    }
    let targets: HashSet<usize> = next.values().map(|&(b, _)| b).collect();
    let starts: Vec<usize> = next.keys().copied().filter(|a| !targets.contains(a)).collect();
    let [start] = starts.as_slice() else {
        return Err("the inner chain is not one open chain from ray to ray".into());
    };
    let point = |v: usize| net.points[v].ok_or_else(|| "a chain vertex has no point".to_string());
    let mut vertices = vec![*start];
    let mut arcs = Vec::new();
    while let Some(&(b, w)) = next.get(vertices.last().expect("non-empty")) {
        arcs.push(w);
        vertices.push(b);
        if arcs.len() > next.len() {
            return Err("the inner chain does not end".into());
        }
    }
    if arcs.len() != next.len() {
        return Err("the inner chain has more than one component".into());
    }
    for &end in [vertices[0], *vertices.last().expect("non-empty")].iter() {
        let p = point(end)?;
        if !(p[normal].lo == 0.0 && p[normal].hi == 0.0) {
            return Err("an end of the inner chain is not exactly on the rays' line".into());
        }
    }
    let mirror = |d: [f64; 2]| {
        let mut m = d;
        m[normal] = -m[normal];
        m
    };
    let directions: Vec<[f64; 2]> =
        arcs.iter().map(|&w| half_plane(&windows[w].window.points, 0.0)).collect::<Result<_, String>>()?;
    let dot = |d: [f64; 2], w: [f64; 2]| {
        Interval::point(d[0]) * Interval::point(w[0]) + Interval::point(d[1]) * Interval::point(w[1])
    };
    // polygon vertex i is chain vertex i; arcs i−1 and i meet there
    let m = arcs.len();
    let mut polygon = Vec::with_capacity(2 * m);
    for (i, &v) in vertices.iter().enumerate() {
        let p = point(v)?;
        let w = [p[0].mid(), p[1].mid()];
        for arc in [i.checked_sub(1), (i < m).then_some(i)].into_iter().flatten() {
            if !(dot(directions[arc], w).lo > 0.0) {
                return Err("a chain vertex's point is not in both adjacent arcs' half-planes".into());
            }
        }
        polygon.push(w);
    }
    let half_polygon = polygon.clone();
    // the mirrored chain back: σw_{m−1}, …, σw_1 (the ends lie on the line)
    for i in (1..m).rev() {
        polygon.push(mirror(polygon[i]));
    }
    let number = polygon_winding(&polygon)?;
    Ok(ChainEvidence { vertices, arcs, directions, polygon: half_polygon, number })
}

/// S on the analysis neighbourhood, every weight enclosed (dense rows).
fn interval_matrix(scheme: &dyn Scheme, analysis: &Analysis) -> Result<Vec<Vec<Interval>>, String> {
    let size = analysis.discovered.analysis.len();
    let everyone: Vec<usize> = (0..size).collect();
    let rows = assemble_rows::<Interval>(scheme, &analysis.discovered, analysis.spectrum.neighbourhood, &everyone)
        .map_err(|e| format!("the interval rows of S could not be assembled: {e:?}"))?;
    Ok(super::tagged::dense(&rows, size, Interval::point(0.0)))
}

/// The block of S the eigenvector lives in (`spectrum::reflection::split`).
fn block_matrix(s: &[Vec<Interval>], image: Option<&Vec<usize>>, name: &str) -> Result<Vec<Vec<Interval>>, String> {
    match (name, image) {
        ("whole", _) => Ok(s.to_vec()),
        (_, Some(image)) => {
            let b = split(s, image);
            Ok(if name == "even" { b.even } else { b.odd })
        }
        _ => Err("no reflection".into()),
    }
}

/// Krawczyk's test for a simple real eigenpair (the unknowns: x with its
/// largest entry x_s fixed to 1, and μ in slot s; F = A·x − μ·x). If
/// K(Y) = −R·F(ũ) + (I − R·J(ũ + Y))·Y lies inside Y, every A in the
/// interval block has exactly one zero in ũ + Y (Krawczyk 1969; Rump 2001,
/// "Computational error bounds for multiple or nearly multiple
/// eigenvalues"): a real eigenpair. Its μ is proved inside one of the
/// named component's discs, which hold exactly one eigenvalue of A, so the
/// eigenpair is the named one. Returns x.
fn krawczyk_eigenpair(
    a: &[Vec<Interval>],
    start: &[Interval],
    component: &super::discs::Component,
) -> Result<(Vec<Interval>, EigenvectorEvidence), String> {
    use nalgebra::{DMatrix, DVector};
    let k = a.len();
    if k == 0 || start.len() != k {
        return Err("sizes".into());
    }
    let s = (0..k).max_by(|&i, &j| start[i].mid().abs().total_cmp(&start[j].mid().abs())).ok_or("empty")?;
    let scale = start[s].mid();
    if scale == 0.0 {
        return Err("zero start".into());
    }
    let mid = DMatrix::from_fn(k, k, |i, j| a[i][j].mid());
    let mut x = DVector::from_fn(k, |i, _| start[i].mid() / scale);
    x[s] = 1.0;
    let mut mu = (&mid * &x)[s];
    // the float Jacobian at (x, μ): column l ≠ s is A[:, l] − μ e_l, column s is −x
    let jacobian = |x: &DVector<f64>, mu: f64| {
        let mut j = mid.clone();
        for l in 0..k {
            j[(l, l)] -= mu;
        }
        for i in 0..k {
            j[(i, s)] = -x[i];
        }
        j
    };
    // a few float Newton steps polish the start
    for _ in 0..3 {
        let r = jacobian(&x, mu).try_inverse().ok_or("singular Jacobian")?;
        let f = &mid * &x - mu * &x;
        let step = r * f;
        for i in 0..k {
            if i == s {
                mu -= step[i];
            } else {
                x[i] -= step[i];
            }
        }
    }
    let r = jacobian(&x, mu).try_inverse().ok_or("singular Jacobian")?;
    let xi: Vec<Interval> = (0..k).map(|i| Interval::point(x[i])).collect();
    let mui = Interval::point(mu);
    // F(ũ) enclosed
    let f: Vec<Interval> = (0..k)
        .map(|i| {
            let mut acc = Interval::point(0.0) - mui * xi[i];
            for j in 0..k {
                acc = acc + a[i][j] * xi[j];
            }
            acc
        })
        .collect();
    let times_r = |v: &[Interval]| -> Vec<Interval> {
        (0..k)
            .map(|i| {
                let mut acc = Interval::point(0.0);
                for j in 0..k {
                    acc = acc + Interval::point(r[(i, j)]) * v[j];
                }
                acc
            })
            .collect()
    };
    let z: Vec<Interval> = times_r(&f).into_iter().map(|v| Interval::point(0.0) - v).collect();
    let mut y: Vec<Interval> = z
        .iter()
        .map(|v| {
            let m = v.lo.abs().max(v.hi.abs());
            Interval::symmetric(2.0 * m + 1e-300)
        })
        .collect();
    for _ in 0..8 {
        // J(ũ + Y) as an interval matrix, then C = I − R·J
        let mu_y = mui + y[s];
        let jy: Vec<Vec<Interval>> = (0..k)
            .map(|i| {
                (0..k)
                    .map(|l| {
                        if l == s {
                            if i == s {
                                Interval::point(-1.0)
                            } else {
                                Interval::point(0.0) - (xi[i] + y[i])
                            }
                        } else if i == l {
                            a[i][l] - mu_y
                        } else {
                            a[i][l]
                        }
                    })
                    .collect()
            })
            .collect();
        let mut kr = z.clone();
        for i in 0..k {
            for l in 0..k {
                let mut rj = Interval::point(0.0);
                for m in 0..k {
                    rj = rj + Interval::point(r[(i, m)]) * jy[m][l];
                }
                let c = Interval::point(if i == l { 1.0 } else { 0.0 }) - rj;
                kr[i] = kr[i] + c * y[l];
            }
        }
        let inside = kr.iter().zip(&y).all(|(kv, yv)| kv.lo > yv.lo && kv.hi < yv.hi);
        if inside {
            let mu_enclosed = mui + kr[s];
            let held = component.discs.iter().any(|d| {
                let d2 = (mu_enclosed - Interval::point(d.re)).square() + Interval::point(d.im).square();
                d2.hi < Interval::point(d.radius).square().lo
            });
            if !held {
                return Err("the eigenvalue found is not shown to be the named one".into());
            }
            let x_enclosed = (0..k).map(|i| if i == s { Interval::point(1.0) } else { xi[i] + kr[i] }).collect();
            let evidence = EigenvectorEvidence {
                block: "",
                component: 0,
                s,
                x: x.iter().copied().collect(),
                mu,
                r: (0..k).map(|i| (0..k).map(|j| r[(i, j)]).collect()).collect(),
                y: y.iter().map(|v| v.hi).collect(),
            };
            return Ok((x_enclosed, evidence));
        }
        // ε-inflation
        y = kr
            .iter()
            .map(|v| {
                let m = v.lo.abs().max(v.hi.abs());
                Interval::symmetric(1.5 * m + 1e-300)
            })
            .collect();
    }
    Err("Krawczyk's test did not verify".into())
}
