//! Supports in whole runs: a bolt across an open joint carries the block hanging on it; bolts and
//! a liner installed at a stage take load only from then on; bad support input is named.

use adit::Scene;
use adit::solve::Quiet;

/// A 2 m × 2 m region cut by a horizontal joint at y = 0 (no tensile strength), the top fixed,
/// gravity on: the lower block (2 m × 1 m, 2700 kg/m³) hangs on one vertical bolt from its base
/// into the upper block.
fn hanging_block() -> Scene {
    let text = r#"{
        "name": "hanging",
        "materials": { "rock": { "density": 2700, "young": 10e9, "poisson": 0.25 } },
        "region": { "polygon": [[-1, -1], [1, -1], [1, 1], [-1, 1]],
                    "edge_names": ["bottom", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.1, "edge_far": 0.2, "grading": 0.2 },
        "joint_materials": { "joint": { "normal_stiffness": 1e11, "shear_stiffness": 1e11, "friction": 30 } },
        "joints": [{ "from": [-1, 0], "to": [1, 0], "material": "joint" }],
        "gravity": [0, -9.81],
        "boundary": [{ "part": "top", "fix": "xy" }],
        "bolts": [{ "name": "bolt", "young": 200e9, "area": 4.9e-4, "yield_force": 2e5,
                    "grout_stiffness": 1e9, "bond_strength": 1e6, "segment": 0.1,
                    "line": { "from": [0, -1], "to": [0, 0.8] } }],
        "solve": { "ratio": 1e-6, "max_cycles": 200000 }
    }"#;
    Scene::from_json(text, "hanging").unwrap()
}

#[test]
fn a_bolt_across_an_open_joint_carries_the_hanging_block() {
    let sc = hanging_block();
    let out = std::env::temp_dir().join("adit_hanging_test");
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    assert_eq!(r.summary.status, "converged", "{:?}", r.summary);
    let c = &r.built.model.supports.cables;
    let weight = 2700.0 * 9.81 * 2.0 * 1.0;
    // The segment crossing the joint (y from −0.0 to 0.1 or −0.1 to 0) carries the weight.
    let s = (0..c.segment.len())
        .find(|&s| {
            let [a, b] = c.segment[s].map(|n| c.pos[n as usize][1]);
            a <= 0.0 && b > 0.0
        })
        .unwrap();
    assert!(
        (c.axial[s] - weight).abs() < 0.03 * weight,
        "bolt force at the joint {} N/m, block weight {weight} N/m",
        c.axial[s]
    );
    // The joint has opened under the block: it carries no tension.
    let contacts = &r.built.model.contacts;
    assert!(contacts.state.iter().all(|s| s.normal <= 1e-6));
}

#[test]
fn without_its_bolt_the_block_falls() {
    let mut sc = hanging_block();
    sc.bolts.clear();
    sc.solve.max_cycles = 20_000;
    let out = std::env::temp_dir().join("adit_falling_test");
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    assert_ne!(r.summary.status, "converged");
    // A mechanism, not a numerical instability.
    let reason = r.summary.reason.unwrap_or_default();
    assert!(!reason.contains("unstable"), "{reason}");
}

#[test]
fn support_input_errors_name_the_field() {
    let bad = |edit: &dyn Fn(&mut serde_json::Value), field: &str| {
        let mut v: serde_json::Value =
            serde_json::from_str(include_str!("../../models/tunnel.json")).unwrap();
        edit(&mut v);
        let err = Scene::from_json(&v.to_string(), "tunnel")
            .unwrap_err()
            .to_string();
        assert!(err.contains(field), "{err}");
    };
    bad(
        &|v| v["bolts"][0]["bond_strength"] = (-1.0).into(),
        "bolts[0].bond_strength",
    );
    bad(
        &|v| v["liners"][0]["excavation"] = "nowhere".into(),
        "liners[0].excavation",
    );
    bad(
        &|v| {
            v["stages"][2]["install"] = serde_json::json!(["crown bolts"]);
            v["stages"][0]["install"] = serde_json::json!(["shotcrete"]);
        },
        "stages[0].install[0]: 'shotcrete' is installed on the wall of 'tunnel' before it is excavated",
    );
    bad(
        &|v| v["stages"][0]["install"] = serde_json::json!(["no such support"]),
        "stages[0].install[0]",
    );
    // A support on a wall that a stage makes must be installed by a stage: one that no stage
    // installs would be there from the start, carrying load in the rock before its wall exists.
    bad(
        &|v| v["stages"][2]["install"] = serde_json::json!(["crown bolts"]),
        "liners[0].name: 'shotcrete' is on the wall of 'tunnel', which stage 'excavate, 25 % support' excavates, but no stage installs it",
    );
    bad(
        &|v| v["stages"][2]["install"] = serde_json::json!(["shotcrete"]),
        "bolts[0].name: 'crown bolts' is on the wall of 'tunnel'",
    );
}

