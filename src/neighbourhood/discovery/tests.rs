//! Unit tests of neighbourhood discovery against the ring sizes known in
//! closed form. Discovery only follows which old vertices a new one depends
//! on, so the test schemes here have the stencil supports of Catmull–Clark,
//! Loop and Doo–Sabin with uniform weights (1/size of each stencil; this
//! layer may not import the scheme catalogue).
//!
//! Counting on the regular lattice around the centre (ring k+1: the corners
//! of faces touching ring k):
//! * Catmull–Clark, valence n: a quad sector of the 1-ring holds e_j and f_j,
//!   so ring ≤ 1 is 2n + 1 points (the minimal set: the vertex and edge rules
//!   reach exactly that far). The surface ring over the faces at the centre
//!   depends on ring ≤ 2: per sector the 2 × 2 block of quads has 3 × 3
//!   vertices, of which the centre is shared by all and the 2 on one spoke by
//!   the next sector, leaving 6: 6n + 1.
//! * Loop, valence n: ring ≤ 1 is n + 1; ring 2 adds per sector the spoke
//!   point at distance 2 and the one between two spokes: 3n + 1.
//! * Doo–Sabin, an n-gon: its n corners (the corner rule stays inside a
//!   face); ring 1 adds per corner the two outer corners of the edge quad and
//!   the far corner of the vertex quad: 4n.
//!
//! Besides the counts, each set is compared with the rings computed here
//! from the patch itself.

use super::discover;
use crate::mesh::{PolyMesh, SectorKind};
use crate::neighbourhood::configuration::Configuration;
use crate::neighbourhood::discovery::NeighbourhoodKind;
use crate::numeric::{Inexact, Weight};
use crate::sdc::slots::{weigh, Host, Mask, Slot, Wants};
use crate::sdc::{Caps, CentreKind, MeshDomain, Origin, Params, RuleResult, Rules, Scheme, SchemeInfo, Topology};

/// A scheme with the given host's mandatory slots, each weighed 1/(number of
/// slots of its rule): the stencil supports of the scheme the host is named
/// after, affine.
struct Support {
    info: SchemeInfo,
    host: Host,
    params: Params,
}

impl Support {
    fn new(name: &'static str, host: Host, topology: Topology, centre: CentreKind, sector: SectorKind) -> Self {
        let info =
            SchemeInfo { name, description: "test: uniform weights", topology, centre, sector, caps: Caps::NONE };
        Support { info, host, params: Params::default() }
    }
    fn catmull_clark() -> Self {
        let t = Topology::PrimalQuad;
        Support::new("support-cc", Host::PrimalQuad, t, CentreKind::Vertex, SectorKind::Quad)
    }
    fn loop_() -> Self {
        let t = Topology::PrimalTriangle;
        Support::new("support-loop", Host::PrimalTriangle, t, CentreKind::Vertex, SectorKind::Tri)
    }
    fn doo_sabin() -> Self {
        Support::new("support-ds", Host::Dual, Topology::Dual, CentreKind::Face, SectorKind::Quad)
    }
    /// Slots of `rule` at valence (or face size) n, as the host gathers them
    /// without optional families.
    fn slots(&self, rule: &str, n: usize) -> usize {
        match (self.host, rule) {
            (Host::PrimalQuad, "vertex") => 2 * n + 1,
            (Host::PrimalQuad, "edge") => 6,
            (Host::PrimalQuad, "face") => n,
            (Host::PrimalTriangle, "vertex") => n + 1,
            (Host::PrimalTriangle, "edge") => 4,
            (Host::Dual, "corner") => n,
            (h, r) => panic!("{h:?} has no rule {r} here"),
        }
    }
}

impl Wants for Support {
    fn rule(&self, _: &str) -> bool {
        false
    }
    fn family(&self, _: &str, _: &str) -> bool {
        false
    }
}

impl<W: Weight> Mask<W> for Support {
    fn weight(&self, _: &PolyMesh, rule: &'static str, slot: &Slot) -> Result<W, Inexact> {
        Ok(W::ratio(1, self.slots(rule, slot.n) as i64))
    }
}

