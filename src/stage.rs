//! Stages: what changes between the solves of a staged run — excavations removed, zone and joint
//! materials, gravity and boundary conditions changed, supports installed, the support pressure
//! left on their walls (convergence–confinement), displacements reset.

use adit_meshing::BoundaryEdge;

use std::collections::BTreeMap;

use crate::cycle::{Cycle, CycleParams, ZoneScheme};
use crate::model::{FIX_X, FIX_Y, MaterialId, Model, traction};
use crate::output::WallMoves;
use crate::setup::{
    BoundaryEffect, NOT_FILL, Plan, StagePlan, add_body_weight, add_tractions, add_zone_weight,
    rock_walls,
};

/// What the stages so far have done.
#[derive(Debug, Clone, Default)]
pub struct Staging {
    /// Support fraction now applied on the walls of each excavation (index as in the scene), or
    /// `None` while it is filled; an excavation open from the start begins at 0.
    support: Vec<Option<f64>>,
    /// Gravitational acceleration now, m/s².
    gravity: [f64; 2],
    /// Fixities and loads of the boundary conditions now in force.
    boundary: BoundaryEffect,
}

impl Staging {
    /// The state before the first stage: excavations that no stage names are open, unsupported.
    pub fn new(plan: &Plan) -> Staging {
        Staging {
            support: plan.open.iter().map(|&open| open.then_some(0.0)).collect(),
            gravity: plan.gravity,
            boundary: plan.conditions.clone(),
        }
    }

    /// Apply `stage` to the model before its solve: remove the rock of the excavations it names,
    /// give the zone and joint materials it names their new properties and its regions their new
    /// material, change gravity and the boundary conditions, install the bolts and liners it
    /// names, set the support pressure of every excavation made so far to `support_fraction` × the
    /// in-situ traction on its walls, and reset displacements if asked. A quiet boundary in force
    /// in the stage holds, as constant loads, the forces the fixities it replaces exerted when the
    /// stage began (`held_reactions`).
    pub fn apply(&mut self, stage: &StagePlan, model: &mut Model, plan: &Plan) {
        let held = stage.quiet.as_ref().map(|q| {
            let before: Vec<u8> = q
                .nodes
                .iter()
                .map(|&n| model.nodes.fixed[n as usize])
                .collect();
            (q.nodes.clone(), before, held_reactions(model, &q.nodes))
        });
        for &j in &stage.excavate {
            // The rock's contacts go with it: the wall is unsupported until a pressure is set.
            remove_fill(model, &plan.fill, j);
            self.support[j as usize] = Some(0.0);
        }
        for (m, law) in &stage.materials {
            model.materials.zone[m.0 as usize] = law.boxed_copy();
        }
        for &(b, m) in &stage.regions {
            set_block_material(model, b as usize, m);
        }
        if let Some(g) = stage.gravity {
            let now = self.gravity;
            let change = [g[0] - now[0], g[1] - now[1]];
            let laws = &model.materials.zone;
            add_zone_weight(&mut model.nodes, &model.zones, laws, change);
            add_body_weight(&mut model.bodies, laws, change);
            self.gravity = g;
        }
        for (k, law) in &stage.joint_materials {
            model.materials.joint[*k as usize] = law.boxed_copy();
        }
        if let Some(effect) = &stage.boundary {
            self.change_boundary(effect, model);
        }
        model.quiet = stage.quiet.clone();
        if let Some(mut inputs) = model.inputs.take() {
            inputs.stop(&mut model.nodes.vel, &mut model.nodes.applied);
        }
        model.inputs = stage.inputs.clone();
        let dynamic = stage.solve.mode == crate::scene::SolveMode::Dynamic;
        match model.peaks.as_mut() {
            Some(peaks) => peaks.begin(&model.nodes.vel),
            None if dynamic => model.peaks = Some(crate::dynamics::Peaks::new(&model.nodes.vel)),
            None => {}
        }
        if dynamic && model.ejection.is_none() {
            let open: Vec<u32> = (self.support.iter().enumerate())
                .filter(|(_, s)| s.is_some())
                .map(|(j, _)| j as u32)
                .collect();
            model.ejection = Some(crate::dynamics::Ejection::new(wall_blocks(
                model, plan, &open,
            )));
        }
        model.energy = (dynamic && plan.energy).then(|| {
            let (nodes, bodies) = (&model.nodes, &model.bodies);
            crate::dynamics::Energy::start(
                &nodes.vel,
                &bodies.velocity,
                &nodes.applied,
                &model.zones.stress,
                model.supports.slot_nodes(),
            )
        });
        if let Some((nodes, before, reactions)) = held {
            hold_reactions(model, &nodes, &before, &reactions);
        }
        for &id in &stage.install {
            model.supports.install(id, &model.nodes.disp);
        }
        for (j, support) in self.support.iter_mut().enumerate() {
            let Some(now) = support else { continue };
            let change = stage.support_fraction - *now;
            if change != 0.0 {
                let edges = &plan.boundary.edges;
                let walls: Vec<BoundaryEdge> =
                    rock_walls(edges, &model.blocks, &plan.fill, j as u32)
                        .copied()
                        .collect();
                add_tractions(&mut model.nodes, walls.iter(), |p, n| {
                    let t = traction(&plan.in_situ.at(p[1]), n);
                    [change * t[0], change * t[1]]
                });
                *now = stage.support_fraction;
            }
        }
        if stage.reset_displacements {
            model.nodes.origin.clone_from(&model.nodes.disp);
        }
        carry_net_load(model);
    }

