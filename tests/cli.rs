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
        serde_json::from_str(include_str!("../models/kirsch.json")).unwrap();
    v["solve"]["max_cycles"] = 20.into();
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
