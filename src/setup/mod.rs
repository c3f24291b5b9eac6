//! From a validated scene to a model: cut the region into blocks, zone each block, initialise the
//! in-situ stress in zones and joints, apply fixities, boundary tractions and gravity, and detect
//! the contacts along the joints. `setup_meshed` is the recipe; the material catalogues are in
//! `catalogue.rs`, what is worth a warning in `warnings.rs`.

mod bodies;
pub use bodies::add_body_weight;
mod boundary;
mod catalogue;
mod far_field;
mod geometry;
mod plan;
mod plastic_depth;
mod repair;
mod stage_regions;
mod supports;
#[cfg(test)]
mod tests;
mod warnings;

use std::collections::BTreeMap;

use adit_meshing::{BoundaryEdge, EdgeKind, MeshStats};

use boundary::part_nodes;
pub use boundary::{BoundaryEffect, add_tractions, boundary_effect, edge_in_part};
pub use geometry::{Meshed, NOT_FILL, domain, joint_segments, mesh, sharper_than, zoning};
pub use plan::{Boundary, InSituField, Plan, StagePlan};

use catalogue::{JointCatalogue, ZoneCatalogue};
pub use catalogue::{joint_law, matrix_law, zone_law};
pub use plastic_depth::{DEPTH_MARGIN, plastic_depth, plastic_radius};
use warnings::warnings;

use crate::contact::detect::{Detection, Touch, detect};
use crate::joint::{FAILED, JointState};
use crate::law::ZoneLaw;
use crate::model::Contacts;
use crate::model::blocks::{Blocks, NO_BLOCK, NO_EDGE};
use crate::model::{BODY, Gather, MaterialId, Materials, Model, Nodes, Zones, traction};
use crate::scene::{BlockMode, BoundaryCondition, InSitu, Scene};
use crate::support::{SupportId, Supports};

/// A model ready to cycle, the plan of its stages, and what was learnt while building it.
pub struct Setup {
    pub model: Model,
    pub plan: Plan,
    pub mesh: MeshStats,
    /// Things worth a warning: sliver blocks, joints merged into walls.
    pub warnings: Vec<String>,
}

/// The wall edges of excavation `j` on the rock that stays: not the edges of its own fill (`fill`:
/// the staged excavation whose rock each block is, or `NOT_FILL`), nor of any removed block.
pub fn rock_walls<'a>(
    edges: &'a [BoundaryEdge],
    blocks: &'a Blocks,
    fill: &'a [u32],
    j: u32,
) -> impl Iterator<Item = &'a BoundaryEdge> {
    edges
        .iter()
        .filter(move |e| e.kind == EdgeKind::Excavation(j))
        .filter(move |e| {
            let b = blocks.block_of_node(e.nodes[0]);
            fill.get(b).copied().unwrap_or(NOT_FILL) != j && !blocks.is_removed(b)
        })
}

/// In-situ stress at elevation y, Pa: [σxx, σyy, σzz, σxy], σzz defaulting to ν(σxx + σyy).
pub fn in_situ_stress(s: &InSitu, y: f64, poisson: f64) -> [f64; 4] {
    let dy = y - s.y_ref;
    let sxx = s.sxx + s.gradient.sxx * dy;
    let syy = s.syy + s.gradient.syy * dy;
    let szz = match s.szz {
        Some(v) => v + s.gradient.szz * dy,
        None => poisson * (sxx + syy),
    };
    [sxx, syy, szz, s.sxy]
}

/// The block meshes joined into one numbering.
struct Assembled {
    pos: Vec<[f64; 2]>,
    /// Zones of the deformable blocks and the block of each.
    triangles: Vec<[u32; 3]>,
    zone_block: Vec<u32>,
    /// Outline triangles of the rigid and simple blocks and the block of each.
    outline: Vec<[u32; 3]>,
    outline_block: Vec<u32>,
    blocks: Blocks,
    boundary: Vec<BoundaryEdge>,
}

