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

use crate::mesh::IdMap;

use super::{ChartBuilder, Refined};
use crate::error::Error;
use crate::mesh::PolyMesh;
use crate::sdc::Origin;

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
    let mut faces = Vec::new();
    let mut parents = Vec::new();
    for (f, face) in mesh.faces().iter().enumerate() {
        faces.push((0..face.len()).map(|k| id(near(face, k), &mut origins)).collect::<Vec<_>>());
        parents.push(Origin::Face(f));
    }
    for (a, b) in mesh.edges() {
        if radial[&key(a, b)] {
            continue;
        }
        let (Some((f, ka)), Some((g, kg))) = (mesh.half_edge(a, b), mesh.half_edge(b, a)) else { continue };
        let (ff, gf) = (mesh.face(f), mesh.face(g));
        let (kb, kga) = ((ka + 1) % ff.len(), (kg + 1) % gf.len());
        let quad = vec![near(ff, kb), near(ff, ka), near(gf, kga), near(gf, kg)];
        faces.push(quad.into_iter().map(|o| id(o, &mut origins)).collect());
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
