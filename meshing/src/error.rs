//! Errors of geometry validation and meshing; each names the offending shape and the reason.

use thiserror::Error;

use crate::joints::EdgeKind;

/// Why a domain could not be built or meshed.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum MeshError {
    /// A polygon has fewer than three distinct vertices or (nearly) zero area.
    #[error("{shape}: degenerate polygon ({reason})")]
    Degenerate { shape: String, reason: String },
    /// Two non-adjacent edges of one polygon cross or touch.
    #[error("{shape}: polygon is self-intersecting (edge {a} crosses edge {b})")]
    SelfIntersecting { shape: String, a: usize, b: usize },
    /// A hole is not strictly inside the region.
    #[error("{shape}: excavation is not inside the region ({reason})")]
    HoleOutside { shape: String, reason: String },
    /// Two holes overlap or touch.
    #[error("{a} and {b}: excavations overlap or touch")]
    HolesOverlap { a: String, b: String },
    /// Zoning controls that cannot produce a mesh.
    #[error("{0}")]
    Zoning(String),
    /// The mesh has more zones than the scene allows.
    #[error(
        "{zones} zones exceed the limit of {limit}: coarsen the zoning or raise `zoning.max_zones`"
    )]
    TooManyZones { zones: usize, limit: usize },
    /// Joint set `set`'s joints lie closer together than the cutter can tell apart.
    #[error(
        "{spacing} m is below the {tolerance:.4} m within which the cutter merges vertices \
         (zoning.merge_tolerance, by default 0.3 × zoning.edge_at_excavation, less near short wall \
         edges): joints this close cannot be told apart; space them wider, zone finer or lower \
         zoning.merge_tolerance"
    )]
    JointsTooClose {
        set: usize,
        spacing: f64,
        tolerance: f64,
    },
    /// The triangulator failed or could not reach the requested quality.
    #[error("triangulation failed: {0}")]
    Triangulation(String),
    /// A block's boundary crosses itself (`message` says where); `kinds` are what the block's
    /// edges there lie on: the joints, walls or region edges that made the crossing.
    #[error("triangulation failed: {message}")]
    Crossing {
        message: String,
        kinds: Vec<EdgeKind>,
    },
    /// Refinement at the requested minimum angle ran out of its vertex budget.
    #[error("triangulation failed: {0}")]
    Refinement(String),
}

impl MeshError {
    /// The error, said of block `b` (its number in the blocking) where that helps to find it.
    pub fn in_block(self, b: usize) -> MeshError {
        match self {
            MeshError::Crossing { message, kinds } => MeshError::Crossing {
                message: format!("block {b}: {message}"),
                kinds,
            },
            other => other,
        }
    }
}