/// For each boundary edge of `blocks`, the block whose boundary has the same edge the other way,
/// its ends at the same positions `pos` to the bit (`adit_meshing::spacing::key`, as the zoning
/// placed them; `Blocks::edge_across`), or `NO_BLOCK`.
fn edges_across(blocks: &Blocks, pos: &[[f64; 2]]) -> Vec<u32> {
    let bits = |n: u32| adit_meshing::spacing::key(pos[n as usize]);
    let by_ends: std::collections::HashMap<_, u32> = (blocks.edges.iter().enumerate())
        .map(|(e, &[a, b])| ((bits(a), bits(b)), e as u32))
        .collect();
    (blocks.edges.iter())
        .map(|&[a, b]| match by_ends.get(&(bits(b), bits(a))) {
            Some(&twin) => blocks.block_of_node(blocks.edges[twin as usize][0]) as u32,
            None => NO_BLOCK,
        })
        .collect()
}

/// Concatenate the block meshes: global nodes, zones, and the block table.
fn assemble(meshed: &Meshed) -> Assembled {
    let (mut pos, mut tris, mut zone_block) = (Vec::new(), Vec::new(), Vec::new());
    let (mut outline, mut outline_block) = (Vec::new(), Vec::new());
    let mut blocks = Blocks {
        node_start: vec![0],
        zone_start: vec![0],
        edge_start: vec![0],
        ..Default::default()
    };
    let mut boundary = Vec::new();
    for (b, m) in meshed.meshes.iter().enumerate() {
        let offset = pos.len() as u32;
        pos.extend_from_slice(&m.points);
        let (t, owner) = if meshed.modes[b] == BlockMode::Deformable {
            (&mut tris, &mut zone_block)
        } else {
            (&mut outline, &mut outline_block)
        };
        t.extend(m.triangles.iter().map(|t| t.map(|n| n + offset)));
        owner.extend(std::iter::repeat_n(b as u32, m.triangles.len()));
        for e in &m.boundary {
            let nodes = e.nodes.map(|n| n + offset);
            blocks.edges.push(nodes);
            blocks.edge_kind.push(e.kind);
            boundary.push(BoundaryEdge {
                nodes,
                kind: e.kind,
            });
        }
        blocks.node_start.push(pos.len() as u32);
        blocks.zone_start.push(tris.len() as u32);
        blocks.edge_start.push(blocks.edges.len() as u32);
    }
    blocks.node_edges = vec![[NO_EDGE; 2]; pos.len()];
    for (e, &[a, b]) in blocks.edges.iter().enumerate() {
        blocks.node_edges[a as usize][1] = e as u32;
        blocks.node_edges[b as usize][0] = e as u32;
    }
    blocks.edge_across = edges_across(&blocks, &pos);
    Assembled {
        pos,
        triangles: tris,
        zone_block,
        outline,
        outline_block,
        blocks,
        boundary,
    }
}

/// Add the weight of the zones under gravity `g` (m/s²) to their corners' applied loads: ρ g A / 3
/// on each corner (lumped), N/m.
pub fn add_zone_weight(nodes: &mut Nodes, zones: &Zones, laws: &[Box<dyn ZoneLaw>], g: [f64; 2]) {
    if g == [0.0, 0.0] {
        return;
    }
    for z in 0..zones.len() {
        let w = laws[zones.material[z].0 as usize].density() * zones.area[z] / 3.0;
        for &n in &zones.nodes[z] {
            nodes.applied[n as usize][0] += w * g[0];
            nodes.applied[n as usize][1] += w * g[1];
        }
    }
}

