//! Wavefront OBJ polygon meshes: reading (`v` and `f` statements) and writing.
//!
//! Only what subdivision needs is read: vertex positions and polygon faces.
//! Texture coordinates, normals, groups, materials, smoothing groups, lines and
//! comments are skipped. Face entries may be `7`, `7/2`, `7/2/5`, `7//5`, or
//! negative (relative to the vertices read so far); only the position index is
//! used.
//!
//! Boundary, crease and corner tags (`mesh::tags`) are comment lines, so
//! that other programs read the file as a plain mesh:
//!
//! * `#crease i j [k ...]`: the edges i–j (j–k, ...) are sharp (crease
//!   edges); a chain of any length, each step an edge of the mesh;
//! * `#corner i [j ...]`: the vertices are corners (interpolated).
//!
//! Indices are 1-based, as in `f` lines (no relative indices); the keyword
//! follows `#` without a space (`# crease` is an ordinary comment). A mesh
//! with tag lines is read with `PolyMesh::tags` set (open edges are not
//! tagged here: the `refine` command tags them as the boundary). A side file
//! of tags ([`read_tags`]) has the same lines without the `#`. The writer
//! puts the sharp edges between two faces (creases) and the corners back as
//! such lines; boundary edges are not written (they are the open edges).
//!
//! The reader is meant to face files from anywhere, so every defect gives a
//! one-line error that names the line, and every size is capped before it is
//! allocated (see the `MAX_*` constants): a hostile file cannot make it panic,
//! loop, or allocate without bound. The caps match the size of mesh that
//! `refine` produces (2,000,000 faces); the half-edge maps of a mesh at the cap
//! take a few hundred megabytes.

use std::collections::HashMap;
use std::io::Read;
use std::path::Path;

use crate::error::Error;

use super::{PolyMesh, Tags};

/// Largest OBJ file read, in bytes (the file is read whole, so this bounds memory).
pub const MAX_FILE_BYTES: u64 = 256 * 1024 * 1024;
/// Largest number of vertices accepted.
pub const MAX_VERTICES: usize = 2_000_000;
/// Largest number of faces accepted.
pub const MAX_FACES: usize = 2_000_000;
/// Largest total number of face corners (sum of face sizes) accepted.
pub const MAX_CORNERS: usize = 8_000_000;

/// A mesh read from OBJ: connectivity and one position per vertex.
pub type ObjMesh = (PolyMesh, Vec<[f64; 3]>);

/// Read an OBJ file from disk; errors (`Error::File`) name the file and,
/// where it applies, the line.
pub fn read_obj_file(path: &Path) -> Result<ObjMesh, Error> {
    read_file(path)
}

fn read_file(path: &Path) -> Result<ObjMesh, Error> {
    let file = std::fs::File::open(path).map_err(|e| Error::File(format!("cannot read {}: {e}", path.display())))?;
    let too_large =
        || Error::File(format!("{}: file is larger than the supported {} bytes", path.display(), MAX_FILE_BYTES));
    // a regular file says its size up front: refuse it before reading anything
    if file.metadata().is_ok_and(|m| m.is_file() && m.len() > MAX_FILE_BYTES) {
        return Err(too_large());
    }
    let mut bytes = Vec::new();
    // read at most one byte more than the cap, so an oversized file is detected
    // without ever holding more than the cap in memory
    file.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Error::File(format!("cannot read {}: {e}", path.display())))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(too_large());
    }
    let text = crate::io::decode_text(bytes).map_err(|e| {
        // report the line of the first invalid byte
        let line = 1 + e.as_bytes()[..e.utf8_error().valid_up_to()].iter().filter(|&&b| b == b'\n').count();
        Error::File(format!("{}: line {line}: not valid UTF-8 text", path.display()))
    })?;
    parse_text(&text).map_err(|e| e.context(path.display()))
}

/// Parse OBJ text. Errors (`Error::File`) are one line and start with
/// `line N:` when a line is to blame.
pub fn parse_obj(text: &str) -> Result<ObjMesh, Error> {
    parse_text(text)
}

