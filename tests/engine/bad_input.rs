//! Bad, huge and odd input (issue 15): one clear `error:` line naming the field and the limit,
//! before anything large is built, and never a panic, an abort or a hang.

use crate::common;

use std::process::{Command, Stdio};
use std::time::Duration;

use serde_json::{Value, json};

fn model(name: &str) -> Value {
    let path = format!("{}/models/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// `adit check` on `text`: exit code (None: killed after 60 s) and stderr.
fn check_text(text: &str, tag: &str) -> (Option<i32>, String) {
    // Tests run in parallel in one process and may check under the same tag.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!(
        "adit-bad-input-{tag}-{}-{call}.json",
        std::process::id()
    ));
    std::fs::write(&path, text).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_adit"))
        .args(["check", path.to_str().unwrap()])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (code, err) = common::wait_at_most(child, Duration::from_secs(60));
    std::fs::remove_file(&path).unwrap();
    (code, err)
}

/// `adit check` of `scene` must fail at once with one error line starting `error: {field}`.
fn refused(scene: &Value, field: &str) -> String {
    let (code, err) = check_text(&scene.to_string(), &field.replace(['[', ']', '.'], "_"));
    assert_eq!(code, Some(1), "{field}: {err}");
    assert!(
        err.starts_with(&format!("error: {field}")),
        "{field}: {err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    err
}

#[test]
fn huge_counts_are_refused_naming_the_field() {
    let tunnel = model("tunnel");
    // Set the field at `pointer` (its parent must exist).
    let with = |pointer: &str, v: Value| {
        let mut s = tunnel.clone();
        let (parent, key) = pointer.rsplit_once('/').unwrap();
        s.pointer_mut(parent).unwrap()[key] = v;
        s
    };
    let max = json!(u64::MAX);
    refused(
        &with("/excavations/0/horseshoe/segments", max.clone()),
        "excavations[0].horseshoe.segments",
    );
    refused(
        &with("/excavations/0/horseshoe/segments", json!(9e15 as u64)),
        "excavations[0].horseshoe.segments",
    );
    refused(
        &with("/bolts/0/pattern/count", max),
        "bolts[0].pattern.count",
    );
    refused(
        &with("/bolts/0/pattern/count", json!(1_000_000)),
        "bolts[0].pattern.count",
    );
    refused(&with("/joint_sets/0/spacing", json!(1e-9)), "joint_sets[0]");
    refused(
        &with("/joint_sets/0/spread_spacing", json!(1e300)),
        "joint_sets[0]",
    );
    refused(&with("/bolts/0/segment", json!(1e-12)), "bolts[0].segment");
    refused(&with("/bolts/0/segment", json!(1e-6)), "bolts[0].segment");
    refused(
        &with("/bolts/0/pattern/length", json!(9e15)),
        "bolts[0].pattern.length",
    );
    let err = refused(
        &with("/zoning/edge_at_excavation", json!(1e-6)),
        "zoning.max_zones",
    );
    assert!(err.contains("raise `zoning.max_zones`"), "{err}");
    let mut grains = tunnel.clone();
    grains["voronoi"] = json!({ "size": 1e-160, "material": "joint" });
    refused(&grains, "voronoi.size");
    let mut kirsch = model("kirsch");
    kirsch["excavations"][0]["circle"]["segments"] = json!(100_000_000);
    refused(&kirsch, "excavations[0].circle.segments");
    // A region traced from a terrain model may have 200 000 vertices, not more.
    let mut terrain = model("kirsch");
    let ring: Vec<[f64; 2]> = (0..200_001)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 200_001.0;
            [40.0 * t.cos(), 40.0 * t.sin()]
        })
        .collect();
    terrain["region"] = json!({ "polygon": ring, "material": "rock" });
    let err = refused(&terrain, "region.polygon");
    assert!(err.contains("limit of 200000"), "{err}");
}

