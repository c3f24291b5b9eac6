//! One row of the validation report: a case, its size, its cost and its named relative errors.

use std::collections::BTreeMap;

use serde::Serialize;

/// A case's result as it appears in `target/validation/report.json`.
#[derive(Debug, Clone, Serialize)]
pub struct CaseReport {
    pub case: String,
    pub zones: usize,
    pub cycles: u64,
    pub wall_s: f64,
    pub zone_cycles_per_s: f64,
    /// Named relative errors (e.g. `stress_l2`, `wall_displacement`).
    #[serde(flatten)]
    pub errors: BTreeMap<String, f64>,
}

impl CaseReport {
    /// The largest of the named errors.
    pub fn worst(&self) -> f64 {
        self.errors.values().copied().fold(0.0, f64::max)
    }
}
