//! The blocks each stage's `regions` give another zone material, resolved once on the block
//! geometry when the model is built.

use adit_meshing::Block;

use super::catalogue::ZoneCatalogue;
use super::geometry::selects;
use crate::model::MaterialId;
use crate::scene::Scene;

/// For each stage, the blocks its `regions` select and the material each takes (later regions of
/// a stage override earlier ones). A block's density cannot change (its masses and weight are set
/// when the model is built): an error naming the region's material otherwise.
pub(super) fn stage_materials(
    scene: &Scene,
    blocks: &[Block],
    initial: &[MaterialId],
    zones: &ZoneCatalogue,
) -> anyhow::Result<Vec<Vec<(u32, MaterialId)>>> {
    let names = &zones.names;
    let density = |m: MaterialId| zones.laws[m.0 as usize].density();
    let mut now = initial.to_vec();
    let mut out = Vec::with_capacity(scene.stages.len());
    for (i, stage) in scene.stages.iter().enumerate() {
        let mut changes: Vec<(u32, MaterialId)> = Vec::new();
        for (b, block) in blocks.iter().enumerate() {
            let Some((k, region)) = stage
                .regions
                .iter()
                .enumerate()
                .rev()
                .find(|(_, r)| selects(block, &r.polygon, r.at))
            else {
                continue;
            };
            let m = zones.id(
                &region.material,
                &format!("stages[{i}].regions[{k}].material"),
            )?;
            let before = now[b];
            if (density(m) - density(before)).abs() > 1e-9 * density(before) {
                anyhow::bail!(
                    "stages[{i}].regions[{k}].material: '{}' has density {} kg/m³ and the block it \
                     reaches (centroid ({:.3}, {:.3}) m) has {} kg/m³ ('{}'); a block's masses and \
                     weight are set when the model is built, so the density cannot change",
                    region.material,
                    density(m),
                    block.outer.centroid()[0],
                    block.outer.centroid()[1],
                    density(before),
                    names[before.0 as usize]
                );
            }
            now[b] = m;
            changes.push((b as u32, m));
        }
        out.push(changes);
    }
    Ok(out)
}
