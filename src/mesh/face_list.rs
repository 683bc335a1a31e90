//! The faces of a mesh as one list of corners with offsets (compressed rows)
//! instead of a vector per face: a refinement makes a face per corner of the
//! old mesh, and one allocation (and free) per face, with 24 bytes of vector
//! header beside each face's corners, was a large part of building the
//! meshes of discovery and of the nets. A face reads as a slice, so callers
//! iterate, index and compare faces as they did a `Vec<Vec<VertexId>>`.

use std::ops::Index;

/// A vertex of a mesh: an index into its vertex list (defined here, below
/// `polymesh`, which re-exports it, so that the files of `mesh` import in
/// one direction).
pub type VertexId = usize;

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FaceList {
    corners: Vec<VertexId>,
    /// face f is `corners[start[f]..start[f + 1]]`; `start[0]` is 0
    start: Vec<usize>,
}

impl Default for FaceList {
    fn default() -> Self {
        FaceList::new()
    }
}

impl FaceList {
    pub fn new() -> FaceList {
        FaceList::with_capacity(0, 0)
    }

    /// Room for `faces` faces with `corners` corners in all.
    pub fn with_capacity(faces: usize, corners: usize) -> FaceList {
        let mut start = Vec::with_capacity(faces + 1);
        start.push(0);
        FaceList { corners: Vec::with_capacity(corners), start }
    }

    /// Append a face (its corners in cycle order).
    pub fn push(&mut self, face: &[VertexId]) {
        self.corners.extend_from_slice(face);
        self.start.push(self.corners.len());
    }

    /// Append a face given corner by corner.
    pub fn push_iter(&mut self, face: impl IntoIterator<Item = VertexId>) {
        self.corners.extend(face);
        self.start.push(self.corners.len());
    }

    pub fn len(&self) -> usize {
        self.start.len() - 1
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The corners of every face, face after face.
    pub fn corners(&self) -> &[VertexId] {
        &self.corners
    }

    pub fn get(&self, f: usize) -> Option<&[VertexId]> {
        Some(&self.corners[*self.start.get(f)?..*self.start.get(f + 1)?])
    }

    pub fn first(&self) -> Option<&[VertexId]> {
        self.get(0)
    }

    /// The faces in order, each as its corner slice.
    pub fn iter(&self) -> Faces<'_> {
        Faces { list: self, front: 0, back: self.len() }
    }

    /// A vector per face (for callers that edit faces one by one).
    pub fn to_vec(&self) -> Vec<Vec<VertexId>> {
        self.iter().map(<[VertexId]>::to_vec).collect()
    }
}

impl Index<usize> for FaceList {
    type Output = [VertexId];
    fn index(&self, f: usize) -> &[VertexId] {
        &self.corners[self.start[f]..self.start[f + 1]]
    }
}

impl From<Vec<Vec<VertexId>>> for FaceList {
    fn from(faces: Vec<Vec<VertexId>>) -> FaceList {
        let mut list = FaceList::with_capacity(faces.len(), faces.iter().map(Vec::len).sum());
        faces.iter().for_each(|f| list.push(f));
        list
    }
}

impl<const N: usize> From<Vec<[VertexId; N]>> for FaceList {
    fn from(faces: Vec<[VertexId; N]>) -> FaceList {
        let mut list = FaceList::with_capacity(faces.len(), N * faces.len());
        faces.iter().for_each(|f| list.push(f));
        list
    }
}

/// The faces of a [`FaceList`] as slices, in order.
#[derive(Clone, Debug)]
pub struct Faces<'a> {
    list: &'a FaceList,
    front: usize,
    back: usize,
}

impl<'a> Iterator for Faces<'a> {
    type Item = &'a [VertexId];
    #[inline]
    fn next(&mut self) -> Option<&'a [VertexId]> {
        (self.front < self.back).then(|| {
            self.front += 1;
            &self.list[self.front - 1]
        })
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        (self.back - self.front, Some(self.back - self.front))
    }
}

impl DoubleEndedIterator for Faces<'_> {
    fn next_back(&mut self) -> Option<Self::Item> {
        (self.front < self.back).then(|| {
            self.back -= 1;
            &self.list[self.back]
        })
    }
}

impl ExactSizeIterator for Faces<'_> {}

impl<'a> IntoIterator for &'a FaceList {
    type Item = &'a [VertexId];
    type IntoIter = Faces<'a>;
    fn into_iter(self) -> Faces<'a> {
        self.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random face lists of mixed sizes (a fixed linear congruential
    /// sequence): the flat list holds, indexes, iterates (both ways) and
    /// prefixes exactly the faces it was given, one vector per face.
    #[test]
    fn flat_faces_equal_the_faces_given() {
        let mut state = 12345u64;
        let mut next = |m: u64| {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((state >> 33) % m) as usize
        };
        for _ in 0..20 {
            let faces: Vec<Vec<VertexId>> =
                (0..next(30)).map(|_| (0..3 + next(4)).map(|_| next(100)).collect()).collect();
            let list = FaceList::from(faces.clone());
            assert_eq!(list.len(), faces.len());
            assert_eq!(list.is_empty(), faces.is_empty());
            assert_eq!(list.to_vec(), faces);
            assert_eq!(list.first(), faces.first().map(Vec::as_slice));
            assert_eq!(list.iter().len(), faces.len());
            for (f, face) in faces.iter().enumerate() {
                assert_eq!(&list[f], face.as_slice());
                assert_eq!(list.get(f), Some(face.as_slice()));
            }
            assert_eq!(list.get(faces.len()), None);
            let backwards: Vec<&[VertexId]> = list.iter().rev().collect();
            assert!(backwards.iter().copied().eq(faces.iter().rev().map(Vec::as_slice)));
            assert_eq!(list.corners(), faces.concat().as_slice());
            let mut pushed = FaceList::new();
            faces.iter().for_each(|f| pushed.push_iter(f.iter().copied()));
            assert_eq!(pushed, list);
        }
    }
}
