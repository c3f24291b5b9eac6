//! Direct shear of a jointed specimen under constant normal stress (the laboratory test UDEC users
//! calibrate joints with): a 1 m top block on a longer fixed bottom block, a normal stress σn on its
//! top, and the block driven sideways at a slow, constant velocity without rotating (a guided shear
//! box). The joint's average shear
//! stress must rise with the shear stiffness ks, peak at c + σn tan φ, fall to σn tan φ once the
//! cohesion is lost, and the top block must rise by tan ψ per unit of slip (Coulomb slip model).

use std::time::Instant;

use adit::Scene;
use adit::implicit::Cost;
use adit::joint::{BartonBandis, Roughness};
use adit::scene::{SolveMethod, SolveSpec};
use adit::setup::setup;

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
    scene_at(h, joint, SIGMA_N)
}

/// The specimen with normal stress `sigma_n` (Pa, compression positive) on its top.
fn scene_at(h: f64, joint: &str, sigma_n: f64) -> Scene {
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
        sn = -sigma_n
    );
    Scene::from_json(&text, "direct shear scene").expect("valid direct shear scene")
}

/// One sample of a shear test.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    /// Horizontal displacement of the top block, m.
    pub x: f64,
    /// Shear force on the joint (Σ τ L over its contacts), N/m: the average shear stress of the 1 m joint, Pa.
    pub shear: f64,
    /// Vertical displacement of the top block, m.
    pub y: f64,
    /// Length-weighted mean shear displacement of the joint's contacts, m.
    pub slip: f64,
    /// Length-weighted mean shear path Σ|Δus| of the joint's contacts, m.
    pub path: f64,
    /// Length-weighted mean normal stress of the joint's contacts, Pa (tension positive).
    pub normal: f64,
}

/// What the normal loading left: the length-weighted mean normal displacement of the joint's
/// contacts (m, opening positive).
fn mean_normal_displacement(c: &adit::model::Contacts) -> f64 {
    (0..c.len())
        .map(|k| c.state[k].normal_displacement * c.length[k])
        .sum::<f64>()
        / c.length.iter().sum::<f64>()
}

/// A test's curve, the mean normal displacement of the joint after the normal loading (m), the
/// cycles (or iterations), the zones and, implicitly, the solves' cost.
struct Test {
    curve: Vec<Sample>,
    loaded: f64,
    cycles: u64,
    zones: usize,
    cost: Option<Cost>,
}

/// Load the specimen with σn, then drive the top block sideways to 3 mm, solved by `method`; the
/// curve, the cycles (or iterations) and, implicitly, the solves' cost. Explicitly the block
/// moves at 2e-8 m a cycle and is sampled every 500 cycles; implicitly each sample is a static
/// solve with the block driven by the same 1e-5 m (`implicit::solve_driven`).
fn shear(
    sc: &Scene,
    method: SolveMethod,
) -> anyhow::Result<(Vec<Sample>, u64, usize, Option<Cost>)> {
    let t = shear_test(sc, method, 1)?;
    Ok((t.curve, t.cycles, t.zones, t.cost))
}

/// [`shear`], with the joint's closure after the normal loading, the explicit drive `slowdown`
/// times slower than 2e-8 m a cycle.
fn shear_test(sc: &Scene, method: SolveMethod, slowdown: u64) -> anyhow::Result<Test> {
    let mut b = setup(sc)?;
    let spec = SolveSpec {
        method,
        ..sc.solve.clone()
    };
    let (mut solver, settled_cycles, mut cost) =
        crate::settle_keeping_solver(&mut b.model, &spec, "direct shear: normal loading")?;
    // The whole top block is driven sideways (x fixed at a constant velocity, y free): like the
    // guided box of a shear rig, it cannot rotate, so the joint shears uniformly.
    let top_block = b
        .model
        .blocks
        .block_of_node(b.plan.boundary.part_nodes["top"][0]);
    let nodes = b.model.blocks.node_start[top_block] as usize
        ..b.model.blocks.node_start[top_block + 1] as usize;
    let top: Vec<u32> = nodes.map(|n| n as u32).collect();
    let loaded = mean_normal_displacement(&b.model.contacts);
    // m per cycle (Δt = 1 in the mass-scaled static mode), sampled every 1e-5 m.
    let rate = 2e-8 / slowdown as f64;
    let chunk = 500 * slowdown;
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
    let mut cycles = settled_cycles;
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
        let path = (0..c.len())
            .map(|k| c.state[k].shear_path * c.length[k])
            .sum::<f64>()
            / c.length.iter().sum::<f64>();
        let normal = (0..c.len())
            .map(|k| c.state[k].normal * c.length[k])
            .sum::<f64>()
            / c.length.iter().sum::<f64>();
        curve.push(Sample {
            normal,
            x: mean(&b.model, 0) - x0,
            shear: force.abs(),
            y: mean(&b.model, 1) - y0,
            slip,
            path,
        });
    }
    Ok(Test {
        curve,
        loaded,
        cycles,
        zones: b.model.zones.len(),
        cost,
    })
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

