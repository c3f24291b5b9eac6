//! The stage plan: what each stage does, resolved once from the scene when the model is set up
//! (excavation, material and support names to ids, stage regions to blocks, each stage's solve),
//! with the boundary the conditions act on and the in-situ stress the walls carry. The stage
//! driver (`Staging`) works on the model and this plan, never on the scene.

use std::collections::BTreeMap;

use adit_meshing::{BoundaryEdge, Domain};

use super::BoundaryEffect;
use super::catalogue::{joint_law, zone_law};
use crate::joint::JointLaw;
use crate::law::ZoneLaw;
use crate::model::MaterialId;
use crate::scene::{InSitu, Scene, SolveSpec, Stage};
use crate::support::SupportId;

/// The boundary of the blocks: where boundary conditions and wall tractions act.
pub struct Boundary {
    /// Boundary edges of all blocks (global node ids), material on the left, labelled by kind.
    pub edges: Vec<BoundaryEdge>,
    /// The validated domain the blocks cover.
    pub domain: Domain,
    /// Boundary nodes of each named part (`outer`, region edge names, excavation names), sorted.
    pub part_nodes: BTreeMap<String, Vec<u32>>,
}

/// The in-situ stress field and the Poisson's ratio that gives its σzz where the scene leaves it
/// out (that of the region's rock).
#[derive(Debug, Clone)]
pub struct InSituField {
    pub in_situ: InSitu,
    pub poisson: f64,
}

impl InSituField {
    /// In-situ stress at elevation y (m), Pa: [σxx, σyy, σzz, σxy] (`in_situ_stress`).
    pub fn at(&self, y: f64) -> [f64; 4] {
        super::in_situ_stress(&self.in_situ, y, self.poisson)
    }
}

/// What one stage does, in the order `Staging::apply` does it.
pub struct StagePlan {
    /// Name, reported in the summary.
    pub name: String,
    /// Excavations whose rock this stage removes.
    pub excavate: Vec<u32>,
    /// Zone materials given new properties: the material and its new law.
    pub materials: Vec<(MaterialId, Box<dyn ZoneLaw>)>,
    /// Blocks that take another zone material, with that material.
    pub regions: Vec<(u32, MaterialId)>,
    /// Gravitational acceleration from this stage on, m/s² (`None`: unchanged).
    pub gravity: Option<[f64; 2]>,
    /// Joint materials given new properties: the joint material id and its new law.
    pub joint_materials: Vec<(u32, Box<dyn JointLaw>)>,
    /// The fixities and loads of the boundary conditions from this stage on (`None`: unchanged).
    pub boundary: Option<BoundaryEffect>,
    /// The quiet boundary of the conditions in force during this stage, if they have one.
    pub quiet: Option<crate::dynamics::QuietBoundary>,
    /// The prescribed motions and load histories of the conditions in force during this stage,
    /// if they have any.
    pub inputs: Option<crate::dynamics::Inputs>,
    /// Bolt groups and liners installed, after the excavations.
    pub install: Vec<SupportId>,
    /// Fraction of the in-situ traction left on the walls of every excavation made so far.
    pub support_fraction: f64,
    /// Measure displacements from the start of this stage on.
    pub reset_displacements: bool,
    /// How to solve this stage.
    pub solve: SolveSpec,
    /// The factor of safety to search after the solve, if asked.
    pub factor_of_safety: Option<crate::scene::FactorOfSafetySpec>,
}

/// The whole plan: the state before the first stage and the stages in order.
pub struct Plan {
    /// Name of each excavation; its index is the excavation id of `EdgeKind::Excavation`.
    pub excavations: Vec<String>,
    /// For each block, the staged excavation whose rock fills it, or `NOT_FILL`.
    pub fill: Vec<u32>,
    pub boundary: Boundary,
    pub in_situ: InSituField,
    /// Excavations open (empty) from the start: those no stage excavates.
    pub open: Vec<bool>,
    /// Gravitational acceleration before the first stage, m/s².
    pub gravity: [f64; 2],
    /// The fixities and loads of the boundary conditions before the first stage.
    pub conditions: BoundaryEffect,
    /// The stages; a scene without stages is one stage named `solve` with the scene's solve.
    pub stages: Vec<StagePlan>,
    /// Whether the scene has stages of its own (the summary lists them and the ground reaction
    /// curve is written).
    pub(crate) staged: bool,
    /// Whether a history reads the energy balance, which dynamic stages then keep
    /// (`dynamics::Energy`).
    pub energy: bool,
}

