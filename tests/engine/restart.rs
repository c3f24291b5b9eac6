//! Checkpoints, `--from-stage` and `--from`: a run of `models/tunnel.json` restarted from stage 2
//! or 3 writes the files of the run that was not stopped, bit for bit, also after the first run
//! was killed in the middle of a stage; the tunnel excavated once and continued with other bolt
//! patterns writes, for each, the files of a whole run of that scene (issue 49's branching bar);
//! a checkpoint of another scene's stages, a damaged one or a missing one is refused naming why.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::common;

use adit::solve::Quiet;
use adit::{Scene, run_scene, run_scene_branch, run_scene_from};

fn tunnel() -> Scene {
    Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("models/tunnel.json")).unwrap()
}

fn folder(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("adit-restart-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn copy(from: &Path, to: &Path) {
    std::fs::create_dir_all(to.join("checkpoints")).unwrap();
    for sub in ["", "checkpoints"] {
        for e in std::fs::read_dir(from.join(sub)).unwrap().flatten() {
            if e.path().is_file() {
                std::fs::copy(e.path(), to.join(sub).join(e.file_name())).unwrap();
            }
        }
    }
}

/// Every result file of `a` is in `b` with the same bytes (summary.json: the same figures but
/// for the seconds), and `b` has no other.
fn same_results(a: &Path, b: &Path) {
    let names = |d: &Path| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .flatten()
            .filter(|e| e.path().is_file())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    };
    assert_eq!(names(a), names(b));
    for f in names(a) {
        if f.ends_with(".vtu") || f.ends_with(".csv") || f.ends_with(".pvd") {
            assert!(
                std::fs::read(a.join(&f)).unwrap() == std::fs::read(b.join(&f)).unwrap(),
                "{f} differs"
            );
        }
    }
    let summary = |d: &Path| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(d.join("summary.json")).unwrap()).unwrap()
    };
    let (x, y) = (summary(a), summary(b));
    for key in [
        "status",
        "cycles",
        "final_ratio",
        "stages",
        "zones",
        "contacts",
    ] {
        assert_eq!(x[key], y[key], "summary.json {key}");
    }
}

#[test]
fn a_run_from_stage_2_or_3_equals_the_run_not_stopped() {
    let whole = folder("whole");
    run_scene(&tunnel(), &whole, &mut Quiet).unwrap();
    for n in [3, 2] {
        let again = folder(&format!("from{n}"));
        copy(&whole, &again);
        let r = run_scene_from(&tunnel(), &again, n, &mut Quiet).unwrap();
        assert_eq!(r.summary.status, "converged");
        same_results(&whole, &again);
        std::fs::remove_dir_all(&again).unwrap();
    }
    std::fs::remove_dir_all(&whole).unwrap();
}