/// The Barton–Bandis joint of the test: JRC 10 and JCS 100 MPa on a 0.1 m sample, φr = 30°,
/// Kni = 2e10 Pa/m, Vm = 0.5 mm, ks = 2e10 Pa/m (above the peak's secant τp/δp at every σn
/// tested, so that the elastic line meets the curve before its peak), M = 2.
pub fn barton_bandis() -> BartonBandis {
    BartonBandis::new(
        (2e10, 0.5e-3),
        2e10,
        Roughness {
            jrc: 10.0,
            jcs: 100e6,
            sample_length: 0.1,
            block_size: None,
        },
        30.0,
        2.0,
    )
}

const BARTON_BANDIS_JOINT: &str = r#"{ "law": "barton_bandis", "normal_stiffness": 2e10,
    "shear_stiffness": 2e10, "friction": 30, "jrc": 10, "jcs": 100e6, "max_closure": 0.5e-3 }"#;

/// A Barton–Bandis direct shear test at `sigma_n` (Pa): the row and the curve. Errors: the
/// joint's closure under σn against the hyperbola σn Vm/(Kni Vm + σn); the peak shear stress
/// against σn tan(φr + JRC log10(JCS/σn)); the rise of the block after the peak against the
/// dilation the mobilized JRC gives, Σ tan dmob(δ) Δλ over the samples (δ the joints' mean shear
/// path, Δλ its plastic part: the path's increment plus the elastic recovery of the falling
/// shear stress, −Δτ/ks).
pub fn run_barton_bandis(
    h: f64,
    sigma_n: f64,
    method: SolveMethod,
) -> anyhow::Result<(CaseReport, Vec<Sample>)> {
    let start = Instant::now();
    let law = barton_bandis();
    // The nodes along the joint have masses for the stiffness at JCS (Kmax = 121 Kni here), far
    // above the hyperbola's tangent at these stresses: the top block's rise lags the dilation
    // under a fast drive, compressing the joint beyond σn in proportion to the rate (at
    // 2e-8 m a cycle, 8 % at σn = 0.5 MPa; at a quarter of it, 2 %). Hence a drive eight times
    // slower than the Coulomb test's.
    let t = shear_test(&scene_at(h, BARTON_BANDIS_JOINT, sigma_n), method, 8)?;
    let closure = -t.loaded;
    let closure_exact = law.closure(sigma_n);
    let peak = t.curve.iter().map(|p| p.shear).fold(0.0, f64::max);
    let peak_exact = law.peak_strength(sigma_n);
    let from = t
        .curve
        .iter()
        .position(|p| p.path >= law.peak_displacement)
        .ok_or_else(|| anyhow::anyhow!("the test did not reach the peak displacement"))?;
    let post = &t.curve[from..];
    let predicted: f64 = post
        .windows(2)
        .map(|w| {
            let mid = 0.5 * (w[0].path + w[1].path);
            let plastic = (w[1].path - w[0].path) - (w[1].shear - w[0].shear) / law.shear_stiffness;
            law.mobilized(mid, sigma_n).dilation.tan() * plastic
        })
        .sum();
    let rise = post.last().expect("sampled").y - post[0].y;
    let errors = [
        ("closure", (closure - closure_exact).abs() / closure_exact),
        ("peak_shear", (peak - peak_exact).abs() / peak_exact),
        ("dilation", (rise - predicted).abs() / predicted),
    ];
    let report = CaseReport::new(
        format!(
            "Barton–Bandis direct shear, σn = {} MPa{}",
            sigma_n / 1e6,
            crate::method_suffix(method)
        ),
        t.zones,
        t.cycles,
        start.elapsed().as_secs_f64(),
        Some(h),
        &errors,
    )
    .with_implicit(t.cost);
    Ok((report, t.curve))
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

    /// The coarse twin of the report's Barton–Bandis section: two normal stresses, explicit and
    /// implicit, closure within 1 %, peak within 2 %, the rise after the peak within 5 % of the
    /// mobilized JRC's dilation (measured: peak 0.02 % / 0.14 % explicit, 0.1 % implicit;
    /// dilation under 0.7 %; closure under 0.03 %).
    #[test]
    fn barton_bandis_joint_peaks_at_its_criterion_and_dilates_by_its_mobilized_jrc() {
        for sn in [1e6, 4e6] {
            let (r, _) = run_barton_bandis(0.125, sn, SolveMethod::Explicit).unwrap();
            eprintln!("{r:?}");
            assert!(r.errors["closure"] < 0.01, "{r:?}");
            assert!(r.errors["peak_shear"] < 0.02, "{r:?}");
            assert!(r.errors["dilation"] < 0.05, "{r:?}");
            let (i, _) = run_barton_bandis(0.125, sn, SolveMethod::Implicit).unwrap();
            eprintln!("{i:?}");
            assert!(i.errors["closure"] < 0.01, "{i:?}");
            assert!(i.errors["peak_shear"] < 0.02, "{i:?}");
            assert!(i.errors["dilation"] < 0.05, "{i:?}");
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