fn parse_text(text: &str) -> Result<ObjMesh, Error> {
    let mut points: Vec<[f64; 3]> = Vec::new();
    let mut vertex_line: Vec<usize> = Vec::new();
    let mut faces: Vec<Vec<usize>> = Vec::new();
    let mut face_line: Vec<usize> = Vec::new();
    let mut corners = 0usize;
    // tag lines (`#crease`, `#corner`), applied once the mesh is built
    let mut tag_lines: Vec<(usize, &str)> = Vec::new();
    for (k, raw) in text.lines().enumerate() {
        let line_no = k + 1;
        let err = |msg: String| Error::File(format!("line {line_no}: {msg}"));
        if let Some(tag) = raw.trim_start().strip_prefix('#').filter(|t| is_tag_line(t)) {
            tag_lines.push((line_no, tag));
            continue;
        }
        // a comment may follow a statement on the same line
        let content = raw.split('#').next().unwrap_or("");
        let mut tokens = content.split_whitespace();
        let Some(keyword) = tokens.next() else { continue };
        match keyword {
            "v" => {
                if points.len() >= MAX_VERTICES {
                    return Err(err(format!("more than {MAX_VERTICES} vertices (the supported maximum)")));
                }
                let mut xyz = [0.0; 3];
                let mut count = 0;
                for tok in tokens {
                    let x: f64 = tok.parse().map_err(|_| err(format!("'{tok}' is not a number")))?;
                    if !x.is_finite() {
                        return Err(err(format!("vertex coordinate '{tok}' is not finite")));
                    }
                    if count < 3 {
                        xyz[count] = x;
                    }
                    count += 1;
                }
                // x y z, optionally followed by w or an r g b colour, which are not used
                if !(3..=7).contains(&count) {
                    return Err(err(format!("a vertex needs 3 coordinates, got {count} numbers")));
                }
                points.push(xyz);
                vertex_line.push(line_no);
            }
            "f" => {
                if faces.len() >= MAX_FACES {
                    return Err(err(format!("more than {MAX_FACES} faces (the supported maximum)")));
                }
                let mut face = Vec::new();
                for tok in tokens {
                    if corners >= MAX_CORNERS {
                        return Err(err(format!(
                            "more than {MAX_CORNERS} face corners in total (the supported maximum)"
                        )));
                    }
                    let bad = || err(format!("'{tok}' is not a vertex reference such as 7, 7/2, 7/2/5 or 7//5"));
                    let mut parts = tok.split('/');
                    let idx: i64 = parts.next().unwrap_or("").parse().map_err(|_| bad())?;
                    // texture and normal references are not used, but must be well formed
                    let rest: Vec<&str> = parts.collect();
                    if rest.len() > 2 || rest.iter().any(|p| !p.is_empty() && p.parse::<i64>().is_err()) {
                        return Err(bad());
                    }
                    let resolved = if idx > 0 {
                        // positive indices may refer forward; checked once all vertices are read
                        (idx - 1) as u64
                    } else if idx < 0 {
                        let back = idx.unsigned_abs();
                        if back > points.len() as u64 {
                            return Err(err(format!(
                                "relative vertex index {idx} reaches before the first vertex ({} read so far)",
                                points.len()
                            )));
                        }
                        points.len() as u64 - back
                    } else {
                        return Err(err("vertex index 0 is invalid (OBJ indices start at 1)".into()));
                    };
                    if resolved >= MAX_VERTICES as u64 {
                        return Err(err(format!("vertex index {idx} is out of range")));
                    }
                    face.push(resolved as usize);
                    corners += 1;
                }
                if face.len() < 3 {
                    return Err(err(format!("a face needs at least 3 vertices, got {}", face.len())));
                }
                faces.push(face);
                face_line.push(line_no);
            }
            // everything else (vt, vn, vp, g, o, s, usemtl, mtllib, l, p, ...) carries nothing we use
            _ => {}
        }
    }
    if faces.is_empty() {
        return Err(Error::File(
            if points.is_empty() { "empty mesh: no vertices and no faces" } else { "no faces" }.into(),
        ));
    }
    validate(&points, &vertex_line, &faces, &face_line)?;
    let mut mesh = PolyMesh::new(points.len(), faces).map_err(|e| Error::File(format!("invalid mesh: {e}")))?;
    if !tag_lines.is_empty() {
        let mut tags = Tags::new();
        for (line_no, line) in tag_lines {
            tag_line(&mesh, &mut tags, line).map_err(|e| Error::File(format!("line {line_no}: {e}")))?;
        }
        mesh.tags = Some(tags);
    }
    Ok((mesh, points))
}

