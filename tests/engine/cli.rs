//! The `adit` command: clear errors and a non-zero exit on bad input, never a panic.

use std::process::Command;

fn adit(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_adit"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

#[test]
fn bad_scene_is_one_clear_error() {
    let path = std::env::temp_dir().join(format!("adit-bad-{}.json", std::process::id()));
    std::fs::write(&path, r#"{ "name": "x", "materials": { "rock": { "density": 1, "young": 1e9, "poisson": 0.5 } } }"#)
        .unwrap();
    let (code, _, err) = adit(&["check", path.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        err.starts_with("error: ") && err.contains("line 1"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    std::fs::remove_file(&path).unwrap();
}

#[test]
fn missing_file_is_one_clear_error() {
    let (code, _, err) = adit(&["run", "no/such/scene.json"]);
    assert_eq!(code, 1);
    assert!(
        err.starts_with("error: cannot read no/such/scene.json"),
        "{err}"
    );
}

#[test]
fn check_prints_mesh_statistics() {
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/models/kirsch.json");
    let (code, out, _) = adit(&["check", model]);
    assert_eq!(code, 0);
    assert!(out.contains("zones") && out.contains("min angle"), "{out}");
}

/// A run that stops at its cycle limit is not a success (issue 49, friction item 2): it says so
/// and exits with 3, its files written.
#[test]
fn a_run_at_its_cycle_limit_exits_with_3() {
    let mut v: serde_json::Value =
        serde_json::from_str(include_str!("../../models/kirsch.json")).unwrap();
    v["solve"]["max_cycles"] = 20.into();
    v["solve"]["method"] = "explicit".into();
    let dir = std::env::temp_dir().join(format!("adit-cycle-limit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("limit.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let out = dir.join("out");
    let (code, _, err) = adit(&[
        "run",
        scene.to_str().unwrap(),
        "--quiet",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 3, "{err}");
    assert!(err.contains("cycle limit"), "{err}");
    assert!(out.join("summary.json").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A temporary folder of this test process.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("adit-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The number after `prefix` in `text` (up to the next space).
fn number_after(text: &str, prefix: &str) -> f64 {
    let rest = &text[text
        .find(prefix)
        .unwrap_or_else(|| panic!("{prefix:?} in {text}"))
        + prefix.len()..];
    rest.split_whitespace().next().unwrap().parse().unwrap()
}

/// The bundled tunnel says nothing alarming (issue 49, friction item 12): the joint traces that
/// end inside blocks are how non-persistent joints are, not a warning, and a zone angle below
/// `zoning.min_angle` is explained where it is; `adit check` and `adit run` report the same
/// critical step, the smallest over the stages (item 13), and the run says what mass scaling is.
#[test]
fn the_tunnel_runs_without_alarms_and_check_and_run_agree_on_its_step() {
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/models/tunnel.json");
    let (code, checked, _) = adit(&["check", model]);
    assert_eq!(code, 0);
    assert!(!checked.contains("warning: 1670"), "{checked}");
    assert!(
        checked.contains("joint traces end inside a block and are part of its rock"),
        "{checked}"
    );
    assert!(
        checked.contains("zoning.min_angle = 28° holds everywhere but in such corners"),
        "{checked}"
    );
    let dir = scratch("tunnel");
    let (code, ran, err) = adit(&["run", model, "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("absorbed"), "{err}");
    let check_step = number_after(&checked, "critical time step ");
    let run_step = number_after(&ran, "time step: critical ");
    assert_eq!(check_step, run_step, "{checked}\n{ran}");
    assert!(ran.contains("stage 'bolts and shotcrete'"), "{ran}");
    assert!(ran.contains("on scaled masses (static:"), "{ran}");
    let summary: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("summary.json")).unwrap()).unwrap();
    let critical = summary["critical_timestep"].as_f64().unwrap();
    assert_eq!(format!("{critical:.3e}").parse::<f64>().unwrap(), run_step);
    assert_eq!(summary["critical_stage"], "bolts and shotcrete");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A value of the wrong type is named by its JSON path and in words (issue 49, friction item 6).
#[test]
fn a_wrong_type_names_its_json_path_and_says_a_number() {
    let mut v: serde_json::Value =
        serde_json::from_str(include_str!("../../models/kirsch.json")).unwrap();
    v["materials"]["rock"]["young"] = "ten".into();
    let dir = scratch("type");
    let scene = dir.join("typed.json");
    std::fs::write(&scene, serde_json::to_string_pretty(&v).unwrap()).unwrap();
    let (code, _, err) = adit(&["check", scene.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        err.contains(", at materials.rock.young: invalid type: string \"ten\", expected a number"),
        "{err}"
    );
    assert!(!err.contains("f64") && !err.contains(" at line "), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A run given no `--out` over an earlier run's folder says it replaces it (issue 49, friction
/// item 3: never overwrite another run silently).
#[test]
fn a_run_over_an_earlier_one_says_it_replaces_it() {
    let dir = scratch("replace");
    let mut v: serde_json::Value =
        serde_json::from_str(include_str!("../../models/kirsch.json")).unwrap();
    v["output"] = serde_json::json!({ "folder": dir.join("out").to_str().unwrap() });
    v["zoning"] = serde_json::json!({ "edge_at_excavation": 0.3, "edge_far": 8.0 });
    let scene = dir.join("again.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let (code, _, first) = adit(&["run", scene.to_str().unwrap(), "--quiet"]);
    assert_eq!(code, 0, "{first}");
    assert!(!first.contains("replaces"), "{first}");
    let (code, _, second) = adit(&["run", scene.to_str().unwrap(), "--quiet"]);
    assert_eq!(code, 0, "{second}");
    assert!(
        second.contains("holds an earlier run; this run replaces it"),
        "{second}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