    /// Replace the boundary conditions in force by those with `effect`: fixities only the old
    /// ones set are released, new ones hold their components still, and the loads change by the
    /// new minus the old. Nodes of removed rock stay held; `setup` refused a change of fixity at a
    /// rigid or simple block's node.
    fn change_boundary(&mut self, effect: &BoundaryEffect, model: &mut Model) {
        let (old_fixed, old_load) = &self.boundary;
        let (new_fixed, new_load) = effect;
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
        self.boundary = effect.clone();
    }

    /// Mean closure (m, inward positive) of the wall of each excavation made so far: the
    /// displacement of the rock's wall nodes along the inward normal of their wall edges.
    pub fn closures(&self, model: &Model, plan: &Plan) -> std::collections::BTreeMap<String, f64> {
        let m = model;
        let mut out = std::collections::BTreeMap::new();
        for (j, support) in self.support.iter().enumerate() {
            if support.is_none() {
                continue;
            }
            let (mut sum, mut count) = (0.0, 0usize);
            for e in rock_walls(&plan.boundary.edges, &m.blocks, &plan.fill, j as u32) {
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
                out.insert(plan.excavations[j].clone(), closure);
            }
        }
        out
    }

    /// How the wall of each excavation made so far moved (`WallMoves`): of its rock wall nodes
    /// (by their place at the start), the crown and the invert are those within 1 % of the
    /// wall's height of its top and its bottom nearest its vertical mid-line, the sidewalls those
    /// within 1 % of its width of its leftmost and rightmost nearest its mid-height (a flat roof,
    /// floor or wall is read at its middle, not at a corner); displacements since the start of
    /// the run.
    pub fn wall_moves(&self, model: &Model, plan: &Plan) -> BTreeMap<String, WallMoves> {
        let m = model;
        let pos = &m.nodes.pos;
        let mut out = BTreeMap::new();
        for (j, support) in self.support.iter().enumerate() {
            if support.is_none() {
                continue;
            }
            let nodes: Vec<usize> =
                rock_walls(&plan.boundary.edges, &m.blocks, &plan.fill, j as u32)
                    .flat_map(|e| e.nodes.map(|n| n as usize))
                    .collect();
            let Some(points) = WallPoints::of(&nodes, pos) else {
                continue;
            };
            let u = |n: usize| m.nodes.disp[n];
            let mut moves = WallMoves::of(
                u(points.crown),
                u(points.invert),
                u(points.left),
                u(points.right),
            );
            let pressure = liner_pressure(m, plan, j as u32);
            let centre = nodes.iter().map(|&n| pos[n][1]).sum::<f64>() / nodes.len() as f64;
            let s = plan.in_situ.at(centre);
            let mean = -0.5 * (s[0] + s[1]);
            moves.support_pressure_pa = pressure;
            moves.support_pressure_ratio = if mean > 0.0 { pressure / mean } else { 0.0 };
            // A failed run's state may not be finite: its moves are left out, not written null.
            if moves.is_finite() {
                out.insert(plan.excavations[j].clone(), moves);
            }
        }
        out
    }

    /// The support fraction now applied (that of the last stage).
    pub fn support_fraction(&self) -> f64 {
        self.support.iter().flatten().copied().next().unwrap_or(0.0)
    }
}

