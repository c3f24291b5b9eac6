//! A block dropped edge-first onto a corner (issue 5, case 6): a 1 m × 0.5 m block whose flat
//! bottom strikes the right-angled corner of a step (the upper level 2 m × 1 m, a lower level
//! 0.5 m high running on to x = 6 m, fixed at the bottom) at 2 m/s under gravity, without damping,
//! its centre 0.1 m beyond the corner, so that it bounces, pivots over the corner and falls onto the
//! lower level. Joint kn = ks = 1e11 Pa/m, friction 30°, zones of 0.1 m (0.2 m in `cargo test`).
//!
//! Nothing here has a closed form; what must hold is what goes wrong in codes that jam on corners:
//! the block's mechanical energy (kinetic + potential, relative to the start) never grows beyond
//! what it started with (`energy_gain`, over its initial kinetic energy: a jammed or exploding
//! contact creates energy), no contact overlaps by more than its tolerance (`overlap`, the deepest
//! over the run relative to the tolerance), and the block ends beyond the corner, having fallen
//! off onto the lower level (where, undamped, it keeps bouncing).

use std::time::Instant;

use adit::Scene;
use adit::model::Model;
use adit::setup::setup;
use adit::solve::{Quiet, Solver, Status};

use crate::report::{CaseReport, StepInfo};

const GRAVITY: f64 = 9.81;
/// Speed at first contact, m/s (a drop from v²/2g ≈ 0.2 m).
const SPEED: f64 = 2.0;

fn scene(block: &str, base: &str, edge: f64) -> anyhow::Result<Scene> {
    let text = serde_json::json!({
        "name": "drop",
        "materials": { "rock": { "density": 2500, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [6, 0], [6, 0.5], [2, 0.5], [2, 1], [2.6, 1], [2.6, 1.5], [1.6, 1.5],
                                [1.6, 1], [0, 1]],
                    "edge_names": ["bottom", "e1", "e2", "e3", "e4", "e5", "e6", "e7", "e8", "e9"],
                    "material": "rock" },
        "zoning": { "edge_at_excavation": edge, "edge_far": edge },
        "joint_materials": { "joint": { "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": 30 } },
        "joints": [{ "from": [1.6, 1], "to": [2, 1], "material": "joint" }],
        "blocks": { "mode": base, "regions": [{ "mode": block, "at": [2.1, 1.25] }] },
        "gravity": [0, -GRAVITY],
        "boundary": [{ "part": "bottom", "fix": "xy" }],
        "solve": { "mode": "dynamic", "damping": 0.0, "max_cycles": 200 }
    });
    Ok(Scene::from_json(&text.to_string(), "drop")?)
}

/// Kinetic energy (J/m), mass (kg/m) and centre of mass (m) of block `b`.
fn state(m: &Model, b: usize) -> (f64, f64, [f64; 2]) {
    if let Some(k) = m.bodies.block.iter().position(|&x| x as usize == b) {
        let (v, mass) = (m.bodies.velocity[k], m.bodies.mass[k]);
        let ke: f64 = (0..m.bodies.mode[k].dofs())
            .map(|d| 0.5 * mass[d] * v[d] * v[d])
            .sum();
        return (ke, mass[0], m.bodies.centroid[k]);
    }
    let range = m.blocks.node_start[b] as usize..m.blocks.node_start[b + 1] as usize;
    let (mut ke, mut mass, mut moment) = (0.0, 0.0, [0.0; 2]);
    for n in range {
        let (v, w) = (m.nodes.vel[n], m.nodes.mass[n]);
        ke += 0.5 * w * (v[0] * v[0] + v[1] * v[1]);
        mass += w;
        let x = [
            m.nodes.pos[n][0] + m.nodes.disp[n][0],
            m.nodes.pos[n][1] + m.nodes.disp[n][1],
        ];
        moment = [moment[0] + w * x[0], moment[1] + w * x[1]];
    }
    (ke, mass, moment.map(|v| v / mass))
}

/// Drop a `block` block onto the corner of a `base` base (zones of `edge` m) and follow it for a
/// second.
pub fn run(block: &str, base: &str, edge: f64) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let sc = scene(block, base, edge)?;
    let mut b = setup(&sc)?;
    let m = &mut b.model;
    let top = (0..m.nodes.len())
        .find(|&n| m.nodes.pos[n][1] > 1.4 && m.nodes.pos[n][0] > 2.0)
        .ok_or_else(|| anyhow::anyhow!("no node on the falling block"))?;
    let falling = m.blocks.block_of_node(top as u32);
    if let Some(k) = m.bodies.block.iter().position(|&x| x as usize == falling) {
        m.bodies.velocity[k][1] = -SPEED;
    }
    for n in m.blocks.node_start[falling] as usize..m.blocks.node_start[falling + 1] as usize {
        m.nodes.vel[n] = [0.0, -SPEED];
    }
    let mut solver = Solver::new(m, &sc.solve, 0);
    solver.spec.ratio = 0.0;
    let (ke0, mass, c0) = state(m, falling);
    let energy = |m: &Model| {
        let (ke, _, c) = state(m, falling);
        ke + mass * GRAVITY * (c[1] - c0[1])
    };
    let (mut cycles, mut gain, mut overlap) = (0u64, 0.0f64, 0.0f64);
    let duration = 1.0;
    while cycles as f64 * solver.params.dt < duration {
        let sol = solver.solve(m, &mut Quiet);
        if let Status::Failed(reason) = &sol.status {
            anyhow::bail!("drop ({block} block on {base} base) failed: {reason}");
        }
        cycles += sol.cycles;
        gain = gain.max(energy(m) - ke0);
        let deepest = m
            .contacts
            .state
            .iter()
            .map(|s| -s.normal_displacement)
            .fold(0.0, f64::max);
        overlap = overlap.max(deepest / m.contact_tolerance);
    }
    let (_, _, [x_end, y_end]) = state(m, falling);
    let lowest = (m.blocks.node_start[falling] as usize..m.blocks.node_start[falling + 1] as usize)
        .map(|n| m.nodes.pos[n][1] + m.nodes.disp[n][1])
        .fold(f64::INFINITY, f64::min);
    anyhow::ensure!(
        lowest < 0.9,
        "the {block} block stayed on the corner (centre at ({x_end:.3}, {y_end:.3}) m)"
    );
    Ok(CaseReport::new(
        format!(
            "{block} block dropped edge-first at {SPEED} m/s onto the corner of a {base} base, \
             undamped, zones of {edge} m: off the corner, centre at ({x_end:.2}, {y_end:.2}) m after {duration} s"
        ),
        m.zones.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        None,
        &[("energy_gain", gain.max(0.0) / ke0), ("overlap", overlap)],
    )
    .with_step(StepInfo::of(&solver)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_block_dropped_onto_a_corner_tips_off_without_gaining_energy() {
        for (block, base) in [("rigid", "deformable"), ("deformable", "deformable")] {
            let r = run(block, base, 0.2).unwrap();
            eprintln!("{r:?}");
            assert!(r.errors["energy_gain"] < 0.02, "{r:?}");
            assert!(r.errors["overlap"] < 1.0, "{r:?}");
        }
    }
}
