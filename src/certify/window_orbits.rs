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
//! fails, every ring face is checked, as before. Tests:
//! tests/certify_charmap.rs (each orbit of ring faces holds exactly one
//! representative, with the rotation rebuilt there from the chart; data the
//! rotation does not keep turns the reduction off).

use crate::charmap::net::Net;
use crate::neighbourhood::discovery::Rotation;

/// The positions in `ring` of the faces whose windows the rule check needs:
/// one per orbit of the rotation by `period` sectors, or every position
/// when no rotation of the net is established.
pub fn representatives<T>(net: &Net<T>, ring: &[usize], period: usize) -> Vec<usize> {
    RingOrbits::new(net, ring, period).orbits.iter().map(|o| o[0]).collect()
}

/// Per position in `ring`, the position of its orbit's representative
/// (itself for a representative, and for every face when no rotation of the
/// net is established).
pub fn representative_of<T>(net: &Net<T>, ring: &[usize], period: usize) -> Vec<usize> {
    RingOrbits::new(net, ring, period).representative_of(ring.len())
}

/// The ring's faces in orbits of the rotation by `period` sectors (lemmas
/// C3 and C5′): each orbit in turn order from its representative, as
/// positions in `ring`, with the vertex turn that carries each member onto
/// the next. Every face is its own orbit when no rotation is established,
/// and also when the orbits are not what a free rotation of the ring gives
/// (an image outside the ring, a face with two corners in one orbit).
pub struct RingOrbits {
    pub orbits: Vec<Vec<usize>>,
    rotation: Option<Rotation>,
}

impl RingOrbits {
    pub fn new<T>(net: &Net<T>, ring: &[usize], period: usize) -> RingOrbits {
        let singletons = || RingOrbits { orbits: (0..ring.len()).map(|i| vec![i]).collect(), rotation: None };
        let Some(rotation) = rotation_of(net, period) else { return singletons() };
        let mesh = &net.mesh;
        let mut position = vec![usize::MAX; mesh.num_faces()];
        for (i, &f) in ring.iter().enumerate() {
            position[f] = i;
        }
        // the image of a face: the face holding the turned first edge (the
        // rotation was checked to map every face onto one, corners in order)
        let turned = |f: usize| -> Option<usize> {
            let face = mesh.face(f);
            let (a, b) = (rotation.turned(face[0])?, rotation.turned(face[1])?);
            mesh.half_edge(a, b).map(|(g, _)| g)
        };
        let mut placed = vec![false; ring.len()];
        let mut orbits = Vec::new();
        for i in 0..ring.len() {
            if placed[i] || !represents(mesh, &rotation, ring[i]) {
                continue;
            }
            let mut orbit = vec![i];
            let mut f = ring[i];
            loop {
                let Some(g) = turned(f) else { return singletons() };
                let p = position[g];
                if p == i {
                    break;
                }
                // a second representative in one orbit is a face with two
                // corners in one orbit (it represents itself)
                if p == usize::MAX || placed[p] || orbit.len() >= rotation.order() || represents(mesh, &rotation, g) {
                    return singletons();
                }
                orbit.push(p);
                f = g;
            }
            for &p in &orbit {
                placed[p] = true;
            }
            orbits.push(orbit);
        }
        if placed.contains(&false) {
            return singletons();
        }
        RingOrbits { orbits, rotation: Some(rotation) }
    }

    /// Per position, the position of its orbit's representative.
    pub fn representative_of(&self, len: usize) -> Vec<usize> {
        let mut of = vec![usize::MAX; len];
        for orbit in &self.orbits {
            for &p in orbit {
                of[p] = orbit[0];
            }
        }
        of
    }

    /// The vertex that `v` is turned to (None without a rotation).
    pub(crate) fn turned(&self, v: usize) -> Option<usize> {
        self.rotation.as_ref()?.turned(v)
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