/// The pressure the installed liners put on the rock wall of excavation `j`, Pa: their links'
/// forces on its wall nodes along the rock's outward normal there (the edges' normals weighted by
/// their half lengths), against it, over the wall's length.
fn liner_pressure(m: &Model, plan: &Plan, j: u32) -> f64 {
    let mut normal: BTreeMap<usize, [f64; 2]> = BTreeMap::new();
    let mut length = 0.0;
    for e in rock_walls(&plan.boundary.edges, &m.blocks, &plan.fill, j) {
        let [a, b] = e.nodes.map(|n| n as usize);
        let (pa, pb) = (m.nodes.pos[a], m.nodes.pos[b]);
        // Material on the left: (dy, −dx) points out of the rock, into the opening.
        let half = [0.5 * (pb[1] - pa[1]), -0.5 * (pb[0] - pa[0])];
        length += (pb[0] - pa[0]).hypot(pb[1] - pa[1]);
        for n in [a, b] {
            let w = normal.entry(n).or_insert([0.0; 2]);
            *w = [w[0] + half[0], w[1] + half[1]];
        }
    }
    if length <= 0.0 {
        return 0.0;
    }
    let pushed: f64 = (m.supports.liners.rock_forces(&m.nodes.disp))
        .filter_map(|(n, f)| {
            let w = normal.get(&n)?;
            let size = w[0].hypot(w[1]);
            (size > 0.0).then(|| -(f[0] * w[0] + f[1] * w[1]) / size)
        })
        .sum();
    // + 0.0: an empty sum is −0.0.
    pushed / length + 0.0
}

/// The nodes `WallMoves` reads on one wall (`Staging::wall_moves`).
struct WallPoints {
    crown: usize,
    invert: usize,
    left: usize,
    right: usize,
}

impl WallPoints {
    /// Of the wall nodes `nodes` at positions `pos`; none without nodes.
    fn of(nodes: &[usize], pos: &[[f64; 2]]) -> Option<WallPoints> {
        let (lo, hi) = nodes.iter().fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), &n| {
                let p = pos[n];
                (
                    [lo[0].min(p[0]), lo[1].min(p[1])],
                    [hi[0].max(p[0]), hi[1].max(p[1])],
                )
            },
        );
        let mid = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
        let tol = [0.01 * (hi[0] - lo[0]), 0.01 * (hi[1] - lo[1])];
        // Of the nodes whose coordinate `d` is within tolerance of `edge`, the nearest the
        // mid-line across it.
        let pick = |d: usize, edge: f64| {
            let across = 1 - d;
            (nodes.iter().copied())
                .filter(|&n| (pos[n][d] - edge).abs() <= tol[d])
                .min_by(|&a, &b| {
                    let off = |n: usize| (pos[n][across] - mid[across]).abs();
                    off(a).total_cmp(&off(b))
                })
        };
        Some(WallPoints {
            crown: pick(1, hi[1])?,
            invert: pick(1, lo[1])?,
            left: pick(0, lo[0])?,
            right: pick(0, hi[0])?,
        })
    }
}

/// The blocks on the walls of the `open` excavations that joints and that wall alone bound (no
/// edge of theirs on the region's boundary), each with its excavation, its nodes, the unit
/// normal out of the rock into the opening (the sum of its wall edges' outward normals, each as
/// long as its edge, at the current positions) and its nodes' mean position, m.
fn wall_blocks(model: &Model, plan: &Plan, open: &[u32]) -> Vec<crate::dynamics::WallBlock> {
    let blocks = &model.blocks;
    let edges = &plan.boundary.edges;
    let at = |n: u32| {
        let (p, u) = (model.nodes.pos[n as usize], model.nodes.disp[n as usize]);
        [p[0] + u[0], p[1] + u[1]]
    };
    let on_region: std::collections::BTreeSet<usize> = (edges.iter())
        .filter(|e| matches!(e.kind, adit_meshing::EdgeKind::Region(_)))
        .map(|e| blocks.block_of_node(e.nodes[0]))
        .collect();
    let mut walls: BTreeMap<(usize, u32), [f64; 2]> = BTreeMap::new();
    for &j in open {
        for e in rock_walls(edges, blocks, &plan.fill, j) {
            let b = blocks.block_of_node(e.nodes[0]);
            if on_region.contains(&b) {
                continue;
            }
            let ([x0, y0], [x1, y1]) = (at(e.nodes[0]), at(e.nodes[1]));
            let n = walls.entry((b, j)).or_insert([0.0; 2]);
            n[0] += y1 - y0;
            n[1] -= x1 - x0;
        }
    }
    (walls.into_iter())
        .filter_map(|((b, j), n)| {
            let length = n[0].hypot(n[1]);
            let nodes = [blocks.node_start[b], blocks.node_start[b + 1]];
            let count = (nodes[1] - nodes[0]) as f64;
            (length > 0.0 && count > 0.0).then(|| {
                let sum = (nodes[0]..nodes[1])
                    .map(at)
                    .fold([0.0; 2], |s, x| [s[0] + x[0], s[1] + x[1]]);
                crate::dynamics::WallBlock {
                    block: b as u32,
                    excavation: j,
                    nodes,
                    normal: [n[0] / length, n[1] / length],
                    centroid: [sum[0] / count, sum[1] / count],
                }
            })
        })
        .collect()
}

