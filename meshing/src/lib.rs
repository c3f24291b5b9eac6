//! Block geometry and triangulation for adit: polygons with holes, excavation shapes, and graded
//! constrained-Delaunay zoning (spade) of a block into constant-strain triangles.

pub mod blocks;
pub mod domain;
pub mod error;
pub mod geometry;
pub mod joints;
mod pinch;
mod polygon_index;
mod segment_grid;
pub mod spacing;
pub mod triangulate;
pub mod union_find;
pub mod voronoi;

pub use blocks::{Block, Blocking, Merges, OntoWall, cut_blocks, cut_blocks_filled};
pub use domain::{Domain, Hole};
pub use error::MeshError;
pub use geometry::{Point, Polygon};
pub use joints::{EdgeKind, JointSet, Segment, SplitMix};
pub use spacing::BoundarySpacing;
pub use triangulate::{
    BoundaryEdge, MeshStats, TriMesh, Zoning, triangulate, triangulate_block, triangulate_blocks,
    triangulate_outline,
};

/// A hash map with a fixed hasher: the same insertions iterate in the same order in every run and
/// process, so cutting and meshing are deterministic (std's `RandomState` seeds every map anew,
/// and an iteration order that varies made the same scene mesh differently from run to run).
pub(crate) type Map<K, V> = std::collections::HashMap<K, V, FixedHasher>;
/// A hash set with a fixed hasher (see `Map`).
pub(crate) type Set<K> = std::collections::HashSet<K, FixedHasher>;
/// SipHash with fixed keys.
pub(crate) type FixedHasher =
    std::hash::BuildHasherDefault<std::collections::hash_map::DefaultHasher>;
