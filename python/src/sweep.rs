//! The engine's half of `adit.sweep`: plan the runs, make one run into a row, find a row already
//! made, write the table. The Python half schedules the runs (a process pool or Dask).

use std::path::{Path, PathBuf};

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use adit::sweep::{Row, RunInput, SweepSpec, done, plan, remove_table, run_one, write_table};

fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// A sweep's plan as Python gets it: name, default output folder, base scene (JSON text), and each
/// run's id and parameters (JSON text).
type Plan = (String, String, String, Vec<(String, String)>);

/// The plan of the sweep in `spec_json` (its base scene's path relative to `spec_dir`): its name,
/// its default output folder, the base scene as JSON text, and each run's id and parameters (JSON
/// text).
#[pyfunction]
pub fn sweep_plan(spec_json: &str, spec_dir: PathBuf) -> PyResult<Plan> {
    let spec = SweepSpec::from_json(spec_json, "spec").map_err(value_error)?;
    let base = spec.base_scene(&spec_dir).map_err(value_error)?;
    let runs = plan(&spec)
        .into_iter()
        .map(|r| {
            let params = serde_json::to_string(&r.params).expect("parameters serialize");
            (r.id, params)
        })
        .collect();
    Ok((
        spec.name.clone(),
        spec.out_dir().to_string_lossy().into_owned(),
        base.to_string(),
        runs,
    ))
}

fn input(id: &str, params_json: &str) -> PyResult<RunInput> {
    Ok(RunInput {
        id: id.to_string(),
        params: serde_json::from_str(params_json).map_err(value_error)?,
    })
}

/// Run `id` with its parameters on the base scene into `<out>/runs/<id>/`; its row as JSON text.
#[pyfunction]
pub fn sweep_run(
    py: Python<'_>,
    base_json: &str,
    id: &str,
    params_json: &str,
    out: PathBuf,
) -> PyResult<String> {
    let base: serde_json::Value = serde_json::from_str(base_json).map_err(value_error)?;
    let input = input(id, params_json)?;
    adit::interrupt::clear();
    let row = py.detach(|| run_one(&base, &input, &out));
    serde_json::to_string(&row).map_err(|e| PyRuntimeError::new_err(e.to_string()))
}

/// The row run `id` left in `out` with these parameters, if it finished.
#[pyfunction]
pub fn sweep_done(out: PathBuf, id: &str, params_json: &str) -> PyResult<Option<String>> {
    let row = done(&out, &input(id, params_json)?);
    Ok(row.map(|r| serde_json::to_string(&r).expect("a row serializes")))
}

/// Write `sweep.csv` and `sweep.png` of the rows (JSON texts, in the runs' order) into `out`;
/// the warnings of a plot that could not be drawn.
#[pyfunction]
pub fn sweep_table(out: PathBuf, rows_json: Vec<String>) -> PyResult<Vec<String>> {
    let rows: Vec<Row> = rows_json
        .iter()
        .map(|r| serde_json::from_str(r).map_err(value_error))
        .collect::<PyResult<_>>()?;
    write_table(Path::new(&out), &rows).map_err(|e| PyRuntimeError::new_err(format!("{e:#}")))
}

/// Remove the table an earlier sweep left in `out` (`sweep.csv`, `sweep.png`, `sweep.parquet`),
/// so that a table that exists is of a sweep that finished.
#[pyfunction]
pub fn sweep_clear(out: PathBuf) -> PyResult<()> {
    remove_table(&out).map_err(|e| PyRuntimeError::new_err(format!("{}: {e}", out.display())))
}
