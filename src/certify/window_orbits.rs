//! One ring face per rotation orbit for the certificate's rule check.
//!
//! The rule check (`charmap::check_rules`, lemma C3) compares the scheme's
//! exact stencils at every entity of every ring face's window with a box
//! spline's masks. The ring is invariant under the configuration's
//! rotation ρ (by `period` sectors), and the rules are functions of the
//! combinatorics in their slots (the premise C3 already rests on to carry a
//! match from one level to every later one): where ρ is an automorphism of
//! the net's mesh that keeps everything a rule reads — the faces with their
//! cyclic order, the face points, the per-vertex parameters, no tags and no
//! lattice directions — the stencil at ρ(e) is ρ applied to the stencil at
//! e, and the box-spline mask at ρ(e) is ρ applied to the mask at e (the
//! masks are combinatorial too). So a window whose entities all match has
//! images that all match, and checking one window per orbit decides the
//! same as checking all of them, at 1/g of the cost (g = n / period).
//!
//! Everything here is combinatorial and checked, not assumed: ρ comes from
//! the lattice chart (`neighbourhood::discovery::Rotation`) and is accepted
//! only after every face of the net is shown to map onto a face with its
//! corners in the same cyclic order and the same ring flags. Where anything
//! fails, every ring face is checked, as before.

use crate::charmap::net::Net;
use crate::neighbourhood::discovery::Rotation;

/// The positions in `ring` of the faces whose windows the rule check needs:
/// one per orbit of the rotation by `period` sectors, or every position
/// when no rotation of the net is established.
pub(super) fn representatives<T>(net: &Net<T>, ring: &[usize], period: usize) -> Vec<usize> {
    match rotation_of(net, period) {
        Some(rotation) => (0..ring.len()).filter(|&i| represents(&net.mesh, &rotation, ring[i])).collect(),
        None => (0..ring.len()).collect(),
    }
}

/// The rotation of the net by `period` sectors, when it is an automorphism
/// of the net's mesh keeping every datum a rule reads and the ring flags.
fn rotation_of<T>(net: &Net<T>, period: usize) -> Option<Rotation> {
    let mesh = &net.mesh;
    // tags and lattice directions are data the automorphism would have to
    // carry as well: such nets are checked whole
    if mesh.tags.is_some() || mesh.lattice_dirs.is_some() {
        return None;
    }
    let rotation = Rotation::new(mesh, period, true);
    if rotation.order() < 2 {
        return None;
    }
    let turn = |v: usize| rotation.turned(v);
    for f in 0..mesh.num_faces() {
        let face = mesh.face(f);
        let image: Vec<usize> = face.iter().map(|&v| turn(v)).collect::<Option<_>>()?;
        let (g, k) = mesh.half_edge(image[0], image[1])?;
        let target = mesh.face(g);
        if target.len() != image.len() || (0..image.len()).any(|i| target[(k + i) % target.len()] != image[i]) {
            return None;
        }
        let same = |flags: &[bool]| flags.get(f) == flags.get(g);
        if !same(&net.outer) || !same(&net.inner) || !same(&net.inner2) {
            return None;
        }
        match (mesh.face_point(f), mesh.face_point(g)) {
            (None, None) => {}
            (Some(p), Some(q)) if turn(p) == Some(q) => {}
            _ => return None,
        }
    }
    if let Some(params) = &mesh.vertex_params {
        // the same parameter bit for bit at every vertex and its image
        if (0..params.len()).any(|v| turn(v).is_none_or(|w| params[w].to_bits() != params[v].to_bits())) {
            return None;
        }
    }
    Some(rotation)
}