/// Whether the text after a `#` is a tag line (`crease ...`, `corner ...`).
fn is_tag_line(t: &str) -> bool {
    matches!(t.split_whitespace().next(), Some("crease" | "corner")) && !t.starts_with(char::is_whitespace)
}

/// Apply one tag line (`crease i j [k ...]` or `corner i [j ...]`, 1-based
/// indices) to `tags`; the error names what is wrong, without the line.
fn tag_line(mesh: &PolyMesh, tags: &mut Tags, line: &str) -> Result<(), String> {
    let mut tokens = line.split_whitespace();
    let keyword = tokens.next().unwrap_or("");
    let nv = mesh.num_vertices();
    let mut ids = Vec::new();
    for tok in tokens {
        let i: u64 = tok
            .parse()
            .map_err(|_| format!("{keyword}: '{tok}' is not a vertex index (a whole number from 1, as in f lines)"))?;
        if i == 0 || i > nv as u64 {
            return Err(format!("{keyword}: vertex index {i} is out of range (the mesh has {nv} vertices, from 1)"));
        }
        ids.push(i as usize - 1);
    }
    match keyword {
        "crease" => {
            if ids.len() < 2 {
                return Err(format!("crease: needs at least two vertex indices (an edge), got {}", ids.len()));
            }
            for w in ids.windows(2) {
                let (a, b) = (w[0], w[1]);
                if mesh.half_edge(a, b).is_none() && mesh.half_edge(b, a).is_none() {
                    return Err(format!("crease: {}-{} is not an edge of the mesh", a + 1, b + 1));
                }
                tags.mark_sharp(a, b);
            }
        }
        "corner" => {
            if ids.is_empty() {
                return Err("corner: needs at least one vertex index".into());
            }
            for v in ids {
                if mesh.incident_faces(v).is_empty() {
                    return Err(format!("corner: vertex {} is not used by any face", v + 1));
                }
                tags.mark_corner(v);
            }
        }
        other => return Err(format!("unknown tag '{other}' (expected crease or corner)")),
    }
    Ok(())
}

/// Largest file of tags read, in bytes.
pub const MAX_TAG_FILE_BYTES: usize = 64 * 1024 * 1024;

/// Add the tags of a side file (`crease i j [k ...]` and `corner i [j ...]`
/// lines, 1-based vertex indices, `#` starting a comment) to `mesh`'s tags;
/// `source` names the file in errors, which are one line naming the line.
pub fn read_tags(text: &str, mesh: &mut PolyMesh, source: &str) -> Result<(), Error> {
    if text.len() > MAX_TAG_FILE_BYTES {
        return Err(Error::File(format!("{source}: larger than {MAX_TAG_FILE_BYTES} bytes")));
    }
    let mut tags = mesh.tags.clone().unwrap_or_default();
    for (k, raw) in text.lines().enumerate() {
        let content = raw.split('#').next().unwrap_or("");
        if content.trim().is_empty() {
            continue;
        }
        tag_line(mesh, &mut tags, content).map_err(|e| Error::File(format!("{source} line {}: {e}", k + 1)))?;
    }
    mesh.tags = Some(tags);
    Ok(())
}

