//! Blocks: each block owns a contiguous range of nodes and zones and a closed boundary (its rings
//! of edges, material on the left), whose edges carry the kind of feature they lie on.

use adit_meshing::EdgeKind;

/// Marks "no edge" in `Blocks::node_edges`.
pub const NO_EDGE: u32 = u32::MAX;

/// Marks "no block" in `Blocks::edge_across`.
pub const NO_BLOCK: u32 = u32::MAX;

/// Structure-of-arrays block data. Ranges: block b owns nodes `node_start[b]..node_start[b+1]`,
/// zones `zone_start[b]..zone_start[b+1]` and boundary edges `edge_start[b]..edge_start[b+1]`.
#[derive(Debug, Clone, Default)]
pub struct Blocks {
    pub node_start: Vec<u32>,
    pub(crate) zone_start: Vec<u32>,
    pub(crate) edge_start: Vec<u32>,
    /// Boundary edges (node ids), material on the left.
    pub edges: Vec<[u32; 2]>,
    /// What each boundary edge lies on.
    pub(crate) edge_kind: Vec<EdgeKind>,
    /// For each node, its boundary edges [incoming, outgoing], or `NO_EDGE` for interior nodes.
    pub(crate) node_edges: Vec<[u32; 2]>,
    /// For each boundary edge, the block whose boundary has the same edge the other way at the
    /// start (the block across a joint or a filled excavation's wall, where the two zonings put
    /// their nodes at the same places), or `NO_BLOCK` (empty: none known).
    pub(crate) edge_across: Vec<u32>,
    /// Corner rounding radius of each node, m (`contact::rounding`; 0 but at the convex corners of
    /// rigid and simple blocks; empty: no rounding).
    pub round: Vec<f64>,
    /// Radius of the arc a sharp convex corner (round 0) would have, m, used only by its
    /// corner-to-corner contacts, for their normal and gap (`contact::rounding::contact_arc`): the
    /// contact tolerance; 0, sharp corners meet edges only.
    pub sharp_round: f64,
    /// Blocks removed by an excavation stage (empty: none).
    pub(crate) removed: Vec<bool>,
}

impl Blocks {
    /// Number of blocks.
    pub fn len(&self) -> usize {
        self.node_start.len().saturating_sub(1)
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Boundary edge ids of block `b`.
    pub fn edge_range(&self, b: usize) -> std::ops::Range<usize> {
        self.edge_start[b] as usize..self.edge_start[b + 1] as usize
    }

    /// Whether block `b` has been excavated.
    pub fn is_removed(&self, b: usize) -> bool {
        self.removed.get(b).copied().unwrap_or(false)
    }

    /// Rounding radius of node `n`, m.
    pub fn round_of(&self, n: u32) -> f64 {
        self.round.get(n as usize).copied().unwrap_or(0.0)
    }

    /// Block owning node `n`.
    pub fn block_of_node(&self, n: u32) -> usize {
        self.node_start.partition_point(|&s| s <= n) - 1
    }

    /// The block across edge `e` (`edge_across`), if it is still there.
    pub fn across(&self, e: u32) -> Option<usize> {
        let b = *self.edge_across.get(e as usize)?;
        (b != NO_BLOCK && !self.is_removed(b as usize)).then_some(b as usize)
    }

    /// The mean of block `b`'s node positions `pos` (m): where a message places the block.
    pub fn node_mean(&self, b: usize, pos: &[[f64; 2]]) -> [f64; 2] {
        let nodes = &pos[self.node_start[b] as usize..self.node_start[b + 1] as usize];
        let count = nodes.len().max(1) as f64;
        [0, 1].map(|d| nodes.iter().map(|p| p[d]).sum::<f64>() / count)
    }
}