impl<W: Weight> Rules<MeshDomain, W> for Support {
    fn rule(&self, mesh: &PolyMesh, origin: Origin) -> RuleResult<W> {
        weigh(self.host, mesh, origin, self, &W::one())
    }
}

impl Scheme for Support {
    fn info(&self) -> &SchemeInfo {
        &self.info
    }
    fn params(&self) -> &Params {
        &self.params
    }
}

/// Ring of every vertex of `mesh` from `centre` (ring k+1: the unvisited
/// corners of faces touching ring k); usize::MAX where unreached.
fn rings_from(mesh: &PolyMesh, centre: &[usize]) -> Vec<usize> {
    let mut ring = vec![usize::MAX; mesh.num_vertices()];
    centre.iter().for_each(|&v| ring[v] = 0);
    for k in 0.. {
        let mut grew = false;
        for face in mesh.faces() {
            if face.iter().any(|&v| ring[v] == k) {
                for &u in face {
                    if ring[u] == usize::MAX {
                        ring[u] = k + 1;
                        grew = true;
                    }
                }
            }
        }
        if !grew {
            break;
        }
    }
    ring
}

fn within(ring: &[usize], r: usize) -> Vec<usize> {
    (0..ring.len()).filter(|&v| ring[v] <= r).collect()
}

fn sorted(set: &[usize]) -> Vec<usize> {
    let mut s = set.to_vec();
    s.sort();
    s
}

/// The only vertex of the patch with a closed fan of n faces (n irregular).
fn centre_vertex(mesh: &PolyMesh, n: usize) -> usize {
    let found: Vec<usize> = (0..mesh.num_vertices()).filter(|&v| mesh.valence(v) == Some(n)).collect();
    assert_eq!(found.len(), 1, "one vertex of valence {n}: {found:?}");
    found[0]
}

/// Discovers both sets and checks them against rings ≤ `minimal_rings` and ≤
/// `analysis_rings` of `centre` and the closed-form sizes.
fn check(
    scheme: &Support,
    n: usize,
    centre: impl Fn(&PolyMesh) -> Vec<usize>,
    sizes: (usize, usize),
    rings: (usize, usize),
) {
    let config = Configuration::regular(scheme, n).unwrap();
    let d = discover(scheme, &config).unwrap();
    let name = scheme.info.name;
    assert_eq!(d.set(NeighbourhoodKind::Minimal).len(), sizes.0, "{name}, n = {n}: minimal set");
    assert_eq!(d.set(NeighbourhoodKind::Analysis).len(), sizes.1, "{name}, n = {n}: analysis neighbourhood");
    let ring = rings_from(&d.patch, &centre(&d.patch));
    assert_eq!(
        sorted(d.set(NeighbourhoodKind::Minimal)),
        within(&ring, rings.0),
        "{name}, n = {n}: minimal = ring ≤ {}",
        rings.0
    );
    assert_eq!(
        sorted(d.set(NeighbourhoodKind::Analysis)),
        within(&ring, rings.1),
        "{name}, n = {n}: analysis = ring ≤ {}",
        rings.1
    );
}

#[test]
fn catmull_clark_supports_give_2n_plus_1_and_6n_plus_1() {
    for n in [3, 5, 6, 8] {
        check(&Support::catmull_clark(), n, |m| vec![centre_vertex(m, n)], (2 * n + 1, 6 * n + 1), (1, 2));
    }
}

#[test]
fn loop_supports_give_n_plus_1_and_3n_plus_1() {
    for n in [3, 4, 5, 7] {
        check(&Support::loop_(), n, |m| vec![centre_vertex(m, n)], (n + 1, 3 * n + 1), (1, 2));
    }
}

#[test]
fn doo_sabin_supports_give_n_and_4n() {
    for n in [3, 5, 6] {
        let central_face = |m: &PolyMesh| {
            let faces: Vec<&[usize]> = m.faces().iter().filter(|f| f.len() == n).collect();
            assert_eq!(faces.len(), 1, "one {n}-gon");
            faces[0].to_vec()
        };
        check(&Support::doo_sabin(), n, central_face, (n, 4 * n), (0, 1));
    }
}

