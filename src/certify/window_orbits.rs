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
    let of = representative_of(net, ring, period);
    (0..ring.len()).filter(|&i| of[i].rep == i).collect()
}

/// Where a ring face stands in its orbit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OrbitPlace {
    /// the position in the ring of the orbit's representative (the face's
    /// own for a representative)
    pub rep: usize,
    /// the representative's corner that the rotation carries to this face's
    /// first corner (0 for a representative): faces of one orbit with the
    /// same corner have their windows laid out alike (`Window::around` puts
    /// the first corner at the origin), rotated copies of each other
    pub corner: usize,
}

/// Per position in `ring`, its place in its orbit (itself with corner 0 for
/// a representative, and for every face when no rotation of the net is
/// established). The ring must be a union of orbits (the ring flags are
/// among what the rotation is checked to keep); a face whose orbit holds no
/// representative in the ring represents itself.
pub fn representative_of<T>(net: &Net<T>, ring: &[usize], period: usize) -> Vec<OrbitPlace> {
    let itself = |i: usize| OrbitPlace { rep: i, corner: 0 };
    let Some(rotation) = rotation_of(net, period) else { return (0..ring.len()).map(itself).collect() };
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
    (0..ring.len())
        .map(|i| {
            if represents(mesh, &rotation, ring[i]) {
                return itself(i);
            }
            // turn the face and its first corner together until the face
            // is its orbit's representative
            let (mut f, mut first) = (ring[i], mesh.face(ring[i])[0]);
            for _ in 1..rotation.order() {
                match (turned(f), rotation.turned(first)) {
                    (Some(g), Some(v)) if position[g] != usize::MAX => (f, first) = (g, v),
                    _ => return itself(i),
                }
                if represents(mesh, &rotation, f) {
                    return match mesh.face(f).iter().position(|&c| c == first) {
                        Some(corner) => OrbitPlace { rep: position[f], corner },
                        None => itself(i),
                    };
                }
            }
            itself(i)
        })
        .collect()
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
