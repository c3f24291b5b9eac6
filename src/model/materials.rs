//! The material catalogue: the law of each zone material and joint material with their names, and
//! which joint material each joint feature and hole wall takes. Set up once from the scene; a
//! stage may give a material new properties (a new law in its slot), never new slots.

use super::MaterialId;
use crate::joint::JointLaw;
use crate::law::ZoneLaw;

pub struct Materials {
    /// Zone laws, indexed by `MaterialId`: the scene's materials in name order, then (staged
    /// scenes) the null law excavated zones take.
    pub zone: Vec<Box<dyn ZoneLaw>>,
    /// Zone material names, indexed by `MaterialId`.
    pub zone_names: Vec<String>,
    /// The null law's id (staged scenes only).
    pub null: Option<MaterialId>,
    /// Joint laws, indexed by joint material id: the scene's joint materials in name order, then
    /// the glued interfaces of staged fills and inclusions.
    pub joint: Vec<Box<dyn JointLaw>>,
    /// Joint material names, indexed by joint material id.
    pub(crate) joint_names: Vec<String>,
    /// Joint material of each joint feature (`EdgeKind::Joint(k)`: sets first, then explicit
    /// joints, then Voronoi grain boundaries).
    pub feature: Vec<u32>,
    /// Joint material of each hole's wall: a staged excavation's fill, an inclusion's interface,
    /// `contact::detect::NO_MATERIAL` for a hole open from the start.
    pub hole: Vec<u32>,
}

impl Materials {
    /// The id of zone material `name`.
    pub fn zone_id(&self, name: &str) -> Option<MaterialId> {
        let i = self.zone_names.iter().position(|n| n == name);
        i.map(|i| MaterialId(i as u32))
    }

    /// The id of joint material `name`.
    pub fn joint_id(&self, name: &str) -> Option<u32> {
        let i = self.joint_names.iter().position(|n| n == name);
        i.map(|i| i as u32)
    }
}
