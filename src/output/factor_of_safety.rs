//! What `summary.json` says of a stage's factor of safety (`stages[i].factor_of_safety`), which
//! `strength_reduction` searches.

/// One trial factor and what its solve did.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Trial {
    /// The trial factor F (dimensionless): strengths divided by it.
    pub factor: f64,
    /// Whether the stage reached equilibrium at F.
    pub stable: bool,
    /// How its solve ended (`converged`, `cycle_limit`, `failed`).
    pub status: String,
    /// Cycles (explicit) or iterations (implicit) the trial took.
    pub cycles: u64,
    /// The block still sliding when the trial converged (named with its speed), which makes it
    /// unstable; absent when none was.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moving: Option<String>,
}

/// A factor of safety found.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FactorOfSafety {
    /// The factor of safety: the largest factor found stable (dimensionless); 0 when none down to
    /// 1 / `max_factor` was.
    pub factor: f64,
    /// The smallest factor found unstable (dimensionless); `None` when the stage was stable up to
    /// `max_factor` (its factor of safety is at least that).
    pub unstable: Option<f64>,
    /// The search's relative tolerance (dimensionless).
    pub tolerance: f64,
    /// The trials in the order they ran (the stage's own solve at F = 1 not among them).
    pub trials: Vec<Trial>,
}

impl FactorOfSafety {
    /// One line for the console: the factor, its bracket and the trials.
    pub fn describe(&self) -> String {
        let trials = self.trials.len();
        match self.unstable {
            Some(u) if self.factor > 0.0 => format!(
                "factor of safety {:.4} (unstable at {u:.4}; {trials} trials)",
                self.factor
            ),
            Some(u) => {
                format!("factor of safety below {u:.4}, the smallest tried ({trials} trials)")
            }
            None => format!(
                "factor of safety at least {:.4}, the largest tried ({trials} trials)",
                self.factor
            ),
        }
    }
}