#[test]
fn an_edge_longer_than_the_region_builds() {
    let mut s = model("kirsch");
    // (1e308 is refused now, beyond the 1e30 any number of a scene may reach.)
    s["zoning"]["edge_far"] = json!(1e30);
    let (code, err) = check_text(&s.to_string(), "edge-far");
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn names_mean_one_thing_and_are_safe_in_files() {
    let tunnel = model("tunnel");
    let mut outer = tunnel.clone();
    outer["excavations"][0]["name"] = json!("outer");
    let err = refused(&outer, "excavations[0].name");
    assert!(
        err.contains("already names the whole outer boundary"),
        "{err}"
    );
    let mut edge = tunnel.clone();
    edge["excavations"][0]["name"] = json!("right");
    refused(&edge, "excavations[0].name");
    for bad in ["..", ".", "a\"<b", &"x".repeat(300)] {
        let mut s = tunnel.clone();
        s["name"] = json!(bad);
        refused(&s, "name");
    }
    let text = tunnel.to_string().replacen(
        "\"materials\":{",
        "\"materials\":{\"rock\":{\"density\":1,\"young\":1,\"poisson\":0.2},",
        1,
    );
    let (code, err) = check_text(&text, "duplicate");
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("`rock` is defined twice") && err.contains("line 1"),
        "{err}"
    );
}

#[test]
fn a_byte_order_mark_is_not_an_error_and_bad_utf8_has_a_position() {
    let text = format!("\u{feff}{}", model("kirsch"));
    let (code, err) = check_text(&text, "bom");
    assert_eq!(code, Some(0), "{err}");
    let path = std::env::temp_dir().join(format!("adit-latin1-{}.json", std::process::id()));
    std::fs::write(&path, b"{\n \"name\": \"caf\xe9\" }").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_adit"))
        .args(["check", path.to_str().unwrap()])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(err.contains("line 2, column 14: not UTF-8"), "{err}");
    std::fs::remove_file(&path).unwrap();
}

/// `adit check s.json | head -1`: the reader goes away; adit ends quietly instead of panicking.
#[test]
fn a_closed_pipe_is_not_a_panic() {
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/models/kirsch.json");
    let mut child = Command::new(env!("CARGO_BIN_EXE_adit"))
        .args(["check", model])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// `check` builds what `run` builds before solving: a bolt that leaves the rock is refused there.
#[test]
fn check_refuses_what_run_refuses() {
    let mut s = model("kirsch");
    s["bolts"] = json!([{ "name": "probe", "young": 200e9, "area": 4.9e-4, "yield_force": 200e3,
        "grout_stiffness": 2e9, "bond_strength": 3e5, "out_of_plane_spacing": 1.0,
        "line": { "from": [0, 0], "to": [0, 5] } }]);
    let err = refused(&s, "bolts[0]");
    assert!(err.contains("leaves the rock"), "{err}");
}

/// A zone sharper than `zoning.accept_angle` that no joint makes (a region with a 2.9° corner) is
/// refused naming the field and where; one a joint makes is repaired instead: the tunnel's joints
/// make zones of 15° (joint set 1 meets the region's sides at 15°), and asked for 20° the pieces
/// of joint beside them are dropped with a warning naming their set. An accept angle at or above
/// `min_angle` is refused.
#[test]
fn sharp_zones_are_refused_unless_a_joint_piece_makes_them() {
    let wedge = json!({
        "name": "wedge",
        "materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [10, 0], [10, 0.5]], "material": "rock" },
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 0.25, "accept_angle": 5 }
    });
    let err = refused(&wedge, "zoning.accept_angle");
    assert!(err.contains("near ("), "{err}");
    let mut s = model("tunnel");
    s["zoning"]["accept_angle"] = json!(20);
    let scene = adit::Scene::from_json(&s.to_string(), "tunnel").unwrap();
    let built = adit::setup::setup(&scene).unwrap();
    assert!(
        built
            .warnings
            .iter()
            .any(|w| w.starts_with("joint_sets[") && w.contains("dropped the piece")),
        "{:?}",
        built.warnings
    );
    assert!(
        built.mesh.min_angle_deg >= 20.0,
        "{}",
        built.mesh.min_angle_deg
    );
    s["zoning"]["accept_angle"] = json!(40);
    refused(&s, "zoning.accept_angle");
}

