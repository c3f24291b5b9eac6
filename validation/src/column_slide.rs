//! A jointed column driven by a boundary load: a 1 m wide, 2 m high column on a fixed base, cut
//! through its middle by one joint at α, loaded by σ on its top and its own weight. Settled on a
//! joint that holds, then released undamped with friction φ < α: the upper block slides along the
//! joint as a rigid body, s(t) = ½ a t², a = (P + W)(sin α − cos α tan φ)/m (P = σ × 1 m the top
//! load, W = m g its weight, m its mass), without rotating (the reaction's resultant lies within the
//! joint).

use std::time::Instant;

use adit::Scene;
use adit::joint::{CoulombSlip, tan_deg};
use adit::scene::{BlockMode, Rayleigh, RayleighComponents, SolveMode};
use adit::setup::setup;
use adit::solve::{Quiet, Solver, Status};

use crate::incline::mode_name;
use crate::report::CaseReport;

const G: f64 = 9.81;
const DENSITY: f64 = 2500.0;
/// The top load, Pa (compression).
pub const LOAD: f64 = 1e6;
/// The joint's normal and shear stiffness, Pa/m.
const STIFFNESS: f64 = 1e10;

fn scene(alpha_deg: f64, h: f64, mode: BlockMode) -> Scene {
    let rise = 0.5 * alpha_deg.to_radians().tan();
    let text = format!(
        r#"{{
        "name": "sliding_column",
        "materials": {{ "rock": {{ "density": {DENSITY}, "young": 10e9, "poisson": 0.25 }} }},
        "region": {{ "polygon": [[0, 0], [1, 0], [1, 2], [0, 2]], "edge_names": ["base", "right", "top", "left"],
                    "material": "rock" }},
        "zoning": {{ "edge_at_excavation": {h}, "edge_far": {h} }},
        "joint_materials": {{ "plane": {{ "normal_stiffness": {STIFFNESS}, "shear_stiffness": {STIFFNESS}, "friction": 80 }} }},
        "joints": [{{ "from": [0, {y0}], "to": [1, {y1}], "material": "plane" }}],
        "gravity": [0, {g}],
        "blocks": {{ "mode": "{mode}" }},
        "boundary": [{{ "part": "base", "fix": "xy" }}, {{ "part": "top", "normal_stress": {load} }}],
        "solve": {{ "ratio": 1e-7, "max_cycles": 400000 }}
    }}"#,
        y0 = 1.0 - rise,
        y1 = 1.0 + rise,
        g = -G,
        load = -LOAD,
        mode = mode_name(mode),
    );
    Scene::from_json(&text, "sliding column scene").expect("valid sliding column scene")
}

/// How the upper block starts its slide.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// Settled statically under its loads on a joint that holds (φ = 80°), then released with φ.
    Settled,
    /// From rest on an unstressed joint of friction φ, the load and gravity applied at once.
    FromRest,
}

/// The stiffness-proportional Rayleigh damping of the damped runs: ξ = 5 % at the frequency of the
/// upper block bouncing on its joint, f = √(kn L / m) / 2π (L the joint's length, m the block's
/// mass per metre), which does not resist the block's rigid motion.
fn joint_damping(alpha_deg: f64) -> Rayleigh {
    let length = 1.0 / alpha_deg.to_radians().cos();
    let mass = DENSITY * UPPER_AREA;
    Rayleigh {
        fraction: 0.05,
        frequency: (STIFFNESS * length / mass).sqrt() / (2.0 * std::f64::consts::PI),
        components: RayleighComponents::Stiffness,
    }
}

/// The upper block's area, m² (the joint crosses the 1 m × 2 m column through its centre).
const UPPER_AREA: f64 = 1.0;

/// The closed form's acceleration down the joint, m/s².
pub fn acceleration(alpha_deg: f64, phi_deg: f64) -> f64 {
    let a = alpha_deg.to_radians();
    let mass = DENSITY * UPPER_AREA;
    (LOAD * 1.0 + mass * G) * (a.sin() - a.cos() * tan_deg(phi_deg)) / mass
}

