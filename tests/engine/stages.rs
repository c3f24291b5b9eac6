//! Staged runs: a tunnel filled with rock until its stage, excavation releasing the wall, a
//! support pressure lowered stage by stage, displacements reset, one output step per stage.

use crate::common;

use adit::Scene;
use adit::solve::Quiet;

fn scene() -> Scene {
    Scene::from_json(common::STAGED_TUNNEL, "staged").unwrap()
}

/// Run `sc` into a fresh temporary folder named `folder`; every stage must converge.
fn run_converged(sc: &Scene, folder: &str) -> adit::RunResult {
    let out = std::env::temp_dir().join(folder);
    let _ = std::fs::remove_dir_all(&out);
    let r = adit::run_scene(sc, &out, &mut Quiet).unwrap();
    let stages = &r.summary.stages;
    assert!(
        stages.iter().all(|s| s.status == "converged"),
        "{folder}: {stages:?}"
    );
    r
}

#[test]
fn staged_excavation_releases_the_wall_stage_by_stage() {
    let sc = scene();
    let out = std::env::temp_dir().join("adit_staged_test");
    let _ = std::fs::remove_dir_all(&out);
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    let stages = &r.summary.stages;
    assert_eq!(stages.len(), 3);
    assert!(stages.iter().all(|s| s.status == "converged"), "{stages:?}");
    let pvd = std::fs::read_to_string(out.join("staged.pvd")).unwrap();
    assert_eq!(pvd.matches("_zones_").count(), 3, "{pvd}");
    // The ground reaction curve: closure grows as the support is lowered (elastic: linear).
    let grc = std::fs::read_to_string(out.join("ground_reaction.csv")).unwrap();
    let rows: Vec<&str> = grc.lines().collect();
    assert_eq!(
        rows[0],
        "stage,support_fraction,closure_tunnel_m,tunnel_crown_m,tunnel_invert_m,\
         tunnel_left_wall_m,tunnel_right_wall_m,tunnel_span_convergence_m,\
         tunnel_height_convergence_m,tunnel_support_pressure_pa"
    );
    assert_eq!(rows.len(), 4, "{grc}");
    // The wall moves per stage are the summary's (issue 49: not only the mean closure).
    let last: Vec<&str> = rows[3].split(',').collect();
    let crown: f64 = last[3].parse().unwrap();
    assert_eq!(crown, stages[2].walls["tunnel"].crown_m);
    let span: f64 = last[7].parse().unwrap();
    assert!(span > 0.0 && span == stages[2].walls["tunnel"].span_convergence_m);
    let (half, none) = (stages[1].closure["tunnel"], stages[2].closure["tunnel"]);
    assert!(
        half > 0.0 && (none / half - 2.0).abs() < 0.05,
        "{half} {none}"
    );
    // Elastic wall displacement: −Δp a/(2G) for the pressure released, Δp = 10 MPa in all.
    let m = &r.built.model;
    let g = 10e9 / 2.5;
    let wall: Vec<u32> = r.built.plan.boundary.part_nodes["tunnel"]
        .iter()
        .copied()
        .filter(|&n| !m.blocks.is_removed(m.blocks.block_of_node(n)))
        .collect();
    let u = wall
        .iter()
        .map(|&n| {
            let (p, d) = (m.nodes.pos[n as usize], m.nodes.disp[n as usize]);
            (d[0] * p[0] + d[1] * p[1]) / p[0].hypot(p[1])
        })
        .sum::<f64>()
        / wall.len() as f64;
    let exact = -10e6 / (2.0 * g);
    assert!((u - exact).abs() < 0.03 * exact.abs(), "{u} vs {exact}");
    // The excavated zones carry no stress.
    let null = m.materials.null.unwrap();
    let excavated: Vec<usize> = (0..m.zones.len())
        .filter(|&z| m.zones.material[z] == null)
        .collect();
    assert!(!excavated.is_empty());
    assert!(excavated.iter().all(|&z| m.zones.stress[z] == [0.0; 4]));
}

#[test]
fn reset_displacements_measures_from_the_stage() {
    let mut sc = scene();
    sc.stages[2].reset_displacements = true;
    let out = std::env::temp_dir().join("adit_staged_reset_test");
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    let nodes = &r.built.model.nodes;
    // The origin is the displacement at the end of stage 2, which is not zero at the wall.
    assert!(nodes.origin.iter().any(|o| o[0] != 0.0 || o[1] != 0.0));
}