/// Joints closer together than the cutter's merge tolerance (set 0 of the tunnel 0.06 m apart, the
/// tolerance 0.075 m) are refused before cutting, naming the set's spacing and the tolerance in
/// plain numbers (they made block boundaries that crossed themselves, and 64 repairs at a second
/// each did not undo them). Just above it (0.1 m) the set builds, its needles repaired.
#[test]
fn joints_closer_than_the_merge_tolerance_are_refused() {
    let mut s = model("tunnel");
    s["joint_sets"][0]["spacing"] = json!(0.06);
    let err = refused(&s, "joint_sets[0].spacing");
    assert!(
        err.contains("0.06 m is below the 0.0750 m") && !err.contains("Some("),
        "{err}"
    );
    s["zoning"]["merge_tolerance"] = json!(0.5);
    let err = refused(&s, "zoning.merge_tolerance");
    assert!(err.contains("at most zoning.edge_at_excavation"), "{err}");
}

/// `zoning.merge_tolerance` sets the distance: a set 0.06 m apart in a 2 m box zoned at 0.25 m is
/// refused at the default (0.075 m) and cut into its 33 slabs at 0.02 m.
#[test]
fn the_merge_tolerance_is_a_scene_field() {
    let mut s = json!({
        "name": "slabs",
        "materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
        "joint_materials": { "j": { "normal_stiffness": 1e10, "shear_stiffness": 1e9, "friction": 30 } },
        "region": { "polygon": [[0, 0], [2, 0], [2, 2], [0, 2]], "material": "rock" },
        "joint_sets": [{ "dip": 0, "spacing": 0.06, "origin": [0, 0.03], "material": "j" }],
        "zoning": { "edge_at_excavation": 0.25, "edge_far": 0.25 }
    });
    refused(&s, "joint_sets[0].spacing");
    s["zoning"]["merge_tolerance"] = json!(0.02);
    let scene = adit::Scene::from_json(&s.to_string(), "slabs").unwrap();
    let built = adit::setup::setup(&scene).unwrap();
    assert_eq!(built.model.blocks.len(), 34);
}

/// `check` refuses what `run` refuses before its first cycle: a lone rigid block has no stiffness
/// to derive a time step from.
#[test]
fn check_refuses_a_scene_without_a_time_step() {
    let s: Value = serde_json::from_str(common::LONE_RIGID_BLOCK).unwrap();
    refused(&s, "solve: no zone or contact stiffness");
}

