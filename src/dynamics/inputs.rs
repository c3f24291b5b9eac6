//! The dynamic inputs of one list of boundary conditions: its parts' prescribed motions
//! (`motion.rs`) and load histories (`load.rs`), which the cycle applies before its motion stage
//! (`Cycle::run`) and the stage change takes off (`Inputs::stop`).

use super::load::TimedLoad;
use super::motion::Motion;

/// Prescribed motions and load histories in force.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Inputs {
    pub(crate) motions: Vec<Motion>,
    pub(crate) loads: Vec<TimedLoad>,
}

impl Inputs {
    pub fn is_empty(&self) -> bool {
        self.motions.is_empty() && self.loads.is_empty()
    }

    /// Before the motion stage of the step from `time` to `time + dt` (s since the stage
    /// began): the held components to their velocity at `time + dt/2` (m/s), the load histories
    /// to their value at `time`.
    pub(crate) fn impose(
        &mut self,
        vel: &mut [[f64; 2]],
        applied: &mut [[f64; 2]],
        time: f64,
        dt: f64,
    ) {
        for m in &self.motions {
            m.impose(vel, time, dt);
        }
        for l in &mut self.loads {
            l.apply(applied, time);
        }
    }

    /// The held components: each prescribed motion's nodes with its axis (0 x, 1 y).
    pub(crate) fn held(&self) -> impl Iterator<Item = (u32, usize)> + '_ {
        (self.motions.iter()).flat_map(|m| m.nodes.iter().map(move |&n| (n, m.axis)))
    }

    /// When the list stops being in force: the held components come to rest (a held component
    /// keeps its velocity, so one a motion left moving would go on moving in the next stage,
    /// which holds it still or frees it), and the load histories come off the applied loads.
    pub(crate) fn stop(&mut self, vel: &mut [[f64; 2]], applied: &mut [[f64; 2]]) {
        for m in &self.motions {
            for &n in &m.nodes {
                vel[n as usize][m.axis] = 0.0;
            }
        }
        for l in &mut self.loads {
            l.remove(applied);
        }
    }
}