#[test]
fn a_stage_naming_an_unknown_excavation_is_an_error() {
    let bad = r#"{
        "name": "s", "materials": { "rock": { "density": 2500, "young": 1e9, "poisson": 0.2 } },
        "region": { "polygon": [[0, 0], [10, 0], [10, 10], [0, 10]], "material": "rock" },
        "zoning": { "edge_at_excavation": 1, "edge_far": 2 },
        "stages": [{ "name": "dig", "excavate": ["adit"] }]
    }"#;
    let err = Scene::from_json(bad, "s").unwrap_err().to_string();
    assert_eq!(err, "stages[0].excavate[0]: no excavation named 'adit'");
}

/// The tunnel model (the README's main job) runs through its stages to equilibrium: its rock
/// yields around the opening, and the bolts and shotcrete installed after partial relaxation
/// take load.
#[test]
fn tunnel_model_converges_through_its_stages() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models/tunnel.json");
    let sc = Scene::load(&path).unwrap();
    let out = std::env::temp_dir().join("adit_tunnel_model_test");
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    assert!(
        r.summary.stages.iter().all(|s| s.status == "converged"),
        "{:?}",
        r.summary.stages
    );
    let yielded = r
        .built
        .model
        .zones
        .state
        .iter()
        .filter(|&&s| s & 4 != 0)
        .count();
    assert!(yielded > 100, "{yielded} zones yielded in shear");
    // The supports went in at the third stage and carry load; they hold the wall in.
    let m = &r.built.model.supports;
    assert!(m.cables.active.iter().chain(&m.liners.active).all(|&a| a));
    let loads = m.loads();
    assert!(loads.bolt_force > 50e3 / 1.5, "{loads:?}");
    assert!(loads.liner_thrust > 1e6, "{loads:?}");
    let closure = |i: usize| r.summary.stages[i].closure["tunnel"];
    assert!(
        closure(2) > closure(1) && closure(2) < 0.02,
        "{:?}",
        r.summary.stages
    );
    assert!(out.join("tunnel_supports_0002.vtu").exists());
}

/// `support_fraction` acts on an excavation that is open from the start (no stage excavates it):
/// half the in-situ traction left on the wall halves the elastic closure, and the summary says so.
#[test]
fn support_fraction_holds_an_excavation_open_from_the_start() {
    let mut sc = scene();
    sc.stages = vec![
        serde_json::from_value(serde_json::json!({ "name": "half", "support_fraction": 0.5 }))
            .unwrap(),
        serde_json::from_value(serde_json::json!({ "name": "none", "support_fraction": 0.0 }))
            .unwrap(),
    ];
    let out = std::env::temp_dir().join("adit_open_support_test");
    let _ = std::fs::remove_dir_all(&out);
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    let stages = &r.summary.stages;
    assert_eq!(stages[0].support_fraction, 0.5);
    let (half, none) = (stages[0].closure["tunnel"], stages[1].closure["tunnel"]);
    // Elastic closure of the wall: Δp a/(2G) with Δp = 5 and then 10 MPa, G = 4 GPa.
    let full = 10e6 * 1.0 / (2.0 * 4e9);
    assert!(
        (half / (0.5 * full) - 1.0).abs() < 0.05,
        "{half} vs {}",
        0.5 * full
    );
    assert!((none / full - 1.0).abs() < 0.05, "{none} vs {full}");
}