/// What the plan is made from besides the scene: names resolved to ids by the catalogues and
/// supports, the stage regions resolved to blocks.
pub(super) struct Resolved<'a> {
    pub(crate) zone_id: &'a dyn Fn(&str) -> anyhow::Result<MaterialId>,
    pub(crate) joint_id: &'a dyn Fn(&str) -> anyhow::Result<u32>,
    pub(crate) support_id: &'a dyn Fn(&str) -> anyhow::Result<SupportId>,
    /// For each stage, the blocks its `regions` reach and their new material.
    pub(crate) stage_regions: Vec<Vec<(u32, MaterialId)>>,
    /// The fixities and loads of the top-level `boundary`.
    pub(crate) initial_boundary: BoundaryEffect,
    /// Those of each stage's `boundary`, if it has one.
    pub(crate) stage_boundary: Vec<Option<BoundaryEffect>>,
    /// The quiet boundary in force during each stage, if any.
    pub(crate) stage_quiet: Vec<Option<crate::dynamics::QuietBoundary>>,
    /// The prescribed motions and load histories in force during each stage, if any.
    pub(crate) stage_inputs: Vec<Option<crate::dynamics::Inputs>>,
}

impl Plan {
    pub(super) fn of(
        scene: &Scene,
        boundary: Boundary,
        fill: Vec<u32>,
        in_situ: InSituField,
        r: Resolved,
    ) -> anyhow::Result<Plan> {
        let excavations: Vec<String> = scene.excavations.iter().map(|e| e.name.clone()).collect();
        let excavation_id = |name: &str| -> anyhow::Result<u32> {
            let j = excavations.iter().position(|n| n == name);
            j.map(|j| j as u32)
                .ok_or_else(|| anyhow::anyhow!("no excavation '{name}'"))
        };
        let single = [Stage {
            name: "solve".into(),
            ..Default::default()
        }];
        let staged = !scene.stages.is_empty();
        let stages = if staged { &scene.stages[..] } else { &single };
        let mut plans = Vec::with_capacity(stages.len());
        let mut stage_boundary = r.stage_boundary.into_iter();
        let mut stage_quiet = r.stage_quiet.into_iter();
        let mut stage_inputs = r.stage_inputs.into_iter();
        for (i, st) in stages.iter().enumerate() {
            let p = format!("stages[{i}]");
            plans.push(StagePlan {
                name: st.name.clone(),
                excavate: st
                    .excavate
                    .iter()
                    .map(|n| excavation_id(n))
                    .collect::<anyhow::Result<_>>()?,
                materials: st
                    .materials
                    .iter()
                    .map(|(n, m)| {
                        let law = zone_law(m, &format!("{p}.materials.{n}"))?;
                        Ok(((r.zone_id)(n)?, law))
                    })
                    .collect::<anyhow::Result<_>>()?,
                regions: r.stage_regions.get(i).cloned().unwrap_or_default(),
                gravity: st.gravity,
                joint_materials: st
                    .joint_materials
                    .iter()
                    .map(|(n, m)| {
                        let law = joint_law(m, &format!("{p}.joint_materials.{n}"))?;
                        Ok(((r.joint_id)(n)?, law))
                    })
                    .collect::<anyhow::Result<_>>()?,
                boundary: stage_boundary.next().flatten(),
                quiet: stage_quiet.next().flatten(),
                inputs: stage_inputs.next().flatten(),
                install: st
                    .install
                    .iter()
                    .map(|n| (r.support_id)(n))
                    .collect::<anyhow::Result<_>>()?,
                support_fraction: st.support_fraction,
                reset_displacements: st.reset_displacements,
                solve: st.solve.clone().unwrap_or_else(|| scene.solve.clone()),
                factor_of_safety: st.factor_of_safety,
            });
        }
        Ok(Plan {
            open: scene
                .excavations
                .iter()
                .map(|e| !scene.is_staged(&e.name))
                .collect(),
            excavations,
            fill,
            boundary,
            in_situ,
            gravity: scene.gravity,
            conditions: r.initial_boundary,
            stages: plans,
            staged,
            energy: scene.histories.iter().any(|h| h.quantity.is_energy()),
        })
    }
}
