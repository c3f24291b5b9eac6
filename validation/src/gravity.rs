//! Gravity: a confined column loading itself, and an in-situ stress gradient in equilibrium with
//! gravity that must leave the model at rest.
//!
//! Column of height H on a fixed base with its sides on rollers (uniaxial strain): σyy(y) =
//! −ρg(H − y), σxx = σzz = ν/(1 − ν) σyy, and the settlement u_y(y) = −ρg(Hy − y²/2)/M with the
//! constrained modulus M = K + 4G/3 (e.g. Jaeger, Cook & Zimmerman, §5.7).

use std::time::Instant;

use adit::Scene;
use adit::scene::SolveMethod;
use adit::setup::setup;

use crate::report::CaseReport;
use crate::settle;

const RHO: f64 = 2500.0;
const G: f64 = 9.81;
const YOUNG: f64 = 10e9;
const POISSON: f64 = 0.25;
const HEIGHT: f64 = 20.0;

fn column_scene(h: f64, in_situ: bool) -> Scene {
    let in_situ = if in_situ {
        format!(
            r#""in_situ": {{ "syy": {syy}, "sxx": {sxx}, "y_ref": 0,
                 "gradient": {{ "syy": {gy}, "sxx": {gx} }} }},"#,
            syy = -RHO * G * HEIGHT,
            sxx = -RHO * G * HEIGHT * POISSON / (1.0 - POISSON),
            gy = RHO * G,
            gx = RHO * G * POISSON / (1.0 - POISSON)
        )
    } else {
        String::new()
    };
    let text = format!(
        r#"{{
        "name": "column",
        "materials": {{ "rock": {{ "density": {RHO}, "young": {YOUNG}, "poisson": {POISSON} }} }},
        "region": {{ "polygon": [[0, 0], [5, 0], [5, {HEIGHT}], [0, {HEIGHT}]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" }},
        "zoning": {{ "edge_at_excavation": {h}, "edge_far": {h} }},
        {in_situ}
        "gravity": [0, -{G}],
        "boundary": [{{ "part": "base", "fix": "xy" }}, {{ "part": "left", "fix": "x" }}, {{ "part": "right", "fix": "x" }}],
        "solve": {{ "ratio": 1e-9, "max_cycles": 500000 }}
    }}"#
    );
    Scene::from_json(&text, "column scene").expect("valid column scene")
}

/// Self-weight of a confined column: relative L2 error of σyy over zones and largest settlement
/// error over nodes relative to the top settlement.
pub fn self_weight(h: f64) -> anyhow::Result<CaseReport> {
    self_weight_by(h, SolveMethod::Explicit)
}

/// [`self_weight`] solved by `method` (`solve.method`); the row's case names it unless explicit.
pub fn self_weight_by(h: f64, method: SolveMethod) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let mut scene = column_scene(h, false);
    scene.solve.method = method;
    let mut b = setup(&scene)?;
    let (cycles, implicit) = crate::settle_by_method(&mut b.model, &scene.solve, "column")?;
    let m = crate::constrained_modulus(YOUNG, POISSON);
    let model = &b.model;
    let (mut num, mut den) = (0.0, 0.0);
    for z in 0..model.zones.len() {
        let c = model.zones.centroid(z, &model.nodes.pos);
        let exact = -RHO * G * (HEIGHT - c[1]);
        let a = model.zones.area[z];
        num += a * (model.zones.stress[z][1] - exact).powi(2);
        den += a * exact * exact;
    }
    let settlement = |y: f64| -RHO * G * (HEIGHT * y - 0.5 * y * y) / m;
    let top = settlement(HEIGHT).abs();
    let du = (0..model.nodes.len())
        .map(|n| (model.nodes.disp[n][1] - settlement(model.nodes.pos[n][1])).abs())
        .fold(0.0, f64::max)
        / top;
    let wall_s = start.elapsed().as_secs_f64();
    let errors = [("stress_l2", (num / den).sqrt()), ("settlement", du)];
    let case = format!(
        "gravity: confined column self-weight{}",
        crate::method_suffix(method)
    );
    Ok(
        CaseReport::new(case, model.zones.len(), cycles, wall_s, Some(h), &errors)
            .with_implicit(implicit),
    )
}

/// In-situ stress with the gravity gradient: the model must stay at rest. Error: largest
/// displacement relative to the settlement the column would show under its own weight from zero
/// stress (ρgH²/2M).
pub fn in_situ_equilibrium(h: f64) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let scene = column_scene(h, true);
    let mut b = setup(&scene)?;
    let (_, cycles) = settle(&mut b.model, &scene.solve, "column")?;
    let m = crate::constrained_modulus(YOUNG, POISSON);
    let reference = RHO * G * HEIGHT * HEIGHT / (2.0 * m);
    let umax = b
        .model
        .nodes
        .disp
        .iter()
        .map(|u| u[0].hypot(u[1]))
        .fold(0.0, f64::max);
    let wall_s = start.elapsed().as_secs_f64();
    let errors = [("displacement", umax / reference)];
    Ok(CaseReport::new(
        "gravity: in-situ gradient at rest",
        b.model.zones.len(),
        cycles,
        wall_s,
        Some(h),
        &errors,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn column_under_self_weight_matches_the_closed_form() {
        let r = self_weight(1.0).unwrap();
        eprintln!("{r:?}");
        assert!(
            r.errors["stress_l2"] < 0.02 && r.errors["settlement"] < 0.02,
            "{r:?}"
        );
    }

    #[test]
    fn in_situ_gradient_with_gravity_stays_at_rest() {
        let r = in_situ_equilibrium(1.0).unwrap();
        eprintln!("{r:?}");
        assert!(r.errors["displacement"] < 0.01, "{r:?}");
    }
}