/// A block on a 30° slope (gravity tilted) settles on a joint that cannot slip; the next stage gives
/// the joint a friction angle below the slope and the block slides; a stage naming an unknown joint
/// material is an error naming it.
#[test]
fn a_stage_changes_a_joint_material() {
    let a = 30f64.to_radians();
    let text = format!(
        r#"{{
        "name": "slope",
        "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
        "region": {{ "polygon": [[0, 0], [4, 0], [4, 1], [2, 1], [2, 1.5], [1, 1.5], [1, 1], [0, 1]],
                    "edge_names": ["bottom", "e1", "e2", "e3", "e4", "e5", "e6", "e7"], "material": "rock" }},
        "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
        "joint_materials": {{ "plane": {{ "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": 80 }} }},
        "joints": [{{ "from": [1, 1], "to": [2, 1], "material": "plane" }}],
        "gravity": [{gx}, {gy}],
        "boundary": [{{ "part": "bottom", "fix": "xy" }}],
        "solve": {{ "ratio": 1e-6, "max_cycles": 20000 }},
        "stages": [
            {{ "name": "settle" }},
            {{ "name": "weaken", "joint_materials": {{ "plane": {{ "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": 20 }} }} }}
        ]
    }}"#,
        gx = 9.81 * a.sin(),
        gy = -9.81 * a.cos()
    );
    let sc = Scene::from_json(&text, "slope").unwrap();
    let out = std::env::temp_dir().join("adit_joint_change_test");
    let _ = std::fs::remove_dir_all(&out);
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    let stages = &r.summary.stages;
    assert_eq!(stages[0].status, "converged", "{stages:?}");
    // Sliding: no equilibrium, and the block has moved down the slope by far more than the
    // elastic settling.
    assert_ne!(stages[1].status, "converged", "{stages:?}");
    let m = &r.built.model;
    let top = (0..m.nodes.len())
        .filter(|&n| m.nodes.pos[n][1] > 1.4)
        .map(|n| m.nodes.disp[n][0])
        .fold(f64::INFINITY, f64::min);
    assert!(top > 1e-3, "the block moved {top} m down the slope");

    let bad = text.replace(
        r#""weaken", "joint_materials": { "plane""#,
        r#""weaken", "joint_materials": { "nope""#,
    );
    let msg = Scene::from_json(&bad, "slope").unwrap_err().to_string();
    assert!(
        msg.contains("stages[1].joint_materials.nope: no joint material named 'nope'"),
        "{msg}"
    );
}

/// Gravity turned on by a stage loads a column of three blocks with its weight: the normal force
/// across each joint is the weight above it, for deformable blocks (zone weights at the nodes) and
/// rigid ones (block weights).
#[test]
fn a_stage_turns_gravity_on() {
    for mode in ["deformable", "rigid"] {
        let text = format!(
            r#"{{
            "name": "column",
            "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
            "region": {{ "polygon": [[0, 0], [1, 0], [1, 3], [0, 3]], "edge_names": ["base", "right", "top", "left"],
                        "material": "rock" }},
            "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
            "joint_materials": {{ "bedding": {{ "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": 30 }} }},
            "joint_sets": [{{ "dip": 0, "spacing": 1, "material": "bedding" }}],
            "blocks": {{ "mode": "{mode}" }},
            "boundary": [{{ "part": "base", "fix": "xy" }}, {{ "part": "left", "fix": "x" }}, {{ "part": "right", "fix": "x" }}],
            "solve": {{ "ratio": 1e-7 }},
            "stages": [ {{ "name": "weightless" }}, {{ "name": "gravity on", "gravity": [0, -9.81] }} ]
        }}"#
        );
        let sc = Scene::from_json(&text, "column").unwrap();
        let r = run_converged(&sc, &format!("adit_gravity_stage_{mode}"));
        let (m, c) = (&r.built.model, &r.built.model.contacts);
        for (joint_y, depth) in [(1.0, 2.0), (2.0, 1.0)] {
            let force: f64 = (0..c.len())
                .filter(|&k| (m.nodes.pos[c.node[k] as usize][1] - joint_y).abs() < 1e-9)
                .map(|k| c.state[k].normal * c.length[k])
                .sum();
            let weight = 2500.0 * 9.81 * depth;
            assert!(
                (-force / weight - 1.0).abs() < 0.02,
                "{mode}: joint at {joint_y}: {force} N/m against {weight}"
            );
        }
    }
}

/// A stage can weaken the rock: the elastic rock around the open tunnel becomes Mohr–Coulomb and
/// yields; a stage cannot change a density, nor name a material the scene does not have.
#[test]
fn a_stage_changes_a_zone_material() {
    let mut sc = scene();
    sc.stages = vec![
        serde_json::from_value(serde_json::json!({ "name": "elastic" })).unwrap(),
        serde_json::from_value(
            serde_json::json!({ "name": "weakened", "materials": { "rock": {
            "density": 2500, "young": 10e9, "poisson": 0.25, "law": "mohr_coulomb",
            "cohesion": 2e6, "friction": 30 } } }),
        )
        .unwrap(),
    ];
    let r = run_converged(&sc, "adit_material_stage_test");
    let stages = &r.summary.stages;
    let yielded = r
        .built
        .model
        .zones
        .state
        .iter()
        .filter(|&&s| s != 0)
        .count();
    assert!(yielded > 0, "no zone yielded after weakening");
    assert!(
        stages[1].closure["tunnel"] > 1.2 * stages[0].closure["tunnel"],
        "{stages:?}"
    );
    let mut v: serde_json::Value = serde_json::json!({ "name": "heavier", "materials": { "rock": {
        "density": 3000, "young": 10e9, "poisson": 0.25 } } });
    // Through the loader, as a user's file would be.
    let text = |stages: &serde_json::Value| {
        let mut s: serde_json::Value = serde_json::from_str(common::STAGED_TUNNEL).unwrap();
        s["stages"] = serde_json::json!([stages]);
        s.to_string()
    };
    let msg = Scene::from_json(&text(&v), "t").unwrap_err().to_string();
    assert!(
        msg.starts_with("stages[0].materials.rock.density: a stage cannot change the density"),
        "{msg}"
    );
    v["materials"] =
        serde_json::json!({ "granite": { "density": 2500, "young": 1e9, "poisson": 0.2 } });
    let msg = Scene::from_json(&text(&v), "t").unwrap_err().to_string();
    assert!(
        msg.starts_with("stages[0].materials.granite: no material named 'granite'"),
        "{msg}"
    );
}

