//! `summary.json`'s `reactions`: the force each fixing boundary condition in force at the end of a
//! run exerts on the model, as UDEC and FLAC report the reactions of fixed gridpoints. A platen's
//! load is read here; so is a point fixity's, which only holds a model against rigid motion when
//! it carries next to nothing (`docs/scene-format.md`, `boundary[i]`).

use serde::Serialize;

use crate::cycle::Cycle;
use crate::model::{BODY, FIX_X, FIX_Y, Model};
use crate::scene::{BoundaryCondition, Scene};
use crate::setup::{Plan, boundary_effect};

/// What one fixing condition holds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reaction {
    /// The condition, as the scene names it (`boundary[3]`, `stages[2].boundary[0]`).
    pub condition: String,
    /// Nodes it fixes, those of deformable blocks (a rigid or simple block's fixities act
    /// through its constraint and are left out), shared ones included.
    pub nodes: usize,
    /// Total force its fixities exert on the model, N/m: at each fixed node, in each component it
    /// fixes, the negative of the force the rest of the model and the applied loads put there
    /// (the support's reaction; 0 in a component it leaves free).
    pub force: [f64; 2],
}

/// The conditions in force after the stage `last` of `scene` (the last of that stage and those
/// before it to give a list, else the top-level `boundary`), with the scene's path of the list.
fn in_force(scene: &Scene, last: usize) -> (&[BoundaryCondition], String) {
    let staged = (scene.stages.iter().enumerate().take(last + 1).rev())
        .find_map(|(i, s)| s.boundary.as_deref().map(|list| (list, i)));
    match staged {
        Some((list, i)) => (list, format!("stages[{i}].boundary")),
        None => (&scene.boundary, "boundary".into()),
    }
}

