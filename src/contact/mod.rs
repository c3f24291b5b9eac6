//! Contact detection between blocks: each boundary node of one block against the boundary edges of
//! another (UDEC's deformable-block contacts), the joint state carried over from the contacts found
//! before (`model::Contacts` holds them), and the rounding of rigid and simple blocks' corners.

pub mod detect;
mod edge_grid;
pub mod rounding;