/// A stage replaces the boundary conditions: a block held fixed on every side under 10 MPa is put
/// on rollers (left, base) with the in-situ stress as traction on the other two sides, and nothing
/// moves; a later stage lowers the stress on the right to 5 MPa and the block stretches by the
/// plane-strain Δσ (1 − ν²) L / E; held fixed again, it stays where it is.
#[test]
fn a_stage_switches_a_boundary_from_fixed_to_stress() {
    let stages = [
        r#"{ "name": "held" }"#,
        r#"{ "name": "on stress", "boundary": [ { "part": "left", "fix": "x" }, { "part": "base", "fix": "y" },
             { "part": "right", "normal_stress": -10e6 }, { "part": "top", "in_situ_traction": true } ] }"#,
        r#"{ "name": "unload", "boundary": [ { "part": "left", "fix": "x" }, { "part": "base", "fix": "y" },
             { "part": "right", "normal_stress": -5e6 }, { "part": "top", "normal_stress": -10e6 } ] }"#,
        r#"{ "name": "held again", "boundary": [ { "part": "outer", "fix": "xy" } ] }"#,
    ];
    let run = |count: usize| {
        let text = format!(
            r#"{{
            "name": "box",
            "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
            "region": {{ "polygon": [[0, 0], [2, 0], [2, 1], [0, 1]], "edge_names": ["base", "right", "top", "left"],
                        "material": "rock" }},
            "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
            "in_situ": {{ "sxx": -10e6, "syy": -10e6 }},
            "boundary": [{{ "part": "outer", "fix": "xy" }}],
            "solve": {{ "ratio": 1e-8 }},
            "stages": [{}]
        }}"#,
            stages[..count].join(",")
        );
        let sc = Scene::from_json(&text, "box").unwrap();
        let r = run_converged(&sc, &format!("adit_boundary_stage_{count}"));
        let m = &r.built.model.nodes;
        let right: Vec<f64> = (0..m.len())
            .filter(|&n| m.pos[n][0] == 2.0)
            .map(|n| m.disp[n][0])
            .collect();
        let largest = m.disp.iter().map(|u| u[0].hypot(u[1])).fold(0.0, f64::max);
        (right.iter().sum::<f64>() / right.len() as f64, largest)
    };
    let (_, at_rest) = run(2);
    assert!(
        at_rest < 1e-9,
        "moved {at_rest} m on its own in-situ traction"
    );
    let stretch = 5e6 * (1.0 - 0.25f64.powi(2)) * 2.0 / 10e9;
    let (unloaded, _) = run(3);
    assert!(
        (unloaded / stretch - 1.0).abs() < 0.01,
        "{unloaded} m against {stretch} m"
    );
    let (held, _) = run(4);
    assert!(
        (held - unloaded).abs() < 1e-3 * stretch,
        "{held} m after {unloaded} m"
    );
}