/// Slide the upper block for `duration` s with friction `phi_deg` on a joint at `alpha_deg`,
/// started by `start`, undamped or with [`joint_damping`]. Errors: `slide`, the largest
/// |s_h(t) − s(t)| over 20 samples relative to s at the end (s_h the mean displacement of the
/// block's nodes along the joint); `final`, (s_h − s)/s at the end, signed; `rotation`, the top
/// edge's largest rotation (rad) times the half-width (0.5 m) over s at the end.
pub fn run(
    (alpha_deg, phi_deg): (f64, f64),
    start_by: Start,
    damped: bool,
    duration: f64,
    h: f64,
    mode: BlockMode,
) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let mut sc = scene(alpha_deg, h, mode);
    let mu = tan_deg(phi_deg);
    let joint = CoulombSlip {
        normal_stiffness: STIFFNESS,
        shear_stiffness: STIFFNESS,
        tan_friction: mu,
        cohesion: 0.0,
        residual_cohesion: 0.0,
        tensile_strength: 0.0,
        tan_dilation: 0.0,
    };
    let mut b = setup(&sc)?;
    anyhow::ensure!(b.model.blocks.len() == 2, "expected two blocks");
    let settled = match start_by {
        Start::Settled => crate::settle_by_method(&mut b.model, &sc.solve, "settling")?.0,
        Start::FromRest => 0,
    };
    b.model.materials.joint[0] = Box::new(joint);
    let corner = |m: &adit::model::Model, p: [f64; 2]| {
        (0..m.nodes.len())
            .find(|&n| m.nodes.pos[n] == p)
            .expect("a corner of the column")
    };
    let (left, right) = (corner(&b.model, [0.0, 2.0]), corner(&b.model, [1.0, 2.0]));
    let upper = b.model.blocks.block_of_node(left as u32);
    let nodes =
        b.model.blocks.node_start[upper] as usize..b.model.blocks.node_start[upper + 1] as usize;
    sc.solve.mode = SolveMode::Dynamic;
    sc.solve.damping = Some(0.0);
    sc.solve.rayleigh = damped.then(|| joint_damping(alpha_deg));
    for v in &mut b.model.nodes.vel {
        *v = [0.0; 2];
    }
    let mut dynamic = Solver::new(&mut b.model, &sc.solve, 0);
    let dt = dynamic.params.dt;
    let mean = |m: &adit::model::Model| {
        let k = nodes.len() as f64;
        let s = nodes.clone().fold([0.0; 2], |s, n| {
            let d = m.nodes.disp[n];
            [s[0] + d[0], s[1] + d[1]]
        });
        [s[0] / k, s[1] / k]
    };
    let u0 = mean(&b.model);
    let (l0, r0) = (b.model.nodes.disp[left], b.model.nodes.disp[right]);
    let a = alpha_deg.to_radians();
    let accel = acceleration(alpha_deg, phi_deg);
    let samples = 20;
    let steps = (duration / dt / samples as f64).ceil() as u64;
    dynamic.spec.max_cycles = steps;
    dynamic.spec.monitor_every = steps;
    let (mut worst, mut turn, mut along, mut cycles) = (0.0f64, 0.0f64, 0.0, settled);
    for k in 1..=samples {
        let sol = dynamic.solve(&mut b.model, &mut Quiet);
        anyhow::ensure!(
            !matches!(sol.status, Status::Failed(_)),
            "sliding column failed: {:?}",
            sol.status
        );
        cycles += sol.cycles;
        let t = (k as u64 * steps) as f64 * dt;
        let u = mean(&b.model);
        // Down the joint: −(cos α, sin α).
        along = -((u[0] - u0[0]) * a.cos() + (u[1] - u0[1]) * a.sin());
        worst = worst.max((along - 0.5 * accel * t * t).abs());
        let (l, r) = (b.model.nodes.disp[left], b.model.nodes.disp[right]);
        turn = turn.max((((r[1] - r0[1]) - (l[1] - l0[1])) / 1.0).abs());
    }
    let t_end = (samples as u64 * steps) as f64 * dt;
    let exact = 0.5 * accel * t_end * t_end;
    let started = match start_by {
        Start::Settled => "settled",
        Start::FromRest => "from rest",
    };
    let damping = if damped {
        "Rayleigh ξ = 5 % (stiffness)"
    } else {
        "undamped"
    };
    Ok(CaseReport::new(
        format!(
            "column, joint at {alpha_deg}°, φ = {phi_deg}°, {started}, {damping} ({})",
            mode_name(mode)
        ),
        b.model.zones.len(),
        cycles,
        start.elapsed().as_secs_f64(),
        Some(h),
        &[
            ("slide", worst / exact),
            ("final", (along - exact) / exact),
            ("rotation", 0.5 * turn / exact),
        ],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coarse twin of the report's column section at 35°: damped, every mode within 3 % of the
    /// rigid-block slide, settled or from rest (measured at zones of 0.1 m: 0.1–0.4 %).
    #[test]
    fn a_damped_column_slides_as_the_rigid_block_closed_form() {
        for mode in [BlockMode::Rigid, BlockMode::Simple, BlockMode::Deformable] {
            for start in [Start::Settled, Start::FromRest] {
                let r = run((35.0, 30.0), start, true, 0.05, 0.2, mode).unwrap();
                eprintln!("{r:?}");
                assert!(r.errors["slide"] < 0.03, "{r:?}");
                assert!(r.errors["rotation"] < 0.01, "{r:?}");
            }
        }
        // Undamped, the rigid block slides as the closed form too (issue 48 reported 57 % too
        // far and a rotation; measured here 0.07 %, rotation 2e-4 of the slide).
        let r = run(
            (35.0, 30.0),
            Start::Settled,
            false,
            0.05,
            0.2,
            BlockMode::Rigid,
        )
        .unwrap();
        assert!(
            r.errors["slide"] < 0.01 && r.errors["rotation"] < 0.01,
            "{r:?}"
        );
    }
}
