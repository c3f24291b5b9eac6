//! The element test of a zone law (issue 48): a small plane-strain specimen, 1 m × 2 m, under a
//! confining stress σ3 on its sides, compressed between smooth platens past its peak. With a
//! perfectly plastic law every zone flows on the yield surface at the same mean σ3, so the platen
//! stress while the specimen flows is the law's strength σ1(σ3): what `strength` measures, against
//! a closed form.
//!
//! The confinement is applied as in-situ stress and side tractions, so the specimen starts in
//! equilibrium; the top is driven down (`crate::drive_nodes`) to the axial `strain`: explicitly at
//! a constant rate, brought to rest over `DECELERATION` samples and relaxed to an unbalanced-force
//! ratio of 1e-10 (a platen stopped at once would unload zones elastically below the surface: at
//! 2e-6 strain a cycle by 0.4 % of σ1, which is the test's error, not the law's; driven over
//! 400 000 cycles and brought to rest gently, 1e-7); implicitly in `IMPLICIT_STEPS` static steps,
//! each solved to equilibrium. The platen stress is the area mean of σyy
//! (∫σ dA = ∮ x ⊗ t ds), whose mean σxx is the side traction exactly.

use std::time::Instant;

use adit::Scene;
use adit::scene::{SolveMethod, SolveSpec};
use adit::setup::setup;
use adit::solve::Status;

/// Height of the specimen, m (its width is 1 m).
const HEIGHT: f64 = 2.0;
/// Cycles between samples of an explicit drive.
const CHUNK: u64 = 500;
/// Samples over which the explicit drive is brought to rest.
const DECELERATION: u64 = 40;
/// Static steps of an implicit drive.
const IMPLICIT_STEPS: u64 = 40;

/// What one element test measured.
#[derive(Debug, Clone)]
pub struct Strength {
    /// Confining stress σ3, Pa (compression positive; negative: tension).
    pub sigma3: f64,
    /// Axial stress σ1 while flowing at the end of the drive, Pa (compression positive).
    pub sigma1: f64,
    /// Largest axial stress seen while driving, Pa.
    pub peak: f64,
    pub zones: usize,
    pub cycles: u64,
    pub seconds: f64,
    /// Fraction of the specimen's area whose zones have yielded.
    pub yielded: f64,
}

