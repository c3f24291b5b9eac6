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
}

impl CaseReport {
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
        }
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
