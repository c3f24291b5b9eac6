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
    /// The largest displacement of a node during the trial, from the stage's equilibrium, m.
    pub displacement_m: f64,
    /// The farthest a block moved beyond the rock around it (the least displacement of its
    /// nodes less the largest of the nodes of the blocks it touched at the stage's equilibrium;
    /// the largest over the blocks, at least 0), m: a trial whose block left the rock around it
    /// by more than `displacement_limit` is unstable.
    pub departure_m: f64,
    /// How many zones the trial turned inside out (their area in the deformed configuration
    /// reversed: the rock gone through itself, which small strain does not see). Reported, not
    /// judged (where it first happens depends on the solve's path); a factor of safety whose own
    /// trial has any is warned of (`FactorOfSafety::inverted_warning`).
    #[serde(default)]
    pub inverted: usize,
    /// The block still sliding when the trial converged (named with its speed), which makes it
    /// unstable; absent when none was.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moving: Option<String>,
    /// Why its solve stopped, when it `failed` (the monitor's or the step's reason: a runaway,
    /// interpenetration, an unstable step, naming the node or zone); absent otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
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
    /// The blocks the mechanism moves (at the smallest unstable factor): each that moved at
    /// least half as far as the farthest, farthest first (at most ten); empty when no trial was
    /// unstable.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub mechanism: Vec<MovingBlock>,
}

/// A block of a mechanism and how far it moved.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MovingBlock {
    /// Its number (the zones' and contacts' `block`).
    pub block: u32,
    /// The mean of its nodes' positions, m.
    pub at: [f64; 2],
    /// Its largest node displacement from the stage's equilibrium, m.
    pub displacement_m: f64,
}

impl FactorOfSafety {
    /// One line for the console: the factor, its bracket and the trials, and the blocks of its
    /// mechanism.
    pub fn describe(&self) -> String {
        let moving = match self.mechanism.as_slice() {
            [] => String::new(),
            blocks => format!(
                "; the mechanism moves block {} ({:.3} m at most)",
                blocks
                    .iter()
                    .map(|b| format!("{} at ({:.1}, {:.1}) m", b.block, b.at[0], b.at[1]))
                    .collect::<Vec<_>>()
                    .join(", "),
                blocks[0].displacement_m
            ),
        };
        self.bracket() + &moving
    }

    /// A warning when the trial at the factor of safety turned zones inside out
    /// (`Trial::inverted`): its rock has passed through itself, which small strain does not see,
    /// so the factor is where a path-dependent flow stopped, not a property of the rock; it names
    /// the largest factor tried whose trial turned none.
    pub fn inverted_warning(&self) -> Option<String> {
        let found = self.at_factor()?;
        (found.inverted > 0).then(|| {
            let sound = self.largest_whole();
            format!(
                "factor of safety {:.4}: its trial turned {} zones inside out (nodes moved up to \
                 {:.2} m from the stage's equilibrium): the rock has passed through itself, which \
                 small strain does not see, and the factor depends on the solve's path; the \
                 largest factor tried whose trial turned none is {sound:.4}",
                self.factor, found.inverted, found.displacement_m
            )
        })
    }

    /// The trial at the factor of safety (a stable one; none when no trial was stable).
    pub fn at_factor(&self) -> Option<&Trial> {
        (self.trials.iter()).find(|t| t.stable && t.factor == self.factor)
    }

    /// The largest factor tried whose trial was stable and turned no zone inside out (0: none).
    pub fn largest_whole(&self) -> f64 {
        (self.trials.iter())
            .filter(|t| t.stable && t.inverted == 0)
            .map(|t| t.factor)
            .fold(0.0, f64::max)
    }

    /// The factor, its bracket and the trials.
    fn bracket(&self) -> String {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn trial(factor: f64, stable: bool, inverted: usize) -> Trial {
        Trial {
            factor,
            stable,
            status: "converged".into(),
            cycles: 10,
            displacement_m: factor,
            departure_m: 0.0,
            inverted,
            moving: None,
            reason: None,
        }
    }

    #[test]
    fn a_factor_whose_trial_inverted_zones_is_warned_of() {
        let mut fos = FactorOfSafety {
            factor: 3.5,
            unstable: Some(4.0),
            tolerance: 0.01,
            trials: vec![
                trial(2.0, true, 0),
                trial(4.0, false, 9),
                trial(3.0, true, 0),
            ],
            mechanism: Vec::new(),
        };
        fos.trials.push(trial(3.5, true, 0));
        assert_eq!(fos.inverted_warning(), None);
        fos.trials[3].inverted = 2;
        let warning = fos.inverted_warning().expect("a warning");
        assert!(warning.contains("turned 2 zones inside out"), "{warning}");
        assert!(warning.contains("turned none is 3.0000"), "{warning}");
    }
}
