//! A sweep on this machine (`adit sweep`): worker threads each take the next run not yet done,
//! until none is left or a Ctrl-C stops them (the runs under way stop at the end of a cycle and
//! leave no row, so a restart makes them again). Each run goes to its own process (`in_child`),
//! so that even a run that aborts is a row with its error, never a lost sweep.

use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use super::{Row, RunInput, done, save};

/// Make `runs` into `out` with `workers` threads, each run by `run`, skipping those already done;
/// `told` hears of each row as it comes (and whether it was done before). Returns the rows in the
/// runs' order; a run stopped by Ctrl-C, or never started, has none.
pub fn run_local(
    runs: &[RunInput],
    out: &Path,
    workers: usize,
    run: &(dyn Fn(&RunInput) -> Row + Sync),
    told: &(dyn Fn(&Row, bool) + Sync),
) -> Vec<Option<Row>> {
    let rows: Vec<Mutex<Option<Row>>> = runs.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..workers.max(1) {
            s.spawn(|| {
                loop {
                    if crate::interrupt::requested() {
                        return;
                    }
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(input) = runs.get(i) else {
                        return;
                    };
                    let (row, before) = match done(out, input) {
                        Some(row) => (row, true),
                        None => (run(input), false),
                    };
                    told(&row, before);
                    if row.status != "interrupted" {
                        *rows[i].lock().expect("no worker panics holding a row") = Some(row);
                    }
                }
            });
        }
    });
    rows.into_iter()
        .map(|r| r.into_inner().expect("no worker panics holding a row"))
        .collect()
}

/// Make run `input` in a process of its own: `exe sweep-run` with the base scene in `base` (a
/// JSON file), which leaves the row in `out` (`run_one`). A process that ends without a row after
/// a Ctrl-C gives an interrupted row (left unsaved, so a restart makes the run again); one that
/// ends without a row otherwise (an abort, a kill) gives a failed row naming how it ended.
pub fn in_child(exe: &Path, base: &Path, input: &RunInput, out: &Path) -> Row {
    let params = serde_json::to_string(&input.params).expect("parameters serialize");
    let start = std::time::Instant::now();
    // The run's standard input stays open while this process lives: the run stops when it
    // closes (`adit sweep-run`), so a sweep killed alone leaves no run going on.
    let ended = Command::new(exe)
        .arg("sweep-run")
        .arg(base)
        .arg(&input.id)
        .arg(&params)
        .arg(out)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .and_then(|mut child| {
            let held = child.stdin.take();
            let ended = child.wait_with_output();
            drop(held);
            ended
        });
    if let Some(row) = done(out, input) {
        return row;
    }
    if crate::interrupt::requested() {
        let mut row = Row::failed(input, None);
        row.status = "interrupted".into();
        return row;
    }
    let how = match ended {
        Ok(o) => {
            let said = String::from_utf8_lossy(&o.stderr);
            let said = said.trim();
            let said = if said.is_empty() {
                String::new()
            } else {
                format!(": {said}")
            };
            format!("the run's process ended ({}) without a row{said}", o.status)
        }
        Err(e) => format!("the run's process could not start: {e}"),
    };
    let mut row = Row::failed(input, Some(how));
    row.wall_seconds = start.elapsed().as_secs_f64();
    save(&mut row, out);
    row
}
