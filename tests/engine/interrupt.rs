//! Ctrl-C during a staged run (issue 15): the run stops at the end of a cycle and leaves a summary
//! with status `interrupted`, the history to that cycle, the last state, no temporary file and no
//! file of an earlier run; the exit code is 130.

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[test]
fn ctrl_c_leaves_an_interrupted_run_that_says_so() {
    let out = std::env::temp_dir().join(format!("adit-interrupt-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).unwrap();
    // What an earlier, longer run left.
    std::fs::write(out.join("tunnel_zones_0009.vtu"), "earlier").unwrap();
    std::fs::write(out.join("summary.json"), r#"{ "status": "converged" }"#).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_adit"))
        .args([
            "run",
            concat!(env!("CARGO_MANIFEST_DIR"), "/models/tunnel.json"),
            "--quiet",
            "--out",
        ])
        .arg(&out)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Interrupt once the solve is under way (history rows are being written).
    let start = Instant::now();
    let history = out.join("history.csv");
    while std::fs::read_to_string(&history).map_or(0, |h| h.lines().count()) < 50 {
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "the run never started cycling"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    unsafe {
        libc::kill(child.id() as libc::pid_t, libc::SIGINT);
    }
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130));

    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["status"], "interrupted", "{summary}");
    let cycles = summary["cycles"].as_u64().unwrap();
    let rows = std::fs::read_to_string(&history).unwrap();
    let last = rows.lines().last().unwrap();
    assert_eq!(
        last.split(',').next().unwrap(),
        cycles.to_string(),
        "{last}"
    );
    let files: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(!files.iter().any(|f| f.ends_with(".tmp")), "{files:?}");
    assert!(
        !files.contains(&"tunnel_zones_0009.vtu".to_string()),
        "{files:?}"
    );
    // The last state is written, and the collection lists it.
    let pvd = std::fs::read_to_string(out.join("tunnel.pvd")).unwrap();
    assert!(pvd.contains(&format!("timestep=\"{cycles}\"")), "{pvd}");
    std::fs::remove_dir_all(&out).unwrap();
}
