//! Model state as structure-of-arrays: nodes, zones, blocks, contacts, supports and the gather
//! tables, indexed by typed ids. Stages of the cycle borrow the parts they need.

pub mod blocks;
pub mod bodies;
mod contacts;
mod materials;
pub mod nodes;
mod velocity;
pub mod zones;

pub use contacts::Contacts;
pub use materials::Materials;
pub use nodes::{BODY, FIX_X, FIX_Y, Nodes};
pub use zones::{Stress, Zones, traction};

use crate::support::Supports;

/// Index of a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct NodeId(pub u32);

/// Index of a zone material.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct MaterialId(pub u32);

/// For each node, the slots of the zone-force buffer that hold its contributions, in a fixed order
/// (compressed rows): node n gathers `slots[start[n]..start[n+1]]`, each an index into the flat
/// per-zone force array (zone·3 + local corner).
#[derive(Debug, Clone, Default)]
pub struct Gather {
    pub start: Vec<u32>,
    pub(crate) slots: Vec<u32>,
}

impl Gather {
    /// Build from zone connectivity.
    pub fn new(num_nodes: usize, zone_nodes: &[[u32; 3]]) -> Gather {
        let flat: Vec<u32> = zone_nodes.iter().flatten().copied().collect();
        Gather::from_slots(num_nodes, &flat)
    }

    /// Build from the node of each slot (slot s acts on node `slot_nodes[s]`).
    pub fn from_slots(num_nodes: usize, slot_nodes: &[u32]) -> Gather {
        let mut count = vec![0u32; num_nodes + 1];
        for &n in slot_nodes {
            count[n as usize + 1] += 1;
        }
        for i in 0..num_nodes {
            count[i + 1] += count[i];
        }
        let mut fill = count.clone();
        let mut slots = vec![0u32; slot_nodes.len()];
        for (s, &n) in slot_nodes.iter().enumerate() {
            slots[fill[n as usize] as usize] = s as u32;
            fill[n as usize] += 1;
        }
        Gather {
            start: count,
            slots,
        }
    }

    /// Slots of node `n`.
    pub fn of(&self, n: usize) -> &[u32] {
        &self.slots[self.start[n] as usize..self.start[n + 1] as usize]
    }
}

/// Everything a run evolves (nodes, zones, rigid and simple blocks, contacts, supports, with the
/// gather tables that follow them) and the material catalogue the laws come from.
pub struct Model {
    pub nodes: Nodes,
    pub zones: Zones,
    pub gather: Gather,
    /// Largest extent of the model, m (a length scale for runaway checks).
    pub size: f64,
    pub blocks: blocks::Blocks,
    /// Rigid and simple blocks (deformable blocks have zones instead).
    pub bodies: bodies::Bodies,
    /// Contacts, with the gather of their force slots.
    pub contacts: Contacts,
    /// Contact detection tolerance, m.
    pub contact_tolerance: f64,
    /// Rock bolts and liners (inactive until installed).
    pub supports: Supports,
    /// Mixed discretization (`zoning.mixed`): 1 / (area of the zones around each node), 1/m²;
    /// `None` when each zone keeps its own volumetric strain.
    pub mixed: Option<Vec<f64>>,
    /// For each node, the slots of the support-force buffer acting on it.
    pub(crate) support_gather: Gather,
    /// The elastic far field outside the region's outer boundary (`region.far_field`), if any.
    pub far_field: Option<crate::far_field::FarField>,
    /// For each node, the slots of the far field's force buffer acting on it (none without one).
    pub(crate) far_gather: Gather,
    /// Zone and joint laws, and which joint material each joint feature and hole wall takes.
    pub materials: Materials,
    /// The quiet boundary in force (`dynamics::QuietBoundary`: dynamic stages only), if any.
    pub quiet: Option<crate::dynamics::QuietBoundary>,
    /// The prescribed motions and load histories in force (`dynamics::Inputs`: dynamic stages
    /// only), if any.
    pub inputs: Option<crate::dynamics::Inputs>,
    /// Each node's peak particle velocity over the dynamic stages so far (`None` before the
    /// first).
    pub peaks: Option<crate::dynamics::Peaks>,
    /// The blocks on the excavations' walls watched for ejection since the first dynamic stage
    /// (`None` before it).
    pub ejection: Option<crate::dynamics::Ejection>,
    /// The energy balance of the dynamic stage in progress, when a history asks for it.
    pub energy: Option<crate::dynamics::Energy>,
}