/// The quiet boundary of the quiet parts of `conditions` (the scene's `path`), `None` when none
/// is: each edge of such a part with the impedances ρCp, ρCs of the zone beside it; an error
/// naming the condition when an edge has no zone beside it (a rigid or simple block's).
fn quiet(
    conditions: &[BoundaryCondition],
    path: &str,
    boundary: &Boundary,
    model: &Model,
) -> anyhow::Result<Option<crate::dynamics::QuietBoundary>> {
    let quiet: Vec<(usize, &BoundaryCondition)> = (conditions.iter().enumerate())
        .filter(|(_, c)| c.quiet)
        .collect();
    if quiet.is_empty() {
        return Ok(None);
    }
    let (zones, laws, pos) = (&model.zones, &model.materials.zone, &model.nodes.pos);
    let mut beside = std::collections::HashMap::with_capacity(3 * zones.nodes.len());
    for (z, tri) in zones.nodes.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            beside.insert((a.min(b), a.max(b)), z);
        }
    }
    let mut edges = Vec::new();
    for &(k, c) in &quiet {
        let name = c.part.as_deref().unwrap_or_default();
        let part = (boundary.edges.iter()).filter(|e| edge_in_part(&boundary.domain, e.kind, name));
        for e in part {
            let [a, b] = e.nodes;
            let [pa, pb] = e.nodes.map(|n| pos[n as usize]);
            let Some(&z) = beside.get(&(a.min(b), a.max(b))) else {
                anyhow::bail!(
                    "{path}[{k}].quiet: part '{name}' has an edge of a rigid or simple block \
                     (from ({:.3}, {:.3}) m); a quiet boundary takes its impedance from the \
                     zones of a deformable block",
                    pa[0],
                    pa[1]
                );
            };
            let law = &laws[zones.material[z].0 as usize];
            let ((bulk, shear), rho) = (law.moduli(), law.density());
            let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
            let length = dx.hypot(dy);
            if c.free_field && (dx.abs() > 1e-9 * length || length == 0.0) {
                anyhow::bail!(
                    "{path}[{k}].free_field: part '{name}' has an edge that is not vertical \
                     (from ({:.3}, {:.3}) to ({:.3}, {:.3}) m); a free-field column stands \
                     beside a vertical side",
                    pa[0],
                    pa[1],
                    pb[0],
                    pb[1]
                );
            }
            edges.push(crate::dynamics::QuietEdge {
                nodes: e.nodes,
                ends: [pa, pb],
                length,
                normal: [dy / length, -dx / length],
                impedance: [
                    ((bulk + 4.0 * shear / 3.0) * rho).sqrt(),
                    (shear * rho).sqrt(),
                ],
                density: rho,
                condition: k,
            });
        }
    }
    let incident: Vec<_> = (quiet.iter())
        .filter_map(|&(k, c)| c.incident.as_ref().map(|w| (k, w)))
        .collect();
    let free_field: Vec<usize> = (quiet.iter())
        .filter_map(|&(k, c)| c.free_field.then_some(k))
        .collect();
    Ok(Some(crate::dynamics::QuietBoundary::new(
        &edges,
        &incident,
        &free_field,
    )))
}

/// The dynamic inputs of `conditions` (the scene's `path`), `None` when none has any: each
/// prescribed motion with the nodes of its part, each load history with its consistent nodal
/// loads; an error naming the condition when a moving node is a rigid or simple block's (its
/// velocity is the block's).
fn inputs(
    conditions: &[BoundaryCondition],
    path: &str,
    boundary: &Boundary,
    in_situ: &InSituField,
    model: &Model,
) -> anyhow::Result<Option<crate::dynamics::Inputs>> {
    use crate::dynamics::{History, Motion, TimedLoad};
    let mut inputs = crate::dynamics::Inputs::default();
    for (k, c) in conditions.iter().enumerate() {
        let (Some(spec), Some(name)) = (&c.motion, &c.part) else {
            continue;
        };
        let nodes = boundary.part_nodes.get(name).cloned().unwrap_or_default();
        let body = |&n: &u32| {
            (model.bodies.of_node.get(n as usize))
                .is_some_and(|&b| b != crate::model::bodies::NO_BODY)
        };
        if let Some(&n) = nodes.iter().find(|n| body(n)) {
            let p = model.nodes.pos[n as usize];
            anyhow::bail!(
                "{path}[{k}].motion: part '{name}' has a node of a rigid or simple block (at \
                 ({:.3}, {:.3}) m), whose velocity is the block's; give that block `mode` \
                 \"deformable\"",
                p[0],
                p[1]
            );
        }
        inputs.motions.push(Motion::new(spec, nodes));
    }
    for (k, forces) in boundary::history_loads(conditions, boundary, in_situ, &model.nodes.pos) {
        let history = conditions[k].history.as_ref().expect("a load history");
        inputs
            .loads
            .push(TimedLoad::new(History::of(history), forces));
    }
    Ok((!inputs.is_empty()).then_some(inputs))
}

