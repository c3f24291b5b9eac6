//! Contact state as structure-of-arrays: a boundary node of one block against a boundary edge of
//! another (UDEC's deformable-block contacts), each with a joint state that persists across
//! re-detection (`contact::detect`).

use super::Gather;
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
    /// For each node, the slots of the contact-force buffer acting on it (contact·3 + role): made
    /// with the list (`indexed`, `none`, `kept`), so it always follows it.
    pub gather: Gather,
}

impl Contacts {
    pub fn len(&self) -> usize {
        self.node.len()
    }

    pub fn is_empty(&self) -> bool {
        self.node.is_empty()
    }

    /// No contacts, among `nodes` nodes.
    pub fn none(nodes: usize) -> Contacts {
        Contacts::default().indexed(nodes, &[])
    }

    /// The list with its gather made for `nodes` nodes and the blocks' `edges`.
    pub fn indexed(mut self, nodes: usize, edges: &[[u32; 2]]) -> Contacts {
        self.gather = Gather::new(nodes, &self.triples(edges));
        self
    }

    /// The contacts `c` with `keep[c]`, in order, indexed as `indexed` does.
    pub fn kept(&self, keep: &[bool], nodes: usize, edges: &[[u32; 2]]) -> Contacts {
        let mut kept = Contacts::default();
        for (c, _) in keep.iter().enumerate().filter(|(_, k)| **k) {
            kept.node.push(self.node[c]);
            kept.edge.push(self.edge[c]);
            kept.block.push(self.block[c]);
            kept.xi.push(self.xi[c]);
            kept.length.push(self.length[c]);
            kept.material.push(self.material[c]);
            kept.corner.push(self.corner[c]);
            kept.state.push(self.state[c]);
        }
        kept.indexed(nodes, edges)
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
