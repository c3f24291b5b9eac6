//! Cost of contact detection against the number of blocks: square regions cut by two orthogonal
//! persistent joint sets into n × n square blocks, each block zoned into two triangles; the time of
//! one full detection (broad and narrow phase) is measured at 1k, 4k and 16k blocks.

use std::time::Instant;

use adit::Scene;
use adit::contact::detect::{Detection, detect};
use adit::joint::JointState;
use adit::setup::setup;
use serde::Serialize;

/// Detection cost at one size.
#[derive(Debug, Clone, Serialize)]
pub struct DetectionCost {
    pub blocks: usize,
    pub contacts: usize,
    /// Seconds of one detection (best of three).
    pub detect_s: f64,
    /// Nanoseconds per block.
    pub ns_per_block: f64,
    /// Seconds to cut, zone and build the model.
    pub build_s: f64,
}

fn grid_scene(n: usize) -> Scene {
    let spacing = 1.0;
    let size = n as f64 * spacing;
    let text = format!(
        r#"{{
        "name": "grid",
        "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
        "region": {{ "polygon": [[0, 0], [{size}, 0], [{size}, {size}], [0, {size}]], "material": "rock" }},
        "zoning": {{ "edge_at_excavation": {h}, "edge_far": {h}, "min_angle": 20 }},
        "joint_materials": {{ "j": {{ "normal_stiffness": 1e10, "shear_stiffness": 1e10 }} }},
        "joint_sets": [{{ "dip": 0, "spacing": {spacing}, "origin": [0.0, 0.0], "material": "j" }},
                       {{ "dip": 90, "spacing": {spacing}, "origin": [0.0, 0.0], "material": "j" }}]
    }}"#,
        h = 2.0 * spacing
    );
    Scene::from_json(&text, "grid scene").expect("valid grid scene")
}

/// Build an n × n block grid and time its detection.
pub fn measure(n: usize) -> anyhow::Result<DetectionCost> {
    let start = Instant::now();
    let b = setup(&grid_scene(n))?;
    let build_s = start.elapsed().as_secs_f64();
    let m = &b.model;
    let d = Detection {
        blocks: &m.blocks,
        x: &m.nodes.pos,
        tolerance: m.contact_tolerance,
        joint_material: &m.materials.feature,
        hole_material: &m.materials.hole,
    };
    let mut best = f64::INFINITY;
    let mut contacts = 0;
    for _ in 0..3 {
        let t = Instant::now();
        let c = detect(&d, &m.contacts, &|_| JointState::default());
        best = best.min(t.elapsed().as_secs_f64());
        contacts = c.len();
    }
    Ok(DetectionCost {
        blocks: m.blocks.len(),
        contacts,
        detect_s: best,
        ns_per_block: best / m.blocks.len() as f64 * 1e9,
        build_s,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_blocks_touch_their_four_neighbours() {
        let c = measure(8).unwrap();
        assert_eq!(c.blocks, 64);
        // Each shared face (2·8·7 of them) carries four contacts, two nodes on each side; at each
        // of the 7·7 interior corners the diagonal blocks touch corner to corner, both ways, twice.
        assert_eq!(c.contacts, 4 * 2 * 8 * 7 + 4 * 7 * 7);
    }
}
