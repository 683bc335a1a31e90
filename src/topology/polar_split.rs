//! Polar split (polar bi-2 subdivision, PolBS): a polar net has poles
//! surrounded by triangle fans and rings of quads around them. Refinement is
//! binary in the radial direction only; the number of spokes never changes.
//!
//! Edges are radial (spokes from a pole and their continuations across quad
//! rings) or circumferential (the ring edges). Every face shrinks to a copy
//! of itself whose corner near old corner x is
//! * the new pole, for a pole x (`Vertex(x)`);
//! * `Edge(p, x)` on the spoke p–x, in a triangle at pole p;
//! * `Edge(x, y)` on the radial edge x–y of a quad (the point near x).
//!
//! Every interior circumferential edge gets a quad joining the shrunken faces
//! on its two sides (parent `Edge`), so each ring of quads becomes two rings.
//!
//! Charts: all vertices lie on spokes, at (spoke, ring, 0). The ring-r points
//! near x on the radial edge to ring r + 1 and r − 1 get rings 2r and 2r − 1
//! (one ring per radial half-segment), the spoke points ring 1, the pole stays at 0.
//!
//! The host unit (`Host::Polar`, scheme files `topology = "polar"`): the pole
//! rule, the spoke rule and the radial rule. It grows by 2 per level (each
//! ring of quads becomes two); no box spline of a lattice dilation.

use crate::mesh::IdMap;

use crate::error::Error;
use crate::mesh::FaceList;
use crate::mesh::PolyMesh;
use crate::mesh::SectorKind;
use crate::mesh::Tags;
use crate::sdc::host::{refuse_tags, Refined, RefinementHost, RegularSpline};
use crate::sdc::slots::Host;
use crate::sdc::slots::OriginKind::{Edge as E, Vertex as V};
use crate::sdc::slots::Valence::{Any, Fixed};
use crate::sdc::slots::{
    canonical, fam, rule, unsupported, Gather, GatherError, Gathered, HostSpec, Part, RuleSlots, Wants, ONE, PER_J,
};
use crate::sdc::CentreKind;
use crate::sdc::Origin;
use crate::topology::chart_builder::ChartBuilder;

/// A pole: an interior vertex whose faces are all triangles.
pub fn is_pole(mesh: &PolyMesh, v: usize) -> bool {
    mesh.fan_corners(v).is_some_and(|fan| fan.iter().all(|&(f, _)| mesh.face(f).len() == 3))
}

/// `is_pole` for every vertex, asked once: each triangle asks for its three
/// corners, and a pole of valence n has n triangles (n fan walks of length n).
fn poles(mesh: &PolyMesh) -> Vec<bool> {
    (0..mesh.num_vertices()).map(|v| is_pole(mesh, v)).collect()
}

fn key(a: usize, b: usize) -> (usize, usize) {
    (a.min(b), a.max(b))
}

