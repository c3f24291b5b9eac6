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
    /// Representative zone size near the feature of interest, m (where meaningful).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub h: Option<f64>,
    /// Named relative errors (e.g. `stress_l2`, `wall_displacement`).
    #[serde(flatten)]
    pub errors: BTreeMap<String, f64>,
    /// The time step and what limited it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step: Option<StepInfo>,
    /// What the implicit solve cost (its iterations are the row's `cycles`), when it ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub implicit: Option<adit::implicit::Cost>,
}

/// A run's time step: the critical step with real masses and what set it, and the step used.
#[derive(Debug, Clone, Serialize)]
pub struct StepInfo {
    /// Critical step with real masses, s (the dynamic step before the safety factor).
    pub critical_s: f64,
    /// Step used, s (1 for static runs, whose masses are scaled instead).
    pub used_s: f64,
    /// What set the critical step: zones or contacts at a node, supports, a rigid or simple block.
    pub limited_by: String,
}

impl StepInfo {
    /// The step a solver derived for its model.
    pub fn of(solver: &adit::solve::Solver) -> StepInfo {
        StepInfo {
            critical_s: solver.step.dt_critical,
            used_s: solver.params.dt,
            limited_by: solver.step.describe(),
        }
    }

    /// The step a scene run reported in its summary.
    pub fn from_summary(s: &adit::output::Summary) -> StepInfo {
        StepInfo {
            critical_s: s.critical_timestep,
            used_s: s.timestep,
            limited_by: s.critical_limiter.clone(),
        }
    }

    /// `1.2e-5 s, zones at node 40` (static runs) or `…, used 9.6e-6 s` (dynamic runs).
    pub fn label(&self) -> String {
        let used = if self.used_s == 1.0 {
            String::new()
        } else {
            format!(", used {:.2e} s", self.used_s)
        };
        format!("{:.2e} s, {}{used}", self.critical_s, self.limited_by)
    }
}

impl CaseReport {
    /// Whether a hole's plastic radius and wall displacement are both within `bar` (relative).
    pub fn hole_within(&self, bar: f64) -> bool {
        self.errors["plastic_radius"] <= bar && self.errors["wall_displacement"] <= bar
    }

    /// A row from its figures; zone-cycles per second follow from zones, cycles and seconds.
    pub fn new(
        case: impl Into<String>,
        zones: usize,
        cycles: u64,
        wall_s: f64,
        h: Option<f64>,
        errors: &[(&str, f64)],
    ) -> Self {
        CaseReport {
            case: case.into(),
            zones,
            cycles,
            wall_s,
            zone_cycles_per_s: zones as f64 * cycles as f64 / wall_s,
            h,
            errors: errors.iter().map(|&(k, v)| (k.to_string(), v)).collect(),
            step: None,
            implicit: None,
        }
    }

    /// The row with the cost of its implicit solve, if one ran.
    pub fn with_implicit(mut self, cost: Option<adit::implicit::Cost>) -> Self {
        self.implicit = cost;
        self
    }

    /// The row with its run's time step.
    pub fn with_step(mut self, step: StepInfo) -> Self {
        self.step = Some(step);
        self
    }

    /// The largest of the named errors.
    pub fn worst(&self) -> f64 {
        self.errors.values().copied().fold(0.0, f64::max)
    }
}

/// Observed order of convergence between two levels: log(e₁/e₂) / log(h₁/h₂).
pub fn observed_order(h1: f64, e1: f64, h2: f64, e2: f64) -> f64 {
    (e1 / e2).ln() / (h1 / h2).ln()
}

/// Least-squares slope of log e against log h over all levels.
pub fn fitted_order(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = points.iter().map(|&(h, e)| (h.ln(), e.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = lx.iter().map(|x| (x - mx).powi(2)).sum();
    sxy / sxx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orders_of_an_exact_power_law() {
        let pts: Vec<(f64, f64)> = [0.4, 0.2, 0.1].iter().map(|&h| (h, 3.0 * h * h)).collect();
        assert!((observed_order(0.4, pts[0].1, 0.2, pts[1].1) - 2.0).abs() < 1e-12);
        assert!((fitted_order(&pts) - 2.0).abs() < 1e-12);
    }
}