/// Whether face `f` is its orbit's representative: its anchor (the corner
/// whose orbit representative has the smallest id; ρ maps the anchor of f
/// to the anchor of ρf) is its own representative. A face with two corners
/// in one orbit has no well-defined anchor and represents itself.
fn represents(mesh: &crate::mesh::PolyMesh, rotation: &Rotation, f: usize) -> bool {
    let face = mesh.face(f);
    let mut reps: Vec<usize> = face.iter().map(|&v| rotation.rep(v)).collect();
    let anchor = face[(0..face.len()).min_by_key(|&i| reps[i]).expect("a face has corners")];
    reps.sort_unstable();
    let tie = reps.windows(2).any(|w| w[0] == w[1]);
    tie || rotation.rep(anchor) == anchor
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::charmap::net::refine_net_exactly_as;
    use crate::neighbourhood::Configuration;
    use crate::spectrum::{analyse, Options};

    /// The net of a certificate's first try (two analysis steps) with
    /// placeholder points (the faces and flags do not depend on them), its
    /// ring, and the rotation period.
    fn ring_net(name: &str, n: usize) -> (Net<[f64; 2]>, Vec<usize>, usize) {
        let scheme = crate::schemes::resolve(name, &[]).unwrap();
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        let analysis = analyse(scheme.as_ref(), &config, &Options::default()).unwrap();
        let d = &analysis.discovered;
        let level0 = vec![Some([0.0, 0.0]); d.patch.num_vertices()];
        let net = refine_net_exactly_as::<f64, [f64; 2]>(scheme.as_ref(), d, level0, 2).unwrap();
        let ring: Vec<usize> = (0..net.mesh.num_faces()).filter(|&f| net.outer[f] && !net.inner[f]).collect();
        (net, ring, config.rotation_period(scheme.as_ref()))
    }

    /// The image of face f under the rotation, found by its turned corners
    /// (independently of `rotation_of`'s check).
    fn turned_face(net: &Net<[f64; 2]>, rotation: &Rotation, f: usize) -> usize {
        let face = net.mesh.face(f);
        net.mesh.half_edge(rotation.turned(face[0]).unwrap(), rotation.turned(face[1]).unwrap()).unwrap().0
    }

    #[test]
    fn every_orbit_of_ring_faces_has_exactly_one_representative() {
        for (name, n) in [("catmull-clark", 5), ("loop", 7), ("doo-sabin", 6), ("tps", 4), ("catmull-clark", 3)] {
            let (net, ring, period) = ring_net(name, n);
            let reps = representatives(&net, &ring, period);
            // every sector of a regular configuration is alike: the ring's
            // faces fall into orbits of g = n / period faces each
            let g = n / period;
            assert_eq!(reps.len() * g, ring.len(), "{name} n = {n}: {} of {} faces", reps.len(), ring.len());
            let rotation = Rotation::new(&net.mesh, period, true);
            let is_rep: std::collections::HashSet<usize> = reps.iter().map(|&i| ring[i]).collect();
            for &f in &ring {
                let mut orbit = vec![f];
                while orbit.len() < g {
                    orbit.push(turned_face(&net, &rotation, *orbit.last().unwrap()));
                }
                assert_eq!(turned_face(&net, &rotation, orbit[g - 1]), f, "{name} n = {n}: g turns close the orbit");
                let met = orbit.iter().filter(|h| is_rep.contains(h)).count();
                assert_eq!(met, 1, "{name} n = {n}: the orbit of face {f} holds {met} representatives");
            }
        }
    }

    #[test]
    fn data_the_rotation_does_not_keep_turn_the_reduction_off() {
        let (mut net, ring, period) = ring_net("catmull-clark", 5);
        assert!(representatives(&net, &ring, period).len() < ring.len());
        // one vertex's parameter differs from its images'
        let mut params = vec![0.5; net.mesh.num_vertices()];
        params[net.mesh.face(ring[0])[0]] = 0.25;
        net.mesh.vertex_params = Some(params);
        assert_eq!(representatives(&net, &ring, period).len(), ring.len(), "an asymmetric per-vertex parameter");
        // the same parameter everywhere keeps the symmetry
        net.mesh.vertex_params = Some(vec![0.5; net.mesh.num_vertices()]);
        assert!(representatives(&net, &ring, period).len() < ring.len());
        // lattice directions are not carried by the rotation
        net.mesh.vertex_params = None;
        net.mesh.lattice_dirs = Some(vec![0; net.mesh.num_faces()]);
        assert_eq!(representatives(&net, &ring, period).len(), ring.len(), "lattice directions");
        // a flag that is not rotation-invariant: the ring itself is not
        net.mesh.lattice_dirs = None;
        net.inner[ring[0]] = true;
        assert_eq!(representatives(&net, &ring, period).len(), ring.len(), "a ring that does not turn");
    }
}
