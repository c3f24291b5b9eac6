//! Impact (issue 5, case 7): a block striking a fixed base through an elastic joint. Without
//! damping the contact is a spring: the block must leave with the speed it came in with (energy
//! conserved up to what the base keeps as vibration and the explicit scheme's error); with
//! damping it must come to rest on the base.
//!
//! A 1 m × 0.5 m block (rigid, or deformable) on a 2 m × 0.5 m deformable base fixed at its
//! bottom, joined by a joint with kn = ks = 1e10 Pa/m, no cohesion or tension, friction 30°.
//! The block starts moving down at 1 m/s (no gravity); the run follows it until it has left the
//! base and flown for 2 ms.

use std::time::Instant;

use adit::Scene;
use adit::setup::setup;
use adit::solve::{Quiet, Solver, Status};

use crate::report::{CaseReport, StepInfo};

fn scene(mode: &str, damping: f64) -> anyhow::Result<Scene> {
    let text = serde_json::json!({
        "name": "impact",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [2, 0], [2, 0.5], [1.5, 0.5], [1.5, 1.0], [0.5, 1.0], [0.5, 0.5], [0, 0.5]],
                    "edge_names": ["base", "e1", "e2", "e3", "e4", "e5", "e6", "e7"], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.125, "edge_far": 0.125 },
        "joint_materials": { "joint": { "normal_stiffness": 1e10, "shear_stiffness": 1e10, "friction": 30 } },
        "joints": [{ "from": [0.5, 0.5], "to": [1.5, 0.5], "material": "joint" }],
        "blocks": { "regions": [{ "mode": mode, "at": [1.0, 0.75] }] },
        "boundary": [{ "part": "base", "fix": "xy" }],
        "solve": { "mode": "dynamic", "damping": damping, "max_cycles": 1 }
    });
    Ok(Scene::from_json(&text.to_string(), "impact")?)
}

/// Kinetic energy (J/m) and mean vertical velocity (m/s) of the striking block's nodes (or its
/// body).
fn striker(model: &adit::model::Model, block: usize) -> (f64, f64) {
    if let Some(k) = model.bodies.block.iter().position(|&b| b as usize == block) {
        let (v, m) = (model.bodies.velocity[k], model.bodies.mass[k]);
        let ke = 0.5 * (m[0] * v[0] * v[0] + m[1] * v[1] * v[1] + m[2] * v[2] * v[2]);
        return (ke, v[1]);
    }
    let b = &model.blocks;
    let range = b.node_start[block] as usize..b.node_start[block + 1] as usize;
    let (mut ke, mut p, mut mass) = (0.0, 0.0, 0.0);
    for n in range {
        let (v, m) = (model.nodes.vel[n], model.nodes.mass[n]);
        ke += 0.5 * m * (v[0] * v[0] + v[1] * v[1]);
        p += m * v[1];
        mass += m;
    }
    (ke, p / mass)
}

/// Set the striking block (the one above y = 0.5 m) moving at `vy` m/s; returns its index.
fn launch(m: &mut adit::model::Model, vy: f64) -> anyhow::Result<usize> {
    let top = (0..m.nodes.len() as u32)
        .find(|&n| m.nodes.pos[n as usize][1] > 0.9)
        .ok_or_else(|| anyhow::anyhow!("no node on the striking block"))?;
    let block = m.blocks.block_of_node(top);
    if let Some(k) = m.bodies.block.iter().position(|&bb| bb as usize == block) {
        m.bodies.velocity[k][1] = vy;
    }
    let range = m.blocks.node_start[block] as usize..m.blocks.node_start[block + 1] as usize;
    for n in range {
        m.nodes.vel[n] = [0.0, vy];
    }
    Ok(block)
}

/// Strike the base at 1 m/s, undamped, with a `mode` block; `energy_loss`: 1 − the block's
/// kinetic energy after it has left the base over its energy before the impact.
pub fn run(mode: &str) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let sc = scene(mode, 0.0)?;
    let mut b = setup(&sc)?;
    let m = &mut b.model;
    let block = launch(m, -1.0)?;
    let mut solver = Solver::new(m, &sc.solve, 0);
    let (ke0, _) = striker(m, block);
    let dt = solver.params.dt;
    let (mut cycles, mut left_at) = (0u64, None);
    while cycles < 2_000_000 {
        let sol = solver.solve(m, &mut Quiet);
        anyhow::ensure!(!matches!(sol.status, Status::Failed(_)), "{:?}", sol.status);
        cycles += 1;
        let touching = m.contacts.state.iter().any(|s| s.normal < 0.0);
        let (_, vy) = striker(m, block);
        if left_at.is_none() && vy > 0.0 && !touching {
            left_at = Some(cycles);
        }
        if left_at.is_some_and(|c| (cycles - c) as f64 * dt > 2e-3) {
            break;
        }
    }
    anyhow::ensure!(left_at.is_some(), "the block never left the base");
    let (ke1, vy) = striker(m, block);
    Ok(CaseReport::new(
        format!("impact at 1 m/s on a fixed base, {mode} block, undamped: leaves at {vy:.4} m/s"),
        m.zones.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        None,
        &[("energy_loss", 1.0 - ke1 / ke0)],
    )
    .with_step(StepInfo::of(&solver)))
}

/// The same impact with gravity and local damping 0.8, solved statically: the block must come to
/// rest on the base. Returns the cycles to equilibrium.
pub fn settles(mode: &str) -> anyhow::Result<u64> {
    let mut sc = scene(mode, 0.8)?;
    sc.gravity = [0.0, -9.81];
    sc.solve.mode = adit::scene::SolveMode::Static;
    sc.solve.max_cycles = 100_000;
    sc.solve.ratio = 1e-6;
    let mut b = setup(&sc)?;
    launch(&mut b.model, -1e-4)?;
    let (_, cycles) = crate::settle(&mut b.model, &sc.solve, "damped impact")?;
    Ok(cycles)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_undamped_impact_gives_the_energy_back() {
        // What the block does not take back stays in the deformable base (and, for a deformable
        // block, in its own vibration): 1.6 % rigid, 2.7 % simple, 4.2 % deformable.
        for (mode, bound) in [("rigid", 0.03), ("simple", 0.05), ("deformable", 0.08)] {
            let r = run(mode).unwrap();
            let loss = r.errors["energy_loss"];
            assert!((0.0..bound).contains(&loss), "{r:?}");
        }
    }

    #[test]
    fn a_damped_impact_settles() {
        for mode in ["rigid", "simple", "deformable"] {
            settles(mode).unwrap();
        }
    }
}
