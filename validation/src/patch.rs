//! Patch tests on an irregular mesh (a uniform stress and a linear displacement field must be
//! reproduced to round-off) and uniaxial compression of one block against Hooke's law.

use std::time::Instant;

use adit::Scene;
use adit::model::{FIX_X, FIX_Y};
use adit::setup::{Setup, setup};
use adit::solve::{Quiet, Solver, Status};

use crate::report::CaseReport;
use crate::settle;

/// Material of the patch tests: E = 10 GPa, ν = 0.25.
const YOUNG: f64 = 10e9;
const POISSON: f64 = 0.25;

/// A one-block scene on an irregular pentagon, zoned to about `h` (m), with extra JSON boundary
/// conditions and a solve tolerance.
fn pentagon_scene(h: f64, boundary: &str, ratio: f64) -> Scene {
    let text = format!(
        r#"{{
        "name": "patch",
        "materials": {{ "rock": {{ "density": 2500, "young": {YOUNG}, "poisson": {POISSON} }} }},
        "region": {{ "polygon": [[0, 0], [1.3, 0.1], [1.1, 1.2], [0.4, 1.0], [-0.1, 0.6]], "material": "rock" }},
        "zoning": {{ "edge_at_excavation": {h}, "edge_far": {h}, "min_angle": 25 }},
        "boundary": [{boundary}],
        "solve": {{ "ratio": {ratio}, "max_cycles": 200000 }}
    }}"#
    );
    Scene::from_json(&text, "patch scene").expect("valid patch scene")
}

/// Plane-strain stress [σxx, σyy, σzz, σxy] (Pa) of a uniform strain [εxx, εyy, γxy].
fn hooke(e: [f64; 3]) -> [f64; 4] {
    let lambda = YOUNG * POISSON / ((1.0 + POISSON) * (1.0 - 2.0 * POISSON));
    let mu = YOUNG / (2.0 * (1.0 + POISSON));
    let tr = e[0] + e[1];
    [
        lambda * tr + 2.0 * mu * e[0],
        lambda * tr + 2.0 * mu * e[1],
        lambda * tr,
        mu * e[2],
    ]
}

fn max_stress_error(built: &Setup, exact: [f64; 4]) -> f64 {
    let scale = exact.iter().map(|v| v.abs()).fold(0.0, f64::max);
    built
        .model
        .zones
        .stress
        .iter()
        .flat_map(|s| (0..4).map(move |k| (s[k] - exact[k]).abs()))
        .fold(0.0, f64::max)
        / scale
}

fn report(
    case: &str,
    built: &Setup,
    cycles: u64,
    wall_s: f64,
    errors: &[(&str, f64)],
) -> CaseReport {
    CaseReport::new(case, built.model.zones.len(), cycles, wall_s, None, errors)
}

/// Linear displacement patch test: boundary nodes are driven along u = A·x + c over 100 cycles,
/// then held while the interior relaxes; interior nodes must follow the linear field and every
/// zone must carry the stress of the uniform strain.
pub fn linear_displacement(h: f64) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let scene = pentagon_scene(h, r#"{ "part": "outer", "fix": "xy" }"#, 1e-14);
    let mut built = setup(&scene)?;
    let a = [[2e-4, -1e-4], [0.5e-4, -3e-4]];
    let c = [1e-3, -2e-3];
    let field = |p: [f64; 2]| {
        [
            a[0][0] * p[0] + a[0][1] * p[1] + c[0],
            a[1][0] * p[0] + a[1][1] * p[1] + c[1],
        ]
    };
    let ramp = 100u64;
    let mut solver = Solver::new(&mut built.model, &scene.solve, 0);
    let nodes = &mut built.model.nodes;
    for n in 0..nodes.len() {
        if nodes.fixed[n] == FIX_X | FIX_Y {
            let u = field(nodes.pos[n]);
            nodes.vel[n] = [
                u[0] / ramp as f64 / solver.params.dt,
                u[1] / ramp as f64 / solver.params.dt,
            ];
        }
    }
    solver.spec.max_cycles = ramp;
    let first = solver.solve(&mut built.model, &mut Quiet);
    // Hold the boundary; interior velocities carry on (zeroing them would break the leapfrog's
    // half-step between displacement and strain).
    let nodes = &mut built.model.nodes;
    for n in 0..nodes.len() {
        if nodes.fixed[n] != 0 {
            nodes.vel[n] = [0.0; 2];
        }
    }
    solver.spec.max_cycles = 200_000;
    let second = solver.solve(&mut built.model, &mut Quiet);
    anyhow::ensure!(
        second.status == Status::Converged,
        "patch test did not converge: {:?}",
        second.status
    );
    let nodes = &built.model.nodes;
    let umax = nodes
        .pos
        .iter()
        .map(|&p| field(p)[0].hypot(field(p)[1]))
        .fold(0.0, f64::max);
    let du = (0..nodes.len())
        .map(|n| {
            let e = field(nodes.pos[n]);
            (nodes.disp[n][0] - e[0]).hypot(nodes.disp[n][1] - e[1])
        })
        .fold(0.0, f64::max)
        / umax;
    let ds = max_stress_error(&built, hooke([a[0][0], a[1][1], a[0][1] + a[1][0]]));
    let wall = start.elapsed().as_secs_f64();
    Ok(report(
        "patch: linear displacement",
        &built,
        first.cycles + second.cycles,
        wall,
        &[("displacement_max", du), ("stress_max", ds)],
    ))
}

