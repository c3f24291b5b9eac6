//! The run's observer on the Python side: forwards each monitor row to the caller's callback, and
//! turns the callback's exception (a `KeyboardInterrupt` too) into the engine's interruption.
//! Ctrl-C itself is watched on the main thread (`run`).

use pyo3::prelude::*;
use pyo3::types::PyDict;

use adit::solve::{HistoryRow, Observer};

pub struct Progress {
    callback: Option<Py<PyAny>>,
    /// The callback's exception, raised when the run has stopped.
    pub error: Option<PyErr>,
    /// Whether the callback raised `KeyboardInterrupt`.
    pub interrupted: bool,
}

impl Progress {
    pub fn new(callback: Option<Py<PyAny>>) -> Progress {
        Progress {
            callback,
            error: None,
            interrupted: false,
        }
    }
}

impl Observer for Progress {
    fn monitored(&mut self, row: &HistoryRow) {
        if self.interrupted || self.error.is_some() {
            return;
        }
        let Some(callback) = &self.callback else {
            return;
        };
        Python::attach(|py| {
            let called = (|| {
                let d = PyDict::new(py);
                d.set_item("cycle", row.cycle)?;
                d.set_item("time_s", row.time)?;
                d.set_item("ratio", row.ratio)?;
                d.set_item("kinetic_energy_j_per_m", row.kinetic)?;
                callback.call1(py, (d,)).map(|_| ())
            })();
            if let Err(e) = called {
                if e.is_instance_of::<pyo3::exceptions::PyKeyboardInterrupt>(py) {
                    self.interrupted = true;
                } else {
                    self.error = Some(e);
                }
                adit::interrupt::request();
            }
        });
    }
}
