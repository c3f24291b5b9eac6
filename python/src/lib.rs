//! The Python module `adit._adit`: run a scene given as JSON text and get its results as NumPy
//! arrays. The pure-Python package `adit` (`pysrc/adit/`) wraps it with type hints, scene
//! loading and sweeps.

mod progress;
mod sweep;

use std::path::PathBuf;

use numpy::{IntoPyArray, PyArrayMethods};
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use adit::output::arrays::{Tables, Values, names};
use adit::{Scene, run_scene_branch, run_scene_from};

use progress::Progress;

/// Validate and build a scene given as JSON text and refuse what a run would refuse, as
/// `adit check` does (no solve): a `ValueError` naming the field when a run would not start.
#[pyfunction]
fn check(py: Python<'_>, scene_json: &str) -> PyResult<()> {
    let scene = parse(scene_json)?;
    py.detach(|| adit::run::check_scene(&scene).map(|_| ()))
        .map_err(|e| PyValueError::new_err(format!("{e:#}")))
}

/// The scene in `scene_json`; a parse error names the JSON path of the value (the text was
/// written by `json.dumps`, not by the user: its lines mean nothing to them).
fn parse(scene_json: &str) -> PyResult<Scene> {
    Scene::from_json(scene_json, "scene").map_err(|e| match e {
        adit::scene::SceneError::Parse { path, message, .. } if !path.is_empty() => {
            PyValueError::new_err(format!("{path}: {message}"))
        }
        adit::scene::SceneError::Parse { message, .. } => PyValueError::new_err(message),
        other => PyValueError::new_err(other.to_string()),
    })
}

/// Run the scene given as JSON text (from stage `from_stage`, numbered from 1: a later one goes on
/// from the checkpoint the stage before left in `out`), writing its output files into `out`
/// (default: the scene's `output.folder`, else the first of `out/<name>`, `out/<name>-2`, … no
/// earlier run wrote; a resumed run's default is `out/<name>`; `from_checkpoint`: go on from that
/// checkpoint of this scene or of another whose stages up to it are the same), calling `progress(row)` at each
/// monitor step with a dict of `cycle`, `time_s`, `ratio` and `kinetic_energy_j_per_m`. Ctrl-C
/// stops the run at the end of a cycle (its files are written, its summary says `interrupted`)
/// and raises `KeyboardInterrupt`; an exception in `progress` stops it the same way and is
/// raised. Returns a dict of the results (`adit.Results` wraps it).
#[pyfunction]
#[pyo3(signature = (scene_json, out=None, progress=None, from_stage=1, from_checkpoint=None))]
fn run<'py>(
    py: Python<'py>,
    scene_json: &str,
    out: Option<PathBuf>,
    progress: Option<Py<PyAny>>,
    from_stage: usize,
    from_checkpoint: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    if from_stage < 1 {
        return Err(PyValueError::new_err(
            "from_stage: stages are numbered from 1",
        ));
    }
    if from_stage > 1 && from_checkpoint.is_some() {
        return Err(PyValueError::new_err(
            "from_checkpoint: give it or from_stage, not both (a checkpoint names its stage)",
        ));
    }
    let scene = parse(scene_json)?;
    // A run given no folder never writes over an earlier one (a resumed run goes on in its own).
    let out = match out {
        Some(dir) => dir,
        None if from_stage > 1 => adit::run::default_out_dir(&scene),
        None => adit::run::fresh_out_dir(&scene),
    };
    let out = std::path::absolute(&out).unwrap_or(out);
    // A Ctrl-C that stopped an earlier run of this process does not stop this one.
    adit::interrupt::clear();
    // The run goes on its own thread; this (main) thread watches for Ctrl-C, which Python only
    // reports on the main thread, and asks the run to stop at the end of a cycle.
    let dir = out.clone();
    let worker = std::thread::spawn(move || {
        let mut observer = Progress::new(progress);
        let result = match &from_checkpoint {
            Some(checkpoint) => run_scene_branch(&scene, &dir, checkpoint, &mut observer),
            None => run_scene_from(&scene, &dir, from_stage, &mut observer),
        };
        (result, observer)
    });
    let mut interrupted = false;
    while !worker.is_finished() {
        py.detach(|| std::thread::sleep(std::time::Duration::from_millis(20)));
        if let Err(e) = py.check_signals() {
            if !e.is_instance_of::<PyKeyboardInterrupt>(py) {
                adit::interrupt::request();
                let _ = worker.join();
                return Err(e);
            }
            interrupted = true;
            adit::interrupt::request();
        }
    }
    let (result, mut observer) = worker
        .join()
        .map_err(|_| PyRuntimeError::new_err("the run panicked (a defect of the engine)"))?;
    if let Some(err) = observer.error.take() {
        return Err(err);
    }
    if interrupted || observer.interrupted {
        return Err(PyKeyboardInterrupt::new_err(format!(
            "the run was interrupted; its last state is in {}",
            out.display()
        )));
    }
    let r = result.map_err(|e| PyRuntimeError::new_err(format!("{e:#}")))?;
    let dict = PyDict::new(py);
    for (table, columns) in Tables::of(&r.built.model).tables {
        let t = PyDict::new(py);
        for c in columns {
            let rows = |len: usize| {
                if c.width == 1 {
                    vec![len]
                } else {
                    vec![len / c.width, c.width]
                }
            };
            match c.values {
                Values::Float(v) => {
                    let shape = rows(v.len());
                    t.set_item(c.name, v.into_pyarray(py).reshape(shape)?)?;
                }
                Values::Int(v) => {
                    let shape = rows(v.len());
                    t.set_item(c.name, v.into_pyarray(py).reshape(shape)?)?;
                }
            }
        }
        dict.set_item(table, t)?;
    }
    for (kind, list) in names(&r.built.model) {
        dict.set_item(kind, list)?;
    }
    let h = r.solution.history();
    let history = PyDict::new(py);
    history.set_item(
        "cycle",
        h.iter()
            .map(|r| r.cycle as i64)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    history.set_item(
        "time_s",
        h.iter()
            .map(|r| r.time)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    history.set_item(
        "ratio",
        h.iter()
            .map(|r| r.ratio)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    history.set_item(
        "kinetic_energy_j_per_m",
        h.iter()
            .map(|r| r.kinetic)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    dict.set_item("history", history)?;
    let summary =
        serde_json::to_string(&r.summary).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    dict.set_item("summary_json", summary)?;
    dict.set_item("out_dir", r.out_dir.to_string_lossy().into_owned())?;
    Ok(dict)
}

/// The engine's version.
#[pyfunction]
fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

#[pymodule]
fn _adit(m: &Bound<'_, PyModule>) -> PyResult<()> {
    // Load NumPy's C API now, so that no later call can meet a pending Ctrl-C while loading it.
    numpy::PyArray1::<f64>::zeros(m.py(), 0, false);
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(version, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_plan, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_run, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_done, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_table, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_clear, m)?)?;
    Ok(())
}