/// Uniform stress patch test: the traction σ·n of a uniform σ on the whole boundary of an
/// unstressed irregular mesh (two nodes pinned against rigid motion) gives σ in every zone.
pub fn uniform_stress(h: f64) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let bcs = r#"{ "part": "outer", "stress": { "sxx": -3e6, "syy": 1e6, "sxy": 2e6 } },
                 { "at": [0, 0], "fix": "xy" }, { "at": [1.3, 0.1], "fix": "y" }"#;
    let scene = pentagon_scene(h, bcs, 1e-14);
    let mut built = setup(&scene)?;
    let (_, cycles) = settle(&mut built.model, &scene.solve, "patch test")?;
    let sxx = -3e6;
    let syy = 1e6;
    let exact = [sxx, syy, 0.0, 2e6];
    // σzz follows from the plane-strain strain of σ: σzz = ν(σxx + σyy).
    let exact = [exact[0], exact[1], POISSON * (sxx + syy), exact[3]];
    let ds = max_stress_error(&built, exact);
    let wall = start.elapsed().as_secs_f64();
    Ok(report(
        "patch: uniform stress",
        &built,
        cycles,
        wall,
        &[("stress_max", ds)],
    ))
}

/// Uniaxial compression of one square block (2 m × 2 m) in plane strain: bottom on rollers, top
/// loaded by p = 10 MPa. Hooke's law gives σyy = −p, σxx = 0, σzz = −νp, top displacement
/// −p(1 − ν²)H/E and lateral displacement pν(1 + ν)L/E.
pub fn uniaxial(h: f64) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let p = 10e6;
    let text = format!(
        r#"{{
        "name": "uniaxial",
        "materials": {{ "rock": {{ "density": 2500, "young": {YOUNG}, "poisson": {POISSON} }} }},
        "region": {{ "polygon": [[0, 0], [2, 0], [2, 2], [0, 2]], "edge_names": ["bottom", "right", "top", "left"],
                    "material": "rock" }},
        "zoning": {{ "edge_at_excavation": {h}, "edge_far": {h} }},
        "boundary": [{{ "part": "bottom", "fix": "y" }}, {{ "at": [0, 0], "fix": "x" }},
                     {{ "part": "top", "normal_stress": {} }}],
        "solve": {{ "ratio": 1e-12, "max_cycles": 200000 }}
    }}"#,
        -p
    );
    let scene = Scene::from_json(&text, "uniaxial scene")?;
    let mut built = setup(&scene)?;
    let (_, cycles) = settle(&mut built.model, &scene.solve, "uniaxial test")?;
    let axial = -p * (1.0 - POISSON * POISSON) * 2.0 / YOUNG;
    let lateral = p * POISSON * (1.0 + POISSON) * 2.0 / YOUNG;
    let nodes = &built.model.nodes;
    let (mut e_axial, mut e_lateral) = (0.0f64, 0.0f64);
    for n in 0..nodes.len() {
        let [x, y] = nodes.pos[n];
        e_axial = e_axial.max((nodes.disp[n][1] - axial * y / 2.0).abs() / axial.abs());
        e_lateral = e_lateral.max((nodes.disp[n][0] - lateral * x / 2.0).abs() / lateral);
    }
    let ds = max_stress_error(&built, [0.0, -p, -POISSON * p, 0.0]);
    let wall = start.elapsed().as_secs_f64();
    Ok(report(
        "uniaxial compression",
        &built,
        cycles,
        wall,
        &[
            ("axial_displacement", e_axial),
            ("lateral_displacement", e_lateral),
            ("stress_max", ds),
        ],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_displacement_is_reproduced_to_round_off() {
        let r = linear_displacement(0.2).unwrap();
        eprintln!("{r:?}");
        assert!(r.zones >= 40);
        assert!(r.worst() < 1e-8, "{r:?}");
    }

    #[test]
    fn uniform_stress_is_reproduced_to_round_off() {
        let r = uniform_stress(0.2).unwrap();
        eprintln!("{r:?}");
        assert!(r.worst() < 1e-8, "{r:?}");
    }

    #[test]
    fn uniaxial_block_follows_hookes_law() {
        let r = uniaxial(0.5).unwrap();
        eprintln!("{r:?}");
        assert!(r.worst() < 1e-8, "{r:?}");
    }
}
