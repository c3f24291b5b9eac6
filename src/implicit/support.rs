//! Which blocks nothing holds: a block whose nodes are all free and that no chain of contacts
//! joins to a block with a fixed node has no stiffness against moving as a whole, so the matrix
//! is singular. They are named before any factorization (a mechanism, not a solver failure).

use adit_meshing::union_find::UnionFind;

use crate::model::{FIX_X, FIX_Y, Model};

/// The blocks (not removed) that are neither fixed at a node nor joined by contacts, through
/// other blocks, to one that is.
pub fn unsupported_blocks(model: &Model) -> Vec<usize> {
    let blocks = &model.blocks;
    let n = blocks.len();
    // Union–find over blocks, joined by every contact (its node's block and its edge's block).
    let mut sets = UnionFind::new(n);
    let c = &model.contacts;
    for k in 0..c.len() {
        sets.join(blocks.block_of_node(c.node[k]), c.block[k] as usize);
    }
    let mut held = vec![false; n];
    for (node, &f) in model.nodes.fixed.iter().enumerate() {
        if f & (FIX_X | FIX_Y) != 0 {
            let b = blocks.block_of_node(node as u32);
            if !blocks.is_removed(b) {
                held[sets.root(b)] = true;
            }
        }
    }
    (0..n)
        .filter(|&b| !blocks.is_removed(b) && !held[sets.root(b)])
        .collect()
}