/// Checks that PolyMesh::new would also make, but reported with line numbers,
/// plus non-manifold vertices, which PolyMesh does not detect and which would
/// make the one-ring walks of the rules see only part of a vertex's faces.
fn validate(
    points: &[[f64; 3]],
    vertex_line: &[usize],
    faces: &[Vec<usize>],
    face_line: &[usize],
) -> Result<(), Error> {
    let nv = points.len();
    let mut half_edges: HashMap<(usize, usize), usize> = HashMap::with_capacity(faces.iter().map(|f| f.len()).sum());
    for (f, face) in faces.iter().enumerate() {
        let line = face_line[f];
        for &v in face {
            if v >= nv {
                return Err(Error::File(format!(
                    "line {line}: face refers to vertex {}, but the file has only {nv} vertices",
                    v + 1
                )));
            }
        }
        for (k, &a) in face.iter().enumerate() {
            if face[k + 1..].contains(&a) {
                return Err(Error::File(format!("line {line}: face uses vertex {} twice", a + 1)));
            }
            let b = face[(k + 1) % face.len()];
            if let Some(&g) = half_edges.get(&(a, b)) {
                return Err(Error::File(format!(
                    "line {line}: edge {}-{} is used in the same direction by the face on line {}: \
                     the mesh is non-manifold or inconsistently oriented",
                    a + 1,
                    b + 1,
                    face_line[g]
                )));
            }
            half_edges.insert((a, b), f);
        }
    }
    // An edge with more than two faces always repeats a direction (caught above).
    // A vertex is manifold when its faces form one fan: link two corners at v when
    // their faces share an edge at v, and count the connected groups.
    let corner_start = super::polymesh::corner_offsets(nv, faces);
    let mut slot = corner_start.clone();
    let mut corner_face = vec![0usize; corner_start[nv]];
    for (f, face) in faces.iter().enumerate() {
        for &v in face {
            corner_face[slot[v]] = f;
            slot[v] += 1;
        }
    }
    let mut parent: Vec<usize> = (0..corner_face.len()).collect();
    fn find(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    for v in 0..nv {
        let range = corner_start[v]..corner_start[v + 1];
        // position of each face among v's corners
        let local: HashMap<usize, usize> = range.clone().map(|c| (corner_face[c], c)).collect();
        for c in range.clone() {
            let face = &faces[corner_face[c]];
            let k = face.iter().position(|&u| u == v).expect("corner of v");
            let next = face[(k + 1) % face.len()];
            // the face across the edge v->next holds next->v
            if let Some(&g) = half_edges.get(&(next, v)) {
                if let Some(&c2) = local.get(&g) {
                    let (ra, rb) = (find(&mut parent, c), find(&mut parent, c2));
                    parent[ra] = rb;
                }
            }
        }
        let roots: std::collections::HashSet<usize> = range.map(|c| find(&mut parent, c)).collect();
        if roots.len() > 1 {
            return Err(Error::File(format!(
                "line {}: vertex {} is non-manifold (its faces form {} separate fans)",
                vertex_line[v],
                v + 1,
                roots.len()
            )));
        }
    }
    Ok(())
}

/// OBJ text for a mesh: a comment header, `v` lines (shortest round-trip decimal
/// form of each coordinate, so reading the file back gives the same numbers) and
/// `f` lines with 1-based indices.
pub fn write_obj(mesh: &PolyMesh, points: &[[f64; 3]], header: &str) -> String {
    let mut out = String::with_capacity(32 * points.len() + 24 * mesh.num_faces());
    for line in header.lines() {
        out.push_str("# ");
        out.push_str(line);
        out.push('\n');
    }
    for p in points {
        // Debug formatting is the shortest round-trip form and uses exponents for tiny/huge values
        out.push_str(&format!("v {:?} {:?} {:?}\n", p[0], p[1], p[2]));
    }
    for face in mesh.faces() {
        out.push('f');
        for &v in face {
            out.push_str(&format!(" {}", v + 1));
        }
        out.push('\n');
    }
    if let Some(tags) = &mesh.tags {
        // creases (sharp edges between two faces) and corners; the boundary
        // is the open edges, tagged again on reading
        for (a, b) in tags.sharp_edges().into_iter().filter(|&(a, b)| mesh.is_interior_edge(a, b)) {
            out.push_str(&format!("#crease {} {}\n", a + 1, b + 1));
        }
        for c in tags.corners() {
            out.push_str(&format!("#corner {}\n", c + 1));
        }
    }
    out
}
