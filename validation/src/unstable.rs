//! A run made unstable on purpose (issue 5's bar): the Kirsch model on a coarse mesh (zones three
//! times the shipped size) solved statically with its step forced to 3× the stable one (masses are
//! scaled for Δt = 1 s at the safety factor, so Δt = 3 s is three times past it). It must stop
//! within a few cycles with a message naming the node and the cause; the same model at its derived
//! step converges.

use std::time::Instant;

use adit::setup::setup;
use adit::solve::{Quiet, Solver, Status};

use crate::report::{CaseReport, StepInfo};

/// How the run ended.
#[derive(Debug, Clone)]
pub struct Forced {
    /// Step over the stable one.
    pub factor: f64,
    pub zones: usize,
    pub cycles: u64,
    /// `None` when it converged; the stop message otherwise.
    pub stop: Option<String>,
    pub wall_s: f64,
    pub step: StepInfo,
}

impl Forced {
    pub fn report(&self) -> CaseReport {
        let what = match &self.stop {
            Some(reason) => format!("stopped: “{reason}”"),
            None => "converged".into(),
        };
        CaseReport::new(
            format!(
                "Kirsch (zones × 3), static step {}× the stable one: {what}",
                self.factor
            ),
            self.zones,
            self.cycles,
            self.wall_s,
            None,
            &[],
        )
        .with_step(self.step.clone())
    }
}

/// Solve the coarse Kirsch model with its step `factor` times the stable one.
pub fn run(factor: f64) -> anyhow::Result<Forced> {
    let start = Instant::now();
    let mut sc = crate::shipped_kirsch()?;
    sc.zoning.edge_at_excavation *= 3.0;
    sc.zoning.edge_far *= 3.0;
    let mut b = setup(&sc)?;
    let mut solver = Solver::new(&mut b.model, &sc.solve, 0);
    solver.params.dt *= factor;
    let sol = solver.solve(&mut b.model, &mut Quiet);
    let stop = match sol.status {
        Status::Converged => None,
        Status::Failed(reason) => Some(reason),
        other => anyhow::bail!("expected convergence or a stop, got {other:?}"),
    };
    Ok(Forced {
        factor,
        zones: b.model.zones.len(),
        cycles: sol.cycles,
        stop,
        wall_s: start.elapsed().as_secs_f64(),
        step: StepInfo::of(&solver),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_static_step_three_times_past_the_limit_stops_within_a_few_cycles() {
        let r = run(3.0).unwrap();
        let reason = r.stop.expect("expected a stop");
        assert!(
            r.cycles <= 10,
            "stopped only after {} cycles: {reason}",
            r.cycles
        );
        assert!(reason.contains("unstable: node "), "{reason}");
    }

    #[test]
    fn the_stable_step_is_not_flagged() {
        let r = run(1.0).unwrap();
        assert!(r.stop.is_none(), "{:?}", r.stop);
    }
}