#[test]
fn a_run_killed_in_its_last_stage_goes_on_from_the_checkpoint_before() {
    let whole = folder("whole-cli");
    run_scene(&tunnel(), &whole, &mut Quiet).unwrap();
    let killed = folder("killed");
    let adit = env!("CARGO_BIN_EXE_adit");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/models/tunnel.json");
    let mut child = Command::new(adit)
        .args(["run", scene, "--quiet", "--out"])
        .arg(&killed)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let second = killed.join("checkpoints/stage_02.ckpt");
    while !second.exists() && start.elapsed() < Duration::from_secs(120) {
        std::thread::sleep(Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(
        !killed.join("checkpoints/stage_03.ckpt").exists(),
        "killed before its last stage ended"
    );
    let out = Command::new(adit)
        .args(["run", scene, "--quiet", "--from-stage", "3", "--out"])
        .arg(&killed)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    same_results(&whole, &killed);
    std::fs::remove_dir_all(&whole).unwrap();
    std::fs::remove_dir_all(&killed).unwrap();
}

/// The tunnel model with simple blocks to its left and rigid ones above (bodies, bolts, liners,
/// contacts and zones in one scene).
fn every_kind() -> Scene {
    let mut s = tunnel();
    s.blocks = serde_json::from_value(serde_json::json!({
        "mode": "deformable",
        "regions": [
            { "mode": "simple", "polygon": [[-40, -40], [-15, -40], [-15, 40], [-40, 40]] },
            { "mode": "rigid", "polygon": [[-15, 20], [40, 20], [40, 40], [-15, 40]] }
        ]
    }))
    .unwrap();
    s
}

/// The state a checkpoint puts into a model built anew is the state of the model that ran, field
/// by field: what a solve or a stage changes is all saved (a field left out shows here).
#[test]
fn a_restored_model_is_the_model_that_ran() {
    let mut two = every_kind();
    two.stages.truncate(2);
    let dir = folder("fields");
    let ran = run_scene(&two, &dir, &mut Quiet).unwrap();
    assert!(ran.summary.rigid_blocks > 0 && ran.summary.simple_blocks > 0);
    let bytes = std::fs::read(dir.join("checkpoints/stage_02.ckpt")).unwrap();
    let mut built = adit::setup::setup(&two).unwrap();
    let adit::setup::Setup { model, plan, .. } = &mut built;
    let mut staging = adit::stage::Staging::new(plan);
    for stage in &plan.stages {
        staging.apply(stage, model, plan);
    }
    adit::checkpoint::decode(&bytes, &two, model).unwrap();
    // Each field's every array and value, as its Debug text.
    let fields = |m: &adit::model::Model| {
        [
            ("nodes", format!("{:?}", m.nodes)),
            ("zones", format!("{:?}", m.zones)),
            ("bodies", format!("{:?}", m.bodies)),
            ("blocks", format!("{:?}", m.blocks)),
            ("contacts", format!("{:?}", m.contacts)),
            ("supports", format!("{:?}", m.supports)),
            ("mixed", format!("{:?}", m.mixed)),
        ]
    };
    for ((name, a), (_, b)) in fields(&ran.built.model).into_iter().zip(fields(model)) {
        assert!(a == b, "{name} differ");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_run_of_every_block_kind_from_stage_3_equals_the_run_not_stopped() {
    let whole = folder("kinds-whole");
    run_scene(&every_kind(), &whole, &mut Quiet).unwrap();
    let again = folder("kinds-again");
    copy(&whole, &again);
    run_scene_from(&every_kind(), &again, 3, &mut Quiet).unwrap();
    same_results(&whole, &again);
    std::fs::remove_dir_all(&whole).unwrap();
    std::fs::remove_dir_all(&again).unwrap();
}

/// With the far field by boundary elements, explicitly and implicitly.
#[test]
fn a_run_with_a_far_field_from_stage_2_equals_the_run_not_stopped() {
    for method in ["explicit", "implicit"] {
        let scene = common::staged_with_far_field(method);
        let whole = folder(&format!("far-{method}"));
        run_scene(&scene, &whole, &mut Quiet).unwrap();
        let again = folder(&format!("far-{method}-again"));
        copy(&whole, &again);
        run_scene_from(&scene, &again, 2, &mut Quiet).unwrap();
        same_results(&whole, &again);
        std::fs::remove_dir_all(&whole).unwrap();
        std::fs::remove_dir_all(&again).unwrap();
    }
}

#[test]
fn a_checkpoint_of_another_scene_or_damaged_or_missing_is_refused() {
    let dir = folder("refused");
    let mut small = tunnel();
    small.stages.truncate(2);
    run_scene(&small, &dir, &mut Quiet).unwrap();
    let error = |scene: &Scene, n: usize| {
        let e = run_scene_from(scene, &dir, n, &mut Quiet)
            .err()
            .expect("refused");
        format!("{e:#}")
    };
    let mut other = small.clone();
    other.in_situ.sxx *= 1.01;
    assert!(
        error(&other, 2)
            .contains("differs from this scene in its first 1 stage(s): first at in_situ.sxx"),
        "{}",
        error(&other, 2)
    );
    assert!(
        error(&small, 3).contains("the scene has 2 stage(s)"),
        "{}",
        error(&small, 3)
    );
    assert!(error(&small, 5).contains("no checkpoint of stage 4"));
    let path = dir.join("checkpoints/stage_01.ckpt");
    let bytes = std::fs::read(&path).unwrap();
    std::fs::write(&path, &bytes[..bytes.len() / 2]).unwrap();
    assert!(
        error(&small, 2).contains("ends early"),
        "{}",
        error(&small, 2)
    );
    std::fs::write(&path, b"not a checkpoint at all").unwrap();
    assert!(error(&small, 2).contains("not an adit checkpoint"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `output.checkpoints: false` leaves no checkpoint (and removes those an earlier run of the
/// scene left), writes the same results otherwise, and a `--from-stage` run then says why it
/// has none to go on from.
#[test]
fn a_run_without_checkpoints_leaves_none_and_says_so() {
    let mut small = tunnel();
    small.stages.truncate(2);
    let (with, without) = (folder("with-checkpoints"), folder("without-checkpoints"));
    run_scene(&small, &with, &mut Quiet).unwrap();
    run_scene(&small, &without, &mut Quiet).unwrap();
    assert!(without.join("checkpoints/stage_02.ckpt").exists());
    small.output.checkpoints = false;
    run_scene(&small, &without, &mut Quiet).unwrap();
    let left = std::fs::read_dir(without.join("checkpoints"))
        .map(|d| d.count())
        .unwrap_or(0);
    assert_eq!(left, 0, "checkpoints left");
    same_results(&with, &without);
    let e = run_scene_from(&small, &without, 2, &mut Quiet)
        .err()
        .expect("refused");
    let e = format!("{e:#}");
    assert!(
        e.contains("no checkpoint of stage 1") && e.contains("output.checkpoints is false"),
        "{e}"
    );
    std::fs::remove_dir_all(&with).unwrap();
    std::fs::remove_dir_all(&without).unwrap();
}

/// Every file of `a` and `b`, checkpoints and plots too, has the same bytes but summary.json,
/// whose figures but the seconds are the same (`same_results`).
fn same_files(a: &Path, b: &Path) {
    same_results(a, b);
    for sub in ["", "checkpoints"] {
        for e in std::fs::read_dir(a.join(sub)).unwrap().flatten() {
            let name = e.file_name();
            if e.path().is_file() && name != "summary.json" {
                let theirs = std::fs::read(b.join(sub).join(&name)).unwrap();
                assert!(
                    std::fs::read(e.path()).unwrap() == theirs,
                    "{sub}/{name:?} differs"
                );
            }
        }
    }
}

/// Issue 49's branching bar: the tunnel excavated once (its run's checkpoint after stage 2)
/// and continued with two other bolt patterns (closer bolts round the wall; bolts farther apart
/// along the tunnel, in a scene of another name) writes, for each, the files of a whole run of
/// that scene; a scene whose second stage differs is refused naming the field.
#[test]
fn the_tunnel_branched_after_its_excavation_writes_the_files_of_its_whole_run() {
    let base = folder("branch-base");
    run_scene(&tunnel(), &base, &mut Quiet).unwrap();
    let checkpoint = base.join("checkpoints/stage_02.ckpt");
    let mut closer = tunnel();
    let pattern = closer.bolts[0]
        .pattern
        .as_mut()
        .expect("the tunnel's bolts are a pattern");
    (pattern.spacing, pattern.count) = (0.9, 13);
    let mut wider = tunnel();
    wider.name = "tunnel_wide".into();
    wider.bolts[0].out_of_plane_spacing = 2.5;
    for (tag, scene) in [("closer", closer), ("wider", wider)] {
        let whole = folder(&format!("branch-{tag}-whole"));
        let branch = folder(&format!("branch-{tag}"));
        run_scene(&scene, &whole, &mut Quiet).unwrap();
        let r = run_scene_branch(&scene, &branch, &checkpoint, &mut Quiet).unwrap();
        assert_eq!(r.summary.status, "converged");
        same_files(&whole, &branch);
        std::fs::remove_dir_all(&whole).unwrap();
        std::fs::remove_dir_all(&branch).unwrap();
    }
    let mut earlier = tunnel();
    earlier.stages[1].support_fraction = 0.3;
    let e = run_scene_branch(&earlier, &folder("branch-refused"), &checkpoint, &mut Quiet)
        .err()
        .expect("refused");
    let e = format!("{e:#}");
    assert!(
        e.contains(
            "first at stages[1].support_fraction (the checkpoint's `support_fraction: 0.25`, \
             the scene's `support_fraction: 0.3`)"
        ),
        "{e}"
    );
    std::fs::remove_dir_all(&base).unwrap();
}