/// The window (`WINDOW_SECTORS` sectors on each side of the representatives)
/// changes what is refined, never what is found: at valences where it
/// applies, the pruned search finds the same minimal and analysis sets, after
/// the same number of analysis steps, with the same composed rows of S as
/// the search on the whole patch (`prune = false`), and both match the
/// closed-form sizes above.
#[test]
fn windowed_discovery_equals_the_whole_patchs() {
    use super::{first_patch_rings, try_discover};
    let schemes: [(Support, fn(usize) -> (usize, usize)); 3] = [
        (Support::catmull_clark(), |n| (2 * n + 1, 6 * n + 1)),
        (Support::loop_(), |n| (n + 1, 3 * n + 1)),
        (Support::doo_sabin(), |n| (n, 4 * n)),
    ];
    for (scheme, sizes) in &schemes {
        for n in [41, 64] {
            let config = Configuration::regular(scheme, n).unwrap();
            let rings = first_patch_rings(scheme, &config);
            let mut blame = false;
            let windowed = try_discover(scheme, &config, rings, true, &mut blame).unwrap();
            let whole = try_discover(scheme, &config, rings, false, &mut blame).unwrap();
            let name = scheme.info.name;
            // the window does cut the refined meshes at this valence
            let step = &whole.refinements()[0].mesh;
            let kept = super::window_faces(step, config.rotation_period(scheme)).map(|k| k.len());
            assert!(kept.is_some_and(|k| k < step.num_faces()), "{name}, n = {n}: the window applies");
            assert!(!blame, "{name}, n = {n}: no stencil was cut off by the window");
            for kind in [NeighbourhoodKind::Minimal, NeighbourhoodKind::Analysis] {
                assert_eq!(windowed.set(kind), whole.set(kind), "{name}, n = {n}: {kind:?} set");
            }
            assert_eq!(
                (windowed.set(NeighbourhoodKind::Minimal).len(), windowed.set(NeighbourhoodKind::Analysis).len()),
                sizes(n),
                "{name}, n = {n}: closed-form sizes"
            );
            assert_eq!(windowed.analysis_levels, whole.analysis_levels, "{name}, n = {n}: analysis steps");
            let rows = |d: &super::Discovered| {
                let mut r: Vec<(usize, Vec<(usize, f64)>)> =
                    d.composite.iter().map(|(v, row)| (*v, row.entries.clone())).collect();
                r.sort_by_key(|(v, _)| *v);
                r
            };
            assert_eq!(rows(&windowed), rows(&whole), "{name}, n = {n}: composed rows of S");
        }
    }
}

/// Two discoveries on one host, configuration and patch size share the
/// scheme-independent meshes (`PatchTopology`: the same patch, not a copy),
/// and each still finds the closed-form neighbourhoods; a different patch
/// size is a different topology with the same findings. The second scheme
/// has another identity (name), so the discovery memo does not answer for
/// it: only the topology is shared.
#[test]
fn discoveries_on_one_host_share_the_patch_topology_and_find_the_same_sets() {
    use super::{discover_with_rings, try_discover};
    use std::sync::Arc;
    let first = Support::catmull_clark();
    let mut second = Support::catmull_clark();
    second.info.name = "support-cc-second";
    for n in [5, 7] {
        let config = Configuration::regular(&first, n).unwrap();
        let mut blame = false;
        let a = try_discover(&first, &config, 3, true, &mut blame).unwrap();
        let b = try_discover(&second, &config, 3, true, &mut blame).unwrap();
        assert!(Arc::ptr_eq(&a.patch, &b.patch), "n = {n}: one patch for both schemes");
        assert!(Arc::ptr_eq(&a.labels, &b.labels), "n = {n}: one labelling");
        let larger = discover_with_rings(&second, &config, 4).unwrap();
        assert!(!Arc::ptr_eq(&a.patch, &larger.patch), "n = {n}: a 4-ring patch is another topology");
        assert!(larger.patch.num_vertices() > a.patch.num_vertices());
        for d in [&a, &b, &larger] {
            let sizes = (d.set(NeighbourhoodKind::Minimal).len(), d.set(NeighbourhoodKind::Analysis).len());
            assert_eq!(sizes, (2 * n + 1, 6 * n + 1), "n = {n}: closed-form sizes");
            assert_eq!(d.analysis_levels, a.analysis_levels, "n = {n}: analysis steps");
        }
        // the same vertices, by their labels (ids differ between patch sizes)
        let labelled = |d: &super::Discovered| -> Vec<_> {
            d.set(NeighbourhoodKind::Analysis).iter().map(|&v| format!("{:?}", d.labels[v])).collect()
        };
        assert_eq!(labelled(&a), labelled(&b), "n = {n}");
        assert_eq!(labelled(&a), labelled(&larger), "n = {n}");
    }
}

