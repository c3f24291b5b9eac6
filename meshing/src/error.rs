//! Errors of geometry validation and meshing; each names the offending shape and the reason.

use thiserror::Error;

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
    /// The triangulator failed or could not reach the requested quality.
    #[error("triangulation failed: {0}")]
    Triangulation(String),
    /// Refinement at the requested minimum angle ran out of its vertex budget.
    #[error("triangulation failed: {0}")]
    Refinement(String),
}
