//! Stages: what changes between the solves of a staged run — excavations removed, zone and joint
//! materials, gravity and boundary conditions changed, supports installed, the support pressure
//! left on their walls (convergence–confinement), displacements reset.

use adit_meshing::BoundaryEdge;

use crate::model::{FIX_X, FIX_Y, MaterialId, Model, traction};
use crate::scene::{BoundaryCondition, Scene, Stage};
use crate::setup::{
    NOT_FILL, Setup, add_body_weight, add_tractions, add_zone_weight, boundary_effect,
    in_situ_stress, joint_law, rock_walls, zone_law,
};

/// What the stages so far have done.
#[derive(Debug, Clone, Default)]
pub struct Staging {
    /// Support fraction now applied on the walls of each excavation (index as in the scene), or
    /// `None` while it is filled; an excavation open from the start begins at 0.
    support: Vec<Option<f64>>,
    /// Gravitational acceleration now, m/s².
    gravity: [f64; 2],
    /// Boundary conditions now in force.
    boundary: Vec<BoundaryCondition>,
    /// Stages applied so far.
    applied: usize,
}

impl Staging {
    /// Excavations that no stage names are open from the start, unsupported.
    pub fn new(scene: &Scene) -> Staging {
        Staging {
            support: scene
                .excavations
                .iter()
                .map(|e| (!scene.is_staged(&e.name)).then_some(0.0))
                .collect(),
            gravity: scene.gravity,
            boundary: scene.boundary.clone(),
            applied: 0,
        }
    }

    /// Apply `stage` to the model before its solve: remove the rock of the excavations it names,
    /// give the zone and joint materials it names their new properties and its regions their new
    /// material, change gravity and the boundary conditions, install the bolts and liners it
    /// names, set the support pressure of every excavation made so far to `support_fraction` × the
    /// in-situ traction on its walls, and reset displacements if asked.
    pub fn apply(&mut self, stage: &Stage, scene: &Scene, built: &mut Setup) {
        for name in &stage.excavate {
            let j = scene
                .excavations
                .iter()
                .position(|e| e.name == *name)
                .expect("validated");
            // The rock's contacts go with it: the wall is unsupported until a pressure is set.
            remove_fill(&mut built.model, j as u32);
            self.support[j] = Some(0.0);
        }
        for (name, spec) in &stage.materials {
            built.model.laws[index_of(&scene.materials, name)] = zone_law(spec);
        }
        // The stage's regions, resolved when the model was built (none for a scene without stages).
        let regions = built
            .stage_materials
            .get(self.applied)
            .cloned()
            .unwrap_or_default();
        self.applied += 1;
        for (b, m) in regions {
            set_block_material(&mut built.model, b as usize, m);
        }
        if let Some(g) = stage.gravity {
            let now = self.gravity;
            let model = &mut built.model;
            let change = [g[0] - now[0], g[1] - now[1]];
            add_zone_weight(&mut model.nodes, &model.zones, &model.laws, change);
            add_body_weight(&mut model.bodies, &model.laws, change);
            self.gravity = g;
        }
        for (name, spec) in &stage.joint_materials {
            built.model.joint_laws[index_of(&scene.joint_materials, name)] = joint_law(spec);
        }
        if let Some(list) = &stage.boundary {
            self.change_boundary(list, scene, built);
        }
        for name in &stage.install {
            let model = &mut built.model;
            let known = model.supports.install(name, &model.nodes.disp);
            debug_assert!(known, "validated: '{name}' is a bolt group or liner");
        }
        let poisson = scene.materials[&scene.region.material].poisson;
        for (j, support) in self.support.iter_mut().enumerate() {
            let Some(now) = support else { continue };
            let change = stage.support_fraction - *now;
            if change != 0.0 {
                let walls: Vec<BoundaryEdge> = rock_walls(&built.boundary, &built.model, j as u32)
                    .copied()
                    .collect();
                add_tractions(&mut built.model.nodes, walls.iter(), |p, n| {
                    let t = traction(&in_situ_stress(&scene.in_situ, p[1], poisson), n);
                    [change * t[0], change * t[1]]
                });
                *now = stage.support_fraction;
            }
        }
        if stage.reset_displacements {
            built.model.nodes.origin.clone_from(&built.model.nodes.disp);
        }
    }

    /// Replace the boundary conditions in force by `list`: fixities only the old list set are
    /// released, new ones hold their components still, and the loads change by the new list's
    /// minus the old one's. Nodes of removed rock stay held; `setup` refused a change of fixity at a
    /// rigid or simple block's node.
    fn change_boundary(&mut self, list: &[BoundaryCondition], scene: &Scene, built: &mut Setup) {
        let effect = |conditions: &[BoundaryCondition]| {
            boundary_effect(
                conditions,
                scene,
                &built.boundary,
                &built.domain,
                &built.part_nodes,
                &built.model.nodes.pos,
            )
        };
        let (old_fixed, old_load) = effect(&self.boundary);
        let (new_fixed, new_load) = effect(list);
        let model = &mut built.model;
        let nodes = &mut model.nodes;
        for n in 0..nodes.len() {
            if model
                .blocks
                .is_removed(model.blocks.block_of_node(n as u32))
            {
                continue;
            }
            let released = old_fixed[n] & !new_fixed[n];
            for (d, flag) in [(0, FIX_X), (1, FIX_Y)] {
                if new_fixed[n] & flag != 0 {
                    nodes.vel[n][d] = 0.0;
                }
                nodes.applied[n][d] += new_load[n][d] - old_load[n][d];
            }
            nodes.fixed[n] = (nodes.fixed[n] & !released) | new_fixed[n];
        }
        self.boundary = list.to_vec();
    }