/// Issue 52's scenes, each refused at once naming its field, where `adit check` had aborted on
/// a 6 GB allocation (in-situ stress or gravity of 1e19–1e21 Pa over the model), `run` had spun
/// in the plot writer for over 10 minutes (a bolt spacing of 1e-300 m), the cutter had grown past
/// 11.5 GB (two persistent sets 0.02 m apart over a 100 m box) or meshed for over 10 minutes (one
/// such set), or the scene had built with its nonsense dropped without a word.
#[test]
fn extreme_values_are_refused_naming_the_field() {
    let tunnel = model("tunnel");
    let with = |pointer: &str, v: Value| {
        let mut s = tunnel.clone();
        let (parent, key) = pointer.rsplit_once('/').unwrap();
        s.pointer_mut(parent).unwrap()[key] = v;
        s
    };
    refused(&with("/in_situ/y_ref", json!(1.8e19)), "in_situ.y_ref");
    refused(&with("/in_situ/gradient/syy", json!(1.8e19)), "in_situ.syy");
    refused(&with("/gravity", json!([0, -9e15])), "gravity");
    refused(&with("/in_situ/szz", json!(1e308)), "in_situ.szz");
    refused(
        &with("/bolts/0/out_of_plane_spacing", json!(1e-300)),
        "bolts[0].out_of_plane_spacing",
    );
    refused(
        &with("/joint_sets/0/origin", json!([1e300, 0])),
        "joint_sets[0].origin[0]",
    );
    let mut tiny = tunnel.clone();
    tiny["region"]["polygon"][0] = json!([1e-300, -40]);
    refused(&tiny, "region.polygon[0][0]");
    refused(
        &with("/excavations/0/horseshoe/center", json!([1e-300, 0])),
        "excavations[0].horseshoe.center[0]",
    );
    let joint = |from: Value, to: Value| json!([{ "from": from, "to": to, "material": "joint" }]);
    refused(
        &with("/joints", joint(json!([-1e300, 0]), json!([1e300, 1]))),
        "joints[0].from[0]",
    );
    let err = refused(
        &with("/joints", joint(json!([50, 0]), json!([60, 1]))),
        "joints[0]",
    );
    assert!(err.contains("wholly outside"), "{err}");
    let mut at = tunnel.clone();
    at["blocks"] = json!({ "regions": [{ "mode": "rigid", "at": [100, 0] }] });
    refused(&at, "blocks.regions[0].at");
    // Too many blocks, or the zones of thin strips, estimated before cutting.
    let mut dense = with(
        "/region/polygon",
        json!([[-50, -50], [50, -50], [50, 50], [-50, 50]]),
    );
    dense["zoning"]["merge_tolerance"] = json!(0.01);
    for set in dense["joint_sets"].as_array_mut().unwrap() {
        set["spacing"] = json!(0.02);
        let set = set.as_object_mut().unwrap();
        set.remove("trace");
        set.remove("gap");
    }
    let err = refused(&dense, "joint_sets[1]");
    assert!(err.contains("blocks"), "{err}");
    dense["joint_sets"].as_array_mut().unwrap().truncate(1);
    let err = refused(&dense, "joint_sets[0].spacing");
    assert!(err.contains("zones"), "{err}");
    // A hole too small for the cutter to resolve (1e-18 m in a 50 m model took 20 s to fail).
    let mut tiny = model("jointed_tunnel");
    tiny["excavations"][0]["circle"]["radius"] = json!(1e-18);
    refused(&tiny, "excavations[0].circle.radius");
    // Explicit joints over the limit are blamed on `joints`, not on the first set.
    let many: Vec<Value> = (0..100_001)
        .map(|k| json!({ "from": [-10, k as f64 * 1e-4], "to": [10, 1.0], "material": "joint" }))
        .collect();
    refused(&with("/joints", Value::Array(many)), "joints");
}

/// The Barton–Bandis law's fields are checked by the CLI, each refusal naming its field.
#[test]
fn barton_bandis_fields_are_checked() {
    let tunnel = model("tunnel");
    let name = tunnel["joint_sets"][0]["material"]
        .as_str()
        .unwrap()
        .to_string();
    let path = format!("joint_materials.{name}");
    let with = |fields: Value| {
        let mut s = tunnel.clone();
        let j = s["joint_materials"][&name].as_object_mut().unwrap();
        for key in ["cohesion", "tensile_strength", "dilation"] {
            j.remove(key);
        }
        j.insert("law".into(), json!("barton_bandis"));
        for (k, v) in fields.as_object().unwrap() {
            j.insert(k.clone(), v.clone());
        }
        s
    };
    let good = json!({ "jrc": 8, "jcs": 60e6, "max_closure": 4e-4 });
    let bad = |key: &str, v: Value| {
        let mut f = good.clone();
        f[key] = v;
        refused(&with(f), &format!("{path}.{key}"))
    };
    bad("jrc", json!(25));
    bad("jcs", json!(-1));
    bad("max_closure", json!(0));
    bad("block_size", json!(0));
    bad("dilation_divisor", json!(0.5));
    bad("max_normal_stiffness", json!(1));
    bad("cohesion", json!(1e5));
    let mut missing = good.clone();
    missing.as_object_mut().unwrap().remove("jcs");
    refused(&with(missing), &format!("{path}.jcs"));
}

/// A scene that passes every bound but whose first cycles blow up (rock of 1 kPa under 0.9 TPa)
/// fails `adit check` as it fails `run`, naming the cycle and the node, instead of measuring
/// cycles on exploded positions (in-situ stresses of 1e21 Pa had aborted there).
#[test]
fn check_fails_on_first_cycles_that_blow_up() {
    let mut s = model("tunnel");
    s["materials"]["rock"] = json!({ "density": 2700, "young": 1e3, "poisson": 0.25 });
    s["in_situ"]["sxx"] = json!(-9e11);
    s["in_situ"]["syy"] = json!(-9e11);
    let err = refused(&s, "the scene's first cycles fail");
    assert!(err.contains("unstable"), "{err}");
}

