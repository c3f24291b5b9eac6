//! Peak particle velocity (PPV): each node's largest speed |v| over the run's dynamic stages,
//! m/s, the measure of ground shaking that blast and rockburst damage criteria use (the `ppv`
//! point field and `summary.json`'s `peak_particle_velocity`), and each node's acceleration over
//! the last step (the monitoring points' `acceleration_x`, `acceleration_y`). Kept only once a
//! dynamic stage has begun: a static run pays nothing for it.

use rayon::prelude::*;

/// Each node's peak speed so far, m/s, and its acceleration over the last step, m/s².
#[derive(Debug, Clone, PartialEq)]
pub struct Peaks {
    pub speed: Vec<f64>,
    /// Each node's acceleration over the last dynamic step, (v_{n+½} − v_{n−½})/Δt, m/s² (the
    /// central difference's own: what moved the node, damping and quiet boundaries included; 0
    /// in static stages).
    pub acceleration: Vec<[f64; 2]>,
    /// Each node's velocity after the last step, m/s.
    last: Vec<[f64; 2]>,
}

impl Peaks {
    /// Nodes moving at `vel` (m/s) that have not peaked.
    pub fn new(vel: &[[f64; 2]]) -> Peaks {
        Peaks {
            speed: vec![0.0; vel.len()],
            acceleration: vec![[0.0; 2]; vel.len()],
            last: vel.to_vec(),
        }
    }

    /// A stage begins with the nodes at `vel` (m/s): a dynamic one measures its first step's
    /// acceleration from them, a static one has none (its masses are scaled).
    pub(crate) fn begin(&mut self, vel: &[[f64; 2]]) {
        self.last.copy_from_slice(vel);
        self.acceleration.fill([0.0; 2]);
    }

    /// After a step of `dt` s: each node's peak to the larger of it and its speed now, |v| (m/s),
    /// and its acceleration (v − v_last)/Δt.
    pub(crate) fn record(&mut self, vel: &[[f64; 2]], dt: f64) {
        (self.speed.par_iter_mut())
            .zip(self.acceleration.par_iter_mut())
            .zip(self.last.par_iter_mut())
            .zip(vel.par_iter())
            .with_min_len(4096)
            .for_each(|(((p, a), last), v)| {
                *p = p.max(v[0].hypot(v[1]));
                *a = [(v[0] - last[0]) / dt, (v[1] - last[1]) / dt];
                *last = *v;
            });
    }

    /// The largest peak and its node (`None` without nodes).
    pub fn largest(&self) -> Option<(u32, f64)> {
        (self.speed.iter().enumerate())
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(n, &s)| (n as u32, s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peaks_keep_the_largest_speed_and_the_last_steps_acceleration() {
        let mut p = Peaks::new(&[[0.0; 2]; 2]);
        p.record(&[[3.0, 4.0], [0.0, -1.0]], 0.5);
        assert_eq!(p.acceleration, vec![[6.0, 8.0], [0.0, -2.0]]);
        p.record(&[[1.0, 0.0], [0.0, 2.0]], 0.5);
        assert_eq!(p.speed, vec![5.0, 2.0]);
        assert_eq!(p.largest(), Some((0, 5.0)));
        assert_eq!(p.acceleration, vec![[-4.0, -8.0], [0.0, 6.0]]);
        p.begin(&[[1.0, 1.0], [0.0, 0.0]]);
        assert_eq!(p.acceleration, vec![[0.0; 2]; 2]);
        p.record(&[[2.0, 1.0], [0.0, 0.0]], 1.0);
        assert_eq!(p.acceleration, vec![[1.0, 0.0], [0.0, 0.0]]);
    }
}
