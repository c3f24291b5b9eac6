//! Contact state as structure-of-arrays: a boundary node of one block against a boundary edge of
//! another (UDEC's deformable-block contacts), each with a joint state that persists across
//! re-detection (`contact::detect`).

use crate::joint::JointState;

/// Structure-of-arrays contact data.
#[derive(Debug, Clone, Default)]
pub struct Contacts {
    /// The contacting node (of block A).
    pub node: Vec<u32>,
    /// The boundary edge it touches (of block B), an index into `Blocks::edges`.
    pub edge: Vec<u32>,
    /// Block B.
    pub block: Vec<u32>,
    /// Position of the contact point along the edge, 0 at its first node and 1 at its second.
    pub xi: Vec<f64>,
    /// Length of joint the contact represents, m (half the node's tributary length: both sides of a
    /// joint carry contacts, so together they cover it once).
    pub length: Vec<f64>,
    /// Joint material of the contact.
    pub material: Vec<u32>,
    /// Whether the contact is between two rounded corners (its node against the edge's first node,
    /// ξ = 0, along the line of the rounding centres) rather than node against edge.
    pub corner: Vec<bool>,
    pub state: Vec<JointState>,
}

impl Contacts {
    pub fn len(&self) -> usize {
        self.node.len()
    }

    pub fn is_empty(&self) -> bool {
        self.node.is_empty()
    }

    /// The three nodes each contact acts on: its node, then the edge's two nodes.
    pub fn triples(&self, edges: &[[u32; 2]]) -> Vec<[u32; 3]> {
        self.node
            .iter()
            .zip(&self.edge)
            .map(|(&n, &e)| [n, edges[e as usize][0], edges[e as usize][1]])
            .collect()
    }
}
