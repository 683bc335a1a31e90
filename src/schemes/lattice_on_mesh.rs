//! A regular-lattice scheme (four masks over (i, j) offsets, `crate::lattice`)
//! applied to quad meshes that carry lattice directions: analysis patches of
//! valence 4 (directions from the sector charts, which are the plane Z² turned
//! by a quarter per sector) and closed regular quad meshes oriented with
//! `PolyMesh::orient_lattice`. The masks stay the single source of the rules;
//! this file only finds which old vertex sits at offset (r, s).
//!
//! The topology is Catmull–Clark's quad split: the new vertex of an old vertex
//! is p_{2i,2j}, of a +i edge p_{2i+1,2j}, of a +j edge p_{2i,2j+1}, of a face
//! p_{2i+1,2j+1} (with (i, j) the face's corner whose outgoing edge is +i).

use crate::lattice::{LatticeScheme, LatticeWeight};
use crate::mesh::{PolyMesh, SectorKind};
use crate::numeric::{Cyclotomic, Interval, Rational, SmallRational, TPoly};
use crate::sdc::slots::OriginKind;
use crate::sdc::{Caps, CentreKind, MeshDomain, Params, Rules, Scheme, SchemeInfo};
use crate::sdc::{GatherError, Topology};
use crate::sdc::{Origin, RuleResult, Stencil};

pub struct LatticeOnMesh {
    inner: Box<dyn LatticeScheme>,
    params: Params,
    info: SchemeInfo,
}

impl LatticeOnMesh {
    pub fn new(inner: Box<dyn LatticeScheme>) -> Self {
        let info = SchemeInfo {
            name: inner.name(),
            description: inner.description(),
            topology: Topology::PrimalQuad,
            centre: CentreKind::Vertex,
            sector: SectorKind::Quad,
            caps: Caps {
                fixed_valence: Some(4),
                lattice_oriented: true,
                // asymmetric masks: the local matrix does not commute with the quarter turn
                rotation_symmetric: false,
                ..Caps::NONE
            },
        };
        // a lattice scheme file may have parameters; the mesh analyses report them
        let params = inner.params().clone();
        LatticeOnMesh { inner, params, info }
    }

    fn masks_on_mesh<W: LatticeWeight>(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        let ((alpha, beta), base) = match parity_and_base(mesh, origin) {
            Ok(found) => found,
            Err(cause) => return Ok(Err(cause)),
        };
        let mut s = Stencil::new();
        for ((r, t), w) in W::mask_of(self.inner.as_ref(), alpha, beta) {
            match walk(mesh, base, r, t) {
                Ok(v) => s.add(v, w),
                Err(cause) => return Ok(Err(cause)),
            }
        }
        Ok(Ok(s))
    }
}

/// Direction (0 = +i, 1 = +j, 2 = −i, 3 = −j) of edge k of face f.
fn edge_dir(mesh: &PolyMesh, f: usize, k: usize) -> Option<u8> {
    if mesh.face(f).len() != 4 {
        return None;
    }
    if let Some(d) = &mesh.lattice_dirs {
        return Some(((d[f] as usize + k) % 4) as u8);
    }
    // a valence-4 analysis patch: chart s is the plane turned by s quarter turns
    let chart = mesh.chart.as_ref().filter(|c| c.sectors() == 4)?;
    let s = chart.face_sector[f]?;
    let face = mesh.face(f);
    let (a, b) =
        (chart.in_chart(chart.vertex_coords[face[k]], s), chart.in_chart(chart.vertex_coords[face[(k + 1) % 4]], s));
    let local = match (b.0 - a.0, b.1 - a.1) {
        (x, 0) if x > 0 => 0,
        (0, y) if y > 0 => 1,
        (x, 0) if x < 0 => 2,
        (0, y) if y < 0 => 3,
        _ => return None,
    };
    Some(((local + s) % 4) as u8)
}

/// The neighbour of v in direction `dir`: `Truncated` when v's fan has no
/// face there (the rim of a patch), `NotCovered` when a face around v is not
/// a quad with lattice directions.
fn step(mesh: &PolyMesh, v: usize, dir: u8) -> Result<usize, GatherError> {
    for f in mesh.faces_around(v) {
        let face = mesh.face(f);
        let k = face.iter().position(|&u| u == v).ok_or(GatherError::NotCovered)?;
        if edge_dir(mesh, f, k).ok_or(GatherError::NotCovered)? == dir {
            return Ok(face[(k + 1) % face.len()]);
        }
    }
    Err(GatherError::Truncated)
}