/// A factor of safety asked out of range or of a dynamic stage, and a residual cohesion above
/// the cohesion or on another law: refused naming the field, before any solve (`adit check`
/// refuses what `adit run` would).
#[test]
fn a_factor_of_safety_that_cannot_be_searched_is_refused() {
    let with_fos = |model_name: &str, fos: Value| {
        let mut s = model(model_name);
        s["stages"][2]["factor_of_safety"] = fos;
        s
    };
    refused(
        &with_fos("tunnel", json!({ "tolerance": 0 })),
        "stages[2].factor_of_safety.tolerance",
    );
    refused(
        &with_fos("tunnel", json!({ "max_factor": 1 })),
        "stages[2].factor_of_safety.max_factor",
    );
    refused(
        &with_fos("tunnel", json!({ "displacement_limit": -0.1 })),
        "stages[2].factor_of_safety.displacement_limit",
    );
    let extra = with_fos("tunnel", json!({ "tolerance": 0.01, "extra": 1 }));
    let (code, err) = check_text(&extra.to_string(), "fos_extra");
    assert!(
        code == Some(1) && err.contains("unknown field `extra`"),
        "{err}"
    );
    let mut dynamic = with_fos("tunnel", json!({}));
    dynamic["stages"][2]["solve"] = json!({ "mode": "dynamic", "max_cycles": 100 });
    refused(&dynamic, "stages[2].factor_of_safety");
    let mut residual = model("tunnel");
    residual["joint_materials"]["joint"]["residual_cohesion"] = json!(3e5);
    refused(&residual, "joint_materials.joint.residual_cohesion");
    residual["joint_materials"]["joint"]["residual_cohesion"] = json!(1e5);
    residual["joint_materials"]["joint"]["law"] = json!("glued");
    residual["joint_materials"]["joint"]["cohesion"] = json!(0);
    refused(&residual, "joint_materials.joint.residual_cohesion");
}