#[test]
fn a_bolt_outside_the_rock_is_an_error() {
    let mut sc = hanging_block();
    sc.bolts[0].line.as_mut().unwrap().to = [0.0, 3.0];
    let err = adit::setup::setup(&sc).err().unwrap().to_string();
    assert!(
        err.contains("bolts[0]") && err.contains("leaves the rock"),
        "{err}"
    );
}

/// The bundled tunnel's 0.15 m of shotcrete (σc 40 MPa) carries a thrust near 9 MN/m, 60 MPa:
/// the run says so, in the summary, its warnings and `liner_capacity.png`, with the least
/// factor of safety of its elements.
#[test]
fn an_overloaded_liner_is_warned_with_its_factor_of_safety() {
    let sc = Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/tunnel.json"
    )))
    .unwrap();
    let out = std::env::temp_dir().join("adit_liner_capacity_test");
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    let liners = &r.built.model.supports.liners;
    let [load] = r.summary.liners.as_slice() else {
        panic!("one liner: {:?}", r.summary.liners)
    };
    let least = (0..liners.element.len())
        .map(|e| liners.safety(e).unwrap().factor())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(load.factor_of_safety, Some(least));
    assert!(least < 1.0 && load.over_capacity.unwrap() > 0, "{load:?}");
    // The largest thrust over the section's area is beyond σc.
    assert!(load.thrust_n / 0.15 > 40e6, "{load:?}");
    let warned = (r.summary.warnings.iter())
        .any(|w| w.starts_with("liner 'shotcrete'") && w.contains("over capacity"));
    assert!(warned, "{:?}", r.summary.warnings);
    assert!(out.join("liner_capacity.png").exists());
}

#[test]
fn liner_strengths_are_checked() {
    let bad = |capacity: serde_json::Value, field: &str| {
        let mut v: serde_json::Value =
            serde_json::from_str(include_str!("../../models/tunnel.json")).unwrap();
        v["liners"][0]["capacity"] = capacity;
        let err = Scene::from_json(&v.to_string(), "tunnel")
            .unwrap_err()
            .to_string();
        assert!(err.contains(field), "{err}");
    };
    bad(
        serde_json::json!({ "compressive_strength": 40e6, "tensile_strength": -1.0 }),
        "liners[0].capacity.tensile_strength",
    );
    bad(
        serde_json::json!({ "compressive_strength": 40e6 }),
        "tensile_strength",
    );
}

/// A ring lining a hole under hydrostatic stress carries no shear and no moment: the pressure it
/// puts on the wall (`walls[..].support_pressure_pa`) is its thrust over its radius (Laplace).
#[test]
fn a_rings_wall_pressure_is_its_thrust_over_its_radius() {
    let mut v: serde_json::Value =
        serde_json::from_str(include_str!("../../models/kirsch.json")).unwrap();
    v["in_situ"] = serde_json::json!({ "sxx": -20e6, "syy": -20e6 });
    v["zoning"] =
        serde_json::json!({ "edge_at_excavation": 0.15, "edge_far": 8.0, "grading": 0.4 });
    v["excavations"][0]["circle"]["segments"] = 48.into();
    v["liners"] = serde_json::json!([{ "name": "ring", "excavation": "tunnel", "young": 30e9,
        "area": 0.15, "inertia": 2.8125e-4 }]);
    v["stages"] = serde_json::json!([
        { "name": "in-situ" },
        { "name": "excavate", "excavate": ["tunnel"], "support_fraction": 0.5 },
        { "name": "lined", "install": ["ring"], "support_fraction": 0.0 }
    ]);
    let sc = Scene::from_json(&v.to_string(), "ring").unwrap();
    let out = std::env::temp_dir().join("adit_ring_pressure_test");
    let r = adit::run_scene(&sc, &out, &mut Quiet).unwrap();
    let walls = &r.summary.stages[2].walls["tunnel"];
    let thrust = r.summary.liners[0].thrust_n;
    let (p, expected) = (walls.support_pressure_pa, thrust / 1.0);
    assert!(
        (p - expected).abs() < 0.01 * expected,
        "{p} against {expected}"
    );
    assert!((walls.support_pressure_ratio - p / 20e6).abs() < 1e-12);
    // Before the liner is installed it puts nothing on the wall.
    assert_eq!(r.summary.stages[1].walls["tunnel"].support_pressure_pa, 0.0);
}