/// What `of` makes of the list of boundary conditions in force during each stage (the one stage
/// of a scene without stages): the last list given at or before it (`stages[i].boundary`, else
/// the top-level `boundary`), with its path in the scene.
fn per_stage<T: Clone>(
    scene: &Scene,
    of: impl Fn(&[BoundaryCondition], &str) -> anyhow::Result<T>,
) -> anyhow::Result<Vec<T>> {
    let mut now = of(&scene.boundary, "boundary")?;
    if scene.stages.is_empty() {
        return Ok(vec![now]);
    }
    let mut out = Vec::with_capacity(scene.stages.len());
    for (i, stage) in scene.stages.iter().enumerate() {
        if let Some(list) = &stage.boundary {
            now = of(list, &format!("stages[{i}].boundary"))?;
        }
        out.push(now.clone());
    }
    Ok(out)
}

/// Build the model of a validated scene.
pub fn setup(scene: &Scene) -> anyhow::Result<Setup> {
    setup_meshed(scene, mesh(scene)?)
}

/// [`setup`] from the blocks and zones `mesh` made of `scene`: join the block meshes, give the
/// zones their materials and in-situ stress, load and fix the boundary, make the rigid and simple
/// blocks, set up the joint laws and the contacts along the joints, then the supports.
pub fn setup_meshed(scene: &Scene, meshed: Meshed) -> anyhow::Result<Setup> {
    let stats = meshed.stats();
    let Assembled {
        pos,
        triangles,
        zone_block,
        outline,
        outline_block,
        mut blocks,
        boundary: edges,
    } = assemble(&meshed);
    let mut nodes = Nodes::at(pos);
    let mut zones = Zones::from_triangles(&triangles, &nodes.pos);
    zones.block = zone_block;

    let zone_laws = ZoneCatalogue::of(scene)?;
    let block_material = zone_laws.of_blocks(&meshed);
    let stage_regions = stage_regions::stage_materials(
        scene,
        &meshed.blocking.blocks,
        &block_material,
        &zone_laws,
    )?;
    let stress_at = |c: [f64; 2], m: MaterialId| {
        in_situ_stress(&scene.in_situ, c[1], zone_laws.poisson[m.0 as usize])
    };
    stress_zones(&mut zones, &nodes.pos, &block_material, stress_at);
    add_zone_weight(&mut nodes, &zones, &zone_laws.laws, scene.gravity);

    let in_situ = InSituField {
        in_situ: scene.in_situ.clone(),
        poisson: zone_laws.poisson[zone_laws.region.0 as usize],
    };
    let part_nodes = part_nodes(scene, &meshed.domain, &edges);
    let boundary = Boundary {
        edges,
        domain: meshed.domain.clone(),
        part_nodes,
    };
    let effect = |conditions: &[BoundaryCondition], path: &str| {
        boundary_effect(conditions, path, &boundary, &in_situ, &nodes.pos)
    };
    let initial = effect(&scene.boundary, "boundary")?;
    let mut stage_boundary = Vec::with_capacity(scene.stages.len());
    for (i, stage) in scene.stages.iter().enumerate() {
        let path = format!("stages[{i}].boundary");
        stage_boundary.push(
            stage
                .boundary
                .as_deref()
                .map(|list| effect(list, &path))
                .transpose()?,
        );
    }
    apply(&mut nodes, &initial);

    let mut bodies = bodies::bodies(
        &meshed.modes,
        &blocks,
        &mut nodes,
        &block_material,
        &zone_laws.laws,
        stress_at,
        scene.gravity,
    );
    if !bodies.is_empty() {
        blocks.round = bodies::round(scene, &bodies, &blocks, &nodes.pos, &meshed.modes);
    }
    bodies.outline = outline;
    refuse_body_fixity_changes(&nodes, &initial, &stage_boundary)?;
    let body_of_block: BTreeMap<u32, u32> = bodies
        .block
        .iter()
        .enumerate()
        .map(|(k, &b)| (b, k as u32))
        .collect();
    bodies.outline_body = outline_block.iter().map(|b| body_of_block[b]).collect();

    let joint_laws = JointCatalogue::of(scene, &meshed, &zone_laws)?;
    anyhow::ensure!(
        blocks.len() == 1 || !joint_laws.laws.is_empty(),
        "joint_materials: {} blocks need at least one joint material for their contacts",
        blocks.len()
    );
    let contact_tolerance = scene
        .contacts
        .tolerance
        .unwrap_or(0.05 * scene.zoning.edge_at_excavation);
    blocks.sharp_round = contact_tolerance;
    let contacts = if blocks.len() > 1 {
        let d = Detection {
            blocks: &blocks,
            x: &nodes.pos,
            tolerance: contact_tolerance,
            joint_material: &joint_laws.feature,
            hole_material: &joint_laws.hole,
        };
        detect(&d, &Contacts::default(), &|t: &Touch| {
            in_situ_joint(&in_situ, t)
        })
    } else {
        Contacts::none(nodes.len())
    };

    let mut warnings = warnings(scene, &meshed)?;
    let region_density = zone_laws.laws[zone_laws.region.0 as usize].density();
    warnings.extend(warnings::unbalanced_in_situ(scene, region_density));

    let size = boundary.domain.outer.size();
    let gather = Gather::new(nodes.len(), &zones.nodes);
    let mixed = scene
        .zoning
        .mixed
        .then(|| inverse_patch_areas(&zones, nodes.len()));
    let mut model = Model {
        nodes,
        zones,
        gather,
        size,
        blocks,
        bodies,
        contacts,
        contact_tolerance,
        supports: Default::default(),
        support_gather: Gather::default(),
        far_field: None,
        far_gather: Gather::default(),
        quiet: None,
        inputs: None,
        peaks: None,
        ejection: None,
        energy: None,
        mixed,
        materials: Materials {
            zone: zone_laws.laws,
            zone_names: zone_laws.names,
            null: zone_laws.null,
            joint: joint_laws.laws,
            joint_names: joint_laws.names,
            feature: joint_laws.feature,
            hole: joint_laws.hole,
        },
    };
    let fill = meshed.fill;
    model.supports = supports::supports(scene, &model, &fill, &boundary)?;
    model.support_gather = Gather::from_slots(model.nodes.len(), &model.supports.slot_nodes());
    model.far_field = far_field::far_field(scene, &model, &boundary, &in_situ)?;
    if let Some(w) = (model.far_field.as_ref()).and_then(|f| far_field::stretch_warning(f.stretch))
    {
        warnings.push(w);
    }
    model.far_gather = match &model.far_field {
        Some(f) => Gather::from_slots(model.nodes.len(), &f.nodes),
        None => Gather::from_slots(model.nodes.len(), &[]),
    };
    let stage_quiet = per_stage(scene, |l, p| quiet(l, p, &boundary, &model))?;
    let stage_inputs = per_stage(scene, |l, p| inputs(l, p, &boundary, &in_situ, &model))?;
    let (zones, laws) = (&model.zones, &model.materials.zone);
    warnings.extend(warnings::coarse_for_waves(
        scene,
        zones,
        laws,
        &model.nodes.pos,
    ));
    let m = &model.materials;
    let plan = Plan::of(
        scene,
        boundary,
        fill,
        in_situ,
        plan::Resolved {
            zone_id: &|n| {
                m.zone_id(n)
                    .ok_or_else(|| anyhow::anyhow!("no material '{n}'"))
            },
            joint_id: &|n| {
                m.joint_id(n)
                    .ok_or_else(|| anyhow::anyhow!("no joint material '{n}'"))
            },
            support_id: &|n| {
                model
                    .supports
                    .id(n)
                    .ok_or_else(|| anyhow::anyhow!("no bolt group or liner '{n}'"))
            },
            stage_regions,
            initial_boundary: initial,
            stage_boundary,
            stage_quiet,
            stage_inputs,
        },
    )?;
    install_from_start(&mut model.supports, &plan, &model.nodes.disp);
    Ok(Setup {
        model,
        plan,
        mesh: stats,
        warnings,
    })
}

