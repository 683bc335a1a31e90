//! Polygon meshes: connectivity only (positions live beside the mesh, so the same
//! topology can carry 3-D points, 2-D points or sparse weight rows).

pub mod face_list;
pub mod lattice;
pub mod obj;
pub mod polymesh;
pub mod tags;

pub use face_list::FaceList;
pub use lattice::{Chart, LatticeCoord, SectorKind};
pub use polymesh::{EdgeNumbering, FaceId, IdMap, IdSet, PolyMesh, VertexId};
pub use tags::{Tags, VertexTag};
