//! Direct shear of a jointed specimen under constant normal stress (the laboratory test UDEC users
//! calibrate joints with): a 1 m top block on a longer fixed bottom block, a normal stress σn on its
//! top, and the block driven sideways at a slow, constant velocity without rotating (a guided shear
//! box). The joint's average shear
//! stress must rise with the shear stiffness ks, peak at c + σn tan φ, fall to σn tan φ once the
//! cohesion is lost, and the top block must rise by tan ψ per unit of slip (Coulomb slip model).

use std::time::Instant;

use adit::Scene;
use adit::implicit::Cost;
use adit::scene::{SolveMethod, SolveSpec};
use adit::setup::setup;
use adit::solve::Status;

use crate::report::CaseReport;

/// Joint properties of the test.
const KS: f64 = 1e9;
const SIGMA_N: f64 = 1e6;
const COHESION: f64 = 0.2e6;
const FRICTION: f64 = 30.0;
const DILATION: f64 = 5.0;

/// The Coulomb joint of the test.
fn coulomb() -> String {
    format!(
        r#"{{ "normal_stiffness": 1e10, "shear_stiffness": {KS}, "friction": {FRICTION},
             "cohesion": {COHESION}, "dilation": {DILATION} }}"#
    )
}

fn scene(h: f64, joint: &str) -> Scene {
    let text = format!(
        r#"{{
        "name": "direct_shear",
        "materials": {{ "rock": {{ "density": 2500, "young": 50e9, "poisson": 0.2 }} }},
        "region": {{ "polygon": [[-0.5, 0], [1.5, 0], [1.5, 0.5], [1, 0.5], [1, 1], [0, 1], [0, 0.5], [-0.5, 0.5]],
                    "edge_names": ["base", "e1", "e2", "e3", "top", "e5", "e6", "e7"], "material": "rock" }},
        "zoning": {{ "edge_at_excavation": {h}, "edge_far": {h} }},
        "joint_materials": {{ "sample": {joint} }},
        "joints": [{{ "from": [0, 0.5], "to": [1, 0.5], "material": "sample" }}],
        "boundary": [{{ "part": "base", "fix": "xy" }}, {{ "part": "top", "fix": "x" }},
                     {{ "part": "top", "normal_stress": {sn} }}],
        "solve": {{ "ratio": 1e-6, "max_cycles": 200000 }}
    }}"#,
        sn = -SIGMA_N
    );
    Scene::from_json(&text, "direct shear scene").expect("valid direct shear scene")
}

/// One sample of a shear test.
#[derive(Debug, Clone, Copy)]
struct Sample {
    /// Horizontal displacement of the top block, m.
    x: f64,
    /// Shear force on the joint (Σ τ L over its contacts), N/m: the average shear stress of the 1 m joint, Pa.
    shear: f64,
    /// Vertical displacement of the top block, m.
    y: f64,
    /// Length-weighted mean shear displacement of the joint's contacts, m.
    slip: f64,
}

