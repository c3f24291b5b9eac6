//! Jointed rock mass as an equivalent continuum: a 20 m square of elastic rock cut by two sets of
//! persistent joints, loaded by a uniform stress σ on its boundary (three point fixities hold it
//! against rigid motion only). The joints are Coulomb joints too strong to slip under σ, so the
//! exact answer is the uniform stress: every block strains by the intact compliance, every joint
//! of a set opens and slides by the same σₙ/kₙ and τ/kₛ, and the square's mean strain is that of
//! the smeared rock mass, `adit::far_field::jointed_compliance` (Goodman 1989, §6.5), with each
//! set's spacing taken as the square's area over the length of its joints in it (a finite square
//! holds a little more or less joint than 1/spacing per area).
//!
//! Error: the largest deviation of the mean strain's components (ε_xx, ε_yy, ε_xy), measured by
//! the boundary integral ε̄ = (1/A) ∮ sym(u ⊗ n) ds (which counts the joints' openings and slips
//! inside), over the largest component of the exact one. Where joints cross, four corners meet at
//! a point and the diagonal ones are in contact: a contact that held them together there would
//! stiffen the mass, which this case measures.

use std::time::Instant;

use adit::Scene;
use adit::far_field::{JointSet, jointed_compliance, plane_strain_compliance};
use adit::scene::SolveMethod;
use adit::setup::setup;

use crate::report::CaseReport;

/// Half-width of the square, m.
const HALF: f64 = 10.0;
/// The rock: Young's modulus (Pa), Poisson's ratio.
const ROCK: (f64, f64) = (20e9, 0.25);
/// The joints' normal and shear stiffness, Pa/m.
const JOINT: (f64, f64) = (2e10, 1e10);
/// The boundary stress (σxx, σyy, σxy), Pa: principal stresses of −1.8 and −4.2 MPa, so every
/// joint is shut, and τ ≤ 1.2 MPa against a strength of 1 MPa + 1.8 MPa tan 40°.
const LOAD: [f64; 3] = [-4e6, -2e6, 0.6e6];

/// Two joint sets: dips (degrees counter-clockwise from +x), spacings (m) and origins (m).
#[derive(Debug, Clone, Copy)]
pub struct Sets {
    pub dips: [f64; 2],
    pub spacings: [f64; 2],
    pub origins: [[f64; 2]; 2],
}

/// The jointed square with zones of `edge` (m), solved by `method`.
pub fn scene(sets: &Sets, edge: f64, method: SolveMethod) -> anyhow::Result<Scene> {
    let set = |k: usize| {
        serde_json::json!({ "dip": sets.dips[k], "spacing": sets.spacings[k],
                            "origin": sets.origins[k], "material": "joint" })
    };
    let method = match method {
        SolveMethod::Implicit => "implicit",
        _ => "explicit",
    };
    let text = serde_json::json!({
        "name": "equivalent",
        "materials": { "rock": { "density": 2600, "young": ROCK.0, "poisson": ROCK.1 } },
        "region": { "polygon": [[-HALF, -HALF], [HALF, -HALF], [HALF, HALF], [-HALF, HALF]],
                    "material": "rock" },
        "zoning": { "edge_at_excavation": edge, "edge_far": edge },
        "joint_materials": { "joint": { "normal_stiffness": JOINT.0, "shear_stiffness": JOINT.1,
                                        "friction": 40, "cohesion": 1e6 } },
        "joint_sets": [set(0), set(1)],
        "boundary": [
            { "part": "outer", "stress": { "sxx": LOAD[0], "syy": LOAD[1], "sxy": LOAD[2] } },
            { "at": [-HALF, -HALF], "fix": "xy" },
            { "at": [HALF, -HALF], "fix": "y" }
        ],
        "solve": { "ratio": 1e-7, "max_cycles": 400000, "method": method }
    });
    Ok(Scene::from_json(&text.to_string(), "equivalent")?)
}

/// Length of the line through `o` along unit `t` inside the square, m.
fn chord(o: [f64; 2], t: [f64; 2]) -> f64 {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for k in 0..2 {
        if t[k].abs() < 1e-14 {
            if o[k].abs() > HALF {
                return 0.0;
            }
            continue;
        }
        let (a, b) = ((-HALF - o[k]) / t[k], (HALF - o[k]) / t[k]);
        lo = lo.max(a.min(b));
        hi = hi.min(a.max(b));
    }
    (hi - lo).max(0.0)
}

