//! From a validated scene to a model: cut the region into blocks, zone each block, initialise the
//! in-situ stress in zones and joints, apply fixities, boundary tractions and gravity, and detect
//! the contacts along the joints.

mod bodies;
pub use bodies::add_body_weight;
mod boundary;
mod geometry;
mod repair;
mod stage_regions;
mod supports;
#[cfg(test)]
mod tests;

use std::collections::BTreeMap;

use adit_meshing::{BoundaryEdge, Domain, EdgeKind, MeshStats};

use boundary::part_nodes;
pub use boundary::{add_tractions, boundary_effect, edge_in_part};
pub use geometry::{Meshed, NOT_FILL, domain, joint_segments, mesh, zoning};

use crate::contact::detect::{Detection, NO_MATERIAL, Touch, detect};
use crate::joint::{
    ContinuouslyYielding, CoulombSlip, FAILED, Glued, JointLaw, JointState, tan_deg,
};
use crate::law::{Elastic, MohrCoulomb, Null, ZoneLaw};
use crate::model::Contacts;
use crate::model::blocks::{Blocks, NO_EDGE};
use crate::model::{BODY, Gather, MaterialId, Model, Nodes, Zones, traction};
use crate::scene::{
    BlockMode, BoundaryCondition, InSitu, JointLawKind, JointMaterial, Material, Scene, ZoneLawKind,
};

/// A model ready to cycle, with what was learnt while building it.
pub struct Setup {
    pub model: Model,
    pub mesh: MeshStats,
    /// Boundary nodes of each named part (`outer`, region edge names, excavation names), sorted.
    pub part_nodes: BTreeMap<String, Vec<u32>>,
    /// Boundary edges of all blocks (global node ids), material on the left, labelled by kind.
    pub boundary: Vec<BoundaryEdge>,
    /// The validated domain the blocks cover.
    pub domain: Domain,
    /// For each stage, the blocks its `regions` give another zone material, with that material.
    pub stage_materials: Vec<Vec<(u32, MaterialId)>>,
    /// Things worth a warning: sliver blocks, joints absorbed into blocks.
    pub warnings: Vec<String>,
}

/// Most thin blocks named one by one in the warnings; the rest are counted.
const THIN_NAMED: usize = 10;

/// A warning for each block too thin to zone at the finest size asked for (the first
/// `THIN_NAMED`, then a count), saying what became of it.
fn thin_warnings(scene: &Scene, meshed: &Meshed) -> Vec<String> {
    let made = match scene.blocks.thin {
        BlockMode::Deformable => {
            "zoned as finely as it needs (its zones may set the time step; blocks.thin: \
             \"simple\" or \"rigid\" takes it out of the zoning)"
        }
        BlockMode::Simple => "made simple (blocks.thin)",
        BlockMode::Rigid => "made rigid (blocks.thin)",
    };
    let mut out: Vec<String> = meshed
        .thin
        .iter()
        .take(THIN_NAMED)
        .map(|t| {
            let c = meshed.blocking.blocks[t.block].outer.centroid();
            format!(
                "block {} (centroid ({:.3}, {:.3}) m) is {:.3e} m thick (2 × area / perimeter), \
                 under half zoning.edge_at_excavation = {} m: {made}",
                t.block, c[0], c[1], t.thickness, scene.zoning.edge_at_excavation
            )
        })
        .collect();
    if meshed.thin.len() > THIN_NAMED {
        out.push(format!(
            "{} more blocks are as thin, and were treated alike",
            meshed.thin.len() - THIN_NAMED
        ));
    }
    out
}