/// Load the specimen with σn, then drive the top block sideways to 3 mm, solved by `method`; the
/// curve, the cycles (or iterations) and, implicitly, the solves' cost. Explicitly the block
/// moves at 2e-8 m a cycle and is sampled every 500 cycles; implicitly each sample is a static
/// solve with the block driven by the same 1e-5 m (`implicit::solve_driven`).
fn shear(
    sc: &Scene,
    method: SolveMethod,
) -> anyhow::Result<(Vec<Sample>, u64, usize, Option<Cost>)> {
    let mut b = setup(sc)?;
    let spec = SolveSpec {
        method,
        ..sc.solve.clone()
    };
    let (mut solver, settled, mut cost) = crate::solve_by_method(&mut b.model, &spec);
    anyhow::ensure!(
        settled.status == Status::Converged,
        "direct shear: normal loading did not converge: {:?}",
        settled.status
    );
    // The whole top block is driven sideways (x fixed at a constant velocity, y free): like the
    // guided box of a shear rig, it cannot rotate, so the joint shears uniformly.
    let top_block = b
        .model
        .blocks
        .block_of_node(b.plan.boundary.part_nodes["top"][0]);
    let nodes = b.model.blocks.node_start[top_block] as usize
        ..b.model.blocks.node_start[top_block + 1] as usize;
    let top: Vec<u32> = nodes.map(|n| n as u32).collect();
    let rate = 2e-8; // m per cycle (Δt = 1 in the mass-scaled static mode)
    let chunk = 500u64;
    let drive = crate::drive_nodes(&mut b.model, &top, 0, rate, chunk, method);
    let mut analysis = adit::implicit::Analysis::default();
    let mean = |m: &adit::model::Model, d: usize| {
        top.iter()
            .map(|&n| m.nodes.disp[n as usize][d])
            .sum::<f64>()
            / top.len() as f64
    };
    let (x0, y0) = (mean(&b.model, 0), mean(&b.model, 1));
    solver.spec.max_cycles = chunk;
    solver.spec.ratio = 0.0;
    let mut curve: Vec<Sample> = Vec::new();
    let mut cycles = settled.cycles;
    while mean(&b.model, 0) - x0 < 3e-3 {
        let sol = crate::drive_sample(
            &mut b.model,
            &mut solver,
            &spec,
            &drive,
            &mut analysis,
            &mut cost,
        )
        .map_err(|status| {
            anyhow::anyhow!(
                "direct shear ({}) did not converge: {status:?}",
                method.name()
            )
        })?;
        cycles += sol.cycles;
        let c = &b.model.contacts;
        // Both sides' contacts together cover the 1 m joint once: Σ τ L is the shear force.
        let force: f64 = (0..c.len()).map(|k| c.state[k].shear * c.length[k]).sum();
        let slip = (0..c.len())
            .map(|k| c.state[k].shear_displacement.abs() * c.length[k])
            .sum::<f64>()
            / c.length.iter().sum::<f64>();
        curve.push(Sample {
            x: mean(&b.model, 0) - x0,
            shear: force.abs(),
            y: mean(&b.model, 1) - y0,
            slip,
        });
    }
    Ok((curve, cycles, b.model.zones.len(), cost))
}

/// Shear the specimen to 3 mm; errors: peak and residual shear stress against c + σn tan φ and
/// σn tan φ, the pre-peak shear stiffness against ks, and the dilation rate against tan ψ.
pub fn run(h: f64) -> anyhow::Result<CaseReport> {
    run_by(h, SolveMethod::Explicit)
}

/// [`run`] solved by `method`; the row's case names it.
pub fn run_by(h: f64, method: SolveMethod) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let (curve, cycles, zones, cost) = shear(&scene(h, &coulomb()), method)?;
    let tan_phi = FRICTION.to_radians().tan();
    let peak_exact = COHESION + SIGMA_N * tan_phi;
    let residual_exact = SIGMA_N * tan_phi;
    let peak = curve.iter().map(|p| p.shear).fold(0.0, f64::max);
    let residual = curve.last().expect("sheared").shear;
    // Pre-peak stiffness: secant at a third of the peak.
    let pre = curve
        .iter()
        .find(|p| p.shear > peak_exact / 3.0)
        .expect("loading branch");
    let stiffness = pre.shear / pre.x;
    // Dilation rate over the last third of the slip.
    let n = curve.len();
    let (a, z) = (curve[2 * n / 3], curve[n - 1]);
    let dilation_rate = (z.y - a.y) / (z.x - a.x);
    let wall_s = start.elapsed().as_secs_f64();
    let errors = [
        ("peak_shear", (peak - peak_exact).abs() / peak_exact),
        (
            "residual_shear",
            (residual - residual_exact).abs() / residual_exact,
        ),
        // The blocks' own elasticity is in series with the joint: a small, physical, difference.
        ("shear_stiffness", (stiffness - KS).abs() / KS),
        (
            "dilation_rate",
            (dilation_rate - DILATION.to_radians().tan()).abs() / DILATION.to_radians().tan(),
        ),
    ];
    Ok(CaseReport::new(
        format!(
            "direct shear, σn = 1 MPa, c = 0.2 MPa, φ = 30°, ψ = 5°{}",
            crate::method_suffix(method)
        ),
        zones,
        cycles,
        wall_s,
        Some(h),
        &errors,
    )
    .with_implicit(cost))
}

