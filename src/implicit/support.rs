//! Which blocks nothing holds: a block whose nodes are all free and that no chain of contacts
//! joins to a block with a fixed node has no stiffness against moving as a whole, so the matrix
//! is singular. They are named before any factorization (a mechanism, not a solver failure).

use crate::model::{FIX_X, FIX_Y, Model};

/// The blocks (not removed) that are neither fixed at a node nor joined by contacts, through
/// other blocks, to one that is.
pub fn unsupported_blocks(model: &Model) -> Vec<usize> {
    let blocks = &model.blocks;
    let n = blocks.len();
    // Union–find over blocks, joined by every contact (its node's block and its edge's block).
    let mut parent: Vec<usize> = (0..n).collect();
    fn root(parent: &mut [usize], mut b: usize) -> usize {
        while parent[b] != b {
            parent[b] = parent[parent[b]];
            b = parent[b];
        }
        b
    }
    let c = &model.contacts;
    for k in 0..c.len() {
        let a = root(&mut parent, blocks.block_of_node(c.node[k]));
        let b = root(&mut parent, c.block[k] as usize);
        parent[a] = b;
    }
    let mut held = vec![false; n];
    for (node, &f) in model.nodes.fixed.iter().enumerate() {
        if f & (FIX_X | FIX_Y) != 0 {
            let b = blocks.block_of_node(node as u32);
            if !blocks.is_removed(b) {
                let r = root(&mut parent, b);
                held[r] = true;
            }
        }
    }
    (0..n)
        .filter(|&b| !blocks.is_removed(b) && !held[root(&mut parent, b)])
        .collect()
}
