//! A sweep on this machine's threads (`adit sweep`): each worker takes the next run not yet done,
//! until none is left or a Ctrl-C stops them (the runs under way stop at the end of a cycle and
//! leave no row, so a restart makes them again).

use std::path::Path;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use serde_json::Value;

use super::{Row, RunInput, done, run_one};

/// Run `runs` on `base` into `out` with `workers` threads, skipping those already done; `told`
/// hears of each row as it comes (and whether it was done before). Returns the rows in the runs'
/// order; a run stopped by Ctrl-C, or never started, has none.
pub fn run_local(
    base: &Value,
    runs: &[RunInput],
    out: &Path,
    workers: usize,
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
                        None => (run_one(base, input, out), false),
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