/// The specimen of `material` (a scene's material object) zoned at `edge` m under `sigma3`,
/// compressed to the axial `strain` (negative: pulled) over `cycles` explicitly, or in as many
/// implicit steps of `CHUNK` cycles' worth, by `method`.
pub fn strength(
    material: &serde_json::Value,
    sigma3: f64,
    edge: f64,
    (strain, cycles): (f64, u64),
    method: SolveMethod,
) -> anyhow::Result<Strength> {
    let (rate, cycles_to_strain) = (strain / cycles as f64, cycles);
    let start = Instant::now();
    let sc = scene(material, sigma3, edge)?;
    let mut b = setup(&sc)?;
    let spec = SolveSpec {
        method,
        ..sc.solve.clone()
    };
    let (mut solver, mut cycles, mut cost) = crate::settle_keeping_solver(
        &mut b.model,
        &spec,
        &format!("element test under σ3 = {sigma3:e} Pa: the confinement"),
    )?;
    let top = b.plan.boundary.part_nodes["top"].clone();
    let chunk = match method {
        SolveMethod::Explicit => CHUNK,
        _ => cycles_to_strain.div_ceil(IMPLICIT_STEPS),
    };
    let drive = crate::drive_nodes(&mut b.model, &top, 1, -rate * HEIGHT, chunk, method);
    let mut analysis = adit::implicit::Analysis::default();
    solver.spec.max_cycles = chunk;
    solver.spec.ratio = 0.0;
    let area: f64 = b.model.zones.area.iter().sum();
    let platen = |m: &adit::model::Model| {
        -m.zones
            .stress
            .iter()
            .zip(&m.zones.area)
            .map(|(s, a)| s[1] * a)
            .sum::<f64>()
            / area
    };
    // The largest platen stress in the drive's sense (compression positive when compressed).
    let mut peak = 0.0f64;
    let sense = strain.signum();
    let mut sample = |model: &mut adit::model::Model| {
        crate::drive_sample(model, &mut solver, &spec, &drive, &mut analysis, &mut cost)
            .map(|sol| sol.cycles)
            .map_err(|status| anyhow::anyhow!("element test under σ3 = {sigma3:e} Pa: {status:?}"))
    };
    while -b.model.nodes.disp[top[0] as usize][1] / HEIGHT / strain < 1.0 {
        cycles += sample(&mut b.model)?;
        peak = peak.max(sense * platen(&b.model));
    }
    if method == SolveMethod::Explicit {
        for k in (0..DECELERATION).rev() {
            for &n in &top {
                b.model.nodes.vel[n as usize][1] = -rate * HEIGHT * k as f64 / DECELERATION as f64;
            }
            cycles += sample(&mut b.model)?;
        }
        solver.spec.max_cycles = 2_000_000;
        solver.spec.ratio = 1e-10;
        let held = solver.solve(&mut b.model, &mut adit::solve::Quiet);
        anyhow::ensure!(
            held.status == Status::Converged,
            "element test under σ3 = {sigma3:e} Pa: relaxing did not converge: {:?}",
            held.status
        );
        cycles += held.cycles;
    }
    let m = &b.model;
    let yielded: f64 = (0..m.zones.len())
        .filter(|&i| m.zones.state[i] != 0)
        .map(|i| m.zones.area[i])
        .sum();
    Ok(Strength {
        sigma3,
        sigma1: platen(m),
        peak: sense * peak,
        zones: m.zones.len(),
        cycles,
        seconds: start.elapsed().as_secs_f64(),
        yielded: yielded / area,
    })
}

/// The specimen scene: `material` as `rock`, confined by `sigma3` (compression positive).
fn scene(material: &serde_json::Value, sigma3: f64, edge: f64) -> anyhow::Result<Scene> {
    let text = serde_json::json!({
        "name": "element test",
        "materials": { "rock": material },
        "region": { "polygon": [[0, 0], [1, 0], [1, HEIGHT], [0, HEIGHT]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": edge, "edge_far": edge },
        "in_situ": { "sxx": -sigma3, "syy": -sigma3 },
        "boundary": [
            { "part": "base", "fix": "y" }, { "part": "top", "fix": "y" },
            { "at": [0.5, 0], "fix": "x" },
            { "part": "left", "normal_stress": -sigma3 },
            { "part": "right", "normal_stress": -sigma3 }
        ],
        "solve": { "ratio": 1e-10, "max_cycles": 2000000 }
    });
    Ok(Scene::from_json(&text.to_string(), "element test")?)
}

#[cfg(test)]
mod coarse {
    use super::*;

    /// A Mohr–Coulomb specimen (c 1 MPa, φ 30°) under 2 MPa ends on σ3 Nφ + 2c√Nφ to 1e-6,
    /// explicit and implicit.
    #[test]
    fn a_mohr_coulomb_specimen_ends_on_its_envelope() {
        let material = serde_json::json!({
            "density": 2500, "young": 5e9, "poisson": 0.25, "law": "mohr_coulomb",
            "cohesion": 1e6, "friction": 30, "dilation": 0
        });
        let exact = 2e6 * 3.0 + 2.0 * 1e6 * 3f64.sqrt();
        for method in [SolveMethod::Explicit, SolveMethod::Implicit] {
            let r = strength(&material, 2e6, 0.5, (0.0016, 400_000), method).unwrap();
            assert!(
                (r.sigma1 - exact).abs() < 1e-6 * exact,
                "{method:?}: {} against {exact}",
                r.sigma1
            );
            assert!(r.yielded > 0.999, "{method:?}: {}", r.yielded);
        }
    }
}