/// The vertex at lattice offset (r, s) from v (i first, then j: on a regular
/// grid any path gives the same vertex).
fn walk(mesh: &PolyMesh, v: usize, r: i64, s: i64) -> Result<usize, GatherError> {
    let mut v = v;
    for _ in 0..r.unsigned_abs() {
        v = step(mesh, v, if r > 0 { 0 } else { 2 })?;
    }
    for _ in 0..s.unsigned_abs() {
        v = step(mesh, v, if s > 0 { 1 } else { 3 })?;
    }
    Ok(v)
}

/// The mask parity of the new vertex and the old vertex (i, j) it is based
/// at; `NotCovered` where the faces at the origin carry no lattice
/// directions, `Unsupported` for a corner (the quad split creates none).
fn parity_and_base(mesh: &PolyMesh, origin: Origin) -> Result<((u8, u8), usize), GatherError> {
    let uncovered = GatherError::NotCovered;
    match origin {
        Origin::Vertex(v) => Ok(((0, 0), v)),
        Origin::Edge(a, b) => {
            let (f, k, reversed) = match mesh.half_edge(a, b) {
                Some((f, k)) => (f, k, false),
                None => {
                    let (f, k) = mesh.half_edge(b, a).ok_or(uncovered)?;
                    (f, k, true)
                }
            };
            let mut d = edge_dir(mesh, f, k).ok_or(uncovered)?;
            if reversed {
                d = (d + 2) % 4;
            }
            // a -> b has direction d
            Ok(match d {
                0 => ((1, 0), a),
                2 => ((1, 0), b),
                1 => ((0, 1), a),
                _ => ((0, 1), b),
            })
        }
        Origin::Face(f) => {
            let k = (0..4).find(|&k| edge_dir(mesh, f, k) == Some(0)).ok_or(uncovered)?;
            Ok(((1, 1), mesh.face(f)[k]))
        }
        Origin::Corner { .. } => Err(GatherError::Unsupported(Topology::PrimalQuad, OriginKind::of(origin))),
    }
}

impl Rules<MeshDomain, f64> for LatticeOnMesh {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<f64> {
        self.masks_on_mesh::<f64>(mesh, origin)
    }
}

impl Rules<MeshDomain, Rational> for LatticeOnMesh {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<Rational> {
        self.masks_on_mesh::<Rational>(mesh, origin)
    }
}

/// The rational masks in machine integers (spoiled where they do not fit).
impl Rules<MeshDomain, SmallRational> for LatticeOnMesh {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<SmallRational> {
        let exact = self.masks_on_mesh::<Rational>(mesh, origin)?;
        Ok(exact
            .map(|s| Stencil { terms: s.terms.iter().map(|(v, w)| (*v, SmallRational::from_rational(w))).collect() }))
    }
}

/// Lattice masks are exact rationals or floats: enclosures exist for the
/// rational ones only (the lattice family has no interval rules of its own).
impl Rules<MeshDomain, Interval> for LatticeOnMesh {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<Interval> {
        let exact = self.masks_on_mesh::<Rational>(mesh, origin)?;
        Ok(exact.map(|s| Stencil { terms: s.terms.iter().map(|(v, w)| (*v, Interval::rational(w))).collect() }))
    }
}

/// The rational masks as elements of Q (the certificate's exact premises).
impl Rules<MeshDomain, Cyclotomic> for LatticeOnMesh {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<Cyclotomic> {
        let exact = self.masks_on_mesh::<Rational>(mesh, origin)?;
        Ok(exact.map(|s| Stencil { terms: s.terms.iter().map(|(v, w)| (*v, Cyclotomic::from_rational(w))).collect() }))
    }
}

/// No polynomial rows in a swept parameter: the lattice masks are read as
/// numbers, so every weight is the undefined element and the exact sweep
/// refuses the scheme (rather than take a parameter for a constant).
impl Rules<MeshDomain, TPoly> for LatticeOnMesh {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<TPoly> {
        let exact = self.masks_on_mesh::<Rational>(mesh, origin)?;
        Ok(exact.map(|s| Stencil { terms: s.terms.iter().map(|(v, _)| (*v, TPoly::undefined())).collect() }))
    }
}

impl Scheme for LatticeOnMesh {
    fn info(&self) -> &SchemeInfo {
        &self.info
    }
    fn params(&self) -> &Params {
        &self.params
    }
    /// A lattice scheme may come from a file whose name another file shares:
    /// not memoised (no registry claim analyses these on a mesh repeatedly).
    fn identity(&self) -> Option<String> {
        None
    }
}