    /// Mean closure (m, inward positive) of the wall of each excavation made so far: the
    /// displacement of the rock's wall nodes along the inward normal of their wall edges.
    pub fn closures(
        &self,
        scene: &Scene,
        built: &Setup,
    ) -> std::collections::BTreeMap<String, f64> {
        let m = &built.model;
        let mut out = std::collections::BTreeMap::new();
        for (j, support) in self.support.iter().enumerate() {
            if support.is_none() {
                continue;
            }
            let (mut sum, mut count) = (0.0, 0usize);
            for e in rock_walls(&built.boundary, m, j as u32) {
                let [a, b] = e.nodes.map(|n| n as usize);
                let (pa, pb) = (m.nodes.pos[a], m.nodes.pos[b]);
                let len = (pb[0] - pa[0]).hypot(pb[1] - pa[1]);
                // Outward normal of the rock (material on the left) points into the excavation.
                let n = [(pb[1] - pa[1]) / len, -(pb[0] - pa[0]) / len];
                for k in [a, b] {
                    let u = m.nodes.disp[k];
                    sum += u[0] * n[0] + u[1] * n[1];
                    count += 1;
                }
            }
            let closure = sum / count.max(1) as f64;
            // A failed run's state may not be finite: its closure is left out, not written null.
            if closure.is_finite() {
                out.insert(scene.excavations[j].name.clone(), closure);
            }
        }
        out
    }

    /// The support fraction now applied (that of the last stage).
    pub fn support_fraction(&self) -> f64 {
        self.support.iter().flatten().copied().next().unwrap_or(0.0)
    }
}

/// Index of the law of material `name`: zone and joint laws are indexed in the order of the
/// scene's `materials` and `joint_materials` (sorted names).
fn index_of<V>(materials: &std::collections::BTreeMap<String, V>, name: &str) -> usize {
    materials
        .keys()
        .position(|n| n == name)
        .expect("validated: a material of the scene")
}

/// Give block `b` zone material `m`, keeping its stress, yield state and plastic strain; removed
/// rock keeps its null law.
fn set_block_material(model: &mut Model, b: usize, m: MaterialId) {
    if model.blocks.is_removed(b) {
        return;
    }
    let (z0, z1) = (model.blocks.zone_start[b], model.blocks.zone_start[b + 1]);
    for z in z0 as usize..z1 as usize {
        model.zones.material[z] = m;
    }
    if let Some(k) = model.bodies.block.iter().position(|&bb| bb as usize == b) {
        model.bodies.material[k] = m;
    }
}

/// Remove the rock filling excavation `j`: its blocks are marked removed (detection skips them),
/// their zones take the null law, their nodes and bodies are held still and unloaded, and the
/// contacts they made are dropped, so the walls lose the traction the rock gave them.
pub fn remove_fill(model: &mut Model, j: u32) {
    let null = model
        .null_material
        .expect("a staged scene has the null law");
    let n_blocks = model.blocks.len();
    model.blocks.removed.resize(n_blocks, false);
    for b in 0..n_blocks {
        if model.fill.get(b).copied().unwrap_or(NOT_FILL) != j {
            continue;
        }
        model.blocks.removed[b] = true;
        let (z0, z1) = (model.blocks.zone_start[b], model.blocks.zone_start[b + 1]);
        for z in z0 as usize..z1 as usize {
            model.zones.material[z] = null;
            model.zones.stress[z] = [0.0; 4];
            model.zones.state[z] = 0;
        }
        let (n0, n1) = (model.blocks.node_start[b], model.blocks.node_start[b + 1]);
        for n in n0 as usize..n1 as usize {
            model.nodes.fixed[n] |= FIX_X | FIX_Y;
            model.nodes.vel[n] = [0.0; 2];
            model.nodes.applied[n] = [0.0; 2];
        }
        if let Some(k) = model.bodies.block.iter().position(|&bb| bb as usize == b) {
            model.bodies.constraint[k] =
                std::array::from_fn(|i| std::array::from_fn(|j| if i == j { 1.0 } else { 0.0 }));
            model.bodies.velocity[k] = [0.0; 6];
            model.bodies.weight[k] = [0.0; 2];
            model.bodies.stress[k] = [0.0; 4];
        }
    }
    let blocks = &model.blocks;
    let keep: Vec<bool> = (0..model.contacts.len())
        .map(|c| {
            let node_block = blocks.block_of_node(model.contacts.node[c]);
            !blocks.is_removed(node_block) && !blocks.is_removed(model.contacts.block[c] as usize)
        })
        .collect();
    model.contacts = model
        .contacts
        .kept(&keep, model.nodes.len(), &model.blocks.edges);
}