/// The force each fixity of `nodes` exerts on the model as it is: the negative of the node's
/// out-of-balance force, measured by the cycle's force stages with a zero step, N/m. Taken before
/// a stage whose boundary turns quiet changes anything (the static boundary's reactions, which
/// UDEC and FLAC apply to a viscous boundary so that a model in equilibrium stays at rest).
fn held_reactions(model: &mut Model, nodes: &[u32]) -> Vec<[f64; 2]> {
    let params = CycleParams {
        dt: 0.0,
        damping: 0.0,
        scheme: ZoneScheme::of(model, false),
        mass_damping: 0.0,
        stiffness_damping: 0.0,
        trial: false,
    };
    let mut cycle = Cycle::new(model);
    cycle.prime(model, &params);
    (nodes.iter())
        .map(|&n| {
            let f = cycle.node_force(model, n as usize);
            [-f[0], -f[1]]
        })
        .collect()
}

/// Add `reactions` (N/m, from [`held_reactions`]) to the loads of `nodes` in each component
/// `before` fixed (their fixity flags then) and that is now free: a quiet boundary holds, as
/// constant forces, what the fixities it replaces held.
fn hold_reactions(model: &mut Model, nodes: &[u32], before: &[u8], reactions: &[[f64; 2]]) {
    for ((&n, &was), r) in nodes.iter().zip(before).zip(reactions) {
        let n = n as usize;
        for (d, flag) in [(0, FIX_X), (1, FIX_Y)] {
            if was & flag != 0 && model.nodes.fixed[n] & flag == 0 {
                model.nodes.applied[n][d] += r[d];
            }
        }
    }
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

/// Remove the rock filling excavation `j` (`fill`: the staged excavation whose rock each block
/// is): its blocks are marked removed (detection skips them), their zones take the null law (a
/// staged scene's catalogue has one), their nodes and bodies are held still and unloaded, and the
/// contacts they made are dropped, so the walls lose the traction the rock gave them.
pub fn remove_fill(model: &mut Model, fill: &[u32], j: u32) {
    let Some(null) = model.materials.null else {
        return;
    };
    let n_blocks = model.blocks.len();
    model.blocks.removed.resize(n_blocks, false);
    for b in 0..n_blocks {
        if fill.get(b).copied().unwrap_or(NOT_FILL) != j {
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

/// Let the far field, if any, carry the near field's net external load (its nodes' loads, its
/// rigid and simple blocks' weights and the far field's in-situ loads F⁰; `FarField::carry`):
/// nonzero once an excavation under gravity has taken its weight away. The line force acts at
/// the area centroid of the excavated zones and bodies (of all of them before any), moved to the
/// nearest zone's or body's centroid so that it lies inside the interface; a net load below 1e-9
/// of the loads' magnitudes is rounding and carried as none.
fn carry_net_load(model: &mut Model) {
    let Some(far) = &model.far_field else {
        return;
    };
    let loads = (model.nodes.applied.iter())
        .chain(&model.bodies.weight)
        .chain(&far.in_situ);
    let (mut net, mut magnitude) = ([0.0; 2], 0.0);
    for f in loads {
        net = [net[0] + f[0], net[1] + f[1]];
        magnitude += f[0].hypot(f[1]);
    }
    if net[0].hypot(net[1]) <= 1e-9 * magnitude {
        net = [0.0; 2];
    }
    // The zones' and the bodies' centroids (m), areas (m²) and whether they were excavated.
    let (zones, bodies, pos) = (&model.zones, &model.bodies, &model.nodes.pos);
    let null = model.materials.null;
    let parts = (0..zones.len())
        .map(|z| {
            let centre = zones.centroid(z, pos);
            (centre, zones.area[z], Some(zones.material[z]) == null)
        })
        .chain((0..bodies.len()).map(|k| {
            let removed = model.blocks.is_removed(bodies.block[k] as usize);
            (bodies.centroid[k], bodies.area[k], removed)
        }));
    let parts: Vec<([f64; 2], f64, bool)> = parts.collect();
    let any_excavated = parts.iter().any(|p| p.2);
    let chosen = parts.iter().filter(|p| p.2 || !any_excavated);
    let (moment, area) = chosen.fold(([0.0; 2], 0.0), |(m, a), (c, w, _)| {
        ([m[0] + w * c[0], m[1] + w * c[1]], a + w)
    });
    let mean = [moment[0] / area, moment[1] / area];
    let gap = |p: &[f64; 2]| (p[0] - mean[0]).hypot(p[1] - mean[1]);
    let Some(&(at, _, _)) = parts.iter().min_by(|a, b| gap(&a.0).total_cmp(&gap(&b.0))) else {
        return;
    };
    if let Some(far) = &mut model.far_field {
        far.carry(net, at);
    }
}
