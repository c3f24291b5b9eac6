//! A load history on a boundary part (`boundary[i].history`; FLAC's `apply … history`): the
//! condition's traction (`stress`, `in_situ_traction`, `normal_stress`/`shear_stress`) times a
//! dimensionless history h(t), as consistent nodal loads F h(t), N/m: a blast's pressure on an
//! excavation's wall, a load pulse on a surface. The forces of the step from t to t + Δt act at t
//! (as the quiet boundary's incident waves), so the stage changes each node's applied load by
//! F (h(t) − h_before) before the motion stage.

use super::History;

/// One condition's load history: its nodal loads at h = 1 and the factor now applied.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct TimedLoad {
    history: History,
    /// Each node's load at h = 1, N/m.
    forces: Vec<(u32, [f64; 2])>,
    /// The factor h the nodes' applied loads hold now.
    now: f64,
}

impl TimedLoad {
    /// The load `forces` (N/m per node at h = 1) scaled by `history`, not yet applied.
    pub fn new(history: History, forces: Vec<(u32, [f64; 2])>) -> TimedLoad {
        TimedLoad {
            history,
            forces,
            now: 0.0,
        }
    }

    /// The applied loads (N/m) to F h(`time`).
    pub fn apply(&mut self, applied: &mut [[f64; 2]], time: f64) {
        let h = self.history.at(time);
        self.add(applied, h - self.now);
        self.now = h;
    }

    /// Take the load off the applied loads (the list stops being in force).
    pub fn remove(&mut self, applied: &mut [[f64; 2]]) {
        self.add(applied, -self.now);
        self.now = 0.0;
    }

    fn add(&self, applied: &mut [[f64; 2]], factor: f64) {
        if factor == 0.0 {
            return;
        }
        for &(n, f) in &self.forces {
            let a = &mut applied[n as usize];
            a[0] += factor * f[0];
            a[1] += factor * f[1];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The applied load follows F h(t) and returns to what it was when removed.
    #[test]
    fn the_applied_load_follows_the_history() {
        let h = History::Table(vec![[0.0, 0.0], [1.0, 2.0]]);
        let mut load = TimedLoad::new(h, vec![(1, [3.0, -1.0])]);
        let mut applied = [[1.0, 1.0], [10.0, 20.0]];
        load.apply(&mut applied, 0.5);
        assert_eq!(applied, [[1.0, 1.0], [13.0, 19.0]]);
        load.apply(&mut applied, 1.0);
        assert_eq!(applied, [[1.0, 1.0], [16.0, 18.0]]);
        load.remove(&mut applied);
        assert_eq!(applied, [[1.0, 1.0], [10.0, 20.0]]);
    }
}
