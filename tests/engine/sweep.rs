//! `adit sweep`: a grid of runs gathered into one table; a failing run is a row with its error;
//! a sweep killed half way and started again runs only the runs still missing, and its table is
//! the uninterrupted sweep's.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn folder(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("adit-sweep-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A spec over the shipped Kirsch model, coarse, with `values` of the far-field sxx (Pa) and one
/// run whose parameter path does not exist in the scene.
fn spec(dir: &Path, values: &[f64], cycles: u64) -> PathBuf {
    let kirsch = Path::new(env!("CARGO_MANIFEST_DIR")).join("models/kirsch.json");
    let mut base: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(kirsch).unwrap()).unwrap();
    base["zoning"]["edge_at_excavation"] = 0.3.into();
    base["zoning"]["edge_far"] = 8.0.into();
    base["solve"]["max_cycles"] = cycles.into();
    base["solve"]["ratio"] = 1e-12.into();
    let spec = serde_json::json!({
        "name": "kirsch_sweep",
        "base": base,
        "grid": { "in_situ.sxx": values, "materials.rock.poisson": [0.25] },
    });
    let path = dir.join("spec.json");
    std::fs::write(&path, spec.to_string()).unwrap();
    path
}

fn sweep(spec: &Path, out: &Path) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_adit"));
    c.arg("sweep")
        .arg(spec)
        .arg("--out")
        .arg(out)
        .args(["--workers", "1"]);
    c
}

#[test]
fn a_sweep_writes_one_row_per_run_and_a_failure_is_a_row() {
    let dir = folder("rows");
    let path = spec(&dir, &[-10e6, -12e6, -14e6], 300);
    // One more run, whose material does not exist: a row with its error.
    let mut s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    s["grid"]["materials.granite.young"] = serde_json::json!([1e9]);
    std::fs::write(&path, s.to_string()).unwrap();
    let out = dir.join("out");
    let done = sweep(&path, &out).output().unwrap();
    assert!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
    let table = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines.len(), 1 + 3, "{table}");
    assert!(
        lines[0].starts_with("id,in_situ.sxx,materials.granite.young,"),
        "{table}"
    );
    assert!(
        lines[1..]
            .iter()
            .all(|l| l.contains(",failed,") && l.contains("no materials.granite")),
        "{table}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_sweep_killed_half_way_runs_only_what_is_missing() {
    let dir = folder("kill");
    let values: Vec<f64> = (0..6).map(|k| -10e6 - 1e6 * k as f64).collect();
    let path = spec(&dir, &values, 2500);
    // The whole sweep once, uninterrupted.
    let whole = dir.join("whole");
    assert!(sweep(&path, &whole).output().unwrap().status.success());
    // Again, killed (SIGKILL: no chance to tidy up) once two runs have their rows.
    let out = dir.join("out");
    let mut child = sweep(&path, &out).stdout(Stdio::null()).spawn().unwrap();
    let rows = |out: &Path| {
        (0..6)
            .filter(|k| out.join(format!("runs/run_{k:04}/row.json")).exists())
            .count()
    };
    let start = Instant::now();
    while rows(&out) < 2 && start.elapsed() < Duration::from_secs(120) {
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    // The killed sweep's runs stop with it (their standard input closes).
    let start = Instant::now();
    while running(&out) > 0 {
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "a run of the killed sweep goes on"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    let before = rows(&out);
    assert!((2..6).contains(&before), "{before} runs done when killed");
    assert!(
        !out.join("sweep.csv").exists(),
        "no table from a killed sweep"
    );
    let again = sweep(&path, &out).output().unwrap();
    assert!(again.status.success());
    let said = String::from_utf8_lossy(&again.stdout);
    assert_eq!(said.matches("done before").count(), before, "{said}");
    assert_eq!(
        said.matches(" converged (").count() + said.matches(" cycle_limit (").count(),
        6,
        "{said}"
    );
    // The restarted sweep's table is the uninterrupted one's but for the seconds.
    let figures = |p: &Path| -> Vec<String> {
        std::fs::read_to_string(p.join("sweep.csv"))
            .unwrap()
            .lines()
            .map(|l| {
                let mut f: Vec<&str> = l.split(',').collect();
                f.remove(5); // wall_seconds
                f.join(",")
            })
            .collect()
    };
    assert_eq!(figures(&out), figures(&whole));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The processes running runs of the sweep into `out` (`adit sweep-run`), found by their
/// command lines.
fn running(out: &Path) -> usize {
    let Ok(entries) = std::fs::read_dir("/proc") else {
        return 0;
    };
    entries
        .flatten()
        .filter(|e| {
            std::fs::read(e.path().join("cmdline")).is_ok_and(|cmd| {
                let cmd = String::from_utf8_lossy(&cmd).replace('\0', " ");
                cmd.contains("sweep-run") && cmd.contains(&*out.to_string_lossy())
            })
        })
        .count()
}

/// Each run is a process of its own: one killed (as an abort would end it) is a failed row naming
/// how it ended, and the sweep goes on with the others.
#[test]
fn a_run_whose_process_dies_is_a_failed_row() {
    let dir = folder("abort");
    let path = spec(&dir, &[-10e6, -12e6, -14e6], 200_000);
    let out = dir.join("out");
    let mut child = sweep(&path, &out).stdout(Stdio::null()).spawn().unwrap();
    // The first run's process, found by its command line.
    let first = || -> Option<String> {
        std::fs::read_dir("/proc").ok()?.flatten().find_map(|e| {
            let cmd = std::fs::read(e.path().join("cmdline")).ok()?;
            let cmd = String::from_utf8_lossy(&cmd).replace('\0', " ");
            (cmd.contains("sweep-run")
                && cmd.contains("run_0000")
                && cmd.contains(&*out.to_string_lossy()))
            .then(|| e.file_name().to_string_lossy().into_owned())
        })
    };
    let start = Instant::now();
    let pid = loop {
        if let Some(pid) = first() {
            break pid;
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no run process seen"
        );
        std::thread::sleep(Duration::from_millis(2));
    };
    assert!(
        Command::new("kill")
            .args(["-9", &pid])
            .status()
            .unwrap()
            .success()
    );
    assert!(child.wait().unwrap().success());
    let table = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines.len(), 4, "{table}");
    assert!(
        lines[1].contains(",failed,") && lines[1].contains("SIGKILL"),
        "{table}"
    );
    assert!(
        lines[2..].iter().all(|l| !l.contains(",failed,")),
        "{table}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