/// A sign or unit slip an RS2 user makes (friction item 10 of issue 49): an in-situ stress given
/// compression positive, a friction angle in radians: `adit check` warns, naming the field (the
/// scene stays valid: a tensile field or a tiny friction can be meant).
#[test]
fn a_flipped_in_situ_sign_and_a_friction_in_radians_are_warned() {
    let mut s = model("tunnel");
    let check = |s: &Value, tag: &str| {
        let path =
            std::env::temp_dir().join(format!("adit-warn-{tag}-{}.json", std::process::id()));
        std::fs::write(&path, s.to_string()).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_adit"))
            .args(["check", path.to_str().unwrap()])
            .output()
            .unwrap();
        std::fs::remove_file(&path).unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let plain = check(&s, "plain");
    assert!(
        !plain.contains("in_situ.") && !plain.contains("friction:"),
        "{plain}"
    );
    s["in_situ"]["sxx"] = json!(20e6);
    s["joint_materials"]["joint"]["friction"] = json!(0.52);
    let warned = check(&s, "slips");
    assert!(
        warned.contains("warning: in_situ.sxx: tensile over the whole region"),
        "{warned}"
    );
    assert!(!warned.contains("in_situ.syy"), "{warned}");
    assert!(
        warned.contains("warning: joint_materials.joint.friction: 0.52°"),
        "{warned}"
    );
    // Supports without stages (item 11): in the rock before the excavation is made.
    let mut unstaged = model("tunnel");
    unstaged["stages"] = json!([]);
    let warned = check(&unstaged, "unstaged");
    let supports = "warning: stages: none, so the 2 bolt group(s) and liner(s) act from the start";
    assert!(warned.contains(supports), "{warned}");
}

/// A 2 m × 10 m column of elastic rock whose first boundary condition is `base`, its sides on
/// rollers, solved by `solve`.
fn column(base: Value, solve: Value) -> Value {
    json!({
        "name": "column",
        "materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
        "region": { "polygon": [[0, 0], [2, 0], [2, 10], [0, 10]],
                    "edge_names": ["base", "right", "top", "left"], "material": "rock" },
        "zoning": { "edge_at_excavation": 1, "edge_far": 1 },
        "boundary": [base, { "part": "left", "fix": "x" }, { "part": "right", "fix": "x" }],
        "solve": solve
    })
}

/// A quiet part in force during a static stage, fixed too, or a point's; an incident wave
/// without a quiet part, or without its velocity, or with a table and a pulse; a duration of a
/// static solve or not positive: refused naming the field, before any solve.
#[test]
fn quiet_boundaries_and_waves_out_of_place_are_refused() {
    let dynamic = json!({ "mode": "dynamic", "duration": 0.1, "damping": 0 });
    let wave = json!({ "wave": "p", "velocity": 1, "pulse": "ricker", "frequency": 20 });
    let err = refused(
        &column(json!({ "part": "base", "quiet": true }), json!({})),
        "boundary[0].quiet",
    );
    assert!(err.contains("dynamic"), "{err}");
    let mut staged = column(json!({ "part": "base", "fix": "xy" }), json!({}));
    staged["stages"] = json!([
        { "name": "settle" },
        { "name": "shake", "boundary": [{ "part": "base", "quiet": true }], "solve": dynamic.clone() },
        { "name": "static again", "solve": { "mode": "static" } }
    ]);
    let err = refused(&staged, "stages[1].boundary[0].quiet");
    assert!(
        err.contains("stages[2] ('static again') is static"),
        "{err}"
    );
    refused(
        &column(
            json!({ "part": "base", "quiet": true, "fix": "y" }),
            dynamic.clone(),
        ),
        "boundary[0].fix",
    );
    refused(
        &column(json!({ "at": [1, 0], "quiet": true }), dynamic.clone()),
        "boundary[0].quiet",
    );
    refused(
        &column(
            json!({ "part": "base", "fix": "xy", "incident": wave }),
            dynamic.clone(),
        ),
        "boundary[0].incident",
    );
    let mut slow = wave.clone();
    slow.as_object_mut().unwrap().remove("velocity");
    refused(
        &column(
            json!({ "part": "base", "quiet": true, "incident": slow }),
            dynamic.clone(),
        ),
        "boundary[0].incident.velocity",
    );
    let mut both = wave.clone();
    both["table"] = json!([[0, 0], [0.01, 1]]);
    refused(
        &column(
            json!({ "part": "base", "quiet": true, "incident": both }),
            dynamic.clone(),
        ),
        "boundary[0].incident",
    );
    let backwards = json!({ "wave": "s", "table": [[0, 0], [0.02, 1], [0.01, 0]] });
    refused(
        &column(
            json!({ "part": "base", "quiet": true, "incident": backwards }),
            dynamic.clone(),
        ),
        "boundary[0].incident.table[2]",
    );
    refused(
        &column(
            json!({ "part": "base", "fix": "xy" }),
            json!({ "duration": 1 }),
        ),
        "solve.duration",
    );
    refused(
        &column(
            json!({ "part": "base", "fix": "xy" }),
            json!({ "mode": "dynamic", "duration": 0 }),
        ),
        "solve.duration",
    );
}

/// A prescribed motion in force during a static solve, on a quiet part, on a component the part
/// also fixes, a point's, with both a velocity and an acceleration or neither, a baseline on a
/// velocity, an unending sine acceleration, or on a rigid block's nodes; a load history in a
/// static solve, without a load or without its amplitude: refused naming the field, before any
/// solve.
#[test]
fn prescribed_motions_out_of_place_are_refused() {
    let dynamic = json!({ "mode": "dynamic", "duration": 0.1, "damping": 0 });
    let shake = json!({ "direction": "x", "velocity": { "pulse": "sine", "amplitude": 0.1, "frequency": 5 } });
    let base = |motion: &Value, extra: Value| {
        let mut b = json!({ "part": "base", "fix": "y", "motion": motion });
        for (k, v) in extra.as_object().unwrap() {
            b[k] = v.clone();
        }
        b
    };
    let err = refused(
        &column(base(&shake, json!({})), json!({})),
        "boundary[0].motion",
    );
    assert!(err.contains("dynamic"), "{err}");
    refused(
        &column(
            base(&shake, json!({ "quiet": true, "fix": null })),
            dynamic.clone(),
        ),
        "boundary[0].motion",
    );
    refused(
        &column(base(&shake, json!({ "fix": "xy" })), dynamic.clone()),
        "boundary[0].motion.direction",
    );
    refused(
        &column(
            json!({ "at": [1, 0], "fix": "y", "motion": shake }),
            dynamic.clone(),
        ),
        "boundary[0].motion",
    );
    let mut both = shake.clone();
    both["acceleration"] = json!({ "table": [[0, 0], [0.1, 1]] });
    refused(
        &column(base(&both, json!({})), dynamic.clone()),
        "boundary[0].motion",
    );
    let neither = json!({ "direction": "x" });
    refused(
        &column(base(&neither, json!({})), dynamic.clone()),
        "boundary[0].motion",
    );
    let mut corrected = shake.clone();
    corrected["baseline"] = json!(true);
    refused(
        &column(base(&corrected, json!({})), dynamic.clone()),
        "boundary[0].motion.baseline",
    );
    let unending = json!({ "direction": "x",
        "acceleration": { "pulse": "sine", "amplitude": 1, "frequency": 5 } });
    refused(
        &column(base(&unending, json!({})), dynamic.clone()),
        "boundary[0].motion.acceleration.cycles",
    );
    let pulse = json!({ "pulse": "ricker", "amplitude": 1, "frequency": 20 });
    let loaded = json!({ "part": "base", "normal_stress": -1e6, "history": pulse });
    let err = refused(&column(loaded.clone(), json!({})), "boundary[0].history");
    assert!(err.contains("dynamic"), "{err}");
    refused(
        &column(
            json!({ "part": "base", "fix": "y", "history": pulse }),
            dynamic.clone(),
        ),
        "boundary[0].history",
    );
    let mut silent = loaded;
    silent["history"] = json!({ "pulse": "ricker", "frequency": 20 });
    refused(
        &column(silent, dynamic.clone()),
        "boundary[0].history.amplitude",
    );
    // Free-field sides: quiet, without an incident wave, vertical.
    let mut sides = column(json!({ "part": "base", "quiet": true }), dynamic.clone());
    sides["boundary"][1] = json!({ "part": "left", "free_field": true });
    refused(&sides, "boundary[1].free_field");
    sides["boundary"][1] = json!({ "part": "left", "quiet": true, "free_field": true,
        "incident": { "wave": "s", "velocity": 1, "pulse": "ricker", "frequency": 20 } });
    refused(&sides, "boundary[1].incident");
    sides["boundary"][1] = json!({ "part": "outer", "quiet": true, "free_field": true });
    let err = refused(&sides, "boundary[1].free_field");
    assert!(err.contains("not vertical"), "{err}");
    let mut rigid = column(base(&shake, json!({})), dynamic.clone());
    rigid["blocks"] = json!({ "mode": "rigid" });
    let err = refused(&rigid, "boundary[0].motion");
    assert!(err.contains("rigid or simple block"), "{err}");
}

/// An energy history with a point, a point history without one, or an energy history in a scene
/// with no dynamic solve: refused naming the field.
#[test]
fn energy_histories_out_of_place_are_refused() {
    let column = |histories: Value, solve: Value| {
        json!({
            "name": "column",
            "materials": { "rock": { "density": 2500, "young": 1e10, "poisson": 0.25 } },
            "region": { "polygon": [[0, 0], [2, 0], [2, 10], [0, 10]], "material": "rock" },
            "zoning": { "edge_at_excavation": 1, "edge_far": 1 },
            "boundary": [{ "part": "outer", "fix": "xy" }],
            "solve": solve,
            "histories": histories
        })
    };
    let dynamic = json!({ "mode": "dynamic", "duration": 0.01, "damping": 0 });
    refused(
        &column(
            json!([{ "name": "k", "at": [1, 1], "quantity": "kinetic_energy" }]),
            dynamic.clone(),
        ),
        "histories[0].at",
    );
    refused(
        &column(
            json!([{ "name": "u", "quantity": "displacement_x" }]),
            dynamic,
        ),
        "histories[0].at",
    );
    refused(
        &column(
            json!([{ "name": "e", "quantity": "energy_error" }]),
            json!({}),
        ),
        "histories[0].quantity",
    );
}