/// The wall edges of excavation `j` on the rock that stays: not the edges of its own fill (the
/// rock that fills a staged excavation until a stage removes it), nor of any removed block.
pub fn rock_walls<'a>(
    boundary: &'a [BoundaryEdge],
    model: &'a Model,
    j: u32,
) -> impl Iterator<Item = &'a BoundaryEdge> {
    let blocks = &model.blocks;
    boundary
        .iter()
        .filter(move |e| e.kind == EdgeKind::Excavation(j))
        .filter(move |e| {
            let b = blocks.block_of_node(e.nodes[0]);
            model.fill.get(b).copied().unwrap_or(NOT_FILL) != j && !blocks.is_removed(b)
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

/// The zone law of a material (scene-validated).
pub fn zone_law(m: &Material) -> Box<dyn ZoneLaw> {
    let elastic = Elastic::from_young(m.young, m.poisson, m.density);
    match m.law {
        ZoneLawKind::Elastic => Box::new(elastic),
        ZoneLawKind::MohrCoulomb => {
            let c = m.cohesion.expect("validated");
            let phi = m.friction.expect("validated");
            let tension = m.tensile_strength.unwrap_or(f64::INFINITY);
            let mut law = MohrCoulomb::new(elastic, c, phi, m.dilation, tension);
            law.softening = m
                .softening
                .iter()
                .map(|p| (p.plastic_strain, p.cohesion, p.friction.to_radians()))
                .collect();
            Box::new(law)
        }
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

/// The joint law of a joint material (scene-validated).
pub fn joint_law(j: &JointMaterial) -> Box<dyn JointLaw> {
    let (normal_stiffness, shear_stiffness) = (j.normal_stiffness, j.shear_stiffness);
    match j.law {
        JointLawKind::Glued => Box::new(Glued {
            normal_stiffness,
            shear_stiffness,
        }),
        JointLawKind::Coulomb => Box::new(CoulombSlip {
            normal_stiffness,
            shear_stiffness,
            tan_friction: tan_deg(j.friction),
            cohesion: j.cohesion,
            tensile_strength: j.tensile_strength,
            tan_dilation: tan_deg(j.dilation),
        }),
        JointLawKind::ContinuouslyYielding => Box::new(ContinuouslyYielding {
            normal_stiffness,
            shear_stiffness,
            friction: j.friction.to_radians(),
            initial_friction: j.initial_friction.unwrap_or(j.friction).to_radians(),
            roughness: j.roughness.expect("validated"),
        }),
    }
}

/// Build the model of a validated scene.
pub fn setup(scene: &Scene) -> anyhow::Result<Setup> {
    setup_meshed(scene, mesh(scene)?)
}

/// The mesh's sharpest zone against `zoning.accept_angle`: an error naming the block and where.
fn refuse_sharp_zones(scene: &Scene, meshed: &Meshed) -> anyhow::Result<()> {
    let sharpest = meshed.sharpest_zone();
    let accept = scene.zoning.accept_angle;
    match sharpest {
        Some((angle, at, b)) if angle < accept => anyhow::bail!(
            "zoning.accept_angle: a zone of block {b} near ({:.3}, {:.3}) m has an angle of \
             {angle:.2}°, below the {accept}° accepted (joints or walls meet at such an angle, or \
             lie closer than the zoning there; it would set a tiny time step): move or coarsen \
             the joints, or lower `zoning.accept_angle` (0 accepts any)",
            at[0],
            at[1]
        ),
        _ => Ok(()),
    }
}

/// [`setup`] from the blocks and zones `mesh` made of `scene`.
pub fn setup_meshed(scene: &Scene, meshed: Meshed) -> anyhow::Result<Setup> {
    let stats = meshed.stats();
    let Assembled {
        pos,
        triangles: tris,
        zone_block,
        outline,
        outline_block,
        mut blocks,
        boundary,
    } = assemble(&meshed);
    let mut nodes = Nodes::at(pos);
    let mut zones = Zones::from_triangles(&tris, &nodes.pos);
    zones.block = zone_block;

    let mut material_names: Vec<String> = scene.materials.keys().cloned().collect();
    let mut laws: Vec<Box<dyn ZoneLaw>> = scene.materials.values().map(zone_law).collect();
    let region_mat = material_names
        .iter()
        .position(|n| *n == scene.region.material)
        .expect("validated");
    // Excavated zones take the null law (the last material).
    let null_material = (!scene.stages.is_empty()).then(|| {
        material_names.push("excavated".into());
        laws.push(Box::new(Null));
        MaterialId((laws.len() - 1) as u32)
    });
    // Each block's material: the region's, or its inclusion's.
    let material_id = |name: &str| {
        MaterialId(
            material_names
                .iter()
                .position(|n| n == name)
                .expect("validated") as u32,
        )
    };
    let block_material: Vec<MaterialId> = meshed
        .inclusion
        .iter()
        .map(|&i| match scene.inclusions.get(i as usize) {
            Some(inc) => material_id(&inc.material),
            None => MaterialId(region_mat as u32),
        })
        .collect();
    let stage_materials = stage_regions::stage_materials(
        scene,
        &meshed.blocking.blocks,
        &block_material,
        &material_id,
    )?;
    let poisson: Vec<f64> = scene.materials.values().map(|m| m.poisson).collect();
    let stress_at =
        |c: [f64; 2], m: MaterialId| in_situ_stress(&scene.in_situ, c[1], poisson[m.0 as usize]);
    for z in 0..zones.len() {
        let m = block_material[zones.block[z] as usize];
        zones.material[z] = m;
        zones.stress[z] = stress_at(zones.centroid(z, &nodes.pos), m);
    }

    // Gravity: body force ρ g A / 3 on each corner (lumped).
    add_zone_weight(&mut nodes, &zones, &laws, scene.gravity);

    let domain = &meshed.domain;
    let part_nodes = part_nodes(scene, domain, &boundary);
    let effect = |conditions: &[BoundaryCondition], pos: &[[f64; 2]]| {
        boundary_effect(conditions, scene, &boundary, domain, &part_nodes, pos)
    };
    let (fixed, applied) = effect(&scene.boundary, &nodes.pos);
    for n in 0..nodes.len() {
        nodes.fixed[n] |= fixed[n];
        nodes.applied[n] = [
            nodes.applied[n][0] + applied[n][0],
            nodes.applied[n][1] + applied[n][1],
        ];
    }

    let mut bodies = bodies::bodies(
        &meshed.modes,
        &blocks,
        &mut nodes,
        &block_material,
        &laws,
        stress_at,
        scene.gravity,
    );
    if !bodies.is_empty() {
        blocks.round = bodies::round(scene, &bodies, &blocks, &nodes.pos, &meshed.modes);
    }
    let body_of_block: BTreeMap<u32, u32> = bodies
        .block
        .iter()
        .enumerate()
        .map(|(k, &b)| (b, k as u32))
        .collect();
    bodies.outline = outline;
    // A stage's boundary conditions change node fixities and loads; the fixities of a rigid or
    // simple block's nodes are folded into its constraint here, once, so they cannot change.
    let mut before = fixed;
    for (i, stage) in scene.stages.iter().enumerate() {
        let Some(list) = &stage.boundary else {
            continue;
        };
        let (after, _) = effect(list, &nodes.pos);
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
    bodies.outline_body = outline_block.iter().map(|b| body_of_block[b]).collect();

    // Joint laws, and the material of each joint feature (sets first, then explicit joints).
    let mut joint_material_names: Vec<String> = scene.joint_materials.keys().cloned().collect();
    let mut joint_laws: Vec<Box<dyn JointLaw>> =
        scene.joint_materials.values().map(joint_law).collect();
    let material_index = |name: &str| {
        joint_material_names
            .iter()
            .position(|n| n == name)
            .expect("validated") as u32
    };
    let joint_material: Vec<u32> = scene
        .joint_sets
        .iter()
        .map(|s| material_index(&s.material))
        .chain(scene.joints.iter().map(|j| material_index(&j.material)))
        .chain(scene.voronoi.iter().map(|v| material_index(&v.material)))
        .collect();
    let contact_tolerance = scene
        .contacts
        .tolerance
        .unwrap_or(0.05 * scene.zoning.edge_at_excavation);
    // The rock filling a staged excavation is glued to its surroundings until it is removed, with
    // the stiffness of the stiffest joint material, or of the rock over a wall zone (E/h) if there
    // is none (so that filling adds nothing stiffer than the model already has).
    let fill_material = meshed.fill.iter().any(|&f| f != NOT_FILL).then(|| {
        let (kn, ks) = joint_laws
            .iter()
            .map(|l| l.stiffness())
            .fold(None, |m: Option<(f64, f64)>, k| {
                Some(m.map_or(k, |m| (m.0.max(k.0), m.1.max(k.1))))
            })
            .unwrap_or_else(|| {
                let e = scene.materials[&scene.region.material].young;
                let k = e / scene.zoning.edge_at_excavation;
                (k, 0.5 * k)
            });
        joint_material_names.push("excavation fill".into());
        joint_laws.push(Box::new(Glued {
            normal_stiffness: kn,
            shear_stiffness: ks,
        }));
        (joint_laws.len() - 1) as u32
    });
    // Inclusions are bonded to the rock around: glued, kn = (largest E of the rock and the
    // inclusions) / h at the excavation, so the interface is stiffer than a zone of either side.
    let inclusion_material = (!scene.inclusions.is_empty()).then(|| {
        let e = scene
            .inclusions
            .iter()
            .map(|i| &i.material)
            .chain([&scene.region.material])
            .map(|m| scene.materials[m].young)
            .fold(0.0, f64::max);
        let k = e / scene.zoning.edge_at_excavation;
        joint_material_names.push("inclusion interface".into());
        joint_laws.push(Box::new(Glued {
            normal_stiffness: k,
            shear_stiffness: 0.5 * k,
        }));
        (joint_laws.len() - 1) as u32
    });
    // The joint material of each hole's wall: a staged excavation's fill, an inclusion's
    // interface, none for a hole from the start.
    let hole_material: Vec<u32> = (0..meshed.domain.holes.len())
        .map(|j| match scene.excavations.get(j) {
            Some(e) if scene.is_staged(&e.name) => fill_material,
            Some(_) => None,
            None => inclusion_material,
        })
        .map(|m| m.unwrap_or(NO_MATERIAL))
        .collect();
    anyhow::ensure!(
        blocks.len() == 1 || !joint_laws.is_empty(),
        "joint_materials: {} blocks need at least one joint material for their contacts",
        blocks.len()
    );

    // Joints present from the start are intact and carry the in-situ traction; corner contacts
    // (blocks meeting at a point, not along a joint) start unstressed, without strength, at their
    // gap if apart (rounded corners of diagonal blocks at a joint crossing), else at zero overlap
    // (the cut geometry has none; a negative gap is an artefact of the corner).
    let in_situ_joint = |t: &Touch| {
        if !t.face {
            return JointState {
                normal_displacement: t.gap.max(0.0),
                flags: FAILED,
                ..Default::default()
            };
        }
        let s = in_situ_stress(&scene.in_situ, t.point[1], poisson[region_mat]);
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
    };
    let contacts = if blocks.len() > 1 {
        let d = Detection {
            blocks: &blocks,
            x: &nodes.pos,
            tolerance: contact_tolerance,
            joint_material: &joint_material,
            hole_material: &hole_material,
        };
        detect(&d, &Contacts::default(), &in_situ_joint)
    } else {
        Contacts::none(nodes.len())
    };

    let mut warnings = Vec::new();
    let mut is_thin = vec![false; meshed.blocking.blocks.len()];
    for t in &meshed.thin {
        is_thin[t.block] = true;
    }
    for &b in meshed.blocking.slivers.iter().filter(|&&b| !is_thin[b]) {
        let blk = &meshed.blocking.blocks[b];
        warnings.push(format!(
            "block {b} is a sliver (area {:.3e} m²); consider coarser joints or zoning",
            blk.area()
        ));
    }
    warnings.extend(thin_warnings(scene, &meshed));
    refuse_sharp_zones(scene, &meshed)?;
    warnings.extend(meshed.repairs.iter().cloned());
    for (b, mesh) in meshed.meshes.iter().enumerate() {
        if meshed.modes[b] == BlockMode::Deformable && mesh.angle_limit_deg < scene.zoning.min_angle
        {
            let c = meshed.blocking.blocks[b].outer.centroid();
            warnings.push(format!(
                "block {b} (centroid ({:.3}, {:.3}) m): refinement to zoning.min_angle = {}° did not \
                 end (its constraints meet at small angles); zoned aiming at {}°",
                c[0], c[1], scene.zoning.min_angle, mesh.angle_limit_deg
            ));
        }
    }
    let merges = meshed.blocking.merges;
    if merges.count > 0 {
        warnings.push(format!(
            "cutting moved {} vertices onto others within zoning.merge_tolerance = {:.4} m (joint \
             ends onto joints or walls, crossings onto corners); the largest move, {:.4} m, onto \
             ({:.3}, {:.3}) m",
            merges.count, meshed.merge_tolerance, merges.largest, merges.at[0], merges.at[1]
        ));
    }
    if meshed.blocking.absorbed_joint_length > 0.0 {
        warnings.push(format!(
            "{:.3} m of joint traces end inside blocks and were absorbed into them",
            meshed.blocking.absorbed_joint_length
        ));
    }

    let size = domain.outer.size();
    let gather = Gather::new(nodes.len(), &zones.nodes);
    let mut model = Model {
        nodes,
        zones,
        gather,
        laws,
        material_names,
        size,
        blocks,
        bodies,
        contacts,
        joint_laws,
        joint_material_names,
        joint_material,
        contact_tolerance,
        hole_material,
        fill: meshed.fill.clone(),
        null_material,
        supports: Default::default(),
        support_gather: Gather::default(),
        mixed: None,
    };
    if scene.zoning.mixed {
        let mut patch = vec![0.0; model.nodes.len()];
        for (t, &a) in model.zones.nodes.iter().zip(&model.zones.area) {
            for &n in t {
                patch[n as usize] += a;
            }
        }
        model.mixed = Some(
            patch
                .into_iter()
                .map(|a| if a > 0.0 { 1.0 / a } else { 0.0 })
                .collect(),
        );
    }
    model.supports = supports::supports(scene, &model, &meshed.domain, &boundary)?;
    model.support_gather = Gather::from_slots(model.nodes.len(), &model.supports.slot_nodes());
    // Supports no stage installs are there from the start.
    let staged: Vec<&String> = scene.stages.iter().flat_map(|s| &s.install).collect();
    let from_start = scene.bolts.iter().map(|b| &b.name);
    for name in from_start.chain(scene.liners.iter().map(|l| &l.name)) {
        if !staged.contains(&name) {
            model.supports.install(name, &model.nodes.disp);
        }
    }
    Ok(Setup {
        model,
        mesh: stats,
        part_nodes,
        boundary,
        domain: meshed.domain,
        stage_materials,
        warnings,
    })
}