/// A rigid block's fixities are folded into its constraint once: a stage that changes them is an
/// error naming the field; a stage that changes only loads on it is fine.
#[test]
fn a_stage_cannot_change_the_fixity_of_a_rigid_block() {
    let text = |boundary: &str| {
        format!(
            r#"{{
            "name": "rigid",
            "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }} }},
            "region": {{ "polygon": [[0, 0], [1, 0], [1, 2], [0, 2]], "edge_names": ["base", "right", "top", "left"],
                        "material": "rock" }},
            "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
            "joint_materials": {{ "bedding": {{ "normal_stiffness": 1e10, "shear_stiffness": 1e10, "friction": 30 }} }},
            "joint_sets": [{{ "dip": 0, "spacing": 1, "material": "bedding" }}],
            "blocks": {{ "mode": "rigid" }},
            "boundary": [{{ "part": "base", "fix": "xy" }}],
            "stages": [ {{ "name": "first" }}, {{ "name": "second", "boundary": {boundary} }} ]
        }}"#
        )
    };
    let freed = Scene::from_json(&text(r#"[{ "part": "left", "fix": "x" }]"#), "rigid").unwrap();
    let msg = adit::setup::setup(&freed)
        .err()
        .expect("refused")
        .to_string();
    assert!(
        msg.starts_with("stages[1].boundary: changes the fixity"),
        "{msg}"
    );
    let loaded =
        text(r#"[{ "part": "base", "fix": "xy" }, { "part": "top", "normal_stress": -1e5 }]"#);
    let sc = Scene::from_json(&loaded, "rigid").unwrap();
    assert!(adit::setup::setup(&sc).is_ok());
    let bad = text(r#"[{ "part": "nowhere", "fix": "x" }]"#);
    let msg = Scene::from_json(&bad, "rigid")
        .expect_err("refused")
        .to_string();
    assert!(msg.contains("stages[1].boundary[0].part"), "{msg}");
}

/// A stage gives the top block of a confined column of three another material (UDEC's
/// `change mat` over a range) and loads the column: it shortens by σ h / M per block with
/// M = E(1 − ν)/((1 + ν)(1 − 2ν)) of each block's material, plus σ/kn per joint. A region
/// reaching a block of another density, or naming no material, is refused naming the field.
#[test]
fn a_stage_gives_a_region_another_material() {
    let text = |region: &str| {
        format!(
            r#"{{
            "name": "column",
            "materials": {{ "rock": {{ "density": 2500, "young": 10e9, "poisson": 0.25 }},
                            "stiff": {{ "density": 2500, "young": 40e9, "poisson": 0.25 }},
                            "heavy": {{ "density": 3000, "young": 40e9, "poisson": 0.25 }} }},
            "region": {{ "polygon": [[0, 0], [1, 0], [1, 3], [0, 3]], "edge_names": ["base", "right", "top", "left"],
                        "material": "rock" }},
            "zoning": {{ "edge_at_excavation": 0.25, "edge_far": 0.25 }},
            "joint_materials": {{ "bedding": {{ "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": 30 }} }},
            "joint_sets": [{{ "dip": 0, "spacing": 1, "material": "bedding" }}],
            "boundary": [{{ "part": "base", "fix": "y" }}, {{ "part": "left", "fix": "x" }}, {{ "part": "right", "fix": "x" }}],
            "solve": {{ "ratio": 1e-8 }},
            "stages": [ {{ "name": "as built" }},
                        {{ "name": "stiff top, loaded", "regions": [{region}],
                           "boundary": [{{ "part": "base", "fix": "y" }}, {{ "part": "left", "fix": "x" }},
                                        {{ "part": "right", "fix": "x" }}, {{ "part": "top", "normal_stress": -1e6 }}] }} ]
        }}"#
        )
    };
    let sc = Scene::from_json(
        &text(r#"{ "at": [0.5, 2.5], "material": "stiff" }"#),
        "column",
    )
    .unwrap();
    let r = run_converged(&sc, "adit_region_stage");
    let m = &r.built.model.nodes;
    let top: Vec<f64> = (0..m.len())
        .filter(|&n| m.pos[n][1] == 3.0)
        .map(|n| -m.disp[n][1])
        .collect();
    let settlement = top.iter().sum::<f64>() / top.len() as f64;
    let modulus = |e: f64| e * 0.75 / (1.25 * 0.5);
    let exact = 1e6 * (2.0 / modulus(10e9) + 1.0 / modulus(40e9) + 2.0 / 1e11);
    assert!(
        (settlement / exact - 1.0).abs() < 5e-3,
        "{settlement} m against {exact} m"
    );
    let heavy = Scene::from_json(
        &text(r#"{ "polygon": [[0, 2], [1, 2], [1, 3], [0, 3]], "material": "heavy" }"#),
        "column",
    )
    .unwrap();
    let msg = adit::setup::setup(&heavy)
        .err()
        .expect("refused")
        .to_string();
    assert!(
        msg.starts_with("stages[1].regions[0].material: 'heavy' has density 3000"),
        "{msg}"
    );
    let unknown = text(r#"{ "at": [0.5, 2.5], "material": "granite" }"#);
    let msg = Scene::from_json(&unknown, "column")
        .expect_err("refused")
        .to_string();
    assert!(
        msg.contains("stages[1].regions[0].material: no material named 'granite'"),
        "{msg}"
    );
}