/// The exact mean strain (ε_xx, ε_yy, ε_xy) of the square under `LOAD`: the smeared compliance
/// with each set's spacing the square's area over its joints' length in it.
pub fn exact(sets: &Sets) -> [f64; 3] {
    let area = 4.0 * HALF * HALF;
    let smeared: Vec<JointSet> = (0..2)
        .map(|k| {
            let (sin, cos) = sets.dips[k].to_radians().sin_cos();
            let n = [-sin, cos];
            let lines = (2.0 * HALF * 2f64.sqrt() / sets.spacings[k]).ceil() as i64 + 2;
            let length: f64 = (-lines..=lines)
                .map(|i| {
                    let s = i as f64 * sets.spacings[k];
                    chord(
                        [sets.origins[k][0] + s * n[0], sets.origins[k][1] + s * n[1]],
                        [cos, sin],
                    )
                })
                .sum();
            JointSet {
                dip: sets.dips[k],
                spacing: area / length,
                normal_stiffness: JOINT.0,
                shear_stiffness: JOINT.1,
            }
        })
        .collect();
    let b = jointed_compliance(plane_strain_compliance(ROCK.0, ROCK.1), &smeared);
    let e: Vec<f64> = (0..3)
        .map(|i| (0..3).map(|j| b[i][j] * LOAD[j]).sum())
        .collect();
    [e[0], e[1], 0.5 * e[2]]
}

/// The square's mean strain (ε_xx, ε_yy, ε_xy) from its outer edges' displacements,
/// (1/A) ∮ sym(u ⊗ n) ds: an edge on the square's side carries the mean of its nodes' u.
fn mean_strain(model: &adit::model::Model) -> [f64; 3] {
    let (x, u, blocks) = (&model.nodes.pos, &model.nodes.disp, &model.blocks);
    let on_side = |p: [f64; 2], q: [f64; 2]| {
        (0..2).any(|k| (p[k].abs() - HALF).abs() < 1e-9 && (q[k] - p[k]).abs() < 1e-9)
    };
    let mut e = [0.0; 3];
    for [a, b] in blocks.edges.iter().map(|e| e.map(|n| n as usize)) {
        if !on_side(x[a], x[b]) {
            continue;
        }
        // Outward normal × length: the edge turned clockwise (blocks run anticlockwise).
        let n = [x[b][1] - x[a][1], -(x[b][0] - x[a][0])];
        let m = [0.5 * (u[a][0] + u[b][0]), 0.5 * (u[a][1] + u[b][1])];
        e[0] += m[0] * n[0];
        e[1] += m[1] * n[1];
        e[2] += 0.5 * (m[0] * n[1] + m[1] * n[0]);
    }
    e.map(|v| v / (4.0 * HALF * HALF))
}

/// One run: its row and the mean strain's relative error.
pub fn run(sets: &Sets, edge: f64, method: SolveMethod) -> anyhow::Result<CaseReport> {
    let start = Instant::now();
    let sc = scene(sets, edge, method)?;
    let mut b = setup(&sc)?;
    let what = "the jointed square";
    let (cycles, cost) = crate::settle_by_method(&mut b.model, &sc.solve, what)?;
    let wall_s = start.elapsed().as_secs_f64();
    let (got, want) = (mean_strain(&b.model), exact(sets));
    let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let error = (0..3).fold(0.0f64, |m, k| m.max((got[k] - want[k]).abs())) / scale;
    let zones = b.model.zones.len();
    Ok(CaseReport {
        case: format!(
            "sets at {:.0}° and {:.0}°, {} m and {} m apart, zones of {edge} m{}",
            sets.dips[0],
            sets.dips[1],
            sets.spacings[0],
            sets.spacings[1],
            crate::method_suffix(method)
        ),
        zones,
        cycles,
        wall_s,
        zone_cycles_per_s: zones as f64 * cycles as f64 / wall_s,
        h: Some(edge),
        errors: [("mean_strain".to_string(), error)].into(),
        step: None,
        implicit: cost,
    })
}

/// The report's geometries: the jointed tunnel's sets, and sets crossing at 40° to 90°, spaced
/// 1.5 m to 4 m, their origins off the zoning's grid and no joint along a side within the
/// meshing's merge tolerance of it (such a joint is merged into the side: a horizontal set at
/// y = −9.9 m was, and the square strained 3 % less than the exact answer that counts it).
pub fn geometries() -> Vec<Sets> {
    let sets = |dips: [f64; 2], spacings: [f64; 2], origins: [[f64; 2]; 2]| Sets {
        dips,
        spacings,
        origins,
    };
    vec![
        sets([35.0, 110.0], [2.5, 3.0], [[0.4, 0.3], [-0.2, 0.5]]),
        sets([0.0, 90.0], [2.0, 2.5], [[0.3, 0.9], [0.7, -0.2]]),
        sets([16.0, 125.0], [1.77, 1.91], [[-0.5, 0.6], [0.2, -0.8]]),
        sets([30.0, 70.0], [1.5, 2.0], [[0.1, -0.3], [-0.6, 0.4]]),
        sets([62.0, 106.0], [3.6, 2.8], [[0.9, 0.2], [-0.3, -0.7]]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coarse twin of the report's case: the jointed tunnel's two sets in zones of 1 m,
    /// solved implicitly, strain as the smeared rock mass to 1 %.
    #[test]
    fn a_jointed_square_strains_as_its_equivalent_continuum() {
        let r = run(&geometries()[0], 1.0, SolveMethod::Implicit).unwrap();
        eprintln!("{r:?}");
        assert!(r.errors["mean_strain"] < 0.01, "{:?}", r.errors);
    }
}