/// `RegionEntities` answers what `region_entities`' set holds: on the patch
/// of each regular configuration below (quads with Catmull–Clark's host,
/// triangles with Loop's, and the faces of Doo–Sabin's), with every third
/// face flagged, for every origin of one refinement of the patch, every
/// face parent, every entity of the set and a few entities of no mesh.
#[test]
fn region_entities_answer_what_the_set_holds() {
    use super::{region_entities, RegionEntities};
    use crate::neighbourhood::builder::build_patch;
    for scheme in [Support::catmull_clark(), Support::loop_(), Support::doo_sabin()] {
        for n in [3, 5, 8] {
            let config = Configuration::regular(&scheme, n).unwrap();
            let (patch, _) = build_patch(&config, 3);
            let flags: Vec<bool> = (0..patch.num_faces()).map(|f| f % 3 == 0).collect();
            let set = region_entities(&patch, &flags);
            let region = RegionEntities::new(&patch, &flags);
            let refined = scheme.info.topology.refine(&patch).unwrap();
            let (nv, nf) = (patch.num_vertices(), patch.num_faces());
            let off =
                [Origin::Vertex(nv), Origin::Edge(0, nv), Origin::Face(nf), Origin::Corner { face: 0, corner: 9 }];
            let asked = refined.vertex_origins.iter().chain(&refined.face_parents).chain(&set).chain(&off);
            for &o in asked {
                assert_eq!(region.contains(o), set.contains(&o), "{}, n = {n}: {o:?}", scheme.info.name);
            }
        }
    }
}

/// `RegionEntities` answers exactly what `region_entities`' set holds, for every
/// origin of a small mixed mesh (quads and triangles, open rim) and every
/// pattern of flagged faces, including origins of no face (reversed and
/// non-existent edges, out-of-range ids).
#[test]
fn the_dense_region_holds_exactly_the_region_entities() {
    // a 3×2 grid of quads (vertices 0..12, row-major, 4 per row) with
    // the last quad split into two triangles
    let q = |a: usize| vec![a, a + 1, a + 5, a + 4];
    let faces = vec![q(0), q(1), q(2), q(4), q(5), vec![6, 7, 11], vec![6, 11, 10]];
    let mesh = PolyMesh::new(12, faces).unwrap();
    let nf = mesh.num_faces();
    for pattern in 0u32..(1 << nf) {
        let flags: Vec<bool> = (0..nf).map(|f| pattern >> f & 1 == 1).collect();
        let set = super::region_entities(&mesh, &flags);
        let dense = super::RegionEntities::new(&mesh, &flags);
        let mut origins: Vec<Origin> = (0..14).map(Origin::Vertex).collect();
        origins.extend((0..13).flat_map(|a| (0..13).map(move |b| Origin::Edge(a, b))));
        origins.extend((0..nf + 1).map(Origin::Face));
        origins.extend((0..nf + 1).flat_map(|f| (0..4).map(move |corner| Origin::Corner { face: f, corner })));
        for o in origins {
            assert_eq!(dense.contains(o), set.contains(&o), "{o:?} with faces {flags:?}");
        }
    }
}
