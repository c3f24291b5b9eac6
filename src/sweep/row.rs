//! One run of a sweep to one row of its table.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::{RunInput, scene_of};
use crate::model::Model;
use crate::output::atomic::write_atomic;
use crate::solve::Quiet;

/// What one run gave: its inputs, its status, and the figures a support study compares.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Row {
    pub id: String,
    pub params: BTreeMap<String, Value>,
    /// `converged`, `cycle_limit`, `failed` or `interrupted`.
    pub status: String,
    /// Why it failed (a bad parameter, a scene refused, a solve that failed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    pub wall_seconds: f64,
    pub cycles: u64,
    /// Mean wall closure of each excavation at the end of the run, m (staged scenes).
    pub closure_m: BTreeMap<String, f64>,
    /// Zones yielded at the end (excavated ones left out).
    pub yielded_zones: usize,
    /// Largest axial force of an installed bolt segment, N/m (tension positive; none without
    /// bolts).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_bolt_force_n_per_m: Option<f64>,
    /// Largest compressive axial force (thrust) of an installed liner element, N/m (none
    /// without liners).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_liner_thrust_n_per_m: Option<f64>,
}

/// The folder of run `id` under the sweep's output folder.
pub fn run_dir(out: &Path, id: &str) -> PathBuf {
    out.join("runs").join(id)
}

/// The row run `input` left in `out` when it finished with these parameters (an interrupted
/// run left none): the run need not be made again.
pub fn done(out: &Path, input: &RunInput) -> Option<Row> {
    let text = std::fs::read_to_string(run_dir(out, &input.id).join("row.json")).ok()?;
    let row: Row = serde_json::from_str(&text).ok()?;
    (row.params == input.params).then_some(row)
}

/// Run `input` on `base` into `<out>/runs/<id>/` and return its row, a failure included; the
/// row is also left as `row.json` there (but for an interrupted run, which a restart makes
/// again).
pub fn run_one(base: &Value, input: &RunInput, out: &Path) -> Row {
    let start = Instant::now();
    let dir = run_dir(out, &input.id);
    let mut row = Row::failed(input, None);
    // One process at a time in a run's folder: a sweep killed alone (SIGKILL to its own
    // process) leaves its runs' processes finishing, and the restarted sweep makes the same
    // runs. The lock is the operating system's (flock), let go when its holder ends however it
    // ends; a run that finished while this one waited is not made again.
    let _lock = match lock(&dir) {
        Ok(lock) => lock,
        Err(e) => {
            row.error = Some(format!("{}: {e}", dir.join(LOCK).display()));
            save(&mut row, out);
            return row;
        }
    };
    if let Some(row) = done(out, input) {
        return row;
    }
    let ran = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| -> anyhow::Result<_> {
        let scene = scene_of(base, input)?;
        let scene = crate::Scene::from_json(&scene.to_string(), &input.id)?;
        crate::run_scene(&scene, &dir, &mut Quiet)
    }));
    match ran {
        Ok(Ok(r)) => {
            row.status = r.summary.status.clone();
            row.error = r.summary.reason.clone();
            row.cycles = r.summary.cycles;
            if let Some(last) = r.summary.stages.last() {
                row.closure_m = last.closure.clone();
            }
            figures(&mut row, &r.built.model);
        }
        Ok(Err(e)) => row.error = Some(format!("{e:#}")),
        Err(_) => row.error = Some("the run panicked (a defect of the engine)".into()),
    }
    row.wall_seconds = start.elapsed().as_secs_f64();
    if row.status != "interrupted" {
        save(&mut row, out);
    }
    row
}

/// The file a run's process holds locked while it works in the run's folder.
const LOCK: &str = "lock";

/// The run folder `dir`, made if missing, locked for this process (waiting for another that
/// holds it): the lock is let go when the file returned is dropped or the process ends.
fn lock(dir: &Path) -> std::io::Result<std::fs::File> {
    std::fs::create_dir_all(dir)?;
    let file = std::fs::OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .open(dir.join(LOCK))?;
    file.lock()?;
    Ok(file)
}

impl Row {
    /// A row of run `input` that failed, for `error`.
    pub fn failed(input: &RunInput, error: Option<String>) -> Row {
        Row {
            id: input.id.clone(),
            params: input.params.clone(),
            status: "failed".into(),
            error,
            wall_seconds: 0.0,
            cycles: 0,
            closure_m: BTreeMap::new(),
            yielded_zones: 0,
            max_bolt_force_n_per_m: None,
            max_liner_thrust_n_per_m: None,
        }
    }
}

/// Leave `row` as `row.json` in its run's folder under `out`; a row that cannot be written says
/// so in its error.
pub fn save(row: &mut Row, out: &Path) {
    let dir = run_dir(out, &row.id);
    let text = serde_json::to_string_pretty(&*row).expect("a row serializes");
    let saved = std::fs::create_dir_all(&dir)
        .and_then(|_| write_atomic(&dir.join("row.json"), |w| w.write_all(text.as_bytes())));
    if let Err(e) = saved {
        row.error
            .get_or_insert_with(|| format!("row.json not written: {e}"));
    }
}

/// Yielded zones, the largest bolt force and liner thrust of the model at the run's end.
fn figures(row: &mut Row, model: &Model) {
    let z = &model.zones;
    row.yielded_zones = (0..z.len())
        .filter(|&e| z.state[e] != 0 && !model.blocks.is_removed(z.block[e] as usize))
        .count();
    let (c, l) = (&model.supports.cables, &model.supports.liners);
    let installed = |group: u32, active: &[bool]| active[group as usize];
    row.max_bolt_force_n_per_m = (0..c.segment.len())
        .filter(|&k| installed(c.segment_group[k], &c.active))
        .map(|k| c.axial[k])
        .reduce(f64::max);
    row.max_liner_thrust_n_per_m = (0..l.element.len())
        .filter(|&k| installed(l.element_group[k], &l.active))
        .map(|k| -l.axial[k])
        .reduce(f64::max);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row read back from its `row.json` has the figures it was written with, to the bit (a
    /// restarted sweep's table is the uninterrupted one's): serde_json's `float_roundtrip`.
    #[test]
    fn a_row_reads_back_bit_for_bit() {
        let mut rng = adit_meshing::joints::SplitMix(11);
        for _ in 0..200 {
            let x = f64::from_bits(rng.next_u64() >> 2);
            let row = Row {
                id: "run_0000".into(),
                params: [("in_situ.sxx".to_string(), Value::from(-x))].into(),
                status: "converged".into(),
                error: None,
                wall_seconds: 1.0,
                cycles: 3,
                closure_m: [("tunnel".to_string(), 0.011115722249229583 * x.fract())].into(),
                yielded_zones: 2,
                max_bolt_force_n_per_m: Some(x),
                max_liner_thrust_n_per_m: None,
            };
            let back: Row =
                serde_json::from_str(&serde_json::to_string_pretty(&row).unwrap()).unwrap();
            assert_eq!(back, row);
        }
    }
}
