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
pub mod triangulate;
pub mod voronoi;

pub use blocks::{Block, Blocking, Merges, cut_blocks, cut_blocks_filled};
pub use domain::{Domain, Hole};
pub use error::MeshError;
pub use geometry::{Point, Polygon};
pub use joints::{EdgeKind, JointSet, Segment, SplitMix};
pub use triangulate::{
    BoundaryEdge, MeshStats, TriMesh, Zoning, triangulate, triangulate_block, triangulate_outline,
};