/// The same test with a continuously yielding joint whose bounding friction starts at the basic
/// friction (φm0 = φ = 30°, so no wear): under constant σn the joint's average shear stress
/// follows τ = τm (1 − exp(−ks u/τm)), τm = σn tan φ, against its mean slip u (the law's closed
/// form, Cundall & Hart 1984). Error: largest |τ − τ(u)| over the curve relative to τm.
pub fn run_yielding(h: f64) -> anyhow::Result<CaseReport> {
    run_yielding_by(h, SolveMethod::Explicit)
}

/// [`run_yielding`] solved by `method`; the row's case names it.
pub fn run_yielding_by(h: f64, method: SolveMethod) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let joint = format!(
        r#"{{ "law": "continuously_yielding", "normal_stiffness": 1e10, "shear_stiffness": {KS},
             "friction": {FRICTION}, "roughness": 1e-3 }}"#
    );
    let (curve, cycles, zones, cost) = shear(&scene(h, &joint), method)?;
    let tau_m = SIGMA_N * FRICTION.to_radians().tan();
    let worst = curve
        .iter()
        .map(|p| (p.shear - tau_m * (1.0 - (-KS * p.slip / tau_m).exp())).abs() / tau_m)
        .fold(0.0, f64::max);
    Ok(CaseReport::new(
        format!(
            "direct shear, continuously yielding joint, σn = 1 MPa, φ = φm0 = 30°{}",
            crate::method_suffix(method)
        ),
        zones,
        cycles,
        start.elapsed().as_secs_f64(),
        Some(h),
        &[("shear_curve", worst)],
    )
    .with_implicit(cost))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn direct_shear_peaks_at_cohesion_plus_friction_and_dilates() {
        let r = run(0.125).unwrap();
        eprintln!("{r:?}");
        for e in ["peak_shear", "residual_shear", "shear_stiffness"] {
            assert!(r.errors[e] < 0.02, "{e}: {r:?}");
        }
        // On this coarse mesh the block rises about 5 % less than tan ψ per unit slip: the end
        // contacts, which lose and gain partners, dilate less. The report's finer mesh is within 2 %.
        assert!(r.errors["dilation_rate"] < 0.08, "{r:?}");
        // Under displacement control, each sample a static solve: the same curve, each error
        // within 0.5 percentage points of the explicit one's or below it (issue 17's bar), the
        // dilation rate within 1. The joints' trial from each sample's commit takes the slip at its
        // end, a joint that fails within a sample ends it at its residual strength, as explicitly,
        // and a slipping joint's return counts the compression its dilation adds
        // (`CoulombSlip::plastic_slip`). Measured: peak 1.33 % as explicitly, residual 1e-7
        // against 0.064 %, stiffness alike; dilation rate 1.34 % against 0.67 %: each sample of
        // steady sliding rises by tan ψ to 1e-5 implicitly (±10 % explicitly), and the window's
        // 1.34 % is one event, the box sinking by 1.3 samples' rise at 2.82 mm of shear (where an
        // end contact changes; not traced further), which the explicit samples do not show.
        let i = run_by(0.125, SolveMethod::Implicit).unwrap();
        eprintln!("{i:?}");
        for (e, ve) in &r.errors {
            let bar = if e == "dilation_rate" { 0.01 } else { 0.005 };
            assert!(i.errors[e] < ve + bar, "{e}: {i:?} {r:?}");
        }
    }

    /// 3.1 % on this coarse mesh, 1.4 % at the report's 0.0625 m (the end contacts, which lose
    /// and gain partners, lag the closed form; the error halves with the zone size).
    #[test]
    fn continuously_yielding_joint_follows_its_closed_form() {
        let r = run_yielding(0.125).unwrap();
        eprintln!("{r:?}");
        assert!(r.errors["shear_curve"] < 0.05, "{r:?}");
    }
}