/// Radial (true) or circumferential (false) for every edge.
fn classify(mesh: &PolyMesh, pole: &[bool]) -> Result<IdMap<(usize, usize), bool>, Error> {
    let mut radial: IdMap<(usize, usize), bool> = IdMap::default();
    let not_polar = |f: usize, why: &str| Error::Input(format!("not a polar net: face {} {why}", f + 1));
    let set =
        |map: &mut IdMap<(usize, usize), bool>, a: usize, b: usize, r: bool, f: usize| match map.insert(key(a, b), r) {
            Some(old) if old != r => Err(not_polar(f, "has an edge that is both radial and circumferential")),
            _ => Ok(()),
        };
    for (f, face) in mesh.faces().iter().enumerate() {
        match face.len() {
            3 => {
                let poles: Vec<usize> = (0..3).filter(|&k| pole[face[k]]).collect();
                let [k] = poles[..] else { return Err(not_polar(f, "is a triangle without exactly one pole")) };
                let (p, a, b) = (face[k], face[(k + 1) % 3], face[(k + 2) % 3]);
                set(&mut radial, p, a, true, f)?;
                set(&mut radial, p, b, true, f)?;
                set(&mut radial, a, b, false, f)?;
            }
            4 => {}
            _ => return Err(not_polar(f, "is neither a triangle at a pole nor a quad")),
        }
    }
    // propagate across quads: opposite edges have the same type, adjacent ones differ
    loop {
        let mut changed = false;
        for (f, face) in mesh.faces().iter().enumerate().filter(|(_, fc)| fc.len() == 4) {
            let e = |k: usize| key(face[k % 4], face[(k + 1) % 4]);
            let Some(k) = (0..4).find(|&k| radial.contains_key(&e(k))) else { continue };
            let r = radial[&e(k)];
            for (t, want) in [(k + 1, !r), (k + 2, r), (k + 3, !r)] {
                if radial.get(&e(t)) != Some(&want) {
                    set(&mut radial, face[t % 4], face[(t + 1) % 4], want, f)?;
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    if let Some(f) = (0..mesh.num_faces()).find(|&f| {
        let face = mesh.face(f);
        (0..face.len()).any(|k| !radial.contains_key(&key(face[k], face[(k + 1) % face.len()])))
    }) {
        return Err(not_polar(f, "is not reached from any pole through rings of quads"));
    }
    Ok(radial)
}

pub fn refine(mesh: &PolyMesh) -> Result<Refined, Error> {
    let pole = poles(mesh);
    let radial = classify(mesh, &pole)?;
    let mut origins: Vec<Origin> = Vec::new();
    let mut ids: IdMap<Origin, usize> = IdMap::default();
    let mut id = |o: Origin, origins: &mut Vec<Origin>| {
        *ids.entry(o).or_insert_with(|| {
            origins.push(o);
            origins.len() - 1
        })
    };
    // the new vertex of face `face` near its corner k
    let near = |face: &[usize], k: usize| -> Origin {
        let m = face.len();
        let x = face[k];
        if m == 3 {
            if pole[x] {
                return Origin::Vertex(x);
            }
            let p = *face.iter().find(|&&v| pole[v]).expect("classified");
            return Origin::Edge(p, x);
        }
        let (next, prev) = (face[(k + 1) % m], face[(k + m - 1) % m]);
        let y = if radial[&key(x, next)] { next } else { prev };
        Origin::Edge(x, y)
    };
    let mut faces = FaceList::new();
    let mut parents = Vec::new();
    for (f, face) in mesh.faces().iter().enumerate() {
        faces.push_iter((0..face.len()).map(|k| id(near(face, k), &mut origins)));
        parents.push(Origin::Face(f));
    }
    for (a, b) in mesh.edges() {
        if radial[&key(a, b)] {
            continue;
        }
        let (Some((f, ka)), Some((g, kg))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else { continue };
        let (ff, gf) = (mesh.face(f), mesh.face(g));
        let (kb, kga) = ((ka + 1) % ff.len(), (kg + 1) % gf.len());
        let quad = [near(ff, kb), near(ff, ka), near(gf, kga), near(gf, kg)];
        faces.push_iter(quad.into_iter().map(|o| id(o, &mut origins)));
        parents.push(Origin::Edge(a, b));
    }
    let mut new_mesh = PolyMesh::new(origins.len(), faces).map_err(|e| Error::Input(e.to_string()))?;
    if let Some(chart) = mesh.chart.as_ref().filter(|c| c.scale == 1) {
        let mut cb = ChartBuilder::new(chart);
        for o in &origins {
            match *o {
                Origin::Vertex(v) => {
                    let c = chart.vertex_coords[v];
                    cb.push(c.sector, 0, 0);
                    cb.ok &= c.is_centre();
                }
                Origin::Edge(x, y) => {
                    let (cx, cy) = (chart.vertex_coords[x], chart.vertex_coords[y]);
                    let ring = if cx.is_centre() {
                        1
                    } else if cy.i > cx.i {
                        2 * cx.i
                    } else {
                        2 * cx.i - 1
                    };
                    let spoke = if cx.is_centre() { cy.sector } else { cx.sector };
                    cb.ok &= cx.j == 0 && cy.j == 0;
                    cb.push(spoke, ring, 0);
                }
                _ => unreachable!("the polar split creates pole and radial points only"),
            }
        }
        for (k, p) in parents.iter().enumerate() {
            let s = match *p {
                Origin::Face(f) => chart.face_sector[f],
                _ => None,
            };
            // a joining quad lies in the sector of its first corner's spoke
            let first = new_mesh.face(k)[0];
            cb.face_sector.push(Some(s.unwrap_or(cb.coords[first].sector)));
        }
        new_mesh.chart = cb.finish(1);
    }
    Ok(Refined { mesh: new_mesh, vertex_origins: origins, face_parents: parents })
}

/// The host unit: everything the engine asks of this host.
pub struct PolarSplit;

static SPEC: HostSpec = HostSpec {
    host: Host::Polar,
    name: "polar",
    sector: SectorKind::Tri,
    centre: CentreKind::Polar,
    face_control: false,
    rules: RULES,
};

impl RefinementHost for PolarSplit {
    fn spec(&self) -> &'static HostSpec {
        &SPEC
    }
    fn refine(&self, mesh: &PolyMesh) -> Result<Refined, Error> {
        refine(mesh)
    }
    fn refine_tags(&self, mesh: &PolyMesh, _: &[Origin]) -> Result<Option<Tags>, Error> {
        refuse_tags(Host::Polar, mesh)
    }
    fn gather(&self, mesh: &PolyMesh, origin: Origin, _wants: &dyn Wants) -> Gather {
        match origin {
            Origin::Vertex(p) => {
                mesh.fan_corners(p).ok_or(GatherError::Truncated)?;
                let ring = mesh.uniform_ring(p, 3).ok_or(GatherError::NotCovered)?;
                let mut part = Part::around("pole", ring.len(), p);
                part.put("centre", 0, p);
                ring.iter().enumerate().for_each(|(j, &a)| part.put("ring", j, a));
                Ok(Gathered::one(part))
            }
            // the pole's ring from the mesh's cached fan: every spoke point asks
            // for it, and copying the fan each time would be quadratic in n
            Origin::Edge(x, y) => match mesh.uniform_ring(x, 3) {
                // x is a pole: the spoke rule, ring turned so that a_0 = y
                Some(ring) => {
                    let n = ring.len();
                    let i = ring.iter().position(|&a| a == y).ok_or(GatherError::NotCovered)?;
                    let mut part = Part::around("spoke", n, x);
                    part.put("pole", 0, x);
                    (0..n).for_each(|j| part.put("ring", j, ring[(i + j) % n]));
                    Ok(Gathered::one(part))
                }
                None => {
                    let mut part = Part::new("radial", 2);
                    part.put("near", 0, x);
                    part.put("far", 0, y);
                    Ok(Gathered::one(part))
                }
            },
            Origin::Face(_) | Origin::Corner { .. } => unsupported(Host::Polar, origin),
        }
    }
    fn steps_per_analysis(&self) -> usize {
        1
    }
    fn growth_per_level(&self) -> usize {
        2
    }
    fn size_bound(&self, mesh: &PolyMesh) -> usize {
        let corners: usize = mesh.faces().iter().map(|f| f.len()).sum();
        let (v, e, f) = (mesh.num_vertices(), mesh.edges().len(), mesh.num_faces());
        // every face shrinks to a copy (one new point per corner at most) and
        // every edge gets a joining quad
        (f + e).max(corners + v)
    }
    fn mesh_requirement(&self) -> &'static str {
        "a closed polar net (poles with triangle fans, rings of quads)"
    }
    fn regular_spline(&self) -> RegularSpline {
        RegularSpline::NoBoxSpline
    }
}

const RULES: &[RuleSlots] = &[
    rule(
        "pole",
        V,
        Any,
        &[fam("centre", ONE, "the pole p"), fam("ring", PER_J, "the pole's j-th neighbour")],
        "the new pole (n spokes)",
    ),
    canonical(
        "spoke",
        E,
        &[fam("pole", ONE, "the pole p"), fam("ring", PER_J, "a_j, the pole's neighbours, a_0 the spoke's end")],
        false,
        "the new vertex on spoke p-a_0",
    ),
    rule(
        "radial",
        E,
        Fixed(2),
        &[fam("near", ONE, "the near end x of radial edge x-y"), fam("far", ONE, "the far end y")],
        "the new vertex on a radial edge near x (away from the pole)",
    ),
];

#[cfg(test)]
mod tests {
    use super::super::host_tests::check_host;
    use super::*;

    /// A polar sphere: poles 0 and 1, `rings` rings of n vertices between
    /// them, n triangles at each pole and rings − 1 rings of n quads.
    fn polar_sphere(n: usize, rings: usize) -> PolyMesh {
        let ring = |r: usize, s: usize| 2 + r * n + s % n;
        let mut faces = Vec::new();
        for s in 0..n {
            faces.push(vec![0, ring(0, s), ring(0, s + 1)]);
            faces.push(vec![1, ring(rings - 1, s + 1), ring(rings - 1, s)]);
            for r in 0..rings - 1 {
                faces.push(vec![ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s + 1)]);
            }
        }
        PolyMesh::new(2 + rings * n, faces).unwrap()
    }

    /// Every face shrinks to a copy and every circumferential edge (n per
    /// ring) gets a quad: F' = F + rings·n = 2F − n. The ratio F'/F tends to
    /// the stated growth 2 as the rings multiply (and never exceeds it).
    #[test]
    fn states_its_growth_bound_and_rules() {
        let n = 5;
        for rings in 2..6 {
            let sphere = polar_sphere(n, rings);
            let f = sphere.num_faces();
            assert_eq!(f, (rings + 1) * n);
            check_host(Host::Polar, &sphere, f + rings * n, false);
            assert_eq!(PolarSplit.growth_per_level() * f - (f + rings * n), n);
        }
    }
}