/// The reaction of each fixing condition in force after stage `last`, from the forces `cycle`
/// last computed on `model`, in the scene's order. A component of a node that two conditions fix
/// (a corner of two fixed edges) counts in the first, so that the reactions add up to the force
/// all the fixities exert.
pub fn reactions(
    scene: &Scene,
    plan: &Plan,
    model: &Model,
    cycle: &Cycle,
    last: usize,
) -> anyhow::Result<Vec<Reaction>> {
    let (list, path) = in_force(scene, last);
    let mut out = Vec::new();
    // The components counted so far, per node.
    let mut counted = vec![0u8; model.nodes.len()];
    for (k, bc) in list.iter().enumerate() {
        if bc.fix.is_none() {
            continue;
        }
        let one = std::slice::from_ref(bc);
        let (fixed, _) =
            boundary_effect(one, &path, &plan.boundary, &plan.in_situ, &model.nodes.pos)?;
        let (mut nodes, mut force) = (0, [0.0; 2]);
        for (n, &flags) in fixed.iter().enumerate() {
            if flags == 0 || model.nodes.fixed[n] & BODY != 0 {
                continue;
            }
            nodes += 1;
            let f = cycle.node_force(model, n);
            for (d, flag) in [(0, FIX_X), (1, FIX_Y)] {
                if flags & flag != 0 && model.nodes.fixed[n] & flag & !counted[n] != 0 {
                    force[d] -= f[d];
                    counted[n] |= flag;
                }
            }
        }
        out.push(Reaction {
            condition: format!("{path}[{k}]"),
            nodes,
            force,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use crate::Scene;

    /// Net reaction of a run of `text`, N/m, and its reactions' conditions.
    fn net(text: &str, name: &str) -> ([f64; 2], Vec<String>) {
        let scene = Scene::from_json(text, name).unwrap();
        let out = std::env::temp_dir().join(format!("adit-test-reactions-{name}"));
        let r = crate::run_scene(&scene, &out, &mut crate::solve::Quiet).unwrap();
        let _ = std::fs::remove_dir_all(&out);
        assert_eq!(r.summary.status, "converged", "{name}");
        let sum = |d: usize| r.summary.reactions.iter().map(|x| x.force[d]).sum();
        let names = r.summary.reactions.iter().map(|x| x.condition.clone());
        ([sum(0), sum(1)], names.collect())
    }

    /// A 4 m × 10 m column of rock (ρ = 2 500 kg/m³, g = 10 m/s², ν = 0.25) on a base on
    /// rollers between rollers carries its weight, 1 MN/m, on its base, and its sides the
    /// uniaxial strain's lateral stress, ν/(1 − ν) ρ g H²/2 = 416.7 kN/m each.
    /// Then a box under the in-situ stress of that rock (its gradient exactly ρ g) on its sides,
    /// held by four rollers, whose staged tunnel is dug in a later stage with the list of
    /// fixities changed: what is left weighs less than the sides carry by the rock dug out, ρ g
    /// times the tunnel polygon's area, and the rollers carry that.
    #[test]
    fn the_fixities_carry_the_weight_the_loads_leave() {
        let rock = r#""materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
                      "gravity": [0, -10], "solve": { "method": "implicit", "ratio": 1e-10 }"#;
        let column = format!(
            r#"{{ "name": "c", {rock},
              "region": {{ "polygon": [[0, 0], [4, 0], [4, 10], [0, 10]],
                           "edge_names": ["base", "right", "top", "left"], "material": "rock" }},
              "zoning": {{ "edge_at_excavation": 1, "edge_far": 1 }},
              "boundary": [{{ "part": "base", "fix": "y" }}, {{ "part": "left", "fix": "x" }},
                           {{ "part": "right", "fix": "x" }}] }}"#
        );
        let scene = Scene::from_json(&column, "c").unwrap();
        let out = std::env::temp_dir().join("adit-test-reactions-column");
        let r = crate::run_scene(&scene, &out, &mut crate::solve::Quiet).unwrap();
        let _ = std::fs::remove_dir_all(&out);
        let f: Vec<[f64; 2]> = r.summary.reactions.iter().map(|x| x.force).collect();
        assert!((f[0][1] / 1e6 - 1.0).abs() < 1e-9, "{f:?}");
        assert!((f[0][0] + f[1][0] + f[2][0]).abs() < 1e-3, "{f:?}");
        let lateral = 2500.0 * 10.0 * 50.0 / 3.0;
        assert!((f[1][0] / lateral - 1.0).abs() < 5e-3, "{f:?}");
        assert!((f[2][0] / lateral + 1.0).abs() < 5e-3, "{f:?}");

        let tunnel = format!(
            r#"{{ "name": "t", {rock},
              "region": {{ "polygon": [[-10, -10], [10, -10], [10, 10], [-10, 10]], "material": "rock" }},
              "excavations": [{{ "name": "t", "circle": {{ "center": [0, 0], "radius": 1, "segments": 16 }} }}],
              "zoning": {{ "edge_at_excavation": 0.5, "edge_far": 2 }},
              "in_situ": {{ "sxx": -5e6, "syy": -5e6, "gradient": {{ "sxx": 25000, "syy": 25000 }} }},
              "boundary": [{{ "part": "outer", "in_situ_traction": true }},
                           {{ "at": [10, 0], "fix": "y" }}, {{ "at": [-10, 0], "fix": "y" }},
                           {{ "at": [0, 10], "fix": "x" }}, {{ "at": [0, -10], "fix": "x" }}],
              "stages": [{{ "name": "in situ" }},
                         {{ "name": "dig", "excavate": ["t"],
                            "boundary": [{{ "part": "outer", "in_situ_traction": true }},
                                         {{ "at": [-10, 0], "fix": "xy" }}, {{ "at": [10, 0], "fix": "y" }}] }}] }}"#
        );
        let ([fx, fy], names) = net(&tunnel, "t");
        let area = 8.0 * (std::f64::consts::PI / 8.0).sin();
        assert_eq!(names, ["stages[1].boundary[1]", "stages[1].boundary[2]"]);
        assert!(
            fx.abs() < 1e-3 && (fy / (-25000.0 * area) - 1.0).abs() < 1e-9,
            "{fx} {fy}"
        );
    }
}