/// Each zone takes its block's material and the in-situ stress at its centroid.
fn stress_zones(
    zones: &mut Zones,
    pos: &[[f64; 2]],
    block_material: &[MaterialId],
    stress_at: impl Fn([f64; 2], MaterialId) -> [f64; 4],
) {
    for z in 0..zones.len() {
        let m = block_material[zones.block[z] as usize];
        zones.material[z] = m;
        zones.stress[z] = stress_at(zones.centroid(z, pos), m);
    }
}

/// Add the boundary's fixities and loads `(fixed, applied)` to the nodes.
fn apply(nodes: &mut Nodes, (fixed, applied): &BoundaryEffect) {
    for n in 0..nodes.len() {
        nodes.fixed[n] |= fixed[n];
        nodes.applied[n] = [
            nodes.applied[n][0] + applied[n][0],
            nodes.applied[n][1] + applied[n][1],
        ];
    }
}

/// A stage's boundary conditions change node fixities and loads; the fixities of a rigid or simple
/// block's nodes are folded into its constraint once, when it is made, so a stage that changes one
/// is an error naming the stage. `initial`: the effect of the top-level `boundary`; `stages`: that
/// of each stage's `boundary`, if it has one.
fn refuse_body_fixity_changes(
    nodes: &Nodes,
    initial: &BoundaryEffect,
    stages: &[Option<BoundaryEffect>],
) -> anyhow::Result<()> {
    let mut before = &initial.0;
    for (i, stage) in stages.iter().enumerate() {
        let Some((after, _)) = stage else {
            continue;
        };
        let body_node =
            (0..nodes.len()).find(|&n| nodes.fixed[n] & BODY != 0 && before[n] != after[n]);
        if let Some(n) = body_node {
            let p = nodes.pos[n];
            anyhow::bail!(
                "stages[{i}].boundary: changes the fixity of a node of a rigid or simple block at \
                 ({:.3}, {:.3}) m, which is set once when the block is built; fix that block in the \
                 top-level `boundary`, or make it deformable",
                p[0],
                p[1]
            );
        }
        before = after;
    }
    Ok(())
}

