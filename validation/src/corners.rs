//! Corner to corner (issue 5, case 6): four blocks of a 2 m square cut by two persistent joints
//! that cross at its centre, so four corners meet exactly at one point — two diagonal blocks rigid,
//! the other two deformable (or all four of one mode) — under a uniform biaxial compression
//! σxx = σyy = −1 MPa (rollers on the left and bottom, pressure on the right and top). With all
//! four blocks of one mode the exact answer is the uniform stress: every joint carries 1 MPa and
//! nothing slips. Errors: `stress`, the largest deviation of a deformable zone's σxx, σyy (and
//! |σxy|) from it; `stress_mean`, that of a deformable block's mean stress; `joint_stress`, the
//! largest deviation of a contact's normal stress (corner contacts aside); `overlap`, the deepest
//! overlap relative to the contact tolerance.
//!
//! Finding: where the zoning of the two sides of a joint does not match (nodes of one side facing
//! the middle of the other's edges), node-to-edge contacts do not pass the contact patch test:
//! contact normal stresses vary by ±35 % along the joint and the zones beside it by ±30 %, though
//! each block's mean stress is right to 0.3 %. A segment-to-segment (mortar) contact would fix it. With rigid
//! and deformable blocks mixed the stress is not uniform (rigid blocks do not strain, so the joints
//! between them shear): only the overlap and the convergence are checked.

use std::time::Instant;

use adit::Scene;
use adit::setup::setup;

use crate::report::{CaseReport, StepInfo};

fn scene(modes: [&str; 2]) -> anyhow::Result<Scene> {
    let text = serde_json::json!({
        "name": "corners",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [2, 0], [2, 2], [0, 2]],
                    "edge_names": ["bottom", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.2, "edge_far": 0.2 },
        "joint_materials": { "joint": { "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": 30 } },
        "joints": [{ "from": [1, 0], "to": [1, 2], "material": "joint" },
                   { "from": [0, 1], "to": [2, 1], "material": "joint" }],
        "blocks": { "mode": modes[1], "regions": [{ "mode": modes[0], "at": [0.5, 0.5] },
                                                  { "mode": modes[0], "at": [1.5, 1.5] }] },
        "boundary": [{ "part": "bottom", "fix": "y" }, { "part": "left", "fix": "x" },
                     { "part": "right", "normal_stress": -1e6 }, { "part": "top", "normal_stress": -1e6 }],
        "solve": { "ratio": 1e-7, "max_cycles": 200000 }
    });
    Ok(Scene::from_json(&text.to_string(), "corners")?)
}

/// Solve with the diagonal blocks in `modes[0]` and the others in `modes[1]`.
pub fn run(modes: [&str; 2]) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let sc = scene(modes)?;
    let mut b = setup(&sc)?;
    let (solver, cycles) = crate::settle(&mut b.model, &sc.solve, "corner-to-corner blocks")?;
    let m = &b.model;
    let p = 1e6;
    let stress = crate::uniform_stress_error(&m.zones.stress, [-p, -p, 0.0], p);
    // Each deformable block's area-weighted mean stress against the uniform one.
    let z = &m.zones;
    let stress_mean = (0..m.blocks.len())
        .filter_map(|blk| {
            let (mut a, mut sx, mut sy) = (0.0, 0.0, 0.0);
            for i in (0..z.len()).filter(|&i| z.block[i] as usize == blk) {
                a += z.area[i];
                sx += z.area[i] * z.stress[i][0];
                sy += z.area[i] * z.stress[i][1];
            }
            (a > 0.0).then(|| ((sx / a + p).abs()).max((sy / a + p).abs()) / p)
        })
        .fold(0.0, f64::max)
        .max(
            // Simple blocks carry one uniform stress each.
            (0..m.bodies.len())
                .filter(|&k| m.bodies.mode[k] == adit::model::bodies::BodyMode::Simple)
                .map(|k| {
                    let s = m.bodies.stress[k];
                    ((s[0] + p).abs()).max((s[1] + p).abs()) / p
                })
                .fold(0.0, f64::max),
        );
    let c = &m.contacts;
    let joint = c
        .state
        .iter()
        .zip(&c.corner)
        .filter(|(_, corner)| !**corner)
        .map(|(s, _)| (s.normal + p).abs() / p)
        .fold(0.0, f64::max);
    let overlap = c
        .state
        .iter()
        .map(|s| (-s.normal_displacement).max(0.0))
        .fold(0.0, f64::max)
        / m.contact_tolerance;
    Ok(CaseReport::new(
        format!(
            "four blocks meeting corner to corner under 1 MPa biaxial: {} diagonal, {} others",
            modes[0], modes[1]
        ),
        m.zones.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        None,
        &[
            ("stress", stress),
            ("stress_mean", stress_mean),
            ("joint_stress", joint),
            ("overlap", overlap),
        ],
    )
    .with_step(StepInfo::of(&solver)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_meeting_at_a_point_neither_jam_nor_overlap() {
        for modes in [
            ["deformable", "deformable"],
            ["rigid", "rigid"],
            ["simple", "simple"],
        ] {
            let r = run(modes).unwrap();
            assert!(r.errors["stress_mean"] < 0.01, "{r:?}");
            assert!(r.errors["overlap"] < 1.0, "{r:?}");
        }
        // Rigid blocks do not strain: the stress is not uniform, overlap only.
        let r = run(["rigid", "deformable"]).unwrap();
        assert!(r.errors["overlap"] < 1.0, "{r:?}");
    }
}