/// The joint state a contact found at setup starts in. Joints present from the start are intact
/// and carry the in-situ traction (σzz from the region rock's Poisson's ratio); corner contacts
/// (blocks meeting at a point, not along a joint) start unstressed, without strength, at their gap
/// if apart (rounded corners of diagonal blocks at a joint crossing), else at zero overlap (the cut
/// geometry has none; a negative gap is an artefact of the corner).
fn in_situ_joint(in_situ: &InSituField, t: &Touch) -> JointState {
    if !t.face {
        return JointState {
            normal_displacement: t.gap.max(0.0),
            flags: FAILED,
            ..Default::default()
        };
    }
    let s = in_situ.at(t.point[1]);
    let n = t.normal;
    let tangent = [-n[1], n[0]];
    let t = traction(&s, n);
    let normal = t[0] * n[0] + t[1] * n[1];
    JointState {
        normal,
        shear: t[0] * tangent[0] + t[1] * tangent[1],
        initial_normal: normal,
        ..Default::default()
    }
}

/// The mixed discretization's 1 / (area of the zones around each node), 1/m² (0 at a node without
/// zones).
fn inverse_patch_areas(zones: &Zones, nodes: usize) -> Vec<f64> {
    let mut patch = vec![0.0; nodes];
    for (t, &a) in zones.nodes.iter().zip(&zones.area) {
        for &n in t {
            patch[n as usize] += a;
        }
    }
    patch
        .into_iter()
        .map(|a| if a > 0.0 { 1.0 / a } else { 0.0 })
        .collect()
}

/// Install the bolts and liners no stage installs: they are there from the start.
fn install_from_start(supports: &mut Supports, plan: &Plan, rock: &[[f64; 2]]) {
    let staged: Vec<SupportId> = plan
        .stages
        .iter()
        .flat_map(|s| &s.install)
        .copied()
        .collect();
    let all = (0..supports.cables.names.len() as u32)
        .map(SupportId::Bolts)
        .chain((0..supports.liners.names.len() as u32).map(SupportId::Liner));
    for id in all {
        if !staged.contains(&id) {
            supports.install(id, rock);
        }
    }
}
